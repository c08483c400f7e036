"""An OpenFAST deck set's monopile: SubDyn's pile under the ElastoDyn tower, HydroDyn's
water moving with it.

SubDyn (``CompSub`` = 1) describes the substructure as joints, members between them,
circular cross-sections (E, G, ρ, D, t at each member end, linear between), concentrated
masses at joints, reaction joints (locked DOFs, or an SSI file of coupled springs) and the
interface joint locked to the transition piece at ElastoDyn's ``TowerBsHt``. A monopile is
one vertical chain of circular beam members from one reaction joint to the interface
joint: it becomes the tower's lower part (thin-walled tube: A = π/4·(D² − d²),
I = π/64·(D⁴ − d⁴), J = 2I, d = D − 2t), so the tower's base is the reaction joint.
Anything else (a jacket, a tripod, cables, rigid links) is not a monopile: the tower is
then clamped at the transition piece, said.

The SSI file of a reaction joint gives the 6×6 pile-head stiffness as named entries
(``Kxx``, ``Kxty``, ``Ktyty``, …, in any order): the fore-aft plane's lateral Kxx, rocking
Ktyty and coupling Kxty (x and θy: a positive θy tilts the pile toward +x, so Kxty is the
coupling of (w, w′)) and the torsional Ktztz become the foundation's springs.

HydroDyn's Morison members (strip theory: PropPot False) on the pile's axis give the
hydrodynamic added mass Ca·ρ_w·π(D + 2t_MG)²/4 per length below the still-water level
(Ca of the member's coefficient model: simple, depth-based or member-based), the water of
filled members ρ_fill·π(D − 2t)²/4 below their free surface, and marine growth
ρ_MG·π((D + 2t_MG)² − D²)/4: they move with the pile in bending (``tower.added_mass``).

OpenFAST SubDyn and HydroDyn input-file documentation (user guide, "Input Files").
"""

import itertools
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import SpecError
from ..spec import read_text
from .deck import (
    WATER_DENSITY,
    Deck,
    Table,
    _file,
    beside,
    counted,
    environment,
    parse,
    sea_setting,
    sea_state,
)

#: Joints closer than this [m] (horizontally) lie on one vertical axis.
AXIS_TOLERANCE_M = 0.01
#: A property step between two members is tabulated this far [m] below their joint.
STEP_M = 1e-3


@dataclass
class Monopile:
    """The pile under the tower: stations from the reaction joint (z up, MSL 0) to the
    interface joint, and what it stands on."""

    z: np.ndarray
    mass: np.ndarray  # kg/m
    ei: np.ndarray  # N·m²
    gj: np.ndarray  # N·m²
    polar: np.ndarray  # kg·m (ρJ)
    point_masses: list[tuple[float, float]]  # (z, kg)
    foundation: dict[str, Any]
    axis: tuple[float, float]  # the pile's x, y
    notes: list[str] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)

    @property
    def base(self) -> float:
        return float(self.z[0])


