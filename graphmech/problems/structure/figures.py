"""The structure sheet: the mechanism's links and pairs with its Assur groups outlined, and the
book's block diagram (组合方框图) of how the groups attach to the drivers and the frame.

Links are drawn between the pairs they carry (a ternary link as a shaded-free triangle of its
three pairs), revolutes as hinges (on the frame: pivots), prismatic pairs as slider blocks on
their guides, higher pairs as a contact point with its common normal. Each Assur group is
outlined by a dashed contour around its links and labelled with its class; a class III group's
label says that its polygons need a special construction.
"""
from __future__ import annotations

import math
import textwrap
from typing import Any, Sequence

from graphmech.mechanisms.topology import Mobility, Structure, Topology, roman
from graphmech.drawing.primitives import (Arrow, Circle, FixedPivot, GuideLine, Hinge, Label, Panel, Polyline,
                                         Primitive, Segment, Sheet, Slider)
from graphmech.scales import format_scale, round_scale

#: How far a group's outline stands off its links, mm.
OUTLINE_MM = 7.0
BOX_W, BOX_H, BOX_GAP = 34.0, 14.0, 12.0
#: The longest line of a note under the block diagram, characters (about 2 mm each: A4's 277 mm).
NOTE_CHARS = 100


def choose_scale(topo: Topology, room: tuple[float, float]) -> float:
    pts = [p.at for p in topo.pairs if p.at is not None]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    need = max((max(xs) - min(xs)) / room[0], (max(ys) - min(ys)) / room[1], 1e-12)
    return round_scale(need)


def mechanism_panel(topo: Topology, st: Structure | None, mu: float, notes: Sequence[str]) -> Panel:
    """The links and pairs at μl, the groups outlined."""
    pts = [p.at for p in topo.pairs if p.at is not None]
    ox, oy = pts[0]

    def mm(xy: tuple[float, float]) -> tuple[float, float]:
        return ((xy[0] - ox) / mu, (xy[1] - oy) / mu)

    items: list[Primitive] = []
    where: dict[str, list[tuple[float, float]]] = {x: [] for x in topo.links}
    for p in topo.pairs:
        assert p.at is not None
        for x in p.links:
            if x in where and mm(p.at) not in where[x]:
                where[x].append(mm(p.at))
    rollers = set(topo.rollers())
    for x, ps in where.items():  # each link through its pairs; a roller as its circle
        if x in rollers and len(ps) == 2:
            pin = next(mm(p.at) for p in topo.pairs_of(x) if p.kind == "R" and p.at is not None)
            contact = next(q for q in ps if q != pin)
            items.append(Circle(pin, math.dist(pin, contact), "given"))
        elif len(ps) == 2:
            items.append(Segment(ps[0], ps[1], "given"))
        elif len(ps) > 2:
            items.append(Polyline(tuple(_hull(ps)), "given", closed=True))
        if ps:
            cx, cy = sum(q[0] for q in ps) / len(ps), sum(q[1] for q in ps) / len(ps)
            items.append(Label(x, (cx, cy), (), 3.2, italic=False))
    for p in topo.pairs:
        assert p.at is not None
        c = mm(p.at)
        if p.kind == "R":
            items.append(FixedPivot(c) if topo.frame in p.links else Hinge(c))
        elif p.kind == "P":
            ang = p.angle or 0.0
            u = (math.cos(ang), math.sin(ang))
            if topo.frame in p.links:
                items.append(GuideLine((c[0] - 14 * u[0], c[1] - 14 * u[1]), (c[0] + 14 * u[0], c[1] + 14 * u[1])))
            else:
                items.append(Segment((c[0] - 12 * u[0], c[1] - 12 * u[1]), (c[0] + 12 * u[0], c[1] + 12 * u[1]), "given"))
            items.append(Slider(c, ang))
        else:
            ang = p.angle or 0.0
            n = (math.cos(ang), math.sin(ang))
            items.append(Segment((c[0] - 8 * n[0], c[1] - 8 * n[1]), (c[0] + 8 * n[0], c[1] + 8 * n[1]),
                                 "construction", dashed=True))
            items.append(Circle(c, 1.0, "result"))
        if p.name:
            items.append(Label(p.name, c, (), 3.2))
    if st is not None:
        for g in st.groups:
            ps = [q for x in g.links if x in where for q in where[x]]
            if not ps:
                continue
            outline = _outline(ps, OUTLINE_MM)
            items.append(Polyline(tuple(outline), "construction", closed=True, dashed=True))
            top = max(outline, key=lambda q: (q[1], q[0]))
            items.append(Label(f"{roman(g.grade)} ({','.join(g.links)})", top, ((0.0, -1.0),), 3.0, italic=False))
    return Panel("structure", "Kinematic diagram and Assur groups", tuple(items), (format_scale("l", mu),) + tuple(notes))


