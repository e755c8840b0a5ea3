"""The figures of kinetostatics: loads on the mechanism, each Assur group's free body and force
polygon, Zhukovsky's lever — draw primitives on panels (the renderer knows nothing of forces).

* **Loads on the mechanism** (``forces``): the kinematic diagram at μl with every known load at its
  point — weights G, inertia forces F_i through S (thin) and their single resultant moved by h
  (bold), inertia moments M_i and the balancing moment M_b as curved arrows — and the friction
  circles ρ = f_v·r about the journals: enlarged by a round factor, and said to be not to scale,
  where they would be under 1 mm on the paper (hidden under the pin).
* **Free body and force polygon of each group** (``force_polygons``), the farthest group first:
  the group's links with every force on them (arrow lengths not to scale: the polygon gives the
  magnitudes; with friction each reaction tangent to its friction circle as drawn), and beside it
  the polygon at μF — the known vectors head to tail (thin), the two closing lines
  (construction), the reactions found (bold), each vector labelled beside its middle. Vectors
  shorter than 10 mm (weights and inertia forces beside reactions of a thousand newtons) cannot
  be read to ±0.5 mm: the polygon rings them and a *detail* panel draws that part again at a
  round μF a round factor finer, where they are readable.
* **Zhukovsky's lever** (``lever``): the velocity polygon turned 90° about p, the loads at the
  image points of their points, and the balancing moment it gives.

Text is lettered with the marks of :mod:`graphmech.drawing.lettering` (``F_{i2}``, ``R^{t}_{12}``,
``M_{b}``) and numbers with its :func:`~graphmech.drawing.lettering.number`; captions and notes are
in the scene's notation (:data:`FORCE_WORDS`, ``[page] notation``); every panel states the scales
that measure its paper (``Panel.scales``).
"""
from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Sequence

import numpy as np

from graphmech.drawing.lettering import LETTER, number, point_name, scale_text
from graphmech.drawing.notation import word
from graphmech.drawing.primitives import (ArcArrow, Arrow, Circle, Hinge, Label, Panel, Primitive, Role, Segment,
                                         Sheet, Slider, clip_interval)
from graphmech.mechanisms.linkage import PRP, RPP, RPR, RRP, Crank, Guide, Linkage, Triad
from graphmech.methods.kinetostatics import (GroupPolygon, GuideReaction, KinetostaticSolution, Lever,
                                            PolygonKinematics)
from graphmech.problems.linkage.figures import mechanism_items
from graphmech.scales import is_round_scale, round_scale

if TYPE_CHECKING:
    from graphmech.mechanisms.forces import ForceModel
    from graphmech.methods.linkage_construction import LinkageConstruction

#: Mechanism point (m, as a complex number) → drawing (mm).
ToMm = Callable[[complex], tuple[float, float]]

#: Longest and shortest arrow of a free body or of the loads on the mechanism, mm (not to scale):
#: the shortest as long as a vector to scale is at least (READ_MIN_MM), with room for its letter.
ARROW_LONG, ARROW_SHORT = 18.0, 10.0
#: How far a polygon's closing line runs past the vertex it finds, mm.
CLOSING_OVERRUN = 8.0
#: The shortest vector a student reads to ±0.5 mm within 5 %, mm (FIGURES.md: 10–20 mm).
READ_MIN_MM = 10.0
#: The widest a detail of a force polygon may be drawn, mm, and the margin it keeps around the
#: short vectors (there the long vectors that meet them start or end).
DETAIL_ROOM_MM, DETAIL_MARGIN_MM = 100.0, 8.0
#: The factors a detail enlarges by: round, so that its μF is round too.
DETAIL_FACTORS = tuple(m * 10.0 ** k for k in range(5) for m in (1.0, 2.0, 2.5, 5.0))[1:]
#: A friction circle under this radius on the paper is hidden by the pin (a hinge is 1.2 mm):
#: it is enlarged, by a round factor, to at least ``FRICTION_DRAWN_MM``.
FRICTION_VISIBLE_MM, FRICTION_DRAWN_MM = 1.0, 2.5
#: A polygon's vector shorter than this on the paper is drawn as no vector (a tangential component
#: of 0.003 mm: its 2.8 mm head would point anywhere); the chain runs on through its end.
DRAWN_MIN_MM = 0.1
#: Label size of the vectors and points, mm (the issue's rule: text ≥ 3.5 mm, scripts ≥ 2.5 mm).
TEXT_MM = LETTER

