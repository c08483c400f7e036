"""BeamDyn blades (``CompElast`` = 2): the blade's sectional 6×6 stiffness and mass
matrices as wtvib's blade table.

BeamDyn's primary file gives the blade's key points (``kp_xr, kp_yr, kp_zr``, initial
twist) and names the blade file (``BldFile``); the blade file gives ``station_total``
stations, each a position η along the blade (0 root, 1 tip), a 6×6 stiffness matrix and a
6×6 mass matrix in the order (shear x, shear y, extension, bending about x, bending about
y, torsion), in the section's frame turned by the initial twist. BeamDyn's convention (the
NREL 5-MW's files: K44 = ElastoDyn's EdgStff, K55 = its FlpStff): bending about x is
edgewise, about y flapwise. The bending and torsional stiffnesses are condensed from the
matrix (other strains free: about the section's own tension and shear centres, as the
windIO reader does); mass per length M11, torsional inertia M66; the mass centre's offset
from the reference axis from M16 and M26 (M16 = −m·y_cm, M26 = m·x_cm), the tension
centre's from K34/K33 and K35/K33 and the shear centre's from the shear–torsion terms,
reported. Damping ``damp_type`` 1 is stiffness-proportional (μ per strain): a mode of
frequency f has ζ = π·μ·f, taken for the first flapwise and edgewise modes.

Prebend and sweep (key points off the z axis) are neglected: the blade is straight along
its span (said where present).

OpenFAST BeamDyn user guide, "Input Files" (primary and blade input files).
"""

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import SpecError
from ..spec import read_text
from .deck import _NUMBER, Deck, _file, parse

#: The most stations a BeamDyn blade file may declare.
MAX_STATIONS = 2000


@dataclass
class Blade:
    """A BeamDyn blade as wtvib's ``blade.structure`` (without hub radius), its mass and
    length, the damping its μ give, notes."""

    structure: dict[str, Any]
    mass_kg: float
    length_m: float
    span: np.ndarray
    mass: np.ndarray
    mu: tuple[float, float] | None  # flapwise, edgewise stiffness-proportional damping [s]
    path: Path
    notes: list[str] = field(default_factory=list)


def blade(fst: Deck) -> Blade:
    """Blade 1's BeamDyn model (``BDBldFile(1)`` of the .fst)."""
    main = parse(_file(fst, "BDBldFile(1)", "BDBldFile1"))
    span, twist, offset = _key_points(main)
    bld = parse(_file(main, "BldFile"))
    eta, k, m = _stations(bld)
    length = float(span[-1] - span[0])
    s = eta * length
    flap, edge, gj, turned = _condensed(k)
    mass = m[:, 0, 0]
    polar = m[:, 5, 5]
    structure: dict[str, Any] = {
        "span_m": _list(s),
        "mass_per_length_kg_m": _list(mass),
        "ei_flap_nm2": _list(flap),
        "ei_edge_nm2": _list(edge),
        # the principal axes: the key points' twist less the matrices' own turn (windio.
        # _condensed; θ from BeamDyn's axis 1 towards axis 2, HAWC2's structural pitch)
        "twist_deg": _list(np.interp(s, span - span[0], twist) - turned),
    }
    if np.all(gj > 0) and np.all(polar > 0):
        structure["gj_nm2"] = _list(gj)
        structure["torsional_inertia_kgm"] = _list(polar)
    shear = _shear(k)
    if shear is not None:  # BeamDyn's beam is a Timoshenko beam: flapwise K55 with K11
        structure["ga_flap_n"], structure["ga_edge_n"] = _list(shear[1]), _list(shear[0])
    notes = [
        f"Blade from BeamDyn ({main.path.name}, {bld.path.name}): {len(eta)} stations of 6×6 "
        "stiffness and mass matrices; flapwise K55 and edgewise K44 (BeamDyn's axes) and "
        "torsion K66 condensed about the section's own centres, with their shear K11 and K22 "
        "(a Timoshenko beam), mass M11, torsional inertia M66; structural twist from the key "
        "points' initial twist."
    ]
    centres = _centres(k, m)
    if centres:
        notes.append(centres)
    if offset > 0.01 * length:
        notes.append(
            f"BeamDyn's key points leave the pitch axis by up to {offset:.3g} m (prebend, "
            "sweep): the blade is modelled straight along its span."
        )
    mu = _damping(bld)
    return Blade(structure, float(np.trapezoid(mass, s)), length, s, mass, mu, bld.path, notes)


def _key_points(main: Deck) -> tuple[np.ndarray, np.ndarray, float]:
    """Span positions (kp_zr), initial twist [deg] and the largest offset off the z axis."""
    lines = read_text(main.path, ansi=True).splitlines()
    head = next((i for i, line in enumerate(lines) if "kp_zr" in line.split()), None)
    if head is None:
        raise SpecError("BeamDyn file of an unknown layout: no kp_zr table", source=str(main.path))
    header = lines[head].split()
    missing = [name for name in ("kp_xr", "kp_yr") if name not in header]
    if missing:
        raise SpecError(
            f"the key points' table names no {' or '.join(missing)} column (its header: "
            "kp_xr kp_yr kp_zr initial_twist)",
            line=head + 1,
            source=str(main.path),
        )
    rows = []
    j = head + 1
    while j < len(lines) and lines[j].strip().startswith("("):
        j += 1
    while j < len(lines):
        cells = lines[j].split()
        if len(cells) < len(header) or not all(_NUMBER.match(c) for c in cells[: len(header)]):
            break
        rows.append([float(c.replace("D", "E")) for c in cells[: len(header)]])
        j += 1
    table = np.array(rows)
    if len(table) < 3:
        raise SpecError(
            "BeamDyn needs at least three key points (kp_xr, kp_yr, kp_zr, initial_twist)",
            line=head + 1,
            source=str(main.path),
        )
    z = table[:, header.index("kp_zr")]
    if np.any(np.diff(z) <= 0):
        raise SpecError(
            "the key points' kp_zr must increase from root to tip", line=head + 1,
            source=str(main.path),
        )  # fmt: skip
    twist = table[:, header.index("initial_twist")] if "initial_twist" in header else 0 * z
    off = np.hypot(table[:, header.index("kp_xr")], table[:, header.index("kp_yr")])
    return z, twist, float(np.max(np.abs(off - off[0])))


