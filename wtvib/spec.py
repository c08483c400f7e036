"""The turbine spec: wtvib's input format (version 1), validated once, at the boundary.

A spec is a YAML file written by hand. Units are in the key names (``_hz``, ``_rpm``,
``_m``, ``_kg``, ``_kw``); ratios have no suffix. Any number may instead be written as a
*quantity* mapping that records where it came from::

    fa1: {value: 0.42, provenance: derived, source: hau, note: "between 1P and 2P (Fig. 7.22)"}

``provenance`` is ``published`` (a number printed in the source), ``derived`` (computed or
read from a statement in the source) or ``representative`` (a plausible value chosen where
the source gives none). ``source`` names an entry of the top-level ``sources`` mapping.

Validation errors become one :class:`~wtvib.errors.SpecError` line naming the field path and
the YAML line. Past this module, code trusts the spec (STYLE.md habit 4).
"""

import itertools
import os
from collections.abc import Mapping
from pathlib import Path as FsPath
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import (
    BaseModel,
    ConfigDict,
    Discriminator,
    Field,
    PrivateAttr,
    Tag,
    ValidationError,
    model_validator,
)

from .errors import SpecError
from .rules import PRESETS, MarginRule, Status
from .yamlio import Document, Path, format_path, parse

FORMAT_VERSION = 1

#: Files larger than this are refused before parsing; override with the environment
#: variable WTVIB_MAX_BYTES (bytes) or the ``max_bytes`` argument.
MAX_FILE_BYTES = int(os.environ.get("WTVIB_MAX_BYTES", 20 * 1024 * 1024))


class _Strict(BaseModel):
    model_config = ConfigDict(
        extra="forbid", frozen=True, allow_inf_nan=False, str_strip_whitespace=True
    )


Positive = Annotated[float, Field(gt=0)]
Ratio = Annotated[float, Field(ge=0, lt=1)]


class Quantity(_Strict):
    """A number with its provenance (accepted wherever a number is)."""

    value: float = Field(description="The number itself, in the unit its key names.")
    provenance: Literal["published", "derived", "representative"] = Field(
        description="published: printed in the source; derived: computed or read from a "
        "statement in the source; representative: a plausible value where the source gives "
        "none."
    )
    source: str | None = Field(None, description="Key of the top-level `sources` mapping.")
    note: str | None = Field(None, description="How the value was obtained.")
    tolerance: float | None = Field(
        None,
        ge=0,
        description="Uncertainty for `check --uncertainty`: normal — one standard deviation "
        "as a fraction of the value (0.15 for ±15 %); uniform — half-width as a fraction; "
        "lognormal — the factor at one standard deviation (2 for ×/÷ 2). [-]",
    )
    distribution: Literal["normal", "uniform", "lognormal"] = Field(
        "normal", description="Distribution of the uncertain value."
    )


class ModeSpec(_Strict):
    """A natural frequency given directly, with optional damping and stiffening."""

    frequency_hz: Positive = Field(description="Natural frequency at standstill. [Hz]")
    damping_ratio: Ratio | None = Field(
        None,
        description="Modal damping ratio (fraction of critical); subsystem default if omitted. [-]",
    )
    southwell: float | None = Field(
        None,
        ge=0,
        description="Blade modes only: Southwell coefficient K in f² = f₀² + K·(Ω/2π)². "
        "Default 1.19 for flap and 0.19 for edge modes (uniform cantilever), 0 for torsion. [-]",
    )
    description: str | None = Field(None, description="Free text shown in the report.")


def _mode_tag(value: Any) -> str:
    return "full" if isinstance(value, Mapping) else "number"


ModeEntry = Annotated[
    Annotated[Positive, Tag("number")] | Annotated[ModeSpec, Tag("full")],
    Discriminator(_mode_tag),
]

TowerModeName = Annotated[str, Field(pattern=r"^(fa|ss|tor)[1-9]$")]
BladeModeName = Annotated[str, Field(pattern=r"^(flap|edge|tor)[1-9]$")]
YawModeName = Annotated[str, Field(pattern=r"^[1-9]$")]


class TurbineInfo(_Strict):
    """Identification of the turbine."""

    name: str = Field(min_length=1, description="Name shown in reports.")
    manufacturer: str | None = None
    year: int | None = Field(None, ge=1800, le=2200, description="Year of commissioning.")
    rated_power_kw: Positive | None = Field(None, description="Rated power. [kW]")
    rotor_diameter_m: Positive | None = Field(None, description="Rotor diameter. [m]")
    hub_height_m: Positive | None = Field(None, description="Hub height. [m]")
    description: str | None = None


