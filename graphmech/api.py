"""The Python API: a scene as a :class:`Problem` — its check table, its drawing, its variants.

>>> import graphmech as gm
>>> p = gm.loads('''
... title = "Slider-crank"
... find = ["v_C", "omega_2"]
... units = {length = "mm", angle = "deg"}
... frame = {A = [0, 0]}
... driver = {type = "crank", link = "1", pivot = "A", tip = "B", length = 50, angle = 90, omega_rad_s = 10}
... [[dyad]]
... type = "RRP"
... joints = ["B", "C"]
... links = ["2", "3"]
... length = 150
... guide = {through = [0, 0], angle = 0}
... branch = "forward"
... ''')
>>> table = p.check()
>>> [row.name for row in table]
['v_C', 'omega_2']
>>> table["v_C"].exact, table["v_C"].rel_error < 1e-9
(-0.5, True)
>>> verdict = p.check(measured={"v_C": -0.49}).measured[0]   # within ±0.5 mm of drawing × μv?
>>> verdict.ok, verdict.tolerance
(False, 0.005)
>>> round(p.replace({"driver.angle": 30}).check()["v_C"].exact, 6)
-0.323193
>>> p.render().svg.startswith("<svg")
True

Every function here raises :class:`~graphmech.errors.SceneError` (a bad scene or key path) or
another :class:`~graphmech.errors.GraphmechError` (a construction that cannot be made) with the
one-line message the command prints.
"""
from __future__ import annotations

import json
import math
import os
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, overload

from graphmech.errors import GraphmechError, SceneError, UnknownName
from graphmech.problems import check as check_scene
from graphmech.problems import steps
from graphmech.problems import timings as check_timings
from graphmech.problems import with_precision
from graphmech.problems.judging import Row, Verdict, estimate_text
from graphmech.problems.reader import Scene, Written
from graphmech.scene import draw, id_prefix, parse_scene, parse_toml, read_data
from graphmech.tolerances import MAX_PRECISION_MM
from graphmech.variants import Assignment, replace, value_text, variant_name

#: The fields of a check row, as ``check --json`` writes them (:meth:`Row.as_dict`).
ROW_FIELDS = ("name", "unit", "drawn_mm", "scale", "graphical", "exact", "rel_error", "error_source",
              "error_estimate", "basis", "ill_conditioned")


# ------------------------------------------------------------------------------ the problem


class Problem:
    """A validated scene: what :func:`load`, :func:`loads` and :func:`from_dict` return.

    ``name`` is the file's stem (with a variant's assignments, ``crank-driver.angle=60``),
    ``title`` and ``kind`` the scene's; ``scene`` the validated :class:`Scene` (SI units);
    ``data`` the TOML data it was read from; ``variant`` the assignments that made it from its
    original (empty for a scene as written).
    """

    def __init__(self, data: Mapping[str, Any], source: str = "scene", *, raw: bytes | None = None,
                 page: str | None = None, variant: Assignment | None = None) -> None:
        self.data = _plain(data, "", source, ())
        self.source = source
        self.page = page
        self.variant: Assignment = dict(variant or {})
        self.scene: Scene[Any] = parse_scene(self.data, source, page)
        # ids as the command gives them for the same file; a variant's differ from its original's
        base = raw if raw is not None else json.dumps(self.data, sort_keys=True, default=str).encode()
        self._raw = base
        tail = "".join(f"\n{k}={value_text(v)}" for k, v in self.variant.items()).encode()
        self.prefix = id_prefix(base + tail)

    @property
    def name(self) -> str:
        return variant_name(Path(self.source).stem, self.variant)

    @property
    def title(self) -> str:
        return self.scene.title

    @property
    def kind(self) -> str:
        return self.scene.kind

    def __repr__(self) -> str:
        return f"<graphmech.Problem {self.name!r}: {self.kind}, {self.title!r}>"

    def check(self, measured: Mapping[str, float | str] | Sequence[tuple[str, float | str]] | None = None,
              precision: float | None = None) -> CheckTable:
        """The check table; ``measured`` judges your own values (``{"pc": 40.5}`` drawn mm,
        ``{"v_C": 0.26}`` SI) within ``precision`` mm of drawing (default: the scene's)."""
        extra = tuple((str(k), _number(k, v, self.source)) for k, v in _pairs(measured))
        an, verdicts, doc, lines = check_scene(with_precision(self.scene, _precision(precision, self.source)), extra)
        return CheckTable(title=self.title, rows=tuple(an.rows), measured=tuple(verdicts),
                          warnings=tuple(an.warnings), scales=dict(an.scales),
                          scale_notes=tuple(an.scale_notes()), lines=tuple(lines), extras=doc,
                          variant=dict(self.variant), timings=tuple(check_timings(self.scene, an)))

    def render(self) -> Drawing:
        """The drawing: ``.svg`` text, ``.save(path)`` as SVG, PDF or PNG, shown by Jupyter."""
        svg, warnings = draw(self.scene, self.prefix)
        return Drawing(svg, tuple(warnings), self.name)

    def replace(self, changes: Mapping[str, Any]) -> Problem:
        """A variant: the scene with the values at the key paths changed (``{"driver.angle": 60}``,
        ``{"dyad[0].lengths[1]": 55}``), in the unit the scene states; validated like the file."""
        if not isinstance(changes, Mapping) or not all(isinstance(k, str) for k in changes):
            raise TypeError("replace takes a mapping of key paths to values: {\"driver.angle\": 60}")
        data = replace(self.data, changes, self.source)
        return Problem(data, self.source, raw=self._raw, page=self.page, variant={**self.variant, **changes})

    def steps(self) -> list[str]:
        """The construction protocol: the steps of the drawing as the book words them, in the
        scene's notation, with every length drawn and every value found (unnumbered)."""
        return steps(self.scene)

    def with_page(self, page: str | None) -> Problem:
        """The same problem on other paper (``"A4"`` … ``"A1-portrait"``, ``"fit"``)."""
        return Problem(self.data, self.source, raw=self._raw, page=page, variant=self.variant)


