"""Gears on hostile and extreme input: every mutation of a gear scene reads or is refused in one
line; what reads checks to finite rows and draws, or is refused in one line — never a traceback,
a NaN or a hang; extreme gears (one tooth, 100 000 teeth, a shift that makes the tooth pointed,
α at 5° and 45°) are checked and drawn."""
from __future__ import annotations

import math
import tomllib

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphmech.errors import GraphmechError, SceneError
from graphmech.problems import check
from graphmech.scene import draw, parse_scene
from tests.conftest import SCENES
from tests.mutation import mutate, scene_or_refusal, toml_values

REFERENCE = ("gear.involute_z20_m8", "gear.contact_ratio_19_42", "gear.root_circle_equals_base_circle")
ALL_TOOTH = ["d", "db", "da", "df", "s_pitch", "sa", "sb", "alpha_a", "rho_a", "ra_pointed", "W", "d_pin", "M",
             "z_root_eq_base"]

gear_values = toml_values(["external", "internal", "rack", "tooth", "meshing", "zones", "measurement", "mm", "deg",
                           0, 1, 2, 17, 1000, 100000, -1, 0.5, 1e-300, 1e300], max_leaves=10)


def checked_and_drawn(scene) -> str | None:
    """Check and draw a scene: its rows all finite and the SVG written — or one line refusing it."""
    try:
        an, _, _, _ = check(scene)
        assert all(math.isfinite(r.graphical) and math.isfinite(r.exact) for r in an.rows)
        svg = draw(scene, "g")[0]
        assert "nan" not in svg.lower().replace("nanjing", "")
        return None
    except GraphmechError as err:
        text = err.one_line(scene.source) if isinstance(err, SceneError) else str(err)
        assert "\n" not in text and text
        return text


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.data())
def test_any_mutation_of_a_gear_scene_reads_checks_and_draws_or_is_refused_in_one_line(data):
    base = tomllib.loads((SCENES / f"{data.draw(st.sampled_from(REFERENCE))}.toml").read_text(encoding="utf-8"))
    scene = scene_or_refusal(mutate(data, base, gear_values, most=2))
    if scene is not None:
        g = scene.problem.gears
        assert g.system.m > 0 and all(1 <= x.z <= 100_000 for x in g.gears)
        checked_and_drawn(scene)


def _scene(text: str):
    return parse_scene(tomllib.loads(text), "g.toml")


@pytest.mark.parametrize("z", [1, 2, 3, 8, 16, 17, 18, 41, 42, 1000, 100_000])
@pytest.mark.parametrize("x", [-0.5, 0.0, 0.6])
def test_extreme_tooth_numbers_and_shifts_check_and_draw(z, x):
    text = f'find = {ALL_TOOTH!r}\nshow = ["tooth", "measurement", "root_base"]\n[gear]\nm_mm = 5\nz = {z}\nx = {x}\n'
    refused = checked_and_drawn(_scene(text.replace("'", '"')))
    if refused is not None:  # a tooth of one or two teeth, a shift that leaves no tooth: said, at a key
        assert z <= 3 or "pointed" in refused or "inside" in refused, refused


@pytest.mark.parametrize("alpha", [5, 14.5, 20, 25, 45])
def test_pressure_angles_from_5_to_45_degrees(alpha):
    refused = checked_and_drawn(_scene(f'find = ["sa", "rho_a", "W", "M"]\n[gear]\nm_mm = 4\nz = 30\n'
                                       f'alpha_deg = {alpha}\n'))
    # beyond about 32° (h*a + c* = 1.25) the basic rack's tooth is pointed before its tip line: said
    assert (refused is None) == (alpha < 32), refused
    assert refused is None or "pointed before its tip line" in refused


@pytest.mark.parametrize("pair", [
    'z = [1, 2]\nmeshing = "external"', 'z = [3, 4]\nmeshing = "internal"', 'z = [20, 21]\nmeshing = "internal"',
    'z = [20, 100000]\nmeshing = "external"', 'z = [100000]\nmeshing = "rack"', 'z = [20]\nmeshing = "rack"\nx = [3]',
    'z = [20, 30]\nmeshing = "external"\ncentre_distance_mm = 1e6', 'z = [20, 30]\nmeshing = "external"\nx = [-3, -3]',
])
def test_extreme_pairs_check_and_draw_or_say_why_not(pair):
    refused = checked_and_drawn(_scene(f'find = ["B1B2", "eps_alpha", "alpha_w"]\n[gear]\nm_mm = 5\n{pair}\n'))
    assert refused is None or any(why in refused for why in ("overlap", "wrong order", "inside", "no line of action",
                                                               "do not come into contact", "without backlash")), refused


@pytest.mark.parametrize("gear", ["z = 40\nx = 2.5", "z = 2\nx = 3", "z = 60\nx = -2.5\ninternal = true"])
def test_pins_in_a_closed_space_are_refused_at_the_pin_diameter(gear):
    refused = checked_and_drawn(_scene(f'find = ["d_pin", "M"]\n[gear]\nm_mm = 5\n{gear}\n'))
    assert refused is not None and "gear.pin_diameter" in refused and "space on the reference circle is closed" in refused


def test_specific_sliding_with_the_contact_beyond_N_keeps_its_sign():
    """z = [12, 60]: gear 2's tip reaches past N₁ (interference); the radius of curvature at B₂ on
    gear 1 is negative there, and the specific sliding with it — the construction agrees."""
    an, _, _, _ = check(_scene('find = ["eta_root1", "eta_tip2", "eta_tip1", "eta_root2"]\n[gear]\nm_mm = 5\n'
                               'z = [12, 60]\nmeshing = "external"\n'))
    r = {x.name: x for x in an.rows}
    assert any("B2 lies beyond N1" in w for w in an.warnings)
    assert an.mesh is not None and an.mesh.rho["N1B2"] < 0.0
    assert r["eta_root1"].graphical == pytest.approx(5.42946839, rel=1e-8) and r["eta_root1"].rel_error < 1e-9
    assert r["eta_tip2"].graphical == pytest.approx(1.22576073, rel=1e-8) and r["eta_tip2"].rel_error < 1e-9


@pytest.mark.parametrize("gear, positions, most", [("z = 15", 400, 48), ("z = 100000", None, 7)])
def test_a_generation_too_large_to_cut_is_refused_naming_the_positions_that_fit(gear, positions, most):
    """400 positions per pitch (an error estimate of 800), or z = 10⁵ at the default 12, would run
    for minutes: refused in one line with the most positions that fit."""
    n = "" if positions is None else f"positions = {positions}\n"
    with pytest.raises(SceneError) as e:
        check(_scene(f'show = ["generation"]\n[gear]\nm_mm = 4\n{gear}\n[gear.generation]\ncutter_speed_m_s = 0.002\n{n}'))
    line = e.value.one_line("g.toml")
    assert line.startswith("g.toml: gear.generation" + (".positions" if positions else "") + ": ")
    assert f"at most positions = {most} fit" in line, line


@pytest.mark.parametrize("word", ["least", "least_exact"])
def test_the_rack_s_least_shift_is_refused_for_one_ring_as_for_a_ring_in_a_pair(word):
    with pytest.raises(SceneError) as e:
        _scene(f'find = ["x"]\n[gear]\nm_mm = 4\nz = 15\ninternal = true\nx = "{word}"\n')
    assert e.value.one_line("g.toml") == ("g.toml: gear.x: a ring is cut by a pinion cutter, not a rack: the rack's "
                                          "least shift does not apply to it; give x as a number")
