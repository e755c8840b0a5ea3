"""A plan fused into one straight-line function: the kernels' arithmetic inlined, guards checked once.

:class:`~graphmech.construction.graph.Plan` runs a construction step by step, each step a call of
its kernel with tuples in and out, each degenerate case checked where it arises. That costs more
than the arithmetic itself: a Python call and a tuple per step at one position, and at many
positions a numpy reduction per guard. Here the plan's steps are recorded once
(:mod:`graphmech.construction.tracing`) and written out as one function of plain locals, for the
scalar path (floats, :mod:`math`) or the batch path (numpy), with

* no call, tuple or dictionary per step: each component is a local variable;
* each identical operation done once, and constants as numpy 0-d arrays on the batch path (numpy
  combines an array with one faster than with a Python float, to the same bits);
* the guards gathered and tested once at the end: if any position is degenerate, the fused run
  is dropped and the plan runs step by step, which says where and why as before.

It computes exactly what the step-by-step run computes: the same operations on the same operands
in the same order, to the last bit. :func:`fuse` checks that on the run that asks for it, and a
plan whose fused function differs in any bit keeps running step by step. A step that cannot be
recorded (it branches on a value, or calls numpy itself) is called as it is, in its place.
Recording runs every kernel once with stand-ins, so a kernel must be what the step graph asks of
it anyway: a function of its inputs that changes nothing outside itself.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from graphmech.construction.tracing import Node, Tape, Traced, TracingOps
from graphmech.geometry.kernels import COND_CAP, ArrayOps, ScalarOps

#: A compiled step: (name, text, kernel, inputs), as :class:`~graphmech.construction.graph.Plan` keeps it.
Program = tuple[tuple[str, str, Callable[..., Any], tuple[str, ...]], ...]
#: ``run(ops, params) -> {step name: value}``, the same signature as the step-by-step run.
Run = Callable[[Any, Mapping[str, Any]], dict[str, Any]]


class Fallback(Exception):  # noqa: N818 — a signal, not an error: run the plan step by step
    """A guard tripped on the fused run: the plan runs step by step instead."""


#: How each operation is written on the scalar path and on the batch path ({0}, {1}: operands).
_SCALAR = {"add": "{0} + {1}", "sub": "{0} - {1}", "mul": "{0} * {1}", "div": "{0} / {1}", "pow": "{0} ** {1}",
           "neg": "-{0}", "abs": "abs({0})", "lt": "{0} < {1}", "le": "{0} <= {1}", "gt": "{0} > {1}",
           "ge": "{0} >= {1}", "sqrt": "_sqrt({0})", "cos": "_cos({0})", "sin": "_sin({0})",
           "hypot": "_hypot({0}, {1})", "absolute": "abs({0})", "maximum": "{0} if {0} > {1} else {1}",
           "where": "{2}"}  # ScalarOps.where is the value itself: a scalar position that fails raises
_BATCH = dict(_SCALAR, maximum="_maximum({0}, {1})", where="_where({0}, {1}, {2})")
#: Operations where a float constant is passed as a 0-d array on the batch path.
_ARITHMETIC = {"add", "sub", "mul", "div", "lt", "le", "gt", "ge"}


def _shape(v: Any) -> int | None:
    """How a step's value is held: k components (a tuple), 0 (one number), None (anything else)."""
    if isinstance(v, tuple):
        return len(v) if all(_number(x) for x in v) else None
    return 0 if _number(v) else None


def _number(x: Any) -> bool:
    return isinstance(x, (float, int, np.floating)) and not isinstance(x, bool) or (
        isinstance(x, np.ndarray) and x.dtype.kind == "f")


def _traced_like(out: Any, shape: int) -> bool:
    def ok(x: Any) -> bool:
        return isinstance(x, Traced) or _number(x)

    if shape == 0:
        return ok(out)
    return isinstance(out, tuple) and len(out) == shape and all(ok(x) for x in out)


class _Writer:
    """The function's text and the objects it names."""

    def __init__(self, batch: bool) -> None:
        self.batch = batch
        self.lines: list[str] = []
        self.names: dict[str, Any] = {"_sqrt": math.sqrt, "_cos": math.cos, "_sin": math.sin,
                                      "_hypot": math.hypot, "Fallback": Fallback, "CAP": COND_CAP}
        if batch:
            self.names.update(_sqrt=np.sqrt, _cos=np.cos, _sin=np.sin, _hypot=np.hypot,
                              _maximum=np.maximum, _where=np.where, _nonzero=np.count_nonzero)
        self._consts: dict[int, str] = {}

    def const(self, c: Any, as_array: bool = False) -> str:
        if not self.batch and type(c) in (float, int) and math.isfinite(c):
            return f"({c!r})"  # a literal: the compiler keeps it with the code, the cheapest load
        obj = np.array(c) if as_array and self.batch and type(c) is float else c
        key = id(c) * 2 + (obj is not c)
        if key not in self._consts:
            self._consts[key] = f"k{len(self._consts)}"
            self.names[self._consts[key]] = obj
        return self._consts[key]

    def bind(self, prefix: str, obj: Any) -> str:
        name = f"{prefix}{len(self.names)}"
        self.names[name] = obj
        return name


