"""Reading a disc-cam scene (``[cam]``): base circle, follower, motion program, division step."""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any, Mapping, cast

from graphmech.scales import phi_axis_problem
from graphmech.mechanisms.cam import (
    Contact,
    DiscCam,
    Follower,
    MotionProgram,
    OscillatingFollower,
    Law,
    Segment,
    SegmentKind,
    Sense,
    TranslatingFollower,
)
from graphmech.problems.reader import MAX_TABLE_POINTS
from graphmech.exact.cam_forces import CamFriction
from graphmech.problems.reader import (
    LINKAGE_KEYS,
    MISSING,
    Reader,
    Scene,
    Value,
    compact,
    not_for,
    raise_sorted,
    read_header,
    read_measured,
    read_scales,
    read_tail,
    type_name,
)


#: What a cam scene may show: the profile by inversion and the s–δ, v–δ, a–δ diagrams.
CAM_SHOW_CHOICES = ("profile", "displacement", "velocity", "acceleration")
#: What a cam scene shows when it does not say.
CAM_SHOW_DEFAULT = ("profile",)
#: The inversion's division step when a cam scene does not give one, rad (15°).
CAM_STEP_DEFAULT = math.radians(15.0)
#: The finest division step, rad (0.1°: at most 3600 divisions).
CAM_STEP_MIN = math.radians(0.1)
#: The coarsest division step, rad (90°).
CAM_STEP_MAX = math.radians(90.0)
#: The most segments a cam's motion program may have.
MAX_SEGMENTS = 100


@dataclass(frozen=True)
class CamScene:
    """The cam of a cam scene.

    Parameters
    ----------
    cam : DiscCam
        The cam, its follower and motion program, in SI (m, rad, rad/s).
    step : float
        The division step of the inversion, rad (default 15°); the inversion also divides
        at the joints of the motion program's segments.
    roller_circles : bool
        Draw the roller circles of the inversion (always False without a roller).
    """

    cam: DiscCam
    step: float
    roller_circles: bool = True
    #: The working profile's coordinates at every division, as handed in (``[cam] coordinates``):
    #: in ``check --json`` and as a table on the sheet.
    coordinates: bool = False
    #: The forces on the follower with friction at one position (``[cam.forces]``, problems.cam.forces).
    forces: CamFriction | None = None


_FOLLOWER_TYPES = ("translating", "oscillating")
_CONTACTS: tuple[Contact, ...] = ("knife", "roller", "flat")
_SEGMENT_KINDS: tuple[SegmentKind, ...] = ("rise", "return", "dwell")
_SENSES: tuple[Sense, ...] = ("opposite", "same")
#: The keys only one type of follower has.
_TRANSLATING_ONLY = ("offset",)
_OSCILLATING_ONLY = ("pivot_distance", "arm", "sense")


def _peek_follower(data: Mapping[str, Any]) -> str | None:
    """The follower's type if the scene states a valid one (to choose the scales' units)."""
    cam = data.get("cam")
    follower = cam.get("follower") if isinstance(cam, dict) else None
    kind = follower.get("type") if isinstance(follower, dict) else None
    return kind if kind in _FOLLOWER_TYPES else None


