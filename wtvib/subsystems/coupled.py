"""Whole-turbine modes: tower, nacelle, drive train and flexible blades coupled (Hau §7.6).

Hau's §7.6: where subsystems couple strongly, "complex vibrational coupling modes are
produced whose natural frequencies deviate distinctly from the separate natural frequencies
of the components". This module couples the models the other modules build — the tower
finite elements (:mod:`wtvib.subsystems.tower`), the blades' cantilever modes
(:mod:`wtvib.subsystems.blade`), the
drive-train chain (:mod:`wtvib.subsystems.drivetrain`) and the yaw spring
(:mod:`wtvib.subsystems.yaw`) — into one
model by Lagrange's equations, parked and rotating.

Model
-----
* Tower: fore-aft and side-side bending finite elements (base condition as the tower's),
  torsion elements where GJ is given; gravity loads the tower with the whole head's weight.
* Nacelle: a rigid body on the tower top, the tower head minus the rotor (blades as their
  mass distribution, hub as a point mass at the apex with its polar inertia), on the yaw
  spring where the spec has one.
* Drive train: the spec's chain without its blades — hub first — on the shaft through the
  apex; the generator locked (parked, Jonkman et al. 2009 Table 9-1) or free (rotating).
* Blades: each blade's lowest cantilever modes (flap and edge mixed by structural twist), as
  point masses at the blade elements' Gauss points; rotation adds the centrifugal (geometric)
  stiffness of the blade model and, from the kinematics, in-plane softening, Coriolis and
  gyroscopic terms.

Method
------
Every material point of the rotor has the position p = u + R(θ)·[a + Rₓ(ψⱼ + φ)·b(η)] (tower
top displacement u, nacelle rotation vector θ, apex a, blade azimuth ψⱼ = ψ + 2π(j−1)/N,
drive-train rotation φ, blade deflection b). It is expanded to second order in the small
coordinates q (p ≈ p₀ + P₁q + ½qᵀP₂q) and its azimuth derivatives; the kinetic energy
T = ½Σ m |ṗ|² then gives, with ψ = Ωt,

    M q̈ + (Ω·dM/dψ + C − Cᵀ) q̇ + (K_V + Ω²·Σ m [P₁ᵀP₁″ + p₀″·P₂]) q = 0,
    M = Σ m P₁ᵀP₁,   C = Ω·Σ m [P₁ᵀP₁′ + p₀′·P₂]   (′ = d/dψ),

exact to first order. The hub's spin adds J_p·Ω gyroscopic coupling of nacelle tilt and yaw.
With three or more blades the multi-blade (Coleman) transformation
(:mod:`wtvib.subsystems.multiblade`)
turns the periodic equations into time-invariant ones in the fixed frame, so the rotating
modes are eigenvalues — cyclic blade modes split into backward and forward whirl, f ∓ 1P, as
in a fixed-frame Campbell diagram. Two-bladed rotors stay periodic: their parked modes are
computed, and their stability over the speed range by Floquet theory (:mod:`wtvib.numerics.floquet`,
check ``system.floquet``). This module builds the model and gives the audit its view
(``system.*`` modes, checks ``system.coupling`` and ``system.floquet``).

Assumed and neglected (stated in the report): shaft tilt, precone and prebend; blade
torsion and section rotary inertia; gravity on the blades; gyroscopic moments of drive-train
parts other than the hub (generator spinning at i·Ω); structural damping other than the
drive train's dampers. Aerodynamic damping at the operating points is added by
:mod:`wtvib.aero.aerodamping` where the spec has aerodynamics.

References
----------
M. H. Hansen, "Improved modal dynamics of wind turbines to avoid stall-induced vibrations",
Wind Energy 6 (2003) 179–195 (model structure, Coleman transformation, whirl naming);
G. Bir, "Multi-blade coordinate transformation and its application to wind turbine
analysis", AIAA 2008-1300 (MBC); Jonkman et al. 2009, NREL/TP-500-38060, Table 9-1.
"""

import functools
import re
from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any, Literal

import numpy as np
from numpy.typing import NDArray

from ..errors import SpecError
from ..judge import closeness
from ..judge.analysis import Analysis, Context, Damping, Subsystem, section_damping
from ..judge.resonance import standstill_stability
from ..numerics import beam, modal
from ..numerics.kinematics import (
    GENERATORS,
    PHI,
    TX,
    TY,
    TZ,
    UX,
    UY,
    Jet,
    MatrixJet,
    nacelle_rotation,
    rx,
    skew,
    spin,
)
from ..numerics.rigid import Rigid, nacelle, rotor_points
from ..results import Check, Mode, Rule, Sampled, Stiffened, Whirl, by_frequency, ordinal
from ..spec import BladeStructure, Spec
from ..spec.base import StiffnessDamping
from ..units import rpm_to_rad_s
from . import blade, drivetrain, imported, mass_damper, tower, yaw
from .multiblade import MODES_KEPT, Layout, Sweep, SystemModes, parked, sweep
from .periodic import stability_check

Array = NDArray[np.float64]
Index = NDArray[np.intp]

_RIGID = 6

#: Rotor speeds of the rotating sweep (0 … 1.1 × overspeed, the blade model's top speed too);
#: 30 points is the Campbell sweep the cost target was set for.
SPEED_SAMPLES = 30


# ---------------------------------------------------------------------------------------
# The parts


#: The undamped standstill modes solved at first (:meth:`Model.standstill_modes`): more than
#: the parked modes (3 × the kept ones + 2: 65 on a floating base) and a path's first point
#: (3 × MODES_KEPT: 48) ask; a model of hundreds of coordinates solves these alone.
STANDSTILL_SOLVED = 96


#: The tower's own modes a plane a coupled tower ordinal is compared with
#: (:attr:`Model.tower_curvatures`): beyond them an ordinal is not checked — a coupled model
#: keeps MODES_KEPT modes and a few more, a floating platform's two rigid motions a plane
#: counted among the tower's.
TOWER_MODES_NAMED = 12


@dataclass(frozen=True)
class BladeModes:
    """One blade's lowest cantilever modes evaluated at its Gauss points (point masses)."""

    names: tuple[str, ...]  # flap1, edge1, flap2, …
    omega: Array  # standstill circular frequencies, (K,)
    geometric: Array  # ΦᵀK_geo(Ω = 1)Φ, centrifugal stiffness per Ω², (K, K)
    radius: Array  # distance from the rotor axis, (P,)
    mass: Array  # point masses, (P,)
    flap: Array  # out-of-plane deflection per mode, (P, K)
    edge: Array  # in-plane deflection per mode (direction of rotation), (P, K)
    length: Array  # blade length each point stands for (Gauss weight; 0: the tip mass), (P,)


def blade_modes(spec: Spec, count: int) -> BladeModes:
    """The blade's lowest ``count`` cantilever modes (wtvib.subsystems.blade model) at the Gauss
    points;
    computed once per spec object (one audit builds the model in several conditions)."""
    s = spec.blade.structure
    assert s is not None
    dofs = tuple(spec.blade.dofs) if spec.blade.dofs is not None else None
    out: BladeModes = spec.derived(
        ("coupled.blade_modes", count, dofs),
        s,
        lambda: _blade_modes(s, blade.fe_model(spec), count, dofs),
    )
    return out


def _blade_modes(
    s: BladeStructure, fe: "blade.BladeFE", count: int, dofs: tuple[str, ...] | None = None
) -> BladeModes:
    points = rotor_points(s.hub_radius_m, np.asarray(s.span_m), np.asarray(s.mass_per_length_kg_m))
    nodes, b = points.nodes, points.basis
    # the tension's geometric stiffness only: the kinematics give the in-plane softening;
    # the standstill modes are the blade model's own (the same mesh: rigid.rotor_points)
    assert np.array_equal(nodes, fe.nodes)
    geo = fe.geo
    if dofs is None:
        keep = np.arange(min(count, len(fe.standstill.frequency_hz)))
    else:  # a deck's degrees of freedom: those of the standstill modes, by name
        names = blade.plane_names(fe.standstill.shapes)
        keep = np.array([j for j, n in enumerate(names) if n in dofs], dtype=int)
    frequency_hz, phi = fe.standstill.frequency_hz[keep], fe.standstill.shapes[:, keep]
    full = np.vstack([np.zeros((4, phi.shape[1])), phi])
    n_el = len(nodes) - 1
    w_dofs = beam.chain_dofs(n_el, 4, (0, 1))
    v_dofs = beam.chain_dofs(n_el, 4, (2, 3))
    points_n = b.n.shape[0] * b.n.shape[1]  # Gauss points (element × point)
    # the deflections as the blade model interpolates them (Hermite or Timoshenko)
    h_w, h_v = blade.deflections(s, nodes)
    on = full[np.concatenate([w_dofs, v_dofs], axis=1)]
    flap = np.einsum("ega,eak->egk", h_w, on).reshape(points_n, phi.shape[1])
    edge = np.einsum("ega,eak->egk", h_v, on).reshape(points_n, phi.shape[1])
    radius, mass = points.radius, points.mass
    length = np.asarray(b.w, float).ravel()
    if s.tip_mass_kg:  # one more point: the tip mass, moving with the tip node
        radius = np.append(radius, s.hub_radius_m + nodes[-1])
        mass = np.append(mass, s.tip_mass_kg)
        length = np.append(length, 0.0)
        flap = np.vstack([flap, full[-4]])
        edge = np.vstack([edge, full[-2]])
    return BladeModes(
        tuple(blade.plane_names(phi)),
        2 * np.pi * frequency_hz,
        phi.T @ geo @ phi,
        radius,
        mass,
        flap,
        edge,
        length,
    )


