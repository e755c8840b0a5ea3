"""Variants of a scene: the same problem with some of its numbers changed, without editing TOML.

A teacher's twenty versions of one exercise are one scene and a few assignments
``driver.angle=30,45,60``: :func:`parse_assignment` reads one ``--set KEY=V1,V2,…``,
:func:`combinations` makes every combination of several, :func:`replace` writes one into the
scene's TOML data, and :func:`variant_name` names its files (``scene-driver.angle=30``).

A KEY is a key path as graphmech's messages print it: tables joined by ``.``, an array's element
by ``[i]`` (``driver.angle``, ``dyad[0].lengths[1]``, ``cam.segment[2].angle``). A quantity's
unit may be left off where the file writes it in its key (``driver.angle`` finds
``driver.angle_deg``); the value is then in the unit the scene states, as the file's own is.
A value is a TOML value (``30``, ``1.5e-3``, ``[0, 90]``, ``"zh"``); a bare word is a string.

>>> data = {"driver": {"angle_deg": 30, "omega_rad_s": 10}, "dyad": [{"lengths_mm": [40, 50]}]}
>>> replace(data, {"driver.angle": 60, "dyad[0].lengths[1]": 55.0}, "s.toml")
{'driver': {'angle_deg': 60, 'omega_rad_s': 10}, 'dyad': [{'lengths_mm': [40, 55.0]}]}
>>> data["driver"]["angle_deg"]  # the original is left as it was
30
>>> parse_assignment("driver.angle=30,45,60")
('driver.angle', [30, 45, 60])
>>> [variant_name("crank", c) for c in combinations([("driver.angle", [30, 45]), ("driver.omega", [10])])]
['crank-driver.angle=30-driver.omega=10', 'crank-driver.angle=45-driver.omega=10']
"""
from __future__ import annotations

import copy
import hashlib
import itertools
import math
import re
import tomllib
from collections.abc import Mapping, Sequence
from typing import Any

from graphmech.errors import COMMAND_LINE, SceneError
from graphmech.problems.reader import did_you_mean, say

#: One step of a key path: a key, then any number of ``[i]``.
_STEP = re.compile(r"([^.\[\]]+)((?:\[\d+\])*)")
#: At most this many variants from one command (a product of --set lists grows fast).
MAX_VARIANTS = 10_000
#: bytes: the longest name :func:`variant_name` gives. A file system holds 255 bytes a name, and
#: the name gets an extension (``.json``) and, while it is written, a temporary file's affixes.
MAX_NAME_BYTES = 200

Assignment = dict[str, Any]


def _steps(path: str, source: str) -> list[str | int]:
    """``dyad[0].lengths[1]`` → ``["dyad", 0, "lengths", 1]``."""
    steps: list[str | int] = []
    for part in path.split("."):
        m = _STEP.fullmatch(part.strip())
        if m is None:
            raise SceneError([(path, "not a key path: write keys joined by '.', an element as [i] "
                                     "(driver.angle, dyad[0].lengths[1])")], source)
        steps.append(m.group(1))
        steps += [int(i) for i in re.findall(r"\[(\d+)\]", m.group(2))]
    return steps


def _key_in(table: Mapping[str, Any], key: str, path: str, source: str) -> str:
    """The key of ``table`` that ``key`` names: itself, or the one ``key_<unit>``."""
    if key in table:
        return key
    with_unit = [k for k in table if isinstance(k, str) and k.startswith(key + "_")]
    if len(with_unit) == 1:
        return with_unit[0]
    if len(with_unit) > 1:
        raise SceneError([(path, f"ambiguous: the table has {', '.join(with_unit)}; name one")], source)
    # a key's base without its unit is a candidate too: "angel" is nearest "angle" (of angle_deg)
    keys = [str(k) for k in table]
    bases = {k[:i] for k in keys for i, c in enumerate(k) if c == "_" and i}
    raise SceneError([(path, "not in the scene" + did_you_mean(key, [*keys, *bases]) +
                       " (--set changes a value the scene has; add a new key in the file)")], source)


def replace(data: Mapping[str, Any], changes: Mapping[str, Any], source: str = "scene") -> dict[str, Any]:
    """A deep copy of the TOML ``data`` with each key path of ``changes`` set to its value.

    Raises :class:`SceneError` naming the key path when it is not in the scene (with the nearest
    key), runs through something that is no table or array, or indexes past an array's end.
    The new value is judged by the scene reader as the file's own would be.
    """
    out = copy.deepcopy(dict(data))
    for path, value in changes.items():
        node: Any = out
        steps = _steps(path, source)
        for n, step in enumerate(steps):
            last = n == len(steps) - 1
            where = _path_text(steps[: n + 1])
            if isinstance(step, int):
                if not isinstance(node, list):
                    raise SceneError([(where, "not an array: no element [i] to change")], source)
                if step >= len(node):
                    raise SceneError([(where, f"the array has {len(node)} element{'s' * (len(node) != 1)}")],
                                     source)
                key: str | int = step
            else:
                if not isinstance(node, dict):
                    raise SceneError([(where, "not a table: no key to change in it")], source)
                key = _key_in(node, step, where, source)
            if last:
                _same_sort(node[key], value, path, source)
                node[key] = value
            else:
                node = node[key]
    return out


