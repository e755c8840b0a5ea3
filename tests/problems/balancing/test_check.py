"""Balancing scenes: mass-radius polygons against the equations of balance; extreme cases; errors."""
from __future__ import annotations

import cmath
import json
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphmech.problems.balancing.check import analyse_balancing, balancing_figure
from graphmech.errors import SceneError
from graphmech.exact import balancing as ex
from graphmech.mechanisms.rotor import RotorMass
from graphmech.methods import balancing as gm
from graphmech.drawing.primitives import Arrow
from graphmech.scene import load_scene
from tests.conftest import SCENES, check_json, run_cli, values

masses = st.lists(st.tuples(st.floats(0.1, 50.0), st.floats(0.01, 0.5), st.floats(-180.0, 360.0),
                            st.floats(-0.3, 1.3)), min_size=1, max_size=7)


@settings(max_examples=80, deadline=None)
@given(ms=masses, mu=st.sampled_from([0.01, 0.05, 0.2]))
def test_dynamic_polygons_meet_the_equations_of_balance(ms, mu):
    rotor = [RotorMass(str(k + 1), m, r, math.radians(a), z) for k, (m, r, a, z) in enumerate(ms)]
    I, II = gm.dynamic_balance(rotor, 0.0, 1.0, (0.2, 0.3), mu)
    WI, WII = ex.dynamic_correction([ex.Unbalance(u.m, u.r, u.theta, u.z) for u in rotor], 0.0, 1.0)
    size = sum(u.m * u.r for u in rotor) * 3
    for c, w in ((I, WI), (II, WII)):
        drawn = 0j if c.balanced else cmath.rect(c.W, c.theta)
        assert abs(drawn - w) <= 1e-13 * size
    force, moment = ex.residuals([ex.Unbalance(u.m, u.r, u.theta, u.z) for u in rotor],
                                 [(0j if c.balanced else cmath.rect(c.W, c.theta), z) for c, z in ((I, 0.0), (II, 1.0))])
    assert force <= 1e-13 * size and moment <= 1e-13 * size


@settings(max_examples=60, deadline=None)
@given(ms=masses)
def test_static_polygon_closes_on_the_correction(ms):
    rotor = [RotorMass(str(k + 1), m, r, math.radians(a)) for k, (m, r, a, _) in enumerate(ms)]
    c = gm.static_balance(rotor, 0.1, 0.02)
    w = ex.static_correction([ex.Unbalance(u.m, u.r, u.theta) for u in rotor])
    size = sum(u.m * u.r for u in rotor)
    if c.balanced:
        assert abs(w) <= 1e-11 * size
    else:
        assert abs(cmath.rect(c.W, c.theta) - w) <= 1e-13 * size
        assert c.m_b == pytest.approx(c.W / 0.1, rel=1e-15)


