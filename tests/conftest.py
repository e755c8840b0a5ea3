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
