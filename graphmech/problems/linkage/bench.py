"""Benchmark of the velocity and acceleration polygons: the four-bar AD 120, AB 60, BC 120,
CD 90 mm (ω1 = 10 rad/s) at one position and over a 360-position cycle, against a plain
vectorised closed-form numpy solution, and the largest error against the exact solution.

Records as in :mod:`graphmech.bench`.
"""
from __future__ import annotations

from typing import Any

import numpy as np

from graphmech.exact.linkage import solve as solve_exact
from graphmech.mechanisms.linkage import Crank, Linkage, RRR
from graphmech.methods.polygons import build_polygons
from graphmech.timing import best_time



FOURBAR_QUANTITIES = ("v_B", "v_C", "v_CB", "omega_2", "omega_3", "a_C", "a_CB", "a_CB_n", "a_CB_t",
                      "a_CD_n", "a_CD_t", "alpha_2", "alpha_3")


def fourbar() -> Linkage:
    """AD 120, AB 60, BC 120, CD 90 mm, C above AD, ω1 = 10 rad/s."""
    return Linkage({"A": (0.0, 0.0), "D": (0.12, 0.0)}, Crank("1", "A", "B", 0.06, 10.0),
                   (RRR("B", "C", "D", ("2", "3"), (0.12, 0.09), "left"),), frame_link="4")


def closed_form_fourbar(phi: np.ndarray, a: float = 0.06, b: float = 0.12, c: float = 0.09,
                        d: float = 0.12, w1: float = 10.0) -> dict[str, np.ndarray]:
    """A plain vectorised closed-form solution of the same four-bar: the speed yardstick.

    It computes the same quantities the polygon benchmark measures (``FOURBAR_QUANTITIES``).

    Positions by the law of cosines, rates by the differentiated loop a·e^{iφ} + b·e^{iθ2} =
    d + c·e^{iθ3} (Cramer's rule).
    """
    bx, by = a * np.cos(phi), a * np.sin(phi)
    ex, ey = d - bx, -by
    f = np.hypot(ex, ey)
    base = np.arctan2(ey, ex)
    beta = np.arccos((b * b + f * f - c * c) / (2 * b * f))
    t2 = base + beta  # C left of B→D
    cx, cy = bx + b * np.cos(t2), by + b * np.sin(t2)
    t3 = np.arctan2(cy, cx - d)
    s23 = np.sin(t3 - t2)
    w2 = a * w1 * np.sin(phi - t3) / (b * s23)
    w3 = a * w1 * np.sin(phi - t2) / (c * s23)
    al2 = (a * w1 ** 2 * np.cos(phi - t3) + b * w2 ** 2 * np.cos(t2 - t3) - c * w3 ** 2) / (b * s23)
    al3 = (a * w1 ** 2 * np.cos(phi - t2) + b * w2 ** 2 - c * w3 ** 2 * np.cos(t3 - t2)) / (c * s23)
    w2s, w3s = w2 * w2, w3 * w3
    return {"v_B": np.full_like(phi, abs(w1) * a), "v_C": np.abs(w3) * c, "v_CB": np.abs(w2) * b,
            "omega_2": w2, "omega_3": w3, "a_C": c * np.hypot(al3, w3s), "a_CB": b * np.hypot(al2, w2s),
            "a_CB_n": w2s * b, "a_CB_t": np.abs(al2) * b, "a_CD_n": w3s * c, "a_CD_t": np.abs(al3) * c,
            "alpha_2": al2, "alpha_3": al3}


def polygon_records(repeat: int = 7) -> list[dict[str, Any]]:
    """The four-bar's velocity and acceleration polygons at 1 and at 360 positions."""
    from graphmech.problems.linkage.sizes import characteristic
    from graphmech.problems.linkage.check import exact_value

    lk = fourbar()
    b = build_polygons(lk, {"l": 0.002, "v": 0.01, "a": 0.1})
    plan = b.g.prune([b.quantities[q].slot for q in FOURBAR_QUANTITIES])
    records = []
    for n in (1, 360):
        phis = np.radians(np.arange(n) * (360.0 / n) + (165.0 if n == 1 else 0.0))
        if n == 1:
            p0 = float(phis[0])
            secs, _ = best_time(lambda: plan.solve({"phi": p0}), repeat, 2000)
            sols = [plan.solve({"phi": p0})]
        else:
            secs, _ = best_time(lambda: plan.evaluate_batch({"phi": phis}), repeat, 50)
            batch = plan.evaluate_batch({"phi": phis})
            sols = [batch.at(i) for i in range(n)]
        kin = solve_exact(lk, phis)
        worst = 0.0
        for i, sol in enumerate(sols):
            for q in FOURBAR_QUANTITIES:
                qq = b.quantities[q]
                d, s = sol[qq.slot]
                e = exact_value(kin, qq.exact, i)
                worst = max(worst, abs(d * s - e) / max(abs(e), characteristic(lk, qq.unit)))
        records.append({"method": "polygons", "case": "fourbar-120-60-120-90", "n": n, "seconds": secs,
                        "max_rel_error": worst})
    phis = np.radians(np.arange(360.0))
    secs, _ = best_time(lambda: closed_form_fourbar(phis), repeat, 50)
    ref = closed_form_fourbar(phis)
    kin = solve_exact(lk, phis)
    err = 0.0
    for q in FOURBAR_QUANTITIES:
        qq = b.quantities[q]
        exact = np.array([exact_value(kin, qq.exact, i) for i in range(len(phis))])
        err = max(err, float(np.max(np.abs(ref[q] - exact))) / max(float(np.max(np.abs(exact))),
                                                                  characteristic(lk, qq.unit)))
    records.append({"method": "closed-form-numpy", "case": "fourbar-120-60-120-90", "n": 360, "seconds": secs,
                    "max_rel_error": err})
    return records


def bench(quick: bool = False) -> tuple[list[dict[str, Any]], list[str]]:
    """The polygons' records and the notes comparing them with the targets."""
    records = polygon_records(repeat=3 if quick else 7)
    by = {(r["method"], r["n"]): r for r in records}
    one, cyc, base = by[("polygons", 1)], by[("polygons", 360)], by[("closed-form-numpy", 360)]
    notes = [
        f"one position: {one['seconds'] * 1e6:.1f} µs (target < 25 µs)",
        f"360-position cycle: {cyc['seconds'] * 1e6:.0f} µs = {cyc['seconds'] / base['seconds']:.2f}× "
        f"the plain closed-form numpy solution ({base['seconds'] * 1e6:.0f} µs; target ≤ 3×)",
        f"agreement: {max(one['max_rel_error'], cyc['max_rel_error']):.1e} (target ≤ 1e-12)",
    ]
    return records, notes
