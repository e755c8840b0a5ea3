"""Extreme but valid gear scenes (issue 18): a shift below x_min (undercut, drawn and said), negative
shifts below the standard centre distance, a shift that makes the tooth pointed."""
from __future__ import annotations

import pytest

from tests.conftest import check_json, run_cli, values

def shift_scene(tmp_path, text: str, find: list[str] | None = None):
    f = tmp_path / "g.toml"
    f.write_text((f"find = {find!r}\n".replace("'", '"') if find else "") + text)
    return f

def test_below_the_standard_distance_with_negative_shifts(tmp_path):
    f = shift_scene(tmp_path, '[gear]\nm_mm = 10\nz = [30, 40]\nmeshing = "external"\ncentre_distance_mm = 345\n'
                        'x = "for_centre_distance"\n', ["x_sum", "x1", "y", "delta_y", "alpha_w", "eps_alpha"])
    doc = check_json(f)
    q = values(doc)
    assert q["x_sum"]["graphical"] < 0 and q["y"]["graphical"] == pytest.approx(-0.5)
    assert q["alpha_w"]["graphical"] < 20.0
    for name in q:
        assert q[name]["graphical"] == pytest.approx(q[name]["exact"], rel=1e-9, abs=1e-12), name
    assert doc["gear"]["drive"] == "negative"


def test_a_shift_below_x_min_is_undercut_drawn_and_said(tmp_path):
    f = shift_scene(tmp_path, '[gear]\nm_mm = 4\nz = 18\nx = -1.5\n', ["x", "x_min", "x_min_exact", "s_pitch"])
    code, out, err = run_cli("check", str(f))
    assert code == 0 and "undercut" in err and "x_min = -0.0528" in err
    svg = tmp_path / "g.svg"
    assert run_cli("render", str(f), "-o", str(svg))[0] == 0
    assert ">undercut<" in svg.read_text()


def test_a_shift_that_makes_the_tooth_pointed_is_said(tmp_path):
    f = shift_scene(tmp_path, '[gear]\nm_mm = 4\nz = 10\nx = 1.2\n', ["sa", "ra_pointed"])
    code, out, err = run_cli("check", str(f))
    assert code == 0 and "pointed below its tip circle" in err
    q = values(check_json(f))
    assert q["ra_pointed"]["graphical"] < 0.5 * 0.004 * 10 + 2.2 * 0.004
