"""The protocol of a structure scene (graphmech/problems/structure/steps.py): the mobility counted
as the book counts it, checked by the Jacobian's rank, and the Assur groups taken off — every
count the check's."""
from __future__ import annotations

import tomllib

from graphmech.problems import check, steps
from graphmech.scene import load_scene
from graphmech.scene import parse_scene as parse
from tests.conftest import SCENES, run_cli


def parse_scene(text: str, source: str = "s.toml"):
    return parse(tomllib.loads(text), source)


def test_the_redundant_parallelogram_is_counted_checked_and_taken_apart():
    scene = load_scene(SCENES / "structure.parallelogram_redundant.toml")
    lines = steps(scene)
    assert lines == [
        "count the moving links (1 is the frame): 2, 3, 4, 5 — n = 4",
        "count the lower pairs: A, B, C, D, E, F — p_l = 6",
        "no higher pairs: p_h = 0",
        "redundant constraints, as the scene states them: p′ = 1",
        "F = 3n − (2p_l + p_h − p′) − F′: F = 3·4 − (2·6 + 0 − 1) − 0 = 1",
        "check at the drawn position: the 12 constraint equations have rank 11: F = 3·4 − 11 − 0 = 1, p′ = 12 − 11 = 1",
        "F = 1 = the number of drivers (2): the motion is determined",
        "leave out the link(s) 5 that only repeat a motion already fixed (the redundant constraints), as the book does",
        "detach the class II Assur group of links 3, 4 (pairs B, C, D): 3·2 = 2·3, F = 0",
        "what is left: the frame 1 and the driver(s) 2 — the class I mechanism",
        "the highest group is of class II: a class II mechanism",
    ]
    rows = {r.name: r for r in check(scene)[0].rows}
    # the count's F and p′ are the rows' graphical values, the Jacobian's their exact ones
    assert lines[4].endswith(f"= {int(rows['F'].graphical)}") and lines[5].endswith(f"p′ = 12 − 11 = "
                                                                                    f"{int(rows['p_redundant'].exact)}")
    assert f"F = 3·4 − 11 − 0 = {int(rows['F'].exact)}" in lines[5]


def test_compound_hinges_rollers_and_higher_pairs_are_counted_as_the_book_does():
    hinge = steps(load_scene(SCENES / "dof.hfut_cases-3-1.toml"))
    assert hinge[1] == "C is a compound hinge of 3 links (3, 4, 5): it counts as 2 revolutes"
    assert hinge[3] == "count the lower pairs: A, B, C ×2, D, E ×2, F, G, G′ — p_l = 10"
    # the groups come off furthest from the driver first
    assert [x.split(" (pairs")[0] for x in hinge if x.startswith("detach")] == [
        "detach the class II Assur group of links 7, 8", "detach the class II Assur group of links 5, 6",
        "detach the class II Assur group of links 3, 4"]
    cam = steps(load_scene(SCENES / "dof.hfut_cases-3-2.toml"))
    assert "the roller 3 turns about its own pin without moving the rest: a local freedom — F′ = 1" in cam
    assert "F = 3n − (2p_l + p_h − p′) − F′: F = 3·9 − (2·12 + 1 − 0) − 1 = 1" in cam
    assert cam.index("leave out the roller 3 (its local freedom): the contact moves onto its follower") < \
        cam.index("replace the higher pair K by a virtual link with two revolutes at the centres of curvature")


def test_a_class_iii_group_and_a_rigid_design():
    eg = steps(load_scene(SCENES / "dof.hfut_cases-ic_engine_EG.toml"))
    assert "detach the class III Assur group of links 2, 3, 4, 5 (pairs A, B, C, C′, D, E): 3·4 = 2·6, F = 0" in eg
    assert eg[-1] == "the highest group is of class III: a class III mechanism"
    press = steps(load_scene(SCENES / "dof.hfut_cases-punch_press.toml"))
    assert "F = 0 ≤ 0: the links form a rigid structure and cannot move" in press


def test_printed_cases_get_their_formulas():
    lines = steps(load_scene(SCENES / "dof.chen_ch3_cases.toml"))
    assert lines[:3] == ["3-5_original: F = 3·3 − (2·4 + 1 − 0) − 0 = 0",
                         "3-5_original: F = 0 ≤ 0 — a rigid structure, it cannot move",
                         "3-5_fix_b: F = 3·4 − (2·5 + 1 − 0) − 0 = 1"]
    assert len(lines) == 8


def test_chinese_and_russian_wording():
    text = (SCENES / "structure.parallelogram_redundant.toml").read_text(encoding="utf-8") + \
        '\n[page]\nnotation = "{}"\n'
    zh = steps(parse_scene(text.replace("{}", "zh")))
    assert zh[0] == "数活动构件（1为机架）：2, 3, 4, 5，n = 4"
    assert zh[3] == "虚约束（题给）：p′ = 1" and zh[6] == "F = 1，等于原动件数（2）：机构具有确定的运动"
    assert zh[8] == "拆下由构件3, 4（运动副B, C, D）组成的II级杆组：3·2 = 2·3，F = 0"
    ru = steps(parse_scene(text.replace("{}", "ru")))
    assert ru[4] == "по формуле Чебышева F = 3n − (2p_l + p_h − p′) − F′: F = 3·4 − (2·6 + 0 − 1) − 0 = 1"
    assert ru[-1] == "высший класс групп — II: механизм II класса"


def test_the_cli_prints_it_numbered():
    code, out, err = run_cli("steps", str(SCENES / "dof.hfut_cases-ic_engine.toml"))
    assert err == ""
    lines = out.splitlines()
    assert code == 0 and len(lines) == 11
    assert lines[4] == ("5. check at the drawn position: the 20 constraint equations have rank 20: "
                        "F = 3·7 − 20 − 0 = 1, p′ = 20 − 20 = 0")
