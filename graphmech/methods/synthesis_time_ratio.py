"""Design from the time ratio K, drawn as the book draws it (孙桓 §8 按行程速比系数设计四杆机构).

θ = 180°(K − 1)/(K + 1) is the crank angle between the rocker's limit positions C₁, C₂; the crank
pin B is collinear with A and C at both, so AC₁ and AC₂ are BC ∓ AB and, once measured on the
drawing, give the crank l_AB = (AC₂ − AC₁)/2 and the coupler l_BC = (AC₁ + AC₂)/2.

crank-rocker from the rocker l_CD, the frame l_AD and one limit position ∠ADC₁ (the bank's
    variant): draw the frame line AD, lay off DC₁ at the limit angle, join AC₁, lay off a ray from A
    at θ to AC₁ (either side) and cut it with the rocker's circle about D: each cut is a C₂.
crank-rocker from l_CD, l_AD and the swing ψ: draw C₁, C₂ on the rocker's circle ψ apart; the
    θ-circle: from C₁ a line at 90° − θ to C₁C₂ meets the chord's perpendicular bisector at the
    centre O (either side of the chord), radius OC₁; every point of the arc on O's side sees
    C₁C₂ at θ. The circle of radius l_AD about D cuts it at A.

slider-crank from the stroke H and the offset e: C₁C₂ = H on the guide, the θ-circle on that chord,
    cut by the line at e from the guide at A (behind C₁).
guide bar from the frame l_AC (and the ram's stroke H): the bar's limit lines from C at ψ/2 = θ/2
    either side of CA; the perpendicular from A to one is the crank; D₁D₂ = H gives the bar.

Each crank-rocker's θ-circle (through A, C₁, C₂: the centre where the bisectors of AC₁ and C₁C₂ meet) is
drawn for both variants. A design is kept where C₁ and C₂ lie on one side of the frame line (one
assembly branch) and the crank is the Grashof crank (:func:`graphmech.methods.characteristics.
grashof_class` on the measured lengths); mirror images are one design. Everything is drawn in
millimetres at μl with the construction kernels; the closed forms are
:mod:`graphmech.exact.synthesis` (not used here).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Literal

from graphmech.errors import AssemblyError, DegenerateConstruction
from graphmech.geometry.kernels import (
    ScalarOps,
    intersect_circle_line,
    intersect_circles,
    intersect_lines,
)
from graphmech.methods.characteristics import grashof_class

__all__ = ["DrawnDesign", "DrawnGuideBar", "DrawnSlider", "draw_from_limit", "draw_from_swing", "draw_guide_bar",
           "draw_slider_crank", "theta_of_K"]

_XY = tuple[float, float]
#: Below this, relative to the linkage's size on paper, the crank has no length (C₂ on C₁).
NO_CRANK = 1e-9


def theta_of_K(K: float) -> float:
    """θ = 180°(K − 1)/(K + 1), rad (as the book computes it before drawing)."""
    return math.radians(180.0 * (K - 1.0) / (K + 1.0))


@dataclass(frozen=True)
class DrawnDesign:
    """One designed crank-rocker on the drawing, mm: A, D, C₁, C₂, the crank pins B₁, B₂ at the
    limits, the measured AC₁, AC₂ and the θ-circle (centre, radius; None when θ = 0: a line)."""

    points: dict[str, _XY] = field(hash=False)
    AC1_mm: float
    AC2_mm: float
    circle: tuple[_XY, float] | None
    #: the largest condition number of the cuts that placed the design (≈ 1/sin of their angle):
    #: K near 1 makes the θ-circle huge and its cuts shallow
    cond: float = 1.0

    @property
    def lAB_mm(self) -> float:
        return abs(self.AC2_mm - self.AC1_mm) / 2.0

    @property
    def lBC_mm(self) -> float:
        return (self.AC1_mm + self.AC2_mm) / 2.0

    @property
    def lCD_mm(self) -> float:
        return _dist(self.points["C1"], self.points["D"])

    @property
    def lAD_mm(self) -> float:
        return _dist(self.points["A"], self.points["D"])

    @property
    def branch(self) -> Literal["left", "right"]:
        """The side of the directed line B₁ → D that C₁ lies to."""
        return "left" if _left(self.points["B1"], self.points["D"], self.points["C1"]) > 0.0 else "right"

    @property
    def theta(self) -> float:
        """∠C₁AC₂ measured on the drawing, rad."""
        A, C1, C2 = self.points["A"], self.points["C1"], self.points["C2"]
        u, v = (C1[0] - A[0], C1[1] - A[1]), (C2[0] - A[0], C2[1] - A[1])
        return abs(math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1]))


def _dist(p: _XY, q: _XY) -> float:
    return math.hypot(q[0] - p[0], q[1] - p[1])


def _left(p: _XY, q: _XY, r: _XY) -> float:
    return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])


def _polar(at: _XY, r: float, angle: float) -> _XY:
    """The point r mm from ``at`` at ``angle`` (a protractor and a rule)."""
    return (at[0] + r * math.cos(angle), at[1] + r * math.sin(angle))


def _bisector(ops: ScalarOps, p: _XY, q: _XY) -> tuple[float, float, float, float]:
    n = _dist(p, q)
    return ((p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0, -(q[1] - p[1]) / n, (q[0] - p[0]) / n)


def _design(ops: ScalarOps, A: _XY, D: _XY, C1: _XY, C2: _XY) -> DrawnDesign | None:
    """Measure AC₁, AC₂; keep a one-branch Grashof crank-rocker; its θ-circle."""
    cond = max(ops.conds.values(), default=1.0)  # the cuts so far placed A, C₁, C₂
    ac1, ac2 = _dist(A, C1), _dist(A, C2)
    a, b, c, d = abs(ac2 - ac1) / 2.0, (ac1 + ac2) / 2.0, _dist(D, C1), _dist(A, D)
    if a <= NO_CRANK * (b + c + d) or _left(A, D, C1) * _left(A, D, C2) <= 0.0:
        return None
    if grashof_class(a, b, c, d) != "crank_rocker_AB":
        return None
    pins = {}
    for name, C, ac in (("B1", C1, ac1), ("B2", C2, ac2)):
        t = a if ac > min(ac1, ac2) else -a  # ahead of A at the extended limit, behind at the folded
        pins[name] = (A[0] + t * (C[0] - A[0]) / ac, A[1] + t * (C[1] - A[1]) / ac)
    circle = None
    drawing = ScalarOps()  # the circle is drawn, not measured: its cut is not the design's
    drawing.step = "O = bisector(AC₁) ∩ bisector(C₁C₂)"
    try:
        O = intersect_lines(drawing, _bisector(drawing, A, C1), _bisector(drawing, C1, C2))
        circle = ((O[0], O[1]), _dist(O, C1))
    except DegenerateConstruction:  # θ = 0: A on the line C₁C₂, no circle
        pass
    return DrawnDesign({"A": A, "D": D, "C1": C1, "C2": C2, **pins}, ac1, ac2, circle, float(cond))


def _distinct(designs: list[DrawnDesign]) -> list[DrawnDesign]:
    out: list[DrawnDesign] = []
    for x in designs:
        if not any(abs(x.AC1_mm - y.AC1_mm) <= 1e-9 * x.lAD_mm and abs(x.AC2_mm - y.AC2_mm) <= 1e-9 * x.lAD_mm
                   for y in out):
            out.append(x)
    return sorted(out, key=lambda x: -x.lBC_mm)


def draw_from_limit(c_mm: float, d_mm: float, limit: float, theta: float) -> list[DrawnDesign]:
    """The crank-rockers with rocker c_mm, frame d_mm, a limit position at ∠ADC₁ = ``limit`` and
    θ, drawn with A at the origin and D on the x axis; longest coupler first.

    >>> [round(x.lAB_mm, 6) for x in draw_from_limit(37.5, 50.0, math.radians(45), math.radians(36))]
    [24.655882, 11.255997]
    """
    ops = ScalarOps()
    A, D = (0.0, 0.0), (d_mm, 0.0)
    C1 = _polar(D, c_mm, math.pi - limit)  # DC₁ at the limit angle to DA
    toward = math.atan2(C1[1], C1[0])  # the direction of AC₁
    found = []
    for s in (-1.0, 1.0):
        ray = (A[0], A[1], math.cos(toward + s * theta), math.sin(toward + s * theta))
        for side in (1.0, -1.0):
            ops.step = "C₂ = ray(A, θ to AC₁) ∩ circle(D, l_CD)"
            try:
                C2 = intersect_circle_line(ops, D, c_mm, ray, side, lambda e: "the ray misses the rocker's circle")
            except AssemblyError:
                break
            if (C2[0] - A[0]) * ray[2] + (C2[1] - A[1]) * ray[3] <= 0.0:  # behind A: not on the ray
                continue
            x = _design(ops, A, D, C1, C2)
            if x is not None:
                found.append(x)
    return _distinct(found)


def draw_from_swing(c_mm: float, d_mm: float, psi: float, theta: float,
                    middle: float = math.pi / 2) -> list[DrawnDesign]:
    """The crank-rockers with rocker c_mm, frame d_mm, swing ψ and θ, drawn with D at the origin
    and C₁, C₂ at ``middle`` ± ψ/2 (the rocker's middle position upright by default); one of each
    mirror pair (A to the left of the middle position DC); longest coupler first.

    >>> [round(x.lAB_mm, 6) for x in draw_from_swing(37.5, 50.0, math.radians(40), math.radians(36))]
    [11.018694]
    """
    ops = ScalarOps()
    D = (0.0, 0.0)
    C1, C2 = _polar(D, c_mm, middle + psi / 2), _polar(D, c_mm, middle - psi / 2)
    ux, uy = math.cos(middle), math.sin(middle)

    def left(P: _XY) -> bool:  # of the middle position's line from D
        return ux * P[1] - uy * P[0] > 0.0

    chord = _dist(C1, C2)
    u = ((C2[0] - C1[0]) / chord, (C2[1] - C1[1]) / chord)
    found = []
    if theta == 0.0:  # the locus is the line C₁C₂ itself
        for side in (1.0, -1.0):
            ops.step = "A = line(C₁C₂) ∩ circle(D, l_AD)"
            try:
                A = intersect_circle_line(ops, D, d_mm, (C1[0], C1[1], u[0], u[1]), side, lambda e: "no A")
            except AssemblyError:
                break
            if left(A):
                found.append(_design(ops, A, D, C1, C2))
        return _distinct([x for x in found if x is not None])
    mid = _bisector(ops, C1, C2)
    for s in (1.0, -1.0):  # O below the chord (D's side, the chord turned right), then above it
        turn = -s * (math.pi / 2 - theta)
        ops.step = "O = line(C₁, 90° − θ to C₁C₂) ∩ bisector(C₁C₂)"
        O = intersect_lines(ops, (C1[0], C1[1], u[0] * math.cos(turn) - u[1] * math.sin(turn),
                                  u[0] * math.sin(turn) + u[1] * math.cos(turn)), mid)
        R = _dist(O, C1)
        for side in (1.0, -1.0):
            ops.step = "A = θ-circle ∩ circle(D, l_AD)"
            try:
                A = intersect_circles(ops, O, R, D, d_mm, side, lambda dd: "the θ-circle misses the frame's circle")
            except AssemblyError:
                break
            # on the arc that sees C₁C₂ at θ (O's side of the chord), left of the middle position
            if _left(C1, C2, A) * _left(C1, C2, O) > 0.0 and left(A):
                found.append(_design(ops, A, D, C1, C2))
    return _distinct([x for x in found if x is not None])


@dataclass(frozen=True)
class DrawnGuideBar:
    """A guide bar (shaper) designed from K on the drawing, mm: the bar's pivot C, the crank's A
    above it, the crank pins B₁, B₂ where the bar is tangent to the crank circle and — with a
    stroke — the bar's ends D₁, D₂, the ram's stroke apart."""

    points: dict[str, _XY] = field(hash=False)
    lAB_mm: float
    lCD_mm: float | None


def draw_guide_bar(d_mm: float, theta: float, H_mm: float | None = None) -> DrawnGuideBar:
    """The guide bar with l_AC = d_mm and θ (= ψ): the bar's limit lines from C at ψ/2 either side
    of CA; the perpendicular from A to a limit line is the crank AB₁ (the crank circle touches the
    bar there). With the ram's stroke H: D₁D₂ = H laid off ⟂ CA, cut by the limit lines: l_CD = CD₂.

    >>> g = draw_guide_bar(100.0, math.radians(60), 100.0)
    >>> round(g.lAB_mm, 9), round(g.lCD_mm, 9)
    (50.0, 100.0)
    """
    ops = ScalarOps()
    C, A = (0.0, 0.0), (0.0, d_mm)
    pts: dict[str, _XY] = {"A": A, "C": C}
    lengths = []
    for name, s in (("1", 1.0), ("2", -1.0)):
        u = (-s * math.sin(theta / 2.0), math.cos(theta / 2.0))  # the limit line's direction from C
        ops.step = f"B{name} = perpendicular(A, C-limit line {name})"
        B = intersect_lines(ops, (C[0], C[1], u[0], u[1]), (A[0], A[1], -u[1], u[0]))
        pts["B" + name] = B
        lengths.append(_dist(A, B))
        if H_mm is not None:
            ops.step = f"D{name} = limit line {name} ∩ (H/2 from CA)"
            pts["D" + name] = intersect_lines(ops, (C[0], C[1], u[0], u[1]), (-s * H_mm / 2.0, 0.0, 0.0, 1.0))
    return DrawnGuideBar(pts, lengths[0], None if H_mm is None else _dist(C, pts["D2"]))


@dataclass(frozen=True)
class DrawnSlider:
    """A slider-crank designed from K on the drawing, mm: the slider's limits C₁, C₂ on the guide
    (the x axis), the crank's pivot A at the offset, the crank pins B₁, B₂, the θ-circle."""

    points: dict[str, _XY] = field(hash=False)
    AC1_mm: float
    AC2_mm: float
    circle: tuple[_XY, float]
    #: the largest condition number of the cuts that placed A (as :attr:`DrawnDesign.cond`)
    cond: float = 1.0

    @property
    def lAB_mm(self) -> float:
        return (self.AC2_mm - self.AC1_mm) / 2.0

    @property
    def lBC_mm(self) -> float:
        return (self.AC1_mm + self.AC2_mm) / 2.0


def draw_slider_crank(H_mm: float, e_mm: float, theta: float) -> DrawnSlider | None:
    """The slider-crank with stroke H, offset e and θ > 0: C₁C₂ = H on the guide; the θ-circle on
    it (from C₁ a line at 90° − θ to C₁C₂ meets the bisector at O); the line at the offset e from
    the guide cuts it at A — the cut behind C₁, so that the slider stays ahead of A at both limits.
    None where there is none, or its crank does not turn fully (l_AB + e ≥ l_BC).

    >>> s = draw_slider_crank(50.0, 10.0, math.radians(36))
    >>> round(s.lAB_mm, 6), round(s.lBC_mm, 6)
    (23.318878, 37.341945)
    """
    ops = ScalarOps()
    C1, C2 = (0.0, 0.0), (H_mm, 0.0)
    turn = math.pi / 2 - theta  # towards the offset's side (+y)
    ops.step = "O = line(C₁, 90° − θ to C₁C₂) ∩ bisector(C₁C₂)"
    O = intersect_lines(ops, (0.0, 0.0, math.cos(turn), math.sin(turn)), _bisector(ops, C1, C2))
    R = _dist(O, C1)
    ops.step = "A = θ-circle ∩ line(offset e ∥ guide)"
    try:
        A = intersect_circle_line(ops, O, R, (0.0, e_mm, 1.0, 0.0), -1.0, lambda e: "the offset line misses the θ-circle")
    except AssemblyError:
        return None
    if not A[0] < -NO_CRANK * H_mm:  # A between the limits: the slider would change sides of A (two branches)
        return None
    ac1, ac2 = _dist(A, C1), _dist(A, C2)
    a, b = (ac2 - ac1) / 2.0, (ac1 + ac2) / 2.0
    if a <= NO_CRANK * b or a + e_mm >= b:
        return None
    B1 = (A[0] - a * (C1[0] - A[0]) / ac1, A[1] - a * (C1[1] - A[1]) / ac1)
    B2 = (A[0] + a * (C2[0] - A[0]) / ac2, A[1] + a * (C2[1] - A[1]) / ac2)
    return DrawnSlider({"A": A, "B1": B1, "B2": B2, "C1": C1, "C2": C2}, ac1, ac2, (O, R),
                       float(max(ops.conds.values(), default=1.0)))
