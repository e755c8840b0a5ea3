"""The kinematic diagram (机构运动简图) at μl: where every point of the linkage is.

Each dyad's middle joint is found the draftsman's way: as the intersection of two loci
(two circles for RRR, circle and guide for RRP, two lines for RPP and PRP).
"""
from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from graphmech.geometry import kernels as K
from graphmech.mechanisms.linkage import PRP, Crank, LinkGuide, LinkPoint, RPP, RPR, RRP, RRR, SliderInput, Triad
from graphmech.methods.linkage_construction import own

if TYPE_CHECKING:
    from graphmech.geometry.kernels import Components, Ops
    from graphmech.methods.linkage_construction import LinkageConstruction
    from graphmech.mechanisms.linkage import Linkage, Part

PANEL = "mechanism"


def add_frame(b: "LinkageConstruction") -> None:
    frame = b.linkage.frame_points
    driver = b.linkage.driver
    b.origin = next(iter(frame.values())) if frame else getattr(driver, "guide").through
    for name, xy0 in frame.items():
        xy = b.to_drawing(xy0)
        b.mech[name] = b.g.add(name, "point", lambda ops, xy=xy: xy, (), role="given",
                               text=f"frame point {name}", panel=PANEL, label=name, say=("frame", name))


def add(b: "LinkageConstruction", part: Part) -> None:
    build: dict[type, Callable[..., None]] = {Crank: _crank, SliderInput: _slider, RRR: _rrr, RRP: _rrp,
                                              RPR: _rpr, RPP: _rpp, PRP: _prp, LinkPoint: _point, Triad: _triad}
    build[type(part)](b, part)


def _crank(b: "LinkageConstruction", d: Crank) -> None:
    r = d.length / b.mu_l

    def tip(ops: Ops, phi: Any, a: Components) -> Components:
        return (a[0] + r * ops.cos(phi), a[1] + r * ops.sin(phi))

    b.mech[d.tip] = b.g.add(d.tip, "point", tip, (b.param, b.mech[d.pivot]), role="given",
                            text=f"{d.tip} on the crank circle about {d.pivot} at φ", panel=PANEL,
                            label=d.tip, say=("crank", d.pivot, d.tip, d.link))


def _slider(b: "LinkageConstruction", d: SliderInput) -> None:
    mu = b.mu_l
    gx, gy = d.guide.direction
    ox, oy = b.to_drawing(d.guide.through)
    b.slider_dir[d.point] = (gx, gy)
    b.translating.add(d.link)

    def point(ops: Ops, s: Any) -> Components:
        return (ox + s / mu * gx, oy + s / mu * gy)

    b.mech[d.point] = b.g.add(d.point, "point", point, (b.param,), role="given",
                              text=f"{d.point} at s along its guide", panel=PANEL, label=d.point,
                              say=("slider_at", d.point, d.link))


def _rrr(b: "LinkageConstruction", y: RRR) -> None:
    mu = b.mu_l
    r1, r2 = y.lengths[0] / mu, y.lengths[1] / mu
    side = 1.0 if y.branch == "left" else -1.0
    i, j = y.links
    P, C, Q = y.p, y.c, y.q

    def explain(d: Any) -> str:
        s = f"l{i} + l{j} = {(r1 + r2) * mu:.4g} m"
        dd = f"|{P}{Q}| = {d * mu:.4g} m" if not hasattr(d, "shape") else f"|{P}{Q}|"
        if not hasattr(d, "shape") and d < abs(r1 - r2):
            return f"{dd} < |l{i} − l{j}| = {abs(r1 - r2) * mu:.4g} m"
        return f"{dd} > {s}" if not hasattr(d, "shape") else f"{dd} is not between |l{i} − l{j}| and {s}"

    def joint(ops: Ops, p: Components, q: Components) -> Components:
        return K.intersect_circles(ops, p, r1, q, r2, side, explain)

    b.mech[C] = b.g.add(C, "point", joint, (b.mech[P], b.mech[Q]), role="given",
                        text=f"{C} = circle({P}, l{i}) ∩ circle({Q}, l{j}), {y.branch} of {P}→{Q}",
                        panel=PANEL, label=C, say=("circles", C, P, Q, y.branch))


