"""Yaw system: tower head on the yaw drive (and tower torsion), gear play, friction,
yaw moments and gyroscopics (Hau ch. 7.4, Figs. 7.17 and 7.18).

One-mass model: the tower head's inertia about the yaw axis on the drives' stiffness
(n drives in parallel) in series with the tower's torsional stiffness; two-mass model when
the tower's own torsional inertia is given. Gear play (half-gap δ) is a dead-zone spring,
linearised by its describing function: its stiffness grows with the vibration amplitude
(none inside the gap), so the frequency falls as the amplitude shrinks toward the play.
"""

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import SpecError
from ..judge.analysis import Analysis, Context, Damping, Subsystem, section_damping
from ..judge.excitation import Excitation, OperatingRange
from ..judge.resonance import lines_met, steady_samples
from ..numerics import modal
from ..results import Check, Mode, Rule, ordinal
from ..rules import MarginRule
from ..spec import Spec
from ..units import rpm_to_rad_s
from .given import given_modes

Array = NDArray[np.float64]


def describing_function(amplitude_over_gap: ArrayLike) -> Array:
    """Effective stiffness ratio N/k of a spring with a dead zone ±δ at amplitude A.

    Notes
    -----
    N/k = 1 − (2/π)·[asin(δ/A) + (δ/A)·√(1 − (δ/A)²)] for A > δ, 0 otherwise
    (first-harmonic balance). A/δ = 1.2, 2, 5 → 0.0796, 0.3910, 0.7471.

    References
    ----------
    A. Gelb, W. E. Vander Velde, *Multiple-Input Describing Functions and Nonlinear System
    Design*, McGraw-Hill 1968, ch. 2 (dead zone); DOMAIN.md §3.
    """
    r = np.asarray(amplitude_over_gap, dtype=float)
    inv = np.clip(1.0 / np.maximum(r, 1.0), 0.0, 1.0)
    n = 1.0 - (2.0 / math.pi) * (np.arcsin(inv) + inv * np.sqrt(1.0 - inv**2))
    return np.asarray(np.where(r > 1.0, n, 0.0))


def series(*stiffness: float) -> float:
    """Springs in series: 1/k = Σ 1/kᵢ."""
    return 1.0 / sum(1.0 / k for k in stiffness)


def friction_damping_ratio(moment: float, inertia: float, omega: float, amplitude: float) -> float:
    """Equivalent viscous damping ratio of Coulomb friction at amplitude A.

    Notes
    -----
    Equal energy per cycle: 4·M_f·A = π·c·ω·A² → c = 4M_f/(πωA); ζ = c/(2Jω) =
    2M_f/(π·J·ω²·A). (Den Hartog, *Mechanical Vibrations*, §8.3.)
    """
    return 2.0 * moment / (math.pi * inertia * omega**2 * amplitude)


def gyroscopic_moments(
    polar_inertia: float, omega: float, yaw_rate: float, blades: int, azimuth: ArrayLike
) -> tuple[Array, Array]:
    """Gyroscopic tilt and yaw moments of a rotor yawed at ``yaw_rate`` [rad/s].

    Notes
    -----
    Three or more blades: a constant tilt moment J_p·Ω·Ω_yaw, no yaw moment. Two blades
    (azimuth ψ from the vertical): tilt J_p·Ω·Ω_yaw·(1 + cos 2ψ), yaw J_p·Ω·Ω_yaw·sin 2ψ.
    (Hau ch. 6.8 and 7.4.1; DOMAIN.md §3.)
    """
    psi = np.asarray(azimuth, dtype=float)
    base = polar_inertia * omega * yaw_rate
    if blades >= 3:
        return np.full_like(psi, base), np.zeros_like(psi)
    return base * (1.0 + np.cos(2 * psi)), base * np.sin(2 * psi)


