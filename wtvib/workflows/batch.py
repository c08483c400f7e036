"""Batch audits over a catalogue: discovery, parallel runs, summary rows, outputs.

Each input is audited in a worker process (load → solve → plot); results come back as
plain data (the report's ``to_dict()`` and PNG bytes) in the order the inputs were given.
One bad file never stops a run: it becomes an *input error* row with its one-line message,
and anything else that goes wrong in one turbine (a bug, a crashed worker) an *internal
error* row naming the exception; the rest completes and the summaries are written.
"""

import contextlib
import csv
import io
import json
import os
import time
from collections.abc import Callable, Iterable, Iterator, Sequence
from concurrent.futures import Executor, Future, ProcessPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..errors import WtvibError
from ..outputs.files import campbell_to_csv
from ..rules import STATUS_ORDER, worst_check
from ..spec.load import OPTIONS_FILE
from .options import Options

if TYPE_CHECKING:
    from ..audit import Report
    from ..document import ReportDoc

#: Two documents, two shapes, two ids (wtvib.workflows.contract): the summary and the full results.
SUMMARY_SCHEMA = "wtvib-batch-summary/1"
RESULTS_SCHEMA = "wtvib-batch-results/1"
SPEC_SUFFIXES = (".yaml", ".yml", ".dat", ".fst")

#: Outcome order for sorting and exit codes: errors are worst, internal ones last.
OUTCOME_ORDER = {**STATUS_ORDER, "input-error": 4, "internal-error": 5}

#: Exit code of a run with an internal error (a bug in wtvib, not the user's input).
EXIT_INTERNAL = 3


@dataclass(frozen=True)
class Item:
    """The result of one input: a report (as data) or an error, plus timings.

    ``internal`` marks an error that is not the user's: an exception wtvib did not expect.
    """

    path: str
    key: str
    report: "ReportDoc | None" = None
    error: str | None = None
    pngs: dict[str, bytes] = field(default_factory=dict)
    timings: dict[str, float] = field(default_factory=dict)
    internal: bool = False
    campbell_csv: str | None = None  # the Campbell data (written beside the JSON)

    @property
    def outcome(self) -> str:
        if self.report is None:
            return "internal-error" if self.internal else "input-error"
        return str(self.report["verdict"])

    def row(self) -> dict[str, Any]:
        """The summary row: turbine, file, tower class, verdict, worst check, its margin, and
        the report's warnings (what an importer assumed, suspicious values: a pass audited
        at an assumed speed must not read as a plain pass)."""
        if self.report is None:
            return {
                "file": self.path,
                "turbine": None,
                "tower_class": None,
                "verdict": self.outcome,
                "worst_check": None,
                "margin": None,
                "message": self.error,
                "warnings": [],
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
            "warnings": list(self.report["warnings"]),
        }


def discover(paths: Iterable[Path]) -> list[Path]:
    """Input files: files as given; folders searched recursively for specs, windIO files,
    ElastoDyn main decks (``.dat``/``.fst`` files that name a ``TwrFile``) and HAWC2 models
    (:func:`discover_all` also says what it left out)."""
    return discover_all(paths)[0]


def discover_all(paths: Iterable[Path]) -> tuple[list[Path], list[tuple[str, str]]]:
    """The inputs, and every file left out with why: a file given or found twice (by its
    path, a link to it, the same file under another name), and the files in the folders
    that ``check`` reads but a batch of turbines does not (another tool's Campbell results,
    the parts of a HAWC2 model) — never a silent skip."""
    found: list[Path] = []
    skipped: list[tuple[str, str]] = []
    for p in paths:
        if p.is_dir():
            inputs, left = _search(p)
            found += inputs
            skipped += left
        else:
            found.append(p)
    seen: dict[object, Path] = {}
    unique = []
    for p in found:
        try:
            info = p.stat()
            r: object = (info.st_dev, info.st_ino)  # the file, however it is named
        except (OSError, ValueError):  # a symlink loop, a missing file: its audit says
            r = p.absolute()
        if r in seen:
            skipped.append((str(p), f"the same file as {seen[r]}, audited once"))
            continue
        seen[r] = p
        unique.append(p)
    return unique, skipped


#: Files a folder may hold that ``check`` reads but a batch of turbine descriptions does
#: not audit one by one, and why.
LEFT_OUT = {
    ".lin": "an OpenFAST linearisation: check its folder (its azimuths are one operating point)",
    ".cmb": "HAWCStab2 Campbell results: check it on its own (with --blades where it does not say)",
}


