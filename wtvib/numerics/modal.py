"""The one generic eigen-solver and mode tracking, shared by every structural model.

* :func:`solve` — the generalised symmetric problem K φ = ω² M φ (undamped modes);
* :func:`oscillations` — the damped (state-space) roots, refused where they fall below
  rounding;
* :func:`ritz_basis` — a reduced basis that follows a problem as parameters change it;
* :func:`mac` and :func:`track` — modal assurance criterion and following modes across a
  parameter sweep by shape similarity rather than by sorting frequencies.

References
----------
R. J. Allemang, "The modal assurance criterion — twenty years of use and abuse", Sound and
Vibration 37(8), 2003 (MAC).
"""

import contextlib
import itertools
import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import WtvibError

Array = NDArray[np.float64]


class ModalError(WtvibError, ArithmeticError):
    """A structural model whose eigenproblem has no physical solution (e.g. not stable)."""


#: Threads a stack of independent problems is shared out over (:func:`set_threads`): 1 for
#: wtvib used as a library; a command that audits one turbine sets its cores.
_threads = 1
#: A stack is shared out only where each thread gets at least this many of its problems
#: and they are at least this size: a thread's start costs what a 30 × 30 solve does.
STACK_PER_THREAD, STACK_SIZE = 4, 40


def set_threads(count: int) -> None:
    """Share a stack of eigenproblems (a sweep's speeds, an operating schedule's points) out
    over ``count`` threads. numpy's LAPACK calls let go of the interpreter, and each problem
    is solved alone as before, one BLAS thread each: the same bits whatever the count (a
    test) — only sooner where there are cores to spare (bench/RESULTS.md)."""
    global _threads
    _threads = max(1, int(count))


