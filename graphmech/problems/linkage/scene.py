"""Reading a linkage scene: the frame points, the driver, Assur dyads in assembly order, extra
points on links and the driver's positions (``[frame]``, ``[driver]``, ``[[dyad]]``, ``[[point]]``).

Whether a linkage can be *assembled* at a position is not decided here: the construction does
that, position by position.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Literal, Mapping

from graphmech.errors import SceneError
from graphmech.mechanisms.linkage import (
    PRP,
    RPP,
    RPR,
    RRP,
    RRR,
    Branch,
    Crank,
    Driver,
    Guide,
    Linkage,
    LinkGuide,
    LinkPoint,
    Positions,
    SliderInput,
    Triad,
)
from graphmech.tolerances import PARALLEL_SIN

if TYPE_CHECKING:
    from graphmech.problems.cycle.scene import CycleScene
    from graphmech.problems.linkage.higher_pair import HigherPairs
from graphmech.problems.reader import (
    LINKAGE_KEYS,
    LINK_ID,
    MISSING,
    POINT_NAME,
    Reader,
    Scene,
    file_order,
    read_header,
    read_measured,
    read_scales,
    read_tail,
    say,
)


#: The choices of a dyad's keys, typed as its model takes them.
_BRANCHES: tuple[Branch, ...] = ("left", "right")
_RRP_BRANCHES: tuple[Literal["forward", "backward"], ...] = ("forward", "backward")
_BARS: tuple[Literal["first", "second"], ...] = ("first", "second")

#: What a scene may show, in the order a textbook draws them.
SHOW_CHOICES = ("mechanism", "velocity", "acceleration", "instant_centres")
#: Frame point name → coordinates in m (None when they were invalid: the name still counts).
_Frame = Mapping[str, "tuple[float, float] | None"]


@dataclass
class _Part:
    """One element's names and links, with the key paths to blame."""

    where: str  # "driver", "dyad[1]", "point[0]"
    needs: list[tuple[str, str]] = field(default_factory=list)  # (name, path) used, must exist
    defines: list[tuple[str, str]] = field(default_factory=list)  # (name, path) new points
    links: list[tuple[str, str]] = field(default_factory=list)  # (link, path) new moving links
    carries: list[tuple[str, list[str]]] = field(default_factory=list)  # link → its points
    translating: list[str] = field(default_factory=list)  # links that only translate
    on: tuple[str | None, str] | None = None  # a [[point]]'s link (None if invalid), its path
    guides_on: list[tuple[str, list[tuple[str, str]], str]] = field(default_factory=list)  # a guide's link, its line, path
    model: Any = None  # the model object, when its own values were valid
    opaque: bool = False  # its type is unknown: names and links kept, nothing checked


def _opaque(
    r: Reader, where: str, name_keys: tuple[str, ...], link_keys: tuple[str, ...]
) -> _Part:
    """A driver or dyad of unknown type: keep whatever names and links it gives, silently,
    so that the one wrong ``type`` does not bring a cascade of "not defined" after it."""

    def valid(values: Any, pattern: re.Pattern[str]) -> list[str]:
        items = values if isinstance(values, list) else [values]
        return [str(v) for v in items if isinstance(v, (str, int)) and pattern.fullmatch(str(v))]

    names = [n for key in name_keys for n in valid(r.table.get(key), POINT_NAME)]
    links = [x for key in link_keys for x in valid(r.table.get(key), LINK_ID)]
    return _Part(
        where,
        defines=[(n, where) for n in names],
        links=[(x, where) for x in links],
        carries=[(x, names) for x in links],
        opaque=True,
    )


def _read_frame(top: Reader) -> tuple[dict[str, tuple[float, float] | None], str | None]:
    """[frame]: point coordinates (m; None when invalid) and the optional frame link number."""
    r = top.table_at("frame")
    points: dict[str, tuple[float, float] | None] = {}
    if r is None:
        return points, None
    link = None
    value = r.raw("link")
    if value is not MISSING:
        link = r.link_id(value, r.at("link"))
    for key in list(r.table):
        if key in r.used or key == "link":
            continue
        name = key.split("_", 1)[0]
        if not POINT_NAME.fullmatch(name) or len(name) > 8:
            continue  # finish() reports it
        points[name] = r.pair(name)  # the name counts even if its coordinates are wrong
    r.finish("a frame point is named in capitals with its coordinates, e.g. A_mm = [0, 0]")
    return points, link