#: The force sheet's captions and notes: key → (English, 中文, русский), as graphmech.drawing.notation.WORDS.
FORCE_WORDS: Mapping[str, tuple[str, str, str]] = {
    "loads": ("Loads and inertia forces, {}", "机构所受外力及惯性力，{}", "силы, действующие на механизм, {}"),
    "free body": ("Free body, {}", "{}的分离体受力图", "{}: расчётная схема"),
    "force polygon": ("{}, {}", "{}的{}", "{}, {}"),  # (word "force polygon", the group): 杆组 4–5的力多边形
    "detail": ("Detail {} of the force polygon, {}", "{}的力多边形局部放大图 {}", "выносной элемент {} плана сил, {}"),
    "enlarged": ("{}× the force polygon's scale", "放大 {} 倍", "увеличено в {} раз"),
    "group": ("group {}", "杆组 {}", "группа {}"),
    "driver": ("driver {}", "原动件 {}", "начальное звено {}"),
    "lever": ("Zhukovsky's lever (velocity polygon turned 90°)", "儒可夫斯基杠杆（速度多边形转过 90°）",
              "рычаг Жуковского (план скоростей, повёрнутый на 90°)"),
    "arrows not to scale": ("arrows not to scale", "箭头长度未按比例", "длины стрелок не в масштабе"),
    "friction circles": ("friction circles ρ = f_{v}·r at μ_{l}", "摩擦圆 ρ = f_{v}·r 按 μ_{l} 画出",
                         "круги трения ρ = f_{v}·r в масштабе μ_{l}"),
    "friction circles enlarged": ("friction circles ρ = f_{v}·r ×{} ({})", "摩擦圆 ρ = f_{v}·r 放大 {} 倍（{}）",
                                  "круги трения ρ = f_{v}·r ×{} ({})"),
    "tangent": ("{}, reactions tangent to them", "{}，总反力与之相切", "{}, реакции касаются их"),
    "without friction": ("without friction", "不计摩擦", "без трения"),
}

_ROMAN = ("I", "II", "III", "IV", "V", "VI", "VII", "VIII", "IX", "X")


def _w(key: str, notation: str, *fill: str) -> str:
    """The words of ``key`` in ``notation``, each ``{}`` filled in turn (not str.format: the
    lettering marks ``_{v}`` hold braces too)."""
    out = word(key, notation, FORCE_WORDS)
    for text in fill:
        out = out.replace("{}", text, 1)
    return out


def force_label(name: str) -> str:
    """A force's name lettered as the book prints it: ``R^t_12`` → R^{t}_{12}, ``F_i2`` → F_{i2},
    ``F'_i2`` → F′_{i2} (the resultant moved by h), ``M_b`` → M_{b}.

    >>> force_label("R^t_12"), force_label("F'_i2"), force_label("M_b"), force_label("Q")
    ('R^{t}_{12}', 'F′_{i2}', 'M_{b}', 'Q')
    """
    prime = "′" if "'" in name else ""
    name = name.replace("'", "")
    sup = ""
    if "^" in name:
        head, _, rest = name.partition("^")
        key, _, tail = rest.partition("_")
        sup, name = "^{" + key + "}", head + ("_" + tail if tail else "")
    head, sep, tail = name.partition("_")
    sub = "_{" + tail.replace("_", ",") + "}" if sep and tail else ""
    return head + prime + sup + sub


def group_text(group: GroupPolygon, notation: str) -> str:
    """The group's name in the notation: "group 4–5", "杆组 4–5", "driver 1" …"""
    if group.name.startswith("driver"):
        return _w("driver", notation, group.links[0])
    return _w("group", notation, "–".join(group.links))


def _c(z: complex) -> tuple[float, float]:
    return (float(z.real), float(z.imag))


def _unit(z: complex) -> tuple[float, float]:
    m = abs(z)
    return (float(z.real / m), float(z.imag / m)) if m > 0 else (0.0, 0.0)


def _arrow_length(mag: float, largest: float) -> float:
    """Not to scale: a readable length that still grows with the force."""
    if largest <= 0 or mag <= 0:
        return 0.0
    return ARROW_SHORT + (ARROW_LONG - ARROW_SHORT) * math.sqrt(mag / largest)


