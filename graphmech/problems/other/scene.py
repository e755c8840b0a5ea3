"""Read a scene of the other common mechanisms (其他常用机构): ``[geneva]`` (a single-pin external
Geneva wheel) and ``[differential_screw]`` (a differential or compound screw). A scene poses one of
them or both; docs/scene-format.md ("Other mechanisms") lists every key and name.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from graphmech.problems.reader import (
    MISSING,
    Reader,
    Scene,
    Value,
    raise_sorted,
    read_header,
    read_measured,
    read_scales,
    read_tail,
    say,
)

#: What an other-mechanisms scene may show.
OTHER_SHOW_CHOICES = ("geneva", "geneva_polygons", "geneva_curves", "differential_screw")
#: The Geneva wheel's names → unit (SI; n_dial in r/min as the book gives a speed).
GENEVA_QUANTITIES = {"R_crank": "m", "S_wheel": "m", "h_slot": "m", "r_lock": "m", "k_motion": "", "T_cycle": "s",
                     "t_motion": "s", "t_rest": "s", "n_dial": "r/min", "omega_wheel_max": "rad/s"}
#: The names at the dial angle ``dial_angle``.
GENEVA_AT_ANGLE = {"omega_wheel": "rad/s", "epsilon_wheel": "rad/s²", "v_slide": "m/s", "a_k_pin": "m/s²"}
#: The differential screw's names: screw B for a travel (both branches), or link 2's travel.
SCREW_QUANTITIES = {"p_B": "m", "p_B_alt": "m", "s_B": "m"}
HANDS = ("right", "left")
#: The most slots a Geneva scene takes (a wheel of the book has 3 to 12).
MAX_SLOTS = 360
#: The range of a length (m), of a time (s) and of the dial's speed (rad/s) a scene takes: beyond,
#: the drawing's scales leave double precision.
MIN_SIZE, MAX_SIZE = 1e-9, 1e6
TIMES = (1e-6, 1e9)
SPEEDS = (1e-9, 1e6)


@dataclass(frozen=True)
class GenevaProblem:
    """[geneva] in SI: z slots, the centre distance L, the pin's radius r, the tip thickness b;
    the dial's speed ω₁ (rad/s) given or from the rest t_rest; the dial angle φ for ω₂, ε₂."""

    z: int
    L: float
    r_pin: float
    b: float
    omega1: float
    t_rest: float | None = None
    phi: float | None = None


@dataclass(frozen=True)
class ScrewProblem:
    """[differential_screw] in SI: screw A (link 1 in the frame), its lead and hand; either the
    travel of link 2 per turn of 1 asked for (→ screw B, both branches) or screw B given."""

    p_A: float
    hand_A: str
    travel: float | None = None
    p_B: float | None = None
    hand_B: str | None = None


@dataclass(frozen=True)
class OtherScene:
    geneva: GenevaProblem | None
    screw: ScrewProblem | None


def _value(r: Reader, base: str, *, required: bool = True) -> Value | None:
    return _bounded(r, base, "length", required, MIN_SIZE, MAX_SIZE, "m")


def _bounded(r: Reader, base: str, kind: str, required: bool, lo: float, hi: float, unit: str) -> Value | None:
    """A positive quantity within [lo, hi] (SI): beyond, the drawing's scales leave double precision."""
    v = r.value(base, kind, required=required, positive=True)
    if v is not None and not lo <= v.si <= hi:
        r.problem(v.path, f"{v.text()} is absurd for a mechanism (from {lo:g} to {hi:g} {unit})")
        return None
    return v


def _length(r: Reader, base: str, *, required: bool = True) -> float | None:
    v = _value(r, base, required=required)
    return None if v is None else v.si


