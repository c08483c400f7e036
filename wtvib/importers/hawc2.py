"""HAWC2 turbine models (the htc file and the st, ae, pc and operating-point files it names)
as wtvib specs.

What is read (htc syntax: :mod:`wtvib.importers.htc`):

* ``new_htc_structure``: the main bodies — their ``c2_def`` centre lines and twist,
  ``timoschenko_input`` (st file, classical or fully populated ``FPM 1``, set and subset),
  ``concentrated_mass`` and ``damping_posdef``/``damping_aniso``/``_v2``, ``copy_main_body`` — and
  the ``orientation`` (``base``; ``relative`` with its successive ``mbdy2_eulerang``
  rotations) that places them; ``constraint`` for the tower's base (``fix0``), or the
  floater that holds it: an ``ESYSWamit`` external system with ``elasticBar`` moorings,
  read as wtvib's floating platform (:mod:`wtvib.importers.hawc2_floater`).
* The bodies are recognised by their place in the chain, not their names alone: the body
  fixed to the ground (``fix0``) with the one above it up to the towertop is the tower;
  the body whose last node carries the hubs is the shaft; the bodies attached to the
  hubs are the blades.
* ``aero``: ``nblades``, the ae and pc files, ``ae_sets``; ``wind``'s density.
* The operating range: an operational data file (``.opt``) in the model's ``data/``
  folder (HAWCStab2's), else the DTU Wind Energy controller's constants (minimum and
  rated rotor speed, rated power, fine pitch, optimal tip-speed ratio).

HAWC2's frames: global z points down, y downwind; a body's z runs along its centre line.
A bending stiffness about a section's x axis (E·I_x) bends it in y: for the tower
(x lateral) that is fore-aft, for a blade (x along the chord, HAWC2's hub frame) flapwise.
The structural pitch of the principal axes adds to the centre line's twist; HAWC2 twist is
positive about the blade's z (root to tip), the opposite sense of wtvib's (towards
feather), so both are negated. Prebend and sweep, shaft tilt and cone are said and
neglected, as for the other importers; damping is stiffness-proportional as HAWC2 gives it
(ζ = π·β·f, the K coefficients of ``damping_posdef``, ``_aniso`` or ``_aniso_v2``: which
direction each damps, :func:`_stiffness_damping`). The blades are Timoshenko beams as
HAWC2's are: the shear deflecting along y, k_y·G·A, goes with E·I_x (flapwise), k_x·G·A
with E·I_y (a fully populated set: K22 with K44, K11 with K55); the tower stays an
Euler–Bernoulli beam (a tube, whose shear deformation is negligible).
"""

import itertools
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import SpecError
from ..numerics.rigid import Part, assembled
from . import htc
from .hawc2_floater import Floater
from .hawc2_floater import find as find_floater
from .hawc2_floater import platform as floating_platform
from .hawc2_soil import pile_on_soil
from .htc import Block, Command
from .servodyn import dtu_speeds

#: The 19 columns of a classical st set and what they are.
ST = ("r", "m", "x_cg", "y_cg", "ri_x", "ri_y", "x_sh", "y_sh", "E", "G", "I_x", "I_y", "I_p",
      "k_x", "k_y", "A", "pitch", "x_e", "y_e")  # fmt: skip
#: A fully populated set's first nine columns; K11 … K66 (upper triangle) follow.
FPM_HEAD = ("r", "m", "x_cg", "y_cg", "ri_x", "ri_y", "pitch", "x_e", "y_e")


@dataclass
class Body:
    """A main body: its centre line (x, y, z, twist per section) and st table, where it
    is in the model."""

    name: str
    block: Block
    c2: np.ndarray  # sections × (x, y, z, twist)
    st: np.ndarray  # rows of the st set
    fpm: bool
    masses: list[tuple[int, np.ndarray]]  # (node, x y z m Ixx Iyy Izz)
    damping: tuple[float, ...]  # one of DAMPING's commands: Mx My Mz Kx Ky Kz
    damping_by: str = "damping_posdef"  # the command that gave them
    origin: np.ndarray = field(default_factory=lambda: np.zeros(3))
    frame: np.ndarray = field(default_factory=lambda: np.eye(3))
    placed: bool = False
    #: the body's nodes (body frame): its c2_def sections, or ``uniform N``'s N points
    nodes: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))

    @property
    def length(self) -> float:
        return float(np.sum(np.linalg.norm(np.diff(self.c2[:, :3], axis=0), axis=1)))

    def node(self, which: str) -> np.ndarray:
        """A node's position in the body's frame (``last`` or its 1-based number, which the
        reader has checked against the body's nodes)."""
        points = self.nodes if len(self.nodes) else self.c2[:, :3]
        i = len(points) - 1 if which == "last" else int(float(which)) - 1
        return np.asarray(points[min(max(i, 0), len(points) - 1)])

    def at(self, which: str) -> np.ndarray:
        """A node's global position."""
        return np.asarray(self.origin + self.frame @ self.node(which))


def _rotation(angles: list[float]) -> np.ndarray:
    """HAWC2's Euler angles [deg]: rotations about x, then y, then z of the frame."""
    ax, ay, az = (math.radians(a) for a in angles)
    rx = np.array([[1, 0, 0], [0, math.cos(ax), -math.sin(ax)], [0, math.sin(ax), math.cos(ax)]])
    ry = np.array([[math.cos(ay), 0, math.sin(ay)], [0, 1, 0], [-math.sin(ay), 0, math.cos(ay)]])
    rz = np.array([[math.cos(az), -math.sin(az), 0], [math.sin(az), math.cos(az), 0], [0, 0, 1]])
    return np.asarray(rx @ ry @ rz)


def _bodies(structure: Block, root: Path) -> dict[str, Body]:
    blocks = structure.each("main_body")
    by_name = {}
    for b in blocks:
        name_cmd = b.need("name")
        by_name[name_cmd.text(0).lower()] = b
    out: dict[str, Body] = {}
    for name, b in by_name.items():
        source = b
        copy = b.get("copy_main_body")
        if copy is not None:
            original = copy.values[0].lower() if copy.values else ""
            if original not in by_name:
                raise SpecError(
                    f"copy_main_body names {original!r}, which is no main body",
                    line=copy.line,
                    source=str(copy.file),
                )
            source = by_name[original]
        out[name] = _body(name, source, root)
    return out


#: How far a body's centre line may reach from its origin [m].
MAX_COORDINATE_M = 1000.0


def _body(name: str, b: Block, root: Path) -> Body:
    c2_block = b.block("c2_def")
    if c2_block is None:
        raise SpecError(f"main body {name}: no c2_def block", line=b.line, source=str(b.file))
    secs = c2_block.all("sec")
    if len(secs) < 2:
        raise SpecError(
            f"main body {name}: its c2_def has {len(secs)} section(s), two at least are needed",
            line=c2_block.line,
            source=str(c2_block.file),
        )
    rows = []
    for sec in secs:  # sec number x y z twist: a centre line within a kilometre
        row = [sec.number(i) for i in range(1, 5)]
        if max(abs(v) for v in row[:3]) > MAX_COORDINATE_M:
            raise SpecError(
                f"sec: a centre-line point {MAX_COORDINATE_M:g} m or more from its body's "
                "origin: no wind turbine is that large",
                line=sec.line,
                source=str(sec.file),
            )
        rows.append(row)
    c2 = np.array(rows)
    timo = b.block("timoschenko_input")
    if timo is None:
        raise SpecError(
            f"main body {name}: no timoschenko_input block", line=b.line, source=str(b.file)
        )
    file_cmd = timo.need("filename")
    path = htc.resolve(file_cmd.text(0), root, file_cmd.file.parent, file_cmd)
    fpm_cmd = timo.get("fpm")
    fpm = fpm_cmd is not None and fpm_cmd.number(0) == 1
    set_cmd = timo.need("set")
    st = htc.read_st(path, int(set_cmd.number(0)), int(set_cmd.number(1)), 30 if fpm else len(ST))
    nodes = _nodes(b, c2)
    masses = [_concentrated(c, len(nodes)) for c in b.all("concentrated_mass")]
    damp = next((cmd for cmd in map(b.get, DAMPING) if cmd is not None), None)
    damping = tuple(damp.first(6)) if damp is not None else (0.0,) * 6
    by = damp.key if damp is not None else DAMPING[0]
    return Body(name, b, c2, st, fpm, masses, damping, by, nodes=nodes)


