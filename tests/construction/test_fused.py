"""The fused plan: the same bits as the step-by-step run, on both paths, for every reference scene;
degenerate positions run step by step and say what they said before."""
from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from graphmech.construction import fused
from graphmech.construction.graph import Construction, Plan
from graphmech.errors import AssemblyError, DegenerateConstruction
from graphmech.geometry.kernels import ArrayOps, ScalarOps
from graphmech.methods.polygons import build_polygons
from graphmech.problems.linkage.bench import CASES

SCALES = {"l": 0.002, "v": 0.01, "a": 0.1}
SCENES = sorted((Path(__file__).parents[2] / "figures" / "scenes").glob("*.toml"))


def bench_plan(case):
    b = build_polygons(case.linkage(), SCALES)
    return b.g.prune([b.quantities[q].slot for q in case.quantities])


def positions(params):
    return max(np.size(v) for v in params.values())


def step_by_step(plan, params, batch):
    ops = ArrayOps(positions(params)) if batch else ScalarOps()
    return plan._run(ops, params), ops.conds


def fused_run(plan, params, batch):
    sample = step_by_step(plan, params, batch)
    run = fused.fuse(plan._program, plan._constants, plan._params, sample[0], batch)
    ops = ArrayOps(positions(params)) if batch else ScalarOps()
    with np.errstate(all="ignore"):
        return run, (run(ops, params), ops.conds), sample


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
@pytest.mark.parametrize("batch", [False, True], ids=["scalar", "batch"])
def test_the_bench_linkages_fuse_whole_and_give_the_same_bits(case, batch):
    plan = bench_plan(case)
    phis = np.radians(np.arange(0.0, 360.0, 7.0))
    for params in ([{"phi": phis}] if batch else [{"phi": float(p)} for p in phis[::5]]):
        run, got, want = fused_run(plan, params, batch)
        assert fused.same_run(got, want)
    assert " = K" not in run.source  # every step inlined: no kernel called as it is
    assert "C[" in run.source and ("raise Fallback" in run.source)


def test_a_plan_fuses_after_its_runs_and_then_uses_the_fused_function():
    plan = bench_plan(CASES[0])
    for k in range(Plan.FUSE_AFTER[False] + 1):
        assert plan._fused[False] is None
        plan.solve({"phi": 0.3 + k})
    assert callable(plan._fused[False])
    for k in range(Plan.FUSE_AFTER[True] + 1):
        assert plan._fused[True] is None
        plan.evaluate_batch({"phi": np.arange(3.0) + k})
    assert callable(plan._fused[True])
    a, b = plan.solve({"phi": 1.25}), step_by_step(plan, {"phi": 1.25}, False)
    assert fused.same_run((a.values, a.conds), b)


def dead_centre_plan():
    """A double rocker AB 80, BC 100, CD 90, AD 120 mm: it cannot be assembled near φ = 180°
    (|BD| > BC + CD)."""
    from graphmech.mechanisms.linkage import Crank, Linkage, RRR

    lk = Linkage({"A": (0.0, 0.0), "D": (0.12, 0.0)}, Crank("1", "A", "B", 0.08, 10.0),
                 (RRR("B", "C", "D", ("2", "3"), (0.1, 0.09), "left"),), frame_link="4")
    b = build_polygons(lk, SCALES)
    return b.g.prune([b.quantities[q].slot for q in ("v_C", "a_C", "omega_2")])


def test_a_figure_and_a_check_never_pay_for_fusing(monkeypatch):
    """Writing the fused function costs as much as hundreds of runs: the 12-position sheet and
    its check (a few runs a plan) go step by step."""
    from graphmech import api

    fused_now = []
    monkeypatch.setattr(Plan, "_fuse", lambda self, *a: fused_now.append(self))
    p = api.load(Path(__file__).parents[2] / "figures" / "scenes" / "linkage.slider_crank_offset-cycle.toml")
    p.check(), p.render()
    assert fused_now == []


