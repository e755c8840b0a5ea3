"""``graphmech gallery DIR -d SITE``: a static HTML page of the figures of a folder of scenes.

For each scene ``DIR/*.toml`` (by file name) the page shows its figure (``SITE/<name>.svg``, an
``<img>``), its check table — the rows of ``graphmech check`` with how accurate each says it is —,
its measured values judged, its warnings, and links to the figure and to a copy of the scene
(``SITE/<name>.toml``). A scene that cannot be read, drawn or checked is listed with its one-line
reason and the others are still written. Every text taken from a scene is HTML-escaped; the output
depends on the scenes alone (no clock, sorted order), so the same folder gives the same bytes.
"""
from __future__ import annotations

import html
import os
from collections.abc import Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING
from urllib.parse import quote

from graphmech.errors import GraphmechError, printable
from graphmech.files import write_atomic
from graphmech.problems.judging import estimate_text
from graphmech.scene import MAX_BYTES

if TYPE_CHECKING:
    from graphmech.api import CheckTable
    from graphmech.batch import Result

INDEX = "index.html"

STYLE = """
body { font-family: "DejaVu Serif", "Noto Serif CJK SC", serif; margin: 1.5em auto; max-width: 80em;
       padding: 0 1em; color: #111; }
h1 { font-size: 1.5em; } h2 { font-size: 1.2em; margin-top: 2em; border-top: 1px solid #999; padding-top: .5em; }
figure { margin: 1em 0; } figure img { max-width: 100%; height: auto; border: 1px solid #ccc; }
table { border-collapse: collapse; font-size: .9em; margin: .5em 0; }
th, td { border: 1px solid #bbb; padding: .15em .5em; } td.n { text-align: right; font-variant-numeric: tabular-nums; }
td.bad, .failed { color: #a00; } ul.warnings { color: #730; } p.scales, p.files { font-size: .9em; }
"""


@dataclass(frozen=True)
class Entry:
    """One scene of the gallery: its figure and check, or the reason it failed."""

    name: str  # the scene file's name without .toml (the figure and the copy are <name>.svg, <name>.toml)
    source: bytes | None  # the scene file, copied beside the page (None: it could not be read)
    svg: str | None = None
    table: CheckTable | None = None  # its check: rows, verdicts, scales, notes
    warnings: tuple[str, ...] = ()  # the drawing's and the check's, each once
    error: str | None = None  # one line: why the scene failed


def entries(paths: Sequence[Path], workers: int | None = None) -> list[Entry]:
    """Draw and check each scene file as ``graphmech batch`` does (on a process pool), in order."""
    from graphmech import batch

    results = batch.run(batch.jobs([str(p) for p in paths], []), batch.Options(figure="svg", check=True), workers)
    return [entry(p, r) for p, r in zip(paths, results)]


def entry(path: Path, r: Result) -> Entry:
    """One scene's entry from its batch result (and its file, copied beside the page)."""
    name, file = path.name[:-5], path.name
    try:
        with open(path, "rb") as fh:
            source: bytes | None = fh.read(MAX_BYTES + 1)
    except OSError as e:
        source = None
        if r.error is None:
            r = replace(r, error=printable(f"{file}: cannot read the file ({e.strerror or e})"))
    if source is not None and len(source) > MAX_BYTES:  # refused as a scene: no copy of it either
        source = None
    t = r.table
    if r.error is not None or t is None or r.figure is None:
        return Entry(name, source, error=r.error or f"{file}: not made")
    return Entry(name, source, r.figure.decode("utf-8"), t, r.warnings)


def scene_files(folder: str | os.PathLike[str]) -> list[Path]:
    """The scenes of a gallery: ``folder/*.toml``, sorted by name (so the page is the same bytes on
    every file system); refused in one line when there is none."""
    where = Path(folder)
    if not where.is_dir():
        raise GraphmechError(f"{folder}: not a folder")
    files = sorted((p for p in where.glob("*.toml") if p.is_file()), key=lambda p: p.name)
    if not files:
        raise GraphmechError(f"{folder}: no scene files (*.toml) in it")
    return files


def _shown(text: object) -> str:
    """``text`` as the page shows it: a file name's undecodable bytes (surrogate escapes) as U+FFFD."""
    return str(text).encode("utf-8", "surrogateescape").decode("utf-8", "replace")


def _e(text: object) -> str:
    return html.escape(_shown(text), quote=True)


def _href(file: str) -> str:
    """A link to ``file``, its bytes percent-encoded as the file system has them."""
    return _e(quote(os.fsencode(file)))


def _anchor(name: str) -> str:
    """The id of a scene's section (the contents link to ``#`` and it, percent-encoded)."""
    return "scene-" + _shown(name)


