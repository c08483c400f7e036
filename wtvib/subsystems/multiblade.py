"""Multi-blade (Coleman) coordinates: the coupled model's modes in the fixed frame.

With three or more blades the transformation ηⱼ = a₀ + Σ_h (a_hc cos hψⱼ + a_hs sin hψⱼ)
(+ the alternating (−1)ʲ a for even N) turns the periodic equations of
:class:`wtvib.subsystems.coupled.Model` into time-invariant ones: each rotor speed is one
eigenproblem,
and cyclic blade modes appear as backward and forward whirl, f ∓ 1P. Modes are named by
where their kinetic energy sits and followed across speed by mass-weighted MAC.

References
----------
G. Bir, "Multi-blade coordinate transformation and its application to wind turbine
analysis", AIAA 2008-1300; M. H. Hansen, "Improved modal dynamics of wind turbines to avoid
stall-induced vibrations", Wind Energy 6 (2003) 179–195 (whirl naming).
"""

import math
import re
from collections import Counter
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Any, Protocol

import numpy as np
from numpy.typing import NDArray

from ..numerics import modal
from ..numerics.coleman import coleman
from ..results import ordinal
from ..units import rad_s_to_rpm

Array = NDArray[np.float64]
Index = NDArray[np.intp]


@dataclass(frozen=True)
class Layout:
    """Global degrees of freedom: offsets of each part and the map of the local coordinates.

    ``local[j]`` holds, for blade j, the global index of each local coordinate (−1: held)
    and ``sign`` its sign (the side-side slope is −θₓ).
    """

    size: int
    fa: slice
    ss: slice
    torsion: slice
    yaw: int | None
    chain: slice
    blades: slice
    local: Index
    sign: Array
    #: the tuned mass dampers' own coordinates (fixed frame), between the chain and the blades
    dampers: slice = field(default_factory=lambda: slice(0, 0))


class RotorModes(Protocol):
    """What is read of the blades' modes: their names and standstill circular frequencies."""

    @property
    def names(self) -> tuple[str, ...]: ...
    @property
    def omega(self) -> Array: ...


class Model(Protocol):
    """What the multi-blade transformation, the tracking and the Floquet check read of the
    coupled model (:class:`wtvib.subsystems.coupled.Model`, which builds it): this module does not
    know how the model is built."""

    @property
    def layout(self) -> Layout: ...
    @property
    def rotor(self) -> RotorModes: ...
    @property
    def blades(self) -> int: ...
    @property
    def condition(self) -> str: ...
    @property
    def k_v(self) -> Array: ...
    @property
    def d_v(self) -> Array: ...
    @property
    def k_blades(self) -> int: ...
    @property
    def multiblade(self) -> tuple[Array, Array, Array, Array, Array]: ...
    @property
    def standstill(self) -> tuple[Array, Array, Array]: ...
    @property
    def groups(self) -> dict[str, Index]: ...
    @property
    def tower_curvatures(self) -> Mapping[str, Array]: ...
    def standstill_modes(self, count: int) -> modal.Modes: ...
    @property
    def active(self) -> Index: ...
    def ritz(self, count: int) -> tuple[Array, tuple[Array, Array, Array, Array, Array]]: ...
    # M, D, K at Ω and ψ: new arrays each call, which the caller may change in place
    def matrices(self, omega: float, psi: float) -> tuple[Array, Array, Array]: ...


#: Coupled modes reported: the lowest ones, up to this many (wtvib's choice: enough for the
#: first and second tower, blade-flap and drive-train modes of Jonkman et al. Table 9-1).
MODES_KEPT = 16

#: A mode above the lowest ones kept is kept too where it carries at least this share of the
#: kinetic energy of a part that no kept mode is dominated by — the drive train, tower
#: torsion, yaw — and a mode's description names such a share: on the WindPACT 1.5 MW the
#: gearbox reaction on the tower top splits the drive-train torsion (25.6 Hz with the tower
#: held) over the tower's 4th–6th side-side modes, 14–24 % each (wtvib's choice of threshold;
#: tests/validation/test_coupled.py).
CONTENT_SHARE = 0.2
#: At most this many modes are kept by content.
CONTENT_EXTRA = 4
_CONTENT = {
    "drivetrain": "drive-train torsion",
    "tower.tor": "tower torsion",
    "yaw": "yaw",
    "damper": "tuned mass damper",
}
#: Candidates a tracked path compares beyond the modes it follows.
TRACK_SPARE = 4

#: The Ritz basis of the rotating sweep and of the damped solves at the operating points
#: (``Model.ritz``, :func:`wtvib.numerics.modal.ritz_basis`): the undamped standstill modes up to
#: the
#: highest a path follows and its spare candidates (at least RITZ_STANDSTILL), and what the
#: loads on the lowest RITZ_IMAGES excite beyond them — of the drive train's dampers, of the
#: Ω² stiffness (centrifugal stiffening and softening) and of the Ω damping (gyroscopic and
#: Coriolis terms): 31–34 vectors on seven reference turbines. The sweep's frequencies then
#: agree with the full model's to 1e-8 and the damped solves' ζ to 1e-9, where 48
#: standstill modes alone were up to 3e-4 off (the AOC 15/50) and the 32 of the damped
#: solves 2e-5 (the NREL 5-MW): tests/validation/test_coupled.py, test_aerodynamics.py. A
#: path's first point, where the modes it follows are chosen (by content among 3 ×
#: MODES_KEPT roots), is solved in a basis of that many standstill modes: the same modes as
#: the full model's, and none of a stiffness far above the rest (a shaft typed as rigid),
#: whose root would squeeze the slow ones into rounding.
RITZ_STANDSTILL = MODES_KEPT + CONTENT_EXTRA + TRACK_SPARE
RITZ_IMAGES = MODES_KEPT

_KINDS = {"flap": "flapwise", "edge": "edgewise"}

# ---------------------------------------------------------------------------------------
# Multi-blade coordinates


def fixed_frame(model: "Model", omega: float, psi: float = 0.0) -> tuple[Array, Array, Array]:
    """M, D, K in multi-blade coordinates (time-invariant for three or more blades).

    q = T(ψ)·z with q̇ = T·ż + Ω·T′·z and q̈ = T·z̈ + 2Ω·T′·ż + Ω²·T″·z, projected with Tᵀ.
    """
    m, d, k = model.matrices(omega, psi)
    # T is the identity outside the blades' block and kron(B, I) on it, T′ and T″ zero
    # outside it: the products touch that block's rows and columns only (dense ones cost
    # n³: 0.15 s each on a tower with its monopile's 815 coordinates)
    b, b1, b2, _ = coleman(model.blades, psi)
    eye = np.eye(model.k_blades)
    tb, tb1, tb2 = (np.asarray(np.kron(x, eye), dtype=float) for x in (b, b1, b2))
    blk = model.layout.blades

    def times_t(a: Array) -> Array:  # A·T, in place
        a[:, blk] = a[:, blk] @ tb
        return a

    def t_times(a: Array) -> Array:  # Tᵀ·A, in place
        a[blk, :] = tb.T @ a[blk, :]
        return a

    # associated as the dense products were, (Tᵀ·M)·T and ((2Ω)·M)·T′ (T′, T″ are zero
    # outside the block: their terms add to its columns only), so that every element is
    # rounded alike and the outputs stay the same to the bit; in place on the matrices
    # model.matrices copied for this call (five copies of an 815² matrix saved on the
    # IEA-15 monopile), the stiffness first: it reads the damping's and the mass's columns
    # as they were
    stiffness = times_t(k)
    stiffness[:, blk] = ((omega**2) * m[:, blk] @ tb2 + omega * d[:, blk] @ tb1) + stiffness[:, blk]
    damping = times_t(d)
    damping[:, blk] = (2 * omega) * m[:, blk] @ tb1 + damping[:, blk]
    return times_t(t_times(m)), t_times(damping), t_times(stiffness)


def _blade_block(model: "Model", size: int) -> slice:
    """The blades' coordinates among ``size`` (the model's, or its :attr:`Model.active`):
    the last ones."""
    count = model.blades * model.k_blades
    return slice(size - count, size)


def fixed_frame_damping(model: "Model", d: Array, omega: float | Array) -> tuple[Array, Array]:
    """A damping matrix ``d`` of the periodic equations (at ψ = 0) in multi-blade
    coordinates: Tᵀ·D·T to the damping and Ω·Tᵀ·D·T′ to the stiffness (q̇ = T·ż + Ω·T′·z),
    exact for an isotropic rotor of three or more blades. A stack of matrices (…, n, n)
    takes a rotor speed per matrix; ``d`` on all the model's coordinates or on
    :attr:`Model.active` (the result on the same)."""
    # T is the identity outside the blades' block and kron(B, I) on it, T′ is kron(B′, I)
    # there and zero elsewhere: only that block's rows and columns change (9 of the NREL
    # deck's 52 coordinates, 9 of the IEA-22's 204: dense products would do the rest for nothing).
    # The blades' coordinates are the last, of the model's and of Model.active alike.
    b, b1, _, _ = coleman(model.blades, 0.0)
    eye = np.eye(model.k_blades)
    tb, tb1 = np.kron(b, eye), np.kron(b1, eye)
    blk = _blade_block(model, d.shape[-1])
    damping = d.copy()
    damping[..., :, blk] = d[..., :, blk] @ tb  # D·T
    damping[..., blk, :] = tb.T @ damping[..., blk, :]  # Tᵀ·(D·T)
    stiffness = np.zeros_like(d)
    stiffness[..., :, blk] = d[..., :, blk] @ tb1  # D·T′
    stiffness[..., blk, :] = tb.T @ stiffness[..., blk, :]
    stiffness *= np.asarray(omega, dtype=float)[..., None, None]
    return damping, stiffness


