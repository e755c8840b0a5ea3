"""The step graph of a construction, pruned once, evaluated per position or for many at once.

A :class:`Construction` is what a draftsman does, written down: named steps, each making a
point, line, circle, vector or measured scalar from earlier ones ("through b draw ⟂ BC",
"c = intersection"). It is built once per scene (structure), then :meth:`Construction.prune`
keeps only the steps that the requested outputs depend on and compiles them into a
:class:`Plan`; the plan is evaluated at one position (Python floats — the fast path) or at
many positions at once (numpy arrays). Parameters that change with the position (the crank
angle) are named inputs of the evaluation.

>>> from graphmech.geometry import kernels as K
>>> g = Construction()
>>> _ = g.param("t")
>>> _ = g.add("P", "point", lambda ops, t: (t, 0.0), ("t",), text="P on the x axis")
>>> _ = g.add("Q", "point", lambda ops, p: (p[0], 2.0), ("P",), text="Q above P")
>>> _ = g.add("R", "point", lambda ops: (9.0, 9.0), (), text="R (not needed)")
>>> plan = g.prune(["Q"])
>>> [s.name for s in plan.steps]
['t', 'P', 'Q']
>>> plan.evaluate({"t": 3.0})["Q"]
(3.0, 2.0)
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Iterable, Literal, Mapping, cast

import numpy as np

from graphmech.geometry.kernels import COND_CAP, ArrayOps, ScalarOps

Kind = Literal["point", "line", "circle", "vector", "segment", "scalar", "param"]
Role = Literal["given", "construction", "result", "label", "hidden"]


@dataclass(frozen=True)
class Step:
    """One named step of a construction.

    Attributes
    ----------
    name : str
        Slot name, unique in the construction (``"c"``, ``"⟂BC through b"``).
    kind : str
        What it makes: point, line, circle, vector (drawn as an arrow from its first to its
        second input; no computation), segment (the same without an arrowhead), scalar (a
        measurement) or param.
    kernel : callable or None
        ``kernel(ops, *input_values) -> value``; None for vectors and params.
    inputs : tuple of str
        Names of the steps it reads.
    role : str
        given, construction, result, label, or hidden (computed, never drawn).
    text : str
        The draftsman's words; used in messages ("c = ⟂BC through b ∩ ⟂DC through p").
    panel : str or None
        Which figure it belongs to (mechanism, velocity, acceleration).
    label : str or None
        The letter written at a point ("b", "c′").
    say : tuple of str
        The step for the construction protocol (``graphmech steps``): a phrase's key and its
        arguments, names only (``("perp", "B", "C")``); the kind's protocol words it in the
        scene's notation with the numbers of a solution. Empty: not a step a draftsman writes.
    """

    name: str
    kind: Kind
    kernel: Callable[..., Any] | None
    inputs: tuple[str, ...]
    role: Role = "construction"
    text: str = ""
    panel: str | None = None
    label: str | None = None
    say: tuple[str, ...] = ()


class Construction:
    """A growing graph of steps (structure only: no numbers until evaluated)."""

    def __init__(self) -> None:
        self.steps: dict[str, Step] = {}
        #: line step → the point steps it must be drawn through (its visible extent)
        self.extent: dict[str, list[str]] = {}

    def param(self, name: str) -> str:
        self.steps[name] = Step(name, "param", None, (), role="hidden")
        return name

    def add(
        self,
        name: str,
        kind: Kind,
        kernel: Callable[..., Any] | None,
        inputs: Iterable[str],
        *,
        role: Role = "construction",
        text: str = "",
        panel: str | None = None,
        label: str | None = None,
        say: Iterable[str] = (),
    ) -> str:
        inputs = tuple(inputs)
        if name in self.steps:
            raise KeyError(f"step {name!r} is defined twice")
        for i in inputs:
            if i not in self.steps:
                raise KeyError(f"step {name!r} reads {i!r}, which is not defined before it")
        self.steps[name] = Step(name, kind, kernel, inputs, role, text or name, panel, label,
                                 tuple(say))
        if kind == "line":
            self.extent[name] = [inputs[0]] if inputs else []
        return name

    def extend_line(self, line: str, *points: str) -> None:
        """Make the drawn piece of ``line`` reach these points too (e.g. its intersection)."""
        self.extent[line].extend(points)

    def has(self, name: str) -> bool:
        return name in self.steps

    def dependencies(self, targets: Iterable[str]) -> set[str]:
        """Every step the targets depend on, themselves included."""
        need: set[str] = set()
        stack = list(targets)
        while stack:
            n = stack.pop()
            if n in need:
                continue
            if n not in self.steps:
                raise KeyError(f"no step named {n!r}")
            need.add(n)
            stack.extend(self.steps[n].inputs)
        return need

    def prune(self, targets: Iterable[str]) -> "Plan":
        """Compile the steps the targets depend on, in construction order."""
        targets = list(targets)
        need = self.dependencies(targets)
        kept = tuple(s for s in self.steps.values() if s.name in need)
        return Plan(kept, {k: [p for p in v if p in need] for k, v in self.extent.items() if k in need})


@dataclass(slots=True)
class Solution:
    """Values of a plan's steps at one position, with the condition number of each intersection."""

    values: dict[str, Any]
    conds: dict[str, float]

    def __getitem__(self, name: str) -> Any:
        return self.values[name]


