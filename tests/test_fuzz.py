"""A seeded mutation run over the reference scenes and the docs' examples, through the whole
command (tests/fuzz.py says what each run is held to). The suite's budget is short; the campaign
of ≥ 10 000 mutants is `python -m tests.fuzz --mutants 10000` (README, "Fuzzing")."""
from __future__ import annotations

import math
import random
import tomllib

import pytest

from tests import fuzz
from tests.conftest import run_cli

MUTANTS = 150  # ≈ 15 s; the same seed, the same mutants, every run


def test_the_toml_writer_round_trips_every_base_and_the_hostile_values():
    for _, doc in fuzz.bases():
        assert tomllib.loads(fuzz.dumps(doc)) == doc
    odd = {"t": fuzz.HOSTILE_TEXT, "x": {"y": [0, -0.0, 5e-324, 1e300, 10**400, math.inf, True]}}
    back = tomllib.loads(fuzz.dumps(odd))
    assert back["t"] == fuzz.HOSTILE_TEXT and back["x"]["y"][4] == 10**400 and math.isnan(
        tomllib.loads(fuzz.dumps({"n": math.nan}))["n"])


def test_every_mutation_kind_changes_the_scene():
    rng = random.Random(0)
    pool = fuzz.bases()
    kinds = set()
    for _ in range(300):
        name, base = rng.choice(pool)
        doc, kind = fuzz.mutate(base, rng)
        kinds.add(kind)
        # an extreme may hit its own value, two points may already coincide
        assert doc != base or kind in ("extreme", "coincide"), (name, kind)
    assert kinds == {"extreme", "type", "delete", "unknown", "array", "text", "coincide", "scale"}


def test_a_broken_promise_is_seen(tmp_path):
    """The runner itself: a command that prints two lines, or exits 3, is reported."""
    def two_lines(*argv, limit=60.0):
        return 2, "", "fuzz.toml: a\nfuzz.toml: b\n"

    def internal(*argv, limit=60.0):
        return 3, "", "graphmech: internal error (ZeroDivisionError)\n"

    doc = fuzz.bases()[0][1]
    assert fuzz.run_one(doc, tmp_path, two_lines)[1]
    assert fuzz.run_one(doc, tmp_path, internal)[1]
    assert not fuzz.run_one(doc, tmp_path, run_cli)[1]


def test_seeded_mutants_keep_every_promise(tmp_path):
    r = fuzz.campaign(MUTANTS, seed=20261126, folder=tmp_path, run_cli=run_cli, log=None)
    broken = [f"{name}: {b[0]}" for name, _, b in r["failures"]]
    assert not broken, "\n".join(broken)
    outcomes = {o for (_, o) in r["counts"]}
    assert outcomes == {"answered", "refused"}  # both kinds of run were exercised
