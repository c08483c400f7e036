"""Aerodynamic damping of every mode in operation: the quasi-steady blade-element forces,
linearised about each steady operating point, added to the modal models.

Section model (Hau ch. 7.2.3; DOMAIN.md §3): a blade section in the relative wind W, inflow
angle φ to the rotor plane, feels per unit length the normal (downwind) and tangential
(direction of rotation) forces

    F_n = ½ρcW(C_L U_t + C_D U_n),   F_t = ½ρcW(C_L U_n − C_D U_t),

with U_n = V(1 − a) − v_n and U_t = Ωr(1 + a′) + v_t for section velocities v_n (downwind)
and v_t (direction of rotation). Linearised about the steady point at frozen induction
(the wake does not respond: quasi-steady, as OpenFAST's frozen-wake linearisation) they
are −C·v with (s = sin φ, c = cos φ, ′ = d/dα)

    C_nn = ½ρcW [C_L sc + C_D(1 + s²) + C_L′ c² + C_D′ sc]
    C_nt = −½ρcW [C_L(1 + c²) + C_D sc − C_L′ sc − C_D′ s²]
    C_tn = ½ρcW [C_L(1 + s²) − C_D sc + C_L′ sc − C_D′ c²]
    C_tt = ½ρcW [−C_L sc + C_D(1 + c²) + C_L′ s² − C_D′ sc];

C_nn and C_tt are the stall check's c(ψ) for flapwise (ψ = 90° − φ) and edgewise
(ψ = 180° − φ) motion. Past stall C_L′ < 0 makes C_tt, and in deep stall C_nn, negative.

The C_L′ terms are ½ρcW·C_L′·u·uᵀ, u = (cos φ, sin φ) (:func:`section_lift`): the lift's
response to the angle of attack, which the shed wake lags (:mod:`wtvib.numerics.unsteady`, Jones's
approximation of Wagner's function); the judged damping has that part lagged, the
quasi-steady result is kept beside it for comparison.

Models:

* the coupled whole-turbine model (three or more blades): each blade point's velocity from
  the model's kinematics (blade modes, tower-top translation and rotation, drive train),
  D = Σ Jᵀ C J per blade, in multi-blade coordinates, the lift's part through lag states
  (:func:`wtvib.subsystems.multiblade.lift_lag`); the damped eigenproblem at each operating point,
  each mode matched by shape to the structural mode at the same rotor speed (overdamped
  roots kept, with ζ = 1);
* isolated blade modes: the single-mode root with the modal coefficient ∫ C φ² dr on the
  generalised mass ∫ m φ² dr, its lift part lagged (quasi-steady: ζ_a = ∫ C φ² dr /
  (2ω ∫ m φ² dr); flap: C_nn, edge: C_tt);
* isolated first tower bending modes: the rotor's hub-velocity damping N_b∫C_nn dr
  (fore-aft) and (N_b/2)∫C_tt dr (side-side, azimuth mean) on the tower's first-mode
  generalised mass, the head plus 33/140 of the tower (a cantilever's equivalent tip
  mass, Blevins Table 8-8). Translation only: the coupled model, restricted to the same
  motion, agrees within 10 % on the NREL 5-MW, and adds the rotor's tilt with the tower
  top's slope and the blades' flap share (+40–90 % there) — the isolated value is low.

Dynamic stall (``aerodynamics.dynamic_stall``): the part of the lift slope that the
separation point lags (:func:`wtvib.numerics.unsteady.separated_slope`, from Kirchhoff's
separation function of each polar) goes through one lag state per coordinate at the
sections' weighted 1/T_f, the rest as above; in attached flow that part is zero.

Neglected and stated: aerodynamic stiffness (the rotor plane's tilt and yaw, blade
torsion), the apparent mass, dynamic inflow, dynamic stall where the spec does not ask for
it, the tower's own drag.
Structural damping is the mode's given or assumed ratio, added to the aerodynamic one and
stated separately.
"""

import functools
import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from ..judge.analysis import Analysis, Context, Damping, Subsystem, no_modes
from ..numerics import modal, unsteady
from ..results import Check, Mode, OperatingDamping, Rule, operating_points
from ..rules import HEAVY_DAMPING, NEGATIVE
from ..spec import Spec
from ..subsystems import blade
from ..units import rad_s_to_rpm
from . import bem

if TYPE_CHECKING:
    from ..subsystems.coupled import Model as CoupledModel
    from ..subsystems.multiblade import Extra, LiftLag, Model, Path

Array = NDArray[np.float64]

#: A mode's aerodynamic damping ratio at the operating points: with the lift lagged by the
#: shed wake (judged) and quasi-steady (for comparison).
Estimate = tuple[Array, Array]

#: A damped mode stands for a structural one when MAC + energy overlap reaches this (of 2);
#: below it the structural mode's first-order damping is used (:func:`multiblade.perturbed`).
MATCH = 1.5

#: Below :data:`MATCH` but at least this, the best damped root is a weak match: the lower of
#: its damping and the first-order estimate is kept — the conservative of two estimates. The
#: first-order damping of a structural mode that mixes with a heavily damped one is that
#: mode's borrowed: the NREL 5-MW's first backward edgewise whirl at 10 m/s and 11.43 rpm,
#: beside the forward flap whirl (0.88 Hz, ζ 0.56), matched at 1.495 to a root of ζ 0.016
#: (OpenFAST: 0.020, tests/validation/test_openfast_sweep.py), had a first-order 0.165.
WEAK = 1.0

#: The tower's equivalent tip mass in its first bending mode: 33/140 = 0.2357 of its mass (a
#: uniform cantilever with a tip mass, Rayleigh's cubic shape: the 0.2357·mL of DOMAIN.md
#: §5's tip-mass closed form; Blevins, Formulas for Natural Frequency, Table 8-8).
TOWER_EQUIVALENT = 33 / 140


def section_matrix(
    rho: float, chord: Array, w: Array, phi: Array, cl: Array, cd: Array, dcl: Array, dcd: Array
) -> Array:
    """The quasi-steady damping matrix per unit length [N·s/m²] of sections, shaped
    (…, 2, 2) over (out-of-plane, in-plane) velocities (see the module notes)."""
    q = 0.5 * rho * chord * w
    s, c = np.sin(phi), np.cos(phi)
    out = np.empty((*np.shape(q), 2, 2))
    out[..., 0, 0] = q * (cl * s * c + cd * (1 + s * s) + dcl * c * c + dcd * s * c)
    out[..., 0, 1] = -q * (cl * (1 + c * c) + cd * s * c - dcl * s * c - dcd * s * s)
    out[..., 1, 0] = q * (cl * (1 + s * s) - cd * s * c + dcl * s * c - dcd * c * c)
    out[..., 1, 1] = q * (-cl * s * c + cd * (1 + c * c) + dcl * s * s - dcd * s * c)
    return out


def section_lift(rho: float, chord: Array, w: Array, phi: Array, dcl: Array) -> Array:
    """The lift slope's part of :func:`section_matrix`: ½ρcW·C_L′·u·uᵀ with
    u = (cos φ, sin φ) — a section velocity v changes the angle of attack by uᵀv/W and the
    lift, along u, by ½ρcW²·C_L′ times that. The part the shed wake lags
    (:mod:`wtvib.numerics.unsteady`); the rest (drag, the lift's change with the relative speed and
    direction) acts at once."""
    q = 0.5 * rho * chord * w * dcl
    u = np.stack([np.cos(phi), np.sin(phi)], axis=-1)
    return np.asarray(q[..., None, None] * u[..., :, None] * u[..., None, :])


