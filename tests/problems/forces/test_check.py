"""Kinetostatics: extreme cases, friction, only what the scene asks, bad input, figures."""
from __future__ import annotations

import dataclasses
import math
import re
import subprocess
import sys
import tomllib

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import graphmech.methods.kinetostatics as K
from graphmech.errors import SceneError
from graphmech.problems.forces.check import analyse_forces
from graphmech.mechanisms.forces import ForceModel, LinkMass
from graphmech.scene import load_scene, parse_scene
from tests.conftest import ROOT, SCENES, check_json, fourbar_scene, run_cli

FOURBAR_LOADS = """
[forces]
[[forces.mass]]
link = "2"
point = "B"
mass_kg = 1
[[forces.moment]]
link = "3"
moment_Nm = -10
"""

SLIDER_CRANK = """
find = ["R_12", "R_43", "M_b"]
show = ["mechanism"]
[units]
length = "mm"
angle = "deg"
[frame]
A = [0, 0]
[driver]
type = "crank"
link = "1"
pivot = "A"
tip = "B"
length = 100
angle = 90
omega_rad_s = 10
[[dyad]]
type = "RRP"
joints = ["B", "C"]
links = ["2", "3"]
length = {length}
guide = {{ through = [0, 0], angle = 0 }}
branch = "forward"
[forces]
[[forces.mass]]
link = "3"
point = "C"
mass_kg = 2
[[forces.force]]
link = "3"
point = "C"
force_N = 100
angle = 180
{extra}
"""


def _scene(text: str):
    return parse_scene(tomllib.loads(text), "t.toml")


def _fourbar(c: float, find: str = '["R_23", "M_b"]', show: str = '["mechanism"]', extra: str = "") -> str:
    return fourbar_scene(a=60, b=100, c=c, d=120, angle="180", find=find, show=show) + FOURBAR_LOADS + extra


