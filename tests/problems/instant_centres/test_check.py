"""The instant-centre method's check (graphmech/problems/instant_centres/check.py): the names it
claims, the exact centre of two links from their velocity fields, the JSON summary, and the rows
and verdicts of a scene that asks for centres."""
from __future__ import annotations

import dataclasses
import math
import tomllib

import pytest

from graphmech.errors import SceneError
from graphmech.problems.instant_centres.check import (asked, canonical, claims, exact_centre, relative_speed,
                                                      summary)
from graphmech.problems.linkage.check import analyse
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES, check_json, run_cli
from tests.scenes import scene_text

#: An offset slider-crank at three crank angles (30°, 120°, 250°), μl = 0.002 m/mm.
SLIDER_CRANK = scene_text("linkage/ic_slider_crank")


def scene_of(text: str, show=("instant_centres",), find=()):
    """The scene ``text`` with its own show and find."""
    return parse_scene({**tomllib.loads(text), "show": list(show), "find": list(find)}, "test.toml")


def intersection(p, q, r, s):
    """Where line pq meets line rs."""
    d1, d2 = (q[0] - p[0], q[1] - p[1]), (s[0] - r[0], s[1] - r[1])
    t = ((r[0] - p[0]) * d2[1] - (r[1] - p[1]) * d2[0]) / (d1[0] * d2[1] - d1[1] * d2[0])
    return (p[0] + t * d1[0], p[1] + t * d1[1])


# ------------------------------------------------------------------------------------------
# Names
# ------------------------------------------------------------------------------------------


def test_the_at_ic_alias_is_the_ic_suffix():
    assert canonical("omega_3@ic") == "omega_3_ic"
    assert canonical("omega_3@ic@30") == "omega_3_ic@30"
    assert canonical("v_C@30") == "v_C@30" and canonical("P13") == "P13"


@pytest.mark.parametrize("name, mine", [
    ("P13", True), ("x_P13@30", True), ("dir_P1_10", True), ("omega_3_ic", True), ("omega_3@ic", True),
    ("v_C_ic", True), ("v_min_BC_ic", True), ("s_min_BC_ic", True), ("phi_v0_C", True), ("phi_v0_C_1", True),
    ("v_C", False), ("omega_3", False), ("a_C@30", False),
])
def test_the_method_claims_its_own_names_only(name, mine):
    assert claims(name) is mine


def test_a_scene_asks_for_centres_by_show_find_or_measured():
    scene = scene_of(SLIDER_CRANK, show=("mechanism",), find=["v_C"])
    assert not asked(scene)
    assert asked(scene, (("x_P13@30", 0.1),))
    assert asked(dataclasses.replace(scene, find=("P13",))) and asked(dataclasses.replace(scene, show=("instant_centres",)))
    assert asked(dataclasses.replace(scene, measured=(("omega_3@ic@30", 1.0),)))


# ------------------------------------------------------------------------------------------
# The exact centres
# ------------------------------------------------------------------------------------------


def test_the_exact_centre_of_a_joint_and_of_coupler_and_frame():
    """P12 is the crank's pivot A; P13 of a four-bar is where AB meets DC (Kennedy's theorem)."""
    scene = parse_scene(tomllib.loads(scene_text("linkage/fourbar_phi30")))  # crank 2, coupler 3, rocker 4, frame 5
    kin = analyse(scene).exact
    lk = scene.linkage
    kind, a = exact_centre(lk, kin, "5", "2", 0)
    assert kind == "point" and a == pytest.approx((0.0, 0.0), abs=1e-15)
    kind, p13 = exact_centre(lk, kin, "5", "3", 0)
    P = {k: tuple(kin.point[k][0]) for k in "ABCD"}
    assert kind == "point" and p13 == pytest.approx(intersection(P["A"], P["B"], P["D"], P["C"]), rel=1e-12)


