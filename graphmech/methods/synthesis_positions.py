"""Linkage synthesis by given positions, as the book constructs it (实现给定位置的设计).

coupler through two or three positions
    Each position of the coupler is given by its two joint points B_i, C_i. B moves on a circle
    about the fixed pivot A, so A is the centre of the circle through B₁, B₂, B₃: the meeting point
    of the perpendicular bisectors b₁₂ and b₂₃; D likewise from C₁, C₂, C₃. With two positions
    each pivot lies anywhere on its bisector: a stated frame line picks it.
two or three corresponding positions of input and output (反转法, the relative-pole inversion)
    Seen from the output link DC, the frame turns back: turn the input's joint B_i about D by
    −(ψ_i − ψ₁) to B_i′; C₁ is then the centre of the circle through B₁, B₂′, B₃′ (three positions)
    or the point of the bisector of B₁B₂′ at the stated output length from D (two positions).
    The same inversion finds the joint E on a rocker that drives a slider through three given
    positions F_i (seed 000 连杆 4): turn F_i about D by the rocker's rotations.
slider-crank through slider and crank positions
    Seen from the slider, the frame translates back: shift B_i by −(s_i − s₁) along the guide;
    the slider's pin C₁ is the circumcentre of B₁, B₂′, B₃′, or with two positions the point where
    the bisector of B₁B₂′ cuts the stated guide line.

Every point is constructed with the kernels of :mod:`graphmech.geometry.kernels` (lines through
midpoints at right angles, their intersection, a circle cut by a line); each result records what
the draftsman draws — the bisectors, the arcs of the inversion, the inverted points — for the
figure. Lengths in metres, angles in radians (CCW positive). The independent check is
:mod:`graphmech.exact.synthesis_positions`.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from graphmech.errors import DegenerateConstruction, OutOfDomain
from graphmech.geometry.kernels import (
    Components,
    ScalarOps,
    intersect_circle_line,
    intersect_circles,
    intersect_lines,
    line_fixed,
    line_perpendicular_to,
    unit,
)
from graphmech.tolerances import COINCIDENT_REL

__all__ = [
    "Arc",
    "Bisector",
    "CouplerDesign",
    "CouplerPointDesign",
    "FourbarDesign",
    "Inversion",
    "JointDesign",
    "SliderCrankDesign",
    "circumcentre",
    "coupler_positions",
    "fourbar_positions",
    "fourbar_through_coupler_points",
    "invert_rigid",
    "invert_rotation",
    "invert_translation",
    "joint_by_inversion",
    "perpendicular_bisector",
    "slider_crank_positions",
]

XY = tuple[float, float]
#: A line as the kernels take it: a point and a unit direction (px, py, dx, dy).
LineXY = tuple[float, float, float, float]

#: |sin| of the angle at a precision point below which three points count as on one line (relative
#: to the triangle's sides): the bisectors then are parallel to rounding.
COLLINEAR_SIN = 1e-9


@dataclass(frozen=True)
class Bisector:
    """The perpendicular bisector ``label`` of the segment ``ends`` (thin line); ``line`` is its
    midpoint and unit direction."""

    label: str
    ends: tuple[XY, XY]
    line: LineXY


@dataclass(frozen=True)
class Arc:
    """A thin arc (or circle) about ``centre`` of ``radius``: the locus a stated length gives."""

    label: str
    centre: XY
    radius: float


@dataclass(frozen=True)
class Inversion:
    """A point carried back by the inversion: ``original`` → ``image``, turned about ``centre`` by
    ``angle`` (rad, an arc drawn from the one to the other) or shifted by ``shift`` (m, along the
    guide; centre None)."""

    label: str
    original: XY
    image: XY
    centre: XY | None
    angle: float = 0.0
    shift: XY = (0.0, 0.0)
    #: for a point carried with a moving link: the link's two points at position i, then at 1
    #: (the triangle drawn on the one copied onto the other)
    carried: tuple[XY, XY, XY, XY] | None = None


@dataclass(frozen=True)
class CouplerDesign:
    """A four-bar whose coupler BC passes through the given positions.

    ``A``, ``D`` the fixed pivots; ``l_AB``, ``l_BC``, ``l_CD``, ``l_AD`` the links (m).
    """

    A: XY
    D: XY
    l_AB: float
    l_BC: float
    l_CD: float
    l_AD: float
    bisectors: tuple[Bisector, ...]


@dataclass(frozen=True)
class JointDesign:
    """The joint found by inversion on the output link: ``joint`` at position 1, the images of the
    other link's joint, the bisectors (and the arc of a stated length) that placed it."""

    joint: XY
    inversions: tuple[Inversion, ...]
    bisectors: tuple[Bisector, ...]
    arcs: tuple[Arc, ...] = ()


