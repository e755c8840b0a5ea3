"""The linkage construction the figure builders share, kept apart from polygons.py, which imports the builders.

:mod:`graphmech.methods.polygons` lays the construction out figure after figure and so imports
the builders (:mod:`~graphmech.methods.diagram`, :mod:`~graphmech.methods.velocity`,
:mod:`~graphmech.methods.acceleration`, :mod:`~graphmech.methods.measure`,
:mod:`~graphmech.methods.elements`); they import only this: :class:`LinkageConstruction`, the
naming of the construction's own points (:func:`own`) and the step names of the two poles.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from graphmech.construction import Construction
from graphmech.mechanisms.linkage import Linkage
from graphmech.methods.quantities import Quantity


def own(panel: str, tag: str) -> str:
    """The step name of a point the construction adds itself (pole, n′, k′): apart from images."""
    return f"{panel[0]}:({tag})"


#: The pole p of the velocity polygon: the image of every fixed point.
VELOCITY_POLE = own("velocity", "p")
#: The pole p′ of the acceleration polygon.
ACCELERATION_POLE = own("acceleration", "p'")


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


__all__ = ["ACCELERATION_POLE", "LinkageConstruction", "VELOCITY_POLE", "own"]
