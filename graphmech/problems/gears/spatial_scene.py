"""Reading a helical, bevel or worm pair (``meshing = "helical"``, ``"bevel"``, ``"worm"``): the keys
``beta``, ``face_width``, ``shaft_angle``, ``worm_diameter`` / ``q`` and ``ratio`` of ``[gear]``, and
the names such a pair may find (docs/scene-format.md, "Helical, bevel and worm gears").

Called from :func:`graphmech.problems.gears.scene._read_gear` (one hook) and from its name
look-ups; it knows the gear model and the reader, not the scene (which imports it).
"""
from __future__ import annotations

import math

from graphmech.mechanisms.gear import SPATIAL_MESHINGS, GearSet, Meshing, SpatialPair
from graphmech.problems.judging import close_names
from graphmech.problems.reader import MISSING, Reader, not_for, say

#: A helical pair's names → unit in ``check`` (gear's own with its number).
HELICAL_QUANTITIES = {
    "beta": "deg", "a_initial": "m", "a": "m", "mt": "m", "alpha_t": "deg", "pn": "m", "pt": "m", "sn": "m",
    "st": "m", "ha": "m", "hf": "m", "beta_b": "deg", "eps_alpha": "", "eps_beta": "", "eps_gamma": "",
    **{f"{stem}{i}": unit for i in (1, 2) for stem, unit in
       (("d", "m"), ("da", "m"), ("df", "m"), ("db", "m"), ("alpha_at", "deg"), ("zv", ""), ("pz", "m"))},
}
#: A bevel pair's names (on the large end).
BEVEL_QUANTITIES = {
    "R_cone": "m", "theta_a": "deg", "theta_f": "deg", "ha": "m", "hf": "m",
    **{f"{stem}{i}": unit for i in (1, 2) for stem, unit in
       (("delta", "deg"), ("d", "m"), ("da", "m"), ("df", "m"), ("zv", ""))},
}
#: A worm drive's names (gear 1 the worm, gear 2 the wheel).
WORM_QUANTITIES = {
    "z2": "", "q": "", "gamma1": "deg", "beta2": "deg", "px": "m", "pz1": "m", "d1": "m", "d2": "m", "da1": "m",
    "da2": "m", "df1": "m", "df2": "m", "a": "m",
}
#: The names that need the face width B.
NEEDS_B = ("eps_beta", "eps_gamma")
#: The book's helix angles: helical gears 8° … 20°, double-helical up to about 40°; 45° is a limit
#: no gear reaches (the reader refuses β ≥ 45°).
BETA_WORDS = "0 ≤ β < 45° (helical gears are cut with β = 8° … 20°, double-helical up to about 40°)"
#: The least helix angle drawn, rad: below it the lead πd/tan β (10⁹·πd) cannot be cut on the
#: developed turn (the helix and the line x = πd are parallel to double precision).
BETA_LEAST = 1e-9
#: The widest face, in modules: a strip a million modules long leaves p_t no drawn length.
FACE_MOST_M = 1000.0
#: How close to whole z₂ = i·z₁ must be.
WHOLE_REL = 1e-9


def spatial_quantities(gears: GearSet) -> dict[str, str]:
    """The names this helical, bevel or worm pair can find, with their units."""
    if gears.meshing == "helical":
        b = gears.spatial.face_width if gears.spatial is not None else None
        return {n: u for n, u in HELICAL_QUANTITIES.items() if b is not None or n not in NEEDS_B}
    if gears.meshing == "bevel":
        return dict(BEVEL_QUANTITIES)
    return dict(WORM_QUANTITIES)


def spatial_unit(name: str, gears: GearSet) -> str | None:
    """The unit of a find/measured name of a helical, bevel or worm pair, or None.

    >>> from graphmech.mechanisms.gear import SpurGear, ToothSystem
    >>> g = GearSet(ToothSystem(0.008, 0.35), (SpurGear(20), SpurGear(40)), "helical", spatial=SpatialPair(0.2))
    >>> spatial_unit("zv2", g), spatial_unit("eps_beta", g), spatial_unit("delta1", g)
    ('', None, None)
    """
    return spatial_quantities(gears).get(name)