@dataclass(frozen=True)
class FourbarDesign:
    """A four-bar A B C D taking the corresponding positions φ_i (input AB), ψ_i (output DC).

    ``B1``, ``C1`` the moving joints at position 1; ``l_AB``, ``l_BC``, ``l_CD``, ``l_AD`` (m);
    ``psi_offset`` the angle of DC₁ minus ψ₁: the output's angle at position i is
    ψ_i + ``psi_offset``.
    """

    A: XY
    D: XY
    B1: XY
    C1: XY
    l_AB: float
    l_BC: float
    l_CD: float
    l_AD: float
    psi_offset: float
    construction: JointDesign


@dataclass(frozen=True)
class CouplerPointDesign:
    """A four-bar A B C D whose coupler point E passes through E_i (seed 000 连杆 5's form).

    ``B``, ``C``, ``E`` every joint at every position; the links (m), ``l_BE`` fixing E on BC.
    """

    A: XY
    D: XY
    B: tuple[XY, ...]
    C: tuple[XY, ...]
    E: tuple[XY, ...]
    l_AB: float
    l_BC: float
    l_CD: float
    l_AD: float
    l_EC: float
    l_BE: float
    construction: JointDesign


@dataclass(frozen=True)
class SliderCrankDesign:
    """A slider-crank taking crank angles φ_i with slider displacements s_i.

    ``C1`` the slider's pin at position 1; ``l_AB``, ``l_BC`` (m); ``offset`` e the signed distance
    of A from the pin's path (+ when A lies to the left of the guide's direction).
    """

    A: XY
    B1: XY
    C1: XY
    l_AB: float
    l_BC: float
    offset: float
    guide_angle: float
    construction: JointDesign


# --------------------------------------------------------------------------------- the kernels


def _distinct(points: Sequence[XY], labels: Sequence[str], scale: float = 0.0) -> None:
    # relative to the whole figure (``scale`` the linkage's size where known): two of three
    # positions 1e-150 m apart are one point
    size = max(abs(x) + abs(y) for x, y in points) + max(_dist(p, q) for p in points for q in points) + scale
    for i in range(len(points)):
        for j in range(i + 1, len(points)):
            if _dist(points[i], points[j]) <= COINCIDENT_REL * size:
                raise DegenerateConstruction(
                    f"{labels[i]}{labels[j]}", f"{labels[i]} and {labels[j]} coincide: two positions of one point "
                    "give no bisector (the positions must be distinct)")


def perpendicular_bisector(P: XY, Q: XY, label: str) -> Bisector:
    """The perpendicular bisector of PQ (the locus of the centres of circles through P and Q)."""
    ops = ScalarOps()
    ops.step = label
    u = unit(ops, P, Q)
    mid = ((P[0] + Q[0]) / 2.0, (P[1] + Q[1]) / 2.0)
    px, py, dx, dy = line_perpendicular_to(ops, mid, u)
    return Bisector(label, (P, Q), (float(px), float(py), float(dx), float(dy)))


def circumcentre(points: Sequence[XY], labels: Sequence[str], centre: str = "O",
                 scale: float = 0.0) -> tuple[XY, tuple[Bisector, Bisector]]:
    """The centre of the circle through three points: the bisectors of 1–2 and 2–3 meet there.

    Raises DegenerateConstruction, in words, when two points coincide (to rounding, relative to the
    points or to ``scale``, the linkage's size) or the three lie on one line.
    """
    if len(points) != 3 or len(labels) != 3:
        raise OutOfDomain(f"a circle is drawn through three points, not {len(points)}")
    _distinct(points, labels, scale)
    (x1, y1), (x2, y2), (x3, y3) = points
    # collinear: the sine of the angle between 1→2 and 1→3 (the bisectors would be parallel)
    cr = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
    if abs(cr) <= COLLINEAR_SIN * math.hypot(x2 - x1, y2 - y1) * math.hypot(x3 - x1, y3 - y1):
        raise DegenerateConstruction(
            f"{centre} = b{labels[0]}{labels[1]} ∩ b{labels[1]}{labels[2]}",
            f"{', '.join(labels)} lie on one straight line: no circle passes through them, so no fixed pivot "
            "can carry them")
    b12 = perpendicular_bisector(points[0], points[1], f"b{labels[0]}{labels[1]}")
    b23 = perpendicular_bisector(points[1], points[2], f"b{labels[1]}{labels[2]}")
    ops = ScalarOps()
    ops.step = f"{centre} = {b12.label} ∩ {b23.label}"
    x, y = intersect_lines(ops, b12.line, b23.line)
    return (float(x), float(y)), (b12, b23)


