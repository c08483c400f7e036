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
linearisation and HAWCStab2 use (Beddoes–Leishman attached flow, Hansen 2004).

**Dynamic stall: the separation point's lag.** Past the lift's linear range the flow
separates from the trailing edge; the separation point does not move at once with the angle
of attack but follows it with the time constant T_f = T_f0·c/(2W) (Øye 1991; the
Beddoes–Leishman family's f″ state, Hansen, Gaunaa & Madsen, Risø-R-1354, 2004; AeroDyn's
theory manual, "Unsteady Aerodynamics"). With the inviscid lift C_inv = C_Lα(α − α₀) and
Kirchhoff's flat-plate separation

    C_L = C_inv·((1 + √f)/2)²,   so   f_st(α) = (2·√(C_L/C_inv) − 1)²   clipped to [0, 1]

(0 beyond the first full separation on either side of α₀), the lift of a section whose
separation point f lags is C_L = f·C_inv + (1 − f)·C_fs(α) with the fully separated lift
C_fs. Linearised about a steady point, the lift slope splits into a part that acts at once
and one that the separation point lags:

    δC_L = (C_L′ − L)·δα + L·δf/f_st′,   δf = f_st′·δα/(1 + s·T_f),
    L = (C_inv − C_fs)·f_st′ = C_inv·(3 + √f)/(4(1 + √f))·f_st′

(the second form from Kirchhoff's relation). In attached flow f_st = 1 and L = 0: nothing
changes; past stall C_L′ < 0 but C_L′ − L > 0, and a vibration faster than 1/T_f meets the
positive slope — the quasi-steady stall damping is the slow limit, the conservative one.
One pole per section stands for the separation's chain (Beddoes–Leishman's pressure lag
T_p before f″ adds its time: T_p0 + T_f0, the first-order sum of the two), and in the
Beddoes–Leishman models it sits behind the shed wake — their separation follows the
effective angle of attack, so the separated part goes through Jones's filter and then the
pole; in Øye's, which has no shed wake, it follows the angle itself. Left out: the
non-circulatory (apparent-mass) lift, small beside a blade's mass, the leading-edge vortex
of deep dynamic stall (not a small-signal effect), and the dynamic inflow of the wake as a
whole (its time constant, R/V ≈ 10 s, is far slower than the blade and tower modes).
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


#: Within this angle [deg] of α₀ the inviscid lift is too small to divide by: the flow is
#: taken as attached there (f_st = 1), and the inviscid slope is sought outside it.
ATTACHED_NEAR_DEG = 0.5

#: The inviscid lift slope C_Lα: the steepest secant C_L/(α − α₀) within this angle [deg] of
#: the zero-lift angle, which is sought within ±ZERO_LIFT_WITHIN_DEG (AeroDyn takes its
#: defaults within ±20°: theory manual, "Calculating Default Airfoil Coefficients").
LINEAR_WITHIN_DEG, ZERO_LIFT_WITHIN_DEG = 10.0, 20.0


def separation_table(alpha_deg: Array, cl: Array) -> tuple[Array, Array, Array]:
    """Kirchhoff's steady separation function f_st on each row of lift tables ``cl`` (S, A)
    over the angles ``alpha_deg`` (A,), with each row's zero-lift angle α₀ [deg] and inviscid
    slope C_Lα [1/deg] (see the module notes). A row without a zero-lift angle of rising lift
    near 0° (a cylinder's C_L ≡ 0) has C_Lα = 0 and f_st ≡ 1: no separation dynamics."""
    a = np.asarray(alpha_deg, float)
    cl = np.atleast_2d(np.asarray(cl, float))
    f = np.ones_like(cl)
    alpha0 = np.zeros(len(cl))
    slope = np.zeros(len(cl))
    near = np.abs(a) <= ZERO_LIFT_WITHIN_DEG
    for s, row in enumerate(cl):
        up = np.flatnonzero(near[:-1] & near[1:] & (row[:-1] <= 0) & (row[1:] > 0))
        if len(up) == 0:
            continue
        i = up[np.argmin(np.abs(a[up]))]
        a0 = a[i] - row[i] * (a[i + 1] - a[i]) / (row[i + 1] - row[i])
        d = a - a0
        linear = (np.abs(d) >= ATTACHED_NEAR_DEG) & (np.abs(d) <= LINEAR_WITHIN_DEG)
        secant = np.where(linear, row / np.where(linear, d, 1.0), 0.0)
        if secant.max() <= 0:
            continue
        alpha0[s], slope[s] = a0, secant.max()
        far = np.abs(d) >= ATTACHED_NEAR_DEG
        ratio = np.where(far, row / np.where(far, slope[s] * d, 1.0), 1.0)
        root = 2 * np.sqrt(np.clip(ratio, 0.25, 1.0)) - 1
        fs = root * root
        # fully separated beyond the first full separation on either side of α₀
        above, below = np.flatnonzero((d > 0) & (fs <= 0)), np.flatnonzero((d < 0) & (fs <= 0))
        if len(above):
            fs[above[0] :] = 0.0
        if len(below):
            fs[: below[-1] + 1] = 0.0
        f[s] = fs
    return f, alpha0, slope


