"""Excitations: rotor harmonics kP and gear-mesh lines, and the operating speeds.

Every excitation is a straight line through the origin of the Campbell diagram,
f = order · Ω/2π (Hau ch. 7.1, Fig. 7.2).
"""

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..rules import Energy
from ..spec import RotorSpeed, Spec
from ..units import rpm_to_rad_s


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

    def conv(pairs: Sequence[Sequence[float]]) -> tuple[tuple[float, float], ...]:
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
    blades: int | None = None  # rotor harmonics: the rotor's blade count (energy by frame)

    def frequency_hz(self, omega: ArrayLike) -> NDArray[np.float64]:
        """Excitation frequency [Hz] at rotor speeds ``omega`` [rad/s]."""
        return self.order * np.asarray(omega, dtype=float) / (2.0 * np.pi) + self.offset_hz

    def acts_on(self, subsystem: str) -> bool:
        return self.subsystems is None or subsystem in self.subsystems

    def blade_harmonic(self, whirl: str | None) -> int | None:
        """The rotating-frame harmonic that drives a fixed-frame rotor mode of ``whirl`` on
        this fixed-frame line (:func:`driving_harmonic`); None for other lines, for modes
        that do not whirl (``fixed``) and for a cyclic pair at rest (two harmonics, k ± 1:
        :meth:`energy_for` takes the stronger)."""
        if self.blades is None or whirl in (None, "fixed", "cyclic"):
            return None
        return driving_harmonic(round(self.order), str(whirl))

    def energy_for(self, whirl: str | None) -> Energy | None:
        """Energy class of this line on a mode of ``whirl``; None: the line cannot drive it."""
        if self.blades is None or whirl is None or whirl == "fixed":
            return self.energy
        k = round(self.order)
        ms = (k - 1, k + 1) if whirl == "cyclic" else (driving_harmonic(k, whirl),)
        found = [harmonic_energy(m, self.blades) for m in ms if m >= 1]
        if not found:
            return None
        energy = min(found, key=_ENERGY_RANK.index)
        # a symmetric rotor passes blade loads to its rotor modes only at fixed-frame
        # multiples of N (driving_harmonic, Notes): other lines need rotor asymmetry
        return energy if k % self.blades == 0 else "minor"


def driving_harmonic(k: int, whirl: str) -> int:
    """The blade (rotating-frame) harmonic mP behind a fixed-frame rotor mode on line kP.

    Notes
    -----
    Blade b of N sits at ψ_b = Ωt + 2πb/N; an azimuth-periodic load on it, F cos(mψ_b), is a
    rotating-frame harmonic mP. In multi-blade coordinates the collective part
    (1/N)Σ_b cos(mψ_b) is cos(mΩt) when N divides m and zero otherwise; the cyclic part
    (2/N)Σ_b cos(mψ_b)·cos ψ_b = (1/N)Σ_b[cos((m+1)ψ_b) + cos((m−1)ψ_b)] carries fixed-frame
    frequencies (m ± 1)Ω. A cyclic mode of rotating frequency f_R appears in the fixed frame
    as the backward whirl f_R − Ω and the forward whirl f_R + Ω. So a backward-whirl mode met
    by fixed-frame kP has f_R = (k + 1)Ω — the blades' (k+1)P drives it; a forward-whirl mode
    (k − 1)P; a collective mode kP. A cyclic pair that does not travel (standstill) is judged
    by the stronger of (k ± 1)P. For three blades, fixed 3P on a flap backward
    whirl is the blades' 4P (minor), on a forward whirl their 2P (secondary).

    The same sums say which fixed-frame lines reach the rotor modes at all: the blades' mP
    drives the collective only when N divides m, the cyclic pair only when N divides m ± 1,
    so a rotor with identical blades excites its rotor modes at fixed-frame multiples of
    N·P only. Any other fixed-frame line (4P on three blades) needs rotor asymmetry — blade
    to blade differences in mass, pitch or shape — and is judged as a minor excitation
    whatever the blade harmonic behind it (:meth:`Excitation.energy_for`); fixed-frame
    modes (tower, drive train, yaw) keep each line's own class (1P imbalance, 2P).

    References
    ----------
    M. H. Hansen, "Aeroelastic instability problems for wind turbines", Wind Energy 10 (2007)
    551–577, §2 (whirl frequencies f_R ∓ Ω); G. Bir, NREL/CP-500-42553 (2008), §2 (MBC);
    DOMAIN.md §3 ("Fixed and rotating frames").
    """
    if whirl == "backward":
        return k + 1
    if whirl == "forward":
        return k - 1
    return k  # collective, alternating (a cyclic pair at rest: see Excitation.energy_for)


#: Energy classes, strongest first.
_ENERGY_RANK: tuple[Energy, ...] = ("dominant", "secondary", "minor")


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
        Excitation(
            f"{k}P", float(k), harmonic_energy(k, blades), _harmonic_text(k, blades), blades=blades
        )
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


def excitations(spec: Spec, own: Sequence[Excitation] = ()) -> list[Excitation]:
    """Every excitation the audit checks for this turbine: the rotor's harmonics, which act
    on every subsystem, and the lines each subsystem declares as its ``own`` (the drive
    train's gear mesh, shaft imbalance and generator side:
    :func:`wtvib.subsystems.drivetrain.excitations`) — none for a parked rotor: every line
    is at 0 Hz at standstill."""
    if spec.rotor.speed.parked:
        return []
    return rotor_harmonics(spec.rotor.blades, spec.audit.harmonics) + list(own)
