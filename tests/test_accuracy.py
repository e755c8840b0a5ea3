"""Every row of every reference scene says how accurate it is, and the methods' own error
estimates are honest: within a factor of ten of the true error wherever that exceeds 1e-10,
and below 1e-8 where the true error is round-off (graphmech/accuracy.py)."""
from __future__ import annotations

import math

import pytest

from graphmech.accuracy import CONSTRUCTION, SOURCES, estimate_from_three, observed_order, relative, richardson
from graphmech.problems.cam.check import PROFILE_DEVIATION
from tests.conftest import SCENES, check_json

REFERENCE_SCENES = sorted(SCENES.glob("*.toml"))


def test_richardson_recovers_the_error_of_a_second_order_method():
    # v(N) = v* + C/N²: the estimate of v(N)'s error is exact
    exact, c = 1.0, 3.0
    v = {n: exact + c / n**2 for n in (12, 24, 48)}
    assert richardson(v[12], v[24], 2) == pytest.approx(c / 144, rel=1e-12)
    assert estimate_from_three(v[12], v[24], v[48]) == pytest.approx(c / 144, rel=1e-9)
    # a first-order one (a maximum sampled at a kink) is seen as first order
    w = {n: exact + c / n for n in (12, 24, 48)}
    assert observed_order(w[12], w[24], w[48]) == pytest.approx(1.0, rel=1e-12)
    assert estimate_from_three(w[12], w[24], w[48]) == pytest.approx(c / 12, rel=1e-9)
    assert relative(math.inf, 2.0) == math.inf and relative(math.nan, 0.0) == math.inf
    assert relative(1.0, 0.0) == 1.0 and relative(1.0, 4.0) == 0.25


@pytest.mark.parametrize("path", REFERENCE_SCENES, ids=lambda p: p.stem)
def test_every_row_says_how_accurate_it_is(path):
    doc = check_json(path)
    for q in doc["quantities"]:
        assert q["error_source"] in SOURCES, q
        if q["error_source"] == CONSTRUCTION:  # exact but for round-off, or it says it is not
            assert q["error_estimate"] is None, q
            assert q["rel_error"] < 1e-9 or q["ill_conditioned"], q
            continue
        est, true = q["error_estimate"], q["rel_error"]
        assert est is not None and math.isfinite(est) and est >= 0 and q["basis"], q
        if q["name"] == PROFILE_DEVIATION:  # a distance to the exact profile: its value is its error
            continue
        if true > 1e-10:
            assert 0.1 <= est / true <= 10, (q["name"], est, true)
        else:
            assert est < 1e-8, (q["name"], est, true)


def test_the_reference_scenes_have_discretised_rows_to_judge():
    """Flywheels from N positions, cycle diagrams by chords and cams read at their divisions are
    not constructions: the test above judges their estimates on these scenes."""
    sources = {}
    for path in REFERENCE_SCENES:
        if path.stem.split(".")[0] in ("fly", "cam", "linkage"):
            for q in check_json(path)["quantities"]:
                sources.setdefault(path.stem.split(".")[0], set()).add(q["error_source"])
    assert all(len(s - {CONSTRUCTION}) >= 1 for s in sources.values()), sources


def test_a_drawing_does_not_pay_for_the_error_estimates(monkeypatch, tmp_path):
    """The estimates redo the work at 2N, 4N (8N) positions or divisions: only `check` asks for them."""
    from graphmech.problems.cam import check as cam_check
    from graphmech.problems.flywheel import check as flywheel_check
    from tests.conftest import run_cli

    def refuse(*args, **kwargs):
        raise AssertionError("an error estimate was computed for a drawing")

    monkeypatch.setattr(flywheel_check, "_estimate", refuse)
    monkeypatch.setattr(cam_check, "_estimated", refuse)
    for scene in ("fly.compressor_course_project", "cam.offset_roller_translating-pos"):
        code, _, err = run_cli("render", str(SCENES / f"{scene}.toml"), "-o", str(tmp_path / "x.svg"))
        assert code == 0, err
        code, _, err = run_cli("check", str(SCENES / f"{scene}.toml"))
        assert code == 3 and "an error estimate was computed" in err  # check does compute them