def spatial_names(gears: GearSet) -> list[str]:
    """Every name the pair can find (for 'did you mean')."""
    return list(spatial_quantities(gears))


def spatial_unknown(name: str, gears: GearSet) -> str:
    """Why a name is not one of this pair's, in one line."""
    if gears.meshing == "helical" and name in NEEDS_B:
        return f"{say(name)} needs the face width B: give face_width_mm"
    others = [m for m in SPATIAL_MESHINGS if m != gears.meshing
              and name in {"helical": HELICAL_QUANTITIES, "bevel": BEVEL_QUANTITIES, "worm": WORM_QUANTITIES}[m]]
    if others:
        return f"{say(name)} is a {others[0]} pair's quantity, not a {gears.meshing} pair's"
    hint = close_names(name.partition("@")[0], spatial_names(gears))
    return f"unknown gear quantity {say(name)} for a {gears.meshing} pair{hint}"


def read_spatial(g: Reader, meshing: Meshing | None, zs: tuple[int, ...] | None,
                 xs: tuple[float | None, ...] | None, m: float | None
                 ) -> tuple[SpatialPair | None, tuple[int, ...] | None, tuple[float | None, ...] | None]:
    """The helical, bevel or worm keys of ``[gear]``: (the pair's geometry, the tooth numbers — z₂
    from ``ratio`` when only z₁ is given —, the shifts); refusals go to the reader's problems.
    A spur gear or pair refuses these keys; ``(None, zs, xs)`` then."""
    keys = ("beta", "face_width", "shaft_angle", "worm_diameter", "q", "ratio")
    if meshing not in SPATIAL_MESHINGS:
        why = {"beta": 'a helix angle belongs to meshing = "helical" (a spur pair has β = 0)',
               "face_width": 'a face width is read for meshing = "helical" (ε_β) or "bevel"',
               "shaft_angle": 'a shaft angle belongs to meshing = "bevel"',
               "worm_diameter": 'a worm diameter belongs to meshing = "worm"',
               "q": 'a diameter factor q belongs to meshing = "worm"',
               "ratio": 'ratio is read for a helical, bevel or worm pair (a spur pair\'s is z2/z1)'}
        for key in keys:
            not_for(g, [key], why[key])
        return None, zs, xs
    assert meshing is not None
    bad = len(g.problems)
    what = f"a {meshing} pair"
    if xs is not None and any(x not in (None, 0.0) for x in xs):
        g.problem(g.at("x"), f"a profile-shifted {meshing} pair is not posed yet: leave x out (x = 0)")
    for key in ("span_teeth", "pin_diameter"):
        if g.present(key) is not None:
            g.problem(g.at(g.present(key) or key), f"{key} is a spur gear's; {what} does not read it")
    beta = 0.0
    face = None
    sigma = 0.5 * math.pi
    d1 = None
    if meshing == "helical":
        got = g.scalar("beta", "angle", required=True)
        if got is not None and not 0.0 <= got < 0.25 * math.pi:
            g.problem(g.at(g.present("beta") or "beta"), f"a helix angle of {math.degrees(got):g}° is outside {BETA_WORDS}")
        elif got is not None and 0.0 < got < BETA_LEAST:
            g.problem(g.at(g.present("beta") or "beta"), f"a helix angle of {math.degrees(got):g}° has no drawable lead "
                      f"(β < {BETA_LEAST:g} rad): give beta = 0 for a spur pair")
        elif got is not None:
            beta = got
    else:
        not_for(g, ["beta"], f"a helix angle belongs to a helical pair, not {what}"
                + (" (the wheel's β₂ equals the worm's lead angle γ₁)" if meshing == "worm" else ""))
    if meshing in ("helical", "bevel"):
        face = g.scalar("face_width", "length", required=False, positive=True)
        if face is not None and m is not None and face > FACE_MOST_M * m:
            g.problem(g.at(g.present("face_width") or "face_width"), f"a face width of {face * 1e3:g} mm is no gear's "
                      f"(at most {FACE_MOST_M:g}·m = {FACE_MOST_M * m * 1e3:g} mm)")
            face = None
    else:
        not_for(g, ["face_width"], "a worm drive's face width is not read (its sizes follow from m, z and d₁)")
    if meshing == "bevel":
        got = g.scalar("shaft_angle", "angle", required=False, default=0.5 * math.pi)
        if got is not None and not 0.0 < got < math.pi:
            g.problem(g.at(g.present("shaft_angle") or "shaft_angle"),
                      f"a shaft angle of {math.degrees(got):g}° is outside 0 < Σ < 180°")
        elif got is not None:
            sigma = got
        if g.present("centre_distance") is not None:
            g.problem(g.at(g.present("centre_distance") or "centre_distance"),
                      "a bevel pair's axes intersect: it has no centre distance (give shaft_angle)")
    else:
        not_for(g, ["shaft_angle"], f"a shaft angle belongs to a bevel pair, not {what}")
    if meshing == "worm":
        d1 = _worm_diameter(g, m)
        if g.present("centre_distance") is not None:
            g.problem(g.at(g.present("centre_distance") or "centre_distance"),
                      "a worm drive's centre distance follows from d₁ and d₂, a = (d₁ + d₂)/2: give worm_diameter or q")
    else:
        not_for(g, ["worm_diameter", "q"], f"the worm's reference diameter belongs to a worm drive, not {what}")
    zs = _with_ratio(g, meshing, zs)
    if len(g.problems) > bad or zs is None:
        return None, zs, xs
    return SpatialPair(beta=beta, face_width=face, shaft_angle=sigma, worm_diameter=d1), zs, (0.0,) * len(zs)


