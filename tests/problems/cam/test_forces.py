"""The forces on a cam mechanism with friction (issue 22 item 1, 000 力 3; invented data): the follower's
force polygon by Culmann's construction against the equilibrium equations solved exactly."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.exact.cam_forces import CamFriction, solve
from graphmech.problems.cam.forces import force_polygon, force_rows
from tests.conftest import SCENES, assert_refused, check_json, run_cli, values

SCENE = SCENES / "cam.follower_forces_friction.toml"


def _cam():
    from graphmech.scene import load_scene

    return load_scene(SCENE).problem


def test_the_scene_reads_the_forces_off_the_polygon_as_the_linear_system_gives_them():
    doc = check_json(SCENE)
    q = values(doc)
    assert doc["scales"]["F"] == 10.0  # the 500 N load about 60 mm long: 50 mm
    cs = _cam()
    ex = solve(cs.cam, cs.forces)
    for name, want in (("R_K", ex.R), ("R_B1", float(np.hypot(*ex.R_B1))), ("R_B2", float(np.hypot(*ex.R_B2))),
                       ("M_1", ex.M1)):
        assert q[name]["exact"] == pytest.approx(want, rel=1e-12)
        assert q[name]["graphical"] == pytest.approx(want, rel=1e-9)  # a construction: exact to round-off
    assert q["R_K"]["drawn_mm"] == pytest.approx(ex.R / 10.0, rel=1e-9)
    # the reactions balance the load: R12 pushes up more than Q, the guide holds back the difference
    assert q["R_K"]["graphical"] > 500.0 and q["M_1"]["graphical"] > 0.0


@pytest.mark.parametrize("phi, f", [(6.0, 0.15), (5.0, 0.1), (0.0, 0.0), (10.0, 0.4)])
def test_the_polygon_closes_both_when_the_guide_reactions_cross_and_when_they_are_parallel(phi, f):
    cs = _cam()
    d = CamFriction(math.radians(60), 500.0, math.radians(phi), f, 0.060, 0.030)
    a0, a1, a2, a3 = force_polygon(cs.cam, d, 10.0)["a"]
    ex = solve(cs.cam, d)
    assert (a1 - a0) * 10.0 == pytest.approx([0.0, -500.0])
    assert (a2 - a1) * 10.0 == pytest.approx(ex.R * ex.position.d, abs=1e-8)
    assert (a3 - a2) * 10.0 == pytest.approx(ex.R_B1, abs=1e-8)
    assert (a0 - a3) * 10.0 == pytest.approx(ex.R_B2, abs=1e-8)
    rows = force_rows(cs.cam, d, 10.0, ["R_K", "M_1"])
    assert rows["M_1"].graphical == pytest.approx(ex.M1, rel=1e-9)


def test_with_the_guide_reactions_parallel_the_lever_rule_splits_them():
    from graphmech.scene import load_scene

    # the offset roller of cam.offset_roller_translating-pos at 60°: R12 leant by φ = 5° passes so near B
    # that both guide ends bear on the same side (the two reactions parallel: no Culmann point S)
    c = load_scene(SCENES / "cam.offset_roller_translating-pos.toml").problem.cam
    d = CamFriction(math.radians(60), 100.0, math.radians(5), 0.1, 0.040, 0.020)
    ex = solve(c, d)
    assert ex.N1 < 0.0 and ex.N2 < 0.0
    a0, _, a2, a3 = force_polygon(c, d, 2.0)["a"]
    assert (a3 - a2) * 2.0 == pytest.approx(ex.R_B1, abs=1e-8)
    assert (a0 - a3) * 2.0 == pytest.approx(ex.R_B2, abs=1e-8)


def test_the_sheet_draws_the_free_body_and_force_polygon_under_the_profile_and_its_diagram():
    from graphmech.problems.cam import _sheet
    from graphmech.scene import load_scene

    sheet, _ = _sheet(load_scene(SCENE), ())
    assert [(p.name, p.row) for p in sheet.panels] == [("profile", 0), ("displacement", 0), ("free body", 1),
                                                       ("forces", 1)]
    assert sheet.panels[2].title == "Free body of the follower, with friction"
    forces = sheet.panels[3]
    assert forces.notes[0] == "μ_{F} = 10 N/mm" and forces.scales == (("F", 10.0),)
    assert sorted(i.text for i in forces.items if hasattr(i, "text")) == ["Q", "R_{12}", "R′_{32}", "R″_{32}"]


def test_a_measured_force_is_judged_at_the_polygons_scale():
    exact = values(check_json(SCENE))["R_K"]["exact"]
    code, out, _ = run_cli("check", str(SCENE), "--measured", f"R_K={exact + 4.0}")  # 0.4 mm at μF = 10 N/mm
    assert code == 0, out
    code, out, _ = run_cli("check", str(SCENE), "--measured", f"R_K={exact + 6.0}")
    assert code == 1


@pytest.mark.parametrize("change, key, words", [
    ("at = 60", "cam.forces.at", "does not rise"),  # replaced by a dwell below
    ('contact = "roller"', "cam.forces", "translating roller follower"),
    ("guide_friction = 0.15", "cam.forces.guide_friction", "between 0 and 10"),
    ("overhang = 30", "cam.forces.at", "jams in its guide"),
])
def test_a_position_without_a_drive_or_a_wrong_follower_is_refused(tmp_path, change, key, words):
    new = {"at = 60": "at = 160", 'contact = "roller"': 'contact = "knife"',
           "guide_friction = 0.15": "guide_friction = -1", "overhang = 30": "overhang = 300"}[change]
    text = SCENE.read_text(encoding="utf-8").replace(change, new)
    if change == 'contact = "roller"':
        text = text.replace("roller_radius = 10\n", "")
    elif change == "overhang = 30":
        text = text.replace("guide_friction = 0.15", "guide_friction = 3")
    p = tmp_path / "f.toml"
    p.write_text(text, encoding="utf-8")
    assert_refused(run_cli("check", str(p)), p.name, key, words)


def test_forces_need_their_table(tmp_path):
    p = tmp_path / "n.toml"
    text = SCENE.read_text(encoding="utf-8").split("[cam.forces]")[0] + '[page]\nsize = "A3"\n'
    p.write_text(text, encoding="utf-8")
    assert_refused(run_cli("check", str(p)), p.name, "find[1]", "R_K needs [cam.forces]")


def _sketch():
    from graphmech.problems.cam.check import analyse_cam
    from graphmech.problems.cam.forces import sketch_panel
    from graphmech.scene import load_scene

    scene = load_scene(SCENE)
    an = analyse_cam(scene, (), estimates=False)
    return scene.problem, sketch_panel(an.cam, scene.problem.forces, an.drawn, an.scales["l"])


def _cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def _unit(p, q):
    v = np.subtract(q, p)
    return v / np.hypot(*v)


def test_the_sketch_draws_r12_leant_by_phi_from_the_common_normal_at_k_and_the_follower_at_delta():
    from graphmech.drawing.primitives import Arrow, Label, Segment

    cs, panel = _sketch()
    mu = panel.scales[0][1]
    assert mu == 0.0025  # the profile's 0.002 would stand 120 mm tall: the next round scale
    p = solve(cs.cam, cs.forces).position
    K = tuple(p.K / mu)
    r12 = [a for a in panel.items if isinstance(a, Arrow) and a.p1 == pytest.approx(K, abs=1e-12)]
    normal = [s for s in panel.items if isinstance(s, Segment) and s.dashdot]
    assert len(r12) == 1 and len(normal) == 1
    d, n = _unit(r12[0].p0, r12[0].p1), _unit(normal[0].p0, normal[0].p1)
    assert math.degrees(math.acos(abs(float(d @ n)))) == pytest.approx(6.0, abs=1e-9)
    # the normal passes through K and the roller's centre B (at s(60°) above the base circle)
    for q in (p.K, p.B):
        rel = q / mu - np.array(normal[0].p0)
        assert abs(float(rel[0] * n[1] - rel[1] * n[0])) < 1e-9
    texts = [x.text for x in panel.items if isinstance(x, Label)]
    for name in ("Q", "R_{12}", "R′_{32}", "R″_{32}", "K", "B_{1}", "B_{2}", "P", "S", "ω", "φ", "φ′", "n"):
        assert name in texts
    assert texts.count("n") == 2 and texts.count("φ′") == 2


def test_the_sketch_leans_the_guide_reactions_by_atan_f_and_culmanns_lines_meet_at_s():
    from graphmech.drawing.primitives import Arrow, Circle, Segment

    cs, panel = _sketch()
    mu = panel.scales[0][1]
    ex = solve(cs.cam, cs.forces)
    p = ex.position
    for end, R in ((p.B1, ex.R_B1), (p.B2, ex.R_B2)):
        (a,) = [a for a in panel.items if isinstance(a, Arrow) and a.p1 == pytest.approx(tuple(end / mu), abs=1e-12)]
        u = _unit(a.p0, a.p1)
        assert u == pytest.approx(R / np.hypot(*R), abs=1e-12)  # along the exact reaction
        assert math.degrees(math.atan2(abs(u[1]), abs(u[0]))) == pytest.approx(math.degrees(math.atan(0.15)), abs=1e-9)
    # S: where both reactions' lines run; the dashed P–S carries the resultant of Q and R12
    (ps,) = [s for s in panel.items if isinstance(s, Segment) and s.dashed]
    S = np.array(ps.p1)
    assert any(isinstance(c, Circle) and c.center == pytest.approx(tuple(S)) for c in panel.items)
    for end in (p.B1, p.B2):
        rel = S - end / mu
        assert abs(float(_cross(rel, _unit((0, 0), (ex.R_B1 if end is p.B1 else ex.R_B2))))) < 1e-9
    c = np.array(ps.p1) - np.array(ps.p0)
    res = ex.R * p.d + np.array([0.0, -500.0])  # Q + R12, balanced by the guide's resultant along P–S
    assert abs(float(_cross(c / np.hypot(*c), res / np.hypot(*res)))) < 1e-9



@pytest.mark.parametrize("f, has_s", [(0.0, False), (0.01, False), (0.4, True)])
def test_the_sketch_leaves_s_off_when_the_guide_reactions_are_parallel_or_meet_far_off(f, has_s):
    from graphmech.drawing.primitives import Label, Segment
    from graphmech.problems.cam.check import analyse_cam
    from graphmech.problems.cam.forces import sketch_items
    from graphmech.scene import load_scene

    scene = load_scene(SCENE)
    an = analyse_cam(scene, (), estimates=False)
    d = CamFriction(math.radians(60), 500.0, math.radians(6), f, 0.060, 0.030)
    items = sketch_items(an.cam, d, an.drawn, 0.0025)
    texts = [i.text for i in items if isinstance(i, Label)]
    # f = 0.01: S stands 3 m off (b/2f), beyond 4 × the guide's top; f = 0: no S at all (and no φ′)
    assert ("S" in texts) is has_s and any(isinstance(i, Segment) and i.dashed for i in items) is has_s
    assert texts.count("φ′") == (0 if f == 0.0 else 2) and "P" in texts and "R_{12}" in texts
