"""Flywheel scenes: [flywheel] in TOML, a Machine in SI out; every problem with the key path written."""

from __future__ import annotations

import dataclasses
import math
import re
import tomllib
from functools import partial
from pathlib import Path

import pytest

from graphmech.mechanisms.linkage import RPP, Crank, LinkPoint
from graphmech.mechanisms.machine import (
    CrankMoment,
    LinkMoment,
    Machine,
    Mass,
    Motor,
    SliderLoad,
    Table,
)
from graphmech.problems.flywheel.scene import (
    FLYWHEEL_SHOW_DEFAULT,
    Braking,
    FlywheelScene,
    TrueMotionSpec,
)
from graphmech.scene import Scene, load_scene, parse_scene
from tests.conftest import ROOT, reference_area, run_cli
from tests.scenes import only_problem, parse_text, refusal, replace_once, scene_text

DOCS = ROOT / "docs" / "scene-format.md"

#: Every feature at once: an offset slider-crank compressor with an indicator diagram, a moment
#: on link 3 and one on the crank, a motor, the true motion and braking.
COMPRESSOR = scene_text("flywheel/compressor")
#: fly.ic_engine_flywheel: an engine's crank torque, period π, no linkage.
ENGINE = scene_text("flywheel/engine")
#: fly.brake_time: braking only.
BRAKING = scene_text("flywheel/braking")

P_MPA = (0, 0.014, 0.032, 0.055, 0.087, 0.132, 0.201, 0.317, 0.5, 0.5, 0.5)
S_OVER_H = (0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1)
PISTON_AREA = math.pi * 0.12**2 / 4


# Messages name the file fly.toml.
parse = partial(parse_text, source="fly.toml")
problems_of = partial(refusal, source="fly.toml")
only = partial(only_problem, source="fly.toml")
replace = replace_once


def load_block(text: str, k: int) -> str:
    """``text`` up to (not including) its k-th [[flywheel.load]] (0-based)."""
    parts = text.split("[[flywheel.load]]")
    return "[[flywheel.load]]".join(parts[: k + 1])


# ------------------------------------------------------------------------------------------
# Round trips
# ------------------------------------------------------------------------------------------


def test_compressor_round_trip_in_si(tmp_path: Path) -> None:
    path = tmp_path / "compressor.toml"
    path.write_text(COMPRESSOR, encoding="utf-8")
    scene = load_scene(path)
    assert scene.source == "compressor.toml"
    assert scene.show == ("moment", "work", "energy", "inertia", "wittenbauer", "indicator")
    assert scene.find == ("J_F", "M_b", "Jp@1")
    assert scene.kind != "cam"
    fly = scene.problem
    assert isinstance(fly, FlywheelScene)
    assert (fly.positions, fly.method, fly.tangents, fly.pole_distance) == (12, "wittenbauer", "exact", 40.0)
    assert fly.true_motion == TrueMotionSpec("Radau", 1e-10)
    assert fly.braking == Braking(20.0, 3.0)

    m = fly.machine
    assert isinstance(m, Machine)
    assert m.linkage is scene.linkage
    crank = m.linkage.driver
    assert isinstance(crank, Crank) and crank.length == pytest.approx(0.075, rel=1e-15)
    assert m.linkage.points == (LinkPoint("S2", "2", ("B", "C"), pytest.approx(0.1), 0.0),)
    assert m.start == pytest.approx(math.radians(1.5280685946107546), rel=1e-15)
    assert m.cycle == 2 * math.pi
    assert m.omega_m == pytest.approx(960 * math.pi / 30, rel=1e-15)
    assert m.delta == 0.04
    assert m.masses == (Mass("2", "S2", 3.0, 0.025),)
    assert m.inertia == 0.0
    assert m.balance == "driving"
    assert m.motor == Motor(stiffness=1e5)
    assert m.sense == 1

    slider, on_link, on_crank = m.loads
    assert isinstance(slider, SliderLoad)
    assert (slider.point, slider.axis, slider.sense, slider.during) == ("C", 0.0, -1, "forward")
    assert slider.table.x == pytest.approx(S_OVER_H)
    assert slider.table.y == pytest.approx([p * 1e6 * PISTON_AREA for p in P_MPA], rel=1e-14)
    assert slider.table.y[-1] == pytest.approx(5654.866776461628)  # 0.5 MPa on a 120 mm piston
    assert on_link == LinkMoment(
        "3", Table(pytest.approx((0, math.pi, math.pi, 2 * math.pi)), (0.0, 0.0, -400.0, -400.0))
    )
    assert isinstance(on_crank, CrankMoment)
    assert on_crank.table.x == pytest.approx([math.radians(a) for a in (0, 20, 50, 180)])
    assert on_crank.table.y == (0.0, 200.0, 200.0, 0.0)

    # the positions the linkage is drawn at: 12, 30° apart from position 1, labelled 1 … 12
    assert scene.positions.labels == tuple(str(k) for k in range(1, 13))
    assert scene.positions.values == pytest.approx(
        [m.start + math.radians(30 * k) for k in range(12)], rel=1e-14
    )


def test_flywheel_scene_is_frozen() -> None:
    scene = parse(COMPRESSOR)
    with pytest.raises(dataclasses.FrozenInstanceError):
        scene.problem.positions = 24  # type: ignore[misc]
    with pytest.raises(dataclasses.FrozenInstanceError):
        scene.problem.machine.delta = 0.1  # type: ignore[misc]
    with pytest.raises(dataclasses.FrozenInstanceError):
        scene.problem.braking.moment = 1.0  # type: ignore[misc]


def test_engine_without_a_linkage() -> None:
    scene = parse(ENGINE)
    assert scene.linkage is None and scene.positions is None and scene.kind != "cam"
    fly = scene.problem
    assert (fly.positions, fly.method, fly.tangents, fly.pole_distance) == (12, "indicator", "exact", None)
    assert fly.true_motion is None and fly.braking is None
    m = fly.machine
    assert m.linkage is None and m.start == 0.0 and m.sense == 1
    assert m.cycle == math.pi
    assert m.omega_m == pytest.approx(620 * math.pi / 30, rel=1e-15)
    assert m.delta == 0.01
    assert m.balance == "resisting"
    assert (m.masses, m.inertia, m.motor) == ((), 0.0, None)
    (load,) = m.loads
    assert load == CrankMoment(
        Table(pytest.approx((0, math.pi / 9, 5 * math.pi / 18, math.pi)), (0.0, 200.0, 200.0, 0.0))
    )
    assert m.positions(fly.positions) == pytest.approx([math.pi * k / 12 for k in range(12)])


def test_braking_only_needs_no_delta_nor_loads() -> None:
    scene = parse(BRAKING)
    fly = scene.problem
    assert fly.braking == Braking(20.0, 3.0)
    m = fly.machine
    assert m.loads == () and m.inertia == 0.5 and m.omega_m == 100.0
    assert math.isnan(m.delta)  # nothing to smooth
    assert fly.positions == 12 and m.cycle == 2 * math.pi
    assert scene.show == ("rundown",)  # no cycle to draw: the run-down ω(t)
    # a time limit is optional; a δ, when given, is kept
    scene = parse(BRAKING.replace("time_limit_s = 3\n", "").replace("[flywheel]\n", "[flywheel]\ndelta = 0.05\n"))
    assert scene.problem.braking == Braking(20.0, None)
    assert scene.problem.machine.delta == 0.05


