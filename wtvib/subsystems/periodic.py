"""The coupled two-bladed turbine's periodic equations and their Floquet multipliers.

The coupled whole-turbine model (:mod:`wtvib.subsystems.coupled`) of a two-bladed turbine has
periodic coefficients (its rotor is not isotropic): :func:`periodic` writes its equations
in a reduced, rotation-invariant basis as two azimuth harmonics, and :func:`multipliers`
takes their Floquet multipliers with :mod:`wtvib.numerics.floquet`'s integrator (check
``system.floquet``).

References
----------
Hau §7.6 and ch. 6.8.2; M. H. Hansen, Wind Energy 6 (2003) 179–195 (periodic rotor
equations); Blanes et al., Physics Reports 470 (2009) (Magnus integrator).
"""

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from ..judge.excitation import operating_range
from ..judge.resonance import regime_of
from ..numerics import modal
from ..numerics.floquet import _GAUSS, GROWTH, MAX_STEPS, REFINE, propagate, steps_for
from ..results import Check, Rule
from ..units import rad_s_to_hz, rpm_to_rad_s
from .multiblade import Model, parked
from .rotor import bladed

if TYPE_CHECKING:
    from ..rules import Status
    from ..spec import Spec

Array = NDArray[np.float64]


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
        out: Array = (
            x[0]
            + np.cos(psi) * x[1]
            + np.sin(psi) * x[2]
            + np.cos(2 * psi) * x[3]
            + np.sin(2 * psi) * x[4]
        )
        return out

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
    res = parked(model, count=modes, by_content=False)
    keep = max(4, int(np.count_nonzero(res.frequency_hz <= cutoff_hz)))
    shapes = np.real(res.shapes[:, :keep])
    fixed = np.ones(lay.size, dtype=bool)
    fixed[lay.blades] = False
    q, r = np.linalg.qr(shapes[fixed])
    size = np.abs(np.diag(r))
    # a model whose fixed parts do not move (a deck with only its blades' DOFs on) has none
    q = q[:, size > 1e-9 * size.max()] if size.size and size.max() > 0 else q[:, :0]
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

    None where the speed cannot be analysed: a rotor that does not turn (Ω ≤ 0: no period,
    the parked modes are the standstill solution's), one revolution would need more than
    ``max_steps`` steps (a slow rotor with a stiff basis), or the multipliers do not come out
    finite.
    """
    if not omega > 0:
        return None
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


def cutoff_hz(spec: "Spec") -> float:
    """The highest parked frequency the check's basis keeps: modes up to three times the
    highest excitation checked carry the parametric coupling (wtvib's choice of margin, no
    published figure; it keeps the basis small)."""
    top = float(rad_s_to_hz(rpm_to_rad_s(spec.rotor.speed.overspeed)))
    return max(2.0, 3 * spec.audit.harmonics * top)


def _confirmed(p: Periodic, omega: float) -> NDArray[np.complex128] | None:
    """:func:`multipliers` at Ω, integrated again on finer steps (floquet.REFINE) where
    they show growth: what stays above 1 + GROWTH is growth, not the step's error."""
    found = multipliers(p, omega)
    if found is None:
        return None
    steps = steps_for(p.highest_hz, 2 * np.pi / omega)
    for k in REFINE:
        if found is None or np.abs(found).max() <= 1 + GROWTH:
            break
        finer = multipliers(p, omega, steps=k * steps, max_steps=max(REFINE) * MAX_STEPS)
        if finer is None:
            break
        found = finer
    return found


_FLOQUET_RULE = Rule(
    "Floquet multipliers of the coupled periodic system, |ρ| ≤ 1",
    "Hau §7.6 and ch. 6.8.2 (periodic coefficients of two-bladed rotors, Floquet)",
)


def stability_check(spec: "Spec", model: "Model") -> "Check":
    """``system.floquet``: parametric stability of the coupled two-bladed turbine ``model``
    over its speed range (periodic coefficients; three or more blades are time-invariant)."""
    speed = spec.rotor.speed
    cutoff = cutoff_hz(spec)
    p = periodic(model, cutoff_hz=cutoff)
    low = speed.steady_rpm[0][0]
    rpm = np.unique(
        np.concatenate(
            [np.linspace(low, speed.overspeed, 12), [a for band in speed.steady_rpm for a in band]]
        )
    )
    turbine = f"Coupled {bladed(spec.rotor.blades)} turbine"
    rpm = rpm[rpm > 0]  # a rotor at rest has no period: its parked modes stand for it
    if len(rpm) == 0:
        return Check(
            id="system.floquet",
            subsystem="system",
            status="info",
            message=f"{turbine} not analysed: its rotor does not turn (0 rpm), so its "
            "equations have no period — the parked modes are its modes",
            rule=_FLOQUET_RULE,
            numbers={"not_analysed_rpm": [0.0]},
        )
    found = [_confirmed(p, float(rpm_to_rad_s(n))) for n in rpm]
    skipped = [float(n) for n, f in zip(rpm, found, strict=True) if f is None]
    rpm = np.array([n for n, f in zip(rpm, found, strict=True) if f is not None])
    largest = [float(np.abs(f).max()) for f in found if f is not None]
    if not largest:
        return Check(
            id="system.floquet",
            subsystem="system",
            status="info",
            message=f"{turbine} not analysed: at these speeds one revolution "
            f"would need more than {MAX_STEPS:,} integration steps of its fastest mode "
            f"({p.highest_hz:.3g} Hz), or the multipliers were not finite",
            rule=_FLOQUET_RULE,
            numbers={"not_analysed_rpm": skipped},
        )
    unstable = [float(n) for n, r in zip(rpm, largest, strict=True) if r > 1 + GROWTH]
    op = operating_range(speed)

    def in_operation(n: float) -> bool:
        return regime_of(float(rpm_to_rad_s(n)), op) in ("steady", "quick-pass")

    steady = [n for n in unstable if in_operation(n)]
    gaps = [n for n in skipped if in_operation(n)]
    status: Status = "fail" if steady else "warn" if unstable or gaps else "pass"
    where = ", ".join(f"{n:.3g}" for n in unstable)
    return Check(
        id="system.floquet",
        subsystem="system",
        status=status,
        message=f"{turbine}, Floquet multipliers over {low:.3g}–"
        f"{speed.overspeed:.3g} rpm (generator {model.condition}): largest |ρ| "
        f"{max(largest):.6f}; "
        + (f"growing at {where} rpm" if where else "no growth")
        + (
            f"; not analysed at {', '.join(f'{n:.3g}' for n in skipped)} rpm (one revolution "
            f"would need over {MAX_STEPS:,} steps of the basis's fastest mode, "
            f"{p.highest_hz:.3g} Hz, or the multipliers were not finite)"
            if skipped
            else ""
        ),
        rule=_FLOQUET_RULE,
        numbers={
            "rpm": [round(float(n), 6) for n in rpm],
            "max_multiplier": [round(r, 9) for r in largest],
            "unstable_rpm": unstable,
            "not_analysed_rpm": skipped,
            "basis": f"{p.k0.shape[0]} coordinates (fixed parts of the parked modes up to "
            f"{cutoff:.3g} Hz, every blade coordinate)",
        },
    )
