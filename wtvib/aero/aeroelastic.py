"""Blade aeroelastic stability: static divergence and classical bending–torsion flutter.

The blade section is the aeroelastician's *typical section* (Hau ch. 7.2, Fig. 7.6): a rigid
aerofoil of semichord b on a plunge spring k_h and a torsion spring k_θ about its elastic
axis (EA), with its centre of mass x_θ·b behind the EA. Notation and sign conventions are
those of Hodges & Pierce, *Introduction to Structural Dynamics and Aeroelasticity* (2nd ed.,
ch. 5): h plunge (positive down), θ pitch (nose up), a = EA position aft of mid-chord in
semichords, μ = m/(πρb²), r² = I_θ/(m b²), σ = ω_h/ω_θ.

- Divergence, typical section: q_D = k_θ/(e·c·C_Lα) per metre of span, with e = b(½ + a) the
  distance [m] of the aerodynamic centre (quarter chord) ahead of the EA and c the chord.
- Divergence, cantilever blade (strip theory): a finite-element torsion bar under the
  aerodynamic twisting moment of a rotating blade (local dynamic pressure ∝ r²), plus the
  centrifugal "propeller moment" stiffness Ω²·I_θ·cos 2β (β: angle of the chord to the rotor
  plane; a thin section's mass lies along its chord). The uniform non-rotating cantilever has
  the closed form q_D = π²GJ/(4·e·c·C_Lα·l²). Coning adds a *constant* torsional moment
  (the flapwise component of the centrifugal force acting at the centre of mass) — a
  pre-twist, not a stiffness — so it does not move the divergence speed.
- Flutter: Theodorsen's unsteady aerodynamics, solved by the p-k method (Hassig 1971) and,
  as a cross-check, by the k-method (V-g). At the flutter point both are exact.
"""

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from ..errors import SpecError
from ..judge.analysis import Analysis, Context, Subsystem, no_modes
from ..numerics import beam
from ..numerics.modal import solve, state_roots
from ..spec import check_section_inertia
from ..subsystems.blade import default_damping as blade_damping
from ..units import rpm_to_rad_s

if TYPE_CHECKING:
    from ..results import Check, Mode, Rule
    from ..rules import Status
    from ..spec import Spec

Array = NDArray[np.float64]
CArray = NDArray[np.complex128]

#: Thin-aerofoil lift-curve slope 2π per radian.
THIN_AEROFOIL_LIFT_SLOPE = 2 * math.pi


@dataclass(frozen=True)
class Section:
    """A typical section in SI units (per metre of span)."""

    semichord_m: float
    a: float  # EA aft of mid-chord, in semichords
    x_theta: float  # centre of mass aft of the EA, in semichords
    mass_kg_m: float
    inertia_kgm: float  # about the EA, per metre
    omega_h: float  # uncoupled plunge (flap) frequency [rad/s]
    omega_theta: float  # uncoupled torsion frequency [rad/s]
    air_density: float = 1.225
    lift_slope: float = THIN_AEROFOIL_LIFT_SLOPE

    @property
    def k_theta(self) -> float:
        return self.inertia_kgm * self.omega_theta**2

    @property
    def ac_ahead_of_ea_m(self) -> float:
        """e: distance from the aerodynamic centre (¼ chord) back to the EA. [m]"""
        return self.semichord_m * (0.5 + self.a)

    def mass_matrix(self) -> Array:
        m, b = self.mass_kg_m, self.semichord_m
        s = m * b * self.x_theta
        return np.array([[m, s], [s, self.inertia_kgm]])

    def stiffness_matrix(self) -> Array:
        return np.diag([self.mass_kg_m * self.omega_h**2, self.k_theta])


# --- divergence -------------------------------------------------------------------------


def divergence_pressure(s: Section) -> float:
    """Typical-section divergence dynamic pressure q_D = k_θ/(e·c·C_Lα); inf if the EA is
    at or ahead of the aerodynamic centre (lift then twists the section nose down). [Pa]"""
    arm = s.ac_ahead_of_ea_m
    if arm <= 0:
        return math.inf
    return s.k_theta / (arm * 2 * s.semichord_m * s.lift_slope)


