"""Placeholder until the PDF/PNG export lands: SVG only."""
from __future__ import annotations

import os
from pathlib import Path

from graphmech.errors import GraphmechError
from graphmech.files import write_atomic

FORMATS = ("svg", "pdf", "png")


def format_of(path: str | os.PathLike[str], fmt: str | None = None) -> str:
    ext = Path(path).suffix.lower().lstrip(".")
    if ext not in FORMATS:
        raise GraphmechError(f"{Path(path).name}: unknown format .{ext}: write .svg, .pdf or .png")
    if fmt is not None and fmt != ext:
        raise GraphmechError(f"{Path(path).name}: the extension says {ext}, --format says {fmt}")
    return ext


def convert(svg: str, fmt: str, dpi: float | None = None) -> bytes:
    if fmt != "svg":
        raise GraphmechError("PDF and PNG: not yet")
    return svg.encode("utf-8")


def save(svg: str, path: str | os.PathLike[str], fmt: str | None = None, dpi: float | None = None) -> None:
    write_atomic(path, convert(svg, format_of(path, fmt), dpi))
