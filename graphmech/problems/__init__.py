"""The kinds of problem a scene poses, and for each how it is checked and drawn.

A scene file is one problem: a linkage (its polygons, instant centres), a full cycle, a disc
cam, a flywheel, a kinetostatic analysis, an efficiency or a balancing problem, a structure.
Each kind has its own check module (``<kind>_check.py``) and figures (``methods/*_figures.py``);
this module is the one place that says which is which, so the command line (``cli.py``) treats
every kind alike: analyse, judge the measured values, draw, and report what the kind adds to
``check --json`` and to the text table. Imports are lazy: a check never imports the renderer's
code of another kind, and nothing here imports matplotlib.
"""
from __future__ import annotations

import dataclasses
import importlib
from dataclasses import dataclass
from typing import Any, Callable

from graphmech.errors import SceneError
from graphmech.problems.judging import refuse_non_finite

Extra = tuple[tuple[str, float], ...]
Footer = tuple[str, ...]


@dataclass(frozen=True)
class Kind:
    """How one kind of problem is carried out.

    analyse(scene, extra) → analysis with ``rows``, ``warnings``, ``scales``, ``scale_notes()``;
    judge(analysis, extra) → verdicts on the measured values (the precision is the scene's);
    sheet(scene, footer) → the :class:`~graphmech.drawing.primitives.Sheet` and its warnings;
    extras(analysis) → what ``check --json`` adds; lines(analysis) → lines printed under the table.
    """

    name: str
    analyse: Callable[[Any, Extra], Any]
    judge: Callable[[Any, Extra], list[Any]]
    sheet: Callable[[Any, Footer], tuple[Any, list[str]]]
    extras: Callable[[Any], dict[str, Any]] = lambda an: {}
    lines: Callable[[Any], list[str]] = lambda an: []


def kind_of(scene: Any) -> Kind:
    """The kind of problem ``scene`` poses (exactly one: the scene reader refuses mixtures)."""
    for field in ("efficiency", "balancing", "structure", "flywheel", "forces", "cam", "cycle"):
        if getattr(scene, field, None) is not None:
            return KINDS[field]
    return KINDS["linkage"]


def with_precision(scene: Any, precision_mm: float | None) -> Any:
    """The scene with the drawing precision a user gave on the command line (None: the scene's own)."""
    return scene if precision_mm is None else dataclasses.replace(scene, precision_mm=precision_mm)


def _function(module: str, name: str) -> Callable[..., Any]:
    """``module.name``, imported when first called: a check never imports another kind's code."""

    def call(*args: Any, **kwargs: Any) -> Any:
        return getattr(importlib.import_module(module), name)(*args, **kwargs)

    return call


def _analysing(module: str, name: str) -> Callable[..., Any]:
    """A check module's ``analyse_…(scene, extra)``; whatever it finds is finite or refused in words
    (for the table, the JSON and the drawing alike)."""
    analyse = _function(module, name)

    def call(*args: Any, **kwargs: Any) -> Any:
        an = analyse(*args, **kwargs)
        refuse_non_finite(an.rows)
        return an

    return call


def _judging(module: str, name: str) -> Callable[[Any, Extra], list[Any]]:
    """A check module's ``judge_…(analysis)`` (the precision is the scene's; ``extra`` is in the analysis)."""
    judge = _function(module, name)
    return lambda an, extra: judge(an)


#: Each kind's analysis and judge, imported when first used.
_analyse_linkage = _analysing("graphmech.problems.linkage.check", "analyse")
_analyse_cycle = _analysing("graphmech.problems.cycle.check", "analyse_cycle")
_analyse_cam = _analysing("graphmech.problems.cam.check", "analyse_cam")
_analyse_flywheel = _analysing("graphmech.problems.flywheel.check", "analyse_flywheel")
_analyse_efficiency = _analysing("graphmech.problems.efficiency.check", "analyse_efficiency")
_analyse_balancing = _analysing("graphmech.problems.balancing.check", "analyse_balancing")
_analyse_forces = _analysing("graphmech.problems.forces.check", "analyse_forces")
_judge_linkage = _judging("graphmech.problems.linkage.check", "judge")
_judge_cycle = _judging("graphmech.problems.cycle.check", "judge_cycle")
_judge_cam = _judging("graphmech.problems.cam.check", "judge_cam")
_judge_flywheel = _judging("graphmech.problems.flywheel.check", "judge_flywheel")
_judge_efficiency = _judging("graphmech.problems.efficiency.check", "judge_efficiency")
_judge_balancing = _judging("graphmech.problems.balancing.check", "judge_balancing")