def test_defaults() -> None:
    text = (
        COMPRESSOR.replace("positions = 12\n", "")
        .replace("cycle_deg = 360\n", "")
        .replace('method = "wittenbauer"\n', "")
        .replace('tangents = "exact"\n', "")
        .replace("pole_distance_mm = 40\n", "")
        .replace("inertia_kgm2 = 0.0\n", "")
        .replace("inertia_kgm2 = 0.025\n", "")
        .replace('solver = "Radau"\nrtol = 1e-10\n', "")
        .replace('show = ["moment", "work", "energy", "inertia", "wittenbauer", "indicator"]\n', "")
    )
    scene = parse(text)
    fly = scene.problem
    assert (fly.positions, fly.method, fly.tangents, fly.pole_distance) == (12, "wittenbauer", "exact", None)
    assert fly.true_motion == TrueMotionSpec()
    assert fly.machine.cycle == 2 * math.pi and fly.machine.inertia == 0.0
    assert fly.machine.masses == (Mass("2", "S2", 3.0, 0.0),)
    assert scene.show == ("energy", "wittenbauer")


@pytest.mark.parametrize(
    ("written", "delta"), [("0.04", 0.04), ('"1/25"', 0.04), ('" 1 / 80 "', 0.0125), ('"3/100"', 0.03), ("1", 1.0)]
)
def test_delta_as_a_number_or_a_fraction(written: str, delta: float) -> None:
    assert parse(replace(COMPRESSOR, "delta = 0.04", f"delta = {written}")).problem.machine.delta == delta


def test_units_by_table_equal_units_by_suffix() -> None:
    by_table = parse(
        ENGINE.replace("[flywheel]", '[units]\nomega = "rpm"\nangle = "deg"\nmoment = "kNm"\n\n[flywheel]')
        .replace("speed_rpm", "speed")
        .replace("cycle_deg", "cycle")
        .replace("phi_deg", "phi")
        .replace("moment_Nm = [0, 200, 200, 0]", "moment = [0, 0.2, 0.2, 0]")
    )
    by_suffix = parse(
        ENGINE.replace("speed_rpm = 620", f"speed_rad_s = {620 * math.pi / 30!r}")
        .replace("cycle_deg = 180", f"cycle_rad = {math.pi!r}")
        .replace("moment_Nm = [0, 200, 200, 0]", "moment_kNm = [0, 0.2, 0.2, 0]")
    )
    a, b = by_table.problem.machine, by_suffix.problem.machine
    assert (a.omega_m, a.cycle) == pytest.approx((b.omega_m, b.cycle), rel=1e-15)
    assert a.loads[0].table.y == b.loads[0].table.y == (0.0, 200.0, 200.0, 0.0)


def test_pressure_units_area_and_force() -> None:
    def slider(text: str) -> SliderLoad:
        load = parse(text).problem.machine.loads[0]
        assert isinstance(load, SliderLoad)
        return load

    reference = slider(COMPRESSOR).table.y
    in_bar = COMPRESSOR.replace("pressure_MPa = [0, 0.014", "pressure_bar = [0, 0.14").replace(
        "0.5, 0.5, 0.5]", "5, 5, 5]"
    ).replace("0.032, 0.055, 0.087, 0.132, 0.201, 0.317", "0.32, 0.55, 0.87, 1.32, 2.01, 3.17")
    assert slider(in_bar).table.y == pytest.approx(reference, rel=1e-14)
    by_area = COMPRESSOR.replace("piston_diameter_mm = 120", f"area_m2 = {PISTON_AREA!r}")
    assert slider(by_area).table.y == pytest.approx(reference, rel=1e-15)
    forces = ", ".join(repr(f / 1000) for f in reference)
    by_force = re.sub(r"pressure_MPa = \[.*\]\npiston_diameter_mm = 120", f"force_kN = [{forces}]", COMPRESSOR)
    assert slider(by_force).table.y == pytest.approx(reference, rel=1e-15)
    both = slider(COMPRESSOR.replace('during = "forward"', 'during = "both"').replace('sense = "backward"', 'sense = "forward"'))
    assert (both.during, both.sense) == ("both", 1)
    with_units = COMPRESSOR.replace('angle = "deg"', 'angle = "deg"\npressure = "kPa"\nlength_unused = 1').replace(
        "pressure_MPa = [0, 0.014, 0.032, 0.055, 0.087, 0.132, 0.201, 0.317, 0.5, 0.5, 0.5]",
        "pressure = [0, 14, 32, 55, 87, 132, 201, 317, 500, 500, 500]",
    )
    err = problems_of(with_units)  # an unknown [units] entry is still an unknown key
    assert err.problems == [("units.length_unused", "unknown key; did you mean length?")]
    assert slider(with_units.replace("length_unused = 1\n", "")).table.y == pytest.approx(reference, rel=1e-13)


def test_clockwise_crank_and_a_pivot_mass() -> None:
    text = replace(COMPRESSOR, "omega_rpm = 960", 'omega_rpm = 960\ndirection = "cw"')
    text = replace(
        text,
        "[[flywheel.mass]]",
        '[[flywheel.mass]]\nlink = "1"\npoint = "A"\nmass_kg = 0\ninertia_kgm2 = 0.05\n\n[[flywheel.mass]]',
    )
    scene = parse(text)
    m = scene.problem.machine
    assert m.sense == -1 and m.omega_m == pytest.approx(960 * math.pi / 30)
    assert m.masses[0] == Mass("1", "A", 0.0, 0.05)
    # positions go clockwise from position 1
    assert scene.positions.values[1] == pytest.approx(m.start - math.radians(30))


def test_synchronous_motor() -> None:
    motor = parse(replace(COMPRESSOR, "stiffness = 1e5", "synchronous_rpm = 960.001")).problem.machine.motor
    assert motor == Motor(synchronous=pytest.approx(960.001 * math.pi / 30, rel=1e-15))


def test_slider_load_on_an_rpp_dyad_takes_its_guide_axis() -> None:
    text = scene_text("flywheel/rpp_slider_load")
    scene = parse(text)
    assert isinstance(scene.linkage.dyads[0], RPP)
    (load,) = scene.problem.machine.loads
    assert load.axis == pytest.approx(math.radians(30)) and load.table.y == (100.0, 100.0)


def test_scales_are_tied_by_the_pole_distance() -> None:
    tied = math.radians(2) * 10 * 40  # μφ·μM·H
    scales = f"\n[scales]\nphi_deg_per_mm = 2\nM_Nm_per_mm = 10\nT_J_per_mm = {tied!r}\n"
    assert parse(C + scales).scales["T"] == pytest.approx(tied)
    assert parse(C.replace("pole_distance_mm = 40\n", "") + scales.replace(repr(tied), "2")).scales["T"] == 2
    assert only(C + scales.replace(repr(tied), "2")) == (
        "scales.T_J_per_mm",
        "μT = 2 J/mm contradicts μM·μφ·H = 13.9626 J/mm (H = pole_distance_mm = 40): graphical integration "
        "ties the four; give three of them",
    )


def test_a_braking_only_scene_shows_no_cycle() -> None:
    assert parse(BRAKING).show == ("rundown",)
    assert only('show = ["wittenbauer"]\n' + BRAKING) == (
        "show[0]",
        "wittenbauer needs [[flywheel.load]]: a braking-only scene has no cycle to draw (show rundown or "
        "mechanism, or leave show out)",
    )
    assert only('show = ["energy", "rundown"]\n' + ENGINE.replace('show = ["moment", "energy"]\n', "")) == (
        "show[1]", "rundown needs a [flywheel.braking] table: the run-down under a brake")
    assert parse(ENGINE.replace('show = ["moment", "energy"]\n', "")).show == FLYWHEEL_SHOW_DEFAULT


