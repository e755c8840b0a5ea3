"""Read a gear scene (``[gear]``): one involute spur gear, or a pair in mesh.

``z = 20`` poses one gear (its tooth, its span and pins); ``z = [19, 42]`` with ``meshing``
poses a pair (``"external"``, ``"internal"``: gear 2 is the ring; ``"rack"``: ``z = [z1]`` and
a rack). The names a scene may find are fixed here (:data:`GEAR_QUANTITIES`, a gear's own with
its number in a pair) and checked on reading, so a misspelt name is one line naming ``find[i]``.
"""
from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from graphmech.errors import GraphmechError
from graphmech.exact import gear as ex
from graphmech.exact import profile_shift as ps
from graphmech.mechanisms.gear import (
    MAX_SHIFT,
    MESHINGS,
    SPATIAL_MESHINGS,
    GearSet,
    Meshing,
    RackGeneration,
    SpurGear,
    ToothSystem,
)
from graphmech.problems.gears.generation import GENERATION_QUANTITIES, read_generation
from graphmech.problems.gears.spatial_scene import (
    read_spatial,
    spatial_names,
    spatial_unit,
    spatial_unknown,
)
from graphmech.problems.judging import close_names
from graphmech.problems.reader import (
    MISSING,
    Reader,
    Scene,
    is_choice,
    one_of,
    raise_sorted,
    read_header,
    read_measured,
    read_scales,
    read_tail,
    say,
    type_name,
)

#: What a gear scene may show (figures.PANELS in this order).
GEAR_SHOW_CHOICES = ("tooth", "meshing", "zones", "measurement", "root_base", "generation", "helix")
#: A gear's own quantities (a number suffix in a pair) → unit in ``check``.
TOOTH_QUANTITIES = {
    "d": "m", "db": "m", "da": "m", "df": "m", "ha": "m", "hf": "m",
    "s_pitch": "m", "e_pitch": "m", "sa": "m", "sb": "m", "alpha_a": "deg", "rho_pitch": "m", "rho_a": "m",
    "ra_pointed": "m", "alpha_a_pointed": "deg", "inv_alpha_a_pointed": "",
    "W": "m", "d_pin": "m", "M": "m",
    "x": "", "x_min": "", "x_min_exact": "",
}
#: Quantities at a stated radius, named ``s_k@85`` (the radius in mm).
AT_RADIUS = {"s_k": "m", "alpha_k": "deg", "rho_k": "m", "theta_k": "deg"}
#: The set's quantities (no suffix).
SET_QUANTITIES = {"p": "m", "pb": "m", "z_root_eq_base": "", "z_min": "", "z_min_exact": ""}
#: A pair's quantities.
PAIR_QUANTITIES = {
    "a": "m", "a_w": "m", "alpha_w": "deg", "rw1": "m", "rw2": "m", "N1N2": "m", "B1B2": "m", "eps_alpha": "",
    "single_contact": "m", "double_contact": "m", "eta_tip1": "", "eta_root1": "", "eta_tip2": "", "eta_root2": "",
    "backlash": "m", "x_sum": "", "y": "", "delta_y": "",
}
#: Design words for ``x`` (docs/scene-format.md, "Profile shift"): the shifts chosen, not stated.
SHIFT_WORDS = ("least", "least_exact", "for_centre_distance", "repair")
#: The largest tooth number (z = 1000 is the book's "rack limit"; beyond 1e5 a tooth is a rack's).
MAX_Z = 100_000
#: The module's sane range, m (a watch gear 0.05 mm … a mill gear 100 mm, with margins).
MODULE_RANGE = (1e-6, 10.0)
#: The radius in a name ``s_k@85``: mm.
RADIUS_AT = re.compile(r"[0-9]+(?:\.[0-9]+)?")


@dataclass(frozen=True)
class GearScene:
    """A [gear] table in SI: the set, and per gear the span's k and the pin diameter when stated."""

    gears: GearSet
    span_teeth: tuple[int | None, ...] = ()
    pin_diameter: tuple[float | None, ...] = ()
    #: the key path of the stated centre distance as written (``gear.centre_distance_mm``), for messages
    centre_distance_key: str = "gear.centre_distance"
    #: how the shifts were chosen (a word of SHIFT_WORDS), None when stated as numbers
    shift: str | None = None
    #: with shift "for_centre_distance": the pinion's stated shift; with "repair": the wheel's thickness loss, m
    x1_stated: float | None = None
    thickness_loss: float | None = None
    #: [gear.generation]: the rack cutter's generation (problems/gears/generation.py)
    generation: RackGeneration | None = None

    @property
    def labels(self) -> tuple[str, ...]:
        """The gears' suffixes: ``("",)`` for one gear, ``("1", "2")`` for a pair, ``("1",)`` for a pinion on a rack."""
        if not self.gears.pair:
            return ("",)
        return tuple(str(i + 1) for i in range(len(self.gears.gears)))


