"""Benchmarks of issue 3: tower solve against pyBmodes, full check wall times.

Run: ``.venv/bin/pip install pybmodes`` (or ``pip install -e '.[bench]'``), then
``.venv/bin/python bench/bench_structure.py`` from the repository root, with ../shared
beside it. Both tower solves run in this one process on the same NREL 5-MW ElastoDyn
deck; medians over many repetitions. Record the output in bench/RESULTS.md.
"""

import os
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


def main() -> None:
    from wtvib import importers, tower

    print(
        f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}"
    )
    spec = importers.load(NREL)

    def wtvib_tower():  # type: ignore[no-untyped-def]
        b = tower.discretise(spec.tower)
        return [
            tower.bending_modes(b, spec.tower_head, [], spec.tower.foundation, d).frequency_hz
            for d in ("fa", "ss")
        ]

    ours = median_time(wtvib_tower)
    fa, ss = wtvib_tower()
    print(
        f"wtvib tower solve (FA + SS, 2 modes each, {tower.DEFAULT_ELEMENTS} elements, "
        f"converged to 1e-5): median {ours * 1e3:.3f} ms; fa1 {fa[0]:.4f} ss1 {ss[0]:.4f} Hz"
    )
    try:
        from pybmodes.models import Tower
    except ImportError:
        print("pybmodes not installed: pip install pybmodes to compare")
        return
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        pb = Tower.from_elastodyn(str(NREL))
        theirs = median_time(lambda: pb.run(n_modes=4))
        freqs = pb.run(n_modes=4).frequencies
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
                subprocess.run([WTVIB, "check", *args, "--out", tmp], capture_output=True)
                runs.append(time.perf_counter() - t0)
            print(
                f"wtvib check {name} with Campbell PNG (whole process): median "
                f"{statistics.median(runs):.2f} s (runs {', '.join(f'{r:.2f}' for r in runs)})"
            )


if __name__ == "__main__":
    main()
