"""The instant-centre figures: the kinematic diagram with every centre and the Kennedy lines used,
and the polygon of links (the bookkeeping circle), one pair of panels per position.

As the book draws them: the links as numbered points on a circle, a solid chord for each direct
centre, a dashed chord for each centre found by Kennedy's theorem; on the diagram the centres as
small circles labelled P_ij, each Kennedy line thin through the two known centres it joins and
the one it finds. A centre at infinity is a direction: an arrow (from the sliding pair, or along
the Kennedy line) labelled "P14 ∞". A centre farther than the panel can hold is an arrow
pointing at it with its coordinates. What the construction cannot determine is written under
the panel's title.
"""
from __future__ import annotations

import math
from dataclasses import replace
from typing import Any, Sequence, cast

from graphmech.problems.linkage.figures import caption, mechanism_items, prime
from graphmech.methods.instant_centres import Centre, InstantCentres, centre_name, direct_centres, pair
from graphmech.drawing.primitives import Arrow, Circle, Label, Panel, Primitive, Segment
from graphmech.drawing.lettering import LETTER, number, scale_text, subscript
from graphmech.scales import round_scale

#: Radius of the polygon of links, mm.
CIRCLE_R = 16.0
#: Length of the arrow that stands for a centre at infinity (or off the panel), mm.
ARROW_MM = 14.0
#: A centre farther than this many mechanism sizes from the mechanism is drawn as an arrow.
FAR = 4.0
#: How far a Kennedy line runs past the outermost centre it carries, mm.
OVERRUN = 5.0


def label(i: str, j: str) -> str:
    """``P₁₃`` as the book prints it."""
    return _sub(centre_name(i, j))


def _scaled(ic: InstantCentres, k: float) -> dict[tuple[str, str], tuple[float, float] | None]:
    return {key: (None if c.point is None else (c.point[0] * k, c.point[1] * k)) for key, c in ic.centres.items()}


def panel_scale(mu_l: float, pos: dict[str, tuple[float, float]], ic: InstantCentres, room: tuple[float, float]) -> float:
    """μl of the instant-centre panel: the diagram's, or a rounder coarser one so that the
    mechanism and its centres (those within :data:`FAR` sizes) fit ``room`` (mm)."""
    xs = [p[0] for p in pos.values()]
    ys = [p[1] for p in pos.values()]
    cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    for c in ic.centres.values():
        if c.point is not None and math.dist(c.point, (cx, cy)) <= FAR * ic.size:
            xs.append(c.point[0])
            ys.append(c.point[1])
    need = max((max(xs) - min(xs)) / room[0], (max(ys) - min(ys)) / room[1]) * mu_l
    return mu_l if need <= mu_l else round_scale(need)


