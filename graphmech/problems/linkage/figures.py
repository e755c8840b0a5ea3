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
from typing import Any, Sequence

from graphmech.mechanisms.linkage import Crank, Linkage, LinkPoint, RPP, RPR, RRP, RRR, SliderInput
from graphmech.drawing.primitives import (ArcArrow, Arrow, FixedPivot, GuideLine, Hinge, Label, Panel, Primitive,
                                         Segment, Sheet, Slider)
from graphmech.drawing.lettering import subscript
from graphmech.scales import format_scale

TITLES = {"mechanism": "Kinematic diagram", "velocity": "Velocity polygon", "acceleration": "Acceleration polygon"}
SCALE_OF = {"mechanism": "l", "velocity": "v", "acceleration": "a"}

#: How far a construction line runs past the outermost point it carries, mm.
LINE_OVERRUN = 6.0


def display(label: str) -> str:
    """Image letters as the book prints them: c2' → c₂′, p' → p′."""
    return subscript(label).replace("'", "′")


def _pt(v: Any) -> tuple[float, float]:
    return (float(v[0]), float(v[1]))


def _unit(a: tuple[float, float], b: tuple[float, float]) -> tuple[float, float]:
    dx, dy = b[0] - a[0], b[1] - a[1]
    n = math.hypot(dx, dy)
    return (dx / n, dy / n) if n > 0 else (0.0, 0.0)


def _dirs(ds: Any) -> tuple[tuple[float, float], ...]:
    """Directions for a label to avoid; a zero-length line has none."""
    return tuple(d for d in ds if d != (0.0, 0.0))