def _nodes(b: Block, c2: np.ndarray) -> np.ndarray:
    """A main body's nodes in its frame, as its ``node_distribution`` puts them: at the
    c2_def sections (``c2_def``, and where none is given), or ``uniform N`` — N nodes at
    equal distances along the centre line."""
    cmd = b.get("node_distribution")
    kind = cmd.text(0).lower() if cmd is not None and cmd.values else "c2_def"
    if kind == "c2_def":
        return np.asarray(c2[:, :3])
    if kind != "uniform" or cmd is None:
        raise SpecError(
            f"node_distribution: {kind!r} is not c2_def or uniform", line=b.line, source=str(b.file)
        )
    count = int(cmd.within(1, 2, 1e4, "node_distribution uniform: the number of nodes"))
    steps = np.linalg.norm(np.diff(c2[:, :3], axis=0), axis=1)
    along = np.concatenate([[0.0], np.cumsum(steps)])
    at = np.linspace(0.0, along[-1], count)
    return np.stack([np.interp(at, along, c2[:, k]) for k in range(3)], axis=1)


def _concentrated(cmd: Command, nodes: int) -> tuple[int, np.ndarray]:
    """A ``concentrated_mass`` command on a body of ``nodes`` nodes: its node, offset
    (x, y, z) [m], mass [kg] and inertias about its body's axes [kg·m²] — a node the body
    does not have, a negative mass or inertia, or a value no turbine has, one line naming
    the command."""
    node = int(cmd.within(0, 1, nodes, "concentrated_mass: node"))
    offset = [cmd.within(i, -1e4, 1e4, f"concentrated_mass: offset {a} [m]")
              for i, a in zip((1, 2, 3), "xyz", strict=True)]  # fmt: skip
    mass = cmd.within(4, 0.0, 1e9, "concentrated_mass: mass [kg]")
    inertia = [cmd.within(i, 0.0, 1e13, f"concentrated_mass: inertia I{a} [kg·m²]")
               for i, a in zip((5, 6, 7), ("xx", "yy", "zz"), strict=True)]  # fmt: skip
    return node, np.array([*offset, mass, *inertia])


def _place(bodies: dict[str, Body], orientation: Block) -> None:
    """Each body's origin and frame from the orientation block."""
    for base in orientation.each("base"):
        cmd = base.get("mbdy") or base.need("body")
        body = _named(bodies, cmd)
        ini = base.get("inipos")
        body.origin = np.array(ini.first(3)) if ini is not None else np.zeros(3)
        angles = base.all("mbdy_eulerang") + base.all("body_eulerang")
        frame = np.eye(3)
        for a in angles:
            frame = frame @ _rotation(a.first(3))
        body.frame, body.placed = frame, True
    relatives = orientation.each("relative")
    for _ in range(len(relatives) + 1):  # in order, each after its parent
        for rel in relatives:
            first = rel.get("mbdy1") or rel.need("body1")
            second = rel.get("mbdy2") or rel.need("body2")
            parent, child = _named(bodies, first), _named(bodies, second)
            if not parent.placed or child.placed:
                continue
            frame = parent.frame.copy()
            for a in rel.all("mbdy2_eulerang") + rel.all("body2_eulerang"):
                frame = frame @ _rotation(a.first(3))
            child.origin = parent.at(_node_ref(first, "last", parent)) - frame @ child.node(
                _node_ref(second, "1", child)
            )
            child.frame, child.placed = frame, True


def _node_ref(cmd: Command, default: str, body: Body) -> str:
    """The node a ``mbdy1``/``mbdy2`` command names after the body: ``last`` or its
    number (1 up to the body's nodes), or one line naming file and line."""
    if len(cmd.values) < 2:
        return default
    which = cmd.values[1].lower()
    if which == "last":
        return which
    if not which.isascii() or not which.isdigit() or int(which) < 1:
        raise SpecError(
            f"{cmd.key}: node {cmd.values[1]!r} is not 'last' or a node number (1, 2, …)",
            line=cmd.line,
            source=str(cmd.file),
        )
    if int(which) > len(body.nodes):
        raise SpecError(
            f"{cmd.key}: node {int(which)} of body {body.name}, which has {len(body.nodes)}",
            line=cmd.line,
            source=str(cmd.file),
        )
    return str(int(which))


def _named(bodies: dict[str, Body], cmd: Command) -> Body:
    name = cmd.values[0].lower() if cmd.values else ""
    if name not in bodies:
        raise SpecError(
            f"{cmd.key} names the body {name!r}, which the model does not have",
            line=cmd.line,
            source=str(cmd.file),
        )
    return bodies[name]


@dataclass
class _Chain:
    """The bodies in their roles."""

    tower: list[Body]  # base up
    head: list[Body]  # above the tower, below the shaft (towertop, connector …)
    shaft: Body
    hubs: list[Body]
    blades: list[Body]
    #: the ESYSWamit floater holding the lowest body (skipped: the tower stands on it)
    floater: "Floater | None" = None


#: Words of the bodies that sit between a tower and its shaft (not the tower's own).
HEAD_WORDS = ("top", "connector", "nacelle", "yaw", "bedplate")


def _unheld(base: str, structure: Block) -> None:
    """Refuse a model whose lowest body no fix0, no soil and no ESYSWamit floater holds
    (another floater's external systems, which wtvib does not read) — clamped, its tower's
    modes would be another turbine's."""
    constraint = structure.block("constraint")
    where = constraint if constraint is not None else structure
    systems = []
    for dll in constraint.each("dll") if constraint is not None else []:
        node, name = dll.get("mbdy_node"), dll.get("dll")
        if (
            node is not None
            and node.values
            and node.values[0].lower() == base
            and name
            and name.values
        ):
            systems.append(name.values[0].strip("'\""))
    names = ", ".join(dict.fromkeys(systems))
    held_by = f", held by the external systems {names}" if systems else ""
    raise SpecError(
        f"the lowest body, {base}, is fixed to the ground by no fix0 and held by no soil "
        f"block{held_by}: a floating model whose floater wtvib does not read (it reads an "
        "ESYSWamit ext_sys joined to the body by a constraint dll with esys_node), and "
        "clamped its tower would be another turbine's; audit the same turbine's OpenFAST "
        "deck set or windIO file",
        line=where.line,
        source=str(where.file),
    )


