"""The Kind record (graphmech/problems/kind.py): whether a scene file poses a kind, and a kind's
check — analyse, refuse what is not finite, judge, extras, lines — in that order."""
from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

from graphmech.errors import DegenerateConstruction
from graphmech.problems import KINDS
from graphmech.problems.judging import Row, Verdict
from graphmech.problems.kind import Kind


def toy(rows, **fields):
    """A kind whose analysis is ``rows`` and whose calls are recorded in ``calls``."""
    calls = []

    def analyse(scene, extra):
        calls.append(("analyse", scene, extra))
        return SimpleNamespace(rows=rows)

    def judge(an, extra):
        calls.append(("judge", extra))
        return [Verdict(name, value, 1.0, 0.1, abs(value - 1.0) <= 0.1, "m") for name, value in extra]

    kind = Kind("toy", ("toy",), read=lambda *a: None, analyse=analyse, judge=judge, sheet=lambda s, f: (None, []),
                **fields)
    return kind, calls


def test_a_kind_is_posed_by_its_tables_unless_it_says_otherwise():
    kind, _ = toy([])
    assert kind.posed_by({"toy": {}}) and not kind.posed_by({"frame": {}})
    picky = Kind("picky", ("toy",), read=None, analyse=None, judge=None, sheet=None,  # type: ignore[arg-type]
                 poses=lambda data: "special" in data)
    assert picky.posed_by({"special": 1}) and not picky.posed_by({"toy": {}})


def test_the_linkage_poses_what_no_other_kind_does():
    assert KINDS["linkage"].posed_by({"frame": {}, "driver": {}})
    assert KINDS["linkage"].posed_by({"title": "nothing else"})  # the last resort
    assert KINDS["cam"].posed_by({"cam": {}}) and not KINDS["cam"].posed_by({"driver": {}})
    assert KINDS["cycle"].posed_by({"characteristics": {}})


def test_check_analyses_judges_and_adds_nothing_by_default():
    kind, calls = toy([Row("v_C", "m/s", 10.0, 0.1, 1.0, 1.0, 0.0)])
    an, verdicts, extras, lines = kind.check("scene", [("v_C", 1.05)])
    assert [c[0] for c in calls] == ["analyse", "judge"]
    assert calls[0][2] == (("v_C", 1.05),)  # the command line's values as a tuple
    assert [v.ok for v in verdicts] == [True] and extras == {} and lines == []
    assert an.rows[0].name == "v_C"


def test_check_uses_the_kinds_extras_and_lines():
    kind, _ = toy([], extras=lambda an: {"cycle": {"n": 12}}, lines=lambda an: ["a line under the table"])
    _, verdicts, extras, lines = kind.check("scene")
    assert verdicts == [] and extras == {"cycle": {"n": 12}} and lines == ["a line under the table"]


def test_an_analysis_that_is_not_finite_is_refused_before_judging():
    kind, calls = toy([Row("J_F", "kg·m²", None, 1.0, math.inf, 1.0, 0.0)])
    with pytest.raises(DegenerateConstruction, match="J_F"):
        kind.check("scene")
    assert [c[0] for c in calls] == ["analyse"]


def test_every_registered_kind_names_itself_and_reads_and_checks():
    for name, kind in KINDS.items():
        assert kind.name == name and kind.tables
        assert callable(kind.read) and callable(kind.analyse) and callable(kind.judge) and callable(kind.sheet)


def test_every_kind_has_a_protocol_and_the_registry_refuses_one_without(monkeypatch):
    import dataclasses

    from graphmech.errors import NotApplicable
    from graphmech.problems import steps

    assert all(kind.steps is not None for kind in KINDS.values())
    monkeypatch.setitem(KINDS, "cycle", dataclasses.replace(KINDS["cycle"], steps=None))  # a kind to come
    with pytest.raises(NotApplicable, match="no construction protocol for a cycle scene yet"):
        steps(SimpleNamespace(kind="cycle"))