def monopile(fst: Deck, interface_z: float) -> Monopile | str:
    """The SubDyn monopile of a deck set, or why it is not one (a sentence for the
    report's warning)."""
    sd = parse(_file(fst, "SubFile"))
    text = read_text(sd.path, ansi=True)
    joints = counted(sd, text, ("NJoints",), "JointZss")
    members = counted(sd, text, ("NMembers",), "MJointID1")
    props = counted(sd, text, ("NPropSets", "NPropSetsCyl"), "XsecD")
    react = counted(sd, text, ("NReact",), "RJointID")
    interf = counted(sd, text, ("NInterf",), "IJointID")
    if joints is None or members is None or props is None or react is None or interf is None:
        missing = [
            name
            for name, t in (
                ("NJoints", joints),
                ("NMembers", members),
                ("NPropSets (circular sections)", props),
                ("NReact", react),
                ("NInterf", interf),
            )
            if t is None
        ]
        raise SpecError(
            f"SubDyn file of an unknown layout: no {', '.join(missing)} table",
            source=str(sd.path),
        )
    ids = joints.ids("JointID")
    xyz = {
        j: (x, y, z)
        for j, x, y, z in zip(
            ids,
            joints.numbers("JointXss"),
            joints.numbers("JointYss"),
            joints.numbers("JointZss"),
            strict=True,
        )
    }
    spread = len(react.rows) > 1 and _along_the_pile(sd, react, xyz)
    if len(interf.rows) != 1 or (len(react.rows) != 1 and not spread):
        return (
            f"its SubDyn substructure has {len(react.rows)} reaction and {len(interf.rows)} "
            "interface joints — not a monopile"
            + (" (nor one on springs along it: each reaction joint free, with an SSI file)"
               if len(react.rows) > 1 else "")
        )  # fmt: skip
    base = min(react.ids("RJointID"), key=lambda j: xyz[j][2])
    chain = _chain(members, base, interf.ids("IJointID")[0], xyz)
    if isinstance(chain, str):
        return chain
    sections = _sections(props)
    z, mass, ei, gj, polar = _stations(chain, members, sections, xyz, sd)
    if spread:
        return _on_springs(sd, text, react, (z, mass, ei, gj, polar), xyz, interface_z)
    top = z[-1]
    notes = [
        f"Monopile from SubDyn ({sd.path.name}): {len(chain)} circular members from the "
        f"reaction joint at z = {z[0]:g} m to the interface joint at z = {top:g} m, under the "
        "ElastoDyn tower (thin-walled tubes, E, G and ρ of each section)."
    ]
    warnings = _joined(top, interface_z)
    point_masses = _point_masses(sd, text, xyz, notes)
    foundation = _reaction(sd, react, notes)
    x0, y0, _ = xyz[react.ids("RJointID")[0]]
    return Monopile(z, mass, ei, gj, polar, point_masses, foundation, (x0, y0), notes, warnings)


def _along_the_pile(sd: Deck, react: Table, xyz: dict[int, tuple[float, float, float]]) -> bool:
    """Whether several reaction joints are springs along one vertical pile (OWI-Lab's
    FOOS IEA-10: one per 0.5 m of its embedded length, each free with an SSI file): every
    one on one axis, every DOF free, every one with an SSI file."""
    flags = ("RctTDXss", "RctTDYss", "RctTDZss", "RctRDXss", "RctRDYss", "RctRDZss")
    if not react.has("SSIfile") or not all(react.has(f) for f in flags):
        return False
    ids = react.ids("RJointID")
    if any(j not in xyz for j in ids):
        return False
    x0, y0, _ = xyz[ids[0]]
    free = all(all(v == 0 for v in react.numbers(f)) for f in flags)
    files = all(t.lower() not in ("", "none", "unused") for t in react.texts("SSIfile"))
    axis = all(math.hypot(xyz[j][0] - x0, xyz[j][1] - y0) <= AXIS_TOLERANCE_M for j in ids)
    return free and files and axis


def _chain(
    members: Table, base: int, top: int, xyz: dict[int, tuple[float, float, float]]
) -> list[int] | str:
    """Member rows from the reaction joint up to the interface joint, one after another
    on one vertical axis — or why the substructure is not that."""
    first, second = members.ids("MJointID1"), members.ids("MJointID2")
    kinds = members.texts("MType") if members.has("MType") else ["1"] * len(first)
    for j in (*first, *second):
        if j not in xyz:
            raise SpecError(
                f"a member names joint {j}, which the joint table does not have",
                line=members.lines[(first + second).index(j) % len(first)],
                source=str(members.path),
            )
    if any(k.lower() not in ("1", "1c") for k in kinds):
        return "its SubDyn substructure has cables, rigid links or non-circular beams"
    if len(set(first) | set(second)) != len(first) + 1:
        return (
            f"its SubDyn substructure's {len(first)} members do not form one chain "
            "(a jacket or tripod, not a monopile)"
        )
    order, at = [], base
    left = set(range(len(first)))
    while at != top and left:
        step = next((i for i in left if at in (first[i], second[i])), None)
        if step is None:
            return "its SubDyn members do not lead from the reaction joint to the interface joint"
        left.remove(step)
        order.append(step)
        at = second[step] if first[step] == at else first[step]
    if at != top or left:
        return "its SubDyn members do not lead from the reaction joint to the interface joint"
    x0, y0, _ = xyz[base]
    for i in order:
        for j in (first[i], second[i]):
            if math.hypot(xyz[j][0] - x0, xyz[j][1] - y0) > AXIS_TOLERANCE_M:
                return "its SubDyn substructure is not vertical (a member leaves the pile's axis)"
    heights = [xyz[base][2]] + [
        xyz[second[i] if xyz[second[i]][2] > xyz[first[i]][2] else first[i]][2] for i in order
    ]
    if any(b <= a for a, b in itertools.pairwise(heights)):
        return "its SubDyn monopile does not rise from the reaction joint to the interface joint"
    return order


