"""PNG bytes of a report's figures, drawn beside the audit.

A ``check`` spends about as long importing matplotlib (≈ 0.5 s) and drawing its figures
(0.15–0.4 s each) as it spends auditing. Where there is more than one core and ``os.fork``
(Linux), :class:`Drawer` forks a drawing process once the models are imported and before
the audit starts: it imports matplotlib while the audit runs, receives the report
(pickled without the spec's derived models: 0.2 MB for the NREL 5-MW deck, 0.6 MB for the
IEA-22, a few ms), and draws the figures
in processes forked again (matplotlib loaded), up to two per core. (Forking before the
models are imported gains nothing: the drawing process needs them to unpickle the
report.) It returns PNG bytes; the caller writes the files (its own atomic,
no-silent-overwrite rule). The bytes are those drawing in-process gives (a test). If the
drawing process fails in any way — killed, out of memory, a drawing bug — the figures are
drawn in-process instead, where a drawing bug then raises as it always did: a fault there
costs time, never a figure. ``WTVIB_DRAW=inline`` draws in-process always.
"""

import contextlib
import os
import pickle
import select
import signal
import sys
import threading
import time
from collections.abc import Callable
from types import TracebackType
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ...audit import Report


def cores() -> int:
    """The cores this process may run on."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def forking() -> bool:
    """Whether drawing beside the audit can help here — and is safe: never from a process
    with other threads running (a fork copies none of them, but any lock one holds, and the
    drawing process could wait on it for ever; Python 3.12 warns of it too)."""
    return (
        sys.platform.startswith("linux")
        and hasattr(os, "fork")
        and cores() > 1
        and os.environ.get("WTVIB_DRAW", "") != "inline"
        and threading.active_count() == 1
    )


def inline(report: "Report", detail: bool) -> dict[str, bytes]:
    """The figures drawn in this process, as PNG bytes by file stem suffix."""
    from . import diagrams, png_bytes

    _lean_matplotlib()
    return {name: png_bytes(fig) for name, fig in diagrams(report, detail).items()}


def _config_home() -> None:
    """Where matplotlib keeps its font cache: its own choice (MPLCONFIGDIR, else the user's
    cache directory, ``$XDG_CACHE_HOME/matplotlib`` or ``~/.cache/matplotlib``) where that
    can be written; else wtvib's folder in the user's cache directory. matplotlib would
    otherwise make a ``/tmp/matplotlib-*`` folder for every run and leave it behind."""
    from pathlib import Path

    def writable(folder: Path) -> bool:
        try:
            folder.mkdir(parents=True, exist_ok=True)
            return os.access(folder, os.W_OK | os.X_OK)
        except OSError:
            return False

    given = os.environ.get("MPLCONFIGDIR")
    cache = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache")
    if given is not None:
        if writable(Path(given)):
            return
    elif writable(cache / "matplotlib"):
        return
    for folder in (cache / "wtvib" / "matplotlib", Path.cwd() / ".wtvib-matplotlib"):
        if writable(folder):
            os.environ["MPLCONFIGDIR"] = str(folder)
            return


def _lean_matplotlib() -> None:
    """Import matplotlib without its help text.

    matplotlib spends about 40 % of its import writing, for
    every artist class, the signature and docstring of its ``set`` method and the property
    lists its methods' docstrings include (``artist.kwdoc``): help for interactive use,
    which a process that draws PNGs never reads. Where matplotlib is not imported yet, both
    are skipped — for the rest of the process: a drawing process, a batch worker, the CLI
    drawing in-process (the same pixels, a test). Where it is (a user's program that
    imported it), nothing changes; nor where a matplotlib no longer has the two hooks.
    """
    if "matplotlib" not in sys.modules:
        _config_home()
        import matplotlib.artist as artist

        if hasattr(artist.Artist, "_update_set_signature_and_docstring") and hasattr(
            artist, "kwdoc"
        ):
            artist.Artist._update_set_signature_and_docstring = classmethod(lambda cls: None)
            artist.kwdoc = lambda artist: ""


def _warm() -> None:
    """Import what drawing needs (matplotlib with the Agg canvas)."""
    _lean_matplotlib()
    import matplotlib.backends.backend_agg
    import matplotlib.figure
    import matplotlib.lines
    import matplotlib.patches  # noqa: F401

    from . import blade, campbell, drivetrain, rotor, system  # noqa: F401


#: A drawing process that has not answered after this long [s] is killed and the figures
#: are drawn in-process (drawing takes seconds; a hung process must not hang the check).
TIMEOUT_S = 120.0


def _read(fd: int, timeout: float | None = None) -> bytes | None:
    """Everything from a pipe until it closes; None if ``timeout`` [s] passes first."""
    deadline = None if timeout is None else time.monotonic() + timeout
    chunks: list[bytes] = []
    try:
        while True:
            if deadline is not None:
                ready, _, _ = select.select([fd], [], [], max(0.0, deadline - time.monotonic()))
                if not ready:
                    return None
            chunk = os.read(fd, 1 << 20)
            if not chunk:
                return b"".join(chunks)
            chunks.append(chunk)
    finally:
        os.close(fd)


def _write(fd: int, data: bytes) -> None:
    try:
        view = memoryview(data)
        while view:
            view = view[os.write(fd, view) :]
    finally:
        os.close(fd)


def _fork(work: Callable[[], object]) -> tuple[int, int]:
    """``work()`` in a forked child; (its pid, the pipe to read its pickled result from)."""
    read, write = os.pipe()
    try:
        pid = os.fork()
    except OSError:
        os.close(read)
        os.close(write)
        raise
    if pid == 0:  # the child: never returns
        os.close(read)
        code = 0
        try:
            try:
                result = pickle.dumps(("ok", work()))
            except BaseException as exc:  # reported; the parent then draws in-process
                code = 1
                result = pickle.dumps(("error", f"{type(exc).__name__}: {exc}"))
            _write(write, result)
        finally:
            os._exit(code)
    os.close(write)
    return pid, read


def _collect(pid: int, fd: int) -> Any:
    """A forked child's result, or None if it failed or did not answer in TIMEOUT_S."""
    data = _read(fd, TIMEOUT_S)
    if data is None:
        os.kill(pid, signal.SIGKILL)
    os.waitpid(pid, 0)
    try:
        status, value = pickle.loads(data or b"")
    except Exception:  # killed before it wrote, or cut short
        return None
    return value if status == "ok" else None


