"""The cam profile by inversion (反转法), as the textbook draws it, and what is measured on it.

The cam stands still; the follower is turned the opposite way, division by division:

translating follower
    1. draw the base circle r0 and the offset circle e;
    2. divide the offset circle from the start at the cam angles δ_k, *against* the cam's
       rotation: the follower's axis at division k is the tangent there, K_k its foot;
    3. where that tangent meets the base circle is B0_k; lay off the displacement s_k from
       B0_k along it: B_k, a point of the pitch curve;
oscillating follower
    1. draw the base circle and the circle through the follower's pivot (radius |OA|);
    2. divide the pivot circle at −δ_k: the pivot's inverted positions A_k;
    3. from A_k lay off the rocker angle ψ0 ± φ_k from the line A_kO, arm length l: B_k.

The pitch curve is then drawn through the B_k. A roller's working profile is the inner
envelope of the roller circles (the pitch curve eroded by r_r — shapely's buffer, which is
what it is good at); a flat face's is the envelope of the face lines (consecutive lines
intersected). Pressure angle and radius of curvature are *read off the drawing*: the tangent
at B_k from the chord B_{k−1}B_{k+1}, the curvature from the circle through three points —
so they converge to the exact values as the divisions get finer (error ∝ 1/N²).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, cast

import numpy as np

from graphmech.construction import Construction
from graphmech.errors import NoSolution
from graphmech.geometry import kernels as K
from graphmech.mechanisms.cam import DiscCam, TranslatingFollower
from graphmech.mechanisms.motion import breakpoints, displacement, impacts

if TYPE_CHECKING:
    from graphmech.geometry.kernels import Components, Ops, Value

PANEL = "profile"


def whole_turn_step(step: float) -> float:
    """The step the divisions are drawn at: ``step`` rounded so that it divides a turn (7° → 7.0588°).

    >>> round(math.degrees(whole_turn_step(math.radians(7.0))), 4)
    7.0588
    """
    return math.tau / max(1, round(math.tau / step))


def divisions(cam: DiscCam, step: float, breakpoints: np.ndarray) -> np.ndarray:
    """The cam angles of the divisions: every ``step`` (rounded to divide a turn) from 0, plus the
    laws' joints (rad, sorted)."""
    n = round(math.tau / whole_turn_step(step))
    grid = np.arange(n) * (math.tau / n)
    allv = np.concatenate([grid, np.asarray(breakpoints, dtype=float) % math.tau])
    allv = np.unique(np.round(allv, 12))
    return allv[allv < math.tau - 1e-12]


