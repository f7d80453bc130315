"""Shared timing helper of the benchmark scripts."""

import statistics
import time


def median_time(function, repeat: int = 7) -> float:
    """Median wall time in s of ``repeat`` calls of ``function``."""
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return statistics.median(times)
