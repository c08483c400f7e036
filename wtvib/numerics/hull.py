"""A floating platform's hull of circular members: its mass, buoyancy, waterplane, added mass
by strip theory, and the water ballast that trims it.

Each member is a straight tube between two points, its outer diameter and wall layers
varying along it, with bulkheads, stiffeners and ballast inside. The platform's matrices are
6 × 6 about the origin (the platform reference point, PRP, on the still-water line below the
tower axis) in the order surge, sway, heave, roll, pitch, yaw; a member is cut into
``SLICES`` slices, each a rigid mass (or a strip of fluid) at its centre.

* Rigid body: a mass m at r with inertia J about its own centre adds
  [[m·I, −m·S], [m·S, J − m·S·S]] (S the cross-product matrix of r: S·v = r × v).
* Hydrostatics (linear, about the undisplaced position): the displaced volume V and its
  centre z_B from the submerged slices; the waterplane from each member crossing z = 0 (its
  section there, area πD²/4 over the cosine of its tilt): C₃₃ = ρgA_wp, C₄₄ = ρg(∫y²dA +
  V·z_B), C₅₅ = ρg(∫x²dA + V·z_B), C₃₄ = ρg∫y dA, C₃₅ = −ρg∫x dA, C₄₅ = −ρg∫xy dA,
  C₄₆ = −ρgV·x_B, C₅₆ = −ρgV·y_B (Faltinsen 1990, §2.3; WAMIT's .hst without the weight
  term, which :func:`wtvib.subsystems.platform.restoring` adds from the platform's own mass).
* Added mass by strip theory (Morison's inertia term): a submerged slice of length dl adds
  ρ·C_a·(πD²/4)·dl across its axis; a free end below water, and each change of diameter
  along a member, adds ρ·C_a,end·(π/12)·|ΔD³| along it (RAFT's end term, Hall et al. 2022;
  C_a,end ≈ 2/π gives a one-sided disc's potential-flow value ρD³/6).
* Water ballast (variable ballast): the mass that makes buoyancy equal weight and the
  moorings' pull (WISDEM FloatingSE's balance), filling the compartments from the lowest up
  to one common level, as connected tanks would (WISDEM instead shares it by capacity, each
  compartment filled the same fraction); fixed ballast fills its compartment from the low
  end.

Jonkman 2010 (NREL/TP-500-47535) §5 and Allen et al. 2020 (NREL/TP-5000-76773) describe the
reference platforms; Faltinsen, *Sea Loads on Ships and Offshore Structures* (1990) ch. 2
and 4; Hall et al., RAFT (Wind Energy Science 2022).
"""

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

Array = NDArray[np.float64]

#: Slices a member is cut into (a 40 m column: 0.2 m slices, well below its diameter).
SLICES = 200

#: A member within this angle of the horizontal holds its ballast along its length, in the
#: circular segment of its section below the level; a steeper one fills from its low end.
LEVEL_DEG = 30.0


@dataclass(frozen=True)
class Layer:
    """A wall layer: thickness at the member's stations [m], material density [kg/m³]."""

    thickness: Array
    density: float


@dataclass(frozen=True)
class Disc:
    """A bulkhead across the member's inside at a station s ∈ [0, 1]."""

    station: float
    thickness: float
    density: float


@dataclass(frozen=True)
class Fill:
    """Ballast between stations s0 < s1: ``volume`` of ``density`` from the low end, or, for
    water ballast (``volume`` None), the share :func:`trim` gives it."""

    start: float
    end: float
    density: float
    volume: float | None = None


@dataclass(frozen=True)
class Member:
    """A circular member from ``a`` to ``b`` [m]; ``stations`` ∈ [0, 1] along it carry its
    outer diameter [m] and the layers' thicknesses (outside in)."""

    name: str
    a: Array
    b: Array
    stations: Array
    diameter: Array
    layers: Sequence[Layer]
    bulkheads: Sequence[Disc] = ()
    stiffener_mass_per_m: float = 0.0
    outfitting: float = 1.0
    ca: float = 1.0
    ca_end: float = 0.6
    free_ends: tuple[bool, bool] = (True, True)
    fills: Sequence[Fill] = ()

    @property
    def length(self) -> float:
        return float(np.linalg.norm(self.b - self.a))

    @property
    def axis(self) -> Array:
        return np.asarray((self.b - self.a) / self.length)


@dataclass(frozen=True)
class Slices:
    """A member cut into slices: centres s, positions r, length each, outer and inner
    diameters, and the share of each slice below the water line."""

    s: Array
    r: Array
    dl: Array
    outer: Array
    inner: Array
    wet: Array


