"""The benchmark's records: their shape and their accuracy (speed is measured there, not here)."""
from __future__ import annotations

import json

from tests.conftest import BENCH_GUARD_S, run_cli


def test_bench_records_and_agreement(tmp_path):
    code, out, err = run_cli("bench", "--json", "--quick", "-o", str(tmp_path), limit=BENCH_GUARD_S)
    assert code == 0, err
    doc = json.loads(out)
    saved = json.loads((tmp_path / "bench.json").read_text())
    assert [r["n"] for r in saved["records"]] == [r["n"] for r in doc["records"]]
    recs = {(r["method"], r["case"], r["n"]): r for r in doc["records"]}
    for n in (1, 360):
        r = recs[("polygons", "fourbar-120-60-120-90", n)]
        assert set(r) == {"method", "case", "n", "seconds", "max_rel_error"}
        assert r["seconds"] > 0  # measured, not judged: speed belongs to the bench
        assert r["max_rel_error"] <= 1e-12
    # the yardstick solves the same linkage to the same answers
    assert recs[("closed-form-numpy", "fourbar-120-60-120-90", 360)]["max_rel_error"] <= 1e-12


def test_instant_centre_and_mobility_records():
    from graphmech.problems.instant_centres.bench import ic_records

    recs = {(r["method"], r["n"]): r for r in ic_records(quick=True)}
    for n in (1, 360):
        r = recs[("instant-centres", n)]
        assert r["seconds"] > 0 and r["max_rel_error"] <= 1e-12
    assert recs[("mobility-rank", 13)]["max_rel_error"] == 0.0  # the count and the rank agree: F = 1


def test_the_flywheel_bench_sweep_estimates_its_own_error():
    """J_F of the compressor from N = 12 … 3600 positions: the pipeline's estimate of its own error
    (the same work at 2N and 4N) within a factor of ten of the true error (measured 0.92 … 1.41)."""
    from graphmech.problems.flywheel.bench import wittenbauer_records

    records = wittenbauer_records(repeat=1)
    assert {r["n"] for r in records} == {12, 24, 36, 72, 360, 3600}
    assert {r["case"] for r in records} == {"compressor-exact", "compressor-book", "compressor-indicator"}
    for r in records:
        assert r["max_rel_error"] > 1e-10  # a discretised value at every N of the sweep
        assert 0.5 <= r["error_estimate"] / r["max_rel_error"] <= 2, r
