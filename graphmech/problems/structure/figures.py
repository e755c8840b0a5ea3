"""The structure sheet: the mechanism's kinematic sketch (机构运动简图) with its Assur groups
outlined, the book's block diagram (组合方框图) of how the groups attach to the drivers and the
frame, and — for a book's printed counts — a table of n, p_l, p_h (p′, F′) and F under the formula.

Links are drawn between the pairs they carry: a binary link as a bar, a link of three or more
pairs as a filled plate (the book's hatched or shaded triangle) with its number inside, a
redundant link (虚约束: the Jacobian finds p′ > 0 and no group takes the link) dashed; revolutes as
hinges (on the frame: pivots), prismatic pairs as slider blocks on their guides, higher pairs as
a contact point with its common normal. Each Assur group is outlined by a dashed contour and
labelled with its class. Every caption and note is in the scene's notation (en, zh, ru).
"""
from __future__ import annotations

import dataclasses
import math
import textwrap
from typing import Any, Sequence

from graphmech.drawing.lettering import LETTER, point_name, scale_text, text_box_size
from graphmech.drawing.notation import WORDS as COMMON, word
from graphmech.mechanisms.topology import Mobility, Structure, Topology, roman
from graphmech.drawing.primitives import (Arrow, Circle, FixedPivot, GuideLine, Hinge, Label, Panel, Plate, Polyline,
                                         Primitive, Segment, Sheet, Slider, Text)
from graphmech.render.layout import panel_bbox
from graphmech.scales import round_scale

#: How far a group's outline stands off its links, mm.
OUTLINE_MM = 7.0
BOX_W, BOX_H, BOX_GAP = 34.0, 14.0, 12.0
#: The least width a block diagram's chain goes to before it wraps into rows, mm.
BLOCK_WIDTH = 150.0
#: The longest line of a note under the block diagram, characters (about 2 mm each: A4's 277 mm).
NOTE_CHARS = 100
#: Every text of the sheet, mm (the issue's least body text).
TEXT = LETTER
#: A table's row height and the free room either side of a cell's text, mm.
ROW, CELL_PAD = 7.5, 2.5
#: A number column's least width, mm.
NUMBER_COL = 12.0

#: The structure sheet's words (graphmech.drawing.notation's shape): key → (English, 中文, русский);
#: ``{}`` are filled in.
WORDS: dict[str, tuple[str, str, str]] = {
    "structure": COMMON["structure"],
    "groups": ("Structure: drivers and Assur groups", "机构的组成：原动件与基本杆组",
               "строение механизма: начальные звенья и группы Ассура"),
    "cases": ("Mobility from the printed counts", "由题给数据计算自由度", "подвижность по заданным числам"),
    "class": ("a class {} mechanism", "{}级机构", "механизм {} класса"),
    "replaced": ("higher pairs replaced by a link and two revolutes: {}", "高副低代：{}",
                 "высшие пары заменены звеном с двумя шарнирами: {}"),
    "removed": ("rollers (local freedoms) left out: {}", "局部自由度（滚子）除去：{}",
                "местные подвижности (ролики) исключены: {}"),
    "compound": ("compound hinges (k − 1 pairs each): {}", "复合铰链（各计 k − 1 个转动副）：{}",
                 "сложные шарниры (k − 1 пар каждый): {}"),
    "rank": ("rank J = {} of {}: F = 3·{} − {} − {} = {}", "rank J = {}（{} 个约束方程）：F = 3·{} − {} − {} = {}",
             "rank J = {} из {}: F = 3·{} − {} − {} = {}"),
    "redundant": ("redundant links (dashed, p′ = {}) left out of the groups: {}",
                  "虚约束构件（虚线，p′ = {}）不计入杆组：{}",
                  "звенья избыточных связей (штриховые, p′ = {}) в группы не входят: {}"),
    "no group": ("links {} form no Assur group: the number of drivers differs from the mobility",
                 "构件 {} 不能组成基本杆组：原动件数与自由度不等",
                 "звенья {} не образуют группы Ассура: число начальных звеньев не равно подвижности"),
    "special": ("class {} group ({}): its velocity and acceleration polygons need a special construction "
                "(Assur's special points, or a false-position polygon)",
                "{}级杆组（{}）：速度、加速度多边形须用特殊作图法（特殊点法或试凑法）",
                "группа {} класса ({}): планы скоростей и ускорений строятся особым способом "
                "(особые точки Ассура или метод ложных положений)"),
    "case": ("case", "机构", "схема"),
    "rigid": ("rigid", "桁架", "ферма"),
}


