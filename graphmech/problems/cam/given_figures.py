"""The sheet of a cam given by its profile: the inversion drawing and the s–δ diagram.

profile (at μl)
    the disc (bold) about its centre C, the pitch circle (thin, dashed for a roller), the base
    circle r0 and the farthest circle (thin, dash-dot) about O; the offset circle e or the circle
    of the pivots a; the follower's inverted positions at the divisions (a translating axis from
    its foot, a rocker's pivot and arm) with their pitch points, numbered; each named contact's
    follower drawn bold with its letter at the touched point, and its pressure angle α_E as an arc
    between the common normal and the direction the follower's point moves.
displacement (at μs, chosen to draw the rise some 40 mm high, and μφ, a turn 120 mm long, unless stated)
    the ordinates at the divisions as thin verticals and the curve through the dense closed form.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from graphmech.drawing.primitives import (
    Circle,
    FixedPivot,
    Hinge,
    Label,
    Panel,
    Polyline,
    Primitive,
    Role,
    Segment,
    Sheet,
    angle_mark,
)
from graphmech.exact import cam_profile as exact
from graphmech.mechanisms.cam import OscillatingFollower, TranslatingFollower
from graphmech.methods.cam_analysis import PolylineInversion

if TYPE_CHECKING:
    from graphmech.methods.cam_analysis import DrawnPosition
    from graphmech.problems.cam.profile_given import GivenCamAnalysis, GivenCamScene
    from graphmech.problems.kind import Footer
    from graphmech.problems.reader import Scene

#: The least length of a pressure angle's arc, mm (a 1° angle at a radius of 8 mm would be 0.14 mm).
ARC_LEAST = 0.4


def _mm(p: tuple[float, float], mu: float) -> tuple[float, float]:
    return (p[0] / mu, p[1] / mu)


def _follower(an: GivenCamAnalysis, p: DrawnPosition, bold: bool) -> list[Primitive]:
    """One inverted follower: its axis or arm (and flat face), its point."""
    cam, mu = an.cam, an.scales["l"]
    f = cam.follower
    role: Role = "result" if bold else "construction"
    out: list[Primitive] = []
    B = _mm(p.point, mu)
    if isinstance(f, TranslatingFollower):
        turn = -cam.rotation * p.delta
        d = (-math.sin(turn), math.cos(turn))
        end = (B[0] + d[0] * 12.0, B[1] + d[1] * 12.0)
        out.append(Segment(_mm(p.pivot, mu), end, role, dashed=not bold))
        if f.contact == "flat":
            w = (d[1] * 10.0, -d[0] * 10.0)
            out.append(Segment((B[0] - w[0], B[1] - w[1]), (B[0] + w[0], B[1] + w[1]), role))
    else:
        A = _mm(p.pivot, mu)
        if f.contact == "flat":
            u = (B[0] - A[0], B[1] - A[1])
            out.append(Segment(A, (A[0] + 1.15 * u[0], A[1] + 1.15 * u[1]), role, dashed=not bold))
        else:
            out.append(Segment(A, B, role, dashed=not bold))
        out.append(Hinge(A, 0.8))
    if f.contact == "roller" and bold:
        out.append(Circle(B, f.roller_radius / mu, "result"))
    return out


def pressure_mark(an: GivenCamAnalysis, p: DrawnPosition, name: str) -> list[Primitive]:
    """The pressure angle at a named contact: short arms from the follower's point B along the common
    normal (through B and the contact, or through B and P12 for a knife) and along B's velocity (a
    translating follower's axis; ⟂ the rocker's arm), each turned to the side that makes the angle
    acute, and the arc between them lettered α_E. A flat face (α ≡ 0) has none."""
    from graphmech.problems.cam.figures import MARK_ARC, MARK_LINE

    cam, mu = an.cam, an.scales["l"]
    f = cam.follower
    if f.contact == "flat":
        return []
    B = _mm(p.point, mu)
    through = p.contact if f.contact == "roller" else p.p12
    n = (p.point[0] - through[0], p.point[1] - through[1])
    if isinstance(f, TranslatingFollower):
        turn = -cam.rotation * p.delta
        v = (-math.sin(turn), math.cos(turn))
    else:
        v = (-(p.point[1] - p.pivot[1]), p.point[0] - p.pivot[0])  # ⟂ the arm A_δB
    ln, lv = math.hypot(*n), math.hypot(*v)
    if not (ln > 0.0 and lv > 0.0 and math.isfinite(ln)):
        return []
    n, v = (n[0] / ln, n[1] / ln), (v[0] / lv, v[1] / lv)
    if n[0] * v[0] + n[1] * v[1] < 0.0:
        v = (-v[0], -v[1])
    # a small angle gets a wider arc, so that it is at least ARC_LEAST long and can be seen
    r = max(MARK_ARC, ARC_LEAST / p.alpha) if p.alpha > 0.0 else MARK_ARC
    reach = max(MARK_LINE, r + MARK_LINE - MARK_ARC)
    arms: list[Primitive] = [Segment(B, (B[0] + reach * d[0], B[1] + reach * d[1]), "label") for d in (n, v)]
    return arms + angle_mark(B, n, v, r, f"α_{{{name}}}")


def profile_items(an: GivenCamAnalysis) -> list[Primitive]:
    """The inversion drawing (module docstring), paper mm."""
    cam, mu, inv = an.cam, an.scales["l"], an.inversion
    f = cam.follower
    items: list[Primitive] = [Circle((0.0, 0.0), inv.r0 / mu, "construction", dashdot=True),
                              Circle((0.0, 0.0), inv.r_max / mu, "construction", dashdot=True),
                              FixedPivot((0.0, 0.0)), Label("O", (0.0, 0.0))]
    if isinstance(inv, PolylineInversion):  # the curve through the given points, and its pitch curve
        items.append(Polyline(tuple(map(tuple, (inv.P / mu).tolist())), "given", closed=True))
        if f.contact == "roller":
            items.append(Polyline(tuple(map(tuple, (inv.B / mu).tolist())), "construction", closed=True, dashed=True))
        for x, y in cam.profile.points:  # type: ignore[union-attr]
            items.append(Hinge((x / mu, y / mu), 0.4))
    else:
        C = _mm(cam.disc.centre, mu)
        items += [Circle(C, cam.disc.radius / mu, "given"), Hinge(C, 0.6), Label("C", C)]
        if f.contact == "roller":
            items.append(Circle(C, cam.pitch_radius() / mu, "construction", dashed=True))
    if isinstance(f, TranslatingFollower) and f.offset != 0.0:
        items.append(Circle((0.0, 0.0), abs(f.offset) / mu, "construction", dashed=True))
    if isinstance(f, OscillatingFollower):
        items.append(Circle((0.0, 0.0), f.pivot_distance / mu, "construction", dashed=True))
    for k, p in enumerate(an.positions[:-1]):
        items += _follower(an, p, False)
        items.append(Label(str(k), _mm(p.pivot if isinstance(f, OscillatingFollower) else p.point, mu), italic=False))
    for name, (g, _) in an.contacts.items():
        p = inv.at(g)
        items += _follower(an, p, True)
        items.append(Label(name, _mm(p.contact, mu)))
        items += pressure_mark(an, p, name)
    return items


def diagram_items(an: GivenCamAnalysis, notation: str = "en") -> list[Primitive]:
    from graphmech.drawing.lettering import number
    from graphmech.drawing.notation import word
    from graphmech.problems.cam.figures import WORDS

    cam = an.cam
    ang = isinstance(cam.follower, OscillatingFollower)
    k_s = 1.0 / an.scales["s"]  # mm per unit of s (m or rad)
    k_d = 1.0 / an.scales["phi"]
    turn_mm = math.tau * k_d
    items: list[Primitive] = [Segment((0.0, 0.0), (turn_mm + 6.0, 0.0), "given"),
                              Segment((0.0, 0.0), (0.0, exact.rise(cam) * k_s + 6.0), "given"),
                              Label("δ", (turn_mm + 6.0, 0.0)), Label("ψ" if ang else "s", (0.0, exact.rise(cam) * k_s + 6.0))]
    for k, p in enumerate(an.positions):
        x = p.delta * k_d
        items.append(Segment((x, 0.0), (x, p.s * k_s), "construction"))
    d = np.linspace(0.0, math.tau, 721)
    s = exact.displacement(cam, d)
    items.append(Polyline(tuple(zip((d * k_d).tolist(), (s * k_s).tolist())), "result"))
    # the rise from the lowest position to the highest, the return back: named under the axis
    low, high = float(d[int(np.argmin(s))]), float(d[int(np.argmax(s))])
    for kind, start, span in (("rise", low, (high - low) % math.tau), ("return", high, (low - high) % math.tau)):
        mid = (start + span / 2.0) % math.tau
        items.append(Label(f"{word(kind, notation, WORDS)} {number(round(math.degrees(span)))}°", (mid * k_d, -4.0),
                           italic=False))
    for name, (g, _) in an.contacts.items():
        items.append(Label(name, (g * k_d, float(exact.displacement(cam, g)) * k_s)))
    return items


def given_sheet(scene: Scene[GivenCamScene], footer: Footer) -> tuple[Sheet, list[str]]:
    from graphmech.drawing.notation import word
    from graphmech.problems.cam.figures import WORDS, drawn_scale
    from graphmech.problems.cam.profile_given import analyse_given
    from graphmech.problems.reader import page_size

    an = analyse_given(scene, ())
    ang = isinstance(an.cam.follower, OscillatingFollower)
    notation = scene.page.notation
    panels = []
    if "profile" in scene.show:
        panels.append(Panel("profile", word("profile", notation, WORDS), tuple(profile_items(an)),
                            (f"μl = {an.scales['l']:g} m/mm",), row=0, scales=(("l", an.scales["l"]),)))
    if "displacement" in scene.show:
        (note, bar), (phi_note, _) = drawn_scale("s", an.scales["s"], ang), drawn_scale("phi", an.scales["phi"])
        head = f"{word('displacement', notation, WORDS)} {'ψ' if ang else 's'}–{word('cam angle', notation, WORDS)}"
        panels.append(Panel("displacement", head, tuple(diagram_items(an, notation)), (note, phi_note), row=0,
                            scales=((bar, an.scales["s"]), ("phi", an.scales["phi"]))))
    return Sheet(scene.title, tuple(panels), page_size(scene), tuple(footer)), list(an.warnings)
