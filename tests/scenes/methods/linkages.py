"""Linkages whose polygons are worked out by hand, shared by tests/methods/test_{velocity,
acceleration,measure,polygons}.py, and the little evaluation they all need.

Each is placed so that one position has a closed form (the numbers are in the docstrings), SI
units; the scales draw every polygon a few centimetres across.
"""
from __future__ import annotations

import math
from typing import Any

from graphmech.mechanisms.linkage import RPP, RPR, RRP, RRR, Crank, Guide, Linkage, LinkPoint, SliderInput
from graphmech.methods.linkage_construction import LinkageConstruction

SCALES = {"l": 0.001, "v": 0.01, "a": 0.1}

#: Crank a = 0.05 at ω1 = 10; rocker c = 0.08 pivoted at D = (0.12, 0); coupler b so that at
#: φ = 90° B = (0, 0.05), C = (0.12, 0.08): CD stands vertical, so v_C ∥ v_B, ω2 = 0,
#: v_C = ω1·a = 0.5, ω3 = ω1·a/c = 6.25; then α2 = (ω1²a − ω3²c)/d = 15.625,
#: α3 = α2·(c − a)/c = 5.859375, a_C = (−α3·c, −ω3²·c) = (−0.46875, −3.125).
#: E is a point of the coupler (for the images).
RIGHT_FOURBAR = Linkage(
    {"A": (0.0, 0.0), "D": (0.12, 0.0)}, Crank("1", "A", "B", 0.05, 10.0),
    (RRR("B", "C", "D", ("2", "3"), (math.hypot(0.12, 0.03), 0.08), "left"),),
    (LinkPoint("E", "2", ("B", "C"), 0.04, 0.02),),
)


def slider_crank(omega: float = 10.0, epsilon: float = 0.0) -> Linkage:
    """Centred slider-crank a = 0.03, b = 0.06 on the x axis. At φ = 90°: v_C = −ω·a, ω2 = 0
    and (ε = 0) a_C = ω²a²/√(b² − a²) = √3 along the guide, α2 = ω²a/√(b² − a²)."""
    return Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.03, omega, epsilon),
                   (RRP("B", "C", ("2", "3"), 0.06, Guide((0.0, 0.0), 0.0)),))


#: Guide bar: crank a = 0.03 at ω1 = 10 about A, bar 3 pivoted at C = (0, −0.04), block 2 on the
#: crank pin. At φ = 0, CB = (0.03, 0.04), L = 0.05: ω3 = ω1a²/L² = 3.6, v_rel = ω1·a·h/L = 0.24
#: (away from C), a^k = 2ω3·v_rel = 1.728, α3 = (a_B·n − a^k)/L = 13.44, a^r = 1.152.
GUIDE_BAR = Linkage(
    {"A": (0.0, 0.0), "C": (0.0, -0.04)}, Crank("1", "A", "B", 0.03, 10.0),
    (RPR("B", "C", ("2", "3"), bar="second"),),
)

#: GUIDE_BAR with its slot e = 0.03 to the left of C: at φ = 0, CB = (0.03, 0.04), t = 0.04, the bar
#: along û = (0.96, 0.28), its foot F = (−0.0084, −0.0112); by hand in the bar's frame (divide the loop
#: by û): ω3 = 7.2, ṫ = v_B2B3 = 0.3, α3 = −48.12, ẗ = −2.25, a^k = 2ω3·ṫ = 4.32.
OFFSET_GUIDE_BAR = Linkage(
    {"A": (0.0, 0.0), "C": (0.0, -0.04)}, Crank("1", "A", "B", 0.03, 10.0),
    (RPR("B", "C", ("2", "3"), bar="second", offset=0.03),),
)


def scotch_yoke(epsilon: float = 0.0) -> Linkage:
    """Crank a = 0.04 at ω = 10, a vertical slot, the yoke on the x axis: x_C = a·cos φ,
    v_C = −aω·sin φ, a_C = −a(ω²·cos φ + ε·sin φ)."""
    return Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.04, 10.0, epsilon),
                   (RPP("B", "C", ("2", "3"), math.pi / 2, Guide((0.0, 0.0), 0.0)),))


#: A slider C driven along a guide at 60° through (−0.3, 0), v = −1.5 m/s, a = 4 m/s²; the
#: coupler CB (0.3) and the crank BA (0.1) about the frame point A follow it.
SLIDER_DRIVEN = Linkage(
    {"A": (0.0, 0.0)}, SliderInput("3", "C", Guide((-0.3, 0.0), math.radians(60.0)), -1.5, 4.0),
    (RRR("C", "B", "A", ("2", "1"), (0.3, 0.1), "left"),),
)


def evaluate(b: LinkageConstruction, position: float, *names: str) -> dict[str, Any]:
    """The steps ``names`` and the quantities' slots at one position (floats)."""
    slots = [b.quantities[n].slot if n in b.quantities else n for n in names]
    return b.g.prune(slots).evaluate({b.param: position})


def value(b: LinkageConstruction, sol: dict[str, Any], name: str) -> float:
    """A measured quantity: drawn length × its scale."""
    drawn, scale = sol[b.quantities[name].slot]
    return drawn * scale
