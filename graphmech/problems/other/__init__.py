"""Other common mechanisms (其他常用机构): the Geneva wheel (``[geneva]``: its sizes, motion
coefficient, period and the wheel's ω₂, ε₂ by the pin's polygons, drawn at μl with its slots,
pin and locking arcs) and the differential screw (``[differential_screw]``: screw B's lead on
both branches, or link 2's travel per turn).
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from graphmech.problems.kind import Extra, Footer, Kind

if TYPE_CHECKING:  # annotations only: the kind's modules load when first used
    from graphmech.drawing.primitives import Sheet
    from graphmech.problems.judging import Verdict
    from graphmech.problems.other.check import OtherAnalysis
    from graphmech.problems.other.scene import OtherScene
    from graphmech.problems.reader import Reader, Scene


def _read(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]) -> Scene[OtherScene]:
    from graphmech.problems.other.scene import parse_other_scene

    return parse_other_scene(data, source, top, order)


def _analyse(scene: Scene[OtherScene], extra: Extra) -> OtherAnalysis:
    from graphmech.problems.other.check import analyse_other

    return analyse_other(scene, extra)


def _judge(an: OtherAnalysis, extra: Extra) -> list[Verdict]:
    from graphmech.problems.other.check import judge_other

    return judge_other(an)


def _sheet(scene: Scene[OtherScene], footer: Footer) -> tuple[Sheet, list[str]]:
    from graphmech.problems.judging import finite
    from graphmech.problems.other.check import analyse_other
    from graphmech.problems.other.figures import other_sheet
    from graphmech.problems.reader import page_size

    an = finite(analyse_other(scene, ()))
    return other_sheet(an, page_size(scene), footer), list(an.warnings)


def _extras(an: OtherAnalysis) -> dict[str, Any]:
    return an.summary()


def _lines(an: OtherAnalysis) -> list[str]:
    from graphmech.problems.other.check import text_lines

    return text_lines(an)


def _steps(scene: Scene[OtherScene]) -> list[str]:
    from graphmech.problems.other.steps import other_steps

    return other_steps(scene)


KIND = Kind("other", ("geneva", "differential_screw"), _read, _analyse, _judge, _sheet, _extras, _lines,
            steps=_steps)
