"""Read a mobility and structure scene: the ``[structure]`` table (links and pairs), or a
book's printed counts (``[[structure.case]]``).

A structure scene describes a mechanism by its topology — which links, which pairs join which
links — with, optionally, where each pair is (for the rank of the constraint Jacobian at that
geometry). It is analysed by :mod:`graphmech.problems.structure.check`; the format is in
``docs/scene-format.md`` ("Instant centres and structure").
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Mapping

from graphmech.mechanisms.topology import Pair, PairKind, Topology
from graphmech.problems.reader import (
    LINKAGE_KEYS,
    MISSING,
    Reader,
    Scene,
    raise_sorted,
    read_header,
    read_measured,
    read_scales,
    read_tail,
    say,
)

#: What a structure scene may show.
STRUCTURE_SHOW_CHOICES = ("structure",)
#: What a structure scene can find (``graphmech.problems.structure.check`` computes each).
STRUCTURE_QUANTITIES = ("n", "pl", "ph", "p_redundant", "F_local", "F_count", "F", "F_actual", "rank",
                        "p_redundant_actual", "class")
_PAIR_KINDS: tuple[PairKind, ...] = ("R", "P", "higher")
#: The most pairs (and printed cases) one structure scene may list.
MAX_PAIRS = 200
#: The most links one compound hinge may join.
MAX_HINGE = 12


@dataclass(frozen=True)
class Case:
    """A book's printed counts for one mechanism (no topology): F = 3n − (2pl + ph − p′) − F′."""

    label: str
    n: int
    pl: int
    ph: int = 0
    p_redundant: int = 0
    F_local: int = 0


@dataclass(frozen=True)
class StructureScene:
    """A topology (with or without joint coordinates) or a list of printed counts."""

    topology: Topology | None
    geometry: bool  # every pair has coordinates: the Jacobian's rank can be taken
    cases: tuple[Case, ...] = ()


#: The largest count a structure scene takes (links, pairs): a mechanism of the book has a dozen.
MAX_COUNT = 10_000


def _count(r: Reader, key: str, *, required: bool = True, default: int = 0) -> int | None:
    value = r.raw(key, required=required, hint="a whole number ≥ 0")
    if value is MISSING:
        return default
    if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value <= MAX_COUNT:
        r.problem(r.at(key), f"must be a whole number from 0 to {MAX_COUNT}, not {say(value)}")
        return None
    return value


def _links(r: Reader, key: str, *, required: bool = False) -> list[str] | None:
    value = r.raw(key, required=required, hint='a list of link numbers such as ["2", "3"]')
    if value is MISSING:
        return None
    if not isinstance(value, list):
        r.problem(r.at(key), 'must be a list of link numbers such as ["2", "3"]')
        return None
    out = [r.link_id(v, f"{r.at(key)}[{i}]") for i, v in enumerate(value)]
    for i, x in enumerate(out):
        if x is not None and x in out[:i]:
            r.problem(f"{r.at(key)}[{i}]", f"link {x!r} is listed twice")
            return None
    valid = [x for x in out if x is not None]
    return valid if len(valid) == len(out) else None


