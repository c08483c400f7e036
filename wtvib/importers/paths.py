"""Files a model names, found as the code that reads the model would find them.

OpenFAST and HAWC2 models are written on Windows as often as not, where a file's name is
read without regard to case and with either slash: ``"..\\5MW_Baseline\\Blade.dat"``, or
``./data/dtu_10mw_rwt_tower_st.dat`` for ``DTU_10MW_RWT_Tower_st.dat`` (a DTU 10 MW model
in wetb's test files). On a case-sensitive file system those names are no file. wtvib takes
a name as written first; where no such file is there, as Windows reads it — backslashes as
separators, each part matched without regard to case where exactly one entry of its folder
matches — and the audit says so in its assumptions (:func:`recording`).
"""

import os
from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from pathlib import Path, PureWindowsPath

#: The read under way (:func:`recording`): the names read as Windows reads them, and other
#: notes; None outside one.
_READ: ContextVar[tuple[dict[str, Path], list[str]] | None] = ContextVar("names", default=None)


def locate(folder: Path, name: str) -> Path:
    """``folder / name`` where that is a file; else the file Windows would open for that
    name (noted in the read under way); else ``folder / name``, for the caller to refuse."""
    literal = folder / name
    if is_file(literal):
        return literal
    found = _as_windows_reads(folder, name)
    if found is None:
        return literal
    read = _READ.get()
    if read is not None:
        read[0].setdefault(name, found)
    return found


def note(text: str) -> None:
    """One note on how a name was found, for the read under way (once)."""
    read = _READ.get()
    if read is not None and text not in read[1]:
        read[1].append(text)


@contextmanager
def recording() -> Iterator[list[str]]:
    """The notes on the names :func:`locate` found within the block — those read as Windows
    reads them in one — filled in when the block ends."""
    out: list[str] = []
    read: tuple[dict[str, Path], list[str]] = ({}, [])
    token = _READ.set(read)
    try:
        yield out
    finally:
        _READ.reset(token)
        windows, notes = read
        if windows:
            named = "; ".join(f"{name!r} → {found.name}" for name, found in windows.items())
            out.append(
                f"{len(windows)} file name(s) of the model are no file's on this file system "
                f"and were read as Windows reads them, backslashes as separators, case "
                f"ignored: {named}"
            )
        out.extend(notes)


def _as_windows_reads(folder: Path, name: str) -> Path | None:
    windows = PureWindowsPath(name)
    if windows.drive:  # C:\… names a disk this machine does not have
        return None
    here, parts = (Path("/"), windows.parts[1:]) if windows.root else (folder, windows.parts)
    for part in parts:
        if part in (".", ".."):
            here = here / part
            continue
        exact = here / part
        if _exists(exact):
            here = exact
            continue
        try:
            with os.scandir(here) as entries:
                matches = [e.name for e in entries if e.name.lower() == part.lower()]
        except OSError:
            return None
        if len(matches) != 1:
            return None
        here = here / matches[0]
    return here if is_file(here) else None


def is_file(path: Path) -> bool:
    try:
        return path.is_file()
    except (OSError, ValueError):  # a name the file system cannot hold
        return False


def _exists(path: Path) -> bool:
    try:
        return path.exists()
    except (OSError, ValueError):
        return False