def speed_of(q: float, rho: float) -> float:
    """Air speed of a dynamic pressure q = ½ρV². [m/s]"""
    return math.sqrt(2 * q / rho) if math.isfinite(q) else math.inf


def cantilever_divergence(
    stations: Array,
    gj: Array,
    arm_c_cla: Array,
    pressure_shape: Array,
    spring_per_length: Array | None = None,
    elements: int = 40,
) -> float:
    """Divergence of a torsion bar clamped at stations[0], by finite elements. [Pa]

    Solves (K_GJ + K_cf) φ = q·K_a φ for the lowest q, with the aerodynamic twisting stiffness
    K_a = ∫ e·c·C_Lα·s(x) NᵀN dx (s: local dynamic pressure / reference, e.g. (r/R)² on a
    rotor) and K_cf = ∫ k_cf NᵀN dx (centrifugal propeller-moment stiffness per length).
    Properties are given at ``stations``, linear in between. Returns inf when no positive
    divergence pressure exists (the EA at or ahead of the aerodynamic centre everywhere).
    """
    stations = np.asarray(stations, float)
    aero = np.asarray(arm_c_cla, float) * np.asarray(pressure_shape, float)
    if np.all(aero <= 0):
        return math.inf
    spring = np.zeros_like(stations) if spring_per_length is None else spring_per_length
    nodes = beam.mesh(stations, elements)
    x, _ = beam.gauss_points(nodes)

    def at(values: Array) -> Array:
        return beam.interpolate(x, stations, np.asarray(values, float))

    k_gj, k_a = beam.assemble_torsion(nodes, at(gj), at(aero))
    _, k_cf = beam.assemble_torsion(nodes, 0 * at(gj), at(spring))
    k, ka = (k_gj + k_cf)[1:, 1:], k_a[1:, 1:]  # clamp the root
    if np.any(aero < 0):  # moments of both signs: K_a indefinite, take the least positive q
        lam = np.linalg.eigvals(np.linalg.solve(k, ka))
        real = lam.real[np.abs(lam.imag) <= 1e-9 * np.abs(lam).max()]
        return float(1 / real.max()) if np.any(real > 0) else math.inf
    return float((2 * math.pi * solve(k, ka, count=1).frequency_hz[0]) ** 2)


# --- unsteady aerodynamics --------------------------------------------------------------


def theodorsen(k: float) -> complex:
    """Theodorsen's function C(k) = H₁⁽²⁾(k)/(H₁⁽²⁾(k) + i·H₀⁽²⁾(k)); C(0) = 1."""
    if k <= 0:
        return 1.0 + 0.0j
    from scipy.special import hankel2  # only aeroelastic checks pay for the import

    h1, h0 = hankel2(1, k), hankel2(0, k)
    return complex(h1 / (h1 + 1j * h0))


def aero_matrix(s: Section, k: float, speed: float, steady: bool = False) -> CArray:
    """Generalised aerodynamic forces [−L, M_EA] = A·[h, θ] for harmonic motion at reduced
    frequency k = ωb/U (Theodorsen, H&P eq. 5.310). ``steady``: the steady-flow model,
    lift ½ρU²·2b·C_Lα·θ at the quarter chord (no aerodynamic damping or inertia)."""
    b, a, rho, u = s.semichord_m, s.a, s.air_density, speed
    circ = s.lift_slope / (2 * math.pi)  # scale Theodorsen's 2π circulatory lift to C_Lα
    if steady:
        lift_theta = rho * u**2 * b * s.lift_slope
        return np.array([[0, -lift_theta], [0, b * (0.5 + a) * lift_theta]], dtype=complex)
    w = k * u / b
    c = theodorsen(k) * circ
    out = np.empty((2, 2), dtype=complex)
    for j, (h, th) in enumerate(((1.0, 0.0), (0.0, 1.0))):
        hd, hdd, thd, thdd = 1j * w * h, -(w**2) * h, 1j * w * th, -(w**2) * th
        q3 = hd + u * th + b * (0.5 - a) * thd  # downwash at the ¾ chord
        lift = (
            math.pi * rho * b**2 * (hdd + u * thd - b * a * thdd)
            + 2 * math.pi * rho * u * b * c * q3
        )
        moment = (
            math.pi
            * rho
            * b**2
            * (b * a * hdd - u * b * (0.5 - a) * thd - b**2 * (1 / 8 + a**2) * thdd)
            + 2 * math.pi * rho * u * b**2 * (a + 0.5) * c * q3
        )
        out[:, j] = (-lift, moment)
    return out


