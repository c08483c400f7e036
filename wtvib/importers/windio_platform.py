"""windIO ``floating_platform`` and ``mooring`` → wtvib's ``platform`` foundation (2.x, and
1.x in its own words: a member's ``internal_structure`` and ``ballasts``, cylindrical
joints' angles in radians).

The platform is the hull of :mod:`wtvib.numerics.hull`: each member a circular tube between two
joints (cartesian, cylindrical (r, θ, z) or relative to another joint), its outer diameter,
wall layers, bulkheads, ring and longitudinal stiffeners, outfitting factor and ballast as
the file gives them; pontoons that enter another member's side are cut at its surface (so
no volume counts twice); the transition piece and ``rigid_bodies`` are point masses at
their joints. Buoyancy and the waterplane come from the members' outer surface, added mass
from strip theory with each member's ``Ca`` (and ``axial_coeffs.Ca`` of a free end's joint,
else RAFT's 0.6, for the axial term), the moorings' stiffness and pull from MoorPy. The
water ballast (``variable_flag``) is what makes the platform float at its design draft with
the turbine on it: WISDEM's FloatingSE rule, share by capacity.

windIO turbine schema 2.x (``components.floating_platform``, ``components.mooring``; the
windio package); WISDEM ``floatingse/floating_system.py`` (the ballast rule); MoorPy's line
property library (``getLineProps``) for a line type given by its material and diameter only.
"""

import contextlib
import io
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import SpecError
from ..numerics import hull
from ..units import STANDARD_GRAVITY

#: Sea water where the file gives no density [kg/m³] (OpenFAST's and WISDEM's default).
SEA_WATER = 1025.0

#: windIO's default member ``Ca`` is −1 ("not given"): wtvib then takes a circular
#: cylinder's potential-flow value, 1 (DNV-RP-C205, Table A-1).
DEFAULT_CA = 1.0

#: The axial (end) added-mass coefficient where the end's joint gives none (RAFT's default).
DEFAULT_CA_END = 0.6

#: A member meeting another at less than this angle is not cut at its surface.
MIN_CUT_SINE = 0.2

#: The tower must stand within this distance of the platform's origin [m].
AXIS_TOLERANCE = 0.5

#: A flooded member's fill: "to the water line" rather than a volume.
FLOODED = -1.0

#: windIO 1.x's names of a member's ``structure`` and of its ``ballast`` list (2.x's
#: names; the IEA-15's own WT_Ontology/IEA-15-240-RWT_VolturnUS-S.yaml is 1.x).
V1_STRUCTURE, V1_BALLAST = "internal_structure", "ballasts"

#: At most this many members and joints (a platform has tens; hostile files stay bounded).
MAX_PARTS = 500


@dataclass(frozen=True)
class Floater:
    """The ``platform`` foundation block, what the report says about it, and warnings."""

    block: dict[str, Any]
    notes: list[str]
    warnings: list[str]


def platform(
    d: dict[str, Any], path: Path, carried_kg: float, tower_base_z: float, v2: bool = True
) -> Floater:
    """The windIO file's floating platform under a turbine of ``carried_kg`` (tower and
    head) whose tower starts at ``tower_base_z`` [m above the still-water line]; ``v2``:
    the file is windIO 2.x (else 1.x: :data:`V1_STRUCTURE`, cylindrical joints' angles in
    radians)."""
    reader = _Platform(d, path, v2)
    return reader.floater(carried_kg, tower_base_z)


