"""A linkage through a whole cycle (``[cycle]``) and the characteristics of its basic loop
(``[characteristics]``): N positions on one sheet, coupler curves, s–φ read off the drawing and
differentiated by chords, Grashof's class, extreme positions, K, the least transmission angle.

The scene is read by the linkage's reader (a full cycle is a linkage scene that asks for more);
check.py, figures.py and bench.py are this kind's own.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, cast

from graphmech.problems.kind import Bench, Extra, Footer, Kind

if TYPE_CHECKING:  # annotations only: the kind's modules load when first used
    from graphmech.drawing.primitives import Sheet
    from graphmech.problems.cycle.check import CycleAnalysis
    from graphmech.problems.cycle.scene import CycleScene
    from graphmech.problems.judging import Verdict
    from graphmech.problems.reader import Reader, Scene


def _read(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]) -> Scene[CycleScene]:
    from graphmech.problems.linkage.scene import parse_linkage_scene

    return cast("Scene[CycleScene]", parse_linkage_scene(data, source, top, order))  # a cycle scene: its kind says so


def _analyse(scene: Scene[CycleScene], extra: Extra) -> CycleAnalysis:
    from graphmech.problems.cycle.check import analyse_cycle

    return analyse_cycle(scene, extra)


def _judge(an: CycleAnalysis, extra: Extra) -> list[Verdict]:
    from graphmech.problems.cycle.check import judge_cycle

    return judge_cycle(an)


def _sheet(scene: Scene[CycleScene], footer: Footer) -> tuple[Sheet, list[str]]:
    from graphmech.problems.cycle.check import analyse_cycle
    from graphmech.problems.cycle.figures import cycle_sheet
    from graphmech.problems.judging import finite
    from graphmech.problems.reader import page_size

    an = finite(analyse_cycle(scene, (), diagram_errors=False))  # the figure shows no diagram's error
    return cycle_sheet(scene.title, an, list(scene.show), page_size(scene), footer), list(an.warnings)


def _bench(quick: bool) -> Bench:
    from graphmech.problems.cycle.bench import bench

    return bench(quick)


def _steps(scene: Scene[CycleScene]) -> list[str]:
    from graphmech.problems.cycle.steps import cycle_steps

    return cycle_steps(scene)


KIND = Kind("cycle", ("cycle", "characteristics"), _read, _analyse, _judge, _sheet,
            lambda an: dict(an.summary), lambda an: an.summary_lines(), bench=_bench, steps=_steps)
