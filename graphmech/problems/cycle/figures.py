"""The figures of a full cycle and of a linkage's characteristics, as a course sheet draws them.

cycle — the kinematic diagram at N positions overlaid (at μl)
    position 1 drawn bold with its letters, the others thin, the crank pin's positions numbered
    1 … N in the crank's sense; with ``paths`` the paths of the chosen points (coupler curves)
    through all N positions, their positions dotted.
velocity, acceleration — the polygons of all positions with a common pole (at μv, μa)
    each position's vectors from the pole and its polygon's sides; the images lettered with the
    position's number (b₁, c₁ … b₁₂, c₁₂).
diagrams — per slider (link): s–φ, v–φ and a–φ stacked (ψ–φ, ω–φ, ε–φ for a link)
    s read off the kinematic diagram at the positions; v–φ by graphical differentiation: the
    pole P₁ at H₁ left of the origin, rays from it parallel to the chords of s–φ cut the v axis,
    each value carried across to the middle of its interval; a–φ likewise from v–φ with H₂.
characteristics — the extreme positions
    both extreme positions (position 1 bold, the other dashed), the arcs of radius BC − AB and
    BC + AB about A that find them, the crank angle θ between them and the swing ψ (or the
    stroke H) marked; the position of the smallest transmission angle γ_min thin, with γ_min
    marked at C.

Many positions (N up to 3600) are drawn in full in the curves and paths; the overlaid
mechanisms, polygons, numbers and rays are thinned to a readable count, and the panel's note
says which positions are drawn.
"""
from __future__ import annotations

import dataclasses
import math
from typing import Any, Mapping, Sequence, cast

import numpy as np

from graphmech.construction.graph import values_at
from graphmech.problems.linkage.figures import caption, display, mechanism_items, polygon_items
from graphmech.drawing.diagrams import AXIS_OVERRUN, count_every, moved, numbers_every, phi_axis_numbers
from graphmech.drawing.primitives import (XY, Arrow, Circle, FixedPivot, GuideLine, Hinge, Label, Panel, Plate,
                                         Polyline, Primitive, Role, Segment, Sheet, Slider, angle_arc,
                                         angle_mark)
from graphmech.drawing.lettering import LETTER, number, scale_text
from graphmech.drawing.notation import word

__all__ = ["cycle_sheet", "cycle_items", "polygons_items", "diagram_items", "characteristics_items", "MOST_DRAWN"]

#: At most this many overlaid mechanisms (and polygons) are drawn; at most this many rays.
MOST_DRAWN, MOST_RAYS = 24, 12
#: Path points get a dot up to this many positions.
MOST_DOTS = 72
#: Radius of a dot, mm; of the angle marks θ, ψ, γ.
DOT, MARK_R = 0.35, 9.0
#: The smallest transmission angle's letter.
GAMMA_MIN = "γ_{min}"
#: Vertical gap between the stacked diagrams, mm.
STACK_GAP = 14.0

_BELOW = ((0.0, 1.0), (1.0, 0.0), (-1.0, 0.0))


def _pt(v: Any) -> XY:
    return (float(v[0]), float(v[1]))


def _unit(a: XY, b: XY) -> XY:
    dx, dy = b[0] - a[0], b[1] - a[1]
    n = math.hypot(dx, dy)
    return (dx / n, dy / n) if n > 0 else (0.0, 0.0)


def drawn_positions(n: int) -> list[int]:
    """Which of N positions are drawn overlaid (0-based): all up to :data:`MOST_DRAWN`, else every k-th.

    >>> drawn_positions(12)[-1], len(drawn_positions(3600)), drawn_positions(3600)[:3]
    (11, 18, [0, 200, 400])
    """
    return list(range(0, n, count_every(n, MOST_DRAWN)))


#: A drawn curve keeps a vertex only this far (mm) along it from the last one kept: a 0.5 mm chord
#: departs from an arc of 5 mm radius by 0.006 mm, far below the pen.
CURVE_STEP_MM = 0.5


def thinned(points: Any, step: float = CURVE_STEP_MM) -> tuple[XY, ...]:
    """The vertices of a drawn curve at least ``step`` mm apart along it (ends kept).

    Thousands of positions put vertices hundredths of a millimetre apart; the curve looks the same
    through every ``step`` mm, and the sheet's label placer works on far fewer segments.

    >>> thinned([(0.0, 0.0), (0.1, 0.0), (0.2, 0.0), (0.3, 0.0), (1.0, 0.0)], step=0.25)
    ((0.0, 0.0), (0.3, 0.0), (1.0, 0.0))
    """
    p = np.asarray(points, dtype=float)
    if len(p) <= 2:
        return tuple(map(_pt, p))
    s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(p, axis=0).T))])
    bins = np.floor(s / step + 1e-9)
    keep = np.flatnonzero(np.diff(bins, prepend=-1.0) > 0)
    if keep[-1] != len(p) - 1:
        keep = np.append(keep, len(p) - 1)
    return tuple(map(_pt, p[keep]))


def _which(n: int) -> str:
    k = count_every(n, MOST_DRAWN)
    return "" if k == 1 else f"every {k}th of the {n} positions drawn"


