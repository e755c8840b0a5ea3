"""The positions forms by inversion: a slider-crank through crank and slider positions, a rocker
leading a slider (seed 000 连杆 4), a coupler point through three points (000 连杆 5) — the joints
against the exact side, re-checked by hand, the positions reached, the refusals, the figures, the
steps in three languages and the conditioning of the cuts."""
from __future__ import annotations

import cmath
import json
import math
import re

import pytest

from graphmech.drawing.primitives import Label, Polyline, Segment
from graphmech.errors import SceneError
from graphmech.problems.synthesis.check import analyse_synthesis
from graphmech.problems.synthesis.figures import synthesis_sheet
from graphmech.problems.synthesis.steps import protocol
from tests.conftest import SCENES, assert_refused, check_json, run_cli, values
from tests.scenes import parse_text, replace_once

SLIDER = (SCENES / "synthesis.slider_crank_positions.toml").read_text(encoding="utf-8")
ROCKER = (SCENES / "synthesis.rocker_slider_three_positions.toml").read_text(encoding="utf-8")
POINT = (SCENES / "synthesis.coupler_point_three_positions.toml").read_text(encoding="utf-8")


def _rows(text: str) -> dict:
    return {r.name: r for r in analyse_synthesis(parse_text(text)).rows}


# ------------------------------------------------------------------------------- slider-crank


def test_the_slider_crank_puts_the_slider_where_it_is_asked():
    an = analyse_synthesis(parse_text(SLIDER))
    rows = {r.name: r for r in an.rows}
    assert list(rows) == ["lBC", "e", "xC1", "yC1", "reanalysis_error", "gamma_min"]
    assert all(r.rel_error < 1e-12 and not r.ill_conditioned for r in an.rows)
    b, e = rows["lBC"].exact, rows["e"].exact
    assert (b, e) == pytest.approx((0.0599757786, 0.0100133467), rel=1e-8)
    # by hand: the pin on the path y = −e, the crank at φ_i, the coupler b: x_C − x_C1 = s_i − s₁
    s = [0.0, 0.020, 0.051]
    for phi, si in zip((180.0, 255.0, 315.0), s):
        Bx, By = 0.03 * math.cos(math.radians(phi)), 0.03 * math.sin(math.radians(phi))
        xC = Bx + math.sqrt(b * b - (By + e) ** 2)
        assert xC - rows["xC1"].exact == pytest.approx(si, abs=1e-12)
    assert rows["yC1"].exact == pytest.approx(-e, rel=1e-12)
    assert rows["reanalysis_error"].exact < 1e-9 and rows["reanalysis_error"].graphical < 1e-9
    assert rows["gamma_min"].exact == pytest.approx(48.1518713, rel=1e-8)
    assert an.solutions[0]["grashof"] == "crank" and an.warnings == []


def test_two_slider_positions_take_the_pins_path():
    text = replace_once(replace_once(SLIDER, "[180, 255, 315]", "[180, 255]"), "[0, 20, 51]", "[0, 20]")
    rows = _rows(text + "guide_through_mm = [0, -10]\n")
    C1 = complex(rows["xC1"].exact, rows["yC1"].exact)
    B1, B2 = 0.03 * cmath.exp(1j * math.pi), 0.03 * cmath.exp(1j * math.radians(255)) - 0.020
    assert C1.imag == pytest.approx(-0.010, abs=1e-15) and rows["e"].exact == pytest.approx(0.010, rel=1e-12)
    assert abs(C1 - B1) == pytest.approx(abs(C1 - B2), rel=1e-12)  # on the bisector of B₁B₂′
    assert rows["reanalysis_error"].exact < 1e-9


@pytest.mark.parametrize(("old", "new", "key", "reason"), [
    ("s_mm = [0, 20, 51]", "s_mm = [0, 20]", "synthesis.s_mm", "2 slider positions for 3 crank angles: give as many of each"),
    ("phi_deg = [180, 255, 315]\ns_mm = [0, 20, 51]", "phi_deg = [180, 255]\ns_mm = [0, 20]", "synthesis.guide_through",
     "with two positions the pin C₁ lies anywhere on the bisector: give guide_through_mm (a point of the pin's path)"),
    ("s_mm = [0, 20, 51]", "s_mm = [0, 20, 51]\nguide_through_mm = [0, 0]", "synthesis.guide_through_mm",
     "three positions fix the slider's pin: no guide_through is taken"),
    ("phi_deg = [180, 255, 315]\ns_mm = [0, 20, 51]\nguide_angle_deg = 0",
     "phi_deg = [0, 90, 180]\ns_mm = [0, 30, 0]\nguide_angle_deg = 90", "synthesis.s_mm",
     ("C1 = bB1B2' ∩ bB2'B3': B1, B2', B3' lie on one straight line: no circle passes through them, so no fixed "
     "pivot can carry them")),
])
def test_impossible_slider_data_are_refused_in_one_line(old, new, key, reason, tmp_path):
    p = tmp_path / "s.toml"
    p.write_text(replace_once(SLIDER, old, new), encoding="utf-8")
    assert assert_refused(run_cli("check", str(p)), "s.toml") == f"s.toml: {key}: {reason}"