def _page(scene: Any) -> tuple[float, float]:
    from graphmech.problems.reader import page_size

    return page_size(scene)


# ---------------------------------------------------------------------------- linkage


def _linkage_sheet(scene: Any, footer: Footer, caption: str = "") -> tuple[Any, list[str]]:
    from graphmech.problems.linkage.sizes import position_text
    from graphmech.problems.linkage.figures import linkage_sheet
    from graphmech.methods.polygons import PANELS

    _linkage_fits(scene)
    an = _analyse_linkage(scene, ())
    b = an.build
    texts = [caption + position_text(b, lab) for lab in an.labels]
    sheet = linkage_sheet(scene.title, b.linkage, b, an.plan, an.solutions, an.labels, texts, an.scales,
                          [s for s in scene.show if s in PANELS], _page(scene), footer)
    if "instant_centres" in scene.show:
        from graphmech.problems.instant_centres.figures import ic_panels

        sheet = dataclasses.replace(sheet, panels=sheet.panels + tuple(ic_panels(an, _page(scene))))
    return sheet, list(an.warnings)


def _linkage_fits(scene: Any) -> None:
    """One row of panels per position: refuse more than the page holds before any work is done."""
    from graphmech.problems.linkage.check import rows_that_fit

    page = _page(scene)
    fit = rows_that_fit(page)
    if len(scene.positions.values) > fit:
        raise SceneError([("driver", f"{len(scene.positions.values)} positions do not fit one sheet of "
                                     f"{page[0]:g} × {page[1]:g} mm (at most {fit}, one row of panels each): "
                                     "split the scene or choose a larger [page] size; `graphmech check` "
                                     "takes up to 3600")], scene.source)


def _linkage_extras(an: Any) -> dict[str, Any]:
    if an.instant_centres is None:
        return {}
    from graphmech.problems.instant_centres.check import summary

    return {"instant_centres": summary(an)}


# ---------------------------------------------------------------------------- cycle, cam


def _cycle_sheet(scene: Any, footer: Footer) -> tuple[Any, list[str]]:
    from graphmech.problems.cycle.figures import cycle_sheet

    an = _analyse_cycle(scene, ())
    return cycle_sheet(scene.title, an, list(scene.show), _page(scene), footer), list(an.warnings)


def _cam_sheet(scene: Any, footer: Footer) -> tuple[Any, list[str]]:
    from graphmech.problems.cam.figures import cam_sheet

    an = _analyse_cam(scene, (), estimates=False)  # a drawing needs no error estimates
    sheet = cam_sheet(scene.title, an.cam, an.drawn, an.scales, list(scene.show), _page(scene),
                      roller_circles=scene.cam.roller_circles, marks=an.marks, footer=footer)
    return sheet, list(an.warnings)


def _cam_extras(an: Any) -> dict[str, Any]:
    return {"impacts": an.impacts, **({"divisions": an.divisions} if an.divisions else {})}


# ---------------------------------------------------------------------------- flywheel


def _flywheel_sheet(scene: Any, footer: Footer) -> tuple[Any, list[str]]:
    from graphmech.problems.flywheel.figures import flywheel_sheet
    from graphmech.drawing.primitives import Sheet

    an = _analyse_flywheel(scene, (), estimates=False)  # a drawing needs no error estimates
    cycle_panels = [p for p in scene.show if p not in ("mechanism", "rundown")]
    if an.design is None and not any(p in scene.show for p in ("mechanism", "rundown")):
        raise SceneError([("show", "nothing to draw: this flywheel scene asks for no diagram; "
                                   "use graphmech check")], scene.source)
    panels: list[Any] = []
    if "mechanism" in scene.show and scene.linkage is not None:
        panels += _mechanism_at_position_1(scene, footer)
    if cycle_panels and an.design is not None:
        panels += flywheel_sheet(scene.title, an.design, cycle_panels, _page(scene), footer).panels
    if "rundown" in scene.show:
        from graphmech.problems.flywheel.braking_figures import rundown_panel

        b = scene.flywheel.braking
        panels.append(rundown_panel(an.braking_inertia, scene.flywheel.machine.omega_m, b.moment, b.time_limit))
    return Sheet(scene.title, tuple(panels), _page(scene), footer), list(an.warnings)