def _each(solver: Any, stack: Any) -> Any:
    """``solver`` (a numpy.linalg function of a stack) of ``stack``, shared out over the
    threads :func:`set_threads` allows: its result as one call gives it."""
    count, size = stack.shape[0], stack.shape[-1]
    threads = min(_threads, count // STACK_PER_THREAD)
    if threads <= 1 or size < STACK_SIZE:
        return solver(stack)
    from concurrent.futures import ThreadPoolExecutor

    cuts = np.linspace(0, count, threads + 1).astype(int)
    with ThreadPoolExecutor(threads) as pool:  # joined here: no thread outlives the call
        parts = list(pool.map(lambda a, b: solver(stack[a:b]), cuts[:-1], cuts[1:]))
    if isinstance(parts[0], tuple):  # eig, eigh: (values, vectors), each joined
        joined = [np.concatenate(found) for found in zip(*parts, strict=True)]
        kind = type(parts[0])  # numpy's EigResult, EighResult: named as one call's
        return kind(*joined) if hasattr(kind, "_fields") else tuple(joined)
    return np.concatenate(parts)


@dataclass(frozen=True)
class Modes:
    """Natural frequencies [Hz] (ascending) and mass-normalised shapes (columns)."""

    frequency_hz: Array
    shapes: Array


def solve(k: Array, m: Array, count: int | None = None) -> Modes:
    """Lowest ``count`` modes of K φ = ω² M φ (K, M symmetric, M positive definite).

    Notes
    -----
    Shifted and inverted (the spectral transformation of Ericsson & Ruhe, "The spectral
    transformation Lanczos method", Math. Comp. 35, 1980): with the Cholesky factor of
    K + σM = L Lᵀ (σ = SHIFT), the standard symmetric problem (L⁻¹ M L⁻ᵀ) y = μ y, whose
    largest μ = 1/(ω² + σ) are the lowest modes, φ = L⁻ᵀ y; done with numpy so that a check
    never has to import scipy.linalg (a third of a second). Its rounding is relative to the
    largest μ, so that the lowest modes keep their own precision however stiff the model's
    highest (ε·(ω² + σ)²/(σ·ω²), :data:`SHIFT`). The reduction with M's factor
    (L⁻¹ K L⁻ᵀ, LAPACK's ``sygv``) rounds every ω² to ε times the highest: a tower and
    monopile of 200 elements (ω²_max ≈ 10¹²) had its lowest coupled modes 5·10⁻⁵ off, a
    cantilever with ten 1-mm elements among 0.5-m ones its first two +4.5 % and +38 %
    (tests/validation/test_structure.py).

    Raises
    ------
    ModalError
        M is not positive definite, or K has a clearly negative eigenvalue (a structure that
        buckles under its loads, e.g. gravity on an over-soft tower).
    """
    return solve_stacked(k[None], m[None], count)[0]


def lowest(modes: Modes, count: int) -> Modes:
    """The lowest ``count`` of solved modes (all of them, if fewer): what :func:`solve` with
    that count gives (it solves the whole problem and keeps the first)."""
    return Modes(modes.frequency_hz[:count], modes.shapes[:, :count])


#: the message where a model's matrices leave the range of floating point
OUT_OF_RANGE = (
    "the model's numbers leave the range of floating point (a mass or inertia far too small "
    "for its stiffness, or a stiffness far too large): check the magnitudes in the input"
)


def solve_stacked(k: Array, m: Array, count: int | None = None) -> list[Modes]:
    """:func:`solve` for a stack of same-sized problems, shape (p, n, n), in one call."""
    shifted = _shifted_form(k, m)
    if shifted is None:  # an eigenvalue below −σ: buckling, or rounding of one far stiffer
        a, inv_t = _standard_form(k, m)
        w2, y = _each(np.linalg.eigh, a)
    else:
        a, inv_t = shifted
        mu, y = _each(np.linalg.eigh, a)
        w2, y = _unshifted(mu[:, ::-1]), y[:, :, ::-1]
    _check_stable(w2)
    top = w2.shape[-1] if count is None else min(count, w2.shape[-1])
    hz = np.sqrt(np.clip(w2[:, :top], 0.0, None)) / (2.0 * np.pi)
    shared = _repeated(w2)  # a repeated eigenvalue's shapes: one basis, not rounding's
    wide = _cluster_end(shared, top) if top else 0
    shapes = _normalised(inv_t @ y[:, :, :wide], m)
    for i in np.flatnonzero(shared[:, : max(wide - 1, 0)].any(axis=1)):
        shapes[i] = _one_basis(shapes[i], m[i], shared[i, : wide - 1])
    return [Modes(hz[i], shapes[i, :, :top]) for i in range(len(w2))]


#: Eigenvalues closer than this share of their size (and of σ) are one to the solve's
#: rounding (ε·(ω² + σ)²/(σ·ω²), 10⁻¹³–10⁻¹¹ where shapes matter): their shapes are any
#: basis of the space they span, and rounding picked one — another machine another.
REPEATED = 1e-10


def _repeated(w2: Array) -> NDArray[np.bool_]:
    """For a stack's ascending ω² (p, n): whether each one and the next are one (p, n)."""
    close = np.zeros(w2.shape, dtype=bool)
    close[:, :-1] = np.diff(w2, axis=1) <= REPEATED * (np.abs(w2[:, 1:]) + SHIFT)
    return close


def _cluster_end(shared: NDArray[np.bool_], top: int) -> int:
    """Past the last mode of every stack's cluster that holds mode ``top`` − 1."""
    end = top
    while end < shared.shape[1] and shared[:, end - 1].any():
        end += 1
    return end


def _one_basis(phi: Array, m: Array, shared: NDArray[np.bool_]) -> Array:
    """``phi`` (n, k: M-normalised shapes) with each run of repeated eigenvalues (``shared``
    (k − 1,): each with the next) given the one basis its space has whatever the rounding:
    the coordinates the space moves most picked by column-pivoted QR of its rows (their
    norms are the same for every basis of it), each shape 1 at its own and 0 at the
    others', then M-orthonormalised in the coordinates' order — a symmetric floater's surge
    and sway each along its axis, a round blade's flap and edge each in its plane, a rigid
    rotor's collective and cyclic flap each its own coordinate, in their order."""
    out = phi.copy()
    start = 0
    for j in range(len(shared) + 1):
        if j < len(shared) and shared[j]:
            continue
        if j > start:
            # shapes rounding cannot resolve (no pivot block to invert): left as found
            with contextlib.suppress(np.linalg.LinAlgError):
                out[:, start : j + 1] = _aligned(phi[:, start : j + 1], m)
        start = j + 1
    return out


def _aligned(v: Array, m: Array) -> Array:
    """:func:`_one_basis` of one space (the columns of ``v``)."""
    k = v.shape[1]
    rest, pivots = v.copy(), []
    for _ in range(k):
        norms = np.einsum("ij,ij->i", rest, rest)
        p = int(np.flatnonzero(norms >= (1.0 - 1e-8) * norms.max())[0])  # a tie: the first
        pivots.append(p)
        q = rest[p] / np.linalg.norm(rest[p])
        rest = rest - np.outer(rest @ q, q)
    pivots.sort()  # in the coordinates' order: a space of coordinates comes back as they are
    w = v @ np.linalg.inv(v[pivots, :])  # 1 at its own coordinate, 0 at the others'
    lower = np.linalg.cholesky(w.T @ m @ w)
    return np.asarray(w @ np.linalg.inv(lower).T)


def frequencies_stacked(k: Array, m: Array, count: int, *, unstable_as_nan: bool = False) -> Array:
    """The lowest ``count`` natural frequencies [Hz] of each problem of a stack, shape
    (p, count): :func:`solve_stacked` without the mode shapes (eigenvalues only, half the
    work — the Monte Carlo samples' path). A problem that buckles raises, or with
    ``unstable_as_nan`` comes back as NaN (a sample among many may buckle)."""
    shifted = _shifted_form(k, m)
    if shifted is None:
        w2 = np.asarray(np.linalg.eigvalsh(_standard_form(k, m)[0]), dtype=float)
    else:
        w2 = _unshifted(np.asarray(np.linalg.eigvalsh(shifted[0]), dtype=float)[:, ::-1])
    if not unstable_as_nan:
        _check_stable(w2)
    hz = np.sqrt(np.clip(w2[:, :count], 0.0, None)) / (2.0 * np.pi)
    hz[_unstable(w2)] = np.nan
    return np.asarray(hz)


#: the message where a mass matrix has no Cholesky factor
NOT_POSITIVE = "the mass matrix is not positive definite (a zero or negative mass or inertia?)"


def _require_finite(k: Array, m: Array) -> None:
    """A ModalError where K or M holds NaN or an infinity."""
    if not (np.all(np.isfinite(k)) and np.all(np.isfinite(m))):
        raise ModalError("the structural matrices hold NaN or infinite values")


#: The spectral shift σ [rad²/s²] of :func:`solve`, a frequency of 0.16 Hz: K + σM is
#: positive definite for a stable structure, even where K is singular (a free rotor, a
#: floater), and the rounding of ω² is ε·(ω² + σ)²/(σ·ω²) relative — 10⁻¹³ at a floater's
#: surge of 0.008 Hz, 10⁻⁹ at 500 Hz — over every frequency a wind turbine has.
SHIFT = 1.0


def _shifted_form(k: Array, m: Array) -> tuple[Array, Array] | None:
    """L⁻¹ M L⁻ᵀ (symmetrised) and L⁻ᵀ for a stack, K + σM = L Lᵀ; None where K + σM has
    no Cholesky factor (an eigenvalue below −σ). ModalError where M is not positive
    definite or the numbers leave floating point."""
    _require_finite(k, m)
    try:
        np.linalg.cholesky(m)
    except np.linalg.LinAlgError:
        raise ModalError(NOT_POSITIVE) from None
    with np.errstate(over="ignore", invalid="ignore"):
        shifted = k + SHIFT * m
    try:
        lower = np.linalg.cholesky(shifted)
    except np.linalg.LinAlgError:
        return None
    inv = _inverse_lower(np.asarray(lower, dtype=float))
    inv_t = np.swapaxes(inv, -1, -2)
    with np.errstate(over="ignore", invalid="ignore"):
        a = inv @ m @ inv_t
    if not (np.all(np.isfinite(a)) and np.all(np.isfinite(inv_t))):
        raise ModalError(OUT_OF_RANGE)
    return 0.5 * (a + np.swapaxes(a, -1, -2)), inv_t


def _unshifted(mu: Array) -> Array:
    """ω² = 1/μ − σ of a stack's μ (descending). A μ within rounding of zero (a mode
    stiffer than ε can tell from the rest, ω² above 10¹⁵·(ω₁² + σ)) is taken at that
    floor, n·ε·μ_max: ω² at the largest the problem can resolve."""
    floor = mu.shape[-1] * np.finfo(float).eps * mu[..., :1]
    return np.asarray(1.0 / np.maximum(mu, floor) - SHIFT)


def _normalised(phi: Array, m: Array) -> Array:
    """A stack's shapes scaled to φᵀ M φ = 1."""
    return np.asarray(phi / np.sqrt(np.einsum("pij,pij->pj", phi, m @ phi))[:, None, :])


def _standard_form(k: Array, m: Array) -> tuple[Array, Array]:
    """L⁻¹ K L⁻ᵀ (symmetrised) and L⁻ᵀ for a stack, M = L Lᵀ: where K + σM has no
    Cholesky factor, the reduction that finds the negative eigenvalue to report."""
    _require_finite(k, m)
    try:
        lower = np.linalg.cholesky(m)
    except np.linalg.LinAlgError:
        raise ModalError(NOT_POSITIVE) from None
    inv = _inverse_lower(np.asarray(lower, dtype=float))
    inv_t = np.swapaxes(inv, -1, -2)
    with np.errstate(over="ignore", invalid="ignore"):
        a = inv @ k @ inv_t
    if not np.all(np.isfinite(a)):
        raise ModalError(OUT_OF_RANGE)
    return 0.5 * (a + np.swapaxes(a, -1, -2)), inv_t


#: A stack at least this many times deeper than its matrices are wide is inverted row by
#: row across the stack (the Monte Carlo samples: 2,000 problems of 6 × 6).
DEEP_STACK = 16


def _inverse_lower(lower: Array) -> Array:
    """L⁻¹ of a stack of lower-triangular matrices. A deep stack of small ones by forward
    substitution, one row of all the inverses at a time (n vectorised steps, about four
    times faster for thousands of 6 × 6 than numpy's general inverse, a LAPACK call per
    matrix);
    any other by numpy's inverse."""
    n = lower.shape[-1]
    if lower.ndim != 3 or lower.shape[0] < DEEP_STACK * n:
        return np.asarray(np.linalg.inv(lower))
    out = np.zeros_like(lower)
    diagonal = np.diagonal(lower, axis1=-2, axis2=-1)
    for i in range(n):  # row i: (e_i − L[i, :i] · X[:i, :]) / L[i, i]
        row = -np.einsum("pk,pkj->pj", lower[:, i, :i], out[:, :i, :])
        row[:, i] += 1.0
        out[:, i, :] = row / diagonal[:, i, None]
    return out


def _unstable(w2: Array) -> NDArray[np.bool_]:
    """Which problems of a stack have a clearly negative lowest eigenvalue (they buckle)."""
    scale = np.maximum(np.abs(w2).max(axis=-1, initial=0.0), 1.0)
    return np.asarray(w2[:, 0] < -1e-8 * scale)


def _check_stable(w2: Array) -> None:
    """ModalError where a problem's lowest eigenvalue is clearly negative (it buckles)."""
    unstable = np.flatnonzero(_unstable(w2))
    if unstable.size:
        raise ModalError(
            f"the structure is unstable (negative stiffness eigenvalue "
            f"{w2[unstable[0], 0]:.3g}): check stiffnesses and masses"
        )


def ritz_basis(
    k: Array, m: Array, count: int, changes: list[Array], images: int, modes: Modes | None = None
) -> Array:
    """An M-orthonormal Rayleigh–Ritz basis for K φ = ω² M φ as other terms change it: the
    lowest ``count`` modes and, for each change matrix C (a term the undamped modes leave
    out: a damper, the rotor's Ω² stiffness, its Ω damping), what the lowest ``images``
    modes' loads C φ excite beyond those modes — the static response (K + σM)⁻¹ r to the
    part r of each load the kept modes do not carry (modal truncation augmentation:
    Dickens, Nakagawa & Wittbrodt, "A critique of mode acceleration and modal truncation
    augmentation methods for modal response analysis", Comput. Struct. 62, 1997). A vector
    that adds no new direction (a load the kept modes carry whole) is dropped.

    σ > 0 makes K + σM invertible where K is singular (a free rotor on its shaft): the
    squared circular frequency of the highest mode imaged. ``modes``: K and M's lowest modes,
    where already solved (at least ``count`` of them, or all the problem has).
    """
    base = solve(k, m, min(count, k.shape[0])) if modes is None else lowest(modes, count)
    phi = base.shapes
    if not changes or images <= 0 or phi.shape[1] == k.shape[0]:
        return phi
    top = min(images, phi.shape[1])
    sigma = max(float(2 * np.pi * base.frequency_hz[top - 1]) ** 2, 1.0)
    loads = np.concatenate([c @ phi[:, :top] for c in changes], axis=1)
    rest = loads - m @ (phi @ (phi.T @ loads))  # the force the kept modes do not carry
    left = np.linalg.norm(rest, axis=0) > 1e-9 * np.linalg.norm(loads, axis=0)
    x = np.linalg.solve(k + sigma * m, rest[:, left])
    x /= np.sqrt(np.einsum("ij,ij->j", x, m @ x))
    for _ in range(2):  # M-orthogonal to the modes (to round-off; twice, as Gram–Schmidt)
        x -= phi @ (phi.T @ (m @ x))
    gram, vec = np.linalg.eigh(x.T @ m @ x)
    keep = gram > 1e-10  # a new direction, not round-off (which sits below 1e-12)
    extra = x @ (vec[:, keep] / np.sqrt(gram[keep]))
    return np.concatenate([phi, extra], axis=1)


def mac(a: NDArray[Any], b: NDArray[Any]) -> Array:
    """MAC matrix between the columns of ``a`` and of ``b`` (values in 0 … 1); complex
    shapes (gyroscopic systems) use the Hermitian form |aᴴb|² / (aᴴa · bᴴb)."""
    num = np.abs(a.conj().T @ b) ** 2
    den = np.outer(np.einsum("ij,ij->j", a.conj(), a).real, np.einsum("ij,ij->j", b.conj(), b).real)
    return np.asarray(num / np.where(den > 0, den, 1.0))


def track(previous: NDArray[Any], current: NDArray[Any]) -> NDArray[np.intp]:
    """Order of ``current``'s columns that best continues ``previous``'s (max total MAC).

    ``current`` may hold more columns than ``previous`` (candidates; the unmatched ones are
    left out). Exhaustive over permutations for up to 7 modes of a square problem (an exact
    assignment), greedy otherwise.
    """
    return assign(mac(previous, current))


def assign(score: NDArray[Any], optimal: bool = False) -> NDArray[np.intp]:
    """For each row of a similarity matrix (previous modes × candidates) the column that
    continues it (max total score): exhaustive for up to 7 square, greedy otherwise;
    ``optimal``: the best assignment always (Hungarian method, :func:`_hungarian`)."""
    if optimal:
        best = np.argmax(score, axis=1)
        if len(np.unique(best)) == len(best):  # each row's best column, none shared: the
            return np.asarray(best, dtype=np.intp)  # sum of the row maxima, which nothing exceeds
        return _hungarian(np.asarray(score, float))
    n, candidates = score.shape
    if n <= 7 and candidates == n:
        best = max(
            itertools.permutations(range(n)),
            key=lambda p: sum(score[i, j] for i, j in enumerate(p)),
        )
        return np.array(best, dtype=np.intp)
    order = np.full(n, -1, dtype=np.intp)
    taken = np.zeros(candidates, dtype=bool)
    for i in np.argsort(-score.max(axis=1)):
        # the free column of the highest score (the first of equals)
        j = int(np.argmax(np.where(taken, -np.inf, score[i])))
        order[i] = j
        taken[j] = True
    return order


def _hungarian(score: NDArray[np.float64]) -> NDArray[np.intp]:
    """The assignment of rows to distinct columns with the largest total score (n ≤ m):
    Kuhn–Munkres with potentials, O(n²m) — scipy's ``linear_sum_assignment`` does the same,
    but importing scipy.optimize costs most of a second an audit need not pay."""
    cost = score.max() - score  # minimise
    n, m = cost.shape
    u, v = np.zeros(n + 1), np.zeros(m + 1)
    owner = np.zeros(m + 1, dtype=np.intp)  # column → row (1-based; 0: free)
    way = np.zeros(m + 1, dtype=np.intp)
    for i in range(1, n + 1):
        owner[0] = i
        j0 = 0
        low = np.full(m + 1, np.inf)
        used = np.zeros(m + 1, dtype=bool)
        while True:
            used[j0] = True
            i0 = owner[j0]
            free = ~used[1:]
            reduced = cost[i0 - 1] - u[i0] - v[1:]
            better = free & (reduced < low[1:])
            low[1:] = np.where(better, reduced, low[1:])
            way[1:] = np.where(better, j0, way[1:])
            cand = np.where(free, low[1:], np.inf)
            j1 = int(np.argmin(cand)) + 1
            delta = cand[j1 - 1]
            u[owner[used]] += delta
            v[used] -= delta
            low[1:] = np.where(free, low[1:] - delta, low[1:])
            j0 = j1
            if owner[j0] == 0:
                break
        while j0:  # augment along the path
            j1 = way[j0]
            owner[j0] = owner[j1]
            j0 = j1
    out = np.full(n, -1, dtype=np.intp)
    for j in range(1, m + 1):
        if owner[j]:
            out[owner[j] - 1] = j - 1
    return out


@dataclass(frozen=True)
class DampedModes:
    """Oscillatory modes of M q̈ + D q̇ + K q = 0: natural frequency |λ|/2π, damping
    ratio −Re λ/|λ| and (real, phase-aligned) shapes; ``rigid`` counts the degrees of
    freedom without an oscillation (rigid-body motion, or overdamped)."""

    frequency_hz: Array
    damping_ratio: Array
    shapes: Array
    rigid: int


def eigenvalue(frequency_hz: ArrayLike, damping_ratio: ArrayLike) -> NDArray[np.complex128]:
    """The upper root λ = ω₀(−ζ + i√(1 − ζ²)) of a mode of undamped natural frequency
    ω₀ = 2πf and damping ratio ζ (the inverse of :class:`DampedModes`' |λ|/2π and −Re λ/|λ|;
    ζ ≥ 1 gives the real root −ζω₀)."""
    z = np.asarray(damping_ratio, dtype=float)
    w0 = 2 * np.pi * np.asarray(frequency_hz, dtype=float)
    return np.asarray(w0 * (-z + 1j * np.sqrt(np.maximum(1 - z**2, 0.0))))


def damping_ratio(lam: ArrayLike) -> Array:
    """ζ = −Re λ/|λ| of roots λ (the inverse of :func:`eigenvalue`, with |λ|/2π)."""
    root = np.asarray(lam)
    return np.asarray(-root.real / np.abs(root))


def state_roots(k: Array, m: Array, d: Array) -> NDArray[np.complex128]:
    """Eigenvalues λ of M q̈ + D q̇ + K q = 0 (any K, D; M invertible), first-order form."""
    return np.asarray(np.linalg.eigvals(state_matrix(k, m, d)))


def state_matrix(
    k: Array, m: Array, d: Array, lag: tuple[Array, Array, Array, Array] | None = None
) -> Array:
    """A = [[0, I], [−M⁻¹K, −M⁻¹D]] of M q̈ + D q̇ + K q = 0 in first-order form: the one
    builder of it. Stacks (..., n, n) broadcast: many speeds or azimuths at once.

    ``lag`` = (F, P, V, S): first-order states χ with χ̇ = P·q + V·q̇ + S·χ that add the
    force −F·χ (the lift's lag, :class:`wtvib.subsystems.multiblade.LiftLag`), appended after q̇:
    A = [[0, I, 0], [−M⁻¹K, −M⁻¹D, −M⁻¹F], [P, V, S]]."""
    n = k.shape[-1]
    try:
        minv = np.linalg.inv(m)
    except np.linalg.LinAlgError:
        raise ModalError("the inertia matrix is singular (a zero inertia?)") from None
    shape = np.broadcast_shapes(k.shape, m.shape, d.shape)[:-2]
    size = 2 * n + (0 if lag is None else lag[3].shape[-1])
    out = np.zeros((*shape, size, size))
    out[..., :n, n : 2 * n] = np.eye(n)
    with np.errstate(over="ignore", invalid="ignore"):
        out[..., n : 2 * n, :n] = -(minv @ k)
        out[..., n : 2 * n, n : 2 * n] = -(minv @ d)
        if lag is not None:
            f, p, v, s = lag
            out[..., n : 2 * n, 2 * n :] = -(minv @ f)
            out[..., 2 * n :, :n] = p
            out[..., 2 * n :, n : 2 * n] = v
            out[..., 2 * n :, 2 * n :] = s
    if not np.all(np.isfinite(out)):
        raise ModalError(OUT_OF_RANGE)
    return out


#: A root smaller than this times the largest is lost in rounding: the eigen-solver's
#: absolute error is about the machine epsilon (2.2e-16) times the matrix's norm, so such a
#: root's relative error exceeds 2e-5 (Golub & Van Loan, *Matrix Computations*, §7.2).
ROUNDING = 1e-11


def oscillations(
    k: Array,
    m: Array,
    d: Array,
    floor: float | None = None,
    unstable: str = "keep",
    overdamped: bool = False,
) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
    """The oscillatory roots λ (Im λ > 0) of M q̈ + D q̇ + K q = 0, ascending |λ|, and the
    displacement part of their (complex) eigenvectors — the state-space eigenproblem every
    damped modal solve in wtvib shares.

    Roots with |λ| below ``floor`` [rad/s] are no oscillation; None: 1e-5·|λ|max, which also
    drops the λ ≈ 0 of rigid-body motion (a defective double root that rounding splits into
    a pair of size ~√ε·|λ|max). ``unstable="refuse"`` raises ModalError on a root with a
    positive real part. ``overdamped``: real roots count too (a mode damped past critical
    keeps a place, with ζ = 1, so that shape tracking does not hand its name to another).
    """
    ((lam, vec),) = oscillations_stacked(k[None], m, d[None], floor, unstable, overdamped)
    return lam, vec


def oscillations_stacked(
    k: Array,
    m: Array,
    d: Array,
    floor: float | None = None,
    unstable: str = "keep",
    overdamped: bool = False,
    lag: tuple[Array, Array, Array, Array] | None = None,
) -> list[tuple[NDArray[np.complex128], NDArray[np.complex128]]]:
    """:func:`oscillations` of a stack of problems (K and D shaped (p, n, n), one M): the
    state matrices built and solved as one stack (M inverted once, one eigen-solver call
    for the lot — a sweep's points, an operating schedule's), each filtered alone.

    ``lag``: first-order states beside the structure (:func:`state_matrix`); roots in which
    they take part more than the structure does (participation factors, :func:`state_modes`)
    are the lag's own, not modes of the structure, and are left out."""
    n = k.shape[-1]
    lams, vecs = _each(np.linalg.eig, state_matrix(k, m, d, lag))
    if lag is not None:
        try:
            left = _each(np.linalg.inv, vecs)  # rows: the left eigenvectors
        except np.linalg.LinAlgError:
            raise ModalError(DEFECTIVE) from None
        structure = participation(vecs, np.swapaxes(left, -1, -2))[..., : 2 * n, :].sum(axis=-2)
        own = structure < 0.5
        lams = np.where(own, 0j, lams)  # dropped below as a root of zero size
    return [
        _oscillatory(lam, vec, n, floor, unstable, overdamped)
        for lam, vec in zip(lams, vecs, strict=True)
    ]


def _oscillatory(
    lam: NDArray[np.complex128],
    vec: NDArray[np.complex128],
    n: int,
    floor: float | None,
    unstable: str,
    overdamped: bool,
) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
    scale = max(float(np.abs(lam).max(initial=0.0)), 1.0)
    if floor is None:
        tiny, imag = 1e-5 * scale, 1e-9 * scale
    else:
        tiny, imag = floor, 1e-6
    if unstable == "refuse" and np.any((lam.real > 1e-9 * scale) & (np.abs(lam) > tiny)):
        raise ModalError("the drive train is unstable (an eigenvalue with positive real part)")
    osc = (lam.imag > imag) & (np.abs(lam) > tiny)
    if overdamped:
        osc |= (np.abs(lam.imag) <= imag) & (lam.real < 0) & (np.abs(lam) > tiny)
    if np.any(np.abs(lam[osc]) < ROUNDING * scale):
        raise ModalError(
            f"the model's roots span {math.log10(scale / np.abs(lam[osc]).min()):.0f} orders "
            "of magnitude, beyond what double precision resolves: its slowest modes are "
            "rounding, not physics — a damper, stiffness or inertia far out of range?"
        )
    lam, vec = lam[osc], vec[:n, osc]
    order = np.argsort(np.abs(lam))
    return lam[order], vec[:, order]


def damped(k: Array, m: Array, d: Array) -> DampedModes:
    """Damped modes by the state-space eigenproblem (first-order form).

    Notes
    -----
    A = [[0, I], [−M⁻¹K, −M⁻¹D]]; eigenvalues λ = −ζω ± iω√(1−ζ²). Each conjugate pair is
    one mode; the degrees of freedom left over (λ ≈ 0 rigid-body rotation, or real roots of
    overdamped motion) are counted in ``rigid``.

    References
    ----------
    D. J. Inman, *Engineering Vibration*, §4.10 (state-space modal analysis).
    """
    n = k.shape[0]
    if not (np.all(np.isfinite(k)) and np.all(np.isfinite(m)) and np.all(np.isfinite(d))):
        raise ModalError("the drive-train matrices hold NaN or infinite values")
    lam, vec = oscillations(k, m, d, unstable="refuse")
    shapes = np.empty((n, len(lam)))
    for j in range(len(lam)):
        v = vec[:, j]
        v = v * np.exp(-1j * np.angle(v[np.argmax(np.abs(v))]))  # align the phase
        shapes[:, j] = v.real / np.max(np.abs(v.real))
    return DampedModes(np.abs(lam) / (2 * np.pi), damping_ratio(lam), shapes, n - len(lam))


@dataclass(frozen=True)
class StateModes:
    """The roots of a first-order system ẋ = A x (Im λ ≥ 0), their right eigenvectors
    (columns) and participation factors (rows: states, columns: roots; each column sums
    to 1)."""

    roots: NDArray[np.complex128]
    vectors: NDArray[np.complex128]
    participation: Array


#: From this many states on, the left eigenvectors come from LAPACK's solve with the right
#: ones (``dgeev``: one call, no inverse of the right vectors — 2,900 states: the inverse
#: cost a third as much again as the eigen-solution); below it numpy's eig and inverse,
#: which keep scipy's import (0.2 s) off a small check.
LEFT_VECTORS_STATES = 300
DEFECTIVE = "the state matrix is defective: its eigenvectors do not span"


def _roots_upper(lam: NDArray[np.complex128]) -> NDArray[np.bool_]:
    """The roots with Im λ ≥ 0 (to rounding): one of each complex pair, and the real ones."""
    return np.asarray(lam.imag >= -1e-12 * max(1.0, float(np.abs(lam).max(initial=0.0))))


def state_modes(a: Array) -> StateModes:
    """Every root of ẋ = A x with Im λ ≥ 0, with the participation of each state in it.

    The participation factor of state k in root i is |φ_ki·ψ_ik| normalised over k, φ the
    right and ψ the left eigenvectors (ψ = Φ⁻¹): invariant under the scaling of each
    state, so that states in metres, radians and metres per second weigh alike (Pérez-
    Arriaga, Verghese and Schweppe 1982).

    References
    ----------
    I. J. Pérez-Arriaga, G. C. Verghese, F. C. Schweppe, "Selective modal analysis with
    applications to electric power systems, part I", IEEE Trans. PAS-101(9), 1982.
    """
    if a.shape[0] >= LEFT_VECTORS_STATES:
        return _state_modes_both_sides(a)
    found = np.linalg.eig(a)
    lam = found.eigenvalues.astype(np.complex128)
    vec = found.eigenvectors.astype(np.complex128)
    try:
        left = np.linalg.inv(vec).T.astype(np.complex128)
    except np.linalg.LinAlgError:
        raise ModalError(DEFECTIVE) from None
    # ψᵢᵀ·φᵢ = 1 by construction: vectors that do not span show as a huge ψᵢ instead
    _refuse_defective(
        np.abs(np.einsum("ki,ki->i", left, vec)),
        np.linalg.norm(left, axis=0),
        np.linalg.norm(vec, axis=0),
    )
    keep = _roots_upper(lam)
    return StateModes(lam[keep], vec[:, keep], participation(vec[:, keep], left[:, keep]))


def _refuse_defective(product: Array, size_left: Array, size_right: Array) -> None:
    """A ModalError where a root's left and right eigenvectors are orthogonal to rounding,
    |ψᵢᵀ·φᵢ| ≤ 10⁻¹²·|ψᵢ|·|φᵢ|: its eigenvectors do not span (a Jordan block), and the
    participation factors of that root mean nothing."""
    if np.any(product <= 1e-12 * size_left * size_right):
        raise ModalError(DEFECTIVE)


def _state_modes_both_sides(a: Array) -> StateModes:
    """:func:`state_modes` from LAPACK's ``dgeev`` with both eigenvector sets, called
    directly: a real matrix's vectors come as real columns (a complex pair's vector as its
    real and imaginary parts, in the columns of the pair's two roots), and only the kept
    roots' are made complex — scipy's ``eig`` would make both whole sets complex first
    (2,900 states: four seconds beside the solve's sixteen, bench/RESULTS.md). The left
    vectors ψ (ψᵢᵀ·A = λᵢ·ψᵢᵀ) are the conjugates of LAPACK's (uᵢᴴ·A = λᵢ·uᵢᴴ), each to a
    scale of its own, which the participation factors' normalisation removes."""
    from scipy.linalg import lapack

    n = a.shape[0]
    lwork, _ = lapack.dgeev_lwork(n, compute_vl=1, compute_vr=1)
    wr, wi, vl, vr, info = lapack.dgeev(a, compute_vl=1, compute_vr=1, lwork=int(lwork))
    if info != 0:
        raise ModalError(f"the eigen-solution of the {n}-state matrix did not converge")
    lam = wr + 1j * wi
    keep = np.where(_roots_upper(lam))[0]
    # a pair's first root (Im λ > 0): vector = column j + i·column j+1; its second: the
    # conjugate, column j−1 − i·column j; a real root: column j
    first, second = wi[keep] > 0, wi[keep] < 0
    real_at = np.where(second, keep - 1, keep)
    imag_at = np.where(first, keep + 1, keep)
    sign = np.where(first, 1.0, np.where(second, -1.0, 0.0))
    right_re, right_im = vr[:, real_at], vr[:, imag_at] * sign
    left_re, left_im = vl[:, real_at], vl[:, imag_at] * -sign  # ψ = conj(u)
    del vl, vr
    # ψᵢᵀ·φᵢ, 0 for a root whose vectors do not span
    product = np.hypot(
        np.einsum("ki,ki->i", left_re, right_re) - np.einsum("ki,ki->i", left_im, right_im),
        np.einsum("ki,ki->i", left_re, right_im) + np.einsum("ki,ki->i", left_im, right_re),
    )
    size_left = np.sqrt(
        np.einsum("ki,ki->i", left_re, left_re) + np.einsum("ki,ki->i", left_im, left_im)
    )
    size_right = np.sqrt(
        np.einsum("ki,ki->i", right_re, right_re) + np.einsum("ki,ki->i", right_im, right_im)
    )
    _refuse_defective(product, size_left, size_right)
    weight = np.hypot(left_re, left_im)
    del left_re, left_im
    weight *= np.hypot(right_re, right_im)
    vectors = right_re + 1j * right_im
    return StateModes(lam[keep], vectors, _per_root(weight))


def participation(vec: NDArray[np.complex128], left: NDArray[np.complex128]) -> Array:
    """Participation factors |φ_ki·ψ_ik| of the states k in the roots i, each root's summing
    to 1 (:func:`state_modes`): right eigenvectors φ as columns, left ones ψ as columns too
    (stacks: the last two axes)."""
    return _per_root(np.abs(vec * left))


def _per_root(weight: Array) -> Array:
    """Participation weights |φ_ki·ψ_ik| as each root's shares, in place (states: the
    second-last axis)."""
    total = weight.sum(axis=-2, keepdims=True)
    weight /= np.where(total > 0, total, 1.0)
    return weight
