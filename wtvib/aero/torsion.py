"""The blades' steady twist under their aerodynamic moment (the aeroelastic steady state in
torsion).

A blade section carries, per unit length, the aerodynamic moment about its shear centre

    m = q·(c·C_M + e·C_N),   q = ½ρW²c,   C_N = C_L cos α + C_D sin α,

with C_M the aerofoil's pitching moment about the quarter chord (where the lift and drag act)
and e the quarter chord's distance ahead of the shear centre (positive: the shear centre aft
of it, the normal force then twists the section nose-up). The blade, clamped in torsion at
the root (or held by the pitch drive's spring k_p), twists by

    θ(x) = T(0)/k_p + ∫₀ˣ T(s)/GJ(s) ds,   T(s) = ∫ₛᴿ m(u) du,

nose-up positive: the angle of attack grows by θ (Hodges & Pierce, *Introduction to
Structural Dynamics and Aeroelasticity*, 2nd ed., §3.4 — the torsional divergence problem
of a wing, here with the BEM's inflow). The moment depends on the angle of attack and so on
the twist: the steady state is the fixed point θ = F·m(θ), found by Newton's method with
each section's own ∂m/∂α (the induction's answer to the twist left out of the Jacobian, so
convergence is linear at the rate of that answer, fast).

Large modern blades are soft in torsion: the IEA 15 MW's twists ~3° nose-down at its tip at
rated under C_M ≈ −0.1 — the difference between OpenFAST with ElastoDyn (rigid in torsion)
and with BeamDyn, or HAWCStab2, in their thrust (IEA-22-280-RWT issue 99; the IEA-15's HAWC2
README: both its blade models "feature torsional deflections and are therefore equivalent to
a BeamDyn model", an ElastoDyn equivalent needs the shear modulus raised by orders of
magnitude — what ``aerodynamics.steady_torsion: false`` does here). Left out: the
bending–torsion coupling of swept or anisotropic blades and the twist the flapwise
deflection of a prebent blade adds.
"""

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]


@dataclass(frozen=True)
class Torsion:
    """What the steady twist needs at the aerodynamic stations (S)."""

    flexibility: Array  # F (S, S) [rad per N·m/m]: twist at each station per moment per length
    arm: Array  # e (S,) [m]: the quarter chord ahead of the shear centre
    cm: Array  # C_M on the rotor's α grid (S, A), about the quarter chord, nose-up positive


def flexibility(
    radius: Array, root: float, gj: Array, gj_root: float, pitch_spring: float | None
) -> Array:
    """F (S, S): the twist θ [rad] at stations ``radius`` (S,) from the blade's root at
    ``root`` [m] per moment per unit length [N·m/m] at each station (piecewise linear
    between stations, nothing inboard of the first), GJ ``gj`` (S,) at the stations and
    ``gj_root`` at the root [N·m²], the root held by ``pitch_spring`` [N·m/rad] (None:
    clamped). Trapezoidal rules on the stations: exact for a uniform moment on a uniform
    blade (θ = m·(L·x − x²/2)/GJ is matched to the rule's O(Δx²))."""
    x = np.concatenate([[root], np.asarray(radius, float)])
    g = np.concatenate([[gj_root], np.asarray(gj, float)])
    n = len(x)
    w = _segments(np.diff(x), n)
    loaded = w.copy()
    loaded[0] = 0.0  # no aerodynamic load between the root and the first station
    u = np.zeros((n, n))  # T = U·m: each point's moment from the blade outboard of it
    u[:-1] = np.cumsum(loaded[::-1], axis=0)[::-1]
    v = np.zeros((n, n))  # θ = V·(T/GJ): the twist accumulated from the root
    v[1:] = np.cumsum(w, axis=0)
    out = v @ (u / g[:, None])
    if pitch_spring is not None:  # the root turns on the pitch drive's spring
        out = out + u[0][None, :] / pitch_spring
    return np.asarray(out[1:, 1:])


def _segments(dx: Array, n: int) -> Array:
    """Each segment's trapezoid weights on the grid's points (n − 1, n)."""
    w = np.zeros((n - 1, n))
    idx = np.arange(n - 1)
    w[idx, idx] = 0.5 * dx
    w[idx, idx + 1] = 0.5 * dx
    return w


def moment(
    t: Torsion, rho: float, chord: Array, w: Array, alpha: Array, cl: Array, cd: Array, cm: Array
) -> Array:
    """m (K, S) [N·m/m]: each section's aerodynamic moment about its shear centre per unit
    length, nose-up positive, at relative wind ``w`` and angle of attack ``alpha`` [rad] with
    the coefficients there."""
    q = 0.5 * rho * w * w * chord
    normal = cl * np.cos(alpha) + cd * np.sin(alpha)
    return np.asarray(q * (chord * cm + t.arm * normal))