def _mechanism_at_position_1(scene: Any, footer: Footer) -> list[Any]:
    """A flywheel scene's mechanism, drawn at position 1 (where φ = 0) as a linkage scene would."""
    from graphmech.mechanisms.linkage import Positions

    first = Positions(scene.positions.values[:1], scene.positions.labels[:1])
    lscene = dataclasses.replace(scene, show=("mechanism",), find=(), measured=(), flywheel=None, positions=first)
    sheet, _ = _linkage_sheet(lscene, footer, caption="position 1 (φ = 0), ")
    return [dataclasses.replace(p, row=0) for p in sheet.panels]


def _flywheel_extras(an: Any) -> dict[str, Any]:
    out = {}
    if an.motion is not None:
        out["true_motion"] = an.motion_summary()
    if an.braking is not None:
        out["braking"] = an.braking_summary()
    return out


def _flywheel_lines(an: Any) -> list[str]:
    if an.braking is None:
        return []
    br = an.braking_summary()
    verdict = "" if br["ok"] is None else (f" ≤ {br['time_limit']:g} s: meets the requirement" if br["ok"]
                                           else f" > {br['time_limit']:g} s: DOES NOT meet the requirement")
    return [f"stopping time {br['t_stop']:.6g} s{verdict}"]


# ---------------------------------------------------------------------------- forces


def _forces_sheet(scene: Any, footer: Footer) -> tuple[Any, list[str]]:
    from graphmech.problems.forces.check import render_forces

    return render_forces(scene, footer)


def _forces_extras(an: Any) -> dict[str, Any]:
    return {"friction": an.friction_summary()} if an.scene.forces.model.has_friction else {}


def _efficiency_sheet(scene: Any, footer: Footer) -> tuple[Any, list[str]]:
    from graphmech.problems.efficiency.check import efficiency_figure

    an = _analyse_efficiency(scene, ())
    return efficiency_figure(an, _page(scene), footer), list(an.warnings)


def _balancing_sheet(scene: Any, footer: Footer) -> tuple[Any, list[str]]:
    from graphmech.problems.balancing.check import balancing_figure

    an = _analyse_balancing(scene, ())
    return balancing_figure(an, _page(scene), footer), list(an.warnings)


# ---------------------------------------------------------------------------- structure


def _structure_analyse(scene: Any, extra: Extra) -> Any:
    from graphmech.problems.structure.check import analyse_structure

    return analyse_structure(scene)


def _structure_judge(an: Any, extra: Extra) -> list[Any]:
    from graphmech.problems.structure.check import judge_structure

    return judge_structure(an, extra)


def _structure_sheet(scene: Any, footer: Footer) -> tuple[Any, list[str]]:
    from graphmech.problems.structure.figures import structure_sheet

    an = _structure_analyse(scene, ())
    return structure_sheet(scene.title, an, _page(scene), footer), list(an.warnings)


def _structure_lines(an: Any) -> list[str]:
    from graphmech.problems.structure.check import text_summary

    return text_summary(an)


KINDS: dict[str, Kind] = {
    "linkage": Kind("linkage", _analyse_linkage, _judge_linkage, _linkage_sheet, _linkage_extras),
    "cycle": Kind("cycle", _analyse_cycle, _judge_cycle, _cycle_sheet, lambda an: dict(an.summary),
                  lambda an: an.summary_lines()),
    "cam": Kind("cam", _analyse_cam, _judge_cam, _cam_sheet, _cam_extras),
    "flywheel": Kind("flywheel", _analyse_flywheel, _judge_flywheel, _flywheel_sheet, _flywheel_extras,
                     _flywheel_lines),
    "forces": Kind("forces", _analyse_forces, lambda an, extra: an.verdicts, _forces_sheet, _forces_extras),
    "efficiency": Kind("efficiency", _analyse_efficiency, _judge_efficiency, _efficiency_sheet),
    "balancing": Kind("balancing", _analyse_balancing, _judge_balancing, _balancing_sheet),
    "structure": Kind("structure", _structure_analyse, _structure_judge, _structure_sheet,
                      lambda an: {"structure": an.summary()}, _structure_lines),
}


def check(scene: Any, extra: Extra = ()) -> tuple[Any, list[Any], dict[str, Any], list[str]]:
    """Analyse a scene and judge its measured values: (analysis, verdicts, JSON extras, text lines)."""
    kind = kind_of(scene)
    an = kind.analyse(scene, tuple(extra))
    return an, kind.judge(an, tuple(extra)), kind.extras(an), kind.lines(an)


def sheet(scene: Any, footer: Footer = ()) -> tuple[Any, list[str]]:
    """The drawing of a scene and the warnings found while making it."""
    return kind_of(scene).sheet(scene, footer)


__all__ = ["KINDS", "Kind", "check", "kind_of", "sheet", "with_precision"]