def _say(key: str, notation: str, *args: object) -> str:
    return word(key, notation, WORDS).format(*args)


def choose_scale(topo: Topology, room: tuple[float, float]) -> float:
    pts = [p.at for p in topo.pairs if p.at is not None]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    need = max((max(xs) - min(xs)) / room[0], (max(ys) - min(ys)) / room[1], 1e-12)
    return round_scale(need)


def _away(c: tuple[float, float], others: Sequence[tuple[float, float]]) -> tuple[tuple[float, float], ...]:
    """Unit directions from ``c`` to each of ``others`` (the lines leaving a pair)."""
    out = []
    for q in others:
        d = math.dist(c, q)
        if d > 1e-9:
            out.append(((q[0] - c[0]) / d, (q[1] - c[1]) / d))
    return tuple(out)


def _inradius(ps: Sequence[tuple[float, float]]) -> float:
    """2·area / perimeter of a convex polygon: the room inside it for a number, mm."""
    n = len(ps)
    area = 0.5 * abs(sum(ps[k][0] * ps[(k + 1) % n][1] - ps[(k + 1) % n][0] * ps[k][1] for k in range(n)))
    perimeter = sum(math.dist(ps[k], ps[(k + 1) % n]) for k in range(n))
    return 2.0 * area / perimeter if perimeter > 0 else 0.0


