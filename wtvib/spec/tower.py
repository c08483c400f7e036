"""The tower: given modes or its structure (tube sections or distributed properties),
head and foundation."""

import itertools
import math
from typing import Annotated, Literal

from pydantic import Field, model_validator

from .base import (
    Height,
    ModeEntry,
    Positive,
    Ratio,
    ShapePolynomial,
    StiffnessDamping,
    TableRows,
    TowerModeName,
    TowerSize,
    _increasing,
    _same_length,
    _Strict,
)


class Material(_Strict):
    """An isotropic material (steel by default values in the catalogue)."""

    youngs_modulus_pa: Positive = Field(description="Young's modulus E. [Pa]")
    shear_modulus_pa: Positive | None = Field(
        None, description="Shear modulus G; default E / (2·(1 + 0.3)). [Pa]"
    )
    density_kg_m3: Positive = Field(description="Density. [kg/m³]")
    mass_factor: Positive = Field(
        1.0, description="Outfitting factor on the shell mass (flanges, paint, bolts). [-]"
    )

    @property
    def shear(self) -> float:
        """G, given or from E with Poisson's ratio 0.3 (steel). [Pa]"""
        return self.shear_modulus_pa or self.youngs_modulus_pa / 2.6


class TubularSections(_Strict):
    """A tapered tube: outer diameter and wall thickness at stations, linear in between."""

    height_m: list[Height] = Field(description="Station heights above the tower base. [m]")
    outer_diameter_m: list[TowerSize] = Field(description="Outer diameter. [m]")
    wall_thickness_m: list[TowerSize] = Field(description="Wall thickness. [m]")

    @model_validator(mode="after")
    def _consistent(self) -> "TubularSections":
        _increasing("height_m", self.height_m)
        _same_length(self, "height_m")
        for i, (d, t) in enumerate(zip(self.outer_diameter_m, self.wall_thickness_m, strict=True)):
            if 2 * t >= d:
                raise ValueError(
                    f"station {i}: wall thickness {t} m is not less than half the diameter {d} m"
                )
        return self


class DistributedTower(_Strict):
    """A tower as a table of distributed properties (as in ElastoDyn tower files)."""

    height_m: list[Height] = Field(description="Station heights above the tower base. [m]")
    mass_per_length_kg_m: list[Positive] = Field(description="Mass per length. [kg/m]")
    ei_fa_nm2: list[Positive] = Field(description="Fore-aft bending stiffness. [N·m²]")
    ei_ss_nm2: list[Positive] = Field(description="Side-side bending stiffness. [N·m²]")
    gj_nm2: list[Positive] | None = Field(None, description="Torsional stiffness. [N·m²]")
    polar_inertia_kgm: list[Positive] | None = Field(
        None, description="Polar mass moment of inertia per length. [kg·m]"
    )
    rows: TableRows | None = Field(
        None, description="Where the stations stand in the file they were read from."
    )

    @model_validator(mode="after")
    def _consistent(self) -> "DistributedTower":
        _increasing("height_m", self.height_m)
        _same_length(self, "height_m")
        if (self.gj_nm2 is None) != (self.polar_inertia_kgm is None):
            raise ValueError("give gj_nm2 and polar_inertia_kgm together (torsion needs both)")
        return self


class PointMass(_Strict):
    """A concentrated mass on the tower (flange, platform, transition piece)."""

    height_m: Height = Field(description="Height above the tower base. [m]")
    mass_kg: Positive = Field(description="Mass. [kg]")


