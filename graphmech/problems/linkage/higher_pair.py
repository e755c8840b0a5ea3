"""Higher pairs inside a linkage scene (``[[higher_pair]]``, 高副低代): a cam and its follower,
gear teeth, a wheel rolling on a track.

The scene writes the linkage already substituted: for a sliding contact a dyad link joins the two
profiles' centres of curvature at the contact (the ``substitute_link``, revolutes at both ends), so
the polygons and the instant centres of that linkage are the mechanism's at that position —
velocities and accelerations, exactly, for circular profiles whose centres stay on their links.
For pure rolling on a fixed straight profile the contact point is the rolling link's instant
centre with the frame, written as a frame point carrying the link: velocities only.

Here: reading and cross-checking the table (:func:`read_higher_pairs`), the rows ``dir_normal_ij``
and ``v_slip_ij`` (:func:`add_rows`), and the drawing of the profiles, the contact and the common
normal over the mechanism panels (:func:`decorate`). The closed form a circular cam is checked
against is :mod:`graphmech.exact.higher_pair`.
"""
from __future__ import annotations

import dataclasses
import math
import re
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Literal

import numpy as np

from graphmech.errors import SceneError
from graphmech.mechanisms.linkage import RPP, RPR, RRP, RRR, Crank, Linkage, Positions
from graphmech.problems.reader import MISSING

if TYPE_CHECKING:
    from graphmech.drawing.primitives import Sheet
    from graphmech.problems.reader import Reader

Motion = Literal["sliding", "rolling"]
MOTIONS: tuple[Motion, ...] = ("sliding", "rolling")
Side = Literal["left", "right"]
SIDES: tuple[Side, ...] = ("left", "right")

#: ``dir_normal_23``, ``v_slip_23`` (with or without ``@position``): the higher pair's values.
_NAME = re.compile(r"(dir_normal|v_slip)_([0-9A-Za-z]+)")
#: |CiCj| must equal ρi + ρj to this relative tolerance (the scene's numbers are typed, not computed).
LENGTH_REL = 1e-9


@dataclass(frozen=True)
class HigherPair:
    """One higher pair: links (i, j), the centres of curvature (and radii, m) of their profiles at
    the contact, and its lower-pair substitute (a link between the centres, or the contact point)."""

    links: tuple[str, str]
    motion: Motion
    centres: tuple[str, ...]  # sliding: (Ci, Cj); rolling on a fixed straight profile: (Ci,)
    radii: tuple[float, ...]
    substitute: str | None = None  # sliding: the substitute link Ci–Cj (or the block at Ci on a flat face)
    contact: str | None = None  # rolling: the contact point K, a frame point
    face_side: Side | None = None  # a flat face of link j: to this side of its slot

    @property
    def flat(self) -> bool:
        """Link j's profile is straight (a flat face): its centre of curvature is at infinity."""
        return self.motion == "sliding" and len(self.centres) == 1

    @property
    def name(self) -> str:
        return self.links[0] + self.links[1]


@dataclass(frozen=True)
class HigherPairs:
    """What a linkage scene with ``[[higher_pair]]`` tables carries in ``Scene.problem``."""

    pairs: tuple[HigherPair, ...]


def pairs_of(scene: Any) -> tuple[HigherPair, ...]:
    return scene.problem.pairs if isinstance(getattr(scene, "problem", None), HigherPairs) else ()


def claims(name: str) -> bool:
    """Whether a ``find`` name (with or without ``@position``) is a higher pair's."""
    return _NAME.fullmatch(name.partition("@")[0]) is not None


# ---------------------------------------------------------------------------- reading


def _bar(linkage: Linkage, link: str, a: str, b: str) -> float | None:
    """The length of ``link`` between its revolutes a and b where a dyad (RRR, or an RRP's
    coupler) or the crank fixes it; None where the link is not such a binary bar a–b."""
    d = linkage.driver
    if isinstance(d, Crank) and d.link == link and {d.pivot, d.tip} == {a, b}:
        return float(d.length)
    for y in linkage.dyads:
        if isinstance(y, RRR):
            for k, (p, length) in enumerate(((y.p, y.lengths[0]), (y.q, y.lengths[1]))):
                if y.links[k] == link and {p, y.c} == {a, b}:
                    return float(length)
        elif isinstance(y, RRP) and y.links[0] == link and {y.p, y.c} == {a, b}:
            return float(y.length)
    return None


