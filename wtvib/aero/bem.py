"""Steady blade-element momentum (BEM) operating points over the wind range.

The textbook method (Hansen, *Aerodynamics of Wind Turbines*, ch. 6; Hau ch. 5): each blade
station is an aerofoil in the relative wind W of axial speed V(1 − a) and tangential speed
Ωr(1 + a′); momentum balance gives the inductions a, a′ with Prandtl's tip and hub losses
and Buhl's correction of the thrust coefficient for a > 0.4. The equations are solved in
the inflow angle φ alone, after S. A. Ning, "A simple solution method for the blade element
momentum equations with guaranteed convergence", Wind Energy 17 (2014) 1327–1345: one
residual R(φ) with a bracketed root, found by bisection for all stations and operating
points at once (no iteration that can fail to converge). A station at the tip, where
Prandtl's tip loss is zero, carries no load — or, read from an AeroDyn deck, what AeroDyn's
BEMT gives its last node (a = 1, a′ = 0, loaded at φ = 0; :attr:`Rotor.at_tip`).

The controller's steady schedule (Jonkman et al. 2009 §7): variable speed holds the optimal
tip-speed ratio between the minimum and rated rotor speed (region 2), then rated speed;
pitch regulation pitches to feather where the aerodynamic power would exceed rated power /
efficiency (region 3); stall regulation holds the fine pitch at every wind — or, where the
model gives its own operating points (``control.operating_points``: a HAWC2 model's
operational data file), those. Neglected and stated: shaft tilt, precone, prebend, blade
bending, wind shear, tower shadow and skewed inflow (uniform steady axial wind on a planar
rotor). The blades' steady twist under their aerodynamic moment is solved with the flow
where the blade's torsional stiffness and the polars' C_M are given (:mod:`wtvib.aero.
torsion`): the operating points of a torsionally soft blade, as HAWCStab2 computes them.
"""

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from ..numerics.modal import ModalError
from ..spec import Control, Spec
from ..units import rad_s_to_rpm, rpm_to_rad_s
from . import torsion
from .torsion import Torsion

Array = NDArray[np.float64]

#: Wind speeds of the schedule: this many from cut-in to cut-out (the rated wind is added).
WIND_SAMPLES = 25

#: Resampled polars: every POLAR_STEP_DEG from −180° to 180° (linear between the given points).
POLAR_STEP_DEG = 0.25

#: Lift and drag slopes by central differences over ±SLOPE_STEP_DEG (smooths the kinks of a
#: tabulated polar).
SLOPE_STEP_DEG = 0.5

#: The φ residual's root: BISECTIONS halvings of the bracket (≤ π/2 → 0.006 rad), then
#: FALSI steps of Illinois regula falsi inside it (|R| at machine level on the NREL 5-MW).
BISECTIONS, FALSI = 8, 8

_EPS = 1e-6
#: A station this close to the tip radius (relative) is at the tip: a deck's rounding (r-test's
#: AeroDyn blades end at BlSpn 61.4999 m on a 61.5 m blade).
TIP_ROUNDING = 1e-4