def _write(tmp_path, text: str, name: str = "s.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


# ----------------------------------------------------------------------------- extreme cases


def test_transmission_angle_near_zero_reactions_grow_without_bound_and_warn():
    """At φ1 = 180° |BD| = 180 mm; l2 + l3 just above it puts C nearly in line with B and D."""
    r = {}
    for c in (80.5, 80.01, 80.0001):
        fa = analyse_forces(_scene(_fourbar(c)))
        q = {row.name: row for row in fa.rows}
        r[c] = q["R_23"].graphical
        assert q["R_23"].rel_error < 1e-9  # the matrix method agrees even here
        near = [w for w in fa.warnings if "grow without bound" in w]
        assert bool(near) == (c < 80.1), fa.warnings
        assert q["M_b"].graphical == pytest.approx(10.0 / 3.0, rel=1e-12)  # M_b stays bounded
    # R ~ 1/sin γ: γ shrinks 10× from 1.22° to 0.122°, so does R grow 10×
    assert r[80.0001] / r[80.01] == pytest.approx(10.0, rel=1e-3)
    assert r[80.01] > 7 * r[80.5]
    # closer still, rounding itself is amplified past the agreement bar: the rows say so
    fa = analyse_forces(_scene(_fourbar(80.00001)))
    row = {x.name: x for x in fa.rows}["R_23"]
    assert row.ill_conditioned and row.rel_error > 1e-10
    assert not any(x.ill_conditioned for x in analyse_forces(_scene(_fourbar(80.01))).rows)


def test_near_collinear_closing_lines_of_a_slider_group_are_flagged():
    bad = analyse_forces(_scene(SLIDER_CRANK.format(length=100.2, extra="")))
    good = analyse_forces(_scene(SLIDER_CRANK.format(length=150, extra="")))
    assert any("near-collinear forces" in w and "group 2–3" in w for w in bad.warnings)
    assert not any("near-collinear" in w for w in good.warnings)
    assert values_of(bad)["R_12"] > 40 * values_of(good)["R_12"]


def values_of(fa):
    return {r.name: r.graphical for r in fa.rows}


def test_exactly_parallel_closing_lines_are_one_line_errors():
    kin = K.PolygonKinematics({}, {}, {}, {}, {}, 1.0, np.array([True]))
    with pytest.raises(K.DegenerateConstruction, match="grow without bound"):
        K._guard_parallel(np.array([0.0]), kin.valid, "group 2–3: parallel")


def test_f_zero_is_the_frictionless_solution_without_iterating(monkeypatch):
    rounds = []
    original = K._solve_round
    monkeypatch.setattr(K, "_solve_round", lambda *a, **k: rounds.append(1) or original(*a, **k))
    zero = """
[[forces.journal]]
point = "B"
f_v = 0
radius = 10
[[forces.guide]]
link = "3"
f = 0
"""
    fa0 = analyse_forces(_scene(SLIDER_CRANK.format(length=150, extra=zero)))
    assert len(rounds) == 1 and fa0.solution.iterations == 0
    rounds.clear()
    fa = analyse_forces(_scene(SLIDER_CRANK.format(length=150, extra="")))
    assert len(rounds) == 1
    assert values_of(fa0) == values_of(fa)
    rounds.clear()
    friction = zero.replace("f_v = 0", "f_v = 0.2").replace("f = 0", "f = 0.15")
    ff = analyse_forces(_scene(SLIDER_CRANK.format(length=150, extra=friction)))
    # the frictionless start, the rounds, then one more whose change estimates the error
    assert len(rounds) > 3 and ff.solution.iterations == len(rounds) - 2
    for row in ff.rows:
        assert row.rel_error < 1e-10, row  # successive approximation = scipy's root on the matrix
    assert values_of(ff)["M_b"] != pytest.approx(values_of(fa)["M_b"], rel=1e-3)


def test_friction_that_does_not_converge_says_so_in_one_line(tmp_path):
    text = SLIDER_CRANK.format(length=150, extra="""
[[forces.journal]]
point = "B"
f_v = 0.2
radius = 10
[[forces.guide]]
link = "3"
f = 0.3
""").replace("[forces]\n", "[forces]\nmax_iterations = 2\n", 1)
    code, out, err = run_cli("check", str(_write(tmp_path, text)))
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and err.startswith("s.toml: forces: friction by successive approximation: "
                                                    "does not converge in 2 rounds")


def test_friction_circle_larger_than_the_geometry_allows(tmp_path):
    text = _fourbar(90, extra='[[forces.journal]]\npoint = "B"\nf_v = 0.2\nradius = 60\n')
    code, out, err = run_cli("check", str(_write(tmp_path, text)))
    assert code == 2 and out == ""
    assert err == ("s.toml: forces.journal[0]: the journal at B (r = 60 mm, friction circle ρ = 12 mm) is "
                   "larger than the geometry allows: it must be smaller than half the 60 mm to the next joint\n")


# ----------------------------------------------------------------------------- only what is asked


def test_only_the_balancing_moment_builds_no_polygons_and_no_lever(monkeypatch):
    built = []
    original = K.GroupPolygon
    monkeypatch.setattr(K, "GroupPolygon", lambda *a, **k: built.append(a[0]) or original(*a, **k))
    import graphmech.problems.forces.check as fc

    monkeypatch.setattr(fc, "zhukovsky_lever", lambda *a, **k: pytest.fail("lever built"))
    fa = analyse_forces(_scene(_fourbar(90, find='["M_b"]')))
    assert [r.name for r in fa.rows] == ["M_b"] and built == [] and fa.lever is None
    fa = analyse_forces(_scene(_fourbar(90, find='["M_b"]', show='["force_polygons"]')))
    assert built == ["group 2–3", "driver 1"]


def test_a_frictionless_scene_does_not_iterate(monkeypatch):
    rounds = []
    original = K._solve_round
    monkeypatch.setattr(K, "_solve_round", lambda *a, **k: rounds.append(1) or original(*a, **k))
    check_json(SCENES / "force.sixbar_kinetostatic.toml")
    assert len(rounds) == 1


def test_force_polygons_close():
    fa = analyse_forces(load_scene(SCENES / "force.sixbar_kinetostatic.toml"))
    assert [g.name for g in fa.solution.groups] == ["group 4–5", "group 2–3", "driver 1"]
    for g in fa.solution.groups:
        total = sum(complex(v[0]) for _, v in g.chain)
        assert abs(total) < 1e-10 * max(abs(complex(v[0])) for _, v in g.chain), g.name


# ----------------------------------------------------------------------------- bad input


@pytest.mark.parametrize("find, message", [
    ('["R_13"]', "find[0]: links 1 and 3 have no joint (reactions: R_12, R_14, R_23, R_34)"),
    ('["F_i3"]', "find[0]: link 3 has no [[forces.mass]] (masses on links 2)"),
    ('["eta"]', "find[0]: eta compares with friction: this scene has none"),
])
def test_unknown_force_names_are_one_line_errors(tmp_path, find, message):
    code, out, err = run_cli("check", str(_write(tmp_path, _fourbar(90, find=find))))
    assert code == 2 and err == f"s.toml: {message}\n"


RPP_LOADS = """
[forces]
gravity_m_s2 = 9.81
[[forces.mass]]
link = "2"
point = "B"
mass_kg = 0.5
[[forces.mass]]
link = "3"
point = "C"
mass_kg = 2
[[forces.force]]
name = "Q"
link = "3"
point = "C"
force_N = 300
angle = 180
"""
RPP_FRICTION = """
[[forces.guide]]
link = "2"
f = 0.15
[[forces.guide]]
link = "3"
f = 0.1
[[forces.journal]]
point = "B"
f_v = 0.1
radius = 5
"""


@pytest.mark.parametrize("friction", [False, True])
def test_rpp_slotted_slider_polygons_lever_and_matrix_agree(friction):
    """linkage.slider_fixed_angle_guide (block 2 in the 120° slot of slider 3 on the x guide) at
    four crank angles: friction in the slot, on the guide and in the journal B."""
    text = (SCENES / "linkage.slider_fixed_angle_guide.toml").read_text(encoding="utf-8")
    text = text.replace("angle = 45\n", "angle = [45, 100, 200, 300]\n", 1)
    text = text.replace('find = ["omega_2"', 'find = ["R_12", "R_23", "R_43", "M_43", "e_43", "M_b", "M_b_lever", "omega_2"')
    fa = analyse_forces(_scene(text + RPP_LOADS + (RPP_FRICTION if friction else "")))
    rows = {r.name: r for r in fa.rows}
    for row in fa.rows:
        if not (friction and "lever" in row.name):
            assert row.rel_error < 1e-12, row
    assert (fa.solution.iterations > 0) == friction
    if not friction:
        for lab in ("45", "100", "200", "300"):
            assert rows[f"M_b_lever@{lab}"].graphical == pytest.approx(rows[f"M_b@{lab}"].exact, rel=1e-12)
    # the slot's reaction on the block is ⟂ the slot (tilted by φ = arctan 0.15 with friction)
    r = complex(fa.solution.reactions[("3", "2")][0])
    slot = complex(np.cos(np.radians(120.0)), np.sin(np.radians(120.0)))
    tilt = abs(np.degrees(np.angle(r / (1j * slot))))
    assert min(tilt, 180 - tilt) == pytest.approx(np.degrees(np.arctan(0.15)) if friction else 0.0, abs=1e-9)


RPR_LOADS = """
[forces]
gravity_m_s2 = 9.81
[[forces.mass]]
link = "2"
point = "D"
mass_kg = 1.5
inertia_kgm2 = 0.004
[[forces.mass]]
link = "3"
point = "C"
mass_kg = 0.5
inertia_kgm2 = 0.0005
[[forces.force]]
name = "F"
link = "2"
point = "E"
force_N = 40
angle = -60
"""
RPR_FRICTION = """
[[forces.journal]]
point = "B"
f_v = 0.1
radius = 5
[[forces.journal]]
point = "C"
f_v = 0.1
radius = 5
[[forces.guide]]
link = "3"
f = 0.2
"""


@pytest.mark.parametrize("friction", [False, True])
def test_rpr_oscillating_block_polygons_lever_and_matrix_agree(friction):
    """The oscillating block of kin.oscillating_block (bar 2 through the block 3 pivoted at C),
    with ε1 = 20 rad/s² and at three positions."""
    text = (SCENES / "kin.oscillating_block.toml").read_text(encoding="utf-8")
    text = text.replace("angle = 45", "angle = [45, 160, 300]\nepsilon_rad_s2 = 20")
    text = text.replace('find = ["l_BC"', 'find = ["R_12", "R_23", "R_43", "R_41", "M_b", "M_b_lever", "F_i3", "M_i3", "l_BC"')
    text += RPR_LOADS + (RPR_FRICTION if friction else "")
    fa = analyse_forces(_scene(text))
    rows = {r.name: r for r in fa.rows}
    assert len([n for n in rows if n.startswith("R_")]) == 12
    for row in fa.rows:
        if row.name.startswith("M_b_lever") and friction:
            continue  # the lever is frictionless
        assert row.rel_error < 1e-12, row
    # the block turns with the bar: its inertia couple counts in the lever too
    assert rows["M_i3@45"].graphical == pytest.approx(-0.0005 * fa.kin.alpha["2"][0], rel=1e-14)
    assert (fa.solution.iterations > 0) == friction
    if not friction:
        assert rows["M_b_lever@160"].graphical == pytest.approx(rows["M_b@160"].exact, rel=1e-12)


def test_forces_scene_keys_are_checked(tmp_path):
    text = _fourbar(90).replace("mass_kg = 1", "mass_kg = -1\ncolour = 3")
    code, _, err = run_cli("check", str(_write(tmp_path, text)))
    assert code == 2 and err.startswith("s.toml: forces.mass[0].")
    with pytest.raises(SceneError, match="not a point of link 2"):
        _scene(_fourbar(90).replace('point = "B"', 'point = "D"'))


def test_value_objects_are_frozen():
    with pytest.raises(dataclasses.FrozenInstanceError):
        LinkMass("2", "S2", 1.0).mass = 2.0  # type: ignore[misc]
    with pytest.raises(dataclasses.FrozenInstanceError):
        ForceModel().gravity = 9.81  # type: ignore[misc]


# ----------------------------------------------------------------------------- figures


def test_force_sheet_panels_and_one_position_only(tmp_path):
    from graphmech.scene import render_scene

    svg, warnings = render_scene(SCENES / "force.sixbar_kinetostatic.toml")
    for title in ("Free body, group 4–5", "Force polygon, group 2–3", "Zhukovsky", "μF = 25 N/mm"):
        assert title in svg
    text = _fourbar(90, show='["force_polygons"]').replace('angle = 180', 'angle = [170, 180]')
    code, _, err = run_cli("render", str(_write(tmp_path, text)), "-o", str(tmp_path / "x.svg"))
    assert code == 2 and "draw one position" in err and not (tmp_path / "x.svg").exists()


def test_check_of_a_force_scene_never_imports_matplotlib():
    code = ("import sys; from graphmech.cli import main; "
            f"main(['check', {str(SCENES / 'force.sixbar_kinetostatic-friction.toml')!r}]); "
            "assert not any(m.split('.')[0] == 'matplotlib' for m in sys.modules), 'matplotlib imported'")
    r = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr


def test_measured_forces_are_judged_at_the_drawing_precision():
    """R_12 read off the polygon at μF = 25 N/mm: ±0.5 mm is ±12.5 N; M_b ± 12.5 N × l_AB."""
    scene = SCENES / "force.sixbar_kinetostatic.toml"
    code, out, err = run_cli("check", str(scene), "--json", "--measured", "R_12=1595,M_b=121.8,h_2=0.0245")
    assert code == 0, err
    import json

    verdicts = {v["name"]: v for v in json.loads(out)["measured"]}
    assert verdicts["R_12"]["tolerance"] == pytest.approx(12.5) and verdicts["R_12"]["ok"]
    assert verdicts["M_b"]["tolerance"] == pytest.approx(12.5 * 0.08) and verdicts["M_b"]["ok"]
    assert verdicts["h_2"]["tolerance"] == pytest.approx(0.0025) and verdicts["h_2"]["ok"]
    code, out, _ = run_cli("check", str(scene), "--measured", "R_12=1600.5")
    assert code == 1 and "OUT OF TOLERANCE" in out


# ----------------------------------------------------------------------------- properties



def _fourbar_linkage(a: float, b: float, c: float, d: float):
    from graphmech.mechanisms.linkage import RRR, Crank, Linkage, LinkPoint

    return Linkage({"A": (0.0, 0.0), "D": (d, 0.0)}, Crank("1", "A", "B", a, 10.0, 3.0),
                   (RRR("B", "C", "D", ("2", "3"), (b, c), "left"),),
                   (LinkPoint("S2", "2", ("B", "C"), b / 2, 0.01), LinkPoint("S3", "3", ("D", "C"), c / 3, 0.0)), "0")


@settings(max_examples=40, deadline=None)
@given(phi=st.floats(0.0, 6.28), m2=st.floats(0.1, 10.0), m3=st.floats(0.1, 10.0), f=st.floats(0.0, 500.0),
       angle=st.floats(-3.14, 3.14), friction=st.booleans())
def test_polygons_equal_the_matrix_method_on_random_loads(phi, m2, m3, f, angle, friction):
    """A crank-rocker (AB 60, BC 120, CD 90, AD 120 mm) at any angle, any loads, with or without
    friction: the group-by-group polygons and the matrix method give the same reactions and M_b."""
    from graphmech.exact.kinetostatics import solve_forces
    from graphmech.mechanisms.forces import PointForce, RevoluteFriction
    from graphmech.methods.polygons import build_polygons

    lk = _fourbar_linkage(0.06, 0.12, 0.09, 0.12)
    journals = tuple(RevoluteFriction(p, 0.1, 0.005) for p in "ABCD") if friction else ()
    model = ForceModel((LinkMass("2", "S2", m2, m2 * 0.002), LinkMass("3", "S3", m3, m3 * 0.001)),
                       (PointForce("3", "C", f, angle),), gravity=9.81, revolute_friction=journals)
    b = build_polygons(lk, {"l": 0.001, "v": 0.01, "a": 0.1})
    batch = b.g.prune(K.construction_targets(b)).evaluate_batch({"phi": np.array([phi])})
    kin = K.kinematics_from_construction(b, batch.values, batch.valid)
    sol = K.kinetostatics(lk, model, kin, polygons=False)
    ex = solve_forces(lk, model, np.array([phi]))
    size = max(abs(complex(r[0])) for r in sol.reactions.values())
    for key, r in sol.reactions.items():
        assert abs(complex(r[0]) - complex(*ex.reactions[key][0])) <= 1e-9 * size, key
    assert abs(sol.balancing_moment[0] - ex.balancing_moment[0]) <= 1e-9 * size * 0.06
    if not friction:
        lever = K.zhukovsky_lever(lk, model, kin)
        assert abs(lever.balancing_moment[0] - ex.balancing_moment[0]) <= 1e-9 * size * 0.06


SLIDER_DRIVEN = """
title = "Slider-driven rocker: balancing force"
show = ["forces", "force_polygons", "lever"]
find = ["F_b", "F_b_lever", "R_12", "R_23", "R_03", "R_01", "M_01"{more}]
[units]
length = "mm"
angle = "deg"
velocity = "m/s"
acceleration = "m/s2"
[frame]
link = "0"
O = [0, 0]
D = [100, 60]
[driver]
type = "slider"
link = "1"
point = "B"
guide = {{ through = "O", angle = 0 }}
position = [40, 60, 80]
velocity = 0.5
acceleration = -2
[[dyad]]
type = "RRR"
joints = ["B", "C", "D"]
links = ["2", "3"]
lengths = [80, 50]
branch = "right"
[[point]]
name = "S2"
link = "2"
base = ["B", "C"]
along = 40
left = 0
[forces]
gravity_m_s2 = 9.81
[[forces.mass]]
link = "1"
point = "B"
mass_kg = 3
[[forces.mass]]
link = "2"
point = "S2"
mass_kg = 1
inertia_kgm2 = 0.002
[[forces.moment]]
name = "M_r"
link = "3"
moment_Nm = 4
{extra}
"""


@pytest.mark.parametrize("friction", [False, True])
def test_a_driving_slider_gets_a_balancing_force(friction):
    """The slider-driven rocker of the docs at three positions: F_b by the polygons, by the matrix
    method and by Zhukovsky's lever (F_b = μv·ΣM_p/v)."""
    extra = '[[forces.guide]]\nlink = "1"\nf = 0.2\n[[forces.journal]]\npoint = "C"\nf_v = 0.2\nradius = 5\n'
    text = SLIDER_DRIVEN.format(more=', "F_b0"' if friction else "", extra=extra if friction else "")
    fa = analyse_forces(_scene(text))
    rows = {r.name: r for r in fa.rows}
    assert len(rows) == 3 * (8 if friction else 7)
    for row in fa.rows:
        assert row.rel_error < 1e-12, row
    for lab in ("40", "60", "80"):  # the lever is frictionless
        ref = rows[f"F_b0@{lab}"].graphical if friction else rows[f"F_b@{lab}"].graphical
        assert rows[f"F_b_lever@{lab}"].graphical == pytest.approx(ref, rel=1e-12)
    assert rows["F_b@60"].graphical == pytest.approx(-86.8604612 if friction else -89.4518378, rel=1e-8)
    assert _scene(text).kind == "forces"
    with pytest.raises(SceneError, match="the driver is a slider: its balancing force is F_b"):
        analyse_forces(_scene(text.replace('"F_b",', '"M_b",', 1)))


@settings(max_examples=40, deadline=None)
@given(phi=st.floats(0.0, 6.28), m3=st.floats(0.1, 10.0), f=st.floats(0.0, 2000.0), fs=st.floats(0.0, 0.4),
       fv=st.floats(0.0, 0.3), e=st.floats(-30.0, 30.0))
def test_slider_crank_with_friction_equals_the_matrix_method(phi, m3, f, fs, fv, e):
    """An offset slider-crank (AB 100, BC 300 mm, offset e) at any angle, a piston force against +x,
    friction on the guide and in all three journals: polygons = matrix method (scipy root)."""
    from graphmech.exact.kinetostatics import solve_forces
    from graphmech.mechanisms.forces import PointForce, RevoluteFriction, SlidingFriction
    from graphmech.mechanisms.linkage import RRP, Crank, Guide, Linkage, LinkPoint
    from graphmech.methods.polygons import build_polygons

    lk = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.1, 150.0),
                 (RRP("B", "C", ("2", "3"), 0.3, Guide((0.0, e / 1000.0), 0.0), "forward"),),
                 (LinkPoint("S2", "2", ("B", "C"), 0.1, 0.0),), "0")
    model = ForceModel((LinkMass("2", "S2", 2.0, 0.02), LinkMass("3", "C", m3)), (PointForce("3", "C", f, np.pi),),
                       gravity=9.81, revolute_friction=tuple(RevoluteFriction(p, fv, 0.01) for p in "ABC"),
                       sliding_friction=(SlidingFriction("3", fs),))
    b = build_polygons(lk, {"l": 0.002, "v": 0.1, "a": 10.0})
    batch = b.g.prune(K.construction_targets(b)).evaluate_batch({"phi": np.array([phi])})
    kin = K.kinematics_from_construction(b, batch.values, batch.valid)
    sol = K.kinetostatics(lk, model, kin, polygons=False)
    ex = solve_forces(lk, model, np.array([phi]))
    assert ex.valid[0]
    size = max(abs(complex(r[0])) for r in sol.reactions.values())
    for key, r in sol.reactions.items():
        assert abs(complex(r[0]) - complex(*ex.reactions[key][0])) <= 1e-8 * size, key
    assert abs(sol.balancing_moment[0] - ex.balancing_moment[0]) <= 1e-8 * size * 0.1


