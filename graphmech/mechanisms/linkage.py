"""A planar linkage: frame, a driver, Assur dyads attached in order, extra points on links.

Everything here is SI (m, rad, rad/s, rad/s²) and immutable. A linkage is *structure*: it
says which points exist, which link carries them and how the dyads join them. The numbers
that change from position to position (crank angle, or a slider's displacement) are given
apart, as the driver's ``positions``.

Conventions
-----------
Angles are measured from +x, counter-clockwise positive; x to the right, y up.
A point's name is its capital letter ("B", "C"); a link's id is the book's number ("2").

Dyads (Assur groups of class II)
--------------------------------
``RRR``  P–C–Q: links ``(i, j)``; i carries P and C, j carries Q and C.
``RRP``  P–C on a guide: link i (coupler) carries P and C; j is the slider at C. The guide is on
         the frame (:class:`Guide`) or on a moving link (:class:`LinkGuide`: the slotted link drives
         the pin C); then C<j> (= C) and C<link> name the coincident points, as for PRP.
``RPR``  P and Q pivots; i is pivoted at P, j at Q, and they slide on each other along PQ.
         ``bar`` tells which of the two is the guide bar (its line passes through the
         other's pivot); the other is the block. The sliding point X is the block's pivot;
         the coincident points are X<bar> (unknown) and X<block>: v_X<bar> = v_X<block> + v_rel.
         ``offset`` e ≠ 0: an offset guide bar, its line at e to the left of its own pivot O
         (the foot F = O + e·n̂, n̂ the bar's direction û turned 90° CCW; X = F + t·û, t > 0).
``RPP``  P revolute on link i (a block); i slides in a straight slot of link j (slot angle
         fixed, j translates), j slides along a frame guide; C is j's point on the guide.
``PRP``  C revolute joining two blocks i and j; i slides on a guide of a known link, j on another
         (the tangent mechanism: a block on a turning bar, pinned to a slider on a frame guide).
         A guide is a frame :class:`Guide` or a :class:`LinkGuide`, the line through two points of
         a moving link; the coincident point of that link at C is C<link> ("C1"), and the blocks'
         own points at C are C<i>, C<j> (both C): v_C = v_C1 + v_rel (∥ the guide).

Class III group (:class:`Triad`)
--------------------------------
A ternary link carrying C, D, E, each joined by a binary link to a known point (B–C, F–D,
G–E): four links, six revolutes. It is one more entry of ``Linkage.dyads`` (the groups in
assembly order), solved as a whole — its position has no closed form. A leg may instead be a
block on a frame guide (``Triad.guides``: the IC engine's piston when EG drives): its inner joint
slides along the guide, and its ``outer`` entry repeats the inner joint (there is no outer pivot).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Literal, Union

Branch = Literal["left", "right"]


@dataclass(frozen=True)
class Guide:
    """A straight guide fixed on the frame.

    Parameters
    ----------
    through : (float, float)
        A point of the guide line, m.
    angle : float
        Direction of the guide, rad from +x CCW; displacements and slider velocities are
        positive along it.
    """

    through: tuple[float, float]
    angle: float

    @property
    def direction(self) -> tuple[float, float]:
        return (math.cos(self.angle), math.sin(self.angle))


@dataclass(frozen=True)
class LinkGuide:
    """A straight guide on a moving link: the line through two of its points, ``through`` → ``towards``.

    It turns with its link; a block sliding on it meets the Coriolis acceleration 2ω×v_rel.
    """

    link: str
    through: str
    towards: str


@dataclass(frozen=True)
class Crank:
    """A crank turning about a frame pivot: ``tip = pivot + length·(cos φ, sin φ)``."""

    link: str
    pivot: str
    tip: str
    length: float
    omega: float  # rad/s, + CCW
    epsilon: float = 0.0  # rad/s², + CCW
    kind: Literal["crank"] = "crank"


@dataclass(frozen=True)
class SliderInput:
    """A slider driven along a frame guide: ``point = guide.through + s·guide.direction``."""

    link: str
    point: str
    guide: Guide
    velocity: float  # m/s along the guide
    acceleration: float = 0.0  # m/s² along the guide
    kind: Literal["slider"] = "slider"


Driver = Union[Crank, SliderInput]


@dataclass(frozen=True)
class RRR:
    """Dyad P–C–Q with three revolutes; C to the ``branch`` side of the directed line P→Q."""

    p: str
    c: str
    q: str
    links: tuple[str, str]
    lengths: tuple[float, float]  # l_PC, l_QC  (m)
    branch: Branch = "left"
    kind: Literal["RRR"] = "RRR"


@dataclass(frozen=True)
class RRP:
    """Dyad P–C with slider C on a guide (slider-crank's coupler and slider; a slotted link's pin).

    ``branch``: C lies ahead ("forward") of or behind ("backward") the foot of the
    perpendicular from P to the guide, along the guide's direction.
    """

    p: str
    c: str
    links: tuple[str, str]  # (coupler, slider)
    length: float  # l_PC (m)
    guide: Guide | LinkGuide
    branch: Literal["forward", "backward"] = "forward"
    kind: Literal["RRP"] = "RRP"

    @property
    def coincident(self) -> tuple[str, ...]:
        """On a moving guide: the slider's point C<j> (C itself) and the guide link's C<link>."""
        g = self.guide
        return (self.c + self.links[1], self.c + g.link) if isinstance(g, LinkGuide) else ()


@dataclass(frozen=True)
class RPR:
    """Guide-bar / rocking-block dyad: i pivoted at P, j pivoted at Q, sliding along PQ (along the
    tangent from the block's pivot to the circle of radius |offset| about the bar's pivot)."""

    p: str
    q: str
    links: tuple[str, str]
    bar: Literal["first", "second"] = "first"
    offset: float = 0.0  # m: e, the bar's line to the left (+) of its own pivot, along its direction
    kind: Literal["RPR"] = "RPR"

    @property
    def bar_link(self) -> str:
        return self.links[0] if self.bar == "first" else self.links[1]

    @property
    def block_link(self) -> str:
        return self.links[1] if self.bar == "first" else self.links[0]

    @property
    def bar_pivot(self) -> str:
        return self.p if self.bar == "first" else self.q

    @property
    def block_pivot(self) -> str:
        """The sliding point X: the block's pivot, which the bar's line passes through."""
        return self.q if self.bar == "first" else self.p

    @property
    def coincident(self) -> tuple[str, str]:
        """Names of the coincident points (on the bar, on the block), e.g. ("C2", "C3")."""
        x = self.block_pivot
        return (x + self.bar_link, x + self.block_link)


@dataclass(frozen=True)
class RPP:
    """Block i pivoted at P slides in a slot of j (absolute slot angle); j slides on a frame guide.

    ``c`` is j's reference point: where the slot line through P meets the guide.
    """

    p: str
    c: str
    links: tuple[str, str]  # (block, slotted slider)
    slot_angle: float  # rad, direction of the slot line (j translates, so it is fixed)
    guide: Guide
    kind: Literal["RPP"] = "RPP"

    @property
    def coincident(self) -> tuple[str, str]:
        """(P on the block, P on the slotted link), e.g. ("B2", "B3")."""
        return (self.p + self.links[0], self.p + self.links[1])


@dataclass(frozen=True)
class PRP:
    """Blocks i and j pinned together at C, i sliding on ``guides[0]``, j on ``guides[1]``.

    Each guide is on a known link: the frame (:class:`Guide`) or a moving link
    (:class:`LinkGuide`); C is where the two guide lines meet.
    """

    c: str
    links: tuple[str, str]  # (block on guides[0], block on guides[1])
    guides: tuple[Guide | LinkGuide, Guide | LinkGuide]
    kind: Literal["PRP"] = "PRP"

    def on_guide(self, k: int) -> str | None:
        """The point of guide k's link at C ("C1"); None for a frame guide (its point is fixed)."""
        g = self.guides[k]
        return self.c + g.link if isinstance(g, LinkGuide) else None

    @property
    def coincident(self) -> tuple[str, ...]:
        """Every name this dyad defines besides C: the blocks' points C<i>, C<j> (both C) and
        the guides' links' points at C."""
        moving = tuple(n for n in (self.on_guide(0), self.on_guide(1)) if n is not None)
        return (self.c + self.links[0], self.c + self.links[1]) + moving