def mechanism_panel(topo: Topology, st: Structure | None, mu: float, notes: Sequence[str],
                    redundant: Sequence[str] = (), notation: str = "en") -> Panel:
    """The kinematic sketch at μl, the groups outlined; the ``redundant`` links dashed."""
    pts = [p.at for p in topo.pairs if p.at is not None]
    ox, oy = pts[0]

    def mm(xy: tuple[float, float]) -> tuple[float, float]:
        return ((xy[0] - ox) / mu, (xy[1] - oy) / mu)

    items: list[Primitive] = []
    labels: list[Primitive] = []
    where: dict[str, list[tuple[float, float]]] = {x: [] for x in topo.links}
    for p in topo.pairs:
        assert p.at is not None
        for x in p.links:
            if x in where and mm(p.at) not in where[x]:
                where[x].append(mm(p.at))
    rollers = set(topo.rollers())
    for x, ps in where.items():  # each link through its pairs; a roller as its circle
        dashed = x in redundant
        if x in rollers and len(ps) == 2:
            pin = next(mm(p.at) for p in topo.pairs_of(x) if p.kind == "R" and p.at is not None)
            contact = next(q for q in ps if q != pin)
            items.append(Circle(pin, math.dist(pin, contact), "given", dashed=dashed))
            labels.append(Label(x, pin, _away(pin, [contact]), TEXT, italic=False))
            continue
        hull = _hull(ps) if len(ps) > 2 else list(ps)
        if len(hull) == 2:
            items.append(Segment(hull[0], hull[1], "given", dashed=dashed))
        elif len(hull) > 2 and dashed:
            items.append(Polyline(tuple(hull), "given", closed=True, dashed=True))
        if not ps:
            continue
        cx, cy = sum(q[0] for q in ps) / len(ps), sum(q[1] for q in ps) / len(ps)
        if len(hull) == 2 and len(ps) > 2:  # a bar through a middle pair: beside its longest piece
            a, b = hull
            along = sorted(ps, key=lambda q: (q[0] - a[0]) * (b[0] - a[0]) + (q[1] - a[1]) * (b[1] - a[1]))
            p0, p1 = max(zip(along[:-1], along[1:]), key=lambda pq: math.dist(*pq))
            cx, cy = (p0[0] + p1[0]) / 2.0, (p0[1] + p1[1]) / 2.0
        inside = len(hull) > 2 and not dashed and _inradius(hull) >= 0.75 * max(text_box_size(x, TEXT))
        if len(hull) > 2 and not dashed:  # the plate, its number inside it as the book writes it
            items.append(Plate(tuple(hull), number=x if inside else "", number_at=(cx, cy), number_size=TEXT))
        if not inside:  # a bar's number beside its middle, off the bar
            labels.append(Label(x, (cx, cy), _away((cx, cy), hull if len(hull) == 2 else ()), TEXT, italic=False))
    for p in topo.pairs:
        assert p.at is not None
        c = mm(p.at)
        others = [q for x in p.links if x != topo.frame and x in where for q in where[x] if q != c]
        avoid = list(_away(c, others))
        if p.kind == "R":
            items.append(FixedPivot(c) if topo.frame in p.links else Hinge(c))
            if topo.frame in p.links:
                avoid.append((0.0, -1.0))  # the pivot's base below it
        elif p.kind == "P":
            ang = p.angle or 0.0
            u = (math.cos(ang), math.sin(ang))
            if topo.frame in p.links:
                items.append(GuideLine((c[0] - 14 * u[0], c[1] - 14 * u[1]), (c[0] + 14 * u[0], c[1] + 14 * u[1])))
            else:
                items.append(Segment((c[0] - 12 * u[0], c[1] - 12 * u[1]), (c[0] + 12 * u[0], c[1] + 12 * u[1]), "given"))
            items.append(Slider(c, ang))
            avoid += [u, (-u[0], -u[1])]
        else:
            ang = p.angle or 0.0
            n = (math.cos(ang), math.sin(ang))
            items.append(Segment((c[0] - 8 * n[0], c[1] - 8 * n[1]), (c[0] + 8 * n[0], c[1] + 8 * n[1]),
                                 "construction", dashed=True))
            items.append(Circle(c, 1.0, "result"))
            avoid += [n, (-n[0], -n[1])]
        if p.name:
            labels.append(Label(point_name(p.name), c, tuple(avoid), TEXT))
    if st is not None:
        for g in st.groups:
            ps = [q for x in g.links if x in where for q in where[x]]
            if not ps:
                continue
            outline = _outline(ps, OUTLINE_MM)
            items.append(Polyline(tuple(outline), "construction", closed=True, dashed=True))
            top = max(outline, key=lambda q: (q[1], q[0]))
            labels.append(Label(f"{roman(g.grade)} ({','.join(g.links)})", top, ((0.0, -1.0),), TEXT, italic=False))
        items, moved = _numbers_clear_of_outlines(items)
        labels += moved
    return Panel("structure", word("structure", notation, WORDS), tuple(items + labels),
                 (scale_text("l", mu),) + tuple(notes), scales=(("l", mu),))


