"""Efficiency and self-locking by force polygons: the inclined plane, the screw, the wedge.

The textbook's method, step by step, in drawing millimetres at the force scale μF (N/mm):

1. the velocities: which way each body slides relative to the one it touches (for the wedge a
   small velocity triangle: v2 = v1 + v21, v2 ∥ guide 2, v21 ∥ the face);
2. the frictionless polygon (thin, dashed) — which side each contact bears on, and the ideal
   driving force F0;
3. each total reaction turned from its normal by the friction angle φ against the relative
   velocity ("R21 makes φ with the normal, on the side opposite to v12");
4. the polygon of each body: lay off the known forces head to tail, through the end draw a line
   ∥ the first unknown, through the start a line ∥ the second, intersect; the unknowns are read
   off as drawn lengths × μF.

η = ideal / actual driving force: forward (F drives) η = F0/F; reverse (the load Q drives and F
holds it back) η = F/F0; reverse η ≤ 0 is self-locking. The closed-form answers that check these
are in :mod:`graphmech.exact.efficiency`; nothing here is taken from there.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from collections.abc import Callable
from typing import Literal, Sequence

from graphmech.errors import DegenerateConstruction, OutOfDomain
from graphmech.geometry.kernels import ScalarOps, intersect_lines

XY = tuple[float, float]
Direction = Literal["forward", "reverse"]
#: An efficiency this close to 0 is the self-locking limit, reported as exactly 0.
ETA_ZERO = 1e-12
#: Where self-locking limits are looked for, rad: an incline (an unrolled thread) can be drawn at
#: any positive angle up to 89.999°; a wedge's face only while it still meets guide 2 (sin γ
#: well above PARALLEL_SIN), up to 90°.
INCLINE_LIMIT_RANGE = (1e-200, math.radians(89.999))
WEDGE_LIMIT_RANGE = (1e-12, math.pi / 2 - 1e-9)


@dataclass(frozen=True)
class DrawnForce:
    """One side of a force polygon: ``start`` → ``end`` in drawing mm; ``value`` N (> 0 along the
    force's drawn sense); ``name`` such as ``"R12"``."""

    name: str
    start: XY
    end: XY
    value: float


@dataclass(frozen=True)
class ForcePolygon:
    """The closed polygon of one body's forces (head to tail), at μF.

    ``cond`` is 1/|sin| of the angle at which the two unknown directions meet: large means the
    polygon closes at a shallow intersection (near-collinear forces) and its answers are
    ill-conditioned.
    """

    body: str
    forces: tuple[DrawnForce, ...]
    cond: float
    ideal: bool = False


@dataclass(frozen=True)
class Stroke:
    """One direction of motion solved: the polygons (ideal first, dashed), the forces, η.

    ``F`` is None when no finite force moves the forward stroke (the unknown lines are parallel:
    self-locked forward, η = 0).
    """

    direction: Direction
    polygons: tuple[ForcePolygon, ...]
    F: float | None
    F0: float
    eta: float
    reactions: tuple[tuple[str, float], ...]
    cond: float
    velocities: tuple[tuple[str, XY], ...] = ()


def _unit(x: float, y: float) -> XY:
    n = math.hypot(x, y)
    return (x / n, y / n)


def _dot(a: XY, b: XY) -> float:
    return a[0] * b[0] + a[1] * b[1]


def turned_by_friction(normal: XY, v_rel: XY, phi: float) -> XY:
    """The total reaction's direction: the normal turned by φ against the relative velocity.

    ``normal`` points into the body the reaction acts on; ``v_rel`` is that body's velocity
    relative to the other one (along the contact). Turning towards −v_rel by φ.

    >>> [round(c, 12) for c in turned_by_friction((0.0, 1.0), (1.0, 0.0), math.pi / 4)]
    [-0.707106781187, 0.707106781187]
    """
    t = _unit(*v_rel)
    c, s = math.cos(phi), math.sin(phi)
    return (normal[0] * c - t[0] * s, normal[1] * c - t[1] * s)


@dataclass(frozen=True)
class Unknown:
    """An unknown force of known direction: ``direction`` a unit vector (its drawn sense)."""

    name: str
    direction: XY


def close_polygon(body: str, start: XY, known: Sequence[DrawnForce | tuple[str, XY]], a: Unknown, b: Unknown,
                  mu_F: float, *, ideal: bool = False) -> ForcePolygon:
    """Lay off the known forces from ``start``, close with ``a`` then ``b``.

    Known forces are (name, vector in N) laid off head to tail at μF (or already drawn sides,
    reused as they are, e.g. R21 on the side R12 of the previous polygon). Through the last end
    a line ∥ a, through ``start`` a line ∥ b; their intersection X gives a = X − end and
    b = start − X. The values are the drawn lengths × μF, signed along the given directions.

    Raises
    ------
    DegenerateConstruction
        When a and b are parallel: the polygon cannot close (no finite force balances).
    """
    sides: list[DrawnForce] = []
    p = start
    for k in known:
        if isinstance(k, DrawnForce):
            sides.append(DrawnForce(k.name, k.start, k.end, k.value))
            p = k.end
            continue
        name, (fx, fy) = k
        q = (p[0] + fx / mu_F, p[1] + fy / mu_F)
        sides.append(DrawnForce(name, p, q, math.hypot(fx, fy)))
        p = q
    ops = ScalarOps()
    ops.step = f"{body}: through the end draw ∥ {a.name}, through the start ∥ {b.name}, intersect"
    x = intersect_lines(ops, (p[0], p[1], a.direction[0], a.direction[1]),
                        (start[0], start[1], b.direction[0], b.direction[1]))
    cond = float(ops.conds[ops.step])
    a_mm = _dot((x[0] - p[0], x[1] - p[1]), a.direction)
    b_mm = _dot((start[0] - x[0], start[1] - x[1]), b.direction)
    sides.append(DrawnForce(a.name, p, x, a_mm * mu_F))
    sides.append(DrawnForce(b.name, x, start, b_mm * mu_F))
    return ForcePolygon(body, tuple(sides), cond, ideal)


def _crossing(poly: ForcePolygon) -> float:
    """The sine of the angle from the first unknown side to the second (the last two drawn)."""
    a, b = poly.forces[-2], poly.forces[-1]
    ax, ay = a.end[0] - a.start[0], a.end[1] - a.start[1]
    bx, by = b.end[0] - b.start[0], b.end[1] - b.start[1]
    sa = math.copysign(1.0, a.value) if a.value else 1.0
    sb = math.copysign(1.0, b.value) if b.value else 1.0
    return (ax * by - ay * bx) * sa * sb  # the directions as given, whatever the signs came out


def _value(poly: ForcePolygon, name: str) -> float:
    return next(s.value for s in poly.forces if s.name == name)


def _eta(direction: Direction, F0: float, F: float | None) -> float:
    if F is None:
        return 0.0
    eta = F0 / F if direction == "forward" else F / F0
    return 0.0 if abs(eta) <= ETA_ZERO else eta


# ---------------------------------------------------------------------------- incline and screw


def _sense(direction: str) -> float:
    """+1 forward, −1 reverse; anything else is a caller's mistake, not a reverse stroke."""
    if direction not in ("forward", "reverse"):
        raise OutOfDomain(f"direction must be 'forward' or 'reverse', not {direction!r}")
    return 1.0 if direction == "forward" else -1.0


def incline(Q: float, alpha: float, phi: float, direction: Direction, mu_F: float,
            push: str = "horizontal", *, names: tuple[str, str] = ("F", "R")) -> Stroke:
    """A block of weight Q on an incline α; F horizontal (the unrolled screw) or ∥ the incline.

    Parameters
    ----------
    Q : float
        Weight, N (vertical, down).
    alpha, phi : float
        The incline's angle and the friction angle, rad.
    direction : {"forward", "reverse"}
        forward: F pushes the block up the incline; reverse: it slides down, F holds it.
    mu_F : float
        Force scale, N/mm.
    push : {"horizontal", "parallel"}
    names : (str, str)
        What to call the driving force and the reaction.

    Examples
    --------
    >>> s = incline(1000.0, math.radians(30), math.atan(0.1), "forward", 20.0)
    >>> round(s.F, 6), round(s.eta, 9)
    (718.853283, 0.803154528)
    """
    fname, rname = names
    up = (math.cos(alpha), math.sin(alpha))
    if push not in ("horizontal", "parallel"):
        raise OutOfDomain(f"push must be 'horizontal' or 'parallel', not {push!r}")
    v = up if _sense(direction) > 0 else (-up[0], -up[1])
    normal = (-math.sin(alpha), math.cos(alpha))  # the incline pushes the block up-and-out
    f_dir = (1.0, 0.0) if push == "horizontal" else up
    load = ("Q", (0.0, -Q))
    polys = []
    ideal = close_polygon("block", (0.0, 0.0), [load], Unknown(fname, f_dir), Unknown(rname, normal), mu_F,
                          ideal=True)
    F0 = _value(ideal, fname)
    polys.append(ideal)
    r_dir = turned_by_friction(normal, v, phi)
    try:
        real = close_polygon("block", (0.0, 0.0), [load], Unknown(fname, f_dir), Unknown(rname, r_dir), mu_F)
    except DegenerateConstruction:  # F ∥ R: no finite force moves it
        return Stroke(direction, tuple(polys), None, F0, 0.0, (), math.inf, (("v", v),))
    polys.append(real)
    F = _value(real, fname)
    return Stroke(direction, tuple(polys), F, F0, _eta(direction, F0, F), ((rname, _value(real, rname)),),
                  real.cond, (("v", v),))


# ---------------------------------------------------------------------------- the wedge


def wedge(Q: float, gamma: float, beta: float, phi: float, direction: Direction, mu_F: float) -> Stroke:
    """The wedge of problem F1430 (reconstructed): two sliders, three sliding faces.

    Slider 2 slides on a horizontal guide (frame 3) against the resistance Q (towards −x);
    the face between 1 and 2 is inclined at γ to that guide; slider 1 slides on a frame guide
    at β below the horizontal, on the other side of the face, pushed along it by F.

    The polygons: slider 2 (Q, R12, R32), then slider 1 (R21 = −R12 on the same side,
    F, R31) — drawn joined along R12, as the book does.

    Examples
    --------
    >>> s = wedge(1000.0, math.radians(60), math.radians(60), math.atan(0.15), "forward", 20.0)
    >>> round(s.F, 6), round(s.F0, 9)
    (1430.700422, 1000.0)
    """
    sense = _sense(direction)
    guide1 = (math.cos(beta), -math.sin(beta))  # slider 1 pushed down along −β (forward)
    guide2 = (1.0, 0.0)
    face = (math.cos(gamma), math.sin(gamma))
    # velocity triangle (unit v1): from p lay off v1; v2 ∥ guide 2 through p, v21 ∥ face through v1's end
    ops = ScalarOps()
    ops.step = "velocities: v2 = v1 + v21, v2 ∥ guide 2, v21 ∥ the face"
    v1 = (sense * guide1[0], sense * guide1[1])
    v2 = intersect_lines(ops, (0.0, 0.0, guide2[0], guide2[1]), (v1[0], v1[1], face[0], face[1]))
    v21 = (v2[0] - v1[0], v2[1] - v1[1])  # slider 2 relative to slider 1
    n12 = (math.sin(gamma), -math.cos(gamma))  # face normal into slider 2
    n32 = (0.0, 1.0)
    n31 = (math.sin(beta), math.cos(beta))  # guide 1's normal (up side)
    load = ("Q", (-Q, 0.0))

    def solve(fr: float, sides: tuple[float, float, float] | None, ideal: bool) -> tuple[ForcePolygon, ForcePolygon]:
        s12, s32, s31 = sides or (1.0, 1.0, 1.0)
        d12 = turned_by_friction((s12 * n12[0], s12 * n12[1]), v21, fr)
        d32 = turned_by_friction((s32 * n32[0], s32 * n32[1]), v2, fr)
        d31 = turned_by_friction((s31 * n31[0], s31 * n31[1]), v1, fr)
        p2 = close_polygon("slider 2", (0.0, 0.0), [load], Unknown("R32", d32), Unknown("R12", d12), mu_F, ideal=ideal)
        r12 = next(s for s in p2.forces if s.name == "R12")
        r21 = DrawnForce("R21", r12.end, r12.start, r12.value)
        p1 = close_polygon("slider 1", r12.end, [r21], Unknown("F", guide1), Unknown("R31", d31), mu_F, ideal=ideal)
        return p2, p1

    # frictionless: which side each contact bears on (the signs of the normal forces)
    q2, q1 = solve(0.0, None, True)
    s12, s32, s31 = (1.0 if _value(p, n) >= 0 else -1.0 for p, n in ((q2, "R12"), (q2, "R32"), (q1, "R31")))
    sides = (s12, s32, s31)
    F0 = _value(q1, "F")
    ideal_polys = (q2, q1) if sides == (1.0, 1.0, 1.0) else solve(0.0, sides, True)
    try:
        p2, p1 = solve(phi, sides, False)
    except DegenerateConstruction:
        return Stroke(direction, ideal_polys, None, F0, 0.0, (), math.inf, (("v1", v1), ("v2", v2)))
    # friction turning the two unknowns of a triangle past parallel is self-locking (F changes sign
    # through infinity: η ≤ 0), not a contact changing sides
    locked = any(_crossing(q) * _crossing(p) < 0 for q, p in ((ideal_polys[0], p2), (ideal_polys[1], p1)))
    for p, n in ((p2, "R12"), (p2, "R32"), (p1, "R31")):
        if _value(p, n) < 0 and not locked:
            raise DegenerateConstruction(
                f"{p.body}: {n}", "friction reverses the side this contact bears on (γ + β too close to 90° or "
                "γ too steep): the one-sided reconstruction does not apply")
    F = _value(p1, "F")
    reactions = tuple((n, abs(_value(p, n))) for p, n in ((p2, "R12"), (p2, "R32"), (p1, "R31")))
    return Stroke(direction, ideal_polys + (p2, p1), F, F0, _eta(direction, F0, F), reactions,
                  max(p2.cond, p1.cond), (("v1", v1), ("v2", v2)))


def wedge_locking_angle(beta: float, phi: float) -> float:
    """The face angle γ below which no finite F drives the wedge forward (η = 0), rad.

    Found on the construction: slider 2's polygon closes only while the total reactions R12 and
    R32 are not parallel; γ is turned until they are (bisection on the sine of the angle between
    them, each drawn from its normal turned by φ against the velocities of the triangle).
    The closed form, 2φ, is :mod:`graphmech.exact.efficiency`'s business.
    """
    n32 = (0.0, 1.0)

    def sine(gamma: float) -> float:
        ops = ScalarOps()
        guide1 = (math.cos(beta), -math.sin(beta))
        face = (math.cos(gamma), math.sin(gamma))
        v2 = intersect_lines(ops, (0.0, 0.0, 1.0, 0.0), (guide1[0], guide1[1], face[0], face[1]))
        v21 = (v2[0] - guide1[0], v2[1] - guide1[1])
        d12 = turned_by_friction((math.sin(gamma), -math.cos(gamma)), v21, phi)
        d32 = turned_by_friction(n32, v2, phi)
        return d12[0] * d32[1] - d12[1] * d32[0]

    return limiting_angle(sine, *WEDGE_LIMIT_RANGE)


# ---------------------------------------------------------------------------- the wedge clamp and the buffer


def wedge_clamp(Q: float, alpha: float, phi1: float, phi2: float, direction: Direction, mu_F: float) -> Stroke:
    """The welding clamp's wedge (000 效率 2): one body between two faces, each with its own
    friction angle (0: frictionless).

    Face 1 is horizontal below the wedge, which slides along it (+x forward: driven in) under F ∥
    face 1; face 2 above it meets face 1 at the wedge angle α ahead of the wedge, and the clamp's
    body presses on it with the clamping force Q (its total reaction R2). The polygon: lay off
    R2 = Q (the normal of face 2 turned by φ2 against the wedge's velocity along face 2), close
    with F and R1 (face 1's normal turned by φ1 against its velocity along face 1).

    Examples
    --------
    >>> s = wedge_clamp(1000.0, math.radians(20), math.atan(0.1), math.atan(0.1), "reverse", 10.0)
    >>> round(s.F, 6), round(s.F0, 6), round(s.eta, 9)
    (149.913714, 342.020143, 0.438318376)
    """
    sense = _sense(direction)
    v = (sense, 0.0)  # the wedge relative to face 1
    v2 = (sense * math.cos(alpha), -sense * math.sin(alpha))  # … and relative to face 2, along it
    n1 = (0.0, 1.0)
    n2 = (-math.sin(alpha), -math.cos(alpha))  # the body pushes the wedge down and back

    def solve(f1: float, f2: float, ideal: bool) -> ForcePolygon:
        d2 = turned_by_friction(n2, v2, f2)
        return close_polygon("wedge", (0.0, 0.0), [("Q", (Q * d2[0], Q * d2[1]))], Unknown("F", (1.0, 0.0)),
                             Unknown("R1", turned_by_friction(n1, v, f1)), mu_F, ideal=ideal)

    ideal = solve(0.0, 0.0, True)
    F0 = _value(ideal, "F")
    try:
        real = solve(phi1, phi2, False)
    except DegenerateConstruction:  # F ∥ R1: no finite force moves it
        return Stroke(direction, (ideal,), None, F0, 0.0, (), math.inf, (("v", v), ("v2", v2)))
    if _value(real, "R1") < 0.0:
        raise DegenerateConstruction("wedge: R1", "friction turns face 1's total reaction to pull (α ± φ2 beyond "
                                     "90°): the wedge lifts off face 1 and the clamp does not apply")
    F = _value(real, "F")
    return Stroke(direction, (ideal, real), F, F0, _eta(direction, F0, F), (("R_face1", _value(real, "R1")),),
                  real.cond, (("v", v), ("v2", v2)))


def buffer(Q: float, alpha: float, phi: float, direction: Direction, mu_F: float) -> Stroke:
    """The wedge buffer of 000 效率 3 (reconstructed: the guides frictionless, the face between the
    wedges with friction φ, as the book's single φ says).

    Wedge 1 slides down a vertical guide 3 (on its right) under P (named F); the face between it
    and wedge 2 descends to the right at α to the horizontal; wedge 2 slides left along the
    horizontal guide 4 against the spring Q. Velocities (forward): v1 = (0, −1), v2 = (−cot α, 0),
    v21 = v2 − v1 along the face. Polygons: wedge 2 (Q, R42, R12), then wedge 1 (R21 = −R12, F,
    R31), joined along R12.

    Examples
    --------
    >>> s = buffer(1000.0, math.radians(40), math.atan(0.15), "forward", 20.0)
    >>> round(s.F, 6), round(s.F0, 6)
    (1633.820269, 1191.753593)
    """
    sense = _sense(direction)
    v1 = (0.0, -sense)
    v2 = (-sense / math.tan(alpha), 0.0)
    v21 = (v2[0] - v1[0], v2[1] - v1[1])
    n12 = (-math.sin(alpha), -math.cos(alpha))  # into wedge 2 (below-left of the face)

    def solve(fr: float, ideal: bool) -> tuple[ForcePolygon, ForcePolygon]:
        d12 = turned_by_friction(n12, v21, fr)
        p2 = close_polygon("wedge 2", (0.0, 0.0), [("Q", (Q, 0.0))], Unknown("R42", (0.0, 1.0)),
                           Unknown("R12", d12), mu_F, ideal=ideal)
        r12 = next(s for s in p2.forces if s.name == "R12")
        r21 = DrawnForce("R21", r12.end, r12.start, r12.value)
        p1 = close_polygon("wedge 1", r12.end, [r21], Unknown("F", (0.0, -1.0)), Unknown("R31", (-1.0, 0.0)),
                           mu_F, ideal=ideal)
        return p2, p1

    q2, q1 = solve(0.0, True)
    F0 = _value(q1, "F")
    try:
        p2, p1 = solve(phi, False)
    except DegenerateConstruction:  # R12 ∥ guide 4's normal: no finite force moves it
        return Stroke(direction, (q2, q1), None, F0, 0.0, (), math.inf, (("v1", v1), ("v2", v2)))
    F = _value(p1, "F")
    reactions = tuple((n, abs(_value(p, n))) for p, n in ((p2, "R12"), (p2, "R42"), (p1, "R31")))
    return Stroke(direction, (q2, q1, p2, p1), F, F0, _eta(direction, F0, F), reactions, max(p2.cond, p1.cond),
                  (("v1", v1), ("v2", v2)))


# ---------------------------------------------------------------------------- limiting angles


def limiting_angle(eta_of: Callable[[float], float], lo: float, hi: float) -> float:
    """The angle in (lo, hi) where η(angle) changes sign, by bisection on the construction.

    The textbook gives the self-locking limit in closed form (α = φ for the incline, ψ = φv for
    a screw); here it is found as a draftsman would, by redrawing the polygon until η = 0 — down
    to adjacent floating-point angles, so the limit is exact but for round-off however small it
    is (a stop at an absolute 1e-15 rad left a limit of 1e-12 rad 1e-3 off). While the bracket
    spans more than a factor of 4 it is halved geometrically (a limit of 1e-14 rad in a range
    from 1e-200 rad to 90° takes ten steps to reach), then arithmetically.
    """
    f_lo = eta_of(lo)
    if (f_lo > 0) == (eta_of(hi) > 0):
        raise DegenerateConstruction("the self-locking limit", "η does not change sign between "
                                     f"{math.degrees(lo):.3g}° and {math.degrees(hi):.3g}°: the limit lies outside "
                                     "the angles the construction can draw")
    for _ in range(400):  # ≈ 10 geometric + 53 arithmetic steps reach adjacent floats
        mid = math.sqrt(lo) * math.sqrt(hi) if 0.0 < lo and 4.0 * lo < hi else lo + 0.5 * (hi - lo)
        if not lo < mid < hi:
            break
        f_mid = eta_of(mid)
        if (f_mid > 0) == (f_lo > 0) and f_mid != 0.0:
            lo, f_lo = mid, f_mid
        else:
            hi = mid
    return lo + 0.5 * (hi - lo)


# ---------------------------------------------------------------------------- chains of machines


@dataclass(frozen=True)
class StageResult:
    """A stage of a chain: its name, efficiency, power in and out (W)."""

    name: str
    eta: float
    power_in: float
    power_out: float


def chain(stages: Sequence[tuple[str, Sequence[tuple[float, Sequence[float]]]]], power_out: float) -> tuple[float, tuple[StageResult, ...]]:
    """Walk the chain from the output back to the motor, stage by stage.

    Each stage is (name, branches); a branch is (share of the stage's input power, the
    efficiencies of the machines in series in it). A stage of one branch is machines in series;
    several branches are machines in parallel (the stage's η = Σ share·Π η / Σ share).

    Returns
    -------
    (η overall, stages with their powers)
    """
    etas = []
    for name, branches in stages:
        total = sum(s for s, _ in branches)
        eta = 0.0
        for share, series in branches:
            prod = 1.0
            for e in series:
                prod *= e
            eta += share / total * prod
        etas.append((name, eta))
    results: list[StageResult] = []
    p = power_out
    for name, eta in reversed(etas):
        p_in = p / eta
        results.append(StageResult(name, eta, p_in, p))
        p = p_in
    results.reverse()
    return power_out / p, tuple(results)


__all__ = ["DrawnForce", "ForcePolygon", "Stroke", "StageResult", "Unknown", "buffer", "chain", "close_polygon", "incline",
           "limiting_angle", "turned_by_friction", "wedge", "wedge_clamp", "wedge_locking_angle", "ETA_ZERO",
           "INCLINE_LIMIT_RANGE", "WEDGE_LIMIT_RANGE"]
