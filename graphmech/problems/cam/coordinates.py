"""The working profile's coordinates at every division, as handed in (``[cam] coordinates = true``).

A design office hands a cam in with a table beside the drawing: per division its cam angle δ, the
displacement s (a rocker's ψ), and the working (actual) profile's point in the cam frame as x, y and
as polar r, θ. Here that point is read off the drawing — the knife's tip B_k; for a roller the point
of the roller circle about B_k facing the drawn envelope's nearest point; for a flat face the middle of the
face's stretch between its neighbours' corners — and set beside the exact envelope's
(:func:`graphmech.exact.cam.profile`). The book's closed form for a roller, pitch point minus r_r
along the normal, is what the tests hold the exact side to.
"""
from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from graphmech.drawing.lettering import LETTER, text_box_size
from graphmech.drawing.primitives import Panel, Polyline, Primitive, Segment, Text
from graphmech.exact import cam as exact_cam
from graphmech.mechanisms.cam import DiscCam, OscillatingFollower
from graphmech.methods.cam_inversion import DrawnProfile

#: The table's row height and the free room either side of a cell's text, mm (the structure
#: sheet's cases table uses 7.5 mm: this one has a row per division).
ROW, CELL_PAD = 5.5, 2.0
#: The rows of one block of the table; more stand in blocks side by side (a low table under the
#: drawing, as the scales are chosen for: graphmech.problems.cam.check.choose_cam_scales).
BLOCK_ROWS = 13
#: The most rows the sheet's table lists (three blocks); a finer step lists every k-th division (said under it).
MAX_ROWS = 3 * BLOCK_ROWS
#: The table's words: key → (English, 中文, русский).
WORDS: dict[str, tuple[str, str, str]] = {
    "title": ("Working profile coordinates", "凸轮实际廓线坐标", "координаты действительного профиля"),
    "every": ("one division in {} listed", "每 {} 个分点列出一个", "каждое {}-е деление"),
    "frame": ("O at the origin, the follower along +y at δ = 0; θ from +x counter-clockwise",
              "O 为原点，δ = 0 时从动件沿 +y；θ 自 +x 逆时针量", "O — начало координат, толкатель по +y при δ = 0; θ от +x против часовой"),
    "frame rocker": ("O at the origin, the rocker's pivot A on +x; θ from +x counter-clockwise",
                     "O 为原点，摆杆转轴 A 在 +x 上；θ 自 +x 逆时针量", "O — начало координат, ось коромысла A на +x; θ от +x против часовой"),
}


def _say(key: str, notation: str, *args: object) -> str:
    en, zh, ru = WORDS[key]
    return {"zh": zh, "ru": ru}.get(notation, en).format(*args)


def drawn_contacts(cam: DiscCam, drawn: DrawnProfile) -> np.ndarray:
    """The working profile's point at each division, read off the drawing, (N, 2) m (NaN where the
    drawing has no profile, an envelope eroded away)."""
    f = cam.follower
    pitch = np.asarray(drawn.pitch, dtype=float)
    if f.contact == "knife":
        return pitch.copy()
    if f.contact == "roller":
        import shapely

        if len(drawn.actual) < 4:
            return np.full_like(pitch, math.nan)
        ring = shapely.LinearRing(drawn.actual)
        # the roller circle about B_k touches the envelope towards the envelope's nearest point (the
        # offset polygon has a corner there, r_r/cos(τ/2) from B_k: the contact is on the circle)
        at = shapely.line_interpolate_point(ring, shapely.line_locate_point(ring, shapely.points(pitch)))
        toward = np.asarray(shapely.get_coordinates(at), dtype=float) - pitch
        with np.errstate(divide="ignore", invalid="ignore"):
            out: np.ndarray = pitch + f.roller_radius * toward / np.hypot(toward[:, 0], toward[:, 1])[:, None]
        return out
    # flat face k: the line through B_k along t_k; its stretch of the envelope runs between the
    # corners with faces k − 1 and k + 1, and the contact is its middle (B_k itself where a
    # neighbour is parallel: a dwell, the face touching the circle at the foot B_k)
    t = np.column_stack([-drawn.axis_dir[:, 1], drawn.axis_dir[:, 0]])
    lam = np.zeros(len(pitch))
    for shift in (1, -1):
        q, u = np.roll(pitch, -shift, axis=0), np.roll(t, -shift, axis=0)
        d = q - pitch
        den = t[:, 0] * u[:, 1] - t[:, 1] * u[:, 0]
        with np.errstate(divide="ignore", invalid="ignore"):
            along = (d[:, 0] * u[:, 1] - d[:, 1] * u[:, 0]) / den
        lam += 0.5 * np.where(np.abs(den) > 1e-12, along, 0.0)  # a parallel neighbour adds nothing
    return pitch + t * lam[:, None]


