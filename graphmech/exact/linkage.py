"""Exact kinematics of a planar class-II linkage by closed-form vector loops.

This is the textbook's *analytical* method, kept apart from the graphical one so that it can check
it: every dyad is a closed vector loop written with complex numbers (a plane vector ``x + iy``,
a link of length ``l`` at angle ``θ`` is ``l·e^{iθ}``). Positions come in angle form (law of
cosines and ``atan2`` for RRR, ``arcsin`` for RRP, ``atan2`` for RPR (less the tangent angle ``atan2(e, t)`` for an offset
guide bar), a fixed-angle triangle for
RPP, two lines' intersection for PRP); velocities and accelerations come from differentiating the loop once and twice, which gives
two linear equations in the two unknown rates, solved by Cramer's rule written out.

Nothing here is taken from ``graphmech.construction``, ``graphmech.methods`` or
``graphmech.geometry``: a check that reuses what it checks proves nothing. The module imports only
numpy, math, the linkage model and the errors.

Notes
-----
A plane vector ``u`` is the complex number ``u_x + i·u_y``; ``u × w = Im(ū·w) = u_x w_y − u_y w_x``.
The real unknowns ``x, y`` of ``x·a + y·b = c`` (two scalar equations) are, by Cramer's rule,
``x = (c × b)/(a × b)`` and ``y = (a × c)/(a × b)``. A link vector ``l·e^{iθ}`` has the time
derivative ``i·ω·l·e^{iθ}`` and the second derivative ``(i·α − ω²)·l·e^{iθ}``: every dyad below
uses only these two rules.
"""
from __future__ import annotations

import cmath
import math
from dataclasses import dataclass
from typing import Union, cast

import numpy as np

from graphmech.errors import OutOfDomain, SceneError
from graphmech.tolerances import PARALLEL_SIN, TANGENT_REL
from graphmech.mechanisms.linkage import (
    PRP,
    RPP,
    RPR,
    RRP,
    RRR,
    Crank,
    Guide,
    Linkage,
    LinkGuide,
    LinkPoint,
    SliderInput,
    Triad,
)
from graphmech.exact.triad import solve_triad

__all__ = ["Kinematics", "solve"]

# Tolerances are shared (one place for all of them); the *computation* here shares nothing with
# the construction. TANGENT_REL: relative discriminant (sin² of the dyad's angle at its outer
# joint) down to which two circles, or a circle and a guide, still count as touching.
# PARALLEL_SIN: |sin| of an RPP's slot–guide angle below which the lines count as parallel.

#: Relative size below which two pivots count as coincident.
_COINCIDENT_REL = 1e-12

_TWO_PI = 2.0 * math.pi

_Array = np.ndarray
_Vec = Union[_Array, complex]  # a plane vector (or N of them) as complex numbers


@dataclass(frozen=True)
class Kinematics:
    """Exact state at N positions (arrays have first axis N).

    Parameters
    ----------
    point : dict of str to ndarray, shape (N, 2)
        Every named point's position, m.
    vel : dict of str to ndarray, shape (N, 2)
        Every named point's velocity, m/s.
    acc : dict of str to ndarray, shape (N, 2)
        Every named point's acceleration, m/s².
    angle : dict of str to ndarray, shape (N,)
        Moving link id → angle of the link, rad in [0, 2π): the direction of its first two points
        in ``Linkage.links()`` order; the guide (or slot) angle for a translating link; the bar's
        angle for an RPR block; an offset guide bar's (and its block's) angle is its line's direction
        û, from the foot F of the perpendicular from its pivot towards the block.
    omega : dict of str to ndarray, shape (N,)
        Moving link id → angular velocity, rad/s, + CCW (0 for translating links).
    alpha : dict of str to ndarray, shape (N,)
        Moving link id → angular acceleration, rad/s², + CCW.
    valid : ndarray of bool, shape (N,)
        False where the linkage cannot be assembled or a rate is unbounded (a dead centre: a
        dyad's velocity equations are singular).
    reason : tuple of str
        Per position: ``""`` where valid, else a short reason (the first dyad that failed).
    assembled : ndarray of bool, shape (N,)
        False only where the linkage cannot be assembled: a dead centre is assembled (its
        ``point`` holds the configuration) though not ``valid`` — what a check of positions asks.

    Notes
    -----
    All arrays are finite and read-only. Where the linkage cannot be assembled, every array is 0
    at that position. At a dead centre (a tangent assembly: the position exists, the rates do
    not) ``point`` and ``angle`` hold the configuration and ``vel``, ``acc``, ``omega``,
    ``alpha`` are 0.
    """

    point: dict[str, np.ndarray]
    vel: dict[str, np.ndarray]
    acc: dict[str, np.ndarray]
    angle: dict[str, np.ndarray]
    omega: dict[str, np.ndarray]
    alpha: dict[str, np.ndarray]
    valid: np.ndarray
    reason: tuple[str, ...]
    assembled: np.ndarray


# --------------------------------------------------------------------------------------------
# Plane-vector algebra on complex numbers


