"""The figures of a disc cam: the profile by inversion (反转法) and the follower's motion diagrams.

Methods produce primitives with roles; a renderer turns them into SVG and knows nothing of cams.
The sheet is drawn as the textbook draws it, one panel per figure, in one row:

profile (at μl)
    the cam centre O (a hinge) and the base circle r0 (thin); the offset circle e (thin, dashed)
    of an offset translating follower, or the circle of the pivots of an oscillating one; the
    follower's inverted positions — a translating follower's axis, tangent to the offset circle
    at its foot K_k and run out past B_k, numbered 0, 1, 2 … at its outer end; an oscillating
    follower's pivot A_k, numbered there, and its arm A_kB_k —; the pitch points B_k as dots; the pitch curve through them (thin, dashed for a roller),
    the roller circles at the B_k (or a flat face's lines), the working profile (bold); the cam's
    sense of rotation ω as a curved arrow about O and the follower itself at division 0;
displacement s–δ (at μs and μφ)
    the cam-angle axis divided at the same divisions and numbered as on the profile, the
    ordinates s_k as thin verticals, the curve, the segments named under the axis (rise 150° …);
velocity v–δ = ω·s′ and acceleration a–δ = ω²·s″
    drawn from dense evaluation, one polyline per smooth piece of the law; a jump (velocity at a
    rigid impact, acceleration at a soft one) as a thin dashed vertical, and a rigid impact's
    infinite acceleration as a short arrow labelled +∞ (or −∞, downwards), as the book shows it.

Every size fixed here is paper millimetres; every quantity is laid off at its panel's μ.
"""
from __future__ import annotations

import math
from typing import Any, Sequence, cast

import numpy as np

from graphmech.mechanisms.cam import DiscCam, OscillatingFollower, TranslatingFollower
from graphmech.mechanisms.motion import breakpoints, displacement, impacts
from graphmech.methods.cam_inversion import DrawnProfile, divisions, draw_profile
from graphmech.drawing.lettering import LETTER, number, scale_text, text_box_size
from graphmech.drawing.notation import word
from graphmech.drawing.primitives import (ArcArrow, Arrow, Circle, FixedPivot, GuideLine, Hinge, Label, Panel,
                                         Polyline, Primitive, Segment, Sheet, angle_arc)
from graphmech.errors import OutOfDomain
from graphmech.scales import format_scale

#: The panels a cam sheet can show, in the order they stand in the row.
PANELS = ("profile", "displacement", "velocity", "acceleration")
#: The cam sheet's words (graphmech.drawing.notation's shape): key → (English, 中文 (孙桓), русский).
WORDS: dict[str, tuple[str, str, str]] = {
    "profile": ("Cam profile by inversion", "凸轮轮廓曲线（反转法）", "профиль кулачка (метод обращения движения)"),
    "displacement": ("Displacement diagram", "位移线图", "график перемещений"),
    "velocity": ("Velocity diagram", "速度线图", "график скоростей"),
    "acceleration": ("Acceleration diagram", "加速度线图", "график ускорений"),
    # the segments under the s–δ axis (孙桓: 推程, 远休止, 回程, 近休止; удаление, стояние, возвращение)
    "rise": ("rise", "推程", "удаление"),
    "return": ("return", "回程", "возвращение"),
    "far dwell": ("dwell", "远休止", "дальнее стояние"),
    "near dwell": ("dwell", "近休止", "ближнее стояние"),
    "undercut": ("undercut", "运动失真", "подрез"),
    "ccw": ("ω counter-clockwise", "ω 逆时针", "ω против часовой стрелки"),
    "cw": ("ω clockwise", "ω 顺时针", "ω по часовой стрелке"),
    # the cam angle's symbol on the diagrams' axis (孙桓 δ; the Russian books φ)
    "cam angle": ("δ", "δ", "φ"),
}
#: The ordinate's symbol per diagram: translating follower, oscillating follower.
SYMBOLS = {"displacement": ("s", "ψ"), "velocity": ("v", "ω_{2}"), "acceleration": ("a", "ε_{2}")}
SCALE_KEY = {"displacement": "s", "velocity": "v", "acceleration": "a"}
#: The key of a diagram's ordinate scale (graphmech.scales.SCALE_INFO): translating, oscillating.
DRAWN_SCALE = {"s": ("s", "psi"), "v": ("v", "omega"), "a": ("a", "epsilon")}
ORDER = {"displacement": 0, "velocity": 1, "acceleration": 2}
UNITS = {"s": ("m/mm", "rad/mm"), "v": ("(m/s)/mm", "(rad/s)/mm"), "a": ("(m/s²)/mm", "(rad/s²)/mm")}