def _joined(top: float, interface_z: float) -> list[str]:
    """The warning where SubDyn's interface joint is not at ElastoDyn's TowerBsHt."""
    if abs(top - interface_z) <= 0.01:
        return []
    return [
        f"tower.foundation: SubDyn's interface joint is at z = {top:g} m but ElastoDyn's "
        f"TowerBsHt is {interface_z:g} m: the pile is joined to the tower at TowerBsHt"
    ]


def _on_springs(
    sd: Deck,
    text: str,
    react: Table,
    stations: tuple[np.ndarray, ...],
    xyz: dict[int, tuple[float, float, float]],
    interface_z: float,
) -> "Monopile":
    """A pile on springs along its embedded length (a reaction joint with its SSI file
    at every spring): above the highest spring — the mudline — the pile is the tower's
    lower part; below it, a beam on the springs, statically condensed to the mudline's
    lateral, rocking and coupling stiffness (each plane's fore-aft springs) and torsion.
    Its mass below the mudline is left out (the condensation is static), said."""
    z, mass, ei, gj, polar = stations
    ids = sorted(react.ids("RJointID"), key=lambda j: xyz[j][2])
    paths = dict(zip(react.ids("RJointID"), react.texts("SSIfile"), strict=True))
    at = np.array([xyz[j][2] for j in ids])
    on_pile = set(np.round(z, 6))
    springs = []
    for j in ids:
        line = react.lines[react.ids("RJointID").index(j)]
        if round(xyz[j][2], 6) not in on_pile:
            raise SpecError(f"reaction joint {j} is on no member of the pile", line=line,
                            source=str(sd.path))  # fmt: skip
        path = beside(sd.path, paths[j])
        if not path.is_file():
            raise SpecError(f"SSIfile names {paths[j]!r}, which does not exist", line=line,
                            source=str(sd.path))  # fmt: skip
        springs.append(_springs(parse(path)))
    k = np.array(springs)
    mudline = float(at[-1])
    head, guyan = _condensed(at, stations, k, sd.path)
    keep = z >= mudline - 1e-9
    notes = [
        f"Monopile from SubDyn ({sd.path.name}): the pile from the mudline (its highest "
        f"spring, z = {mudline:g} m) to the interface joint at z = {z[-1]:g} m, under the "
        "ElastoDyn tower (thin-walled tubes, E, G and ρ of each section).",
        f"The pile below the mudline ({mudline - at[0]:.3g} m, to z = {at[0]:g} m) stands on "
        f"the SSI files' springs at its {len(ids)} reaction joints (their Kxx, Ktyty, Kxty "
        "and Ktztz, the fore-aft plane's in both), condensed statically to the mudline: "
        f"lateral {head[0]:.4g} N/m, rocking {head[1]:.4g} N·m/rad, coupling {head[2]:.4g} "
        f"N, torsion {head[3]:.4g} N·m/rad; its mass below the mudline "
        f"({float(np.trapezoid(mass[~keep], z[~keep])):,.0f} kg, of which the springs' "
        f"static shape carries {guyan:,.0f} kg to the mudline) is left out.",
    ]
    warnings = _joined(float(z[-1]), interface_z)
    masses = [(h, m) for h, m in _point_masses(sd, text, xyz, notes) if h >= mudline - 1e-9]
    foundation: dict[str, Any] = {"kind": "springs", "lateral_n_m": head[0],
                                  "rocking_nm_rad": head[1], "coupling_n": head[2]}  # fmt: skip
    if head[3] > 0:
        foundation["torsional_nm_rad"] = head[3]
    x0, y0, _ = xyz[ids[0]]
    cut = (z[keep], mass[keep], ei[keep], gj[keep], polar[keep])
    return Monopile(*cut, masses, foundation, (x0, y0), notes, warnings)


