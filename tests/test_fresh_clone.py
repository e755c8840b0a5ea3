"""A clone with nothing beside it runs its own tests: the reference data lives in the repository,
no test climbs out of it, and the README's test command is the one CI runs and shows its summary.

The whole suite from a fresh clone in a fresh venv is `.ci/fresh-clone` (see the README).
"""
from __future__ import annotations

import ast
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import graphmech
from tests.conftest import REFERENCE, ROOT, reference_problems

TESTS = ROOT / "tests"


def _test_sources() -> list[Path]:
    return sorted(p for p in TESTS.rglob("*.py") if "reference" not in p.parts)


def _levels_up(node: ast.AST) -> int | None:
    """How many folders above the file ``Path(__file__)…`` names (.parent: 1, .parents[k]: k + 1),
    or None if the expression is not built on ``__file__``."""
    if isinstance(node, ast.Attribute) and node.attr == "parent":
        up = _levels_up(node.value)
        return None if up is None else up + 1
    if (isinstance(node, ast.Subscript) and isinstance(node.value, ast.Attribute)
            and node.value.attr == "parents" and isinstance(node.slice, ast.Constant)):
        up = _levels_up(node.value.value)
        return None if up is None else up + node.slice.value + 1
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):  # .resolve(), .absolute()
        return _levels_up(node.func.value)
    if isinstance(node, ast.Call):  # Path(__file__)
        return 0 if "__file__" in ast.unparse(node) else None
    return 0 if isinstance(node, ast.Name) and node.id == "__file__" else None


def _climbs_out(node: ast.AST, depth: int) -> str | None:
    """Why this expression names a path above the repository root, or None.

    ``depth`` is how many folders the test file lies below the root (tests/x.py: 1, whose
    ``parents[1]`` and ``.parent.parent`` are the root itself)."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        if re.search(r"(^|[/\\])\.\.([/\\]|$)", node.value):
            return f"the string {node.value!r} goes up a folder"
    if isinstance(node, ast.Attribute) and node.attr == "parent" and isinstance(node.value, ast.Name) \
            and node.value.id == "ROOT":
        return "ROOT.parent is outside the repository"
    up = _levels_up(node)
    if up is not None and up > depth + 1:
        return f"{up} folders up from a file {depth} folder(s) below the root"
    return None


def test_the_path_check_sees_each_way_out():
    bad = ['"../data.toml"', "ROOT.parent / 'x'", "Path(__file__).parent.parent.parent / 'x'",
           "Path(__file__).resolve().parents[2] / 'x'",
           "Path(__file__).resolve().parents[1].parent / 'x'"]
    for text in bad:
        assert any(_climbs_out(n, 1) for n in ast.walk(ast.parse(text))), text
    good = ["ROOT / 'tests'", "Path(__file__).resolve().parents[1]", "Path(__file__).parent.parent / 'x'", "'a..b'"]
    for text in good:
        assert not any(_climbs_out(n, 1) for n in ast.walk(ast.parse(text))), text


def test_no_test_reads_a_path_outside_the_repository():
    found = []
    for path in _test_sources():
        depth = len(path.relative_to(ROOT).parts) - 1
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if (why := _climbs_out(node, depth)) is not None:
                found.append(f"{path.relative_to(ROOT)}:{getattr(node, 'lineno', '?')}: {why}")
    assert not found, "\n".join(found)


def test_the_reference_bank_is_in_the_repository_and_says_where_it_came_from():
    assert REFERENCE.resolve().is_relative_to(ROOT)
    head = REFERENCE.read_text(encoding="utf-8").splitlines()[0]
    assert head.startswith("# Copied verbatim from the team's reference bank")
    bank = reference_problems()
    assert len(bank) == 47 and "kin.oscillating_block" in bank
    for pid, p in bank.items():
        assert {"id", "area", "source", "statement", "inputs"} <= p.keys(), pid


def test_the_readme_test_command_is_what_ci_runs():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    command = 'pip install ".[test]" && python -m pytest -q'
    assert f"```sh\n{command}\n```" in readme
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8").strip().splitlines()
    assert ci[-2:] == ['pip install --quiet ".[test]"', "python -m pytest -q"]


def test_pytest_q_prints_the_summary_line():
    """`-q` in addopts plus the README's `-q` gives `-qq`, which hides "N passed"."""
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    assert "-q" not in config["tool"]["pytest"]["ini_options"]["addopts"].split()
    one = f"{Path(__file__).relative_to(ROOT)}::test_the_path_check_sees_each_way_out"
    out = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", one],
                         cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stdout + out.stderr
    assert re.search(r"^1 passed in [0-9.]+s", out.stdout, re.MULTILINE), out.stdout


def test_version_is_printed_by_the_command():
    out = subprocess.run([sys.executable, "-m", "graphmech", "--version"], capture_output=True, text=True,
                         timeout=60)
    assert out.returncode == 0 and out.stdout == f"graphmech {graphmech.__version__}\n"
    assert out.stderr == ""