def _cross(u: _Vec, w: _Vec) -> _Array:
    """``u × w = u_x·w_y − u_y·w_x`` (the z-component of the cross product)."""
    return cast(_Array, u.real * w.imag - u.imag * w.real)


def _cramer(a: _Vec, b: _Vec, c: _Vec, det: _Vec) -> tuple[_Array, _Array]:
    """Real ``x, y`` with ``x·a + y·b = c``, given ``det = a × b`` (Cramer's rule)."""
    return _cross(c, b) / det, _cross(a, c) / det


class _State:
    """What is known so far while the dyads are solved in order."""

    def __init__(self, n: int) -> None:
        self.n = n
        self.zero = np.zeros(n, dtype=complex)
        self.pts: dict[str, tuple[_Array, _Array, _Array]] = {}  # name -> (z, v, a) complex
        self.angle: dict[str, _Array] = {}
        self.omega: dict[str, _Array] = {}
        self.alpha: dict[str, _Array] = {}
        self.assembled = np.ones(n, dtype=bool)
        self.valid = np.ones(n, dtype=bool)
        self.reason = np.full(n, "", dtype=object)

    def fail(self, mask: _Array, why: str, *, dead_centre: bool = False) -> None:
        """Mark positions invalid (keeping the first reason); a dead centre stays assembled."""
        new = mask & self.valid
        if new.any():
            self.reason[new] = why
            self.valid &= ~mask
        if not dead_centre:
            self.assembled &= ~mask

    def translating(self, link: str, angle: float) -> None:
        self.angle[link] = np.full(self.n, angle)
        self.omega[link] = self.alpha[link] = np.zeros(self.n)

    def rotating(self, link: str, theta: _Array, w: _Array, al: _Array) -> None:
        self.angle[link], self.omega[link], self.alpha[link] = theta, w, al


# --------------------------------------------------------------------------------------------
# Driver and dyads


def _crank(st: _State, d: Crank, phi: _Array) -> None:
    """``B = A + l·e^{iφ}``; ``v_B = iω·l·e^{iφ}``; ``a_B = (iε − ω²)·l·e^{iφ}``."""
    za = st.pts[d.pivot][0]
    r = d.length * np.exp(1j * phi)
    st.pts[d.tip] = (za + r, 1j * d.omega * r, (1j * d.epsilon - d.omega**2) * r)
    st.rotating(d.link, phi, np.full(st.n, d.omega), np.full(st.n, d.epsilon))


def _slider_input(st: _State, d: SliderInput, s: _Array) -> None:
    """``C = G + s·u`` with constant ``ṡ`` and ``s̈`` along the guide direction ``u``."""
    u = cmath.exp(1j * d.guide.angle)
    g = complex(*d.guide.through)
    st.pts[d.point] = (g + s * u, np.full(st.n, d.velocity * u), np.full(st.n, d.acceleration * u))
    st.translating(d.link, d.guide.angle)


def _rrr(st: _State, y: RRR) -> None:
    """P–C–Q: loop ``P + l1·e^{iθ1} = Q + l2·e^{iθ2}``, C on the ``branch`` side of P→Q.

    Position: with ``PQ = d·e^{iψ}``, the law of cosines gives the projection of PC on PQ,
    ``a1 = l1·cos β = (l1² + d² − l2²)/(2d)``, the height ``h = l1·sin β = √(l1² − a1²)``, and the
    angles at P and Q, ``β = atan2(h, a1)``, ``γ = atan2(h, d − a1)``. Then ``θ1 = ψ ± β`` and
    ``θ2 = ψ + π ∓ γ`` (upper sign: C to the left). Rates: differentiating the loop,
    ``ω1·(i·l1·e1) + ω2·(−i·l2·e2) = v_Q − v_P`` and, once more,
    ``α1·(i·l1·e1) + α2·(−i·l2·e2) = a_Q − a_P + ω1²·l1·e1 − ω2²·l2·e2``; the determinant is
    ``l1·l2·sin(θ1 − θ2)``, zero exactly at the tangent (dead-centre) assembly.
    """
    zp, vp, ap = st.pts[y.p]
    zq, vq, aq = st.pts[y.q]
    l1, l2 = y.lengths
    sign = 1.0 if y.branch == "left" else -1.0
    pq = zq - zp
    d = np.abs(pq)
    psi = np.arctan2(pq.imag, pq.real)
    coincide = d <= _COINCIDENT_REL * (l1 + l2)
    d = np.where(coincide, 1.0, d)
    a1 = (l1 * l1 + d * d - l2 * l2) / (2.0 * d)
    sin2 = 1.0 - (a1 / l1) ** 2  # sin²β: the discriminant relative to l1²
    h = l1 * np.sqrt(np.maximum(sin2, 0.0))
    th1 = psi + sign * np.arctan2(h, a1)
    th2 = psi + math.pi - sign * np.arctan2(h, d - a1)
    name = f"RRR {y.p}-{y.c}-{y.q}"
    st.fail(coincide, f"{name}: {y.p} and {y.q} coincide")
    st.fail(sin2 < -TANGENT_REL, f"{name}: cannot be assembled (|{y.p}{y.q}| out of reach)")
    dead = sin2 <= TANGENT_REL
    st.fail(dead, f"{name}: dead centre ({y.p}, {y.c}, {y.q} in line), rates unbounded",
            dead_centre=True)

    r1 = l1 * np.exp(1j * th1)
    r2 = l2 * np.exp(1j * th2)
    k1, k2 = 1j * r1, -1j * r2  # coefficients of ω1 and ω2 (and of α1, α2)
    det = np.where(dead, 1.0, _cross(k1, k2))
    w1, w2 = _cramer(k1, k2, vq - vp, det)
    al1, al2 = _cramer(k1, k2, aq - ap + w1 * w1 * r1 - w2 * w2 * r2, det)
    st.pts[y.c] = (zp + r1, vp + w1 * k1, ap + al1 * k1 - w1 * w1 * r1)
    st.rotating(y.links[0], th1, w1, al1)
    st.rotating(y.links[1], th2, w2, al2)