def _render(report: "Report", detail: bool, jobs: int) -> dict[str, bytes]:
    """The figures drawn by ``jobs`` processes: this one and jobs − 1 forked."""
    from . import drawers, png_bytes

    makers = drawers(report, detail)
    names = list(makers)
    jobs = max(1, min(jobs, len(names)))

    def part(k: int) -> dict[str, bytes]:
        out = {}
        for name in names[k::jobs]:
            fig = makers[name]()
            if fig is not None:
                out[name] = png_bytes(fig)
        return out

    children = [_fork(lambda k=k: part(k)) for k in range(1, jobs)]  # type: ignore[misc]
    parts = [part(0)] + [_collect(pid, fd) for pid, fd in children]
    if any(p is None for p in parts):
        raise RuntimeError("a drawing process failed")
    merged: dict[str, bytes] = {}
    for p in parts:
        merged.update(p)
    return {name: merged[name] for name in names if name in merged}


class Drawer:
    """Start before the audit, ask for the PNGs after it (module docstring). A context
    manager: leaving it without asking ends the drawing process."""

    def __init__(self, enabled: bool = True) -> None:
        self._child: tuple[int, int] | None = None
        self._inbox: int | None = None
        self._sent = False
        if not (enabled and forking()):
            return
        read, write = os.pipe()

        def work() -> object:
            os.close(write)
            _warm()
            data = _read(read)  # the parent's audit takes what it takes
            if not data:  # the audit failed: nothing to draw
                return None
            report, detail = pickle.loads(data)
            # more processes than cores: figures differ in cost, and the system then shares
            # the cores between them (three figures on two: not the longest two in a row)
            return _render(report, detail, 2 * cores())

        try:
            self._child = _fork(work)
        except OSError:  # no process to spare (a process limit): draw in-process
            os.close(write)
            return
        finally:
            os.close(read)
        self._inbox = write

    def send(self, report: "Report", detail: bool) -> None:
        """Hand the report to the drawing process, which starts drawing at once: the caller
        may do other work (render its text) before it asks for :meth:`pngs`."""
        if self._inbox is not None:
            inbox, self._inbox = self._inbox, None
            self._sent = True
            try:
                data = pickle.dumps((report, detail))
            except Exception:  # a report that does not pickle: the drawing process reads
                os.close(inbox)  # nothing and ends; pngs() draws in-process
                return
            with contextlib.suppress(OSError):  # the drawing process is gone
                _write(inbox, data)

    def pngs(self, report: "Report", detail: bool) -> dict[str, bytes]:
        """The report's figures as PNG bytes by file stem suffix (diagrams' order); the
        same report and ``detail`` as :meth:`send`, if it was called."""
        self.send(report, detail)
        if self._child is not None:
            child, self._child = self._child, None
            value = _collect(*child)
            if isinstance(value, dict):
                return value
        return inline(report, detail)

    def close(self) -> None:
        """End the drawing process where it still runs: nothing to draw, or a report whose
        figures are no longer wanted (the caller failed after :meth:`send`)."""
        if self._inbox is not None:
            os.close(self._inbox)
            self._inbox = None
        if self._child is not None:
            # nothing more to draw: ended at once (waiting would wait for its import of
            # matplotlib, a third of a second, before an error could be shown)
            with contextlib.suppress(ProcessLookupError):
                os.kill(self._child[0], signal.SIGKILL)
            _collect(*self._child)
            self._child = None

    def __enter__(self) -> "Drawer":
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self.close()
