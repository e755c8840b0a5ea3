"""The sheet of a flywheel scene: the mechanism at position 1, the diagrams against φ, the
Wittenbauer diagram or the energy indicator, and the run-down when braking is asked for."""
from __future__ import annotations

import math
from typing import Any

from graphmech.drawing.primitives import Sheet
from graphmech.errors import SceneError
from graphmech.problems.flywheel.braking_figures import rundown_panel
from graphmech.problems.flywheel.check import analyse_flywheel, true_motion_curve
from graphmech.problems.flywheel.figures import MOTION_SAMPLES, flywheel_sheet, motion_panel
from graphmech.problems.judging import finite
from graphmech.problems.linkage.sheet import mechanism_at_position_1
from graphmech.problems.reader import Scene, page_size


def scene_sheet(scene: Scene[Any], footer: tuple[str, ...]) -> tuple[Sheet, list[str]]:
    """The drawing of a flywheel scene and the warnings found while making it."""
    an = finite(analyse_flywheel(scene, (), estimates=False))  # a drawing needs no error estimates
    notation = scene.page.notation
    cycle_panels = [p for p in scene.show if p not in ("mechanism", "motion", "rundown")]
    if an.design is None and not any(p in scene.show for p in ("mechanism", "motion", "rundown")):
        raise SceneError([("show", "nothing to draw: this flywheel scene asks for no diagram; "
                                   "use graphmech check")], scene.source)
    panels: list[Any] = []
    if "mechanism" in scene.show and scene.linkage is not None:
        panels += mechanism_at_position_1(scene, footer)
    if cycle_panels and an.design is not None:
        panels += flywheel_sheet(scene.title, an.design, cycle_panels, page_size(scene), footer, notation).panels
    if "motion" in scene.show and an.motion is not None:
        phi, omega = true_motion_curve(an, MOTION_SAMPLES)
        mu_phi = an.design.scales["phi"] if an.design is not None else math.radians(2.5)
        panels.append(motion_panel(phi, omega, scene.problem.machine.omega_m, mu_phi, notation,
                                   (an.motion.omega_max, an.motion.omega_min)))
    if "rundown" in scene.show:
        b = scene.problem.braking
        panels.append(rundown_panel(an.braking_inertia, scene.problem.machine.omega_m, b.moment, b.time_limit,
                                    notation))
    return Sheet(scene.title, tuple(panels), page_size(scene), footer), list(an.warnings)
