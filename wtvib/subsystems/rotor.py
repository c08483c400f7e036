"""Rotors with one or two blades: periodic coefficients and Floquet stability (Hau ch. 7.6).

A two-bladed rotor's inertia about the tilt and yaw axes changes twice per revolution, so
the tower head's equations of motion have periodic coefficients. Model (nacelle-fixed axes:
x shaft, y tilt axis, z yaw axis; azimuth ψ = Ωt from the vertical; rotor polar inertia
J_p, blades as a line of point masses):

* hingeless hub — nacelle tilt θ and yaw φ carry the rotor rigidly:
  (I_y + J_p cos²ψ)θ̈ + J_p sinψ cosψ φ̈ − J_pΩ sin2ψ θ̇ + J_pΩ(1 + cos2ψ) φ̇ + c_θθ̇ + k_θθ = 0
  J_p sinψ cosψ θ̈ + (I_z + J_p sin²ψ)φ̈ − J_pΩ(1 − cos2ψ) θ̇ + J_pΩ sin2ψ φ̇ + c_φφ̇ + k_φφ = 0
  (Newton–Euler: M = dH/dt + ω × H; the moments it gives for steady yawing are the
  gyroscopic J_p·Ω·Ω_yaw·(1 + cos 2ψ) and sin 2ψ of Hau ch. 7.4.1.)
* teetered hub — a teeter angle β about the axis across the blades; the gyroscopic terms
  cancel and the nacelle feels only the teeter spring and damper:
  I_yθ̈ + c_θθ̇ + k_θθ = (k_ββ + c_ββ̇) cosψ,  I_zφ̈ + c_φφ̇ + k_φφ = (k_ββ + c_ββ̇) sinψ,
  J_pβ̈ + c_ββ̇ + (k_β + J_pΩ²)β = −J_p(θ̈ cosψ + φ̈ sinψ + 2Ω(φ̇ cosψ − θ̇ sinψ)).

With three or more blades the sums over the blades make every coefficient constant (the
multi-blade view: the rotor's inertia is isotropic in its plane).

Floquet: the multipliers of one revolution by :mod:`wtvib.numerics.floquet`'s integrator, over the
rotor speeds from 10 % of the lowest steady speed to 130 % of the overspeed limit: the
``rotor.floquet`` check and its stability map.

References
----------
Hau ch. 6.8.2 and 7.6; DOMAIN.md §3; P. P. Friedmann, Computers & Structures 35 (1990).
"""

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from ..judge.analysis import Analysis, Context, Damping, Subsystem, no_modes, section_damping
from ..judge.excitation import operating_range
from ..judge.resonance import split_by_regime
from ..numerics import modal
from ..numerics.floquet import (
    GROWTH,
    MAX_STEPS,
    MIN_STEPS,
    REFINE,
    StateMatrix,
    monodromy_batch,
    steps_for,
)
from ..units import rad_s_to_rpm, rpm_to_rad_s

if TYPE_CHECKING:
    from ..judge.excitation import OperatingRange
    from ..results import Check, Mode
    from ..spec import Spec

Array = NDArray[np.float64]


