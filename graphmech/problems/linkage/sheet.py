"""The sheet of a linkage scene: one row of panels per position — the mechanism, its velocity and
acceleration polygons — and the instant centres when the scene asks for them."""
from __future__ import annotations

import dataclasses
from typing import Any

from graphmech.drawing.primitives import Sheet
from graphmech.errors import SceneError
from graphmech.mechanisms.linkage import Positions
from graphmech.methods.polygons import PANELS
from graphmech.problems.instant_centres.figures import ic_panels
from graphmech.problems.judging import finite
from graphmech.problems.linkage.check import analyse, rows_that_fit
from graphmech.problems.linkage.figures import linkage_sheet
from graphmech.problems.linkage.sizes import position_text
from graphmech.problems.reader import Scene, page_size


def scene_sheet(scene: Scene[Any], footer: tuple[str, ...], caption: str = "") -> tuple[Sheet, list[str]]:
    """The drawing of a linkage scene and the warnings found while making it; ``caption`` goes
    before each position's name (a flywheel scene's "position 1 (φ = 0), ")."""
    _fits(scene)
    an = finite(analyse(scene, ()))
    b = an.build
    texts = [caption + position_text(b, lab) for lab in an.labels]
    sheet = linkage_sheet(scene.title, b.linkage, b, an.plan, an.solutions, an.labels, texts, an.scales,
                          [s for s in scene.show if s in PANELS], page_size(scene), footer)
    if "instant_centres" in scene.show:
        sheet = dataclasses.replace(sheet, panels=sheet.panels + tuple(ic_panels(an, page_size(scene))))
    return sheet, list(an.warnings)


def _fits(scene: Scene[Any]) -> None:
    """One row of panels per position: refuse more than the page holds before any work is done."""
    page = page_size(scene)
    fit = rows_that_fit(page)
    assert scene.positions is not None
    if len(scene.positions.values) > fit:
        raise SceneError([("driver", f"{len(scene.positions.values)} positions do not fit one sheet of "
                                     f"{page[0]:g} × {page[1]:g} mm (at most {fit}, one row of panels each): "
                                     "split the scene or choose a larger [page] size; `graphmech check` "
                                     "takes up to 3600")], scene.source)


def mechanism_at_position_1(scene: Scene[Any], footer: tuple[str, ...]) -> list[Any]:
    """A scene's mechanism drawn at position 1 (where φ = 0) as a linkage scene would draw it
    (the first panel of a flywheel sheet)."""
    assert scene.positions is not None
    first = Positions(scene.positions.values[:1], scene.positions.labels[:1])
    lscene = dataclasses.replace(scene, show=("mechanism",), find=(), measured=(), kind="linkage", problem=None,
                                 positions=first)
    sheet, _ = scene_sheet(lscene, footer, caption="position 1 (φ = 0), ")
    return [dataclasses.replace(p, row=0) for p in sheet.panels]