# ----------------------------------------------------------------------------- hostile input (review)


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
    text = SLIDER_CRANK.format(length=300, extra="")
    assert old in text
    code, out, err = run_cli("check", str(_write(tmp_path, text.replace(old, new, 1))))
    assert (code, out) == (2, "")
    assert err == f"s.toml: {message}\n"


DOC_BLOCKS = re.findall(r"```toml\n(.*?)```", (ROOT / "docs" / "scene-format.md").read_text(encoding="utf-8"), re.S)


def _doc_scene(title: str) -> str:
    return next(b for b in DOC_BLOCKS if b.startswith(f'title = "{title}"'))


@pytest.mark.parametrize("title, mu_l", [
    ("Oscillating block: reactions with friction", "μl = 0.002 m/mm"),
    ("Slider-driven rocker: balancing force", "μl = 0.005 m/mm"),
])
def test_chosen_scales_fit_the_force_sheet_on_its_page(tmp_path, title, mu_l):
    # μl was chosen for the mechanism alone, filling the page: the free bodies and the lever ran
    # off it ("the panels need 410.9 mm of height … run off the page", RPR at μl = 0.0005 m/mm)
    p = _write(tmp_path, _doc_scene(title))
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "s.svg"))
    assert code == 0 and "run off the page" not in err
    assert mu_l in (tmp_path / "s.svg").read_text(encoding="utf-8")
    code, out, _ = run_cli("check", str(p))
    assert code == 0 and mu_l + " (chosen)" in out  # the table reads the figure's lengths