def _read_guide(parent: Reader, key: str, frame: _Frame, sub: Reader | None = None) -> Guide | None:
    """A frame guide {through = [x, y] or a frame point's name, angle (default 0)}."""
    r = sub if sub is not None else parent.table_at(
        key, required=True, hint=f"write {key} = {{through_mm = [0, 0], angle_deg = 0}}"
    )
    if r is None:
        return None
    through: tuple[float, float] | None
    if isinstance(name := r.table.get("through"), str):
        r.raw("through")  # marks the key read: its value is name
        through = frame.get(name)
        if name not in frame:
            r.problem(r.at("through"), f"{say(name)} is not a frame point")
    else:
        through = r.pair("through")
    angle = r.scalar("angle", "angle", required=False, default=0.0)
    r.finish()
    return Guide(through, angle) if through is not None and angle is not None else None


def _read_any_guide(parent: Reader, key: str, frame: _Frame, part: _Part, sub: Reader | None = None
                    ) -> Guide | LinkGuide | None:
    """A frame guide, or a guide on a moving link: ``{link = "1", line = ["A", "B"]}``, the line
    through two points of that link (defined before the dyad), turning with it."""
    r = sub if sub is not None else parent.table_at(
        key, required=True, hint=f"write {key} = {{through_mm = [0, 0], angle_deg = 0}}")
    if r is None:
        return None
    if "line" not in r.table and "link" not in r.table:
        return _read_guide(parent, key, frame, r)
    value = r.raw("link", required=True, hint='the number of the moving link the guide is on, e.g. link = "1"')
    link = None if value is MISSING else r.link_id(value, r.at("link"))
    line = r.name_list("line", 2, r.point_name)
    for extra in ("through", "angle"):
        found = r.present(extra)
        if found is not None:
            r.used.add(found)
            r.problem(r.at(found), "a guide on a link is the line through two of its points: give line, not " + extra)
    r.finish()
    (u, u_path), (v, v_path) = line
    if u is not None and u == v:
        r.problem(v_path, f"the line's two points must differ ({u} twice)")
        return None
    if link is None or u is None or v is None:
        return None
    part.needs += [(u, u_path), (v, v_path)]
    part.guides_on.append((link, [(u, u_path), (v, v_path)], r.at("link")))
    return LinkGuide(link, u, v)


def _read_driver(
    top: Reader, frame: _Frame, crank_only: str = ""
) -> tuple[_Part, Positions | None]:
    """[driver]: a crank or a slider, and the positions it is drawn at.

    ``crank_only``: the reason a slider is refused (a scene whose driver must be a crank).
    """
    part = _Part("driver")
    r = top.table_at(
        "driver", required=True, hint='add a [driver] table (type = "crank" or "slider")'
    )
    if r is None:
        return part, None
    kind = r.string("type", choices=("crank", "slider"), required=True)
    if kind == "slider" and crank_only:
        r.problem(r.at("type"), crank_only)
        kind = None
    if kind is None:
        return _opaque(r, "driver", ("pivot", "tip", "point"), ("link",)), None
    link_value = r.raw("link", required=True, hint='the driver\'s link number, e.g. link = "1"')
    link = None if link_value is MISSING else r.link_id(link_value, r.at("link"))
    if link is not None:
        part.links.append((link, r.at("link")))

    def name(key: str) -> str | None:
        value = r.raw(key, required=True, hint='a point name such as "B"')
        return None if value is MISSING else r.point_name(value, r.at(key))

    model: Driver | None = None
    if kind == "crank":
        pivot, tip = name("pivot"), name("tip")
        length = r.scalar("length", "length", positive=True)
        positions = r.positions("angle", "angle")
        omega = r.scalar("omega", "omega")
        epsilon = r.scalar("epsilon", "epsilon", required=False, default=0.0)
        direction = r.string("direction", choices=("ccw", "cw"), default="ccw")
        if direction == "cw" and omega is not None and epsilon is not None:
            if omega < 0:
                r.problem(
                    r.at("direction"), 'with direction = "cw" give omega as a magnitude (≥ 0)'
                )
                omega = None
            else:  # both read positive clockwise; stored CCW-positive
                omega, epsilon = -omega + 0.0, -epsilon + 0.0
        if pivot is not None:
            if pivot not in frame:
                known = f"frame points: {', '.join(frame)}" if frame else "add it to [frame]"
                r.problem(r.at("pivot"), f"{pivot} is not a frame point ({known})")
            else:
                part.needs.append((pivot, r.at("pivot")))
        if tip is not None:
            part.defines.append((tip, r.at("tip")))
        if link is not None:
            part.carries.append((link, [n for n in (pivot, tip) if n]))
        if (link is not None and pivot is not None and tip is not None and length is not None
                and omega is not None and epsilon is not None and direction is not None):
            model = Crank(link, pivot, tip, length, omega, epsilon)
    else:
        point = name("point")
        guide = _read_guide(r, "guide", frame)
        positions = r.positions("position", "length")
        velocity = r.scalar("velocity", "velocity")
        acceleration = r.scalar("acceleration", "acceleration", required=False, default=0.0)
        if point is not None:
            part.defines.append((point, r.at("point")))
        if link is not None:
            part.carries.append((link, [point] if point else []))
            part.translating.append(link)
        if (link is not None and point is not None and guide is not None and velocity is not None
                and acceleration is not None):
            model = SliderInput(link, point, guide, velocity, acceleration)
    r.finish()
    part.model = model
    return part, positions


