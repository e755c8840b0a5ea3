"""What a kind of problem is to the rest of graphmech: one record, :class:`Kind`.

A kind (a linkage, a disc cam, a flywheel …) lives in its own package
``graphmech/problems/<kind>/``: ``scene.py`` reads its tables, ``check.py`` analyses and judges,
``figures.py`` draws, ``bench.py`` times its methods. The package's ``__init__.py`` states its
``KIND``; :mod:`graphmech.problems` lists the kinds once, and everything else — the scene
loader, ``check``, ``render``, ``bench`` — goes through that list.

A kind's ``__init__`` imports nothing of the kind's own: its reader, check, figures and bench
are imported by the record's functions when first called, so that starting graphmech does not
load the code (and scipy, shapely) of every kind — only that of the scene at hand.
"""
from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Generic, TypeVar

from graphmech.problems.judging import A, Analysis, finite

if TYPE_CHECKING:  # for the annotations only: the registry stays light at start-up
    from graphmech.drawing.primitives import Sheet
    from graphmech.problems.judging import Verdict
    from graphmech.problems.reader import Reader, Scene

#: Measured values given on the command line: (name, value).
Extra = tuple[tuple[str, float], ...]
#: Lines printed under a drawing (the command that made it).
Footer = tuple[str, ...]
#: Benchmark records (dicts with "method", "case", "n", "seconds", "max_rel_error" …) and notes.
Bench = tuple[list[dict[str, Any]], list[str]]


#: A kind's problem, ``Scene.problem`` (a CamScene, a FlywheelScene …).
P = TypeVar("P")


def _no_extras(an: Analysis) -> dict[str, Any]:
    return {}


def _no_lines(an: Analysis) -> list[str]:
    return []


@dataclass(frozen=True)
class Kind(Generic[P, A]):
    """One kind of problem: how a scene poses it, how it is read, checked, drawn and timed.

    name : the kind's name, ``Scene.kind`` (``"cam"``).
    tables : the top-level TOML tables that pose it (``("cam",)``); also offered as
        suggestions for a misspelt top-level key in any scene.
    read(data, source, top, order) → Scene : the rest of the reading once the common
        tables are known (``top`` is the reader of the whole file, ``order`` its keys' order).
    analyse(scene, extra) → analysis with ``rows``, ``warnings``, ``scales``, ``scale_notes()``.
    judge(analysis, extra) → verdicts on the measured values (the precision is the scene's).
    sheet(scene, footer) → the drawing and the warnings found while making it.
    extras(analysis) → what ``check --json`` adds; lines(analysis) → lines under the text table.
    timings(analysis) → wall times under ``graphmech check``'s text table alone (they differ from
        run to run: not in ``--json``, nor in the gallery).
    bench(quick) → benchmark records and notes for ``graphmech bench`` (None: none of its own).
    poses(data) → whether a scene file poses this kind (default: it has one of ``tables``).
    mixture(data) → (key path, reason) refusing a scene that mixes this kind with another,
        or None.
    steps(scene) → the construction protocol, one line per step, not numbered (``graphmech
        steps``); None: this kind has none yet.
    """

    name: str
    tables: tuple[str, ...]
    read: Callable[[Mapping[str, Any], str, Reader, Mapping[str, int]], Scene[P]]
    analyse: Callable[[Scene[P], Extra], A]
    judge: Callable[[A, Extra], list[Verdict]]
    sheet: Callable[[Scene[P], Footer], tuple[Sheet, list[str]]]
    extras: Callable[[A], dict[str, Any]] = _no_extras
    lines: Callable[[A], list[str]] = _no_lines
    bench: Callable[[bool], Bench] | None = None
    poses: Callable[[Mapping[str, Any]], bool] | None = None
    mixture: Callable[[Mapping[str, Any]], tuple[str, str] | None] | None = None
    steps: Callable[[Scene[P]], list[str]] | None = None
    timings: Callable[[A], list[str]] = _no_lines

    def posed_by(self, data: Mapping[str, Any]) -> bool:
        """Whether the scene file ``data`` poses this kind of problem."""
        return self.poses(data) if self.poses is not None else any(t in data for t in self.tables)

    def check(self, scene: Scene[P], extra: Extra = ()) -> tuple[A, list[Verdict], dict[str, Any], list[str]]:
        """Analyse a scene and judge its measured values: (analysis, verdicts, JSON extras, text
        lines). Whatever the analysis finds is finite, or refused in words."""
        an = finite(self.analyse(scene, tuple(extra)))
        return an, self.judge(an, tuple(extra)), self.extras(an), self.lines(an)


__all__ = ["Analysis", "Bench", "Extra", "Footer", "Kind"]
