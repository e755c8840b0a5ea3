"""The instant-centre and mobility benchmarks (graphmech/problems/instant_centres/bench.py): the
records' shape and that the timed work is exact (ω and v_C by centres against the exact kinematics;
F = F_actual for the roller-follower linkage). No assertion on speed."""
from __future__ import annotations

import pytest

from graphmech.problems import KINDS
from graphmech.problems.instant_centres.bench import ic_records


@pytest.fixture(scope="module")
def records():
    return ic_records(quick=True)


def test_the_records_name_their_method_case_and_size(records):
    assert [(r["method"], r["case"], r["n"]) for r in records] == [
        ("instant-centres-per-position", "fourbar-120-60-120-90", 1), ("instant-centres", "fourbar-120-60-120-90", 1),
        ("instant-centres-per-position", "fourbar-120-60-120-90", 360),
        ("instant-centres", "fourbar-120-60-120-90", 360), ("mobility-rank", "hfut-3-2-roller", 13)]
    assert all(set(r) == {"method", "case", "n", "seconds", "max_rel_error"} for r in records)
    assert all(r["seconds"] > 0 for r in records)


def test_omega_and_v_c_by_instant_centres_are_exact_at_every_position(records):
    """One by one and as arrays over the positions alike."""
    assert all(r["max_rel_error"] < 1e-13 for r in records[:4])


def test_the_mobility_count_and_the_jacobians_rank_agree(records):
    """The roller-follower linkage of 10 links and 13 pairs: its error is |F − F_actual|."""
    assert records[4]["max_rel_error"] == 0.0


def test_the_linkage_bench_includes_these_records():
    bench = KINDS["linkage"].bench
    assert bench is not None
    records, _ = bench(True)
    assert [r["method"] for r in records][-3:] == ["instant-centres-per-position", "instant-centres",
                                                            "mobility-rank"]