def quantity_unit(name: str, problem: GearScene) -> str | None:
    """The unit of a find/measured name in this scene, or None when the scene has no such quantity.

    >>> g = GearScene(GearSet(ToothSystem(0.005, math.radians(20)), (SpurGear(19), SpurGear(42)), "external"))
    >>> quantity_unit("da2", g), quantity_unit("s_k1@85", g), quantity_unit("da", g), quantity_unit("B1B2", g)
    ('m', 'm', None, 'm')
    """
    if problem.gears.meshing in SPATIAL_MESHINGS:  # helical, bevel, worm: spatial_scene's names
        return spatial_unit(name, problem.gears)
    base, _, at = name.partition("@")
    if problem.generation is not None and base in GENERATION_QUANTITIES and not at:
        return GENERATION_QUANTITIES[base]
    labels = problem.labels
    for i, label in enumerate(labels):
        if label and not base.endswith(label):
            continue
        stem = base[: len(base) - len(label)] if label else base
        if at:
            if stem in AT_RADIUS and RADIUS_AT.fullmatch(at):
                return AT_RADIUS[stem]
        elif stem in ("x_min", "x_min_exact") and problem.gears.gears[i].internal:
            continue  # a ring is cut by a pinion cutter: the rack's least shift is not its
        elif stem in TOOTH_QUANTITIES:
            return TOOTH_QUANTITIES[stem]
    if at:
        return None
    if base in SET_QUANTITIES:
        return SET_QUANTITIES[base]
    if problem.gears.pair and base in PAIR_QUANTITIES:
        if problem.gears.meshing == "rack" and base in ("rw2", "N1N2", "x_sum", "y", "delta_y"):
            return None
        if problem.gears.meshing == "internal" and base in ("delta_y", "x_sum"):  # a ring: x₂ − x₁ counts, its tips stay
            return None
        return PAIR_QUANTITIES[base]
    return None


def known_names(problem: GearScene) -> list[str]:
    """Every plain name the scene can find (for 'did you mean')."""
    if problem.gears.meshing in SPATIAL_MESHINGS:
        return spatial_names(problem.gears)
    names = [n for n in (stem + label for label in problem.labels for stem in TOOTH_QUANTITIES)
             if quantity_unit(n, problem) is not None]
    names += [f"{stem}{label}@r" for label in problem.labels for stem in AT_RADIUS]
    names += list(SET_QUANTITIES) + (list(GENERATION_QUANTITIES) if problem.generation is not None else [])
    if problem.gears.pair:
        names += [n for n in PAIR_QUANTITIES if quantity_unit(n, problem) is not None]
    return names


def parse_gear_scene(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]) -> Scene[GearScene]:
    """The rest of :func:`graphmech.scene.parse_scene` for a scene with a [gear] table.

    Examples
    --------
    >>> from graphmech.scene import parse_scene
    >>> s = parse_scene({"gear": {"m_mm": 5, "z": [19, 42], "meshing": "external"}}, "g.toml")
    >>> s.problem.gears.gears, s.problem.labels
    ((SpurGear(z=19, x=0.0, internal=False, delta_y=0.0), SpurGear(z=42, x=0.0, internal=False, delta_y=0.0)), ('1', '2'))
    >>> parse_scene({"gear": {"m_mm": 5, "z": [19, 42]}}, "g.toml")
    Traceback (most recent call last):
    ...
    graphmech.errors.SceneError: g.toml: gear.meshing: missing: a pair of gears needs meshing = "external", "internal" or "rack"
    """
    title, show, find = read_header(top, GEAR_SHOW_CHOICES, ())
    scales = read_scales(top, entries=(("l", "length"), ("tooth", "length"), ("zones", "length"),
                                       ("generation", "length")))
    for key in data:
        if key in ("frame", "driver", "dyad", "point", "cam", "flywheel", "forces", "structure", "cycle",
                   "characteristics", "efficiency", "balancing"):
            top.used.add(key)
            top.problem(key, "belongs to another kind of problem; this is a gear scene ([gear]): put each in a "
                             "scene of its own")
    g = top.table_at("gear", required=True)
    problem = None if g is None else _read_gear(g)
    if problem is not None:
        for i, name in enumerate(find):
            if quantity_unit(name, problem) is None:
                top.problem(f"find[{i}]", _unknown(name, problem))
    measured = read_measured(top, None, cam=False)
    if problem is not None:
        for name, _ in measured:
            if quantity_unit(name, problem) is None:
                top.problem(f"measured.{name}", _unknown(name, problem))
    precision, page = read_tail(top)
    if top.problems or problem is None:
        raise_sorted(top.problems, data, order, "gear", source)
    return Scene(source=source, title=title, show=show, find=find, scales=scales, measured=measured,
                 precision_mm=precision, page=page, kind="gears", problem=problem)


