"""Analysis of a disc cam given by its profile, by inversion (反转法) as the book draws it.

The cam stands still; the follower is drawn turned back by −rot·δ about O. For an eccentric disc
every step is a compass-and-straightedge cut (:mod:`graphmech.geometry.kernels`):

* the pitch (theoretical) curve is the circle about the disc's centre C of radius R + r_r; the
  base circle the circle about O through its nearest point (on the line OC);
* a translating knife or roller: the inverted axis (tangent to the offset circle e) cut with the
  pitch circle; s is read along the axis from the base circle;
* a translating flat face: the tangent to the disc ⟂ the inverted axis, at C + R·(axis);
* a rocker: the arm's circle l about the inverted pivot A_δ (on the circle a about O) cut with the
  pitch circle, or the tangent from A_δ to the disc by the Thales circle on A_δC; ψ is read at A_δ
  from A_δO, the swing from the base circle's position;
* the pressure angle between the common normal (through C) and the follower point's motion;
* the follower's velocity by the instant centre P12, where the common normal meets the line
  through O ⟂ the axis (v = ω·|OP12|) or the line OA (ω2 = ω·OP12/AP12);
* a contact E on the profile: the ray from O cuts the disc at E, the normal CE carries the pitch
  point E′ = E + r_r·n; the inverted follower through E′ (the tangent from E′ to the offset
  circle, the pivot an arm from E′ on the circle a, the tangent at E through the circle a, a flat
  face ⟂ CE) gives its cam angle: the angle between two such positions is the angle turned.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphmech.errors import DegenerateConstruction, NoSolution
from graphmech.geometry.kernels import (
    Components,
    ScalarOps,
    intersect_circle_line,
    intersect_circles,
    unit,
)
from graphmech.mechanisms.cam import OscillatingFollower, TranslatingFollower
from graphmech.mechanisms.cam_profile import GivenCam, PointsProfile

__all__ = ["DrawnPosition", "Inversion", "PolylineInversion", "inversion"]

_TWO_PI = 2.0 * math.pi
#: A contact point drawn further than this (relative to R) from the one given is not it.
_SAME_POINT_REL = 1e-9


@dataclass(frozen=True)
class DrawnPosition:
    """The inverted follower drawn at cam angle δ (cam frame, m, rad).

    pivot : the inverted pivot A_δ (rocker) or the axis' foot on the offset circle (translating).
    point : the follower point B (roller centre, knife tip) or the flat face's point of contact.
    contact : the point of the working profile touched.
    q : the position read off: the distance along the axis from O's perpendicular (m) or ψ (rad).
    s : the displacement from the lowest position (m, or rad for a rocker).
    alpha : the pressure angle (rad).
    v : the follower's velocity (m/s, or rad/s for a rocker), positive while it rises.
    p12 : the instant centre of cam and follower.
    """

    delta: float
    pivot: tuple[float, float]
    point: tuple[float, float]
    contact: tuple[float, float]
    q: float
    s: float
    alpha: float
    v: float
    p12: tuple[float, float]


def _no_cut(what: str) -> object:
    return lambda d: f"{what} do not meet"


def _rot(x: float, y: float, t: float) -> tuple[float, float]:
    c, s = math.cos(t), math.sin(t)
    return c * x - s * y, s * x + c * y


def _angle(u: Components, v: Components) -> float:
    """The angle between two directions (from :func:`unit`), 0 … π."""
    return math.acos(max(-1.0, min(1.0, u[0] * v[0] + u[1] * v[1])))


class Inversion:
    """The book's inversion drawing of a given cam; every reading is a construction."""

    def __init__(self, cam: GivenCam) -> None:
        self.cam = cam
        self.ops = ScalarOps()
        f = cam.follower
        self.sigma = cam.rotation if isinstance(f, OscillatingFollower) and f.sense == "opposite" else -cam.rotation
        self.C = cam.disc.centre
        self.R = cam.disc.radius
        self.rho = cam.pitch_radius()
        # the base circle through the pitch curve's nearest point to O, and the farthest circle
        ref = self.R if f.contact == "flat" else self.rho
        if self.C == (0.0, 0.0):  # a disc turning about its own centre
            self.r0 = self.r_max = ref
        else:
            to_o = unit(self.ops, self.C, (0.0, 0.0))
            near = intersect_circle_line(self.ops, self.C, ref, (self.C[0], self.C[1], to_o[0], to_o[1]), 1.0,
                                         _no_cut("OC and the pitch circle"))  # type: ignore[arg-type]
            far = intersect_circle_line(self.ops, self.C, ref, (self.C[0], self.C[1], to_o[0], to_o[1]), -1.0,
                                        _no_cut("OC and the pitch circle"))  # type: ignore[arg-type]
            self.r0, self.r_max = math.hypot(*near), math.hypot(*far)
        self.q_low, self.q_high = self._at_radius(self.r0), self._at_radius(self.r_max)

    # ----------------------------------------------------------------- the follower at δ = 0 against a circle about O

    def _at_radius(self, r: float) -> float:
        """The follower's position q when it rests on the circle of radius r about O (drawn at δ = 0)."""
        f, ops = self.cam.follower, self.ops
        if isinstance(f, TranslatingFollower):
            if f.contact == "flat":
                return r
            k = intersect_circle_line(ops, (0.0, 0.0), r, (f.offset, 0.0, 0.0, 1.0), 1.0,
                                      _no_cut("the axis and the circle"))  # type: ignore[arg-type]
            return float(k[1])
        a = f.pivot_distance
        if f.contact == "flat":  # the tangent from A to the circle r: Thales circle on AO
            t = intersect_circles(ops, (0.0, 0.0), r, (a / 2.0, 0.0), a / 2.0, 1.0,
                                  _no_cut("the Thales circle and the circle"))  # type: ignore[arg-type]
        else:
            t = intersect_circles(ops, (a, 0.0), f.arm, (0.0, 0.0), r, 1.0,
                                  _no_cut("the arm's circle and the circle"))  # type: ignore[arg-type]
        return _angle(unit(ops, (a, 0.0), (0.0, 0.0)), unit(ops, (a, 0.0), t))

    # ----------------------------------------------------------------- one position

    def _psi(self, A: tuple[float, float], X: Components, turn: float) -> float:
        """ψ read at the inverted pivot A_δ: the angle from A_δO to A_δX in the rocker's sense."""
        bx, by = _rot(X[0] - A[0], X[1] - A[1], -turn)
        return math.atan2(self.sigma * by, -bx)

    def at(self, delta: float) -> DrawnPosition:
        """The follower drawn at cam angle δ and everything read off it."""
        cam, ops, C = self.cam, self.ops, self.C
        f = cam.follower
        turn = -cam.rotation * delta
        if isinstance(f, TranslatingFollower):
            dx, dy = _rot(0.0, 1.0, turn)
            foot = _rot(f.offset, 0.0, turn)
            if f.contact == "flat":
                point = intersect_circle_line(ops, C, self.R, (C[0], C[1], dx, dy), 1.0,
                                              _no_cut("the disc and its diameter"))  # type: ignore[arg-type]
                contact, normal_through = point, point
            else:
                point = intersect_circle_line(ops, C, self.rho, (foot[0], foot[1], dx, dy), 1.0,
                                              _no_cut("the inverted axis and the pitch circle"))  # type: ignore[arg-type]
                contact = self._on_disc_towards(point)
                normal_through = point
            q = point[0] * dx + point[1] * dy
            n = unit(ops, C, normal_through)
            alpha = 0.0 if f.contact == "flat" else _angle(n, (dx, dy)) if n[0] * dx + n[1] * dy >= 0 else \
                math.pi - _angle(n, (dx, dy))
            # P12: the common normal cut with the line through O ⟂ the axis
            p12 = self._cut_lines((C[0], C[1], n[0], n[1]), (0.0, 0.0, -dy, dx))
            v = cam.rotation * cam.omega * (-p12[1] * dx + p12[0] * dy)  # (J·P12)·axis
            return DrawnPosition(delta, foot, (float(point[0]), float(point[1])), contact, q, q - self.q_low,
                                 alpha, v, p12)
        A = _rot(f.pivot_distance, 0.0, turn)
        cands: list[Components] = []
        for side in (1.0, -1.0):
            if f.contact == "flat":  # the tangent point by the Thales circle on A_δC
                M = ((A[0] + C[0]) / 2.0, (A[1] + C[1]) / 2.0)
                half = math.hypot(A[0] - C[0], A[1] - C[1]) / 2.0
                cands.append(intersect_circles(ops, C, self.R, M, half, side,
                                               _no_cut("the Thales circle and the disc")))  # type: ignore[arg-type]
            else:
                cands.append(intersect_circles(ops, A, f.arm, C, self.rho, side,
                                               _no_cut("the arm's circle and the pitch circle")))  # type: ignore[arg-type]
        point = max(cands, key=lambda X: self._psi(A, X, turn))  # the follower rests on the outer cut
        psi = self._psi(A, point, turn)
        n = unit(ops, C, point)
        if f.contact == "flat":
            contact, alpha = (float(point[0]), float(point[1])), 0.0
        else:
            contact = self._on_disc_towards(point)
            arm = unit(ops, A, point)
            alpha = abs(math.pi / 2.0 - _angle(n, arm))
        p12 = self._cut_lines((C[0], C[1], n[0], n[1]), (0.0, 0.0, A[0] / f.pivot_distance, A[1] / f.pivot_distance))
        mu = (p12[0] * A[0] + p12[1] * A[1]) / (f.pivot_distance ** 2)  # P12 = μ·A_δ
        omega2 = cam.rotation * cam.omega * mu / (mu - 1.0)  # counter-clockwise positive
        v = -self.sigma * omega2
        return DrawnPosition(delta, A, (float(point[0]), float(point[1])), contact, psi, psi - self.q_low, alpha, v, p12)

    def _on_disc_towards(self, point: Components) -> tuple[float, float]:
        """The disc's point on the radius C→point (the roller's contact)."""
        n = unit(self.ops, self.C, point)
        x = intersect_circle_line(self.ops, self.C, self.R, (self.C[0], self.C[1], n[0], n[1]), 1.0,
                                  _no_cut("the radius and the disc"))  # type: ignore[arg-type]
        return float(x[0]), float(x[1])

    def _cut_lines(self, l1: Components, l2: Components) -> tuple[float, float]:
        from graphmech.geometry.kernels import intersect_lines

        p = intersect_lines(self.ops, l1, l2)
        return float(p[0]), float(p[1])

    # ----------------------------------------------------------------- contacts and the stroke

    def rise(self) -> float:
        """h: the follower's positions on the farthest and the base circles, drawn at δ = 0."""
        return self.q_high - self.q_low

    def _touched(self, polar: float) -> tuple[Components, Components]:
        """The profile's point at polar angle φ about O (the ray from O cut with the disc) and its
        normal (along the radius CE)."""
        w = (math.cos(polar), math.sin(polar))
        E = intersect_circle_line(self.ops, self.C, self.R, (0.0, 0.0, w[0], w[1]), 1.0,
                                  _no_cut("the ray and the disc"))  # type: ignore[arg-type]
        return E, unit(self.ops, self.C, E)

    #: How near (relative to the cam's size) the drawn contact at the δ found must come to the given
    #: point: the cuts are exact for a disc.
    same_point_rel = _SAME_POINT_REL

    def contact(self, polar: float, name: str = "") -> float:
        """The cam angle δ at which the follower touches the profile at polar angle ``polar``."""
        cam, ops = self.cam, self.ops
        f = cam.follower
        E, n = self._touched(polar)
        r = f.roller_radius if f.contact == "roller" else 0.0
        B = (E[0] + r * n[0], E[1] + r * n[1])
        turns: list[float] = []
        if isinstance(f, TranslatingFollower):
            if f.contact == "flat":
                turns = [math.atan2(n[1], n[0]) - math.pi / 2.0]
            elif f.offset == 0.0:
                turns = [math.atan2(B[1], B[0]) - math.pi / 2.0]
            else:  # the tangents from B to the offset circle, by the Thales circle on OB
                for side in (1.0, -1.0):
                    try:
                        Q = intersect_circles(ops, (0.0, 0.0), abs(f.offset), (B[0] / 2.0, B[1] / 2.0),
                                              math.hypot(*B) / 2.0, side, _no_cut("the offset and Thales circles"))  # type: ignore[arg-type]
                    except DegenerateConstruction:
                        continue
                    d = unit(ops, Q, B)
                    turns.append(math.atan2(d[1], d[0]) - math.pi / 2.0)
        else:
            for side in (1.0, -1.0):
                try:
                    if f.contact == "flat":
                        A = intersect_circle_line(ops, (0.0, 0.0), f.pivot_distance, (E[0], E[1], -n[1], n[0]), side,
                                                  _no_cut("the tangent and the pivot's circle"))  # type: ignore[arg-type]
                    else:
                        A = intersect_circles(ops, (0.0, 0.0), f.pivot_distance, B, f.arm, side,
                                              _no_cut("the pivot's and the arm's circles"))  # type: ignore[arg-type]
                except DegenerateConstruction:
                    continue
                turns.append(math.atan2(A[1], A[0]))
        best: tuple[float, float] | None = None  # (distance, δ): the candidate whose drawn contact is E
        for turn in turns:
            delta = (-cam.rotation * turn) % _TWO_PI
            if delta >= _TWO_PI:
                delta = 0.0
            P = self.at(delta).contact
            gap = math.hypot(P[0] - E[0], P[1] - E[1])
            if gap <= self.same_point_rel * cam.size and (best is None or gap < best[0]):
                best = (gap, delta)
        if best is not None:
            return best[1]
        raise NoSolution(f"the follower never touches the profile at {name or 'the contact'} (polar angle "
                         f"{math.degrees(polar):.6g}° about O): that point of the cam faces away from it")