def _rrp(st: _State, y: RRP) -> None:
    """P–C, C sliding on a guide: loop ``P + l·e^{iθ} = G + s·u``, ``u = e^{iδ}``.

    Position: the loop's component across the guide gives ``sin(θ − δ) = −h/l`` with
    ``h = u × (P − G)``, P's distance to the left of the guide; ``θ − δ = arcsin(−h/l)`` forward,
    ``π − arcsin(−h/l)`` backward; along the guide ``s = u·(P − G) + l·cos(θ − δ)``. Rates:
    ``ω·(i·l·e^{iθ}) + ṡ·(−u) = −v_P`` and ``α·(i·l·e^{iθ}) + s̈·(−u) = −a_P + ω²·l·e^{iθ}``;
    the determinant is ``l·cos(θ − δ)``, zero when the coupler stands square to the guide.

    A guide on a moving link k (G its point ``through``, u turning with ``u̇ = iω_k·u``) adds its own
    motion to the right-hand sides: ``v_G + iω_k·s·u`` and ``a_G + (iα_k − ω_k²)·s·u + 2iω_k·ṡ·u``
    (the Coriolis term); the slider turns with k.
    """
    zp, vp, ap = st.pts[y.p]
    l = y.length
    zg, vg, ag, u, wk, alk, bad = _guide_line(st, y.guide)
    delta = y.guide.angle if isinstance(y.guide, Guide) else np.angle(u)  # a frame guide's as given
    rel = zp - zg
    sin_rel = -_cross(u, rel) / l  # sin(θ − δ)
    sin2 = 1.0 - sin_rel * sin_rel  # cos²(θ − δ): the discriminant relative to l²
    rel_angle = np.arcsin(np.clip(sin_rel, -1.0, 1.0))
    if y.branch == "backward":
        rel_angle = math.pi - rel_angle
    th = delta + rel_angle
    s = (rel * u.conjugate()).real + l * np.cos(rel_angle)
    name = f"RRP {y.p}-{y.c}"
    st.fail(bad, f"{name}: the guide's two points coincide, its line is undefined")
    st.fail(sin2 < -TANGENT_REL, f"{name}: cannot be assembled ({y.p} farther than l from the guide)")
    dead = sin2 <= TANGENT_REL
    st.fail(dead, f"{name}: dead centre ({y.p}{y.c} square to the guide), rates unbounded",
            dead_centre=True)

    r = l * np.exp(1j * th)
    k1 = 1j * r  # coefficient of ω (and α); that of ṡ (and s̈) is −u
    det = np.where(dead | bad, 1.0, _cross(k1, -u))
    w, sd = _cramer(k1, -u, vg + 1j * wk * s * u - vp, det)
    al, sdd = _cramer(k1, -u, ag + (1j * alk - wk * wk) * s * u + 2j * wk * sd * u - ap + w * w * r, det)
    zc = zg + s * u
    st.pts[y.c] = (zc, vp + w * k1, ap + al * k1 - w * w * r)
    st.rotating(y.links[0], th, w, al)
    if isinstance(y.guide, LinkGuide):  # the guide link's point at C; the slider turns with it
        on_slider, on_guide = y.coincident
        st.pts[on_slider] = st.pts[y.c]
        st.pts[on_guide] = (zc, vg + 1j * wk * s * u, ag + (1j * alk - wk * wk) * s * u)
        st.rotating(y.links[1], np.broadcast_to(np.asarray(delta, dtype=float), (st.n,)),
                    np.broadcast_to(wk, (st.n,)).astype(float),
                    np.broadcast_to(alk, (st.n,)).astype(float))
    else:
        st.pts[y.c] = (zc, sd * u, sdd * u)  # exactly along the guide
        st.translating(y.links[1], y.guide.angle)


