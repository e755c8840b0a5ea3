"""The full cycle's construction protocol: positions, extreme positions, diagrams by chords, and
every value of the check table read as the table reads it."""
from __future__ import annotations

import tomllib

from graphmech.problems import check
from graphmech.problems.cycle.steps import cycle_steps
from graphmech.problems.protocol import num
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES, run_cli

CYCLE = SCENES / "linkage.slider_crank_offset-cycle.toml"


def test_every_value_of_the_check_table_is_in_the_protocol():
    for name in ("linkage.slider_crank_offset-cycle", "linkage.quick_return_timing", "fly.compressor_course_project-cycle",
                 "linkage.fourbar_28_52_50_72-cycle", "linkage.grashof_ranges"):
        scene = load_scene(SCENES / f"{name}.toml")
        text = "\n".join(cycle_steps(scene))
        an, _, _, lines = check(scene)
        for row in an.rows:
            assert f"{row.name} = " in text and num(row.graphical) in text, (name, row.name)
        assert all(line in text for line in lines)


def test_the_sheet_is_drawn_in_the_books_order():
    lines = cycle_steps(load_scene(CYCLE))
    starts = ("choose μl", "divide the crank's turn into 12 positions from φ₁ = 4.301°", "the extreme positions",
              "the diagrams against φ", "read s_C@4 = −22.92 mm × 0.005 = −0.1146 m")
    order = [next(k for k, line in enumerate(lines) if line.startswith(s)) for s in starts]
    assert order == sorted(order)
    assert "read v_C_diagram@3.5 = −28.26 mm × 0.03581 = −1.012 m/s ±1.4 % (12 positions)" in lines


def test_the_protocol_speaks_the_scenes_notation():
    for notation, words in (("zh", "极位夹角θ"), ("ru", "крайние положения")):
        data = tomllib.loads(CYCLE.read_text(encoding="utf-8"))
        data.setdefault("page", {})["notation"] = notation
        assert any(words in line for line in cycle_steps(parse_scene(data, "x.toml"))), notation


def test_the_command_prints_it_numbered():
    code, out, _ = run_cli("steps", str(SCENES / "linkage.quick_return_timing.toml"))
    assert code == 0 and out.splitlines()[3] == "4. K = 1.4"


def test_a_swing_is_laid_out_out_and_back_not_as_a_turn():
    lines = cycle_steps(load_scene(SCENES / "linkage.rocker_swing.toml"))
    assert lines[1].startswith("the driver swings from −97.9° to 97.9° (its limits: the dyad on its point toggles")
    assert "12 positions, 1 … 7 out" in lines[1] and "k and 14 − k are one place" in lines[1]
    stroke = cycle_steps(load_scene(SCENES / "linkage.slider_stroke.toml"))
    assert stroke[1].startswith("the driver swings from 20 mm to 120 mm: 8 positions, 1 … 5 out")
    assert not any("crank's turn" in line for line in lines + stroke)