@dataclass(frozen=True)
class YawModel:
    """The yaw system's numbers (SI): inertias, stiffnesses, play."""

    inertia: float  # mean tower-head inertia about the yaw axis
    inertia_variation: float  # ± at 2P for two-bladed rotors
    drive: float  # all drives together, no play
    tower: float | None
    tower_inertia: float | None
    half_gap: float | None
    amplitude: float | None

    def frequencies(self, play_factor: float = 1.0, inertia: float | None = None) -> Array:
        """Natural frequencies [Hz] with the drive stiffness scaled by ``play_factor``."""
        j = self.inertia if inertia is None else inertia
        k_d = self.drive * play_factor
        if k_d <= 0:
            return np.array([0.0])
        if self.tower_inertia is None or self.tower is None:
            k_one = k_d if self.tower is None else series(k_d, self.tower)
            return np.array([math.sqrt(k_one / j) / (2 * math.pi)])
        k = np.array([[self.tower + k_d, -k_d], [-k_d, k_d]])
        m = np.diag([self.tower_inertia, j])
        return modal.solve(k, m).frequency_hz

    def at_amplitude(self, amplitude: float) -> float:
        """First frequency [Hz] when the vibration amplitude through the play is A [rad]."""
        if not self.half_gap:
            return float(self.frequencies()[0])
        return float(self.frequencies(float(describing_function(amplitude / self.half_gap)))[0])

    def critical_amplitude(self, f_target: float) -> float | None:
        """Amplitude [rad] at which the play brings the first frequency down to f_target."""
        if not self.half_gap or f_target >= self.at_amplitude(1e6 * self.half_gap):
            return None
        lo, hi = self.half_gap * (1 + 1e-9), self.half_gap * 1e6
        for _ in range(200):
            mid = math.sqrt(lo * hi)
            if self.at_amplitude(mid) < f_target:
                lo = mid
            else:
                hi = mid
        return math.sqrt(lo * hi)


def model(spec: Spec) -> YawModel:
    """The yaw model of a spec with a drive stiffness."""
    y = spec.yaw
    assert y.drive_stiffness_nm_rad is not None
    j_p = rotor_polar_inertia(spec)
    variation = 0.5 * j_p if spec.rotor.blades == 2 and j_p else 0.0
    if y.inertia_kgm2 is not None:
        j = y.inertia_kgm2
    elif spec.tower_head is not None:
        h = spec.tower_head
        j = h.inertia_yaw_kgm2 + h.mass_kg * h.cm_downwind_m**2
    else:
        raise modal.ModalError("yaw.inertia_kgm2 or tower_head is needed for the yaw model")
    if j <= 0:
        raise SpecError(
            "the yaw model needs the tower head's inertia about the yaw axis: give "
            "tower_head.inertia_yaw_kgm2 (or yaw.inertia_kgm2); with no inertia and the CM on "
            "the tower axis it is zero",
            path="tower_head.inertia_yaw_kgm2",
        )
    if variation >= j:  # a two-bladed rotor's own yaw inertia swings 0 … J_p about J_p/2
        raise SpecError(
            f"the tower head's yaw inertia ({j:.4g} kg·m²) must exceed half the rotor's polar "
            f"inertia ({variation:.4g} kg·m²): a two-bladed rotor's own yaw inertia swings "
            "between 0 and J_p about its mean J_p/2, which the head's inertia includes",
            path=(
                "yaw.inertia_kgm2" if y.inertia_kgm2 is not None else "tower_head.inertia_yaw_kgm2"
            ),
        )
    play = y.play
    half_gap = math.radians(play.half_gap_deg) if play else None
    k_drive = y.drives * y.drive_stiffness_nm_rad
    amplitude = None
    if play is not None:
        if play.amplitude_deg is not None:
            amplitude = math.radians(play.amplitude_deg)
        elif y.yaw_moment_amplitude_nm is not None:
            amplitude = half_gap + y.yaw_moment_amplitude_nm / k_drive  # type: ignore[operator]
    return YawModel(
        j, variation, k_drive, y.tower_torsion_nm_rad, y.tower_inertia_kgm2, half_gap, amplitude
    )


def rotor_polar_inertia(spec: Spec) -> float | None:
    """Rotor inertia about the shaft: given, or blades + hub of the drive-train chain."""
    if spec.yaw.rotor_polar_inertia_kgm2 is not None:
        return spec.yaw.rotor_polar_inertia_kgm2
    chain = spec.drivetrain.chain
    if len(chain) >= 2 and chain[0].name == "blades":
        return chain[0].inertia_kgm2 + chain[1].inertia_kgm2
    return None