@dataclass(frozen=True)
class Sections:
    """The blade sections' damping matrices at each steady operating point."""

    schedule: bem.Schedule
    radius: Array  # stations [m], (S,)
    c: Array  # per unit length and blade [N·s/m²], (K, S, 2, 2)
    lift: Array  # the lift slope's part of c (section_lift), (K, S, 2, 2)
    rate: Array  # each section's reduced rate 2W/c [1/s], (K, S)
    #: the part of ``lift`` that the separation point lags (dynamic stall), and each
    #: section's separation rate 1/T_f = 2W/(c·T_f0) [1/s]; None: no separation lag
    separated: Array | None = None
    separated_rate: Array | None = None

    @functools.cached_property
    def lift_rate(self) -> Array:
        """The lift part weighted by each section's 2W/c: summed over sections and divided
        by the lift part's sum, the lift-weighted reduced rate of a lag filter."""
        return np.asarray(self.lift * self.rate[..., None, None])

    @functools.cached_property
    def attached_rate(self) -> Array:
        """The lift part that the shed wake lags — the whole lift slope's, less its
        separated part where the separation point lags — weighted by each section's 2W/c
        (as :attr:`lift_rate`; a stalled section's whole slope can sum to nothing over the
        span, its attached part does not)."""
        if self.separated is None:
            return self.lift_rate
        return np.asarray((self.lift - self.separated) * self.rate[..., None, None])

    @functools.cached_property
    def separated_weighted(self) -> Array | None:
        """The separated part weighted by each section's 1/T_f (as :attr:`lift_rate`)."""
        if self.separated is None or self.separated_rate is None:
            return None
        return np.asarray(self.separated * self.separated_rate[..., None, None])

    def at(self, radius: Array, table: Array | None = None) -> Array:
        """The matrices (``table``, else ``c``) at other radii (K, P, 2, 2): linear
        between stations, zero outside them."""
        r = np.asarray(radius, float)
        x = self.radius
        tab = self.c if table is None else table
        flat = tab.reshape(len(tab), len(x), 4)
        # every point and entry at once, with np.interp's own arithmetic: the slope of the
        # interval times the distance from its start, a station's own value where r is one
        j = np.clip(np.searchsorted(x, r, side="right") - 1, 0, len(x) - 2)
        slope = (flat[:, j + 1] - flat[:, j]) / (x[j + 1] - x[j])[:, None]
        out = slope * (r - x[j])[:, None] + flat[:, j]
        out[:, r == x[j]] = flat[:, j][:, r == x[j]]
        out[:, r == x[-1]] = flat[:, -1, None, :]
        out[:, (r < x[0]) | (r > x[-1])] = 0.0
        return out.reshape(len(tab), len(r), 2, 2)


def sections(spec: Spec) -> Sections:
    """The spec's operating points and section matrices (computed once per spec object)."""
    assert spec.aerodynamics is not None
    out: Sections = spec.derived(
        ("aerodamping.sections", 0), spec.aerodynamics, lambda: _sections(spec)
    )
    return out


def _sections(spec: Spec) -> Sections:
    r = bem.rotor(spec)
    sch = bem.schedule(spec)
    sol = sch.solution
    h = math.radians(bem.SLOPE_STEP_DEG)
    cl_p, cd_p = r.polar(sol.alpha + h)
    cl_m, cd_m = r.polar(sol.alpha - h)
    dcl, dcd = (cl_p - cl_m) / (2 * h), (cd_p - cd_m) / (2 * h)
    c = section_matrix(r.rho, r.chord, sol.w, sol.phi, sol.cl, sol.cd, dcl, dcd)
    lift = section_lift(r.rho, r.chord, sol.w, sol.phi, dcl)
    separated = separated_rate = None
    if r.separation_time is not None:  # dynamic stall: the separation point's lagged part
        lags = r.separation_time > 0  # T_f0 = 0: the separation follows at once, no lag
        slope = np.where(lags, r.separated_slope(sol.alpha, h), 0.0)
        separated = section_lift(r.rho, r.chord, sol.w, sol.phi, slope)
        separated_rate = unsteady.lag_rates(sol.w, r.chord) / np.where(lags, r.separation_time, 1.0)
    assert spec.aerodynamics is not None
    if spec.aerodynamics.induction == "equilibrium":
        g = inflow_response(r, sol)
    elif spec.aerodynamics.induction == "dynamic" and r.fixed_tip_induction and r.at_tip.any():
        # AeroDyn's last node keeps a = 1 whatever its dynamic wake does (its DBEMT
        # skips the node): its normal inflow stays 0, the in-plane follows the motion.
        # A wake frozen for linearisation (DBEMT_Mod −1) freezes the node's induced
        # velocity instead, and the node's motion turns its flow: the identity.
        g = np.broadcast_to(np.eye(2), (*sol.phi.shape, 2, 2)).copy()
        g[:, r.at_tip] = np.diag([0.0, 1.0])
    else:
        g = None
    if g is not None:
        c, lift = c @ g, lift @ g
        separated = None if separated is None else separated @ g
    rate = unsteady.lag_rates(sol.w, r.chord)
    return Sections(sch, r.radius, c, lift, rate, separated, separated_rate)


#: The section speed [m/s] of the central differences of :func:`inflow_response`: far
#: above the BEM root's rounding (its φ to ~1e-13 rad on W of 10–100 m/s), far below any
#: change of the flow's curvature (its error O(δ²/W²) ≈ 1e-10).
INFLOW_STEP = 1e-3


def inflow_response(r: bem.Rotor, sol: bem.Solution) -> Array:
    """How the flow a section meets answers its motion where the induction is in
    equilibrium with it (AeroDyn's BEMT without dynamic wake): G (K, S, 2, 2) with
    (−δU_n, δU_t) = G·(v_n, v_t) — the identity at frozen induction. Each section's
    momentum balance is re-solved with the section moving at ±δ downwind and in the
    direction of rotation (:func:`wtvib.aero.bem.solve`'s ``motion``), G by central differences
    of U_n = W sin φ, U_t = W cos φ; where the balance has no root (no induction) G = I.

    A section moving downwind lowers its thrust, the momentum balance then asks less
    induction, which gives back part of the lost inflow: G_nn < 1 — except where Prandtl's
    tip loss, which falls as the inflow angle grows, asks more induction instead: the NREL
    5-MW at rated has G_nn 1.07–1.13 over 40–56 m of its 63 m. Its flap family is damped
    1–3 % more so than at frozen induction (OpenFAST 5 on the same decks: 0.1–1.1 % more,
    tests/validation/test_openfast_sweep.py): neither is a bound of the other in general."""
    out = np.zeros((*sol.phi.shape, 2, 2))
    for j in (0, 1):  # (−δU_n, δU_t) per unit v_n, then v_t
        step = np.zeros(2)
        step[j] = INFLOW_STEP
        ahead = bem.solve(r, sol.wind, sol.omega, sol.pitch, (float(step[0]), float(step[1])))
        back = bem.solve(r, sol.wind, sol.omega, sol.pitch, (float(-step[0]), float(-step[1])))
        for i, (trig, to) in enumerate(((np.sin, -1.0), (np.cos, 1.0))):
            du = ahead.w * trig(ahead.phi) - back.w * trig(back.phi)
            out[..., i, j] = to * du / (2 * INFLOW_STEP)
    held = ~sol.converged
    out[held] = np.eye(2)
    return out