@dataclass(frozen=True)
class Model:
    """The coupled model of one turbine in one generator condition."""

    spec: Spec
    condition: str
    layout: Layout
    k_v: Array  # elastic (potential) stiffness, rotor-speed independent
    d_v: Array  # the drive train's dampers and generator coupling (grid), speed independent
    m_fixed: Array  # mass of the non-rotating parts, with the hub
    rotor: BladeModes
    nacelle: Rigid
    hub_mass: float
    hub_polar: float
    apex: Array
    blades: int
    assumptions: tuple[str, ...]
    #: the part of k_v that is the head's weight on the bending tower (geometric stiffness,
    #: not material: a stiffness-proportional damping does not act on it); None: no gravity
    k_gravity: Array | None = None

    @property
    def k_blades(self) -> int:
        return len(self.rotor.names)

    @functools.cached_property
    def multiblade(self) -> tuple[Array, Array, Array, Array, Array]:
        """M, D₀, D₁, K₀, K₂ of the multi-blade equations: D = D₀ + Ω·D₁ and
        K = K₀ + Ω²·K₂ exactly (every rotating term is Ω or Ω² times a constant matrix; D₀
        holds the drive train's dampers)."""
        from .multiblade import fixed_frame  # the transformation lives there

        m, d0, k0 = self.standstill
        _, d1, k1 = fixed_frame(self, 1.0)
        return m, d0, d1 - d0, k0, k1 - k0

    @functools.cached_property
    def standstill(self) -> tuple[Array, Array, Array]:
        """M, D, K in multi-blade coordinates at standstill, blade 1 up (Ω = 0, ψ = 0):
        the parked modes' and the multi-blade equations' constant terms."""
        from .multiblade import fixed_frame

        return fixed_frame(self, 0.0)

    @functools.cached_property
    def groups(self) -> dict[str, Index]:
        """The coordinate groups its modes are named by (:func:`multiblade.coordinate_groups`),
        once per model — a sweep names or labels its modes at every speed; read-only."""
        from .multiblade import coordinate_groups

        out = coordinate_groups(self)
        for index in out.values():
            index.flags.writeable = False
        return out

    @functools.cached_property
    def tower_curvatures(self) -> dict[str, Array]:
        """The tower's own bending modes in each plane (``tower.fa``, ``tower.ss``) as
        curvatures — the change of slope from node to node, a column each, lowest first:
        the isolated tower of :mod:`wtvib.subsystems.tower`, its head as the tower's modes
        carry it (:func:`tower.bending_head`), on the coupled model's nodes. A coupled mode is
        named the tower's k-th bending only where it bends the tower as the k-th of these
        (:func:`multiblade._bends_as_its_own`); none for a rigid tower."""
        spec = self.spec
        if spec.tower.rigid:
            return {}
        found: dict[str, Array] = spec.derived(
            ("coupled.tower_curvatures", 0), spec, lambda: _tower_curvatures(spec)
        )
        return found

    def standstill_modes(self, count: int) -> modal.Modes:
        """The lowest ``count`` undamped modes at standstill, blade 1 up (K₀ and M of
        :attr:`standstill`): solved once for the Ritz bases and the parked modes — at least
        STANDSTILL_SOLVED of them (every one of a small model), again where more are asked."""
        solved: modal.Modes | None = self.__dict__.get("_standstill_modes")
        size = self.layout.size
        if solved is None or min(count, size) > len(solved.frequency_hz):
            m, _, k0 = self.standstill
            solved = modal.solve(k0, m, min(max(count, STANDSTILL_SOLVED), size))
            self.__dict__["_standstill_modes"] = solved  # frozen: the cache lives in __dict__
        return modal.lowest(solved, count)

    def ritz(self, count: int) -> tuple[Array, tuple[Array, Array, Array, Array, Array]]:
        """A reduced basis Φ — the lowest ``count`` undamped standstill modes in
        multi-blade coordinates and what the loads of the dampers (D₀) and of the rotation
        (K₂, D₁) on the lowest ``multiblade.RITZ_IMAGES`` excite beyond them, M-orthonormal
        (:func:`wtvib.numerics.modal.ritz_basis`) — and the multi-blade matrices projected on it,
        ΦᵀXΦ (computed once per model and count): the sweep and the damped solves at the
        operating points run in it."""
        from .multiblade import RITZ_IMAGES

        cache = self.__dict__.setdefault("_ritz", {})  # frozen: the cache lives in __dict__
        if count not in cache:
            m, d0, d1, k0, k2 = self.multiblade
            basis = modal.ritz_basis(
                k0, m, count, [k2, d1, d0], RITZ_IMAGES, self.standstill_modes(count)
            )
            cache[count] = (basis, tuple(basis.T @ x @ basis for x in (m, d0, d1, k0, k2)))
        out: tuple[Array, tuple[Array, Array, Array, Array, Array]] = cache[count]
        return out

    def matrices(self, omega: float, psi: float) -> tuple[Array, Array, Array]:
        """M, D, K of the periodic equations at rotor speed Ω [rad/s] and azimuth ψ."""
        lay = self.layout
        m = self.m_fixed.copy()
        d = self.d_v.copy()
        k = self.k_v.copy()
        kb = self.k_blades
        n = _RIGID + kb
        r = self.rotor
        mm = np.repeat(r.mass, 3)
        # parked: the mass matrix needs first-order terms only
        b, rot = self._blade_points(second_order=omega != 0.0)
        g = GENERATORS[0]
        for j in range(self.blades):
            rj = rx(psi + 2 * np.pi * j / self.blades)
            v = b.rotated(rj)
            p = rot.apply(Jet(v.c0 + self.apex, v.c1, v.c2))
            p1 = p.c1.reshape(-1, n).copy()
            p1[0::3, UX] += 1.0
            p1[1::3, UY] += 1.0
            self._scatter(m, (p1 * mm[:, None]).T @ p1, j)
            if p.c2 is None:
                continue
            blk = slice(lay.blades.start + j * kb, lay.blades.start + (j + 1) * kb)
            p2 = p.c2.reshape(-1, n, n)
            d1 = rot.apply(b.rotated(rj @ g))
            d2 = rot.apply(b.rotated(rj @ g @ g))
            d1c1 = d1.c1.reshape(-1, n)
            m_psi = (d1c1 * mm[:, None]).T @ p1
            c_loc = omega * (
                (p1 * mm[:, None]).T @ d1c1 + np.tensordot(mm * d1.c0.ravel(), p2, axes=1)
            )
            k_loc = omega**2 * (
                (p1 * mm[:, None]).T @ d2.c1.reshape(-1, n)
                + np.tensordot(mm * d2.c0.ravel(), p2, axes=1)
            )
            self._scatter(d, omega * (m_psi + m_psi.T) + c_loc - c_loc.T, j)
            self._scatter(k, k_loc, j)
            k[blk, blk] += omega**2 * r.geometric
        # the hub's spin: J_p·Ω couples nacelle tilt and yaw (T ⊃ ½J_pΩ(θ_zθ̇_y − θ_yθ̇_z))
        c_hub = np.zeros((_RIGID, _RIGID))
        c_hub[TY, TZ] = 0.5 * self.hub_polar * omega
        c_hub[TZ, TY] = -0.5 * self.hub_polar * omega
        self._scatter(d, c_hub - c_hub.T, 0, rigid_only=True)
        return m, d, k

    def _blade_points(self, second_order: bool) -> tuple[Jet, MatrixJet]:
        """A blade's points in the hub frame, turned by the drive train (before the blade's
        azimuth), and the nacelle's rotation to apply after it."""
        n = _RIGID + self.k_blades
        r = self.rotor
        c1 = np.zeros((len(r.radius), 3, n))
        c1[:, 0, _RIGID:] = r.flap
        c1[:, 1, _RIGID:] = -r.edge  # in-plane, direction of rotation at ψ = 0 is −y
        c0 = np.zeros((len(r.radius), 3))
        c0[:, 2] = r.radius
        c2 = np.zeros((len(r.radius), 3, n, n)) if second_order else None
        turn = spin(n, self.layout.local[0][PHI] >= 0)
        return turn.apply(Jet(c0, c1, c2)), nacelle_rotation(n)

    @functools.cached_property
    def section_velocity(self) -> Array:
        """(blades, P, 2, n): each blade point's velocity out of the rotor plane (downwind)
        and in it (direction of rotation) per rate of the blade's local coordinates, at
        ψ = 0 — first order, the directions those of the undeflected rotor (the section
        velocities an aerodynamic damping acts on)."""
        b, rot = self._blade_points(second_order=False)
        out = []
        for j in range(self.blades):
            rj = rx(2 * np.pi * j / self.blades)
            v = b.rotated(rj)
            p1 = rot.apply(Jet(v.c0 + self.apex, v.c1, None)).c1.copy()
            p1[:, 0, UX] += 1.0
            p1[:, 1, UY] += 1.0
            tangent = rj @ np.array([0.0, -1.0, 0.0])
            out.append(np.stack([p1[:, 0, :], np.einsum("i,pin->pn", tangent, p1)], axis=1))
        return np.stack(out)

    @functools.cached_property
    def active(self) -> Index:
        """The coordinates the blades' sections move (each blade's modes and the tower top's,
        nacelle's and shaft's motion they ride on) and the generator's (:attr:`generator`),
        ascending — the blades' last: the rows and columns an operating point's damping
        matrix fills (a few dozen of the hundreds a tower on a monopile has)."""
        local = self.layout.local
        found = local[local >= 0]
        if self.generator is not None:
            found = np.append(found, self.generator)
        out = np.unique(found).astype(np.intp)
        out.flags.writeable = False
        return out

    @property
    def generator(self) -> int | None:
        """The generator's coordinate: the drive-train chain's last (the hub's where the
        chain is one mass); None without a chain."""
        chain = self.layout.chain
        return chain.stop - 1 if chain.stop > chain.start else None

    def section_damping(self, c: Array) -> Array:
        """The damping matrix (ψ = 0) of section forces −c·v per blade point, on the
        coordinates :attr:`active` (zero elsewhere): ``c`` (…, P, 2, 2) [N·s/m] acts on the
        (out-of-plane, in-plane) velocity — a stack of such tables (the operating points)
        gives the stack of matrices."""
        lead = c.shape[:-3]
        size = len(self.active)
        d = np.zeros((*lead, size, size))
        flat = c.reshape(*lead, -1)
        n = self.section_velocity.shape[-1]
        where = np.searchsorted(self.active, np.maximum(self.layout.local, 0))
        for j, products in enumerate(self._velocity_products):
            # Σ_{p,a,b} c[p, a, b]·J[p, a, :]ᵀ·J[p, b, :]: one product with the table
            self._scatter(d, (flat @ products).reshape(*lead, n, n), j, at=where[j])
        return d

    @functools.cached_property
    def _velocity_products(self) -> Array:
        """(blades, P·2·2, n·n): J[p, a, i]·J[p, b, k] of each blade's section velocities."""
        jac = self.section_velocity
        b, p, _, n = jac.shape
        return np.asarray(np.einsum("jpai,jpbk->jpabik", jac, jac).reshape(b, p * 4, n * n))

    def _scatter(
        self,
        target: Array,
        local: Array,
        blade_no: int,
        rigid_only: bool = False,
        at: Index | None = None,
    ) -> None:
        """Add a blade's local matrix into ``target`` at its global coordinates (``at``: at
        those positions instead, of a matrix on fewer coordinates; held ones left out)."""
        idx = self.layout.local[blade_no]
        sgn = self.layout.sign[blade_no]
        if rigid_only:
            idx, sgn = idx[:_RIGID], sgn[:_RIGID]
        keep = np.flatnonzero(idx >= 0)
        i, s = (idx if at is None else at)[keep], sgn[keep]
        # the last two axes (a stack of matrices keeps its leading ones)
        part = local[..., keep[:, None], keep[None, :]]
        target[..., i[:, None], i[None, :]] += s[:, None] * part * s[None, :]


