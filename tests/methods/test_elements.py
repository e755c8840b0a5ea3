"""graphmech.methods.elements: the drawn elements the polygons share — vectors, images, construction
lines and the shared directions — added to a real four-bar's construction and evaluated."""
from __future__ import annotations

import math

import pytest

from graphmech.mechanisms.linkage import RRR, Crank, Linkage
from graphmech.methods.elements import direction, image, line, own, vector
from graphmech.methods.polygons import build_polygons


@pytest.fixture
def b():
    fourbar = Linkage({"A": (0.0, 0.0), "D": (0.12, 0.0)}, Crank("1", "A", "B", 0.06, 10.0),
                      (RRR("B", "C", "D", ("2", "3"), (0.12, 0.09), "left"),), (), "0")
    return build_polygons(fourbar, {"l": 0.001, "v": 0.01, "a": 0.1})


def test_a_vector_is_one_step_named_by_its_figure_and_ends(b):
    before = len(b.g.steps)
    vector(b, "velocity", "v:b", "v:c")  # the polygon has bc already: drawn once
    vector(b, "velocity", "v:c", "v:c")  # no arrow from a point to itself
    assert len(b.g.steps) == before
    vector(b, "acceleration", "a:b'", "a:c'", role="construction", kind="segment")
    s = b.g.steps["a:a:b'->a:c'"]
    assert (s.kind, s.role, s.inputs, s.panel, s.text) == ("segment", "construction", ("a:b'", "a:c'"),
                                                           "acceleration", "segment a:b'a:c'")
    assert s.kernel is None  # drawn, never computed


def test_an_image_is_found_by_its_kernel_and_remembered(b):
    images: dict[str, str] = {}
    mid = image(b, "velocity", images, "M", "m", lambda ops, p, q: ((p[0] + q[0]) / 2, (p[1] + q[1]) / 2),
                ("v:b", "v:c"), "m halves bc")
    assert mid == "v:m" == images["M"] and b.g.steps[mid].label == "m" and b.g.steps[mid].role == "result"
    v = b.g.prune([mid]).evaluate({"phi": 0.7})
    assert v[mid] == pytest.approx(((v["v:b"][0] + v["v:c"][0]) / 2, (v["v:b"][1] + v["v:c"][1]) / 2), rel=1e-15)
    with pytest.raises(KeyError, match="defined twice"):  # one image per letter
        image(b, "velocity", images, "M", "m", lambda ops, p: p, ("v:b",), "again")


def test_a_construction_line_is_drawn_thin_through_its_first_point(b):
    name = line(b, "velocity", "∥AB@c", lambda ops, p: (p[0], p[1], 1.0, 0.0), ("v:c",), "through c draw ∥ AB")
    s = b.g.steps[name]
    assert name == "v:∥AB@c" and (s.kind, s.role, s.panel) == ("line", "construction", "velocity")
    assert b.g.extent[name] == ["v:c"]


def test_a_direction_is_one_shared_unit_vector_and_length(b):
    assert direction(b, "B", "C") == "dir:B->C"  # already built by the polygons: reused, not added twice
    name = direction(b, "A", "C")
    assert b.g.steps[name].role == "hidden" and b.g.steps[name].kind == "scalar"
    v = b.g.prune([name]).evaluate({"phi": 1.1})
    (ax, ay), (cx, cy) = v["A"], v["C"]
    ux, uy, n = v[name]
    assert n == pytest.approx(math.hypot(cx - ax, cy - ay), rel=1e-15)
    assert (ux, uy) == pytest.approx(((cx - ax) / n, (cy - ay) / n), rel=1e-15)


def test_the_constructions_own_points_never_meet_an_image():
    # a user's point named P has the image v:p; the pole is v:(p)
    assert own("velocity", "p") == "v:(p)" and own("acceleration", "k'") == "a:(k')"
    assert own("velocity", "p") != "v:p"
