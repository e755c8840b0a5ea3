"""The figures of the other mechanisms.

geneva
    the Geneva wheel at μl as the book draws it: the wheel (centre O₂) with its z slots (two
    parallel sides 2r apart, a round bottom h deep) and its concave locking arcs between them,
    the dial's arm O₁A with the pin (radius r) in a slot at the dial angle, the dial's convex
    locking arc (radius R − r − b, cut away on the pin's side), the pin's circle R and the line
    of centres dash-dot, the entry point K with O₁K ⟂ O₂K.
geneva_polygons
    the pin's velocity polygon (p a₁ a₂, at μv) and acceleration polygon (π a₁′ n₂′ k′ a₂′, at μa).
geneva_curves
    ω₂(φ) and ε₂(φ) across the engagement, constructed at 49 dial angles.
differential_screw
    the screw: link 1 (a rod with the handwheel) in the frame 3 through screw A and in link 2
    through screw B, link 2 sliding in the frame's guide C; each screw's lead and hand written.
"""
from __future__ import annotations

import math
from typing import Literal

from graphmech.drawing.lettering import LETTER, number, scale_text
from graphmech.drawing.notation import word
from graphmech.drawing.primitives import (
    ArcArrow,
    Arrow,
    Circle,
    FixedPivot,
    GuideLine,
    Hinge,
    Label,
    Panel,
    Polyline,
    Primitive,
    Segment,
    Sheet,
    Text,
)
from graphmech.problems.other.check import OtherAnalysis
from graphmech.scales import round_scale

XY = tuple[float, float]

#: The sheet's words (English, 中文, русский), drawn text only.
OTHER_WORDS: dict[str, tuple[str, str, str]] = {
    "geneva": ("Geneva wheel, z = «z», φ = «phi»°", "槽轮机构，z = «z»，φ = «phi»°", "Мальтийский механизм, z = «z», φ = «phi»°"),
    "curves": ("Wheel's ω₂(φ) and ε₂(φ) while the pin drives it", "槽轮的ω₂(φ)、ε₂(φ)曲线",
               "ω₂(φ) и ε₂(φ) креста за время зацепления"),
    "screw": ("Differential screw", "差动螺旋机构", "Дифференциальный винт"),
    "velocity polygon": ("Velocity polygon of the pin", "圆销的速度多边形", "план скоростей пальца"),
    "acceleration polygon": ("Acceleration polygon of the pin", "圆销的加速度多边形", "план ускорений пальца"),
}


def _w(key: str, notation: str) -> str:
    return word(key, notation, OTHER_WORDS)


def _arc(c: XY, r: float, a0: float, a1: float, n: int = 24) -> list[XY]:
    return [(c[0] + r * math.cos(a0 + (a1 - a0) * k / n), c[1] + r * math.sin(a0 + (a1 - a0) * k / n))
            for k in range(n + 1)]


def wheel_outline(O2: XY, S: float, h: float, r: float, r_lock: float, L: float, z: int, theta0: float) -> list[XY]:
    """The wheel's outline (drawing mm): for each slot (axis at θ₀ + 2πk/z from O₂) its sides and
    round bottom, then the tip's outer arc, the concave locking arc (centre L from O₂ on the
    bisector, radius r_lock), the next tip."""
    Ro = math.hypot(S, r)
    c = (Ro * Ro + L * L - r_lock * r_lock) / (2 * Ro * L)
    delta = math.acos(max(-1.0, min(1.0, c)))  # the locking arc meets the outer circle at θm ± δ
    tip = math.atan2(r, S)
    pts: list[XY] = []
    for k in range(z):
        th = theta0 + 2 * math.pi * k / z
        u, n = (math.cos(th), math.sin(th)), (-math.sin(th), math.cos(th))
        depth = S - h + r  # the bottom's centre from O₂

        def at(a: float, b: float, u: XY = u, n: XY = n) -> XY:
            return (O2[0] + a * u[0] + b * n[0], O2[1] + a * u[1] + b * n[1])

        pts += [at(S, -r), at(depth, -r)]
        pts += [at(depth + r * math.cos(a), r * math.sin(a)) for a in
                (math.pi * (1.5 - j / 12) for j in range(13))]  # the round bottom, −r side to +r side
        pts.append(at(S, r))
        tm = th + math.pi / z
        if th + tip < tm - delta:
            pts += _arc(O2, Ro, th + tip, tm - delta, 6)
            C = (O2[0] + L * math.cos(tm), O2[1] + L * math.sin(tm))
            P0, P1 = _arc(O2, Ro, tm - delta, tm - delta, 1)[0], _arc(O2, Ro, tm + delta, tm + delta, 1)[0]
            b0 = math.atan2(P0[1] - C[1], P0[0] - C[0])
            b1 = math.atan2(P1[1] - C[1], P1[0] - C[0])
            if b1 > b0:  # go round C the short way, through the side facing O₂
                b1 -= 2 * math.pi
            pts += _arc(C, r_lock, b0, b1, 20)
            pts += _arc(O2, Ro, tm + delta, th + 2 * math.pi / z - tip, 6)
        else:
            pts += _arc(O2, Ro, th + tip, th + 2 * math.pi / z - tip, 12)
    return pts


