"""Second-order expansions ("jets") of positions and rotations in small coordinates.

The coupled model (:mod:`wtvib.subsystems.coupled`) writes every rotor point's position as
p = u + R(θ)·[a + Rₓ(ψⱼ + φ)·b(η)] and expands it to second order in the small coordinates q:
p ≈ p₀ + P₁q + ½qᵀP₂q. This module is that algebra — vector jets, rotation-matrix jets and
their products — independent of any turbine.

References
----------
M. H. Hansen, "Improved modal dynamics of wind turbines to avoid stall-induced vibrations",
Wind Energy 6 (2003) 179–195 (the kinematics of the rotor on a moving nacelle).
"""

import functools
import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]

# Local coordinates of the nacelle and rotor: tower-top displacement (x downwind, y lateral),
# nacelle rotations about x (roll), y (tilt), z (yaw), drive-train rotation, blade modes.
UX, UY, TX, TY, TZ, PHI = range(6)


def skew(v: Array) -> Array:
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


#: Generators of small rotations: G_i·v = e_i × v.
GENERATORS = [skew(e) for e in np.eye(3)]


def rx(angle: float) -> Array:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


@dataclass(frozen=True)
class Jet:
    """A vector field expanded to second order: v ≈ c0 + c1·q + ½ qᵀ·c2·q.

    Shapes: c0 (..., 3), c1 (..., 3, n), c2 (..., 3, n, n) with c2 symmetric in (n, n);
    c2 None: expanded to first order only (all the parked mass matrix needs).
    """

    c0: Array
    c1: Array
    c2: Array | None

    def rotated(self, r: Array) -> "Jet":
        """A constant matrix applied: r·v."""
        return Jet(
            self.c0 @ r.T,
            np.moveaxis(np.tensordot(self.c1, r, axes=([-2], [1])), -1, -2),
            None
            if self.c2 is None
            else np.moveaxis(np.tensordot(self.c2, r, axes=([-3], [1])), -1, -3),
        )


@dataclass(frozen=True)
class MatrixJet:
    """A 3×3 matrix field expanded to second order (constant over the points)."""

    a0: Array
    a1: Array
    a2: Array

    def apply(self, v: Jet) -> Jet:
        """(A·v) truncated at the order of v (tensordot: BLAS rather than einsum loops)."""
        c0, c1, c2 = (v.c0, v.c1, v.c2) if self._identity else self._constant(v)
        c1 = c1 + np.tensordot(v.c0, self.a1, axes=([-1], [1]))
        if c2 is None:
            return Jet(c0, c1, None)
        cross = np.tensordot(v.c1, self.a1, axes=([-2], [1]))  # (..., m, i, n)
        cross = np.moveaxis(cross, -3, -1)  # (..., i, n, m)
        return Jet(
            c0,
            c1,
            c2 + np.tensordot(v.c0, self.a2, axes=([-1], [1])) + cross + np.swapaxes(cross, -1, -2),
        )

    def _constant(self, v: Jet) -> tuple[Array, Array, Array | None]:
        """A₀·v, term by term."""
        return (
            v.c0 @ self.a0.T,
            np.moveaxis(np.tensordot(v.c1, self.a0, axes=([-2], [1])), -1, -2),
            None
            if v.c2 is None
            else np.moveaxis(np.tensordot(v.c2, self.a0, axes=([-3], [1])), -1, -3),
        )

    @functools.cached_property
    def _identity(self) -> bool:
        """A₀ = I (every small rotation about the undeflected state): A₀·v is v itself."""
        return bool(np.array_equal(self.a0, np.eye(3)))


def nacelle_rotation(n: int) -> MatrixJet:
    """R(θ) ≈ I + Θ + ½Θ² for the rotation vector θ = (q[TX], q[TY], q[TZ])."""
    a1 = np.zeros((3, 3, n))
    a2 = np.zeros((3, 3, n, n))
    for i in range(3):
        a1[:, :, TX + i] = GENERATORS[i]
        for j in range(3):
            a2[:, :, TX + i, TX + j] = 0.5 * (
                GENERATORS[i] @ GENERATORS[j] + GENERATORS[j] @ GENERATORS[i]
            )
    return MatrixJet(np.eye(3), a1, a2)


def spin(n: int, phi: bool) -> MatrixJet:
    """Rₓ(φ) ≈ I + φG + ½φ²G² for the drive-train rotation φ = q[PHI] (identity without)."""
    a1 = np.zeros((3, 3, n))
    a2 = np.zeros((3, 3, n, n))
    if phi:
        a1[:, :, PHI] = GENERATORS[0]
        a2[:, :, PHI, PHI] = GENERATORS[0] @ GENERATORS[0]
    return MatrixJet(np.eye(3), a1, a2)