def _springs(deck: Deck) -> list[float]:
    """One SSI file's Kxx, Ktyty, Kxty and Ktztz — a negative spring, or a coupling the
    two it couples cannot hold, one line naming the file and the entry."""
    k = {key: deck.num(key, default=0.0) for key in ("Kxx", "Ktyty", "Kxty", "Ktztz")}
    for key in ("Kxx", "Ktyty", "Ktztz"):
        if k[key] < 0:
            raise SpecError(f"{key} {k[key]:g}: a spring of negative stiffness",
                            line=deck.values[key][1], source=str(deck.path))  # fmt: skip
    if k["Kxty"] ** 2 > k["Kxx"] * k["Ktyty"]:
        raise SpecError(
            f"Kxty {k['Kxty']:g}: more coupling than Kxx {k['Kxx']:g} and Ktyty "
            f"{k['Ktyty']:g} can hold (Kxty² ≤ Kxx·Ktyty)",
            line=deck.values["Kxty"][1],
            source=str(deck.path),
        )
    return [k["Kxx"], k["Ktyty"], k["Kxty"], k["Ktztz"]]


#: The smallest head stiffness, relative to the largest element stiffness, that a static
#: condensation keeps to about four digits in double precision (its rounding ε/ratio,
#: ε ≈ 2.2e-16: measured 5e-6 at a ratio of 1.8e-11, tests/validation/test_soil.py).
PRECISION = 1e-12


def _condensed(
    at: np.ndarray, stations: tuple[np.ndarray, ...], k: np.ndarray, path: Any
) -> tuple[tuple[float, float, float, float], float]:
    """The stiffness at the top of a beam on springs: the pile's Euler–Bernoulli and
    torsion elements between the springs' heights ``at`` (its stations' EI, GJ and mass
    per length, Gauss-integrated), springs ``k`` (rows Kxx, Ktyty, Kxty, Ktztz) at the
    nodes, everything below the top node condensed out: (lateral, rocking, coupling,
    torsion), and the lateral mass the static shape of a unit head displacement carries
    (Guyan's), for the statement."""
    from ..numerics import beam

    z, mass, ei, gj, polar = stations
    n = len(at)
    x, _ = beam.gauss_points(at)
    kb, mb = beam.assemble_bending(at, np.interp(x, z, ei), np.interp(x, z, mass))
    w, t = np.arange(0, 2 * n, 2), np.arange(1, 2 * n, 2)
    kb[w, w] += k[:, 0]
    kb[t, t] += k[:, 1]
    kb[w, t] += k[:, 2]
    kb[t, w] += k[:, 2]
    kt, _ = beam.assemble_torsion(at, np.interp(x, z, gj), np.interp(x, z, polar))
    kt[np.arange(n), np.arange(n)] += k[:, 3]
    try:
        shape = np.vstack([-np.linalg.solve(kb[:-2, :-2], kb[:-2, -2:]), np.eye(2)])
        lat = shape.T @ kb @ shape
        tor = kt[-1:, -1:] - kt[-1:, :-1] @ np.linalg.solve(kt[:-1, :-1], kt[:-1, -1:])
    except np.linalg.LinAlgError:
        raise SpecError("the SSI files' springs do not hold the pile (its condensed stiffness "
                        "is singular)", source=str(path)) from None  # fmt: skip
    # the condensation subtracts element stiffnesses of order max(diag K) to leave the
    # head's: beyond PRECISION of them the difference is rounding, not the soil
    if not lat[0, 0] > PRECISION * float(np.max(np.abs(np.diag(kb)))):
        raise SpecError("the SSI files' springs are too soft against the pile to condense "
                        "to the mudline in double precision", source=str(path))  # fmt: skip
    if not (lat[0, 0] > 0 and lat[1, 1] > 0 and lat[0, 1] ** 2 < lat[0, 0] * lat[1, 1]):
        raise SpecError("the SSI files' springs do not hold the pile head (its condensed "
                        "lateral and rocking stiffness is not positive)",
                        source=str(path))  # fmt: skip
    guyan = float((shape.T @ mb @ shape)[0, 0])
    return (float(lat[0, 0]), float(lat[1, 1]), float(lat[0, 1]), float(tor[0, 0])), guyan


