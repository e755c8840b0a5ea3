"""[train.dynamics] and [train.efficiency] read from the [train] table's Reader, checked against
the train, and their rows (the book's method beside the exact solution) and lines."""
from __future__ import annotations

import math
import tomllib
from typing import Any

import pytest

from graphmech.errors import SceneError
from graphmech.exact.gear_train import solve
from graphmech.mechanisms.gear_train import Gear, GearTrain, Member, Mesh
from graphmech.problems.reader import Reader, Scene
from graphmech.problems.trains.dynamics import (
    TrainDynamics,
    check_dynamics,
    dynamics_lines,
    dynamics_rows,
    is_dynamics_name,
    read_dynamics,
    split_name,
)
from graphmech.problems.trains.scene import TrainScene
from tests.conftest import check_json, values

SEED = """
[train.dynamics]
reduce_to = "1"

[[train.dynamics.member]]
name = "1"
inertia_kgm2 = 0.01

[[train.dynamics.member]]
name = "2"
inertia_kgm2 = 0.04
mass_kg = 2

[[train.dynamics.member]]
name = "2'"
inertia_kgm2 = 0.01
mass_kg = 4

[[train.dynamics.member]]
name = "H"
inertia_kgm2 = 0.18
moment_Nm = 60

[train.efficiency]
eta_mesh = [0.98, 0.97]
output = "H"
"""


def read(text: str) -> tuple[TrainDynamics | None, list[tuple[str, str]]]:
    problems: list[tuple[str, str]] = []
    table: dict[str, Any] = tomllib.loads(text).get("train", {})
    return read_dynamics(Reader(table, "train", problems, {})), problems


def seed_train() -> GearTrain:
    return GearTrain((Member("1"), Member("2", "H"), Member("3"), Member("H")),
                     (Gear("1", 20, "1"), Gear("2", 40, "2"), Gear("2'", 20, "2"), Gear("3", 40, "3")),
                     (Mesh("1", "2"), Mesh("2'", "3")), fixed=("3",), inputs={"1": 10.0})


def scene(text: str, find: tuple[str, ...], train: GearTrain | None = None) -> Scene[TrainScene]:
    dyn, problems = read(text)
    assert problems == []
    ts = TrainScene(train or seed_train(), module=0.01, module_stated=True, dynamics=dyn)
    return Scene("t.toml", "t", (), find, {}, kind="trains", problem=ts)


def test_read_the_seed_tables() -> None:
    dyn, problems = read(SEED)
    assert problems == [] and dyn is not None
    assert dyn.reduce_to == "1" and [b.name for b in dyn.bodies] == ["1", "2", "2'", "H"]
    assert dyn.bodies[2].mass == 4.0 and dyn.bodies[3].moment == 60.0
    assert dyn.eta_mesh == (0.98, 0.97) and dyn.sink == "H" and dyn.source is None
    res = check_dynamics(dyn, seed_train(), problems)
    assert problems == []
    two = next(b for b in res.bodies if b.member == "2")
    assert (two.inertia, two.mass) == (pytest.approx(0.05), 6.0)  # the gears on one member add
    assert res.source == "1"  # the train's input


def test_nothing_posed_reads_none() -> None:
    assert read("[train]\nfixed = ['3']\n") == (None, [])


@pytest.mark.parametrize("text,path,reason", [
    ("[train.dynamics]\n[[train.dynamics.member]]\ninertia_kgm2 = 1", "train.dynamics.member[0].name", "missing"),
    ("[train.dynamics]\n[[train.dynamics.member]]\nname = '1'\ninertia_kg = 1", "train.dynamics.member[0].inertia_kg",
     "not a unit of a moment of inertia"),
    ("[train.dynamics]\n[[train.dynamics.member]]\nname = '1'\nmass_kg = -1", "train.dynamics.member[0].mass_kg", "≥ 0"),
    ("[train.dynamics]\n[[train.dynamics.member]]\nname = '2'\ncount = 0", "train.dynamics.member[0].count", "≥ 1"),
    ("[train.efficiency]\neta_mesh = 1.2\noutput = 'H'", "train.efficiency.eta_mesh", "(0, 1]"),
    ("[train.efficiency]\neta_mesh = 0.9\nouptut = 'H'", "train.efficiency.ouptut", "did you mean output"),
    ("[train.efficiency]\neta_mesh = 0.9\n[[train.efficiency.worm]]\nf_v = 0.1", "train.efficiency.worm[0]",
     "lead angle"),
    ("[train.efficiency]\neta_mesh = 0.9\n[[train.efficiency.worm]]\nq = 10\nf_v = 0.1\nphi_v_deg = 5",
     "train.efficiency.worm[0]", "one of them"),
])
def test_read_refusals(text: str, path: str, reason: str) -> None:
    _, problems = read(text)
    assert any(p == path and reason in r for p, r in problems), problems


def test_check_refusals_against_the_train() -> None:
    problems: list[tuple[str, str]] = []
    dyn, _ = read("[train.dynamics]\nreduce_to = '9'\n[[train.dynamics.member]]\nname = '1'\nmass_kg = 1\n"
                  "[train.efficiency]\neta_mesh = [0.9]\n")
    assert dyn is not None
    check_dynamics(dyn, seed_train(), problems)
    paths = dict(problems)
    assert "not a member" in paths["train.dynamics.reduce_to"]
    assert "fixed axis" in paths["train.dynamics.member[0]"]
    assert "1 efficiencies for 2 meshes" in paths["train.efficiency.eta_mesh"]
    assert paths["train.efficiency.output"].startswith("missing")


