"""What every command says besides its report: exit codes, one-line messages on the
standard streams (safe for any name, :func:`wtvib.outputs.streams.shown`), a spinner while
a step runs on a terminal, and the rich console the tables are drawn on."""

import contextlib
import sys
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any, NoReturn

#: Exit codes: pass or warn, fail (or warn with --strict), bad input or output, a wtvib bug.
EXIT_PASS, EXIT_FAIL, EXIT_INPUT, EXIT_INTERNAL = 0, 1, 2, 3


def shown(text: object) -> str:
    """Text safe to show on a terminal (no control or direction-override characters)."""
    from ..outputs.streams import shown as safe

    return safe(text)


def say(text: str, err: bool = False) -> None:
    """One line on standard output (or error), flushed at once."""
    stream = sys.stderr if err else sys.stdout
    stream.write(text + "\n")
    stream.flush()


def wrote(console: Any, paths: list[Path]) -> None:
    """``wrote <path>`` for each file: on stderr where there is no console (a JSON report on
    stdout), else as the console's own lines after the report."""
    if console is None:
        for path in paths:
            say(f"wrote {shown(path)}", err=True)
        return
    from ..outputs.report import wrote as listed

    sys.stdout.flush()
    listed(console, paths)


def console(stderr: bool = False) -> Any:
    """A rich console that does not hard-wrap text where it is not a terminal (a pipe, a
    file: ``window … | less`` had "74.3%)" alone on a line); tables and panels keep their
    width (COLUMNS where the user sets it)."""
    from rich.console import Console

    stream = sys.stderr if stderr else sys.stdout
    try:
        terminal = stream.isatty()
    except (AttributeError, ValueError):
        terminal = False
    return Console(stderr=stderr, soft_wrap=not terminal)


@contextlib.contextmanager
def working(what: str) -> Iterator[None]:
    """A spinner saying ``what`` on stderr while a step runs — on a terminal only (rich is
    not imported otherwise), and gone after."""
    if not sys.stderr.isatty():
        yield
        return

    with console(stderr=True).status(what, spinner="line"):
        yield


@contextlib.contextmanager
def cluster(address: str | None) -> Iterator[Any]:
    """A Dask client on ``address`` for the command's duration (None: run locally)."""
    if address is None:
        yield None
        return
    from ..studies.cluster import close, connect

    client = connect(address)
    try:
        yield client
    finally:
        close(client)


def dump(doc: object) -> None:
    """A JSON document on standard output, as every command writes one."""
    import json

    sys.stdout.write(json.dumps(doc, indent=2, ensure_ascii=False) + "\n")


def failed(exc: Exception, source: object, inputs: str) -> int:
    """A command's exception as one line on stderr, and its exit code: a user's mistake
    (a :class:`wtvib.errors.WtvibError`; a model that cannot be solved names ``source``)
    or the environment's (an ``OSError`` naming a file, or the standard output that could
    not take the report) exit 2; anything else is a wtvib bug naming ``inputs``, exit 3 —
    never 1, the code of a FAIL verdict."""
    from ..errors import WtvibError
    from ..outputs import streams

    if isinstance(exc, WtvibError):
        text = str(exc)
        modal = sys.modules.get("wtvib.numerics.modal")  # not imported for a typo's error
        if source is not None and modal is not None and isinstance(exc, modal.ModalError):
            text = f"{source}: {text}"  # a model that cannot be solved: which input
        say(f"error: {shown(text)}", err=True)
        return EXIT_INPUT
    if isinstance(exc, OSError):  # the environment's fault: a full disk, a closed pipe
        lost = streams.lost_output(exc)
        if lost is not None:
            streams.discard_stdout()
            say(f"error: {lost}", err=True)
            return EXIT_INPUT
        if exc.filename is not None:
            reason = exc.strerror or type(exc).__name__
            say(f"error: {streams.shown(exc.filename)}: {reason}", err=True)
            return EXIT_INPUT
    from .batch import internal_message  # a bug: the numerical stack may be imported

    say(f"error: {shown(internal_message(inputs, exc))}", err=True)
    return EXIT_INTERNAL


