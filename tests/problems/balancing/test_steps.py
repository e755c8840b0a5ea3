"""The construction protocol of a balancing scene (graphmech/problems/balancing/steps.py): the
mass-radius products, their shares in the correction planes, each polygon laid off and closed,
every number the check table's."""
from __future__ import annotations

import tomllib

import pytest

from graphmech.problems import check, steps
from graphmech.problems.protocol import num
from graphmech.scene import load_scene
from graphmech.scene import parse_scene as parse
from tests.conftest import SCENES, run_cli
from tests.scenes import scene_text


def parse_scene(text: str, source: str = "b.toml"):
    return parse(tomllib.loads(text), source)


#: The line each row's reading is in.
ANCHOR = {"W_b": "the closing side W_b,", "m_b": "m_b = ", "theta_b": "θ_b = ",
          "W_I": "the closing side W_bᴵ,", "m_I": "m_bᴵ = ", "theta_I": "θ_bᴵ = ",
          "W_II": "the closing side W_bᴵᴵ,", "m_II": "m_bᴵᴵ = ", "theta_II": "θ_bᴵᴵ = ",
          "residual_force": "|Σ mᵢrᵢ| = ", "residual_moment": "|Σ mᵢrᵢzᵢ|",
          "W_b1": "W_b1 = ", "W_b2": "W_b2 = ", "m_b1": "m_b1 = ", "m_b2": "m_b2 = ", "F_unbalanced": "F = ω²"}


@pytest.mark.parametrize("name", ["bal.disc_static", "bal.rotor_dynamic", "bal.split_two_directions",
                                  "bal.rotor_centrifugal"])
def test_every_number_read_is_the_check_tables(name):
    scene = load_scene(SCENES / f"{name}.toml")
    lines, rows = steps(scene), check(scene)[0].rows
    assert len(rows) >= 4
    for r in rows:
        line = next(x for x in lines if ANCHOR[r.name] in x)
        assert f"= {num(r.graphical)} " in line or f"= {num(r.graphical)}°" in line, (r.name, line)
        if r.drawn_mm is not None:
            assert f"{num(r.drawn_mm)} mm" in line, (r.name, line)


def test_the_static_polygon_is_laid_off_head_to_tail_and_closed():
    lines = steps(load_scene(SCENES / "bal.disc_static.toml"))
    assert lines == [
        "mass m₁: W₁ = m₁·r₁ = 5 kg × 0.1 m = 0.5 kg·m, at θ₁ = 90°",
        "mass m₂: W₂ = m₂·r₂ = 7 kg × 0.2 m = 1.4 kg·m, at θ₂ = 0°",
        "mass m₃: W₃ = m₃·r₃ = 8 kg × 0.15 m = 1.2 kg·m, at θ₃ = 270°",
        "mass m₄: W₄ = m₄·r₄ = 10 kg × 0.1 m = 1 kg·m, at θ₄ = 180°",
        "choose μW = 0.05 (kg·m)/mm (as the scene gives it)",
        "the mass-radius polygon: from o lay the products off head to tail, each ∥ its mass's radius",
        "from o lay off W₁ = 0.5/μW = 10 mm at 90° to the x axis",
        "from the end of W₁ lay off W₂ = 1.4/μW = 28 mm at 0° to the x axis",
        "from the end of W₂ lay off W₃ = 1.2/μW = 24 mm at 270° to the x axis",
        "from the end of W₃ lay off W₄ = 1/μW = 20 mm at 180° to the x axis",
        "the closing side W_b, from the end of W₄ back to o: measure 16.12 mm: W_b = 16.12 × 0.05 = 0.8062 kg·m",
        "the correction mass at r_b = 0.15 m: m_b = W_b/r_b = 16.12 mm × 0.05/0.15 = 5.375 kg",
        "measure the direction of W_b from the x axis: θ_b = 119.7° — the correction mass goes there",
        "check: with the correction masses added, |Σ mᵢrᵢ| = 2.483×10⁻¹⁶ kg·m — the force polygon closes",
    ]


