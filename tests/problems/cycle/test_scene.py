"""Reading the full cycle and the characteristics (graphmech/problems/cycle/scene.py): [cycle] and
[characteristics], the positions they make, and every refusal one line naming the key."""
from __future__ import annotations

import math
import re
import tomllib
from pathlib import Path

import pytest

from graphmech.errors import SceneError
from graphmech.problems.cycle.scene import CharacteristicsSpec, CycleScene, CycleSpec
from graphmech.scene import parse_scene
from tests.conftest import assert_refused, fourbar_scene, run_cli
from tests.scenes import scene_text, write_scene

#: The centred slider-crank (AB = 50, BC = 200 mm) over 12 positions from its extreme.
SLIDER = scene_text("cycle/slider_crank")
#: The parallelogram AB = CD = 30, BC = AD = 60 mm, asked for its characteristics only.
PARALLELOGRAM = scene_text("cycle/parallelogram")


def with_line(text, key, value):
    """``text`` with the top-level line ``key = …`` set to ``key = value``."""
    return re.sub(rf"(?m)^{key} = .*$", lambda m: f"{key} = {value}", text)


#: The same, asked for no values and showing the cycle only.
CYCLE_ONLY = with_line(with_line(SLIDER, "show", '["cycle"]'), "find", "[]")