def _rpr(st: _State, y: RPR) -> None:
    """Guide bar pivoted at B, block pivoted at X sliding on it: loop ``B + r·e^{iθ} = X``.

    Position: ``r = |X − B|``, ``θ = atan2(X − B)``. Rates (the block turns with the bar):
    ``ṙ·e^{iθ} + ω·(i·r·e^{iθ}) = v_X − v_B`` and
    ``r̈·e^{iθ} + α·(i·r·e^{iθ}) = a_X − a_B − 2·ṙ·ω·i·e^{iθ} + ω²·r·e^{iθ}`` (the Coriolis term
    ``2·ṙ·ω·i·e^{iθ}``); the determinant is ``r``. The bar's point at X moves with
    ``v_B + ω·(i·r·e^{iθ})`` and ``a_B + (iα − ω²)·r·e^{iθ}``; the block's point at X is X itself.
    """
    if y.offset != 0.0:
        _rpr_offset(st, y)
        return
    zb, vb, ab = st.pts[y.bar_pivot]
    zx, vx, ax = st.pts[y.block_pivot]
    rel = zx - zb
    r = np.abs(rel)
    th = np.arctan2(rel.imag, rel.real)
    coincide = r <= _COINCIDENT_REL * np.maximum(np.abs(zb), np.abs(zx))
    st.fail(coincide, f"RPR {y.p}-{y.q}: {y.p} and {y.q} coincide, the bar's line is undefined")
    r = np.where(coincide, 1.0, r)

    # The bar's direction straight from the loop, not as e^{iθ} of a rounded θ: with the pin 2e-4 mm
    # from the pivot, θ's last bit moves e's small component by 1e-5 of itself, and the Coriolis
    # term 2·ṙ·ω, with ω ≈ 5e6 rad/s, with it.
    e = np.where(coincide, 1.0, rel / r)
    k2 = 1j * r * e  # coefficient of ω (and α); that of ṙ (and r̈) is e^{iθ}
    rd, w = _cramer(e, k2, vx - vb, r)
    _, al = _cramer(e, k2, ax - ab - 2.0 * rd * w * 1j * e + w * w * r * e, r)
    on_bar, on_block = y.coincident
    st.pts[on_bar] = (zx, vb + w * k2, ab + al * k2 - w * w * r * e)
    st.pts[on_block] = st.pts[y.block_pivot]
    st.rotating(y.bar_link, th, w, al)
    st.rotating(y.block_link, th, w, al)


def _rpr_offset(st: _State, y: RPR) -> None:
    """An offset guide bar: its line at e to the left of its pivot O, loop ``O + (t + i·e)·e^{iθ} = X``.

    Position: ``|X − O|² = t² + e²`` gives ``t = √(|OX|² − e²) > 0`` (X outside the circle of radius
    |e| about O; the line is the tangent from X to it) and ``θ = arg(X − O) − atan2(e, t)``. Rates,
    differentiating with ``e`` fixed on the bar and ``t`` sliding (the block turns with the bar):
    ``ṫ·e^{iθ} + ω·(i·(t + i·e)·e^{iθ}) = v_X − v_O`` and
    ``ẗ·e^{iθ} + α·(i·(t + i·e)·e^{iθ}) = a_X − a_O − 2·ṫ·ω·i·e^{iθ} + ω²·(t + i·e)·e^{iθ}``; the
    determinant is ``t``, zero where X is on the circle (a dead centre). The bar's point at X moves
    with ``v_O + iω·(X − O)`` and ``a_O + (iα − ω²)·(X − O)``.
    """
    zb, vb, ab = st.pts[y.bar_pivot]
    zx, vx, ax = st.pts[y.block_pivot]
    e_off = y.offset
    rel = zx - zb
    d = np.abs(rel)
    disc = 1.0 - (e_off / d) ** 2  # t²/|OX|²: cos² of the angle between OX and the line
    name = f"RPR {y.p}-{y.q}"
    st.fail(disc < -TANGENT_REL, f"{name}: cannot be assembled (the block's pivot {y.block_pivot} is within "
                                 f"the offset |e| of the bar's pivot {y.bar_pivot})")
    dead = disc <= TANGENT_REL
    st.fail(dead, f"{name}: dead centre ({y.block_pivot} on the circle of radius |e| about {y.bar_pivot}), "
                  "rates unbounded", dead_centre=True)
    t = d * np.sqrt(np.maximum(disc, 0.0))
    w_line = t + 1j * e_off  # X − O in the bar's frame
    u = rel / w_line  # e^{iθ}, straight from the loop (|t + i·e| ≥ |e| > 0)
    u = u / np.abs(u)
    th = np.angle(u)
    k2 = 1j * w_line * u  # coefficient of ω (and α); that of ṫ (and ẗ) is e^{iθ}
    det = np.where(dead, 1.0, t)
    td, w = _cramer(u, k2, vx - vb, det)
    _, al = _cramer(u, k2, ax - ab - 2.0 * td * w * 1j * u + w * w * w_line * u, det)
    on_bar, on_block = y.coincident
    st.pts[on_bar] = (zx, vb + 1j * w * rel, ab + (1j * al - w * w) * rel)
    st.pts[on_block] = st.pts[y.block_pivot]
    st.rotating(y.bar_link, th, w, al)
    st.rotating(y.block_link, th, w, al)