def _guide_line(b: "LinkageConstruction", guide: Any) -> Components:
    gx, gy = guide.direction
    return (*b.to_drawing(guide.through), gx, gy)


def _rrp(b: "LinkageConstruction", y: RRP) -> None:
    mu = b.mu_l
    r = y.length / mu
    side = 1.0 if y.branch == "forward" else -1.0
    P, C = y.p, y.c
    g = y.guide
    if isinstance(g, LinkGuide):  # the slotted link's line through two of its points, where it is now
        _rrp_on_link(b, y, g, r, side)
        return
    line = _guide_line(b, g)
    b.slider_dir[C] = g.direction
    b.translating.add(y.links[1])

    def explain(e: Any) -> str:
        if hasattr(e, "shape"):
            return f"{P} is farther than l{y.links[0]} from the guide"
        return f"{P} is {e * mu:.4g} m from the guide > l{y.links[0]} = {y.length:.4g} m"

    def joint(ops: Ops, p: Components) -> Components:
        return K.intersect_circle_line(ops, p, r, line, side, explain)

    b.mech[C] = b.g.add(C, "point", joint, (b.mech[P],), role="given",
                        text=f"{C} = circle({P}, l{y.links[0]}) ∩ guide, {y.branch}", panel=PANEL,
                        label=C, say=("circle_guide", C, P))


def _rrp_on_link(b: "LinkageConstruction", y: RRP, g: LinkGuide, r: float, side: float) -> None:
    P, C = y.p, y.c

    def explain(e: Any) -> str:
        if hasattr(e, "shape"):
            return f"{P} is farther than l{y.links[0]} from the line {g.through}{g.towards}"
        return f"{P} is {e * b.mu_l:.4g} m from the line {g.through}{g.towards} > l{y.links[0]} = {y.length:.4g} m"

    def joint(ops: Ops, p: Components, u: Components, v: Components) -> Components:
        ux, uy, _ = K.unit(ops, u, v)
        return K.intersect_circle_line(ops, p, r, K.line_fixed(ops, u, ux, uy), side, explain)

    b.mech[C] = b.g.add(C, "point", joint, (b.mech[P], b.mech[g.through], b.mech[g.towards]), role="given",
                        text=f"{C} = circle({P}, l{y.links[0]}) ∩ line {g.through}{g.towards}, {y.branch}",
                        panel=PANEL, label=C, say=("circle_guide", C, P))
    for name in y.coincident:
        b.mech[name] = b.mech[C]


def tangent_name(y: RPR) -> str:
    """The step (and ``b.mech`` key) of an offset guide bar's foot F: where its line touches the
    circle of radius |e| about its pivot (no point name is one)."""
    return own(PANEL, f"F{y.bar_pivot}{y.block_pivot}")


def offset_bar_lines(linkage: Linkage) -> dict[str, tuple[str, str]]:
    """Link → the two ``b.mech`` keys along its own line, F → X, for each offset guide bar and its
    block: their angle is that line's, not the direction of their first two points."""
    return {lk: (tangent_name(y), y.block_pivot) for y in linkage.dyads
            if isinstance(y, RPR) and y.offset != 0.0 for lk in (y.bar_link, y.block_link)}


def bar_direction(b: LinkageConstruction, y: RPR) -> str:
    """The direction of the bar's line: O→X through the bar's pivot O, F→X for an offset bar."""
    from graphmech.methods.elements import direction

    if y.offset == 0.0:
        return direction(b, y.bar_pivot, y.block_pivot)
    a, c = b.mech[tangent_name(y)], b.mech[y.block_pivot]
    name = f"dir:{a}->{c}"  # as elements.direction names it, with words for a failure (F on X: a dead centre)
    if not b.g.has(name):
        X, O = y.block_pivot, y.bar_pivot
        b.g.add(name, "scalar", K.unit, (a, c), role="hidden", panel=PANEL,
                text=f"the offset bar's line F{X} ({X} on the circle of radius |e| about {O}: a dead centre)")
    return name


