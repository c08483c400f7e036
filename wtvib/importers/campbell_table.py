"""Tabulated Campbell curves: a CSV of rotor speed against frequency (and damping) per mode —
what a test campaign or any other tool produces.

One row per mode and operating point, with a header::

    mode,rpm,frequency_hz,damping_ratio,whirl,frame,wind_m_s,description
    tower.fa1,6.9,0.3240,0.01,,fixed,,
    blade.flap1.backward,6.9,0.6075,0.45,backward,fixed,5.0,1st flap backward whirl

``mode``, ``rpm`` and ``frequency_hz`` are required; ``damping_ratio`` is a fraction of
critical (not %), ``whirl`` backward | forward | collective | cyclic | fixed, ``frame`` fixed
(a whole-turbine mode, the default) or rotating (a blade mode in the rotating frame).
"""

import csv
import math
import re
from pathlib import Path
from typing import Any

from ..errors import SpecError
from .campbell_results import MAX_MODES, results_spec
from .deck import _NUMBER

REQUIRED = ("mode", "rpm", "frequency_hz")
OPTIONAL = ("damping_ratio", "whirl", "frame", "wind_m_s", "description")
#: Columns of wtvib's own Campbell CSV (``check --campbell-csv``) that a table may carry and
#: that are not read (the pitch, the damping's aerodynamic part, the aeroelastic root, the
#: quasi-steady damping): a file wtvib wrote reads back.
IGNORED = (
    "pitch_deg",
    "aerodynamic_damping_ratio",
    "aeroelastic_frequency_hz",
    "damped_frequency_hz",
    "method",
    "quasi_steady_damping_ratio",
)
_ID = re.compile(r"^[a-z][a-z0-9_]*(\.[a-z0-9_]+)*$")


def looks_like(text: str) -> bool:
    """A CSV whose header (the first line that is not blank or a ``#`` comment) names the
    required columns."""
    first = next(
        (ln for ln in text.splitlines() if ln.strip() and not ln.lstrip().startswith("#")), ""
    )
    cols = {c.strip().lower() for c in first.split(",")}
    return all(c in cols for c in REQUIRED)


def to_spec_data(
    path: Path, text: str, blades: int | None, rpm: tuple[float, float] | None = None
) -> dict[str, Any]:
    """The wtvib-format dictionary of a Campbell table."""
    numbered = _rows(path, text)
    first, rows = numbered[0], numbered[1:]
    col = _columns(first, path)
    modes: dict[str, dict[str, Any]] = {}
    for line, row in rows:
        if not any(c.strip() for c in row):
            continue
        if len(row) != len(col):
            raise SpecError(
                f"{len(row)} cells, the header has {len(col)}", line=line, source=str(path)
            )
        _add_point(modes, {name: row[i].strip() for name, i in col.items()}, line, path)
    if not modes:
        raise SpecError("no data rows under the header", source=str(path))
    for name, m in modes.items():
        _by_speed(name, m, path)
    return results_spec(
        path,
        f"the Campbell table {path.name}",
        modes,
        blades,
        [str(path)],
        f"Campbell table {path.name}",
        rpm=rpm,
    )


def _columns(first: tuple[int, list[str]], path: Path) -> dict[str, int]:
    """The header's columns by name: known ones only, each once."""
    header = [c.strip().lower() for c in first[1]]
    unknown = [c for c in header if c not in REQUIRED + OPTIONAL + IGNORED]
    if unknown:
        raise SpecError(
            f"unknown column(s) {', '.join(unknown)}; expected {', '.join(REQUIRED + OPTIONAL)}",
            line=first[0],
            source=str(path),
        )
    twice = sorted({c for c in header if header.count(c) > 1})
    if twice:
        raise SpecError(
            f"column(s) {', '.join(twice)} given twice: which is meant?",
            line=first[0],
            source=str(path),
        )
    return {name: header.index(name) for name in header}


