"""Tolerances the arithmetic can keep, on any IEEE-754 machine and BLAS.

An eigenvalue computed in floating point is exact for a nearby matrix: LAPACK's
nonsymmetric solver (``dgeev``, which balances the matrix first) is backward stable,
``‖E‖ ≤ p(n)·ε·‖B‖`` for the balanced matrix B = D⁻¹AD, p(n) "a modestly growing function
of n" (Anderson et al., *LAPACK Users' Guide*, 3rd ed., §4.8). To first order a simple root
then moves by at most κᵢ·‖E‖, κᵢ = ‖yᵢ‖‖xᵢ‖/|yᵢᴴxᵢ| its condition number (left and right
vectors; Wilkinson, *The Algebraic Eigenvalue Problem*, §2.8; Golub & Van Loan §7.2.2).
Which CPU, which BLAS, which number of threads and which LAPACK path (values only, or with
vectors) only change the rounding inside that bound — so a comparison of roots is held to
it, not to the digits one machine happened to give.

A number stored in a reference file carries its own rounding: half a unit in its last
written decimal (:func:`half_unit`).
"""

import math

import numpy as np
from numpy.typing import NDArray

EPS = float(np.finfo(float).eps)


def root_bounds(a: NDArray[np.float64], solves: int = 2) -> tuple[NDArray, NDArray]:
    """Every eigenvalue of ``a`` and how far rounding may move it [same unit as λ].

    ``solves`` matrices formed and solved independently (2: the reference's and ours, each
    formed by sums of products of the same size as the solve) each contribute
    ``n·ε·‖B‖_F``; the bound is ``2·solves·n·ε·‖B‖_F·κᵢ``.
    """
    import scipy.linalg as sl

    b, _ = sl.matrix_balance(a, permute=False)
    lam, left, right = sl.eig(b, left=True, right=True)
    cosine = np.abs(np.sum(left.conj() * right, axis=0))
    kappa = np.linalg.norm(left, axis=0) * np.linalg.norm(right, axis=0) / cosine
    n = a.shape[0]
    return lam, 2 * solves * n * EPS * np.linalg.norm(b) * kappa


def half_unit(x: float) -> float:
    """Half a unit in the last decimal of ``x`` as written (``repr``, the shortest string
    that reads back as the same double: what a JSON file written with those digits holds)."""
    text = repr(float(x)).lower()
    mantissa, _, exponent = text.partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 0.5 * 10.0 ** -(decimals - int(exponent or 0))


def frequency_and_damping_bounds(
    lam: NDArray[np.complex128], bound: NDArray[np.float64]
) -> tuple[NDArray, NDArray, NDArray, NDArray]:
    """Natural frequency |λ|/2π [Hz] and damping ratio −Re λ/|λ| of the roots with
    Im λ > 0, each with how far rounding may move it: |δ|λ|| ≤ |δλ|, and
    |δζ| ≤ |δλ|/|λ| (ζ is the cosine of λ's angle from the negative real axis)."""
    up = lam.imag > 0
    mag = np.abs(lam[up])
    return (
        mag / (2 * math.pi),
        bound[up] / (2 * math.pi),
        -lam[up].real / mag,
        bound[up] / mag,
    )
