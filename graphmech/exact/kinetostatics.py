"""Exact kinetostatics by the matrix method: every joint reaction unknown at once, A·x = b.

This is the independent check of the force polygons (:mod:`graphmech.methods.kinetostatics`):
it takes the motion from the closed-form kinematics (:mod:`graphmech.exact.linkage`), writes the
three equilibrium equations of every moving link (ΣF_x = 0, ΣF_y = 0, ΣM = 0 about one of the
link's points, inertia loads included by d'Alembert) and solves them all together — no groups,
no order, no polygons. With friction the equations are no longer linear (a friction couple is
ρ·|R|, a slider's friction force f·|N|); they are solved by scipy's ``root`` (Powell's hybrid
method) from the frictionless solution, not by successive approximation.

Unknowns, in order: for every revolute (a, b) the two components of R_ab (the force of a on b;
−R_ab acts on a); for every sliding pair its normal reaction N (along the guide's normal, the
guide turned +90°) and the reaction's moment M about the slider's point (−N, −M on the guide's
link when the guide moves); last the balancing moment M_b on the crank.

Nothing here comes from ``graphmech.methods`` or ``graphmech.construction``.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import cast

import numpy as np

from graphmech.errors import NotApplicable, UnknownName
from graphmech.exact.linkage import Kinematics, solve as solve_kinematics
from graphmech.mechanisms.forces import ForceModel
from graphmech.roots import newton
from graphmech.mechanisms.linkage import PRP, RPP, RPR, RRP, RRR, Crank, Guide, Linkage, LinkGuide, SliderInput, Triad

__all__ = ["ExactForces", "solve_forces", "pairs"]


@dataclass(frozen=True)
class ExactForces:
    """The exact reactions at N positions.

    Attributes
    ----------
    reactions : dict of (str, str) to ndarray, shape (N, 2)
        (i, j) → R_ij, N (both orders present, R_ji = −R_ij).
    guide_moments : dict of str to ndarray, shape (N,)
        Slider link → moment of the guide's reaction about the slider's point, N·m.
    balancing_moment : ndarray, shape (N,)
        M_b on the crank, N·m (0 with a slider driver).
    inertia_force : dict of str to ndarray, shape (N, 2)
        Link → F_i = −m·a_S, N.
    inertia_moment : dict of str to ndarray, shape (N,)
        Link → M_i = −J_S·α, N·m.
    condition : ndarray, shape (N,)
        Condition number of the equilibrium matrix (large: near a toggle, reactions unbounded).
    valid : ndarray of bool
        Where the kinematics and the equations could be solved.
    iterations : ndarray of int
        Function evaluations of the nonlinear solver per position (0 without friction).
    balancing_force : ndarray or None
        A driving slider's balancing force along its guide, N (None for a crank; then
        ``balancing_moment`` is M_b, and 0 for a slider).
    """

    reactions: dict[tuple[str, str], np.ndarray]
    guide_moments: dict[str, np.ndarray]
    balancing_moment: np.ndarray
    inertia_force: dict[str, np.ndarray]
    inertia_moment: dict[str, np.ndarray]
    condition: np.ndarray
    valid: np.ndarray
    iterations: np.ndarray
    balancing_force: np.ndarray | None = None


def pairs(linkage: Linkage) -> tuple[list[tuple[str, str, str]], list[tuple[str, str, str, str]]]:
    """The revolutes ``(a, b, point)`` and the sliding pairs ``(a, b, point, guide)``: link b slides
    on link a at ``point``; ``guide`` is ``"frame"`` (a's guide of fixed direction, a the frame) or
    ``"slot"`` (an RPP block b in the straight slot of a), ``"link"`` (a's guide line through two
    of its points, an RRP or PRP slider on a moving link), or the name of the bar's pivot (the
    guide runs from it through ``point``)."""
    frame = linkage.frame_link
    on: dict[str, str] = {name: frame for name in linkage.frame_points}
    revolutes: list[tuple[str, str, str]] = []
    slides: list[tuple[str, str, str, str]] = []
    d = linkage.driver
    if isinstance(d, Crank):
        revolutes.append((frame, d.link, d.pivot))
        on.setdefault(d.tip, d.link)
    else:  # a driving slider on its frame guide
        slides.append((frame, d.link, d.point, "frame"))
        on.setdefault(d.point, d.link)
    extra = {pt.name: pt.link for pt in linkage.points}
    for y in linkage.dyads:
        if isinstance(y, PRP):  # two blocks pinned at C, each sliding on its guide (the frame's or a link's)
            i, j = y.links
            revolutes.append((i, j, y.c))
            slides += [(_guide_link(g, frame), b, y.c, "frame" if isinstance(g, Guide) else "link")
                       for b, g in zip(y.links, y.guides)]
            on.setdefault(y.c, i)
            continue
        if isinstance(y, Triad):  # three binary links on known points, each pinned to the ternary link
            for k in range(3):
                if y.outer[k] not in on and y.outer[k] in extra:
                    on[y.outer[k]] = extra[y.outer[k]]
                revolutes += [(on[y.outer[k]], y.links[k], y.outer[k]), (y.links[k], y.links[3], y.inner[k])]
                on.setdefault(y.inner[k], y.links[3])
            continue
        for name in (y.p, getattr(y, "q", y.p)):
            if name not in on and name in extra:
                on[name] = extra[name]
        if isinstance(y, RRR):
            revolutes += [(on[y.p], y.links[0], y.p), (y.links[0], y.links[1], y.c), (on[y.q], y.links[1], y.q)]
            on.setdefault(y.c, y.links[0])
        elif isinstance(y, RRP):
            revolutes += [(on[y.p], y.links[0], y.p), (y.links[0], y.links[1], y.c)]
            slides.append((_guide_link(y.guide, frame), y.links[1], y.c, "frame" if isinstance(y.guide, Guide) else "link"))
            on.setdefault(y.c, y.links[0])
        elif isinstance(y, RPR):
            revolutes += [(on[y.bar_pivot], y.bar_link, y.bar_pivot), (on[y.block_pivot], y.block_link, y.block_pivot)]
            slides.append((y.bar_link, y.block_link, y.block_pivot, y.bar_pivot))
        elif isinstance(y, RPP):
            revolutes.append((on[y.p], y.links[0], y.p))
            slides += [(y.links[1], y.links[0], y.p, "slot"), (frame, y.links[1], y.c, "frame")]
            on.setdefault(y.c, y.links[1])
        else:
            raise NotApplicable(f"the matrix method here takes RRR, RRP, RPR, RPP, PRP and RRR-III groups, not {y.kind}")
    return revolutes, slides


def _guide_link(g: Guide | LinkGuide, frame: str) -> str:
    return frame if isinstance(g, Guide) else g.link


def _guide_of(linkage: Linkage, b: str) -> Guide | LinkGuide:
    """The guide the slider b of an RRP or PRP group slides on."""
    for y in linkage.dyads:
        if isinstance(y, RRP) and y.links[1] == b:
            return y.guide
        if isinstance(y, PRP) and b in y.links:
            return y.guides[y.links.index(b)]
    raise UnknownName(f"link {b} slides on the guide of no RRP or PRP group")


def _moving_links(linkage: Linkage) -> list[str]:
    return [k for k in linkage.links() if k != linkage.frame_link]


def solve_forces(linkage: Linkage, model: ForceModel, positions: np.ndarray,
                 kin: Kinematics | None = None) -> ExactForces:
    """Solve the equilibrium of every moving link at the given crank angles (rad).

    Examples
    --------
    A crank alone, its weight 10 N at 0.1 m from the pivot, horizontal: M_b = 1 N·m.

    >>> from graphmech.mechanisms.linkage import Crank, Linkage, LinkPoint
    >>> from graphmech.mechanisms.forces import ForceModel, LinkMass
    >>> crank = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.2, 0.0), (),
    ...                 (LinkPoint("S", "1", ("A", "B"), 0.1, 0.0),), "0")
    >>> model = ForceModel(masses=(LinkMass("1", "S", 1.0),), gravity=10.0)
    >>> ex = solve_forces(crank, model, np.array([0.0]))
    >>> round(float(ex.balancing_moment[0]), 12), ex.reactions[("0", "1")][0].tolist()
    (1.0, [0.0, 10.0])
    """
    positions = np.asarray(positions, dtype=float)
    if kin is None:
        kin = solve_kinematics(linkage, positions)
    n = positions.shape[0]
    revolutes, sliders = pairs(linkage)
    links = _moving_links(linkage)
    row = {k: 3 * i for i, k in enumerate(links)}
    pts = linkage.links()
    ref = {k: kin.point[pts[k][0]] for k in links}  # moments of link k about its first point
    m = 2 * len(revolutes) + 2 * len(sliders) + 1
    if m != 3 * len(links):
        raise NotApplicable(f"{m} unknowns for {3 * len(links)} equations: not a linkage of Assur groups")
    A = np.zeros((n, m, m))
    rhs = np.zeros((n, m))

    def cross_col(r: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Moment coefficients of (F_x, F_y) applied at arm r: r_x·F_y − r_y·F_x."""
        return -r[:, 1], r[:, 0]

    for u, (a, b, p) in enumerate(revolutes):
        for link, sign in ((b, 1.0), (a, -1.0)):
            if link not in row:
                continue
            r0 = row[link]
            A[:, r0, 2 * u] += sign
            A[:, r0 + 1, 2 * u + 1] += sign
            cx, cy = cross_col(kin.point[p] - ref[link])
            A[:, r0 + 2, 2 * u] += sign * cx
            A[:, r0 + 2, 2 * u + 1] += sign * cy
    base = 2 * len(revolutes)
    # A sliding pair: the force of a on b is N·n at the point (n ⟂ the guide) plus a couple M.
    tangents = [_guide_tangent(linkage, kin, slide) for slide in sliders]
    t: np.ndarray | tuple[float, float]  # a slide's tangents, then the driving slider's guide
    for s, (a, b, p, _) in enumerate(sliders):
        t = tangents[s]
        nrm = np.stack([-t[:, 1], t[:, 0]], axis=1)
        for link, sign in ((b, 1.0), (a, -1.0)):
            if link not in row:
                continue
            r0 = row[link]
            A[:, r0, base + 2 * s] += sign * nrm[:, 0]
            A[:, r0 + 1, base + 2 * s] += sign * nrm[:, 1]
            cx, cy = cross_col(kin.point[p] - ref[link])
            A[:, r0 + 2, base + 2 * s] += sign * (cx * nrm[:, 0] + cy * nrm[:, 1])
            A[:, r0 + 2, base + 2 * s + 1] += sign
    d = linkage.driver
    if isinstance(d, Crank):  # the balancing moment on the crank
        A[:, row[d.link] + 2, m - 1] = 1.0
    else:  # the balancing force along the driving slider's guide, through its point
        t = (math.cos(d.guide.angle), math.sin(d.guide.angle))
        r0 = row[d.link]
        cx, cy = cross_col(kin.point[d.point] - ref[d.link])
        A[:, r0, m - 1], A[:, r0 + 1, m - 1] = t
        A[:, r0 + 2, m - 1] = cx * t[0] + cy * t[1]

    # Known loads: weights, d'Alembert's inertia loads, external forces and moments.
    f_in: dict[str, np.ndarray] = {}
    m_in: dict[str, np.ndarray] = {}

    def load(link: str, force: np.ndarray, at: np.ndarray) -> None:
        if link not in row:
            return
        r0 = row[link]
        rhs[:, r0] -= force[:, 0]
        rhs[:, r0 + 1] -= force[:, 1]
        arm = at - ref[link]
        rhs[:, r0 + 2] -= arm[:, 0] * force[:, 1] - arm[:, 1] * force[:, 0]

    for lm in model.masses:
        if lm.link not in row:
            continue
        at = kin.point[lm.point]
        f = -lm.mass * kin.acc[lm.point]
        f_in[lm.link] = f
        m_in[lm.link] = -lm.inertia * kin.alpha.get(lm.link, np.zeros(n))
        load(lm.link, f, at)
        load(lm.link, np.stack([np.zeros(n), np.full(n, -lm.mass * model.gravity)], axis=1), at)
        rhs[:, row[lm.link] + 2] -= m_in[lm.link]
    for pf in model.forces:
        vec = np.tile([pf.magnitude * math.cos(pf.angle), pf.magnitude * math.sin(pf.angle)], (n, 1))
        if pf.resistance:
            power = np.einsum("ij,ij->i", vec, kin.vel[pf.point])
            vec = np.where((power < 0)[:, None], vec, 0.0)
        load(pf.link, vec, kin.point[pf.point])
    for c in model.couples:
        if c.link in row:
            rhs[:, row[c.link] + 2] -= c.moment

    valid = np.asarray(kin.valid, bool).copy()
    with np.errstate(all="ignore"):
        condition = np.linalg.cond(A)
    valid &= np.isfinite(condition) & (condition < 1e15)
    x = np.zeros((n, m))
    if np.any(valid):
        x[valid] = np.linalg.solve(A[valid], rhs[valid][..., None])[..., 0]
    iterations = np.zeros(n, dtype=int)
    if model.has_friction:
        x, iterations, ok = _with_friction(linkage, model, kin, A, rhs, x, valid, revolutes, sliders, tangents)
        valid &= ok

    reactions: dict[tuple[str, str], np.ndarray] = {}
    for u, (a, b, _) in enumerate(revolutes):
        r = x[:, 2 * u: 2 * u + 2]
        reactions[(a, b)], reactions[(b, a)] = r, -r
    guide_moments: dict[str, np.ndarray] = {}
    fric = {fr.link: fr.f for fr in model.sliding_friction}
    for s, (a, b, p, _) in enumerate(sliders):
        nrm_mag = x[:, base + 2 * s]
        t = tangents[s]
        v = np.einsum("ij,ij->i", _sliding_velocity(linkage, kin, sliders[s]), t)
        tang = -fric.get(b, 0.0) * np.abs(nrm_mag) * _sense(v, _speed_scale(kin))
        r = nrm_mag[:, None] * np.stack([-t[:, 1], t[:, 0]], axis=1) + tang[:, None] * t
        reactions[(a, b)], reactions[(b, a)] = r, -r
        guide_moments[b] = x[:, base + 2 * s + 1]
    if isinstance(d, Crank):
        return ExactForces(reactions, guide_moments, x[:, m - 1], f_in, m_in, condition, valid, iterations)
    return ExactForces(reactions, guide_moments, np.zeros(n), f_in, m_in, condition, valid, iterations, x[:, m - 1])


