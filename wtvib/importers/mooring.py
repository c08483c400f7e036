"""A floating deck set's moorings: their stiffness at the platform's undisplaced position,
from NREL's MoorPy (quasi-static catenary lines; Hall et al., MoorPy documentation).

MAP++ (``CompMooring`` = 1) input: its LINE DICTIONARY (diameter, mass per length in air,
EA), NODE PROPERTIES (``fix`` anchors, ``vessel`` fairleads, ``connect`` nodes; ``depth``
for the seabed) and LINE PROPERTIES (type, unstretched length, anchor and fairlead node),
and ``repeat`` angles in its SOLVER OPTIONS (the system copied about the vertical axis).
MoorDyn (``CompMooring`` = 3) input: read by MoorPy itself, its ``vessel``/``coupled`` points
attached to the platform. The water depth is the deck set's (SeaState, HydroDyn or the
.fst: ``WtrDpth``). Lines are wet: their weight in water w = (m − ρ·πd²/4)·g.

MoorPy is wtvib's one dependency for floating platforms (its catenary solver does the job
better than a hand-written one: it is NREL's, and RAFT's). Jonkman 2010 (NREL/TP-500-47535)
Table 5-1 gives the OC3-Hywind mooring stiffness this reproduces (K₁₁ 41,180 N/m,
K₁₅ −2.821·10⁶ N, K₃₃ 11,940 N/m, K₄₄ 311.1·10⁶ N·m/rad, K₆₆ 11.56·10⁶ N·m/rad).
"""

import contextlib
import functools
import io
import math
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import SpecError
from ..spec import read_text
from .deck import Deck, _file, environment, finite, parse

#: At most this many mooring lines (a platform has a handful; the bound keeps a hostile
#: file's repeat angles from building millions).
MAX_LINES = 1000

#: A line strained beyond this at the undisplaced position cannot be what the file means: it
#: is too short to reach between its ends (steel chain and wire yield below 1 %, fibre ropes
#: stretch a few per cent at their breaking load).
MAX_STRAIN = 0.1

#: How MAP++ names its node types.
ANCHOR, FAIRLEAD, CONNECT = "fix", "vessel", "connect"


def stiffness(fst: Deck, rho: float, g: float) -> tuple[np.ndarray, str]:
    """The moorings' 6×6 stiffness at the PRP, and what it came from."""
    mode = fst.num("CompMooring", default=0)
    if mode == 0:
        return np.zeros((6, 6)), "no moorings (CompMooring = 0)"
    if mode not in (1, 3) or "MooringFile" not in fst.values:
        raise SpecError(
            f"CompMooring = {mode:g}: wtvib reads MAP++ (1) and MoorDyn (3) moorings",
            line=fst.values.get("CompMooring", ("", None))[1],
            source=str(fst.path),
        )
    path = _file(fst, "MooringFile")
    depth = _depth(fst)
    try:
        import moorpy  # noqa: F401
    except ImportError:
        raise SpecError(
            "a floating platform's moorings need MoorPy: pip install moorpy", source=str(path)
        ) from None
    with contextlib.redirect_stdout(io.StringIO()):  # MoorPy prints its progress
        system = _map_system(path, depth, rho, g) if mode == 1 else _moordyn_system(path, depth)
        k = _body_stiffness(system, path)
    kind = "MAP++" if mode == 1 else "MoorDyn"
    return k, f"{kind} moorings {path.name} (MoorPy, depth {depth:g} m)"


def _depth(fst: Deck) -> float:
    """The water depth: SeaState's, HydroDyn's, else the .fst's WtrDpth."""
    env = environment(fst)
    for key in ("SeaStFile", "HydroFile"):
        if key in fst.values and fst.text(key).lower() != "unused":
            try:
                deck = parse(_file(fst, key))
            except SpecError:
                continue
            deck.inherited.update(env)
            if "WtrDpth" in deck.values:
                return deck.num("WtrDpth", default=env.get("WtrDpth", (0.0, ""))[0])
    if "WtrDpth" in env:
        return env["WtrDpth"][0]
    raise SpecError("the deck set gives no water depth (WtrDpth)", source=str(fst.path))


def _section(lines: list[str], title: str) -> tuple[list[str], list[tuple[list[str], int]]]:
    """A MAP++ section's header and rows (after the units line, to the next rule)."""
    start = next((i for i, line in enumerate(lines) if title in line.upper()), None)
    if start is None:
        return [], []
    header = lines[start + 1].split() if start + 1 < len(lines) else []
    rows = []
    for n in range(start + 3, len(lines)):
        if lines[n].lstrip().startswith("-"):
            break
        if lines[n].split():
            rows.append((lines[n].split(), n + 1))
    return header, rows


