"""The figures of the kinematics methods: a construction's solution → draw primitives on panels.

Methods produce primitives with roles; a renderer turns them into SVG and knows nothing of
linkages. 
The kinematic diagram is drawn in the textbook's symbols from the linkage's structure
(frame pivots hatched, hinges, slider blocks on hatched guides, links as lines); the polygons
are drawn from the construction's own steps: points with their image letters, vectors as
arrows, construction lines as thin segments through the points they carry.
"""
from __future__ import annotations

import math
from dataclasses import replace
from typing import Any, Mapping, Sequence

from graphmech.mechanisms.linkage import (PRP, Crank, Guide, Linkage, LinkGuide, LinkPoint, RPP, RPR, RRP, RRR,
                                          SliderInput, Triad)
from graphmech.drawing.notation import WORDS, word
from graphmech.methods.diagram import tangent_name
from graphmech.methods.velocity import assur_name
from graphmech.drawing.primitives import (XY, ArcArrow, Arrow, FixedPivot, GuideLine, Hinge, Label, Panel, Plate,
                                         Primitive, Role, Segment, Sheet, Slider, angle_mark)
from graphmech.drawing.lettering import LETTER, point_name, scale_text, subscript

#: The kinematics sheets' captions in the three notations (graphmech.drawing.notation's shape);
#: a template's {0}, {1} take a position, a link or a point.
LINKAGE_WORDS: Mapping[str, tuple[str, str, str]] = {
    **WORDS,
    "polygon of links": ("Polygon of links", "瞬心多边形", "многоугольник звеньев"),
    "by Kennedy": ("solid: direct, dashed: by Kennedy", "实线：直接观察，虚线：三心定理",
                   "сплошные — непосредственно, штриховые — по теореме Кеннеди"),
    "undetermined": ("undetermined", "不能确定", "не определены"),
    "all positions": ("Kinematic diagram at all positions", "各位置机构运动简图", "кинематическая схема во всех положениях"),
    "paths of": ("{0}, paths of {1}", "{0}，{1}点轨迹", "{0}, траектории {1}"),
    "velocity polygons, common pole": ("Velocity polygons of all positions, common pole", "各位置速度多边形（共用极点）",
                                       "планы скоростей всех положений с общим полюсом"),
    "acceleration polygons, common pole": ("Acceleration polygons of all positions, common pole",
                                           "各位置加速度多边形（共用极点）",
                                           "планы ускорений всех положений с общим полюсом"),
    "extremes fourbar": ("Extreme positions, θ, ψ and γ_{min}", "极限位置、极位夹角θ、摆角ψ与γ_{min}",
                         "крайние положения, θ, ψ и γ_{min}"),
    "extremes slider_crank": ("Extreme positions, θ, H and γ_{min}", "极限位置、极位夹角θ、行程H与γ_{min}",
                              "крайние положения, θ, H и γ_{min}"),
    "extremes guide_bar": ("Extreme positions, θ and ψ", "极限位置、极位夹角θ与摆角ψ", "крайние положения, θ и ψ"),
    "Grashof": ("Grashof's rule: the classes as l_{{{0}}} grows (mm)", "格拉斯霍夫条件：l_{{{0}}}变化时的机构类型 (mm)",
                "условие Грасгофа: тип механизма в зависимости от l_{{{0}}} (мм)"),
    "diagrams link": ("{0} of link {1}, by chords", "构件{1}的{0}线图（弦线法）", "{0} звена {1} (метод хорд)"),
    "diagrams point": ("{0} of slider {1}, by chords", "滑块{1}的{0}线图（弦线法）", "{0} ползуна {1} (метод хорд)"),
    "diagrams path": ("{0} of point {1}, by chords", "{1}点的{0}线图（弦线法）", "{0} точки {1} (метод хорд)"),
    "zero velocity": ("v_{{{0}}} = 0", "v_{{{0}}} = 0", "v_{{{0}}} = 0"),
}

#: The panels' captions, by panel.
TITLES = {"mechanism": "kinematic diagram", "velocity": "velocity polygon", "acceleration": "acceleration polygon"}
SCALE_OF = {"mechanism": "l", "velocity": "v", "acceleration": "a"}