_DYAD_TYPES = ("RRR", "RRP", "RPR", "RPP", "PRP")


def _read_dyad(r: Reader, index: int, frame: _Frame) -> _Part:
    """One [[dyad]]: its joints, links and dimensions, by type."""
    where = f"dyad[{index}]"
    part = _Part(where)
    kind = r.string("type", choices=_DYAD_TYPES, required=True)
    if kind is None:
        return _opaque(r, where, ("joints",), ("links",))
    count = 3 if kind == "RRR" else 1 if kind == "PRP" else 2
    joints = r.name_list("joints", count, r.point_name)
    links = r.name_list("links", 2, r.link_id)
    (i, i_path), (j, j_path) = links
    part.links = [(x, p) for x, p in links if x is not None]
    if i is not None and i == j:
        r.problem(j_path, "a dyad's two links must differ")
    names = [n for n, _ in joints]

    def carry(link: str | None, *points: str | None) -> None:
        if link is not None:
            part.carries.append((link, [p for p in points if p]))

    def new(k: int, name: str | None = None) -> None:
        n = joints[k][0] if name is None else name
        if n is not None:
            part.defines.append((n, joints[k][1]))

    def need(*ks: int) -> None:
        for k in ks:
            n, path = joints[k]
            if n is not None:
                part.needs.append((n, path))

    if kind == "RRR":
        p, c, q = names
        lengths_given = r.quantity("lengths", "length")
        lengths: tuple[float, float] | None = None
        if lengths_given is not None:
            raw = r.numbers(
                lengths_given.value,
                r.at(lengths_given.key),
                2,
                positive=True,
                shape=f"[l_{p or 'P'}{c or 'C'}, l_{q or 'Q'}{c or 'C'}]",
            )
            lengths = None if raw is None else (lengths_given.si(raw[0]), lengths_given.si(raw[1]))
        branch = r.string("branch", choices=_BRANCHES, required=True)
        need(0, 2)
        new(1)
        carry(i, p, c)
        carry(j, q, c)
        if (p is not None and c is not None and q is not None and i is not None and j is not None
                and lengths is not None and branch is not None):
            part.model = RRR(p, c, q, (i, j), lengths, branch)
        if p is not None and p == q:
            r.problem(joints[2][1], f"the two outer joints must differ ({p} twice)")
    elif kind == "RRP":
        p, c = names
        length = r.scalar("length", "length", positive=True)
        guide = _read_any_guide(r, "guide", frame, part)
        side = r.string("branch", choices=_RRP_BRANCHES, required=True)
        need(0)
        new(1)
        carry(i, p, c)
        carry(j, c)
        if isinstance(guide, LinkGuide):  # a slotted link drives the pin C: C<j> and C<link> stand at C
            if c is not None and j is not None and guide.link not in (i, j):  # (its own link: refused below)
                new(1, c + j)
                new(1, c + guide.link)
                carry(j, c + j)
                carry(guide.link, c + guide.link)
        elif j is not None:
            part.translating.append(j)
        if (p is not None and c is not None and i is not None and j is not None and length is not None
                and guide is not None and side is not None):
            part.model = RRP(p, c, (i, j), length, guide, side)
    elif kind == "RPR":
        p, q = names
        bar = r.string("bar", choices=_BARS, required=True)
        offset = r.scalar("offset", "length", required=False, default=0.0)  # e: an offset guide bar
        need(0, 1)
        if p is not None and p == q:
            r.problem(joints[1][1], f"the two pivots must differ ({p} twice)")
        if (p is not None and q is not None and i is not None and j is not None and bar is not None
                and offset is not None):
            model = RPR(p, q, (i, j), bar, offset)
            part.model = model
            on_bar, on_block = model.coincident
            k = 1 if bar == "first" else 0  # the sliding point is the block's pivot
            new(k, on_bar)
            new(k, on_block)
            carry(model.bar_link, model.bar_pivot, on_bar)
            carry(model.block_link, model.block_pivot, on_block)
        else:
            carry(i, p)
            carry(j, q)
    elif kind == "PRP":
        c = names[0]
        new(0)
        guides: list[Guide | LinkGuide | None] = [None, None]
        value = r.raw("guides", required=True,
                      hint='the two blocks\' guides, e.g. guides = [{link = "1", line = ["A", "B"]}, '
                           '{through_mm = [100, 0], angle_deg = 90}]')
        if value is not MISSING:
            if not isinstance(value, list) or len(value) != 2 or not all(isinstance(g, dict) for g in value):
                r.problem(r.at("guides"), "must be a list of 2 guide tables, one per block, in the order of links")
            else:
                guides = [_read_any_guide(r, "guides", frame, part, r.sub(g, f"{r.at('guides')}[{m}]"))
                          for m, g in enumerate(value)]
        g0, g1 = guides
        same = isinstance(g0, LinkGuide) and isinstance(g1, LinkGuide) and g0.link == g1.link
        if same:
            r.problem(f"{r.at('guides')}[1].link", "both guides on one link: C is fixed on it where their lines "
                                                   "meet, the blocks cannot slide (put the guides on two links)")
        for m, (x, g) in enumerate(zip((i, j), guides)):
            carry(x, c, c + x if c and x else None)
            if isinstance(g, LinkGuide) and g.link not in (i, j) and not (same and m == 1):  # else refused
                carry(g.link, c + g.link if c else None)
                if c:
                    new(0, c + g.link)
            elif g is not None and x is not None:
                part.translating.append(x)
            if c and x:
                new(0, c + x)
        if all(isinstance(g, Guide) for g in guides):
            r.problem(r.at("guides"), "both guides on the frame: the dyad cannot move (put one on a moving "
                                      'link: {link = "1", line = ["A", "B"]})')
        elif (c is not None and i is not None and j is not None and guides[0] is not None and guides[1] is not None
              and not same):
            part.model = PRP(c, (i, j), (guides[0], guides[1]))
    else:  # RPP
        p, c = names
        slot = r.scalar("slot_angle", "angle")
        guide = _read_guide(r, "guide", frame)
        need(0)
        new(1)
        if p is not None and i is not None and j is not None:
            new(0, p + i)
            new(0, p + j)
        carry(i, p, p + i if p and i else None)
        carry(j, c, p + j if p and j else None)
        part.translating.extend(x for x in (i, j) if x is not None)
        if (
            slot is not None
            and guide is not None
            and abs(math.sin(slot - guide.angle)) < PARALLEL_SIN
        ):
            r.problem(r.at("slot_angle"), "the slot is parallel to the guide: the dyad cannot move")
        elif (p is not None and c is not None and i is not None and j is not None and slot is not None
              and guide is not None):
            part.model = RPP(p, c, (i, j), slot, guide)
    r.finish()
    return part


