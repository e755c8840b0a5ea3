"""Instant centres (瞬心) of a linkage by Kennedy's theorem (三心定理), and velocities from them.

The textbook's steps, in the draftsman's order:

1. number the links (the frame too) and put them as points on a circle — the *polygon of links*
   (bookkeeping circle); every instant centre P_ij is the chord i–j;
2. the **direct** centres: a revolute joining i and j is P_ij; a sliding pair's P_ij is at
   infinity perpendicular to the guide (a point at infinity is a *direction*); a compound hinge
   gives the centre of every two of its links; draw those chords solid;
3. every other P_ij by Kennedy's theorem: P_ij lies on the line P_ik P_kj for every third link k,
   so two such lines (two triangles i-k-j and i-m-j of the polygon with the chord i–j as common
   side) meet at P_ij; draw that chord dashed and go on until every chord is drawn;
4. velocities: P_ij is the point where links i and j have the same velocity, so with the frame 1,
   ``ω_j = ω_i · P1iPij / P1jPij`` (signed lengths on the line through P1i, P1j, Pij) and the
   speed of a point X of link k is ``|ω_k|·|P1k X|``.

Points are homogeneous ``(x, y, w)`` in drawing millimetres: ``w = 1`` a point, ``w = 0`` a point
at infinity in the direction ``(x, y)``. The line through two points and the intersection of two
lines are cross products, so a line through a point at infinity (the perpendicular to a guide)
and two parallel lines meeting at infinity need no special case. What the construction cannot
decide it says: two Kennedy lines that coincide (a parallelogram's change point) leave P_ij
undetermined; a velocity ratio whose denominator vanishes (P1j = Pij: a dead centre) leaves ω_j
undetermined. Nothing is ever NaN.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from itertools import combinations
from typing import Any, Literal, Mapping

import numpy as np

from graphmech.errors import NotApplicable, OutOfDomain
from graphmech.mechanisms.linkage import (
    PRP,
    RPP,
    RPR,
    RRP,
    Linkage,
    LinkGuide,
    SliderInput,
    Triad,
)
from graphmech.methods.diagram import tangent_name
from graphmech.tolerances import COND_WARN, PARALLEL_SIN

#: Two points or lines closer than this, relative to the mechanism's drawn size, are one.
SAME_REL = 1e-9

XY = tuple[float, float]
Kind = Literal["direct", "kennedy", "undetermined"]


@dataclass(frozen=True)
class Centre:
    """One instant centre P_ij (i < j in the links' order).

    Parameters
    ----------
    links : (str, str)
        The two link ids.
    kind : {"direct", "kennedy", "undetermined"}
        How it was found.
    point : (float, float) or None
        Drawing mm at μl where finite; None at infinity or undetermined.
    direction : (float, float) or None
        Unit vector of the direction in which a centre at infinity lies (its sense is immaterial).
    via : tuple of str
        For a Kennedy centre, the two third links k, m of the lines Pik–Pkj and Pim–Pmj used;
        for a direct one, the joint it stands at ("B", or "guide" for a sliding pair).
    cond : float
        1/|sin| of the angle between the two Kennedy lines (1 for a direct centre).
    why : str
        Why it is undetermined ("" otherwise).
    """

    links: tuple[str, str]
    kind: Kind
    point: XY | None = None
    direction: XY | None = None
    via: tuple[str, ...] = ()
    cond: float = 1.0
    why: str = ""

    @property
    def at_infinity(self) -> bool:
        return self.point is None and self.direction is not None

    @property
    def known(self) -> bool:
        return self.kind != "undetermined"

    def homogeneous(self) -> np.ndarray:
        if self.point is not None:
            return np.array([self.point[0], self.point[1], 1.0])
        assert self.direction is not None
        return np.array([self.direction[0], self.direction[1], 0.0])


@dataclass(frozen=True)
class LinkMotion:
    """A link's instantaneous motion found from the centres: ``v(X) = v0 + ω·k×X`` (mm at μl).

    ``omega`` rad/s (+ CCW); ``v0`` the velocity of the drawing's origin as a point of the link, in
    drawing-mm·rad/s (multiply by μl for m/s). ``found`` says how: ("driver",) or
    (i, "P1i", "Pij", "P1j") — the link it was found from and the three centres on one line.
    ``drawn``/``scale`` give the ratio as measured: ω = drawn × scale with drawn = P1iPij (mm,
    signed) and scale = ω_i / P1jPij (1/mm, signed); None where no ratio was measured.
    """

    link: str
    omega: float
    v0: XY
    found: tuple[str, ...]
    drawn: float | None = None
    scale: float | None = None

    def velocity(self, x: XY) -> XY:
        """Velocity of the link's point at ``x`` (drawing mm), in drawing-mm·rad/s."""
        return (self.v0[0] - self.omega * x[1], self.v0[1] + self.omega * x[0])


@dataclass(frozen=True)
class InstantCentres:
    """Every instant centre of a linkage at one position and the links' motions from them.

    ``links`` in the order of the polygon of links (the frame first); ``centres`` keyed by the
    sorted pair; ``motions`` per link where the centres determine it; ``undetermined`` per link
    otherwise, with the reason; ``size`` the mechanism's drawn size, mm.
    """

    links: tuple[str, ...]
    frame: str
    centres: Mapping[tuple[str, str], Centre]
    order: tuple[tuple[str, str], ...]  # the centres in the order they were found
    motions: Mapping[str, LinkMotion]
    undetermined: Mapping[str, str]
    size: float

    def centre(self, i: str, j: str) -> Centre:
        return self.centres[pair(self.links, i, j)]

    def absolute(self, k: str) -> Centre:
        """P1k: the centre of link k with the frame."""
        return self.centre(self.frame, k)


def pair(links: tuple[str, ...], i: str, j: str) -> tuple[str, str]:
    """The pair (i, j) in polygon order."""
    return (i, j) if links.index(i) < links.index(j) else (j, i)


def centre_name(i: str, j: str) -> str:
    """``P13``; ``P1_10`` where a link id has more than one character."""
    return f"P{i}{j}" if len(i) == len(j) == 1 else f"P{i}_{j}"


def polygon_of_links(linkage: Linkage) -> tuple[str, ...]:
    """The links in the order the book numbers them: the frame, the driver, then each dyad's."""
    out = [linkage.frame_link]
    for lid in linkage.links():
        if lid not in out:
            out.append(lid)
    return tuple(sorted(out, key=lambda s: (0, int(s)) if s.isdigit() else (1, s)))


# ---------------------------------------------------------------------------- direct centres


@dataclass(frozen=True)
class Direct:
    """A direct centre: at a joint (``at`` a point name) or at infinity ⟂ a sliding pair."""

    links: tuple[str, str]
    at: str | None = None  # the joint's point name
    normal: float | None = None  # for a sliding pair: the direction of the centre, rad (⟂ guide)
    on: str | None = None  # a point of the sliding pair, to draw the arrow from
    across: tuple[str, str] | None = None  # RPR: the bar's pivot and the block's, whose line is the guide (a
    # guide on a moving link, PRP: its two points)


def direct_centres(linkage: Linkage) -> list[Direct]:
    """Every direct centre of the linkage, from its joints and sliding pairs.

    A point carried by several links (including the frame's points) is a revolute — a compound
    hinge where more than two links meet — and is the centre of every two of them.
    """
    frame = linkage.frame_link
    carriers: dict[str, list[str]] = {name: [frame] for name in linkage.frame_points}
    for lid, names in linkage.links().items():
        for n in names:
            lst = carriers.setdefault(n, [])
            if lid not in lst:
                lst.append(lid)
    out: list[Direct] = []
    seen: set[frozenset[str]] = set()
    for name, links in carriers.items():
        for i, j in combinations(links, 2):
            if i != j and frozenset((i, j)) not in seen:
                seen.add(frozenset((i, j)))
                out.append(Direct((i, j), at=name))

    def slide(i: str, j: str, guide_angle: float | None, on: str, across: tuple[str, str] | None = None) -> None:
        if frozenset((i, j)) in seen:
            return
        seen.add(frozenset((i, j)))
        normal = None if guide_angle is None else guide_angle + math.pi / 2
        out.append(Direct((i, j), normal=normal, on=on, across=across))

    d = linkage.driver
    if isinstance(d, SliderInput):
        slide(frame, d.link, d.guide.angle, d.point)
    for y in linkage.dyads:
        if isinstance(y, RRP):
            g = y.guide
            if isinstance(g, LinkGuide):  # a slotted link drives the pin C
                slide(g.link, y.links[1], None, y.c, (g.through, g.towards))
            else:
                slide(frame, y.links[1], g.angle, y.c)
        elif isinstance(y, RPR):
            # the bar's line: through its pivot, or (an offset bar) through its foot F, the diagram's own point
            start = tangent_name(y) if y.offset != 0.0 else y.bar_pivot
            slide(y.links[0], y.links[1], None, y.block_pivot, (start, y.block_pivot))
        elif isinstance(y, RPP):
            slide(y.links[0], y.links[1], y.slot_angle, y.p)
            slide(frame, y.links[1], y.guide.angle, y.c)
        elif isinstance(y, PRP):  # each block slides on its guide's link; the pin C is P_ij (a joint)
            for block, g in zip(y.links, y.guides):
                if isinstance(g, LinkGuide):
                    slide(g.link, block, None, y.c, (g.through, g.towards))
                else:
                    slide(frame, block, g.angle, y.c)
        elif isinstance(y, Triad):  # a slider leg: its block slides on the frame guide at its pin
            for block, on, pin in zip(y.links, y.guides, y.inner):
                if on is not None:
                    slide(frame, block, on.angle, pin)
    return out


# ---------------------------------------------------------------------------- homogeneous kernels


def _line(p: np.ndarray, q: np.ndarray, size: float) -> np.ndarray | None:
    """The line through two homogeneous points, normalised; None if they are one point.

    A line is ``(a, b, c)`` with ``a·x + b·y + c·w = 0``, scaled so that ``|(a, b)| = 1``; the
    line at infinity (through two points at infinity) is ``(0, 0, 1)``.
    """
    line = np.cross(p, q)
    if p[2] == 0.0 and q[2] == 0.0:  # two directions: the line at infinity, unless they are one
        return np.array([0.0, 0.0, 1.0]) if abs(line[2]) > PARALLEL_SIN else None
    ab = math.hypot(line[0], line[1])  # two finite points: their distance
    if p[2] != 0.0 and q[2] != 0.0 and ab <= SAME_REL * size:
        return None
    return line / ab


def _meet(l1: np.ndarray, l2: np.ndarray, size: float) -> tuple[np.ndarray | None, float]:
    """Where two lines meet (homogeneous, normalised) and the condition 1/|sin| of their angle.

    Returns ``(None, inf)`` when the lines are one line (the centre is not determined by them).
    """
    x = np.cross(l1, l2)
    inf1, inf2 = l1[0] == l1[1] == 0.0, l2[0] == l2[1] == 0.0
    if inf1 and inf2:
        return None, math.inf
    if inf1 or inf2:  # a finite line meets the line at infinity in its own direction
        other = l2 if inf1 else l1
        return np.array([-other[1], other[0], 0.0]), 1.0
    s = l1[0] * l2[1] - l1[1] * l2[0]  # sin of the angle between them
    if abs(s) <= PARALLEL_SIN:
        same_sense = l1[0] * l2[0] + l1[1] * l2[1] > 0.0
        gap = abs(l1[2] - l2[2]) if same_sense else abs(l1[2] + l2[2])
        if gap <= SAME_REL * size:
            return None, math.inf
        return np.array([-l1[1], l1[0], 0.0]), 1.0  # a direction: as sure as the lines' own
    return np.array([x[0] / x[2], x[1] / x[2], 1.0]), 1.0 / abs(s)


def _as_centre(links: tuple[str, str], h: np.ndarray, kind: Kind, via: tuple[str, ...], cond: float) -> Centre:
    if h[2] == 0.0:
        n = math.hypot(h[0], h[1])
        dx, dy = h[0] / n, h[1] / n
        if dx < 0.0 or (dx == 0.0 and dy < 0.0):  # one of the two senses, always the same one
            dx, dy = -dx, -dy
        return Centre(links, kind, None, (float(dx) + 0.0, float(dy) + 0.0), via, cond)
    return Centre(links, kind, (float(h[0]), float(h[1])), None, via, cond)


# ---------------------------------------------------------------------------- the construction


def instant_centres(linkage: Linkage, pos: Mapping[str, XY], driver_omega: float | None = None,
                    driver_velocity: float | None = None, mu_l: float = 1.0) -> InstantCentres:
    """All N(N−1)/2 instant centres at one position, and every link's motion from them.

    Parameters
    ----------
    linkage : Linkage
        The mechanism (its structure: links, joints, guides).
    pos : mapping of str to (float, float)
        Every point's position on the kinematic diagram, drawing mm (as the construction drew it).
    driver_omega, driver_velocity : float, optional
        The driver's ω (rad/s) for a crank; v (m/s along the guide) for a driven slider. Taken
        from the linkage's driver when not given.
    mu_l : float
        μl, m/mm: converts a driven slider's m/s to drawing-mm·rad/s units.

    Returns
    -------
    InstantCentres

    Examples
    --------
    A four-bar drawn at μl = 0.001 m/mm with the crank AB and the rocker DC both upright
    (frame 1, crank 2, coupler 3, rocker 4): AB ∥ DC, so P13 is at infinity, straight up.

    >>> import math
    >>> from graphmech.mechanisms.linkage import Crank, Linkage, RRR
    >>> fb = Linkage({"A": (0.0, 0.0), "D": (0.12, 0.0)}, Crank("2", "A", "B", 0.06, 10.0),
    ...              (RRR("B", "C", "D", ("3", "4"), (math.hypot(0.12, 0.03), 0.09)),), frame_link="1")
    >>> ic = instant_centres(fb, {"A": (0, 0), "D": (120, 0), "B": (0, 60), "C": (120, 90)})
    >>> ic.centre("1", "3").direction, ic.centre("2", "4").point
    ((0.0, 1.0), (-240.0, 0.0))
    >>> ic.motions["3"].omega, ic.motions["4"].omega  # ω4 = ω2·P12P24/P14P24 = 10·240/360
    (0.0, 6.666666666666667)
    """
    frame = linkage.frame_link
    links = polygon_of_links(linkage)
    pts = [p for p in pos.values()]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    size = max(math.hypot(max(xs) - min(xs), max(ys) - min(ys)), 1e-9) if pts else 1.0

    centres: dict[tuple[str, str], Centre] = {}
    order: list[tuple[str, str]] = []
    for dc in direct_centres(linkage):
        key = pair(links, *dc.links)
        if key in centres:
            continue
        if dc.at is not None:
            c = Centre(key, "direct", (float(pos[dc.at][0]), float(pos[dc.at][1])), None, (dc.at,))
        else:
            if dc.normal is not None:
                ang = dc.normal
            else:  # RPR: the bar's line (through both pivots, or F and X) (PRP: the guide's two points)
                (p, q) = dc.across or ("", "")
                ang = math.atan2(pos[q][1] - pos[p][1], pos[q][0] - pos[p][0]) + math.pi / 2
            c = _as_centre(key, np.array([math.cos(ang), math.sin(ang), 0.0]), "direct", ("guide",), 1.0)
        centres[key] = c
        order.append(key)

    kennedy(links, centres, order, size)
    motions, undetermined = _motions(linkage, links, centres, pos, driver_omega, driver_velocity, mu_l, size)
    return InstantCentres(links, frame, centres, tuple(order), motions, undetermined, size)


def kennedy(links: tuple[str, ...], centres: dict[tuple[str, str], Centre], order: list[tuple[str, str]],
            size: float) -> None:
    """Complete ``centres`` (keyed by :func:`pair`, the direct ones given) by Kennedy's theorem, in place.

    Every missing P_ij lies on the line P_ik P_kj for each third link k; two distinct lines fix it
    (the best-conditioned pair of them is kept). What no two lines fix is left "undetermined" with
    the reason. ``order`` receives the keys in the order they were found. Used by
    :func:`instant_centres` (a linkage) and by a scene that states its direct centres itself
    (graphmech.problems.centres: wheels in rolling contact).
    """
    # Kennedy: P_ij on the lines P_ik–P_kj; two distinct lines fix it. Go round until no chord
    # can be added (a draftsman's passes over the polygon of links).
    unknown = [key for key in combinations(links, 2) if key not in centres]
    why: dict[tuple[str, str], str] = {}
    progress = True
    while unknown and progress:
        progress = False
        for key in list(unknown):
            i, j = key
            lines = []
            for k in links:
                if k in key:
                    continue
                a, b = centres.get(pair(links, i, k)), centres.get(pair(links, k, j))
                if a is None or b is None:
                    continue
                line = _line(a.homogeneous(), b.homogeneous(), size)
                if line is None:
                    why[key] = (f"{centre_name(*a.links)} and {centre_name(*b.links)} coincide, so they "
                                "give no line")
                    continue
                lines.append((k, line))
            found = None
            for (k, l1), (m, l2) in combinations(lines, 2):
                h, cond = _meet(l1, l2, size)
                if h is None:
                    why[key] = (f"the lines {centre_name(*pair(links, i, k))}{centre_name(*pair(links, k, j))} and "
                                f"{centre_name(*pair(links, i, m))}{centre_name(*pair(links, m, j))} coincide")
                    continue
                if found is None or cond < found[1]:
                    found = (_as_centre(key, h, "kennedy", (k, m), cond), cond)
                    if cond < COND_WARN:
                        break
            if found is not None:
                centres[key] = found[0]
                order.append(key)
                unknown.remove(key)
                progress = True
    for key in unknown:
        centres[key] = Centre(key, "undetermined", why=why.get(key, "fewer than two Kennedy lines through it"))
        order.append(key)


def _motions(linkage: Linkage, links: tuple[str, ...], centres: Mapping[tuple[str, str], Centre],
             pos: Mapping[str, XY], driver_omega: float | None, driver_velocity: float | None,
             mu_l: float, size: float) -> tuple[dict[str, LinkMotion], dict[str, str]]:
    """Each link's ω (and velocity field) from the driver's, by ``ω_j = ω_i·P1iPij/P1jPij``."""
    frame = linkage.frame_link
    d = linkage.driver
    motions: dict[str, LinkMotion] = {frame: LinkMotion(frame, 0.0, (0.0, 0.0), ("frame",))}
    if isinstance(d, SliderInput):
        v = (driver_velocity if driver_velocity is not None else d.velocity) / mu_l
        motions[d.link] = LinkMotion(d.link, 0.0, (v * math.cos(d.guide.angle), v * math.sin(d.guide.angle)),
                                     ("driver",))
    else:
        w = driver_omega if driver_omega is not None else d.omega
        a = pos[d.pivot]
        motions[d.link] = LinkMotion(d.link, w, (w * a[1], -w * a[0]), ("driver",))
    return motions_from(links, frame, centres, motions, size)


def motions_from(links: tuple[str, ...], frame: str, centres: Mapping[tuple[str, str], Centre],
                 motions: dict[str, LinkMotion], size: float) -> tuple[dict[str, LinkMotion], dict[str, str]]:
    """Every link's motion from the known ones (``motions``: the frame's and the driver's), by
    ``ω_j = ω_i·P1iPij/P1jPij`` through the three centres on one line; the links left
    undetermined, with the reason. ``motions`` is completed in place and returned.
    """
    reasons: dict[str, str] = {}
    progress = True
    while progress:
        progress = False
        for j in links:
            if j in motions:
                continue
            p1j = centres[pair(links, frame, j)]
            if not p1j.known:
                reasons[j] = f"{centre_name(*p1j.links)} is undetermined"
                continue
            for i in links:
                if i not in motions or i == frame:
                    continue
                pij = centres[pair(links, i, j)]
                if not pij.known:
                    reasons[j] = f"{centre_name(*pij.links)} is undetermined"
                    continue
                mi = motions[i]
                found = _motion_from(j, i, mi, centres[pair(links, frame, i)], pij, p1j, size)
                if isinstance(found, str):
                    reasons[j] = found
                    continue
                motions[j] = found
                reasons.pop(j, None)
                progress = True
                break
    undetermined = {j: reasons.get(j, "no link with a known motion shares a centre with it")
                    for j in links if j not in motions}
    return motions, undetermined


def _motion_from(j: str, i: str, mi: LinkMotion, p1i: Centre, pij: Centre, p1j: Centre,
                 size: float) -> LinkMotion | str:
    """Link j's motion from link i's, through P1i, Pij, P1j (on one line by Kennedy)."""
    names = (i, centre_name(*p1i.links), centre_name(*pij.links), centre_name(*p1j.links))
    if pij.at_infinity:  # i and j translate relative to each other: same ω
        if p1j.at_infinity:
            return f"{names[2]} and {names[3]} are both at infinity"
        assert p1j.point is not None
        x = p1j.point
        return LinkMotion(j, mi.omega, (mi.omega * x[1], -mi.omega * x[0]), names, None, None)
    assert pij.point is not None
    v = mi.velocity(pij.point)  # Pij moves alike as a point of i and of j
    if p1j.at_infinity:  # j translates with the velocity of Pij
        return LinkMotion(j, 0.0, v, names, None, None)
    assert p1j.point is not None
    rx, ry = pij.point[0] - p1j.point[0], pij.point[1] - p1j.point[1]
    r = math.hypot(rx, ry)
    if r <= SAME_REL * size:
        if math.hypot(*v) <= SAME_REL * size * max(abs(mi.omega), 1e-300):
            return (f"{names[2]} coincides with {names[3]} and stands still: "
                    f"ω{j} = ω{i}·{names[1]}{names[2]}/{names[3]}{names[2]} is 0/0")
        return (f"{names[2]} coincides with {names[3]} but moves: a dead centre, "
                f"ω{j} = ω{i}·{names[1]}{names[2]}/{names[3]}{names[2]} has a zero denominator")
    ux, uy = rx / r, ry / r
    w = (rx * v[1] - ry * v[0]) / (r * r)
    drawn = scale = None
    if p1i.point is not None:  # the book's ratio: signed lengths along the line through the three
        drawn = (pij.point[0] - p1i.point[0]) * ux + (pij.point[1] - p1i.point[1]) * uy
        scale = mi.omega / r
    x = p1j.point
    return LinkMotion(j, w, (w * x[1], -w * x[0]), names, drawn, scale)


# ---------------------------------------------------------------------------- over many positions at once


@dataclass(frozen=True, eq=False)
class CentresBatch:
    """Every instant centre and every link's motion at N positions (arrays over the positions).

    ``centres[key]`` is (N, 3) homogeneous as :meth:`Centre.homogeneous` — ``(x, y, 1)`` a point,
    ``(dx, dy, 0)`` the unit direction of a centre at infinity, ``(0, 0, 0)`` undetermined;
    ``omega[k]`` (N,) rad/s and ``v0[k]`` (N, 2) as :class:`LinkMotion`, 0 where ``determined[k]`` is
    False. ``by_position`` lists the positions constructed one by one (a degenerate centre there).
    """

    links: tuple[str, ...]
    frame: str
    order: tuple[tuple[str, str], ...]
    centres: Mapping[tuple[str, str], np.ndarray]
    omega: Mapping[str, np.ndarray]
    v0: Mapping[str, np.ndarray]
    determined: Mapping[str, np.ndarray]
    by_position: tuple[int, ...]

    def velocity(self, link: str, x: Any) -> np.ndarray:
        """Velocity (N, 2) of the link's point at ``x`` ((N, 2) or a pair of (N,) arrays), drawing-mm·rad/s."""
        xx, xy = (x[:, 0], x[:, 1]) if isinstance(x, np.ndarray) and x.ndim == 2 else x
        w, v0 = self.omega[link], self.v0[link]
        return np.stack([v0[:, 0] - w * xy, v0[:, 1] + w * xx], axis=1)


class _Unbatched(Exception):
    """The linkage's recipe is not one the array path follows (a line at infinity, a centre left open)."""


#: Thresholds are tested with this margin on the array path: a position near one (where a float
#: rounded differently might decide otherwise) is constructed one by one, as :func:`instant_centres`.
_MARGIN = 4.0

_H = tuple[Any, Any, float]  # x, y (arrays or numbers) and w, the same at every position


def _hypot(a: Any, b: Any) -> Any:
    # math.hypot, not np.hypot: they differ in the last bit at ~0.5 % of arguments, and the array
    # path must give the per-position construction's numbers exactly
    if np.ndim(a) == 0 and np.ndim(b) == 0:
        return math.hypot(a, b)
    n = max(np.size(a), np.size(b))
    return np.fromiter(map(math.hypot, np.broadcast_to(a, (n,)).tolist(), np.broadcast_to(b, (n,)).tolist()),
                       float, n)


def instant_centres_batch(linkage: Linkage, pos: Mapping[str, tuple[Any, Any]], n: int,
                          driver_omega: float | None = None, driver_velocity: float | None = None,
                          mu_l: float = 1.0) -> CentresBatch:
    """:func:`instant_centres` at n positions at once, with exactly its numbers.

    Kennedy's order — which two lines meet at which centre, and through which centres each
    link's ω is found — is the same at every position where no centre degenerates, so it is worked
    out once from the structure (as :func:`kennedy` and :func:`motions_from` would go) and its
    lines and meets are evaluated as array operations in the same floating-point steps. A position
    where a step is near a threshold (two centres in one point, parallel or ill-conditioned Kennedy
    lines, a dead centre) is constructed one by one by :func:`instant_centres`, as is every position
    of a linkage whose order includes a line at infinity or leaves a centre undetermined.

    Parameters
    ----------
    pos : mapping of str to (x, y)
        Every point of the kinematic diagram, drawing mm; x and y arrays of length n or numbers
        (a frame point), as :meth:`graphmech.construction.graph.Plan.evaluate_batch` gives them.
    n : int
        The number of positions.

    Examples
    --------
    >>> from graphmech.mechanisms.linkage import Crank, Linkage, RRR
    >>> fb = Linkage({"A": (0.0, 0.0), "D": (0.12, 0.0)}, Crank("2", "A", "B", 0.06, 10.0),
    ...              (RRR("B", "C", "D", ("3", "4"), (math.hypot(0.12, 0.03), 0.09)),), frame_link="1")
    >>> cb = instant_centres_batch(fb, {"A": (0.0, 0.0), "D": (120.0, 0.0), "B": (np.array([0.0, 60.0]),
    ...     np.array([60.0, 0.0])), "C": (np.array([120.0, 150.0]), np.array([90.0, 80.0]))}, 2)
    >>> cb.by_position, float(cb.omega["4"][0])  # P13 at infinity at the first: constructed alone
    ((0,), 6.666666666666667)
    """
    names = list(pos)
    xy = {k: (_coord(pos[k][0]), _coord(pos[k][1])) for k in names}  # a frame point stays a number
    frame = linkage.frame_link
    links = polygon_of_links(linkage)
    keys = list(combinations(links, 2))
    out_c = {key: np.zeros((n, 3)) for key in keys}
    out_w = {k: np.zeros(n) for k in links}
    out_v = {k: np.zeros((n, 2)) for k in links}
    out_d = {k: np.zeros(n, dtype=bool) for k in links}
    try:
        with np.errstate(divide="ignore", invalid="ignore"):  # at a degenerate position: constructed alone
            order, ok = _batched(linkage, links, xy, n, driver_omega, driver_velocity, mu_l, out_c, out_w, out_v, out_d)
    except _Unbatched:
        order, ok = (), np.zeros(n, dtype=bool)
    alone = tuple(int(i) for i in np.flatnonzero(~ok))
    for i in alone:
        ic = instant_centres(linkage, {k: (_at(xy[k][0], i), _at(xy[k][1], i)) for k in names},
                             driver_omega, driver_velocity, mu_l)
        order = order or ic.order
        for key, c in ic.centres.items():
            out_c[key][i] = c.homogeneous() if c.known else 0.0
        for k in links:
            m = ic.motions.get(k)
            out_d[k][i] = m is not None
            out_w[k][i], out_v[k][i] = (m.omega, m.v0) if m is not None else (0.0, (0.0, 0.0))
    return CentresBatch(links, frame, tuple(order), out_c, out_w, out_v, out_d, alone)


def _coord(v: Any) -> Any:
    return float(v) if np.ndim(v) == 0 else np.asarray(v, dtype=float)


def _at(v: Any, i: int) -> float:
    return float(v) if np.ndim(v) == 0 else float(v[i])


def _batched(linkage: Linkage, links: tuple[str, ...], xy: Mapping[str, tuple[np.ndarray, np.ndarray]], n: int,
             driver_omega: float | None, driver_velocity: float | None, mu_l: float,
             out_c: dict[tuple[str, str], np.ndarray], out_w: dict[str, np.ndarray], out_v: dict[str, np.ndarray],
             out_d: dict[str, np.ndarray]) -> tuple[tuple[tuple[str, str], ...], np.ndarray]:
    """The array path of :func:`instant_centres_batch`: fills the outputs, returns the order and
    which positions it decided (the others are left to the per-position construction)."""
    frame = linkage.frame_link
    if n == 0 or not xy:
        raise _Unbatched("no positions")
    xs, ys = np.empty((len(xy), n)), np.empty((len(xy), n))
    for row, (x, y) in enumerate(xy.values()):
        xs[row], ys[row] = x, y
    size = np.maximum(np.hypot(xs.max(0) - xs.min(0), ys.max(0) - ys.min(0)), 1e-9)  # thresholds only
    ok = np.ones(n, dtype=bool)
    H: dict[tuple[str, str], _H] = {}
    order: list[tuple[str, str]] = []
    for dc in direct_centres(linkage):
        key = pair(links, *dc.links)
        if key in H:
            continue
        if dc.at is not None:
            H[key] = (xy[dc.at][0], xy[dc.at][1], 1.0)
        elif dc.normal is not None:
            u = _as_centre(key, np.array([math.cos(dc.normal), math.sin(dc.normal), 0.0]), "direct", (), 1.0).direction
            assert u is not None
            H[key] = (np.full(n, u[0]), np.full(n, u[1]), 0.0)
        else:  # the bar's line turns with the position: its normal position by position, as the construction
            (p, q) = dc.across or ("", "")
            dirs = [_as_centre(key, np.array([math.cos(a), math.sin(a), 0.0]), "direct", (), 1.0).direction
                    for a in (math.atan2(qy - py, qx - px) + math.pi / 2 for px, py, qx, qy in
                              zip(*(np.broadcast_to(c, (n,)).tolist() for c in (*xy[p], *xy[q]))))]
            arr = np.array(dirs, dtype=float).reshape(n, 2)
            H[key] = (arr[:, 0], arr[:, 1], 0.0)
        order.append(key)

    def line(a: _H, b: _H) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        if a[2] == 0.0 and b[2] == 0.0:
            raise _Unbatched("a line at infinity")
        l0, l1, l2 = a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]
        ab = _hypot(l0, l1)
        if a[2] != 0.0 and b[2] != 0.0:
            ok[ab <= _MARGIN * SAME_REL * size] = False
        return l0 / ab, l1 / ab, l2 / ab

    # Kennedy's order, as kennedy() goes when every line is drawn and the first two meet well
    unknown = [key for key in combinations(links, 2) if key not in H]
    progress = True
    while unknown and progress:
        progress = False
        for key in list(unknown):
            i, j = key
            third = [k for k in links if k not in key and pair(links, i, k) in H and pair(links, k, j) in H]
            if len(third) < 2:
                continue
            (m1, m2) = [line(H[pair(links, i, k)], H[pair(links, k, j)]) for k in third[:2]]
            x0 = m1[1] * m2[2] - m1[2] * m2[1]
            x1 = m1[2] * m2[0] - m1[0] * m2[2]
            s = m1[0] * m2[1] - m1[1] * m2[0]
            ok[~(np.abs(s) > _MARGIN * PARALLEL_SIN)] = False
            if len(third) > 2:  # kennedy() would try another pair of lines where these meet badly
                ok[~(np.abs(s) * COND_WARN > _MARGIN)] = False
            H[key] = (x0 / s, x1 / s, 1.0)
            order.append(key)
            unknown.remove(key)
            progress = True
    if unknown:
        raise _Unbatched("a centre no two lines fix")

    # each link's motion, as motions_from() goes
    d = linkage.driver
    W: dict[str, Any] = {frame: 0.0}
    V: dict[str, tuple[Any, Any]] = {frame: (0.0, 0.0)}
    if isinstance(d, SliderInput):
        v = (driver_velocity if driver_velocity is not None else d.velocity) / mu_l
        W[d.link], V[d.link] = 0.0, (v * math.cos(d.guide.angle), v * math.sin(d.guide.angle))
    else:
        w = driver_omega if driver_omega is not None else d.omega
        W[d.link], V[d.link] = w, (w * xy[d.pivot][1], -w * xy[d.pivot][0])
    progress = True
    while progress:
        progress = False
        for j in links:
            if j in W:
                continue
            p1j = H[pair(links, frame, j)]
            for i in links:
                if i not in W or i == frame:
                    continue
                pij = H[pair(links, i, j)]
                wi, vi = W[i], V[i]
                if pij[2] == 0.0:  # i and j translate relative to each other
                    if p1j[2] == 0.0:
                        continue
                    W[j], V[j] = wi, (wi * p1j[1], -(wi * p1j[0]))
                else:
                    vx, vy = vi[0] - wi * pij[1], vi[1] + wi * pij[0]
                    if p1j[2] == 0.0:
                        W[j], V[j] = 0.0, (vx, vy)
                    else:
                        rx, ry = pij[0] - p1j[0], pij[1] - p1j[1]
                        r = _hypot(rx, ry)
                        ok[r <= _MARGIN * SAME_REL * size] = False
                        w = (rx * vy - ry * vx) / (r * r)
                        W[j], V[j] = w, (w * p1j[1], -w * p1j[0])
                progress = True
                break
    if len(W) < len(links):
        raise _Unbatched("a link's motion no centre gives")
    for key in order:
        h = H[key]
        out_c[key][:, 0], out_c[key][:, 1], out_c[key][:, 2] = h
    for k in links:
        out_w[k][:] = W[k]
        out_v[k][:, 0], out_v[k][:, 1] = V[k]
        out_d[k][:] = True
    return tuple(order), ok