#: How far a construction line runs past the outermost point it carries, mm.
LINE_OVERRUN = 6.0
#: A guide stops this far (mm, along it) short of a frame pivot on its line, so its hatching
#: never runs through the pivot's symbol (its ground line is 4.8 mm either side).
PIVOT_CLEAR = 7.0
#: The marks of the other positions in one panel: B′, B″, B‴, then B₄, B₅ …
PRIMES = ("′", "″", "‴")


def caption(key: str, notation: str = "en") -> str:
    """A caption of the kinematics sheets in ``notation`` (``LINKAGE_WORDS``)."""
    return word(key, notation, LINKAGE_WORDS)


def prime(k: int) -> str:
    """The mark of the k-th other position (1-based): ′, ″, ‴, then a subscript number."""
    return PRIMES[k - 1] if 1 <= k <= len(PRIMES) else subscript(str(k + 1))


def display(label: str) -> str:
    """Image letters as the book prints them: c2' → c₂′, p' → p′."""
    return subscript(label).replace("'", "′")


def _pt(v: Any) -> tuple[float, float]:
    return (float(v[0]), float(v[1]))


def drawn_points(build: Any, values: Mapping[str, Any]) -> dict[str, tuple[float, float]]:
    """The kinematic diagram's points as solved (drawing mm), by point name."""
    return {name: _pt(values[slot]) for name, slot in build.mech.items() if slot in values}


def _unit(a: tuple[float, float], b: tuple[float, float]) -> tuple[float, float]:
    dx, dy = b[0] - a[0], b[1] - a[1]
    n = math.hypot(dx, dy)
    return (dx / n, dy / n) if n > 0 else (0.0, 0.0)


def _dirs(ds: Any) -> tuple[tuple[float, float], ...]:
    """Directions for a label to avoid; a zero-length line has none."""
    return tuple(d for d in ds if d != (0.0, 0.0))


def _hull(points: Sequence[XY]) -> list[XY]:
    """The convex hull of ``points``, counter-clockwise (monotone chain).

    >>> _hull([(0, 0), (2, 0), (1, 1), (1, 0.2)])
    [(0, 0), (2, 0), (1, 1)]
    """
    pts = sorted(set(points))
    if len(pts) < 3:
        return list(pts)

    def cross(o: XY, a: XY, b: XY) -> float:
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower: list[XY] = []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    upper: list[XY] = []
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def _gap(x: float, y: float) -> float:
    return abs((x - y + math.pi) % math.tau - math.pi)


def sense_mark(centre: XY, r: float, busy: Sequence[float], value: float, text: str, role: Role = "result",
               first: float | None = None, ground: bool = False) -> list[Primitive]:
    """The sense of an angular velocity or acceleration: a curved arrow of 75° about ``centre``
    (CCW for a positive ``value``), clear of the lines leaving it at the angles ``busy`` (and
    of the ground below a frame pivot), lettered ``text`` (ω_{2}, ε_{3}) at its middle.
    ``first``: the angle to try first (the side of the link it stands on)."""
    sweep = math.copysign(math.radians(75.0), value)
    start = first if first is not None else (busy[0] if busy else 0.0) + math.pi / 2

    def clear(mid: float) -> bool:
        return all(_gap(mid, b) >= math.radians(62.0) for b in busy) and (
            not ground or _gap(mid, -math.pi / 2) >= math.radians(85.0))

    mids = [start + math.radians(k * 15.0 * sign) for k in range(0, 13) for sign in ((1, -1) if k else (1,))]
    mid_angle = next((m for m in mids if clear(m)), start)
    arc = ArcArrow(centre, r, mid_angle - sweep / 2, sweep, role)
    mid = arc.points(2)[1]
    return [arc, Label(text, mid, (_unit(mid, centre),), LETTER)]


