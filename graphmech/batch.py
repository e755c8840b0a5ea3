"""Many figures and checks at once: scenes × variants, on a process pool.

A :class:`Job` is one scene file with one variant (:mod:`graphmech.variants`); :func:`make` does
one job — loads, varies, draws (SVG, PDF or PNG) and checks — and returns what it would write,
or its one-line error, never raising; :func:`run` does many on all cores, results in job order.
The caller writes: ``render`` writes nothing unless every job succeeded; ``batch`` writes every
job that succeeded (each all-or-nothing) and reports the others in one line each.
"""
from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from graphmech.api import CheckTable, Problem, load
from graphmech.errors import GraphmechError, one_line, printable
from graphmech.variants import Assignment, value_text, variant_name

if TYPE_CHECKING:
    from graphmech.render.chromium import Browser

#: Fewer jobs than this are done in this process: a pool's start costs more than it gives.
POOL_FROM = 4


@dataclass(frozen=True)
class Job:
    """One scene file with one variant of it (``{}``: the scene as written), on ``page``."""

    scene: str
    variant: Assignment = field(default_factory=dict)
    page: str | None = None

    @property
    def file(self) -> str:
        return Path(self.scene).name

    @property
    def name(self) -> str:
        """The stem of the files it writes: ``crank`` or ``crank-driver.angle=30`` (its problem's name)."""
        return variant_name(Path(self.scene).stem, self.variant)

    @property
    def label(self) -> str:
        """The job as messages name it: ``crank.toml`` or ``crank.toml [driver.angle=30]``."""
        return self._with_values(self.file)

    def _with_values(self, head: str) -> str:
        if not self.variant:
            return head
        return f"{head} [{', '.join(f'{k}={value_text(v)}' for k, v in self.variant.items())}]"


def jobs(scenes: Iterable[str], variants: Sequence[Assignment], page: str | None = None) -> list[Job]:
    """Every scene with every variant, scene by scene."""
    return [Job(s, v, page) for s in scenes for v in (variants or [{}])]


def distinct_names(todo: Iterable[Job]) -> None:
    """Refuse (one line) jobs that would write the same files — one scene given twice, two
    ``crank.toml`` in two folders, values that name alike (``30`` and ``30.0``) — before any is
    done: else the last would silently replace the others."""
    first: dict[str, Job] = {}
    for job in todo:
        other = first.setdefault(job.name, job)
        if other is not job:
            raise GraphmechError(f"{other._with_values(other.scene)} and {job._with_values(job.scene)} would both "
                                 f"be written as {job.name}: give each its own file name or values")


@dataclass(frozen=True)
class Options:
    """What each job makes: a figure in ``figure`` format (None: none) at ``dpi``; the check
    (with ``measured`` values judged at ``precision`` mm) when ``check``."""

    figure: str | None = "svg"
    dpi: float | None = None
    check: bool = False
    measured: tuple[tuple[str, float], ...] = ()
    precision: float | None = None


@dataclass(frozen=True)
class Result:
    """What one job made: its ``name`` (the file stem of its outputs), the figure's bytes, the
    check table, the warnings — or ``error``, the one line saying why it could not be made."""

    job: Job
    name: str = ""
    figure: bytes | None = None
    table: CheckTable | None = None
    warnings: tuple[str, ...] = ()
    error: str | None = None

    @property
    def ok(self) -> bool:
        return self.error is None


def problem(job: Job) -> Problem:
    """The job's problem: the file, on its page, with its variant's values."""
    p = load(job.scene, job.page)
    return p.replace(job.variant) if job.variant else p


def make(job: Job, options: Options) -> Result:
    """Do one job; a refusal (bad scene, bad key path, a construction that cannot be made, an
    unreadable file, a missing browser) is the result's ``error``, never an exception."""
    try:
        p = problem(job)
        figure: bytes | None = None
        warnings: tuple[str, ...] = ()
        if options.figure is not None:
            drawing = p.render()
            warnings = drawing.warnings
            figure = _convert(drawing.svg, options.figure, options.dpi)
        table = p.check(options.measured, options.precision) if options.check else None
        if table is not None:  # the drawing's and the check's, each once
            warnings = tuple(dict.fromkeys([*warnings, *table.warnings]))
        return Result(job, p.name, figure, table, tuple(warnings))
    except GraphmechError as e:  # the file named once, with the variant: "x.toml [driver.angle=30]: …"
        line = one_line(e, job.file)
        return Result(job, error=job.label + line[len(job.file):] if line.startswith(job.file + ": ") else line)
    except OSError as e:
        return Result(job, error=f"{job.label}: {e.filename or ''}{': ' if e.filename else ''}{e.strerror or e}")
    except RecursionError:
        return Result(job, error=f"{job.label}: nested too deeply")
    except Exception as e:  # a bug of ours: this job fails in one line, the others are still made
        return Result(job, error=printable(f"{job.label}: internal error ({type(e).__name__}: {e}); "
                                           "please report it with the scene"))


