"""Rotors with one or two blades: periodic coefficients and Floquet stability (Hau ch. 7.6).

A two-bladed rotor's inertia about the tilt and yaw axes changes twice per revolution, so
the tower head's equations of motion have periodic coefficients. Model (nacelle-fixed axes:
x shaft, y tilt axis, z yaw axis; azimuth ψ = Ωt from the vertical; rotor polar inertia
J_p, blades as a line of point masses):

* hingeless hub — nacelle tilt θ and yaw φ carry the rotor rigidly:
  (I_y + J_p cos²ψ)θ̈ + J_p sinψ cosψ φ̈ − J_pΩ sin2ψ θ̇ + J_pΩ(1 + cos2ψ) φ̇ + c_θθ̇ + k_θθ = 0
  J_p sinψ cosψ θ̈ + (I_z + J_p sin²ψ)φ̈ − J_pΩ(1 − cos2ψ) θ̇ + J_pΩ sin2ψ φ̇ + c_φφ̇ + k_φφ = 0
  (Newton–Euler: M = dH/dt + ω × H; the moments it gives for steady yawing are the
  gyroscopic J_p·Ω·Ω_yaw·(1 + cos 2ψ) and sin 2ψ of Hau ch. 7.4.1.)
* teetered hub — a teeter angle β about the axis across the blades; the gyroscopic terms
  cancel and the nacelle feels only the teeter spring and damper:
  I_yθ̈ + c_θθ̇ + k_θθ = (k_ββ + c_ββ̇) cosψ,  I_zφ̈ + c_φφ̇ + k_φφ = (k_ββ + c_ββ̇) sinψ,
  J_pβ̈ + c_ββ̇ + (k_β + J_pΩ²)β = −J_p(θ̈ cosψ + φ̈ sinψ + 2Ω(φ̇ cosψ − θ̇ sinψ)).

With three or more blades the sums over the blades make every coefficient constant (the
multi-blade view: the rotor's inertia is isotropic in its plane).

The coupled whole-turbine model (:mod:`wtvib.coupled`) of a two-bladed turbine is periodic
too: :func:`periodic` writes its equations in a reduced, rotation-invariant basis as two
azimuth harmonics, and :func:`multipliers` takes their Floquet multipliers.

Floquet: the state-transition matrix over one period T = 2π/Ω, Φ̇ = A(t)Φ, Φ(0) = I, by
classical fourth-order Runge–Kutta with a fixed number of steps (error O(h⁴), checked
against the Mathieu equation's stability boundaries and a matrix exponential); the
eigenvalues of the monodromy matrix Φ(T) are the Floquet multipliers ρ: |ρ| > 1 unstable.

References
----------
G. Floquet (1883); P. P. Friedmann, "Numerical methods for the treatment of periodic
systems with applications to structural dynamics and helicopter rotor dynamics", Computers
& Structures 35, 1990; Hau ch. 6.8.2 and 7.6; DOMAIN.md §3.
"""

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from . import modal
from .analysis import Analysis, Context, Damping, section_damping
from .excitation import operating_range
from .multiblade import parked
from .resonance import split_by_regime
from .units import rpm_to_rad_s

if TYPE_CHECKING:
    from .coupled import Model
    from .results import Check, Mode
    from .spec import Spec

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
    for k in range(int(s.max(initial=0))):
        more = s > k
        e[more] = e[more] @ e[more]
    return np.asarray(e, dtype=np.float64)


