"""Timing for the benchmarks (graphmech/timing.py): the best of the runs, per call, and the last
result. No assertion on speed: a fake clock gives the times."""
from __future__ import annotations

import itertools

import graphmech.timing as timing
from graphmech.timing import best_time, best_times_interleaved


def test_the_best_run_divided_by_the_calls_is_the_time(monkeypatch):
    # three runs of two calls: 5 s, 2 s, 3 s → the best is 2 s, 1 s per call
    ticks = iter([0.0, 5.0, 10.0, 12.0, 20.0, 23.0])
    monkeypatch.setattr(timing.time, "perf_counter", lambda: next(ticks))
    monkeypatch.setattr(timing, "ENOUGH_S", 100.0)
    seconds, _ = best_time(lambda: None, repeat=3, number=2)
    assert seconds == 1.0


def test_runs_stop_once_they_have_taken_enough_time(monkeypatch):
    # runs of 0.4 s, 0.5 s, 0.3 s, 0.1 s: after the third the runs have taken 1.2 s ≥ ENOUGH_S
    ticks = iter([0.0, 0.4, 1.0, 1.5, 2.0, 2.3, 3.0, 3.1])
    monkeypatch.setattr(timing.time, "perf_counter", lambda: next(ticks))
    calls = itertools.count()
    seconds, _ = best_time(lambda: next(calls), repeat=7)
    assert next(calls) == 3 and abs(seconds - 0.3) < 1e-12


def test_the_function_runs_repeat_times_number_and_its_last_result_is_kept():
    counter = itertools.count(1)
    seconds, last = best_time(lambda: next(counter), repeat=4, number=5)
    assert last == 20 and next(counter) == 21
    assert seconds >= 0.0


def test_no_runs_give_an_infinite_time_and_no_result():
    seconds, last = best_time(lambda: 1 / 0, repeat=0)
    assert seconds == float("inf") and last is None


def test_interleaved_runs_alternate_and_each_keeps_its_best(monkeypatch):
    # two runs of f, g alternated: f 4 s, g 1 s, f 2 s, g 3 s (two calls each) → 1 s and 0.5 s a call
    ticks = iter([0.0, 4.0, 10.0, 11.0, 20.0, 22.0, 30.0, 33.0])
    monkeypatch.setattr(timing.time, "perf_counter", lambda: next(ticks))
    calls = []
    seconds = best_times_interleaved([lambda: calls.append("f"), lambda: calls.append("g")], repeat=2, number=2)
    assert seconds == [1.0, 0.5]
    assert calls == ["f", "f", "g", "g", "f", "f", "g", "g"]
