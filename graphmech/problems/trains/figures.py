"""The figures of a gear-train scene: the schematic in the book's symbols and the velocity diagram.

schematic
    the train at μl in the symbols of GB/T 4460 as 孙桓 draws them: a spur gear seen from the side
    a narrow rectangle across its shaft, as high as its pitch diameter (meshing gears touch at the
    pitch point, marked by a short dash-dot pitch line); an internal gear its two rims, the teeth
    inward, joined by its web (a bracket); shafts thick, in bearings on the hatched frame at their
    ends, a hollow shaft drawn as two lines round the shaft inside it; the carrier H a crank from
    its shaft to the planet's pin; a fixed member hatched to the frame; a bevel gear a trapezoid
    toward its cone's apex; a worm a rectangle with its thread lines (slanting as its hand), a gear
    seen along its axis a circle (dashed where a nearer one hides it). The axial positions are not to
    scale (one slot per mesh stage; a spatial mesh's gears where the mesh puts them).
    Every moving member has its arrow of rotation: in the side view a straight arrow showing where
    its near side moves (a positive speed along +x: down), on a gear seen along its axis a curved
    arrow (positive along +z: counter-clockwise).
velocity
    the book's velocity diagram (:mod:`graphmech.methods.train_velocity`) beside the side view, at
    the same μl for the heights and μv for the velocities: the line of centres, each pitch point's
    velocity, each member's velocity line labelled with its name; below, the pole O, the ω line at
    the pole distance H, the rays parallel to the velocity lines and their cuts, the lengths ℓ and
    ω = μv·ℓ/(μl·H) in the notes.
"""
from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from graphmech.drawing.lettering import LETTER, number, scale_text
from graphmech.drawing.notation import word
from graphmech.drawing.primitives import (
    XY,
    ArcArrow,
    Arrow,
    Circle,
    GuideLine,
    Label,
    Panel,
    Polyline,
    Primitive,
    Segment,
    Sheet,
)
from graphmech.errors import OutOfDomain
from graphmech.exact.gear_train import solve
from graphmech.mechanisms.gear_train import GearTrain
from graphmech.methods.train_layout import TrainLayout, prime
from graphmech.methods.train_velocity import TrainVelocityDiagram
from graphmech.problems.gears.figures import dimension
from graphmech.problems.kind import Footer
from graphmech.problems.reader import Scene, page_size
from graphmech.problems.trains.diagram import OMEGA_MM, SLOT_MM, drawn
from graphmech.problems.trains.scene import TrainScene

#: The train's words (laid out as graphmech.drawing.notation.WORDS: English, 中文, русский).
TRAIN_WORDS: dict[str, tuple[str, str, str]] = {
    "schematic": ("Schematic of the train", "轮系运动简图", "Кинематическая схема передачи"),
    "velocity": ("Velocity diagram", "速度图", "План скоростей"),
    "not axial": ("axial positions not to scale", "轴向位置未按比例", "осевые размеры не в масштабе"),
    "false position": ("the loop closed by false position (trial line «m»)", "封闭环路用试位法求得（试作 «m» 的速度线）",
                       "контур замкнут методом ложного положения (пробная линия «m»)"),
    "clipped": ("the rays of «m» clipped at the ω line's end (ℓ above: H is chosen for the speeds asked)",
                "«m»的射线在ω线端部截断（ℓ见上；极距H按所求转速选取）",
                "лучи «m» обрезаны у конца прямой ω (ℓ выше: H выбрано для искомых скоростей)"),
    "spatial": ("a spatial train: no velocity diagram (its axes are not parallel)",
                "空间轮系：各轴不平行，不作速度图", "пространственная передача: план скоростей не строится"),
}

#: The paper sizes of the symbols, mm (the axial pitch of the slots: diagram.SLOT_MM): a gear's width, a ring's rim,
#: a shaft's overhang past its last gear, the gap of a hollow shaft, a bearing's box.
GEAR_W, RIM_T, OVERHANG, HOLLOW = 3.0, 2.0, 11.0, 1.0
BEARING = (4.0, 3.0)
#: Where a carrier's arm and a ring's web stand from their slot's middle (fractions of a slot).
ARM_AT, WEB_AT = 0.3, 0.45
#: A worm's half length in its radii.
WORM_L = 2.2
#: A rotation arrow's length, mm.
TURN_MM = 6.0
#: The ω line's reach either side of the pole's foot, mm: a ray cutting it farther is drawn clipped there.
CLIP_MM = OMEGA_MM + 10.0


def train_word(key: str, notation: str = "en") -> str:
    return word(key, notation, TRAIN_WORDS)


@dataclass(frozen=True)
class Schematic:
    """The schematic's items; ``arrows`` each moving member's arrow of rotation (for the tests:
    a straight arrow's direction, a curved one's sweep)."""

    items: tuple[Primitive, ...]
    arrows: Mapping[str, Arrow | ArcArrow]


def _v(p: XY, q: XY, k: float = 1.0) -> XY:
    return (p[0] + k * q[0], p[1] + k * q[1])


def _rect(c: XY, e: XY, half_along: float, lo: float, hi: float) -> Polyline:
    """A rectangle along ``e`` (unit) about the point c: ±half_along along e, lo…hi across it."""
    n = (-e[1], e[0])
    pts = [_v(_v(c, e, s * half_along), n, t) for s, t in ((-1, lo), (1, lo), (1, hi), (-1, hi))]
    return Polyline(tuple(pts), "given", closed=True)