def _chain(bodies: dict[str, Body], structure: Block, embedded: set[str]) -> _Chain:
    constraint = structure.block("constraint")
    parents: dict[str, str] = {}
    orientation = structure.block("orientation")
    assert orientation is not None
    for rel in orientation.each("relative"):
        first = rel.get("mbdy1") or rel.need("body1")
        second = rel.get("mbdy2") or rel.need("body2")
        parents[second.text(0).lower()] = first.text(0).lower()
    children: dict[str, list[str]] = {}
    for child, parent in parents.items():
        children.setdefault(parent, []).append(child)
    fixed = []
    if constraint is not None:
        fixed = [(c.get("mbdy") or c.need("body")).text(0).lower() for c in constraint.each("fix0")]
    base = next((n for n in fixed if n in bodies), None)
    if base is None:  # the first body with none below it and some above (a floater's
        # members placed by base blocks of their own, joined by constraints: not the chain)
        roots = [n for n in bodies if n not in parents]
        base = next((n for n in roots if n in children), roots[0] if roots else None)
    if base is None:
        raise SpecError(
            "no body stands on the ground (no fix0, no base)", source=str(structure.file)
        )
    floater = None
    if base not in fixed and base not in embedded:
        floater = find_floater(structure, base)
        if floater is None:
            _unheld(base, structure)
    while (base in embedded or (floater and base == floater.body)) and len(
        children.get(base, [])
    ) == 1:  # a pile in the soil: the tower from the mudline up; a floater's body: on it
        base = children[base][0]

    # the shaft: the body with three (or two, one) hubs on its last node, each with a blade
    def leaves(name: str) -> list[str]:
        return children.get(name, [])

    path = [base]
    while True:
        kids = leaves(path[-1])
        if len(kids) != 1:
            break
        path.append(kids[0])
    shaft_name = path[-1]
    hubs = [bodies[n] for n in leaves(shaft_name)]
    blades = [bodies[leaves(h.name)[0]] for h in hubs if leaves(h.name)]
    if not hubs or not blades:
        raise SpecError(
            f"no rotor on the chain {' → '.join(path)}: the body {shaft_name!r} carries no hub "
            "with a blade",
            source=str(structure.file),
        )
    run = 0  # the tower: the bodies from the ground up to the first of the head's
    while run < len(path) - 1 and not any(w in path[run] for w in HEAD_WORDS):
        run += 1
    tower = [bodies[n] for n in path[: max(run, 1)]]
    head = [bodies[n] for n in path[max(run, 1) : -1]]
    return _Chain(tower, head, bodies[shaft_name], hubs, blades, floater)


# ------------------------------------------------------------------------------------------
# The spec's parts


#: Stiffer than any material [Pa] (diamond's Young's modulus about 1.1e12, steel's 2.1e11):
#: the mark of a body made rigid on purpose — HAWC2 models keep a "stiff" subset beside
#: each flexible one, E and G raised a millionfold (the DTU 10 MW's tower set 1 subset 2:
#: E 2.1e17 Pa).
MAX_MODULUS_PA = 1e13


def _flexible(body: Body) -> None:
    """A tower's or a blade's st subset as the body bends in service; one line naming the
    subset where it is one of the model's rigid ones (its modes at hundreds of hertz would
    be audited as the turbine's, as implausible frequencies)."""
    if body.fpm:
        return
    st = {k: body.st[:, i] for i, k in enumerate(ST)}
    stiffest = float(max(np.max(st["E"]), np.max(st["G"])))
    if stiffest > MAX_MODULUS_PA:
        timo = body.block.block("timoschenko_input")
        cmd = timo.need("set") if timo is not None else None
        raise SpecError(
            f"body {body.name}: its st subset has a modulus of {stiffest:.3g} Pa, stiffer "
            "than any material (steel 2.1e11): a subset that makes the body rigid (HAWC2's "
            "'stiff' subsets); a vibration audit needs the body flexible — select its "
            "flexible subset",
            line=cmd.line if cmd is not None else body.block.line,
            source=str(cmd.file if cmd is not None else body.block.file),
        )


def _tower(chain: _Chain) -> tuple[dict[str, Any], float, np.ndarray]:
    """The tower's distributed properties (every tower body stacked from the base), its
    height and the global position of its top."""
    heights, mass, ei_fa, ei_ss, gj, polar = [], [], [], [], [], []
    offset = 0.0
    for body in chain.tower:
        _flexible(body)
        st = body.st
        r = st[:, 0]
        if body.fpm:
            raise SpecError(
                f"body {body.name}: a fully populated st set for a tower is not read",
                line=body.block.line,
                source=str(body.block.file),
            )
        cols = {k: st[:, i] for i, k in enumerate(ST)}
        # a station repeated at a property step is kept, nudged (the tables may not repeat)
        h = r + offset
        heights += list(h)
        mass += list(cols["m"])
        ei_fa += list(cols["E"] * cols["I_x"])
        ei_ss += list(cols["E"] * cols["I_y"])
        gj += list(cols["G"] * cols["I_p"])
        polar += list(cols["m"] * (cols["ri_x"] ** 2 + cols["ri_y"] ** 2))
        offset += body.length
    h = np.array(heights)
    for i in range(1, len(h)):
        if h[i] <= h[i - 1]:
            h[i] = h[i - 1] + 1e-6 * max(h[-1], 1.0)
    top = chain.tower[-1].at("last")
    return (
        {
            "height_m": [float(v) for v in h],
            "mass_per_length_kg_m": mass,
            "ei_fa_nm2": ei_fa,
            "ei_ss_nm2": ei_ss,
            "gj_nm2": gj,
            "polar_inertia_kgm": polar,
        },
        float(offset),
        top,
    )


def _blade(chain: _Chain) -> tuple[dict[str, Any], np.ndarray, np.ndarray, float]:
    """Blade 1's table: span along its centre line, mass, flap and edge stiffness about the
    principal axes, the principal axes' twist in wtvib's sense, torsion."""
    body = chain.blades[0]
    _flexible(body)
    st = body.st
    c2 = body.c2
    z_c2 = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(c2[:, :3], axis=0), axis=1))])
    r = st[:, 0]
    if body.fpm:
        from .windio import _condensed, _shear

        k = _fpm_stiffness(st)
        flap, edge, tors, turned = _condensed(k)
        shear = _shear(k)  # K22's with K44 (flap), K11's with K55 (edge)
        # the matrices are in the axes turned by the pitch: a turn they still hold adds
        m, ri_x, ri_y, pitch = st[:, 1], st[:, 4], st[:, 5], st[:, 6] + turned
    else:
        cols = {name: st[:, i] for i, name in enumerate(ST)}
        flap = cols["E"] * cols["I_x"]
        edge = cols["E"] * cols["I_y"]
        tors = cols["G"] * cols["I_p"]
        # the shear deflecting along y goes with E·I_x (flapwise): k_y·G·A
        ga = cols["G"] * cols["A"]
        shear = (cols["k_y"] * ga, cols["k_x"] * ga)
        if not all(np.all(np.isfinite(g)) and np.all(g > 0) for g in shear):
            shear = None
        m, ri_x, ri_y, pitch = cols["m"], cols["ri_x"], cols["ri_y"], cols["pitch"]
    twist = np.interp(r, z_c2, c2[:, 3]) + pitch
    span = r - r[0]
    structure = {
        "span_m": [float(v) for v in span],
        "mass_per_length_kg_m": [float(v) for v in m],
        "ei_flap_nm2": [float(v) for v in flap],
        "ei_edge_nm2": [float(v) for v in edge],
        "twist_deg": [float(-v) for v in twist],  # HAWC2's sense about z, wtvib's to feather
        "gj_nm2": [float(v) for v in tors],
        "torsional_inertia_kgm": [float(v) for v in m * (ri_x**2 + ri_y**2)],
    }
    if shear is not None:  # HAWC2's beams are Timoshenko beams
        structure["ga_flap_n"] = [float(v) for v in shear[0]]
        structure["ga_edge_n"] = [float(v) for v in shear[1]]
    return structure, span, m, float(body.length)


def _mass_of(body: Body) -> float:
    st = body.st
    return float(np.trapezoid(st[:, 1], st[:, 0]))