def _stations(bld: Deck) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """η, K and M of every station of a BeamDyn blade file."""
    count = bld.whole("station_total", low=2, high=MAX_STATIONS)
    lines = read_text(bld.path, ansi=True).splitlines()
    start = next(
        (i for i, line in enumerate(lines) if "DISTRIBUTED PROPERTIES" in line.upper()), None
    )
    if start is None:
        raise SpecError(
            "BeamDyn blade file of an unknown layout: no DISTRIBUTED PROPERTIES section",
            source=str(bld.path),
        )
    numbers: list[float] = []
    where: list[int] = []
    for number, line in enumerate(lines[start + 1 :], start=start + 2):
        for cell in line.split():
            if not _NUMBER.match(cell):
                raise SpecError(
                    f"{cell!r} is not a number (a BeamDyn station is η, then 36 stiffness "
                    "and 36 mass entries)",
                    line=number,
                    source=str(bld.path),
                )
            numbers.append(float(cell.replace("D", "E").replace("d", "e")))
            where.append(number)
    need = count * 73
    if len(numbers) < need:
        raise SpecError(
            f"station_total = {count}, but the file holds {len(numbers) // 73} whole "
            "stations (η, 6×6 stiffness, 6×6 mass): cut short?",
            line=where[-1] if where else start + 1,
            source=str(bld.path),
        )
    data = np.asarray(numbers[:need]).reshape(count, 73)
    eta = data[:, 0]
    if abs(eta[0]) > 1e-6 or abs(eta[-1] - 1) > 1e-6 or np.any(np.diff(eta) <= 0):
        raise SpecError(
            f"the stations' η must increase from 0 to 1 (they run {eta[0]:g} … {eta[-1]:g})",
            line=where[0],
            source=str(bld.path),
        )
    k = data[:, 1:37].reshape(count, 6, 6)
    m = data[:, 37:73].reshape(count, 6, 6)
    bad = ~(np.isfinite(data).all(axis=1) & (k[:, 3, 3] > 0) & (k[:, 4, 4] > 0) & (m[:, 0, 0] > 0))
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise SpecError(
            f"station {i + 1} (η = {eta[i]:g}): the bending stiffnesses K44, K55 and the mass "
            "M11 must be positive and finite",
            line=where[i * 73],
            source=str(bld.path),
        )
    return eta, 0.5 * (k + k.transpose(0, 2, 1)), m


def _shear(k: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    """The transverse shear stiffnesses (K22's, K11's), other strains free."""
    from .windio import _shear as shear

    return shear(k)


def _condensed(k: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Flapwise (about y), edgewise (about x) and torsional stiffness, other strains free,
    about the principal axes, and their turn from the section's axes [deg]."""
    from .windio import _condensed as condensed  # one condensation for 6×6 sections

    k44, k55, k66, turned = condensed(k)
    return k55, k44, k66, turned


def _centres(k: np.ndarray, m: np.ndarray) -> str:
    """The largest offsets of the mass and tension centres from the reference axis."""
    mass = m[:, 0, 0]
    x_cm, y_cm = m[:, 1, 5] / mass, -m[:, 0, 5] / mass
    ea = k[:, 2, 2]
    with np.errstate(divide="ignore", invalid="ignore"):
        x_tc = np.where(ea > 0, -k[:, 2, 4] / ea, 0.0)
        y_tc = np.where(ea > 0, k[:, 2, 3] / ea, 0.0)
    cm, tc = float(np.max(np.hypot(x_cm, y_cm))), float(np.max(np.hypot(x_tc, y_tc)))
    if cm < 1e-6 and tc < 1e-6:
        return "The sections' mass and tension centres lie on the reference axis."
    return (
        f"Mass centres up to {cm:.3g} m and tension centres up to {tc:.3g} m off the "
        "reference axis (M16, M26; K34, K35): the bending stiffnesses are about the "
        "section's own centres, the offsets' coupling of bending and torsion is not modelled."
    )


def _damping(bld: Deck) -> tuple[float, float] | None:
    """Flapwise and edgewise μ of stiffness-proportional damping (damp_type 1)."""
    if bld.num("damp_type", default=0) != 1:
        return None
    lines = read_text(bld.path, ansi=True).splitlines()
    head = next((i for i, line in enumerate(lines) if line.split()[:1] == ["mu1"]), None)
    if head is None:
        return None
    j = head + 1
    while j < len(lines) and lines[j].strip().startswith("("):
        j += 1
    cells = lines[j].split() if j < len(lines) else []
    if len(cells) < 6 or not all(_NUMBER.match(c) for c in cells[:6]):
        raise SpecError("the damping coefficients mu1 … mu6 must be six numbers", line=j + 1,
                        source=str(bld.path))  # fmt: skip
    mu = [float(c.replace("D", "E")) for c in cells[:6]]
    if any(v < 0 or not math.isfinite(v) for v in mu):
        raise SpecError("the damping coefficients mu1 … mu6 must be ≥ 0", line=j + 1,
                        source=str(bld.path))  # fmt: skip
    return mu[4], mu[3]


def _list(a: np.ndarray) -> list[float]:
    return [float(f"{v:.10g}") for v in a]
