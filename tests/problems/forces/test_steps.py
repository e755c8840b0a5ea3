"""The construction protocol of kinetostatics (graphmech/problems/forces/steps.py): the kinematics
the loads need, the inertia loads, the groups from the last to the driver with their polygons at μF,
the balancing moment and the lever — every number the check table's."""
from __future__ import annotations

import tomllib
from dataclasses import replace
from pathlib import Path

import pytest

from graphmech.problems import check, steps
from graphmech.problems.protocol import num
from graphmech.scene import load_scene, parse_scene
from tests.conftest import ROOT, SCENES, run_cli

FORCES = ROOT / "tests" / "scenes" / "forces"


def _index(lines: list[str], text: str) -> int:
    found = [k for k, line in enumerate(lines) if text in line]
    assert found, (text, lines)
    return found[0]


def _protocol(path: Path) -> tuple[list[str], list]:
    scene = load_scene(path)
    return steps(scene), check(scene)[0].rows


def test_the_sixbar_is_protocolled_group_by_group_from_the_last():
    lines, _ = _protocol(SCENES / "force.sixbar_kinetostatic.toml")
    order = [
        "choose μl = 0.005 m/mm (as the scene gives it) and draw the kinematic diagram at φ₁ = 120°",
        "measure p′s₂′ = 81.78 mm: a_S2 = p′s₂′·μa = 8.178 m/s²",
        "choose μF = 25 N/mm (as the scene gives it) for the force polygons",
        "G_2 = m₂·g = 4 × 9.81 = 39.24 N, downward at S₂ (1.57 mm at μF)",
        "F_i2 = −m₂·a_S2: F_i2 = 4 × 8.178 = 32.71 N at S₂, opposite to p′s₂′ (1.309 mm at μF)",
        "M_i2 = −J_S2·α₂ = −0.03 × 25.42 = −0.7627 N·m (clockwise)",
        "h_2 = |M_i2|/F_i2 = 0.7627/32.71 = 0.02332 m, h_2/μl = 4.663 mm",
        "P_r = 1000 N at K, at 0° to the x axis (40 mm at μF)",
        "free body of group 4–5 (links 4, 5): known G_4, F_i4, G_5, F_i5, P_r, M_i4; unknown R_34 at E, R_05 from "
        "the guide",
        "moments of link 4 about F: R^t_34·l_EF = ΣM_F: R^t_34 = 9.3 N ⟂ EF (0.372 mm at μF)",
        "from o lay off R^t_34 = 9.3 N: 0.372 mm at 92.84° to the x axis",
        "then P_r = 1000 N: 40 mm at 0°",
        "through the end of P_r draw a line ⟂ the guide (the line of R_05), through o a line ∥ EF (the line of "
        "R^n_34); they meet at the polygon's closing vertex",
        "R_34 = R^n_34 + R^t_34: measure from the start of R^n_34 to the end of R^t_34, 34.47 mm: R_34 = 34.47 × 25 "
        "= 861.7 N",
        "moments of slider 5 about F give where R_05 acts: M_05 = −15 N·m; e_05 = −0.08582 m along the guide from F "
        "(−17.16 mm at μl)",
        "free body of group 2–3 (links 2, 3)",
        "from o lay off R^t_12 = 1.626 N: 0.06503 mm at 102.2° to the x axis (under 0.1 mm: not drawn)",
        "then R_43 = 861.7 N: 34.47 mm at 2.22°",
        "through the end of R^t_03 draw a line ∥ DC (the line of R^n_03), through o a line ∥ BC (the line of R^n_12)",
        "R_32 = 64.37 × 25 = 1609 N (R_23 = −R_32)",
        "free body of driver 1: known G_1, R_21; unknown R_01 at A, M_b",
        "R_01 closes the polygon, from the end of R_21 back to o",
        "moments of the driver 1 about A: M_b = −ΣM_A = 120.9 N·m (counter-clockwise)",
        "Zhukovsky's lever: turn the velocity polygon 90° about p",
        "ΣM_p = 72530 N·mm: M_b = μv·ΣM_p/ω₁ = 0.02 × 72530/12 = 120.9 N·m (M_b_lever)",
    ]
    at = [_index(lines, text) for text in order]
    assert at == sorted(at), at
    assert lines[-1] == order[-1]
    assert "a_A = 0 (A does not move): F_i1 = 0" in lines  # the crank's mass sits on its pivot


def _check_rows(lines: list[str], rows: list) -> None:
    """Every row of the check table is read in the protocol with the table's numbers (4 s.f.)."""
    for r in rows:
        if "_" not in r.name or not any(r.name.startswith(p) for p in ("R_", "F_", "M_", "h_", "e_", "eta")):
            continue  # kinematic rows: the linkage protocol's (tests/problems/linkage/test_steps.py)
        mine = [line for line in lines if r.name in line and (f"= {num(r.graphical)}" in line
                                                               or f"= {num(abs(r.graphical))} " in line)]
        assert mine, (r.name, num(r.graphical), [x for x in lines if r.name in x])
        if r.drawn_mm is not None:
            assert any(f"{num(r.drawn_mm)} mm" in x or f"{num(abs(r.drawn_mm))} mm" in x for x in mine), (r, mine)