_TRIAD_TYPES = ("RRR-III",)


def _read_triad(r: Reader, index: int, frame: _Frame) -> _Part:
    """One [[triad]]: a class III group — three binary links from known points to a ternary link."""
    where = f"triad[{index}]"
    part = _Part(where)
    kind = r.string("type", choices=_TRIAD_TYPES, required=True)
    if kind is None:
        return _opaque(r, where, ("inner",), ("links",))
    outer = r.name_list("outer", 3, r.point_name)
    inner = r.name_list("inner", 3, r.point_name)
    links = r.name_list("links", 4, r.link_id)
    # A slider leg (a block on a frame guide, the IC engine's piston): its outer entry repeats its
    # inner joint, and slider_guide is that guide
    sliding = [k for k in range(3) if outer[k][0] is not None and outer[k][0] == inner[k][0]]
    guide = _read_guide(r, "slider_guide", frame) if r.present("slider_guide") is not None else None
    if sliding and r.present("slider_guide") is None:
        r.problem(r.at("slider_guide"), f"missing: outer repeats {outer[sliding[0]][0]}, a block on a frame guide "
                  "— give slider_guide = {through = [x, y], angle = a}")
    elif len(sliding) > 1:
        r.problem(outer[sliding[1]][1], "one slider leg at most (outer repeats its inner joint once)")
    elif not sliding and r.present("slider_guide") is not None:
        r.problem(r.at("slider_guide"), "no slider leg: repeat that leg's inner joint in outer to slide it on this guide")
    part.links = [(x, p) for x, p in links if x is not None]
    part.needs = [(n, p) for k, (n, p) in enumerate(outer) if n is not None and k not in sliding]
    part.defines = [(n, p) for n, p in inner if n is not None]
    seen: dict[str, str] = {}
    for x, path in links:
        if x is not None and x in seen:
            r.problem(path, f"a class III group's four links must differ ({x} twice)")
        seen.setdefault(x or "", path)
    names = [x for k, (x, _) in enumerate(outer) if k not in sliding] + [x for x, _ in inner]
    paths = [p for k, (_, p) in enumerate(outer) if k not in sliding] + [p for _, p in inner]
    for k, x in enumerate(names):
        if x is not None and x in names[:k]:
            r.problem(paths[k], f"the group's {'' if sliding else 'six '}joints must differ ({x} twice)")
    slider_link = links[sliding[0]][0] if sliding else None
    if slider_link is not None:
        part.translating.append(slider_link)
    for k in range(3):
        lk = links[k][0]
        if lk is not None:
            part.carries.append((lk, [x for x in (None if k in sliding else outer[k][0], inner[k][0]) if x]))
    ternary_link = links[3][0]
    if ternary_link is not None:
        part.carries.append((ternary_link, [x for x, _ in inner if x]))

    def lengths(key: str, shape: str, free: list[int]) -> tuple[float, float, float] | None:
        """Three lengths > 0; a slider leg's (``free``) must be 0: its block has no outer pivot."""
        given = r.quantity(key, "length")
        if given is None:
            return None
        raw = r.numbers(given.value, r.at(given.key), 3, positive=not free, shape=shape)
        for k in range(3) if raw is not None and free else ():
            if (raw[k] != 0.0) if k in free else not raw[k] > 0.0:  # type: ignore[index]
                r.problem(f"{r.at(given.key)}[{k}]", "must be 0 for the slider leg" if k in free else "must be > 0")
                raw = None
                break
        return None if raw is None else (given.si(raw[0]), given.si(raw[1]), given.si(raw[2]))

    binary = lengths("lengths", "[l_BC, l_FD, l_GE]", sliding)
    sides = lengths("ternary", "[l_CD, l_DE, l_EC]", [])
    if sides is not None:
        a, b, c = sides
        if not (a < b + c and b < a + c and c < a + b):
            r.problem(r.at(r.present("ternary") or "ternary"),
                      "the ternary link's sides [l_CD, l_DE, l_EC] do not make a triangle")
            sides = None
    start: tuple[tuple[float, float], tuple[float, float], tuple[float, float]] | None = None
    given = r.quantity("start", "length")
    if given is not None:
        path = r.at(given.key)
        value = given.value
        if not isinstance(value, list) or len(value) != 3:
            r.problem(path, "must be [[x, y], [x, y], [x, y]]: C, D, E near the wanted assembly")
        else:
            raw = [r.numbers(v, f"{path}[{k}]", 2) for k, v in enumerate(value)]
            pts = [(given.si(p[0]), given.si(p[1])) for p in raw if p is not None]
            if len(pts) == 3:
                (cx, cy), (dx, dy), (ex, ey) = pts
                if (dx - cx) * (ey - cy) - (dy - cy) * (ex - cx) == 0.0:
                    r.problem(path, "C, D, E in line: the start must show the ternary link's triangle")
                else:
                    start = (pts[0], pts[1], pts[2])
    assur: tuple[int, int] = (0, 1)
    if r.present("assur") is not None:
        pair = r.name_list("assur", 2, r.link_id)
        ids = [x for x, _ in links[:3]]
        got = [ids.index(x) if x in ids else None for x, _ in pair]
        for (x, at), idx in zip(pair, got):
            if x is not None and idx is None:
                r.problem(at, f"{x} is not one of the group's binary links ({', '.join(i or '?' for i in ids)})")
        g0, g1 = got
        if g0 is not None and g1 is not None:
            if g0 == g1:
                r.problem(pair[1][1], "name two different binary links")
            else:
                assur = (g0, g1)
    r.finish()
    o = [x for x, _ in outer if x is not None]
    i_ = [x for x, _ in inner if x is not None]
    ln = [x for x, _ in links if x is not None]
    if (len(o) == 3 and len(i_) == 3 and len(ln) == 4 and binary is not None and sides is not None
            and start is not None and len(seen) == 4):
        guides = tuple(guide if k in sliding else None for k in range(3))
        if not sliding or guide is not None:
            part.model = Triad((o[0], o[1], o[2]), (i_[0], i_[1], i_[2]), (ln[0], ln[1], ln[2], ln[3]), binary, sides,
                               start, assur, (guides[0], guides[1], guides[2]))
    return part