def build_inversion(cam: DiscCam) -> Construction:
    """The step graph of one division: parameters ``delta`` (rad) and ``s`` (m or rad)."""
    g = Construction()
    g.param("delta")
    g.param("s")
    f = cam.follower
    rot = float(cam.rotation)
    r0 = cam.base_radius
    g.add("O", "point", lambda ops: (0.0, 0.0), (), role="given", text="cam centre O", panel=PANEL, label="O")
    if isinstance(f, TranslatingFollower):
        e = f.offset

        def foot(ops: Ops, delta: Value) -> Components:
            # K_k: the start foot (e, 0) turned by −rot·δ (the follower turns against the cam)
            c, sn = ops.cos(delta), ops.sin(delta)
            return (e * c + 0.0 * delta, -rot * e * sn)

        def axis(ops: Ops, k: Components, delta: Value) -> Components:
            c, sn = ops.cos(delta), ops.sin(delta)
            return (k[0], k[1], rot * sn, c)  # the start axis direction (0, 1) turned by −rot·δ

        g.add("K", "point", foot, ("delta",), text="K_k on the offset circle at −δ_k", panel=PANEL, label="K")
        g.add("axis", "line", axis, ("K", "delta"), text="the follower's axis: tangent to the offset circle at K_k",
              panel=PANEL)
        g.add("B0", "point",
              lambda ops, o, line: K.intersect_circle_line(ops, o, r0, line, 1.0, lambda _: "the axis misses the base circle"),
              ("O", "axis"), text="B0_k = axis ∩ base circle", panel=PANEL, label="B0")
        g.add("B", "point", lambda ops, b0, line, s: (b0[0] + s * line[2], b0[1] + s * line[3]),
              ("B0", "axis", "s"), role="result", text="lay off B0_kB_k = s_k along the axis", panel=PANEL, label="B")
    else:
        a, l = f.pivot_distance, f.arm
        if f.contact == "flat":
            # the face is the line through A along the rocker, tangent to the base circle at the
            # start: its distance a·sin ψ0 from O is r0 (the arm length is not used)
            psi0 = math.asin(r0 / a)
        else:
            psi0 = math.acos((a * a + l * l - r0 * r0) / (2.0 * a * l))
        # "opposite": during the rise the rocker turns against the cam — for a CCW cam the arm
        # starts turned ψ0 clockwise from A→O (B above OA) and turns further clockwise.
        turn = -rot if f.sense == "opposite" else rot

        def pivot(ops: Ops, delta: Value) -> Components:
            return (a * ops.cos(delta), -rot * a * ops.sin(delta))

        def rocker(ops: Ops, ap: Components, s: Value) -> Components:
            ux, uy = -ap[0] / a, -ap[1] / a  # A_k → O
            psi = turn * (psi0 + s)
            c, sn = ops.cos(psi), ops.sin(psi)
            return (c * ux - sn * uy, sn * ux + c * uy)  # A_k → O turned by ±(ψ0 + φ_k)

        g.add("A", "point", pivot, ("delta",), text="A_k on the pivot circle at −δ_k", panel=PANEL, label="A")
        if f.contact == "flat":
            g.add("face", "line", lambda ops, ap, s: (ap[0], ap[1], *rocker(ops, ap, s)), ("A", "s"),
                  text="the face: the line through A_k at ∠OA_k(face) = ψ0 ± φ_k, ψ0 = asin(r0/a)",
                  panel=PANEL)

            def face_foot(ops: Ops, line: Components) -> Components:
                t = -(line[0] * line[2] + line[1] * line[3])  # (O − A_k)·u
                return (line[0] + t * line[2], line[1] + t * line[3])

            g.add("B", "point", face_foot, ("face",), role="result",
                  text="B_k: the foot of the perpendicular from O on the face", panel=PANEL, label="B")
        else:
            def arm(ops: Ops, ap: Components, s: Value) -> Components:
                ux, uy = rocker(ops, ap, s)
                return (ap[0] + l * ux, ap[1] + l * uy)

            g.add("B", "point", arm, ("A", "s"), role="result",
                  text="lay off ∠OA_kB_k = ψ0 ± φ_k, A_kB_k = l", panel=PANEL, label="B")
    return g


@dataclass(frozen=True)
class DrawnProfile:
    """What the inversion drew, and what is read off it, at N divisions."""

    delta: np.ndarray  # (N,) rad
    pitch: np.ndarray  # (N,2) m
    axis_dir: np.ndarray  # (N,2) the follower's direction of motion at B_k (unit)
    actual: np.ndarray  # (M,2) the working profile as drawn (closed polyline), m
    pressure_angle: np.ndarray  # (N,) rad, read off the drawn pitch curve
    rho_pitch: np.ndarray  # (N,) m, signed (> 0 convex), circle through three points
    valid: np.ndarray  # (N,) bool