def _rpp(st: _State, y: RPP) -> None:
    """Block at P in a slot (``w = e^{iσ}``) of j, j on a frame guide: ``G + s·u + q·w = P``.

    Both links translate, so the triangle has fixed angles: ``s = ((P − G) × w)/(u × w)``,
    ``q = (u × (P − G))/(u × w)``, and the same two equations with ``v_P`` and ``a_P`` on the right
    give ``ṡ, q̇`` and ``s̈, q̈``. C moves with ``ṡ·u`` and ``s̈·u``; so does j's point at P.
    """
    zp, vp, ap = st.pts[y.p]
    u = cmath.exp(1j * y.guide.angle)
    w = cmath.exp(1j * y.slot_angle)
    g = complex(*y.guide.through)
    det = _cross(u, w)  # sin(σ − δ), non-zero (checked before solving)
    s, _ = _cramer(u, w, zp - g, det)
    sd, _ = _cramer(u, w, vp, det)
    sdd, _ = _cramer(u, w, ap, det)
    zc = g + s * u
    on_block, on_slotted = y.coincident
    st.pts[y.c] = (zc, sd * u, sdd * u)
    st.pts[on_block] = st.pts[y.p]
    st.pts[on_slotted] = (zp, sd * u, sdd * u)
    st.translating(y.links[0], y.slot_angle)
    st.translating(y.links[1], y.guide.angle)


def _guide_line(st: _State, g: Guide | LinkGuide) -> tuple[_Vec, _Vec, _Vec, _Vec, _Array, _Array, _Array]:
    """A guide line as ``(U, v_U, a_U, e, ω, α, bad)``: a point U on it, its direction e and the
    rates of the link it is fixed on (0 for the frame); ``bad`` where U and V coincide."""
    if isinstance(g, Guide):
        zero = np.zeros(st.n)
        return (complex(*g.through), st.zero, st.zero, np.full(st.n, cmath.exp(1j * g.angle)), zero, zero,
                np.zeros(st.n, dtype=bool))
    zu, vu, au = st.pts[g.through]
    uv = st.pts[g.towards][0] - zu
    length = np.abs(uv)
    bad = length <= _COINCIDENT_REL * np.maximum(np.abs(zu), np.abs(zu + uv))
    e = uv / np.where(bad, 1.0, length)
    return zu, vu, au, e, st.omega[g.link], st.alpha[g.link], bad


def _prp(st: _State, y: PRP) -> None:
    """Blocks on two guides pinned at C: ``U1 + t1·e1 = U2 + t2·e2`` (each e turning with its link).

    Position: Cramer's rule on ``t1·e1 − t2·e2 = U2 − U1``. With ``ė = iω·e`` the loop differentiated
    once and twice keeps the coefficients ``e1, −e2`` and gains on the right the guides' own motion:
    ``ṫ1·e1 − ṫ2·e2 = (v_U2 + iω2·t2·e2) − (v_U1 + iω1·t1·e1)`` and
    ``ẗ1·e1 − ẗ2·e2 = (a_U2 + (iα2 − ω2²)·t2·e2 + 2iω2·ṫ2·e2) − (a_U1 + (iα1 − ω1²)·t1·e1 + 2iω1·ṫ1·e1)``
    (the Coriolis terms ``2iω·ṫ·e``). The determinant ``e1 × e2`` vanishes when the guides are
    parallel: C is then at infinity (or anywhere on them), the linkage cannot be assembled.
    """
    u1, v1, a1, e1, w1, al1, bad1 = _guide_line(st, y.guides[0])
    u2, v2, a2, e2, w2, al2, bad2 = _guide_line(st, y.guides[1])
    name = f"PRP {y.c}"
    st.fail(bad1 | bad2, f"{name}: a guide's two points coincide, its line is undefined")
    det = _cross(e1, e2)
    parallel = np.abs(det) <= PARALLEL_SIN
    st.fail(parallel, f"{name}: the two guides are parallel, {y.c} is undefined")
    det = np.where(parallel | bad1 | bad2, 1.0, -det)  # the coefficients are e1 and −e2
    t1, t2 = _cramer(e1, -e2, u2 - u1, det)
    td1, td2 = _cramer(e1, -e2, v2 + 1j * w2 * t2 * e2 - v1 - 1j * w1 * t1 * e1, det)
    rhs = (a2 + (1j * al2 - w2 * w2) * t2 * e2 + 2j * w2 * td2 * e2
           - a1 - (1j * al1 - w1 * w1) * t1 * e1 - 2j * w1 * td1 * e1)
    tdd1, _ = _cramer(e1, -e2, rhs, det)
    zc = u1 + t1 * e1
    on_guide = [(u1, v1, a1, e1, w1, al1, t1), (u2, v2, a2, e2, w2, al2, t2)]
    st.pts[y.c] = (zc, v1 + 1j * w1 * t1 * e1 + td1 * e1,
                   a1 + (1j * al1 - w1 * w1) * t1 * e1 + 2j * w1 * td1 * e1 + tdd1 * e1)
    for k, (u, v, a, e, w, al, t) in enumerate(on_guide):
        st.pts[y.c + y.links[k]] = st.pts[y.c]
        on = y.on_guide(k)
        if on is not None:  # the guide's link's point at C
            st.pts[on] = (zc, v + 1j * w * t * e, a + (1j * al - w * w) * t * e)
        st.rotating(y.links[k], np.angle(e), np.broadcast_to(w, (st.n,)).astype(float),
                    np.broadcast_to(al, (st.n,)).astype(float))