def mechanism_items(build: Any, pos: dict[str, tuple[float, float]],
                    guide_span: dict[int, tuple[float, float]] | None = None,
                    senses: Mapping[str, tuple[float | None, float | None]] | None = None,
                    mark: str | None = None) -> list[Primitive]:
    """The kinematic diagram at one position; ``pos`` maps point names to drawing mm.

    ``senses``: link → (ω, ε) found by the construction (None: not found), drawn as curved
    arrows on the link. ``mark``: this is another position of a panel that already holds one
    (an extreme position, the γ_min position): its links thin dashed, its moving points
    lettered with the mark (B′, C′), no frame, link numbers or senses.
    """
    linkage: Linkage = build.linkage
    mu_l = build.mu_l
    other = mark is not None
    items: list[Primitive] = []
    lines: dict[str, list[tuple[float, float]]] = {}  # point → directions of lines leaving it
    hinges: list[str] = []
    fixed: list[str] = []

    numbers: list[Primitive] = []
    done: set[str] = set()
    coincident = {n for y in linkage.dyads if isinstance(y, (RPR, RPP, PRP, RRP)) for n in y.coincident}
    # a link with three or more joints not on one line is a plate (a ternary link's triangle)
    sliding = {y.bar_link for y in linkage.dyads if isinstance(y, RPR)} | \
              {y.links[0] for y in linkage.dyads if isinstance(y, RPP)}
    plates: dict[str, list[XY]] = {}
    for lid, names in linkage.links().items():
        at = [pos[n] for n in dict.fromkeys(names) if n in pos and n not in coincident]
        hull = _hull(at)
        if lid not in sliding and len(hull) >= 3 and lid != linkage.frame_link:
            area = 0.5 * abs(sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(hull, hull[1:] + hull[:1])))
            if area > 0.5 * max(math.dist(a, b) for a in hull for b in hull):  # not a sliver: ≥ 1 mm thick
                plates[lid] = hull

    def number(lid: str | None, at: tuple[float, float], along: tuple[float, float] | None = (1.0, 0.0)) -> None:
        """The link's number, upright, as the book writes it beside the link (once per link)."""
        if lid is not None and lid not in done and not other:
            done.add(lid)
            avoid = _dirs((along, (-along[0], -along[1]))) if along is not None else ()
            numbers.append(Label(lid, at, avoid, LETTER, italic=False))

    def link(a: str, b: str, lid: str | None = None) -> None:
        if a in pos and b in pos and pos[a] != pos[b]:
            u = _unit(pos[a], pos[b])
            lines.setdefault(a, []).append(u)
            lines.setdefault(b, []).append(_unit(pos[b], pos[a]))
            if lid in plates:
                return  # drawn as its plate
            items.append(Segment(pos[a], pos[b], "construction", dashed=True) if other else Segment(pos[a], pos[b], "given"))
            number(lid, ((pos[a][0] + pos[b][0]) / 2, (pos[a][1] + pos[b][1]) / 2), u)

    def guide(key: int, g: Any, at: str, where: XY | None = None) -> None:
        gx, gy = g.direction
        ox, oy = build.to_drawing(g.through)
        lo, hi = (guide_span or {}).get(key, (0.0, 0.0))
        here = pos[at] if where is None else where
        s = (here[0] - ox) * gx + (here[1] - oy) * gy
        lo, hi = min(lo, s) - 12.0, max(hi, s) + 12.0
        nx, ny = gy, -gx  # the side GuideLine hatches (right of its direction)
        near: tuple[float, float] | None = None
        for f in linkage.frame_points:
            if f not in pos:
                continue
            t = (pos[f][0] - ox) * gx + (pos[f][1] - oy) * gy
            d = (pos[f][0] - ox) * nx + (pos[f][1] - oy) * ny
            if abs(d) < PIVOT_CLEAR and lo - PIVOT_CLEAR < t < hi + PIVOT_CLEAR:
                # a frame pivot on (or by) the guide's line: the guide stops short of it
                if t <= s:
                    lo = max(lo, min(t + PIVOT_CLEAR, s - 6.0))
                else:
                    hi = min(hi, max(t - PIVOT_CLEAR, s + 6.0))
            if abs(d) > 0.5 and (near is None or abs(d) < abs(near[0])):
                near = (d, t)
        p0, p1 = (ox + lo * gx, oy + lo * gy), (ox + hi * gx, oy + hi * gy)
        # the hatching on the fixed side, away from the nearest frame pivot (the crank's)
        items.append(GuideLine(p1, p0) if near is not None and near[0] > 0 else GuideLine(p0, p1))
        lines.setdefault(at, []).extend([(gx, gy), (-gx, -gy)])

    def slider(at: str, angle: float) -> None:
        items.append(Slider(pos[at], angle))

    d = linkage.driver
    if isinstance(d, Crank):
        link(d.pivot, d.tip, d.link)
        a, t = pos[d.pivot], pos[d.tip]
        phi = math.atan2(t[1] - a[1], t[0] - a[0])
        r = min(7.0, 0.45 * math.dist(a, t)) if a != t else 7.0
        if d.omega != 0.0 and not other:  # the driver's sense: a curved arrow about its pivot, as books draw ω₁
            numbers += sense_mark(a, r, [phi], d.omega, f"ω_{{{d.link}}}", "given", phi + math.radians(75.0), True)
        if d.epsilon != 0.0 and not other:
            numbers += sense_mark(a, r + 4.0, [phi], d.epsilon, f"ε_{{{d.link}}}", "given", phi - math.radians(75.0),
                                  True)
        fixed.append(d.pivot)
        hinges.append(d.tip)
    else:
        if not other:
            guide(-1, d.guide, d.point)
        slider(d.point, d.guide.angle)
        number(d.link, pos[d.point], d.guide.direction)
    for k, y in enumerate(linkage.dyads):
        if isinstance(y, RRR):
            link(y.p, y.c, y.links[0])
            link(y.q, y.c, y.links[1])
            hinges += [y.p, y.c, y.q]
        elif isinstance(y, RRP):
            link(y.p, y.c, y.links[0])
            hinges += [y.p, y.c]
            g = y.guide
            if isinstance(g, LinkGuide):  # the pin C's block in the slotted link's line
                if y.c in pos:
                    _block_on_link(g, y.links[1], pos[y.c], y.c, pos, items, lines, number, other)
                continue
            if not other:
                guide(k, g, y.c)
            slider(y.c, g.angle)
            number(y.links[1], pos[y.c], g.direction)
        elif isinstance(y, RPR):
            bp, x = pos[y.bar_pivot], pos[y.block_pivot]
            foot = pos.get(tangent_name(y)) if y.offset != 0.0 else None
            if foot is not None and foot != bp:  # an offset guide bar: its arm OF ⟂ its line F→X
                items.append(Segment(bp, foot, "construction", dashed=True) if other else Segment(bp, foot, "given"))
                lines.setdefault(y.bar_pivot, []).append(_unit(bp, foot))
                bp = foot
            u = _unit(bp, x)
            reach = math.dist(bp, x) + 12.0
            for pt in linkage.points:  # the bar runs past every point fixed on it
                if pt.link == y.bar_link and pt.name in pos:
                    reach = max(reach, (pos[pt.name][0] - bp[0]) * u[0] + (pos[pt.name][1] - bp[1]) * u[1] + 6.0)
            end = (bp[0] + reach * u[0], bp[1] + reach * u[1])
            items.append(Segment(bp, end, "construction", dashed=True) if other else Segment(bp, end, "given"))
            if bp == pos[y.bar_pivot]:  # the line leaves the pivot (an offset bar's arm is noted above)
                lines.setdefault(y.bar_pivot, []).append(u)
            lines.setdefault(y.block_pivot, []).extend([u, (-u[0], -u[1])])
            items.append(Slider(x, math.atan2(u[1], u[0])))
            hinges += [y.p, y.q]
            number(y.bar_link, ((bp[0] + x[0]) / 2, (bp[1] + x[1]) / 2), u)
            number(y.block_link, x, u)
        elif isinstance(y, RPP):
            sx, sy = math.cos(y.slot_angle), math.sin(y.slot_angle)
            c, p = pos[y.c], pos[y.p]
            t_c = (p[0] - c[0]) * sx + (p[1] - c[1]) * sy
            t_end = t_c + (10.0 if t_c >= 0 else -10.0)
            tip = (c[0] + t_end * sx, c[1] + t_end * sy)
            items.append(Segment(c, tip, "construction", dashed=True) if other else Segment(c, tip, "given"))
            if not other:
                guide(k, y.guide, y.c)
            items.append(Slider(c, y.guide.angle))
            items.append(Slider(p, y.slot_angle, 6.0, 4.0))
            number(y.links[0], p, (sx, sy))
            number(y.links[1], c, y.guide.direction)
            lines.setdefault(y.p, []).extend([(sx, sy), (-sx, -sy)])
            hinges.append(y.p)
        elif isinstance(y, PRP) and y.c in pos:
            _prp_items(y, k, pos, items, lines, guide, number, other)
            hinges.append(y.c)
        elif isinstance(y, Triad):
            for n in range(3):
                on = y.guides[n]
                if on is not None:  # a block on a frame guide (the piston)
                    if not other:
                        guide(k, on, y.inner[n])
                    slider(y.inner[n], on.angle)
                    number(y.links[n], pos[y.inner[n]], on.direction)
                    continue
                link(y.outer[n], y.inner[n], y.links[n])
            for m0, m1 in ((0, 1), (1, 2), (2, 0)):
                link(y.inner[m0], y.inner[m1], y.links[3])
            hinges += [*y.outer, *y.inner]
            s_at = pos.get(assur_name(y))
            if s_at is not None and not other:  # Assur's point S: the two binary links extended to it
                for n in y.assur:
                    items.append(Segment(pos[y.inner[n]], s_at, "construction", dashed=True))
                items.append(Label("S", s_at, (_unit(s_at, pos[y.inner[y.assur[0]]]),
                                               _unit(s_at, pos[y.inner[y.assur[1]]])), LETTER))
    for pt in linkage.points:
        if pt.name not in pos:
            continue
        if pt.link in plates:
            for other_name in linkage.links()[pt.link]:
                if other_name in pos and other_name != pt.name:
                    lines.setdefault(pt.name, []).append(_unit(pos[pt.name], pos[other_name]))
        elif len(pt.base) == 2 and pt.left != 0.0 and pt.base[0] in pos:
            u = _unit(pos[pt.base[0]], pos[pt.base[1]])
            a = pt.along / mu_l
            foot = (pos[pt.base[0]][0] + a * u[0], pos[pt.base[0]][1] + a * u[1])
            items.append(Segment(foot, pos[pt.name], "construction", dashed=True) if other
                         else Segment(foot, pos[pt.name], "given"))
            lines.setdefault(pt.name, []).append(_unit(pos[pt.name], foot))
        elif len(pt.base) == 2:
            link(pt.base[0], pt.name)
    for lid, hull in plates.items():
        if other:
            items += [Segment(a, b, "construction", dashed=True) for a, b in zip(hull, hull[1:] + hull[:1])]
        else:
            items.append(Plate(tuple(hull)))
            cx, cy = sum(p[0] for p in hull) / len(hull), sum(p[1] for p in hull) / len(hull)
            number(lid, (cx, cy), None)
    if not other:
        for name in dict.fromkeys(fixed + [n for n in hinges if n in linkage.frame_points]):
            items.append(FixedPivot(pos[name]))
    for name in dict.fromkeys(hinges):
        if name not in linkage.frame_points and name in pos:
            items.append(Hinge(pos[name]))
    if not other:
        numbers += _sense_marks(linkage, pos, senses or {}, lines)
    for name in dict.fromkeys(list(linkage.frame_points) + [n for n in pos if n[:1].isupper()]):
        if name not in pos or name in coincident:  # C2, C3 stand where C is: one letter
            continue
        if other and name in linkage.frame_points:
            continue  # the frame is drawn once, with its letters
        items.append(Label(point_name(name) + (mark or ""), pos[name], _dirs(lines.get(name, ())), LETTER))
    return items + numbers