@dataclass(frozen=True)
class LiftLag:
    """The blades' lift lag states (:mod:`wtvib.numerics.unsteady`) in multi-blade coordinates, one
    set per operating point (stacks): χ̇ = P·z + V·ż + S·χ, the generalised force −F·χ."""

    force: Array  # F (…, n, L)
    on_position: Array  # P (…, L, n)
    on_rate: Array  # V (…, L, n)
    rates: Array  # S (…, L, L)

    def at(self, i: int) -> "LiftLag":
        """The states of operating point i."""
        return LiftLag(self.force[i], self.on_position[i], self.on_rate[i], self.rates[i])

    def reduced(self, basis: Array) -> "LiftLag":
        """In a reduced basis z = Φ·p."""
        return LiftLag(
            basis.T @ self.force, self.on_position @ basis, self.on_rate @ basis, self.rates
        )

    def joined(self, other: "LiftLag") -> "LiftLag":
        """Both sets of states side by side (independent filters on the same coordinates)."""
        a, b = self.rates.shape[-1], other.rates.shape[-1]
        rates = np.zeros((*self.rates.shape[:-2], a + b, a + b))
        rates[..., :a, :a] = self.rates
        rates[..., a:, a:] = other.rates
        return LiftLag(
            np.concatenate([self.force, other.force], axis=-1),
            np.concatenate([self.on_position, other.on_position], axis=-2),
            np.concatenate([self.on_rate, other.on_rate], axis=-2),
            rates,
        )


#: What a point adds to the multi-blade equations: damping and stiffness, and the lift's lag
#: states where the aerodynamics is unsteady.
Extra = tuple[Array, Array] | tuple[Array, Array, LiftLag]


def lift_lag(
    model: "Model",
    d_lift: Array,
    d_rate: Array,
    omega: Array,
    terms: Sequence[tuple[float, float]] | None = None,
    columns: NDArray[np.intp] | None = None,
) -> LiftLag:
    """Jones's lag of the blades' lift (:mod:`wtvib.numerics.unsteady`) on the coupled model
    — or another filter's ``terms`` (Aᵢ, bᵢ): the separation point's one pole (1, 1) with
    ``d_rate`` weighted by each section's 1/T_f.

    ``d_lift`` (p, n, n): the lift slope's part of the section damping (on the model's
    coordinates or on :attr:`Model.active`, ψ = 0, one matrix per operating point; the
    states act on the same), ``d_rate``: the same with each section's
    reduced rate 2W/c as a factor; ``omega`` (p,): the rotor speeds. The lag acts on the
    velocities the lift responds to: the coordinates whose columns ``d_lift`` fills (each
    blade's modes, the hub's motion). Each such coordinate's velocity goes through one
    filter per term of Jones's approximation, at its lift-weighted reduced rate; the
    blades' filters, like their coordinates, in multi-blade form: with z_b = T_b·χ and
    T_b′ = T_b·R, χ̇ = −(β + Ω·R)·χ + βA·(ż + Ω·R·z) (R constant for three or more blades,
    so the lagged system stays time-invariant). The immediate share (1 − A₁ − A₂) of the
    lift stays in the damping matrix (:func:`fixed_frame_damping` of the rest)."""
    from ..numerics.unsteady import JONES

    filters = JONES if terms is None else tuple(terms)
    n = d_lift.shape[-1]
    diag = np.abs(np.diagonal(d_lift, axis1=-2, axis2=-1))
    blk = np.arange(n)[_blade_block(model, n)]
    cols = lag_columns(model, d_lift) if columns is None else columns
    width = len(cols)
    weight = diag[:, cols]
    rate = np.abs(np.diagonal(d_rate, axis1=-2, axis2=-1))[:, cols]
    fallback = rate.sum(axis=1, keepdims=True) / np.maximum(
        weight.sum(axis=1, keepdims=True), 1e-300
    )
    kappa = np.where(weight > 0, rate / np.where(weight > 0, weight, 1.0), fallback)
    b, b1, _, _ = coleman(model.blades, 0.0)
    turn = np.zeros((width, width))
    at = np.flatnonzero(np.isin(cols, blk))
    turn[np.ix_(at, at)] = np.kron(np.linalg.solve(b, b1), np.eye(model.k_blades))
    pick = np.zeros((width, n))
    pick[np.arange(width), cols] = 1.0
    om = np.asarray(omega, float)[:, None, None]
    mbc, _ = fixed_frame_damping(model, d_lift, omega)
    f = mbc[..., :, cols]
    count = len(filters)
    points = len(om)
    force = np.concatenate([f] * count, axis=-1)
    on_rate = np.zeros((points, count * width, n))
    on_position = np.zeros_like(on_rate)
    rates = np.zeros((points, count * width, count * width))
    for i, (amp, b_i) in enumerate(filters):
        beta = b_i * kappa  # (p, width)
        rows = slice(i * width, (i + 1) * width)
        on_rate[:, rows] = amp * beta[:, :, None] * pick
        on_position[:, rows] = amp * beta[:, :, None] * (om * (turn @ pick))
        rates[:, rows, rows] = -(beta[:, :, None] * np.eye(width) + om * turn)
    return LiftLag(force, on_position, on_rate, rates)


def lag_columns(model: "Model", d_lift: Array) -> NDArray[np.intp]:
    """The coordinates whose velocity a lift's lag states filter: each blade's modes and
    whatever else ``d_lift`` (…, n, n) damps (the hub's motion)."""
    n = d_lift.shape[-1]
    blk = np.arange(n)[_blade_block(model, n)]
    diag = np.abs(np.diagonal(d_lift, axis1=-2, axis2=-1)).reshape(-1, n)
    used = np.flatnonzero(diag.max(axis=0) > 1e-12 * max(float(diag.max(initial=0.0)), 1e-300))
    return np.union1d(blk, used)


def separation_lag(
    model: "Model",
    d_sep: Array,
    d_rate: Array,
    omega: Array,
    jones: LiftLag | None,
    columns: NDArray[np.intp],
) -> LiftLag:
    """The separation point's lag (dynamic stall, :mod:`wtvib.numerics.unsteady`) of the
    separated part ``d_sep`` of the lift, ``d_rate`` that part weighted by each section's
    1/T_f: one state per coordinate of ``columns``, behind Jones's ``jones`` states where
    the shed wake lags the lift (its input the effective velocity (1 − A₁ − A₂)·ż + Σ zᵢ,
    in multi-blade form as :func:`lift_lag`'s), else on the velocity itself; returned
    joined after ``jones``'s states."""
    from ..numerics.unsteady import IMMEDIATE

    amp = 1.0 if jones is None else IMMEDIATE
    sep = lift_lag(model, d_sep, d_rate, omega, ((amp, 1.0),), columns)
    if jones is None:
        return sep
    out = jones.joined(sep)
    width = len(columns)
    beta = -np.diagonal(sep.rates, axis1=-2, axis2=-1)  # the rotation's terms: no diagonal
    feed = beta[..., :, None] * np.eye(width)
    base = jones.rates.shape[-1]
    for start in range(0, base, width):  # every Jones term's states feed the separation
        out.rates[..., base:, start : start + width] = feed
    return out


# ---------------------------------------------------------------------------------------
# Modes, named by participation


@dataclass(frozen=True)
class SystemModes:
    """Modes of the coupled model at one rotor speed: frequencies, shapes in multi-blade
    coordinates (complex when rotating), names, and where their kinetic energy sits."""

    frequency_hz: Array
    shapes: NDArray[np.complex128]
    names: tuple[str, ...]
    descriptions: tuple[str, ...]
    energy: tuple[dict[str, float], ...]  # shares by group, cyclic pairs merged (shares())
    whirl: tuple[str | None, ...]  # backward / collective / forward / cyclic …; None: no rotor
    damping_ratio: Array | None = None  # −Re λ/|λ| (rotating solve; the drive train's dampers)
    span: int = 0  # the kept modes lie among this many lowest roots (0: the kept ones)


def parked(
    model: "Model", psi: float = 0.0, count: int = MODES_KEPT, by_content: bool = True
) -> SystemModes:
    """Modes of the parked turbine (Ω = 0) at rotor azimuth ψ (blade 1 up at ψ = 0): the
    lowest ``count`` and, ``by_content``, the higher ones :func:`by_content` keeps."""
    wanted = min(count + 2 + (_spare(count) if by_content else 0), model.layout.size)
    if psi == 0.0:  # blade 1 up: the model's standstill modes, solved once
        m, _, _ = model.standstill
        res = model.standstill_modes(wanted)
    else:
        m, _, k = fixed_frame(model, 0.0, psi)
        res = modal.solve(k, m, wanted)
    keep = res.frequency_hz > 1e-3  # a free generator leaves the rotor free to turn
    f, shapes = res.frequency_hz[keep], res.shapes[:, keep].astype(complex)
    idx = _by_content(model, m, shapes, count) if by_content else np.arange(min(count, len(f)))
    f, shapes = f[idx], shapes[:, idx]
    return SystemModes(f, shapes, *_name(model, m, shapes), span=int(idx[-1]) + 1)


