"""The few result types every subsystem shares: modes and checks (DESIGN.md)."""

import functools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .document import CheckDoc, ModeDoc, OperatingDoc, RuleDoc
from .rules import Status


class SpeedCurve(Protocol):
    """Natural frequency [Hz] as a function of rotor speed Ω [rad/s] (vectorised)."""

    def __call__(self, omega: NDArray[np.float64]) -> NDArray[np.float64]: ...


@dataclass(frozen=True)
class Southwell:
    """Rotational stiffening of a blade mode: f² = f₀² + K·(Ω/2π)².

    Parameters
    ----------
    f0_hz
        Natural frequency at standstill. [Hz]
    k
        Southwell coefficient. [-]

    References
    ----------
    R. Southwell & F. Gough (1921), as used for rotor blades in e.g. Hansen, *Aerodynamics
    of Wind Turbines*; for a uniform cantilever hinged at the axis K ≈ 1.19 (flap) and
    K_flap − 1 ≈ 0.19 (edge) (DOMAIN.md §3).
    """

    f0_hz: float
    k: float

    def __call__(self, omega: NDArray[np.float64]) -> NDArray[np.float64]:
        rev_hz = np.asarray(omega, dtype=float) / (2.0 * np.pi)
        return np.sqrt(self.f0_hz**2 + self.k * rev_hz**2)


@dataclass(frozen=True)
class Stiffened:
    """A parked frequency carried over rotor speed by another mode's rotational
    stiffening: f² = f₀² + g(Ω)² − g(0)².

    A one- or two-bladed rotor's coupled modes are solved parked (turning, the system is
    periodic); a blade mode among them stiffens as the isolated blade it stands for does
    — Southwell's increment, the centrifugal stiffness added to the parked mode's.

    Parameters
    ----------
    f0_hz
        The parked frequency. [Hz]
    along
        The curve whose increment is added (the isolated blade mode's).
    """

    f0_hz: float
    along: SpeedCurve

    def __call__(self, omega: NDArray[np.float64]) -> NDArray[np.float64]:
        g = self.along(np.asarray(omega, dtype=float))
        g0 = float(self.along(np.zeros(1))[0])
        return np.sqrt(np.maximum(self.f0_hz**2 + g**2 - g0**2, 0.0))


