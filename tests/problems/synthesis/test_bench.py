"""The synthesis benchmark's records: the structural error read off the sampled curve converges
where the largest error is inside the range, and is exact at an end; located, it is independent of
the sampling (speed is measured there, not here)."""
from __future__ import annotations

import pytest

from graphmech.problems.synthesis.bench import (
    LOCATED,
    SAMPLED,
    bench,
    structural_error_records,
)

REQUIRED = {"method", "case", "n", "seconds", "max_rel_error"}


def test_records_of_the_structural_error_against_the_samples():
    recs = structural_error_records(quick=True)
    assert all(REQUIRED <= set(r) for r in recs) and all(r["seconds"] > 0 for r in recs)
    by = {(r["method"], r["case"], r["n"]): r for r in recs}
    assert {r["n"] for r in recs} == {11, 51, 201, 2001}
    # located (refined): the same max at any sampling
    assert {r["method"] for r in recs} == {LOCATED, SAMPLED}  # file names of the plots: no spaces
    assert max(r["max_rel_error"] for r in recs if r["method"] == LOCATED) < 1e-12
    # read off the curve: Chebyshev's largest error is at x₀, a sample; uniform's inside the range
    assert all(by[(SAMPLED, "log10-chebyshev", n)]["max_rel_error"] == 0.0 for n in (11, 51, 201))
    uni = [by[(SAMPLED, "log10-uniform", n)]["max_rel_error"] for n in (11, 51, 201, 2001)]
    assert uni[0] == pytest.approx(6.6e-3, rel=0.05) and uni[2] < 1e-4 < uni[0] and uni[3] < 1e-6
    assert by[(SAMPLED, "log10-uniform", 2001)]["max_error_deg"] == pytest.approx(0.1962396139, abs=1e-9)


def test_the_notes_say_each_case():
    _, notes = bench(quick=True)
    assert len(notes) == 2 and notes[0].startswith("structural error log10-chebyshev: max 0.1686°")
    assert "exact at every n" in notes[0] and "order" in notes[1]
