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


def median_times(function, repeat: int = 7) -> tuple[float, float]:
    """Median wall and CPU (this process's) times in s of ``repeat`` calls of ``function``: on a shared machine the
    CPU time of a single-threaded call is what it costs, the wall time also what the others took."""
    walls, cpus = [], []
    for _ in range(repeat):
        wall, cpu = time.perf_counter(), time.process_time()
        function()
        walls.append(time.perf_counter() - wall)
        cpus.append(time.process_time() - cpu)
    return statistics.median(walls), statistics.median(cpus)