def hidden(q: XY, near: Sequence[tuple[XY, float]]) -> bool:
    """Whether the paper point q lies inside one of the nearer discs."""
    return any(math.dist(q, c) < r for c, r in near)


def _hidden_circle(c: XY, R: float, near: Sequence[tuple[XY, float]], n: int = 240) -> list[Primitive]:
    """A circle behind nearer discs: solid where seen, dashed where hidden (the drawing's hidden
    line), as runs of a polyline through n points."""
    pts = [(c[0] + R * math.cos(2 * math.pi * k / n), c[1] + R * math.sin(2 * math.pi * k / n)) for k in range(n)]
    flags = [hidden(q, near) for q in pts]
    start = next((k for k in range(n) if flags[k] != flags[k - 1]), 0)
    out: list[Primitive] = []
    run = [pts[start]]
    for j in range(1, n + 1):
        k = (start + j) % n
        run.append(pts[k])
        if flags[k] != flags[(k - 1) % n] or j == n:
            h = flags[(k - 1) % n]
            out.append(Polyline(tuple(run), "construction" if h else "given", dashed=h))
            run = [pts[k]]
    return out


class _Drawer:
    """The schematic of one train: every member's symbols on the paper at μl."""

    def __init__(self, lay: TrainLayout, mu_l: float, omega: Mapping[str, float], exits: Sequence[str],
                 hands: Mapping[int, str]):
        self.lay, self.mu_l, self.omega, self.hand = lay, mu_l, omega, hands
        self.level: dict[str, int] = {}  # a hollow shaft's nesting round the shaft inside it
        self._left: set[str] = set()
        self.train: GearTrain = lay.train
        self.items: list[Primitive] = []
        self.arrows: dict[str, Arrow | ArcArrow] = {}
        self.exits = set(exits)
        self.worms = {m.a for m in self.train.meshes if m.kind == "worm"}
        self.bevels = {g for m in self.train.meshes if m.kind == "bevel" for g in (m.a, m.b)}
        self.rings = {m.b if lay.radius[m.b] > lay.radius[m.a] else m.a
                      for m in self.train.meshes if m.kind == "internal"}

    # ------------------------------------------------------------------ the paper's geometry
    def p(self, q: tuple[float, float, float]) -> XY:
        return (q[0] / self.mu_l, q[1] / self.mu_l)

    def e2(self, member: str) -> XY | None:
        """The member's axis on the paper (unit), None seen end-on."""
        e = self.lay.line(member)
        return None if e[2] > 0.5 else (e[0], e[1])

    def along(self, member: str, point: XY) -> float:
        e = self.e2(member)
        assert e is not None
        o = self.p(self.lay.origin[member])
        return (point[0] - o[0]) * e[0] + (point[1] - o[1]) * e[1]

    def at(self, member: str, s: float, off: float = 0.0) -> XY:
        e = self.e2(member)
        assert e is not None
        return _v(_v(self.p(self.lay.origin[member]), e, s), (-e[1], e[0]), off)

    def R(self, gear: str) -> float:
        return self.lay.radius[gear] / self.mu_l

    def gears_of(self, member: str) -> list[str]:
        return [g.name for g in self.train.gears if g.member == member]

    # ------------------------------------------------------------------ features along a shaft
    def ring_side(self, gear: str) -> int:
        """The side (along the axis) of a ring's web: away from its planets' other gears, else
        toward its shaft's exit, else +1."""
        m = self.train.gear(gear).member
        c = self.along(m, self.p(self.lay.centre(gear)))
        pull = 0.0
        for mesh in self.train.meshes:
            if gear in (mesh.a, mesh.b):
                other = self.train.gear(mesh.b if mesh.a == gear else mesh.a).member
                for g in self.gears_of(other):
                    if self.e2(other) == self.e2(m):
                        pull += self.along(m, self.p(self.lay.centre(g))) - c
                h = self.train.member(other).carrier
                if h is not None and h != m:
                    pull += self.arm_s(other) - c
        if pull != 0.0:
            return -1 if pull > 0 else 1
        return 1

    def arm_s(self, planet: str) -> float:
        """Where the carrier's arm meets the planet's pin, along the planet's axis: past its last
        gear on the +x side (the first gear's side for a carrier that leaves to the left)."""
        ss = sorted(self.along(planet, self.p(self.lay.centre(g))) for g in self.gears_of(planet))
        h = self.train.member(planet).carrier
        left = h is not None and self.leaves_left(h)
        return ss[0] - ARM_AT * SLOT_MM if left else ss[-1] + ARM_AT * SLOT_MM

    def leaves_left(self, member: str) -> bool:
        return member in self._left

    def features(self, member: str) -> list[float]:
        """Where along its axis the member's shaft must reach: its gears (a ring's web), a
        carrier's arms."""
        out: list[float] = []
        for g in self.gears_of(member):
            c = self.along(member, self.p(self.lay.centre(g)))
            if g in self.rings:
                out.append(c + self.ring_side(g) * WEB_AT * SLOT_MM)
            elif g in self.worms:
                out += [c - WORM_L * self.R(g), c + WORM_L * self.R(g)]
            else:
                out.append(c)
        for pl in self.train.planets(member):
            if self.e2(pl) is not None and self.e2(pl) == self.e2(member):
                out.append(self.along(member, self.at(pl, self.arm_s(pl))))
        return out

    # ------------------------------------------------------------------ the whole schematic
    def draw(self) -> Schematic:
        groups = self._groups()
        for key in sorted(groups):
            self._group(groups[key])
        for m in self.train.members:
            for g in self.gears_of(m.name):
                self._gear(g)
            if m.carrier is not None:
                self._planet(m.name)
        self._pitch_lines()
        for m in self.train.members:
            self._arrow(m.name)
        return Schematic(tuple(self.items), dict(self.arrows))

    def _groups(self) -> dict[tuple[float, ...], list[str]]:
        """Fixed-axis members by the line of their axis (the coaxial ones together)."""
        out: dict[tuple[float, ...], list[str]] = {}
        for m in self.train.members:
            if m.carrier is not None:
                continue
            e = self.e2(m.name)
            o = self.p(self.lay.origin[m.name])
            if e is None:
                key: tuple[float, ...] = (2.0, round(o[0], 6), round(o[1], 6))
            else:
                key = (e[0], round(o[0] * e[1] - o[1] * e[0], 6))  # the line's distance from the origin
            out.setdefault(key, []).append(m.name)
        return out

    def cross_planets(self, h: str) -> list[str]:
        """The planets of ``h`` whose axis stands across h's in the side view: a bevel
        differential's planets on the cross pin of its case."""
        e = self.e2(h)
        return [pl for pl in self.train.planets(h) if e is not None and (f := self.e2(pl)) is not None
                and abs(f[0] * e[0] + f[1] * e[1]) < 1e-9]

    def case(self, h: str) -> tuple[float, float, float]:
        """A differential's case round its planets and side gears: (start, end) along h's axis and
        its half height."""
        pls = self.cross_planets(h)
        sides = [g for pl in pls for mesh in self.train.meshes if pl in (self.train.gear(mesh.a).member,
                 self.train.gear(mesh.b).member) for g in (mesh.a, mesh.b) if self.train.gear(g).member != pl]
        ss = [self.along(h, self.p(self.lay.centre(g))) for g in sides + self.gears_of(h)]
        half = max([abs(self._across(h, self.p(self.lay.centre(g)))) for pl in pls for g in self.gears_of(pl)]
                   + [self.R(g) for g in sides]) + 3.0
        return min(ss) - 2.0, max(ss) + 2.0, half

    def _differential(self, members: list[str], h: str) -> None:
        """A bevel differential's line: the case of h (hubs in bearings, the cross pin drawn with its
        planets), each side gear's shaft out through the hub on its back, a fixed one held."""
        lo, hi, half = self.case(h)
        e = self.e2(h)
        assert e is not None
        self.level[h] = 1
        self.items.append(_rect(self.at(h, (lo + hi) / 2), e, (hi - lo) / 2, -half, half))
        for a, b in ((lo - OVERHANG / 2, lo), (hi, hi + OVERHANG / 2)):  # the case's hollow hubs
            self._shaft(h, a, b, 1)
        self._bearing(h, lo - OVERHANG / 2 + BEARING[0] / 2, 1)
        self._bearing(h, hi + OVERHANG / 2 - BEARING[0] / 2, 1)
        for m in members:
            if m == h:
                continue
            for g in self.gears_of(m):
                at = self.along(m, self.p(self.lay.centre(g)))
                end = lo - OVERHANG if self._apex(g) > 0 else hi + OVERHANG
                self._shaft(m, min(at, end), max(at, end), 0)
                if m in self.train.fixed:
                    self._ground_across(m, end)
        pin = [self.at(h, self.along(h, self.p(self.lay.origin[pl])), t * half) for pl in self.cross_planets(h)
               for t in (-1.0, 1.0)]
        for p0, p1 in zip(pin[::2], pin[1::2]):
            self.items.append(Segment(p0, p1, "given"))
        self.items.append(Label(prime(h), self.at(h, hi - 2.0, -half), ((0.0, 1.0), (1.0, 0.0)), LETTER, italic=False))

    def _group(self, members: list[str]) -> None:
        if self.e2(members[0]) is None:
            for m in members:  # a shaft seen end-on: its section
                c = self.p(self.lay.origin[m])
                self.items.append(Circle(c, 1.0, "given"))
            return
        diff = next((m for m in members if self.cross_planets(m)), None)
        if diff is not None:
            self._differential(members, diff)
            return
        fixed = [m for m in members if m in self.train.fixed]
        moving = [m for m in members if m not in self.train.fixed]
        if len(moving) == 1 and not fixed:  # a shaft of its own, in bearings at both ends
            m = moving[0]
            ss = self._own_span(m)
            lo, hi = ss[0] - OVERHANG, ss[-1] + OVERHANG
            ends = [True, True]
            for w in self._webs(m):  # a ring's web it would pass: it ends short, no bearing there
                if ss[-1] < w < hi:
                    hi, ends[1] = w - 1.5, False
                elif lo < w < ss[0]:
                    lo, ends[0] = w + 1.5, False
            for g in self.gears_of(m):  # a bevel gear's shaft leaves from its back, not its apex
                if g in self.bevels:
                    at = self.along(m, self.p(self.lay.centre(g)))
                    if self._apex(g) > 0 and at >= ss[-1]:
                        hi, ends[1] = at, False
                    elif self._apex(g) < 0 and at <= ss[0]:
                        lo, ends[0] = at, False
            self._shaft(m, lo, hi, 0)
            if ends[0] or not ends[1]:
                self._bearing(m, lo + BEARING[0] / 2 + 1.0, 0)
            if ends[1]:
                self._bearing(m, hi - BEARING[0] / 2 - 1.0, 0)
            return
        first = {m: min(self._own_span(m, carrier_planets=True)) for m in moving}
        order = sorted(moving, key=lambda m: (first[m], [x.name for x in self.train.members].index(m)))
        leaving = [m for m in order if m in self.exits or m in self.train.inputs]
        if leaving:
            self._left.add(leaving[0])
        spans = {m: self._own_span(m) for m in moving + fixed}
        s_lo = min(min(s) for s in spans.values())
        s_hi = max(max(s) for s in spans.values())
        right = [m for m in leaving[1:]]
        for m in moving:
            ss = spans[m]
            if leaving and m == leaving[0]:
                self.level[m] = 0
                self._shaft(m, s_lo - OVERHANG, ss[-1], 0)
                self._bearing(m, s_lo - OVERHANG + BEARING[0] / 2 + 1.0, 0)
            elif m in right:
                level = right.index(m)
                self.level[m] = level
                end = s_hi + OVERHANG * (len(right) - level)
                self._shaft(m, ss[0], end, level)
                self._bearing(m, end - BEARING[0] / 2 - 1.0, level)
            elif len(ss) > 1:
                self._shaft(m, ss[0], ss[-1], 0)
        for m in fixed:  # a fixed central gear's own shaft (a ring is grounded at its rims)
            ss = spans[m]
            if all(g in self.rings for g in self.gears_of(m)):
                continue
            end = s_lo - OVERHANG if ss[0] <= s_lo else s_hi + OVERHANG
            self._shaft(m, min(ss[0], end), max(ss[-1], end), 0)
            self._ground_across(m, end)

    def _webs(self, m: str) -> list[float]:
        """Where along m's axis the webs of the other members' rings stand across it."""
        out = []
        e = self.e2(m)
        for g in sorted(self.rings):
            o = self.train.gear(g).member
            if o == m or self.e2(o) != e or e is None:
                continue
            c = self.p(self.lay.centre(g))
            web = _v(c, e, self.ring_side(g) * WEB_AT * SLOT_MM)
            mine = self.at(m, 0.0)
            across = abs((mine[0] - web[0]) * -e[1] + (mine[1] - web[1]) * e[0])
            if across < self.R(g) + RIM_T:
                out.append(self.along(m, web))
        return out

    def _own_span(self, m: str, carrier_planets: bool = False) -> list[float]:
        f = sorted(self.features(m))
        if carrier_planets:
            for pl in self.train.planets(m):
                if self.e2(pl) == self.e2(m):
                    f += [self.along(m, self.at(pl, self.along(pl, self.p(self.lay.centre(g)))))
                          for g in self.gears_of(pl)]
        return sorted(f) if f else [0.0]

    def _shaft(self, m: str, s0: float, s1: float, level: int) -> None:
        if s1 - s0 < 1e-9:
            return
        if level == 0:
            self.items.append(Segment(self.at(m, s0), self.at(m, s1), "given"))
        else:
            for off in (-level * HOLLOW, level * HOLLOW):
                self.items.append(Segment(self.at(m, s0, off), self.at(m, s1, off), "given"))

    def _bearing(self, m: str, s: float, level: int) -> None:
        """A bearing: a box on the shaft, a stalk down to the frame, the frame hatched."""
        w, h = BEARING
        e = self.e2(m)
        assert e is not None
        half = h / 2 + level * HOLLOW
        self.items.append(_rect(self.at(m, s), e, w / 2, -half, half))
        # the frame lies below a horizontal shaft, left of a vertical one
        down = -1.0 if e[0] != 0.0 else 1.0
        foot = self.at(m, s, down * (half + 3.0))
        self.items.append(Segment(self.at(m, s, down * half), foot, "given"))
        a, b = _v(foot, e, -4.0), _v(foot, e, 4.0)
        self.items.append(GuideLine(a, b) if down < 0 else GuideLine(b, a))

    def _ground_across(self, m: str, s: float) -> None:
        """A fixed shaft's end held in the frame: a ground line across it, hatched outward."""
        e = self.e2(m)
        assert e is not None
        a, b = self.at(m, s, -4.0), self.at(m, s, 4.0)
        out = 1.0 if s > 0 else -1.0
        self.items.append(GuideLine(a, b) if out > 0 else GuideLine(b, a))

    # ------------------------------------------------------------------ gears
    def nearer(self, g: str) -> list[tuple[XY, float]]:
        """The discs (centre, radius on the paper) of the gears seen end-on nearer the viewer (+z)
        than the end-on gear g that cover part of its circle: another member's, a slot in front."""
        m = self.train.gear(g).member
        c, R = self.p(self.lay.centre(g)), self.R(g)
        z = self.lay.centre(g)[2]
        out = []
        for o in self.train.gears:
            mo = o.member
            if mo == m or self.e2(mo) is not None or self.lay.centre(o.name)[2] <= z + 1e-9 * self.mu_l:
                continue
            co, Ro = self.p(self.lay.centre(o.name)), self.R(o.name)
            if math.dist(c, co) < R + Ro and math.dist(c, co) + R > Ro:  # crosses its rim, not wholly hidden
                out.append((co, Ro))
        return out

    def _gear(self, g: str) -> None:
        m = self.train.gear(g).member
        c = self.p(self.lay.centre(g))
        R = self.R(g)
        e = self.e2(m)
        label_at: XY
        if e is None:  # seen along its axis; behind a nearer gear seen so (toward +z), that part hidden
            near = self.nearer(g)
            if near:
                self.items += _hidden_circle(c, R, near)
            else:
                self.items.append(Circle(c, R, "given"))
            label_at = _v(c, (R * 0.7071, R * 0.7071))
        elif g in self.worms:
            self._worm(g, c, e, R)
            label_at = _v(c, (-e[1], e[0]), R + 1.0)
        elif g in self.bevels:
            self._bevel(g, c, e, R)
            label_at = _v(c, (-e[1], e[0]), R + 1.0)
        elif g in self.rings:
            self._ring(g, c, e, R)
            label_at = _v(c, (-e[1], e[0]), R + RIM_T)
        else:
            self.items.append(_rect(c, e, GEAR_W / 2, -R, R))
            # at its far rim, unless a ring meshes there (a planet): then beside its face, halfway out
            ring_far = any(g in (mesh.a, mesh.b) and self.rings & {mesh.a, mesh.b} for mesh in self.train.meshes)
            label_at = _v(c, (-e[1], e[0]), self._far_side(g) * R * (0.5 if ring_far else 1.0))
        self.items.append(Label(prime(g), label_at, ((0.0, 1.0), (0.0, -1.0)), LETTER, italic=False))

    def _far_side(self, g: str) -> float:
        """+1 or −1: the side of a side-view gear away from its first mesh's pitch point."""
        for k, mesh in enumerate(self.train.meshes):
            if g in (mesh.a, mesh.b):
                m = self.train.gear(g).member
                e = self.e2(m)
                assert e is not None
                d = _v(self.p(self.lay.pitch[k]), self.p(self.lay.centre(g)), -1.0)
                return -1.0 if d[0] * -e[1] + d[1] * e[0] > 0 else 1.0
        return 1.0

    def _ring(self, g: str, c: XY, e: XY, R: float) -> None:
        m = self.train.gear(g).member
        s = self.ring_side(g)
        web = s * WEB_AT * SLOT_MM
        n = (-e[1], e[0])
        for side in (1.0, -1.0):  # the rims: the teeth inward, the web to one side
            pts = (_v(_v(c, e, -s * GEAR_W / 2), n, side * R), _v(_v(c, e, web), n, side * R),
                   _v(_v(c, e, web), n, side * (R + RIM_T)), _v(_v(c, e, -s * GEAR_W / 2), n, side * (R + RIM_T)))
            self.items.append(Polyline(pts, "given", closed=True))
            if m in self.train.fixed:  # held in the frame: hatched on its outside
                a, b = _v(_v(c, e, -s * GEAR_W / 2), n, side * (R + RIM_T)), _v(_v(c, e, web), n, side * (R + RIM_T))
                self.items.append(GuideLine(a, b) if (side > 0) == (b[0] < a[0] or b[1] > a[1]) else GuideLine(b, a))
        # the web reaches its own hub (a hollow one: its outer line) or leaves a hole for the shaft
        # that passes it
        inner = self.level[m] * HOLLOW if m in self.level else HOLLOW + 0.6
        if inner == 0.0:
            self.items.append(Segment(_v(_v(c, e, web), n, R + RIM_T), _v(_v(c, e, web), n, -(R + RIM_T)), "given"))
        else:
            for side in (1.0, -1.0):
                self.items.append(Segment(_v(_v(c, e, web), n, side * (R + RIM_T)), _v(_v(c, e, web), n, side * inner),
                                          "given"))

    def _worm(self, g: str, c: XY, e: XY, R: float) -> None:
        L = WORM_L * R
        self.items.append(_rect(c, e, L, -R, R))
        hand = next((self.hand.get(k, "right") for k, mesh in enumerate(self.train.meshes) if mesh.a == g), "right")
        slant = 0.6 * R if hand == "right" else -0.6 * R  # right-hand: the near threads fall to the right
        for k in range(-2, 3):
            s = k * L / 3.0
            self.items.append(Segment(_v(_v(c, e, s - slant), (-e[1], e[0]), R * 0.9),
                                      _v(_v(c, e, s + slant), (-e[1], e[0]), -R * 0.9), "construction"))

    def _apex(self, g: str) -> float:
        """+1 or −1: the side along its axis where a bevel gear's cone has its apex (toward the
        centre of the gear it meshes)."""
        m = self.train.gear(g).member
        e = self.e2(m)
        assert e is not None
        c = self.p(self.lay.centre(g))
        for mesh in self.train.meshes:
            if g in (mesh.a, mesh.b):
                other = mesh.b if mesh.a == g else mesh.a
                d = _v(self.p(self.lay.centre(other)), c, -1.0)
                return 1.0 if d[0] * e[0] + d[1] * e[1] >= 0 else -1.0
        return 1.0

    def _bevel(self, g: str, c: XY, e: XY, R: float, flip: bool = False) -> None:
        apex_dir = -self._apex(g) if flip else self._apex(g)
        depth = 0.35 * R
        n = (-e[1], e[0])
        pts = (_v(c, n, R), _v(_v(c, e, apex_dir * depth), n, 0.6 * R), _v(_v(c, e, apex_dir * depth), n, -0.6 * R),
               _v(c, n, -R))
        self.items.append(Polyline(pts, "given", closed=True))

    def _pitch_lines(self) -> None:
        for k, mesh in enumerate(self.train.meshes):
            if mesh.kind not in ("external", "internal"):
                continue
            m = self.train.gear(mesh.a).member
            e = self.e2(m)
            if e is None:
                continue
            p = self.p(self.lay.pitch[k])
            self.items.append(Segment(_v(p, e, -GEAR_W), _v(p, e, GEAR_W), "construction", dashdot=True))
            pl = next((self.train.gear(g).member for g in (mesh.a, mesh.b)
                       if self.mirrored(self.train.gear(g).member)), None)
            if pl is not None:  # the mirrored planet's pitch point too
                h = self.train.member(pl).carrier
                assert h is not None
                q = self.reflect(h, p)
                self.items.append(Segment(_v(q, e, -GEAR_W), _v(q, e, GEAR_W), "construction", dashdot=True))

    # ------------------------------------------------------------------ planets and carriers
    def _planet(self, pl: str) -> None:
        h = self.train.member(pl).carrier
        assert h is not None
        e = self.e2(pl)
        if e is not None and pl in self.cross_planets(h):  # on the case's cross pin (drawn with it); its twin
            for g in self.gears_of(pl):
                c = self.p(self.lay.centre(g))
                if not any(self._across(h, self.p(self.lay.origin[o])) * self._across(h, c) < 0
                           for o in self.cross_planets(h) if o != pl):
                    self._bevel(g, self.reflect(h, c), e, self.R(g), flip=True)
            return
        if e is None or self.e2(h) != e:  # a planet across the carrier: its pin from the carrier's axis
            for g in self.gears_of(pl):
                c = self.p(self.lay.centre(g))
                if e is None:  # the pin seen end-on, on the carrier's arm from its axis
                    self.items.append(Segment(self.at(h, self.along(h, c)), c, "given"))
                    self.items.append(Circle(c, 1.0, "given"))
                    continue
                # from the apex on the carrier's axis (seen end-on: its point) through the gear, past its back
                foot = self.p(self.lay.origin[h]) if self.e2(h) is None else self.at(h, self.along(h, c))
                d = math.dist(foot, c)
                out = (e[0], e[1]) if d == 0.0 else ((c[0] - foot[0]) / d, (c[1] - foot[1]) / d)
                self.items.append(Segment(foot, _v(c, out, GEAR_W), "given"))
            return
        ss = [self.along(pl, self.p(self.lay.centre(g))) for g in self.gears_of(pl)]
        arm = self.arm_s(pl)
        lo, hi = min(ss + [arm]), max(ss + [arm])
        self.items.append(Segment(self.at(pl, lo - (GEAR_W if arm > lo else 0.0)),
                                  self.at(pl, hi + (GEAR_W if arm < hi else 0.0)), "given"))
        foot = self.at(h, self.along(h, self.at(pl, arm)))
        self.items.append(Segment(self.at(pl, arm), foot, "given"))  # the carrier's arm
        mid = _v(self.at(pl, arm), _v(foot, self.at(pl, arm), -1.0), 0.5)
        if not any(isinstance(it, Label) and it.text == prime(h) for it in self.items):
            self.items.append(Label(prime(h), mid, ((0.0, 1.0), (0.0, -1.0)), LETTER, italic=False))
        if self.mirrored(pl):
            self._mirror_planet(pl, lo - (GEAR_W if arm > lo else 0.0), hi + (GEAR_W if arm < hi else 0.0), arm)

    def mirrored(self, pl: str) -> bool:
        """Whether the planet is drawn a second time across its carrier's axis, as the book draws
        a planet set (one above, one below; the carrier a fork to both): unless the scene lists a
        planet of the same carrier on that side already (the closed differential's copies)."""
        h = self.train.member(pl).carrier
        e = self.e2(pl)
        if h is None or e is None or self.e2(h) != e:
            return False
        side = self._across(h, self.p(self.lay.origin[pl]))
        if abs(side) < 1e-9:
            return False
        return not any(self._across(h, self.p(self.lay.origin[o])) * side < 0 for o in self.train.planets(h)
                       if o != pl and self.e2(o) == e)

    def _across(self, h: str, q: XY) -> float:
        """The signed distance of a paper point from the carrier's axis line."""
        e = self.e2(h)
        assert e is not None
        o = self.p(self.lay.origin[h])
        return (q[0] - o[0]) * -e[1] + (q[1] - o[1]) * e[0]

    def reflect(self, h: str, q: XY) -> XY:
        """A paper point reflected across the carrier's axis line."""
        e = self.e2(h)
        assert e is not None
        d = self._across(h, q)
        return _v(q, (-e[1], e[0]), -2.0 * d)

    def _mirror_planet(self, pl: str, lo: float, hi: float, arm: float) -> None:
        """The planet's copy across the carrier's axis: its gears, its pin and the arm (no letters,
        no arrow: it turns as the planet drawn above)."""
        h = self.train.member(pl).carrier
        assert h is not None
        e = self.e2(pl)
        assert e is not None
        for g in self.gears_of(pl):
            self.items.append(_rect(self.reflect(h, self.p(self.lay.centre(g))), e, GEAR_W / 2, -self.R(g), self.R(g)))
        self.items.append(Segment(self.reflect(h, self.at(pl, lo)), self.reflect(h, self.at(pl, hi)), "given"))
        foot = self.at(h, self.along(h, self.at(pl, arm)))
        self.items.append(Segment(self.reflect(h, self.at(pl, arm)), foot, "given"))

    # ------------------------------------------------------------------ arrows of rotation
    def _arrow(self, m: str) -> None:
        w = self.omega.get(m, 0.0)
        if m in self.train.fixed or w == 0.0:
            return
        sense = self.lay.axis[m]
        e = self.e2(m)
        gears = self.gears_of(m)
        if e is None:  # along ±z: a curved arrow, counter-clockwise for a positive speed toward the viewer
            c = self.p(self.lay.origin[m])
            r = max([self.R(g) for g in gears], default=5.0) * 0.75  # clear of a smaller gear on it
            sweep = math.radians(70.0) * (1.0 if w * sense[2] > 0 else -1.0)
            arc = ArcArrow(c, r, math.radians(200.0) - sweep / 2, sweep, "given")
            self.items.append(arc)
            self.arrows[m] = arc
            return
        # the near side moves along ω·û × ẑ: down for +x, for +y to the right
        u = (sense[0] * w, sense[1] * w)
        d = (u[1], -u[0])
        n = math.hypot(*d)
        d = (d[0] / n, d[1] / n)
        if gears:
            g = gears[0]
            c = self.p(self.lay.centre(g))
            if g in self.rings:  # beside its web, halfway out on the side away from the planet
                mid = _v(_v(c, (-e[1], e[0]), self._far_side(g) * self.R(g) * 0.6), e,
                         self.ring_side(g) * (WEB_AT * SLOT_MM + 2.5))
            elif g in self.bevels:  # behind its back face, away from the apex
                away = 1.0 if e[0] != 0.0 else -1.0  # the side away from its bearings' frame
                mid = _v(_v(c, e, -self._apex(g) * 5.0), (-e[1], e[0]), away * self.R(g) * 0.5)
            else:  # beside the gear, halfway out on the side away from its mesh
                mid = _v(_v(c, (-e[1], e[0]), self._far_side(g) * self.R(g) * 0.5), e, GEAR_W / 2 + 2.5)
        else:  # a bare carrier: beside its arm
            pl = self.train.planets(m)
            if pl and self.e2(pl[0]) == e:
                top = self.at(pl[0], self.arm_s(pl[0]))
                foot = self.at(m, self.along(m, top))
                mid = _v(_v(top, _v(foot, top, -1.0), 0.5), e, 2.5)
            else:
                mid = self.at(m, 0.0, 4.0)
        a = Arrow(_v(mid, d, -TURN_MM / 2), _v(mid, d, TURN_MM / 2), "given")
        self.items.append(a)
        self.arrows[m] = a