def invert_rotation(P: XY, centre: XY, angle: float, label: str) -> Inversion:
    """P turned about ``centre`` by ``angle`` (rad, CCW): the inversion on a rotating link."""
    c, s = math.cos(angle), math.sin(angle)
    dx, dy = P[0] - centre[0], P[1] - centre[1]
    return Inversion(label, P, (centre[0] + c * dx - s * dy, centre[1] + s * dx + c * dy), centre, angle)


def invert_translation(P: XY, shift: XY, label: str) -> Inversion:
    """P shifted by ``shift`` (m): the inversion on a translating link (the slider)."""
    return Inversion(label, P, (P[0] + shift[0], P[1] + shift[1]), None, 0.0, shift)


def invert_rigid(P: XY, at_i: tuple[XY, XY], at_1: tuple[XY, XY], label: str) -> Inversion:
    """P carried with a moving link from its position i (points ``at_i``) to its position 1
    (``at_1``): the triangle P·at_i copied onto at_1 — the inversion on a coupler."""
    (p, q), (p1, q1) = at_i, at_1
    if abs(_dist(p, q) - _dist(p1, q1)) > 1e-9 * _dist(p1, q1):
        raise OutOfDomain(f"the link is not rigid: its two points are {_dist(p, q):.6g} m and {_dist(p1, q1):.6g} m "
                          "apart in the two positions")
    turn = math.atan2(q1[1] - p1[1], q1[0] - p1[0]) - math.atan2(q[1] - p[1], q[0] - p[0])
    c, s = math.cos(turn), math.sin(turn)
    dx, dy = P[0] - p[0], P[1] - p[1]
    return Inversion(label, P, (p1[0] + c * dx - s * dy, p1[1] + s * dx + c * dy), None, turn,
                     carried=(p, q, p1, q1))


def _on_bisector(b: Bisector, centre: XY, radius: float, side: float, step: str) -> XY:
    """The point of the bisector at ``radius`` from ``centre`` (ahead +1 or behind −1 the foot)."""
    ops = ScalarOps()
    ops.step = step
    return _xy(intersect_circle_line(
        ops, centre, radius, b.line, side,
        lambda e: f"the bisector {b.label} passes {e:.6g} m from the centre, farther than the stated length "
                  f"{radius:.6g} m: the arc does not reach it"))


def _xy(p: Components) -> XY:
    return (float(p[0]), float(p[1]))


def _dist(P: XY, Q: XY) -> float:
    return math.hypot(Q[0] - P[0], Q[1] - P[1])


def _positive(name: str, x: float) -> float:
    if not (math.isfinite(x) and x > 0.0):
        raise OutOfDomain(f"{name} must be a positive finite length, got {x!r}")
    return float(x)


def _count(**seqs: Sequence[object]) -> int:
    ns = {len(v) for v in seqs.values()}
    if len(ns) != 1 or not ns <= {2, 3}:
        names = ", ".join(f"{k} ({len(v)})" for k, v in seqs.items())
        raise OutOfDomain(f"two or three positions are taken, the same number of each: {names}")
    return ns.pop()


# --------------------------------------------------------------------------------- the designs


def joint_by_inversion(points: Sequence[XY], pivot: XY, rotations: Sequence[float], names: str = "B",
                       joint: str = "C", length: float | None = None, side: float = 1.0,
                       numbers: Sequence[int] | None = None) -> JointDesign:
    """The joint on a link turning about ``pivot`` that a second link carries through ``points``.

    ``rotations[i]`` is the link's rotation from position 1 to position i (rad, CCW; the first is 0).
    Each point is turned about the pivot by −rotation (the inversion); the joint at position 1 is the
    circumcentre of the images (three positions), or with two the point of their bisector at
    ``length`` from the pivot, ``side`` +1 / −1 choosing between the two. ``numbers`` are the
    positions' numbers as the book names them (default 1, 2, 3): the construction turned to
    position 2 passes the points in the order 2, 1, 3 and names them so.
    """
    n = _count(points=points, rotations=rotations)
    label = [f"{names}{k}" for k in (numbers or range(1, n + 1))]
    joint = f"{joint}{(numbers or (1,))[0]}"
    inv = tuple(invert_rotation(points[i], pivot, -(rotations[i] - rotations[0]), f"{label[i]}'") for i in range(1, n))
    images = [points[0], *(v.image for v in inv)]
    image_labels = [label[0], *(v.label for v in inv)]
    scale = max(_dist(p, pivot) for p in points)
    if n == 3:
        centre, bis = circumcentre(images, image_labels, joint, scale)
        return JointDesign(centre, inv, bis)
    if length is None:
        raise OutOfDomain(f"with two positions the joint {joint} lies anywhere on the bisector: state its length "
                          "from the pivot")
    _positive(f"the length of the pivot to {joint[0]}", length)
    _distinct(images, image_labels, scale)
    b = perpendicular_bisector(images[0], images[1], f"b{image_labels[0]}{image_labels[1]}")
    at = _on_bisector(b, pivot, length, side, f"{joint} = arc ∩ {b.label}")
    return JointDesign(at, inv, (b,), (Arc(joint, pivot, length),))