def _unknown(name: str, problem: GearScene) -> str:
    if problem.gears.meshing in SPATIAL_MESHINGS:
        return spatial_unknown(name, problem.gears)
    base, _, at = name.partition("@")
    if at and not RADIUS_AT.fullmatch(at):
        return f"{say(name)}: the radius after @ is a number of mm (s_k@85)"
    if not problem.gears.pair and base in PAIR_QUANTITIES:
        return f"{say(name)} belongs to a pair of gears: give z = [z1, z2] and meshing"
    what = "one gear" if not problem.gears.pair else f"an {problem.gears.meshing} pair" \
        if problem.gears.meshing == "external" or problem.gears.meshing == "internal" else "a rack and pinion"
    hint = _close(base, known_names(problem))
    if not hint and not problem.gears.pair and _close(base, PAIR_QUANTITIES):
        hint = _close(base, PAIR_QUANTITIES) + " (a pair's: give z = [z1, z2] and meshing)"
    return f"unknown gear quantity {say(name)} for {what}{hint}"


def _close(base: str, names: Any) -> str:
    """'; did you mean …?' by spelling, or by a name that begins with what was written (eps → eps_alpha)."""
    hint = close_names(base, names)
    starts = sorted(n for n in names if n.startswith(base) and len(base) >= 2)
    return hint or (f"; did you mean {', '.join(starts[:3])}?" if starts else "")


