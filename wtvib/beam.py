"""Euler–Bernoulli beam finite elements: bending (Hermite cubics) and torsion (linear).

Element properties are taken at the element midpoint, so a mesh of ``n`` elements over a
tapered member converges with O(h²); the default meshes are chosen by the convergence test
in ``tests/validation/test_beam_convergence.py``.

References
----------
J. S. Przemieniecki, *Theory of Matrix Structural Analysis*, McGraw-Hill 1968, ch. 5 and
11 (element stiffness, consistent mass and geometric stiffness matrices); R. D. Cook et
al., *Concepts and Applications of Finite Element Analysis*, 4th ed., §16.
"""

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]


def bending_stiffness(ei: float, length: float) -> Array:
    """Stiffness of a bending element, dofs (w₁, θ₁, w₂, θ₂). [N/m, N, N·m]"""
    L = length
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
    L = length
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
    L = length
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


def mesh(stations: Array, elements: int) -> Array:
    """Node positions: ``elements`` equal divisions, plus every input station."""
    return np.union1d(np.linspace(stations[0], stations[-1], elements + 1), stations)


def midpoint_values(nodes: Array, stations: Array, values: Array) -> Array:
    """Property at each element's midpoint, linear between input stations."""
    return np.interp(0.5 * (nodes[1:] + nodes[:-1]), stations, values)


def assemble_bending(
    nodes: Array, ei: Array, m: Array, axial: Array | None = None
) -> tuple[Array, Array]:
    """Global K and M of a beam in one bending plane, 2 dofs per node, ends free.

    ``ei``, ``m`` and ``axial`` are per element (midpoint values).
    """
    n = 2 * len(nodes)
    k = np.zeros((n, n))
    mm = np.zeros((n, n))
    for e, length in enumerate(np.diff(nodes)):
        s = slice(2 * e, 2 * e + 4)
        k[s, s] += bending_stiffness(ei[e], length)
        if axial is not None:
            k[s, s] += geometric_stiffness(axial[e], length)
        mm[s, s] += bending_mass(m[e], length)
    return k, mm


def assemble_torsion(nodes: Array, gj: Array, ip: Array) -> tuple[Array, Array]:
    """Global K and M of a torsion member, 1 dof per node, ends free."""
    n = len(nodes)
    k = np.zeros((n, n))
    mm = np.zeros((n, n))
    for e, length in enumerate(np.diff(nodes)):
        s = slice(e, e + 2)
        k[s, s] += torsion_stiffness(gj[e], length)
        mm[s, s] += torsion_mass(ip[e], length)
    return k, mm