def to_spec_data(path: Path, text: str) -> dict[str, Any]:
    """wtvib spec data from a HAWC2 htc file and the files it names."""
    top = htc.parse(path)
    root = htc.root_folder(path)
    chain, embedded, bodies = _model_chain(top, root, path)
    tower_table, tower_length, top_pos = _tower(chain)
    blade_structure, span, bmass, blade_length = _blade(chain)
    n_blades = len(chain.blades)
    aero = top.block("aero")
    if aero is not None and aero.get("nblades") is not None:
        n_blades = int(aero.need("nblades").number(0))
    hub_radius = chain.hubs[0].length
    apex = chain.shaft.at("last")
    # HAWC2's global frame: z down, y downwind; the tower top is the reference
    downwind = float(apex[1] - top_pos[1])
    above = float(top_pos[2] - apex[2])
    blade_mass = float(np.trapezoid(bmass, span))
    j_blades = n_blades * float(np.trapezoid(bmass * (hub_radius + span) ** 2, span))
    parts, hub_mass, inertias = _head_parts(chain, top_pos)
    drivetrain, drivetrain_note = _drivetrain(chain.shaft, j_blades, inertias)
    light = _light_generator(chain.shaft, inertias.generator, j_blades)
    parts.append(Part("blades", n_blades * blade_mass, downwind, above, j_blades / 2, j_blades,
                      j_blades / 2))  # fmt: skip
    speed, control, statement = _operation(top, root, path)
    data: dict[str, Any] = {
        "wtvib": 1,
        "turbine": {
            "name": path.stem,
            "rotor_diameter_m": round(2 * (hub_radius + blade_length), 6),
            "hub_height_m": round(float(-apex[2]), 6),
        },
        "rotor": {
            "blades": n_blades,
            "orientation": "upwind" if downwind < 0 else "downwind",
            "hub": "rigid",
            "speed": speed,
        },
        "tower": {
            "height_m": round(tower_length, 6),
            **_stiffness_damping(chain.tower[0]),
            "distributed": tower_table,
        },
        "tower_head": assembled(parts).as_head(),
        "blade": {
            "length_m": round(blade_length, 6),
            "mass_kg": round(blade_mass, 3),
            **_stiffness_damping(chain.blades[0]),
            "structure": {"hub_radius_m": round(hub_radius, 6), **blade_structure},
        },
        "drivetrain": drivetrain,
        "coupled": {
            "apex_downwind_m": round(downwind, 6),
            "apex_above_top_m": round(above, 6),
            "hub_mass_kg": hub_mass,
            "hub_inertia_kgm2": inertias.hub,
        },
        "assumptions": [
            *top.notes,
            *_assembly_notes(path, chain, downwind, above),
            statement,
            *([drivetrain_note] if drivetrain_note else []),
        ],
    }
    if light:
        data["warnings"] = [light]
    _support(data, top, root, (chain, embedded, bodies))
    aerodynamics = _aerodynamics(top, root, chain, control)
    if aerodynamics is not None:
        data["aerodynamics"] = aerodynamics
    out: dict[str, Any] = _plain(data)
    return out


def _support(
    data: dict[str, Any],
    top: Block,
    root: Path,
    model: tuple["_Chain", set[str], dict[str, Body]],
) -> None:
    """What the tower stands in or on, added to the spec's ``data``: the water a monopile
    moves (the hydro block), the floater (its platform block and notes), and the warnings
    of what of the support is not read."""
    chain, embedded, bodies = model
    added, hydro_left = _added_mass(top, chain)
    if added is not None:
        data["tower"]["added_mass"] = added
    soil = top.block("soil")
    elements = soil.each("soil_element") if soil is not None else []
    if chain.floater is None and len(elements) == 1:  # the pile on the model's own soil
        pile = _named(bodies, elements[0].need("mbdy_name"))
        if pile.fpm:
            raise SpecError(
                f"soil_element: the body {pile.name}'s st set is fully populated: wtvib stands "
                "a pile given by its classical st (E, I, A) on the soil",
                line=elements[0].line,
                source=str(elements[0].file),
            )
        foundation, note = pile_on_soil(elements[0], pile.st, pile.length, root)
        data["tower"]["foundation"] = foundation
        data["assumptions"].append(note)
        embedded = set()
    beside: list[str] = []
    if chain.floater is not None:
        structure = top.block("new_htc_structure")
        assert structure is not None
        block, notes = floating_platform(
            structure, chain.floater, bodies, chain.tower[0].at("1"), root
        )
        data["tower"]["foundation"] = {"kind": "platform", "platform": block}
        data["assumptions"] += notes
        beside = _beside_the_chain(chain, bodies, block)
        if hydro_left:  # the floater's members: WAMIT's is its added mass
            data["assumptions"].append(
                f"HAWC2's hydro elements on {', '.join(hydro_left)} (the floater's members: "
                "Morison's drag and inertia beside WAMIT's potential flow) are left out: the "
                "floater's added mass is WAMIT's, its viscous drag is not modelled."
            )
            hydro_left = []
    warnings = _support_warnings(embedded, hydro_left) + beside
    if warnings:
        data.setdefault("warnings", []).extend(warnings)


def _beside_the_chain(
    chain: "_Chain", bodies: dict[str, Body], platform: dict[str, Any]
) -> list[str]:
    """A floating model's bodies outside the turbine's chain (the floater's members, which
    HAWC2 models write massless, carrying its hydro elements: ESYSWamit's MASS is the
    floater's): where they carry mass, that mass is not in the platform — said."""
    used = {id(b) for b in (*chain.tower, *chain.head, chain.shaft, *chain.hubs, *chain.blades)}
    left = [b for b in bodies.values() if id(b) not in used]
    mass = sum(_mass_of(b) + sum(float(m[3]) for _, m in b.masses) for b in left)
    if not mass > 1e-3 * platform["mass_kg"]:
        return []
    names = ", ".join(b.name for b in left)
    return [
        f"tower.foundation: the model's bodies beside the turbine ({names}) carry "
        f"{mass:,.0f} kg that the floater's MASS ({platform['mass_kg']:,.0f} kg) does not: "
        "left out of the platform"
    ]


def _model_chain(top: Block, root: Path, path: Path) -> tuple["_Chain", set[str], dict[str, Body]]:
    """The model's main bodies recognised by their place in the chain, the bodies its soil
    block embeds, and every main body, placed by the orientation block."""
    structure = top.block("new_htc_structure")
    if structure is None:
        raise SpecError("no new_htc_structure block: not a HAWC2 turbine model", source=str(path))
    bodies = _bodies(structure, root)
    orientation = structure.block("orientation")
    if orientation is None:
        raise SpecError("no orientation block", line=structure.line, source=str(path))
    _place(bodies, orientation)
    soil = top.block("soil")
    elements = soil.each("soil_element") if soil else []
    embedded = {_named(bodies, e.need("mbdy_name")).name for e in elements}
    return _chain(bodies, structure, embedded), embedded, bodies


#: A shaft whose torsion would put the generator against the hub above this frequency [Hz]
#: is rigid: HAWC2 models write rigid bodies with moduli of 1e17 (the IEA-22's shaft), and
#: a drive-train mode at 10⁴ Hz is a number no turbine has.
RIGID_SHAFT_HZ = 1000.0


