"""The construction protocol of a flywheel scene (graphmech/problems/flywheel/steps.py): Jп and Mп at
the N positions, the scales, the integration by chords, the constant moment, ΔT, and J_F from the
Wittenbauer diagram's tangents or the energy indicator — every number the check table's."""
from __future__ import annotations

import tomllib

import pytest

from graphmech.problems import check, steps
from graphmech.problems.protocol import num
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES, run_cli


def _index(lines: list[str], text: str) -> int:
    found = [k for k, line in enumerate(lines) if text in line]
    assert found, (text, lines)
    return found[0]


def _protocol(name: str) -> tuple[list[str], list]:
    scene = load_scene(SCENES / f"{name}.toml")
    return steps(scene), check(scene)[0].rows


def test_the_compressor_is_protocolled_in_the_course_projects_order():
    lines, _ = _protocol("fly.compressor_course_project")
    order = [
        "divide the cycle Φ = 360° into N = 12 positions, Δφ = 30° (every value below read off these 12 positions)",
        "position 4 (φ = 90°): from its velocity polygon Jп = Σ(m·v_S² + J_S·ω²)/ω₁² = 0.0918 kg·m²",
        "choose μφ = 2.5 °/mm (chosen to fit the page), μM = 10 (N·m)/mm (chosen to fit the page) and the pole "
        "distance H = 30 mm (chosen to fit the page): μT = μM·μφ·H = 13.09 J/mm",
        "lay off the ordinates Mп/μM at φ/μφ and Jп/μJ (mm):",
        "integrate Mп by chords",
        "the ray from P parallel to it cuts the M axis at 5.294 mm: Md = 5.294 × 10 = 52.94 N·m",
        "ΔT at 9 = 16.45 mm: ΔT = 16.45 × 13.09 = 215.3 J",
        "the highest ordinate of ΔT is at position 9 (φ = 240°): 16.45 mm: DeltaT_max = 16.45 × 13.09 = 215.3 J",
        "draw the Wittenbauer diagram ΔT(Jп)",
        "tan ψmax = μJ·ωmax²/(2μT) = 0.002 × 102.5²/(2 × 13.09) = 0.8033: ψmax = 38.77°",
        "draw the upper tangent at ψmax touching the diagram (at position 8); it cuts the ΔT axis at k = −10.97 mm",
        "draw the lower tangent at ψmin touching the diagram (at position 3); it cuts the ΔT axis at l = −29.06 mm",
        "measure kl = 18.09 mm: J_F = μT·kl/(ω_m²·δ) = 13.09 × 18.09/(100.5² × 0.04) = 0.5859 kg·m²",
        "with this flywheel the equation of motion is integrated (not a construction): delta_achieved = 0.04301",
    ]
    at = [_index(lines, text) for text in order]
    assert at == sorted(at), at
    # N ordinates and N chords, one line each
    assert sum(line.startswith("position ") and ": x = " in line for line in lines) == 12
    assert sum(line.startswith("interval ") for line in lines) == 12
    # the chord polygon ends at Aп(Φ), the constant moment's work line runs to −Aп(Φ)
    assert lines[_index(lines, "interval 12–13 (= 1)")].endswith("Aп at 13 (= 1) = −25.41 mm")
    assert "straight line from the origin to −Aп(Φ) = 25.41 mm" in lines[_index(lines, "the constant moment's work")]


def _check_rows(lines: list[str], rows: list) -> None:
    """Every row's value (and drawn length) of the check table is in the protocol (4 s.f.)."""
    text = "\n".join(lines)
    for r in rows:
        assert f"{num(r.graphical)}" in text, (r.name, num(r.graphical))
        if r.drawn_mm is not None:
            assert f"{num(r.drawn_mm)} mm" in text, (r.name, num(r.drawn_mm))


@pytest.mark.parametrize("name", ["fly.compressor_course_project", "fly.ic_engine_flywheel",
                                  "fly.compressor_course_project-stiff"])
