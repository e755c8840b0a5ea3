"""Checking a gear-train scene (graphmech/problems/trains/check.py): the rows asked for, the
default rows, the lines under the table, the JSON's basic trains, measured values judged."""
from __future__ import annotations

import math

import pytest

from graphmech.problems import check
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES, check_json, run_cli, values
from tests.scenes import scene_path


def test_rows_and_lines_of_the_electric_screwdriver():
    an, verdicts, extras, lines = check(load_scene(SCENES / "train.electric_screwdriver.toml"))
    assert [r.name for r in an.rows] == ["i1H2", "nH2"]
    assert [r.unit for r in an.rows] == ["", "r/min"]
    # i1H2 a ratio of two lengths on the ω line, nH2 a length × μω (H2 is slow: 0.73 mm, flagged)
    assert an.rows[0].drawn_mm is None and an.rows[0].rel_error < 1e-15
    assert an.rows[1].drawn_mm == pytest.approx(69.47069943289226 / an.rows[1].scale, rel=1e-12)
    assert an.rows[1].graphical == an.rows[1].drawn_mm * an.rows[1].scale and an.rows[1].ill_conditioned
    assert lines[0] == ("split: planetary 1-2-3-H1 (carrier H1) + planetary 4-5-6-H2 (carrier H2); joined by "
                        "n4 = nH1: member H1 is in 1-2-3-H1, 4-5-6-H2")
    assert lines[-1] == "sense: H2 turns the same way as the input 1"
    assert [b["equations"] for b in extras["train"]["basic_trains"]] == [
        ["i^H1_1,3 = (n1 − nH1)/(n3 − nH1) = −z3/z1 = −5.57143"],
        ["i^H2_4,6 = (n4 − nH2)/(n6 − nH2) = −z6/z4 = −5.57143"]]
    assert extras["train"]["senses"]["1"] == "-y" and verdicts == []


def test_default_rows_are_every_free_member_s_speed_and_the_mobility():
    s = parse_scene({"train": {"z": {"1": 20, "2": 40}, "mesh": [{"gears": ["1", "2"]}],
                               "input": [{"member": "1", "speed_rad_s": 10}]}}, "t.toml")
    an, *_ = check(s)
    n2 = -5.0 * 30 / math.pi
    assert [r.name for r in an.rows] == ["n2", "dof"]
    assert an.rows[0].graphical == pytest.approx(n2, rel=1e-15) and an.rows[0].exact == pytest.approx(n2, rel=1e-15)
    assert (an.rows[1].graphical, an.rows[1].exact) == (1.0, 1.0)


def test_omega_rows_and_measured_values(tmp_path):
    p = tmp_path / "m.toml"
    p.write_text('find = ["omega2", "i12"]\n[measured]\nomega2 = -5.0\ni12 = -1.9\n[train]\nz = { "1" = 20, "2" = 40 }\n'
                 '[[train.mesh]]\ngears = ["1", "2"]\n[[train.input]]\nmember = "1"\nspeed_rad_s = 10\n', encoding="utf-8")
    doc = check_json(p)
    q = values(doc)
    assert q["omega2"]["graphical"] == -5.0 and q["i12"]["graphical"] == -2.0
    ok = {v["name"]: v["ok"] for v in doc["measured"]}
    assert ok == {"omega2": True, "i12": False}
    code, _, _ = run_cli("check", str(p))
    assert code == 1


DYNAMICS = """
find = {find}
[train]
m_mm = 10
fixed = ["3"]
z = {{ "1" = 20, "2" = 40, "2'" = 20, "3" = 40 }}
[[train.member]]
name = "2"
gears = ["2", "2'"]
carrier = "H"
[[train.member]]
name = "H"
gears = []
[[train.mesh]]
gears = ["1", "2"]
[[train.mesh]]
gears = ["2'", "3"]
[[train.input]]
member = "1"
speed_rad_s = 100
{tables}
"""


def test_dynamics_and_efficiency_rows_come_with_the_train_s(tmp_path):
    """[train.dynamics] and [train.efficiency] read with the scene, their rows beside the speeds:
    i_1H = 1 − (40·40)/(20·20) = −3, η = 1 − (1 − η^H)(i − 1)/i with η^H = 0.98² (two meshes)."""
    p = tmp_path / "d.toml"
    p.write_text(DYNAMICS.format(find='["nH", "J_red_1", "M_red_1", "eta_train"]', tables="""
[train.dynamics]
reduce_to = "1"
[[train.dynamics.member]]
name = "H"
inertia_kgm2 = 0.18
moment_Nm = 60
[train.efficiency]
eta_mesh = 0.98
output = "H"
"""), encoding="utf-8")
    q = values(check_json(p))
    assert list(q) == ["nH", "J_red_1", "M_red_1", "eta_train"]
    assert q["J_red_1"]["exact"] == pytest.approx(0.18 / 9, rel=1e-14)
    assert q["M_red_1"]["exact"] == pytest.approx(-20.0, rel=1e-14)
    eta_h = 0.98 ** 2
    assert q["eta_train"]["graphical"] == pytest.approx(1 - (1 - eta_h) * 4 / 3, rel=1e-14)
    assert q["eta_train"]["rel_error"] < 1e-14


