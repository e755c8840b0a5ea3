"""The positions task: a coupler through two or three given positions — the pivots by the
perpendicular bisectors against the exact circumcentres, the design re-analysed, the refusals."""
from __future__ import annotations

import pytest

from graphmech.errors import SceneError
from graphmech.problems.synthesis.check import (
    analyse_synthesis,
    judge_synthesis,
    text_lines,
)
from graphmech.problems.synthesis.figures import synthesis_sheet
from graphmech.problems.synthesis.positions import CouplerPositions, exact_pivots
from graphmech.problems.synthesis.steps import protocol
from tests.conftest import ROOT, SCENES, run_cli
from tests.scenes import parse_text, replace_once

THREE = (ROOT / "figures" / "scenes" / "synthesis.coupler_three_positions.toml").read_text(encoding="utf-8")
TWO = """
[synthesis]
task = "positions"
frame_through_mm = [0, 0]
frame_angle_deg = 0
[[synthesis.position]]
B_mm = [-14, 48]
C_mm = [46, 73]
[[synthesis.position]]
B_mm = [14, 48]
C_mm = [70, 81]
"""


def _rows(text: str) -> dict[str, float]:
    return {r.name: r.graphical for r in analyse_synthesis(parse_text(text)).rows}


def test_three_positions_put_A_and_D_at_the_circumcentres():
    an = analyse_synthesis(parse_text(THREE))
    rows = {r.name: r for r in an.rows}
    # B₁, B₂, B₃ lie on the circle of radius 50 mm about the origin: A = (0, 0), l_AB = 50 mm
    assert rows["lAB"].graphical == pytest.approx(0.05, rel=1e-12) and rows["lBC"].exact == pytest.approx(0.065)
    assert abs(rows["xA"].graphical) < 1e-15 and abs(rows["yA"].graphical) < 1e-15
    assert (rows["xD"].exact, rows["yD"].exact) == pytest.approx((0.0835, 0.0005), abs=1e-15)
    assert rows["lCD"].drawn_mm == pytest.approx(81.62413858657258, rel=1e-12)
    assert all(r.rel_error < 1e-12 for r in an.rows)
    assert rows["reanalysis_error"].exact < 1e-9 and rows["reanalysis_error"].graphical < 1e-9
    assert rows["gamma_min"].exact == pytest.approx(23.0338935, rel=1e-8)
    assert an.solutions[0]["grashof"] == "crank_rocker_AB" and an.warnings == []
    assert text_lines(an)[0].startswith("design: l_AB = 50 mm, l_BC = 65 mm, l_CD = 81.6241 mm, l_AD = 83.5015 mm: "
                                        "crank rocker AB; re-analysed through the positions: error ")


def test_two_positions_put_the_pivots_on_the_frame_line():
    rows = _rows(TWO)
    assert (rows["xA"], rows["yA"], rows["yD"]) == pytest.approx((0.0, 0.0, 0.0), abs=1e-15)
    # D on y = 0 equally far from C₁ (46, 73) and C₂ (70, 81) mm: x = (70² + 81² − 46² − 73²)/(2·24) mm
    assert rows["xD"] == pytest.approx((70**2 + 81**2 - 46**2 - 73**2) / 48 / 1000, rel=1e-12)
    assert rows["reanalysis_error"] < 1e-9


def test_the_exact_pivots_on_a_slanted_frame_line_are_equally_far():
    p = CouplerPositions(((0.0, 1.0), (1.0, 1.2)), ((2.0, 1.0), (3.0, 0.8)), ((0.0, 0.0), 0.3), "k")
    A, D = exact_pivots(p)
    assert abs(A - complex(*p.B[0])) == pytest.approx(abs(A - complex(*p.B[1])), rel=1e-12)
    assert abs(D - complex(*p.C[0])) == pytest.approx(abs(D - complex(*p.C[1])), rel=1e-12)
    assert (A / complex(0.9553364891256061, 0.29552020666133955)).imag == pytest.approx(0.0, abs=1e-12)