def test_scales_measured_check_and_page() -> None:
    text = COMPRESSOR.replace("pole_distance_mm = 40\n", "") + """
[scales]
l_mm_per_mm = 5
v_m_s_per_mm = 0.1
phi_deg_per_mm = 2
M_Nm_per_mm = 10
J_kgm2_per_mm = 0.001
T_kJ_per_mm = 0.002

[measured]
"Jp@1" = 0.059
J_F = 0.47
"kl" = 61

[check]
precision_mm = 0.25

[page]
size = "A3"
"""
    scene = parse(text)
    assert scene.scales == pytest.approx(
        {"l": 0.005, "v": 0.1, "phi": math.radians(2), "M": 10.0, "J": 0.001, "T": 2.0}
    )
    assert scene.measured == (("Jp@1", 0.059), ("J_F", 0.47), ("kl", 61.0))
    assert scene.precision_mm == 0.25
    assert scene.page.size == (420.0, 297.0)


def test_find_names_and_position_labels() -> None:
    scene = parse(replace(COMPRESSOR, 'find = ["J_F", "M_b", "Jp@1"]', 'find = ["Jp@12", "omega_max", "T@3"]'))
    assert scene.find == ("Jp@12", "omega_max", "T@3")
    assert only(replace(COMPRESSOR, '"Jp@1"]', '"Jp@13"]')) == (
        "find[2]",
        "no position 13: the positions are numbered 1 … 12",
    )
    assert only(replace(COMPRESSOR, "positions = 12", "positions = 24").replace('"Jp@1"]', '"Jp@25"]'))[1] == (
        "no position 25: the positions are numbered 1 … 24"
    )
    assert only(replace(COMPRESSOR, '"Jp@1"]', '"Jp@01"]'))[1].startswith("no position 01")
    assert only(replace(COMPRESSOR, '"Jp@1"]', '"J F"]')) == (
        "find[2]",
        "'J F' is not a quantity name: letters, digits and underscores, then @position if it is "
        "one position's (J_F, M_b, Jp@1)",
    )


# ------------------------------------------------------------------------------------------
# Each problem: its key path and message
# ------------------------------------------------------------------------------------------

C = COMPRESSOR
MOMENT_LOAD = 'phi_deg = [0, 180, 180, 360]'