def _guide_spans(cyc: Any) -> dict[int, tuple[float, float]]:
    """The stretch of each guide its slider covers over the cycle (mm along the guide)."""
    from graphmech.mechanisms.linkage import RPP, RRP, Guide, SliderInput

    linkage, b = cyc.build.linkage, cyc.build
    guides = [(-1, linkage.driver.guide, linkage.driver.point)] if isinstance(linkage.driver, SliderInput) else []
    guides += [(k, y.guide, y.c) for k, y in enumerate(linkage.dyads)
               if isinstance(y, (RRP, RPP)) and isinstance(y.guide, Guide)]
    spans = {}
    for k, g, point in guides:
        if point in cyc.mech:
            ox, oy = b.to_drawing(g.through)
            s = (cyc.mech[point][:, 0] - ox) * g.direction[0] + (cyc.mech[point][:, 1] - oy) * g.direction[1]
            spans[k] = (float(s.min()), float(s.max()))
    return spans


# ----------------------------------------------------------------------------- the mechanism
def cycle_items(cyc: Any, paths: Sequence[str] = ()) -> list[Primitive]:
    """The mechanism at its drawn positions, numbered, with the paths of ``paths``."""
    spans = _guide_spans(cyc)
    crank = cyc.build.linkage.driver
    items: list[Primitive] = []
    first: list[Primitive] = []
    for i in drawn_positions(cyc.n):
        pos = {name: _pt(xy[i]) for name, xy in cyc.mech.items()}
        its = mechanism_items(cyc.build, pos, spans)
        if i == 0:  # letters, not link numbers: the numbers on this sheet are the positions'
            links = set(cyc.build.linkage.links())
            first = [it for it in its if not (isinstance(it, Label) and not it.italic and it.text in links)]
            continue
        for it in its:  # the other positions thin dashed, without letters, arrows or repeated frame
            if isinstance(it, Segment):
                items.append(Segment(it.p0, it.p1, "construction", dashed=True))
            elif isinstance(it, Plate):
                items += [Segment(a, b, "construction", dashed=True) for a, b in zip(it.points, it.points[1:] + it.points[:1])]
            elif isinstance(it, (Hinge, Slider)):
                items.append(it)
    numbers: list[Primitive] = []
    if cyc.swing:
        numbers = _swing_numbers(cyc)
    else:
        A = cyc.mech[crank.pivot][0]
        tip = cyc.mech[crank.tip]
        every = numbers_every(cyc.n, 2.0 * math.pi * float(np.hypot(*(tip[0] - A))) / cyc.n, LETTER)
        for i in range(0, cyc.n, every):
            at = _pt(tip[i])
            numbers.append(Label(str(i + 1), at, (_unit(at, _pt(A)),), LETTER, italic=False))
    curves: list[Primitive] = []
    for name in paths:
        xy = cyc.mech[name]
        curves.append(Polyline(thinned(cyc.paths.get(name, xy)), "result", closed=not cyc.swing))
        if cyc.n <= MOST_DOTS:
            curves += [Circle(_pt(p), DOT, "result") for p in xy]
    return items + curves + first + numbers


def _swing_numbers(cyc: Any) -> list[Primitive]:
    """A swing's positions numbered at the driver's point: position k and N + 2 − k are one place,
    numbered together (``2, 12``) on the side away from the rocker's pivot (a slider's: beside its guide)."""
    from graphmech.mechanisms.linkage import Crank

    d = cyc.build.linkage.driver
    tip = cyc.mech[d.tip if isinstance(d, Crank) else d.point]
    n, half = cyc.n, cyc.n // 2
    out: list[Primitive] = []
    spacing = float(np.hypot(*np.diff(tip[: half + 1], axis=0).T).mean())  # mm between neighbours
    for i in range(0, half + 1, numbers_every(n, spacing / 2.0, LETTER)):  # "2, 12" is twice as wide
        at = _pt(tip[i])
        if isinstance(d, Crank):
            away = _unit(at, _pt(cyc.mech[d.pivot][0]))
        else:
            away = (-d.guide.direction[1], d.guide.direction[0])
        text = str(i + 1) if i in (0, half) else f"{i + 1}, {n + 1 - i}"
        out.append(Label(text, at, (away,), LETTER, italic=False))
    return out


#: Images of the common-pole polygons closer than this (mm) share one label.
MERGE_MM = 1.0


def polygons_items(cyc: Any, panel: str) -> list[Primitive]:
    """The polygons of the drawn positions with a common pole, images lettered with the
    position (b₁ … b₁₂); images that (nearly) coincide share one label (c_{3,9}; b_{4},c_{4}); a
    point's images on one line through the pole are numbered, lettered at the farthest tip only."""
    b, plan = cyc.build, cyc.plan
    images = b.vel if panel == "velocity" else b.acc
    items: list[Primitive] = []
    pole = ""
    found: list[tuple[XY, str, int]] = []  # (where, image letter, position number)
    for i in drawn_positions(cyc.n):
        if i in cyc.polygon_failures:  # no polygon at a change point: the panel's note says so
            continue
        values = values_at(cyc.values, i)
        for it in polygon_items(plan, values, panel):
            if isinstance(it, Segment) and it.role == "construction":
                continue
            if isinstance(it, Label):
                if i == 0 and abs(it.anchor[0]) < 1e-9 and abs(it.anchor[1]) < 1e-9:
                    pole = it.text  # the pole (and the images of fixed points)
                continue
            items.append(it)
        for name, step in images.items():
            s = plan.by_name.get(step)
            if s is None or not s.label or step not in values:
                continue
            at = _pt(values[step])
            if math.hypot(*at) < 1e-6:
                continue
            found.append((at, display(s.label), i + 1))
    out: list[Primitive] = [Label(pole, (0.0, 0.0), (), LETTER)] if pole else []
    found = _numbers_on_lines(found)
    for group in _clusters(found, MERGE_MM):
        at = (sum(g[0][0] for g in group) / len(group), sum(g[0][1] for g in group) / len(group))
        out.append(Label(_merged(group), at, (), LETTER))
    return items + out


