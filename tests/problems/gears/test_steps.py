"""The construction protocol of a gear scene (graphmech/problems/gears/steps.py): the circles, the
involute by points, the line of action and B₁B₂, every number the check table's."""
from __future__ import annotations

import pytest

from graphmech.problems import check, steps
from graphmech.problems.protocol import num
from graphmech.scene import load_scene
from tests.conftest import SCENES, run_cli


@pytest.mark.parametrize("name", ["gear.involute_z20_m8", "gear.contact_ratio_19_42",
                                  "gear.root_circle_equals_base_circle"])
def test_every_row_is_read_in_the_protocol(name):
    scene = load_scene(SCENES / f"{name}.toml")
    lines, rows = steps(scene), check(scene)[0].rows
    assert len(rows) >= 3
    for r in rows:
        line = next(x for x in lines if x.startswith(("read " + r.name + " ", r.name + " = ")))
        assert num(r.graphical) in line, (r.name, line)
        if r.drawn_mm is not None and r.scale != 1.0:
            assert f"{num(r.drawn_mm)} mm" in line, (r.name, line)


def test_the_pair_protocol_draws_the_line_of_action_then_the_zones():
    lines = steps(load_scene(SCENES / "gear.contact_ratio_19_42.toml"))
    first = lambda words: next(i for i, x in enumerate(lines) if words in x)
    assert first("d = mz = 95 mm") < first("O₁O₂ = a′ = 152.5 mm") < first("cuts N₁N₂ at B₂") < first("p_b = 14.76 mm")
    assert lines[-1] == "ε = B₁B₂/p_b = 1.633"


def test_the_protocol_in_chinese(tmp_path):
    p = tmp_path / "g.toml"
    p.write_text((SCENES / "gear.contact_ratio_19_42.toml").read_text(encoding="utf-8") + '\n[page]\nnotation = "zh"\n',
                 encoding="utf-8")
    code, out, err = run_cli("steps", str(p))
    assert code == 0, err
    assert "作O₁O₂ = a′ = 152.5 mm" in out and "两对齿啮合区" in out


def test_the_shift_design_comes_before_the_circles_it_gives():
    lines = steps(load_scene(SCENES / "gear.profile_shifted_12_12_a130.toml"))
    first = lambda words: next(i for i, x in enumerate(lines) if words in x)
    assert first("120 mm < a′ = 130 mm: a positive drive") < first("x₁ + x₂ = 1.25") \
        < first("Δy = x₁ + x₂ − y = 0.2505") < first("d_a = 147.5 mm")
    repair = steps(load_scene(SCENES / "gear.repair_shift_17_118.toml"))
    assert repair[0].startswith("the wheel re-cut 0.75 mm thinner: x₂ = −Δs/(2m·tan α) = −0.2061")
    assert any("equal and opposite" in x for x in repair)


def test_the_least_shift_and_the_drive_in_chinese(tmp_path):
    p = tmp_path / "g.toml"
    p.write_text('[gear]\nm_mm = 4\nz = 15\nx = "least"\n[page]\nnotation = "zh"\n', encoding="utf-8")
    code, out, err = run_cli("steps", str(p))
    assert code == 0, err
    assert "不根切：x ≥ x_min = h*a(z_min − z)/z_min = 0.1176（z_min = 17）" in out
    p.write_text((SCENES / "gear.profile_shifted_12_12_a130.toml").read_text(encoding="utf-8")
                 .replace('size = "A4-portrait"', 'size = "A4-portrait"\nnotation = "zh"'), encoding="utf-8")
    code, out, err = run_cli("steps", str(p))
    assert code == 0, err
    assert "故为正传动" in out and "齿顶降低 Δy·m = 2.505 mm" in out


@pytest.mark.parametrize("name", ["gear.rack_cutter_generation_cases-1", "gear.rack_cutter_generation_cases-3"])
def test_a_generation_scene_has_a_protocol_with_its_scale(name):
    """The generation panel's μl is chosen in the protocol like the others' (it was a KeyError)."""
    lines = steps(load_scene(SCENES / f"{name}.toml"))
    assert any(x.startswith("choose") and x.endswith(" for the generation") for x in lines), lines