def read_higher_pairs(top: Reader, linkage: Linkage | None, positions: Positions | None,
                      show: tuple[str, ...], find: tuple[str, ...]) -> HigherPairs | None:
    """The ``[[higher_pair]]`` tables, cross-checked against the (substituted) linkage; problems
    are reported on ``top``. None when the scene has none."""
    readers = top.tables_at("higher_pair")
    if not readers:
        return None
    pairs = [p for k, r in enumerate(readers) if (p := _read_one(r, k, linkage)) is not None]
    rolling = [k for k, p in enumerate(pairs) if p.motion == "rolling"]
    if rolling:
        where = f"higher_pair[{rolling[0]}].relative_motion"
        if positions is not None and len(positions.values) > 1:
            top.problem(where, "the contact point is the rolling link's pivot at one position only: "
                               "give one driver position")
        accel = [n for n in find if n.startswith(("a_", "alpha_"))]
        if "acceleration" in show or accel:
            top.problem(where, "a rolling contact's pivot moves on: the substitute gives velocities only, "
                               f"not {accel[0] if accel else 'the acceleration polygon'}")
    names = [p.name for p in pairs]
    for k, n in enumerate(names):
        if n in names[:k] or n[::-1] in names[:k]:
            top.problem(f"higher_pair[{k}].links", f"links {n[0]} and {n[1:]} have one higher pair already")
    return HigherPairs(tuple(pairs))


def _read_one(r: Reader, k: int, linkage: Linkage | None) -> HigherPair | None:
    links = r.name_list("links", 2, r.link_id)
    motion = r.string("relative_motion", choices=MOTIONS, required=True)
    value = r.raw("centres_of_curvature", required=True, hint='["C", "B"], one point of each link')
    side = r.string("face_side", choices=SIDES)
    # a sliding pair with one centre: link j's profile is a flat face (its centre at infinity)
    count = 1 if motion == "rolling" or (isinstance(value, list) and len(value) == 1 and motion == "sliding") else 2
    if count == 2 and side is not None:
        r.problem(r.at("face_side"), "only for a flat face (a sliding pair with one centre of curvature)")
    elif count == 1 and motion == "sliding" and side is None and r.present("face_side") is None:
        r.problem(r.at("face_side"), 'missing: the flat face lies to the "left" or "right" of the slot its '
                                     "block slides in, at ρ from the block's pin")
    centres: list[str | None] = []
    c_path = r.at("centres_of_curvature")
    if value is not MISSING:
        if not isinstance(value, list) or len(value) != count:
            r.problem(c_path, ("must be a list of one point name" if count == 1 else "must be a list of 2 point names")
                              + (" (the rolling link's centre; the fixed profile is straight)" if count == 1 else ""))
        else:
            centres = [r.point_name(v, f"{c_path}[{n}]") for n, v in enumerate(value)]
    radii: list[float] | None = None
    given = r.quantity("radii_of_curvature", "length")
    if given is not None:
        got = r.numbers(given.value, r.at(given.key), count, positive=True, shape="[ρi, ρj]" if count == 2 else "[ρi]")
        radii = None if got is None else [given.si(x) for x in got]
    sub = r.raw("substitute_link")
    contact = r.raw("contact_point")
    substitute = contact_pt = None
    if motion == "sliding":
        if sub is MISSING:
            r.problem(r.at("substitute_link"), "missing: the dyad link that joins the two centres of curvature "
                                               "(on a flat face: the block pinned at the centre)")
        else:
            substitute = r.link_id(sub, r.at("substitute_link"))
        if contact is not MISSING:
            r.problem(r.at("contact_point"), "a sliding contact is substituted by a link: give substitute_link only")
    elif motion == "rolling":
        if contact is MISSING:
            r.problem(r.at("contact_point"), "missing: the contact point, a frame point carried by the rolling link")
        else:
            contact_pt = r.point_name(contact, r.at("contact_point"))
        if sub is not MISSING:
            r.problem(r.at("substitute_link"), "a rolling contact is substituted by its contact point: "
                                               "give contact_point only")
    r.finish()
    ids = [x for x, _ in links]
    if (motion is None or radii is None or None in ids or len(centres) != count or None in centres
            or (motion == "sliding" and substitute is None) or (motion == "rolling" and contact_pt is None)):
        return None
    pair = HigherPair((str(ids[0]), str(ids[1])), motion, tuple(str(c) for c in centres), tuple(radii),
                      substitute, contact_pt, side if count == 1 and motion == "sliding" else None)
    if linkage is not None:
        _cross_check(r, pair, linkage)
    return pair


