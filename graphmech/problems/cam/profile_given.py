"""A cam scene that gives the cam's profile (``[cam.profile]``) instead of its motion law: the
analysis by inversion (the reverse of the design), checked against the closed form.

The follower's displacement s(δ) (a rocker's ψ(δ)), the pressure angle, its velocity, the base
circle, the rise and, between named contacts (``[[cam.contact]]``, the book's E and F), the cam
angle turned and the displacement: each drawn by :class:`graphmech.methods.cam_analysis.Inversion`
and computed by :mod:`graphmech.exact.cam_profile`.
"""
from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any, cast

import numpy as np

from graphmech.errors import NoSolution, SceneError
from graphmech.exact import cam_profile as exact
from graphmech.mechanisms.cam import OscillatingFollower, TranslatingFollower
from graphmech.mechanisms.cam_profile import (
    EccentricDisc,
    GivenCam,
    GivenContact,
    PointsProfile,
    shape_problem,
)
from graphmech.methods.cam_analysis import (
    DRAWN_CHORDS,
    DrawnPosition,
    Inversion,
    PolylineInversion,
    inversion,
)
from graphmech.problems.judging import Row, Verdict, close_names, measured_entries
from graphmech.problems.reader import (
    LINKAGE_KEYS,
    MAX_TABLE_POINTS,
    Reader,
    Scene,
    compact,
    raise_sorted,
    read_header,
    read_measured,
    read_scales,
    read_tail,
)
from graphmech.scales import round_scale

#: What a given-profile scene may show: the inversion drawing and the s–δ diagram.
GIVEN_SHOW_CHOICES = ("profile", "displacement")
#: The find names without a position.
GIVEN_QUANTITIES = {"h": "m", "r0": "m", "r0_actual": "m", "alpha_max": "deg", "alpha_max_at": "deg"}
#: The names read at a position: a cam angle in degrees (s@45) or a contact's name (alpha@F).
GIVEN_AT = ("s", "psi", "alpha", "v")
#: The names read between two contacts: delta@E-F, s@E-F, psi@E-F.
GIVEN_BETWEEN = ("delta", "s", "psi")
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_']*")
#: The inversion's divisions for the s–δ table when the scene gives no step, rad.
GIVEN_STEP_DEFAULT = math.radians(15.0)
#: The fewest points a profile may be given by.
MIN_POINTS = 5
#: The most contacts a scene may name.
MAX_CONTACTS = 26


@dataclass(frozen=True)
class GivenCamScene:
    """The cam of a scene with ``[cam.profile]``: the cam and the s–δ table's division step (rad)."""

    cam: GivenCam
    step: float = GIVEN_STEP_DEFAULT


def _mm(x: float) -> str:
    return f"{compact(float(f'{x * 1e3:.6g}'))} mm"


def _check_fit(r: Reader, cam: GivenCam) -> None:
    """The follower must rest on the disc all round: what the kind checks against r0 for a
    motion law, here against the disc's nearest and farthest circles r0 and r_max about O."""
    f = cam.follower
    r0, r_max = exact.radii(cam)
    if isinstance(f, TranslatingFollower):
        if f.contact != "flat" and not abs(f.offset) < r0:
            r.problem(r.at("follower") + ".offset", f"|e| = {_mm(abs(f.offset))} is not smaller than the base radius "
                                                   f"r0 = {_mm(r0)} (the disc's nearest pitch radius): the axis misses it")
        return
    a = f.pivot_distance
    if f.contact == "flat":
        if not r_max < a:
            r.problem(r.at("follower") + ".pivot_distance",
                      f"the disc reaches {_mm(r_max)} from O, beyond the pivot a = {_mm(a)}: the face through it cannot "
                      "rest on the disc all round")
        return
    if not (abs(a - f.arm) < r0 and r_max < a + f.arm and r_max < a):
        r.problem(r.at("follower") + ".arm",
                  f"the arm cannot rest on the disc all round: its reach |a − l| … a + l must hold the pitch circle's "
                  f"r0 = {_mm(r0)} … {_mm(r_max)}, and the pivot a = {_mm(a)} lie beyond {_mm(r_max)}")


