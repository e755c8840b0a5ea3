"""Shared test helpers: the reference problems and running the command line in-process."""
from __future__ import annotations

import io
import json
import tomllib
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared"
SCENES = ROOT / "figures" / "scenes"


@pytest.fixture(scope="session")
def problems() -> dict:
    with open(SHARED / "problems.toml", "rb") as f:
        return {p["id"]: p for p in tomllib.load(f)["problem"]}


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
