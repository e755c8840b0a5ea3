"""Efficiency and self-locking (``[efficiency]``): a block on an inclined plane, a wedge, square
and V threads, chains of machines — force polygons with friction, η, the self-locking limit,
checked against the closed-form trigonometric answers.
"""
from __future__ import annotations

from typing import Any

from graphmech.problems.kind import Bench, Extra, Footer, Kind


def _read(data: Any, source: str, top: Any, order: Any) -> Any:
    from graphmech.problems.efficiency.scene import parse_efficiency_scene

    return parse_efficiency_scene(data, source, top, order)


def _analyse(scene: Any, extra: Extra) -> Any:
    from graphmech.problems.efficiency.check import analyse_efficiency

    return analyse_efficiency(scene, extra)


def _judge(an: Any, extra: Extra) -> list[Any]:
    from graphmech.problems.efficiency.check import judge_efficiency

    return judge_efficiency(an)


def _sheet(scene: Any, footer: Footer) -> Any:
    from graphmech.problems.efficiency.check import analyse_efficiency, efficiency_figure
    from graphmech.problems.judging import finite
    from graphmech.problems.reader import page_size

    an = finite(analyse_efficiency(scene, ()))
    return efficiency_figure(an, page_size(scene), footer), list(an.warnings)


def _bench(quick: bool) -> Bench:
    from graphmech.problems.efficiency.bench import bench

    return bench(quick)


KIND = Kind("efficiency", ("efficiency",), _read, _analyse, _judge, _sheet, bench=_bench)
