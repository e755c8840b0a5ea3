"""Scenes the tests share, one TOML file each under ``tests/scenes/<kind>/``, named for what it is,
and the few steps every scene test takes: write a scene to a folder, parse its text, catch its refusal.

A test that needs a variant reads the text and changes it (``replace_once(scene_text(...), ...)``),
so the scene it starts from is written once, here, and not again inline in each test module.
"""
from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest

from graphmech.errors import SceneError
from graphmech.problems.reader import Scene
from graphmech.scene import parse_scene

HERE = Path(__file__).resolve().parent
DOCS = HERE.parents[1] / "docs" / "scene-format.md"


def scene_path(name: str) -> Path:
    """The file of the shared scene ``name`` (``"cam/offset_roller"`` → tests/scenes/cam/offset_roller.toml)."""
    path = HERE / f"{name}.toml"
    if not path.is_file():
        known = sorted(p.relative_to(HERE).with_suffix("").as_posix() for p in HERE.rglob("*.toml"))
        raise FileNotFoundError(f"no shared test scene {name!r}; there are: {', '.join(known)}")
    return path


def scene_text(name: str) -> str:
    """The TOML text of the shared scene ``name``."""
    return scene_path(name).read_text(encoding="utf-8")


def doc_blocks() -> list[str]:
    """Every TOML block of docs/scene-format.md (the examples a user copies)."""
    return re.findall(r"^```toml\n(.*?)^```", DOCS.read_text(encoding="utf-8"), re.S | re.M)


def write_scene(folder: Path, text: str | bytes, name: str = "scene.toml") -> Path:
    """``text`` written to ``folder/name`` (bytes as they are, text as UTF-8)."""
    path = folder / name
    if isinstance(text, bytes):
        path.write_bytes(text)
    else:
        path.write_text(text, encoding="utf-8")
    return path


def parse_text(text: str, source: str = "scene.toml") -> Scene:
    """The scene that TOML ``text`` reads as, named ``source`` in its messages."""
    return parse_scene(tomllib.loads(text), source)


def refusal(text: str, source: str = "scene.toml") -> SceneError:
    """The SceneError that reading ``text`` must raise."""
    with pytest.raises(SceneError) as info:
        parse_text(text, source)
    return info.value


def only_problem(text: str, source: str = "scene.toml") -> tuple[str, str]:
    """The one (key path, reason) of a scene with one mistake, said on one line."""
    err = refusal(text, source)
    assert len(err.problems) == 1, err.problems
    assert "\n" not in str(err)
    return err.problems[0]


def replace_once(text: str, old: str, new: str) -> str:
    """``text`` with its first ``old`` replaced; ``old`` must be there (a variant that changes
    nothing would test the original again)."""
    assert old in text, old
    return text.replace(old, new, 1)
