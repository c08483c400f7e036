"""Benchmark of issue 6: the blade-stability checks' cost inside a check (< 1 s per turbine).

Run: ``.venv/bin/python bench/bench_aeroelastic.py``. Compares ``audit.run`` on the
catalogue's stall-controlled rotor with and without its ``blade.aeroelastic`` block (the
comparison run side by side), then the pieces: one p-k flutter sweep (120 speeds, bisected
flutter point), the k-method cross-check, and the stability-limit chart drawn with the PNGs.
Medians of 15 runs.
"""

import math
from pathlib import Path

import numpy as np
from timing import machine, median_ms

from wtvib import audit, spec
from wtvib.aero import aeroelastic

TURBINE = Path(__file__).resolve().parents[1] / "turbines" / "stall-rotor-1mw.yaml"


def main() -> None:
    print(machine())
    full = spec.load(TURBINE)
    bare = full.model_copy(update={"blade": full.blade.model_copy(update={"aeroelastic": None})})
    audit.run(full)  # warm imports (scipy.special for Theodorsen's function)
    with_ms = median_ms(lambda: audit.run(full))
    without_ms = median_ms(lambda: audit.run(bare))
    # the textbook section (b = ω_θ = ρ = 1; a = −0.2, x_θ = 0.1, μ = 20, r² = 6/25, σ = 0.4)
    m = 20 * math.pi
    section = aeroelastic.Section(1.0, -0.2, 0.1, m, 6 / 25 * m, 0.4, 1.0, 1.0)
    pk_ms = median_ms(lambda: aeroelastic.flutter(section, 3.0))
    k_ms = median_ms(lambda: aeroelastic.k_method(section, np.geomspace(8.0, 0.05, 300)))
    chart_ms = median_ms(lambda: aeroelastic.stability_chart(section, 2.0), runs=5)
    print(f"audit.run with blade.aeroelastic    {with_ms:8.1f} ms")
    print(f"audit.run without it                {without_ms:8.1f} ms")
    print(f"  difference (divergence, flutter, stall) {with_ms - without_ms:8.1f} ms")
    print(f"p-k flutter sweep (textbook section) {pk_ms:8.1f} ms")
    print(f"k-method cross-check                 {k_ms:8.1f} ms")
    print(f"stability-limit chart (PNG only)     {chart_ms:8.1f} ms")


if __name__ == "__main__":
    main()