@dataclass(frozen=True)
class Rotor:
    """The rotor's aerodynamic tables, ready for vectorised solves."""

    radius: Array  # stations from the rotor axis, (S,) [m]
    chord: Array  # (S,) [m]
    twist: Array  # aerodynamic twist, (S,) [rad]
    cl: Array  # lift per station on the resampled α grid, (S, A)
    cd: Array  # drag, (S, A)
    blades: int
    tip_radius: float  # [m]
    hub_radius: float  # [m]
    rho: float  # [kg/m³]
    tip_loss: bool
    hub_loss: bool
    #: each station's separation time constant T_f0 [half-chord transits] where the lift's
    #: separation point lags (dynamic stall, :mod:`wtvib.numerics.unsteady`); None: it does not
    separation_time: Array | None = None
    #: the blades' steady twist under their aerodynamic moment (:mod:`wtvib.aero.torsion`);
    #: None: rigid in torsion
    torsion: "Torsion | None" = None
    #: a station at the tip loaded as AeroDyn loads its last node (:attr:`at_tip`)
    fixed_tip_induction: bool = False

    def polar(self, alpha: Array) -> tuple[Array, Array]:
        """C_L, C_D at angles of attack ``alpha`` [rad], shaped (…, S) (a non-finite angle
        reads the table at 0°: the solution's finiteness check names the failure)."""
        cl, cd = self._lookup(alpha, self._flat)
        return cl, cd

    def _lookup(self, alpha: Array, flat: tuple[Array, ...]) -> tuple[Array, ...]:
        """Tables on the α grid (each flattened, S·A) read at ``alpha`` [rad], linear."""
        x = (np.degrees(np.where(np.isfinite(alpha), alpha, 0.0)) + 180.0) % 360.0
        x = x / POLAR_STEP_DEG
        i = np.minimum(x.astype(np.intp), self.cl.shape[1] - 2)
        t = x - i
        k = i + self._row_start  # into the flattened tables: station s's row starts at s·A
        u = 1 - t
        k1 = k + 1
        return tuple(table.take(k) * u + table.take(k1) * t for table in flat)

    def moment(self, w: Array, alpha: Array) -> Array:
        """Each section's aerodynamic moment about its shear centre per unit length [N·m/m]
        at relative wind ``w`` and angle of attack ``alpha`` [rad], (K, S)
        (:func:`wtvib.aero.torsion.moment`); the rotor must have its ``torsion``."""
        assert self.torsion is not None
        cl, cd, cm = self._lookup(alpha, (*self._flat, self.torsion.cm.ravel()))
        return torsion.moment(self.torsion, self.rho, self.chord, w, alpha, cl, cd, cm)

    @functools.cached_property
    def separation(self) -> tuple[Array, Array, Array]:
        """Kirchhoff's separation function on the α grid (S, A), each station's zero-lift
        angle [deg] and inviscid slope [1/deg]
        (:func:`wtvib.numerics.unsteady.separation_table`)."""
        from ..numerics.unsteady import separation_table

        grid = np.arange(self.cl.shape[1], dtype=float) * POLAR_STEP_DEG - 180.0
        return separation_table(grid, self.cl)

    def separated_slope(self, alpha: Array, step: float) -> Array:
        """The part of each section's lift slope [1/rad] at ``alpha`` [rad] that the
        separation point lags (:func:`wtvib.numerics.unsteady.separated_slope`), its f_st′
        by central differences over ±``step`` [rad] like the polar's slopes; 0 where the
        separation does not lag (``separation_time`` None)."""
        from ..numerics.unsteady import separated_slope

        if self.separation_time is None:
            return np.zeros_like(alpha)
        f, alpha0, slope = self.separation
        flat = (f.ravel(),)
        (f_now,) = self._lookup(alpha, flat)
        (f_up,) = self._lookup(alpha + step, flat)
        (f_down,) = self._lookup(alpha - step, flat)
        inviscid = slope * (np.degrees(alpha) - alpha0)
        return separated_slope(inviscid, f_now, (f_up - f_down) / (2 * step))

    @functools.cached_property
    def at_tip(self) -> NDArray[np.bool_]:
        """The stations at the blade's tip (within :data:`TIP_ROUNDING` of the tip radius,
        a deck's rounding) where Prandtl's tip loss is on: F = 0 there, and the momentum
        balance has no root in that limit (a floor on F leaves an arbitrary load). Such a
        section carries no load (a = 1, a′ = −1: the flow stopped there) — or, with
        :attr:`fixed_tip_induction`, what AeroDyn's BEMT gives its blade's last node, whose
        inductions it fixes at a = 1, a′ = 0 (BEMT.f90, ``FixedInductions``): the section
        meets the rotation's speed alone, at φ = 0, and carries that lift and drag; with
        the induction in equilibrium or a dynamic wake the node's own motion then leaves
        its inflow angle at 0 (a stays 1). AeroDyn fixes a node at the hub likewise where
        the hub loss is on; left as it is here (the root's speed is small)."""
        if not self.tip_loss:
            return np.zeros(len(self.radius), dtype=bool)
        return np.asarray(self.radius >= self.tip_radius * (1 - TIP_ROUNDING))

    @functools.cached_property
    def solidity(self) -> Array:
        """Local solidity B·c/(2πr) per station."""
        return np.asarray(self.blades * self.chord / (2 * np.pi * self.radius))

    @functools.cached_property
    def loss_terms(self) -> tuple["_Loss | None", "_Loss | None"]:
        """Prandtl's exponents, tip then hub (None: that loss off; no hub, no hub loss and
        no 1/0)."""
        tip = hub = None
        if self.tip_loss:
            tip = _Loss.of(
                self.blades / 2 * (self.tip_radius - self.radius), np.maximum(self.radius, 1e-12)
            )
        if self.hub_loss and self.hub_radius > 0:
            hub = _Loss.of(
                self.blades / 2 * (self.radius - self.hub_radius),
                np.full_like(self.radius, self.hub_radius),
            )
        return tip, hub

    @functools.cached_property
    def _flat(self) -> tuple[Array, Array]:
        return self.cl.ravel(), self.cd.ravel()

    @functools.cached_property
    def _row_start(self) -> NDArray[np.intp]:
        return np.asarray(np.arange(self.cl.shape[0], dtype=np.intp) * self.cl.shape[1])


def rotor(spec: Spec) -> Rotor:
    """The spec's aerodynamic tables (computed once per spec object)."""
    aero = spec.aerodynamics
    assert aero is not None and spec.turbine.rotor_diameter_m is not None
    out: Rotor = spec.derived(("bem.rotor", 0), aero, lambda: _rotor(spec))
    return out


def _rotor(spec: Spec) -> Rotor:
    aero = spec.aerodynamics
    assert aero is not None and spec.turbine.rotor_diameter_m is not None
    grid = np.arange(-180.0, 180.0 + 1e-9, POLAR_STEP_DEG)
    tables = {
        name: (_periodic(grid, p.alpha_deg, p.cl), _periodic(grid, p.alpha_deg, p.cd))
        for name, p in aero.airfoils.items()
    }
    st = aero.stations
    hub = spec.blade.structure.hub_radius_m if spec.blade.structure else st.radius_m[0]
    twisting = None
    if aero.steady_torsion:
        twisting = _torsion(spec, grid)
    return Rotor(
        np.asarray(st.radius_m, float),
        np.asarray(st.chord_m, float),
        np.radians(np.asarray(st.twist_deg, float)),
        np.stack([tables[n][0] for n in st.airfoil]),
        np.stack([tables[n][1] for n in st.airfoil]),
        spec.rotor.blades,
        spec.turbine.rotor_diameter_m / 2,
        min(hub, st.radius_m[0]),
        aero.air_density_kg_m3,
        aero.tip_loss,
        aero.hub_loss,
        np.array([aero.airfoils[n].separation_time for n in st.airfoil], float)
        if aero.dynamic_stall
        else None,
        twisting,
        aero.fixed_tip_induction,
    )


def _periodic(grid: Array, alpha_deg: list[float], values: list[float]) -> Array:
    """A polar's column on the α grid [deg], linear between its points and periodic in α: a
    polar that stops short of ±180° is continued to its other end."""
    a = np.asarray(alpha_deg, float)
    v = np.asarray(values, float)
    a_ext = np.concatenate([a[-1:] - 360.0, a, a[:1] + 360.0])
    return np.asarray(np.interp(grid, a_ext, np.concatenate([v[-1:], v, v[:1]])))