def _read_gear(g: Reader) -> GearScene | None:
    bad = len(g.problems)
    m = g.scalar("m", "length", positive=True)
    if m is not None and not MODULE_RANGE[0] <= m <= MODULE_RANGE[1]:
        g.problem(g.at(g.present("m") or "m"), f"a module of {m * 1000:g} mm is no gear's (1e-3 … 1e4 mm)")
        m = None
    alpha = g.scalar("alpha", "angle", required=False, default=math.radians(20.0))
    if alpha is not None and not math.radians(5.0) <= alpha <= math.radians(45.0):
        g.problem(g.at(g.present("alpha") or "alpha"), f"a pressure angle of {math.degrees(alpha):g}° is no "
                                                       "involute gear's (5° … 45°)")
        alpha = None
    ha = _coefficient(g, "ha_star", 1.0, 0.0, 3.0)
    c = _coefficient(g, "c_star", 0.25, 0.0, 1.0)
    gen = read_generation(g, m)  # [gear.generation]: a blank speed and L set z and x
    zs = _teeth(g) if gen is None or gen.z_drawn is None else (gen.z_drawn,)
    count = len(zs) if zs is not None else 1
    shift = _shift_word(g)
    xs = (0.0,) * count if shift is not None else _per_gear(g, "x", count, 0.0) \
        if gen is None or gen.x_drawn is None else (gen.x_drawn,)
    meshing_value = g.raw("meshing")
    meshing: Meshing | None = None
    if meshing_value is not MISSING:
        if not is_choice(meshing_value, MESHINGS):
            g.problem(g.at("meshing"), f"unknown value {say(meshing_value)}: use {one_of(MESHINGS)}")
        else:
            meshing = meshing_value
    internal = g.flag("internal")
    if zs is not None:
        if len(zs) == 2 and meshing is None and meshing_value is MISSING:
            g.problem(g.at("meshing"), 'missing: a pair of gears needs meshing = "external", "internal" or "rack"')
        elif meshing == "rack" and len(zs) != 1:
            g.problem(g.at("z"), "a rack and pinion gives the pinion's z alone: z = [z1]")
        elif meshing in ("external", "internal") and len(zs) != 2:
            g.problem(g.at("z"), f"an {meshing} pair needs z = [z1, z2]")
        elif meshing == "internal" and zs[1] <= zs[0]:
            g.problem(g.at("z"), f"the ring (gear 2) must have more teeth than the pinion: z = {list(zs)}")
        if internal and meshing is not None:
            g.problem(g.at("internal"), 'a pair says which gear is a ring by meshing = "internal"')
    a_w = g.scalar("centre_distance", "length", required=False, positive=True)
    if a_w is not None and meshing is None:
        g.problem(g.at(g.present("centre_distance") or "centre_distance"), "one gear has no centre distance: "
                                                                          "give z = [z1, z2] and meshing")
    ks = _span_teeth(g, count, zs)
    pins = _per_gear(g, "pin_diameter", count, None, kind="length")
    x1_raw = g.raw("x1")
    x1 = None if x1_raw is MISSING else g.number(x1_raw, g.at("x1"))
    loss = g.scalar("thickness_loss", "length", required=False, positive=True)
    shorten = g.flag("tip_shortening")
    _shift_keys(g, shift, meshing, a_w, x1, loss, shorten, bool(internal) and meshing is None)
    spatial, zs, xs = read_spatial(g, meshing, zs, xs, m)  # helical, bevel, worm: spatial_scene.py
    if spatial is not None and zs is not None:
        ks, pins = (None,) * len(zs), (None,) * len(zs)
    g.finish()
    if len(g.problems) > bad or None in (m, alpha, ha, c, zs, xs, ks, pins) or zs is None or xs is None:
        return None
    assert m is not None and alpha is not None and ha is not None and c is not None and ks is not None \
        and pins is not None
    ring = [meshing == "internal" and i == 1 or (meshing is None and bool(internal)) for i in range(len(zs))]
    system = ToothSystem(m, alpha, ha, c)
    where = g.at(g.present("centre_distance") or "centre_distance")
    if shift is not None:
        chosen = _choose_shifts(g, system, shift, zs, meshing, a_w, x1, loss, where)
        if chosen is None:
            return None
        if any(abs(x or 0.0) > MAX_SHIFT for x in chosen):
            key = {"for_centre_distance": g.at("x1") if x1 is not None and abs(x1) > MAX_SHIFT else where,
                   "repair": g.at(g.present("thickness_loss") or "thickness_loss")}.get(shift, g.at("x"))
            said = ', '.join(f'{x:.6g}' for x in chosen if x is not None)
            g.problem(key, f"the least shift x_min = {said} is far below −{MAX_SHIFT:g}: a gear of so many teeth needs "
                           "no shift against undercut (leave x out)" if shift in ("least", "least_exact") else
                           f"the shifts chosen come to x = {said}: beyond ±{MAX_SHIFT:g}, no gear's")
            return None
        xs = chosen
    gears = tuple(SpurGear(z, float(x or 0.0), r) for z, x, r in zip(zs, xs, ring))
    if meshing == "external" and shorten is not False:
        gears = _shortened(system, gears, a_w)
        dy = gears[0].delta_y
        if dy >= 2.0 * ha + c:  # the tip circle would lie on or inside the root circle: no tooth left
            g.problem(where if a_w is not None else g.at("x"),
                      f"the tips shortened by Δy = x₁ + x₂ − y = {dy:.6g} would fall below the roots (Δy ≥ 2h*a + c* "
                      f"= {2.0 * ha + c:g}): the shifts x = {gears[0].x:.6g}, {gears[1].x:.6g} are too large for "
                      f"z = {gears[0].z}, {gears[1].z}")
            return None
    return GearScene(GearSet(system, gears, meshing, a_w, spatial), tuple(ks), tuple(pins), where, shift, x1, loss,
                     None if gen is None else gen.model)


def _shift_word(g: Reader) -> str | None:
    """``x = "least"`` …: the design word, or None for stated numbers (read by _per_gear)."""
    value = g.raw("x")
    if not isinstance(value, str):
        return None
    if value not in SHIFT_WORDS:
        g.problem(g.at("x"), f"unknown value {say(value)}: a shift coefficient, a list of them, or {one_of(SHIFT_WORDS)}")
        return None
    return value