def geneva_items(an: OtherAnalysis) -> tuple[list[Primitive], float]:
    g, lay = an.scene.problem.geneva, an.lay
    assert g is not None and lay is not None
    mu = an.scales["l"]
    O1, O2 = lay.O1, lay.O2
    R, r, L = lay.R_mm, g.r_pin / mu, g.L / mu
    phi = g.phi if g.phi is not None else -lay.half_angle * 0.5
    A = (O1[0] + R * math.cos(phi), O1[1] + R * math.sin(phi))
    theta0 = math.atan2(A[1] - O2[1], A[0] - O2[0])  # a slot along O₂A
    items: list[Primitive] = [
        Polyline(tuple(wheel_outline(O2, lay.S_mm, lay.h_mm, r, lay.r_lock_mm, L, g.z, theta0)), "given", closed=True),
        Segment((O1[0] - R - 6, 0.0), (O2[0] + lay.S_mm + 6, 0.0), "construction", dashdot=True),
        Circle(O1, R, "construction", dashdot=True),
        Polyline(tuple(_arc(O1, lay.r_lock_mm, phi + lay.half_angle + 0.35, phi + 2 * math.pi - lay.half_angle - 0.35,
                            60)), "given"),
        Segment(O1, A, "given"), Circle(A, r, "given"),
        Segment(O1, lay.K, "construction", dashed=True), Segment(O2, lay.K, "construction", dashed=True),
        FixedPivot(O1), FixedPivot(O2), Hinge(A),
        Label("O_{1}", O1, ((1.0, 0.0), (math.cos(phi), math.sin(phi))), LETTER),
        Label("O_{2}", O2, ((-1.0, 0.0),), LETTER),
        Label("A", A, ((-math.cos(phi), -math.sin(phi)),), LETTER),
        Label("K", lay.K, (), LETTER),
        Label("1", ((O1[0] + A[0]) / 2, (O1[1] + A[1]) / 2), (), LETTER, italic=False),
        Label("2", (O2[0] + 0.5 * lay.S_mm * math.cos(theta0 + math.pi / g.z),
                    O2[1] + 0.5 * lay.S_mm * math.sin(theta0 + math.pi / g.z)), (), LETTER, italic=False),
        ArcArrow(O1, 0.45 * R, phi + 0.6, 0.9, "given"),
        Label("ω_{1}", (O1[0] + 0.45 * R * math.cos(phi + 1.05), O1[1] + 0.45 * R * math.sin(phi + 1.05)), (), LETTER),
    ]
    if an.at_angle is not None and abs(an.at_angle.omega2) > 1e-9 * g.omega1:  # at entry or exit ω₂ = 0: no sense
        s = math.copysign(0.9, an.at_angle.omega2)
        items += [ArcArrow(O2, 0.3 * lay.S_mm, theta0 + math.pi / g.z, s, "result"),
                  Label("ω_{2}", (O2[0] + 0.3 * lay.S_mm * math.cos(theta0 + math.pi / g.z + s),
                                  O2[1] + 0.3 * lay.S_mm * math.sin(theta0 + math.pi / g.z + s)), (), LETTER)]
    return items, math.degrees(phi)


