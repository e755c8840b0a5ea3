"""Benchmarks of the true motion: scipy's stiff solvers on the compressor of the course project.

Each record is ``{"method", "case", "n", "seconds", "max_rel_error", "rtol", "solver", "cycles",
"nfev"}`` as in :mod:`graphmech.bench`: ``n`` is the accepted steps per cycle (of the last,
periodic cycle), ``seconds`` the best wall time of one whole periodic solve (tables, every cycle
and the refinement of the extremes), ``max_rel_error`` is ``|δ − δ_ref|/δ_ref``. Speed is measured
here, never in timed tests.

Cases (``fly.compressor_course_project``, J_F of the exact Wittenbauer form):

* ``compressor-constant``: the constant balancing moment; δ_ref from the energy equation
  (:meth:`ExactMachine.energy_motion`), which needs no integration at all;
* ``compressor-stiff-1e5``: the motor characteristic of stiffness 1e5 (its time constant is
  1e-5 rad of crank travel); δ_ref from Radau at rtol 1e-13.

One more record, ``true-motion-explicit`` (only with ``graphmech bench --explicit``: it takes
about 13 s), gives RK45's accepted steps on the stiff case for one cycle (extrapolated from twelve
1° samples in quick mode, said so in its ``note``).
"""
from __future__ import annotations

import dataclasses
import math
import time
from functools import partial
from typing import Any, Literal, cast

import numpy as np

from graphmech.exact.flywheel import ExactMachine
from graphmech.exact.true_motion import integrate, true_motion
from graphmech.mechanisms.linkage import RRP, Crank, Guide, Linkage, LinkPoint
from graphmech.mechanisms.machine import Machine, Mass, Motor, SliderLoad, Table
from graphmech.accuracy import convergence_order, estimate_from_three
from graphmech.timing import best_time

__all__ = ["RTOLS", "SOLVERS", "compressor_machine", "explicit_record", "true_motion_records"]

SOLVERS = ("Radau", "BDF", "LSODA")
RTOLS = (1e-4, 1e-6, 1e-8, 1e-10, 1e-12)
QUICK_RTOLS = (1e-4, 1e-8, 1e-12)
#: Stiffness ratio of the motor case: [M0/(ω_s − ω_m)]/(J_F + max Jп) over ω_m.
STIFFNESS = 1e5


def compressor_machine(motor: Motor | None = None) -> Machine:
    """The offset slider-crank compressor of ``fly.compressor_course_project``.

    Crank 75 mm at 960 rev/min CCW, rod 300 mm (S2 100 mm from B, 3 kg, 0.025 kg·m²), piston
    4.5 kg on the guide y = +10 mm, J1 = 0.05 kg·m², bore 120 mm, the indicator diagram on the
    compression stroke (piston moving away from A, gas force toward A), δ = 1/25, a constant
    driving moment. Position 1 is the outer dead centre.

    Parameters
    ----------
    motor : Motor, optional
        For the true motion with a motor characteristic (None: constant driving moment).

    Examples
    --------
    >>> m = compressor_machine()
    >>> round(math.degrees(m.start), 4), m.loads[0].during
    (1.5281, 'forward')
    """
    e, lab, lbc = 0.010, 0.075, 0.300
    wm = 960 * math.pi / 30
    link = Linkage({"A": (0.0, 0.0)}, Crank("1", "A", "B", lab, wm),
                   (RRP("B", "C", ("2", "3"), lbc, Guide((0.0, e), 0.0), "forward"),),
                   (LinkPoint("S2", "2", ("B", "C"), 0.100, 0.0),), frame_link="4")
    area = math.pi * 0.12 ** 2 / 4
    p_mpa = (0, .014, .032, .055, .087, .132, .201, .317, .5, .5, .5)
    table = Table((0, .1, .2, .3, .4, .5, .6, .7, .8, .9, 1), tuple(p * 1e6 * area for p in p_mpa))
    return Machine(link, start=math.asin(e / (lab + lbc)), cycle=2 * math.pi, omega_m=wm,
                   delta=0.04,
                   masses=(Mass("1", "A", 0.0, 0.05), Mass("2", "S2", 3.0, 0.025),
                           Mass("3", "C", 4.5, 0.0)),
                   loads=(SliderLoad("C", 0.0, -1, "forward", table),), balance="driving",
                   motor=motor)



