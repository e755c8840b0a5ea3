"""A planar mechanism's topology: its links and pairs; mobility and structure (Assur groups).

What the book does before any kinematics (平面机构的结构分析):

* **mobility** by the Grübler–Kutzbach count ``F = 3n − (2pl + ph − p′) − F′``: n moving links,
  pl lower pairs (revolute R, prismatic P; a compound hinge joining k links counts k − 1),
  ph higher pairs, p′ redundant constraints (虚约束), F′ local freedoms (局部自由度, e.g. a
  roller turning about its own pin);
* the **actual mobility** at a given geometry: ``F = 3n − rank J`` less the local freedoms,
  where J is the Jacobian of the pair constraints with respect to the links' (x, y, θ) —
  the redundant constraints are ``p′ = (2pl + ph) − rank J`` (a parallelogram with an extra
  parallel link: the count says 0, the linkage moves);
* the **structure**: with the drivers and the frame known, split the other links into the
  smallest groups with zero mobility of their own (Assur groups, 基本杆组), each attached to
  what is already known; a group's class is II for a dyad, else the largest closed contour
  inside it (a ternary link's three pairs: III; a four-sided contour: IV); the mechanism's
  class is its highest group's.

Everything here is pure and SI; numbers only enter through the joints' coordinates.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from itertools import combinations
from typing import Literal

import numpy as np

from graphmech.errors import OutOfDomain

PairKind = Literal["R", "P", "higher"]

#: The largest Assur group searched for (links): class II–IV groups of the books have 2, 4 or 6.
MAX_GROUP = 6
#: The most candidate groups of one size examined before the search gives up.
MAX_CANDIDATES = 200_000

#: Relative singular value below which the constraint Jacobian counts as rank-deficient
#: (σ ≤ RANK_REL·σ_max). Constraint rows are O(1) (unit directions) and O(size) (lever arms),
#: so the columns are scaled by the mechanism's size first.
RANK_REL = 1e-9


@dataclass(frozen=True)
class Pair:
    """A kinematic pair (运动副).

    Parameters
    ----------
    kind : {"R", "P", "higher"}
        Revolute, prismatic (both lower pairs) or a higher pair (point or line contact).
    links : tuple of str
        The links it joins; an R joining k > 2 links is a compound hinge (k − 1 pairs).
    name : str
        The book's letter (``"A"``), for messages and drawings.
    at : (float, float) or None
        Where it is, m: the hinge's centre, a point of the prismatic pair's guide, the contact
        point of a higher pair. Needed for the Jacobian, not for the count.
    angle : float or None
        A prismatic pair's guide direction, or a higher pair's common normal, rad.
    """

    kind: PairKind
    links: tuple[str, ...]
    name: str = ""
    at: tuple[float, float] | None = None
    angle: float | None = None

    @property
    def count(self) -> int:
        """How many pairs it counts as: k − 1 for a hinge of k links."""
        return len(self.links) - 1


@dataclass(frozen=True)
class Topology:
    """Links and pairs of a planar mechanism; ``frame`` is the fixed link, ``drivers`` the inputs."""

    frame: str
    links: tuple[str, ...]  # moving links, in the book's order
    pairs: tuple[Pair, ...]
    drivers: tuple[str, ...] = ()
    redundant: int | None = None  # p′ as the book states it (None: not stated)

    @property
    def n(self) -> int:
        return len(self.links)

    @property
    def pl(self) -> int:
        return sum(p.count for p in self.pairs if p.kind in ("R", "P"))

    @property
    def ph(self) -> int:
        return sum(p.count for p in self.pairs if p.kind == "higher")

    @property
    def compound(self) -> tuple[Pair, ...]:
        """The compound hinges (复合铰链): revolutes joining three links or more."""
        return tuple(p for p in self.pairs if p.kind == "R" and len(p.links) > 2)

    def pairs_of(self, link: str) -> list[Pair]:
        return [p for p in self.pairs if link in p.links]

    def rollers(self) -> tuple[str, ...]:
        """Links with a local freedom (局部自由度): a roller — a moving link with exactly one
        revolute, to another moving link (the follower that carries it), and one higher pair and
        nothing else; it may turn about its pin without moving anything else (the contact normal
        passes through the pin for a round roller). A link pinned to the frame with one higher
        pair is an oscillating follower, not a roller."""
        out = []
        for lid in self.links:
            ps = self.pairs_of(lid)
            kinds = sorted(p.kind for p in ps)
            pin = next((p for p in ps if p.kind == "R"), None)
            if (kinds == ["R", "higher"] and all(len(p.links) == 2 for p in ps) and lid not in self.drivers
                    and pin is not None and self.frame not in pin.links):
                out.append(lid)
        return tuple(out)


@dataclass(frozen=True)
class Mobility:
    """The Grübler–Kutzbach count and, with a geometry, the Jacobian's rank.

    ``F_count = 3n − 2pl − ph`` (nothing recognised); ``F = 3n − (2pl + ph − p′) − F′`` with p′
    as the scene states it (else 0: a count cannot see a redundant constraint) and F′ the rollers;
    ``F_actual = 3n − rank J − F′`` and ``p_redundant_actual = (2pl + ph) − rank J``.
    """

    n: int
    pl: int
    ph: int
    F_local: int
    p_redundant: int
    F_count: int
    F: int
    rank: int | None = None
    equations: int | None = None
    F_actual: int | None = None
    p_redundant_actual: int | None = None
    singular_values: tuple[float, ...] = ()
    tolerance: float = RANK_REL
    compound: tuple[str, ...] = ()
    rollers: tuple[str, ...] = ()


def constraint_jacobian(topo: Topology) -> np.ndarray:
    """The pair constraints' Jacobian at the given geometry, columns (x, y, θ·L) of each link.

    Every link's frame is put at its own configuration (θ = 0 now), so a point P of link a moves
    by ``δx_a + δθ_a·k×(P − o)`` where o is the coordinate origin. An R pair at P between a and
    b gives two rows (the points of a and b at P move alike), a P pair two (the same rotation;
    no motion across the guide), a higher pair one (no motion along the common normal).
    θ is scaled by the mechanism's size L so that all columns are lengths.

    Raises
    ------
    ValueError
        If a pair has no coordinates.
    """
    cols = {lid: 3 * k for k, lid in enumerate(topo.links)}
    pts = [p.at for p in topo.pairs if p.at is not None]
    if len(pts) < len(topo.pairs):
        missing = [p.name or "+".join(p.links) for p in topo.pairs if p.at is None]
        raise OutOfDomain(f"pairs without coordinates: {', '.join(missing)}")
    cx, cy, size = _reference(topo)
    rows: list[np.ndarray] = []

    def point_row(link: str, sign: float, px: float, py: float, d: tuple[float, float], row: np.ndarray) -> None:
        """Add ``sign · d·(δx + δθ·k×r)`` of link's point at P to the row (nothing for the frame)."""
        if link == topo.frame:
            return
        c = cols[link]
        rx, ry = px - cx, py - cy
        row[c] += sign * d[0]
        row[c + 1] += sign * d[1]
        row[c + 2] += sign * (d[0] * -ry + d[1] * rx) / size

    for p in topo.pairs:
        assert p.at is not None
        px, py = p.at
        if p.kind == "R":
            base = p.links[0]
            for other in p.links[1:]:
                for d in ((1.0, 0.0), (0.0, 1.0)):
                    row = np.zeros(3 * topo.n)
                    point_row(base, 1.0, px, py, d, row)
                    point_row(other, -1.0, px, py, d, row)
                    rows.append(row)
        else:
            a, b = p.links
            ang = p.angle or 0.0
            normal = (-math.sin(ang), math.cos(ang)) if p.kind == "P" else (math.cos(ang), math.sin(ang))
            row = np.zeros(3 * topo.n)
            point_row(a, 1.0, px, py, normal, row)
            point_row(b, -1.0, px, py, normal, row)
            rows.append(row)
            if p.kind == "P":  # no relative rotation
                row = np.zeros(3 * topo.n)
                for link, sign in ((a, 1.0), (b, -1.0)):
                    if link != topo.frame:
                        row[cols[link] + 2] += sign
                rows.append(row)
    return np.array(rows) if rows else np.zeros((0, 3 * topo.n))