@dataclass(frozen=True)
class HeadModel:
    """Tower head on yaw and tilt springs carrying a rotor (SI units)."""

    blades: int
    hub: str
    polar: float  # J_p
    tilt_inertia: float  # I_y without the rotor
    yaw_inertia: float  # I_z without the rotor
    tilt_stiffness: float
    yaw_stiffness: float
    tilt_damping: float
    yaw_damping: float
    teeter_stiffness: float = 0.0
    teeter_damping: float = 0.0

    def parts(self, psi: float | Array) -> tuple[Array, Array, Array, Array, Array]:
        """M(ψ), G₀(ψ), G₁(ψ), K₀(ψ), K₂ with G = G₀ + Ω·G₁ and K = K₀ + Ω²·K₂; for an
        array of azimuths each has that leading shape (all azimuths of a sweep at once)."""
        jp = self.polar
        psi_a = np.asarray(psi, dtype=float)
        lead = psi_a.shape
        s, c = np.sin(psi_a), np.cos(psi_a)

        def full(n: int) -> Array:
            return np.zeros((*lead, n, n))

        if self.blades >= 3:
            m, g0, g1, k0 = full(2), full(2), full(2), full(2)
            m[..., 0, 0], m[..., 1, 1] = self.tilt_inertia + jp / 2, self.yaw_inertia + jp / 2
            g0[..., 0, 0], g0[..., 1, 1] = self.tilt_damping, self.yaw_damping
            g1[..., 0, 1], g1[..., 1, 0] = jp, -jp
            k0[..., 0, 0], k0[..., 1, 1] = self.tilt_stiffness, self.yaw_stiffness
            return m, g0, g1, k0, full(2)
        if self.hub == "teetered":
            kb, cb = self.teeter_stiffness, self.teeter_damping
            m, g0, g1, k0, k2 = full(3), full(3), full(3), full(3), full(3)
            m[..., 0, 0], m[..., 1, 1] = self.tilt_inertia, self.yaw_inertia
            m[..., 2, 0], m[..., 2, 1], m[..., 2, 2] = jp * c, jp * s, jp
            g0[..., 0, 0], g0[..., 1, 1], g0[..., 2, 2] = self.tilt_damping, self.yaw_damping, cb
            g0[..., 0, 2], g0[..., 1, 2] = -cb * c, -cb * s
            g1[..., 2, 0], g1[..., 2, 1] = -2 * jp * s, 2 * jp * c
            k0[..., 0, 0], k0[..., 1, 1] = self.tilt_stiffness, self.yaw_stiffness
            k0[..., 2, 2] = kb
            k0[..., 0, 2], k0[..., 1, 2] = -kb * c, -kb * s
            k2[..., 2, 2] = jp
            return m, g0, g1, k0, k2
        s2, c2 = np.sin(2 * psi_a), np.cos(2 * psi_a)
        m, g0, g1, k0 = full(2), full(2), full(2), full(2)
        m[..., 0, 0], m[..., 1, 1] = self.tilt_inertia + jp * c * c, self.yaw_inertia + jp * s * s
        m[..., 0, 1] = m[..., 1, 0] = jp * s * c
        g0[..., 0, 0], g0[..., 1, 1] = self.tilt_damping, self.yaw_damping
        g1[..., 0, 0], g1[..., 0, 1] = -jp * s2, jp * (1 + c2)
        g1[..., 1, 0], g1[..., 1, 1] = -jp * (1 - c2), jp * s2
        k0[..., 0, 0], k0[..., 1, 1] = self.tilt_stiffness, self.yaw_stiffness
        return m, g0, g1, k0, full(2)

    def state_matrices(self, omegas: Array, psi: float | Array) -> Array:
        """A at azimuth ψ for many rotor speeds Ω [rad/s], shape (speeds, 2n, 2n); for an
        array of azimuths (azimuths, speeds, 2n, 2n)."""
        m, g0, g1, k0, k2 = (x[..., None, :, :] for x in self.parts(psi))
        w = np.asarray(omegas, dtype=float)[:, None, None]
        return modal.state_matrix(k0 + w**2 * k2, m, g0 + w * g1)

    def state_matrix(self, omega: float) -> StateMatrix:
        """A(t) of the first-order system at rotor speed Ω [rad/s]."""
        return lambda t: self.state_matrices(np.array([omega]), omega * t)[0]