# ------------------------------------------------------------------------------- 000 连杆 4


def test_seed_linkage_4_finds_the_books_l_EF():
    an = analyse_synthesis(parse_text(ROCKER))
    rows = {r.name: r for r in an.rows}
    assert list(rows) == ["lDE", "lEF", "xE", "yE", "reanalysis_error"]
    assert rows["lEF"].exact == pytest.approx(0.130157116, rel=1e-8)  # the book: 130 mm
    assert all(r.rel_error < 1e-12 for r in an.rows) and rows["reanalysis_error"].exact < 1e-9
    # at the book's μl = 5 mm/mm E₂F₂ is drawn 26 mm (the book: 26 × 5 = 130)
    at5 = _rows(replace_once(ROCKER, "l_mm_per_mm = 2", "l_mm_per_mm = 5"))
    assert at5["lEF"].drawn_mm == pytest.approx(26.0314232, rel=1e-8) and round(at5["lEF"].drawn_mm) == 26
    # by hand: E₂ equally far from F₂ and from F₁, F₃ turned about D by ∠C_iDC₂
    E2, C = complex(rows["xE"].exact, rows["yE"].exact), [-0.125j, 0.075 - 0.1j, 0.12 - 0.035j]
    F = [0.07 + 0.025j, 0.14 + 0.025j, 0.2 + 0.025j]
    for i in (0, 2):
        turned = F[i] * C[1] / C[i]  # |C_i| all 0.125: the rotation C_i → C₂
        assert abs(E2 - turned) == pytest.approx(abs(E2 - F[1]), rel=1e-12)
    assert an.solutions[0]["grashof"] == "rocker" and an.solutions[0]["one_branch"]


def test_turned_to_another_position_the_same_links_come_out():
    two = _rows(ROCKER)
    one = _rows(replace_once(ROCKER, "invert_to = 2", "invert_to = 1"))
    assert one["lEF"].exact == pytest.approx(two["lEF"].exact, rel=1e-12)
    assert one["lDE"].exact == pytest.approx(two["lDE"].exact, rel=1e-12)
    E1, E2 = complex(one["xE"].exact, one["yE"].exact), complex(two["xE"].exact, two["yE"].exact)
    assert E2 == pytest.approx(E1 * (0.075 - 0.1j) / -0.125j, abs=1e-15)  # E₁ turned with the rocker


def test_two_rocker_positions_take_l_DE_and_the_side():
    text = ROCKER[:ROCKER.rindex("[[synthesis.position]]")].replace("invert_to = 2", "invert_to = 2\nl_DE_mm = 80")
    rows = _rows(text)
    assert rows["lDE"].exact == pytest.approx(0.08, rel=1e-12) and rows["reanalysis_error"].exact < 1e-9
    assert rows["lEF"].exact == pytest.approx(0.1238157555, rel=1e-9)
    # the other cut of the arc: the slider would change branch between the positions (said, not refused)
    an = analyse_synthesis(parse_text(text.replace("l_DE_mm = 80", "l_DE_mm = 80\nside = -1")))
    assert an.warnings == [("the prescribed positions lie on both branches: the linkage cannot pass through them "
                           "without being taken apart")]
    with pytest.raises(SceneError) as e:
        parse_text(text.replace("l_DE_mm = 80\n", ""))
    assert e.value.problems[0][0] == "synthesis.l_DE"
    steps = protocol(analyse_synthesis(parse_text(text)))
    assert steps[2] == "turn F₁ about D by ∠C₁DC₂ to F₁′; the arc of radius DE = 0.08/μl = 40 mm about D cuts the bisector of F₂F₁′ at E₂"