def test_a_translating_link_has_its_centre_at_infinity_or_none_at_rest():
    """The parallelogram AB = CD = 60 mm at 70°: cranks 2 and 4 turn alike (ω = 10 rad/s), so P24 is at
    infinity along AD; the coupler translates, so P13 lies (numerically) ~1e14 m away along AB."""
    scene = load_scene(SCENES / "ic.parallelogram.toml")
    kin = analyse(scene).exact
    lk = scene.linkage
    kind, d = exact_centre(lk, kin, "2", "4", 0)
    assert kind == "direction" and abs(d[1]) < 1e-12 and abs(d[0]) == pytest.approx(1.0)
    kind, far = exact_centre(lk, kin, "1", "3", 0)
    assert math.hypot(*far) > 1e12
    assert math.degrees(math.atan2(far[1], far[0])) % 180 == pytest.approx(70.0, abs=1e-6)
    speed = relative_speed(lk, kin, "2", "4", 0)
    assert speed == pytest.approx(1.2)  # no relative turn: |v0₂ − v0₄| = ω·AD = 10 × 0.12
    assert exact_centre(lk, kin, "2", "4", 0, at_rest=speed * 1.01) == ("none", (0.0, 0.0))


def test_the_summary_lists_each_position_its_centres_and_omegas():
    an = analyse(load_scene(SCENES / "ic.parallelogram.toml"))
    [pos] = summary(an)
    assert [c["name"] for c in pos["centres"]] == ["P12", "P14", "P23", "P34", "P13", "P24"]
    assert pos["centres"][1] == {"name": "P14", "kind": "direct", "x": pytest.approx(0.12), "y": pytest.approx(0.0)}
    assert pos["centres"][5]["via"] and pos["centres"][5]["direction_deg"] % 180 == pytest.approx(0.0, abs=1e-9)
    assert pos["omega"] == {"2": 10.0, "3": 0.0, "4": pytest.approx(10.0)}


# ------------------------------------------------------------------------------------------
# Through a scene: rows, verdicts, refusals
# ------------------------------------------------------------------------------------------


def test_only_what_is_asked_is_computed():
    an = analyse(scene_of(SLIDER_CRANK, show=("mechanism",), find=["v_C"]))
    assert an.instant_centres is None
    an = analyse(scene_of(SLIDER_CRANK, show=("mechanism",), find=["omega_3_ic"]))
    assert an.instant_centres is not None and [r.name[:10] for r in an.rows] == ["omega_3_ic"] * 3


@pytest.mark.parametrize("name,reason", [
    ("P19", "names no instant centre"), ("omega_9_ic", "no link '9'"), ("v_Z_ic", "no point 'Z'"),
    ("v_min_AC_ic", "not points of one moving link"), ("phi_v0_A", "point of the frame"),
    ("phi_v0_C@30", "whole turn"),
])
def test_bad_instant_centre_names_are_one_line_errors(name, reason):
    with pytest.raises(SceneError) as e:
        analyse(scene_of(SLIDER_CRANK, find=[name]))
    assert reason in str(e.value) and "find[0]" in str(e.value)


def test_measured_instant_centre_values_are_judged_within_the_drawing_precision(problems):
    book = problems["kin.fourbar_instant_centres"]["book"]
    scene = SCENES / "kin.fourbar_instant_centres.toml"
    doc = check_json(scene, "--measured", f"omega_3_ic={book['omega3_rad_s']},v_C_ic={book['vC_m_s']}",
                     "--measured", f"phi_v0_C_1={book['phi_vC0_deg'][0]},v_min_BC_ic={book['vE_m_s']}")
    m = {v["name"]: v for v in doc["measured"]}
    assert m["omega_3_ic"]["ok"] and m["v_C_ic"]["ok"] and m["phi_v0_C_1"]["ok"]
    # v_E: 0.5 mm at μl = 0.002 m/mm is ±0.0025 m/s; the book's 0.357 is 0.0039 off
    assert not m["v_min_BC_ic"]["ok"] and m["v_min_BC_ic"]["tolerance"] == pytest.approx(0.5 * 0.002 * 2.538487, rel=1e-5)
    code, out, err = run_cli("check", str(scene), "--measured", "x_P99=0.1")
    assert code == 2 and "names no instant centre" in err
    an_text = SLIDER_CRANK
    with pytest.raises(SceneError) as e:
        from graphmech.problems.linkage.check import judge

        sc = scene_of(an_text, find=["v_C"])
        sc = __import__("dataclasses").replace(sc, measured=(("omega_3_ic", 2.0),))
        judge(analyse(sc))
    assert "name one, e.g. omega_3_ic@30" in str(e.value)


