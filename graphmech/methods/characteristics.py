"""Linkage characteristics drawn as the textbook draws them: Grashof's rule, the extreme
(dead-centre) positions, θ, ψ or the stroke H, K and the smallest transmission angle.

The basic loop of a linkage — its driving crank and the first dyad — is one of

four-bar (RRR dyad hinged to a frame point D)
    Grashof's rule: with s the shortest link and l the longest, s + l < p + q lets the shortest
    link turn fully (it is the crank: crank-rocker; it is the frame: double crank; it is the
    coupler: double rocker); s + l = p + q is the change point; s + l > p + q, double rocker.
    The extreme positions: "with centre A draw arcs of radius AC₁ = BC − AB and AC₂ = BC + AB;
    they cut the rocker's circle about D at C₁ and C₂". θ = ∠C₁AC₂, ψ = ∠C₁DC₂. The smallest
    transmission angle γ = ∠BCD (or 180° − ∠BCD) is where the crank lies along the frame line,
    either way: both positions are drawn and γ measured on each.
slider-crank (RRP dyad): AC₁ = BC − AB and AC₂ = BC + AB cut the guide at C₁, C₂; the stroke
    H = C₁C₂; γ_min where the crank stands at right angles to the guide, away from it.
guide bar (RPR dyad, the bar pivoted at a frame point C, the block on the crank pin B): the
    extremes are where the bar is tangent to the crank circle — the crank circle cut by the
    circle on AC as diameter (Thales) — ψ = θ = ∠B₁CB₂; the block drives the bar at 90°.

Every point is constructed on the drawing (millimetres at μl) with the construction kernels and
the angles are measured on it, so the values carry the drawing's own arithmetic; the exact
closed forms are :mod:`graphmech.exact.characteristics` (not used here).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable, cast
from graphmech.errors import NotApplicable
from graphmech.geometry.kernels import ScalarOps, intersect_circle_line, intersect_circles
from graphmech.mechanisms.linkage import RPR, RRP, RRR, Crank, Guide, Linkage

__all__ = ["Loop", "DrawnCharacteristics", "basic_loop", "draw_characteristics", "grashof_class",
           "grashof_ranges", "LOOP_KINDS"]

#: The loops whose characteristics are drawn.
LOOP_KINDS = ("fourbar", "slider_crank", "guide_bar")

_XY = tuple[float, float]


@dataclass(frozen=True)
class Loop:
    """The basic loop: the crank and the first dyad, with the names and lengths the book uses.

    ``names`` maps the roles to the scene's point names: ``A`` (crank pivot), ``B`` (crank
    tip), ``C`` (the output joint: rocker pin, slider, or the bar's frame pivot), ``D`` (a
    four-bar's rocker pivot). Lengths in m; ``links`` the link ids (crank, coupler or block,
    rocker or slider or bar).
    """

    kind: str
    names: dict[str, str] = field(hash=False)
    links: tuple[str, str, str]
    a: float  # crank
    b: float  # coupler (four-bar, slider-crank), a guide bar's offset e (signed; 0: centred)
    c: float  # rocker (four-bar) or 0
    sense: float  # +1 CCW, −1 CW


def basic_loop(linkage: Linkage) -> Loop:
    """The basic loop of ``linkage``, or ValueError saying why it has none we can characterise."""
    d = linkage.driver
    if not isinstance(d, Crank):
        raise NotApplicable("the characteristics are those of a crank-driven loop; this linkage is driven by a slider")
    if not linkage.dyads:
        raise NotApplicable("the linkage has no dyad after its crank: nothing swings or slides")
    y = linkage.dyads[0]
    sense = -1.0 if d.omega < 0 else 1.0
    names = {"A": d.pivot, "B": d.tip}
    if isinstance(y, RRR) and y.p == d.tip and y.q in linkage.frame_points:
        names.update(C=y.c, D=y.q)
        return Loop("fourbar", names, (d.link, *y.links), d.length, y.lengths[0], y.lengths[1], sense)
    if isinstance(y, RRR) and y.q == d.tip and y.p in linkage.frame_points:
        names.update(C=y.c, D=y.p)
        return Loop("fourbar", names, (d.link, y.links[1], y.links[0]), d.length, y.lengths[1], y.lengths[0], sense)
    if isinstance(y, RRP) and isinstance(y.guide, Guide) and y.p == d.tip:
        names.update(C=y.c)
        return Loop("slider_crank", names, (d.link, *y.links), d.length, y.length, 0.0, sense)
    if isinstance(y, RPR) and y.bar == "second" and y.p == d.tip and y.q in linkage.frame_points:
        names.update(C=y.q)
        return Loop("guide_bar", names, (d.link, y.links[0], y.links[1]), d.length, y.offset, 0.0, sense)
    raise NotApplicable("the first dyad does not close a four-bar (RRR to a frame point), a slider-crank (RRP on the "
                     "crank pin) or a guide bar (RPR with the bar pivoted on the frame, bar = \"second\") with "
                     "the crank")


def grashof_class(a: float, b: float, c: float, d: float) -> str:
    """Grashof's rule for crank a, coupler b, rocker c, frame d.

    >>> grashof_class(28, 52, 50, 72), grashof_class(50, 30, 50, 30), grashof_class(50, 50, 35, 30)
    ('crank_rocker_AB', 'change_point', 'double_crank')
    """
    links = {"AB": a, "BC": b, "CD": c, "AD": d}
    s, l = min(links.values()), max(links.values())
    rest = a + b + c + d - s - l
    tol = 1e-12 * (a + b + c + d)
    if l > a + b + c + d - l + tol:
        return "none"
    if abs(s + l - rest) <= tol:
        return "change_point"
    if s + l > rest:
        return "double_rocker"
    shortest = min(links, key=lambda k: (links[k], k))
    return {"AB": "crank_rocker_AB", "CD": "crank_rocker_CD", "AD": "double_crank", "BC": "double_rocker"}[shortest]


def grashof_ranges(b: float, c: float, d: float) -> list[tuple[str, float, float]]:
    """The classes of the four-bar as the crank length a runs from 0 to b + c + d, by Grashof's rule.

    Where a is the shortest link the rule turns on a + l = p + q, where it is the longest on
    a + s = p + q, in between on s + l = a + (the other): those values of a are the
    boundaries.

    >>> [(k, lo, hi) for k, lo, hi in grashof_ranges(50, 35, 30)]
    [('crank_rocker_AB', 0.0, 15.0), ('double_rocker', 15.0, 45.0), ('double_crank', 45.0, 55.0), ('double_rocker', 55.0, 115.0)]
    """
    others = sorted((float(b), float(c), float(d)))
    s, m, l = others
    limit = s + m + l
    # a shortest, a longest, a in the middle; and below l − s − m the links cannot close at all
    cuts: set[float] | list[float] = {0.0, limit, s + m - l, m + l - s, s + l - m, l - s - m}
    cuts = sorted(x for x in cuts if 0.0 <= x <= limit)
    out: list[tuple[str, float, float]] = []
    for lo, hi in zip(cuts[:-1], cuts[1:]):
        k = grashof_class(0.5 * (lo + hi), b, c, d)
        if out and out[-1][0] == k:
            out[-1] = (k, out[-1][1], hi)
        elif k != "none":
            out.append((k, lo, hi))
    return out


@dataclass(frozen=True)
class DrawnCharacteristics:
    """The characteristics as constructed on the drawing.

    Attributes
    ----------
    loop : Loop
    grashof : str
        By Grashof's rule (four-bar), else ``"crank"``.
    mu_l : float
        The drawing's scale, m/mm.
    points : dict
        Drawing mm (origin at A): ``A``, ``D`` or the bar's pivot ``C``; ``B1``, ``C1`` and
        ``B2``, ``C2`` at the extreme positions (1: the working stroke starts here); ``Bg``, ``Cg``
        where γ is smallest; for a slider the guide as ``G0``, ``G1`` (two points on it).
    phi_start, phi_end : float or None
        The crank's absolute angles at the extreme positions, rad [0, 2π); None (with θ and ψ)
        when the output turns fully too (a double crank, a parallelogram).
    theta, psi, stroke_mm, gamma_min, gamma_min_at : float
        θ (rad), ψ (rad; None for a slider), H on the drawing (mm; None for a rocker), γ_min
        (rad) and the crank angle where it occurs (rad).
    """

    loop: Loop
    grashof: str
    mu_l: float
    points: dict[str, _XY] = field(hash=False)
    phi_start: float | None
    phi_end: float | None
    theta: float | None
    psi: float | None
    stroke_mm: float | None
    gamma_min: float
    gamma_min_at: float


def _angle(u: _XY, v: _XY) -> float:
    """The angle between two drawn directions, measured as a protractor does (0 … π)."""
    return abs(math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1]))


def _sub(p: _XY, q: _XY) -> _XY:
    return (p[0] - q[0], p[1] - q[1])


def _along(p: _XY, q: _XY, t: float) -> _XY:
    """The point t mm from p towards q."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    n = math.hypot(dx, dy)
    return (p[0] + t * dx / n, p[1] + t * dy / n)


