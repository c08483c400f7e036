"""Euler–Bernoulli beam finite elements: bending (Hermite cubics) and torsion (linear).

Element matrices are integrated with a 4-point Gauss rule over properties evaluated at the
Gauss points, exact for properties linear between stations; assembly is vectorised. The
default meshes are chosen by the convergence test in ``tests/validation``.

References
----------
J. S. Przemieniecki, *Theory of Matrix Structural Analysis*, McGraw-Hill 1968, ch. 5 and
11 (element stiffness, consistent mass and geometric stiffness matrices); R. D. Cook et
al., *Concepts and Applications of Finite Element Analysis*, 4th ed., §16.
"""

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]


#: Beyond this many input stations a member is not meshed at every station: a uniform mesh
#: of this many elements samples the (linearly interpolated) table at its Gauss points. A
#: 10,000-station tower took 300 s and 15 GB as 10,000 elements.
MAX_STATION_NODES = 200


def mesh(stations: Array, elements: int) -> Array:
    """Node positions: every input station, plus equal divisions between them.

    Stations closer than 1/10,000 of the member length are merged (a property step
    tabulated as two stations 1 mm apart). A division node closer than a quarter of the
    nominal element length to a station is dropped: very short elements make the stiffness
    matrix ill-conditioned (12·EI/L³ swamps the low eigenvalues in double precision). A
    table of more than :data:`MAX_STATION_NODES` stations is meshed uniformly instead (see
    :func:`resampled`).
    """
    if resampled(stations):
        return np.linspace(stations[0], stations[-1], MAX_STATION_NODES + 1)
    length = stations[-1] - stations[0]
    merged = [stations[0]]
    for s in stations[1:]:
        if s - merged[-1] > 1e-4 * length:
            merged.append(s)
        else:
            merged[-1] = s if s == stations[-1] else merged[-1]
    fixed = np.asarray(merged)
    grid = np.linspace(stations[0], stations[-1], elements + 1)
    gap = 0.25 * length / elements
    far = np.min(np.abs(fixed[:, None] - grid[None, :]), axis=0) > gap
    return np.union1d(fixed, grid[far])


def resampled(stations: Array) -> bool:
    """Whether a member's table is too long to mesh at every station (said in the report)."""
    return len(stations) > MAX_STATION_NODES


#: 4-point Gauss–Legendre rule on [0, 1]: exact for the degree-7 integrands of a consistent
#: mass matrix with linearly varying mass per length.
_XI, _W = np.polynomial.legendre.leggauss(4)
GAUSS_XI = 0.5 * (_XI + 1.0)
GAUSS_W = 0.5 * _W


def gauss_points(nodes: Array) -> tuple[Array, Array]:
    """Positions [m] and weights [m] (weight × element length) of the Gauss points, (n, 4)."""
    lengths = np.diff(nodes)
    x = nodes[:-1, None] + lengths[:, None] * GAUSS_XI[None, :]
    return x, lengths[:, None] * GAUSS_W[None, :]


def _hermite_tables() -> tuple[Array, Array, Array]:
    """The cubic Hermite polynomials of ξ at the Gauss points, (4 points, 4 dofs): N, dN/dξ
    and d²N/dξ², each dof's rotation ones still to be multiplied by the element length."""
    xi = GAUSS_XI[:, None]
    n = np.hstack(
        [1 - 3 * xi**2 + 2 * xi**3, xi - 2 * xi**2 + xi**3, 3 * xi**2 - 2 * xi**3, -(xi**2) + xi**3]
    )
    d1 = np.hstack(
        [-6 * xi + 6 * xi**2, 1 - 4 * xi + 3 * xi**2, 6 * xi - 6 * xi**2, -2 * xi + 3 * xi**2]
    )
    d2 = np.hstack([-6 + 12 * xi, -4 + 6 * xi, 6 - 12 * xi, -2 + 6 * xi])
    return n, d1, d2


_HERMITE = _hermite_tables()


def _hermite(lengths: Array) -> tuple[Array, Array, Array]:
    """Hermite shape functions N, dN/dx, d²N/dx² at the Gauss points, each (n, 4, 4dofs)."""
    L = lengths[:, None, None]
    # the rotation dofs' functions scale with the element length (w′ = dw/dx)
    scale = np.concatenate([np.ones_like(L), L, np.ones_like(L), L], axis=-1)
    n, d1, d2 = (table[None] * scale for table in _HERMITE)
    return n, d1 / L, d2 / L**2


