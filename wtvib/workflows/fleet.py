"""``batch``: every turbine found, audited in parallel (locally or on a Dask cluster), each
one's files written as it arrives, then the summaries and the combined PDF — a bad file
never stops the batch, Ctrl-C keeps what was completed."""

import contextlib
import dataclasses
import json
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from . import batch, ui
from .batch import Item
from .options import Options


@dataclass(frozen=True)
class Batch:
    """What ``batch`` was asked."""

    inputs: list[Path]
    options: Options
    out: Path | None = None  # the folder of every file (None: the summary table only)
    json: bool = False
    jobs: int | None = None
    plots: bool = True
    sort: str = "file"
    strict: bool = False
    scheduler: str | None = None
    force: bool = False


def run(asked: Batch) -> int:
    """Audit the catalogue; the exit code (130 or 143 where interrupted)."""
    from ..errors import SpecError
    from ..outputs.report import batch_progress, batch_summary

    paths, skipped = batch.discover_all(asked.inputs)
    for where, why in skipped:  # said, never left out in silence
        print(f"skipped {ui.shown(where)}: {ui.shown(why)}", file=sys.stderr)
    if not paths:
        raise SpecError(f"no spec files ({', '.join(batch.SPEC_SUFFIXES)}) found in the inputs")
    err = ui.console(stderr=True)
    lock = batch.FolderLock(asked.out) if asked.out is not None else None
    writer = Writer(asked.out, asked.force, skipped) if asked.out is not None else None
    done: list[Item] = []
    with (
        lock or contextlib.nullcontext(),
        ui.cluster(asked.scheduler) as client,
        batch.terminate_as_interrupt() as stopped,
    ):
        executor = client.get_executor() if client is not None else None
        with batch_progress(err, len(paths)) as advance:

            def on_done(item: Item) -> None:
                if writer is not None:
                    writer.item(item)
                done.append(item)
                advance(item)

            try:
                items = batch.run(
                    paths, jobs=asked.jobs, plots=asked.plots, on_done=on_done,
                    options=asked.options, executor=executor, alive=_alive(client),
                )  # fmt: skip
                if writer is not None:  # a turbine whose files could not be written
                    items = writer.failed(items)
            except KeyboardInterrupt:
                if writer is not None:  # the summaries of what was completed
                    writer.finish(done, plots=False, interrupted=True)
                err.print(
                    f"interrupted: {len(done)} of {len(paths)} inputs completed; their files "
                    "and the summaries of them are written, nothing is half-written"
                )
                return 143 if stopped() else 130
        if writer is not None:
            writer.finish(items, asked.plots)
    if asked.json:
        sys.stdout.write(batch.results_json(items))
    else:
        written = writer.written if writer else []
        batch_summary(ui.console(), batch.sort_items(items, asked.sort), written)
    return batch.exit_code(items, asked.strict)


def _alive(client: Any) -> Callable[[], bool] | None:
    """Whether the cluster still has a worker (None: a local run, always alive)."""
    if client is None:
        return None
    from ..studies.cluster import has_workers

    return lambda: bool(has_workers(client))


class Writer:
    """Writes a batch's files atomically as results arrive, then the summaries."""

    def __init__(self, folder: Path, force: bool, skipped: list[tuple[str, str]]) -> None:
        self.folder = folder
        self.force = force
        self.written: list[Path] = []
        self.timings: dict[str, dict[str, float]] = {}
        self.unwritten: dict[str, str] = {}  # item key → why its files were not written
        self.pdf_error: str | None = None
        self.skipped = skipped  # inputs left out, and why

    def _write(self, name: str, data: bytes) -> None:
        from ..outputs.files import write_atomic

        t0 = time.perf_counter()
        self.written.append(write_atomic(self.folder / name, data, force=self.force, folder=True))
        key = name.split(".")[0]
        self.timings.setdefault(key, {}).setdefault("write", 0.0)
        self.timings[key]["write"] += time.perf_counter() - t0

    def item(self, item: Item) -> None:
        """The item's files; one that cannot be written (a name too long for the file
        system, a full disk) fails that item alone: the others and the summaries go on."""
        from ..errors import OutputError

        try:
            self._item(item)
        except OutputError as exc:
            self.unwritten[item.key] = str(exc)

    def failed(self, items: list[Item]) -> list[Item]:
        """The items with those whose files could not be written turned into errors."""
        return [
            dataclasses.replace(
                it, report=None, pngs={}, campbell_csv=None,
                error=f"audited, but its files could not be written: {self.unwritten[it.key]}",
            )
            if it.key in self.unwritten
            else it
            for it in items
        ]  # fmt: skip

    def _item(self, item: Item) -> None:
        if item.report is not None:
            text = json.dumps(item.report, indent=2, ensure_ascii=False, allow_nan=False) + "\n"
            self._write(f"{item.key}.json", utf8(text))
        if item.campbell_csv is not None:
            self._write(f"{item.key}.campbell.csv", utf8(item.campbell_csv))
        for suffix, png in item.pngs.items():
            self._write(f"{item.key}.{suffix}.png", png)
        self.timings.setdefault(item.key, {}).update(item.timings)

    def finish(self, items: list[Item], plots: bool, interrupted: bool = False) -> None:
        """The summaries (JSON, CSV), the combined PDF and the run's metadata."""
        summary = json.dumps(batch.summary(items), indent=2, ensure_ascii=False) + "\n"
        self._write("summary.json", utf8(summary))
        self._write("summary.csv", utf8(batch.summary_csv(items)))
        if plots:
            self._pdf(items)
        meta = self._metadata(interrupted)
        self._write("run-metadata.json", utf8(json.dumps(meta, indent=2) + "\n"))

    def _pdf(self, items: list[Item]) -> None:
        from ..outputs import pdfreport

        entries = [(it.report, it.pngs) for it in items if it.report is not None]
        errors = [(it.path, str(it.error), it.outcome) for it in items if it.report is None]
        t0 = time.perf_counter()
        try:
            with ui.working(f"writing audit.pdf ({len(entries)} turbines)"):
                pdf = pdfreport.build(entries, errors=errors)
        except Exception as exc:  # the PDF is lost, not the run's other files
            self.pdf_error = f"audit.pdf could not be laid out ({type(exc).__name__})"
            ui.console(stderr=True).print(f"warning: {self.pdf_error}; the other files are written")
        else:
            self.timings["audit"] = {"build": time.perf_counter() - t0}
            self._write("audit.pdf", pdf)

    def _metadata(self, interrupted: bool) -> dict[str, Any]:
        import platform

        from .. import __version__

        return {
            "schema": "wtvib-run/1",
            "wtvib": __version__,
            "python": platform.python_version(),
            "machine": platform.machine(),
            "timings_s": self.timings,
            **({"interrupted": True} if interrupted else {}),
            **({"audit_pdf": self.pdf_error} if self.pdf_error else {}),
            **({"unwritten": self.unwritten} if self.unwritten else {}),
            **(
                {"skipped": [{"file": f, "why": w} for f, w in self.skipped]}
                if self.skipped
                else {}
            ),
        }


def utf8(text: str) -> bytes:
    """Text as UTF-8, a file name that is not (a byte Python keeps as a lone surrogate)
    written as its escape — still valid JSON, where it sits inside a string."""
    return text.encode("utf-8", errors="backslashreplace")