def _wrap(x: float) -> float:
    return x % (2.0 * math.pi)


def _left(p: _XY, q: _XY, r: _XY) -> float:
    """> 0 when r lies left of the directed line p → q."""
    return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])


def _order(A: _XY, B1: _XY, B2: _XY, sense: float) -> tuple[float, float, float, bool]:
    """(phi_start, phi_end, θ, swapped): the slow stroke starts at the returned start."""
    p1 = _wrap(math.atan2(B1[1] - A[1], B1[0] - A[0]))
    p2 = _wrap(math.atan2(B2[1] - A[1], B2[0] - A[0]))
    travel = _wrap(sense * (p2 - p1))
    theta = abs(travel - math.pi)
    # equal strokes (θ = 0): start at B2 (the extended position of a four-bar or slider-crank)
    return (p1, p2, theta, False) if travel > math.pi + 1e-9 else (p2, p1, theta, True)


def draw_characteristics(linkage: Linkage, mu_l: float) -> DrawnCharacteristics:
    """Construct the extreme positions and the smallest transmission angle of the basic loop.

    Parameters
    ----------
    linkage : Linkage
        SI units; its first dyad closes the basic loop with the crank (:func:`basic_loop`).
    mu_l : float
        The drawing's scale, m/mm.

    Raises
    ------
    ValueError
        No basic loop, or the crank cannot turn fully (no extreme positions of a crank).

    Examples
    --------
    >>> from graphmech.mechanisms.linkage import Crank, RRR, Linkage
    >>> fb = Linkage({"A": (0.0, 0.0), "D": (0.072, 0.0)}, Crank("1", "A", "B", 0.028, 10.0),
    ...              (RRR("B", "C", "D", ("2", "3"), (0.052, 0.050), "left"),))
    >>> ch = draw_characteristics(fb, 0.0005)
    >>> ch.grashof, round(math.degrees(ch.theta), 4), round(math.degrees(ch.psi), 4), round(math.degrees(ch.gamma_min), 4)
    ('crank_rocker_AB', 18.5617, 70.5582, 22.7342)
    """
    loop = basic_loop(linkage)
    ops = ScalarOps()
    n = loop.names
    origin = linkage.frame_points[n["A"]]

    def mm(xy: tuple[float, float]) -> _XY:
        return ((xy[0] - origin[0]) / mu_l, (xy[1] - origin[1]) / mu_l)

    A = (0.0, 0.0)
    a = loop.a / mu_l
    pts: dict[str, _XY] = {"A": A}
    no_turn = "the crank does not turn fully"
    if loop.kind == "fourbar":
        D = mm(linkage.frame_points[n["D"]])
        b, c = loop.b / mu_l, loop.c / mu_l
        d = math.hypot(D[0], D[1])
        kind = grashof_class(a, b, c, d)
        if kind not in ("crank_rocker_AB", "double_crank", "change_point"):
            raise NotApplicable(f"{no_turn} ({kind.replace('_', ' ')} by Grashof's rule): no extreme positions")
        rrr = cast(RRR, linkage.dyads[0])  # basic_loop's "fourbar" is an RRR on the crank's tip
        branch = rrr.branch if rrr.q == n["D"] else ("right" if rrr.branch == "left" else "left")
        side = 1.0 if branch == "left" else -1.0

        def on_branch(B: _XY, C: _XY) -> bool:
            return side * _left(B, D, C) >= 0.0

        def rocker_pin(radius: float, crank_back: bool) -> tuple[_XY, _XY]:
            """C on the arc of ``radius`` about A and the rocker's circle; B on AC (or behind A)."""
            ops.step = f"{n['C']} = arc({n['A']}, {n['B']}{n['C']} {'−' if crank_back else '+'} {n['A']}{n['B']}) ∩ " \
                       f"circle({n['D']}, {n['C']}{n['D']})"
            for s in (1.0, -1.0):
                C = intersect_circles(ops, A, radius, D, c, s, lambda dd: no_turn)
                B = _along(A, C, -a if crank_back else a)
                if on_branch(B, C):
                    return B, C
            return B, C

        links = {"AB": a, "BC": b, "CD": c, "AD": d}
        shortest = min(links.values())
        rocker_turns = kind == "double_crank" or (kind == "change_point" and c <= shortest * (1 + 1e-12))
        if rocker_turns:  # the output turns fully too: γ only
            g_best = _fourbar_gamma_drawn(A, D, a, b, c, ops, on_branch)
            pts.update(D=D, Bg=g_best[1], Cg=g_best[2])
            return DrawnCharacteristics(loop, kind, mu_l, pts, None, None, None, None, None, g_best[0],
                                        _wrap(math.atan2(g_best[1][1], g_best[1][0])))
        if b - a <= 1e-12 * (a + b + c + d):  # a deltoid AB = BC: folded, C falls on A
            raise NotApplicable(f"{n['A']}{n['B']} = {n['B']}{n['C']} (a deltoid): at the folded position "
                             f"{n['C']} falls on {n['A']}, so the crank's angle there is undetermined: "
                             "no extreme positions")
        B1, C1 = rocker_pin(b - a, True)  # folded: AC₁ = BC − AB
        B2, C2 = rocker_pin(b + a, False)  # extended: AC₂ = BC + AB
        psi: float | None = _angle(_sub(C1, D), _sub(C2, D))
        stroke = None
        pts["D"] = D
        best = _fourbar_gamma_drawn(A, D, a, b, c, ops, on_branch)
    elif loop.kind == "slider_crank":
        kind = "crank"
        y = linkage.dyads[0]
        assert isinstance(y, RRP) and isinstance(y.guide, Guide)
        b = loop.b / mu_l
        G = mm(y.guide.through)
        g = y.guide.direction
        line = (G[0], G[1], g[0], g[1])
        side = 1.0 if y.branch == "forward" else -1.0
        ops.step = f"{n['C']}₁ = arc({n['A']}, {n['B']}{n['C']} − {n['A']}{n['B']}) ∩ guide"
        C1 = intersect_circle_line(ops, A, b - a, line, side, lambda e: no_turn)
        ops.step = f"{n['C']}₂ = arc({n['A']}, {n['B']}{n['C']} + {n['A']}{n['B']}) ∩ guide"
        C2 = intersect_circle_line(ops, A, b + a, line, side, lambda e: no_turn)
        B1, B2 = _along(A, C1, -a), _along(A, C2, a)
        psi, stroke = None, math.dist(C1, C2)
        # γ smallest where B is farthest from the guide: the crank ⟂ the guide, away from it
        off = (A[0] - G[0]) * g[1] - (A[1] - G[1]) * g[0]  # > 0: A right of the guide's direction
        normal = (g[1], -g[0]) if off >= 0.0 else (-g[1], g[0])
        B = (a * normal[0], a * normal[1])
        C = intersect_circle_line(ops, B, b, line, side, lambda e: no_turn)
        # γ = 90° − α, α the pressure angle between BC and the slider's path
        across = _angle(_sub(B, C), (-g[1], g[0]))
        best = (min(across, math.pi - across), B, C)
        lo = min(0.0, (C1[0] - G[0]) * g[0] + (C1[1] - G[1]) * g[1], (C2[0] - G[0]) * g[0] + (C2[1] - G[1]) * g[1])
        hi = max((C1[0] - G[0]) * g[0] + (C1[1] - G[1]) * g[1], (C2[0] - G[0]) * g[0] + (C2[1] - G[1]) * g[1])
        pts["G0"] = (G[0] + (lo - 10.0) * g[0], G[1] + (lo - 10.0) * g[1])
        pts["G1"] = (G[0] + (hi + 10.0) * g[0], G[1] + (hi + 10.0) * g[1])
    elif loop.b != 0.0:  # an offset guide bar
        kind = "crank"
        Cp = mm(linkage.frame_points[n["C"]])
        B1, B2, F1, F2, psi, best = _offset_guide_bar_drawn(A, Cp, a, loop.b / mu_l, ops, n)
        C1, C2, stroke = Cp, Cp, None
        pts.update(C=Cp, F1=F1, F2=F2)
    else:  # guide bar
        kind = "crank"
        Cp = mm(linkage.frame_points[n["C"]])
        if a >= math.hypot(*Cp) * (1.0 - 1e-12):
            raise NotApplicable("the bar turns fully (a rotating guide bar): no extreme positions")
        M = (Cp[0] / 2.0, Cp[1] / 2.0)  # the circle on AC as diameter: the bar ⟂ the crank there
        ops.step = f"{n['B']}₁, {n['B']}₂ = crank circle ∩ circle on {n['A']}{n['C']} as diameter"
        r = math.hypot(*Cp) / 2.0
        B1 = intersect_circles(ops, A, a, M, r, 1.0, lambda dd: no_turn)
        B2 = intersect_circles(ops, A, a, M, r, -1.0, lambda dd: no_turn)
        C1, C2 = Cp, Cp
        psi, stroke = _angle(_sub(B1, Cp), _sub(B2, Cp)), None
        pts["C"] = Cp
        best = (math.pi / 2.0, B1, Cp)
    start, end, theta, swapped = _order(A, B1, B2, loop.sense)
    if swapped:
        B1, B2, C1, C2 = B2, B1, C2, C1
        if "F1" in pts:
            pts["F1"], pts["F2"] = pts["F2"], pts["F1"]
    assert best is not None
    pts.update(B1=B1, C1=C1, B2=B2, C2=C2, Bg=best[1], Cg=best[2])
    centred = loop.kind == "guide_bar" and loop.b == 0.0  # γ = 90° everywhere: named at the start
    at = start if centred else _wrap(math.atan2(best[1][1], best[1][0]))
    return DrawnCharacteristics(loop, kind, mu_l, pts, start, end, theta, psi, stroke, best[0], at)