def _rigid_mass(part: Rigid) -> Array:
    """Mass matrix of a rigid part in the local rigid coordinates (u, θ)."""
    jac = np.zeros((3, _RIGID))
    jac[0, UX] = jac[1, UY] = 1.0
    jac[:, TX : TZ + 1] = -skew(part.c)  # θ̇ × c = −c × θ̇
    m = part.mass * jac.T @ jac
    m[TX : TZ + 1, TX : TZ + 1] += np.diag(part.inertia)
    return m


def _nacelle(spec: Spec, rotor: BladeModes, hub_mass: float, hub_polar: float) -> Rigid:
    """The tower head minus the rotor: what stays rigid on the tower top."""
    head, cm = spec.tower_head, spec.coupled
    assert head is not None and cm is not None
    n = spec.rotor.blades
    return nacelle(
        head,
        np.array([cm.apex_downwind_m, 0.0, cm.apex_above_top_m]),
        n * float(rotor.mass.sum()) + hub_mass,
        n * float(np.sum(rotor.mass * rotor.radius**2)) + hub_polar,
    )


def _tower_curvatures(spec: Spec) -> dict[str, Array]:
    """:attr:`Model.tower_curvatures`, solved once per spec: the same for every generator
    condition's model (the tower and its head do not change with it)."""
    t = spec.tower
    b, head = tower.discretise(t), tower.bending_head(spec)
    pair = tower.bending_pair(
        b, head, t.point_masses, t.foundation, t.gravity, count=TOWER_MODES_NAMED
    )
    out = {
        part: np.diff(modes.shapes[1::2], axis=0)
        for part, modes in zip(("tower.fa", "tower.ss"), pair, strict=True)
    }
    for found in out.values():
        found.flags.writeable = False  # shared by the conditions' models
    return out


def build(spec: Spec, condition: str) -> Model:
    """The coupled model of the spec in a generator condition (``locked``, ``free`` or
    ``grid``); built once per spec object and condition (an audit asks for it for the modes,
    the coupling table and the two-bladed Floquet check)."""
    key = ("coupled.model." + condition, 0)
    model: Model = spec.derived(key, spec, lambda: _build(spec, condition))
    return model


def _build(spec: Spec, condition: str) -> Model:
    cm = spec.coupled
    t = spec.tower
    if cm is None or spec.blade.structure is None or spec.tower_head is None:
        raise SpecError("the coupled model needs coupled, blade.structure and tower_head")
    if not t.has_structure:
        raise SpecError("the coupled model needs the tower's structure (sections or table)")
    notes: list[str] = []
    rotor = blade_modes(spec, cm.blade_modes)
    parts_k, parts_m, parts_g = _tower_parts(spec, notes)
    n_tor = parts_k[2].shape[0] if len(parts_k) == 3 else 0
    k_yaw = _yaw_spring(spec, n_tor, notes)
    chain = _chain(spec, condition, notes)
    lay = _layout(
        [part.shape[0] for part in parts_k[:2]], n_tor, k_yaw, chain.m.shape[0], spec, rotor
    )
    k_v, m_fixed = _tower_blocks(parts_k, lay), _tower_blocks(parts_m, lay)
    k_gravity = _tower_blocks(parts_g, lay) if parts_g else None
    d_v = np.zeros((lay.size, lay.size))
    if lay.yaw is not None:
        assert k_yaw is not None
        # the yaw drive: its spring and its dashpot (ServoDyn's YawDamp) between the nacelle
        # and the tower top's torsion (the ground, where torsion is not modelled)
        c_yaw = spec.yaw.drive_damping_nms_rad or 0.0
        for mat, value in ((k_v, k_yaw), (d_v, c_yaw)):
            mat[lay.yaw, lay.yaw] += value
            if n_tor:
                top = lay.torsion.stop - 1
                mat[top, top] += value
                mat[top, lay.yaw] -= value
                mat[lay.yaw, top] -= value
    ch, n_chain = lay.chain, chain.m.shape[0]
    if n_chain:
        k_v[ch, ch] = chain.k
        d_v[ch, ch] = chain.d
        m_fixed[ch, ch] = chain.m
    _add_dampers(spec, lay, k_v, d_v, m_fixed, [part.shape[0] for part in parts_k[:2]])
    kb = len(rotor.names)
    for j in range(spec.rotor.blades):
        blk = slice(lay.blades.start + j * kb, lay.blades.start + (j + 1) * kb)
        k_v[blk, blk] += np.diag(rotor.omega**2)

    nacelle = _nacelle(spec, rotor, cm.hub_mass_kg, chain.hub_polar)
    apex = np.array([cm.apex_downwind_m, 0.0, cm.apex_above_top_m])
    hub_i = np.array([0.0, 0.5 * chain.hub_polar, 0.5 * chain.hub_polar])
    rigid = _rigid_mass(nacelle) + _rigid_mass(Rigid(cm.hub_mass_kg, apex, hub_i))
    if n_chain:
        # chain masses spin about the shaft (x): roll couples with their rotations
        for i in range(n_chain):
            g = ch.start + i
            rigid[TX, TX] += chain.own[i]
            _add_pair(m_fixed, lay.local[0, TX], g, -chain.coupling[i])  # θₓ dof is −u_y′
    else:
        rigid[TX, TX] += chain.hub_polar
    model = Model(
        spec,
        condition,
        lay,
        k_v,
        d_v,
        m_fixed,
        rotor,
        nacelle,
        cm.hub_mass_kg,
        chain.hub_polar,
        apex,
        spec.rotor.blades,
        tuple(notes),
        k_gravity,
    )
    model._scatter(m_fixed, rigid, 0, rigid_only=True)
    return model