def stalled(spec: Spec) -> NDArray[np.bool_]:
    """At each operating point, whether any section of the blade's outer half is past its
    lift maximum (C_L′ < 0): where a negative damping can be stall's. In attached flow a
    pure in-plane motion is still damped negatively where −C_L·sin φ·cos φ (the lift turning
    with the in-plane velocity) outweighs the drag and C_L′·sin²φ — at a high lift and a
    small inflow angle, not stall (see :func:`attached_flow_note`)."""
    sec = sections(spec)
    outer = sec.radius >= 0.5 * float(sec.radius[-1])
    return np.asarray(np.any(sec.lift[:, outer, 0, 0] < 0, axis=1))


def attached_flow_note(mode_id: str) -> str:
    """Why a negative damping of an isolated estimate in attached flow warns, not fails."""
    return (
        f"{mode_id}: in attached flow (C_L′ > 0 over the blade's outer half), not stall — the "
        "isolated estimate damps a purely in-plane motion, whose −C_L·sin φ·cos φ (the lift "
        "turning with the in-plane velocity) can outweigh drag at a high lift and a small "
        "inflow angle; the mode's out-of-plane share and its couplings, which the coupled "
        "model (a `coupled` block) holds, are left out: a warning, not a verdict"
    )


def isolated_in_attached_flow(spec: Spec, op: OperatingDamping, negative: Sequence[int]) -> bool:
    """Whether a mode's negative damping at points ``negative`` is an isolated estimate's in
    attached flow (then it warns: :func:`attached_flow_note`)."""
    if op.method is None or any(op.method[k] != "isolated" for k in negative):
        return False
    stall = stalled(spec)
    return len(stall) == len(op.wind) and not any(stall[k] for k in negative)


#: A damped root at or above this damping ratio is no oscillation (overdamped: its two
#: roots real, or within rounding of it); its damping is reported as 1.
OVERDAMPED = 0.999


def _operating(
    sch: bem.Schedule,
    aero: Array,
    structural: float,
    source: str,
    part: tuple[str, ...] | None = None,
    roots: tuple[Array, Array, NDArray[np.bool_]] | None = None,
    quasi: Array | None = None,
) -> OperatingDamping:
    """The mode's damping at the operating points; ``roots``: the matched damped roots'
    natural frequency and eigenvalue damping, and where they are first-order estimates —
    a root damped past critical reports ζ = 1 and is marked overdamped; ``quasi``: the
    aerodynamic damping with quasi-steady lift, kept for comparison (at most 1 in total,
    as every total)."""
    sol = sch.solution
    total = np.minimum(np.asarray(aero, float) + structural, 1.0)
    steady = None
    if quasi is not None:
        steady = tuple(float(min(q + structural, 1.0)) for q in quasi)
    if roots is None:
        natural, method = None, tuple("isolated" for _ in total)
    else:
        freq, zeta, first = roots
        over = (np.asarray(zeta) >= OVERDAMPED) | (total >= OVERDAMPED)
        total = np.where(over, 1.0, np.minimum(total, 1.0))
        natural = tuple(float(f) for f in freq)
        method = tuple(
            "first-order" if f else "overdamped" if o else "eigenvalue"
            for f, o in zip(first, over, strict=True)
        )
    return OperatingDamping(
        tuple(float(v) for v in sol.wind),
        tuple(float(o) for o in sol.omega),
        tuple(float(p) for p in np.degrees(sol.pitch)),
        tuple(float(a) for a in aero),
        tuple(float(t) for t in total),
        source,
        part,
        natural,
        method,
        steady,
    )


# ---------------------------------------------------------------------------------------
# The coupled model


@dataclass(frozen=True)
class Coupled:
    """The coupled model's modes at the operating points: names, |λ|/2π and −Re λ/|λ|."""

    names: tuple[str, ...]
    frequency_hz: Array  # (K, modes)
    damping_ratio: Array  # (K, modes), eigenvalue damping (aerodynamics + dampers)
    standstill: Array  # (modes,), the eigenvalue damping at standstill (the dampers)
    first_order: NDArray[np.bool_]  # (K, modes): no damped mode matched, first-order ζ
    parts: tuple[tuple[str, ...], ...]  # (K, modes): where each mode's energy sits there
    quasi_steady: Array  # (K, modes): ζ with the lift unlagged (quasi-steady), to compare
    #: (K,): the generator's torque law as a damper [N·m·s/rad] (:func:`generator_damping`),
    #: None where it has none
    generator: Array | None = None


def coupled(spec: Spec, sec: Sections, reduced: bool = True) -> Coupled | None:
    """The coupled model's damped modes at each operating point (None: no coupled model
    with a rotating multi-blade view); ``reduced``: in the model's Ritz basis
    (``Model.ritz``), else the full model."""
    from ..subsystems import coupled as coupled_model
    from ..subsystems.multiblade import (
        Extra,
        at_speeds,
        fixed_frame_damping,
        matched,
        parts,
    )

    if not coupled_model.applies(spec) or spec.rotor.blades < 3:
        return None
    assert spec.coupled is not None
    model = coupled_model.build(spec, spec.coupled.rotating_condition)
    sol = sec.schedule.solution
    per_length = model.rotor.length[None, :, None, None]
    c_points = sec.at(model.rotor.radius) * per_length
    # the structural modes at each operating speed, continued from the rotating sweep's
    # nearest speed: the names and reference shapes
    speeds = sorted({round(float(w), 12) for w in sol.omega})
    sw = coupled_model.rotating_sweep(spec)
    path = at_speeds(model, sw, speeds, reduced)
    at = {w: i for i, w in enumerate(speeds)}
    where = [at[round(float(om), 12)] for om in sol.omega]  # each point's speed in the path
    part = [parts(model, model.multiblade[0], shapes) for shapes in path.shapes]
    # every operating point's aerodynamic damping and stiffness at once (stacks): the
    # quasi-steady forces, and the lift slope's part of them that the shed wake lags
    d_qs = model.section_damping(c_points)
    law = generator_damping(spec, sec.schedule) if model.generator is not None else None
    if law is not None and model.generator is not None:  # the torque law: a damper
        at_gen = int(np.searchsorted(model.active, model.generator))
        d_qs[:, at_gen, at_gen] += law
    refs = [path.shapes[i] for i in where]
    qs_d, qs_k = fixed_frame_damping(model, d_qs, sol.omega)
    qs_points: list[tuple[float, Extra]] = [
        (float(om), (d, k)) for om, d, k in zip(sol.omega, qs_d, qs_k, strict=True)
    ]
    structural = [path.frequency_hz[i] for i in where]
    ids = sw.names
    steady = matched(model, qs_points, refs, reduced=path.basis, frequencies=structural, names=ids)
    if _shed_wake(spec) or sec.separated is not None:  # the lift's lagged parts: lag states
        lag, d_now = _lagged(model, sec, d_qs, _shed_wake(spec))
        d_aero, k_aero = fixed_frame_damping(model, d_now, sol.omega)
        extras: list[Extra] = [
            (d, k, lag.at(i)) for i, (d, k) in enumerate(zip(d_aero, k_aero, strict=True))
        ]
        points = [(float(om), extra) for om, extra in zip(sol.omega, extras, strict=True)]
        damped = matched(model, points, refs, reduced=path.basis, frequencies=structural, names=ids)
    else:  # quasi-steady: the judged damping is the quasi-steady one
        extras, damped = [extra for _, extra in qs_points], steady
    freq, zeta, unresolved, quasi = _matched_roots(
        model, path, sol.omega, where, refs, extras, damped, steady, qs_points
    )
    assert path.first.damping_ratio is not None
    return Coupled(
        tuple(f"system.{n}" for n in sw.names),
        freq,
        zeta,
        np.asarray(path.first.damping_ratio),
        unresolved,
        tuple(part[i] for i in where),
        np.minimum(quasi, 1.0),
        law,
    )