def _assembly_order(dyads: list[_Part], triads: list[_Part], points: list[_Part]) -> list[_Part]:
    """The groups in assembly order: each class III group right after the last group that makes one
    of its outer joints, directly or through the base points of a [[point]] (first of all when the
    frame and the driver make them), and after the class III groups written before it."""
    out = list(dyads)
    after = 0  # class III groups keep their file order among themselves
    for t in triads:
        ready = {n: k + 1 for k, d in reversed(list(enumerate(out))) for n, _ in d.defines}
        for p in points:  # a point is known once its base points are (points in file order)
            for n, _ in p.defines:
                ready.setdefault(n, max((ready.get(b, 0) for b, _ in p.needs), default=0))
        at = max([after, *(ready.get(n, 0) for n, _ in t.needs)])
        out.insert(at, t)
        after = at + 1
    return out


def _read_point(r: Reader, index: int) -> _Part:
    """One [[point]]: a point fixed on a link, placed from one or two points of that link."""
    part = _Part(f"point[{index}]")
    value = r.raw("name", required=True, hint='a point name such as "E"')
    name = None if value is MISSING else r.point_name(value, r.at("name"))
    value = r.raw("link", required=True, hint="the number of the link that carries the point")
    link = None if value is MISSING else r.link_id(value, r.at("link"))
    bases: list[tuple[str, str]] = []
    value = r.raw("base", required=True, hint='base = ["B", "C"] (or one point with offset)')
    ok = value is not MISSING
    if ok and (not isinstance(value, list) or len(value) not in (1, 2)):
        r.problem(r.at("base"), "must be a list of 1 or 2 point names")
        ok = False
    elif ok and isinstance(value, list):  # a list of 1 or 2: the branch above refused the rest
        for k, b in enumerate(value):
            b_name = r.point_name(b, f"{r.at('base')}[{k}]")
            ok = ok and b_name is not None
            if b_name is not None:
                bases.append((b_name, f"{r.at('base')}[{k}]"))
        if len(bases) == 2 and bases[0][0] == bases[1][0]:
            r.problem(bases[1][1], f"the two base points must differ ({bases[0][0]} twice)")
            ok = False
    along = left = None
    if ok and len(bases) == 1:  # a translating link: offset [dx, dy] from the one point
        offset = r.pair("offset", required=False)
        if offset is None and r.present("offset") is None:
            r.problem(r.at("offset"), "missing: with one base point give offset_mm = [dx, dy]")
        for key in filter(None, (r.present("along"), r.present("left"))):
            r.used.add(key)
            r.problem(r.at(key), "with one base point give offset = [dx, dy] instead")
        if offset is not None:
            along, left = offset
    elif ok:  # U + along·û + left·n̂
        along = r.scalar("along", "length")
        left = r.scalar("left", "length", required=False, default=0.0)
        offset_key = r.present("offset")
        if offset_key is not None:
            r.used.add(offset_key)
            r.problem(
                r.at(offset_key), "offset needs a single base point; with two give along/left"
            )
    else:  # base is broken: still read the rest so that it is not reported as unknown
        for extra in ("along", "left", "offset"):
            r.quantity(extra, "length", required=False)
    r.finish()
    if name is not None:
        part.defines.append((name, r.at("name")))
    part.needs, part.on = bases, (link, r.at("link"))
    if name is not None and link is not None and along is not None and left is not None and ok:
        part.model = LinkPoint(name, link, tuple(b for b, _ in bases), along, left)
    return part


