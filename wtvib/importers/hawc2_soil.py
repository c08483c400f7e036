"""HAWC2's distributed soil springs (the ``soil`` block's data file): the lateral springs
along an embedded pile as wtvib's soil layers.

The file, as HAWC2 reads it and the IEA-15 monopile model ships it
(``HAWC2/IEA-15-240-RWT-Monopile/soil/IEA_15MW_Soil.dat``, made by that model's
``scripts/make_soil_file.py``): a title line, then sets each opened by ``#N`` and a name
(``lateral``, ``axial``, ``rotation_z``), a line ``nrow ndefl``, a line of the ``ndefl``
deflections [m or rad], and ``nrow`` rows of the pile's global z [m, down] followed by the
force per metre of pile at each deflection [kN/m]. wtvib reads the ``lateral`` set: its
initial slope (force over deflection between the first two deflections) is E_py [N/m²]
at each z, from the first row's z as the mudline, linear between rows — one soil layer
(kind ``modulus``, its top value and gradient) per interval. The axial and torsional sets
are not used (wtvib's tower bends on its foundation; torsion on the soil is held).
"""

import itertools
from pathlib import Path
from typing import Any

from ..errors import SpecError
from ..spec import read_text
from .deck import finite

#: HAWC2's soil files give forces in kN.
KILO = 1e3


def looks_like(text: str) -> bool:
    """A HAWC2 soil file: a ``#N`` set line followed by a set name."""
    lines = [ln.strip() for ln in text.splitlines()[:4]]
    return (
        len(lines) >= 3
        and lines[1].startswith("#")
        and lines[2].split()[:1] in (["lateral"], ["axial"], ["rotation_z"])
    )


def profile(path: Path) -> dict[str, Any]:
    """The lateral set as a soil profile (``soil`` layers, as ``check --soil`` takes)."""
    lines = read_text(path, ansi=True).splitlines()
    i = 1
    while i < len(lines):
        if lines[i].strip().startswith("#") and i + 1 < len(lines):
            name = lines[i + 1].split()[:1]
            if name == ["lateral"]:
                return {"soil": _layers(path, lines, i + 2)}
        i += 1
    raise SpecError("a HAWC2 soil file without a 'lateral' set", source=str(path))


def _layers(path: Path, lines: list[str], at: int) -> list[dict[str, Any]]:
    if at + 1 >= len(lines):
        raise SpecError("the lateral set is cut short", line=at, source=str(path))
    counts = lines[at].split()
    if len(counts) < 2:
        raise SpecError("expected 'nrow ndefl'", line=at + 1, source=str(path))
    rows, defl = (finite(c, at + 1, path) for c in counts[:2])
    if not (rows == int(rows) and 2 <= rows <= 500 and defl == int(defl) and defl >= 2):
        raise SpecError(
            "nrow must be a whole number from 2 to 500 and ndefl at least 2",
            line=at + 1,
            source=str(path),
        )
    cells = lines[at + 1].split()
    x = [finite(c, at + 2, path) for c in cells[:2]]
    if len(x) < 2 or x[1] <= x[0]:
        raise SpecError("the deflections must increase", line=at + 2, source=str(path))
    z, e_py = [], []
    for k in range(int(rows)):
        n = at + 2 + k
        parts = lines[n].split() if n < len(lines) else []
        if len(parts) < 3:
            raise SpecError(
                f"nrow = {int(rows)}, but row {k + 1} is missing or short", line=n + 1,
                source=str(path),
            )  # fmt: skip
        z.append(finite(parts[0], n + 1, path))
        f0, f1 = (finite(p, n + 1, path) for p in parts[1:3])
        slope = (f1 - f0) / (x[1] - x[0]) * KILO
        if slope < 0:
            raise SpecError("a spring of negative stiffness", line=n + 1, source=str(path))
        e_py.append(slope)
    if any(b <= a for a, b in itertools.pairwise(z)):
        raise SpecError("the rows' z must increase downwards", line=at + 3, source=str(path))
    top = z[0]
    return [
        {
            "bottom_m": z[k + 1] - top,
            "kind": "modulus",
            "modulus_pa": e_py[k],
            "gradient_pa_m": max((e_py[k + 1] - e_py[k]) / (z[k + 1] - z[k]), 0.0),
        }
        for k in range(len(z) - 1)
    ]
