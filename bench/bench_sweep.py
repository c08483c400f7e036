"""Issue 20's blade-sweep target: wtvib's rotating-blade sweep of 13 speeds against
pyBmodes' ``campbell_sweep`` on the same NREL 5-MW ElastoDyn blade, single-threaded both.

Run: ``.venv/bin/python bench/bench_sweep.py`` (needs ../shared; pyBmodes from the bench
extra: ``pip install -e '.[bench]'``). Both sweeps run in this one process, alternately,
from models already loaded (the sweep alone: 0 to 13.9 rpm, 13 speeds, 4 blade modes);
medians of many repetitions. Record the output in bench/RESULTS.md.
"""

import os

os.environ.update({k: "1" for k in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")})

import statistics
import time
import warnings
from collections.abc import Callable
from pathlib import Path

import numpy as np
from timing import machine

ROOT = Path(__file__).resolve().parents[1]
DECK = ROOT.parent / "shared/reference/NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"
RPM = np.linspace(0.0, 13.9, 13)


def alternate(runs: dict[str, Callable[[], object]], repeat: int) -> dict[str, list[float]]:
    out: dict[str, list[float]] = {k: [] for k in runs}
    for _ in range(repeat):
        for name, fn in runs.items():
            t0 = time.perf_counter()
            fn()
            out[name].append(time.perf_counter() - t0)
    return out


def main() -> None:
    from wtvib import importers
    from wtvib.subsystems import blade

    print(machine() + "; OPENBLAS_NUM_THREADS=1 on both sides")
    structure = importers.load(DECK).blade.structure
    assert structure is not None
    omega = RPM * np.pi / 30

    def ours() -> np.ndarray:
        return blade.rotating_modes(structure, omega, count=4)[1]

    runs: dict[str, Callable[[], object]] = {"wtvib blade.rotating_modes": ours}
    try:
        from pybmodes.campbell import campbell_sweep
        from pybmodes.models import RotatingBlade
    except ImportError:
        print("pyBmodes not installed (pip install -e '.[bench]'): no comparison")
        campbell_sweep = None
    if campbell_sweep is not None:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            model = RotatingBlade.from_elastodyn(DECK)

        def theirs() -> object:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                return campbell_sweep(model, RPM, n_blade_modes=4, n_tower_modes=0)

        runs["pyBmodes campbell_sweep"] = theirs
    times = alternate(runs, 40)
    for name, t in times.items():
        print(
            f"{name} (13 speeds, 4 modes): median {statistics.median(t) * 1e3:.2f} ms "
            f"(min {min(t) * 1e3:.2f})"
        )
    if campbell_sweep is not None:
        ratio = statistics.median(times["pyBmodes campbell_sweep"]) / statistics.median(
            times["wtvib blade.rotating_modes"]
        )
        print(f"  ratio pyBmodes / wtvib: {ratio:.1f}× (target ≥ 30×)")
        f_ours = ours()
        f_theirs = np.asarray(theirs().frequencies)[:, :4]  # type: ignore[attr-defined]
        print(
            f"  at 0 rpm: wtvib {np.round(f_ours[0], 4)} Hz, pyBmodes {np.round(f_theirs[0], 4)} Hz"
        )
        print(
            f"  at 13.9 rpm: wtvib {np.round(f_ours[-1], 4)} Hz, "
            f"pyBmodes {np.round(f_theirs[-1], 4)} Hz"
        )


if __name__ == "__main__":
    main()
