"""Read a balancing scene (``[balancing]``): a rigid rotor's eccentric masses and its correction.

``type = "static"``: the masses lie in one plane (a disc); one correction mass at radius r_b.
``type = "dynamic"``: the masses lie at axial positions z; two correction planes I and II at
``planes`` (distinct), a correction mass in each at its radius. Read by the same reader as every
scene (key paths, one-line messages, all problems collected); called from
:func:`graphmech.problems.efficiency.scene.parse_efficiency_scene`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from graphmech.mechanisms.rotor import RotorMass
from graphmech.problems.reader import MISSING, Reader, say, type_name

BALANCING_TYPES = ("static", "dynamic")
#: What a balancing scene may show: the rotor (end view with the masses; the planes for a
#: dynamic one) and the mass-radius polygons at μW.
BALANCING_SHOW_CHOICES = ("rotor", "polygon")
#: Quantities: name → (unit, which type has it).
QUANTITIES = {
    "static": {"W_b": "kg·m", "m_b": "kg", "theta_b": "deg", "residual_force": "kg·m"},
    "dynamic": {"W_I": "kg·m", "m_I": "kg", "theta_I": "deg", "W_II": "kg·m", "m_II": "kg", "theta_II": "deg",
                "residual_force": "kg·m", "residual_moment": "kg·m²"},
}
#: The correction split into two given directions (static, ``split_angles``; seed 001 8-4).
SPLIT_QUANTITIES = {"W_b1": "kg·m", "W_b2": "kg·m", "m_b1": "kg", "m_b2": "kg"}
#: The unbalanced rotor's centrifugal force at ``speed`` (seed 001 8-1).
SPEED_QUANTITIES = {"F_unbalanced": "N"}
#: Two split directions whose |sin| of the angle between them is below this are parallel: the
#: closing side cannot be resolved along them.
PARALLEL_SPLIT = 1e-9
DEFAULT_FIND = {"static": ("W_b", "m_b", "theta_b", "residual_force"),
                "dynamic": ("W_I", "m_I", "theta_I", "W_II", "m_II", "theta_II", "residual_force", "residual_moment")}
MAX_MASSES = 50
#: Two correction planes closer than this, relative to their distance from z = 0 (or to 1 mm), are
#: one plane: the lever rule would divide by a rounding error.
COINCIDENT_PLANES = 1e-9
#: The largest m, r or |z| in SI units (kg, m): beyond it the polygon's sums overflow.
MAX_SIZE = 1e9


@dataclass(frozen=True)
class BalancingProblem:
    """A [balancing] table in SI: the masses, the correction radii (one per plane) and, for a
    dynamic balance, the axial positions (z_I, z_II) of the correction planes."""

    type: str
    masses: tuple[RotorMass, ...]
    r_b: tuple[float, ...]
    planes: tuple[float, float] | None = None
    split: tuple[float, float] | None = None  # α₁, α₂ (rad): the correction split along them
    omega: float | None = None  # the rotor's speed, rad/s, for F_unbalanced


def read_balancing(top: Reader) -> BalancingProblem | None:
    """[balancing] → :class:`BalancingProblem` (None after reporting when it is invalid).

    Examples
    --------
    >>> from graphmech.scene import parse_scene
    >>> s = parse_scene({"balancing": {"type": "dynamic", "planes_mm": [100, 100], "correction_radius_mm": 50,
    ...     "mass": [{"m_kg": 1, "r_mm": 10, "angle_deg": 0, "z_mm": 50}]}}, "r.toml")
    Traceback (most recent call last):
    ...
    graphmech.errors.SceneError: r.toml: balancing.planes_mm: the correction planes coincide (z = 0.1 m): dynamic balancing needs two distinct planes
    """
    r = top.table_at("balancing", required=True)
    if r is None:
        return None
    kind = r.string("type", choices=BALANCING_TYPES, required=True)
    dynamic = kind == "dynamic"
    radii = _radii(r, 2 if dynamic else 1)
    planes = None
    if dynamic:
        given = r.quantity("planes", "length", required=True)
        if given is not None:
            zz = r.numbers(given.value, r.at(given.key), 2, shape="[z_I, z_II]")
            if zz is not None and max(abs(given.si(zz[0])), abs(given.si(zz[1]))) > MAX_SIZE:
                r.problem(r.at(given.key), "absurd plane positions for a rotor (|z| up to 1e9 m)")
            elif zz is not None:
                a, b = given.si(zz[0]), given.si(zz[1])
                if abs(a - b) <= COINCIDENT_PLANES * max(abs(a), abs(b), 1e-3):
                    r.problem(r.at(given.key), f"the correction planes coincide (z = {a:g} m): dynamic balancing "
                                               "needs two distinct planes")
                else:
                    planes = (a, b)
    elif r.present("planes") is not None:
        r.quantity("planes", "length", required=False)
        r.problem(r.at(r.present("planes") or "planes"), 'a static balance has one plane: no planes (write type = "dynamic")')
    split = _split(r, dynamic)
    omega = r.scalar("speed", "omega", required=False, positive=True)
    masses = []
    items = r.tables_at("mass")
    if not items and "mass" not in r.table:
        r.problem(r.at("mass"), "no [[balancing.mass]]: nothing to balance")
    if len(items) > MAX_MASSES:
        r.problem(r.at("mass"), f"too many masses ({len(items)} > {MAX_MASSES})")
        items = []
    names: set[str] = set()
    for k, s in enumerate(items):
        name = s.raw("name")
        label = str(k + 1)
        if name is not MISSING:
            if not isinstance(name, str) or not name.isalnum() or len(name) > 6:
                s.problem(s.at("name"), f"must be a short label of letters and digits, not "
                                        f"{say(name) if isinstance(name, str) else type_name(name)}")
            else:
                label = name
        if label in names:
            s.problem(s.at("name"), f"mass {label} is given twice")
        names.add(label)
        m = s.scalar("m", "mass", positive=True)
        rad = s.scalar("r", "length", positive=True)
        th = s.scalar("angle", "angle")
        if dynamic:
            z = s.scalar("z", "length")
        else:
            z = 0.0
            if s.present("z") is not None:
                s.quantity("z", "length", required=False)
                s.problem(s.at(s.present("z") or "z"), 'a static balance has one plane: no z (write type = "dynamic")')
        s.finish()
        for value, base in ((m, "m"), (rad, "r"), (z, "z")):
            if value is not None and (abs(value) > MAX_SIZE or 0 < abs(value) < 1e-9):
                s.problem(s.at(s.present(base) or base), f"{value:g} (SI) is absurd for a rotor")
                m = None
        if m is not None and rad is not None and th is not None and z is not None:
            masses.append(RotorMass(label, m, rad, th, z))
    r.finish()
    if kind is None or radii is None or (dynamic and planes is None) or len(masses) != len(items) or not masses:
        return None
    return BalancingProblem(kind, tuple(masses), radii, planes, split, omega)


def _split(r: Reader, dynamic: bool) -> tuple[float, float] | None:
    """``split_angles``: two non-parallel directions (static only), in rad."""
    given = r.quantity("split_angles", "angle", required=False)
    if given is None:
        return None
    path = r.at(given.key)
    if dynamic:
        r.problem(path, 'a split into two directions is for a static balance (type = "static")')
        return None
    aa = r.numbers(given.value, path, 2, shape="[alpha_1, alpha_2]")
    if aa is None:
        return None
    a1, a2 = given.si(aa[0]), given.si(aa[1])
    if abs(math.sin(a2 - a1)) < PARALLEL_SPLIT:
        r.problem(path, f"the two directions are parallel ({math.degrees(a1):g}° and {math.degrees(a2):g}°): no split")
        return None
    return a1, a2


def _radii(r: Reader, count: int) -> tuple[float, ...] | None:
    given = r.quantity("correction_radius", "length", required=True)
    if given is None:
        return None
    path = r.at(given.key)
    value = given.value
    if isinstance(value, list):
        xs = r.numbers(value, path, count, positive=True, shape="[r_I, r_II]" if count == 2 else "[r_b]")
        out = None if xs is None else tuple(given.si(x) for x in xs)
    else:
        x = r.number(value, path, positive=True)
        out = None if x is None else (given.si(x),) * count
    if out is not None and any(not 1e-9 <= v <= MAX_SIZE for v in out):
        r.problem(path, "an absurd correction radius for a rotor (between 1e-9 and 1e9 m)")
        return None
    return out


__all__ = ["BALANCING_SHOW_CHOICES", "BALANCING_TYPES", "BalancingProblem", "DEFAULT_FIND", "QUANTITIES", "RotorMass", "SPEED_QUANTITIES", "SPLIT_QUANTITIES",
           "read_balancing"]