@pytest.mark.parametrize(
    ("text", "path", "message"),
    [
        (replace(C, "positions = 12", "positions = 2"), "flywheel.positions",
         "must lie between 4 and 3600, not 2: too few to draw the diagrams"),
        (replace(C, "positions = 12", "positions = 4000"), "flywheel.positions",
         "must lie between 4 and 3600, not 4000: absurd"),
        (replace(C, "positions = 12", "positions = 12.5"), "flywheel.positions",
         "must be a whole number of positions (4 … 3600), not 12.5"),
        (replace(C, "positions = 12", 'positions = "12"'), "flywheel.positions",
         "must be a whole number of positions (4 … 3600), not a string"),
        (replace(C, "delta = 0.04", "delta = 0"), "flywheel.delta",
         "must lie between 0 and 2, not 0: δ = (ω_max − ω_min)/ω_m, and ω_min > 0"),
        (replace(C, "delta = 0.04", "delta = 2.5"), "flywheel.delta",
         "must lie between 0 and 2, not 2.5: δ = (ω_max − ω_min)/ω_m, and ω_min > 0"),
        (replace(C, "delta = 0.04", 'delta = "25/1"'), "flywheel.delta",
         "must lie between 0 and 2, not '25/1': δ = (ω_max − ω_min)/ω_m, and ω_min > 0"),
        (replace(C, "delta = 0.04", 'delta = "1/0"'), "flywheel.delta",
         '\'1/0\' is not a fraction: write a number (0.04) or "1/25"'),
        (replace(C, "delta = 0.04", 'delta = "4%"'), "flywheel.delta",
         '\'4%\' is not a fraction: write a number (0.04) or "1/25"'),
        (replace(C, "delta = 0.04\n", ""), "flywheel.delta",
         'missing: the coefficient of speed fluctuation δ = (ω_max − ω_min)/ω_m, e.g. delta = 0.04 or "1/25"'),
        (replace(C, "cycle_deg = 360", "cycle_deg = 100"), "flywheel.cycle_deg",
         ("must divide one turn a whole number of times (360°, 180°, 120° …) or be two turns (720°, a "
          "four-stroke engine), not 100°")),
        (replace(C, "cycle_deg = 360", "cycle_deg = 1080"), "flywheel.cycle_deg",
         ("must divide one turn a whole number of times (360°, 180°, 120° …) or be two turns (720°, a "
          "four-stroke engine), not 1080°")),
        (replace(C, "cycle_deg = 360", "cycle_deg = 0"), "flywheel.cycle_deg", "must be > 0"),
        (replace(C, "cycle_deg = 360", "cycle_deg = 360\nspeed_rpm = 960"), "flywheel.speed_rpm",
         "given twice: with a linkage the mean speed ω_m is the driver's omega (driver.omega_rpm)"),
        (replace(C, 'balance = "driving"\n', ""), "flywheel.balance",
         'missing: write balance = "driving" or "resisting"'),
        (replace(C, 'balance = "driving"', 'balance = "drive"'), "flywheel.balance",
         "unknown value 'drive': use driving or resisting (did you mean driving?)"),
        (replace(C, 'method = "wittenbauer"', 'method = "witenbauer"'), "flywheel.method",
         "unknown value 'witenbauer': use wittenbauer or indicator (did you mean wittenbauer?)"),
        (replace(C, 'tangents = "exact"', 'tangents = "approximate"'), "flywheel.tangents",
         "unknown value 'approximate': use exact or book"),
        (replace(C, "pole_distance_mm = 40", "pole_distance_mm = -4"), "flywheel.pole_distance_mm", "must be > 0"),
        (replace(C, "pole_distance_mm = 40", "pole_distance_cm = 4"), "flywheel.pole_distance_cm",
         "H is a distance on the drawing: write pole_distance_mm"),
        (replace(C, "inertia_kgm2 = 0.0", "inertia_kgm2 = -1"), "flywheel.inertia_kgm2", "must be ≥ 0, not -1 kgm2"),
        (replace(C, "inertia_kgm2 = 0.0", "inertia_kg = 1"), "flywheel.inertia_kg",
         "kg is not a unit of a moment of inertia; write inertia_kgm2"),
        # masses
        (replace(C, 'link = "2"\npoint = "S2"', 'link = "7"\npoint = "S2"'), "flywheel.mass[0].link",
         "link 7 is not a moving link (links: 1, 2, 3)"),
        (replace(C, 'link = "2"\npoint = "S2"', 'link = "4"\npoint = "S2"'), "flywheel.mass[0].link",
         "link 4 is the frame: it does not move"),
        (replace(C, 'link = "2"\npoint = "S2"', 'link = "2"\npoint = "A"'), "flywheel.mass[0].point",
         "A is not a point of link 2 (it carries B, C, S2)"),
        (replace(C, 'link = "2"\npoint = "S2"', 'link = "2"\npoint = "S9"'), "flywheel.mass[0].point",
         "S9 is not a point of link 2 (it carries B, C, S2)"),
        (replace(C, 'point = "S2"', 'point = "s2"'), "flywheel.mass[0].point",
         "'s2' is not a point name: capital letters, then digits or primes (B, C2, E')"),
        (replace(C, "mass_kg = 3", "mass_kg = -3"), "flywheel.mass[0].mass_kg", "must be ≥ 0, not -3 kg"),
        (replace(C, "mass_kg = 3\n", ""), "flywheel.mass[0].mass",
         "missing: write mass_kg (or mass with [units] mass)"),
        (replace(C, "[[flywheel.load]]", '[[flywheel.mass]]\nlink = "2"\npoint = "B"\nmass_kg = 1\n\n[[flywheel.load]]'),
         "flywheel.mass[1].link", "link 2 already has its mass (flywheel.mass[0])"),
        # a slider load
        (replace(C, 'point = "C"', 'point = "B"'), "flywheel.load[0].point",
         "B is not a slider: a slider load acts on the slider point of an RRP or RPP dyad (this linkage's: C)"),
        (replace(C, 'during = "forward"', 'during = "compression"'), "flywheel.load[0].during",
         "unknown value 'compression': use forward, backward or both"),
        (replace(C, 'sense = "backward"\n', ""), "flywheel.load[0].sense",
         'missing: write sense = "forward" or "backward"'),
        (replace(C, "0.014", "-0.014"), "flywheel.load[0].pressure_MPa[1]",
         "must be ≥ 0, not -0.014 MPa: the diagram gives the force's magnitude; sense gives its direction"),
        (replace(C, "0.5, 0.5, 0.5]", "0.5, 0.5]"), "flywheel.load[0].pressure_MPa",
         "has 10 values, s_over_H has 11: one value for each"),
        (replace(C, "s_over_H = [0, 0.1,", "s_over_H = [0.05, 0.1,"), "flywheel.load[0].s_over_H[0]",
         "must be 0, not 0.05: s/H runs from 0 to 1"),
        (replace(C, "0.8, 0.9, 1]", "0.8, 0.9, 0.95]"), "flywheel.load[0].s_over_H[10]",
         "must be 1, not 0.95: s/H runs from 0 to 1"),
        (replace(C, "0.8, 0.9, 1]", "0.8, 0.9, 1.2]"), "flywheel.load[0].s_over_H[10]",
         "must lie between 0 and 1, not 1.2: s/H is the slider's displacement over its stroke"),
        (replace(C, "0.2, 0.3, 0.4", "0.3, 0.2, 0.4"), "flywheel.load[0].s_over_H[3]",
         "0.2 comes after 0.3: the values must not decrease (a repeated value is a step)"),
        (replace(C, "s_over_H = [0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1]", "s_over_H = [0]"),
         "flywheel.load[0].s_over_H", "must have at least 2 points, not 1"),
        (replace(C, "piston_diameter_mm = 120", "piston_diameter_mm = 120\narea_mm2 = 11310"),
         "flywheel.load[0].area_mm2", "give piston_diameter or area, not both"),
        (replace(C, "piston_diameter_mm = 120\n", ""), "flywheel.load[0].piston_diameter",
         "missing: with pressure give piston_diameter_mm (the area is π d²/4) or area_mm2"),
        (replace(C, "piston_diameter_mm = 120", "piston_diameter_mm = 120\nforce_N = [0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1]"),
         "flywheel.load[0].force_N", "give force or pressure (with the piston's area), not both"),
        (re.sub(r"pressure_MPa = \[.*\]\n", "", C), "flywheel.load[0].force",
         "missing: give force_N = [...] (one per s_over_H), or pressure_MPa = [...] with piston_diameter_mm"),
        (re.sub(r"pressure_MPa = \[.*\]", "force_N = [0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1]", C),
         "flywheel.load[0].piston_diameter_mm", "only with pressure (force is already a force)"),
        (replace(C, "pressure_MPa", "pressure_N"), "flywheel.load[0].pressure_N",
         "N is not a unit of a pressure; write pressure_MPa, pressure_kPa, pressure_Pa or pressure_bar"),
        (replace(C, 'sense = "backward"', 'sense = "backward"\nlink = "3"'), "flywheel.load[0].link",
         'only for type = "moment" or "crank" (this load is slider)'),
        # a moment on a link, and on the crank
        (replace(C, MOMENT_LOAD, "phi_deg = [0, 180, 170, 360]"), "flywheel.load[1].phi_deg[2]",
         "170° comes after 180°: the angles must not decrease (a repeated value is a step)"),
        (replace(C, MOMENT_LOAD, "phi_deg = [0, 180, 180, 400]"), "flywheel.load[1].phi_deg[3]",
         "400° is outside the cycle: φ runs from 0 at position 1 to Φ = 360°"),
        (replace(C, MOMENT_LOAD, "phi_deg = [-10, 180, 180, 360]"), "flywheel.load[1].phi_deg[0]",
         "-10° is outside the cycle: φ runs from 0 at position 1 to Φ = 360°"),
        (replace(C, "phi_deg = [0, 20, 50, 180]", "phi_deg = [0, 20, 50, 360]")
         .replace(MOMENT_LOAD, "phi_deg = [0, 90, 90, 180]").replace("cycle_deg = 360", "cycle_deg = 180"),
         "flywheel.load[2].phi_deg[3]", "360° is outside the cycle: φ runs from 0 at position 1 to Φ = 180°"),
        (replace(C, "moment_Nm = [0, 0, -400, -400]", "moment_Nm = [0, 0, -400]"), "flywheel.load[1].moment_Nm",
         "has 3 values, phi_deg has 4: one moment for each"),
        (replace(C, 'link = "3"\nphi_deg', 'link = "4"\nphi_deg'), "flywheel.load[1].link",
         "link 4 is the frame: a moment on it does no work"),
        (replace(C, 'link = "3"\nphi_deg', 'link = "9"\nphi_deg'), "flywheel.load[1].link",
         "link 9 is not a moving link (links: 1, 2, 3)"),
        (replace(C, 'link = "3"\nphi_deg', "phi_deg"), "flywheel.load[1].link",
         'missing: the number of the link it acts on, e.g. link = "3"'),
        (replace(C, 'type = "moment"', 'type = "torque"'), "flywheel.load[1].type",
         "unknown value 'torque': use slider, moment or crank"),
        (replace(C, 'type = "crank"\nphi_deg', 'type = "crank"\nlink = "1"\nphi_deg'), "flywheel.load[2].link",
         'a "crank" load acts on the crank itself: leave link out (or write type = "moment")'),
        (replace(C, 'type = "crank"\nphi_deg', 'type = "crank"\npoint = "C"\nphi_deg'), "flywheel.load[2].point",
         'only for type = "slider" (this load is crank)'),
        (replace(C, "moment_Nm = [0, 200, 200, 0]", "moment_Nm = 200"), "flywheel.load[2].moment_Nm",
         "must be a list of numbers, not a number"),
        (replace(C, "moment_Nm = [0, 200, 200, 0]", "moment_Nm = [0, 200, inf, 0]"), "flywheel.load[2].moment_Nm[2]",
         "must be a finite number, not inf"),
        (replace(C, "moment_Nm = [0, 200, 200, 0]", "moment = [0, 200, 200, 0]"), "flywheel.load[2].moment",
         "unit not stated: write moment_Nm or set [units] moment"),
        # the motor, the true motion, braking
        (replace(C, 'balance = "driving"', 'balance = "resisting"'), "flywheel.motor",
         'only with balance = "driving": a motor\'s characteristic gives the driving moment, and here the constant '
         "moment is the resistance"),
        (replace(C, "stiffness = 1e5", "synchronous_rpm = 950"), "flywheel.motor.synchronous_rpm",
         "must exceed the mean speed ω_m = 960 rpm: a motor gives no moment at its synchronous speed"),
        (replace(C, "stiffness = 1e5", "stiffness = 1e5\nsynchronous_rpm = 980"), "flywheel.motor.synchronous_rpm",
         "give stiffness or synchronous, not both"),
        (replace(C, "stiffness = 1e5", ""), "flywheel.motor",
         "give stiffness (e.g. stiffness = 1e5) or the synchronous speed (synchronous_rpm, above the mean speed)"),
        (replace(C, "stiffness = 1e5", "stiffness = 0"), "flywheel.motor.stiffness", "must be > 0"),
        (replace(C, "rtol = 1e-10", "rtol = 1e-16"), "flywheel.true_motion.rtol",
         "must lie between 1e-14 and 0.01, not 1e-16"),
        (replace(C, 'solver = "Radau"', 'solver = "radau"'), "flywheel.true_motion.solver",
         "unknown value 'radau': use Radau, BDF, LSODA, RK45 or DOP853 (did you mean Radau?)"),
        (replace(C, "moment_Nm = 20", "moment_Nm = -20"), "flywheel.braking.moment_Nm", "must be > 0"),
        (replace(C, "time_limit_s = 3", "time_limit_s = 0"), "flywheel.braking.time_limit_s", "must be > 0"),
        (replace(C, "time_limit_s = 3", "time_limit_min = 3"), "flywheel.braking.time_limit_min",
         "unknown key; did you mean time_limit_ms?"),
        # the driver of a flywheel scene
        (replace(C, "angle = 1.5280685946107546", "angle = [0, 30]"), "driver.angle",
         "one number in a flywheel scene: the crank's angle at position 1 (the [flywheel] positions divide the "
         "cycle from there)"),
        (replace(C, "omega_rpm = 960", "omega_rpm = 960\nepsilon_rad_s2 = 2"), "driver.epsilon_rad_s2",
         "not in a flywheel scene: the crank turns at the mean speed ω_m on average, and how far it strays is what "
         "the flywheel limits; leave epsilon out"),
        (replace(C, "omega_rpm = 960", "omega_rpm = 0"), "driver.omega_rpm",
         "must not be 0: it is the crank's mean speed ω_m, and its sign the sense of rotation"),
        (replace(C, 'type = "crank"', 'type = "slider"'), "driver.type",
         'a flywheel scene\'s driver is a crank (type = "crank"): the machine is reduced to its crank'),
        # the header and the other tables
        (replace(C, '"indicator"]', '"indicator", "velocity"]'), "show[6]",
         "unknown value 'velocity': use mechanism, moment, work, energy, inertia, wittenbauer, indicator, motion or rundown"),
        (C + '\n[measured]\n"Jp@13" = 0.06\n', "measured.Jp@13", "no position 13: the positions are numbered 1 … 12"),
        (C + "\n[scales]\nM_J_per_mm = 10\n", "scales.M_J_per_mm",
         "J_per_mm is not a unit of a moment; write M_Nm_per_mm or M_kNm_per_mm"),
        (C + "\n[scales]\na_m_s2_per_mm = 1\n", "scales.a_m_s2_per_mm", "unknown key; did you mean v_m_s_per_mm?"),
        (C + "\n[check]\nprecision_mm = 0\n", "check.precision_mm", "must be > 0"),
        (C + '\n[page]\nsize = "A5"\n', "page.size",
         "unknown paper 'A5': use A4, A4-portrait, A3, A3-portrait, A2, A2-portrait, A1, A1-portrait, "
         "fit (the drawing cropped) or [width, height] in mm"),
    ],
)
def test_each_problem_names_its_key(text: str, path: str, message: str) -> None:
    assert only(text) == (path, message)


