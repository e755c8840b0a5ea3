"""Timing for the benchmarks: the best of several runs (the least disturbed by other processes)."""
from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from typing import Any


#: Seconds of runs after which best_time stops repeating: a run that long is its own best (the
#: disturbances best-of-N guards against are milliseconds), and the bench stays under a minute.
ENOUGH_S = 1.0


def best_time(fn: Callable[[], Any], repeat: int, number: int = 1) -> tuple[float, Any]:
    """Seconds per call of ``fn`` — the best of ``repeat`` runs of ``number`` calls, fewer once the
    runs have taken ENOUGH_S in all — and its last result.

    >>> secs, out = best_time(lambda: 6 * 7, repeat=3, number=10)
    >>> out, secs >= 0.0
    (42, True)
    """
    best, out, spent = math.inf, None, 0.0
    for _ in range(repeat):
        t = time.perf_counter()
        for _ in range(number):
            out = fn()
        took = time.perf_counter() - t
        best, spent = min(best, took / number), spent + took
        if spent >= ENOUGH_S:
            break
    return best, out


def best_times_interleaved(fns: Sequence[Callable[[], Any]], repeat: int, number: int = 1) -> list[float]:
    """Seconds per call of each of ``fns``, each the best of ``repeat`` runs of ``number`` calls, the
    runs alternated (f, g, f, g, …) so that every function sees the same machine state: a ratio of
    two such times is fair on a shared machine.

    >>> a, b = best_times_interleaved([lambda: 1, lambda: 2], repeat=3, number=10)
    >>> a >= 0.0 and b >= 0.0
    True
    """
    best = [math.inf] * len(fns)
    for _ in range(repeat):
        for k, fn in enumerate(fns):
            t = time.perf_counter()
            for _ in range(number):
                fn()
            best[k] = min(best[k], (time.perf_counter() - t) / number)
    return best


__all__ = ["best_time", "best_times_interleaved"]
