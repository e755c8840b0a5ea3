"""Read a synthesis scene: the ``[synthesis]`` table, dispatched on its ``task``.

Each task reads the rest of the table in its own module (``time_ratio``: design from the time
ratio K); a task still to come is refused by name. The format is in ``docs/scene-format.md``
("Synthesis scenes").
"""
from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from graphmech.problems.reader import (
    Reader,
    Scene,
    raise_sorted,
    read_header,
    read_measured,
    read_scales,
    read_tail,
)
from graphmech.problems.synthesis.function import FunctionProblem, read_function
from graphmech.problems.synthesis.positions import PositionsProblem, read_positions
from graphmech.problems.synthesis.time_ratio import Problem, read_time_ratio

#: What a synthesis scene may show: the construction with the designed linkages.
SYNTHESIS_SHOW_CHOICES = ("design",)
#: The tasks and their readers (the function task of issue 20 joins here).
TASKS: dict[str, Callable[[Reader], Problem | PositionsProblem | FunctionProblem | None]] = {
    "time_ratio": read_time_ratio, "positions": read_positions, "function": read_function}


@dataclass(frozen=True)
class SynthesisScene:
    """What [synthesis] asks: its task and that task's problem (a :class:`TimeRatio` …)."""

    task: str
    problem: Problem | PositionsProblem | FunctionProblem


def parse_synthesis_scene(data: Mapping[str, Any], source: str, top: Reader,
                          order: Mapping[str, int]) -> Scene[SynthesisScene]:
    """The whole scene file → ``Scene[SynthesisScene]``, or every problem in file order."""
    title, show, find = read_header(top, SYNTHESIS_SHOW_CHOICES, SYNTHESIS_SHOW_CHOICES)
    scales = read_scales(top, entries=(("l", "length"),))
    problem = None
    r = top.table_at("synthesis", required=True)
    task = None
    if r is not None:
        task = r.string("task", choices=tuple(TASKS), required=True)
        if task is not None:
            problem = TASKS[task](r)
        else:
            r.ignore(*r.table)
        r.finish()
    measured = read_measured(top, None)
    precision, page = read_tail(top)
    if top.problems or problem is None or task is None:
        raise_sorted(top.problems, data, order, "synthesis", source)
    return Scene(source=source, title=title, show=show, find=find, scales=scales, measured=measured,
                 precision_mm=precision, page=page, kind="synthesis", problem=SynthesisScene(task, problem))


__all__ = ["SYNTHESIS_SHOW_CHOICES", "TASKS", "SynthesisScene", "parse_synthesis_scene"]