def _same_sort(old: Any, new: Any, path: str, source: str) -> None:
    """A table stays a table: a value in a table's place (or a table in a value's) is surely a
    wrong key path. Numbers, arrays and strings the scene reader judges, as it does the file's."""
    if isinstance(old, dict) != isinstance(new, dict):
        what = "a table" if isinstance(old, dict) else "a value"
        raise SceneError([(path, f"the scene has {what} here; --set changes values, not tables")], source)


def _path_text(steps: Sequence[str | int]) -> str:
    text = ""
    for s in steps:
        text += f"[{s}]" if isinstance(s, int) else (f".{s}" if text else s)
    return text


def _split_top(text: str) -> list[str]:
    """Split at commas outside brackets and quotes: ``30,[0,90],"a,b"`` → three values."""
    parts, depth, quote, start = [], 0, "", 0
    for i, ch in enumerate(text):
        if quote:
            quote = "" if ch == quote else quote
        elif ch in "\"'":
            quote = ch
        elif ch in "[{":
            depth += 1
        elif ch in "]}":
            depth -= 1
        elif ch == "," and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    parts.append(text[start:])
    return [p.strip() for p in parts]


def parse_value(text: str, path: str) -> Any:
    """One value as TOML reads it; a bare word (``zh``, ``ccw``) is a string."""
    try:
        return tomllib.loads(f"v = {text}")["v"]
    except tomllib.TOMLDecodeError:
        if re.fullmatch(r"[\w\-+.]+", text) and not re.fullmatch(r"[\d\-+.eE]+", text):
            return text
        raise SceneError([(f"--set {path}", f"{say(text)} is not a value: write a number, "
                                            "[a, b], a word or \"quoted text\"")], COMMAND_LINE) from None


def parse_assignment(text: str) -> tuple[str, list[Any]]:
    """``KEY=V1,V2,…`` (one ``--set``) → (KEY, [values])."""
    path, sep, values = text.partition("=")
    path = path.strip()
    if not sep or not path or not values.strip():
        raise SceneError([(f"--set {text}", "expected KEY=VALUE[,VALUE…] (driver.angle=30,45,60)")], COMMAND_LINE)
    return path, [parse_value(v, path) for v in _split_top(values)]


def combinations(assignments: Sequence[tuple[str, Sequence[Any]]]) -> list[Assignment]:
    """Every combination of the assigned values, the first key varying slowest; one empty
    assignment when there is none (the scene as it is). A key given twice: the last wins."""
    merged: dict[str, Sequence[Any]] = {}
    for path, values in assignments:
        merged.pop(path, None)
        merged[path] = values
    count = math.prod(len(v) for v in merged.values())
    if count > MAX_VARIANTS:
        raise SceneError([("--set", f"{count} combinations: at most {MAX_VARIANTS} in one run")], COMMAND_LINE)
    return [dict(zip(merged, combo)) for combo in itertools.product(*merged.values())]


def value_text(value: Any) -> str:
    """A value as a file name and a table show it: ``30``, ``0.5``, ``zh``, ``[0,90]``."""
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, float) and value.is_integer() and abs(value) < 1e15:
        return str(int(value))
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, list):
        return "[" + ",".join(value_text(v) for v in value) + "]"
    if isinstance(value, dict):  # an inline table, as TOML writes it
        return "{" + ",".join(f"{k}={value_text(v)}" for k, v in value.items()) + "}"
    return str(value)


def variant_name(stem: str, assignment: Assignment) -> str:
    """``<stem>-<key>=<value>[-…]``; characters a file name cannot hold become ``_``. A name longer
    than :data:`MAX_NAME_BYTES` is cut there and ends with a hash of the whole, so it can still
    be written and two long names stay two."""
    name = stem + "".join(f"-{k}={value_text(v)}" for k, v in assignment.items())
    name = re.sub(r'[\\/:*?"<>|\x00-\x1f\s]', "_", name)
    raw = name.encode("utf-8", "surrogatepass")  # a lone surrogate (a file name's undecodable byte) counts 3
    if len(raw) <= MAX_NAME_BYTES:
        return name
    digest = "~" + hashlib.sha256(raw).hexdigest()[:10]
    head, size = "", len(digest)
    for ch in name:  # whole characters only: a name cut inside one would not be UTF-8
        size += len(ch.encode("utf-8", "surrogatepass"))
        if size > MAX_NAME_BYTES:
            break
        head += ch
    return head + digest


__all__ = ["MAX_NAME_BYTES", "MAX_VARIANTS", "combinations", "parse_assignment", "parse_value", "replace", "value_text",
           "variant_name"]
