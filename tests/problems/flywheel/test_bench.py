"""The flywheel benchmark's parts (speed is measured by the bench, never here): the compressor it
runs on, the Wittenbauer sweep's records and the one-line notes made of them."""
from __future__ import annotations

import math

import pytest

from graphmech.mechanisms.machine import Motor, SliderLoad
from graphmech.problems.flywheel.bench import (SOLVERS, compressor_machine, true_motion_notes,
                                               wittenbauer_records)


def test_the_compressor_is_the_course_projects():
    """Crank 75 mm, rod 300 mm, offset 10 mm, 960 rpm; position 1 the outer dead centre asin(e/(l1 + l2))."""
    m = compressor_machine()
    assert m.start == pytest.approx(math.asin(0.010 / 0.375), rel=1e-15)
    assert math.degrees(m.start) == pytest.approx(1.5280685946107546, rel=1e-12)
    assert m.omega_m == pytest.approx(32 * math.pi, rel=1e-15) and (m.delta, m.cycle) == (0.04, 2 * math.pi)
    assert [(s.link, s.point, s.mass, s.inertia) for s in m.masses] == [
        ("1", "A", 0.0, 0.05), ("2", "S2", 3.0, 0.025), ("3", "C", 4.5, 0.0)]
    (load,) = m.loads
    assert isinstance(load, SliderLoad) and (load.sense, load.during) == (-1, "forward")
    assert load.table.y[-1] == pytest.approx(0.5e6 * math.pi * 0.12 ** 2 / 4, rel=1e-15)  # 0.5 MPa, bore 120 mm
    assert m.motor is None and compressor_machine(Motor(stiffness=1e5)).motor == Motor(stiffness=1e5)


@pytest.fixture(scope="module")
def sweep():
    return wittenbauer_records(repeat=1, ns=(12, 24))


def test_the_wittenbauer_records_at_twelve_positions_are_the_course_projects(sweep, problems):
    ref = problems["fly.compressor_course_project"]["exact"]
    by = {(r["case"], r["n"]): r for r in sweep}
    assert set(by) == {(c, n) for c in ("compressor-exact", "compressor-book", "compressor-indicator")
                       for n in (12, 24)}
    assert by[("compressor-exact", 12)]["J_F"] == pytest.approx(ref["JF_12pos_trapz_kgm2"], rel=1e-9)
    for r in sweep:
        assert r["method"] == ("energy-indicator" if r["case"] == "compressor-indicator" else "wittenbauer")
        assert r["max_rel_error"] == pytest.approx(abs(r["J_F"] - r["J_F_exact"]) / r["J_F_exact"], rel=1e-12)
        assert r["seconds"] > 0
    # twice the positions: the error falls about fourfold (chords), and the estimate follows it
    for case in ("compressor-exact", "compressor-book", "compressor-indicator"):
        coarse, fine = by[(case, 12)], by[(case, 24)]
        assert 3.0 < coarse["max_rel_error"] / fine["max_rel_error"] < 7.0
        assert 0.5 < fine["error_estimate"] / fine["max_rel_error"] < 2.0
        assert coarse["J_F_exact"] == fine["J_F_exact"]


def test_the_notes_name_the_stiff_radau_solve_and_rk45s_steps():
    radau = {"method": "true-motion", "case": "compressor-stiff-1e5", "solver": "Radau", "rtol": 1e-10,
             "seconds": 0.042, "n": 150, "cycles": 3}
    rk45 = {"method": "true-motion-explicit", "case": "compressor-stiff-1e5", "solver": "RK45", "rtol": 1e-10,
            "n": 30000, "note": "one whole cycle from the periodic ω0"}
    assert true_motion_notes([radau, rk45]) == [
        "stiff periodic solve, Radau rtol 1e-10: 42 ms (target < 100 ms), 150 steps/cycle, 3 cycles",
        "RK45 needs 30000 steps for one stiff cycle = 200× Radau's (one whole cycle from the periodic ω0)"]
    # quick mode has no 1e-10 run: the note falls back to 1e-8; without a stiff Radau run, no note
    quick = dict(radau, rtol=1e-8)
    assert true_motion_notes([quick])[0].startswith("stiff periodic solve, Radau rtol 1e-08")
    assert true_motion_notes([dict(radau, solver="BDF")]) == []
    assert "Radau" in SOLVERS


def test_the_flywheel_bench_sweep_estimates_its_own_error():
    """J_F of the compressor from N = 12 … 3600 positions: the pipeline's estimate of its own error
    (the same work at 2N and 4N) within a factor of ten of the true error (measured 0.92 … 1.41)."""
    records = wittenbauer_records(repeat=1)
    assert {r["n"] for r in records} == {12, 24, 36, 72, 360, 3600}
    assert {r["case"] for r in records} == {"compressor-exact", "compressor-book", "compressor-indicator"}
    for r in records:
        assert r["max_rel_error"] > 1e-10  # a discretised value at every N of the sweep
        assert 0.5 <= r["error_estimate"] / r["max_rel_error"] <= 2, r


def test_the_explicit_record_counts_rk45s_steps_on_the_stiff_cycle():
    """graphmech bench --explicit: RK45's accepted steps (quick: extrapolated from twelve 1° windows)
    are far more than the stiff solvers' hundred-odd a cycle."""
    from graphmech.problems.flywheel.bench import explicit_record

    r = explicit_record(quick=True)
    assert r["method"] == "true-motion-explicit" and r["solver"] == "RK45" and r["case"] == "compressor-stiff-1e5"
    assert r["n"] > 10_000 and r["nfev"] > r["n"] and "extrapolated" in r["note"]
