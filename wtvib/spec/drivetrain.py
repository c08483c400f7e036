"""The drive train: gear stages, the chain of inertias and shafts, the generator."""

from typing import Annotated, Literal

from pydantic import Field, model_validator

from .base import ModeEntry, Positive, Ratio, _Strict


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


class FluidCoupling(_Strict):
    """A hydrodynamic (fluid) coupling in the shaft (Hau 7.3.3): torque by slip, no elastic
    stiffness."""

    rated_slip: float = Field(
        gt=0,
        lt=0.5,
        description="Slip between its input and output at rated torque (0.03 = 3 %). [-]",
    )


class ChainShaft(_Strict):
    """The torsional connection between two consecutive masses of the chain."""

    stiffness_nm_rad: Positive | None = Field(
        None,
        description="Torsional stiffness; null for a rigid connection (the masses move as "
        "one, or, between blades and hub, the blades' edgewise spring alone). [N·m/rad]",
    )
    fluid_coupling: FluidCoupling | None = Field(
        None,
        description="A fluid coupling instead of a shaft: no stiffness, the damping of its "
        "slip (rated torque over slip × speed); stiffness and damping then stay unset.",
    )
    damping_nms_rad: float = Field(0.0, ge=0, description="Torsional damping. [N·m·s/rad]")
    speed_ratio: Positive = Field(
        1.0, description="Speed of the shaft the stiffness refers to / rotor speed. [-]"
    )

    @model_validator(mode="after")
    def _one_kind(self) -> "ChainShaft":
        if self.fluid_coupling is None and "stiffness_nm_rad" not in self.model_fields_set:
            raise ValueError(
                "stiffness_nm_rad is needed (null for a rigid connection), or fluid_coupling"
            )
        if self.fluid_coupling is not None and (
            self.stiffness_nm_rad is not None or self.damping_nms_rad
        ):
            raise ValueError(
                "a fluid coupling has no elastic stiffness and its damping follows from its "
                "slip: give fluid_coupling alone, without stiffness_nm_rad or damping_nms_rad"
            )
        return self


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
    grid_frequency_hz: Annotated[float, Field(ge=1.0, le=1000.0)] = Field(
        50.0, description="Grid frequency: 50 or 60 Hz, 16.7 on a railway's, 400 on board. [Hz]"
    )
    pull_out_power_kw: Positive | None = Field(
        None, description="Synchronous: pull-out (maximum) power P_max. [kW]"
    )
    rated_slip: float | None = Field(
        None, gt=0, lt=0.5, description="Induction: slip at rated power (0.01 = 1 %). [-]"
    )
    controller_damping_nms_rad: float = Field(
        0.0, ge=0, description="Converter: damping the speed controller adds. [N·m·s/rad]"
    )

    @model_validator(mode="after")
    def _pull_out_above_rated(self) -> "GeneratorModel":
        # the magnetic spring c_m ∝ cos(asin(P/P_max)) exists only below the pull-out power
        if self.pull_out_power_kw is not None and self.pull_out_power_kw <= self.rated_power_kw:
            raise ValueError(
                f"pull_out_power_kw ({self.pull_out_power_kw:g}) must exceed rated_power_kw "
                f"({self.rated_power_kw:g}): at or above it the generator falls out of step"
            )
        return self


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