#: How far a follower's line runs past B_k (past its roller circle), mm.
LINE_OVERRUN = 5.0
#: A flat face's line runs this far past its contact point, and at least this far either side of B_k, mm.
FACE_PAST, FACE_MIN = 3.0, 5.0
#: Radius of the dot marking a pitch point B_k (drawn with the result pen: a solid dot), mm.
DOT = 0.3
#: The smooth curves (pitch curve, working profile) are drawn by the same inversion at divisions
#: this fine, rad — or finer, so that no chord on paper is longer than SMOOTH_CHORD mm.
SMOOTH_STEP, SMOOTH_CHORD = math.radians(1.0), 1.0
#: Font size of every text of the sheet (the issue's least body text), mm.
TEXT = LETTER
#: Font size of the division numbers, mm.
NUMBER_SIZE = TEXT
#: Least free distance between two division numbers, mm.
NUMBER_CLEARANCE = 0.8
#: The division step used for the s–δ diagram when no profile was drawn, rad.
DEFAULT_STEP = math.radians(15.0)
#: Dense evaluation of the diagrams: one sample every this much of the δ axis, mm.
SAMPLE_STEP = 0.25
#: The band under the s–δ diagram's numbers where the segments are named, mm below the axis.
NAMES_ROW = (7.0, 12.5)
#: Font size of the segments' names, mm.
NAME_SIZE = TEXT
#: How far the diagram axes run past the curve, mm.
AXIS_OVERRUN = 7.0
#: Length of the arrow marking an infinite acceleration, mm.
INFINITY_ARROW = 10.0
#: The follower's stem beyond its roller / tip, and where its guide stands on it, mm.
STEM, GUIDE_AT = 20.0, 14.0
#: Length of the lines showing the pressure angle, and the radius of its arc, mm.
MARK_LINE, MARK_ARC = 14.0, 8.0
#: Half size of an undercut cross, and the length of the leader to its label, mm.
CROSS, LEADER = 1.8, 8.0
#: How far the centre lines through O run past the working profile, mm.
CENTRE_PAST = 4.0
#: A value evaluated this close before a joint is its left-hand limit, rad.
LEFT_LIMIT = 1e-9



def _unit(v: Any) -> tuple[float, float]:
    n = math.hypot(float(v[0]), float(v[1]))
    return (float(v[0]) / n, float(v[1]) / n) if n > 0 else (0.0, 0.0)


def _dirs(*ds: tuple[float, float]) -> tuple[tuple[float, float], ...]:
    """Directions for a label to avoid; a zero vector (a degenerate line) has none."""
    return tuple(d for d in ds if d != (0.0, 0.0))


def _add(p: Any, q: Any, k: float = 1.0) -> tuple[float, float]:
    return (float(p[0]) + k * float(q[0]), float(p[1]) + k * float(q[1]))


def _mm(x: float) -> str:
    return f"{number(x * 1e3)} mm"


def _angular(cam: DiscCam) -> bool:
    return isinstance(cam.follower, OscillatingFollower)


def _circle_points(r: float, n: int = 120) -> tuple[tuple[float, float], ...]:
    return tuple((r * math.cos(math.tau * k / n), r * math.sin(math.tau * k / n)) for k in range(n))


def scale_note(key: str, value: float, angular: bool = False) -> str:
    """The note of a scale as the drawing states it: ``μs = 0.0005 m/mm``, ``μφ = 2.5 °/mm``; for
    an oscillating follower the angle's, ``μψ = 0.005 rad/mm`` (and μω, με).

    >>> scale_note("s", 0.0005), scale_note("a", 0.5, True), scale_note("phi", math.radians(2.5))
    ('μs = 0.0005 m/mm', 'με = 0.5 (rad/s²)/mm', 'μφ = 2.5 °/mm')
    """
    if not angular or key not in ("s", "v", "a"):
        return format_scale(key, value)
    symbol = {"s": ("s", "ψ"), "v": ("v", "ω"), "a": ("a", "ε")}[key][int(angular)]
    return f"μ{symbol} = {value:.6g} {UNITS[key][int(angular)]}"


def drawn_scale(key: str, value: float, angular: bool = False) -> tuple[str, str]:
    """A panel's scale as its drawing states it (:func:`graphmech.drawing.lettering.scale_text`)
    and its key in graphmech.scales.SCALE_INFO, for the graphic scale bar: an oscillating
    follower's swing is ``psi`` (°/mm); the check keeps :func:`scale_note`'s full precision.

    >>> drawn_scale("s", math.radians(0.5), True), drawn_scale("a", 1.0 / 3.0)
    (('μ_{ψ} = 0.5 °/mm', 'psi'), ('μ_{a} = 0.3333 (m/s²)/mm', 'a'))
    """
    if key in DRAWN_SCALE:
        key = DRAWN_SCALE[key][int(angular)]
    return scale_text(key, value), key


def number_gap(n: int, size: float = NUMBER_SIZE) -> float:
    """The least distance between two division numbers' anchors: the widest number's width plus
    clearance, mm."""
    return text_box_size(str(max(n - 1, 0)), size)[0] + 2.0 * NUMBER_CLEARANCE


