"""A linkage through a whole cycle (``[cycle]``) and the characteristics of its basic loop
(``[characteristics]``): N positions on one sheet, coupler curves, s–φ read off the drawing and
differentiated by chords, Grashof's class, extreme positions, K, the least transmission angle.

The scene is read by the linkage's reader (a full cycle is a linkage scene that asks for more);
check.py, figures.py and bench.py are this kind's own.
"""
from __future__ import annotations

from typing import Any

from graphmech.problems.kind import Bench, Extra, Footer, Kind


def _read(data: Any, source: str, top: Any, order: Any) -> Any:
    from graphmech.problems.linkage.scene import parse_linkage_scene

    return parse_linkage_scene(data, source, top, order)


def _analyse(scene: Any, extra: Extra) -> Any:
    from graphmech.problems.cycle.check import analyse_cycle

    return analyse_cycle(scene, extra)


def _judge(an: Any, extra: Extra) -> list[Any]:
    from graphmech.problems.cycle.check import judge_cycle

    return judge_cycle(an)


def _sheet(scene: Any, footer: Footer) -> Any:
    from graphmech.problems.cycle.check import analyse_cycle
    from graphmech.problems.cycle.figures import cycle_sheet
    from graphmech.problems.judging import finite
    from graphmech.problems.reader import page_size

    an = finite(analyse_cycle(scene, ()))
    return cycle_sheet(scene.title, an, list(scene.show), page_size(scene), footer), list(an.warnings)


def _bench(quick: bool) -> Bench:
    from graphmech.problems.cycle.bench import bench

    return bench(quick)


KIND = Kind("cycle", ("cycle", "characteristics"), _read, _analyse, _judge, _sheet,
            lambda an: dict(an.summary), lambda an: an.summary_lines(), bench=_bench)
