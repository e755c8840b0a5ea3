"""The polygons' benchmark (graphmech/problems/linkage/bench.py): its four-bar, the closed-form
yardstick it is timed against, and records whose errors are those of exact constructions. No
assertion on speed."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.exact.linkage import solve
from graphmech.problems.linkage.bench import FOURBAR_QUANTITIES, bench, closed_form_fourbar, fourbar, polygon_records


def test_the_benchmarks_four_bar():
    lk = fourbar()
    assert lk.frame_points == {"A": (0.0, 0.0), "D": (0.12, 0.0)}
    assert (lk.driver.length, lk.driver.omega) == (0.06, 10.0)
    assert lk.dyads[0].lengths == (0.12, 0.09) and lk.dyads[0].branch == "left"


def test_the_closed_form_agrees_with_the_exact_solution_over_a_turn():
    phi = np.radians(np.arange(0.0, 360.0, 7.5))
    ref = closed_form_fourbar(phi)
    kin = solve(fourbar(), phi)
    assert kin.valid.all()
    np.testing.assert_allclose(ref["omega_2"], kin.omega["2"], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(ref["omega_3"], kin.omega["3"], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(ref["alpha_3"], kin.alpha["3"], rtol=1e-10, atol=1e-10)
    np.testing.assert_allclose(ref["v_C"], np.hypot(*kin.vel["C"].T), rtol=1e-12, atol=1e-14)
    assert set(ref) == set(FOURBAR_QUANTITIES)


def test_the_closed_form_keeps_the_velocity_projection_theorem():
    """φ = 0: B at (60, 0) mm moving straight up at ω₁·AB = 0.6 m/s; C from the triangle BCD (120, 90,
    BD = 60). The components of v_B and v_C along BC are equal (the coupler is rigid)."""
    ref = closed_form_fourbar(np.array([0.0]))
    beta = math.acos((0.12 ** 2 + 0.06 ** 2 - 0.09 ** 2) / (2 * 0.12 * 0.06))
    c = (0.06 + 0.12 * math.cos(beta), 0.12 * math.sin(beta))
    w3 = float(ref["omega_3"][0])
    v_c = (-w3 * c[1], w3 * (c[0] - 0.12))  # ω3 × DC
    u = ((c[0] - 0.06) / 0.12, c[1] / 0.12)
    assert ref["v_B"][0] == pytest.approx(0.6)
    assert 0.6 * u[1] == pytest.approx(v_c[0] * u[0] + v_c[1] * u[1], rel=1e-12)
    assert ref["v_C"][0] == pytest.approx(math.hypot(*v_c), rel=1e-12)


@pytest.fixture(scope="module")
def records():
    return polygon_records(repeat=1)


def test_the_polygons_records_are_exact_constructions(records):
    assert [(r["method"], r["n"]) for r in records] == [("polygons", 1), ("polygons", 360),
                                                        ("closed-form-numpy", 360)]
    assert all(r["case"] == "fourbar-120-60-120-90" and r["seconds"] > 0 for r in records)
    assert records[0]["max_rel_error"] < 1e-13 and records[1]["max_rel_error"] < 1e-12
    assert records[2]["max_rel_error"] < 1e-10


def test_the_notes_compare_with_the_targets():
    records, notes = bench(quick=True)
    assert len(records) == 3 and len(notes) == 3
    assert notes[0].startswith("one position: ") and notes[0].endswith("µs (target < 25 µs)")
    assert "the plain closed-form numpy solution" in notes[1] and notes[1].endswith("target ≤ 3×)")
    assert notes[2].startswith("agreement: ") and notes[2].endswith("(target ≤ 1e-12)")
