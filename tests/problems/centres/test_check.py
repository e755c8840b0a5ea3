"""The centres of a friction planetary drive by Kennedy's theorem against Willis' formula and the
exact velocity equations; the sign of ω1/ω2 from how P12 divides P14P24."""
from __future__ import annotations

import math

import pytest

from graphmech.problems.centres.check import analyse_centres, centres_steps, ratio
from graphmech.scene import load_scene
from tests.conftest import SCENES, assert_refused, check_json, run_cli, values

PLANETARY = SCENES / "ic.friction_planetary.toml"

#: A second geometry: the planet 2 (r2 = 10) inside the driven ring 1 (R1 = 50), rolling on the fixed
#: wheel 4 (r4 = 30) at the middle; no carrier.
RING_DRIVEN = """
title = "Planet inside a driven ring, on a fixed sun"
find = ["P12", "P24", "ratio_1_2", "omega_2_ic"]
[units]
length = "mm"
omega = "rad/s"
[centres]
frame = "4"
driver = "1"
omega = -6
points = { O = [10, -5], C = [10, 35] }
[[centres.wheel]]
link = "1"
centre = "O"
radius = 50
internal = true
[[centres.wheel]]
link = "2"
centre = "C"
radius = 10
[[centres.wheel]]
link = "4"
centre = "O"
radius = 30
[[centres.revolute]]
links = ["1", "4"]
at = "O"
[[centres.rolling]]
links = ["1", "2"]
[[centres.rolling]]
links = ["2", "4"]
"""


def willis(r_planet: float, r_1: float, r_4: float, one_internal: bool) -> float:
    """ω1/ω2 of a planet rolling on wheel 1 and on the fixed wheel 4, by Willis' formula for the
    equivalent planetary (the planet's centre turns about O like a carrier H):
    (ω1 − ωH)/(ω2 − ωH) = ∓r2/r1 and (0 − ωH)/(ω2 − ωH) = ±r2/r4 (− for an external contact)."""
    s1 = r_planet / r_1 if one_internal else -r_planet / r_1
    s4 = -r_planet / r_4 if one_internal else r_planet / r_4
    # from the ring: −ωH = s4·(ω2 − ωH) → ωH = s4·ω2/(s4 − 1); with ω2 = 1:
    wh = s4 / (s4 - 1.0)
    return wh + s1 * (1.0 - wh)


def test_the_seed_answer_matches_willis_to_1e_12_with_opposite_senses():
    doc = check_json(PLANETARY)
    v = values(doc)
    r1, r2, r4 = 40.0, 15.0, 70.0
    assert willis(r2, r1, r4, False) == pytest.approx(-2 * r2 / r1, abs=1e-15)  # −0.75: the closed form
    assert v["ratio_1_2"]["graphical"] == pytest.approx(willis(r2, r1, r4, False), abs=1e-12)
    assert v["ratio_1_2"]["graphical"] < 0  # P12 divides P14P24 internally: opposite senses
    assert v["ratio_1_2"]["drawn_mm"] == pytest.approx(-30.0, abs=1e-12)  # P24P12 = −2·r2 at μl = 0.001
    assert v["omega_2_ic"]["graphical"] == pytest.approx(10.0 / -0.75, abs=1e-12)
    # the carrier: ωH = −r2·ω2/(r1 + r2)
    assert v["omega_3_ic"]["graphical"] == pytest.approx(-15.0 * (10.0 / -0.75) / 55.0, abs=1e-12)
    assert all(q["rel_error"] < 1e-12 for q in doc["quantities"])
    centres = doc["instant_centres"]["centres"]
    assert centres["P13"]["kind"] == "direct" and centres["P12"]["via"] == ["rolling"]
    assert centres["P24"]["x"] == pytest.approx(0.07 * 2 ** -0.5, abs=1e-15)


def test_a_second_geometry_turns_both_in_the_same_sense(tmp_path):
    p = tmp_path / "ring.toml"
    p.write_text(RING_DRIVEN, encoding="utf-8")
    v = values(check_json(p))
    assert v["ratio_1_2"]["graphical"] == pytest.approx(willis(10.0, 50.0, 30.0, True), abs=1e-12)
    assert v["ratio_1_2"]["graphical"] == pytest.approx(0.4, abs=1e-12)  # P12 outside P14P24: same sense
    assert v["omega_2_ic"]["graphical"] == pytest.approx(-6.0 / 0.4, abs=1e-12)
    assert v["x_P24"]["graphical"] == pytest.approx(0.010, abs=1e-15) and \
        v["y_P24"]["graphical"] == pytest.approx(0.025, abs=1e-15)


