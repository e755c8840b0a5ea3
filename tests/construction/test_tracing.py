"""Recording a kernel: exact simplifications only, one node per identical operation, refusals."""
from __future__ import annotations

import math

import numpy as np
import pytest

from graphmech.construction.tracing import Tape, Traced, TracingOps, Untraceable
from graphmech.geometry import kernels as K
from graphmech.geometry.kernels import ArrayOps, ScalarOps


def ops_of(nodes):
    return [n.op for n in nodes]


def test_only_simplifications_exact_in_ieee_are_made():
    tape = Tape()
    x = tape.input("param", "x")
    assert (x - 0.0) is not x and (x - 0.0).node is x.node  # x − (+0) = x, −0 included
    assert (x + -0.0).node is x.node and (-0.0 + x).node is x.node
    assert (x * 1.0).node is x.node and (1.0 * x).node is x.node and (x / 1.0).node is x.node
    kept = [x + 0.0, 0.0 + x, x - -0.0, x * 0.0, 0.0 - x, 1.0 / x]  # −0 + 0 = +0; 0·x is ±0 or NaN
    assert all(k.node is not x.node for k in kept)
    assert ops_of(tape.nodes) == ["input", "add", "add", "sub", "mul", "sub", "div"]


def test_identical_operations_are_one_node_and_constants_are_told_apart_exactly():
    tape = Tape()
    x = tape.input("param", "x")
    assert (x * 2.0).node is (x * 2.0).node
    assert (x + 0.0).node is not (x + -0.0).node  # 0.0 == −0.0, yet not the same constant
    assert (x * 2).node is not (x * 2.0).node  # an int and a float stay apart
    assert (x * np.float64(2.0)).node is not (x * 2.0).node


@pytest.mark.parametrize("use", [bool, float, int, lambda v: v == 1.0, lambda v: v[0], lambda v: math.sqrt(v),
                                 lambda v: np.sin(v), lambda v: max(v, 1.0)])
def test_a_traced_value_cannot_be_used_as_a_number(use):
    x = Tape().input("param", "x")
    with pytest.raises((Untraceable, TypeError)):
        use(x)


def test_numpy_hands_arithmetic_back_to_the_traced_value():
    tape = Tape()
    x = tape.input("param", "x")
    y = np.float64(3.0) * x
    assert isinstance(y, Traced) and y.node.op == "mul" and y.node.args[0] == 3.0


def test_the_ops_record_functions_guards_and_condition_numbers():
    tape = Tape()
    ops = TracingOps(tape, ScalarOps)
    ops.step = "c = l1 ∩ l2"
    l1 = (tape.input("param", "px"), 0.0, 1.0, 0.0)
    l2 = (2.0, -1.0, tape.input("param", "ex"), tape.input("param", "ey"))
    point = K.intersect_lines(ops, l1, l2)
    assert all(isinstance(c, Traced) for c in point)
    assert [text for text, _ in ops.guards] == ["c = l1 ∩ l2"]  # parallel lines
    assert ops.guards[0][1].op == "lt"
    assert [text for text, _ in ops.cond_nodes] == ["c = l1 ∩ l2"]
    # functions of constants alone are computed now, as the path's ops would
    assert ops.sqrt(4.0) == 2.0 and type(TracingOps(tape, ArrayOps).sqrt(4.0)) is np.float64
    assert ops.where(False, 1.0, point[0]) is point[0]  # a guard's answer on the fast path
    with pytest.raises(Untraceable):
        ops.conds  # a kernel that reads the condition numbers is called as it is
    with pytest.raises(Untraceable):
        ops.guard(True, "always")