def _rpr(b: "LinkageConstruction", y: RPR) -> None:
    # The bar's line runs from its pivot through the block's pivot: no new point, but the
    # coincident points X<bar>, X<block> sit where the block's pivot is.
    x = y.block_pivot
    for name in y.coincident:
        b.mech[name] = b.mech[x]
    if y.offset != 0.0:
        _rpr_tangent(b, y)


def _rpr_tangent(b: LinkageConstruction, y: RPR) -> None:
    """An offset guide bar: its line is the tangent from X to the circle of radius |e| about its pivot
    O, found as the book draws it — the circle on OX as diameter cuts that circle at the foot F, on
    the side e names (left of O→X for e > 0)."""
    O, X = y.bar_pivot, y.block_pivot
    r = abs(y.offset) / b.mu_l
    side = 1.0 if y.offset > 0.0 else -1.0

    def explain(d: Any) -> str:
        if hasattr(d, "shape"):
            return f"{X} is within the offset |e| of the bar's pivot {O}"
        return f"|{O}{X}| = {2.0 * d * b.mu_l:.4g} m < the offset |e| = {abs(y.offset):.4g} m"

    def foot(ops: Ops, o: Components, x: Components) -> Components:
        m = ((o[0] + x[0]) / 2.0, (o[1] + x[1]) / 2.0)  # the circle on OX as diameter
        half = ops.hypot(x[0] - o[0], x[1] - o[1]) / 2.0
        return K.intersect_circles(ops, o, r, m, half, side, explain)

    b.mech[tangent_name(y)] = b.g.add(
        tangent_name(y), "point", foot, (b.mech[O], b.mech[X]), role="construction",
        text=f"F = circle({O}, |e|) ∩ circle on {O}{X} as diameter: {X}F is the bar's line, tangent to the "
             f"circle of radius |e| about {O}", panel=PANEL, say=("tangent", O, X))


def _rpp(b: "LinkageConstruction", y: RPP) -> None:
    sx, sy = math.cos(y.slot_angle), math.sin(y.slot_angle)
    line = _guide_line(b, y.guide)
    P, C = y.p, y.c
    b.slider_dir[C] = y.guide.direction
    b.translating.update(y.links)

    def joint(ops: Ops, p: Components) -> Components:
        return K.intersect_lines(ops, K.line_fixed(ops, p, sx, sy), line)

    b.mech[C] = b.g.add(C, "point", joint, (b.mech[P],), role="given",
                        text=f"{C} = slot through {P} ∩ guide", panel=PANEL, label=C,
                        say=("slot_guide", C, P))
    b.mech[y.coincident[0]] = b.mech[P]
    b.mech[y.coincident[1]] = b.mech[P]


def _prp(b: "LinkageConstruction", y: PRP) -> None:
    # C where the two guides' lines meet: a frame guide is fixed, a link's runs through two of its points
    C = y.c
    fixed: list[Components | None] = []
    inputs: list[str] = []
    for k, g in enumerate(y.guides):
        if isinstance(g, LinkGuide):
            fixed.append(None)
            inputs += [b.mech[g.through], b.mech[g.towards]]
        else:
            fixed.append(_guide_line(b, g))
            b.slider_dir[C] = g.direction  # v_C is read along the frame guide, signed
            b.translating.add(y.links[k])

    def joint(ops: Ops, *pts: Components) -> Components:
        given = iter(pts)
        lines = []
        for line in fixed:
            if line is None:
                u, v = next(given), next(given)
                ux, uy, _ = K.unit(ops, u, v)
                line = K.line_fixed(ops, u, ux, uy)
            lines.append(line)
        return K.intersect_lines(ops, lines[0], lines[1])

    words = [f"{g.through}{g.towards}" if isinstance(g, LinkGuide) else "the guide" for g in y.guides]
    b.mech[C] = b.g.add(C, "point", joint, tuple(inputs), role="given",
                        text=f"{C} = {words[0]} ∩ {words[1]}", panel=PANEL, label=C,
                        say=("guides_meet", C))
    for name in y.coincident:
        b.mech[name] = b.mech[C]


