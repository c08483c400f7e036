"""windIO turbine YAML (1.x and 2.x) → wtvib spec data.

The two major versions differ: 2.x has ``components.tower.outer_shape`` and
``structure.layers``, component masses under ``elastic_properties`` and rotor speeds in rpm
under ``control``; 1.x has ``outer_shape_bem`` / ``internal_structure_2d_fem``, blade
properties under ``elastic_properties_mb.six_x_six`` (upper-triangle 6×6 per station) and
speeds in rad/s under ``control.torque`` or ``control.supervisory``, and no hub or nacelle
masses (WISDEM computes those), which must then be given with ``head_mass``. windIO 2.0
(WISDEM's examples) has 2.x's geometry with 1.x's control blocks, their speeds in rpm and
pitch in degrees (windIO's converter, ``converters/windIO2windIO.py``), and may lack the
masses too.

References
----------
IEA Wind Task 37, windIO turbine schema (``windIO/schemas/turbine/turbine_schema.yaml``,
windio 2.1.1): K44 and K55 are the two bending stiffnesses of a blade section, K66 the
torsional stiffness; ``reference_axis.z`` heights in m. The schema text calls K44 flapwise,
while the IEA-15 and IEA-22 example files hold the edgewise values in K44 (as BeamDyn
does); wtvib takes the lower of the two over most of the span as flapwise. The 6×6 matrices
refer to the reference axis: the bending and torsional stiffnesses are condensed from them
(other strains free, :func:`_condensed`) rather than read off the diagonal.
"""

import math
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import SpecError
from ..numerics.rigid import Part, assembled
from ..spec.yamlio import format_path, parse, parse_plain
from .floating import refusal

#: Index of the mass and polar inertia in a row-major upper triangle of the 6×6 mass matrix.
_UT = {"mass": 0, "i_plr": 20}


#: windIO components that make a turbine float (:mod:`.windio_platform` reads them).
FLOATING = ("floating_platform", "mooring")


def to_spec_data(
    path: Path,
    text: str,
    head_mass: float | None = None,
    clamped_base: bool = False,
    soil: dict[str, Any] | None = None,
    rpm: tuple[float, float] | None = None,
) -> dict[str, Any]:
    """wtvib spec data from a windIO turbine file (see :func:`_to_spec_data`); ``rpm``: the
    operating range the command line gives — the file's is then not read, and the caller
    sets the rotor speed (``importers._with_speed``).

    A field wtvib needs that is missing is one line naming its path; anything else a
    hostile file can do to the reader (a number where a mapping goes, tables of unequal
    length) is one line naming the file and what failed — never a traceback.
    """
    try:
        return _to_spec_data(path, text, head_mass, clamped_base, soil, rpm)
    except SpecError:
        raise
    except (KeyError, TypeError, ValueError, IndexError, AttributeError) as exc:
        detail = f"{type(exc).__name__}: {exc}" if str(exc) else type(exc).__name__
        raise SpecError(
            "the windIO file does not have the shape wtvib reads (a field of the wrong type "
            f"or tables of different lengths): {detail}",
            source=str(path),
        ) from None


def _to_spec_data(
    path: Path,
    text: str,
    head_mass: float | None = None,
    clamped_base: bool = False,
    soil: dict[str, Any] | None = None,
    rpm: tuple[float, float] | None = None,
) -> dict[str, Any]:
    """wtvib spec data from a windIO turbine file.

    A floating turbine (``floating_platform``/``mooring`` components) stands on its platform
    (:mod:`.windio_platform`); with ``clamped_base`` the tower is audited as if clamped at its
    base instead, and the report says so in its headline.
    """
    d, floating, v2, version, notes = _document(path, text, clamped_base)
    reader = _Reader(d, path, v2)
    asm = d.get("assembly", {})
    blades = _blade_count(asm, path)
    speed = _speed(reader, rpm, path, notes)
    tower, tower_notes = reader.tower()
    if soil is not None:  # a soil profile beside the file (--soil): the pile stands on it
        tower_notes = _on_soil(reader, tower, tower_notes, soil, path)
    notes += tower_notes
    structure, blade_mass, blade_len = reader.blade()
    if structure is None:
        notes.append("No blade structural properties in the file: blade modes not computed.")
    head, head_note = reader.head(blades, blade_mass, structure, head_mass)
    notes.append(head_note)
    mass_warnings = reader.mass_warnings() if head_mass is None else []
    warnings = (
        [
            "tower.foundation: a floating turbine audited with the tower clamped at its base "
            "(--clamped-base): the platform's and moorings' modes and their effect on the "
            "tower are not modelled"
        ]
        if floating and clamped_base
        else []
    ) + mass_warnings
    if floating and not clamped_base:
        from .windio_platform import platform

        floater = platform(d, path, _carried(tower, head), reader.tower_base, v2)
        tower["foundation"] = {"kind": "platform", "platform": floater.block}
        notes += floater.notes
        warnings += floater.warnings
    data: dict[str, Any] = {
        "wtvib": 1,
        "turbine": {
            "name": str(d.get("name", path.stem)),
            **_opt("rated_power_kw", asm.get("rated_power"), 1e-3),
            **_opt("rotor_diameter_m", asm.get("rotor_diameter")),
            **_opt("hub_height_m", asm.get("hub_height")),
        },
        "sources": {"file": f"{path.name} ({version})"},
        "rotor": {
            "blades": blades,
            "orientation": "downwind"
            if str(asm.get("rotor_orientation", "upwind")).lower() == "downwind"
            else "upwind",
            "hub": "hingeless",
            "speed": speed,
        },
        "tower": tower,
        "tower_head": head,
        "blade": {"structure": structure, **_opt("length_m", blade_len)} if structure else {},
        "assumptions": notes,
        **({"warnings": warnings} if warnings else {}),
    }
    if blade_len:
        from .windio_aero import aerodynamics

        hub_r = float(d["components"].get("hub", {}).get("diameter", 0.0)) / 2.0
        aero = aerodynamics(d, v2, hub_r, blade_len, str(path))
        if aero is not None:
            data["aerodynamics"] = aero[0]
            notes.append(aero[1])
    _add_drivetrain(data, reader, blades, structure, notes)
    if structure and reader.apex:
        data["coupled"] = {**reader.apex, **reader.hub}
    return data


