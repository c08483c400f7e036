"""The turbine's identity and its rotor: blades, orientation, hub and operating speeds."""

from typing import Annotated, Literal

from pydantic import Field, model_validator

from .base import Positive, RotorDiameter, Rpm, _Strict


class TurbineInfo(_Strict):
    """Identification of the turbine."""

    name: str = Field(min_length=1, description="Name shown in reports.")
    manufacturer: str | None = None
    year: int | None = Field(None, ge=1800, le=2200, description="Year of commissioning.")
    rated_power_kw: Positive | None = Field(None, description="Rated power. [kW]")
    rotor_diameter_m: RotorDiameter | None = Field(None, description="Rotor diameter. [m]")
    hub_height_m: Positive | None = Field(None, description="Hub height. [m]")
    description: str | None = None


class RotorSpeed(_Strict):
    """Rotor speed: a fixed speed (or several, for pole-changing generators), a range, or
    parked (a standstill audit of another tool's parked results: no rotor excitation)."""

    parked: bool = Field(
        False,
        description="A standstill audit: the rotor does not turn (another tool's results "
        "at 0 rpm, `results`); no rotor harmonic is judged, the modes' stability is.",
    )
    fixed_rpm: Rpm | Annotated[list[Rpm], Field(min_length=1)] | None = Field(
        None, description="Fixed operating speed(s). [rpm]"
    )
    min_rpm: Annotated[float, Field(ge=0, le=1e4)] | None = Field(
        None,
        description="Lowest steady speed (variable); 0: steady operation from standstill, "
        "no start-up regime. [rpm]",
    )
    rated_rpm: Rpm | None = Field(None, description="Rated speed (variable). [rpm]")
    max_rpm: Rpm | None = Field(None, description="Highest steady speed (variable). [rpm]")
    overspeed_rpm: Rpm | None = Field(None, description="Transient overspeed limit. [rpm]")
    overspeed_factor: float | None = Field(
        None,
        gt=1,
        description="Transient overspeed as a factor on the highest steady speed; default "
        "1.15 when neither this nor overspeed_rpm is given (Hau ch. 7.3.4, Growian). [-]",
    )
    source: str | None = Field(
        None,
        max_length=300,
        description="Where the operating speeds come from (an importer's or the command "
        "line's statement, shown beside the speeds in the headline).",
    )
    # pairs as lists: YAML has no tuples, and a strict tuple refuses every list it is given
    quick_pass_rpm: list[Annotated[list[Rpm], Field(min_length=2, max_length=2)]] = Field(
        default_factory=list,
        description="Speed bands [low, high] the controller passes through quickly without "
        "steady operation (variable speed). [rpm]",
    )

    @model_validator(mode="after")
    def _consistent(self) -> "RotorSpeed":
        fixed = self.fixed_rpm is not None
        ranged = self.min_rpm is not None or self.max_rpm is not None
        if self.parked:
            given = [k for k, v in self if k not in ("parked", "source") and v not in (None, [])]
            if given:
                raise ValueError(f"parked: true takes no speeds ({', '.join(given)} given)")
            return self
        if fixed == ranged:
            raise ValueError("give either fixed_rpm, or min_rpm and max_rpm (or parked: true)")
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
        """Steady operating speeds as closed intervals (a fixed speed is a point; parked:
        standstill, 0 rpm). [rpm]"""
        if self.parked:
            return [(0.0, 0.0)]
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
        if self.parked:
            return 0.0
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
