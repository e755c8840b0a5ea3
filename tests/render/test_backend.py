"""The backend protocol: the drawing vocabulary, which each backend speaks with the same words."""
from __future__ import annotations

import inspect

import pytest

from graphmech.render.backend import Backend
from graphmech.render.recording import RecordingBackend
from graphmech.render.svg import SvgBackend

VOCABULARY = {"begin", "begin_group", "end_group", "line", "polyline", "circle", "text", "finish"}


def test_the_vocabulary_is_eight_calls() -> None:
    names = {n for n, v in vars(Backend).items() if callable(v) and not n.startswith("_")}
    assert names == VOCABULARY


class Minimal:
    def begin(self, page_w, page_h, title=""): ...
    def begin_group(self, name): ...
    def end_group(self): ...
    def line(self, p0, p1, style_key, dashed=False): ...
    def polyline(self, points, style_key, closed=False, filled=False): ...
    def circle(self, c, r, style_key, filled=False): ...
    def text(self, s, at, size, anchor="start", italic=False, style_key="text"): ...
    def finish(self): return None


class NoFinish(Minimal):
    finish = None  # type: ignore[assignment]


def test_a_backend_is_whatever_has_every_call() -> None:
    assert isinstance(Minimal(), Backend)
    assert not isinstance(NoFinish(), Backend)
    assert not isinstance(object(), Backend)


@pytest.mark.parametrize("backend", [RecordingBackend, SvgBackend])
@pytest.mark.parametrize("call", sorted(VOCABULARY))
def test_each_backend_takes_the_protocols_parameters_and_defaults(backend: type, call: str) -> None:
    def params(f) -> list[tuple[str, object]]:
        return [(p.name, p.default) for p in inspect.signature(f).parameters.values()]

    assert params(getattr(backend, call)) == params(getattr(Backend, call))
