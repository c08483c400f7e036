"""``check`` and ``report``: one turbine audited, its report printed or laid out as a PDF,
its figures drawn beside the audit and written without losing anything."""

import dataclasses
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from . import ui
from .options import Options

if TYPE_CHECKING:
    from ..audit import Report


@dataclass(frozen=True)
class Check:
    """What ``check`` was asked: the input, how to read and judge it (``options``), how
    to show the report and which files to write."""

    spec_file: Path
    options: Options
    json: bool = False  # the JSON document on stdout, not the terminal report
    out: Path | None = None  # the figures' folder (None: the current directory)
    plots: bool = True
    detail: bool = False
    strict: bool = False  # warn exits 1 too
    campbell_csv: Path | None = None
    force: bool = False
    show_all: bool = False
    all_figures: bool = False
    samples: int | None = None  # Monte Carlo samples of --uncertainty (None: none)
    seed: int = 0
    scheduler: str | None = None


def check(asked: Check) -> int:
    """Audit one turbine, print its report, write its figures (and the Campbell CSV); the
    exit code (:data:`wtvib.workflows.ui.EXIT_FAIL` for a failing verdict)."""
    from ..outputs.files import campbell_to_csv, folder_exists, write_atomic

    if asked.campbell_csv is not None:
        folder_exists(asked.campbell_csv)
    written: list[Path] = []
    # the input read first: a mistake in it is answered before the models are imported
    turbine = asked.options.load(asked.spec_file)
    settings = asked.options.settings(turbine)
    from .. import audit
    from ..outputs.plots.render import Drawer

    ui.solve_on_every_core()

    uncertainty = asked.samples is not None
    with Drawer(enabled=asked.plots) as drawer:  # imports matplotlib beside the audit
        doing = f"auditing, {asked.samples:,} Monte Carlo samples" if uncertainty else "auditing"
        with ui.cluster(asked.scheduler) as client, ui.working(doing):
            report = audit.run(
                turbine, settings, samples=asked.samples, seed=asked.seed, client=client
            )
        if asked.plots:
            drawer.send(report, detail=asked.all_figures)  # drawn while the text renders
        # the report rendered while the figures draw, printed once they are written (a
        # file that may not be replaced stops the check before anything is printed)
        console, text = rendered(report, asked.json, show_all=asked.show_all, detail=asked.detail)
        if asked.plots:
            folder = asked.out if asked.out is not None else Path.cwd()  # never beside the input
            with ui.working("drawing the figures"):
                pngs = drawer.pngs(report, detail=asked.all_figures)
            tag = asked.options.tag(uncertainty)
            for suffix, png in pngs.items():
                path = folder / f"{asked.spec_file.stem}{tag}.{suffix}.png"
                written.append(write_atomic(path, png, force=asked.force, folder=True))
    if asked.campbell_csv is not None:
        data = campbell_to_csv(report.campbell, report.identity).encode()
        written.append(write_atomic(asked.campbell_csv, data, force=asked.force))
    sys.stdout.write(text)
    ui.wrote(console, written)
    for warning in report.warnings:
        ui.say(f"warning: {ui.shown(warning)}", err=True)
    failing = report.verdict == "fail" or (asked.strict and report.verdict == "warn")
    return ui.EXIT_FAIL if failing else ui.EXIT_PASS


def rendered(report: "Report", json: bool, *, show_all: bool, detail: bool) -> tuple[Any, str]:
    """The report as the text ``check`` prints: JSON (no console), or the terminal report
    captured from the console it is then printed beside (the files written)."""
    if json:
        from ..outputs.report import to_json

        return None, to_json(report)

    from ..outputs.report import terminal

    console = ui.console()
    with console.capture() as captured:
        terminal(report, console, show_all=show_all, detail=detail or show_all)
    return console, captured.get()


def pdf(
    spec_file: Path,
    output: Path,
    options: Options,
    *,
    force: bool = False,
    samples: int | None = None,
    seed: int = 0,
    debug: bool = False,
) -> int:
    """Audit one turbine and write its PDF report (every figure, drawn beside the audit);
    ``debug``: an unexpected exception raises, for its traceback. The exit code."""
    from .. import audit
    from ..outputs import pdfreport
    from ..outputs.files import folder_exists, write_atomic
    from ..outputs.plots.render import Drawer
    from . import batch

    if samples is not None:
        options = dataclasses.replace(options, samples=samples, seed=seed)
    folder_exists(output)  # before the audit, not after it
    ui.solve_on_every_core()
    # every figure, drawn beside the audit as check draws its own (plots.render); forked
    # before the spinner's thread starts (a fork copies no thread, but a lock one holds)
    with Drawer() as drawer, ui.working("auditing and drawing the figures"):

        def draw(report: "audit.Report") -> dict[str, bytes]:
            return drawer.pngs(report, detail=True)

        one = batch.audit_one_raising if debug else batch.audit_one
        item = one(str(spec_file), spec_file.stem, True, options, draw)
    if item.report is None:
        ui.say(f"error: {ui.shown(item.error)}", err=True)
        return ui.EXIT_INTERNAL if item.internal else ui.EXIT_INPUT
    with ui.working(f"writing {output.name}"):
        document = pdfreport.build([(item.report, item.pngs)])
    write_atomic(output, document, force=force)
    ui.say(f"wrote {ui.shown(output)} (verdict {item.report['verdict']})")
    return ui.EXIT_FAIL if item.report["verdict"] == "fail" else ui.EXIT_PASS
