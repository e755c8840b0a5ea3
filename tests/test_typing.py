"""The type check is part of the suite: mypy, as configured in pyproject.toml ([tool.mypy]), finds
no error in graphmech/, and that configuration stays strict.

mypy caches what it learnt in .mypy_cache/ at the root (git ignores it): the first run on a clean
clone checks every module, later runs only the changed ones.
"""
from __future__ import annotations

import os
import tomllib

from tests.conftest import ROOT

PYPROJECT = ROOT / "pyproject.toml"


def _mypy_config() -> dict:
    return tomllib.loads(PYPROJECT.read_text(encoding="utf-8"))["tool"]["mypy"]


def test_the_type_check_is_strict_on_the_whole_package():
    config = _mypy_config()
    assert config.get("strict") is True, "[tool.mypy] must keep strict = true"
    assert config.get("files") == ["graphmech"]
    assert config.get("python_version") == "3.11"
    # no strict flag turned back off behind strict's back
    relaxed = {k: v for k, v in config.items() if k.startswith(("allow_", "disallow_", "warn_", "no_implicit", "strict_"))
               and v is False}
    assert relaxed == {}, f"strict flags turned off in [tool.mypy]: {relaxed}"


def test_only_untyped_libraries_are_let_off():
    """ignore_missing_imports only for libraries with no type information here (numpy and
    matplotlib ship theirs, and are checked); no module of graphmech is let off anything."""
    overrides = _mypy_config().get("overrides", [])
    for o in overrides:
        modules = o["module"] if isinstance(o["module"], list) else [o["module"]]
        assert not any(m.split(".")[0] in ("graphmech", "numpy", "matplotlib") for m in modules), o
        assert set(o) == {"module", "ignore_missing_imports"}, o


def test_mypy_finds_no_error_in_graphmech():
    from mypy import api  # in the test extra: pip install ".[test]"

    cwd = os.getcwd()
    os.chdir(ROOT)  # the config's files and cache are relative to the root
    try:
        out, err, status = api.run(["--config-file", str(PYPROJECT), "--no-error-summary"])
    finally:
        os.chdir(cwd)
    errors = [line for line in out.splitlines() if ": error:" in line]
    assert status == 0 and not errors, (
        f"mypy (strict, pyproject.toml) reports {len(errors)} error(s); the first:\n"
        + "\n".join(errors[:15]) + (f"\n{err}" if err else "") + f"\n{_typed_versions()}")


def _typed_versions() -> str:
    """numpy and matplotlib ship their own types and are not pinned: a failure with no change to
    graphmech may come from a newer one (the versions it was clean with: README, Tests)."""
    from importlib.metadata import version

    return "checked with " + ", ".join(f"{p} {version(p)}" for p in ("mypy", "numpy", "matplotlib"))