def _torsion(spec: Spec, grid: Array) -> Torsion | None:
    """What the blades' steady twist needs (:mod:`wtvib.aero.torsion`): None where the blade
    has no torsional stiffness (blade.structure.gj_nm2) or nothing twists it (no polar's cm,
    no shear centre off the quarter chord)."""
    aero = spec.aerodynamics
    s = spec.blade.structure
    assert aero is not None
    if s is None or s.gj_nm2 is None:
        return None
    st = aero.stations
    offset = st.shear_centre_chord
    if all(aero.airfoils[n].cm is None for n in st.airfoil) and (
        offset is None or not any(x != 0.25 for x in offset)
    ):
        return None
    cm = np.zeros((len(st.airfoil), len(grid)))  # C_M 0 where a polar gives none
    for i, name in enumerate(st.airfoil):
        p = aero.airfoils[name]
        if p.cm is not None:
            cm[i] = _periodic(grid, p.alpha_deg, p.cm)
    radius = np.asarray(st.radius_m, float)
    chord = np.asarray(st.chord_m, float)
    arm = np.zeros_like(chord) if offset is None else (np.asarray(offset) - 0.25) * chord
    span = np.asarray(s.span_m, float)
    gj = np.asarray(s.gj_nm2, float)
    root = s.hub_radius_m if s.hub_radius_m > 0 else float(radius[0])
    root = min(root, float(radius[0]))
    at = np.interp(radius - root, span, gj)
    flex = torsion.flexibility(radius, root, at, float(gj[0]), s.pitch_drive_nm_rad)
    return Torsion(flex, arm, cm)


@dataclass(frozen=True)
class Solution:
    """Steady BEM solution at K operating points (station arrays shaped (K, S))."""

    wind: Array  # (K,) [m/s]
    omega: Array  # (K,) [rad/s]
    pitch: Array  # (K,) [rad]
    phi: Array  # inflow angle to the rotor plane [rad]
    alpha: Array  # angle of attack [rad]
    a: Array  # axial induction
    a_t: Array  # tangential induction
    w: Array  # relative wind [m/s]
    cl: Array
    cd: Array
    thrust: Array  # (K,) [N]
    torque: Array  # (K,) [N·m]
    converged: NDArray[np.bool_]  # (K, S): a bracketed root was found
    #: the blades' steady elastic twist (K, S) [rad], nose-up positive (the angle of attack
    #: grows by it); None: rigid in torsion
    elastic_twist: Array | None = None
    #: (K,): points where the steady twist did not settle (torsional divergence), solved
    #: rigid there
    twist_unsettled: NDArray[np.bool_] | None = None

    @property
    def power(self) -> Array:
        """Aerodynamic power [W]."""
        return np.asarray(self.torque * self.omega)


@dataclass(frozen=True)
class _Loss:
    """One of Prandtl's loss factors, F = (2/π)·arccos(e^(−x)) with x = a / (b·|sin φ|)."""

    minus_a: Array  # −a per station (−(a/d) is (−a)/d exactly)
    b: Array
    beyond: bool  # some a < 0 (a station past the tip): e^(−x) > 1 there, clipped to 1

    @classmethod
    def of(cls, a: Array, b: Array) -> "_Loss":
        return cls(-a, b, bool(np.any(a < 0)))

    def arccos(self, s: Array) -> Array:
        """arccos(e^(−x)) at |sin φ| = ``s``."""
        e = np.exp(self.minus_a / (self.b * s))
        return np.asarray(np.arccos(np.minimum(e, 1.0) if self.beyond else e))


def _losses(r: Rotor, phi: Array, sin_phi: Array | None = None) -> Array:
    """Prandtl's tip and hub loss factor F(φ) at each station (≥ 1e-6); ``sin_phi``: sin φ,
    where already computed."""
    s = np.maximum(np.abs(np.sin(phi) if sin_phi is None else sin_phi), 1e-9)
    tip, hub = r.loss_terms
    f: Array | None = None
    if tip is not None:
        f = (2 / np.pi) * tip.arccos(s)
    if hub is not None:
        g = hub.arccos(s)
        f = (2 / np.pi) * g if f is None else f * (2 / np.pi) * g
    return np.maximum(f, 1e-6) if f is not None else np.ones_like(phi)


def _coefficients(r: Rotor, phi: Array, theta: Array) -> tuple[Array, ...]:
    """sin φ, cos φ, C_L, C_D, F and Ning's k, k′ at inflow angles φ (twist + pitch θ)."""
    s, c = np.sin(phi), np.cos(phi)
    cl, cd = r.polar(phi - theta)
    cn = cl * c + cd * s
    ct = cl * s - cd * c
    f = _losses(r, phi, s)
    sigma = r.solidity
    k = sigma * cn / (4 * f * s * s)
    kp = sigma * ct / (4 * f * s * c)
    return s, c, cl, cd, f, k, kp


def _momentum(k: Array, f: Array) -> Array:
    """The axial induction of the momentum region (φ > 0): a = k/(1 + k), Buhl's empirical
    thrust above k = 2/3."""
    light = k <= 2 / 3
    if light.all():  # no station in Buhl's region (each branch costs what all of it does)
        return np.asarray(k / (1 + k))
    two_f = 2 * f
    fk = two_f * k
    g1 = fk - (10 / 9 - f)
    g2 = np.maximum(fk - f * (4 / 3 - f), 0.0)
    g3 = fk - (25 / 9 - two_f)
    flat = np.abs(g3) < 1e-6  # g3 = 0: the quadratic's linear limit
    if flat.any():
        buhl = np.where(
            flat,
            1 - 1 / (2 * np.sqrt(np.maximum(g2, 1e-12))),
            (g1 - np.sqrt(g2)) / np.where(flat, 1.0, g3),
        )
    else:
        buhl = (g1 - np.sqrt(g2)) / g3
    return np.asarray(np.where(light, k / (1 + k), buhl))


def _balance(
    phi: Array, s: Array, c: Array, k: Array, kp: Array, a_pos: Array, speed_ratio: Array
) -> Array:
    """Ning's residual R(φ) (momentum region with ``a_pos``; propeller brake for φ < 0)."""
    one_minus_a = np.where(np.abs(1 - a_pos) < 1e-12, 1e-12, 1 - a_pos)  # a = 1: no flow
    swirl = c / speed_ratio * (1 - kp)
    return np.asarray(np.where(phi > 0, s / one_minus_a - swirl, s * (1 - k) - swirl))