def _read_follower(
    cam: Reader, r0: Value | None
) -> tuple[Follower | None, str | None, str | None, bool]:
    """[cam.follower]: the follower, its type and contact (None when invalid), and whether
    anything in it was wrong."""
    r = cam.table_at(
        "follower",
        required=True,
        hint='add a [cam.follower] table (type = "translating" or "oscillating")',
    )
    if r is None:
        return None, None, None, True
    before = len(r.problems)
    kind = r.string("type", choices=_FOLLOWER_TYPES, required=True)
    contact = r.string("contact", choices=_CONTACTS, required=True)
    if kind is None:  # the keys belong to one type or the other: nothing to judge them by
        r.ignore("roller_radius", *_TRANSLATING_ONLY, *_OSCILLATING_ONLY)
        r.finish()
        return None, None, contact, True

    roller: Value | None = None
    if contact == "roller":
        roller = r.value("roller_radius", "length", positive=True)
        if roller is not None and r0 is not None and roller.si >= r0.si:
            r.problem(
                roller.path,
                f"r_r = {roller.text()} is not smaller than the base radius r0 = {r0.text()}: "
                "the working profile's base circle (r0 − r_r) would vanish",
            )
            roller = None
    elif contact is None:
        r.ignore("roller_radius")
    else:
        not_for(r, ["roller_radius"], f'only for contact = "roller" (this follower is {contact})')

    model: Follower | None = None
    # a value can be None without a problem here (a wrong [units] entry is reported there)
    complete = contact is not None and (contact != "roller" or roller is not None)
    if kind == "translating":
        offset = r.value("offset", "length", required=False)
        not_for(r, _OSCILLATING_ONLY, f"only for an oscillating follower (this one is {kind})")
        if offset is not None and r0 is not None and abs(offset.si) >= r0.si:
            r.problem(
                offset.path,
                f"|e| = {offset.text(abs(offset.si))} is not smaller than the base radius "
                f"r0 = {r0.text()}: the follower's axis misses the base circle",
            )
        e = 0.0 if offset is None else offset.si + 0.0
        complete = complete and (offset is not None or r.present("offset") is None)
        if complete and contact is not None and len(r.problems) == before:  # complete: contact given
            model = TranslatingFollower(e, contact, roller.si if roller else 0.0)
    else:
        a = r.value("pivot_distance", "length", positive=True)
        # a flat face lies along the rocker through A: it has no arm length (docs: not used)
        arm = r.value("arm", "length", positive=True, required=contact != "flat")
        sense = r.string("sense", choices=_SENSES, required=True)
        not_for(r, _TRANSLATING_ONLY, f"only for a translating follower (this one is {kind})")
        if contact == "flat":
            # the face is the line through the pivot A along the rocker, tangent to the base
            # circle at the start (ψ0 = asin(r0/a)); the arm length is not used
            if a is not None and r0 is not None and not r0.si < a.si:
                r.problem(
                    a.path,
                    f"a flat face through the pivot cannot touch the base circle: the base radius "
                    f"r0 = {r0.text()} must be smaller than pivot_distance a = {a.text()}",
                )
        elif a is not None and arm is not None and r0 is not None:
            near, far = abs(a.si - arm.si), a.si + arm.si
            if not near < r0.si < far:
                r.problem(
                    arm.path,
                    f"the arm cannot reach the base circle: r0 = {r0.text()} must lie between "
                    f"|a − l| = {r0.text(near)} and a + l = {r0.text(far)} "
                    f"(pivot_distance a = {a.text()}, arm l = {arm.text()})",
                )
        complete = complete and (arm is not None or (contact == "flat" and r.present("arm") is None))
        if complete and contact is not None and a is not None and sense is not None and len(r.problems) == before:
            model = OscillatingFollower(a.si, arm.si if arm else 0.0, contact, roller.si if roller else 0.0, sense)
    r.finish()
    return model, kind, contact, len(r.problems) != before


def _motion_path(
    path: str, segments: list[tuple[str, str]], stroke_path: str
) -> str:
    """A key path of :func:`graphmech.mechanisms.motion.validate` as the scene writes it."""
    if path == "program.stroke":
        return stroke_path
    m = re.fullmatch(r"program\.segments(?:\[(\d+)\](.*))?", path)
    if m is None:
        return "cam." + path
    if m.group(1) is None:
        return "cam.segment"
    i = int(m.group(1))
    if i >= len(segments):
        return "cam.segment"
    where, angle_path = segments[i]
    return angle_path if m.group(2) == ".angle" else where + m.group(2)