def _triad(st: _State, y: Triad) -> None:
    """A class III group: its loops eliminated to one equation in θ2 (:mod:`graphmech.exact.triad`)."""
    sol = solve_triad(y, st.pts)
    for bad in np.flatnonzero(~sol.valid):
        st.fail(np.arange(st.n) == bad, sol.reason[bad], dead_centre=bool(sol.assembled[bad]))
    for k, name in enumerate(y.inner):
        st.pts[name] = (sol.z[k], sol.v[k], sol.a[k])
    for k, (row, link) in enumerate(zip((0, 2, 3), y.links[:3])):  # the solution's rows: θ2, θ3, θ4, θ5
        g = y.guides[k]
        if g is not None:  # a block on a frame guide
            st.translating(link, g.angle)
        else:
            st.rotating(link, sol.theta[row], sol.omega[row], sol.alpha[row])
    st.rotating(y.links[3], sol.theta[1], sol.omega[1], sol.alpha[1])


def _link_point(st: _State, pt: LinkPoint, frame_link: str) -> None:
    """``X = U + (along + i·left)·û`` on a rigid link: ``v = v_U + iω·UX``, ``a = a_U + (iα − ω²)·UX``."""
    zu, vu, au = st.pts[pt.base[0]]
    if len(pt.base) == 2:
        uv = st.pts[pt.base[1]][0] - zu
        length = np.abs(uv)
        coincide = length <= _COINCIDENT_REL * np.maximum(np.abs(zu), np.abs(zu + uv))
        st.fail(coincide, f"point {pt.name}: base points {pt.base[0]} and {pt.base[1]} coincide")
        ux = complex(pt.along, pt.left) * uv / np.where(coincide, 1.0, length)
    else:  # a translating link or the frame: absolute x/y offsets
        ux = complex(pt.along, pt.left)
    if pt.link == frame_link:
        st.pts[pt.name] = (zu + ux, vu, au)
        return
    w, al = st.omega[pt.link], st.alpha[pt.link]
    st.pts[pt.name] = (zu + ux, vu + 1j * w * ux, au + (1j * al - w * w) * ux)


# --------------------------------------------------------------------------------------------
# Structure check and solving order (once per call; collects every problem, then raises)

_Step = Union[Crank, SliderInput, RRR, RRP, RPR, RPP, PRP, Triad, LinkPoint]