def test_positions_that_admit_no_grashof_crank_are_said():
    text = THREE.replace("[-14, 48]", "[20, 60]").replace("[46, 73]", "[60, 90]").replace("[14, 48]", "[45, 78]")
    text = text.replace("[70, 81]", "[93, 92]").replace("[40, 30]", "[72, 80]").replace("[79, 82]", "[102, 40]")
    an = analyse_synthesis(parse_text(text))
    assert an.warnings == ["AB does not turn fully (crank rocker CD)"]
    assert "gamma_min" not in {r.name for r in an.rows}
    assert text_lines(an)[0].endswith("; AB does not turn fully (crank rocker CD)")


@pytest.mark.parametrize(("old", "new", "problem"), [
    ("B_mm = [40, 30]\nC_mm = [79, 82]", "B_mm = [28, 48]\nC_mm = [93, 48]",
     ("synthesis.position", ("A = bB1B2 ∩ bB2B3: B1, B2, B3 lie on one straight line: no circle passes through "
                             "them, so no fixed pivot can carry them"))),
    ("C_mm = [79, 82]", "C_mm = [80, 82]", ("synthesis.position", ("the coupler is not rigid: B_iC_i = 0.065, 0.065, "
                                                                    "0.0656049 m differ"))),
])
def test_what_no_design_answers_is_refused_in_one_line(old: str, new: str, problem: tuple[str, str]):
    with pytest.raises(SceneError) as e:
        analyse_synthesis(parse_text(replace_once(THREE, old, new)))
    assert e.value.problems == [problem]


def test_the_frame_line_is_asked_with_two_positions_and_refused_with_three():
    with pytest.raises(SceneError) as e:
        parse_text(TWO.replace("frame_through_mm = [0, 0]\n", ""))
    assert e.value.problems[0][0] == "synthesis.frame_through"
    with pytest.raises(SceneError) as e:
        parse_text(replace_once(THREE, 'task = "positions"', 'task = "positions"\nframe_angle_deg = 0'))
    assert e.value.problems == [("synthesis.frame_angle_deg", "three positions fix both pivots: no frame line is taken")]
    with pytest.raises(SceneError) as e:
        parse_text('[synthesis]\ntask = "positions"\n[[synthesis.position]]\nB_mm = [0, 0]\nC_mm = [1, 0]\n')
    assert e.value.problems[0] == ("synthesis.position", ("give two or three [[synthesis.position]] tables "
                                                          "(the coupler's positions), not 1"))


def test_a_hand_length_is_judged_and_an_unknown_name_refused():
    verdicts = judge_synthesis(analyse_synthesis(parse_text(THREE + "\n[measured]\nlCD = 0.0816\nlAD = 0.080\n")))
    assert [(v.name, v.ok) for v in verdicts] == [("lCD", True), ("lAD", False)]
    with pytest.raises(SceneError) as e:
        analyse_synthesis(parse_text(replace_once(THREE, "show = [\"design\"]", "show = [\"design\"]\nfind = [\"lAC\"]")))
    assert e.value.problems[0][0] == "find[0]"


def test_the_figure_draws_the_bisectors_thin_and_the_linkage_bold():
    from graphmech.drawing.primitives import Segment

    an = analyse_synthesis(parse_text(THREE))
    sheet = synthesis_sheet(an, (297.0, 210.0))
    items = sheet.panels[0].items
    segs = [i for i in items if isinstance(i, Segment)]
    assert len([s for s in segs if s.role == "result"]) == 3  # A B₁, B₁ C₁, C₁ D
    assert len([s for s in segs if s.role == "construction" and not s.dashed and not s.dashdot]) == 4  # bisectors
    assert sheet.panels[0].notes[1] == "l_{AB} = 50 mm, l_{BC} = 65 mm, l_{CD} = 81.62 mm, l_{AD} = 83.5 mm"