def _point(b: "LinkageConstruction", pt: LinkPoint) -> None:
    mu = b.mu_l
    along, left = pt.along / mu, pt.left / mu
    if len(pt.base) == 1:
        def fixed(ops: Ops, u: Components) -> Components:
            return (u[0] + along, u[1] + left)

        b.mech[pt.name] = b.g.add(pt.name, "point", fixed, (b.mech[pt.base[0]],), role="given",
                                  text=f"{pt.name} on link {pt.link}", panel=PANEL, label=pt.name,
                                  say=("on_link", pt.name, pt.link, pt.base[0]))
        return
    U, V = pt.base

    def placed(ops: Ops, u: Components, v: Components) -> Components:
        ux, uy, _ = K.unit(ops, u, v)
        return (u[0] + along * ux - left * uy, u[1] + along * uy + left * ux)

    b.mech[pt.name] = b.g.add(pt.name, "point", placed, (b.mech[U], b.mech[V]), role="given",
                              text=f"{pt.name} on link {pt.link}", panel=PANEL, label=pt.name,
                              say=("on_link", pt.name, pt.link, U, V))


#: Newton iterations at most for a class III group's position (quadratic convergence from a
#: start near the assembly takes 5–8; the rest is for a start further off, steps capped).
NEWTON_STEPS = 60
#: The largest Newton step in either angle, rad: a far start walks instead of jumping branches.
NEWTON_MAX_STEP = 0.5


#: A slider leg's guide on the kinematic diagram: (a point of it, its unit direction), drawing mm.
DrawnGuide = tuple[complex, complex]