def test_a_degenerate_position_runs_step_by_step_and_says_the_same(monkeypatch):
    monkeypatch.setattr(Plan, "FUSE_AFTER", {False: 2, True: 2})
    plan = dead_centre_plan()
    ok = np.radians([60.0, 90.0, 120.0])
    for _ in range(3):
        plan.evaluate_batch({"phi": ok})
        plan.solve({"phi": float(ok[1])})
    assert callable(plan._fused[True]) and callable(plan._fused[False])
    phis = np.radians(np.arange(0.0, 360.0, 10.0))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the fused run's NaN at the bad position stays silent
        got = plan.evaluate_batch({"phi": phis})
    ops = ArrayOps(phis.size)
    want = plan._run(ops, {"phi": phis})
    assert not got.valid.all() and np.array_equal(got.valid, ~ops.bad)
    assert {k: (m.tolist(), r) for k, (m, r) in got.failures.items()} == \
        {k: (m.tolist(), r) for k, (m, r) in ops.failures.items()}
    assert all(fused.same_bits(got[k], want[k]) for k in want)
    with pytest.raises((AssemblyError, DegenerateConstruction)) as fast:
        plan.solve({"phi": math.pi}, position="φ = 180°")
    with pytest.raises((AssemblyError, DegenerateConstruction)) as slow:
        plan._run(ScalarOps(), {"phi": math.pi})
    assert type(fast.value) is type(slow.value) and "φ = 180°" in str(fast.value)
    assert str(fast.value).replace(" at φ = 180°", "").split(":")[:2] == str(slow.value).split(":")[:2]


def test_a_step_that_branches_on_a_value_is_called_as_it_is():
    g = Construction()
    g.param("t")
    g.add("P", "point", lambda ops, t: (t * 2.0, t + 1.0), ("t",))
    g.add("Q", "point", lambda ops, p: (p[0] if p[0] > 1.0 else -p[0], 3.0), ("P",))  # a branch
    g.add("R", "point", lambda ops, p, q: (ops.hypot(p[0] - q[0], p[1]), q[1] * p[1]), ("P", "Q"))
    plan = g.prune(["R"])
    run, got, want = fused_run(plan, {"phi": 0.2, "t": 0.2}, False)
    assert fused.same_run(got, want)
    assert run.source.count(" = K") == 1  # Q alone


@pytest.mark.parametrize("scene", SCENES, ids=[s.stem for s in SCENES])
def test_every_reference_scene_checks_the_same_with_every_plan_fused_at_once(scene, monkeypatch):
    """Each plan fused on its first run (and checked bit for bit against it there): the check
    table of every reference scene is the one it was."""
    from graphmech import api

    want = api.load(scene).check().to_json()
    refused = []
    real = fused.same_run

    def same(a, b):
        ok = real(a, b)
        if not ok:
            refused.append("a fused plan differs from the step-by-step run")
        return ok

    real_fuse = fused.fuse

    def fuse(*a, **k):
        try:
            return real_fuse(*a, **k)
        except Exception as e:  # a defect in the tracing or the writing
            refused.append(repr(e))
            raise

    monkeypatch.setattr(Plan, "FUSE_AFTER", {False: 0, True: 0})
    monkeypatch.setattr(fused, "same_run", same)
    monkeypatch.setattr(fused, "fuse", fuse)
    assert api.load(scene).check().to_json() == want
    assert refused == []


def test_the_scalar_path_writes_a_value_read_once_inside_its_reader_and_constants_as_literals():
    g = Construction()
    g.param("t")
    g.add("P", "point", lambda ops, t: (ops.maximum(t * 3.0, 1.0), (t + 2.0) * 5.0), ("t",))
    plan = g.prune(["P"])
    run, got, want = fused_run(plan, {"t": 0.25}, False)
    assert fused.same_run(got, want) and got[0]["P"] == (1.0, 11.25)
    lines = run.source.splitlines()
    assert any(line.endswith("= t0 * (3.0)") for line in lines)  # read twice by maximum: a local
    assert any(line.endswith("= (t0 + (2.0)) * (5.0)") for line in lines)  # read once: written inside
    run_b, got_b, want_b = fused_run(plan, {"t": np.array([0.25, 1.0])}, True)
    assert fused.same_run(got_b, want_b) and "(3.0)" not in run_b.source  # numpy 0-d constants