def _sections(props: Table) -> dict[int, tuple[float, float, float, float, float]]:
    """Property set → (E, G, ρ, D, t), each checked for a tube."""
    out = {}
    names = ("YoungE", "ShearG" if props.has("ShearG") else "ShearG1", "MatDens", "XsecD", "XsecT")
    columns = [props.numbers(n) for n in names]
    for row, pid in enumerate(props.ids("PropSetID")):
        e, g, rho, d, t = (float(c[row]) for c in columns)
        if not (e > 0 and g > 0 and rho > 0 and d > 0 and 0 < 2 * t <= d):
            raise SpecError(
                f"property set {pid}: E, G, ρ and D must be positive and the wall 0 < 2t ≤ D "
                f"(got E {e:g}, G {g:g}, ρ {rho:g}, D {d:g}, t {t:g})",
                line=props.lines[row],
                source=str(props.path),
            )
        out[pid] = (e, g, rho, d, t)
    return out


def _stations(
    order: list[int],
    members: Table,
    sections: dict[int, tuple[float, float, float, float, float]],
    xyz: dict[int, tuple[float, float, float]],
    sd: Deck,
) -> tuple[np.ndarray, ...]:
    """Heights and distributed properties of the pile: each member's two ends (a property
    step at a joint tabulated :data:`STEP_M` below it)."""
    first, second = members.ids("MJointID1"), members.ids("MJointID2")
    p1, p2 = members.ids("MPropSetID1"), members.ids("MPropSetID2")
    rows: list[tuple[float, tuple[float, ...]]] = []
    for i in order:
        ends = [(xyz[first[i]][2], p1[i]), (xyz[second[i]][2], p2[i])]
        ends.sort()
        for (z, pid), where in zip(ends, ("bottom", "top"), strict=True):
            if pid not in sections:
                raise SpecError(
                    f"member {members.ids('MemberID')[i]} names property set {pid}, which "
                    "the circular cross-section table does not have",
                    line=members.lines[i],
                    source=str(sd.path),
                )
            props = _tube(*sections[pid])
            if where == "bottom" and rows and abs(rows[-1][0] - z) < STEP_M:
                if np.allclose(rows[-1][1], props, rtol=1e-9):
                    continue
                rows[-1] = (z - STEP_M, rows[-1][1])
            rows.append((z, props))
    heights = np.array([r[0] for r in rows])
    table = np.array([r[1] for r in rows])
    return (heights, *table.T)


def _tube(e: float, g: float, rho: float, d: float, t: float) -> tuple[float, ...]:
    inner = d - 2 * t
    area = math.pi / 4 * (d**2 - inner**2)
    second = math.pi / 64 * (d**4 - inner**4)
    return (rho * area, e * second, g * 2 * second, rho * 2 * second)


def _point_masses(
    sd: Deck, text: str, xyz: dict[int, tuple[float, float, float]], notes: list[str]
) -> list[tuple[float, float]]:
    table = counted(sd, text, ("NCmass",), "CMJointID")
    if table is None or not table.rows:
        return []
    out = []
    for joint, mass, line in zip(
        table.ids("CMJointID"), table.numbers("JMass"), table.lines, strict=True
    ):
        if joint not in xyz or mass < 0:
            raise SpecError(
                f"concentrated mass at joint {joint}: the joint must exist and the mass be ≥ 0",
                line=line,
                source=str(sd.path),
            )
        if mass > 0:
            out.append((xyz[joint][2], float(mass)))
    if not out:
        return out
    notes.append(
        "SubDyn's concentrated masses as point masses on the pile: "
        + ", ".join(f"{m:,.0f} kg at z = {z:g} m" for z, m in out)
        + " (their rotary inertias neglected)."
    )
    return out


#: An SSI file's stiffness entries that wtvib uses, and what for.
SSI_KEYS = ("Kxx", "Ktyty", "Kxty", "Kyy", "Ktxtx", "Kytx", "Ktztz")


def _reaction(sd: Deck, react: Table, notes: list[str]) -> dict[str, Any]:
    """The reaction joint: clamped (all DOFs locked, no SSI file) or on the SSI file's
    springs."""
    flags = [
        react.numbers(k)[0]
        for k in ("RctTDXss", "RctTDYss", "RctTDZss", "RctRDXss", "RctRDYss", "RctRDZss")
    ]
    ssi = react.texts("SSIfile")[0] if react.has("SSIfile") else ""
    line = react.lines[0]
    if ssi and ssi.lower() not in ("", "none", "unused"):
        path = beside(sd.path, ssi)
        if not path.is_file():
            raise SpecError(f"SSIfile names {ssi!r}, which does not exist", line=line,
                            source=str(sd.path))  # fmt: skip
        return _ssi(parse(path))
    if not all(f == 1 for f in flags):
        raise SpecError(
            "the reaction joint has free DOFs and no SSI file: wtvib models a monopile "
            "clamped at its reaction joint or on an SSI file's springs",
            line=line,
            source=str(sd.path),
        )
    notes.append(
        "The pile is clamped at its reaction joint (every DOF locked, no SSI file), as "
        "SubDyn models it: rigid soil, so the frequencies are an upper bound."
    )
    return {"kind": "clamped"}