def _reference(topo: Topology) -> tuple[float, float, float]:
    """The Jacobian's reference point (the middle of the pairs' box) and size (its diagonal), m."""
    pts = [p.at for p in topo.pairs if p.at is not None]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    size = max(math.hypot(max(xs) - min(xs), max(ys) - min(ys)), 1e-300)
    return (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2, size


def _spin(topo: Topology, roller: str) -> np.ndarray:
    """The roller turning about its own pin, as a vector of the Jacobian's unknowns."""
    cx, cy, size = _reference(topo)
    pin = next(p for p in topo.pairs_of(roller) if p.kind == "R")
    assert pin.at is not None
    e = np.zeros(3 * topo.n)
    c = 3 * topo.links.index(roller)
    e[c:c + 3] = ((pin.at[1] - cy) / size, -(pin.at[0] - cx) / size, 1.0)  # the pin stands still
    return e


def grubler(n: int, pl: int, ph: int = 0, p_redundant: int = 0, F_local: int = 0) -> int:
    """Grübler–Kutzbach: F = 3n − (2pl + ph − p′) − F′ (n moving links, pl lower and ph higher
    pairs, p′ redundant constraints, F′ local freedoms).

    >>> grubler(3, 4), grubler(3, 3, 1, F_local=1), grubler(4, 6, p_redundant=1)
    (1, 1, 1)
    """
    return 3 * n - (2 * pl + ph - p_redundant) - F_local


def mobility(topo: Topology, with_geometry: bool) -> Mobility:
    """The count, and with ``with_geometry`` the rank of the constraint Jacobian (numpy's SVD)."""
    rollers = topo.rollers()
    f_local = len(rollers)
    count = 3 * topo.n - 2 * topo.pl - topo.ph
    rank = eq = f_actual = p_act = None
    sv: tuple[float, ...] = ()
    if with_geometry:
        J = constraint_jacobian(topo)
        eq = J.shape[0]
        s = np.linalg.svd(J, compute_uv=False) if J.size else np.zeros(0)
        sv = tuple(float(x) for x in s)
        top = float(s[0]) if s.size else 0.0
        rank = int(np.sum(s > RANK_REL * top)) if top > 0 else 0
        # a roller's spin is a local freedom only if no constraint feels it (the contact normal
        # through its pin): J times the spin about the pin is zero
        spins = sum(1 for r in rollers
                    if np.linalg.norm(J @ _spin(topo, r)) <= RANK_REL * max(top, 1e-300) * np.linalg.norm(_spin(topo, r)))
        f_actual = 3 * topo.n - rank - spins
        p_act = eq - rank
    stated = topo.redundant if topo.redundant is not None else 0  # the count knows only what is stated
    F = grubler(topo.n, topo.pl, topo.ph, stated, f_local)
    return Mobility(topo.n, topo.pl, topo.ph, f_local, stated, count, F, rank, eq, f_actual, p_act, sv, RANK_REL,
                    tuple(p.name or "+".join(p.links) for p in topo.compound), rollers)


# ---------------------------------------------------------------------------- structure


@dataclass(frozen=True)
class AssurGroup:
    """A group of links with zero mobility of its own, attached to what is known before it."""

    links: tuple[str, ...]
    grade: int  # the class: 2 for a dyad, 3, 4 …
    pairs: tuple[str, ...]  # the names of its pairs (internal and external)


@dataclass(frozen=True)
class Structure:
    """The decomposition: the frame and drivers (class I), then Assur groups in attaching order."""

    drivers: tuple[str, ...]
    groups: tuple[AssurGroup, ...]
    grade: int  # the mechanism's class (1 with no group)
    replaced: tuple[str, ...] = ()  # higher pairs replaced by a virtual link and two revolutes (高副低代)
    removed: tuple[str, ...] = ()  # rollers merged into their followers (local freedoms)
    leftover: tuple[str, ...] = ()  # links no group could take (the count and the drivers disagree)
    messages: tuple[str, ...] = field(default=())


def _lower(topo: Topology) -> tuple[Topology, tuple[str, ...], tuple[str, ...]]:
    """Rollers out (their higher pair moved onto the follower), each higher pair replaced by a
    virtual binary link with two revolutes (高副低代), so that only lower pairs remain."""
    rollers = set(topo.rollers())
    pairs = []
    for p in topo.pairs:
        links = p.links
        if p.kind == "higher":
            for r in rollers & set(links):  # the roller's follower takes its place in the contact
                pin = next(q for q in topo.pairs_of(r) if q.kind == "R")
                follower = next(x for x in pin.links if x != r)
                links = tuple(follower if x == r else x for x in links)
        elif any(x in rollers for x in links):
            continue
        pairs.append(Pair(p.kind, links, p.name, p.at, p.angle))
    out, replaced, virtual = [], [], []
    for k, p in enumerate(pairs):
        if p.kind == "higher":
            v = f"h{p.name}" if p.name else f"h{k + 1}"  # the substitute link, named after its contact
            virtual.append(v)
            replaced.append(p.name or "+".join(p.links))
            out += [Pair("R", (p.links[0], v), f"{p.name}′"), Pair("R", (v, p.links[1]), f"{p.name}″")]
        else:
            out.append(p)
    links = tuple(x for x in topo.links if x not in rollers) + tuple(virtual)
    return (Topology(topo.frame, links, tuple(out), topo.drivers), tuple(replaced), tuple(sorted(rollers)))


def _contributed(p: Pair, group: set[str], known: set[str]) -> int:
    """Pairs of a (compound) hinge that bind the group: those among group ∪ known less those
    already among the known alone."""
    inside = sum(1 for x in p.links if x in group or x in known)
    before = sum(1 for x in p.links if x in known)
    return max(0, inside - 1) - max(0, before - 1)


def _grade(links: tuple[str, ...], pairs: list[Pair]) -> int:
    """II for a dyad; else the longest closed contour of the group's internal pairs (≥ 4), or
    the most pairs on one of its links (a ternary base link: III)."""
    if len(links) == 2:
        return 2
    inner = [p for p in pairs if all(x in links for x in p.links)]
    adj: dict[str, set[str]] = {x: set() for x in links}
    for p in inner:
        for a, b in combinations(p.links, 2):
            adj[a].add(b)
            adj[b].add(a)
    longest = 0

    def walk(start: str, node: str, seen: list[str]) -> None:
        nonlocal longest
        for nxt in adj[node]:
            if nxt == start and len(seen) >= 3:
                longest = max(longest, len(seen))
            elif nxt not in seen and nxt > start:
                walk(start, nxt, seen + [nxt])

    for s in links:
        walk(s, s, [s])
    per_link = max(sum(p.count if len(p.links) == 2 else 1 for p in pairs if x in p.links) for x in links)
    return max(longest if longest >= 4 else 0, per_link, 3)


def structure(topo: Topology) -> Structure:
    """Split the mechanism into its drivers and Assur groups (smallest first, in attaching order).

    Examples
    --------
    A four-bar: frame 1, crank 2, then the dyad 3–4.

    >>> fb = Topology("1", ("2", "3", "4"), (Pair("R", ("1", "2"), "A"), Pair("R", ("2", "3"), "B"),
    ...               Pair("R", ("3", "4"), "C"), Pair("R", ("4", "1"), "D")), ("2",))
    >>> s = structure(fb)
    >>> [(g.links, g.grade) for g in s.groups], s.grade
    ([(('3', '4'), 2)], 2)
    """
    low, replaced, removed = _lower(topo)
    known = {low.frame, *low.drivers}
    rest = [x for x in low.links if x not in known]
    groups: list[AssurGroup] = []
    adjacent: dict[str, set[str]] = {x: set() for x in low.links}
    for p in low.pairs:
        for a, b in combinations([x for x in p.links if x in adjacent], 2):
            adjacent[a].add(b)
            adjacent[b].add(a)
    while rest:
        found = None
        for size in range(2, min(len(rest), MAX_GROUP) + 1, 2):
            for combo in _connected_subsets(rest, size, adjacent):
                group = set(combo)
                pairs = [p for p in low.pairs if group & set(p.links)]
                binding = sum(_contributed(p, group, known) for p in pairs)
                if 3 * size != 2 * binding:
                    continue
                # each link of the group must be held: no sub-part left free (a dyad inside is found first)
                if not _connected(group, pairs):
                    continue
                found = combo, pairs
                break
            if found:
                break
        if not found:
            break
        combo, pairs = found
        names = tuple(dict.fromkeys(p.name or "+".join(p.links) for p in pairs if
                                    _contributed(p, set(combo), known) > 0))
        groups.append(AssurGroup(tuple(combo), _grade(tuple(combo), pairs), names))
        known |= set(combo)
        rest = [x for x in rest if x not in known]
    grade = max([g.grade for g in groups], default=1)
    msgs = []
    for g in groups:
        if g.grade >= 3:
            msgs.append(f"class {_roman(g.grade)} group ({', '.join(g.links)}): the velocity and acceleration "
                        "polygons cannot be drawn dyad by dyad here — the polygon method needs a special "
                        "construction (Assur's special points, or a trial-and-error / false-position polygon)")
    if rest:
        msgs.append(f"links {', '.join(rest)} form no Assur group with drivers {', '.join(topo.drivers) or 'none'}: "
                    "the number of drivers differs from the mobility")
    return Structure(tuple(topo.drivers), tuple(groups), grade, replaced, removed, tuple(rest), tuple(msgs))


def _connected_subsets(rest: list[str], size: int, adjacent: dict[str, set[str]]) -> list[tuple[str, ...]]:
    """Every connected set of ``size`` links of ``rest``, each in ``rest``'s order, the sets in a
    fixed order (an Assur group is connected, so only these need the count)."""
    allowed = set(rest)
    order = {x: k for k, x in enumerate(rest)}
    found: set[frozenset[str]] = set()
    frontier = [frozenset([x]) for x in rest]
    for _ in range(size - 1):
        grown: set[frozenset[str]] = set()
        for sub in frontier:
            for x in sub:
                for y in adjacent[x]:
                    if y in allowed and y not in sub:
                        grown.add(sub | {y})
            if len(grown) > MAX_CANDIDATES:  # a knot of compound hinges: give up, said by the caller
                return []
        frontier = list(grown)
    found.update(frontier)
    return sorted((tuple(sorted(f, key=order.__getitem__)) for f in found),
                  key=lambda t: [order[x] for x in t])


def _connected(group: set[str], pairs: list[Pair]) -> bool:
    adj: dict[str, set[str]] = {x: set() for x in group}
    for p in pairs:
        inside = [x for x in p.links if x in group]
        for a, b in combinations(inside, 2):
            adj[a].add(b)
            adj[b].add(a)
    start = next(iter(group))
    seen, todo = {start}, [start]
    while todo:
        for nxt in adj[todo.pop()]:
            if nxt not in seen:
                seen.add(nxt)
                todo.append(nxt)
    return seen == group


def _roman(k: int) -> str:
    return {1: "I", 2: "II", 3: "III", 4: "IV", 5: "V", 6: "VI"}.get(k, str(k))


roman = _roman

__all__ = ["AssurGroup", "Mobility", "Pair", "Structure", "Topology", "constraint_jacobian", "grubler", "mobility", "roman",
           "structure", "RANK_REL"]