def propagate(a: Callable[[float], Array], period: float, steps: int) -> Array:
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
    step exponentials are taken in one batched call.
    """
    h = period / steps
    root3 = math.sqrt(3.0)
    exps = []
    for i in range(steps):
        a1, a2 = a((i + _GAUSS[0]) * h), a((i + _GAUSS[1]) * h)
        exps.append(0.5 * h * (a1 + a2) + root3 / 12 * h * h * (a2 @ a1 - a1 @ a2))
    factors = expm(np.stack(exps))
    phi = factors[0]
    for f in factors[1:]:
        phi = f @ phi
    return np.asarray(phi)


def monodromy(a: StateMatrix, period: float, steps: int = 400) -> Array:
    """Φ(T) of Φ̇ = A(t)Φ over one period (see :func:`propagate`)."""
    return propagate(a, period, steps)


@dataclass(frozen=True)
class Floquet:
    """Multipliers ρ, exponents λ = ln ρ / T and the period T of one analysis."""

    multipliers: NDArray[np.complex128]
    period: float

    @property
    def largest(self) -> float:
        return float(np.max(np.abs(self.multipliers)))

    @property
    def exponents(self) -> NDArray[np.complex128]:
        return np.log(self.multipliers.astype(complex)) / self.period

    def frequencies_hz(self) -> Array:
        """Principal frequencies |Im λ|/2π in [0, 1/(2T)]; each is ambiguous by k/T (k·Ω
        for the rotor's period): the principal branch is reported, the ambiguity is real."""
        return np.abs(self.exponents.imag) / (2 * math.pi)


def stability(a: StateMatrix, period: float, steps: int = 400) -> Floquet:
    """Floquet multipliers of ẋ = A(t)x over one period (the monodromy's eigenvalues)."""
    return Floquet(np.linalg.eigvals(monodromy(a, period, steps)).astype(complex), period)


@dataclass(frozen=True)
class HeadModel:
    """Tower head on yaw and tilt springs carrying a rotor (SI units)."""

    blades: int
    hub: str
    polar: float  # J_p
    tilt_inertia: float  # I_y without the rotor
    yaw_inertia: float  # I_z without the rotor
    tilt_stiffness: float
    yaw_stiffness: float
    tilt_damping: float
    yaw_damping: float
    teeter_stiffness: float = 0.0
    teeter_damping: float = 0.0

    def parts(self, psi: float) -> tuple[Array, Array, Array, Array, Array]:
        """M(ψ), G₀(ψ), G₁(ψ), K₀(ψ), K₂ with G = G₀ + Ω·G₁ and K = K₀ + Ω²·K₂."""
        jp = self.polar
        if self.blades >= 3:
            m = np.diag([self.tilt_inertia + jp / 2, self.yaw_inertia + jp / 2])
            g0 = np.diag([self.tilt_damping, self.yaw_damping])
            g1 = np.array([[0.0, jp], [-jp, 0.0]])
            k0 = np.diag([self.tilt_stiffness, self.yaw_stiffness])
            return m, g0, g1, k0, np.zeros((2, 2))
        s, c = math.sin(psi), math.cos(psi)
        if self.hub == "teetered":
            kb, cb = self.teeter_stiffness, self.teeter_damping
            m = np.array(
                [[self.tilt_inertia, 0.0, 0.0], [0.0, self.yaw_inertia, 0.0], [jp * c, jp * s, jp]]
            )
            g0 = np.array(
                [
                    [self.tilt_damping, 0.0, -cb * c],
                    [0.0, self.yaw_damping, -cb * s],
                    [0.0, 0.0, cb],
                ]
            )
            g1 = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [-2 * jp * s, 2 * jp * c, 0.0]])
            k0 = np.array(
                [
                    [self.tilt_stiffness, 0.0, -kb * c],
                    [0.0, self.yaw_stiffness, -kb * s],
                    [0.0, 0.0, kb],
                ]
            )
            k2 = np.zeros((3, 3))
            k2[2, 2] = jp
            return m, g0, g1, k0, k2
        s2, c2 = math.sin(2 * psi), math.cos(2 * psi)
        m = np.array(
            [
                [self.tilt_inertia + jp * c * c, jp * s * c],
                [jp * s * c, self.yaw_inertia + jp * s * s],
            ]
        )
        g0 = np.diag([self.tilt_damping, self.yaw_damping])
        g1 = np.array([[-jp * s2, jp * (1 + c2)], [-jp * (1 - c2), jp * s2]])
        k0 = np.diag([self.tilt_stiffness, self.yaw_stiffness])
        return m, g0, g1, k0, np.zeros((2, 2))

    def state_matrices(self, omegas: Array, psi: float) -> Array:
        """A at azimuth ψ for many rotor speeds Ω [rad/s], shape (speeds, 2n, 2n)."""
        m, g0, g1, k0, k2 = self.parts(psi)
        w = np.asarray(omegas, dtype=float)[:, None, None]
        return modal.state_matrix(k0 + w**2 * k2, m, g0 + w * g1)

    def state_matrix(self, omega: float) -> StateMatrix:
        """A(t) of the first-order system at rotor speed Ω [rad/s]."""
        return lambda t: self.state_matrices(np.array([omega]), omega * t)[0]


