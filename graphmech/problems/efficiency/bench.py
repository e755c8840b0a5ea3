"""Benchmarks of the force polygons of efficiency problems and of the mass-radius polygons.

Records as in :mod:`graphmech.bench`: ``{"method", "case", "n", "seconds", "max_rel_error"}``.

* ``force-polygon`` / ``incline-sweep``: ``n`` inclines (α from 1° to 80°, f = 0.15, both strokes)
  drawn one polygon pair each; error of F against the closed form Q·tan(α ± φ);
* ``force-polygon`` / ``wedge-F1430``: the two strokes of problem F1430 (four triangles);
  error of F against the sine-rule solution;
* ``mass-radius-polygon`` / ``dynamic-random``: a rotor of ``n`` masses balanced in two planes;
  error of the corrections against the equations of balance solved by Cramer's rule, relative to
  Σ m·r.

Speed is measured here, never in timed tests.
"""
from __future__ import annotations

import math
import random
from typing import Any, cast

from graphmech.exact import balancing as exb
from graphmech.exact import efficiency as exe
from graphmech.mechanisms.rotor import RotorMass
from graphmech.methods import balancing as gmb
from graphmech.methods import efficiency as gme
from graphmech.timing import best_time

__all__ = ["efficiency_records"]



def efficiency_records(repeat: int = 5, ns: tuple[int, ...] = (10, 100, 1000),
                       masses: tuple[int, ...] = (4, 16, 64, 256, 1024)) -> list[dict[str, Any]]:
    """Run time and error of the force and mass-radius polygons."""
    records: list[dict[str, Any]] = []
    phi = math.atan(0.15)
    for n in ns:
        alphas = [math.radians(1.0 + 79.0 * k / max(n - 1, 1)) for k in range(n)]

        def sweep() -> float:
            err = 0.0
            for a in alphas:
                for d in ("forward", "reverse"):
                    s = gme.incline(1000.0, a, phi, d, 10.0)
                    e = exe.incline_force(1000.0, a, phi, d)
                    err = max(err, abs(cast(float, s.F) - e) / max(abs(e), 1000.0))  # none self-locks (α ≤ 80°)
            return err

        secs, err = best_time(sweep, repeat)
        records.append({"method": "force-polygon", "case": "incline-sweep", "n": n, "seconds": secs,
                        "max_rel_error": err})

    def wedge() -> float:
        err = 0.0
        g = b = math.radians(60.0)
        for d in ("forward", "reverse"):
            s = gme.wedge(1000.0, g, b, phi, d, 25.0)
            e = exe.wedge_forces(1000.0, g, b, phi, d).F
            err = max(err, abs(cast(float, s.F) - e) / abs(e))  # F1430's wedge moves both ways
        return err

    secs, err = best_time(wedge, repeat)
    records.append({"method": "force-polygon", "case": "wedge-F1430", "n": 2, "seconds": secs, "max_rel_error": err})
    rng = random.Random(5)
    for n in masses:
        rotor = [RotorMass(str(k + 1), rng.uniform(0.5, 20.0), rng.uniform(0.02, 0.4), rng.uniform(0, 2 * math.pi),
                          rng.uniform(-0.1, 1.1)) for k in range(n)]
        size = sum(u.m * u.r for u in rotor)

        def balance() -> float:
            I, II = gmb.dynamic_balance(rotor, 0.0, 1.0, (0.3, 0.3), 0.01)
            WI, WII = exb.dynamic_correction([exb.Unbalance(u.m, u.r, u.theta, u.z) for u in rotor], 0.0, 1.0)
            return max(abs(c.vector - w)
                       for c, w in ((I, WI), (II, WII))) / size

        secs, err = best_time(balance, repeat)
        records.append({"method": "mass-radius-polygon", "case": "dynamic-random", "n": n, "seconds": secs,
                        "max_rel_error": err})
    return records


def bench(quick: bool = False) -> tuple[list[dict[str, Any]], list[str]]:
    """The efficiency polygons' and the mass-radius polygons' records (no notes)."""
    return efficiency_records(repeat=2 if quick else 5), []
