"""Two gears in mesh, constructed as the book does (Fig. 5-19 of the Chinese text).

Gear 1 (the driver) at O₁ = (0, 0); gear 2 above it at O₂ = (0, a′) for an external pair, below
at O₂ = (0, −a′) for a ring, or a rack whose reference line is y = a′. The pitch point P lies on
O₁O₂ (on the y axis); the line of action N₁N₂ is tangent to both base circles through P, rising
to the right at α′ to the common tangent (gear 1 turns clockwise); the tip circles cut it at B₂
(gear 2's tip: contact begins) and B₁ (gear 1's tip: contact ends). Everything measured here —
α′, B₁B₂, p_b, the zones, the radii of curvature at B₁, B₂ — is a length or angle on that
construction; the closed forms are :mod:`graphmech.exact.gear`'s.
"""
from __future__ import annotations

from dataclasses import dataclass

from graphmech.mechanisms.gear import GearSet

XY = tuple[float, float]


@dataclass(frozen=True)
class MeshConstruction:
    """The construction of a pair in mesh (m, rad).

    O2, N2, r_w2 are None for a rack (N₂ is at infinity along the line of action). ``a_w`` is the
    centre distance drawn (a′), ``alpha_w`` the angle measured between N₁N₂ and the common tangent
    at P, ``r_w1``/``r_w2`` the working pitch radii (O₁P, O₂P). ``pb`` the base pitch as laid off
    on the line of action, ``B1B2``, ``N1N2`` (None for a rack), ``eps_alpha`` = B₁B₂/p_b.
    ``zone_points``: the points at p_b from B₁ and from B₂ on B₁B₂ (bounding the double-contact
    zones at its ends and the single-contact zone between), empty when ε < 1 or ε ≥ 2;
    ``single_contact``/``double_contact`` their lengths (None likewise). ``rho``: the radii of
    curvature at the ends of contact, {"N1B1", "N1B2", "N2B1", "N2B2"} (N2… absent for a rack).
    ``backlash``: circumferential, on the working pitch circle, from the flanks constructed there
    (None unless the set states both a′ and the shifts). ``interference``: B₁ or B₂ beyond N₂ or
    N₁ ("B1 beyond N2" …), empty when the contact lies within N₁N₂."""

    O1: XY
    O2: XY | None
    P: XY
    N1: XY
    N2: XY | None
    B1: XY
    B2: XY
    a_w: float
    alpha_w: float
    r_w1: float
    r_w2: float | None
    pb: float
    B1B2: float
    N1N2: float | None
    eps_alpha: float
    zone_points: tuple[XY, ...]
    single_contact: float | None
    double_contact: float | None
    rho: dict[str, float]
    backlash: float | None
    interference: tuple[str, ...]


def construct_meshing(gears: GearSet) -> MeshConstruction:
    raise NotImplementedError


__all__ = ["MeshConstruction", "construct_meshing"]
