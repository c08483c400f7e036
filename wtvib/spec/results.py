"""Modes another tool computed: the Campbell results of OpenFAST linearisation, HAWCStab2 or a
table, as the modes of a turbine to judge."""

from typing import Annotated, Literal

from pydantic import Field, model_validator

from .base import Positive, _increasing, _Strict

Whirl = Literal["backward", "forward", "collective", "cyclic", "fixed"]

#: Mode ids of imported results: a dotted name of letters, digits and underscores.
ResultModeName = Annotated[str, Field(pattern=r"^[a-z][a-z0-9_]*(\.[a-z0-9_]+)*$", max_length=80)]


class ResultMode(_Strict):
    """One mode over the operating points: frequency and (optionally) damping at each."""

    description: str = Field(max_length=200, description="What the mode is (from the tool).")
    frame: Literal["fixed", "rotating"] = Field(
        "fixed",
        description="fixed: a whole-turbine mode in the fixed frame (multi-blade "
        "coordinates, whirl per point); rotating: a blade mode in the rotating frame.",
    )
    rpm: list[Annotated[float, Field(ge=0, le=10_000)]] = Field(
        min_length=1, description="Rotor speed of each operating point. [rpm]"
    )
    frequency_hz: list[Positive] = Field(description="Natural frequency at each point. [Hz]")
    damping_ratio: list[Annotated[float, Field(ge=-1, le=1)]] | None = Field(
        None, description="Damping ratio at each point (negative: unstable). [-]"
    )
    whirl: list[Whirl] | None = Field(None, description="Whirl at each point (fixed frame).")
    wind_m_s: list[Annotated[float, Field(ge=0, le=100)]] | None = Field(
        None, description="Wind speed of each point. [m/s]"
    )
    damped_frequency_hz: list[Annotated[float, Field(ge=0)]] | None = Field(
        None, description="Damped frequency (imaginary part of the root) at each point. [Hz]"
    )
    share: list[Annotated[float, Field(ge=0, le=1)]] | None = Field(
        None,
        description="The share of the mode held by the coordinate group it is named after, "
        "at each point (the name's confidence). [-]",
    )

    @model_validator(mode="after")
    def _consistent(self) -> "ResultMode":
        n = len(self.rpm)
        if n > 1:
            _increasing("rpm", self.rpm)
        for name in (
            "frequency_hz",
            "damping_ratio",
            "whirl",
            "wind_m_s",
            "damped_frequency_hz",
            "share",
        ):
            values = getattr(self, name)
            if values is not None and len(values) != n:
                raise ValueError(f"{name} has {len(values)} values but rpm has {n}")
        return self


class Results(_Strict):
    """The modes of the turbine as another tool computed them, with where they came from."""

    tool: str = Field(max_length=200, description="The tool and method (shown per mode).")
    files: list[str] = Field(default_factory=list, description="The files read.")
    modes: dict[ResultModeName, ResultMode] = Field(min_length=1)
