"""Velocity and acceleration polygons of a linkage: the whole construction, built once per scene.

The construction is laid out the way the textbook does it, one figure after the other:

1. the kinematic diagram at μl (:mod:`graphmech.methods.diagram`): the driver's points, then
   each dyad's joint as the intersection of two loci;
2. the velocity polygon at μv (:mod:`graphmech.methods.velocity`): pole p, ``pb = ω1·l_AB/μv``
   ⟂ AB, then for each dyad two lines through known images whose intersection is the new image;
3. the acceleration polygon at μa (:mod:`graphmech.methods.acceleration`): pole p′, the normal
   components laid off from the velocity polygon's ω, the tangential (and Coriolis) lines, and
   their intersections.

All drawing coordinates are millimetres. Every quantity a scene may ask for is a measurement
step; :meth:`Construction.prune` later keeps only what is asked for.

The construction itself, :class:`LinkageConstruction`, is defined in
:mod:`graphmech.methods.linkage_construction` (the builders import it from there, not from
here) and importable from here as before.
"""
from __future__ import annotations

from dataclasses import replace
from typing import Any

from graphmech.mechanisms.linkage import Crank, Guide, Linkage, RPP, RPR, RRP, RRR
from graphmech.methods import acceleration, diagram, measure, velocity
from graphmech.methods.linkage_construction import LinkageConstruction

PANELS = ("mechanism", "velocity", "acceleration")


def build_polygons(linkage: Linkage, scales: dict[str, float]) -> LinkageConstruction:
    """Build the kinematic diagram, velocity polygon and acceleration polygon of a linkage.

    Parameters
    ----------
    linkage : Linkage
        The mechanism (SI units).
    scales : dict
        ``{"l": μl, "v": μv, "a": μa}`` in m/mm, (m/s)/mm, (m/s²)/mm.
    """
    b = LinkageConstruction(linkage, dict(scales))
    b.param = "phi" if isinstance(linkage.driver, Crank) else "s"
    b.g.param(b.param)
    b.link_points = linkage.links()
    diagram.add_frame(b)
    velocity.add_pole(b)
    acceleration.add_pole(b)
    # The driver, then each dyad in order — each through all three figures. An extra point is
    # placed as soon as its base points are, so a later dyad may hang on it (six-bars).
    pending = list(linkage.points)

    def place(part: Any) -> None:
        diagram.add(b, part)
        velocity.add(b, part)
        acceleration.add(b, part)

    for part in (linkage.driver, *linkage.dyads):
        place(part)
        while (ready := next((p for p in pending if all(u in b.mech for u in p.base)), None)):
            pending.remove(ready)
            place(ready)
    for pt in pending:  # base points never placed: let the step graph name what is missing
        place(pt)
    add_point_quantities(b)
    return b


def add_point_quantities(b: LinkageConstruction) -> None:
    """v_X, a_X, relative v_XY, a_XY, l_XY and θ for every point and link."""
    for name in b.vel:
        measure.point_speed(b, name)
    for name in b.acc:
        measure.point_acceleration(b, name)
    along = {lk: (b.mech[u], b.mech[v]) for lk, (u, v) in diagram.offset_bar_lines(b.linkage).items()}  # θ of û
    for link, pts in b.link_points.items():
        for i, x in enumerate(pts):
            for y in pts:
                if x == y:
                    continue
                measure.relative(b, x, y)
                measure.length(b, x, y)
        measure.link_angle(b, link, along.get(link))
    for x, y in b.coincident:
        measure.relative(b, x, y)
    for name, q in list(b.quantities.items()):  # many books write ε for angular acceleration
        if name.startswith("alpha_"):
            b.quantity(replace(q, name="epsilon_" + name[len("alpha_"):]))
    for dyad in b.linkage.dyads:
        if isinstance(dyad, RPR):  # the bar's length between the pivots, l_BC, as the book reads it
            measure.length(b, dyad.bar_pivot, dyad.block_pivot)
            measure.length(b, dyad.block_pivot, dyad.bar_pivot)
    for x in dict.fromkeys([*b.vel, *b.acc]):
        if x not in b.linkage.frame_points:  # a frame point's velocity is the pole: no direction
            measure.direction_of(b, x)
    add_transmission_angles(b)


def add_transmission_angles(b: LinkageConstruction) -> None:
    """γ and α (measure.transmission) at each output joint where they are defined: an RRR dyad
    with one outer joint on the frame (at its middle joint, pushed from the other outer joint); an
    RRP slider on a frame guide; a guide bar turning about a frame pivot (at the block's pivot,
    pushed across the bar, moving ⟂ the arm to the bar's pivot)."""
    frame = b.linkage.frame_points
    for y in b.linkage.dyads:
        if isinstance(y, RRR) and (y.p in frame) != (y.q in frame):
            pivot, pusher = (y.q, y.p) if y.q in frame else (y.p, y.q)
            measure.transmission(b, y.c, pusher, pivot, (y.c, pusher, pivot), rocker=True)
        elif isinstance(y, RRP) and isinstance(y.guide, Guide):
            g = y.guide.direction
            measure.transmission(b, y.c, y.p, g, (y.c, y.p, g), rocker=False)
        elif isinstance(y, RPR) and y.bar_pivot in frame and y.block_pivot not in frame:
            x, c = y.block_pivot, y.bar_pivot  # the bar's line as the diagram draws it
            measure.transmission(b, x, c, diagram.bar_direction(b, y), ("bar", x, c, y.bar_link), rocker=False)


__all__ = ["LinkageConstruction", "build_polygons", "PANELS", "RRR", "RRP", "RPR", "RPP"]