def _document(
    path: Path, text: str, clamped_base: bool
) -> tuple[dict[str, Any], list[str], bool, str, list[str]]:
    """The file's data (with the paths of its values), its floating components, whether it
    is windIO 2.x, its version's name, and the first notes: what was imported, the schema's
    check (2.x), a redefined YAML anchor. A file with moorings and no platform is refused
    (unless the tower is read clamped at its base)."""
    doc = parse_plain(text, str(path))
    d = _paths(doc.data, (), str(path))
    if not isinstance(d, dict) or "components" not in d:
        raise SpecError("not a windIO turbine file (no 'components')", source=str(path))
    floating = [c for c in FLOATING if c in d["components"]]
    if floating == ["mooring"] and not clamped_base:
        raise refusal(
            "components.mooring",
            "the file has moorings but no components.floating_platform",
            str(path),
            path="components.mooring",
        )
    v2 = "outer_shape" in d["components"].get("tower", {})
    version = f"windIO {d.get('windIO_version', '2.x' if v2 else '1.x')}"
    notes = [f"Imported from the {version} file {path.name}."]
    if v2:  # the windIO schema first, then what wtvib needs
        notes.append(_schema_checked(d, text, path))
    if doc.redefined_anchors:
        notes.append(
            "The file defines the YAML anchor(s) "
            + ", ".join(repr(a) for a in doc.redefined_anchors)
            + " twice; as YAML 1.2 allows, each alias uses the latest definition (PyYAML's "
            "safe_load would refuse the file)."
        )
    return d, floating, v2, version, notes


def _speed(
    reader: "_Reader", rpm: tuple[float, float] | None, path: Path, notes: list[str]
) -> dict[str, Any]:
    """The rotor's operating range as the file gives it (said in ``notes``), or nothing
    where the command line gives it (``rpm``: the caller sets it, importers._with_speed)."""
    if rpm is not None:
        return {}
    found_speed, speed_note = reader.speed()
    notes.append(speed_note)
    where = speed_note.split(":")[0].removeprefix("Operating range from ")
    return {**found_speed, "source": f"{where} of {path.name}"}


def _add_drivetrain(
    data: dict[str, Any],
    reader: "_Reader",
    blades: int,
    structure: dict[str, Any] | None,
    notes: list[str],
) -> None:
    """The drive train's gear ratio and its chain of inertias and shafts, where the file
    gives them."""
    gear = reader.gear_ratio()
    if gear:
        data["drivetrain"] = {"gear_ratio": gear}
    chain = reader.chain(blades, structure, gear or 1.0)
    if chain is not None:
        data["drivetrain"] = {**data.get("drivetrain", {}), **chain[0]}
        notes.append(chain[1])


def _schema_checked(d: dict[str, Any], text: str, path: Path) -> str:
    """What the windIO 2.x schema says of the file: a refusal (its first objection to a
    value, with field and line) or the statement that it was checked (the keys it requires
    and the file leaves out said), or could not be."""
    from . import windio_schema

    if not windio_schema.available():
        return (
            "Not checked against the windIO schema (the windio package is not installed: "
            "pip install 'wtvib[windio]'); wtvib's own checks apply."
        )
    every = windio_schema.objections(d)
    # a key the schema requires and the file leaves out is refused only where the audit
    # reads it (its own checks then name it): WISDEM's own examples leave out hub.cd,
    # a drag coefficient windIO 2.1 requires and no vibration audit reads
    left_out = [(bad, message) for bad, message, required in every if required]
    found = [(bad, message) for bad, message, required in every if not required]
    if found:
        bad, message = found[0]
        more = f" (and {len(found) - 1} more)" if len(found) > 1 else ""
        try:  # the line, from the careful reader (only on this error path)
            line = parse(text, str(path)).line_of(bad)
        except SpecError:
            line = None
        raise SpecError(
            f"the windIO 2.x schema refuses the file: {message}{more}",
            path=format_path(bad) or None,
            line=line,
            source=str(path),
        )
    if left_out:
        keys = ", ".join(
            f"{format_path(bad) or '(top)'}: {message.split(' is a required')[0]}"
            for bad, message in left_out
        )
        return (
            "Checked against the windIO 2.x turbine schema (the windio package's): the file "
            f"leaves out keys it requires ({keys}) — not read by this audit, which reads and "
            "checks what it needs itself."
        )
    return "Checked against the windIO 2.x turbine schema (the windio package's)."


def _blade_count(asm: dict[str, Any], path: Path) -> int:
    """assembly.number_of_blades (default 3), a whole number ≥ 1."""
    blades = asm.get("number_of_blades", 3)
    if isinstance(blades, bool) or not isinstance(blades, int) or blades < 1:
        raise SpecError(
            f"assembly.number_of_blades must be a whole number ≥ 1 (got {blades!r})",
            source=str(path),
        )
    return blades


def _on_soil(
    reader: "_Reader",
    tower: dict[str, Any],
    notes: list[str],
    soil: dict[str, Any],
    path: Path,
) -> list[str]:
    """The embedded pile stood on the soil profile given beside the file (``tower`` gets its
    foundation); the tower's notes with the clamp's statement replaced."""
    pile = reader.embedded
    if pile is None:
        raise SpecError(
            "--soil needs a monopile with an embedded part below the mudline; the file has none",
            source=str(path),
        )
    tower["foundation"] = {"kind": "soil", "pile": pile, **soil}
    return [
        n.replace(
            "the foundation is clamped at the mudline (rigid soil, the default soil "
            "treatment: no soil springs are in the file), so frequencies are an upper "
            "bound",
            "the embedded pile stands on the soil profile given with --soil",
        )
        for n in notes
    ]


class _Map(dict):  # type: ignore[type-arg]
    """A windIO mapping that knows where it is: a missing key is one line naming its path."""

    def __init__(self, items: Any, path: tuple[Any, ...], source: str) -> None:
        super().__init__(items)
        self.path, self.source = path, source

    def __missing__(self, key: Any) -> Any:
        where = ".".join(str(p) for p in (*self.path, key))
        raise SpecError(f"{where} is missing (wtvib reads it)", source=self.source)

    def __deepcopy__(self, memo: dict[int, Any]) -> "_Map":
        import copy

        return _Map({k: copy.deepcopy(v, memo) for k, v in self.items()}, self.path, self.source)


def _paths(node: Any, path: tuple[Any, ...], source: str) -> Any:
    """The parsed document with every mapping a :class:`_Map` (lists stay lists)."""
    if isinstance(node, dict):
        return _Map({k: _paths(v, (*path, k), source) for k, v in node.items()}, path, source)
    if isinstance(node, list):
        return [_paths(v, (*path, i), source) for i, v in enumerate(node)]
    return node