@dataclass
class BatchSolution:
    """Values at N positions (arrays), which positions failed, and why (step → mask, reason)."""

    values: dict[str, Any]
    raw_conds: dict[str, Any]
    valid: np.ndarray
    failures: dict[str, tuple[np.ndarray, str]] = field(default_factory=dict)
    n: int = 1

    def __getitem__(self, name: str) -> Any:
        return self.values[name]

    @property
    def conds(self) -> dict[str, np.ndarray]:
        """Condition number of each intersection step at every position (capped, finite)."""
        return {k: np.minimum(np.broadcast_to(c, (self.n,)), COND_CAP) for k, c in self.raw_conds.items()}

    def at(self, i: int) -> Solution:
        """The solution at position i, as plain floats."""
        return Solution(values_at(self.values, i), {k: float(c[i]) for k, c in self.conds.items()})


def values_at(values: dict[str, Any], i: int) -> dict[str, Any]:
    """Batch values (arrays over positions, or tuples of them, or constants) at position i, as
    plain floats."""

    def pick(v: Any) -> Any:
        if isinstance(v, tuple):
            return tuple(pick(x) for x in v)
        if isinstance(v, np.ndarray):
            return float(v[i]) if v.ndim else float(v)
        return v

    return {k: pick(v) for k, v in values.items()}


#: A compiled step: (name, text, kernel, inputs).
_Compiled = tuple[str, str, Callable[..., Any], tuple[str, ...]]
#: The compiled plan: ``run(ops, params) -> {step name: value}``.
_Run = Callable[[ScalarOps | ArrayOps, Mapping[str, Any]], dict[str, Any]]


def _compile(program: tuple[_Compiled, ...], constants: dict[str, Any], params: list[str]) -> _Run:
    """Turn the ordered steps into one straight-line Python function.

    The function body is ``ops.step = text; v3 = kernel3(ops, v1, v2)`` per step: no dictionary
    look-ups or argument lists are built per step, which is most of the cost of a single
    position (a few µs per step otherwise). Returns ``run(ops, params) -> {step name: value}``.
    """
    local = {name: f"c{i}" for i, name in enumerate(constants)}
    local.update({name: f"p{i}" for i, name in enumerate(params)})
    body = ["def run(ops, P):"]
    body += [f"    {local[n]} = P[{n!r}]" for n in params]
    kernels, texts = [], []
    for i, (name, text, kernel, inputs) in enumerate(program):
        local[name] = f"v{i}"
        kernels.append(kernel)
        texts.append(text)
        args = ", ".join(["ops"] + [local[x] for x in inputs])
        body.append(f"    ops.step = T[{i}]")
        body.append(f"    v{i} = K[{i}]({args})")
    body.append("    return {" + ", ".join(f"{n!r}: {v}" for n, v in local.items()) + "}")
    namespace: dict[str, Any] = {"K": tuple(kernels), "T": tuple(texts)}
    namespace.update({f"c{i}": v for i, v in enumerate(constants.values())})
    exec(compile("\n".join(body), "<construction plan>", "exec"), namespace)  # noqa: S102 — our own code
    return cast(_Run, namespace["run"])


def _read_only(a: np.ndarray, n: int) -> np.ndarray:
    """``a`` over n positions, read-only (a kernel must not write into the caller's array): a view
    where it already has n values (np.broadcast_to costs ten times as much)."""
    if a.shape != (n,):
        return np.broadcast_to(a, (n,))
    v = a.view()
    v.flags.writeable = False
    return v


