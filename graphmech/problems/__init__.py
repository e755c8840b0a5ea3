"""The kinds of problem a scene poses — the one list of them — and, for any scene, its check and
its drawing.

A scene file is one problem: a linkage (its polygons, instant centres), a full cycle, a disc
cam, involute gears, a flywheel, a kinetostatic analysis, an efficiency or a balancing problem, a structure, a gear train, a linkage's synthesis, a Geneva wheel or a differential screw, or wheels in rolling contact
stated by their direct instant centres.
Each kind lives in its own package ``graphmech/problems/<kind>/`` and states its
:class:`~graphmech.problems.kind.Kind` there (its tables, reader, check, sheet, bench);
:data:`KINDS` below is the only place that lists them, so the scene loader, ``check``,
``render`` and ``bench`` treat every kind alike. Adding a kind: docs/adding-a-kind.md.

Importing this module imports each kind's ``__init__`` (its Kind record) and the reading toolkit,
nothing of a kind's own: its reader, check, figures and bench are imported when a scene of that
kind is read, checked or drawn; never scipy, shapely or matplotlib (tests/test_layout.py).
"""
from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING, Any

from graphmech.problems import (balancing, cam, centres, cycle, efficiency, flywheel, forces, gears, linkage, other,
                                structure, synthesis, trains)
from graphmech.errors import NotApplicable
from graphmech.problems.kind import Analysis, Extra, Footer, Kind

if TYPE_CHECKING:  # annotations only: importing the registry stays light
    from graphmech.drawing.primitives import Sheet
    from graphmech.problems.judging import Verdict
    from graphmech.problems.reader import Scene

#: Every kind, by name, in the order a scene file is matched against them: the first whose
#: tables the file has reads it (a structure scene may hold a linkage's tables too; a scene
#: that poses nothing else is a linkage).
#: (Each kind has its own problem and analysis types; the registry holds them side by side.)
KINDS: dict[str, Kind[Any, Any]] = {k.name: k for k in (
    structure.KIND, forces.KIND, efficiency.KIND, balancing.KIND, cam.KIND, gears.KIND, flywheel.KIND, cycle.KIND,
    trains.KIND, synthesis.KIND, other.KIND, centres.KIND, linkage.KIND,
)}


def kind_of(scene: Scene[Any]) -> Kind[Any, Any]:
    """The kind of problem ``scene`` poses (exactly one: the scene reader refuses mixtures)."""
    return KINDS[scene.kind]


def tables() -> tuple[str, ...]:
    """Every kind's own top-level tables (``"cam"``, ``"flywheel"`` …), in the order of :data:`KINDS`."""
    return tuple(t for k in KINDS.values() for t in k.tables)


def with_precision(scene: Scene[Any], precision_mm: float | None) -> Scene[Any]:
    """The scene with the drawing precision a user gave on the command line (None: the scene's own)."""
    return scene if precision_mm is None else dataclasses.replace(scene, precision_mm=precision_mm)


def check(scene: Scene[Any], extra: Extra = ()) -> tuple[Analysis, list[Verdict], dict[str, Any], list[str]]:
    """Analyse a scene and judge its measured values: (analysis, verdicts, JSON extras, text lines);
    a value as written is judged by its digits and sign, whatever the kind (judging.as_written)."""
    from graphmech.problems.judging import as_written

    an, verdicts, doc, lines = kind_of(scene).check(scene, extra)
    return an, [as_written(v) for v in verdicts], doc, lines


def timings(scene: Scene[Any], an: Analysis) -> list[str]:
    """How long the check of ``scene`` spent where it is worth saying (the true motion's
    integration): lines for ``graphmech check``'s text table alone, since they differ run to run."""
    return kind_of(scene).timings(an)


def sheet(scene: Scene[Any], footer: Footer = ()) -> tuple[Sheet, list[str]]:
    """The drawing of a scene and the warnings found while making it; the page as ``[page]``
    says (cropped to the content for ``size = "fit"``, a title block) — one place for every kind."""
    drawing, warnings = kind_of(scene).sheet(scene, footer)
    return dataclasses.replace(drawing, fit=scene.page.fit, title_block=scene.page.title_block), warnings


def steps(scene: Scene[Any]) -> list[str]:
    """The construction protocol of a scene: its steps as the book words them, in the scene's
    notation, with every length drawn and every value read; one line per step, not numbered (the
    caller numbers them). A kind without a protocol yet is refused in one line."""
    kind = kind_of(scene)
    if kind.steps is None:
        with_one = ", ".join(k.name for k in KINDS.values() if k.steps is not None)
        raise NotApplicable(f"no construction protocol for a {kind.name} scene yet (graphmech steps covers: {with_one})")
    return kind.steps(scene)


__all__ = ["KINDS", "Kind", "check", "kind_of", "sheet", "steps", "tables", "timings", "with_precision"]