def write(tmp_path, text, name="r.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


BALANCED = """
title = "two equal masses opposite"
[balancing]
type = "static"
correction_radius_mm = 100
[[balancing.mass]]
m_kg = 2
r_mm = 50
angle_deg = 30
[[balancing.mass]]
m_kg = 1
r_mm = 100
angle_deg = 210
"""


def test_an_already_balanced_rotor_needs_no_correction_and_gets_no_angle(tmp_path):
    p = write(tmp_path, BALANCED)
    code, out, err = run_cli("check", str(p), "--json")
    assert code == 0 and "NaN" not in out
    doc = json.loads(out)
    q = values(doc)
    assert "theta_b" not in q  # no angle of nothing
    assert q["m_b"]["graphical"] == 0.0 and q["W_b"]["graphical"] == 0.0
    assert q["m_b"]["exact"] <= 1e-15
    assert any("already balanced: no correction mass needed" in w for w in doc["warnings"])
    code, out, err = run_cli("render", str(p), "-o", str(tmp_path / "b.svg"))
    assert code == 0 and "no correction mass needed" in (tmp_path / "b.svg").read_text(encoding="utf-8")


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


def test_a_mass_outside_the_planes_gives_a_reversed_share(tmp_path):
    p = write(tmp_path, """
find = ["W_I", "W_II", "theta_I", "theta_II", "residual_moment"]
[balancing]
type = "dynamic"
planes_mm = [0, 100]
correction_radius_mm = [50, 60]
[[balancing.mass]]
m_kg = 1
r_mm = 100
angle_deg = 0
z_mm = 150
""")
    q = values(check_json(p))
    # W·(z_II − z)/L = −0.05 in plane I (so the correction there points along 0°), 0.15 in plane II
    assert q["W_I"]["graphical"] == pytest.approx(0.05, rel=1e-14)
    assert q["theta_I"]["graphical"] == pytest.approx(0.0, abs=1e-12)
    assert q["W_II"]["graphical"] == pytest.approx(0.15, rel=1e-14)
    assert q["theta_II"]["graphical"] == pytest.approx(180.0, rel=1e-14)
    assert q["residual_moment"]["graphical"] <= 1e-16


def test_the_figure_draws_the_closing_side_bold_at_muW():
    an = analyse_balancing(load_scene(SCENES / "bal.disc_static.toml"))
    sheet = balancing_figure(an, (297.0, 210.0))
    assert [p.name for p in sheet.panels] == ["rotor", "polygon"]
    poly = sheet.panels[1]
    bold = [i for i in poly.items if isinstance(i, Arrow) and i.role == "result"]
    thin = [i for i in poly.items if isinstance(i, Arrow) and i.role == "given"]
    assert len(bold) == 1 and len(thin) == 4
    assert math.dist(bold[0].p0, bold[0].p1) * 0.05 == pytest.approx(0.8062257748298549, rel=1e-13)
    assert bold[0].p1 == (0.0, 0.0)  # closes back on the start


def test_only_the_asked_panels(tmp_path):
    text = (SCENES / "bal.rotor_dynamic.toml").read_text(encoding="utf-8").replace(
        'show = ["rotor", "polygon"]', 'show = ["polygon"]')
    an = analyse_balancing(load_scene(write(tmp_path, text)))
    assert [p.name for p in balancing_figure(an, (297.0, 210.0)).panels] == ["polygonI", "polygonII"]


def test_measured_angle_is_judged_against_the_drawing():
    code, out, err = run_cli("check", str(SCENES / "bal.disc_static.toml"), "--json",
                             "--measured", "theta_b=119.7,m_b=5.3,W_b=0.9")
    v = {m["name"]: m for m in json.loads(out)["measured"]}
    assert v["theta_b"]["ok"] and v["m_b"]["ok"]  # 0.5 mm of a 16 mm side: ±1.8°; 0.5 mm × μW/r_b = 0.17 kg
    assert not v["W_b"]["ok"] and code == 1


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


def test_recorded_draw_calls_of_a_polygon_panel():
    """Each mass-radius product is a shaft and a filled triangle (never a marker); labels are text."""
    from graphmech.render.recording import RecordingBackend
    from graphmech.render.sheet import draw_sheet

    an = analyse_balancing(load_scene(SCENES / "bal.disc_static.toml"))
    sheet = balancing_figure(an, (297.0, 210.0))
    only_polygon = type(sheet)(sheet.title, (sheet.panels[1],), sheet.page, sheet.footer)
    calls = draw_sheet(only_polygon, RecordingBackend())
    heads = [c for c in calls if c[0] == "polyline" and c[4] and len(c[1]) == 3]
    assert len(heads) == 5  # W1 … W4 and the closing W_b
    texts = {c[1] for c in calls if c[0] == "text"}
    assert {"W₁", "W₂", "W₃", "W₄", "Wb"} <= texts
    assert any("μW = 0.05 (kg·m)/mm" in t for t in texts)


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


def test_the_library_refuses_a_zero_scale_or_correction_radius():
    # static_balance(…, mu_W=0) raised ZeroDivisionError from inside the polygon
    from graphmech.mechanisms.rotor import RotorMass
    from graphmech.methods.balancing import static_balance

    m = [RotorMass("1", 1.0, 0.1, 0.0)]
    with pytest.raises(ValueError, match="μW and r_b must be positive"):
        static_balance(m, 0.1, 0.0)
    with pytest.raises(ValueError, match="r_b = 0.0"):
        static_balance(m, 0.0, 1.0)
    assert static_balance(m, 0.1, 0.01).m_b == pytest.approx(1.0, rel=1e-15)