class Plan:
    """The pruned, ordered steps of a construction, ready to evaluate."""

    def __init__(self, steps: tuple[Step, ...], extent: Mapping[str, list[str]]) -> None:
        self.steps = steps
        self.extent = dict(extent)
        self.by_name = {s.name: s for s in steps}
        # Steps with no inputs (frame points, poles) are the same at every position:
        # evaluated once here. The rest is compiled to (name, text, kernel, inputs).
        self._constants: dict[str, Any] = {}
        for s in steps:
            if s.kernel is not None and not s.inputs:
                ops = ScalarOps()
                ops.step = s.text
                self._constants[s.name] = s.kernel(ops)
        self._program = tuple(
            (s.name, s.text, s.kernel, s.inputs) for s in steps
            if s.kernel is not None and s.name not in self._constants
        )
        self._params = [s.name for s in steps if s.kind == "param"]
        self._run = _compile(self._program, self._constants, self._params)
        # The fused function of each path (fused.py), written once the plan has been run
        # FUSE_AFTER times step by step; None until then, False where it cannot be fused or would
        # not give the same bits.
        self._fused: dict[bool, Any] = {False: None, True: None}
        self._runs = {False: 0, True: 0}

    #: Step-by-step runs before the fused function is written (scalar path, batch path). Writing
    #: it costs 2–4 ms (recording, writing, compiling, checking), which a run at one position wins
    #: back by 5–9 µs and a run over a batch by 30–70 µs: a plan is fused once it has been run
    #: often enough to pay for it, so a figure or a check (a few runs a plan) never pays.
    FUSE_AFTER = {False: 500, True: 50}

    def _fuse(self, batch: bool, sample: tuple[dict[str, Any], dict[str, Any]], ops_for: Callable[[], Any],
              params: Mapping[str, Any]) -> None:
        """Write the fused function of one path and keep it if it gives ``sample``'s every bit."""
        from graphmech.construction import fused

        self._fused[batch] = False
        try:
            run = fused.fuse(self._program, self._constants, self._params, sample[0], batch)
            ops = ops_for()
            with np.errstate(all="ignore"):
                got = (run(ops, params), ops.conds)
        except Exception:  # noqa: BLE001 — a plan that cannot be fused runs step by step, as before
            return
        if fused.same_run(got, sample) and not (batch and np.count_nonzero(ops.bad)):
            self._fused[batch] = run

    def __contains__(self, name: str) -> bool:
        return name in self.by_name

    def evaluate(self, params: Mapping[str, Any], position: str | None = None) -> dict[str, Any]:
        """Evaluate at one position (floats); a degenerate step raises, naming itself."""
        return self.solve(params, position).values

    def solve(self, params: Mapping[str, Any], position: str | None = None) -> Solution:
        run = self._fused[False]
        if run:
            ops = ScalarOps()
            ops.position = position
            try:
                return Solution(run(ops, params), ops.conds)
            except Exception:  # noqa: BLE001 — degenerate somewhere: step by step says where and why
                pass
        ops = ScalarOps()
        ops.position = position
        values = self._run(ops, params)
        if run is None:
            self._runs[False] += 1
            if self._runs[False] > self.FUSE_AFTER[False]:
                self._fuse(False, (values, ops.conds), ScalarOps, params)
        return Solution(values, ops.conds)

    def evaluate_batch(self, params: Mapping[str, Any]) -> BatchSolution:
        """Evaluate at many positions at once; failing positions are marked, never NaN."""
        arrays = {k: np.asarray(v, dtype=float) for k, v in params.items()}
        n = max((a.size for a in arrays.values() if a.ndim), default=1)
        params = {k: (_read_only(a, n) if a.ndim else a) for k, a in arrays.items()}
        run = self._fused[True]
        if run:
            ops = ArrayOps(n)
            try:
                with np.errstate(all="ignore"):  # a degenerate position is run again step by step
                    vals = run(ops, params)
                return BatchSolution(vals, ops.conds, ~ops.bad, ops.failures, n)
            except Exception:  # noqa: BLE001
                pass
        ops = ArrayOps(n)
        vals = self._run(ops, params)
        if run is None:
            self._runs[True] += 1
            if self._runs[True] > self.FUSE_AFTER[True] and not np.count_nonzero(ops.bad):
                self._fuse(True, (vals, ops.conds), lambda: ArrayOps(n), params)
        return BatchSolution(vals, ops.conds, ~ops.bad, ops.failures, n)