class MassDamper(_Strict):
    """A tuned mass damper on the tower or the nacelle (OpenFAST ServoDyn's structural
    control, StC): a mass on a spring and a dashpot, moving in one bending plane of the
    tower — its own mode, and the damping it lends the tower's modes near it (Den Hartog,
    *Mechanical Vibrations*, 4th ed., 1956, §3.3)."""

    name: str = Field(max_length=100, description="Where it comes from (e.g. the StC file).")
    on: Literal["tower", "nacelle"] = Field(
        description="What it is mounted on: a point of the tower, or the nacelle (the tower "
        "top, with the nacelle's rotation)."
    )
    height_m: Annotated[float, Field(ge=-1e3, le=1e4)] = Field(
        description="Its rest position: above the tower base (on the tower), or above the "
        "tower top (on the nacelle). [m]"
    )
    direction: Literal["fore-aft", "side-side"] = Field(
        description="The plane it moves in (OpenFAST's StC X: fore-aft, Y: side-side)."
    )
    mass_kg: Positive = Field(description="Moving mass. [kg]")
    stiffness_n_m: Positive = Field(description="Spring stiffness. [N/m]")
    damping_ns_m: Annotated[float, Field(ge=0, le=1e12)] = Field(
        0.0, description="Dashpot damping coefficient. [N·s/m]"
    )

    @property
    def frequency_hz(self) -> float:
        """Its own frequency on a rigid mount, √(k/m)/2π. [Hz]"""
        return math.sqrt(self.stiffness_n_m / self.mass_kg) / (2 * math.pi)

    @property
    def damping_ratio(self) -> float:
        """Its own damping ratio on a rigid mount, c/(2√(km)). [-]"""
        return self.damping_ns_m / (2 * math.sqrt(self.stiffness_n_m * self.mass_kg))


class AddedMass(_Strict):
    """Mass per length that moves with the tower in bending but is not the tower's own: the
    water a submerged monopile accelerates (hydrodynamic added mass, Ca·ρ_w·πD²/4), the
    water inside a flooded pile, marine growth. Its weight is not counted (the water's is
    carried by buoyancy). Zero between stations outside the given range."""

    height_m: list[Height] = Field(description="Station heights above the tower base. [m]")
    mass_per_length_kg_m: list[Annotated[float, Field(ge=0, le=1e7)]] = Field(
        description="Added mass per length. [kg/m]"
    )
    source: str | None = Field(None, max_length=2000, description="Where it comes from.")

    @model_validator(mode="after")
    def _consistent(self) -> "AddedMass":
        _increasing("added_mass.height_m", self.height_m)
        if len(self.mass_per_length_kg_m) != len(self.height_m):
            raise ValueError(
                f"mass_per_length_kg_m has {len(self.mass_per_length_kg_m)} values but "
                f"height_m has {len(self.height_m)}"
            )
        return self


class Pile(_Strict):
    """The embedded part of a monopile, below the mudline (the tower's base)."""

    embedded_length_m: Annotated[float, Field(ge=0.1, le=200)] = Field(
        description="Pile length below the mudline. [m]"
    )
    diameter_m: Annotated[float, Field(gt=0, le=30)] = Field(description="Outer diameter. [m]")
    wall_thickness_m: TowerSize = Field(description="Wall thickness. [m]")
    youngs_modulus_pa: Positive = Field(2.1e11, description="Young's modulus (steel). [Pa]")

    @model_validator(mode="after")
    def _wall(self) -> "Pile":
        if 2 * self.wall_thickness_m >= self.diameter_m:
            raise ValueError("wall_thickness_m must be less than half the diameter")
        return self