def _plan(linkage: Linkage) -> list[_Step]:
    """The driver, the dyads and the extra points in solving order, after checking the structure.

    An extra point is solved as soon as its link and its base points are known, so a dyad may
    hang on a coupler point (a six-bar).
    """
    problems: list[tuple[str, str]] = []
    known = set(linkage.frame_points)
    links: set[str] = set()
    translating: set[str] = set()
    frame = linkage.frame_link
    carried = linkage.links()
    pending = list(enumerate(linkage.points))
    plan: list[_Step] = []

    def need(key: str, *names: str) -> None:
        for n in names:
            if n not in known:
                problems.append((key, f"point {n!r} is not known before this step"))

    def new_points(key: str, *names: str) -> None:
        for n in names:
            if n in known:
                problems.append((key, f"point {n!r} is defined twice"))
            known.add(n)

    def new_links(key: str, *ids: str) -> None:
        for i in ids:
            if i == frame or i in links:
                problems.append((key, f"link {i!r} is the frame or already used"))
            links.add(i)

    def link_guide(key: str, g: LinkGuide) -> None:
        """A guide on a moving link: that link solved before, the line through two of its points."""
        need(key, g.through, g.towards)
        if g.link == frame or g.link not in links:
            problems.append((key + ".link", f"link {g.link!r} is not a moving link solved before"))
        elif not {g.through, g.towards} <= set(carried[g.link]):
            problems.append((key + ".line", f"the line's points must be points of link {g.link!r}"))

    def place_points() -> None:
        progress = True
        while progress:
            progress = False
            for k, pt in list(pending):
                if (pt.link == frame or pt.link in links) and all(b in known for b in pt.base):
                    pending.remove((k, pt))
                    plan.append(pt)
                    new_points(f"points[{k}].name", pt.name)
                    progress = True

    d = linkage.driver
    if isinstance(d, Crank):
        if d.pivot not in linkage.frame_points:
            problems.append(("driver.pivot", f"crank pivot {d.pivot!r} is not a frame point"))
        if not d.length > 0:
            problems.append(("driver.length", "crank length must be > 0"))
        new_points("driver.tip", d.tip)
    else:
        new_points("driver.point", d.point)
        translating.add(d.link)
    new_links("driver.link", d.link)
    plan.append(d)
    place_points()

    for k, y in enumerate(linkage.dyads):
        key = f"dyads[{k}]"
        if isinstance(y, RRR):
            need(key, y.p, y.q)
            if not min(y.lengths) > 0:
                problems.append((key + ".lengths", "lengths must be > 0"))
            if y.branch not in ("left", "right"):
                problems.append((key + ".branch", "branch must be 'left' or 'right'"))
            new_points(key + ".c", y.c)
        elif isinstance(y, RRP):
            need(key, y.p)
            if not y.length > 0:
                problems.append((key + ".length", "length must be > 0"))
            if y.branch not in ("forward", "backward"):
                problems.append((key + ".branch", "branch must be 'forward' or 'backward'"))
            new_points(key + ".c", y.c, *y.coincident)
            if isinstance(y.guide, LinkGuide):
                link_guide(f"{key}.guide", y.guide)
            else:
                translating.add(y.links[1])
        elif isinstance(y, RPR):
            need(key, y.p, y.q)
            if y.bar not in ("first", "second"):
                problems.append((key + ".bar", "bar must be 'first' or 'second'"))
            new_points(key + ".coincident", *y.coincident)
        elif isinstance(y, PRP):
            for m, g in enumerate(y.guides):
                if isinstance(g, LinkGuide):
                    link_guide(f"{key}.guides[{m}]", g)
            if all(isinstance(g, Guide) for g in y.guides):
                problems.append((key + ".guides", "both guides on the frame: the dyad cannot move"))
            new_points(key + ".c", y.c, *y.coincident)
            translating.update(y.links[m] for m, g in enumerate(y.guides) if isinstance(g, Guide))
        elif isinstance(y, RPP):
            need(key, y.p)
            if abs(math.sin(y.slot_angle - y.guide.angle)) <= PARALLEL_SIN:
                problems.append((key + ".slot_angle", "slot parallel to the guide: C is undefined"))
            new_points(key + ".c", y.c, *y.coincident)
            translating.update(y.links)
        elif isinstance(y, Triad):
            need(key, *y.known_outer)
            if not min(y.ternary + tuple(x for k, x in enumerate(y.lengths) if not y.slides(k))) > 0:
                problems.append((key + ".lengths", "lengths must be > 0"))
            a, b, c = y.ternary
            if not (a < b + c and b < a + c and c < a + b):
                problems.append((key + ".ternary", "the ternary link's sides do not make a triangle"))
            new_points(key + ".inner", *y.inner)
        else:
            problems.append((key, f"unknown dyad {type(y).__name__}"))
            continue
        new_links(key + ".links", *y.links)
        plan.append(y)
        place_points()

    for k, pt in enumerate(linkage.points):
        key = f"points[{k}]"
        if pt.link != frame and pt.link not in links:
            problems.append((key + ".link", f"link {pt.link!r} is not a link of the linkage"))
        elif pt.link != frame and not set(pt.base) <= set(carried[pt.link]):
            problems.append((key + ".base", f"base points must be points of link {pt.link!r}"))
        if len(pt.base) not in (1, 2):
            problems.append((key + ".base", "base must name one or two points"))
        elif len(pt.base) == 1 and pt.link != frame and pt.link not in translating:
            problems.append((key + ".base", "a one-point base needs a translating link"))
    for k, pt in pending:
        problems.append((f"points[{k}].base", f"base points {pt.base} are never all solved"))

    if problems:
        raise SceneError(problems, source="linkage")
    return plan


# --------------------------------------------------------------------------------------------


def _xy(z: _Array) -> _Array:
    """N complex numbers as a read-only (N, 2) float array (a view, no copy)."""
    out = np.ascontiguousarray(z, dtype=complex).view(np.float64).reshape(-1, 2)
    out.flags.writeable = False
    return out


def _frozen(x: _Array) -> _Array:
    x.flags.writeable = False
    return x


def _wrap(theta: _Array) -> _Array:
    """Angle in [0, 2π)."""
    out = np.mod(theta, _TWO_PI)
    out[out >= _TWO_PI] = 0.0  # np.mod(-1e-17, 2π) rounds to 2π
    return cast(np.ndarray, out)


