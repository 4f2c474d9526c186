"""The best-of-N wall-clock timer the speed benchmarks share."""
from __future__ import annotations

import time
from typing import Callable, TypeVar

T = TypeVar("T")


def best_of(fn: Callable[[], T], repeats: int) -> tuple[float, T]:
    """(the best wall time of ``repeats`` calls of ``fn``, in s; what the last
    call returned). The best, not the mean: the machine's noise only adds."""
    best, result = float("inf"), None
    for _ in range(repeats):
        start = time.perf_counter()
        result = fn()
        best = min(best, time.perf_counter() - start)
    return best, result
