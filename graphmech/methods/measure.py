"""Measuring the drawing: each quantity is a step returning ``(drawn_mm, scale)``.

The length is taken from the exact construction (floats, not rounded SVG coordinates) and
signed where the quantity has a sense: ω and α counter-clockwise positive (the sense in which
the relative vector turns about its base point), a slider's velocity along its guide.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from graphmech.geometry.kernels import cross
from graphmech.geometry.primitives import degrees_0_360
from graphmech.methods.elements import direction
from graphmech.methods.linkage_construction import ACCELERATION_POLE, VELOCITY_POLE
from graphmech.methods.quantities import Quantity

if TYPE_CHECKING:
    from graphmech.geometry.kernels import Components, Ops
    from graphmech.methods.linkage_construction import LinkageConstruction
    from graphmech.methods.quantities import Exact


def _add(b: "LinkageConstruction", name: str, unit: str, kernel: Callable[..., Components], inputs: tuple[str, ...],
         exact: Exact, panel: str, segment: tuple[str, ...] = ()) -> str:
    slot = f"m:{name}"
    if not b.g.has(slot):
        b.g.add(slot, "scalar", kernel, inputs, role="hidden", text=f"measure {name}", panel=panel,
                say=("measure", name))
        b.quantity(Quantity(name, unit, slot, exact, panel, segment))
    return slot


def _label(b: "LinkageConstruction", slot: str) -> str:
    return b.g.steps[slot].label or ""


def _segment(start: str, end: str, scale: float, name: str, b: "LinkageConstruction",
             unit: str, exact: Exact, panel: str) -> str:
    """A plain drawn length |start end| × scale."""

    def kern(ops: Ops, s: Components, e: Components) -> Components:
        return (ops.hypot(e[0] - s[0], e[1] - s[1]), scale)

    return _add(b, name, unit, kern, (start, end), exact, panel, (_label(b, start), _label(b, end)))


# ----------------------------------------------------------------------- angular rates


def omega(b: "LinkageConstruction", link: str, U: str, V: str) -> None:
    """ω of a link read off the polygon: ω = (UV × uv)/|UV|² · μv/μl (sense: uv turned about u)."""
    mv, ml = b.scales["v"], b.mu_l

    def kern(ops: Ops, d: Components, iu: Components, iv: Components) -> Components:
        return (cross(d[0], d[1], iv[0] - iu[0], iv[1] - iu[1]), mv / (d[2] * ml))

    b.omega[link] = _add(b, f"omega_{link}", "rad/s", kern, (direction(b, U, V), b.vel[U], b.vel[V]),
                         ("omega", link), "velocity", (_label(b, b.vel[U]), _label(b, b.vel[V])))


def alpha(b: "LinkageConstruction", link: str, U: str, V: str, n: str, end: str) -> None:
    """α of a link from its tangential component n→end: α = (UV × a^t)/|UV|² · μa/μl."""
    ma, ml = b.scales["a"], b.mu_l

    def kern(ops: Ops, d: Components, s: Components, e: Components) -> Components:
        return (cross(d[0], d[1], e[0] - s[0], e[1] - s[1]), ma / (d[2] * ml))

    b.alpha[link] = _add(b, f"alpha_{link}", "rad/s²", kern, (direction(b, U, V), n, end),
                         ("alpha", link), "acceleration", (_label(b, n), _label(b, end)))


def zero_rate(b: "LinkageConstruction", link: str) -> None:
    """A translating link: ω = α = 0 exactly."""
    zero = lambda ops: (0.0, 1.0)  # noqa: E731
    b.omega[link] = _add(b, f"omega_{link}", "rad/s", zero, (), ("omega", link), "velocity")
    b.alpha[link] = _add(b, f"alpha_{link}", "rad/s²", zero, (), ("alpha", link), "acceleration")


def same_rate(b: "LinkageConstruction", link: str, other: str) -> None:
    """A block sliding on a bar turns with it."""
    b.omega[link] = b.omega[other]
    q = b.quantities[f"omega_{other}"]
    b.quantity(Quantity(f"omega_{link}", q.unit, q.slot, ("omega", link), q.panel, q.segment))


# ----------------------------------------------------------------------- point quantities


def _speed(b: "LinkageConstruction", x: str, img: str, pole: str, scale: float, prefix: str,
           unit: str, panel: str) -> None:
    g = b.slider_dir.get(x)
    if g is None:
        _segment(pole, img, scale, f"{prefix}_{x}", b, unit, ("speed" if prefix == "v" else "acc", x), panel)
        return
    gx, gy = g

    def kern(ops: Ops, p: Components, e: Components) -> Components:
        return ((e[0] - p[0]) * gx + (e[1] - p[1]) * gy, scale)

    kind = "slide_v" if prefix == "v" else "slide_a"
    _add(b, f"{prefix}_{x}", unit, kern, (pole, img), (kind, x, gx, gy), panel,
         (_label(b, pole), _label(b, img)))


def point_speed(b: "LinkageConstruction", x: str) -> None:
    _speed(b, x, b.vel[x], VELOCITY_POLE, b.scales["v"], "v", "m/s", "velocity")


def point_acceleration(b: "LinkageConstruction", x: str) -> None:
    _speed(b, x, b.acc[x], ACCELERATION_POLE, b.scales["a"], "a", "m/s²", "acceleration")


def relative(b: "LinkageConstruction", x: str, y: str) -> None:
    """v_XY = |yx|·μv and a_XY = |y′x′|·μa (velocity/acceleration of X relative to Y)."""
    if x in b.vel and y in b.vel:
        _segment(b.vel[y], b.vel[x], b.scales["v"], f"v_{x}{y}", b, "m/s", ("rel_v", x, y), "velocity")
    if x in b.acc and y in b.acc:
        _segment(b.acc[y], b.acc[x], b.scales["a"], f"a_{x}{y}", b, "m/s²", ("rel_a", x, y),
                 "acceleration")


def length(b: "LinkageConstruction", x: str, y: str) -> None:
    """l_XY measured on the kinematic diagram."""
    _segment(b.mech[x], b.mech[y], b.mu_l, f"l_{x}{y}", b, "m", ("length", x, y), "mechanism")


def link_angle(b: "LinkageConstruction", link: str, line: tuple[str, str] | None = None) -> None:
    """θ of a rotating link: direction of its first two points, degrees in [0, 360); ``line``: two
    steps of the diagram along the link's own line instead (an offset guide bar's F→X)."""
    pts = b.link_points.get(link, [])
    if link in b.translating or (line is None and len(pts) < 2):
        return
    ends = line if line is not None else (b.mech[pts[0]], b.mech[pts[1]])

    def kern(ops: Ops, u: Components, v: Components) -> Components:
        if ops.batch:  # degrees_0_360 for arrays
            import numpy as np

            d = np.degrees(np.arctan2(v[1] - u[1], v[0] - u[0])) % 360.0
            return (np.where(d == 360.0, 0.0, d), 1.0)
        return (degrees_0_360(math.atan2(v[1] - u[1], v[0] - u[0])), 1.0)

    _add(b, f"theta_{link}", "deg", kern, ends, ("angle", link), "mechanism")


def component(b: "LinkageConstruction", name: str, start: str, end: str, exact: Exact) -> None:
    """A laid-off or found component (normal, tangential, Coriolis, relative) in the acceleration polygon."""
    _segment(start, end, b.scales["a"], name, b, "m/s²", exact, "acceleration")


# ----------------------------------------------------------------------- directions and angles


def _degrees(ops: Ops, dy: Any, dx: Any) -> Any:
    """atan2 in degrees, [0, 360), for a scalar or a batch of positions."""
    if ops.batch:
        import numpy as np

        d = np.degrees(np.arctan2(dy, dx)) % 360.0
        return np.where(d == 360.0, 0.0, d)
    return degrees_0_360(math.atan2(float(dy), float(dx)))


def _line_angle(ops: Ops, ux: Any, uy: Any, vx: Any, vy: Any) -> Any:
    """The acute angle between two lines (directions u, v), degrees in [0, 90]: atan2(|u×v|, |u·v|)."""
    c = ops.absolute(cross(ux, uy, vx, vy))
    d = ops.absolute(ux * vx + uy * vy)
    if ops.batch:
        import numpy as np

        return np.degrees(np.arctan2(c, d))
    return math.degrees(math.atan2(float(c), float(d)))


def direction_of(b: "LinkageConstruction", x: str) -> None:
    """dir_v_X, dir_a_X: the direction of X's velocity (acceleration), read with a protractor on
    the polygon's pole→image vector, degrees counter-clockwise from +x in [0, 360)."""
    for prefix, table, pole, panel in (("v", b.vel, VELOCITY_POLE, "velocity"),
                                       ("a", b.acc, ACCELERATION_POLE, "acceleration")):
        if x not in table:
            continue

        def kern(ops: Ops, p: Components, e: Components) -> Components:
            return (_degrees(ops, e[1] - p[1], e[0] - p[0]), 1.0)

        # no segment: "pc" read off the polygon stays v_C's
        _add(b, f"dir_{prefix}_{x}", "deg", kern, (pole, table[x]), (f"dir_{prefix}", x), panel)