def _offset_guide_bar_drawn(A: _XY, C: _XY, a: float, e: float, ops: ScalarOps, n: dict[str, str]
                            ) -> tuple[_XY, _XY, _XY, _XY, float, tuple[float, _XY, _XY]]:
    """An offset guide bar's extremes (drawing mm): where its line, at e left of C, is tangent to the
    crank circle — a common tangent of the circles (A, a) and (C, |e|). The line through A parallel
    to it is at e ± a from C: the circle (C, |e ± a|) cut by the circle on AC as diameter gives its
    foot T (CT ⟂ AT), AT gives the line's direction û (towards the block: (A − C)·û > 0), and
    B = A ∓ a·n̂, F = C + e·n̂ (n̂ = û turned 90° CCW). Returns B₁, B₂, F₁, F₂, ψ and (γ_min, B′, C):
    γ = 90° less the angle between CB and the line, smallest where |CB| is, B′ on AC.
    """
    d = math.hypot(C[0] - A[0], C[1] - A[1])
    if a + abs(e) >= d * (1.0 - 1e-12):
        raise NotApplicable(f"{n['A']}{n['B']} + |e| is not less than {n['A']}{n['C']}: the crank pin reaches the "
                            f"circle of radius |e| about {n['C']}, so the bar cannot follow it round: no extreme positions")
    M = ((A[0] + C[0]) / 2.0, (A[1] + C[1]) / 2.0)
    out: list[tuple[_XY, _XY, _XY]] = []
    for sigma in (1.0, -1.0):
        ops.step = f"{n['B']} = the line at e from {n['C']} tangent to the crank circle ({'+' if sigma > 0 else '−'})"
        for side in (1.0, -1.0):
            T = intersect_circles(ops, C, abs(e + sigma * a), M, d / 2.0, side, lambda dd: "no tangent")
            ux, uy = A[0] - T[0], A[1] - T[1]
            if math.hypot(ux, uy) == 0.0:
                continue
            if (A[0] - C[0]) * ux + (A[1] - C[1]) * uy < 0.0:
                ux, uy = -ux, -uy
            ln = math.hypot(ux, uy)
            ux, uy = ux / ln, uy / ln
            nx, ny = -uy, ux
            if abs((A[0] - C[0]) * nx + (A[1] - C[1]) * ny - (e + sigma * a)) <= 1e-9 * d:
                out.append(((A[0] - sigma * a * nx, A[1] - sigma * a * ny), (C[0] + e * nx, C[1] + e * ny), (ux, uy)))
                break
    if len(out) != 2:
        raise NotApplicable("the offset guide bar's extreme lines could not be constructed")
    (B1, F1, u1), (B2, F2, u2) = out
    psi = _angle(u1, u2)
    Bg = _along(A, C, a)  # the crank pointing at C: |CB| smallest, the line most oblique to CB
    Fg = intersect_circles(ops, C, abs(e), ((Bg[0] + C[0]) / 2.0, (Bg[1] + C[1]) / 2.0),
                           math.dist(Bg, C) / 2.0, 1.0 if e > 0.0 else -1.0, lambda dd: "no tangent")
    gamma = math.pi / 2.0 - _angle(_sub(Bg, Fg), _sub(Bg, C))
    return B1, B2, F1, F2, psi, (gamma, Bg, C)