def _drivetrain(
    shaft: Body, j_blades: float, inertias: "_ShaftInertias"
) -> tuple[dict[str, Any], str | None]:
    """The drive train: the blades on a rigid hub, the shaft's torsion to the generator;
    and what the import made of a rigid shaft, of a generator partway along the shaft or of
    a shaft with no generator inertia."""
    hub_inertia, gen_inertia = inertias.hub, inertias.generator
    if not hub_inertia + gen_inertia > 0:
        raise SpecError(
            f"body {shaft.name}: no inertia about the shaft (no concentrated_mass with one): "
            "the hub and generator a drive train turns are missing",
            line=shaft.block.line,
            source=str(shaft.block.file),
        )
    blades = {"name": "blades", "inertia_kgm2": j_blades}
    note: str | None
    if gen_inertia <= 0 or hub_inertia <= 0:  # everything at one end: nothing to twist
        inertia = hub_inertia + gen_inertia
        note = (
            f"Drive train: the shaft {shaft.name} carries its inertia at one end only "
            f"({inertia:.4g} kg·m²): the blades against that inertia, no shaft torsion."
        )
        chain = [blades, {"name": "hub", "inertia_kgm2": inertia}]
        return {"chain": chain, "shafts": [{"stiffness_nm_rad": None}]}, note
    shaft_k = inertias.stiffness
    torsion_hz = math.sqrt(shaft_k * (1 / hub_inertia + 1 / gen_inertia)) / (2 * math.pi)
    rigid = torsion_hz > RIGID_SHAFT_HZ
    if rigid:
        note = (
            f"Drive train: the shaft {shaft.name} taken as rigid (G·I_p/L = {shaft_k:.3g} "
            f"N·m/rad would put the generator against the hub at {torsion_hz:.3g} Hz: a rigid "
            "body as HAWC2 models write one)."
        )
    elif inertias.partway:
        note = (
            f"Drive train: generator-side inertia sits partway along the shaft {shaft.name} "
            f"({inertias.partway} of its {shaft.length:.3g} m) and turns against the hub's "
            f"({hub_inertia:.4g} kg·m²) through the shaft between them: "
            f"{shaft_k:.3g} N·m/rad (∫dr/GJ from its place to the hub's end), "
            f"{torsion_hz:.3g} Hz."
        )
    else:
        note = None
    shafts = [
        {"stiffness_nm_rad": None},
        {"stiffness_nm_rad": None}
        if rigid
        else {"stiffness_nm_rad": shaft_k, "damping_nms_rad": shaft_k * shaft.damping[5]},
    ]
    chain = [
        blades,
        {"name": "hub", "inertia_kgm2": hub_inertia},
        {"name": "generator", "inertia_kgm2": gen_inertia},
    ]
    return {"chain": chain, "shafts": shafts}, note


#: A generator side lighter than this share of the blades' polar inertia is no generator a
#: turbine has (direct drives carry 0.6–2 %: the IEA-15's, IEA-10's, IEA-22's; a geared
#: generator on the low-speed shaft, its inertia times the ratio squared, 10–35 %).
LIGHT_GENERATOR = 1e-3


def _light_generator(shaft: Body, generator: float, j_blades: float) -> str | None:
    """A warning where the shaft's generator side is suspiciously light (HAWC2 models give
    a geared generator's inertia on the low-speed shaft: the DTU 10 MW's 'generator
    equivalent slow shaft', 3.751e6 kg·m²)."""
    if not 0 < generator < LIGHT_GENERATOR * j_blades:
        return None
    return (
        f"drivetrain: the generator side of the shaft {shaft.name} turns {generator:,.4g} "
        f"kg·m², {100 * generator / j_blades:.2g} % of the blades' {j_blades:,.3g} — a geared "
        "generator's inertia belongs on the low-speed shaft times the gear ratio squared; "
        "the drive train's modes are the model's as written"
    )


def _assembly_notes(path: Path, chain: "_Chain", downwind: float, above: float) -> list[str]:
    """What the import assembled, and from which bodies."""
    tilt = _tilt(chain.shaft)
    return [
        f"Imported from the HAWC2 model {path.name}: bodies "
        + ", ".join(b.name for b in (*chain.tower, *chain.head, chain.shaft))
        + f", {len(chain.hubs)} hubs and blades ({chain.blades[0].name}'s st set "
        f"{'fully populated (6×6, condensed)' if chain.blades[0].fpm else 'classical'}); "
        f"the tower ({', '.join(b.name for b in chain.tower)}) "
        f"{'on the floater' if chain.floater else 'clamped'} at {chain.tower[0].name}'s base; "
        "the rotor apex "
        f"{downwind:+.3g} m downwind of the tower top and {above:.3g} m above it; shaft "
        f"tilt {tilt:.3g}° and the blades' prebend and cone neglected.",
        "Tower head assembled from the bodies above the tower: their concentrated "
        "masses (nacelle, yaw system), the shaft's (hub mass, hub and generator inertia) "
        "and the blades at the apex.",
    ]


def _support_warnings(embedded: set[str], hydro_left: list[str]) -> list[str]:
    """What of the model's support is not read: its pile in the soil, hydro elements on
    bodies that are not the tower's."""
    warnings = []
    if embedded:
        warnings.append(
            f"tower.foundation: the model's pile in the soil ({', '.join(sorted(embedded))}, "
            "HAWC2's soil block) is not read: the tower is clamped at the mudline, so its "
            "bending frequencies are upper bounds"
        )
    if hydro_left:
        warnings.append(
            "tower.added_mass: HAWC2's hydro elements on "
            f"{', '.join(hydro_left)} (not the tower's bodies from the mudline up) are not read: "
            "the water they move is missing"
        )
    return warnings


#: HAWC2's water density where its water_properties give none [kg/m³].
WATER_DENSITY = 1027.0
#: The largest reference area a hydro section may give [m²]: a pile 40 m across (monopiles
#: are 6–12 m; a floater's column is no tower body).
MAX_WATER_AREA = 1300.0


def _added_mass(top: Block, chain: "_Chain") -> tuple[dict[str, Any] | None, list[str]]:
    """The water a submerged tower (monopile) moves in bending, from the hydro block: each
    hydro_element's sections (``sec z Cm Cd V Vr width``, z along its body from node 1) give
    ρ·Cm·Vr per length — Morison's added mass, Cm the added-mass coefficient and Vr its
    reference volume per length (HAWC2's hydro_element; DTU's windIO-to-HAWC2 converter
    writes Ca and πD²/4 there) — linear between sections, where the body is under the mean
    water level (``mwl``; HAWC2's z points down) and above the mudline; on the tower's
    bodies, at heights above its base. Returns the spec's ``tower.added_mass`` (None: no
    such water) and the bodies whose elements were left (not the tower's)."""
    hydro = top.block("hydro")
    if hydro is None:
        return None, []
    water = hydro.block("water_properties")

    def setting(key: str, default: float, low: float, high: float) -> float:
        cmd = water.get(key) if water is not None else None
        return default if cmd is None else cmd.within(0, low, high, f"water_properties {key}")

    rho = setting("rho", WATER_DENSITY, 500.0, 2000.0)  # kg/m³: water, fresh to brine
    mwl = setting("mwl", 0.0, -MAX_COORDINATE_M, MAX_COORDINATE_M)
    mud = setting("mudlevel", math.inf, -MAX_COORDINATE_M, MAX_COORDINATE_M)
    offsets, at = {}, 0.0
    for each in chain.tower:
        offsets[each.name] = at
        at += each.length
    heights: list[float] = []
    masses: list[float] = []
    left: list[str] = []
    for element in hydro.each("hydro_element"):
        name_cmd = element.get("mbdy_name") or element.need("body_name")  # HAWC2 reads both
        name = name_cmd.values[0].lower() if name_cmd.values else ""
        body: Body | None = next((b for b in chain.tower if b.name == name), None)
        if body is None:
            left.append(name or "an unnamed body")
            continue
        z, m = _sections(element, body, rho)
        wet = _submerged(z, np.array([float(_along(body, v)[2]) for v in z]), mwl, mud)
        heights += [offsets[name] + v for v in wet]
        masses += list(np.interp(wet, z, m))
    if len(heights) < 2:
        return None, left
    order = np.argsort(heights, kind="stable")
    h, m = np.asarray(heights)[order], np.asarray(masses)[order]
    keep = np.append(np.diff(h) > 0, True)  # one value per height (a section repeated)
    return {
        "height_m": [float(v) for v in h[keep]],
        "mass_per_length_kg_m": [float(v) for v in m[keep]],
        "source": (
            "HAWC2's hydro block: ρ·Cm·Vr of each hydro_element section below the mean water "
            f"level (ρ = {rho:g} kg/m³, Morison's added mass)"
        ),
    }, left