def _explicit_record(stiff: Machine, exact: ExactMachine, J_F: float, omega0: float,
                     quick: bool, rtol: float = 1e-10) -> dict[str, Any]:
    """RK45's accepted steps for one cycle of the stiff case, from the periodic ω0."""
    t = time.perf_counter()
    if quick:  # twelve 1° windows, each entered on the periodic motion (found by Radau)
        steps = nfev = 0
        width = math.radians(1.0)
        for k in range(12):
            a = exact.cycle * k / 12 + math.radians(5.0)
            w = integrate(stiff, exact, J_F, (0.0, a), omega0, rtol=rtol).omega
            run = integrate(stiff, exact, J_F, (a, a + width), w, solver="RK45", rtol=rtol)
            steps, nfev = steps + run.steps, nfev + run.nfev
        scale = exact.cycle / (12 * width)
        n, nfev = round(steps * scale), round(nfev * scale)
        note = f"extrapolated ×{scale:.0f} from twelve 1° windows ({steps} steps)"
    else:
        run = integrate(stiff, exact, J_F, (0.0, exact.cycle), omega0, solver="RK45", rtol=rtol)
        n, nfev = run.steps, run.nfev
        note = "one whole cycle from the periodic ω0"
    secs = time.perf_counter() - t
    return {"method": "true-motion-explicit", "case": "compressor-stiff-1e5",
            "n": n, "seconds": secs, "max_rel_error": None, "rtol": rtol, "solver": "RK45",
            "cycles": 1, "nfev": nfev, "note": note}


def true_motion_records(quick: bool = False) -> list[dict[str, Any]]:
    """Steps, time and δ error of Radau, BDF and LSODA against rtol, constant and stiff drive."""
    repeat = 1 if quick else 2  # 25 ms … 0.9 s a run: two are enough to leave a disturbance out
    rtols = QUICK_RTOLS if quick else RTOLS
    plain = compressor_machine()
    exact = ExactMachine(plain)
    J_F = exact.wittenbauer("exact").J_F
    stiff = dataclasses.replace(plain, motor=Motor(stiffness=STIFFNESS))
    ref_stiff = true_motion(stiff, exact, J_F, solver="Radau", rtol=1e-13)
    cases = (("compressor-constant", plain, exact.energy_motion(J_F).delta),
             ("compressor-stiff-1e5", stiff, ref_stiff.delta))
    records = []
    for case, machine, d_ref in cases:
        for solver in SOLVERS:
            for rtol in rtols:
                secs, tm = best_time(partial(true_motion, machine, exact, J_F, solver=solver, rtol=rtol),
                                 repeat)
                records.append({"method": "true-motion", "case": case, "n": tm.steps, "seconds": secs,
                                "max_rel_error": abs(tm.delta - d_ref) / d_ref, "rtol": rtol,
                                "solver": solver, "cycles": tm.cycles, "nfev": tm.nfev})
    return records


def explicit_record(quick: bool = False) -> dict[str, Any]:
    """``true-motion-explicit``: RK45's steps on the stiff case (``graphmech bench --explicit``; about
    13 s for the whole cycle, so not in the default run)."""
    plain = compressor_machine()
    exact = ExactMachine(plain)
    J_F = exact.wittenbauer("exact").J_F
    stiff = dataclasses.replace(plain, motor=Motor(stiffness=STIFFNESS))
    ref = true_motion(stiff, exact, J_F, solver="Radau", rtol=1e-13)
    return _explicit_record(stiff, exact, J_F, ref.omega0, quick)