def timoshenko(lengths: Array, phi: Array) -> tuple[Array, Array, Array, Array]:
    """The shear-deformable (Timoshenko) element's interdependent interpolation at the Gauss
    points, dofs (w₁, θ₁, w₂, θ₂) with θ the section's rotation: the deflection N, its
    slope dN/dx, the rotation Θ and its derivative dΘ/dx, each (n, 4 points, 4 dofs), for
    each element's φ = 12·EI/(κGA·L²). The shear strain dN/dx − Θ is constant along an
    element, and the interpolation is exact for a uniform element loaded at its ends; at
    φ = 0 it is the Hermite cubics with θ = w′.

    References
    ----------
    D. Friedman, Z. Kosmatka, "An improved two-node Timoshenko beam finite element",
    Computers & Structures 47 (1993) 473–481; J. N. Reddy, "On locking-free shear
    deformable beam finite elements", Comput. Methods Appl. Mech. Eng. 149 (1997) 113–132.
    """
    xi = GAUSS_XI[None, :]
    L = lengths[:, None]
    f = phi[:, None]
    d = 1.0 + f
    one = np.ones_like(xi) + 0 * L
    n = np.stack(
        [
            (1 + f - f * xi - 3 * xi**2 + 2 * xi**3) / d,
            L * ((1 + f / 2) * xi - (2 + f / 2) * xi**2 + xi**3) / d,
            (f * xi + 3 * xi**2 - 2 * xi**3) / d,
            L * (-(f / 2) * xi - (1 - f / 2) * xi**2 + xi**3) / d,
        ],
        axis=-1,
    )
    n1 = np.stack(
        [
            (-f - 6 * xi + 6 * xi**2) / (L * d),
            ((1 + f / 2) - (4 + f) * xi + 3 * xi**2) / d,
            (f + 6 * xi - 6 * xi**2) / (L * d),
            (-(f / 2) - (2 - f) * xi + 3 * xi**2) / d,
        ],
        axis=-1,
    )
    rot = np.stack(
        [
            6 * (xi**2 - xi) / (L * d),
            (1 + f - (4 + f) * xi + 3 * xi**2) / d,
            -6 * (xi**2 - xi) / (L * d),
            (-(2 - f) * xi + 3 * xi**2) / d,
        ],
        axis=-1,
    )
    rot1 = np.stack(
        [
            6 * (2 * xi - 1) / (L**2 * d),
            (-(4 + f) + 6 * xi) / (L * d),
            -6 * (2 * xi - 1) / (L**2 * d),
            (-(2 - f) + 6 * xi) / (L * d),
        ],
        axis=-1,
    )
    return n * one[..., None], n1 * one[..., None], rot * one[..., None], rot1 * one[..., None]


@dataclass(frozen=True)
class Basis:
    """Gauss points and Hermite shape functions of a mesh, computed once per mesh."""

    nodes: Array
    x: Array
    w: Array
    n: Array
    d1: Array
    d2: Array


def basis(nodes: Array) -> Basis:
    """The quadrature and shape-function data of a mesh (reused for every property set)."""
    x, w = gauss_points(nodes)
    n, d1, d2 = _hermite(np.diff(nodes))
    return Basis(nodes, x, w, n, d1, d2)


def bending_elements(
    nodes: Array | Basis, ei: Array, m: Array, axial: Array | None = None
) -> tuple[Array, Array, Array]:
    """Element stiffness (bending), geometric stiffness and mass, each (n, 4, 4).

    ``ei``, ``m`` and ``axial`` are values at the Gauss points, shape (n, 4).
    Integrating with the Gauss rule makes linearly tapered properties exact; for constant
    properties the matrices equal :func:`bending_stiffness` and :func:`bending_mass`.
    """
    b = nodes if isinstance(nodes, Basis) else basis(nodes)
    k = np.einsum("eg,egi,egj->eij", b.w * ei, b.d2, b.d2)
    mass = np.einsum("eg,egi,egj->eij", b.w * m, b.n, b.n)
    geo = (
        np.zeros_like(k) if axial is None else np.einsum("eg,egi,egj->eij", b.w * axial, b.d1, b.d1)
    )
    return k, geo, mass