def draw_profile(cam: DiscCam, delta: np.ndarray, s: np.ndarray, plan: Any | None = None) -> DrawnProfile:
    """Carry out the inversion at the divisions ``delta`` with displacements ``s`` and read it off."""
    f = cam.follower
    if plan is None:
        keep = ["axis"] if isinstance(f, TranslatingFollower) else ["A"] + (["face"] if f.contact == "flat" else [])
        plan = build_inversion(cam).prune(["B"] + keep)
    sol = plan.evaluate_batch({"delta": delta, "s": s})
    bx, by = sol["B"]
    pitch = np.column_stack([np.broadcast_to(bx, delta.shape), np.broadcast_to(by, delta.shape)])
    if isinstance(f, TranslatingFollower):
        line = sol["axis"]
        axis_dir = np.column_stack([np.broadcast_to(line[2], delta.shape), np.broadcast_to(line[3], delta.shape)])
    elif f.contact == "flat":
        # the face's own direction u turned a quarter: the normal, the way the face moves
        line = sol["face"]
        turn = -cam.rotation if f.sense == "opposite" else cam.rotation
        axis_dir = turn * np.column_stack([-np.broadcast_to(line[3], delta.shape),
                                           np.broadcast_to(line[2], delta.shape)])
    else:
        ax, ay = sol["A"]
        arm = pitch - np.column_stack([ax, ay])
        # B moves ⟂ to the arm, in the sense the rocker turns as s grows
        turn = -cam.rotation if f.sense == "opposite" else cam.rotation
        axis_dir = turn * np.column_stack([-arm[:, 1], arm[:, 0]]) / np.hypot(arm[:, 0], arm[:, 1])[:, None]
    prev, nxt = np.roll(pitch, 1, axis=0), np.roll(pitch, -1, axis=0)
    chord = nxt - prev
    tangent = chord / np.hypot(chord[:, 0], chord[:, 1])[:, None]
    # pressure angle: between the follower's motion and the pitch curve's normal
    sin_a = np.abs(tangent[:, 0] * axis_dir[:, 1] - tangent[:, 1] * axis_dir[:, 0])
    cos_a = np.abs(tangent[:, 0] * axis_dir[:, 0] + tangent[:, 1] * axis_dir[:, 1])
    pressure = np.arctan2(cos_a, sin_a)
    rho = _three_point_radius(prev, pitch, nxt, cam.rotation)
    actual = _working_profile(cam, pitch, axis_dir)
    return DrawnProfile(delta, pitch, axis_dir, actual, pressure, rho, sol.valid)


def _three_point_radius(p: np.ndarray, q: np.ndarray, r: np.ndarray, rotation: int) -> np.ndarray:
    """Radius of the circle through three points, signed > 0 where the curve bends towards the cam
    (convex profile), for a curve traversed against the cam's rotation."""
    a = np.hypot(*(q - p).T)
    b = np.hypot(*(r - q).T)
    c = np.hypot(*(r - p).T)
    cross = (q - p)[:, 0] * (r - q)[:, 1] - (q - p)[:, 1] * (r - q)[:, 0]
    with np.errstate(divide="ignore", invalid="ignore"):
        rho = a * b * c / (2.0 * cross)
    rho = np.where(np.isfinite(rho), rho, 1e300)
    return -rotation * rho  # the inverted follower runs clockwise for a CCW cam


def _working_profile(cam: DiscCam, pitch: np.ndarray, axis_dir: np.ndarray) -> np.ndarray:
    f = cam.follower
    if f.contact == "knife":
        return pitch
    if f.contact == "roller":
        import shapely

        # the roller's arc round a corner is drawn as finely as the divisions (its chord error
        # would otherwise put a floor under the profile's convergence)
        eroded = shapely.Polygon(pitch).buffer(-f.roller_radius, quad_segs=max(32, math.ceil(len(pitch) / 4)))
        if eroded.is_empty:
            return np.zeros((0, 2))
        if eroded.geom_type == "MultiPolygon":
            eroded = max(eroded.geoms, key=lambda g: g.area)
        return np.asarray(eroded.exterior.coords)
    # flat face ⟂ the follower's motion (translating), or along the rocker through A_k (oscillating:
    # B_k is the foot of the perpendicular from O, axis_dir the face's normal): the envelope of the
    # face lines through B_k
    # face k: the line through B_k ⟂ d_k; the envelope's corners are faces k and k+1 intersected
    faces = (pitch[:, 0], pitch[:, 1], -axis_dir[:, 1], axis_dir[:, 0])
    ops = K.ArrayOps(len(pitch))
    ops.step = "face k ∩ face k+1"
    x, y = K.intersect_lines(ops, faces, tuple(np.roll(c, -1) for c in faces))
    return np.column_stack([x, y])[~ops.bad]  # parallel neighbours have no corner