def test_a_centre_kennedy_cannot_fix_is_refused_where_a_ratio_needs_it(tmp_path):
    """Without the compound hinge at O, P13 (sun and carrier) has one Kennedy line only (P14 = P34)."""
    text = PLANETARY.read_text(encoding="utf-8").replace(
        'links = ["1", "3", "4"]\nat = "O"', 'links = ["1", "4"]\nat = "O"\n\n[[centres.revolute]]\n'
                                             'links = ["3", "4"]\nat = "O"')
    p = tmp_path / "fp.toml"
    p.write_text(text.replace('find = ["P12", "P24", "P14", "ratio_1_2", "omega_2_ic", "omega_3_ic"]',
                              'find = ["ratio_1_3"]'), encoding="utf-8")
    assert_refused(run_cli("check", str(p)), p.name, "find[0]: ratio_1_3: P13 is undetermined")


IDLER = """
find = ["P13", "ratio_1_3", "omega_3_ic"]
[units]
length = "mm"
omega = "rad/s"
[centres]
frame = "4"
driver = "1"
omega = 5
points = { A = [0, 0], B = [35, 0], D = [55, 34.64101615137754] }
[[centres.wheel]]
link = "1"
centre = "A"
radius = 20
[[centres.wheel]]
link = "2"
centre = "B"
radius = 15
[[centres.wheel]]
link = "3"
centre = "D"
radius = 25
[[centres.revolute]]
links = ["1", "4"]
at = "A"
[[centres.revolute]]
links = ["2", "4"]
at = "B"
[[centres.revolute]]
links = ["3", "4"]
at = "D"
[[centres.rolling]]
links = ["1", "2"]
[[centres.rolling]]
links = ["2", "3"]
"""


def test_kennedy_finds_the_centre_of_two_wheels_through_an_idler(tmp_path):
    """Wheels 1 and 3 on fixed axles A, D driven through the idler 2: P13 is where the line P12P23 meets
    AD; ω1/ω3 = r3/r1, the same sense (two external contacts)."""
    p = tmp_path / "idler.toml"
    p.write_text(IDLER, encoding="utf-8")
    an = analyse_centres(load_scene(p))
    c = an.ic.centre("1", "3")
    assert c.kind == "kennedy" and set(c.via) == {"2", "4"}
    v = {r.name: r for r in an.rows}
    assert v["ratio_1_3"].graphical == pytest.approx(25.0 / 20.0, abs=1e-12)
    assert v["omega_3_ic"].graphical == pytest.approx(5.0 * 20.0 / 25.0, abs=1e-12)
    # P13 on AD at ω-weighted position: ω1·AP13 = ω3·DP13 (signed), i.e. P13 = (ω1·A − ω3·D)/(ω1 − ω3)
    w1, w3 = 5.0, 4.0
    assert (v["x_P13"].graphical, v["y_P13"].graphical) == pytest.approx(
        ((0 - w3 * 0.055) / (w1 - w3), (0 - w3 * 0.03464101615137754) / (w1 - w3)), abs=1e-15)


def test_contacts_that_lock_the_drive_are_refused(tmp_path):
    """A ring off-centre: P12, P24 and P14 not on one line — Kennedy's theorem says the drive is locked."""
    text = PLANETARY.read_text(encoding="utf-8").replace(
        "points = { O = [0, 0], C = [38.89087296526011, 38.89087296526011] }",
        f"points = {{ O = [0, 0], C = [55, 0], Q = [{55 + 55 * math.cos(math.radians(100))!r}, {55 * math.sin(math.radians(100))!r}] }}").replace(
        'centre = "O"\nradius = 70', 'centre = "Q"\nradius = 70')
    p = tmp_path / "locked.toml"
    p.write_text(text, encoding="utf-8")
    assert_refused(run_cli("check", str(p)), p.name, "P12, P24 and P14 are not on one line",
                   "by Kennedy's theorem the pairs lock links 1, 2, 4")


def test_the_ratio_reads_signed_lengths_and_the_steps_name_kennedy():
    an = analyse_centres(load_scene(PLANETARY))
    num, den, r = ratio(an.ic, "1", "2")
    assert (num, den) == pytest.approx((-30.0, 40.0), abs=1e-12) and r == pytest.approx(-0.75, abs=1e-15)
    steps = centres_steps(load_scene(PLANETARY))
    assert steps[0].startswith("Number the links 1, 2, 3, 4 (the frame 4)")
    assert any(s.startswith("P12: where the two wheels touch") for s in steps)
    assert steps[-4:] == ["Kennedy's theorem: P12, P23 and P13 lie on one line (checked).",
                          "Kennedy's theorem: P12, P24 and P14 lie on one line (checked).",
                          "Kennedy's theorem: P23, P34 and P24 lie on one line (checked).",
                          "ω1/ω2 = P24P12 / P14P12 = -0.75 (opposite senses)"]


def test_measured_values_are_judged(tmp_path):
    code, out, err = run_cli("check", str(PLANETARY), "--measured", "ratio_1_2=-0.75", "--measured", "x_P12=0.0283")
    assert code == 0 and "OUT OF TOLERANCE" not in out, err
    code, out, err = run_cli("check", str(PLANETARY), "--measured", "ratio_1_2=+0.75")  # the sense is wrong
    assert code == 1 and "OUT OF TOLERANCE" in out, err
