"""The involute tooth constructed as the book draws it: by points.

The base circle is divided, a tangent drawn at each division N, and the arc unwound from the
flank's start to N laid off along it: K = N − r_b·φ·t (the string unwound from the base circle).
A point at a stated radius r_k is found the same way with φ = tan α_k (the tangent length NK is
√(r_k² − r_b²), the leg of the right triangle ONK). Thicknesses are arcs between the two flanks'
points, radii of curvature the lengths NK; nothing here uses inv α = tan α − α, which is the
exact solution's (:mod:`graphmech.exact.gear`).

Placement: the gear's centre O at the origin, tooth 0 centred on +y, the drawn teeth 0, ±1 …
around it; lengths in m, angles in rad.
"""
from __future__ import annotations

from dataclasses import dataclass

from graphmech.mechanisms.gear import SpurGear, ToothSystem

XY = tuple[float, float]


@dataclass(frozen=True)
class Flank:
    """One flank by points: the start on the base circle, the points K₀ … K_{N−1} from the base
    (or from where the fillet meets it) to the tip, and the strings (N_i, K_i) drawn for them."""

    start: XY
    points: tuple[XY, ...]
    strings: tuple[tuple[XY, XY], ...]


@dataclass(frozen=True)
class ToothOutline:
    """A gear's drawn teeth about O = (0, 0): its circles (m), each tooth's (left, right) flanks,
    the root fillets traced by the cutter's tip between them, and the closed outline of the drawn
    sector (flanks, tip arcs, fillets, root arcs) as one polyline. ``undercut``: the fillet cuts
    into the involute above the base circle (the cutter's tip line passes beyond N)."""

    r: float
    rb: float
    ra: float
    rf: float
    teeth: tuple[tuple[Flank, Flank], ...]
    fillets: tuple[tuple[XY, ...], ...]
    outline: tuple[XY, ...]
    undercut: bool


@dataclass(frozen=True)
class AtRadius:
    """Tooth 0 cut by the circle r_k: the points K on its left and right flank, their strings'
    ends N on the base circle, and what is measured there: α_k (the angle at O between OK and ON),
    the arc thickness s_k between the two K, ρ_k = NK, θ_k the polar angle of K from its flank's
    start on the base circle."""

    r_k: float
    K_left: XY
    K_right: XY
    N_left: XY
    N_right: XY
    alpha_k: float
    s_k: float
    rho_k: float
    theta_k: float


@dataclass(frozen=True)
class SpanMeasurement:
    """The span W_k over k teeth: a line tangent to the base circle (the caliper's jaws are
    perpendicular to it) and its points K₁, K₂ on the two outer flanks of k teeth; W = |K₁K₂|."""

    k: int
    N: XY
    K1: XY
    K2: XY
    W: float


@dataclass(frozen=True)
class PinMeasurement:
    """Pins of diameter d_p in two spaces opposite (or nearest opposite, odd z): their centres,
    the points where they touch the flanks, and M over them (between them for an internal gear)."""

    d_pin: float
    centres: tuple[XY, XY]
    contacts: tuple[XY, ...]
    M: float


def tooth_outline(system: ToothSystem, gear: SpurGear, teeth: int = 3, points: int = 12) -> ToothOutline:
    raise NotImplementedError


def at_radius(system: ToothSystem, gear: SpurGear, r_k: float) -> AtRadius:
    raise NotImplementedError


def pointed_tip(system: ToothSystem, gear: SpurGear) -> AtRadius:
    raise NotImplementedError


def span(system: ToothSystem, gear: SpurGear, k: int) -> SpanMeasurement:
    raise NotImplementedError


def over_pins(system: ToothSystem, gear: SpurGear, d_pin: float | None = None) -> PinMeasurement:
    raise NotImplementedError


__all__ = ["AtRadius", "Flank", "PinMeasurement", "SpanMeasurement", "ToothOutline", "at_radius", "over_pins",
           "pointed_tip", "span", "tooth_outline"]