def least_speed_on_line(ic: InstantCentres, link: str, a: XY, b: XY) -> tuple[float, float, XY] | str:
    """The point of line AB (fixed on ``link``) with the least speed: the foot of the ⟂ from P1k.

    Returns ``(s, distance, foot)``: ``s`` the foot's signed distance from A along A→B (mm),
    ``distance`` from P1k to the line (mm; the speed is |ω|·distance·μl), or the reason why there
    is no single such point (a translating link: every point moves alike).
    """
    if link not in ic.motions:
        return ic.undetermined.get(link, "its motion is undetermined")
    p1k = ic.absolute(link)
    n = math.hypot(b[0] - a[0], b[1] - a[1])
    if n == 0.0:
        return "the two points coincide"
    ux, uy = (b[0] - a[0]) / n, (b[1] - a[1]) / n
    if p1k.point is None or ic.motions[link].omega == 0.0:
        return f"link {link} translates here: every point of it has the same speed"
    s = (p1k.point[0] - a[0]) * ux + (p1k.point[1] - a[1]) * uy
    foot = (a[0] + s * ux, a[1] + s * uy)
    dist = abs((p1k.point[0] - a[0]) * uy - (p1k.point[1] - a[1]) * ux)
    return s, dist, foot


# ---------------------------------------------------------------------------- helpers on the linkage


