"""BLAS threads: ``wtvib check`` on the NREL 5-MW deck set with one BLAS thread (the CLI's
default since issue 20) and with two (this machine's cores: numpy's default), side by side,
alternating runs so that machine load hits both alike.

Run: ``.venv/bin/python bench/bench_threads.py [RUNS]`` (needs ../shared). Wall-clock
medians of whole processes (start-up included), no PNGs.
"""

import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

from timing import machine

ROOT = Path(__file__).resolve().parents[1]
DECK = ROOT.parent / "shared" / "reference" / "NREL5MW" / "NREL-5MW.fst"


def run(threads: str) -> float:
    env = {**os.environ, "OPENBLAS_NUM_THREADS": threads, "OMP_NUM_THREADS": threads}
    t0 = time.perf_counter()
    subprocess.run(
        [str(ROOT / ".venv" / "bin" / "wtvib"), "check", str(DECK), "--no-plots", "-f", "json"],
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        check=False,
    )
    return time.perf_counter() - t0


def main() -> None:
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 7
    times: dict[str, list[float]] = {"1": [], "2": []}
    for _ in range(runs):
        for threads in times:
            times[threads].append(run(threads))
    print(machine())
    for threads, ts in times.items():
        print(
            f"BLAS threads {threads}: median {statistics.median(ts):.2f} s, "
            f"min {min(ts):.2f} s, max {max(ts):.2f} s ({runs} runs)"
        )


if __name__ == "__main__":
    main()