#: Why a WISDEM/WEIS options file in a folder is not audited (every WISDEM example folder
#: holds its modeling and analysis options beside the windIO turbine)
OPTIONS = OPTIONS_FILE


#: Stems of the batch's own files: an input may not take them (its report would be
#: overwritten by the summary).
RESERVED = frozenset({"summary", "run-metadata", "audit"})


def _search(folder: Path) -> tuple[list[Path], list[tuple[str, str]]]:
    """The main inputs in a folder and its subfolders; a subfolder that cannot be searched
    (no permission) is itself an input, whose audit says why — never skipped silently."""
    from ..importers import is_main_input
    from ..spec.load import other_kind

    out: list[Path] = []
    unreadable: list[Path] = []
    left: list[tuple[str, str]] = []

    def refused(exc: OSError) -> None:
        unreadable.append(Path(exc.filename) if exc.filename else folder)

    for root, dirs, files in os.walk(folder, onerror=refused):
        hidden = [d for d in dirs if d.startswith(".")]  # .git, .github: a tool's, said
        left += [(str(Path(root) / d), "a hidden folder (a tool's), not searched") for d in hidden]
        dirs[:] = sorted(d for d in dirs if not d.startswith("."))
        for q in sorted(Path(root) / f for f in files):
            try:
                regular = q.is_file()
            except OSError:
                regular = False
            yaml = regular and q.suffix.lower() in (".yaml", ".yml")
            if yaml and (kind := other_kind(q)) is not None:
                left.append((str(q), kind))
            elif regular and is_main_input(q):
                out.append(q)
            elif regular and q.suffix.lower() in LEFT_OUT:
                left.append((str(q), LEFT_OUT[q.suffix.lower()]))
            elif regular and q.suffix.lower() == ".htc":
                left.append(
                    (str(q), "a part of a HAWC2 model, read where the model continues in it")
                )
    named = _named_by_decks(out)
    alone = []
    for q in out:  # each resolved once; a list's remove() made a large batch quadratic
        deck = named.get(_resolved(q))
        if deck is None:
            alone.append(q)
        else:
            left.append((str(q), f"the ElastoDyn file of {deck}, audited with its deck set"))
    return sorted(alone) + unreadable, left


def _named_by_decks(found: Sequence[Path]) -> dict[Path, Path]:
    """The ElastoDyn files the .fst files among ``found`` name (``EDFile``), each with the
    .fst: audited with its deck set, not again alone (without its AeroDyn and ServoDyn: a
    second story of one turbine). An .fst that cannot be read names none (its own audit
    says why)."""
    from ..importers.deck import beside, parse

    named: dict[Path, Path] = {}
    for fst in found:
        if fst.suffix.lower() != ".fst":
            continue
        try:
            ed = beside(fst, parse(fst).text("EDFile"))
        except (WtvibError, OSError):
            continue
        if _resolved(ed) != _resolved(fst):
            named[_resolved(ed)] = fst
    return named


def _resolved(p: Path) -> Path:
    try:
        return p.resolve()
    except (OSError, RuntimeError):  # a symlink loop
        return p.absolute()


def output_keys(paths: Sequence[Path]) -> list[str]:
    """File stems for the outputs, one per input and never one of the batch's own.

    A stem shared by several inputs (``a/x.yaml``, ``b/x.yaml``; ``y.yaml`` and ``y.yml``)
    takes as many parent folders as make it unique (``a/t/x`` and ``b/t/x`` →
    ``a__t__x`` and ``b__t__x``), then its suffix; a reserved stem is prefixed ``input__``.
    """
    parts = [_resolved(p).with_suffix("").parts for p in paths]
    keys = []
    for p, mine in zip(paths, parts, strict=True):
        others = {q for q in parts if q != mine}
        depth = 1
        while depth < len(mine) and any(q[-depth:] == mine[-depth:] for q in others):
            depth += 1
        key = "__".join(mine[-depth:])
        if sum(q == mine for q in parts) > 1:  # same path, other suffix (y.yaml, y.yml)
            key += "__" + p.suffix.lstrip(".")
        keys.append(f"input__{key}" if key in RESERVED else key)
    return _unique(keys)


def _unique(keys: list[str]) -> list[str]:
    """The stems made unique where the joins still meet (``a/b.yaml`` and ``a__b.yaml``
    both ``a__b``; ``summary.yaml`` and ``input__summary.yaml``), by ``--2``, ``--3`` … in
    input order, case aside (a case-blind file system holds ``A`` and ``a`` as one); none
    is one of the batch's own names."""
    taken = {k.casefold() for k in RESERVED}
    out = []
    for key in keys:
        candidate, n = key, 1
        while candidate.casefold() in taken:
            n += 1
            candidate = f"{key}--{n}"
        taken.add(candidate.casefold())
        out.append(candidate)
    assert len({k.casefold() for k in out}) == len(out)
    return out


