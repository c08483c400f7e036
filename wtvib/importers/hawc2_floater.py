"""A HAWC2 model's floater as wtvib's floating platform: the external systems HAWC2 holds
it with, read for what a modal audit needs.

* **The floater** — an ``ext_sys`` of module ``ESYSWamit`` (DTU's WAMIT-based floater),
  joined to the model's lowest main body by a ``constraint`` ``dll`` whose ``mbdy_node``
  names that body and whose ``esys_node`` names the system, its ``ID`` the WAMIT body's
  origin (the PRP, on the still-water line) from the body's origin. Its ``data``:
  ``WAMIT_FILE`` (the WAMIT results' stem: the ``.1`` added mass at each period, the
  ``.hst`` hydrostatics, as OpenFAST's HydroDyn reads them, length scale 1 m), ``MASS``,
  ``COG`` (in WAMIT's frame, z up from the still-water line: the VolturnUS-S's −14.94 m),
  ``RIJ_COG i i`` (radii of gyration about the CM), ``DENSITY`` and ``GRAVITY``.
* **The moorings** — ``ext_sys`` of module ``elasticBar`` (``ESYSMooring``): a line of
  mass per length in air and in water (``mass``), axial stiffness ``axial_stiff``, laid
  straight from ``start_pos`` to ``end_pos`` on the seabed (the unstretched length is their
  distance: how DTU's windIO-to-HAWC2 converter and the IEA-15's
  ``make_umainesemi_mooring.py`` write it), its first node fixed to the ground
  (``cstrbarfixedtoglobal``) and its last to the floater's body (``cstrbarsfixedtobody…``,
  the fairlead at ``ID`` from the body's node). Their stiffness at the undisplaced
  position from MoorPy's catenary (:func:`wtvib.importers.mooring.lines_stiffness`).

HAWC2's global frame (x lateral, y downwind, z down) is turned into the platform's (x
downwind, y lateral, z up: OpenFAST's, which the spec's matrices use): (X, Y, Z) =
(y, x, −z). WAMIT's matrices are taken in that frame as OpenFAST takes the same files;
``INIT_ROT`` turns the WAMIT body in HAWC2 and is not applied (said): a platform
symmetric under a half turn, as the three-column semisubmersibles are, is the same either
way. Left out, and said: radiation damping, the quadratic drag (``QUADDRAG``), the lines'
own dynamics, a horizontal offset of the CM.
"""

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Protocol

import numpy as np

from ..errors import SpecError
from . import htc
from .htc import Block, Command
from .hydrodyn import Naming, matrix_rows, wamit_added_mass, wamit_hydrostatic


class Placed(Protocol):
    """A main body placed in HAWC2's global frame (:class:`wtvib.importers.hawc2.Body`)."""

    origin: np.ndarray
    frame: np.ndarray

    def at(self, which: str) -> np.ndarray: ...


#: Where a floater's data give no density or gravity: sea water, standard gravity.
DENSITY, GRAVITY = 1025.0, 9.80665


@dataclass(frozen=True)
class Floater:
    """The floater HAWC2 holds a body with: the ``ext_sys`` block, the body's name, and the
    constraint that joins them (its ``ID``: the PRP from the body's origin)."""

    system: Block
    body: str
    constraint: Block


def find(structure: Block, base: str) -> Floater | None:
    """The ESYSWamit floater that holds the body ``base``, if one does."""
    constraint = structure.block("constraint")
    systems = {
        _word(s.get("name")): s
        for s in structure.each("ext_sys")
        if _word(s.get("module")) == "esyswamit"
    }
    for dll in constraint.each("dll") if constraint is not None else []:
        node, esys = dll.get("mbdy_node"), dll.get("esys_node")
        if node is None or esys is None or _word(node) != base:
            continue
        system = systems.get(_word(esys))
        if system is not None:
            return Floater(system, base, dll)
    return None


def _word(cmd: Command | None) -> str:
    return cmd.values[0].strip("'\"").lower() if cmd is not None and cmd.values else ""


def _data(system: Block) -> dict[str, list[Command]]:
    """An ext_sys block's ``data KEY values`` commands by key (upper case), the key dropped
    from each command's values."""
    out: dict[str, list[Command]] = {}
    for cmd in system.all("data"):
        if cmd.values:
            rest = Command(cmd.values[0], cmd.values[1:], cmd.file, cmd.line)
            out.setdefault(cmd.values[0].upper(), []).append(rest)
    return out


def _one(data: dict[str, list[Command]], key: str, system: Block) -> Command:
    """The floater's first ``data KEY`` command, or one line saying what it gives."""
    name = _word(system.get("name"))
    return _first(data, key, system, f"ext_sys {name}: no data {key} — the floater's "
                  f"{_NEEDED[key]} is needed")  # fmt: skip