def test_loads_missing_entirely() -> None:
    no_loads = load_block(C, 0).split("[flywheel.motor]")[0]
    assert only(no_loads) == ("flywheel.load", "no [[flywheel.load]]: nothing for the flywheel to smooth")
    assert only(no_loads.replace("positions = 12", "positions = 12\nload = []")) == (
        "flywheel.load",
        "no [[flywheel.load]]: nothing for the flywheel to smooth",
    )
    assert only(replace(ENGINE, "[[flywheel.load]]", "[flywheel.load]")) == (
        "flywheel.load",
        "must be an array of tables: write [[flywheel.load]]",
    )


def test_without_a_linkage() -> None:
    mass = '\n[[flywheel.mass]]\nlink = "2"\npoint = "S2"\nmass_kg = 3\n'
    assert only(ENGINE + mass) == (
        "flywheel.mass",
        "[[flywheel.mass]] needs a linkage ([frame], [driver], [[dyad]] …): without one give the machine's "
        "whole reduced inertia as flywheel.inertia_kgm2",
    )
    slider = ENGINE + '\n[[flywheel.load]]\ntype = "slider"\npoint = "C"\ns_over_H = [0, 1]\nforce_N = [1, 1]\n'
    assert only(slider) == (
        "flywheel.load[1].type",
        'a "slider" load needs a linkage ([frame], [driver], [[dyad]] …): without one give the moments '
        'reduced to the crank, type = "crank"',
    )
    moment = ENGINE + '\n[[flywheel.load]]\ntype = "moment"\nlink = "3"\nphi_deg = [0, 1]\nmoment_Nm = [1, 1]\n'
    assert only(moment)[0] == "flywheel.load[1].type"
    assert only(ENGINE.replace("speed_rpm = 620\n", "")) == (
        "flywheel.speed",
        "missing: write speed_rad_s (or speed with [units] omega)",
    )
    assert only(ENGINE.replace("speed_rpm = 620", "speed_rpm = -620")) == ("flywheel.speed_rpm", "must be > 0")
    assert only(ENGINE + "\n[scales]\nl_mm_per_mm = 2\n") == (
        "scales.l_mm_per_mm",
        "only with a linkage: a flywheel scene without one has no mechanism to draw",
    )
    assert only(ENGINE.replace('show = ["moment", "energy"]', 'show = ["mechanism"]')) == (
        "show[0]",
        "unknown value 'mechanism': use moment, work, energy, inertia, wittenbauer, indicator, motion or rundown",
    )
    assert only(ENGINE.replace('find = ["Mr", "DeltaW_max", "J_F"]', 'find = ["J_F@13"]')) == (
        "find[0]",
        "no position 13: the positions are numbered 1 … 12",
    )


def test_braking_only_scenes() -> None:
    assert only(BRAKING.replace("inertia_kgm2 = 0.5\n", "")) == (
        "flywheel.braking",
        "nothing to stop: a braking-only scene designs no flywheel, so give the machine's reduced inertia "
        "(inertia_kgm2) or its [[flywheel.mass]]",
    )
    assert only(BRAKING.replace("inertia_kgm2 = 0.5", "inertia_kgm2 = 0"))[0] == "flywheel.braking"
    assert only(BRAKING + "\n[flywheel.motor]\nstiffness = 1e5\n") == (
        "flywheel.motor",
        "only with [[flywheel.load]]: a motor drives the machine through its cycle, and a braking-only scene has none",
    )
    assert only(BRAKING + "\n[flywheel.true_motion]\n") == (
        "flywheel.true_motion",
        "only with [[flywheel.load]]: the true motion is run with the designed J_F, and a braking-only scene "
        "designs none",
    )
    assert only(BRAKING.replace("moment_Nm = 20\n", "")) == (
        "flywheel.braking.moment",
        "missing: write moment_Nm (or moment with [units] moment)",
    )
    # still validated when given
    assert only(BRAKING.replace("[flywheel]\n", "[flywheel]\ndelta = 3\n"))[0] == "flywheel.delta"
    # a linkage with its masses may stand in for the inertia
    linkage = load_block(C, 0).replace("inertia_kgm2 = 0.0\n", "").replace("delta = 0.04\n", "")
    linkage = re.sub(r"show = .*\n", 'show = ["mechanism", "rundown"]\n', linkage)
    scene = parse(linkage + "[flywheel.braking]\nmoment_Nm = 20\n")
    assert scene.problem.machine.masses and scene.problem.machine.loads == ()
    assert len(scene.positions.values) == 12


def test_cam_and_flywheel_is_one_line() -> None:
    cam = '\n[cam]\nbase_radius_mm = 30\nrotation = "ccw"\nomega_rad_s = 1\n'
    err = problems_of(ENGINE + cam)
    assert err.problems == [
        (
            "flywheel",
            "a scene is a disc cam ([cam]) or a flywheel problem ([flywheel]), not both: put each in a scene of its own",
        )
    ]
    assert str(err).count("\n") == 0 and str(err).startswith("fly.toml: flywheel: a scene is")