def true_motion_notes(records: list[dict[str, Any]]) -> list[str]:
    """One-line findings: the stiff Radau solve's time, and RK45's steps against Radau's."""
    by = {(r["method"], r["case"], r["solver"], r["rtol"]): r for r in records}
    notes = []
    radau = by.get(("true-motion", "compressor-stiff-1e5", "Radau", 1e-10))
    if radau is None:
        radau = by.get(("true-motion", "compressor-stiff-1e5", "Radau", 1e-8))
    if radau is not None:
        notes.append(f"stiff periodic solve, Radau rtol {radau['rtol']:.0e}: {radau['seconds'] * 1e3:.0f} ms "
                     f"(target < 100 ms), {radau['n']} steps/cycle, {radau['cycles']} cycles")
        rk = [r for r in records if r["method"] == "true-motion-explicit"]
        if rk:
            notes.append(f"RK45 needs {rk[0]['n']} steps for one stiff cycle = {rk[0]['n'] / radau['n']:.0f}× "
                         f"Radau's ({rk[0]['note']})")
    return notes


#: Positions of the Wittenbauer benchmark (the course project's 12, then finer).
WITTENBAUER_N = (12, 24, 36, 72, 360, 3600)


def wittenbauer_records(repeat: int = 5, ns: tuple[int, ...] = WITTENBAUER_N) -> list[dict[str, Any]]:
    """J_F of the compressor by the whole graphical pipeline at N positions against the exact J_F.

    One run = the velocity polygons at N positions (Jп, Mп), graphical integration, the balancing
    moment, ΔT, the Wittenbauer diagram and its tangents (or the energy indicator). The exact J_F
    takes the tangents to the continuous curve (:class:`graphmech.exact.flywheel.ExactMachine`).
    """
    from graphmech.exact.flywheel import ExactMachine
    from graphmech.methods.flywheel import FlywheelDesign, design_flywheel
    from graphmech.methods.reduction import reduce_to_crank

    m = compressor_machine()
    ex = ExactMachine(m)
    refs = {"exact": ex.wittenbauer("exact").J_F, "book": ex.wittenbauer("book").J_F, "indicator": ex.indicator().J_F}
    dw_ref = ex.indicator().delta_W
    records = []
    for case, ref in refs.items():
        need = ("indicator",) if case == "indicator" else ("wittenbauer",)
        form: Literal["exact", "book"] = "book" if case == "book" else "exact"
        def design(n: int) -> FlywheelDesign:
            r = reduce_to_crank(m, np.asarray(m.positions(n)), {"l": 0.002, "v": 0.05})
            return design_flywheel(r.phi, r.J, r.M, cycle=m.cycle, omega_m=m.omega_m, delta=m.delta,
                                   balance=m.balance, form=form, H_mm=40.0, need=need)

        def j_f(d: FlywheelDesign) -> float:
            return cast(float, d.J_F_indicator if case == "indicator" else d.J_F)  # the one asked for (need)

        for n in ns:
            secs, d = best_time(lambda: design(n), repeat, 1)
            got = j_f(d)
            # what the method says of its own error: the same pipeline at 2N and 4N (not timed)
            estimate = estimate_from_three(got, j_f(design(2 * n)), j_f(design(4 * n))) / abs(got)
            records.append({"method": "wittenbauer" if case != "indicator" else "energy-indicator",
                            "case": f"compressor-{case}", "n": n, "seconds": secs,
                            "max_rel_error": abs(got - ref) / abs(ref), "error_estimate": estimate,
                            "J_F": got, "J_F_exact": ref,
                            "DeltaW_max_rel_error": abs(d.dT_max - d.dT_min - dw_ref) / dw_ref})
    return records


def _flywheel_notes(records: list[dict[str, Any]]) -> list[str]:
    out = []
    for case in dict.fromkeys(r["case"] for r in records if r["method"] in ("wittenbauer", "energy-indicator")):
        rs = [r for r in records if r["case"] == case]
        o = convergence_order(rs)
        big = max(rs, key=lambda r: r["n"])
        out.append(f"{rs[0]['method']} {case}: J_F error " + ", ".join(f"{r['max_rel_error']:.1e} (N={r['n']})" for r in rs)
                   + f"; order {o['overall']:.2f}; N = {big['n']} in {big['seconds'] * 1e3:.1f} ms (target < 200 ms)")
    return out


def bench(quick: bool = False) -> tuple[list[dict[str, Any]], list[str]]:
    """J_F by the Wittenbauer diagram and the energy indicator against N, and the true motion's
    integrators; the notes on their convergence."""
    records = wittenbauer_records(repeat=2 if quick else 5)
    return records + true_motion_records(quick=quick), _flywheel_notes(records)