def _add_dampers(
    spec: Spec, lay: Layout, k: Array, d: Array, m: Array, sizes: Sequence[int]
) -> None:
    """The tuned mass dampers (:mod:`wtvib.subsystems.mass_damper`) on the tower's bending
    coordinates: each its own coordinate (``lay.dampers``), on its spring and dashpot to
    its mounting point (nothing moves on a rigid tower: the damper on a fixed mount)."""
    dampers = spec.tower.dampers
    if not dampers:
        return
    nodes = tower.discretise(spec.tower).nodes
    for j, damper in enumerate(dampers):
        plane = lay.fa if damper.direction == "fore-aft" else lay.ss
        size = sizes[0] if damper.direction == "fore-aft" else sizes[1]
        a = np.zeros(lay.size)
        if size:
            a[plane] = mass_damper.attachment(nodes, size, damper)
        x = lay.dampers.start + j
        m[x, x] += damper.mass_kg
        for mat, value in ((k, damper.stiffness_n_m), (d, damper.damping_ns_m)):
            mat += value * np.outer(a, a)
            mat[:, x] -= value * a
            mat[x, :] -= value * a
            mat[x, x] += value


def _tower_blocks(parts: Sequence[Array], lay: Layout) -> Array:
    """The tower's fore-aft, side-side and torsion matrices (as many as given) placed on
    the model's coordinates."""
    out = np.zeros((lay.size, lay.size))
    for part, sl in zip(parts, (lay.fa, lay.ss, lay.torsion), strict=False):
        out[sl, sl] = part
    return out


def _tower_parts(spec: Spec, notes: list[str]) -> tuple[list[Array], list[Array], list[Array]]:
    """The tower's stiffness and mass in fore-aft and side-side bending and, where it has a
    GJ, torsion — on its foundation, the head left to the coupled model — and the weight's
    part of the tower's bending stiffness (none without gravity, or on a floater)."""
    t = spec.tower
    b = tower.discretise(t)
    parts_k: list[Array] = []
    parts_m: list[Array] = []
    parts_g: list[Array] = []
    if t.rigid:  # every tower DOF off in the deck: the nacelle on a fixed tower top
        notes.append("the tower held rigid (the deck switches its DOFs off)")
        empty = np.zeros((0, 0))
        return [empty, empty], [empty, empty], []
    directions: tuple[Literal["fa", "ss"], ...] = ("fa", "ss")
    for direction in directions:
        k, m = tower.bending_system(
            b, spec.tower_head, t.point_masses, t.foundation, direction, t.gravity, False
        )
        parts_k.append(k)
        parts_m.append(m)
        # the weight's softening of a tower that stands on the ground; on a floater it is
        # mostly the whole turbine's tilt, which the floater's restoring holds — not the
        # tower's bending (its share taken there: 1.3–1.4 on the OC3 spar's and OC4 semi's
        # pitch and roll, where the tower hardly bends), so none is separated
        if t.gravity and t.foundation.kind != "platform":
            k_elastic, _ = tower.bending_system(
                b, spec.tower_head, t.point_masses, t.foundation, direction, False, False
            )
            parts_g.append(np.asarray(k - k_elastic))
    if b.gj is not None and b.polar is not None:
        k, m = tower.torsion_system(b, None, t.foundation)
        parts_k.append(k)
        parts_m.append(m)
    else:
        notes.append("tower torsion not modelled (no GJ): the tower top does not twist")
    return parts_k, parts_m, parts_g


def _yaw_spring(spec: Spec, n_tor: int, notes: list[str]) -> float | None:
    """The yaw drive's stiffness (in series with the tower's torsion where the tower's own
    torsion is not modelled), None where the nacelle's yaw is held; 0 for a free yaw
    (``yaw.drive: free`` without a stiffness: the nacelle turns on the tower top with
    nothing to hold it, as ElastoDyn's yaw DOF without ServoDyn's yaw spring)."""
    if spec.yaw.free:
        notes.append("the nacelle free in yaw (yaw.drive: free, no yaw stiffness)")
        return 0.0
    if spec.yaw.has_model:
        k_yaw = yaw.model(spec).drive
        if n_tor == 0 and spec.yaw.tower_torsion_nm_rad:
            k_yaw = yaw.series(k_yaw, spec.yaw.tower_torsion_nm_rad)
        return k_yaw
    if n_tor == 0:
        notes.append("no yaw stiffness and no tower torsion: nacelle yaw held")
    return None


@dataclass(frozen=True)
class _Chain:
    """The drive train without its blades (the coupled model carries them), hub first:
    M, K, D, each mass's own inertia and its coupling to the nacelle's roll, the hub's polar
    inertia."""

    m: Array
    k: Array
    d: Array
    own: Array
    coupling: Array
    hub_polar: float


def _chain(spec: Spec, condition: str, notes: list[str]) -> _Chain:
    cm = spec.coupled
    assert cm is not None
    empty = np.zeros((0, 0))
    chain_m, chain_k, chain_d = empty, empty, empty
    coupling = own = np.zeros(0)
    hub_polar = cm.hub_inertia_kgm2 or 0.0
    dt = spec.drivetrain
    if dt.chain:
        rest = dt.chain[1:] if dt.chain[0].name == "blades" else dt.chain
        shafts = dt.shafts[1:] if dt.chain[0].name == "blades" else dt.shafts
        if shafts and all(s.stiffness_nm_rad is None and s.fluid_coupling is None for s in shafts):
            # a rigid drive shaft (a deck's DrTrDOF off, a HAWC2 model's rigid shaft): no
            # torsion between the hub and the generator, which turn as one mass — free
            # (the rotor's azimuth a degree of freedom: ElastoDyn's GenDOF on), on the
            # grid's spring, or held with the rotor's speed (locked: GenDOF off)
            notes.append("the drive shaft rigid: no drive-train torsion")
        if rest:  # one mass too: a rotor free on its bearing (held only where locked)
            sub = spec.model_copy(
                update={
                    "drivetrain": dt.model_copy(
                        update={"chain": rest, "shafts": shafts, "reference_shaft": "rotor"}
                    )
                }
            )
            reduced = drivetrain.reduce(sub, rigid_ok=True)
            chain_m, chain_k, chain_d = drivetrain.system(reduced, sub, condition)
            size = chain_m.shape[0]
            coupling, own = reduced.coupling[:size], reduced.own[:size]
            if size == 0:  # one rigid mass, held: the rotor turns at its speed
                hub_polar = cm.hub_inertia_kgm2 or rest[0].inertia_kgm2
            elif cm.hub_inertia_kgm2 is None:  # the hub's own (a rigid shaft merges more)
                hub_polar = (
                    float(chain_m[0, 0])
                    if reduced.names[0] == rest[0].name
                    else rest[0].inertia_kgm2
                )
            elif reduced.names[0] == rest[0].name:  # the given hub inertia replaces the hub's
                chain_m = chain_m.copy()
                chain_m[0, 0] = coupling[0] = own[0] = hub_polar
            else:  # the hub merged with what a rigid shaft joins to it: its share replaced
                chain_m = chain_m.copy()
                coupling, own = coupling.copy(), own.copy()
                delta = hub_polar - rest[0].inertia_kgm2
                chain_m[0, 0] += delta
                coupling[0] += delta
                own[0] += delta
    if chain_m.shape[0] == 0:
        notes.append("no flexible drive train: the rotor is held on the nacelle")
    return _Chain(chain_m, chain_k, chain_d, own, coupling, hub_polar)