def test_misspelt_keys_get_suggestions() -> None:
    err = problems_of(replace(C, "delta = 0.04", "dleta = 0.04"))
    assert err.problems == [  # the typo first: it is why the other is missing
        ("flywheel.dleta", "unknown key; did you mean delta?"),
        (
            "flywheel.delta",
            'missing: the coefficient of speed fluctuation δ = (ω_max − ω_min)/ω_m, e.g. delta = 0.04 or "1/25"',
        ),
    ]
    assert problems_of(replace(C, "mass_kg = 3", "mass_gk = 3")).problems[0] == (
        "flywheel.mass[0].mass_gk",
        "unknown key; did you mean mass_kg?",
    )
    assert problems_of(replace(C, "s_over_H = [", "s_over_h = [")).problems[0] == (
        "flywheel.load[0].s_over_h",
        "unknown key; did you mean s_over_H?",
    )
    assert only(replace(C, "[flywheel.true_motion]", "[flywheel.true_moton]")) == (
        "flywheel.true_moton",
        "unknown key; did you mean true_motion?",
    )
    assert problems_of(replace(C, "[[flywheel.load]]", "[[flywheel.loads]]")).problems[0] == (
        "flywheel.loads",
        "unknown key; did you mean load?",
    )
    assert only(replace(C, "pole_distance_mm = 40", "pole_distanse_mm = 40")) == (
        "flywheel.pole_distanse_mm",
        "unknown key; did you mean pole_distance_mm?",
    )
    assert only(replace(C, "positions = 12", "postions = 12")) == (
        "flywheel.postions",
        "unknown key; did you mean positions?",
    )
    # a linkage scene with a misspelt [flywheel] is still a linkage scene, told of the spelling
    linkage = re.sub(r"show = .*\n", "", C.split("[flywheel]")[0])
    assert only(linkage + "[flywheels]\ndelta = 0.04\n") == ("flywheels", "unknown key; did you mean flywheel?")


def test_every_problem_is_collected_in_file_order() -> None:
    text = (
        C.replace("positions = 12", "positions = 2")
        .replace("delta = 0.04", "delta = 9")
        .replace('point = "S2"', 'point = "A"')
        .replace("0.014", "-0.014")
        .replace("phi_deg = [0, 20, 50, 180]", "phi_deg = [0, 20, 10, 180]")
        .replace("rtol = 1e-10", "rtol = 1")
        .replace("length = 300", "length = -300")
    )
    err = problems_of(text)
    assert [p for p, _ in err.problems] == [
        "dyad[0].length",
        "flywheel.positions",
        "flywheel.delta",
        "flywheel.load[0].pressure_MPa[1]",
        "flywheel.load[2].phi_deg[2]",
        "flywheel.true_motion.rtol",
    ]  # the broken linkage leaves the mass's point unjudged
    assert str(err).startswith("fly.toml: dyad[0].length: must be > 0") and str(err).endswith("(and 5 more)")
    assert "\n" not in str(err)


def test_check_of_a_bad_flywheel_scene_is_one_line_exit_2(tmp_path: Path) -> None:
    path = tmp_path / "bad.toml"
    path.write_text(replace(ENGINE, "delta = 0.01", "delta = 3"), encoding="utf-8")
    code, out, err = run_cli("check", str(path))
    assert code == 2 and out == ""
    assert err == (
        "bad.toml: flywheel.delta: must lie between 0 and 2, not 3: δ = (ω_max − ω_min)/ω_m, and ω_min > 0\n"
    )
    path.write_text(load_block(ENGINE, 0), encoding="utf-8")
    code, _, err = run_cli("check", str(path))
    assert code == 2 and err == "bad.toml: flywheel.load: no [[flywheel.load]]: nothing for the flywheel to smooth\n"


# ------------------------------------------------------------------------------------------
# The documentation and the reference problems
# ------------------------------------------------------------------------------------------


def doc_flywheel_scenes() -> dict[str, Scene]:
    blocks = re.findall(r"^```toml\n(.*?)^```", DOCS.read_text(encoding="utf-8"), re.DOTALL | re.MULTILINE)
    scenes = [parse_scene(tomllib.loads(b), "scene-format.md") for b in blocks]
    return {s.title: s for s in scenes if s.kind == "flywheel"}



def test_docs_have_the_five_flywheel_examples() -> None:
    scenes = doc_flywheel_scenes()
    assert len(scenes) == 5
    given_dT = [s for s in scenes.values() if s.problem.machine.energy_table is not None]
    assert len(given_dT) == 1 and given_dT[0].problem.machine.loads == ()
    tables = [s for s in scenes.values() if s.problem.machine.inertia_table is not None and s.problem.machine.loads]
    assert len(tables) == 1 and tables[0].measured == (("kl", 61.0), ("J_F", 42.4))
    with_linkage = [s for s in scenes.values() if s.linkage is not None]
    assert len(with_linkage) == 1 and with_linkage[0].problem.true_motion is not None
    kinds = {load.kind for s in scenes.values() for load in s.problem.machine.loads}
    assert kinds == {"slider", "crank"}
    assert {s.problem.machine.balance for s in scenes.values() if s.problem.machine.loads} == {"driving", "resisting"}
    assert any(s.problem.braking is not None and not s.problem.machine.loads for s in scenes.values())


TWELVE = "[0, 30, 60, 90, 120, 150, 180, 210, 240, 270, 300, 330]"
SAME_J = "[" + ", ".join(["0.6"] * 12) + "]"


def jp_table(phi: str, inertia: str) -> str:
    """The engine of fly.ic_engine_flywheel over a turn, with Jп given as a table (two TOML lists)."""
    return (replace(ENGINE, "cycle_deg = 180", "cycle_deg = 360")
            + f"\n[flywheel.reduced_inertia]\nphi_deg = {phi}\ninertia_kgm2 = {inertia}\n")


def test_documented_error_messages_are_real() -> None:
    """Every line of the flywheel 'What is refused' block is a message the reader gives."""
    text = DOCS.read_text(encoding="utf-8")
    section = text.split("### What is refused in a flywheel scene", 1)[1]
    documented = re.search(r"```text\n(.*?)```", section, re.DOTALL).group(1).strip().splitlines()
    mistakes = [
        load_block(C, 0).split("[flywheel.motor]")[0],
        replace(C, "delta = 0.04", "delta = 2.5"),
        replace(C, "positions = 12", "positions = 2"),
        replace(C, "cycle_deg = 360", "cycle_deg = 100"),
        jp_table("[0, 30, 60, 90]", "[0.6, 0.7, 0.8, 0.9]").replace("60, 90]", "90, 60]"),
        jp_table(TWELVE, SAME_J).replace("cycle_deg = 360", "cycle_deg = 720"),
        jp_table("[0, 120, 240]", "[0.6, 0.7, 0]"),
        jp_table(TWELVE[:-1] + ", 360]", SAME_J[:-1] + ", 0.7]"),
        DT_SCENE.replace("[page]", '[[flywheel.load]]\ntype = "crank"\nphi_deg = [0, 360]\nmoment_Nm = [1, 1]\n[page]'),
        replace(DT_SCENE, "increment_J = [0, -342.7", "increment_J = [5, -342.7"),
        replace(C, "cycle_deg = 360", "cycle_deg = 360\nspeed_rpm = 960"),
        replace(C, 'link = "2"\npoint = "S2"', 'link = "2"\npoint = "A"'),
        replace(C, 'point = "C"', 'point = "B"'),
        replace(C, "0.5, 0.5, 0.5]", "0.5, 0.5]"),
        replace(ENGINE, "phi_deg = [0, 20, 50, 180]", "phi_deg = [0, 180, 170, 180]").replace("cycle_deg = 180", "cycle_deg = 360"),
        replace(ENGINE, "phi_deg = [0, 20, 50, 180]", "phi_deg = [0, 20, 50, 400]").replace("cycle_deg = 180", "cycle_deg = 360"),
        ENGINE.replace('type = "crank"', 'type = "slider"\npoint = "C"').replace("phi_deg = [0, 20, 50, 180]\nmoment_Nm = [0, 200, 200, 0]", "s_over_H = [0, 1]\nforce_N = [1, 1]"),
        replace(C, 'balance = "driving"', 'balance = "resisting"'),
        BRAKING.replace("inertia_kgm2 = 0.5\n", ""),
        C + '\n[measured]\n"Jp@13" = 0.06\n',
        replace(C, "angle = 1.5280685946107546", "angle = [0, 30]"),
        ENGINE + '\n[cam]\nbase_radius_mm = 30\n',
        C + "\n[scales]\nphi_deg_per_mm = 2\nM_Nm_per_mm = 10\nT_J_per_mm = 2\n",
        'show = ["energy"]\n' + BRAKING,
    ]
    got = [str(problems_of(m)) for m in mistakes]
    assert [line.replace("fly.toml: ", "", 1) for line in documented] == [g.replace("fly.toml: ", "", 1) for g in got]


