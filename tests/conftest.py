"""Shared test helpers: the reference problems and running the command line in-process."""
from __future__ import annotations

import functools
import io
import json
import tomllib
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SCENES = ROOT / "figures" / "scenes"
# The textbook's reference problems, copied into the repository (a clone has nothing beside it).
REFERENCE = ROOT / "tests" / "reference" / "problems.toml"


@functools.cache
def reference_problems() -> dict[str, dict]:
    """The bank's problems by id (read once; callers must not change them)."""
    with REFERENCE.open("rb") as f:
        return {p["id"]: p for p in tomllib.load(f)["problem"]}


def reference_problem(pid: str) -> dict:
    return reference_problems()[pid]


def reference_area(area: str) -> dict[str, dict]:
    """The bank's problems of one area (``kinematics``, ``cam``, ``flywheel`` …) by id."""
    return {pid: p for pid, p in reference_problems().items() if p["area"] == area}


@pytest.fixture(scope="session")
def problems() -> dict:
    return reference_problems()


def run_cli(*argv: str) -> tuple[int, str, str]:
    """Run ``graphmech`` in-process; (exit code, stdout, stderr)."""
    from graphmech.cli import main

    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        code = main(list(argv))
    return code, out.getvalue(), err.getvalue()


def check_json(scene: Path | str, *extra: str) -> dict:
    code, out, err = run_cli("check", str(scene), "--json", *extra)
    assert code in (0, 1), err
    return json.loads(out)


def values(doc: dict) -> dict:
    return {q["name"]: q for q in doc["quantities"]}


FOURBAR_TEMPLATE = """
title = "{title}"
show = {show}
find = {find}
[units]
length = "mm"
angle = "deg"
omega = "rad/s"
{scales}
[frame]
A = [0, 0]
D = [{d}, 0]
[driver]
type = "crank"
link = "1"
pivot = "A"
tip = "B"
length = {a}
angle = {angle}
omega = {omega}
epsilon_rad_s2 = {epsilon}
[[dyad]]
type = "RRR"
joints = ["B", "C", "D"]
links = ["2", "3"]
lengths = [{b}, {c}]
branch = "left"
"""


def fourbar_scene(*, a=60, b=120, c=90, d=120, angle="165", omega=10, epsilon=0, scales="",
                  find='["v_C", "omega_2"]', show='["mechanism", "velocity", "acceleration"]',
                  title="four-bar") -> str:
    """A four-bar scene (AB crank at A, C left of B→D) as TOML text, for tests to vary."""
    return FOURBAR_TEMPLATE.format(a=a, b=b, c=c, d=d, angle=angle, omega=omega, epsilon=epsilon,
                                   scales=scales, find=find, show=show, title=title)
