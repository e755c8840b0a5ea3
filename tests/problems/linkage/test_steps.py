"""The construction protocol of a linkage scene (graphmech/problems/linkage/steps.py): the steps in
the book's order, worded in the scene's notation, every number the one the check table (and so
the drawing) has."""
from __future__ import annotations

import re
import tomllib

import pytest

from graphmech.drawing.lettering import number
from graphmech.problems import check, steps
from graphmech.problems.linkage.steps import symbol
from graphmech.problems.protocol import num
from graphmech.scene import load_scene
from graphmech.scene import parse_scene as parse
from tests.conftest import SCENES, fourbar_scene


def parse_scene(text: str, source: str):
    return parse(tomllib.loads(text), source)


def _protocol(name: str) -> tuple[list[str], list]:
    scene = load_scene(SCENES / f"{name}.toml")
    return steps(scene), check(scene)[0].rows


def _index(lines: list[str], text: str) -> int:
    found = [k for k, line in enumerate(lines) if text in line]
    assert found, (text, lines)
    return found[0]


def test_the_oscillating_block_is_protocolled_in_the_books_order():
    lines, _ = _protocol("kin.oscillating_block")
    order = [
        "choose μl = 0.002 m/mm (as the scene gives it) and draw the kinematic diagram at φ₁ = 45°",
        "draw the crank AB at φ₁ = 45°: AB = l_AB/μl = 0.03/0.002 = 15 mm",
        "choose μv = 0.005 (m/s)/mm (as the scene gives it) and mark the pole p of the velocity polygon",
        "from p lay off pb ⟂ AB in the sense of ω₁ (counter-clockwise): pb = ω₁·l_AB/μv = 10 × 0.03/0.005 = 60 mm",
        "through b draw a line ⟂ BC",
        "through p draw a line ∥ BC",
        "c₂ = the intersection of the two lines: pc₂ = 34.48 mm, bc₂ = 49.11 mm",
        "draw △bc₂d ∼ △BC₂D, the letters in the same order (velocity image): d:",
        "choose μa = 0.05 (m/s²)/mm",
        "from p′ lay off p′b′ ∥ BA, from B towards A: p′b′ = ω₁²·l_AB/μa = 10² × 0.03/0.05 = 60 mm (a_B = 3 m/s²)",
        "from b′ lay off b′n₂′ ∥ C₂B, from C₂ towards B: b′n₂′ = ω₂²·l_C2B/μa = 1.995² × 0.1231/0.05 = 9.798 mm",
        "through n₂′ draw a line ⟂ BC₂ (the direction of a^t_C2B)",
        "from p′ lay off p′k′ = a^k_C2C3 = 2ω₂·v_C2C3/μa = 2 × 1.995 × 0.1724/0.05 = 13.76 mm, v_C2C3 turned 90°",
        "through k′ draw a line ∥ BC (the direction of a^r_C2C3)",
        "c₂′ = the intersection of the two lines: p′c₂′ = 41.65 mm, k′c₂′ = 39.31 mm, n₂′c₂′ = 20.72 mm",
        "measure n₂′c₂′ = 20.72 mm: α₂ = n₂′c₂′·μa/l_BC = 20.72 × 0.05/0.1231 = −8.419 rad/s² (clockwise)",
        "measure p′e′ = 56.68 mm: a_E = p′e′·μa = 2.834 m/s²",
    ]
    at = [_index(lines, text) for text in order]
    assert at == sorted(at), at
    assert lines[0] == order[0] and len(lines) == 31


def _measure_lines(lines: list[str], rows: list, multi: bool, labels: tuple[str, ...]) -> None:
    """Every row the scene finds has its measurement in the protocol, with the check's numbers."""
    starts = [k for k, line in enumerate(lines) if "draw the kinematic diagram at" in line]
    for r in rows:
        base, _, at = r.name.partition("@")
        block = lines[starts[labels.index(at)]:][: (starts + [len(lines)])[labels.index(at) + 1] - starts[labels.index(at)]] \
            if multi else lines
        sym = symbol(base)
        mine = [line for line in block if f": {sym} = " in line or f"：{sym} = " in line]
        assert mine, (r.name, block)
        line = mine[0]
        assert f"= {num(r.graphical)} " in line or line.endswith(f"= {num(r.graphical)}°"), (r, line)
        if r.drawn_mm is not None:
            assert f" = {num(abs(r.drawn_mm))} mm" in line, (r, line)
            # to the printed precision: four significant figures of the drawn length and the value
            assert float(num(abs(r.drawn_mm)).replace("−", "-")) == pytest.approx(abs(r.drawn_mm), rel=5e-4)


@pytest.mark.parametrize("name", ["kin.oscillating_block", "linkage.slider_crank_offset", "kin.oscillating_block-zh"])
def test_every_number_read_is_the_check_tables(name):
    scene = load_scene(SCENES / f"{name}.toml")
    an = check(scene)[0]
    _measure_lines(steps(scene), an.rows, len(an.labels) > 1, an.labels)


def test_the_laid_off_lengths_are_the_drawings():
    # v_C2C3 = pc₂·μv is the check's; the Coriolis step uses the same ω₂ and v_C2C3 the check reads
    lines, rows = _protocol("kin.oscillating_block")
    value = {r.name: r for r in rows}
    cor = lines[_index(lines, "p′k′ = a^k_C2C3 = 2ω₂")]
    assert f"2 × {num(value['omega_2'].graphical)} × {num(value['v_C2C3'].graphical)}/0.05 = " \
           f"{num(value['a_k_C2C3'].drawn_mm)} mm" in cor
    diagram = lines[_index(lines, "measure BC = ")]
    assert diagram == f"measure BC = {num(value['l_BC'].drawn_mm)} mm: l_BC = BC·μl = {num(value['l_BC'].graphical)} m"