def _read_structure(st: Reader) -> StructureScene | None:
    cases = []
    case_tables = st.tables_at("case")
    if len(case_tables) > MAX_PAIRS:
        st.problem(st.at("case"), f"{len(case_tables)} cases: at most {MAX_PAIRS} in one scene")
        case_tables = []
    for c in case_tables:
        label = c.string("label", required=True)
        n, pl = _count(c, "n"), _count(c, "pl")
        ph, pr, fl = _count(c, "ph", required=False), _count(c, "p_redundant", required=False), \
            _count(c, "F_local", required=False)
        c.finish()
        if label is not None and n is not None and pl is not None and ph is not None and pr is not None \
                and fl is not None:
            cases.append(Case(label, n, pl, ph, pr, fl))
    pair_tables = st.tables_at("pair")
    if len(pair_tables) > MAX_PAIRS:
        st.problem(st.at("pair"), f"{len(pair_tables)} pairs: at most {MAX_PAIRS} in one scene")
        pair_tables = []
    if cases and pair_tables:
        st.problem(st.at("case"), "a scene gives either printed counts ([[structure.case]]) or a topology "
                                  "([[structure.pair]]), not both")
    frame = st.raw("frame", required=not cases, hint='the fixed link\'s number, e.g. frame = "1"')
    frame_id = None if frame is MISSING else st.link_id(frame, st.at("frame"))
    drivers = _links(st, "drivers") or []
    moving = _links(st, "links")
    redundant = _count(st, "redundant", required=False, default=-1)
    pairs: list[Pair] = []
    with_at = 0
    for k, p in enumerate(pair_tables):
        kind = p.string("kind", choices=_PAIR_KINDS, required=True)
        links = _links(p, "links", required=True)
        name = p.raw("name")
        if name is not MISSING and not isinstance(name, str):
            p.problem(p.at("name"), "must be a string such as \"A\"")
            name = MISSING
        at = p.pair("at", required=False)
        angle = p.scalar("angle", "angle", required=False)
        if angle is not None and not abs(angle) <= 1e6:  # a direction: keep its sine meaningful
            p.problem(p.at(p.present("angle") or "angle"), "must be an angle within ±1e6 rad")
            angle = None
        if links is not None:
            if len(set(links)) != len(links):
                p.problem(p.at("links"), "a link is listed twice")
                links = None
            elif kind in ("P", "higher") and len(links) != 2:
                p.problem(p.at("links"), f"a {kind} pair joins exactly two links, not {len(links)}")
                links = None
            elif len(links) < 2:
                p.problem(p.at("links"), "a pair joins at least two links")
                links = None
            elif len(links) > MAX_HINGE:
                p.problem(p.at("links"), f"{len(links)} links in one hinge: at most {MAX_HINGE}")
                links = None
        if kind == "R" and angle is not None:  # a revolute has no direction: the angle would be ignored
            p.problem(p.at(p.present("angle") or "angle"), "a revolute (R) has no direction: drop angle "
                                                             "(it is a P pair's guide or a higher pair's normal)")
        if kind in ("P", "higher") and at is not None and angle is None:
            what = "the guide's direction" if kind == "P" else "the common normal's direction"
            p.problem(p.at("angle"), f"missing: {what} (with at, for the Jacobian)")
        p.finish()
        if kind is not None and links is not None:
            with_at += at is not None
            pairs.append(Pair(kind, tuple(links), name if isinstance(name, str) else "", at, angle))
    st.finish()
    if cases:
        return StructureScene(None, False, tuple(cases))
    if not pair_tables:
        st.problem(st.at("pair"), "no [[structure.pair]]: describe the pairs (or give [[structure.case]] counts)")
        return None
    if frame_id is None or len(pairs) < len(pair_tables):  # a broken pair: the rest would only echo it
        return None
    if 0 < with_at < len(pairs):
        missing = next(k for k, p in enumerate(pairs) if p.at is None)
        st.problem(f"{st.at('pair')}[{missing}].at", "give every pair's coordinates or none (the Jacobian needs all)")
    seen = list(dict.fromkeys(x for p in pairs for x in p.links if x != frame_id))
    if moving is None:
        moving = seen
    else:
        for x in seen:
            if x not in moving:
                st.problem(st.at("links"), f"link {x!r} has pairs but is not listed")
        for x in moving:
            if x not in seen:
                st.problem(st.at("links"), f"link {x!r} has no pair: it would be a free body")
    if frame_id not in {x for p in pairs for x in p.links}:
        st.problem(st.at("frame"), f"no pair joins the frame {frame_id!r}")
    for i, d in enumerate(drivers):
        if d not in moving:
            st.problem(f"{st.at('drivers')}[{i}]", f"{d!r} is not a moving link")
        elif not any(frame_id in p.links and d in p.links for p in pairs):
            st.problem(f"{st.at('drivers')}[{i}]", f"driver {d!r} must be joined to the frame")
    topo = Topology(frame_id, tuple(moving), tuple(pairs), tuple(drivers),
                    None if redundant in (-1, None) else redundant)
    return StructureScene(topo, with_at == len(pairs) and len(pairs) > 0)


def parse_structure_scene(data: Mapping[str, Any], source: str, top: Reader, order: Mapping[str, int]
                          ) -> Scene[StructureScene]:
    """The rest of :func:`graphmech.scene.parse_scene` for a scene with a [structure] table.

    Examples
    --------
    >>> from graphmech.scene import parse_scene
    >>> s = parse_scene({"structure": {"frame": "1", "drivers": ["2"], "pair": [
    ...     {"kind": "R", "links": ["1", "2"]}, {"kind": "R", "links": ["2", "3"]},
    ...     {"kind": "R", "links": ["3", "4"]}, {"kind": "R", "links": ["4", "1"]}]}}, "fourbar.toml")
    >>> t = s.problem.topology
    >>> t.links, t.n, t.pl, s.problem.geometry
    (('2', '3', '4'), 3, 4, False)
    """
    problems = top.problems
    title, show, find = read_header(top, STRUCTURE_SHOW_CHOICES, ("structure",))
    scales = read_scales(top, entries=(("l", "length"),))
    for key in (*LINKAGE_KEYS, "cam", "flywheel"):
        if key in data:
            top.used.add(key)
            what = {"cam": "a cam scene", "flywheel": "a flywheel scene"}.get(key, "a linkage scene")
            top.problem(key, f"belongs to {what}; this is a structure scene ([structure]): put each in a "
                             "scene of its own")
    st = top.table_at("structure")
    structure = None if st is None else _read_structure(st)
    for i, name in enumerate(find):
        base = name.partition("@")[0]
        if base not in STRUCTURE_QUANTITIES:
            top.problem(f"find[{i}]", f"unknown quantity {base!r}: a structure scene finds "
                                      f"{', '.join(STRUCTURE_QUANTITIES)}")
    measured = read_measured(top, None, cam=True)  # whole numbers, no positions (judged exactly)
    for name, _ in measured:
        if name not in STRUCTURE_QUANTITIES:
            top.problem(f"measured.{name}", f"unknown quantity {name!r}: a structure scene judges "
                                            f"{', '.join(STRUCTURE_QUANTITIES)}")
    precision, page = read_tail(top)
    if problems or structure is None:
        raise_sorted(problems, data, order, "structure", source)
    return Scene(source=source, title=title, show=show, find=find, scales=scales, measured=measured,
                 precision_mm=precision, page=page, kind="structure", problem=structure)


__all__ = ["Case", "STRUCTURE_QUANTITIES", "STRUCTURE_SHOW_CHOICES", "StructureScene", "parse_structure_scene"]