def fuse(program: Program, constants: Mapping[str, Any], params: list[str], sample: Mapping[str, Any],
         batch: bool) -> Run:
    """Record the plan's steps and write them out as one function; ``sample`` is a step-by-step
    run's values (they tell how each step's value is held)."""
    tape = Tape()
    tops = TracingOps(tape, ArrayOps if batch else ScalarOps)
    sym: dict[str, Any] = dict(constants)
    for p in params:
        sym[p] = tape.input("param", p)
    # Per step: ("traced", name, text, its guards, its conds, end of its nodes) or
    # ("called", name, text, kernel, inputs, end of the nodes before it, shape).
    plan: list[tuple[Any, ...]] = []
    raw: set[str] = set()  # steps whose value is not a tuple of numbers: only called steps read them
    for name, text, kernel, inputs in program:
        shape = _shape(sample.get(name))
        args = [sym[x] for x in inputs]
        tops.step = text
        g0, c0 = len(tops.guards), len(tops.cond_nodes)
        out: Any = None
        if shape is not None and not any(x in raw for x in inputs):
            try:
                out = kernel(tops, *args)
            except Exception:  # anything a kernel does that cannot be recorded: call it as it is
                out = None
            if out is not None and not _traced_like(out, shape):
                out = None
        if out is not None:
            sym[name] = out
            plan.append(("traced", name, text, (g0, len(tops.guards)), (c0, len(tops.cond_nodes)), len(tape.nodes)))
            continue
        del tops.guards[g0:], tops.cond_nodes[c0:]
        plan.append(("called", name, text, kernel, inputs, len(tape.nodes), shape))
        if shape is None:
            raw.add(name)
            sym[name] = None
        elif shape == 0:
            sym[name] = tape.input("called", name)
        else:
            sym[name] = tuple(tape.input("called", name, k) for k in range(shape))
    return _write(tape, tops, plan, sym, constants, params, batch)


def _roots(tops: TracingOps, sym: Mapping[str, Any]) -> list[Node]:
    """The nodes the function must compute for their own sake: the guards, the condition numbers
    and the components of the steps' values."""
    out = [n for _, n in tops.guards] + [n for _, n in tops.cond_nodes if isinstance(n, Node)]
    for v in sym.values():
        out += [x.node for x in (v if isinstance(v, tuple) else (v,)) if isinstance(x, Traced)]
    return out


def _needed(tape: Tape, roots: list[Node]) -> list[bool]:
    """Which nodes the roots depend on (themselves included)."""
    need = [False] * len(tape.nodes)
    stack = list(roots)
    while stack:
        n = stack.pop()
        if need[n.index]:
            continue
        need[n.index] = True
        stack.extend(a for a in n.args if isinstance(a, Node))
    return need


def _read_once(tape: Tape, roots: list[Node], need: list[bool]) -> list[bool]:
    """The nodes read exactly once, by another node whose form writes that operand once, and not
    themselves roots (a step's value, a guard or a condition number)."""
    reads = [0] * len(tape.nodes)
    for n in tape.nodes:
        if need[n.index]:
            for i, a in enumerate(n.args):
                if isinstance(a, Node):
                    # maximum writes both operands twice; where drops its first two on this path
                    reads[a.index] += 2 if n.op == "maximum" or n.op == "where" and i < 2 else 1
    pinned = {n.index for n in roots}
    return [need[i] and reads[i] == 1 and i not in pinned and n.op != "input" for i, n in enumerate(tape.nodes)]


