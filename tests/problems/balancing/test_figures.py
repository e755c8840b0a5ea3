"""The balancing sheet: the closing side bold at μW, only the asked panels, the recorded draw calls."""
from __future__ import annotations

import math
from functools import partial

import pytest

from graphmech.drawing.primitives import Arrow
from graphmech.problems.balancing.check import analyse_balancing, balancing_figure
from graphmech.scene import load_scene
from tests.conftest import SCENES
from tests.scenes import write_scene

write = partial(write_scene, name="r.toml")


def test_the_figure_draws_the_closing_side_bold_at_muW():
    an = analyse_balancing(load_scene(SCENES / "bal.disc_static.toml"))
    sheet = balancing_figure(an, (297.0, 210.0))
    assert [p.name for p in sheet.panels] == ["rotor", "polygon"]
    poly = sheet.panels[1]
    bold = [i for i in poly.items if isinstance(i, Arrow) and i.role == "result"]
    thin = [i for i in poly.items if isinstance(i, Arrow) and i.role == "given"]
    assert len(bold) == 1 and len(thin) == 4
    assert math.dist(bold[0].p0, bold[0].p1) * 0.05 == pytest.approx(0.8062257748298549, rel=1e-13)
    assert bold[0].p1 == (0.0, 0.0)  # closes back on the start


def test_only_the_asked_panels(tmp_path):
    text = (SCENES / "bal.rotor_dynamic.toml").read_text(encoding="utf-8").replace(
        'show = ["rotor", "polygon"]', 'show = ["polygon"]')
    an = analyse_balancing(load_scene(write(tmp_path, text)))
    assert [p.name for p in balancing_figure(an, (297.0, 210.0)).panels] == ["polygonI", "polygonII"]


def test_recorded_draw_calls_of_a_polygon_panel():
    """Each mass-radius product is a shaft and a filled triangle (never a marker); labels are text."""
    from graphmech.render.recording import RecordingBackend
    from graphmech.render.sheet import draw_sheet

    an = analyse_balancing(load_scene(SCENES / "bal.disc_static.toml"))
    sheet = balancing_figure(an, (297.0, 210.0))
    only_polygon = type(sheet)(sheet.title, (sheet.panels[1],), sheet.page, sheet.footer)
    calls = draw_sheet(only_polygon, RecordingBackend())
    heads = [c for c in calls if c[0] == "polyline" and c[4] and len(c[1]) == 3]
    assert len(heads) == 5  # W1 … W4 and the closing W_b
    texts = {c[1] for c in calls if c[0] == "text"}
    assert {"W_{1}", "W_{2}", "W_{3}", "W_{4}", "W_{b}"} <= texts
    assert any("μ_{W} = 0.05 (kg·m)/mm" in t for t in texts)


def test_captions_in_the_notation_marks_and_dash_dot_centre_lines(tmp_path):
    """bal.rotor_dynamic in 中文: the captions are the book's, the symbols marks (m_{b}^{I}, W_{1}^{I}),
    the rotor's centre lines and axis dash-dot, every panel states its paper scale."""
    from graphmech.drawing.primitives import Label, Segment

    text = (SCENES / "bal.rotor_dynamic.toml").read_text(encoding="utf-8") + '\n[page]\nnotation = "zh"\n'
    an = analyse_balancing(load_scene(write(tmp_path, text)))
    sheet = balancing_figure(an, (297.0, 210.0))
    panels = {p.name: p for p in sheet.panels}
    assert panels["rotor"].title == "转子：端视图" and panels["polygonII"].title == "质径积矢量多边形，平衡平面 II"
    assert panels["rotor"].scales == (("l", 0.02),) and panels["polygonI"].scales == (("W", 0.1),)
    texts = {i.text for p in sheet.panels for i in p.items if isinstance(i, Label)}
    assert {"m_{b}^{I}", "m_{b}^{II}", "m_{1}", "W_{1}^{I}", "W_{b}^{II}"} <= texts
    assert not any("_" in t.replace("_{", "") for t in texts)
    centre = [i for i in panels["rotor"].items + panels["side"].items if isinstance(i, Segment) and i.dashdot]
    assert len(centre) == 3  # two across the end view, the axis in the side view
    assert panels["polygonI"].notes[1] == "m_{b}r_{b} = 2.783 kg·m, θ_{b} = 5.942°, m_{b} = 5.566 kg"


def test_the_split_is_drawn_in_the_polygon_panel():
    an = analyse_balancing(load_scene(SCENES / "bal.split_two_directions.toml"))
    sheet = balancing_figure(an, (297.0, 210.0))
    polygon = next(p for p in sheet.panels if p.name == "polygon")
    closing = an.corrections[0].closing
    K = an.split_corner
    arrows = [(a.p0, a.p1) for a in polygon.items if isinstance(a, Arrow) and a.role == "result"]
    assert (closing.start, K) in arrows and (K, closing.end) in arrows
    # the sides along 180° and 270°, 0.0366 and 0.1366 kg·m at μW = 0.004 kg·m/mm
    assert K[1] == pytest.approx(closing.start[1], abs=1e-12) and K[0] == pytest.approx(closing.end[0], abs=1e-12)
    assert closing.start[0] - K[0] == pytest.approx(0.1 * (math.cos(math.radians(30)) - 0.5) / 0.004, rel=1e-9)