def _vector_label(text: str, p0: tuple[float, float], p1: tuple[float, float]) -> Label:
    """A vector's letter beside its middle, clear of the vector itself (FIGURES.md)."""
    u = _unit(complex(p1[0] - p0[0], p1[1] - p0[1]))
    mid = ((p0[0] + p1[0]) / 2, (p0[1] + p1[1]) / 2)
    return Label(text, mid, (u, (-u[0], -u[1])), TEXT_MM)


def _arrows(forces: Sequence[tuple[str, complex, complex]], to_mm: ToMm, largest: float,
            role: Role = "result") -> list[Primitive]:
    """Arrows from each force's point of application along the force, labelled beside the middle."""
    items: list[Primitive] = []
    for name, vec, at in forces:
        length = _arrow_length(abs(vec), largest)
        if length == 0.0:
            continue
        p0 = to_mm(at)
        u = _unit(vec)
        p1 = (p0[0] + length * u[0], p0[1] + length * u[1])
        items.append(Arrow(p0, p1, role))
        items.append(_vector_label(force_label(name), p0, p1))
    return items


def _moment_arc(at: tuple[float, float], moment: float, name: str, r: float = 5.0) -> list[Primitive]:
    if moment == 0.0:
        return []
    sweep = math.copysign(math.radians(120.0), moment)
    arc = ArcArrow(at, r, math.radians(30.0) - sweep / 2 + math.pi / 2, sweep, "result")
    end = arc.points(2)[2]
    out = _unit(complex(end[0] - at[0], end[1] - at[1]))
    return [arc, Label(force_label(name), end, ((-out[0], -out[1]),), TEXT_MM)]


def friction_factor(rho: Mapping[str, float], mu_l: float) -> float:
    """How many times the friction circles are drawn larger than at μl: 1 where the smallest is
    at least ``FRICTION_VISIBLE_MM`` on the paper, else the round factor that draws it at least
    ``FRICTION_DRAWN_MM`` (every circle by the same factor, so they compare).

    >>> friction_factor({"A": 0.003, "E": 0.0018}, 0.005), friction_factor({"A": 0.01}, 0.005)
    (10.0, 1.0)
    """
    drawn = [r / mu_l for r in rho.values() if r > 0]
    if not drawn or min(drawn) >= FRICTION_VISIBLE_MM:
        return 1.0
    return round_scale(FRICTION_DRAWN_MM / min(drawn))


def friction_notes(factor: float, notation: str, tangent: bool) -> tuple[str, ...]:
    """What the friction circles drawn are: at μl, or enlarged and not to scale."""
    if factor == 1.0:
        note = _w("friction circles", notation)
    else:
        note = _w("friction circles enlarged", notation, number(factor), word("not to scale", notation))
    return (_w("tangent", notation, note) if tangent else note,)


