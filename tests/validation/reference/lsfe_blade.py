"""An independent model of a BeamDyn blade as BeamDyn discretises it: one Legendre spectral
finite element of order p over the whole member (BeamDyn's ``order_elem``; r-test's NREL
5-MW blade has one member, p = 5), its displacements and rotations interpolated by the
Lagrange polynomials on the p + 1 Gauss–Lobatto–Legendre nodes, the energy integrated by the
trapezoidal rule on the blade file's stations (``quadrature = 2``, ``refine``).

Written for the tests only, from the papers, not from wtvib: Wang et al., "BeamDyn: a
high-fidelity wind turbine blade solver in the FAST modular framework", Wind Energy 20
(2017) 1439–1462 (the LSFE, its nodes and quadrature); the BeamDyn user's guide
(NREL/TP-5000-66909: the 6×6 sectional matrices, K44/K55 the bending stiffnesses about the
section's x and y axes — edgewise and flapwise —, K11/K22 the shear stiffnesses). Linear
Timoshenko bending in two planes turned by the key points' initial twist, with rotary
inertia (M44, M55), the centrifugal tension's geometric stiffness and the in-plane
softening of a blade turning at Ω; axial and torsion decouple (diagonal sections) and are
left out. The root is clamped.
"""

from pathlib import Path

import numpy as np
from numpy.polynomial import legendre
from scipy.linalg import eigh


def read(primary: Path, blade: Path) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Key points (x, y, z, twist °) of the primary file, and the blade file's stations η
    with their 6×6 stiffness and mass matrices."""
    lines = primary.read_text().splitlines()
    i = next(k for k, ln in enumerate(lines) if "kp_xr" in ln) + 2
    kp = []
    while not lines[i].strip().startswith("-"):
        kp.append([float(x) for x in lines[i].split()[:4]])
        i += 1
    text = blade.read_text().splitlines()
    j = next(k for k, ln in enumerate(text) if "DISTRIBUTED PROPERTIES" in ln) + 1
    numbers = []
    for ln in text[j:]:
        try:
            numbers += [float(x) for x in ln.split()]
        except ValueError:
            continue
    table = np.asarray(numbers)
    n = len(table) // 73
    rows = table[: n * 73].reshape(n, 73)
    return np.asarray(kp), rows[:, 0], rows[:, 1:37].reshape(n, 6, 6), rows[:, 37:].reshape(n, 6, 6)


def _gll(p: int) -> np.ndarray:
    """The p + 1 Gauss–Lobatto–Legendre nodes on [−1, 1]."""
    c = np.zeros(p + 1)
    c[-1] = 1.0
    return np.concatenate([[-1.0], np.sort(legendre.legroots(legendre.legder(c))), [1.0]])


def _lagrange(nodes: np.ndarray, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Lagrange polynomials on ``nodes`` and their derivatives at ``x``, (len(x), nodes)."""
    n = len(nodes)
    value, slope = np.ones((len(x), n)), np.zeros((len(x), n))
    for k in range(n):
        others = [m for m in range(n) if m != k]
        for m in others:
            value[:, k] *= (x - nodes[m]) / (nodes[k] - nodes[m])
        for j in others:
            term = np.full(len(x), 1.0 / (nodes[k] - nodes[j]))
            for m in others:
                if m != j:
                    term = term * (x - nodes[m]) / (nodes[k] - nodes[m])
            slope[:, k] += term
    return value, slope


def frequencies(
    kp: np.ndarray,
    eta: np.ndarray,
    stiffness: np.ndarray,
    mass: np.ndarray,
    order: int,
    refine: int = 1,
    omega: float = 0.0,
    hub_radius: float = 0.0,
) -> dict[str, float]:
    """The lowest six bending modes [Hz], named flap1, edge1, … by the plane that moves more."""
    length = float(kp[-1, 2])
    e = np.concatenate(
        [np.linspace(eta[i], eta[i + 1], refine + 1)[:-1] for i in range(len(eta) - 1)] + [eta[-1:]]
    )
    w = np.zeros(len(e))
    w[:-1] += np.diff(e) / 2
    w[1:] += np.diff(e) / 2
    z, wz = e * length, w * length

    def at(values: np.ndarray) -> np.ndarray:
        return np.interp(e, eta, values)

    ei_flap, ei_edge = at(stiffness[:, 4, 4]), at(stiffness[:, 3, 3])
    ga_flap, ga_edge = at(stiffness[:, 0, 0]), at(stiffness[:, 1, 1])
    m, j_flap, j_edge = at(mass[:, 0, 0]), at(mass[:, 4, 4]), at(mass[:, 3, 3])
    beta = np.radians(np.interp(z, kp[:, 2], kp[:, 3]))
    value, slope = _lagrange(_gll(order), 2 * e - 1)
    slope = slope * 2 / length
    size = 4 * (order + 1)  # per node: flap and edge deflection, flap and edge rotation

    def rows(first: int, table: np.ndarray) -> np.ndarray:
        out = np.zeros((len(e), 2, size))
        out[:, 0, first::4], out[:, 1, first + 1 :: 4] = table, table
        return out

    u, du, rot, drot = rows(0, value), rows(0, slope), rows(2, value), rows(2, slope)
    c, s = np.cos(beta), np.sin(beta)

    def turned(f: np.ndarray, g: np.ndarray) -> np.ndarray:
        return np.stack(
            [np.stack([f * c * c + g * s * s, (g - f) * s * c], -1),
             np.stack([(g - f) * s * c, f * s * s + g * c * c], -1)], -2
        )  # fmt: skip

    def energy(a: np.ndarray, tensor: np.ndarray, weight: np.ndarray = wz) -> np.ndarray:
        return np.einsum("q,qai,qab,qbj->ij", weight, a, tensor, a)

    shear = du - rot
    k = energy(drot, turned(ei_flap, ei_edge)) + energy(shear, turned(ga_flap, ga_edge))
    mm = np.einsum("q,qai,qaj->ij", wz * m, u, u) + energy(rot, turned(j_flap, j_edge))
    if omega:
        pull = m * (hub_radius + z)
        tension = omega**2 * np.array([np.trapezoid(pull[i:], z[i:]) for i in range(len(z))])
        k += np.einsum("q,qai,qaj->ij", wz * tension, du, du)
        k -= omega**2 * np.einsum("q,qi,qj->ij", wz * m, u[:, 1], u[:, 1])
    free = np.arange(4, size)  # the root clamped
    lam, vec = eigh(k[np.ix_(free, free)], mm[np.ix_(free, free)])
    full = np.zeros((size, len(lam)))
    full[free] = vec
    names, count = [], {"flap": 0, "edge": 0}
    for j in range(6):
        kind = "flap" if np.sum(full[0::4, j] ** 2) >= np.sum(full[1::4, j] ** 2) else "edge"
        count[kind] += 1
        names.append(f"{kind}{count[kind]}")
    return dict(zip(names, (np.sqrt(np.abs(lam[:6])) / (2 * np.pi)).tolist(), strict=True))