def _cross_check(r: Reader, p: HigherPair, linkage: Linkage) -> None:
    """The pair against the substituted linkage: links, centres and substitute as declared."""
    carried = linkage.links()
    carried.setdefault(linkage.frame_link, []).extend(linkage.frame_points)
    i, j = p.links
    for n, lid in enumerate(p.links):
        if lid not in carried:
            r.problem(f"{r.at('links')}[{n}]", f"link {lid} is not a link of the linkage ({', '.join(carried)})")
            return
    if i == j:
        r.problem(r.at("links"), "the two links must differ")
        return
    for n, c in enumerate(p.centres):
        if c not in carried[p.links[n]]:
            r.problem(f"{r.at('centres_of_curvature')}[{n}]", f"{c} is not a point of link {p.links[n]}")
            return
    if p.flat:
        if _slide(linkage, p) is None:
            r.problem(r.at("substitute_link"), f"link {p.substitute} is not a block pinned at {p.centres[0]} "
                                               f"sliding on link {j} (an RPP's block or an RPR's block on the bar {j})")
    elif p.motion == "sliding":
        assert p.substitute is not None
        ci, cj = p.centres
        length = _bar(linkage, p.substitute, ci, cj) if p.substitute not in p.links else None
        if length is None:
            r.problem(r.at("substitute_link"), f"link {p.substitute} is not a dyad's binary link {ci}{cj}: "
                                               "the substitute joins the two centres of curvature")
        elif abs(length - sum(p.radii)) > LENGTH_REL * length:
            r.problem(r.at("substitute_link"), f"|{ci}{cj}| = {length * 1e3:.6g} mm is not ρi + ρj = "
                                               f"{sum(p.radii) * 1e3:.6g} mm (convex profiles touching outside)")
        if ci == cj:
            r.problem(r.at("centres_of_curvature"), "the two centres must differ")
    else:
        assert p.contact is not None
        if j != linkage.frame_link:
            r.problem(f"{r.at('links')}[1]", f"a rolling contact on a fixed profile: the second link is the "
                                             f"frame, {linkage.frame_link}")
        elif p.contact not in linkage.frame_points:
            r.problem(r.at("contact_point"), f"{p.contact} is not a frame point")
        elif p.contact not in carried[i]:
            r.problem(r.at("contact_point"), f"{p.contact} is not carried by link {i} (its pivot there)")
        else:
            length = _bar(linkage, i, p.centres[0], p.contact)
            if length is None or abs(length - p.radii[0]) > LENGTH_REL * p.radii[0]:
                r.problem(r.at("contact_point"), f"{p.contact} is not at ρ = {p.radii[0] * 1e3:.6g} mm from "
                                                 f"{p.centres[0]} on link {i}")


# ---------------------------------------------------------------------------- rows


def _slide(linkage: Linkage, p: HigherPair) -> RPP | RPR | None:
    """The dyad whose block (the substitute) is pinned at Ci and slides on link j: a flat face's."""
    for y in linkage.dyads:
        if isinstance(y, RPP) and (y.links[0], y.p, y.links[1]) == (p.substitute, p.centres[0], p.links[1]):
            return y
        if isinstance(y, RPR) and (y.block_link, y.block_pivot, y.bar_link) == (p.substitute, p.centres[0], p.links[1]):
            return y
    return None


def geometry(p: HigherPair, at: dict[str, Any], linkage: Linkage, per_m: float = 1.0
             ) -> tuple[tuple[float, float], tuple[float, float]]:
    """The contact K and the unit common normal n̂ (from Ci towards link j's profile), from the
    points ``at`` (m, or drawing mm with ``per_m`` = 1/μl)."""
    ax, ay = (float(v) for v in at[p.centres[0]])
    if p.flat:  # n̂ ⟂ the slot; K at ρi from Ci on the face's side
        y = _slide(linkage, p)
        if isinstance(y, RPP):
            u = (math.cos(y.slot_angle), math.sin(y.slot_angle))
        else:
            assert isinstance(y, RPR)
            ox, oy = (float(v) for v in at[y.bar_pivot])
            wx, wy, e = ax - ox, ay - oy, y.offset * per_m  # X − O = t·û + e·n̂ (the offset bar)
            t = math.sqrt(max(wx * wx + wy * wy - e * e, 0.0))
            w2 = wx * wx + wy * wy or 1.0
            u = ((t * wx + e * wy) / w2, (t * wy - e * wx) / w2)
        sign = 1.0 if p.face_side == "left" else -1.0
        n = (-sign * u[1], sign * u[0])
        rho = p.radii[0] * per_m
        return (ax + rho * n[0], ay + rho * n[1]), n
    far = at[p.centres[1]] if p.contact is None else at[p.contact]
    dx, dy = float(far[0]) - ax, float(far[1]) - ay
    d = math.hypot(dx, dy) or 1.0
    rho = p.radii[0] * per_m
    return (ax + rho * dx / d, ay + rho * dy / d), (dx / d, dy / d)