#: The drawn profile of a cam given by points: the curve through them drawn as this many chords
#: (a French curve's line, read off as a polyline) when the scene does not say.
DRAWN_CHORDS = 720


class PolylineInversion(Inversion):
    """The inversion of a cam given by points, as drawn: the curve through the points drawn as a
    polyline of ``chords`` chords, the pitch curve by laying r_r off along each vertex's normal (⟂
    the chord through its neighbours), and every cut made on the chords. Its readings carry the
    drawing's discretisation: O(1/chords²) where the contact runs along a chord."""

    def __init__(self, cam: GivenCam, chords: int = DRAWN_CHORDS) -> None:
        self.cam = cam
        self.ops = ScalarOps()
        f = cam.follower
        self.sigma = cam.rotation if isinstance(f, OscillatingFollower) and f.sense == "opposite" else -cam.rotation
        profile = cam.profile
        assert isinstance(profile, PointsProfile)
        t = np.linspace(0.0, profile.length, chords, endpoint=False)
        self.P = profile.at(t)
        tau = np.roll(self.P, -1, axis=0) - np.roll(self.P, 1, axis=0)
        # each vertex's normal ⟂ the chord through its neighbours; between vertices it is read by
        # proportion along the chord (the normal of the drawn curve, to O(1/chords²))
        self.N = np.column_stack([tau[:, 1], -tau[:, 0]]) / np.hypot(tau[:, 0], tau[:, 1])[:, None]
        self.B = self.P + cam.roller * self.N
        ref = self.P if f.contact == "flat" else self.B
        self.r0 = float(np.min(_segment_distances(ref)))
        self.r_max = float(np.max(np.hypot(ref[:, 0], ref[:, 1])))
        self.q_low, self.q_high = self._at_radius(self.r0), self._at_radius(self.r_max)
        chord = float(np.max(np.hypot(*(np.roll(self.P, -1, axis=0) - self.P).T)))
        self.same_point_rel = 4.0 * chord / cam.size

    def _normal(self, i: int, lam: float) -> Components:
        """The drawn normal a fraction ``lam`` along the chord from vertex i to the next."""
        n = (1.0 - lam) * self.N[i] + lam * self.N[(i + 1) % len(self.N)]
        k = math.hypot(*n)
        return (float(n[0] / k), float(n[1] / k), 1.0)

    def _tangent_where(self, g: np.ndarray, keep: np.ndarray) -> np.ndarray:
        """The drawn curve's point where ``g`` (one value a vertex) changes sign on a chord whose
        first vertex ``keep`` allows, by proportion along the chord."""
        nxt = np.roll(g, -1)
        for i in np.flatnonzero((np.sign(g) != np.sign(nxt)) & keep):
            lam = g[i] / (g[i] - nxt[i])
            return np.asarray(self.P[i] + lam * (self.P[(i + 1) % len(self.P)] - self.P[i]))
        raise NoSolution("no tangent to the drawn profile")  # pragma: no cover - a convex closed curve has one

    def _touched(self, polar: float) -> tuple[Components, Components]:
        """The ray from O cut with the drawn profile, and the drawn normal there."""
        w = np.array([math.cos(polar), math.sin(polar)])
        P, Q = self.P, np.roll(self.P, -1, axis=0)
        c0, c1 = P[:, 0] * w[1] - P[:, 1] * w[0], Q[:, 0] * w[1] - Q[:, 1] * w[0]
        for i in np.flatnonzero((np.sign(c0) != np.sign(c1)) & (P @ w > 0.0)):
            lam = c0[i] / (c0[i] - c1[i])
            X = P[i] + lam * (Q[i] - P[i])
            return (float(X[0]), float(X[1])), self._normal(int(i), lam)
        raise NoSolution(f"the ray at {math.degrees(polar):.6g}° misses the drawn profile")  # pragma: no cover

    def at(self, delta: float) -> DrawnPosition:
        cam = self.cam
        f = cam.follower
        turn = -cam.rotation * delta
        P, Q = self.B, np.roll(self.B, -1, axis=0)
        if isinstance(f, TranslatingFollower):
            d = np.array(_rot(0.0, 1.0, turn))
            foot = _rot(f.offset, 0.0, turn)
            if f.contact == "flat":  # the tangent ⟂ the axis, where the drawn normal turns past it
                X = self._tangent_where(self.N[:, 0] * d[1] - self.N[:, 1] * d[0], self.N @ d > 0)
                n = (float(d[0]), float(d[1]), 1.0)
                contact = (float(X[0]), float(X[1]))
                alpha = 0.0
            else:
                c0 = (P[:, 0] - foot[0]) * d[1] - (P[:, 1] - foot[1]) * d[0]
                c1 = np.roll(c0, -1)
                best: tuple[float, np.ndarray, Components] | None = None
                for i in np.flatnonzero(np.sign(c0) != np.sign(c1)):
                    lam = c0[i] / (c0[i] - c1[i])
                    X = P[i] + lam * (Q[i] - P[i])
                    if best is None or X @ d > best[0]:
                        best = (float(X @ d), X, self._normal(int(i), float(lam)))
                if best is None:
                    raise NoSolution(f"the inverted axis misses the drawn pitch curve at δ = {math.degrees(delta):.6g}°")
                _, X, n = best
                contact = (float(X[0] - cam.roller * n[0]), float(X[1] - cam.roller * n[1]))
                alpha = math.acos(min(1.0, abs(n[0] * d[0] + n[1] * d[1])))
            q = float(X @ d)
            p12 = self._cut_lines((float(X[0]), float(X[1]), n[0], n[1]), (0.0, 0.0, -float(d[1]), float(d[0])))
            v = cam.rotation * cam.omega * (-p12[1] * d[0] + p12[0] * d[1])
            return DrawnPosition(delta, foot, (float(X[0]), float(X[1])), contact, q, q - self.q_low, alpha, v, p12)
        A = _rot(f.pivot_distance, 0.0, turn)
        if f.contact == "flat":  # the tangent from A_δ, of the larger ψ: where A_δP turns past the drawn curve
            a_x = np.array(A)
            along = np.sum((self.P - a_x) * self.N, axis=1)
            rel = self.P - a_x  # ψ of every drawn point, read at A_δ as _psi reads one
            c, s = math.cos(-turn), math.sin(-turn)
            seen = np.arctan2(self.sigma * (s * rel[:, 0] + c * rel[:, 1]), -(c * rel[:, 0] - s * rel[:, 1]))
            X = self._tangent_where(along, seen >= np.median(seen))
            arm = unit(self.ops, A, (float(X[0]), float(X[1])))
            n = (-arm[1], arm[0], 1.0)
            contact, alpha = (float(X[0]), float(X[1])), 0.0
        else:  # the arm's circle about A_δ cut with the chords of the pitch curve
            cands: list[tuple[np.ndarray, Components]] = []
            g = np.hypot(P[:, 0] - A[0], P[:, 1] - A[1]) - f.arm
            for i in np.flatnonzero(np.sign(g) != np.sign(np.roll(g, -1))):
                X, lam = _circle_chord(np.array(A), f.arm, P[i], Q[i])
                cands.append((X, self._normal(int(i), lam)))
            if not cands:
                raise NoSolution(f"the arm does not reach the drawn pitch curve at δ = {math.degrees(delta):.6g}°")
            X, n = max(cands, key=lambda c: self._psi(A, (float(c[0][0]), float(c[0][1])), turn))
            contact = (float(X[0] - cam.roller * n[0]), float(X[1] - cam.roller * n[1]))
            alpha = abs(math.pi / 2.0 - _angle(n, unit(self.ops, A, (float(X[0]), float(X[1])))))
        psi = self._psi(A, (float(X[0]), float(X[1])), turn)
        a = f.pivot_distance
        p12 = self._cut_lines((float(X[0]), float(X[1]), n[0], n[1]), (0.0, 0.0, A[0] / a, A[1] / a))
        mu = (p12[0] * A[0] + p12[1] * A[1]) / (a * a)
        v = -self.sigma * cam.rotation * cam.omega * mu / (mu - 1.0)
        return DrawnPosition(delta, A, (float(X[0]), float(X[1])), contact, psi, psi - self.q_low, alpha, v, p12)