@dataclass(frozen=True)
class Sampled:
    """A frequency-vs-speed curve computed at some rotor speeds, linear in between.

    ``omega`` [rad/s] ascending, ``hz`` [Hz]; held constant beyond the sampled range.
    """

    omega: tuple[float, ...]
    hz: tuple[float, ...]

    def __call__(self, omega: NDArray[np.float64]) -> NDArray[np.float64]:
        return np.asarray(np.interp(np.asarray(omega, dtype=float), *self._arrays))

    @functools.cached_property
    def _arrays(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        # the tuples as arrays once: the resonance routine evaluates a curve thousands of
        # times an audit
        return np.asarray(self.omega, dtype=float), np.asarray(self.hz, dtype=float)


@dataclass(frozen=True)
class Shape:
    """A mode shape: positions along a member [m] and the normalised deflection there."""

    position_m: tuple[float, ...]
    deflection: tuple[float, ...]
    labels: tuple[str, ...] = ()


@dataclass(frozen=True)
class Whirl:
    """Whirl labels of a fixed-frame rotor mode at rotor speeds ``omega`` [rad/s] (the speeds
    of its curve): ``backward`` (f_R − Ω), ``collective``, ``forward`` (f_R + Ω), or ``cyclic``
    where the pair does not travel (standstill)."""

    omega: tuple[float, ...]
    labels: tuple[str, ...]

    def at(self, omega: float) -> str:
        """The label at the sampled speed nearest ``omega``."""
        i = int(np.argmin(np.abs(np.asarray(self.omega) - omega)))
        return self.labels[i]


@dataclass(frozen=True)
class OperatingDamping:
    """A mode's damping at the steady operating points (aerodynamic + structural).

    Points in wind order; ``total`` = ``aero`` + the mode's structural damping ratio.
    """

    wind: tuple[float, ...]  # [m/s]
    omega: tuple[float, ...]  # rotor speed [rad/s]
    pitch_deg: tuple[float, ...]
    aero: tuple[float, ...]  # aerodynamic damping ratio ζ_a
    total: tuple[float, ...]  # ζ_a + structural
    source: str  # the model it came from
    # where the mode's energy sits at each point (coupled modes: ``blade.flap1``,
    # ``tower.fa`` … — a mode followed through a veering changes part); None: not known
    part: tuple[str, ...] | None = None
    #: the aeroelastic root's natural frequency |λ|/2π at each point [Hz] (coupled modes;
    #: None: no damped eigenvalue, the judged structural curve only)
    natural_hz: tuple[float, ...] | None = None
    #: how each point's damping was obtained: "eigenvalue" (the damped root matched to the
    #: mode), "overdamped" (that root is damped past critical: no oscillation there, ζ held
    #: at 1), "first-order" (no damped root resembled the mode: the structural mode's
    #: first-order estimate), "isolated" (an isolated subsystem estimate)
    method: tuple[str, ...] | None = None
    #: the total damping with quasi-steady aerodynamics (the lift following the angle of
    #: attack at once, no shed-wake lag) at each point, for comparison; None: not computed
    quasi_steady: tuple[float, ...] | None = None

    @property
    def damped_hz(self) -> tuple[float, ...] | None:
        """The aeroelastic root's damped frequency ω_n·√(1 − ζ²)/2π at each point [Hz]: 0
        where overdamped (no oscillation)."""
        if self.natural_hz is None:
            return None
        return tuple(
            f * math.sqrt(max(1.0 - z * z, 0.0)) if m != "overdamped" else 0.0
            for f, z, m in zip(self.natural_hz, self.total, self.method or (), strict=False)
        )

    def at(self, omega: float) -> float:
        """The lowest total damping of the operating points at rotor speed Ω [rad/s]
        (several winds share the rated speed), linear between speeds, held beyond them."""
        speeds, low = self._lowest_by_speed
        return float(np.interp(omega, speeds, low))

    @functools.cached_property
    def _lowest_by_speed(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        speeds, which = np.unique(np.round(np.asarray(self.omega), 9), return_inverse=True)
        low = np.full(len(speeds), np.inf)
        np.minimum.at(low, which, np.asarray(self.total, dtype=float))
        return speeds, low

    @property
    def lowest(self) -> int:
        """Index of the operating point with the lowest total damping."""
        return int(np.argmin(self.total))


@dataclass(frozen=True)
class Mode:
    """A natural mode of one subsystem.

    ``frequency_hz`` is the standstill value; ``curve``, where present, gives the frequency
    over rotor speed (Campbell diagrams and resonance checks use it).
    """

    id: str
    subsystem: str
    description: str
    frequency_hz: float
    damping_ratio: float | None = None
    curve: SpeedCurve | None = None
    shape: Shape | None = field(default=None, compare=False)
    regimes: frozenset[str] | None = None  # operating regimes the mode exists in (None: all)
    condition: str | None = None  # the condition the frequency holds in (generator free …)
    whirl: Whirl | None = field(default=None, compare=False)
    superseded_by: str | None = None  # the coupled mode judged in its place
    damping_source: str | None = None  # where damping_ratio came from when not the mode's own
    origin: str = "given"  # given (in the spec), computed (a subsystem model) or coupled
    replaces: str | None = None  # the isolated mode a coupled mode stands for (if it exists)
    operating: OperatingDamping | None = field(default=None, compare=False)  # in operation
    #: The worst status a resonance on this mode may take, where its damping is beyond the
    #: model (a floating platform's rigid-body modes: warn — radiation and viscous damping)
    status_cap: Status | None = None
    #: The standstill frequency's band [Hz] with lower- and upper-bound inputs (a monopile's
    #: soil, an uncalibrated concrete tower's modulus): judged as a band — a line anywhere
    #: in it, or within the margin of its ends.
    band_hz: tuple[float, float] | None = None

    def band_factors(self) -> tuple[float, float] | None:
        """The band as factors on the frequency (applied along the curve)."""
        if self.band_hz is None or self.frequency_hz <= 0:
            return None
        return self.band_hz[0] / self.frequency_hz, self.band_hz[1] / self.frequency_hz

    def damping_at(self, omega: float, default: float) -> float:
        """The damping ratio judged at rotor speed Ω [rad/s]: in operation where known (the
        aerodynamics), else the mode's own or the default."""
        if self.operating is not None:
            return self.operating.at(omega)
        return self.damping_ratio if self.damping_ratio is not None else default

    def frequency_at(self, omega: ArrayLike) -> NDArray[np.float64]:
        """Natural frequency [Hz] at rotor speeds ``omega`` [rad/s]."""
        w = np.asarray(omega, dtype=float)
        if self.curve is None:
            return np.full_like(w, self.frequency_hz)
        return np.asarray(self.curve(w), dtype=float)

    def to_dict(self) -> ModeDoc:
        doc: ModeDoc = {
            "id": self.id,
            "subsystem": self.subsystem,
            "description": self.description,
            "frequency_hz": round(self.frequency_hz, 6),
            "damping_ratio": self.damping_ratio,
            "speed_dependent": self.curve is not None,
        }
        if self.regimes is not None:
            doc["regimes"] = sorted(self.regimes)
        if self.condition is not None:
            doc["condition"] = self.condition
        if self.superseded_by:
            doc["superseded_by"] = self.superseded_by
        if self.damping_source:
            doc["damping_source"] = self.damping_source
        if self.operating:
            doc["damping_in_operation"] = self._operating()
        if self.band_hz is not None:
            doc["band_hz"] = [round(self.band_hz[0], 6), round(self.band_hz[1], 6)]
        if self.whirl is not None:
            rpm = [round(w * 30 / np.pi, 4) for w in self.whirl.omega]
            doc["whirl"] = {"rpm": rpm, "labels": list(self.whirl.labels)}
        return doc

    def _operating(self) -> OperatingDoc:
        op = self.operating
        assert op is not None
        i = op.lowest
        return {
            "lowest_total_damping_ratio": round(op.total[i], 6),
            "aerodynamic_damping_ratio": round(op.aero[i], 6)
            if math.isfinite(op.aero[i])
            else None,
            "at_wind_m_s": round(op.wind[i], 4) if math.isfinite(op.wind[i]) else None,
            "at_rpm": round(op.omega[i] * 30 / np.pi, 4),
            "source": op.source,
        }

    @property
    def judged(self) -> bool:
        """Whether the resonance routine judges this mode: it exists in some operating regime
        and no better (coupled) model has it."""
        return self.superseded_by is None and (self.regimes is None or bool(self.regimes))


@dataclass(frozen=True)
class Rule:
    """The rule a check applied, and where it comes from."""

    name: str
    source: str

    def to_dict(self) -> RuleDoc:
        return {"name": self.name, "source": self.source}


@dataclass(frozen=True)
class Check:
    """One audit finding: a stable id, a status, a message, the rule and its numbers."""

    id: str
    subsystem: str
    status: Status
    message: str
    rule: Rule
    numbers: dict[str, Any] = field(default_factory=dict)

    def to_dict(self) -> CheckDoc:
        doc = {
            "id": self.id,
            "subsystem": self.subsystem,
            "status": self.status,
            "message": self.message,
            "rule": self.rule.to_dict(),
            **self.numbers,
        }
        return cast(CheckDoc, doc)  # the numbers' keys: CheckDoc's optional fields


def by_frequency(mode: Mode) -> tuple[float, str]:
    """The order modes are listed in: by frequency, and modes the arithmetic cannot tell
    apart (equal to nine significant digits: a symmetric floater's surge and sway, a round
    beam's flap and edge) by id — the same order on every machine, where rounding's last
    bits had decided it."""
    return (float(f"{mode.frequency_hz:.9g}"), mode.id)


def ordinal(k: int) -> str:
    """Ordinal words of mode descriptions: 1 → '1st', 2 → '2nd', 3 → '3rd', 4 → '4th'."""
    return f"{k}{ {1: 'st', 2: 'nd', 3: 'rd'}.get(k if k < 20 else k % 10, 'th') }"


def operating_points(winds: Sequence[float], kind: str = "operating points") -> str:
    """How many operating points, over which winds: ``26 operating points 3–25 m/s``, or
    ``1 operating point at 8 m/s`` (a linearisation deck's own)."""
    if len(winds) == 1:
        return f"1 {kind.removesuffix('s')} at {winds[0]:g} m/s"
    return f"{len(winds)} {kind} {winds[0]:g}–{winds[-1]:g} m/s"


def dotted_lines(name: str, fits: Callable[[str], bool]) -> list[str]:
    """A dotted id or field path (``drivetrain.resonance.mesh.stage2``) in lines that each
    ``fits``, broken after a dot, never mid-word; a part too long for any line keeps one of
    its own. For tables: the id stays readable and whole (the JSON keeps it on one line)."""
    parts = name.split(".")
    lines = [""]
    for piece in [p + "." for p in parts[:-1]] + parts[-1:]:
        if lines[-1] and not fits(lines[-1] + piece):
            lines.append("")
        lines[-1] += piece
    return lines
