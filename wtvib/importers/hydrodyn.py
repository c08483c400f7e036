"""A floating deck set's platform: ElastoDyn's platform mass, HydroDyn's potential-flow
added mass and hydrostatics, the moorings' stiffness, as wtvib's ``platform`` foundation.

* ElastoDyn: ``PtfmMass``, its CM (``PtfmCMzt``), its inertias about the CM (``PtfmRIner``,
  ``PtfmPIner``, ``PtfmYIner``), the platform reference (``PtfmRefzt``) and the tower base
  (``TowerBsHt``), all heights above MSL.
* HydroDyn, potential flow (``PotMod`` = 1): the WAMIT files ``PotFile``.1 (added mass; the
  rows of period 0 are the infinite-frequency A∞) and ``PotFile``.hst (hydrostatic
  restoring), dimensionalised with ``WAMITULEN`` = L, the water density ρ and g:
  A = Ā·ρ·L^k with k = 3, 4, 5 and C = C̄·ρ·g·L^k with k = 2, 3, 4 for translation–
  translation, mixed and rotation–rotation terms (the WAMIT user manual's
  nondimensionalisation, as HydroDyn undoes it); plus ``AddCLin`` (additional stiffness).
  A platform of strip-theory members only (``PotMod`` = 0) is not modelled (said).
* Moorings: MAP++ (``CompMooring`` = 1) or MoorDyn (3), their stiffness at the undisplaced
  position from MoorPy (:mod:`wtvib.importers.mooring`).

OpenFAST ElastoDyn, HydroDyn and MAP++/MoorDyn input-file documentation; WAMIT User
Manual v7, §4 (output file formats and their nondimensionalisation).
"""

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import SpecError
from ..numerics import hull
from ..spec import read_text
from ..units import STANDARD_GRAVITY
from .deck import (
    _NUMBER,
    WATER_DENSITY,
    Deck,
    _file,
    _fortran,
    beside,
    environment,
    parse,
    present,
    sea_setting,
    sea_state,
)

#: The largest WAMIT length scale ``WAMITULEN`` [m] taken (OpenFAST's platforms use 1 m).
MAX_LENGTH_SCALE = 1000.0


def platform(main: Deck, fst: Deck) -> tuple[dict[str, Any], list[str]] | str:
    """The ``platform`` block of the deck set's floating platform and what the report
    says about it, or why it cannot be modelled (a sentence for the refusal)."""
    if fst.num("CompHydro", default=0) == 0 or "HydroFile" not in fst.values:
        return "no HydroDyn: nothing gives the platform's hydrostatics"
    hd = parse(_file(fst, "HydroFile"))
    env = environment(fst)
    hd.inherited.update(env)
    if hd.num("PotMod", default=0) != 1:
        return (
            "its HydroDyn has no potential-flow model (PotMod ≠ 1): a platform of strip-theory "
            "members only is not modelled"
        )
    rho = sea_setting(hd, sea_state(fst), "WtrDens", WATER_DENSITY)
    g = env.get("Gravity", (STANDARD_GRAVITY, ""))[0]
    length = hd.num("WAMITULEN", default=1.0)
    if not 0 < length <= MAX_LENGTH_SCALE:  # WAMIT's results scale with L⁵: bound it
        raise SpecError(
            f"WAMITULEN {length:g} m is not a body's length scale (0 to {MAX_LENGTH_SCALE:g} m)",
            line=hd.values.get("WAMITULEN", ("", None))[1],
            source=str(hd.path),
        )
    root = hd.text("PotFile")
    named = Naming("PotFile", hd.values.get("PotFile", ("", None))[1], hd.path)
    added, by_frequency = wamit_added_mass(beside(hd.path, root + ".1"), rho, length, named)
    hydrostatic = wamit_hydrostatic(beside(hd.path, root + ".hst"), rho, g, length, named)
    extra = _matrix(hd, "AddCLin")
    from .mooring import stiffness as mooring_stiffness

    moorings, mooring_note = mooring_stiffness(fst, rho, g)
    refz = main.num("PtfmRefzt", default=0.0)
    body = _Body(
        _not_negative(main, "PtfmMass"),
        main.num("PtfmCMzt") - refz,
        _not_negative(main, "PtfmRIner"),
        _not_negative(main, "PtfmPIner"),
        _not_negative(main, "PtfmYIner"),
    )
    members = _members(hd, rho, refz)
    ballast = members.fill
    total = body.plus(ballast) if ballast is not None else body
    by_frequency, dropped = _positive_inertia(by_frequency, total)
    block = {
        "tower_base_m": main.num("TowerBsHt", default=0.0) - refz,
        "mass_kg": total.mass,
        "cm_m": total.cm,
        "inertia_roll_kgm2": total.roll,
        "inertia_pitch_kgm2": total.pitch,
        "inertia_yaw_kgm2": total.yaw,
        "added_mass": matrix_rows(added),
        "added_mass_by_frequency": by_frequency,
        "stiffness": matrix_rows(hydrostatic + extra + moorings),
        "source": f"ElastoDyn {main.path.name}, HydroDyn {hd.path.name} (WAMIT {root}.1, "
        f".hst), {mooring_note}",
    }
    ballasted = (
        f", with the water in HydroDyn's filled members ({ballast.mass:,.0f} kg at "
        f"{ballast.cm:.3g} m, moving with the platform as a rigid mass)"
        if ballast is not None
        else ""
    )
    notes = [
        f"Floating platform from the deck set: ElastoDyn's mass {body.mass:,.0f} kg (CM "
        f"{body.cm:g} m from the PRP){ballasted}, HydroDyn's added mass (WAMIT {root}.1: "
        f"each mode takes it at its own frequency, from {len(by_frequency)} periods; A∞ "
        f"where the file has no others) and hydrostatics ({root}.hst; ρ {rho:g} kg/m³, L "
        f"{length:g} m), "
        f"AddCLin, and {mooring_note}; the platform is a rigid body with six DOFs under the "
        "tower (wtvib.subsystems.platform), its radiation damping, viscous drag and second-order "
        "loads "
        "left out." + members.left_out + dropped
    ]
    return block, notes