class SoilLayer(_Strict):
    """A soil layer down to ``bottom_m`` below the mudline, as an initial lateral (p-y)
    stiffness per unit pile length E_py [N/m²]: sand from its friction angle, stiff clay
    from its undrained shear strength (E_py = k·z, k the initial modulus of subgrade
    reaction; wtvib.subsystems.soil), or E_py given (soft clay or a site's own value: at the layer's
    top plus a gradient with depth)."""

    bottom_m: Annotated[float, Field(gt=0, le=500)] = Field(
        description="Depth of the layer's bottom below the mudline. [m]"
    )
    kind: Literal["sand", "clay", "modulus"] = Field(
        description="sand (friction angle), clay (undrained shear strength) or modulus."
    )
    friction_angle_deg: Annotated[float, Field(ge=25, le=45)] | None = Field(
        None, description="Sand: effective friction angle φ′. [deg]"
    )
    undrained_shear_strength_pa: Annotated[float, Field(ge=50e3, le=400e3)] | None = Field(
        None,
        description="Stiff clay: undrained shear strength s_u, 50-400 kPa (the stiff clay of "
        "Reese et al. 1975, whose initial p-y slope wtvib uses; softer or harder clay: kind "
        "modulus with its E_py). [Pa]",
    )
    modulus_pa: Annotated[float, Field(ge=0, le=1e11)] | None = Field(
        None, description="E_py at the layer's top. [N/m²]"
    )
    gradient_pa_m: Annotated[float, Field(ge=0, le=1e10)] = Field(
        0.0, description="Increase of E_py with depth in the layer. [N/m³]"
    )

    @model_validator(mode="after")
    def _given(self) -> "SoilLayer":
        # each kind's required field, then the optional ones it also uses
        needs, *also = {
            "sand": ("friction_angle_deg",),
            "clay": ("undrained_shear_strength_pa",),
            "modulus": ("modulus_pa", "gradient_pa_m"),
        }[self.kind]
        if getattr(self, needs) is None:
            raise ValueError(f"a {self.kind} layer needs {needs}")
        uses = {needs, *also}
        unused = [
            name
            for name, field in type(self).model_fields.items()
            if name not in uses | {"bottom_m", "kind"} and getattr(self, name) != field.default
        ]
        if unused:
            raise ValueError(f"{', '.join(unused)} is not used by a {self.kind} layer")
        return self


class SoilBounds(_Strict):
    """Lower- and upper-bound soil: factors on every layer's stiffness."""

    lower: Annotated[float, Field(gt=0, le=1)] = Field(
        0.5, description="Factor of the lower-bound soil (default 0.5: half as stiff). [-]"
    )
    upper: Annotated[float, Field(ge=1, le=10)] = Field(
        2.0, description="Factor of the upper-bound soil (default 2: twice as stiff). [-]"
    )


class SoilProfile(_Strict):
    """A soil profile file for an imported monopile (``check --soil FILE``): the ``soil``
    layers and optional ``bounds`` of a spec's foundation, validated on their own so that a
    mistake names that file and its line."""

    soil: list[SoilLayer] = Field(min_length=1, max_length=50, description="Layers, top down.")
    bounds: SoilBounds | None = Field(None, description="Lower- and upper-bound soil.")


Matrix6 = Annotated[
    list[
        Annotated[
            list[Annotated[float, Field(ge=-1e16, le=1e16)]], Field(min_length=6, max_length=6)
        ]
    ],
    Field(min_length=6, max_length=6),
]


class AddedMassPoint(_Strict):
    """The platform's added mass at one frequency (a row set of a WAMIT .1 file)."""

    frequency_hz: float = Field(
        ge=0, le=1e3, description="Frequency (0: the zero-frequency limit). [Hz]"
    )
    matrix: Matrix6 = Field(
        description="Added mass at the PRP at this frequency. [kg, kg·m, kg·m²]"
    )


#: A wave period [s]: swell and wind sea lie between 1 and 100 s.
WavePeriod = Annotated[float, Field(ge=0.5, le=100)]


