"""Timing for the benchmarks: the best of several runs (the least disturbed by other processes)."""
from __future__ import annotations

import math
import time
from typing import Any, Callable


def best_time(fn: Callable[[], Any], repeat: int, number: int = 1) -> tuple[float, Any]:
    """Seconds per call of ``fn`` — the best of ``repeat`` runs of ``number`` calls — and its last result.

    >>> secs, out = best_time(lambda: 6 * 7, repeat=3, number=10)
    >>> out, secs >= 0.0
    (42, True)
    """
    best, out = math.inf, None
    for _ in range(repeat):
        t = time.perf_counter()
        for _ in range(number):
            out = fn()
        best = min(best, (time.perf_counter() - t) / number)
    return best, out


__all__ = ["best_time"]