class RotorSpeed(_Strict):
    """Rotor speed: a fixed speed (or several, for pole-changing generators) or a range."""

    fixed_rpm: Positive | Annotated[list[Positive], Field(min_length=1)] | None = Field(
        None, description="Fixed operating speed(s). [rpm]"
    )
    min_rpm: Positive | None = Field(None, description="Lowest steady speed (variable). [rpm]")
    rated_rpm: Positive | None = Field(None, description="Rated speed (variable). [rpm]")
    max_rpm: Positive | None = Field(None, description="Highest steady speed (variable). [rpm]")
    overspeed_rpm: Positive | None = Field(None, description="Transient overspeed limit. [rpm]")
    overspeed_factor: float | None = Field(
        None,
        gt=1,
        description="Transient overspeed as a factor on the highest steady speed; default "
        "1.15 when neither this nor overspeed_rpm is given (Hau ch. 7.3.4, Growian). [-]",
    )
    quick_pass_rpm: list[tuple[Positive, Positive]] = Field(
        default_factory=list,
        description="Speed bands [low, high] the controller passes through quickly without "
        "steady operation (variable speed). [rpm]",
    )

    @model_validator(mode="after")
    def _consistent(self) -> "RotorSpeed":
        fixed = self.fixed_rpm is not None
        ranged = self.min_rpm is not None or self.max_rpm is not None
        if fixed == ranged:
            raise ValueError("give either fixed_rpm, or min_rpm and max_rpm")
        if ranged:
            if self.min_rpm is None or self.max_rpm is None:
                raise ValueError("a variable-speed rotor needs both min_rpm and max_rpm")
            if self.min_rpm > self.max_rpm:
                raise ValueError(f"min_rpm ({self.min_rpm}) exceeds max_rpm ({self.max_rpm})")
            if self.rated_rpm is not None and not self.min_rpm <= self.rated_rpm <= self.max_rpm:
                raise ValueError("rated_rpm must lie between min_rpm and max_rpm")
        elif self.rated_rpm is not None:
            raise ValueError("rated_rpm belongs to a variable-speed rotor; use fixed_rpm")
        if self.overspeed_rpm is not None and self.overspeed_factor is not None:
            raise ValueError("give overspeed_rpm or overspeed_factor, not both")
        top = self.top_rpm
        if self.overspeed_rpm is not None and self.overspeed_rpm <= top:
            raise ValueError(f"overspeed_rpm must exceed the highest steady speed ({top} rpm)")
        for low, high in self.quick_pass_rpm:
            if not low < high:
                raise ValueError(f"quick_pass_rpm band [{low}, {high}] must be increasing")
            if not ranged or low < (self.min_rpm or 0) or high > top:
                raise ValueError(
                    f"quick_pass_rpm band [{low}, {high}] must lie inside min_rpm..max_rpm"
                )
        return self

    @property
    def steady_rpm(self) -> list[tuple[float, float]]:
        """Steady operating speeds as closed intervals (a fixed speed is a point). [rpm]"""
        if self.fixed_rpm is not None:
            speeds = self.fixed_rpm if isinstance(self.fixed_rpm, list) else [self.fixed_rpm]
            return [(s, s) for s in sorted(speeds)]
        assert self.min_rpm is not None and self.max_rpm is not None
        return [(self.min_rpm, self.max_rpm)]

    @property
    def dwell_rpm(self) -> list[float]:
        """Speeds the rotor spends most time at: each fixed speed, or rated (default max)."""
        if self.fixed_rpm is not None:
            return [a for a, _ in self.steady_rpm]
        return [self.rated_rpm if self.rated_rpm is not None else self.top_rpm]

    @property
    def top_rpm(self) -> float:
        """Highest steady speed. [rpm]"""
        return self.steady_rpm[-1][1]

    @property
    def overspeed(self) -> float:
        """Transient overspeed limit, explicit or from the factor (default 1.15). [rpm]"""
        if self.overspeed_rpm is not None:
            return self.overspeed_rpm
        return self.top_rpm * (self.overspeed_factor or DEFAULT_OVERSPEED_FACTOR)


#: Default transient overspeed factor: Hau ch. 7.3.4 discusses Growian at 115 % overspeed.
DEFAULT_OVERSPEED_FACTOR = 1.15


class Rotor(_Strict):
    """The rotor: blade number, layout, hub and speed."""

    blades: int = Field(ge=1, le=20, description="Number of blades N_b.")
    orientation: Literal["upwind", "downwind", "vertical-axis"] = Field(
        description="Rotor position relative to the tower, or a vertical-axis (Darrieus) rotor."
    )
    hub: Literal["hingeless", "rigid", "teetered", "hinged"] = Field(
        description="Hub type; 'rigid' and 'hingeless' mean the same."
    )
    speed: RotorSpeed
    teeter_stiffness_nm_rad: float = Field(
        0.0,
        ge=0,
        description="Teetered hub: teeter spring (centrifugal stiffening is added). [N·m/rad]",
    )
    teeter_damping_nms_rad: float = Field(
        0.0, ge=0, description="Teetered hub: teeter damper. [N·m·s/rad]"
    )


def _increasing(name: str, values: list[float]) -> None:
    if len(values) < 2:
        raise ValueError(f"{name} needs at least two stations")
    if any(b <= a for a, b in itertools.pairwise(values)):
        raise ValueError(f"{name} must increase strictly from station to station")