def test_a_dynamics_name_without_its_table_is_refused_when_read(tmp_path):
    p = tmp_path / "d.toml"
    p.write_text(DYNAMICS.format(find='["nH", "eta_train"]', tables=""), encoding="utf-8")
    assert run_cli("check", str(p)) == (2, "", f"{p.name}: find[1]: eta_train needs [train.dynamics] or [train.efficiency]\n")


def test_a_self_locking_worm_is_said_under_the_table(tmp_path):
    p = tmp_path / "w.toml"
    p.write_text("""
find = ["n2", "eta_worm_reverse_1"]
[train]
z = { "1" = 1, "2" = 40 }
[[train.mesh]]
gears = ["1", "2"]
kind = "worm"
hand = "right"
sign = 1
[[train.input]]
member = "1"
speed_rpm = 1440
[train.efficiency]
eta_mesh = 0.9
output = "2"
[[train.efficiency.worm]]
q = 10
f_v = 0.12
""", encoding="utf-8")
    an, _, _, lines = check(load_scene(p))
    gamma = math.atan(0.1)
    phi = math.atan(0.12)
    assert an.rows[1].exact == pytest.approx(math.tan(gamma - phi) / math.tan(gamma), rel=1e-14)
    assert an.rows[1].exact < 0
    assert [ln for ln in lines if ln.startswith("self_locking")] == [
        "self_locking: worm 1 self-locks: γ = 5.711° ≤ φ_v = 6.843°, the wheel cannot drive it (η′ = -0.1976)"]


def test_a_bevel_planet_s_speed_is_its_spin_relative_to_the_carrier():
    """The automobile differential, one wheel held: the case turns at 1500·15/45 = 500 r/min, the free
    wheel at 2·500 (i^H_13 = −1); the bevel planet's axis turns with the case, so its row is its spin
    about its own axis relative to the case, (n1 − nH)·z1/z2 = 500·20/12 — not nH + that, a sum
    across perpendicular axes."""
    an, _, extras, lines = check(load_scene(scene_path("trains/bevel_differential")))
    q = {r.name: r for r in an.rows}
    assert q["nH"].exact == pytest.approx(500.0, rel=1e-14) and q["n1"].exact == pytest.approx(1000.0, rel=1e-14)
    assert q["n2"].graphical == pytest.approx(500.0 * 20 / 12, rel=1e-14)
    assert q["n2"].exact == pytest.approx(500.0 * 20 / 12, rel=1e-14) and q["iH13"].exact == -1.0
    assert "sense: 2 spins + about its axis +y relative to its carrier H (arrow +x; its axis turns with H)" in lines
    assert extras["train"]["senses"]["2"] == "+x"


def test_identical_idlers_divide_the_power_at_one_efficiency(tmp_path):
    """Two idlers between 1 and 3: the power divides, but both branches lose the same fraction, so
    the book's series rule holds (η = 0.98²) — as the exact power balance finds."""
    p = tmp_path / "i.toml"
    p.write_text("""
find = ["eta_train", "n3"]
[train]
z = { "1" = 20, "2" = 30, "2b" = 30, "3" = 40 }
[[train.mesh]]
gears = ["1", "2"]
[[train.mesh]]
gears = ["2", "3"]
[[train.mesh]]
gears = ["1", "2b"]
[[train.mesh]]
gears = ["2b", "3"]
[[train.input]]
member = "1"
speed_rpm = 100
[train.efficiency]
eta_mesh = 0.98
output = "3"
""", encoding="utf-8")
    q = values(check_json(p))
    assert q["eta_train"]["graphical"] == pytest.approx(0.98 ** 2, rel=1e-15)
    assert q["eta_train"]["rel_error"] < 1e-14


def test_a_member_at_rest_reads_zero_off_the_diagram(tmp_path):
    """i^H_13 = (50·100)/(100·50) = 1 with the carrier driven: the sun 1 stays at rest; its ray falls
    on the pole's foot within round-off, read as 0 — not as −4e-12 r/min with a warning."""
    p = tmp_path / "r.toml"
    p.write_text('find = ["n1"]\n[train]\nfixed = ["3"]\nz = { "1" = 100, "2" = 50, "2\'" = 50, "3" = 100 }\n'
                 '[[train.member]]\nname = "2"\ngears = ["2", "2\'"]\ncarrier = "H"\n[[train.member]]\nname = "H"\n'
                 'gears = []\n[[train.mesh]]\ngears = ["1", "2"]\n[[train.mesh]]\ngears = ["2\'", "3"]\n'
                 '[[train.input]]\nmember = "H"\nspeed_rpm = 10000\n', encoding="utf-8")
    an, _, _, lines = check(load_scene(p))
    assert (an.rows[0].drawn_mm, an.rows[0].graphical, an.rows[0].exact) == (0.0, 0.0, 0.0)
    assert an.warnings == [] and "sense: 1 is at rest" in lines
