"""Benchmark of the cam inversion: the drawn profile's deviation from the exact one and the time
for 24 … 3600 divisions, with all the checks a scene runs.

Records as in :mod:`graphmech.bench` (``n`` is the number of divisions of the turn).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphmech.exact import cam as exact_cam
from graphmech.mechanisms.cam import DiscCam, MotionProgram, OscillatingFollower, Segment, TranslatingFollower
from graphmech.methods.cam_inversion import CamReading, near, read_cam, rigid_corners as _rigid_corners
from graphmech.accuracy import convergence_order
from graphmech.timing import best_time



#: Divisions of the turn at which the inversion is drawn and measured.
CAM_DIVISIONS = (24, 48, 96, 180, 360, 720, 1440, 3600)


#: Exact points on the working profile against which a drawn profile is measured.
CAM_EXACT_SAMPLES = 20_000


#: How far below a joint its left-hand limit is taken, rad (beyond the motion law's snapping).
_DEG = math.pi / 180.0


def cam_cases() -> dict[str, DiscCam]:
    """The benchmark's cams: two reference problems and a flat-faced follower on smooth laws.

    ``offset-roller-e+10`` is cam.offset_roller_translating (e = +10, r0 = 30, r_r = 10, h = 16 mm;
    uniform rise 150°, dwell 30°, parabolic return 120°, dwell 60°; cam CCW): its pitch curve has a
    concave corner at 0° and a convex one at 150°. ``oscillating-roller`` is cam.oscillating_roller
    (|OA| = 55, r0 = 25, l = 50, r_r = 8 mm; 25° cosine rise over 180°, sine return over 180°,
    rocker turning against the cam). ``flat-face-translating``: a flat face ⟂ a centred axis,
    r0 = 30 mm, h = 12 mm, 3-4-5 rise 120°, dwell 30°, cycloidal return 120°, dwell 90°, cam CCW
    (no velocity jump, and r0 + s + s″ > 0 throughout: no undercut).
    """
    offset = MotionProgram(0.016, (Segment("rise", 150 * _DEG, "uniform"), Segment("dwell", 30 * _DEG),
                                   Segment("return", 120 * _DEG, "parabolic"), Segment("dwell", 60 * _DEG)))
    rocker = MotionProgram(25 * _DEG, (Segment("rise", math.pi, "cosine"), Segment("return", math.pi, "sine")))
    smooth = MotionProgram(0.012, (Segment("rise", 120 * _DEG, "poly345"), Segment("dwell", 30 * _DEG),
                                   Segment("return", 120 * _DEG, "sine"), Segment("dwell", 90 * _DEG)))
    return {
        "offset-roller-e+10": DiscCam(0.030, TranslatingFollower(0.010, "roller", 0.010), offset, rotation=1),
        "oscillating-roller": DiscCam(0.025, OscillatingFollower(0.055, 0.050, "roller", 0.008, "opposite"),
                                      rocker, rotation=1),
        "flat-face-translating": DiscCam(0.030, TranslatingFollower(0.0, "flat"), smooth, rotation=1),
    }


@dataclass(frozen=True)
class CamReference:
    """The exact cam (graphmech.exact.cam): its working profile as a dense closed polyline, and
    the exact values of what ``read_cam`` reads off the drawing."""

    points: np.ndarray  # (M, 2) m, in order round the profile
    angles: np.ndarray  # (M,) rad: the cam angle each point belongs to
    corners: np.ndarray  # rad: the pitch curve's corners
    size: float  # m: the largest radius of the working profile
    alpha_max: float
    alpha_max_at: float
    rho_min: float
    rho_min_at: float
    undercut: bool


def cam_reference(cam: DiscCam, samples: int = CAM_EXACT_SAMPLES) -> CamReference:
    """The exact solution the drawing is measured against (never timed)."""
    from graphmech.tolerances import TANGENT_REL

    pts, ang = exact_cam.working_profile(cam, samples)
    alpha, alpha_at = exact_cam.max_pressure_angle(cam)
    f = cam.follower
    if f.contact == "flat":
        rho, rho_at = exact_cam.min_rho_actual(cam, samples)
        under = rho <= cam.base_radius * TANGENT_REL
    else:
        rho, rho_at = exact_cam.min_convex_rho_pitch(cam)
        under = f.contact == "roller" and f.roller_radius >= rho * (1.0 - TANGENT_REL)
    return CamReference(pts, ang, _rigid_corners(cam), float(np.max(np.hypot(*pts.T))), alpha, alpha_at,
                        rho, rho_at, bool(under))


def _nearest(points: np.ndarray, ring: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Distance from each point to the closed polyline through ``ring``, and the nearest segment's index."""
    import shapely

    if len(ring) > 1 and np.array_equal(ring[0], ring[-1]):
        ring = ring[:-1]
    closed = np.concatenate([ring, ring[:1]])
    segments = shapely.linestrings(np.stack([closed[:-1], closed[1:]], axis=1))
    idx, dist = shapely.STRtree(segments).query_nearest(shapely.points(points), return_distance=True,
                                                        all_matches=False)
    out_d = np.full(len(points), np.inf)
    out_i = np.zeros(len(points), dtype=int)
    out_d[idx[0]] = dist  # one match per point (all_matches=False)
    out_i[idx[0]] = idx[1]
    return out_d, out_i