def test_the_lever_with_friction_names_the_frictionless_balancing_moment(tmp_path):
    # the caption said "M_b = μv·ΣM_p/ω1 = …" though the lever knows no friction: it is M_b0
    code, _, err = run_cli("render", str(_write(tmp_path, _doc_scene("Oscillating block: reactions with friction")
                                               .replace('show = ["forces", "force_polygons"]',
                                                        'show = ["forces", "lever"]'))), "-o", str(tmp_path / "s.svg"))
    svg = (tmp_path / "s.svg").read_text(encoding="utf-8")
    assert code == 0 and "M_b0 = μv·ΣM_p/ω1 = " in svg and "N·m (without friction)" in svg


@pytest.mark.parametrize("find, show, key", [
    ('["M_b_lever"]', '["mechanism"]', "find[0]"),
    ('["M_b"]', '["forces", "lever"]', "show"),
])
def test_a_lever_of_a_crank_at_rest_names_the_key_that_asked_for_it(tmp_path, find, show, key):
    # the message had no key path: "s.toml: Zhukovsky's lever: the crank stands still: …"
    text = SLIDER_CRANK.format(length=300, extra="").replace("omega_rad_s = 10", "omega_rad_s = 0")
    text = text.replace('find = ["R_12", "R_43", "M_b"]', f"find = {find}").replace('show = ["mechanism"]',
                                                                                 f"show = {show}")
    code, out, err = run_cli("check", str(_write(tmp_path, text)))
    assert (code, out) == (2, "")
    assert err == f"s.toml: {key}: Zhukovsky's lever: the crank stands still: no virtual power\n"