def _arrow(a: XY, b: XY, role: Literal["given", "result"]) -> list[Primitive]:
    """The vector a → b, or nothing where it vanishes (ω₂ = 0 at entry, no Coriolis term at φ = 0)."""
    return [Arrow(a, b, role)] if math.hypot(b[0] - a[0], b[1] - a[1]) > 1e-6 else []


def polygon_items(an: OtherAnalysis) -> tuple[list[Primitive], list[Primitive]]:
    pp = an.at_angle
    assert pp is not None
    o = (0.0, 0.0)
    v: list[Primitive] = [*_arrow(o, pp.a1, "given"), *_arrow(o, pp.a2, "result"), *_arrow(pp.a2, pp.a1, "result"),
                          Label("p", o, (), LETTER), Label("a_{1}", pp.a1, (), LETTER), Label("a_{2}", pp.a2, (), LETTER)]
    a: list[Primitive] = [*_arrow(o, pp.a1_, "given"), *_arrow(o, pp.n2_, "given"), *_arrow(pp.k_, pp.a1_, "given"),
                          *_arrow(pp.n2_, pp.a2_, "result"), *_arrow(pp.a2_, pp.k_, "result"),
                          *_arrow(o, pp.a2_, "result"),
                          Label("π", o, (), LETTER), Label("a_{1}′", pp.a1_, (), LETTER),
                          Label("n_{2}′", pp.n2_, (), LETTER), Label("k′", pp.k_, (), LETTER),
                          Label("a_{2}′", pp.a2_, (), LETTER)]
    return v, a


def curve_items(an: OtherAnalysis) -> tuple[list[Primitive], list[str]]:
    """ω₂ above, ε₂ below, against φ (degrees) — 100 mm across the engagement."""
    phis = [math.degrees(c[0]) for c in an.curves]
    w = [c[1] for c in an.curves]
    e = [c[2] for c in an.curves]
    mu_phi = round_scale((phis[-1] - phis[0]) / 100.0)
    mu_w = round_scale(max(abs(x) for x in w) / 25.0)
    mu_e = round_scale(max(abs(x) for x in e) / 18.0)
    x0, x1 = phis[0] / mu_phi, phis[-1] / mu_phi
    top = 0.0
    low = -max(abs(x) for x in w) / mu_w - 28.0  # the ε₂ axis below the ω₂ curve
    items: list[Primitive] = [
        Arrow((x0 - 4, top), (x1 + 8, top), "construction"), Segment((0.0, top - 2), (0.0, top + 30), "construction"),
        Polyline(tuple((p / mu_phi, top + y / mu_w) for p, y in zip(phis, w)), "result"),
        Label("φ", (x1 + 8, top), (), LETTER), Label("ω_{2}", (0.0, top + 30), (), LETTER),
        Arrow((x0 - 4, low), (x1 + 8, low), "construction"), Segment((0.0, low - 21), (0.0, low + 21), "construction"),
        Polyline(tuple((p / mu_phi, low + y / mu_e) for p, y in zip(phis, e)), "result"),
        Label("φ", (x1 + 8, low), (), LETTER), Label("ε_{2}", (0.0, low + 21), (), LETTER),
        Text(number(phis[0]) + "°", (x0, top - 4)), Text(number(phis[-1]) + "°", (x1, top - 4)),
    ]
    notes = [f"μ_{{φ}} = {number(mu_phi)} °/mm", f"μ_{{ω}} = {number(mu_w)} (rad/s)/mm",
             f"μ_{{ε}} = {number(mu_e)} (rad/s²)/mm"]
    return items, notes