#: Draws a report's figures: PNG bytes by file stem suffix (``plots.render.Drawer.pngs``).
Draw = Callable[["Report"], dict[str, bytes]]


def audit_one(
    path: str, key: str, plots: bool, options: Options | None = None, draw: Draw | None = None
) -> Item:
    """Load, audit and (optionally) plot one input — every figure, drawn in this process
    unless ``draw`` is given. Never raises (but for Ctrl-C): a user's mistake is an input
    error, any other exception an internal error naming it."""
    try:
        return audit_one_raising(path, key, plots, options or Options(), draw)
    except WtvibError as exc:
        return Item(path, key, error=str(exc))
    except Exception as exc:  # the last line of defence: one turbine, not the batch
        return Item(path, key, error=internal_message(path, exc), internal=True)


def internal_message(path: str, exc: BaseException) -> str:
    """The one line an unexpected exception becomes: file, exception, and what to do."""
    text = str(exc).splitlines()[0] if str(exc) else ""
    return (
        f"{path}: internal error ({type(exc).__name__}{': ' + text if text else ''}); this is "
        "a wtvib bug, not a verdict — rerun with --debug for the traceback and report it"
    )


def audit_one_raising(
    path: str, key: str, plots: bool, options: Options, draw: Draw | None = None
) -> Item:
    """:func:`audit_one` letting every exception through (``--debug``: its traceback)."""
    from .. import audit

    t0 = time.perf_counter()
    turbine = options.load(path)
    t1 = time.perf_counter()
    report = audit.run(
        turbine, options.settings(turbine), samples=options.samples, seed=options.seed
    )
    t2 = time.perf_counter()
    pngs: dict[str, bytes] = {}
    if plots:
        from ..outputs.plots.render import inline

        pngs = draw(report) if draw is not None else inline(report, detail=True)
    t3 = time.perf_counter()
    return Item(
        path,
        key,
        report=report.to_dict(),
        pngs=pngs,
        timings={"load": t1 - t0, "solve": t2 - t1, "plot": t3 - t2},
        campbell_csv=campbell_to_csv(report.campbell, report.identity),
    )


#: How long a batch waits on a cluster without workers, and how often it looks.
WORKERLESS_S = 60
POLL_S = 2.0


def worker_start(parent: int) -> None:
    """A batch worker's first act: it dies with the process that started it — a killed
    ``batch`` (SIGKILL) leaves no worker behind holding the caller's pipe open — by the
    kernel's parent-death signal on Linux and a watchdog on the parent's pid elsewhere;
    Ctrl-C and SIGTERM are the parent's to handle (a worker ignores the one and dies of the
    other, without a traceback), and its standard output is /dev/null (the parent writes)."""
    import signal
    import threading

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)  # not the parent's handler, inherited
    with contextlib.suppress(OSError):
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, 1)
        os.close(null)
    with contextlib.suppress(OSError, AttributeError, TypeError):
        import ctypes

        libc = ctypes.CDLL(None)
        libc.prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
    if os.getppid() != parent:  # the parent died before the signal was asked for
        os._exit(1)

    def watchdog() -> None:
        while os.getppid() == parent:
            time.sleep(1.0)
        os._exit(1)

    threading.Thread(target=watchdog, name="wtvib-parent-watchdog", daemon=True).start()


def run(
    paths: Sequence[Path],
    *,
    jobs: int | None = None,
    plots: bool = True,
    on_done: Callable[[Item], None] | None = None,
    options: Options | None = None,
    executor: Executor | None = None,
    alive: Callable[[], bool] | None = None,
) -> list[Item]:
    """Audit every input, in parallel on ``jobs`` processes (or on ``executor``: a Dask
    cluster's, :mod:`wtvib.studies.cluster`); results in input order.

    ``on_done`` is called in the parent process as each item completes (progress, writes).
    ``alive`` (a cluster's: whether it has a worker) bounds the wait: with no worker for
    :data:`WORKERLESS_S` the items left are reported as not audited, the rest stands.
    ``KeyboardInterrupt`` propagates after cancelling what has not started.
    """
    keys = output_keys(paths)
    jobs = jobs or os.cpu_count() or 1
    if executor is None and (jobs == 1 or len(paths) < 2):
        return _in_turn(paths, keys, plots, options, on_done)
    own = executor is None
    pool = executor or ProcessPoolExecutor(
        max_workers=min(jobs, len(paths)), initializer=worker_start, initargs=(os.getpid(),)
    )
    with pool if own else contextlib.nullcontext(pool):
        futures: dict[Future[Item], int] = {
            pool.submit(audit_one, str(p), k, plots, options): i
            for i, (p, k) in enumerate(zip(paths, keys, strict=True))
        }
        try:
            results = _gathered(futures, paths, keys, on_done, alive)
        except BaseException:
            # stop now: pending work is cancelled and running workers are ended (their
            # results would be thrown away), so Ctrl-C or SIGTERM returns at once
            for fut in futures:
                fut.cancel()
            if own:
                _stop(pool)  # type: ignore[arg-type]
            raise
    return [results[i] for i in range(len(paths))]