#: Relative rotation or sliding below this fraction of the largest rate in the mechanism is none:
#: the friction's sense is then undefined, and the friction force or couple is taken as zero.
_STILL = 1e-9


def _sense(x: np.ndarray | float, scale: np.ndarray | float) -> np.ndarray:
    return np.where(np.abs(x) > _STILL * np.asarray(scale), np.sign(x), 0.0)


def _speed_scale(kin: Kinematics) -> np.ndarray:
    return cast(np.ndarray, np.max(np.stack([np.hypot(v[:, 0], v[:, 1]) for v in kin.vel.values()]), axis=0))


def _guide_tangent(linkage: Linkage, kin: Kinematics, slide: tuple[str, str, str, str]) -> np.ndarray:
    """Unit direction of a sliding pair's guide at every position, shape (N, 2)."""
    a, b, p, guide = slide
    n = kin.valid.shape[0]
    if guide in ("frame", "slot"):
        d = linkage.driver
        if guide == "slot":
            angle = next(y.slot_angle for y in linkage.dyads if isinstance(y, RPP) and y.links[0] == b)
        elif isinstance(d, SliderInput) and d.link == b:
            angle = d.guide.angle
        elif any(isinstance(y, RPP) and y.links[1] == b for y in linkage.dyads):
            angle = next(y.guide.angle for y in linkage.dyads if isinstance(y, RPP) and y.links[1] == b)
        else:
            angle = cast(Guide, _guide_of(linkage, b)).angle
        return np.tile([math.cos(angle), math.sin(angle)], (n, 1))
    if guide == "link":
        g = cast(LinkGuide, _guide_of(linkage, b))
        d = kin.point[g.towards] - kin.point[g.through]
    elif any(isinstance(y, RPR) and y.offset != 0.0 and y.bar_link == a and y.block_pivot == p for y in linkage.dyads):
        # an offset guide bar's line misses its pivot: its direction is the bar's angle, not pivot → block
        return np.stack([np.cos(kin.angle[a]), np.sin(kin.angle[a])], axis=1)
    else:
        d = kin.point[p] - kin.point[guide]
    length = np.hypot(d[:, 0], d[:, 1])
    return cast(np.ndarray, d / np.where(length > 0, length, 1.0)[:, None])


