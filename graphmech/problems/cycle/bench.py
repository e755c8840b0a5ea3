"""Benchmark of the full cycle: graphical differentiation's error against N, and a sheet's time.

``graphical-differentiation`` records: the s–φ diagram read off the kinematic diagram at N
positions (one vectorised evaluation of the construction), differentiated by chords twice, and
compared with the exact v (at the interval middles) and a (at the positions) of
:mod:`graphmech.exact.linkage`. The error is the largest over the cycle, relative to
max(|exact|, ω₁·l_AB) (ω₁²·l_AB for accelerations), as in ``check``. Chords give the derivative at
the middle of the interval to O(Δφ²), so the error should fall 100× for 10× the positions.

``full-cycle-sheet``: the time to render the 12-position sheet of
figures/scenes/linkage.slider_crank_offset-cycle.toml (parse, construct, check the diagrams,
draw, write the SVG text), no error.
"""
from __future__ import annotations

import math
from typing import Any, cast

import numpy as np

from graphmech.accuracy import convergence_order, extrapolated
from graphmech.exact.linkage import solve as solve_exact
from graphmech.mechanisms.linkage import RRP, RRR, Crank, Guide, Linkage
from graphmech.methods.full_cycle import CycleDiagram, cycle_positions, evaluate_cycle, finer_positions
from graphmech.timing import best_time

__all__ = ["CYCLE_N", "bench", "cycle_notes", "differentiation_records"]

#: Positions of the graphical-differentiation benchmark.
CYCLE_N = (12, 24, 36, 72, 360, 3600)


def _cases() -> dict[str, tuple[Linkage, str]]:
    slider = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.1, 10.0),
                     (RRP("B", "C", ("2", "3"), 0.3, Guide((0.0, 0.03), 0.0), "forward"),))
    rocker = Linkage({"A": (0.0, 0.0), "D": (0.072, 0.0)}, Crank("1", "A", "B", 0.028, 10.0),
                     (RRR("B", "C", "D", ("2", "3"), (0.052, 0.050), "left"),))
    return {"slider-crank-offset": (slider, "C"), "crank-rocker-28-52-50-72": (rocker, "3")}



def differentiation_records(repeat: int = 5, ns: tuple[int, ...] = CYCLE_N) -> list[dict[str, Any]]:
    """One record per case, derivative (first, second) and N."""
    out = []
    for case, (linkage, subject) in _cases().items():
        d = linkage.driver
        assert isinstance(d, Crank)
        point = subject[0].isalpha()
        mu_s = 0.002 if point else math.radians(2.0)
        mu_phi = math.radians(360.0 / 120.0)

        def diagram(positions: np.ndarray) -> CycleDiagram:
            return evaluate_cycle(linkage, {"l": 0.002, "v": 0.05, "a": 0.5}, positions, diagrams=[subject],
                                  mu_phi=mu_phi, mu_s={subject: mu_s}, H_mm=(20.0, 20.0)).diagrams[0]

        for n in ns:
            angles = cycle_positions(0.0, n, 1.0)
            secs, dg = best_time(lambda: diagram(angles), repeat)
            # what the chords say of their own error (not timed): the same diagrams over 2N and 4N
            # positions placed on the N, Richardson with the chords' order 2
            v_lim, a_lim = (_extrapolated([diagram(finer_positions(0.0, n, 1.0, m, middles)) for m in (2, 4)], n, pick)
                            for middles, pick in ((True, "v"), (False, "a")))
            mids = angles + math.pi / n
            at, mid = solve_exact(linkage, angles), solve_exact(linkage, mids)
            if point:
                v_ex, a_ex = mid.vel[subject][:, 0], at.acc[subject][:, 0]
            else:
                v_ex, a_ex = mid.omega[subject], at.alpha[subject]
            w = abs(d.omega)
            cv, ca = (w * d.length, w * w * d.length) if point else (w, w * w)
            v = dg.velocity.derivative_mm * dg.mu_v
            a = dg.a_mm * dg.mu_a
            ev = float(np.max(np.abs(v - v_ex) / np.maximum(np.abs(v_ex), cv)))
            ea = float(np.max(np.abs(a - a_ex) / np.maximum(np.abs(a_ex), ca)))
            est_v = float(np.max(np.abs(v - v_lim) / np.maximum(np.abs(v_lim), cv)))
            est_a = float(np.max(np.abs(a - a_lim) / np.maximum(np.abs(a_lim), ca)))
            names = ("v", "a") if point else ("omega", "alpha")
            for what, err, est in zip(names, (ev, ea), (est_v, est_a)):
                out.append({"method": "graphical-differentiation", "case": f"{case}-{what}", "n": n,
                            "seconds": secs, "max_rel_error": err, "error_estimate": est})
    return out


def _extrapolated(finer: list[Any], n: int, pick: str) -> np.ndarray:
    """v (at the N middles) or a (at the N positions) from the diagrams over 2N and 4N positions,
    extrapolated to infinitely many (the chords' order 2)."""
    v2, v4 = ((f.velocity.derivative_mm * f.mu_v if pick == "v" else f.a_mm * f.mu_a)[::m]
              for f, m in zip(finer, (2, 4)))
    assert len(v2) == len(v4) == n
    return cast(np.ndarray, extrapolated(v2, v4, order=2))  # on arrays too


def cycle_notes(records: list[dict[str, Any]]) -> list[str]:
    out = []
    for case in dict.fromkeys(r["case"] for r in records if r["method"] == "graphical-differentiation"):
        rs = [r for r in records if r["case"] == case]
        o = convergence_order(rs)
        big = max(rs, key=lambda r: r["n"])
        out.append(f"graphical differentiation {case}: " + ", ".join(f"{r['max_rel_error']:.1e} (N={r['n']})" for r in rs)
                   + f"; order {o['overall']:.2f}; N = {big['n']} in {big['seconds'] * 1e3:.2f} ms")
    return out


def bench(quick: bool = False) -> tuple[list[dict[str, Any]], list[str]]:
    """Graphical differentiation of the drawn cycle against N, and the notes on its convergence."""
    records = differentiation_records(repeat=2 if quick else 5)
    return records, cycle_notes(records)