def _spare(count: int) -> int:
    """Roots solved beyond the lowest ``count`` to look for modes kept by content."""
    return 2 * count


def _by_content(model: "Model", m: Array, shapes: NDArray[np.complex128], count: int) -> Index:
    """Indices of the lowest ``count`` modes and of the higher ones that carry at least
    CONTENT_SHARE of the energy of a part (drive train, tower torsion, yaw) that dominates
    no lower mode, lowest first, at most CONTENT_EXTRA of them."""
    groups = model.groups
    energy = _energy(m, shapes)
    energy /= np.maximum(energy.sum(axis=0, keepdims=True), 1e-300)
    part = {g: energy[groups[g]].sum(axis=0) for g in _CONTENT if g in groups and len(groups[g])}
    kept = list(range(min(count, shapes.shape[1])))
    open_ = [g for g, e in part.items() if not np.any(e[kept] >= 0.5)]
    for j in range(len(kept), shapes.shape[1]):
        if not open_ or len(kept) >= count + CONTENT_EXTRA:
            break
        hit = [g for g in open_ if part[g][j] >= CONTENT_SHARE]
        if hit:
            kept.append(j)
            open_ = [g for g in open_ if part[g][j] < 0.5]
    return np.asarray(kept, dtype=np.intp)


def rotating(
    model: "Model",
    omega: float,
    count: int = MODES_KEPT,
    extra: Extra | None = None,
    reduced: int = 0,
    by_content: bool = False,
) -> SystemModes:
    """Fixed-frame modes at rotor speed Ω [rad/s] (multi-blade coordinates, N ≥ 3): the
    lowest ``count`` and, ``by_content``, the higher ones :func:`_by_content` keeps;
    ``extra`` adds a damping and a stiffness matrix in multi-blade coordinates (the
    aerodynamic ones of an operating point, :func:`fixed_frame_damping`); ``reduced``
    solves in the model's Ritz basis of that many standstill modes and their images
    (``Model.ritz``)."""
    ((lam, vec),) = _roots(model, [(omega, extra)], reduced, overdamped=False)
    m = model.multiblade[0]
    idx = (
        _by_content(model, m, vec[:, : count + _spare(count)], count)
        if by_content
        else np.arange(min(count, len(lam)))
    )
    modes = _selected(lam, vec, idx)
    names, texts, energy, whirl = _name(model, m, modes.shapes)
    return replace(modes, names=names, descriptions=texts, energy=energy, whirl=whirl)


def _selected(lam: NDArray[np.complex128], vec: NDArray[np.complex128], idx: Index) -> SystemModes:
    """The roots ``idx`` as modes (unnamed): |λ|/2π and −Re λ/|λ|, as
    wtvib.numerics.modal.damped."""
    lam, shapes = lam[idx], vec[:, idx]
    span = int(idx[-1]) + 1 if len(idx) else 0
    return SystemModes(
        np.abs(lam) / (2 * np.pi),
        shapes,
        (),
        (),
        (),
        (),
        damping_ratio=modal.damping_ratio(lam),
        span=span,
    )


def _roots(
    model: "Model",
    points: Sequence[tuple[float, Extra | None]],
    reduced: int,
    overdamped: bool,
) -> list[tuple[NDArray[np.complex128], NDArray[np.complex128]]]:
    """The oscillatory roots and their shapes (multi-blade coordinates) at each (Ω, extra
    matrices) point — D = D₀ + Ω·D₁ (+ extra), K = K₀ + Ω²·K₂ (+ extra), with the lift's
    lag states where the extra holds them (:class:`LiftLag`) — all points as one stack
    (modal.oscillations_stacked); ``reduced``: in the model's Ritz basis of that many
    standstill modes, the shapes mapped back; ``overdamped``: real roots kept too (a path
    followed by shape keeps heavily damped flap modes). Roots below 1 mHz are the rotor
    turning on a free generator, not oscillations."""
    if reduced:  # in the Ritz basis, shapes mapped back
        basis, (m, d0, d1, k0, k2) = model.ritz(reduced)
    else:
        m, d0, d1, k0, k2 = model.multiblade
    omega = np.array([om for om, _ in points], dtype=float)[:, None, None]
    d, k = d0 + omega * d1, k0 + omega**2 * k2
    lags: list[LiftLag] = []
    for i, (_, extra) in enumerate(points):
        if extra is not None:
            ed, ek = extra[0], extra[1]
            on = _embedding(model, ed.shape[-1], basis if reduced else None)
            if on is None:  # all the model's coordinates: added as they are
                d[i] += ed
                k[i] += ek
            else:
                d[i] += on.T @ ed @ on
                k[i] += on.T @ ek @ on
            if len(extra) > 2:
                lag = extra[2]
                lags.append(lag.reduced(on) if on is not None else lag)
    states = None
    if lags:
        if len(lags) != len(points):
            raise ValueError("lift lag states at some points only")
        states = (
            np.stack([g.force for g in lags]),
            np.stack([g.on_position for g in lags]),
            np.stack([g.on_rate for g in lags]),
            np.stack([g.rates for g in lags]),
        )
    found = modal.oscillations_stacked(
        k, m, d, floor=2 * np.pi * 1e-3, overdamped=overdamped, lag=states
    )
    return [(lam, basis @ vec if reduced else vec) for lam, vec in found]


def _embedding(model: "Model", size: int, basis: Array | None) -> Array | None:
    """How a matrix on ``size`` coordinates (the model's, or :attr:`Model.active`) enters
    the equations solved: the rows of ``basis`` (a Ritz basis) or of the identity that
    those coordinates are; None where it is added as it is."""
    lay_size = model.layout.size
    if size == lay_size:
        return basis
    active = model.active
    if basis is not None:
        return np.asarray(basis[active])
    out = np.zeros((size, lay_size))
    out[np.arange(size), active] = 1.0
    return out


def coordinate_groups(model: "Model") -> dict[str, Index]:
    """Coordinate groups by which modes are named (multi-blade coordinates for the rotor);
    a model keeps its own (``Model.groups``)."""
    lay = model.layout
    out: dict[str, Index] = {
        "tower.fa": np.arange(lay.fa.start, lay.fa.stop),
        "tower.ss": np.arange(lay.ss.start, lay.ss.stop),
        "tower.tor": np.arange(lay.torsion.start, lay.torsion.stop),
        "drivetrain": np.arange(lay.chain.start, lay.chain.stop),
    }
    if lay.yaw is not None:
        out["yaw"] = np.array([lay.yaw])
    if lay.dampers.stop > lay.dampers.start:
        out["damper"] = np.arange(lay.dampers.start, lay.dampers.stop)
    _, _, _, harmonics = coleman(model.blades, 0.0)
    kb = model.k_blades
    for k, name in enumerate(model.rotor.names):
        for h, label in enumerate(harmonics):
            out[f"blade.{name}.{label}"] = np.array([lay.blades.start + h * kb + k])
    return out


def shares(
    m: Array, shapes: NDArray[np.complex128], groups: Mapping[str, Index]
) -> tuple[tuple[str, ...], Array, tuple[str, ...], Array]:
    """Each mode's kinetic-energy share per coordinate group (|x̄ᵢ·(M x)ᵢ| summed,
    normalised) and the same with each cyclic cos/sin pair merged into one ``cyclic``
    group — all modes (the columns of ``shapes``) at once: the group names and a
    (groups, modes) table of shares, then the merged names and table."""
    names = tuple(g for g, i in groups.items() if len(i))
    table = _fractions(_energy(m, shapes), [groups[g] for g in names])
    merged_names, merged = _summed(
        [g.replace("cos", "cyclic").replace("sin", "cyclic") for g in names], table
    )
    return names, table, merged_names, merged


def _fractions(energy: Array, parts: Sequence[NDArray[np.intp]]) -> Array:
    """(parts, modes): each mode's (column's) share of its energy in each part's
    coordinates (a mode without energy: zeros)."""
    total = energy.sum(axis=0)
    total[total == 0.0] = 1.0
    return np.array([energy[idx].sum(axis=0) / total for idx in parts])


def _energy(m: Array, shapes: NDArray[np.complex128]) -> Array:
    """|x̄ᵢ·(M x)ᵢ| of each coordinate i and mode (column) x: its kinetic-energy density."""
    # Re(x̄ᵢ·(M x)ᵢ) = xrᵢ·(M xr)ᵢ + xiᵢ·(M xi)ᵢ: one real product (M is real; a complex one
    # converts it to complex first — 4 ms a call at the IEA-15 monopile's n = 815)
    modes = shapes.shape[1]
    both = _mass_times(m, np.concatenate([shapes.real, shapes.imag], axis=1))
    return np.asarray(np.abs(shapes.real * both[:, :modes] + shapes.imag * both[:, modes:]))


