"""A flywheel (``[flywheel]``): a machine reduced to its crank at N positions, Aп by graphical
integration, ΔT, the Wittenbauer diagram or the energy indicator, J_F; the true motion with the
flywheel just designed, and a braking check.
"""
from __future__ import annotations

from typing import Any

from graphmech.problems.kind import Bench, Extra, Footer, Kind


def _read(data: Any, source: str, top: Any, order: Any) -> Any:
    from graphmech.problems.flywheel.scene import parse_flywheel_scene

    return parse_flywheel_scene(data, source, top, order)


def _analyse(scene: Any, extra: Extra) -> Any:
    from graphmech.problems.flywheel.check import analyse_flywheel

    return analyse_flywheel(scene, extra)


def _judge(an: Any, extra: Extra) -> list[Any]:
    from graphmech.problems.flywheel.check import judge_flywheel

    return judge_flywheel(an)


def _sheet(scene: Any, footer: Footer) -> Any:
    from graphmech.problems.flywheel.sheet import scene_sheet

    return scene_sheet(scene, footer)


def _extras(an: Any) -> dict[str, Any]:
    out = {}
    if an.motion is not None:
        out["true_motion"] = an.motion_summary()
    if an.braking is not None:
        out["braking"] = an.braking_summary()
    return out


def _lines(an: Any) -> list[str]:
    if an.braking is None:
        return []
    br = an.braking_summary()
    verdict = "" if br["ok"] is None else (f" ≤ {br['time_limit']:g} s: meets the requirement" if br["ok"]
                                           else f" > {br['time_limit']:g} s: DOES NOT meet the requirement")
    return [f"stopping time {br['t_stop']:.6g} s{verdict}"]


def _bench(quick: bool) -> Bench:
    from graphmech.problems.flywheel.bench import bench

    return bench(quick)


KIND = Kind("flywheel", ("flywheel",), _read, _analyse, _judge, _sheet, _extras, _lines, bench=_bench)