def numbered_every(where: Sequence[np.ndarray], n: int, size: float = NUMBER_SIZE) -> int:
    """Number every k-th division, k the smallest of 1, 2, 3, 4, 6 … for which the numbers of
    every panel stand at least a number's width (plus clearance) apart.

    ``where`` holds, per panel, the positions (n × 2, mm) where the n division numbers go.

    >>> x = np.column_stack([np.arange(24) * 4.0, np.zeros(24)])
    >>> numbered_every([x], 24)      # "23" is 3.4 mm wide: 4 mm apart is too close
    2
    """
    need = number_gap(n, size)
    for k in (1, 2, 3, 4, 6, 8, 12, 24):
        ok = True
        for pts in where:
            chosen = np.asarray(pts, dtype=float)[::k]
            chosen = chosen[np.isfinite(chosen).all(axis=1)]
            if len(chosen) > 1:
                ok &= bool(np.min(np.hypot(*np.diff(chosen, axis=0).T)) >= need)
        if ok or k >= n:
            return k
    return max(n, 1)


# ----------------------------------------------------------------------------- the profile
def _feet(cam: DiscCam, delta: np.ndarray) -> np.ndarray:
    """Translating: the axis's foot K_k on the offset circle; oscillating: the pivot A_k (m)."""
    f = cam.follower
    r = f.offset if isinstance(f, TranslatingFollower) else f.pivot_distance
    return np.column_stack([r * np.cos(delta), -cam.rotation * r * np.sin(delta)])


def _outer_ends(cam: DiscCam, drawn: DrawnProfile, mu_l: float) -> np.ndarray:
    """Where each division's number goes (drawing mm): the outer end of a translating
    follower's line, an oscillating follower's pivot A_k."""
    f = cam.follower
    if isinstance(f, OscillatingFollower):
        return _feet(cam, drawn.delta) / mu_l
    reach = LINE_OVERRUN + (f.roller_radius / mu_l if f.contact == "roller" else 0.0)
    return drawn.pitch / mu_l + reach * drawn.axis_dir


def _face_spans(cam: DiscCam, drawn: DrawnProfile, mu_l: float) -> np.ndarray:
    """A flat face's line at each division, as the span (from, to) along the face from B_k
    (mm, + to the right of the follower's motion): past its contact with the profile."""
    pitch, u = drawn.pitch / mu_l, drawn.axis_dir
    act = drawn.actual / mu_l
    act = act[np.isfinite(act).all(axis=1)] if len(act) else act
    tol = 1e-6 * (1.0 + cam.base_radius / mu_l)
    spans = np.tile([-FACE_MIN, FACE_MIN], (len(pitch), 1))
    for k, (b, d) in enumerate(zip(pitch, u)):
        if not (np.isfinite(b).all() and np.isfinite(d).all()) or not len(act):
            continue
        rel = act - b
        on = np.abs(rel @ d) < tol
        if on.any():
            t = rel[on] @ np.array([d[1], -d[0]])
            spans[k] = (min(float(t.min()), 0.0) - FACE_PAST, max(float(t.max()), 0.0) + FACE_PAST)
    return spans


def _follower_items(cam: DiscCam, b0: tuple[float, float], u0: tuple[float, float], mu_l: float,
                    face: tuple[float, float]) -> list[Primitive]:
    """The follower itself at division 0: stem (or arm), roller / knife tip / flat face."""
    f = cam.follower
    n0 = (u0[1], -u0[0])  # to the right of the follower's direction of motion
    items: list[Primitive] = []
    rr = f.roller_radius / mu_l if f.contact == "roller" else 0.0
    if isinstance(f, OscillatingFollower):
        a0 = (f.pivot_distance / mu_l, 0.0)
        items += [Segment(a0, b0, "given"), FixedPivot(a0)]
    else:
        top = _add(b0, u0, rr + STEM)
        items.append(Segment(b0, top, "given"))
        # the fixed guide the stem slides in: short lines either side, hatched outside
        mid = _add(b0, u0, rr + GUIDE_AT)
        for side in (1.0, -1.0):
            c = _add(mid, n0, side * 2.2)
            p0, p1 = _add(c, u0, -side * 2.5), _add(c, u0, side * 2.5)
            items.append(GuideLine(p0, p1))
    if f.contact == "roller":
        items += [Circle(b0, rr, "given"), Hinge(b0, min(1.0, 0.3 * rr))]
    elif f.contact == "knife":
        for side in (1.0, -1.0):
            items.append(Segment(b0, _add(_add(b0, u0, 4.0), n0, side * 1.6), "given"))
    else:
        half = max(abs(face[0]), abs(face[1])) + 2.0
        items.append(Segment(_add(b0, n0, -half), _add(b0, n0, half), "given"))
    return items


def _point_on(pitch: np.ndarray, delta: np.ndarray, at: float) -> np.ndarray:
    """The point of the drawn pitch polygon at cam angle ``at``, between its divisions."""
    d = np.append(delta, delta[0] + math.tau)
    p = np.vstack([pitch, pitch[:1]])
    at = float(at) % math.tau
    if at < d[0]:
        at += math.tau
    i = int(np.clip(np.searchsorted(d, at, side="right") - 1, 0, len(delta) - 1))
    t = (at - d[i]) / (d[i + 1] - d[i]) if d[i + 1] > d[i] else 0.0
    return cast(np.ndarray, p[i] + t * (p[i + 1] - p[i]))


