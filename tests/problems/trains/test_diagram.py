"""The geometry a gear-train scene is drawn with (graphmech/problems/trains/diagram.py): one layout
and one velocity diagram for the figure and the check, the scales chosen once for a list input,
none for a spatial train, a stage's own module closing a planet set."""
from __future__ import annotations

import math

import pytest

from graphmech.errors import NoSolution
from graphmech.exact.gear_train import solve
from graphmech.mechanisms.gear_train import rpm
from graphmech.problems.trains.diagram import asked, drawn
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES, run_cli


def test_the_conveyor_s_lengths_are_its_speeds():
    s = load_scene(SCENES / "train.conveyor_planetary_n4.toml")
    dr = drawn(s)
    d = dr.velocity
    assert d is not None and dr.mu_l == d.mu_l
    exact = solve(s.problem.train).omega
    for m, w in exact.items():
        assert d.lengths[m] * d.mu_omega == pytest.approx(w, rel=1e-12, abs=1e-12 * exact["1"])
    # the input's line through ω₁·r₁ at r₁ = m·z₁/2 = 10 mm
    assert dr.layout.radius["1"] == pytest.approx(0.010, rel=1e-15)


def test_a_list_input_is_read_at_the_first_value_s_scales():
    s = load_scene(SCENES / "train.textile_differential_n6.toml")
    first, second = drawn(s), drawn(s, {"1": rpm(200.0), "H": rpm(316.0)})
    assert first.velocity is not None and second.velocity is not None
    assert (second.velocity.mu_v, second.velocity.H) == (first.velocity.mu_v, first.velocity.H)
    n6 = second.velocity.omega("6") * 30 / math.pi
    assert n6 == pytest.approx(295.29256198347105, rel=1e-12)


def test_a_spatial_train_has_no_velocity_diagram():
    dr = drawn(load_scene(SCENES / "train.ysj10_4_worm_train.toml"))
    assert dr.velocity is None and not dr.layout.parallel


def test_stage_modules_close_the_winch_reducer_s_planet_set():
    s = load_scene(SCENES / "train.ysj10_8_winch_reducer.toml")
    assert dict(s.problem.gear_modules) == {"1": 0.003, "2": 0.003, "3": 0.004, "4": 0.004}
    lay = drawn(s).layout
    assert lay.arm("2") == pytest.approx(0.114, rel=1e-12)  # 3·(24 + 52)/2 = 4·(78 − 21)/2 mm
    one_module = parse_scene({"train": {"z": {"1": 24, "2": 52, "3": 21, "4": 78}, "fixed": ["4"],
                                         "member": [{"name": "2", "gears": ["2", "3"], "carrier": "H"},
                                                    {"name": "H", "gears": []}],
                                         "mesh": [{"gears": ["1", "2"]}, {"gears": ["3", "4"], "kind": "internal"}],
                                         "input": [{"member": "1", "speed_rpm": 100}]}}, "w.toml")
    with pytest.raises(NoSolution, match="not coaxial: arms 38 mm and 28.5 mm"):
        drawn(one_module)


PLANET_1_49999 = """
title = "p"
[train]
fixed = ["3"]
z = {{ "1" = 1, "2" = 49999, "3" = 99999 }}
[[train.member]]
name = "2"
carrier = "H"
[[train.member]]
name = "H"
gears = []
[[train.mesh]]
gears = ["1", "2"]
[[train.mesh]]
gears = ["2", "3"]
kind = "internal"
[[train.input]]
member = "1"
speed_rpm = {n}
"""


@pytest.mark.parametrize("n", ["100", "1e-150", "0"])
def test_extreme_trains_stay_on_the_sheet(tmp_path, n):
    """A sun of 1 tooth in a ring of 99 999 (the sun's ray 10⁵ times steeper than the carrier's), a
    speed of 10⁻¹⁵⁰ r/min, a train at rest: the scales are chosen so that the sheet holds them."""
    p = tmp_path / "p.toml"
    p.write_text(PLANET_1_49999.format(n=n), encoding="utf-8")
    code, _out, err = run_cli("render", str(p), "-o", str(tmp_path / "p.svg"))
    assert (code, err) == (0, "")
    d = drawn(load_scene(p)).velocity
    assert d is not None and 1.0 <= d.H <= 1000.0
    assert max(abs(x) for x in d.lengths.values()) <= 60.0 + 1e-9


def test_a_locked_train_is_said_before_its_drawing(tmp_path):
    p = tmp_path / "l.toml"
    p.write_text('[train]\nfixed = ["3"]\nz = { "1" = 80, "2" = 30, "3" = "coaxial" }\n'
                 '[[train.member]]\nname = "2"\ncarrier = "H"\n[[train.member]]\nname = "H"\ngears = []\n'
                 '[[train.mesh]]\ngears = ["2", "1"]\nkind = "internal"\n[[train.mesh]]\ngears = ["2", "3"]\n'
                 'kind = "internal"\n[[train.input]]\nmember = "1"\nspeed_rpm = 100\n', encoding="utf-8")
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "l.svg"))
    assert code == 2 and err.startswith("l.toml: the train locks") and not (tmp_path / "l.svg").exists()


def test_the_pole_distance_is_chosen_for_the_speeds_asked():
    # the closed differential asks n3 and n5: H = 40 mm (the sheet's most) draws ℓ5 = 3.35 mm, four
    # times the 0.84 mm an H fitted to the input's ray gave; the input's ray runs 164 mm, clipped
    s = load_scene(SCENES / "train.closed_differential_n3_n5.toml")
    assert asked(s) == ("5", "3")
    d = drawn(s).velocity
    assert d is not None and d.H == 40.0 and d.mu_v == 0.05
    assert d.lengths["5"] == pytest.approx(3.3510321638291125, rel=1e-12)
    assert d.lengths["1"] == pytest.approx(164.2, rel=1e-3)
    exact = solve(s.problem.train).omega
    assert d.omega("5") == pytest.approx(exact["5"], rel=1e-12)
    # the conveyor asks i14: the input's ray is asked too, so H stays where ℓ1 fits the ω line
    c = drawn(load_scene(SCENES / "train.conveyor_planetary_n4.toml")).velocity
    assert c is not None and c.H == 10.0 and abs(c.lengths["1"]) <= 60.0