def _shift_keys(g: Reader, shift: str | None, meshing: Meshing | None, a_w: float | None, x1: float | None,
                loss: float | None, shorten: bool | None, ring: bool = False) -> None:
    """The keys that go with a design word, and the words that need a pair or a centre distance."""
    if x1 is not None and shift != "for_centre_distance":
        g.problem(g.at("x1"), 'the pinion\'s shift x1 goes with x = "for_centre_distance" (gear 2 takes the rest); '
                              "otherwise give x = [x1, x2]")
    if loss is not None and shift != "repair":
        g.problem(g.at(g.present("thickness_loss") or "thickness_loss"), 'a thickness loss goes with x = "repair"')
    if shorten is not None and meshing != "external":
        g.problem(g.at("tip_shortening"), "only an external pair's tips are shortened (Δy)")
    if shift == "for_centre_distance":
        if meshing not in ("external", "rack"):
            g.problem(g.at("x"), 'x = "for_centre_distance" chooses the shifts of an external pair or a rack and '
                                 "pinion on the stated centre distance")
        elif a_w is None:
            g.problem(g.at("centre_distance"), 'missing: x = "for_centre_distance" needs the centre distance a′ '
                                               "(centre_distance_mm = …)")
        elif meshing == "rack" and x1 is not None:
            g.problem(g.at("x1"), "a rack and pinion has one shift, set by the centre distance: no x1")
    if shift == "repair":
        if meshing != "external":
            g.problem(g.at("x"), 'x = "repair" re-cuts the wheel of an external pair (z = [z1, z2])')
        elif loss is None:
            g.problem(g.at("thickness_loss"), 'missing: x = "repair" needs the wheel\'s thickness loss '
                                              "(thickness_loss_mm = …)")
    if shift is not None and meshing in SPATIAL_MESHINGS:
        g.problem(g.at("x"), f"shifted {meshing} gears are not posed yet: give x = 0 (or leave x out)")
    if shift in ("least", "least_exact") and (meshing == "internal" or ring):
        g.problem(g.at("x"), "a ring is cut by a pinion cutter, not a rack: the rack's least shift does not apply "
                             f"to it; give {'x = [x1, x2]' if meshing == 'internal' else 'x as a number'}")


def _choose_shifts(g: Reader, system: ToothSystem, shift: str, zs: tuple[int, ...],
                   meshing: Meshing | None, a_w: float | None, x1: float | None, loss: float | None, where: str
                   ) -> tuple[float | None, ...] | None:
    """The shifts a design word asks for, by the book's closed forms (the check then constructs
    each one again and sets the two side by side)."""
    try:
        if shift == "least":
            return tuple(ps.x_min_book(system, z) for z in zs)
        if shift == "least_exact":
            return tuple(ps.x_min_exact(system, z) for z in zs)
        if shift == "repair":
            assert loss is not None
            x2 = ps.repair_shift(system, loss)
            a = 0.5 * system.m * (zs[0] + zs[1])
            if a_w is not None and abs(a_w - a) > 1e-9 * a:
                g.problem(where, f"a zero-sum repair keeps the standard centre distance a = {a * 1000:.6g} mm, not "
                                 f"{a_w * 1000:.6g} mm")
                return None
            return (-x2, x2)
        assert a_w is not None
        if meshing == "rack":
            return ((a_w - 0.5 * system.m * zs[0]) / system.m,)
        d = ps.shifts_for_centre_distance(system, zs[0], zs[1], a_w, x1)
        return (d.x1, d.x2)
    except GraphmechError as err:
        g.problem(where if shift == "for_centre_distance" else g.at("x"), str(err))
        return None


def _shortened(system: ToothSystem, gears: tuple[SpurGear, ...], a_w: float | None) -> tuple[SpurGear, ...]:
    """An external pair with x₁ + x₂ ≠ 0: both tips shortened by Δy·m for the standard clearance at
    the pair's centre distance (stated, or where it meshes without backlash)."""
    g1, g2 = gears
    if g1.x + g2.x == 0.0:
        return gears
    try:
        at = a_w if a_w is not None else ex.meshing(GearSet(system, gears, "external")).a_w
        dy = ps.tip_shortening(system, g1.z, g2.z, g1.x + g2.x, at)
    except GraphmechError:  # a pair that cannot mesh: the check says why
        return gears
    if dy <= 0.0:
        return gears
    return tuple(SpurGear(g.z, g.x, g.internal, dy) for g in gears)