def monodromy_batch(
    a_of_psi: Callable[[float], Array], omegas: Array, steps: int = MIN_STEPS
) -> Array:
    """Monodromy matrices for many rotor speeds at once, integrating over the azimuth.

    With ψ = Ωt as the variable, dΦ/dψ = A(ψ)/Ω·Φ over ψ ∈ [0, 2π]; ``a_of_psi(ψ)`` returns
    the state matrices of all speeds, shape (speeds, n, n).
    """
    scale = (1.0 / np.asarray(omegas, dtype=float))[:, None, None]
    return propagate(lambda psi: a_of_psi(psi) * scale, 2 * math.pi, steps)


def stability_map(model: "HeadModel", speeds_rad_s: Array) -> Array:
    """Largest Floquet multiplier magnitude over rotor speeds (1 on a stability boundary;
    NaN where the multipliers do not come out finite: not analysed).

    Each speed gets :func:`steps_for` its fastest mode (from A at ψ = 0); speeds needing the
    same power-of-two multiple of :data:`MIN_STEPS` are integrated together.
    """
    w = np.asarray(speeds_rad_s, dtype=float)
    with np.errstate(all="ignore"):
        fastest = np.abs(np.linalg.eigvals(model.state_matrices(w, 0.0))).max(axis=1)
        need = np.array(
            [steps_for(f / (2 * math.pi), 2 * math.pi / x) for f, x in zip(fastest, w, strict=True)]
        )
        bucket = MIN_STEPS * 2 ** np.ceil(np.log2(need / MIN_STEPS)).astype(int)
        largest = np.full(w.shape, np.nan)
        for steps in np.unique(bucket):
            sel = bucket == steps

            def a_of_psi(psi: float, sel: NDArray[np.bool_] = sel) -> Array:
                return model.state_matrices(w[sel], psi)

            phi = monodromy_batch(a_of_psi, w[sel], int(steps))
            finite = np.all(np.isfinite(phi), axis=(1, 2))
            phi[~finite] = 0.0
            found = np.max(np.abs(np.linalg.eigvals(phi)), axis=1)
            largest[sel] = np.where(finite, found, np.nan)  # NaN: not analysed
    return largest


def head_model(spec: "Spec", modes: "Sequence[Mode]") -> tuple[HeadModel | None, list[str]]:
    """The tower-head model of a spec, or None with what is missing.

    Notes
    -----
    Rotor J_p: ``yaw.rotor_polar_inertia_kgm2`` or blades + hub of the drive-train chain.
    Nacelle yaw inertia without the rotor: the head's yaw inertia (``yaw.inertia_kgm2`` or
    tower_head I_yaw + M·x²) less the rotor's mean J_p/2; tilt likewise from the head's
    pitch inertia, else equal to yaw. Stiffnesses put the head on its yaw mode (yaw.1, else
    the tower's first torsion) and on the tower's first fore-aft bending (the head's nodding
    in that mode, an approximation), with the rotor's mean inertia: k = (I + J_p/2)(2πf)².
    Damping from the yaw and tower default damping ratios.
    """
    from . import yaw as yaw_mod

    by_id = {m.id: m for m in modes}
    j_p = yaw_mod.rotor_polar_inertia(spec)
    f_yaw = next((by_id[i].frequency_hz for i in ("yaw.1", "tower.tor1") if i in by_id), None)
    f_tilt = next((by_id[i].frequency_hz for i in ("tower.fa1", "tower.ss1") if i in by_id), None)
    head = spec.tower_head
    total_yaw = spec.yaw.inertia_kgm2 or (
        head.inertia_yaw_kgm2 + head.mass_kg * head.cm_downwind_m**2 if head else None
    )
    missing = [
        name
        for name, v in (
            ("the rotor's polar inertia", j_p),
            ("a yaw (or tower torsion) frequency", f_yaw),
            ("a first tower bending frequency", f_tilt),
            ("the tower head's yaw inertia", total_yaw),
        )
        if not v
    ]
    if missing:
        return None, missing
    assert j_p and f_yaw and f_tilt and total_yaw
    i_z = max(total_yaw - j_p / 2, 0.05 * j_p)
    i_y = (
        max(head.inertia_pitch_kgm2 - j_p / 2, 0.05 * j_p)
        if head and head.inertia_pitch_kgm2
        else i_z
    )
    k_z = (i_z + j_p / 2) * (2 * math.pi * f_yaw) ** 2
    k_y = (i_y + j_p / 2) * (2 * math.pi * f_tilt) ** 2
    c_z = 2 * spec.yaw.damping_ratio * math.sqrt(k_z * (i_z + j_p / 2))
    c_y = 2 * spec.tower.damping_ratio * math.sqrt(k_y * (i_y + j_p / 2))
    hub = "teetered" if spec.rotor.hub == "teetered" else "hingeless"
    return HeadModel(
        spec.rotor.blades,
        hub,
        j_p,
        i_y,
        i_z,
        k_y,
        k_z,
        c_y,
        c_z,
        spec.rotor.teeter_stiffness_nm_rad,
        spec.rotor.teeter_damping_nms_rad,
    ), []


