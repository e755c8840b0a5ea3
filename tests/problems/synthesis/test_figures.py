"""The synthesis sheet: a panel per design, the θ-circle, the linkage bold, the lengths in the notes."""
from __future__ import annotations

import math

from graphmech.drawing.primitives import Circle, Segment
from graphmech.problems.synthesis.check import analyse_synthesis
from graphmech.problems.synthesis.figures import synthesis_sheet
from graphmech.scene import load_scene, render_scene
from tests.conftest import SCENES

BANK = SCENES / "linkage.crank_rocker_synthesis_K1.5.toml"


def test_each_design_has_its_panel_with_its_theta_circle_and_its_lengths():
    an = analyse_synthesis(load_scene(BANK))
    sheet = synthesis_sheet(an, (297.0, 210.0))
    assert [p.name for p in sheet.panels] == ["design1", "design2"]
    for panel, g in zip(sheet.panels, an.drawn):
        circles = [i for i in panel.items if isinstance(i, Circle)]
        O, R = g.circle
        assert any(c.center == O and c.r == R for c in circles)  # the θ-circle, thin
        bold = [i for i in panel.items if isinstance(i, Segment) and i.role == "result"]
        assert sorted(round(math.dist(s.p0, s.p1), 9) for s in bold) == sorted(
            round(x, 9) for x in (g.lAB_mm, g.lBC_mm, g.lCD_mm))
        assert any("l_{AB} = (AC_{2} − AC_{1})/2" in n for n in panel.notes)
    assert "49.31 mm" in sheet.panels[0].notes[2] and "22.51 mm" in sheet.panels[1].notes[2]


def test_the_reference_figure_is_the_scene_rendered():
    svg, _ = render_scene(BANK)
    assert svg.lstrip().startswith(("<?xml", "<svg")) and "</svg>" in svg


def test_a_guide_bar_is_drawn_with_its_limit_lines_and_stroke():
    from graphmech.drawing.primitives import Label
    from tests.scenes import parse_text

    an = analyse_synthesis(parse_text('[synthesis]\ntask = "time_ratio"\nmechanism = "guide_bar"\nK = 2\n'
                                      "frame_mm = 300\nstroke_mm = 400\n"))
    sheet = synthesis_sheet(an, (297.0, 210.0))
    (panel,) = sheet.panels
    assert {i.text for i in panel.items if isinstance(i, Label)} >= {"A", "C", "B_{1}", "B_{2}", "D_{1}", "D_{2}", "H"}
    assert any(isinstance(i, Circle) and i.r == an.guide.lAB_mm for i in panel.items)  # the crank circle
    assert "150 mm" in panel.notes[1] and "400 mm" in panel.notes[2]


def test_a_slider_crank_is_drawn_on_its_guide_with_its_theta_circle():
    from graphmech.drawing.primitives import GuideLine, Slider
    from tests.scenes import parse_text

    an = analyse_synthesis(parse_text('[synthesis]\ntask = "time_ratio"\nmechanism = "slider_crank"\nK = 1.5\n'
                                      "stroke_mm = 50\noffset_mm = 10\n"))
    (panel,) = synthesis_sheet(an, (297.0, 210.0)).panels
    O, R = an.slider.circle
    assert any(isinstance(i, Circle) and i.center == O and i.r == R for i in panel.items)
    assert sum(isinstance(i, GuideLine) for i in panel.items) == 1 and sum(isinstance(i, Slider) for i in panel.items) == 1
    assert "23.32 mm" in panel.notes[2] and "37.34 mm" in panel.notes[2]


def test_a_huge_theta_circle_is_drawn_as_its_arc_through_A_C1_C2():
    from graphmech.drawing.primitives import Polyline
    from tests.scenes import parse_text, replace_once, scene_text

    an = analyse_synthesis(parse_text(replace_once(scene_text("synthesis/swing"), "K = 1.4", "K = 1.0001")))
    sheet = synthesis_sheet(an, (297.0, 210.0))
    for panel, g in zip(sheet.panels, an.drawn):
        O, R = g.circle
        assert R > 1e4 and not any(isinstance(i, Circle) and i.r == R for i in panel.items)
        arcs = [i for i in panel.items if isinstance(i, Polyline) and all(
            abs(math.dist(p, O) - R) < 1e-6 * R for p in i.points)]
        assert len(arcs) == 1
        xs = [p[0] for p in arcs[0].points]
        assert max(xs) - min(xs) < 3 * max(g.lAD_mm, g.AC2_mm)  # on the sheet, not kilometres off it