def _layout(
    bending: list[int],
    n_tor: int,
    k_yaw: float | None,
    n_chain: int,
    spec: Spec,
    rotor: BladeModes,
) -> Layout:
    """The global degrees of freedom: the tower's fore-aft, side-side and torsion, the yaw
    drive's, the chain's, the tuned mass dampers', then each blade's modes; each blade's
    local coordinates mapped onto them (the tower top's and the shaft's motion, its own
    modes)."""
    n_fa, n_ss = bending
    kb = len(rotor.names)
    nb = spec.rotor.blades
    n_dampers = len(spec.tower.dampers)
    offsets = np.cumsum(
        [0, n_fa, n_ss, n_tor, 0 if k_yaw is None else 1, n_chain, n_dampers, nb * kb]
    )
    size = int(offsets[-1])
    fa, ss, tor = (slice(int(offsets[i]), int(offsets[i + 1])) for i in range(3))
    yaw_dof = None if k_yaw is None else int(offsets[3])
    ch = slice(int(offsets[4]), int(offsets[5]))
    dampers = slice(int(offsets[5]), int(offsets[6]))
    bl = slice(int(offsets[6]), int(offsets[7]))
    theta_z = yaw_dof if yaw_dof is not None else (tor.stop - 1 if n_tor else -1)
    local = np.full((nb, _RIGID + kb), -1, dtype=np.intp)
    sign = np.ones((nb, _RIGID + kb))
    for j in range(nb):
        local[j, UX], local[j, TY] = fa.stop - 2, fa.stop - 1
        local[j, UY], local[j, TX] = ss.stop - 2, ss.stop - 1
        sign[j, TX] = -1.0  # θₓ = −du_y/dz
        local[j, TZ] = theta_z
        local[j, PHI] = ch.start if n_chain else -1
        local[j, _RIGID:] = np.arange(bl.start + j * kb, bl.start + (j + 1) * kb)
    return Layout(size, fa, ss, tor, yaw_dof, ch, bl, local, sign, dampers)


def _add_pair(m: Array, i: int, j: int, value: float) -> None:
    """Add a symmetric off-diagonal pair (no-op where i is held)."""
    if i < 0:
        return
    m[i, j] += value
    m[j, i] += value


def applies(spec: Spec) -> bool:
    """Whether the spec asks for (and has what the coupled model needs)."""
    return (
        spec.coupled is not None
        and spec.blade.structure is not None
        and spec.tower_head is not None
        and spec.tower.has_structure
        and spec.rotor.orientation != "vertical-axis"
        # a deck with its tower and blades switched rigid has nothing left to couple
        and not (spec.tower.rigid and spec.blade.dofs == [])
    )


def speeds(spec: Spec) -> Array:
    """Rotor speeds of the sweep: standstill to the overspeed limit [rad/s] (nothing is
    judged beyond it, so nothing is computed or drawn there)."""
    top = float(rpm_to_rad_s(spec.rotor.speed.overspeed))
    return np.linspace(0.0, top, SPEED_SAMPLES)


def rotating_sweep(spec: Spec) -> Sweep:
    """The rotating sweep of the coupled model in the spec's rotating condition (three or
    more blades), once per spec object: the Campbell curves of the coupled modes, and the
    modes the damped solves at the operating points continue (aerodamping)."""
    assert spec.coupled is not None
    cond = spec.coupled.rotating_condition
    key = ("coupled.sweep." + cond, 0)

    def solve() -> Sweep:
        model = build(spec, cond)
        found = sweep(model, speeds(spec), kept(spec))
        names, texts = platform_named(model, found.names, found.descriptions, found.path.shapes[0])
        return replace(found, names=names, descriptions=texts)

    found: Sweep = spec.derived(key, spec, solve)
    return found


#: The coupled model's names of a floating platform's modes (:func:`platform_named`).
PLATFORM = "platform."


def parked_named(model: Model) -> SystemModes:
    """The parked modes (:func:`wtvib.subsystems.multiblade.parked`), a floating platform's
    named."""
    res = parked(model, count=kept(model.spec))
    names, texts = platform_named(model, res.names, res.descriptions, res.shapes)
    return replace(res, names=names, descriptions=texts)


#: A floating turbine's coupled model holds five platform modes (surge, sway, roll, pitch
#: and yaw; heave has no degree of freedom in it) below its tower and rotor modes.
PLATFORM_MODES = 5


def kept(spec: Spec) -> int:
    """How many of the coupled model's lowest modes are kept: MODES_KEPT, and the platform's
    five on a floating base."""
    return MODES_KEPT + (PLATFORM_MODES if spec.tower.foundation.kind == "platform" else 0)


def platform_named(
    model: Model,
    names: Sequence[str],
    descriptions: Sequence[str],
    shapes: NDArray[np.complex128],
) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """On a floating base: the modes whose tower motion is mostly the whole turbine's rigid
    motion on the platform (:func:`wtvib.subsystems.tower.rigid_share`) named ``platform.<motion>``,
    the tower's own bending and torsion numbered after them (``tower.fa1`` is the first
    bending mode, not the platform's pitch). Elsewhere the names as they are."""
    p = model.spec.tower.foundation.platform
    if p is None:
        return tuple(names), tuple(descriptions)
    m = model.standstill[0]
    lay = model.layout
    heights = tower.discretise(model.spec.tower).nodes + p.tower_base_m
    platform: dict[str, int] = {}  # the platform's modes among each kind's, by kind
    out_names: list[str] = []
    out_texts: list[str] = []
    tower_modes: list[tuple[int, str]] = []  # the tower's own: where, and of which kind
    for j, (name, text) in enumerate(zip(names, descriptions, strict=True)):
        z = shapes[:, j]
        x = np.real(z * np.conj(z[np.argmax(np.abs(z))]))  # a standstill shape, real
        kind = next((k for k in ("tower.fa", "tower.ss", "tower.tor") if name.startswith(k)), None)
        if kind is None:
            out_names.append(name)
            out_texts.append(text)
            continue
        block = {"tower.fa": lay.fa, "tower.ss": lay.ss, "tower.tor": lay.torsion}[kind]
        xb, mb = x[block], m[block, block]
        if kind == "tower.tor":
            # the tower turning whole on the platform's yaw
            share = tower.motion_share(xb, mb, np.ones((len(xb), 1)))
            motion = "yaw"
        else:
            direction: Literal["fa", "ss"] = "fa" if kind == "tower.fa" else "ss"
            share = tower.rigid_share(xb, mb, heights)
            motion = tower.platform_motion(p, direction, xb[:2], None)
        if share >= tower.PLATFORM_SHARE:
            out_names.append(f"platform.{motion}")
            out_texts.append(f"platform {motion} (coupled model, added mass A∞)")
            platform[kind] = platform.get(kind, 0) + 1
            continue
        tower_modes.append((j, kind))
        out_names.append(name)
        out_texts.append(text)
    # every tower ordinal — the mode's id, its description, what it is at standstill or at
    # the top speed — counted without the platform's modes below the tower's own: the id as
    # its text (a tower mode named by another family, a blade whirl, leaves its ordinal out)
    for j, kind in tower_modes:
        rest = out_names[j][len(kind) :]
        number = rest[: len(rest) - len(rest.lstrip("0123456789"))]
        n = int(number) - platform.get(kind, 0) if number else 1
        out_names[j] = f"{kind}{max(n, 1)}{rest[len(number) :]}"
    return tuple(out_names), tuple(_platform_counted(t, platform) for t in out_texts)


_TOWER_ORDINAL = re.compile(r"\b(\d+)(?:st|nd|rd|th) tower (fore-aft|side-side|torsion)\b")
_TOWER_KIND = {"fore-aft": "tower.fa", "side-side": "tower.ss", "torsion": "tower.tor"}


def _platform_counted(text: str, platform: Mapping[str, int]) -> str:
    """``text`` with each "Nth tower fore-aft/side-side/torsion" renumbered without the
    ``platform`` modes of that kind (a floating turbine's rigid-body modes, the lowest)."""

    def shifted(match: re.Match[str]) -> str:
        n = int(match.group(1)) - platform.get(_TOWER_KIND[match.group(2)], 0)
        if n < 1:  # one of the platform's own modes
            return f"the platform's rigid-body motion ({match.group(2)})"
        return f"{ordinal(n)} tower {match.group(2)}"

    return _TOWER_ORDINAL.sub(shifted, text)


#: A coupled mode kept for its content (beyond the lowest MODES_KEPT) stands for its isolated
#: namesake only within this factor of its frequency; farther off it is another mode of the
#: same part (IEA-15: the isolated tower torsion, 0.77 Hz, turns the rigid rotor's yaw
#: inertia; the coupled model's first mode dominated by tower torsion is at 8.9 Hz, the
#: rotor's yaw having gone into the cyclic flap mode). wtvib's choice: the isolated second
#: tower modes lie up to a factor 1.5 from their coupled ones (Hau §7.6's "distinctly").
PAIRED = 1.6