def _deg(v: tuple[float, float]) -> float:
    return math.degrees(math.atan2(v[1], v[0])) % 180.0 % 180.0


def _exact_velocity(linkage: Linkage, kin: Any, link: str, x: tuple[float, float], i: int) -> np.ndarray:
    """The exact velocity (m/s) of link's point at x (m): v_P + ω k×(x − P) from one of its points."""
    if link == linkage.frame_link:
        return np.zeros(2)
    w = float(kin.omega[link][i])
    name = linkage.links()[link][0]
    px, py = kin.point[name][i]
    vx, vy = kin.vel[name][i]
    return np.array([vx - w * (x[1] - py), vy + w * (x[0] - px)])


def add_rows(an: Any) -> None:
    """Append the rows ``find`` asks of the higher pairs; bad names → SceneError."""
    from graphmech.methods.instant_centres import positions_mm
    from graphmech.problems.instant_centres.check import centres_at
    from graphmech.problems.judging import Row, split_name
    from graphmech.problems.linkage.sizes import characteristic

    scene, linkage = an.scene, an.build.linkage
    pairs = {p.name: p for p in pairs_of(scene)}
    problems: list[tuple[str, str]] = []
    multi = len(an.labels) > 1
    mu = an.scales["l"]
    for k, raw in enumerate(scene.find):
        base, at = split_name(raw)
        m = _NAME.fullmatch(base)
        if m is None:
            continue
        what, key = m.groups()
        p = pairs.get(key) or next((q for q in pairs.values() if q.name == key[::-1] or
                                    (q.links[1] + q.links[0]) == key), None)
        if p is None:
            problems.append((f"find[{k}]", f"no [[higher_pair]] of links {key}"
                                           + (f" (pairs: {', '.join(pairs)})" if pairs else "")))
            continue
        if at is not None and at not in an.labels:
            problems.append((f"find[{k}]", f"no position {at!r} (positions: {', '.join(an.labels)})"))
            continue
        for i in ([an.labels.index(at)] if at is not None else range(len(an.labels))):
            sol = an.solutions[i]
            if sol is None or not an.exact.valid[i]:
                continue
            suffix = f"@{an.labels[i]}" if multi else ""
            drawn_at = positions_mm(an.build, sol)
            exact_at = {n: (float(xy[i][0]), float(xy[i][1])) for n, xy in an.exact.point.items()}
            kx, nx = geometry(p, drawn_at, linkage, 1.0 / mu)
            ke, ne = geometry(p, exact_at, linkage)
            if what == "dir_normal":
                g, e = _deg(nx), _deg(ne)
                err = abs((g - e + 90.0) % 180.0 - 90.0) / 180.0
                an.rows.append(Row(f"dir_normal_{p.name}{suffix}", "deg", None, 1.0, g, e, err))
                continue
            ic = centres_at(an, sol)
            c = ic.centre(*p.links)
            wi, wj = (ic.motions[lid].omega if lid in ic.motions else 0.0 for lid in p.links)
            if not c.known or not all(lid in ic.motions or lid == linkage.frame_link for lid in p.links):
                an.warnings.append(f"{an.labels[i]}: the instant centre P{p.name} is undetermined: "
                                   f"v_slip_{p.name} not found")
                continue
            if c.point is not None:  # |ωi − ωj|·|Pij K|
                drawn = math.dist(c.point, kx)
                scale = abs(wi - wj) * mu
            else:  # ωi = ωj: the links translate relative to each other
                vi = ic.motions[p.links[0]].velocity(kx) if p.links[0] in ic.motions else (0.0, 0.0)
                vj = ic.motions[p.links[1]].velocity(kx) if p.links[1] in ic.motions else (0.0, 0.0)
                drawn, scale = math.hypot(vi[0] - vj[0], vi[1] - vj[1]), mu
            g = drawn * scale
            e = float(np.hypot(*(_exact_velocity(linkage, an.exact, p.links[0], ke, i)
                                 - _exact_velocity(linkage, an.exact, p.links[1], ke, i))))
            err = abs(g - e) / max(abs(e), characteristic(linkage, "m/s", an.size))
            an.rows.append(Row(f"v_slip_{p.name}{suffix}", "m/s", drawn, scale, g, e, err))
    if problems:
        raise SceneError(problems, scene.source)