@pytest.mark.parametrize("path", [SCENES / "force.sixbar_kinetostatic.toml",
                                  SCENES / "force.sixbar_kinetostatic-friction.toml",
                                  SCENES / "force.slider_crank_inertia_partial.toml",
                                  FORCES / "double_slider.toml", FORCES / "slider_driven_rocker.toml",
                                  FORCES / "fourbar_loaded.toml", FORCES / "slider_crank.toml",
                                  SCENES / "force.tangent_mechanism.toml", FORCES / "slotted_link_pin.toml"])
def test_every_number_read_is_the_check_tables(path):
    lines, rows = _protocol(path)
    assert any(r.name.partition("@")[0] in ("eta", "M_b", "F_b", "F_i2", "R_23", "R_12") for r in rows)
    _check_blocks(lines, rows)


def test_eta_is_the_ratio_of_the_two_balancing_moments_read():
    lines, rows = _protocol(SCENES / "force.sixbar_kinetostatic-friction.toml")
    value = {r.name: r.graphical for r in rows}
    assert lines[-2] == f"the same polygons without friction give M_b0 = {num(value['M_b0'])} N·m"
    assert lines[-1] == f"η = M_b0/M_b = {num(value['M_b0'])}/{num(value['M_b'])} = {num(value['eta'])}"
    assert value["eta"] == pytest.approx(0.8919, abs=5e-5)


def test_friction_circles_and_angle_come_before_the_groups():
    lines, rows = _protocol(SCENES / "force.sixbar_kinetostatic-friction.toml")
    circle = _index(lines, "friction circle about B: ρ = f_v·r = 0.15 × 0.015 = 0.00225 m (0.45 mm at μl)")
    angle = _index(lines, "friction angle on the guide of link 5: φ = arctan f = arctan 0.1 = 5.711°")
    rounds = _index(lines, "after 9 rounds no reaction changes by more than 1e-10 N")
    assert circle < angle < rounds < _index(lines, "free body of group 4–5")
    assert "draw a line at φ = 5.711° to the guide's normal (the line of R_05)" in lines[_index(lines, "(the line of R_05)")]
    r12 = {r.name: r for r in rows}["R_12"]
    tangent = lines[_index(lines, "R_12 is tangent to the friction circle about B")]
    assert f"M_f = ρ·|R_12| = 0.00225 × {num(r12.graphical)} = {num(0.00225 * r12.graphical)} N·m" in tangent


def test_a_slider_driver_closes_with_its_balancing_force():
    lines, rows = _protocol(FORCES / "double_slider.toml")
    fb = {r.name: r for r in rows}["F_b"]
    assert fb.graphical < 0
    assert (f"F_b along the guide: measure {num(abs(fb.drawn_mm))} mm: |F_b| = {num(abs(fb.drawn_mm))} × 2 = "
            f"{num(abs(fb.graphical))} N (F_b points against the guide's direction)") in lines
    assert any("through o a line ∥ the guide (the line of F_b)" in line for line in lines)


def test_only_what_the_scene_asks_for_is_protocolled():
    # the inertia loads alone: no free body, no polygon
    lines, _ = _protocol(SCENES / "force.slider_crank_inertia_partial.toml")
    assert not any("free body" in line or "lay off R" in line for line in lines)
    assert lines[-1].startswith("F_i3 = −m₃·a_C: F_i3 = 2.141 × 1820 = 3896 N at C")
    # one reaction of the last group: that group only, not the driver
    text = (FORCES / "fourbar_loaded.toml").read_text().replace('find = ["R_23", "M_b"]', 'find = ["R_23"]')
    only = steps(parse_scene(tomllib.loads(text), "f.toml"))
    assert any("free body of group 2–3" in line for line in only)
    assert not any("driver 1" in line or "M_b" in line for line in only)


def test_a_guide_bar_and_block_group():
    text = (SCENES / "kin.oscillating_block.toml").read_text()
    text = "\n".join(line for line in text.splitlines() if not line.startswith(("find", "show")))
    text = 'find = ["R_12", "R_23", "R_43", "M_b"]\nshow = ["mechanism"]\n' + text + """
[forces]
gravity_m_s2 = 9.81

[[forces.mass]]
link = "2"
point = "D"
mass_kg = 2
inertia_kgm2 = 0.01
"""
    scene = parse_scene(tomllib.loads(text), "rpr.toml")
    lines, rows = steps(scene), check(scene)[0].rows
    r23 = {r.name: r for r in rows}["R_23"]
    bar = lines[_index(lines, "moments of the bar 2 about B and of the block 3 about C")]
    assert bar.endswith(f"R_23 = {num(r23.graphical)} N ⟂ the bar ({num(r23.drawn_mm)} mm at μF)")
    assert "R_12 closes the polygon, from the end of F_i2 back to o" in lines
    _check_rows(lines, rows)