def modes(spec: Spec, isolated: Mapping[str, Mode] | None = None) -> list[Mode]:
    """Coupled modes (ids ``system.<name>``) with their fixed-frame curves over rotor speed;
    ``isolated``: the isolated modes by id (their frequencies for :data:`PAIRED`).

    Three or more blades: the rotating sweep in the spec's rotating condition; one or two
    blades: the parked modes (periodic system; the Floquet check covers rotation), a blade
    mode among them stiffened over speed as its isolated blade mode (:func:`_turning`).
    """
    if not applies(spec):
        return []
    assert spec.coupled is not None
    cond = spec.coupled.rotating_condition
    model = build(spec, cond)
    given = isolated or {}
    known = {k: m.frequency_hz for k, m in given.items()}
    if spec.rotor.blades < 3:
        return [_turning(m, cond, given) for m in _parked_modes(spec, model, cond, known)]
    return _rotating_modes(spec, model, cond, known)


@dataclass(frozen=True)
class _Standing:
    """What a coupled mode stands for: its isolated counterpart (:func:`counterparts`) and
    the regimes it exists in (the drive train's modes in its generator condition)."""

    spec: Spec
    condition: str
    known: Mapping[str, float]
    pairs: Mapping[str, str]
    chained: Collection[str]

    def exists(self, name: str) -> frozenset[str] | None:
        if name.startswith("drivetrain"):
            return drivetrain.regimes(self.spec, self.condition)
        return None

    def stands_for(self, j: int, name: str, f: float) -> str | None:
        iso = self.pairs[name]
        if j < kept(self.spec) or iso not in self.known or name in self.chained:
            return iso
        return iso if max(f, self.known[iso]) <= PAIRED * min(f, self.known[iso]) else None


def _parked_modes(spec: Spec, model: Model, cond: str, known: Mapping[str, float]) -> list[Mode]:
    """A two-bladed turbine's coupled modes: parked only (its rotation is periodic)."""
    res = parked_named(model)
    at = _Standing(spec, cond, known, *counterparts(spec, res.names, cond))
    return [
        Mode(
            f"system.{n}",
            "system",
            f"{d}, parked (coupled)",
            float(f),
            regimes=at.exists(n),
            condition=f"coupled model, generator {cond}, parked",
            origin="coupled",
            replaces=at.stands_for(j, n, float(f)),
        )
        for j, (f, n, d) in enumerate(
            zip(res.frequency_hz, res.names, res.descriptions, strict=True)
        )
        if not n.startswith(PLATFORM)
    ]


def _rotating_modes(spec: Spec, model: Model, cond: str, known: Mapping[str, float]) -> list[Mode]:
    """The rotating sweep's modes, each with its curve, whirl and damping: the parts'
    material damping weighted by strain energy, with the drive train's and tuned mass
    dampers' added where they give some. A floating platform's modes are left to the
    isolated model (judged at their own frequency)."""
    sw = rotating_sweep(spec)
    omega = tuple(sw.omega.tolist())
    order = np.argsort(sw.frequency_hz[0])
    at = _Standing(spec, cond, known, *counterparts(spec, [sw.names[j] for j in order], cond))
    weighted = strain_weighted(spec, model, sw.path.shapes[0], sw.frequency_hz[0])
    lower = default_damping(spec)
    said = "the drive train's dampers" + (
        " and the tuned mass dampers" if spec.tower.dampers else ""
    )
    out = []
    for j, name in enumerate(sw.names):
        if name.startswith(PLATFORM):
            continue
        material = weighted[j]
        # the drive train's dampers (the eigenvalue damping at standstill) add to the
        # parts' own material damping: a tower mode that moves the gearbox a little must
        # not lose its structural damping to the dampers' 0.0002 (AOC 15/50: side-side
        # judged at ζ = 0.0011, DAF 450)
        ratio, source = material.with_dampers(float(sw.damping_ratio[j]), DAMPERS_FLOOR, said)
        if ratio is None and material is not lower:  # no dampers: the weighted material
            ratio, source = material.ratio, material.source
        labels = sw.whirl[j]
        whirl = (
            Whirl(omega, tuple(w or "fixed" for w in labels))
            if any(w is not None for w in labels)
            else None
        )
        text = sw.descriptions[j]
        if name in at.chained and not name.startswith("drivetrain"):
            text += ", the drive train's first torsion (the blades against the generator)"
        out.append(
            Mode(
                f"system.{name}",
                "system",
                text,
                float(sw.frequency_hz[0, j]),
                damping_ratio=ratio,
                damping_source=source,
                curve=Sampled(omega, tuple(sw.frequency_hz[:, j].tolist())),
                regimes=at.exists(name),
                condition=f"coupled model, generator {cond}",
                whirl=whirl,
                origin="coupled",
                replaces=at.stands_for(j, name, float(sw.frequency_hz[0, j])),
            )
        )
    return sorted(out, key=by_frequency)


#: A coupled mode whose eigenvalue damping at standstill (the drive train's dampers) is below
#: this has none worth stating: its damping ratio is the parts' material damping alone.
DAMPERS_FLOOR = 1e-4


#: A coupled frequency within this fraction of its isolated counterpart "stays close" (wtvib's
#: reading of Hau §7.6's "close"; the book gives no figure).
CLOSE = 0.05


def counterparts(
    spec: Spec, names: Sequence[str], condition: str
) -> tuple[dict[str, str], frozenset[str]]:
    """The isolated mode each coupled mode (``names`` in frequency order) stands for
    (:func:`isolated_id`), with the drive train's chain paired in order: where the isolated
    chain puts the blades' edgewise spring first (``blade_edge_spring``), its first mode is
    the blades swinging edgewise, collectively, against the rest of the train — in the coupled
    model the collective edge mode, named for where its energy sits: ``drivetrain1`` where a
    geared generator holds much of it (the NREL 5-MW), ``blade.edge1.collective`` where a
    direct-drive generator holds little (the IEA-15: 1.7 Hz, the isolated chain's 7.7 Hz
    beside it was judged as a second mode). Those and the drive-train modes pair with
    ``drivetrain.<condition>.1, 2, …`` in order — by their place in the chain, however far
    the lumped chain's frequencies lie from the coupled ones (the second set returned)."""
    out = {n: isolated_id(n, condition) for n in names}
    dt = spec.drivetrain
    if dt is None or not dt.chain or not dt.blade_edge_spring or dt.chain[0].name != "blades":
        return out, frozenset()
    chain = [n for n in names if n.startswith("drivetrain") or n == "blade.edge1.collective"]
    for k, n in enumerate(chain, start=1):
        out[n] = f"drivetrain.{condition}.{k}"
    return out, frozenset(chain)


def isolated_id(name: str, condition: str) -> str:
    """The isolated subsystem mode a coupled mode grows out of (``tower.fa1`` → tower.fa1)."""
    base = name.split("_")[0] if name.startswith(("tower", "drivetrain", "yaw")) else name
    if base.startswith("tower."):
        return base
    if base.startswith("damper"):
        return f"tower.{base}"
    if base.startswith("drivetrain"):
        return f"drivetrain.{condition}.{base.removeprefix('drivetrain')}"
    if base.startswith("yaw"):
        return f"yaw.{base.removeprefix('yaw')}"
    return "blade." + name.split(".")[1]


def _judged_names(spec: Spec) -> dict[str, str]:
    """The judged modes' names (their whirl in operation) by their names at standstill
    (the axis a cyclic pair turns the rotor about); two blades: the same names."""
    if spec.rotor.blades < 3:
        return {}
    assert spec.coupled is not None
    sw = rotating_sweep(spec)
    first = sw.path.first
    # the standstill names as the parked modes have them: a floating platform's named
    # (its rigid-body modes come first, the tower's bending numbered after them)
    model = build(spec, spec.coupled.rotating_condition)
    standing, _ = platform_named(model, first.names, first.descriptions, first.shapes)
    return dict(zip(standing, sw.names, strict=True))


