"""A gear train: rotating members, the gears they carry, the meshes between them, in SI.

The model the gear-train kind is built on (the book's 轮系): ordinary (every axis fixed in the
frame), planetary and differential trains (planets carried by a carrier H), and compound trains
made of these. Nothing here solves anything: :mod:`graphmech.exact.gear_train` writes the meshes
as a linear system; the constructions (Willis' converted train, the velocity diagram) come later.

Conventions:

* A *member* is one rigid rotating body; it may carry several gears (the double planet 2–2′, a
  shaft with gears 2 and 3, a carrier with a gear cut on it). Names are the book's, primes allowed
  (``"2'"``); a member is usually named after its first gear.
* Every member's speed ω (rad/s) is signed along its own axis. A member's axis is fixed in the
  frame (``carrier=None``: the ordinary gears, the central gears and the carriers themselves, coaxial
  with their carrier) or carried by a carrier member (a planet, ``carrier="H"``). For a planet
  whose axis is not parallel to its carrier's (a bevel planet), ω − ω_H is its spin relative to
  the carrier, the quantity the book's converted train uses.
* A mesh between gears a and b is written in the frame of the member that carries both axes —
  the frame, or the planets' carrier H: (ω_a − ω_H)/(ω_b − ω_H) = s·z_b/z_a. Parallel axes take s
  from the kind (external −1, internal +1); a bevel or worm mesh, or any mesh whose sense the book
  reads from the arrows on its figure, states ``sign`` (spatial axes have no sign of their own:
  it depends on the positive senses chosen on the two axes). A worm's z is its number of starts.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cached_property
from typing import Literal

from graphmech.errors import OutOfDomain

#: Mesh kinds; the parallel-axis ones give the sign of ω_a/ω_b in the carrier's frame.
MeshKind = Literal["external", "internal", "bevel", "worm"]
PARALLEL_SIGN: Mapping[str, int] = {"external": -1, "internal": +1}
MESH_KINDS: tuple[str, ...] = ("external", "internal", "bevel", "worm")

#: The directions a scene names an axis or a pitch point's direction by, as unit vectors of the
#: drawing (x right, y up, z toward the viewer): the one table of them.
AXES: Mapping[str, tuple[int, int, int]] = {
    "+x": (1, 0, 0), "-x": (-1, 0, 0), "+y": (0, 1, 0), "-y": (0, -1, 0), "+z": (0, 0, 1), "-z": (0, 0, -1),
}
#: A worm's hand as h = ±1 (right, left).
HANDS: Mapping[str, int] = {"right": +1, "left": -1}


@dataclass(frozen=True)
class Member:
    """A rigid rotating body; ``carrier`` is the member whose arm carries its axis (a planet);
    ``axis`` its axis in the drawing (:data:`AXES`), along which its speed is signed."""

    name: str
    carrier: str | None = None
    axis: str = "+x"


@dataclass(frozen=True)
class Gear:
    """A gear (or a worm: z = its number of starts) cut on ``member``."""

    name: str
    z: int
    member: str


@dataclass(frozen=True)
class Mesh:
    """Gears ``a`` and ``b`` in mesh; ``sign`` of ω_a/ω_b in the carrier's frame when stated (or
    found from the arrows by the book's rule); a spatial mesh's geometry where the scene draws it:
    ``towards`` (the directions from a's and b's axes to the pitch point, :data:`AXES`) and a worm's
    ``hand`` (the worm is ``a``)."""

    a: str
    b: str
    kind: MeshKind = "external"
    sign: int | None = None
    towards: tuple[str, str] | None = None
    hand: str | None = None

    @property
    def relative_sign(self) -> int:
        """The sign s of (ω_a − ω_H)/(ω_b − ω_H): stated, else from a parallel-axis kind."""
        if self.sign is not None:
            return self.sign
        if self.kind in PARALLEL_SIGN:
            return PARALLEL_SIGN[self.kind]
        raise OutOfDomain(f"the {self.kind} mesh {self.a}–{self.b} needs its sign (from the figure's arrows)")


@dataclass(frozen=True)
class GearTrain:
    """Members, gears, meshes; the members held in the frame; the inputs (member → ω in rad/s)."""

    members: tuple[Member, ...]
    gears: tuple[Gear, ...]
    meshes: tuple[Mesh, ...]
    fixed: tuple[str, ...] = ()
    inputs: Mapping[str, float] = field(default_factory=dict)

    def __post_init__(self) -> None:
        names = [m.name for m in self.members]
        if len(set(names)) != len(names):
            raise OutOfDomain(f"member names repeat: {names}")
        gear_names = [g.name for g in self.gears]
        if len(set(gear_names)) != len(gear_names):
            raise OutOfDomain(f"gear names repeat: {gear_names}")
        known = set(names)
        for m in self.members:
            if m.axis not in AXES:
                raise OutOfDomain(f"member {m.name}: axis {m.axis!r} is not one of {tuple(AXES)}")
            if m.carrier is not None:
                if m.carrier not in known or m.carrier == m.name:
                    raise OutOfDomain(f"member {m.name}: its carrier {m.carrier!r} is not another member")
                if self.member(m.carrier).carrier is not None:
                    raise OutOfDomain(f"member {m.name}: its carrier {m.carrier} is itself a planet (not posed)")
        for g in self.gears:
            if g.member not in known:
                raise OutOfDomain(f"gear {g.name}: no member {g.member!r}")
            if isinstance(g.z, bool) or not isinstance(g.z, int) or g.z < 1:
                raise OutOfDomain(f"gear {g.name}: a tooth number (or number of starts) is a whole number ≥ 1, not {g.z!r}")
        for mesh in self.meshes:
            if mesh.kind not in MESH_KINDS:
                raise OutOfDomain(f"mesh {mesh.a}–{mesh.b}: kind {mesh.kind!r} is not one of {MESH_KINDS}")
            if mesh.sign not in (None, 1, -1):
                raise OutOfDomain(f"mesh {mesh.a}–{mesh.b}: sign {mesh.sign!r} is not +1 or −1")
            if mesh.towards is not None and not all(t in AXES for t in mesh.towards):
                raise OutOfDomain(f"mesh {mesh.a}–{mesh.b}: towards {mesh.towards!r} are not directions {tuple(AXES)}")
            if mesh.hand is not None and mesh.hand not in HANDS:
                raise OutOfDomain(f"mesh {mesh.a}–{mesh.b}: hand {mesh.hand!r} is not right or left")
            _ = mesh.relative_sign  # a spatial mesh without its sign is refused here
            if self.gear(mesh.a).member == self.gear(mesh.b).member:
                raise OutOfDomain(f"mesh {mesh.a}–{mesh.b}: both gears on one member")
            self.mesh_frame(mesh)
        for name in (*self.fixed, *self.inputs):
            if name not in known:
                raise OutOfDomain(f"no member {name!r} (fixed or input)")
        for name, w in self.inputs.items():
            if name in self.fixed:
                raise OutOfDomain(f"member {name} is both fixed and an input")
            if isinstance(w, bool) or not isinstance(w, (int, float)) or not math.isfinite(w):
                raise OutOfDomain(f"the input speed of {name} is a finite number, not {w!r}")

    @cached_property
    def _by_name(self) -> tuple[dict[str, Member], dict[str, Gear]]:
        # looked up once per mesh in every pass of the split and the exact solution: a linear
        # search made a train of a few hundred members take seconds
        return {m.name: m for m in self.members}, {g.name: g for g in self.gears}

    def member(self, name: str) -> Member:
        m = self._by_name[0].get(name)
        if m is None:
            raise OutOfDomain(f"the train has no member {name!r}")
        return m

    def gear(self, name: str) -> Gear:
        g = self._by_name[1].get(name)
        if g is None:
            raise OutOfDomain(f"the train has no gear {name!r}")
        return g

    def member_of(self, name: str) -> str:
        """A member's name, or the name of the member carrying the gear ``name`` (members first)."""
        if name in self._by_name[0]:
            return name
        return self.gear(name).member

    @property
    def carriers(self) -> tuple[str, ...]:
        """The members that carry planets, in the order of the members."""
        used = {m.carrier for m in self.members if m.carrier is not None}
        return tuple(m.name for m in self.members if m.name in used)

    def planets(self, carrier: str) -> tuple[str, ...]:
        return tuple(m.name for m in self.members if m.carrier == carrier)

    def mesh_frame(self, mesh: Mesh) -> str | None:
        """The member whose frame the mesh is written in: a carrier, or None for the frame.

        A planet meshes with a central member (coaxial with its carrier) or with another planet of
        the same carrier; planets of two different carriers never mesh directly.
        """
        ca = self.member(self.gear(mesh.a).member).carrier
        cb = self.member(self.gear(mesh.b).member).carrier
        if ca is not None and cb is not None and ca != cb:
            raise OutOfDomain(f"mesh {mesh.a}–{mesh.b}: planets of two carriers ({ca}, {cb}) do not mesh")
        return ca if ca is not None else cb

    def with_inputs(self, inputs: Mapping[str, float], fixed: tuple[str, ...] | None = None) -> GearTrain:
        """The same train driven otherwise (another input, another member braked)."""
        return GearTrain(self.members, self.gears, self.meshes, self.fixed if fixed is None else fixed, dict(inputs))


def rpm(n: float) -> float:
    """A speed in r/min (the book's n) as ω in rad/s."""
    return n * math.pi / 30.0
