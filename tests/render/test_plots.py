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


@pytest.fixture(scope="module")
def plotted(tmp_path_factory: pytest.TempPathFactory):
    """The files written and the figures drawn (plt.close held back until the test is done)."""
    import matplotlib.pyplot as plt

    figures = []
    out = tmp_path_factory.mktemp("plots")
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(plt, "close", figures.append)
        paths = error_time_plots(RECORDS, out)
    yield out, paths, figures
    for fig in figures:
        plt.close(fig)


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
