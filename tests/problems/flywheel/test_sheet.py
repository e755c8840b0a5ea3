"""The sheet of a flywheel scene: which panels, in which order, with the warnings found on the way."""
from __future__ import annotations

import dataclasses
import re
import tomllib

import pytest

from graphmech.errors import SceneError
from graphmech.problems.flywheel.sheet import scene_sheet
from graphmech.scene import Scene, parse_scene
from tests.conftest import SCENES
from tests.scenes import scene_text


def scene(text: str) -> Scene:
    return parse_scene(tomllib.loads(text), "fly.toml")


def test_a_braking_only_scene_is_its_run_down():
    """fly.brake_time: J = 0.5 kg·m², ω0 = 100 rad/s, M = 20 N·m: one panel, t_stop = 2.5 s in its notes."""
    sheet, warnings = scene_sheet(scene(scene_text("flywheel/braking")), ("footer",))
    assert [p.name for p in sheet.panels] == ["rundown"]
    assert sheet.page == (297.0, 210.0) and sheet.footer == ("footer",) and warnings == []
    assert sheet.panels[0].notes[1].endswith("= 0.02·125 = 2.5 s")
    assert sheet.panels[0].notes[2] == "required t ≤ 3 s: stops in time"


def test_the_cycle_panels_follow_show():
    engine = scene_text("flywheel/engine")
    sheet, _ = scene_sheet(scene(engine), ())
    assert [p.name for p in sheet.panels] == ["moment", "energy"]
    assert sheet.title == "IC engine"
    # the Wittenbauer diagram shares its panel with ΔT(φ); no mechanism without a linkage
    both = engine.replace('show = ["moment", "energy"]', 'show = ["energy", "wittenbauer"]')
    both = both.replace('method = "indicator"', 'method = "wittenbauer"\ninertia_kgm2 = 0.5')
    assert [p.name for p in scene_sheet(scene(both), ())[0].panels] == ["energy+wittenbauer"]


def test_the_mechanism_at_position_1_comes_first_and_warnings_come_back():
    """The course project at 12 positions: the true motion's δ is 7.5 % above the required 1/25."""
    text = (SCENES / "fly.compressor_course_project.toml").read_text(encoding="utf-8")
    text = re.sub(r"show = \[.*?\]", 'show = ["mechanism", "energy"]', text, flags=re.S)
    sheet, warnings = scene_sheet(scene(text), ())
    assert [p.name for p in sheet.panels] == ["mechanism-1", "energy"]
    assert sheet.panels[0].notes == ("μ_{l} = 0.001 m/mm",)
    (warning,) = warnings
    assert "gives δ = 0.0430076 in the true motion, above the required 0.04 (+7.52 %)" in warning


def test_a_scene_asking_for_no_drawing_is_refused_at_show():
    braking = scene(scene_text("flywheel/braking"))
    with pytest.raises(SceneError) as info:
        scene_sheet(dataclasses.replace(braking, show=()), ())
    assert info.value.problems == [
        ("show", "nothing to draw: this flywheel scene asks for no diagram; use graphmech check")]


def test_loads_no_constant_moment_balances_are_refused_at_balance():
    """The shared compressor's moments deliver 13.7 J a cycle: no constant driving moment balances them."""
    with pytest.raises(SceneError) as info:
        scene_sheet(scene(scene_text("flywheel/compressor")), ())
    ((path, reason),) = info.value.problems
    assert path == "flywheel.balance"
    assert reason.startswith("the loads deliver 13.7466 J over a cycle: a constant driving moment cannot balance")
