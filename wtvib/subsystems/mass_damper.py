"""Tuned mass dampers on the tower or the nacelle: a mass on a spring and a dashpot moving
in one bending plane, attached to the tower's finite elements (OpenFAST ServoDyn's
structural control, StC, as ``tower.dampers``).

A damper of mass m, stiffness k and damping c at a point whose displacement is u = aᵀq
(``a``: the point's motion per degree of freedom of the tower's bending model — a node's
deflection; on the nacelle, the tower top's deflection plus its slope times the damper's
height above the top) adds a coordinate x (the mass's own displacement) with

    T = ½m·ẋ²,   V = ½k·(x − aᵀq)²,   dissipation ½c·(ẋ − aᵀq̇)²,

so that K gains k·[[a aᵀ, −a], [−aᵀ, 1]], D the same with c, and M the mass m on x. On a
rigid mount (a = 0) the damper oscillates alone at √(k/m)/2π with ζ = c/(2√(km)); tuned
near a tower mode it splits that mode in two and damps both (J. P. Den Hartog,
*Mechanical Vibrations*, 4th ed., 1956, §3.3).

The tower's own damping enters as modal damping of the bare tower: D_s = M·Φ·diag(2ζᵣωᵣ)·ΦᵀM
over its mass-normalised modes Φ (each mode's ratio as the tower gives it), and the damped
modes of the whole are the roots of M q̈ + D q̇ + K q = 0 (:func:`wtvib.numerics.modal.oscillations`):
frequency |λ|/2π, damping ratio −Re λ/|λ|.
"""

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..numerics import modal
from ..spec.tower import MassDamper

Array = NDArray[np.float64]


def attachment(nodes: Array, size: int, damper: MassDamper) -> Array:
    """The damper's mounting point's displacement per degree of freedom of a bending
    system of ``size`` dofs, (u, u′) per node from the base up, whose last node is the
    tower top (a held base's dofs left out at the front): on the tower, the deflection of
    the node at its height (:func:`wtvib.subsystems.tower.discretise` puts a node there); on the
    nacelle, the top's deflection and its slope times the height above the top. A point
    on a held base does not move (zeros)."""
    a = np.zeros(size)
    offset = 2 * len(nodes) - size  # the held base's dofs, not in the system
    if damper.on == "nacelle":
        a[-2] = 1.0
        a[-1] = damper.height_m
        return a
    i = 2 * int(np.argmin(np.abs(nodes - damper.height_m))) - offset
    if i >= 0:
        a[i] = 1.0
    return a


def augmented(
    k: Array, m: Array, d: Array, dampers: Sequence[MassDamper], points: Sequence[Array]
) -> tuple[Array, Array, Array]:
    """K, M, D of a structure (``k``, ``m``, ``d``: n dofs) with its dampers' coordinates
    appended, each damper on its mounting point (``points``: its :func:`attachment`)."""
    n, count = k.shape[0], len(dampers)
    out = [np.zeros((n + count, n + count)) for _ in range(3)]
    out[0][:n, :n], out[1][:n, :n], out[2][:n, :n] = k, m, d
    for j, (damper, a) in enumerate(zip(dampers, points, strict=True)):
        x = n + j
        out[1][x, x] = damper.mass_kg
        for mat, value in ((out[0], damper.stiffness_n_m), (out[2], damper.damping_ns_m)):
            mat[:n, :n] += value * np.outer(a, a)
            mat[:n, x] -= value * a
            mat[x, :n] -= value * a
            mat[x, x] += value
    return out[0], out[1], out[2]


def modal_damping(m: Array, bare: modal.Modes, zeta: Array) -> Array:
    """D = M·Φ·diag(2ζᵣωᵣ)·ΦᵀM of mass-normalised modes Φ (all of the structure's) with
    damping ratios ``zeta``: the damping matrix whose undamped modes keep those ratios."""
    omega = 2 * np.pi * bare.frequency_hz
    mp = m @ bare.shapes
    return np.asarray((mp * (2 * zeta * omega)) @ mp.T)


@dataclass(frozen=True)
class Root:
    """A damped mode of a structure with its dampers: which bare mode it continues (its
    index in the bare modes), or None for a damper's own mode; frequency |λ|/2π [Hz],
    damping ratio, the structure's part of its shape (real, phase-aligned)."""

    bare: int | None
    frequency_hz: float
    damping_ratio: float
    shape: Array


def damped_modes(
    k: Array,
    m: Array,
    dampers: Sequence[MassDamper],
    points: Sequence[Array],
    ratio: Callable[[int, float], float],
    count: int,
) -> list[Root]:
    """The lowest ``count`` modes of the bare structure (K, M) as its dampers leave them,
    and the dampers' own modes, lowest first. ``ratio(r, f)``: the structure's damping
    ratio of its bare mode r at frequency f [Hz].

    Each root is the continuation of the bare mode its structural part resembles most
    (MAC), the roots taken in order of the structure's share of their kinetic energy: a
    damper tuned to a mode splits it, and the root moving the structure more keeps the
    mode's name, the other is the damper's; a root continuing a bare mode beyond the
    lowest ``count`` is left out."""
    n = k.shape[0]
    bare = modal.solve(k, m)
    zeta = np.array([ratio(r, float(f)) for r, f in enumerate(bare.frequency_hz)])
    ka, ma, da = augmented(k, m, modal_damping(m, bare, zeta), dampers, points)
    lam, vec = modal.oscillations(ka, ma, da, floor=1e-9)
    want = min(count + len(dampers), len(lam))
    lam, vec = lam[:want], vec[:, :want]
    energy = np.abs(np.conj(vec) * (ma @ vec)).real
    share = energy[:n].sum(axis=0) / np.maximum(energy.sum(axis=0), 1e-300)
    structure = np.empty((n, want))
    for j in range(want):  # the structure's part, phase-aligned on the largest coordinate
        v = vec[:, j] * np.exp(-1j * np.angle(vec[np.argmax(np.abs(vec[:, j])), j]))
        structure[:, j] = v[:n].real
    best = np.argmax(modal.mac(bare.shapes, structure), axis=0) if want else np.zeros(0, int)
    owner: dict[int, int | None] = {}
    for j in np.argsort(-share, kind="stable"):
        r = int(best[j])
        if r >= count:  # a higher mode of the structure
            continue
        owner[int(j)] = r if r not in owner.values() else None
    freq, damping = np.abs(lam) / (2 * np.pi), modal.damping_ratio(lam)
    roots = [Root(owner[j], float(freq[j]), float(damping[j]), structure[:, j]) for j in owner]
    own = sorted((r for r in roots if r.bare is None), key=lambda r: r.frequency_hz)
    kept = [r for r in roots if r.bare is not None] + own[: len(dampers)]
    return sorted(kept, key=lambda r: r.frequency_hz)