def test_eta_of_a_crank_that_the_loads_drive_is_actual_over_ideal_output():
    # the docs' slider-crank: P pushes the slider, the crank absorbs power (M_b0 = -50.16 N·m);
    # η was M_b0/M_b = 1.074 > 1, now M_b/M_b0 as for a reverse stroke
    fa = analyse_forces(_scene(_doc_scene("Slider-crank with friction: balancing moment")))
    rows = {r.name: r for r in fa.rows}
    m_b, m_b0 = rows["M_b"].exact, rows["M_b0"].exact
    assert m_b0 == pytest.approx(-50.1601797, rel=1e-9) and -m_b0 > -m_b > 0
    assert rows["eta"].exact == pytest.approx(m_b / m_b0, rel=1e-15)
    assert rows["eta"].exact == pytest.approx(0.930961525, rel=1e-9)
    assert rows["eta"].rel_error < 1e-14
    # a crank that drives keeps η = M_b0/M_b (the six-bar with friction: 0.8919214560679)
    fa = analyse_forces(load_scene(SCENES / "force.sixbar_kinetostatic-friction.toml"))
    eta = next(r for r in fa.rows if r.name == "eta")
    assert eta.exact == pytest.approx(0.8919214560679, rel=1e-12)


RPP_LOADED = """
find = ["R_12", "R_03", "M_b", "M_b0"]
show = ["mechanism"]
[frame]
link = "0"
A_mm = [0, 0]
[driver]
type = "crank"
link = "1"
pivot = "A"
tip = "B"
length_mm = 40
angle_deg = { start = 0, stop = 360, step = 60 }
omega_rad_s = 100
[[dyad]]
type = "RPP"
joints = ["B", "C"]
links = ["2", "3"]
slot_angle_deg = 60
guide = { through = "A", angle_deg = 0 }
[forces]
[[forces.mass]]
link = "3"
point = "C"
mass_kg = 2
[[forces.force]]
link = "3"
point = "C"
force_N = 500
angle_deg = 0
resistance = true
[[forces.journal]]
point = "B"
f_v = 0.1
radius_mm = 5
[[forces.guide]]
link = "3"
f = 0.15
"""