def transmission(b: "LinkageConstruction", joint: str, pusher: str, along: str | tuple[float, float],
                 exact: Exact, rocker: bool) -> None:
    """γ_X and α_X at a dyad's output joint X, measured on the kinematic diagram.

    ``rocker``: the coupler X–``pusher`` pushes along its line, X turns about the rocker's pivot
    ``along`` (a point): γ is the acute angle between coupler and rocker. Otherwise ``along`` is
    the line X moves along or is pushed across — a slider's guide (a fixed direction) or a guide
    bar's line (a direction step, X–``pusher`` then the arm to the bar's pivot) — and γ is 90° less
    the acute angle between that line and X–``pusher``. The pressure angle is α = 90° − γ, the
    angle between the push and the velocity of X.
    """
    fixed: tuple[float, float] | None = None
    extra: tuple[str, ...]
    if isinstance(along, tuple):
        fixed, extra = along, ()
    else:
        extra = (b.mech[along] if rocker else along,)
    inputs = (b.mech[joint], b.mech[pusher], *extra)

    def gamma(ops: Ops, x: Components, p: Components, *o: Components) -> Any:
        ux, uy = p[0] - x[0], p[1] - x[1]
        if rocker:
            return _line_angle(ops, ux, uy, o[0][0] - x[0], o[0][1] - x[1])
        gx, gy = fixed if fixed is not None else (o[0][0], o[0][1])
        return 90.0 - _line_angle(ops, ux, uy, gx, gy)

    def kern_g(ops: Ops, *c: Components) -> Components:
        return (gamma(ops, *c), 1.0)

    def kern_a(ops: Ops, *c: Components) -> Components:
        return (90.0 - gamma(ops, *c), 1.0)

    _add(b, f"gamma_{joint}", "deg", kern_g, inputs, ("gamma", *exact), "mechanism")
    _add(b, f"pressure_angle_{joint}", "deg", kern_a, inputs, ("pressure", *exact), "mechanism")