@pytest.mark.parametrize(("old", "new", "key", "reason"), [
    ("C_mm = [75, -100]", "C_mm = [75, -101]", "synthesis.position",
     "the rocker is not rigid: DC_i = 0.125, 0.125801, 0.125 m differ"),
    ("F_mm = [140, 25]", "F_mm = [140, 26]", "synthesis.position",
     "F1, F2, F3 do not lie on one straight line: the slider moves on a straight guide"),
    ("invert_to = 2", "invert_to = 4", "synthesis.invert_to",
     "must be the number of a position, 1 to 3 (the rocker held still there)"),
    ("invert_to = 2", "invert_to = 2\nl_DE_mm = 80", "synthesis.l_DE_mm", "three positions fix E: no l_DE or side is taken"),
])
def test_impossible_rocker_data_are_refused_in_one_line(old, new, key, reason, tmp_path):
    p = tmp_path / "r.toml"
    p.write_text(replace_once(ROCKER, old, new), encoding="utf-8")
    assert assert_refused(run_cli("check", str(p)), "r.toml") == f"r.toml: {key}: {reason}"


# ------------------------------------------------------------------------------- 000 连杆 5


def test_seed_linkage_5_leads_the_coupler_point_through_its_three_points():
    an = analyse_synthesis(parse_text(POINT))
    rows = {r.name: r for r in an.rows}
    assert list(rows) == ["lAB", "lBC", "lBE", "xB1", "yB1", "reanalysis_error", "gamma_min"]
    assert all(r.rel_error < 1e-12 and not r.ill_conditioned for r in an.rows)
    assert (rows["lAB"].exact, rows["lBC"].exact, rows["lBE"].exact) == pytest.approx(
        (0.0363382937, 0.138481026, 0.206830046), rel=1e-8)
    assert rows["reanalysis_error"].exact < 1e-9 and rows["gamma_min"].exact == pytest.approx(36.3087675, rel=1e-8)
    sol = an.solutions[0]
    C1, B1, A = complex(*sol["C1"]), complex(*sol["B1"]), -0.12 + 0j
    E1 = -0.02 + 0.14j
    assert abs(C1) == pytest.approx(0.095) and abs(E1 - C1) == pytest.approx(0.07)  # the given lengths
    assert (C1 / E1).imag > 0  # side = 1: C₁ to the left of D → E₁
    assert abs(B1 - A) == pytest.approx(rows["lAB"].exact, rel=1e-12)
    assert sol["grashof"] == "crank_rocker_AB" and sol["one_branch"] and an.warnings == []


@pytest.mark.parametrize(("old", "new", "key", "reason"), [
    ("E_mm = [20, 140]", "E_mm = [200, 0]", "synthesis.position",
     ("C2 = arc D ∩ arc E2: cannot be assembled: E2 is 0.2 m from D: the arcs CD = 0.095 m and EC = 0.07 m do not "
     "meet (they reach from 0.025 m to 0.165 m)")),
    ("\nside = 1\n", "\nside = 2\n", "synthesis.side", "must be 1 or -1, or a list of three (C_i left or right of D → E_i)"),
    ("E_mm = [60, 140]", "E_mm = [-20, 140]", "synthesis.position",
     "E1E3: E1 and E3 coincide: two positions of one point give no bisector (the positions must be distinct)"),
])
def test_impossible_coupler_point_data_are_refused_in_one_line(old, new, key, reason, tmp_path):
    p = tmp_path / "c.toml"
    p.write_text(replace_once(POINT, old, new), encoding="utf-8")
    assert assert_refused(run_cli("check", str(p)), "c.toml") == f"c.toml: {key}: {reason}"


def test_a_side_for_each_position_is_taken():
    rows = _rows(replace_once(POINT, "\nside = 1\n", "\nside = [1, 1, 1]\n"))
    assert rows["lAB"].exact == pytest.approx(0.0363382937, rel=1e-8)
    with pytest.raises(SceneError) as e:
        parse_text(replace_once(POINT, "\nside = 1\n", "\nside = [1, 1]\n"))
    assert e.value.problems[0][0] == "synthesis.side"


# ------------------------------------------------------------------------------- all three


def test_check_json_gives_si_values_and_the_design():
    doc = check_json(SCENES / "synthesis.rocker_slider_three_positions.toml")
    assert values(doc)["lEF"]["graphical"] == pytest.approx(0.130157116, rel=1e-8)
    sol = doc["synthesis"]["solutions"][0]
    assert doc["synthesis"]["task"] == "positions" and sol["E2"] == pytest.approx([0.0488583032, -0.0679196751])
    assert sol["reanalysis"]["error"] < 1e-9
    doc = check_json(SCENES / "synthesis.slider_crank_positions.toml")
    assert values(doc)["gamma_min"]["unit"] == "deg" and values(doc)["e"]["unit"] == "m"


def test_find_keeps_the_rows_asked():
    rows = _rows(replace_once(ROCKER, 'show = ["design"]', 'show = ["design"]\nfind = ["lEF"]'))
    assert list(rows) == ["lEF"]


