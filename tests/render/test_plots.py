"""The benchmark's plots: one SVG per method, what each panel shows (figures caught before they
are closed) and what is left off a log axis. Byte-stability is tested with the cam bench
(tests/problems/cam/test_bench.py)."""
from __future__ import annotations

import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from graphmech.render.plots import _file_name, error_time_plots


def record(method: str, case: str, n: int, error: float | None, seconds: float | None) -> dict:
    return {"method": method, "case": case, "n": n, "max_rel_error": error, "seconds": seconds}


RECORDS = [
    record("cam inversion/v2", "a", 100, 1e-5, 1e-3),  # out of order: sorted by n
    record("cam inversion/v2", "a", 10, 1e-3, 1e-4),
    record("cam inversion/v2", "a", 1000, 0.0, 1e-2),  # an exact 0 cannot go on a log axis
    record("cam inversion/v2", "b", 10, 1e-2, 2e-4),
    record("cam inversion/v2", "b", 100, 1e-4, None),
    record("cam/inversion v2", "a", 10, None, 0.0),   # spelt like the first once cleaned; nothing to show
]


def _drawn(plots, records, out):
    """Run a plotting function with plt.close held back: yields (out, the files written, the
    figures drawn), closing the figures once the tests are done with them."""
    import matplotlib.pyplot as plt

    figures = []
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(plt, "close", figures.append)
        paths = plots(records, out)
    yield out, paths, figures
    for fig in figures:
        plt.close(fig)


@pytest.fixture(scope="module")
def plotted(tmp_path_factory: pytest.TempPathFactory):
    """The files written and the figures drawn by error_time_plots."""
    yield from _drawn(error_time_plots, RECORDS, tmp_path_factory.mktemp("plots"))


def test_one_svg_per_method_named_safely_in_order(plotted) -> None:
    out, paths, figures = plotted
    assert [p.name for p in paths] == ["cam_inversion_v2.svg", "cam_inversion_v2_.svg"]
    assert len(figures) == 2
    for p in paths:
        assert p.parent == out and ET.parse(p).getroot().tag.endswith("svg")
    assert "<dc:date>" not in paths[0].read_text(encoding="utf-8")


def test_each_case_is_a_line_on_log_axes_without_the_points_a_log_axis_cannot_show(plotted) -> None:
    ax_e, ax_t = plotted[2][0].axes
    assert [ax.get_xscale() for ax in (ax_e, ax_t)] == ["log", "log"]
    assert [ax.get_yscale() for ax in (ax_e, ax_t)] == ["log", "log"]
    assert "cam inversion/v2" in ax_e.get_title() and "error" in ax_e.get_title()
    a, b = ax_e.lines
    assert (a.get_label(), list(a.get_xdata()), list(a.get_ydata())) == ("a", [10, 100], [1e-3, 1e-5])
    assert list(b.get_ydata()) == [1e-2, 1e-4]
    ta, tb = ax_t.lines
    assert list(ta.get_ydata()) == pytest.approx([0.1, 1.0, 10.0])  # ms
    assert (list(tb.get_xdata()), list(tb.get_ydata())) == ([10], pytest.approx([0.2]))
    assert [t.get_text() for t in ax_e.texts] == ["1 point(s) with zero or no error not shown (log axis)"]
    assert [t.get_text() for t in ax_t.texts] == ["1 point(s) with no time not shown (log axis)"]
    assert [t.get_text() for t in ax_e.get_legend().get_texts()] == ["a", "b"]


def test_a_method_with_nothing_to_show_has_empty_panels_and_no_legend(plotted) -> None:
    ax_e, ax_t = plotted[2][1].axes
    assert len(ax_e.lines) == len(ax_t.lines) == 0
    assert ax_e.get_legend() is None and ax_t.get_legend() is None
    assert [t.get_text() for t in ax_t.texts] == ["1 point(s) with no time not shown (log axis)"]


def test_no_records_write_nothing(tmp_path: Path) -> None:
    assert error_time_plots([], tmp_path) == []
    assert list(tmp_path.iterdir()) == []


def test_file_names_keep_letters_digits_dots_dashes() -> None:
    assert _file_name("four-bar 1.2 (exact)") == "four-bar_1.2_exact"  # and no "_" left at the ends
    assert _file_name("runs/four-bar") == "runs_four-bar"  # never a path into another folder
    assert _file_name("...") == _file_name("") == "method"


def test_without_matplotlib_the_plots_are_refused_in_one_line_and_nothing_is_written(tmp_path, monkeypatch) -> None:
    """matplotlib is the plots extra: an install without it gets one line saying what to install."""
    from graphmech.errors import GraphmechError

    monkeypatch.setitem(sys.modules, "matplotlib", None)  # `import matplotlib` now raises ImportError
    with pytest.raises(GraphmechError) as refused:
        error_time_plots(RECORDS, tmp_path)
    assert str(refused.value) == 'the log-log plots need matplotlib: pip install "graphmech[plots]"'
    assert isinstance(refused.value.__cause__, ImportError)
    assert list(tmp_path.iterdir()) == []


# ---------------------------------------------------------------------------- error against time