# --- flutter ----------------------------------------------------------------------------


@dataclass(frozen=True)
class Branch:
    """One aeroelastic mode along the speed sweep: frequency [rad/s] and damping ratio."""

    speed: Array
    omega: Array
    damping: Array


@dataclass(frozen=True)
class Flutter:
    """The flutter point (inf when none in the range) and the branches that led to it."""

    speed: float
    omega: float
    branches: tuple[Branch, ...]
    method: str
    divergence_speed: float = math.inf  # a real root crossing zero in the same sweep


def pk_root(
    s: Section, speed: float, omega_guess: float, steady: bool = False, index: int | None = None
) -> complex:
    """The p-k root p = σ + iω of a branch at air speed U: the ``index``-th oscillatory root
    by frequency while all branches oscillate, else the root nearest ``omega_guess``.

    Notes
    -----
    The aerodynamic matrix at k = ωb/U is split into an in-phase part (a stiffness) and a
    quadrature part divided by ω (a damping): M ẍ − (A_I/ω) ẋ + (K − A_R) x = 0; the
    frequency is iterated until it equals the one the aerodynamics were evaluated at.
    """
    m, kk = s.mass_matrix(), s.stiffness_matrix()
    w = omega_guess
    root = complex(0.0, w)
    for _ in range(60):
        a = aero_matrix(s, w * s.semichord_m / speed, speed, steady)
        roots = state_roots(kk - a.real, m, -a.imag / max(w, 1e-12))
        roots = roots[roots.imag >= 0]  # a real root continues a branch whose ω went to 0
        upper = roots[roots.imag > 0]
        upper = upper[np.argsort(upper.imag)]  # ascending frequency
        if index is not None and upper.size == 2:
            root = complex(upper[index])
        else:
            root = complex(roots[np.argmin(np.abs(roots - 1j * w))])
        # of roots at the same frequency (a real pair ±σ, a coalesced pair), the least stable
        twins = roots[np.abs(roots.imag - root.imag) <= 1e-9 * max(abs(root), 1.0)]
        root = complex(twins[np.argmax(twins.real)])
        if root.imag <= 0 or abs(root.imag - w) < 1e-10 * max(w, 1.0):
            break
        w = root.imag
    return root


def pk_sweep(s: Section, speeds: Array, steady: bool = False) -> Flutter:
    """p-k method over ``speeds`` (ascending); the flutter point refined by bisection."""
    m, kk = s.mass_matrix(), s.stiffness_matrix()
    start = np.sort(np.abs(state_roots(kk, m, np.zeros((2, 2))).imag))[::2]
    guesses = list(start)
    rows: list[list[complex]] = []
    for u in speeds:
        row = [pk_root(s, float(u), g, steady, j) for j, g in enumerate(guesses)]
        guesses = [r.imag if r.imag > 0 else g for r, g in zip(row, guesses, strict=True)]
        rows.append(row)
    roots = np.array(rows)
    damping = -roots.real / np.maximum(np.abs(roots), 1e-300)
    branches = tuple(Branch(speeds, roots[:, j].imag, damping[:, j]) for j in range(2))
    flutter_point, static = (math.inf, math.nan), math.inf
    for j in range(2):
        neg = np.nonzero(damping[:, j] < -1e-9)[0]
        if neg.size == 0 or neg[0] == 0:
            continue
        i = int(neg[0])
        lo, hi, g = float(speeds[i - 1]), float(speeds[i]), float(roots[i - 1, j].imag)
        for _ in range(40):
            mid = 0.5 * (lo + hi)
            r = pk_root(s, mid, g, steady, j)
            if r.real < 1e-9 * abs(r):
                lo, g = mid, r.imag if r.imag > 0 else g
            else:
                hi = mid
        r = pk_root(s, hi, g, steady, j)
        if r.imag > 1e-6 * g:
            flutter_point = min(flutter_point, (hi, r.imag))
        else:
            static = min(static, hi)
    method = "p-k (steady aerodynamics)" if steady else "p-k"
    return Flutter(flutter_point[0], flutter_point[1], branches, method, static)