def _positive_inertia(points: list[dict[str, Any]], body: "_Body") -> tuple[list[Any], str]:
    """The added-mass table without the periods where a diagonal term is negative beyond the
    body's own inertia (a moonpool's sloshing near its resonance: the ITI barge's WAMIT
    table near 0.55 Hz) — no rigid body has a negative inertia; the table is interpolated
    across them — and what the note says of it."""
    z2 = body.mass * body.cm**2
    own = [body.mass] * 3 + [body.roll + z2, body.pitch + z2, body.yaw]
    kept = [q for q in points if all(q["matrix"][i][i] + own[i] > 0 for i in range(6))]
    gone = [q["frequency_hz"] for q in points if q not in kept]
    if not gone:
        return points, ""
    return kept, (
        f" WAMIT's added mass at {len(gone)} periods ({min(gone):.3g}–{max(gone):.3g} Hz) is "
        "negative beyond the platform's own inertia (a moonpool's or gap's resonance): "
        "those periods are left out of the table, which is interpolated across them."
    )


class _Body:
    """A rigid body on the platform's axis: mass, CM height, inertias about its CM."""

    def __init__(self, mass: float, cm: float, roll: float, pitch: float, yaw: float) -> None:
        self.mass, self.cm, self.roll, self.pitch, self.yaw = mass, cm, roll, pitch, yaw

    def plus(self, other: "_Body") -> "_Body":
        m = self.mass + other.mass
        cm = (self.mass * self.cm + other.mass * other.cm) / m
        shift = self.mass * (self.cm - cm) ** 2 + other.mass * (other.cm - cm) ** 2
        return _Body(
            m, cm, self.roll + other.roll + shift, self.pitch + other.pitch + shift,
            self.yaw + other.yaw,
        )  # fmt: skip


class _Members:
    """What HydroDyn's members add that its potential-flow files do not hold."""

    def __init__(self, fill: _Body | None, left_out: str) -> None:
        self.fill, self.left_out = fill, left_out


#: Pieces each filled member is cut into for its water's mass and inertia.
PIECES = 200