def _fourbar_gamma_drawn(A: _XY, D: _XY, a: float, b: float, c: float, ops: ScalarOps,
                         on_branch: Callable[[_XY, _XY], bool]) -> tuple[float, _XY, _XY]:
    """γ where the crank lies along the frame line, towards D and away from it: the smaller."""
    best = None
    # Frame pivots that coincide leave the frame line undefined, but the triangle ABC is then
    # rigid (B and C both turn about A): γ is the same everywhere, so any line will do.
    towards = D if D != A else (A[0] + 1.0, A[1])
    for t in (a, -a):
        B = _along(A, towards, t)
        for s in (1.0, -1.0):
            C = intersect_circles(ops, B, b, D, c, s, lambda dd: "the crank does not turn fully")
            if on_branch(B, C):
                break
        delta = _angle(_sub(B, C), _sub(D, C))
        g = min(delta, math.pi - delta)
        if best is None or g < best[0] - 1e-12:
            best = (g, B, C)
    assert best is not None
    return best


def fourbar_lengths(linkage: Linkage) -> dict[str, float]:
    """The four links of a four-bar loop by their ends (m): AB, BC, CD, AD."""
    loop = basic_loop(linkage)
    if loop.kind != "fourbar":
        raise NotApplicable("Grashof's rule is for a hinged four-bar")
    A, D = linkage.frame_points[loop.names["A"]], linkage.frame_points[loop.names["D"]]
    return {"AB": loop.a, "BC": loop.b, "CD": loop.c, "AD": math.dist(A, D)}
