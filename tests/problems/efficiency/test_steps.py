"""The protocol of an efficiency scene (graphmech/problems/efficiency/steps.py): chains walked
stage by stage, force polygons laid off and closed with their lengths, η and the self-locking
limits — every number the check table's."""
from __future__ import annotations

import tomllib

import pytest

from graphmech.problems import check, steps
from graphmech.problems.protocol import num
from graphmech.scene import load_scene
from graphmech.scene import parse_scene as parse
from tests.conftest import SCENES, run_cli


def parse_scene(text: str, source: str = "e.toml"):
    return parse(tomllib.loads(text), source)


def _anchor(name: str, multi: bool) -> tuple[str, str]:
    """(the stroke's heading or "", the text of the line the row's reading is in)."""
    base, _, at = name.partition("@")
    head = {"forward": "the forward stroke", "reverse": "the reverse stroke"}.get(at, "")
    line = {"eta": "η = F₀/F = " if at != "reverse" else "η′ = F/F₀ = ", "F": "measure F: ", "F0": "measure F₀: ",
            "R": "measure R: ", "R12": "measure R₁₂: ", "R32": "measure R₃₂: ", "R31": "measure R₃₁: ",
            "M": "M = F·d₂/2", "phi": "friction angle", "phi_v": "friction angle", "psi": "ψ = ",
            "r_f": "r_f = ", "sigma": "σ = ", "gamma_limit": "self-locking limit γ", "P_in": "P_in = P_out/η = ",
            "P_out": "P_out = Q·v", "self_locking_angle": "self-locking limit ψ",
            "eta_self_locking_max": "the forward η there"}[base]
    if base == "eta" and not at and not multi:
        line = "η = " if name == "eta" else line
    return head, line


def _agrees(lines: list[str], rows: list, multi: bool) -> None:
    for r in rows:
        head, text = _anchor(r.name, multi)
        start = next(k for k, x in enumerate(lines) if head in x and "with friction" in x) if head else 0
        if r.name.startswith(("F0", "R")) or r.name.partition("@")[0] == "F":
            # the reading with friction (F0: the frictionless polygon's)
            start = start if r.name.startswith("F0") else next(
                (k for k, x in enumerate(lines) if k >= start and "with friction" in x), start)
        line = next(x for x in lines[start:] if text in x)
        assert _has(line, num(r.graphical)), (r.name, r.graphical, line)
        if r.drawn_mm is not None:
            assert f"{num(abs(r.drawn_mm))} mm" in line, (r.name, r.drawn_mm, line)


def _has(line: str, number: str) -> bool:
    import re

    return re.search(rf"(?<![\d.]){re.escape(number)}(?![\d])", line) is not None


@pytest.mark.parametrize("name", ["force.wedge_F1430", "thread.m8_bolt_tightening_partial",
                                  "thread.self_locking_efficiency_bound", "thread.m20_lead_angles-coarse",
                                  "eff.belt_conveyor_chain", "eff.belt_conveyor_chain-book"])
def test_every_number_read_is_the_check_tables(name):
    scene = load_scene(SCENES / f"{name}.toml")
    rows = check(scene)[0].rows
    assert rows
    _agrees(steps(scene), rows, len(getattr(scene.problem, "directions", ())) > 1)


def test_the_wedge_is_two_polygons_joined_along_r12_per_stroke():
    lines = steps(load_scene(SCENES / "force.wedge_F1430.toml"))
    assert lines[0] == "the friction angle: φ = arctan f = arctan 0.15 = 8.531°"
    assert lines[1] == "choose μF = 25 N/mm (as the scene gives it)"
    k = lines.index("the forward stroke (F drives), with friction: turn each total reaction from its normal by φ "
                    "against the relative velocity; the polygon of slider 2")
    assert lines[k + 1:k + 10] == [
        "from o lay off Q = 1000 N: 1000/μF = 40 mm at 180° to the x axis",
        "through its end draw a line ∥ R₃₂ (98.53° to the x axis), through the start a line ∥ R₁₂ (141.5°); they meet",
        "measure R₃₂: 36.58 mm × 25 = 914.4 N",
        "measure R₁₂: 58.07 mm × 25 = 1452 N",
        "the forward stroke (F drives), with friction: turn each total reaction from its normal by φ against the "
        "relative velocity; the polygon of slider 1",
        "reuse the side R₁₂ of the previous polygon, reversed: R₂₁ = −R₁₂",
        "through its end draw a line ∥ F (120° to the x axis), through the start a line ∥ R₃₁ (38.53°); they meet",
        "measure F: 57.23 mm × 25 = 1431 N",
        "measure R₃₁: 21.49 mm × 25 = 537.3 N",
    ]
    assert lines[k + 10] == "η = F₀/F = 1000/1431 = 0.699"
    assert lines[-1] == "redraw the reverse polygon at steeper angles until η′ = 0: the self-locking limit γ = 17.06°"


