"""Mutation fuzzing of whole commands: the reference scenes and the docs' examples, mutated, run
through ``graphmech check`` and ``render`` in-process, and every run held to the command's promises.

Used by tests/test_fuzz.py (a short seeded budget in the suite) and as a campaign::

    python -m tests.fuzz --mutants 10000 --seed 1 [--limit 60] [--out DIR]

which prints the counts by outcome and by mutation, the slowest mutants and every broken promise
(with the mutant's TOML written to ``fuzz-failures/`` for a regression test).
"""
from __future__ import annotations

import argparse
import copy
import json
import math
import random
import re
import sys
import time
import tomllib
import xml.etree.ElementTree as ET
from collections import Counter
from pathlib import Path

from tests.mutation import paths as key_paths

ROOT = Path(__file__).resolve().parents[1]
SCENES = ROOT / "figures" / "scenes"
DOCS = ROOT / "docs" / "scene-format.md"

SENTINEL = "an existing output, which a refusal must leave as it is\n"
EXTREMES = [0, -0.0, 5e-324, -5e-324, 1e-300, 1e300, -1e300, math.nan, math.inf, -math.inf, 10**400, -1,
            2**64, 1e-9, 0.5]
HOSTILE_TEXT = ['<svg onload="alert(1)">&amp;</svg>', "A\nB", "\x1b[31mred", "C\u202eD", "", " ", "P",
                "N2", "K", "E&<>'\"", "x" * 300]
OTHER_TYPES = ["A", True, [], {}, [1, 2], {"x": 1}, [[0, 0]], "nan"]


# ------------------------------------------------------------------------------------------ TOML

def _key(k: str) -> str:
    return json.dumps(k, ensure_ascii=False)  # a TOML basic string is JSON's, but for \u escapes


def _string(s: str) -> str:
    out = []
    for c in s:
        if c == '"':
            out.append('\\"')
        elif c == "\\":
            out.append("\\\\")
        elif not c.isprintable() or c in "\u2028\u2029":
            out.append(f"\\u{ord(c):04x}" if ord(c) <= 0xFFFF else f"\\U{ord(c):08x}")
        else:
            out.append(c)
    return '"' + "".join(out) + '"'


def _value(v: object) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        r = repr(v)
        return r if any(c in r for c in ".en") else r + ".0"
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_key(k)} = {_value(x)}" for k, x in v.items()) + "}"
    raise TypeError(type(v))


def dumps(doc: dict) -> str:
    """A TOML text for ``doc`` (every table inline: the readers see only the data)."""
    return "".join(f"{_key(k)} = {_value(v)}\n" for k, v in doc.items())


# ------------------------------------------------------------------------------------------ bases

def bases() -> list[tuple[str, dict]]:
    """(name, scene) for every reference scene and every complete example in the docs."""
    out = [(p.stem, tomllib.loads(p.read_text(encoding="utf-8"))) for p in sorted(SCENES.glob("*.toml"))]
    blocks = re.findall(r"^```toml\n(.*?)^```", DOCS.read_text(encoding="utf-8"), re.DOTALL | re.MULTILINE)
    for i, b in enumerate(blocks):
        try:
            doc = tomllib.loads(b)
        except tomllib.TOMLDecodeError:
            continue
        if "title" in doc or "show" in doc or "find" in doc:
            out.append((f"docs-{i}", doc))
    return out


def _points(data: object, path: tuple = ()) -> list[tuple]:
    """Paths of [x, y] coordinate pairs (to make two of them coincide)."""
    if isinstance(data, dict):
        return [q for k, v in data.items() for q in _points(v, path + (k,))]
    if isinstance(data, list):
        if len(data) == 2 and all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in data):
            return [path]
        return [q for i, v in enumerate(data) for q in _points(v, path + (i,))]
    return []


def _get(doc: object, path: tuple) -> object:
    for step in path:
        doc = doc[step]  # type: ignore[index]
    return doc