def test_compressor_course_project() -> None:
    p = reference_area("flywheel")["fly.compressor_course_project"]
    inputs, exact = p["inputs"], p["exact"]
    scene = doc_flywheel_scenes()["Air compressor: flywheel by the Wittenbauer diagram"]
    m = scene.problem.machine
    crank, rod = m.linkage.driver, m.linkage.dyads[0]
    assert crank.length == pytest.approx(inputs["lAB_m"]) and rod.length == pytest.approx(inputs["lBC_m"])
    assert rod.guide.through[1] == pytest.approx(inputs["e_m"])
    assert m.linkage.points[0].along == pytest.approx(inputs["lBS2_m"])
    assert m.omega_m == pytest.approx(exact["omega_m_rad_s"], rel=1e-15)
    assert m.delta == pytest.approx(inputs["delta"], rel=1e-15)
    assert m.start == pytest.approx(math.radians(exact["theta_ODC_deg"]), rel=1e-15)
    assert m.inertia == inputs["J1_kgm2"]
    assert m.masses == (
        Mass("2", "S2", inputs["m2_kg"], inputs["JS2_kgm2"]),
        Mass("3", "C", inputs["m3_kg"], 0.0),
    )
    (load,) = m.loads
    assert load.table.x == pytest.approx(inputs["load_table_s_over_H"])
    area = exact["A_piston_m2"]
    assert load.table.y == pytest.approx([p * 1e6 * area for p in inputs["load_table_p_MPa"]], rel=1e-14)
    assert (load.axis, load.sense, load.during) == (0.0, -1, "forward")  # toward A, compressing
    assert scene.problem.positions == inputs["positions_N"]
    assert [math.degrees(phi) for phi in m.positions(scene.problem.positions)] == pytest.approx(
        exact["positions_phi_deg"]
    )
    # position 1 is the outer dead centre: A, B, C collinear
    assert scene.positions.values[0] == pytest.approx(math.asin(inputs["e_m"] / (inputs["lAB_m"] + inputs["lBC_m"])))


def test_ic_engine_flywheel() -> None:
    p = reference_area("flywheel")["fly.ic_engine_flywheel"]
    inputs = p["inputs"]
    m = doc_flywheel_scenes()["IC engine: flywheel on the crankshaft"].problem.machine
    assert m.linkage is None and m.cycle == math.pi and m.balance == "resisting"
    assert m.omega_m == pytest.approx(inputs["nm_r_min"] * math.pi / 30, rel=1e-15)
    assert m.delta == inputs["delta"]
    (load,) = m.loads
    assert load.table.x == pytest.approx([math.radians(a) for a in inputs["Md_breakpoints_deg"]])
    assert load.table.y == tuple(inputs["Md_breakpoints_Nm"])
    # the constant resistance from the work balance, as the book finds it
    x, y = load.table.x, load.table.y
    work = sum((x[i + 1] - x[i]) * (y[i + 1] + y[i]) / 2 for i in range(len(x) - 1))
    assert work / m.cycle == pytest.approx(p["exact"]["Mr_Nm"], rel=1e-12)


def test_brake_time() -> None:
    p = reference_area("flywheel")["fly.brake_time"]
    inputs = p["inputs"]
    fly = doc_flywheel_scenes()["Run-down under a brake"].problem
    assert fly.machine.omega_m == inputs["omega_rad_s"]
    assert fly.machine.inertia == inputs["Je_kgm2"]
    assert fly.braking == Braking(inputs["Mr_Nm"], inputs["t_required_s"])
    assert fly.machine.inertia * fly.machine.omega_m / fly.braking.moment == p["exact"]["t_s"]


# ------------------------------------------------------------------------------------------
# Jп as a table, and the 720° cycle
# ------------------------------------------------------------------------------------------

COURSE = (ROOT / "figures" / "scenes" / "fly.wittenbauer_course_project.toml").read_text(encoding="utf-8")
J_LIST = "[0.6008325, 0.6018516, 0.6019891"


@pytest.mark.parametrize(
    ("old", "new", "message"),
    [
        (J_LIST, "[0.6008325, nan, 0.6019891", "flywheel.reduced_inertia.inertia_kgm2[1]: must be a finite number, not nan"),
        (J_LIST, "[0.6008325, 0, 0.6019891",
         "flywheel.reduced_inertia.inertia_kgm2[1]: must be > 0, not 0 kg·m²: a reduced moment of inertia"),
        (J_LIST, "[0.6008325, -0.1, 0.6019891",
         "flywheel.reduced_inertia.inertia_kgm2[1]: must be > 0, not -0.1 kg·m²: a reduced moment of inertia"),
        ("phi_deg = [0, 30, 60, 90,", "phi_deg = [0, 30, 90, 60,",
         "flywheel.reduced_inertia.phi_deg[3]: 60° comes after 90°: the angles must increase (Jп(φ) has no steps)"),
        ("phi_deg = [0, 30, 60, 90,", "phi_deg = [0, 30, 30, 90,",
         "flywheel.reduced_inertia.phi_deg[2]: 30° comes after 30°: the angles must increase (Jп(φ) has no steps)"),
        ("phi_deg = [0, 30, 60, 90,", "phi_deg = [10, 30, 60, 90,",
         "flywheel.reduced_inertia.phi_deg[0]: must be 0, not 10°: the table starts at position 1 (φ = 0)"),
        ("270, 300, 330]", "270, 300, 390]",
         "flywheel.reduced_inertia.phi_deg[11]: 390° is outside the cycle: φ runs from 0 at position 1 to Φ = 360°"),
        ("positions = 12", "positions = 12\ncycle_deg = 720",
         ("flywheel.reduced_inertia.phi_deg: ends at 330°, 390° short of the cycle Φ = 720°, more than its "
          "longest step (30°): a table of another period?")),
        ("270, 300, 330]", "270, 300, 330, 360]",
         "flywheel.reduced_inertia.inertia_kgm2: has 12 values, phi_deg has 13: one Jп for each"),
        ('tangents = "book"', 'tangents = "book"\n[flywheel.true_motion]',
         ("flywheel.true_motion: not with [flywheel.reduced_inertia]: the equation of motion needs dJп/dφ, and a "
          "table of Jп has none at its points (give the masses instead)")),
    ],
)
def test_a_bad_table_of_jp_is_refused_in_one_line(tmp_path: Path, old: str, new: str, message: str) -> None:
    path = tmp_path / "course.toml"
    path.write_text(replace(COURSE, old, new), encoding="utf-8")
    code, out, err = run_cli("check", str(path))
    assert (code, out, err) == (2, "", f"course.toml: {message}\n")