def _sections(element: Block, body: Body, rho: float) -> tuple[np.ndarray, np.ndarray]:
    """A hydro_element's sections along its body (z from node 1, rising) and ρ·Cm·Vr at
    each [kg/m]."""
    rows = []
    for sec in element.all("sec"):
        z, cm, vr = sec.number(0), sec.number(1), sec.number(4)
        if not (0 <= z <= body.length * 1.001 and 0 <= cm <= 10 and 0 <= vr <= MAX_WATER_AREA):
            raise SpecError(
                f"hydro_element {body.name}: sec {z:g} {cm:g} … {vr:g}: z must lie on the "
                f"body (0 to {body.length:.4g} m), Cm from 0 to 10 and Vr from 0 to "
                f"{MAX_WATER_AREA:g} m²",
                line=sec.line,
                source=str(sec.file),
            )
        rows.append((z, rho * cm * vr))
    if len(rows) < 2 or any(b[0] <= a[0] for a, b in itertools.pairwise(rows)):
        raise SpecError(
            f"hydro_element {body.name}: its sections must be two or more, at rising z",
            line=element.line,
            source=str(element.file),
        )
    table = np.array(rows)
    return table[:, 0], table[:, 1]


def _submerged(z: np.ndarray, depth: np.ndarray, mwl: float, mud: float) -> list[float]:
    """The positions along a body (its sections' ``z`` and where, linear between them, its
    global ``depth`` — HAWC2's z, down — crosses the water level or the mudline) that lie in
    the water: mwl ≤ depth ≤ mud."""
    points = list(z)
    for a, b, da, db in zip(z, z[1:], depth, depth[1:], strict=False):
        for level in (mwl, mud):
            if math.isfinite(level) and (da - level) * (db - level) < 0:
                points.append(a + (b - a) * (level - da) / (db - da))
    at = np.sort(np.asarray(points))
    wet = np.interp(at, z, depth)
    tol = 1e-9 * max(1.0, float(np.max(np.abs(depth))))
    return [float(v) for v, d in zip(at, wet, strict=True) if mwl - tol <= d <= mud + tol]


def _along(body: Body, distance: float) -> np.ndarray:
    """The global position of the point ``distance`` along a body's centre line from its
    first node."""
    steps = np.linalg.norm(np.diff(body.c2[:, :3], axis=0), axis=1)
    s = np.concatenate([[0.0], np.cumsum(steps)])
    local = np.array([np.interp(distance, s, body.c2[:, k]) for k in range(3)])
    return np.asarray(body.origin + body.frame @ local)


def _plain(value: Any) -> Any:
    """The data with numpy's numbers as Python's (the spec and ``convert``'s YAML take
    those), every number to ten digits."""
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, (np.floating, float)):
        return float(f"{float(value):.10g}")
    if isinstance(value, np.integer):
        return int(value)
    return value


@dataclass(frozen=True)
class _ShaftInertias:
    """The polar inertias a shaft carries, parted into the hub's (rigidly joined to the
    shaft's last node, where the hubs sit) and the generator side's, and the shaft's
    torsional stiffness between them [N·m/rad]; ``partway`` says where a generator-side
    inertia nearer the hub's end than the other sits (empty where none does)."""

    hub: float
    generator: float
    stiffness: float
    partway: str