def _members(hd: Deck, rho: float, refz: float) -> _Members:
    """The water in HydroDyn's filled members (ballast: a rigid mass moving with the
    platform, its inertia from thin slices of each member's inner tube about the PRP) and
    a sentence on the strip-theory members (``PropPot`` false) whose added mass and buoyancy
    wtvib leaves out."""
    from .deck import counted
    from .subdyn import _fills

    text = read_text(hd.path, ansi=True)
    joints = counted(hd, text, ("NJoints",), "Jointzi")
    members = counted(hd, text, ("NMembers",), "MJointID1")
    props = counted(hd, text, ("NPropSets", "NPropSetsCyl"), "PropD")
    if joints is None or members is None or props is None or not members.rows:
        return _Members(None, "")
    xyz = dict(zip(joints.ids("JointID"), zip(joints.numbers("Jointxi"),
               joints.numbers("Jointyi"), joints.numbers("Jointzi"), strict=True),
               strict=True))  # fmt: skip
    prop = dict(zip(props.ids("PropSetID"), zip(props.numbers("PropD"),
                props.numbers("PropThck"), strict=True), strict=True))  # fmt: skip
    fills = _fills(hd, text, rho)
    pot = members.texts("PropPot") if members.has("PropPot") else ["true"] * len(members.rows)
    m6 = np.zeros((6, 6))
    strip, strip_volume = 0, 0.0
    for i, mid in enumerate(members.ids("MemberID")):
        a, b = members.ids("MJointID1")[i], members.ids("MJointID2")[i]
        pa, pb = members.ids("MPropSetID1")[i], members.ids("MPropSetID2")[i]
        if a not in xyz or b not in xyz or pa not in prop or pb not in prop:
            raise SpecError(f"member {mid} names a joint or property set HydroDyn does not "
                            "have", line=members.lines[i], source=str(hd.path))  # fmt: skip
        ra, rb = np.array(xyz[a]), np.array(xyz[b])
        s = (np.arange(PIECES) + 0.5) / PIECES
        r = ra + s[:, None] * (rb - ra)
        d = prop[pa][0] + s * (prop[pb][0] - prop[pa][0])
        t = prop[pa][1] + s * (prop[pb][1] - prop[pa][1])
        ds = float(np.linalg.norm(rb - ra)) / PIECES
        if not pot[i].lstrip(".").lower().startswith("t"):
            strip += 1
            strip_volume += float(np.sum(np.pi / 4 * d**2 * ds * (r[:, 2] < 0)))
        if mid not in fills:
            continue
        surface, density = fills[mid]
        wet = r[:, 2] <= surface
        dm = density * np.pi / 4 * np.clip(d - 2 * t, 0, None) ** 2 * ds * wet
        rel = r - np.array([0.0, 0.0, refz])
        m6 += hull.at_points(dm[:, None, None] * np.eye(3), rel)
    left = (
        f" HydroDyn's {strip} strip-theory members (PropPot false: {strip_volume:,.0f} m³ "
        "below the water line) add added mass and buoyancy wtvib leaves out."
        if strip
        else ""
    )
    mass = m6[0, 0]
    if mass <= 0:
        return _Members(None, left)
    cm = m6[0, 4] / mass
    fill = _Body(mass, cm, m6[3, 3] - mass * cm**2, m6[4, 4] - mass * cm**2, m6[5, 5])
    return _Members(fill, left)


def _not_negative(deck: Deck, key: str) -> float:
    """A mass or inertia of the deck, refused where negative."""
    value = deck.num(key)
    if value < 0:
        raise SpecError(
            f"{key} = {value:g}: a mass or inertia cannot be negative",
            line=deck.values[key][1],
            source=str(deck.path),
        )
    return value


def _exponent(i: int, j: int, base: int) -> int:
    return base + (i >= 3) + (j >= 3)


@dataclass(frozen=True)
class Naming:
    """What names a WAMIT file: the key (HydroDyn's ``PotFile``, HAWC2's ``WAMIT_FILE``),
    its line and its file — where a missing file is reported."""

    key: str
    line: int | None
    source: Path


