"""The balancing check: a rotor already balanced, a mass outside the planes, measured values judged."""
from __future__ import annotations

import json
from functools import partial

import pytest

from tests.conftest import SCENES, check_json, run_cli, values
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