def _block_on_link(g: LinkGuide, block: str, c: XY, name: str, pos: dict[str, XY], items: list[Primitive],
                   lines: dict[str, list[XY]], number: Any, other: bool) -> None:
    """A block at c sliding on a moving link's line through two of its points: the line drawn on to
    c where c lies beyond them (a slotted bar), and the block along it."""
    u0, u1 = pos.get(g.through), pos.get(g.towards)
    if u0 is None or u1 is None or u0 == u1:
        return
    u = _unit(u0, u1)
    reach = (c[0] - u0[0]) * u[0] + (c[1] - u0[1]) * u[1]
    far = math.dist(u0, u1)
    if reach > far or reach < 0.0:  # the bar runs on past C, as a slotted bar does
        end = reach + (8.0 if reach > far else -8.0)
        tip = (u0[0] + end * u[0], u0[1] + end * u[1])
        start = u1 if reach > far else u0
        items.append(Segment(start, tip, "construction", dashed=True) if other else Segment(start, tip, "given"))
    items.append(Slider(c, math.atan2(u[1], u[0])))
    lines.setdefault(name, []).extend([u, (-u[0], -u[1])])
    number(block, c, u)


def _prp_items(y: PRP, k: int, pos: dict[str, XY], items: list[Primitive], lines: dict[str, list[XY]],
               guide: Any, number: Any, other: bool) -> None:
    """A PRP dyad on the diagram: the block on a link's guide is a slider on that link's line (the
    line drawn on to C); the block on a frame guide is a rod from C along the guide to its slider."""
    c = pos[y.c]
    for block, g in zip(y.links, y.guides):
        if isinstance(g, LinkGuide):
            _block_on_link(g, block, c, y.c, pos, items, lines, number, other)
        else:
            gx, gy = g.direction
            # the rod runs away from the other guide's pivot, so it stays clear of the bar
            other_g = y.guides[1] if g is y.guides[0] else y.guides[0]
            base = pos.get(other_g.through) if isinstance(other_g, LinkGuide) else None
            sense = 1.0 if base is None or (c[0] - base[0]) * gx + (c[1] - base[1]) * gy >= 0.0 else -1.0
            at = (c[0] + sense * 14.0 * gx, c[1] + sense * 14.0 * gy)
            items.append(Segment(c, at, "construction", dashed=True) if other else Segment(c, at, "given"))
            if not other:
                guide(k, g, y.c, at)
            items.append(Slider(at, g.angle))
            lines.setdefault(y.c, []).append((sense * gx, sense * gy))
            number(block, at, (gx, gy))


