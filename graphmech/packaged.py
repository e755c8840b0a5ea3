"""What is installed with the package besides the code: the example scenes, the docs and the
scene templates (``graphmech examples``, ``graphmech new``).

The example scenes and the docs have one copy each, ``figures/scenes`` and ``docs/`` of the
repository; pyproject.toml installs them as the package data ``graphmech/examples`` and
``graphmech/docs``. Run from a checkout (``PYTHONPATH``, ``python -m`` at the root, an editable
install) the checkout's own copies are read, so the files a test or a user edits are the ones
used; an installed package reads its data through :mod:`importlib.resources`.
"""
from __future__ import annotations

import difflib
import os
import tomllib
from importlib.resources import files
from importlib.resources.abc import Traversable
from pathlib import Path

from graphmech.errors import GraphmechError, printable
from graphmech.files import write_atomic

_HERE = Path(__file__).resolve().parent

#: The kinds ``graphmech new`` writes a template for: graphmech/templates/<kind>.toml, each a
#: commented copy of the example scene its first line names.
TEMPLATES = ("linkage", "cam", "flywheel", "forces", "balancing", "efficiency", "structure", "cycle", "gears",
             "trains", "synthesis", "other")


def _data(installed: str, checkout: str) -> Traversable:
    """The folder ``graphmech/<installed>`` of an installed package, or the checkout's ``checkout``."""
    root = _HERE.parent
    if (root / "pyproject.toml").is_file() and (root / checkout).is_dir():
        return root / checkout  # a checkout: the one copy
    return files("graphmech").joinpath(installed)


def examples() -> Traversable:
    """The folder of the example scenes (figures/scenes)."""
    return _data("examples", "figures/scenes")


def docs() -> Traversable:
    """The folder of the docs (docs/: scene-format.md …)."""
    return _data("docs", "docs")


def templates() -> Traversable:
    """The folder of the scene templates (always inside the package)."""
    return files("graphmech").joinpath("templates")


def example_names() -> list[str]:
    """The example scenes' names (their file names without .toml), sorted."""
    return sorted(p.name[:-5] for p in examples().iterdir() if p.name.endswith(".toml") and p.is_file())


def _unknown(what: str, name: str, known: list[str], listing: str) -> GraphmechError:
    close = difflib.get_close_matches(name.casefold(), known, n=1, cutoff=0.5)
    hint = f"; did you mean {close[0]!r}?" if close else ""
    return GraphmechError(f"unknown {what} {printable(name)!r}{hint} ({listing})")


def example(name: str) -> Traversable:
    """The example scene file ``name`` (with or without .toml); an unknown name is refused with
    the closest name."""
    stem = name.removesuffix(".toml")
    known = example_names()
    if stem not in known:
        raise _unknown("example", name, known, "graphmech examples lists them")
    return examples().joinpath(stem + ".toml")


def example_title(name: str) -> str:
    """The title an example scene states (one line, control characters escaped)."""
    data = tomllib.loads(example(name).read_text(encoding="utf-8"))
    return printable(str(data.get("title", "")))


def template(kind: str) -> str:
    """The commented scene template of ``kind`` (one of :data:`TEMPLATES`)."""
    if kind not in TEMPLATES:
        raise _unknown("template", kind, list(TEMPLATES), "choose from " + ", ".join(TEMPLATES))
    return templates().joinpath(kind + ".toml").read_text(encoding="utf-8")


def write_new(out: str | os.PathLike[str], text: str) -> None:
    """Write ``text`` to a new file ``out``: an existing file is never replaced (a copied example
    or a template is a start to edit, and someone's edits may be in the file already)."""
    path = Path(out)
    if path.is_dir():
        raise GraphmechError(f"{out}: is a folder; give a file name")
    if os.path.lexists(path):
        raise GraphmechError(f"{out}: exists; not overwriting it (remove it or give another name)")
    if not Path(os.path.realpath(path)).parent.is_dir():
        raise GraphmechError(f"{out}: folder does not exist")
    write_atomic(path, text)


__all__ = ["TEMPLATES", "docs", "example", "example_names", "example_title", "examples", "template",
           "templates", "write_new"]
