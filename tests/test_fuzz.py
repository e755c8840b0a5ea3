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


def test_a_method_refusal_that_got_past_the_reader_is_seen(tmp_path, monkeypatch):
    """A method's OutOfDomain reaches the user as one line with exit 2 — but without a key path:
    the reader let through what it should have refused, and the fuzzer says so."""
    from graphmech.errors import NoSolution, OutOfDomain
    from graphmech.problems.linkage import check as linkage_check

    doc = next(base for name, base in fuzz.bases() if name == "kin.oscillating_block")

    def refuse(*args, **kwargs):
        raise OutOfDomain("a scale must be positive and finite, not 0.0")

    monkeypatch.setattr(linkage_check, "build_polygons", refuse)
    outcome, broken, _ = fuzz.run_one(doc, tmp_path, run_cli)
    assert outcome == "refused" and broken == [
        "check: a method's OutOfDomain got past the reader (no key path): "
        "fuzz.toml: a scale must be positive and finite, not 0.0"]

    def no_answer(*args, **kwargs):  # the data's own dead end: an answer, not a gap
        raise NoSolution("no unique result")

    monkeypatch.setattr(linkage_check, "build_polygons", no_answer)
    assert fuzz.run_one(doc, tmp_path, run_cli)[:2] == ("refused", [])


def test_seeded_mutants_keep_every_promise(tmp_path):
    r = fuzz.campaign(MUTANTS, seed=20261126, folder=tmp_path, run_cli=run_cli, log=None)
    broken = [f"{name}: {b[0]}" for name, _, b in r["failures"]]
    assert not broken, "\n".join(broken)
    outcomes = {o for (_, o) in r["counts"]}
    assert outcomes == {"answered", "refused"}  # both kinds of run were exercised


# What the 10 000-mutant campaign (seed 11) found after the families were fixed: each is
# now refused in one line at its key (the edit to a reference scene, the words of the refusal).
CAMPAIGN_FINDINGS = [
    ("cam.offset_roller_translating-pos", "omega_rad_s = 1\n", "omega_rad_s = 1e300\n", "the cam construction: numbers out of"),
    ("cam.offset_roller_translating-pos", "base_radius = 30\n", "base_radius = 1e300\n", "cam.base_radius: r0 = 1e+300 mm leaves the stroke"),
    ("linkage.slider_crank_offset", "length = 300\n", "length = 1e300\n", "too large for double precision"),
    ("fly.ic_engine_flywheel", "delta = 0.01\n", "delta = 5e-324\n", "flywheel.delta: 4.94065645841e-324 is below 1e-09"),
    ("fly.ic_engine_flywheel", "cycle_deg = 180\n", "cycle_deg = 5e-324\n", "flywheel.cycle_deg: 4.94066e-324 is 0 once converted"),
    ("fly.compressor_course_project", "omega_rpm = 960\n", "omega_rpm = 1e-300\n", "the reduction to the crank: numbers out of"),
    ("fly.compressor_course_project", "pressure_MPa = [0, 0.014,", "pressure_MPa = [0, 1e300,", "pressure_MPa[1]: 1e+300 is beyond 1e+15"),
    ("force.sixbar_kinetostatic-friction", "through = [0, 300]", "through = [1e300, 300]", "frame: the mechanism lies"),
    ("structure.parallelogram_redundant", "redundant = 1\n", f"redundant = {10**60}\n", "structure.redundant: must be a whole number"),
    # the second campaign (seed 12): 3 of 10 000
    ("fly.compressor_course_project", "piston_diameter_mm = 120\n", "piston_diameter_mm = 1e300\n",
     "piston_diameter_mm: the piston's force p·A reaches beyond 1e+15 N"),
    ("fly.compressor_course_project-stiff", "angle = 0 }", "angle = -1e300 }", "guide.angle: -1e+300 is more than 1000 turns"),
    ("kin.fourbar_instant_centres", "omega = 10\n", "omega = 5e-324\n", "makes every velocity underflow double precision"),
    # the third (seed 13): 1 of 10 000
    ("fly.ic_engine_flywheel", "speed_rpm = 620\n", "speed_rpm = 5e-324\n", "flywheel.speed_rpm: 4.94066e-324 is 0 once converted"),
]


@pytest.mark.parametrize("scene_id, old, new, words", CAMPAIGN_FINDINGS, ids=[f"{c[0]}:{c[2].strip()[:20]}" for c in CAMPAIGN_FINDINGS])
def test_what_the_campaign_found_is_refused_in_one_line(tmp_path, scene_id, old, new, words):
    from tests.conftest import SCENES, assert_refused

    text = (SCENES / f"{scene_id}.toml").read_text(encoding="utf-8")
    assert old in text
    p = tmp_path / "found.toml"
    p.write_text(text.replace(old, new, 1), encoding="utf-8")
    out = tmp_path / "found.svg"
    for argv in (("check", str(p), "--json"), ("render", str(p), "-o", str(out))):
        assert_refused(run_cli(*argv), "found.toml", words)
    assert not out.exists()
