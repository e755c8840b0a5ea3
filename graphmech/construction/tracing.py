"""A kernel's arithmetic recorded once, as a graph of operations on its components.

The construction kernels (:mod:`graphmech.geometry.kernels` and the methods' closures) are written
once for floats and for arrays. Run with :class:`Traced` stand-ins instead of numbers and a
:class:`TracingOps` instead of the real ops, a kernel records what it computes: every ``+``,
``ops.hypot`` and guard becomes a :class:`Node` of one :class:`Tape` shared by all the steps of a
plan. Constants (a link's length in mm, a scale factor) stay Python numbers, so arithmetic on them
alone is done by Python as the kernel would do it, and the tape holds only what varies with the
position. :mod:`graphmech.construction.fused` writes the tape out as one straight-line function.

A kernel that branches on a traced value (``if x > 0``), converts one to a float, or hands one to
numpy cannot be recorded: :class:`Untraceable` is raised and the step is called as it is.

The tape keeps the arithmetic exactly: the same operations on the same operands in the same order,
with only simplifications that are exact in IEEE arithmetic (``x − 0.0``, ``x + (−0.0)``, ``x·1.0``,
``x/1.0``) and one node for repeated identical operations.

>>> tape = Tape()
>>> x = tape.input("phi")
>>> y = (x * 2.0 - 0.0) * 1.0 + x * 2.0
>>> [(n.op, len(n.args)) for n in tape.nodes]
[('input', 1), ('mul', 2), ('add', 2)]
"""
from __future__ import annotations

import math
from typing import Any

from graphmech.errors import GraphmechError
from graphmech.geometry.kernels import ArrayOps, ScalarOps


class Untraceable(GraphmechError):
    """The kernel did something with a traced value that cannot be recorded."""


class Node:
    """One recorded operation: ``op`` applied to ``args`` (nodes or constants)."""

    __slots__ = ("op", "args", "index")

    def __init__(self, op: str, args: tuple[Any, ...], index: int) -> None:
        self.op = op
        self.args = args
        self.index = index

    def __repr__(self) -> str:
        return f"Node({self.op!r}, #{self.index})"


def _is_exact_zero(c: Any, sign: float) -> bool:
    return type(c) is float and c == 0.0 and math.copysign(1.0, c) == sign


def _is_one(c: Any) -> bool:
    return type(c) in (float, int) and c == 1


def _const_key(c: Any) -> Any:
    """A key that tells constants apart exactly (0.0 from −0.0, 1 from 1.0, a float from a numpy scalar)."""
    if isinstance(c, float):
        return (type(c).__name__, float(c).hex())
    if isinstance(c, (int, bool, str)):
        return (type(c).__name__, c)
    return ("id", id(c))


class Tape:
    """The recorded operations of a plan, in order, each identical operation once."""

    def __init__(self) -> None:
        self.nodes: list[Node] = []
        self._seen: dict[Any, Node] = {}  # (constants keyed by identity live on in their nodes' args)

    def node(self, op: str, *args: Any) -> Node:
        key = (op, *((("n", a.index) if isinstance(a, Node) else _const_key(a)) for a in args))
        hit = self._seen.get(key)
        if hit is not None:
            return hit
        n = Node(op, args, len(self.nodes))
        self.nodes.append(n)
        self._seen[key] = n
        return n

    def input(self, name: Any, *more: Any) -> "Traced":
        """A value read from outside the tape: a parameter, or a component of a step called as it is."""
        return Traced(self, self.node("input", name, *more))

    def apply(self, op: str, *args: Any) -> "Traced":
        plain = tuple(a.node if isinstance(a, Traced) else a for a in args)
        if len(plain) == 2:
            a, b = plain
            if isinstance(a, Node) and (op == "sub" and _is_exact_zero(b, 1.0) or op == "add" and _is_exact_zero(b, -1.0)
                                        or op in ("mul", "div") and _is_one(b)):
                return Traced(self, a)
            if isinstance(b, Node) and (op == "add" and _is_exact_zero(a, -1.0) or op == "mul" and _is_one(a)):
                return Traced(self, b)
        return Traced(self, self.node(op, *plain))


def _refuse(*_: Any) -> Any:
    raise Untraceable("a traced value was used as a plain number")