def _clusters(found: list[tuple[XY, str, int]], within: float) -> list[list[tuple[XY, str, int]]]:
    """The points in groups, each point within ``within`` mm of its group's first point (no
    chains: images spaced along one line stay apart)."""
    groups: list[list[tuple[XY, str, int]]] = []
    for f in found:
        home = next((g for g in groups if math.dist(f[0], g[0][0]) < within), None)
        if home is None:
            groups.append([f])
        else:
            home.append(f)
    return [sorted(g, key=lambda t: (t[1] == "", t[1], t[2])) for g in groups]  # letters before bare numbers


def _numbers_on_lines(found: list[tuple[XY, str, int]]) -> list[tuple[XY, str, int]]:
    """The images of a point that all lie on one line through the pole (a slider's velocity
    along its guide) pile up along that line: they keep their letter at the farthest tip only,
    the others are numbered (the letter "" stands for "the same as the line's")."""
    by: dict[str, list[int]] = {}
    for k, (_, letter, _) in enumerate(found):
        by.setdefault(letter, []).append(k)
    out = list(found)
    for letter, ks in by.items():
        far = max(ks, key=lambda k: math.hypot(*found[k][0]))
        r = math.hypot(*found[far][0])
        if len(ks) < 3 or r <= 0.0:
            continue
        u = (found[far][0][0] / r, found[far][0][1] / r)
        if all(abs(found[k][0][0] * u[1] - found[k][0][1] * u[0]) < 0.5 for k in ks):
            for k in ks:
                if k != far:
                    out[k] = (found[k][0], "", found[k][2])
    return out


def _merged(group: list[tuple[XY, str, int]]) -> str:
    """One label for images standing together: c_{3,9}; b_{4}, c_{4}; s₂(3,9)."""
    by: dict[str, list[int]] = {}
    for _, letter, k in group:
        by.setdefault(letter, []).append(k)
    parts = []
    for letter, ks in by.items():
        nums = ",".join(str(k) for k in sorted(set(ks)))
        parts.append(nums if not letter else
                     f"{letter}({nums})" if any(ch in letter for ch in "₀₁₂₃₄₅₆₇₈₉") else f"{letter}_{{{nums}}}")
    return ",".join(parts)


# ----------------------------------------------------------------------------- the diagrams
def _axes(xe: float, lo: float, hi: float, name: str, n: int, every: int, period: float,
          left: float = 0.0) -> tuple[list[Primitive], list[Label]]:
    items: list[Primitive] = [Arrow((left, 0.0), (xe + AXIS_OVERRUN, 0.0), "label"),
                              Arrow((0.0, lo - (3.0 if lo < 0.0 else 0.0)), (0.0, hi + AXIS_OVERRUN), "label")]
    x = np.arange(n + 1) * (period / n)
    for k in range(every, n + 1, every):
        items.append(Segment((float(x[k]), 0.0), (float(x[k]), -1.0), "label"))
    labels = [Label(name, (0.0, hi + AXIS_OVERRUN), ((0.0, -1.0),), LETTER),
              Label("φ", (xe + AXIS_OVERRUN, 0.0), ((-1.0, 0.0),), LETTER),
              Label("O", (0.0, 0.0), ((1.0, 0.0), (0.0, 1.0), (0.0, -1.0)), LETTER)]
    return items, labels + [dataclasses.replace(t, size=LETTER) for t in phi_axis_numbers(x, every)]


def _differentiation_items(diff: Any, values_at: np.ndarray, name: str, n: int, every: int, period: float,
                           pole_name: str) -> list[Primitive]:
    """A derivative diagram: pole, rays ∥ the chords, the values carried to the interval middles."""
    H = diff.H_mm
    y = np.asarray(values_at, dtype=float)
    lo, hi = min(0.0, float(y.min())), max(0.0, float(y.max()))
    items, labels = _axes(period, lo, hi, name, n, every, period, left=-H - 4.0)
    P = (-H, 0.0)
    ray_every = count_every(n, MOST_RAYS)
    construction: list[Primitive] = []
    for k in range(0, n, ray_every):
        v = float(diff.derivative_mm[k])
        construction += [Segment(P, (0.0, v), "construction"),
                         Segment((0.0, v), (float(diff.mid_mm[k]) % period, v), "construction", dashed=True)]
    # the curve through the values at the middles, closed across the cycle's seam
    mx = np.asarray(diff.mid_mm, dtype=float) % period
    order = np.argsort(mx)
    mx, my = mx[order], np.asarray(diff.derivative_mm, dtype=float)[order]
    gap = (mx[0] + period - mx[-1])
    y0 = float(my[-1] + (my[0] - my[-1]) * (period - mx[-1]) / gap) if gap > 0 else float(my[0])
    curve = [(0.0, y0)] + list(zip(mx.tolist(), my.tolist())) + [(period, y0)]
    result: list[Primitive] = [Polyline(thinned(curve), "result"), Circle(P, DOT, "result")]
    if n <= MOST_DOTS:
        result += [Circle((float(a), float(b)), DOT, "result") for a, b in zip(mx, my)]
    yd = lo - 5.0
    dim: list[Primitive] = [Segment(P, (P[0], yd - 1.5), "label"), Arrow((-H / 2.0, yd), (-H, yd), "label"),
                            Arrow((-H / 2.0, yd), (0.0, yd), "label"), Segment((0.0, 0.0), (0.0, yd - 1.5), "label")]
    names = [Label(pole_name, P, ((1.0, 0.0), (1.0, 0.5)), LETTER),
             Label("H" + pole_name[1:], (-H / 2.0, yd), ((1.0, 0.0), (-1.0, 0.0)), LETTER)]
    return construction + items + result + dim + labels[:3] + names + labels[3:]


