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


def test_the_reference_scenes_record_times_every_example_scene_on_the_pool(quick_bench):
    """Figure and check of the example scenes in one run (--quick: every tenth); the notes state
    its time and the batch record's."""
    from graphmech.bench import REFERENCE_STRIDE_QUICK
    from graphmech.packaged import example_names

    code, out, _, _ = quick_bench
    doc = json.loads(out)
    [r] = [r for r in doc["records"] if r["method"] == "reference-scenes"]
    assert code == 0 and r["case"] == "every-10th-example"
    assert r["n"] == len(example_names()[::REFERENCE_STRIDE_QUICK]) and r["failed"] == 0
    assert r["seconds"] > 0 and r["per_scene"] == r["seconds"] / r["n"] and r["workers"] >= 1
    notes = doc["notes"]
    assert any(n.startswith(f"reference scenes: {r['n']} example scenes") and "ms a scene" in n for n in notes)
    assert any(n.startswith("batch: 12 variants") for n in notes)


def test_the_memory_record_measures_a_3600_position_cycle(quick_bench):
    code, out, _, _ = quick_bench
    doc = json.loads(out)
    [r] = [r for r in doc["records"] if r["method"] == "cycle-memory"]
    assert code == 0 and r["n"] == 3600 and r["case"] == "slider-crank-offset-3600"
    # arrays over 3600 positions are tens of kB each: the check holds a few hundred of them at once
    assert 1.0 < r["peak_mib"] < 200.0 and r["seconds"] > 0
    assert r["max_rel_error"] < 1e-5  # the chords' diagrams at 3600 positions (order 2)
    assert "full cycle, 3600 positions (slider-crank-offset-3600): checked in " in "\n".join(doc["notes"])


def test_every_discretised_method_has_its_error_against_time_plot(quick_bench):
    from graphmech.render.plots import discretised_methods

    _, _, _, folder = quick_bench
    records = json.loads((folder / "bench.json").read_text())["records"]
    methods = discretised_methods(records)
    assert {"cam-inversion", "wittenbauer", "energy-indicator", "graphical-differentiation", "involute",
            "rack-generation", "true-motion"} <= set(methods)
    assert sorted(p.name for p in folder.glob("*-error-time.svg")) == sorted(f"{m}-error-time.svg" for m in methods)


def test_compare_names_each_records_change_and_what_is_new_or_gone():
    from graphmech.bench import compare

    old = [{"method": "polygons", "case": "fourbar", "n": 360, "seconds": 2e-4, "max_rel_error": 4.7e-15},
           {"method": "true-motion", "case": "stiff", "n": 90, "seconds": 0.5, "max_rel_error": 1e-6,
            "solver": "Radau", "rtol": 1e-6},
           {"method": "old-method", "case": "x", "n": 1, "seconds": 1.0, "max_rel_error": None}]
    new = [{"method": "polygons", "case": "fourbar", "n": 360, "seconds": 1e-4, "max_rel_error": 2.0e-15},
           {"method": "true-motion", "case": "stiff", "n": 90, "seconds": 0.5, "max_rel_error": 1e-6,
            "solver": "Radau", "rtol": 1e-6},
           {"method": "true-motion", "case": "stiff", "n": 90, "seconds": 0.4, "max_rel_error": 1e-6,
            "solver": "BDF", "rtol": 1e-6}]
    assert compare(old, new) == [
        "polygons fourbar n=360: 200.0 → 100.0 µs (×0.50), error 4.7e-15 → 2.0e-15",
        "true-motion stiff n=90 solver=Radau rtol=1e-06: 500000.0 → 500000.0 µs (×1.00)",
        "true-motion stiff n=90 solver=BDF rtol=1e-06: 400000.0 µs (new)",
        "old-method x n=1: gone",
    ]


def test_a_run_compared_with_itself_changes_nothing(quick_bench):
    from graphmech.bench import compare, read_records

    _, _, _, folder = quick_bench
    saved = read_records(folder / "bench.json")
    lines = compare(saved, saved)
    assert len(lines) == len({(r["method"], r["case"], r["n"], r.get("solver"), r.get("rtol")) for r in saved})
    assert all("(×1.00)" in line for line in lines)


def test_a_bad_file_to_compare_with_is_refused_before_the_bench_runs(tmp_path):
    from tests.conftest import assert_refused, run_cli

    bad = tmp_path / "old.json"
    bad.write_text('{"records": [{"method": "polygons", "case": "c", "n": 1, "seconds": -1}]}', encoding="utf-8")
    assert_refused(run_cli("bench", "--compare", str(bad), limit=20.0), str(bad), "records[0].seconds",
                   "positive number")
    bad.write_text("not json", encoding="utf-8")
    assert_refused(run_cli("bench", "--compare", str(bad), limit=20.0), str(bad), "not a bench.json")
    assert_refused(run_cli("bench", "--compare", str(tmp_path / "none.json"), limit=20.0), str(tmp_path / "none.json"),
                   "cannot read")


def test_the_default_bench_leaves_the_rk45_demonstration_to_its_flag(quick_bench):
    _, out, _, _ = quick_bench
    methods = {r["method"] for r in json.loads(out)["records"]}
    assert "true-motion" in methods and "true-motion-explicit" not in methods