def _wamit_rows(path: Path, named: Naming, columns: int) -> list[tuple[list[float], int]]:
    if not present(path):
        raise SpecError(
            f"{named.key} names {path.name!r}, which does not exist",
            line=named.line,
            source=str(named.source),
        )
    rows = []
    for number, line in enumerate(read_text(path, ansi=True).splitlines(), start=1):
        cells = line.split()
        if not cells:
            continue
        try:
            values = [float(c.replace("D", "E")) for c in cells[:columns]]
        except ValueError:
            raise SpecError(f"not a WAMIT row of numbers: {line[:60]!r}", line=number,
                            source=str(path)) from None  # fmt: skip
        if len(values) < columns or not all(math.isfinite(v) for v in values):
            raise SpecError("a WAMIT row cut short or not finite", line=number,
                            source=str(path))  # fmt: skip
        rows.append((values, number))
    return rows


def _index(value: float, number: int, path: Path) -> int:
    if value != int(value) or not 1 <= value <= 6:
        raise SpecError(f"DOF index {value:g} is not 1 … 6 (one body)", line=number,
                        source=str(path))  # fmt: skip
    return int(value) - 1


#: At most this many frequencies of a WAMIT .1 file are kept (evenly spread; the spec's
#: table holds up to 1000).
MAX_FREQUENCIES = 200


def wamit_added_mass(
    path: Path, rho: float, length: float, named: Naming
) -> tuple[np.ndarray, list[dict[str, Any]]]:
    """A∞ from a WAMIT .1 file (its rows of period 0) and A(f) at its other periods (period
    −1: the zero-frequency limit), dimensionalised and symmetrised."""
    by_period: dict[float, np.ndarray] = {}
    for (period, i, j, a, *_), number in _wamit_rows(path, named, 4):
        p, q = _index(i, number, path), _index(j, number, path)
        if period < 0 and period != -1:
            raise SpecError(f"period {period:g}: WAMIT periods are −1, 0 or positive",
                            line=number, source=str(path))  # fmt: skip
        out = by_period.setdefault(period, np.zeros((6, 6)))
        out[p, q] = a * rho * length ** _exponent(p, q, 3)
    if 0.0 not in by_period:
        raise SpecError("no rows of period 0 (the infinite-frequency added mass)", source=str(path))
    infinite = by_period.pop(0.0)
    table = sorted(
        (0.0 if period == -1 else 1.0 / period, 0.5 * (a + a.T)) for period, a in by_period.items()
    )
    if len(table) > MAX_FREQUENCIES:
        keep = np.unique(np.linspace(0, len(table) - 1, MAX_FREQUENCIES).round().astype(int))
        table = [table[k] for k in keep]
    points = [{"frequency_hz": float(f"{f:.10g}"), "matrix": matrix_rows(a)} for f, a in table]
    return 0.5 * (infinite + infinite.T), points


def wamit_hydrostatic(path: Path, rho: float, g: float, length: float, named: Naming) -> np.ndarray:
    """The hydrostatic restoring matrix of a WAMIT .hst file, dimensionalised, symmetrised."""
    out = np.zeros((6, 6))
    for (i, j, c), number in _wamit_rows(path, named, 3):
        p, q = _index(i, number, path), _index(j, number, path)
        out[p, q] = c * rho * g * length ** _exponent(p, q, 2)
    return 0.5 * (out + out.T)


def _matrix(hd: Deck, key: str) -> np.ndarray:
    """A 6×6 matrix input (``AddCLin``): its key on the first row, five rows after."""
    lines = read_text(hd.path, ansi=True).splitlines()
    start = next((n for n, line in enumerate(lines) if key in line.split()), None)
    if start is None:
        return np.zeros((6, 6))
    rows = []
    for n in range(start, start + 6):
        cells = lines[n].split()[:6] if n < len(lines) else []
        values = [float(_fortran(c)) for c in cells if _NUMBER.match(c)]
        if len(values) != 6 or not all(math.isfinite(v) for v in values):
            raise SpecError(f"{key} must be six rows of six numbers", line=n + 1,
                            source=str(hd.path))  # fmt: skip
        rows.append(values)
    return np.array(rows)


def matrix_rows(a: np.ndarray) -> list[list[float]]:
    """A matrix as the spec's rows, each number to ten significant digits."""
    return [[float(f"{v:.10g}") for v in row] for row in a]