def diagram_items(dg: Any, n: int, period: float) -> list[Primitive]:
    """s–φ, v–φ and a–φ of one subject, stacked top to bottom (the s diagram's origin at (0, 0))."""
    point = dg.kind != "link"
    names = ("s", "v", "aτ" if dg.kind == "path" else "a") if point else ("ψ", "ω", "ε")
    every = numbers_every(n, period / n, LETTER)
    # s–φ: the curve through the positions, closed at the cycle's end
    x = np.append(dg.x_mm, period)
    s = np.append(dg.s_mm, dg.s_mm[0] + dg.rise_mm)
    lo, hi = min(0.0, float(s.min())), max(0.0, float(s.max()))
    # the subject as a subscript: s_{C}, ψ_{3}
    def sub(name: str) -> str:
        return f"a_{{{dg.subject}}}^{{τ}}" if name == "aτ" else f"{name}_{{{dg.subject}}}"

    items, labels = _axes(period, lo, hi, sub(names[0]), n, every, period)
    top: list[Primitive] = [Polyline(thinned(np.column_stack([x, s])), "result")]
    if n <= MOST_DOTS:
        top += [Circle((float(a), float(b)), DOT, "result") for a, b in zip(dg.x_mm, dg.s_mm)]
        top += [Segment((float(a), 0.0), (float(a), float(b)), "construction") for a, b in zip(dg.x_mm, dg.s_mm)
                if abs(b) > 1e-9]
    out: list[Primitive] = items + top + cast("list[Primitive]", labels)
    v_name, a_name = sub(names[1]), sub(names[2])
    v_items = _differentiation_items(dg.velocity, dg.velocity.derivative_mm, v_name, n, every, period, "P_{1}")
    a_items = _differentiation_items(dg.acceleration, dg.a_mm, a_name, n, every, period, "P_{2}")
    y = lo - STACK_GAP - 6.0
    v_hi = max(0.0, float(np.max(dg.velocity.derivative_mm)))
    v_lo = min(0.0, float(np.min(dg.velocity.derivative_mm)))
    dy_v = y - v_hi - AXIS_OVERRUN
    out += [moved(i, 0.0, dy_v) for i in v_items]
    a_hi = max(0.0, float(np.max(dg.acceleration.derivative_mm)))
    dy_a = dy_v + v_lo - 5.0 - STACK_GAP - a_hi - AXIS_OVERRUN - 2.0
    out += [moved(i, 0.0, dy_a) for i in a_items]
    return out


def _diagram_notes(dg: Any, mu_phi: float) -> tuple[str, ...]:
    h1, h2 = number(dg.velocity.H_mm), number(dg.acceleration.H_mm)
    if dg.kind == "path":
        s = f"s along the path of {dg.subject} (its chords end to end): {scale_text('s', dg.mu_s)}, " \
            f"{scale_text('phi', mu_phi)}"
        v = f"H_{{1}} = {h1} mm: the speed, μ_{{v}} = μ_{{s}}·ω_{{1}}/(μ_{{φ}}·H_{{1}}) = {number(dg.mu_v)} (m/s)/mm"
        a = (f"H_{{2}} = {h2} mm: the tangential acceleration, μ_{{a}} = μ_{{v}}·ω_{{1}}/(μ_{{φ}}·H_{{2}}) = "
             f"{number(dg.mu_a)} (m/s²)/mm")
    elif dg.kind == "point":
        s = f"{scale_text('s', dg.mu_s)}, {scale_text('phi', mu_phi)}"
        v = f"H_{{1}} = {h1} mm: μ_{{v}} = μ_{{s}}·ω_{{1}}/(μ_{{φ}}·H_{{1}}) = {number(dg.mu_v)} (m/s)/mm"
        a = f"H_{{2}} = {h2} mm: μ_{{a}} = μ_{{v}}·ω_{{1}}/(μ_{{φ}}·H_{{2}}) = {number(dg.mu_a)} (m/s²)/mm"
    else:  # a link's angle: μψ in degrees per mm, as the scene states it
        s = f"μ_{{ψ}} = {number(math.degrees(dg.mu_s))} °/mm, {scale_text('phi', mu_phi)}"
        v = f"H_{{1}} = {h1} mm: μ_{{ω}} = μ_{{ψ}}·ω_{{1}}/(μ_{{φ}}·H_{{1}}) = {number(dg.mu_v)} (rad/s)/mm"
        a = f"H_{{2}} = {h2} mm: μ_{{ε}} = μ_{{ω}}·ω_{{1}}/(μ_{{φ}}·H_{{2}}) = {number(dg.mu_a)} (rad/s²)/mm"
    return (s, v, a)