def slices(member: Member, n: int = SLICES) -> Slices:
    """The member's slices (:class:`Slices`): ``n`` equal ones, cut again at its stations,
    its compartments' ends and the water line, so that no slice straddles a step of
    diameter, a bulkhead's compartment or the water surface."""
    za, zb = member.a[2], member.b[2]
    extra = [x for x in member.stations if 0 < x < 1]
    extra += [x for f in member.fills for x in (f.start, f.end) if 0 < x < 1]
    if min(za, zb) < 0 < max(za, zb):
        extra.append(za / (za - zb))
    edges = np.unique(np.concatenate([np.linspace(0.0, 1.0, n + 1), extra]))
    edges = edges[np.concatenate([[True], np.diff(edges) > 1e-12])]
    s = (edges[1:] + edges[:-1]) / 2
    r = member.a + s[:, None] * (member.b - member.a)
    outer = np.interp(s, member.stations, member.diameter)
    wall = sum(
        (np.interp(s, member.stations, x.thickness) for x in member.layers), np.zeros(len(s))
    )
    inner = np.clip(outer - 2 * wall, 0.0, None)
    dz = abs(zb - za) * np.diff(edges)
    low = r[:, 2] - dz / 2
    wet = np.where(
        dz > 1e-12,
        np.clip(-low / np.where(dz > 1e-12, dz, 1.0), 0.0, 1.0),
        (r[:, 2] < 0).astype(float),
    )
    return Slices(s, r, np.diff(edges) * member.length, outer, inner, wet)


def skew(r: Array) -> Array:
    """S with S·v = r × v."""
    x, y, z = r
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


def at_point(a: Array, r: Array, j: Array | None = None) -> Array:
    """The 6 × 6 matrix at the origin of a 3 × 3 translational mass ``a`` at ``r`` (with
    rotational inertia ``j`` about r): [[a, −a·S], [S·a, j − S·a·S]]."""
    return at_points(a[None], np.asarray(r, dtype=float)[None], None if j is None else j[None])


def at_points(a: Array, r: Array, j: Array | None = None) -> Array:
    """:func:`at_point` summed over n points: ``a`` (n, 3, 3), ``r`` (n, 3), ``j`` (n, 3, 3)."""
    x, y, z = r[:, 0], r[:, 1], r[:, 2]
    zero = np.zeros_like(x)
    s = np.stack(
        [np.stack([zero, -z, y], -1), np.stack([z, zero, -x], -1), np.stack([-y, x, zero], -1)],
        axis=1,
    )
    out = np.zeros((6, 6))
    out[:3, :3] = a.sum(axis=0)
    out[:3, 3:] = -np.einsum("nij,njk->ik", a, s)
    out[3:, :3] = np.einsum("nij,njk->ik", s, a)
    out[3:, 3:] = -np.einsum("nij,njk,nkl->il", s, a, s)
    if j is not None:
        out[3:, 3:] += j.sum(axis=0)
    return out


def _inner(member: Member, s: float) -> float:
    """The inside diameter at station s [m] (at a step of diameter: the wider side's, which
    a bulkhead there closes)."""
    wall = sum(float(np.interp(s, member.stations, x.thickness)) for x in member.layers)
    i = np.searchsorted(member.stations, s)
    sides = [float(np.interp(s, member.stations, member.diameter))]
    sides += [
        float(member.diameter[k])
        for k in (i - 1, i, i + 1)
        if 0 <= k < len(member.stations) and abs(member.stations[k] - s) < 1e-3
    ]
    return max(max(sides) - 2 * wall, 0.0)


def _about_axis(axis: Array, along: ArrayLike, across: ArrayLike) -> Array:
    """3 × 3 inertias (one per entry of ``along``/``across``) with ``along`` about the axis
    and ``across`` about any normal to it."""
    q = np.outer(axis, axis)
    along, across = np.asarray(along, dtype=float), np.asarray(across, dtype=float)
    return np.asarray(along[..., None, None] * q + across[..., None, None] * (np.eye(3) - q))


def _tubes(member: Member, cut: Slices, mass: Array, outer: Array, inner: Array) -> Array:
    """Slices of tube of ``mass`` each, between diameters ``outer`` and ``inner``."""
    r2 = (outer**2 + inner**2) / 4  # (R_o² + R_i²)
    j = _about_axis(member.axis, mass * r2 / 2, mass * (r2 / 4 + cut.dl**2 / 12))
    return at_points(mass[:, None, None] * np.eye(3), cut.r, j)