def _check_table(t: CheckTable) -> list[str]:
    if not t.rows:
        return []
    head = ["quantity", "drawn mm", "μ", "graphical", "exact", "rel. error", "unit", "error source",
            "estimate"]
    out = ['<table class="check">', "<thead><tr>" + "".join(f"<th>{h}</th>" for h in head) + "</tr></thead>",
           "<tbody>"]
    for r in t.rows:
        drawn = "" if r.drawn_mm is None else f"{r.drawn_mm:.3f}"
        source = r.error_source + (" (ill-conditioned)" if r.ill_conditioned else "")
        cells = [(r.name, ""), (drawn, "n"), (f"{r.scale:.5g}", "n"), (f"{r.graphical:.9g}", "n"),
                 (f"{r.exact:.9g}", "n"), (f"{r.rel_error:.1e}", "n"), (r.unit, ""), (source, ""),
                 (estimate_text(r), "")]
        out.append("<tr>" + "".join(f'<td class="{c}">{_e(v)}</td>' if c else f"<td>{_e(v)}</td>"
                                    for v, c in cells) + "</tr>")
    out += ["</tbody>", "</table>"]
    return out


def _verdict_table(t: CheckTable) -> list[str]:
    if not t.measured:
        return []
    head = ["measured", "value", "expected", "± tol", "verdict", "unit"]
    out = ['<table class="measured">', "<thead><tr>" + "".join(f"<th>{h}</th>" for h in head) + "</tr></thead>",
           "<tbody>"]
    for v in t.measured:
        verdict = '<td>ok</td>' if v.ok else '<td class="bad">OUT OF TOLERANCE</td>'
        out.append(f'<tr><td>{_e(v.name)}</td><td class="n">{v.measured:.6g}</td><td class="n">{v.expected:.6g}'
                   f'</td><td class="n">{v.tolerance:.3g}</td>{verdict}<td>{_e(v.unit)}</td></tr>')
    out += ["</tbody>", "</table>"]
    return out


def _section(e: Entry) -> list[str]:
    heading = (e.table.title if e.table is not None else "") or e.name
    out = [f'<section id="{_e(_anchor(e.name))}">', f"<h2>{_e(heading)}</h2>"]
    links = [f'<a href="{_href(e.name + ".toml")}">{_e(e.name)}.toml</a>'] if e.source is not None else []
    if e.error is not None or e.table is None:
        out.append(f'<p class="failed">failed: {_e(e.error)}</p>')
    else:
        t = e.table
        links.append(f'<a href="{_href(e.name + ".svg")}">{_e(e.name)}.svg</a>')
        out.append(f'<figure><img src="{_href(e.name + ".svg")}" alt="{_e(heading)}"></figure>')
        if t.scale_notes:
            out.append(f'<p class="scales">{_e(" · ".join(t.scale_notes))}</p>')
        out += _check_table(t) + _verdict_table(t)
        if t.lines:
            out += ['<ul class="notes">', *(f"<li>{_e(n)}</li>" for n in t.lines), "</ul>"]
        if e.warnings:
            out += ['<ul class="warnings">', *(f"<li>warning: {_e(w)}</li>" for w in e.warnings), "</ul>"]
    if links:
        out.append(f'<p class="files">{"scene and figure" if len(links) > 1 else "scene"}: {" · ".join(links)}</p>')
    out.append("</section>")
    return out


def page(entries: Sequence[Entry], heading: str) -> str:
    """The gallery's index.html for ``entries`` (in that order)."""
    from graphmech.version import __version__

    failed = sum(e.error is not None for e in entries)
    count = f"{len(entries)} scene{'s' if len(entries) != 1 else ''}" + (f", {failed} failed" if failed else "")
    out = ["<!DOCTYPE html>", '<html lang="en">', "<head>", '<meta charset="utf-8">',
           '<meta name="viewport" content="width=device-width, initial-scale=1">',
           f'<meta name="generator" content="graphmech {_e(__version__)}">',
           f"<title>{_e(heading)}</title>", f"<style>{STYLE}</style>", "</head>", "<body>",
           f"<h1>{_e(heading)}</h1>", f"<p>{_e(count)}: each figure with its check — graphical against exact.</p>",
           '<nav><ul class="contents">']
    for e in entries:
        mark = ' <span class="failed">(failed)</span>' if e.error is not None else ""
        out.append(f'<li><a href="#{_e(quote(_anchor(e.name)))}">{_e(e.name)}</a>{mark}</li>')
    out.append("</ul></nav>")
    for e in entries:
        out += _section(e)
    out += ["</body>", "</html>", ""]
    return "\n".join(out)


def make_gallery(folder: str | os.PathLike[str], site: str | os.PathLike[str]) -> tuple[Path, list[Entry]]:
    """Write the gallery of ``folder``'s scenes into ``site`` (made if absent): index.html, each
    figure and each scene's copy. Returns the index's path and the entries (those with an
    ``error`` failed; the rest are written all the same)."""
    files = scene_files(folder)
    out = Path(site)
    if out.exists() and not out.is_dir():
        raise GraphmechError(f"{site}: is not a folder")
    made = entries(files)  # everything made, and the page, before anything is written
    text = page(made, f"graphmech gallery: {Path(folder).resolve().name}")
    out.mkdir(parents=True, exist_ok=True)
    for e in made:
        if e.source is not None:
            write_atomic(out / f"{e.name}.toml", e.source)
        if e.svg is not None:
            write_atomic(out / f"{e.name}.svg", e.svg)
    index = out / INDEX
    write_atomic(index, text)
    return index, made


__all__ = ["INDEX", "Entry", "entries", "entry", "make_gallery", "page", "scene_files"]