def _sense_marks(linkage: Linkage, pos: dict[str, XY], senses: Mapping[str, tuple[float | None, float | None]],
                 lines: dict[str, list[XY]]) -> list[Primitive]:
    """ω and ε of each link as found: about its frame pivot (a rocker) or at the middle of the
    link on either side (a coupler)."""
    out: list[Primitive] = []
    driver = linkage.driver.link
    for lid, names in linkage.links().items():
        omega, eps = senses.get(lid, (None, None))
        if lid == driver or (omega is None and eps is None):
            continue
        at = [n for n in dict.fromkeys(names) if n in pos]
        if len(at) < 2:
            continue
        pivot = next((n for n in at if n in linkage.frame_points), None)
        if pivot is not None:
            far = max(at, key=lambda n: math.dist(pos[n], pos[pivot]))
            length = math.dist(pos[far], pos[pivot])
            if length <= 0.0:
                continue
            phi = math.atan2(pos[far][1] - pos[pivot][1], pos[far][0] - pos[pivot][0])
            busy = [math.atan2(u[1], u[0]) for u in lines.get(pivot, [])] or [phi]
            r = min(7.0, 0.45 * length)
            if omega is not None:
                out += sense_mark(pos[pivot], r, busy, omega, f"ω_{{{lid}}}", first=phi + math.radians(75.0), ground=True)
            if eps is not None:
                out += sense_mark(pos[pivot], r + 4.0, busy, eps, f"ε_{{{lid}}}", first=phi - math.radians(75.0),
                                  ground=True)
            continue
        a, b = max(((p, q) for p in at for q in at), key=lambda pq: math.dist(pos[pq[0]], pos[pq[1]]))
        length = math.dist(pos[a], pos[b])
        if length <= 0.0:
            continue
        mid = ((pos[a][0] + pos[b][0]) / 2, (pos[a][1] + pos[b][1]) / 2)
        phi = math.atan2(pos[b][1] - pos[a][1], pos[b][0] - pos[a][0])
        r = min(6.0, 0.3 * length)
        busy = [phi, phi + math.pi]
        # a plate's marks stand outside it, off the side its other joints are not on
        side = sum((pos[n][0] - mid[0]) * -math.sin(phi) + (pos[n][1] - mid[1]) * math.cos(phi) for n in at)
        if abs(side) > 1.0:
            out_angle = phi - math.pi / 2 if side > 0 else phi + math.pi / 2
            if omega is not None:
                out += sense_mark(mid, r, busy, omega, f"ω_{{{lid}}}", first=out_angle)
            if eps is not None:
                out += sense_mark(mid, r + 4.0, busy, eps, f"ε_{{{lid}}}", first=out_angle)
            continue
        if omega is not None:
            out += sense_mark(mid, r, busy, omega, f"ω_{{{lid}}}", first=phi + math.pi / 2)
        if eps is not None:
            out += sense_mark(mid, r, busy, eps, f"ε_{{{lid}}}", first=phi - math.pi / 2)
    return out