def _read_program(cam: Reader, follower: str | None) -> tuple[MotionProgram | None, bool]:
    """[cam.program] (the stroke) and [[cam.segment]]: the motion program; whether it had
    problems."""
    kind: str | None
    from graphmech.mechanisms.motion import LAWS, validate

    before = len(cam.problems)
    stroke: Value | None = None
    stroke_path = "cam.program.stroke"
    p = cam.table_at(
        "program",
        required=True,
        hint="add a [cam.program] table with the stroke (stroke_mm = 16, or an oscillating "
        "follower's stroke_deg = 25)",
    )
    if p is not None:
        if follower is None:
            p.ignore("stroke")
        else:
            kind = "length" if follower == "translating" else "angle"
            stroke = p.value("stroke", kind, positive=True)
            if stroke is not None:
                stroke_path = stroke.path
                if kind == "angle" and stroke.si >= math.pi:
                    p.problem(
                        stroke.path,
                        f"an oscillating follower's stroke (its swing) must be below 180°, "
                        f"not {stroke.text()}",
                    )
                    stroke = None
        p.finish("the segments are [[cam.segment]] tables, beside [cam.program]")

    if cam.raw("segment") is MISSING:
        cam.problem(
            cam.at("segment"),
            "missing: add [[cam.segment]] tables (kind = \"rise\", \"dwell\", \"return\" …) "
            "whose angles add up to 360°",
        )
        return None, True
    readers = cam.tables_at("segment")
    if len(readers) > MAX_SEGMENTS:
        cam.problem(cam.at("segment"), f"too many segments ({len(readers)} > {MAX_SEGMENTS})")
        return None, True
    intact = isinstance(cam.table["segment"], list) and len(readers) == len(cam.table["segment"])
    if not readers:
        if isinstance(cam.table["segment"], list) and not cam.table["segment"]:
            cam.problem(cam.at("segment"), "no segments: a program needs at least a rise and a return")
        return None, True

    segments: list[Segment] = []
    where: list[tuple[str, str]] = []  # each segment's path and its angle's path
    angles: list[Value | None] = []
    kinds_ok = True
    for s in readers:
        kind = s.string("kind", choices=_SEGMENT_KINDS, required=True)
        kinds_ok = kinds_ok and kind is not None
        angle = s.value("angle", "angle")
        if kind == "dwell" and angle is not None and angle.si == 0:
            # a 0° dwell is no dwell: the rise runs straight into the return (or the next rise)
            not_for(s, ["law"], "a dwell has no motion law: leave law out")
            s.finish()
            continue
        if angle is not None and angle.si <= 0:
            s.problem(angle.path, "must be > 0")
            angle = None
        angles.append(angle)
        law: Law | None = None
        table: tuple[tuple[float, float], ...] = ()
        if kind in ("rise", "return"):
            law = s.string("law", choices=LAWS, required=True)
        elif kind == "dwell":
            not_for(s, ["law"], "a dwell has no motion law: leave law out")
        else:
            s.ignore("law")
        if law == "table":
            table_value = s.raw(
                "table", required=True, hint="table = [[0, 0], [0.5, 0.3], [1, 1]] (fractions)"
            )
            parsed = _read_table(s, table_value) if table_value is not MISSING else None
            if parsed is None:
                law = None  # reported: do not let validate() repeat it
            else:
                table = parsed
        elif law is not None or kind == "dwell":
            not_for(s, ["table"], 'only with law = "table"')
        else:
            s.ignore("table")
        s.finish()
        segments.append(
            Segment(
                kind or "dwell",
                angle.si if angle is not None else 1.0,
                (law or "uniform") if kind in ("rise", "return") else None,
                table,
            )
        )
        where.append((s.path, angle.path if angle is not None else s.at("angle")))

    # The motion program's own rules (alternation, laws, tables), on the scene's paths.
    # Angles and the stroke are judged here, in the scene's units; a placeholder stands in
    # for whatever was already reported.
    program = MotionProgram(stroke.si if stroke is not None else 1.0, tuple(segments))
    if intact:
        for path, reason in validate(program):
            if path == "program.stroke" or path.endswith(".angle"):
                continue
            if reason.startswith("the angles add up"):
                continue
            if not kinds_ok and (path.endswith(".kind") or path == "program.segments"):
                continue
            cam.problem(_motion_path(path, where, stroke_path), reason)

    if intact and all(a is not None for a in angles):
        total = sum(a.si for a in cast("list[Value]", angles))  # all given (above)
        if abs(total - 2.0 * math.pi) > 1e-9:
            in_rad = any(a.unit == "rad" for a in cast("list[Value]", angles))
            rad = f" ({total:.9g} rad, not 2π = {2.0 * math.pi:.9g})" if in_rad else ""
            cam.problem(
                cam.at("segment"),
                f"the segment angles add up to {compact(float(f'{math.degrees(total):.9g}'))}°, "
                f"not 360°{rad}: together they are one turn of the cam",
            )
    ok = len(cam.problems) == before and stroke is not None
    return (program if ok else None), not ok