def test_a_position_where_every_load_vanishes_is_not_a_large_relative_error():
    # at 240° the slider's acceleration is 0 and the resistance idle: every reaction is round-off
    # (4.2e-13 N against 4.5e-13 N), which the per-position denominator read as 6 % errors
    fa = analyse_forces(_scene(RPP_LOADED))
    rows = {r.name: r for r in fa.rows}
    assert abs(rows["R_12@240"].exact) < 1e-9 and rows["R_12@0"].exact == pytest.approx(1643.4364734438561, rel=1e-12)
    assert max(r.rel_error for r in fa.rows) < 1e-13


def test_a_measured_moment_on_a_slider_driven_scene_is_judged(tmp_path):
    # --measured M_01=… crashed: 'SliderInput' object has no attribute 'length' (exit 3)
    p = _write(tmp_path, _doc_scene("Slider-driven rocker: balancing force"))
    doc = check_json(p, "--measured", "M_01=0.0001")
    v = next(x for x in doc["measured"] if x["name"] == "M_01")
    assert v["expected"] == 0.0 and v["ok"] is True and 0 < v["tolerance"] < 1
    code, _, err = run_cli("check", str(p), "--measured", "M_01=1")
    assert code == 1 and err == ""


def test_a_resultant_moved_farther_than_the_mechanism_is_drawn_as_a_couple(tmp_path):
    # link 2 of 1 mg with J = 0.03 kg·m²: h = |M_i/F_i| ≈ 19 km, and F_i2′ was drawn there (the
    # sheet "needs 11289459.9 mm of height")
    text = (SCENES / "force.sixbar_kinetostatic.toml").read_text(encoding="utf-8")
    assert "mass_kg = 4\n" in text
    p = _write(tmp_path, text.replace("mass_kg = 4\n", "mass_kg = 1e-6\n"))
    fa = analyse_forces(load_scene(p))
    assert float(fa.solution.inertia["2"].offset[0]) > 1e4  # metres
    code, _, err = run_cli("render", str(p), "-o", str(tmp_path / "s.svg"))
    svg = (tmp_path / "s.svg").read_text(encoding="utf-8")
    assert code == 0 and "run off the page" not in err
    assert "Fᵢ₂′" not in svg and "Fᵢ₂" in svg and "Fᵢ₃′" in svg


