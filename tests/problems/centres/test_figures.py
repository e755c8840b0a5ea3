"""The friction planetary drive's figure: wheels as circles, the ring hatched, the centres marked,
Kennedy's line, the polygon of links."""
from __future__ import annotations

import math

from graphmech.drawing.primitives import Circle, FixedPivot, Label, Segment
from graphmech.problems.centres.check import analyse_centres
from graphmech.problems.centres.figures import HATCH_DEG, centres_sheet
from graphmech.scene import load_scene
from tests.conftest import SCENES, run_cli

PLANETARY = SCENES / "ic.friction_planetary.toml"


def test_the_sheet_draws_the_wheels_the_centres_and_the_polygon_of_links():
    an = analyse_centres(load_scene(PLANETARY))
    sheet = centres_sheet(an, (297.0, 210.0))
    assert [p.name for p in sheet.panels] == ["centres", "polygon"]
    items = sheet.panels[0].items
    wheels = sorted(round(i.r, 9) for i in items if isinstance(i, Circle) and i.role == "given")
    assert wheels == [15.0, 40.0, 70.0]  # r2, r1, R4 at μl = 0.001 m/mm
    hatch = [i for i in items if isinstance(i, Segment) and i.role == "construction" and not i.dashed]
    assert len(hatch) == int(360 / HATCH_DEG)
    assert all(math.hypot(*h.p1) > 70.0 for h in hatch)  # outside the ring: the frame's side
    labels = {i.text for i in items if isinstance(i, Label)}
    assert {"P₁₂", "P₂₄", "P₁₄"} <= labels or {"P12", "P24", "P14"} <= {t.replace("₁", "1").replace("₂", "2")
                                                                         .replace("₄", "4") for t in labels}
    kennedy = [i for i in items if isinstance(i, Segment) and i.dashed]
    assert any(math.hypot(*s.p0) < 1e-9 or math.hypot(*s.p1) < 1e-9 for s in kennedy)  # P14 … P24
    assert sum(isinstance(i, FixedPivot) for i in items) == 1
    assert any("ω1/ω2 = P24P12 / P14P12 = −0.75" in n for n in sheet.panels[0].notes)
    assert sheet.panels[0].scales == (("l", 0.001),)


def test_the_reference_figure_renders(tmp_path):
    out = tmp_path / "fp.svg"
    code, _, err = run_cli("render", str(PLANETARY), "-o", str(out))
    assert code == 0 and err == "", err
    assert out.read_text(encoding="utf-8") == (SCENES.parent / "ic.friction_planetary.svg").read_text(encoding="utf-8")