@dataclass(frozen=True)
class StabilityMap:
    speeds_rpm: Array
    largest: Array
    unstable_rpm: tuple[tuple[float, float], ...]


def map_for(spec: "Spec", model: HeadModel, points: int = 200) -> StabilityMap:
    """|ρ|max from 10 % of the lowest steady speed to 130 % of the overspeed limit."""
    speed = spec.rotor.speed
    lo = 0.1 * speed.steady_rpm[0][0]
    hi = 1.3 * speed.overspeed
    rpm = np.linspace(lo, hi, points)
    largest = stability_map(model, rpm_to_rad_s(rpm))
    bad = largest > 1 + 1e-6
    bands = []
    i = 0
    while i < len(rpm):
        if bad[i]:
            j = i
            while j + 1 < len(rpm) and bad[j + 1]:
                j += 1
            bands.append((float(rpm[i]), float(rpm[j])))
            i = j + 1
        else:
            i += 1
    return StabilityMap(rpm, largest, tuple(bands))


def check(spec: "Spec", modes: "Sequence[Mode]") -> "tuple[Check, StabilityMap | None]":
    """The ``rotor.floquet`` check: parametric stability of the tower head with its rotor."""
    from .results import Check, Rule

    rule = Rule(
        "Floquet multipliers of the monodromy matrix, |ρ| ≤ 1",
        "Hau ch. 6.8.2 and 7.6 (periodic coefficients, Floquet theory)",
    )
    if spec.rotor.orientation == "vertical-axis":
        return Check(
            "rotor.floquet",
            "rotor",
            "info",
            "vertical-axis rotor: the tower-head yaw/tilt model does not apply",
            rule,
        ), None
    if spec.rotor.blades >= 3:
        return Check(
            "rotor.floquet",
            "rotor",
            "info",
            f"{spec.rotor.blades} blades: the rotor's inertia is isotropic in its plane, "
            "the equations are time-invariant — no parametric excitation",
            rule,
        ), None
    model, missing = head_model(spec, modes)
    if model is None:
        return Check(
            "rotor.floquet",
            "rotor",
            "info",
            "two-bladed rotor not analysed: needs " + ", ".join(missing),
            rule,
        ), None
    smap = map_for(spec, model)
    speed = spec.rotor.speed
    op = operating_range(speed)
    unstable = [(float(rpm_to_rad_s(a)), float(rpm_to_rad_s(b))) for a, b in smap.unstable_rpm]
    split = split_by_regime(unstable, op, lambda w: any(a <= w <= b for a, b in unstable))
    steady = split["steady"] + split["quick-pass"]
    transient = split["overspeed"] + split["start-up"]
    bands = ", ".join(f"{a:.3g}–{b:.3g} rpm" for a, b in smap.unstable_rpm) or "none"
    hub = spec.rotor.hub
    if steady:
        status = "fail"
        text = (
            f"{hub} two-bladed rotor: parametric instability in steady operation "
            f"(unstable bands {bands})"
        )
        if hub != "teetered":
            text += " — the hazardous concept of a hingeless rotor on a flexible tower (Hau 7.5.1)"
    elif transient:
        status = "warn"
        text = f"{hub} two-bladed rotor: unstable only at start-up or overspeed ({bands})"
    else:
        status = "pass"
        text = (
            f"{hub} two-bladed rotor: stable over the operating range (unstable bands "
            f"outside it: {bands})"
        )
        if hub == "teetered":
            text += " — the teetered hub decouples the rotor moments"
    steady_rpm = np.concatenate(
        [np.linspace(a, b, 25) if b > a else np.array([a]) for a, b in speed.steady_rpm]
    )
    in_operation = stability_map(model, rpm_to_rad_s(steady_rpm))
    skipped = [float(x) for x in smap.speeds_rpm[np.isnan(smap.largest)]]
    if skipped:
        text += (
            f"; not analysed at {len(skipped)} speeds between {min(skipped):.3g} and "
            f"{max(skipped):.3g} rpm (multipliers not finite)"
        )
        if status == "pass" and np.isnan(in_operation).any():
            status = "warn"  # part of the operating range is unknown: not a pass
    finite = in_operation[np.isfinite(in_operation)]
    numbers = {
        "max_multiplier_in_operation": round(float(np.max(finite)), 6) if finite.size else None,
        "not_analysed_rpm": [round(x, 4) for x in skipped],
        "unstable_rpm": [[round(a, 4), round(b, 4)] for a, b in smap.unstable_rpm],
        "hub": hub,
        "polar_inertia_kgm2": model.polar,
    }
    return Check("rotor.floquet", "rotor", status, text, rule, numbers), smap  # type: ignore[arg-type]


