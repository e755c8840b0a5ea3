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


def _spatial(scene: Scene[GearScene]) -> bool:
    """A helical, bevel or worm pair: graphmech.problems.gears.spatial analyses, judges and draws it."""
    from graphmech.errors import SceneError
    from graphmech.mechanisms.gear import SPATIAL_MESHINGS

    spatial = scene.problem.gears.meshing in SPATIAL_MESHINGS
    wrong = [i for i, p in enumerate(scene.show) if (p == "helix") != spatial]
    if wrong:
        i = wrong[0]
        raise SceneError([(f"show[{i}]", 'a helical, bevel or worm pair draws the panel "helix" alone' if spatial else
                           'the panel "helix" belongs to a helical, bevel or worm pair')], scene.source)
    return spatial


def _analyse(scene: Scene[GearScene], extra: Extra, estimates: bool = True) -> GearAnalysis:
    if _spatial(scene):
        from graphmech.problems.gears.spatial import analyse_spatial

        return analyse_spatial(scene, extra)
    from graphmech.problems.gears.check import analyse

    return analyse(scene, extra, estimates)


def _judge(an: GearAnalysis, extra: Extra) -> list[Verdict]:
    from graphmech.problems.gears.check import judge
    from graphmech.problems.gears.spatial import SpatialAnalysis
    from graphmech.problems.gears.spatial import judge as judge_spatial

    return judge_spatial(an) if isinstance(an, SpatialAnalysis) else judge(an)


def _sheet(scene: Scene[GearScene], footer: Footer) -> tuple[Sheet, list[str]]:
    from graphmech.problems.gears.check import gear_figure
    from graphmech.problems.gears.helix_figure import helix_sheet
    from graphmech.problems.gears.spatial import SpatialAnalysis
    from graphmech.problems.judging import finite
    from graphmech.problems.reader import page_size

    an = finite(_analyse(scene, (), estimates=False))  # the figure shows no row's error estimate
    sheet = helix_sheet(an, page_size(scene), footer) if isinstance(an, SpatialAnalysis) else \
        gear_figure(an, page_size(scene), footer)
    return sheet, list(an.warnings)


def _extras(an: GearAnalysis) -> dict[str, Any]:
    from graphmech.problems.gears.check import extras
    from graphmech.problems.gears.spatial import SpatialAnalysis
    from graphmech.problems.gears.spatial import extras as extras_spatial

    return extras_spatial(an) if isinstance(an, SpatialAnalysis) else extras(an)


def _lines(an: GearAnalysis) -> list[str]:
    from graphmech.problems.gears.check import lines
    from graphmech.problems.gears.spatial import SpatialAnalysis
    from graphmech.problems.gears.spatial import lines as lines_spatial

    return lines_spatial(an) if isinstance(an, SpatialAnalysis) else lines(an)


def _bench(quick: bool) -> Bench:
    from graphmech.problems.gears.bench import bench

    return bench(quick)


def _steps(scene: Scene[GearScene]) -> list[str]:
    if _spatial(scene):
        from graphmech.problems.gears.spatial import analyse_spatial, protocol

        return protocol(analyse_spatial(scene, ()))
    from graphmech.problems.gears.steps import gear_steps

    return gear_steps(scene)


KIND = Kind("gears", ("gear",), _read, _analyse, _judge, _sheet, extras=_extras, lines=_lines, bench=_bench,
            steps=_steps)