def _add_point(
    modes: dict[str, dict[str, Any]], cell: dict[str, str], line: int, path: Path
) -> None:
    """One row's point onto its mode's curve (a new mode where the id is new)."""
    name = cell["mode"]
    if not _ID.match(name):
        raise SpecError(
            f"column mode: {name!r} is not a mode id (lower-case words joined by dots, "
            "e.g. tower.fa1, blade.flap1.backward)",
            line=line,
            source=str(path),
        )
    if name not in modes and len(modes) >= MAX_MODES:
        raise SpecError(
            f"more than {MAX_MODES} modes: a whole-turbine Campbell diagram has tens; "
            "wtvib reads at most that many",
            line=line,
            source=str(path),
        )
    m = modes.setdefault(
        name,
        {
            "description": cell.get("description") or name,
            "frame": cell.get("frame") or "fixed",
            "rpm": [],
            "frequency_hz": [],
            "damping_ratio": [],
            "whirl": [],
            "wind_m_s": [],
        },
    )
    rpm = _number(cell["rpm"], line, "rpm", path)
    hz = _number(cell["frequency_hz"], line, "frequency_hz", path)
    wind = cell.get("wind_m_s", "")
    point = (rpm, _number(wind, line, "wind_m_s", path) if wind else None)
    seen = m.setdefault("_points", {})
    if point in seen and seen[point][0] != hz:
        raise SpecError(
            f"mode {name} at {rpm:g} rpm{'' if point[1] is None else f', {point[1]:g} m/s'} "
            f"is given twice, {seen[point][0]:g} Hz (line {seen[point][1]}) and {hz:g} Hz: "
            "which is meant?",
            line=line,
            source=str(path),
        )
    seen[point] = (hz, line)
    m["rpm"].append(rpm)
    if hz <= 0:
        raise SpecError(
            f"column frequency_hz: {hz:g} Hz — a natural frequency is positive",
            line=line,
            source=str(path),
        )
    m["frequency_hz"].append(hz)
    for opt in ("damping_ratio", "wind_m_s"):
        value = cell.get(opt, "")
        m[opt].append(_number(value, line, opt, path) if value else None)
    m["whirl"].append(cell.get("whirl") or None)


def _by_speed(name: str, m: dict[str, Any], path: Path) -> None:
    """A mode's points in order of speed; an optional column given at every point of the
    mode or at none (dropped)."""
    m.pop("_points", None)
    order = sorted(range(len(m["rpm"])), key=lambda i: m["rpm"][i])
    for key in ("rpm", "frequency_hz", "damping_ratio", "whirl", "wind_m_s"):
        m[key] = [m[key][i] for i in order]
    for key in ("damping_ratio", "whirl", "wind_m_s"):
        given = [v is not None for v in m[key]]
        if not any(given):
            del m[key]
        elif not all(given):
            raise SpecError(
                f"column {key}: mode {name} has it at some speeds only; give it at every "
                "point of the mode or at none",
                source=str(path),
            )


#: The longest cell (Python's csv limit).
MAX_CELL = 131_072


def _rows(path: Path, text: str) -> list[tuple[int, list[str]]]:
    """The table's non-blank rows with their lines, any line ending (CR, LF, CR LF). A
    quoted cell may hold a line break (RFC 4180) where its row still has the header's
    cells and the file goes on after it; otherwise a quote left open would swallow the rows
    after it, and is refused."""
    lines = text.splitlines()
    reader = csv.reader(lines)
    out: list[tuple[int, list[str]]] = []
    width: int | None = None
    before = 0
    while True:
        try:
            row = next(reader)
        except StopIteration:
            break
        except csv.Error as exc:
            raise SpecError(
                f"not a CSV row ({exc}; a cell over {MAX_CELL:,} characters, or a stray quote?)",
                line=reader.line_num,
                source=str(path),
            ) from None
        start = before + 1
        comment = bool(row) and row[0].lstrip().startswith("#")
        if reader.line_num > start and (
            comment or width is None or len(row) != width or reader.line_num >= len(lines)
        ):
            raise SpecError(
                f"a quoted cell runs from line {start} to {reader.line_num}: a quote left open?",
                line=start,
                source=str(path),
            )
        before = reader.line_num
        if any(c.strip() for c in row) and not comment:
            width = len(row) if width is None else width
            out.append((start, row))
    if not out:
        raise SpecError("the file is empty", source=str(path))
    return out


def _number(text: str, line: int, column: str, path: Path) -> float:
    if not _NUMBER.match(text.strip()) and text.strip().lower() not in ("inf", "-inf", "nan"):
        raise SpecError(f"column {column}: {text!r} is not a number", line=line, source=str(path))
    value = float(text.strip().replace("D", "E").replace("d", "e"))
    if not math.isfinite(value):
        raise SpecError(
            f"column {column}: {text} is not a finite number", line=line, source=str(path)
        )
    return value
