"""The construction protocol of a synthesis scene (graphmech/problems/synthesis/steps.py): θ from K,
the construction with every length drawn, each design measured — every number the check table's."""
from __future__ import annotations

import pytest

from graphmech.problems import check, steps
from graphmech.problems.protocol import num
from graphmech.scene import load_scene
from tests.conftest import SCENES, run_cli
from tests.scenes import parse_text, scene_text

BANK = SCENES / "linkage.crank_rocker_synthesis_K1.5.toml"


def test_the_banks_protocol_reads_the_check_tables_numbers():
    scene = load_scene(BANK)
    lines, rows = steps(scene), {r.name: r for r in check(scene)[0].rows}
    assert lines[0] == "θ = 180°(K − 1)/(K + 1) = 180° × (1.5 − 1)/(1.5 + 1) = 36°"
    for k in (1, 2):
        line = next(x for x in lines if x.startswith(f"sol{k}: measure"))
        for n in ("AC1", "AC2"):
            assert f"{num(rows[f'sol{k}_{n}'].drawn_mm)} mm" in line
        for n in ("lAB", "lBC"):
            assert f"= {num(rows[f'sol{k}_{n}'].graphical)} m" in line
        assert f"check sol{k}: re-analysed, K = 1.5, ψ = {num(rows[f'sol{k}_psi'].exact)}°" in lines[-3 + k]


@pytest.mark.parametrize("text, words", [
    (scene_text("synthesis/swing"), "the θ-circle: from C₁ a line at 90° − θ = 60°"),
    ('[synthesis]\ntask = "time_ratio"\nmechanism = "slider_crank"\nK = 1.5\nstroke_mm = 50\noffset_mm = 10\n',
     "the line at the offset e = 0.01/μl = 10 mm"),
    ('[synthesis]\ntask = "time_ratio"\nmechanism = "guide_bar"\nK = 2\nframe_mm = 300\nstroke_mm = 400\n',
     "measure CD₂ = 80 mm: l_CD = 0.4 m"),
])
def test_each_mechanism_has_its_construction_in_words(text, words):
    lines = steps(parse_text(text))
    assert any(words in x for x in lines), lines
    assert lines[-1].startswith("check design: re-analysed")


def test_the_protocol_is_worded_in_the_scenes_notation():
    text = BANK.read_text(encoding="utf-8") + '\n[page]\nnotation = "zh"\n'
    lines = steps(parse_text(text))
    assert lines[0].startswith("极位夹角 θ") and "摇杆圆" in lines[4]


def test_graphmech_steps_prints_it_numbered():
    code, out, err = run_cli("steps", str(BANK))
    assert (code, err) == (0, "") and out.startswith("1. θ = 180°(K − 1)/(K + 1)")