def _first(data: dict[str, list[Command]], key: str, block: Block, missing: str) -> Command:
    """The first ``data KEY`` command of an ext_sys block, else ``missing`` on its line."""
    found = data.get(key)
    if not found:
        raise SpecError(missing, line=block.line, source=str(block.file))
    return found[0]


_NEEDED = {
    "WAMIT_FILE": "WAMIT results (added mass and hydrostatics)",
    "MASS": "mass",
    "COG": "centre of mass",
    "RIJ_COG": "radii of gyration (RIJ_COG 1 1 …, 2 2, 3 3)",
}


def _bounded(cmd: Command, i: int, low: float, high: float, what: str) -> float:
    return cmd.within(i, low, high, f"{cmd.key}: {what}")


def to_platform(x: np.ndarray) -> np.ndarray:
    """A point or vector in HAWC2's global frame in the platform's (x downwind, z up)."""
    return np.array([x[1], x[0], -x[2]])


def platform(
    structure: Block,
    floater: Floater,
    bodies: Mapping[str, Placed],
    tower_base: np.ndarray,
    root: Path,
) -> tuple[dict[str, Any], list[str]]:
    """The spec's ``platform`` block of the floater and what the report says about it;
    ``bodies``: the model's main bodies, placed; ``tower_base``: the tower's base in
    HAWC2's global frame."""
    system = floater.system
    data = _data(system)
    rho = _bounded(data["DENSITY"][0], 0, 500, 2000, "density") if "DENSITY" in data else DENSITY
    g = _bounded(data["GRAVITY"][0], 0, 1, 30, "gravity") if "GRAVITY" in data else GRAVITY
    mass = _bounded(_one(data, "MASS", system), 0, 1.0, 1e10, "mass [kg]")
    cog = _one(data, "COG", system)
    cm = [_bounded(cog, i, -1000, 1000, "CM coordinate [m]") for i in range(3)]
    radii = _radii(data, system)
    stem = _one(data, "WAMIT_FILE", system)
    base = htc.resolve(stem.text(0).strip("'\""), root, stem.file.parent, stem, ".1")
    named = Naming("WAMIT_FILE", stem.line, stem.file)
    added, by_frequency = wamit_added_mass(base.with_name(base.name + ".1"), rho, 1.0, named)
    hydrostatic = wamit_hydrostatic(base.with_name(base.name + ".hst"), rho, g, 1.0, named)
    held = bodies[floater.body]
    prp = held.origin + held.frame @ _point(floater.constraint.get("id"))
    moorings, mooring_note = _moorings(structure, floater, bodies, prp, (rho, g))
    block = {
        "tower_base_m": float(prp[2] - tower_base[2]),  # HAWC2's z points down
        "mass_kg": mass,
        "cm_m": cm[2],
        "inertia_roll_kgm2": mass * radii[0] ** 2,
        "inertia_pitch_kgm2": mass * radii[1] ** 2,
        "inertia_yaw_kgm2": mass * radii[2] ** 2,
        "added_mass": matrix_rows(added),
        "added_mass_by_frequency": by_frequency,
        "stiffness": matrix_rows(hydrostatic + moorings),
        "source": f"HAWC2 ESYSWamit floater {_word(system.get('name'))} (WAMIT {base.name}.1, "
        f".hst), {mooring_note}",
    }
    off_axis = (
        f"; its CM's horizontal offset ({cm[0]:g}, {cm[1]:g}) m neglected"
        if any(abs(v) > 1e-6 for v in cm[:2])
        else ""
    )
    notes = [
        f"Floating platform from the HAWC2 model's ESYSWamit floater "
        f"{_word(system.get('name'))} (ext_sys, {system.file.name}:{system.line}): mass "
        f"{mass:,.0f} kg, CM {cm[2]:g} m from the PRP{off_axis}, radii of gyration "
        f"{radii[0]:g}, {radii[1]:g}, {radii[2]:g} m; WAMIT's added mass ({base.name}.1: "
        f"each mode takes it at its own frequency, from {len(by_frequency)} periods) and "
        f"hydrostatics ({base.name}.hst; ρ {rho:g} kg/m³, g {g:g} m/s², L 1 m), in the "
        "platform's frame as OpenFAST reads them (ESYSWamit's INIT_ROT not applied); "
        f"{mooring_note}; the platform a rigid body with six DOFs under the tower, its "
        "radiation damping, quadratic drag (QUADDRAG) and the lines' dynamics left out."
    ]
    return block, notes


def _radii(data: dict[str, list[Command]], system: Block) -> list[float]:
    """The radii of gyration about the CM (``RIJ_COG i i r``) about x, y, z of WAMIT's
    frame, which is the platform's as OpenFAST takes the same files (x downwind: 1 1 is
    roll); the products (``i ≠ j``) are not read."""
    _one(data, "RIJ_COG", system)
    found: dict[int, float] = {}
    for cmd in data["RIJ_COG"]:
        i, j = cmd.number(0), cmd.number(1)
        if i == j and i in (1.0, 2.0, 3.0):
            found[int(i)] = _bounded(cmd, 2, 0, 1000, "radius of gyration [m]")
    missing = [i for i in (1, 2, 3) if i not in found]
    if missing:
        raise SpecError(
            f"ext_sys {_word(system.get('name'))}: no RIJ_COG {missing[0]} {missing[0]} — the "
            "floater's radii of gyration about its three axes are needed",
            line=system.line,
            source=str(system.file),
        )
    return [found[1], found[2], found[3]]


