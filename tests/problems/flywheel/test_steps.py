"""The flywheel's construction protocol: the positions, the scales, the method's diagrams in the
book's order, and every value of the check table read off as the table reads it."""
from __future__ import annotations

import tomllib

from graphmech.problems.flywheel.check import analyse_flywheel
from graphmech.problems.flywheel.steps import flywheel_steps
from graphmech.problems.protocol import num
from graphmech.scene import load_scene, parse_scene
from tests.conftest import SCENES, run_cli

COMPRESSOR = SCENES / "fly.compressor_course_project.toml"


def test_every_value_of_the_check_table_is_in_the_protocol():
    for name in ("fly.compressor_course_project", "fly.ic_engine_flywheel", "fly.brake_time",
                 "fly.compressor_course_project-stiff"):
        scene = load_scene(SCENES / f"{name}.toml")
        text = "\n".join(flywheel_steps(scene))
        for row in analyse_flywheel(scene).rows:
            assert f"{row.name} = " in text and num(row.graphical) in text, (name, row.name)


def test_the_wittenbauer_steps_come_in_the_books_order_and_kl_gives_J_F():
    lines = flywheel_steps(load_scene(COMPRESSOR))
    order = [next(k for k, line in enumerate(lines) if line.startswith(start)) for start in
             ("divide the cycle into 12 positions", "choose μφ", "draw Mп(φ)", "integrate Mп(φ) by chords",
              "draw the energy–mass (Wittenbauer) diagram", "draw its tangents", "J_F = kl·μT", "read J_F")]
    assert order == sorted(order)
    # J_F's drawn length is kl = |k − l|, the two cut-offs read before it
    assert "read k = −10.97 mm × 13.09 = −143.6 J (±7.5 %, 12 positions)" in lines
    assert "read l = −29.06 mm × 13.09 = −380.4 J (±0.83 %, 12 positions)" in lines
    assert "read J_F = 18.09 mm × 0.03238 = 0.5859 kg·m² (±7.7 %, 12 positions)" in lines


def test_the_indicator_and_the_brake_have_their_own_steps():
    ind = flywheel_steps(load_scene(SCENES / "fly.ic_engine_flywheel.toml"))
    assert any(line.startswith("draw the energy indicator") for line in ind)
    assert not any("Wittenbauer" in line for line in ind)
    brake = flywheel_steps(load_scene(SCENES / "fly.brake_time.toml"))
    assert brake[-1] == "read t_stop = 125 mm × 0.02 = 2.5 s" and "ε = M/J = 20 N·m / 0.5 kg·m²" in brake[1]


def test_the_protocol_speaks_the_scenes_notation():
    for notation, words in (("zh", "能量—质量（维滕鲍尔）图"), ("ru", "диаграмму энергомасс")):
        data = tomllib.loads(COMPRESSOR.read_text(encoding="utf-8"))
        data.setdefault("page", {})["notation"] = notation
        assert any(words in line for line in flywheel_steps(parse_scene(data, "x.toml"))), notation


def test_the_command_prints_it_numbered():
    code, out, _ = run_cli("steps", str(SCENES / "fly.brake_time.toml"))
    assert code == 0 and out.splitlines()[-1] == "3. read t_stop = 125 mm × 0.02 = 2.5 s"