def test_the_steps_read_the_checks_numbers():
    lines = protocol(analyse_synthesis(parse_text(THREE)))
    assert lines[1] == "draw the coupler's 3 given positions B_iC_i (BC = 65 mm)"
    assert lines[3] == ("measure AB₁ = 50 mm, C₁D = 81.62 mm, AD = 83.5 mm: l_AB = 0.05 m, l_CD = 0.08162 m, "
                        "l_AD = 0.0835 m")
    assert lines[2].startswith("A is the centre of the circle through B₁, B₂, B₃")


FOURBAR = (ROOT / "figures" / "scenes" / "synthesis.fourbar_three_positions.toml").read_text(encoding="utf-8")
FOURBAR_TWO = """
[synthesis]
task = "positions"
A_mm = [0, 0]
D_mm = [100, 0]
l_AB_mm = 30
phi_deg = [45, 90]
psi_deg = [60, 80]
l_CD_mm = 60
side = -1
"""


def test_three_corresponding_positions_give_C1_by_inversion():
    import cmath
    import math

    an = analyse_synthesis(parse_text(FOURBAR))
    rows = {r.name: r for r in an.rows}
    assert list(rows) == ["lBC", "lCD", "xC1", "yC1", "reanalysis_error", "gamma_min"]
    assert (rows["xC1"].exact, rows["yC1"].exact) == pytest.approx((0.10838657, 0.0525162563), rel=1e-8)
    C1, D = complex(rows["xC1"].exact, rows["yC1"].exact), 0.1 + 0j
    B = [0.03 * cmath.exp(1j * math.radians(f)) for f in (45, 90, 135)]
    # C₁ equally far from B₁ and from each B_i turned back about D by ψ_i − ψ₁
    back = [D + (B[i] - D) * cmath.exp(-1j * math.radians(d)) for i, d in ((1, 20), (2, 45))]
    assert all(abs(C1 - b) == pytest.approx(abs(C1 - B[0]), rel=1e-12) for b in back)
    assert rows["reanalysis_error"].exact < 1e-9 and all(r.rel_error < 1e-12 for r in an.rows)
    assert an.solutions[0]["grashof"] == "crank_rocker_AB"
    assert protocol(an)[3] == "measure B₁C₁ = 92.62 mm, C₁D = 53.18 mm: l_BC = 0.09262 m, l_CD = 0.05318 m"


def test_two_positions_take_l_CD_and_the_side():
    behind = {r.name: r.exact for r in analyse_synthesis(parse_text(FOURBAR_TWO)).rows}
    ahead_an = analyse_synthesis(parse_text(FOURBAR_TWO.replace("side = -1", "side = 1")))
    ahead = {r.name: r.exact for r in ahead_an.rows}
    assert behind["lCD"] == pytest.approx(0.06) and ahead["lCD"] == pytest.approx(0.06)
    assert behind["lBC"] == pytest.approx(0.109066, rel=1e-5) and ahead["lBC"] == pytest.approx(0.048957, rel=1e-5)
    assert behind["reanalysis_error"] < 1e-9 and ahead["reanalysis_error"] < 1e-9
    # the other cut admits no Grashof crank: said, not refused
    assert ahead_an.warnings == ["the positions admit no Grashof crank (double rocker): AB does not turn fully"]
    assert "gamma_min" not in ahead


def test_bad_input_output_positions_are_refused_in_one_line():
    with pytest.raises(SceneError) as e:
        analyse_synthesis(parse_text(FOURBAR_TWO.replace("l_CD_mm = 60", "l_CD_mm = 50")))
    assert e.value.problems == [("synthesis.psi_deg", (
        "C1 = arc ∩ bB1B2': cannot be assembled: the bisector bB1B2' passes 0.0511498 m from the centre, "
        "farther than the stated length 0.05 m: the arc does not reach it"))]
    with pytest.raises(SceneError) as e:
        parse_text(FOURBAR_TWO.replace("l_CD_mm = 60\n", ""))
    assert e.value.problems[0][0] == "synthesis.l_CD"
    with pytest.raises(SceneError) as e:
        parse_text(FOURBAR.replace("psi_deg = [60, 80, 105]", "psi_deg = [60, 80]"))
    assert e.value.problems[0] == ("synthesis.psi_deg", "2 output angles for 3 input angles: give as many of each")
    with pytest.raises(SceneError) as e:
        parse_text(FOURBAR_TWO.replace("side = -1", "side = 2"))
    assert e.value.problems[0][0] == "synthesis.side"