@dataclass(frozen=True)
class Triad:
    """A class III Assur group RRR-III: ternary link ``links[3]`` carrying ``inner`` = (C, D, E);
    binary link ``links[k]`` joins ``outer[k]`` (a known point) to ``inner[k]``.

    ``lengths`` = (l_BC, l_FD, l_GE); ``ternary`` = (l_CD, l_DE, l_EC), the ternary link's sides.
    ``start`` (m): the joints C, D, E near the wanted assembly (the book's figure) — it picks
    the assembly (of up to six) and the ternary triangle's hand (E left or right of C→D).
    ``assur``: the two binary links whose lines meet at the special (Assur) point S of the
    ternary link, by index into ``outer`` (default the first two).
    ``guides[k]``: a frame guide for a slider leg — link ``links[k]`` is a block pinned to the
    ternary link at ``inner[k]`` and sliding on that guide; then ``outer[k] == inner[k]`` and
    ``lengths[k] == 0``. Its "line" for the special point is the normal to the guide at the joint
    (the pin's velocity and tangential acceleration are along the guide).
    """

    outer: tuple[str, str, str]
    inner: tuple[str, str, str]
    links: tuple[str, str, str, str]
    lengths: tuple[float, float, float]
    ternary: tuple[float, float, float]
    start: tuple[tuple[float, float], tuple[float, float], tuple[float, float]]
    assur: tuple[int, int] = (0, 1)
    guides: tuple[Guide | None, Guide | None, Guide | None] = (None, None, None)
    kind: Literal["RRR-III"] = "RRR-III"

    def slides(self, k: int) -> bool:
        """Whether leg k is a block on a frame guide (not a binary link to an outer pivot)."""
        return self.guides[k] is not None

    @property
    def known_outer(self) -> tuple[str, ...]:
        """The outer joints the group needs known: those of its pivoted legs."""
        return tuple(o for k, o in enumerate(self.outer) if not self.slides(k))

    @property
    def hand(self) -> float:
        """+1 when E lies left of C→D in ``start`` (the ternary triangle's orientation), else −1."""
        (cx, cy), (dx, dy), (ex, ey) = self.start
        return 1.0 if (dx - cx) * (ey - cy) - (dy - cy) * (ex - cx) >= 0.0 else -1.0

    @property
    def name(self) -> str:
        """The group as the book names it by its joints, e.g. "B-C, F-D, G-E (CDE)"."""
        legs = (f"{i} on its guide" if self.slides(k) else f"{o}-{i}" for k, (o, i) in enumerate(zip(self.outer, self.inner)))
        return ", ".join(legs) + f" ({''.join(self.inner)})"


