"""Benchmarks of kinetostatics: the six-bar of ``force.sixbar_kinetostatic`` over a cycle.

Each record is ``{"method": "kinetostatics", "case", "n", "seconds", "max_rel_error", ...}`` as in
:mod:`graphmech.bench`. One run is the whole graphical pipeline at ``n`` crank positions at once:
the polygon construction evaluated (positions, velocity and acceleration images), the inertia
loads, the force polygons group by group, the balancing moment and Zhukovsky's lever. The matrix
method is timed apart (``matrix_seconds``). ``max_rel_error`` is the largest disagreement of the
three answers — every reaction polygon vs matrix, M_b polygon vs matrix, M_b lever vs matrix —
relative to the largest reaction (× the crank's length for moments) at that position.

Cases: ``sixbar`` (frictionless); ``sixbar-friction`` (friction circles in all six journals and a
friction angle on the guide, successive approximation vectorised over the positions, against
scipy's ``root`` position by position; ``rounds`` is how many rounds it took).
"""
from __future__ import annotations

from typing import Any, cast

import numpy as np

from graphmech.exact.kinetostatics import solve_forces
from graphmech.exact.linkage import solve as solve_exact
from graphmech.mechanisms.forces import ForceModel, LinkMass, PointForce, RevoluteFriction, SlidingFriction
from graphmech.mechanisms.linkage import RRP, RRR, Crank, Guide, Linkage, LinkPoint
from graphmech.methods.kinetostatics import (
    KinetostaticSolution,
    Lever,
    construction_targets,
    kinematics_from_construction,
    kinetostatics,
    zhukovsky_lever,
)
from graphmech.methods.polygons import build_polygons
from graphmech.timing import best_time

__all__ = ["sixbar", "sixbar_loads", "kinetostatic_records", "kinetostatic_notes"]


def sixbar() -> Linkage:
    """Crank AB 80 mm at 12 rad/s, RRR B–C–D (280, 200 mm), E on DC at 400 mm, RRP E–F 350 mm on y = 300 mm."""
    return Linkage(
        {"A": (0.0, 0.0), "D": (0.3, -0.06)},
        Crank("1", "A", "B", 0.08, 12.0),
        (RRR("B", "C", "D", ("2", "3"), (0.28, 0.2), "left"),
         RRP("E", "F", ("4", "5"), 0.35, Guide((0.0, 0.3), 0.0), "backward")),
        (LinkPoint("E", "3", ("D", "C"), 0.4, 0.0), LinkPoint("S2", "2", ("B", "C"), 0.14, 0.0),
         LinkPoint("S3", "3", ("D", "C"), 0.22, 0.0), LinkPoint("S4", "4", ("E", "F"), 0.175, 0.0),
         LinkPoint("K", "5", ("F",), 0.0, -0.015)),
        "0",
    )


def sixbar_loads(friction: bool = False) -> ForceModel:
    """Masses, gravity and the working resistance of the six-bar; with friction if asked."""
    masses = (LinkMass("1", "A", 2.0), LinkMass("2", "S2", 4.0, 0.03), LinkMass("3", "S3", 6.0, 0.09),
              LinkMass("4", "S4", 3.5, 0.036), LinkMass("5", "F", 12.0))
    forces = (PointForce("5", "K", 1000.0, 0.0, True, "P_r"),)
    if not friction:
        return ForceModel(masses, forces, gravity=9.81)
    journals = tuple(RevoluteFriction(p, 0.15, r) for p, r in zip("ABCDEF", (0.02, 0.015, 0.015, 0.02, 0.012, 0.012)))
    return ForceModel(masses, forces, gravity=9.81, revolute_friction=journals,
                      sliding_friction=(SlidingFriction("5", 0.1),))



def _disagreement(sol: Any, lever: Any, ex: Any, crank: float) -> dict[str, float]:
    """Largest |polygon − matrix| (reactions, M_b) and |lever − matrix| (M_b), relative."""
    scale = np.max(np.stack([np.abs(r) for r in sol.reactions.values()]), axis=0)
    scale = np.where(scale > 0, scale, 1.0)
    poly = 0.0
    for key, r in sol.reactions.items():
        e = ex.reactions[key][:, 0] + 1j * ex.reactions[key][:, 1]
        poly = max(poly, float(np.max(np.abs(r - e) / scale)))
    mb = float(np.max(np.abs(sol.balancing_moment - ex.balancing_moment) / (scale * crank)))
    out = {"polygon_vs_matrix": max(poly, mb)}
    if lever is not None:
        out["lever_vs_matrix"] = float(np.max(np.abs(lever.balancing_moment - ex.balancing_moment) / (scale * crank)))
    return out


def kinetostatic_records(quick: bool = False) -> list[dict[str, Any]]:
    """The six-bar at 1 and 360 positions, frictionless and with friction."""
    lk = sixbar()
    b = build_polygons(lk, {"l": 0.005, "v": 0.02, "a": 0.1})
    plan = b.g.prune(construction_targets(b))
    repeat = 3 if quick else 7
    records = []
    for case, friction in (("sixbar", False), ("sixbar-friction", True)):
        model = sixbar_loads(friction)
        for n in (1, 360):
            phi = np.radians(np.arange(n) * (360.0 / n) + (120.0 if n == 1 else 0.0))

            def run() -> tuple[KinetostaticSolution, Lever | None]:
                batch = plan.evaluate_batch({"phi": phi})
                kin = kinematics_from_construction(b, batch.values, batch.valid)
                sol = kinetostatics(lk, model, kin, polygons=False)
                lever = zhukovsky_lever(lk, model, kin) if not friction else None
                return sol, lever

            secs, (sol, lever) = best_time(run, repeat)
            kin_exact = solve_exact(lk, phi)
            m_secs, ex = best_time(lambda: solve_forces(lk, model, phi, kin_exact), 1 if friction else repeat)
            d = _disagreement(sol, lever, ex, cast("Crank", lk.driver).length)
            records.append({"method": "kinetostatics", "case": case, "n": n, "seconds": secs,
                            "max_rel_error": max(d.values()), **d, "matrix_seconds": m_secs,
                            "rounds": sol.iterations})
    return records


def kinetostatic_notes(records: list[dict[str, Any]]) -> list[str]:
    out = []
    for r in records:
        if r["method"] == "kinetostatics" and r["n"] > 1:
            lever = f", lever vs matrix {r['lever_vs_matrix']:.1e}" if "lever_vs_matrix" in r else ""
            out.append(f"kinetostatics {r['case']}: {r['n']} positions in {r['seconds'] * 1e3:.1f} ms "
                       f"(matrix method {r['matrix_seconds'] * 1e3:.1f} ms); polygons vs matrix "
                       f"{r['polygon_vs_matrix']:.1e}{lever}"
                       + (f"; {r['rounds']} rounds of successive approximation" if r["rounds"] else ""))
    return out


def bench(quick: bool = False) -> tuple[list[dict[str, Any]], list[str]]:
    """The kinetostatics' records over a 360-position cycle and the notes comparing the methods."""
    records = kinetostatic_records(quick=quick)
    return records, kinetostatic_notes(records)