def stability_map(model: "HeadModel", speeds_rad_s: Array) -> Array:
    """Largest Floquet multiplier magnitude over rotor speeds (1 on a stability boundary;
    NaN where the multipliers do not come out finite: not analysed).

    Each speed gets :func:`steps_for` its fastest mode (from A at ψ = 0); speeds needing the
    same power-of-two multiple of :data:`MIN_STEPS` are integrated together; a speed needing
    more than :data:`MAX_STEPS` is not analysed (NaN). A speed that shows growth is
    integrated again on finer steps (floquet.REFINE): growth is what stays.
    """
    w = np.asarray(speeds_rad_s, dtype=float)
    with np.errstate(all="ignore"):
        fastest = np.abs(np.linalg.eigvals(model.state_matrices(w, 0.0))).max(axis=1)
        need = np.array(  # capped past MAX_STEPS: those speeds are not analysed anyway
            [
                min(steps_for(f / (2 * math.pi), 2 * math.pi / x), MAX_STEPS + 1)
                if math.isfinite(f / x)
                else MAX_STEPS + 1
                for f, x in zip(fastest, w, strict=True)
            ]
        )
        bucket = MIN_STEPS * 2 ** np.ceil(np.log2(need / MIN_STEPS)).astype(int)
        largest = np.full(w.shape, np.nan)
        todo = need <= MAX_STEPS  # beyond: not analysed (NaN)
        for k in (1, *REFINE):
            for steps in np.unique(bucket[todo]):
                sel = (bucket == steps) & todo

                def a_of_psi(psi: float | Array, sel: NDArray[np.bool_] = sel) -> Array:
                    return model.state_matrices(w[sel], psi)

                phi = monodromy_batch(a_of_psi, w[sel], int(k * steps), every_azimuth=True)
                finite = np.all(np.isfinite(phi), axis=(1, 2))
                phi[~finite] = 0.0
                found = np.max(np.abs(np.linalg.eigvals(phi)), axis=1)
                # NaN: not analysed; a finer pass that is not finite keeps the coarser answer
                largest[sel] = np.where(finite, found, np.nan if k == 1 else largest[sel])
            todo = todo & (largest > 1 + GROWTH)  # integrated again, finer, where it grows
            if not todo.any():
                break
    return largest


def head_model(spec: "Spec", modes: "Sequence[Mode]") -> tuple[HeadModel | None, list[str]]:
    """The tower-head model of a spec, or None with what is missing.

    Notes
    -----
    Rotor J_p: ``yaw.rotor_polar_inertia_kgm2`` or blades + hub of the drive-train chain.
    Nacelle yaw inertia without the rotor: the head's yaw inertia (``yaw.inertia_kgm2`` or
    tower_head I_yaw + M·x²) less the rotor's mean J_p/2; tilt likewise from the head's
    pitch inertia, else equal to yaw. Stiffnesses put the head on its yaw mode (yaw.1, else
    the tower's first torsion) and on the tower's first fore-aft bending (the head's nodding
    in that mode, an approximation), with the rotor's mean inertia: k = (I + J_p/2)(2πf)².
    Damping from the yaw and tower default damping ratios.
    """
    from . import yaw as yaw_mod

    by_id = {m.id: m for m in modes}
    j_p = yaw_mod.rotor_polar_inertia(spec)
    f_yaw = next((by_id[i].frequency_hz for i in ("yaw.1", "tower.tor1") if i in by_id), None)
    f_tilt = next((by_id[i].frequency_hz for i in ("tower.fa1", "tower.ss1") if i in by_id), None)
    head = spec.tower_head
    total_yaw = spec.yaw.inertia_kgm2 or (
        head.inertia_yaw_kgm2 + head.mass_kg * head.cm_downwind_m**2 if head else None
    )
    missing = [
        name
        for name, v in (
            ("the rotor's polar inertia", j_p),
            ("a yaw (or tower torsion) frequency", f_yaw),
            ("a first tower bending frequency", f_tilt),
            ("the tower head's yaw inertia", total_yaw),
        )
        if not v
    ]
    if missing:
        return None, missing
    assert j_p and f_yaw and f_tilt and total_yaw
    i_z = max(total_yaw - j_p / 2, 0.05 * j_p)
    i_y = (
        max(head.inertia_pitch_kgm2 - j_p / 2, 0.05 * j_p)
        if head and head.inertia_pitch_kgm2
        else i_z
    )
    k_z = (i_z + j_p / 2) * (2 * math.pi * f_yaw) ** 2
    k_y = (i_y + j_p / 2) * (2 * math.pi * f_tilt) ** 2
    c_z = 2 * spec.yaw.damping_ratio * math.sqrt(k_z * (i_z + j_p / 2))
    c_y = 2 * spec.tower.damping_ratio * math.sqrt(k_y * (i_y + j_p / 2))
    hub = "hingeless" if spec.rotor.hub == "hinged" else spec.rotor.hub  # no flap hinges here
    return HeadModel(
        spec.rotor.blades,
        hub,
        j_p,
        i_y,
        i_z,
        k_y,
        k_z,
        c_y,
        c_z,
        spec.rotor.teeter_stiffness_nm_rad,
        spec.rotor.teeter_damping_nms_rad,
    ), []


