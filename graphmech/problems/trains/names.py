"""The names a gear-train scene may find (docs/scene-format.md, "Gear-train scenes", Names).

``n<k>``/``n_<k>`` (r/min) and ``omega<k>``/``omega_<k>`` (rad/s) of a member or of a gear's
member, with ``[j]`` for the j-th value of a list input; ``i<a><b>`` = n_a/n_b; ``i<H><a><b>`` =
Willis' i^H_ab (H a carrier); ``_`` separates names that could run together (``i1_H2``,
``i7_14``), and a name read two ways is refused saying both; ``z<k>`` a tooth number solved from
the coaxial condition; ``dof``.
"""
from __future__ import annotations

import itertools
import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Literal

from graphmech.errors import UnknownName
from graphmech.mechanisms.gear_train import GearTrain

What = Literal["n", "omega", "i", "iH", "z", "dof"]
#: Each quantity's unit in ``check``.
UNITS: Mapping[str, str] = {"n": "r/min", "omega": "rad/s", "i": "", "iH": "", "z": "", "dof": ""}
_SPEED = re.compile(r"(omega|n)_?(.+?)(?:\[(\d+)\])?")
_RATIO = re.compile(r"i(.+?)(?:\[(\d+)\])?")


@dataclass(frozen=True)
class Name:
    """A find name read: what it is, its members or gears (a, b), the carrier, the list index."""

    text: str
    what: What
    a: str | None = None
    b: str | None = None
    carrier: str | None = None
    index: int | None = None

    @property
    def unit(self) -> str:
        return UNITS[self.what]


def _tokenisations(body: str, known: set[str]) -> list[tuple[str, ...]]:
    """Every way to read ``body`` as a run of known names (``_`` forces a break)."""
    def ways(s: str) -> list[tuple[str, ...]]:
        if not s:
            return [()]
        out = []
        for k in range(1, len(s) + 1):
            if s[:k] in known:
                out += [(s[:k], *rest) for rest in ways(s[k:])]
        return out

    parts = body.split("_")
    if any(not p for p in parts):
        return []
    return [tuple(itertools.chain(*combo)) for combo in itertools.product(*(ways(p) for p in parts))]


def parse_name(text: str, train: GearTrain, solved_z: Mapping[str, int], count: int = 1) -> Name:
    """``text`` as a :class:`Name` of this train, or refused (:class:`UnknownName`) in one line;
    ``count``: how many values a list input has (1: none)."""
    members = {m.name for m in train.members}
    known = members | {g.name for g in train.gears}
    if text == "dof":
        return Name(text, "dof")
    m = _SPEED.fullmatch(text)
    if m and m.group(2) in known:
        return Name(text, "n" if m.group(1) == "n" else "omega", m.group(2), index=_index(text, m.group(3), count))
    if text.startswith("z") and (text[1:].lstrip("_") in solved_z):
        return Name(text, "z", text[1:].lstrip("_"))
    m = _RATIO.fullmatch(text)
    if m:
        reads: list[tuple[tuple[str, ...], Name]] = []
        for toks in _tokenisations(m.group(1), known):
            if len(toks) == 2 and train.member_of(toks[0]) != train.member_of(toks[1]):
                reads.append((toks, Name(text, "i", toks[0], toks[1])))
            elif (len(toks) == 3 and toks[0] in train.carriers and toks[0] not in toks[1:]
                  and train.member_of(toks[1]) != train.member_of(toks[2])):
                reads.append((toks, Name(text, "iH", toks[1], toks[2], toks[0])))
        if len(reads) > 1:
            alts = ", ".join("|".join(t) for t, _ in reads)
            raise UnknownName(f"{text!r} is ambiguous ({alts}); write i{'_'.join(reads[0][0])}")
        if reads:
            n = reads[0][1]
            index = _index(text, m.group(2), count) if n.what == "i" else None
            return Name(text, n.what, n.a, n.b, n.carrier, index)
    raise UnknownName(f"unknown gear-train quantity {text!r}{_suggest(text, train, solved_z)}")


def _index(text: str, written: str | None, count: int) -> int | None:
    if written is None:
        return None
    j = int(written)
    if count == 1:
        raise UnknownName(f"{text!r}: no input of this scene is a list, so it takes no [{j}]")
    if j >= count:
        raise UnknownName(f"{text!r}: the list input has {count} values, [0] … [{count - 1}]")
    return j


def known_names(train: GearTrain, solved_z: Mapping[str, int]) -> list[str]:
    """Every plain name the scene can find (for 'did you mean')."""
    members = [m.name for m in train.members]
    out = ["dof"] + [f"n{k}" for k in members] + [f"omega{k}" for k in members] + [f"z{g}" for g in solved_z]
    out += [f"i{a}{b}" for a in members for b in members if a != b]
    out += [f"i{h}{a}{b}" for h in train.carriers for a in members for b in members
            if len({a, b, h}) == 3 and train.member(a).carrier is None and train.member(b).carrier is None]
    return out


def _suggest(text: str, train: GearTrain, solved_z: Mapping[str, int]) -> str:
    from graphmech.problems.reader import did_you_mean

    return did_you_mean(text, known_names(train, solved_z))


__all__ = ["UNITS", "Name", "known_names", "parse_name"]
