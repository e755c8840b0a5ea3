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
from tests.conftest import SCENES
from tests.scenes import scene_text

#: The four-bar at φ = 30°, showing the mechanism and its velocity polygon.
FOURBAR = scene_text("linkage/fourbar_phi30")


def scene(text=FOURBAR):
    return parse_scene(tomllib.loads(text), "fourbar.toml")


def test_a_panel_per_shown_figure_and_position_with_the_footer():
    sheet, warnings = scene_sheet(scene(), ("graphmech test",))
    assert [p.name for p in sheet.panels] == ["mechanism-30", "velocity-30"]
    assert sheet.panels[0].title == "Kinematic diagram, φ_{2} = 30°"
    assert sheet.footer == ("graphmech test",) and sheet.page == (297.0, 210.0)
    # μv = 0.01 is the finest round scale the A4 panel holds: v_C comes out under 10 mm, so it is named
    assert warnings == ["v_C is drawn 9.4 mm long at μv = 0.01 (m/s)/mm, under 10 mm: read to ±0.5 mm it is "
                        "±5.3 % (a smaller μv or a larger page makes it longer)"]
    rec = RecordingBackend()
    draw_sheet(sheet, rec)
    groups = [c[1] for c in rec.calls if c[0] == "begin_group" and not c[1].startswith(("label", "caption"))]
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
    assert panels[0].title == "Kinematic diagram, position 1 (φ = 0), φ_{2} = 1°"


def _sheet_and_check(name, notation=None):
    """The sheet's captions and the check's text of a reference scene, in ``notation``."""
    from graphmech.problems import sheet as sheet_of
    from tests.conftest import ROOT

    text = (ROOT / "figures" / "scenes" / f"{name}.toml").read_text(encoding="utf-8")
    if notation:
        text += f'\n[page]\nnotation = "{notation}"\n'
    drawn, _ = sheet_of(parse_scene(tomllib.loads(text), f"{name}.toml"), ())
    return drawn, text


@pytest.mark.parametrize("notation, velocity", [("zh", "速度多边形"), ("ru", "план скоростей")])
def test_the_notation_changes_the_captions_and_not_the_check(tmp_path, notation, velocity):
    from tests.conftest import run_cli

    en, text_en = _sheet_and_check("linkage.slider_crank_offset")
    other, text = _sheet_and_check("linkage.slider_crank_offset", notation)
    assert [p.title.partition(",")[0] for p in en.panels[:3]] == ["Kinematic diagram", "Velocity polygon",
                                                                   "Acceleration polygon"]
    assert other.panels[1].title.startswith(velocity) and other.panels[0].title != en.panels[0].title
    assert [p.notes for p in other.panels] == [p.notes for p in en.panels]  # μ is written the same
    a, b = tmp_path / "en.toml", tmp_path / f"{notation}.toml"
    a.write_text(text_en, encoding="utf-8")
    b.write_text(text, encoding="utf-8")
    for args in ((), ("--json",)):
        out_en, out = run_cli("check", str(a), *args), run_cli("check", str(b), *args)
        assert out_en[0] == out[0] == 0 and out_en[1].replace("en.toml", "X") == out[1].replace(f"{notation}.toml", "X")


KINEMATICS = sorted(p.stem for p in SCENES.glob("*.toml") if p.stem.split(".")[0] in ("linkage", "kin", "ic"))


@pytest.mark.parametrize("name", KINEMATICS)
def test_the_drawn_text_is_lettered_not_typed(name):
    """Every composed text of the kinematics sheets: no ASCII "_" outside the marks, letters ≥ 3.5 mm,
    numbers to at most 4 significant figures, no hyphen for a minus; each panel states its scales."""
    import re

    from graphmech.drawing.lettering import plain
    from graphmech.drawing.primitives import Label

    drawn, _ = _sheet_and_check(name)
    for p in drawn.panels:
        texts = [p.title, *p.notes] + [it.text for it in p.items if isinstance(it, Label)]
        for t in texts:
            assert "_" not in plain(t), (p.name, t)
            for num in re.findall(r"\d+\.\d+", plain(t)):
                assert len(num.replace(".", "").lstrip("0")) <= 4, (p.name, t)
            assert not re.search(r"(?<![\w)])-\d", t), (p.name, t)
        assert all(it.size >= 3.5 for it in p.items if isinstance(it, Label)), p.name
        if not p.name.startswith(("ic-circle", "polygon")):  # the polygon of links is not to scale
            assert p.scales, p.name