@pytest.mark.parametrize(("text", "bold", "arcs", "labels"), [
    (SLIDER, 2, 1, {"B_{2}′", "B_{3}′", "C_{1}", "C_{3}"}),
    (ROCKER, 4, 3, {"F_{1}′", "F_{3}′", "E_{2}", "C_{1}"}),
    (POINT, 5, 5, {"A_{2}′", "A_{3}′", "B_{1}", "E_{3}"}),
])
def test_the_figures_draw_the_inversion_thin_and_the_design_bold(text, bold, arcs, labels):
    panel = synthesis_sheet(analyse_synthesis(parse_text(text)), (297.0, 210.0)).panels[0]
    segs = [i for i in panel.items if isinstance(i, Segment)]
    assert len([s for s in segs if s.role == "result"]) == bold
    assert len([i for i in panel.items if isinstance(i, Polyline)]) == arcs
    assert labels <= {i.text for i in panel.items if isinstance(i, Label)}


def test_the_seed_4_notes_give_the_answer():
    notes = synthesis_sheet(analyse_synthesis(parse_text(ROCKER)), (297.0, 210.0)).panels[0].notes
    assert notes[1] == "l_{DE} = 83.67 mm, l_{EF} = E_{2}F_{2} = 130.2 mm"


@pytest.mark.parametrize(("notation", "line"), [
    ("en", "measure DE₂ = 41.83 mm, E₂F₂ = 65.08 mm: l_DE = 0.08367 m, l_EF = 0.1302 m"),
    ("zh", "量得DE₂ = 41.83 mm，E₂F₂ = 65.08 mm：l_DE = 0.08367 m，l_EF = 0.1302 m"),
    ("ru", "измеряем DE₂ = 41.83 mm, E₂F₂ = 65.08 mm: l_DE = 0.08367 m, l_EF = 0.1302 m"),
])
def test_the_steps_read_the_checks_numbers_in_three_languages(notation, line):
    text = ROCKER if notation == "en" else ROCKER + f'\n[page]\nnotation = "{notation}"\n'
    lines = protocol(analyse_synthesis(parse_text(text)))
    assert lines[3] == line
    assert ("F₂、F₁′、F₃′" if notation == "zh" else "F₂, F₁′, F₃′") in lines[2] and lines[-1].endswith(("link)", "最长杆）", "звена)"))


def test_the_slider_and_coupler_point_steps():
    s = protocol(analyse_synthesis(parse_text(SLIDER)))
    assert s[3] == "measure B₁C₁ = 120 mm and the offset of A from the guide e = 20.03 mm: l_BC = 0.05998 m, e = 0.01001 m"
    c = protocol(analyse_synthesis(parse_text(POINT)))
    assert c[1].startswith("draw A, D and E₁, E₂, E₃; the arc of radius CD = 0.095/μl = 47.5 mm about D")
    assert c[3] == ("measure AB₁ = 18.17 mm, B₁C₁ = 69.24 mm, B₁E₁ = 103.4 mm: l_AB = 0.03634 m, l_BC = 0.1385 m, "
                    "l_BE = 0.2068 m")


# ------------------------------------------------------------------------------- conditioning


def test_bisectors_meeting_shallow_are_flagged_in_the_slider_form():
    text = replace_once(replace_once(SLIDER, "[180, 255, 315]", "[60, 105, 150]"), "[0, 20, 51]", "[0, -24, -36]")
    an = analyse_synthesis(parse_text(text.replace("l_mm_per_mm = 0.5", "l_mm_per_mm = 5")))
    assert an.warnings == [("shallow intersection 'C1 = bB1B2' ∩ bB2'B3'' at 1.57°: a hand construction is unreliable "
                           "here (a 0.5 mm error becomes about 18 mm); lBC, e, xC1, yC1 marked ill-conditioned")]
    assert [r.name for r in an.rows if r.ill_conditioned] == ["lBC", "e", "xC1", "yC1"]