Dyad = Union[RRR, RRP, RPR, RPP, PRP, Triad]


@dataclass(frozen=True)
class LinkPoint:
    """An extra point fixed on a link, placed relative to two points of that link.

    ``position = U + along·û + left·n̂`` where û is the unit vector U→V and n̂ is û turned
    90° CCW. For a translating link with one known point, give ``base=(U,)`` and then
    ``along``/``left`` are the x/y offsets (m).
    """

    name: str
    link: str
    base: tuple[str, ...]
    along: float
    left: float


#: Any part of a linkage in its order of assembly: the driver, a dyad or a point on a link.
Part = Union[Driver, Dyad, LinkPoint]


@dataclass(frozen=True)
class Linkage:
    """A class-II linkage: frame points, a driver, dyads in assembly order, extra points."""

    frame_points: dict[str, tuple[float, float]]
    driver: Driver
    dyads: tuple[Dyad, ...] = ()
    points: tuple[LinkPoint, ...] = ()
    frame_link: str = "4"

    def __hash__(self) -> int:  # frame_points is a dict; hash by identity is enough
        return id(self)

    def links(self) -> dict[str, list[str]]:
        """Link id → the names of the points it carries, in the order they appear."""
        out: dict[str, list[str]] = {}

        def add(link: str, *names: str) -> None:
            lst = out.setdefault(link, [])
            for n in names:
                if n not in lst:
                    lst.append(n)

        d = self.driver
        if isinstance(d, Crank):
            add(d.link, d.pivot, d.tip)
        else:
            add(d.link, d.point)
        for y in self.dyads:
            if isinstance(y, RRR):
                add(y.links[0], y.p, y.c)
                add(y.links[1], y.q, y.c)
            elif isinstance(y, RRP):
                add(y.links[0], y.p, y.c)
                add(y.links[1], y.c)
                if isinstance(y.guide, LinkGuide):
                    add(y.guide.link, y.coincident[1])
            elif isinstance(y, RPR):
                add(y.bar_link, y.bar_pivot, y.coincident[0])
                add(y.block_link, y.block_pivot)
            elif isinstance(y, RPP):
                add(y.links[0], y.p)
                add(y.links[1], y.c)
            elif isinstance(y, PRP):
                add(y.links[0], y.c)
                add(y.links[1], y.c)
                for k, g in enumerate(y.guides):
                    on = y.on_guide(k)
                    if isinstance(g, LinkGuide) and on is not None:
                        add(g.link, on)
            elif isinstance(y, Triad):
                for k in range(3):
                    add(y.links[k], y.outer[k], y.inner[k])
                add(y.links[3], *y.inner)
        for pt in self.points:
            add(pt.link, pt.name)
        return out


@dataclass(frozen=True)
class Positions:
    """The driver's positions: crank angles (rad) or slider displacements (m)."""

    values: tuple[float, ...]
    labels: tuple[str, ...] = field(default=())  # e.g. ("50", "220") for name suffixes
