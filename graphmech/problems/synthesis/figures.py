"""The synthesis sheet: the construction as the book draws it — the frame line and the rocker's
circle, the limit positions DC₁, DC₂, the arcs about A that measure AC₁ and AC₂, each design's
θ-circle through A, C₁, C₂ thin — and each designed linkage bold at one limit with its dimensions.
One panel per design, at μl.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from graphmech.drawing.lettering import number, scale_text
from graphmech.drawing.primitives import (
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
    Slider,
    angle_arc,
    arc_through,
)
from graphmech.problems.synthesis.common import unit

if TYPE_CHECKING:
    from graphmech.methods.synthesis_time_ratio import (
        DrawnDesign,
        DrawnGuideBar,
        DrawnSlider,
    )
    from graphmech.problems.synthesis.check import SynthesisAnalysis

_XY = tuple[float, float]


def _arc(at: _XY, r: float, through: _XY, half_deg: float = 12.0) -> Polyline:
    """A short arc of radius r about ``at`` through the point ``through`` (a compass mark)."""
    import math

    mid = math.atan2(through[1] - at[1], through[0] - at[0])
    h = math.radians(half_deg)
    return Polyline(tuple((at[0] + r * math.cos(mid - h + 2 * h * k / 12), at[1] + r * math.sin(mid - h + 2 * h * k / 12))
                          for k in range(13)), "construction")


def design_items(g: DrawnDesign, mu: float) -> list[Primitive]:
    """One design's construction and the linkage, bold at its limit C₁."""
    p = g.points
    A, D, C1, C2, B1, B2 = p["A"], p["D"], p["C1"], p["C2"], p["B1"], p["B2"]
    items: list[Primitive] = [
        Segment(A, D, "construction", dashdot=True),
        Circle(D, g.lCD_mm, "construction"),
        Segment(D, C1, "given"), Segment(D, C2, "given", dashed=True),
        Segment(A, C1, "construction"), Segment(A, C2, "construction"),
        _arc(A, g.AC1_mm, C1), _arc(A, g.AC2_mm, C2),
    ]
    if g.circle is not None:
        items.append(theta_circle(g.circle, (A, C1, C2)))
    r = min(g.AC1_mm, g.AC2_mm) * 0.35
    theta = angle_arc(A, (C1[0] - A[0], C1[1] - A[1]), (C2[0] - A[0], C2[1] - A[1]), r)
    items += [] if theta is None else [theta]
    # the designed linkage bold at the limit C₁, dashed at the other limit C₂
    items += [Segment(A, B1, "result"), Segment(B1, C1, "result"), Segment(C1, D, "result"),
              Segment(A, B2, "given", dashed=True), Segment(B2, C2, "given", dashed=True),
              FixedPivot(A), FixedPivot(D), Hinge(B1), Hinge(B2), Hinge(C1), Hinge(C2)]
    u1, u2 = unit(A, C1), unit(A, C2)
    mid = unit((0.0, 0.0), (u1[0] + u2[0], u1[1] + u2[1])) if u1 != (-u2[0], -u2[1]) else u1
    items += [Label("A", A, (u1, u2, unit(A, D))), Label("D", D, (unit(D, A), unit(D, C1), unit(D, C2))),
              Label("B_{1}", B1), Label("B_{2}", B2), Label("C_{1}", C1), Label("C_{2}", C2)]
    if theta is not None:  # K = 1: no angle to mark
        items.append(Label("θ", (A[0] + 1.3 * r * mid[0], A[1] + 1.3 * r * mid[1])))
    return items


#: A θ-circle wider than this many times the design's own points is drawn as its arc through them.
_FULL_CIRCLE_MOST = 3.0


def theta_circle(circle: tuple[_XY, float], through: tuple[_XY, ...]) -> Circle | Polyline:
    """The θ-circle whole, as the book draws it; as its arc through A, C₁, C₂ where θ is small and
    the circle huge (K near 1: its radius C₁C₂/(2 sin θ) grows without bound)."""
    (cx, cy), r = circle
    span = max(_dist(p, q) for p in through for q in through)
    if 2.0 * r <= _FULL_CIRCLE_MOST * span:
        return Circle((cx, cy), r, "construction")
    return arc_through((cx, cy), through, margin_mm=0.15 * span)


def guide_bar_items(g: DrawnGuideBar) -> list[Primitive]:
    """The guide bar: the line CA, the bar's limit lines from C, the crank circle tangent to them
    thin; the linkage bold at B₁ (dashed at B₂); with a stroke, the bar to D₁, D₂ and H between."""
    p = g.points
    A, C, B1, B2 = p["A"], p["C"], p["B1"], p["B2"]
    items: list[Primitive] = [Segment(C, A, "construction", dashdot=True), Circle(A, g.lAB_mm, "construction")]
    ends = [p.get("D1", B1), p.get("D2", B2)]
    items += [Segment(C, ends[0], "result"), Segment(C, ends[1], "given", dashed=True),
              Segment(A, B1, "result"), Segment(A, B2, "given", dashed=True),
              FixedPivot(A), FixedPivot(C), Hinge(B1), Hinge(B2)]
    arc = angle_arc(C, unit(C, B1), unit(C, B2), 0.3 * _dist(C, A))
    items += [] if arc is None else [arc]
    items += [Label("A", A, (unit(A, C), unit(A, B1), unit(A, B2))), Label("C", C, (unit(C, A),)),
              Label("B_{1}", B1), Label("B_{2}", B2), Label("ψ = θ", (C[0], C[1] + 0.38 * _dist(C, A)))]
    if "D1" in p:
        D1, D2 = p["D1"], p["D2"]
        items += [Segment(D1, D2, "construction"), Label("D_{1}", D1), Label("D_{2}", D2),
                  Label("H", ((D1[0] + D2[0]) / 2, D1[1]), ((1.0, 0.0), (-1.0, 0.0)))]
    return items


