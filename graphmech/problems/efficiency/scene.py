"""Read an efficiency scene (``[efficiency]``) — and route a balancing scene to its reader.

An efficiency scene is one problem of friction and efficiency: a block on an inclined plane, the
wedge of problem F1430, a screw (square or V thread), or a chain of machines in series and in
parallel. :func:`parse_efficiency_scene` is the rest of :func:`graphmech.scene.parse_scene` for a
scene with an ``[efficiency]`` or a ``[balancing]`` table (the latter read by
:mod:`graphmech.problems.balancing.scene`), with the same reader, key paths and one-line messages: every
problem is collected, then raised once as a :class:`~graphmech.errors.SceneError`.

The format, with examples, is the "Efficiency and balancing scenes" section of
``docs/scene-format.md``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Mapping

from graphmech.problems.reader import (
    LINKAGE_KEYS,
    MISSING,
    Reader,
    Scene,
    raise_sorted,
    read_header,
    read_measured,
    read_scales,
    read_tail,
    say,
    is_choice,
    type_name,
)

if TYPE_CHECKING:
    from graphmech.methods.efficiency import Direction
    from graphmech.problems.balancing.scene import BalancingProblem


EFFICIENCY_TYPES = ("incline", "wedge", "screw", "chain", "wedge_clamp", "buffer")
DIRECTIONS: tuple[Direction, ...] = ("forward", "reverse")
THREADS = ("square", "V")
PUSHES = ("horizontal", "parallel")
#: A screw's collar (bearing face) friction radius: the mean (d0 + dw)/4, or the annulus' exact
#: (dw³ − d0³)/(3(dw² − d0²)) under uniform pressure.
COLLAR_RADII = ("mean", "annulus")
#: What an efficiency scene may show: the sketch of the bodies with their forces (the unrolled
#: thread for a screw, the block diagram of a chain) and the force polygons at μF.
EFFICIENCY_SHOW_CHOICES = ("diagram", "polygon")
#: The keys each type reads, besides ``type``.
_TYPE_KEYS = {
    "incline": ("angle", "push", "f", "load", "direction"),
    "wedge": ("gamma", "beta", "f", "load", "direction"),
    "screw": ("thread", "half_angle", "f", "f_v", "d2", "pitch", "starts", "lead_angle", "at_self_locking_limit",
              "d1", "collar", "load", "direction", "f_c", "torque", "collar_radius", "speed"),
    "chain": ("load", "speed", "stage"),
    "wedge_clamp": ("wedge_angle", "face", "load", "direction"),
    "buffer": ("wedge_angle", "f", "load", "direction"),
}
#: Quantities each type offers: name → (unit, depends on the direction, needs friction).
QUANTITIES: dict[str, dict[str, tuple[str, bool, bool]]] = {
    "incline": {"phi": ("deg", False, True), "F": ("N", True, True), "F0": ("N", False, False),
                "eta": ("", True, True), "R": ("N", True, True), "self_locking_angle": ("deg", False, True)},
    "wedge": {"phi": ("deg", False, True), "F": ("N", True, True), "F0": ("N", False, False),
              "eta": ("", True, True), "R12": ("N", True, True), "R32": ("N", True, True),
              "R31": ("N", True, True), "gamma_limit": ("deg", False, True)},
    "screw": {"psi": ("deg", False, False), "phi_v": ("deg", False, True), "F": ("N", True, True),
              "F0": ("N", False, False), "M": ("N·m", True, True), "eta": ("", True, True),
              "R": ("N", True, True), "self_locking_angle": ("deg", False, True),
              "eta_self_locking_max": ("", False, True), "r_f": ("m", False, False), "sigma": ("Pa", False, False),
              "r_c": ("m", False, False), "M_c": ("N·m", False, False), "T_tighten": ("N·m", False, True),
              "F_a": ("N", False, True), "sigma_a": ("Pa", False, True), "P_drive": ("W", False, True),
              "n_screw": ("rpm", False, False)},
    # each face of the clamp declares its own f (0: frictionless), so nothing waits for a scene-wide f
    "wedge_clamp": {"phi_face1": ("deg", False, False), "phi_face2": ("deg", False, False), "F": ("N", True, False),
                    "F0": ("N", False, False), "eta": ("", True, False), "R_face1": ("N", True, False),
                    "alpha_lock_reverse": ("deg", False, False)},
    "buffer": {"phi": ("deg", False, True), "F": ("N", True, True), "F0": ("N", False, False),
               "eta": ("", True, True), "R12": ("N", True, True), "R42": ("N", True, True), "R31": ("N", True, True),
               "alpha_lock_forward": ("deg", False, True), "alpha_lock_reverse": ("deg", False, True),
               "f_lock_forward": ("", False, False), "f_lock_reverse": ("", False, False)},
    "chain": {"eta": ("", False, False), "P_in": ("W", False, False), "P_out": ("W", False, False)},
}
DEFAULT_FIND = {"incline": ("F", "eta"), "wedge": ("F", "eta"), "screw": ("psi", "eta"), "chain": ("eta", "P_in"),
                "wedge_clamp": ("F", "eta"), "buffer": ("F", "eta")}


@dataclass(frozen=True)
class Stage:
    """A stage of a chain: its name and its branches (share of the input power, the
    efficiencies in series along the branch); one branch = machines in series."""

    name: str
    branches: tuple[tuple[float, tuple[float, ...]], ...]


@dataclass(frozen=True)
class EfficiencyProblem:
    """An [efficiency] table in SI (N, rad, m, W).

    ``f`` is the friction coefficient (for a screw given as ``f_v``: the equivalent one, then
    ``half_angle`` is 0); None when the scene asks for nothing that needs it. ``lead_angle`` of a
    screw is None when it sits at the self-locking limit (ψ = φv). A wedge clamp's and a buffer's
    wedge angle α is ``angle``; the clamp's faces are (name, f), face 1 the one F runs along.
    A screw's ``torque`` is a wrench's T (the axial force follows from it), ``f_c`` the collar's
    friction coefficient, ``collar_rule`` its friction radius, ``speed`` the load's lift speed.
    """

    type: str
    directions: tuple[Direction, ...] = DIRECTIONS
    f: float | None = None
    load: float | None = None
    angle: float | None = None  # incline α
    push: str = "horizontal"
    gamma: float | None = None
    beta: float | None = None
    thread: str = "square"
    half_angle: float = 0.0
    f_is_equivalent: bool = False
    d2: float | None = None
    lead: float | None = None
    lead_angle: float | None = None
    at_limit: bool = False
    d1: float | None = None
    collar: tuple[float, float] | None = None
    speed: float | None = None
    stages: tuple[Stage, ...] = ()
    faces: tuple[tuple[str, float], ...] = ()
    f_c: float | None = None
    torque: float | None = None
    collar_rule: str = "mean"

    def quantities(self) -> dict[str, tuple[str, bool, bool]]:
        return QUANTITIES[self.type]


_FORCES_KEYS = ("title", "show", "find", "scales", "units", "measured", "check", "page", "efficiency", "balancing")


def parse_efficiency_scene(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]
                           ) -> Scene[EfficiencyProblem | BalancingProblem]:
    """The rest of :func:`graphmech.scene.parse_scene` for an [efficiency] or [balancing] scene.

    Examples
    --------
    >>> from graphmech.scene import parse_scene
    >>> s = parse_scene({"efficiency": {"type": "incline", "angle_deg": 30, "f": 0.1, "load_N": 1000}}, "x.toml")
    >>> s.problem.directions, round(s.problem.angle, 12)
    (('forward', 'reverse'), 0.523598775598)
    >>> parse_scene({"efficiency": {"type": "incline", "angle_deg": 95, "f": 0.1, "load_N": 1}}, "x.toml")
    Traceback (most recent call last):
    ...
    graphmech.errors.SceneError: x.toml: efficiency.angle_deg: must lie between 0° and 90° (exclusive; at least 0.01° from either)
    """
    problems = top.problems
    for key in LINKAGE_KEYS + ("cam", "flywheel"):
        if key in data:
            top.used.add(key)
            top.problem(key, f"a scene is one problem: [{key}] does not go with [efficiency] or [balancing]; "
                             "put it in a scene of its own")
    if "efficiency" in data and "balancing" in data:
        top.used.add("balancing")
        top.problem("balancing", "a scene is one problem: efficiency ([efficiency]) or balancing ([balancing]), "
                                 "not both")
    balancing = "efficiency" not in data
    if balancing:
        from graphmech.problems.balancing.scene import BALANCING_SHOW_CHOICES, read_balancing

        title, show, find = read_header(top, BALANCING_SHOW_CHOICES, BALANCING_SHOW_CHOICES)
        scales = read_scales(top, entries=[("W", "mass_radius"), ("l", "length")])
        problem: Any = read_balancing(top)
    else:
        title, show, find = read_header(top, EFFICIENCY_SHOW_CHOICES, EFFICIENCY_SHOW_CHOICES)
        scales = read_scales(top, entries=[("F", "force")])
        problem = read_efficiency(top, find, show)
        if problem is not None and problem.type == "chain":  # a chain has its block diagram, no polygon
            if "show" not in data:
                show = ("diagram",)
            elif "polygon" in show:
                top.problem(f"show[{list(data['show']).index('polygon')}]",
                            "a chain of machines has no force polygon: show diagram")
    # names such as eta@reverse: the check validates the direction against the quantity
    measured = read_measured(top, None)
    precision, page = read_tail(top, _FORCES_KEYS)
    if problems or problem is None:
        raise_sorted(problems, data, order, "balancing" if balancing else "efficiency", source)
    return Scene(source=source, title=title, show=show, find=find, scales=scales, measured=measured,
                 precision_mm=precision, page=page, kind="balancing" if balancing else "efficiency",
                 problem=problem)


#: How close an angle may come to the ends of its range, degrees: a wedge of 1e-300° has no
#: finite ideal force, and no drawing can tell it from 0°.
ANGLE_MARGIN_DEG = 0.01
#: The largest load, N: beyond it the polygons' sums overflow long before any drawing makes sense.
MAX_LOAD_N = 1e12
#: The smallest overall efficiency of a chain: below it nothing reaches the load (and P_in overflows).
MIN_CHAIN_ETA = 1e-12


def _angle(r: Reader, base: str, lo: float, hi: float, required: bool = True,
           hi_included: bool = False) -> float | None:
    """An angle in (lo, hi) at least ANGLE_MARGIN_DEG from either end; ``hi_included`` admits hi
    itself (a wedge's guide 1 at β = 90°: the wedge press)."""
    v = r.value(base, "angle", required=required)
    if v is None:
        return None
    top = math.radians(hi) if hi_included else math.radians(hi - ANGLE_MARGIN_DEG)
    if not (math.radians(lo + ANGLE_MARGIN_DEG) <= v.si <= top):
        ends = (f"at least {ANGLE_MARGIN_DEG:g}° above {lo:g}°, at most {hi:g}°" if hi_included else
                f"exclusive; at least {ANGLE_MARGIN_DEG:g}° from either")
        r.problem(v.path, f"must lie between {lo:g}° and {hi:g}° ({ends})")
        return None
    return v.si


def _length(r: Reader, base: str) -> float | None:
    """A thread's diameter or pitch: 1 µm … 100 m (beyond, squares underflow or overflow)."""
    v = r.value(base, "length", required=False, positive=True)
    if v is None:
        return None
    if not 1e-6 <= v.si <= 100.0:
        r.problem(v.path, f"{v.text()} is absurd for a screw thread (1 µm … 100 m)")
        return None
    return v.si


def _load(r: Reader, base: str, kind: str, required: bool = True) -> float | None:
    v = r.value(base, kind, required=required, positive=True)
    if v is None:
        return None
    if v.si > MAX_LOAD_N or v.si < 1e-9:
        r.problem(v.path, f"{v.text()} is absurd for a machine (between 1e-9 and {MAX_LOAD_N:g} in SI units)")
        return None
    return v.si


def _fraction(r: Reader, value: Any, path: str, what: str) -> float | None:
    x = r.number(value, path)
    if x is None:
        return None
    if not 0.0 < x <= 1.0:
        r.problem(path, f"{what} must lie in (0, 1], not {x:g}")
        return None
    return x


def _directions(r: Reader) -> tuple[Direction, ...]:
    value = r.raw("direction")
    if value is MISSING:
        return DIRECTIONS
    items = value if isinstance(value, list) else [value]
    out: list[Direction] = []
    for i, item in enumerate(items):
        path = r.at("direction") + (f"[{i}]" if isinstance(value, list) else "")
        if not is_choice(item, DIRECTIONS):
            r.problem(path, f"unknown value {say(item) if isinstance(item, str) else type_name(item)}: "
                            'use "forward" (F drives: raising, tightening) or "reverse" (the load drives: '
                            "lowering, loosening)")
        elif item in out:
            r.problem(path, f"{item} is listed twice")
        else:
            out.append(item)
    if isinstance(value, list) and not value:
        r.problem(r.at("direction"), "an empty list: give forward, reverse or both")
    return tuple(out) or DIRECTIONS


def _needs_friction(kind: str, find: tuple[str, ...], show: tuple[str, ...]) -> bool:
    names = [n.partition("@")[0] for n in find] or list(DEFAULT_FIND[kind])
    q = QUANTITIES[kind]
    return "polygon" in show or any(q.get(n, ("", False, True))[2] for n in names)


def _needs_load(kind: str, find: tuple[str, ...], show: tuple[str, ...]) -> bool:
    """The load Q is needed for the polygon and every force, moment or stress (η too: it is read
    off the polygons); not for angles such as ψ."""
    names = [n.partition("@")[0] for n in find] or list(DEFAULT_FIND[kind])
    return "polygon" in show or any(n in ("F", "F0", "eta", "R", "R12", "R32", "R31", "R42", "R_face1", "M", "sigma",
                                          "M_c", "T_tighten", "P_drive") for n in names)


def read_efficiency(top: Reader, find: tuple[str, ...], show: tuple[str, ...]) -> EfficiencyProblem | None:
    """[efficiency] → :class:`EfficiencyProblem` (None after reporting when it is invalid)."""
    r = top.table_at("efficiency", required=True)
    if r is None:
        return None
    kind = r.string("type", choices=EFFICIENCY_TYPES, required=True)
    if kind is None:
        r.ignore(*{k for keys in _TYPE_KEYS.values() for k in keys})
        r.finish()
        return None
    # a key of two other types (speed, wedge_angle) is said once; a clamp says its own word on f
    flagged: set[str] = {"f"} if kind == "wedge_clamp" else set()
    for other, keys in _TYPE_KEYS.items():
        for key in keys:
            if key not in _TYPE_KEYS[kind] and key not in flagged and r.present(key) is not None:
                flagged.add(key)
                r.known.add(key)
                for k in list(r.table):
                    if k == key or k.startswith(key + "_"):
                        r.used.add(k)
                        r.problem(r.at(k), f"not a key of type {kind!r} (it belongs to {other!r})")
    ok = True
    if kind == "chain":
        load = _load(r, "load", "force")
        speed = _load(r, "speed", "velocity")
        stages = _read_stages(r)
        r.finish()
        if load is None or speed is None or not stages or _has(r, "efficiency"):
            return None
        return EfficiencyProblem("chain", (), load=load, speed=speed, stages=stages)
    directions = _directions(r)
    # a screw tightened by a wrench: the torque gives the axial force, no load is needed
    load_needed = _needs_load(kind, find, show) and not (kind == "screw" and r.present("torque") is not None)
    load = _load(r, "load", "force", required=load_needed)
    prob: dict[str, Any] = {}
    if kind == "wedge_clamp":
        if "f" in r.table:
            r.used.add("f")
            r.problem(r.at("f"), "a wedge clamp's faces each declare their own f in [[efficiency.face]]")
        prob["angle"] = _angle(r, "wedge_angle", 0.0, 90.0)
        prob["faces"] = _read_faces(r)
        r.finish()
        if prob["angle"] is None or len(prob["faces"]) != 2 or (load_needed and load is None) or _has(r, "efficiency"):
            return None
        return EfficiencyProblem(kind, directions, load=load, **prob)
    f_needed = _needs_friction(kind, find, show)
    f, equivalent = _friction(r, kind, f_needed)
    if kind == "buffer":
        prob["angle"] = _angle(r, "wedge_angle", 0.0, 90.0)
        ok = prob["angle"] is not None
    elif kind == "incline":
        prob["angle"] = _angle(r, "angle", 0.0, 90.0)
        prob["push"] = r.string("push", choices=PUSHES, default="horizontal") or "horizontal"
        ok = prob["angle"] is not None
    elif kind == "wedge":
        prob["gamma"] = _angle(r, "gamma", 0.0, 90.0)
        prob["beta"] = _angle(r, "beta", 0.0, 90.0, hi_included=True)  # 90°: the wedge press
        ok = prob["gamma"] is not None and prob["beta"] is not None
        if ok and abs(math.degrees(prob["gamma"] + prob["beta"]) - 90.0) < 1.0:
            r.problem(r.at(r.present("beta") or "beta"),
                      "γ + β within 1° of 90°: slider 1's guide carries almost nothing and the side it bears on "
                      "is undecided; the reconstruction needs γ + β clear of 90°")
            ok = False
    else:
        ok = _read_screw(r, prob, f, equivalent)
    r.finish()
    if not ok or (load_needed and load is None) or (f_needed and f is None) or _has(r, "efficiency"):
        return None
    return EfficiencyProblem(kind, directions, f=f, load=load, f_is_equivalent=equivalent, **prob)


def _has(r: Reader, prefix: str) -> bool:
    return any(p.startswith(prefix) for p, _ in r.problems)


def _friction(r: Reader, kind: str, needed: bool) -> tuple[float | None, bool]:
    has_f, has_fv = "f" in r.table, kind == "screw" and "f_v" in r.table
    r.known.update(["f", "f_v"] if kind == "screw" else ["f"])
    if has_f and has_fv:
        r.used.update(["f", "f_v"])
        r.problem(r.at("f_v"), "give f (with the thread's form) or f_v (the equivalent coefficient), not both")
        return None, False
    key = "f_v" if has_fv else "f"
    if key not in r.table:
        if needed:
            more = " or f_v (the equivalent coefficient)" if kind == "screw" else ""
            r.problem(r.at("f"), f"missing: the friction coefficient f{more}, needed for what the scene asks "
                                 "(η, F, the polygon)")
        return None, False
    r.used.add(key)
    x = r.number(r.table[key], r.at(key))
    if x is None:
        return None, False
    if not 0.0 <= x < 10.0:
        r.problem(r.at(key), f"must lie in [0, 10), not {x:g}")
        return None, False
    return x, has_fv


def _read_screw(r: Reader, prob: dict[str, Any], f: float | None, equivalent: bool) -> bool:
    thread = r.string("thread", choices=THREADS, default="square") or "square"
    prob["thread"] = thread
    ok = True
    if thread == "V" and not equivalent:
        prob["half_angle"] = _angle(r, "half_angle", 0.0, 90.0, required=f is not None) or 0.0
    else:
        if r.present("half_angle") is not None:
            r.value("half_angle", "angle")
            if thread == "square":
                r.problem(r.at(r.present("half_angle") or "half_angle"), "a square thread has no half-angle "
                          '(write thread = "V")')
                ok = False
        prob["half_angle"] = 0.0
    prob["d2"] = _length(r, "d2")
    pitch = _length(r, "pitch")
    starts_raw = r.raw("starts")
    starts = 1
    if starts_raw is not MISSING:
        if isinstance(starts_raw, bool) or not isinstance(starts_raw, int) or not 1 <= starts_raw <= 12:
            r.problem(r.at("starts"), "must be a whole number of thread starts, 1 … 12")
            ok = False
        else:
            starts = starts_raw
    limit = r.flag("at_self_locking_limit")
    if limit is None and r.raw("at_self_locking_limit") is not MISSING:
        ok = False  # said by flag()
    at_limit = limit is True
    lead_angle = _angle(r, "lead_angle", 0.0, 90.0, required=False)
    given = [n for n, v in (("pitch", pitch), ("lead_angle", lead_angle)) if v is not None] + \
        (["at_self_locking_limit"] if at_limit else [])
    if len(given) != 1:
        key = given[1] if len(given) > 1 else "pitch"
        where = r.at(r.present(key) or key)
        r.problem(where, "give the thread's lead as exactly one of pitch_mm (with d2_mm), lead_angle_deg, or "
                         "at_self_locking_limit = true" + (f" (given: {', '.join(given)})" if given else ""))
        return False
    if pitch is not None:
        if prob["d2"] is None:
            r.problem(r.at("d2"), "missing: the pitch diameter d2 (write d2_mm), needed with pitch")
            return False
        prob["lead"] = pitch * starts
        prob["lead_angle"] = math.atan(prob["lead"] / (math.pi * prob["d2"]))
    elif lead_angle is not None:
        prob["lead_angle"] = lead_angle
    else:
        if not f:
            r.problem(r.at("at_self_locking_limit"), "the self-locking limit ψ = φv needs a friction coefficient "
                                                     "f > 0 (without friction nothing self-locks)")
            return False
        prob["at_limit"] = True
        prob["lead_angle"] = None
    prob["d1"] = _length(r, "d1")
    if prob["d1"] is not None and prob["d2"] is not None and prob["d1"] >= prob["d2"]:
        r.problem(r.at(r.present("d1") or "d1"), f"the minor diameter d1 = {prob['d1'] * 1000:g} mm must be smaller "
                                                 f"than the pitch diameter d2 = {prob['d2'] * 1000:g} mm")
        ok = False
    collar = r.quantity("collar", "length", required=False)
    if collar is not None:
        xy = r.numbers(collar.value, r.at(collar.key), 2, positive=True, shape="[d0, dw]")
        if xy is not None:
            if not all(1e-6 <= collar.si(v) <= 100.0 for v in xy):
                r.problem(r.at(collar.key), "absurd bearing-face diameters (1 µm … 100 m)")
                ok = False
            elif xy[0] >= xy[1]:
                r.problem(r.at(collar.key), "the bearing face's inner diameter d0 must be smaller than its outer dw")
                ok = False
            prob["collar"] = (collar.si(xy[0]), collar.si(xy[1]))
    if "f_c" in r.table:
        r.used.add("f_c")
        fc = r.number(r.table["f_c"], r.at("f_c"))
        if fc is not None and not 0.0 <= fc < 10.0:
            r.problem(r.at("f_c"), f"must lie in [0, 10), not {fc:g}")
            fc = None
        ok = ok and fc is not None
        prob["f_c"] = fc
    r.known.add("f_c")
    torque = r.value("torque", "moment", required=False, positive=True)
    if torque is not None:
        if not 1e-9 <= torque.si <= 1e12:
            r.problem(torque.path, f"{torque.text()} is absurd for a wrench (between 1e-9 and 1e12 N·m)")
            ok = False
        prob["torque"] = torque.si
    prob["collar_rule"] = r.string("collar_radius", choices=COLLAR_RADII, default="mean") or "mean"
    prob["speed"] = _load(r, "speed", "velocity", required=False)
    return ok


def _read_faces(r: Reader) -> tuple[tuple[str, float], ...]:
    """A wedge clamp's two [[efficiency.face]] tables: name and f (0: frictionless)."""
    out = []
    tables = r.tables_at("face")
    for k, t in enumerate(tables):
        name = t.string("name", default=f"face {k + 1}") or f"face {k + 1}"
        if len(name) > 40:
            t.problem(t.at("name"), "too long (at most 40 characters)")
        raw = t.raw("f", required=True, hint="its friction coefficient, 0 for a frictionless face")
        x = None if raw is MISSING else t.number(raw, t.at("f"))
        if x is not None and not 0.0 <= x < 10.0:
            t.problem(t.at("f"), f"must lie in [0, 10), not {x:g} (0: frictionless)")
            x = None
        t.finish()
        if x is not None:
            out.append((name, x))
    if len(tables) != 2 and not _has(r, r.at("face")):
        r.problem(r.at("face"), f"{len(tables)} [[efficiency.face]] tables: a wedge clamp has two faces (face 1, "
                                "along which F pushes the wedge, then face 2, which bears the clamping force)")
    return tuple(out)


def _read_stages(r: Reader) -> tuple[Stage, ...]:
    out = []
    for k, s in enumerate(r.tables_at("stage")):
        name = s.string("name", default=f"stage {k + 1}") or f"stage {k + 1}"
        if len(name) > 40:
            s.problem(s.at("name"), "too long (at most 40 characters)")
        has_eta, has_branch = "eta" in s.table, "branch" in s.table
        s.known.update(["eta", "count", "branch"])
        if has_eta == has_branch:
            s.problem(s.at("eta"), "give eta (machines in series) or [[…branch]] (machines in parallel), one of them")
            s.used.update(["eta", "branch", "count"])
            s.finish()
            continue
        if has_eta:
            s.used.add("eta")
            eta = _fraction(s, s.table["eta"], s.at("eta"), "an efficiency")
            count_raw = s.raw("count")
            count = 1
            if count_raw is not MISSING:
                if isinstance(count_raw, bool) or not isinstance(count_raw, int) or not 1 <= count_raw <= 100:
                    s.problem(s.at("count"), "must be a whole number 1 … 100 (identical machines in series)")
                    count = 0
                else:
                    count = count_raw
            s.finish()
            if eta is not None and count:
                out.append(Stage(name, ((1.0, (eta,) * count),)))
            continue
        branches = []
        for b in s.tables_at("branch"):
            share = b.raw("share", required=True, hint="the branch's share of the stage's input power")
            sh = None if share is MISSING else b.number(share, b.at("share"), positive=True)
            etas = b.raw("eta", required=True, hint="the efficiencies in series along the branch, a list")
            es: list[float] = []
            if etas is not MISSING:
                items = etas if isinstance(etas, list) else [etas]
                for i, e in enumerate(items):
                    x = _fraction(b, e, b.at("eta") + (f"[{i}]" if isinstance(etas, list) else ""), "an efficiency")
                    if x is not None:
                        es.append(x)
                if not items:
                    b.problem(b.at("eta"), "an empty list")
                ok = len(es) == len(items) and bool(items)
            else:
                ok = False
            b.finish()
            if sh is not None and ok:
                branches.append((sh, tuple(es)))
        s.finish()
        if len(branches) < 2 and not _has(s, s.path):
            s.problem(s.at("branch"), "machines in parallel need at least two [[…branch]] tables")
        elif branches:
            out.append(Stage(name, tuple(branches)))
    if not out and not _has(r, r.at("stage")):
        r.problem(r.at("stage"), "no [[efficiency.stage]]: a chain needs at least one machine")
    log_eta = sum(math.log(sum(sh * math.prod(es) for sh, es in st.branches) / sum(sh for sh, _ in st.branches))
                  for st in out if all(math.prod(es) > 0 for _, es in st.branches))
    if out and (log_eta < math.log(MIN_CHAIN_ETA) or any(math.prod(es) <= 0 for st in out for _, es in st.branches)):
        r.problem(r.at("stage"), f"the chain's overall efficiency is below {MIN_CHAIN_ETA:g}: nothing reaches the load")
        return ()
    return tuple(out)


__all__ = ["EfficiencyProblem", "Stage", "parse_efficiency_scene", "read_efficiency", "QUANTITIES", "DEFAULT_FIND",
           "EFFICIENCY_SHOW_CHOICES"]
