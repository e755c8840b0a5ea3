"""The recording backend: every call as a plain tuple, arguments normalised, defaults filled in."""
from __future__ import annotations

import numpy as np

from graphmech.render.recording import RecordingBackend


def test_calls_are_recorded_in_order_with_defaults_filled_in() -> None:
    rec = RecordingBackend()
    rec.begin(297, 210)
    rec.begin_group("panel")
    rec.line((0, 0), (10, 0), "given")
    rec.polyline([(0, 0), (1, 1), (2, 0)], "result")
    rec.circle((5, 5), 2, "hinge")
    rec.text("b", (1, 2), 3.5)
    rec.end_group()
    assert rec.calls == [
        ("begin", 297.0, 210.0, ""),
        ("begin_group", "panel"),
        ("line", (0.0, 0.0), (10.0, 0.0), "given", False),
        ("polyline", ((0.0, 0.0), (1.0, 1.0), (2.0, 0.0)), "result", False, False),
        ("circle", (5.0, 5.0), 2.0, "hinge", False),
        ("text", "b", (1.0, 2.0), 3.5, "start", False, "text"),
        ("end_group",),
    ]


def test_arguments_are_normalised_to_plain_floats_bools_and_tuples() -> None:
    rec = RecordingBackend()
    rec.line(np.array([1, 2]), (np.float32(0.5), 3), "construction", dashed=1)  # type: ignore[arg-type]
    rec.polyline(((x, -x) for x in range(3)), "given", closed=1, filled=0)  # type: ignore[arg-type]
    rec.text("ω₁", [4, 5], 2, "middle", italic="yes", style_key="label")  # type: ignore[arg-type]
    line, poly, text = rec.calls
    assert line == ("line", (1.0, 2.0), (0.5, 3.0), "construction", True)
    assert all(type(v) is float for p in line[1:3] for v in p) and line[4] is True
    assert poly == ("polyline", ((0.0, 0.0), (1.0, -1.0), (2.0, -2.0)), "given", True, False)
    assert text == ("text", "ω₁", (4.0, 5.0), 2.0, "middle", True, "label")


def test_finish_returns_the_calls_and_they_stay_readable() -> None:
    rec = RecordingBackend()
    rec.begin(1.0, 1.0, "t")
    rec.line((0.0, 0.0), (1.0, 0.0), "given")
    rec.line((0.0, 0.0), (0.0, 1.0), "result", True)
    out = rec.finish()
    assert isinstance(out, tuple) and out[-1] == ("finish",) and list(out) == rec.calls
    assert [c[3] for c in rec.of("line")] == ["given", "result"]
    assert rec.of("circle") == [] and rec.of("finish") == [("finish",)]
    rec.calls.append(("extra",))  # the product is a snapshot
    assert out[-1] == ("finish",)