def separated_slope(inviscid: Array, f: Array, df: Array) -> Array:
    """L = (C_inv − C_fs)·f_st′ = C_inv·(3 + √f)/(4(1 + √f))·f_st′: the part of the steady
    lift slope that the separation point lags (per the unit of ``df``; module notes)."""
    root = np.sqrt(np.clip(f, 0.0, 1.0))
    return np.asarray(inviscid * (3 + root) / (4 * (1 + root)) * df)


def single_mode_roots(
    mass: float | Array,
    stiffness: Array,
    damping: Array,
    lift: Array,
    rate: Array,
    separated: Array | float = 0.0,
    separated_rate: Array | float = 1.0,
    shed_wake: bool = True,
) -> NDArray[np.complex128]:
    """The oscillating root of m·ẍ + (d + C·l)·ẋ + k·x = 0 with the lift part l of the
    damping lagged by Jones's filter at the reduced rate 2W/c (``rate``; not where
    ``shed_wake`` is false) and its ``separated`` part (included in ``lift``) by the
    separation point's pole at ``separated_rate`` 1/T_f behind it (in series: the
    Beddoes–Leishman separation follows the shed wake's effective angle of attack; Øye's,
    without a shed wake, the angle itself), one problem per entry of the (broadcast)
    arrays; NaN where the mode does not oscillate (its roots real: overdamped).
    ``damping``: the part that acts at once (drag, the lift's change with the relative
    speed, structural), without the lift slope's share."""
    m, k, d, lift_d, kappa, sep, sep_rate = np.broadcast_arrays(
        *(
            np.asarray(x, float)
            for x in (mass, stiffness, damping, lift, rate, separated, separated_rate)
        )
    )
    # one degree of freedom and its lag states (modal.state_matrix's lag form), the force
    # −Σ fᵢ·zᵢ: Jones's two on the attached part of the lift, żᵢ = Aᵢβᵢ·ẋ − βᵢ·zᵢ (the
    # effective velocity v_E = (1 − A₁ − A₂)·ẋ + z₁ + z₂), and the separation point's one on
    # its separated part, ẏ = β_s·(v_E − y) (v_E = ẋ without a shed wake)
    attached = lift_d - sep
    amp = [a for a, _ in JONES] if shed_wake else []
    beta = [b * kappa for _, b in JONES] if shed_wake else []
    force = [attached] * len(amp)
    if np.any(sep != 0):
        amp.append(IMMEDIATE if shed_wake else 1.0)
        beta.append(sep_rate)
        force.append(sep)
    now = d + (IMMEDIATE if shed_wake else 1.0) * attached
    one = (*m.shape, 1, 1)
    lag = None
    if force:
        count = len(force)
        rates = np.stack(beta, axis=-1)
        s_matrix = -rates[..., None] * np.eye(count)
        if shed_wake and count > len(JONES):  # the separation's input: the shed wake's states
            s_matrix[..., -1, : len(JONES)] = sep_rate[..., None]
        lag = (
            np.stack(force, axis=-1)[..., None, :],
            np.zeros((*m.shape, count, 1)),
            (np.array(amp) * rates)[..., None],
            s_matrix,
        )
    a = modal.state_matrix(k.reshape(one), m.reshape(one), now.reshape(one), lag)
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
