"""Helical, bevel and worm gears in closed form: the book's formulas, never a drawn point.

The independent reference for :mod:`graphmech.methods.helix`. Imports only the gear model, ``math``
and the base modules (it shares nothing with :mod:`graphmech.exact.gear` either: the transverse
contact ratio is written out again from the tip pressure angles).

Conventions (:class:`graphmech.mechanisms.gear.SpatialPair`): SI lengths, angles in rad; the
tooth system's m is m_n (helical), the large-end module (bevel) or the axial module (worm); no
profile shift (x = 0: the reader refuses shifted helical, bevel and worm gears).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from graphmech.errors import NotApplicable, OutOfDomain
from graphmech.mechanisms.gear import GearSet, SpatialPair

#: Helical gears are made with 0 ≤ β < 45° (the reader says so); at 45° m_t = √2·m_n and z_v = 2.83z.
BETA_MAX = 0.25 * math.pi


def _spatial(gears: GearSet, kind: str) -> SpatialPair:
    if gears.meshing != kind:
        raise NotApplicable(f"this is not a {kind} pair (meshing = {gears.meshing!r})")
    if len(gears.gears) != 2:
        raise OutOfDomain(f"a {kind} pair needs two gears, not {len(gears.gears)}")
    s = gears.system
    if not (math.isfinite(s.m) and s.m > 0.0 and 0.0 < s.alpha < 0.5 * math.pi):
        raise OutOfDomain("the module must be a positive length and the pressure angle within 0 … 90°")
    for g in gears.gears:
        if g.x != 0.0 or g.internal:
            raise NotApplicable(f"a shifted or internal {kind} gear is not posed here (x = {g.x:g})")
        if isinstance(g.z, bool) or not isinstance(g.z, int) or g.z < 1:
            raise OutOfDomain(f"a tooth number is a whole number ≥ 1, not {g.z!r}")
    return gears.spatial if gears.spatial is not None else SpatialPair()


# --------------------------------------------------------------------------------------------
# Helical gears on parallel axes


@dataclass(frozen=True)
class HelicalValues:
    """A standard helical pair (m, rad), per-gear values as (gear 1, gear 2).

    beta: the pair's helix angle; a_initial: m_n(z₁ + z₂)/(2 cos β_stated); a = m_t(z₁ + z₂)/2;
    mt = m_n/cos β, alpha_t = atan(tan α_n/cos β); pn = πm_n, pt = πm_t, sn = pn/2, st = pt/2;
    d = m_t z, da = d + 2h*a m_n, df = d − 2(h*a + c*)m_n, db = d cos α_t, ha = h*a m_n,
    hf = (h*a + c*)m_n; alpha_at = arccos(db/da); zv = z/cos³β; beta_b = atan(tan β cos α_t);
    pz = πd/tan β (None at β = 0: a spur gear's helix never turns); eps_alpha =
    [z₁(tan α_at1 − tan α_t) + z₂(tan α_at2 − tan α_t)]/(2π); eps_beta = B sin β/(πm_n) and
    eps_gamma = ε_α + ε_β (None without B)."""

    beta: float
    a_initial: float
    a: float
    mt: float
    alpha_t: float
    pn: float
    pt: float
    sn: float
    st: float
    d: tuple[float, float]
    da: tuple[float, float]
    df: tuple[float, float]
    db: tuple[float, float]
    ha: float
    hf: float
    alpha_at: tuple[float, float]
    zv: tuple[float, float]
    beta_b: float
    pz: tuple[float, float] | None
    eps_alpha: float
    eps_beta: float | None
    eps_gamma: float | None


def helix_angle(gears: GearSet) -> tuple[float, float]:
    """(β of the pair, a_initial): β as stated, or with a stated a, cos β = m_n(z₁ + z₂)/(2a)
    (refused where that gives no β in 0 … 45°); a_initial = m_n(z₁ + z₂)/(2 cos β_stated).

    >>> from graphmech.mechanisms.gear import SpurGear, ToothSystem
    >>> g = GearSet(ToothSystem(0.008, math.radians(20)), (SpurGear(20), SpurGear(40)), "helical", 0.25,
    ...             SpatialPair(beta=math.radians(15)))
    >>> [round(v, 9) for v in (math.degrees(helix_angle(g)[0]), helix_angle(g)[1] * 1e3)]
    [16.260204708, 248.466283298]
    """
    sp = _spatial(gears, "helical")
    if not (math.isfinite(sp.beta) and 0.0 <= sp.beta < BETA_MAX):
        raise OutOfDomain(f"a helix angle of {math.degrees(sp.beta):g}° is outside 0 ≤ β < 45°")
    half = 0.5 * gears.system.m * (gears.gears[0].z + gears.gears[1].z)
    a_initial = half / math.cos(sp.beta)
    a = gears.centre_distance
    if a is None:
        return sp.beta, a_initial
    c = half / a
    if not c <= 1.0:
        raise OutOfDomain(f"a = {a * 1e3:.6g} mm is less than m_n(z₁ + z₂)/2 = {half * 1e3:.6g} mm, the spur "
                          "pair's (β = 0): no helix angle gives it")
    beta = math.atan2(math.sqrt((a - half) * (a + half)), half)  # acos(half/a), accurate as a → half
    if beta >= BETA_MAX:
        raise OutOfDomain(f"a = {a * 1e3:.6g} mm needs β = {math.degrees(beta):.6g}°, outside 0 ≤ β < 45°")
    return beta, a_initial


def helical(gears: GearSet) -> HelicalValues:
    """The closed forms of a helical pair (see :class:`HelicalValues`).

    >>> from graphmech.mechanisms.gear import SpurGear, ToothSystem
    >>> g = GearSet(ToothSystem(0.008, math.radians(20)), (SpurGear(20), SpurGear(40)), "helical", 0.25,
    ...             SpatialPair(beta=math.radians(15), face_width=0.03))
    >>> h = helical(g)
    >>> [round(v, 9) for v in (h.zv[1], h.eps_alpha, h.eps_beta, h.eps_gamma)]
    [45.211226852, 1.548050969, 0.33422538, 1.88227635]
    """
    sp = _spatial(gears, "helical")
    s = gears.system
    beta, a_initial = helix_angle(gears)
    z = (gears.gears[0].z, gears.gears[1].z)
    cb = math.cos(beta)
    mt = s.m / cb
    alpha_t = math.atan(math.tan(s.alpha) / cb)
    ha, hf = s.ha_star * s.m, (s.ha_star + s.c_star) * s.m
    d = (mt * z[0], mt * z[1])
    da = (d[0] + 2.0 * ha, d[1] + 2.0 * ha)
    df = (d[0] - 2.0 * hf, d[1] - 2.0 * hf)
    db = (d[0] * math.cos(alpha_t), d[1] * math.cos(alpha_t))
    alpha_at = (math.acos(db[0] / da[0]), math.acos(db[1] / da[1]))
    t = math.tan(alpha_t)
    eps_alpha = (z[0] * (math.tan(alpha_at[0]) - t) + z[1] * (math.tan(alpha_at[1]) - t)) / (2.0 * math.pi)
    eps_beta = None if sp.face_width is None else sp.face_width * math.sin(beta) / (math.pi * s.m)
    pz = None if beta == 0.0 else (math.pi * d[0] / math.tan(beta), math.pi * d[1] / math.tan(beta))
    return HelicalValues(
        beta=beta, a_initial=a_initial, a=0.5 * mt * (z[0] + z[1]), mt=mt, alpha_t=alpha_t,
        pn=math.pi * s.m, pt=math.pi * mt, sn=0.5 * math.pi * s.m, st=0.5 * math.pi * mt, d=d, da=da, df=df, db=db,
        ha=ha, hf=hf, alpha_at=alpha_at, zv=(z[0] / cb ** 3, z[1] / cb ** 3),
        beta_b=math.atan(math.tan(beta) * math.cos(alpha_t)), pz=pz, eps_alpha=eps_alpha, eps_beta=eps_beta,
        eps_gamma=None if eps_beta is None else eps_alpha + eps_beta)


# --------------------------------------------------------------------------------------------
# Straight bevel gears on intersecting axes


@dataclass(frozen=True)
class BevelValues:
    """A standard straight bevel pair (m, rad) at the large end, per-gear values as (gear 1, gear 2).

    delta: the pitch cone angles, tan δ₁ = sin Σ/(z₂/z₁ + cos Σ), δ₂ = Σ − δ₁; R = d/(2 sin δ) the
    cone distance; theta_a = atan(h_a/R), theta_f = atan(h_f/R) (the tip and root angles of a
    contracting-clearance pair; the equal-clearance pair of GB 12369, θ_a1 = θ_f2, is not offered); d = mz, da = d + 2h_a cos δ,
    df = d − 2h_f cos δ; zv = z/cos δ (Tredgold: the back cone developed is a spur gear of radius
    r/cos δ)."""

    delta: tuple[float, float]
    R: float
    theta_a: float
    theta_f: float
    d: tuple[float, float]
    da: tuple[float, float]
    df: tuple[float, float]
    ha: float
    hf: float
    zv: tuple[float, float]


def bevel(gears: GearSet) -> BevelValues:
    """The closed forms of a bevel pair (see :class:`BevelValues`); refused where a pitch cone angle
    reaches 90° (gear 2 a crown gear, or an internal bevel gear: not posed).

    >>> from graphmech.mechanisms.gear import SpurGear, ToothSystem
    >>> b = bevel(GearSet(ToothSystem(0.004, math.radians(20), 1.0, 0.2), (SpurGear(20), SpurGear(40)), "bevel"))
    >>> [round(v, 9) for v in (math.degrees(b.delta[0]), b.R * 1e3, b.zv[1])]
    [26.565051177, 89.4427191, 89.4427191]
    """
    sp = _spatial(gears, "bevel")
    s = gears.system
    sigma = sp.shaft_angle
    if not (math.isfinite(sigma) and 0.0 < sigma < math.pi):
        raise OutOfDomain(f"a shaft angle of {math.degrees(sigma):g}° is outside 0 < Σ < 180°")
    z1, z2 = gears.gears[0].z, gears.gears[1].z
    d1 = math.atan2(math.sin(sigma), z2 / z1 + math.cos(sigma))
    delta = (d1, sigma - d1)
    if max(delta) >= 0.5 * math.pi:
        raise NotApplicable(f"Σ = {math.degrees(sigma):g}° makes δ = {math.degrees(max(delta)):.6g}° ≥ 90°: a crown "
                            "or internal bevel gear, not posed here")
    d = (s.m * z1, s.m * z2)
    R = 0.5 * d[0] / math.sin(delta[0])
    ha, hf = s.ha_star * s.m, (s.ha_star + s.c_star) * s.m
    cd = (math.cos(delta[0]), math.cos(delta[1]))
    return BevelValues(delta=delta, R=R, theta_a=math.atan(ha / R), theta_f=math.atan(hf / R), d=d,
                       da=(d[0] + 2.0 * ha * cd[0], d[1] + 2.0 * ha * cd[1]),
                       df=(d[0] - 2.0 * hf * cd[0], d[1] - 2.0 * hf * cd[1]), ha=ha, hf=hf,
                       zv=(z1 / cd[0], z2 / cd[1]))


# --------------------------------------------------------------------------------------------
# A cylindrical (Archimedean) worm and its wheel on crossed axes (Σ = 90°)


@dataclass(frozen=True)
class WormValues:
    """A standard worm drive (m, rad); gear 1 the worm with z₁ starts, gear 2 the wheel.

    q = d₁/m; gamma1 = atan(z₁/q) the worm's lead angle, beta2 = γ₁ the wheel's helix angle (same
    hand); px = πm the axial pitch, pz1 = z₁p_x the lead; d2 = mz₂; da1 = d₁ + 2h*a m,
    df1 = d₁ − 2(h*a + c*)m; da2 = d₂ + 2h*a m (the throat), df2 = d₂ − 2(h*a + c*)m;
    a = (d₁ + d₂)/2 = m(q + z₂)/2; ratio = z₂/z₁."""

    z2: int
    q: float
    gamma1: float
    beta2: float
    px: float
    pz1: float
    d1: float
    d2: float
    da1: float
    da2: float
    df1: float
    df2: float
    a: float
    ratio: float


def worm(gears: GearSet) -> WormValues:
    """The closed forms of a worm drive (see :class:`WormValues`).

    >>> from graphmech.mechanisms.gear import SpurGear, ToothSystem
    >>> w = worm(GearSet(ToothSystem(0.005, math.radians(20), 1.0, 0.2), (SpurGear(2), SpurGear(41)), "worm",
    ...                  spatial=SpatialPair(worm_diameter=0.05)))
    >>> round(math.degrees(w.gamma1), 9), round(w.a * 1e3, 9), w.q
    (11.309932474, 127.5, 10.0)
    """
    sp = _spatial(gears, "worm")
    s = gears.system
    d1 = sp.worm_diameter
    if d1 is None or not (math.isfinite(d1) and d1 > 0.0):
        raise OutOfDomain(f"a worm needs its reference diameter d₁ > 0, not {d1!r}")
    z1, z2 = gears.gears[0].z, gears.gears[1].z
    ha, hf = s.ha_star * s.m, (s.ha_star + s.c_star) * s.m
    if d1 - 2.0 * hf <= 0.0:
        raise OutOfDomain(f"d₁ = {d1 * 1e3:.6g} mm leaves no worm core: d_f1 = d₁ − 2(h*a + c*)m ≤ 0")
    q = d1 / s.m
    gamma = math.atan2(z1, q)
    d2 = s.m * z2
    return WormValues(z2=z2, q=q, gamma1=gamma, beta2=gamma, px=math.pi * s.m, pz1=z1 * math.pi * s.m, d1=d1, d2=d2,
                      da1=d1 + 2.0 * ha, da2=d2 + 2.0 * ha, df1=d1 - 2.0 * hf, df2=d2 - 2.0 * hf,
                      a=0.5 * (d1 + d2), ratio=z2 / z1)


__all__ = ["BETA_MAX", "BevelValues", "HelicalValues", "WormValues", "bevel", "helical", "helix_angle", "worm"]