def _diagram_scales(dg: Any, mu_phi: float) -> tuple[tuple[str, float], ...]:
    """The scales that measure a diagram's paper: its ordinate (a length's μs; an angle's μψ has
    no entry of its own in SCALE_INFO and gets none) and μφ along the axis."""
    return ((("s", dg.mu_s),) if dg.kind != "link" else ()) + (("phi", mu_phi),)


# ----------------------------------------------------------------------------- characteristics
#: A centre line longer than this on paper (a drawing metres wide at a stated μl) is drawn thin
#: solid: the renderer cuts a dash-dot line into pieces, thousands of them on a metre.
LONGEST_DASHDOT_MM = 1000.0


def _centre_line(a: XY, b: XY) -> Segment:
    """A line of centres (AD, AC): thin dash-dot."""
    return Segment(a, b, "construction", dashdot=math.dist(a, b) <= LONGEST_DASHDOT_MM)


def _guide(g0: XY, g1: XY, pivot: XY) -> GuideLine:
    """A frame guide hatched on the side away from the crank's pivot (GuideLine hatches the
    right of its direction), so the hatching never runs toward or through the pivot."""
    right = (g1[1] - g0[1]) * (pivot[0] - g0[0]) - (g1[0] - g0[0]) * (pivot[1] - g0[1])
    return GuideLine(g1, g0) if right > 0 else GuideLine(g0, g1)


def _arc_between(centre: XY, p: XY, q: XY, role: Role = "construction") -> Polyline | None:
    r = math.dist(centre, p)
    return angle_arc(centre, _unit(centre, p), _unit(centre, q), r, role)


