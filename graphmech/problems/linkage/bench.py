"""Benchmark of the velocity and acceleration polygons on four linkages (ω1 = 10 rad/s): the four-bar
AD 120, AB 60, BC 120, CD 90 mm, the offset slider-crank AB 100, BC 300, e 30 mm, the guide bar AC 300,
AB 100 mm and a six-bar (the four-bar and a slider CE 200 mm on the guide 150 mm above AD), at one
position and over a 360-position cycle, against a closed-form solution of the same quantities —
plain vectorised numpy over the cycle, the math module at one position — timed interleaved with
them, and the largest error of each against the exact solution. The polygons are timed as a plan
run again and again runs: fused into one straight-line function (graphmech.construction.fused)
after its first runs, which the best of the repeats leaves out.

Records as in :mod:`graphmech.bench`.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any, NamedTuple

import numpy as np

from graphmech.exact.linkage import solve as solve_exact
from graphmech.mechanisms.linkage import RPR, RRP, RRR, Crank, Guide, Linkage
from graphmech.methods.polygons import build_polygons
from graphmech.timing import best_times_interleaved

FOURBAR_QUANTITIES = ("v_B", "v_C", "v_CB", "omega_2", "omega_3", "a_C", "a_CB", "a_CB_n", "a_CB_t",
                      "a_CD_n", "a_CD_t", "alpha_2", "alpha_3")
SLIDER_CRANK_QUANTITIES = ("v_B", "v_C", "v_CB", "omega_2", "alpha_2", "a_C", "a_CB", "a_CB_n", "a_CB_t")
GUIDE_BAR_QUANTITIES = ("v_B3", "v_B3B2", "omega_3", "alpha_3", "a_B3", "a_k_B3B2", "a_r_B3B2", "a_B3C_n",
                        "a_B3C_t")
SIXBAR_QUANTITIES = FOURBAR_QUANTITIES + ("omega_5", "alpha_5", "v_E", "a_E", "v_EC", "a_EC", "a_EC_n", "a_EC_t")


def fourbar() -> Linkage:
    """AD 120, AB 60, BC 120, CD 90 mm, C above AD, ω1 = 10 rad/s."""
    return Linkage({"A": (0.0, 0.0), "D": (0.12, 0.0)}, Crank("1", "A", "B", 0.06, 10.0),
                   (RRR("B", "C", "D", ("2", "3"), (0.12, 0.09), "left"),), frame_link="4")


def slider_crank() -> Linkage:
    """AB 100, BC 300 mm, the slider C on the guide 30 mm above A (along +x, C ahead), ω1 = 10 rad/s."""
    return Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", 0.1, 10.0),
                   (RRP("B", "C", ("2", "3"), 0.3, Guide((0.0, 0.03), 0.0), "forward"),), frame_link="4")


def guide_bar() -> Linkage:
    """AC 300 (C above A), AB 100 mm: the crank's block 2 at B slides on the bar 3 pivoted at C."""
    return Linkage({"A": (0.0, 0.0), "C": (0.0, 0.3)}, Crank("1", "A", "B", 0.1, 10.0),
                   (RPR("C", "B", ("3", "2"), "first"),), frame_link="4")


def sixbar() -> Linkage:
    """The four-bar of :func:`fourbar` and the dyad C–E (CE 200 mm), E on the guide 150 mm above AD."""
    four = fourbar()
    return Linkage(four.frame_points, four.driver,
                   four.dyads + (RRP("C", "E", ("5", "6"), 0.2, Guide((0.0, 0.15), 0.0), "forward"),),
                   frame_link="4")


class _Ops(NamedTuple):
    """The functions a closed form needs: numpy's over a cycle, the math module's at one position, so
    that one text is both yardsticks (vectorised, and scalar as a hand-written solution would be)."""

    sin: Callable[[Any], Any]
    cos: Callable[[Any], Any]
    sqrt: Callable[[Any], Any]
    atan2: Callable[[Any, Any], Any]
    acos: Callable[[Any], Any]
    hypot: Callable[[Any, Any], Any]
    abs: Callable[[Any], Any]
    full: Callable[[Any, float], Any]  # a constant at every position


def _same(phi: float, value: float) -> float:
    return value