def mechanism_items(build: Any, pos: dict[str, tuple[float, float]],
                    guide_span: dict[int, tuple[float, float]] | None = None) -> list[Primitive]:
    """The kinematic diagram at one position; ``pos`` maps point names to drawing mm."""
    linkage: Linkage = build.linkage
    mu_l = build.mu_l
    items: list[Primitive] = []
    lines: dict[str, list[tuple[float, float]]] = {}  # point → directions of lines leaving it
    hinges: list[str] = []
    fixed: list[str] = []

    numbers: list[Label] = []
    coincident = {n for y in linkage.dyads if isinstance(y, (RPR, RPP)) for n in y.coincident}

    def number(lid: str | None, at: tuple[float, float], along: tuple[float, float] = (1.0, 0.0)) -> None:
        """The link's number, upright, as the book writes it beside the link (once per link)."""
        if lid is not None and lid not in {n.text for n in numbers}:
            numbers.append(Label(lid, at, _dirs((along, (-along[0], -along[1]))), 3.2, italic=False))

    def link(a: str, b: str, lid: str | None = None) -> None:
        if a in pos and b in pos and pos[a] != pos[b]:
            items.append(Segment(pos[a], pos[b], "given"))
            u = _unit(pos[a], pos[b])
            lines.setdefault(a, []).append(u)
            lines.setdefault(b, []).append(_unit(pos[b], pos[a]))
            number(lid, ((pos[a][0] + pos[b][0]) / 2, (pos[a][1] + pos[b][1]) / 2), u)

    def guide(key: int, g: Any, at: str) -> None:
        gx, gy = g.direction
        ox, oy = build.to_drawing(g.through)
        lo, hi = (guide_span or {}).get(key, (0.0, 0.0))
        s = (pos[at][0] - ox) * gx + (pos[at][1] - oy) * gy
        lo, hi = min(lo, s) - 12.0, max(hi, s) + 12.0
        # hatching below a horizontal guide, as books draw it
        p0, p1 = (ox + lo * gx, oy + lo * gy), (ox + hi * gx, oy + hi * gy)
        items.append(GuideLine(p0, p1))
        lines.setdefault(at, []).extend([(gx, gy), (-gx, -gy)])

    d = linkage.driver
    if isinstance(d, Crank):
        link(d.pivot, d.tip, d.link)
        if d.omega != 0.0:  # the driver's sense: a curved arrow about its pivot, as books draw ω₁
            a, t = pos[d.pivot], pos[d.tip]
            phi = math.atan2(t[1] - a[1], t[0] - a[0])
            sweep = math.copysign(math.radians(75.0), d.omega)
            r = min(7.0, 0.45 * math.dist(a, t)) if a != t else 7.0
            # centre the arc where it clears the crank and the ground hatching below the pivot
            def clear(mid: float) -> bool:
                def gap(x: float, y: float) -> float:
                    return abs((x - y + math.pi) % math.tau - math.pi)

                return gap(mid, phi) >= math.radians(75.0) and gap(mid, -math.pi / 2) >= math.radians(85.0)

            mids = [phi + math.radians(k * 15.0) for k in range(5, 20)]
            mid_angle = next((m for m in mids if clear(m)), phi + math.pi / 2)
            arc = ArcArrow(a, r, mid_angle - sweep / 2, sweep, "given")
            items.append(arc)
            mid = arc.points(2)[1]
            numbers.append(Label("ω" + subscript(d.link), mid, (), 3.2))
        fixed.append(d.pivot)
        hinges.append(d.tip)
    else:
        guide(-1, d.guide, d.point)
        items.append(Slider(pos[d.point], d.guide.angle))
        number(d.link, pos[d.point], d.guide.direction)
    for k, y in enumerate(linkage.dyads):
        if isinstance(y, RRR):
            link(y.p, y.c, y.links[0])
            link(y.q, y.c, y.links[1])
            hinges += [y.p, y.c, y.q]
        elif isinstance(y, RRP):
            link(y.p, y.c, y.links[0])
            hinges += [y.p, y.c]
            guide(k, y.guide, y.c)
            items.append(Slider(pos[y.c], y.guide.angle))
            number(y.links[1], pos[y.c], y.guide.direction)
        elif isinstance(y, RPR):
            bp, x = pos[y.bar_pivot], pos[y.block_pivot]
            u = _unit(bp, x)
            reach = math.dist(bp, x) + 12.0
            for pt in linkage.points:  # the bar runs past every point fixed on it
                if pt.link == y.bar_link and pt.name in pos:
                    reach = max(reach, (pos[pt.name][0] - bp[0]) * u[0] + (pos[pt.name][1] - bp[1]) * u[1] + 6.0)
            end = (bp[0] + reach * u[0], bp[1] + reach * u[1])
            items.append(Segment(bp, end, "given"))
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
            items.append(Segment(c, (c[0] + t_end * sx, c[1] + t_end * sy), "given"))
            guide(k, y.guide, y.c)
            items.append(Slider(c, y.guide.angle))
            items.append(Slider(p, y.slot_angle, 6.0, 4.0))
            number(y.links[0], p, (sx, sy))
            number(y.links[1], c, y.guide.direction)
            lines.setdefault(y.p, []).extend([(sx, sy), (-sx, -sy)])
            hinges.append(y.p)
    for pt in linkage.points:
        if pt.name not in pos:
            continue
        if len(pt.base) == 2 and pt.left != 0.0 and pt.base[0] in pos:
            u = _unit(pos[pt.base[0]], pos[pt.base[1]])
            a = pt.along / mu_l
            foot = (pos[pt.base[0]][0] + a * u[0], pos[pt.base[0]][1] + a * u[1])
            items.append(Segment(foot, pos[pt.name], "given"))
            lines.setdefault(pt.name, []).append(_unit(pos[pt.name], foot))
        elif len(pt.base) == 2:
            link(pt.base[0], pt.name)
    for name in dict.fromkeys(fixed + [n for n in hinges if n in linkage.frame_points]):
        items.append(FixedPivot(pos[name]))
    for name in dict.fromkeys(hinges):
        if name not in linkage.frame_points and name in pos:
            items.append(Hinge(pos[name]))
    for name in dict.fromkeys(list(linkage.frame_points) + [n for n in pos if n[:1].isupper()]):
        if name in pos and name not in coincident:  # C2, C3 stand where C is: one letter
            items.append(Label(name, pos[name], _dirs(lines.get(name, ()))))
    return items + numbers


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
                  show: Sequence[str], page: tuple[float, float], footer: tuple[str, ...] = ()) -> Sheet:
    """The whole sheet: for each position, the panels the scene shows, side by side."""
    panels: list[Panel] = []
    spans = guide_spans(linkage, build, solutions)
    for i, sol in enumerate(solutions):
        if sol is None:
            continue
        for panel in show:
            note = (format_scale(SCALE_OF[panel], scales[SCALE_OF[panel]]),)
            if panel == "mechanism":
                pos = {name: _pt(sol.values[slot]) for name, slot in build.mech.items() if slot in sol.values}
                items = mechanism_items(build, pos, spans)
                head = f"{TITLES[panel]}, {position_text[i]}"
            else:
                items = polygon_items(plan, sol.values, panel)
                head = TITLES[panel] + (f", {position_text[i]}" if len(solutions) > 1 else "")
            panels.append(Panel(f"{panel}-{labels[i]}", head, tuple(items), note, row=i))
    return Sheet(title, tuple(panels), page, footer)


def guide_spans(linkage: Linkage, build: Any, solutions: Sequence[Any]) -> dict[int, tuple[float, float]]:
    """The stretch of each guide its slider covers over the drawn positions (mm along the guide)."""
    spans: dict[int, tuple[float, float]] = {}
    guides = [(-1, linkage.driver.guide, linkage.driver.point)] if isinstance(linkage.driver, SliderInput) else []
    guides += [(k, y.guide, y.c) for k, y in enumerate(linkage.dyads) if isinstance(y, (RRP, RPP))]
    for k, g, point in guides:
        gx, gy = g.direction
        ox, oy = build.to_drawing(g.through)
        ss = [(float(sol.values[build.mech[point]][0]) - ox) * gx + (float(sol.values[build.mech[point]][1]) - oy) * gy
              for sol in solutions if sol is not None and build.mech.get(point) in sol.values]
        if ss:
            spans[k] = (min(ss), max(ss))
    return spans


__all__ = ["linkage_sheet", "mechanism_items", "polygon_items", "display", "LinkPoint"]
