"""The two-bladed Floquet checks: audit time of the catalogue's two-bladed turbines.

Run with one BLAS thread (the models solve small dense problems; threading makes them
erratic):  OPENBLAS_NUM_THREADS=1 .venv/bin/python bench/bench_floquet.py
Run it under two checkouts alternately (PYTHONPATH=<checkout>) to compare versions.
"""

import sys
from pathlib import Path

from timing import machine, median_ms

from wtvib import audit, spec

TURBINES = Path(__file__).resolve().parent.parent / "turbines"
NAMES = ("mod-0", "mod-1", "mod-2", "wts-3", "wts-4", "wts-75", "growian", "aeroman")


def main() -> None:
    print(machine())
    specs = {n: spec.load(TURBINES / f"{n}.yaml") for n in NAMES}
    for s in specs.values():
        audit.run(s)  # warm-up: imports and caches
    total = 0.0
    for name, s in specs.items():
        t = median_ms(lambda s=s: audit.run(s), runs=9)
        total += t
        print(f"{name:10s} audit {t:7.1f} ms")
    print(f"{'all eight':10s} audit {total:7.1f} ms (sum of medians)")
    sys.stdout.flush()


if __name__ == "__main__":
    main()
