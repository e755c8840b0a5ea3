"""The figures of a balancing problem: the rotor and its mass-radius polygons.

rotor
    the end view (at μl): the rotor's circle, each eccentric mass a small circle on its radius,
    labelled m_{1}, m_{2} …, the correction masses bold on their radii (r_{b}), the centre lines
    dash-dot; for a dynamic balance also a side view: the rotor's axis (dash-dot), the planes of
    the masses (thin) and the correction planes I and II (bold), with their axial positions.
polygon
    one panel per correction plane (at μW): the mass-radius products W_{1}, W_{2} … head to tail
    (thin arrows, each parallel to its mass's radius — in a correction plane the lever-rule
    shares, reversed where a mass lies outside the planes), and the closing side W_{b} from the
    last end back to the start (bold), its magnitude and angle in the notes.
"""
from __future__ import annotations

import math
from typing import Any, Sequence

from graphmech.geometry.primitives import degrees_0_360
from graphmech.methods.balancing import Correction
from graphmech.drawing.lettering import LETTER, number, scale_text
from graphmech.drawing.notation import word
from graphmech.drawing.primitives import Arrow, Circle, Label, Panel, Primitive, Segment, Sheet
from graphmech.scales import round_scale

#: The rotor's end view radius on paper, about, mm; the side view's length between the outer
#: planes, about, mm.
ROTOR_MM, SIDE_MM = 40.0, 120.0

#: The balancing sheet's words (laid out as graphmech.drawing.notation.WORDS: English, 中文,
#: русский); «plane» is filled with I or II. Drawn text only.
BAL_WORDS: dict[str, tuple[str, str, str]] = {
    "end view": ("Rotor: end view", "转子：端视图", "Ротор: вид с торца"),
    "side view": ("Rotor: side view, correction planes I and II", "转子：侧视图，平衡平面 I、II",
                  "Ротор: вид сбоку, плоскости коррекции I и II"),
    "polygon": ("Mass-radius polygon", "质径积矢量多边形", "План векторов дисбалансов"),
    "in plane": (", plane «plane»", "，平衡平面 «plane»", ", плоскость «plane»"),
    "none in plane": ("no mass acts in plane «plane»: no correction mass needed",
                      "平衡平面 «plane» 中无不平衡质量：无需加平衡质量",
                      "в плоскости «plane» нет масс: корректирующая масса не нужна"),
    "closes": ("closes by itself: no correction mass needed", "自行封闭：无需加平衡质量",
               "замыкается сам: корректирующая масса не нужна"),
}


def bal_word(key: str, notation: str = "en", plane: str = "") -> str:
    """``key`` of :data:`BAL_WORDS` in ``notation``, «plane» filled in.

    >>> bal_word("polygon", "zh") + bal_word("in plane", "zh", "II")
    '质径积矢量多边形，平衡平面 II'
    """
    return word(key, notation, BAL_WORDS).replace("«plane»", plane)


def _w_name(name: str) -> str:
    """``"W1I"`` → ``W_{1}^{I}``, ``"WbII"`` → ``W_{b}^{II}``, ``"W2"`` → ``W_{2}`` (lettering marks).

    >>> _w_name("W1I"), _w_name("WbII"), _w_name("W12"), _w_name("Wb")
    ('W_{1}^{I}', 'W_{b}^{II}', 'W_{12}', 'W_{b}')
    """
    body = name[1:]
    plane = "II" if body.endswith("II") else "I" if body.endswith("I") and not body.isdigit() else ""
    core = body[: len(body) - len(plane)]
    return "W" + (f"_{{{core}}}" if core else "") + (f"^{{{plane}}}" if plane else "")


def _m_name(name: str) -> str:
    """A mass's letter: ``m_{1}`` for a numbered mass, ``m_{A}`` for a named one."""
    return f"m_{{{name}}}"


def polygon_items(c: Correction) -> list[Primitive]:
    items: list[Primitive] = []
    for s in c.sides:
        if math.hypot(s.end[0] - s.start[0], s.end[1] - s.start[1]) < 1e-9:
            continue
        items.append(Arrow(s.start, s.end, "given"))
        d = (s.end[0] - s.start[0], s.end[1] - s.start[1])
        n = math.hypot(*d)
        items.append(Label(_w_name(s.name), ((s.start[0] + s.end[0]) / 2, (s.start[1] + s.end[1]) / 2),
                           ((d[0] / n, d[1] / n), (-d[0] / n, -d[1] / n)), LETTER))
    if not c.balanced:
        s = c.closing
        items.append(Arrow(s.start, s.end, "result"))
        d = (s.end[0] - s.start[0], s.end[1] - s.start[1])
        n = math.hypot(*d)
        items.append(Label(_w_name(s.name), ((s.start[0] + s.end[0]) / 2, (s.start[1] + s.end[1]) / 2),
                           ((d[0] / n, d[1] / n), (-d[0] / n, -d[1] / n)), LETTER))
    if not items:  # no mass has a share in this plane: the polygon is its start point, closed
        items = [Circle((0.0, 0.0), 0.8, "result"), Label("o", (0.0, 0.0), (), LETTER)]
    return items