def _write(tape: Tape, tops: TracingOps, plan: list[tuple[Any, ...]], sym: Mapping[str, Any],
           constants: Mapping[str, Any], params: list[str], batch: bool) -> Run:
    w = _Writer(batch)
    roots = _roots(tops, sym)
    need = _needed(tape, roots)
    local: dict[int, str] = {}  # node index → its local
    called: dict[str, str] = {}  # called step → the local holding its value
    forms = _BATCH if batch else _SCALAR
    body = w.lines

    # On the scalar path a node read once, by an operation that writes it once, is written inside
    # its reader: one store and load fewer (a Python local costs as much as the arithmetic).
    inline: dict[int, str] = {}
    depth: dict[int, int] = {}
    once = [False] * len(tape.nodes) if batch else _read_once(tape, roots, need)

    def operand(a: Any, op: str) -> str:
        if isinstance(a, Node):
            return inline.pop(a.index) if a.index in inline else local[a.index]
        return w.const(a, as_array=op in _ARITHMETIC)

    def component(x: Any) -> str:
        return local[x.node.index] if isinstance(x, Traced) else w.const(x)

    def value(name: str) -> str:
        if name in called:
            return called[name]
        v = sym[name]
        if name in constants:
            return w.const(v)
        if isinstance(v, tuple):
            return "(" + "".join(component(x) + ", " for x in v) + ")"
        return component(v)

    done = 0

    def nodes_until(end: int) -> None:
        nonlocal done
        for n in tape.nodes[done:end]:
            if not need[n.index]:
                continue
            t = local[n.index] = f"t{n.index}"
            if n.op == "input":
                kind, name, *k = n.args
                src = f"P[{name!r}]" if kind == "param" else called[name] + (f"[{k[0]}]" if k else "")
                body.append(f"    {t} = {src}")
                continue
            d = 1 + max((depth.get(a.index, 0) for a in n.args if isinstance(a, Node)), default=0)
            expr = forms[n.op].format(*(operand(a, n.op) for a in n.args))
            if once[n.index] and d < 24:  # (a bound on the nesting the parser accepts)
                inline[n.index], depth[n.index] = f"({expr})", d
            else:
                body.append(f"    {t} = {expr}")
        done = max(done, end)

    guards: list[Node] = []
    for entry in plan:
        if entry[0] == "called":
            _, name, text, kernel, inputs, end, _shape_ = entry
            nodes_until(end)
            out = called[name] = f"o{len(called)}"
            body.append(f"    ops.step = {w.bind('T', text)}")
            body.append(f"    {out} = {w.bind('K', kernel)}(ops, {''.join(value(x) + ', ' for x in inputs)})")
            continue
        _, name, text, (g0, g1), (c0, c1), end = entry
        nodes_until(end)
        for _, node in tops.guards[g0:g1]:
            if not any(g is node for g in guards):
                guards.append(node)
                if not batch:
                    body.append(f"    if {local[node.index]}: raise Fallback")
        for step, c in tops.cond_nodes[c0:c1]:
            key = w.bind("T", step)
            if isinstance(c, Node):
                body.append(f"    C[{key}] = {local[c.index]}" if batch else
                            f"    C[{key}] = {local[c.index]} if {local[c.index]} < CAP else CAP")
            else:  # a constant condition number, stored as the kernel's ops would store it
                body.append(f"    C[{key}] = {w.const(c if batch or c < COND_CAP else COND_CAP)}")
    nodes_until(len(tape.nodes))
    if batch:  # a called step marks its own degenerate positions in ops.bad
        # (count_nonzero is a plain C call: a quarter of a reduction's .any(), and of an | too)
        tests = [f"_nonzero({local[g.index]})" for g in guards] + (["_nonzero(ops.bad)"] if called else [])
        if tests:
            body.append(f"    if {' or '.join(tests)}: raise Fallback")
    # The values: a copy of a dictionary that already holds every key, in order, and the values that
    # never change (a dictionary display of thirty entries costs half as much again).
    names = [*constants, *params, *(e[1] for e in plan)]
    template = {n: _fixed(n, constants, sym, called) for n in names}
    body.append(f"    d = {w.bind('D', template)}.copy()")
    body += [f"    d[{n!r}] = {value(n)}" for n in names if template[n] is None]
    body.append("    return d")
    text = "def run(ops, P):\n    C = ops.conds\n" + "\n".join(body) + "\n"
    return _compile(text, w.names)


def _fixed(name: str, constants: Mapping[str, Any], sym: Mapping[str, Any], called: Mapping[str, str]) -> Any:
    """A step's value if it is the same at every position (a plan's constant, or a tuple of
    constants), else None."""
    if name in constants:
        return constants[name]
    v = sym.get(name)
    if name in called or v is None or not isinstance(v, tuple) or any(isinstance(x, Traced) for x in v):
        return None
    return v


def _compile(text: str, names: dict[str, Any]) -> Run:
    namespace = dict(names)
    exec(compile(text, "<fused plan>", "exec"), namespace)  # noqa: S102 — our own code
    run: Run = namespace["run"]
    run.source = text  # type: ignore[attr-defined]  # for tests and for reading it
    return run


# ----------------------------------------------------------------------------- the bitwise check


def same_bits(a: Any, b: Any) -> bool:
    """Whether two values (tuples of floats or arrays, nested) are the same to the last bit, -0.0 and
    NaN included.

    >>> same_bits((1.0, np.array([0.0])), (1.0, np.array([0.0]))), same_bits(0.0, -0.0)
    (True, False)
    """
    if isinstance(a, tuple) or isinstance(b, tuple):
        return (isinstance(a, tuple) and isinstance(b, tuple) and len(a) == len(b)
                and all(same_bits(x, y) for x, y in zip(a, b)))
    if isinstance(a, np.ndarray) != isinstance(b, np.ndarray):
        return False
    if _number(a) and _number(b):
        x, y = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        return x.shape == y.shape and x.tobytes() == y.tobytes()
    return a is b or a == b


def same_run(a: tuple[dict[str, Any], dict[str, Any]], b: tuple[dict[str, Any], dict[str, Any]]) -> bool:
    """Whether two runs — (values, condition numbers) — agree in every key, in order, to the last bit."""
    return all(list(x) == list(y) and all(same_bits(x[k], y[k]) for k in x) for x, y in zip(a, b))


__all__ = ["Fallback", "fuse", "same_bits", "same_run"]
