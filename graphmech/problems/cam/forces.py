"""The forces on a cam mechanism with friction (``[cam.forces]``): the follower's force polygon.

At a position δ of the rise, the load Q down the follower's axis, the cam's total reaction R12 at
the contact K (leant from the common normal by the friction angle φ) and the guide's two total
reactions at its ends B1, B2 (leant from the normal to the guide by φ′ = atan f) hold the follower
in equilibrium. Their lines are all known and their magnitudes not: Culmann's construction — Q and
R12 meet at P, the two guide reactions at S, and Q + R12 balances their resultant along PS — gives
the force polygon: Q laid off at μF, R12 and the resultant from its ends, the resultant split along
the two guide reactions (two parallel guide reactions are split by the lever rule instead). The
cam's driving moment is R12's moment about O, its lever read off the position. The exact side,
:mod:`graphmech.exact.cam_forces`, solves the three equilibrium equations as a linear system.
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphmech.drawing.lettering import scale_text
from graphmech.drawing.primitives import (ArcArrow, Arrow, Circle, FixedPivot, GuideLine, Hinge, Label, Panel,
                                         Polyline, Primitive, Segment, angle_mark)
from graphmech.errors import NoSolution
from graphmech.exact.cam_forces import CamForces, CamFriction, CamPosition, solve
from graphmech.geometry import kernels as K
from graphmech.mechanisms.cam import DiscCam
from graphmech.problems.judging import Row
from graphmech.problems.reader import MISSING, Reader
from graphmech.scales import round_scale

#: What a scene with [cam.forces] can ask for, with its unit.
CAM_FORCE_QUANTITIES = {"R_K": "N", "R_B1": "N", "R_B2": "N", "M_1": "N·m"}
#: The force polygon's load Q is drawn about this long when μF is chosen, mm.
LOAD_MM = 60.0
#: The free-body sketch: each force's arrow, the common normal's and the guide normals' run past
#: their points, the radius of the φ arcs, the stem above B2, the guide's half gap, a point's dot (mm);
#: Culmann's S is drawn up to SKETCH_REACH times the guide's top from O.
FORCE_MM, NORMAL_PAST, PHI_ARC, SKETCH_STEM, GUIDE_GAP, DOT = 18.0, 10.0, 9.0, 6.0, 1.5, 0.3
SKETCH_REACH = 4.0
#: R12's arrow in the sketch, shorter than the others: it stands inside the cam, mm.
R12_MM = 12.0
#: The sketch is drawn at the profile's μl, or coarser to stand about this tall, mm.
SKETCH_HEIGHT = 80.0


def read_forces(r: Reader) -> CamFriction | None:
    """[cam.forces]: at (an angle on the rise), load (a force), friction_angle, guide_friction (f ≥ 0),
    guide_length, overhang (lengths); None when absent or wrong (said)."""
    t = r.table_at("forces")
    if t is None:
        return None
    before = len(t.problems)
    at = t.value("at", "angle")
    load = t.value("load", "force", positive=True)
    phi = t.value("friction_angle", "angle")
    if phi is not None and not 0.0 <= phi.si < math.pi / 2:
        t.problem(phi.path, f"must lie between 0 and 90°, not {phi.text()}")
    f_raw = t.raw("guide_friction", required=True, hint="guide_friction = 0.1 (the guide's coefficient f)")
    f = None if f_raw is MISSING else t.number(f_raw, t.at("guide_friction"))
    if f is not None and not 0.0 <= f < 10.0:
        t.problem(t.at("guide_friction"), f"must lie between 0 and 10, not {f:g}")
    b = t.value("guide_length", "length", positive=True)
    ell = t.value("overhang", "length", positive=True)
    t.finish()
    if len(t.problems) != before or None in (at, load, phi, f, b, ell):
        return None
    assert at is not None and load is not None and phi is not None and f is not None and b is not None and ell is not None
    return CamFriction(at.si, load.si, phi.si, float(f), b.si, ell.si)


def _line(p: np.ndarray, d: np.ndarray) -> tuple[float, float, float, float]:
    u = d / np.hypot(*d)
    return (float(p[0]), float(p[1]), float(u[0]), float(u[1]))


def _meet(l1: tuple[float, float, float, float], l2: tuple[float, float, float, float]) -> np.ndarray:
    ops = K.ScalarOps()
    ops.step = "force polygon"
    x, y = K.intersect_lines(ops, l1, l2)
    return np.array([float(x), float(y)])


def force_polygon(cam: DiscCam, data: CamFriction, mu: float) -> dict[str, Any]:
    """Culmann's construction and the force polygon at μF (N/mm): the polygon's corners a0 … a3 (mm)
    — a0→a1 Q, a1→a2 R12, a2→a3 R_B1, a3→a0 R_B2 — and the guide reactions' directions, as
    drawn; Culmann's points P and S (m, machine frame; S None when the guide reactions are
    parallel), the guide reactions' directions e1, e2 and the resultant's c. The guide friction's
    sense comes from the exact solution's signs of N1, N2 (which end bears on which side is read
    off the sketch of the follower tilting in its guide)."""
    ex = solve(cam, data)
    p: CamPosition = ex.position
    s1, s2 = math.copysign(1.0, ex.N1), math.copysign(1.0, ex.N2)
    e1, e2 = np.array([s1, -data.f]), np.array([s2, -data.f])
    axis = np.array([0.0, 1.0])
    P = _meet(_line(p.B, axis), _line(p.K, p.d))  # Q's line (the axis) and R12's
    crossing = abs(float(e1[0] * e2[1] - e1[1] * e2[0])) > 1e-9  # no guide friction, or one sense: parallel
    S: np.ndarray | None = None
    if crossing:
        S = _meet(_line(p.B1, e1), _line(p.B2, e2))
        c = S - P
    else:  # parallel guide reactions: their resultant is parallel to them, through P
        c = e1
    a0 = np.zeros(2)
    a1 = a0 + np.array([0.0, -data.load / mu])
    a2 = _meet(_line(a1, p.d), _line(a0, c))
    if crossing:
        a3 = _meet(_line(a2, e1), _line(a0, e2))
    else:  # the lever rule on the axis: C crosses it at y_C; N1 : N2 = (y2 − y_C) : (y_C − y1)
        yc = float(_meet(_line(P, c), _line(p.B, axis))[1])
        w1 = (float(p.B2[1]) - yc) / (float(p.B2[1]) - float(p.B1[1]))
        a3 = a2 + w1 * (a0 - a2)
    return {"a": (a0, a1, a2, a3), "exact": ex, "P": P, "S": S, "e": (e1, e2), "c": c}


def choose_force_scale(data: CamFriction) -> float:
    """μF that draws the load about LOAD_MM long, N/mm."""
    return round_scale(data.load / LOAD_MM)


def force_rows(cam: DiscCam, data: CamFriction, mu: float, names: list[str]) -> dict[str, Row]:
    """The rows asked for: each reaction's length off the polygon at μF, and the cam's moment with
    R12 as drawn and its lever about O, against the linear system's."""
    poly = force_polygon(cam, data, mu)
    a0, a1, a2, a3 = poly["a"]
    ex: CamForces = poly["exact"]
    drawn = {"R_K": float(np.hypot(*(a2 - a1))), "R_B1": float(np.hypot(*(a3 - a2))),
             "R_B2": float(np.hypot(*(a0 - a3)))}
    exact = {"R_K": ex.R, "R_B1": float(np.hypot(*ex.R_B1)), "R_B2": float(np.hypot(*ex.R_B2))}
    out: dict[str, Row] = {}
    for name in names:
        if name == "M_1":
            K_ = ex.position.K
            force = drawn["R_K"] * mu * ex.position.d
            g = cam.rotation * float(K_[0] * force[1] - K_[1] * force[0])
            out[name] = Row(name, "N·m", None, 1.0, g, ex.M1, abs(g - ex.M1) / max(abs(ex.M1), 1e-300))
        else:
            g = drawn[name] * mu
            out[name] = Row(name, "N", drawn[name], mu, g, exact[name], abs(g - exact[name]) / data.load)
    return out