def _ssi(deck: Deck) -> dict[str, Any]:
    """Pile-head springs from an SSI file's named stiffness entries."""
    k = {key: deck.num(key, default=0.0) for key in SSI_KEYS}
    kl, kr, klr = k["Kxx"], k["Ktyty"], k["Kxty"]
    if not (kl > 0 and kr > 0 and klr**2 < kl * kr):
        raise SpecError(
            f"the SSI stiffness must hold the pile head: Kxx > 0, Ktyty > 0 and "
            f"Kxty² < Kxx·Ktyty (got {kl:g}, {kr:g}, {klr:g})",
            line=deck.values.get("Kxx", ("", None))[1],
            source=str(deck.path),
        )
    # side-side: y and θx, a positive θx tilts toward −y, so (v, v′) couple by −Kytx
    if not np.allclose([k["Kyy"], k["Ktxtx"], -k["Kytx"]], [kl, kr, klr], rtol=0.05):
        note = (
            f" The side-side springs (Kyy {k['Kyy']:.4g}, Ktxtx {k['Ktxtx']:.4g}, Kytx "
            f"{k['Kytx']:.4g}) differ from the fore-aft ones by more than 5 %: the fore-aft "
            "springs are used in both planes."
        )
    else:
        note = ""
    found: dict[str, Any] = {
        "kind": "springs",
        "lateral_n_m": kl,
        "rocking_nm_rad": kr,
        "coupling_n": klr,
        "_note": f"Pile head on the springs of the SSI file {deck.path.name}: Kxx {kl:.4g} N/m, "
        f"Ktyty {kr:.4g} N·m/rad, Kxty {klr:.4g} N." + note,
    }
    if k["Ktztz"] > 0:
        found["torsional_nm_rad"] = k["Ktztz"]
    return found


# -- HydroDyn ----------------------------------------------------------------------


@dataclass
class Water:
    """The water moving with the pile: heights (z, MSL 0) and mass per length."""

    z: np.ndarray
    mass: np.ndarray
    note: str


@dataclass(frozen=True)
class _Sea:
    """What the water adds to a member, HydroDyn's way: density, still-water level, marine
    growth by depth, added-mass coefficients and the member's coefficient model."""

    rho: float
    swl: float
    growth: tuple[np.ndarray, np.ndarray, np.ndarray] | None
    ca: Any
    kind: int


def _member_mass(
    mid: Any,
    za: float,
    zb: float,
    at_a: tuple[float, float],
    at_b: tuple[float, float],
    fill: tuple[float, float] | None,
    sea: _Sea,
    z_grid: np.ndarray,
) -> np.ndarray:
    """One member's mass per length moving with the pile on ``z_grid`` [kg/m]: added mass
    Ca·ρ_w·π(D+2t_MG)²/4 below the still-water level, its marine growth and the water
    filling it (``fill``: level and density) — diameter and wall (``at_a``, ``at_b``)
    linear between its joints, zero outside them."""
    lo, hi = sorted((za, zb))
    inside = (z_grid >= lo) & (z_grid <= hi)
    s = (z_grid - za) / (zb - za) if zb != za else np.zeros_like(z_grid)
    d = at_a[0] + s * (at_b[0] - at_a[0])
    t = at_a[1] + s * (at_b[1] - at_a[1])
    mg_t, mg_rho = _growth(sea.growth, z_grid, sea.swl)
    outer = d + 2 * mg_t
    wet = z_grid <= sea.swl
    added = sea.ca.along(sea.kind, mid, z_grid, s) * sea.rho * math.pi / 4 * outer**2 * wet
    grown = mg_rho * math.pi / 4 * (outer**2 - d**2)
    filled = (
        fill[1] * math.pi / 4 * np.clip(d - 2 * t, 0, None) ** 2 * (z_grid <= fill[0])
        if fill is not None
        else np.zeros_like(z_grid)
    )
    return np.asarray(inside * (added + grown + filled))


