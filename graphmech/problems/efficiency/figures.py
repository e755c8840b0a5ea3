"""The figures of an efficiency problem: the bodies with their forces, and the force polygons.

Methods produce primitives with roles; a renderer turns them into SVG. Forces in a polygon are
laid off at μF (N/mm); everything in a diagram is paper millimetres (directions true, lengths
not to a force scale).

diagram
    incline — the incline at α (hatched), the block on it, Q, F and the total reaction R turned
    from the normal (thin dashed) by φ against the velocity v;
    screw — the thread unrolled: the lead triangle π·d2 by L = n·P with ψ, and the nut as a
    block on it, pushed by the circumferential force F (horizontal), loaded by Q;
    wedge — guide 2 (horizontal), the face at γ, guide 1 at β, sliders 1 and 2, Q and F;
    chain — the machines as boxes in the order power flows, their η, the power between them;
    wedge_clamp — the wedge 3 between face 1 (workpiece 1, below) and face 2 (body 2, above) at
    α, F along face 1, the clamping force Q and R1 at their faces (each face's name and f);
    buffer — wedge 1 on guide 3, wedge 2 on guide 4, the face between them at α, P and Q.
polygon
    one panel per direction (forward: F drives; reverse: the load drives): the frictionless
    polygon thin and dashed (F0), the polygon with friction bold, every side an arrow named
    after its force; for the wedge the two sliders' triangles joined along R12.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Sequence, cast


from graphmech.drawing.diagrams import transformed
from graphmech.methods.efficiency import Direction, ForcePolygon, StageResult, Stroke
from graphmech.drawing.lettering import LETTER, number, point_name, scale_text
from graphmech.drawing.notation import word
from graphmech.drawing.primitives import (XY, Arrow, Circle, GuideLine, Label, Panel, Polyline, Primitive, Segment,
                                         Sheet, Slider)

if TYPE_CHECKING:
    from graphmech.problems.efficiency.scene import EfficiencyProblem, Stage

#: Length of a force arrow in a diagram (directions only), mm.
ARROW_MM = 16.0
#: Paper size of a diagram's main feature (the incline, the unrolled thread), mm.
DIAGRAM_MM = 70.0
#: The wedge's sketch, enlarged from its 48 mm layout to about the incline's size.
WEDGE_SCALE = 1.4
#: A diagram (not to a force scale) is enlarged to fill its share of the page, up to this factor.
MOST_ENLARGED = 3.0

#: The efficiency sheet's words (laid out as graphmech.drawing.notation.WORDS: English, 中文,
#: русский). Drawn text only.
EFF_WORDS: dict[str, tuple[str, str, str]] = {
    "forward": ("forward stroke: F drives", "正行程：F 为驱动力", "прямой ход: движет F"),
    "reverse": ("reverse stroke: the load drives", "反行程：载荷为驱动力", "обратный ход: движет нагрузка"),
    "force polygon": ("Force polygon", "力多边形", "План сил"),
    "screw": ("Screw thread unrolled", "螺纹展开", "Развёртка резьбы"),
    "incline": ("Inclined plane", "斜面", "Наклонная плоскость"),
    "wedge": ("Wedge", "楔形机构", "Клин"),
    "wedge_clamp": ("Wedge clamp", "楔形夹具", "Клиновой зажим"),
    "buffer": ("Wedge buffer", "楔块缓冲器", "Клиновой амортизатор"),
    "series": ("Machines in series", "串联机组", "Последовательное соединение машин"),
    "parallel": (" and in parallel", "与并联", " и параллельное"),
    "motor": ("motor", "电动机", "двигатель"),
    "load": ("load", "工作机", "нагрузка"),
    "self-locked": ("F ∥ R: no finite force — self-locked, η = 0", "F ∥ R：无有限驱动力——自锁，η = 0",
                    "F ∥ R: конечной силы нет — самоторможение, η = 0"),
}


def eff_word(key: str, notation: str = "en") -> str:
    """``key`` of :data:`EFF_WORDS` in ``notation``.

    >>> eff_word("force polygon", "ru"), eff_word("screw", "zh")
    ('План сил', '螺纹展开')
    """
    return word(key, notation, EFF_WORDS)


def _extent(items: Sequence[Primitive]) -> tuple[float, float]:
    """Width and height of the items' points, mm."""
    pts: list[XY] = []
    for i in items:
        if isinstance(i, (Segment, Arrow, GuideLine)):
            pts += [i.p0, i.p1]
        elif isinstance(i, Polyline):
            pts += list(i.points)
        elif isinstance(i, (Slider, Circle)):
            pts.append(i.center)
    xs, ys = [p[0] for p in pts] or [0.0], [p[1] for p in pts] or [0.0]
    return max(xs) - min(xs), max(ys) - min(ys)


