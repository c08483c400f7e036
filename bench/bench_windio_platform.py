"""A windIO floating platform read into wtvib's platform block, and the whole check.

Run: ``.venv/bin/python bench/bench_windio_platform.py [CHECKOUT ...]`` from the repository
root (needs the windio package: the dev extra). One BLAS thread. For each checkout given
(default: this one), in a subprocess with ``PYTHONPATH`` set to it: the median of
``importers.windio_platform.platform`` on the windio package's IEA-15 VolturnUS-S and IEA-22
floaters (the first call in the process, which reads MoorPy's line library, then the
median of nine more), and the median wall time of the whole
``wtvib check … --no-plots`` process on the IEA-22 floater. Checkouts run alternately, run by
run. Record the output in bench/RESULTS.md.
"""

import os

os.environ.update({k: "1" for k in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")})

import json
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
from bench.timing import machine  # noqa: E402

INNER = r"""
import json, statistics, time, yaml
from pathlib import Path
import windIO
from wtvib.importers import windio
from wtvib.importers.windio_platform import platform
out = {}
for name in ("IEA-15-240-RWT_VolturnUS-S.yaml", "IEA-22-280-RWT_Floater.yaml"):
    p = Path(windIO.__file__).parent / "examples" / "turbine" / name
    d = windio._paths(yaml.safe_load(p.read_text()), (), str(p))
    t = time.perf_counter(); platform(d, p, 2.5e6, 15.0)
    out[name + " first"] = 1000 * (time.perf_counter() - t)
    times = []
    for _ in range(9):
        t = time.perf_counter(); platform(d, p, 2.5e6, 15.0); times.append(time.perf_counter() - t)
    out[name] = 1000 * statistics.median(times)
print(json.dumps(out))
"""


def platform_ms(checkout: Path) -> dict[str, float]:
    env = {**os.environ, "PYTHONPATH": str(checkout)}
    # run from /tmp: ``python -c`` puts the working folder first on sys.path, ahead of
    # PYTHONPATH, and from a checkout it would import that checkout's wtvib instead
    done = subprocess.run(
        [sys.executable, "-c", INNER], env=env, capture_output=True, text=True, cwd="/tmp"
    )
    if done.returncode:
        raise SystemExit(done.stderr[-2000:])
    result: dict[str, float] = json.loads(done.stdout.strip().splitlines()[-1])
    return result


def check_s(checkout: Path) -> float:
    import windIO

    floater = Path(windIO.__file__).parent / "examples" / "turbine" / "IEA-22-280-RWT_Floater.yaml"
    env = {**os.environ, "PYTHONPATH": str(checkout)}
    cmd = [sys.executable, "-c", "from wtvib.cli import main; main()", "check", str(floater)]
    cmd += ["--no-plots"]
    times = []
    for _ in range(5):
        t = time.perf_counter()
        subprocess.run(cmd, env=env, capture_output=True, cwd="/tmp")
        times.append(time.perf_counter() - t)
    return statistics.median(times)


def main() -> None:
    checkouts = [Path(a).resolve() for a in sys.argv[1:]] or [ROOT]
    print(machine() + ", one BLAS thread")
    for run in range(3):
        for c in checkouts:
            ms = platform_ms(c)
            whole = check_s(c)
            parts = ", ".join(
                f"{k.split('_')[0].split('.')[0]}{' first' if k.endswith('first') else ''} "
                f"{v:.1f} ms"
                for k, v in ms.items()
            )
            print(
                f"run {run + 1} {c.name}: platform {parts}; IEA-22 check --no-plots {whole:.2f} s"
            )


if __name__ == "__main__":
    main()
