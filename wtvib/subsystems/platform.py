"""A floating platform under the tower: a rigid body with six degrees of freedom.

The platform's matrices are given about its reference point (PRP, on the still-water line
below the tower axis), in OpenFAST's order (surge, sway, heave, roll, pitch, yaw):

* mass: its rigid-body mass matrix — m, its centre of mass at height z_G on the axis, its
  inertias about the CM (roll, pitch, yaw) moved to the PRP (parallel axes) — plus the
  hydrodynamic added mass A (infinite-frequency A∞ of a potential-flow code, or strip
  theory);
* restoring: the hydrostatic stiffness (waterplane area ρgA_wp in heave, ρg(I_wp + V·z_B)
  in roll and pitch) and the moorings' (linearised about the undisplaced position), to
  which the platform's own weight adds −m·g·z_G in roll and pitch (the tower's and the
  nacelle's weight act through the tower model's gravity: its geometric stiffness and the
  head's P-δ term).

In a bending plane the tower's base carries the platform: with the base at height h above
the PRP, the fore-aft plane's base translation u and slope u′ are the platform's surge
x = u − h·u′ and pitch θ = u′; the side-side plane's v and v′ its sway y = v − h·v′ and
roll φ = −v′ (a positive roll tilts the tower towards −y). The platform's 2 × 2 blocks of
each plane enter the tower's matrices at the base (Tᵀ·M·T, Tᵀ·K·T): surge and pitch (sway
and roll) come out as the plane's lowest modes, the tower's bending above them, with its
base free. Heave and yaw are single degrees of freedom: heave with the whole turbine's
mass, yaw on the tower's torsion.

Jonkman 2010 (NREL/TP-500-47535, the OC3-Hywind spar: §5, its matrices and frequencies);
Robertson et al. 2014 (NREL/TP-5000-60601, OC4-DeepCwind).
"""

from collections.abc import Callable
from typing import TYPE_CHECKING, Literal

import numpy as np
from numpy.typing import NDArray

from ..numerics.modal import ModalError
from ..units import STANDARD_GRAVITY

if TYPE_CHECKING:
    from ..spec.tower import Platform

Array = NDArray[np.float64]
G = STANDARD_GRAVITY

#: The platform DOFs of each bending plane (translation, rotation) in the 6-DOF order.
PLANE_DOFS: dict[str, tuple[int, int]] = {"fa": (0, 4), "ss": (1, 3)}


def rigid_mass(p: "Platform") -> Array:
    """The platform's rigid-body mass matrix at the PRP (its CM on the axis at z_G)."""
    m, z = p.mass_kg, p.cm_m
    out = np.zeros((6, 6))
    out[0, 0] = out[1, 1] = out[2, 2] = m
    out[0, 4] = out[4, 0] = m * z  # surge–pitch: a pitch θ moves the CM by z·θ in x
    out[1, 3] = out[3, 1] = -m * z  # sway–roll: a roll φ moves it by −z·φ in y
    out[3, 3] = p.inertia_roll_kgm2 + m * z**2
    out[4, 4] = p.inertia_pitch_kgm2 + m * z**2
    out[5, 5] = p.inertia_yaw_kgm2
    return out


def added_mass(p: "Platform", frequency_hz: float | None = None) -> Array:
    """The added mass at a frequency: the platform's table A(f) interpolated (beyond it: its
    nearest end), or A∞ (``added_mass``) where it has no table or no frequency is asked."""
    table = p.added_mass_by_frequency
    if not table or frequency_hz is None:
        return np.asarray(p.added_mass, dtype=float)
    f = np.array([point.frequency_hz for point in table])
    a = np.array([point.matrix for point in table], dtype=float)
    i = int(np.searchsorted(f, frequency_hz))
    if i == 0:
        return np.asarray(a[0])
    if i == len(f):
        return np.asarray(a[-1])
    w = (frequency_hz - f[i - 1]) / (f[i] - f[i - 1])
    return np.asarray((1 - w) * a[i - 1] + w * a[i])


def mass(p: "Platform", frequency_hz: float | None = None) -> Array:
    """Rigid-body and added mass at the PRP (the added mass at ``frequency_hz``,
    :func:`added_mass`)."""
    return rigid_mass(p) + added_mass(p, frequency_hz)


def restoring(p: "Platform") -> Array:
    """Hydrostatic and mooring stiffness at the PRP, with the platform's weight term
    −m·g·z_G in roll and pitch."""
    k = np.asarray(p.stiffness, dtype=float).copy()
    k[3, 3] -= p.mass_kg * G * p.cm_m
    k[4, 4] -= p.mass_kg * G * p.cm_m
    return k


def transform(p: "Platform", direction: Literal["fa", "ss"]) -> Array:
    """From the tower base's (translation, slope) to the platform's (translation,
    rotation) in the plane (module notes)."""
    h = p.tower_base_m
    return np.array([[1.0, -h], [0.0, 1.0 if direction == "fa" else -1.0]])


def plane(
    p: "Platform", direction: Literal["fa", "ss"], frequency_hz: float | None = None
) -> tuple[Array, Array]:
    """The platform's mass and stiffness in a bending plane at the tower base's (u, u′)."""
    i = list(PLANE_DOFS[direction])
    t = transform(p, direction)
    m = mass(p, frequency_hz)[np.ix_(i, i)]
    k = restoring(p)[np.ix_(i, i)]
    return t.T @ m @ t, t.T @ k @ t


def heave_frequency(p: "Platform", mass_above: float) -> float:
    """The heave mode [Hz]: the whole turbine's mass (the platform's, its added mass at the
    mode's own frequency and ``mass_above``: tower and head) on the heave stiffness."""
    k = restoring(p)[2, 2]
    return at_own_frequency(
        lambda f: float(np.sqrt(max(k, 0.0) / (mass(p, f)[2, 2] + mass_above)) / (2 * np.pi))
    )


def yaw(p: "Platform", frequency_hz: float | None = None) -> tuple[float, float]:
    """The platform's yaw inertia (with added mass) and stiffness, at the tower's axis."""
    return float(mass(p, frequency_hz)[5, 5]), float(restoring(p)[5, 5])


#: A mode's frequency with the added mass at it is a fixed point, found by iterating from
#: A∞ (the added mass varies slowly with frequency: a few steps reach the tolerance, 1e-5
#: relative — above the eigen-solver's rounding of a 0.01 Hz mode beside the tower's).
ITERATIONS, TOLERANCE = 50, 1e-5


def at_own_frequency(frequency: Callable[[float | None], float]) -> float:
    """The fixed point f = frequency(f) of a mode whose added mass depends on its
    frequency, starting from A∞ (``frequency(None)``)."""
    f = frequency(None)
    for _ in range(ITERATIONS):
        step = frequency(f)
        if abs(step - f) <= TOLERANCE * max(f, 1e-12):
            return step
        f = step
    raise ModalError(
        f"a platform mode near {f:.3g} Hz finds no frequency at which its added mass agrees "
        f"with it in {ITERATIONS} steps: check the platform's added_mass_by_frequency"
    )