#: How near the law's torque at a kink a point's torque counts as on the higher region's
#: side (its aerodynamic torque is the generator's less the losses the law leaves out).
KINK = 0.01


def generator_damping(spec: Spec, sch: bem.Schedule) -> Array | None:
    """The generator's torque law as a damper on the drive train at each operating point:
    dT/dΩ [N·m·s/rad] of ``control.generator_torque`` at the point's rotor speed (2T/Ω
    where T = k·Ω², nothing where the torque is held). At a kink of the law (where two of
    its regions meet, the rated speed of a fixed-speed schedule) the point's own torque —
    its aerodynamic power over its speed — says which side the generator is on: within
    :data:`KINK` of the law's torque there or above it, the higher region (a fixed-speed
    schedule at the rated speed holding rated power is on the law's flat top, not on its
    steep region 2½). None without a law or where the generator is not free (locked, or on
    the grid: ``coupled.rotating_condition``)."""
    aero, cm = spec.aerodynamics, spec.coupled
    if aero is None or aero.control.generator_torque is None:
        return None
    if cm is None or cm.rotating_condition != "free":
        return None
    law = aero.control.generator_torque
    rpm, torque = np.asarray(law.rpm), np.asarray(law.torque_nm)
    n = np.asarray(rad_s_to_rpm(sch.solution.omega))
    step = 1e-6 * np.maximum(n, 1e-3)
    omega = np.maximum(sch.solution.omega, 1e-9)
    above = sch.solution.power / omega >= np.interp(n, rpm, torque) * (1 - KINK)
    low = np.where(above, n, n - step)
    slope = (np.interp(low + step, rpm, torque) - np.interp(low, rpm, torque)) / step
    return np.asarray(slope * 30 / math.pi)


def _lagged(
    model: "CoupledModel", sec: Sections, d_qs: Array, shed_wake: bool
) -> tuple["LiftLag", Array]:
    """The coupled model's lag states at every operating point and the damping that acts at
    once: Jones's shed-wake filters on the attached part of the lift (``shed_wake``), the
    separation point's pole on its separated part (dynamic stall)."""
    from ..subsystems.multiblade import lag_columns, lift_lag, separation_lag

    omega = sec.schedule.solution.omega
    per_length = model.rotor.length[None, :, None, None]

    def on_model(table: Array) -> Array:
        return np.asarray(model.section_damping(sec.at(model.rotor.radius, table) * per_length))

    d_lift = on_model(sec.lift)
    d_sep = None
    attached = d_lift
    if sec.separated is not None:
        d_sep = on_model(sec.separated)
        attached = d_lift - d_sep
    lag = None
    d_now = d_qs  # without a shed wake the attached part acts at once
    columns = lag_columns(model, np.abs(attached) + (0.0 if d_sep is None else np.abs(d_sep)))
    if shed_wake:
        lag = lift_lag(model, attached, on_model(sec.attached_rate), omega, columns=columns)
        d_now = d_qs - (1.0 - unsteady.IMMEDIATE) * attached
    if d_sep is not None:
        assert sec.separated_weighted is not None
        weighted = on_model(sec.separated_weighted)
        lag = separation_lag(model, d_sep, weighted, omega, lag, columns)
        d_now = d_now - d_sep
    assert lag is not None
    return lag, d_now


def _matched_roots(
    model: "Model",
    path: "Path",
    omega: Array,
    where: list[int],
    refs: list[NDArray[np.complex128]],
    extras: list["Extra"],
    damped: list[tuple[Array, Array, Array]],
    steady: list[tuple[Array, Array, Array]],
    qs_points: list[tuple[float, "Extra"]],
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.bool_], NDArray[np.float64]]:
    """Each operating point's frequency and damping of every structural mode from its
    matched damped root, the first-order estimate where none matched (and where), and the
    quasi-steady damping beside it."""
    from ..subsystems.multiblade import perturbed

    kept = path.kept
    freq = np.empty((len(omega), kept))
    zeta = np.empty((len(omega), kept))
    unresolved = np.zeros((len(omega), kept), dtype=bool)
    quasi = np.empty((len(omega), kept))
    for k, (om, i) in enumerate(zip(omega, where, strict=True)):
        ref, extra = refs[k], extras[k]
        freq[k], zeta[k], score = damped[k]
        _, quasi[k], qs_score = steady[k]
        # where no damped mode resembles the structural one (veering, overdamping): the
        # first-order estimate on the structural mode (eigenvalue lam) instead
        lam = modal.eigenvalue(path.frequency_hz[i], path.damping_ratio[i])
        poor_qs = qs_score < MATCH
        if np.any(poor_qs):
            first = perturbed(model, float(om), qs_points[k][1], ref, lam)
            poor_qs &= (qs_score < WEAK) | (first < quasi[k])
            quasi[k, poor_qs] = first[poor_qs]
        poor = score < MATCH
        if np.any(poor):
            first = perturbed(model, float(om), extra, ref, lam)
            poor &= (score < WEAK) | (first < zeta[k])  # a weak match: the lower of the two
            zeta[k, poor] = first[poor]
            freq[k, poor] = path.frequency_hz[i][poor]
            unresolved[k] = poor
    return freq, zeta, unresolved, quasi


# ---------------------------------------------------------------------------------------
# Isolated modes


def blade_shape(mode: Mode, r: Array, root: float) -> Array:
    """The mode's deflection at radii r: its computed shape, else the uniform cantilever's
    first bending mode (β₁l = 1.8751, Blevins Table 8-1), normalised to the tip."""
    if mode.shape is not None:
        x = np.asarray(mode.shape.position_m) + root
        return np.asarray(np.interp(r, x, np.asarray(mode.shape.deflection)))
    bl = 1.8751040687
    length = r[-1] - root
    xi = np.clip((r - root) / length, 0, 1) * bl
    sigma = (math.cosh(bl) + math.cos(bl)) / (math.sinh(bl) + math.sin(bl))
    phi = np.cosh(xi) - np.cos(xi) - sigma * (np.sinh(xi) - np.sin(xi))
    return np.asarray(phi / phi[-1])


def blade_mass(spec: Spec, r: Array, root: float) -> Array | None:
    """Mass per length [kg/m] at radii r: the structure's, else the blade mass spread
    evenly; None without either."""
    st = spec.blade.structure
    if st is not None:
        return np.interp(r - st.hub_radius_m, st.span_m, st.mass_per_length_kg_m)
    if spec.blade.mass_kg is not None:
        return np.full_like(r, spec.blade.mass_kg / (r[-1] - root))
    return None


def generalised_mass(
    spec: Spec, mode: Mode, root: float, tip: float
) -> tuple[Array, Array, float] | None:
    """A blade mode's generalised mass ∫m·φ² dr (+ the tip mass) with φ = 1 at the tip, on
    80 radii from ``root`` to ``tip`` [m]: (radii, shape, mass); None without the blade's
    mass or a span."""
    if not tip > root:
        return None
    r = np.linspace(root, tip, 80)
    m = blade_mass(spec, r, root)
    if m is None:
        return None
    shape = blade_shape(mode, r, root)
    gen_mass = float(np.trapezoid(m * shape**2, r))
    st = spec.blade.structure
    if st is not None and st.tip_mass_kg:
        gen_mass += st.tip_mass_kg * float(shape[-1]) ** 2
    return (r, shape, gen_mass) if gen_mass > 0 else None


