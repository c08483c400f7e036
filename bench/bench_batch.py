"""Benchmarks of issue 7: CLI start-up, catalogue batch, results-only throughput.

Run: ``.venv/bin/python bench/bench_batch.py [--scaling]`` (from the repository root;
``--scaling``: the fleet's throughput over 1 … cores processes and Dask workers). Prints medians
over repeated runs; record the figures with the machine in bench/RESULTS.md. Not a test:
speed is measured here, never asserted in the test suite.
"""

import json
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
WTVIB = str(Path(sys.executable).with_name("wtvib"))


def timed(cmd: list[str], repeat: int) -> list[float]:
    out = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        subprocess.run(cmd, capture_output=True, check=False)
        out.append(time.perf_counter() - t0)
    return out


def main() -> None:
    print(
        f"machine: {platform.machine()}, {platform.processor() or '?'}; "
        f"python {platform.python_version()}; cores {__import__('os').cpu_count()}"
    )
    helps = timed([WTVIB, "--help"], 7)
    print(f"wtvib --help: median {statistics.median(helps):.3f} s (min {min(helps):.3f})")

    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "audit"
        full = []
        for _ in range(3):
            shutil.rmtree(out, ignore_errors=True)
            full += timed([WTVIB, "batch", str(ROOT / "turbines"), "--out-dir", str(out)], 1)
        n = len(list((ROOT / "turbines").glob("*.yaml")))
        print(
            f"catalogue batch ({n} turbines, PNG+JSON+PDF): median "
            f"{statistics.median(full):.2f} s (runs: {', '.join(f'{t:.2f}' for t in full)})"
        )
        meta = json.loads((out / "run-metadata.json").read_text())
        phases = ("load", "solve", "plot", "write")
        totals = {p: sum(t.get(p, 0.0) for t in meta["timings_s"].values()) for p in phases}
        print(
            "per-turbine breakdown (sum over turbines, worker time): "
            + ", ".join(f"{p} {totals[p]:.2f} s" for p in phases)
        )
        for key, t in sorted(meta["timings_s"].items()):
            if key in ("summary", "audit", "run-metadata"):
                extra = f", build {t['build']:.2f} s" if "build" in t else ""
                print(f"  {key:>14}: write {t.get('write', 0):.3f} s{extra}")
                continue
            print(f"  {key:>14}: " + ", ".join(f"{p} {t.get(p, 0) * 1000:.0f} ms" for p in phases))

        many = Path(tmp) / "many"
        many.mkdir()
        copies = -(-1000 // n)  # at least 1,000 specs (issue 20)
        for i in range(copies):
            for spec in (ROOT / "turbines").glob("*.yaml"):
                shutil.copy(spec, many / f"{spec.stem}-{i:02d}.yaml")
        count = copies * n
        runs = timed([WTVIB, "batch", str(many), "--no-plots", "--format", "json"], 3)
        med = statistics.median(runs)
        print(
            f"results-only batch ({count} specs, --no-plots): median {med:.2f} s "
            f"= {count / med:.0f} turbines/s"
        )
        dask_throughput(many, count)


def dask_throughput(folder: Path, count: int, workers: int | None = None, repeat: int = 3) -> None:
    """The same specs through ``batch --scheduler`` on a local Dask cluster (``workers``
    worker processes, default one per core, one thread each, started as a user would:
    ``dask scheduler`` and ``dask worker``), against the local process pool above."""
    import os

    workers = workers or os.cpu_count() or 1
    dask = str(Path(sys.executable).with_name("dask"))
    if not Path(dask).exists():
        print("dask: not installed (pip install 'wtvib[distributed]'); skipped")
        return
    port = 8799
    address = f"tcp://127.0.0.1:{port}"
    quiet = {"stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL}
    scheduler = subprocess.Popen(
        [dask, "scheduler", "--port", str(port), "--no-dashboard"], **quiet
    )
    worker = subprocess.Popen(
        [
            dask,
            "worker",
            address,
            "--nworkers",
            str(workers),
            "--nthreads",
            "1",
            "--no-dashboard",
        ],
        **quiet,
    )
    try:
        time.sleep(6)  # the scheduler and its workers start
        cmd = [WTVIB, "batch", str(folder), "--no-plots", "-f", "json", "--scheduler", address]
        timed(cmd, 1)  # workers import wtvib once
        runs = timed(cmd, repeat)
        med = statistics.median(runs)
        print(
            f"results-only batch on a local Dask cluster ({count} specs, {workers} "
            f"worker processes): median {med:.2f} s = {count / med:.0f} turbines/s"
        )
    finally:
        worker.terminate()
        scheduler.terminate()
        worker.wait(timeout=30)
        scheduler.wait(timeout=30)


def scaling() -> None:
    """Issue 42: results-only throughput of the 1,003-spec fleet over 1 … cores local
    processes (``--jobs``) and Dask workers, one run each after the workers' warm-up."""
    import os

    with tempfile.TemporaryDirectory() as tmp:
        many = Path(tmp) / "many"
        many.mkdir()
        n = len(list((ROOT / "turbines").glob("*.yaml")))
        copies = -(-1000 // n)
        for i in range(copies):
            for spec in (ROOT / "turbines").glob("*.yaml"):
                shutil.copy(spec, many / f"{spec.stem}-{i:02d}.yaml")
        count = copies * n
        for jobs in range(1, (os.cpu_count() or 1) + 1):
            cmd = [WTVIB, "batch", str(many), "--no-plots", "-f", "json", "--jobs", str(jobs)]
            (t,) = timed(cmd, 1)
            print(f"results-only batch ({count} specs), {jobs} local process(es): {t:.1f} s "
                  f"= {count / t:.0f} turbines/s")  # fmt: skip
        for workers in range(1, (os.cpu_count() or 1) + 1):
            dask_throughput(many, count, workers, repeat=1)


if __name__ == "__main__":
    scaling() if "--scaling" in sys.argv else main()