def written(tmp_path, text, name="s.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def read(text):
    return parse_scene(tomllib.loads(text), "s.toml")


def problems_of(text):
    with pytest.raises(SceneError) as info:
        read(text)
    return info.value.problems


def degrees(positions):
    return [round(math.degrees(v) % 360, 9) for v in positions.values]


# ------------------------------------------------------------------------------------------
# What a [cycle] and a [characteristics] table make
# ------------------------------------------------------------------------------------------


def test_a_cycle_from_the_extreme_numbers_n_positions_from_the_dead_centre():
    scene = read(SLIDER)
    assert scene.kind == "cycle"
    assert scene.problem == CycleScene(CycleSpec(12, "extreme", ("C",), ("C", "2"), {}, None),
                                       CharacteristicsSpec(None, False), 0.0)
    assert scene.positions.labels == tuple(str(k) for k in range(1, 13))
    assert degrees(scene.positions) == [30.0 * k for k in range(12)]  # centred: the dead centre at φ = 0


def test_an_offset_slider_cranks_extreme_is_where_crank_and_rod_are_in_line():
    """Guide 20 mm above A: the outer dead centre has AC = AB + BC = 250 mm, so φ = asin(e/(a + b))."""
    scene = read(SLIDER.replace("through = [0, 0]", "through = [0, 20]"))
    assert scene.problem.start_angle == pytest.approx(math.asin(20 / 250), rel=1e-12)
    assert scene.positions.values[6] == pytest.approx(math.asin(20 / 250) + math.pi, rel=1e-12)


def test_a_cycle_from_the_driver_starts_at_its_angle_and_turns_its_way():
    from_driver = SLIDER.replace('start = "extreme"', 'start = "driver"').replace("angle = 0\n", "angle = 45\n")
    assert degrees(read(from_driver).positions)[:4] == [45.0, 75.0, 105.0, 135.0]
    clockwise = from_driver.replace("omega = 10", 'omega = 10\ndirection = "cw"')
    assert degrees(read(clockwise).positions)[:4] == [45.0, 15.0, 345.0, 315.0]


def test_a_bare_cycle_table_is_twelve_positions_from_the_driver():
    bare = CYCLE_ONLY.replace("positions = 12\n", "").replace('start = "extreme"\n', "")
    bare = bare.replace('diagrams = ["C", "2"]\n', "").replace('paths = ["C"]\n', "")
    assert read(bare).problem.cycle == CycleSpec()
    assert CycleSpec() == CycleSpec(12, "driver", (), (), {}, None)


def test_characteristics_keep_the_working_time_and_the_ranges():
    scene = read(PARALLELOGRAM + "[characteristics]\nt_work_s = 7\nranges = true\n")
    assert scene.kind == "cycle" and scene.problem.cycle is None
    assert scene.problem.characteristics == CharacteristicsSpec(7.0, True)
    assert scene.positions.labels == ("60",) and scene.problem.start_angle == pytest.approx(math.radians(60))


def test_stated_pole_distances_are_kept_in_mm():
    scene = read(SLIDER.replace('paths = ["C"]', 'paths = ["C"]\npole_distance_mm = [30, 25]'))
    assert scene.problem.cycle.pole_distance_mm == (30.0, 25.0)


# ------------------------------------------------------------------------------------------
# Refusals
# ------------------------------------------------------------------------------------------


@pytest.mark.parametrize("edit, problem", [
    (("positions = 12", "positions = 12.5"), ("cycle.positions", "must be a whole number of positions (4 … 3600), not '12.5'")),
    (("positions = 12", "positions = 3601"), ("cycle.positions", "must lie between 4 and 3600, not 3601")),
    (('paths = ["C"]', 'paths = ["C", "C"]'), ("cycle.paths[1]", "'C' is listed twice")),
    (('diagrams = ["C", "2"]', 'diagrams = ["C", 3]'),
     ("cycle.diagrams[1]", "'3' has no s–φ diagram: name a slider, a rotating link or a moving point "
                           "(C (slider), 1 (link), B (point), 2 (link))")),
    (('paths = ["C"]', 'paths = ["C"]\nscales = { phi_deg_per_mm = 2, v_m_s_per_mm = 0.02 }\npole_distance_mm = 30'),
     ("cycle.pole_distance_mm", "give the pole distances or the diagrams' μv, not both: they fix each other "
                                "(μv = μs·ω₁/(μφ·H₁), μa = μv·ω₁/(μφ·H₂))")),
])
def test_each_cycle_problem_names_its_key(edit, problem):
    assert problems_of(SLIDER.replace(*edit)) == [problem]


def test_what_needs_a_cycle_table_says_so():
    problems = problems_of(SLIDER.replace("[cycle]", "[cyc]"))
    assert problems[0] == ("show[0]", '"cycle" needs a [cycle] table (positions = 12, start = "extreme" …)')
    assert ("cyc", "unknown key; did you mean cycle?") in problems


def test_the_grashof_ranges_are_a_hinged_four_bars():
    assert problems_of(SLIDER.replace("[cycle]", "[characteristics]\nranges = true\n[cycle]")) == [
        ("characteristics.ranges", "the Grashof ranges are those of a hinged four-bar")]


def test_a_double_crank_has_no_extreme_to_start_from():
    """AD = 20 the shortest link, 20 + 50 < 30 + 45: both AB and CD turn fully."""
    double = (PARALLELOGRAM.replace("D_mm = [60, 0]", "D_mm = [20, 0]").replace("[60, 30]", "[50, 45]")
              + '[cycle]\nstart = "extreme"\n')
    assert problems_of(double) == [("cycle.start", "no extreme position to start from: the output turns fully "
                                                   'too (a double crank); start = "driver"')]


# ------------------------------------------------------------------------------------------
# Through the command line: one line, nothing written
# ------------------------------------------------------------------------------------------


@pytest.mark.parametrize("edit, key", [
    (('positions = 12', 'positions = 2'), "cycle.positions"),
    (('start = "extreme"', 'start = "dead"'), "cycle.start"),
    (('diagrams = ["C", "2"]', 'diagrams = ["A"]'), "cycle.diagrams[0]"),
    (('paths = ["C"]', 'paths = ["Q"]'), "cycle.paths[0]"),
    (('paths = ["C"]', 'paths = ["C", "A"]'), "cycle.paths[1]"),  # the frame pivot's "path": was drawn as a dot
    (('angle = 0', 'angle = [0, 30]'), "driver.angle"),
    (('omega = 10', 'omega = 10\nepsilon_rad_s2 = 2'), "driver.epsilon"),
    (('omega = 10', 'omega = 0'), "driver.omega"),  # v, a all 0 and μv = 0 before
    (('paths = ["C"]', 'paths = ["C"]\npole_distance_mm = 1e308'), "cycle.pole_distance_mm"),  # exit 3 before
    (('paths = ["C"]', 'paths = ["C"]\npole_distance_mm = [20, 5000]'), "cycle.pole_distance_mm[1]"),
    (('paths = ["C"]', 'paths = ["C"]\nscales = { phi_deg_per_mm = 1e-300 }'), "cycle.scales.phi_deg_per_mm"),
    (('paths = ["C"]', 'paths = ["C"]\nscales = { s_m_per_mm = 0.005, v_m_s_per_mm = 1e-300 }'), "cycle.scales.v_m_s_per_mm"),
])
def test_bad_cycle_input_is_one_line_naming_the_key(tmp_path, edit, key):
    p = written(tmp_path, SLIDER.replace(*edit))
    code, out, err = run_cli("render", str(p), "-o", str(tmp_path / "x.svg"))
    assert code == 2 and err.count("\n") == 1 and f": {key}:" in err, err
    assert not (tmp_path / "x.svg").exists()


def test_mechanism_is_refused_beside_a_cycle(tmp_path):
    code, _, err = run_cli("check", str(written(tmp_path, with_line(SLIDER, "show", '["mechanism", "cycle"]'))))
    assert code == 2 and "show[0]" in err and '"cycle"' in err


def test_unknown_find_names_are_refused(tmp_path):
    code, _, err = run_cli("check", str(written(tmp_path, with_line(SLIDER, "find", '["v_C_diagram@3"]'))))
    assert code == 2 and "find[0]" in err and "interval middle" in err


def test_a_slider_driven_linkage_has_no_full_turn(tmp_path):
    # a slider has a stroke, not a turn: its cycle needs [cycle] between (tests/problems/cycle/test_swing.py)
    p = tmp_path / "sl.toml"
    p.write_text(scene_text("cycle/slider_driven"), encoding="utf-8")
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "x.svg"))
    assert code == 2 and err.count("\n") == 1 and ": driver.type:" in err and "between_mm" in err, err