def torsion_elements(nodes: Array, gj: Array, ip: Array) -> tuple[Array, Array]:
    """Element stiffness and mass of a torsion member (linear shape functions), (n, 2, 2)."""
    _, w = gauss_points(nodes)
    L = np.diff(nodes)[:, None]
    xi = GAUSS_XI[None, :]
    n = np.stack([1 - xi + 0 * L, xi + 0 * L], axis=-1)
    d = np.stack([-1 / L + 0 * xi, 1 / L + 0 * xi], axis=-1)
    return (np.einsum("eg,egi,egj->eij", w * gj, d, d), np.einsum("eg,egi,egj->eij", w * ip, n, n))


def assemble(elements: Array, dofs: NDArray[np.intp], size: int) -> Array:
    """Scatter element matrices (n, k, k) into a global (size, size) matrix.

    ``dofs`` (n, k) holds the global dof of each element dof.
    """
    flat = (dofs[:, :, None] * size + dofs[:, None, :]).ravel()
    summed = np.bincount(flat, weights=elements.ravel(), minlength=size * size)
    return np.asarray(summed.reshape(size, size), dtype=float)


def chain_dofs(elements: int, per_node: int, picks: tuple[int, ...]) -> NDArray[np.intp]:
    """Global dofs of each element for a chain of nodes with ``per_node`` dofs each.

    ``picks`` are the node-local dof indices used by the element, e.g. (0, 1) for (w, w′).
    """
    first = np.arange(elements, dtype=np.intp)[:, None] * per_node
    local = np.array(picks, dtype=np.intp)
    return np.concatenate([first + local, first + per_node + local], axis=1)


#: Elements of the default blade mesh (input stations are nodes too; first flap and edge
#: agree to 1e-5 with a 4× finer mesh, tests/validation/test_structure.py).
BLADE_ELEMENTS = 30


def interpolate(nodes_x: Array, stations: Array, values: Array) -> Array:
    """Property values at arbitrary positions, linear between input stations."""
    return np.interp(nodes_x, stations, values)


def assemble_bending(
    nodes: Array | Basis, ei: Array, m: Array, axial: Array | None = None
) -> tuple[Array, Array]:
    """Global K (bending + geometric) and M of a beam in one plane, dofs (w, w′) per node.

    Properties are given at the Gauss points, shape (elements, 4).
    """
    k, geo, mass = bending_elements(nodes, ei, m, axial)
    count = len(nodes.nodes if isinstance(nodes, Basis) else nodes)
    dofs = chain_dofs(count - 1, 2, (0, 1))
    size = 2 * count
    return assemble(k + geo, dofs, size), assemble(mass, dofs, size)


def assemble_torsion(nodes: Array, gj: Array, ip: Array) -> tuple[Array, Array]:
    """Global K and M of a torsion member, one dof per node; properties at Gauss points."""
    k, mass = torsion_elements(nodes, gj, ip)
    dofs = chain_dofs(len(nodes) - 1, 1, (0,))
    return assemble(k, dofs, len(nodes)), assemble(mass, dofs, len(nodes))


def polynomial_frequency(
    stations: Array,
    ei: Array,
    mass: Array,
    coefficients: Sequence[float],
    base: float,
    length: float,
) -> float | None:
    """The frequency a mode-shape polynomial φ(x) = Σ c_k·x^k (k = 2 … 6, x = 0 at ``base``,
    1 at ``base + length``) implies on a cantilever with bending stiffness ``ei`` [N·m²]
    and mass ``mass`` [kg/m] at ``stations`` [m]: √(∫EI·φ″² / ∫m·φ²)/2π, ElastoDyn's
    FreqTFA(i,1), FreqBF(i,1) (its KTFA(i,i) over MTFA(i,i) without the tip mass;
    OpenFAST's ElastoDyn, SetTowerParameters and Coeff). [Hz] (None: no length, stiffness
    or mass.)"""
    if not length > 0:
        return None
    z = base + np.linspace(0.0, length, 801)
    x = (z - base) / length
    c = list(coefficients)
    shape = sum(ck * x**k for k, ck in zip(range(2, 7), c, strict=True))
    curvature = sum(k * (k - 1) * ck * x ** (k - 2) for k, ck in zip(range(2, 7), c, strict=True))
    k_ii = float(
        np.trapezoid(np.interp(z, stations, ei) * (np.asarray(curvature) / length**2) ** 2, z)
    )
    m_ii = float(np.trapezoid(np.interp(z, stations, mass) * np.asarray(shape) ** 2, z))
    return math.sqrt(k_ii / m_ii) / (2 * math.pi) if k_ii > 0 and m_ii > 0 else None