def ic_panel(name: str, head: str, build: Any, pos: dict[str, tuple[float, float]], ic: InstantCentres,
             mu_panel: float, notes: Sequence[str] = (), marks: Sequence[tuple[str, Any]] = (), row: int | None = None,
             spans: dict[int, tuple[float, float]] | None = None,
             senses: dict[str, tuple[float | None, float | None]] | None = None) -> Panel:
    """The kinematic diagram at ``mu_panel`` with every centre and the Kennedy lines used.

    ``marks``: extra results to draw, ``("least", (a, b, foot, P1k))`` — the perpendicular from
    P1k to line ab and its foot (the point of least speed, labelled E).
    """
    k = build.mu_l / mu_panel
    b2 = replace(build, scales={**build.scales, "l": mu_panel})
    p2 = {n: (x * k, y * k) for n, (x, y) in pos.items()}
    sp = {key: (lo * k, hi * k) for key, (lo, hi) in (spans or {}).items()}
    items: list[Primitive] = list(mechanism_items(b2, p2, sp, senses))
    pts = _scaled(ic, k)
    xs = [p[0] for p in p2.values()]
    ys = [p[1] for p in p2.values()]
    centre = ((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2)
    size = ic.size * k
    near = {key for key, p in pts.items() if p is not None and math.dist(p, centre) <= FAR * size}

    # The Kennedy lines: through the two known centres, on to the one they find.
    for key in ic.order:
        c = ic.centres[key]
        if c.kind != "kennedy":
            continue
        i, j = key
        for m in c.via:
            on = [pair(ic.links, i, m), pair(ic.links, m, j), key]
            items.extend(_line(on, ic, pts, near))
    # The centres.
    slides = {frozenset(d.links): d.on for d in direct_centres(build.linkage) if d.on is not None}
    for key in ic.order:
        c = ic.centres[key]
        text = label(*key)
        if c.kind == "undetermined":
            continue
        if key in near:
            p = pts[key]
            assert p is not None
            items.append(Circle(p, 1.0, "result"))
            items.append(Label(text, p, (), LETTER))
        elif c.point is not None:  # far: an arrow pointing at it
            p = pts[key]
            assert p is not None
            d = math.dist(p, centre)
            u = ((p[0] - centre[0]) / d, (p[1] - centre[1]) / d)
            start = (centre[0] + 0.6 * size * u[0], centre[1] + 0.6 * size * u[1])
            end = (start[0] + ARROW_MM * u[0], start[1] + ARROW_MM * u[1])
            x, y = (c.point[0] * build.mu_l + build.origin[0], c.point[1] * build.mu_l + build.origin[1])
            items.append(Arrow(start, end, "result"))
            items.append(Label(f"{text} → ({number(x)}, {number(y)}) m", end, (u,), LETTER))
        else:
            assert c.direction is not None
            at = slides.get(frozenset(key))
            base = p2[at] if at in p2 else _on_line_base(c, ic, pts, near, centre)
            u = c.direction
            if at in p2:  # the direction perpendicular to the guide, off the slider
                start = (base[0] + 4.0 * u[0], base[1] + 4.0 * u[1])
            else:
                start = base
            end = (start[0] + ARROW_MM * u[0], start[1] + ARROW_MM * u[1])
            items.append(Arrow(start, end, "result"))
            items.append(Label(text + "∞", end, (u,), LETTER))
    for kind, data in marks:
        if kind == "least":
            _, _, foot, p1 = data
            f = (foot[0] * k, foot[1] * k)
            q = (p1[0] * k, p1[1] * k)
            items.append(Segment(q, f, "construction", dashed=True))
            items.append(Circle(f, 1.0, "result"))
            free = next(n for n in "EMNQRSTUVWXYZ" if n not in p2)  # the book calls it E when E is free
            items.append(Label(free, f, (), LETTER))
            a, b = p2[data[0]], p2[data[1]]
            lo = min(a, b, f, key=lambda t: (t[0] - a[0]) * (b[0] - a[0]) + (t[1] - a[1]) * (b[1] - a[1]))
            hi = max(a, b, f, key=lambda t: (t[0] - a[0]) * (b[0] - a[0]) + (t[1] - a[1]) * (b[1] - a[1]))
            items.append(Segment(lo, hi, "construction"))
    return Panel(name, head, tuple(items), (scale_text("l", mu_panel),) + tuple(notes), row=row,
                 scales=(("l", mu_panel),))


#: The drawn centres, by pair of links (None: at infinity).
_Points = dict[tuple[str, str], 'tuple[float, float] | None']


def _line(on: list[tuple[str, str]], ic: InstantCentres, pts: _Points, near: set[tuple[str, str]]) -> list[Primitive]:
    """A Kennedy line through the finite near centres on it, overrunning, or toward a direction."""
    u: tuple[float, float] | None
    finite = cast("list[tuple[float, float]]", [pts[key] for key in on if key in near])  # near ones are drawn
    dirs = [ic.centres[key].direction for key in on if ic.centres[key].at_infinity]
    spread = len(finite) >= 2 and max(math.dist(p, finite[0]) for p in finite) > 1e-9
    if spread:
        a = finite[0]
        b = max(finite, key=lambda p: math.dist(p, a))
        d = math.dist(a, b)
        u = ((b[0] - a[0]) / d, (b[1] - a[1]) / d)
        ts = [(p[0] - a[0]) * u[0] + (p[1] - a[1]) * u[1] for p in finite]
        lo, hi = min(ts) - OVERRUN, max(ts) + OVERRUN
        if dirs:  # it runs on toward a centre at infinity
            hi += ARROW_MM
            lo -= ARROW_MM
        return [Segment((a[0] + lo * u[0], a[1] + lo * u[1]), (a[0] + hi * u[0], a[1] + hi * u[1]), "construction")]
    if finite and dirs:  # one point (or several at one place) and a direction
        a, u = finite[0], dirs[0]
        assert u is not None
        return [Segment((a[0] - 3 * ARROW_MM * u[0], a[1] - 3 * ARROW_MM * u[1]),
                        (a[0] + 3 * ARROW_MM * u[0], a[1] + 3 * ARROW_MM * u[1]), "construction")]
    return []


def _on_line_base(c: Centre, ic: InstantCentres, pts: _Points, near: set[tuple[str, str]], centre: tuple[float, float]) -> tuple[float, float]:
    """Where to start the arrow of a Kennedy centre at infinity: a known centre on its lines."""
    i, j = c.links
    for m in c.via:
        for key in (pair(ic.links, i, m), pair(ic.links, m, j)):
            if key in near:
                p = pts[key]
                assert p is not None
                return p
    return centre


def circle_panel(name: str, ic: InstantCentres, row: int | None = None, notation: str = "en") -> Panel:
    """The polygon of links: links as numbered points on a circle; a solid chord per direct
    centre, a dashed chord per centre found by Kennedy's theorem; undetermined ones left out."""
    n = len(ic.links)
    at = {lid: (CIRCLE_R * math.cos(math.pi / 2 - 2 * math.pi * k / n), CIRCLE_R * math.sin(math.pi / 2 - 2 * math.pi * k / n))
          for k, lid in enumerate(ic.links)}
    items: list[Primitive] = [Circle((0.0, 0.0), CIRCLE_R, "construction")]
    for key in ic.order:
        c = ic.centres[key]
        if c.kind == "undetermined":
            continue
        items.append(Segment(at[key[0]], at[key[1]], "given" if c.kind == "direct" else "result",
                             dashed=c.kind == "kennedy"))
    for lid, p in at.items():
        items.append(Circle(p, 0.8, "result"))
        items.append(Label(lid, p, ((-p[0] / CIRCLE_R, -p[1] / CIRCLE_R),), LETTER, italic=False))
    missing = [centre_name(*k) for k in ic.order if ic.centres[k].kind == "undetermined"]
    notes = (caption("by Kennedy", notation),) + (
        (f"{caption('undetermined', notation)}: {', '.join(missing)}",) if missing else ())
    return Panel(name, caption("polygon of links", notation), tuple(items), notes, row=row)


def ic_panels(an: Any, page: tuple[float, float], first_row: int = 0) -> list[Panel]:
    """The instant-centre panels of every constructed position of a checked linkage scene."""
    from graphmech.problems.linkage.sizes import drawn_position_text
    from graphmech.problems.linkage.figures import guide_spans
    from graphmech.methods.instant_centres import (common_link, least_speed_on_line, point_names, positions_mm,
                                                   split_line)

    ica = an.instant_centres
    build = an.build
    notation = getattr(an.scene.page, "notation", "en")
    spans = guide_spans(build.linkage, build, an.solutions)
    rows = max(1, sum(1 for s in an.solutions if s is not None))
    room = (page[0] * 0.5, max((page[1] - 40.0) / rows - 60.0, 30.0))  # less title, notes, gaps
    least = []
    for raw in an.scene.find:
        base = raw.partition("@")[0]
        if base.startswith(("v_min_", "s_min_")) and base.endswith("_ic"):
            if base[len("v_min_"):-len("_ic")] not in least:
                least.append(base[len("v_min_"):-len("_ic")])
    panels: list[Panel] = []
    for i, sol in enumerate(an.solutions):
        ic = ica.centres[i] if ica is not None else None
        if sol is None or ic is None:
            continue
        pos = positions_mm(build, sol)
        mu = panel_scale(build.mu_l, pos, ic, room)
        notes = [_omega_note(ic, lid, build.mu_l) for lid in ic.links
                 if lid in ic.motions and len(ic.motions[lid].found) == 4]
        notes += [f"ω_{{{lid}}}: {why}" for lid, why in ic.undetermined.items()]
        notes += [f"{centre_name(*c.links)}: undetermined — {c.why}" for c in ic.centres.values() if not c.known]
        for x, zs in ica.zeros.items():
            notes.append(f"v_{{{x}}} = 0 at φ_{{{build.linkage.driver.link}}} = "
                         + ", ".join(f"{number(math.degrees(z))}°" for z in zs) if zs else
                         f"v_{{{x}}} ≠ 0 over the whole turn")  # (was "= 0 at φ = " and nothing)
        marks = []
        for text in least:
            ab = split_line(text, point_names(build.linkage))
            lid = common_link(build.linkage, *ab) if ab else None
            if ab and lid:
                found = least_speed_on_line(ic, lid, pos[ab[0]], pos[ab[1]])
                p1 = ic.absolute(lid).point
                if not isinstance(found, str) and p1 is not None:
                    marks.append(("least", (ab[0], ab[1], found[2], p1)))
        # the senses of the ω found from the centres, drawn on their links
        senses: dict[str, tuple[float | None, float | None]] = {
            lid: (ic.motions[lid].omega, None) for lid in ic.links
            if lid in ic.motions and len(ic.motions[lid].found) == 4 and not ic.absolute(lid).at_infinity
            and abs(ic.motions[lid].omega) > 1e-9 * (abs(getattr(build.linkage.driver, "omega", 0.0)) or 1.0)}
        head = caption("instant centres", notation) + ", " + drawn_position_text(build, an.labels[i])
        panels.append(ic_panel(f"ic-{an.labels[i]}", head, build, pos, ic, mu, notes, marks, first_row + i, spans,
                               senses))
        panels.append(circle_panel(f"ic-circle-{an.labels[i]}", ic, first_row + i, notation))
    if ica is not None:
        last = first_row + len(an.solutions)
        for k, (x, zs) in enumerate(ica.zeros.items()):
            if zs:
                panels.append(zero_panel(an, x, zs, spans, last + k, notation))
    return panels


def zero_panel(an: Any, x: str, zeros: Sequence[float], spans: dict[int, tuple[float, float]] | None,
               row: int, notation: str = "en") -> Panel:
    """The mechanism drawn at each crank angle where v_x = 0, with the centre that makes it so:
    the driver's centre with x's link falls on the driver's pivot (the ratio's numerator is 0).
    The first position bold with its letters, the others thin dashed with primed letters (B′, C′)."""
    from graphmech.methods.instant_centres import instant_centres, positions_mm, signed_rate

    build = an.build
    linkage = build.linkage
    driver = linkage.driver.link
    carrier = signed_rate(linkage, x)[1]  # the rocker or slider whose rate vanishes with v_x
    items: list[Primitive] = []
    seen: set[tuple[float, float]] = set()
    for k, z in enumerate(zeros):
        sol = an.plan.solve({build.param: float(z)})
        pos = positions_mm(build, sol)
        mark = prime(k) if k else None
        items += mechanism_items(build, pos, spans, mark=mark)
        tip = pos.get(getattr(linkage.driver, "tip", ""), None)
        if tip is not None:
            items.append(Label(f"φ_{{{driver}}} = {number(math.degrees(z))}°", tip, (), LETTER, italic=False))
        ic = instant_centres(linkage, pos, mu_l=build.mu_l)
        if carrier is not None and carrier != driver:
            c = ic.centre(driver, carrier)
            key = (round(c.point[0], 6), round(c.point[1], 6)) if c.point is not None else None
            if c.point is not None and key is not None and key not in seen:
                seen.add(key)
                items.append(Circle(c.point, 1.4, "result"))
                items.append(Label(label(driver, carrier), c.point, (), LETTER))
    ang = ", ".join(f"{number(math.degrees(z))}°" for z in zeros)
    return Panel(f"ic-zero-{x}", caption("zero velocity", notation).format(x), tuple(items),
                 (scale_text("l", build.mu_l), f"at φ_{{{driver}}} = {ang}"), row=row, scales=(("l", build.mu_l),))


def _omega_note(ic: InstantCentres, lid: str, mu_l: float) -> str:
    mo = ic.motions[lid]
    i = mo.found[0]
    if ic.absolute(lid).at_infinity:  # a translating link: every point moves as P_ij does
        v = math.hypot(*mo.v0) * mu_l
        return f"link {lid} translates ({_sub(mo.found[3])} ∞): v = v({_sub(mo.found[2])}) = {number(v)} m/s"
    p1i, pij, p1j = (_sub(n) for n in mo.found[1:])
    return f"ω_{{{lid}}} = ω_{{{i}}}·{p1i}{pij}/{p1j}{pij} = {number(mo.omega)} rad/s"


def _sub(name: str) -> str:
    """``P13`` → ``P₁₃``."""
    return "P" + subscript(name[1:].replace("_", ","))


__all__ = ["circle_panel", "ic_panel", "ic_panels", "panel_scale"]