def test_each_position_is_protocolled_in_turn():
    lines, _ = _protocol("linkage.slider_crank_offset")
    first, second = _index(lines, "at φ₁ = 50°"), _index(lines, "at φ₁ = 220°")
    assert first == 0 and second == 20
    assert lines[3].startswith("draw the guide of C through x = 0 mm, y = 6 mm at 0° to the x axis; an arc about B "
                               "with radius BC = 60 mm meets it at C")
    assert "v_C = pc·μv = −0.8671 m/s (pc points against the guide's direction)" in lines[11]


def test_chinese_and_russian_wording():
    zh, _ = _protocol("kin.oscillating_block-zh")
    assert zh[0] == "取μl = 0.002 m/mm（题给），作φ₁ = 45°时的机构运动简图"
    assert "任取极点p作速度多边形" in zh[7] and zh[9] == "过b作BC的垂线"
    assert zh[11].startswith("两线交于c₂：pc₂ = 34.48 mm，bc₂ = 49.11 mm")
    assert any(line.startswith("根据加速度影像原理，作△b′c₂′d′ ∽ △BC₂D") for line in zh)
    assert any(line.startswith("量得p′e′ = 56.68 mm：a_E = p′e′·μa = 2.834 m/s²") for line in zh)
    text = (SCENES / "kin.oscillating_block-zh.toml").read_text(encoding="utf-8").replace('notation = "zh"',
                                                                                         'notation = "ru"')
    ru = steps(parse_scene(text, "ru.toml"))
    assert ru[0] == "выбираем μl = 0.002 m/mm (задан) и строим кинематическую схему при φ₁ = 45°"
    assert ru[9] == "через точку b проводим прямую ⟂ BC" and "полюс p плана скоростей" in ru[7]
    assert any(line.startswith("измеряем pd = 45.15 mm: v_D = pd·μv = 0.2258 m/s") for line in ru)
    assert len(ru) == len(zh) == 31


def test_only_what_find_asks_for_is_protocolled():
    lines = steps(parse_scene(fourbar_scene(find='["v_C"]'), "f.toml"))
    assert not any("acceleration" in line or "ω₂ =" in line for line in lines)
    assert lines[-1].startswith("measure pc = ") and "v_C = pc·μv = " in lines[-1]
    more = steps(parse_scene(fourbar_scene(find='["alpha_3"]', epsilon=5), "f.toml"))
    crank = [line for line in more if line.startswith("from p′ lay off p′b′ = a_B")]
    assert len(crank) == 1 and "ε₁·l_AB/μa" in crank[0]
    assert "ω₃ = " in more[_index(more, "measure pc = ")] and more[-1].startswith("measure ")


def test_a_scene_that_asks_nothing_gets_the_panels_it_shows():
    lines = steps(parse_scene(fourbar_scene(find="[]", show='["mechanism", "velocity"]'), "f.toml"))
    assert lines[-1].startswith("c = the intersection of the two lines: pc = ") and not any("μa" in x for x in lines)


def test_instant_centres_are_protocolled_with_kennedys_lines():
    lines, rows = _protocol("kin.fourbar_instant_centres")
    assert "P13 = (line P12P23) ∩ (line P14P34) by Kennedy's theorem: x = 85.18 mm, y = −22.82 mm" in lines
    value = {r.name: r for r in rows}
    w3 = value["omega_3_ic"]
    assert f"read off the drawing: ω_3_ic = {num(w3.drawn_mm)} mm × {num(w3.scale)} = {num(w3.graphical)} rad/s" in lines
    assert lines[-1] == f"read off the drawing: phi_v0_C_2 = {num(value['phi_v0_C_2'].graphical)}°"


def test_numbers_are_written_as_the_drawing_writes_them():
    assert num(-8.418688) == number(-8.418688) == "−8.419"
    assert re.fullmatch(r"ω₂|ε₃", symbol("omega_2")) and symbol("a_CB_t") == "a^t_CB"


def test_a_class_iii_group_is_protocolled_by_assurs_point():
    lines, rows = _protocol("kin.class_iii_sixbar")
    order = [
        "draw the crank AB at φ₁ = 60°",
        "the class III group B-C, F-D, G-E (CDE): C, D, E where all three binary links fit the ternary link",
        "mark C: BC = 37.5 mm",
        "extend BC and FD: they meet at S, Assur's special point of the ternary link",
        "through b draw a line ⟂ BC",
        "through p draw a line ⟂ FD",
        "s = the intersection of the two lines",
        "through s draw a line ⟂ SE",
        "e = the intersection of the two lines",
        "draw △sec ∼ △SEC, the letters in the same order (velocity image): c:",
        "from n₂′ lay off n₂′σ₁′ ∥ SC, from S towards C",
        "s′ = the intersection of the two lines",
        "from s′ lay off s′n₃′ ∥ ES, from E towards S",
        "draw △s′e′c′ ∼ △SEC, the letters in the same order (acceleration image): c′:",
    ]
    at = [_index(lines, text) for text in order]
    assert at == sorted(at), at
    assert len(rows) == 14