def isolated_blade(spec: Spec, mode: Mode, sec: Sections) -> Estimate | None:
    """ζ_a of an isolated blade mode (flap: out-of-plane, edge: in-plane) at each
    operating point, with the lift lagged and quasi-steady (:func:`_single_mode`); None
    without the blade's mass."""
    kind = mode.id.split(".")[1].rstrip("0123456789")
    if kind not in ("flap", "edge"):
        return None
    st = spec.blade.structure
    root = st.hub_radius_m if st is not None else float(sec.radius[0])
    found = generalised_mass(spec, mode, root, float(sec.radius[-1]))
    if found is None:
        return None
    r, shape, gen_mass = found
    e = 0 if kind == "flap" else 1
    weight = shape**2

    def on_shape(table: Array) -> Array:  # Σ over the span of a section table on the shape
        return np.asarray(np.trapezoid(sec.at(r, table)[:, :, e, e] * weight, r, axis=1))

    omega = 2 * np.pi * mode.frequency_at(sec.schedule.solution.omega)
    return _single_mode(
        gen_mass,
        omega,
        (on_shape(sec.c), on_shape(sec.lift), on_shape(sec.attached_rate)),
        _shed_wake(spec),
        _separated(sec, on_shape),
    )


def tower_mass(spec: Spec) -> float | None:
    """The tower's mass [kg]: given, else from its structure."""
    t = spec.tower
    if t.mass_kg is not None:
        return t.mass_kg
    if not t.has_structure:
        return None
    from ..subsystems.tower import discretise

    b = discretise(t)
    return float(np.sum(b.mass * b.basis.w))


def isolated_tower(spec: Spec, mode: Mode, sec: Sections) -> Estimate | None:
    """ζ_a of an isolated first tower bending mode at each operating point (the rotor's
    damping of the hub's velocity), with the lift lagged and quasi-steady
    (:func:`_single_mode`); None for other modes or without the masses."""
    if mode.id not in ("tower.fa1", "tower.ss1") or spec.tower_head is None:
        return None
    m_tower = tower_mass(spec)
    if m_tower is None:
        return None
    gen_mass = spec.tower_head.mass_kg + TOWER_EQUIVALENT * m_tower
    r = sec.radius
    nb = spec.rotor.blades
    # fore-aft: the out-of-plane velocity of every blade; side-side: the in-plane velocity
    # of a blade is v·cos ψⱼ, the azimuth mean of cos² is ½
    e, share = (0, nb) if mode.id == "tower.fa1" else (1, 0.5 * nb)

    def rotor(table: Array) -> Array:
        return np.asarray(share * np.trapezoid(table[:, :, e, e], r, axis=1))

    omega = 2 * np.pi * mode.frequency_at(sec.schedule.solution.omega)
    return _single_mode(
        gen_mass,
        omega,
        (rotor(sec.c), rotor(sec.lift), rotor(sec.attached_rate)),
        _shed_wake(spec),
        _separated(sec, rotor),
    )


def _separated(sec: Sections, reduce: Callable[[Array], Array]) -> tuple[Array, Array] | None:
    """The separation point's lagged part of a mode's damping coefficient and that part
    weighted by each section's 1/T_f (``reduce``: a section table to the mode's coefficient);
    None without dynamic stall."""
    if sec.separated is None or sec.separated_weighted is None:
        return None
    return reduce(sec.separated), reduce(sec.separated_weighted)


def _lift(spec: Spec) -> str:
    return "lift lagged" if _shed_wake(spec) else "lift quasi-steady"


def induction_words(spec: Spec | None) -> str:
    """How the induction answers the blades' motion, in the words the report says it."""
    how = spec.aerodynamics.induction if spec is not None and spec.aerodynamics else "frozen"
    if how == "equilibrium":
        return (
            "the induction in equilibrium with the motion (each section's momentum balance "
            "re-solved, as AeroDyn's BEMT without dynamic wake)"
        )
    if how == "dynamic":
        return (
            "the induction held over a vibration's period by the wake's time constant "
            "(a dynamic wake, read as frozen induction; AeroDyn's last node at a = 1)"
        )
    return "frozen induction (the induced velocity held: no dynamic inflow)"


def _shed_wake(spec: Spec) -> bool:
    """Whether the lift is lagged by the shed wake (``aerodynamics.shed_wake``)."""
    return spec.aerodynamics is not None and spec.aerodynamics.shed_wake


def _single_mode(
    gen_mass: float,
    omega: Array,
    forces: tuple[Array, Array, Array],
    shed_wake: bool = True,
    separated: tuple[Array, Array] | None = None,
) -> tuple[Array, Array]:
    """ζ_a of one mode (generalised mass, circular frequency ω at each operating point) with
    ``forces`` = (c, lift, attached_rate): the modal damping coefficient c of the
    blade-element forces, its lift-slope part and that part less the separated one weighted
    by each section's 2W/c (:attr:`Sections.attached_rate`); ``separated``:
    the lift's part the separation point lags and that part weighted by 1/T_f (dynamic
    stall). The root with the lift lagged (:func:`wtvib.numerics.unsteady.single_mode_roots`;
    1 where it does not oscillate) — or, with neither lag, the quasi-steady ratio, at most
    1 — and the quasi-steady c/(2ωm), which may exceed 1."""
    c, lift, attached_rate = forces
    quasi = np.asarray(c / (2 * omega * gen_mass))
    if not shed_wake and separated is None:
        return np.minimum(quasi, 1.0), quasi
    sep, sep_rate = (0.0, 1.0) if separated is None else (separated[0], _mean_rate(*separated))
    # the weighted mean of the sections' rates (one filter stands for them all)
    rate = _mean_rate(lift - sep, attached_rate)
    root = unsteady.single_mode_roots(
        gen_mass, gen_mass * omega**2, c - lift, lift, rate, sep, sep_rate, shed_wake
    )
    lagged = np.where(np.isnan(root), 1.0, modal.damping_ratio(root))
    return np.asarray(lagged), quasi


def _mean_rate(part: Array, weighted: Array) -> Array:
    """A lagged part's mean rate: its sections' rates weighted by the part (the weighted
    sum over the part's)."""
    return np.asarray(np.abs(weighted / np.where(part != 0, part, 1.0)))


# ---------------------------------------------------------------------------------------
# Every judged mode


def modify(
    spec: Spec, built: Mapping[str, list[Mode]], heavy: float = HEAVY_DAMPING
) -> tuple[dict[str, list[Mode]], tuple[str, ...]]:
    """The :class:`wtvib.judge.analysis.Modifier` protocol: :func:`in_operation`."""
    return in_operation(spec, built, heavy)


def in_operation(
    spec: Spec, built: Mapping[str, list[Mode]], heavy: float = HEAVY_DAMPING
) -> tuple[dict[str, list[Mode]], tuple[str, ...]]:
    """Every judged mode with its damping at the operating points (``Mode.operating``), and
    the statements the report makes about how; unchanged (and nothing said) without
    aerodynamics. ``heavy``: the damping ratio above which a mode has no
    resonant peak (its frequency shift by the aerodynamics is not worth stating)."""
    if spec.aerodynamics is None:
        return dict(built), ()
    sec = sections(spec)
    sch = sec.schedule
    cpl = coupled(spec, sec)
    index = {n: j for j, n in enumerate(cpl.names)} if cpl else {}
    by_id = {m.id: m for ms in built.values() for m in ms}
    shift = 0.0
    out: dict[str, list[Mode]] = {}
    skipped: dict[str, list[str]] = {}  # why not → modes
    for sub, modes in built.items():
        done = []
        for m in modes:
            found, source = _aerodynamic(spec, m, sec, cpl, index, by_id)
            if found is None:
                if m.judged and m.subsystem != "rotor":
                    skipped.setdefault(source, []).append(m.id)
                done.append(m)
                continue
            aero, quasi = found
            if m.id in index and cpl is not None:  # how far |λ| departs from the judged curve
                f_struct = m.frequency_at(sch.solution.omega)
                ok = (f_struct > 0) & (aero + (m.damping_ratio or 0.0) < heavy)
                if np.any(ok):
                    rel = np.abs(cpl.frequency_hz[ok, index[m.id]] / f_struct[ok] - 1)
                    shift = max(shift, float(rel.max()))
            structural = m.damping_ratio or 0.0
            part, roots = None, None
            if m.id in index and cpl is not None:
                j = index[m.id]
                part = tuple(row[j] for row in cpl.parts)
                roots = (cpl.frequency_hz[:, j], cpl.damping_ratio[:, j], cpl.first_order[:, j])
            done.append(
                replace(m, operating=_operating(sch, aero, structural, source, part, roots, quasi))
            )
        out[sub] = done
    return out, _notes(spec, cpl, heavy, shift, out, skipped)


