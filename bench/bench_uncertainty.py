"""Benchmark of issue 10: 10,000 Monte Carlo samples of a full tower model (< 5 s).

Run: ``.venv/bin/python bench/bench_uncertainty.py``. The tower is the NREL 5-MW tower from
its geometry (Jonkman et al. 2009, §6) with the published tower-head mass; Young's modulus
(±5 %), density (±3 %) and head mass (±5 %) are uncertain. Medians of 3 runs.
"""

import os
import platform
import statistics
import time

from wtvib import spec
from wtvib.studies import uncertainty


def nrel_geometry() -> spec.Spec:
    def q(value: float, tol: float) -> dict[str, object]:
        return {"value": value, "provenance": "published", "tolerance": tol}

    return spec.from_data(
        {
            "wtvib": 1,
            "turbine": {"name": "NREL 5-MW tower from geometry"},
            "rotor": {
                "blades": 3,
                "orientation": "upwind",
                "hub": "rigid",
                "speed": {"min_rpm": 6.9, "max_rpm": 12.1},
            },
            "tower": {
                "sections": {
                    "height_m": [0, 87.6],
                    "outer_diameter_m": [6.0, 3.87],
                    "wall_thickness_m": [0.0351, 0.0247],
                },
                "material": {
                    "youngs_modulus_pa": q(2.1e11, 0.05),
                    "shear_modulus_pa": 8.08e10,
                    "density_kg_m3": q(8500, 0.03),
                },
            },
            "tower_head": {
                "mass_kg": q(350000, 0.05),
                "cm_downwind_m": -0.26,
                "cm_above_top_m": 1.95,
                "inertia_pitch_kgm2": 2.3e7,
                "inertia_roll_kgm2": 3.9e7,
            },
        }
    )


def main() -> None:
    s = nrel_geometry()
    print(
        f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}"
    )
    runs = []
    for _ in range(3):
        t0 = time.perf_counter()
        out = uncertainty.sample(s, 10_000, seed=1)
        runs.append(time.perf_counter() - t0)
    f = out.frequencies["tower.fa1"]
    print(
        f"10,000 samples (fa1 and ss1, stacked eigen-solves in chunks of 2,000): median "
        f"{statistics.median(runs):.2f} s (runs {', '.join(f'{r:.2f}' for r in runs)}); "
        f"fa1 mean {f.mean():.4f} Hz, std {f.std():.4f} Hz"
    )


if __name__ == "__main__":
    main()