def loads_items(build: LinkageConstruction, kin: PolygonKinematics, sol: KinetostaticSolution, model: ForceModel,
                i: int, friction: float = 1.0) -> list[Primitive]:
    """The kinematic diagram with the known loads, inertia resultants, M_b and the friction
    circles (drawn ``friction`` times their size at μl)."""
    linkage: Linkage = build.linkage
    pos = {name: build.to_drawing(_c(complex(p[i]))) for name, p in kin.point.items()}
    # the kinematic diagram's letters as this sheet letters them: S_{2}, at least 3.5 mm
    items = [Label(point_name(x.text), x.anchor, x.avoid, max(x.size, TEXT_MM), x.italic) if isinstance(x, Label)
             else x for x in mechanism_items(build, pos)]

    def to_mm(z: complex) -> tuple[float, float]:
        return build.to_drawing(_c(z))

    loads: list[tuple[str, complex, complex]] = []
    shifted: list[tuple[str, complex, complex]] = []
    # A single resultant moved farther than the mechanism is wide is a couple in all but name
    # (a light link turning fast: h = |M_i/F_i| runs to kilometres): F_i and M_i stay at S.
    xs, ys = [p[0] for p in pos.values()], [p[1] for p in pos.values()]
    reach = 2.0 * max(max(xs) - min(xs), max(ys) - min(ys), ARROW_LONG) * build.mu_l
    for lm in model.masses:
        if lm.link == linkage.frame_link:
            continue
        at = complex(kin.point[lm.point][i])
        if model.gravity > 0 and lm.mass > 0:
            loads.append((f"G_{lm.link}", complex(0.0, -lm.mass * model.gravity), at))
        il = sol.inertia.get(lm.link)
        if il is not None and il.moment[i] != 0:
            items += _moment_arc(build.to_drawing(_c(at)), float(il.moment[i]), f"M_i{lm.link}", 4.0)
        if il is not None and abs(il.force[i]) > 0:
            if il.moment[i] != 0 and 0 < il.offset[i] <= reach:
                # F_i through S (thin), and its single resultant moved by h (bold)
                loads.append((f"F_i{lm.link}", complex(il.force[i]), at))
                shifted.append((lm.link, complex(il.force[i]), at + complex(il.resultant_shift[i])))
            else:
                loads.append((f"F_i{lm.link}", complex(il.force[i]), at))
    for pf in model.forces:
        vec = complex(*pf.vector)
        if pf.resistance and (np.conj(vec) * kin.vel[pf.point][i]).real >= 0:
            continue
        loads.append((pf.name, vec, complex(kin.point[pf.point][i])))
    largest = max([abs(v) for _, v, _ in loads + shifted], default=0.0)
    items += _arrows(loads, to_mm, largest, "given")
    for link, vec, at in shifted:
        length = _arrow_length(abs(vec), largest)
        p0 = to_mm(at)
        u = _unit(vec)
        p1 = (p0[0] + length * u[0], p0[1] + length * u[1])
        items.append(Arrow(p0, p1, "result"))
        items.append(_vector_label(force_label(f"F'_i{link}"), p0, p1))
        s = to_mm(at - complex(sol.inertia[link].resultant_shift[i]))
        if math.dist(s, p0) > 1e-9:  # the offset h, a thin dimension line from S, lettered h_{2}
            items.append(Segment(s, p0, "construction"))
            items.append(_vector_label(f"h_{{{link}}}", s, p0))
    links = linkage.links()
    for c in model.couples:  # the scene's own moments on links (a resisting moment M_r …)
        items += _moment_arc(_middle(kin, links[c.link], i, to_mm), c.moment, c.name, 4.0)
    d = linkage.driver
    if isinstance(d, Crank):  # round the crank's friction circle, if drawn
        circle = max((friction * fr.rho / build.mu_l for fr in model.revolute_friction if fr.point == d.pivot),
                     default=0.0)
        items += _moment_arc(pos[d.pivot], float(sol.balancing_moment[i]), "M_b", max(9.0, circle + 3.0))
    elif sol.balancing_force is not None and float(sol.balancing_force[i]) != 0.0:
        f_b = float(sol.balancing_force[i]) * complex(math.cos(d.guide.angle), math.sin(d.guide.angle))
        items += _arrows([("F_b", f_b, complex(kin.point[d.point][i]))], to_mm, abs(f_b), "result")
    for fr in model.revolute_friction:
        if fr.rho > 0 and fr.point in pos:
            items.append(Circle(pos[fr.point], friction * fr.rho / build.mu_l, "construction"))
    return items