def _mark_items(cam: DiscCam, drawn: DrawnProfile, mu_l: float, ok: np.ndarray,
                marks: dict[str, Any], notation: str = "en", smooth: DrawnProfile | None = None) -> list[Primitive]:
    """The largest pressure angle drawn at its division; the undercut places crossed on the drawn
    working profile (``smooth``, by default ``drawn``'s)."""
    smooth = drawn if smooth is None else smooth
    items: list[Primitive] = []
    labels: list[Primitive] = []
    idx = np.flatnonzero(ok)
    if "alpha_max_at" in marks and len(idx) >= 3 and cam.follower.contact != "flat":  # a face: α ≡ 0
        gap = np.abs((drawn.delta[idx] - float(marks["alpha_max_at"]) + math.pi) % math.tau - math.pi)
        j = int(np.argmin(gap))
        k, prev, nxt = idx[j], idx[j - 1], idx[(j + 1) % len(idx)]
        b = tuple(drawn.pitch[k] / mu_l)
        tangent = _unit(drawn.pitch[nxt] - drawn.pitch[prev])
        u = _unit(drawn.axis_dir[k])
        normal = (-tangent[1], tangent[0])
        if normal[0] * u[0] + normal[1] * u[1] < 0.0:
            normal = (-normal[0], -normal[1])
        if tangent != (0.0, 0.0) and u != (0.0, 0.0):
            items += [Segment(b, _add(b, normal, MARK_LINE), "label"), Segment(b, _add(b, u, MARK_LINE), "label")]
            arc = angle_arc(b, normal, u, MARK_ARC)
            if arc is not None:
                items.append(arc)
            alpha = float(marks.get("alpha_max", drawn.pressure_angle[k]))
            mid = _unit(_add(normal, u))
            labels.append(Label(f"α_{{max}} = {number(math.degrees(alpha))}°", _add(b, mid, MARK_LINE + 1.0),
                                ((-mid[0], -mid[1]),), TEXT, italic=False))
    for at in marks.get("undercut_at", ()) or ():
        if not len(idx):
            break
        p = _point_on(drawn.pitch[idx], drawn.delta[idx], float(at))
        act = smooth.actual[np.isfinite(smooth.actual).all(axis=1)] if len(smooth.actual) else smooth.actual
        if len(act):  # where the working profile goes wrong: its point nearest the pitch point
            p = act[int(np.argmin(np.hypot(*(act - p).T)))]
        c = (float(p[0]) / mu_l, float(p[1]) / mu_l)
        s = CROSS / math.sqrt(2.0)
        items += [Segment((c[0] - s, c[1] - s), (c[0] + s, c[1] + s), "label"),
                  Segment((c[0] - s, c[1] + s), (c[0] + s, c[1] - s), "label")]
        inward = _unit((-c[0], -c[1]))  # a leader into the profile, where only thin lines run
        if inward == (0.0, 0.0):
            labels.append(Label(word("undercut", notation, WORDS), c, (), TEXT, italic=False))
            continue
        tail = _add(c, inward, LEADER)
        items.append(Segment(_add(c, inward, CROSS), tail, "label"))
        labels.append(Label(word("undercut", notation, WORDS), tail, ((-inward[0], -inward[1]),), TEXT,
                            italic=False))
    return items + labels


def smooth_drawing(cam: DiscCam, drawn: DrawnProfile, mu_l: float) -> DrawnProfile:
    """The inversion carried out again at divisions of 1° (finer where a 1° chord would be longer
    than SMOOTH_CHORD mm on paper), the laws' joints among them: the pitch curve and the working
    profile the drawing shows as smooth curves — the same construction as at the numbered
    divisions, which stay the ones measured."""
    reach = float(np.nanmax(np.hypot(*drawn.pitch.T))) / mu_l if len(drawn.pitch) else 0.0
    step = min(SMOOTH_STEP, SMOOTH_CHORD / reach) if reach > 0.0 and math.isfinite(reach) else SMOOTH_STEP
    delta = divisions(cam, step, breakpoints(cam.program))
    return draw_profile(cam, delta, displacement(cam.program, delta))


def _closed_curve(points: np.ndarray, keep: np.ndarray) -> tuple[tuple[float, float], ...]:
    return tuple((float(x), float(y)) for x, y in points[keep])