class _Platform:
    def __init__(self, d: dict[str, Any], path: Path, v2: bool = True) -> None:
        self.d, self.path, self.v2 = d, path, v2
        self.fp = d["components"]["floating_platform"]
        env = d.get("environment", {}) if isinstance(d.get("environment"), dict) else {}
        self.rho = self.positive(env.get("water_density", SEA_WATER), "environment.water_density")
        self.g = STANDARD_GRAVITY
        self.notes: list[str] = []
        self.warnings: list[str] = []
        self.radians: list[tuple[str, float]] = []  # stiffener spacings read as radians
        self.flooded: list[str] = []

    def fail(self, message: str, where: str | None = None) -> SpecError:
        return SpecError(message, path=where, source=str(self.path))

    def positive(self, value: Any, where: str) -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.fail(f"{where} must be a number (got {value!r})", where)
        if not (math.isfinite(value) and value > 0):
            raise self.fail(f"{where} must be a positive number (got {value!r})", where)
        return float(value)

    def number(self, value: Any, where: str, low: float = -1e6, high: float = 1e6) -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.fail(f"{where} must be a number (got {value!r})", where)
        if not (math.isfinite(value) and low <= value <= high):
            raise self.fail(f"{where} = {value!r} is outside {low:g} … {high:g}", where)
        return float(value)

    def density(self, name: Any, where: str) -> float:
        for m in self.d.get("materials", []):
            if isinstance(m, dict) and m.get("name") == name:
                rho = m.get("rho")
                if isinstance(rho, list) and rho:
                    rho = rho[0]
                return self.positive(rho, f"materials ({name}).rho")
        raise self.fail(f"{where}: material {name!r} is not in the file's materials", where)

    # -- geometry -----------------------------------------------------------------------
    def joints(self) -> dict[str, np.ndarray]:
        out: dict[str, np.ndarray] = {}
        pending = list(enumerate(self.fp["joints"]))
        if len(pending) > MAX_PARTS:
            raise self.fail(f"{len(pending)} joints: wtvib reads at most {MAX_PARTS}")
        for _ in range(len(pending) + 1):  # relative joints may name later ones
            waiting = []
            for i, j in pending:
                where = f"components.floating_platform.joints[{i}]"
                loc = j["location"]
                if not isinstance(loc, list) or len(loc) != 3:
                    raise self.fail(f"{where}.location must be three numbers", where)
                a, b, z = (self.number(v, f"{where}.location") for v in loc)
                if j.get("cylindrical", False):
                    # θ in degrees in windIO 2.x, in radians in 1.x (the IEA-15's own 1.x
                    # VolturnUS-S gives its columns at 3.14159265, 1.0471976, −1.0471976)
                    t = math.radians(b) if self.v2 else b
                    xyz = np.array([a * math.cos(t), a * math.sin(t), z])
                else:
                    xyz = np.array([a, b, z])
                base = j.get("relative", "origin")
                if base not in (None, "origin"):
                    if base not in out:
                        waiting.append((i, j))
                        continue
                    dims = np.asarray(j.get("relative_dims", [True] * 3), bool)
                    xyz = xyz + np.where(dims, out[base], 0.0)
                out[str(j["name"])] = xyz
            if not waiting:
                return out
            pending = waiting
        names = ", ".join(str(j.get("name")) for _, j in pending[:3])
        raise self.fail(f"joints {names} are relative to joints that never resolve (a cycle?)")

    def members(self, joints: dict[str, np.ndarray]) -> list[hull.Member]:
        raw = list(enumerate(self.fp["members"]))
        if not raw or len(raw) > MAX_PARTS:
            raise self.fail(
                f"components.floating_platform.members: {len(raw)} members (1 … {MAX_PARTS})"
            )
        # axial joints: each member's, once both its ends are known (a pontoon may end at
        # another member's axial joint and carry axial joints of its own)
        hosts: dict[str, tuple[int, float]] = {}  # axial joint → (member, its station)
        for _ in range(len(raw)):
            progress = False
            for i, m in raw:
                j1, j2 = str(m["joint1"]), str(m["joint2"])
                if j1 not in joints or j2 not in joints:
                    continue
                for k, axial in enumerate(m.get("axial_joints", []) or []):
                    name = str(axial["name"])
                    if name in joints:
                        continue
                    where = f"components.floating_platform.members[{i}].axial_joints[{k}]"
                    s = self.number(axial["grid"], f"{where}.grid", 0.0, 1.0)
                    joints[name] = joints[j1] + s * (joints[j2] - joints[j1])
                    hosts[name] = (i, s)
                    progress = True
            if not progress:
                break
        out = []
        for i, m in raw:
            where = f"components.floating_platform.members[{i}]"
            for key in ("joint1", "joint2"):
                if str(m[key]) not in joints:
                    raise self.fail(f"{where}.{key}: joint {m[key]!r} is not defined", where)
            out.append(self.member(i, m, joints, hosts, raw))
        return out

    def member(
        self,
        i: int,
        m: dict[str, Any],
        joints: dict[str, np.ndarray],
        hosts: dict[str, tuple[int, float]],
        raw: list[tuple[int, dict[str, Any]]],
    ) -> hull.Member:
        where = f"components.floating_platform.members[{i}]"
        shape = m["outer_shape"]
        if shape.get("shape", "circular") != "circular":
            raise self.fail(
                f"{where}.outer_shape.shape is {shape.get('shape')!r}: wtvib models circular "
                "members only",
                f"{where}.outer_shape.shape",
            )
        a, b = joints[str(m["joint1"])].copy(), joints[str(m["joint2"])].copy()
        length = float(np.linalg.norm(b - a))
        if length <= 1e-6:
            raise self.fail(f"{where}: joint1 and joint2 are at one point", where)
        grid, diameter = self.table(shape["outer_diameter"], f"{where}.outer_shape.outer_diameter")
        # windIO 1.x names a member's walls and ballast internal_structure and ballasts
        part = "structure" if "structure" in m or "internal_structure" not in m else V1_STRUCTURE
        struct = m.get(part, {}) or {}
        at = f"{where}.{part}"
        layers = []
        for k, layer in enumerate(struct.get("layers", []) or []):
            lw = f"{at}.layers[{k}]"
            g, t = self.table(layer["thickness"], f"{lw}.thickness", zero=True)
            layers.append(hull.Layer(np.interp(grid, g, t), self.density(layer["material"], lw)))
        bulkheads = []
        if struct.get("bulkhead"):
            bw = f"{at}.bulkhead"
            rho = self.density(struct["bulkhead"]["material"], bw)
            g, t = self.table(struct["bulkhead"]["thickness"], f"{bw}.thickness", zero=True)
            bulkheads = [hull.Disc(float(s), float(x), rho) for s, x in zip(g, t, strict=True)]
        inner = float(np.min(diameter)) - 2 * sum(float(np.max(x.thickness)) for x in layers)
        stiffeners = self.stiffeners(struct, at, max(inner, 0.0) / 2, length)
        fills = self.fills(m, struct, at)
        a, b = self.cut_ends(i, m, a, b, joints, hosts, raw)
        return hull.Member(
            name=str(m["name"]),
            a=a,
            b=b,
            stations=grid,
            diameter=diameter,
            layers=layers,
            bulkheads=bulkheads,
            stiffener_mass_per_m=stiffeners,
            outfitting=self.positive(
                struct.get("outfitting_factor", 1.0), f"{at}.outfitting_factor"
            ),
            ca=self.coefficient(m.get("Ca"), f"{where}.Ca"),
            ca_end=self.axial_ca(m),
            free_ends=(
                self.free(str(m["joint1"]), i, raw, hosts),
                self.free(str(m["joint2"]), i, raw, hosts),
            ),
            fills=fills,
        )

    def fills(self, m: dict[str, Any], struct: dict[str, Any], at: str) -> list[hull.Fill]:
        """A member's water and ballast: open to the sea (``flooded``: its water to the
        water line), fixed ballast (a material's volume), the compartments the trim fills
        with water (``variable_flag``)."""
        fills = []
        if struct.get("flooded", False):  # open to the sea: its water, to the water line, is mass
            self.flooded.append(str(m["name"]))
            fills.append(hull.Fill(0.0, 1.0, self.rho, FLOODED))
        key = "ballast" if "ballast" in struct or V1_BALLAST not in struct else V1_BALLAST
        for k, ballast in enumerate(struct.get(key, []) or []):
            bw = f"{at}.{key}[{k}]"
            g, _ = self.table(
                {"grid": ballast["grid"], "values": [0.0] * len(ballast["grid"])},
                f"{bw}.grid",
                zero=True,
            )
            if ballast.get("variable_flag", False):
                fills.append(hull.Fill(float(g[0]), float(g[-1]), self.rho))
            else:
                rho = self.density(ballast["material"], bw)
                volume = self.positive(ballast["volume"], f"{bw}.volume")
                fills.append(hull.Fill(float(g[0]), float(g[-1]), rho, volume))
        return fills

    def cut_ends(
        self,
        i: int,
        m: dict[str, Any],
        a: np.ndarray,
        b: np.ndarray,
        joints: dict[str, np.ndarray],
        hosts: dict[str, tuple[int, float]],
        raw: list[tuple[int, dict[str, Any]]],
    ) -> tuple[np.ndarray, np.ndarray]:
        """The member's ends, each cut back to the surface of the member whose side it
        enters (its end an axial joint of that member), so that no volume counts twice."""
        length = float(np.linalg.norm(b - a))
        axis = (b - a) / length
        for end, name in ((0, str(m["joint1"])), (1, str(m["joint2"]))):
            if name not in hosts or hosts[name][0] == i:
                continue
            host = raw[hosts[name][0]][1]
            h_a, h_b = joints[str(host["joint1"])], joints[str(host["joint2"])]
            h_axis = (h_b - h_a) / np.linalg.norm(h_b - h_a)
            sine = float(np.linalg.norm(np.cross(axis, h_axis)))
            hg, hd = self.table(host["outer_shape"]["outer_diameter"], "host")
            radius = float(np.interp(hosts[name][1], hg, hd)) / 2
            if sine >= MIN_CUT_SINE and radius / sine < 0.45 * length:
                cut = radius / sine * axis
                a, b = (a + cut, b) if end == 0 else (a, b - cut)
        return a, b

    def axial_ca(self, m: dict[str, Any]) -> float:
        """The axial (end) added-mass coefficient: the ``axial_coeffs.Ca`` its end joints
        give (their mean), else :data:`DEFAULT_CA_END`."""
        given = []
        for j in self.fp["joints"]:
            if str(j.get("name")) in (str(m["joint1"]), str(m["joint2"])):
                coeffs = j.get("axial_coeffs") or {}
                if isinstance(coeffs, dict) and "Ca" in coeffs:
                    where = f"components.floating_platform.joints ({j.get('name')}).axial_coeffs.Ca"
                    given.append(self.number(coeffs["Ca"], where, 0.0, 10.0))
        return float(np.mean(given)) if given else DEFAULT_CA_END

    def free(
        self,
        joint: str,
        i: int,
        raw: list[tuple[int, dict[str, Any]]],
        hosts: dict[str, tuple[int, float]],
    ) -> bool:
        """An end no other member meets."""
        if joint in hosts and hosts[joint][0] != i:
            return False
        return not any(k != i and joint in (str(m["joint1"]), str(m["joint2"])) for k, m in raw)

    def table(self, field: Any, where: str, zero: bool = False) -> tuple[np.ndarray, np.ndarray]:
        try:
            g = np.asarray(field["grid"], float)
            v = np.asarray(field["values"], float)
        except (TypeError, ValueError, KeyError):
            raise self.fail(f"{where} must be a grid and values of numbers", where) from None
        if g.ndim != 1 or g.shape != v.shape or len(g) < 1:
            raise self.fail(f"{where}: grid and values must be lists of one length", where)
        if not (np.all(np.isfinite(g)) and np.all(np.isfinite(v))):
            raise self.fail(f"{where}: grid and values must be finite", where)
        if np.any(g < 0) or np.any(g > 1) or np.any(np.diff(g) < 0):
            raise self.fail(f"{where}.grid must rise within 0 … 1", where)
        if np.any(v < 0) or (not zero and np.any(v <= 0)) or np.any(v > 1e3):
            raise self.fail(f"{where}.values must be {'≥' if zero else '>'} 0 m and ≤ 1 km", where)
        return g, v

    def coefficient(self, value: Any, where: str) -> float:
        if value is None:
            return DEFAULT_CA
        values = value if isinstance(value, list) else [value]
        numbers = [self.number(v, where, -1.0, 10.0) for v in values] or [-1.0]
        mean = float(np.mean(numbers))
        return mean if mean >= 0 else DEFAULT_CA

    def stiffeners(self, struct: dict[str, Any], where: str, radius: float, length: float) -> float:
        """Ring and longitudinal stiffeners' mass per metre of member [kg/m]."""
        out = 0.0
        for key in ("ring_stiffeners", "longitudinal_stiffeners"):
            s = struct.get(key)
            if not s:
                continue
            sw = f"{where}.{key}"
            rho = self.density(s["material"], sw)
            area = sum(
                self.number(s[a], f"{sw}.{a}", 0.0, 10.0)
                * self.number(s[b], f"{sw}.{b}", 0.0, 10.0)
                for a, b in (("flange_thickness", "flange_width"), ("web_height", "web_thickness"))
            )
            spacing = self.number(s.get("spacing", 0.0), f"{sw}.spacing", 0.0, 360.0)
            if spacing <= 0:
                continue
            if key == "ring_stiffeners":  # spacing: a share of the member's length
                out += rho * area * 2 * math.pi * radius / (spacing * length)
                continue
            if spacing < math.pi / 2:  # windIO 1.x's radians (its converter's rule)
                self.radians.append((sw, spacing))
                spacing = math.degrees(spacing)
            out += rho * area * round(360.0 / spacing)  # spacing: degrees round the section
        return out

    # -- the floater -----------------------------------------------------------------------
    def floater(self, carried: float, tower_base_z: float) -> Floater:
        joints = self.joints()
        members = self.members(joints)
        if self.radians:
            where, value = self.radians[0]
            more = f" (and {len(self.radians) - 1} more)" if len(self.radians) > 1 else ""
            self.warnings.append(
                f"{where}.spacing = {value:g}{more}: read as radians ({math.degrees(value):.4g}°), "
                "as windIO's own 1.x → 2.x converter does; windIO 2.x gives it in degrees"
            )
        top = self.tower_joint(joints, tower_base_z)
        steel = sum((hull.structure(m) for m in members), np.zeros((6, 6)))
        points = self.point_masses(joints, top)
        fixed, variable = self.fixed_ballast(members)
        float_ = hull.buoyancy(members)
        if float_.volume <= 0:
            raise self.fail("the platform's members displace no water (none below z = 0)")
        k_moor, pull, moor_note = self.moorings(joints)
        carried_total = steel[0, 0] + fixed[0, 0] + points[0, 0] + carried + pull / self.g
        trimmed = hull.trim(float_.volume, self.rho, carried_total, variable)
        water = sum((hull.ballast(m, f, trimmed.level) for m, f in variable), np.zeros((6, 6)))
        body = steel + fixed + points + water
        mass = float(body[0, 0])
        cm = np.array([body[1, 5], -body[0, 5], body[0, 4]]) / mass
        # the platform's (in wtvib's model) centre of mass is on the axis
        off = math.hypot(cm[0], cm[1])
        if off > AXIS_TOLERANCE:
            self.warnings.append(
                f"tower.foundation: the platform's centre of mass is {off:.3g} m off the tower "
                "axis; wtvib's platform model takes it on the axis"
            )
        inertia = body[3:, 3:] + mass * hull.skew(cm) @ hull.skew(cm)
        products = max(abs(inertia[0, 1]), abs(inertia[0, 2]), abs(inertia[1, 2]))
        if products > 0.01 * min(inertia[0, 0], inertia[1, 1]):
            self.warnings.append(
                f"tower.foundation: the platform's products of inertia reach {products:.3g} "
                "kg·m² (over 1 % of its roll and pitch inertias); wtvib's platform model keeps "
                "its principal axes along x, y, z"
            )
        added = hull.added_mass(members, self.rho)
        restoring = hull.hydrostatic(float_, self.rho, self.g) + k_moor
        block = {
            "tower_base_m": float(top[2]),
            "mass_kg": mass,
            "cm_m": float(cm[2]),
            "inertia_roll_kgm2": float(inertia[0, 0]),
            "inertia_pitch_kgm2": float(inertia[1, 1]),
            "inertia_yaw_kgm2": float(inertia[2, 2]),
            "added_mass": _list(added),
            "stiffness": _list(restoring),
            "source": f"windIO floating_platform and mooring of {self.path.name} "
            "(wtvib.numerics.hull: "
            f"strip theory, waterplane hydrostatics; {moor_note})",
        }
        self.trim_notes(trimmed, steel, fixed, water, float_)
        if self.flooded:
            self.notes.append(
                f"Flooded members ({', '.join(self.flooded)}): the sea water inside them, up to "
                "the water line, moves with the platform as mass (their outer volume still "
                "counts as displacement)."
            )
        self.notes.append(
            f"Floating platform from the windIO file's {len(members)} members "
            f"(wtvib.numerics.hull, circular members cut where they enter another's side): "
            f"{mass:,.0f} kg with its ballast, CM {cm[2]:.3g} m, displacement "
            f"{float_.volume:,.0f} m³ (centre of buoyancy {float_.centre[2]:.3g} m), "
            f"waterplane {float_.area:.4g} m²; added mass by strip theory (members' Ca, "
            f"axial {DEFAULT_CA_END:g} at free ends and steps of diameter, ρ {self.rho:g} "
            f"kg/m³), {moor_note}. The platform is a rigid body with six DOFs under the tower "
            "(wtvib.subsystems.platform); its radiation damping, viscous drag, wave excitation "
            "and the "
            "added mass's change with frequency are left out."
        )
        return Floater(block, self.notes, self.warnings)

    def tower_joint(self, joints: dict[str, np.ndarray], tower_base_z: float) -> np.ndarray:
        """The transition joint, where the tower stands: one, on the axis, at its base."""
        transition = [str(j["name"]) for j in self.fp["joints"] if j.get("transition", False)]
        if len(transition) != 1:
            raise self.fail(
                "components.floating_platform.joints: exactly one joint must be the "
                f"transition (transition: true) where the tower stands; {len(transition)} are"
            )
        top = joints[transition[0]]
        if math.hypot(top[0], top[1]) > AXIS_TOLERANCE:
            raise self.fail(
                f"the transition joint {transition[0]!r} is at x = {top[0]:g}, y = {top[1]:g} "
                "m: wtvib's platform has the tower on its vertical axis through the origin"
            )
        if abs(top[2] - tower_base_z) > AXIS_TOLERANCE:
            raise self.fail(
                f"the tower starts at z = {tower_base_z:g} m but the platform's transition "
                f"joint {transition[0]!r} is at z = {top[2]:g} m: they must meet"
            )
        return top

    def point_masses(self, joints: dict[str, np.ndarray], top: np.ndarray) -> np.ndarray:
        """The transition piece at the tower's joint and the ``rigid_bodies`` (6 × 6)."""
        points = np.zeros((6, 6))
        tp = float(self.fp.get("transition_piece_mass", 0.0) or 0.0)
        if tp:
            points += hull.at_point(
                self.number(tp, "transition_piece_mass", 0, 1e9) * np.eye(3), top
            )
        for k, body in enumerate(self.fp.get("rigid_bodies", []) or []):
            bw = f"components.floating_platform.rigid_bodies[{k}]"
            if str(body["joint1"]) not in joints:
                raise self.fail(f"{bw}.joint1: joint {body['joint1']!r} is not defined", bw)
            r = joints[str(body["joint1"])] + np.asarray(body.get("cm_offset", [0, 0, 0]), float)
            mass = self.number(body["mass"], f"{bw}.mass", 0.0, 1e10)
            inertia = np.diag(
                [
                    self.number(v, f"{bw}.moments_of_inertia", 0, 1e15)
                    for v in body["moments_of_inertia"]
                ]
            )
            points += hull.at_point(mass * np.eye(3), r, inertia)
        return points

    def fixed_ballast(
        self, members: list[hull.Member]
    ) -> tuple[np.ndarray, list[tuple[hull.Member, hull.Fill]]]:
        """The fixed ballast and flooded members' water (6 × 6), and the water-ballast
        compartments left for the trim."""
        fixed = np.zeros((6, 6))
        variable: list[tuple[hull.Member, hull.Fill]] = []
        for m in members:
            for f in m.fills:
                if f.volume is None:
                    variable.append((m, f))
                    continue
                if f.volume == FLOODED:
                    fixed += hull.ballast(m, f, 0.0)
                    continue
                room = hull.capacity(m, f)
                if f.volume > room * 1.01:
                    self.warnings.append(
                        f"tower.foundation: member {m.name}'s ballast of {f.volume:g} m³ "
                        f"overfills its compartment ({room:.4g} m³); the compartment is taken "
                        "full"
                    )
                fixed += hull.ballast(m, f, hull.level([(m, f)], f.volume))
        return fixed, variable

    def trim_notes(
        self,
        trimmed: hull.Trim,
        steel: np.ndarray,
        fixed: np.ndarray,
        water: np.ndarray,
        float_: hull.Buoyancy,
    ) -> None:
        room = trimmed.room
        level = f", z = {trimmed.level:.3g} m" if math.isfinite(trimmed.level) else ""
        self.notes.append(
            f"Ballast: the hull's steel {steel[0, 0]:,.0f} kg, fixed ballast "
            f"{fixed[0, 0]:,.0f} kg and {water[0, 0]:,.0f} kg of water ballast — the mass "
            "that floats the platform at its design draft with the turbine and the moorings' "
            f"pull, in its {room:,.0f} m³ of variable-ballast compartments filled from the "
            f"lowest up to one level{level} (connected tanks)."
        )
        if trimmed.shortfall > 0.005 * self.rho * float_.volume:
            self.warnings.append(
                f"tower.foundation: the platform does not float at its design draft: "
                f"{trimmed.shortfall:,.0f} kg more water ballast would be needed than its "
                f"variable-ballast compartments hold ({room:,.0f} m³); audited at the design "
                "draft regardless"
            )
        elif trimmed.shortfall < -0.005 * self.rho * float_.volume:
            self.warnings.append(
                f"tower.foundation: the platform is {-trimmed.shortfall:,.0f} kg too heavy to "
                "float at its design draft with no water ballast at all; audited at the "
                "design draft regardless"
            )

    def moorings(self, joints: dict[str, np.ndarray]) -> tuple[np.ndarray, float, str]:
        """The moorings' stiffness at the PRP, their downward pull [N], and a note."""
        moor = self.d["components"].get("mooring")
        if not moor:
            self.warnings.append(
                "tower.foundation: the floating platform has no moorings in the file: its "
                "surge, sway and yaw have no stiffness"
            )
            return np.zeros((6, 6)), 0.0, "no moorings"
        from .mooring import windio_system

        depth = self.depth(moor, joints)
        with contextlib.redirect_stdout(io.StringIO()):
            k, force, count, said = windio_system(moor, joints, depth, self.rho, self.g, self.path)
        note = f"{count} mooring lines (MoorPy, depth {depth:g} m; " + "; ".join(said) + ")"
        return k, -force, note

    def depth(self, moor: dict[str, Any], joints: dict[str, np.ndarray]) -> float:
        env = self.d.get("environment", {})
        if isinstance(env, dict) and env.get("water_depth") is not None:
            return self.positive(env["water_depth"], "environment.water_depth")
        anchors = [
            -joints[str(n["joint"])][2]
            for n in moor.get("nodes", []) or []
            if n.get("node_type") == "fixed" and str(n.get("joint")) in joints
        ]
        if not anchors or max(anchors) <= 0:
            raise self.fail(
                "no water depth: environment.water_depth is missing and no anchor "
                "lies below the water line"
            )
        self.notes.append(
            f"Water depth {max(anchors):g} m: the deepest anchor's (the file gives no "
            "environment.water_depth)."
        )
        return float(max(anchors))


def _list(a: np.ndarray) -> list[list[float]]:
    return [[float(f"{v:.10g}") for v in row] for row in a]