def _residual(r: Rotor, phi: Array, theta: Array, speed_ratio: Array) -> Array:
    """Ning's residual R(φ) alone (the root search's evaluations)."""
    s, c, _, _, f, k, kp = _coefficients(r, phi, theta)
    return _balance(phi, s, c, k, kp, _momentum(k, f), speed_ratio)


def _induction(
    r: Rotor, phi: Array, theta: Array, speed_ratio: Array
) -> tuple[Array, Array, Array, Array, Array]:
    """Ning's residual R(φ) and the inductions, C_L, C_D it implies."""
    s, c, cl, cd, f, k, kp = _coefficients(r, phi, theta)
    a_pos = _momentum(k, f)
    a_neg = k / np.where(np.abs(k - 1) < 1e-12, 1e-12, k - 1)  # propeller brake (φ < 0)
    a = np.where(phi > 0, a_pos, a_neg)
    a_t = kp / np.where(np.abs(1 - kp) < 1e-12, 1e-12, 1 - kp)
    return _balance(phi, s, c, k, kp, a_pos, speed_ratio), a, a_t, cl, cd


def _root(
    res: Callable[[Array], Array], shape: tuple[int, int]
) -> tuple[Array, Array, Array, Array, NDArray[np.bool_]]:
    """The inflow angle's root of the residual ``res`` at every station and point: the
    bracket's ends and their residuals after bisection and regula falsi, and where a
    bracket was found at all."""

    # brackets in Ning's order: momentum/windmill (0, π/2], propeller brake [−π/4, 0),
    # then (π/2, π); the next is tried only where no bracket is found yet
    def ends(low: float, high: float) -> tuple[Array, Array, Array, Array]:
        """A bracket's ends at every station and point, and R there (one evaluation)."""
        both = np.stack([np.full(shape, low), np.full(shape, high)])
        r_both = res(both)
        return both[0], both[1], r_both[0], r_both[1]

    lo, hi, r_lo, r_hi = ends(_EPS, np.pi / 2)
    found = r_lo * r_hi < 0
    for low, high in ((-np.pi / 4, -_EPS), (np.pi / 2, np.pi - _EPS)):
        if found.all():
            break
        la, lb, ra, rb = ends(low, high)
        ok = ~found & (ra * rb < 0)
        lo, r_lo = np.where(ok, la, lo), np.where(ok, ra, r_lo)
        hi, r_hi = np.where(ok, lb, hi), np.where(ok, rb, r_hi)
        found |= ok
    for _ in range(BISECTIONS):  # halve the bracket: it stays a bracket whatever R looks like
        mid = 0.5 * (lo + hi)
        r_mid = res(mid)
        left = np.sign(r_mid) == np.sign(r_lo)
        lo, r_lo = np.where(left, mid, lo), np.where(left, r_mid, r_lo)
        hi, r_hi = np.where(left, hi, mid), np.where(left, r_hi, r_mid)
    for _ in range(FALSI):  # then regula falsi (Illinois) inside it: superlinear
        den = np.where(r_hi != r_lo, r_hi - r_lo, 1.0)
        x = np.clip(hi - r_hi * (hi - lo) / den, np.minimum(lo, hi), np.maximum(lo, hi))
        r_x = res(x)
        same = np.sign(r_x) == np.sign(r_hi)
        # the end that stays has its residual halved (Illinois), the other moves to x
        lo, r_lo = np.where(same, lo, hi), np.where(same, 0.5 * r_lo, r_hi)
        hi, r_hi = x, r_x
    return lo, hi, r_lo, r_hi, found


def solve(
    r: Rotor,
    wind: Array,
    omega: Array,
    pitch: Array,
    motion: tuple[float, float] = (0.0, 0.0),
    start: Array | None = None,
) -> Solution:
    """The steady BEM solution at operating points (wind [m/s], Ω [rad/s], pitch [rad]),
    all stations and points at once; ``motion``: every section moving at (v_n, v_t) [m/s]
    (downwind, in the direction of rotation), its momentum balance solved in the flow it
    meets — V − v_n axially, Ωr + v_t in the rotor plane — as AeroDyn's BEMT takes a
    blade's own velocity into its inflow (the induction in equilibrium with the motion).
    With the rotor's ``torsion`` the blades twist under their moment: the steady twist is
    solved with the flow (:func:`_twisted`), from ``start`` (K, S) [rad] where given (a
    nearby point's twist: fewer rounds), else from the rigid blade."""
    if r.torsion is not None:
        return _twisted(r, wind, omega, pitch, motion, start)
    return _solve(r, wind, omega, pitch, motion)


#: The steady twist's Newton rounds at most, its step tolerance [rad] (1e-6 rad moves an
#: angle of attack by 6e-5°; the rounds converge linearly at ~0.02 per round on the IEA-22,
#: the induction's answer left out of the Jacobian: four solves from a rigid start), and
#: the twist [rad] beyond which a point is taken as torsionally divergent (solved rigid
#: there, said).
TORSION_ROUNDS, TORSION_TOLERANCE, TORSION_LIMIT = 12, 1e-6, math.radians(30.0)