def _model_words(spec: Spec) -> str:
    """The report's sentence on the aerodynamic model of the damping in operation."""
    lift = (
        "the lift's response lagged by the shed wake (Jones's approximation of Wagner's "
        "function at each section's 2W/c; the quasi-steady damping is kept beside it in the "
        "Campbell data)"
        if _shed_wake(spec)
        else "the lift quasi-steady, following the angle of attack at once (no shed-wake "
        "lag: aerodynamics.shed_wake false — an OpenFAST deck's UA_Mod 0, 6 or 7)"
    )
    assert spec.aerodynamics is not None
    stall = (
        "the separation point lagging the angle of attack past the lift's linear range "
        "(dynamic stall: Kirchhoff's separation from the polar, one pole of T_f0·c/(2W) per "
        "section, T_f0 "
        + ", ".join(sorted({f"{a.separation_time:g}" for a in spec.aerodynamics.airfoils.values()}))
        + ")"
        if spec.aerodynamics.dynamic_stall
        else "no dynamic stall: past stall the lift follows the static polar at once"
    )
    return (
        "Aerodynamic damping: blade-element forces linearised at each operating point with "
        f"{induction_words(spec)} ({stall}), lift and drag slopes over "
        f"±{bem.SLOPE_STEP_DEG:g}°, {lift}; aerodynamic stiffness (tilt, yaw, torsion) and "
        "apparent mass neglected; no skewed wake (a code whose skewed-wake model answers the "
        "tower top's sideways motion at once — OpenFAST's Skew_Mod 1 — damps the first "
        "side-side tower mode more: 7 % on the NREL 5-MW at 8 m/s); total damping = "
        "aerodynamic + the mode's structural ratio."
    )


def _notes(
    spec: Spec,
    cpl: Coupled | None,
    heavy: float,
    shift: float,
    out: Mapping[str, list[Mode]],
    skipped: Mapping[str, list[str]],
) -> tuple[str, ...]:
    """What the report says of the damping in operation: the operating points, the
    aerodynamic model, the coupled modes (``shift``: how far their |λ| departs from the
    judged curves), where a first-order estimate stood in, the modes left structural."""
    sch = sections(spec).schedule
    notes = [*sch.assumptions, _statement(spec, sch), _model_words(spec)]
    assert spec.aerodynamics is not None
    if sch.solution.elastic_twist is not None:
        notes.append(BENDING_ONLY)
    if cpl is not None:
        notes.append(
            "Coupled modes: the damped eigenproblem of the whole-turbine model at each "
            "operating point (multi-blade coordinates; a Ritz basis of standstill modes and "
            "of what the rotation's and the dampers' loads on them excite, the full "
            "model's ζ to 1e-9), each mode matched by shape and energy to the "
            "structural mode at that rotor speed; frequencies are judged on the structural "
            f"curve, which the aeroelastic |λ| of the modes damped below ζ = {heavy:g} "
            f"departs from by at most {shift:.1%}."
        )
        law = cpl.generator
        if law is not None and spec.aerodynamics.control.generator_torque is not None:
            source = spec.aerodynamics.control.generator_torque.source or "control.generator_torque"
            notes.append(
                f"The generator's torque law ({source}) damps the drive train: its slope "
                "dT/dΩ at each operating point, a damper from the generator to ground "
                f"({law.min():,.3g} … {law.max():,.3g} N·m·s/rad; 2T/Ω where the torque is "
                "k·Ω², none where it is held constant)."
            )
    if cpl is not None and cpl.first_order.any():
        present = {m.id for ms in out.values() for m in ms}
        named = [
            f"{n} ({int(cpl.first_order[:, j].sum())})"
            for j, n in enumerate(cpl.names)
            if cpl.first_order[:, j].any() and n in present
        ]
        notes.append(
            f"At {int(cpl.first_order.sum())} of {cpl.first_order.size} mode-points no "
            "damped mode resembled the structural one (MAC + energy overlap below "
            f"{MATCH:g} of 2, or below {WEAK:g} with a lower damping than the first-order "
            "estimate: strong aerodynamic coupling, overdamping or veering); there "
            "the structural mode's first-order damping xᴴ(λD + K′)x / xᴴ(2λM + G)x is used: "
            + ", ".join(named)
            + "."
        )
    for why, ids in skipped.items():
        notes.append(
            f"No aerodynamic damping for {', '.join(ids)} ({why}): judged with the "
            "structural damping."
        )
    return tuple(notes)


#: Said where the blades twist under load (a torsional stiffness given): their modes do
#: not twist, and the edgewise modes' aerodynamic damping is an upper bound there
#: (tests/validation/test_hawc2.py, test_the_iea22_edge_damping_near_rated_is_wtvib_s_gap).
BENDING_ONLY = (
    "The blades' modes bend only: their twist in vibration is not modelled (their steady "
    "twist under load is). Codes whose blades twist in their modes damp the first edgewise "
    "modes less near rated — on the IEA-22, HAWC2 1.6–6 and OpenFAST with BeamDyn 1.8–3.4 "
    "times less than wtvib, where with blades rigid in torsion (ElastoDyn) the two agree "
    "within −32 … +12 %: for a blade soft in torsion the edgewise modes' aerodynamic "
    "damping near rated is an upper bound."
)

#: Why a mode has no aerodynamic damping (the report says it, mode by mode).
NO_MODEL = (
    "no model of it: the coupled model, where there is one, damps every mode it holds; the "
    "isolated estimates cover the first tower bending and the blades' flap and edge modes"
)
NO_TOWER_MASS = (
    "the isolated estimate of the first tower bending needs the tower head and the tower's "
    "mass: tower.mass_kg or its structure"
)
NO_BLADE_MASS = "the isolated estimate of a blade mode needs the blade's mass and span"


