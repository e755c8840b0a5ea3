"""The kinetostatics benchmark's records: their shape and the agreement of the three methods."""
from __future__ import annotations

from graphmech.problems.forces.bench import kinetostatic_notes, kinetostatic_records, sixbar, sixbar_loads


def test_kinetostatic_records_agree(problems):
    records = kinetostatic_records(quick=True)
    assert [(r["case"], r["n"]) for r in records] == [
        ("sixbar", 1), ("sixbar", 360), ("sixbar-friction", 1), ("sixbar-friction", 360)]
    for r in records:
        assert r["method"] == "kinetostatics" and r["seconds"] > 0 and r["matrix_seconds"] > 0
        assert r["polygon_vs_matrix"] <= 1e-12, r  # force polygons vs matrix method
        assert r.get("lever_vs_matrix", 0.0) <= 1e-12, r  # Zhukovsky's lever vs matrix method
        assert (r["rounds"] > 0) == r["case"].endswith("friction")
    notes = kinetostatic_notes(records)
    assert len(notes) == 2 and "360 positions" in notes[0] and "lever vs matrix" in notes[0]


def test_bench_sixbar_is_the_reference_problem(problems):
    """The bench's linkage and loads are those of force.sixbar_kinetostatic (its M_b at 120°)."""
    import numpy as np

    from graphmech.exact.kinetostatics import solve_forces

    ref = problems["force.sixbar_kinetostatic"]["exact"]
    for friction, key in ((False, "Mb_Nm"), (True, "Mb_friction_Nm")):
        ex = solve_forces(sixbar(), sixbar_loads(friction), np.radians([120.0]))
        assert float(ex.balancing_moment[0]) == __import__("pytest").approx(ref[key], rel=1e-12)