def profile_items(cam: DiscCam, drawn: DrawnProfile, mu_l: float, *, roller_circles: bool = True,
                  marks: dict[str, Any] | None = None, number_every: int = 1, notation: str = "en",
                  smooth: DrawnProfile | None = None) -> list[Primitive]:
    """The profile panel at μl (drawing mm, O at the origin), in the draftsman's order.

    Parameters
    ----------
    cam : DiscCam
    drawn : DrawnProfile
        What :func:`~graphmech.methods.cam_inversion.draw_profile` drew (m) at the numbered
        divisions; divisions whose construction failed (``valid`` false) are left out.
    mu_l : float
        m/mm.
    roller_circles : bool
        Draw a roller follower's circle at every B_k.
    marks : dict, optional
        ``alpha_max_at`` (rad) and ``alpha_max`` (rad): the pressure angle drawn at the nearest
        division; ``undercut_at`` (rad, a list): crosses where the working profile goes wrong.
    number_every : int
        Number every k-th division (0, k, 2k …).
    notation : str
        "en", "zh" or "ru": the drawn words (graphmech.drawing.notation).
    smooth : DrawnProfile, optional
        The same inversion at fine divisions, whose pitch curve and working profile are drawn
        (by default :func:`smooth_drawing`).
    """
    f = cam.follower
    rot = 1.0 if cam.rotation >= 0 else -1.0
    ok = np.asarray(drawn.valid, dtype=bool) & np.isfinite(drawn.pitch).all(axis=1) \
        & np.isfinite(drawn.axis_dir).all(axis=1)
    fine = smooth_drawing(cam, drawn, mu_l) if smooth is None else smooth
    pitch = drawn.pitch / mu_l
    u = drawn.axis_dir
    feet = _feet(cam, drawn.delta) / mu_l
    ends = _outer_ends(cam, drawn, mu_l)
    rr = f.roller_radius / mu_l if f.contact == "roller" else 0.0
    items: list[Primitive] = []
    labels: list[Primitive] = []
    origin = (0.0, 0.0)
    actual = np.asarray(fine.actual, dtype=float) / mu_l
    actual = actual[np.isfinite(actual).all(axis=1)] if len(actual) else actual

    # 1. the centre lines through O, the base circle r0 and the offset (pivot) circle: thin dash-dot
    reach = max([cam.base_radius / mu_l] + ([float(np.max(np.hypot(*actual.T)))] if len(actual) else [])) \
        + CENTRE_PAST
    items += [Segment((-reach, 0.0), (reach, 0.0), "construction", dashdot=True),
              Segment((0.0, -reach), (0.0, reach), "construction", dashdot=True)]
    items.append(Circle(origin, cam.base_radius / mu_l, "construction", dashdot=True))
    guide_r = abs(f.offset) if isinstance(f, TranslatingFollower) else f.pivot_distance
    if guide_r / mu_l > 0.5:
        items.append(Circle(origin, guide_r / mu_l, "construction", dashdot=True))

    # 2. the follower's inverted positions, numbered at their outer ends
    gap = number_gap(len(pitch))
    faces = _face_spans(cam, drawn, mu_l) if f.contact == "flat" else np.zeros((len(pitch), 2))
    for k in np.flatnonzero(ok):
        b, foot, end, d = tuple(pitch[k]), tuple(feet[k]), tuple(ends[k]), _unit(u[k])
        if isinstance(f, OscillatingFollower):
            if math.dist(foot, b) > 1e-9:
                items.append(Segment(foot, b, "construction"))
            radial = _unit(foot)
            out = radial if radial != (0.0, 0.0) else (1.0, 0.0)
            avoid = _dirs((-out[0], -out[1]), (out[1], -out[0]), (-out[1], out[0]))
        else:
            if math.dist(foot, end) > 1e-9:
                items.append(Segment(foot, end, "construction"))
            avoid = _dirs((-d[0], -d[1]), (d[1], -d[0]), (-d[1], d[0]))
        if f.contact == "flat":
            n = (d[1], -d[0])
            items.append(Segment(_add(b, n, float(faces[k, 0])), _add(b, n, float(faces[k, 1])), "construction"))
        # every number_every-th; the last ones not on top of number 0 (the divisions run round)
        if k % number_every == 0 and (k == 0 or not ok[0] or math.dist(end, tuple(ends[0])) >= gap):
            labels.append(Label(str(k), end, avoid, NUMBER_SIZE, italic=False))

    # 3. the pitch curve, smooth (thin dash-dot for a roller, as 孙桓 draws the 理论廓线), and the
    #    pitch points B_k on it as dots
    fine_ok = np.asarray(fine.valid, dtype=bool) & np.isfinite(fine.pitch).all(axis=1)
    if f.contact == "roller" and fine_ok.sum() >= 3:
        items.append(Polyline(_closed_curve(fine.pitch / mu_l, fine_ok), "construction", closed=True, dashdot=True))
    items += [Circle(tuple(pitch[k]), DOT, "result") for k in np.flatnonzero(ok)]

    # 4. the roller circles, and the working profile as their envelope (bold, smooth)
    if f.contact == "roller" and roller_circles and rr > 0.0:
        items += [Circle(tuple(pitch[k]), rr, "construction") for k in np.flatnonzero(ok)]
    if len(actual) >= 3:
        items.append(Polyline(tuple(map(tuple, actual)), "result", closed=True))

    # 5. the follower at division 0, the cam's sense of rotation, the centre O
    if ok[0]:
        items += _follower_items(cam, tuple(pitch[0]), _unit(u[0]), mu_l, tuple(faces[0]))
    r_arc = min(12.0, max(5.0, 0.45 * cam.base_radius / mu_l))
    if isinstance(f, TranslatingFollower) and abs(f.offset) / mu_l > 7.0:
        r_arc = min(r_arc, 0.75 * abs(f.offset) / mu_l)  # inside the offset circle, clear of the lines
    sweep = rot * math.radians(80.0)
    arc = ArcArrow(origin, r_arc, -math.pi / 2 - sweep / 2, sweep, "given")
    items += [arc, Hinge(origin)]
    marked = _mark_items(cam, drawn, mu_l, ok, marks or {}, notation, fine)
    return (items + [m for m in marked if not isinstance(m, Label)]
            + [Label("O", origin, ((0.0, -1.0), (1.0, 0.0), (-1.0, 0.0), (0.0, 1.0)), TEXT),
               Label("ω", arc.points(2)[1], ((1.0, 0.0), (-1.0, 0.0), (0.0, -1.0)), TEXT)]  # off the arc, inside it
            + [m for m in marked if isinstance(m, Label)] + labels)


