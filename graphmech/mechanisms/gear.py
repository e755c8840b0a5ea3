"""Involute spur gears: the basic rack's tooth system, a gear, and a pair in mesh.

Frozen dataclasses in SI (m, rad), no drawing and no checking: the construction
(:mod:`graphmech.methods.involute`, :mod:`graphmech.methods.gear_meshing`) and the exact solution
(:mod:`graphmech.exact.gear`) both start from these.

Conventions (docs/scene-format.md, [gear]):

- an internal gear (a ring) has its own positive tooth number z; its tooth *space* at the
  reference circle is πm/2 + 2xm·tan α, its tip circle d − 2(h*a − x)m and its root circle
  d + 2(h*a + c* + x)m, so that inv α′ = 2 tan α (x₂ − x₁)/(z₂ − z₁) + inv α holds for an
  internal pair as the book writes it;
- gear 1 is the pinion and the driver; in a rack-and-pinion pair the rack is the second member
  (``gears`` holds the pinion alone);
- the stated centre distance a′ is the distance O₁O₂, or for a rack the distance from the
  pinion's centre to the rack's reference line.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

#: How two members mesh: two external gears, a pinion inside a ring, a pinion on a rack; a helical
#: pair on parallel axes, a bevel pair on intersecting axes, a worm and its wheel on crossed axes.
Meshing = Literal["external", "internal", "rack", "helical", "bevel", "worm"]
MESHINGS: tuple[Meshing, ...] = ("external", "internal", "rack", "helical", "bevel", "worm")
#: The meshings whose teeth are not straight spur teeth (their geometry is :class:`SpatialPair`'s).
SPATIAL_MESHINGS: tuple[Meshing, ...] = ("helical", "bevel", "worm")
#: |x| above this is no gear anyone cuts (the tooth is pointed long before): the readers' limit.
MAX_SHIFT = 10.0


@dataclass(frozen=True)
class ToothSystem:
    """The basic rack's profile shared by the gears of a set: module m (m), pressure angle α at
    the reference circle (rad), addendum and clearance coefficients h*a, c*."""

    m: float
    alpha: float
    ha_star: float = 1.0
    c_star: float = 0.25


@dataclass(frozen=True)
class SpurGear:
    """A spur gear: tooth number z, profile shift coefficient x, internal (a ring) or not, and
    the tip shortening coefficient Δy of a shifted external pair (its tip circle
    d + 2(h*a + x − Δy)m keeps the standard clearance at the pair's centre distance)."""

    z: int
    x: float = 0.0
    internal: bool = False
    delta_y: float = 0.0


@dataclass(frozen=True)
class SpatialPair:
    """What a helical, bevel or worm pair adds to its tooth system (SI, rad). ``ToothSystem.m`` is
    then the normal module m_n (helical), the module at the large end (bevel) or the worm's axial
    module (= the wheel's transverse module), and α, h*a, c* the normal (helical) or axial (worm)
    values.

    helical: ``beta`` the helix angle as stated — the pair's, or with a stated centre distance a
    the initial one, the pair's then being cos β = m_n(z₁ + z₂)/(2a); bevel: ``shaft_angle`` Σ;
    worm: ``worm_diameter`` d₁ (gear 1 is the worm, its z the number of starts). ``face_width`` B (helical: for ε_β; bevel: along the cone), None if not given."""

    beta: float = 0.0
    face_width: float | None = None
    shaft_angle: float = 0.5 * math.pi
    worm_diameter: float | None = None


@dataclass(frozen=True)
class GearSet:
    """One gear (``meshing`` None), or a pair in mesh: ``gears`` = (pinion, wheel) for an external
    or internal pair, (pinion,) for a rack and pinion. ``centre_distance`` is the stated a′ (None:
    the distance at which the pair meshes without backlash)."""

    system: ToothSystem
    gears: tuple[SpurGear, ...]
    meshing: Meshing | None = None
    centre_distance: float | None = None
    #: a helical, bevel or worm pair's own geometry (None for spur gears)
    spatial: SpatialPair | None = None

    @property
    def pair(self) -> bool:
        return self.meshing is not None


@dataclass(frozen=True)
class RackGeneration:
    """Generation by the rack cutter (范成法): the cutter's speed v (m/s); the blank's angular
    speed ω (rad/s) and the distance L from the blank's centre to the cutter's datum line (m),
    each None when the gear's z and x set them (ω = v/r, L = r + xm with r = mz/2); the cutter
    positions drawn per tooth pitch (the cutter moves πm/N between two)."""

    cutter_speed: float
    blank_speed: float | None = None
    datum_distance: float | None = None
    positions: int = 12


__all__ = ["MESHINGS", "SPATIAL_MESHINGS", "GearSet", "Meshing", "RackGeneration", "SpatialPair", "SpurGear",
           "ToothSystem"]
