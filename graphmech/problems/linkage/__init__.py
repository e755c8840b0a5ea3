"""A linkage at given positions: its velocity and acceleration polygons (and instant centres
when the scene asks for them), each measured value checked against the exact kinematics.

scene.py reads ``[frame]``, ``[driver]``, ``[[dyad]]``, ``[[point]]`` (and a full cycle, which
is the ``cycle`` kind); check.py builds the construction and judges; figures.py and sheet.py
draw; sizes.py holds the linkage's characteristic sizes shared with the kinds built on it;
bench.py times the polygons against a plain numpy closed form.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, cast

from graphmech.problems.kind import Bench, Extra, Footer, Kind
from graphmech.problems.reader import LINKAGE_KEYS

if TYPE_CHECKING:  # annotations only: the kind's modules load when first used
    from graphmech.drawing.primitives import Sheet
    from graphmech.problems.judging import Verdict
    from graphmech.problems.linkage.check import Analysis as LinkageAnalysis
    from graphmech.problems.reader import Reader, Scene


def _read(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]) -> Scene[None]:
    from graphmech.problems.linkage.scene import parse_linkage_scene

    return cast("Scene[None]", parse_linkage_scene(data, source, top, order))  # a linkage scene: its kind says so


def _analyse(scene: Scene[None], extra: Extra) -> LinkageAnalysis:
    from graphmech.problems.linkage.check import analyse

    return analyse(scene, extra)


def _judge(an: LinkageAnalysis, extra: Extra) -> list[Verdict]:
    from graphmech.problems.linkage.check import judge

    return judge(an)


def _sheet(scene: Scene[None], footer: Footer) -> tuple[Sheet, list[str]]:
    from graphmech.problems.linkage.sheet import scene_sheet

    return scene_sheet(scene, footer)


def _extras(an: LinkageAnalysis) -> dict[str, Any]:
    if an.instant_centres is None:
        return {}
    from graphmech.problems.instant_centres.check import summary

    return {"instant_centres": summary(an)}


def _steps(scene: Scene[None]) -> list[str]:
    from graphmech.problems.linkage.steps import linkage_steps

    return linkage_steps(scene)


def _bench(quick: bool) -> Bench:
    from graphmech.problems.instant_centres.bench import ic_records
    from graphmech.problems.linkage.bench import bench

    records, notes = bench(quick)
    return records + ic_records(quick=quick), notes


KIND = Kind("linkage", LINKAGE_KEYS, _read, _analyse, _judge, _sheet, _extras, bench=_bench,
            poses=lambda data: True, steps=_steps)  # the last one asked: a scene that poses nothing else is a linkage's