def profile_notes(cam: DiscCam, mu_l: float, notation: str = "en") -> tuple[str, ...]:
    """μl and the cam's given dimensions (r0, e or l_OA and l_AB, r_r) and its sense of rotation."""
    f = cam.follower
    dims = [f"r_{{0}} = {_mm(cam.base_radius)}"]
    if isinstance(f, TranslatingFollower):
        if f.offset:
            dims.append(f"e = {_mm(f.offset)}")
    else:
        dims += [f"l_{{OA}} = {_mm(f.pivot_distance)}"] + ([f"l_{{AB}} = {_mm(f.arm)}"] if f.arm else [])  # a face: none
    if f.contact == "roller":
        dims.append(f"r_{{r}} = {_mm(f.roller_radius)}")
    sense = word("ccw" if cam.rotation >= 0 else "cw", notation, WORDS)
    return (drawn_scale("l", mu_l)[0], ", ".join(dims) + f"; {sense}")


# ----------------------------------------------------------------------------- the diagrams
def _pieces(cam: DiscCam) -> list[tuple[float, float]]:
    """The smooth pieces of the law: between the joints and the laws' own knots, rad."""
    cuts = {float(a) % math.tau for a in breakpoints(cam.program)}
    cuts |= {float(i.angle) % math.tau for i in impacts(cam.program)}
    edges = sorted(cuts | {0.0}) + [math.tau]
    return [(a, b) for a, b in zip(edges[:-1], edges[1:]) if b - a > 1e-12]


def _value(cam: DiscCam, delta: np.ndarray | float, order: int) -> np.ndarray:
    """s, v = ω·s′ or a = ω²·s″ (SI) at ``delta``."""
    return cam.omega ** order * displacement(cam.program, delta, order)


def _left(cam: DiscCam, at: float, order: int) -> float:
    """The left-hand limit at a joint (at 0: the end of the turn before)."""
    at = at if at > 0.0 else math.tau
    return float(_value(cam, at - LEFT_LIMIT, order))


def _segment_name(kind: str, angle: float, room: float) -> str:
    """A segment's name under the s–δ axis, "rise 150°", or just "150°" if that is all there is
    room for (``room`` mm between its joints), or nothing.

    >>> _segment_name("dwell", math.radians(30), 25.0), _segment_name("dwell", math.radians(30), 10.0)
    ('dwell 30°', '30°')
    """
    for text in (f"{kind} {number(math.degrees(angle))}°", f"{number(math.degrees(angle))}°"):
        if text_box_size(text, NAME_SIZE)[0] + 1.0 <= room:
            return text
    return ""


def kind_word(cam: DiscCam, k: int) -> str:
    """The key of segment ``k``'s name in :data:`WORDS`: a dwell is far (远休止) at the top of the
    stroke, near (近休止) at the bottom."""
    seg = cam.program.segments[k]
    if seg.kind != "dwell":
        return seg.kind
    start = float(sum(x.angle for x in cam.program.segments[:k]))
    top = float(displacement(cam.program, np.array([start + 0.5 * seg.angle]))[0]) > 0.5 * cam.program.stroke
    return "far dwell" if top else "near dwell"