def triad_position(ops: Ops, b_: Components | None, f_: Components | None, g_: Components | None, *,
                   lengths: tuple[float, float, float], ternary: tuple[float, float, float], hand: float,
                   start: tuple[Components, Components, Components], name: str,
                   guides: tuple[DrawnGuide | None, DrawnGuide | None, DrawnGuide | None] = (None, None, None)
                   ) -> Components:
    """A class III group's joints (Cx, Cy, Dx, Dy, Ex, Ey) by Newton's method on its two loop equations.

    Unknowns: q of the first leg — θ2 (``C = B + l2·e^{iθ2}``) or, on a slider leg, the pin's
    place s on its guide (``C = Q + s·u``) — and θ3 (of CD); ``D = C + l_CD·e^{iθ3}``, E = C +
    l_CE·e^{i(θ3 ± γ)}; equations ``|D − F|² = l4²``, ``|E − G|² = l5²`` — on a slider leg the
    pin's distance from its guide, ``Im(ū·(X − Q)) = 0``. The start is the stated figure's C, D.
    The condition number reported is that of the Jacobian scaled by the lengths (σmax/σmin),
    infinite where the group locks. A slider leg's outer joint is None (its guide stands in).
    At several positions (the batch path) each starts from the last that converged, the first from
    the start: the group is followed along its branch over a cycle.
    """
    import numpy as np

    l2, l4, l5 = lengths
    a, bb, c = ternary
    cos_g = (a * a + c * c - bb * bb) / (2.0 * a * c)
    rot = complex(cos_g, hand * math.sqrt(max(0.0, 1.0 - cos_g * cos_g)))
    z = [None if p is None else np.asarray(p[0], dtype=float) + 1j * np.asarray(p[1], dtype=float) for p in (b_, f_, g_)]
    like = next(x for x in z if x is not None).real
    c0, d0 = complex(*start[0]), complex(*start[1])
    g0 = guides[0]
    zb = 0.0j if z[0] is None else z[0]  # B (a slider first leg has none: its guide's point stands in)
    if g0 is None:
        q = np.angle(c0 - zb) + 0.0 * like
    else:
        q = ((c0 - g0[0]) * g0[1].conjugate()).real + 0.0 * like
    th3 = np.full_like(q, np.angle(d0 - c0))

    def at(v: Any, sl: slice | None) -> Any:
        """v at the positions ``sl`` (all of them: None)."""
        return v if sl is None or np.ndim(v) == 0 else v[sl]

    def joint_c(q: np.ndarray, sl: slice | None = None) -> tuple[np.ndarray, np.ndarray]:
        """C and ∂C/∂q."""
        if g0 is None:
            r2 = l2 * np.exp(1j * q)
            return at(zb, sl) + r2, 1j * r2
        return g0[0] + q * g0[1], g0[1] + 0.0 * q

    def residual(k: int, x: np.ndarray, dx: tuple[np.ndarray, np.ndarray], length: float, sl: slice | None = None
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Leg k's equation at its joint x, its two derivatives, and the row's unit normal (X − O)/l or
        i·u, by which the condition number's Jacobian is taken."""
        g = guides[k]
        zk = at(z[k], sl)
        if g is None and zk is not None:
            ox = x - zk
            # ∂|X − F|²/∂θ = 2 (X − F)·(i r): the dot product of plane vectors as Re(ū·w)
            return ((ox * ox.conjugate()).real - length * length, 2 * (ox.conjugate() * dx[0]).real,
                    2 * (ox.conjugate() * dx[1]).real, ox / length)
        assert g is not None
        u = g[1]
        return (((x - g[0]) * u.conjugate()).imag, (dx[0] * u.conjugate()).imag,
                (dx[1] * u.conjugate()).imag, 1j * u + 0.0 * x)

    def newton(q: np.ndarray, th3: np.ndarray, sl: slice | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Newton's iterations from (q, θ3) at the positions ``sl``; and whether each converged."""
        for _ in range(NEWTON_STEPS):
            zc, dc = joint_c(q, sl)
            rd = a * np.exp(1j * th3)
            re = c / a * rd * rot
            g1, j11, j12, _ = residual(1, zc + rd, (dc, 1j * rd), l4, sl)
            g2, j21, j22, _ = residual(2, zc + re, (dc, 1j * re), l5, sl)
            det = j11 * j22 - j12 * j21
            det = np.where(det == 0.0, 1e-300, det)
            d2 = np.clip((j22 * g1 - j12 * g2) / det, -NEWTON_MAX_STEP, NEWTON_MAX_STEP)
            d3 = np.clip((j11 * g2 - j21 * g1) / det, -NEWTON_MAX_STEP, NEWTON_MAX_STEP)
            q, th3 = q - d2, th3 - d3
            if np.max(np.abs(d2) + np.abs(d3)) < 1e-15:
                break
        return q, th3, np.abs(d2) + np.abs(d3) < 1e-9

    if ops.batch and np.ndim(q) == 1 and np.size(q) > 1:
        # Several positions (a cycle, in its order): each from the last one that converged, the first
        # from the start — the group is followed along its branch (continuation), as the hand draws it
        q, th3 = np.array(q, dtype=float), np.array(th3, dtype=float)
        from_q, from_t = q[:1].copy(), th3[:1].copy()
        for i in range(q.size):
            qi, ti, ok = newton(from_q.copy(), from_t.copy(), slice(i, i + 1))
            q[i], th3[i] = qi[0], ti[0]
            if ok[0]:
                from_q, from_t = qi, ti
    else:
        q, th3, _ = newton(q, th3)
    zc, dc = joint_c(q)
    rd = a * np.exp(1j * th3)
    re = c / a * rd * rot
    zd, ze = zc + rd, zc + re
    misses = []
    for k, x, length in ((1, zd, l4), (2, ze, l5)):
        g = guides[k]
        misses.append(np.abs(np.abs(x - z[k]) - length) / length if g is None
                      else np.abs(((x - g[0]) * g[1].conjugate()).imag) / a)
    miss = np.maximum(misses[0], misses[1])
    bad = ops.guard(miss > 1e-9, lambda: f"{name}: Newton's method from the start found no assembly "
                    "(out of reach, or the start is too far from it)", assembly=True)
    # The Jacobian scaled by rows (l4, l5; 1 on a slider leg: its row is a unit normal's) and by
    # columns (l2, or 1 for a pin's place on its guide; l_CD for the ternary link's angle, one scale
    # per column, so that scaling keeps a singular matrix singular)
    col2 = l2 if g0 is None else 1.0
    _, _, _, n4 = residual(1, zd, (dc, 1j * rd), l4)
    _, _, _, n5 = residual(2, ze, (dc, 1j * re), l5)
    m11 = (n4.conjugate() * dc).real / col2
    m12 = (n4.conjugate() * 1j * rd).real / a
    m21 = (n5.conjugate() * dc).real / col2
    m22 = (n5.conjugate() * 1j * re).real / a
    fro = m11 * m11 + m12 * m12 + m21 * m21 + m22 * m22
    mdet = np.abs(m11 * m22 - m12 * m21)
    cond = (fro + np.sqrt(np.maximum(fro * fro - 4.0 * mdet * mdet, 0.0))) / np.maximum(2.0 * mdet, 1e-300)
    ops.cond(cond if ops.batch else float(cond))
    out = (zc.real, zc.imag, zd.real, zd.imag, ze.real, ze.imag)
    if ops.batch:
        return tuple(ops.where(bad, 0.0, v) for v in out)
    return tuple(float(v) for v in out)


def _triad(b: "LinkageConstruction", y: Triad) -> None:
    mu = b.mu_l
    C, D, E = y.inner
    start = tuple(b.to_drawing(p) for p in y.start)
    lengths = (y.lengths[0] / mu, y.lengths[1] / mu, y.lengths[2] / mu)
    ternary = (y.ternary[0] / mu, y.ternary[1] / mu, y.ternary[2] / mu)
    guides = tuple(None if g is None else (complex(*b.to_drawing(g.through)), complex(*g.direction)) for g in y.guides)
    pivoted = [k for k in range(3) if not y.slides(k)]
    for k, g in enumerate(y.guides):
        if g is not None:  # a block on a frame guide: v of its pin is read along the guide, signed
            b.slider_dir[y.inner[k]] = g.direction
            b.translating.add(y.links[k])

    def joints(ops: Ops, *given: Components) -> Components:
        outer: list[Components | None] = [None, None, None]
        for k, p in zip(pivoted, given):
            outer[k] = p
        return triad_position(ops, outer[0], outer[1], outer[2], lengths=lengths, ternary=ternary, hand=y.hand,
                              start=start, guides=guides, name=f"class III group {y.name}")  # type: ignore[arg-type]

    group = b.g.add(f"m:({C}{D}{E})", "scalar", joints, tuple(b.mech[y.outer[k]] for k in pivoted), role="hidden",
                    text=f"{C}, {D}, {E}: the class III group's loops solved by Newton's method from the start",
                    panel=PANEL, say=("triad", C, D, E))
    for k, (P, Q) in enumerate(zip(y.inner, y.outer)):
        on = y.slides(k)
        b.mech[P] = b.g.add(P, "point", lambda ops, t, k=k: (t[2 * k], t[2 * k + 1]), (group,), role="given",
                            text=f"{P} of the class III group ({'sliding on its guide' if on else f'joined to {Q}'})",
                            panel=PANEL, label=P, say=("triad_slider", P) if on else ("triad_joint", P, Q))
