"""The gear benchmark's records: the involute by points converges as 1/n², the meshing is exact
(speed is measured there, not here)."""
from __future__ import annotations

import math

from graphmech.problems.gears.bench import bench, gear_records

REQUIRED = {"method", "case", "n", "seconds", "max_rel_error"}


def test_records_and_the_involutes_order_of_convergence():
    recs = gear_records(repeat=1, points=(8, 16, 32, 64))
    assert all(REQUIRED <= set(r) for r in recs)
    inv = [r for r in recs if r["method"] == "involute"]
    assert [r["n"] for r in inv] == [8, 16, 32, 64]
    for a, b in zip(inv, inv[1:]):
        order = math.log(a["max_rel_error"] / b["max_rel_error"]) / math.log(2)
        assert 1.8 < order < 2.2, (a, b)  # the chords' sag ~ 1/n²
    assert inv[-1]["max_rel_error"] < 1e-3
    mesh = [r for r in recs if r["method"] == "gear-mesh"]
    assert {r["case"] for r in mesh} >= {"contact-ratio-19-42", "internal-20-80", "rack-z18"}
    assert max(r["max_rel_error"] for r in mesh) < 1e-9


def test_quick_bench_notes():
    records, notes = bench(quick=True)
    assert records and any("n^−2" in n for n in notes)


def test_rack_generation_records_fall_as_one_over_n_squared():
    from graphmech.problems.gears.bench import generation_records

    recs = generation_records(repeat=1, positions=(8, 16, 32))
    assert {r["method"] for r in recs} == {"rack-generation"} and all(REQUIRED <= set(r) for r in recs)
    for case in ("z15-x0", "z18-x-1.5-undercut"):
        mine = [r for r in recs if r["case"] == case]
        assert [r["n"] for r in mine] == [8, 16, 32]
        for a, b in zip(mine, mine[1:]):
            assert 1.5 < math.log2(a["max_rel_error"] / b["max_rel_error"]) < 2.6, (a, b)
    _, notes = bench(quick=True)
    assert any(n.startswith("rack generation z15-x0: the scallops fall as N^−") for n in notes)
