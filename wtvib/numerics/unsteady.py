"""Unsteady lift of an oscillating aerofoil: the lift deficiency of the shed wake.

A section whose angle of attack changes does not reach the steady lift at once: the
vorticity it sheds as its circulation changes induces a downwash that lags the motion
(Wagner's indicial response; in harmonic motion Theodorsen's function C(k), k = ωb/W,
b = c/2). The quasi-steady blade-element damping (:mod:`wtvib.aero.aerodamping`) takes the full
steady lift slope at once, C = 1, and so overdamps the flap modes of large, flexible
blades, whose decay is as fast as the wake's lag.

Jones's two-pole approximation of Wagner's function (R. T. Jones, NACA Report 681, 1940;
Leishman, *Principles of Helicopter Aerodynamics*, 2nd ed., §8.5) writes the lift's
response to an angle of attack α(t) as

    C_L,c = C_L′·[(1 − A₁ − A₂)·α + z₁ + z₂],   żᵢ = −βᵢ·zᵢ + βᵢ·Aᵢ·α,   βᵢ = bᵢ·2W/c,

A₁ = 0.165, b₁ = 0.0455, A₂ = 0.335, b₂ = 0.3: in the Laplace domain the lift deficiency
C(s̄) = 1 − A₁s̄/(s̄ + b₁) − A₂s̄/(s̄ + b₂), s̄ = s·c/(2W) — Theodorsen's C(k) at s̄ = ik
within 1 %, and defined off the imaginary axis too, so that a heavily damped root is
solved as it is (the p-k method's real k is exact only where the damping vanishes).

Two first-order states per lagged input make the blade-element forces a state-space model
whose roots are the aeroelastic modes; the same form OpenFAST's unsteady-aerodynamics
linearisation and HAWCStab2 use (Beddoes–Leishman attached flow, Hansen 2004). Left out:
the non-circulatory (apparent-mass) lift, small beside a blade's mass, dynamic stall and
the dynamic inflow of the wake as a whole (its time constant, R/V ≈ 10 s, is far slower
than the blade and tower modes).
"""

import numpy as np
from numpy.typing import NDArray

from . import modal

Array = NDArray[np.float64]

#: Jones's coefficients of Wagner's function: (Aᵢ, bᵢ).
JONES: tuple[tuple[float, float], ...] = ((0.165, 0.0455), (0.335, 0.3))

#: The share of the lift that follows the angle of attack at once: 1 − A₁ − A₂.
IMMEDIATE = 1.0 - sum(a for a, _ in JONES)


def lift_deficiency(s_bar: NDArray[np.complex128]) -> NDArray[np.complex128]:
    """C(s̄) of Jones's approximation at the reduced Laplace variable s̄ = s·c/(2W)."""
    s = np.asarray(s_bar, dtype=complex)
    out = np.ones_like(s)
    for a, b in JONES:
        out -= a * s / (s + b)
    return out


def lag_rates(w: Array, chord: Array) -> Array:
    """The reduced rate 2W/c [1/s] of each section (βᵢ = bᵢ·2W/c)."""
    return np.asarray(2.0 * np.asarray(w, float) / np.asarray(chord, float))


def single_mode_roots(
    mass: float | Array,
    stiffness: Array,
    damping: Array,
    lift: Array,
    rate: Array,
) -> NDArray[np.complex128]:
    """The oscillating root of m·ẍ + (d + C·l)·ẋ + k·x = 0 with the lift part l of the
    damping lagged by Jones's filter at the reduced rate 2W/c (``rate``), one problem per
    entry of the (broadcast) arrays; NaN where the mode does not oscillate (its roots real:
    overdamped). ``damping``: the part that acts at once (drag, the lift's change with the
    relative speed, structural), without the lift slope's share."""
    m, k, d, lift_d, kappa = np.broadcast_arrays(
        *(np.asarray(x, float) for x in (mass, stiffness, damping, lift, rate))
    )
    # one degree of freedom and Jones's two states (modal.state_matrix's lag form): the
    # force −l·(z₁ + z₂), żᵢ = Aᵢβᵢ·ẋ − βᵢ·zᵢ; the immediate share of the lift in the damping
    beta = np.stack([b * kappa for _, b in JONES], axis=-1)
    amp = np.array([a for a, _ in JONES])
    one = (*m.shape, 1, 1)
    lag = (
        np.repeat(lift_d[..., None, None], len(JONES), axis=-1),
        np.zeros((*m.shape, len(JONES), 1)),
        (amp * beta)[..., None],
        -beta[..., None] * np.eye(len(JONES)),
    )
    a = modal.state_matrix(
        k.reshape(one), m.reshape(one), (d + IMMEDIATE * lift_d).reshape(one), lag
    )
    shape, n = m.shape, a.shape[-1]
    lam = np.linalg.eigvals(a.reshape(-1, n, n)).reshape(*shape, n)
    # the structural root: the pair with a positive imaginary part nearest the undamped
    # frequency (the lag states' own roots are real, at −bᵢ·2W/c)
    omega = np.sqrt(k / m)
    osc = lam.imag > 1e-9 * np.maximum(omega, 1.0)[..., None]
    dist = np.where(osc, np.abs(np.abs(lam) - omega[..., None]), np.inf)
    pick = np.argmin(dist, axis=-1)
    root = np.take_along_axis(lam, pick[..., None], axis=-1)[..., 0]
    return np.asarray(np.where(np.any(osc, axis=-1), root, np.nan + 0j))