@pytest.mark.parametrize("find, diagrams, reason", [
    ('["s_C@4"]', '["2"]', "find[0]: s_C is read off the diagram of C: add C to [cycle] diagrams"),
    ('["v_C_diagram@1.5"]', '["2"]', "find[0]: v_C_diagram is read off the diagram of C: add C to [cycle] diagrams"),
    ('["omega_2_diagram@1.5"]', '["C"]', "find[0]: omega_2_diagram is read off the diagram of 2: add 2 to [cycle] diagrams"),
])
def test_a_diagram_value_of_what_has_no_diagram_says_how_to_get_one(tmp_path, find, diagrams, reason):
    """Before: "unknown quantity 's_C'; did you mean v_C, a_C?" though s_C@4 is a documented name."""
    p = written(tmp_path, with_line(CYCLE_ONLY, "find", find).replace('diagrams = ["C", "2"]', f"diagrams = {diagrams}"))
    code, _, err = run_cli("check", str(p))
    assert code == 2 and err == f"s.toml: {reason}\n", err


@pytest.mark.parametrize("scale, word", [("1e-300", "under 1e-15"), ("1e300", "over 1e+15"), ("5e-324", "under 1e-15")])
def test_a_stated_scale_out_of_every_page_is_refused_where_it_is_read(tmp_path, scale, word):
    p = written(tmp_path, CYCLE_ONLY.replace("[units]", f"[scales]\nl_m_per_mm = {scale}\n\n[units]"))
    for argv in (("render", str(p), "-o", str(tmp_path / "x.svg")), ("check", str(p), "--json")):
        assert_refused(run_cli(*argv), "s.toml", f"scales.l_m_per_mm: {float(scale):g}: {word} SI units per mm")