def _convert(svg: str, fmt: str, dpi: float | None) -> bytes:
    if fmt == "svg":  # no browser needed
        return svg.encode("utf-8")
    from graphmech.render.export import DPI, convert

    return convert(svg, fmt, DPI if dpi is None else dpi, _browser())


#: This process's headless Chromium, started for its first PDF or PNG and kept for the rest:
#: one per worker, not one per figure (a start costs about a second).
_BROWSER: list[Browser] = []


def _browser() -> Browser:
    from graphmech.render.chromium import Browser

    if _BROWSER and _BROWSER[0].alive:
        return _BROWSER[0]
    _close_browser()
    _BROWSER.append(Browser())
    import multiprocessing.util

    if multiprocessing.parent_process() is not None:  # a pool's worker: closed when it exits
        multiprocessing.util.Finalize(None, _close_browser, exitpriority=10)
    return _BROWSER[0]


def _close_browser() -> None:
    while _BROWSER:
        _BROWSER.pop().close()


def run(todo: Sequence[Job], options: Options, workers: int | None = None,
        done: Callable[[Result], None] | None = None) -> list[Result]:
    """Every job, in order; on a pool of ``workers`` processes (default: all cores) when there
    are enough of them. ``done`` is called with each result as it comes, in order."""
    workers = max(1, min(workers or os.cpu_count() or 1, len(todo)))
    results: list[Result] = []
    if workers == 1 or len(todo) < POOL_FROM:
        try:
            for job in todo:
                results.append(make(job, options))
                if done is not None:
                    done(results[-1])
        finally:
            _close_browser()
        return results
    from concurrent.futures import ProcessPoolExecutor  # only for a pool: a single check starts faster

    # one job at a time: a worker takes the next as soon as it is free, so one slow scene (a
    # flywheel's true motion, seconds) does not hold back a chunk of others behind it
    with ProcessPoolExecutor(max_workers=workers) as pool:
        for result in pool.map(make, todo, [options] * len(todo)):
            results.append(result)
            if done is not None:
                done(result)
    return results


def variants_table(results: Sequence[Result]) -> str:
    """The check of many variants, one row per variant, one column per quantity (the graphical
    value; ``check --json`` has everything): a teacher's answer key; then each variant's verdicts
    on the measured values, if any were given."""
    tables = [(r.name, r.table) for r in results if r.table is not None]
    names: list[str] = []
    units: dict[str, str] = {}
    for _, t in tables:
        for row in t:
            if row.name not in units:
                names.append(row.name)
                units[row.name] = row.unit
    width = max([len("variant"), *(len(n) for n, _ in tables)])
    heads = [f"{n} ({units[n]})" if units[n] else n for n in names]
    cols = [max(12, len(h)) for h in heads]
    lines = ["  ".join([f"{'variant':<{width}}", *(f"{h:>{c}}" for h, c in zip(heads, cols))])]
    for name, t in tables:
        by = {row.name: row for row in t}
        cells = [f"{by[n].graphical:>{c}.6g}" if n in by else f"{'':>{c}}" for n, c in zip(names, cols)]
        lines.append("  ".join([f"{name:<{width}}", *cells]))
    for name, t in tables:  # the verdicts on measured values, under the variant they judge
        if t.measured:
            lines += ["", f"{name}:", *t.verdict_lines()]
    return "\n".join(lines)


def check_documents(results: Sequence[Result]) -> list[dict[str, Any]]:
    """``check --json`` of each variant, with its name and values."""
    return [{"name": r.name, **r.table.to_dict()} for r in results if r.table is not None]


__all__ = ["POOL_FROM", "Job", "Options", "Result", "check_documents", "distinct_names", "jobs", "make", "problem", "run",
           "variants_table"]