def schematic(lay: TrainLayout, mu_l: float, omega: Mapping[str, float], exits: Sequence[str] = (),
              hands: Mapping[int, str] | None = None) -> Schematic:
    """The schematic's items at μl; ``omega`` each member's speed (the arrows), ``exits`` the members
    whose shafts leave the train (inputs and outputs: the first to the left, the others to the
    right, nested); ``hands`` the worms' hands by mesh index."""
    return _Drawer(lay, mu_l, omega, exits, dict(hands or {})).draw()


def velocity_items(d: TrainVelocityDiagram, lay: TrainLayout) -> list[Primitive]:
    """The diagram: the line of centres, the pitch points' velocities, the members' lines; the pole,
    the rays, the ω line and the cuts."""
    ys = [p[1] for ln in d.lines.values() for p in ln.points] + [lay.height(m) / d.mu_l for m in d.lines]
    lo, hi = min(ys), max(ys)
    items: list[Primitive] = [Segment((0.0, lo - 4.0), (0.0, hi + 4.0), "construction", dashdot=True)]
    train = lay.train
    for s in d.shared:
        if s.mesh is None:
            continue
        y = s.y / d.mu_l
        x = d.lines[s.a].x_at(y)
        mesh = train.meshes[s.mesh]
        name = f"P_{{{prime(mesh.a)}{prime(mesh.b)}}}"
        if abs(x) > 0.3:
            items.append(Arrow((0.0, y), (x, y), "construction"))
            items.append(Label(name, (x, y), ((-1.0 if x > 0 else 1.0, 0.0),), LETTER))
        else:
            items.append(Label(name, (0.0, y), ((0.0, 1.0), (0.0, -1.0)), LETTER))
    ends: dict[str, tuple[XY, XY, XY]] = {}
    for m, ln in d.lines.items():
        if m in train.fixed:
            continue
        ys_m = [p[1] for p in ln.points]
        t = (ln.slope, 1.0)
        n = math.hypot(*t)
        t = (t[0] / n, t[1] / n)
        y0, y1 = min(ys_m), max(ys_m)
        # past its extreme points by a few mm along itself
        a, b = _v((ln.x_at(y0), y0), t, -4.0), _v((ln.x_at(y1), y1), t, 4.0)
        items.append(Segment(a, b, "result"))
        ends[m] = (a, b, t)
    # each line's name at the end of it farthest from the names already set and the other lines' ends
    # (two lines that meet at one pitch point would otherwise stack their names there)
    taken: list[XY] = []
    for m, (a, b, t) in ends.items():
        others = [q for o, (p0, p1, _) in ends.items() if o != m for q in (p0, p1)]

        def room(q: XY, near: list[XY] = taken + others) -> float:
            return min((math.dist(q, r) for r in near), default=math.inf)

        back = (-t[0], -t[1])
        cands = [(b, t), (a, back)] + [(_v(a, _v(b, a, -1.0), k), t) for k in (0.8, 0.2)]
        # an end if it has room, else the point with the most
        at, out = next((c for c in cands[:2] if room(c[0]) >= 6.0), max(cands, key=lambda c: room(c[0])))
        taken.append(at)
        items.append(Label(prime(m), at, ((-out[0], -out[1]),), LETTER, italic=False))
    # the pole, the ω line at H above it, the rays (one longer than the sheet allows clipped at its end)
    O = d.pole
    clipped = clipped_rays(d, train)
    cuts = {m: d.cut(m) for m in d.lines if m not in clipped}
    xs = [c[0] for c in cuts.values()] + [O[0]]
    x_lo = O[0] - CLIP_MM if any(d.lengths[m] < 0 for m in clipped) else min(xs) - 5.0
    x_hi = O[0] + CLIP_MM if any(d.lengths[m] > 0 for m in clipped) else max(xs) + 5.0
    top = O[1] + d.H
    items.append(Segment((x_lo, top), (x_hi, top), "construction"))
    items.append(Segment(O, (O[0], top), "construction", dashed=True))
    # the pole distance dimensioned left of the rays with its value: a bare "H" beside the carriers'
    # rays H, H1, H2 would read as one of them
    xd = x_lo - 6.0
    items.append(Segment((O[0], O[1]), (xd - 2.0, O[1]), "label"))
    items.append(Segment((x_lo, top), (xd - 2.0, top), "label"))
    items += dimension((xd, O[1]), (xd, top), f"H = {number(d.H)} mm", (-1.0, 0.0))
    items.append(Circle(O, 0.8, "result"))
    items.append(Label("O", O, ((0.0, 1.0),), LETTER, italic=False))
    seen: dict[tuple[float, float], str] = {}
    for m, c in cuts.items():
        if m in train.fixed:
            continue
        items.append(Segment(O, c, "construction"))
        key = (round(c[0], 3), round(c[1], 3))
        seen[key] = seen.get(key, "") + ("," if key in seen else "") + prime(m)
    for m in clipped:  # toward its cut, stopped at the ω line's end: the arrow says it runs on
        x = x_hi if d.lengths[m] > 0 else x_lo
        end = (x, O[1] + d.H * (x - O[0]) / d.lengths[m])
        key = (round(end[0], 3), round(end[1], 3))
        if key not in seen:  # members turning alike (the closed differential's 2 and 6) share one ray
            items.append(Arrow(O, end, "construction"))
        seen[key] = seen.get(key, "") + ("," if key in seen else "") + prime(m)
    for (x, y), text in seen.items():
        avoid = ((0.0, -1.0),) if y == top else ((-1.0 if x < O[0] else 1.0, 0.0), (0.0, -1.0))
        items.append(Label(text, (x, y), avoid, LETTER, italic=False))
    return items