def k_method(s: Section, reduced: Array) -> Flutter:
    """k-method (V-g): for each reduced frequency k, (1+ig)/ω² are the eigenvalues of
    K⁻¹(M + Ã(k)), Ã = A/ω²; U = ωb/k. Flutter where the required damping g crosses zero
    upward. ``reduced``: descending k values (speed rises along the sweep)."""
    m, kk = s.mass_matrix(), s.stiffness_matrix()
    b = s.semichord_m

    def eig(k: float) -> tuple[CArray, CArray]:
        # with U = ωb/k every aerodynamic term scales as ω²: evaluate at ω = 1
        a_tilde = aero_matrix(s, k, b / k)
        lam, vec = np.linalg.eig(np.linalg.solve(kk, m + a_tilde))
        return lam, vec

    lam0, _ = eig(float(reduced[0]))
    order = np.argsort(-lam0.real)  # low frequency = large Re λ
    rows = [lam0[order]]
    for k in reduced[1:]:
        lam, _ = eig(float(k))
        prev = rows[-1]
        pick = [int(np.argmin(np.abs(lam - p))) for p in prev]
        if pick[0] == pick[1]:
            pick = (
                [0, 1]
                if abs(lam[0] - prev[0]) + abs(lam[1] - prev[1])
                <= abs(lam[1] - prev[0]) + abs(lam[0] - prev[1])
                else [1, 0]
            )
        rows.append(lam[pick])
    lams = np.array(rows)
    omega = 1 / np.sqrt(np.maximum(lams.real, 1e-300))
    g = lams.imag / lams.real
    speeds = omega * b / reduced[:, None]
    branches = tuple(Branch(speeds[:, j], omega[:, j], g[:, j]) for j in range(2))
    best = (math.inf, math.nan)
    for j in range(2):
        valid = lams[:, j].real > 0  # Re λ ≤ 0: no real frequency (static divergence region)
        up = np.nonzero((g[:-1, j] < 0) & (g[1:, j] >= 0) & valid[:-1] & valid[1:])[0]
        if up.size == 0:
            continue
        i = int(up[0])

        def g_of(k: float, j: int = j, ref: complex = lams[i, j]) -> float:
            lam, _ = eig(k)
            v = lam[np.argmin(np.abs(lam - ref))]
            return float(v.imag / v.real)

        lo, hi = float(reduced[i]), float(reduced[i + 1])
        for _ in range(50):
            mid = 0.5 * (lo + hi)
            if g_of(mid) < 0:
                lo = mid
            else:
                hi = mid
        lam, _ = eig(hi)
        v = lam[np.argmin(np.abs(lam - lams[i, j]))]
        if v.real <= 0:
            continue
        w = 1 / math.sqrt(v.real)
        if w * b / hi < best[0]:
            best = (w * b / hi, w)
    return Flutter(best[0], best[1], branches, "k (V-g)")


def flutter(s: Section, top_speed: float, steps: int = 120) -> Flutter:
    """Flutter speed by the p-k method from 1 % to ``top_speed`` (inf if none below it)."""
    speeds = np.linspace(0.01 * top_speed, top_speed, steps)
    return pk_sweep(s, speeds)


# --- stability-limit chart (Hau Fig. 7.6) -----------------------------------------------