def _read_table(s: Reader, value: Any) -> tuple[tuple[float, float], ...] | None:
    """A ``table`` law's points [[x, y], …], fractions of the segment's angle and the stroke."""
    path = s.at("table")
    if not isinstance(value, list):
        s.problem(path, f"must be a list of [x, y] points, not {type_name(value)}")
        return None
    if len(value) > MAX_TABLE_POINTS:
        s.problem(path, f"too many points ({len(value)} > {MAX_TABLE_POINTS})")
        return None
    points = [s.numbers(v, f"{path}[{j}]", 2, shape="[x, y]") for j, v in enumerate(value)]
    valid = [pt for pt in points if pt is not None]
    if len(valid) < len(points):
        return None
    return tuple((pt[0], pt[1]) for pt in valid)


#: A base radius below this fraction of the cam's size is lost in round-off (r0 + s == s).
CAM_R0_MIN_REL = 1e-12


def _lost_in_round_off(r0: Value, f: Follower, stroke: float) -> list[tuple[str, str]]:
    """A base circle or a rocker position that double precision cannot tell from the degenerate
    one: the profile's normal, curvature and envelope then come out as 0/0."""
    size = stroke if isinstance(f, TranslatingFollower) else f.pivot_distance
    if r0.si < CAM_R0_MIN_REL * size:
        what = f"the stroke h = {r0.text(stroke)}" if isinstance(f, TranslatingFollower) else \
            f"pivot_distance a = {r0.text(size)}"
        return [(r0.path, f"r0 = {r0.text()} is lost in round-off beside {what}: the profile cannot be "
                          f"drawn (r0 ≥ {CAM_R0_MIN_REL:g} × that)")]
    if isinstance(f, TranslatingFollower) and stroke < CAM_R0_MIN_REL * r0.si:  # the other way round
        return [(r0.path, f"r0 = {r0.text()} leaves the stroke h = {r0.text(stroke)} in round-off: the profile "
                          f"is a circle to double precision (r0 ≤ h / {CAM_R0_MIN_REL:g})")]
    if isinstance(f, OscillatingFollower) and f.contact != "flat":
        a, l = f.pivot_distance, f.arm
        if not -1.0 < (a * a + l * l - r0.si * r0.si) / (2.0 * a * l) < 1.0:  # cos of ψ0, as the inversion finds it
            return [(r0.path, f"r0 = {r0.text()} meets the arm's reach |a − l| or a + l within round-off: "
                              "the rocker's start angle ψ0 cannot be found")]
    return []


