"""Benchmark of issue 17: aerodynamic operating points plus damped coupled modes at 25 winds
(target: under 0.5 s per turbine), side by side with the structural-only audit.

Run: ``OPENBLAS_NUM_THREADS=1 .venv/bin/python bench/bench_aerodamping.py`` (needs
``../shared/reference`` and the windio package's IEA-15 2.x file). Per turbine: the BEM
schedule (25 winds + rated, pitch search above rated), the section damping matrices, the
damped coupled modes at every operating point (structural reference path, damped solve and
matching per point), and ``audit.run`` with and without the ``aerodynamics`` block. Each
measurement on a freshly loaded spec where a cache would otherwise hide the work. Medians of
``RUNS`` runs; one BLAS thread on both sides (set by the caller: numpy's threads make small
solves erratic on this 2-core machine).
"""

import os
from pathlib import Path

from timing import machine, median_ms

from wtvib import audit, importers
from wtvib.aero import aerodamping, bem

RUNS = 7
SHARED = Path(__file__).resolve().parents[2] / "shared"


def turbines() -> list[tuple[str, Path]]:
    import windIO

    examples = Path(windIO.__file__).parent / "examples/turbine"
    return [
        ("NREL 5-MW (OpenFAST deck set, AeroDyn 15)", SHARED / "reference/NREL5MW/NREL-5MW.fst"),
        ("IEA-15-240-RWT (windIO 2.x, monopile)", examples / "IEA-15-240-RWT.yaml"),
    ]


def measure(path: Path) -> list[tuple[str, float]]:
    """The rows of one turbine [ms]."""
    s = importers.load(path)
    audit.run(s)  # warm up (imports, the coupled model's cache)
    sch = bem.schedule(s)

    def fresh():  # type: ignore[no-untyped-def]
        return importers.load(path)

    def aero_from_fresh() -> object:
        t = fresh()
        return aerodamping.coupled(t, aerodamping.sections(t))

    def structural() -> object:
        return audit.run(fresh().model_copy(update={"aerodynamics": None}))

    load_ms = median_ms(fresh, RUNS)
    return [
        (f"operating points ({len(sch.wind)} winds)", median_ms(lambda: bem._schedule(s), RUNS)),
        ("section damping matrices", median_ms(lambda: aerodamping._sections(s), RUNS)),
        (
            "damped coupled modes at every point",
            median_ms(lambda: aerodamping.coupled(s, aerodamping.sections(s)), RUNS),
        ),
        (
            "all of the above from a fresh spec (coupled model built too)",
            median_ms(aero_from_fresh, RUNS) - load_ms,
        ),
        ("audit.run, aeroelastic", median_ms(lambda: audit.run(fresh()), RUNS) - load_ms),
        ("audit.run, structural only", median_ms(structural, RUNS) - load_ms),
    ]


def main() -> None:
    print(machine(), f"| OPENBLAS_NUM_THREADS={os.environ.get('OPENBLAS_NUM_THREADS', 'unset')}")
    print("(audit.run and 'from a fresh spec': the spec is loaded anew each run, load excluded)")
    for label, path in turbines():
        print(label)
        for name, value in measure(path):
            print(f"  {name:62s} {value:8.1f} ms")


if __name__ == "__main__":
    main()
