"""Checking a gear-train scene (graphmech/problems/trains/check.py): the rows asked for, the
default rows, the lines under the table, the JSON's basic trains, measured values judged."""
from __future__ import annotations

import math

import pytest

from graphmech.problems import check
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES, check_json, run_cli, values


def test_rows_and_lines_of_the_electric_screwdriver():
    an, verdicts, extras, lines = check(load_scene(SCENES / "train.electric_screwdriver.toml"))
    assert [r.name for r in an.rows] == ["i1H2", "nH2"]
    assert [r.unit for r in an.rows] == ["", "r/min"]
    assert all(r.drawn_mm is None and r.rel_error < 1e-15 for r in an.rows)
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