def test_the_dynamic_products_are_shared_between_the_planes_before_the_polygons():
    lines = steps(load_scene(SCENES / "bal.rotor_dynamic.toml"))
    assert lines[4] == "the correction planes: I at z = 0 m, II at z = 0.9 m, Δ = z_II − z_I = 0.9 m"
    assert lines[6] == ("resolve W₂ (z₂ = 0.3 m) into the planes: W₂ᴵ = W₂·(z_II − z₂)/Δ = 3 kg·m, "
                        "W₂ᴵᴵ = W₂·(z₂ − z_I)/Δ = 1.5 kg·m")
    first = lines.index("the mass-radius polygon of plane I: from o lay the products off head to tail, each ∥ "
                        "its mass's radius")
    second = next(k for k, x in enumerate(lines) if x.startswith("the mass-radius polygon of plane II"))
    assert first < second and "W₄ᴵ = 0: nothing to lay off" in lines[first:second]
    assert lines[second + 1] == "W₁ᴵᴵ = 0: nothing to lay off"
    assert lines[second + 2] == "from o lay off W₂ᴵᴵ = 1.5/μW = 15 mm at 270° to the x axis"


def test_a_reversed_share_is_laid_off_the_other_way():
    lines = steps(parse_scene("""
find = ["W_I", "theta_I"]
[balancing]
type = "dynamic"
planes_mm = [0, 100]
correction_radius_mm = [50, 60]
[[balancing.mass]]
m_kg = 1
r_mm = 100
angle_deg = 0
z_mm = 150
"""))
    assert "W₁ᴵ < 0: it is laid off reversed, at θ + 180°" in lines
    assert "from o lay off W₁ᴵ = 0.05/μW = " in lines[lines.index("W₁ᴵ < 0: it is laid off reversed, at θ + 180°") + 3]
    assert any(x.endswith("at 180° to the x axis") and x.startswith("from o lay off W₁ᴵ") for x in lines)
    assert "measure the direction of W_bᴵ from the x axis: θ_bᴵ = 0° — the correction mass goes there" in lines
    assert not any("m_bᴵ = " in x or "θ_bᴵᴵ" in x or "|Σ" in x for x in lines)  # not asked for


def test_a_balanced_rotor_says_its_polygon_closes():
    lines = steps(parse_scene(scene_text("balancing/balanced_opposite")))
    assert lines[-2] == "the polygon closes by itself: W_b = 0, no correction mass needed"
    assert not any("θ_b" in x for x in lines)


def test_chinese_and_russian_wording():
    text = (SCENES / "bal.rotor_dynamic.toml").read_text(encoding="utf-8") + '\n[page]\nnotation = "{}"\n'
    zh = steps(parse_scene(text.replace("{}", "zh")))
    assert zh[0] == "质量m₁：质径积W₁ = m₁·r₁ = 10 kg × 0.4 m = 4 kg·m，方向θ₁ = 155°"
    assert "作质径积矢量多边形（平衡平面I）：自o点起将各质径积首尾相接依次画出，方向与各质量的向径一致" in zh
    assert "由W₃ᴵ的末端指向o点的封闭矢量即W_bᴵ：量得27.83 mm，W_bᴵ = 27.83 × 0.1 = 2.783 kg·m" in zh
    ru = steps(parse_scene(text.replace("{}", "ru")))
    assert ru[9] == "выбираем μW = 0.1 (kg·m)/mm (задан)"
    assert "строим план векторов дисбалансов плоскости II" in ru[18]
    assert any(x.startswith("измеряем угол W_bᴵᴵ с осью x: θ_bᴵᴵ = 143.9°") for x in ru)
    assert len(zh) == len(ru) == 28


def test_the_cli_prints_it_numbered():
    code, out, err = run_cli("steps", str(SCENES / "bal.disc_static.toml"))
    lines = out.splitlines()
    assert code == 0 and err == "" and len(lines) == 14
    assert lines[10] == "11. the closing side W_b, from the end of W₄ back to o: measure 16.12 mm: W_b = 16.12 × 0.05 = " \
                        "0.8062 kg·m"


def test_the_split_and_the_centrifugal_force_are_constructed_in_words():
    lines = steps(load_scene(SCENES / "bal.split_two_directions.toml"))
    assert lines[-1] == ("split W_b along the given directions α₁ = 180° and α₂ = 270°: through the start of W_b draw "
                         "a line ∥ α₁, through o a line ∥ α₂; they meet at K: W_b1 = 9.151 mm × 0.004 = 0.0366 kg·m, "
                         "W_b2 = 34.15 mm × 0.004 = 0.1366 kg·m (a negative one points against its direction); the "
                         "masses at r_b: m_b1 = 0.366 kg, m_b2 = 1.366 kg")
    lines = steps(load_scene(SCENES / "bal.rotor_centrifugal.toml"))
    assert lines[-1] == ("before balancing, at ω = 523.6 rad/s the rotor's centrifugal force F = ω²·|Σ mᵢrᵢ| = "
                         "523.6² × 0.5 kg·m = 137100 N")