def test_a_table_of_jp_closed_at_the_cycle_is_the_same_table() -> None:
    """Written up to Φ with Jп(Φ) = Jп(0), or stopping at 330° (closed back to Jп(0)): one machine."""
    open_ = only_scene(COURSE).problem.machine.inertia_table
    closed = only_scene(replace(replace(COURSE, "270, 300, 330]", "270, 300, 330, 360]"),
                                "0.6025725, 0.6009025, 0.6]", "0.6025725, 0.6009025, 0.6, 0.6008325]")
                        ).problem.machine.inertia_table
    assert open_ == closed
    assert open_.x[-1] == 2 * math.pi and open_.y[-1] == open_.y[0] == 0.6008325 and len(open_.x) == 13
    assert only_problem(replace(replace(COURSE, "270, 300, 330]", "270, 300, 330, 360]"),
                                "0.6025725, 0.6009025, 0.6]", "0.6025725, 0.6009025, 0.6, 0.7]")) == (
        "flywheel.reduced_inertia.inertia_kgm2[12]",
        "0.7 kg·m² at Φ = 360° differs from 0.600832 kg·m² at φ = 0: Jп repeats every cycle")


def test_a_four_stroke_cycle_is_two_turns() -> None:
    m = only_scene((ROOT / "figures" / "scenes" / "fly.four_stroke_engine.toml").read_text(encoding="utf-8")
                   ).problem.machine
    assert m.cycle == 4 * math.pi
    assert m.positions(48)[24] == pytest.approx(2 * math.pi, rel=1e-15)  # position 25: the second turn begins
    assert only_scene(replace(ENGINE, "cycle_deg = 180", "cycle_deg = 720")).problem.machine.cycle == 4 * math.pi
    assert only_problem(replace(ENGINE, "cycle_deg = 180", "cycle_deg = 540")) == (
        "flywheel.cycle_deg", ("must divide one turn a whole number of times (360°, 180°, 120° …) or be two "
                               "turns (720°, a four-stroke engine), not 540°"))


def only_scene(text: str) -> Scene:
    return parse_text(text, "fly.toml")


# ------------------------------------------------------------------------------------------
# ΔT(φ) as a table: [flywheel.energy_increment]
# ------------------------------------------------------------------------------------------

DT_SCENE = (ROOT / "figures" / "scenes" / "fly.energy_table.toml").read_text(encoding="utf-8")
DT_PHI = "phi_deg = [0, 15, 30, 45,"
DT_REFUSED = "needs the moments: [flywheel.energy_increment] gives ΔT, which cannot be split back into its " \
             "driving and resisting moments"


@pytest.mark.parametrize(
    ("old", "new", "message"),
    [
        ("increment_J = [0, -342.7", "increment_J = [0, nan",
         "flywheel.energy_increment.increment_J[1]: must be a finite number, not nan"),
        ("increment_J = [0, -342.7", "increment_J = [5, -342.7",
         "flywheel.energy_increment.increment_J[0]: must be 0, not 5 J: ΔT is counted from position 1 (φ = 0)"),
        (DT_PHI, "phi_deg = [0, 15, 45, 30,",
         "flywheel.energy_increment.phi_deg[3]: 30° comes after 45°: the angles must increase (ΔT(φ) has no steps)"),
        (DT_PHI, "phi_deg = [5, 15, 30, 45,",
         "flywheel.energy_increment.phi_deg[0]: must be 0, not 5°: the table starts at position 1 (φ = 0)"),
        ("330, 345]", "330, 345, 360]",
         "flywheel.energy_increment.increment_J: has 24 values, phi_deg has 25: one ΔT for each"),
        ('tangents = "book"', 'tangents = "book"\nbalance = "driving"',
         "flywheel.balance: not with [flywheel.energy_increment]: the table of ΔT gives no moments, so there is "
         "no constant moment to find and no equation of motion to solve"),
        ('tangents = "book"', 'tangents = "book"\npole_distance_mm = 40',
         "flywheel.pole_distance_mm: not with [flywheel.energy_increment]: ΔT is given, nothing is integrated"),
        ("T_J_per_mm = 109", "T_J_per_mm = 109\nM_Nm_per_mm = 50",
         "scales.M_Nm_per_mm: not with [flywheel.energy_increment]: ΔT is given, no moment diagram is drawn"),
        ('show = ["energy",', 'show = ["moment", "energy",', f"show[0]: moment {DT_REFUSED}"),
        ('find = ["DeltaT@2",', 'find = ["Md",', f"find[0]: Md {DT_REFUSED}"),
        ('find = ["DeltaT@2",', 'find = ["Mp@3",', f"find[0]: Mp {DT_REFUSED}"),
        ("[page]", '[[flywheel.load]]\ntype = "crank"\nphi_deg = [0, 360]\nmoment_Nm = [10, 10]\n\n[page]',
         "flywheel.energy_increment: not with [[flywheel.load]]: the table of ΔT already holds the moments' work; "
         "give one or the other"),
    ],
)
def test_a_bad_table_of_delta_t_is_refused_in_one_line(tmp_path: Path, old: str, new: str, message: str) -> None:
    path = tmp_path / "dt.toml"
    path.write_text(replace(DT_SCENE, old, new), encoding="utf-8")
    code, out, err = run_cli("check", str(path))
    assert (code, out, err) == (2, "", f"dt.toml: {message}\n")


def test_a_table_of_delta_t_is_closed_at_the_cycle_and_holds_no_loads() -> None:
    m = only_scene(DT_SCENE).problem.machine
    t = m.energy_table
    assert m.loads == () and t is not None and len(t.x) == 25
    assert t.x[-1] == 2 * math.pi and t.y[0] == t.y[-1] == 0.0
    assert t.y[14] == 6401.1 and t.x[14] == pytest.approx(math.radians(210), rel=1e-15)
    closed = replace(replace(DT_SCENE, "330, 345]", "330, 345, 360]"), "1255.7, 545.2]", "1255.7, 545.2, 0]")
    assert only_scene(closed).problem.machine.energy_table == t
    assert only_problem(replace(replace(DT_SCENE, "330, 345]", "330, 345, 360]"), "1255.7, 545.2]",
                                "1255.7, 545.2, 7]")) == (
        "flywheel.energy_increment.increment_J[24]",
        "7 J at Φ = 360° differs from 0 J at φ = 0: ΔT repeats every cycle")


def test_a_delta_too_small_for_double_precision_is_refused(tmp_path):
    # fuzz seed 96: δ = 1e-300 made the Wittenbauer tangents' slopes equal (no key path)
    from tests.conftest import assert_refused, edited_scene, run_cli

    scene = "fly.wittenbauer_course_project.toml"
    p = edited_scene(tmp_path, scene, "delta = 0.2", "delta = 1e-300", "f.toml")
    assert_refused(run_cli("check", str(p)), "f.toml", "flywheel.delta", "below 1e-09")
    p = edited_scene(tmp_path, scene, "delta = 0.2", "delta = 1e-9", "f.toml")
    code, _, err = run_cli("check", str(p))
    assert code in (0, 1), err


def test_a_speed_whose_square_vanishes_is_refused(tmp_path):
    # fuzz seed 101: ω_m = 5e-324 rad/s made both Wittenbauer slopes 0 (no key path)
    from tests.conftest import assert_refused, edited_scene, run_cli

    p = edited_scene(tmp_path, "fly.wittenbauer_course_project.toml", "speed_rad_s = 28", "speed_rad_s = 5e-324",
                     "f.toml")
    assert_refused(run_cli("check", str(p)), "f.toml", "flywheel.speed_rad_s", "below 1e-100")
