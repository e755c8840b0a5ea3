"""The geometry a gear-train scene is drawn with, shared by its figure and its check: the layout at
the schematic's μl and the velocity diagram at μv and the pole distance H — stated, or chosen so
that the drawing fits — so that the lengths the check reports are the ones on the sheet.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from graphmech.errors import GraphmechError, NoSolution, NotApplicable
from graphmech.methods.train_layout import TrainLayout, layout
from graphmech.methods.train_velocity import TrainVelocityDiagram, velocity_diagram
from graphmech.problems.reader import Scene
from graphmech.problems.trains.names import parse_name
from graphmech.problems.trains.scene import TrainScene
from graphmech.scales import round_scale, round_scale_below
from graphmech.tolerances import POLE_RANGE_MM  # a chosen H stays within what a scene may state

#: The axial pitch of the schematic's slots on the paper, mm.
SLOT_MM = 16.0
#: The schematic's height and the velocity diagram's width on the paper, about, mm.
SCHEMATIC_MM, VELOCITY_MM, OMEGA_MM = 80.0, 40.0, 60.0
#: The shortest pole distance chosen, mm (a slow member's ℓ is then short: the method's limit).
H_LEAST = 10.0
#: The longest pole distance chosen, mm, and the height the lines' diagram and H share at most: with
#: the notes below they fill the sheet's height.
H_MOST, TALL_MM = 40.0, 115.0


@dataclass(frozen=True)
class Drawn:
    """The layout at μl (m per drawing mm) and, for a parallel-axis train, the velocity diagram."""

    layout: TrainLayout
    mu_l: float
    velocity: TrainVelocityDiagram | None


def _layout(scene: Scene[TrainScene], inputs: Mapping[str, float] | None, gap: float | None) -> TrainLayout:
    p = scene.problem
    train = p.train if inputs is None else p.train.with_inputs(inputs)
    try:
        return layout(train, p.module, p.axes, p.sides, p.towards, p.coaxial, gap=gap, modules=p.gear_modules)
    except NoSolution as e:  # the scene's remedy, where the book's stages have their own modules
        raise NoSolution(f"{e}: give each stage its module ([[train.mesh]] m) as the book's gears have them") from None


def drawn(scene: Scene[TrainScene], inputs: Mapping[str, float] | None = None) -> Drawn:
    """The scene's layout and velocity diagram (None for a spatial train) at the scene's scales.

    ``inputs`` (another value of a list input) draws the diagram again at the scales chosen for the
    first value, so every row of one scene reads one μω. A loop that does not close (the coaxial
    condition) raises NoSolution from the layout.
    """
    lay0 = _layout(scene, None, None)
    if "l" in scene.scales:
        mu_l = scene.scales["l"]
    else:
        # the drawing's height: every gear's centre ± its radius (a spatial train: its width too)
        cs = [(lay0.centre(g.name), lay0.radius[g.name]) for g in lay0.train.gears]
        ext = max(q[1] + r for q, r in cs) - min(q[1] - r for q, r in cs)
        if not lay0.parallel:
            ext = max(ext, max(q[0] + r for q, r in cs) - min(q[0] - r for q, r in cs))
        mu_l = round_scale(max(ext, 1e-9) / SCHEMATIC_MM)
    lay = _layout(scene, None, SLOT_MM * mu_l)
    if not lay.parallel:
        return Drawn(lay, mu_l, None)
    d = train_velocity(lay, scene, mu_l)
    if inputs is not None:
        lay = _layout(scene, inputs, SLOT_MM * mu_l)
        d = velocity_diagram(lay, mu_l, d.mu_v, d.H)
    return Drawn(lay, mu_l, d)


def asked(scene: Scene[TrainScene]) -> tuple[str, ...]:
    """The members whose lengths ℓ the scene's ``find`` reads off the ω line: a speed's member, a
    ratio's two (Willis' ratios, tooth numbers and the rest are the book's equations')."""
    p = scene.problem
    out: list[str] = []
    for text in scene.find:
        try:
            n = parse_name(text.split("[")[0], p.train, p.solved_z)
        except GraphmechError:  # a dynamics name, read elsewhere
            continue
        if n.what in ("n", "omega", "i"):
            for g in (n.a, n.b):
                if g is not None and p.train.member_of(g) not in out:
                    out.append(p.train.member_of(g))
    return tuple(out)


def train_velocity(lay: TrainLayout, scene: Scene[TrainScene], mu_l: float) -> TrainVelocityDiagram:
    """The velocity diagram at the scene's scales (μv, then H from ``pole_distance`` or μω), else
    chosen for the speeds the scene asks (:func:`asked`; none: every member): the fastest pitch
    point at most :data:`VELOCITY_MM` wide, the longest ℓ asked about :data:`OMEGA_MM` at a pole
    distance between :data:`H_LEAST` and :data:`H_MOST` — so a slow output is drawn as long as the
    sheet allows, and a faster member's ray that would cut the ω line beyond it is drawn clipped at
    the line's end (its ℓ in the notes). μv is coarsened where a small fast gear asked beside large
    slow ones would otherwise run its ray off the sheet at H_LEAST."""
    if not lay.parallel:
        raise NotApplicable("the velocity diagram is drawn for trains whose axes are all parallel")
    probe = velocity_diagram(lay, mu_l, 1.0, 1.0)  # at μv = 1: X is v in m/s, slopes ω·μl
    vmax = max((abs(ln.x_at(p[1])) for ln in probe.lines.values() for p in ln.points), default=0.0)
    every = max(abs(ln.slope) for ln in probe.lines.values())
    # a member asked at rest (to rounding: the Ferguson train's sun) has ℓ = 0 at any H
    want = [m for m in asked(scene) if abs(probe.lines[m].slope) > 1e-9 * every] or list(probe.lines)
    smax = max(abs(probe.lines[m].slope) for m in want)
    need = max(vmax / VELOCITY_MM, H_LEAST * smax / OMEGA_MM)
    mu_v = scene.scales.get("v") or (round_scale(need) if need > 0.0 else 1.0)  # 1: every member at rest
    if scene.problem.pole_distance is not None:
        H = scene.problem.pole_distance
    elif "omega" in scene.scales:
        H = mu_v / (mu_l * scene.scales["omega"])
    elif smax > 0.0:
        fits = OMEGA_MM * mu_v / smax
        least = H_LEAST if "v" not in scene.scales else POLE_RANGE_MM[0]
        ys = [p[1] for ln in probe.lines.values() for p in ln.points]
        most = max(5.0 * math.floor(min(H_MOST, TALL_MM - (max(ys) - min(ys))) / 5.0), least)  # whole 5 mm
        H = min(max(round_scale_below(fits), least), most, POLE_RANGE_MM[1])
    else:
        H = 20.0
    return velocity_diagram(lay, mu_l, mu_v, H)


__all__ = ["H_LEAST", "H_MOST", "OMEGA_MM", "SCHEMATIC_MM", "SLOT_MM", "TALL_MM", "VELOCITY_MM", "Drawn", "asked", "drawn", "train_velocity"]
