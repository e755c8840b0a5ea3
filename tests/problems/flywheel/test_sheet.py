"""The sheet of a flywheel scene: which panels, in which order, with the warnings found on the way."""
from __future__ import annotations

import dataclasses
import math
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


def _in_notation(path, notation: str) -> str:
    """The reference scene's text with ``[page] notation`` set."""
    text = path.read_text(encoding="utf-8")
    return re.sub(r"\[page\]\n", f'[page]\nnotation = "{notation}"\n', text)


def test_the_notation_changes_the_drawn_symbols_and_captions_never_the_check(tmp_path):
    """fly.ic_engine_flywheel in 中文 and русский: the reduced moment is drawn M_{e} / M_{п} (never the
    Russian "Mп" read as "Mn" in English), the captions are the book's; check prints the same bytes."""
    from tests.conftest import run_cli

    ref = SCENES / "fly.ic_engine_flywheel.toml"
    drawn = {}
    for notation in ("en", "zh", "ru"):
        sheet, _ = scene_sheet(scene(_in_notation(ref, notation)), ())
        drawn[notation] = {p.name: (p.title, {i.text for i in p.items if hasattr(i, "text")}) for p in sheet.panels}
    assert "M_{red}" in drawn["en"]["moment"][1] and "M_{r}" in drawn["en"]["moment"][1]
    assert "M_{e}" in drawn["zh"]["moment"][1] and "M_{er}" in drawn["zh"]["moment"][1]
    assert "M_{п}" in drawn["ru"]["moment"][1] and "M_{с}" in drawn["ru"]["moment"][1]
    assert "ΔE" in drawn["zh"]["energy"][1] and "ΔT" in drawn["ru"]["energy"][1]
    assert drawn["zh"]["moment"][0] == "等效力矩 M_{e}(φ) 及其图解积分"
    assert drawn["zh"]["indicator"][0] == "能量指示图"
    assert drawn["ru"]["moment"][0] == "Приведённый момент M_{п}(φ), графическое интегрирование"
    assert drawn["en"]["moment"][0] == "Reduced moment M_{red}(φ), integrated by chords"
    # no composed text carries a bare "_" nor the Cyrillic п outside a mark
    for notation in drawn:
        for title, texts in drawn[notation].values():
            for t in texts | {title}:
                assert re.sub(r"_\{[^}]*\}", "", t).count("_") == 0, t
                assert "Mп" not in t and "Jп" not in t
    outputs = set()
    for notation in ("en", "zh", "ru"):
        path = tmp_path / f"fly-{notation}.toml"
        path.write_text(_in_notation(ref, notation), encoding="utf-8")
        code, out, _ = run_cli("check", str(path))
        assert code == 0
        outputs.add(out)
    assert len(outputs) == 1 and "Mr " in next(iter(outputs))  # the find name stays Mr


def test_the_stiff_sheet_draws_omega_of_the_true_motion():
    """fly.compressor_course_project-stiff: ω(φ) of the motion the check solves (Radau), the φ axis at ω_m,
    at a round μω that spreads ω_max − ω_min (5.2e-5 rad/s) over tens of mm; closed over the cycle."""
    from graphmech.drawing.primitives import Polyline, Segment

    sc = scene((SCENES / "fly.compressor_course_project-stiff.toml").read_text(encoding="utf-8"))
    assert "motion" in sc.show
    sheet, _ = scene_sheet(sc, ())
    [p] = [p for p in sheet.panels if p.name == "motion"]
    scales = dict(p.scales)
    assert scales["omega"] == 2e-6 and scales["phi"] == pytest.approx(math.radians(2.5))
    [curve] = [i for i in p.items if isinstance(i, Polyline)]
    y = [pt[1] for pt in curve.points]
    levels = sorted(i.p0[1] for i in p.items if isinstance(i, Segment) and i.dashed)
    assert min(y) == pytest.approx(levels[0], abs=0.05) and max(y) == pytest.approx(levels[1], abs=0.05)
    assert levels[1] - levels[0] > 20.0  # readable: ω_max − ω_min over 20 mm
    assert y[0] == pytest.approx(y[-1], abs=0.01)  # periodic
    assert curve.points[-1][0] == pytest.approx(360.0 / 2.5)
    assert p.notes[0] == "μ_{ω} = 2×10^{−6} (rad/s)/mm, μ_{φ} = 2.5 °/mm"