NUMPY = _Ops(np.sin, np.cos, np.sqrt, np.arctan2, np.arccos, np.hypot, np.abs, np.full_like)
MATH = _Ops(math.sin, math.cos, math.sqrt, math.atan2, math.acos, math.hypot, abs, _same)


def _fourbar(phi: Any, m: _Ops, a: float = 0.06, b: float = 0.12, c: float = 0.09, d: float = 0.12,
             w1: float = 10.0) -> tuple[dict[str, Any], tuple[Any, ...]]:
    """The four-bar's quantities, and C, θ3, ω3, α3 and ω3² (for a dyad on C: nothing computed for it
    alone, so the four-bar's yardstick does only the four-bar's work).

    Positions by the law of cosines, rates by the differentiated loop a·e^{iφ} + b·e^{iθ2} =
    d + c·e^{iθ3} (Cramer's rule).
    """
    bx, by = a * m.cos(phi), a * m.sin(phi)
    ex, ey = d - bx, -by
    f = m.hypot(ex, ey)
    base = m.atan2(ey, ex)
    beta = m.acos((b * b + f * f - c * c) / (2 * b * f))
    t2 = base + beta  # C left of B→D
    cx, cy = bx + b * m.cos(t2), by + b * m.sin(t2)
    t3 = m.atan2(cy, cx - d)
    s23 = m.sin(t3 - t2)
    w2 = a * w1 * m.sin(phi - t3) / (b * s23)
    w3 = a * w1 * m.sin(phi - t2) / (c * s23)
    al2 = (a * w1 ** 2 * m.cos(phi - t3) + b * w2 ** 2 * m.cos(t2 - t3) - c * w3 ** 2) / (b * s23)
    al3 = (a * w1 ** 2 * m.cos(phi - t2) + b * w2 ** 2 - c * w3 ** 2 * m.cos(t3 - t2)) / (c * s23)
    w2s, w3s = w2 * w2, w3 * w3
    out = {"v_B": m.full(phi, abs(w1) * a), "v_C": m.abs(w3) * c, "v_CB": m.abs(w2) * b,
           "omega_2": w2, "omega_3": w3, "a_C": c * m.hypot(al3, w3s), "a_CB": b * m.hypot(al2, w2s),
           "a_CB_n": w2s * b, "a_CB_t": m.abs(al2) * b, "a_CD_n": w3s * c, "a_CD_t": m.abs(al3) * c,
           "alpha_2": al2, "alpha_3": al3}
    return out, (cx, cy, t3, w3, al3, w3s)


def closed_form_fourbar(phi: np.ndarray, a: float = 0.06, b: float = 0.12, c: float = 0.09,
                        d: float = 0.12, w1: float = 10.0) -> dict[str, np.ndarray]:
    """A plain vectorised closed-form solution of the same four-bar: the speed yardstick.

    It computes the same quantities the polygon benchmark measures (``FOURBAR_QUANTITIES``).
    """
    return _fourbar(phi, NUMPY, a, b, c, d, w1)[0]


def _rrp(p: tuple[Any, ...], m: _Ops, b: float, e: float) -> tuple[Any, ...]:
    """An RRP dyad P–C, C sliding on the guide y = e along +x, ahead of P's foot (``forward``): from
    P's position, velocity and acceleration, the coupler's θ, ω, α and C's x, v, a along the guide.

    P_y + b·sin θ = e, differentiated twice: ω = −v_Py / (b cos θ), α = (b ω² sin θ − a_Py) / (b cos θ).
    """
    px, py, vx, vy, ax, ay = p
    s = (e - py) / b
    co = m.sqrt(1.0 - s * s)
    w = -vy / (b * co)
    al = (b * w * w * s - ay) / (b * co)
    return w, al, px + b * co, vx - b * w * s, ax - b * al * s - b * w * w * co


def _slider_crank(phi: Any, m: _Ops, a: float = 0.1, b: float = 0.3, e: float = 0.03,
                  w1: float = 10.0) -> dict[str, Any]:
    """The offset slider-crank AB a, BC b, the guide y = e: the quantities of ``SLIDER_CRANK_QUANTITIES``."""
    cp, sp = m.cos(phi), m.sin(phi)
    w, al, _, v, acc = _rrp((a * cp, a * sp, -a * w1 * sp, a * w1 * cp, -a * w1 * w1 * cp, -a * w1 * w1 * sp),
                            m, b, e)
    ws = w * w
    return {"v_B": m.full(phi, abs(w1) * a), "v_C": v, "v_CB": m.abs(w) * b, "omega_2": w, "alpha_2": al,
            "a_C": acc, "a_CB": b * m.hypot(al, ws), "a_CB_n": ws * b, "a_CB_t": m.abs(al) * b}


