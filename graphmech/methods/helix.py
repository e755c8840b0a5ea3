"""Helical, bevel and worm gears constructed as the book draws them: the developed reference
cylinder, the normal section's ellipse, the transverse meshing, the worm's developed thread, the
bevel pair's cones and back cones (Tredgold).

Every value is a length or an angle measured on lines drawn and cut (the kernels' intersections);
the closed forms are :mod:`graphmech.exact.gear_spatial`'s. Where a value is a definition it is
equal by construction and said so: d = m_t z, d_a = d + 2h_a, d_f = d − 2h_f, d_b = d cos α_t
(the transverse circles, as for a spur gear); p_n = πm_n, s_n = p_n/2 (the normal rack's pitch
and tooth, x = 0); the worm's p_x = πm, q = d₁/m, d₂ = mz₂, a = (d₁ + d₂)/2.

Coordinates of a development: x along the circumference (the cylinder unrolled), y along the
axis; a helix is a straight line at β to the axis (y), rising to the right.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from graphmech.errors import NotApplicable, OutOfDomain
from graphmech.geometry.kernels import ScalarOps, intersect_circle_line, intersect_lines
from graphmech.mechanisms.gear import GearSet, SpatialPair, SpurGear, ToothSystem
from graphmech.methods.gear_meshing import MeshConstruction, construct_meshing
from graphmech.methods.involute import at_radius

XY = tuple[float, float]
Line = tuple[float, float, float, float]  # a point and a unit direction (px, py, ux, uy)


def _cut(ops: ScalarOps, l1: Line, l2: Line, step: str) -> XY:
    ops.step = step
    p = intersect_lines(ops, l1, l2)
    return float(p[0]), float(p[1])


def _angle(u: XY, v: XY) -> float:
    """The angle between two directions, 0 … π."""
    return math.atan2(abs(u[0] * v[1] - u[1] * v[0]), u[0] * v[0] + u[1] * v[1])


def _dist(a: XY, b: XY) -> float:
    return math.hypot(a[0] - b[0], a[1] - b[1])


def _spatial(gears: GearSet, kind: str) -> SpatialPair:
    if gears.meshing != kind or len(gears.gears) != 2:
        raise NotApplicable(f"not a {kind} pair of two gears (meshing = {gears.meshing!r})")
    return gears.spatial if gears.spatial is not None else SpatialPair()


# --------------------------------------------------------------------------------------------
# The helical pair


@dataclass(frozen=True)
class HelixAngle:
    """β found from a rounded centre distance: the leg L = m_n(z₁ + z₂)/2 laid off from O, the
    circle of radius a about O cut by the perpendicular at L in A; β = ∠LOA. ``initial``: the
    line from O at β_stated cut by that perpendicular at I, a_initial = OI. Without a stated a,
    A = I (β is the stated one)."""

    L: XY
    A: XY
    I: XY
    beta: float
    a_initial: float


@dataclass(frozen=True)
class Development:
    """The reference cylinder's development (x along the circumference, y along the axis),
    ``width`` πd of gear 1 (πd₂ is z₂/z₁ of it) by ``height`` B. ``helices``: tooth lines through
    (k·p_t, 0), k = 0, 1, 2 … drawn as segments across the strip; the normal pitch p_n laid off
    perpendicular to the helix through O gives ``Pn`` (foot on the next helix) and, cut by the
    x axis, ``Pt`` = (p_t, 0); the normal tooth s_n likewise gives ``St`` = (s_t, 0). ``beta``:
    measured between the drawn helix and the axis; ``top``: the helix through O cut by y = B,
    its x the advance B·tan β. ``rack``: the normal rack's flank offset h·tan α_n (h = m_n) laid
    off normal to the helix, cut by the x axis at (w_t, 0), so tan α_t = w_t/h."""

    width: float
    height: float
    helices: tuple[tuple[XY, XY], ...]
    Pn: XY
    Pt: XY
    St: XY
    top: XY
    beta: float
    pn: float
    pt: float
    sn: float
    st: float
    mt: float
    alpha_t: float
    advance: float


@dataclass(frozen=True)
class Lead:
    """One gear's helix over a whole turn, developed: the base πd from (0, 0) to (πd, 0), the
    helix from (0, 0) at β to the axis cut by the vertical x = πd at (πd, p_z): the lead. On the
    base cylinder the same lead over πd_b: β_b = ∠ between (πd_b, p_z) and the axis."""

    pi_d: float
    pi_db: float
    pz: float
    beta_b: float


@dataclass(frozen=True)
class NormalSection:
    """The plane normal to the helix at the pitch point cuts the reference cylinder (radius r) in an
    ellipse of semi-axes a_e = r/cos β (constructed: the trace of the plane, at β to the
    transverse section, cut by the cylinder's outline x = r) and b_e = r. Its radius of curvature
    at the pitch point (the end of the minor axis) by the rectangle's construction: the corner
    C = (a_e, b_e), the perpendicular from C to the diagonal (a_e, 0)–(0, b_e) cuts the minor axis
    at the centre of curvature K; ρ = |K, (0, b_e)| = a_e²/b_e, and z_v = 2ρ/m_n."""

    r: float
    E: XY
    a_e: float
    b_e: float
    C: XY
    K: XY
    rho: float
    zv: float


@dataclass(frozen=True)
class HelicalConstruction:
    """The helical pair constructed: β, the development, each gear's lead and normal section, the
    transverse tooth system (m_t, α_t measured; h_a and h_f the normal ones, as lengths) and its
    pair in mesh (:func:`graphmech.methods.gear_meshing.construct_meshing`: B₁B₂, p_bt, ε_α),
    the tip pressure angles measured on the transverse flanks, ε_β = (B tan β)/p_t,
    ε_γ = ε_α + ε_β (None without B); leads None at β = 0."""

    angle: HelixAngle
    development: Development
    leads: tuple[Lead, Lead] | None
    sections: tuple[NormalSection, NormalSection]
    transverse: GearSet
    mesh: MeshConstruction
    alpha_at: tuple[float, float]
    eps_alpha: float
    eps_beta: float | None
    eps_gamma: float | None


def helix_angle(gears: GearSet) -> HelixAngle:
    """β from a stated centre distance (see :class:`HelixAngle`)."""
    sp = _spatial(gears, "helical")
    ops = ScalarOps()
    half = 0.5 * gears.system.m * (gears.gears[0].z + gears.gears[1].z)
    L = (half, 0.0)
    up: Line = (half, 0.0, 0.0, 1.0)
    I = _cut(ops, (0.0, 0.0, math.cos(sp.beta), math.sin(sp.beta)), up, "I = the line at β₀ ∩ the perpendicular at L")
    a = gears.centre_distance
    if a is None:
        A = I
    else:
        if a < half:
            raise OutOfDomain(f"the circle of radius a = {a * 1e3:.6g} mm does not reach the perpendicular at "
                              f"m_n(z₁ + z₂)/2 = {half * 1e3:.6g} mm: no helix angle gives this a")
        ops.step = "A = the circle (O, a) ∩ the perpendicular at L"
        p = intersect_circle_line(ops, (0.0, 0.0), a, up, 1.0, lambda e: "the circle misses the perpendicular")
        A = (float(p[0]), max(float(p[1]), 0.0))
    return HelixAngle(L=L, A=A, I=I, beta=math.atan2(A[1], A[0]), a_initial=math.hypot(*I))


def development(system: ToothSystem, z1: int, beta: float, height: float, teeth: int = 4) -> Development:
    """The development of gear 1's reference cylinder over ``height`` (see :class:`Development`)."""
    ops = ScalarOps()
    u = (math.sin(beta), math.cos(beta))        # along the helix
    n = (math.cos(beta), -math.sin(beta))       # normal to it, in the development
    axis_x: Line = (0.0, 0.0, 1.0, 0.0)
    pn = math.pi * system.m                     # the normal rack's pitch: a definition
    sn = 0.5 * pn

    def offset(w: float) -> Line:
        return (w * n[0], w * n[1], u[0], u[1])

    Pt = _cut(ops, offset(pn), axis_x, "Pt = the helix p_n further on ∩ the x axis")
    St = _cut(ops, offset(sn), axis_x, "St = the tooth's other flank (s_n on) ∩ the x axis")
    h = system.m
    w_n = h * math.tan(system.alpha)            # the normal rack's flank over the depth h = m_n
    W = _cut(ops, offset(w_n), axis_x, "the normal flank offset ∩ the x axis: w_t")
    pt, st = Pt[0], St[0]
    Pn = (pn * n[0], pn * n[1])
    top = _cut(ops, (0.0, 0.0, u[0], u[1]), (0.0, height, 1.0, 0.0), "the helix through O ∩ y = B")
    width = z1 * pt                             # πd = z·p_t: the circumference divided into z
    helices = []
    for k in range(teeth + 1):
        x0 = k * pt
        helices.append(((x0, 0.0), (x0 + top[0], height)))
    return Development(width=width, height=height, helices=tuple(helices), Pn=Pn, Pt=Pt, St=St, top=top,
                       beta=_angle(u, (0.0, 1.0)), pn=pn, pt=pt, sn=sn, st=st, mt=pt / math.pi,
                       alpha_t=math.atan2(W[0], h), advance=top[0])


def lead(pi_d: float, pi_db: float, beta: float) -> Lead | None:
    """One turn of the helix developed (see :class:`Lead`); None at β = 0 (it never turns)."""
    if beta == 0.0:
        return None
    ops = ScalarOps()
    Z = _cut(ops, (0.0, 0.0, math.sin(beta), math.cos(beta)), (pi_d, 0.0, 0.0, 1.0), "the helix ∩ x = πd")
    return Lead(pi_d=pi_d, pi_db=pi_db, pz=Z[1], beta_b=_angle((pi_db, Z[1]), (0.0, 1.0)))


def normal_section(r: float, beta: float, mn: float) -> NormalSection:
    """The normal section's ellipse and its radius of curvature at the pitch point."""
    ops = ScalarOps()
    E = _cut(ops, (0.0, 0.0, math.cos(beta), math.sin(beta)), (r, 0.0, 0.0, 1.0),
             "E = the normal plane's trace ∩ the cylinder's outline")
    a_e, b_e = math.hypot(*E), r
    C = (a_e, b_e)
    diag = (-a_e, b_e)
    nd = math.hypot(*diag)
    perp = (b_e / nd, a_e / nd)                 # ⟂ to the diagonal (a_e, 0)–(0, b_e)
    K = _cut(ops, (C[0], C[1], perp[0], perp[1]), (0.0, 0.0, 0.0, 1.0), "K = the perpendicular from C ∩ the minor axis")
    rho = b_e - K[1]
    return NormalSection(r=r, E=E, a_e=a_e, b_e=b_e, C=C, K=K, rho=rho, zv=2.0 * rho / mn)


def construct_helical(gears: GearSet) -> HelicalConstruction:
    """The helical pair constructed (see :class:`HelicalConstruction`)."""
    sp = _spatial(gears, "helical")
    s = gears.system
    z1, z2 = gears.gears[0].z, gears.gears[1].z
    ang = helix_angle(gears)
    beta = ang.beta
    B = sp.face_width
    dev = development(s, z1, beta, B if B is not None else 3.0 * math.pi * s.m)
    # the transverse section: a spur pair of module m_t and pressure angle α_t, its addendum and
    # dedendum the normal ones (h_a = h*a·m_n), as coefficients of m_t
    k = s.m / dev.mt
    ts = ToothSystem(dev.mt, dev.alpha_t, s.ha_star * k, s.c_star * k)
    tg = GearSet(ts, (SpurGear(z1), SpurGear(z2)), "external")
    mesh = construct_meshing(tg)
    r = (0.5 * dev.mt * z1, 0.5 * dev.mt * z2)
    alpha_at = tuple(at_radius(ts, g, r_i + s.ha_star * s.m).alpha_k for g, r_i in zip(tg.gears, r))
    sections = (normal_section(r[0], beta, s.m), normal_section(r[1], beta, s.m))
    leads = None
    l1 = lead(math.pi * 2.0 * r[0], math.pi * 2.0 * r[0] * math.cos(dev.alpha_t), beta)
    l2 = lead(math.pi * 2.0 * r[1], math.pi * 2.0 * r[1] * math.cos(dev.alpha_t), beta)
    if l1 is not None and l2 is not None:
        leads = (l1, l2)
    eps_beta = None if B is None else dev.advance / dev.pt
    return HelicalConstruction(angle=ang, development=dev, leads=leads, sections=sections, transverse=tg, mesh=mesh,
                               alpha_at=(alpha_at[0], alpha_at[1]), eps_alpha=mesh.eps_alpha, eps_beta=eps_beta,
                               eps_gamma=None if eps_beta is None else mesh.eps_alpha + eps_beta)


# --------------------------------------------------------------------------------------------
# The bevel pair


@dataclass(frozen=True)
class BevelConstruction:
    """The bevel pair in its axial section: the apex O at the origin, gear 1's axis along +x, gear
    2's at Σ from it (``u2``). P, the pitch point at the large end, is where the lines at r₁ from
    axis 1 and at r₂ from axis 2 cross; δ₁ = ∠(axis 1, OP), δ₂ = ∠(OP, axis 2), R = OP. The back
    cone's generator is the perpendicular to OP at P; it cuts axis 1 at ``V1`` and axis 2 at ``V2``:
    the virtual gears' radii r_v = V_iP (Tredgold) and z_v = 2r_v/m. The tips A_i and roots F_i are
    laid off from P along the back cone (h_a out, h_f in): θ_a = ∠POA₁, θ_f = ∠POF₁, d_a = 2·A_i's
    distance from its axis, d_f likewise."""

    u2: XY
    P: XY
    V1: XY
    V2: XY
    A: tuple[XY, XY]
    F: tuple[XY, XY]
    delta: tuple[float, float]
    R: float
    theta_a: float
    theta_f: float
    da: tuple[float, float]
    df: tuple[float, float]
    r_v: tuple[float, float]
    zv: tuple[float, float]


def _from_axis(p: XY, u: XY, side: XY | None = None) -> float:
    """The distance of p from the line through O along the unit u; with ``side``, negative when p
    lies beyond the axis from it (a root point past the axis of a gear of few teeth: d_f < 0, as a
    spur gear's)."""
    d = p[0] * u[1] - p[1] * u[0]
    if side is not None and d * (side[0] * u[1] - side[1] * u[0]) < 0.0:
        return -abs(d)
    return abs(d)


def construct_bevel(gears: GearSet) -> BevelConstruction:
    """The bevel pair's axial section (see :class:`BevelConstruction`)."""
    sp = _spatial(gears, "bevel")
    s = gears.system
    ops = ScalarOps()
    sigma = sp.shaft_angle
    r1, r2 = 0.5 * s.m * gears.gears[0].z, 0.5 * s.m * gears.gears[1].z
    u1 = (1.0, 0.0)
    u2 = (math.cos(sigma), math.sin(sigma))
    n2 = (math.sin(sigma), -math.cos(sigma))    # from axis 2 towards axis 1
    P = _cut(ops, (0.0, r1, 1.0, 0.0), (r2 * n2[0], r2 * n2[1], u2[0], u2[1]),
             "P = the line r₁ from axis 1 ∩ the line r₂ from axis 2")
    R = math.hypot(*P)
    op = (P[0] / R, P[1] / R)
    delta = (_angle(u1, op), _angle(op, u2))
    if max(delta) >= 0.5 * math.pi or P[0] <= 0.0:
        raise NotApplicable("a pitch cone angle reaches 90°: a crown or internal bevel gear, not posed here")
    back = (P[0], P[1], -op[1], op[0])         # the back cone's generator, ⟂ OP at P
    V1 = _cut(ops, back, (0.0, 0.0, 1.0, 0.0), "V1 = the back cone ∩ axis 1")
    V2 = _cut(ops, back, (0.0, 0.0, u2[0], u2[1]), "V2 = the back cone ∩ axis 2")
    ha, hf = s.ha_star * s.m, (s.ha_star + s.c_star) * s.m
    A, F, da, df = [], [], [], []
    for V, u in ((V1, u1), (V2, u2)):
        rv = _dist(V, P)
        w = ((P[0] - V[0]) / rv, (P[1] - V[1]) / rv)   # along the back cone, away from the axis
        a_pt, f_pt = (P[0] + ha * w[0], P[1] + ha * w[1]), (P[0] - hf * w[0], P[1] - hf * w[1])
        A.append(a_pt)
        F.append(f_pt)
        da.append(2.0 * _from_axis(a_pt, u))
        df.append(2.0 * _from_axis(f_pt, u, P))
    r_v = (_dist(V1, P), _dist(V2, P))
    return BevelConstruction(u2=u2, P=P, V1=V1, V2=V2, A=(A[0], A[1]), F=(F[0], F[1]), delta=(delta[0], delta[1]),
                             R=R, theta_a=_angle(op, A[0]), theta_f=_angle(op, F[0]), da=(da[0], da[1]),
                             df=(df[0], df[1]), r_v=r_v, zv=(2.0 * r_v[0] / s.m, 2.0 * r_v[1] / s.m))


# --------------------------------------------------------------------------------------------
# The worm


@dataclass(frozen=True)
class WormConstruction:
    """The worm's reference cylinder developed (x around, y along the worm's axis): one turn πd₁
    wide; the thread from O rising to T = (πd₁, p_z) (the lead p_z = z₁p_x laid off along the
    axis); the other z₁ − 1 starts parallel, p_x apart along the axis. γ₁ = ∠(thread, x): the lead
    angle; the wheel's axis lies along x (crossed at 90°), so its helix angle β₂ is the same
    angle, measured to the wheel's axis."""

    pi_d1: float
    px: float
    pz1: float
    T: XY
    threads: tuple[tuple[XY, XY], ...]
    gamma1: float
    beta2: float


def construct_worm(gears: GearSet) -> WormConstruction:
    """The worm's developed thread (see :class:`WormConstruction`)."""
    sp = _spatial(gears, "worm")
    if sp.worm_diameter is None:
        raise OutOfDomain("a worm needs its reference diameter d₁ (worm_diameter or q)")
    s = gears.system
    ops = ScalarOps()
    z1 = gears.gears[0].z
    pi_d1 = math.pi * sp.worm_diameter
    px = math.pi * s.m
    pz = z1 * px                                # the lead: z₁ axial pitches laid off
    n = math.hypot(pi_d1, pz)
    T = _cut(ops, (0.0, 0.0, pi_d1 / n, pz / n), (pi_d1, 0.0, 0.0, 1.0), "T = the thread ∩ x = πd₁")
    threads = tuple(((0.0, k * px), (T[0], T[1] + k * px)) for k in range(z1))
    thread = (T[0], T[1])
    return WormConstruction(pi_d1=pi_d1, px=px, pz1=T[1], T=T, threads=threads,
                            gamma1=_angle(thread, (1.0, 0.0)), beta2=_angle(thread, (1.0, 0.0)))


__all__ = ["BevelConstruction", "Development", "HelicalConstruction", "HelixAngle", "Lead", "NormalSection",
           "WormConstruction", "construct_bevel", "construct_helical", "construct_worm", "development",
           "helix_angle", "lead", "normal_section"]