@dataclass(frozen=True)
class StabilityChart:
    """Torsional stiffness [N·m/rad per m] at the divergence and flutter limits against the
    centre-of-mass offset behind the elastic axis [fraction of chord], for one section at
    one air speed; the flutter limit is nan where the section does not flutter."""

    offset_chord: Array
    flutter_k_theta: Array
    divergence_k_theta: float
    blade_offset_chord: float
    blade_k_theta: float
    speed: float


def _k_method_speeds(s: Section, a_tilde: CArray, reduced: Array, w_theta: Array) -> Array:
    """k-method flutter speeds for torsion frequencies ``w_theta`` (all else fixed), from
    aerodynamic matrices Ã(k) precomputed on ``reduced`` (descending). Vectorised over both
    (closed-form 2×2 eigenvalues); the zero crossing of g is interpolated linearly on the k
    grid (for charts, not for checks)."""
    m = s.mass_matrix()
    rows = m[None, :, :] + a_tilde  # (nk, 2, 2): M + Ã(k)
    a00 = np.broadcast_to(
        rows[:, 0, 0] / (s.mass_kg_m * s.omega_h**2), (len(w_theta), len(reduced))
    )
    a01 = np.broadcast_to(rows[:, 0, 1] / (s.mass_kg_m * s.omega_h**2), a00.shape)
    k_t = s.inertia_kgm * np.asarray(w_theta)[:, None] ** 2
    a10, a11 = rows[None, :, 1, 0] / k_t, rows[None, :, 1, 1] / k_t
    half = 0.5 * (a00 + a11)
    root = np.sqrt(half**2 - (a00 * a11 - a01 * a10))
    lam1, lam2 = half + root, half - root
    first = lam1.real >= lam2.real  # branch 0: the larger Re λ (lower frequency)
    lam = np.stack([np.where(first, lam1, lam2), np.where(first, lam2, lam1)], axis=-1)
    valid = lam.real > 0
    re = np.where(valid, lam.real, 1.0)
    g = np.where(valid, lam.imag / re, np.nan)
    speed = np.where(valid, s.semichord_m / (np.sqrt(re) * reduced[None, :, None]), np.nan)
    up = (g[:, :-1] < 0) & (g[:, 1:] >= 0)  # (nw, nk-1, 2)
    found = up.any(axis=1)
    n = np.argmax(up, axis=1)  # first crossing per (w, branch)
    take = np.arange(len(w_theta))[:, None], n, np.arange(2)[None, :]
    g0, g1 = g[take], g[(take[0], n + 1, take[2])]
    v0, v1 = speed[take], speed[(take[0], n + 1, take[2])]
    with np.errstate(invalid="ignore", divide="ignore"):
        v = v0 + (-g0 / (g1 - g0)) * (v1 - v0)
    return np.asarray(np.where(found, v, np.inf).min(axis=1))


def stability_chart(s: Section, speed: float, points: int = 25) -> StabilityChart:
    """Divergence and flutter limits of the section's torsional stiffness at air ``speed``,
    over centre-of-mass offsets from 5 % chord ahead of the elastic axis to 25 % behind."""
    reduced = np.geomspace(6.0, 0.01, 400)
    b = s.semichord_m
    a_tilde = np.stack([aero_matrix(s, float(k), b / float(k)) for k in reduced])
    offsets = np.linspace(-0.05, 0.25, points)
    w_grid = s.omega_theta * np.geomspace(0.1, 10.0, 60)
    limit = np.full(points, np.nan)
    for i, off in enumerate(offsets):
        trial = Section(**{**s.__dict__, "x_theta": 2 * off})
        u_f = _k_method_speeds(trial, a_tilde, reduced, w_grid)
        # stiffer than the last grid point that still flutters below ``speed``: stable
        fails = np.nonzero(u_f < speed)[0]
        if fails.size and fails[-1] < len(w_grid) - 1:
            lo = int(fails[-1])
            ratio = (speed - u_f[lo]) / (u_f[lo + 1] - u_f[lo]) if np.isfinite(u_f[lo + 1]) else 0.5
            w = w_grid[lo] * (w_grid[lo + 1] / w_grid[lo]) ** float(np.clip(ratio, 0, 1))
            limit[i] = s.inertia_kgm * w**2
    q = 0.5 * s.air_density * speed**2
    return StabilityChart(
        offsets,
        limit,
        q * s.ac_ahead_of_ea_m * 2 * b * s.lift_slope,
        s.x_theta / 2,
        s.k_theta,
        speed,
    )