class Platform(_Strict):
    """A floating platform under the tower: a rigid body with six degrees of freedom (surge,
    sway, heave, roll, pitch, yaw) about its reference point (PRP, on the still-water line
    below the tower axis), its matrices in that order (OpenFAST's)."""

    tower_base_m: Annotated[float, Field(ge=-200, le=500)] = Field(
        description="Height of the tower base above the PRP. [m]"
    )
    mass_kg: Positive = Field(description="Platform mass (structure and ballast). [kg]")
    cm_m: Annotated[float, Field(ge=-1000, le=500)] = Field(
        description="Height of the platform's centre of mass above the PRP (negative: below). [m]"
    )
    inertia_roll_kgm2: float = Field(ge=0, le=1e15, description="About the CM. [kg·m²]")
    inertia_pitch_kgm2: float = Field(ge=0, le=1e15, description="About the CM. [kg·m²]")
    inertia_yaw_kgm2: float = Field(ge=0, le=1e15, description="About the CM. [kg·m²]")
    added_mass: Matrix6 = Field(
        description="Hydrodynamic added mass at the PRP (infinite-frequency A∞, or strip "
        "theory). [kg, kg·m, kg·m²]"
    )
    added_mass_by_frequency: list[AddedMassPoint] = Field(
        default_factory=list,
        max_length=1000,
        description="Added mass A(f) at rising frequencies: each mode takes it at its own "
        "frequency, interpolated (beyond the table: its nearest end); empty: added_mass at "
        "every frequency.",
    )
    stiffness: Matrix6 = Field(
        description="Restoring stiffness at the PRP: hydrostatics and moorings (the "
        "platform's own weight term is added by wtvib from its mass and CM). [N/m, N/rad, "
        "N·m/rad]"
    )
    source: str | None = Field(None, max_length=2000, description="Where the matrices come from.")
    wave_periods_s: tuple[WavePeriod, WavePeriod] | None = Field(
        None,
        description="The site's wave energy band as periods (shortest, longest) [s]: the "
        "platform's modes are compared with it, as information.",
    )

    @model_validator(mode="after")
    def _symmetric(self) -> "Platform":
        if self.wave_periods_s is not None and not (
            self.wave_periods_s[0] < self.wave_periods_s[1]
        ):
            raise ValueError("wave_periods_s must be (shortest, longest), shortest first")
        matrices = [("added_mass", self.added_mass), ("stiffness", self.stiffness)]
        matrices += [
            (f"added_mass_by_frequency[{n}].matrix", point.matrix)
            for n, point in enumerate(self.added_mass_by_frequency)
        ]
        # the platform's own inertia on the diagonal, at the PRP: a frequency's added mass
        # may be negative (a moonpool's sloshing near its resonance: the ITI barge's WAMIT
        # table), not the body's whole inertia
        z2 = self.mass_kg * self.cm_m**2
        own = [self.mass_kg] * 3 + [
            self.inertia_roll_kgm2 + z2,
            self.inertia_pitch_kgm2 + z2,
            self.inertia_yaw_kgm2,
        ]
        for name, m in matrices:
            if name == "added_mass" and any(m[i][i] < 0 for i in range(6)):
                raise ValueError(f"{name}: an added mass on the diagonal is negative")
            if name.startswith("added_mass_by") and any(m[i][i] + own[i] <= 0 for i in range(6)):
                raise ValueError(
                    f"{name}: an added mass on the diagonal is negative beyond the platform's "
                    "own mass or inertia (the body's whole inertia would be negative)"
                )
            for i in range(6):
                for j in range(i):
                    a, b = m[i][j], m[j][i]
                    if abs(a - b) > 1e-6 * max(abs(a), abs(b), 1.0) + 1e-9:
                        raise ValueError(
                            f"{name} must be symmetric: [{i + 1}][{j + 1}] = {a:g} but "
                            f"[{j + 1}][{i + 1}] = {b:g}"
                        )
        f = [point.frequency_hz for point in self.added_mass_by_frequency]
        if any(b <= a for a, b in itertools.pairwise(f)):
            raise ValueError("added_mass_by_frequency must be at rising frequencies")
        return self


