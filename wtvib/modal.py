"""The one generic eigen-solver and mode tracking, shared by every structural model.

* :func:`solve` — the generalised symmetric problem K φ = ω² M φ (undamped modes);
* :func:`mac` and :func:`track` — modal assurance criterion and following modes across a
  parameter sweep by shape similarity rather than by sorting frequencies.

References
----------
R. J. Allemang, "The modal assurance criterion — twenty years of use and abuse", Sound and
Vibration 37(8), 2003 (MAC).
"""

from dataclasses import dataclass

import numpy as np
import scipy.linalg
from numpy.typing import NDArray
from scipy.optimize import linear_sum_assignment

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

    Raises
    ------
    ModalError
        M is not positive definite, or K has a clearly negative eigenvalue (a structure that
        buckles under its loads, e.g. gravity on an over-soft tower).
    """
    n = k.shape[0]
    top = n - 1 if count is None else min(count, n) - 1
    try:
        w2, shapes = scipy.linalg.eigh(k, m, subset_by_index=(0, top), check_finite=True)
    except (np.linalg.LinAlgError, ValueError) as exc:
        raise ModalError(f"eigenproblem failed: {exc}") from None
    scale = max(float(np.abs(w2).max(initial=0.0)), 1.0)
    if w2[0] < -1e-8 * scale:
        raise ModalError(
            f"the structure is unstable (negative stiffness eigenvalue {w2[0]:.3g}): "
            "check stiffnesses and masses"
        )
    w2 = np.clip(w2, 0.0, None)
    return Modes(np.sqrt(w2) / (2.0 * np.pi), shapes)


def mac(a: Array, b: Array) -> Array:
    """MAC matrix between the columns of ``a`` and of ``b`` (values in 0 … 1)."""
    num = np.abs(a.T @ b) ** 2
    den = np.outer(np.einsum("ij,ij->j", a, a), np.einsum("ij,ij->j", b, b))
    return np.asarray(num / np.where(den > 0, den, 1.0))


def track(previous: Array, current: Array) -> NDArray[np.intp]:
    """Order of ``current``'s columns that best continues ``previous``'s (max total MAC)."""
    rows, cols = linear_sum_assignment(-mac(previous, current))
    order = np.empty(previous.shape[1], dtype=np.intp)
    order[rows] = cols
    return order