def _aerodynamic(
    spec: Spec,
    m: Mode,
    sec: Sections,
    cpl: Coupled | None,
    index: Mapping[str, int],
    by_id: Mapping[str, Mode],
) -> tuple[Estimate | None, str]:
    """A mode's aerodynamic damping ratio at each operating point (with the lift lagged,
    and quasi-steady for comparison) and the model it came from: the coupled model's where
    it has the mode (judged), else an isolated estimate for blade and first tower modes
    (also for isolated modes shown beside a coupled one, and for a coupled mode the coupled
    model gives none: fewer than three blades); None, and why not, where no model gives
    one."""
    if m.id in index and cpl is not None:
        if not m.judged:
            return None, ""
        j = index[m.id]
        aero = cpl.damping_ratio[:, j] - cpl.standstill[j]
        quasi = cpl.quasi_steady[:, j] - cpl.standstill[j]
        return (aero, quasi), "coupled model, damped eigenvalues at the operating points"
    if m.subsystem == "system":  # a coupled mode without a damped solve (N < 3: periodic)
        base = by_id.get(m.replaces or "")
        if base is None or base.subsystem not in ("blade", "tower"):
            return None, _periodic(spec)
        found, why = _isolated(spec, base, sec)
        if found is None:
            also = "no isolated estimate covers it either" if why == NO_MODEL else why
            return None, f"{_periodic(spec)}; {also}"
        # the same modal damping coefficient at this mode's frequency: ζ ∝ 1/ω
        omega = sec.schedule.solution.omega
        ratio = base.frequency_at(omega) / m.frequency_at(omega)
        return (found[0] * ratio, found[1] * ratio), (
            f"isolated estimate of {base.id} at this mode's frequency ({_periodic(spec)})"
        )
    return _isolated(spec, m, sec)


def _isolated(spec: Spec, m: Mode, sec: Sections) -> tuple[Estimate | None, str]:
    if m.subsystem == "blade" and m.id.split(".")[1].rstrip("0123456789") in ("flap", "edge"):
        aero = isolated_blade(spec, m, sec)
        if aero is None:
            return None, NO_BLADE_MASS
        return aero, f"isolated blade mode, section damping on its shape, {_lift(spec)}"
    if m.subsystem == "tower" and m.id in ("tower.fa1", "tower.ss1"):
        aero = isolated_tower(spec, m, sec)
        if aero is None:
            return None, NO_TOWER_MASS
        return aero, (
            "isolated tower mode: the rotor's damping of the hub's translation on the head + "
            f"33/140 of the tower, {_lift(spec)} (tilt and blade flexibility left out: low)"
        )
    return None, NO_MODEL


def _periodic(spec: Spec) -> str:
    n = spec.rotor.blades
    return (
        f"the coupled model of a {n}-bladed rotor has periodic coefficients: its damped "
        "modes in operation are not computed"
    )


def _statement(spec: Spec, sch: bem.Schedule) -> str:
    c = spec.aerodynamics.control  # type: ignore[union-attr]
    rpm = sch.rpm
    pitch = sch.pitch_deg
    given = c.operating_points
    text = (
        (
            f"Operating points: the model's own {len(sch.wind)} "
            f"({given.source or 'aerodynamics.control.operating_points'}), "
            if given is not None
            else f"Operating points: {len(sch.wind)} winds "
        )
        + f"{sch.wind[0]:g}–{sch.wind[-1]:g} m/s, "
        f"{rpm.min():.3g}–{rpm.max():.3g} rpm, pitch {pitch.min():.3g}–{pitch.max():.3g}°; "
        f"region-2 tip-speed ratio {sch.tip_speed_ratio:.3g} ({sch.tsr_source}); "
    )
    twist = _twist_words(spec, sch)
    if given is not None:
        text += (
            f"rated wind {sch.rated_wind:.3g} m/s (where the power the pitch holds at the "
            "top rotor speed is reached)"
            if sch.rated_wind is not None
            else f"{c.regulation} regulation"
        )
    elif c.regulation == "pitch" and sch.rated_wind is not None and sch.rated_power:
        text += (
            f"rated wind {sch.rated_wind:.3g} m/s, pitch holding {sch.rated_power / 1e3:,.0f} "
            "kW aerodynamic above it"
        )
    else:
        text += f"{c.regulation} regulation at the fine pitch {c.fine_pitch_deg:g}°"
    return text + "." + twist


def _twist_words(spec: Spec, sch: bem.Schedule) -> str:
    """What the blades' steady twist under load did at the operating points (empty: rigid)."""
    sol = sch.solution
    if sol.elastic_twist is None:
        return ""
    tip = np.degrees(sol.elastic_twist[:, -1])
    assert spec.aerodynamics is not None
    centre = (
        "the lift's arm about the given shear centres"
        if spec.aerodynamics.stations.shear_centre_chord is not None
        else "the shear centre taken at the quarter chord (not given: no lift arm)"
    )
    text = (
        " The blades twist under their steady aerodynamic moment (the polars' C_M about the "
        f"quarter chord, {centre}, the blade's GJ): at the tip "
        f"{tip.min():+.2f} … {tip.max():+.2f}° (nose-up positive) over the operating points."
    )
    bad = sol.twist_unsettled
    if bad is not None and bad.any():
        winds = ", ".join(f"{v:g}" for v in sol.wind[bad])
        text += (
            f" At {winds} m/s the twist did not settle (the blade's torsion diverges there): "
            "solved rigid in torsion at those points."
        )
    return text


# ---------------------------------------------------------------------------------------
# The subsystem protocol (wtvib.judge.analysis): the aerodynamics' own checks

NAME = "aerodynamics"


def default_damping(spec: Spec) -> Damping:
    return blade.default_damping(spec)  # no modes of its own: never used


build_modes = no_modes  # it damps the others' modes (in_operation)


def _rule_operation() -> Rule:
    return Rule(
        "steady operating points (blade-element momentum) over cut-in … cut-out",
        "Hau ch. 5 and 7.5.1 (system damping = structural + aerodynamic); Ning 2014 (BEM "
        "residual); Jonkman et al. 2009 §7 (the controller's schedule)",
    )


@dataclass(frozen=True)
class AerodynamicsResults:
    """What the damping figure draws beside the modes: the operating points' schedule."""

    schedule: bem.Schedule


def _points(sch: bem.Schedule, cp: Array, ct: Array) -> list[dict[str, Any]]:
    """The steady operating points as the check's numbers (``aerodynamics.operation``)."""
    sol = sch.solution
    return [
        {
            "wind_m_s": round(float(v), 4),
            "rpm": round(float(n), 4),
            "pitch_deg": round(float(p), 4),
            "region": reg,
            "power_kw": round(float(pw) / 1e3, 3),
            "thrust_kn": round(float(t) / 1e3, 3),
            "cp": round(float(a), 5),
            "ct": round(float(b), 5),
        }
        for v, n, p, reg, pw, t, a, b in zip(
            sch.wind,
            sch.rpm,
            sch.pitch_deg,
            sch.region,
            sol.power,
            sol.thrust,
            cp,
            ct,
            strict=True,
        )
    ]