def test_an_extreme_start_that_cannot_be_assembled_is_refused_at_cycle_start(tmp_path):
    """A four-bar exactly at Grashof's equality (AD + BC = AB + CD = 70 mm): the extreme position's
    pin cannot be assembled (an AssemblyError, an ArithmeticError); the reader says so at its key
    instead of letting the construction's step name the problem."""
    text = fourbar_scene(a=30, b=50, c=40, d=20, show='["cycle"]', find="[]") + (
        '[cycle]\npositions = 12\nstart = "extreme"\n')
    assert_refused(run_cli("check", str(write_scene(tmp_path, text))), "scene.toml",
                   "cycle.start: no extreme position to start from", "cannot be assembled")


# ---------------------------------------------------------------------------- a driver that swings

ROCKER = (Path(__file__).resolve().parents[3] / "figures" / "scenes" / "linkage.rocker_swing.toml").read_text(
    encoding="utf-8")
STROKE = (Path(__file__).resolve().parents[3] / "figures" / "scenes" / "linkage.slider_stroke.toml").read_text(
    encoding="utf-8")


def test_a_swing_numbers_its_positions_out_and_back():
    sc = read(ROCKER)
    q = sc.positions.values
    assert sc.positions.labels == tuple(str(k) for k in range(1, 13))
    assert q[0] == pytest.approx(-math.acos(-0.1375), abs=1e-12) and q[6] == pytest.approx(math.acos(-0.1375), abs=1e-12)
    assert all(q[k] == q[12 - k] for k in range(1, 6))
    assert sc.problem.swing == (q[0], q[6]) and sc.problem.stated == 0.0 and sc.problem.cycle.between == "limits"
    stroke = read(STROKE)
    assert stroke.positions.values == pytest.approx((0.02, 0.045, 0.07, 0.095, 0.12, 0.095, 0.07, 0.045), abs=1e-15)


@pytest.mark.parametrize("text,where,words", [
    (ROCKER.replace("positions = 12", "positions = 11"), "cycle.positions", ("must be even",)),
    (ROCKER.replace('paths = ["E"]', 'paths = ["E"]\ndiagrams = ["C"]'), "cycle.diagrams", ("reverses", "v jumps")),
    (ROCKER.replace('paths = ["E"]', 'paths = ["E"]\nstart = "extreme"'), "cycle.start", ("first end",)),
    (ROCKER.replace('between = "limits"', 'between = "ends"'), "cycle.between", ('"limits"',)),
    (ROCKER.replace('between = "limits"', "between_deg = [10, 10]"), "cycle.between_deg", ("one position",)),
    (ROCKER.replace('between = "limits"', "between_deg = [10]"), "cycle.between_deg", ("[from, to]",)),
    # ends a whole turn apart are one place: the crank's swing was 0° (every position at 10°), checked silently
    (ROCKER.replace('between = "limits"', "between_deg = [10, 370]"), "cycle.between_deg", ("one place on the turn",)),
    (ROCKER.replace('between = "limits"', "between_deg = [0, 1e-300]"), "cycle.between_deg", ("one place on the turn",)),
    (ROCKER.replace("omega = 5", "omega = 5\nepsilon_rad_s2 = 2"), "driver.epsilon", ("uniformly",)),
    (ROCKER.replace("angle = 0 ", "angle = 180 "), "cycle.between", ("cannot be assembled",)),
    (ROCKER.replace("length = 80", "length = 20").replace("lengths = [40, 60]", "lengths = [60, 50]"),
     "cycle.between", ("turns fully",)),
    (STROKE.replace("between = [20, 120]", "between = [120, 20]"), "cycle.between", ("against the slider's velocity",)),
    (STROKE.replace("velocity = 0.5 ", "velocity = 0.5\nacceleration = 1 "), "driver.acceleration", ("uniformly",)),
    (STROKE.replace('paths = ["E"]', 'paths = ["E"]\n[characteristics]'), "driver.type", ("characteristics",)),
])
def test_what_a_swing_refuses_is_one_line_naming_the_key(tmp_path, text, where, words):
    err = assert_refused(run_cli("check", str(written(tmp_path, text))), "s.toml", *words)
    assert f": {where}:" in err, err
