"""The one generic eigen-solver and mode tracking, shared by every structural model.

* :func:`solve` — the generalised symmetric problem K φ = ω² M φ (undamped modes);
* :func:`mac` and :func:`track` — modal assurance criterion and following modes across a
  parameter sweep by shape similarity rather than by sorting frequencies.

References
----------
R. J. Allemang, "The modal assurance criterion — twenty years of use and abuse", Sound and
Vibration 37(8), 2003 (MAC).
"""

import itertools
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .errors import WtvibError

Array = NDArray[np.float64]


class ModalError(WtvibError, ArithmeticError):
    """A structural model whose eigenproblem has no physical solution (e.g. not stable)."""


@dataclass(frozen=True)
class Modes:
    """Natural frequencies [Hz] (ascending) and mass-normalised shapes (columns)."""

    frequency_hz: Array
    shapes: Array


def solve(k: Array, m: Array, count: int | None = None) -> Modes:
    """Lowest ``count`` modes of K φ = ω² M φ (K, M symmetric, M positive definite).

    Notes
    -----
    Reduced to a standard symmetric problem with the Cholesky factor of M, M = L Lᵀ:
    (L⁻¹ K L⁻ᵀ) y = ω² y, φ = L⁻ᵀ y — the reduction LAPACK's ``sygv`` performs; done with
    numpy so that a check never has to import scipy.linalg (a third of a second).

    Raises
    ------
    ModalError
        M is not positive definite, or K has a clearly negative eigenvalue (a structure that
        buckles under its loads, e.g. gravity on an over-soft tower).
    """
    return solve_stacked(k[None], m[None], count)[0]


def solve_stacked(k: Array, m: Array, count: int | None = None) -> list[Modes]:
    """:func:`solve` for a stack of same-sized problems, shape (p, n, n), in one call."""
    if not (np.all(np.isfinite(k)) and np.all(np.isfinite(m))):
        raise ModalError("the structural matrices hold NaN or infinite values")
    try:
        lower = np.linalg.cholesky(m)
    except np.linalg.LinAlgError:
        raise ModalError(
            "the mass matrix is not positive definite (a zero or negative mass or inertia?)"
        ) from None
    inv = np.linalg.inv(lower)
    inv_t = np.swapaxes(inv, -1, -2)
    a = inv @ k @ inv_t
    w2, y = np.linalg.eigh(0.5 * (a + np.swapaxes(a, -1, -2)))
    top = w2.shape[-1] if count is None else min(count, w2.shape[-1])
    out = []
    for i in range(len(w2)):
        w = w2[i, :top]
        scale = max(float(np.abs(w2[i]).max(initial=0.0)), 1.0)
        if w[0] < -1e-8 * scale:
            raise ModalError(
                f"the structure is unstable (negative stiffness eigenvalue {w[0]:.3g}): "
                "check stiffnesses and masses"
            )
        shapes = inv_t[i] @ y[i, :, :top]
        out.append(Modes(np.sqrt(np.clip(w, 0.0, None)) / (2.0 * np.pi), shapes))
    return out


def mac(a: Array, b: Array) -> Array:
    """MAC matrix between the columns of ``a`` and of ``b`` (values in 0 … 1)."""
    num = np.abs(a.T @ b) ** 2
    den = np.outer(np.einsum("ij,ij->j", a, a), np.einsum("ij,ij->j", b, b))
    return np.asarray(num / np.where(den > 0, den, 1.0))


def track(previous: Array, current: Array) -> NDArray[np.intp]:
    """Order of ``current``'s columns that best continues ``previous``'s (max total MAC).

    Exhaustive over permutations for up to 7 modes (an exact assignment), greedy beyond.
    """
    score = mac(previous, current)
    n = score.shape[0]
    if n <= 7:
        best = max(
            itertools.permutations(range(n)),
            key=lambda p: sum(score[i, j] for i, j in enumerate(p)),
        )
        return np.array(best, dtype=np.intp)
    order = np.full(n, -1, dtype=np.intp)
    free = set(range(n))
    for i in np.argsort(-score.max(axis=1)):
        j = max(free, key=lambda c: score[i, c])
        order[i] = j
        free.remove(j)
    return order