def clipped_rays(d: TrainVelocityDiagram, train: GearTrain) -> tuple[str, ...]:
    """The moving members whose cut on the ω line lies farther than :data:`CLIP_MM` from the
    pole's foot: the pole distance was chosen for slower members the scene asks about."""
    return tuple(m for m in d.lines if m not in train.fixed and abs(d.lengths[m]) > CLIP_MM)


def velocity_notes(d: TrainVelocityDiagram, train: GearTrain, notation: str) -> tuple[str, ...]:
    notes = [scale_text("l", d.mu_l), scale_text("v", d.mu_v),
             f"H = {number(d.H)} mm, {scale_text('omega', d.mu_omega)}"]
    read = [f"ℓ_{{{prime(m)}}} = {number(d.lengths[m])} mm, ω_{{{prime(m)}}} = {number(d.omega(m))} rad/s"
            for m in d.lines if m not in train.fixed]
    notes += ["; ".join(read[k:k + 2]) for k in range(0, len(read), 2)]  # two members a line
    clipped = clipped_rays(d, train)
    if clipped:
        notes.append(train_word("clipped", notation).replace("«m»", ", ".join(prime(m) for m in clipped)))
    if d.trials:
        notes.append(train_word("false position", notation).replace("«m»", ", ".join(prime(t) for t in d.trials)))
    return tuple(notes)