def _read_cam(top: Reader) -> CamScene | None:
    """[cam]: the disc cam, its follower and motion program, and how to divide the inversion."""
    r = top.table_at("cam", required=True)
    if r is None:
        return None
    before = len(r.problems)
    r0 = r.value("base_radius", "length", positive=True)
    # a crank's word for it: say so (below) instead of "rotation: missing"
    rotation = r.string("rotation", choices=("ccw", "cw"), required="direction" not in r.table)
    omega = r.value("omega", "omega", positive=True)
    step = r.value("step", "angle", required=False, positive=True)
    if step is not None and not CAM_STEP_MIN <= step.si <= CAM_STEP_MAX:
        r.problem(
            step.path,
            f"must lie between 0.1° and 90°, not {step.text()}: "
            + ("too coarse to draw a profile" if step.si > CAM_STEP_MAX else "too many divisions"),
        )
    alpha = r.value("alpha_permissible", "angle", required=False, positive=True)
    if alpha is not None and not alpha.si < math.pi / 2:
        r.problem(alpha.path, f"must be below 90°, not {alpha.text()}")
    circles = r.flag("roller_circles")
    coordinates = r.flag("coordinates")  # the profile's table as handed in (problems.cam.coordinates)
    if "direction" in r.table and "direction" not in r.used:  # the crank's word for it
        r.used.add("direction")
        r.problem(r.at("direction"), 'a cam\'s sense is written rotation = "ccw" or "cw"')
    follower, kind, contact, follower_bad = _read_follower(r, r0)
    if circles is not None and contact is not None and contact != "roller":
        r.problem(r.at("roller_circles"), f'only for contact = "roller" (this follower is {contact})')
    program, program_bad = _read_program(r, kind)
    forces = None
    if "forces" in r.table:  # the follower's forces with friction (problems.cam.forces)
        from graphmech.problems.cam.forces import read_forces

        forces = read_forces(r)
        if forces is not None and (kind != "translating" or contact != "roller"):
            r.problem(r.at("forces"), "the forces with friction are found for a translating roller follower")
            forces = None
    if r0 is not None and follower is not None and program is not None:
        for path, why in _lost_in_round_off(r0, follower, program.stroke):
            r.problem(path, why)
    r.finish()
    if len(r.problems) != before or follower_bad or program_bad:
        return None
    if r0 is None or rotation is None or omega is None or follower is None or program is None:
        return None  # pragma: no cover - each of these was reported
    disc = DiscCam(
        base_radius=r0.si,
        follower=follower,
        program=program,
        rotation=1 if rotation == "ccw" else -1,
        omega=omega.si,
        alpha_permissible=None if alpha is None else alpha.si,
    )
    if forces is not None:  # a position where the cam drives and the follower does not jam
        from graphmech.problems.cam.forces import refuse

        jam = refuse(disc, forces)
        if jam is not None:
            r.problem(r.at("forces") + ".at", jam)
            return None
    return CamScene(
        cam=disc,
        step=CAM_STEP_DEFAULT if step is None else step.si,
        roller_circles=contact == "roller" and circles is not False,
        coordinates=coordinates is True,
        forces=forces,
    )


def parse_cam_scene(
    data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]
) -> Scene[CamScene]:
    """The rest of :func:`graphmech.scene.parse_scene` for a scene with a [cam] table."""
    problems = top.problems
    title, show, find = read_header(top, CAM_SHOW_CHOICES, CAM_SHOW_DEFAULT)
    scales = read_scales(top, cam=True, follower=_peek_follower(data))
    why = phi_axis_problem(scales["phi"]) if "phi" in scales else None  # the diagrams' φ axis, as a cycle's
    if why:
        tab = data.get("scales")
        top.problem("scales." + next((k for k in cast("Mapping[str, Any]", tab) if k.startswith("phi")), "phi"), why)
    for key in LINKAGE_KEYS:
        if key in data:
            top.used.add(key)
            what = f"[[{key}]]" if key in ("dyad", "point") else f"[{key}]"
            top.problem(key, f"{what} belongs to a linkage scene; this is a cam scene ([cam])")
    cam = _read_cam(top)
    measured = read_measured(top, None, cam=True)
    precision, page = read_tail(top)
    if problems or cam is None:
        raise_sorted(problems, data, order, "cam", source)
    return Scene(
        source=source,
        title=title,
        show=show,
        find=find,
        scales=scales,
        measured=measured,
        precision_mm=precision,
        page=page,
        kind="cam",
        problem=cam,
    )


#: [cam.follower] as the kind reads it, for a scene that gives the cam's profile
#: (graphmech.problems.cam.profile_given); r0 None leaves the checks against the base circle out.
read_follower = _read_follower
