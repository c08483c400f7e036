"""OpenFAST ServoDyn's structural control (StC): the tuned mass dampers a deck set mounts
on its nacelle (``NumNStC``, ``NStCfiles``) and tower (``NumTStC``, ``TStCfiles``), as the
spec's ``tower.dampers``.

Each StC file gives its degrees of freedom (``StC_DOF_MODE`` 1: independent X, Y, Z
dampers; 2: an omnidirectional XY damper of one mass), its rest position (``StC_P_X/Y/Z``,
from the nacelle's reference at the yaw bearing, or from the tower's base), and per
direction its mass, stiffness and damping (``StC_X_M``, ``StC_X_K``, ``StC_X_C`` …; the
omnidirectional damper's mass ``StC_XY_M``). X is downwind (fore-aft), Y lateral
(side-side). A spring given as a force table (``Use_F_TBL``) is taken at its slope at rest.

Not modelled, each said: blade and substructure dampers (``NumBStC``, ``NumSStC``),
vertical (Z) dampers, which no bending mode moves, tuned liquid column dampers (mode 3),
prescribed or DLL forces (modes 4, 5), semi-active or active control (``StC_CMODE``; the
passive spring and dashpot are taken), end stops.

OpenFAST documentation, ServoDyn "Structural Control" input file.
"""

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import SpecError
from ..spec import read_text
from .deck import Deck, _tokens, beside, finite, parse, present

#: ServoDyn's keys of the StC files by where they are mounted (those wtvib models).
MOUNTS = {"nacelle": ("NumNStC", "NStCfiles"), "tower": ("NumTStC", "TStCfiles")}
#: and those it does not
UNMODELLED = {"blade": ("NumBStC", "BStCfiles"), "substructure": ("NumSStC", "SStCfiles")}
_DIRECTIONS = {"X": "fore-aft", "Y": "side-side"}


@dataclass
class Control:
    """The dampers of a deck set's ServoDyn as ``tower.dampers`` entries, what was read and
    what was not modelled."""

    dampers: list[dict[str, Any]] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)


def read(servo: Deck | None) -> Control:
    """The structural control a ServoDyn file mounts (none where it has no StC inputs)."""
    out = Control()
    if servo is None:
        return out
    for place, (count, _) in UNMODELLED.items():
        if count in servo.values and servo.whole(count, low=0, high=100) > 0:
            out.warnings.append(
                f"structural control: {servo.whole(count, low=0, high=100)} {place} damper(s) "
                f"({count} in {servo.path.name}) not modelled — their modes and damping are "
                "not in this audit"
            )
    for place, (count, files) in MOUNTS.items():
        if count not in servo.values:
            continue
        n = servo.whole(count, low=0, high=100)
        for path in _names(servo, files, n):
            _one(parse(path), place, out)
    return out


def _names(servo: Deck, key: str, count: int) -> list[Path]:
    """The ``count`` files a ``…StCfiles`` line names (several quoted names before the key:
    read from the line itself), each there or one line naming it."""
    if count == 0:
        return []
    line = servo.values[key][1] if key in servo.values else None
    if line is None:  # several names: the key is not the second token of its line
        text = read_text(servo.path, ansi=True).splitlines()
        line = next(
            (i + 1 for i, t in enumerate(text) if key in _tokens(t)[count : count + 1]), None
        )
    if line is None:
        raise SpecError(f"{key} is not in the file", source=str(servo.path))
    names = [
        t.strip('"')
        for t in _tokens(read_text(servo.path, ansi=True).splitlines()[line - 1])[:count]
    ]
    out = []
    for name in names:
        path = beside(servo.path, name)
        if not present(path):
            raise SpecError(f"{key} names {name!r}, which does not exist", line=line,
                            source=str(servo.path))  # fmt: skip
        out.append(path)
    return out