def screw_items(an: OtherAnalysis) -> list[Primitive]:
    """Link 1 a rod with a handwheel, screw A in the frame's nut, screw B in link 2's nut; 2 slides on C."""
    s = an.scene.problem.screw
    assert s is not None
    items: list[Primitive] = [Segment((-10.0, 0.0), (130.0, 0.0), "construction", dashdot=True),
                              Segment((-2.0, -14.0), (-2.0, 14.0), "given"),  # the handwheel, edge on
                              Segment((-2.0, 0.0), (118.0, 0.0), "given")]

    def thread(x0: float, x1: float, r: float) -> list[Primitive]:
        zig = [(x0 + (x1 - x0) * k / 12, r * (1 if k % 2 else -1)) for k in range(13)]
        return [Polyline(tuple(zig), "given"), Segment((x0, -r), (x1, -r), "construction"),
                Segment((x0, r), (x1, r), "construction")]

    items += thread(20.0, 45.0, 4.0) + thread(75.0, 100.0, 4.0)
    # the frame's nut A: a block on the hatched ground; link 2's nut B: a block sliding on the guide C
    items += [Polyline(((18.0, -9.0), (47.0, -9.0), (47.0, 9.0), (18.0, 9.0)), "given", closed=True),
              Segment((32.5, -9.0), (32.5, -20.0), "given"), GuideLine((10.0, -20.0), (55.0, -20.0)),
              Polyline(((73.0, -9.0), (102.0, -9.0), (102.0, 9.0), (73.0, 9.0)), "given", closed=True),
              Polyline(((80.0, -9.0), (95.0, -9.0), (95.0, -16.0), (80.0, -16.0)), "given", closed=True),
              GuideLine((65.0, -16.0), (112.0, -16.0)),
              Label("1", (10.0, 0.0), (), LETTER, italic=False), Label("3", (32.5, -25.0), (), LETTER, italic=False),
              Label("2", (87.5, 12.0), (), LETTER, italic=False), Label("A", (32.5, 12.0), (), LETTER),
              Label("B", (108.0, 6.0), (), LETTER), Label("C", (87.5, -21.0), (), LETTER)]
    lines = [f"p_{{A}} = {number(s.p_A * 1000)} mm, {s.hand_A}-hand"]
    for n, p, h, m in an.screw:
        if n == "s_B":
            lines = [lines[0], f"p_{{B}} = {number((s.p_B or 0.0) * 1000)} mm, {s.hand_B}-hand",
                     f"s_{{2}} = {number(p * 1000)} mm per turn of 1"]
        else:
            lines.append(f"p_{{B}} = {number(p * 1000)} mm, {h}-hand ({'2 against 1' if m == 'against' else '2 with 1'})")
    items += [Text(t, (0.0, -34.0 - 6.0 * i), anchor="start") for i, t in enumerate(lines)]
    return items


def other_sheet(an: OtherAnalysis, page: tuple[float, float], footer: tuple[str, ...] = ()) -> Sheet:
    """The sheet of the scene's ``show``."""
    notation = an.scene.page.notation
    show = an.scene.show
    panels: list[Panel] = []
    g = an.scene.problem.geneva
    if g is not None and "geneva" in show:
        items, phi = geneva_items(an)
        title = _w("geneva", notation).replace("«z»", str(g.z)).replace("«phi»", number(phi))
        panels.append(Panel("geneva", title, tuple(items), (scale_text("l", an.scales["l"]),), row=0,
                            scales=(("l", an.scales["l"]),)))
    if g is not None and "geneva_polygons" in show and an.at_angle is not None:
        v, a = polygon_items(an)
        panels.append(Panel("velocity", _w("velocity polygon", notation), tuple(v), (scale_text("v", an.scales["v"]),),
                            row=1, scales=(("v", an.scales["v"]),)))
        panels.append(Panel("acceleration", _w("acceleration polygon", notation), tuple(a),
                            (scale_text("a", an.scales["a"]),), row=1, scales=(("a", an.scales["a"]),)))
    if g is not None and "geneva_curves" in show and an.curves:
        items_c, notes = curve_items(an)
        panels.append(Panel("curves", _w("curves", notation), tuple(items_c), tuple(notes), row=1))
    if an.scene.problem.screw is not None and "differential_screw" in show:
        panels.append(Panel("screw", _w("screw", notation), tuple(screw_items(an)), (), row=0))
    return Sheet(an.scene.title, tuple(panels), page, footer)


__all__ = ["OTHER_WORDS", "curve_items", "geneva_items", "other_sheet", "polygon_items", "screw_items",
           "wheel_outline"]
