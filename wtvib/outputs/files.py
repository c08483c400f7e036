"""Writing output files without losing anything: atomic replace, no silent overwrite.

A file is written to a temporary name in the target folder and renamed over the target, so
an interrupted run never leaves a half-written file. An existing file is replaced only if
wtvib wrote it (a PNG whose ``Software`` text chunk names wtvib, a PDF whose creator is
wtvib, a JSON document with a ``wtvib-`` schema, the summary and Campbell CSVs) or the
caller passes ``force``.
"""

import contextlib
import csv
import io
import mmap
import os
import tempfile
from pathlib import Path
from typing import TYPE_CHECKING

from ..errors import OutputError
from . import png

if TYPE_CHECKING:
    from ..judge.campbell import Campbell

SOFTWARE_TAG = "wtvib"
#: First line of the batch summary CSV (recognised as a wtvib output).
CSV_HEADER = b"file,turbine,tower_class,verdict,worst_check,margin,message"
#: First line of the Campbell data CSV (``check --campbell-csv``).
CAMPBELL_HEADER = (
    b"mode,rpm,wind_m_s,pitch_deg,frequency_hz,damping_ratio,aerodynamic_damping_ratio,"
    b"aeroelastic_frequency_hz,damped_frequency_hz,method,quasi_steady_damping_ratio"
)


#: First characters by which a spreadsheet takes a cell for a formula (OWASP, "CSV
#: Injection"): = + - @, tab and carriage return.
_FORMULA_START = ("=", "+", "-", "@", "\t", "\r")


def spreadsheet_cell(text: str) -> str:
    """A text cell a spreadsheet shows as text: one that would start a formula is prefixed
    with a single quote, as OWASP advises (a number such as "-0.5" stays a number)."""
    if not text.startswith(_FORMULA_START):
        return text
    try:
        float(text)
    except ValueError:
        return "'" + text
    return text


#: First line of a CSV that says which wtvib made it from which input (audit.Report.identity).
IDENTITY = b"# produced by wtvib "


def is_ours(path: Path) -> bool:
    """True if ``path`` is a file wtvib wrote earlier (only regular files are opened: a FIFO
    would block the read)."""
    if not path.is_file():
        return False
    try:
        with path.open("rb") as fh:
            head = fh.read(65536)
            if head.startswith(b"%PDF"):  # the document info dictionary can be anywhere
                with mmap.mmap(fh.fileno(), 0, access=mmap.ACCESS_READ) as whole:
                    return whole.find(b"/Creator (wtvib") >= 0
    except (OSError, ValueError):
        return False
    if head.startswith(png.SIGNATURE):
        return _png_software(head).startswith(SOFTWARE_TAG)
    if head.startswith(CONVERTED):
        return _unedited(path)
    return head.startswith((b'{\n  "schema": "wtvib-', CSV_HEADER, CAMPBELL_HEADER, IDENTITY))


#: First bytes of a spec ``wtvib convert`` wrote; its first line ends with the digest of
#: the rest, so that a converted spec is replaced only while nobody has edited it.
CONVERTED = b"# wtvib spec converted from "


def converted_spec(source_name: str, body: str) -> bytes:
    """A converted spec's text: the header naming its source and the digest of ``body``."""
    import hashlib

    digest = hashlib.sha256(body.encode()).hexdigest()[:16]
    return CONVERTED + f"{source_name} (unedited while sha256 {digest})\n".encode() + body.encode()


def _unedited(path: Path) -> bool:
    import hashlib
    import re

    try:
        first, _, body = path.read_bytes().partition(b"\n")
    except OSError:
        return False
    match = re.search(rb"\(unedited while sha256 ([0-9a-f]{16})\)$", first)
    return match is not None and hashlib.sha256(body).hexdigest()[:16] == match.group(1).decode()


def _png_software(data: bytes) -> str:
    for kind, body in png.chunks(data):
        if kind == b"tEXt" and body.startswith(b"Software\x00"):
            return body.split(b"\x00", 1)[1].decode("latin-1")
        if kind == b"IDAT":
            break
    return ""


def _umask() -> int:
    """The process's umask (read by setting it and putting it back: there is no getter)."""
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def unwritable(folder: Path, exc: OSError) -> str:
    """Why a folder cannot take an output: a file where the folder should be (``--out``
    naming a file) is said as such, not as the system's "File exists"."""

    def there(p: Path) -> bool:
        try:
            return p.exists()
        except OSError:  # a name the file system cannot hold
            return False

    blocker = next((p for p in (folder, *folder.parents) if there(p)), None)
    if blocker is not None and blocker != folder and not blocker.is_dir():
        return f"cannot write to {folder}: {blocker} is a file, not a folder"
    if blocker == folder and not folder.is_dir():
        return f"cannot write to {folder}: {blocker} is a file, not a folder"
    return f"cannot write to {folder}: {exc.strerror}"