def diagram_items(cam: DiscCam, panel: str, mu: float, mu_phi: float, delta: np.ndarray | None,
                  number_every: int = 1, notation: str = "en") -> list[Primitive]:
    """A motion diagram (``panel`` "displacement", "velocity" or "acceleration") at μ and μφ.

    The δ axis runs right from the origin; ``delta`` are the profile's divisions (the s–δ
    diagram is divided and numbered there, every ``number_every``-th number written);
    ``notation`` letters it (graphmech.drawing.notation).
    """
    order = ORDER[panel]
    angular = _angular(cam)
    width = math.tau / mu_phi
    items: list[Primitive] = []
    labels: list[Label] = []
    curves: list[np.ndarray] = []
    for a, b in _pieces(cam):
        n = max(2, int(math.ceil((b - a) / mu_phi / SAMPLE_STEP)))
        d = np.linspace(a, b, n + 1)
        y = np.append(_value(cam, d[:-1], order), _left(cam, b, order)) / mu
        curves.append(np.column_stack([d / mu_phi, y]))
    if order > 0:  # jumps: thin dashed verticals; a rigid impact's infinite acceleration, ±∞
        for imp in impacts(cam.program):
            x = float(imp.angle) % math.tau / mu_phi
            y0 = _left(cam, float(imp.angle), order) / mu
            y1 = float(_value(cam, float(imp.angle) % math.tau, order)) / mu
            if abs(y1 - y0) > 1e-6 and (order == 2 or imp.kind == "rigid"):
                items.append(Segment((x, y0), (x, y1), "construction", dashed=True))
            if order == 2 and imp.kind == "rigid" and imp.jump != 0.0:
                up = 1.0 if imp.jump > 0 else -1.0
                tip = (x, up * INFINITY_ARROW)
                items.append(Arrow((x, 0.0), tip, "result"))
                labels.append(Label("+∞" if up > 0 else "−∞", tip, ((0.0, -up), (1.0, 0.0)), TEXT, italic=False))
        for a in breakpoints(cam.program)[1:]:  # the joints' cam angles under the axis
            labels.append(Label(f"{number(math.degrees(float(a)))}°", (float(a) / mu_phi, 0.0),
                                ((0.0, 1.0), (1.0, 0.0), (-1.0, 0.0)), TEXT, italic=False))
    ys = [0.0] + [float(v) for c in curves for v in (c[:, 1].min(), c[:, 1].max())]
    ys += [it.p1[1] for it in items if isinstance(it, Arrow)]
    lo, hi = min(ys), max(ys)

    # the axes, as thin arrows
    top = hi + AXIS_OVERRUN
    bottom = lo - AXIS_OVERRUN if lo < 0.0 else 0.0
    items.append(Arrow((0.0, 0.0), (width + AXIS_OVERRUN, 0.0), "label"))
    items.append(Arrow((0.0, bottom), (0.0, top), "label"))
    symbol = SYMBOLS[panel][int(angular)]
    labels[:0] = [Label(symbol, (0.0, top), ((0.0, -1.0),), TEXT),
                  Label(word("cam angle", notation, WORDS), (width + AXIS_OVERRUN, 0.0), ((-1.0, 0.0),), TEXT)]
    joints = [float(a) for a in breakpoints(cam.program)] + [math.tau]
    ticks = [float(x) for x in delta] if panel == "displacement" and delta is not None else joints
    for x in sorted(set(ticks) | set(joints[1:])):
        if x > 0.0:
            items.append(Segment((x / mu_phi, 0.0), (x / mu_phi, -1.0), "label"))

    if panel == "displacement":
        if delta is not None:
            s = displacement(cam.program, delta) / mu
            for k, (x, y) in enumerate(zip(delta / mu_phi, s)):
                if abs(y) > 1e-9:
                    items.append(Segment((float(x), 0.0), (float(x), float(y)), "construction"))
                if k % number_every == 0:
                    labels.append(Label(str(k), (float(x), 0.0), ((0.0, 1.0), (1.0, 0.0), (-1.0, 0.0)),
                                        NUMBER_SIZE, italic=False))
        h = cam.program.stroke / mu
        items.append(Segment((-1.0, h), (0.0, h), "label"))
        labels.append(Label("ψ_{max}" if angular else "h", (0.0, h), ((1.0, 0.0), (0.0, 1.0), (0.0, -1.0)), TEXT))
        for j in joints:  # the segments named under the numbers, parted at the joints
            items.append(Segment((j / mu_phi, -NAMES_ROW[0]), (j / mu_phi, -NAMES_ROW[1]), "label"))
        for k, (seg, a, b) in enumerate(zip(cam.program.segments, joints[:-1], joints[1:])):
            name = _segment_name(word(kind_word(cam, k), notation, WORDS), seg.angle, (b - a) / mu_phi)
            if name:
                labels.append(Label(name, ((a + b) / 2.0 / mu_phi, -NAMES_ROW[0]),
                                    ((0.0, 1.0), (1.0, 0.0), (-1.0, 0.0)), NAME_SIZE, italic=False))
    for c in curves:
        items.append(Polyline(tuple(map(tuple, c)), "result"))
    return items + labels


# ----------------------------------------------------------------------------- the sheet
def panel_rows(show: Sequence[str]) -> dict[str, int]:
    """Which row each panel stands in: up to two panels in one row; with three or four, the first
    two (the profile and the s–δ diagram) above and the rest below — a row of four does not fit a
    sheet with readable captions."""
    shown = [p for p in PANELS if p in show]
    return {p: (0 if len(shown) <= 2 or k < 2 else 1) for k, p in enumerate(shown)}


