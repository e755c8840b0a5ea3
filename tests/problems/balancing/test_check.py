"""The balancing check: a rotor already balanced, a mass outside the planes, measured values judged."""
from __future__ import annotations

import json
import math
from functools import partial

import pytest

from tests.conftest import SCENES, assert_refused, check_json, run_cli, values
from tests.scenes import scene_text, write_scene

write = partial(write_scene, name="r.toml")


BALANCED = scene_text("balancing/balanced_opposite")


def test_an_already_balanced_rotor_needs_no_correction_and_gets_no_angle(tmp_path):
    p = write(tmp_path, BALANCED)
    code, out, err = run_cli("check", str(p), "--json")
    assert code == 0 and "NaN" not in out
    doc = json.loads(out)
    q = values(doc)
    assert "theta_b" not in q  # no angle of nothing
    assert q["m_b"]["graphical"] == 0.0 and q["W_b"]["graphical"] == 0.0
    assert q["m_b"]["exact"] <= 1e-15
    assert any("already balanced: no correction mass needed" in w for w in doc["warnings"])
    code, out, err = run_cli("render", str(p), "-o", str(tmp_path / "b.svg"))
    assert code == 0 and "no correction mass needed" in (tmp_path / "b.svg").read_text(encoding="utf-8")


def test_a_mass_outside_the_planes_gives_a_reversed_share(tmp_path):
    p = write(tmp_path, """
find = ["W_I", "W_II", "theta_I", "theta_II", "residual_moment"]
[balancing]
type = "dynamic"
planes_mm = [0, 100]
correction_radius_mm = [50, 60]
[[balancing.mass]]
m_kg = 1
r_mm = 100
angle_deg = 0
z_mm = 150
""")
    q = values(check_json(p))
    # W·(z_II − z)/L = −0.05 in plane I (so the correction there points along 0°), 0.15 in plane II
    assert q["W_I"]["graphical"] == pytest.approx(0.05, rel=1e-14)
    assert q["theta_I"]["graphical"] == pytest.approx(0.0, abs=1e-12)
    assert q["W_II"]["graphical"] == pytest.approx(0.15, rel=1e-14)
    assert q["theta_II"]["graphical"] == pytest.approx(180.0, rel=1e-14)
    assert q["residual_moment"]["graphical"] <= 1e-16


def test_measured_angle_is_judged_against_the_drawing():
    code, out, err = run_cli("check", str(SCENES / "bal.disc_static.toml"), "--json",
                             "--measured", "theta_b=119.7,m_b=5.3,W_b=0.9")
    v = {m["name"]: m for m in json.loads(out)["measured"]}
    assert v["theta_b"]["ok"] and v["m_b"]["ok"]  # 0.5 mm of a 16 mm side: ±1.8°; 0.5 mm × μW/r_b = 0.17 kg
    assert not v["W_b"]["ok"] and code == 1




# --- issue 22 item 7: the correction split into two directions (001 8-4), the centrifugal force (001 8-1)

def test_the_split_along_two_directions_matches_the_closed_form():
    q = values(check_json(SCENES / "bal.split_two_directions.toml"))
    # Σ mᵢrᵢ = 0.1·(cos 30° + cos 120°, sin 30° + sin 120°); W_b = −Σ: along 180° and 270°
    w1 = 0.1 * (math.cos(math.radians(30)) + math.cos(math.radians(120)))
    w2 = 0.1 * (math.sin(math.radians(30)) + math.sin(math.radians(120)))
    for name, want in (("W_b1", w1), ("W_b2", w2), ("m_b1", w1 / 0.1), ("m_b2", w2 / 0.1)):
        assert q[name]["exact"] == pytest.approx(want, rel=1e-9, abs=0)
        assert q[name]["graphical"] == pytest.approx(want, rel=1e-9, abs=0)
    assert q["W_b"]["exact"] == pytest.approx(math.hypot(w1, w2), rel=1e-9)


def test_a_component_against_its_direction_is_negative(tmp_path):
    # one mass 0.2 kg·m at 0°: W_b = 0.2 at 180°; along 90° and 45° — 180° = −√2·e45° + 1·e90°
    # (×0.2): W_b1 (90°) = +0.2, W_b2 (45°) = −0.2·√2 (that mass goes at 225°)
    p = write(tmp_path, """
find = ["W_b1", "W_b2"]
[balancing]
type = "static"
correction_radius_mm = 100
split_angles_deg = [90, 45]
[[balancing.mass]]
m_kg = 2
r_mm = 100
angle_deg = 0
""")
    q = values(check_json(p))
    assert q["W_b1"]["exact"] == pytest.approx(0.2, rel=1e-9)
    assert q["W_b2"]["exact"] == pytest.approx(-0.2 * math.sqrt(2), rel=1e-9)
    assert q["W_b1"]["graphical"] == pytest.approx(0.2, rel=1e-9)
    assert q["W_b2"]["graphical"] == pytest.approx(-0.2 * math.sqrt(2), rel=1e-9)


def test_split_exact_is_the_two_by_two_solve():
    from graphmech.problems.balancing.check import split_exact

    a1, a2 = math.radians(20), math.radians(110)
    w = complex(0.3, -0.7)
    x1, x2 = split_exact(w, (a1, a2))
    back = x1 * complex(math.cos(a1), math.sin(a1)) + x2 * complex(math.cos(a2), math.sin(a2))
    assert abs(back - w) < 1e-15


def test_the_centrifugal_force_before_balancing():
    q = values(check_json(SCENES / "bal.rotor_centrifugal.toml"))
    omega = 5000 * math.pi / 30
    assert q["F_unbalanced"]["exact"] == pytest.approx(omega ** 2 * 1000 * 0.5e-3, rel=1e-9)
    assert q["F_unbalanced"]["graphical"] == pytest.approx(137077.8389, rel=1e-9)
    assert q["F_unbalanced"]["exact"] / (1000 * 9.81) == pytest.approx(13.97, abs=0.01)  # about 14 × its weight


def test_the_centrifugal_force_of_a_dynamic_rotor_is_that_of_the_whole_sum(tmp_path):
    p = write(tmp_path, """
find = ["F_unbalanced"]
[balancing]
type = "dynamic"
planes_mm = [0, 300]
correction_radius_mm = 100
speed_rad_s = 100
[[balancing.mass]]
m_kg = 1
r_mm = 100
angle_deg = 0
z_mm = 50
[[balancing.mass]]
m_kg = 1
r_mm = 50
angle_deg = 90
z_mm = 250
""")
    q = values(check_json(p))
    want = 100.0 ** 2 * math.hypot(0.1, 0.05)
    assert q["F_unbalanced"]["exact"] == pytest.approx(want, rel=1e-9)
    assert q["F_unbalanced"]["graphical"] == pytest.approx(want, rel=1e-9)


@pytest.mark.parametrize(("extra", "find", "words"), [
    ("", "W_b1", "W_b1 needs [balancing] split_angles"),
    ("", "F_unbalanced", "F_unbalanced needs [balancing] speed"),
])
def test_a_split_or_force_without_its_data_is_refused(tmp_path, extra, find, words):
    p = write(tmp_path, f"""
find = ["{find}"]
[balancing]
type = "static"
correction_radius_mm = 100
{extra}
[[balancing.mass]]
m_kg = 1
r_mm = 100
angle_deg = 0
""")
    assert_refused(run_cli("check", str(p)), "r.toml", f"find[0]: {words}")