class Foundation(_Strict):
    """How the tower base is held: clamped, on springs, or a monopile in soil (the tower's
    base is then the mudline)."""

    kind: Literal["clamped", "springs", "soil", "platform"] = Field(
        "clamped", description="Base condition."
    )
    lateral_n_m: Positive | None = Field(None, description="Lateral spring. [N/m]")
    rocking_nm_rad: Positive | None = Field(None, description="Rocking spring. [N·m/rad]")
    coupling_n: float | None = Field(
        None,
        ge=-1e15,
        le=1e15,
        description="Lateral-rocking coupling K_LR of the springs (a pile head's: negative, "
        "e.g. wtvib.subsystems.soil.shadlou). [N]",
    )
    torsional_nm_rad: Positive | None = Field(None, description="Torsional spring. [N·m/rad]")
    pile: Pile | None = Field(None, description="The embedded pile (kind soil).")
    platform: Platform | None = Field(None, description="The floating platform (kind platform).")
    soil: list[SoilLayer] = Field(
        default_factory=list, max_length=50, description="Soil layers, top down (kind soil)."
    )
    bounds: SoilBounds = Field(default_factory=SoilBounds)

    @model_validator(mode="after")
    def _springs(self) -> "Foundation":
        if self.kind == "springs" and self.lateral_n_m is None and self.rocking_nm_rad is None:
            raise ValueError("a 'springs' foundation needs lateral_n_m and/or rocking_nm_rad")
        if self.coupling_n is not None:
            kl, kr = self.lateral_n_m, self.rocking_nm_rad
            if kl is None or kr is None or self.coupling_n**2 >= kl * kr:
                raise ValueError(
                    "coupling_n needs lateral_n_m and rocking_nm_rad with K_LR² < K_L·K_R "
                    "(a stable spring)"
                )
        if (self.kind == "platform") != (self.platform is not None):
            raise ValueError("a 'platform' foundation needs platform, and only it has one")
        if self.kind == "soil":
            if self.pile is None or not self.soil:
                raise ValueError("a 'soil' foundation needs pile and soil")
            _increasing("bottom_m of the soil layers", [x.bottom_m for x in self.soil] + [1e9])
            if self.soil[-1].bottom_m < self.pile.embedded_length_m:
                raise ValueError(
                    f"the soil layers end at {self.soil[-1].bottom_m:g} m, above the pile tip "
                    f"at {self.pile.embedded_length_m:g} m"
                )
        return self


class TowerHead(_Strict):
    """The rotor–nacelle assembly as a rigid body on the tower top."""

    mass_kg: Positive = Field(description="Total tower-head mass (rotor, hub, nacelle). [kg]")
    cm_downwind_m: float = Field(
        0.0, ge=-1000, le=1000, description="CM downwind of the tower axis. [m]"
    )
    cm_above_top_m: float = Field(0.0, ge=-1000, le=1000, description="CM above the tower top. [m]")
    inertia_pitch_kgm2: float = Field(
        0.0, ge=0, description="Inertia about the lateral (nodding) axis through the CM. [kg·m²]"
    )
    inertia_roll_kgm2: float = Field(
        0.0, ge=0, description="Inertia about the fore-aft (roll) axis through the CM. [kg·m²]"
    )
    inertia_yaw_kgm2: float = Field(
        0.0, ge=0, description="Inertia about the vertical (yaw) axis through the CM. [kg·m²]"
    )