def load(path: str | os.PathLike[str], page: str | None = None) -> Problem:
    """A scene file (TOML, UTF-8), validated; ``page`` replaces its ``[page] size``."""
    data, raw = read_data(path)
    return Problem(data, Path(path).name, raw=raw, page=page)


def loads(text: str | bytes, name: str = "scene.toml", page: str | None = None) -> Problem:
    """A scene from TOML text (or its UTF-8 bytes); ``name`` is the file name messages give."""
    if not isinstance(text, (str, bytes, bytearray)):
        raise TypeError(f"loads takes the TOML text (str or bytes), not {type(text).__name__}")
    # a lone surrogate goes through, for parse_toml to refuse as not UTF-8 with its line
    raw = text.encode("utf-8", "surrogatepass") if isinstance(text, str) else bytes(text)
    return Problem(parse_toml(raw, name), name, raw=raw, page=page)


def from_dict(data: Mapping[str, Any], name: str = "scene.toml", page: str | None = None) -> Problem:
    """A scene from a dict shaped as the TOML (``{"driver": {"angle_deg": 30, …}, …}``)."""
    if not isinstance(data, Mapping):
        raise SceneError([("", "a scene must be a table (a dict)")], name)
    return Problem(data, name, page=page)


def _plain(value: Any, path: str, source: str, within: tuple[int, ...]) -> Any:
    """A copy of scene data as TOML has it — tables with text keys, arrays — so the reader meets
    nothing else (a dict of a user's is copied: changing it later changes no Problem)."""
    if isinstance(value, (Mapping, list)):
        if id(value) in within:
            raise SceneError([(path, "contains itself")], source)
        within = (*within, id(value))
    if isinstance(value, Mapping):
        out = {}
        for k, v in value.items():
            if not isinstance(k, str):
                raise SceneError([(f"{path}.{k!r}" if path else repr(k), "a key must be text (a str)")], source)
            out[k] = _plain(v, f"{path}.{k}" if path else k, source, within)
        return out
    if isinstance(value, list):
        return [_plain(v, f"{path}[{i}]", source, within) for i, v in enumerate(value)]
    return value


def _pairs(measured: object) -> Sequence[tuple[object, object]]:
    """``measured`` as (name, value) pairs: a mapping, or a sequence of pairs (None: none)."""
    if measured is None:
        return ()
    if isinstance(measured, Mapping):
        return tuple(measured.items())
    if not isinstance(measured, (str, bytes)) and isinstance(measured, Sequence) and all(
            isinstance(p, Sequence) and not isinstance(p, (str, bytes)) and len(p) == 2 for p in measured):
        return tuple((p[0], p[1]) for p in measured)
    raise TypeError('measured takes {"pc": 40.5, …} or [("pc", 40.5), …]')


