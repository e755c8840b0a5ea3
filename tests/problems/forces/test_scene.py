"""Reading the [forces] table: its keys, its refusals in one line, what it may show."""
from __future__ import annotations

import re
import tomllib
from functools import partial

import pytest

from graphmech.errors import SceneError
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES, run_cli
from tests.scenes import scene_text, write_scene


def _scene(text: str):
    return parse_scene(tomllib.loads(text), "t.toml")


_write = partial(write_scene, name="s.toml")


def test_friction_circle_larger_than_the_geometry_allows(tmp_path):
    text = scene_text("forces/fourbar_loaded") + '[[forces.journal]]\npoint = "B"\nf_v = 0.2\nradius = 60\n'
    code, out, err = run_cli("check", str(_write(tmp_path, text)))
    assert code == 2 and out == ""
    assert err == ("s.toml: forces.journal[0]: the journal at B (r = 60 mm, friction circle ρ = 12 mm) is "
                   "larger than the geometry allows: it must be smaller than half the 60 mm to the next joint\n")


def test_a_prp_group_and_a_moving_guide_take_guide_friction_on_their_blocks(tmp_path):
    # the tangent mechanism's block 2 (on the bar 1) and rod 3 (on the frame's guide) are sliders; the bar is not
    kin = (SCENES / "kin.tangent_mechanism.toml").read_text(encoding="utf-8")
    text = kin.replace('show = ["mechanism", "velocity", "acceleration"]', 'show = ["mechanism"]').replace(
        "find = [", 'find = ["M_b", ') + '[forces]\n[[forces.force]]\nlink = "3"\npoint = "C"\nforce_N = 100\nangle = 270\n'
    for link in ("2", "3"):
        scene = _scene(text + f'[[forces.guide]]\nlink = "{link}"\nf = 0.1\n')
        assert [sf.link for sf in scene.problem.model.sliding_friction] == [link]
    code, out, err = run_cli("check", str(_write(tmp_path, text + '[[forces.guide]]\nlink = "1"\nf = 0.1\n')))
    assert (code, out) == (2, "")
    assert err == ("s.toml: forces.guide[0].link: link 1 is not a slider (on a frame guide or a guide bar) "
                   "(sliders: 2, 3)\n")
    slotted = scene_text("linkage/slotted_link_pin").replace("find = [", 'find = ["M_b", ')
    scene = _scene(slotted + '[forces]\n[[forces.guide]]\nlink = "4"\nf = 0.15\n[[forces.journal]]\npoint = "C"\n'
                   'f_v = 0.1\nradius = 4\n')
    assert scene.problem.model.sliding_friction[0].link == "4" and scene.problem.model.revolute_friction[0].point == "C"


def test_forces_scene_keys_are_checked(tmp_path):
    text = scene_text("forces/fourbar_loaded").replace("mass_kg = 1", "mass_kg = -1\ncolour = 3")
    code, _, err = run_cli("check", str(_write(tmp_path, text)))
    assert code == 2 and err.startswith("s.toml: forces.mass[0].")
    with pytest.raises(SceneError, match="not a point of link 2"):
        _scene(scene_text("forces/fourbar_loaded").replace('point = "B"', 'point = "D"'))