# ---------------------------------------------------------------------------- drawing


def decorate(sheet: Sheet, an: Any) -> Sheet:
    """Over each mechanism panel: the substitute link thin and dashed (as the book draws it), the
    two profiles' circles of curvature, the contact K and the common normal through it."""
    from graphmech.drawing.lettering import LETTER
    from graphmech.drawing.primitives import Label, Polyline, Segment
    from graphmech.methods.instant_centres import positions_mm

    pairs = pairs_of(an.scene)
    if not pairs:
        return sheet
    panels = []
    for panel in sheet.panels:
        kind, _, label = panel.name.partition("-")
        if kind not in ("mechanism", "ic", "velocity") or label not in an.labels or \
                an.solutions[an.labels.index(label)] is None:
            panels.append(panel)
            continue
        if kind == "velocity":
            panels.append(dataclasses.replace(panel, items=panel.items + tuple(
                _images(pairs, an, an.solutions[an.labels.index(label)]))))
            continue
        at = positions_mm(an.build, an.solutions[an.labels.index(label)])
        items = list(panel.items)
        if kind == "ic":  # the instant centres' diagram, at its own μl: only the substitute is restyled
            k = an.scales["l"] / dict(panel.scales)["l"]
            at = {n: (x * k, y * k) for n, (x, y) in at.items()}
        mu = an.scales["l"]
        for p in pairs:
            a = at[p.centres[0]]
            if p.substitute is not None and not p.flat:  # the substitute link: drawn thin and dashed
                b = at[p.centres[1]]
                items = [dataclasses.replace(s, role="construction", dashed=True)
                         if isinstance(s, Segment) and s.role == "given" and {s.p0, s.p1} == {a, b} else s
                         for s in items]
            if kind == "ic":
                continue
            k, (ux, uy) = geometry(p, at, an.build.linkage, 1.0 / mu)
            for n, c in enumerate(p.centres):
                r = p.radii[n] / mu
                items.append(Polyline(tuple((at[c][0] + r * math.cos(t), at[c][1] + r * math.sin(t))
                                            for t in np.linspace(0.0, 2.0 * math.pi, 97)), "given", closed=True))
            over = 0.5 * max(p.radii) / mu
            far = at[p.centres[1]] if p.contact is None and not p.flat else k
            items.append(Segment((a[0] - over * ux, a[1] - over * uy), (far[0] + over * ux, far[1] + over * uy),
                                 "construction", dashdot=True))
            if p.contact is not None or p.flat:  # the straight profile (a fixed rack, a flat face), tangent at K
                half = 1.2 * p.radii[0] / mu
                ends = ((k[0] - half * uy, k[1] + half * ux), (k[0] + half * uy, k[1] - half * ux))
                items.append(Segment(*ends, "given"))
            if p.contact is not None:
                items += [Label("M", e, ((uy, -ux), (-uy, ux)), LETTER) for e in ends]  # the book's MM
            else:
                items.append(Label("K", k, ((ux, uy), (-ux, -uy)), LETTER))
            items.append(Label("n", (far[0] + over * ux, far[1] + over * uy), ((ux, uy), (-ux, -uy)), LETTER))
        panels.append(dataclasses.replace(panel, items=tuple(items)))
    return dataclasses.replace(sheet, panels=tuple(panels))


def _images(pairs: tuple[HigherPair, ...], an: Any, sol: Any) -> list[Any]:
    """On the velocity polygon, a rolling wheel's velocity image (速度影像): its pitch circle maps to
    the circle about its centre's image c through the contact's image (p, for a fixed track), the
    book's g3."""
    from graphmech.drawing.lettering import LETTER
    from graphmech.drawing.primitives import Label, Polyline

    out: list[Any] = []
    vel = an.build.vel
    for p in pairs:
        if p.contact is None or vel.get(p.centres[0]) not in sol.values or vel.get(p.contact) not in sol.values:
            continue
        cx, cy = (float(v) for v in sol.values[vel[p.centres[0]]])
        kx, ky = (float(v) for v in sol.values[vel[p.contact]])
        r = math.hypot(kx - cx, ky - cy)
        if r <= 1e-9:
            continue
        out.append(Polyline(tuple((cx + r * math.cos(t), cy + r * math.sin(t))
                                  for t in np.linspace(0.0, 2.0 * math.pi, 97)), "result", closed=True))
        out.append(Label(f"g{p.links[0]}", (cx + r * math.cos(1.0), cy + r * math.sin(1.0)),
                         ((math.cos(1.0), math.sin(1.0)),), LETTER))
    return out