def closed_form_slider_crank(phi: np.ndarray) -> dict[str, np.ndarray]:
    """Vectorised closed form of the offset slider-crank 100/300/e 30 (``slider_crank``)."""
    return _slider_crank(phi, NUMPY)


def _guide_bar(phi: Any, m: _Ops, a: float = 0.1, h: float = 0.3, w1: float = 10.0) -> dict[str, Any]:
    """The guide bar: crank AB a about A, the bar 3 about C = A + (0, h) through the block's pin B.

    r = CB, L = |r|: ω3 = (r × v_B)/L², the slide L̇ = r·v_B/L; a_B along and across the bar
    gives L̈ = a_B·û + L ω3² and α3 = (a_B·n̂ − 2 L̇ ω3)/L.
    """
    cp, sp = m.cos(phi), m.sin(phi)
    rx, ry = a * cp, a * sp - h
    L = m.hypot(rx, ry)
    vx, vy = -a * w1 * sp, a * w1 * cp
    w3 = (rx * vy - ry * vx) / (L * L)
    ldot = (rx * vx + ry * vy) / L
    ax, ay = -a * w1 * w1 * cp, -a * w1 * w1 * sp
    w3s = w3 * w3
    lddot = (rx * ax + ry * ay) / L + L * w3s
    al3 = ((rx * ay - ry * ax) / L - 2.0 * ldot * w3) / L
    return {"v_B3": m.abs(w3) * L, "v_B3B2": m.abs(ldot), "omega_3": w3, "alpha_3": al3,
            "a_B3": L * m.hypot(al3, w3s), "a_k_B3B2": 2.0 * m.abs(w3 * ldot), "a_r_B3B2": m.abs(lddot),
            "a_B3C_n": L * w3s, "a_B3C_t": L * m.abs(al3)}


def closed_form_guide_bar(phi: np.ndarray) -> dict[str, np.ndarray]:
    """Vectorised closed form of the guide bar AC 300, AB 100 (``guide_bar``)."""
    return _guide_bar(phi, NUMPY)


def _sixbar(phi: Any, m: _Ops, c: float = 0.09, ce: float = 0.2, e: float = 0.15) -> dict[str, Any]:
    """The four-bar of ``fourbar`` (rocker DC = c) and the RRP dyad C–E, E sliding on the guide y = e."""
    out, (cx, cy, t3, w3, al3, w3s) = _fourbar(phi, m, c=c)
    s3, c3 = m.sin(t3), m.cos(t3)
    # C = D + c·e^{iθ3}: v_C = ω3 × DC, a_C = α3 × DC − ω3²·DC
    pc = (cx, cy, -c * w3 * s3, c * w3 * c3, -c * al3 * s3 - c * w3s * c3, c * al3 * c3 - c * w3s * s3)
    w, al, _, v, acc = _rrp(pc, m, ce, e)
    ws = w * w
    out.update({"omega_5": w, "alpha_5": al, "v_E": v, "a_E": acc, "v_EC": m.abs(w) * ce,
                "a_EC": ce * m.hypot(al, ws), "a_EC_n": ws * ce, "a_EC_t": m.abs(al) * ce})
    return out


def closed_form_sixbar(phi: np.ndarray) -> dict[str, np.ndarray]:
    """Vectorised closed form of the six-bar (``sixbar``)."""
    return _sixbar(phi, NUMPY)


class Case(NamedTuple):
    """A benchmark linkage: its name in the records, the quantities timed, and the closed form."""

    name: str
    linkage: Callable[[], Linkage]
    quantities: tuple[str, ...]
    closed_form: Callable[[Any, _Ops], dict[str, Any]]


CASES = (
    Case("fourbar-120-60-120-90", fourbar, FOURBAR_QUANTITIES, lambda phi, m: _fourbar(phi, m)[0]),
    Case("slider-crank-100-300-e30", slider_crank, SLIDER_CRANK_QUANTITIES, _slider_crank),
    Case("guide-bar-300-100", guide_bar, GUIDE_BAR_QUANTITIES, _guide_bar),
    Case("sixbar-120-60-120-90-ce200-e150", sixbar, SIXBAR_QUANTITIES, _sixbar),
)