def check(spec: Spec, isolated: list[Mode]) -> Check | None:
    """Coupled frequencies at standstill against the isolated subsystems' (Hau §7.6).

    The table holds the coupled modes in the condition they are judged in (the rotating
    condition, at standstill), so each id has the frequency it has everywhere in the report;
    where the spec's parked condition differs (Jonkman et al. 2009 Table 9-1: generator
    locked), those frequencies follow in a separate, labelled list.
    """
    if not applies(spec):
        return None
    assert spec.coupled is not None
    cond = spec.coupled.rotating_condition
    model = build(spec, cond)
    res = parked_named(model)
    by_id = {m.id: m.frequency_hz for m in isolated}
    rows: list[dict[str, Any]] = []
    pairs, _ = counterparts(spec, res.names, cond)
    judged = _judged_names(spec)
    for j, (f, name) in enumerate(zip(res.frequency_hz, res.names, strict=True)):
        if name.startswith(PLATFORM):
            continue
        iso = pairs[name]
        f_iso = by_id.get(iso)
        # the judged mode's id and its own standstill value (damped |λ|, as in the modes
        # list): a cyclic pair is named at standstill by the axis it turns the rotor about,
        # in the report by its whirl in operation — one name per mode
        mode_id = f"system.{judged.get(name, name)}"
        f = by_id.get(mode_id, float(f))
        rows.append(
            {
                "id": mode_id,
                **({"standstill_shape": name} if judged.get(name, name) != name else {}),
                "coupled_hz": round(float(f), 6),
                "isolated_id": iso if f_iso is not None else None,
                "isolated_hz": round(f_iso, 6) if f_iso is not None else None,
                # + 0.0: a change rounded to nothing is 0, not −0 (its sign was rounding's)
                "change": round(float(f) / f_iso - 1.0, 6) + 0.0 if f_iso else None,
                "energy": {g: round(v, 4) for g, v in res.energy[j].items() if v >= 0.005},
            }
        )
    paired = [r for r in rows if r["change"] is not None]
    close = sum(1 for r in paired if abs(r["change"]) <= CLOSE)
    apart = sorted((r for r in paired if abs(r["change"]) > CLOSE), key=lambda r: -abs(r["change"]))
    shifts = "; ".join(
        f"{r['id']} {r['isolated_hz']:.3g} → {r['coupled_hz']:.3g} Hz ({r['change']:+.0%})"
        for r in apart[:3]
    )
    numbers: dict[str, Any] = {
        "condition": f"generator {cond}, standstill",
        "modes": rows,
        "model": list(_statements(model)),
    }
    other = spec.coupled.parked_condition
    if other != cond:
        alt = parked_named(build(spec, other))
        numbers["parked"] = {
            "condition": f"generator {other}, parked",
            "modes": [
                {"name": n, "frequency_hz": round(float(f), 6)}
                for f, n in zip(alt.frequency_hz, alt.names, strict=True)
            ],
        }
    return Check(
        id="system.coupling",
        subsystem="system",
        status="info",
        message=f"Coupled whole-turbine model at standstill, generator {cond}: {close} of the "
        f"{len(paired)} modes with an isolated counterpart lie within {CLOSE:.0%} of it (Hau "
        "§7.6: one mode dominates and stays close to the isolated subsystem's frequency)"
        + (f"; departing most: {shifts}" if shifts else "")
        + ". The coupled modes are the ones judged; the isolated values are shown beside them.",
        rule=Rule(
            "coupled modes vs isolated subsystems",
            "Hau, Wind Turbines, §7.6: strongly coupled subsystems produce coupling modes "
            "whose frequencies deviate distinctly from the separate natural frequencies",
        ),
        numbers=numbers,
    )


def _statements(model: Model) -> tuple[str, ...]:
    n = model.nacelle
    return (
        f"{model.blades} flexible blades × {model.k_blades} modes "
        f"({', '.join(model.rotor.names)}), nacelle {n.mass:,.0f} kg rigid, hub "
        f"{model.hub_mass:,.0f} kg / {model.hub_polar:,.0f} kg·m², generator {model.condition}",
        "neglected: shaft tilt, precone, blade torsion, gravity on the blades; damping in "
        "the parked model: the drive train's only",
        *(
            (
                "on its floating platform (surge, sway, roll, pitch, and yaw where the tower "
                "twists; heave has no degree of freedom here), the platform's added mass "
                "taken at A∞ for the tower and rotor modes; its own modes (platform.*) are "
                "judged from the isolated model, each at its own frequency",
            )
            if model.spec.tower.foundation.kind == "platform"
            else ()
        ),
        *model.assumptions,
    )


# ---------------------------------------------------------------------------------------
# The subsystem protocol (wtvib.judge.analysis)

NAME = "system"


def strain_weighted(
    spec: Spec, model: Model, shapes: NDArray[np.complex128], frequency_hz: Array
) -> list[Damping]:
    """Each coupled mode's material damping: the tower's and the blades' ratios weighed by
    the strain energy the mode puts in each (modal strain energy: ζ = Σ ζ_p·E_p / Σ E_p,
    E_p = Re x̄_pᵀ(K x)_p over the part's coordinates at standstill) — a second tower mode
    that hardly bends the blades takes the tower's ratio, not the lower of the two. A mode
    that strains neither (drive train, yaw) takes the lower (:func:`default_damping`).
    Where the tower's ratios are ElastoDyn's (``tower.damping_at: tower-alone``), the
    tower's part is :func:`_tower_alone_ratios`; the blades' likewise
    (``blade.damping_at: blade-alone``, :func:`_blade_alone_ratios`)."""
    tower_d = section_damping(spec.tower, "tower")
    blade_d = blade.default_damping(spec)
    k = model.multiblade[3]
    energy = np.abs(np.real(np.conj(shapes) * (k @ shapes)))
    # a tuned mass damper's spring has no material damping (its dashpot is in the model)
    parts = {kind: np.zeros(shapes.shape[1]) for kind in ("tower", "blade", "damper")}
    by_group = {}
    for group, index in model.groups.items():
        kind = group.split(".")[0]
        if kind in parts and len(index):
            by_group[group] = energy[index].sum(axis=0)
            parts[kind] += by_group[group]
    alone = _tower_alone_ratios(spec, model, shapes, frequency_hz)
    if alone is not None:  # ElastoDyn's: on the tower's material stiffness alone
        alone = alone * _material_share(model, shapes)
    if spec.tower.stiffness_damping_s is not None:
        alone = _stiffness_ratios(spec.tower.stiffness_damping_s, by_group, "tower", frequency_hz)
    blade_z: Array | None = None
    if spec.blade.stiffness_damping_s is not None:
        blade_z = _stiffness_ratios(spec.blade.stiffness_damping_s, by_group, "blade", frequency_hz)
    elif spec.blade.damping_at == "blade-alone":
        blade_z = _blade_alone_ratios(spec, by_group, frequency_hz)
    total = energy.sum(axis=0)
    lower = default_damping(spec)
    same = tower_d.ratio == blade_d.ratio and alone is None and blade_z is None
    if same and not spec.tower.dampers:
        return [lower] * shapes.shape[1]
    assumed = tower_d.assumed or blade_d.assumed
    out = []
    for j in range(shapes.shape[1]):
        e_t, e_b, e_d = parts["tower"][j], parts["blade"][j], parts["damper"][j]
        strained = e_t + e_b + e_d
        if strained < 0.5 * total[j] or total[j] <= 0:
            out.append(lower)
            continue
        z_t = tower_d.ratio if alone is None else float(alone[j])
        z_b = blade_d.ratio if blade_z is None else float(blade_z[j])
        zeta = (z_t * e_t + z_b * e_b) / strained
        share = e_t / max(e_t + e_b, 1e-300)
        how = ""
        if spec.tower.stiffness_damping_s is not None or spec.blade.stiffness_damping_s:
            how = f", tower {z_t:.3%}, blades {z_b:.3%}: stiffness-proportional, π·β·f"
        elif blade_z is not None:
            how = (
                f", tower {z_t:.3%}, blades {z_b:.3%}: ElastoDyn's ratios at the "
                "frequencies the deck's polynomials imply on the tower and blade alone, "
                "× f/f_alone"
            )
        elif alone is not None:
            how = (
                f", the tower's {z_t:.3%}: ElastoDyn's ratios at the frequencies the deck's "
                "polynomials imply on the tower alone, × f/f_alone"
            )
        if e_d > 0.5 * strained:
            out.append(Damping(zeta, "the tuned mass damper's dashpot (no material damping)",
                               False))  # fmt: skip
            continue
        out.append(
            Damping(
                zeta,
                f"tower.damping_ratio and blade.damping_ratio by the mode's strain energy "
                f"({share:.0%} tower, {1 - share:.0%} blades{how}; "
                f"{'assumed: not all given' if assumed else 'given'})",
                assumed,
            )
        )
    return out


def _material_share(model: Model, shapes: NDArray[np.complex128]) -> Array:
    """Each mode's tower strain energy in its material stiffness over that in its whole
    stiffness, the weight's (geometric, softening) part included — (modes,), 1 without
    gravity or on a floater (:func:`_tower_parts`). ElastoDyn damps the tower's degrees of
    freedom in proportion to their material stiffness (CTFA =
    0.01·TwrFADmp·KTFA/(π·FreqTFA(:,1)), KTFA without the weight's softening, which it
    adds apart), so a mode is damped at ζ·(f/f_alone)·E_el/E:
    the weight that lowers the tower's frequency does not lower its damping force (the
    NREL 5-MW's first tower pair under its head +4.5 … +8 %, as OpenFAST damps it,
    tests/validation/test_rtest_models.py). HAWC2's stiffness-proportional damping is
    taken as HAWCStab2 damps it, π·β·f (test_hawc2.py: within 2 % without this share, +7 %
    with it)."""
    g = model.k_gravity
    parts = [i for name, i in model.groups.items() if name.startswith("tower.")]
    if g is None or not parts:
        return np.ones(shapes.shape[1])
    index = np.concatenate(parts)
    k = model.multiblade[3][np.ix_(index, index)]
    x = shapes[index]
    whole = np.real(np.einsum("im,ij,jm->m", np.conj(x), k, x))
    material = whole - np.real(np.einsum("im,ij,jm->m", np.conj(x), g[np.ix_(index, index)], x))
    return np.where(whole > 0, material / np.where(whole > 0, whole, 1.0), 1.0)