def block_panel(st: Structure, topo: Topology, notation: str = "en", redundant: int = 0,
                width: float = math.inf) -> Panel:
    """The block diagram: frame and drivers (class I), then each group, joined by arrows; each
    box's inscription set in its middle; a chain wider than ``width`` mm goes on in rows below,
    the arrow turning down to the next row's first box. ``redundant``: the Jacobian's p′, which
    names the links no group takes as redundant ones."""
    items: list[Primitive] = []
    boxes = [f"I: {topo.frame} + {', '.join(st.drivers) or '—'}"]
    boxes += [f"{roman(g.grade)}: {', '.join(g.links)}" for g in st.groups]
    x, y = 0.0, 0.0
    last: tuple[float, float, float] | None = None  # the box before: left, right, bottom
    for k, text in enumerate(boxes):
        w = max(BOX_W, text_box_size(text, TEXT)[0] + 2.0 * CELL_PAD)
        if k and x + w > width + 1e-9 and last is not None:  # on in the next row
            x, y = 0.0, y - BOX_H - BOX_GAP
            mid_y = y + BOX_H + BOX_GAP / 2.0
            start = ((last[0] + last[1]) / 2.0, last[2])
            items.append(Polyline((start, (start[0], mid_y), (x + w / 2.0, mid_y)), "given"))
            items.append(Arrow((x + w / 2.0, mid_y), (x + w / 2.0, y + BOX_H), "given"))
        elif k:
            items.append(Arrow((x - BOX_GAP, y + BOX_H / 2), (x, y + BOX_H / 2), "given"))
        corners = ((x, y), (x + w, y), (x + w, y + BOX_H), (x, y + BOX_H))
        items.append(Polyline(corners, "given", closed=True))
        items.append(Text(text, (x + w / 2, y + BOX_H / 2), TEXT))
        last = (x, x + w, y)
        x += w + BOX_GAP
    notes = [_say("class", notation, roman(st.grade))]
    if st.replaced:
        notes.append(_say("replaced", notation, ", ".join(map(point_name, st.replaced))))
    if st.removed:
        notes.append(_say("removed", notation, ", ".join(st.removed)))
    said = [_say("special", notation, roman(g.grade), ", ".join(g.links)) for g in st.groups if g.grade >= 3]
    if st.leftover:
        said.append(_say("redundant", notation, redundant, ", ".join(st.leftover)) if redundant
                    else _say("no group", notation, ", ".join(st.leftover)))
    width = NOTE_CHARS if notation != "zh" else NOTE_CHARS // 2  # a CJK character is twice as wide
    for message in said:  # a long message in lines that fit the page
        notes += textwrap.wrap(message, width)
    return Panel("groups", word("groups", notation, WORDS), tuple(items), tuple(notes))


def cases_panel(cases: Sequence[dict[str, Any]], notation: str = "en") -> Panel:
    """A book's printed counts as a table — case, n, p_l, p_h (p′, F′ where a case has them), F —
    under the formula they go into, drawn with lines and text set in its cells."""
    has_pr = any(c["p_redundant"] for c in cases)
    has_fl = any(c["F_local"] for c in cases)
    rigid = any(c["F"] <= 0 for c in cases)
    if has_pr or has_fl:
        formula = "F = 3n − (2p_{l} + p_{h}" + (" − p′" if has_pr else "") + ")" + (" − F′" if has_fl else "")
    else:
        formula = "F = 3n − 2p_{l} − p_{h}"
    head = [word("case", notation, WORDS), "n", "p_{l}", "p_{h}"] + (["p′"] if has_pr else []) \
        + (["F′"] if has_fl else []) + ["F"] + ([""] if rigid else [])
    keys = ["label", "n", "pl", "ph"] + (["p_redundant"] if has_pr else []) + (["F_local"] if has_fl else []) + ["F"]
    rows = []
    for c in cases:
        # a case's label is the scene's name for it; drawn as words, its "_" as spaces
        row = [str(c["label"]).replace("_", " ")] + [str(c[k]).replace("-", "−") for k in keys[1:]]
        rows.append(row + ([word("rigid", notation, WORDS) if c["F"] <= 0 else ""] if rigid else []))
    widths = [max(text_box_size(r[j], TEXT)[0] for r in [head] + rows) + 2.0 * CELL_PAD for j in range(len(head))]
    widths = [w if j == 0 or (rigid and j == len(head) - 1) else max(w, NUMBER_COL) for j, w in enumerate(widths)]
    xs = [0.0]
    for w in widths:
        xs.append(xs[-1] + w)
    width, depth = xs[-1], ROW * (len(rows) + 1)
    items: list[Primitive] = [Text(formula, (width / 2.0, ROW * 0.9), TEXT, italic=True)]
    # the frame and the rule under the head bold, the other rules thin
    items += [Polyline(((0.0, 0.0), (width, 0.0), (width, -depth), (0.0, -depth)), "given", closed=True),
              Segment((0.0, -ROW), (width, -ROW), "given")]
    items += [Segment((0.0, -ROW * k), (width, -ROW * k), "construction") for k in range(2, len(rows) + 1)]
    items += [Segment((x, 0.0), (x, -depth), "construction") for x in xs[1:-1]]
    for k, row in enumerate([head] + rows):
        y = -ROW * (k + 0.5)
        for j, text in enumerate(row):
            if not text:
                continue
            if j == 0:  # names from the left, numbers in the middle of their column
                items.append(Text(text, (xs[0] + CELL_PAD, y), TEXT, "start"))
            else:  # the head's symbols italic, as the formula's
                items.append(Text(text, ((xs[j] + xs[j + 1]) / 2.0, y), TEXT, italic=k == 0 and j < len(keys)))
    return Panel("cases", word("cases", notation, WORDS), tuple(items))


