"""What a gear train's members carry for its dynamics and efficiency, in SI: the inertia, mass and
moment of each member (:class:`Body`), each mesh's efficiency and the worms' friction
(:class:`MeshLosses`), and the geometry both the book's method and the exact solution need (a
planet's arm, the angle between a planet's axis and its carrier's). Nothing here solves anything.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from graphmech.errors import OutOfDomain
from graphmech.mechanisms.gear_train import AXES, GearTrain


@dataclass(frozen=True)
class Body:
    """A member's inertia and load.

    inertia : J about its own axis, kg·m².
    inertia_transverse : J about a diameter, kg·m² (a bevel planet, whose absolute ω has a part
        across its axis; None: not given).
    mass : kg (a planet: its centre moves on the carrier's arm).
    arm : the planet's axis from its carrier's axis, m (None: from the module and its mesh).
    moment : N·m acting on the member, signed along its axis.
    count : identical planets the scene draws once.
    """

    member: str
    inertia: float = 0.0
    inertia_transverse: float | None = None
    mass: float = 0.0
    arm: float | None = None
    moment: float = 0.0
    count: int = 1


@dataclass(frozen=True)
class Worm:
    """A worm mesh (index in ``train.meshes``) with its lead angle γ and friction angle φ_v, rad."""

    mesh: int
    gamma: float
    phi_v: float


@dataclass(frozen=True)
class MeshLosses:
    """Each mesh's efficiency in its carrier's frame; a worm mesh's from γ and φ_v instead."""

    eta: tuple[float, ...]
    worms: tuple[Worm, ...] = ()

    def worm(self, k: int) -> Worm | None:
        return next((w for w in self.worms if w.mesh == k), None)


def axis_cos(axes: Mapping[str, str], a: str, b: str) -> float:
    """cos of the angle between members a's and b's axes (``"+x"`` when not listed)."""
    u, v = AXES[axes.get(a, "+x")], AXES[axes.get(b, "+x")]
    return float(u[0] * v[0] + u[1] * v[1] + u[2] * v[2])


def planet_arm(train: GearTrain, module: float, planet: str, modules: Mapping[str, float] | None = None) -> float:
    """The distance of a planet's axis from its carrier's, m: m(z_c + z_p)/2 from its first mesh
    with a central gear if external, m|z_c − z_p|/2 if internal — m that mesh's module
    (``modules``: gear → its stage's module; else ``module``)."""
    carrier = train.member(planet).carrier
    if carrier is None:
        raise OutOfDomain(f"member {planet} is not a planet: it has no arm")
    for mesh in train.meshes:
        ga, gb = train.gear(mesh.a), train.gear(mesh.b)
        for p, c in ((ga, gb), (gb, ga)):
            if p.member == planet and train.member(c.member).carrier is None and mesh.kind in ("external", "internal"):
                zs = c.z + p.z if mesh.kind == "external" else abs(c.z - p.z)
                return (modules or {}).get(p.name, module) * zs / 2.0
    raise OutOfDomain(f"planet {planet} meshes no central gear on a parallel axis: state its arm")


def check_body(train: GearTrain, body: Body) -> None:
    """A body the train can carry: a mass only on a planet, a transverse J only on a bevel one."""
    m = train.member(body.member)
    for name, v in (("inertia", body.inertia), ("mass", body.mass), ("moment", body.moment)):
        if not math.isfinite(v):
            raise OutOfDomain(f"member {body.member}: its {name} is a finite number, not {v!r}")
    if body.inertia < 0 or body.mass < 0 or (body.inertia_transverse or 0.0) < 0:
        raise OutOfDomain(f"member {body.member}: an inertia or a mass is ≥ 0")
    if body.count < 1:
        raise OutOfDomain(f"member {body.member}: count is a whole number ≥ 1, not {body.count}")
    if m.carrier is None and (body.mass or body.arm is not None or body.count != 1):
        raise OutOfDomain(f"member {body.member} turns about a fixed axis through its centre: its mass, arm "
                          "and count add nothing (give its inertia)")


__all__ = ["Body", "MeshLosses", "Worm", "axis_cos", "check_body", "planet_arm"]
