"""The geometry of a gear train's schematic: pitch radii, each member's axis, the axial slots.

Every gear's pitch radius is r = m·z/2 (a worm's: m·q/2 with the diametral quotient
:data:`WORM_Q`, its z being its starts). Each member's axis is a line in space: a point ``origin``
on it and its direction (the scene's ``axes``, sign dropped: ``"-x"`` lies along x as ``"+x"``
does). The gears of a member sit on its axis at ``origin + offset·e``: for a spur gear its slot's
``slot·gap``, one slot per mesh stage (the gears that mesh, directly or through a chain of meshes,
share a slot, so meshing spur gears stand in one plane), ``gap`` the axial pitch of the slots; a
gear of a spatial mesh where its partner's axis puts it (a bevel pair meets at the apex on both
axes, a worm and its wheel are centred on each other's axis), so two bevels of one stage do not
share a slot's plane and a worm reaches the wheel whatever the slots say.

The axes are found by walking the meshes from the first member, as the book's schematic is drawn:
a mesh puts b's gear at a's gear + r_a·t_a − r_b·t_b, with t the directions from each axis to the
pitch point P. For parallel axes (every axis along x, the side view) t_a = side·ŷ (axes along y
or seen end-on along z: side·x̂, the pair beside each other), and

    external: y_b = y_a + side·(r_a + r_b),   internal: y_b = y_a + side·(r_a − r_b),

``side`` (+1 above, −1 below) being where the pitch point lies from a's axis — b's axis for an
external mesh and for a ring's mesh with its pinion; for a pinion a meshing a ring b the ring's
axis is on the other side (the conveyor's planet 2 with its rings 3 and 4, both meshes "above":
the rings coaxial with the sun below the planet). A carrier and its central members are coaxial,
and so are the pairs the scene says are (``coaxial``): the loop a planet set or a reverted train
closes is the coaxial condition, and a loop that does not close is refused naming the two arms.

Spatial meshes (bevel, worm) use the scene's ``towards`` directions as they are; without them
t_a = the direction of b's axis (a bevel pair's apex on both axes), t_b = a's (for a worm: the
common perpendicular, the wheel below). A drawing, not a check: an axial mismatch in a spatial
loop is left as it is, only the radial closure is checked; a worm on a loop (placed from its own
shaft's spur pair) takes the diameter that reaches its wheel.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from graphmech.errors import NoSolution, OutOfDomain
from graphmech.mechanisms.gear_train import AXES, GearTrain, Mesh

XYZ = tuple[float, float, float]

#: A worm's pitch diameter in modules (the diametral quotient q = d₁/m): a drawing's choice, its
#: speed ratio is the starts' and does not depend on it.
WORM_Q = 10.0

#: A loop closes when its two positions agree to this fraction of the train's largest radius.
CLOSURE_REL = 1e-9

#: The unit vectors the scene names an axis or a direction by (the model's one table, as floats).
DIRECTIONS: Mapping[str, XYZ] = {k: (float(v[0]), float(v[1]), float(v[2])) for k, v in AXES.items()}


def _add(p: XYZ, q: XYZ, k: float = 1.0) -> XYZ:
    return (p[0] + k * q[0], p[1] + k * q[1], p[2] + k * q[2])


def _dot(p: XYZ, q: XYZ) -> float:
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]


def _cross(p: XYZ, q: XYZ) -> XYZ:
    return (p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0])


def direction(name: str) -> XYZ:
    """``"+x"`` … ``"-z"`` as a unit vector."""
    if name not in DIRECTIONS:
        raise OutOfDomain(f"{name!r} is not an axis direction ({', '.join(DIRECTIONS)})")
    return DIRECTIONS[name]


def prime(name: str) -> str:
    """A name as the book letters it: ``2'`` → ``2′``."""
    return name.replace("'", "′")


def _mm(x: float) -> str:
    return f"{x * 1e3:.4g} mm".replace("-", "−")