def _sliding_velocity(linkage: Linkage, kin: Kinematics, slide: tuple[str, str, str, str]) -> np.ndarray:
    """Velocity of b relative to a at the pair's point, shape (N, 2)."""
    a, b, p, guide = slide
    if guide == "frame":
        return kin.vel[p]
    return cast(np.ndarray, kin.vel[p + b] - kin.vel[p + a])  # the coincident points of b and a (block, bar or slot)


def _with_friction(linkage: Linkage, model: ForceModel, kin: Kinematics, A: np.ndarray, rhs: np.ndarray,
                   x0: np.ndarray, valid: np.ndarray, revolutes: list[tuple[str, str, str]],
                   sliders: list[tuple[str, str, str, str]], tangents: list[np.ndarray]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Solve A·x + g(x) = b, g the friction couples and forces, position by position: Newton's
    method from the frictionless solution, with g's exact Jacobian (g is smooth but where a
    reaction vanishes; scipy's ``root`` costs a third of a second to import, so it is the
    fallback, at a position where Newton's method does not reach the root)."""
    links = _moving_links(linkage)
    row = {k: 3 * i for i, k in enumerate(links)}
    pts = linkage.links()
    rho = {fr.point: fr.rho for fr in model.revolute_friction}
    fric = {fr.link: fr.f for fr in model.sliding_friction}
    base = 2 * len(revolutes)
    n = x0.shape[0]
    x = x0.copy()
    evaluations = np.zeros(n, dtype=int)
    ok = np.ones(n, dtype=bool)
    zero = np.zeros(n)
    rel_v = [np.einsum("ij,ij->i", _sliding_velocity(linkage, kin, sl), tangents[s]) for s, sl in enumerate(sliders)]
    w_scale = np.max(np.abs(np.stack(list(kin.omega.values()) or [zero])), axis=0)
    v_scale = _speed_scale(kin)
    for i in np.flatnonzero(valid):
        # Per position: which way each joint turns relatively, and the geometry of the slides.
        rel = [float(_sense(kin.omega.get(b, zero)[i] - kin.omega.get(a, zero)[i], w_scale[i]))
               for a, b, _ in revolutes]
        slide: list[tuple[list[tuple[int, float, np.ndarray]], np.ndarray, float, float]] = []
        for s, (a, b, p, _) in enumerate(sliders):
            t = tangents[s][i]
            arms = [(row[k], sign, kin.point[p][i] - kin.point[pts[k][0]][i]) for k, sign in ((b, 1.0), (a, -1.0))
                    if k in row]
            slide.append((arms, t, float(_sense(rel_v[s][i], v_scale[i])), fric.get(b, 0.0)))

        def residual(z: np.ndarray, i: np.intp = i, rel: list[float] = rel,
                     slide: list[tuple[list[tuple[int, float, np.ndarray]], np.ndarray, float, float]] = slide) -> np.ndarray:
            res = A[i] @ z - rhs[i]
            for u, (a, b, p) in enumerate(revolutes):
                r = rho.get(p, 0.0)
                if r == 0.0 or rel[u] == 0.0:
                    continue
                m_f = -r * math.hypot(z[2 * u], z[2 * u + 1]) * rel[u]  # on b; −m_f on a
                if b in row:
                    res[row[b] + 2] += m_f
                if a in row:
                    res[row[a] + 2] -= m_f
            for s, (arms, t, sv, f) in enumerate(slide):
                if f == 0.0 or sv == 0.0:
                    continue
                tang = -f * abs(z[base + 2 * s]) * sv  # on b along the guide; −tang on a
                for r0, sign, arm in arms:
                    res[r0] += sign * tang * t[0]
                    res[r0 + 1] += sign * tang * t[1]
                    res[r0 + 2] += sign * tang * (arm[0] * t[1] - arm[1] * t[0])
            return cast(np.ndarray, res)

        def jacobian(z: np.ndarray, i: np.intp = i, rel: list[float] = rel,
                     slide: list[tuple[list[tuple[int, float, np.ndarray]], np.ndarray, float, float]] = slide
                     ) -> np.ndarray:
            jac = A[i].copy()
            for u, (a, b, p) in enumerate(revolutes):
                r = rho.get(p, 0.0)
                size = math.hypot(z[2 * u], z[2 * u + 1])
                if r == 0.0 or rel[u] == 0.0 or size == 0.0:
                    continue
                dm = -r * rel[u] / size * np.array([z[2 * u], z[2 * u + 1]])  # ∂m_f/∂(x, y) of the reaction
                if b in row:
                    jac[row[b] + 2, 2 * u: 2 * u + 2] += dm
                if a in row:
                    jac[row[a] + 2, 2 * u: 2 * u + 2] -= dm
            for s, (arms, t, sv, f) in enumerate(slide):
                k = base + 2 * s
                if f == 0.0 or sv == 0.0 or z[k] == 0.0:
                    continue
                dt = -f * math.copysign(1.0, z[k]) * sv  # ∂tang/∂N
                for r0, sign, arm in arms:
                    jac[r0, k] += sign * dt * t[0]
                    jac[r0 + 1, k] += sign * dt * t[1]
                    jac[r0 + 2, k] += sign * dt * (arm[0] * t[1] - arm[1] * t[0])
            return cast(np.ndarray, jac)

        def solved(z: np.ndarray, residual: Callable[[np.ndarray], np.ndarray] = residual) -> bool:
            return float(np.max(np.abs(residual(z)))) <= 1e-9 * max(1.0, float(np.max(np.abs(z))))

        z, calls = newton(residual, jacobian, x0[i])
        if not solved(z):
            # Newton's method cycled where a reaction changes sign: Powell's hybrid method, which
            # keeps to a trust region, from the frictionless solution (scipy, loaded only here)
            from scipy.optimize import root

            sol = root(residual, x0[i], method="hybr", options={"xtol": 1e-14, "maxfev": 2000})
            z, calls = sol.x, calls + sol.nfev
            ok[i] = solved(z)
        x[i] = z
        evaluations[i] = calls
    return x, evaluations, ok
