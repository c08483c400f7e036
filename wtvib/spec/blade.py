"""The blades: given modes or their structure, and the aeroelastic (typical-section) inputs."""

from typing import Annotated, Literal

from pydantic import Field, model_validator

from .base import (
    BladeModeName,
    Chord,
    ModeEntry,
    Positive,
    Ratio,
    ShapePolynomial,
    StiffnessDamping,
    TableRows,
    _increasing,
    _same_length,
    _Strict,
)

#: No operating wind is faster (the work of the stall sweep grows with it: 1e9 m/s
#: allocated 24 GB). [m/s]
MAX_WIND_M_S = 100.0


class BladeStructure(_Strict):
    """A blade as a table of distributed properties along its span (cantilevered at the
    root, or free there: a beam on nothing, as OpenFAST's BeamDyn test beams stand)."""

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
    ga_flap_n: list[Positive] | None = Field(
        None,
        description="Transverse shear stiffness κ·G·A of the flapwise deflection (the shear "
        "that goes with ei_flap_nm2). With ga_edge_n the blade is a Timoshenko beam: its "
        "shear deformation lowers the higher modes (the sections' rotary inertia is "
        "neglected); without, an Euler–Bernoulli beam, as ElastoDyn's. [N]",
    )
    ga_edge_n: list[Positive] | None = Field(
        None, description="Transverse shear stiffness κ·G·A of the edgewise deflection. [N]"
    )
    rows: TableRows | None = Field(
        None, description="Where the stations stand in the file they were read from."
    )
    tip_mass_kg: float = Field(
        0.0, ge=0, description="Point mass at the tip (a tip brake: ElastoDyn TipMass). [kg]"
    )
    root: Literal["clamped", "free"] = Field(
        "clamped",
        description="The blade's root: clamped to the hub (a blade), or free (a beam on "
        "nothing — its rigid-body motion left out, a standstill model).",
    )
    pitch_drive_nm_rad: Positive | None = Field(
        None,
        description="Torsional stiffness of the pitch drive and bearing holding the blade at "
        "its root (Hau 7.2.2); none: the root clamped in torsion. [N·m/rad]",
    )

    @model_validator(mode="after")
    def _consistent(self) -> "BladeStructure":
        _increasing("span_m", self.span_m)
        if self.span_m[0] != 0:
            raise ValueError("span_m must start at 0 (the blade root)")
        _same_length(self, "span_m")
        if (self.gj_nm2 is None) != (self.torsional_inertia_kgm is None):
            raise ValueError("give gj_nm2 and torsional_inertia_kgm together")
        if (self.ga_flap_n is None) != (self.ga_edge_n is None):
            raise ValueError("give ga_flap_n and ga_edge_n together")
        return self


class AeroSection(_Strict):
    """A blade section as a typical section for divergence and flutter (Hau Fig. 7.6)."""

    radius_fraction: float = Field(
        0.75, gt=0, le=1, description="Position r/R of the section on the rotor radius. [-]"
    )
    chord_m: Chord = Field(description="Chord c. [m]")
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
    chord_m: list[Chord] = Field(description="Chord. [m]")
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
        le=MAX_WIND_M_S,
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
    min_wind_m_s: Positive = Field(
        4.0, le=MAX_WIND_M_S, description="Lowest wind speed in operation. [m/s]"
    )
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
    rated_wind_m_s: Annotated[Positive, Field(le=MAX_WIND_M_S)] | None = Field(
        None,
        description="Rated wind speed (pitch regulation); default from the tip-speed ratio. [m/s]",
    )


class TipDamper(_Strict):
    """A tuned mass damper in each blade's tip (Hau 7.2.3: LM's remedy for edgewise
    vibration), tuned and damped as Den Hartog's optimum."""

    mass_kg: Positive = Field(description="Moving mass of the damper in one blade. [kg]")
    tuned_to: Literal["edge1", "flap1"] = Field(
        "edge1", description="The blade mode it is tuned to."
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
    tip_damper: TipDamper | None = Field(
        None, description="A tuned mass damper in each blade's tip (adds damping to the mode)."
    )
    polynomials: dict[Literal["flap1", "flap2", "edge1"], ShapePolynomial] = Field(
        default_factory=dict,
        description="An ElastoDyn deck's blade mode-shape polynomials (BldFl1Sh, BldFl2Sh, "
        "BldEdgSh), audited against the modes the structure computes.",
    )
    damping_by_mode: dict[Literal["flap1", "flap2", "edge1"], Ratio] = Field(
        default_factory=dict,
        description="Damping ratios of single computed blade modes, in place of "
        "damping_ratio (ElastoDyn's BldFlDmp(1), BldFlDmp(2), BldEdDmp(1)). [-]",
    )
    damping_at: Literal["mode", "blade-alone"] = Field(
        "mode",
        description="What the damping ratios are the ratios of: 'mode', each computed "
        "mode's own; 'blade-alone', ElastoDyn's — a stiffness-proportional damping whose "
        "ratio is given at the frequency the mode's polynomial implies on the blade alone "
        "(not turning, without tip mass; the blade's own mode where no polynomial is "
        "given), so that a mode at f carries ζ·f/f_alone (ElastoDyn.f90: CBF = "
        "0.01·BldFDamp·KBF/(π·FreqBF(:,1))).",
    )
    stiffness_damping_s: StiffnessDamping | None = Field(
        None,
        description="The blade's damping as stiffness-proportional (β flapwise, edgewise, "
        "torsion: ζ = π·β·f on every mode, in place of the ratio; HAWC2's damping_aniso, "
        "BeamDyn's μ).",
    )
    dofs: list[Literal["flap1", "flap2", "edge1"]] | None = Field(
        None,
        description="The blade's degrees of freedom where a deck switches some off "
        "(ElastoDyn's FlapDOF1, FlapDOF2, EdgeDOF): only these of the structure's modes are "
        "modelled, in the blade model and the coupled one, as OpenFAST models the deck. "
        "None: every mode the structure has.",
    )