def characteristics_items(dr: Any, linkage: Any) -> list[Primitive]:
    """Both extreme positions, θ and ψ (or H), and the position of γ_min, at μl (A at the origin)."""
    p = dr.points
    loop = dr.loop
    A = p["A"]
    items: list[Primitive] = []
    labels: list[Primitive] = []
    sub = {k: v for k, v in loop.names.items()}
    if dr.theta is None:  # the output turns fully: the linkage where γ is smallest, nothing else
        D, Bg, Cg = p["D"], p["Bg"], p["Cg"]
        items += [Segment(A, Bg, "result"), Segment(Bg, Cg, "result"), Segment(Cg, D, "result"),
                  _centre_line(A, D), FixedPivot(A), FixedPivot(D), Hinge(Bg), Hinge(Cg)]
        labels += angle_mark(Cg, _unit(Cg, Bg), _unit(Cg, D), 6.0, GAMMA_MIN)
        for at, text in ((A, sub["A"]), (D, sub["D"]), (Bg, sub["B"]), (Cg, sub["C"])):
            labels.append(Label(text, at, (_unit(at, A),) if at != A else (), LETTER))
        return items + labels
    B1, C1, B2, C2, Bg, Cg = p["B1"], p["C1"], p["B2"], p["C2"], p["Bg"], p["Cg"]
    if loop.kind == "fourbar":
        D = p["D"]
        # position 1 bold; the other extreme and the γ_min position thin dashed; AD the line of centres
        items += [Segment(A, B1, "result"), Segment(B1, C1, "result"), Segment(C1, D, "result"),
                  Segment(A, B2, "construction", dashed=True), Segment(B2, C2, "construction", dashed=True),
                  Segment(C2, D, "construction", dashed=True),
                  _centre_line(A, D),
                  Segment(Bg, Cg, "construction", dashed=True), Segment(Cg, D, "construction", dashed=True),
                  Segment(A, Bg, "construction", dashed=True)]
        for arc in (_arc_between(A, C1, C2), _arc_between(D, C1, C2)):
            if arc is not None:
                items.append(arc)
        # θ between AC₁ and AC₂; ψ between DC₁ and DC₂; γ at C
        ref = C1 if math.dist(A, C1) > 1e-9 else B1
        labels += angle_mark(A, _unit(A, ref), _unit(A, C2), min(MARK_R, 0.8 * math.dist(A, C2)), "θ")
        labels += angle_mark(D, _unit(D, C1), _unit(D, C2), min(MARK_R, 0.6 * math.dist(D, C1)), "ψ")
        if math.dist(A, C1) > 1e-9:
            items.append(Segment(A, C1, "construction", dashed=True))
        items.append(Segment(A, C2, "construction", dashed=True))
        labels += angle_mark(Cg, _unit(Cg, Bg), _unit(Cg, D), 6.0, GAMMA_MIN)
        items += [FixedPivot(A), FixedPivot(D)] + [Hinge(x) for x in (B1, C1, B2, C2, Bg, Cg)]
        names = [(A, sub["A"]), (D, sub["D"]), (B1, sub["B"] + "₁"), (C1, sub["C"] + "₁"), (B2, sub["B"] + "₂"),
                 (C2, sub["C"] + "₂"), (Bg, sub["B"] + "′"), (Cg, sub["C"] + "′")]
    elif loop.kind == "slider_crank":
        g = _unit(p["G0"], p["G1"])
        items += [_guide(p["G0"], p["G1"], A), Segment(A, B1, "result"), Segment(B1, C1, "result"),
                  Segment(A, B2, "construction", dashed=True), Segment(B2, C2, "construction", dashed=True),
                  Segment(A, Bg, "construction", dashed=True), Segment(Bg, Cg, "construction", dashed=True),
                  Slider(C1, math.atan2(g[1], g[0])), Slider(C2, math.atan2(g[1], g[0]))]
        for r in (math.dist(A, C1), math.dist(A, C2)):
            arc = angle_arc(A, _unit(A, C1), _unit(A, C2), r, "construction")
            if arc is not None:
                items.append(arc)
        if math.dist(A, C1) > 1e-9:
            items.append(Segment(A, C1, "construction", dashed=True))
        items.append(Segment(A, C2, "construction", dashed=True))
        labels += angle_mark(A, _unit(A, C1), _unit(A, C2), MARK_R, "θ")
        # the stroke H dimensioned beside the guide
        nrm = (-g[1], g[0])
        off = -9.0 if (A[0] - C1[0]) * nrm[0] + (A[1] - C1[1]) * nrm[1] > 0 else 9.0
        d1 = (C1[0] + off * nrm[0], C1[1] + off * nrm[1])
        d2 = (C2[0] + off * nrm[0], C2[1] + off * nrm[1])
        mid = ((d1[0] + d2[0]) / 2.0, (d1[1] + d2[1]) / 2.0)
        items += [Segment(C1, d1, "label"), Segment(C2, d2, "label")]
        if math.dist(d1, d2) > 1e-6:  # a stroke too short to draw (a crank of 1e-300 mm) gets no arrows
            items += [Arrow(mid, d1, "label"), Arrow(mid, d2, "label")]
        labels.append(Label("H", mid, (g, (-g[0], -g[1])), LETTER))
        across = (-g[1], g[0])
        normal = across if (Bg[0] - Cg[0]) * across[0] + (Bg[1] - Cg[1]) * across[1] > 0 else (-across[0], -across[1])
        # γ is measured from the normal to the guide (the slider's path is the guide)
        items.append(Segment(Cg, (Cg[0] + 14.0 * normal[0], Cg[1] + 14.0 * normal[1]), "construction", dashed=True))
        labels += angle_mark(Cg, _unit(Cg, Bg), normal, 8.0, GAMMA_MIN)
        items += [FixedPivot(A)] + [Hinge(x) for x in (B1, B2, C1, C2, Bg, Cg)]
        names = [(A, sub["A"]), (B1, sub["B"] + "₁"), (C1, sub["C"] + "₁"), (B2, sub["B"] + "₂"), (C2, sub["C"] + "₂"),
                 (Bg, sub["B"] + "′"), (Cg, sub["C"] + "′")]
    else:
        C = p["C"]
        r = math.dist(A, B1)
        items.append(Circle(A, r, "construction"))
        reach = max(math.dist(C, B1), math.dist(C, B2)) + 12.0
        extremes: tuple[tuple[XY, Role, bool], ...] = ((B1, "result", False), (B2, "construction", True))
        feet = (p.get("F1", C), p.get("F2", C))  # an offset bar's line starts at its foot F, the arm CF ⟂ it
        for (B, role, dashed), F in zip(extremes, feet):
            u = _unit(F, B)
            far = reach if F == C else math.dist(F, B) + 12.0
            items += [Segment(A, B, role, dashed=dashed),
                      Segment(F, (F[0] + far * u[0], F[1] + far * u[1]), role, dashed=dashed),
                      Slider(B, math.atan2(u[1], u[0]))]
            if F != C:
                items.append(Segment(C, F, role, dashed=dashed))
        items.append(_centre_line(A, C))
        u1, u2 = _unit(feet[0], B1), _unit(feet[1], B2)
        det = u1[0] * u2[1] - u1[1] * u2[0]
        if feet[0] != C and abs(det) > 1e-9:  # ψ between the two lines, where they meet
            w = (feet[1][0] - feet[0][0], feet[1][1] - feet[0][1])
            s1 = (w[0] * u2[1] - w[1] * u2[0]) / det
            X = (feet[0][0] + s1 * u1[0], feet[0][1] + s1 * u1[1])
            labels += angle_mark(X, u1, u2, MARK_R * 1.5, "ψ")
        else:
            labels += angle_mark(C, _unit(C, B1), _unit(C, B2), MARK_R * 1.5, "ψ")
        back = (2 * A[0] - B1[0], 2 * A[1] - B1[1])
        items.append(Segment(A, back, "construction", dashed=True))
        labels += angle_mark(A, _unit(A, back), _unit(A, B2), min(MARK_R, 0.8 * r), "θ")
        items += [FixedPivot(A), FixedPivot(C), Hinge(B1), Hinge(B2)]
        names = [(A, sub["A"]), (C, sub["C"]), (B1, sub["B"] + "₁"), (B2, sub["B"] + "₂")]
    for at, text in names:
        labels.append(Label(text, at, (_unit(at, A),) if at != A else (), LETTER))
    return items + labels