def _row(cells: list[str], n: int, width: int, what: str, path: Path) -> list[str]:
    """A MAP++ table row of at least ``width`` cells (line ``n``)."""
    if len(cells) < width:
        raise SpecError(
            f"a {what} row needs {width} columns, this has {len(cells)}", line=n, source=str(path)
        )
    return cells


def _line_type(
    cells: list[str],
    n: int,
    number: Callable[[str, int], float],
    rho: float,
    g: float,
    path: Path,
) -> dict[str, Any]:
    """A LINE DICTIONARY row as MoorPy's line type (its submerged weight per metre in water
    of density ``rho`` [kg/m³] under gravity ``g`` [m/s²])."""
    d, m, ea = (number(c, n) for c in cells[1:4])
    if not (d > 0 and m > 0 and ea > 0):
        raise SpecError(
            "a line type needs a positive Diam, MassDenInAir and EA", line=n, source=str(path)
        )
    weight = (m - rho * math.pi / 4 * d**2) * g  # per metre, submerged
    return {
        "name": cells[0],
        "d_vol": d,
        "m": m,
        "EA": ea,
        "w": weight,
        "MBL": 0.0,
        "cost": 0.0,
        "input_d": d,
        "material": cells[0],
    }


def _map_system(path: Path, depth: float, rho: float, g: float) -> Any:
    import moorpy as mp

    lines = read_text(path, ansi=True).splitlines()

    def number(text: str, line: int) -> float:
        return -depth if text.lower() == "depth" else finite(text, line, path)

    def row(cells: list[str], n: int, width: int, what: str) -> list[str]:
        return _row(cells, n, width, what, path)

    _, types = _section(lines, "LINE DICTIONARY")
    _, nodes = _section(lines, "NODE PROPERTIES")
    _, line_rows = _section(lines, "LINE PROPERTIES")
    _, options = _section(lines, "SOLVER OPTIONS")
    if not types or not nodes or not line_rows:
        raise SpecError(
            "a MAP++ file needs LINE DICTIONARY, NODE PROPERTIES and LINE PROPERTIES rows",
            source=str(path),
        )
    kinds = {}
    for cells, n in types:
        kinds[cells[0]] = _line_type(row(cells, n, 4, "LINE DICTIONARY"), n, number, rho, g, path)
    angles = [0.0]
    for cells, n in options:
        if cells[0].lower() == "repeat":
            angles += [number(c, n) for c in cells[1:]]
    if len(angles) * len(line_rows) > MAX_LINES:
        raise SpecError(
            f"{len(angles) * len(line_rows)} mooring lines: wtvib reads at most {MAX_LINES}",
            source=str(path),
        )
    system = mp.System(depth=depth)
    system.lineTypes.update(kinds)
    system.addBody(-1, np.zeros(6))
    for angle in angles:
        c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
        ids = {}
        for cells, n in nodes:
            kind = row(cells, n, 5, "NODE PROPERTIES")[1].lower()
            x, y, z = (number(v, n) for v in cells[2:5])
            r = [c * x - s * y, s * x + c * y, z]
            role = {FAIRLEAD: "fairlead", ANCHOR: "anchor", CONNECT: "free"}.get(kind)
            if role is None:
                raise SpecError(
                    f"node type {cells[1]!r} is not fix, vessel or connect",
                    line=n,
                    source=str(path),
                )
            ids[cells[0]] = _add_point(system, role, r)
        for cells, n in line_rows:
            row(cells, n, 5, "LINE PROPERTIES")
            if cells[1] not in kinds or cells[3] not in ids or cells[4] not in ids:
                raise SpecError(
                    "a line names a type or node the file does not have", line=n, source=str(path)
                )
            length = number(cells[2], n)
            if not length > 0:
                raise SpecError("a line needs a positive length", line=n, source=str(path))
            system.addLine(length, cells[1], pointA=ids[cells[3]], pointB=ids[cells[4]])
    return system


def _add_point(system: Any, role: str, r: Any) -> int:
    """A mooring node in the MoorPy system — an ``anchor`` (fixed), a ``fairlead`` (fixed to
    the platform's body, the system's first) or a ``free`` connection — and its number."""
    system.addPoint(0 if role == "free" else 1, r)
    number = len(system.pointList)
    if role == "fairlead":
        system.bodyList[0].attachPoint(number, r)
    return number