def _circle_chord(c: np.ndarray, r: float, p: np.ndarray, q: np.ndarray) -> tuple[np.ndarray, float]:
    """Where the circle (c, r) cuts the chord pq (the root within it)."""
    d = q - p
    f = p - c
    a, b, k = float(d @ d), 2.0 * float(f @ d), float(f @ f) - r * r
    root = math.sqrt(max(b * b - 4.0 * a * k, 0.0))
    lam = [x for x in ((-b - root) / (2.0 * a), (-b + root) / (2.0 * a)) if -1e-12 <= x <= 1.0 + 1e-12]
    x = lam[0] if lam else 0.5
    return np.asarray(p + x * d), float(x)


def _segment_distances(poly: np.ndarray) -> np.ndarray:
    """The distance from O to each chord of the closed polyline."""
    p, q = poly, np.roll(poly, -1, axis=0)
    d = q - p
    lam = np.clip(-np.sum(p * d, axis=1) / np.sum(d * d, axis=1), 0.0, 1.0)
    x = p + lam[:, None] * d
    return np.asarray(np.hypot(x[:, 0], x[:, 1]))


def inversion(cam: GivenCam) -> Inversion:
    """The inversion drawing of a given cam: by compass cuts for a disc, on the drawn chords for
    a profile given by points."""
    return PolylineInversion(cam) if isinstance(cam.profile, PointsProfile) else Inversion(cam)