def _one(stc: Deck, place: str, out: Control) -> None:
    """One StC file's dampers into ``out``."""
    mode = stc.whole("StC_DOF_MODE", low=0, high=5)
    name = stc.path.name
    if mode == 0:
        out.notes.append(f"{name}: no degree of freedom (StC_DOF_MODE 0).")
        return
    if mode >= 3:
        kind = {3: "a tuned liquid column damper", 4: "a prescribed force", 5: "a DLL's force"}
        out.warnings.append(
            f"structural control: {name} is {kind[mode]} (StC_DOF_MODE {mode}) — not modelled"
        )
        return
    if "StC_CMODE" in stc.values and stc.whole("StC_CMODE", low=0, high=10) != 0:
        out.warnings.append(
            f"structural control: {name} is controlled (StC_CMODE "
            f"{stc.whole('StC_CMODE', low=0, high=10)}) — modelled as its passive spring and "
            "dashpot"
        )
    if mode == 1 and stc.flag("StC_Z_DOF"):
        out.notes.append(f"{name}: its vertical (Z) damper is not modelled (no bending moves it).")
    height = stc.num("StC_P_Z", default=0.0)
    for axis, direction in _DIRECTIONS.items():
        if mode == 1 and not stc.flag(f"StC_{axis}_DOF"):
            continue
        mass_key = f"StC_{axis}_M" if mode == 1 else "StC_XY_M"
        mass = stc.num(mass_key)
        if not mass > 0:
            raise SpecError(
                f"{mass_key} = {mass:g} kg: a damper needs a mass above 0",
                line=stc.line(mass_key),
                source=str(stc.path),
            )
        stiffness = _spring(stc, axis)
        out.dampers.append(
            {
                "name": f"{name} {axis}",
                "on": place,
                "height_m": height,
                "direction": direction,
                "mass_kg": mass,
                "stiffness_n_m": stiffness,
                "damping_ns_m": stc.num(f"StC_{axis}_C", default=0.0),
            }
        )
    out.notes.append(
        f"Structural control {name}: on the {place} at StC_P_Z = {height:g} m "
        + ("above the tower top" if place == "nacelle" else "above the tower's base")
        + (" (its X, Y offsets neglected)" if stc.num("StC_P_X", default=0.0)
           or stc.num("StC_P_Y", default=0.0) else "")
        + "; a mass on a spring and a dashpot per direction (wtvib.subsystems.mass_damper)."
    )  # fmt: skip


def _spring(stc: Deck, axis: str) -> float:
    """The damper's stiffness in one direction: StC_X_K, or the force table's slope at
    rest where ``Use_F_TBL`` is on; above 0, or one line naming it."""
    key = f"StC_{axis}_K"
    if stc.flag("Use_F_TBL"):
        table = _force_table(stc)
        column = {"X": 0, "Y": 2}[axis]
        x, f = table[:, column], table[:, column + 1]
        k = float(np.interp(1e-6, x, f) - np.interp(-1e-6, x, f)) / 2e-6
        key = "Use_F_TBL"
    else:
        k = stc.num(key)
    if not k > 0:
        raise SpecError(
            f"{key}: a stiffness of {k:g} N/m — a damper needs a spring above 0 N/m",
            line=stc.line(key),
            source=str(stc.path),
        )
    return k


def _force_table(stc: Deck) -> np.ndarray:
    """The StC SPRING FORCES TABLE (X, F_X, Y, F_Y, Z, F_Z), its NKInpSt rows."""
    rows = stc.whole("NKInpSt", low=2, high=10_000)
    lines = read_text(stc.path, ansi=True).splitlines()
    start = next((i for i, t in enumerate(lines) if "SPRING FORCES TABLE" in t.upper()), None)
    if start is None:
        raise SpecError("Use_F_TBL is on but there is no spring force table", source=str(stc.path))
    out = []
    for i in range(start + 3, start + 3 + rows):
        cells = lines[i].split() if i < len(lines) else []
        if len(cells) < 6:
            raise SpecError("the spring force table's row is not six numbers", line=i + 1,
                            source=str(stc.path))  # fmt: skip
        out.append([finite(c, i + 1, stc.path) for c in cells[:6]])
    table = np.array(out)
    if not np.all(np.diff(table[:, 0]) > 0):
        raise SpecError("the spring force table's X column must increase", source=str(stc.path))
    return table
