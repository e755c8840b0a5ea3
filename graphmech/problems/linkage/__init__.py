"""A linkage at given positions: its velocity and acceleration polygons (and instant centres
when the scene asks for them), each measured value checked against the exact kinematics.

scene.py reads ``[frame]``, ``[driver]``, ``[[dyad]]``, ``[[point]]`` (and a full cycle, which
is the ``cycle`` kind); check.py builds the construction and judges; figures.py and sheet.py
draw; sizes.py holds the linkage's characteristic sizes shared with the kinds built on it;
bench.py times the polygons against a plain numpy closed form.
"""
from __future__ import annotations

from typing import Any

from graphmech.problems.kind import Bench, Extra, Footer, Kind
from graphmech.problems.reader import LINKAGE_KEYS


def _read(data: Any, source: str, top: Any, order: Any) -> Any:
    from graphmech.problems.linkage.scene import parse_linkage_scene

    return parse_linkage_scene(data, source, top, order)


def _analyse(scene: Any, extra: Extra) -> Any:
    from graphmech.problems.linkage.check import analyse

    return analyse(scene, extra)


def _judge(an: Any, extra: Extra) -> list[Any]:
    from graphmech.problems.linkage.check import judge

    return judge(an)


def _sheet(scene: Any, footer: Footer) -> Any:
    from graphmech.problems.linkage.sheet import scene_sheet

    return scene_sheet(scene, footer)


def _extras(an: Any) -> dict[str, Any]:
    if an.instant_centres is None:
        return {}
    from graphmech.problems.instant_centres.check import summary

    return {"instant_centres": summary(an)}


def _bench(quick: bool) -> Bench:
    from graphmech.problems.instant_centres.bench import ic_records
    from graphmech.problems.linkage.bench import bench

    records, notes = bench(quick)
    return records + ic_records(quick=quick), notes


KIND = Kind("linkage", LINKAGE_KEYS, _read, _analyse, _judge, _sheet, _extras, bench=_bench,
            poses=lambda data: True)  # the last one asked: a scene that poses nothing else is a linkage's