def forces_panel(cam: DiscCam, data: CamFriction, mu: float, notation: str = "en") -> Panel:
    """The follower's force polygon at μF: Q, R12, R32′ (at B1) and R32″ (at B2), head to tail."""
    a0, a1, a2, a3 = force_polygon(cam, data, mu)["a"]
    items: list[Primitive] = []
    for (p, q), name in zip(((a0, a1), (a1, a2), (a2, a3), (a3, a0)), ("Q", "R_{12}", "R′_{32}", "R″_{32}")):
        if np.hypot(*(q - p)) > 1e-9:
            items.append(Arrow((float(p[0]), float(p[1])), (float(q[0]), float(q[1])), "result"))
            mid = (p + q) / 2.0
            items.append(Label(name, (float(mid[0]), float(mid[1])), ()))
    items.append(Segment((float(a0[0]), float(a0[1])), (float(a2[0]), float(a2[1])), "construction"))  # Culmann's resultant
    title = {"zh": "从动件的力多边形（计摩擦）", "ru": "многоугольник сил толкателя (с трением)"}.get(
        notation, "Force polygon of the follower, with friction")
    note = f"δ = {math.degrees(data.at):.6g}°, φ = {math.degrees(data.phi):.6g}°, f = {data.f:g}"
    return Panel("forces", title, tuple(items), (scale_text("F", mu), note), scales=(("F", mu),))