def structure_sheet(title: str, an: Any, page: tuple[float, float], footer: tuple[str, ...] = (),
                    notation: str = "en") -> Sheet:
    """The whole structure sheet of a checked structure scene, lettered in ``notation``."""
    from graphmech.problems.structure.check import formula

    panels: list[Panel] = []
    if an.cases:
        panels.append(cases_panel(an.cases, notation))
    ss = an.scene.problem
    m: Mobility | None = an.mobility
    if ss.topology is not None and m is not None:
        notes = [formula(m)]
        if m.compound:
            notes.append(_say("compound", notation, ", ".join(map(point_name, m.compound))))
        if m.rank is not None:
            notes.append(_say("rank", notation, m.rank, m.equations, m.n, m.rank, m.F_local, m.F_actual))
        st: Structure | None = an.structure
        p_red = int(m.p_redundant_actual or 0)
        redundant = tuple(st.leftover) if st is not None and p_red > 0 else ()
        if ss.geometry:
            room = (page[0] * 0.6, max(page[1] - 125.0, 40.0))  # less title, notes, the block diagram
            mu = an.scales.get("l") or choose_scale(ss.topology, room)
            an.scales["l"] = mu
            panels.append(mechanism_panel(ss.topology, st, mu, notes, redundant, notation))
        if st is not None:  # as wide as the sketch (150 mm at least), the chain in rows beyond
            box = panel_bbox(panels[-1]) if ss.geometry else (0.0, 0.0, 0.0, 0.0)
            sketch = box[2] - box[0]
            panels.append(block_panel(st, ss.topology, notation, p_red, max(sketch, BLOCK_WIDTH)))
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


def _numbers_clear_of_outlines(items: list[Primitive]) -> tuple[list[Primitive], list[Label]]:
    """A plate's number that an Assur group's outline crosses leaves the plate: the plate keeps
    no number and the number becomes a label, placed clear of every stroke."""
    from shapely.geometry import LineString, box

    outlines = [LineString(i.points + i.points[:1]) for i in items if isinstance(i, Polyline) and i.role == "construction"]
    out: list[Primitive] = []
    moved: list[Label] = []
    for i in items:
        if isinstance(i, Plate) and i.number and i.number_at is not None:
            w, h = text_box_size(i.number, i.number_size)
            (x, y), pad = i.number_at, 0.5
            cell = box(x - w / 2 - pad, y - h / 2 - pad, x + w / 2 + pad, y + h / 2 + pad)
            if any(o.intersects(cell) for o in outlines):
                out.append(dataclasses.replace(i, number=""))
                moved.append(Label(i.number, i.number_at, (), i.number_size, italic=False))
                continue
        out.append(i)
    return out, moved


def _outline(ps: list[tuple[float, float]], off: float) -> list[tuple[float, float]]:
    """A rounded contour ``off`` mm around the points (shapely's buffer of their hull)."""
    from shapely.geometry import MultiPoint

    shape = MultiPoint(ps).convex_hull.buffer(off, quad_segs=4)
    return [(round(x, 6), round(y, 6)) for x, y in list(shape.exterior.coords)[:-1]]


__all__ = ["WORDS", "block_panel", "cases_panel", "choose_scale", "mechanism_panel", "structure_sheet"]