def _read_points(p: Reader) -> PointsProfile | None:
    """``points``: [[x, y], …] with a length unit, at least 5, the spline through them convex round O."""
    given = p.quantity("points", "length")
    p.ignore("radius", "centre")
    if given is None:
        return None
    path, raw = p.at(given.key), given.value
    if not isinstance(raw, list) or not MIN_POINTS <= len(raw) <= MAX_TABLE_POINTS:
        p.problem(path, f"must be a list of {MIN_POINTS} … {MAX_TABLE_POINTS} points [x, y] round O")
        return None
    pts = [p.numbers(v, f"{path}[{j}]", 2, shape="[x, y]") for j, v in enumerate(raw)]
    if any(q is None for q in pts):
        return None
    xy = tuple((given.si(q[0]) + 0.0, given.si(q[1]) + 0.0) for q in cast("list[list[float]]", pts))
    if len(set(xy)) < len(xy):
        p.problem(path, "a point is given twice: the curve runs through each once")
        return None
    arr = np.asarray(xy)
    chords = np.hypot(*np.diff(np.vstack([arr, arr[:1]]), axis=0).T)
    run = np.concatenate([[0.0], np.cumsum(chords)])
    if not (np.isfinite(run).all() and np.all(np.diff(run) > 0.0)):  # 1e300 beside 30 mm: chords lost
        p.problem(path, f"the points lie {float(np.max(np.abs(arr))) * 1e3:.3g} mm from O and {float(np.min(chords)) * 1e3:.3g} mm "
                        "from each other: a chord that small is lost beside the curve's length in double precision")
        return None
    profile = PointsProfile(xy)
    why = shape_problem(profile)
    if why:
        p.problem(path, why)
        return None
    return profile


def _read_profile(r: Reader) -> EccentricDisc | PointsProfile | None:
    p = r.table_at("profile", required=True)
    if p is None:
        return None
    kind = p.string("type", choices=("eccentric_disc", "points"), required=True)
    if kind == "points":
        out = _read_points(p)
        p.finish()
        return out
    p.ignore("points")
    radius = p.value("radius", "length", positive=True)
    centre = p.pair("centre")
    p.finish()
    if radius is None or centre is None:
        return None
    if not math.hypot(*centre) < radius.si:
        p.problem(p.at("centre"), f"the turning centre O must lie inside the disc: |OC| = "
                                  f"{radius.text(math.hypot(*centre))} is not below R = {radius.text()}")
        return None
    return EccentricDisc(radius.si, (centre[0] + 0.0, centre[1] + 0.0))


def _read_contacts(r: Reader) -> tuple[GivenContact, ...]:
    if "contact" not in r.table:
        return ()
    readers = r.tables_at("contact")
    if len(readers) > MAX_CONTACTS:
        r.problem(r.at("contact"), f"too many contacts ({len(readers)} > {MAX_CONTACTS})")
        return ()
    out: list[GivenContact] = []
    for c in readers:
        name = c.string("name", required=True)
        polar = c.value("polar", "angle", required=False)
        delta = c.value("delta", "angle", required=False)
        if name is not None and not _NAME.fullmatch(name):
            c.problem(c.at("name"), f"{name!r}: a contact's name is a letter and letters or digits (E, F, B1)")
            name = None
        elif name is not None and any(o.name == name for o in out):
            c.problem(c.at("name"), f"{name!r} is named twice")
            name = None
        if (polar is None) == (delta is None) and c.present("polar") is None and c.present("delta") is None:
            c.problem(c.at("polar"), "missing: give the contact point's polar angle about O in the cam frame "
                                     "(polar_deg = 120) or the cam angle of the contact (delta_deg = 30)")
        elif polar is not None and delta is not None:
            c.problem(c.at("delta"), "give polar or delta, not both")
        c.finish()
        if name is not None and (polar is not None or delta is not None):
            out.append(GivenContact(name, None if polar is None else polar.si % math.tau,
                                    None if delta is None else delta.si % math.tau))
    return tuple(out)