def swept(method: str, case: str, ns, errors, *, solver: str | None = None, estimates=None) -> list[dict]:
    out = []
    for k, (n, e) in enumerate(zip(ns, errors)):
        r = record(method, case, n, e, 1e-4 * (k + 1))
        if solver is not None:
            r["solver"] = solver
        if estimates is not None:
            r["error_estimate"] = estimates[k]
        out.append(r)
    return out


SWEEPS = [
    *swept("cam-inversion", "roller", [24, 48, 96], [1e-2, 2.5e-3, 6e-4]),
    *swept("cam-inversion", "flat", [24, 48], [8e-3, 2e-3]),
    *swept("wittenbauer", "exact", [12, 72, 360], [7.8e-2, 1.2e-3, 5e-5], estimates=[8.4e-2, 1.3e-3, 7.1e-5]),
    *swept("graphical-differentiation", "v", [12, 36], [None, None], estimates=[1.7e-2, 1.9e-3]),  # its estimate only
    *swept("true-motion", "stiff", [45, 135], [7e-3, 7e-8], solver="Radau"),
    *swept("true-motion", "stiff", [103, 393], [2e-1, 3e-10], solver="BDF"),
    *swept("involute", "z20", [4, 8], [1.3e-2, 0.0]),  # one point left: no sweep
    *swept("polygons", "fourbar", [1, 360], [3.7e-16, 4.7e-15]),  # round-off at every n: exact
    *swept("force-polygon", "incline", [10, 100, 1000], [0.0, 0.0, 0.0]),
    record("full-cycle-sheet", "sheet-12", 12, None, 0.2),
    record("reference-scenes", "all-examples", 131, None, 12.0),
    *swept("rack-generation", "z15", [4, 8], [1.6e-2, 4.8e-3]),
    *swept("rack-generation", "z15", [16], [1.4e-3]),
]


def test_the_discretised_methods_are_those_with_an_error_that_sweeps_n() -> None:
    from graphmech.render.plots import discretised_methods

    assert discretised_methods(SWEEPS) == ["cam-inversion", "wittenbauer", "graphical-differentiation", "true-motion",
                                           "rack-generation"]
    assert discretised_methods([]) == []


@pytest.fixture(scope="module")
def error_time(tmp_path_factory: pytest.TempPathFactory):
    """The files written and the figures drawn by error_against_time_plots."""
    from graphmech.render.plots import error_against_time_plots

    yield from _drawn(error_against_time_plots, SWEEPS, tmp_path_factory.mktemp("error-time"))


def test_every_discretised_method_and_only_those_gets_an_error_time_plot(error_time) -> None:
    from graphmech.render.plots import discretised_methods

    out, paths, figures = error_time
    plotted = {fig.axes[0].get_title().split(":")[0] for fig in figures}
    assert plotted == set(discretised_methods(SWEEPS))
    assert [p.name for p in paths] == [f"{m}-error-time.svg" for m in discretised_methods(SWEEPS)]
    for p in paths:
        assert p.parent == out and ET.parse(p).getroot().tag.endswith("svg")


def test_error_against_time_one_line_per_case_points_labelled_with_n(error_time) -> None:
    _, _, figures = error_time
    by = {fig.axes[0].get_title().split(":")[0]: fig.axes[0] for fig in figures}
    cam = by["cam-inversion"]
    assert (cam.get_xscale(), cam.get_yscale()) == ("log", "log")
    assert "time" in cam.get_xlabel() and "error" in cam.get_ylabel()
    roller, flat = cam.lines
    assert roller.get_label() == "roller" and flat.get_label() == "flat"
    assert list(roller.get_xdata()) == pytest.approx([0.1, 0.2, 0.3])  # ms, on x
    assert list(roller.get_ydata()) == [1e-2, 2.5e-3, 6e-4]  # the error, on y
    assert [t.get_text() for t in cam.texts] == ["24", "48", "96", "24", "48"]  # each point's n
    # the method's own estimate, dashed beside the true error; an estimate alone stands for the error
    w = by["wittenbauer"]
    assert [ln.get_linestyle() for ln in w.lines if ln.get_xdata().size] == ["-", "--"]
    assert list(w.lines[1].get_ydata()) == [8.4e-2, 1.3e-3, 7.1e-5]
    assert list(by["graphical-differentiation"].lines[0].get_ydata()) == [1.7e-2, 1.9e-3]
    # the integrators: one line per solver; cases split across records still make one line
    assert [ln.get_label() for ln in by["true-motion"].lines] == ["stiff Radau", "stiff BDF"]
    assert list(by["rack-generation"].lines[0].get_xdata()) == pytest.approx([0.1, 0.2, 0.1])  # sorted by n
    assert [t.get_text() for t in by["rack-generation"].texts] == ["4", "8", "16"]


def test_error_against_time_plots_are_byte_stable(tmp_path: Path) -> None:
    from graphmech.render.plots import error_against_time_plots

    a, b = tmp_path / "a", tmp_path / "b"
    a.mkdir()
    b.mkdir()
    pa, pb = error_against_time_plots(SWEEPS, a), error_against_time_plots(SWEEPS, b)
    assert [p.read_bytes() for p in pa] == [p.read_bytes() for p in pb]
    exact = [r for r in SWEEPS if r["method"] in ("involute", "polygons", "force-polygon", "full-cycle-sheet")]
    assert error_against_time_plots(exact, tmp_path) == []  # nothing discretised: nothing written