def _in_turn(
    paths: Sequence[Path],
    keys: Sequence[str],
    plots: bool,
    options: Options | None,
    on_done: Callable[[Item], None] | None,
) -> list[Item]:
    """The inputs audited one after another in this process."""
    items = []
    for p, k in zip(paths, keys, strict=True):
        item = audit_one(str(p), k, plots, options)
        if on_done:
            on_done(item)
        items.append(item)
    return items


def _gathered(
    futures: "dict[Future[Item], int]",
    paths: Sequence[Path],
    keys: Sequence[str],
    on_done: Callable[[Item], None] | None,
    alive: Callable[[], bool] | None,
) -> dict[int, Item]:
    """Each submitted audit's item by its input's index, as they complete; a worker that
    died is that row's internal error; on a cluster without a worker for
    :data:`WORKERLESS_S` the items left are not audited, said."""
    from concurrent.futures import FIRST_COMPLETED, wait

    results: dict[int, Item] = {}

    def arrived(i: int, item: Item) -> None:
        results[i] = item
        if on_done:
            on_done(item)

    pending = set(futures)
    since: float | None = None
    while pending:
        done, pending = wait(pending, timeout=POLL_S, return_when=FIRST_COMPLETED)
        for fut in done:
            i = futures[fut]
            try:
                item = fut.result()
            except Exception as exc:  # a worker died (memory, signal): that row only
                error = internal_message(str(paths[i]), exc)
                item = Item(str(paths[i]), keys[i], error=error, internal=True)
            arrived(i, item)
        if done or alive is None or alive():
            since = None
            continue
        since = since or time.monotonic()
        if time.monotonic() - since < WORKERLESS_S:
            continue
        for fut in pending:  # a cluster without workers: the rest fail, said
            fut.cancel()
            i = futures[fut]
            error = (
                f"{paths[i]}: not audited — the cluster had no worker for "
                f"{WORKERLESS_S} s (its workers were lost); run it again"
            )
            arrived(i, Item(str(paths[i]), keys[i], error=error, internal=True))
        break
    return results


def _stop(pool: ProcessPoolExecutor) -> None:
    """End a process pool now: cancel what is queued, terminate the workers, and wait
    (bounded) for the pool's manager thread. On Python 3.11 that thread then tries to fail
    the futures already cancelled and prints an ``InvalidStateError`` traceback (fixed in
    CPython 3.12, gh-94440 family); it is bookkeeping of cancelled work, not a fault of the
    run, and is not shown."""
    import threading
    from concurrent.futures import InvalidStateError

    previous = threading.excepthook

    def quiet(args: threading.ExceptHookArgs) -> None:
        if not isinstance(args.exc_value, InvalidStateError):
            previous(args)

    threading.excepthook = quiet
    try:
        workers = list((getattr(pool, "_processes", None) or {}).values())
        manager = getattr(pool, "_executor_manager_thread", None)
        pool.shutdown(wait=False, cancel_futures=True)
        for process in workers:
            process.terminate()
        if manager is not None:
            manager.join(timeout=10.0)
    finally:
        threading.excepthook = previous


