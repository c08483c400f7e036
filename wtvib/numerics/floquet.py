"""Floquet theory for periodic linear systems: the one periodic integrator of wtvib.

The state-transition matrix over one period T, Φ̇ = A(t)Φ, Φ(0) = I, by fourth-order Magnus
exponential steps (:func:`propagate`); the eigenvalues of the monodromy matrix Φ(T) are the
Floquet multipliers ρ: |ρ| > 1 unstable. Used by the two-bladed rotor on the tower head
(:mod:`wtvib.subsystems.rotor`) and the coupled two-bladed turbine
(:mod:`wtvib.subsystems.periodic`); checked
against the Mathieu equation's stability boundaries, a matrix exponential and the
multi-blade eigenvalues of a three-bladed rotor.

References
----------
G. Floquet (1883); P. P. Friedmann, "Numerical methods for the treatment of periodic
systems with applications to structural dynamics and helicopter rotor dynamics", Computers
& Structures 35, 1990; S. Blanes, F. Casas, J. A. Oteo, J. Ros, "The Magnus expansion and
some of its applications", Physics Reports 470 (2009).
"""

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]
StateMatrix = Callable[[float], Array]


#: Gauss–Legendre nodes of the fourth-order Magnus step, as fractions of the step.
_GAUSS = (0.5 - math.sqrt(3) / 6, 0.5 + math.sqrt(3) / 6)


#: Fewest Magnus steps per revolution: the coefficients hold two azimuth harmonics.
MIN_STEPS = 96
#: Steps per period of the fastest mode: below about one per period the Magnus step loses
#: accuracy on the fast modes (NREL 5-MW coupled, 12.1 rpm: |ρ|max 1.0015 at 96 steps,
#: 1 + 2e-6 at 192, 1 − 1e-7 at 384 — the undamped system's 1 approached from the error side).
STEPS_PER_PERIOD = 2.0
#: The most steps one revolution may take (beyond: the speed is not analysed; ≈ 0.4 s).
MAX_STEPS = 2_000


def steps_for(highest_hz: float, period: float) -> int:
    """Magnus steps over one revolution of ``period`` [s] with modes up to ``highest_hz``."""
    return max(MIN_STEPS, math.ceil(STEPS_PER_PERIOD * highest_hz * period))


#: Coefficients of the diagonal [6/6] Padé approximant of exp (Higham 2005, Table 10.1).
_PADE = (1.0, 1 / 2, 5 / 44, 1 / 66, 1 / 792, 1 / 15840, 1 / 665280)


def expm(x: Array) -> Array:
    """exp of each matrix of a stack (..., n, n): [6/6] Padé with scaling and squaring.

    Each matrix is scaled by 2^s to a 1-norm ≤ ½ (then the [6/6] approximant is exact to
    rounding, Higham 2005 Table 2.1) and squared back s times. Vectorised over the stack:
    5–10× faster than scipy.linalg.expm's per-matrix loop on the small matrices here, equal
    to it within 1e-12 (tests).

    References
    ----------
    N. J. Higham, "The scaling and squaring method for the matrix exponential revisited",
    SIAM J. Matrix Anal. Appl. 26 (2005) 1179–1193.
    """
    x = np.asarray(x, dtype=float)
    norm = np.abs(x).sum(axis=-2).max(axis=-1)
    s = np.maximum(0, np.ceil(np.log2(np.maximum(norm, 1e-300) / 0.5))).astype(int)
    x = x / (2.0**s)[..., None, None]
    eye = np.broadcast_to(np.eye(x.shape[-1]), x.shape)
    x2 = x @ x
    x4 = x2 @ x2
    c = _PADE
    u = x @ (c[1] * eye + c[3] * x2 + c[5] * x4)
    v = c[0] * eye + c[2] * x2 + c[4] * x4 + c[6] * (x4 @ x2)
    e = np.linalg.solve(v - u, v + u)
    # squared back s times each: the stack ordered by s, most first, so that every round
    # squares a leading slice (a view) — the same products as masking, without the copies
    flat, si = e.reshape(-1, *e.shape[-2:]), s.ravel()
    order = np.argsort(-si, kind="stable")
    ordered = flat[order]
    for k in range(int(si.max(initial=0))):
        n = int(np.count_nonzero(si > k))
        ordered[:n] = ordered[:n] @ ordered[:n]
    flat[order] = ordered
    return np.asarray(flat.reshape(e.shape), dtype=np.float64)