def positions_mm(build: Any, sol: Any) -> dict[str, tuple[float, float]]:
    """Every point of the kinematic diagram as the construction drew it (mm)."""
    return {name: (float(sol.values[slot][0]), float(sol.values[slot][1]))
            for name, slot in build.mech.items() if slot in sol.values}


def point_names(linkage: Linkage) -> set[str]:
    """Every named point of the linkage (the frame's too)."""
    names = set(linkage.frame_points)
    for pts in linkage.links().values():
        names.update(pts)
    return names


def split_line(text: str, names: set[str]) -> tuple[str, str] | None:
    """``"BC"`` → ``("B", "C")``: the one split into two known points."""
    splits = [(text[:k], text[k:]) for k in range(1, len(text)) if text[:k] in names and text[k:] in names]
    return splits[0] if len(splits) == 1 else None


def common_link(linkage: Linkage, a: str, b: str) -> str | None:
    """The moving link that carries both points, if any."""
    for lid, pts in linkage.links().items():
        if lid != linkage.frame_link and a in pts and b in pts:
            return lid
    return None


def signed_rate(linkage: Linkage, x: str) -> tuple[str, str, tuple[float, float] | None]:
    """Which signed rate vanishes with v_X: ("omega", link, None) for a point of a link pivoted on the
    frame, ("slide", link, guide direction) for a slider on a frame guide."""
    frame = linkage.frame_link
    carriers = [lid for lid, pts in linkage.links().items() if x in pts and lid != frame]
    if x in linkage.frame_points:
        raise NotApplicable(f"{x} is a point of the frame: its velocity is always 0")
    if not carriers:
        raise OutOfDomain(f"no point {x!r} in the linkage")
    for dc in direct_centres(linkage):
        if frame not in dc.links:
            continue
        lid = dc.links[0] if dc.links[1] == frame else dc.links[1]
        if lid not in carriers:
            continue
        if dc.at is not None:
            return "omega", lid, None
        assert dc.normal is not None
        return "slide", lid, (math.sin(dc.normal), -math.cos(dc.normal))
    raise NotApplicable(f"v_{x} vanishes only where {x} happens to be the instant centre of its link with the frame, "
                     f"which moves: choose a point of a link pivoted on the frame or of a slider on a frame guide")


__all__ = ["Centre", "InstantCentres", "LinkMotion", "Direct", "centre_name", "common_link", "direct_centres",
           "CentresBatch", "instant_centres", "instant_centres_batch", "kennedy", "least_speed_on_line", "motions_from", "pair", "point_names",
           "polygon_of_links", "positions_mm", "signed_rate", "split_line"]