def _moorings(
    structure: Block,
    floater: Floater,
    bodies: Mapping[str, Placed],
    prp: np.ndarray,
    water: tuple[float, float],
) -> tuple[np.ndarray, str]:
    """The elasticBar lines' stiffness at the PRP (``water``: ρ, g) and what it came from."""
    from .mooring import lines_stiffness

    bars = {
        _word(s.get("name")): s
        for s in structure.each("ext_sys")
        if _word(s.get("module")) == "elasticbar"
    }
    if not bars:
        return np.zeros((6, 6)), "no mooring lines (no elasticBar external system)"
    ends = _line_ends(structure, set(bars))
    lines = []
    depth = 0.0
    for name, bar in bars.items():
        data = _data(bar)
        mass = _one_line(data, "MASS", bar)
        m_air = _bounded(mass, 0, 1e-3, 1e5, "mass per length in air [kg/m]")
        m_wet = _bounded(mass, 1, 1e-6, m_air, "mass per length in water [kg/m]")
        ea = _bounded(_one_line(data, "AXIAL_STIFF", bar), 0, 1.0, 1e13, "EA [N]")
        start = _point(_one_line(data, "START_POS", bar))
        end = _point(_one_line(data, "END_POS", bar))
        length = float(np.linalg.norm(end - start))
        fairlead = ends.get(name)
        if fairlead is None:
            raise SpecError(
                f"mooring line {name}: no constraint fixes its first node to the ground and its "
                f"last to the floater's body ({floater.body}) — a line held otherwise is not read",
                line=bar.line,
                source=str(bar.file),
            )
        body, node, offset = fairlead
        if body not in bodies:
            raise SpecError(f"mooring line {name}: its fairlead's body {body!r} does not exist",
                            line=bar.line, source=str(bar.file))  # fmt: skip
        b = bodies[body]
        at = b.at(node) + b.frame @ offset
        depth = max(depth, float(start[2] - prp[2]))
        lines.append((to_platform(start - prp), to_platform(at - prp), length, m_air, m_wet, ea))
    if not depth > 0:
        raise SpecError("the mooring anchors are not below the floater's still-water line",
                        line=structure.line, source=str(structure.file))  # fmt: skip
    k = lines_stiffness(lines, depth, *water, structure.file)
    return k, (
        f"{len(lines)} elasticBar mooring lines (MoorPy at the undisplaced position, depth "
        f"{depth:g} m; each laid from start_pos to end_pos: {lines[0][2]:g} m long)"
    )


def _point(cmd: Command | None) -> np.ndarray:
    """A command's first three values as a point [m] (none: the origin); fewer, or not
    numbers, one line naming the command."""
    if cmd is None:
        return np.zeros(3)
    return np.array([cmd.within(i, -1e4, 1e4, f"{cmd.key}: coordinate [m]") for i in range(3)])


def _one_line(data: dict[str, list[Command]], key: str, bar: Block) -> Command:
    """A mooring line's first ``data KEY`` command, or one line naming the line."""
    return _first(data, key, bar, f"mooring line {_word(bar.get('name'))}: no data {key.lower()}")


def _line_ends(structure: Block, names: set[str]) -> dict[str, tuple[str, str, np.ndarray]]:
    """Each line whose first node a constraint fixes to the ground and whose last it fixes
    to a body: (body, node, ID offset)."""
    constraint = structure.block("constraint")
    anchored: set[str] = set()
    held: dict[str, tuple[str, str, np.ndarray]] = {}
    for dll in constraint.each("dll") if constraint is not None else []:
        init, esys = _word(dll.get("init")), dll.get("esys_node")
        if esys is None or len(esys.values) < 2 or esys.values[0].lower() not in names:
            continue
        line, node = esys.values[0].lower(), esys.values[1]
        if "fixedtoglobal" in init and node == "1":
            anchored.add(line)
        elif "fixedtobody" in init:
            body = dll.need("mbdy_node")
            at = body.values[1] if len(body.values) > 1 else "1"
            if at.lower() != "last" and not (at.isascii() and at.isdigit() and int(at) > 0):
                raise SpecError(
                    f"mbdy_node: node {at!r} is not 'last' or a node number (1, 2, …)",
                    line=body.line,
                    source=str(body.file),
                )
            held[line] = (_word(body), at.lower(), _point(dll.get("id")))
    return {k: v for k, v in held.items() if k in anchored}
