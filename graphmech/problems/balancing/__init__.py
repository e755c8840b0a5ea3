"""Balancing of rotors (``[balancing]``): static (one plane) and dynamic (two correction planes)
mass-radius polygons, the correction read off the closing side, checked against the equations
of balance. Read by the efficiency kind's reader (both are problems of forces alone).
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, cast

from graphmech.problems.kind import Extra, Footer, Kind

if TYPE_CHECKING:  # annotations only: the kind's modules load when first used
    from graphmech.drawing.primitives import Sheet
    from graphmech.problems.balancing.check import BalancingAnalysis
    from graphmech.problems.balancing.scene import BalancingProblem
    from graphmech.problems.judging import Verdict
    from graphmech.problems.reader import Reader, Scene


def _read(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]) -> Scene[BalancingProblem]:
    from graphmech.problems.efficiency.scene import parse_efficiency_scene

    return cast("Scene[BalancingProblem]", parse_efficiency_scene(data, source, top, order))  # a balancing scene: its kind says so


def _analyse(scene: Scene[BalancingProblem], extra: Extra) -> BalancingAnalysis:
    from graphmech.problems.balancing.check import analyse_balancing

    return analyse_balancing(scene, extra)


def _judge(an: BalancingAnalysis, extra: Extra) -> list[Verdict]:
    from graphmech.problems.balancing.check import judge_balancing

    return judge_balancing(an)


def _sheet(scene: Scene[BalancingProblem], footer: Footer) -> tuple[Sheet, list[str]]:
    from graphmech.problems.balancing.check import analyse_balancing, balancing_figure
    from graphmech.problems.judging import finite
    from graphmech.problems.reader import page_size

    an = finite(analyse_balancing(scene, ()))
    return balancing_figure(an, page_size(scene), footer), list(an.warnings)


def _steps(scene: Scene[BalancingProblem]) -> list[str]:
    from graphmech.problems.balancing.steps import balancing_steps

    return balancing_steps(scene)


# its records ("mass-radius-polygon") are timed with the efficiency kind's, as one bench of forces alone
KIND = Kind("balancing", ("balancing",), _read, _analyse, _judge, _sheet, steps=_steps)