#: Why a [[triad]] is refused where it is (a flywheel's machine; the extreme positions and γ).
TRIAD_NOT_YET = ("a class III group is solved in linkage scenes (polygons, instant centres, the full cycle) and force "
                 "scenes only so far: not in [characteristics] or a flywheel's machine yet")


def read_linkage(
    top: Reader, crank_only: str = "", triads: bool = False
) -> tuple[Linkage | None, Positions | None, _Part]:
    """[frame], [driver], [[dyad]], [[triad]] and [[point]], cross-checked.

    Returns the linkage (None when anything in those tables was wrong), the driver's
    positions and the driver as read. ``crank_only``: see :func:`_read_driver`. ``triads``:
    whether the caller solves class III groups (else a [[triad]] is refused).
    """
    data = top.table
    before = len(top.problems)
    frame, link_value = _read_frame(top)
    frame_link_given = (
        "frame" in data and isinstance(data["frame"], dict) and "link" in data["frame"]
    )
    driver, positions = _read_driver(top, frame, crank_only)
    dyads = [_read_dyad(r, k, frame) for k, r in enumerate(top.tables_at("dyad"))]
    triad_parts = [_read_triad(r, k, frame) for k, r in enumerate(top.tables_at("triad"))]
    if not triads and "triad" in data:
        top.problem("triad", TRIAD_NOT_YET)
    points = [_read_point(r, k) for k, r in enumerate(top.tables_at("point"))]
    dyads = _assembly_order(dyads, triad_parts, points)
    frame_link = _check_structure(
        top.problems, frame, (link_value, frame_link_given), driver, dyads, points
    )
    if len(top.problems) != before or any(p.model is None for p in (driver, *dyads, *points)):
        return None, positions, driver
    linkage = Linkage(
        frame_points={name: xy for name, xy in frame.items() if xy is not None},
        driver=driver.model,
        dyads=tuple(d.model for d in dyads),
        points=tuple(p.model for p in points),
        frame_link=frame_link or "0",
    )
    return linkage, positions, driver