def test_names() -> None:
    assert split_name("J_red_2'") == ("J_red", "2'")
    assert split_name("eta_worm_reverse_1") == ("eta_worm_reverse", "1")
    assert split_name("eta_train") == ("eta_train", "")
    assert split_name("eta_H") == ("eta", "H")
    assert not is_dynamics_name("n4") and not is_dynamics_name("J_red") and not is_dynamics_name("iH13")


def test_the_seeds_rows() -> None:
    sc = scene(SEED, ("n4", "J_red_1", "M_red_1", "eta_train", "eta_H"))
    w = solve(sc.problem.train).omega
    rows = {r.name: r for r in dynamics_rows(sc, w)}
    assert list(rows) == ["J_red_1", "M_red_1", "eta_train", "eta_H"]
    assert rows["J_red_1"].graphical == pytest.approx(0.14, rel=1e-14) and rows["J_red_1"].unit == "kg·m²"
    assert rows["M_red_1"].exact == pytest.approx(-20.0, rel=1e-14)
    eta_h = 0.98 * 0.97
    assert rows["eta_H"].graphical == pytest.approx(eta_h) and rows["eta_H"].exact == pytest.approx(eta_h, rel=1e-14)
    # i_1H = −3: x = 1 − 1/i = 4/3, the sun drives the converted train
    assert rows["eta_train"].graphical == pytest.approx(1 - 4 / 3 * (1 - eta_h), rel=1e-12)
    assert all(r.rel_error < 1e-12 for r in rows.values())
    assert dynamics_lines(sc, list(rows.values())) == []


def test_rows_refused_in_one_line() -> None:
    w = solve(seed_train()).omega
    with pytest.raises(SceneError, match=r"find\[0\].*reduces to 1, not H"):
        dynamics_rows(scene(SEED, ("J_red_H",)), w)
    with pytest.raises(SceneError, match="not a carrier"):
        dynamics_rows(scene(SEED, ("eta_1",)), w)
    with pytest.raises(SceneError, match=r"needs \[train.efficiency\]"):
        dynamics_rows(scene("[train.dynamics]\nreduce_to = '1'\n", ("eta_train",)), w)


WORM = """
[train.efficiency]
eta_mesh = 1.0
input = "2"
output = "1"

[[train.efficiency.worm]]
q = 10
f_v = 0.12
"""


def test_a_self_locking_worm_is_said() -> None:
    t = GearTrain((Member("1"), Member("2")), (Gear("1", 1, "1"), Gear("2", 40, "2")),
                  (Mesh("1", "2", "worm", sign=1),), inputs={"1": 150.0})
    sc = scene(WORM, ("gamma_1", "phi_v_1", "eta_worm_1", "eta_worm_reverse_1", "eta_train"), t)
    rows = {r.name: r for r in dynamics_rows(sc, solve(t).omega)}
    assert rows["gamma_1"].exact == pytest.approx(math.degrees(math.atan(0.1)))
    assert rows["phi_v_1"].exact == pytest.approx(math.degrees(math.atan(0.12)))
    assert rows["eta_worm_reverse_1"].graphical == pytest.approx((0.1 - 0.12) / (1 + 0.012) / 0.1, rel=1e-12)
    assert rows["eta_train"].exact == pytest.approx(rows["eta_worm_reverse_1"].exact, rel=1e-12)
    lines = dynamics_lines(sc, list(rows.values()))
    assert lines[0].startswith("self_locking: worm 1 self-locks: γ = 5.711° ≤ φ_v = 6.843°")
    assert "the train self-locks from 2 to 1" in lines[1]


def test_a_planet_s_arm_takes_its_stage_s_module(tmp_path) -> None:
    """A planet of 1 kg on the arm 4·(20 + 30)/2 = 100 mm (the stages' module 4 mm, the train's
    unstated): i_1H = 1 + 80/20 = 5, so J_red_1 = m·(arm/i_1H)² = 1·0.02² = 4e-4 kg·m² — the
    stage's module, not the train's default 1 mm."""
    p = tmp_path / "a.toml"
    p.write_text("""
find = ["J_red_1"]
[train]
fixed = ["3"]
z = { "1" = 20, "2" = 30, "3" = 80 }
[[train.member]]
name = "2"
carrier = "H"
[[train.member]]
name = "H"
gears = []
[[train.mesh]]
gears = ["1", "2"]
m_mm = 4
[[train.mesh]]
gears = ["2", "3"]
kind = "internal"
m_mm = 4
[[train.input]]
member = "1"
speed_rad_s = 100
[train.dynamics]
reduce_to = "1"
[[train.dynamics.member]]
name = "2"
mass_kg = 1
""", encoding="utf-8")
    q = values(check_json(p))["J_red_1"]
    assert q["graphical"] == pytest.approx(4e-4, rel=1e-13) and q["exact"] == pytest.approx(4e-4, rel=1e-13)