def parse_given_scene(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]
                      ) -> Scene[GivenCamScene]:
    """The rest of :func:`graphmech.scene.parse_scene` for a cam scene with ``[cam.profile]``."""
    from graphmech.problems.cam.scene import read_follower

    problems = top.problems
    title, show, find = read_header(top, GIVEN_SHOW_CHOICES, ("profile",))
    follower_table = cast("dict[str, Any]", data["cam"]).get("follower")
    kind = follower_table.get("type") if isinstance(follower_table, dict) else None
    scales = read_scales(top, cam=True, follower=kind if kind in ("translating", "oscillating") else None)
    for key in LINKAGE_KEYS:
        if key in data:
            top.used.add(key)
            top.problem(key, f"[{key}] belongs to a linkage scene; this is a cam scene ([cam])")
    r = cast(Reader, top.table_at("cam", required=True))  # poses_given: [cam] is a table
    rotation = r.string("rotation", choices=("ccw", "cw"), required=True)
    omega = r.value("omega", "omega", positive=True)
    step = r.value("step", "angle", required=False, positive=True)
    if step is not None and not math.radians(0.1) <= step.si <= math.radians(90.0):
        r.problem(step.path, f"must lie between 0.1° and 90°, not {step.text()}")
    for key in ("base_radius", "program", "segment", "alpha_permissible", "roller_circles"):
        if key in r.table or any(k.startswith(key + "_") for k in r.table):
            r.ignore(key)
            r.problem(r.at(key), "the profile is given ([cam.profile]): the base circle and the motion are what "
                                 "the analysis finds, leave this out")
    disc = _read_profile(r)
    follower, _, _, bad = read_follower(r, None)
    contacts = _read_contacts(r)
    r.finish()
    cam = None
    if disc is not None and follower is not None and not bad and rotation is not None and omega is not None:
        cam = GivenCam(disc, follower, 1 if rotation == "ccw" else -1, omega.si, contacts)
        _check_fit(r, cam)
    measured = read_measured(top, None, cam=True)
    precision, page = read_tail(top)
    if problems or cam is None:
        raise_sorted(problems, data, order, "cam", source)
    return Scene(source=source, title=title, show=show, find=find, scales=scales, measured=measured,
                 precision_mm=precision, page=page, kind="cam",
                 problem=GivenCamScene(cam, GIVEN_STEP_DEFAULT if step is None else step.si))


# ---------------------------------------------------------------------------------------- analysis


@dataclass
class GivenCamAnalysis:
    scene: Scene[GivenCamScene]
    cam: GivenCam
    inversion: Inversion
    scales: dict[str, float]
    stated: set[str]
    contacts: dict[str, tuple[float, float]]  # name → (δ drawn, δ exact), rad
    positions: list[DrawnPosition]  # the divisions of the s–δ table
    rows: list[Row] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    extra_measured: tuple[tuple[str, float], ...] = ()

    def scale_notes(self) -> list[str]:
        from graphmech.problems.cam.figures import scale_note

        angular = isinstance(self.cam.follower, OscillatingFollower)
        return [scale_note(k, v, angular) + ("" if k in self.stated else " (chosen)") for k, v in self.scales.items()]


def _angular(cam: GivenCam) -> bool:
    return isinstance(cam.follower, OscillatingFollower)


def _contact_deltas(scene: Scene[GivenCamScene], inv: Inversion) -> dict[str, tuple[float, float]]:
    cam = scene.problem.cam
    out: dict[str, tuple[float, float]] = {}
    problems = []
    for k, c in enumerate(cam.contacts):
        if c.delta is not None:
            out[c.name] = (c.delta, c.delta)
            continue
        polar = cast(float, c.polar)
        try:
            out[c.name] = (inv.contact(polar, c.name), exact.contact_delta(cam, polar, c.name))
        except NoSolution as e:
            problems.append((f"cam.contact[{k}].polar", str(e)))
    if problems:
        raise SceneError(problems, scene.source)
    return out