def free_body_items(build: LinkageConstruction, kin: PolygonKinematics, group: GroupPolygon, rho: dict[str, float],
                    joints: set[str], i: int, guides: Sequence[GuideReaction] = (),
                    friction: float = 1.0) -> list[Primitive]:
    """One group cut free: its links, hinges, slider, and every force on it (arrows not to scale).

    With friction a reaction in a journal is tangent to its friction circle; the circles are drawn
    ``friction`` times their size at μl, and the reactions tangent to the circles so drawn.

    A guide's reaction is drawn on its line of action, unless that crosses the guide farther off
    than the group is wide (a small normal force with a moment): then at the slider's point with
    its moment M_ij about it, as the book draws a slider that bears on the ends of its guide."""
    linkage: Linkage = build.linkage
    pts = linkage.links()
    items: list[Primitive] = []

    def to_mm(z: complex) -> tuple[float, float]:
        return build.to_drawing(_c(z))

    drawn: set[str] = set()
    leaving: dict[str, list[tuple[float, float]]] = {}  # point → directions of the lines drawn from it
    # an offset guide bar is drawn as its arm OF and its line FX below, not as the segment OX
    offset_bars = {(y.bar_pivot, y.coincident[0]) for y in linkage.dyads if isinstance(y, RPR) and y.offset}
    for link in group.links:
        names = pts[link]
        ring = [(y.inner[2], y.inner[0]) for y in linkage.dyads if isinstance(y, Triad) and y.links[3] == link]
        for a, b in [*zip(names, names[1:]), *ring]:  # a class III group's ternary link: its whole triangle
            if (a, b) in offset_bars:
                continue
            za, zb = complex(kin.point[a][i]), complex(kin.point[b][i])
            pa, pb = to_mm(za), to_mm(zb)
            if math.dist(pa, pb) > 1e-9:
                items.append(Segment(pa, pb, "given"))
                leaving.setdefault(a, []).append(_unit(zb - za))
                leaving.setdefault(b, []).append(_unit(za - zb))
        drawn.update(names)
    for y in linkage.dyads:  # the blocks and slots of the group's sliding pairs
        if isinstance(y, (RRP, PRP)):  # a block on each guide of the group (a moving guide at this position)
            for block, line in zip(y.links[1:] if isinstance(y, RRP) else y.links,
                                   (y.guide,) if isinstance(y, RRP) else y.guides):
                if block in group.links:
                    dl = (0j if isinstance(line, Guide) else
                         complex(kin.point[line.towards][i]) - complex(kin.point[line.through][i]))
                    items.append(Slider(to_mm(complex(kin.point[y.c][i])),
                                        line.angle if isinstance(line, Guide) else math.atan2(dl.imag, dl.real)))
        elif isinstance(y, RPR) and y.block_link in group.links:
            x, p = complex(kin.point[y.block_pivot][i]), complex(kin.point[y.bar_pivot][i])
            # along the bar's line: an offset bar's is turned from PX by atan2(e, t)
            tilt = math.atan2(y.offset, math.sqrt(max(abs(x - p) ** 2 - y.offset ** 2, 0.0))) if y.offset else 0.0
            items.append(Slider(to_mm(x), math.atan2((x - p).imag, (x - p).real) - tilt))
        if isinstance(y, RPR) and y.offset and y.bar_link in group.links:  # the arm OF ⟂ the line FX
            x, p = complex(kin.point[y.block_pivot][i]), complex(kin.point[y.bar_pivot][i])
            u_bar = (x - p) / complex(math.sqrt(max(abs(x - p) ** 2 - y.offset ** 2, 0.0)), y.offset)
            foot = p + y.offset * 1j * u_bar / abs(u_bar)
            items += [Segment(to_mm(p), to_mm(foot), "given"), Segment(to_mm(foot), to_mm(x), "given")]
            leaving.setdefault(y.bar_pivot, []).append(_unit(foot - p))
            leaving.setdefault(y.block_pivot, []).append(_unit(foot - x))
        elif isinstance(y, RPP) and y.links[0] in group.links:
            c, p = complex(kin.point[y.c][i]), complex(kin.point[y.p][i])
            items.append(Segment(to_mm(c), to_mm(p), "given"))  # the slot
            items.append(Slider(to_mm(p), y.slot_angle, 6.0, 4.0))
            items.append(Slider(to_mm(c), y.guide.angle))
    d = linkage.driver
    if not isinstance(d, Crank) and d.link in group.links:
        items.append(Slider(to_mm(complex(kin.point[d.point][i])), d.guide.angle))
    for name in sorted(drawn):
        if name in joints:
            items.append(Hinge(to_mm(complex(kin.point[name][i]))))
        if name in rho and rho[name] > 0:
            items.append(Circle(to_mm(complex(kin.point[name][i])), friction * rho[name] / build.mu_l))
        items.append(Label(point_name(name), to_mm(complex(kin.point[name][i])), tuple(leaving.get(name, ())),
                           TEXT_MM))
    # With friction a reaction is tangent to its friction circle: its line of action is moved off
    # the joint's centre so that its moment about it is the friction couple M_f — by ρ, times the
    # factor the circle is drawn larger by, so that it touches the circle drawn.
    couples = {c.name: float(c.moment[i]) for c in group.couples if c.name.startswith("M_f")}
    seen = [to_mm(complex(kin.point[name][i])) for name in drawn]
    reach = 2.0 * max(max(p[0] for p in seen) - min(p[0] for p in seen),
                      max(p[1] for p in seen) - min(p[1] for p in seen), ARROW_LONG) * build.mu_l
    by_name = {g.name: g for g in guides}
    forces, guide_moments = [], []
    for f in group.free_body:
        vec, at = complex(f.vector[i]), complex(f.at[i])
        m = couples.get("M_f" + f.name[2:], 0.0) if f.name.startswith("R_") else 0.0
        if m != 0.0 and abs(vec) > 0:
            at = at - friction * 1j * m * vec / abs(vec) ** 2
        g = by_name.get(f.name)
        if g is not None and abs(at - complex(kin.point[g.point][i])) > reach:
            at = complex(kin.point[g.point][i])
            guide_moments.append((f"M_{g.frame}{g.slider}", float(g.moment[i]), at))
        forces.append((f.name, vec, at))
    largest = max([abs(v) for _, v, _ in forces], default=0.0)
    items += _arrows(forces, to_mm, largest)
    for couple in group.couples:  # M_i, M_b and the scene's own couples; friction couples moved the reactions
        m = float(couple.moment[i])
        if m != 0 and couple.name not in couples:
            items += _moment_arc(_middle(kin, pts[couple.link or group.links[0]], i, to_mm), m, couple.name, 4.0)
    for name, m, at in guide_moments:
        items += _moment_arc(to_mm(at), m, name, 6.0)
    return items