def test_a_scene_couple_is_drawn_on_the_loads_and_on_its_free_body(tmp_path):
    # M_r = 4 N·m on rocker 3 acted in every polygon but was drawn only on Zhukovsky's lever (at c
    # and p): the loads panel and the free body of group 2–3 left it out
    p = _write(tmp_path, _doc_scene("Slider-driven rocker: balancing force"))
    code, _, _ = run_cli("render", str(p), "-o", str(tmp_path / "s.svg"))
    svg = (tmp_path / "s.svg").read_text(encoding="utf-8")
    assert code == 0 and svg.count(">Mᵣ<") == 4
    no_lever = _doc_scene("Slider-driven rocker: balancing force").replace(
        'show = ["forces", "force_polygons", "lever"]', 'show = ["force_polygons"]')
    code, _, _ = run_cli("render", str(_write(tmp_path, no_lever, "t.toml")), "-o", str(tmp_path / "t.svg"))
    assert code == 0 and (tmp_path / "t.svg").read_text(encoding="utf-8").count(">Mᵣ<") == 1


def test_the_fit_counts_the_footer_of_the_rendered_sheet(tmp_path):
    # the chosen μv fitted Zhukovsky's lever to a page without the footer line: rendered, it
    # needed 383.2 mm where the A2 page leaves 381.2 mm
    text = (SCENES / "force.sixbar_kinetostatic.toml").read_text(encoding="utf-8")
    text = text.replace('show = ["forces", "force_polygons", "lever"]', 'show = ["lever"]')
    text = re.sub(r"\[scales\]\n(.*\n){3}", "", text).replace("mu_F_N_per_mm = 25\n", "")
    text = text.replace("angle = 120\n", "angle = 41.6009\n").replace("omega = 12\n", "omega = -50\n")
    assert "[scales]" not in text and "omega = -50" in text
    code, _, err = run_cli("render", str(_write(tmp_path, text)), "-o", str(tmp_path / "s.svg"))
    assert code == 0 and "run off the page" not in err


def test_a_guide_reaction_whose_line_crosses_far_off_is_drawn_at_the_slider_with_its_moment():
    # RPP, slot ⟂ guide, friction: the guide's reaction on slot 3 is nearly along the guide and its
    # line of action crossed the guide 0.55 m from C — its arrow floated 270 mm off the free body
    from graphmech.problems.forces.figures import free_body_items
    from graphmech.drawing.primitives import Arrow, Label

    text = RPP_LOADED.replace("slot_angle_deg = 60", "slot_angle_deg = 90").replace(
        "angle_deg = { start = 0, stop = 360, step = 60 }", "angle_deg = 45")
    scene = _scene(text.replace('show = ["mechanism"]', 'show = ["force_polygons"]'))
    fa = analyse_forces(scene)
    g = fa.solution.guides[0]
    c = complex(fa.kin.point["C"][0])
    e = float(g.moment[0]) / abs(complex(g.force[0]))
    assert abs(e) > 0.2  # metres: the line of action is far off
    group = next(gr for gr in fa.solution.groups if "3" in gr.links)
    items = free_body_items(fa.build, fa.kin, group, {}, {j.point for j in fa.solution.joints}, 0,
                            fa.solution.guides)
    at_c = fa.build.to_drawing((c.real, c.imag))
    assert any(isinstance(x, Arrow) and math.dist(x.p0, at_c) < 1e-9 for x in items)
    assert any(isinstance(x, Label) and x.text == "M₀₃" for x in items)
    xs = [p for x in items if isinstance(x, Arrow) for p in (x.p0[0], x.p1[0])]
    assert max(xs) - min(xs) < 100.0  # mm: the free body stays compact


DOUBLE_SLIDER = """
title = "Slider drives a slider"
show = ["forces", "force_polygons", "lever"]
find = ["F_b", "F_b0", "eta"]
[units]
length = "mm"
angle = "deg"
velocity = "m/s"
acceleration = "m/s2"
[frame]
link = "0"
O = [0, 0]
[driver]
type = "slider"
link = "1"
point = "B"
guide = { through = "O", angle = 0 }
position = 60
velocity = 0.5
acceleration = 0
[[dyad]]
type = "RRP"
joints = ["B", "C"]
links = ["2", "3"]
length = 100
guide = { through = [0, 0], angle = 90 }
branch = "forward"
[[point]]
name = "S2"
link = "2"
base = ["B", "C"]
along = 50
left = 0
[forces]
gravity_m_s2 = 9.81
[[forces.mass]]
link = "2"
point = "S2"
mass_kg = 1
inertia_kgm2 = 0.002
[[forces.mass]]
link = "3"
point = "C"
mass_kg = 2
[[forces.force]]
name = "Q"
link = "3"
point = "C"
force_N = 50
angle = -90
[[forces.guide]]
link = "1"
f = 0.2
[[forces.guide]]
link = "3"
f = 0.15
[[forces.journal]]
point = "B"
f_v = 0.1
radius = 5
"""