@dataclass(frozen=True)
class TrainLayout:
    """The schematic's geometry, in metres (the axial ``gap`` too).

    radius : gear → pitch radius.
    axis : member → its axis' unit direction as the scene gives it (signed: the speed's sense).
    origin : member → the point of its axis at slot 0.
    slot : gear → its axial slot (0, 1, …; meshing gears share one).
    offset : gear → where it sits along its member's axis from ``origin``: its slot's ``slot·gap``,
        a gear of a spatial mesh where the mesh puts it (a bevel pair's gears meet at the apex, a
        worm and its wheel centred on each other's axis).
    pitch : mesh index → the pitch point P.
    tangent : mesh index → (t_a, t_b), the directions from each gear's centre to P.
    parallel : every axis along x and every mesh external or internal: the side view.
    """

    train: GearTrain
    module: float
    gap: float
    radius: Mapping[str, float]
    axis: Mapping[str, XYZ]
    origin: Mapping[str, XYZ]
    slot: Mapping[str, int]
    pitch: Mapping[int, XYZ]
    tangent: Mapping[int, tuple[XYZ, XYZ]]
    parallel: bool
    offset: Mapping[str, float] | None = None

    def line(self, member: str) -> XYZ:
        """The member's axis direction without its sign (the line the gears sit along)."""
        e = self.axis[member]
        return (abs(e[0]), abs(e[1]), abs(e[2]))

    def centre(self, gear: str) -> XYZ:
        """The centre of a gear's pitch circle."""
        m = self.train.gear(gear).member
        at = self.slot[gear] * self.gap if self.offset is None else self.offset[gear]
        return _add(self.origin[m], self.line(m), at)

    def height(self, member: str) -> float:
        """A member's axis height y (the side view of a parallel train)."""
        return self.origin[member][1]

    def slots_of(self, member: str) -> tuple[int, ...]:
        """The slots of the member's gears, sorted (none for a bare carrier)."""
        return tuple(sorted({self.slot[g.name] for g in self.train.gears if g.member == member}))

    def arm(self, planet: str) -> float:
        """A planet's arm: its axis' height above its carrier's (signed)."""
        carrier = self.train.member(planet).carrier
        if carrier is None:
            raise OutOfDomain(f"member {planet} is not a planet")
        return self.height(planet) - self.height(carrier)


def pitch_radius(train: GearTrain, gear: str, module: float) -> float:
    """r = m·z/2; a worm's (the driving gear of a worm mesh) m·q/2."""
    if any(mesh.kind == "worm" and mesh.a == gear for mesh in train.meshes):
        return module * WORM_Q / 2.0
    return module * train.gear(gear).z / 2.0


def slots(train: GearTrain) -> dict[str, int]:
    """gear → slot: the meshes' connected groups of gears, numbered in the order of the gears."""
    parent = {g.name: g.name for g in train.gears}

    def find(g: str) -> str:
        while parent[g] != g:
            parent[g] = parent[parent[g]]
            g = parent[g]
        return g

    order = {g.name: k for k, g in enumerate(train.gears)}
    for mesh in train.meshes:
        ra, rb = sorted((find(mesh.a), find(mesh.b)), key=order.__getitem__)
        if ra != rb:
            parent[rb] = ra  # the group keeps its first gear's name
    number: dict[str, int] = {}
    out: dict[str, int] = {}
    for g in train.gears:
        out[g.name] = number.setdefault(find(g.name), len(number))
    return out