def _moordyn_system(path: Path, depth: float) -> Any:
    import moorpy as mp

    read_text(path)  # its size and encoding checked (MoorPy reads it as UTF-8)
    try:
        system = mp.System(file=str(path), depth=depth)
    except Exception as exc:  # MoorPy's own reader: any failure is the file's
        raise SpecError(
            f"MoorPy cannot read this MoorDyn file ({type(exc).__name__}: {str(exc)[:200]})",
            source=str(path),
        ) from None
    if len(system.lineList) > MAX_LINES:
        raise SpecError(
            f"{len(system.lineList)} mooring lines: wtvib reads at most {MAX_LINES}",
            source=str(path),
        )
    if not system.bodyList:
        system.addBody(-1, np.zeros(6))
        body = system.bodyList[0]
        for point in system.pointList:
            if point.type == -1:
                point.type = 1
                body.attachPoint(point.number, point.r)
    return system


def _body_stiffness(system: Any, path: Path) -> np.ndarray:
    try:  # MoorPy's catenary on a hostile line overflows: its result is checked below
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore", RuntimeWarning)
            system.initialize()
            system.solveEquilibrium()
            k = np.asarray(system.bodyList[0].getStiffnessA(lines_only=True), dtype=float)
    except Exception as exc:  # a line too short to reach, a solver that does not converge
        raise SpecError(
            f"the moorings have no equilibrium at the platform's undisplaced position "
            f"({type(exc).__name__}: {str(exc)[:200]}): check line lengths and nodes",
            source=str(path),
        ) from None
    if k.shape != (6, 6) or not np.all(np.isfinite(k)):
        raise SpecError("the moorings' stiffness is not finite", source=str(path))
    for n, line in enumerate(system.lineList, start=1):
        tension = max(abs(float(line.TA)), abs(float(line.TB)))
        ea = float(line.type["EA"])
        if not tension / ea <= MAX_STRAIN:
            raise SpecError(
                f"mooring line {n} is stretched {tension / ea:.0%} of its length ({tension:.3g} N "
                f"on EA {ea:.3g} N) to reach its ends: it is too short for them (a chain or rope "
                f"strains under {MAX_STRAIN:.0%}) — check its length and its nodes",
                source=str(path),
            )
    return np.asarray(0.5 * (k + k.T))


#: windIO line types → MoorPy's line property library (``getLineProps``).
WINDIO_MATERIALS = {
    "chain": "chain",
    "chain_stud": "chain_studlink",
    "wire": "wire",
    "iwrc": "wire",
    "wire_wire": "wire",
    "polyester": "polyester",
    "fiber": "polyester",
    "nylon": "nylon",
}


@functools.cache
def _line_library() -> Any:
    """MoorPy's line property library (its YAML read once a process)."""
    import moorpy.helpers

    return moorpy.helpers.loadLineProps(None)


