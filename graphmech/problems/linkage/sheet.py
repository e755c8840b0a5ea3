"""The sheet of a linkage scene: one row of panels per position — the mechanism, its velocity and
acceleration polygons — and the instant centres when the scene asks for them."""
from __future__ import annotations

import dataclasses
import math
from typing import Any

from graphmech.drawing.primitives import Primitive, Sheet
from graphmech.errors import SceneError
from graphmech.mechanisms.linkage import Positions
from graphmech.methods.polygons import PANELS
from graphmech.problems.instant_centres.figures import ic_panels
from graphmech.problems.judging import finite, measured_entries, split_name
from graphmech.problems.linkage.check import analyse, rows_that_fit
from graphmech.problems.linkage.figures import direction_mark, drawn_points, linkage_sheet, transmission_marks
from graphmech.problems.linkage.higher_pair import decorate
from graphmech.problems.linkage.sizes import drawn_position_text
from graphmech.problems.reader import Scene, page_size


def scene_sheet(scene: Scene[Any], footer: tuple[str, ...], caption: str = "") -> tuple[Sheet, list[str]]:
    """The drawing of a linkage scene and the warnings found while making it; ``caption`` goes
    before each position's name (a flywheel scene's "position 1 (φ = 0), ")."""
    _fits(scene)
    an = finite(analyse(scene, ()))
    b = an.build
    texts = [caption + drawn_position_text(b, lab) for lab in an.labels]
    notation = getattr(scene.page, "notation", "en")
    sheet = linkage_sheet(scene.title, b.linkage, b, an.plan, an.solutions, an.labels, texts, an.scales,
                          [s for s in scene.show if s in PANELS], page_size(scene), footer, notation,
                          found_senses(an), asked_marks(an))
    if "instant_centres" in scene.show:
        sheet = dataclasses.replace(sheet, panels=sheet.panels + tuple(ic_panels(an, page_size(scene))))
    sheet = decorate(sheet, an)  # the higher pairs' profiles, contact and common normal (none: unchanged)
    return sheet, list(an.warnings)


def found_senses(an: Any) -> list[dict[str, tuple[float | None, float | None]]]:
    """Per position, each link's ω (where the scene shows the velocity polygon) and ε (the
    acceleration polygon) as the construction finds them — their signs are the senses drawn on
    the mechanism. A link that does not turn (a slider) has none."""
    b = an.build
    show = an.scene.show
    wanted = {name: q for name, q in b.quantities.items() if q.exact[0] in ("omega", "alpha")
              and ((q.exact[0] == "omega" and "velocity" in show) or (q.exact[0] == "alpha" and "acceleration" in show))}
    out: list[dict[str, tuple[float | None, float | None]]] = []
    if not wanted or "mechanism" not in show:
        return [{} for _ in an.solutions]
    plan = b.g.prune(list(dict.fromkeys(q.slot for q in wanted.values())))
    scale = {"omega": abs(getattr(b.linkage.driver, "omega", 0.0)) or 1.0}
    for i, sol in enumerate(an.solutions):
        found: dict[str, tuple[float | None, float | None]] = {}
        if sol is not None:
            try:
                values = plan.solve({b.param: float(an.positions[i])}).values
            except (ArithmeticError, ValueError):  # a degenerate polygon: no senses drawn
                values = {}
            for q in wanted.values():
                if q.slot not in values:
                    continue
                drawn, mu = values[q.slot]
                v = float(drawn) * float(mu)
                if not math.isfinite(v) or abs(v) <= 1e-9 * scale["omega"] ** (1 if q.exact[0] == "omega" else 2):
                    continue  # at rest: no sense to draw
                w, e = found.get(q.exact[1], (None, None))
                found[q.exact[1]] = (v, e) if q.exact[0] == "omega" else (w, v)
        out.append(found)
    return out


def asked_marks(an: Any) -> dict[str, list[list[Primitive]]]:
    """Per panel, per position, what the scene's angles ask to be marked: α and γ at each output
    joint on the mechanism, a direction's angle on its polygon (``find`` or measured names)."""
    b = an.build
    out: dict[str, list[list[Primitive]]] = {p: [[] for _ in an.solutions] for p in PANELS}
    names = list(an.scene.find) + [n for _, n, _ in measured_entries(an.scene, an.extra_measured)]
    done: set[tuple[int, tuple[Any, ...]]] = set()
    for raw in names:
        base, at = split_name(raw)
        q = b.quantities.get(base)
        if q is None or q.exact[0] not in ("gamma", "pressure", "dir_v", "dir_a"):
            continue
        for i, sol in enumerate(an.solutions):
            key = (i, q.exact[1:] if q.exact[0] in ("gamma", "pressure") else q.exact)
            if sol is None or (at is not None and at != an.labels[i]) or key in done:
                continue  # γ_C and α_C share one mark
            done.add(key)
            v = sol.values
            if q.exact[0] in ("dir_v", "dir_a"):
                pole, image = b.g.steps[q.slot].inputs
                if pole in v and image in v:
                    out[q.panel][i] += direction_mark(_xy(v[pole]), _xy(v[image]))
                continue
            out["mechanism"][i] += transmission_marks(b.linkage, drawn_points(b, v), q.exact[1:])
    return out


def _xy(v: Any) -> tuple[float, float]:
    return (float(v[0]), float(v[1]))


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
