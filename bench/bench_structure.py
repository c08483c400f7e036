"""Benchmarks of issue 3: tower solve against pyBmodes, full check wall times.

Run: ``.venv/bin/pip install pybmodes`` (or ``pip install -e '.[bench]'``), then
``.venv/bin/python bench/bench_structure.py`` from the repository root, with ../shared
beside it. Both tower solves run in this one process on the same NREL 5-MW ElastoDyn
deck, alternately call by call, one BLAS thread; medians over many repetitions. Record the
output in bench/RESULTS.md.
"""

import os

# one BLAS thread on both sides (numpy's threads make small solves erratic)
os.environ.update({k: "1" for k in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")})

import platform
import statistics
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared"
NREL = SHARED / "reference/NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"
WTVIB = str(Path(sys.executable).with_name("wtvib"))


def median_time(fn, repeat: int = 300) -> float:  # type: ignore[no-untyped-def]
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def alternating(a, b, repeat: int = 300, block: int = 20) -> tuple[float, float]:  # type: ignore[no-untyped-def]
    """Median call times of ``a`` and ``b``, run in turns of ``block`` calls each until
    each has run ``repeat`` times: machine load hits both alike, and neither runs with
    caches the other just emptied (one call each in turn slowed the smaller solve by 20 %)."""
    ta: list[float] = []
    tb: list[float] = []
    while len(ta) < repeat:
        for fn, out in ((a, ta), (b, tb)):
            for _ in range(block):
                t0 = time.perf_counter()
                fn()
                out.append(time.perf_counter() - t0)
    return statistics.median(ta), statistics.median(tb)


def main() -> None:
    from wtvib import importers
    from wtvib.subsystems import tower

    print(
        f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}"
    )
    spec = importers.load(NREL)

    def wtvib_tower():  # type: ignore[no-untyped-def]
        # the audit's own path: the mesh, then both planes in one stacked solve
        b = tower.discretise(spec.tower)
        fa, ss = tower.bending_pair(b, spec.tower_head, [], spec.tower.foundation)
        return fa.frequency_hz, ss.frequency_hz

    fa, ss = wtvib_tower()
    try:
        from pybmodes.models import Tower
    except ImportError:
        ours = median_time(wtvib_tower)
        print(f"wtvib tower solve: median {ours * 1e3:.3f} ms")
        print("pybmodes not installed: pip install pybmodes to compare")
        return
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        pb = Tower.from_elastodyn(str(NREL))
        ours, theirs = alternating(wtvib_tower, lambda: pb.run(n_modes=4), 600)
        freqs = pb.run(n_modes=4).frequencies
    print(
        f"wtvib tower solve (FA + SS, 2 modes each, {tower.DEFAULT_ELEMENTS} elements, "
        f"converged to 1e-5): median {ours * 1e3:.3f} ms; fa1 {fa[0]:.4f} ss1 {ss[0]:.4f} Hz"
    )
    print(
        f"pyBmodes tower solve (Tower.from_elastodyn(...).run(n_modes=4), its default mesh): "
        f"median {theirs * 1e3:.3f} ms; modes {', '.join(f'{f:.4f}' for f in freqs)} Hz"
    )
    print(f"ratio pyBmodes / wtvib: {theirs / ours:.1f}×")

    with tempfile.TemporaryDirectory() as tmp:
        cases = [("NREL 5-MW ElastoDyn", [str(NREL), "--rpm", "6.9:12.1"])]
        try:
            import windIO

            iea15 = Path(windIO.__file__).parent / "examples/turbine/IEA-15-240-RWT.yaml"
            cases.append(("IEA-15 windIO 2.x", [str(iea15)]))
        except ImportError:
            pass
        for name, args in cases:
            runs = []
            for _ in range(5):
                t0 = time.perf_counter()
                subprocess.run([WTVIB, "check", *args, "--out-dir", tmp], capture_output=True)
                runs.append(time.perf_counter() - t0)
            print(
                f"wtvib check {name} with Campbell PNG (whole process): median "
                f"{statistics.median(runs):.2f} s (runs {', '.join(f'{r:.2f}' for r in runs)})"
            )


if __name__ == "__main__":
    main()