# ---------------------------------------------------------------------------------------
# Periodic coefficients (two blades): Floquet analysis in a reduced modal basis


@dataclass(frozen=True)
class Periodic:
    """The periodic equations in a basis of the lowest parked modes, as azimuth harmonics.

    X(ψ) = X₀ + Σ_h (X_ch cos hψ + X_sh sin hψ), h = 1, 2, for X = M, D₁, K₂ (D = D₀ + Ω·D₁,
    K = K₀ + Ω²·K₂): every term is a product of two first-harmonic factors, so two
    harmonics are exact and eight samples recover them without aliasing.
    """

    m: Array  # (5, r, r): constant, cos ψ, sin ψ, cos 2ψ, sin 2ψ
    d1: Array
    k2: Array
    k0: Array  # (r, r)
    d0: Array  # (r, r): the drive train's dampers
    highest_hz: float  # the basis's highest parked frequency (sets the integration step)

    def at(self, x: Array, psi: Array) -> Array:
        """X at the azimuths ψ (array), stacked along the first axis."""
        psi = np.asarray(psi, dtype=float)[:, None, None]
        return (
            x[0]
            + np.cos(psi) * x[1]
            + np.sin(psi) * x[2]
            + np.cos(2 * psi) * x[3]
            + np.sin(2 * psi) * x[4]
        )

    def states(self, omega: float, psi: Array) -> Array:
        """A(ψ) of ẋ = A x at rotor speed Ω for each azimuth ψ, stacked."""
        k = self.k0 + omega**2 * self.at(self.k2, psi)
        d = self.d0 + omega * self.at(self.d1, psi)
        return modal.state_matrix(k, self.at(self.m, psi), d)