def analyse_given(scene: Scene[GivenCamScene], extra_measured: tuple[tuple[str, float], ...] = ()) -> GivenCamAnalysis:
    """The inversion at the named contacts and the divisions, each row against the closed form."""
    gs = scene.problem
    cam = gs.cam
    inv = inversion(cam)
    n = max(1, round(math.tau / gs.step))
    positions = [inv.at(math.tau * k / n) for k in range(n + 1)]
    stated: set[str] = {k for k in ("l", "s", "phi") if k in scene.scales}
    reach = exact.radii(cam)[1] + cam.roller
    if isinstance(cam.follower, OscillatingFollower):
        reach = max(reach, cam.follower.pivot_distance + cam.follower.arm)
    scales = {"l": float(scene.scales["l"]) if "l" in stated else round_scale(2.2 * reach / 150.0)}
    # the s–δ diagram: the rise some 40 mm high, a turn some 120 mm long, unless the scene says
    h = exact.rise(cam)
    if "s" in stated:
        scales["s"] = float(scene.scales["s"])
    elif isinstance(cam.follower, OscillatingFollower):  # books give a swing's scale in degrees per mm
        scales["s"] = math.radians(round_scale(math.degrees(h) / 40.0)) if h > 0 else math.radians(1.0)
    else:
        scales["s"] = round_scale(h / 40.0) if h > 0 else scales["l"]
    scales["phi"] = float(scene.scales["phi"]) if "phi" in stated else math.radians(3.0)
    an = GivenCamAnalysis(scene, cam, inv, scales, stated, _contact_deltas(scene, inv), positions,
                          extra_measured=tuple(extra_measured))
    problems = []
    for k, name in enumerate(scene.find):
        why = _unknown(an, name)
        if why:
            problems.append((f"find[{k}]", why))
    if problems:
        raise SceneError(problems, scene.source)
    an.rows = [_row(an, name) for name in scene.find]
    if isinstance(cam.profile, PointsProfile):
        _estimate(an)
    an.rows = [_divisions_estimate(an, row) if row.name.startswith("alpha_max") else row for row in an.rows]
    return an


def _divisions_estimate(an: GivenCamAnalysis, row: Row) -> Row:
    """The largest pressure angle read at the divisions, with the error the same reading at 2, 4
    and 8 times the divisions shows (the last a floor, as the motion-law cam's readings have)."""
    from dataclasses import replace as copy

    from graphmech.accuracy import READING, estimate_from_three

    n = len(an.positions) - 1
    read = []
    for k in (2, 4, 8):
        finer = copy(an, positions=[an.inversion.at(math.tau * j / (k * n)) for j in range(k * n + 1)])
        read.append(_row(finer, row.name).graphical)
    v1 = row.graphical
    if row.name.endswith("_at"):  # places round the turn: 358° and 2° are 4° apart
        read = [v1 + (v - v1 + 180.0) % 360.0 - 180.0 for v in read]
    est = max(estimate_from_three(v1, read[0], read[1]), abs(v1 - read[2]))
    span = 360.0 if row.name.endswith("_at") else 90.0
    return row.estimated(READING, est / span, f"{n} divisions of {360.0 / n:.6g}°")


def _estimate(an: GivenCamAnalysis) -> None:
    """A drawn profile's readings with their own error: the same rows off the curve drawn with 2
    and 4 times the chords (graphmech.accuracy.estimate_from_three), relative as the row's error is."""
    from dataclasses import replace as copy

    from graphmech.accuracy import DISCRETISATION, estimate_from_three

    finer = []
    for k in (2, 4):
        inv = PolylineInversion(an.cam, k * DRAWN_CHORDS)
        finer.append(copy(an, inversion=inv, contacts=_contact_deltas(an.scene, inv)))
    rows = []
    for row in an.rows:
        g2, g4 = (_row(f, row.name).graphical for f in finer)
        est = estimate_from_three(row.graphical, g2, g4)
        rel = row.rel_error * est / abs(row.graphical - row.exact) if row.graphical != row.exact else 0.0
        rows.append(row.estimated(DISCRETISATION, rel if math.isfinite(rel) else 0.0,
                                  f"the curve drawn as {DRAWN_CHORDS} chords"))
    an.rows = rows


def _where(an: GivenCamAnalysis, at: str) -> tuple[float, float] | None:
    """(δ drawn, δ exact) of a position written as a cam angle in degrees or a contact's name."""
    if at in an.contacts:
        return an.contacts[at]
    try:
        d = math.radians(float(at))
    except ValueError:
        return None
    return (d % math.tau, d % math.tau) if math.isfinite(d) else None


def _unknown(an: GivenCamAnalysis, name: str) -> str | None:
    """Why a find name is not one this scene answers, or None."""
    names = list(an.contacts)
    if name == "alpha_max_at" and an.cam.follower.contact == "flat":
        return "alpha_max_at has no meaning for a flat face: its pressure angle is 0 all round"
    if name in GIVEN_QUANTITIES:
        return None
    if "@" not in name:
        return f"unknown quantity {name!r} for a given profile{close_names(name, [*GIVEN_QUANTITIES, 's@45'])}"
    head, at = name.split("@", 1)
    ang = _angular(an.cam)
    if head == "psi" and not ang:
        return f"{name!r}: a translating follower's displacement is s@… (psi@… is a rocker's)"
    if "-" in at and head in GIVEN_BETWEEN:
        e, f = at.split("-", 1)
        bad = [c for c in (e, f) if c not in an.contacts]
        if bad:
            return f"{name!r}: no contact named {bad[0]!r} (the scene names {', '.join(names) or 'none'})"
        return None
    if head in GIVEN_AT and _where(an, at) is not None:
        return None
    return (f"{name!r}: write {head if head in GIVEN_AT else 's'}@<cam angle in degrees> or @<contact> "
            f"({', '.join(names) or 'no contacts named'}), or delta@E-F between two contacts")