# --- the audit checks -------------------------------------------------------------------


@dataclass(frozen=True)
class StationResult:
    """Divergence and flutter of one blade section at the highest section speed."""

    radius_m: float
    section_speed: float  # √((Ω_over·r)² + V_max²) [m/s]
    section: Section
    divergence_speed: float
    flutter: Flutter
    flutter_k_speed: float  # k-method cross-check [m/s]


def rotor_radius(spec: "Spec") -> float | None:
    """Rotor radius R: half the rotor diameter, else hub radius plus the blade's span."""
    if spec.turbine.rotor_diameter_m is not None:
        return spec.turbine.rotor_diameter_m / 2
    st = spec.blade.structure
    if st is not None:
        return st.hub_radius_m + st.span_m[-1]
    return spec.blade.length_m


def stations(spec: "Spec", modes: "Sequence[Mode]") -> tuple[list[StationResult], list[str]]:
    """Typical sections of ``blade.aeroelastic`` at overspeed; or what is missing."""
    ae = spec.blade.aeroelastic
    assert ae is not None
    radius = rotor_radius(spec)
    by_id = {m.id: m for m in modes}
    st = spec.blade.structure
    missing = [
        need
        for need, ok in (
            ("turbine.rotor_diameter_m (or blade.structure)", radius is not None),
            ("blade.modes.flap1", "blade.flap1" in by_id),
            ("blade.modes.tor1 (or blade.structure with gj_nm2)", "blade.tor1" in by_id),
        )
        if not ok
    ]
    for i, sec in enumerate(ae.sections):
        for name in ("mass_per_length_kg_m", "torsional_inertia_kgm"):
            if getattr(sec, name) is None and (st is None or getattr(st, name) is None):
                missing.append(f"blade.aeroelastic.sections.{i}.{name}")
    if missing:
        return [], missing
    assert radius is not None
    omega = float(rpm_to_rad_s(spec.rotor.speed.overspeed))
    out = []
    for i, sec in enumerate(ae.sections):
        r = sec.radius_fraction * radius
        m = sec.mass_per_length_kg_m or _along(spec, "mass_per_length_kg_m", r)
        inertia = sec.torsional_inertia_kgm or _along(spec, "torsional_inertia_kgm", r)
        try:
            check_section_inertia(m, inertia, sec.offset_m)
        except ValueError as exc:  # the inertia interpolated from blade.structure
            raise SpecError(str(exc), path=f"blade.aeroelastic.sections.{i}") from None
        beta = math.radians(sec.chord_angle_deg)
        w_h = 2 * math.pi * float(by_id["blade.flap1"].frequency_at(omega)[()])
        # torsion stiffened by the propeller moment: ω_θ² = ω_θ0² + Ω²·cos 2β
        w_t0 = 2 * math.pi * by_id["blade.tor1"].frequency_hz
        w_t = math.sqrt(max(w_t0**2 + omega**2 * math.cos(2 * beta), 1e-12))
        s = Section(
            sec.chord_m / 2,
            2 * sec.elastic_axis_chord - 1,
            2 * (sec.centre_of_mass_chord - sec.elastic_axis_chord),
            m,
            inertia,
            w_h,
            w_t,
            ae.air_density_kg_m3,
            ae.lift_slope_per_rad,
        )
        speed = math.hypot(omega * r, ae.max_wind_m_s)
        top = 3.0 * speed
        f = flutter(s, top)
        k_check = k_method(s, np.geomspace(8.0, max(0.3 * w_h * s.semichord_m / top, 1e-4), 300))
        out.append(
            StationResult(
                r, speed, s, speed_of(divergence_pressure(s), s.air_density), f, k_check.speed
            )
        )
    return out, []


