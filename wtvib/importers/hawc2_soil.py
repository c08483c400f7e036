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
import math
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import SpecError
from ..spec import read_text
from . import htc
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


def pile_on_soil(
    element: htc.Block, st: np.ndarray, length: float, root: Path
) -> tuple[dict[str, Any], str]:
    """A HAWC2 model's embedded pile on its own soil: the ``soil_element`` block's body
    (its classical st set ``st``, ``length`` [m] from its tip to the mudline) as wtvib's
    pile — a steel tube whose diameter and wall give the st's I and A at the mudline
    (D² = 8I/A + 2A/π, d² = 8I/A − 2A/π), E from the st — standing on the ``datafile``'s
    lateral springs (:func:`profile`); the foundation block and the statement of it. A pile
    whose I and A no tube has is one line naming the element."""
    body = element.need("mbdy_name").text(0)
    data = element.need("datafile")
    path = htc.resolve(data.text(0), root, data.file.parent, data)
    row = st[int(np.argmax(st[:, 0]))]  # the st row nearest the mudline (the body's end)
    e, i_x, area = float(row[8]), float(row[10]), float(row[15])
    outer2, inner2 = 8 * i_x / area + 2 * area / math.pi, 8 * i_x / area - 2 * area / math.pi
    if not (e > 0 and i_x > 0 and area > 0 and inner2 > 0):
        raise SpecError(
            f"soil_element: the body {body}'s st (I_x {i_x:g} m⁴, A {area:g} m²) is no steel "
            "tube wtvib can stand on the soil",
            line=element.line,
            source=str(element.file),
        )
    diameter = math.sqrt(outer2)
    wall = 0.5 * (diameter - math.sqrt(inner2))
    pile = {
        "embedded_length_m": length,
        "diameter_m": diameter,
        "wall_thickness_m": wall,
        "youngs_modulus_pa": e,
    }
    note = (
        f"The pile below the mudline ({body}, {length:.3g} m: a tube {diameter:.3g} m across "
        f"with a {1e3 * wall:.3g} mm wall, from its st's I and A) stands on the model's own "
        f"soil springs ({data.text(0)}: the lateral set's initial slopes as E_py), with lower- "
        "and upper-bound soil half and twice as stiff."
    )
    return {"kind": "soil", "pile": pile, **profile(path)}, note
