"""Load a scene file — the TOML that says what to construct, draw and check — and hand it to
its kind of problem.

:func:`load_scene` reads the file (UTF-8, at most :data:`MAX_BYTES`, valid TOML);
:func:`parse_scene` reads the tables every scene shares and asks the registry
(:data:`graphmech.problems.KINDS`) which kind the file poses — the first whose tables it has —
and that kind's reader reads the rest (``graphmech/problems/<kind>/scene.py``). Every number is
converted to SI on load. :func:`render_scene` is the whole way from a file to its SVG.

Validation collects *every* problem and raises one :class:`~graphmech.errors.SceneError`;
its key paths read the way the user wrote the file (``dyad[0].lengths[1]``,
``driver.angle_deg[2]``, ``frame.D``, ``cam.segment[2].angle``), and its message is the first
problem in file order.

The format, with an example of every feature, is ``docs/scene-format.md``.
"""

from __future__ import annotations

import hashlib
import os
import re
import tomllib
from pathlib import Path
from typing import Any

from graphmech.errors import SceneError
from graphmech.problems import KINDS, sheet, tables
from graphmech.problems.reader import Reader, Scene, read_units

#: A scene file larger than this (bytes) is refused before it is parsed.
MAX_BYTES = 1 << 20


def with_page(data: dict[str, Any], page: str | None) -> dict[str, Any]:
    """The TOML data with ``[page] size = page`` (the command line's ``--page``) in place of the
    file's own: it is read like the file's, so that every kind's reader chooses its scales and
    judges "does the sheet fit" for that page (None: the file's page). A ``page`` that is no
    table is left for the reader to refuse.

    >>> with_page({"title": "t", "page": {"size": "A4", "notation": "zh"}}, "fit")
    {'title': 't', 'page': {'size': 'fit', 'notation': 'zh'}}
    """
    table = data.get("page", {})
    if page is None or not isinstance(table, dict):
        return data
    return {**data, "page": {**table, "size": page}}


def parse_scene(data: dict[str, Any], source: str = "scene", page: str | None = None) -> Scene[Any]:
    """Validate parsed TOML data and build the :class:`Scene`, in SI units.

    Parameters
    ----------
    data : dict
        The TOML document as ``tomllib`` returns it.
    source : str
        The name used in messages.
    page : str, optional
        A paper size (a name in :data:`graphmech.scales.PAPER`, or ``"fit"``) that replaces the
        scene's ``[page] size`` (:func:`with_page`).

    Returns
    -------
    Scene

    Raises
    ------
    SceneError
        With every problem found (``.problems``); the message is the first, in file order.

    Examples
    --------
    >>> scene = parse_scene({
    ...     "title": "A crank alone",
    ...     "units": {"length": "mm", "angle": "deg"},
    ...     "frame": {"A": [0, 0]},
    ...     "driver": {"type": "crank", "link": "1", "pivot": "A", "tip": "B",
    ...                "length": 50, "angle": [0, 90], "omega_rpm": 60},
    ... }, "crank.toml")
    >>> scene.linkage.driver.length, scene.positions.labels, scene.linkage.frame_link
    (0.05, ('0', '90'), '2')
    >>> round(scene.linkage.driver.omega, 6)
    6.283185
    >>> from graphmech.errors import SceneError
    >>> try:
    ...     parse_scene({
    ...         "frame": {"A_mm": [0, 0]},
    ...         "driver": {"type": "crank", "link": 1, "pivot": "A", "tip": "B",
    ...                    "lenght_mm": 50, "angle_deg": 30, "omega_rad_s": 10},
    ...     }, "bad.toml")
    ... except SceneError as err:
    ...     print(err)
    ...     print(err.problems[1])
    bad.toml: driver.lenght_mm: unknown key; did you mean length_mm? (and 1 more)
    ('driver.length', 'missing: write length_mm (or length with [units] length)')

    A cam scene has a [cam] table instead of [driver]:

    >>> cam = parse_scene({
    ...     "units": {"length": "mm", "angle": "deg"},
    ...     "cam": {"base_radius": 30, "rotation": "ccw", "omega_rad_s": 10,
    ...             "follower": {"type": "translating", "contact": "knife", "offset": 35},
    ...             "program": {"stroke": 16},
    ...             "segment": [{"kind": "rise", "angle": 180, "law": "sine"},
    ...                         {"kind": "return", "angle": 170, "law": "sine"}]},
    ... }, "cam.toml")
    Traceback (most recent call last):
    ...
    graphmech.errors.SceneError: cam.toml: cam.follower.offset: |e| = 35 mm is not smaller than the base radius r0 = 30 mm: the follower's axis misses the base circle (and 1 more)
    """
    problems: list[tuple[str, str]] = []
    if not isinstance(data, dict):
        raise SceneError([("", "a scene must be a TOML table")], source)
    data = with_page(data, page)
    order = {k: n for n, k in enumerate(data)}
    top = Reader(data, "", problems, {})
    top.units = read_units(top)
    # a misspelt kind's table gets a suggestion in any scene; a table the file has is no
    # misspelling of itself (not "cycle: unknown key; did you mean cycle?")
    top.known.update(t for t in tables() if t not in data)
    kind = next(kind for kind in KINDS.values() if kind.posed_by(data))  # the linkage's, if no other
    refusal = kind.mixture(data) if kind.mixture is not None else None
    if refusal is not None:  # one problem: which of the two to read is anyone's guess
        top.problem(*refusal)
        raise SceneError(problems, source)
    return kind.read(data, source, top, order)


