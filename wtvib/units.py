"""Unit conversions, in one place (STYLE.md habit 2).

Inside wtvib, rotor speed is in rad/s and frequency in Hz only where a person reads it;
rpm appears only in the spec and in the report.
"""

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

TWO_PI = 2.0 * math.pi
#: Standard gravity [m/s²] (ISO 80000-3; OpenFAST's default Gravity too).
STANDARD_GRAVITY = 9.80665


def rpm_to_rad_s(rpm: ArrayLike) -> NDArray[np.float64]:
    """Rotor speed from revolutions per minute to rad/s."""
    return np.asarray(rpm, dtype=float) * TWO_PI / 60.0


def rad_s_to_rpm(omega: ArrayLike) -> NDArray[np.float64]:
    """Rotor speed from rad/s to revolutions per minute."""
    return np.asarray(omega, dtype=float) * 60.0 / TWO_PI


def rad_s_to_hz(omega: ArrayLike) -> NDArray[np.float64]:
    """Angular frequency [rad/s] to cyclic frequency [Hz]; also rotor speed to 1P [Hz]."""
    return np.asarray(omega, dtype=float) / TWO_PI
