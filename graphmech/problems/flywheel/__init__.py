"""A flywheel (``[flywheel]``): a machine reduced to its crank at N positions, Aп by graphical
integration, ΔT, the Wittenbauer diagram or the energy indicator, J_F; the true motion with the
flywheel just designed, and a braking check.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from graphmech.problems.kind import Bench, Extra, Footer, Kind

if TYPE_CHECKING:  # annotations only: the kind's modules load when first used
    from graphmech.drawing.primitives import Sheet
    from graphmech.problems.flywheel.check import FlywheelAnalysis
    from graphmech.problems.flywheel.scene import FlywheelScene
    from graphmech.problems.judging import Verdict
    from graphmech.problems.reader import Reader, Scene


def _read(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]) -> Scene[FlywheelScene]:
    from graphmech.problems.flywheel.scene import parse_flywheel_scene

    return parse_flywheel_scene(data, source, top, order)


def _analyse(scene: Scene[FlywheelScene], extra: Extra) -> FlywheelAnalysis:
    from graphmech.problems.flywheel.check import analyse_flywheel

    return analyse_flywheel(scene, extra)


def _judge(an: FlywheelAnalysis, extra: Extra) -> list[Verdict]:
    from graphmech.problems.flywheel.check import judge_flywheel

    return judge_flywheel(an)


def _sheet(scene: Scene[FlywheelScene], footer: Footer) -> tuple[Sheet, list[str]]:
    from graphmech.problems.flywheel.sheet import scene_sheet

    return scene_sheet(scene, footer)


def _extras(an: FlywheelAnalysis) -> dict[str, Any]:
    out = {}
    if an.motion is not None:
        out["true_motion"] = an.motion_summary()
    if an.braking is not None:
        out["braking"] = an.braking_summary()
    return out


def _lines(an: FlywheelAnalysis) -> list[str]:
    if an.braking is None:
        return []
    br = an.braking_summary()
    verdict = "" if br["ok"] is None else (f" ≤ {br['time_limit']:g} s: meets the requirement" if br["ok"]
                                           else f" > {br['time_limit']:g} s: DOES NOT meet the requirement")
    return [f"stopping time {br['t_stop']:.6g} s{verdict}"]


def _timings(an: FlywheelAnalysis) -> list[str]:
    if not an.motion_runs or an.motion is None:
        return []
    runs = "" if an.motion_runs == 1 else f", {an.motion_runs} runs"  # with a reference, an error estimate
    return [f"true motion integrated in {an.motion_seconds:.2f} s ({an.motion.solver}{runs})"]


def _steps(scene: Scene[FlywheelScene]) -> list[str]:
    from graphmech.problems.flywheel.steps import flywheel_steps

    return flywheel_steps(scene)


def _bench(quick: bool) -> Bench:
    from graphmech.problems.flywheel.bench import bench

    return bench(quick)


KIND = Kind("flywheel", ("flywheel",), _read, _analyse, _judge, _sheet, _extras, _lines, bench=_bench, steps=_steps,
            timings=_timings)