def _joints_and_properties(
    joints: Table, props: Table
) -> tuple[dict[int, tuple[float, float, float]], dict[int, tuple[float, float]]]:
    """HydroDyn's joint positions (x, y, z) [m] and member property sets (D, t) [m], by id."""
    xyz = dict(
        zip(
            joints.ids("JointID"),
            zip(
                joints.numbers("Jointxi"),
                joints.numbers("Jointyi"),
                joints.numbers("Jointzi"),
                strict=True,
            ),
            strict=True,
        )
    )
    prop = dict(
        zip(
            props.ids("PropSetID"),
            zip(props.numbers("PropD"), props.numbers("PropThck"), strict=True),
            strict=True,
        )
    )
    return xyz, prop


def water(fst: Deck, pile: Monopile) -> Water | str:
    """HydroDyn's added mass, filled-member water and marine growth along the pile, or
    why there is none (a sentence for the assumptions)."""
    if fst.num("CompHydro", default=0) == 0 or "HydroFile" not in fst.values:
        return (
            "HydroDyn is off (CompHydro = 0): no added mass of the water, as OpenFAST runs "
            "this deck set"
        )
    hd = parse(_file(fst, "HydroFile"))
    env = environment(fst)
    hd.inherited.update(env)
    sea = sea_state(fst)
    if sea is not None:
        sea.inherited.update(env)
    text = read_text(hd.path, ansi=True)
    rho = sea_setting(hd, sea, "WtrDens", WATER_DENSITY)
    swl = sea_setting(hd, sea, "MSL2SWL", 0.0)
    joints = counted(hd, text, ("NJoints",), "Jointzi")
    members = counted(hd, text, ("NMembers",), "MJointID1")
    props = counted(hd, text, ("NPropSets", "NPropSetsCyl"), "PropD")
    if joints is None or members is None or props is None or not members.rows:
        return f"HydroDyn ({hd.path.name}) has no Morison members: no added mass"
    xyz, prop = _joints_and_properties(joints, props)
    ca = _coefficients(hd, text)
    kinds = members.numbers("MCoefMod") if members.has("MCoefMod") else None
    fills = _fills(hd, text, rho)
    growth = counted(hd, text, ("NMGDepths",), "MGDpth")
    depth_mg = (
        (growth.numbers("MGDpth"), growth.numbers("MGThck"), growth.numbers("MGDens"))
        if growth is not None and growth.rows
        else None
    )
    z_grid = np.linspace(pile.z[0], pile.z[-1], 401)
    total = np.zeros_like(z_grid)
    used = []
    pot = members.texts("PropPot") if members.has("PropPot") else ["false"] * len(members.rows)
    x0, y0 = pile.axis
    for i, mid in enumerate(members.ids("MemberID")):
        a, b = members.ids("MJointID1")[i], members.ids("MJointID2")[i]
        if a not in xyz or b not in xyz:
            raise SpecError(f"member {mid} names a joint the joint table does not have",
                            line=members.lines[i], source=str(hd.path))  # fmt: skip
        (xa, ya, za), (xb, yb, zb) = xyz[a], xyz[b]
        if pot[i].lstrip(".").lower().startswith("t"):
            continue  # potential flow: not a strip-theory member
        if max(math.hypot(xa - x0, ya - y0), math.hypot(xb - x0, yb - y0)) > AXIS_TOLERANCE_M:
            continue  # not on the pile's axis (a boat landing, a J-tube): left out, said
        pa, pb = members.ids("MPropSetID1")[i], members.ids("MPropSetID2")[i]
        if pa not in prop or pb not in prop:
            raise SpecError(f"member {mid} names a property set HydroDyn does not have",
                            line=members.lines[i], source=str(hd.path))  # fmt: skip
        kind = int(kinds[i]) if kinds is not None else 1
        around = _Sea(rho, swl, depth_mg, ca, kind)
        total += _member_mass(mid, za, zb, prop[pa], prop[pb], fills.get(mid), around, z_grid)
        used.append(mid)
    if not used:
        return f"HydroDyn ({hd.path.name}) has no strip-theory member on the pile: no added mass"
    fill_text = "; filled members' water" if fills else ""
    note = (
        f"Water moving with the pile from HydroDyn ({hd.path.name}, members "
        f"{', '.join(map(str, used))}): added mass Ca·ρ_w·π(D+2t_MG)²/4 below the still-water "
        f"level (ρ_w {rho:g} kg/m³, SWL {swl:g} m){fill_text}"
        + ("; marine growth" if depth_mg is not None else "")
        + f" — {float(np.trapezoid(total, z_grid)) / 1e3:,.0f} t in all, in bending only."
    )
    return Water(z_grid, total, note)


