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