#: The notes of the characteristics panel in the three notations (graphmech.drawing.notation's
#: shape); a template's {0}, {1} … take the numbers.
NOTES: Mapping[str, tuple[str, str, str]] = {
    "crank_rocker_AB": ("crank-rocker (AB the crank)", "曲柄摇杆机构（AB为曲柄）", "кривошипно-коромысловый (AB — кривошип)"),
    "crank_rocker_CD": ("crank-rocker (CD turns fully)", "曲柄摇杆机构（CD整周转动）",
                        "кривошипно-коромысловый (CD вращается полностью)"),
    "double_crank": ("double crank", "双曲柄机构", "двухкривошипный"),
    "double_rocker": ("double rocker", "双摇杆机构", "двухкоромысловый"),
    "change_point": ("change point (s + l = p + q)", "临界状态（s + l = p + q）", "переходный (s + l = p + q)"),
    "crank": ("the crank turns fully", "曲柄整周转动", "кривошип вращается полностью"),
    "no extremes": ("{0}: the output turns fully, no extreme positions", "{0}：从动件整周转动，无极限位置",
                    "{0}: выходное звено вращается полностью, крайних положений нет"),
    "gamma": ("{0} = {1}° at φ = {2}°", "{0} = {1}°（φ = {2}°）", "{0} = {1}° при φ = {2}°"),
    "drawn": ("{0} (drawn)", "{0}（图示）", "{0} (на чертеже)"),
    "dashed": ("{0} (B′C′, dashed)", "{0}（B′C′，虚线）", "{0} (B′C′, штриховая)"),
    "working begins": ("{0}; position 1 (bold): the working stroke begins", "{0}；位置1（粗线）：工作行程开始",
                       "{0}; положение 1 (жирно): начало рабочего хода"),
    "guide bar": ("γ = 90° throughout: the block drives the bar at right angles", "γ恒为90°：滑块始终垂直推动导杆",
                  "γ = 90° всё время: камень давит на кулису под прямым углом"),
    "timing": ("working stroke {0}° in {1} s, return {2}° in {3} s: a turn in {4} s, n = {5} r/min",
               "工作行程{0}°用时{1} s，回程{2}°用时{3} s：每转{4} s，n = {5} r/min",
               "рабочий ход {0}° за {1} с, холостой {2}° за {3} с: оборот за {4} с, n = {5} об/мин"),
}


def _characteristics_notes(an: Any, notation: str = "en") -> tuple[str, ...]:
    dr = an.drawn

    def say(key: str, *args: object) -> str:
        return word(key, notation, NOTES).format(*args) if key in NOTES else key

    out = [scale_text("l", dr.mu_l)]
    kind = say(dr.grashof)
    gamma = say("gamma", GAMMA_MIN, number(math.degrees(dr.gamma_min)), number(math.degrees(dr.gamma_min_at)))
    if dr.theta is None:
        return tuple(out + [say("no extremes", kind), say("drawn", gamma)])
    out.append(say("working begins", kind))
    line = f"θ = {number(math.degrees(dr.theta))}°"
    if dr.psi is not None:
        line += f", ψ = {number(math.degrees(dr.psi))}°"
    if dr.stroke_mm is not None:
        line += f", H = {number(dr.stroke_mm)} mm = {number(dr.stroke_mm * dr.mu_l)} m"
    k = (math.pi + dr.theta) / (math.pi - dr.theta)
    line += f", K = (180° + θ)/(180° − θ) = {number(k)}"
    out.append(line)
    if dr.loop.kind == "guide_bar":  # centred: γ = 90° throughout; offset: γ_min with the crank at C (not drawn)
        out.append(say("guide bar") if dr.loop.b == 0.0 else gamma)
    else:
        out.append(say("dashed", gamma))
    t_work = an.scene.problem.characteristics.t_work
    if t_work is not None:
        work, back = math.pi + dr.theta, math.pi - dr.theta
        period = t_work * 2.0 * math.pi / work
        out.append(say("timing", number(math.degrees(work)), number(t_work), number(math.degrees(back)),
                       number(period - t_work), number(period), number(60.0 / period)))
    return tuple(out)


#: The classes' names on the ranges diagram.
CLASS_NAMES = {"crank_rocker_AB": "crank-rocker", "crank_rocker_CD": "crank-rocker (CD)", "double_crank": "double crank",
               "double_rocker": "double rocker", "change_point": "change point"}
#: The length of the ranges diagram's axis, mm (its scale a round number).
RANGES_MM = 150.0


def ranges_items(ranges: Sequence[tuple[str, float, float]], crank: str, length: float) -> tuple[list[Primitive], float]:
    """The Grashof ranges of the crank's length on one axis: each class a bold stretch (alternately solid
    and dashed) named above, the limits below; the crank's length in the scene marked. Returns the items and
    the axis's scale (m/mm)."""
    from graphmech.scales import round_scale

    limit = max(hi for _, _, hi in ranges)
    mu = round_scale(limit / RANGES_MM)
    end = limit / mu
    items: list[Primitive] = [Arrow((0.0, 0.0), (end + AXIS_OVERRUN, 0.0), "label")]
    labels: list[Primitive] = [Label(f"l_{{{crank}}}", (end + AXIS_OVERRUN, 0.0), ((-1.0, 0.0),), LETTER),
                               Label("0", (0.0, 0.0), _BELOW, LETTER, italic=False)]
    for k, (kind, lo, hi) in enumerate(ranges):
        x0, x1 = lo / mu, hi / mu
        items.append(Segment((x0, 3.0), (x1, 3.0), "result", dashed=bool(k % 2)))
        items += [Segment((x1, -1.0), (x1, 5.0), "label")]
        labels.append(Label(CLASS_NAMES.get(kind, kind), ((x0 + x1) / 2.0, 3.0), ((0.0, -1.0),), LETTER, italic=False))
        labels.append(Label(number(hi * 1000), (x1, 0.0), _BELOW, LETTER, italic=False))
    x = length / mu
    items.append(Circle((x, 0.0), 1.0, "result"))
    labels.append(Label(f"{crank} = {number(length * 1000)}", (x, -6.0), ((0.0, 1.0),), LETTER))
    return items + labels, mu