def _stiffness_ratios(
    beta: "StiffnessDamping", by_group: dict[str, Array], part: str, frequency_hz: Array
) -> Array:
    """A part's damping ratio in each coupled mode where its damping is stiffness-
    proportional: π·β·f of each coordinate group's direction (tower.fa, tower.ss, tower.tor;
    the blades' flap and edge modes), weighed by the strain energy the mode puts there."""
    weighted = np.zeros_like(frequency_hz, dtype=float)
    energy = np.zeros_like(frequency_hz, dtype=float)
    for group, e in by_group.items():
        kind, *rest = group.split(".")
        if kind != part:
            continue
        direction = rest[0].rstrip("0123456789") if rest else ""
        weighted += e * beta.ratio(direction, 1.0) * frequency_hz
        energy += e
    return np.where(energy > 0, weighted / np.where(energy > 0, energy, 1.0), 0.0)


def _blade_alone_ratios(spec: Spec, by_group: Mapping[str, Array], frequency_hz: Array) -> Array:
    """The blades' damping ratio in each coupled mode where their ratios are ElastoDyn's
    (``blade.damping_at: blade-alone``): each blade mode's strain energy in the coupled
    mode (its multi-blade coordinates, ``blade.flap1.collective`` …) takes the ratio
    ElastoDyn gives its degree of freedom at the coupled frequency
    (:func:`blade.mode_damping`: ζ_k·f/f_alone,k)."""
    alone = blade.alone_frequencies(spec)
    weighted = np.zeros(len(frequency_hz))
    energy = np.zeros(len(frequency_hz))
    for group, e in by_group.items():
        parts = group.split(".")
        if parts[0] != "blade" or len(parts) < 2:
            continue
        zeta = np.array([blade.mode_damping(spec, parts[1], float(f), alone) for f in frequency_hz])
        weighted += e * zeta
        energy += e
    fallback = float(spec.blade.damping_ratio)
    return np.where(energy > 0, weighted / np.where(energy > 0, energy, 1.0), fallback)


def _tower_alone_ratios(
    spec: Spec, model: Model, shapes: NDArray[np.complex128], frequency_hz: Array
) -> Array | None:
    """The tower's damping ratio in each coupled mode where its ratios are ElastoDyn's
    (``damping_at: tower-alone``; None otherwise): ElastoDyn damps each tower mode k in
    proportion to its stiffness, c_k = 2ζ_k·k_k/ω_alone,k, so that a mode at f whose tower
    bending is mode k carries ζ_k·f/f_alone,k (:func:`tower.mode_damping`). The coupled
    mode's tower part is split over the tower's own modes with its head (the tower block of
    the standstill model, K-orthogonal) by their strain energy; what lies beyond the second
    mode of a plane takes the second's ratio."""
    t = spec.tower
    if t.damping_at != "tower-alone":
        return None
    ref = tower.alone_frequencies(spec)
    m, _, _, k, _ = model.multiblade
    weighted = np.zeros(shapes.shape[1])
    energy = np.zeros(shapes.shape[1])
    for plane in ("fa", "ss"):
        index = model.groups.get(f"tower.{plane}")
        if index is None or len(index) < 2:
            continue
        kt, mt = k[np.ix_(index, index)], m[np.ix_(index, index)]
        own = modal.solve(kt, mt, 2).shapes
        x = shapes[index]
        whole = np.abs(np.real(np.conj(x) * (kt @ x))).sum(axis=0)
        rest = whole.copy()
        zetas = []
        for i in range(own.shape[1]):
            phi = own[:, i]
            stiff = float(phi @ kt @ phi)
            e_i = np.abs(phi @ kt @ x) ** 2 / stiff
            rest = rest - e_i
            name = f"{plane}{i + 1}"
            z = t.damping_by_mode.get(name, t.damping_ratio)
            zetas.append(float(z) / ref[name])
            weighted += e_i * zetas[-1] * frequency_hz
        weighted += np.maximum(rest, 0.0) * zetas[-1] * frequency_hz
        energy += whole
    return np.where(energy > 0, weighted / np.where(energy > 0, energy, 1.0), t.damping_ratio)


def default_damping(spec: Spec) -> Damping:
    """The lower of the tower's and the blades' damping ratios (the coupled modes mix them)."""
    tower_d = section_damping(spec.tower, "tower")
    blade_d = blade.default_damping(spec)
    where = "the lower of tower.damping_ratio and blade.damping_ratio"
    assumed = tower_d.assumed or blade_d.assumed
    return Damping(
        min(tower_d.ratio, blade_d.ratio),
        f"{where} ({'assumed: not all given' if assumed else 'given'})",
        assumed,
    )


def build_modes(spec: Spec, built: Mapping[str, list[Mode]]) -> list[Mode]:
    if spec.results is not None:  # another tool's whole-turbine modes, in the model's place
        return imported.modes(spec, "fixed")
    return modes(spec, {m.id: m for ms in built.values() for m in ms})


def _turning(mode: Mode, condition: str, isolated: Mapping[str, Mode]) -> Mode:
    """A one- or two-bladed rotor's parked coupled blade mode over rotor speed: its parked
    frequency stiffened as the isolated blade mode of its family is (:class:`Stiffened`),
    said in its condition. Other modes (the tower's, the drive train's) stay as parked."""
    name = mode.id.removeprefix("system.")
    base = isolated.get(isolated_id(name, condition)) if name.startswith("blade.") else None
    if base is None or base.curve is None:
        return mode
    return replace(
        mode,
        curve=Stiffened(mode.frequency_hz, base.curve),
        condition=f"{mode.condition}; turning, stiffened as the isolated {base.id} is",
    )


def analyse(spec: Spec, ctx: Context) -> Analysis:
    """``system.coupling`` (coupled vs isolated), for two blades ``system.floquet``, and
    ``system.closeness`` (subsystems' modes close to each other, :mod:`wtvib.judge.closeness`)."""
    two_bladed = applies(spec) and spec.rotor.blades < 3
    periodic = (
        stability_check(spec, build(spec, spec.coupled.rotating_condition))  # type: ignore[union-attr]
        if two_bladed
        else None
    )
    if spec.results is not None:
        return imported.stability(spec, ctx)
    found = (
        check(spec, list(ctx.modes)),
        periodic,
        closeness.check(ctx.modes, ctx.op),
        # parked: no rotor harmonic to judge; the modes' damping is what is judged
        standstill_stability(ctx.modes) if spec.rotor.speed.parked else None,
    )
    aerodynamic = spec.aerodynamics is not None and spec.rotor.blades >= 3
    dampers = "the drive train's dampers" + (
        f", {len(spec.tower.dampers)} tuned mass damper(s)" if spec.tower.dampers else ""
    )
    damping = (
        f"{dampers} and the aerodynamics at the operating points (each mode's material "
        "damping added)"
        if aerodynamic
        else f"{dampers} only (each mode's material damping added)"
    )
    statements = (
        (
            "Coupled whole-turbine modes (system.*): tower, nacelle, drive train and "
            f"{spec.rotor.blades} flexible blades in one model (Lagrange, multi-blade "
            "coordinates); shaft tilt, precone, blade torsion and gravity on the blades "
            f"neglected; damping in the model: {damping}."
            + (
                f" The hub is {spec.rotor.hub}, but the model clamps the blades to it: its "
                "asymmetric flap modes are those of a hingeless rotor, not the "
                f"{spec.rotor.hub} rotor's ("
                + (
                    "the teeter hinge is modelled in the rotor-on-tower-head Floquet check only"
                    if spec.rotor.hub == "teetered"
                    else "no model here has flap hinges"
                )
                + ")."
                if spec.rotor.hub in ("teetered", "hinged")
                else ""
            ),
        )
        if applies(spec)
        else ()
    )
    return Analysis(checks=tuple(c for c in found if c is not None), assumptions=statements)


SUBSYSTEM = Subsystem(
    NAME,
    build_modes,
    default_damping,
    analyse,
    part="coupled",
    diagram="campbell-system",
    title="coupled whole turbine",
    figures=("system-energy",),
)
