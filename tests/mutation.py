"""Mutating scenes: what the robustness tests (Hypothesis) and the seeded fuzzer (tests/fuzz.py) share.

A mutation replaces or deletes the value at one key path of a parsed scene; whatever comes of it,
the reader must answer with a scene or a one-line refusal.
"""
from __future__ import annotations

import copy
from collections.abc import Iterable
from typing import Any

from hypothesis import strategies as st

from graphmech.errors import SceneError
from graphmech.problems.reader import Scene
from graphmech.scene import parse_scene


def paths(data: object, path: tuple = ()) -> list[tuple]:
    """Every key path in ``data`` (dicts and lists), the root ``()`` first."""
    if isinstance(data, dict):
        return [path] + [q for k, v in data.items() for q in paths(v, path + (k,))]
    if isinstance(data, list):
        return [path] + [q for i, v in enumerate(data) for q in paths(v, path + (i,))]
    return [path]


def toml_values(words: Iterable[Any], *, max_leaves: int = 12,
                extra: st.SearchStrategy | None = None) -> st.SearchStrategy:
    """Any TOML value — booleans, 64-bit integers, floats with NaN and ±inf, short text, a kind's own
    ``words`` (names, units, keywords, telling numbers) — nested in lists and tables."""
    leaf = (st.booleans() | st.integers(-(2**63), 2**63 - 1) | st.floats(allow_nan=True, allow_infinity=True)
            | st.text(max_size=8) | st.sampled_from(list(words)))
    if extra is not None:
        leaf = leaf | extra
    return st.recursive(
        leaf, lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=6), inner, max_size=4),
        max_leaves=max_leaves)


def mutate(data: st.DataObject, base: dict, values: st.SearchStrategy, *, most: int = 1) -> dict:
    """A copy of ``base`` with one to ``most`` values replaced by one of ``values`` or deleted."""
    mutated = copy.deepcopy(base)
    for _ in range(data.draw(st.integers(1, most)) if most > 1 else 1):
        inner = paths(mutated)[1:]
        if not inner:
            break
        path = data.draw(st.sampled_from(inner))
        parent = mutated
        for step in path[:-1]:
            parent = parent[step]
        if data.draw(st.booleans()) and isinstance(parent, dict):
            del parent[path[-1]]
        else:
            parent[path[-1]] = data.draw(values)
    return mutated


def scene_or_refusal(mutated: dict) -> Scene | None:
    """The scene a mutated table reads as, or None when the reader refused it — in one line, with
    at least one problem named (the promise every mutation is held to)."""
    try:
        return parse_scene(mutated, "fuzz.toml")
    except SceneError as err:
        assert err.problems
        assert "\n" not in str(err)
        return None