@dataclass(frozen=True)
class _Coefficients:
    """HydroDyn's transverse added-mass coefficients: the simple one, the depth-based
    table (z, Ca) and the member-based ends (member → Ca at joint 1, at joint 2)."""

    simple: float
    depth: tuple[np.ndarray, np.ndarray] | None
    member: dict[int, tuple[float, float]]

    def along(self, kind: int, member: int, z: np.ndarray, s: np.ndarray) -> np.ndarray:
        """Ca at heights ``z`` (``s``: 0 at the member's joint 1, 1 at joint 2) of a member
        of coefficient model ``kind`` (1 simple, 2 depth-based, 3 member-based)."""
        if kind == 2 and self.depth is not None:
            return np.asarray(np.interp(z, *self.depth))
        if kind == 3 and member in self.member:
            c1, c2 = self.member[member]
            return c1 + s * (c2 - c1)
        return np.full_like(z, self.simple)


def _coefficients(hd: Deck, text: str) -> _Coefficients:
    depth = counted(hd, text, ("NCoefDpth", "NCoefDpthCyl"), "DpthCa")
    member = counted(hd, text, ("NCoefMembers", "NCoefMembersCyl"), "MemberCa1")
    by_depth = None
    if depth is not None and depth.rows:
        z = -depth.numbers("Dpth")
        order = np.argsort(z)
        by_depth = (z[order], depth.numbers("DpthCa")[order])
    by_member: dict[int, tuple[float, float]] = {}
    if member is not None and member.rows:
        ids = member.ids(member.header[0])
        ends = zip(member.numbers("MemberCa1"), member.numbers("MemberCa2"), strict=True)
        by_member = {m: (float(a), float(b)) for m, (a, b) in zip(ids, ends, strict=True)}
    return _Coefficients(_simple_ca(hd, text), by_depth, by_member)


def _simple_ca(hd: Deck, text: str) -> float:
    """SimplCa of the simple-coefficient table (a header line, units, one row)."""
    lines = text.splitlines()
    for i, line in enumerate(lines):
        header = line.split()
        if "SimplCa" in header:
            j = i + 1
            while j < len(lines) and lines[j].strip().startswith("("):
                j += 1
            cells = lines[j].split() if j < len(lines) else []
            col = header.index("SimplCa")
            try:
                return float(cells[col])
            except (IndexError, ValueError):
                raise SpecError(
                    "SimplCa must be a number", line=j + 1, source=str(hd.path)
                ) from None
    return 1.0


def _fills(hd: Deck, text: str, rho: float) -> dict[int, tuple[float, float]]:
    """Member → (free-surface z, fluid density) of HydroDyn's filled groups."""
    table = counted(hd, text, ("NFillGroups",), "FillNumM")
    out: dict[int, tuple[float, float]] = {}
    if table is None:
        return out
    for row, line in zip(table.rows, table.lines, strict=True):
        try:
            count = int(row[0])
            listed = [int(c) for c in row[1 : 1 + count]]
            surface = float(row[1 + count])
            dens = row[2 + count].strip('"')
            density = rho if dens.lower() == "default" else float(dens)
        except (IndexError, ValueError):
            raise SpecError(
                "a filled-member group must read: count, that many member IDs, FillFSLoc, FillDens",
                line=line,
                source=str(hd.path),
            ) from None
        for m in listed:
            out[m] = (surface, density)
    return out


def _growth(
    table: tuple[np.ndarray, np.ndarray, np.ndarray] | None, z: np.ndarray, swl: float
) -> tuple[np.ndarray, np.ndarray]:
    """Marine-growth thickness and density at each z (depths below the SWL, linear)."""
    if table is None:
        return np.zeros_like(z), np.zeros_like(z)
    depth, thick, dens = table
    order = np.argsort(depth)
    below = swl - z
    inside = (below >= depth[order][0]) & (below <= depth[order][-1])
    t = np.interp(below, depth[order], thick[order]) * inside
    rho = np.interp(below, depth[order], dens[order]) * inside
    return t, rho