def _middle(kin: PolygonKinematics, names: Sequence[str], i: int, to_mm: ToMm) -> tuple[float, float]:
    """Where a couple on a link is drawn: halfway between its first and last points."""
    return to_mm(complex(kin.point[names[0]][i] + kin.point[names[-1]][i]) / 2)


# --------------------------------------------------------------------------------------------
# The force polygon and its detail


@dataclass(frozen=True)
class Detail:
    """The part of a force polygon drawn again larger, where its short vectors are readable.

    ``box`` is the window (x0, y0, x1, y1) in the polygon's own mm at μF; the detail draws what
    lies in it ``factor`` times larger, at ``mu_F`` = μF / factor; ``shown`` are the vectors
    shorter than ``READ_MIN_MM`` at μF that lie wholly in the window."""

    factor: float
    mu_F: float
    box: tuple[float, float, float, float]
    shown: tuple[str, ...]


def _laid_off(group: GroupPolygon, mu_F: float, i: int, least: float = DRAWN_MIN_MM) -> list[tuple[str, complex, complex]]:
    """(name, start, vector) of the polygon's drawn vectors, mm at μF, head to tail from o (those
    under ``least`` mm at μF left out)."""
    out, vertex = [], 0j
    for name, vec in group.chain:
        v = complex(vec[i]) / mu_F
        if abs(v) >= least:
            out.append((name, vertex, v))
        vertex = vertex + v
    return out


def _closing_lines(group: GroupPolygon, mu_F: float, i: int) -> list[tuple[complex, complex]]:
    """The two closing lines: through the end of the known chain and through its start."""
    if len(group.unknown) != 2 or len(group.chain) < 2:
        return []
    starts, vertex = [], 0j
    for _, vec in group.chain:
        starts.append(vertex)
        vertex = vertex + complex(vec[i]) / mu_F
    out = []
    for (_, vec), s in ((group.chain[-2], starts[-2]), (group.chain[-1], starts[-1])):
        v = complex(vec[i]) / mu_F
        if abs(v) == 0:
            continue
        u = v / abs(v)
        out.append((s - CLOSING_OVERRUN * u, s + v + CLOSING_OVERRUN * u))
    return out


def polygon_detail(group: GroupPolygon, mu_F: float, i: int) -> Detail | None:
    """The detail of the group's polygon, or None when every vector is readable at μF.

    The window is drawn around the longest run of consecutive short vectors (a run at the
    chain's end joins one at its start: both meet at o), ``DETAIL_MARGIN_MM`` about it. The factor
    is the least round one that draws each of them ``READ_MIN_MM`` long, unless the window would
    then be wider than ``DETAIL_ROOM_MM``: then the largest that keeps it so. A short vector
    elsewhere in the polygon (a small reaction between two long ones) stays short: the check table
    names it with its reading error."""
    vecs = _laid_off(group, mu_F, i)
    short = [k for k, (_, _, v) in enumerate(vecs) if abs(v) < READ_MIN_MM]
    if not short:
        return None
    runs: list[list[int]] = []
    for k in short:
        if runs and runs[-1][-1] == k - 1:
            runs[-1].append(k)
        else:
            runs.append([k])
    if len(runs) > 1 and runs[0][0] == 0 and runs[-1][-1] == len(vecs) - 1:
        runs[0] = runs.pop() + runs[0]
    run = max(runs, key=len)
    ends = [z for k in run for z in (vecs[k][1], vecs[k][1] + vecs[k][2])]
    x0, x1 = min(z.real for z in ends), max(z.real for z in ends)
    y0, y1 = min(z.imag for z in ends), max(z.imag for z in ends)
    size = max(x1 - x0, y1 - y0)
    need = min(abs(vecs[k][2]) for k in run)
    fits = [f for f in DETAIL_FACTORS if (not is_round_scale(mu_F) or is_round_scale(mu_F / f))
            and size * f + 2 * DETAIL_MARGIN_MM <= DETAIL_ROOM_MM]
    if not fits:
        return None
    factor = next((f for f in fits if need * f >= READ_MIN_MM * (1 - 1e-12)), fits[-1])
    pad = DETAIL_MARGIN_MM / factor
    box = (x0 - pad, y0 - pad, x1 + pad, y1 + pad)
    inside = [name for name, s, v in vecs if abs(v) < READ_MIN_MM and _clip(s, s + v, box) == (0.0, 1.0)]
    return Detail(factor, mu_F / factor, box, tuple(inside))