def block_panel(st: Structure, topo: Topology) -> Panel:
    """The block diagram: frame and drivers (class I), then each group, joined by arrows."""
    items: list[Primitive] = []
    boxes = [f"I: {topo.frame} + {', '.join(st.drivers) or '—'}"]
    boxes += [f"{roman(g.grade)}: {', '.join(g.links)}" for g in st.groups]
    x = 0.0
    for k, text in enumerate(boxes):
        corners = ((x, 0.0), (x + BOX_W, 0.0), (x + BOX_W, BOX_H), (x, BOX_H))
        items.append(Polyline(corners, "given", closed=True))
        items.append(Label(text, (x + BOX_W / 2, BOX_H / 2), (), 3.2, italic=False))
        if k:
            items.append(Arrow((x - BOX_GAP, BOX_H / 2), (x, BOX_H / 2), "given"))
        x += BOX_W + BOX_GAP
    notes = [f"a class {roman(st.grade)} mechanism"]
    if st.replaced:
        notes.append(f"higher pairs replaced by a link and two revolutes: {', '.join(st.replaced)}")
    if st.removed:
        notes.append(f"rollers (local freedoms) left out: {', '.join(st.removed)}")
    for message in st.messages:  # a class III group's message is long: lines that fit the page
        notes += textwrap.wrap(message, NOTE_CHARS)
    return Panel("groups", "Structure: drivers and Assur groups", tuple(items), tuple(notes))


def cases_panel(cases: Sequence[dict[str, Any]]) -> Panel:
    """A book's table of printed counts, one line a case."""
    from graphmech.problems.structure.check import case_formula

    items: list[Primitive] = []
    for k, c in enumerate(cases):
        text = f"{c['label']}:  " + case_formula(c)
        items.append(Label(text, (0.0, -8.0 * k), (), 3.5, italic=False))
    return Panel("cases", "Mobility F = 3n − (2pl + ph − p′) − F′", tuple(items))


def structure_sheet(title: str, an: Any, page: tuple[float, float], footer: tuple[str, ...] = ()) -> Sheet:
    """The whole structure sheet of a checked structure scene."""
    from graphmech.problems.structure.check import formula

    panels: list[Panel] = []
    if an.cases:
        panels.append(cases_panel(an.cases))
    ss = an.scene.problem
    m: Mobility | None = an.mobility
    if ss.topology is not None and m is not None:
        notes = [formula(m)]
        if m.compound:
            notes.append(f"compound hinges (k − 1 pairs each): {', '.join(m.compound)}")
        if m.rank is not None:
            notes.append(f"rank J = {m.rank} of {m.equations}: F = 3·{m.n} − {m.rank} − {m.F_local} = {m.F_actual}")
        if ss.geometry:
            room = (page[0] * 0.6, max(page[1] - 125.0, 40.0))  # less title, notes, the block diagram
            mu = an.scales.get("l") or choose_scale(ss.topology, room)
            an.scales["l"] = mu
            panels.append(mechanism_panel(ss.topology, an.structure, mu, notes))
        if an.structure is not None:
            panels.append(block_panel(an.structure, ss.topology))
            if not ss.geometry:
                panels[-1] = Panel(panels[-1].name, panels[-1].title, panels[-1].items, tuple(notes) + panels[-1].notes)
    return Sheet(title, tuple(panels), page, footer)


def _hull(ps: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """The convex hull of a link's pairs in shapely's order (clockwise with y up); pairs in one line: that line."""
    from shapely.geometry import MultiPoint, Polygon

    hull = MultiPoint(ps).convex_hull
    if not isinstance(hull, Polygon):  # pairs in one line: the line itself
        return [(float(x), float(y)) for x, y in hull.coords]
    return [(float(x), float(y)) for x, y in list(hull.exterior.coords)[:-1]]


def _outline(ps: list[tuple[float, float]], off: float) -> list[tuple[float, float]]:
    """A rounded contour ``off`` mm around the points (shapely's buffer of their hull)."""
    from shapely.geometry import MultiPoint

    shape = MultiPoint(ps).convex_hull.buffer(off, quad_segs=4)
    return [(round(x, 6), round(y, 6)) for x, y in list(shape.exterior.coords)[:-1]]


__all__ = ["block_panel", "cases_panel", "choose_scale", "mechanism_panel", "structure_sheet"]