def test_a_sheet_that_fits_no_round_scale_keeps_readable_drawings_and_says_so(tmp_path):
    # the first fit made everything coarser until the spill was least: μF = 20 N/mm drew 3 mm
    # polygons on an A4 sheet that captions alone overfill; now μl, μv first, a coarser scale only
    # for a real gain, and a hint
    code, _, err = run_cli("render", str(_write(tmp_path, DOUBLE_SLIDER)), "-o", str(tmp_path / "s.svg"))
    assert code == 0 and 'give [page] size = "A3"' in err
    fa = analyse_forces(_scene(DOUBLE_SLIDER))
    assert (fa.scales["l"], fa.scales["F"]) == (0.01, 5.0) and fa.spill_mm > 0
    rows = {r.name: r for r in fa.rows}
    # the loads drive the slider here (F_b0 < 0 along +v): η = F_b/F_b0
    assert rows["F_b0"].exact == pytest.approx(-46.921582, rel=1e-7)
    assert rows["eta"].exact == pytest.approx(rows["F_b"].exact / rows["F_b0"].exact, rel=1e-14)
    a3 = DOUBLE_SLIDER.replace("[units]", '[page]\nsize = "A3"\n[units]')
    code, _, err = run_cli("render", str(_write(tmp_path, a3, "a3.toml")), "-o", str(tmp_path / "a3.svg"))
    assert code == 0 and "run off the page" not in err and "A3" not in err


def test_eta_at_or_below_zero_is_said_to_be_self_locking():
    # the rocking block with f = 5 between block and bar: η ≤ 0 at 20 of 36 positions, in silence
    text = _doc_scene("Oscillating block: reactions with friction").replace("f = 0.2", "f = 5").replace(
        "angle = 45", "angle = { start = 0, stop = 360, step = 10 }").replace(
        'show = ["forces", "force_polygons"]', 'show = ["mechanism"]')
    fa = analyse_forces(_scene(text))
    etas = [r for r in fa.rows if r.name.startswith("eta@")]
    locked = [r for r in etas if r.exact <= 0]
    assert len(etas) == 36 and 0 < len(locked) < 36
    warning = next(w for w in fa.warnings if "self-locking" in w)
    assert f"and {len(locked) - 1} more position(s): η ≤ 0" in warning
    assert not any("self-locking" in w for w in analyse_forces(_scene(
        _doc_scene("Oscillating block: reactions with friction"))).warnings)


def test_friction_dissipates_exactly_the_extra_driving_power_over_the_cycle(tmp_path):
    # an independent check of the friction senses (the polygons and the matrix method share the
    # convention): (M_b − M_b0)·ω1 must equal the power lost, Σ|R|·ρ·|ω_rel| in the journals plus
    # f·|N|·|v| on the guide, each from the matrix method's reactions and the exact kinematics
    text = (SCENES / "force.sixbar_kinetostatic-friction.toml").read_text(encoding="utf-8")
    text = re.sub(r"^show = .*$", 'show = ["mechanism"]', text, flags=re.M)
    text = text.replace("angle = 120\n", "angle = { start = 0, stop = 360, step = 15 }\n", 1)
    assert "step = 15" in text
    fa = analyse_forces(load_scene(_write(tmp_path, text)))
    ex, kin = fa.exact, fa.kinematics.exact
    om = {"0": 0.0, **{k: np.asarray(v) for k, v in kin.omega.items()}}
    lost = 0.0
    for fr in fa.scene.problem.model.revolute_friction:
        (a, b), = [(j.a, j.b) for j in fa.solution.joints if j.point == fr.point]
        lost = lost + np.hypot(*ex.reactions[(a, b)].T) * fr.rho * np.abs(om[b] - om[a])
    r05 = ex.reactions[("0", "5")]
    lost = lost + 0.1 * np.abs(r05[:, 1]) * np.abs(kin.vel["F"][:, 0])  # guide y = 300 mm: N is R_y
    gained = (np.asarray(ex.balancing_moment) - np.asarray(fa.exact_frictionless.balancing_moment)) * 12.0
    ok = np.asarray(ex.valid)
    assert ok.sum() == 24 and np.all(lost[ok] > 0)
    np.testing.assert_allclose(gained[ok], lost[ok], rtol=1e-11)


def test_a_force_scene_refuses_to_show_instant_centres_it_would_not_draw():
    """show = ["forces", "instant_centres"] drew no centres and said nothing; now one line, exit 2."""
    text = (SCENES / "force.sixbar_kinetostatic.toml").read_text(encoding="utf-8")
    text = re.sub(r"^show = \[.*\]$", 'show = ["forces", "instant_centres"]', text, count=1, flags=re.M)
    with pytest.raises(SceneError) as e:
        parse_scene(tomllib.loads(text), "f.toml")
    assert str(e.value).startswith("f.toml: show[1]: the instant centres are drawn on a linkage sheet")
