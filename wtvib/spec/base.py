"""Building blocks of the spec schema: strict models, quantities with provenance, given modes."""

import itertools
import math
from collections.abc import Mapping
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Discriminator, Field, Tag, model_validator


class _Strict(BaseModel):
    """Every spec model: unknown keys refused, immutable, finite, and strict in type — a
    number must be a number ("110000" is text, ``true`` is not one blade), a count a whole
    number (YAML 1.1 coerced both silently)."""

    model_config = ConfigDict(
        extra="forbid", frozen=True, allow_inf_nan=False, str_strip_whitespace=True, strict=True
    )


Positive = Annotated[float, Field(gt=0)]

# Physical ranges far beyond any wind turbine, short of what breaks a model (a
# 1e-300 rpm rotor asked the Floquet sweep for an integer too large for an array, a
# 1e-300 m rotor divided the swept area by zero, a 1e300 m chord overflowed the blade).
#: A rotor speed. [rpm]
Rpm = Annotated[float, Field(ge=1e-3, le=1e4)]
#: A rotor diameter. [m]
RotorDiameter = Annotated[float, Field(ge=0.1, le=1e3)]
#: A blade chord. [m]
Chord = Annotated[float, Field(ge=1e-3, le=1e3)]
#: A tower's or pile's diameter or wall (a 1e300 m diameter overflowed the section's
#: second moment into NaN matrices; a 1e-300 m wall left a pile with no stiffness). [m]
TowerSize = Annotated[float, Field(ge=1e-4, le=1e3)]
#: A height above the tower base. [m]
Height = Annotated[float, Field(ge=-1e3, le=1e4)]


Ratio = Annotated[float, Field(ge=0, lt=1)]


class Quantity(_Strict):
    """A number with its provenance (accepted wherever a number is)."""

    value: int | float = Field(
        description="The number itself, in the unit its key names (a whole number where a "
        "count goes: teeth, pole pairs)."
    )
    provenance: Literal["published", "derived", "tuned", "representative"] = Field(
        description="published: printed in the source; derived: computed or read from a "
        "statement in the source; tuned: set so that the audit reproduces a statement of "
        "the source (its agreement with that statement is by construction, no validation); "
        "representative: a plausible value where the source gives none."
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


#: ElastoDyn stops on a mode-shape polynomial whose coefficients do not add to 1 within
#: this (ElastoDyn_IO.f90, ValidateModeShapeCoeffs).
SHAPE_SUM_TOLERANCE = 0.0015


class ShapePolynomial(_Strict):
    """An ElastoDyn mode-shape polynomial φ(x) = Σ c_k·x^k, k = 2 … 6, over the flexible
    length (x = 0 at the root, 1 at the tip), as a tower or blade file gives it: φ(1) = 1,
    φ(0) = φ′(0) = 0."""

    coefficients: Annotated[list[float], Field(min_length=5, max_length=5)] = Field(
        description="c₂ … c₆, the coefficients of x² … x⁶ (they add to 1). [-]"
    )
    name: str | None = Field(None, max_length=40, description="The deck's key (TwFAM1Sh …).")
    file: str | None = Field(None, max_length=4096, description="The file that gives it.")
    line: int | None = Field(None, ge=1, description="The line of its first coefficient.")

    @model_validator(mode="after")
    def _adds_to_one(self) -> "ShapePolynomial":
        if not all(math.isfinite(c) for c in self.coefficients):
            raise ValueError("the coefficients must be finite numbers")
        total = sum(self.coefficients)
        if abs(total - 1.0) > SHAPE_SUM_TOLERANCE:
            raise ValueError(
                f"the coefficients add to {total:.6g}, not 1 (φ(1) = 1): ElastoDyn stops on "
                f"a sum more than {SHAPE_SUM_TOLERANCE:g} from 1"
            )
        return self


class SpeedTable(_Strict):
    """A natural frequency measured or computed at rotor speeds (a Campbell curve)."""

    rpm: list[Annotated[float, Field(ge=0, le=10_000)]] = Field(
        description="Rotor speeds, increasing. [rpm]"
    )
    frequency_hz: list[Positive] = Field(description="The frequency at each speed. [Hz]")

    @model_validator(mode="after")
    def _consistent(self) -> "SpeedTable":
        _increasing("rpm", self.rpm)
        _same_length(self, "rpm")
        return self


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
    speeds: SpeedTable | None = Field(
        None,
        description="The frequency over rotor speed (e.g. a measured Campbell diagram), "
        "linear between the points and held beyond them; replaces the Southwell stiffening. "
        "A table without 0 rpm starts from frequency_hz at standstill.",
    )

    @model_validator(mode="after")
    def _one_curve(self) -> "ModeSpec":
        if self.speeds is not None and self.southwell is not None:
            raise ValueError("give southwell or speeds, not both (speeds is the whole curve)")
        if self.speeds is not None and self.speeds.rpm[0] == 0:
            f0 = self.speeds.frequency_hz[0]
            if abs(f0 - self.frequency_hz) > 0.01 * self.frequency_hz:
                raise ValueError(
                    f"speeds starts at 0 rpm with {f0:g} Hz but frequency_hz is "
                    f"{self.frequency_hz:g} Hz (the standstill value): make them agree"
                )
        return self


def _mode_tag(value: Any) -> str:
    # a mapping when validating, a ModeSpec when serialising (model_dump): both are "full"
    return "full" if isinstance(value, Mapping | ModeSpec) else "number"


ModeEntry = Annotated[
    Annotated[Positive, Tag("number")] | Annotated[ModeSpec, Tag("full")],
    Discriminator(_mode_tag),
]


TowerModeName = Annotated[str, Field(pattern=r"^(fa|ss|tor)[1-9]$")]


BladeModeName = Annotated[str, Field(pattern=r"^(flap|edge|tor)[1-9]$")]


YawModeName = Annotated[str, Field(pattern=r"^[1-9]$")]


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


class TableRows(_Strict):
    """Where an imported table's stations stand in the file they were read from (an
    ElastoDyn tower or blade file): a message about a station names that file, its line and
    the file's own column name, not the converted field."""

    file: str = Field(description="The file the table was read from.")
    lines: list[int] = Field(description="The line of each station in that file.")
    columns: dict[str, str] = Field(
        default_factory=dict, description="The file's column name of each field."
    )


class StiffnessDamping(_Strict):
    """Stiffness-proportional damping, c = β·k per direction: a mode of frequency f in that
    direction has ζ = π·β·f (HAWC2's damping_posdef/damping_aniso K coefficients, BeamDyn's
    μ). [s]"""

    bending_1: float = Field(
        ge=0, le=1.0, description="β of the first bending direction: fore-aft, flapwise. [s]"
    )
    bending_2: float = Field(ge=0, le=1.0, description="β of the second: side-side, edgewise. [s]")
    torsion: float = Field(0.0, ge=0, le=1.0, description="β of torsion. [s]")

    def ratio(self, direction: str, frequency_hz: float) -> float:
        """ζ = π·β·f of a mode in ``direction`` (fa, ss, flap, edge, tor)."""
        beta = {
            "fa": self.bending_1, "flap": self.bending_1,
            "ss": self.bending_2, "edge": self.bending_2,
        }.get(direction, self.torsion)  # fmt: skip
        return math.pi * beta * frequency_hz