def propagate(
    a: Callable[[float], Array], period: float, steps: int, vectorised: bool = False
) -> Array:
    """Φ(T) of Φ̇ = A(t)Φ, Φ(0) = I: the one periodic integrator of wtvib.

    ``a(t)`` returns one state matrix (n, n) or a stack of them (..., n, n) — many rotor
    speeds at once; the result has the same shape.

    Notes
    -----
    Fourth-order Magnus exponential integrator (Iserles & Nørsett 1999; Blanes, Casas, Oteo &
    Ros, Physics Reports 470, 2009, §5.1): with A₁, A₂ at the Gauss points t + (½ ∓ √3/6)h,

        Φ(t + h) = exp(h/2·(A₁ + A₂) + √3/12·h²·[A₂, A₁]) · Φ(t).

    It is exact for constant coefficients, so a stiff mode on a slow rotor (ω·h ≫ 1) is
    propagated, never amplified: classical RK4 diverges once ω·h > 2.8, and overflowed on
    the catalogue's two-bladed rotors below a few rpm. The error is O(h⁴) in the variation
    of A over a step — for a rotor its azimuth harmonics, not the modes' frequencies. All
    step exponentials are taken in one batched call; ``vectorised``: ``a`` takes the array of
    all Gauss times at once (leading axis), so that the state matrices are built in one go.
    """
    h = period / steps
    root3 = math.sqrt(3.0)
    if vectorised:
        times = (np.arange(steps)[:, None] + np.asarray(_GAUSS)[None, :]).ravel() * h
        both = a(times)
        a1, a2 = both[0::2], both[1::2]
        stacked = 0.5 * h * (a1 + a2) + root3 / 12 * h * h * (a2 @ a1 - a1 @ a2)
    else:
        exps = []
        for i in range(steps):
            b1, b2 = a((i + _GAUSS[0]) * h), a((i + _GAUSS[1]) * h)
            exps.append(0.5 * h * (b1 + b2) + root3 / 12 * h * h * (b2 @ b1 - b1 @ b2))
        stacked = np.stack(exps)
    factors = expm(stacked)
    phi = factors[0]
    for f in factors[1:]:
        phi = f @ phi
    return np.asarray(phi)


def monodromy(a: StateMatrix, period: float, steps: int = 400) -> Array:
    """Φ(T) of Φ̇ = A(t)Φ over one period (see :func:`propagate`)."""
    return propagate(a, period, steps)


def monodromy_batch(
    a_of_psi: Callable[[float], Array],
    omegas: Array,
    steps: int = MIN_STEPS,
    every_azimuth: bool = False,
) -> Array:
    """Monodromy matrices for many rotor speeds at once, integrating over the azimuth.

    With ψ = Ωt as the variable, dΦ/dψ = A(ψ)/Ω·Φ over ψ ∈ [0, 2π]; ``a_of_psi(ψ)`` returns
    the state matrices of all speeds, shape (speeds, n, n) — or, ``every_azimuth``, for an
    array of azimuths at once, shape (azimuths, speeds, n, n).
    """
    scale = (1.0 / np.asarray(omegas, dtype=float))[:, None, None]
    return propagate(
        lambda psi: a_of_psi(psi) * scale, 2 * math.pi, steps, vectorised=every_azimuth
    )


#: Floquet multipliers above 1 + this count as growth (rounding stays far below it).
GROWTH = 1e-6
#: A speed whose multipliers show growth is integrated again with these multiples of its
#: steps, the finest answer kept: the Magnus step's error on a neutral mode (a free
#: generator's slow rotation) is an apparent growth that falls 16-fold as the step halves —
#: the AWT-27 deck's 1 + 7e-6 at 2 steps per period of its fastest mode is 1 − 1e-8 at 8 —
#: where a real instability stays.
REFINE = (2, 4)
