"""The sheet of a linkage scene (graphmech/problems/linkage/sheet.py): a row of panels per position,
the instant centres added when asked, too many positions refused before any work, and the
mechanism at position 1 for a flywheel sheet."""
from __future__ import annotations

import dataclasses
import tomllib

import pytest

from graphmech.errors import SceneError
from graphmech.mechanisms.linkage import Positions
from graphmech.problems.linkage.sheet import mechanism_at_position_1, scene_sheet
from graphmech.render.recording import RecordingBackend
from graphmech.render.sheet import draw_sheet
from graphmech.scene import parse_scene
from tests.scenes import scene_text

#: The four-bar at φ = 30°, showing the mechanism and its velocity polygon.
FOURBAR = scene_text("linkage/fourbar_phi30")


def scene(text=FOURBAR):
    return parse_scene(tomllib.loads(text), "fourbar.toml")


def test_a_panel_per_shown_figure_and_position_with_the_footer():
    sheet, warnings = scene_sheet(scene(), ("graphmech test",))
    assert [p.name for p in sheet.panels] == ["mechanism-30", "velocity-30"]
    assert sheet.panels[0].title == "Kinematic diagram, φ₂ = 30°"
    assert sheet.footer == ("graphmech test",) and sheet.page == (297.0, 210.0) and warnings == []
    rec = RecordingBackend()
    draw_sheet(sheet, rec)
    groups = [c[1] for c in rec.calls if c[0] == "begin_group" and not c[1].startswith("label")]
    assert groups == ["title", "panel1-mechanism-30", "panel2-velocity-30", "footer"]


def test_two_positions_make_two_rows():
    sheet, _ = scene_sheet(scene(FOURBAR.replace("angle = 30", "angle = [30, 60]")), ())
    assert [p.name for p in sheet.panels] == ["mechanism-30", "velocity-30", "mechanism-60", "velocity-60"]


def test_the_instant_centres_follow_the_polygons():
    text = FOURBAR.replace('show = ["mechanism", "velocity"]', 'show = ["mechanism", "instant_centres"]')
    sheet, _ = scene_sheet(scene(text), ())
    assert [p.name for p in sheet.panels] == ["mechanism-30", "ic-30", "ic-circle-30"]


def test_more_positions_than_the_page_holds_are_refused_before_any_work():
    with pytest.raises(SceneError) as info:
        scene_sheet(scene(FOURBAR.replace("angle = 30", "angle = [30, 60, 90]")), ())
    assert str(info.value) == (
        "fourbar.toml: driver: 3 positions do not fit one sheet of 297 × 210 mm (at most 2, one row of panels "
        "each): split the scene or choose a larger [page] size; `graphmech check` takes up to 3600")
    a3, _ = scene_sheet(scene(FOURBAR.replace("angle = 30", "angle = [30, 60, 90]") + '\n[page]\nsize = "A3"\n'), ())
    assert len(a3.panels) == 6


def test_the_mechanism_at_position_1_alone_in_the_first_row():
    s = dataclasses.replace(scene(), positions=Positions((0.5, 1.0), ("1", "2")), find=("v_C",))
    panels = mechanism_at_position_1(s, ())
    assert [(p.name, p.row) for p in panels] == [("mechanism-1", 0)]
    assert panels[0].title == "Kinematic diagram, position 1 (φ = 0), φ₂ = 1°"
