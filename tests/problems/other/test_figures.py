"""The other mechanisms' figures: the wheel's outline, the panels the scene shows."""
from __future__ import annotations

import math

from graphmech.drawing.primitives import Polyline
from graphmech.problems.other.check import analyse_other
from graphmech.problems.other.figures import other_sheet, wheel_outline
from graphmech.scene import load_scene
from tests.conftest import SCENES, run_cli


def test_the_wheel_outline_has_z_slots_of_depth_h_and_stays_within_its_tips():
    S, h, r, rl, L = 51.96, 26.96, 5.0, 22.5, 60.0
    pts = wheel_outline((0.0, 0.0), S, h, r, rl, L, 6, 0.3)
    radii = [math.hypot(*p) for p in pts]
    assert max(radii) <= math.hypot(S, r) + 1e-9
    assert min(radii) == min(radii) and abs(min(radii) - (S - h)) < 1e-9  # the slots' bottoms
    bottoms = [p for p in pts if abs(math.hypot(*p) - (S - h)) < 1e-9]
    assert len(bottoms) == 6


def test_the_sheet_has_the_panels_the_scene_shows():
    an = analyse_other(load_scene(SCENES / "mech.geneva_six_slot.toml"))
    sheet = other_sheet(an, (420.0, 297.0))
    assert [p.name for p in sheet.panels] == ["geneva", "velocity", "acceleration", "curves"]
    assert sheet.panels[0].scales == (("l", 0.005),)
    assert len(an.curves) == 49 and an.curves[24][1] == max(c[1] for c in an.curves)  # ω₂ peaks at φ = 0
    assert any(isinstance(i, Polyline) and i.closed for i in sheet.panels[0].items)


def test_the_reference_figures_render(tmp_path):
    for name in ("mech.geneva_six_slot", "mech.differential_screw"):
        out = tmp_path / f"{name}.svg"
        code, _, err = run_cli("render", str(SCENES / f"{name}.toml"), "-o", str(out))
        assert code == 0 and err == "", err
        svg = out.read_text(encoding="utf-8")
        assert "</svg>" in svg
    assert "Differential screw" in (tmp_path / "mech.differential_screw.svg").read_text(encoding="utf-8")


def test_the_sheet_is_lettered_in_the_scene_notation():
    import dataclasses

    from graphmech.problems.reader import Page

    s = load_scene(SCENES / "mech.geneva_six_slot.toml")
    an = analyse_other(dataclasses.replace(s, page=Page((420.0, 297.0), "zh")))
    sheet = other_sheet(an, (420.0, 297.0))
    assert sheet.panels[0].title == "槽轮机构，z = 6，φ = −20°"
    assert sheet.panels[1].title == "圆销的速度多边形"