def test_a_screw_at_its_self_locking_limit():
    lines = steps(load_scene(SCENES / "thread.self_locking_efficiency_bound.toml"))
    assert lines[1] == "at the self-locking limit the lead angle is ψ = φv = 5.711°"
    # F is drawn 0 mm long: its line is still the one F has in the other polygons
    assert "through its end draw a line ∥ F (0° to the x axis), through the start a line ∥ R (90°); they meet" in lines
    assert "η′ = F/F₀ = 0/100 = 0 ≤ 0: self-locking" in lines
    assert lines[-1] == "the forward η there: η = 0.495 (< 0.5: a self-locking screw wastes half its work or more)"


def test_a_steep_incline_self_locks_forward():
    # α + φ > 90°: no horizontal push, however large, drives the block up (F comes out negative)
    lines = steps(parse_scene("""
find = ["F@forward", "eta@forward"]
[efficiency]
type = "incline"
angle_deg = 85
f = 0.1
load_N = 1000
push = "horizontal"
"""))
    assert lines[0].startswith("choose μF = ") and lines[0].endswith("(chosen to fit the page)")
    assert lines[1] == "the forward stroke (F drives), without friction: the polygon of the block"
    eta = next(x for x in lines if x.startswith("η = F₀/F = "))
    assert eta.endswith(" ≤ 0: self-locking") and "= −" in eta
    assert not any("reverse" in x for x in lines)  # not asked for


def test_a_chain_is_walked_from_the_output_back_to_the_motor():
    lines = steps(load_scene(SCENES / "eff.belt_conveyor_chain-book.toml"))
    assert lines == [
        "the output power: P_out = Q·v = 5500 N × 1.2 m/s = 6600 W",
        "stage V-belt: η₁ = 0.95",
        "stage gear pair: η₂ = 0.97 × 0.97 = 0.9409",
        "stage conveyor: η₃ = 0.92",
        "machines in series: η = 0.95 × 0.9409 × 0.92 = 0.8223",
        "stage conveyor: P_in = P_out/η₃ = 6600/0.92 = 7174 W",
        "stage gear pair: P_in = P_out/η₂ = 7174/0.9409 = 7625 W",
        "stage V-belt: P_in = P_out/η₁ = 7625/0.95 = 8026 W",
        "the motor's power: P_in = P_out/η = 6600/0.8223 = 8026 W",
    ]
    parallel = steps(parse_scene("""
find = ["eta"]
[efficiency]
type = "chain"
load_N = 1000
speed_m_s = 1
[[efficiency.stage]]
name = "split"
[[efficiency.stage.branch]]
share = 0.6
eta = [0.9, 0.95]
[[efficiency.stage.branch]]
share = 0.4
eta = [0.8]
"""))
    assert parallel[1] == "stage split: η₁ = (0.6 × 0.9 × 0.95 + 0.4 × 0.8)/1 = 0.833"


def test_chinese_and_russian_wording():
    text = (SCENES / "thread.m8_bolt_tightening_partial.toml").read_text(encoding="utf-8") + \
        '\n[page]\nnotation = "{}"\n'
    zh = steps(parse_scene(text.replace("{}", "zh")))
    assert zh[0] == "当量摩擦角：φv = arctan f_v = arctan 0.1 = 5.711°"
    assert "正行程（F为驱动力），计摩擦：各总反力偏离法线φ角，偏向与相对速度相反的一侧；滑块的力多边形" in zh
    assert "量得F：7.967 mm × 500 = 3984 N" in zh
    ru = steps(parse_scene(text.replace("{}", "ru")))
    assert ru[4] == "выбираем μF = 500 N/mm (задан)"
    assert "измеряем F: 7.967 mm × 500 = 3984 N" in ru
    assert ru[-1] == "движущий момент: M = F·d₂/2 = 7.967 mm × 500 × 0.003594 = 14.32 N·m"
    assert len(zh) == len(ru) == 17


def test_the_cli_prints_it_numbered():
    code, out, err = run_cli("steps", str(SCENES / "eff.belt_conveyor_chain-book.toml"))
    lines = out.splitlines()
    assert code == 0 and err == "" and len(lines) == 9
    assert lines[4] == "5. machines in series: η = 0.95 × 0.9409 × 0.92 = 0.8223"