def _along(spec: "Spec", name: str, r: float) -> float:
    st = spec.blade.structure
    assert st is not None
    values = getattr(st, name)
    return float(np.interp(r - st.hub_radius_m, st.span_m, values))


def blade_divergence(spec: "Spec") -> float | None:
    """Cantilever divergence as a load factor on the pressures at overspeed and V_max
    (≥ 1: stable); None without the blade's torsional stiffness. Strip theory with the first
    section's e·c·C_Lα along the whole span (a uniform aerodynamic arm: stated)."""
    ae, st = spec.blade.aeroelastic, spec.blade.structure
    if ae is None or st is None or st.gj_nm2 is None or st.torsional_inertia_kgm is None:
        return None
    sec = ae.sections[0]
    omega = float(rpm_to_rad_s(spec.rotor.speed.overspeed))
    x = np.asarray(st.span_m, float)
    r = st.hub_radius_m + x
    arm = sec.chord_m * (sec.elastic_axis_chord - 0.25) * sec.chord_m * ae.lift_slope_per_rad
    pressure = 0.5 * ae.air_density_kg_m3 * ((omega * r) ** 2 + ae.max_wind_m_s**2)
    spring = (
        omega**2
        * np.asarray(st.torsional_inertia_kgm)
        * math.cos(2 * math.radians(sec.chord_angle_deg))
    )
    return cantilever_divergence(x, np.asarray(st.gj_nm2), np.full_like(x, arm), pressure, spring)


def _status(ratio: float, margin: float) -> "Status":
    return "pass" if ratio >= 1 + margin else "warn" if ratio >= 1 else "fail"


def checks(spec: "Spec", modes: "Sequence[Mode]") -> "tuple[list[Check], list[StationResult]]":
    """``blade.divergence`` and ``blade.flutter``: critical speeds over the highest section
    speed (tip or section speed at transient overspeed, with the cut-out wind)."""
    from ..results import Check, Rule

    ae = spec.blade.aeroelastic
    if ae is None:
        return [], []
    div_rule = Rule(
        f"divergence speed ≥ (1 + {ae.speed_margin:g})·highest section speed",
        "Hau ch. 7.2.2 (Fig. 7.6); typical section and strip-theory cantilever (Hodges & "
        "Pierce, Introduction to Structural Dynamics and Aeroelasticity, 2011, ch. 3 and 5)",
    )
    flut_rule = Rule(
        f"flutter speed ≥ (1 + {ae.speed_margin:g})·highest section speed",
        "Hau ch. 7.2.2; Theodorsen aerodynamics, p-k method (Hassig 1971), k-method check",
    )
    results, missing = stations(spec, modes)
    if missing:
        text = "not analysed: needs " + ", ".join(missing)
        return [
            Check("blade.divergence", "blade", "info", text, div_rule),
            Check("blade.flutter", "blade", "info", text, flut_rule),
        ], []
    return [
        _divergence(spec, results, ae.speed_margin, div_rule),
        _flutter(results, ae.speed_margin, flut_rule),
    ], results


def _divergence(
    spec: "Spec", results: "list[StationResult]", margin: float, rule: "Rule"
) -> "Check":
    """``blade.divergence``: every typical section, then the whole blade as a cantilever."""
    from ..results import Check

    div = [(r.divergence_speed / r.section_speed, r) for r in results]
    worst_ratio, worst = min(div, key=lambda t: t[0])
    factor = blade_divergence(spec)
    cantilever_ratio = math.sqrt(factor) if factor is not None else None
    ratios = [worst_ratio] + ([cantilever_ratio] if cantilever_ratio is not None else [])
    ratio = min(ratios)
    where = f"section at r = {worst.radius_m:.3g} m"
    if math.isinf(ratio):
        text = "no divergence: the elastic axis is at or ahead of the aerodynamic centre"
    else:
        text = (
            f"divergence at {ratio:.2f}× the highest section speed "
            f"({where}: V_D = {worst.divergence_speed:.4g} m/s vs {worst.section_speed:.4g} m/s"
            + (
                f"; whole blade {cantilever_ratio:.2f}×"
                if cantilever_ratio is not None and math.isfinite(cantilever_ratio)
                else ""
            )
            + ")"
        )
    numbers = {
        "speed_ratio": _finite(ratio),
        "sections": [
            {
                "radius_m": round(r.radius_m, 4),
                "section_speed_m_s": round(r.section_speed, 4),
                "divergence_speed_m_s": _finite(r.divergence_speed),
                "divergence_pressure_pa": _finite(divergence_pressure(r.section)),
            }
            for r in results
        ],
        "cantilever_load_factor": _finite(factor) if factor is not None else None,
    }
    return Check("blade.divergence", "blade", _status(ratio, margin), text, rule, numbers)