def read_geneva(top: Reader) -> GenevaProblem | None:
    """[geneva] → :class:`GenevaProblem` (None after reporting when invalid).

    Examples
    --------
    >>> from graphmech.scene import parse_scene
    >>> parse_scene({"geneva": {"slots": 6, "dial_wheel_distance_mm": 300, "pin_radius_mm": 140,
    ...     "tip_thickness_mm": 12.5, "dwell_time_s": 30}}, "g.toml")
    Traceback (most recent call last):
    ...
    graphmech.errors.SceneError: g.toml: geneva.pin_radius_mm: a pin of 140 mm leaves no locking arc: r + b must be less than R = L sin(π/z) = 150 mm
    """
    g = top.table_at("geneva")
    if g is None:
        return None
    z = g.raw("slots", required=True, hint="the number of slots z, a whole number ≥ 3")
    if z is not MISSING and (isinstance(z, bool) or not isinstance(z, int) or not 3 <= z <= MAX_SLOTS):
        g.problem(g.at("slots"), f"must be a whole number of slots from 3 to {MAX_SLOTS}, not {say(z)}")
        z = MISSING
    L = _length(g, "dial_wheel_distance")
    pin = _value(g, "pin_radius")
    b = _length(g, "tip_thickness")
    rest = _bounded(g, "dwell_time", "time", False, *TIMES, "s")
    speed = _bounded(g, "dial_speed", "omega", False, *SPEEDS, "rad/s")
    if rest is not None and speed is not None:
        g.problem(speed.path, "give the dial's speed or the wheel's dwell time, not both (one decides the other)")
    elif g.present("dwell_time") is None and g.present("dial_speed") is None:
        g.problem(g.at("dwell_time"), "missing: write dwell_time_s (the rest) or dial_speed_rpm")
    angle = g.value("dial_angle", "angle", required=False)
    g.finish()
    if z is MISSING or L is None or pin is None or b is None or (rest is None and speed is None) or \
            (rest is not None and speed is not None):
        return None
    R, r_pin = L * math.sin(math.pi / z), pin.si
    if r_pin + b >= R:
        g.problem(pin.path, f"a pin of {pin.text()} leaves no locking arc: r + b must be less than "
                            f"R = L sin(π/z) = {pin.text(R)}")
        return None
    if R + r_pin >= L:  # the slot's bottom lies L − R − r from the wheel's centre
        g.problem(pin.path, f"a pin of {pin.text()} needs slots past the wheel's centre: R + r must be less than "
                            f"L (R = L sin(π/z) = {pin.text(R)})")
        return None
    if rest is not None:
        omega1 = 2 * math.pi * (z + 2) / (2 * z * rest.si)  # T = t_rest/(1 − k)
    else:
        assert speed is not None
        omega1 = speed.si
    phi = None
    if angle is not None:
        half = math.pi / 2 - math.pi / z
        phi = math.remainder(angle.si, 2 * math.pi)
        if abs(phi) > half:
            g.problem(angle.path, f"the pin is out of the slot at {angle.text()}: it drives the wheel for "
                                  f"|φ| ≤ {math.degrees(half):.6g}° from the line of centres (the wheel rests)")
            return None
    return GenevaProblem(int(z), L, r_pin, b, omega1, None if rest is None else rest.si, phi)


def read_screw(top: Reader) -> ScrewProblem | None:
    """[differential_screw] → :class:`ScrewProblem` (None after reporting when invalid)."""
    s = top.table_at("differential_screw")
    if s is None:
        return None
    p_A = _length(s, "lead_A")
    hand_A = s.string("hand_A", choices=HANDS, required=True)
    travel = _length(s, "travel", required=False)
    p_B = _length(s, "lead_B", required=False)
    hand_B = s.string("hand_B", choices=HANDS)
    given_B = s.present("lead_B") is not None
    if s.present("travel") is not None and given_B:
        s.problem(s.at(s.present("lead_B") or "lead_B"), "give the travel asked for (to find screw B) or screw B "
                                                          "(to find the travel), not both")
    elif s.present("travel") is None and not given_B:
        s.problem(s.at("travel"), "missing: write travel_mm (the travel of link 2 per turn of link 1) or "
                                  "lead_B_mm with hand_B")
    elif given_B and s.raw("hand_B") is MISSING:
        s.problem(s.at("hand_B"), 'missing: screw B\'s hand, write hand_B = "right" or "left"')
    elif not given_B and s.raw("hand_B") is not MISSING:
        s.problem(s.at("hand_B"), "screw B's hand goes with lead_B: with a travel asked for, both branches are found")
    s.finish()
    if p_A is None or hand_A is None or (travel is None and (p_B is None or hand_B is None)):
        return None
    if travel is not None and p_B is not None:
        return None
    return ScrewProblem(p_A, hand_A, travel, p_B, hand_B)


def parse_other_scene(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]
                      ) -> Scene[OtherScene]:
    """The rest of :func:`graphmech.scene.parse_scene` for a scene with [geneva] or [differential_screw]."""
    title, show, find = read_header(top, OTHER_SHOW_CHOICES, ())
    scales = read_scales(top)
    geneva = read_geneva(top)
    screw = read_screw(top)
    measured = read_measured(top, None, cam=True)
    precision, page = read_tail(top, ("geneva", "differential_screw"))
    section = "geneva" if "geneva" in data else "differential_screw"
    if top.problems or (geneva is None and screw is None):
        raise_sorted(top.problems, data, order, section, source)
    if not show:
        show = tuple(x for x, on in (("geneva", geneva), ("differential_screw", screw)) if on is not None)
    return Scene(source=source, title=title, show=show, find=find, scales=scales, measured=measured,
                 precision_mm=precision, page=page, kind="other", problem=OtherScene(geneva, screw))


__all__ = [
    "GENEVA_AT_ANGLE",
    "GENEVA_QUANTITIES",
    "OTHER_SHOW_CHOICES",
    "SCREW_QUANTITIES",
    "GenevaProblem",
    "OtherScene",
    "ScrewProblem",
    "parse_other_scene",
    "read_geneva",
    "read_screw",
]