class Tower(_Strict):
    """The tower with its tower head (rotor–nacelle mass), by its natural frequencies."""

    construction: (
        Literal[
            "steel-tube", "concrete", "lattice", "guyed-tube", "hybrid", "rotor-column", "other"
        ]
        | None
    ) = Field(None, description="Type of tower.")
    height_m: Positive | None = Field(None, description="Tower height. [m]")
    mass_kg: Positive | None = Field(None, description="Tower mass. [kg]")
    damping_ratio: Ratio = Field(
        0.01, description="Default modal damping ratio of the tower modes. [-]"
    )
    damping_by_mode: dict[TowerModeName, Ratio] = Field(
        default_factory=dict,
        description="Damping ratios of single computed tower modes, in place of "
        "damping_ratio (a measured fore-aft ratio that holds the rotor's aerodynamic "
        "damping, which the side-side and torsion modes lack). [-]",
    )
    rigid: bool = Field(
        False,
        description="The tower held rigid: no tower modes, the nacelle on a fixed tower top "
        "(as a deck with every tower DOF switched off models it: ElastoDyn's TwFADOF1 … "
        "TwSSDOF2 all False).",
    )
    damping_at: Literal["mode", "tower-alone"] = Field(
        "mode",
        description="What the damping ratios are the ratios of: 'mode', each computed "
        "mode's own; 'tower-alone', ElastoDyn's — a stiffness-proportional damping whose "
        "ratio is given at the frequency the mode's polynomial implies on the tower alone "
        "(without head, point masses or gravity; the tower's own mode where no polynomial is "
        "given), so that a mode at f carries ζ·f/f_alone (ElastoDyn.f90: CTFA = "
        "0.01·TwrFADmp·KTFA/(π·FreqTFA(:,1))).",
    )
    stiffness_damping_s: StiffnessDamping | None = Field(
        None,
        description="The tower's damping as stiffness-proportional (β fore-aft, side-side, "
        "torsion: ζ = π·β·f on every mode, in place of the ratios; HAWC2's damping_posdef).",
    )
    sections: TubularSections | None = Field(None, description="Tapered tube geometry.")
    material: Material | None = Field(None, description="Material of the tube sections.")
    distributed: DistributedTower | None = Field(
        None, description="Distributed properties (instead of sections)."
    )
    point_masses: list[PointMass] = Field(default_factory=list)
    dampers: list[MassDamper] = Field(
        default_factory=list,
        max_length=20,
        description="Tuned mass dampers on the tower or the nacelle (structural control).",
    )
    added_mass: AddedMass | None = Field(
        None, description="Water moving with a submerged monopile (bending only)."
    )
    foundation: Foundation = Field(default_factory=Foundation)
    gravity: bool = Field(
        True, description="Include the softening of the tower by its own and the head's weight."
    )
    modes: dict[TowerModeName, ModeEntry] = Field(
        default_factory=dict,
        description="Natural frequencies [Hz]: fa1, fa2 (fore-aft), ss1, ss2 (side-side), "
        "tor1 (torsion). Ignored for modes the structural model computes.",
    )
    polynomials: dict[Literal["fa1", "fa2", "ss1", "ss2"], ShapePolynomial] = Field(
        default_factory=dict,
        description="An ElastoDyn deck's tower mode-shape polynomials (TwFAM1Sh … "
        "TwSSM2Sh), audited against the modes the structure computes.",
    )
    polynomial_base_m: float = Field(
        0.0,
        ge=0,
        description="Where the polynomials' x = 0 is, above the tower's base (ElastoDyn's "
        "tower on a SubDyn pile starts at TowerBsHt, above the pile). [m]",
    )

    @model_validator(mode="after")
    def _one_structure(self) -> "Tower":
        if self.sections is not None and self.distributed is not None:
            raise ValueError("give either sections (with material) or distributed, not both")
        if self.sections is not None and self.material is None:
            raise ValueError("tube sections need a material")
        if self.dampers and not (self.has_structure or self.rigid):
            raise ValueError(
                "dampers act on the tower's structure (sections or distributed properties), "
                "or on a rigid tower"
            )
        self._on_the_tower()
        if self.damping_by_mode and not self.has_structure:
            raise ValueError(
                "damping_by_mode damps modes the tower's structure computes; with given "
                "frequencies, give each mode's damping_ratio in tower.modes"
            )
        return self

    def _on_the_tower(self) -> None:
        """Dampers, point masses and added mass within the tower's stations: the mesh takes
        their heights as nodes, and one beyond the top or below the base made the tower
        longer than its table (its last properties carried on)."""
        table = self.sections or self.distributed
        if table is None:
            return
        low, high = table.height_m[0], table.height_m[-1]
        slack = 1e-6 * (high - low)  # a table's heights rounded by an importer

        def off(h: float) -> bool:
            return not low - slack <= h <= high + slack

        where = f"not on the tower ({low:g} … {high:g} m above its base)"
        for i, d in enumerate(self.dampers):
            if d.on == "tower" and off(d.height_m):
                raise ValueError(f"dampers[{i}] ({d.name}) at {d.height_m:g} m is {where}")
        for i, pm in enumerate(self.point_masses):
            if off(pm.height_m):
                raise ValueError(f"point_masses[{i}] at {pm.height_m:g} m is {where}")
        if self.added_mass is not None:
            a, b = self.added_mass.height_m[0], self.added_mass.height_m[-1]
            if off(a) or off(b):
                raise ValueError(f"added_mass, from {a:g} to {b:g} m, is {where}")

    @property
    def has_structure(self) -> bool:
        return self.sections is not None or self.distributed is not None