def analyse(spec: Spec, ctx: Context) -> Analysis:
    """``aerodynamics.operation`` (the schedule, or that the audit is structural) and
    ``aerodynamics.stability`` (negative total damping of a judged mode anywhere in
    operation fails)."""
    if spec.aerodynamics is None:
        text = (
            f"not analysed: the modes and their damping are {spec.results.tool}'s "
            "(system.stability judges that damping)"
            if spec.results is not None
            else "not analysed: no aerodynamics block — the modes are judged with their "
            "structural damping only"
            + (
                "; the blades' divergence, flutter and stall-induced vibration are checked "
                "from their section data (blade.divergence, blade.flutter, blade.stall.*)"
                if spec.blade.aeroelastic is not None
                else "; no aeroelastic instability looked for (no section data either)"
            )
        )
        return Analysis(checks=(Check(f"{NAME}.operation", NAME, "info", text, _rule_operation()),))
    sec = sections(spec)
    sch = sec.schedule
    r = bem.rotor(spec)
    cp, ct = sch.coefficients(r)
    sol = sch.solution
    # a variable-speed rotor holds its best C_p over region 2 (one λ, one pitch): the
    # winds where it is reached to 1e-6, not the one whose rounding happens to be highest
    best = float(cp.max())
    peak = sch.wind[cp >= best - 1e-6 * abs(best)]  # (a rotor that only brakes: C_p < 0)
    at = (
        f"at {peak[0]:.3g} m/s"
        if len(peak) == 1
        else f"at {len(peak)} winds {peak[0]:.3g}–{peak[-1]:.3g} m/s"
    )
    # a rotor that draws no power anywhere is an input mistake (speed, pitch or twist), and
    # the damping computed at its operating points describes a rotor nobody builds
    braking = best <= 0
    unsettled = sol.twist_unsettled is not None and bool(sol.twist_unsettled.any())
    operation = Check(
        f"{NAME}.operation",
        NAME,
        "warn" if braking or unsettled else "info",
        (
            "the rotor draws no power at any operating point (C_p ≤ 0): check its speed, "
            "pitch and twist — the damping in operation below is of that rotor; "
            if braking
            else ""
        )
        + (
            "the blades' steady twist diverges at "
            f"{', '.join(f'{v:g}' for v in sol.wind[sol.twist_unsettled])} m/s (torsional "
            "divergence: check GJ, the shear centre and C_M) — solved rigid there; "
            if unsettled and sol.twist_unsettled is not None
            else ""
        )
        + f"{operating_points(sch.wind.tolist(), 'steady operating points')}: "
        f"C_p up to {best:.3f} ({at}), thrust up to "
        f"{sol.thrust.max() / 1e3:,.0f} kN, {sch.rpm.min():.3g}–{sch.rpm.max():.3g} rpm, "
        f"pitch {sch.pitch_deg.min():.3g}–{sch.pitch_deg.max():.3g}°"
        + (f", rated wind {sch.rated_wind:.3g} m/s" if sch.rated_wind is not None else ""),
        _rule_operation(),
        {
            "rated_wind_m_s": round(sch.rated_wind, 4) if sch.rated_wind is not None else None,
            "tip_speed_ratio": round(sch.tip_speed_ratio, 4),
            "points": _points(sch, cp, ct),
        },
    )
    return Analysis(
        checks=(operation, stability(ctx.modes, spec)), results=AerodynamicsResults(sch)
    )


def _winds(winds: Sequence[float]) -> str:
    """Where a damping is negative, in words: ``at 10.3 m/s`` or ``at 9.4–11.2 m/s``."""
    a, b = f"{winds[0]:.3g}", f"{winds[-1]:.3g}"
    return f"at {a} m/s" if a == b else f"at {a}–{b} m/s"


def stability(modes: Sequence[Mode], spec: Spec | None = None) -> Check:
    """Negative total damping of a judged mode at any operating point is an instability —
    an isolated estimate's in attached flow a warning (:func:`attached_flow_note`; with
    ``spec``, whose operating points tell)."""
    rule = _stability_rule(spec)
    damped = [m for m in modes if m.judged and m.operating is not None]
    if not damped:
        return Check(
            f"{NAME}.stability",
            NAME,
            "info",
            "not analysed: no judged mode has a model for its aerodynamic damping (blade modes "
            "need blade.mass_kg or blade.structure, first tower modes tower.mass_kg or its "
            "structure and tower_head; the coupled model damps every mode it holds)",
            rule,
        )
    unstable, attached = _negative(damped, spec)
    low = min(damped, key=lambda m: m.operating.total[m.operating.lowest])  # type: ignore[union-attr]
    lop = low.operating
    assert lop is not None
    i = lop.lowest
    numbers: dict[str, Any] = {
        "lowest": {
            "mode": low.id,
            "total_damping_ratio": round(lop.total[i], 6),
            "aerodynamic_damping_ratio": round(lop.aero[i], 6),
            "at_wind_m_s": round(lop.wind[i], 4),
        },
        "unstable": {m.id: [round(v, 4) for v in bad] for m, bad in unstable},
    }
    if attached:
        numbers["negative_in_attached_flow"] = {
            m.id: [round(v, 4) for v in bad] for m, bad in attached
        }
    shown, hidden = _negative_where_not_judged(modes)
    if hidden:
        numbers["negative_where_not_judged"] = hidden
    if unstable:
        text = "; ".join(f"{m.id} negative total damping {_winds(bad)}" for m, bad in unstable)
        return Check(
            f"{NAME}.stability", NAME, "fail", f"aeroelastic instability: {text}", rule, numbers
        )
    if attached:
        text = "; ".join(f"{m.id} negative total damping {_winds(bad)}" for m, bad in attached)
        notes = "; ".join(attached_flow_note(m.id) for m, _ in attached)
        return Check(f"{NAME}.stability", NAME, "warn", f"{text} ({notes})", rule, numbers)
    return Check(
        f"{NAME}.stability",
        NAME,
        "pass",
        f"every judged mode positively damped in operation; lowest: {low.id} ζ = "
        f"{max(lop.total[i], 0.0):.4f} at {lop.wind[i]:.3g} m/s"
        + ("; " + "; ".join(shown) if shown else ""),
        rule,
        numbers,
    )


def _stability_rule(spec: Spec | None) -> Rule:
    """The stability check's rule, naming the aerodynamic model the damping came from."""
    lift = (
        "the lift lagged by the shed wake (Jones's approximation of Wagner's function)"
        if spec is None or _shed_wake(spec)
        else "the lift quasi-steady"
    )
    equilibrium = (
        spec is not None
        and spec.aerodynamics is not None
        and spec.aerodynamics.induction == "equilibrium"
    )
    return Rule(
        "total damping (aerodynamic + structural) > 0 at every operating point, every judged mode",
        "Hau ch. 7.2.3 (stall-induced vibration) and 7.5.1; blade-element section damping "
        f"(M. H. Hansen, Wind Energy 10 (2007) 551–577), {lift}, "
        + ("induction in equilibrium" if equilibrium else "frozen induction"),
    )


#: Modes whose total damping falls below zero, each with the winds where.
Negative = list[tuple[Mode, list[float]]]


def _negative(damped: Sequence[Mode], spec: Spec | None) -> tuple[Negative, Negative]:
    """The judged modes whose total damping falls below zero: those unstable, and the
    isolated estimates that do so in attached flow (a warning)."""
    unstable: Negative = []
    attached: Negative = []
    for m in damped:
        op = m.operating
        assert op is not None
        at = [k for k, z in enumerate(op.total) if z < -NEGATIVE]  # beyond rounding's sign
        if not at:
            continue
        bad = [op.wind[k] for k in at]
        if spec is not None and isolated_in_attached_flow(spec, op, at):
            attached.append((m, bad))
        else:
            unstable.append((m, bad))
    return unstable, attached


def _negative_where_not_judged(modes: Sequence[Mode]) -> tuple[list[str], dict[str, float]]:
    """A mode shown but judged on a better model (an isolated estimate a coupled mode
    supersedes) whose own damping goes negative: the sentence saying so, with the mode
    that judges it — without its number beside a pass (the verdict is the judged model's,
    which stays positive) — and the number for the JSON."""
    shown, hidden = [], {}
    for m in modes:
        op = m.operating
        if m.judged or op is None or min(op.total) >= -NEGATIVE:
            continue
        j = int(np.argmin(op.total))
        shown.append(
            f"{m.id}'s own isolated estimate falls below zero at {op.wind[j]:.3g} m/s "
            f"(judged on {m.superseded_by or 'another model'}, which stays positive)"
        )
        hidden[m.id] = round(op.total[j], 6)
    return shown, hidden


SUBSYSTEM = Subsystem(
    NAME,
    build_modes,
    default_damping,
    analyse,
    part="aerodynamics",
    figures=("damping",),
)
