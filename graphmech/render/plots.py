"""Plots of the benchmark: error and run time against n, one SVG per method; and, for each
discretised method (:func:`discretised_methods`), its error against its run time — what an n more
costs and what it buys.

This is the only module that uses matplotlib, and it imports it inside the function, so that
``graphmech render`` and ``graphmech check`` never load it. matplotlib is an extra
(``pip install "graphmech[plots]"``): without it the plots are refused in one line
(:class:`~graphmech.errors.GraphmechError`) and nothing is written. The SVG is deterministic: a fixed
hash salt for its ids, no date in its metadata, text drawn as paths.
"""
from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any

from graphmech.errors import GraphmechError
from graphmech.files import write_atomic

#: What a user without the extra is told (the command prints it and exits 2).
NEEDS_PLOTS = 'the log-log plots need matplotlib: pip install "graphmech[plots]"'

_MARKERS = ("o", "s", "^", "D", "v", "P", "X", "*")


#: Below this, a record's error is the round-off of an exact construction (polygons, closed
#: forms), whatever its n: no discretisation to show.
ROUND_OFF = 1e-12


def _file_name(method: str) -> str:
    return re.sub(r"[^A-Za-z0-9._-]+", "_", method).strip("._") or "method"


def error_time_plots(records: list[dict[str, Any]], out_dir: Path) -> list[Path]:
    """Per method, a log-log plot of ``max_rel_error`` and of ``seconds`` against ``n``.

    Parameters
    ----------
    records : list of dict
        Benchmark records ``{"method", "case", "n", "seconds", "max_rel_error", ...}``.
    out_dir : Path
        An existing folder; ``<method>.svg`` is written there for each method (characters other
        than letters, digits, ``.``, ``_`` and ``-`` replaced by ``_``).

    Returns
    -------
    list of Path
        The files written, in the order the methods first appear in ``records``.

    Notes
    -----
    One line per case. An error of exactly 0 or None (a record that measures steps, not accuracy),
    or a time ≤ 0, cannot be shown on a log axis: such points are left out and counted in the panel.
    The same records give byte-identical files.

    Raises
    ------
    GraphmechError
        matplotlib is not installed (the ``plots`` extra); nothing is written.
    """
    plt = _pyplot()

    out_dir = Path(out_dir)
    methods = list(dict.fromkeys(r["method"] for r in records))
    written: list[Path] = []
    with plt.rc_context(_RC):
        for method in methods:
            rows = [r for r in records if r["method"] == method]
            cases = list(dict.fromkeys(r["case"] for r in rows))
            fig, (ax_e, ax_t) = plt.subplots(1, 2, figsize=(10.0, 4.2), layout="constrained")
            left_out = {"max_rel_error": 0, "seconds": 0}
            for i, case in enumerate(cases):
                rs = sorted((r for r in rows if r["case"] == case), key=lambda r: r["n"])
                style = {"marker": _MARKERS[i % len(_MARKERS)], "markersize": 4.0, "linewidth": 1.2, "label": case}
                for ax, key, scale in ((ax_e, "max_rel_error", 1.0), (ax_t, "seconds", 1e3)):
                    pts = [(r["n"], r[key] * scale) for r in rs if r[key] is not None and r[key] > 0]
                    left_out[key] += len(rs) - len(pts)
                    if pts:
                        ax.plot([p[0] for p in pts], [p[1] for p in pts], **style)
            ax_e.set_title(f"{method}: largest relative error against n")
            ax_e.set_ylabel("largest relative error (dimensionless)")
            ax_t.set_title(f"{method}: run time against n (best of several runs)")
            ax_t.set_ylabel("time per run (ms)")
            for ax, key in ((ax_e, "max_rel_error"), (ax_t, "seconds")):
                ax.set_xscale("log")
                ax.set_yscale("log")
                ax.set_xlabel("n (positions or divisions per run, count)")
                ax.grid(True, which="major", linewidth=0.5, alpha=0.5)
                if left_out[key]:
                    what = "zero or no error" if key == "max_rel_error" else "no time"
                    ax.text(0.02, 0.02, f"{left_out[key]} point(s) with {what} not shown (log axis)",
                            transform=ax.transAxes, fontsize=7.0)
                if ax.lines:
                    ax.legend(fontsize=7.0, loc="best")
            _save(plt, fig, out_dir / _file_name(method), "svg", written)
    return written


def _positive(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) and v > 0


def _error(r: dict[str, Any]) -> float | None:
    """A record's error: its largest relative error against the exact solution, else its own
    estimate of it (``error_estimate``); None when it has neither to show on a log axis."""
    for key in ("max_rel_error", "error_estimate"):
        if _positive(r.get(key)):
            return float(r[key])
    return None


def _line(r: dict[str, Any]) -> str:
    """The line a record belongs to in its method's plot: its case, and its solver if it has one
    (the integrators' records sweep rtol, one line per solver)."""
    return r["case"] if r.get("solver") is None else f"{r['case']} {r['solver']}"


def _sweeps(records: list[dict[str, Any]], method: str) -> dict[str, list[dict[str, Any]]]:
    """The method's lines that sweep n: at least two different n with an error and a time to show,
    the largest error above :data:`ROUND_OFF`; each line's records by n."""
    lines: dict[str, list[dict[str, Any]]] = {}
    for r in records:
        if r["method"] == method and _error(r) is not None and _positive(r.get("seconds")):
            lines.setdefault(_line(r), []).append(r)
    return {k: sorted(rs, key=lambda r: r["n"]) for k, rs in lines.items()
            if len({r["n"] for r in rs}) >= 2 and max(_error(r) or 0.0 for r in rs) > ROUND_OFF}