#: A model this large (a tower of more than 200 stations, meshed at 200 elements) is a band
#: and a few dense blocks: products with its mass matrix go through its sparse form.
LARGE_STATES = 700

#: The last large mass matrix :func:`_mass_times` made sparse, with its sparse form.
_SPARSE: tuple[Array, Any] | None = None


def _mass_times(m: Array, x: Array) -> Array:
    """M·X. A model of LARGE_STATES coordinates or more (a tower of 200 elements: its
    beam's band and a few dense blocks, under 1 % of M filled) multiplies through M's
    sparse form — 15 times faster at 815 coordinates (the IEA-15 monopile's before its mesh
    took its stations), the same sums to
    rounding (1e-16); the form is made once per matrix (the last one kept: a sweep asks
    with the same M at every speed)."""
    global _SPARSE
    if m.shape[0] < LARGE_STATES:
        return np.asarray(m @ x)
    held = _SPARSE  # one read: the pair stays consistent whatever else runs
    if held is None or held[0] is not m:
        from scipy import sparse

        held = (m, sparse.csr_matrix(m))
        _SPARSE = held
    return np.asarray(held[1] @ x)


def _summed(keys: list[str], table: Array) -> tuple[tuple[str, ...], Array]:
    """The rows of ``table`` summed by their ``keys`` (first-seen order; rows added in the
    order they are listed: a cyclic pair's cos before its sin)."""
    unique = tuple(dict.fromkeys(keys))
    out = np.zeros((len(unique), table.shape[1]))
    row = {k: i for i, k in enumerate(unique)}
    for key, values in zip(keys, table, strict=True):
        out[row[key]] += values
    return unique, out


def parts(model: "Model", m: Array, shapes: NDArray[np.complex128]) -> tuple[str, ...]:
    """The part each mode's kinetic energy mostly sits in: a blade mode over all its
    multi-blade coordinates (``blade.flap1``, ``blade.edge1`` …), else ``tower.fa``,
    ``tower.ss``, ``tower.tor``, ``drivetrain`` or ``yaw``. A mode followed through a
    veering keeps its name and changes its part."""
    return whirls_and_parts(model, m, shapes)[1]


def whirls_and_parts(
    model: "Model", m: Array, shapes: NDArray[np.complex128]
) -> tuple[tuple[str | None, ...], tuple[str, ...]]:
    """Each mode's whirl (backward, forward, cyclic, collective, alternating; None: not a
    rotor mode), as :func:`_name` gives it without the names — what a sweep records at
    every speed — and its :func:`parts`, from one reckoning of the energy shares (M times
    the shapes: on the IEA-15 monopile's 815 coordinates, most of a sweep step's cost)."""
    groups = model.groups
    names, table, merged_names, merged = shares(m, shapes, groups)
    whirl = tuple(
        _whirl(merged_names[int(t)], shapes[:, j], groups)
        for j, t in enumerate(np.argmax(merged, axis=0))
    )
    kinds, summed = _summed(
        [".".join(g.split(".")[:2]) if g.startswith("blade.") else g for g in names], table
    )
    return whirl, tuple(kinds[int(k)] for k in np.argmax(summed, axis=0))


def _name(
    model: "Model", m: Array, shapes: NDArray[np.complex128]
) -> tuple[tuple[str, ...], tuple[str, ...], tuple[dict[str, float], ...], tuple[str | None, ...]]:
    """Ids, descriptions, energy shares (merged) and whirl of each mode, named by those
    shares."""
    groups = model.groups
    group_names, table, merged_names, merged_table = shares(m, shapes, groups)
    share = dict(zip(group_names, table, strict=True))
    names: list[str] = []
    texts: list[str] = []
    energy: list[dict[str, float]] = []
    whirls: list[str | None] = []
    counters: dict[str, int] = {}
    bent: dict[str, list[int]] = {}  # the modes named by each tower part so far
    for j in range(shapes.shape[1]):
        merged = {g: float(v) for g, v in zip(merged_names, merged_table[:, j], strict=True)}
        top = merged_names[int(np.argmax(merged_table[:, j]))]
        whirl = _whirl(top, shapes[:, j], groups)
        first = top
        trial, _ = _mode_name(top, share, j, dict(counters), whirl)

        def unlike(part: str, j: int = j) -> bool:  # not the tower's next mode of that part
            return _bent_alike(model.layout, part, shapes, j, bent.get(part, [])) or not (
                _bends_as_its_own(model, part, shapes[:, j], counters.get(part, 0) + 1)
            )

        if unlike(top) or _free_name(trial, names) is None:  # the next group it has a share in
            top = _free_group(top, merged, share, j, names, counters, unlike)
            whirl = _whirl(top, shapes[:, j], groups)
        name, text = _mode_name(top, share, j, counters, whirl)
        if top != first:
            said = _PARTS.get(first) or _mode_name(first, share, j, {}, None)[1].split(" (")[0]
            text = f"{text}, {merged[first]:.0%} {said} (named by its second share)"
        free = _free_name(name, names)
        if free is not None and free != name:  # the other axis of its cyclic pair
            was, now = name.rsplit("_", 1)[1], free.rsplit("_", 1)[1]
            name, text = free, text.replace(f"({was})", f"({now})")
        if whirl in ("forward", "backward"):
            text = f"{text}, {whirl} whirl"
        mixed = [
            f"{merged[g]:.0%} {label}"
            for g, label in _CONTENT.items()
            if g != top and merged.get(g, 0.0) >= CONTENT_SHARE
        ]
        if mixed:
            text = f"{text}, {', '.join(mixed)}"
        if name in names:  # a second mode of one family: say what else it bends
            bends = [
                f"{merged[g]:.0%} {_PARTS[g]}"
                for g in ("tower.fa", "tower.ss")
                if g != top and merged.get(g, 0.0) >= CONTENT_SHARE
            ]
            text = ", ".join([text, *bends])
            name = f"{name}_{sum(n.startswith(name) for n in names) + 1}"
        if top in _TOWER_BLOCKS:
            bent.setdefault(top, []).append(j)
        names.append(name)
        texts.append(text)
        energy.append(merged)
        whirls.append(whirl)
    return tuple(names), tuple(texts), tuple(energy), tuple(whirls)


#: The tower's coordinate blocks by part: (u, θ) per node in bending, φ per node in torsion.
_TOWER_BLOCKS = {"tower.fa": ("fa", 2), "tower.ss": ("ss", 2), "tower.tor": ("torsion", 1)}

#: A mode whose tower bends (or twists) as an already named tower mode does — the MAC of
#: their curvatures at least this — is not the tower's next mode: the IEA-15 on its
#: VolturnUS-S has three modes of its first tower fore-aft bending mixed with the blades'
#: first flap collective and cyclic (tilt) modes, 0.47–0.61 Hz; the third, 45 % tower, was
#: called the "2nd tower fore-aft" where the tower's own second bending is at 2.5 Hz.
SAME_BENDING = 0.9


def _curvature(layout: Layout, part: str, shape: NDArray[np.complex128]) -> NDArray[np.complex128]:
    """The tower's curvature (bending: the change of slope from node to node; torsion: of
    the twist) in a mode: zero for the platform's rigid motion."""
    block, stride = _TOWER_BLOCKS[part]
    rotation = shape[getattr(layout, block)][stride - 1 :: stride]
    return np.asarray(np.diff(rotation))


def _bent_alike(
    layout: Layout, part: str, shapes: NDArray[np.complex128], j: int, before: Sequence[int]
) -> bool:
    """Whether mode j bends the tower (``part``) as one of the modes ``before`` does
    (:data:`SAME_BENDING`); a mode that does not bend it (rigid motion) is never alike."""
    if part not in _TOWER_BLOCKS or not before:
        return False
    mine = _curvature(layout, part, shapes[:, j])
    if mine.size == 0 or not np.any(np.abs(mine) > 0):
        return False
    for k in before:
        theirs = _curvature(layout, part, shapes[:, k])
        if (
            np.any(np.abs(theirs) > 0)
            and modal.mac(mine[:, None], theirs[:, None])[0, 0] >= SAME_BENDING
        ):
            return True
    return False


#: A coupled mode named the tower's k-th bending in a plane bends the tower as the tower's own
#: k-th mode in that plane does (the isolated tower, its head as the tower's modes carry it:
#: ``Model.tower_curvatures``) — the MAC of their curvatures at least this. On the IEA-15's
#: windIO VolturnUS-S a 0.74 Hz mode, 54 % the blades' first edgewise cyclic and 24 % the
#: tower rolled by the rotor's in-plane reaction (MAC 0.14 against the tower's second
#: side-side, 0.03 against its first), was named the "2nd tower side-side" and the tower's own
#: second bending at 2.80 Hz (MAC 0.87) the 3rd. wtvib's choice of threshold: the first tower
#: modes of the whole turbine, mixed with the blades, keep 0.78 and more.
OWN_BENDING = 0.5