def _swing_note(an: Any) -> str:
    """``12 positions: 1 … 7 out, φ = −97.9° → 97.9° (its limits), 8 … 12 back``."""
    from graphmech.mechanisms.linkage import Crank

    cyc = an.cycle
    n, half = cyc.n, cyc.n // 2
    d = cyc.build.linkage.driver
    q0, q1 = float(cyc.angles[0]), float(cyc.angles[half])
    ends = (f"φ = {number(math.degrees(q0))}° → {number(math.degrees(q1))}°" if isinstance(d, Crank)
            else f"s = {number(q0 * 1000)} → {number(q1 * 1000)} mm")
    limits = " (its limits)" if an.scene.problem.cycle.between == "limits" else ""
    return f"{n} positions: 1 … {half + 1} out, {ends}{limits}, {half + 2} … {n} back"


# ----------------------------------------------------------------------------- the sheet
def cycle_sheet(title: str, an: Any, show: Sequence[str], page: tuple[float, float],
                footer: tuple[str, ...] = ()) -> Sheet:
    """The sheet of a full-cycle / characteristics scene: the panels of ``show`` in its order
    (``paths`` is drawn in the ``cycle`` panel, or alone when ``cycle`` is not shown)."""
    panels: list[Panel] = []
    cyc = an.cycle
    paths = an.scene.problem.cycle.paths if an.scene.problem.cycle is not None else ()
    notation = getattr(an.scene.page, "notation", "en")
    for entry in show:
        if entry == "characteristics":
            head = caption("extremes " + an.drawn.loop.kind, notation)
            panels.append(Panel("characteristics", head,
                                tuple(characteristics_items(an.drawn, an.scene.linkage)), _characteristics_notes(an, notation),
                                scales=(("l", an.drawn.mu_l),)))
            if an.ranges is not None:
                loop = an.drawn.loop
                crank = loop.names["A"] + loop.names["B"]
                items, mu = ranges_items(an.ranges, crank, loop.a)
                panels.append(Panel("ranges", caption("Grashof", notation).format(crank), tuple(items),
                                    (f"{number(mu * 1000)} mm of l_{{{crank}}} per mm",
                                     "s + l < p + q: the shortest link turns fully; = : change point"),
                                    scales=(("l", mu),)))
        elif entry == "cycle" or (entry == "paths" and "cycle" not in show):
            items = cycle_items(cyc, paths if "paths" in show else ())
            notes = [scale_text("l", an.scales["l"]), _swing_note(an) if cyc.swing else f"{cyc.n} positions, 1 at φ = "
                     f"{number(math.degrees(float(cyc.angles[0])))}°" + (" (an extreme position)"
                                                                         if an.scene.problem.cycle.start == "extreme" else "")]
            if _which(cyc.n):
                notes.append(_which(cyc.n) + "; the paths through all")
            head = caption("all positions", notation)
            if "paths" in show:
                head = caption("paths of", notation).format(head, ", ".join(paths))
            panels.append(Panel("cycle", head, tuple(items), tuple(notes), scales=(("l", an.scales["l"]),)))
        elif entry in ("velocity", "acceleration"):
            key = "v" if entry == "velocity" else "a"
            notes = [scale_text(key, an.scales[key])] + ([_which(cyc.n)] if _which(cyc.n) else [])
            if cyc.polygon_failures:
                gone = sorted(cyc.polygon_failures)
                notes.append("no polygon at position" + ("s " if len(gone) > 1 else " ")
                             + ", ".join(str(i + 1) for i in gone[:12]) + (" …" if len(gone) > 12 else "")
                             + ": two of its lines are parallel there" + (" (the swing's ends: the driver stops)"
                                                                           if cyc.swing else ""))
            head = caption(entry + " polygons, common pole", notation)
            panels.append(Panel(entry, head, tuple(polygons_items(cyc, entry)), tuple(notes),
                                scales=((key, an.scales[key]),)))
        elif entry == "diagrams":
            period = 2.0 * math.pi / cyc.mu_phi
            for dg in cyc.diagrams:
                curves = ("ψ–φ, ω–φ, ε–φ" if dg.kind == "link" else "s–φ, v–φ, a^{τ}–φ" if dg.kind == "path"
                          else "s–φ, v–φ, a–φ")
                head = caption("diagrams " + dg.kind, notation).format(curves, dg.subject)
                panels.append(Panel(f"diagrams-{dg.subject}", head, tuple(diagram_items(dg, cyc.n, period)),
                                    _diagram_notes(dg, cyc.mu_phi), scales=_diagram_scales(dg, cyc.mu_phi)))
    return Sheet(title, tuple(panels), (page[0], page[1]), tuple(footer))