def structure(member: Member) -> Array:
    """The member's steel: wall layers, bulkheads and stiffeners, times its outfitting
    factor (6 × 6 at the origin)."""
    cut = slices(member)
    out = np.zeros((6, 6))
    outside = cut.outer.copy()
    for layer in member.layers:
        t = np.interp(cut.s, member.stations, layer.thickness)
        inside = np.clip(outside - 2 * t, 0.0, None)
        m = layer.density * np.pi / 4 * (outside**2 - inside**2) * cut.dl
        out += _tubes(member, cut, m, outside, inside)
        outside = inside
    if member.stiffener_mass_per_m:
        m = member.stiffener_mass_per_m * cut.dl
        out += _tubes(member, cut, m, cut.inner, cut.inner)
    for disc in member.bulkheads:
        d = _inner(member, disc.station)
        plate = disc.density * np.pi / 4 * d**2 * disc.thickness
        r = member.a + disc.station * (member.b - member.a)
        j = _about_axis(member.axis, plate * d**2 / 8, plate * d**2 / 16)
        out += at_point(plate * np.eye(3), r, j)
    return out * member.outfitting


def _is_level(member: Member) -> bool:
    """Within ``LEVEL_DEG`` of the horizontal: its water lies along it, not from one end."""
    return bool(abs(member.axis[2]) < np.sin(np.radians(LEVEL_DEG)))


def held(member: Member, fill: Fill, level: float, cut: Slices | None = None) -> Array:
    """The volume in each slice of the fill's compartment below the water ``level`` [m³]: a
    steep member's slices by the share of their height below it, a level one's (within
    ``LEVEL_DEG`` of the horizontal) by the circular segment of their section (``cut``:
    the member's slices, where the caller has them)."""
    cut = slices(member) if cut is None else cut
    inside = (cut.s >= fill.start) & (cut.s <= fill.end)
    r = cut.inner / 2
    if _is_level(member):
        h = np.clip(level - (cut.r[:, 2] - r), 0.0, 2 * r)
        c = np.clip(r - h, -r, r)
        area = r**2 * np.arccos(np.divide(c, r, out=np.ones_like(r), where=r > 0)) - c * np.sqrt(
            np.clip(r**2 - c**2, 0.0, None)
        )
        share = np.divide(area, np.pi * r**2, out=np.zeros_like(r), where=r > 0)
    else:
        half = abs(member.axis[2]) * cut.dl / 2
        share = np.clip((level - (cut.r[:, 2] - half)) / (2 * half), 0.0, 1.0)
    return np.where(inside, np.pi * r**2 * cut.dl * share, 0.0)


def capacity(member: Member, fill: Fill) -> float:
    """The inside volume of the fill's compartment [m³]."""
    return float(held(member, fill, np.inf).sum())


def level(parts: Sequence[tuple[Member, Fill]], volume: float) -> float:
    """The one water level [m] at which the compartments together hold ``volume`` (connected
    tanks), found by bisection; above them all where they cannot hold it."""
    ends = [z for m, _ in parts for z in (m.a[2], m.b[2])]
    reach = max((float(np.max(m.diameter)) for m, _ in parts), default=0.0)
    low, high = min(ends, default=0.0) - reach, max(ends, default=0.0) + reach
    cuts = [slices(m) for m, _ in parts]
    for _ in range(60):
        mid = (low + high) / 2
        if (
            sum(float(held(m, f, mid, c).sum()) for (m, f), c in zip(parts, cuts, strict=True))
            < volume
        ):
            low = mid
        else:
            high = mid
    return high


def ballast(member: Member, fill: Fill, water_level: float) -> Array:
    """The fill's ballast below ``water_level`` in its compartment, 6 × 6 at the origin."""
    cut = slices(member)
    volume = held(member, fill, water_level, cut)
    if _is_level(member):
        # a level member's water lies in the segment below the level: its centroid
        # (2/3)(r² − e²)^(3/2)/A below the axis, e the level's height above it
        r = cut.inner / 2
        e = np.clip(water_level - cut.r[:, 2], -r, r)
        area = np.divide(volume, cut.dl)
        drop = np.divide(2 / 3 * (r**2 - e**2) ** 1.5, area, out=np.zeros_like(r), where=area > 0)
        lowered = cut.r - drop[:, None] * np.array([0.0, 0.0, 1.0])
        cut = Slices(cut.s, lowered, cut.dl, cut.outer, cut.inner, cut.wet)
    return _tubes(member, cut, fill.density * volume, cut.inner, np.zeros_like(cut.inner))


