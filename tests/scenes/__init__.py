"""Scenes the tests share, one TOML file each under ``tests/scenes/<kind>/``, named for what it is.

A test that needs a variant reads the text and changes it (``scene_text(...).replace(...)``), so
the scene it starts from is written once, here, and not again inline in each test module.
"""
from __future__ import annotations

from pathlib import Path

HERE = Path(__file__).resolve().parent


def scene_path(name: str) -> Path:
    """The file of the shared scene ``name`` (``"cam/disc_roller"`` → tests/scenes/cam/disc_roller.toml)."""
    path = HERE / f"{name}.toml"
    if not path.is_file():
        known = sorted(p.relative_to(HERE).with_suffix("").as_posix() for p in HERE.rglob("*.toml"))
        raise FileNotFoundError(f"no shared test scene {name!r}; there are: {', '.join(known)}")
    return path


def scene_text(name: str) -> str:
    """The TOML text of the shared scene ``name``."""
    return scene_path(name).read_text(encoding="utf-8")