def _coefficient(g: Reader, key: str, default: float, lo: float, hi: float) -> float | None:
    value = g.raw(key)
    if value is MISSING:
        return default
    x = g.number(value, g.at(key))
    if x is not None and not lo <= x <= hi:
        g.problem(g.at(key), f"{x:g} is outside {lo:g} … {hi:g}")
        return None
    return x


def _teeth(g: Reader) -> tuple[int, ...] | None:
    value = g.raw("z", required=True, hint="the tooth number: z = 20, or z = [z1, z2] for a pair")
    if value is MISSING:
        return None
    items = value if isinstance(value, list) else [value]
    path = g.at("z")
    if isinstance(value, list) and not 1 <= len(value) <= 2:
        g.problem(path, f"one or two tooth numbers, not {len(value)}")
        return None
    out = []
    for i, v in enumerate(items):
        p = g.at("z") + (f"[{i}]" if isinstance(value, list) else "")
        if isinstance(v, bool) or not isinstance(v, (int, float)) or (isinstance(v, float) and not v.is_integer()):
            g.problem(p, "a tooth number is a whole number, not "
                        + (f"{v:g}" if isinstance(v, float) else type_name(v)))
            return None
        z = int(v)
        if not 1 <= z <= MAX_Z:
            g.problem(p, f"a gear needs at least 1 tooth and at most {MAX_Z}, not {z}")
            return None
        out.append(z)
    return tuple(out)


def _per_gear(g: Reader, base: str, count: int, default: float | None, kind: str | None = None
              ) -> tuple[float | None, ...] | None:
    """One value for every gear or a list of ``count``: a shift (plain number) or a length."""
    if kind is None:
        value = g.raw(base)
        if value is MISSING:
            return (default,) * count
        path = g.at(base)
        si = 1.0
    else:
        given = g.quantity(base, kind, required=False)
        if given is None:
            return (default,) * count if g.present(base) is None else None
        value, path, si = given.value, g.at(given.key), given.si(1.0)
    if isinstance(value, list):
        xs = g.numbers(value, path, count, positive=kind is not None)
        if xs is None:
            return None
        out: tuple[float | None, ...] = tuple(x * si for x in xs)
    else:
        x = g.number(value, path, positive=kind is not None)
        if x is None:
            return None
        out = (x * si,) * count
    if kind is None and any(v is not None and abs(v) > MAX_SHIFT for v in out):
        g.problem(path, f"a shift coefficient beyond ±{MAX_SHIFT:g} is no gear's")
        return None
    if kind is not None and any(v is not None and not 1e-9 <= v <= 100.0 for v in out):
        g.problem(path, "an absurd pin diameter (1e-6 mm … 100 m)")
        return None
    return out


def _span_teeth(g: Reader, count: int, zs: tuple[int, ...] | None) -> tuple[int | None, ...] | None:
    value = g.raw("span_teeth")
    if value is MISSING:
        return (None,) * count
    items = value if isinstance(value, list) else [value] * count
    if len(items) != count:
        g.problem(g.at("span_teeth"), f"one k per gear ({count}), not {len(items)}")
        return None
    out: list[int | None] = []
    for i, v in enumerate(items):
        path = g.at("span_teeth") + (f"[{i}]" if isinstance(value, list) else "")
        if isinstance(v, bool) or not isinstance(v, int):
            g.problem(path, f"k is a whole number of teeth, not {say(v) if isinstance(v, (int, float)) else type_name(v)}")
            return None
        z = zs[i] if zs is not None and i < len(zs) else None
        if v < 1 or (z is not None and v >= z):
            g.problem(path, f"the span covers 1 … z − 1 teeth{f' (z = {z})' if z is not None else ''}, not {v}")
            return None
        out.append(v)
    return tuple(out)


__all__ = [
    "AT_RADIUS",
    "GEAR_SHOW_CHOICES",
    "PAIR_QUANTITIES",
    "SET_QUANTITIES",
    "SHIFT_WORDS",
    "TOOTH_QUANTITIES",
    "GearScene",
    "known_names",
    "parse_gear_scene",
    "quantity_unit",
]
