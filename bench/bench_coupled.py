"""Benchmark of issue 11: the coupled rotor–tower model (targets: one parked full-system
solve < 10 ms, a 30-point Campbell sweep < 0.5 s).

Run: ``.venv/bin/python bench/bench_coupled.py`` (needs ``../shared/reference``). On the
NREL 5-MW imported from its ElastoDyn deck: building the model, one parked solve (generator
locked, the Table 9-1 condition), one rotating solve, the 30-point sweep, and ``audit.run``
with and without the ``coupled`` block, side by side. Medians of 15 runs (5 for the sweep).
"""

from pathlib import Path

from timing import machine, median_ms

from wtvib import audit, importers
from wtvib.subsystems import coupled, multiblade

DECK = (
    Path(__file__).resolve().parents[2]
    / "shared/reference/NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"
)


def main() -> None:
    print(machine())
    s = importers.load(DECK, importers.ReadOptions(rpm=(6.9, 12.1)))
    bare = s.model_copy(update={"coupled": None})
    locked = coupled.build(s, "locked")
    free = coupled.build(s, "free")
    speeds = coupled.speeds(s)
    audit.run(s)  # warm up
    points = [(float(om), None) for om in speeds]
    path = multiblade.track(free, points, reduced=True)
    basis = free.ritz(path.basis)[0].shape[1]

    def cold(condition: str) -> coupled.Model:
        s._derived.clear()  # recompute the blade's modes and the model too
        return coupled.build(s, condition)

    rows = [
        ("degrees of freedom", float(locked.layout.size), ""),
        ("build the model (blade modes included)", median_ms(lambda: cold("locked")), "ms"),
        ("one parked solve, model built", median_ms(lambda: multiblade.parked(locked)), "ms"),
        ("build + parked solve", median_ms(lambda: multiblade.parked(cold("locked"))), "ms"),
        (
            "first rotating solve (multi-blade matrices)",
            median_ms(lambda: multiblade.rotating(cold("free"), 1.267)),
            "ms",
        ),
        (
            "further rotating solve (12.1 rpm)",
            median_ms(lambda: multiblade.rotating(free, 1.267)),
            "ms",
        ),
        (
            f"{len(speeds)}-point Campbell sweep, from the spec",
            median_ms(lambda: multiblade.sweep(cold("free"), speeds), 5),
            "ms",
        ),
        (
            f"  the sweep, model built, Ritz basis ({basis})",
            median_ms(lambda: multiblade.track(free, points, reduced=True), 5),
            "ms",
        ),
        (
            "  the sweep, model built, full model",
            median_ms(lambda: multiblade.track(free, points), 5),
            "ms",
        ),
    ]
    for label, value, unit in rows:
        print(f"{label:45s} {value:8.1f} {unit}")
    with_ms = median_ms(lambda: audit.run(s), 5)
    without_ms = median_ms(lambda: audit.run(bare), 5)
    print(f"{'audit.run with the coupled block':45s} {with_ms:8.1f} ms")
    print(f"{'audit.run without it':45s} {without_ms:8.1f} ms")


if __name__ == "__main__":
    main()