def reduction(model: "Model", modes: int = 10, cutoff_hz: float = math.inf) -> Array:
    """A basis for the periodic analysis: the fixed parts (tower, nacelle, drive train) of
    the lowest ``modes`` parked modes up to ``cutoff_hz`` (at least four), orthonormalised,
    and the blade coordinates of the blade modes up to ``cutoff_hz`` (at least the first)
    on every blade — complete blade sets keep the basis the same at every azimuth."""
    lay = model.layout
    res = parked(model, count=modes)
    keep = max(4, int(np.count_nonzero(res.frequency_hz <= cutoff_hz)))
    shapes = np.real(res.shapes[:, :keep])
    fixed = np.ones(lay.size, dtype=bool)
    fixed[lay.blades] = False
    q, r = np.linalg.qr(shapes[fixed])
    q = q[:, np.abs(np.diag(r)) > 1e-9 * np.abs(np.diag(r)).max()]
    kb = model.k_blades
    slow = np.flatnonzero(model.rotor.omega / (2 * np.pi) <= cutoff_hz)
    slow = slow if len(slow) else np.array([0])
    rows = np.array([lay.blades.start + j * kb + k for j in range(model.blades) for k in slow])
    basis = np.zeros((lay.size, q.shape[1] + len(rows)))
    basis[fixed, : q.shape[1]] = q
    basis[rows, q.shape[1] + np.arange(len(rows))] = 1.0
    return basis


def periodic(model: "Model", modes: int = 10, cutoff_hz: float = math.inf) -> Periodic:
    """The model's periodic equations (physical blade coordinates) in the basis of
    :func:`reduction`, as azimuth harmonics."""
    phi = reduction(model, modes, cutoff_hz)
    samples = np.arange(8) * (2 * np.pi / 8)
    m, d1, k2 = [], [], []
    k0 = phi.T @ model.k_v @ phi
    d0 = phi.T @ model.d_v @ phi
    for psi in samples:
        m_psi, d, k = model.matrices(1.0, float(psi))  # M does not depend on Ω
        m.append(phi.T @ m_psi @ phi)
        d1.append(phi.T @ d @ phi - d0)
        k2.append(phi.T @ k @ phi - k0)

    def harmonics(x: list[Array]) -> Array:
        a = np.stack(x)
        out = [a.mean(axis=0)]
        for h in (1, 2):
            out.append(2 * np.tensordot(np.cos(h * samples), a, axes=1) / 8)
            out.append(2 * np.tensordot(np.sin(h * samples), a, axes=1) / 8)
        return np.stack(out)

    top = float(modal.solve(k0, m[0]).frequency_hz[-1])
    return Periodic(harmonics(m), harmonics(d1), harmonics(k2), k0, d0, top)


def multipliers(
    p: Periodic, omega: float, steps: int | None = None, max_steps: int = MAX_STEPS
) -> NDArray[np.complex128] | None:
    """Floquet multipliers over one rotor revolution at Ω [rad/s].

    None where the speed cannot be analysed: one revolution would need more than
    ``max_steps`` steps (a slow rotor with a stiff basis), or the multipliers do not come out
    finite.
    """
    period = 2 * np.pi / omega
    steps = steps or steps_for(p.highest_hz, period)
    if steps > max_steps:
        return None
    h = period / steps
    nodes = (np.arange(steps)[:, None] + np.array(_GAUSS)[None, :]).ravel() * h
    a = p.states(omega, omega * nodes)
    index = {float(t): i for i, t in enumerate(nodes)}
    with np.errstate(all="ignore"):
        phi = propagate(lambda t: a[index[t]], period, steps)
        if not np.all(np.isfinite(phi)):
            return None
        return np.linalg.eigvals(phi).astype(complex)


#: Floquet multipliers above 1 + this count as growth (rounding stays far below it).
GROWTH = 1e-6


# ---------------------------------------------------------------------------------------
# The subsystem protocol (wtvib.analysis): the rotor as a periodic system on the tower head

NAME = "rotor"


def default_damping(spec: "Spec") -> Damping:
    return section_damping(spec.yaw, "yaw")


def build_modes(spec: "Spec", built: "Mapping[str, list[Mode]]") -> "list[Mode]":
    return []  # its modes are the tower's and the yaw system's; it judges their stability


def analyse(spec: "Spec", ctx: Context) -> Analysis:
    """``rotor.floquet`` and the stability map it draws (two-bladed rotors)."""
    found, smap = check(spec, ctx.modes)
    return Analysis(checks=(found,), results={"map": smap} if smap is not None else {})