class FolderLock:
    """One batch at a time writes into a folder: a lock file made exclusively (O_EXCL),
    holding the writer's process id; a lock left by a process that is gone is taken over."""

    NAME = ".wtvib-batch.lock"

    def __init__(self, folder: Path) -> None:
        self.path = Path(folder) / self.NAME

    def __enter__(self) -> "FolderLock":
        from ..errors import OutputError
        from ..outputs.files import unwritable

        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise OutputError(unwritable(self.path.parent, exc)) from None
        for _ in range(2):
            try:
                fd = os.open(self.path, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o644)
            except FileExistsError:
                if self.path.is_symlink() or not self.path.is_file():
                    raise OutputError(
                        f"{self.path} is not a wtvib lock file (a symbolic link, a folder or "
                        "a device): remove it, or give another --out-dir"
                    ) from None
                if self._stale():
                    self.path.unlink(missing_ok=True)
                    continue
                raise OutputError(
                    f"another wtvib batch is writing into {self.path.parent} ({self.path} "
                    "holds its process id); wait for it, or give another --out"
                ) from None
            with os.fdopen(fd, "w") as fh:
                fh.write(str(os.getpid()))
            return self
        raise OutputError(f"cannot lock {self.path.parent}")

    #: The largest process id a lock may hold (Linux's pid_max ceiling, 2²²).
    MAX_PID = 1 << 22

    def _stale(self) -> bool:
        """Whether the lock's writer is gone: its process id not running — or no process id
        at all (empty, 0, negative, too large, text: os.kill(0) and os.kill(−1) reach
        whole process groups and never say "gone", a huge one overflows), unless the file
        is a second old or less (a writer between making it and writing its id)."""
        import time

        try:
            text = self.path.read_text(errors="replace").strip()
            young = time.time() - self.path.stat().st_mtime < 1.0
        except OSError:
            return False
        if not text.isdigit() or not 0 < int(text) < self.MAX_PID:
            return not (young and not text)
        try:
            os.kill(int(text), 0)
        except ProcessLookupError:
            return True
        except OSError:  # PermissionError: another user's live process
            return False
        return False

    def __exit__(self, *exc: object) -> None:
        self.path.unlink(missing_ok=True)


@contextlib.contextmanager
def terminate_as_interrupt() -> Iterator[Callable[[], bool]]:
    """SIGTERM handled like Ctrl-C (pending work cancelled, workers stopped, what is complete
    written); yields a function telling whether SIGTERM was the cause. A worker forked just
    as a signal reaches the whole group runs this handler before it sets its own
    (:func:`worker_start`): there it ends at once, without a word — raising inside the fork's
    own bookkeeping printed "Exception ignored" and could leave the worker alive, holding the
    caller's pipe open."""
    import signal

    seen = {"term": False}
    owner = os.getpid()

    def handler(signum: int, frame: object) -> None:
        if os.getpid() != owner:  # a worker that has not set its own handlers yet
            os._exit(128 + signum)
        if signum == signal.SIGTERM:
            seen["term"] = True
        raise KeyboardInterrupt

    try:
        previous = {s: signal.signal(s, handler) for s in (signal.SIGTERM, signal.SIGINT)}
    except ValueError:  # not the main thread (tests): leave signals alone
        yield lambda: False
        return
    try:
        yield lambda: seen["term"]
    finally:
        for s, before in previous.items():
            signal.signal(s, before)


def summary(items: Sequence[Item]) -> dict[str, Any]:
    """The batch summary document (deterministic: no times, no dates)."""
    counts = {k: 0 for k in OUTCOME_ORDER}
    for it in items:
        counts[it.outcome] += 1
    return {
        "schema": SUMMARY_SCHEMA,
        "counts": counts,
        "turbines": [it.row() for it in items],
    }


def summary_csv(items: Sequence[Item]) -> str:
    """The summary rows as CSV text; a text cell that a spreadsheet would run as a
    formula (a turbine or file named "=…") is quoted (:func:`outputs.spreadsheet_cell`)."""
    from ..outputs.files import spreadsheet_cell

    buf = io.StringIO()
    cols = [
        "file",
        "turbine",
        "tower_class",
        "verdict",
        "worst_check",
        "margin",
        "message",
        "warnings",
    ]
    writer = csv.DictWriter(buf, fieldnames=cols, lineterminator="\n")
    writer.writeheader()
    for it in items:
        row = {**it.row()}
        row["warnings"] = " | ".join(row["warnings"])
        writer.writerow(
            {k: spreadsheet_cell(v) if isinstance(v, str) else v for k, v in row.items()}
        )
    return buf.getvalue()


def results_json(items: Sequence[Item]) -> str:
    """One JSON document with every result (``--format json``)."""
    doc = {
        "schema": RESULTS_SCHEMA,
        "results": [
            {"file": it.path, "outcome": it.outcome, "report": it.report, "error": it.error}
            for it in items
        ],
    }
    return json.dumps(doc, indent=2, ensure_ascii=False, allow_nan=False) + "\n"


def exit_code(items: Sequence[Item], strict: bool = False) -> int:
    """3 if any internal error, 2 if any input error, 1 if any fail (or warn with
    ``strict``), else 0."""
    outcomes = {it.outcome for it in items}
    if "internal-error" in outcomes:
        return EXIT_INTERNAL
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