def modes(spec: Spec) -> list[Mode]:
    """Yaw modes: ``yaw.1`` (and ``yaw.2``) yawing without play, ``yaw.play.1`` with the
    play at its vibration amplitude, ``yaw.parked.1`` with the brakes applied."""
    y = spec.yaw
    if not y.has_model:
        return given_modes("yaw", y.modes, lambda n: f"{ordinal(int(n))} yaw mode")
    mdl = model(spec)
    free = mdl.frequencies()
    amp = mdl.amplitude or (
        y.yaw_moment_amplitude_nm / mdl.drive if y.yaw_moment_amplitude_nm else None
    )
    out = []
    for k, f in enumerate(free, start=1):
        zeta = _friction_zeta(y.friction_moment_nm, mdl, float(f), amp) if k == 1 else None
        if k == 1 and y.drive_damping_nms_rad and f > 0:  # the drives' dashpot: c/(2Jω)
            viscous = y.drive_damping_nms_rad / (2 * mdl.inertia * 2 * math.pi * float(f))
            zeta = min((zeta or 0.0) + viscous, 0.99)
        out.append(
            Mode(
                f"yaw.{k}",
                "yaw",
                f"{ordinal(k)} yaw mode, yawing, no gear play ({_model_text(mdl)}) (computed)",
                float(f),
                zeta,
                origin="computed",
            )
        )
    if mdl.half_gap and mdl.amplitude:
        f_play = mdl.at_amplitude(mdl.amplitude)
        out.append(
            Mode(
                "yaw.play.1",
                "yaw",
                f"1st yaw mode, yawing with gear play ±{math.degrees(mdl.half_gap):.2g}° "
                f"at {math.degrees(mdl.amplitude):.2g}° amplitude (computed)",
                f_play,
                _friction_zeta(y.friction_moment_nm, mdl, f_play, mdl.amplitude),
                origin="computed",
            )
        )
    if y.brake_moment_nm > 0:
        f0 = float(free[0])
        out.append(
            Mode(
                "yaw.parked.1",
                "yaw",
                "1st yaw mode, parked with the brakes applied (play taken up) (computed)",
                f0,
                _friction_zeta(y.brake_moment_nm + y.friction_moment_nm, mdl, f0, amp),
                origin="computed",
            )
        )
    return out


def _friction_zeta(
    moment: float, mdl: YawModel, f_hz: float, amplitude: float | None
) -> float | None:
    if moment <= 0 or not amplitude or f_hz <= 0:
        return None
    zeta = friction_damping_ratio(moment, mdl.inertia, 2 * math.pi * f_hz, amplitude)
    return min(zeta, 0.99)


def _model_text(mdl: YawModel) -> str:
    if mdl.tower is None:
        return "one mass on the drives"
    if mdl.tower_inertia is None:
        return "one mass on drives and tower torsion in series"
    return "two masses: tower torsion and drives"


def checks(
    spec: Spec, op: OperatingRange, rule: MarginRule, lines: Sequence[Excitation]
) -> list[Check]:
    """yaw.play, yaw.inertia (two blades) and yaw.moments (the moment budget)."""
    if not spec.yaw.has_model:
        return []
    mdl = model(spec)
    out = [_play_check(spec, mdl, op, rule, lines), _moment_budget(spec)]
    if mdl.inertia_variation:
        f_hi = float(mdl.frequencies(inertia=mdl.inertia - mdl.inertia_variation)[0])
        f_lo = float(mdl.frequencies(inertia=mdl.inertia + mdl.inertia_variation)[0])
        out.append(
            Check(
                id="yaw.inertia",
                subsystem="yaw",
                status="info",
                message=(
                    f"two-bladed rotor: the yaw inertia varies {mdl.inertia:,.0f} "
                    f"± {mdl.inertia_variation:,.0f} kg·m² at 2P, so the yaw frequency "
                    f"swings between {f_lo:.3g} and {f_hi:.3g} Hz — a parametric excitation "
                    "whose stability is a Floquet question (Hau 6.8.2, 7.4.2)"
                ),
                rule=Rule("J(ψ) = J̄ ± J_p/2 (two point-mass blades)", "Hau ch. 7.4.2"),
                numbers={
                    "inertia_mean_kgm2": mdl.inertia,
                    "inertia_variation_kgm2": mdl.inertia_variation,
                    "frequency_range_hz": [round(f_lo, 6), round(f_hi, 6)],
                },
            )
        )
    return [c for c in out if c is not None]