@dataclass(frozen=True)
class StabilityMap:
    """Largest Floquet multiplier over rotor speed: ``speeds`` [rad/s], ``largest`` (NaN:
    not analysed) and the ``unstable`` speed bands [rad/s]."""

    speeds: Array
    largest: Array
    unstable: tuple[tuple[float, float], ...]

    @property
    def speeds_rpm(self) -> Array:
        return rad_s_to_rpm(self.speeds)

    @property
    def unstable_rpm(self) -> tuple[tuple[float, float], ...]:
        return tuple((float(rad_s_to_rpm(a)), float(rad_s_to_rpm(b))) for a, b in self.unstable)


#: the rotor's blade count in words, where a message names it
_BLADED = {1: "one", 2: "two"}


def bladed(blades: int) -> str:
    """ "one-bladed", "two-bladed" …: a rotor's blade count as a message says it."""
    return f"{_BLADED.get(blades, str(blades))}-bladed"


def map_for(op: "OperatingRange", model: HeadModel, points: int = 200) -> StabilityMap:
    """|ρ|max from 10 % of the lowest steady speed to 130 % of the overspeed limit."""
    w = np.linspace(0.1 * op.lowest, 1.3 * op.overspeed, points)
    largest = stability_map(model, w)
    bad = largest > 1 + GROWTH
    bands = []
    i = 0
    while i < len(w):
        if bad[i]:
            j = i
            while j + 1 < len(w) and bad[j + 1]:
                j += 1
            bands.append((float(w[i]), float(w[j])))
            i = j + 1
        else:
            i += 1
    return StabilityMap(w, largest, tuple(bands))


def check(spec: "Spec", modes: "Sequence[Mode]") -> "tuple[Check, StabilityMap | None]":
    """The ``rotor.floquet`` check: parametric stability of the tower head with its rotor."""
    from ..results import Check, Rule

    rule = Rule(
        "Floquet multipliers of the monodromy matrix, |ρ| ≤ 1",
        "Hau ch. 6.8.2 and 7.6 (periodic coefficients, Floquet theory)",
    )
    if spec.rotor.orientation == "vertical-axis":
        why = "vertical-axis rotor: the tower-head yaw/tilt model does not apply"
        return Check("rotor.floquet", "rotor", "info", why, rule), None
    if spec.rotor.blades >= 3:
        why = (
            f"{spec.rotor.blades} blades: the rotor's inertia is isotropic in its plane, "
            "the equations are time-invariant — no parametric excitation"
        )
        return Check("rotor.floquet", "rotor", "info", why, rule), None
    rotor = f"{bladed(spec.rotor.blades)} rotor"
    speed = spec.rotor.speed
    if not speed.overspeed > 0:  # parked: no period, the parked modes are its modes
        why = f"{rotor} not analysed: it does not turn (0 rpm), so its equations have no period"
        return Check("rotor.floquet", "rotor", "info", why, rule), None
    model, missing = head_model(spec, modes)
    if model is None:
        why = f"{rotor} not analysed: needs " + ", ".join(missing)
        return Check("rotor.floquet", "rotor", "info", why, rule), None
    smap = map_for(operating_range(speed), model)
    status, text = _verdict(smap, f"{model.hub} {rotor}", operating_range(speed))
    steady_rpm = np.concatenate(
        [np.linspace(a, b, 25) if b > a else np.array([a]) for a, b in speed.steady_rpm]
    )
    in_operation = stability_map(model, rpm_to_rad_s(steady_rpm))
    skipped = [float(x) for x in smap.speeds_rpm[np.isnan(smap.largest)]]
    status, text = _unanalysed(status, text, f"{model.hub} {rotor}", in_operation, skipped)
    if spec.rotor.hub != model.hub:
        text += (
            f" (the spec's {spec.rotor.hub} hub modelled as {model.hub}: the tower-head model "
            "has no flap hinges)"
        )
    finite = in_operation[np.isfinite(in_operation)]
    numbers = {
        "max_multiplier_in_operation": round(float(np.max(finite)), 6) if finite.size else None,
        "not_analysed_rpm": [round(x, 4) for x in skipped],
        "unstable_rpm": [[round(a, 4), round(b, 4)] for a, b in smap.unstable_rpm],
        "hub": model.hub,
        "polar_inertia_kgm2": model.polar,
    }
    return Check("rotor.floquet", "rotor", status, text, rule, numbers), smap  # type: ignore[arg-type]


