"""What the positions forms share: the exact joint by inversion, the bisector's cut of a line, the
angles the loci meet at and the conditioning they lead to."""
from __future__ import annotations

import cmath
import dataclasses
import math

import pytest

from graphmech.errors import GraphmechError
from graphmech.problems.judging import Row
from graphmech.problems.synthesis.common import (
    arcs_sin,
    conditioning,
    design_rows,
    exact_joint,
    line_arc_sin,
    lines_sin,
    on_line,
)


def test_the_exact_joint_is_equally_far_from_the_turned_back_points():
    pivot, joint = 0.1 + 0j, 0.12 + 0.05j
    rot = [0.0, 0.4, 0.9]
    # the points a link of 0.08 m from the joint reaches as the joint turns about the pivot
    pts = [pivot + (joint - pivot) * cmath.exp(1j * r) + 0.08 * cmath.exp(1j * (1.0 + 2 * r)) for r in rot]
    assert exact_joint(pts, pivot, rot) == pytest.approx(joint, abs=1e-15)
    two = exact_joint(pts[:2], pivot, rot[:2], abs(joint - pivot), near=joint)
    assert two == pytest.approx(joint, abs=1e-15)
    with pytest.raises(GraphmechError, match="does not reach"):
        exact_joint(pts[:2], pivot, rot[:2], 1e-4)


def test_on_line_cuts_the_bisector():
    assert on_line(0j, 1 + 0j, 1j, 2 + 1j) == pytest.approx(1 + 0j)
    with pytest.raises(GraphmechError, match="along the bisector"):
        on_line(0j, 1j, -1 + 0j, 1 + 0j)


def test_the_angles_the_loci_meet_at_by_hand():
    assert lines_sin((0, 0, 1, 0), (0, 0, math.cos(0.3), math.sin(0.3))) == pytest.approx(math.sin(0.3))
    # the line y = 0.6 cuts the unit circle at (0.8, 0.6): against the tangent sin = 0.8
    assert line_arc_sin((0, 0.6, 1, 0), (0, 0), (0.8, 0.6)) == pytest.approx(0.8)
    # unit circles about (0, 0) and (1, 0) meet at 60° (their radii at (0.5, √3/2))
    assert arcs_sin((0, 0), (1, 0), (0.5, math.sqrt(3) / 2)) == pytest.approx(math.sin(math.radians(120)))


def test_conditioning_marks_the_rows_of_a_shallow_cut_only():
    rows = [Row(n, "m", 10.0, 0.001, 0.01, 0.01, 0.0) for n in ("lAB", "lCD")]
    kept, said = conditioning([("A = b1 ∩ b2", math.sin(math.radians(2.0)), ("lAB", "xA")),
                               ("D = b3 ∩ b4", math.sin(math.radians(30.0)), ("lCD",))], rows)
    assert [r.ill_conditioned for r in kept] == [True, False]
    assert said == [("shallow intersection 'A = b1 ∩ b2' at 2°: a hand construction is unreliable here (a 0.5 mm "
                    "error becomes about 14 mm); lAB marked ill-conditioned")]
    _, said = conditioning([("X", 1e-4, ("lCD",))], rows)
    assert said[0].startswith("ill-conditioned intersection 'X': the loci meet at 0.00573° (condition number 1e+04)")


def test_loci_that_touch_are_said_without_an_infinite_number():
    """Arcs that only touch (|sin| = 0, exact data) were said with "condition number inf" and
    "wrong by about inf": the tangency is worded, with the √ε a point of contact moves by."""
    rows = [Row("lAB", "m", 10.0, 0.001, 0.01, 0.01, 0.0)]
    kept, said = conditioning([("C2 = arc D ∩ arc E2", 0.0, ("lAB",))], rows)
    assert kept[0].ill_conditioned
    assert said == [("ill-conditioned intersection 'C2 = arc D ∩ arc E2': the loci touch (they meet at 0°, a point "
                     "of tangency); lAB may be wrong by about 3e-07 relative or more")]
    # a cut so shallow that the round-off estimate overflows is worded the same
    assert conditioning([("X", 1e-200, ("lAB",))], rows)[1][0].startswith("ill-conditioned intersection 'X': the loci touch")


def test_a_design_left_unassembled_by_round_off_is_refused_in_words():
    """An infinite re-analysis error is never a row (its key would be the row's name)."""
    from graphmech.exact.synthesis_positions import Reanalysis

    unreached = Reanalysis(math.inf, (), "left", True, "crank_rocker_AB", None, (), "")
    reached = dataclasses.replace(unreached, error=1e-16)
    with pytest.raises(GraphmechError, match="cannot be assembled at every prescribed position when re-analysed"):
        design_rows({"lAB": 30.0}, {"lAB": 0.03}, 0.001, 0.1, reached, unreached)
    rows, names = design_rows({"lAB": 30.0}, {"lAB": 0.03}, 0.001, 0.1, reached, reached)
    assert names == ["lAB", "reanalysis_error"] and rows[1].exact == 1e-16

