"""Plots of the benchmark: error and run time against n, one SVG per method.

This is the only module that uses matplotlib, and it imports it inside the function, so that
``graphmech render`` and ``graphmech check`` never load it. matplotlib is an extra
(``pip install "graphmech[plots]"``): without it the plots are refused in one line
(:class:`~graphmech.errors.GraphmechError`) and nothing is written. The SVG is deterministic: a fixed
hash salt for its ids, no date in its metadata, text drawn as paths.
"""
from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from graphmech.errors import GraphmechError
from graphmech.files import write_atomic

#: What a user without the extra is told (the command prints it and exits 2).
NEEDS_PLOTS = 'the log-log plots need matplotlib: pip install "graphmech[plots]"'

_MARKERS = ("o", "s", "^", "D", "v", "P", "X", "*")


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
    import io

    try:
        import matplotlib
    except ImportError as e:
        raise GraphmechError(NEEDS_PLOTS) from e

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out_dir = Path(out_dir)
    methods = list(dict.fromkeys(r["method"] for r in records))
    written: list[Path] = []
    with plt.rc_context({"svg.hashsalt": "graphmech", "svg.fonttype": "path", "font.size": 9.0}):
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
            buf = io.BytesIO()
            fig.savefig(buf, format="svg", metadata={"Date": None})
            plt.close(fig)
            name = _file_name(method)
            while out_dir / f"{name}.svg" in written:  # two methods spelt alike after cleaning
                name += "_"
            path = out_dir / f"{name}.svg"
            write_atomic(path, buf.getvalue())
            written.append(path)
    return written
