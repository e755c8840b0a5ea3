"""Balancing of rotors (``[balancing]``): static (one plane) and dynamic (two correction planes)
mass-radius polygons, the correction read off the closing side, checked against the equations
of balance. Read by the efficiency kind's reader (both are problems of forces alone).
"""
from __future__ import annotations

from typing import Any

from graphmech.problems.kind import Extra, Footer, Kind


def _read(data: Any, source: str, top: Any, order: Any) -> Any:
    from graphmech.problems.efficiency.scene import parse_efficiency_scene

    return parse_efficiency_scene(data, source, top, order)


def _analyse(scene: Any, extra: Extra) -> Any:
    from graphmech.problems.balancing.check import analyse_balancing

    return analyse_balancing(scene, extra)


def _judge(an: Any, extra: Extra) -> list[Any]:
    from graphmech.problems.balancing.check import judge_balancing

    return judge_balancing(an)


def _sheet(scene: Any, footer: Footer) -> Any:
    from graphmech.problems.balancing.check import analyse_balancing, balancing_figure
    from graphmech.problems.judging import finite
    from graphmech.problems.reader import page_size

    an = finite(analyse_balancing(scene, ()))
    return balancing_figure(an, page_size(scene), footer), list(an.warnings)


# its records ("mass-radius-polygon") are timed with the efficiency kind's, as one bench of forces alone
KIND = Kind("balancing", ("balancing",), _read, _analyse, _judge, _sheet)