def _polar(p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """r (m) and θ (degrees, 0 … 360, counter-clockwise from +x) of points (N, 2)."""
    r = np.hypot(p[:, 0], p[:, 1])
    theta = np.degrees(np.arctan2(p[:, 1], p[:, 0])) % 360.0
    return r, theta


def _number(x: float) -> float | None:
    return float(x) if math.isfinite(x) else None


def coordinate_columns(cam: DiscCam, drawn_profile: DrawnProfile) -> list[dict[str, Any]]:
    """Per division the drawn and the exact working-profile point: x, y, r (m), θ (degrees)."""
    drawn = drawn_contacts(cam, drawn_profile)
    exact = np.asarray(exact_cam.profile(cam, drawn_profile.delta).actual, dtype=float)
    rd, td = _polar(drawn)
    re, te = _polar(exact)
    return [{"x": _number(drawn[k, 0]), "y": _number(drawn[k, 1]), "r": _number(rd[k]), "theta_deg": _number(td[k]),
             "x_exact": _number(exact[k, 0]), "y_exact": _number(exact[k, 1]), "r_exact": _number(re[k]),
             "theta_exact_deg": _number(te[k])} for k in range(len(drawn_profile.delta))]


def _cell(x: float | None, digits: int = 2) -> str:
    if x is None:
        return "—"
    text = f"{x:.{digits}f}"
    return "0.00" if text in ("-0.00", "0.00") and digits == 2 else text.replace("-", "−")


def _block(head: list[str], rows: list[list[str]], widths: list[float], left: float) -> list[Primitive]:
    """One block of the table, its upper left corner at (left, 0): the frame and the rule under the
    head bold, the other rules thin (as the structure sheet's table of counts)."""
    xs = [left]
    for w in widths:
        xs.append(xs[-1] + w)
    right, depth = xs[-1], ROW * (len(rows) + 1)
    items: list[Primitive] = [Polyline(((left, 0.0), (right, 0.0), (right, -depth), (left, -depth)), "given", closed=True),
                              Segment((left, -ROW), (right, -ROW), "given")]
    items += [Segment((left, -ROW * k), (right, -ROW * k), "construction") for k in range(2, len(rows) + 1)]
    items += [Segment((x, 0.0), (x, -depth), "construction") for x in xs[1:-1]]
    for k, row in enumerate([head] + rows):
        y = -ROW * (k + 0.5)
        for j, text in enumerate(row):
            if k == 0 or j == 0:  # the head and the division numbers in the middle of their column
                items.append(Text(text, ((xs[j] + xs[j + 1]) / 2.0, y), LETTER, italic=k == 0))
            else:  # numbers right-aligned: their decimal points line up
                items.append(Text(text, (xs[j + 1] - CELL_PAD, y), LETTER, "end"))
    return items


def coordinates_panel(cam: DiscCam, divisions: Sequence[dict[str, Any]], notation: str = "en",
                      row: int | None = None) -> Panel:
    """The table on the sheet: division, δ, s (a rocker's ψ), x, y, r in mm and θ in degrees, as
    read off the drawing — the rows of the check's ``divisions`` with :func:`coordinate_columns`."""
    ang = isinstance(cam.follower, OscillatingFollower)
    head = ["k", "δ/°", "ψ/°" if ang else "s/mm", "x/mm", "y/mm", "r/mm", "θ/°"]
    rows_all = list(divisions)
    every = max(1, math.ceil(len(rows_all) / MAX_ROWS))
    rows = []
    for d in rows_all[::every]:
        mm = [None if d[key] is None else d[key] * 1e3 for key in ("x", "y", "r")]
        s = d["s"] if ang else d["s"] * 1e3
        rows.append([str(d["division"]), _cell(d["delta_deg"]), _cell(s), *map(_cell, mm), _cell(d["theta_deg"])])
    widths = [max(text_box_size(r[j], LETTER)[0] for r in [head] + rows) + 2.0 * CELL_PAD for j in range(len(head))]
    n_blocks = math.ceil(len(rows) / BLOCK_ROWS)
    per = math.ceil(len(rows) / n_blocks)
    items: list[Primitive] = []
    left = 0.0
    for b in range(n_blocks):
        items += _block(head, rows[b * per:(b + 1) * per], widths, left)
        left += sum(widths) + 3.0 * CELL_PAD
    notes = [_say("frame rocker" if ang else "frame", notation)] + ([_say("every", notation, every)] if every > 1 else [])
    return Panel("coordinates", _say("title", notation), tuple(items), tuple(notes), row=row)


__all__ = ["BLOCK_ROWS", "MAX_ROWS", "coordinate_columns", "coordinates_panel", "drawn_contacts"]
