"""Textbook closed forms the tests check wtvib's numerical models against (reference
implementations: wtvib itself never calls them).

Przemieniecki, *Theory of Matrix Structural Analysis*, ch. 5 and 11 (beam elements);
Bisplinghoff, Ashley and Halfman, *Aeroelasticity*, §8 (divergence of a uniform cantilever).
"""

import math

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]


def bending_stiffness(ei: float, length: float) -> Array:
    """Stiffness of a bending element, dofs (w₁, θ₁, w₂, θ₂). [N/m, N, N·m]"""
    L = length  # noqa: N806 (the textbooks' element length)
    return (ei / L**3) * np.array(
        [
            [12, 6 * L, -12, 6 * L],
            [6 * L, 4 * L**2, -6 * L, 2 * L**2],
            [-12, -6 * L, 12, -6 * L],
            [6 * L, 2 * L**2, -6 * L, 4 * L**2],
        ]
    )


def bending_mass(m: float, length: float) -> Array:
    """Consistent mass of a bending element with mass per length ``m`` [kg/m]."""
    L = length  # noqa: N806 (the textbooks' element length)
    return (m * L / 420.0) * np.array(
        [
            [156, 22 * L, 54, -13 * L],
            [22 * L, 4 * L**2, 13 * L, -3 * L**2],
            [54, 13 * L, 156, -22 * L],
            [-13 * L, -3 * L**2, -22 * L, 4 * L**2],
        ]
    )


def geometric_stiffness(axial: float, length: float) -> Array:
    """Geometric stiffness of a bending element under axial force ``axial`` [N], tension > 0."""
    L = length  # noqa: N806 (the textbooks' element length)
    return (axial / (30.0 * L)) * np.array(
        [
            [36, 3 * L, -36, 3 * L],
            [3 * L, 4 * L**2, -3 * L, -(L**2)],
            [-36, -3 * L, 36, -3 * L],
            [3 * L, -(L**2), -3 * L, 4 * L**2],
        ]
    )


def torsion_stiffness(gj: float, length: float) -> Array:
    """Stiffness of a torsion element, dofs (φ₁, φ₂). [N·m/rad]"""
    return (gj / length) * np.array([[1.0, -1.0], [-1.0, 1.0]])


def torsion_mass(inertia_per_length: float, length: float) -> Array:
    """Consistent mass of a torsion element; polar mass inertia per length in [kg·m]."""
    return (inertia_per_length * length / 6.0) * np.array([[2.0, 1.0], [1.0, 2.0]])


def cantilever_divergence_closed_form(gj: float, arm_c_cla: float, length: float) -> float:
    """Uniform cantilever under a uniform dynamic pressure: q_D = π²GJ/(4·e·c·C_Lα·l²)."""
    return math.pi**2 * gj / (4 * arm_c_cla * length**2)


def lagged_single_mode_zeta(
    mass: float, omega: float, damping: float, lift: float, rate: float
) -> float:
    """ζ of m·s² + s·(d − l + l·C(s/κ)) + m·ω² = 0 with Jones's C(s̄) = 1 − 0.165·s̄/(s̄ +
    0.0455) − 0.335·s̄/(s̄ + 0.3) (NACA Report 681; Leishman §8.5), the denominators
    multiplied out into a quartic and its roots found as a polynomial's (not as a state
    matrix's eigenvalues, as wtvib does): the oscillating root nearest ω; 1 where none
    oscillates. ``damping`` d is the whole quasi-steady coefficient, ``lift`` l its
    lift-slope part, ``rate`` κ = 2W/c."""
    b1, b2 = 0.0455 * rate, 0.3 * rate
    p1, p2 = np.poly1d([1.0, b1]), np.poly1d([1.0, b2])
    s = np.poly1d([1.0, 0.0])
    structure = np.poly1d([mass, float(damping - lift), mass * omega**2])
    lagged = p1 * p2 - 0.165 * s * p2 - 0.335 * s * p1
    roots = (structure * p1 * p2 + s * lagged * float(lift)).roots
    osc = [r for r in roots if r.imag > 1e-9 * omega]
    if not osc:
        return 1.0
    root = min(osc, key=lambda r: abs(abs(r) - omega))
    return float(-root.real / abs(root))