def _play_check(
    spec: Spec,
    mdl: YawModel,
    op: OperatingRange,
    rule: MarginRule,
    lines: Sequence[Excitation],
) -> Check | None:
    if not mdl.half_gap:
        return None
    f0 = float(mdl.frequencies()[0])
    speeds = steady_samples(op)
    dominant = [e for e in lines if e.energy == "dominant" and e.acts_on("yaw")]

    def hit(f: float) -> list[str]:
        return lines_met(f, lines, op, rule, "yaw")

    # the play's stiffness grows with the vibration amplitude (no stiffness inside the gap),
    # so the yaw frequency falls as the amplitude shrinks: each dominant line's band is met
    # below the amplitude at which the frequency reaches the band's top, the first line at
    # the largest such amplitude (below the known amplitude, where one is known and clear)
    critical: list[tuple[float, str]] = []
    for e in dominant:
        top = float(np.max(e.frequency_hz(speeds)))
        a = mdl.critical_amplitude(rule.natural_band(top)[1])
        if a is not None and (mdl.amplitude is None or a < mdl.amplitude):
            critical.append((a, e.id))
    first = max(critical) if critical else None
    gap = math.degrees(mdl.half_gap)
    numbers: dict[str, object] = {
        "half_gap_deg": round(gap, 6),
        "frequency_no_play_hz": round(f0, 6),
    }
    if first:
        numbers["critical_amplitude_deg"] = round(math.degrees(first[0]), 6)
    if mdl.amplitude is None:
        status = "warn" if first else "pass"
        text = (
            f"gear play ±{gap:.2g}°: no vibration amplitude known (give play.amplitude_deg "
            "or yaw.yaw_moment_amplitude_nm)"
        )
        if first:
            text += (
                f"; the yaw frequency falls from {f0:.3g} Hz onto {first[1]} once the "
                f"amplitude is below {math.degrees(first[0]):.3g}°"
            )
        return Check("yaw.play", "yaw", status, text, _play_rule(rule), numbers)  # type: ignore[arg-type]
    f_a = mdl.at_amplitude(mdl.amplitude)
    numbers.update(
        {
            "amplitude_deg": round(math.degrees(mdl.amplitude), 6),
            "frequency_with_play_hz": round(f_a, 6),
        }
    )
    without, with_play = hit(f0), hit(f_a)
    band = f"{f_a:.3g}–{f0:.3g} Hz"
    if with_play and not without:
        status, text = (
            "fail",
            (
                f"the gear play is the cause: clear without play ({f0:.3g} Hz), the yaw frequency "
                f"drops to {f_a:.3g} Hz at {math.degrees(mdl.amplitude):.2g}° amplitude (play "
                f"±{gap:.2g}°) and meets {', '.join(with_play)} — the Aeroman worm-gear case "
                "(Hau Fig. 7.18)"
            ),
        )
    elif without:
        status, text = (
            "fail",
            (f"within the margin of {', '.join(without)} even without play (band {band})"),
        )
    else:
        status = "pass"
        text = f"with play ±{gap:.2g}° the yaw frequency spans {band}, clear of the dominant lines"
        if first:
            text += f"; it would meet {first[1]} below {math.degrees(first[0]):.3g}° amplitude"
    return Check("yaw.play", "yaw", status, text, _play_rule(rule), numbers)  # type: ignore[arg-type]


def _play_rule(rule: MarginRule) -> Rule:
    return Rule(
        f"dead-zone describing function N/k; {rule.label}",
        "Hau ch. 7.4.2 (Fig. 7.18); Gelb & Vander Velde 1968, ch. 2",
    )


