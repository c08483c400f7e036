"""The targets of issue 20 as whole processes and audits, one BLAS thread everywhere.

Run: ``.venv/bin/python bench/bench_whole.py [RUNS]`` (``audits``: the audits alone; needs
../shared; pyBmodes for the peer comparison: ``pip install -e '.[bench]'``). Whole processes
are run alternately with their comparison so that machine load hits both alike; wall-clock
medians (min–max).
"""

import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from timing import machine, median_ms

ROOT = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent
DECK = ROOT.parent / "shared" / "reference" / "NREL5MW"
ENV = {**os.environ, "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}


#: the same, figures drawn in the one process (the comparison for plots.render)
INLINE = {**ENV, "WTVIB_DRAW": "inline"}


def wall(cmd: list[str], cwd: Path, env: dict[str, str] = ENV) -> float:
    t0 = time.perf_counter()
    subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, check=False)
    return time.perf_counter() - t0


def alternate(commands: dict[str, Callable[[], float]], runs: int) -> dict[str, list[float]]:
    out: dict[str, list[float]] = {k: [] for k in commands}
    for _ in range(runs):
        for name, run in commands.items():
            out[name].append(run())
    return out


def show(name: str, times: list[float]) -> None:
    print(
        f"{name}: median {statistics.median(times):.2f} s "
        f"({min(times):.2f}–{max(times):.2f}, {len(times)} runs)"
    )


def main() -> None:
    if sys.argv[1:] == ["audits"]:
        print(machine() + "; OPENBLAS_NUM_THREADS=1")
        audits()
        return
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 7
    print(machine() + "; OPENBLAS_NUM_THREADS=1 on both sides")
    wtvib = str(BIN / "wtvib")
    pybmodes = shutil.which("pybmodes", path=str(BIN)) or shutil.which("pybmodes")
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        commands: dict[str, Callable[[], float]] = {
            "wtvib --help": lambda: wall([wtvib, "--help"], work),
            "wtvib check turbines/mod-2.yaml (its PNGs)": lambda: wall(
                [wtvib, "check", str(ROOT / "turbines" / "mod-2.yaml"), "--force"], work
            ),
            "wtvib check NREL-5MW.fst (all models, its PNGs)": lambda: wall(
                [wtvib, "check", str(DECK / "NREL-5MW.fst"), "--force"], work
            ),
            "  the same, figures drawn in-process (WTVIB_DRAW=inline)": lambda: wall(
                [wtvib, "check", str(DECK / "NREL-5MW.fst"), "--force"], work, INLINE
            ),
            "  check turbines/mod-2.yaml, figures in-process": lambda: wall(
                [wtvib, "check", str(ROOT / "turbines" / "mod-2.yaml"), "--force"], work, INLINE
            ),
        }
        if pybmodes:
            elastodyn = str(DECK / "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat")
            commands["pyBmodes campbell on the same deck (its PNG + CSV)"] = lambda: wall(
                [
                    pybmodes,
                    "campbell",
                    elastodyn,
                    "--max-rpm",
                    "13.9",
                    "--rated-rpm",
                    "12.1",
                    "--out-dir",
                    str(work / "pyb"),
                ],
                work,
            )
        else:
            print("pyBmodes not installed (pip install -e '.[bench]'): no peer comparison")
        times = alternate(commands, runs)
        for name, t in times.items():
            show(name, t)
        if pybmodes:
            ours = statistics.median(times["wtvib check NREL-5MW.fst (all models, its PNGs)"])
            theirs = statistics.median(times["pyBmodes campbell on the same deck (its PNG + CSV)"])
            print(f"  ratio pyBmodes campbell / wtvib check: {theirs / ours:.2f}")
        unc = [
            wall(
                [
                    wtvib,
                    "check",
                    str(ROOT / "turbines" / "wka-60.yaml"),
                    "--no-plots",
                    "--uncertainty",
                    "--samples",
                    "100000",
                ],
                work,
            )
            for _ in range(max(3, runs // 2))
        ]
        show("wtvib check wka-60 --uncertainty --samples 100000 (no PNGs)", unc)

    audits()


def audits() -> None:
    """``audit.run`` in this process (``bench_whole.py audits``: this alone)."""
    os.environ.update({k: "1" for k in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS")})
    from wtvib import audit, importers

    cases = {
        "NREL 5-MW deck set": DECK / "NREL-5MW.fst",
        "MOD-2 (two-bladed, Floquet)": ROOT / "turbines" / "mod-2.yaml",
    }
    try:
        import windIO

        cases["IEA-22 windIO 2.x example"] = (
            Path(windIO.__file__).parent / "examples" / "turbine" / "IEA-22-280-RWT.yaml"
        )
    except ImportError:
        pass
    for name, path in cases.items():
        # each timed audit on a spec loaded for it (outside the timing): a spec keeps what
        # its audit derived (the BEM schedule, the blade modes), so a second audit of the
        # same object skips that work, which a check never can
        audit.run(importers.load(path))  # the lazy imports and first-call costs, untimed
        fresh = [importers.load(path) for _ in range(9)]
        print(
            f"audit.run, {name}: median {median_ms(lambda f=fresh: audit.run(f.pop()), 9):.0f} ms "
            "(a fresh spec each)"
        )


if __name__ == "__main__":
    main()