def _verdict(smap: "StabilityMap", hub: str, op: "OperatingRange") -> tuple[str, str]:
    """The status and sentence of the unstable bands by where they lie: in steady operation
    a failure, only at start-up or overspeed a warning, outside the range a pass."""
    unstable = list(smap.unstable)
    split = split_by_regime(unstable, op, lambda w: any(a <= w <= b for a, b in unstable))
    steady = split["steady"] + split["quick-pass"]
    transient = split["overspeed"] + split["start-up"]
    bands = ", ".join(f"{a:.3g}–{b:.3g} rpm" for a, b in smap.unstable_rpm) or "none"
    if steady:
        text = f"{hub}: parametric instability in steady operation (unstable bands {bands})"
        if not hub.startswith("teetered"):
            text += " — the hazardous concept of a hingeless rotor on a flexible tower (Hau 7.5.1)"
        return "fail", text
    if transient:
        return "warn", f"{hub}: unstable only at start-up or overspeed ({bands})"
    text = f"{hub}: stable over the operating range (unstable bands outside it: {bands})"
    if hub.startswith("teetered"):
        text += " — the teetered hub decouples the rotor moments"
    return "pass", text


def _unanalysed(
    status: str, text: str, hub: str, in_operation: NDArray[np.float64], skipped: list[float]
) -> tuple[str, str]:
    """The verdict where some speeds could not be integrated: nothing known in operation
    is a warning that says only that; part of the range unknown is not a pass."""
    why = (
        f"multipliers not finite, or a mode so much faster than the rotor that one "
        f"revolution would need over {MAX_STEPS:,} integration steps"
    )
    if np.isnan(in_operation).all():  # nothing known in operation: say that, nothing else
        return "warn", f"{hub}: not analysed at any operating speed ({why})"
    if skipped:
        text += (
            f"; not analysed at {len(skipped)} speeds between {min(skipped):.3g} and "
            f"{max(skipped):.3g} rpm ({why})"
        )
        if status == "pass" and np.isnan(in_operation).any():
            status = "warn"  # part of the operating range is unknown: not a pass
    return status, text


# ---------------------------------------------------------------------------------------
# The subsystem protocol (wtvib.judge.analysis): the rotor as a periodic system on the tower head

NAME = "rotor"


def default_damping(spec: "Spec") -> Damping:
    return section_damping(spec.yaw, "yaw")


build_modes = no_modes  # its modes are the tower's and the yaw system's; it judges them


@dataclass(frozen=True)
class RotorResults:
    """What the Floquet figure draws: the stability map over rotor speed."""

    map: StabilityMap


def analyse(spec: "Spec", ctx: Context) -> Analysis:
    """``rotor.floquet`` and the stability map it draws (two-bladed rotors)."""
    found, smap = check(spec, ctx.modes)
    return Analysis(checks=(found,), results=RotorResults(smap) if smap is not None else None)


SUBSYSTEM = Subsystem(
    NAME,
    build_modes,
    default_damping,
    analyse,
    part="rotor",
    figures=("floquet",),
)
