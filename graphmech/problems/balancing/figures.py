"""The figures of a balancing problem: the rotor and its mass-radius polygons.

rotor
    the end view (at μl): the rotor's circle, each eccentric mass a small circle on its radius,
    labelled m₁, m₂ …, the correction masses bold on their radii (r_b); for a dynamic balance
    also a side view: the shaft, the planes of the masses (thin) and the correction planes I and
    II (bold), with their axial positions.
polygon
    one panel per correction plane (at μW): the mass-radius products W₁, W₂ … head to tail
    (thin arrows, each parallel to its mass's radius — in a correction plane the lever-rule
    shares, reversed where a mass lies outside the planes), and the closing side W_b from the
    last end back to the start (bold), its magnitude and angle in the notes.
"""
from __future__ import annotations

import math
from typing import Any, Sequence

from graphmech.geometry.primitives import degrees_0_360
from graphmech.methods.balancing import Correction
from graphmech.drawing.primitives import Arrow, Circle, Label, Panel, Primitive, Segment, Sheet
from graphmech.drawing.lettering import subscript
from graphmech.scales import format_scale, round_scale

#: The rotor's end view radius on paper, about, mm.
ROTOR_MM = 30.0


def _w_name(name: str) -> str:
    """``"W1I"`` → ``W₁ I``, ``"WbII"`` → ``W_b II``."""
    body = name[1:]
    plane = "II" if body.endswith("II") else "I" if body.endswith("I") and not body.isdigit() else ""
    core = body[: len(body) - len(plane)]
    core = "b" if core == "b" else subscript(core) if core.isdigit() else core
    return "W" + (core if core != "b" else "b") + (" " + plane if plane else "")


def polygon_items(c: Correction) -> list[Primitive]:
    items: list[Primitive] = []
    for s in c.sides:
        if math.hypot(s.end[0] - s.start[0], s.end[1] - s.start[1]) < 1e-9:
            continue
        items.append(Arrow(s.start, s.end, "given"))
        d = (s.end[0] - s.start[0], s.end[1] - s.start[1])
        n = math.hypot(*d)
        items.append(Label(_w_name(s.name), ((s.start[0] + s.end[0]) / 2, (s.start[1] + s.end[1]) / 2),
                           ((d[0] / n, d[1] / n), (-d[0] / n, -d[1] / n)), 3.2))
    if not c.balanced:
        s = c.closing
        items.append(Arrow(s.start, s.end, "result"))
        d = (s.end[0] - s.start[0], s.end[1] - s.start[1])
        n = math.hypot(*d)
        items.append(Label(_w_name(s.name), ((s.start[0] + s.end[0]) / 2, (s.start[1] + s.end[1]) / 2),
                           ((d[0] / n, d[1] / n), (-d[0] / n, -d[1] / n)), 3.4))
    if not items:  # no mass has a share in this plane: the polygon is its start point, closed
        items = [Circle((0.0, 0.0), 0.8, "result"), Label("o", (0.0, 0.0), (), 3.2)]
    return items


def rotor_items(masses: Sequence[Any], corrections: Sequence[Correction], mu_l: float) -> list[Primitive]:
    R = max([u.r for u in masses] + [c.r_b for c in corrections]) * 1.15 / mu_l
    items: list[Primitive] = [Circle((0.0, 0.0), R, "given"), Segment((-R - 4, 0.0), (R + 4, 0.0), "construction", True),
                              Segment((0.0, -R - 4), (0.0, R + 4), "construction", True)]
    for u in masses:
        p = (u.r / mu_l * math.cos(u.theta), u.r / mu_l * math.sin(u.theta))
        items += [Segment((0.0, 0.0), p, "given"), Circle(p, 1.6, "given"),
                  Label("m" + subscript(u.name) if u.name.isdigit() else f"m {u.name}", p,
                        ((-math.cos(u.theta), -math.sin(u.theta)),), 3.0)]
    for c in corrections:
        if c.theta is None:  # balanced
            continue
        th = float(c.theta)
        p = (c.r_b / mu_l * math.cos(th), c.r_b / mu_l * math.sin(th))
        items += [Segment((0.0, 0.0), p, "result"), Circle(p, 2.2, "result"),
                  Label("mb" + (" " + c.plane if c.plane else ""), p, ((-math.cos(th), -math.sin(th)),), 3.2)]
    return items


def side_items(masses: Sequence[Any], planes: tuple[float, float], mu_z: float) -> list[Primitive]:
    zs = [u.z for u in masses] + list(planes)
    lo, hi = min(zs), max(zs)
    items: list[Primitive] = [Segment(((lo - 0.1 * (hi - lo)) / mu_z, 0.0), ((hi + 0.1 * (hi - lo)) / mu_z, 0.0),
                                      "construction", True)]
    for u in masses:
        x = u.z / mu_z
        items += [Segment((x, -8.0), (x, 8.0), "given"), Label("m" + subscript(u.name) if u.name.isdigit() else u.name,
                                                                (x, 10.5), ((0.0, -1.0),), 2.8)]
    for name, z in zip(("I", "II"), planes):
        x = z / mu_z
        items += [Segment((x, -12.0), (x, 12.0), "result"), Label(name, (x, -15.0), ((0.0, 1.0),), 3.2, italic=False)]
    return items


def balancing_sheet(title: str, kind: str, masses: Sequence[Any], planes: tuple[float, float] | None,
                    corrections: Sequence[Correction], mu_W: float, show: Sequence[str], page: tuple[float, float],
                    footer: tuple[str, ...] = ()) -> Sheet:
    """The sheet: the rotor (end view; a dynamic one also from the side) and a polygon per plane."""
    panels: list[Panel] = []
    if "rotor" in show:
        R = max([u.r for u in masses] + [c.r_b for c in corrections])
        mu_l = round_scale(R * 1.15 / ROTOR_MM)
        panels.append(Panel("rotor", "rotor: end view", tuple(rotor_items(masses, corrections, mu_l)),
                            (format_scale("l", mu_l),), row=0))
        if kind == "dynamic" and planes is not None:
            zs = [u.z for u in masses] + list(planes)
            mu_z = round_scale(max(max(zs) - min(zs), 1e-9) / 90.0)
            panels.append(Panel("side", "rotor: side view, correction planes I and II",
                                tuple(side_items(masses, planes, mu_z)), (format_scale("l", mu_z),), row=0))
    if "polygon" in show:
        for c in corrections:
            name = "mass-radius polygon" + (f", plane {c.plane}" if c.plane else "")
            if c.balanced and c.plane and not any(share for _, share in c.shares):
                notes = (format_scale("W", mu_W), f"no mass acts in plane {c.plane}: no correction mass needed")
            elif c.theta is None:  # balanced
                notes = (format_scale("W", mu_W), "closes by itself: no correction mass needed")
            else:
                notes = (format_scale("W", mu_W),
                         f"mb·rb = {c.W:.5g} kg·m, θb = {degrees_0_360(float(c.theta)):.4g}°, "
                         f"mb = {c.m_b:.4g} kg")
            panels.append(Panel(f"polygon{c.plane}", name, tuple(polygon_items(c)), notes, row=1))
    return Sheet(title, tuple(panels), page, footer)


__all__ = ["balancing_sheet", "polygon_items", "rotor_items", "side_items"]