def _tangents(train: GearTrain, mesh: Mesh, k: int, axis: Mapping[str, XYZ], sides: Mapping[int, int],
              towards: Mapping[int, tuple[str, str]]) -> tuple[XYZ, XYZ]:
    ea = axis[train.gear(mesh.a).member]
    eb = axis[train.gear(mesh.b).member]
    if k in towards:
        ta, tb = direction(towards[k][0]), direction(towards[k][1])
        for g, t, e in ((mesh.a, ta, ea), (mesh.b, tb, eb)):
            if _dot(t, e) != 0.0:
                raise OutOfDomain(f"mesh {prime(mesh.a)}–{prime(mesh.b)}: the direction toward the pitch point from "
                                  f"{prime(g)}'s axis lies along that axis")
        return ta, tb
    if mesh.kind in ("external", "internal"):
        if abs(abs(_dot(ea, eb)) - 1.0) > 1e-12:
            raise OutOfDomain(f"the {mesh.kind} mesh {prime(mesh.a)}–{prime(mesh.b)} joins axes that are not parallel")
        s = sides.get(k, 1)
        # the side view's ŷ for axes along x; x̂ for axes along y (vertical) or seen end-on (z): the
        # pair beside each other, as the book draws the spur pair between two worm shafts
        up: XYZ = (0.0, 1.0, 0.0) if abs(ea[0]) > 0.5 else (1.0, 0.0, 0.0)
        t = (s * up[0], s * up[1], s * up[2])
        return (t, t) if mesh.kind == "internal" else (t, (-t[0], -t[1], -t[2]))
    if mesh.kind == "worm":
        n = _cross(ea, eb)
        if _dot(n, n) < 0.5:
            raise OutOfDomain(f"the worm mesh {prime(mesh.a)}–{prime(mesh.b)} needs crossed axes")
        if n[1] > 0 or n[0] > 0 or n[2] > 0:
            n = (-n[0], -n[1], -n[2])
        return n, (-n[0], -n[1], -n[2])
    ua = tuple(abs(v) for v in eb)
    ub = tuple(abs(v) for v in ea)
    return (ua[0], ua[1], ua[2]), (ub[0], ub[1], ub[2])