def enlargement(items: Sequence[Primitive], room: tuple[float, float]) -> float:
    """How many times a diagram drawn to no force scale is enlarged to fill ``room`` (w, h mm):
    1 … MOST_ENLARGED.

    >>> enlargement([Segment((0.0, 0.0), (70.0, 3.0))], (180.0, 100.0))
    2.5714285714285716
    """
    w, h = _extent(items)
    k = min(room[0] / w if w > 0 else MOST_ENLARGED, room[1] / h if h > 0 else MOST_ENLARGED)
    return max(1.0, min(MOST_ENLARGED, k))


def _dir(angle: float) -> XY:
    return (math.cos(angle), math.sin(angle))


def _add(p: XY, d: XY, k: float = 1.0) -> XY:
    return (p[0] + k * d[0], p[1] + k * d[1])


def _mid(a: XY, b: XY) -> XY:
    return ((a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0)


def _unit(v: XY) -> XY:
    n = math.hypot(v[0], v[1]) or 1.0
    return (v[0] / n, v[1] / n)


def _angle_arc(center: XY, r: float, a0: float, a1: float, text: str) -> list[Primitive]:
    """An angle marked by a thin arc from direction a0 to a1 (rad) and its letter."""
    n = 12
    pts = tuple((center[0] + r * math.cos(a0 + (a1 - a0) * k / n), center[1] + r * math.sin(a0 + (a1 - a0) * k / n))
                for k in range(n + 1))
    mid = (a0 + a1) / 2.0
    return [Polyline(pts, "construction"),
            Label(text, (center[0] + (r + 3.0) * math.cos(mid), center[1] + (r + 3.0) * math.sin(mid)), (), LETTER)]


def _force_arrow(name: str, tip: XY, d: XY, length: float = ARROW_MM, at_tail: bool = False) -> list[Primitive]:
    """A force of direction d acting at ``tip`` (pushing: the arrow ends there), or starting there."""
    d = _unit(d)
    start, end = ((tip, _add(tip, d, length)) if at_tail else (_add(tip, d, -length), tip))
    far = end if at_tail else start
    return [Arrow(start, end, "given"), Label(point_name(name), far, ((d[0], d[1]), (-d[0], -d[1])), LETTER)]


# ---------------------------------------------------------------------------- diagrams


def _incline_diagram(alpha: float, phi: float, stroke: Stroke | None, push: str, names: tuple[str, str],
                     thread: tuple[str, str] | None = None) -> list[Primitive]:
    L = DIAGRAM_MM
    up = _dir(alpha)
    top = _add((0.0, 0.0), up, L)
    items: list[Primitive] = [GuideLine((0.0, 0.0), top), Segment((0.0, 0.0), (top[0], 0.0), "construction")]
    if thread is not None:  # the unrolled thread: base π·d2, height L, hypotenuse at ψ
        items += [Segment((top[0], 0.0), top, "construction"),
                  Label(thread[0], (top[0] * 0.3, -4.0), ((0.0, 1.0),), LETTER, italic=False),  # clear of Q
                  Label(thread[1], (top[0] + 4.0, top[1] / 2.0), ((-1.0, 0.0),), LETTER, italic=False)]
    items += _angle_arc((0.0, 0.0), 14.0, 0.0, alpha, "ψ" if thread else "α")
    normal = (-math.sin(alpha), math.cos(alpha))
    contact = _add((0.0, 0.0), up, 0.55 * L)
    centre = _add(contact, normal, 3.5)
    items.append(Slider(centre, alpha, 12.0, 7.0))
    items += _force_arrow("Q", _add(centre, (0.0, -1.0), 3.5), (0.0, -1.0), at_tail=True)
    f_dir = (1.0, 0.0) if push == "horizontal" else up
    items += _force_arrow(names[0], _add(centre, f_dir, -6.0), f_dir)
    if stroke is not None and stroke.velocities:
        v = stroke.velocities[0][1]
        items.append(Arrow(_add(centre, normal, 6.0), _add(_add(centre, normal, 6.0), _unit(v), 10.0), "construction"))
        items.append(Label("v", _add(_add(centre, normal, 6.0), _unit(v), 12.0), (), LETTER))
        t = _unit(v)
        c, s = math.cos(phi), math.sin(phi)
        r_dir = (normal[0] * c - t[0] * s, normal[1] * c - t[1] * s)
        items.append(Segment(_add(contact, normal, -10.0), _add(contact, normal, 22.0), "construction", dashed=True))
        items += _force_arrow(names[1], contact, r_dir, 20.0, at_tail=True)
        a_n = math.atan2(normal[1], normal[0])
        a_r = math.atan2(r_dir[1], r_dir[0])
        if abs(a_r - a_n) > 1e-9:
            items += _angle_arc(contact, 11.0, a_n, a_r, "φ_{v}" if thread else "φ")
    return items


def _wedge_diagram(gamma: float, beta: float, stroke: Stroke | None = None) -> list[Primitive]:
    """Slider 1, a wedge in the V between guide 1 (at β, frame below-left) and the face (at γ);
    slider 2 right of the face on the horizontal guide, Q pushing back on it; the total reactions
    of ``stroke`` (when given) at their contacts, each beside its dashed normal."""
    V = (0.0, 0.0)
    face = _dir(gamma)
    up_left = (-math.cos(beta), math.sin(beta))
    k = WEDGE_SCALE
    g1_end = _add(V, up_left, 48.0 * k)
    items: list[Primitive] = [GuideLine((-30.0 * k, 0.0), (55.0 * k, 0.0)), GuideLine(g1_end, V),
                              Segment(V, _add(V, face, 44.0 * k), "given")]
    h = 24.0 * k * math.sin(gamma)
    s2 = [V, (34.0 * k, 0.0), (34.0 * k, h), _add(V, face, 24.0 * k)]
    items.append(Polyline(tuple(s2), "given", closed=True))
    s1 = [_add(V, face, 6.0 * k), _add(V, face, 34.0 * k), _add(V, up_left, 34.0 * k), _add(V, up_left, 6.0 * k)]
    items.append(Polyline(tuple(s1), "given", closed=True))
    c1 = _mid(_mid(s1[0], s1[1]), _mid(s1[2], s1[3]))
    items += [Label("1", c1, (), LETTER, italic=False), Label("2", (22.0 * k, h / 2.0), (), LETTER, italic=False)]
    items += _force_arrow("Q", (34.0 * k, h / 2.0), (-1.0, 0.0))
    top_mid = _mid(s1[1], s1[2])
    items += _force_arrow("F", top_mid, (-up_left[0], -up_left[1]))
    items += _angle_arc(V, 9.0, 0.0, gamma, "γ")
    items += _angle_arc(V, 18.0, math.pi - beta, math.pi, "β")
    if stroke is not None:  # the total reactions of the first stroke drawn, each at its contact
        real = [poly for poly in stroke.polygons if not poly.ideal]
        sides = {f.name: f for poly in real for f in poly.forces}
        contacts = {"R32": ((27.0 * k, 0.0), (0.0, 1.0)),
                    "R12": (_add(V, face, 19.0 * k), (math.sin(gamma), -math.cos(gamma))),
                    "R31": (_add(V, up_left, 22.0 * k), (math.sin(beta), math.cos(beta)))}
        for name, (at, normal) in contacts.items():
            side = sides.get(name)
            if side is None or math.hypot(side.end[0] - side.start[0], side.end[1] - side.start[1]) == 0.0:
                continue
            d = _unit((side.end[0] - side.start[0], side.end[1] - side.start[1]))
            n = normal if d[0] * normal[0] + d[1] * normal[1] >= 0 else (-normal[0], -normal[1])
            items.append(Segment(_add(at, n, -5.0), _add(at, n, 15.0), "construction", dashed=True))
            items += _force_arrow(name, at, d, 13.0, at_tail=True)
    return items


def _side(stroke: Stroke | None, name: str) -> XY | None:
    """The direction of the friction polygon's side ``name`` (None when not drawn)."""
    for poly in (stroke.polygons if stroke is not None else ()):
        for f in poly.forces:
            if not poly.ideal and f.name == name and math.dist(f.start, f.end) > 0.0:
                return _unit((f.end[0] - f.start[0], f.end[1] - f.start[1]))
    return None


def _clamp_diagram(alpha: float, faces: Sequence[tuple[str, float]], stroke: Stroke | None) -> list[Primitive]:
    """The clamp's wedge 3: face 1 below (workpiece 1), face 2 above (body 2) meeting it at α."""
    L = DIAGRAM_MM / max(1.0, math.tan(alpha))  # a steep wedge shorter, so that it stays DIAGRAM_MM high
    tip, back = (L, 0.0), (0.0, 0.0)
    top = (0.0, L * math.tan(alpha))
    up_face = _dir(math.pi - alpha)  # along face 2 from the tip to the back; body 2 lies above it
    items: list[Primitive] = [GuideLine((-0.15 * L, 0.0), (1.15 * L, 0.0)),
                              GuideLine(_add(top, up_face, 0.15 * L), _add(tip, up_face, -0.15 * L)),
                              Polyline((back, tip, top), "given", closed=True)]
    items += [Label("3", (0.3 * L, 0.3 * top[1]), (), LETTER, italic=False),
              Label(f"1: {faces[0][0]}, f = {number(faces[0][1])}", (0.45 * L, -9.0), ((0.0, -1.0),), LETTER,
                    italic=False),
              Label(f"2: {faces[1][0]}, f = {number(faces[1][1])}",
                    _add(_mid(tip, top), (math.sin(alpha), math.cos(alpha)), 12.0),
                    ((math.sin(alpha), math.cos(alpha)),), LETTER, italic=False)]
    items += _angle_arc(tip, 16.0, math.pi - alpha, math.pi, "α")
    items += _force_arrow("F", (0.0, 0.4 * top[1]), (1.0, 0.0))
    q = _side(stroke, "Q") or (-math.sin(alpha), -math.cos(alpha))
    items += _force_arrow("Q", _mid(tip, top), q)
    r1 = _side(stroke, "R1")
    if r1 is not None:
        items += [Segment((0.65 * L, -6.0), (0.65 * L, 18.0), "construction", dashed=True)]
        items += _force_arrow("R1", (0.65 * L, 0.0), r1, at_tail=True)
    return items


def _buffer_diagram(alpha: float, stroke: Stroke | None) -> list[Primitive]:
    """Wedge 1 (above the face, on the vertical guide 3) and wedge 2 (below it, on guide 4)."""
    a = 0.5 * DIAGRAM_MM
    c, s = a * math.cos(alpha), a * math.sin(alpha)
    A, B, C, D = (-c, s), (c, -s), (c, s), (-c, -s)
    items: list[Primitive] = [GuideLine((c, -s - 6.0), (c, s + 14.0)), GuideLine((-c - 14.0, -s), (c + 6.0, -s)),
                              Polyline((A, B, C), "given", closed=True), Polyline((A, B, D), "given", closed=True)]
    items += [Label("1", _mid(_mid(A, C), B), (), LETTER, italic=False),
              Label("2", _mid(_mid(A, D), B), (), LETTER, italic=False),
              Label("3", (c + 6.0, s + 8.0), ((1.0, 0.0),), LETTER, italic=False),
              Label("4", (-c - 8.0, -s - 6.0), ((0.0, -1.0),), LETTER, italic=False)]
    items += _angle_arc(B, 14.0, math.pi - alpha, math.pi, "α")
    items += _force_arrow("F", _mid(A, C), (0.0, -1.0))
    items += _force_arrow("Q", _mid(A, D), (1.0, 0.0), at_tail=True)
    r12 = _side(stroke, "R12")
    if r12 is not None:
        at = _mid(A, B)
        n = (-math.sin(alpha), -math.cos(alpha))
        items.append(Segment(_add(at, n, -5.0), _add(at, n, 15.0), "construction", dashed=True))
        items += _force_arrow("R12", at, r12, 13.0, at_tail=True)
    return items


def _chain_diagram(stages: Sequence[Stage], powers: Sequence[StageResult], width: float = math.inf,
                   notation: str = "en") -> list[Primitive]:
    """The machines as boxes, the power on the arrows between them, in rows no wider than
    ``width`` mm (a long chain wraps: the power line runs down to the start of the next row)."""
    items: list[Primitive] = []
    box_w, gap = 40.0, 26.0
    per_row = max(1, int((width - 8.0 - gap - 14.0) // (gap + box_w))) if math.isfinite(width) else len(stages)

    def height(stage: Stage) -> float:
        return 20.0 if len(stage.branches) == 1 else 22.0 * len(stage.branches) - 4.0

    def box(cx: float, cy: float, text: str, eta: str) -> None:
        pts = ((cx - box_w / 2, cy - 10.0), (cx + box_w / 2, cy - 10.0), (cx + box_w / 2, cy + 10.0),
               (cx - box_w / 2, cy + 10.0))
        items.append(Polyline(pts, "given", closed=True))
        # the name and η stacked in the box, each pushed off the other's line (two 3.5 mm lines in 20 mm)
        items.append(Label(text, (cx, cy + 1.0), ((0.0, -1.0),), LETTER, italic=False))
        items.append(Label(eta, (cx, cy - 1.0), ((0.0, 1.0),), LETTER))

    items.append(Label(eff_word("motor", notation), (0.0, 0.0), (), LETTER, italic=False))
    x, y, x0 = 8.0, 0.0, 8.0
    for k, (stage, res) in enumerate(zip(stages, powers)):
        if k and k % per_row == 0:  # wrap: down half-way between the rows, back left, down again
            below = max(height(st) for st in stages[k - per_row:k]) / 2.0
            drop = below + max(height(st) for st in stages[k:k + per_row]) / 2.0 + 16.0
            turn = x + gap / 2.0
            items.append(Polyline(((x, y), (turn, y), (turn, y - below - 8.0), (x0 - gap / 2.0, y - below - 8.0),
                                   (x0 - gap / 2.0, y - drop)), "result"))
            x, y = x0 - gap / 2.0, y - drop
            items.append(Arrow((x, y), (x + gap / 2.0, y), "result"))
            items.append(Label(f"{number(res.power_in / 1000.0)} kW", (x + gap / 2.0, y + 4.5), ((0.0, -1.0),),
                               LETTER, italic=False))
            x += gap / 2.0 + box_w / 2.0
        else:
            items.append(Arrow((x, y), (x + gap, y), "result"))
            items.append(Label(f"{number(res.power_in / 1000.0)} kW", (x + gap / 2.0, y + 4.5), ((0.0, -1.0),),
                               LETTER, italic=False))
            x += gap + box_w / 2.0
        if len(stage.branches) == 1:
            series = stage.branches[0][1]
            text = stage.name if len(series) == 1 else f"{stage.name} ×{len(series)}"
            eta = "η = " + (number(series[0]) if len(set(series)) == 1 else "·".join(number(e) for e in series))
            box(x, y, text, eta)
        else:
            n = len(stage.branches)
            for i, (share, series) in enumerate(stage.branches):
                cy = y + (n - 1) * 11.0 - i * 22.0
                pts = ((x - box_w / 2, cy - 9.0), (x + box_w / 2, cy - 9.0), (x + box_w / 2, cy + 9.0),
                       (x - box_w / 2, cy + 9.0))
                items.append(Polyline(pts, "given", closed=True))
                items.append(Label(f"{stage.name}: {number(share)}", (x, cy + 3.4), (), LETTER, italic=False))
                items.append(Label("η = " + "·".join(number(e) for e in series), (x, cy - 3.4), (), LETTER))
        x += box_w / 2.0
    items.append(Arrow((x, y), (x + gap, y), "result"))
    items.append(Label(f"{number(powers[-1].power_out / 1000.0)} kW", (x + gap / 2.0, y + 4.5), ((0.0, -1.0),),
                       LETTER, italic=False))
    items.append(Label(eff_word("load", notation), (x + gap + 6.0, y), (), LETTER, italic=False))
    return items


# ---------------------------------------------------------------------------- polygons


def polygon_items(polygons: Sequence[ForcePolygon]) -> list[Primitive]:
    """Every side of every polygon an arrow with its name; the ideal ones thin and dashed."""
    items: list[Primitive] = []
    seen: set[tuple[str, XY, XY]] = set()
    for poly in polygons:
        for s in poly.forces:
            if math.hypot(s.end[0] - s.start[0], s.end[1] - s.start[1]) < 1e-9:
                continue
            if poly.ideal:
                items.append(Segment(s.start, s.end, "construction", dashed=True))
                continue
            key = (s.name, s.start, s.end)
            if key in seen:
                continue
            seen.add(key)
            if s.name.startswith("R21"):  # the shared side, drawn once as R12 (reversed)
                continue
            items.append(Arrow(s.start, s.end, "result" if s.name in ("F", "R", "R12", "R32", "R31") else "given"))
            d = _unit((s.end[0] - s.start[0], s.end[1] - s.start[1]))
            items.append(Label(point_name(s.name), _mid(s.start, s.end), ((d[0], d[1]), (-d[0], -d[1])), LETTER))
    return items


def efficiency_sheet(title: str, problem: EfficiencyProblem, strokes: dict[Direction, Stroke],
                     chain: tuple[float, tuple[StageResult, ...]] | None, phi: float, angle: float | None,
                     scales: dict[str, float], show: Sequence[str], page: tuple[float, float],
                     footer: tuple[str, ...] = (), notation: str = "en") -> Sheet:
    """The sheet of an efficiency problem: the diagram and a polygon per direction, as shown;
    captions in ``notation``. The diagram (directions true, no force scale) is enlarged to fill
    its share of the page; a polygon stays at μF (its panel's ``scales``)."""
    panels: list[Panel] = []
    first = next(iter(strokes.values()), None)
    if "diagram" in show:
        kind = problem.type
        notes: tuple[str, ...] = ()
        if kind == "chain":
            eta, powers = cast("tuple[float, tuple[StageResult, ...]]", chain)  # walked for every chain
            items = _chain_diagram(problem.stages, powers, page[0] - 40.0, notation)
            parallel = any(len(st.branches) > 1 for st in problem.stages)
            head = eff_word("series", notation) + (eff_word("parallel", notation) if parallel else "")
            notes = (f"η = {number(eta)}",)
        else:
            if kind in ("wedge_clamp", "buffer"):
                alpha = cast(float, problem.angle)  # both read their wedge angle into angle
                items = (_clamp_diagram(alpha, problem.faces, first) if kind == "wedge_clamp"
                         else _buffer_diagram(alpha, first))
                head = f"{eff_word(kind, notation)}: α = {number(math.degrees(alpha))}°"
                if kind == "buffer" and problem.f is not None:
                    notes = (f"φ = arctan f = {number(math.degrees(phi))}°",)
            elif kind == "wedge":
                gamma, beta = cast(float, problem.gamma), cast(float, problem.beta)  # a wedge has both (its reader)
                items = _wedge_diagram(gamma, beta, first)
                head = f"{eff_word('wedge', notation)}: γ = {number(math.degrees(gamma))}°, β = {number(math.degrees(beta))}°"
                notes = (f"φ = arctan f = {number(math.degrees(phi))}°",) if problem.f is not None else ()
            else:
                thread = ("π·d_{2}", "L = n·P") if kind == "screw" else None
                push = problem.push if kind == "incline" else "horizontal"
                alpha = float(cast(float, angle))  # given for an incline and a screw (efficiency_figure)
                items = _incline_diagram(alpha, phi, first, push, ("F", "R"), thread)
                head = f"{eff_word(kind, notation)}: {'ψ' if kind == 'screw' else 'α'} = {number(math.degrees(alpha))}°"
                if problem.f is not None:
                    sym = "φ_{v}" if kind == "screw" else "φ"
                    notes = (f"{sym} = {number(math.degrees(phi))}°",)
            # the diagram fills its share of the page: alone, most of it; beside polygons, half
            share = 1.0 if "polygon" not in show else 0.45
            k = enlargement(items, (share * (page[0] - 60.0), 0.5 * (page[1] - 60.0)))
            items = [transformed(i, k) for i in items]
        panels.append(Panel("diagram", head, tuple(items), notes))
    if "polygon" in show:
        for d, st in strokes.items():
            items = polygon_items(st.polygons)
            if st.F is None:
                notes = (scale_text("F", scales["F"]), eff_word("self-locked", notation))
            else:
                notes = (scale_text("F", scales["F"]),
                         f"F = {number(st.F)} N, F_{{0}} = {number(st.F0)} N, η = {number(st.eta)}")
            panels.append(Panel(f"polygon-{d}", f"{eff_word('force polygon', notation)} — {eff_word(d, notation)}",
                                tuple(items), notes, scales=(("F", scales["F"]),)))
    return Sheet(title, tuple(panels), page, footer)


__all__ = ["EFF_WORDS", "eff_word", "efficiency_sheet", "enlargement", "polygon_items"]
