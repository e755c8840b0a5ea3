"""The construction graph: pruning to what is asked, single and batch evaluation, no NaN."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.problems.linkage.bench import FOURBAR_QUANTITIES, fourbar
from graphmech.errors import DegenerateConstruction
from graphmech.exact.linkage import solve
from graphmech.mechanisms.linkage import Crank, Linkage, RRR
from graphmech.methods.polygons import build_polygons

SCALES = {"l": 0.002, "v": 0.01, "a": 0.1}


def test_prune_keeps_only_the_dependencies():
    b = build_polygons(fourbar(), SCALES)
    plan = b.g.prune([b.quantities["v_C"].slot])
    names = {s.name for s in plan.steps}
    assert {"B", "C", "v:b", "v:c"} <= names
    assert not any(n.startswith("a:") for n in names)  # no acceleration polygon for a velocity
    assert "m:omega_2" not in names
    full = b.g.prune([b.quantities[q].slot for q in FOURBAR_QUANTITIES])
    assert len(full.steps) > len(plan.steps)


def test_batch_equals_single_position_evaluation():
    b = build_polygons(fourbar(), SCALES)
    plan = b.g.prune([b.quantities[q].slot for q in FOURBAR_QUANTITIES])
    phis = np.radians(np.arange(0, 360, 7.5))
    batch = plan.evaluate_batch({"phi": phis})
    assert batch.valid.all()
    for i in (0, 13, 40):
        single = plan.solve({"phi": float(phis[i])})
        for q in FOURBAR_QUANTITIES:
            slot = b.quantities[q].slot
            d1, s1 = single[slot]
            d2, s2 = batch.at(i)[slot]
            assert d1 * s1 == pytest.approx(d2 * s2, rel=1e-13, abs=1e-15)


def test_graphical_equals_exact_over_a_cycle():
    from graphmech.problems.linkage.sizes import characteristic
    from graphmech.problems.linkage.check import exact_value

    lk = fourbar()
    b = build_polygons(lk, SCALES)
    plan = b.g.prune([b.quantities[q].slot for q in FOURBAR_QUANTITIES])
    phis = np.radians(np.arange(0.0, 360.0, 5.0))
    batch = plan.evaluate_batch({"phi": phis})
    kin = solve(lk, phis)
    for i in range(len(phis)):
        sol = batch.at(i)
        for q in FOURBAR_QUANTITIES:
            qq = b.quantities[q]
            d, s = sol[qq.slot]
            e = exact_value(kin, qq.exact, i)
            assert abs(d * s - e) <= 1e-12 * max(abs(e), characteristic(lk, qq.unit)), (q, i)


def non_grashof() -> Linkage:
    return Linkage({"A": (0.0, 0.0), "D": (0.08, 0.0)}, Crank("1", "A", "B", 0.06, 10.0),
                   (RRR("B", "C", "D", ("2", "3"), (0.03, 0.04), "left"),))


def test_batch_marks_positions_that_cannot_be_assembled_and_never_gives_nan():
    b = build_polygons(non_grashof(), SCALES)
    plan = b.g.prune([b.quantities[q].slot for q in ("v_C", "a_C", "alpha_3")])
    phis = np.radians(np.arange(0.0, 360.0, 10.0))
    batch = plan.evaluate_batch({"phi": phis})
    # the crank of this double rocker reaches only |φ| ≤ 57.9°
    assert batch.valid.tolist() == [abs(((p + 180) % 360) - 180) < 57.9 for p in np.degrees(phis)]
    for v in batch.values.values():
        for a in (v if isinstance(v, tuple) else (v,)):
            assert np.isfinite(np.asarray(a, dtype=float)).all()
    (mask, reason), = [(m, r) for s, (m, r) in batch.failures.items()]
    assert "cannot be assembled" in reason and mask.sum() == (~batch.valid).sum()


def test_single_position_failure_names_the_step_and_position():
    b = build_polygons(non_grashof(), SCALES)
    plan = b.g.prune([b.quantities["v_C"].slot])
    with pytest.raises(DegenerateConstruction) as e:
        plan.solve({"phi": math.radians(170.0)}, "φ₁ = 170°")
    msg = str(e.value)
    assert msg == ("C = circle(B, l2) ∩ circle(D, l3), left of B→D: cannot be assembled at φ₁ = 170°: "
                   "|BD| = 0.1395 m > l2 + l3 = 0.07 m")


def test_a_step_is_defined_once_and_only_after_what_it_reads():
    from graphmech.construction import Construction

    g = Construction()
    g.add("P", "point", lambda ops: (0.0, 0.0), ())
    with pytest.raises(KeyError, match="defined twice"):
        g.add("P", "point", lambda ops: (1.0, 0.0), ())
    with pytest.raises(KeyError, match="'Q', which is not defined before it"):
        g.add("R", "point", lambda ops, q: q, ("Q",))
    with pytest.raises(KeyError, match="no step named 'Z'"):
        g.prune(["Z"])
    assert g.steps["P"].text == "P"  # a step without words is named by its name


def test_a_lines_drawn_extent_keeps_only_the_points_the_plan_holds():
    from graphmech.construction import Construction
    from graphmech.geometry import kernels as K

    g = Construction()
    g.add("p", "point", lambda ops: (0.0, 0.0), ())
    g.add("l", "line", lambda ops, p: (p[0], p[1], 1.0, 0.0), ("p",))
    g.add("m", "line", lambda ops: (3.0, 0.0, 0.0, 1.0), ())
    g.add("x", "point", K.intersect_lines, ("l", "m"))
    g.add("far", "point", lambda ops: (9.0, 0.0), ())
    g.extend_line("l", "x", "far")
    assert g.extent["l"] == ["p", "x", "far"] and g.extent["m"] == []
    plan = g.prune(["x"])
    assert plan.extent == {"l": ["p", "x"], "m": []}
    assert "far" not in plan and "x" in plan
    assert plan.evaluate({})["x"] == (3.0, 0.0)


def test_steps_without_inputs_are_evaluated_once_when_pruned():
    from graphmech.construction import Construction

    calls = []
    g = Construction()
    g.param("t")
    g.add("O", "point", lambda ops: calls.append(1) or (1.0, 2.0), ())
    g.add("P", "point", lambda ops, t, o: (o[0] + t, o[1]), ("t", "O"))
    plan = g.prune(["P"])
    assert [plan.evaluate({"t": t})["P"] for t in (0.0, 1.0, 2.0)] == [(1.0, 2.0), (2.0, 2.0), (3.0, 2.0)]
    assert plan.evaluate_batch({"t": np.array([0.0, 5.0])})["P"][0].tolist() == [1.0, 6.0]
    assert calls == [1]


def test_values_at_one_position_of_a_batch():
    from graphmech.construction.graph import values_at

    vals = {"x": np.array([1.0, 2.0]), "p": (np.array([3.0, 4.0]), 7.0), "c": np.float64(5.0), "n": "name"}
    got = values_at(vals, 1)
    assert got == {"x": 2.0, "p": (4.0, 7.0), "c": 5.0, "n": "name"}
    assert type(got["x"]) is float and type(got["p"][0]) is float


def test_a_step_keeps_its_protocol_phrase_and_a_plain_step_has_none():
    from graphmech.construction import Construction

    g = Construction()
    g.add("A", "point", lambda ops: (0.0, 0.0), (), say=("frame", "A"))
    g.add("B", "point", lambda ops, a: (a[0] + 1.0, 0.0), ("A",))
    assert g.steps["A"].say == ("frame", "A") and g.steps["B"].say == ()
    assert g.prune(["B"]).by_name["A"].say == ("frame", "A")