@pytest.mark.parametrize("old, new, message", [
    # a denormal mass made h = |M_i/F_i| overflow: numpy warnings on stderr, then "h_2 is not finite"
    ("mass_kg = 2", "mass_kg = 5e-324",
     "forces.mass[0].mass_kg: 4.94065645841e-324 kg is absurd for a machine (0, or 1e-09 … 1e+12 in SI units)"),
    ("force_N = 100", "force_N = 1e308",
     "forces.force[0].force_N: 1e+308 N is absurd for a machine (0, or 1e-09 … 1e+12 in SI units)"),
    ("[forces]\n", "[forces]\ngravity_m_s2 = 1e308\n",
     "forces.gravity_m_s2: 1e+308 m/s2 is absurd for a machine (0, or 1e-09 … 1e+12 in SI units)"),
    # both given: the message named mass_kg an "unknown key"
    ("mass_kg = 2", "mass_kg = 2\nweight_N = 20", "forces.mass[0].weight_N: give mass or weight, not both"),
    # a second guide friction on the same slider was silently used as well
    ("[forces]\n", "[forces]\n[[forces.guide]]\nlink = \"3\"\nf = 0.1\n[[forces.guide]]\nlink = \"3\"\nf = 0.2\n",
     "forces.guide[1].link: link 3 already has its guide friction (forces.guide[0])"),
    ("[forces]\n", "[forces]\n[[forces.journal]]\npoint = \"B\"\nf_v = 0.1\nradius = 5\n"
                   "[[forces.journal]]\npoint = \"B\"\nf_v = 0.2\nradius = 5\n",
     "forces.journal[1].point: the journal at B is already given (forces.journal[0])"),
    # a force's direction of 1e300° was taken (cos and sin of it are round-off)
    ("angle = 180", "angle = 1e300", "forces.force[0].angle: 1e+300 is more than 1000 turns: give the angle within one turn"),
    # an absurd stated μF drew polygons 1e-297 mm long without a word
    ("[forces]\n", "[forces]\nmu_F_N_per_mm = 1e300\n",
     "forces.mu_F_N_per_mm: 1e+300: over 1e+15 SI units per mm once converted: no page shows a figure at that scale"),
    ("[forces]\n", "[forces]\nmu_F_N_per_mm = 1e9\n",
     "forces.mu_F_N_per_mm: μF = 1e+09 N/mm draws the largest force 1.14e-07 mm long: choose μF so that it "
     "is 1 … 100000 mm (about 2 N/mm)"),
])
def test_hostile_force_inputs_are_one_line_errors(tmp_path, old, new, message):
    text = scene_text("forces/slider_crank").replace("length = 150\n", "length = 300\n", 1)
    assert old in text
    code, out, err = run_cli("check", str(_write(tmp_path, text.replace(old, new, 1))))
    assert (code, out) == (2, "")
    assert err == f"s.toml: {message}\n"


def test_a_force_scene_refuses_to_show_instant_centres_it_would_not_draw():
    """show = ["forces", "instant_centres"] drew no centres and said nothing; now one line, exit 2."""
    text = (SCENES / "force.sixbar_kinetostatic.toml").read_text(encoding="utf-8")
    text = re.sub(r"^show = \[.*\]$", 'show = ["forces", "instant_centres"]', text, count=1, flags=re.M)
    with pytest.raises(SceneError) as e:
        parse_scene(tomllib.loads(text), "f.toml")
    assert str(e.value).startswith("f.toml: show[1]: the instant centres are drawn on a linkage sheet")


def test_the_six_bar_loads_are_read_in_si():
    from graphmech.mechanisms.forces import PointForce

    fs = load_scene(SCENES / "force.sixbar_kinetostatic.toml").problem
    m = fs.model
    assert [(x.link, x.point, x.mass, x.inertia) for x in m.masses] == [
        ("1", "A", 2.0, 0.0), ("2", "S2", 4.0, 0.03), ("3", "S3", 6.0, 0.09), ("4", "S4", 3.5, 0.036), ("5", "F", 12.0, 0.0)]
    assert m.forces == (PointForce("5", "K", 1000.0, 0.0, True, "P_r"),) and m.gravity == 9.81
    assert not m.has_friction and (fs.mu_F, fs.mu_F_path) == (25.0, "forces.mu_F_N_per_mm")


def test_friction_tables_are_read_into_the_model():
    fs = _scene(scene_text("forces/slider_crank") + ('[[forces.journal]]\npoint = "B"\nf_v = 0.2\nradius = 10\n'
                                    '[[forces.guide]]\nlink = "3"\nf = 0.15\n')).problem
    (j,), (g,) = fs.model.revolute_friction, fs.model.sliding_friction
    assert (j.point, j.f_v, j.radius) == ("B", 0.2, pytest.approx(0.01, rel=1e-15))  # mm → m
    assert j.rho == pytest.approx(0.002, rel=1e-15) and (g.link, g.f) == ("3", 0.15)
    assert fs.mu_F is None  # not stated: the check chooses it