def _check_blocks(lines: list[str], rows: list) -> None:
    """_check_rows, position by position where the scene has several."""
    if not any("@" in r.name for r in rows):
        _check_rows(lines, rows)
        return
    starts = [k for k, line in enumerate(lines) if "draw the kinematic diagram at" in line]
    scales = [k for k, line in enumerate(lines) if line.startswith("choose μF")]
    labels = sorted({r.name.partition("@")[2] for r in rows})
    assert len(starts) == len(scales) == len(labels) > 1
    assert all(a < b for a, b in zip(starts, scales))
    for k, start in enumerate(starts):  # each position's block reads its own rows
        block = lines[start:(starts + [len(lines)])[k + 1]]
        label = lines[start].rsplit(" = ", 1)[1].removesuffix("°")  # φ₁ = 300°, s₁ = 40
        mine = [r for r in rows if r.name.endswith(f"@{label}")]
        assert mine
        _check_rows(block, [_renamed(r) for r in mine])


def test_each_position_is_protocolled_in_turn():
    lines, rows = _protocol(FORCES / "rpp_loaded.toml")
    assert len(rows) == 4 * len({r.name.partition("@")[2] for r in rows})
    _check_blocks(lines, rows)


def _renamed(r):
    return replace(r, name=r.name.partition("@")[0])


def test_chinese_and_russian_wording(tmp_path):
    text = (SCENES / "force.sixbar_kinetostatic-friction.toml").read_text(encoding="utf-8")
    text = text.replace("[page]\n", '[page]\nnotation = "zh"\n', 1)
    zh = steps(parse_scene(tomllib.loads(text), "zh.toml"))
    assert "取力比例尺μF = 25 N/mm（题给）作力多边形" in zh
    assert "取杆组 4–5（构件4, 5）为分离体：已知力G_4, F_i4, G_5, F_i5, P_r, M_i4；待求R_34（作用于E）, 导路反力R_05" in zh
    assert any(line.startswith("过P_r的末端作直线与导路法线成φ = 5.711°（R_05的方向），过o点作直线∥ EF") for line in zh)
    assert any(line.startswith("由原动件1对A取矩：平衡力矩M_b = −ΣM_A = 135.5 N·m（逆时针）") for line in zh)
    ru = steps(parse_scene(tomllib.loads(text.replace('notation = "zh"', 'notation = "ru"')), "ru.toml"))
    assert "выбираем масштаб планов сил μF = 25 N/mm (задан)" in ru
    assert any(line.startswith("круг трения вокруг B: ρ = f_v·r = 0.15 × 0.015 = 0.00225 m") for line in ru)
    assert any(line.startswith("моменты начального звена 1 относительно A: уравновешивающий момент M_b") for line in ru)
    assert len(zh) == len(ru) == len(steps(load_scene(SCENES / "force.sixbar_kinetostatic-friction.toml")))


def test_the_cli_prints_it_numbered():
    code, out, err = run_cli("steps", str(SCENES / "force.sixbar_kinetostatic.toml"))
    lines = out.splitlines()
    assert code == 0 and err == ""
    assert [line.split(". ", 1)[0] for line in lines] == [str(k) for k in range(1, len(lines) + 1)]
    assert lines[-1].endswith(". ΣM_p = 72530 N·mm: M_b = μv·ΣM_p/ω₁ = 0.02 × 72530/12 = 120.9 N·m (M_b_lever)")


def test_a_prp_group_closes_on_the_two_guides_normals_and_the_bar_takes_its_reaction():
    lines, rows = _protocol(SCENES / "force.tangent_mechanism.toml")
    value = {r.name: r.graphical for r in rows}
    group = _index(lines, "free body of group 2–3 (links 2, 3)")
    assert "unknown R_12 from the guide, R_43 from the guide" in lines[group]
    close = _index(lines, "they meet at the polygon's closing vertex")
    assert "⟂ the guide (the line of R_43)" in lines[close] and "⟂ the guide AB (the line of R_12)" in lines[close]
    assert _index(lines, f"moments of slider 3 about C give where R_43 acts: M_43 = {num(value['M_43'])} N·m") > close
    pin = _index(lines, "measure R_32 = ")
    driver = _index(lines, "free body of driver 1: known G_1, F_i1, R_21, M_i1; unknown R_41 at A, M_b")
    assert group < close < pin < driver


def test_a_slot_on_a_moving_link_is_named_by_its_line():
    lines, _ = _protocol(FORCES / "slotted_link_pin.toml")
    assert "a line ⟂ the guide AB (the line of R_24)" in lines[_index(lines, "(the line of R_24)")]
    assert _index(lines, "free body of driver 2: known G_2, F_i2, R_42, M_i2; unknown R_12 at A, M_b") > 0