def _clip(a: complex, b: complex, box: tuple[float, float, float, float]) -> tuple[float, float] | None:
    """The part (t0, t1) of the segment a + t·(b − a), 0 ≤ t ≤ 1, inside ``box`` (Liang–Barsky)."""
    return clip_interval((a.real, a.imag), (b.real, b.imag), box)


def polygon_items(group: GroupPolygon, mu_F: float, i: int, detail: Detail | None = None,
                  mark: str = "I") -> list[Primitive]:
    """The group's force polygon at μF: known vectors head to tail, closing lines, reactions found.

    With a ``detail``, the short vectors it draws again are ringed (a thin circle lettered
    ``mark``) and lettered there instead of in a clump here."""
    items: list[Primitive] = []
    shown = set(detail.shown) if detail else set()
    for name, s, v in _laid_off(group, mu_F, i):
        role: Role = "result" if name in group.unknown else "given"
        items.append(Arrow(_c(s), _c(s + v), role))
        if name not in shown:
            items.append(_vector_label(force_label(name), _c(s), _c(s + v)))
    for a, b in _closing_lines(group, mu_F, i):
        items.append(Segment(_c(a), _c(b), "construction"))
    if detail is not None:
        x0, y0, x1, y1 = detail.box
        centre, r = ((x0 + x1) / 2, (y0 + y1) / 2), math.hypot(x1 - x0, y1 - y0) / 2
        items.append(Circle(centre, r, "construction"))
        items.append(Label(mark, (centre[0] + r * 0.7071, centre[1] + r * 0.7071), ((-0.7071, -0.7071),), TEXT_MM,
                           italic=False))
    items.append(Label("o", (0.0, 0.0), (), TEXT_MM))
    return items


def detail_items(group: GroupPolygon, mu_F: float, i: int, detail: Detail) -> list[Primitive]:
    """The window of the group's polygon ``detail.factor`` times larger: every vector and closing
    line cut at the window's edge, arrowheads only where a head is in it, each letter beside the
    middle of the part drawn."""
    f = detail.factor
    items: list[Primitive] = []
    for name, s, v in _laid_off(group, mu_F, i, DRAWN_MIN_MM / f):
        part = _clip(s, s + v, detail.box)
        if part is None:
            continue
        a, b = (s + part[0] * v) * f, (s + part[1] * v) * f
        role: Role = "result" if name in group.unknown else "given"
        items.append(Arrow(_c(a), _c(b), role) if part[1] == 1.0 else Segment(_c(a), _c(b), role))
        if abs(b - a) >= 2.0:
            items.append(_vector_label(force_label(name), _c(a), _c(b)))
    for a0, b0 in _closing_lines(group, mu_F, i):
        part = _clip(a0, b0, detail.box)
        if part is not None:
            d = b0 - a0
            items.append(Segment(_c((a0 + part[0] * d) * f), _c((a0 + part[1] * d) * f), "construction"))
    x0, y0, x1, y1 = detail.box
    if x0 <= 0.0 <= x1 and y0 <= 0.0 <= y1:
        items.append(Label("o", (0.0, 0.0), (), TEXT_MM))
    return items


def lever_items(linkage: Linkage, kin: PolygonKinematics, lever: Lever, i: int) -> list[Primitive]:
    """Zhukovsky's lever: the turned velocity polygon, the loads at the images, the pole p."""
    items: list[Primitive] = []
    pts = linkage.links()
    images = {name: 1j * complex(v[i]) / kin.mu_v for name, v in kin.vel.items()}
    for link, names in pts.items():
        if link == linkage.frame_link:
            continue
        for a, b in zip(names, names[1:]):
            if a in images and b in images and abs(images[a] - images[b]) > 1e-9:
                items.append(Segment(_c(images[a]), _c(images[b]), "given"))
    for name, z in images.items():
        if abs(z) > 1e-9 and name not in linkage.frame_points:
            items.append(Segment((0.0, 0.0), _c(z), "construction"))
            items.append(Label(point_name(name.lower()), _c(z), (_unit(-z),), TEXT_MM))
    arms = [(name, complex(f[i]), complex(at[i])) for name, at, f in lever.arms]
    largest = max([abs(v) for _, v, _ in arms], default=0.0)
    items += _arrows(arms, lambda z: _c(z), largest)
    items.append(Label("p", (0.0, 0.0), (), TEXT_MM))
    return items