def reuse_freed_memory() -> None:
    """Ask glibc's allocator to serve large blocks from its heap and to keep freed ones for
    the next (``mallopt``: M_MMAP_THRESHOLD 1 GiB, M_TRIM_THRESHOLD 2 GiB) instead of mapping
    fresh pages for each block over 32 MB and unmapping it when freed. A full-system
    linearisation's check allocates dozens of 30–70 MB arrays one after another; where a
    fresh page is dear (the benchmark machine: ~4 ms a megabyte) that was 3 s of 24
    (bench/RESULTS.md). The command's process only — wtvib used as a library leaves the
    allocator alone — and nothing where the C library is not glibc."""
    import ctypes

    try:
        mallopt = ctypes.CDLL(None).mallopt
    except (OSError, AttributeError, TypeError):  # not glibc (macOS, musl; Windows)
        return
    mallopt(-3, 1 << 30)  # M_MMAP_THRESHOLD
    mallopt(-1, (1 << 31) - 1)  # M_TRIM_THRESHOLD (a C int)


def collect_old_objects_rarely() -> None:
    """Let Python's cycle collector scan the objects that survived a young collection only
    after a thousand young collections (its default: ten), the oldest as before. A
    command's process creates some 110,000 long-lived objects importing numpy, pydantic,
    the spec's models and wtvib; with the default thresholds the collector went over them
    again and again, 45–110 ms of a check (the mod-2, the IEA-22 windIO file, the IEA-15
    monopile deck set; bench/RESULTS.md), for no memory given back (the same peak). The
    young collections still run as before, so cyclic garbage is still freed, and a batch
    worker's or the Monte Carlo samples' long loops still reach the older generations. The
    command's process only: wtvib used as a library leaves the collector alone."""
    import gc

    young, _, oldest = gc.get_threshold()
    gc.set_threshold(young, 1000, oldest)


def solve_on_every_core() -> None:
    """This process audits one turbine: its stacks of eigenproblems (a sweep's speeds, the
    operating points') are shared out over the cores it may run on
    (:func:`wtvib.numerics.modal.set_threads`: the same bits, sooner). ``batch``'s workers,
    several turbines at once on those cores, leave it at one thread."""
    from ..numerics import modal
    from ..outputs.plots.render import cores

    modal.set_threads(cores())


def main(command: Callable[[], object]) -> NoReturn:
    """Run the command line ``command`` as a process: the standard streams made safe first
    (:mod:`wtvib.outputs.streams`), and what is still buffered for the output flushed here,
    where a full disk is one line and exit 2 rather than Python's "Exception ignored" at
    exit."""
    from ..outputs import streams

    streams.guard()
    reuse_freed_memory()
    collect_old_objects_rarely()
    try:
        command()
        code: object = 0
    except SystemExit as exc:
        code = exc.code
    try:
        sys.stdout.flush()
    except OSError as exc:
        lost = streams.lost_output(exc) or str(exc)
        streams.discard_stdout()
        print(f"error: {lost}", file=sys.stderr)
        code = EXIT_INPUT
    raise SystemExit(code)


def program(command: Callable[[], object]) -> NoReturn:
    """The ``wtvib`` program (its console script, ``python -m wtvib``): :func:`main`, the
    process then ended at once where nothing is left to finish (:func:`end`)."""
    try:
        main(command)
    except SystemExit as exc:
        end(exc.code)


def end(code: object) -> NoReturn:
    """End the ``wtvib`` program's process with ``code`` (after :func:`main`): at once
    where nothing is left to finish — its exit handlers run, the standard streams flushed,
    then ``os._exit``, without the interpreter's teardown (every module and object freed
    one by one: 50–60 ms of a check, bench/RESULTS.md) — else as Python ends (a thread or
    a child process still running, a message as the code, coverage measuring the run, an
    interpreter without ``atexit._run_exitfuncs``). The standard output was flushed by
    :func:`main`; a caller of ``cli.main`` from Python gets its SystemExit as before."""
    import atexit
    import os
    import threading

    run_handlers = getattr(atexit, "_run_exitfuncs", None)
    alone = threading.active_count() == 1 and not (
        "multiprocessing" in sys.modules and sys.modules["multiprocessing"].active_children()
    )
    if (
        (code is None or isinstance(code, int))
        and alone
        and run_handlers is not None
        and "coverage" not in sys.modules
    ):
        run_handlers()
        for stream in (sys.stdout, sys.stderr):
            with contextlib.suppress(OSError, ValueError, AttributeError):
                stream.flush()
        os._exit(code or 0)
    raise SystemExit(code)