def _number(name: object, value: object, source: str) -> float:
    if isinstance(value, Written):
        return value
    if isinstance(value, str):  # a value as written: its digits and sign are judged
        try:
            return Written(value)
        except ValueError as e:
            raise SceneError([(f"measured.{name}", str(e))], source) from None
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise SceneError([(f"measured.{name}", f"must be a finite number, not {value!r}")], source)
    return float(value)


def _precision(value: float | None, source: str) -> float | None:
    """The drawing precision asked (None: the scene's), as ``--precision`` takes it."""
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise TypeError(f"precision is a number of mm, not {type(value).__name__}")
    if not 0 < value <= MAX_PRECISION_MM:
        reason = f"must be a number of mm above 0 and at most {MAX_PRECISION_MM:g}, not {value:g}"
        raise SceneError([("precision", reason)], source)
    return float(value)


# ------------------------------------------------------------------------------ the check table


@dataclass(frozen=True, repr=False)
class CheckTable:
    """The check of a scene: iterate for its rows (:class:`~graphmech.problems.judging.Row`:
    ``name, unit, drawn_mm, scale, graphical, exact, rel_error, error_source, error_estimate,
    basis, ill_conditioned``); ``table["v_C"]`` is one row; ``measured`` the verdicts on your
    values; ``ok`` whether all of them are within tolerance."""

    title: str
    rows: tuple[Row, ...]
    measured: tuple[Verdict, ...] = ()
    warnings: tuple[str, ...] = ()
    scales: dict[str, float] = field(default_factory=dict)
    scale_notes: tuple[str, ...] = ()
    lines: tuple[str, ...] = ()
    extras: dict[str, Any] = field(default_factory=dict)
    variant: Assignment = field(default_factory=dict)
    #: Wall times (the true motion's integration), printed last by :meth:`text` alone: they differ
    #: from run to run, so ``to_json``, ``lines`` and the gallery leave them out.
    timings: tuple[str, ...] = field(default=(), compare=False)

    def __iter__(self) -> Iterator[Row]:
        return iter(self.rows)

    def __len__(self) -> int:
        return len(self.rows)

    @overload
    def __getitem__(self, key: int) -> Row: ...
    @overload
    def __getitem__(self, key: str) -> Row: ...
    def __getitem__(self, key: int | str) -> Row:
        if isinstance(key, int):
            return self.rows[key]
        for row in self.rows:
            if row.name == key:
                return row
        raise UnknownName(f"{key!r}: not in the check table (it has {', '.join(r.name for r in self.rows)})")

    @property
    def ok(self) -> bool:
        """Every measured value is within tolerance (True when none was given)."""
        return all(v.ok for v in self.measured)

    def to_dict(self) -> dict[str, Any]:
        """What ``check --json`` prints (plus ``"variant"`` for a variant)."""
        doc = {"quantities": [r.as_dict() for r in self.rows], "measured": [v.as_dict() for v in self.measured],
               "warnings": list(self.warnings), "scales": self.scales, **self.extras}
        if self.variant:
            doc["variant"] = dict(self.variant)
        return doc

    def to_json(self, indent: int | None = 1) -> str:
        return json.dumps(self.to_dict(), indent=indent, ensure_ascii=False, allow_nan=False)

    def to_pandas(self) -> Any:
        """The rows as a pandas DataFrame (pandas is not a dependency of graphmech)."""
        try:
            import pandas as pd
        except ImportError:
            raise GraphmechError("to_pandas needs pandas: pip install pandas") from None
        return pd.DataFrame([r.as_dict() for r in self.rows], columns=list(ROW_FIELDS))

    def text(self) -> str:
        """The table as ``graphmech check`` prints it."""
        lines = [self.title, "  ".join(self.scale_notes)]
        if self.rows:
            w = max(16, *(len(r.name) for r in self.rows))  # a long name (pressure_angle_C@200) keeps its column
            lines.append(f"{'quantity':<{w}} {'drawn mm':>11} {'μ':>11} {'graphical':>16} {'exact':>16} "
                         f"{'rel.error':>9}  unit")
            for r in self.rows:
                drawn = "" if r.drawn_mm is None else f"{r.drawn_mm:.3f}"
                flag = "  ILL-CONDITIONED" if r.ill_conditioned else ""
                if r.error_estimate is not None:  # a discretised or read-off value: how accurate it says it is
                    flag += "  " + estimate_text(r)
                lines.append(f"{r.name:<{w}} {drawn:>11} {r.scale:>11.5g} {r.graphical:>16.9g} {r.exact:>16.9g}"
                             f" {r.rel_error:>9.1e}  {r.unit}{flag}")
        return "\n".join([*lines, *self.verdict_lines(), *self.lines, *self.timings])

    def verdict_lines(self) -> list[str]:
        """The verdicts on the measured values as ``graphmech check`` prints them (none: no lines)."""
        if not self.measured:
            return []
        w = max(16, *(len(v.name) for v in self.measured))
        lines = [f"{'measured':<{w}} {'value':>11} {'expected':>13} {'± tol':>9}  verdict"]
        for v in self.measured:
            value = f"{v.written:>11}" if v.written else f"{v.measured:>11.6g}"  # as written, and by which rules
            lines.append(f"{v.name:<{w}} {value} {v.expected:>13.6g} {v.tolerance:>9.3g}  "
                         f"{'ok' if v.ok else 'OUT OF TOLERANCE'} ({v.unit}{'; ' + v.rule if v.rule else ''})")
        return lines

    def __str__(self) -> str:
        return self.text()

    def __repr__(self) -> str:
        judged = f", {len(self.measured)} measured" if self.measured else ""
        return f"<graphmech.CheckTable {self.title!r}: {len(self.rows)} rows{judged}>"

    def _repr_html_(self) -> str:
        from html import escape

        head = "".join(f"<th>{escape(h)}</th>" for h in ("quantity", "drawn mm", "μ", "graphical", "exact",
                                                          "rel. error", "unit", "accuracy"))
        body = []
        for r in self.rows:
            acc = "ill-conditioned" if r.ill_conditioned else ""
            acc += " " + estimate_text(r)
            cells = (r.name, "" if r.drawn_mm is None else f"{r.drawn_mm:.3f}", f"{r.scale:.5g}",
                     f"{r.graphical:.9g}", f"{r.exact:.9g}", f"{r.rel_error:.1e}", r.unit, acc.strip())
            body.append("<tr>" + "".join(f"<td>{escape(c)}</td>" for c in cells) + "</tr>")
        for v in self.measured:
            value = escape(v.written) if v.written else f"{v.measured:.6g}"
            body.append(f"<tr><td>{escape(v.name)}</td><td colspan='7'>measured {value}, expected "
                        f"{v.expected:.6g} ± {v.tolerance:.3g} {escape(v.unit)}: "
                        f"<b>{'ok' if v.ok else 'OUT OF TOLERANCE'}</b>"
                        f"{' (' + escape(v.rule) + ')' if v.rule else ''}</td></tr>")
        return (f"<table><caption>{escape(self.title)} — {escape('  '.join(self.scale_notes))}</caption>"
                f"<thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table>")