def _head_parts(chain: _Chain, top: np.ndarray) -> tuple[list[Part], float, _ShaftInertias]:
    """The tower head's parts (downwind x, up z from the tower top): every concentrated
    mass on the bodies above the tower and on the shaft; the hub's mass and the shaft's
    inertias about its axis (:class:`_ShaftInertias`): the hub's are the shaft's masses
    nearer its last node and rigidly joined to it (a torsion on the shaft between them
    above :data:`RIGID_SHAFT_HZ`), the generator's the others — the IEA-15's massless
    generator inertia at the shaft's first node, the IEA-22's generator rotor, bearings and
    brake along its rigid shaft, the IEA-10's generator rotor partway along its flexible
    one — each placed along the shaft by its offset; the shaft's stiffness is the
    generator side's inertia over Σ J·c, c each inertia's torsional compliance to the hub's
    end (exact for one generator inertia)."""
    parts: list[Part] = []
    shaft = chain.shaft
    hub_mass = hub_inertia = gen_inertia = weighted = 0.0
    partway: list[str] = []
    hub_end, far_end = shaft.at("last"), shaft.at("1")
    for body in (*chain.head, shaft):
        for node, (x, y, z, m, ixx, iyy, izz) in body.masses:
            local = body.node(str(node)) + np.array([x, y, z])
            pos = body.origin + body.frame @ local
            spin = izz  # about the body's z: the shaft's axis on the shaft
            if body is shaft:
                along = _place_on(shaft, local)
                compliance = _compliance(shaft, along)
                near = np.linalg.norm(pos - hub_end) <= np.linalg.norm(pos - far_end)
                if near and compliance * izz * (2 * math.pi * RIGID_SHAFT_HZ) ** 2 <= 1.0:
                    hub_mass += m
                    hub_inertia += izz
                else:  # the drive train turns it: its spin is not the head's (roll)
                    gen_inertia += izz
                    weighted += izz * compliance
                    spin = 0.0
                    if near and izz > 0:
                        partway.append(f"{izz:.4g} kg·m² at {along:.3g} m")
            inertia = body.frame @ np.diag([ixx, iyy, spin]) @ body.frame.T
            parts.append(
                Part(
                    f"{body.name} mass at node {node}",
                    max(m, 1e-9),
                    float(pos[1] - top[1]),
                    float(top[2] - pos[2]),
                    pitch=float(inertia[0, 0]),  # about the lateral x axis
                    roll=float(inertia[1, 1]),  # about the downwind axis
                    yaw=float(inertia[2, 2]),
                )
            )
        m_body = _mass_of(body)
        mid = body.origin + body.frame @ body.c2[len(body.c2) // 2, :3]
        parts.append(Part(body.name, max(m_body, 1e-9), float(mid[1] - top[1]),
                          float(top[2] - mid[2])))  # fmt: skip
    hub_body_mass = sum(_mass_of(h) for h in chain.hubs)
    hub_mass += hub_body_mass
    stiffness = gen_inertia / weighted if weighted > 0 else math.inf
    return parts, hub_mass, _ShaftInertias(hub_inertia, gen_inertia, stiffness, ", ".join(partway))


def _place_on(shaft: Body, local: np.ndarray) -> float:
    """A point's place along a straight shaft from its first node [m] (body coordinates),
    within the shaft."""
    start, end = shaft.c2[0, :3], shaft.c2[-1, :3]
    axis = end - start
    length = float(np.linalg.norm(axis))
    if length <= 0:
        return 0.0
    return float(np.clip(np.dot(local - start, axis) / length, 0.0, length))


def _tilt(shaft: Body) -> float:
    axis = shaft.frame @ np.array([0.0, 0.0, 1.0])
    return math.degrees(math.asin(min(1.0, abs(axis[2]) / max(np.linalg.norm(axis), 1e-12))))


def _compliance(shaft: Body, start: float) -> float:
    """The shaft's torsional compliance from ``start`` [m along it] to its last node,
    ∫ dr/GJ [rad/(N·m)], GJ (G·I_p of its st set) linear in r between the st's rows as HAWC2
    interpolates them — exact on each interval (its length over the logarithmic mean of GJ
    at its ends)."""
    st = shaft.st
    gj = st[:, 9] * st[:, 12] if not shaft.fpm else st[:, 29]
    length = shaft.length
    if length <= 0 or np.any(gj <= 0):
        raise SpecError(
            f"body {shaft.name}: no torsional stiffness (G·I_p) to make a drive train of",
            line=shaft.block.line,
            source=str(shaft.block.file),
        )
    r = np.asarray(st[:, 0], float)
    grid = np.unique(np.clip(np.concatenate([r, [start, length]]), start, length))
    g = np.interp(grid, r, gj)
    lo, hi = g[:-1], g[1:]
    log_ratio = np.log(hi / lo)
    flat = np.abs(log_ratio) < 1e-9
    mean = np.where(flat, 0.5 * (lo + hi), (hi - lo) / np.where(flat, 1.0, log_ratio))
    return float(np.sum(np.diff(grid) / mean))


#: A main body's damping commands, each with Mx My Mz Kx Ky Kz (the first given is read).
DAMPING = ("damping_posdef", "damping_aniso", "damping_aniso_v2")


def _stiffness_damping(body: Body) -> dict[str, Any]:
    """A body's K coefficients as wtvib's (fore-aft or flapwise, side-side or edgewise,
    torsion). damping_posdef and damping_aniso_v2 damp the deflection along the body's x
    and y — x the blade's chord (edgewise), the tower's lateral (side-side) — damping_aniso
    the bending about them (x: flapwise, fore-aft). Measured on the models: HAWCStab2's
    DTU 10 MW blade (damping_posdef Kx 1.53e-3, Ky 2.55e-3) damps its first flap mode at
    ζ = π·2.53e-3·f and its first edge mode at π·1.62e-3·f; the IEA-15's damping_aniso
    (3.038e-3, 2.167e-3) gives its flap and edge modes its note's 3 % logarithmic decrement
    with Kx flapwise, the IEA-22's damping_aniso_v2 (2.846e-3, 4.251e-3) its note's 0.5 %
    with Kx edgewise (tests/validation/test_hawc2.py, tests/test_hawc2.py)."""
    _, _, _, kx, ky, kz = (list(body.damping) + [0.0] * 6)[:6]
    if kx <= 0 and ky <= 0:
        return {}
    first, second = (kx, ky) if body.damping_by == "damping_aniso" else (ky, kx)
    return {"stiffness_damping_s": {"bending_1": first, "bending_2": second, "torsion": kz}}


def _operational_data(top: Block, root: Path) -> tuple[Path, np.ndarray, str] | None:
    """The model's operational data file and its rows where the rotor turns (wind order):
    the one its ``hawcstab2`` block names (``operational_data_filename``), else the one
    ``.opt`` in its ``data/`` folder whose rotor turns — the first by name of several, said.
    None where neither gives a turning rotor (a wind-only file: HAWCStab2's winds for a
    controller to find the speeds)."""
    hs2 = top.block("hawcstab2")
    named = hs2.get("operational_data_filename") if hs2 is not None else None
    if named is not None and named.values:
        path = htc.resolve(named.text(0), root, named.file.parent, named)
        table = _turning(htc.read_opt(path))
        how = f"named by the htc's hawcstab2 block (line {named.line})"
        return (path, table, how) if len(table) else None
    found = sorted((root / "data").glob("*.opt")) if (root / "data").is_dir() else []
    usable = [(p, t) for p in found if len(t := _turning(htc.read_opt(p)))]
    if not usable:
        return None
    path, table = usable[0]
    others = [p.name for p in found if p != path]
    how = (
        "the one in data/"
        if not others
        else (
            f"the first by name of the model's data/ folder, which holds {', '.join(others)} "
            "too (the htc names none: a hawcstab2 block's operational_data_filename would)"
        )
    )
    return path, table, how


def _turning(table: np.ndarray) -> np.ndarray:
    """The rows of an operational data table where the rotor turns, in wind order."""
    table = table[np.argsort(table[:, 0], kind="stable")]
    return table[table[:, 2] > 0]


def _operation(top: Block, root: Path, path: Path) -> tuple[dict[str, Any], dict[str, Any], str]:
    """The operating range and control: the model's operational data file
    (:func:`_operational_data`), else the DTU Wind Energy controller's constants."""
    constants = _controller(top)
    opt = _operational_data(top, root)
    control: dict[str, Any] = {"regulation": "pitch"}
    if 1 in constants:
        control["rated_power_kw"] = constants[1].number(1)
    if opt is not None:
        opt_path, table, how = opt
        rpm = table[:, 2]
        speed = {"min_rpm": round(float(rpm.min()), 6), "max_rpm": round(float(rpm.max()), 6),
                 "source": f"{opt_path.name} (operating points)"}  # fmt: skip
        control["cut_in_wind_m_s"] = float(max(table[0, 0], 1.0))
        control["cut_out_wind_m_s"] = float(table[-1, 0])
        control["fine_pitch_deg"] = float(table[:, 1].min())
        # the model's own points, one per wind (the first of a repeated wind)
        turning = table[table[:, 0] > 0]
        turning = turning[np.r_[True, np.diff(turning[:, 0]) > 0]]
        if len(turning) >= 2:
            control["operating_points"] = {
                "wind_m_s": [float(v) for v in turning[:, 0]],
                "rpm": [float(v) for v in turning[:, 2]],
                "pitch_deg": [float(v) for v in turning[:, 1]],
                "source": opt_path.name,
            }
        return (
            speed,
            control,
            f"Operating range from {opt_path.name} ({how}): {rpm.min():.4g}–{rpm.max():.4g} "
            "rpm where its rotor turns.",
        )
    if 2 in constants and 3 in constants:
        low = constants[2]
        lo, hi = dtu_speeds(low.number(1), constants[3].number(1), low.line, str(low.file))
        source = "the DTU Wind Energy controller's constants 2 and 3 (rad/s)"
        speed = {"min_rpm": round(lo, 6), "max_rpm": round(hi, 6), "source": source}
        if 49 in constants and constants[49].number(1) > 0:
            control["tip_speed_ratio"] = constants[49].number(1)
        return (
            speed,
            control,
            f"Operating range {lo:.4g}–{hi:.4g} rpm from the controller's constants (no "
            "operational data file where the rotor turns).",
        )
    raise SpecError(
        "no operating range: the model has no operational data where its rotor turns (an "
        ".opt its hawcstab2 block names, or one in data/) and no DTU Wind Energy controller "
        "with its minimum and rated speed; give --rpm MIN:MAX",
        source=str(path),
    )


#: The DTU Wind Energy controller, by its type2_dll's name or file: named
#: ``dtu_we_controller`` since 2015, ``risoe_controller`` before (the same init constants:
#: 1 rated power [kW], 2 minimum and 3 rated rotor speed [rad/s]; DTU 10 MW RWT v1 htc).
DTU_CONTROLLER = ("dtu_we_controller", "risoe_controller")


def _controller(top: Block) -> dict[int, Command]:
    """The DTU Wind Energy controller's init constants, by number (empty: no such
    controller)."""
    dll = top.block("dll")
    if dll is None:
        return {}
    for t2 in dll.each("type2_dll"):
        said = " ".join(" ".join(c.values) for c in (t2.get("name"), t2.get("filename")) if c)
        if any(known in said.lower() for known in DTU_CONTROLLER):
            init = t2.block("init")
            if init is None:
                return {}
            given = [c for c in init.all("constant") if len(c.values) >= 2]
            for c in given:
                c.number(1)  # each a number, read or not (a load-case template's tag refused)
            return {int(c.number(0)): c for c in given}
    return {}


def _aerodynamics(
    top: Block, root: Path, chain: _Chain, control: dict[str, Any]
) -> dict[str, Any] | None:
    aero = top.block("aero")
    if aero is None:
        return None
    ae_cmd, pc_cmd = aero.get("ae_filename"), aero.get("pc_filename")
    if ae_cmd is None or pc_cmd is None:
        return None
    ae_sets = aero.get("ae_sets")
    set_no = int(ae_sets.number(0)) if ae_sets is not None else 1
    ae = htc.read_ae(htc.resolve(ae_cmd.text(0), root, ae_cmd.file.parent, ae_cmd), set_no)
    profiles = htc.read_pc(htc.resolve(pc_cmd.text(0), root, pc_cmd.file.parent, pc_cmd))
    body = chain.blades[0]
    c2 = body.c2
    z_c2 = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(c2[:, :3], axis=0), axis=1))])
    hub_r = chain.hubs[0].length
    r = np.minimum(ae[:, 0], float(z_c2[-1]))  # ae radii along the centre line, within it
    keep = np.r_[True, np.diff(r) > 1e-9]
    r, chord, thick = r[keep], ae[keep, 1], ae[keep, 2]
    radius = hub_r + r
    radius[0] = max(radius[0], 1e-3)
    twist = -np.interp(r, z_c2, c2[:, 3])
    airfoils, names = _blended(profiles, thick)
    centre = _shear_centre(body, r, chord)
    wind = top.block("wind")
    density = wind.get("density") if wind is not None else None
    stall = aero.get("dynstall_method")
    method = int(stall.number(0)) if stall is not None else 0
    if method in SEPARATION_TIME:
        for polar in airfoils.values():
            polar["separation_time"] = SEPARATION_TIME[method]
    tip = aero.get("tiploss_method")
    return {
        "air_density_kg_m3": density.number(0) if density is not None else 1.225,
        # the shed wake lags the lift in HAWC2's Beddoes–Leishman-type MHH model (2), not in
        # Øye's (1) or without dynamic stall (0); both lag the separation point
        "shed_wake": method >= 2,
        "dynamic_stall": method in SEPARATION_TIME,
        "tip_loss": tip is None or tip.number(0) > 0,
        "stations": {
            "radius_m": [float(v) for v in radius],
            "chord_m": [float(max(v, 1e-3)) for v in chord],
            "twist_deg": [float(v) for v in twist],
            "airfoil": names,
            "shear_centre_chord": centre,
        },
        "airfoils": airfoils,
        "control": control,
    }