def load_scene(path: str | os.PathLike[str], page: str | None = None) -> Scene[Any]:
    """Read a scene file and validate it.

    Parameters
    ----------
    path : str or path-like
        A UTF-8 TOML file of at most :data:`MAX_BYTES` bytes.
    page : str, optional
        A paper size that replaces the scene's ``[page] size`` (see :func:`parse_scene`).

    Returns
    -------
    Scene

    Raises
    ------
    SceneError
        For an unreadable, oversized, non-UTF-8 or malformed file, and for every problem
        :func:`parse_scene` finds; messages start with the file name.
    """
    return parse_scene(read_data(path)[0], Path(path).name, page)


def read_data(path: str | os.PathLike[str]) -> tuple[dict[str, Any], bytes]:
    """A scene file's TOML data, unvalidated, and its bytes (for :func:`id_prefix`); the
    file's problems (unreadable, oversized, not UTF-8, not TOML) raised as in :func:`load_scene`."""
    source = Path(path).name
    try:
        with open(path, "rb") as fh:
            raw = fh.read(MAX_BYTES + 1)
    except OSError as exc:
        raise SceneError([("", f"cannot read the file ({exc.strerror or exc})")], source) from None
    if len(raw) > MAX_BYTES:
        raise SceneError(
            [("", "file is larger than 1 MiB; a scene is a few kilobytes, refusing to read it")],
            source,
        )
    return parse_toml(raw, source), raw


def parse_toml(raw: bytes, source: str = "scene") -> dict[str, Any]:
    """TOML text (UTF-8 bytes, a BOM allowed) as data; its problems as a one-line SceneError
    naming the line."""
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = raw[: exc.start].count(b"\n") + 1
        raise SceneError(
            [
                (
                    f"line {line}",
                    f"not UTF-8 text (byte 0x{raw[exc.start]:02x}); save the file as UTF-8",
                )
            ],
            source,
        ) from None
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        message = str(exc)
        m = re.search(r"\(at line (\d+), column (\d+)\)", message)
        what = re.sub(r"\s*\(at [^)]*\)\s*$", "", message)
        what = what[:1].lower() + what[1:]
        if m:
            raise SceneError(
                [(f"line {m.group(1)}", f"invalid TOML: {what} (column {m.group(2)})")], source
            ) from None
        line = text.count("\n") + 1
        raise SceneError(
            [(f"line {line}", f"invalid TOML: {what} (at the end of the file)")], source
        ) from None
    except RecursionError:
        raise SceneError([("", "invalid TOML: nested too deeply")], source) from None


def render_scene(path: str | os.PathLike[str], page: str | None = None) -> tuple[str, list[str]]:
    """The SVG text of a scene file and the warnings found while making it; ``page`` replaces
    the scene's ``[page] size`` (see :func:`parse_scene`)."""
    return draw(load_scene(path, page), id_prefix(path))


def draw(scene: Scene[Any], prefix: str) -> tuple[str, list[str]]:
    """The SVG text of a scene and the warnings found while making it; element ids start with
    ``prefix`` (:func:`id_prefix`)."""
    from graphmech.render.svg import render_svg  # the SVG backend only when a drawing is made
    from graphmech.version import __version__

    drawing, warnings = sheet(scene, (f"graphmech {__version__}",))
    warnings = list(warnings)
    return render_svg(drawing, prefix, on_warning=warnings.append), warnings


def id_prefix(path: str | os.PathLike[str] | bytes) -> str:
    """Element ids start with a hash of the scene (a file, or its bytes), so two figures inline
    on one page don't clash."""
    raw = path if isinstance(path, bytes) else Path(path).read_bytes()
    return "g" + hashlib.sha256(raw).hexdigest()[:8]


__all__ = ["MAX_BYTES", "Scene", "draw", "id_prefix", "load_scene", "parse_scene", "parse_toml", "read_data",
           "render_scene", "with_page"]