def _twisted(
    r: Rotor,
    wind: Array,
    omega: Array,
    pitch: Array,
    motion: tuple[float, float],
    start: Array | None = None,
) -> Solution:
    """The BEM solution with the blades' steady elastic twist θ = F·m (:mod:`wtvib.aero.
    torsion`): Newton's method on θ − F·m(α(θ)) with each section's ∂m/∂α, the Jacobian of
    the first round kept (a chord method: one inversion per point, the rounds converge
    linearly as Newton's does here, the induction's answer being left out of either), all
    points at once; a point whose twist does not settle within TORSION_ROUNDS or passes
    TORSION_LIMIT is solved rigid."""
    t = r.torsion
    assert t is not None
    h = math.radians(SLOPE_STEP_DEG)
    shape = (len(np.atleast_1d(wind)), len(r.radius))
    elastic = np.zeros(shape) if start is None else np.array(start, float).reshape(shape)
    eye = np.eye(len(r.radius))
    inverse = None  # the Jacobian's inverse, from the first round (a chord method)
    for _ in range(TORSION_ROUNDS):
        sol = _solve(r, wind, omega, pitch, motion, elastic)
        m = r.moment(sol.w, sol.alpha)
        residual = elastic - m @ t.flexibility.T
        if inverse is None:
            dm = (r.moment(sol.w, sol.alpha + h) - r.moment(sol.w, sol.alpha - h)) / (2 * h)
            inverse = np.linalg.inv(eye[None] - t.flexibility[None] * dm[:, None, :])
        step = np.einsum("kij,kj->ki", inverse, residual)
        settled = np.max(np.abs(step), axis=1) <= TORSION_TOLERANCE
        if settled.all():  # the solution is at this twist, the step left below tolerance
            return replace(sol, elastic_twist=elastic, twist_unsettled=~settled)
        elastic = elastic - step
    wild = ~np.all(np.isfinite(elastic), axis=1) | (
        np.max(np.abs(np.where(np.isfinite(elastic), elastic, np.inf)), axis=1) > TORSION_LIMIT
    )
    wild |= ~settled
    elastic[wild] = 0.0
    sol = _solve(r, wind, omega, pitch, motion, elastic)
    return replace(sol, elastic_twist=elastic, twist_unsettled=wild)


def _solve(
    r: Rotor,
    wind: Array,
    omega: Array,
    pitch: Array,
    motion: tuple[float, float] = (0.0, 0.0),
    elastic: Array | None = None,
) -> Solution:
    """:func:`solve` with the blades' twist grown by ``elastic`` (K, S) [rad] (nose-up)."""
    wind = np.asarray(wind, float)
    omega = np.asarray(omega, float)
    pitch = np.asarray(pitch, float)
    if not (
        np.all(np.isfinite(wind)) and np.all(np.isfinite(omega)) and np.all(np.isfinite(pitch))
    ):
        raise ModalError("the operating points' wind, rotor speed or pitch is not finite")
    shape = (len(wind), len(r.radius))
    theta = np.broadcast_to((r.twist[None, :] + pitch[:, None]), shape)
    if elastic is not None:
        theta = theta - elastic
    axial = wind[:, None] - motion[0]  # the flow each section meets
    spin = omega[:, None] * r.radius[None, :] + motion[1]
    lam = np.maximum(spin / axial, 1e-9)
    lam = np.broadcast_to(lam, shape)

    def res(phi: Array) -> Array:
        return _residual(r, phi, theta, lam)

    lo, hi, r_lo, r_hi, found = _root(res, shape)
    phi = np.where(
        found,
        np.where(np.abs(r_hi) <= np.abs(r_lo), hi, lo),
        np.arctan2(np.broadcast_to(axial, shape), np.broadcast_to(spin, shape)),
    )
    _, a, a_t, cl, cd = _induction(r, phi, theta, lam)
    a = np.where(found, a, 0.0)  # no root: the geometric inflow, no induction
    a_t = np.where(found, a_t, 0.0)
    if not np.all(found):
        cl, cd = r.polar(phi - theta)
    tip = r.at_tip
    if tip.any():  # F = 0 (Rotor.at_tip)
        a = np.where(tip, 1.0, a)
        if r.fixed_tip_induction:  # AeroDyn's last node: a′ = 0, loaded at φ = 0
            a_t = np.where(tip, 0.0, a_t)
            phi = np.where(tip, 0.0, phi)
            cl_tip, cd_tip = r.polar(phi - theta)
            cl, cd = np.where(tip, cl_tip, cl), np.where(tip, cd_tip, cd)
        else:  # the flow stopped at the section: no load
            a_t = np.where(tip, -1.0, a_t)
    u_n = axial * (1 - a)
    u_t = spin * (1 + a_t)
    w = np.hypot(u_n, u_t)
    q = 0.5 * r.rho * w * w * r.chord
    s, c = np.sin(phi), np.cos(phi)
    f_n = q * (cl * c + cd * s)
    f_t = q * (cl * s - cd * c)
    thrust = np.asarray(r.blades * np.trapezoid(f_n, r.radius, axis=1))
    torque = np.asarray(r.blades * np.trapezoid(f_t * r.radius, r.radius, axis=1))
    if not (np.all(np.isfinite(thrust)) and np.all(np.isfinite(torque))):
        raise ModalError(
            "the blade-element momentum solution is not finite (thrust or torque overflows): "
            "check the magnitudes of the aerodynamics, rotor speed and wind"
        )
    return Solution(wind, omega, pitch, phi, phi - theta, a, a_t, w, cl, cd, thrust, torque, found)


def power_coefficient(r: Rotor, tsr: Array, pitch_deg: float, wind: float = 10.0) -> Array:
    """C_p at tip-speed ratios ``tsr`` and one pitch [deg] (the C_p(λ, β) surface's row)."""
    tsr = np.asarray(tsr, float)
    v = np.full_like(tsr, wind)
    sol = solve(r, v, tsr * wind / r.tip_radius, np.full_like(tsr, math.radians(pitch_deg)))
    return np.asarray(sol.power / (0.5 * r.rho * np.pi * r.tip_radius**2 * v**3))


# ---------------------------------------------------------------------------------------
# The controller's schedule