@dataclass(frozen=True)
class Buoyancy:
    """What the hull displaces: volume [m³], its centre [m], and the waterplane's area [m²]
    and first and second moments ∫x dA, ∫y dA [m³], ∫x² dA, ∫y² dA, ∫xy dA [m⁴]."""

    volume: float
    centre: Array
    area: float
    moments: Array = field(default_factory=lambda: np.zeros(2))
    seconds: Array = field(default_factory=lambda: np.zeros(3))


def buoyancy(members: Sequence[Member]) -> Buoyancy:
    """The hull's displaced volume and waterplane (:class:`Buoyancy`)."""
    volume, first = 0.0, np.zeros(3)
    area, moments, seconds = 0.0, np.zeros(2), np.zeros(3)
    for member in members:
        cut = slices(member)
        v = np.pi / 4 * cut.outer**2 * cut.dl * cut.wet
        volume += float(v.sum())
        first += v @ cut.r
        za, zb = member.a[2], member.b[2]
        if min(za, zb) < 0 < max(za, zb):  # the member pierces the water line
            s = za / (za - zb)
            x, y, _ = member.a + s * (member.b - member.a)
            d = float(np.interp(s, member.stations, member.diameter))
            a = np.pi / 4 * d**2 / abs(member.axis[2])
            own = np.pi / 64 * d**4 / abs(member.axis[2])
            area += a
            moments += a * np.array([x, y])
            seconds += np.array([a * x * x + own, a * y * y + own, a * x * y])
    centre = first / volume if volume > 0 else np.zeros(3)
    return Buoyancy(volume, centre, area, moments, seconds)


def hydrostatic(b: Buoyancy, rho: float, g: float) -> Array:
    """The hydrostatic restoring at the origin, without the weight term (module notes)."""
    c = np.zeros((6, 6))
    (mx, my), (xx, yy, xy) = b.moments, b.seconds
    c[2, 2] = rho * g * b.area
    c[2, 3] = c[3, 2] = rho * g * my
    c[2, 4] = c[4, 2] = -rho * g * mx
    c[3, 3] = rho * g * (yy + b.volume * b.centre[2])
    c[4, 4] = rho * g * (xx + b.volume * b.centre[2])
    c[3, 4] = c[4, 3] = -rho * g * xy
    return c


def added_mass(members: Sequence[Member], rho: float) -> Array:
    """The hull's added mass by strip theory at the origin (module notes)."""
    out = np.zeros((6, 6))
    for member in members:
        cut = slices(member)
        q = np.outer(member.axis, member.axis)
        across = rho * member.ca * np.pi / 4 * cut.outer**2 * cut.dl * cut.wet
        out += at_points(across[:, None, None] * (np.eye(3) - q), cut.r)
        # axial: each step of diameter along the member, and its free ends
        edges = np.concatenate([[0.0], (cut.s[1:] + cut.s[:-1]) / 2, [1.0]])
        steps = np.abs(np.diff(np.interp(edges, member.stations, member.diameter) ** 3))
        where = list(cut.s)
        volume = list(np.pi / 12 * steps)
        for s, free in ((0.0, member.free_ends[0]), (1.0, member.free_ends[1])):
            if free:
                where.append(s)
                volume.append(
                    np.pi / 12 * float(np.interp(s, member.stations, member.diameter)) ** 3
                )
        r = member.a + np.asarray(where)[:, None] * (member.b - member.a)
        axial = rho * member.ca_end * np.where(r[:, 2] < 0, np.asarray(volume), 0.0)
        out += at_points(axial[:, None, None] * q, r)
    return 0.5 * (out + out.T)


@dataclass(frozen=True)
class Trim:
    """The water ballast that floats the platform at its design draft: its volume [m³], the
    common level it fills the compartments to [m], what is missing where they are too small
    (negative: too much weight without any water) [kg], and the compartments' room [m³]."""

    volume: float
    level: float
    shortfall: float
    room: float


def trim(
    displaced: float, rho: float, carried: float, compartments: Sequence[tuple[Member, Fill]]
) -> Trim:
    """The water ballast that makes buoyancy ρV equal the ``carried`` mass (structure, fixed
    ballast, turbine, and the moorings' vertical pull over g) [kg], filling the variable
    compartments from the lowest up to one level (connected tanks keep the centre of mass
    as low as the compartments allow)."""
    need = displaced - carried / rho  # [m³]
    room = sum(capacity(m, f) for m, f in compartments)
    volume = float(np.clip(need, 0.0, room))
    if volume <= 0:
        return Trim(0.0, -np.inf, rho * need, room)
    return Trim(volume, level(compartments, volume), rho * (need - volume), room)