class Traced:
    """A stand-in for one component (a float or an array of them) while a kernel is recorded."""

    __slots__ = ("tape", "node")
    __array_ufunc__ = None  # numpy hands every operation back to us (or refuses it)

    def __init__(self, tape: Tape, node: Node) -> None:
        self.tape = tape
        self.node = node

    def __add__(self, o: Any) -> "Traced":
        return self.tape.apply("add", self, o)

    def __radd__(self, o: Any) -> "Traced":
        return self.tape.apply("add", o, self)

    def __sub__(self, o: Any) -> "Traced":
        return self.tape.apply("sub", self, o)

    def __rsub__(self, o: Any) -> "Traced":
        return self.tape.apply("sub", o, self)

    def __mul__(self, o: Any) -> "Traced":
        return self.tape.apply("mul", self, o)

    def __rmul__(self, o: Any) -> "Traced":
        return self.tape.apply("mul", o, self)

    def __truediv__(self, o: Any) -> "Traced":
        return self.tape.apply("div", self, o)

    def __rtruediv__(self, o: Any) -> "Traced":
        return self.tape.apply("div", o, self)

    def __pow__(self, o: Any) -> "Traced":
        return self.tape.apply("pow", self, o)

    def __rpow__(self, o: Any) -> "Traced":
        return self.tape.apply("pow", o, self)

    def __neg__(self) -> "Traced":
        return self.tape.apply("neg", self)

    def __abs__(self) -> "Traced":
        return self.tape.apply("abs", self)

    def __lt__(self, o: Any) -> "Traced":
        return self.tape.apply("lt", self, o)

    def __le__(self, o: Any) -> "Traced":
        return self.tape.apply("le", self, o)

    def __gt__(self, o: Any) -> "Traced":
        return self.tape.apply("gt", self, o)

    def __ge__(self, o: Any) -> "Traced":
        return self.tape.apply("ge", self, o)

    # Anything that needs the number itself cannot be recorded.
    __bool__ = __float__ = __int__ = __index__ = __complex__ = __round__ = _refuse
    __eq__ = __ne__ = __floordiv__ = __rfloordiv__ = __mod__ = __rmod__ = __getitem__ = __iter__ = _refuse
    __hash__ = None  # type: ignore[assignment]


class TracingOps:
    """The ops a kernel is recorded with: each function a node; guards and condition numbers noted
    for the step being recorded, and read back by :mod:`graphmech.construction.fused`."""

    def __init__(self, tape: Tape, real: type[ScalarOps] | type[ArrayOps]) -> None:
        self.tape = tape
        self.real = real  # ScalarOps or ArrayOps: what a function of constants alone is computed with
        self.batch = bool(real.batch)
        self.step = "?"
        self.position: str | None = None
        #: (step text, node) of each guard: the position is degenerate where the node is true
        self.guards: list[tuple[str, Any]] = []
        #: (step text, node) of each condition number, in the order the kernel reports them
        self.cond_nodes: list[tuple[str, Any]] = []

    @property
    def conds(self) -> Any:
        raise Untraceable("a kernel read the condition numbers")

    def _f(self, op: str, *args: Any) -> Any:
        if not any(isinstance(a, Traced) for a in args):
            return getattr(self.real, op)(*args)  # constants alone: computed now, as the kernel would
        return self.tape.apply(op, *args)

    def sqrt(self, x: Any) -> Any:
        return self._f("sqrt", x)

    def cos(self, x: Any) -> Any:
        return self._f("cos", x)

    def sin(self, x: Any) -> Any:
        return self._f("sin", x)

    def hypot(self, x: Any, y: Any) -> Any:
        return self._f("hypot", x, y)

    def maximum(self, a: Any, b: Any) -> Any:
        return self._f("maximum", a, b)

    def absolute(self, a: Any) -> Any:
        return self._f("absolute", a)

    def where(self, bad: Any, fallback: Any, value: Any) -> Any:
        if bad is False:  # a guard's answer on the fast path: no position is degenerate
            return value
        if not isinstance(bad, Traced):
            return self.real.where(bad, fallback, value)
        return self._f("where", bad, fallback, value)

    def guard(self, bad: Any, reason: Any, assembly: bool = False) -> Any:
        if isinstance(bad, Traced):
            self.guards.append((self.step, bad.node))
        elif bad:  # degenerate at every position: there is no fast path
            raise Untraceable("a guard that always trips")
        return False

    def fix(self, bad: Any, value: Any, fallback: Any, reason: Any, assembly: bool = False) -> Any:
        self.guard(bad, reason, assembly)
        return value

    def cond(self, c: Any) -> None:
        self.cond_nodes.append((self.step, c.node if isinstance(c, Traced) else c))


__all__ = ["Node", "Tape", "Traced", "TracingOps", "Untraceable"]