def _symmetric(upper: np.ndarray) -> np.ndarray:
    """Symmetric 6×6 matrices from their upper triangles, row-major (K11, K12, …, K66)."""
    rows, cols = np.triu_indices(6)
    full = np.zeros((len(upper), 6, 6))
    full[:, rows, cols] = upper
    full[:, cols, rows] = upper
    return full


#: rpm per rad/s: windIO 1.x gives its control block's rotor speeds in rad/s
_RPM_PER_RAD_S = 60.0 / (2.0 * math.pi)


def _number(value: Any) -> float:
    """A finite number from a control entry, else 0 (absent, text, a boolean, NaN)."""
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        return 0.0
    return float(value)


def _condensed(k: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Principal bending stiffnesses (about axis 1 and axis 2 turned by θ: the K44 and K55
    of the turned section), the torsional stiffness (K66) and θ [deg] of 6×6 section
    matrices with the other strains free: the 2×2 bending block of the inverted compliance,
    its principal axes, and 1/C66.

    The 6×6 matrices refer to the blade's reference axis; where the tension or shear centre
    lies off it, the diagonal terms K44/K55 include EA·offset² (bending–extension coupling)
    and overstate the stiffness of a beam free to stretch. Condensing the other strains out
    gives the bending stiffness about the section's own centres (Hodges, *Nonlinear
    Composite Beam Theory*, 2006, §4: static condensation of a cross-sectional stiffness
    matrix). The block's cross term K45 says the principal axes are turned from the
    section's axes (the aerodynamic twist's, in windIO and BeamDyn) by
    θ = ½·atan(2·K45/(K44 − K55)), |θ| < 45°, from axis 1 towards axis 2 — HAWC2's
    structural pitch: the IEA-15's HAWC2 st file's pitch column is this θ of the same
    blade's BeamDyn matrices to 0.1° (tests/validation/test_windio.py). Falls back to the
    diagonal (θ = 0) where a matrix is singular.
    """
    k44, k55, k66 = k[:, 3, 3].copy(), k[:, 4, 4].copy(), k[:, 5, 5].copy()
    theta = np.zeros(len(k))
    for i, mat in enumerate(k):
        try:
            c = np.linalg.inv(mat)
            bend = np.linalg.inv(c[3:5, 3:5])
        except np.linalg.LinAlgError:
            continue
        if not (np.all(np.isfinite(bend)) and bend[0, 0] > 0 and bend[1, 1] > 0 and c[5, 5] > 0):
            continue
        a, b, ab = bend[0, 0], bend[1, 1], 0.5 * (bend[0, 1] + bend[1, 0])
        t = 0.5 * math.atan(2.0 * ab / (a - b)) if a != b else (math.pi / 4 if ab else 0.0)
        cs, sn = math.cos(t), math.sin(t)
        one = a * cs * cs + 2.0 * ab * sn * cs + b * sn * sn
        two = a * sn * sn - 2.0 * ab * sn * cs + b * cs * cs
        if one > 0 and two > 0:  # else (a block no section has) the diagonal, unturned
            k44[i], k55[i], theta[i] = one, two, math.degrees(t)
        else:
            k44[i], k55[i] = a, b
        k66[i] = 1.0 / c[5, 5]
    return k44, k55, k66, theta


def _shear(k: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    """Transverse shear stiffnesses of 6×6 section matrices with the other strains free
    (:func:`_condensed`'s condensation of the shear block): the one that goes with K44's
    bending (about axis 1, deflecting along axis 2: K22's shear) and the one with K55's
    (K11's). None where a section has none (a zero or missing shear entry): the blade is
    then an Euler–Bernoulli beam."""
    s44, s55 = k[:, 1, 1].copy(), k[:, 0, 0].copy()
    for i, mat in enumerate(k):
        try:
            shear = np.linalg.inv(np.linalg.inv(mat)[0:2, 0:2])
        except np.linalg.LinAlgError:
            continue
        if np.all(np.isfinite(shear)) and shear[0, 0] > 0 and shear[1, 1] > 0:
            s44[i], s55[i] = shear[1, 1], shear[0, 0]
    if not (np.all(np.isfinite(s44)) and np.all(s44 > 0) and np.all(s55 > 0)):
        return None
    return s44, s55


def _carried(tower: dict[str, Any], head: dict[str, Any]) -> float:
    """The mass a platform carries: the tower (its sections, material and point masses)
    and the head [kg]."""
    sec, mat = tower["sections"], tower["material"]
    z = np.asarray(sec["height_m"])
    d = np.asarray(sec["outer_diameter_m"])
    t = np.asarray(sec["wall_thickness_m"])
    area = np.pi / 4 * (d**2 - (d - 2 * t) ** 2)
    steel = float(np.trapezoid(area, z)) * mat["density_kg_m3"] * mat.get("mass_factor", 1.0)
    points = sum(p["mass_kg"] for p in tower.get("point_masses", []))
    return float(steel + points + float(head["mass_kg"]))


def _opt(key: str, value: Any, scale: float = 1.0) -> dict[str, float]:
    return {} if value is None else {key: float(value) * scale}


def _at(field: dict[str, Any], grid: np.ndarray) -> np.ndarray:
    """A windIO ``{grid, values}`` field evaluated on another grid (linear)."""
    return np.asarray(
        np.interp(grid, np.asarray(field["grid"], float), np.asarray(field["values"], float))
    )


#: Two masses of one part differing by more than this factor are reported (wtvib's threshold:
#: the IEA-15 example's two generator masses differ by 0.7 %, the IEA-22's by 2.5×).
MASS_DISAGREEMENT = 1.25


class _Reader:
    def __init__(self, d: dict[str, Any], path: Path, v2: bool) -> None:
        self.d, self.path, self.v2 = d, path, v2
        self.c = d["components"]
        # where the rotor sits on the tower head and the hub (for the coupled model); set by
        # head() when it assembles the head from its parts
        self.apex: dict[str, float] = {}
        self.hub: dict[str, float] = {}
        self.embedded: dict[str, float] | None = None  # the monopile below the mudline
        self.tower_base = 0.0  # the tower's lowest station, z [m]

    @property
    def drivetrain(self) -> dict[str, Any]:
        """components.drivetrain (2.x), or the 1.x nacelle's; empty where neither is given."""
        found: dict[str, Any] = self.c.get("drivetrain") or self.c.get("nacelle", {}).get(
            "drivetrain", {}
        )
        return found

    def fail(self, message: str) -> SpecError:
        return SpecError(message, source=str(self.path))

    def fail_at(self, message: str, where: tuple[str | int, ...]) -> SpecError:
        """The error with the line of ``where`` in the file (read again, on this path only)."""
        from ..spec import read_text

        try:
            line = parse(read_text(self.path), str(self.path)).line_of(where)
        except SpecError:
            line = None
        return SpecError(message, path=format_path(where) or None, line=line, source=str(self.path))

    def field(
        self, value: Any, where: tuple[str | int, ...], grid: np.ndarray, positive: bool = True
    ) -> np.ndarray:
        """A windIO ``{grid, values}`` field on another grid — its own grid increasing from
        0 to 1 (np.interp would read an unsorted one silently wrong), its values finite and,
        where ``positive``, above 0 (a diameter or wall of 0 or less is no tube)."""
        try:
            g = np.asarray(value["grid"], float)
            v = np.asarray(value["values"], float)
        except (KeyError, TypeError, ValueError):
            raise self.fail_at(
                f"{format_path(where)} must be a grid and values of numbers", where
            ) from None
        if g.shape != v.shape or g.ndim != 1 or len(g) < 1:
            raise self.fail_at(
                f"{format_path(where)}: grid and values must be lists of one length", where
            )
        if not (np.all(np.isfinite(g)) and np.all(np.isfinite(v))):
            raise self.fail_at(
                f"{format_path(where)}: every grid point and value must be finite", where
            )
        if np.any(np.diff(g) < 0):
            raise self.fail_at(
                "must increase (it is sorted along the member)",
                (*where, "grid"),
            )
        if positive and np.any(v <= 0):
            k = int(np.flatnonzero(v <= 0)[0])
            raise self.fail_at(
                f"is {v[k]:g}: a tube's diameter and wall are positive", (*where, "values", k)
            )
        return np.asarray(np.interp(grid, g, v))

    def material(self, name: str) -> dict[str, Any]:
        """The named material, its E, G (where given) and ρ checked positive numbers; a
        list-valued modulus (windIO's orthotropic [E1, E2, E3]) gives its first, axial,
        component."""
        for i, m in enumerate(self.d.get("materials", [])):
            if not (isinstance(m, dict) and m.get("name") == name):
                continue
            out = dict(m)
            for key, what in (("E", "Young's modulus"), ("G", "shear modulus"), ("rho", "density")):
                if key not in m:
                    if key == "G":
                        continue
                    raise self.fail(f"materials[{i}].{key} is missing (wtvib reads its {what})")
                value = m[key]
                if isinstance(value, list) and value:
                    value = value[0]
                if not (
                    isinstance(value, (int, float))
                    and not isinstance(value, bool)
                    and math.isfinite(value)
                    and value > 0
                ):
                    raise self.fail(
                        f"materials[{i}].{key} ({name}): the {what} must be a positive number "
                        f"(got {m[key]!r})"
                    )
                out[key] = float(value)
            return out
        raise self.fail(f"material {name!r} is not in the file's materials")

    # -- rotor speed ------------------------------------------------------------------
    def speed(self) -> tuple[dict[str, float], str]:
        ctl = self.d.get("control", {})
        if "min_rotor_speed" in ctl and "rated_rotor_speed" in ctl:
            lo, rated = float(ctl["min_rotor_speed"]), float(ctl["rated_rotor_speed"])
            speed = {"min_rpm": lo, "rated_rpm": rated, "max_rpm": rated}
            top = float(ctl.get("max_rotor_speed", 0.0))
            note = (
                f"Operating range from control.min_rotor_speed/rated_rotor_speed: "
                f"{lo:.3g}–{rated:.3g} rpm"
            )
            if top > rated:
                speed["overspeed_rpm"] = top
                note += f"; control.max_rotor_speed {top:.3g} rpm checked as the overspeed limit"
            return speed, note + "."
        # the control blocks of 1.x, in rad/s — and of 2.0, whose geometry is 2.x's and whose
        # VS_minspd/VS_maxspd are rpm (windIO's own converter, converters/windIO2windIO.py,
        # v1p0_to_v2p0.convert_controls: "from rad/s to rpm"; WISDEM's 2.0 examples: the
        # NREL 5-MW's 6.9/12.1)
        torque = self._torque_speeds(ctl, 1.0 if self.v2 else _RPM_PER_RAD_S)
        if torque is not None:
            return torque
        sub = ctl.get("supervisory", {})
        lo, hi = _number(sub.get("minOmega")), _number(sub.get("maxOmega"))
        if 0 < lo < hi:
            return (
                {"min_rpm": lo * _RPM_PER_RAD_S, "max_rpm": hi * _RPM_PER_RAD_S},
                "Operating range from control.supervisory.minOmega/maxOmega (rad/s): "
                f"{lo * _RPM_PER_RAD_S:.3g}–{hi * _RPM_PER_RAD_S:.3g} rpm.",
            )
        raise self.fail(
            "no rotor speed range in 'control' (min/rated_rotor_speed, "
            "torque.VS_minspd/VS_maxspd or supervisory.minOmega/maxOmega); give "
            "--rpm MIN:MAX"
        )

    def _torque_speeds(
        self, ctl: dict[str, Any], factor: float
    ) -> tuple[dict[str, float], str] | None:
        """The rotor speeds of ``control.torque`` (VS_minspd, VS_maxspd: rpm in 2.0, rad/s in
        1.x): the range they give; where VS_minspd is 0 — no limit, as WISDEM's IEA-3.4 and
        BAR examples give it, with a VS_maxspd of 2 rad/s to match — as WISDEM runs the
        rotor (wisdem/rotorse/rotor_power.py: Ω = clip(tsr·V/R, VS_minspd, min(VS_maxspd,
        maxTS/R))): the lowest the region-2 tip-speed ratio's speed at cut-in, tsr·Vin/R
        (the IEA-3.4's 3.539 rpm, its OpenFAST deck's VS_MinOMSpd), the top the lower of
        VS_maxspd and the tip-speed limit supervisory.maxTS over the rotor radius. (Where
        the file gives a range, its VS_maxspd stands: WISDEM's tip-speed cap would take the
        IEA-15's rated 7.56 rpm 0.8 % down.) None where the block gives no range."""
        torque, sup = ctl.get("torque", {}), ctl.get("supervisory", {})
        lo, hi = (
            _number(torque.get("VS_minspd")) * factor,
            _number(torque.get("VS_maxspd")) * factor,
        )
        if 0 < lo < hi:  # a range the file means (the IEA-10's and IEA-15's rated speeds)
            where = f"control.torque.VS_minspd/VS_maxspd ({'rpm' if factor == 1.0 else 'rad/s'})"
            return {"min_rpm": lo, "max_rpm": hi}, (
                f"Operating range from {where}: {lo:.3g}–{hi:.3g} rpm."
            )
        radius = _number(self.d.get("assembly", {}).get("rotor_diameter")) / 2.0
        said: list[str] = []
        tip_speed = _number(sup.get("maxTS"))
        if hi > 0 and tip_speed > 0 and radius > 0 and tip_speed / radius * _RPM_PER_RAD_S < hi:
            hi = tip_speed / radius * _RPM_PER_RAD_S
            said.append(
                f"the top speed the tip-speed limit maxTS {tip_speed:g} m/s over R {radius:.4g} m"
            )
        tsr, cut_in = _number(torque.get("tsr")), _number(sup.get("Vin"))
        if lo == 0 and tsr > 0 and cut_in > 0 and radius > 0:
            lo = tsr * cut_in / radius * _RPM_PER_RAD_S
            said.append(
                f"the lowest the speed at cut-in, tsr {tsr:g} × Vin {cut_in:g} m/s / R "
                "(VS_minspd 0: no limit)"
            )
        if not 0 < lo < hi:  # where it holds now, the cut-in placed the lowest speed (said)
            return None
        other = ""
        low, high = _number(sup.get("minOmega")), _number(sup.get("maxOmega"))
        if 0 < low < high:  # a second range in the file, unused: said (the IEA-3.4 1.x file's
            # are the NREL 5-MW's 6.9–12.1 rpm)
            other = (
                f" (control.supervisory.minOmega/maxOmega give {low * _RPM_PER_RAD_S:.3g}–"
                f"{high * _RPM_PER_RAD_S:.3g} rpm: not used)"
            )
        return (
            {"min_rpm": lo, "max_rpm": hi},
            f"Operating range from control.torque and control.supervisory as WISDEM runs the "
            f"rotor: {lo:.4g}–{hi:.4g} rpm — {'; '.join(said)}{other}.",
        )

    # -- tower and monopile ---------------------------------------------------------
    def member(self, name: str) -> tuple[np.ndarray, np.ndarray, np.ndarray, dict[str, Any], float]:
        """Heights, outer diameters and wall thicknesses at the member's stations."""
        comp = self.c[name]
        shape = comp["outer_shape"] if self.v2 else comp["outer_shape_bem"]
        struct = comp["structure"] if self.v2 else comp["internal_structure_2d_fem"]
        axis = comp["reference_axis"] if self.v2 else shape["reference_axis"]
        grid = np.asarray(axis["z"]["grid"], float)
        z = np.asarray(axis["z"]["values"], float)
        where = f"components.{name}.reference_axis.z.values"
        if not np.all(np.isfinite(z)) or np.any(np.diff(z) < -1e-9):
            raise self.fail(f"{where} must be finite and increase from the base up")
        keep = np.concatenate([[True], np.diff(z) > 0.01])  # drop 1 mm "step" duplicates
        grid, z = grid[keep], z[keep]
        if len(z) < 2:
            raise self.fail(f"{where}: the {name} has no length (all its stations at one height)")
        part = "outer_shape" if self.v2 else "outer_shape_bem"
        inner = "structure" if self.v2 else "internal_structure_2d_fem"
        diameter = self.field(
            shape["outer_diameter"], ("components", name, part, "outer_diameter"), grid
        )
        layers = struct["layers"]
        thickness = np.zeros(len(grid))
        for i, layer in enumerate(layers):
            thickness = thickness + self.field(
                layer["thickness"], ("components", name, inner, "layers", i, "thickness"), grid
            )
        if np.any(thickness >= diameter / 2):
            k = int(np.flatnonzero(thickness >= diameter / 2)[0])
            raise self.fail_at(
                f"components.{name}: at z = {z[k]:g} m the wall ({float(thickness[k]):g} m) is "
                f"not less than half the diameter ({float(diameter[k]):g} m)",
                ("components", name, inner, "layers"),
            )
        mat = self.material(layers[0]["material"])
        return z, diameter, np.asarray(thickness), mat, float(struct.get("outfitting_factor", 1.0))

    def tower(self) -> tuple[dict[str, Any], list[str]]:
        z, dia, t, mat, factor = self.member("tower")
        notes = [
            f"Tower from {len(z)} stations of outer diameter and wall thickness, "
            f"{mat['name']} (E = {float(mat['E']):.3g} Pa, ρ = {float(mat['rho']):.4g} "
            f"kg/m³), outfitting factor {factor:g}."
        ]
        base = z[0]
        self.tower_base = float(z[0])
        masses = []
        water = None  # the monopile's added mass and its note
        if "monopile" in self.c:
            mz, mdia, mt, mmat, mfactor = self.member("monopile")
            mudline, how = self.mudline(mz)
            if not mz[0] - 1e-6 <= mudline < mz[-1]:
                raise self.fail(
                    f"{how} puts the mudline at z = {mudline:g} m, outside the monopile "
                    f"(z = {mz[0]:g} … {mz[-1]:g} m)"
                )
            gap = z[0] - mz[-1]
            if abs(gap) > max(0.5, 0.01 * (z[-1] - z[0])):
                raise self.fail(
                    f"the tower starts at z = {z[0]:g} m but the monopile ends at z = "
                    f"{mz[-1]:g} m ({'a gap' if gap > 0 else 'an overlap'} of {abs(gap):g} m); "
                    "components.tower and components.monopile reference_axis.z must meet"
                )
            # the part below the mudline: the pile a soil model (--soil) stands on
            below = mz <= mudline + 1e-9
            self.embedded = (
                {
                    "embedded_length_m": float(mudline - mz[0]),
                    "diameter_m": float(np.interp(mudline, mz, mdia)),
                    "wall_thickness_m": float(np.mean(mt[below])),
                    "youngs_modulus_pa": mmat["E"],
                }
                if mudline - mz[0] > 1e-6
                else None
            )
            mz, mdia, mt = _above(mudline, mz, mdia, mt)
            upper = z > mz[-1] + 1e-9
            z = np.concatenate([mz, z[upper]])
            dia = np.concatenate([mdia, dia[upper]])
            t = np.concatenate([mt, t[upper]])
            base = mudline
            tp = float(self.c["monopile"].get("transition_piece_mass", 0.0))
            if tp:
                masses.append({"height_m": float(mz[-1] - base), "mass_kg": tp})
            notes.append(
                f"Monopile included from the mudline ({how}) up to the tower base; the "
                "foundation is clamped at the mudline (rigid soil, the default soil treatment: "
                "no soil springs are in the file), so frequencies are an upper bound; "
                f"transition piece {tp:,.0f} kg as a point mass."
            )
            if mmat["name"] != mat["name"] or mfactor != factor:
                notes.append("Monopile material/outfitting taken equal to the tower's.")
            water = self.monopile_water(mz, mdia, base)
            if water is not None:
                notes.append(water[1])
        tower = {
            "height_m": float(z[-1] - base),
            "sections": {
                "height_m": _list(z - base),
                "outer_diameter_m": _list(dia),
                "wall_thickness_m": _list(t),
            },
            "material": {
                "youngs_modulus_pa": mat["E"],
                **({"shear_modulus_pa": mat["G"]} if "G" in mat else {}),
                "density_kg_m3": mat["rho"],
                "mass_factor": factor,
            },
            "point_masses": masses,
        }
        if water is not None:
            tower["added_mass"] = water[0]
        return tower, notes

    def monopile_water(
        self, z: np.ndarray, dia: np.ndarray, base: float
    ) -> tuple[dict[str, Any], str] | None:
        """The water the monopile moves in bending, below the still-water level (z = 0,
        windIO's mean sea level) and above the mudline ``base``: Ca·ρ_w·πD²/4 per length, Ca = 1
        (windIO gives a monopile's drag coefficient, no added-mass coefficient: a circular
        cylinder's potential-flow value, HydroDyn's usual member Ca and what DTU's windIO-to-
        HAWC2 converter writes for a monopile), ρ_w from environment.water_density; None where
        the pile stands in no water."""
        if base >= 0.0 or z[-1] <= base:
            return None
        env = self.d.get("environment") or {}
        raw = env.get("water_density", 1025.0) if isinstance(env, dict) else 1025.0
        try:
            rho = float(raw)
        except (TypeError, ValueError):
            raise self.fail_at(
                f"environment.water_density must be a number (got {raw!r})",
                ("environment", "water_density"),
            ) from None
        if not 500.0 <= rho <= 2000.0:
            raise self.fail_at(
                f"environment.water_density {rho:g} kg/m³ is no water's",
                ("environment", "water_density"),
            )
        top = min(0.0, float(z[-1]))
        levels = np.unique(np.concatenate([z[(z >= base) & (z <= top)], [base, top]]))
        diameter = np.interp(levels, z, dia)
        mass = rho * np.pi * diameter**2 / 4
        note = (
            f"The monopile's water: Ca·ρ_w·πD²/4 per length from the mudline to the still-water "
            f"level ({float(mass[0]):,.0f} kg/m at the mudline; Ca = 1 assumed — windIO gives "
            f"no added-mass coefficient —, ρ_w = {rho:g} kg/m³) moves with it in bending; a "
            "flooded pile's inner water, which the file does not say, is left out."
        )
        return {
            "height_m": _list(levels - base),
            "mass_per_length_kg_m": _list(mass),
            "source": "windIO monopile outer diameter below the still-water level, Ca = 1",
        }, note

    def mudline(self, mz: np.ndarray) -> tuple[float, str]:
        depth = self.d.get("environment", {}).get("water_depth")
        if depth is not None:
            return -float(depth), f"environment.water_depth = {float(depth):g} m"
        if len(mz) > 2:
            return float(mz[1]), (
                "no water depth in the file: taken at the top of the lowest "
                f"(embedded) monopile segment, z = {mz[1]:g} m"
            )
        return float(mz[0]), "no water depth in the file: taken at the pile's lowest station"

    # -- blade -----------------------------------------------------------------------
    def blade(self) -> tuple[dict[str, Any] | None, float | None, float | None]:
        b = self.c["blade"]
        axis = b["reference_axis"] if self.v2 else b["outer_shape_bem"]["reference_axis"]
        z = axis["z"]
        length = float(np.asarray(z["values"], float)[-1] - np.asarray(z["values"], float)[0])
        hub_r = float(self.c.get("hub", {}).get("diameter", 0.0)) / 2.0
        if self.v2:
            ep = b.get("structure", {}).get("elastic_properties")
            if not ep:
                return None, None, length
            grid = np.asarray(ep["stiffness_matrix"]["grid"], float)
            k = ep["stiffness_matrix"]
            im = ep["inertia_matrix"]
            mass = _at({"grid": im["grid"], "values": im["mass"]}, grid)
            upper = [
                np.asarray(k.get(f"K{a + 1}{c + 1}", np.zeros(len(grid))), float)
                for a, c in zip(*np.triu_indices(6), strict=True)
            ]
            six = _symmetric(np.stack(upper, axis=1))
            flap, edge, gj, turned = _condensed(six)
            shear = _shear(six)
            ip = _at({"grid": im["grid"], "values": im["i_plr"]}, grid) if "i_plr" in im else None
            twist = _at(b["outer_shape"]["twist"], grid)  # degrees in 2.x
        else:
            six = b.get("elastic_properties_mb", {}).get("six_x_six", {})
            if "stiff_matrix" not in six:
                return None, None, length
            grid = np.asarray(six["stiff_matrix"]["grid"], float)
            kv = np.asarray(six["stiff_matrix"]["values"], float)
            mv = np.asarray(six["inertia_matrix"]["values"], float)
            flap, edge, gj, turned = _condensed(_symmetric(kv[:, :21]))
            shear = _shear(_symmetric(kv[:, :21]))
            mass, ip = mv[:, _UT["mass"]], mv[:, _UT["i_plr"]]
            twist = np.degrees(_at(six["twist"], grid))  # radians in 1.x
        if np.count_nonzero(flap > edge) > len(flap) / 2:
            # The schema text calls K44 flapwise, but the published IEA-15/22 files follow
            # BeamDyn (K44 edgewise): the lower stiffness over most of the span is flapwise.
            flap, edge = edge, flap
            shear = shear[::-1] if shear is not None else None
        else:
            # the schema's axes (x to the trailing edge, y to the suction side) are BeamDyn's
            # (x to the suction side, y to the trailing edge) named the other way round: a
            # turn from axis 1 towards axis 2 is the opposite turn about the span
            turned = -turned
        # the principal axes: the aerodynamic twist less the matrices' own turn (θ from
        # BeamDyn's axis 1 towards axis 2, HAWC2's structural pitch: _condensed)
        twist = twist - turned
        span = grid * length
        structure: dict[str, Any] = {
            "hub_radius_m": hub_r,
            "span_m": _list(span),
            "mass_per_length_kg_m": _list(np.maximum(mass, 1e-6)),
            "ei_flap_nm2": _list(flap),
            "ei_edge_nm2": _list(edge),
            "twist_deg": _list(twist),
        }
        if ip is not None and np.all(ip > 0) and np.all(gj > 0):
            structure["gj_nm2"] = _list(gj)
            structure["torsional_inertia_kgm"] = _list(ip)
        if shear is not None:  # the shear with each bending: K22 with K44, K11 with K55
            structure["ga_flap_n"], structure["ga_edge_n"] = _list(shear[0]), _list(shear[1])
        return structure, float(np.trapezoid(mass, span)), length

    # -- tower head ---------------------------------------------------------------------
    def mass_warnings(self) -> list[str]:
        """Masses the file gives twice and differently (the IEA-22 2.1.1 example's
        generator is 508 t as ``mass`` and 1,269 t as ``elastic_properties.mass``, and its
        nacelle 1,565 t against 821 t in the turbine's OpenFAST deck)."""
        dt = self.drivetrain
        out = []
        hub = self.c.get("hub")
        if not (isinstance(hub, dict) and "mass" in (hub.get("elastic_properties") or {})):
            out.append(
                "components.hub: no elastic_properties.mass — the tower head is assembled "
                "without the hub (16 % of the NREL 5-MW's: 56.8 of 350 t), so its tower "
                "frequencies come out high; give the hub's mass, or the head's with --head-mass"
            )
        for name in ("generator", "gearbox", "bedplate"):
            part = dt.get(name) if isinstance(dt, dict) else None
            if not isinstance(part, dict):
                continue
            given = (part.get("mass"), (part.get("elastic_properties") or {}).get("mass"))
            if not all(isinstance(v, int | float) and math.isfinite(v) and v > 0 for v in given):
                continue
            a, b = float(given[0]), float(given[1])  # type: ignore[arg-type]
            ratio = max(a, b) / min(a, b)
            if ratio > MASS_DISAGREEMENT:
                nacelle = (dt.get("elastic_properties") or {}).get("mass")
                text = (
                    f"components.drivetrain.{name}: mass {a:,.0f} kg but "
                    f"elastic_properties.mass {b:,.0f} kg ({ratio:.1f}×) — the file gives two "
                    "masses for one part"
                )
                if isinstance(nacelle, int | float):
                    text += (
                        f"; the nacelle's elastic_properties.mass {nacelle:,.0f} kg, which the "
                        "tower head uses, may carry the larger: check it (--head-mass, or "
                        "convert and edit tower_head)"
                    )
                out.append(text)
        return out

    def head(
        self,
        blades: int,
        blade_mass: float | None,
        structure: dict[str, Any] | None,
        head_mass: float | None,
    ) -> tuple[dict[str, float], str]:
        """The tower head: the hub, nacelle and yaw bearing's masses with the blades on the
        hub, about the tower top — or the command line's mass (``head_mass``)."""
        shape = self.drivetrain.get("outer_shape", self.drivetrain)
        hub_x = -float(shape.get("overhang", 0.0))
        hub_z = float(shape.get("distance_tt_hub", 0.0))
        rotor: list[Part] = []
        j_polar = 0.0
        if blade_mass and structure:
            j_polar = _rotor_polar(structure, blades)
            rotor.append(
                Part(f"{blades} blades", blades * blade_mass, hub_x, hub_z,
                     0.5 * j_polar, j_polar, 0.5 * j_polar)
            )  # fmt: skip
        if head_mass is not None:
            return self._given_head(head_mass, rotor, hub_x, hub_z, j_polar)
        parts = self._head_parts(hub_x, hub_z) + rotor
        self.apex = {"apex_downwind_m": hub_x, "apex_above_top_m": hub_z}
        head = assembled(parts).as_head()
        text = (
            "Tower head assembled from its parts: "
            + ", ".join(
                f"{p.name} {p.mass:,.0f} kg at x = {p.x:.2f} m, z = {p.z:.2f} m" for p in parts
            )
            + f"; total {head['mass_kg']:,.0f} kg (rotor polar inertia {j_polar:,.0f} kg·m², "
            "shaft tilt neglected)."
        )
        return head, text

    def _given_head(
        self, head_mass: float, rotor: "list[Part]", hub_x: float, hub_z: float, j_polar: float
    ) -> tuple[dict[str, float], str]:
        """The command line's tower-head mass (``--head-mass``): where the file gives the
        blades, they stand at the hub with their own inertia (the rotor's is most of the
        head's: dropping it puts the tower's modes 10–30 % high), the rest of the mass half-way
        to the hub as a point; without blades, all of it there, inertias neglected."""
        blades = rotor[0].mass if rotor else 0.0
        if blades >= head_mass:
            raise SpecError(
                f"--head-mass {head_mass:,.0f} kg is not more than the blades' "
                f"{blades:,.0f} kg the file gives: the tower head is the rotor and the "
                "nacelle together",
                source=str(self.path),
            )
        rest = Part("nacelle and hub (the rest)", head_mass - blades, hub_x / 2, hub_z / 2)
        if not rotor:
            return (
                {"mass_kg": head_mass, "cm_downwind_m": hub_x / 2, "cm_above_top_m": hub_z / 2},
                f"Tower head mass {head_mass:,.0f} kg given on the command line (CM taken "
                "half-way to the hub; inertias neglected: the file gives no blades).",
            )
        self.apex = {"apex_downwind_m": hub_x, "apex_above_top_m": hub_z}
        head = assembled([*rotor, rest]).as_head()
        return head, (
            f"Tower head mass {head_mass:,.0f} kg given on the command line: the file's "
            f"{rotor[0].name} ({blades:,.0f} kg, rotor polar inertia {j_polar:,.0f} kg·m²) at the "
            f"hub, x = {hub_x:.2f} m, z = {hub_z:.2f} m, the rest ({head_mass - blades:,.0f} kg: "
            "nacelle and hub) half-way to it as a point mass — their own inertias neglected."
        )

    def _head_parts(self, hub_x: float, hub_z: float) -> "list[Part]":
        """The hub (at the hub centre), the nacelle (its inertia given about the tower top:
        moved to its own centre of mass) and the yaw bearing, where the file gives their
        masses; the nacelle is required."""
        parts: list[Part] = []
        for name, comp in (
            ("hub", self.c.get("hub", {})),
            ("nacelle", self.drivetrain),
            ("yaw", self.c.get("yaw", {})),
        ):
            ep = comp.get("elastic_properties") if isinstance(comp, dict) else None
            if not ep or "mass" not in ep:
                continue
            m = float(ep["mass"])
            if not (math.isfinite(m) and m >= 0):
                raise SpecError(
                    f"components.{name}.elastic_properties.mass must be a mass ≥ 0 kg "
                    f"(got {ep['mass']!r})",
                    source=str(self.path),
                )
            if name == "hub":
                ii = ep.get("inertia", [0, 0, 0])
                parts.append(Part(name, m, hub_x, hub_z, float(ii[1]), float(ii[0]), float(ii[2])))
                self.hub = {"hub_mass_kg": m, "hub_inertia_kgm2": float(ii[0])}
                continue
            loc = ep.get("location", [0.0, 0.0, 0.0])
            x, z = float(loc[0]), float(loc[2])
            if name == "nacelle":
                tt = ep.get("inertia_tt", ep.get("inertia", [0, 0, 0]))
                own = (
                    float(tt[1]) - m * (x * x + z * z),
                    float(tt[0]) - m * z * z,
                    float(tt[2]) - m * x * x,
                )
                parts.append(Part(name, m, x, z, *own))
            else:
                parts.append(Part(name, m, x, z))
        if not any(p.name == "nacelle" for p in parts):
            raise self.fail(
                "the file gives no nacelle/hub masses (windIO files may leave them to WISDEM, "
                "which sizes them); give the whole tower head's mass — blades, hub, nacelle "
                "and yaw bearing together, not an OpenFAST deck's HubMass + NacMass + "
                "YawBrMass alone — with --head-mass KG, or convert and edit tower_head"
            )
        return parts

    def chain(
        self, blades: int, structure: dict[str, Any] | None, gear: float
    ) -> tuple[dict[str, Any], str] | None:
        """The drive train as a chain — blades, hub, generator — where the file gives the
        shaft's spring (``drivetrain.elastic_properties.spring_constant``) and the
        generator's inertia (``generator.elastic_properties.inertia``, its first entry, about
        the shaft), read as WISDEM writes an ElastoDyn deck from the same file (GenIner,
        DTTorSpr, DTTorDmp, HubIner: the IEA-15-240-RWT's deck holds these numbers); None
        without them or the blades' mass."""
        dt = self.drivetrain
        ep = dt.get("elastic_properties") or {}
        gen = (dt.get("generator") or {}).get("elastic_properties") or {}
        spring, inertia = ep.get("spring_constant"), gen.get("inertia")
        if not spring or not inertia or not structure:
            return None
        j_blades = _rotor_polar(structure, blades)
        hub_inertia = ((self.c.get("hub") or {}).get("elastic_properties") or {}).get("inertia")
        raw = {
            "drivetrain.elastic_properties.spring_constant": spring,
            "drivetrain.generator.elastic_properties.inertia[0]": _first(inertia),
            "hub.elastic_properties.inertia[0]": _first(hub_inertia) if hub_inertia else 0.0,
            "drivetrain.elastic_properties.damping_coefficient": ep.get("damping_coefficient")
            or 0.0,
        }
        values: dict[str, float] = {}
        for name, v in raw.items():
            try:
                values[name] = float(v)
            except (TypeError, ValueError):
                raise self.fail(f"components.{name} must be a number (got {v!r})") from None
            may_be_zero = name.startswith(("hub", "drivetrain.elastic_properties.damping"))
            ok = values[name] >= 0 if may_be_zero else values[name] > 0
            if not (math.isfinite(values[name]) and ok):
                raise self.fail(f"components.{name} must be positive (got {v!r})")
        spring = values["drivetrain.elastic_properties.spring_constant"]
        j_gen = values["drivetrain.generator.elastic_properties.inertia[0]"]
        j_hub = values["hub.elastic_properties.inertia[0]"]
        damping = values["drivetrain.elastic_properties.damping_coefficient"]
        chain: list[dict[str, Any]] = [
            {"name": "blades", "inertia_kgm2": j_blades},
            *([{"name": "hub", "inertia_kgm2": j_hub}] if j_hub > 0 else []),
            {"name": "generator", "inertia_kgm2": j_gen, "speed_ratio": gear},
        ]
        # blades to hub: the blades' edgewise spring alone; the shaft on to the generator
        shafts: list[dict[str, Any]] = [{"stiffness_nm_rad": None} for _ in chain[2:]]
        shafts.append({"stiffness_nm_rad": spring, "damping_nms_rad": damping})
        note = (
            f"Drive train: blades {j_blades:,.0f} kg·m² (N·∫m·r² dr), "
            + (f"hub {j_hub:,.0f} kg·m², " if j_hub > 0 else "")
            + f"generator {j_gen:,.0f} kg·m² (its elastic inertia about the shaft; on the "
            f"{'rotor' if gear == 1 else f'{gear:g}:1 generator'} shaft), shaft "
            f"{spring:.4g} N·m/rad and {damping:.4g} N·m·s/rad "
            "(drivetrain.elastic_properties) — as WISDEM writes GenIner, HubIner, DTTorSpr and "
            "DTTorDmp into an ElastoDyn deck; the blades' edgewise flexibility between blades "
            "and hub."
        )
        return {"chain": chain, "shafts": shafts}, note

    def gear_ratio(self) -> float | None:
        dt = self.drivetrain
        ratio = (dt.get("gearbox") or {}).get("gear_ratio", dt.get("gear_ratio"))
        return float(ratio) if ratio else None


def _rotor_polar(structure: dict[str, Any], blades: int) -> float:
    """The blades' polar inertia about the rotor axis, N·∫m·r² dr [kg·m²]."""
    span = np.asarray(structure["span_m"], float)
    per_length = np.asarray(structure["mass_per_length_kg_m"], float)
    return blades * float(np.trapezoid(per_length * (structure["hub_radius_m"] + span) ** 2, span))


def _first(value: Any) -> Any:
    """The first entry of a windIO inertia list (about the shaft), or the value itself."""
    return value[0] if isinstance(value, list) and value else value


def _list(a: np.ndarray) -> list[float]:
    return [float(f"{v:.10g}") for v in np.asarray(a, float)]


def _above(
    mudline: float, z: np.ndarray, dia: np.ndarray, t: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A pile's stations (heights, diameters, walls) from the mudline up: a station added
    at the mudline where it falls between two, its diameter and wall interpolated."""
    keep = z >= mudline - 1e-9
    if mudline in z:
        return z[keep], dia[keep], t[keep]
    cut = np.interp(mudline, z, np.arange(len(z)))
    i = int(cut)
    frac = cut - i
    dia_m = dia[i] + frac * (dia[i + 1] - dia[i])
    t_m = t[i] + frac * (t[i + 1] - t[i])
    return (
        np.concatenate([[mudline], z[keep]]),
        np.concatenate([[dia_m], dia[keep]]),
        np.concatenate([[t_m], t[keep]]),
    )