def cam_sheet(title: str, cam: DiscCam, drawn: DrawnProfile | None, scales: dict[str, float], show: Sequence[str],
              page: tuple[float, float], *, roller_circles: bool = True, marks: dict[str, Any] | None = None,
              footer: tuple[str, ...] = (), number_every: int | None = None, notation: str = "en") -> Sheet:
    """The cam's sheet: the panels of ``show`` in the order profile, displacement, velocity,
    acceleration, side by side in one row.

    Parameters
    ----------
    title : str
    cam : DiscCam
    drawn : DrawnProfile or None
        The inversion's drawing (m) at the divisions; needed for the profile. Without it the
        s–δ diagram is divided every 15° and at the joints.
    scales : dict
        ``"l"`` m/mm (profile), ``"s"`` m/mm or rad/mm (oscillating follower), ``"phi"`` rad/mm
        (the cam-angle axis), ``"v"`` (m/s)/mm, ``"a"`` (m/s²)/mm — each needed only by the
        panels shown.
    show : sequence of str
        A subset of :data:`PANELS`.
    page : (float, float)
        Page size, mm.
    roller_circles : bool
        Draw a roller follower's circle at every pitch point.
    marks : dict, optional
        ``alpha_max_at``, ``alpha_max`` (rad), ``undercut_at`` (list of rad); see
        :func:`profile_items`.
    footer : tuple of str
    number_every : int, optional
        Number every k-th division; by default the smallest k that keeps the numbers apart on
        the profile and the s–δ axis (:func:`numbered_every`).
    notation : str
        "en", "zh" or "ru": the captions and symbols drawn (graphmech.drawing.notation).

    Raises
    ------
    ValueError
        An unknown panel, a missing or non-positive scale, or the profile without a drawing.

    Examples
    --------
    >>> from graphmech.mechanisms.cam import MotionProgram, Segment
    >>> program = MotionProgram(0.016, (Segment("rise", math.pi, "cosine"), Segment("return", math.pi, "cosine")))
    >>> cam = DiscCam(0.03, TranslatingFollower(), program)
    >>> sheet = cam_sheet("Cam", cam, None, {"phi": math.radians(4), "a": 0.001}, ["acceleration"], (297.0, 210.0))
    >>> [(p.notes, p.scales) for p in sheet.panels]
    [(('μ_{a} = 0.001 (m/s²)/mm', 'μ_{φ} = 4 °/mm'), (('a', 0.001), ('phi', 0.06981317007977318)))]
    """
    bad = [p for p in show if p not in PANELS]
    if bad:
        raise OutOfDomain(f"unknown panel(s) {', '.join(map(repr, bad))}; use {', '.join(PANELS)}")
    wanted = [p for p in PANELS if p in show]
    keys = {"l"} if "profile" in wanted else set()
    keys |= {SCALE_KEY[p] for p in wanted if p != "profile"} | ({"phi"} if set(wanted) - {"profile"} else set())
    missing = sorted(k for k in keys if not (k in scales and scales[k] > 0.0 and math.isfinite(scales[k])))
    if missing:
        raise OutOfDomain(f"the scale(s) {', '.join(missing)} must be given, finite and > 0")
    if "profile" in wanted and drawn is None:
        raise OutOfDomain("the profile panel needs the inversion's drawing (draw_profile)")

    if drawn is not None:
        delta = np.asarray(drawn.delta, dtype=float)
    else:
        delta = divisions(cam, DEFAULT_STEP, breakpoints(cam.program))
    if number_every is None:
        where: list[np.ndarray] = []
        if "profile" in wanted and drawn is not None:
            where.append(_outer_ends(cam, drawn, scales["l"]))
        if "displacement" in wanted:
            where.append(np.column_stack([delta / scales["phi"], np.zeros(len(delta))]))
        number_every = numbered_every(where, len(delta)) if where else 1
    number_every = max(1, int(number_every))

    angular = _angular(cam)
    panels: list[Panel] = []
    for p in wanted:
        if p == "profile":
            assert drawn is not None
            items = profile_items(cam, drawn, scales["l"], roller_circles=roller_circles, marks=marks,
                                  number_every=number_every, notation=notation)
            notes = profile_notes(cam, scales["l"], notation)
            head = word(p, notation, WORDS)
            measures: tuple[tuple[str, float], ...] = (("l", scales["l"]),)
        else:
            key = SCALE_KEY[p]
            items = diagram_items(cam, p, scales[key], scales["phi"], delta, number_every, notation)
            (note, bar), (phi_note, _) = drawn_scale(key, scales[key], angular), drawn_scale("phi", scales["phi"])
            notes = (note, phi_note)
            head = f"{word(p, notation, WORDS)} {SYMBOLS[p][int(angular)]}–{word('cam angle', notation, WORDS)}"
            measures = ((bar, scales[key]), ("phi", scales["phi"]))
        panels.append(Panel(p, head, tuple(items), notes, row=panel_rows(show)[p], scales=measures))
    return Sheet(title, tuple(panels), page, footer)


__all__ = ["PANELS", "WORDS", "cam_sheet", "diagram_items", "drawn_scale", "numbered_every", "profile_items",
           "scale_note", "smooth_drawing"]