def _same_length(model: BaseModel, reference: str) -> None:
    n = len(getattr(model, reference))
    for name, value in model:
        if isinstance(value, list) and len(value) != n:
            raise ValueError(f"{name} has {len(value)} values but {reference} has {n}")


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

    height_m: list[float] = Field(description="Station heights above the tower base. [m]")
    outer_diameter_m: list[Positive] = Field(description="Outer diameter. [m]")
    wall_thickness_m: list[Positive] = Field(description="Wall thickness. [m]")

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

    height_m: list[float] = Field(description="Station heights above the tower base. [m]")
    mass_per_length_kg_m: list[Positive] = Field(description="Mass per length. [kg/m]")
    ei_fa_nm2: list[Positive] = Field(description="Fore-aft bending stiffness. [N·m²]")
    ei_ss_nm2: list[Positive] = Field(description="Side-side bending stiffness. [N·m²]")
    gj_nm2: list[Positive] | None = Field(None, description="Torsional stiffness. [N·m²]")
    polar_inertia_kgm: list[Positive] | None = Field(
        None, description="Polar mass moment of inertia per length. [kg·m]"
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

    height_m: float = Field(description="Height above the tower base. [m]")
    mass_kg: Positive = Field(description="Mass. [kg]")


class Foundation(_Strict):
    """How the tower base is held: clamped, or on springs."""

    kind: Literal["clamped", "springs"] = Field("clamped", description="Base condition.")
    lateral_n_m: Positive | None = Field(None, description="Lateral spring. [N/m]")
    rocking_nm_rad: Positive | None = Field(None, description="Rocking spring. [N·m/rad]")
    torsional_nm_rad: Positive | None = Field(None, description="Torsional spring. [N·m/rad]")

    @model_validator(mode="after")
    def _springs(self) -> "Foundation":
        if self.kind == "springs" and self.lateral_n_m is None and self.rocking_nm_rad is None:
            raise ValueError("a 'springs' foundation needs lateral_n_m and/or rocking_nm_rad")
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


class BladeStructure(_Strict):
    """A blade as a table of distributed properties along its span (cantilevered at the root)."""

    hub_radius_m: float = Field(0.0, ge=0, description="Rotor axis to blade root. [m]")
    span_m: list[float] = Field(description="Distance from the blade root. [m]")
    mass_per_length_kg_m: list[Positive] = Field(description="Mass per length. [kg/m]")
    ei_flap_nm2: list[Positive] = Field(description="Flapwise bending stiffness. [N·m²]")
    ei_edge_nm2: list[Positive] = Field(description="Edgewise bending stiffness. [N·m²]")
    twist_deg: list[float] | None = Field(
        None, description="Structural twist of the principal axes to the rotor plane. [deg]"
    )
    gj_nm2: list[Positive] | None = Field(None, description="Torsional stiffness. [N·m²]")
    torsional_inertia_kgm: list[Positive] | None = Field(
        None, description="Mass moment of inertia per length about the pitch axis. [kg·m]"
    )

    @model_validator(mode="after")
    def _consistent(self) -> "BladeStructure":
        _increasing("span_m", self.span_m)
        if self.span_m[0] != 0:
            raise ValueError("span_m must start at 0 (the blade root)")
        _same_length(self, "span_m")
        if (self.gj_nm2 is None) != (self.torsional_inertia_kgm is None):
            raise ValueError("give gj_nm2 and torsional_inertia_kgm together")
        return self


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
    sections: TubularSections | None = Field(None, description="Tapered tube geometry.")
    material: Material | None = Field(None, description="Material of the tube sections.")
    distributed: DistributedTower | None = Field(
        None, description="Distributed properties (instead of sections)."
    )
    point_masses: list[PointMass] = Field(default_factory=list)
    foundation: Foundation = Field(default_factory=Foundation)
    gravity: bool = Field(
        True, description="Include the softening of the tower by its own and the head's weight."
    )
    modes: dict[TowerModeName, ModeEntry] = Field(
        default_factory=dict,
        description="Natural frequencies [Hz]: fa1, fa2 (fore-aft), ss1, ss2 (side-side), "
        "tor1 (torsion). Ignored for modes the structural model computes.",
    )

    @model_validator(mode="after")
    def _one_structure(self) -> "Tower":
        if self.sections is not None and self.distributed is not None:
            raise ValueError("give either sections (with material) or distributed, not both")
        if self.sections is not None and self.material is None:
            raise ValueError("tube sections need a material")
        return self

    @property
    def has_structure(self) -> bool:
        return self.sections is not None or self.distributed is not None


class AeroSection(_Strict):
    """A blade section as a typical section for divergence and flutter (Hau Fig. 7.6)."""

    radius_fraction: float = Field(
        0.75, gt=0, le=1, description="Position r/R of the section on the rotor radius. [-]"
    )
    chord_m: Positive = Field(description="Chord c. [m]")
    elastic_axis_chord: Ratio = Field(
        description="Elastic (shear-centre) axis behind the leading edge, fraction of c. [-]"
    )
    centre_of_mass_chord: Ratio = Field(
        description="Centre of mass behind the leading edge, fraction of c. [-]"
    )
    mass_per_length_kg_m: Positive | None = Field(
        None, description="Mass per length; default: blade.structure at this radius. [kg/m]"
    )
    torsional_inertia_kgm: Positive | None = Field(
        None,
        description="Mass moment of inertia per length about the elastic axis; default: "
        "blade.structure at this radius. [kg·m]",
    )
    chord_angle_deg: float = Field(
        0.0,
        ge=-90,
        le=90,
        description="Angle of the chord to the rotor plane (twist + pitch), for the "
        "centrifugal propeller moment. [deg]",
    )

    @model_validator(mode="after")
    def _inertia_covers_offset(self) -> "AeroSection":
        m, i = self.mass_per_length_kg_m, self.torsional_inertia_kgm
        if m is not None and i is not None:
            check_section_inertia(m, i, self.offset_m)
        return self

    @property
    def offset_m(self) -> float:
        """Centre of mass behind the elastic axis. [m]"""
        return (self.centre_of_mass_chord - self.elastic_axis_chord) * self.chord_m


def check_section_inertia(mass: float, inertia: float, offset: float) -> None:
    """The inertia about the elastic axis includes the offset mass: I_EA ≥ m·d²."""
    if inertia <= mass * offset**2:
        raise ValueError(
            f"torsional_inertia_kgm {inertia:g} kg·m is not more than m·d² = "
            f"{mass * offset**2:.4g} kg·m: the inertia about the elastic axis includes the "
            f"centre of mass's offset d = {offset:.3g} m"
        )


class Polar(_Strict):
    """Aerofoil polar: lift and drag coefficients over the angle of attack."""

    alpha_deg: list[float] = Field(min_length=3, description="Angle of attack. [deg]")
    cl: list[float] = Field(description="Lift coefficient C_L. [-]")
    cd: list[float] = Field(description="Drag coefficient C_D. [-]")

    @model_validator(mode="after")
    def _consistent(self) -> "Polar":
        _increasing("alpha_deg", self.alpha_deg)
        _same_length(self, "alpha_deg")
        return self


class Planform(_Strict):
    """Chord and twist along the blade, for the stall-induced vibration check."""

    radius_fraction: list[float] = Field(min_length=2, description="Position r/R. [-]")
    chord_m: list[Positive] = Field(description="Chord. [m]")
    twist_deg: list[float] = Field(
        description="Angle of the chord to the rotor plane at zero pitch. [deg]"
    )

    @model_validator(mode="after")
    def _consistent(self) -> "Planform":
        _increasing("radius_fraction", self.radius_fraction)
        if self.radius_fraction[0] <= 0 or self.radius_fraction[-1] > 1:
            raise ValueError("radius_fraction must lie in (0, 1]")
        _same_length(self, "radius_fraction")
        return self


class BladeAeroelastic(_Strict):
    """Data for the blade's divergence, flutter and stall-induced vibration checks."""

    sections: list[AeroSection] = Field(min_length=1, max_length=10)
    lift_slope_per_rad: Positive = Field(
        6.283185307179586, description="Lift-curve slope C_Lα (thin aerofoil: 2π). [1/rad]"
    )
    air_density_kg_m3: Positive = Field(1.225, description="Air density ρ. [kg/m³]")
    max_wind_m_s: Positive = Field(
        25.0,
        description="Highest wind speed in operation (cut-out), added to the "
        "section's rotational speed at overspeed. [m/s]",
    )
    speed_margin: float = Field(
        0.15,
        gt=0,
        lt=5,
        description="Required margin of the divergence and flutter speeds over the highest "
        "section speed (0.15: 1.15×, as CS-25.629 asks of aircraft). [-]",
    )
    polar: Polar | None = Field(
        None, description="Aerofoil polar; default a built-in thin-aerofoil/flat-plate stall."
    )
    planform: Planform | None = Field(
        None, description="Chord and twist along the blade; default: the sections (≥ 2)."
    )
    min_wind_m_s: Positive = Field(4.0, description="Lowest wind speed in operation. [m/s]")
    axial_induction: float = Field(
        0.0,
        ge=0,
        lt=0.5,
        description="Axial induction a in the inflow model (0: geometric angle of attack, "
        "the highest). [-]",
    )
    tip_speed_ratio: Positive = Field(
        7.0, description="Tip-speed ratio of variable-speed partial load. [-]"
    )
    pitch_deg: float = Field(0.0, ge=-30, le=90, description="Blade pitch (held). [deg]")
    regulation: Literal["stall", "pitch"] = Field(
        "stall",
        description="Power regulation: stall (pitch held at all winds) or pitch (the stall "
        "check stops at the rated wind).",
    )
    rated_wind_m_s: Positive | None = Field(
        None,
        description="Rated wind speed (pitch regulation); default from the tip-speed ratio. [m/s]",
    )


class Blade(_Strict):
    """The blades, by their natural frequencies at standstill."""

    length_m: Positive | None = Field(None, description="Blade length. [m]")
    mass_kg: Positive | None = Field(None, description="Mass of one blade. [kg]")
    damping_ratio: Ratio = Field(
        0.005, description="Default modal damping ratio of the blade modes. [-]"
    )
    modes: dict[BladeModeName, ModeEntry] = Field(
        default_factory=dict,
        description="Standstill natural frequencies [Hz]: flap1, flap2, edge1, edge2, tor1. "
        "Ignored for modes the structural model computes.",
    )
    structure: BladeStructure | None = Field(
        None, description="Distributed properties: frequencies computed, rotation included."
    )
    aeroelastic: BladeAeroelastic | None = Field(
        None, description="Section data for the divergence and flutter checks."
    )


class GearStage(_Strict):
    """One gearbox stage, for its tooth-mesh excitation."""

    name: str = Field(min_length=1, description="Stage name used in the excitation id.")
    teeth: int = Field(gt=0, description="Teeth on the gear whose shaft speed is given.")
    shaft_speed_ratio: Positive = Field(
        description="Speed of that gear's shaft divided by rotor speed. [-]"
    )


class InertiaFractions(_Strict):
    """Shares of the drive train's total inertia (Hau Table 7.8). [-]"""

    blades: Ratio
    hub: Ratio
    generator: Ratio
    rest: Ratio

    @model_validator(mode="after")
    def _sum_to_one(self) -> "InertiaFractions":
        total = self.blades + self.hub + self.generator + self.rest
        if abs(total - 1.0) > 0.011:
            raise ValueError(f"inertia fractions must add up to 1 (they add up to {total:.3f})")
        return self


class ChainMass(_Strict):
    """One rotating inertia of the drive train, on a shaft turning at its own speed."""

    name: str = Field(min_length=1, description="e.g. blades, hub, gearbox, brake, generator.")
    inertia_kgm2: Positive = Field(description="Polar moment of inertia on its own shaft. [kg·m²]")
    speed_ratio: Positive = Field(1.0, description="Its shaft's speed / rotor speed. [-]")


class ChainShaft(_Strict):
    """The torsional connection between two consecutive masses of the chain."""

    stiffness_nm_rad: Positive | None = Field(
        description="Torsional stiffness; null for a rigid connection (the masses move as "
        "one, or, between blades and hub, the blades' edgewise spring alone). [N·m/rad]"
    )
    damping_nms_rad: float = Field(0.0, ge=0, description="Torsional damping. [N·m·s/rad]")
    speed_ratio: Positive = Field(
        1.0, description="Speed of the shaft the stiffness refers to / rotor speed. [-]"
    )


class FixedExcitation(_Strict):
    """An excitation at a fixed frequency (grid, converter switching, …)."""

    name: str = Field(min_length=1, description="Used in the excitation id.")
    frequency_hz: Positive = Field(description="Excitation frequency. [Hz]")
    energy: Literal["dominant", "secondary", "minor"] = Field(
        "dominant", description="How serious a resonance with it is."
    )


class GeneratorModel(_Strict):
    """The generator's electrical coupling (Hau Fig. 7.11), for small oscillations."""

    rated_power_kw: Positive = Field(description="Rated (electrical) power. [kW]")
    pole_pairs: int = Field(ge=1, le=200, description="Pole pairs p. [-]")
    grid_frequency_hz: Positive = Field(50.0, description="Grid frequency. [Hz]")
    pull_out_power_kw: Positive | None = Field(
        None, description="Synchronous: pull-out (maximum) power P_max. [kW]"
    )
    rated_slip: float | None = Field(
        None, gt=0, lt=0.5, description="Induction: slip at rated power (0.01 = 1 %). [-]"
    )
    controller_damping_nms_rad: float = Field(
        0.0, ge=0, description="Converter: damping the speed controller adds. [N·m·s/rad]"
    )


class Drivetrain(_Strict):
    """The drive train: generator, gearbox and natural frequencies per operating condition."""

    generator: Literal["synchronous", "induction", "converter", "dc"] | None = Field(
        None, description="Generator type."
    )
    grid_coupling: Literal["direct", "converter", "isolated"] | None = Field(
        None, description="How the generator is tied to the grid or load."
    )
    gear_ratio: Positive | None = Field(None, description="Generator speed / rotor speed. [-]")
    gear_stages: list[GearStage] = Field(
        default_factory=list, description="Stages whose mesh frequencies excite the train."
    )
    inertia_fractions: InertiaFractions | None = None
    damping_ratio: Ratio = Field(
        0.02, description="Default modal damping ratio of the drive-train modes. [-]"
    )
    modes: dict[Literal["grid", "free", "locked"], list[ModeEntry]] = Field(
        default_factory=dict,
        description="Natural frequencies [Hz] per condition: grid (generator on the grid), "
        "free (idling / isolated), locked (brake applied), lowest first, rigid-body 0 Hz "
        "modes omitted. Ignored when a chain is given.",
    )
    chain: list[ChainMass] = Field(
        default_factory=list,
        description="Inertias from the rotor end (blades first) to the generator (last).",
    )
    shafts: list[ChainShaft] = Field(
        default_factory=list, description="Connections between consecutive chain masses."
    )
    blade_edge_spring: bool = Field(
        True,
        description="Put the blades' edgewise flexibility between a first mass named 'blades' "
        "and the next one: k_b = J_b·ω_edge² from the blade's first edgewise frequency.",
    )
    reference_shaft: Literal["rotor", "generator"] = Field(
        "rotor", description="Shaft all inertias and stiffnesses are reduced to."
    )
    generator_model: GeneratorModel | None = None
    electrical_excitations: list[FixedExcitation] = Field(
        default_factory=list,
        description="Generator-side excitations at fixed frequencies (grid, converter).",
    )

    @model_validator(mode="after")
    def _chain(self) -> "Drivetrain":
        if self.chain and len(self.shafts) != len(self.chain) - 1:
            raise ValueError(
                f"a chain of {len(self.chain)} masses needs {len(self.chain) - 1} shafts "
                f"(got {len(self.shafts)})"
            )
        if len(self.chain) == 1:
            raise ValueError("a drive-train chain needs at least two masses")
        return self


class YawPlay(_Strict):
    """Backlash in the yaw drive (worm gear, pinion and ring)."""

    half_gap_deg: Positive = Field(description="Half the gear play δ. [deg]")
    amplitude_deg: Positive | None = Field(
        None,
        description="Vibration amplitude A (through the gap) the yaw moments drive; default "
        "δ + M_yaw/k from the cyclic yaw moment. [deg]",
    )


class Yaw(_Strict):
    """The yaw system: given frequencies, or the drive, inertia, play and friction."""

    drive: Literal["active", "fantail", "free"] | None = Field(None, description="Yaw drive.")
    damping_ratio: Ratio = Field(0.02, description="Default modal damping ratio. [-]")
    modes: dict[YawModeName, ModeEntry] = Field(
        default_factory=dict,
        description="Yaw natural frequencies [Hz], keyed 1, 2, … (ignored with a drive model)",
    )
    drive_stiffness_nm_rad: Positive | None = Field(
        None, description="Torsional stiffness of one yaw drive at the yaw axis. [N·m/rad]"
    )
    drives: int = Field(1, ge=1, le=64, description="Yaw drives acting in parallel.")
    inertia_kgm2: Positive | None = Field(
        None,
        description="Tower-head inertia about the yaw axis; default tower_head inertia_yaw + "
        "M·x_cm² (and the rotor's mean for two blades). [kg·m²]",
    )
    rotor_polar_inertia_kgm2: Positive | None = Field(
        None, description="Rotor inertia about its shaft (gyroscopics, two-blade 2P). [kg·m²]"
    )
    tower_torsion_nm_rad: Positive | None = Field(
        None, description="Tower torsional stiffness G·J/L, in series with the drive. [N·m/rad]"
    )
    tower_inertia_kgm2: Positive | None = Field(
        None,
        description="Tower inertia taking part in torsion (two-mass model; default: none, the "
        "tower acts as a spring in series). [kg·m²]",
    )
    play: YawPlay | None = None
    friction_moment_nm: float = Field(
        0.0, ge=0, description="Friction in the yaw bearing / sliding blocks while yawing. [N·m]"
    )
    brake_moment_nm: float = Field(
        0.0, ge=0, description="Holding moment of the yaw brakes when parked. [N·m]"
    )
    yaw_rate_deg_s: Positive | None = Field(None, description="Yawing rate. [deg/s]")
    yaw_moment_amplitude_nm: Positive | None = Field(
        None, description="Amplitude of the cyclic aerodynamic yaw moment at N_b·P. [N·m]"
    )
    rated_torque_nm: Positive | None = Field(
        None, description="Rotor torque at rated power, for the tilted-shaft term. [N·m]"
    )
    shaft_tilt_deg: float = Field(0.0, ge=-20, le=20, description="Shaft tilt angle. [deg]")

    @property
    def has_model(self) -> bool:
        return self.drive_stiffness_nm_rad is not None


class CoupledModel(_Strict):
    """What the coupled rotor–tower model (whole-turbine modes, Hau §7.6) needs beyond the
    subsystems: where the rotor sits on the tower head, the hub, and how many blade modes."""

    apex_downwind_m: float = Field(
        ge=-100,
        le=100,
        description="Rotor centre (apex) downwind of the tower axis; negative upwind. [m]",
    )
    apex_above_top_m: float = Field(
        ge=-100, le=100, description="Rotor centre above the tower top. [m]"
    )
    hub_mass_kg: float = Field(0.0, ge=0, description="Hub mass (part of tower_head). [kg]")
    hub_inertia_kgm2: float | None = Field(
        None,
        ge=0,
        description="Hub inertia about the shaft; default: the drive-train chain's hub (or "
        "0 without a chain). [kg·m²]",
    )
    blade_modes: int = Field(
        3, ge=1, le=6, description="Flexible modes per blade, lowest first (flap1, edge1, …)."
    )
    parked_condition: Literal["locked", "free", "grid"] = Field(
        "locked", description="Generator when parked (Jonkman et al. 2009 Table 9-1: locked)."
    )
    rotating_condition: Literal["locked", "free", "grid"] = Field(
        "free",
        description="Generator in the rotating sweep: free (converter, torque-controlled), "
        "grid (the drivetrain.generator_model coupling), locked.",
    )


class Severity(_Strict):
    """Status given to a margin violation in steady operation, by excitation energy."""

    dominant: Status = Field("fail", description="1P and N_b·P (Hau ch. 7.1).")
    secondary: Status | None = Field(
        None,
        description="kP with 1 < k < N_b, e.g. 2P on a three-bladed rotor, at a dwell speed "
        "(fixed or rated speed); one step milder elsewhere in a variable-speed range (Hau "
        "ch. 7.5.2: 'basically considered less critical', yet WKA-60's tower met 2P at rated "
        "speed and resonated). Default: the preset's (hau: fail, gl2010: warn).",
    )
    minor: Status = Field(
        "info", description="Higher harmonics above N_b·P (Hau ch. 7.2.2: little energy)."
    )


class AuditSettings(_Strict):
    """How strictly to judge: the margin rule, its margin, and how many harmonics."""

    preset: Literal["hau", "gl2010"] = Field(
        "hau", description="Code whose rule and margin are the defaults: " + ", ".join(PRESETS)
    )
    rule: Literal["band", "ratio"] | None = Field(
        None, description="band: |f_n−f_exc| ≥ m·f_exc; ratio: f_exc/f_n outside 1 ± m."
    )
    margin: float | None = Field(None, gt=0, lt=1, description="Margin m (0.10 = 10 %). [-]")
    harmonics: int = Field(6, ge=1, le=60, description="Highest rotor harmonic kP checked.")
    heavy_damping_ratio: float = Field(
        0.3,
        gt=0,
        le=1,
        description="A mode at least this damped (peak amplification 1/(2ζ√(1−ζ²)) ≤ 1.75 at "
        "0.3) has no resonant peak: its margin violations are reported as info. [-]",
    )
    severity: Severity = Field(default_factory=Severity)

    def severities(self) -> dict[str, Status]:
        """Status of a steady-state margin violation per energy class, preset applied."""
        out = self.severity.model_dump()
        if out["secondary"] is None:
            out["secondary"] = PRESETS[self.preset].secondary
        return out

    def margin_rule(self) -> MarginRule:
        """The rule in force: the preset's, with the explicit rule and margin on top."""
        preset = PRESETS[self.preset]
        kind = self.rule or preset.rule
        margin = self.margin if self.margin is not None else preset.margin
        if kind == preset.rule and margin == preset.margin:
            return MarginRule(kind, margin, preset.source, preset.name)
        return MarginRule(kind, margin, f"user setting (preset {preset.name} overridden)")


class Spec(_Strict):
    """A wind turbine to audit (wtvib spec format version 1)."""

    wtvib: Literal[1] = Field(description="Spec format version; this is version 1.")
    turbine: TurbineInfo
    sources: dict[str, str] = Field(
        default_factory=dict, description="Citations, by a short key used in quantities."
    )
    rotor: Rotor
    tower: Tower = Field(default_factory=Tower)
    tower_head: TowerHead | None = Field(
        None, description="Rotor–nacelle assembly on the tower top (for the tower model)."
    )
    blade: Blade = Field(default_factory=Blade)
    drivetrain: Drivetrain = Field(default_factory=Drivetrain)
    yaw: Yaw = Field(default_factory=Yaw)
    coupled: CoupledModel | None = Field(
        None,
        description="Rotor position and hub for the coupled whole-turbine model (needs the "
        "tower and blade structures and tower_head); absent: no coupled modes.",
    )
    audit: AuditSettings = Field(default_factory=AuditSettings)
    notes: str | None = Field(None, description="Anything else worth keeping with the spec.")
    assumptions: list[str] = Field(
        default_factory=list,
        description="How the spec was made (e.g. by an importer): shown in the report.",
    )
    warnings: list[str] = Field(
        default_factory=list,
        description="What the importer could not find and had to assume, loudly: shown in the "
        "report's headline and warnings.",
    )

    _source_file: str | None = PrivateAttr(None)
    _provenance: dict[str, Quantity] = PrivateAttr(default_factory=dict)

    @property
    def source_file(self) -> str | None:
        """The file this spec was read from."""
        return self._source_file

    @property
    def provenance(self) -> dict[str, Quantity]:
        """Provenance of each annotated value, by dotted field path."""
        return dict(self._provenance)


# ---------------------------------------------------------------------------------------
# Loading


def load(path: str | FsPath, *, max_bytes: int = MAX_FILE_BYTES) -> Spec:
    """Read and validate a wtvib spec file.

    Raises
    ------
    SpecError
        Unreadable, oversized, non-UTF-8 or invalid file; the message names field and line.
    """
    text = read_text(path, max_bytes=max_bytes)
    return from_document(parse(text, source=str(path)))


def read_text(path: str | FsPath, *, max_bytes: int = MAX_FILE_BYTES) -> str:
    """A text file's content, refusing missing, oversized, binary or non-UTF-8 files."""
    p = FsPath(path)
    try:
        size = p.stat().st_size
        if size > max_bytes:
            raise SpecError(
                f"file is {size:,} bytes, over the {max_bytes:,}-byte limit", source=str(p)
            )
        raw = p.read_bytes()
    except IsADirectoryError:
        raise SpecError("is a folder, not a file", source=str(p)) from None
    except FileNotFoundError:
        raise SpecError("no such file", source=str(p)) from None
    except OSError as exc:
        raise SpecError(f"cannot read: {exc.strerror}", source=str(p)) from None
    if b"\x00" in raw:
        raise SpecError("binary file, not a YAML text file", source=str(p))
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = raw[: exc.start].count(b"\n") + 1
        raise SpecError("not UTF-8 text", line=line, source=str(p)) from None


def load_document(path: str | FsPath, text: str) -> Document:
    """Parse a file's text as a YAML document (safe, with line numbers)."""
    return parse(text, source=str(path))


def from_data(data: dict[str, Any], source: str | None = None) -> Spec:
    """Validate a wtvib-format dictionary made by a program (an importer), not a file."""
    return from_document(Document(data=data, lines={}, source=source))


def from_document(doc: Document) -> Spec:
    """Validate a parsed document as a :class:`Spec`."""
    if not isinstance(doc.data, dict):
        raise SpecError(
            "expected a mapping of fields (wtvib:, turbine:, rotor:, …) at the top",
            line=doc.line_of(()),
            source=doc.source,
        )
    version = doc.data.get("wtvib")
    if "wtvib" not in doc.data:
        raise SpecError(
            "not a wtvib spec: the version key 'wtvib: 1' is missing", line=1, source=doc.source
        )
    if version != FORMAT_VERSION:
        raise SpecError(
            f"unsupported spec format version {version!r}; this wtvib reads version "
            f"{FORMAT_VERSION}",
            path="wtvib",
            line=doc.line_of(("wtvib",)),
            source=doc.source,
        )
    provenance: dict[str, Quantity] = {}
    data = _extract_quantities(doc, doc.data, (), provenance)
    try:
        spec = Spec.model_validate(data)
    except ValidationError as exc:
        raise _spec_error(exc, doc) from None
    _check_sources(spec, provenance, doc)
    _check_rotor_radius(spec, doc)
    _check_coupled(spec, doc)
    spec._source_file = doc.source
    spec._provenance = provenance
    return spec


def _extract_quantities(doc: Document, node: Any, path: Path, out: dict[str, Quantity]) -> Any:
    """Replace each ``{value: …, provenance: …}`` mapping by its number, recording it."""
    if isinstance(node, dict):
        if "value" in node and "provenance" in node:
            try:
                q = Quantity.model_validate(node)
            except ValidationError as exc:
                raise _spec_error(exc, doc, prefix=path) from None
            out[format_path(path)] = q
            return q.value
        return {k: _extract_quantities(doc, v, (*path, k), out) for k, v in node.items()}
    if isinstance(node, list):
        return [_extract_quantities(doc, v, (*path, i), out) for i, v in enumerate(node)]
    return node


def _check_sources(spec: Spec, provenance: dict[str, Quantity], doc: Document) -> None:
    for where, q in provenance.items():
        if q.source is not None and q.source not in spec.sources:
            known = ", ".join(spec.sources) or "none"
            raise SpecError(
                f"source {q.source!r} is not a key of the top-level 'sources' (known: {known})",
                path=f"{where}.source",
                line=doc.line_of(_split(where)),
                source=doc.source,
            )


def _check_rotor_radius(spec: Spec, doc: Document) -> None:
    """A rotor diameter that leaves no blade beyond the hub radius is a mistake."""
    d, s = spec.turbine.rotor_diameter_m, spec.blade.structure
    if d is not None and s is not None and d / 2 <= s.hub_radius_m:
        raise SpecError(
            f"a rotor radius of {d / 2:g} m leaves no blade beyond the blade root at "
            f"blade.structure.hub_radius_m = {s.hub_radius_m:g} m",
            path="turbine.rotor_diameter_m",
            line=doc.line_of(("turbine", "rotor_diameter_m")),
            source=doc.source,
        )


def _check_coupled(spec: Spec, doc: Document) -> None:
    """The coupled model's needs, named with the line: the structures, and a tower head
    heavy enough to carry the rotor it includes."""
    cm = spec.coupled
    if cm is None:
        return
    missing = [
        name
        for name, present in (
            ("blade.structure", spec.blade.structure is not None),
            ("tower sections or distributed properties", spec.tower.has_structure),
            ("tower_head", spec.tower_head is not None),
        )
        if not present
    ]
    if spec.rotor.orientation == "vertical-axis":
        missing.append("a horizontal-axis rotor")
    if missing:
        raise SpecError(
            f"the coupled model needs {', '.join(missing)}",
            path="coupled",
            line=doc.line_of(("coupled",)),
            source=doc.source,
        )
    s, head = spec.blade.structure, spec.tower_head
    assert s is not None and head is not None
    # the rotor's mass and polar inertia (blades by the trapezoid rule, + hub)
    span, per_length = np.asarray(s.span_m), np.asarray(s.mass_per_length_kg_m)
    m_blade = float(np.trapezoid(per_length, span))
    j_blade = float(np.trapezoid(per_length * (s.hub_radius_m + span) ** 2, span))
    n = spec.rotor.blades
    chain = spec.drivetrain.chain
    hub = cm.hub_inertia_kgm2
    if hub is None and chain and chain[0].name != "blades":
        raise SpecError(
            f"the drive-train chain starts with {chain[0].name!r}: the coupled model models "
            "the blades itself, so it needs the chain's blade inertia as a first mass named "
            "'blades' (or coupled.hub_inertia_kgm2 for the hub alone)",
            path="drivetrain.chain[0].name",
            line=doc.line_of(("drivetrain", "chain", 0, "name")),
            source=doc.source,
        )
    if hub is None and chain:
        hub = chain[1].inertia_kgm2 if len(chain) > 1 else 0.0
    from .rigid import nacelle  # the one place that splits the head

    apex = (cm.apex_downwind_m, 0.0, cm.apex_above_top_m)
    try:
        nacelle(head, np.array(apex), n * m_blade + cm.hub_mass_kg, n * j_blade + (hub or 0.0))
    except SpecError as exc:
        raise SpecError(
            exc.message,
            path=exc.path,
            line=doc.line_of(_split(exc.path or "tower_head")),
            source=doc.source,
        ) from None


def _split(dotted: str) -> Path:
    parts: list[str | int] = []
    for piece in dotted.replace("]", "").replace("[", ".").split("."):
        parts.append(int(piece) if piece.isdigit() else piece)
    return tuple(parts)


_BRANCH = ("function-", "tuple[", "list[", "constrained-", "nullable[", "union[")
_SCALAR_TYPES = (
    "float_type",
    "float_parsing",
    "int_type",
    "int_parsing",
    "string_type",
    "bool_type",
    "none_required",
)


def _spec_error(exc: ValidationError, doc: Document, prefix: Path = ()) -> SpecError:
    """The most telling validation error as one line with field path and YAML line.

    A value that fails every branch of a union (a number or a list, say) reports the branch
    that matches its own shape: a list's error rather than "should be a number".
    """
    errors = exc.errors(include_url=False)

    def mismatch(e: Any) -> bool:
        return e["type"] in _SCALAR_TYPES and isinstance(e.get("input"), list | dict)

    err = min(errors, key=lambda e: (mismatch(e), errors.index(e)))
    loc: list[str | int] = []
    for part in err["loc"]:
        if part in ("number", "full", "[key]", "int", "float", "str") or (
            isinstance(part, str) and part.startswith(_BRANCH)
        ):
            continue
        loc.append(part)
    path: Path = (*prefix, *loc)
    message = _message(err)
    extra = len({tuple(e["loc"][: len(loc)]) for e in errors}) - 1
    more = f" (and {extra} more problem{'s' * (extra > 1)})" if extra > 0 else ""
    return SpecError(
        message + more,
        path=format_path(path) or None,
        line=doc.line_of(path),
        source=doc.source,
    )


def _message(err: Any) -> str:
    kind = err["type"]
    got = err.get("input")
    if kind == "missing":
        return "required field is missing"
    if kind == "extra_forbidden":
        return "unknown field (not part of the wtvib spec; check the spelling)"
    if kind == "string_pattern_mismatch":
        pattern = err.get("ctx", {}).get("pattern", "")
        names = {
            r"^(fa|ss|tor)[1-9]$": "fa1…fa9, ss1…ss9, tor1…tor9",
            r"^(flap|edge|tor)[1-9]$": "flap1…flap9, edge1…edge9, tor1…tor9",
            r"^[1-9]$": "1…9",
        }.get(pattern, pattern)
        return f"{got!r} is not a known mode name (expected {names})"
    if kind == "finite_number":
        return "must be a finite number (NaN and infinity are not allowed)"
    text = str(err["msg"])
    if kind.startswith("value_error"):
        text = text.removeprefix("Value error, ")
    if got is not None and not isinstance(got, dict | list) and kind != "literal_error":
        return f"{text} (got {got!r})"
    if kind == "literal_error":
        return f"{text} (got {got!r})"
    return text


def json_schema() -> dict[str, Any]:
    """JSON Schema of the spec, with every number also accepting a quantity mapping."""
    schema = Spec.model_json_schema()
    defs = schema.setdefault("$defs", {})
    quantity = Quantity.model_json_schema()
    defs["Quantity"] = quantity
    ref = {"$ref": "#/$defs/Quantity"}

    def widen(node: Any) -> Any:
        if isinstance(node, dict):
            if node.get("type") in ("number", "integer") and "const" not in node:
                return {"anyOf": [node, ref]}
            return {k: widen(v) if k != "Quantity" else v for k, v in node.items()}
        if isinstance(node, list):
            return [widen(v) for v in node]
        return node

    out = widen(schema)
    out["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    out["title"] = "wtvib turbine spec, format version 1"
    return out  # type: ignore[no-any-return]