def slider_crank_items(g: DrawnSlider) -> list[Primitive]:
    """The slider-crank: the guide through C₁C₂ = H, the θ-circle on it and the offset line thin,
    the arcs about A; the linkage bold at C₂ (the extended limit), dashed at C₁."""
    p = g.points
    A, B1, B2, C1, C2 = p["A"], p["B1"], p["B2"], p["C1"], p["C2"]
    left = min(A[0], C1[0]) - 5.0
    items: list[Primitive] = [
        GuideLine((left, 0.0), (C2[0] + 8.0, 0.0)), theta_circle(g.circle, (A, C1, C2)),
        Segment((left, A[1]), (C2[0], A[1]), "construction", dashdot=True),
        Segment(A, C1, "construction"), Segment(A, C2, "construction"),
        _arc(A, g.AC1_mm, C1), _arc(A, g.AC2_mm, C2),
        Segment(A, B2, "result"), Segment(B2, C2, "result"), Slider(C2, 0.0),
        Segment(A, B1, "given", dashed=True), Segment(B1, C1, "given", dashed=True),
        FixedPivot(A), Hinge(B1), Hinge(B2), Hinge(C1), Hinge(C2),
    ]
    r = g.AC1_mm * 0.6
    arc = angle_arc(A, unit(A, C1), unit(A, C2), r)
    items += [] if arc is None else [arc]
    items += [Label("A", A, (unit(A, C1), unit(A, C2))), Label("B_{1}", B1), Label("B_{2}", B2),
              Label("C_{1}", C1, ((0.0, 1.0),)), Label("C_{2}", C2, ((0.0, 1.0),)),
              Label("H", ((C1[0] + C2[0]) / 2.0, 0.0), ((1.0, 0.0), (-1.0, 0.0))),
              Label("e", (left, A[1] / 2.0), ((0.0, 1.0), (0.0, -1.0)))]
    return items


def _dist(p: _XY, q: _XY) -> float:
    import math

    return math.hypot(q[0] - p[0], q[1] - p[1])


def synthesis_sheet(an: SynthesisAnalysis, page: tuple[float, float], footer: tuple[str, ...] = ()) -> Sheet:
    """The sheet: one panel per design, its dimensions in the notes."""
    from graphmech.problems.synthesis.check import SELF_CONTAINED

    mu = an.scales["l"]
    p = an.scene.problem.problem
    panels = []
    own = SELF_CONTAINED.get(an.scene.problem.task)
    if own is not None:  # the task draws its own panels
        name, own_panels = own.panels(an.found, mu)
        return Sheet(an.scene.title or name, tuple(own_panels), page, footer)
    assert hasattr(p, "K")  # a time-ratio problem from here on
    if an.slider is not None:
        sc = an.slider
        notes = (scale_text("l", mu),
                 f"AC_{{1}} = {number(sc.AC1_mm)} mm, AC_{{2}} = {number(sc.AC2_mm)} mm (drawn)",
                 (f"l_{{AB}} = (AC_{{2}} − AC_{{1}})/2 = {number(sc.lAB_mm * mu * 1000)} mm, "
                  f"l_{{BC}} = (AC_{{1}} + AC_{{2}})/2 = {number(sc.lBC_mm * mu * 1000)} mm"))
        panels.append(Panel("design", "Slider-crank from K", tuple(slider_crank_items(sc)), notes, row=0,
                            scales=(("l", mu),)))
        return Sheet(an.scene.title or f"Slider-crank from its time ratio K = {p.K:g}", tuple(panels), page, footer)
    if an.guide is not None:
        gb = an.guide
        bar = () if gb.lCD_mm is None else (f"l_{{CD}} = H/(2 sin(ψ/2)) = {number(gb.lCD_mm * mu * 1000)} mm",)
        notes = (scale_text("l", mu), f"l_{{AB}} = l_{{AC}} sin(θ/2) = {number(gb.lAB_mm * mu * 1000)} mm", *bar)
        panels.append(Panel("design", "Guide bar from K", tuple(guide_bar_items(gb)), notes, row=0,
                            scales=(("l", mu),)))
        return Sheet(an.scene.title or f"Guide bar from its time ratio K = {p.K:g}", tuple(panels), page, footer)
    n = len(an.drawn)
    for k, g in enumerate(an.drawn):
        name = f"solution {k + 1}" if n > 1 else "design"
        notes = (scale_text("l", mu),
                 f"AC_{{1}} = {number(g.AC1_mm)} mm, AC_{{2}} = {number(g.AC2_mm)} mm (drawn)",
                 (f"l_{{AB}} = (AC_{{2}} − AC_{{1}})/2 = {number(g.lAB_mm * mu * 1000)} mm, "
                  f"l_{{BC}} = (AC_{{1}} + AC_{{2}})/2 = {number(g.lBC_mm * mu * 1000)} mm"))
        panels.append(Panel(f"design{k + 1}", f"Crank-rocker from K, {name}", tuple(design_items(g, mu)), notes,
                            row=0, scales=(("l", mu),)))
    title = an.scene.title or f"Crank-rocker from its time ratio K = {p.K:g}"
    return Sheet(title, tuple(panels), page, footer)


__all__ = ["design_items", "guide_bar_items", "slider_crank_items", "synthesis_sheet"]
