"""Shared test helpers: the reference problems and running the command line in-process."""
from __future__ import annotations

import functools
import io
import json
import signal
import tomllib
from contextlib import contextmanager, redirect_stderr, redirect_stdout
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


# A command still running after this many seconds fails its test: the hang guard. Bounded time
# is shown this way, never by a speed assertion.
HANG_GUARD_S = 60.0
# The whole quick bench (every kind's sweeps and plots) is work, not a hang: it takes ≈ 25 s alone
# and twice that on a shared machine, so it gets a guard of its own.
BENCH_GUARD_S = 300.0


class Hang(BaseException):  # not an Exception: the command's own "except Exception" must not swallow it
    pass


@contextmanager
def hang_guard(seconds: float = HANG_GUARD_S):
    """Fail (raise Hang) if the block is still running after ``seconds`` (SIGALRM, main thread)."""
    def stop(signum, frame):
        raise Hang(f"still running after {seconds:g} s")

    previous = signal.signal(signal.SIGALRM, stop)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        signal.signal(signal.SIGALRM, previous)


@pytest.fixture(scope="session")
def quick_bench(tmp_path_factory) -> tuple[int, str, str, Path]:
    """``graphmech bench --json --quick -o DIR`` run once for the session: (exit code, stdout,
    stderr, DIR). The whole bench's tests and the cam bench's read the same run."""
    out = tmp_path_factory.mktemp("bench")
    return (*run_cli("bench", "--json", "--quick", "-o", str(out), limit=BENCH_GUARD_S), out)


def run_cli(*argv: str, limit: float = HANG_GUARD_S) -> tuple[int, str, str]:
    """Run ``graphmech`` in-process under the hang guard; (exit code, stdout, stderr)."""
    from graphmech.cli import main

    out, err = io.StringIO(), io.StringIO()
    with hang_guard(limit), redirect_stdout(out), redirect_stderr(err):
        code = main(list(argv))
    return code, out.getvalue(), err.getvalue()


def assert_refused(result: tuple[int, str, str], file: str, *words: str) -> str:
    """A refusal: exit 2, nothing on stdout, one line on stderr that names the file (and the words)."""
    code, out, err = result
    assert code == 2, (code, err)
    assert out == "", out
    assert err.endswith("\n") and err.count("\n") == 1, repr(err)
    assert err.startswith(f"{file}: "), err
    for w in words:
        assert w in err, (w, err)
    return err.rstrip("\n")


def edited_scene(tmp_path: Path, scene: str, old: str, new: str, name: str = "s.toml") -> Path:
    """A reference scene (figures/scenes/``scene``) with its first ``old`` made ``new``, written as
    tmp_path/``name``; ``old`` must be in it (an edit that misses would test the scene unchanged)."""
    text = (SCENES / scene).read_text(encoding="utf-8")
    assert old in text, (scene, old)
    p = tmp_path / name
    p.write_text(text.replace(old, new, 1), encoding="utf-8")
    return p


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
