"""Kinetostatics (a linkage scene with ``[forces]``): inertia loads from the acceleration polygon,
force polygons Assur group by Assur group, the balancing moment or force, Zhukovsky's lever,
friction circles and angles by successive approximation — checked against the matrix method.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from graphmech.problems.kind import Bench, Extra, Footer, Kind

if TYPE_CHECKING:  # annotations only: the kind's modules load when first used
    from graphmech.drawing.primitives import Sheet
    from graphmech.problems.forces.check import ForceAnalysis
    from graphmech.problems.forces.scene import ForceScene
    from graphmech.problems.reader import Reader, Scene


def _read(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]) -> Scene[ForceScene]:
    from graphmech.problems.forces.scene import parse_forces_scene

    return parse_forces_scene(data, source, top, order)


def _analyse(scene: Scene[ForceScene], extra: Extra) -> ForceAnalysis:
    from graphmech.problems.forces.check import analyse_forces

    return analyse_forces(scene, extra)


def _sheet(scene: Scene[ForceScene], footer: Footer) -> tuple[Sheet, list[str]]:
    from graphmech.problems.forces.check import render_forces

    return render_forces(scene, footer)


def _extras(an: ForceAnalysis) -> dict[str, Any]:
    return {"friction": an.friction_summary()} if an.scene.problem.model.has_friction else {}


def _steps(scene: Scene[ForceScene]) -> list[str]:
    from graphmech.problems.forces.steps import force_steps

    return force_steps(scene)


def _bench(quick: bool) -> Bench:
    from graphmech.problems.forces.bench import bench

    return bench(quick)


def _mixture(data: Mapping[str, Any]) -> tuple[str, str] | None:
    others = [t for t in ("cam", "flywheel", "efficiency", "balancing") if t in data]
    if not others:
        return None
    other = {"cam": "a cam", "flywheel": "a flywheel"}.get(others[0], "an efficiency or balancing")
    return ("forces", "[forces] belongs to a linkage scene (kinetostatics), not to "
                      f"{other} scene: put it in a scene of its own")


KIND = Kind("forces", ("forces",), _read, _analyse, lambda an, extra: an.verdicts, _sheet, _extras,
            bench=_bench, mixture=_mixture, steps=_steps)
