"""Efficiency and self-locking (``[efficiency]``): a block on an inclined plane, a wedge, square
and V threads, chains of machines — force polygons with friction, η, the self-locking limit,
checked against the closed-form trigonometric answers.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, cast

from graphmech.problems.kind import Bench, Extra, Footer, Kind

if TYPE_CHECKING:  # annotations only: the kind's modules load when first used
    from graphmech.drawing.primitives import Sheet
    from graphmech.problems.efficiency.check import EfficiencyAnalysis
    from graphmech.problems.efficiency.scene import EfficiencyProblem
    from graphmech.problems.judging import Verdict
    from graphmech.problems.reader import Reader, Scene


def _read(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]) -> Scene[EfficiencyProblem]:
    from graphmech.problems.efficiency.scene import parse_efficiency_scene

    return cast("Scene[EfficiencyProblem]", parse_efficiency_scene(data, source, top, order))  # an efficiency scene: its kind says so


def _analyse(scene: Scene[EfficiencyProblem], extra: Extra) -> EfficiencyAnalysis:
    from graphmech.problems.efficiency.check import analyse_efficiency

    return analyse_efficiency(scene, extra)


def _judge(an: EfficiencyAnalysis, extra: Extra) -> list[Verdict]:
    from graphmech.problems.efficiency.check import judge_efficiency

    return judge_efficiency(an)


def _sheet(scene: Scene[EfficiencyProblem], footer: Footer) -> tuple[Sheet, list[str]]:
    from graphmech.problems.efficiency.check import analyse_efficiency, efficiency_figure
    from graphmech.problems.judging import finite
    from graphmech.problems.reader import page_size

    an = finite(analyse_efficiency(scene, ()))
    return efficiency_figure(an, page_size(scene), footer), list(an.warnings)


def _bench(quick: bool) -> Bench:
    from graphmech.problems.efficiency.bench import bench

    return bench(quick)


def _steps(scene: Scene[EfficiencyProblem]) -> list[str]:
    from graphmech.problems.efficiency.steps import efficiency_steps

    return efficiency_steps(scene)


KIND = Kind("efficiency", ("efficiency",), _read, _analyse, _judge, _sheet, bench=_bench, steps=_steps)
