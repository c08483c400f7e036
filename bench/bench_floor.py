"""Whole checks against the floor every Python tool on this stack pays (issue 55).

    .venv/bin/python bench/bench_floor.py [PAIRS]

The floor is ``python -c "import numpy, scipy.linalg, matplotlib; matplotlib.use('Agg');
import matplotlib.pyplot"`` in the same environment. Each check (its PNGs written, one BLAS
thread) is run alternately with the floor — floor, check, floor, check … — PAIRS times
(default 5), so that the machine's phases hit both alike; the figure kept is the median of
the checks over the median of the floors beside them, and the check's peak resident memory
(its process's ru_maxrss). Needs ../shared and the test data (the IEA-15 monopile deck set
from tests/data/openfast_decks/iea15.tar.gz).
"""

import os
import resource
import statistics
import subprocess
import sys
import tarfile
import tempfile
import time
from pathlib import Path

from timing import machine

ROOT = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent
SHARED = ROOT.parent / "shared" / "reference"
ENV = {
    **os.environ,
    "OPENBLAS_NUM_THREADS": "1",
    "OMP_NUM_THREADS": "1",
    "MKL_NUM_THREADS": "1",
    "MPLBACKEND": "Agg",
}
FLOOR = [
    str(BIN / "python"),
    "-c",
    "import numpy, scipy.linalg, matplotlib; matplotlib.use('Agg'); import matplotlib.pyplot",
]


def run(cmd: list[str], cwd: Path) -> tuple[float, float]:
    """Wall time [s] and peak resident memory [MB] of one process."""
    t0 = time.perf_counter()
    proc = subprocess.Popen(
        cmd, cwd=cwd, env=ENV, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
    )
    _, _, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    return wall, usage.ru_maxrss / 1024


def cases(work: Path) -> dict[str, list[str]]:
    wtvib = str(BIN / "wtvib")
    with tarfile.open(ROOT / "tests/data/openfast_decks/iea15.tar.gz") as tar:
        tar.extractall(work / "iea15", filter="data")
    out = {
        "turbines/mod-2.yaml": [wtvib, "check", str(ROOT / "turbines/mod-2.yaml")],
        "NREL 5-MW ElastoDyn deck": [
            wtvib, "check", str(SHARED / "NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"),
            "--rpm", "6.9:12.1",
        ],
        "NREL-5MW.fst (aeroelastic)": [wtvib, "check", str(SHARED / "NREL5MW/NREL-5MW.fst")],
        "IEA-15 monopile deck set": [
            wtvib, "check",
            str(work / "iea15/OpenFAST/IEA-15-240-RWT-Monopile/IEA-15-240-RWT-Monopile.fst"),
        ],
    }  # fmt: skip
    try:
        import windIO

        example = Path(windIO.__file__).parent / "examples" / "turbine" / "IEA-22-280-RWT.yaml"
        out["IEA-22 windIO example"] = [wtvib, "check", str(example)]
    except ImportError:
        print("windio not installed: the IEA-22 example is left out")
    return out


def main() -> None:
    pairs = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    print(machine() + "; one BLAS thread; medians of", pairs, "alternating pairs")
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    # wtvib's bytecode, as an installed wheel has it: where PYTHONDONTWRITEBYTECODE is set
    # (this machine's shells), an editable checkout would otherwise compile every module
    # at every start (≈ 0.3 s) and the floor, whose libraries are installed, would not
    subprocess.run([str(BIN / "python"), "-m", "compileall", "-q", str(ROOT / "wtvib")], check=True)
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        for name, cmd in cases(work).items():
            out = work / "out"
            out.mkdir(exist_ok=True)
            floors, checks, peaks = [], [], []
            for _ in range(pairs):
                floors.append(run(FLOOR, out)[0])
                wall, peak = run([*cmd, "--out-dir", str(out), "--force"], out)
                checks.append(wall)
                peaks.append(peak)
            floor, check = statistics.median(floors), statistics.median(checks)
            print(
                f"{name}: {check:.2f} s = {check / floor:.2f}× the floor ({floor:.2f} s; "
                f"checks {min(checks):.2f}–{max(checks):.2f}), peak {max(peaks):.0f} MB"
            )


if __name__ == "__main__":
    main()
