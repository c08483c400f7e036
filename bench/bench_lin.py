"""A full-system OpenFAST linearisation's size (issue 42): thousands of states, read and
solved by ``wtvib check``, whole process, one BLAS thread.

The files are made here from OpenFAST's own CalcSteady linearisation of the NREL 5-MW with
AeroDyn's DBEMT inflow states (r-test ``5MW_Land_Linear_Aero_CalcSteady``, three azimuths,
258 states; tests/data/openfast_lin): each azimuth's file grown to ``--states`` states by
hydrodynamic-radiation-like first-order states in the fixed frame (damped 2 × 2 blocks
between 0.05 and 5 Hz, coupled weakly and densely to every other state — so that A is dense,
as a full-system linearisation's is), written in OpenFAST's number format. wtvib must find
the same structural modes in the grown files as in the originals (printed side by side):
the added states are not structural, and their coupling (10⁻² s⁻¹ in all) moves a
structural root by about 10⁻⁴ s⁻¹. Issue 42's goal is for four azimuths: the fourth grown
file is the first a revolution later (:func:`later`).

Each side runs from the set's folder, never from a checkout (``python -c`` puts the working
folder ahead of PYTHONPATH on sys.path).

Run: ``.venv/bin/python bench/bench_lin.py [--states 2900] [--azimuths 4] [--runs 3]
[--before <checkout>]``; prints the machine
line, the wall time and peak memory (``/usr/bin/time``'s maximum resident set) of each run
and their medians.
"""

import argparse
import gzip
import os
import re
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
from timing import machine

