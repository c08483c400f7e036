"""Batch audits over a catalogue: discovery, parallel runs, summary rows, outputs.

Each input is audited in a worker process (load → solve → plot); results come back as
plain data (the report's ``to_dict()`` and PNG bytes) in the order the inputs were given.
One bad file never stops a run: it becomes an *input error* row with its one-line message.
"""

import csv
import io
import json
import math
import os
import time
from collections.abc import Callable, Iterable, Sequence
from concurrent.futures import Future, ProcessPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .errors import WtvibError
from .rules import STATUS_ORDER

BATCH_SCHEMA = "wtvib-batch/1"
SPEC_SUFFIXES = (".yaml", ".yml", ".dat", ".fst")

#: Outcome order for sorting and exit codes: input errors are worst.
OUTCOME_ORDER = {**STATUS_ORDER, "input-error": 4}


@dataclass(frozen=True)
class Item:
    """The result of one input: a report (as data) or an input error, plus timings."""

    path: str
    key: str
    report: dict[str, Any] | None = None
    error: str | None = None
    pngs: dict[str, bytes] = field(default_factory=dict)
    timings: dict[str, float] = field(default_factory=dict)

    @property
    def outcome(self) -> str:
        return "input-error" if self.report is None else str(self.report["verdict"])

    def row(self) -> dict[str, Any]:
        """The summary row: turbine, file, tower class, verdict, worst check, its margin."""
        if self.report is None:
            return {
                "file": self.path,
                "turbine": None,
                "tower_class": None,
                "verdict": "input-error",
                "worst_check": None,
                "margin": None,
                "message": self.error,
            }
        worst = worst_check(self.report["checks"])
        return {
            "file": self.path,
            "turbine": self.report["turbine"]["name"],
            "tower_class": self.report["tower_class"],
            "verdict": self.report["verdict"],
            "worst_check": worst["id"] if worst else None,
            "margin": worst.get("margin") if worst else None,
            "message": worst["message"] if worst else None,
        }


def worst_check(checks: Sequence[dict[str, Any]]) -> dict[str, Any] | None:
    """The most severe check; among equals, the one with the least margin."""

    def severity(c: dict[str, Any]) -> tuple[int, float]:
        margin = c.get("margin")
        return STATUS_ORDER[c["status"]], -margin if margin is not None else -math.inf

    return max(checks, key=severity, default=None)


def discover(paths: Iterable[Path]) -> list[Path]:
    """Input files: files as given; folders searched recursively for specs, windIO files and
    ElastoDyn main decks (``.dat``/``.fst`` files that name a ``TwrFile``)."""
    found: list[Path] = []
    from .importers import is_main_input

    for p in paths:
        if p.is_dir():
            found += sorted(q for q in p.rglob("*") if q.is_file() and is_main_input(q))
        else:
            found.append(p)
    seen: set[Path] = set()
    unique = []
    for p in found:
        r = p.resolve()
        if r not in seen:
            seen.add(r)
            unique.append(p)
    return unique


def output_keys(paths: Sequence[Path]) -> list[str]:
    """File stems for the outputs, made unique with the parent folder where stems clash."""
    stems = [p.stem for p in paths]
    return [f"{p.parent.name}__{p.stem}" if stems.count(p.stem) > 1 else p.stem for p in paths]


def audit_one(path: str, key: str, plots: bool) -> Item:
    """Load, audit and (optionally) plot one input. Never raises for a user's mistake."""
    from . import audit, importers

    t0 = time.perf_counter()
    try:
        turbine = importers.load(path)
    except WtvibError as exc:
        return Item(path, key, error=str(exc), timings={"load": time.perf_counter() - t0})
    t1 = time.perf_counter()
    try:
        report = audit.run(turbine)
    except WtvibError as exc:
        return Item(path, key, error=str(exc), timings={"load": t1 - t0})
    t2 = time.perf_counter()
    pngs: dict[str, bytes] = {}
    if plots:
        from .campbell import diagrams, png_bytes

        pngs = {suffix: png_bytes(fig) for suffix, fig in diagrams(report).items()}
    t3 = time.perf_counter()
    return Item(
        path,
        key,
        report=report.to_dict(),
        pngs=pngs,
        timings={"load": t1 - t0, "solve": t2 - t1, "plot": t3 - t2},
    )


def run(
    paths: Sequence[Path],
    *,
    jobs: int | None = None,
    plots: bool = True,
    on_done: Callable[[Item], None] | None = None,
) -> list[Item]:
    """Audit every input, in parallel on ``jobs`` processes; results in input order.

    ``on_done`` is called in the parent process as each item completes (progress, writes).
    ``KeyboardInterrupt`` propagates after cancelling what has not started.
    """
    keys = output_keys(paths)
    jobs = jobs or os.cpu_count() or 1
    if jobs == 1 or len(paths) < 2:
        items = []
        for p, k in zip(paths, keys, strict=True):
            item = audit_one(str(p), k, plots)
            if on_done:
                on_done(item)
            items.append(item)
        return items
    results: dict[int, Item] = {}
    with ProcessPoolExecutor(max_workers=min(jobs, len(paths))) as pool:
        futures: dict[Future[Item], int] = {
            pool.submit(audit_one, str(p), k, plots): i
            for i, (p, k) in enumerate(zip(paths, keys, strict=True))
        }
        try:
            from concurrent.futures import as_completed

            for fut in as_completed(futures):
                item = fut.result()
                results[futures[fut]] = item
                if on_done:
                    on_done(item)
        except BaseException:
            pool.shutdown(wait=False, cancel_futures=True)
            raise
    return [results[i] for i in range(len(paths))]


def summary(items: Sequence[Item]) -> dict[str, Any]:
    """The batch summary document (deterministic: no times, no dates)."""
    counts = {k: 0 for k in OUTCOME_ORDER}
    for it in items:
        counts[it.outcome] += 1
    return {
        "schema": BATCH_SCHEMA,
        "counts": counts,
        "turbines": [it.row() for it in items],
    }


def summary_csv(items: Sequence[Item]) -> str:
    """The summary rows as CSV text."""
    buf = io.StringIO()
    cols = ["file", "turbine", "tower_class", "verdict", "worst_check", "margin", "message"]
    writer = csv.DictWriter(buf, fieldnames=cols, lineterminator="\n")
    writer.writeheader()
    for it in items:
        writer.writerow(it.row())
    return buf.getvalue()


def results_json(items: Sequence[Item]) -> str:
    """One JSON document with every result (``--format json``)."""
    doc = {
        "schema": BATCH_SCHEMA,
        "results": [
            {"file": it.path, "outcome": it.outcome, "report": it.report, "error": it.error}
            for it in items
        ],
    }
    return json.dumps(doc, indent=2, ensure_ascii=False) + "\n"


def exit_code(items: Sequence[Item], strict: bool = False) -> int:
    """2 if any input error, 1 if any fail (or warn with ``strict``), else 0."""
    outcomes = {it.outcome for it in items}
    if "input-error" in outcomes:
        return 2
    if "fail" in outcomes or (strict and "warn" in outcomes):
        return 1
    return 0


def sort_items(items: Sequence[Item], by: str) -> list[Item]:
    """Items in input order (``file``), by worst outcome first (``verdict``) or by name."""
    if by == "verdict":
        return sorted(items, key=lambda it: -OUTCOME_ORDER[it.outcome])
    if by == "name":
        return sorted(items, key=lambda it: (it.row()["turbine"] or "", it.path))
    return list(items)