#: The push F and the velocity v at an output joint, drawn this long (mm); the arcs of α and γ.
TRANSMISSION_ARROW_MM = 20.0
TRANSMISSION_ARC_MM = (11.0, 15.0)


def transmission_marks(linkage: Linkage, pos: dict[str, XY], spec: tuple[Any, ...]) -> list[Primitive]:
    """α and γ at an output joint X as the book marks them (001 2-3): the push F along the coupler
    (⟂ the bar for a guide bar), the velocity v_X of the output's point, α between them and γ
    between F and the normal to v_X (the rocker's line). ``spec``: a γ quantity's exact spec
    without its kind (:func:`graphmech.methods.polygons.add_transmission_angles`)."""
    if spec[0] == "bar":  # v of the bar's point under the block's pivot: v_B3
        _, x, pivot, link = spec
        name = x + link
        bar = next(y for y in linkage.dyads if isinstance(y, RPR) and y.block_pivot == x)
        start = pos.get(tangent_name(bar), pos[pivot]) if bar.offset != 0.0 else pos[pivot]
        line = _unit(start, pos[x])
        f = (-line[1], line[0])
        arm = _unit(pos[pivot], pos[x])
        u = (-arm[1], arm[0])
    else:
        x, pusher, along = spec
        name = x
        f = _unit(pos[pusher], pos[x])
        if isinstance(along, str):
            arm = _unit(pos[along], pos[x])
            u = (-arm[1], arm[0])
        else:
            u = (float(along[0]), float(along[1]))
    if f == (0.0, 0.0) or u == (0.0, 0.0):
        return []
    if f[0] * u[0] + f[1] * u[1] < 0.0:  # α is the acute angle: v taken along the push
        u = (-u[0], -u[1])
    n = (-u[1], u[0]) if -u[1] * f[0] + u[0] * f[1] >= 0.0 else (u[1], -u[0])
    X = pos[x]
    L = TRANSMISSION_ARROW_MM

    def tip(d: XY) -> XY:
        return (X[0] + L * d[0], X[1] + L * d[1])

    items: list[Primitive] = [Arrow(X, tip(f), "result"), Arrow(X, tip(u), "result"),
                              Segment(X, tip(n), "construction", dashed=True),
                              Label("F", tip(f), (f,), LETTER), Label(f"v_{{{name}}}", tip(u), (u,), LETTER)]
    items += angle_mark(X, u, f, TRANSMISSION_ARC_MM[0], "α")
    items += angle_mark(X, f, n, TRANSMISSION_ARC_MM[1], "γ")
    return items