@dataclass(frozen=True)
class Schedule:
    """Steady operating points over the wind range, in wind order."""

    solution: Solution
    region: tuple[str, ...]  # "partial load", "full load" (pitching) or "stall" per point
    rated_wind: float | None  # [m/s]
    tip_speed_ratio: float  # region-2 λ
    tsr_source: str  # given / optimum of the BEM C_p
    rated_power: float | None  # aerodynamic power held in region 3 [W]
    assumptions: tuple[str, ...]

    @property
    def wind(self) -> Array:
        return self.solution.wind

    @property
    def rpm(self) -> Array:
        return np.asarray(rad_s_to_rpm(self.solution.omega))

    @property
    def pitch_deg(self) -> Array:
        return np.degrees(self.solution.pitch)

    def coefficients(self, r: Rotor) -> tuple[Array, Array]:
        """C_p and C_t at each point."""
        area = np.pi * r.tip_radius**2
        v = self.solution.wind
        cp = self.solution.power / (0.5 * r.rho * area * v**3)
        ct = self.solution.thrust / (0.5 * r.rho * area * v**2)
        return np.asarray(cp), np.asarray(ct)


def optimal_tsr(r: Rotor, pitch_deg: float) -> float:
    """The tip-speed ratio of the highest C_p at a pitch (a scan, refined by a parabola)."""
    tsr = np.arange(2.0, 16.01, 0.25)
    cp = power_coefficient(r, tsr, pitch_deg)
    i = int(np.clip(np.argmax(cp), 1, len(tsr) - 2))
    y0, y1, y2 = cp[i - 1 : i + 2]
    den = y0 - 2 * y1 + y2
    shift = 0.5 * (y0 - y2) / den if den < 0 else 0.0
    return float(tsr[i] + np.clip(shift, -1, 1) * 0.25)


def schedule(spec: Spec) -> Schedule:
    """The steady operating points of the spec's rotor and controller (computed once per
    spec object)."""
    assert spec.aerodynamics is not None
    out: Schedule = spec.derived(("bem.schedule", 0), spec.aerodynamics, lambda: _schedule(spec))
    return out


def _rotor_speed(spec: Spec, r: Rotor, wind: Array, tsr: float, fine: float) -> Array:
    speed = spec.rotor.speed
    if speed.fixed_rpm is not None:
        fixed = sorted(speed.fixed_rpm if isinstance(speed.fixed_rpm, list) else [speed.fixed_rpm])
        if len(fixed) == 1:
            return np.full_like(wind, float(rpm_to_rad_s(fixed[0])))
        # pole-changing: at each wind the speed that gives the higher power at the fine pitch
        options = np.array([float(rpm_to_rad_s(n)) for n in fixed])
        power = np.stack(
            [
                solve(r, wind, np.full_like(wind, om), np.full_like(wind, fine)).power
                for om in options
            ]
        )
        return np.asarray(options[np.argmax(power, axis=0)])
    low = float(rpm_to_rad_s(speed.steady_rpm[0][0]))
    top = float(rpm_to_rad_s(speed.rated_rpm or speed.top_rpm))
    return np.clip(tsr * wind / r.tip_radius, low, top)


def _schedule(spec: Spec) -> Schedule:
    aero = spec.aerodynamics
    assert aero is not None
    r = rotor(spec)
    c = aero.control
    fine = math.radians(c.fine_pitch_deg)
    notes = [_method(r)]
    if c.operating_points is not None:
        return _given(spec, r, notes)
    if c.tip_speed_ratio is not None:
        tsr, tsr_source = c.tip_speed_ratio, "given as aerodynamics.control.tip_speed_ratio"
    else:
        tsr = optimal_tsr(r, c.fine_pitch_deg)
        tsr_source = f"the BEM's highest C_p at {c.fine_pitch_deg:g}° pitch"
    rated_kw = c.rated_power_kw or spec.turbine.rated_power_kw
    p_rated = rated_kw * 1e3 / c.generator_efficiency if rated_kw is not None else None
    winds = np.linspace(c.cut_in_wind_m_s, c.cut_out_wind_m_s, WIND_SAMPLES)

    def lowest(v: Array) -> Array:  # the pitch below rated: fine, or the peak-shaving table
        base = np.full_like(v, fine)
        if c.min_pitch is None:
            return base
        table = np.radians(np.interp(v, c.min_pitch.wind_m_s, c.min_pitch.pitch_deg))
        return np.maximum(base, table)

    def at_fine(v: Array) -> Solution:
        return solve(r, v, _rotor_speed(spec, r, v, tsr, fine), lowest(v))

    if c.regulation == "pitch" and p_rated is None:
        p_rated = _rated_estimate(spec, c, r, tsr, at_fine, notes)
    rated_wind = None
    pitching = c.regulation == "pitch" and p_rated is not None
    if pitching:
        assert p_rated is not None
        excess = at_fine(winds).power - p_rated
        above = np.nonzero(excess > 0)[0]
        if len(above) and above[0] > 0:
            rated_wind = _rated_wind(
                lambda v: at_fine(v).power - p_rated,
                float(winds[above[0] - 1]),
                float(winds[above[0]]),
            )
            winds = np.sort(np.append(winds, rated_wind))
        elif len(above):
            rated_wind = float(winds[0])
            notes.append("the rotor exceeds rated power already at cut-in: pitched from there")
        else:
            notes.append(
                f"rated power {p_rated / 1e3:,.0f} kW (aerodynamic) is not reached below "
                "cut-out: no pitching"
            )
    omega = _rotor_speed(spec, r, winds, tsr, fine)
    pitch = lowest(winds)
    if c.min_pitch is not None:
        notes.append("below rated the pitch follows the controller's minimum-pitch table")
    region = ["stall" if c.regulation == "stall" else "partial load"] * len(winds)
    if pitching and rated_wind is not None:
        assert p_rated is not None
        full = winds > rated_wind * (1 + 1e-9)
        if np.any(full):
            pitch[full] = _pitch_to_rated(r, winds[full], omega[full], pitch[full], p_rated)
            for i in np.nonzero(full)[0]:
                region[i] = "full load"
    sol = solve(r, winds, omega, pitch)
    bad = int(np.count_nonzero(~sol.converged))
    if bad:
        notes.append(
            f"{bad} of {sol.converged.size} station solutions had no BEM root: geometric "
            "inflow used there"
        )
    return Schedule(
        sol,
        tuple(region),
        rated_wind,
        float(tsr),
        tsr_source,
        p_rated,
        tuple(notes),
    )