def _bends_as_its_own(model: "Model", part: str, shape: NDArray[np.complex128], k: int) -> bool:
    """Whether a mode of shape ``shape`` bends the tower in ``part`` (fore-aft, side-side)
    as the tower's own k-th mode in that plane does (:data:`OWN_BENDING`); True where there
    is no such mode to compare with (torsion, a rigid tower, k beyond the tower's modes) or
    the mode does not bend the tower (a platform's rigid motion)."""
    own = model.tower_curvatures.get(part)
    if own is None or k > own.shape[1] or part not in _TOWER_BLOCKS:
        return True
    mine = _curvature(model.layout, part, shape)
    if mine.size != own.shape[0] or not np.any(np.abs(mine) > 0):
        return True
    return bool(modal.mac(mine[:, None], own[:, k - 1 : k].astype(complex))[0, 0] >= OWN_BENDING)


def _free_group(
    top: str,
    merged: Mapping[str, float],
    share: dict[str, Array],
    j: int,
    names: Sequence[str],
    counters: dict[str, int],
    unlike: Callable[[str], bool],
) -> str:
    """Mode j's group to be named by when its first group's name is taken (two coupled
    modes share one blade mode family's coordinate — the AOC 15/50's cyclic edge modes
    with its tower torsion, 49 % and 43 % each) or is a tower part the mode does not bend
    as the tower's next mode (``unlike``): the next group with a share of at least
    :data:`CONTENT_SHARE` whose name is free (a part's names are numbered, free where the
    mode bends the part as its next mode); else its first group (then numbered ``_2``)."""
    for group, value in sorted(merged.items(), key=lambda kv: -kv[1]):
        if group == top or value < CONTENT_SHARE:
            continue
        if group in _PARTS:
            if group in _TOWER_BLOCKS and unlike(group):
                continue
            return group
        name, _ = _mode_name(group, share, j, dict(counters), None)
        if _free_name(name, names) is not None:
            return group
    return top


def _free_name(name: str, names: Sequence[str]) -> str | None:
    """``name`` where no mode has it yet; for a cyclic mode whose axis is taken, the other
    axis of its pair (tilt ↔ yaw) where that is free; else None."""
    if name not in names:
        return name
    if name.split(".")[-1].startswith("cyclic"):
        base, axis = name.rsplit("_", 1)
        other = f"{base}_{'yaw' if axis == 'tilt' else 'tilt'}"
        if other not in names:
            return other
    return None


_PARTS = {
    "tower.fa": "tower fore-aft",
    "tower.ss": "tower side-side",
    "tower.tor": "tower torsion",
    "drivetrain": "drive-train torsion",
    "yaw": "yaw",
    "damper": "tuned mass damper",
}


def _mode_name(
    top: str, share: dict[str, Array], j: int, counters: dict[str, int], whirl: str | None
) -> tuple[str, str]:
    """Id and description of mode j, whose energy sits mostly in group ``top``."""
    if top in _PARTS:
        counters[top] = counters.get(top, 0) + 1
        k = counters[top]
        return f"{top}{k}", f"{ordinal(k)} {_PARTS[top]}"
    _, mode, coord = top.split(".")
    kind = mode.rstrip("0123456789")
    words = _blade_words(mode)
    if coord == "collective":
        return f"blade.{mode}.collective", f"{words}, collective"
    if coord == "alternating":
        return f"blade.{mode}.alternating", f"{words}, alternating (two blades in opposition)"
    h = coord.removeprefix("cyclic")
    c = share[f"blade.{mode}.cos{h}"][j] if f"blade.{mode}.cos{h}" in share else 0.0
    s = share[f"blade.{mode}.sin{h}"][j] if f"blade.{mode}.sin{h}" in share else 0.0
    # flap ∝ cos ψⱼ nods the rotor (tilt), ∝ sin ψⱼ yaws it; edge: cos pushes sideways (yaw
    # through the overhang), sin up and down (tilt)
    tilt = (c >= s) == (kind == "flap")
    axis = "tilt" if tilt else "yaw"
    suffix = "" if h == "1" else h
    name = f"blade.{mode}.cyclic{suffix}_{axis}"
    if whirl in ("forward", "backward"):
        return name, f"{words}, cyclic{suffix}"
    return name, f"{words}, cyclic{suffix} ({axis})"


def _blade_words(mode: str) -> str:
    """A blade mode in words: ``edge1`` → '1st blade edgewise'."""
    kind = mode.rstrip("0123456789")
    return f"{ordinal(int(mode[len(kind) :]))} blade {_KINDS[kind]}"


def _whirl(top: str, x: NDArray[np.complex128], groups: Mapping[str, Index]) -> str | None:
    """The whirl of a mode of shape x whose energy sits mostly in group ``top``: none for
    a tower, drive-train or yaw mode; collective, alternating; for a cyclic one, forward or
    backward where the cyclic pattern travels round the rotor, else cyclic (standing)."""
    if top in _PARTS:
        return None
    _, mode, coord = top.split(".")
    if coord in ("collective", "alternating"):
        return coord
    h = coord.removeprefix("cyclic")
    xc = x[groups[f"blade.{mode}.cos{h}"]].sum()
    xs = x[groups[f"blade.{mode}.sin{h}"]].sum()
    whirl = float(np.imag(np.conj(xc) * xs))
    scale = float(abs(xc) * abs(xs)) or 1.0
    if abs(whirl) > 0.5 * scale:  # rotating: the cyclic pattern travels round the rotor
        return "forward" if whirl < 0 else "backward"
    return "cyclic"


# ---------------------------------------------------------------------------------------
# The rotating sweep (Campbell diagram) and the audit's view


@dataclass(frozen=True)
class Sweep:
    """Coupled modes over rotor speed, each followed by its shape (MAC)."""

    omega: Array  # rotor speeds [rad/s]
    frequency_hz: Array  # (speeds, modes)
    names: tuple[str, ...]  # named at the first speed (standstill)
    descriptions: tuple[str, ...]  # at standstill and at the last speed (whirl direction)
    damping_ratio: Array  # at the first speed
    whirl: tuple[tuple[str | None, ...], ...]  # (modes, speeds): the whirl at each speed
    path: "Path"  # the modes followed (shapes at every speed): other speeds continue it


def sweep(model: "Model", speeds: Array, count: int = MODES_KEPT) -> Sweep:
    """Fixed-frame modes at each speed (three or more blades), tracked by shape."""
    if model.blades < 3:
        raise ValueError("the rotating sweep needs three or more blades (MBC)")
    path = track(model, [(float(om), None) for om in speeds], count, reduced=True)
    rpm = f"{rad_s_to_rpm(float(speeds[-1])):.3g} rpm"
    assert path.first.damping_ratio is not None
    by_mode = tuple(tuple(row[j] for row in path.whirl) for j in range(path.kept))
    by_part = tuple(tuple(row[j] for row in path.parts) for j in range(path.kept))
    names = _in_operation(path.first.names, by_mode, by_part)
    # the standstill description of the curve whose standstill name each now has
    owner = {n: path.first.descriptions[i] for i, n in enumerate(path.first.names)}
    texts = tuple(
        _described(a, b, n, n0, rpm, owner.get(n, a))
        for a, b, n, n0 in zip(
            path.first.descriptions, path.last, names, path.first.names, strict=True
        )
    )
    return Sweep(
        np.asarray(speeds, float),
        path.frequency_hz,
        names,
        texts,
        path.first.damping_ratio,
        by_mode,
        path,
    )


#: A description's ordinals ("5th tower fore-aft"): at the top speed the modes are counted
#: among every candidate root (a floating platform's rigid modes among them), so the same
#: mode may be numbered otherwise there — no change of what it is.
_ORDINAL = re.compile(r"\b\d+(st|nd|rd|th) ")
#: A description's note of a second share ("…, 42% blade.flap1.collective (named by its
#: second share)"): the same mode with or without it.
_SHARE = re.compile(r", \d+% .*$")


def _described(standstill: str, top: str, name: str, first: str, rpm: str, named: str) -> str:
    """A swept mode's description from what it is at standstill and at the top speed
    ``rpm``: one of them where they are the same mode; a cyclic mode named by its whirl in
    operation (``name`` ≠ its standstill name ``first``) says that whirl first, and what
    it has become at the top speed where a veering gave it another's character; a curve
    that took a tower mode's name (:func:`_claims`) says that mode as it is at standstill
    (``named``, the description of the curve whose name it was) first."""
    if _ORDINAL.sub("", standstill) == _ORDINAL.sub("", top):
        return f"{standstill} (coupled)"
    if name == first:
        return f"{standstill}; at {rpm}: {top} (coupled)"
    if name.startswith("tower."):
        if _ORDINAL.sub("", named) == _SHARE.sub("", _ORDINAL.sub("", top)):
            return f"{top} (coupled; at standstill: {standstill})"
        return f"{named}; at {rpm}: {top} (coupled; at standstill: {standstill})"
    family, _, coord = name.rpartition(".")
    whirl = coord.rstrip("0123456789")
    lead = re.sub(r"cyclic(\d*) \((tilt|yaw)\)", rf"cyclic\1, {whirl} whirl", standstill, count=1)
    was, _, before = first.rpartition(".")
    if family != was or (whirl == "collective") != before.startswith("collective"):
        # a veering made it another blade mode's, or a collective a whirl (or back)
        words = _blade_words(family.split(".")[1])
        harmonic = coord[len(whirl) :]
        lead = (
            f"{words}, collective"
            if whirl == "collective"
            else f"{words}, cyclic{harmonic}, {whirl} whirl"
        )
    if _SHARE.sub("", _ORDINAL.sub("", lead)) == _SHARE.sub("", _ORDINAL.sub("", top)):
        return f"{top} (coupled; at standstill: {standstill})"
    return f"{lead}; at {rpm}: {top} (coupled; at standstill: {standstill})"