def force_sheet(title: str, build: LinkageConstruction, kin: PolygonKinematics, sol: KinetostaticSolution, model: ForceModel,
                lever: Lever | None, mu_F: float, show: Sequence[str], i: int, position: str,
                page: tuple[float, float], head: Sequence[Panel] = (), footer: tuple[str, ...] = (),
                notation: str = "en", details: bool = True) -> Sheet:
    """The force sheet of one position: the panels of ``show`` after the kinematic ``head`` panels,
    lettered in ``notation`` ("en", "zh", "ru"); ``details``: each force polygon with vectors
    under 10 mm is followed by its detail."""
    panels: list[Panel] = list(head)
    mu_l = build.mu_l
    rho = {fr.point: fr.rho for fr in model.revolute_friction if fr.rho > 0}
    friction = friction_factor(rho, mu_l)
    not_to_scale = _w("arrows not to scale", notation)
    if "forces" in show:
        notes: tuple[str, ...] = (scale_text("l", mu_l), not_to_scale)
        if rho:
            notes += friction_notes(friction, notation, tangent=False)
        panels.append(Panel("forces", _w("loads", notation, position),
                            tuple(loads_items(build, kin, sol, model, i, friction)), notes,
                            scales=(("l", mu_l),)))
    if "force_polygons" in show:
        joints = {j.point for j in sol.joints}
        marks = 0
        for g in sol.groups:
            key = "-".join(g.links)
            name = group_text(g, notation)
            notes = (not_to_scale,) + (friction_notes(friction, notation, True) if rho else ())
            panels.append(Panel(f"free-{key}", _w("free body", notation, name),
                                tuple(free_body_items(build, kin, g, rho, joints, i, sol.guides, friction)), notes,
                                scales=(("l", mu_l),)))
            detail = polygon_detail(g, mu_F, i) if details else None
            mark = _ROMAN[marks % len(_ROMAN)]
            polygon = word("force polygon", notation)
            caption = _w("force polygon", notation, *((name, polygon) if notation == "zh" else (polygon, name)))
            panels.append(Panel(f"polygon-{key}", caption, tuple(polygon_items(g, mu_F, i, detail, mark)),
                                (scale_text("F", mu_F),), scales=(("F", mu_F),)))
            if detail is not None:
                marks += 1
                args = (name, mark) if notation == "zh" else (mark, name)
                panels.append(Panel(f"detail-{key}", _w("detail", notation, *args),
                                    tuple(detail_items(g, mu_F, i, detail)),
                                    (scale_text("F", detail.mu_F), _w("enlarged", notation, number(detail.factor))),
                                    scales=(("F", detail.mu_F),)))
    if "lever" in show and lever is not None:
        # the lever knows no friction: with friction it gives the frictionless M_b0 (F_b0)
        bare = "0" if model.has_friction else ""
        note = f" ({_w('without friction', notation)})" if model.has_friction else ""
        d = build.linkage.driver
        if lever.balancing_force is not None:
            result = (f"F_{{b{bare}}} = μ_{{v}}·ΣM_{{p}}/v_{{{d.link}}} = "
                      f"{number(float(lever.balancing_force[i]))} N{note}")
        else:
            result = (f"M_{{b{bare}}} = μ_{{v}}·ΣM_{{p}}/ω_{{{d.link}}} = "
                      f"{number(float(lever.balancing_moment[i]))} N·m{note}")
        panels.append(Panel("lever", _w("lever", notation), tuple(lever_items(build.linkage, kin, lever, i)),
                            (scale_text("v", kin.mu_v), result), scales=(("v", kin.mu_v),)))
    return Sheet(title, tuple(panels), page, footer)


__all__ = ["force_sheet", "force_label", "loads_items", "free_body_items",
           "polygon_items", "polygon_detail", "detail_items", "lever_items", "friction_factor", "Detail",
           "FORCE_WORDS", "READ_MIN_MM"]