def discretised_methods(records: list[dict[str, Any]]) -> list[str]:
    """The methods whose error depends on a discretisation: at least one case with two or more n
    (divisions, positions, points, steps), each with an error (``max_rel_error``, or else
    ``error_estimate``) and a time, not all at round-off; in the order they first appear.

    >>> rec = lambda m, n, e: {"method": m, "case": "c", "n": n, "seconds": 1e-3 * n, "max_rel_error": e}
    >>> discretised_methods([rec("cam", 24, 1e-2), rec("cam", 48, 2.5e-3), rec("polygons", 1, 4e-16),
    ...                      rec("polygons", 360, 5e-15), rec("sheet", 12, None)])
    ['cam']
    """
    return list(_discretised(records))


def _discretised(records: list[dict[str, Any]]) -> dict[str, dict[str, list[dict[str, Any]]]]:
    """Each discretised method's lines that sweep n (:func:`_sweeps`), in the order the methods
    first appear."""
    lines = {m: _sweeps(records, m) for m in dict.fromkeys(r["method"] for r in records)}
    return {m: sweeps for m, sweeps in lines.items() if sweeps}


def _tick(v: float, _: object = None) -> str:
    return f"{v:.4g}"


def _tick_2_5(v: float, _: object = None) -> str:
    return _tick(v) if v > 0 and round(v / 10.0 ** math.floor(math.log10(v) + 1e-9)) in (2, 5) else ""


def error_against_time_plots(records: list[dict[str, Any]], out_dir: Path, fmt: str = "svg") -> list[Path]:
    """Per discretised method (:func:`discretised_methods`), a log-log plot of its error against
    its run time: ``<method>-error-time.svg`` (or ``.png``: ``fmt``) in ``out_dir``.

    One line per case (and solver), its points labelled with their n, from the coarsest; the error
    is ``max_rel_error`` (else ``error_estimate``); where the records carry both, the estimate is a
    dashed line of the same colour beside the true error. Points with no error or no time are left
    out, and so are the lines of the method that sweep nothing. The same records give
    byte-identical SVG files.

    Raises
    ------
    GraphmechError
        matplotlib is not installed (the ``plots`` extra); nothing is written.
    """
    plt = _pyplot()
    from matplotlib.ticker import FuncFormatter, NullFormatter

    out_dir = Path(out_dir)
    written: list[Path] = []
    with plt.rc_context(_RC):
        for method, sweeps in _discretised(records).items():
            fig, ax = plt.subplots(figsize=(7.5, 5.0), layout="constrained")
            estimates = False
            for i, (name, rs) in enumerate(sweeps.items()):
                ms = [r["seconds"] * 1e3 for r in rs]
                errs = [_error(r) or 0.0 for r in rs]  # every one an error (_sweeps)
                (line,) = ax.plot(ms, errs, marker=_MARKERS[i % len(_MARKERS)], markersize=4.0, linewidth=1.2,
                                  label=name)
                for k, (r, x, y) in enumerate(zip(rs, ms, errs)):  # above and below in turn: neighbours apart
                    ax.annotate(f"{r['n']}", (x, y), textcoords="offset points", xytext=(4, 3 if k % 2 == 0 else -9),
                                fontsize=6.5, color=line.get_color())
                est = [(x, float(r["error_estimate"])) for r, x in zip(rs, ms)
                       if _positive(r.get("max_rel_error")) and _positive(r.get("error_estimate"))]
                if len(est) >= 2:
                    estimates = True
                    ax.plot([p[0] for p in est], [p[1] for p in est], linestyle="--", linewidth=0.9,
                            color=line.get_color())
            if estimates:  # one legend entry for them all
                ax.plot([], [], linestyle="--", linewidth=0.9, color="0.35", label="dashed: the method's own estimate")
            ax.set_xscale("log")
            ax.set_yscale("log")
            for axis, (lo, hi) in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
                axis.set_major_formatter(FuncFormatter(_tick))  # 0.6, not 6×10⁻¹
                # the minor ticks labelled where few decades leave few major ones: all within one, 2 and 5 within two
                minor = _tick if hi < 10.0 * lo else _tick_2_5 if hi < 100.0 * lo else None
                axis.set_minor_formatter(FuncFormatter(minor) if minor else NullFormatter())
            ax.set_title(f"{method}: error against run time (points labelled with n)")
            ax.set_xlabel("time per run (ms, best of several runs)")
            ax.set_ylabel("largest relative error (dimensionless)")
            ax.grid(True, which="major", linewidth=0.5, alpha=0.5)
            ax.legend(fontsize=7.0, loc="best")
            _save(plt, fig, out_dir / f"{_file_name(method)}-error-time", fmt, written)
    return written


#: matplotlib's settings for every plot (a fixed hash salt: the same records give the same SVG bytes).
_RC = {"svg.hashsalt": "graphmech", "svg.fonttype": "path", "font.size": 9.0}


def _pyplot() -> Any:
    """matplotlib's pyplot on the Agg backend; GraphmechError where the ``plots`` extra is missing."""
    try:
        import matplotlib
    except ImportError as e:
        raise GraphmechError(NEEDS_PLOTS) from e

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _save(plt: Any, fig: Any, stem: Path, fmt: str, written: list[Path]) -> None:
    """Write ``fig`` as stem.fmt (a name already written this run gets a ``_``: two methods spelt
    alike after cleaning), atomically, and close it."""
    import io

    buf = io.BytesIO()
    fig.savefig(buf, format=fmt, **({"metadata": {"Date": None}} if fmt == "svg" else {}))
    plt.close(fig)
    while stem.with_name(f"{stem.name}.{fmt}") in written:
        stem = stem.with_name(stem.name + "_")
    path = stem.with_name(f"{stem.name}.{fmt}")
    write_atomic(path, buf.getvalue())
    written.append(path)