def _rated_estimate(
    spec: Spec,
    c: Control,
    r: Rotor,
    tsr: float,
    at_fine: Callable[[Array], Solution],
    notes: list[str],
) -> float | None:
    """A pitch-regulated rotor's rated power where none is given (an OpenFAST deck whose
    controller's input file is not in the set): the rotor's aerodynamic power at the fine
    pitch where it reaches its top speed at the region-2 tip-speed ratio, V = Ω·R/λ — the
    end of region 2 of a variable-speed turbine, at or a little below its rated power (the
    NREL 5-MW: 10.6 against 11.4 m/s), so that the pitch holds the rotor out of the stall
    the fine pitch would drive it into; said. None where that wind lies outside the
    operating winds (the rotor then runs at its fine pitch, as without pitch control)."""
    speed = spec.rotor.speed
    top_rpm = speed.rated_rpm or speed.top_rpm  # the top speed, as _rotor_speed takes it
    wind = float(rpm_to_rad_s(top_rpm)) * r.tip_radius / tsr
    power = (
        float(at_fine(np.array([wind])).power[0])
        if c.cut_in_wind_m_s < wind < c.cut_out_wind_m_s
        else 0.0
    )
    if not power > 0:
        notes.append(
            "pitch regulation with no rated power given, and none to estimate (the top "
            f"speed's region-2 wind, {wind:.3g} m/s, outside the operating winds or without "
            "power): the rotor at its fine pitch at every wind"
        )
        return None
    notes.append(
        f"pitch regulation with no rated power given: rated power taken as the rotor's "
        f"aerodynamic power where it reaches its top speed ({top_rpm:.4g} rpm) at the region-2 "
        f"tip-speed ratio, {wind:.3g} m/s: {power / 1e3:,.0f} kW (an estimate; give the "
        "turbine's rated power to judge its own)"
    )
    return power


def _method(r: Rotor) -> str:
    """The BEM's method and assumptions, in the words the report says them."""
    rigid = "rigid" if r.torsion is None else "rigid-in-bending (twisting under load)"
    return (
        "steady BEM (Ning 2014 residual; Prandtl tip/hub losses "
        f"{'on' if r.tip_loss else 'off'}/{'on' if r.hub_loss else 'off'}, Buhl's high-"
        f"induction thrust): uniform steady axial wind on a {rigid} planar rotor (no tilt, "
        "precone, prebend, shear or tower shadow)"
    )


def _given(spec: Spec, r: Rotor, notes: list[str]) -> Schedule:
    """The schedule at the model's own operating points (``control.operating_points``): the
    BEM solved there; the region-2 tip-speed ratio is the median of the points below the
    top rotor speed; with pitch regulation, full load at the points the pitch holds at the
    top speed (:func:`_given_rated`)."""
    aero = spec.aerodynamics
    assert aero is not None and aero.control.operating_points is not None
    c = aero.control
    pts = c.operating_points
    assert pts is not None
    winds = np.asarray(pts.wind_m_s, float)
    omega = np.asarray(rpm_to_rad_s(np.asarray(pts.rpm, float)))
    sol = solve(r, winds, omega, np.radians(np.asarray(pts.pitch_deg, float)))
    top = omega >= omega.max() * (1 - 1e-3)
    below = ~top if np.any(~top) else np.ones_like(top)
    tsr = float(np.median(omega[below] * r.tip_radius / winds[below]))
    rated_wind = None
    region = ["stall" if c.regulation == "stall" else "partial load"] * len(winds)
    if c.regulation == "pitch":
        reached = min(float(winds[np.argmax(top)]), float(omega.max() * r.tip_radius / tsr))
        pitch = np.asarray(pts.pitch_deg, float)
        rated_wind = _given_rated(winds, pitch, top, sol.power, reached)
        region = [
            "full load" if rated_wind is not None and t and v >= rated_wind else "partial load"
            for v, t in zip(winds, top, strict=True)
        ]
    rated_kw = c.rated_power_kw or spec.turbine.rated_power_kw
    p_rated = rated_kw * 1e3 / c.generator_efficiency if rated_kw is not None else None
    where = pts.source or "aerodynamics.control.operating_points"
    points = (
        f"{len(winds)} operating points"
        if len(winds) > 1
        else f"one operating point, {winds[0]:g} m/s"
    )
    notes.append(
        f"at the model's {points} ({where}): its rotor speed and pitch, not a schedule computed "
        "here"
    )
    return Schedule(
        sol,
        tuple(region),
        rated_wind,
        tsr,
        "the given operating points' median below rated",
        p_rated,
        tuple(notes),
    )


#: A given point pitches where its pitch stands this far above the fine pitch (its lowest
#: below the top speed) [deg]: the pitch controller's work, not a table's rounding.
PITCHED_DEG = 0.1


def _given_rated(
    winds: Array, pitch: Array, top: NDArray[np.bool_], power: Array, reached: float
) -> float | None:
    """The rated wind of a model's own operating points: where the power the pitch holds at
    the top speed (its first pitched point's) is reached — from the last point below it,
    the power growing as V³ (a constant power coefficient; a rotor held at its top speed
    below rated, the IEA-10's 8.7 rpm from 9 to 10.5 m/s at the fine pitch, grows a little
    slower), within the two points and not before the rotor reaches its top speed
    (``reached``: where the region-2 tip-speed ratio does, at most the lowest wind at it).
    None where no point pitches."""
    fine = float(np.min(pitch[~top])) if np.any(~top) else float(np.min(pitch))
    pitched = np.nonzero(top & (pitch > fine + PITCHED_DEG))[0]
    if not len(pitched):
        return None
    k = int(pitched[0])
    if k == 0:
        return float(winds[0])
    lo, hi = float(winds[k - 1]), float(winds[k])
    if power[k - 1] > 0 and power[k] > power[k - 1]:
        estimate = lo * float(power[k] / power[k - 1]) ** (1 / 3)
    else:
        estimate = hi
    return float(np.clip(max(estimate, reached), lo, hi))