def coupler_positions(B: Sequence[XY], C: Sequence[XY], frame: tuple[XY, float] | None = None) -> CouplerDesign:
    """A four-bar whose coupler BC passes through the given two or three positions (B_i, C_i).

    Three positions: A and D are the circumcentres of B₁B₂B₃ and C₁C₂C₃. Two positions: A and D
    are where the frame line ``frame = (point, angle)`` cuts the bisectors b₁₂ of B and of C.
    The coupler must be rigid: |B_iC_i| the same in every position.
    """
    n = _count(B=B, C=C)
    lengths = [_dist(B[i], C[i]) for i in range(n)]
    if max(lengths) - min(lengths) > 1e-9 * max(lengths):
        raise OutOfDomain(f"the coupler is not rigid: B_iC_i = {', '.join(f'{x:.6g}' for x in lengths)} m differ")
    _positive("BC", lengths[0])
    if n == 3:
        if frame is not None:
            raise OutOfDomain("three positions fix both pivots: no frame line is taken")
        A, bA = circumcentre(B, ("B1", "B2", "B3"), "A")
        D, bD = circumcentre(C, ("C1", "C2", "C3"), "D")
        bis: tuple[Bisector, ...] = (*bA, *bD)
    else:
        if frame is None:
            raise OutOfDomain("with two positions each pivot lies anywhere on its bisector: state the frame line")
        _distinct(B, ("B1", "B2"))
        _distinct(C, ("C1", "C2"))
        ops = ScalarOps()
        line = line_fixed(ops, frame[0], math.cos(frame[1]), math.sin(frame[1]))
        bA2 = perpendicular_bisector(B[0], B[1], "bB1B2")
        bD2 = perpendicular_bisector(C[0], C[1], "bC1C2")
        ops.step = "A = bB1B2 ∩ frame line"
        A = _xy(intersect_lines(ops, bA2.line, line))
        ops.step = "D = bC1C2 ∩ frame line"
        D = _xy(intersect_lines(ops, bD2.line, line))
        bis = (bA2, bD2)
    return CouplerDesign(A, D, _dist(A, B[0]), lengths[0], _dist(D, C[0]), _dist(A, D), bis)


def fourbar_positions(A: XY, D: XY, l_AB: float, phi: Sequence[float], psi: Sequence[float],
                      l_CD: float | None = None, side: float = 1.0) -> FourbarDesign:
    """A four-bar whose input AB at φ_i and output DC at ψ_i correspond (two or three positions).

    B_i = A + l_AB·(cos φ_i, sin φ_i); B_i turned about D by −(ψ_i − ψ₁) → B_i′; C₁ the
    circumcentre of B₁B₂′B₃′, or with two positions on the bisector of B₁B₂′ at ``l_CD`` from D.
    """
    _positive("AB", l_AB)
    _count(phi=phi, psi=psi)
    B = [(A[0] + l_AB * math.cos(f), A[1] + l_AB * math.sin(f)) for f in phi]
    j = joint_by_inversion(B, D, psi, "B", "C", l_CD, side)
    C1 = j.joint
    return FourbarDesign(A, D, B[0], C1, l_AB, _dist(B[0], C1), _dist(D, C1), _dist(A, D),
                         math.atan2(C1[1] - D[1], C1[0] - D[0]) - psi[0], j)