def layout(train: GearTrain, module: float, axes: Mapping[str, str] | None = None,
           sides: Mapping[int, int] | None = None, towards: Mapping[int, tuple[str, str]] | None = None,
           coaxial: tuple[tuple[str, str], ...] = (), gap: float | None = None,
           modules: Mapping[str, float] | None = None) -> TrainLayout:
    """Place every member's axis by walking the meshes (the carriers' and ``coaxial`` axes first).

    ``modules`` gives a gear's own module where its stage has one (gear → m), else ``module``. A
    parallel mesh whose members are both placed already closes a loop: its side is the one that
    closes it (the sun–planet mesh of a planet set placed from the ring), so ``sides`` matter only
    for the meshes that place a member. A spatial mesh's loop is drawn, not checked (a worm's
    diameter here is a drawing's choice).

    Raises
    ------
    NoSolution
        A loop that does not close: a planet set whose arms differ (the coaxial condition), a
        reverted train whose input and output are not coaxial, a mesh whose gears do not reach.
    OutOfDomain
        A module not positive, an unknown axis name, a parallel mesh across crossed axes.
    """
    if not (module > 0.0 and math.isfinite(module)):
        raise OutOfDomain(f"the module is positive and finite, not {module!r}")
    axes, sides, towards = axes or {}, sides or {}, towards or {}
    names = [m.name for m in train.members]
    axis = {n: direction(axes.get(n, "+x")) for n in names}
    radius = {g.name: pitch_radius(train, g.name, (modules or {}).get(g.name, module)) for g in train.gears}
    slot = slots(train)
    big = max(radius.values(), default=module)
    gap = 0.8 * big if gap is None else gap
    tangent = {k: _tangents(train, mesh, k, axis, sides, towards) for k, mesh in enumerate(train.meshes)}
    parallel = all(abs(axis[n][0]) == 1.0 for n in names) and all(
        mesh.kind in ("external", "internal") for mesh in train.meshes)

    def unsigned(n: str) -> XYZ:
        e = axis[n]
        return (abs(e[0]), abs(e[1]), abs(e[2]))

    # the axis edges: a carrier with each central member its planets mesh, the scene's coaxial pairs
    same: list[tuple[str, str]] = []
    for h in train.carriers:
        for mesh in train.meshes:
            if train.mesh_frame(mesh) != h:
                continue
            for g in (mesh.a, mesh.b):
                c = train.gear(g).member
                if train.member(c).carrier is None and c != h and (h, c) not in same:
                    same.append((h, c))
    same += [(a, b) for a, b in coaxial]
    for a, b in coaxial:
        for n in (a, b):
            train.member(n)

    def through(k: int, frm: str) -> tuple[str, XYZ]:
        """The other member of mesh k and its origin, from the origin of ``frm``'s member."""
        mesh = train.meshes[k]
        ga, gb = train.gear(mesh.a), train.gear(mesh.b)
        ta, tb = tangent[k]
        delta = _add(_add((0.0, 0.0, 0.0), ta, radius[mesh.a]), tb, -radius[mesh.b])
        if frm == ga.member:
            ca = _add(origin[frm], unsigned(frm), slot[mesh.a] * gap)
            cb = _add(ca, delta)
            return gb.member, _add(cb, unsigned(gb.member), -slot[mesh.b] * gap)
        cb = _add(origin[frm], unsigned(frm), slot[mesh.b] * gap)
        ca = _add(cb, delta, -1.0)
        return ga.member, _add(ca, unsigned(ga.member), -slot[mesh.a] * gap)

    origin: dict[str, XYZ] = {}
    slid: set[str] = set()

    def twin(q: str) -> bool:
        """Whether the planet q was just put on the axis of another planet of its carrier."""
        h = train.member(q).carrier
        if h is None:
            return False
        return any(o != q and o in origin and math.dist(origin[o], origin[q]) <= CLOSURE_REL * big
                   and unsigned(o) == unsigned(q) for o in train.planets(h))

    def axial(fixed: set[str]) -> None:
        """Slide a central member coaxial with its carrier along its axis to where a spatial mesh
        with a member placed puts it (the side bevels of a differential, one each side of the
        planet): the slots' axial pitch is the side view's, a bevel planet's cone fixes its own."""
        grew = True
        while grew:
            grew = False
            for k, mesh in enumerate(train.meshes):
                if mesh.kind in ("external", "internal"):
                    continue
                ma, mb = train.gear(mesh.a).member, train.gear(mesh.b).member
                for p, q in ((ma, mb), (mb, ma)):
                    if p in fixed and q not in fixed:
                        e = unsigned(q)
                        d = _add(through(k, p)[1], origin[q], -1.0)
                        origin[q] = _add(origin[q], e, _dot(d, e))
                        fixed.add(q)
                        grew = True

    pending = list(names)
    while pending:
        origin[pending[0]] = (0.0, 0.0, 0.0)
        grew = True
        while grew:
            grew = False
            for a, b in same:  # axes first: the planets' arms are then read from their carrier
                for p, q in ((a, b), (b, a)):
                    if p in origin and q not in origin:
                        origin[q] = origin[p]
                        slid.add(q)  # its line is its carrier's; where along it, a bevel mesh may say
                        grew = True
            if grew:
                continue
            for k, mesh in enumerate(train.meshes):
                ma, mb = train.gear(mesh.a).member, train.gear(mesh.b).member
                for p, q in ((ma, mb), (mb, ma)):
                    if p in origin and q not in origin:
                        origin[q] = through(k, p)[1]
                        if twin(q) and k not in towards:
                            # an identical planet listed again (its side the default, or one the scene
                            # gives it would draw it over the first): across the carrier's axis
                            ta, tb = tangent[k]
                            tangent[k] = ((-ta[0], -ta[1], -ta[2]), (-tb[0], -tb[1], -tb[2]))
                            origin[q] = through(k, p)[1]
                        grew = True
                        break
                if grew:
                    break
        pending = [n for n in names if n not in origin]
    axial(set(names) - slid)

    tol = CLOSURE_REL * big

    def off_axis(n: str, p: XYZ) -> XYZ:
        """p − origin[n] with its component along n's axis removed."""
        d = _add(p, origin[n], -1.0)
        e = unsigned(n)
        return _add(d, e, -_dot(d, e))

    for a, b in same:
        d = off_axis(b, origin[a])  # the carrier's or the pair's axes, one line
        if math.sqrt(_dot(d, d)) > tol:
            raise NoSolution(f"{prime(a)} and {prime(b)} are not coaxial: their axes are {_mm(math.sqrt(_dot(d, d)))} "
                             "apart")
    def closes(k: int, ma: str, mb: str) -> tuple[bool, XYZ]:
        _, where = through(k, ma)  # where mesh k would put b's axis, from a's
        d = off_axis(mb, where)
        return math.sqrt(_dot(d, d)) <= tol, where

    for k, mesh in enumerate(train.meshes):
        ma, mb = train.gear(mesh.a).member, train.gear(mesh.b).member
        ok, where = closes(k, ma, mb)
        if ok or mesh.kind not in ("external", "internal"):
            continue
        if k not in towards:  # the other side of a's axis may close it
            ta, tb = tangent[k]
            tangent[k] = ((-ta[0], -ta[1], -ta[2]), (-tb[0], -tb[1], -tb[2]))
            if closes(k, ma, mb)[0]:
                continue
            tangent[k] = (ta, tb)
        raise NoSolution(_not_closed(train, k, ma, mb, where, origin))
    for k, mesh in enumerate(train.meshes):
        if mesh.kind != "worm":
            continue
        # a worm on a loop the other meshes closed (the double-worm reducer's second worm, placed from
        # its spur pair) takes the diameter that reaches its wheel: q is a drawing's choice
        mw, mg = train.gear(mesh.a).member, train.gear(mesh.b).member
        across = _cross(unsigned(mw), unsigned(mg))
        reach = abs(_dot(_add(origin[mw], origin[mg], -1.0), across)) - radius[mesh.b]
        if reach > 0.0 and abs(reach - radius[mesh.a]) > tol:
            radius[mesh.a] = reach
    offset = {g: slot[g] * gap for g in slot}
    for k, mesh in enumerate(train.meshes):
        if mesh.kind in ("external", "internal"):
            continue
        # across axes the partner's axis fixes where along its own axis a gear stands:
        # c_g = c_o + r_o·t_o − r_g·t_g, and c_o·e_g = origin_o·e_g since e_o ⊥ e_g
        ends: tuple[tuple[str, str, XYZ, XYZ], ...] = ((mesh.a, mesh.b, tangent[k][0], tangent[k][1]),
                                                       (mesh.b, mesh.a, tangent[k][1], tangent[k][0]))
        for g, o, t_g, t_o in ends:
            mg, mo = train.gear(g).member, train.gear(o).member
            e = unsigned(mg)
            if abs(_dot(e, unsigned(mo))) > 1e-12:
                continue
            at = _add(_add(origin[mo], t_o, radius[o]), t_g, -radius[g])
            offset[g] = _dot(_add(at, origin[mg], -1.0), e)
    lay = TrainLayout(train, module, gap, radius, axis, origin, slot, {}, tangent, parallel, offset)
    pitch = {k: _add(lay.centre(m.a), tangent[k][0], radius[m.a]) for k, m in enumerate(train.meshes)}
    return TrainLayout(train, module, gap, radius, axis, origin, slot, pitch, tangent, parallel, offset)