#: The rated wind: RATED_ROUNDS grids of RATED_GRID winds, each inside the cell of the one
#: before where the power excess changes sign (a bracket of 0.9 m/s → 3.5 mm), then the
#: secant in that cell (the power is smooth and monotonic there: error far below 1 mm/s).
RATED_GRID, RATED_ROUNDS = 17, 2


def _rated_wind(excess: Callable[[Array], Array], lo: float, hi: float) -> float:
    """The root of the fine-pitch power excess between two winds (``excess`` ≤ 0 at
    ``lo``, > 0 at ``hi``), each round one BEM solve of a grid of winds at once."""
    f_lo = f_hi = 0.0
    for _ in range(RATED_ROUNDS):
        v = np.linspace(lo, hi, RATED_GRID)
        f = excess(v)
        j = int(np.clip(np.argmax(f > 0), 1, RATED_GRID - 1))  # the first wind above rated
        lo, hi, f_lo, f_hi = float(v[j - 1]), float(v[j]), float(f[j - 1]), float(f[j])
    if f_hi == f_lo:
        return hi
    return float(np.clip(lo - f_lo * (hi - lo) / (f_hi - f_lo), lo, hi))


#: Pitch search above rated: a grid of this step [deg] up to PITCH_SPAN_DEG past the fine
#: pitch brackets rated power at each wind, then PITCH_REFINE steps of regula falsi, all
#: winds at once (the power is smooth and monotonic in pitch within a bracket). The grid is
#: solved PITCH_CHUNK points at a time, further points only for the winds still above rated
#: (the reference turbines pitch at most 23–25° at cut-out: one chunk).
PITCH_STEP_DEG, PITCH_SPAN_DEG, PITCH_REFINE, PITCH_CHUNK = 5.0, 60.0, 5, 6


def _pitch_to_rated(r: Rotor, wind: Array, omega: Array, low: Array, p_rated: float) -> Array:
    """The pitch (towards feather from ``low``, each wind's lowest) at which each wind's
    aerodynamic power is rated. A rotor whose blades twist brackets it on the rigid blade's
    grid (one solve a point, the twisted blade's four), then checks and widens the bracket
    on the twisting blade before refining there (:func:`_twisted_bracket`)."""
    steps = np.radians(np.arange(0.0, PITCH_SPAN_DEG + 1e-9, PITCH_STEP_DEG))
    grid = low[:, None] + steps[None, :]  # (winds, grid)
    k, g = grid.shape
    held = r if r.torsion is None else replace(r, torsion=None)
    excess = np.full((k, g), np.inf)  # a point not solved: above rated, as far as we know
    for start in range(0, g, PITCH_CHUNK):
        rows = np.flatnonzero(~np.any(excess <= 0, axis=1))  # no bracket yet
        if rows.size == 0:
            break
        cols = np.arange(start, min(start + PITCH_CHUNK, g))
        pts = np.ix_(rows, cols)
        n = cols.size
        power = solve(held, np.repeat(wind[rows], n), np.repeat(omega[rows], n), grid[pts].ravel())
        excess[pts] = power.power.reshape(rows.size, n) - p_rated
    j = np.where((excess <= 0).any(axis=1), np.argmax(excess <= 0, axis=1), g - 1)
    j = np.maximum(j, 1)
    rows = np.arange(k)
    lo, hi = grid[rows, j - 1], grid[rows, j]
    f_lo, f_hi = excess[rows, j - 1], excess[rows, j]
    twist = None  # the blades' twist at the step before: where the next one starts
    if r.torsion is not None:
        lo, hi, f_lo, f_hi, twist = _twisted_bracket(r, wind, omega, grid, lo, hi, p_rated)
    # a wind whose power stays above rated at the last grid pitch keeps that pitch
    stays_above = (f_hi > 0) & (hi >= grid[:, -1] - 1e-12)
    x = hi
    for _ in range(PITCH_REFINE):
        den = np.where(f_hi != f_lo, f_hi - f_lo, 1.0)
        x = np.clip(hi - f_hi * (hi - lo) / den, np.minimum(lo, hi), np.maximum(lo, hi))
        step = solve(r, wind, omega, x, start=twist)
        f_x, twist = step.power - p_rated, step.elastic_twist
        swap = f_x * f_hi < 0
        lo = np.where(swap, hi, lo)
        f_lo = np.where(swap, f_hi, 0.5 * f_lo)  # Illinois: halve the end that stays
        hi, f_hi = x, f_x
    return np.asarray(np.where(stays_above, grid[:, -1], x))


def _twisted_bracket(
    r: Rotor, wind: Array, omega: Array, grid: Array, lo: Array, hi: Array, p_rated: float
) -> tuple[Array, Array, Array, Array, Array | None]:
    """The rigid blade's bracket of rated power (``lo``, ``hi`` on ``grid``'s steps) checked
    on the twisting blade and moved a grid step down or up where it no longer brackets (its
    twist lowers or raises the power at a pitch), until it does or reaches the grid's ends:
    the ends, their power excess and the twist at ``hi``."""
    first, last = grid[:, 0], grid[:, -1]
    step = grid[:, 1] - grid[:, 0]
    for _ in range(grid.shape[1]):
        at_lo = solve(r, wind, omega, lo)
        at_hi = solve(r, wind, omega, hi, start=at_lo.elastic_twist)
        f_lo, f_hi = at_lo.power - p_rated, at_hi.power - p_rated
        down = (f_lo <= 0) & (lo > first + 1e-12)  # rated lies below the bracket
        up = (f_hi > 0) & (hi < last - 1e-12)  # above it
        if not (down | up).any():
            break
        lo, hi = (
            np.where(down, np.maximum(lo - step, first), np.where(up, hi, lo)),
            np.where(down, lo, np.where(up, np.minimum(hi + step, last), hi)),
        )
    return lo, hi, f_lo, f_hi, at_hi.elastic_twist