ROOT = Path(__file__).resolve().parents[1]
SOURCE = ROOT / "tests" / "data" / "openfast_lin"
CASE = "5MW_Land_Linear_Aero_CalcSteady"
ENV = {**os.environ, "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}


def grow(text: str, states: int, rng: np.random.Generator) -> str:
    """The linearisation ``text`` with first-order fixed-frame states added up to
    ``states``; its A extended (module notes), everything after A left out (B, C, D are not
    read)."""
    lines = text.splitlines()
    n = int(re.search(r"Number of continuous states:\s+(\d+)", text).group(1))  # type: ignore[union-attr]
    extra = states - n
    a_at = next(i for i, ln in enumerate(lines) if re.match(r"\s*A:\s", ln))
    a = np.array([[float(x) for x in ln.split()] for ln in lines[a_at + 1 : a_at + 1 + n]])
    pairs = extra // 2
    f = rng.uniform(0.05, 5.0, pairs) * 2 * np.pi
    zeta = rng.uniform(0.2, 0.9, pairs)
    block = np.zeros((extra, extra))
    for k in range(pairs):
        i = 2 * k
        block[i, i + 1] = 1.0
        block[i + 1, i] = -(f[k] ** 2)
        block[i + 1, i + 1] = -2 * zeta[k] * f[k]
    if extra % 2:
        block[-1, -1] = -1.0
    scale = 1e-2  # 1/s: perturbs a structural root by ~scale²/|Δλ|, far below 0.1 %
    coupled = np.block(
        [
            [a, scale * rng.normal(size=(n, extra)) / np.sqrt(extra)],
            [scale * rng.normal(size=(extra, n)) / np.sqrt(n), block],
        ]
    )
    coupled[n:, n:] += 1e-3 * rng.normal(size=(extra, extra)) / np.sqrt(extra)
    head = lines[:a_at]
    head = [re.sub(r"(Number of continuous states:\s+)\d+", rf"\g<1>{states}", ln) for ln in head]
    row = "{:11d}    0.000000000000E+000" + " " * 53 + "F               1         {}"
    for title, label in (
        ("Order of continuous state derivatives", "First time derivative of HD Radiation"),
        ("Order of continuous states", "HD Radiation"),
    ):  # the later table first: the earlier's insertion does not move it
        start = next(i for i, ln in enumerate(head) if ln.startswith(title))
        end = next(i for i in range(start + 3, len(head)) if not head[i].strip())
        rows = [
            row.format(n + k + 1, f"{label} state {k + 1} (synthetic), -") for k in range(extra)
        ]
        head = head[:end] + rows + head[end:]
    body = "\n".join(" ".join(f"{x: .12E}" for x in row) for row in coupled)
    return "\n".join([*head, f"A: {states} x {states}", body, ""])


def later(text: str, turns: int) -> str:
    """The linearisation ``text`` ``turns`` revolutions later: its azimuth + 2π·turns. The
    source has three azimuths; a fourth file costs what any azimuth costs (read, MBC3, its
    share of the average), and its average weighs that azimuth twice, which moves the
    structural roots by a hundredth of a hertz at most."""

    def turned(m: re.Match[str]) -> str:
        return f"{m.group(1)}{float(m.group(2)) + 2 * np.pi * turns:.6f}"

    return re.sub(r"(Azimuth:\s+)(\S+)", turned, text, count=1)


def run(folder: Path, tree: Path, out: Path) -> tuple[float, float]:
    """``wtvib check`` of the set's first file with the code of ``tree``, whole process:
    wall seconds and peak resident megabytes."""
    cmd = [
        "/usr/bin/time",
        "-f",
        "%e %M",
        sys.executable,
        "-c",
        "from wtvib.cli import main; main()",
    ]
    cmd += ["check", str(folder / f"{CASE}.1.lin"), "--no-plots", "-f", "json", "--rpm", "6:12.1"]
    env = {**ENV, "PYTHONPATH": str(tree), "WTVIB_MAX_BYTES": str(4 * 10**9)}
    with out.open("w") as stdout:  # run from the set's folder: ``python -c`` puts the
        # working folder first on sys.path, ahead of PYTHONPATH, and from a checkout it
        # would import that checkout's wtvib on both sides
        done = subprocess.run(
            cmd, env=env, stdout=stdout, stderr=subprocess.PIPE, text=True, cwd=folder
        )
    if done.returncode not in (0, 1):  # pass or fail: a verdict
        sys.exit(f"{tree}: {done.stderr.strip()[-2000:]}")
    seconds, kb = done.stderr.strip().splitlines()[-1].split()
    return float(seconds), int(kb) / 1024


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--states", type=int, default=2900)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--azimuths", type=int, default=4, help="files of the grown set (≥ 3)")
    ap.add_argument("--floor", action="store_true", help="time the floor too (see floor())")
    ap.add_argument("--before", type=Path, help="a checkout to compare, run alternately")
    args = ap.parse_args()
    print(machine() + "; OPENBLAS_NUM_THREADS=1 on both sides; WTVIB_MAX_BYTES=4e9")
    rng = np.random.default_rng(42)
    trees = {"now": ROOT} | ({"before": args.before.resolve()} if args.before else {})
    with tempfile.TemporaryDirectory() as tmp:
        small, big = Path(tmp, "small"), Path(tmp, "big")
        small.mkdir()
        big.mkdir()
        grown = {}
        for k in (1, 2, 3):
            text = gzip.decompress((SOURCE / f"{CASE}.{k}.lin.gz").read_bytes()).decode()
            (small / f"{CASE}.{k}.lin").write_text(text)
            grown[k] = grow(text, args.states, rng)
            (big / f"{CASE}.{k}.lin").write_text(grown[k])
        for k in range(4, args.azimuths + 1):  # a revolution later: the same matrix
            (big / f"{CASE}.{k}.lin").write_text(later(grown[(k - 1) % 3 + 1], k // 4))
        size = sum(p.stat().st_size for p in big.iterdir()) / 1e6
        print(f"{args.states} states, {max(args.azimuths, 3)} azimuths, {size:.0f} MB of text")
        for name, folder in (("original (258 states)", small), (f"grown ({args.states})", big)):
            times: dict[str, list[float]] = {t: [] for t in trees}
            memory: dict[str, list[float]] = {t: [] for t in trees}
            reports = {}
            for _ in range(args.runs):
                for label, tree in trees.items():  # alternately: load hits both alike
                    reports[label] = Path(tmp, f"{label}.json")
                    seconds, megabytes = run(folder, tree, reports[label])
                    times[label].append(seconds)
                    memory[label].append(megabytes)
            if folder == big and args.floor:
                print(floor(big))
            for label in trees:
                t = times[label]
                print(
                    f"{name}, {label}: median {statistics.median(t):.1f} s "
                    f"({min(t):.1f}–{max(t):.1f}, {len(t)} runs), "
                    f"peak {max(memory[label]):,.0f} MB; "
                    f"modes {_modes(reports[label])}"
                )


FLOOR = """
import re, sys, time
from pathlib import Path
import numpy as np
from scipy.linalg import lapack
from wtvib.importers import openfast_lin as ol
from wtvib.workflows.ui import collect_old_objects_rarely, reuse_freed_memory
reuse_freed_memory()  # as the command does
collect_old_objects_rarely()
paths = sorted(Path(sys.argv[1]).glob("*.lin"))
read = parse = 0.0
for p in paths:  # one file at a time, as the reader
    t = time.perf_counter()
    text = p.read_bytes()
    read += time.perf_counter() - t
    t = time.perf_counter()
    start = re.search(rb"^[ \\t]*A:", text, re.MULTILINE).end()
    np.fromstring(text[text.index(b"\\n", start) + 1 :], sep=" ")
    parse += time.perf_counter() - t
files = [ol.read(p) for p in paths]
lay = ol.layout(files[0].states, files[0].path, files[0].rotor_speed, files[0].a)
a = ol.mbc_average(files, lay)
lwork = int(lapack.dgeev_lwork(len(a), compute_vl=1, compute_vr=1)[0])
t = time.perf_counter()
lapack.dgeev(a, compute_vl=1, compute_vr=1, lwork=lwork)
solve = time.perf_counter() - t
print(f"floor in this phase: the files' bytes {read:.1f} s, numpy's parse of A {parse:.1f} s, "
      f"LAPACK dgeev with both vector sets {solve:.1f} s: {read + parse + solve:.1f} s")
"""


def floor(folder: Path) -> str:
    """What no reader of these files avoids, timed in this phase of the machine and with
    the command's allocator settings: their bytes, numpy's C parser over A, and LAPACK's
    dense two-sided eigen-solution of the averaged A."""
    env = {**ENV, "PYTHONPATH": str(ROOT), "WTVIB_MAX_BYTES": str(4 * 10**9)}
    done = subprocess.run(
        [sys.executable, "-c", FLOOR, str(folder)],
        env=env, capture_output=True, text=True, cwd=folder, check=False,
    )  # fmt: skip
    return done.stdout.strip() or done.stderr.strip()[-500:]


def _modes(report: Path) -> str:
    import json

    data = json.loads(report.read_text())
    modes = sorted((m["frequency_hz"], m["id"]) for m in data["modes"])
    return ", ".join(f"{i} {f:.3f}" for f, i in modes[:8])


if __name__ == "__main__":
    main()
