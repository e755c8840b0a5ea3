"""The coaxial condition of a planet set (or of a reverted train), as the book writes it.

A planet's axis lies at one distance from its carrier's axis whichever central gear it meshes:
with one module and standard gears, the arm is r_c + r_p = m(z_c + z_p)/2 to a sun (external) and
r_c − r_p = m(z_c − z_p)/2 to a ring (internal, the ring central) — the book's r₃ = r₁ + 2r₂, so
z₃ = z₁ + 2z₂ for a sun–planet–ring set, z₁ + z₂ = z₃ − z₂′ with a double planet. A reverted
train's input and output axes on one line give the same condition for its countershaft.

:func:`solve_missing` solves the one missing tooth number from the meshes that close the set and
says the equation as the book writes it; :func:`arms` gives each mesh's arm to check the others.
"""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

from graphmech.errors import NoSolution, OutOfDomain


@dataclass(frozen=True)
class ArmMesh:
    """One mesh of the set: the central gear (on the carrier's axis) and the planet's gear meshing it.

    kind : ``"external"`` (a sun) or ``"internal"`` (a ring). z : None for the missing number.
    """

    central: str
    z_central: int | None
    planet: str
    z_planet: int | None
    kind: str

    def arm(self, z: int | None = None) -> Fraction:
        """The arm in module units, ½(z_c ± z_p), the missing number taken as ``z``."""
        zc = self.z_central if self.z_central is not None else z
        zp = self.z_planet if self.z_planet is not None else z
        if zc is None or zp is None:
            raise OutOfDomain(f"the mesh {self.central}–{self.planet} has a missing tooth number")
        return Fraction(zc + (zp if self.kind == "external" else -zp), 2)

    def text(self) -> str:
        """``(z1 + z2)/2`` or ``(z3 − z2)/2``."""
        return f"(z{self.central} {'+' if self.kind == 'external' else '−'} z{self.planet})/2"


def arms(meshes: Sequence[ArmMesh]) -> list[Fraction]:
    """Each mesh's arm in module units (every tooth number known)."""
    return [m.arm() for m in meshes]


def solve_missing(gear: str, meshes: Sequence[ArmMesh]) -> tuple[int, str]:
    """The missing tooth number of ``gear`` (None in the meshes), and the book's equation for it.

    >>> solve_missing("3", [ArmMesh("1", 10, "2", 32, "external"), ArmMesh("3", None, "2", 32, "internal")])
    (74, 'z3 = z1 + 2·z2 = 74')
    >>> solve_missing("2", [ArmMesh("1", 20, "2", None, "external"), ArmMesh("3", 80, "2", None, "internal")])
    (30, 'z2 = (z3 − z1)/2 = 30')
    """
    for m in meshes:
        if m.kind not in ("external", "internal"):
            raise OutOfDomain(f"the coaxial condition is for external and internal meshes, not {m.kind}")
    known = [m for m in meshes if m.z_central is not None and m.z_planet is not None]
    with_it = [m for m in meshes if m.z_central is None or m.z_planet is None]
    if not with_it:
        raise OutOfDomain(f"gear {gear} is not in the meshes that close the set")
    if known:
        ref = known[0]
        a2 = 2 * ref.arm()  # z_c ± z_p of the closed mesh
        m = with_it[0]
        rhs = f"z{ref.central} {'+' if ref.kind == 'external' else '−'} z{ref.planet}"
        if m.z_central is None:  # the central gear: z_c = 2a ∓ z_p
            sp = 1 if m.kind == "external" else -1
            z = a2 - sp * Fraction(m.z_planet or 0)
            same = ref.planet == m.planet and ref.kind == "external" and m.kind == "internal"
            expr = (f"z{ref.central} + 2·z{m.planet}" if same
                    else f"{rhs} {'−' if sp > 0 else '+'} z{m.planet}")
        elif m.kind == "external":  # a planet's gear against a sun: z_p = 2a − z_c
            z = a2 - Fraction(m.z_central)
            expr = f"{rhs} − z{m.central}"
        else:  # a planet's gear against a ring: z_p = z_c − 2a
            z = Fraction(m.z_central) - a2
            expr = f"z{m.central} − ({rhs})"
    else:  # the planet itself between a sun and a ring: z_s + z_p = z_r − z_p
        ext = [m for m in with_it if m.kind == "external" and m.z_planet is None]
        ring = [m for m in with_it if m.kind == "internal" and m.z_planet is None]
        if not ext or not ring:
            raise OutOfDomain(f"the coaxial condition cannot give z{gear}: it needs a mesh that does not hold it, "
                              "or the planet between a sun and a ring")
        z = Fraction((ring[0].z_central or 0) - (ext[0].z_central or 0), 2)
        expr = f"(z{ring[0].central} − z{ext[0].central})/2"
    if z.denominator != 1:
        raise NoSolution(f"the coaxial condition gives z{gear} = {z}, not a whole number")
    if z < 1:
        raise NoSolution(f"the coaxial condition gives z{gear} = {z}: no such gear")
    zi = int(z)
    arm = [m.arm(zi) for m in meshes]
    if len(set(arm)) != 1:
        raise NoSolution(f"with z{gear} = {zi} the meshes are still not coaxial (arms "
                         f"{', '.join(str(a) for a in arm)} module units)")
    return zi, f"z{gear} = {expr} = {zi}"


__all__ = ["ArmMesh", "arms", "solve_missing"]