def _xy(p: np.ndarray, mu: float = 1.0) -> tuple[float, float]:
    return (float(p[0]) / mu, float(p[1]) / mu)


def sketch_items(cam: DiscCam, data: CamFriction, drawn: Any, mu_l: float) -> list[Primitive]:
    """The follower's free body as the book sketches it (000 力 3), at μl in the machine frame (O at
    the origin, the follower's axis upright): the cam turned to δ (the working profile drawn by the
    inversion, turned), ω, the roller and stem in the guide with its bearing points B1, B2, the
    contact K with the common normal n–n, R12 leant from n by φ, Q down the axis, the guide's
    reactions R′32, R″32 leant from the guide's normal by φ′ = atan f, and Culmann's lines: Q and
    R12 meet at P, the two guide reactions at S, and P–S carries their resultant. S further off than
    SKETCH_REACH times the guide's top from O is left off (f near 0): the reactions' lines stop there."""
    from graphmech.problems.cam.figures import smooth_drawing

    poly = force_polygon(cam, data, mu_l)
    ex: CamForces = poly["exact"]
    p = ex.position
    e1, e2 = (e / np.hypot(*e) for e in poly["e"])
    turn = cam.rotation * (data.at % math.tau)
    rot = np.array([[math.cos(turn), -math.sin(turn)], [math.sin(turn), math.cos(turn)]])
    fine = smooth_drawing(cam, drawn, mu_l)
    prof = np.asarray(fine.actual, dtype=float)
    prof = prof[np.isfinite(prof).all(axis=1)] @ rot.T / mu_l  # the cam turned by δ: the machine frame
    B, Kc, B1, B2 = (_xy(q, mu_l) for q in (p.B, p.K, p.B1, p.B2))
    n, d = _xy(p.n), _xy(p.d)
    rr = cam.follower.roller_radius / mu_l
    top = B2[1] + SKETCH_STEM
    items: list[Primitive] = []
    labels: list[Primitive] = []
    # the cam at δ, its centre and sense of rotation
    if len(prof) >= 3:
        items.append(Polyline(tuple(map(tuple, prof)), "result", closed=True))
    r_arc = min(12.0, max(5.0, 0.45 * cam.base_radius / mu_l))
    sweep = (1.0 if cam.rotation >= 0 else -1.0) * math.radians(80.0)
    arc = ArcArrow((0.0, 0.0), r_arc, -math.pi / 2 - sweep / 2, sweep, "given")
    items += [arc, FixedPivot((0.0, 0.0))]
    labels += [Label("O", (0.0, 0.0), ((0.0, -1.0), (1.0, 0.0), (-1.0, 0.0), (0.0, 1.0))),
               Label("ω", arc.points(2)[1], ((1.0, 0.0), (-1.0, 0.0), (0.0, -1.0)))]
    # the follower: roller, stem, and the guide either side of the stem from B1 to B2 (hatched outside)
    items += [Circle(B, rr, "given"), Hinge(B, min(1.0, 0.3 * rr)), Segment(B, (B[0], top), "given")]
    for side in (1.0, -1.0):
        x = B[0] + side * GUIDE_GAP
        lo, hi = (x, B1[1]), (x, B2[1])
        items.append(GuideLine(lo, hi) if side > 0 else GuideLine(hi, lo))
    # the common normal n–n through K (and B), R12 along it leant by φ, and its line on to P
    P, S = _xy(poly["P"], mu_l), (None if poly["S"] is None else _xy(poly["S"], mu_l))
    n0, n1 = (Kc[0] - (R12_MM + NORMAL_PAST / 2) * n[0], Kc[1] - (R12_MM + NORMAL_PAST / 2) * n[1]), \
        (B[0] + (rr + NORMAL_PAST / 2) * n[0], B[1] + (rr + NORMAL_PAST / 2) * n[1])
    items.append(Segment(n0, n1, "construction", dashdot=True))
    labels += [Label("n", n0, ((n[0], n[1]),)), Label("n", n1, ((-n[0], -n[1]),))]
    # R12 pushes from the cam's side, its head at K (clear of the stem and the guide's arrows)
    tail = (Kc[0] - R12_MM * d[0], Kc[1] - R12_MM * d[1])
    items.append(Arrow(tail, Kc, "result"))
    labels.append(Label("R_{12}", tail, ((d[0], d[1]),)))
    if data.phi > 0.0:
        marked = angle_mark(Kc, (-n[0], -n[1]), (-d[0], -d[1]), PHI_ARC, "φ")
        items += [m for m in marked if not isinstance(m, Label)]
        labels += [m for m in marked if isinstance(m, Label)]
    items += [Circle(Kc, DOT, "result")]
    labels.append(Label("K", Kc, ((n[0], n[1]), (-n[0], -n[1]), (d[0], d[1]))))
    # Q down the follower's axis, on its top
    items.append(Arrow((B[0], top + FORCE_MM), (B[0], top), "result"))
    labels.append(Label("Q", (B[0], top + FORCE_MM), ((0.0, -1.0),)))
    # the guide's reactions at B1, B2: heads at the bearing points, from the side the guide bears on
    reach = SKETCH_REACH * math.hypot(*B2)
    far = S is None or math.hypot(*S) > reach
    for at, e, name in ((B1, e1, "R′_{32}"), (B2, e2, "R″_{32}")):
        u = _xy(e)
        tail = (at[0] - FORCE_MM * u[0], at[1] - FORCE_MM * u[1])
        items.append(Arrow(tail, at, "result"))
        labels.append(Label(name, tail, (u,)))
        if data.f > 0.0:  # the guide's normal at the bearing point, and φ′ between it and the reaction
            out = (-1.0 if u[0] > 0 else 1.0, 0.0)  # the guide's normal, on the side the reaction comes from
            items.append(Segment(at, (at[0] + out[0] * NORMAL_PAST, at[1]), "construction"))
            marked = angle_mark(at, out, (-u[0], -u[1]), PHI_ARC, "φ′")
            items += [m for m in marked if not isinstance(m, Label)]
            labels += [m for m in marked if isinstance(m, Label)]
        items.append(Circle(at, DOT, "result"))
        labels.append(Label("B_{1}" if at is B1 else "B_{2}", at, ((u[0], u[1]), (-u[0], -u[1]), (0.0, 1.0),
                                                                     (0.0, -1.0))))
        if S is not None and not far:  # Culmann: the reactions' lines run on to S
            items.append(Segment(tail, S, "construction"))
    # Culmann's points: P (Q and R12), S (the two guide reactions), and the resultant's line P–S
    if math.dist(Kc, P) > 1e-9:
        items.append(Segment(Kc, P, "construction"))
    items.append(Circle(P, DOT, "result"))
    labels.append(Label("P", P, ((0.0, 1.0), (0.0, -1.0), (d[0], d[1]), (-d[0], -d[1]))))
    if S is not None and not far:
        items += [Segment(P, S, "construction", dashed=True), Circle(S, DOT, "result")]
        labels.append(Label("S", S, (_xy(-poly["c"] / np.hypot(*poly["c"])),)))
    return items + labels