def _in_operation(
    names: Sequence[str],
    whirl: Sequence[Sequence[str | None]],
    part: Sequence[Sequence[str]],
) -> tuple[str, ...]:
    """The sweep's curves named for what they are in operation: a cyclic rotor mode, named
    at standstill by the axis it turns the rotor about (``blade.flap1.cyclic_yaw``), is in
    the fixed frame a backward or a forward whirl once the rotor turns — named so
    (``blade.flap1.backward``; ``backward2`` for the second cyclic harmonic) — and a curve
    that a veering hands from one mode to another is named after what it is at most of the
    rotating speeds (:func:`_claims`): the OC3 decks with the nacelle free in yaw, whose
    first flap cyclic (yaw) mode at standstill is the edgewise backward whirl from 5 rpm on,
    as OpenFAST names it at 12.1 rpm; the windIO VolturnUS-S's first edgewise modes through
    the tower's side-side (its "collective" at 0.74 Hz is the forward whirl from 0.5 rpm on,
    its cyclic (tilt) the collective); the IEA-15 on its VolturnUS-S deck, whose tower
    fore-aft bending at standstill is the flap backward whirl from 3 rpm on, and whose
    curve that whirls backward at low speed is the tower's bending at most speeds (OpenFAST
    5 names them so at rated). A pair both of one whirl keeps its names.

    Each curve takes the first of its claims whose name is free, the first choices of all
    curves before any second: a name one curve leaves may be the one another wants; a curve
    that is the tower's bending in operation takes a tower name of that plane another curve
    has left."""
    out = list(names)
    claims = [_claims(n, w, p) for n, w, p in zip(names, whirl, part, strict=True)]
    for rank in range(max(map(len, claims), default=0)):
        for _ in range(len(names)):
            moved = False
            for j, wanted in enumerate(claims):
                if rank >= len(wanted) or any(_holds(c, out[j]) for c in wanted[:rank]):
                    continue  # no such claim, or an earlier one holds
                new = _free(wanted[rank], names, out)
                if new is not None and new != out[j]:
                    out[j], moved = new, True
            if not moved:
                break
    return tuple(out)


def _free(claim: str, names: Sequence[str], out: Sequence[str]) -> str | None:
    """The name a claim may take now: the claimed name where no curve holds it; for a tower
    plane (``tower.fa``), the first tower name of that plane a curve has left."""
    if not claim.endswith(_PLANE):
        return claim if claim not in out else None
    left = [n for n in names if n not in out and _holds(claim, n)]
    return left[0] if left else None


#: A tower plane's claim (:func:`_claims`) ends so: ``tower.fa``, ``tower.ss``.
_PLANE = (".fa", ".ss")


def _holds(claim: str, name: str) -> bool:
    """Whether a curve named ``name`` has what ``claim`` asks (a tower plane: any of its
    names)."""
    return claim == name or (claim.endswith(_PLANE) and name.rstrip("0123456789") == claim)


def _claims(name: str, whirl: Sequence[str | None], part: Sequence[str]) -> list[str]:
    """What a curve named ``name`` at standstill is in operation, in order of preference
    (:func:`_in_operation`): a blade mode's whirl (``blade.flap1.backward``) at most of the
    rotating speeds; for a blade mode's curve, the tower's bending in one plane
    (``tower.fa``, no whirl — the tower holds more of its energy than the rotor's pattern)
    at most of them, then the whirl it has at most of the speeds where it whirls at all (a
    flap whirl coupled with the tower's bending). Empty for a curve that stays what it is."""
    speeds = len(whirl) - 1
    base, _, coord = name.rpartition(".")
    blade = base.startswith("blade.") and coord.startswith(("cyclic", "collective"))
    if speeds < 1 or not (blade or base == "tower"):
        return []
    votes = [
        (p if p.startswith("blade.") else base, w)
        for w, p in zip(whirl[1:], part[1:], strict=True)
        if w in ("backward", "forward", "collective")
    ]
    tally = Counter(votes).most_common()
    out = []
    for (family, kind), count in tally:
        if count > speeds / 2 and family.startswith("blade."):
            out.append(_whirl_name(family, kind, coord if blade else ""))
    if not blade:
        return [n for n in out if n != name]
    towered = [p for w, p in zip(whirl[1:], part[1:], strict=True) if w is None]
    planes = Counter(p for p in towered if p.startswith("tower.") and p.endswith(_PLANE))
    if len(towered) > speeds / 2 and planes:
        out.append(planes.most_common(1)[0][0])
    whirling = sum(w is not None for w in whirl[1:])
    for (family, kind), count in tally[:1]:
        if count > whirling / 2:
            out.append(_whirl_name(family, kind, coord))
    return [n for n in dict.fromkeys(out) if n != name]


def _whirl_name(family: str, kind: str, coord: str) -> str:
    """``family``'s name as a ``kind`` whirl, the standstill coordinate ``coord``'s cyclic
    harmonic kept (``cyclic2_yaw`` → ``backward2``)."""
    cyclic = coord.startswith("cyclic") and kind != "collective"
    harmonic = coord.split("_")[0].removeprefix("cyclic") if cyclic else ""
    return f"{family}.{kind}{harmonic}"


def at_speeds(model: "Model", sw: Sweep, omegas: Sequence[float], reduced: bool = True) -> "Path":
    """The sweep's modes at other rotor speeds [rad/s] (the operating points'), each
    followed from the sweep's nearest speed as the sweep follows its own from speed to
    speed (:func:`track`: the shape's MAC, and its identity — whirl and part — where a
    candidate lies near) — the sweep's names and kept modes, one solve per speed;
    ``reduced``: in the sweep's Ritz basis, else in the full model. (By MAC alone, an
    operating speed inside a close veering took the pair the other way round from the
    sweep: the windIO IEA-15's first flap forward and edge backward whirls, 1 % apart at
    6.7 rpm.)"""
    path = sw.path
    m = model.multiblade[0]
    weight = np.sqrt(np.diag(m))[:, None]
    part = np.array(parts(model, m, path.first.shapes), dtype=object)
    freqs = np.empty((len(omegas), path.kept))
    zetas = np.empty((len(omegas), path.kept))
    shapes = []
    basis = path.basis if reduced else 0
    points = [(float(om), None) for om in omegas]
    found = _candidates(model, points, path.first.span + TRACK_SPARE, basis, path.kept)
    for i, (om, cur) in enumerate(zip(omegas, found, strict=True)):
        near = int(np.argmin(np.abs(sw.omega - om)))
        kinds, where = whirls_and_parts(model, m, cur.shapes)
        mac = modal.mac(weight * path.shapes[near], weight * cur.shapes)
        same = _same_kind(path.whirl[near], kinds) + np.equal.outer(
            part, np.array(where, dtype=object)
        )
        step = float(om) - float(sw.omega[near])
        score = _identity_score(mac, same, path.frequency_hz[near], cur.frequency_hz, step)
        order = modal.assign(score, optimal=True)
        assert cur.damping_ratio is not None
        freqs[i], zetas[i] = cur.frequency_hz[order], cur.damping_ratio[order]
        shapes.append(cur.shapes[:, order])
    return Path(path.first, freqs, zetas, (), (), tuple(shapes), basis)


@dataclass(frozen=True)
class Path:
    """Modes along a path of rotor speeds (and added matrices), followed by shape from the
    first point's modes."""

    first: SystemModes  # at the first point: the names
    frequency_hz: Array  # (points, modes): |λ|/2π
    damping_ratio: Array  # (points, modes): −Re λ/|λ|
    last: tuple[str, ...]  # descriptions at the last point
    whirl: tuple[tuple[str | None, ...], ...]  # (points, modes)
    shapes: tuple[NDArray[np.complex128], ...]  # (points): each (coordinates, modes)
    basis: int = 0  # the standstill modes of the Ritz basis it was followed in (0: none)
    parts: tuple[tuple[str, ...], ...] = ()  # (points, modes): the part each mode is in (parts)

    @property
    def kept(self) -> int:
        return len(self.first.frequency_hz)