def _exits(scene: Scene[TrainScene]) -> list[str]:
    """The members whose shafts leave the train: the inputs, then those the scene asks about."""
    train = scene.problem.train
    names = [m.name for m in train.members]
    out = [n for n in train.inputs]
    for f in scene.find:
        for n in sorted(names, key=len, reverse=True):
            if f.endswith((n, "_" + n)) and n not in out and f[0] in "noi":
                out.append(n)
                break
    return out


def train_sheet(scene: Scene[TrainScene], footer: Footer) -> tuple[Sheet, list[str]]:
    """The sheet of ``scene.show`` (default both panels; a spatial train: the schematic)."""
    p = scene.problem
    train = p.train
    notation = scene.page.notation
    warnings: list[str] = []
    show = list(scene.show) or ["schematic", "velocity"]
    bad = [s for s in show if s not in ("schematic", "velocity")]
    if bad:
        raise OutOfDomain(f"unknown panel(s) {', '.join(map(repr, bad))}; use schematic, velocity")
    sol = solve(train)  # a train that locks is said first, then a loop that does not close
    dr = drawn(scene)
    lay, mu_l = dr.layout, dr.mu_l
    panels: list[Panel] = []
    if "schematic" in show:
        sch = schematic(lay, mu_l, sol.omega, _exits(scene), p.hands)
        notes: tuple[str, ...] = (scale_text("l", mu_l), train_word("not axial", notation))
        if not lay.parallel and "velocity" in show and scene.show:
            notes += (train_word("spatial", notation),)
        panels.append(Panel("schematic", train_word("schematic", notation), sch.items, notes, row=0,
                            scales=(("l", mu_l),)))
    if "velocity" in show and dr.velocity is not None:
        d = dr.velocity
        panels.append(Panel("velocity", train_word("velocity", notation), tuple(velocity_items(d, lay)),
                            velocity_notes(d, train, notation), row=0, scales=(("l", mu_l), ("v", d.mu_v))))
    elif "velocity" in show and scene.show:
        warnings.append("the velocity diagram is drawn for trains whose axes are all parallel: not drawn for this "
                        "spatial train")
    return Sheet(scene.title, tuple(panels), page_size(scene), footer), warnings


__all__ = ["CLIP_MM", "TRAIN_WORDS", "Schematic", "clipped_rays", "schematic", "train_sheet", "train_word", "velocity_items",
           "velocity_notes"]