def _worm_diameter(g: Reader, m: float | None) -> float | None:
    """d₁ from worm_diameter, or q·m (None when m itself was refused: that is said where it is read)."""
    d1 = g.scalar("worm_diameter", "length", required=False, positive=True)
    q_raw = g.raw("q")
    if q_raw is MISSING and d1 is None:
        if g.present("worm_diameter") is None:
            g.problem(g.at("worm_diameter"), "missing: a worm needs its reference diameter, worm_diameter_mm = 50 "
                                             "or the diameter factor q = d1/m (q = 10)")
        return None
    if q_raw is not MISSING and g.present("worm_diameter") is not None:
        g.problem(g.at("q"), "give the worm's diameter once: worm_diameter or q, not both")
        return None
    if q_raw is MISSING:
        return d1
    q = g.number(q_raw, g.at("q"), positive=True)
    if q is None:
        return None
    if not 2.0 <= q <= 100.0:
        g.problem(g.at("q"), f"a diameter factor q = {q:g} is no worm's (the book's table: 8 … 18; allowed 2 … 100)")
        return None
    return None if m is None else q * m


def _with_ratio(g: Reader, meshing: Meshing, zs: tuple[int, ...] | None) -> tuple[int, ...] | None:
    raw = g.raw("ratio")
    need = f'a {meshing} pair needs z = [z1, z2], or z = [z1] with ratio'
    if raw is MISSING:
        if zs is not None and len(zs) != 2:
            g.problem(g.at("z"), need)
            return None
        return zs
    i = g.number(raw, g.at("ratio"), positive=True)
    if i is None or zs is None:
        return None
    if len(zs) == 2:
        if abs(zs[1] / zs[0] - i) > WHOLE_REL * i:
            g.problem(g.at("ratio"), f"i = {i:g} disagrees with z2/z1 = {zs[1]}/{zs[0]} = {zs[1] / zs[0]:.6g}: give "
                                     "one of them")
            return None
        return zs
    z2 = i * zs[0]
    if abs(z2 - round(z2)) > WHOLE_REL * max(z2, 1.0) or round(z2) < 1:
        g.problem(g.at("ratio"), f"i·z1 = {i:g} × {zs[0]} = {z2:.6g} is not a whole number of teeth for the wheel")
        return None
    if round(z2) > 100_000:
        g.problem(g.at("ratio"), f"i·z1 = {round(z2)} teeth: more than 100000")
        return None
    return (zs[0], round(z2))


__all__ = ["BEVEL_QUANTITIES", "HELICAL_QUANTITIES", "NEEDS_B", "WORM_QUANTITIES", "read_spatial", "spatial_names",
           "spatial_quantities", "spatial_unit", "spatial_unknown"]