def test_the_at_ic_alias_names_the_same_values():
    data = tomllib.loads((SCENES / "kin.fourbar_instant_centres.toml").read_text())
    data["find"], data["measured"] = ["omega_3@ic", "v_C@ic"], {"omega_3@ic": 2.55}
    from graphmech.problems.linkage.check import judge

    an = analyse(parse_scene(data, "alias.toml"))
    assert [(r.name, round(r.graphical, 9)) for r in an.rows] == [("omega_3_ic", 2.538487323), ("v_C_ic", 0.400984584)]
    [v] = judge(an)
    assert v.name == "omega_3_ic" and v.ok


def test_check_json_lists_every_centre_and_what_is_undetermined():
    doc = check_json(SCENES / "ic.parallelogram.toml")
    [pos] = doc["instant_centres"]
    byname = {c["name"]: c for c in pos["centres"]}
    assert set(byname) == {"P12", "P13", "P14", "P23", "P24", "P34"}
    assert byname["P13"]["kind"] == "kennedy" and byname["P13"]["direction_deg"] == pytest.approx(70.0, abs=1e-9)
    assert byname["P23"] == {"name": "P23", "kind": "direct", "x": pytest.approx(0.06 * math.cos(math.radians(70))),
                             "y": pytest.approx(0.06 * math.sin(math.radians(70)))}
    assert pos["omega"] == {"2": 10.0, "3": 0.0, "4": pytest.approx(10.0)} and pos["undetermined"] == {}
    doc = check_json(SCENES / "ic.parallelogram_change_point.toml")
    [pos] = doc["instant_centres"]
    assert {c["name"]: c["kind"] for c in pos["centres"]}["P13"] == "undetermined"
    assert set(pos["undetermined"]) == {"3", "4"}


@pytest.mark.parametrize("measured, reason", [
    ("P13=0.17", "--measured P13: a centre is read as its coordinates: x_P13, y_P13 (m), or dir_P13 (deg) at infinity"),
    ("phi_v0_C=26.4", "--measured phi_v0_C: name one of the angles: phi_v0_C_1, phi_v0_C_2 …"),
    ("phi_v0_C_3=10", "--measured phi_v0_C_3: phi_v0_C_3: v = 0 at 2 crank angle(s) only (phi_v0_C_1, phi_v0_C_2)"),
])
def test_a_measured_centre_or_zero_angle_that_has_no_row_says_what_to_write(measured, reason):
    """Before: 'cannot be judged here (undetermined, at infinity or not constructed)' for a centre
    that is neither — P13 of the book's four-bar is a finite point."""
    code, _, err = run_cli("check", str(SCENES / "kin.fourbar_instant_centres.toml"), "--measured", measured)
    assert code == 2 and err == f"kin.fourbar_instant_centres.toml: {reason}\n", err


@pytest.mark.parametrize("name, reason", [
    ("v_A_ic", "A is a point of the frame: its velocity is always 0"),  # was an internal error (KeyError)
    ("v_D_ic", "D is a point of the frame: its velocity is always 0"),
    ("v_min_BB_ic", "'BB' is one point twice: name a line by two points (v_min_BC_ic for line BC)"),  # was a warning
])
def test_a_frame_points_speed_or_a_one_point_line_is_refused(tmp_path, name, reason):
    text = (SCENES / "kin.fourbar_instant_centres.toml").read_text(encoding="utf-8")
    p = tmp_path / "ic.toml"
    p.write_text("\n".join(f'find = ["{name}"]' if line.startswith("find") else line
                           for line in text.splitlines()) + "\n", encoding="utf-8")
    code, _, err = run_cli("check", str(p))
    assert code == 2 and err == f"ic.toml: find[0]: {reason}\n", err
