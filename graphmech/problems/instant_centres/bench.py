"""Benchmarks of the instant-centre method and of the mobility count and rank.

Records as in :mod:`graphmech.bench` (``{"method", "case", "n", "seconds", "max_rel_error"}``):

* ``instant-centres``, ``fourbar-120-60-120-90``: all six centres, and the coupler's and the
  rocker's ω and v_C from them, at n positions of the bench's four-bar, as arrays over the
  positions (:func:`graphmech.methods.instant_centres.instant_centres_batch`: Kennedy's order worked
  out once; the record ``instant-centres-per-position`` times the one-by-one construction); the error is the largest relative difference of the two ω (to the crank's) and of v_C (to
  ω·l_AB) from :mod:`graphmech.exact.linkage`;
* ``mobility-rank``, the topology of ``dof.hfut_cases-3-2`` (9 links, 13 pairs): the count, the
  constraint Jacobian's SVD and the Assur decomposition; its error is |F − F_actual|.
"""
from __future__ import annotations

import math
import time
from typing import TYPE_CHECKING, Any, Callable, cast

import numpy as np

if TYPE_CHECKING:
    from graphmech.mechanisms.linkage import Crank

__all__ = ["ic_records"]


def _best(fn: Callable[[], Any], repeat: int) -> float:
    best = math.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def ic_records(quick: bool = False) -> list[dict[str, Any]]:
    from graphmech.problems.linkage.bench import fourbar
    from graphmech.exact.linkage import solve
    from graphmech.mechanisms.topology import Pair, Topology, mobility, structure
    from graphmech.methods.instant_centres import instant_centres, instant_centres_batch
    from graphmech.methods.polygons import build_polygons

    linkage = fourbar()
    mu = 0.002
    b = build_polygons(linkage, {"l": mu, "v": 1.0, "a": 1.0})
    plan = b.g.prune(list(b.mech.values()))
    repeat = 2 if quick else 5
    records = []
    for n in (1, 360):
        phi = np.radians(np.arange(n) * (360.0 / n) + 0.5)
        batch = plan.evaluate_batch({b.param: phi})
        sols = [batch.at(i) for i in range(n)]
        pos = [{k: (float(s.values[v][0]), float(s.values[v][1])) for k, v in b.mech.items()} for s in sols]
        arrays = {k: batch.values[v] for k, v in b.mech.items()}

        def run(pos: list[dict[str, tuple[float, float]]] = pos) -> list[Any]:
            return [instant_centres(linkage, p, mu_l=mu) for p in pos]

        def run_batch(arrays: dict[str, Any] = arrays, n: int = n) -> Any:
            return instant_centres_batch(linkage, arrays, n, mu_l=mu)

        kin = solve(linkage, phi)
        w1 = abs(cast("Crank", linkage.driver).omega)
        l1 = cast("Crank", linkage.driver).length
        err = 0.0
        for i, ic in enumerate(run()):
            for lid in ("2", "3"):
                err = max(err, abs(ic.motions[lid].omega - kin.omega[lid][i]) / w1)
            c = ic.motions["3"].velocity(pos[i]["C"])
            v = math.hypot(*c) * mu
            err = max(err, abs(v - float(np.hypot(*kin.vel["C"][i]))) / (w1 * l1))
        records.append({"method": "instant-centres-per-position", "case": "fourbar-120-60-120-90", "n": n,
                        "seconds": _best(run, repeat), "max_rel_error": err})
        cb = run_batch()
        err_b = max(float(np.max(np.abs(cb.omega[lid] - kin.omega[lid]))) / w1 for lid in ("2", "3"))
        v_c = np.hypot(*cb.velocity("3", arrays["C"]).T) * mu
        err_b = max(err_b, float(np.max(np.abs(v_c - np.hypot(*kin.vel["C"].T)))) / (w1 * l1))
        records.append({"method": "instant-centres", "case": "fourbar-120-60-120-90", "n": n,
                        "seconds": _best(run_batch, repeat * 4), "max_rel_error": err_b})

    def R(a: str, c: str, name: str, at: tuple[float, float]) -> Pair:
        return Pair("R", (a, c), name, at)

    topo = Topology("1", ("2", "3", "4", "5", "6", "7", "8", "9", "10"), (
        R("1", "2", "A", (0.0, 0.0)), Pair("higher", ("2", "3"), "K", (0.0, 0.04), math.pi / 2),
        R("3", "4", "B", (0.0, 0.05)), R("4", "1", "C", (-0.06, 0.06)), R("4", "5", "D", (-0.04, 0.09)),
        R("5", "6", "E", (0.02, 0.12)), R("6", "1", "F", (0.06, 0.06)), R("6", "7", "G", (0.08, 0.13)),
        R("7", "8", "H", (0.16, 0.12)), Pair("P", ("8", "1"), "H′", (0.16, 0.12), 0.0),
        R("7", "9", "I", (0.12, 0.15)), R("9", "10", "J", (0.15, 0.19)), R("10", "1", "L", (0.2, 0.17))),
        ("2",))

    def analyse() -> tuple[Any, Any]:
        return mobility(topo, True), structure(topo)

    secs = _best(analyse, repeat * 4)
    m, _ = analyse()
    records.append({"method": "mobility-rank", "case": "hfut-3-2-roller", "n": len(topo.pairs), "seconds": secs,
                    "max_rel_error": float(abs(m.F - (m.F_actual or 0)))})
    return records
