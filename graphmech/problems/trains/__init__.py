"""Gear trains (``[train]``): ordinary, planetary, differential and compound trains (the book's
轮系), solved as the book does — the ordinary ratio, Willis' converted train per carrier, a
compound train split into its basic trains — and by the velocity diagram, drawn as the book's
schematic; checked against every mesh written as one linear equation in the members' speeds
(:mod:`graphmech.exact.gear_train`)."""
from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from graphmech.problems.kind import Extra, Footer, Kind

if TYPE_CHECKING:  # annotations only: the kind's modules load when first used
    from graphmech.drawing.primitives import Sheet
    from graphmech.problems.judging import Verdict
    from graphmech.problems.reader import Reader, Scene
    from graphmech.problems.trains.check import TrainAnalysis
    from graphmech.problems.trains.scene import TrainScene


def _read(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]) -> Scene[TrainScene]:
    from graphmech.problems.trains.scene import parse_train_scene

    return parse_train_scene(data, source, top, order)


def _analyse(scene: Scene[TrainScene], extra: Extra) -> TrainAnalysis:
    from graphmech.problems.trains.check import analyse

    return analyse(scene, extra)


def _judge(an: TrainAnalysis, extra: Extra) -> list[Verdict]:
    from graphmech.problems.trains.check import judge

    return judge(an)


def _extras(an: TrainAnalysis) -> dict[str, Any]:
    from graphmech.problems.trains.check import extras

    return extras(an)


def _lines(an: TrainAnalysis) -> list[str]:
    from graphmech.problems.trains.check import lines

    return lines(an)


def _sheet(scene: Scene[TrainScene], footer: Footer) -> tuple[Sheet, list[str]]:
    from graphmech.problems.trains.figures import train_sheet

    return train_sheet(scene, footer)


def _steps(scene: Scene[TrainScene]) -> list[str]:
    from graphmech.problems.trains.steps import train_steps

    return train_steps(scene)


KIND = Kind("trains", ("train",), _read, _analyse, _judge, _sheet, extras=_extras, lines=_lines, steps=_steps)