def test_the_inversion_is_drawn_with_its_arcs_and_images():
    from graphmech.drawing.primitives import Label, Polyline

    items = synthesis_sheet(analyse_synthesis(parse_text(FOURBAR)), (297.0, 210.0)).panels[0].items
    assert len([i for i in items if isinstance(i, Polyline)]) == 2  # B₂ → B₂′, B₃ → B₃′ about D
    assert {"B_{2}′", "B_{3}′", "C_{1}"} <= {i.text for i in items if isinstance(i, Label)}


@pytest.mark.parametrize("A", ["[100, 0]", "[0, 0]"])
def test_a_frame_of_no_length_is_refused_at_D(A, tmp_path):
    """A and D coinciding (found by the mutation campaign: the re-analysis divided by CD = 0)."""
    p = tmp_path / "f.toml"
    p.write_text(f'[synthesis]\ntask = "positions"\nA_mm = {A}\nD_mm = {A}\nl_AB_mm = 30\n'
                 'phi_deg = [45, 90, 135]\npsi_deg = [60, 80, 105]\n', encoding="utf-8")
    assert run_cli("check", str(p)) == (2, "", "f.toml: synthesis.D_mm: A and D coincide: the frame AD has no length\n")


@pytest.mark.parametrize("edit,key", [
    ('D_mm = [100, 0]', "synthesis.D_mm"),
    ('l_AB_mm = 30', "synthesis.l_AB_mm"),
])
def test_a_size_beyond_double_precision_is_refused_at_its_key(edit, key, tmp_path):
    """Coordinates and lengths of 1e300 mm (found by the mutation campaign: the bisectors and the
    re-analysis overflowed) are refused where they are written."""
    text = ('[synthesis]\ntask = "positions"\nA_mm = [0, 0]\nD_mm = [100, 0]\nl_AB_mm = 30\n'
            'phi_deg = [45, 90, 135]\npsi_deg = [60, 80, 105]\n')
    p = tmp_path / "s.toml"
    p.write_text(text.replace(edit, edit.split("=")[0] + ("= [1e300, 0]" if "[" in edit else "= 1e300")),
                 encoding="utf-8")
    code, out, err = run_cli("check", str(p))
    assert (code, out) == (2, "") and err.startswith(f"s.toml: {key}: 1e+297 m is beyond 1e+06 m")


def test_a_crank_far_shorter_than_the_frame_is_designed_not_refused_as_out_of_range():
    """l_AB = 1e-3 mm against a 100 mm frame: the output DC comes out 2e-3 mm, the angle at B of
    the triangle BCD is 1e-5 rad — the re-analysis took that for a dead centre, counted the
    positions unreached (error inf) and the scene was refused as 'reanalysis_error: numbers out
    of the range of double precision', a row's name for a key."""
    text = replace_once((SCENES / "synthesis.fourbar_three_positions.toml").read_text(encoding="utf-8"),
                        "l_AB_mm = 30", "l_AB_mm = 1e-3")
    rows = {r.name: r for r in analyse_synthesis(parse_text(text)).rows}
    assert rows["lCD"].exact == pytest.approx(2.1363016311e-6, rel=1e-9)
    assert rows["reanalysis_error"].exact < 1e-9 and rows["reanalysis_error"].graphical < 1e-9



def test_a_link_under_a_nanometre_is_refused_at_its_key():
    text = replace_once((SCENES / "synthesis.fourbar_three_positions.toml").read_text(encoding="utf-8"),
                        "l_AB_mm = 30", "l_AB_mm = 1e-7")
    with pytest.raises(SceneError) as e:
        parse_text(text)
    assert e.value.problems == [("synthesis.l_AB_mm",
                                 "1e-10 m is below 1e-09 m: too short for a link to be designed in double precision")]