def _check_structure(
    problems: list[tuple[str, str]],
    frame: _Frame,
    frame_link: tuple[str | None, bool],
    driver: _Part,
    dyads: list[_Part],
    points: list[_Part],
) -> str | None:
    """Check names and links across the scene; return the frame link (None if unknown)."""
    origin: dict[str, str] = {n: "frame" for n in frame}  # name → who defines it
    stage: dict[str, int] = {n: 0 for n in frame}  # name → first dyad index that may use it
    owner: dict[str, str] = {}  # link → who introduced it
    carried: dict[str, list[str]] = {}
    translating: set[str] = set()

    def define(part: _Part, level: int) -> None:
        for name, path in part.defines:
            if part.opaque and name in origin:
                continue
            if name in origin:
                who = "a frame point" if origin[name] == "frame" else f"by {origin[name]}"
                problems.append((path, f"{name} is already defined ({who})"))
            else:
                origin[name], stage[name] = part.where, level

    def carry(part: _Part) -> None:
        for link, names in part.carries:
            lst = carried.setdefault(link, [])
            lst.extend(n for n in names if n not in lst)
        translating.update(part.translating)

    # Driver and dyads: new links, new points, in assembly order.
    for level, part in enumerate([driver, *dyads]):
        for link, path in part.links:
            if link in owner and owner[link] != part.where and not part.opaque:
                problems.append(
                    (
                        path,
                        f"link {link} is already used by {owner[link]}; "
                        "each dyad adds two new links",
                    )
                )
            owner.setdefault(link, part.where)
        define(part, level)
        carry(part)

    # Points, in file order: on an existing moving link, placed from that link's points.
    for part in points:
        (on, on_path), bases = part.on or (None, ""), part.needs
        level = 0
        for base, path in bases:
            if on is None or on not in carried:
                continue
            if base not in origin:
                later = next(
                    (
                        p.where
                        for p in points
                        if p is not part and any(n == base for n, _ in p.defines)
                    ),
                    None,
                )
                tip = f" ({later} defines it: list that point first)" if later else ""
                problems.append((path, f"{base} is not defined before {part.where}{tip}"))
            elif base not in carried[on]:
                problems.append(
                    (
                        path,
                        f"{base} is not a point of link {on} (it carries {', '.join(carried[on])})",
                    )
                )
            else:
                level = max(level, stage[base])
        if on is not None and on not in carried:
            if on == frame_link[0]:
                problems.append((on_path, "a point on the frame belongs in [frame]"))
            else:
                problems.append(
                    (
                        on_path,
                        f"link {on} does not exist (links: {', '.join(carried) or 'none'})",
                    )
                )
        elif on is not None and len(bases) == 1 and on not in translating:
            problems.append(
                (
                    on_path,
                    f"link {on} turns: an offset from one base point needs a translating "
                    "link (a slider); give base = [U, V] with along/left",
                )
            )
        define(part, level)
        if on is not None and on in carried:
            carry(_Part(part.where, carries=[(on, [n for n, _ in part.defines])]))

    # Dyads' outer joints: defined by the frame, the driver or an earlier dyad (or a point
    # placed from those).
    for k, part in enumerate(dyads):
        for name, path in part.needs:
            if name in stage and stage[name] <= k:
                continue
            if name in origin and stage[name] == k + 1:  # made by this group, or placed from its joints
                tip = (" (it is this group's own new joint)" if origin[name] == part.where else
                       f" ({origin[name]} places it from {part.where}'s own joints: a group cannot hang on itself)")
            elif name in origin:
                tip = f" ({origin[name]} defines it: put that first)"
            else:
                tip = ""
            problems.append((path, f"{name} is not defined before {part.where}{tip}"))

    # Guides on moving links: a link introduced before the dyad, the line through two of its points.
    order = [driver.where] + [p.where for p in dyads]
    for k, part in enumerate(dyads):
        for link, line, path in part.guides_on:
            if link not in owner or order.index(owner[link]) > k:
                where = ("the frame: give through and angle" if link == frame_link[0] else
                         f"{part.where}'s own: a guide is on a link defined before it" if owner.get(link) == part.where
                         else f"not a moving link defined before {part.where}")
                problems.append((path, f"link {link} is {where}"))
                continue
            for name, name_path in line:
                if name in origin and name not in carried.get(link, []):
                    carries = ", ".join(carried[link])
                    problems.append((name_path, f"{name} is not a point of link {link} (it carries {carries})"))

    # The frame link.
    fixed, explicit = frame_link
    if explicit:
        if fixed is not None and fixed in owner:
            problems.append(("frame.link", f"link {fixed} is a moving link ({owner[fixed]})"))
        return fixed
    numeric = [int(x) for x in owner if x.isdigit()]
    return str(max(numeric) + 1) if numeric else "0"