def test_every_number_read_is_the_check_tables(name):
    lines, rows = _protocol(name)
    assert len(rows) > 3
    _check_rows(lines, rows)


def test_the_energy_indicator_reads_delta_w_max_at_its_own_scale():
    lines, rows = _protocol("fly.ic_engine_flywheel")
    value = {r.name: r for r in rows}
    w = value["DeltaW_max"]
    assert (f"the highest and lowest points of the chain are c and b: measure {num(w.drawn_mm)} mm: "
            f"ΔW_max = {num(w.drawn_mm)} × {num(w.scale)} = {num(w.graphical)} J") in lines
    assert lines[_index(lines, "draw the energy indicator")].count(" mm") == 4  # a, b, c, a′
    jf = lines[_index(lines, "J_F = ΔW_max/(ω_m²·δ) − J_mean")]
    assert f"= {num(value['J_F'].graphical)} kg·m²" in jf
    assert "Mr = −11.67 × 10 = −116.7 N·m" in lines[_index(lines, "cuts the M axis at")]
    assert not any("Wittenbauer" in line for line in lines)


def test_chinese_and_russian_wording():
    text = (SCENES / "fly.ic_engine_flywheel.toml").read_text(encoding="utf-8")
    zh = steps(parse_scene(tomllib.loads(text.replace("[page]\n", '[page]\nnotation = "zh"\n')), "zh.toml"))
    assert zh[0] == "将一个周期Φ = 180°等分为N = 36个位置，Δφ = 5°（以下各值均由这36个位置求得）"
    assert any(line.startswith("用弦线法对Mп图解积分") for line in zh)
    assert any(line.startswith("指示图的最高点c、最低点b：量得43.63 mm") for line in zh)
    ru = steps(parse_scene(tomllib.loads(text.replace("[page]\n", '[page]\nnotation = "ru"\n')), "ru.toml"))
    assert ru[0].startswith("делим цикл Φ = 180° на N = 36 положений")
    assert any(line.startswith("строим диаграмму избыточных работ") for line in ru)
    assert len(zh) == len(ru) == len(steps(load_scene(SCENES / "fly.ic_engine_flywheel.toml")))


def test_the_cli_prints_it_numbered():
    code, out, err = run_cli("steps", str(SCENES / "fly.ic_engine_flywheel.toml"))
    lines = out.splitlines()
    assert code == 0 and err == ""
    assert [line.split(". ", 1)[0] for line in lines] == [str(k) for k in range(1, len(lines) + 1)]
    assert lines[-2:] == [f"{len(lines) - 1}. n_max = 65.25·30/π = 623.1 r/min",
                          f"{len(lines)}. n_min = 64.6·30/π = 616.9 r/min"]


def test_a_table_of_delta_t_is_read_off_not_integrated():
    """fly.energy_table: ΔT at the positions comes from its table; no moment, chord or pole step."""
    lines, _ = _protocol("fly.energy_table")
    order = [
        "position 2 (φ = 30°): Jп = 0.6019 kg·m², ΔT = −459.6 J (read off the scene's table of ΔT)",
        "position 8 (φ = 210°): Jп = 0.6032 kg·m², ΔT = 6401 J (read off the scene's table of ΔT)",
        "ΔT is given, so nothing is integrated (no μM, no pole)",
        "the highest ordinate of ΔT is at position 8 (φ = 210°): 58.73 mm: DeltaT_max = 58.73 × 109 = 6401 J",
        "it cuts the ΔT axis at k = 56.12 mm (6117 J)",
        "measure kl = 62.07 mm: J_F = μT·kl/(ω_m²·δ) = 109 × 62.07/(28² × 0.2) = 43.15 kg·m²",
    ]
    at = [_index(lines, text) for text in order]
    assert at == sorted(at)
    assert not [line for line in lines if "chord" in line or "Mп" in line or "ray from P" in line]
