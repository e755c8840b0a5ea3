"""Benchmarks of the gear constructions: the involute by points and the meshing.

Records as in :mod:`graphmech.bench`: ``{"method", "case", "n", "seconds", "max_rel_error"}``.

* ``involute`` / ``z20-m8``: tooth 0 of the gear z = 20, m = 8 mm drawn with ``n`` points per
  flank; the error is the largest distance of the exact involute (its polar equation, densely
  sampled) from the drawn polyline, over the flank's height r_a − r_b — the chords' sag, which
  falls as 1/n²; the points themselves are exact;
* ``gear-mesh`` / each case: the line of action cut by the tip circles, constructed ``n`` = 1
  times per call; the error is the largest relative difference of a′, α′, B₁B₂ and ε from the
  closed forms;
* ``rack-generation`` / each case: the tooth the rack cutter's ``n`` positions per pitch leave
  (:func:`graphmech.methods.rack_generation.generate`); the error is the largest distance of the
  generated outline (its vertices: the cusps between positions and the cutter's own points) from
  the exact profile — involute, fillet (trochoid offset), root and tip arcs — over the module m;
  the scallops fall as 1/n².

Speed is measured here, never in timed tests.
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphmech.exact import gear as ex
from graphmech.exact import rack_generation as erg
from graphmech.mechanisms.gear import GearSet, SpurGear, ToothSystem
from graphmech.methods import gear_meshing as gm
from graphmech.methods import involute as inv
from graphmech.methods import rack_generation as rgen
from graphmech.timing import best_time

#: The involute's point counts per flank.
POINTS = (4, 8, 16, 32, 64, 128, 256)
#: Exact samples between two drawn points.
SAMPLES = 64

Z20 = (ToothSystem(0.008, math.radians(20.0)), SpurGear(20))
MESH_CASES: tuple[tuple[str, GearSet], ...] = (
    ("contact-ratio-19-42", GearSet(ToothSystem(0.005, math.radians(20.0)), (SpurGear(19), SpurGear(42)), "external")),
    ("shifted-12-12-a130", GearSet(ToothSystem(0.010, math.radians(20.0)), (SpurGear(12, 0.3), SpurGear(12, 0.3)),
                                   "external")),
    ("internal-20-80", GearSet(ToothSystem(0.004, math.radians(20.0)), (SpurGear(20), SpurGear(80, internal=True)),
                               "internal")),
    ("rack-z18", GearSet(ToothSystem(0.004, math.radians(20.0)), (SpurGear(18),), "rack")),
    ("external-20-1000", GearSet(ToothSystem(0.002, math.radians(20.0)), (SpurGear(20), SpurGear(1000)), "external")),
)


#: Cutter positions per pitch for the generation.
GENERATION_POSITIONS = (4, 8, 16, 32, 64, 128, 256)
GENERATION_CASES: tuple[tuple[str, ToothSystem, SpurGear], ...] = (
    ("z15-x0", ToothSystem(0.004, math.radians(20.0)), SpurGear(15)),
    ("z18-x-1.5-undercut", ToothSystem(0.004, math.radians(20.0)), SpurGear(18, -1.5)),
)


def generation_records(repeat: int = 3, positions: tuple[int, ...] = GENERATION_POSITIONS) -> list[dict[str, Any]]:
    """The generated tooth against the exact profile, and its time, for each N."""
    records: list[dict[str, Any]] = []
    for case, system, gear in GENERATION_CASES:
        exact = erg.generated_profile(system, gear)
        for n in positions:
            def cut(n: int = n, system: ToothSystem = system, gear: SpurGear = gear) -> rgen.Generation:
                return rgen.generate(system, gear, n)

            secs, gen = best_time(cut, repeat)
            err = float(exact.distance(np.asarray(gen.profile)).max()) / system.m
            records.append({"method": "rack-generation", "case": case, "n": n, "seconds": secs, "max_rel_error": err})
    return records


def flank_error(outline: inv.ToothOutline, rb: float, ra: float) -> float:
    """The drawn right flank of tooth 0 against the exact involute through the same points: the
    largest distance of an exact point between two drawn points from their chord, over r_a − r_b."""
    pts = np.asarray(outline.teeth[0][1].points, dtype=float)
    r = np.hypot(pts[:, 0], pts[:, 1])
    theta = np.arctan2(pts[:, 1], pts[:, 0])
    worst = 0.0
    for k in range(len(pts) - 1):
        rr = np.linspace(r[k], r[k + 1], SAMPLES + 2)[1:-1]
        a = np.arccos(np.clip(rb / rr, -1.0, 1.0))
        a0 = math.acos(min(1.0, rb / r[k]))
        # along one flank the polar angle changes by inv α: θ = θ_k + (inv α − inv α_k), with the
        # flank's sense (tooth 0's right flank turns counter-clockwise outwards)
        sense = 1.0 if theta[k + 1] >= theta[k] else -1.0
        th = theta[k] + sense * ((np.tan(a) - a) - (math.tan(a0) - a0))
        x, y = rr * np.cos(th), rr * np.sin(th)
        (x0, y0), (x1, y1) = pts[k], pts[k + 1]
        dx, dy = x1 - x0, y1 - y0
        d = np.abs((x - x0) * dy - (y - y0) * dx) / max(math.hypot(dx, dy), 1e-300)
        worst = max(worst, float(d.max()))
    return worst / (ra - rb)


def gear_records(repeat: int = 7, points: tuple[int, ...] = POINTS) -> list[dict[str, Any]]:
    """Run time and error of the involute by points and of the meshing construction."""
    records: list[dict[str, Any]] = []
    system, gear = Z20
    t = ex.tooth(system, gear)
    for n in points:
        def draw(n: int = n) -> inv.ToothOutline:
            return inv.tooth_outline(system, gear, teeth=1, points=n)

        secs, outline = best_time(draw, repeat)
        records.append({"method": "involute", "case": "z20-m8", "n": n, "seconds": secs,
                        "max_rel_error": flank_error(outline, t.db / 2.0, t.da / 2.0)})
    for case, gears in MESH_CASES:
        def mesh(gears: GearSet = gears) -> gm.MeshConstruction:
            return gm.construct_meshing(gears)

        secs, c = best_time(mesh, repeat)
        e = ex.meshing(gears)
        err = max(abs(c.a_w - e.a_w) / e.a_w, abs(c.alpha_w - e.alpha_w) / e.alpha_w,
                  abs(c.B1B2 - e.B1B2) / e.B1B2, abs(c.eps_alpha - e.eps_alpha) / e.eps_alpha)
        records.append({"method": "gear-mesh", "case": case, "n": 1, "seconds": secs, "max_rel_error": err})
    return records


def bench(quick: bool = False) -> tuple[list[dict[str, Any]], list[str]]:
    """The gear records and a note on the involute's convergence."""
    records = gear_records(repeat=3 if quick else 7, points=POINTS[:4] if quick else POINTS)
    inv_recs = [r for r in records if r["method"] == "involute"]
    notes = []
    if len(inv_recs) >= 2:
        a, b = inv_recs[-2], inv_recs[-1]
        order = math.log(a["max_rel_error"] / b["max_rel_error"]) / math.log(b["n"] / a["n"])
        notes.append(f"involute by points: the chords' sag falls as n^−{order:.2g} "
                     f"({a['max_rel_error']:.2g} of the flank's height at {a['n']} points, {b['max_rel_error']:.2g} at "
                     f"{b['n']}); the points themselves are exact")
    gen = generation_records(repeat=1 if quick else 3,
                             positions=GENERATION_POSITIONS[:3] if quick else GENERATION_POSITIONS)
    records += gen
    for case, _, _ in GENERATION_CASES:
        mine = [r for r in gen if r["case"] == case]
        a, b = mine[-2], mine[-1]
        order = math.log(a["max_rel_error"] / b["max_rel_error"]) / math.log(b["n"] / a["n"])
        notes.append(f"rack generation {case}: the scallops fall as N^−{order:.2g} ({a['max_rel_error']:.2g}·m at "
                     f"{a['n']} positions per pitch, {b['max_rel_error']:.2g}·m at {b['n']}, {b['seconds']:.2g} s)")
    mesh = [r for r in records if r["method"] == "gear-mesh"]
    notes.append(f"meshing: {len(mesh)} cases, worst relative error {max(r['max_rel_error'] for r in mesh):.2g}")
    return records, notes


__all__ = ["bench", "flank_error", "gear_records", "generation_records"]