def _triad_refusals(top: Reader, data: Mapping[str, Any]) -> None:
    """What a scene with a class III group may not ask for yet: one line each."""
    for key in ("characteristics",):
        if key in data:
            top.problem(key, TRIAD_NOT_YET)


def parse_linkage_scene(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]
                        ) -> Scene[CycleScene | HigherPairs | None]:
    """The rest of :func:`graphmech.scene.parse_scene` for a linkage scene (with a full cycle or
    the characteristics when it asks for them)."""
    problems = top.problems
    if not any(k in data for k in LINKAGE_KEYS):
        top.problem(
            "",
            "nothing to draw: add a [driver] table (a linkage scene) or a [cam] table "
            "(a disc cam scene)",
        )
        read_header(top, SHOW_CHOICES, SHOW_CHOICES)
        read_scales(top)
        read_measured(top, None)
        read_tail(top)
        problems.sort(key=lambda p: file_order(p, order))
        raise SceneError(problems, source)
    from graphmech.problems.cycle.scene import CYCLE_SHOW_CHOICES, read_cycle

    default = ("cycle",) if "cycle" in data else ("characteristics",) if "characteristics" in data else SHOW_CHOICES
    title, show, find = read_header(top, SHOW_CHOICES + CYCLE_SHOW_CHOICES, default)
    scales = read_scales(top)
    linkage, positions, _ = read_linkage(top, triads=True)
    if "triad" in data:
        _triad_refusals(top, data)
    cycle = None
    if "cycle" in data or "characteristics" in data or any(s in CYCLE_SHOW_CHOICES for s in show):
        cycle, positions = read_cycle(top, data, show, linkage, positions)
    # -- higher pairs inside the linkage (issue 22 item 4; graphmech/problems/linkage/higher_pair.py)
    higher = None
    if "higher_pair" in data:
        from graphmech.problems.linkage.higher_pair import read_higher_pairs

        higher = read_higher_pairs(top, linkage, positions, show, find)
        if cycle is not None:
            top.problem("higher_pair", "a higher pair is substituted at a stated position: not over a full cycle")
    # -- end of higher pairs
    measured = read_measured(top, positions.labels if positions else None)
    precision, page = read_tail(top)
    if problems or linkage is None:
        problems.sort(key=lambda p: file_order(p, order))
        raise SceneError(problems or [("driver", "invalid")], source)
    return Scene(
        source=source,
        title=title,
        show=show,
        find=find,
        scales=scales,
        linkage=linkage,
        positions=positions,
        measured=measured,
        precision_mm=precision,
        page=page,
        kind="linkage" if cycle is None else "cycle",
        problem=cycle if cycle is not None else higher,
    )
