"""Drawing cost of every figure (issue 20): the figures `report` and `batch` draw, to PNG.

Run: ``OPENBLAS_NUM_THREADS=1 .venv/bin/python bench/bench_figures.py [RUNS]`` from the
repository root. To compare with an earlier commit, check it out beside this one
(``git worktree add /tmp/old <commit>``) and run this same script alternately against both
trees: ``PYTHONPATH=/tmp/old .venv/bin/python bench/bench_figures.py``. The audits run once;
only drawing (figure building, Agg, PNG encoding) is timed, in this process, one BLAS thread.
"""

import statistics
import sys
import time
from pathlib import Path

from timing import machine

ROOT = Path(__file__).resolve().parents[1]
INPUTS = [
    ROOT / "turbines" / "mod-2.yaml",
    ROOT / "turbines" / "mod-0.yaml",
    ROOT / "turbines" / "euros-44m.yaml",
    ROOT.parent / "shared" / "reference" / "NREL5MW" / "NREL-5MW.fst",
]


def main() -> None:
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    import wtvib
    from wtvib import audit
    from wtvib.importers import load
    from wtvib.outputs.plots import drawers, png_bytes

    print(machine() + f"; wtvib from {Path(wtvib.__file__).parent}")
    reports = [audit.run(load(p)) for p in INPUTS if p.exists()]
    makers = [make for r in reports for make in drawers(r, detail=True).values()]
    png_bytes(next(f for f in (m() for m in makers) if f is not None))  # matplotlib warm
    times, count, size = [], 0, 0
    for _ in range(runs):
        t0 = time.perf_counter()
        pngs = [png_bytes(fig) for fig in (make() for make in makers) if fig is not None]
        times.append(time.perf_counter() - t0)
        count, size = len(pngs), sum(map(len, pngs))
    median = 1000 * statistics.median(times)
    print(
        f"{count} figures of {len(reports)} turbines: median {median:.0f} ms"
        f" ({', '.join(f'{1000 * t:.0f}' for t in times)}), {size / 1024:.0f} kB of PNG"
    )


if __name__ == "__main__":
    main()