def sketch_panel(cam: DiscCam, data: CamFriction, drawn: Any, mu_l: float, notation: str = "en") -> Panel:
    """The follower's free body at δ (:func:`sketch_items`), at the profile's μl — or at the round
    scale that draws it about SKETCH_HEIGHT tall (from the cam's far side to the guide's top)."""
    act = np.asarray(drawn.actual, dtype=float)
    act = act[np.isfinite(act).all(axis=1)]
    height = float(np.max(np.hypot(*act.T))) if len(act) else cam.base_radius
    height += float(solve(cam, data).position.B2[1])
    mu_l = max(mu_l, round_scale(height / SKETCH_HEIGHT))
    title = {"zh": "从动件受力图（计摩擦）", "ru": "силы, действующие на толкатель (с трением)"}.get(
        notation, "Free body of the follower, with friction")
    note = f"δ = {math.degrees(data.at):.6g}°, φ′ = atan f = {math.degrees(math.atan(data.f)):.4g}°"
    return Panel("free body", title, tuple(sketch_items(cam, data, drawn, mu_l)), (scale_text("l", mu_l), note),
                 scales=(("l", mu_l),))


def refuse(cam: DiscCam, data: CamFriction) -> str | None:
    """Why the forces cannot be found at this position (None: they can)."""
    from graphmech.errors import OutOfDomain

    try:
        solve(cam, data)
    except (OutOfDomain, NoSolution) as e:
        return str(e)
    return None


__all__ = ["CAM_FORCE_QUANTITIES", "choose_force_scale", "force_polygon", "force_rows", "forces_panel",
           "read_forces", "refuse", "sketch_items", "sketch_panel"]