def _row(an: GivenCamAnalysis, name: str) -> Row:
    cam, inv = an.cam, an.inversion
    mu = an.scales["l"]
    ang = _angular(cam)
    deg = math.degrees
    if name == "h":
        if ang:
            return _angle_row(name, deg(inv.rise()), deg(exact.rise(cam)), 90.0)
        return _length_row(name, inv.rise(), exact.rise(cam), mu, cam.size)
    if name in ("alpha_max", "alpha_max_at"):  # read off the divisions drawn, as the book marks it
        k = max(range(len(an.positions)), key=lambda j: an.positions[j].alpha)
        g_at, (x, x_at) = an.positions[k], exact.max_pressure_angle(cam)
        if name == "alpha_max":
            return _angle_row(name, deg(g_at.alpha), deg(x), 90.0)
        return _angle_row(name, deg(g_at.delta), deg(x_at), 360.0)
    if name in ("r0", "r0_actual"):
        f = cam.follower
        less = f.roller_radius if name == "r0_actual" and f.contact == "roller" else 0.0
        return _length_row(name, inv.r0 - less, exact.radii(cam)[0] - less, mu, cam.size)
    head, at = name.split("@", 1)
    if "-" in at and head in GIVEN_BETWEEN:
        e, f2 = at.split("-", 1)
        (ge, xe), (gf, xf) = an.contacts[e], an.contacts[f2]
        if head == "delta":  # turned in the cam's sense, 0 … 360°
            return _angle_row(name, deg((gf - ge) % math.tau), deg((xf - xe) % math.tau), 360.0)
        g = inv.at(gf).s - inv.at(ge).s
        x = float(exact.displacement(cam, xf) - exact.displacement(cam, xe))
        return _angle_row(name, deg(g), deg(x), 90.0) if ang else _length_row(name, g, x, mu, cam.size)
    gd, xd = cast("tuple[float, float]", _where(an, at))
    p = inv.at(gd)
    if head == "alpha":
        return _angle_row(name, deg(p.alpha), deg(float(exact.pressure_angle(cam, xd))), 90.0)
    if head == "v":
        x = cam.omega * float(exact.rate(cam, xd))
        unit = "rad/s" if ang else "m/s"
        size = cam.omega * (1.0 if ang else cam.size)
        return Row(name, unit, None, 1.0, p.v, x, abs(p.v - x) / size)
    x = float(exact.displacement(cam, xd))
    return _angle_row(name, deg(p.s), deg(x), 90.0) if ang else _length_row(name, p.s, x, mu, cam.size)


def _length_row(name: str, g: float, x: float, mu: float, size: float) -> Row:
    return Row(name, "m", g / mu, mu, float(g), float(x), abs(g - x) / max(abs(x), size))


def _angle_row(name: str, g: float, x: float, span: float) -> Row:
    return Row(name, "deg", None, 1.0, float(g), float(x), abs((g - x + 180.0) % 360.0 - 180.0) / span)


def judge_given(an: GivenCamAnalysis) -> list[Verdict]:
    """Hand readings against the exact values: a length within the drawing precision × μl, an
    angle within the precision seen from the disc's radius."""
    prec = an.scene.precision_mm
    out, problems = [], []
    for key, name, value in measured_entries(an.scene, an.extra_measured):
        why = _unknown(an, name)
        if why:
            problems.append((key, why))
            continue
        row = _row(an, name)
        if row.unit == "deg":
            tol = math.degrees(prec / max(an.cam.size / an.scales["l"], prec))
        elif row.unit in ("m/s", "rad/s"):
            tol = abs(row.exact) * 0.02 + 1e-12  # a velocity read off a velocity polygon: 2 %
        else:
            tol = prec * row.scale
        out.append(Verdict(name, value, row.exact, tol, abs(value - row.exact) <= tol, row.unit))
    if problems:
        raise SceneError(problems, an.scene.source)
    return out


