"""Tabulated Campbell curves: a CSV of rotor speed against frequency (and damping) per mode —
what a test campaign or any other tool produces (issue 22).

One row per mode and operating point, with a header::

    mode,rpm,frequency_hz,damping_ratio,whirl,frame,wind_m_s,description
    tower.fa1,6.9,0.3240,0.01,,fixed,,
    blade.flap1.backward,6.9,0.6075,0.45,backward,fixed,5.0,1st flap backward whirl

``mode``, ``rpm`` and ``frequency_hz`` are required; ``damping_ratio`` is a fraction of
critical (not %), ``whirl`` backward | forward | collective | cyclic | fixed, ``frame`` fixed
(a whole-turbine mode, the default) or rotating (a blade mode in the rotating frame).
"""

import csv
import io
import math
import re
from pathlib import Path
from typing import Any

from ..errors import SpecError
from .campbell_results import results_spec

REQUIRED = ("mode", "rpm", "frequency_hz")
OPTIONAL = ("damping_ratio", "whirl", "frame", "wind_m_s", "description")
_ID = re.compile(r"^[a-z][a-z0-9_]*(\.[a-z0-9_]+)*$")


def looks_like(text: str) -> bool:
    """A CSV whose header names the required columns."""
    first = next((ln for ln in text.splitlines() if ln.strip()), "")
    cols = {c.strip().lower() for c in first.split(",")}
    return all(c in cols for c in REQUIRED)


def to_spec_data(
    path: Path, text: str, blades: int | None, rpm: tuple[float, float] | None = None
) -> dict[str, Any]:
    """The wtvib-format dictionary of a Campbell table."""
    rows = list(csv.reader(io.StringIO(text)))
    header = [c.strip().lower() for c in rows[0]]
    unknown = [c for c in header if c not in REQUIRED + OPTIONAL]
    if unknown:
        raise SpecError(
            f"unknown column(s) {', '.join(unknown)}; expected {', '.join(REQUIRED + OPTIONAL)}",
            line=1,
            source=str(path),
        )
    col = {name: header.index(name) for name in header}
    modes: dict[str, dict[str, Any]] = {}
    for line, row in enumerate(rows[1:], start=2):
        if not any(c.strip() for c in row):
            continue
        if len(row) != len(header):
            raise SpecError(
                f"{len(row)} cells, the header has {len(header)}", line=line, source=str(path)
            )
        cell = {name: row[i].strip() for name, i in col.items()}
        name = cell["mode"]
        if not _ID.match(name):
            raise SpecError(
                f"column mode: {name!r} is not a mode id (lower-case words joined by dots, "
                "e.g. tower.fa1, blade.flap1.backward)",
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
        m["rpm"].append(_number(cell["rpm"], line, "rpm", path))
        hz = _number(cell["frequency_hz"], line, "frequency_hz", path)
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
    if not modes:
        raise SpecError("no data rows under the header", source=str(path))
    for name, m in modes.items():
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
    return results_spec(
        path,
        f"the Campbell table {path.name}",
        modes,
        blades,
        [str(path)],
        f"Campbell table {path.name}",
        rpm=rpm,
    )


def _number(text: str, line: int, column: str, path: Path) -> float:
    try:
        value = float(text)
    except ValueError:
        raise SpecError(
            f"column {column}: {text!r} is not a number", line=line, source=str(path)
        ) from None
    if not math.isfinite(value):
        raise SpecError(
            f"column {column}: {text} is not a finite number", line=line, source=str(path)
        )
    return value