def split_items(c: Correction, corner: tuple[float, float]) -> list[Primitive]:
    """The split of the closing side along two given directions (001 8-4): W_{b1} from its start
    to the corner K, W_{b2} from K to o, the corner lettered K."""
    items: list[Primitive] = []
    for name, a, b in (("W_{b1}", c.closing.start, corner), ("W_{b2}", corner, c.closing.end)):
        d = (b[0] - a[0], b[1] - a[1])
        n = math.hypot(*d)
        if n < 1e-9:  # the correction lies along the other direction: this side is a point
            continue
        items += [Arrow(a, b, "result"),
                  Label(name, ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2), ((-d[1] / n, d[0] / n),), LETTER)]
    items.append(Label("K", corner, (), LETTER))
    return items


def rotor_items(masses: Sequence[Any], corrections: Sequence[Correction], mu_l: float) -> list[Primitive]:
    R = max([u.r for u in masses] + [c.r_b for c in corrections]) * 1.15 / mu_l
    # the centre lines dash-dot, past the rotor's circle
    items: list[Primitive] = [Circle((0.0, 0.0), R, "given"),
                              Segment((-R - 5, 0.0), (R + 5, 0.0), "construction", dashdot=True),
                              Segment((0.0, -R - 5), (0.0, R + 5), "construction", dashdot=True)]
    for u in masses:
        p = (u.r / mu_l * math.cos(u.theta), u.r / mu_l * math.sin(u.theta))
        items += [Segment((0.0, 0.0), p, "given"), Circle(p, 1.6, "given"),
                  Label(_m_name(u.name), p, ((-math.cos(u.theta), -math.sin(u.theta)),), LETTER)]
    for c in corrections:
        if c.theta is None:  # balanced
            continue
        th = float(c.theta)
        p = (c.r_b / mu_l * math.cos(th), c.r_b / mu_l * math.sin(th))
        items += [Segment((0.0, 0.0), p, "result"), Circle(p, 2.2, "result"),
                  Label("m_{b}" + (f"^{{{c.plane}}}" if c.plane else ""), p, ((-math.cos(th), -math.sin(th)),),
                        LETTER)]
    return items


def side_items(masses: Sequence[Any], planes: tuple[float, float], mu_z: float) -> list[Primitive]:
    zs = [u.z for u in masses] + list(planes)
    lo, hi = min(zs), max(zs)
    items: list[Primitive] = [Segment(((lo - 0.1 * (hi - lo)) / mu_z, 0.0), ((hi + 0.1 * (hi - lo)) / mu_z, 0.0),
                                      "construction", dashdot=True)]  # the rotor's axis
    for u in masses:
        x = u.z / mu_z
        items += [Segment((x, -10.0), (x, 10.0), "given"), Label(_m_name(u.name), (x, 12.5), ((0.0, -1.0),), LETTER)]
    for name, z in zip(("I", "II"), planes):
        x = z / mu_z
        items += [Segment((x, -14.0), (x, 14.0), "result"), Label(name, (x, -17.0), ((0.0, 1.0),), LETTER, italic=False)]
    return items


def balancing_sheet(title: str, kind: str, masses: Sequence[Any], planes: tuple[float, float] | None,
                    corrections: Sequence[Correction], mu_W: float, show: Sequence[str], page: tuple[float, float],
                    footer: tuple[str, ...] = (), notation: str = "en",
                    split_corner: tuple[float, float] | None = None) -> Sheet:
    """The sheet: the rotor (end view; a dynamic one also from the side) and a polygon per plane,
    captions in ``notation``; each panel's ``scales`` its paper's."""
    panels: list[Panel] = []
    if "rotor" in show:
        R = max([u.r for u in masses] + [c.r_b for c in corrections])
        mu_l = round_scale(R * 1.15 / ROTOR_MM)
        panels.append(Panel("rotor", bal_word("end view", notation), tuple(rotor_items(masses, corrections, mu_l)),
                            (scale_text("l", mu_l),), row=0, scales=(("l", mu_l),)))
        if kind == "dynamic" and planes is not None:
            zs = [u.z for u in masses] + list(planes)
            mu_z = round_scale(max(max(zs) - min(zs), 1e-9) / SIDE_MM)
            panels.append(Panel("side", bal_word("side view", notation),
                                tuple(side_items(masses, planes, mu_z)), (scale_text("l", mu_z),), row=0,
                                scales=(("l", mu_z),)))
    if "polygon" in show:
        for c in corrections:
            name = bal_word("polygon", notation) + (bal_word("in plane", notation, c.plane) if c.plane else "")
            if c.balanced and c.plane and not any(share for _, share in c.shares):
                notes = (scale_text("W", mu_W), bal_word("none in plane", notation, c.plane))
            elif c.theta is None:  # balanced
                notes = (scale_text("W", mu_W), bal_word("closes", notation))
            else:
                notes = (scale_text("W", mu_W),
                         f"m_{{b}}r_{{b}} = {number(c.W)} kg·m, θ_{{b}} = {number(degrees_0_360(float(c.theta)))}°, "
                         f"m_{{b}} = {number(c.m_b)} kg")
            items = polygon_items(c) + (split_items(c, split_corner) if split_corner is not None else [])
            panels.append(Panel(f"polygon{c.plane}", name, tuple(items), notes, row=1,
                                scales=(("W", mu_W),)))
    return Sheet(title, tuple(panels), page, footer)


__all__ = ["BAL_WORDS", "bal_word", "balancing_sheet", "polygon_items", "rotor_items", "side_items", "split_items"]