def test_the_coupler_and_four_bar_forms_flag_shallow_cuts_too():
    coupler = (SCENES / "synthesis.coupler_three_positions.toml").read_text(encoding="utf-8")
    # B on a flat arc (the sagitta 1 mm over 80 mm): A about 0.8 m below; the coupler translated
    for old, new in (("B_mm = [14, 48]", "B_mm = [26, 49]"), ("C_mm = [70, 81]", "C_mm = [86, 74]"),
                     ("B_mm = [40, 30]", "B_mm = [66, 48]"), ("C_mm = [79, 82]", "C_mm = [126, 73]"),
                     ("C_mm = [46, 73]", "C_mm = [46, 73]"), ("l_mm_per_mm = 1\n", "")):
        coupler = replace_once(coupler, old, new)
    an = analyse_synthesis(parse_text(coupler.replace("[scales]\n", "")))
    assert any(w.startswith("shallow intersection 'A = bB1B2 ∩ bB2B3' at ") for w in an.warnings), an.warnings
    assert {r.name for r in an.rows if r.ill_conditioned} >= {"lAB", "xA", "yA"}
    fourbar = (SCENES / "synthesis.fourbar_three_positions.toml").read_text(encoding="utf-8")
    fourbar = replace_once(fourbar, "psi_deg = [60, 80, 105]", "psi_deg = [60, 80]")
    fourbar = replace_once(fourbar, "phi_deg = [45, 90, 135]", "phi_deg = [45, 90]\nl_CD_mm = 51.2\nside = -1")
    an = analyse_synthesis(parse_text(fourbar))
    assert [w.split(":")[0] for w in an.warnings][-1] == "shallow intersection 'C1 = arc ∩ bB1B2'' at 2.54°"
    assert [r.name for r in an.rows if r.ill_conditioned] == ["lBC", "lCD", "xC1", "yC1"]


def test_an_arc_that_only_touches_is_warned_of_in_words(tmp_path):
    """E2 at l_CD + l_EC from D: the arcs about D and E2 touch (exactly, in the data); the warning
    said "condition number inf … wrong by about inf" — an infinite number in the output."""
    scene = tmp_path / "pt.toml"
    scene.write_text(replace_once(POINT, "E_mm = [20, 140]", "E_mm = [0, 165]"), encoding="utf-8")
    code, out, _ = run_cli("check", "--json", str(scene))
    assert code == 0
    (warning,) = [w for w in json.loads(out)["warnings"] if "C2 = arc D ∩ arc E2" in w]
    assert "the loci touch (they meet at 0°, a point of tangency)" in warning
    assert not re.search(r"\b(inf|nan)\b", out, re.IGNORECASE)


def test_the_scenes_figures_are_committed():
    for name in ("slider_crank_positions", "rocker_slider_three_positions", "coupler_point_three_positions"):
        assert (SCENES.parent / f"synthesis.{name}.svg").is_file()


def test_a_slider_that_comes_back_to_F1_keeps_its_slanted_guide():
    """The rocker turns on while the slider passes its far end and returns to F₁ (found by the
    mutation campaign: the guide was taken along F₁ → F₃, of no length, so horizontal)."""
    turn = cmath.exp(1j * math.radians(30.0))  # the whole figure turned 30°: the guide slants

    def at(z: complex) -> str:
        w = z * turn * 1000
        return f"[{w.real!r}, {w.imag!r}]"

    def F(t: float) -> complex:  # the slider on y = 25 mm of a rocker-slider l_DE = 80, l_EF = 130 mm
        E = 0.08 * cmath.exp(1j * t)
        return complex(E.real + math.sqrt(0.13 ** 2 - (0.025 - E.imag) ** 2), 0.025)

    t = [math.radians(x) for x in (-27.540403, 6.837065, 42.915827)]  # F(t₃) = F(t₁) to 1e-9 m
    f = [F(t[0]), F(t[1]), F(t[0])]
    tables = "".join(f"[[synthesis.position]]\nC_mm = {at(0.125 * cmath.exp(1j * x))}\nF_mm = {at(f[i])}\n"
                     for i, x in enumerate(t))
    an = analyse_synthesis(parse_text(f'[synthesis]\ntask = "positions"\nD_mm = [0, 0]\n{tables}'))
    rows = {r.name: r.exact for r in an.rows}
    assert (rows["lDE"], rows["lEF"]) == pytest.approx((0.08, 0.13), rel=1e-6)
    assert rows["reanalysis_error"] < 1e-9 and an.warnings == []


@pytest.mark.parametrize(("old", "new", "reason"), [
    ("C_mm = [75, -100]", "C_mm = [0, -125]", "C1 and C2 coincide: the rocker must turn from one position to the next"),
    ("F_mm = [140, 25]\n", "F_mm = [70, 25]\n", None),
])
def test_a_rocker_standing_or_a_slider_standing_is_refused(old, new, reason):
    text = replace_once(ROCKER, old, new)
    if reason is None:  # every F on F₁
        text = replace_once(text, "F_mm = [200, 25]", "F_mm = [70, 25]")
        reason = "the slider's positions coincide: it stands still, no guide and no coupler are found"
    with pytest.raises(SceneError) as e:
        parse_text(text)
    assert e.value.problems == [("synthesis.position", reason)]