def _not_closed(train: GearTrain, k: int, ma: str, mb: str, p: XYZ, origin: Mapping[str, XYZ]) -> str:
    """Why mesh k does not close its loop: a planet's two arms, else the two positions of b."""
    mesh = train.meshes[k]
    for planet, other_place in ((mb, p), (ma, None)):
        h = train.member(planet).carrier
        if h is None:
            continue
        if other_place is None:  # a's position as mesh k would put it, from b's
            mesh_delta = _add(p, origin[mb], -1.0)  # where b would be minus where b is
            other_place = _add(origin[ma], mesh_delta, -1.0)
        gears = [prime(g.name) for g in train.gears if g.member == planet]
        arm_now = math.dist(origin[planet][1:], origin[h][1:])
        arm_mesh = math.dist(other_place[1:], origin[h][1:])
        return (f"the planet {'–'.join(gears)} is not coaxial: arms {_mm(arm_now)} and {_mm(arm_mesh)} "
                f"(the mesh {prime(mesh.a)}–{prime(mesh.b)} does not close the planet set of {prime(h)})")
    apart = math.dist(origin[ma][1:], origin[mb][1:])
    needs = math.dist(origin[ma][1:], p[1:])
    return (f"the mesh {prime(mesh.a)}–{prime(mesh.b)} does not close (the coaxial condition): its centre distance "
            f"is {_mm(needs)}, the other meshes put the axes of {prime(ma)} and {prime(mb)} {_mm(apart)} apart")


__all__ = ["CLOSURE_REL", "DIRECTIONS", "WORM_Q", "TrainLayout", "direction", "layout", "pitch_radius", "prime",
           "slots"]