def slider_crank_positions(A: XY, l_AB: float, phi: Sequence[float], s: Sequence[float], guide_angle: float,
                           guide_point: XY | None = None) -> SliderCrankDesign:
    """A slider-crank whose crank at φ_i puts the slider at s_i along the guide (angle ``guide_angle``).

    B_i shifted by −(s_i − s₁) along the guide → B_i′; the pin C₁ is the circumcentre of B₁B₂′B₃′,
    or with two positions where the bisector of B₁B₂′ cuts the pin's path through ``guide_point``.
    """
    _positive("AB", l_AB)
    n = _count(phi=phi, s=s)
    g = (math.cos(guide_angle), math.sin(guide_angle))
    B = [(A[0] + l_AB * math.cos(f), A[1] + l_AB * math.sin(f)) for f in phi]
    inv = tuple(invert_translation(B[i], (-(s[i] - s[0]) * g[0], -(s[i] - s[0]) * g[1]), f"B{i + 1}'")
                for i in range(1, n))
    images = [B[0], *(v.image for v in inv)]
    labels = ["B1", *(v.label for v in inv)]
    if n == 3:
        if guide_point is not None:
            raise OutOfDomain("three positions fix the slider's pin: no guide point is taken")
        C1, bis = circumcentre(images, labels, "C1")
        j = JointDesign(C1, inv, bis)
    else:
        if guide_point is None:
            raise OutOfDomain("with two positions the pin C1 lies anywhere on the bisector: state the guide line")
        _distinct(images, labels)
        b = perpendicular_bisector(images[0], images[1], "bB1B2'")
        ops = ScalarOps()
        ops.step = "C1 = bB1B2' ∩ guide"
        C1 = _xy(intersect_lines(ops, b.line, line_fixed(ops, guide_point, g[0], g[1])))
        j = JointDesign(C1, inv, (b,))
    offset = g[0] * (A[1] - C1[1]) - g[1] * (A[0] - C1[0])
    return SliderCrankDesign(A, B[0], C1, l_AB, _dist(B[0], C1), offset, guide_angle, j)


def _out_of_reach(point: str, r1: float, r2: float) -> Callable[[float], str]:
    def explain(d: float) -> str:
        return (f"{point} is {d:.6g} m from D: the arcs CD = {r1:.6g} m and EC = {r2:.6g} m do not meet "
                f"(they reach from {abs(r1 - r2):.6g} m to {r1 + r2:.6g} m)")
    return explain


def fourbar_through_coupler_points(A: XY, D: XY, E: Sequence[XY], l_CD: float, l_EC: float,
                                   side: float | Sequence[float] = 1.0) -> CouplerPointDesign:
    """A four-bar with given pivots A, D whose coupler point E passes through three given E_i.

    The book's steps (seed 000 连杆 5): the arc of radius l_CD about D and the arcs of radius l_EC
    about E_i give C_i (``side`` +1 / −1: to the left / right of D → E_i, one for all positions or
    one for each); then, seen from the
    coupler CE, the pivot A moves: carry A with the coupler from each position i back to position 1
    (A_i′), and the coupler's joint B₁ is the centre of the circle through A, A₂′, A₃′.
    """
    _positive("CD", l_CD)
    _positive("EC", l_EC)
    if len(E) != 3:
        raise OutOfDomain(f"a coupler point is led through three positions, not {len(E)}")
    _distinct(E, ("E1", "E2", "E3"))
    sides = [float(side)] * 3 if isinstance(side, (int, float)) else [float(x) for x in side]
    if len(sides) != 3:
        raise OutOfDomain(f"one side for all three positions or one for each, not {len(sides)}")
    ops = ScalarOps()
    C: list[XY] = []
    for i, Ei in enumerate(E):
        ops.step = f"C{i + 1} = arc D ∩ arc E{i + 1}"
        C.append(_xy(intersect_circles(ops, D, l_CD, Ei, l_EC, sides[i], _out_of_reach(f"E{i + 1}", l_CD, l_EC))))
    inv = tuple(invert_rigid(A, (C[i], E[i]), (C[0], E[0]), f"A{i + 1}'") for i in (1, 2))
    # A on the coupler (a kite folded: C on A) carries back onto itself: refused as coincident
    B1, bis = circumcentre([A, *(v.image for v in inv)], ["A", "A2'", "A3'"], "B1", l_CD + l_EC + _dist(A, D))
    B = [B1]
    for i in (1, 2):  # B carried forward with the coupler: the inverse of each inversion
        back = invert_rigid(B1, (C[0], E[0]), (C[i], E[i]), f"B{i + 1}")
        B.append(back.image)
    arcs = (Arc("C", D, l_CD), *(Arc(f"C{i + 1}", E[i], l_EC) for i in range(3)))
    return CouplerPointDesign(A, D, tuple(B), tuple(C), tuple(E), _dist(A, B1), _dist(B1, C[0]), l_CD, _dist(A, D),
                              l_EC, _dist(B1, E[0]), JointDesign(B1, inv, bis, arcs))
