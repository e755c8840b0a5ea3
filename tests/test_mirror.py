"""The tests mirror the package: each module that holds logic (it defines a function or a method)
has its own test module at the same place below tests/ (graphmech/problems/cam/scene.py →
tests/problems/cam/test_scene.py), and every test module below a mirrored folder tests a module
that exists — or is one of the few kinds of test that span a kind's modules (EXTRAS).

A package's ``__init__.py`` is wiring, not logic: the registry (problems/__init__.py: KINDS and
its one-line dispatchers) and each kind's lazy wrappers are tested through every registered kind
(tests/problems/test_kind.py) and the scene loader's dispatch (tests/test_scene.py)."""
from __future__ import annotations

import ast
from pathlib import Path

import pytest

from tests.conftest import ROOT

PACKAGE = ROOT / "graphmech"
TESTS = ROOT / "tests"

# Test modules that span a kind's (or a folder's) modules rather than test one: the book's
# problems reproduced by scenes, hostile input, and the extreme but valid cases.
EXTRAS = {"test_reference", "test_robustness", "test_extremes"}
# Test modules of the project as a whole (tests/ itself): layers, types, the fresh clone, the
# fuzzer, the docs' examples, the figures in a browser, this file.
PROJECT = {"test_layout", "test_mirror", "test_typing", "test_fresh_clone", "test_fuzz", "test_docs_examples", "test_notebook",
           "test_browser"}
# Folders below tests/ that mirror nothing: shared data and scenes.
NOT_MIRRORED = {"reference", "scenes", "__pycache__"}


def holds_logic(source: str) -> bool:
    """Whether a module defines a function or a method (constants and plain records do not count)."""
    return any(isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef)) for n in ast.walk(ast.parse(source)))


def modules_with_logic(package: Path = PACKAGE) -> list[Path]:
    return sorted(p for p in package.rglob("*.py")
                  if p.name not in ("__init__.py", "__main__.py") and holds_logic(p.read_text(encoding="utf-8")))


def untested(package: Path = PACKAGE, tests: Path = TESTS) -> list[str]:
    out = []
    for module in modules_with_logic(package):
        rel = module.relative_to(package)
        if not (tests / rel.parent / f"test_{rel.name}").is_file():
            out.append(f"{rel.as_posix()} → tests/{(rel.parent / f'test_{rel.name}').as_posix()}")
    return out


def orphans(package: Path = PACKAGE, tests: Path = TESTS) -> list[str]:
    """Test modules that mirror no module and are not one of the named extras."""
    out = []
    for test in sorted(tests.rglob("test_*.py")):
        rel = test.relative_to(tests)
        if rel.parts[0] in NOT_MIRRORED:
            continue
        stem = test.stem
        if len(rel.parts) == 1 and stem in PROJECT:
            continue
        if len(rel.parts) > 1 and stem in EXTRAS and (package / rel.parent).is_dir():
            continue
        if not (package / rel.parent / f"{stem.removeprefix('test_')}.py").is_file():
            out.append(rel.as_posix())
    return out


def test_every_module_with_logic_has_its_test_module():
    missing = untested()
    assert not missing, f"{len(missing)} modules without a test module:\n" + "\n".join(missing)


def test_every_test_module_mirrors_a_module():
    lost = orphans()
    assert not lost, "test modules that mirror no module:\n" + "\n".join(lost)


def test_every_test_folder_is_a_package():
    """Test modules share base names (tests/problems/cam/test_scene.py, …/linkage/test_scene.py), so
    each folder needs its __init__.py for pytest to import both."""
    bare = [d.relative_to(TESTS).as_posix() for d in TESTS.rglob("*")
            if d.is_dir() and d.name != "__pycache__" and any(d.glob("test_*.py")) and not (d / "__init__.py").is_file()]
    assert not bare, bare


# ---------------------------------------------------------------------------- the checker's own tests


def write(root: Path, files: dict[str, str]) -> None:
    for name, text in files.items():
        (root / name).parent.mkdir(parents=True, exist_ok=True)
        (root / name).write_text(text, encoding="utf-8")


@pytest.mark.parametrize("source, expected", [
    ("X = 1\n", False),
    ("from dataclasses import dataclass\n@dataclass\nclass P:\n    x: float\n", False),
    ("def f():\n    return 1\n", True),
    ("class P:\n    def area(self):\n        return 0\n", True),
])
def test_checker_knows_what_holds_logic(source, expected):
    assert holds_logic(source) is expected


def test_checker_finds_the_untested_and_the_orphans(tmp_path):
    pkg, tests = tmp_path / "pkg", tmp_path / "tests"
    write(pkg, {"a.py": "def f(): pass\n", "k/b.py": "def g(): pass\n", "k/c.py": "C = 1\n",
                "k/__init__.py": "def h(): pass\n"})
    write(tests, {"test_a.py": "", "k/test_robustness.py": "", "k/test_gone.py": "", "test_layout.py": "",
                  "test_other.py": ""})
    assert untested(pkg, tests) == ["k/b.py → tests/k/test_b.py"]
    assert orphans(pkg, tests) == ["k/test_gone.py", "test_other.py"]