def _shear_centre(body: Body, r: np.ndarray, chord: np.ndarray) -> list[float]:
    """Each aerodynamic station's shear centre as a fraction of its chord from the leading
    edge: the classical st set's x_sh from the half-chord line c2_def, along the chord (a
    fully populated set's from its stiffness matrix: :func:`_fpm_shear_centre`). HAWC2's
    blade x axis points in the direction of rotation, towards the leading edge: y is downwind
    (the IEA blades' upwind prebend is negative y) and z towards the tip, so x = y × z points
    ahead of a blade of a rotor turning clockwise seen from upwind, as HAWC2's turn. The IEA 15 MW's
    st file agrees: over its outer half its shear centres lie 0.14–0.26 chords ahead of the
    half chord (at 24–37 % of the chord, near the quarter chord as a blade's are; the other
    way round they would lie at 63–76 % and the blade diverge in torsion at rated)."""
    st = body.st
    x_sh = _fpm_shear_centre(st) if body.fpm else st[:, ST.index("x_sh")]
    ahead = np.interp(r, st[:, 0] - st[0, 0], x_sh)
    return [float(v) for v in np.clip(0.5 - ahead / chord, -0.5, 1.5)]


def _fpm_shear_centre(st: np.ndarray) -> np.ndarray:
    """A fully populated st set's shear centres, x from the half-chord line as a classical
    set's x_sh [m]. Its 6×6 stiffness is given at the elastic centre (x_e, y_e) in axes turned
    by the structural pitch; the shear centre is where a shear force twists the section not
    at all — with the compliance C = K⁻¹ (shear x, y, axial, bending x, y, torsion),
    (−C₅₁/C₅₅, C₅₀/C₅₅) in those axes (zero-based) — turned back and moved to the half-chord
    line (a section whose matrix cannot be inverted: its elastic centre). The IEA-15's FPM
    and classical st files of the same blade give the same x_sh at every station to 2e-11 m
    (tests/test_hawc2.py)."""
    k = _fpm_stiffness(st)
    xs, ys = np.zeros(len(st)), np.zeros(len(st))
    for i, mat in enumerate(k):  # a section whose matrix has no inverse: its elastic centre
        try:
            c = np.linalg.inv(mat)
        except np.linalg.LinAlgError:
            continue
        if np.all(np.isfinite(c)) and c[5, 5] > 0:
            xs[i], ys[i] = -c[5, 1] / c[5, 5], c[5, 0] / c[5, 5]
    pitch = np.radians(st[:, FPM_HEAD.index("pitch")])
    return np.asarray(st[:, FPM_HEAD.index("x_e")] + np.cos(pitch) * xs - np.sin(pitch) * ys)


def _fpm_stiffness(st: np.ndarray) -> np.ndarray:
    """A fully populated st set's 6×6 stiffness matrices, (rows, 6, 6), from their upper
    triangles K11 … K66 (columns 9–29)."""
    k = np.zeros((len(st), 6, 6))
    iu = np.triu_indices(6)
    k[:, iu[0], iu[1]] = st[:, 9:30]
    k[:, iu[1], iu[0]] = st[:, 9:30]
    return k


#: The separation point's time constant [half-chord transits] of HAWC2's dynamic stall
#: models (``dynstall_method``): MHH (2) T_f0 + T_p0 = 6 + 1.5 (Hansen, Gaunaa & Madsen
#: 2004, the constants HAWC2 uses — welib's MHH implementation, "HAWC2" constants), and
#: ATEFlap (3), MHH's model with trailing-edge flaps, alike; Øye (1) 6 (the value Øye's
#: model is usually run with: AeroDyn theory manual, "Oye model").
SEPARATION_TIME = {1: 6.0, 2: 7.5, 3: 7.5}


def _blended(
    profiles: list[tuple[float, np.ndarray]], thickness: np.ndarray
) -> tuple[dict[str, Any], list[str]]:
    """One polar per station, interpolated in relative thickness between the pc set's two
    profiles that bracket it (as HAWC2 does), on the thinner profile's angles."""
    thick = np.array([t for t, _ in profiles])
    order = np.argsort(thick)
    thick = thick[order]
    tables = [profiles[i][1] for i in order]
    grid = np.linspace(-180.0, 180.0, 361)
    cl = np.array([np.interp(grid, t[:, 0], t[:, 1]) for t in tables])
    cd = np.array([np.interp(grid, t[:, 0], t[:, 2]) for t in tables])
    cm = np.array([np.interp(grid, t[:, 0], t[:, 3]) for t in tables])
    airfoils: dict[str, Any] = {}
    names = []
    for t in thickness:
        t = float(np.clip(t, thick[0], thick[-1]))
        name = f"t{t:.2f}"
        if name not in airfoils:
            j = (
                int(np.clip(np.searchsorted(thick, t) - 1, 0, len(thick) - 2))
                if len(thick) > 1
                else 0
            )
            if len(thick) == 1:
                c_l, c_d, c_m = cl[0], cd[0], cm[0]
            else:
                w = (t - thick[j]) / (thick[j + 1] - thick[j]) if thick[j + 1] > thick[j] else 0.0
                c_l = (1 - w) * cl[j] + w * cl[j + 1]
                c_d = (1 - w) * cd[j] + w * cd[j + 1]
                c_m = (1 - w) * cm[j] + w * cm[j + 1]
            airfoils[name] = {
                "alpha_deg": [float(a) for a in grid],
                "cl": [float(v) for v in c_l],
                "cd": [float(max(v, 0.0)) for v in c_d],
                "cm": [float(v) for v in c_m],
            }
        names.append(name)
    return airfoils, names