def mutate(doc: dict, rng: random.Random) -> tuple[dict, str]:
    """One mutation of ``doc``: (the mutant, the kind of mutation)."""
    m = copy.deepcopy(doc)
    paths = key_paths(m)[1:]
    leaves = [p for p in paths if not isinstance(_get(m, p), (dict, list))]
    kind = rng.choice(["extreme", "extreme", "extreme", "type", "delete", "unknown", "array", "text",
                       "coincide", "scale"])
    if kind == "coincide":
        pts = _points(m)
        if len(pts) >= 2:
            a, b = rng.sample(pts, 2)
            _set(m, b, list(_get(m, a)))  # type: ignore[arg-type]
            return m, kind
        kind = "extreme"
    if kind == "scale":
        scales = [p for p in leaves if isinstance(p[-1], str) and ("per_mm" in p[-1] or p[-1].startswith("mu"))]
        if scales:
            _set(m, rng.choice(scales), rng.choice([5e-324, 1e-300, 1e300, 2.5e-6, 0, -1, math.inf]))
            return m, kind
        kind = "extreme"
    if kind == "extreme":
        numbers = [p for p in leaves if isinstance(_get(m, p), (int, float)) and not isinstance(_get(m, p), bool)]
        _set(m, rng.choice(numbers or leaves), rng.choice(EXTREMES))
    elif kind == "type":
        _set(m, rng.choice(paths), copy.deepcopy(rng.choice(OTHER_TYPES)))
    elif kind == "delete":
        p = rng.choice(paths)
        parent = _get(m, p[:-1])
        del parent[p[-1]]  # type: ignore[index, union-attr]
    elif kind == "unknown":
        tables = [p for p in [(), *paths] if isinstance(_get(m, p), dict)]
        _get(m, rng.choice(tables))["unexpected_key"] = 1  # type: ignore[index]
    elif kind == "array":
        arrays = [p for p in paths if isinstance(_get(m, p), list)]
        if arrays:
            p = rng.choice(arrays)
            old = _get(m, p)
            if not old:  # an empty list emptied again is no mutant: fill it with a stray value
                _set(m, p, [copy.deepcopy(rng.choice(OTHER_TYPES))])
            else:
                _set(m, p, [] if rng.random() < 0.5 else (old * (3601 // len(old) + 1))[:3601])
        else:
            _set(m, rng.choice(paths), [])
    elif kind == "text":
        strings = [p for p in leaves if isinstance(_get(m, p), str)]
        where = rng.choice(strings or paths)
        # never the text already there ("K" over find's "K" would change nothing)
        _set(m, where, rng.choice([t for t in HOSTILE_TEXT if t != _get(m, where)]))
    return m, kind


def _set(doc: dict, path: tuple, value: object) -> None:
    _get(doc, path[:-1])[path[-1]] = value  # type: ignore[index]


# ------------------------------------------------------------------------------------------ running

def _no_nonfinite(text: str) -> bool:
    try:
        json.loads(text, parse_constant=lambda c: (_ for _ in ()).throw(ValueError(c)))
    except ValueError:
        return False
    return True


#: Refusals a *method* makes of its arguments (graphmech.errors): a scene that reaches one got past
#: its reader, which should have refused it with the key path. The data's own dead ends
#: (DegenerateConstruction, NoSolution, TrueMotionError) are answers, not gaps.
READER_GAPS = ("OutOfDomain", "NotApplicable", "UnknownName", "WrongKind")


def refusal_class(scene: Path) -> str:
    """The class of the error that checking ``scene`` in-process ends with ("" if none): the
    command prints only its message, and a reader's refusal and a method's read alike there."""
    import warnings

    import numpy as np

    from graphmech.problems import check
    from graphmech.scene import load_scene

    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        try:
            check(load_scene(scene))
        except Exception as e:  # noqa: BLE001 — the class is the answer
            return type(e).__name__
    return ""


def run_one(doc: dict, folder: Path, run_cli, limit: float = 60.0) -> tuple[str, list[str], float]:
    """Run check --json and render on one mutant: (outcome, broken promises, seconds)."""
    scene = folder / "fuzz.toml"
    scene.write_text(dumps(doc), encoding="utf-8")
    out_svg = folder / "out.svg"
    out_svg.write_text(SENTINEL, encoding="utf-8")
    broken: list[str] = []
    t0 = time.perf_counter()
    codes = []
    from tests.conftest import Hang

    for argv in (("check", str(scene), "--json"), ("render", str(scene), "-o", str(out_svg))):
        try:
            code, out, err = run_cli(*argv, limit=limit)
        except Hang as e:
            broken.append(f"{argv[0]}: {e}")
            codes.append(None)
            continue
        codes.append(code)
        lines = err.splitlines()
        if code not in (0, 1, 2):
            broken.append(f"{argv[0]}: exit {code}: {err.strip()[:300]}")
            continue
        if code == 2:
            if len(lines) != 1 or not err.endswith("\n") or not lines[0].startswith("fuzz.toml: "):
                broken.append(f"{argv[0]}: refusal is not one line naming the file: {err[:300]!r}")
            if argv[0] == "check" and (cls := refusal_class(scene)) in READER_GAPS:
                broken.append(f"check: a method's {cls} got past the reader (no key path): {err.strip()[:300]}")
            if argv[0] == "render" and out_svg.read_text(encoding="utf-8") != SENTINEL:
                broken.append("render: a refusal changed the existing output")
            continue
        if any(not ln.startswith("fuzz.toml: warning: ") for ln in lines):
            broken.append(f"{argv[0]}: stderr has more than warnings: {err[:300]!r}")
        if argv[0] == "check" and not _no_nonfinite(out):
            broken.append("check: NaN or inf in the JSON")
        if argv[0] == "render":
            svg = out_svg.read_text(encoding="utf-8")
            try:
                ET.fromstring(svg)
            except ET.ParseError as e:
                broken.append(f"render: not well-formed SVG ({e})")
            # numbers live in attributes (a title may say "nan": that is the user's text)
            if re.search(r'="[^"]*\b(nan|inf)\b|=\s*[−-]?(nan|inf)\b', svg, re.IGNORECASE):
                broken.append("render: NaN or inf in the SVG's numbers")
            if "<svg onload" in svg[100:]:
                broken.append("render: unescaped markup in the SVG")
    outcome = "refused" if 2 in codes else "answered"
    return outcome, broken, time.perf_counter() - t0


def campaign(n: int, seed: int, folder: Path, run_cli, log=print, limit: float = 60.0) -> dict:
    rng = random.Random(seed)
    pool = bases()
    counts: Counter = Counter()
    failures: list[tuple[str, str, list[str]]] = []
    slow: list[tuple[float, str]] = []
    t0 = time.perf_counter()
    for i in range(n):
        name, base = rng.choice(pool)
        doc, kind = mutate(base, rng)
        outcome, broken, secs = run_one(doc, folder, run_cli, limit)
        counts[(kind, outcome if not broken else "BROKEN")] += 1
        slow.append((secs, f"{name}/{kind}#{i}"))
        if broken:
            failures.append((f"{name}/{kind}#{i}", dumps(doc), broken))
        if log and (i + 1) % 500 == 0:
            log(f"{i + 1} mutants, {len(failures)} broken, {time.perf_counter() - t0:.0f} s")
    slow.sort(reverse=True)
    return {"mutants": n, "seconds": time.perf_counter() - t0, "counts": counts, "failures": failures,
            "slowest": slow[:5]}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m tests.fuzz")
    ap.add_argument("--mutants", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", default="fuzz-failures")
    ap.add_argument("--limit", type=float, default=60.0, help="seconds a command may run (the hang guard)")
    args = ap.parse_args(argv)
    import tempfile

    from tests.conftest import run_cli

    with tempfile.TemporaryDirectory() as tmp:
        r = campaign(args.mutants, args.seed, Path(tmp), run_cli, log=lambda s: print(s, file=sys.stderr),
                     limit=args.limit)
    by_kind: dict[str, Counter] = {}
    for (kind, outcome), c in r["counts"].items():
        by_kind.setdefault(kind, Counter())[outcome] += c
    print(f"{r['mutants']} mutants in {r['seconds']:.0f} s (seed {args.seed})")
    for kind, c in sorted(by_kind.items()):
        print(f"  {kind:<9} " + ", ".join(f"{o} {k}" for o, k in sorted(c.items())))
    print("slowest: " + ", ".join(f"{name} {s:.2f} s" for s, name in r["slowest"]))
    if r["failures"]:
        out = Path(args.out)
        out.mkdir(exist_ok=True)
        for name, text, broken in r["failures"]:
            (out / (re.sub(r"[^\w.-]", "_", name) + ".toml")).write_text(
                "".join(f"# {b}\n" for b in broken) + text, encoding="utf-8")
            print(f"BROKEN {name}: {broken[0]}")
    return 1 if r["failures"] else 0


if __name__ == "__main__":
    sys.exit(main())
