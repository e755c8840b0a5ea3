"""Mobility and structure (``[structure]``): the Grübler–Kutzbach count against the rank of the
constraints' Jacobian (redundant constraints), the split into drivers and Assur groups, the
mechanism's class; the links, pairs and groups drawn.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from graphmech.problems.kind import Extra, Footer, Kind

if TYPE_CHECKING:  # annotations only: the kind's modules load when first used
    from graphmech.drawing.primitives import Sheet
    from graphmech.problems.judging import Verdict
    from graphmech.problems.reader import Reader, Scene
    from graphmech.problems.structure.check import StructureAnalysis
    from graphmech.problems.structure.scene import StructureScene


def _read(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]) -> Scene[StructureScene]:
    from graphmech.problems.structure.scene import parse_structure_scene

    return parse_structure_scene(data, source, top, order)


def _analyse(scene: Scene[StructureScene], extra: Extra) -> StructureAnalysis:
    from graphmech.problems.structure.check import analyse_structure

    return analyse_structure(scene)


def _judge(an: StructureAnalysis, extra: Extra) -> list[Verdict]:
    from graphmech.problems.structure.check import judge_structure

    return judge_structure(an, extra)


def _sheet(scene: Scene[StructureScene], footer: Footer) -> tuple[Sheet, list[str]]:
    from graphmech.problems.judging import finite
    from graphmech.problems.reader import page_size
    from graphmech.problems.structure.check import analyse_structure
    from graphmech.problems.structure.figures import structure_sheet

    an = finite(analyse_structure(scene))
    return structure_sheet(scene.title, an, page_size(scene), footer, scene.page.notation), list(an.warnings)


def _lines(an: StructureAnalysis) -> list[str]:
    from graphmech.problems.structure.check import text_summary

    return text_summary(an)


def _steps(scene: Scene[StructureScene]) -> list[str]:
    from graphmech.problems.structure.steps import structure_steps

    return structure_steps(scene)


KIND = Kind("structure", ("structure",), _read, _analyse, _judge, _sheet,
            lambda an: {"structure": an.summary()}, _lines, steps=_steps)
