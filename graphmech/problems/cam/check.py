"""Checking a cam scene: carry out the inversion, read the drawing off, compare with the exact cam.

The counterpart of :mod:`graphmech.problems.linkage.check` for disc cams. The inversion is a discretising
method — the profile is drawn through N division points — so its readings (largest pressure
angle, smallest radius of curvature, the profile itself) converge to the exact values as the
divisions get finer; the check table states by how much they differ at the scene's step, and
``graphmech bench`` reports the error against the number of divisions and the time taken.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any, cast

import numpy as np

from graphmech.accuracy import DISCRETISATION, READING, estimate_from_three, relative
from graphmech.problems.judging import Row, Verdict, close_names, in_double_precision, measured_entries
from graphmech.problems.reader import page_size
from graphmech.errors import NoSolution, SceneError
from graphmech.exact import cam as exact_cam
from graphmech.mechanisms.cam import DiscCam, OscillatingFollower, TranslatingFollower
from graphmech.mechanisms.motion import breakpoints, displacement, impacts, maxima
from graphmech.problems.cam.figures import panel_rows, scale_note
from graphmech.methods.cam_inversion import DrawnProfile, divisions, draw_profile, read_drawing, whole_turn_step
from graphmech.scales import drawn_size_problem, round_scale

if TYPE_CHECKING:
    from graphmech.exact.cam_forces import CamFriction
    from graphmech.problems.cam.scene import CamScene
    from graphmech.problems.reader import Scene

#: What a cam scene can ask for, with the unit each is reported in.
CAM_QUANTITIES = {
    "alpha_max": "deg", "alpha_max_at": "deg", "rho_min_pitch": "m", "rho_min_pitch_at": "deg",
    "profile_deviation": "m", "v_max": "m/s", "v_max_at": "deg", "a_max": "m/s²", "a_max_at": "deg",
    "j_max": "m/s³", "j_max_at": "deg", "r0_min": "m", "h": "m", "rho_min_actual": "m",
    "s0": "m", "psi0": "deg",
}
#: The readings at one division, ``s@45``: the diagram's ordinate (a rocker's ψ, also ``psi@45``) and
#: the pressure angle.
AT_DIVISION = ("s@", "psi@", "alpha@")
#: Dense exact points used to measure how far the drawn profile is from the exact one.
EXACT_SAMPLES = 8192


#: Quantities read off the profile (the others come from the motion diagrams alone).
PROFILE_QUANTITIES = {"alpha_max", "alpha_max_at", "rho_min_pitch", "rho_min_pitch_at", "profile_deviation", "r0_min",
                      "rho_min_actual", "s0", "psi0"}


@dataclass
class CamAnalysis:
    scene: Scene[CamScene]
    cam: DiscCam
    delta: np.ndarray
    s: np.ndarray
    drawn: DrawnProfile | None  # None when the scene asks for nothing on the profile
    scales: dict[str, float]
    stated: set[str]
    rows: list[Row] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    impacts: list[dict[str, Any]] = field(default_factory=list)
    marks: dict[str, Any] = field(default_factory=dict)
    reading: Any = None  # what is read off the drawn profile (methods.cam_inversion.CamReading)
    divisions: list[dict[str, Any]] = field(default_factory=list)  # the book's table, one row a division
    extra_measured: tuple[tuple[str, float], ...] = ()
    step: float = 0.0  # rad, the divisions' step as drawn (2π/N)
    finer: tuple[CamAnalysis, ...] = ()  # the same drawing at 2N, 4N and 8N divisions, for the rows' error estimates

    @property
    def profile(self) -> DrawnProfile:
        """The drawn profile of a scene that asks for a reading off it (its rows and the division
        table are made only then): a statement for the type checker, not a check."""
        return cast("DrawnProfile", self.drawn)

    def scale_notes(self) -> list[str]:
        """μ as written on the drawing (an oscillating follower's μs is an angle per mm)."""
        return [scale_note(k, v, _angular(self.cam)) + ("" if k in self.stated else " (chosen)")
                for k, v in self.scales.items()]


def _angular(cam: DiscCam) -> bool:
    return isinstance(cam.follower, OscillatingFollower)


def profile_deviation(cam: DiscCam, actual: np.ndarray, samples: int = EXACT_SAMPLES) -> float:
    """The largest distance (m) from the exact working profile (corners resolved: the roller's arc
    round a concave corner, the offsets cut at a convex one) to the drawn one, a closed polyline."""
    import shapely

    try:
        exact, _ = exact_cam.working_profile(cam, samples)
    except ValueError as e:  # a flat face cannot follow a velocity jump
        raise NoSolution(str(e)) from None
    return float(np.max(shapely.distance(shapely.points(exact), shapely.LinearRing(actual))))


def choose_cam_scales(scene: Scene[CamScene], cam: DiscCam, drawn: DrawnProfile | None) -> tuple[dict[str, float], set[str]]:
    """μ from the scene where stated; otherwise round values that fit one row of panels."""
    stated: set[str] = {k for k in ("l", "s", "phi", "v", "a") if k in scene.scales}
    # in the book's order, never a set's: the table and the JSON list them the same way every run
    scales: dict[str, float] = {k: float(scene.scales[k]) for k in ("l", "s", "phi", "v", "a") if k in stated}
    w, h = page_size(scene)
    rows = panel_rows(scene.show)
    n_rows = max(rows.values(), default=0) + 1
    if scene.problem.coordinates or (scene.problem.forces is not None and len(rows) > 1):
        n_rows += 1  # the coordinates table or the force polygon in a row of its own under the drawing
    n = max([list(rows.values()).count(r) for r in range(n_rows)] + [1])  # panels in the fullest row
    # In a row the profile gets twice a diagram's width.
    weights = [2.0 if p == "profile" else 1.0 for p, r in rows.items() if r == 0] or [1.0]
    free = w - 20.0 - 12.0 * (n - 1) - 12.0 * n
    room_profile = max(free * 2.0 / sum(weights), 40.0) if "profile" in scene.show else free
    room_w = max(free / max(sum(weights), n), 40.0)
    room_h = (h - 38.0) / n_rows - 35.0
    f = cam.follower
    pitch_r = float(np.max(np.hypot(*drawn.pitch.T))) if drawn is not None else \
        cam.base_radius + (0.0 if _angular(cam) else cam.program.stroke)
    reach = pitch_r + getattr(f, "roller_radius", 0.0)
    if _angular(cam):
        reach = max(reach, cast("OscillatingFollower", f).pivot_distance + getattr(f, "roller_radius", 0.0))
    _legible(scene, cam, scales, 2.0 * reach)
    if scene.problem.forces is not None:  # the force polygon's μF: the load about 60 mm long
        from graphmech.problems.cam.forces import choose_force_scale

        scales["F"] = choose_force_scale(scene.problem.forces)
    if "l" not in scales:
        scales["l"] = round_scale(2.0 * reach / min(room_profile, room_h))
    if "phi" not in scales:  # books choose degrees per mm
        scales["phi"] = math.radians(round_scale(360.0 / room_w))
    ext = maxima(cam.program, cam.omega)
    if "s" not in scales:
        scales["s"] = round_scale(cam.program.stroke / (0.6 * room_h))
    for key in ("v", "a"):
        if key not in scales:
            peak = ext[key].value
            scales[key] = round_scale(2.0 * peak / (0.6 * room_h)) if peak > 0 else 1.0
    return scales, stated


def _legible(scene: Scene[CamScene], cam: DiscCam, stated: dict[str, float], across: float) -> None:
    """Refuse a stated μ that draws what is shown beyond a page (graphmech.scales.DRAWN_SIZE_RANGE_MM,
    the rule a linkage's μl keeps): a 16 km stroke at μs = 0.0005 m/mm would be dashed for hours."""
    ext = maxima(cam.program, cam.omega)
    sizes = {"l": ("profile", across), "s": ("displacement", abs(cam.program.stroke)),
             "v": ("velocity", 2.0 * ext["v"].value), "a": ("acceleration", 2.0 * ext["a"].value)}
    for key, (panel, size) in sizes.items():
        if key in stated and panel in scene.show and size > 0.0:
            why = drawn_size_problem(size, stated[key], key, f"the {panel}", scale_note(key, stated[key], _angular(cam)))
            if why:
                raise SceneError([("scales", why)], scene.source)


def analyse_cam(scene: Scene[CamScene], extra_measured: tuple[tuple[str, float], ...] = (), *,
                estimates: bool = True) -> CamAnalysis:
    """The inversion at the scene's divisions, its readings, and the check table
    (``extra_measured``: hand readings from the command line, which may need the profile; each
    reading's own error estimate redraws at 2, 4 and 8 times the divisions: only a check needs it)."""
    with in_double_precision("the cam construction"):  # ω of 1e300: ω³·j overflows
        return _analyse_cam(scene, extra_measured, estimates)


def _analyse_cam(scene: Scene[CamScene], extra_measured: tuple[tuple[str, float], ...], estimates: bool) -> CamAnalysis:
    estimated = _estimated if estimates else (lambda an, row: row)
    cs = scene.problem
    cam: DiscCam = cs.cam
    names = _requested(scene)
    asked = names + [n for _, n, _ in measured_entries(scene, extra_measured)]
    step = whole_turn_step(cs.step)
    delta = divisions(cam, step, breakpoints(cam.program))
    s = displacement(cam.program, delta)
    # Only what the scene asks for: no profile for a scene that wants the diagrams alone.
    wants_profile = "profile" in scene.show or cs.coordinates or \
        any(n in PROFILE_QUANTITIES or n.startswith("alpha@") for n in asked)
    drawn = draw_profile(cam, delta, s) if wants_profile else None
    scales, stated = choose_cam_scales(scene, cam, drawn)
    an = CamAnalysis(scene, cam, delta, s, drawn, scales, stated, extra_measured=tuple(extra_measured), step=step)
    lin = "rad" if _angular(cam) else "m"
    an.impacts = [{"angle_deg": math.degrees(i.angle), "kind": i.kind,
                   # the jump of v (rigid) or of a (soft), in SI with the cam's ω
                   "jump": i.jump * cam.omega ** (1 if i.kind == "rigid" else 2),
                   "jump_unit": f"{lin}/s" if i.kind == "rigid" else f"{lin}/s²"}
                  for i in impacts(cam.program)]
    for i in impacts(cam.program):
        what = ("rigid impact: the velocity jumps, the acceleration is infinite (an impulse)" if i.kind == "rigid"
                else "soft impact: the acceleration jumps by a finite amount")
        an.warnings.append(f"δ = {math.degrees(i.angle):.6g}°: {what}")
    if drawn is None:
        an.rows = [estimated(an, _row(an, name)) for name in names]
        return an
    an.warnings += exact_cam.undercut(cam)
    reading = read_drawing(cam, drawn)
    an.reading = reading
    an.divisions = division_table(an)
    if reading.undercut:
        what = (f"the roller (r_r = {cam.follower.roller_radius * 1e3:.4g} mm) is no smaller than the pitch curve's "
                f"radius {reading.rho_min * 1e3:.4g} mm" if cam.follower.contact == "roller"
                else f"the profile's radius of curvature reads {reading.rho_min * 1e3:.4g} mm")
        an.warnings.append(f"the drawing undercuts: {what} at δ = {math.degrees(reading.rho_min_at):.4g}°")
        an.marks["undercut_at"] = [reading.rho_min_at]
    an.marks["alpha_max_at"] = reading.alpha_max_at
    an.marks["alpha_max"] = reading.alpha_max
    an.rows = []
    for name in names:
        try:
            an.rows.append(estimated(an, _row(an, name)))
        except ArithmeticError as e:  # e.g. the exact working profile folds over itself (undercut)
            an.warnings.append(f"{name}: not measured — {e}")
        except SceneError:
            raise
        except ValueError as e:  # e.g. no base radius keeps the pressure angle within [α]
            raise SceneError([("cam.alpha_permissible" if name == "r0_min" else "find", f"{name}: {e}")],
                             scene.source) from None
    return an


def division_table(an: CamAnalysis) -> list[dict[str, Any]]:
    """The table books print beside the inversion: per division its number, cam angle, displacement,
    and the pressure angle and pitch-curve radius read off the drawing, with their exact values."""
    cam, drawn = an.cam, an.profile
    ex = exact_cam.profile(cam, an.delta)
    ang = _angular(cam)
    out = []
    for k, d in enumerate(an.delta):
        out.append({
            "division": k, "delta_deg": math.degrees(float(d)),
            "s": math.degrees(float(an.s[k])) if ang else float(an.s[k]), "s_unit": "deg" if ang else "m",
            "alpha_deg": 0.0 if cam.follower.contact == "flat" else math.degrees(float(drawn.pressure_angle[k])),
            "alpha_exact_deg": math.degrees(float(ex.pressure_angle[k])),
            "rho_pitch": float(drawn.rho_pitch[k]) if abs(drawn.rho_pitch[k]) < 1e299 else None,
            "rho_pitch_exact": float(ex.rho_pitch[k]) if np.isfinite(ex.rho_pitch[k]) and abs(ex.rho_pitch[k]) < 1e299 else None,
        })
    if an.scene.problem.coordinates:  # the profile's coordinates as handed in: asked for, else the table as it was
        from graphmech.problems.cam.coordinates import coordinate_columns

        for row, xy in zip(out, coordinate_columns(cam, drawn)):
            row.update(xy)
    return out


def _requested(scene: Scene[CamScene]) -> list[str]:
    problems: list[tuple[str, str]] = []
    names: list[str] = []
    for k, name in enumerate(scene.find):
        why = reading_problem(scene.problem.cam, name)
        if why is not None:
            problems.append((f"find[{k}]", why))
            continue
        if name.startswith(AT_DIVISION):
            names.append(name)
            continue
        if name in _force_names():  # the follower's forces with friction (problems.cam.forces)
            if scene.problem.forces is None:
                problems.append((f"find[{k}]", f"{name} needs [cam.forces]: the position, the load and the friction"))
            else:
                names.append(name)
            continue
        if name not in CAM_QUANTITIES:
            problems.append((f"find[{k}]", f"unknown cam quantity {name!r}{close_names(name, CAM_QUANTITIES)}"))
        elif scene.problem.cam.follower.contact == "flat" and name in ("r0_min", "rho_min_pitch", "rho_min_pitch_at"):
            problems.append((f"find[{k}]", f"{name} has no meaning for a flat face (its pressure angle is 0 at any "
                                           "r0; its curvature is the working profile's: ask for rho_min_actual)"))
        elif name == "r0_min" and scene.problem.cam.alpha_permissible is None:
            problems.append((f"find[{k}]", "r0_min needs the permissible pressure angle: set [cam] alpha_permissible"))
        else:
            names.append(name)
    if problems:
        raise SceneError(problems, scene.source)
    return names


def _force_names() -> dict[str, str]:
    from graphmech.problems.cam.forces import CAM_FORCE_QUANTITIES

    return CAM_FORCE_QUANTITIES


def reading_problem(cam: DiscCam, name: str) -> str | None:
    """Why ``name`` cannot be read off this cam (None: it can, or it is no reading at a division
    and no rocker's name): a cam angle that is no number, a rocker's ψ asked of a translating follower."""
    if name.startswith(AT_DIVISION):
        try:
            if not math.isfinite(float(name.split("@")[1])):
                raise ValueError
        except ValueError:
            return f"{name!r}: write s@<cam angle in degrees>, e.g. s@45 (or alpha@45)"
    if (name.startswith("psi@") or name == "psi0") and not _angular(cam):
        other = "s0" if name == "psi0" else "s@" + name.split("@")[1]
        return f"{name} is a rocker's angle; this follower translates: ask for {other}"
    return None


def _graphical_r0_min(cam: DiscCam, alpha: float, step: float) -> float:
    """The smallest base radius found the draftsman's way: redraw at a trial r0 and read the
    largest pressure angle off the drawing, bisecting on r0 (to 1e-9 relative)."""

    def worst(r0: float) -> float:
        c = replace(cam, base_radius=r0)
        d = divisions(c, step, breakpoints(c.program))
        return read_drawing(c, draw_profile(c, d, displacement(c.program, d))).alpha_max

    f = cam.follower
    lo = abs(getattr(f, "offset", 0.0)) * (1 + 1e-9) + 1e-12
    if _angular(cam):
        rocker = cast("OscillatingFollower", f)
        lo = abs(rocker.pivot_distance - rocker.arm) * (1 + 1e-9) + 1e-12
    hi = max(cam.base_radius, lo * 2, 1e-6)
    while worst(hi) > alpha and hi < 1e3:
        hi *= 2.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if worst(mid) > alpha:
            lo = mid
        else:
            hi = mid
        if hi - lo <= 1e-12 * hi:
            break
    return cast(float, hi)


def _row(an: CamAnalysis, name: str) -> Row:
    cam, drawn, delta = an.cam, an.drawn, an.delta
    deg = math.degrees
    ang = _angular(cam)
    if "@" in name:  # a reading at one division: s@45 (the diagram's ordinate), alpha@45 (pressure angle)
        at_deg = float(name.split("@")[1])
        at = math.radians(at_deg) % math.tau
        k = int(np.argmin(np.abs((delta - at + math.pi) % math.tau - math.pi)))
        if abs((delta[k] - at + math.pi) % math.tau - math.pi) > 1e-9:
            key = f"find[{list(an.scene.find).index(name)}]" if name in an.scene.find else "find"
            raise SceneError([(key, f"{name}: {at_deg:g}° is not a division of this drawing "
                                    f"(every {deg(an.step):.6g}° and at the laws' joints)")], an.scene.source)
        if name.startswith("alpha@"):
            e = float(exact_cam.profile(cam, np.array([delta[k]])).pressure_angle[0])
            g = 0.0 if cam.follower.contact == "flat" else deg(an.profile.pressure_angle[k])  # the face's normal is the axis
            return _angle_row(name, g, deg(e), 90.0)
        e = float(displacement(cam.program, delta[k]))
        if ang:  # an angular displacement ψ (psi@45, or s@45) is reported in degrees
            return Row(name, "deg", an.s[k] / an.scales["s"], deg(an.scales["s"]), deg(an.s[k]), deg(e),
                       abs(an.s[k] - e) / cam.program.stroke)
        return _plain(name, "m", an.s[k] / an.scales["s"], an.scales["s"], e, cam.program.stroke)
    if name in _force_names():  # off the follower's force polygon (problems.cam.forces)
        from graphmech.problems.cam.forces import force_rows

        return force_rows(cam, cast("CamFriction", an.scene.problem.forces), an.scales["F"], [name])[name]
    unit = CAM_QUANTITIES[name]
    size = float(np.max(np.hypot(*drawn.pitch.T))) if drawn is not None else cam.base_radius
    rd = an.reading
    if name in ("alpha_max", "alpha_max_at"):
        a, at = exact_cam.max_pressure_angle(cam)
        if name == "alpha_max":
            return _angle_row(name, deg(rd.alpha_max), deg(a), 90.0)
        there = float(exact_cam.profile(cam, np.array([rd.alpha_max_at])).pressure_angle[0])
        return _angle_row(name, deg(rd.alpha_max_at), deg(_tied(rd.alpha_max_at, at, there, a)), 360.0)
    if name in ("rho_min_pitch", "rho_min_pitch_at"):
        r, at = exact_cam.min_convex_rho_pitch(cam)
        if name == "rho_min_pitch":
            return _plain(name, unit, rd.rho_min / an.scales["l"], an.scales["l"], r, size)
        there = float(exact_cam.profile(cam, np.array([rd.rho_min_at])).rho_pitch[0])
        return _angle_row(name, deg(rd.rho_min_at), deg(_tied(rd.rho_min_at, at, there, r)), 360.0)
    if name == "rho_min_actual":  # the working profile's sharpest convex bend: ρ_pitch − r_r, or read off a flat face
        f = cam.follower
        r_r = f.roller_radius if f.contact == "roller" else 0.0
        if f.contact == "flat":  # the profile's own curvature (r0 + s + s″ for a translating face)
            e = exact_cam.min_rho_actual(cam, EXACT_SAMPLES)[0]
        else:
            e = exact_cam.min_convex_rho_pitch(cam)[0] - r_r
        return _plain(name, unit, (rd.rho_min - r_r) / an.scales["l"], an.scales["l"], e, size)
    if name == "profile_deviation":
        dev = profile_deviation(cam, an.profile.actual)
        return Row(name, unit, dev / an.scales["l"], an.scales["l"], dev, 0.0, dev / size)
    if name == "h":
        if ang:  # a rocker's swing ψ_max, in degrees as the check reports every angle
            drawn_mm = float(np.max(an.s)) / an.scales["s"]
            return Row(name, "deg", drawn_mm, deg(an.scales["s"]), drawn_mm * deg(an.scales["s"]),
                       deg(cam.program.stroke), abs(float(np.max(an.s)) - cam.program.stroke) / cam.program.stroke)
        return _plain(name, "m", float(np.max(an.s)) / an.scales["s"], an.scales["s"],
                      cam.program.stroke, cam.program.stroke)
    if name in ("s0", "psi0"):
        return _start(an, name)
    if name == "r0_min":
        e = exact_cam.min_base_radius(cam, cast(float, cam.alpha_permissible))  # asked for only with it (scene)
        g = _graphical_r0_min(cam, cast(float, cam.alpha_permissible), an.step)
        return _plain(name, unit, g / an.scales["l"], an.scales["l"], e, size)
    # v_max, a_max, j_max and where: read off the diagrams at the divisions vs the exact law
    q = name.split("_")[0]
    order = {"v": 1, "a": 2, "j": 3}[q]
    ext = maxima(cam.program, cam.omega)[q]
    vals = np.abs(displacement(cam.program, delta, order)) * cam.omega ** order
    k = int(np.flatnonzero(vals >= vals.max() * (1 - 1e-9))[0])  # the first division where it is reached
    if name.endswith("_at"):
        return _angle_row(name, deg(delta[k]), deg(ext.at), 360.0)
    scale = an.scales.get(q, 1.0)
    unit = {"v": "rad/s", "a": "rad/s²", "j": "rad/s³"}[q] if ang else unit
    return _plain(name, unit, vals[k] / scale, scale, ext.value, ext.value)


#: Values read off the drawing at the divisions, and how their error arises; s@δ and h are exact
#: ordinates, and the law's v, a, j maxima are read at the divisions off closed forms (exact where the
#: maximum falls on a division, which the finer drawings show).
_SOURCES = {"alpha_max": READING, "alpha_max_at": READING, "rho_min_pitch": READING, "rho_min_pitch_at": READING,
            "rho_min_actual": READING, "r0_min": READING, "profile_deviation": DISCRETISATION,
            "v_max": READING, "v_max_at": READING, "a_max": READING, "a_max_at": READING, "j_max": READING,
            "j_max_at": READING}


#: A reading off by more than this (relative, as estimated or against the exact value) is warned of.
UNRESOLVED = 0.1


def _finer(an: CamAnalysis, factor: int) -> CamAnalysis:
    """The same drawing redone with ``factor`` times the divisions (nested: every division stays one)."""
    cam = an.cam
    step = an.step / factor
    delta = divisions(cam, step, breakpoints(cam.program))
    s = displacement(cam.program, delta)
    if an.drawn is None:
        return replace(an, delta=delta, s=s, step=step)
    drawn = draw_profile(cam, delta, s)
    return replace(an, delta=delta, s=s, drawn=drawn, reading=read_drawing(cam, drawn), step=step)


#: The one row whose value is itself a distance to the exact solution (the drawn profile's largest
#: deviation from the exact working profile): its estimate is that distance, so the tests that
#: judge estimates against the true error leave it out.
PROFILE_DEVIATION = "profile_deviation"


def _estimated(an: CamAnalysis, row: Row) -> Row:
    """A row read off the drawing with the error the drawing itself estimates: the same reading at
    2N and 4N divisions (graphmech.accuracy.estimate_from_three), relative to the row's own
    denominator (an angle's span, or the drawing's size).

    The reading at 8N is a floor under it: a smallest ρ next to a pitch-curve corner, or the place
    of a flat maximum, can read the same at N, 2N and 4N (the base circle's r0, the same division)
    before the finer divisions resolve it — the three would then claim no error at all."""
    name = row.name
    source = READING if name.startswith("alpha@") else _SOURCES.get(name)
    if source is None:
        return row
    n = round(math.tau / an.step)
    basis = f"{n} divisions of {math.degrees(an.step):.6g}°"
    try:
        if not an.finer:  # drawn once for every row
            an.finer = tuple(_finer(an, k) for k in (2, 4, 8))
        v2, v4, v8 = read = tuple(_row(f, name).graphical for f in an.finer)
    except (ArithmeticError, ValueError) as e:  # the finer drawing fails where this one did not
        an.warnings.append(f"{name}: no error estimate — the drawing at {2 * n}…{8 * n} divisions fails ({e})")
        return replace(row, error_source=source, basis=basis)
    v1 = row.graphical
    if name.endswith("_at"):  # places round the turn: 358° and 2° are 4° apart
        v2, v4, v8 = (v1 + (v - v1 + 180.0) % 360.0 - 180.0 for v in (v2, v4, v8))
    est = max(estimate_from_three(v1, v2, v4), abs(v1 - v8))
    if name == PROFILE_DEVIATION:  # measured against the exact profile, it is its own error: the finer
        est = max(est, abs(v1))  # drawings alone miss the buffer's floor (≈ 4e-6 of the size at 0.1°)
    if row.unit == "deg" and row.drawn_mm is None:
        d = 360.0 if name.endswith("_at") else 90.0
    elif name in ("v_max", "a_max", "j_max"):
        d = abs(row.graphical)
    else:
        size = float(np.max(np.hypot(*an.drawn.pitch.T))) if an.drawn is not None else an.cam.base_radius
        d = max(abs(row.graphical), size)
    if name.split("_")[0] in ("v", "a", "j") and relative(est, d) <= 1e-12:
        return row  # the maximum is on a division: the closed form's value, a construction
    if max(relative(est, d), row.rel_error) > UNRESOLVED:
        u = "°" if row.unit == "deg" else f" {row.unit}"
        finer = ", ".join(f"{v:.4g}" for v in read)
        an.warnings.append(f"{name} read at {basis} is {v1:.4g}{u}, at {2 * n}, {4 * n}, {8 * n} divisions {finer}, "
                           f"exact {row.exact:.4g}{u}: the drawing does not resolve it (it changes within a "
                           "division), take a finer step")
    return row.estimated(source, relative(est, d), basis)


def _tied(drawn_at: float, exact_at: float, exact_there: float, extreme: float) -> float:
    """Where the exact extreme is, as compared with the drawing's reading: where the extreme is
    reached on a whole stretch (a dwell on the base circle) or at several places (equal peaks),
    the drawn place is one of them and is right — not an error of 60°."""
    return drawn_at if abs(exact_there - extreme) <= 1e-9 * abs(extreme) else exact_at


def _start(an: CamAnalysis, name: str) -> Row:
    """s₀ off the drawing — B₀'s distance along the axis from the foot of the perpendicular from O
    (the axis is +y at δ = 0, its foot (e, 0)) — or a rocker's ψ₀ = ∠OA₀B₀ with A₀ at (a, 0); s0
    is a rocker's ψ₀ too, as s@45 is its ψ."""
    cam, b0 = an.cam, an.profile.pitch[0]
    if _angular(cam):
        a = cast("OscillatingFollower", cam.follower).pivot_distance
        psi = math.atan2(abs(b0[1]), a - b0[0]) - float(an.s[0])  # ∠ between A→O (−x) and A→B₀
        return _angle_row(name, math.degrees(psi), math.degrees(exact_cam.initial_rocker_angle(cam)), 90.0)
    f = cast("TranslatingFollower", cam.follower)
    r0 = cam.base_radius
    exact = r0 if f.contact == "flat" else math.sqrt(r0 * r0 - f.offset * f.offset)
    s0 = float(b0[1]) - float(an.s[0])
    return _plain(name, "m", s0 / an.scales["l"], an.scales["l"], exact, r0)


def _plain(name: str, unit: str, drawn_mm: float, scale: float, exact: float, size: float) -> Row:
    g = drawn_mm * scale
    return Row(name, unit, float(drawn_mm), float(scale), float(g), float(exact),
               abs(g - exact) / max(abs(exact), abs(size), 1e-300))


def _angle_row(name: str, g: float, e: float, span: float) -> Row:
    err = abs((g - e + 180.0) % 360.0 - 180.0) / span
    return Row(name, "deg", None, 1.0, float(g), float(e), err)


def judge_cam(an: CamAnalysis, precision_mm: float | None = None) -> list[Verdict]:
    """Hand readings of a cam drawing (``alpha_max = 34``, ``rho_min_pitch = 0.029``) against the exact values."""
    prec = precision_mm if precision_mm is not None else an.scene.precision_mm
    out, problems = [], []
    for key, name, value in measured_entries(an.scene, an.extra_measured):
        why = reading_problem(an.cam, name)  # s@45, psi@45, alpha@45 as find takes them
        if name in _force_names() and an.scene.problem.forces is None:
            why = f"{name} needs [cam.forces]: the position, the load and the friction"
        if why is None and name not in CAM_QUANTITIES and name not in _force_names() and not name.startswith(AT_DIVISION):
            why = f"unknown cam quantity {name!r}"
        if why is not None:
            problems.append((key, why))
            continue
        try:
            row = _row(an, name)
        except SceneError as e:  # not a division of this drawing: said under the measured key
            problems += [(key, reason) for _, reason in e.problems]
            continue
        if row.unit == "N·m":  # the cam's moment: R12 read at μF times its lever about O
            from graphmech.exact.cam_forces import position

            lever = float(np.hypot(*position(an.cam, cast("CamFriction", an.scene.problem.forces)).K))
            tol = prec * an.scales["F"] * lever
        elif row.unit == "deg" and row.drawn_mm is None:  # an angle on the profile; a diagram's ψ is read at μψ
            tol = math.degrees(prec / max(an.cam.base_radius / an.scales["l"], prec))
        else:
            tol = prec * row.scale
        out.append(Verdict(name, value, row.exact, tol, abs(value - row.exact) <= tol, row.unit))
    if problems:
        raise SceneError(problems, an.scene.source)
    return out