def track(
    model: "Model",
    points: list[tuple[float, Extra | None]],
    count: int = MODES_KEPT,
    reduced: bool = False,
) -> Path:
    """Modes at each (Ω, extra matrices) point, each followed from the point before by
    mass-weighted MAC (modal.track), with the whirl at every point and the descriptions at
    the last; ``reduced``: the points after the first in the model's Ritz basis
    (RITZ_STANDSTILL); the first, where the modes followed are chosen, in one of as many
    standstill modes as the search by content sees."""
    wide = count + _spare(count) if reduced else 0  # as many as the search by content sees
    first = rotating(model, points[0][0], count, points[0][1], reduced=wide, by_content=True)
    basis = max(RITZ_STANDSTILL, first.span + TRACK_SPARE) if reduced else 0
    kept = len(first.frequency_hz)
    # shapes compared mass-weighted (√diag M): metres of tower and modal blade coordinates
    # would otherwise weigh by their units, not by their share of the motion
    weight = np.sqrt(np.diag(model.multiblade[0]))[:, None]
    freqs = np.empty((len(points), kept))
    zetas = np.empty((len(points), kept))
    freqs[0] = first.frequency_hz
    assert first.damping_ratio is not None
    zetas[0] = first.damping_ratio
    shapes = first.shapes
    every = [shapes]
    last = first.descriptions
    whirl = [list(first.whirl)]
    m = model.multiblade[0]
    # what each mode is — where its energy sits and its whirl — as its id says it: a mode
    # keeps that identity through a crossing, where two modes mix for a point or two and
    # the last point's parts would hand the one's name to the other
    part = np.array(parts(model, m, shapes), dtype=object)
    where_all = [tuple(part.tolist())]
    kind: list[str | None] = list(first.whirl)
    found = _candidates(model, points[1:], first.span + TRACK_SPARE, basis, kept)
    for i, cur in enumerate(found, start=1):
        kinds, where = whirls_and_parts(model, m, cur.shapes)
        mac = modal.mac(weight * shapes, weight * cur.shapes)
        same = _same_kind(kind, kinds) + np.equal.outer(part, np.array(where, dtype=object))
        step = points[i][0] - points[i - 1][0]
        score = _identity_score(mac, same, freqs[i - 1], cur.frequency_hz, step)
        order = modal.assign(score, optimal=True)
        # a standing cyclic pair becomes a backward and a forward whirl once the rotor
        # turns: the whirl it first takes is its identity from then on
        kind = [kinds[o] if k == "cyclic" else k for k, o in zip(kind, order, strict=True)]
        freqs[i] = cur.frequency_hz[order]
        assert cur.damping_ratio is not None
        zetas[i] = cur.damping_ratio[order]
        shapes = cur.shapes[:, order]
        every.append(shapes)
        whirl.append([kinds[o] for o in order])
        where_all.append(tuple(where[o] for o in order))
        if i == len(points) - 1:  # named with every candidate, so that "2nd" counts the
            texts = _name(model, m, cur.shapes)[1]  # same modes wherever it is asked
            last = tuple(texts[o] for o in order)
    return Path(
        first,
        freqs,
        zetas,
        last,
        tuple(tuple(w) for w in whirl),
        tuple(every),
        basis,
        tuple(where_all),
    )


#: How much a mode keeping its kind (collective, backward or forward whirl, not a rotor
#: mode) weighs against its shape's MAC when a path follows it to the next speed: a
#: collective and a cyclic mode that cross in frequency are orthogonal in shape, and the
#: optimal assignment must not swap them where the crossing blurs their MAC (the NREL
#: 5-MW's flap forward whirl crosses its collective near 2 rpm).
KIND_WEIGHT = 1.0


#: A mode's identity — its whirl and the part its energy sits in (:data:`KIND_WEIGHT`) — passes
#: only to a candidate near its frequency at the point before: at a crossing the two modes
#: lie close, their shapes mix and their MACs blur, and identity decides; a candidate
#: farther off is another mode, however alike its kind and part. Near is within what one
#: step of the sweep can move two crossing modes apart: each whirl moves with the rotor
#: speed (a cyclic mode of the first harmonic by ΔΩ/2π, of the second by 2ΔΩ/2π), so
#: IDENTITY_SPEEDS × ΔΩ/2π, and IDENTITY_BAND of the frequency for the stiffening and the
#: veering gap. (The IEA-22 semi's first tower fore-aft mode couples with the flap backward
#: whirl from 3.5 rpm on, with more energy in the blades than in the tower there: its part
#: alone handed the curve to a tower mode at 6.9 Hz with a MAC of 0.04; its second edge
#: forward whirl, half tower side-side near 1.7 Hz, to the next tower mode 9 % up. The NREL
#: 5-MW's flap forward whirl and collective cross 2 % apart, 0.014 Hz, where the band is
#: 0.038 Hz.)
IDENTITY_BAND = 0.02
IDENTITY_SPEEDS = 3.0


def _identity_score(
    mac: Array, same: Array, before: Array, candidates: Array, step: float
) -> Array:
    """The score a path step assigns by: MAC plus KIND_WEIGHT for each identity held
    (``same``: 0 … 2), counted only for candidates near the mode's frequency ``before``
    [Hz] (``candidates``: theirs; ``step``: the rotor speed's change [rad/s])."""
    band = IDENTITY_BAND * before + IDENTITY_SPEEDS * abs(step) / (2 * np.pi)
    near = np.abs(candidates[None, :] - before[:, None]) <= band[:, None]
    return np.asarray(mac + KIND_WEIGHT * np.where(near, same, 0.0))


def _same_kind(before: Sequence[str | None], now: Sequence[str | None]) -> Array:
    """1 where a mode of kind ``before[i]`` may continue as candidate ``now[j]``: the same
    kind, or a standing cyclic mode (standstill) turning into a whirl (and back)."""
    cyclic = {"cyclic", "backward", "forward"}

    def fits(a: str | None, b: str | None) -> bool:
        return a == b or (a in cyclic and b in cyclic and "cyclic" in (a, b))

    return np.array([[1.0 if fits(a, b) else 0.0 for b in now] for a in before])


def _candidates(
    model: "Model",
    points: Sequence[tuple[float, Extra | None]],
    count: int,
    basis: int,
    kept: int,
) -> list[SystemModes]:
    """The roots a path's points after the first choose their ``kept`` modes from (the
    lowest ``count``), overdamped ones among them (a followed mode damped past critical
    keeps its place, with ζ = 1): solved in the Ritz basis of ``basis`` standstill modes,
    all points as one stack, or in full at a point where that basis holds fewer roots than
    the path follows (a damper far out of range squeezes roots towards zero). Fewer in the
    full model too: a mode fell below 1 mHz — ModalError."""
    out = []
    for (omega, extra), (lam, vec) in zip(points, _roots(model, points, basis, True), strict=True):
        if len(lam) < kept and basis:
            ((lam, vec),) = _roots(model, [(omega, extra)], 0, True)
        if len(lam) < kept:
            raise modal.ModalError(
                f"the coupled model keeps {len(lam)} of its {kept} modes at "
                f"{rad_s_to_rpm(omega):.3g} rpm (the others slower than 1 mHz): a damper or "
                "a stiffness far out of range?"
            )
        out.append(_selected(lam, vec, np.arange(min(count, len(lam)))))
    return out


def _overlap(model: "Model", a: NDArray[np.complex128], b: NDArray[np.complex128]) -> Array:
    """Similarity of modes by where their kinetic energy sits, coordinate by coordinate
    (Bhattacharyya overlap of the mass-weighted |x|² distributions): blind to phase, so a
    whirling structural mode and its overdamped, standing aeroelastic form still match."""
    weight = np.diag(model.multiblade[0])[:, None]

    def dist(x: NDArray[np.complex128]) -> Array:
        e = weight * np.abs(x) ** 2
        return np.asarray(e / np.maximum(e.sum(axis=0, keepdims=True), 1e-300))

    return np.sqrt(dist(a)).T @ np.sqrt(dist(b))