def direction_mark(pole: XY, image: XY) -> list[Primitive]:
    """The direction of a polygon's vector pole→image as the book states it: a thin reference line
    along +x from the pole and the arc of the smaller angle to the vector, lettered in degrees."""
    u = _unit(pole, image)
    if u == (0.0, 0.0):
        return []
    L = TRANSMISSION_ARROW_MM
    angle = math.degrees(math.atan2(u[1], u[0]))
    items: list[Primitive] = [Segment(pole, (pole[0] + L, pole[1]), "construction", dashed=True)]
    arc = angle_mark(pole, (1.0, 0.0), u, TRANSMISSION_ARC_MM[0], f"{abs(angle):.4g}°")
    return items + [replace(p, italic=False) if isinstance(p, Label) else p for p in arc]  # a number: upright


def polygon_items(plan: Any, values: dict[str, Any], panel: str) -> list[Primitive]:
    """A polygon panel: construction lines, vectors, image letters, from the construction's steps."""
    items: list[Primitive] = []
    labels: dict[tuple[float, float], Label] = {}
    leaving: dict[str, list[tuple[float, float]]] = {}
    for s in plan.steps:
        if s.panel != panel or s.role == "hidden":
            continue
        if s.kind == "line":
            px, py, dx, dy = (float(v) for v in values[s.name])
            ts = [(float(values[p][0]) - px) * dx + (float(values[p][1]) - py) * dy
                  for p in plan.extent.get(s.name, []) if p in values]
            lo, hi = (min(ts + [0.0]) - LINE_OVERRUN, max(ts + [0.0]) + LINE_OVERRUN)
            items.append(Segment((px + lo * dx, py + lo * dy), (px + hi * dx, py + hi * dy), "construction"))
        elif s.kind in ("vector", "segment"):
            a, b = _pt(values[s.inputs[0]]), _pt(values[s.inputs[1]])
            if math.dist(a, b) > 1e-9:
                items.append(Arrow(a, b, s.role) if s.kind == "vector" else Segment(a, b, s.role))
                leaving.setdefault(s.inputs[0], []).append(_unit(a, b))
                leaving.setdefault(s.inputs[1], []).append(_unit(b, a))
    for s in plan.steps:  # the Coriolis side is named as the book names it, a^k, at its middle
        if s.panel == panel and s.kind == "point" and s.say[:1] == ("coriolis",):
            a, b = _pt(values[s.inputs[0]]), _pt(values[s.name])
            if math.dist(a, b) > 1e-9:
                u = _unit(a, b)
                items.append(Label("a^{k}", ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2), (u, (-u[0], -u[1]))))
    for s in plan.steps:
        if s.panel == panel and s.kind == "point" and s.label and s.role != "hidden":
            at = _pt(values[s.name])
            key = (round(at[0], 6), round(at[1], 6))
            if key in labels:  # coincident images (c = p at a dead centre) share one label
                old = labels[key]
                labels[key] = Label(old.text + "," + display(s.label), at, old.avoid)
            else:
                labels[key] = Label(display(s.label), at, _dirs(leaving.get(s.name, ())))
    return items + list(labels.values())


