"""The senses of rotation in a spatial gear train, read from the arrows as the book does.

Each member's axis is one of the drawing's directions ``"+x"`` (to the right), ``"-x"``, ``"+y"``
(up), ``"-y"``, ``"+z"`` (toward the viewer), ``"-z"``; its speed is signed along that axis by the
right-hand rule. A mesh's sense — the sign of ω_a/ω_b — is then:

* parallel axes (external, internal): from the kind (external −1, internal +1), times û_a·û_b
  when one axis is drawn reversed;
* a bevel pair: the pitch points' velocities agree, ω_a·û_a × t_a = ω_b·û_b × t_b with t the
  directions from each axis to the pitch point, so sign(ω_a/ω_b) = sign((û_a × t_a)·(û_b × t_b));
* a worm ``a`` and its wheel ``b``: the wheel's pitch point moves against the thumb of the worm's
  hand (fingers along the worm's rotation), v_b = −h·ω_a·û_a (h = +1 right hand, −1 left), so
  sign(ω_a/ω_b) = sign((−h·û_a)·(û_b × t_b)).

Arrows that cannot be drawn — a ``towards`` along the member's own axis, pitch-point velocities
that are not along one line — are refused in words. :func:`arrow` is the arrow a drawing puts on
a member for the sense of its speed.
"""
from __future__ import annotations

from graphmech.errors import OutOfDomain
from graphmech.mechanisms.gear_train import AXES, HANDS, PARALLEL_SIGN

Vec = tuple[int, int, int]


def direction(name: str) -> Vec:
    if name not in AXES:
        raise OutOfDomain(f"{name!r} is not a direction: use {', '.join(AXES)}")
    return AXES[name]


def cross(u: Vec, v: Vec) -> Vec:
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def dot(u: Vec, v: Vec) -> int:
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def _pitch_velocity(axis: str, towards: str, who: str) -> Vec:
    """û × t: the direction the pitch point of a positive speed moves; refused along the axis."""
    v = cross(direction(axis), direction(towards))
    if v == (0, 0, 0):
        raise OutOfDomain(f'"{towards}" is along {who}\'s axis, not towards its pitch point')
    return v


def parallel_sign(kind: str, axis_a: str, axis_b: str, a: str = "a", b: str = "b") -> int:
    """ω_a/ω_b's sign for an external (−1) or internal (+1) mesh, the axes drawn ±parallel."""
    ua, ub = direction(axis_a), direction(axis_b)
    d = dot(ua, ub)
    if d == 0:
        raise OutOfDomain(f"an {kind} mesh needs parallel axes: {a} is along {axis_a}, {b} along {axis_b} "
                          "(a bevel pair: kind = \"bevel\")")
    return PARALLEL_SIGN[kind] * d


def bevel_sign(axis_a: str, axis_b: str, towards: tuple[str, str], a: str = "a", b: str = "b") -> int:
    """ω_a/ω_b's sign for a bevel pair: the pitch points' velocities agree."""
    va = _pitch_velocity(axis_a, towards[0], f"gear {a}")
    vb = _pitch_velocity(axis_b, towards[1], f"gear {b}")
    if cross(va, vb) != (0, 0, 0):
        raise OutOfDomain(f"the pitch points do not meet: from {towards[0]} of {a}'s axis and {towards[1]} of "
                          f"{b}'s axis they move across each other")
    if cross(direction(axis_a), direction(axis_b)) == (0, 0, 0):
        raise OutOfDomain(f"a bevel pair's axes meet at an angle: {a} ({axis_a}) and {b} ({axis_b}) are parallel "
                          "(an external or internal mesh)")
    return 1 if dot(va, vb) > 0 else -1


def worm_sign(axis_worm: str, axis_wheel: str, towards: tuple[str, str], hand: str,
              a: str = "a", b: str = "b") -> int:
    """ω_worm/ω_wheel's sign: the wheel's pitch point moves against the thumb of the worm's hand."""
    if hand not in HANDS:
        raise OutOfDomain(f"a worm's hand is \"right\" or \"left\", not {hand!r}")
    uw = direction(axis_worm)
    _pitch_velocity(axis_worm, towards[0], f"worm {a}")
    vb = _pitch_velocity(axis_wheel, towards[1], f"wheel {b}")
    along = -HANDS[hand]
    d = dot(uw, vb)
    if d == 0:
        raise OutOfDomain(f"the pitch points do not meet: wheel {b}'s pitch point (from {towards[1]} of its axis) "
                          f"moves across worm {a}'s axis, not along it")
    if direction(towards[0]) != tuple(-x for x in direction(towards[1])):  # on the axes' common perpendicular
        raise OutOfDomain(f"the pitch point lies between the axes: from wheel {b}'s axis toward {towards[1]}, so from "
                          f"worm {a}'s toward the opposite, not {towards[0]}")
    return 1 if along * d > 0 else -1


def arrow(axis: str, omega: float) -> str:
    """The arrow a drawing puts on a member turning at ω about ``axis``: the direction its near
    side moves (an axis in the drawing's plane: the side toward the viewer, ``"+y"``/``"-y"`` …),
    or ``"ccw"``/``"cw"`` for an axis toward or away from the viewer; ``""`` at rest.

    >>> arrow("+x", 2.0), arrow("+x", -2.0), arrow("+z", 1.0), arrow("-y", 1.0)
    ('-y', '+y', 'ccw', '-x')
    """
    if omega == 0.0:
        return ""
    u = direction(axis)
    s = 1 if omega > 0 else -1
    if u[2] != 0:
        return "ccw" if s * u[2] > 0 else "cw"
    v = cross(u, (0, 0, 1))  # the near side (toward the viewer) of a positive speed moves along û × ẑ
    v = (s * v[0], s * v[1], s * v[2])
    return next(name for name, d in AXES.items() if d == v)


__all__ = ["arrow", "bevel_sign", "parallel_sign", "worm_sign"]