def folder_exists(path: Path) -> None:
    """An output file's folder must exist (OutputError otherwise): checked before the work
    whose result it takes, and again when it is written."""
    folder = Path(path).parent
    if folder.is_dir():
        return
    blocker = next((p for p in (folder, *folder.parents) if p.exists()), None)
    if blocker is not None and not blocker.is_dir():
        raise OutputError(f"cannot write to {folder}: {blocker} is a file, not a folder")
    raise OutputError(
        f"cannot write {path}: the folder {folder} does not exist (an output file's folder "
        "is not made; --out-dir folders are)"
    )


def write_atomic(path: Path, data: bytes, *, force: bool = False, folder: bool = False) -> Path:
    """Write ``data`` to ``path`` atomically. ``folder``: the path's folder is an output
    folder the user named (``--out-dir``), made if missing; an output file's folder must
    exist, as in other tools (``report -o /nonexistent/x.pdf`` made ``/nonexistent``).

    Raises
    ------
    OutputError
        The folder cannot be written, or ``path`` exists, was not written by wtvib and
        ``force`` is false.
    """
    path = Path(path)
    try:
        exists = path.exists()
    except OSError as exc:  # a name the file system cannot hold (over 255 bytes)
        raise OutputError(f"cannot write {str(path)[:300]}: {exc.strerror}") from None
    except UnicodeError:  # a name no file system encoding holds (a lone surrogate)
        raise OutputError(f"cannot write {path!a}: the name is not valid text") from None
    if exists and not path.is_file():  # a device, pipe or folder: never replaced
        raise OutputError(f"{path} is not a regular file; give a file name to write")
    from ..spec.load import was_read

    if exists and was_read(path):  # --force or not: an input is never an output's place
        raise OutputError(f"{path} is an input of this run: no output is written over it")
    if exists and not force and not is_ours(path):
        how = "was not written by wtvib"
        with contextlib.suppress(OSError), path.open("rb") as fh:
            if fh.read(len(CONVERTED)) == CONVERTED:
                how = "was written by wtvib convert and edited since"
        raise OutputError(f"{path} exists and {how}; use --force to replace it")
    if not folder:
        folder_exists(path)
    try:
        if folder:
            path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    except OSError as exc:
        raise OutputError(unwritable(path.parent, exc)[:500]) from None
    except UnicodeError:
        raise OutputError(f"cannot write {path!a}: the name is not valid text") from None
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
            fh.flush()
            # mkstemp makes the file 0600; an output gets the mode the umask gives any file
            os.fchmod(fh.fileno(), 0o666 & ~_umask())
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except OSError as exc:
        Path(tmp).unlink(missing_ok=True)
        raise OutputError(f"cannot write {path}: {exc.strerror}") from None
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def campbell_to_csv(campbell: "Campbell", identity: str | None = None) -> str:
    """The Campbell data as CSV: one row per mode and sample — mode, rpm, wind_m_s,
    pitch_deg, frequency_hz, damping_ratio, aerodynamic_damping_ratio, the aeroelastic
    root's natural and damped frequency, how the point was obtained and the quasi-steady
    damping (wind, pitch and the aerodynamic columns empty where there is none);
    ``identity``: a comment line first (which wtvib, which input)."""
    buf = io.StringIO()
    if identity:
        buf.write(f"# {identity}\n")
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(CAMPBELL_HEADER.decode().split(","))
    for mid, (f, z) in campbell.modes.items():
        natural, damped, method = campbell.roots.get(mid, (None, None, ()))
        for i, n in enumerate(campbell.rpm):
            wind = f"{campbell.wind[i]:.4f}" if campbell.wind else ""
            pitch = f"{campbell.pitch_deg[i]:.4f}" if campbell.pitch_deg else ""
            aero = f"{campbell.aero[mid][i]:.6f}" if mid in campbell.aero else ""
            root = (
                [f"{natural[i]:.6f}", f"{damped[i]:.6f}"]
                if natural is not None and damped is not None
                else ["", ""]
            )
            how = method[i] if method else ""
            steady = f"{campbell.quasi_steady[mid][i]:.6f}" if mid in campbell.quasi_steady else ""
            row = [
                spreadsheet_cell(mid),
                f"{n:.4f}",
                wind,
                pitch,
                f"{f[i]:.6f}",
                f"{z[i]:.6f}",
                aero,
            ]
            w.writerow([*row, *root, how, steady])
    return buf.getvalue()
