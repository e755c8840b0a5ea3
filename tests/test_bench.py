"""The whole benchmark through the command (graphmech/bench.py): its records, saved and printed, and
their accuracy (speed is measured there, not here). Each kind's own records are tested beside the
kind (tests/problems/<kind>/test_bench.py)."""
from __future__ import annotations

import json


def test_bench_records_and_agreement(quick_bench):
    code, out, err, folder = quick_bench
    assert code == 0, err
    doc = json.loads(out)
    saved = json.loads((folder / "bench.json").read_text())
    assert [r["n"] for r in saved["records"]] == [r["n"] for r in doc["records"]]
    recs = {(r["method"], r["case"], r["n"]): r for r in doc["records"]}
    for n in (1, 360):
        r = recs[("polygons", "fourbar-120-60-120-90", n)]
        assert set(r) == {"method", "case", "n", "seconds", "max_rel_error"}
        assert r["seconds"] > 0  # measured, not judged: speed belongs to the bench
        assert r["max_rel_error"] <= 1e-12
    # the yardstick solves the same linkage to the same answers
    assert recs[("closed-form-numpy", "fourbar-120-60-120-90", 360)]["max_rel_error"] <= 1e-12


def test_the_batch_record_times_variants_with_their_checks(quick_bench):
    code, out, _, _ = quick_bench
    batch = [r for r in json.loads(out)["records"] if r["method"] == "batch"]
    assert code == 0 and len(batch) == 1
    r = batch[0]
    assert r["n"] == 12 and r["failed"] == 0 and r["seconds"] > 0 and r["workers"] >= 1
    assert r["max_rel_error"] <= 1e-12  # every variant's every row: constructions, exact to round-off
