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


def triad_position(ops: Ops, b_: Components, f_: Components, g_: Components, *, lengths: tuple[float, float, float],
                   ternary: tuple[float, float, float], hand: float, start: tuple[Components, Components, Components],
                   name: str) -> Components:
    """A class III group's joints (Cx, Cy, Dx, Dy, Ex, Ey) by Newton's method on its two loop equations.

    Unknowns: θ2 (of BC) and θ3 (of CD); ``C = B + l2·e^{iθ2}``, ``D = C + l_CD·e^{iθ3}``, E = C +
    l_CE·e^{i(θ3 ± γ)}; equations ``|D − F|² = l4²``, ``|E − G|² = l5²``. The start is the stated
    figure's C, D (θ2 from B to the start's C). The condition number reported is that of the
    Jacobian scaled by the lengths (σmax/σmin), infinite where the group locks.
    """
    import numpy as np

    l2, l4, l5 = lengths
    a, bb, c = ternary
    cos_g = (a * a + c * c - bb * bb) / (2.0 * a * c)
    rot = complex(cos_g, hand * math.sqrt(max(0.0, 1.0 - cos_g * cos_g)))
    zb = np.asarray(b_[0], dtype=float) + 1j * np.asarray(b_[1], dtype=float)
    zf = np.asarray(f_[0], dtype=float) + 1j * np.asarray(f_[1], dtype=float)
    zg = np.asarray(g_[0], dtype=float) + 1j * np.asarray(g_[1], dtype=float)
    c0, d0 = complex(*start[0]), complex(*start[1])
    th2 = np.angle(c0 - zb) + 0.0 * zf.real
    th3 = np.full_like(th2, np.angle(d0 - c0))
    for _ in range(NEWTON_STEPS):
        r2 = l2 * np.exp(1j * th2)
        rd = a * np.exp(1j * th3)
        re = c / a * rd * rot
        df, eg = zb + r2 + rd - zf, zb + r2 + re - zg
        g1 = (df * df.conjugate()).real - l4 * l4
        g2 = (eg * eg.conjugate()).real - l5 * l5
        # ∂|X − F|²/∂θ = 2 (X − F)·(i r): the dot product of plane vectors as Re(ū·w)
        j11, j12 = 2 * (df.conjugate() * 1j * r2).real, 2 * (df.conjugate() * 1j * rd).real
        j21, j22 = 2 * (eg.conjugate() * 1j * r2).real, 2 * (eg.conjugate() * 1j * re).real
        det = j11 * j22 - j12 * j21
        det = np.where(det == 0.0, 1e-300, det)
        d2 = np.clip((j22 * g1 - j12 * g2) / det, -NEWTON_MAX_STEP, NEWTON_MAX_STEP)
        d3 = np.clip((j11 * g2 - j21 * g1) / det, -NEWTON_MAX_STEP, NEWTON_MAX_STEP)
        th2, th3 = th2 - d2, th3 - d3
        if np.max(np.abs(d2) + np.abs(d3)) < 1e-15:
            break
    r2, rd = l2 * np.exp(1j * th2), a * np.exp(1j * th3)
    re = c / a * rd * rot
    zc = zb + r2
    zd, ze = zc + rd, zc + re
    miss = np.maximum(np.abs(np.abs(zd - zf) - l4) / l4, np.abs(np.abs(ze - zg) - l5) / l5)
    bad = ops.guard(miss > 1e-9, lambda: f"{name}: Newton's method from the start found no assembly "
                    "(out of reach, or the start is too far from it)", assembly=True)
    # The Jacobian scaled by rows (l4, l5) and by columns (l2; l_CD for the ternary link's angle,
    # one scale per column, so that scaling keeps a singular matrix singular)
    m11 = ((zd - zf).conjugate() * 1j * r2).real / (l4 * l2)
    m12 = ((zd - zf).conjugate() * 1j * rd).real / (l4 * a)
    m21 = ((ze - zg).conjugate() * 1j * r2).real / (l5 * l2)
    m22 = ((ze - zg).conjugate() * 1j * re).real / (l5 * a)
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
    (B, F, G), (C, D, E) = y.outer, y.inner
    start = tuple(b.to_drawing(p) for p in y.start)
    lengths = (y.lengths[0] / mu, y.lengths[1] / mu, y.lengths[2] / mu)
    ternary = (y.ternary[0] / mu, y.ternary[1] / mu, y.ternary[2] / mu)

    def joints(ops: Ops, pb: Components, pf: Components, pg: Components) -> Components:
        return triad_position(ops, pb, pf, pg, lengths=lengths, ternary=ternary, hand=y.hand,
                              start=start, name=f"class III group {y.name}")  # type: ignore[arg-type]

    group = b.g.add(f"m:({C}{D}{E})", "scalar", joints, (b.mech[B], b.mech[F], b.mech[G]), role="hidden",
                    text=f"{C}, {D}, {E}: the class III group's loops solved by Newton's method from the start",
                    panel=PANEL, say=("triad", C, D, E))
    for k, (P, Q) in enumerate(zip(y.inner, y.outer)):
        b.mech[P] = b.g.add(P, "point", lambda ops, t, k=k: (t[2 * k], t[2 * k + 1]), (group,), role="given",
                            text=f"{P} of the class III group (joined to {Q})", panel=PANEL, label=P,
                            say=("triad_joint", P, Q))
