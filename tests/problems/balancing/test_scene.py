"""Reading the [balancing] table: the rotor in SI; each bad scene refused in one line naming its key."""
from __future__ import annotations

import math
from functools import partial

import pytest

from graphmech.errors import SceneError
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES, run_cli
from tests.scenes import write_scene

write = partial(write_scene, name="r.toml")


def test_coinciding_correction_planes_are_refused_in_one_line(tmp_path):
    p = write(tmp_path, """
[balancing]
type = "dynamic"
planes_mm = [120, 120]
correction_radius_mm = 80
[[balancing.mass]]
m_kg = 1
r_mm = 50
angle_deg = 0
z_mm = 40
""")
    code, out, err = run_cli("check", str(p))
    assert code == 2 and err == ("r.toml: balancing.planes_mm: the correction planes coincide (z = 0.12 m): "
                                 "dynamic balancing needs two distinct planes\n")


@pytest.mark.parametrize("body, where, words", [
    ('[balancing]\ntype = "static"\ncorrection_radius_mm = 10\n', "balancing.mass", "nothing to balance"),
    ('[balancing]\ntype = "dynamic"\ncorrection_radius_mm = 10\n[[balancing.mass]]\nm_kg = 1\nr_mm = 1\n'
     'angle_deg = 0\nz_mm = 0\n', "balancing.planes", "missing"),
    ('[balancing]\ntype = "static"\ncorrection_radius_mm = 10\n[[balancing.mass]]\nm_kg = 1\nr_mm = 1\n'
     'angle_deg = 0\nz_mm = 3\n', "balancing.mass[0].z_mm", "one plane"),
    ('[balancing]\ntype = "static"\ncorrection_radius_mm = 10\n[[balancing.mass]]\nm_kg = -1\nr_mm = 1\n'
     'angle_deg = 0\n', "balancing.mass[0].m_kg", "> 0"),
    ('[balancing]\ntype = "static"\ncorrection_radius_mm = 10\n[[balancing.mass]]\nm = 1\nr_mm = 1\nangle_deg = 0\n',
     "balancing.mass[0].m", "unit not stated"),
    ('[scales]\nW_kgm = 3\n[balancing]\ntype = "static"\ncorrection_radius_mm = 10\n[[balancing.mass]]\nm_kg = 1\n'
     'r_mm = 1\nangle_deg = 0\n', "scales.W_kgm", "not a unit of a mass-radius product"),
])
def test_bad_balancing_scenes(body, where, words, tmp_path):
    p = write(tmp_path, body)
    with pytest.raises(SceneError) as e:
        load_scene(p)
    assert e.value.problems[0][0] == where, e.value.problems
    assert words in e.value.problems[0][1], e.value.problems
    code, out, err = run_cli("check", str(p))
    assert code == 2 and err.count("\n") == 1


def test_a_stated_scale_that_underflows_in_si_is_refused_in_one_line(tmp_path):
    # 5e-324 kg·cm/mm is a positive number in the file but 0 kg·m/mm once converted: it used to
    # divide by zero (exit 3, internal error)
    p = write(tmp_path, """
[scales]
W_kgcm_per_mm = 5e-324
[balancing]
type = "static"
correction_radius_cm = 15
[[balancing.mass]]
m_kg = 5
r_cm = 10
angle_deg = 90
""")
    code, out, err = run_cli("check", str(p))
    assert (code, out) == (2, "")
    assert err == ("r.toml: scales.W_kgcm_per_mm: 4.94066e-324: under 1e-15 SI units per mm once converted: "
                   "no page shows a figure at that scale\n")


def test_a_dynamic_rotor_is_read_in_si():
    """bal.rotor_dynamic: masses in kg at cm and degrees → m and rad; one correction radius for both planes."""
    p = load_scene(SCENES / "bal.rotor_dynamic.toml").problem
    assert (p.type, p.planes, p.r_b) == ("dynamic", (0.0, 0.9), (0.5, 0.5))
    assert [(u.name, u.m, u.r, u.z) for u in p.masses] == [("1", 10.0, 0.4, 0.0), ("2", 15.0, 0.3, 0.3),
                                                            ("3", 20.0, 0.2, 0.6), ("4", 10.0, 0.3, 0.9)]
    assert [math.degrees(u.theta) for u in p.masses] == pytest.approx([155.0, 270.0, 50.0, 295.0], rel=1e-14)


def test_a_static_disc_has_one_plane_and_one_radius():
    p = load_scene(SCENES / "bal.disc_static.toml").problem
    assert (p.type, p.planes, p.r_b) == ("static", None, (0.15,))
    assert all(u.z == 0.0 for u in p.masses) and len(p.masses) == 4


def test_two_correction_radii_are_one_per_plane():
    data = {"balancing": {"type": "dynamic", "planes_mm": [0, 100], "correction_radius_mm": [50, 60],
                          "mass": [{"m_kg": 1, "r_mm": 100, "angle_deg": 0, "z_mm": 150}]}}
    p = parse_scene(data, "r.toml").problem
    assert p.r_b == pytest.approx((0.05, 0.06), rel=1e-15) and p.planes == pytest.approx((0.0, 0.1), rel=1e-15)
    assert p.masses[0].z == pytest.approx(0.15, rel=1e-15)


@pytest.mark.parametrize(("lines", "words"), [
    ('type = "static"\nsplit_angles_deg = [30, 210]',
     "balancing.split_angles_deg: the two directions are parallel (30° and 210°): no split"),
    ('type = "static"\nsplit_angles_deg = [45, 45]',
     "balancing.split_angles_deg: the two directions are parallel (45° and 45°): no split"),
    ('type = "dynamic"\nplanes_mm = [0, 100]\nsplit_angles_deg = [0, 90]',
     'balancing.split_angles_deg: a split into two directions is for a static balance (type = "static")'),
    ('type = "static"\nspeed_rpm = -5', "balancing.speed_rpm"),
])
def test_a_bad_split_or_speed_is_refused_in_one_line(tmp_path, lines, words):
    p = write(tmp_path, f"""
[balancing]
{lines}
correction_radius_mm = 100
[[balancing.mass]]
m_kg = 1
r_mm = 100
angle_deg = 0
z_mm = 10
""".replace("z_mm = 10\n", "z_mm = 10\n" if "dynamic" in lines else ""))
    code, out, err = run_cli("check", str(p))
    assert code == 2 and out == "" and err.count("\n") == 1 and err.startswith("r.toml: ")
    assert words in err, err


def test_the_split_and_speed_are_read_in_si():
    s = load_scene(SCENES / "bal.split_two_directions.toml")
    assert s.problem.split == pytest.approx((math.pi, 1.5 * math.pi), rel=1e-15)
    assert s.problem.omega is None
    s = load_scene(SCENES / "bal.rotor_centrifugal.toml")
    assert s.problem.omega == pytest.approx(5000 * math.pi / 30, rel=1e-15)