def solve(linkage: Linkage, positions: np.ndarray) -> Kinematics:
    """Exact positions, velocities and accelerations of a class-II linkage at N driver positions.

    Parameters
    ----------
    linkage : Linkage
        The linkage (SI units). Its dyads are solved in order; every dyad's outer joints must be
        points solved before it. An extra point (:class:`LinkPoint`) is solved as soon as its
        link and base points are, so a dyad may hang on a coupler point (a six-bar).
    positions : array_like, shape (N,)
        Driver values: crank angle φ (rad) for a :class:`Crank`; displacement s (m) along the
        guide for a :class:`SliderInput` (``point = guide.through + s·direction``). The driver's
        ω, ε (or v, a along the guide) are the constants stored in the driver.

    Returns
    -------
    Kinematics
        Every named point (frame points, the driver's points, each dyad's points including the
        coincident points of sliding pairs, every :class:`LinkPoint`) and every moving link's
        angle, ω and α, with a validity mask and per-position reasons.

    Raises
    ------
    SceneError
        If the structure is inconsistent (a point used before it is solved, a name or link id
        given twice, an RPP slot parallel to its guide, ...). Positions where the linkage cannot
        be assembled are not errors: they are reported through ``valid`` and ``reason``.
    ValueError
        If ``positions`` is not one-dimensional.

    Notes
    -----
    Each dyad is a vector loop ``Σ l_k·e^{iθ_k} = known``; its two unknowns (two angles, or an
    angle and a sliding distance) follow in closed form. Differentiating the loop with
    ``d(l·e^{iθ})/dt = iω·l·e^{iθ}`` (and, for a sliding length, ``ṙ·e^{iθ}``) gives
    ``x·a + y·b = c`` with the same coefficients ``a, b`` for the velocities and for the
    accelerations; only the right-hand side changes (it gains the centripetal ``ω²·l·e^{iθ}`` and
    Coriolis ``2·ṙ·ω·i·e^{iθ}`` terms). Cramer's rule gives ``x = (c × b)/(a × b)``,
    ``y = (a × c)/(a × b)``. A crank's ε is honoured: the state at φ is that of a crank turning
    at ω with angular acceleration ε at that instant.

    A tangent assembly (a discriminant down to ``-TANGENT_REL``, relative) is assembled, with the
    discriminant clamped to zero; but there ``a × b = 0`` and the rates are unbounded, so the
    position is a dead centre: ``valid`` is False, positions are kept and rates are 0.

    Examples
    --------
    The offset slider-crank (crank 0.1 m at ω = 10 rad/s, coupler 0.3 m, guide 0.03 m above A):

    >>> from graphmech.mechanisms.linkage import Crank, Guide, Linkage, RRP
    >>> sc = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.1, 10.0),
    ...              (RRP("B", "C", ("2", "3"), 0.3, Guide((0.0, 0.03), 0.0)),))
    >>> kin = solve(sc, np.radians([50.0]))
    >>> round(float(np.degrees(kin.angle["2"][0])), 4), round(float(kin.vel["C"][0, 0]), 4)
    (351.063, -0.8671)
    """
    plan = _plan(linkage)
    q = np.atleast_1d(np.asarray(positions, dtype=float))
    if q.ndim != 1:
        raise OutOfDomain(f"positions must be one-dimensional, got shape {q.shape}")
    n = q.shape[0]
    st = _State(n)
    finite = np.isfinite(q)
    if not finite.all():
        st.fail(~finite, "driver position is not finite")
        q = np.where(finite, q, 0.0)

    for name, (x, y) in linkage.frame_points.items():
        st.pts[name] = (np.full(n, complex(x, y)), st.zero, st.zero)
    with np.errstate(all="ignore"):  # positions already marked invalid may divide by zero
        for step in plan:
            if isinstance(step, Crank):
                _crank(st, step, q)
            elif isinstance(step, SliderInput):
                _slider_input(st, step, q)
            elif isinstance(step, RRR):
                _rrr(st, step)
            elif isinstance(step, RRP):
                _rrp(st, step)
            elif isinstance(step, RPR):
                _rpr(st, step)
            elif isinstance(step, RPP):
                _rpp(st, step)
            elif isinstance(step, PRP):
                _prp(st, step)
            elif isinstance(step, Triad):
                _triad(st, step)
            else:
                _link_point(st, step, linkage.frame_link)

    pts, angle, omega, alpha = st.pts, st.angle, st.omega, st.alpha
    if not st.valid.all():  # 0 where assembly failed; rates 0 wherever invalid
        asm, ok = st.assembled, st.valid
        pts = {k: (np.where(asm, z, 0), np.where(ok, v, 0), np.where(ok, a, 0))
               for k, (z, v, a) in pts.items()}
        angle = {k: np.where(asm, t, 0.0) for k, t in angle.items()}
        omega = {k: np.where(ok, w, 0.0) for k, w in omega.items()}
        alpha = {k: np.where(ok, a, 0.0) for k, a in alpha.items()}

    moving = [k for k in linkage.links() if k != linkage.frame_link]
    return Kinematics(
        point={k: _xy(z) for k, (z, _, _) in pts.items()},
        vel={k: _xy(v) for k, (_, v, _) in pts.items()},
        acc={k: _xy(a) for k, (_, _, a) in pts.items()},
        angle={k: _frozen(_wrap(angle[k])) for k in moving},
        omega={k: _frozen(np.array(omega[k], dtype=float)) for k in moving},
        alpha={k: _frozen(np.array(alpha[k], dtype=float)) for k in moving},
        valid=_frozen(st.valid.copy()),
        reason=tuple(st.reason.tolist()),
        assembled=_frozen(st.assembled.copy()),
    )