def linkage_sheet(title: str, linkage: Linkage, build: Any, plan: Any, solutions: Sequence[Any],
                  labels: Sequence[str], position_text: Sequence[str], scales: dict[str, float],
                  show: Sequence[str], page: tuple[float, float], footer: tuple[str, ...] = (),
                  notation: str = "en",
                  senses: Sequence[Mapping[str, tuple[float | None, float | None]]] | None = None,
                  marks: Mapping[str, Sequence[Sequence[Primitive]]] | None = None) -> Sheet:
    """The whole sheet: for each position, the panels the scene shows, side by side.

    ``senses``: per position, each link's ω and ε as the construction found them, drawn on the
    mechanism (:func:`mechanism_items`); ``marks``: per panel, per position, more marks (α and γ
    on the mechanism, a direction's angle on a polygon)."""
    panels: list[Panel] = []
    spans = guide_spans(linkage, build, solutions)
    for i, sol in enumerate(solutions):
        if sol is None:
            continue
        for panel in show:
            key = SCALE_OF[panel]
            note = (scale_text(key, scales[key]),)
            if panel == "mechanism":
                pos = drawn_points(build, sol.values)
                items = mechanism_items(build, pos, spans, senses[i] if senses else None)
                head = f"{caption(TITLES[panel], notation)}, {position_text[i]}"
            else:
                items = polygon_items(plan, sol.values, panel)
                head = caption(TITLES[panel], notation) + (f", {position_text[i]}" if len(solutions) > 1 else "")
            items += list(marks[panel][i]) if marks and panel in marks else []
            panels.append(Panel(f"{panel}-{labels[i]}", head, tuple(items), note, row=i,
                                scales=((key, scales[key]),)))
    return Sheet(title, tuple(panels), page, footer)


def guide_spans(linkage: Linkage, build: Any, solutions: Sequence[Any]) -> dict[int, tuple[float, float]]:
    """The stretch of each guide its slider covers over the drawn positions (mm along the guide)."""
    spans: dict[int, tuple[float, float]] = {}
    guides = [(-1, linkage.driver.guide, linkage.driver.point)] if isinstance(linkage.driver, SliderInput) else []
    guides += [(k, y.guide, y.c) for k, y in enumerate(linkage.dyads)
               if isinstance(y, (RRP, RPP)) and isinstance(y.guide, Guide)]
    for k, g, point in guides:
        gx, gy = g.direction
        ox, oy = build.to_drawing(g.through)
        ss = [(float(sol.values[build.mech[point]][0]) - ox) * gx + (float(sol.values[build.mech[point]][1]) - oy) * gy
              for sol in solutions if sol is not None and build.mech.get(point) in sol.values]
        if ss:
            spans[k] = (min(ss), max(ss))
    return spans


__all__ = ["linkage_sheet", "mechanism_items", "polygon_items", "display", "caption", "sense_mark",
           "prime", "LINKAGE_WORDS", "LinkPoint"]