def _angle_error_deg(a: float, b: float) -> float:
    return abs(math.degrees((a - b + math.pi) % math.tau - math.pi))


def cam_record(case: str, n: int, seconds: float, reading: CamReading, ref: CamReference) -> dict[str, Any]:
    """One benchmark record: the drawing at ``n`` divisions against the exact cam.

    ``max_rel_error`` is the Hausdorff distance between the drawn working profile (a closed
    polyline) and the exact one (``ref.points``, closed): the larger of the farthest exact point
    from the drawing and the farthest drawn vertex from the exact polyline, divided by the largest
    profile radius. ``max_rel_error_smooth`` is the same away from the pitch curve's corners (more
    than two divisions from them); ``worst_at_deg`` is the cam angle where the error is largest.
    """
    act = reading.drawn.actual
    fwd, _ = _nearest(ref.points, act)
    rev, seg = _nearest(act, ref.points)
    rev_at = ref.angles[seg]
    worst = max(float(fwd.max()), float(rev.max()))
    at = ref.angles[int(np.argmax(fwd))] if fwd.max() >= rev.max() else rev_at[int(np.argmax(rev))]
    far = math.tau / n * 2.0
    f_ok, r_ok = ~near(ref.angles, ref.corners, far), ~near(rev_at, ref.corners, far)
    smooth = max(float(np.max(fwd[f_ok], initial=0.0)), float(np.max(rev[r_ok], initial=0.0)))
    vertices = len(act) - (1 if len(act) > 1 and np.array_equal(act[0], act[-1]) else 0)
    return {
        "method": "cam-inversion", "case": case, "n": n, "seconds": seconds,
        "max_rel_error": worst / ref.size,
        "max_rel_error_smooth": smooth / ref.size,
        "worst_at_deg": round(math.degrees(float(at)), 6),
        "divisions": len(reading.delta),
        "profile_vertices": vertices,
        "alpha_max_deg": math.degrees(reading.alpha_max),
        "alpha_max_error_deg": abs(math.degrees(reading.alpha_max - ref.alpha_max)),
        "alpha_max_at_error_deg": (0.0 if ref.alpha_max == 0.0 else _angle_error_deg(reading.alpha_max_at,
                                                                                     ref.alpha_max_at)),
        "rho_min_mm": reading.rho_min * 1e3,
        "rho_min_rel_error": abs(reading.rho_min - ref.rho_min) / abs(ref.rho_min),
        "undercut": reading.undercut,
        "undercut_agrees": reading.undercut == ref.undercut,
    }


def cam_records(repeat: int = 7, ns: tuple[int, ...] = CAM_DIVISIONS,
                samples: int = CAM_EXACT_SAMPLES) -> list[dict[str, Any]]:
    """The cam inversion of each case at each number of divisions: time and error."""
    records = []
    for case, cam in cam_cases().items():
        ref = cam_reference(cam, samples)
        for n in ns:
            secs, _ = best_time(lambda: read_cam(cam, n), repeat, max(1, 360 // n))
            records.append(cam_record(case, n, secs, read_cam(cam, n), ref))
    return records


def _cam_notes(records: list[dict[str, Any]]) -> list[str]:
    cams = [r for r in records if r["method"] == "cam-inversion"]
    cases = list(dict.fromkeys(r["case"] for r in cams))
    big = max(r["n"] for r in cams)
    at_big = {r["case"]: r for r in cams if r["n"] == big}
    notes = [f"cam inversion, {big} divisions, whole drawn profile with all its checks: " +
             ", ".join(f"{c} {at_big[c]['seconds'] * 1e3:.2f} ms" for c in cases) + " (target < 50 ms)"]
    for c in cases:
        rs = [r for r in cams if r["case"] == c]
        o, sm = convergence_order(rs), convergence_order(rs, "max_rel_error_smooth")
        last = at_big[c]
        notes.append(
            f"cam inversion {c}: max rel error {min(rs, key=lambda r: r['n'])['max_rel_error']:.1e} → "
            f"{last['max_rel_error']:.1e} at n = {big} (worst at δ = {last['worst_at_deg']:.2f}°); order "
            f"{o['asymptotic']:.2f} over n = {o['n_from']}…{o['n_to']}, {o['overall']:.2f} fitted over all n; "
            f"away from the pitch curve's corners {sm['asymptotic']:.2f} over n = {sm['n_from']}…{sm['n_to']}, "
            f"{last['max_rel_error_smooth']:.1e} at n = {big}")
    notes.append("cam inversion: where a roller profile's error stops falling (≈ 2–5e-6 near n = 3600) it is the "
                 "drawing's resolution, not the method's: GEOS simplifies the buffer's input at 1 % of r_r, thinning "
                 "the offset's vertices to a spacing of about 1 % of r_r (see profile_vertices); the roller's arc "
                 "round a concave corner is drawn with ⌈n/4⌉ segments per quarter circle, so it is no floor")
    return notes


def bench(quick: bool = False) -> tuple[list[dict[str, Any]], list[str]]:
    """The cam inversion's records and the notes on its convergence and time."""
    records = cam_records(repeat=3 if quick else 7)
    return records, _cam_notes(records)
