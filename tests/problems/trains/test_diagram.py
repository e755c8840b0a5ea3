"""The geometry a gear-train scene is drawn with (graphmech/problems/trains/diagram.py): one layout
and one velocity diagram for the figure and the check, the scales chosen once for a list input,
none for a spatial train, a stage's own module closing a planet set."""
from __future__ import annotations

import math

import pytest

from graphmech.errors import NoSolution
from graphmech.exact.gear_train import solve
from graphmech.mechanisms.gear_train import rpm
from graphmech.problems.trains.diagram import drawn
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES


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