def given_extras(an: GivenCamAnalysis) -> dict[str, Any]:
    """``check --json``'s table of the divisions (δ, s or ψ, α, v, drawn and exact) and the contacts."""
    cam, ang = an.cam, _angular(an.cam)
    rows = []
    for k, p in enumerate(an.positions):
        s_x = float(exact.displacement(cam, p.delta))
        rows.append({"division": k, "delta_deg": math.degrees(p.delta),
                     ("psi_deg" if ang else "s"): math.degrees(p.s) if ang else p.s,
                     ("psi_exact_deg" if ang else "s_exact"): math.degrees(s_x) if ang else s_x,
                     "alpha_deg": math.degrees(p.alpha),
                     "alpha_exact_deg": math.degrees(float(exact.pressure_angle(cam, p.delta))),
                     "v": p.v, "v_exact": cam.omega * float(exact.rate(cam, p.delta))})
    contacts = {n: {"delta_deg": math.degrees(g), "delta_exact_deg": math.degrees(x)}
                for n, (g, x) in an.contacts.items()}
    return {"divisions": rows, "contacts": contacts}


def given_steps(scene: Scene[GivenCamScene]) -> list[str]:
    """The construction protocol of a given cam's analysis by inversion, one line per step."""
    an = analyse_given(scene, ())
    cam, inv, mu = an.cam, an.inversion, an.scales["l"]
    f = cam.follower
    ang = _angular(cam)
    r_r = cam.roller
    out = []
    if isinstance(cam.profile, PointsProfile):
        out.append(f"draw the curve through the {len(cam.profile.points)} given points at μl = {mu:g} m/mm "
                   f"(a French curve; read here as {DRAWN_CHORDS} chords)")
        if r_r:
            out.append(f"lay r_r = {_mm(r_r)} off along the curve's normals: the pitch (theoretical) curve")
    else:
        out.append(f"draw the disc R = {_mm(cam.disc.radius)} about its centre C, |OC| = {_mm(cam.disc.eccentricity)} "
                   f"from the turning centre O, at μl = {mu:g} m/mm")
        if r_r:
            out.append(f"draw the pitch (theoretical) circle R + r_r = {_mm(cam.pitch_radius())} about C")
    out.append(f"draw the base circle r0 = {_mm(inv.r0)} about O through the {'profile' if f.contact == 'flat' else 'pitch curve'}'s "
               f"nearest point, and the circle {_mm(inv.r_max)} through its farthest")
    step = 360.0 / (len(an.positions) - 1)
    if isinstance(f, TranslatingFollower):
        if f.offset:
            out.append(f"draw the offset circle e = {_mm(abs(f.offset))} about O")
        what = ("the face ⟂ the axis touches the profile" if f.contact == "flat"
                else "the axis cuts the pitch curve at the follower point B_k")
        out.append(f"turn the follower back against the cam (反转法) every {step:g}°: at each position {what}; "
                   "s_k is read along the axis from the base circle")
    else:
        what = ("the face through A_k touches the profile (the tangent from A_k)" if f.contact == "flat"
                else f"the arm l = {_mm(f.arm)} about A_k cuts the pitch curve at B_k")
        out.append(f"draw the circle of the pivots a = {_mm(f.pivot_distance)} about O; turn the pivot back against "
                   f"the cam (反转法) every {step:g}° to A_k: {what}; ψ_k = ∠OA_kB_k − ψ0 is read at A_k")
    for name, (g, _) in an.contacts.items():
        c = next(x for x in cam.contacts if x.name == name)
        if c.polar is None:
            out.append(f"contact {name} at δ = {math.degrees(g):.6g}° (given)")
            continue
        out.append(f"contact {name}: the ray from O at {math.degrees(c.polar):.6g}° cuts the profile at {name}; "
                   f"the follower turned back through {'it' if f.contact != 'roller' else 'the pitch point on its normal'} "
                   f"stands at δ_{name} = {math.degrees(g):.6g}°")
    for row in an.rows:
        out.append(f"read {row.name} = {row.graphical:.6g} {row.unit} (exact {row.exact:.6g})")
    out.append("the s–δ diagram: each s_k as an ordinate at δ_k" if not ang else
               "the ψ–δ diagram: each ψ_k as an ordinate at δ_k")
    return out