# ------------------------------------------------------------------------------ the drawing


@dataclass(frozen=True, repr=False)
class Drawing:
    """A scene's drawing: ``svg`` (text), the ``warnings`` found while making it; Jupyter and
    IPython show it inline (``_repr_svg_``)."""

    svg: str
    warnings: tuple[str, ...] = ()
    name: str = "scene"

    def save(self, path: str | Path, format: str | None = None, dpi: float | None = None) -> Path:
        """Write the drawing as SVG, PDF (true size) or PNG (at ``dpi``), by the extension or
        ``format``; atomically. Returns the path."""
        from graphmech.render.export import DPI, save

        save(self.svg, path, format, DPI if dpi is None else dpi)
        return Path(path)

    def _repr_svg_(self) -> str:
        return self.svg

    def __repr__(self) -> str:
        import re

        w = re.search(r'width="([\d.]+)mm"', self.svg[:600])
        h = re.search(r'height="([\d.]+)mm"', self.svg[:600])
        page = f"{w.group(1)} × {h.group(1)} mm" if w and h else "SVG"
        return f"<graphmech.Drawing {self.name!r}: {page}, {len(self.warnings)} warnings>"


__all__ = ["ROW_FIELDS", "CheckTable", "Drawing", "Problem", "from_dict", "load", "loads"]
