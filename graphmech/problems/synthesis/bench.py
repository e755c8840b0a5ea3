"""Benchmarks of the synthesis kind: the structural error of Freudenstein's function generator
against the number of samples of its curve (speed is measured here, never in timed tests).

Records as :mod:`graphmech.bench`'s, from :func:`graphmech.exact.freudenstein.convergence` on
the log10 classic (y = log10 x over [1, 2], Δφ = 60°, Δψ = 90°, three precision points), Chebyshev
and uniform spacing:

* ``freudenstein-structural-error``: the largest |Δψ| located (sampled, each extreme refined),
  against the one at the most samples — independent of the sampling once refined;
* ``structural-error-sampled-curve``: the largest sampled |Δψ| alone, as the check table's
  graphical value reads it off the figure's curve — a discretised value, order 2 where the
  largest error is inside the range (uniform spacing); exact where it is at an end (Chebyshev's).
  Its ``seconds`` are those of the same run (the refinement included).
"""
from __future__ import annotations

import math
from typing import Any

#: The samples of the curve the records take (``quick``: fewer).
SAMPLES = (11, 21, 51, 101, 201, 501, 2001)
QUICK_SAMPLES = (11, 51, 201, 2001)
#: The method names (file names of the bench's plots: no spaces): the located extreme, and the
#: curve read without refinement.
LOCATED, SAMPLED = "freudenstein-structural-error", "structural-error-sampled-curve"


def structural_error_records(quick: bool = False) -> list[dict[str, Any]]:
    """The log10 classic's structural error against the samples, both spacings: the located and the
    sampled largest error, each against the located one at the most samples."""
    from graphmech.exact.freudenstein import FourBar, convergence
    from graphmech.methods.freudenstein import design, named_function

    f = named_function("log10")
    d = math.radians
    records: list[dict[str, Any]] = []
    for spacing in ("chebyshev", "uniform"):
        r = design(f, 1.0, 2.0, d(45), d(60), d(135), d(90), spacing=spacing)
        bar = FourBar(r.a, r.b, r.c, r.d, r.input_reversed, r.output_reversed)
        rows = convergence(bar, f, r.x0, r.x1, r.phi0, r.dphi, r.psi0, r.dpsi, r.phi, case=f"log10-{spacing}",
                           samples=QUICK_SAMPLES if quick else SAMPLES, repeat=1 if quick else 3)
        records += [{**row, "method": LOCATED} for row in rows]
        records += [{**row, "method": SAMPLED, "max_rel_error": row["sampled_rel_error"],
                     "note": "the largest sampled |Δψ| without refinement; timed with it"} for row in rows]
    return records


def structural_error_notes(records: list[dict[str, Any]]) -> list[str]:
    """Per case: the sampled curve's error at the fewest and most samples, the located error's
    largest, the time at 201 samples (the check's curve)."""
    from graphmech.accuracy import convergence_order

    out = []
    for case in dict.fromkeys(r["case"] for r in records if r["method"] == SAMPLED):
        sam = sorted((r for r in records if r["method"] == SAMPLED and r["case"] == case), key=lambda r: r["n"])
        loc = [r for r in records if r["method"] != SAMPLED and r["case"] == case]
        falling = [r for r in sam[:-1] if r["max_rel_error"] > 0]
        order = (f"; order {convergence_order(falling)['overall']:.2f}" if len(falling) >= 2
                 else "; exact at every n (the largest error at an end of the range)")
        at = next((r for r in sam if r["n"] == 201), sam[-1])
        out.append(f"structural error {case}: max {sam[-1]['max_error_deg']:.4f}°; read off the curve "
                   + ", ".join(f"{r['max_rel_error']:.1e} (N={r['n']})" for r in sam[:-1]) + order
                   + f"; located ≤ {max(r['max_rel_error'] for r in loc):.0e} at any N; N = {at['n']} in "
                   f"{at['seconds'] * 1e3:.1f} ms")
    return out


def bench(quick: bool = False) -> tuple[list[dict[str, Any]], list[str]]:
    """The synthesis kind's records and notes."""
    records = structural_error_records(quick)
    return records, structural_error_notes(records)


__all__ = ["LOCATED", "QUICK_SAMPLES", "SAMPLED", "SAMPLES", "bench", "structural_error_notes", "structural_error_records"]
