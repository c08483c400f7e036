"""Excitations: rotor harmonics kP and gear-mesh lines, and the operating speeds.

Every excitation is a straight line through the origin of the Campbell diagram,
f = order · Ω/2π (Hau ch. 7.1, Fig. 7.2).
"""

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .rules import Energy
from .spec import RotorSpeed, Spec
from .units import rpm_to_rad_s


@dataclass(frozen=True)
class OperatingRange:
    """Rotor speeds the turbine runs at, in rad/s.

    ``steady`` holds closed intervals (a fixed speed is a zero-width interval);
    ``quick_pass`` the bands inside them that the controller crosses without dwelling;
    ``dwell`` the speeds the turbine spends most time at (each fixed speed, or the rated
    speed of a variable-speed rotor).
    Start-up and shut-down sweep 0 → lowest steady speed; ``overspeed`` is the transient
    limit above the highest steady speed.
    """

    steady: tuple[tuple[float, float], ...]
    quick_pass: tuple[tuple[float, float], ...]
    overspeed: float
    variable: bool
    dwell: tuple[float, ...] = ()

    @property
    def lowest(self) -> float:
        return self.steady[0][0]

    @property
    def highest(self) -> float:
        return self.steady[-1][1]


def operating_range(speed: RotorSpeed) -> OperatingRange:
    """The operating range of a spec's rotor speed, converted to rad/s."""

    def conv(pairs: Sequence[tuple[float, float]]) -> tuple[tuple[float, float], ...]:
        return tuple((float(rpm_to_rad_s(a)), float(rpm_to_rad_s(b))) for a, b in pairs)

    return OperatingRange(
        steady=conv(speed.steady_rpm),
        quick_pass=conv(speed.quick_pass_rpm),
        overspeed=float(rpm_to_rad_s(speed.overspeed)),
        variable=speed.fixed_rpm is None,
        dwell=tuple(float(rpm_to_rad_s(s)) for s in speed.dwell_rpm),
    )


@dataclass(frozen=True)
class Excitation:
    """A line f = order · Ω/2π in the Campbell diagram.

    ``energy`` tells the rule how serious a resonance with it is; ``subsystems`` limits the
    subsystems it acts on (``None``: all).
    """

    id: str
    order: float
    energy: Energy
    description: str
    subsystems: frozenset[str] | None = None
    offset_hz: float = 0.0  # a fixed-frequency excitation has order 0 and this offset

    def frequency_hz(self, omega: ArrayLike) -> NDArray[np.float64]:
        """Excitation frequency [Hz] at rotor speeds ``omega`` [rad/s]."""
        return self.order * np.asarray(omega, dtype=float) / (2.0 * np.pi) + self.offset_hz

    def acts_on(self, subsystem: str) -> bool:
        return self.subsystems is None or subsystem in self.subsystems


def harmonic_energy(k: int, blades: int) -> Energy:
    """Energy class of the k-th rotor harmonic for a rotor with ``blades`` blades.

    Notes
    -----
    1P (mass and pitch imbalance) and N_b·P (tower shadow, wind shear: "aerodynamic
    imbalance") are the dominant excitations (Hau ch. 7.1). Harmonics between them (2P on a
    three-bladed rotor) carry less energy but resonated on the WKA-60 (Hau ch. 7.5.2), so
    they are *secondary*. Higher harmonics carry little energy (Hau ch. 7.2.2): *minor*.
    """
    if k in (1, blades):
        return "dominant"
    if k < blades:
        return "secondary"
    return "minor"


def rotor_harmonics(blades: int, highest: int) -> list[Excitation]:
    """The rotor harmonics 1P … ``highest``·P, always including N_b·P."""
    top = max(highest, blades)
    return [
        Excitation(f"{k}P", float(k), harmonic_energy(k, blades), _harmonic_text(k, blades))
        for k in range(1, top + 1)
    ]


def _harmonic_text(k: int, blades: int) -> str:
    if k == 1:
        return "rotor speed: mass and pitch imbalance"
    if k == blades:
        return "blade passing: tower shadow, wind shear, yaw misalignment"
    if k < blades:
        return "rotor harmonic below blade passing"
    return "higher rotor harmonic"


def gear_mesh(spec: Spec) -> list[Excitation]:
    """Tooth-mesh excitations of the gearbox stages: teeth × shaft rotational frequency.

    References
    ----------
    Hau ch. 7.3.4 (Aeroman: mesh frequency of the second gear stage, Fig. 7.15).
    """
    return [
        Excitation(
            f"mesh.{stage.name}",
            stage.teeth * stage.shaft_speed_ratio,
            "dominant",
            f"gear mesh {stage.name}: {stage.teeth} teeth × {stage.shaft_speed_ratio:g}·P",
            frozenset({"drivetrain"}),
        )
        for stage in spec.drivetrain.gear_stages
    ]


def electrical(spec: Spec) -> list[Excitation]:
    """Generator-side excitations at fixed frequencies (Hau ch. 7.3.4: grid oscillations,
    inverters, control), acting on the drive train."""
    return [
        Excitation(
            f"electrical.{e.name}",
            0.0,
            e.energy,
            f"generator side: {e.name}",
            frozenset({"drivetrain"}),
            e.frequency_hz,
        )
        for e in spec.drivetrain.electrical_excitations
    ]


def excitations(spec: Spec) -> list[Excitation]:
    """Every excitation the audit checks for this turbine."""
    return (
        rotor_harmonics(spec.rotor.blades, spec.audit.harmonics)
        + gear_mesh(spec)
        + electrical(spec)
    )
