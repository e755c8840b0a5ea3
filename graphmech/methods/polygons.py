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
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any

from graphmech.construction import Construction
from graphmech.mechanisms.linkage import Crank, Linkage, RPP, RPR, RRP, RRR
from graphmech.methods.quantities import Quantity

PANELS = ("mechanism", "velocity", "acceleration")


@dataclass
class LinkageConstruction:
    """A linkage's construction and what can be measured on it.

    Attributes
    ----------
    g : Construction
        The step graph (structure; evaluate a pruned plan of it).
    param : str
        The driver's position parameter: ``"phi"`` (crank angle, rad) or ``"s"`` (m).
    scales : dict
        μ in SI per mm: ``l``, ``v``, ``a``.
    mech, vel, acc : dict
        Point name → its step in the mechanism, velocity polygon, acceleration polygon.
    quantities : dict
        Quantity name → :class:`Quantity`.
    """

    linkage: Linkage
    scales: dict[str, float]
    g: Construction = field(default_factory=Construction)
    param: str = "phi"
    mech: dict[str, str] = field(default_factory=dict)
    vel: dict[str, str] = field(default_factory=dict)
    acc: dict[str, str] = field(default_factory=dict)
    omega: dict[str, str] = field(default_factory=dict)  # link → measurement step (drawn, scale)
    alpha: dict[str, str] = field(default_factory=dict)
    slider_dir: dict[str, tuple[float, float]] = field(default_factory=dict)  # point → guide unit vector
    quantities: dict[str, Quantity] = field(default_factory=dict)
    link_points: dict[str, list[str]] = field(default_factory=dict)
    translating: set[str] = field(default_factory=set)
    coincident: list[tuple[str, str]] = field(default_factory=list)  # (moving, reference) pairs

    origin: tuple[float, float] = (0.0, 0.0)  # m: the mechanism point drawn at (0, 0) mm

    # ------------------------------------------------------------------ helpers
    @property
    def mu_l(self) -> float:
        return self.scales["l"]

    def to_drawing(self, xy: tuple[float, float]) -> tuple[float, float]:
        """A point of the mechanism (m) on the kinematic diagram (mm at μl).

        The drawing's origin is the first frame point: coordinates stay of the size of the
        mechanism, so a linkage placed far from the scene's origin loses no digits.
        """
        return ((xy[0] - self.origin[0]) / self.mu_l, (xy[1] - self.origin[1]) / self.mu_l)

    def quantity(self, q: Quantity) -> None:
        self.quantities.setdefault(q.name, q)

    def steps_of_panel(self, panel: str) -> list[str]:
        """Every drawable step of a panel (what ``show`` asks for)."""
        return [s.name for s in self.g.steps.values() if s.panel == panel and s.role != "hidden"]


def build_polygons(linkage: Linkage, scales: dict[str, float]) -> LinkageConstruction:
    """Build the kinematic diagram, velocity polygon and acceleration polygon of a linkage.

    Parameters
    ----------
    linkage : Linkage
        The mechanism (SI units).
    scales : dict
        ``{"l": μl, "v": μv, "a": μa}`` in m/mm, (m/s)/mm, (m/s²)/mm.
    """
    from graphmech.methods import acceleration, diagram, velocity

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
    from graphmech.methods import measure

    for name in b.vel:
        measure.point_speed(b, name)
    for name in b.acc:
        measure.point_acceleration(b, name)
    for link, pts in b.link_points.items():
        for i, x in enumerate(pts):
            for y in pts:
                if x == y:
                    continue
                measure.relative(b, x, y)
                measure.length(b, x, y)
        measure.link_angle(b, link)
    for x, y in b.coincident:
        measure.relative(b, x, y)
    for name, q in list(b.quantities.items()):  # many books write ε for angular acceleration
        if name.startswith("alpha_"):
            b.quantity(replace(q, name="epsilon_" + name[len("alpha_"):]))
    for y in b.linkage.dyads:
        if isinstance(y, RPR):  # the bar's length between the pivots, l_BC, as the book reads it
            measure.length(b, y.bar_pivot, y.block_pivot)
            measure.length(b, y.block_pivot, y.bar_pivot)


__all__ = ["LinkageConstruction", "build_polygons", "PANELS", "RRR", "RRP", "RPR", "RPP"]
