"""Involute spur gears (``[gear]``): one gear's tooth — its circles, the involute constructed by
points as the book draws it, thicknesses and radii of curvature at any radius, the pointed tip,
the span over k teeth and the dimension over pins — or a pair in mesh (external, internal, rack
and pinion): the working pressure angle, the line of action N₁N₂ cut by the tip circles at B₁B₂,
the contact ratio ε = B₁B₂/p_b with its single- and double-contact zones, the specific sliding
and the backlash; each measured on the construction and checked against the closed forms of
:mod:`graphmech.exact.gear`.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from graphmech.problems.kind import Bench, Extra, Footer, Kind

if TYPE_CHECKING:  # annotations only: the kind's modules load when first used
    from graphmech.drawing.primitives import Sheet
    from graphmech.problems.gears.check import GearAnalysis
    from graphmech.problems.gears.scene import GearScene
    from graphmech.problems.judging import Verdict
    from graphmech.problems.reader import Reader, Scene


def _read(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]) -> Scene[GearScene]:
    from graphmech.problems.gears.scene import parse_gear_scene

    return parse_gear_scene(data, source, top, order)


def _analyse(scene: Scene[GearScene], extra: Extra) -> GearAnalysis:
    from graphmech.problems.gears.check import analyse

    return analyse(scene, extra)


def _judge(an: GearAnalysis, extra: Extra) -> list[Verdict]:
    from graphmech.problems.gears.check import judge

    return judge(an)


def _sheet(scene: Scene[GearScene], footer: Footer) -> tuple[Sheet, list[str]]:
    from graphmech.problems.gears.check import analyse, gear_figure
    from graphmech.problems.judging import finite
    from graphmech.problems.reader import page_size

    an = finite(analyse(scene, ()))
    return gear_figure(an, page_size(scene), footer), list(an.warnings)


def _extras(an: GearAnalysis) -> dict[str, Any]:
    from graphmech.problems.gears.check import extras

    return extras(an)


def _lines(an: GearAnalysis) -> list[str]:
    from graphmech.problems.gears.check import lines

    return lines(an)


def _bench(quick: bool) -> Bench:
    from graphmech.problems.gears.bench import bench

    return bench(quick)


def _steps(scene: Scene[GearScene]) -> list[str]:
    from graphmech.problems.gears.steps import gear_steps

    return gear_steps(scene)


KIND = Kind("gears", ("gear",), _read, _analyse, _judge, _sheet, extras=_extras, lines=_lines, bench=_bench,
            steps=_steps)
