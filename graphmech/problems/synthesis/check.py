"""Checking a synthesis scene: each designed linkage's lengths measured on the construction at μl
against the closed forms, then the linkage re-analysed (drawn and exact) — its K, ψ, γ_min in the
table, the re-analysis error against what was asked under it, with Grashof's class.

The task's own analysis lives in its module (``time_ratio``); this module holds what every task
shares: the analysis record, the scale μl, the names ``find`` may ask for and the verdicts.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from graphmech.errors import SceneError
from graphmech.problems.judging import (
    Row,
    Verdict,
    close_names,
    judge_value,
    measured_entries,
)
from graphmech.problems.synthesis import function, positions, time_ratio
from graphmech.scales import drawn_size_problem, format_scale

if TYPE_CHECKING:
    from graphmech.exact.synthesis import Design
    from graphmech.methods.synthesis_time_ratio import (
        DrawnDesign,
        DrawnGuideBar,
        DrawnSlider,
    )
    from graphmech.problems.reader import Scene
    from graphmech.problems.synthesis.scene import SynthesisScene


#: The tasks that analyse, word and draw themselves, by task name. Each module gives ``size(p)``,
#: ``choose_scale(p)``, ``analyse(p, mu, find, source)`` (a record with ``rows``, ``warnings``,
#: ``solutions``, ``names``), ``lines(found)``, ``panels(found, mu)`` (the sheet's title and
#: panels), ``steps(found, mu, say, num)`` and ``PHRASES``. The time-ratio task predates it and is
#: wired below by hand.
SELF_CONTAINED: dict[str, Any] = {"positions": positions, "function": function}


@dataclass
class SynthesisAnalysis:
    """What one synthesis scene produced: the drawn and the exact designs (paired by order), the
    rows, the warnings, μl and, per design, what ``check --json`` adds (``solutions``)."""

    scene: Scene[SynthesisScene]
    rows: list[Row] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    scales: dict[str, float] = field(default_factory=dict)
    stated: set[str] = field(default_factory=set)
    drawn: list[DrawnDesign] = field(default_factory=list)
    exact: list[Design] = field(default_factory=list)
    solutions: list[dict[str, Any]] = field(default_factory=list)
    guide: DrawnGuideBar | None = None
    slider: DrawnSlider | None = None
    extra_measured: tuple[tuple[str, float], ...] = ()
    #: a self-contained task's record (:data:`SELF_CONTAINED`; None for the time-ratio task)
    found: Any = None

    def scale_notes(self) -> list[str]:
        return [format_scale(k, v) + ("" if k in self.stated else " (chosen)") for k, v in self.scales.items()]


def analyse_synthesis(scene: Scene[SynthesisScene], extra: tuple[tuple[str, float], ...] = ()) -> SynthesisAnalysis:
    """Draw the scene's designs and build the check table."""
    an = SynthesisAnalysis(scene, extra_measured=tuple(extra))
    p: Any = scene.problem.problem
    own = SELF_CONTAINED.get(scene.problem.task)
    task: Any = own or time_ratio
    if "l" in scene.scales:
        an.scales["l"] = scene.scales["l"]
        an.stated.add("l")
        why = drawn_size_problem(task.size(p), scene.scales["l"])
        if why:
            raise SceneError([("scales", why)], scene.source)
    else:
        an.scales["l"] = task.choose_scale(p)
    if own is not None:
        pf = own.analyse(p, an.scales["l"], scene.find, scene.source)
        an.found, an.rows, an.warnings, an.solutions = pf, pf.rows, pf.warnings, pf.solutions
        known = pf.names
    else:
        found = time_ratio.analyse_time_ratio(p, an.scales["l"], scene.find, scene.source)
        an.drawn, an.exact, an.rows, an.warnings, an.solutions = (found.drawn, found.exact, found.rows,
                                                                   found.warnings, found.solutions)
        an.guide, an.slider = found.guide, found.slider
        known = found.names
    wrong = [(f"find[{i}]", _unknown(n, known, len(an.exact))) for i, n in enumerate(scene.find) if n not in known]
    wrong += [(key, _unknown(n, known, len(an.exact)))
              for key, n, _ in measured_entries(scene, an.extra_measured) if n not in known]
    if wrong:
        raise SceneError(wrong, scene.source)
    return an


def _unknown(name: str, known: list[str], count: int) -> str:
    """Why ``name`` is not a row, with the name meant: a design's prefix that the count of designs
    does not take (one design: ``lAB``; several: ``sol1_lAB`` …) is said as such."""
    bare = name.split("_", 1)[1] if name.startswith("sol") and "_" in name else name
    if count == 1 and bare in known:
        return f"unknown synthesis quantity {name!r}: the construction gives one design, its names take no sol prefix ({bare})"
    if count > 1 and f"sol1_{bare}" in known:
        return (f"unknown synthesis quantity {name!r}: the construction gives {count} designs, "
                f"sol1_{bare} … sol{count}_{bare}")
    return f"unknown synthesis quantity {name!r}{close_names(name, known)}"


def judge_synthesis(an: SynthesisAnalysis) -> list[Verdict]:
    """Hand values against the construction: a length within the drawing precision × μl, a
    computed value (θ, K, an angle) within 0.1 %."""
    rows = {r.name: r for r in an.rows}
    out = []
    for key, name, value in measured_entries(an.scene, an.extra_measured):
        if name not in rows:
            raise SceneError([(key, f"{name} is not in the check table (its find leaves it out)")], an.scene.source)
        r = rows[name]
        out.append(judge_value(name, value, r.graphical, r.drawn_mm, r.scale, an.scene.precision_mm, r.unit))
    return out


def text_lines(an: SynthesisAnalysis) -> list[str]:
    """Under the table: each design's Grashof class and its re-analysis error."""
    p: Any = an.scene.problem.problem
    own = SELF_CONTAINED.get(an.scene.problem.task)
    if own is not None:
        return list(own.lines(an.found))
    return [time_ratio.grashof_line(s, p) for s in an.solutions]


__all__ = ["SELF_CONTAINED", "SynthesisAnalysis", "analyse_synthesis", "judge_synthesis", "text_lines"]
