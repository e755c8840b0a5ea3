"""Kinetostatics (a linkage scene with ``[forces]``): inertia loads from the acceleration polygon,
force polygons Assur group by Assur group, the balancing moment or force, Zhukovsky's lever,
friction circles and angles by successive approximation — checked against the matrix method.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from graphmech.problems.kind import Bench, Extra, Footer, Kind


def _read(data: Any, source: str, top: Any, order: Any) -> Any:
    from graphmech.problems.forces.scene import parse_forces_scene

    return parse_forces_scene(data, source, top, order)


def _analyse(scene: Any, extra: Extra) -> Any:
    from graphmech.problems.forces.check import analyse_forces

    return analyse_forces(scene, extra)


def _sheet(scene: Any, footer: Footer) -> Any:
    from graphmech.problems.forces.check import render_forces

    return render_forces(scene, footer)


def _extras(an: Any) -> dict[str, Any]:
    return {"friction": an.friction_summary()} if an.scene.problem.model.has_friction else {}


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
            bench=_bench, mixture=_mixture)