def windio_system(
    mooring: dict[str, Any],
    joints: dict[str, np.ndarray],
    depth: float,
    rho: float,
    g: float,
    path: Path,
) -> tuple[np.ndarray, float, int, list[str]]:
    """A windIO ``mooring`` block's stiffness at the PRP, its vertical force on the
    platform [N] (negative: down), its number of lines, and what was assumed. A line type
    without its own ``mass_density`` and ``stiffness`` takes MoorPy's properties for its
    material at the nominal size whose volume-equivalent diameter is windIO's ``diameter``
    (the schema's definition; WISDEM reads it so: a chain's nominal size is d/1.8)."""
    import moorpy as mp
    import moorpy.helpers

    notes: list[str] = []

    def fail(message: str, where: str) -> SpecError:
        return SpecError(message, path=f"components.mooring.{where}", source=str(path))

    system = mp.System(depth=depth, rho=rho, g=g)
    for i, t in enumerate(mooring["line_types"]):
        d = t.get("diameter")
        if isinstance(d, bool) or not isinstance(d, (int, float)) or not 0 < d < 10:
            raise fail(f"a line's diameter must be 0 … 10 m (got {d!r})", f"line_types[{i}]")
        mass, ea = t.get("mass_density"), t.get("stiffness")
        if isinstance(mass, (int, float)) and isinstance(ea, (int, float)) and mass > 0 < ea:
            given = {"name": str(t["name"]), "d_vol": float(d), "m": float(mass), "EA": float(ea)}
            system.setLineType(name=given["name"], lineType={**given, "material": "custom"})
            continue
        material = WINDIO_MATERIALS.get(str(t.get("type", "")).lower())
        if material is None:
            raise fail(
                f"line type {t.get('type')!r} has no mass_density and stiffness, and MoorPy's "
                f"library has no such material ({', '.join(WINDIO_MATERIALS)})",
                f"line_types[{i}]",
            )
        # windIO's diameter is the volume-equivalent one; MoorPy's library is by nominal size
        library = _line_library()
        probe = mp.helpers.getLineProps(100.0, material, lineProps=library)
        nominal = float(d) / (probe["d_vol"] / 0.1)
        props = mp.helpers.getLineProps(nominal * 1000, material, lineProps=library)
        kind = system.setLineType(name=str(t["name"]), lineType={**props, "name": str(t["name"])})
        notes.append(
            f"line type {t['name']}: {material} of volume-equivalent diameter {float(d):g} m "
            f"(windIO's diameter), nominal {nominal * 1000:.0f} mm — MoorPy's library: "
            f"{kind['m']:.0f} kg/m, EA {kind['EA']:.3g} N"
        )
    system.addBody(-1, np.zeros(6))
    ids = {}
    for i, n in enumerate(mooring["nodes"]):
        kind = str(n.get("node_type", ""))
        joint = n.get("joint")
        if joint is not None and str(joint) in joints:
            r = joints[str(joint)]
        elif isinstance(n.get("location"), list) and len(n["location"]) == 3:
            r = np.asarray(n["location"], float)
        else:
            raise fail("a node needs a joint of the platform or a location", f"nodes[{i}]")
        role = {"vessel": "fairlead", "fixed": "anchor", "connection": "free"}.get(kind)
        if role is None:
            raise fail(f"node_type {kind!r} is not fixed, vessel or connection", f"nodes[{i}]")
        ids[str(n["name"])] = _add_point(system, role, r)
    lines = mooring["lines"]
    if not lines or len(lines) > MAX_LINES:
        raise fail(f"{len(lines)} mooring lines (1 … {MAX_LINES})", "lines")
    for i, line in enumerate(lines):
        a, b, kind = str(line["node1"]), str(line["node2"]), str(line["line_type"])
        if a not in ids or b not in ids or kind not in system.lineTypes:
            raise fail("a line names a node or line type the file does not have", f"lines[{i}]")
        length = line["unstretched_length"]
        if isinstance(length, bool) or not isinstance(length, (int, float)) or not length > 0:
            raise fail("a line needs a positive unstretched_length", f"lines[{i}]")
        system.addLine(float(length), kind, pointA=ids[a], pointB=ids[b])
    k = _body_stiffness(system, path)
    force = float(system.bodyList[0].getForces(lines_only=True)[2])
    if not math.isfinite(force):
        raise SpecError("the moorings' pull on the platform is not finite", source=str(path))
    return k, force, len(lines), notes


def lines_stiffness(
    lines: list[tuple[np.ndarray, np.ndarray, float, float, float, float]],
    depth: float,
    rho: float,
    g: float,
    path: Path,
) -> np.ndarray:
    """The 6×6 stiffness at the PRP of single-segment lines, each (anchor, fairlead [m, the
    PRP's frame: x downwind, z up], unstretched length [m], mass per length in air and in
    water [kg/m], EA [N]): the wet weight from the two masses, as the volume-equivalent
    diameter MoorPy takes (d² = 4(m − m_w)/(πρ))."""
    import moorpy as mp

    if not lines or len(lines) > MAX_LINES:
        raise SpecError(f"{len(lines)} mooring lines (1 … {MAX_LINES})", source=str(path))
    with contextlib.redirect_stdout(io.StringIO()):  # MoorPy prints its progress
        system = mp.System(depth=depth, rho=rho, g=g)
        system.addBody(-1, np.zeros(6))
        for n, (anchor, fairlead, length, m_air, m_wet, ea) in enumerate(lines, start=1):
            kind = f"line{n}"
            d_vol = math.sqrt(4 * (m_air - m_wet) / (math.pi * rho))
            given = {"name": kind, "d_vol": d_vol, "m": m_air, "EA": ea, "material": "custom"}
            system.setLineType(name=kind, lineType=given)
            a = _add_point(system, "anchor", anchor)
            b = _add_point(system, "fairlead", fairlead)
            system.addLine(length, kind, pointA=a, pointB=b)
        return _body_stiffness(system, path)