def case_records(case: Case, repeat: int = 7) -> list[dict[str, Any]]:
    """One case's records: ``polygons`` at 1 and 360 positions, ``closed-form-scalar`` at 1 and
    ``closed-form-numpy`` at 360; each pair timed interleaved, each with its largest error against
    the exact solution (relative to the quantity, or to the linkage's size where it is near zero)."""
    from graphmech.problems.linkage.check import exact_value
    from graphmech.problems.linkage.sizes import characteristic

    lk = case.linkage()
    b = build_polygons(lk, {"l": 0.002, "v": 0.01, "a": 0.1})
    plan = b.g.prune([b.quantities[q].slot for q in case.quantities])

    def worst(kin: Any, values: Callable[[int, str], float], n: int) -> float:
        err = 0.0
        for q in case.quantities:
            qq = b.quantities[q]
            scale = characteristic(lk, qq.unit)
            for i in range(n):
                e = exact_value(kin, qq.exact, i)
                err = max(err, abs(values(i, q) - e) / max(abs(e), scale))
        return err

    def polygon_value(sol: Any, q: str) -> float:
        d, s = sol[b.quantities[q].slot]
        return float(d * s)

    # one position: the plan's float path against the math module
    phi1 = math.radians(165.0)
    kin1 = solve_exact(lk, np.array([phi1]))
    one, scalar = best_times_interleaved([lambda: plan.solve({"phi": phi1}), lambda: case.closed_form(phi1, MATH)],
                                         repeat, 2000)
    sol1, ref1 = plan.solve({"phi": phi1}), case.closed_form(phi1, MATH)
    # the cycle: the plan's batch path against numpy
    phis = np.radians(np.arange(360.0))
    kin = solve_exact(lk, phis)
    cyc, base = best_times_interleaved([lambda: plan.evaluate_batch({"phi": phis}),
                                        lambda: case.closed_form(phis, NUMPY)], repeat, 50)
    batch = plan.evaluate_batch({"phi": phis})
    sols = [batch.at(i) for i in range(len(phis))]
    ref = case.closed_form(phis, NUMPY)

    def record(method: str, n: int, secs: float, err: float) -> dict[str, Any]:
        return {"method": method, "case": case.name, "n": n, "seconds": secs, "max_rel_error": err}

    return [record("polygons", 1, one, worst(kin1, lambda i, q: polygon_value(sol1, q), 1)),
            record("closed-form-scalar", 1, scalar, worst(kin1, lambda i, q: float(ref1[q]), 1)),
            record("polygons", 360, cyc, worst(kin, lambda i, q: polygon_value(sols[i], q), 360)),
            record("closed-form-numpy", 360, base, worst(kin, lambda i, q: float(ref[q][i]), 360))]


def polygon_records(repeat: int = 7) -> list[dict[str, Any]]:
    """Every case's records (:func:`case_records`), case by case."""
    return [r for case in CASES for r in case_records(case, repeat)]


def _met(ok: bool) -> str:
    return "met" if ok else "not met"


def bench(quick: bool = False) -> tuple[list[dict[str, Any]], list[str]]:
    """The polygons' records and the notes comparing them with the targets: one line a case."""
    records = polygon_records(repeat=3 if quick else 7)
    by = {(r["case"], r["method"], r["n"]): r for r in records}
    notes = []
    for case in CASES:
        one, cyc = by[(case.name, "polygons", 1)], by[(case.name, "polygons", 360)]
        scalar, base = by[(case.name, "closed-form-scalar", 1)], by[(case.name, "closed-form-numpy", 360)]
        r360, r1 = cyc["seconds"] / base["seconds"], one["seconds"] / scalar["seconds"]
        notes.append(f"{case.name}: 360 positions {cyc['seconds'] * 1e6:.0f} µs = {r360:.2f}× closed-form "
                     f"numpy (target ≤ 1.5×: {_met(r360 <= 1.5)}); one position {one['seconds'] * 1e6:.1f} µs = "
                     f"{r1:.2f}× closed-form scalar (target ≤ 2×: {_met(r1 <= 2.0)}); agreement "
                     f"{max(one['max_rel_error'], cyc['max_rel_error']):.1e} (target ≤ 1e-12)")
    return records, notes