def matched(
    model: "Model",
    points: Sequence[tuple[float, Extra]],
    references: Sequence[NDArray[np.complex128]],
    spare: int = 24,
    reduced: int = 0,
    frequencies: Sequence[Array] | None = None,
    names: Sequence[str] | None = None,
) -> list[tuple[Array, Array, Array]]:
    """At each (Ω, extra matrices) point, |λ|/2π and ζ of the modes with the extra matrices,
    each matched to a column of that point's reference (the structural modes at the same
    speed) by shape and by where its energy sits (:func:`_overlap`): one assignment per
    point, so a heavily damped mode cannot hand its name along a chain. The points are in
    wind order: a damped mode also continues the one matched at the point before
    (:data:`CONTINUED` of MAC), so that where two damped modes resemble one structural mode
    alike (a lightly damped edgewise mode beside a flap mode damped tens of per cent, both
    near 0.6 Hz) the curve keeps the mode it had. The third array is each match's score:
    MAC + overlap with the reference (0 … 2), or — where the damped mode continues the one
    before it with a MAC of at least :data:`CONTINUED` — that continuity's 2·MAC.
    ``frequencies``: the structural modes' at each point [Hz]; a lightly damped root
    (ζ < :data:`LIGHT`) farther than :data:`RETUNED` from its mode's frequency is not that
    mode, whatever its shape: its score is lowered by 2, and it is neither continued nor
    continues a match. ``names``: the modes' ids; the assignment then also weighs each
    root's energy share in the part its mode is named after (:func:`_named_share`) — where
    the aerodynamics splits two structural modes that mix one part with another (the
    IEA-15's second tower side-side and second backward flap whirl, 40 % tower each, into
    a root 70 % tower with ζ 0.01 and one 91 % blade with ζ 0.39), the tower's id goes with
    the tower's root — and a root with its energy in a tower's, drive train's or yaw
    system's named part (one direction of motion, unlike a blade mode's, which holds every
    whirl) scores 1 + that share where more than half its energy is there and MAC +
    overlap is lower: a majority in the mode's own direction is as good a match as MAC +
    overlap of 1.5 (a tower mode the structure mixes with a flap whirl at the same
    frequency, the damped root unmixed: the IEA-10's first fore-aft at 4 m/s, 96 % tower,
    MAC + overlap 1.0; the IEA-15's second side-side, 70 % tower, 1.40 — their first-order
    damping, of the mixed structural mode, was 0.46 and 0.13 against the roots' 0.066 and
    0.010). A root continuing the match before also lies near its eigenvalue
    (:func:`_continuity`). All points solved as one stack."""
    kept = references[0].shape[1]
    weight = np.sqrt(np.diag(model.multiblade[0]))[:, None]
    out = []
    found = _candidates(model, points, kept + spare, reduced, kept)
    named = _named_groups(model, names) if names is not None else None
    # the modes whose named part is one direction of motion (not a blade mode, whose part
    # holds every whirl of it): a root with its energy there stands for the mode
    directional = np.array([not n.startswith("blade.") for n in names or ()], dtype=float)
    before: NDArray[np.complex128] | None = None
    last = np.zeros(kept, dtype=complex)  # the matches' eigenvalues at the point before
    held = np.zeros(kept, dtype=bool)  # the matches at the point before that may continue
    for k, (reference, cur) in enumerate(zip(references, found, strict=True)):
        # shape (MAC: tells a forward from a backward whirl) plus where the energy sits
        # (blind to phase: keeps an overdamped, standing form with its whirling origin)
        score = modal.mac(weight * reference, weight * cur.shapes) + _overlap(
            model, reference, cur.shapes
        )
        assert cur.damping_ratio is not None
        retuned = (
            _retuned(frequencies[k], cur.frequency_hz, cur.damping_ratio)
            if frequencies is not None
            else np.zeros_like(score)
        )
        score = score - 2.0 * retuned
        lam = modal.eigenvalue(cur.frequency_hz, cur.damping_ratio)
        kin, jump = _continuity(weight, before, last, held, cur.shapes, lam, retuned)
        part = _named_share(model, named, cur.shapes) if named is not None else 0.0
        order = modal.assign(score + kin + part - jump, optimal=True)
        last = lam[order]
        assert cur.damping_ratio is not None
        rows = np.arange(kept)
        best = np.maximum(
            score[rows, order], np.where(kin[rows, order] >= CONTINUED, 2 * kin[rows, order], 0.0)
        )
        if named is not None:  # a tower's or drive train's root is where its energy sits
            own = np.asarray(part)[rows, order] * directional * (retuned[rows, order] == 0.0)
            best = np.where(own > 0.5, np.maximum(best, 1.0 + own), best)
        before, held = cur.shapes[:, order], retuned[rows, order] == 0.0
        out.append((cur.frequency_hz[order], cur.damping_ratio[order], best))
    return out


def _continuity(
    weight: Array,
    before: NDArray[np.complex128] | None,
    last: NDArray[np.complex128],
    held: NDArray[np.bool_],
    shapes: NDArray[np.complex128],
    lam: NDArray[np.complex128],
    retuned: Array,
) -> tuple[Array, Array]:
    """(modes, roots): how each root continues each mode's match at the point before — the
    MAC with its shape ``before`` (where the match may continue: ``held``, not ``retuned``)
    — and how far it lies from that match's eigenvalue ``last``, |λ − λ_before|/|λ_before|,
    which the assignment deducts: roots move continuously with the wind (where a heavily
    damped flap whirl splits into an oscillating root and a creeping one of the same shape,
    the IEA-22's forward flap whirl took the creeping one, 0.32 Hz at ζ 0.98, 70 % of |λ|
    away, beside the oscillating one 12 % away — the backward and collective whirls kept
    theirs); zeros at the first point."""
    if before is None or before.shape[0] != shapes.shape[0]:
        return np.zeros_like(retuned), np.zeros_like(retuned)
    kin = modal.mac(weight * before, weight * shapes) * held[:, None] * (1.0 - retuned)
    scale = np.maximum(np.abs(last[:, None]), 1e-12)
    jump = np.abs(lam[None, :] - last[:, None]) / scale * held[:, None]
    return np.asarray(kin), np.asarray(jump)


def _named_groups(model: "Model", names: Sequence[str]) -> list[NDArray[np.intp]]:
    """Each mode id's coordinates: those of the part it is named after (``tower.ss2`` →
    the tower's side-side coordinates, ``blade.flap2.backward`` → every multi-blade
    coordinate of the blade's flap2 mode, ``drivetrain…``, ``yaw…``); none for an id no
    coordinate group names."""
    groups = model.groups
    out = []
    for name in names:
        head = name.split(".")
        if head[0] == "blade" and len(head) > 1:
            keys = [g for g in groups if g.startswith(f"blade.{head[1]}.")]
        elif head[0] == "tower" and len(head) > 1:
            stem = head[1].rstrip("0123456789")
            keys = [f"tower.{stem}"] if f"tower.{stem}" in groups else []
        else:
            keys = [head[0]] if head[0] in groups else []
        out.append(
            np.concatenate([groups[k] for k in keys]).astype(np.intp)
            if keys
            else np.zeros(0, dtype=np.intp)
        )
    return out


def _named_share(
    model: "Model", named: list[NDArray[np.intp]], shapes: NDArray[np.complex128]
) -> Array:
    """(modes, roots): each root's kinetic-energy share in the coordinates of each mode's
    named part (:func:`_named_groups`)."""
    return _fractions(_energy(model.multiblade[0], shapes), named)


#: A damped mode whose shape continues the one matched at the wind before with at least
#: this MAC is the same mode, however little it resembles the structural one there.
CONTINUED = 0.9

#: A root damped less than LIGHT keeps its mode's frequency within a factor RETUNED: the
#: aerodynamic stiffness moves a lightly damped mode by tens of per cent at most (the flap
#: modes' aeroelastic frequencies lie 16–24 % above the structural ones in wtvib's
#: quasi-steady model of the NREL 5-MW, OpenFAST's own within a few per cent), never
#: threefold with its damping unchanged — a root that does is another mode whose energy
#: sits in the same coordinates (the IEA-22's first edgewise collective, 1.10 Hz, was
#: matched to an undamped root at 3.25 Hz, and its damping reported as −0.000). A heavily
#: damped root may lie farther off (its |λ| is no longer an oscillation's frequency), but
#: not by RETUNED_DAMPED: the IEA-22 monopile's stiff drive-train torsion (94 Hz) was
#: matched to the free generator's creeping root (6 mHz, ζ = 1).
LIGHT = 0.3
RETUNED = 1.5
RETUNED_DAMPED = 10.0


def _retuned(structural: Array, candidates: Array, zeta: Array) -> Array:
    """1 where a candidate root (frequency, ζ) cannot be the structural mode of a row: it
    lies more than RETUNED off that mode's frequency lightly damped, RETUNED_DAMPED
    otherwise; else 0."""
    ratio = np.abs(np.log(np.maximum(candidates[None, :], 1e-12) / structural[:, None]))
    limit = np.where(zeta < LIGHT, math.log(RETUNED), math.log(RETUNED_DAMPED))[None, :]
    return np.asarray(ratio > limit, dtype=float)


def perturbed(
    model: "Model",
    omega: float,
    extra: Extra,
    reference: NDArray[np.complex128],
    lam: NDArray[np.complex128],
) -> Array:
    """ζ of each reference mode (eigenvalue ``lam``, shape x) with ``extra`` damping D and
    stiffness K′ added, to first order: Δλ = −xᴴ(λD + K′)x / xᴴ(2λM + G)x (the left
    eigenvector of a gyroscopic system is x̄; G: the structural damping matrix); lift lag
    states add their force at λ, F·(λ − S)⁻¹·(P + λV)."""
    m, d0, d1, _, _ = model.multiblade
    g = d0 + omega * d1
    d, k = extra[0], extra[1]
    x = reference
    # the extra matrices on the model's coordinates or on Model.active: the shapes there
    xe = x if d.shape[-1] == model.layout.size else x[model.active]

    def quad(a: Array, y: NDArray[np.complex128] = x) -> NDArray[np.complex128]:
        return np.asarray(np.sum(y.conj() * (a @ y), axis=0))  # yⱼᴴ A yⱼ, every column

    num = lam * quad(d, xe) + quad(k, xe)
    if len(extra) > 2:
        lag: LiftLag = extra[2]
        eye = np.eye(lag.rates.shape[-1])
        for j, lj in enumerate(lam):
            states = np.linalg.solve(
                lj * eye - lag.rates, (lag.on_position + lj * lag.on_rate) @ xe[:, j]
            )
            num[j] += xe[:, j].conj() @ (lag.force @ states)
    den = 2 * lam * quad(m) + quad(g)
    new = lam - num / den
    return modal.damping_ratio(new)