def _flutter(results: "list[StationResult]", margin: float, rule: "Rule") -> "Check":
    """``blade.flutter``: the section that flutters first, relative to its own speed."""
    from ..results import Check

    fl = [(r.flutter.speed / r.section_speed, r) for r in results]
    f_ratio, fw = min(fl, key=lambda t: t[0])
    if math.isinf(f_ratio):
        text = (
            f"no flutter up to 3× the highest section speed "
            f"({fw.section_speed:.4g} m/s at r = {fw.radius_m:.3g} m)"
        )
    else:
        text = (
            f"flutter at {f_ratio:.2f}× the highest section speed (r = {fw.radius_m:.3g} m: "
            f"U_F = {fw.flutter.speed:.4g} m/s at {fw.flutter.omega / (2 * math.pi):.3g} Hz, "
            f"section speed {fw.section_speed:.4g} m/s)"
        )
    numbers = {
        "speed_ratio": _finite(f_ratio),
        "sections": [
            {
                "radius_m": round(r.radius_m, 4),
                "section_speed_m_s": round(r.section_speed, 4),
                "flutter_speed_m_s": _finite(r.flutter.speed),
                "flutter_frequency_hz": _finite(r.flutter.omega / (2 * math.pi)),
                "flutter_speed_k_method_m_s": _finite(r.flutter_k_speed),
                "mass_ratio": round(
                    r.section.mass_kg_m
                    / (math.pi * r.section.air_density * r.section.semichord_m**2),
                    4,
                ),
            }
            for r in results
        ],
        "vg_section_radius_m": round(fw.radius_m, 4),
        "vg_section_speed_m_s": round(fw.section_speed, 4),
    }
    return Check("blade.flutter", "blade", _status(f_ratio, margin), text, rule, numbers)


def _finite(x: float) -> float | None:
    """JSON has no infinity: None stands for 'none in the range'."""
    return round(x, 6) if math.isfinite(x) else None


# ---------------------------------------------------------------------------------------
# The subsystem protocol (wtvib.judge.analysis): the blade's aeroelastic stability

NAME = "aeroelastic"


default_damping = blade_damping
build_modes = no_modes  # it judges the blade's modes


@dataclass(frozen=True)
class AeroelasticResults:
    """What the blade's stability figures draw: every station's result, the one nearest to
    flutter (its V-g curves) and its stability-limits chart at the required speed."""

    stations: "tuple[StationResult, ...]"
    worst: "StationResult"
    required_speed_m_s: float
    chart: StabilityChart


def analyse(spec: "Spec", ctx: Context) -> Analysis:
    """``blade.divergence`` and ``blade.flutter``, with the station results, the station
    nearest to flutter (its V-g curves) and its stability-limits chart (Hau Fig. 7.6) at the
    required speed."""
    found, stations_ = checks(spec, ctx.modes)
    ae = spec.blade.aeroelastic
    if not stations_ or ae is None:
        return Analysis(checks=tuple(found))
    worst = min(stations_, key=lambda r: r.flutter.speed / r.section_speed)
    required = worst.section_speed * (1 + ae.speed_margin)
    return Analysis(
        checks=tuple(found),
        results=AeroelasticResults(
            tuple(stations_), worst, required, stability_chart(worst.section, required)
        ),
    )


SUBSYSTEM = Subsystem(
    NAME,
    build_modes,
    default_damping,
    analyse,
    figures=("blade-flutter", "blade-stability"),
)
