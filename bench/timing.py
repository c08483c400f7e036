"""Shared by the benchmark scripts: the machine line and a median timer."""

import os
import platform
import statistics
import time
from collections.abc import Callable


def machine() -> str:
    """The line each benchmark prints first (figures are only comparable on one machine)."""
    return (
        f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}"
    )


def median_ms(fn: Callable[[], object], runs: int = 15) -> float:
    """Median wall time of ``runs`` calls of ``fn`` [ms] (medians: the machine is noisy)."""
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return 1000 * statistics.median(times)
