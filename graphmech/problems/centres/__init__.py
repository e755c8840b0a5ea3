"""Instant centres of a mechanism stated by its direct centres (``[centres]``): wheels in pure
rolling contact (a friction planetary drive) and revolutes; Kennedy's theorem finds the other
centres and the book's ratios ω_i/ω_j, checked against the pairs' exact velocity equations.
A linkage of dyads asks for its centres in a linkage scene instead (``show = ["instant_centres"]``).
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from graphmech.problems.kind import Extra, Footer, Kind

if TYPE_CHECKING:  # annotations only: the kind's modules load when first used
    from graphmech.drawing.primitives import Sheet
    from graphmech.problems.centres.check import CentresAnalysis
    from graphmech.problems.centres.scene import CentresScene
    from graphmech.problems.judging import Verdict
    from graphmech.problems.reader import Reader, Scene


def _read(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]) -> Scene[CentresScene]:
    from graphmech.problems.centres.scene import parse_centres_scene

    return parse_centres_scene(data, source, top, order)


def _analyse(scene: Scene[CentresScene], extra: Extra) -> CentresAnalysis:
    from graphmech.problems.centres.check import analyse_centres

    return analyse_centres(scene, extra)


def _judge(an: CentresAnalysis, extra: Extra) -> list[Verdict]:
    from graphmech.problems.centres.check import judge_centres

    return judge_centres(an)


def _sheet(scene: Scene[CentresScene], footer: Footer) -> tuple[Sheet, list[str]]:
    from graphmech.problems.centres.check import analyse_centres
    from graphmech.problems.centres.figures import centres_sheet
    from graphmech.problems.judging import finite
    from graphmech.problems.reader import page_size

    an = finite(analyse_centres(scene, ()))
    return centres_sheet(an, page_size(scene), footer), list(an.warnings)


def _extras(an: CentresAnalysis) -> dict[str, Any]:
    return an.summary()


def _lines(an: CentresAnalysis) -> list[str]:
    from graphmech.problems.centres.check import text_lines

    return text_lines(an)


def _steps(scene: Scene[CentresScene]) -> list[str]:
    from graphmech.problems.centres.check import centres_steps

    return centres_steps(scene)


KIND = Kind("centres", ("centres",), _read, _analyse, _judge, _sheet, _extras, _lines, steps=_steps)
