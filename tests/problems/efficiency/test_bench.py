"""The force and mass-radius polygon benchmark records: their shape and accuracy (not their speed)."""
from __future__ import annotations

from graphmech.problems.efficiency.bench import efficiency_records


def test_efficiency_records_agree_with_the_closed_forms():
    recs = efficiency_records(repeat=1, ns=(5, 50), masses=(3, 30))
    assert [(r["method"], r["case"], r["n"]) for r in recs] == [
        ("force-polygon", "incline-sweep", 5), ("force-polygon", "incline-sweep", 50),
        ("force-polygon", "wedge-F1430", 2),
        ("mass-radius-polygon", "dynamic-random", 3), ("mass-radius-polygon", "dynamic-random", 30)]
    for r in recs:
        assert set(r) == {"method", "case", "n", "seconds", "max_rel_error"}
        assert r["seconds"] > 0
        assert r["max_rel_error"] <= 1e-13, r