def _moment_budget(spec: Spec) -> Check:
    """The moments about the yaw axis and the tilt axis, each with its formula and source."""
    y = spec.yaw
    speed = spec.rotor.speed
    omega = float(rpm_to_rad_s(speed.top_rpm))
    j_p = rotor_polar_inertia(spec)
    terms: dict[str, float | None] = {}
    notes = []
    hub = spec.rotor.hub
    aero = y.yaw_moment_amplitude_nm
    terms["aerodynamic_cyclic_nm"] = aero
    notes.append(
        f"cyclic aerodynamic yaw moment at {spec.rotor.blades}P: "
        + (f"{aero:,.0f} N·m (given)" if aero else "not given")
        + (
            " — a teetered hub removes most of it"
            if hub == "teetered"
            else " — strongest for hingeless two-bladed rotors"
            if spec.rotor.blades == 2
            else ""
        )
    )
    if j_p and y.yaw_rate_deg_s:
        psi = np.linspace(0.0, 2 * math.pi, 72, endpoint=False)  # a revolution
        about_tilt, about_yaw = gyroscopic_moments(
            j_p, omega, math.radians(y.yaw_rate_deg_s), spec.rotor.blades, psi
        )
        gyro = float(about_tilt.mean())  # J_p·Ω·Ω_yaw: the tilt moment's mean over a revolution
        terms["gyroscopic_nm"] = gyro
        if spec.rotor.blades >= 3:
            notes.append(f"gyroscopic J_p·Ω·Ω_yaw = {gyro:,.0f} N·m, constant, about the tilt axis")
        else:
            notes.append(
                f"gyroscopic J_p·Ω·Ω_yaw = {gyro:,.0f} N·m: tilt ×(1 + cos 2ψ), yaw ×sin 2ψ (at "
                f"2P; up to {float(np.abs(about_yaw).max()):,.0f} N·m about the yaw axis)"
            )
    if y.rated_torque_nm and y.shaft_tilt_deg:
        tilt = y.rated_torque_nm * math.sin(math.radians(abs(y.shaft_tilt_deg)))
        terms["tilted_shaft_torque_nm"] = tilt
        notes.append(f"tilted shaft: Q·sin(tilt) = {tilt:,.0f} N·m about the yaw axis")
    terms["friction_nm"] = y.friction_moment_nm
    terms["brakes_nm"] = y.brake_moment_nm
    notes.append(
        f"friction while yawing {y.friction_moment_nm:,.0f} N·m; brakes when parked "
        f"{y.brake_moment_nm:,.0f} N·m"
    )
    return Check(
        id="yaw.moments",
        subsystem="yaw",
        status="info",
        message="; ".join(notes),
        rule=Rule("moment budget about the yaw and tilt axes", "Hau ch. 7.4.1"),
        numbers={k: (None if v is None else round(v, 3)) for k, v in terms.items()},
    )


# ---------------------------------------------------------------------------------------
# The subsystem protocol (wtvib.judge.analysis)

NAME = "yaw"


def default_damping(spec: Spec) -> Damping:
    return section_damping(spec.yaw, "yaw")


def build_modes(spec: Spec, built: Mapping[str, list[Mode]]) -> list[Mode]:
    return modes(spec)


def analyse(spec: Spec, ctx: Context) -> Analysis:
    """``yaw.play``, ``yaw.inertia`` and ``yaw.moments`` after the yaw resonance checks."""
    return Analysis(checks=tuple(checks(spec, ctx.op, ctx.rule, ctx.lines)))


def warnings(spec: Spec, modes: Sequence[Mode]) -> list[str]:
    """The yaw model's suspicious inputs: a tower head without a yaw inertia, whose yaw
    frequency can be off by a factor.

    The rotor alone has the inertia J_p/2 about a diameter (a planar body: J_x = J_y + J_z,
    J_y = J_z), a lower bound of the head's yaw inertia; the yaw frequency scales with
    1/√J.
    """
    head = spec.tower_head
    first = next((m for m in modes if m.id == "yaw.1"), None)
    if (
        first is None
        or head is None
        or spec.yaw.inertia_kgm2 is not None
        or "inertia_yaw_kgm2" in head.model_fields_set
    ):
        return []
    used = head.inertia_yaw_kgm2 + head.mass_kg * head.cm_downwind_m**2
    j_p = rotor_polar_inertia(spec)
    text = (
        f"tower_head.inertia_yaw_kgm2: not given, so the yaw model uses {used:.3g} kg·m² (the "
        f"head's mass at its CM offset only) and yaw.1 comes out at {first.frequency_hz:.3g} Hz"
    )
    if j_p and j_p / 2 > used:
        estimate = first.frequency_hz * math.sqrt(max(used, 1e-9) / (used + j_p / 2))
        text += (
            f"; the rotor alone adds J_p/2 = {j_p / 2:.3g} kg·m², which would put it near "
            f"{estimate:.3g} Hz"
        )
    return [text + " — give the head's yaw inertia"]


SUBSYSTEM = Subsystem(
    NAME,
    build_modes,
    default_damping,
    analyse,
    part="yaw",
    warnings=warnings,
    diagram="campbell-yaw",
    title="yaw system",
)