# ------------------------------------------------------------------ reading the drawing

@dataclass(frozen=True)
class CamReading:
    """The inversion at N divisions and what is read off the drawing (all that ``seconds`` times)."""

    delta: np.ndarray
    drawn: DrawnProfile
    alpha_max: float  # rad, largest pressure angle read off the drawing
    alpha_max_at: float  # rad, the division where it is
    rho_min: float  # m: smallest convex ρ of the pitch curve (roller, knife) or of the profile (flat face)
    rho_min_at: float  # rad
    undercut: bool  # roller: r_r ≥ that ρ; flat face: the profile's ρ ≤ 0 somewhere


def near(delta: np.ndarray, angles: np.ndarray, tol: float) -> np.ndarray:
    """Which of the cam angles ``delta`` lie within ``tol`` (rad) of one of ``angles``, round the turn."""
    if angles.size == 0:
        return np.zeros(delta.shape, dtype=bool)
    d = np.abs((delta[:, None] - angles[None, :] + math.pi) % math.tau - math.pi)
    return cast(np.ndarray, (d <= tol).any(axis=1))


def rigid_corners(cam: DiscCam) -> np.ndarray:
    """Cam angles where the follower's velocity jumps: the pitch curve's corners (rad)."""
    return np.array(sorted({i.angle % math.tau for i in impacts(cam.program) if i.kind == "rigid"}))


def read_cam(cam: DiscCam, n: int) -> CamReading:
    """Draw the profile at ``n`` divisions and read off it what the textbook asks.

    The displacements at the divisions, the inversion (pitch points and the working profile), the
    largest pressure angle and where, the smallest convex radius of curvature of the pitch curve
    (three-point circles, the pitch curve's corners left out) and the undercut test r_r against
    it. A flat face ⟂ its axis has pressure angle 0 by construction (its normal is the axis); for
    it the radius of curvature is read off the drawn profile (three consecutive envelope points)
    and the undercut test is that radius ≤ 0.
    """
    delta = divisions(cam, math.tau / n, breakpoints(cam.program))
    return read_drawing(cam, draw_profile(cam, delta, displacement(cam.program, delta)))


def read_drawing(cam: DiscCam, drawn: DrawnProfile) -> CamReading:
    """What the textbook reads off a drawn profile (see :func:`read_cam`)."""
    delta = drawn.delta
    if not drawn.valid.all():
        raise NoSolution(f"the inversion is not drawable at {int(np.sum(~drawn.valid))} divisions")
    f = cam.follower
    if f.contact == "flat":
        act = drawn.actual
        rho = _three_point_radius(np.roll(act, 1, axis=0), act, np.roll(act, -1, axis=0), cam.rotation)
        k = int(np.argmin(rho))
        # envelope point k is where the faces at divisions k and k + 1 meet
        ahead = delta[k + 1] if k + 1 < len(delta) else delta[0] + math.tau
        return CamReading(delta, drawn, 0.0, float(delta[0]), float(rho[k]),
                          float(0.5 * (delta[k] + ahead) % math.tau), bool(rho[k] <= 0.0))
    k = int(np.argmax(drawn.pressure_angle))
    rho = drawn.rho_pitch
    ok = (rho > 0.0) & ~near(delta, rigid_corners(cam), 1e-9)
    j = int(np.flatnonzero(ok)[np.argmin(rho[ok])])
    r_r = f.roller_radius if f.contact == "roller" else 0.0
    return CamReading(delta, drawn, float(drawn.pressure_angle[k]), float(delta[k]), float(rho[j]),
                      float(delta[j]), bool(r_r > 0.0 and r_r >= rho[j]))
