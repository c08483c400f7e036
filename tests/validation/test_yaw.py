"""Yaw system: describing function, one-mass frequency, gyroscopics, friction, stories.

Describing function of a dead-zone spring: N/k at A/δ = 1.2, 2, 5 is 0.0796, 0.3910,
0.7471 (DOMAIN.md §3; Gelb & Vander Velde 1968, ch. 2), checked here also against a
numerical Fourier integration. Gyroscopic moments against a point-mass rotor whose
angular momentum is differentiated numerically in the test.
"""

import math

import numpy as np
import pytest

from tests.conftest import TURBINES
from wtvib import audit, importers, spec
from wtvib.subsystems import yaw


@pytest.mark.parametrize(("ratio", "expected"), [(1.2, 0.0796), (2.0, 0.3910), (5.0, 0.7471)])
def test_describing_function_values(ratio, expected):
    assert float(yaw.describing_function(ratio)) == pytest.approx(expected, abs=1e-4)


@pytest.mark.parametrize("ratio", [1.05, 1.2, 2.0, 3.3, 5.0, 20.0])
def test_describing_function_against_fourier_integration(ratio):
    # first Fourier coefficient of the dead-zone force f(x) = k·sign(x)·max(|x| − δ, 0)
    # for x = A·sin θ: N = (1/(πA))·∫₀^{2π} f(A sin θ)·sin θ dθ
    delta, a = 1.0, ratio
    theta = np.linspace(0, 2 * np.pi, 200_001)
    x = a * np.sin(theta)
    force = np.sign(x) * np.maximum(np.abs(x) - delta, 0.0)
    numeric = np.trapezoid(force * np.sin(theta), theta) / (np.pi * a)
    assert float(yaw.describing_function(ratio)) == pytest.approx(numeric, abs=1e-6)


def test_no_play_below_the_gap():
    assert float(yaw.describing_function(0.8)) == 0.0


def test_series_stiffness_and_one_mass_frequency():
    # two drives of 2e8 in parallel (4e8) in series with a tower of 4e8 → 2e8 N·m/rad;
    # J = 5e5 kg·m²: f = √(2e8/5e5)/2π = 20/2π = 3.1831 Hz
    assert yaw.series(4e8, 4e8) == pytest.approx(2e8)
    m = yaw.YawModel(5e5, 0.0, 4e8, 4e8, None, None, None)
    assert m.frequencies()[0] == pytest.approx(20 / (2 * math.pi), rel=1e-12)


def test_play_lowers_the_frequency_with_amplitude():
    m = yaw.YawModel(5e5, 0.0, 4e8, None, None, math.radians(0.5), None)
    f0 = m.frequencies()[0]
    # at A = 2δ the drive acts with 0.3910 of its stiffness
    assert m.at_amplitude(math.radians(1.0)) == pytest.approx(f0 * math.sqrt(0.3910), rel=1e-3)
    target = 0.8 * f0
    a = m.critical_amplitude(target)
    assert a is not None and m.at_amplitude(a) == pytest.approx(target, rel=1e-6)


def test_friction_equivalent_damping_dissipates_the_friction_energy():
    # energy per cycle: viscous π·c·ω·A² must equal Coulomb 4·M_f·A
    moment, inertia, omega, amp = 500.0, 2000.0, 20.0, 0.01
    zeta = yaw.friction_damping_ratio(moment, inertia, omega, amp)
    c = 2 * zeta * inertia * omega
    assert math.pi * c * omega * amp**2 == pytest.approx(4 * moment * amp)


def point_mass_moments(blades: int, psi: float, spin: float, yaw_rate: float) -> np.ndarray:
    """Moment on a rotor of point masses (m = 1 at r = 1) yawed at a constant rate:
    M = dH/dt in the inertial frame, from H = I(ψ)·ω in the yawing nacelle frame
    (x shaft, y lateral, z vertical; ψ from the vertical), by a central difference."""

    def h(psi_: float) -> np.ndarray:
        inertia = np.zeros((3, 3))
        for b in range(blades):
            ang = psi_ + 2 * np.pi * b / blades
            r = np.array([0.0, -math.sin(ang), math.cos(ang)])
            inertia += np.dot(r, r) * np.eye(3) - np.outer(r, r)
        return inertia @ np.array([spin, 0.0, yaw_rate])

    dt = 1e-6
    dh = (h(psi + spin * dt) - h(psi - spin * dt)) / (2 * dt)
    return dh + np.cross([0.0, 0.0, yaw_rate], h(psi))


@pytest.mark.parametrize("blades", [2, 3])
@pytest.mark.parametrize("psi", [0.0, 0.4, 1.1, 2.0])
def test_gyroscopic_moments_against_a_point_mass_rotor(blades, psi):
    spin, yaw_rate = 2.0, 0.1
    m = point_mass_moments(blades, psi, spin, yaw_rate)
    j_p = float(blades)  # point masses 1 kg at 1 m
    tilt, yaw_moment = yaw.gyroscopic_moments(j_p, spin, yaw_rate, blades, psi)
    assert m[1] == pytest.approx(float(tilt), rel=1e-6, abs=1e-9)  # about the tilt axis
    assert m[2] == pytest.approx(float(yaw_moment), rel=1e-6, abs=1e-9)  # about the yaw axis


def test_aeroman_play_is_the_cause_and_the_retrofit_passes():
    # Hau Fig. 7.18: clear without play; the worn worm gear's play drops the frequency onto
    # the rotor's excitation; the active yaw drive with damping cured it (ch. 7.4.2)
    r = audit.run(spec.load(TURBINES / "aeroman.yaml"))
    play = next(c for c in r.checks if c.id == "yaw.play")
    assert play.status == "fail" and "play is the cause" in play.message
    assert play.numbers["frequency_no_play_hz"] > play.numbers["frequency_with_play_hz"]
    fixed = audit.run(spec.load(TURBINES / "aeroman-retrofit.yaml"))
    assert all(c.status in ("pass", "info") for c in fixed.checks if c.subsystem == "yaw")


def _dead_zone(r: float) -> float:
    """Gelb & Vander Velde's dead-zone describing function N/k at A/δ = r (> 1)."""
    x = 1 / r
    return 1 - (2 / math.pi) * (math.asin(x) + x * math.sqrt(1 - x * x))


def test_play_meets_the_first_line_as_the_amplitude_shrinks(write_spec):
    """The play's stiffness grows with the vibration amplitude, so the yaw frequency falls
    as the amplitude shrinks toward the gap. Aeroman (2.6 Hz without play, ±0.5° play, fixed
    56 rpm, 10 % band): the first dominant line met is 2P, whose band top 1.1·2·56/60 Hz the
    frequency reaches at A with f₀·√N(A/δ) = 2.0533 Hz — 1.666° by hand (1P's band is met
    only below 0.68°). Without a known amplitude the check warns with it; at a known 3° the
    frequency is clear and the check says below which amplitude 2P would be met."""
    from scipy.optimize import brentq

    text = (TURBINES / "aeroman.yaml").read_text()
    no_amplitude = "\n".join(ln for ln in text.splitlines() if "yaw_moment_amplitude_nm" not in ln)
    play = next(
        c for c in audit.run(spec.load(write_spec(no_amplitude))).checks if c.id == "yaw.play"
    )
    f0 = play.numbers["frequency_no_play_hz"]
    target = 1.1 * 2 * 56 / 60
    expected = 0.5 * brentq(lambda r: _dead_zone(r) - (target / f0) ** 2, 1 + 1e-9, 1e6)
    assert play.status == "warn" and "onto 2P once the amplitude is below 1.67°" in play.message
    assert play.numbers["critical_amplitude_deg"] == pytest.approx(expected, rel=1e-5)
    known = no_amplitude.replace(
        "    half_gap_deg:",
        "    amplitude_deg: {value: 3.0, provenance: representative}\n    half_gap_deg:",
    )
    play = next(
        c
        for c in audit.run(spec.load(write_spec(known, name="k.yaml"))).checks
        if c.id == "yaw.play"
    )
    assert play.numbers["frequency_with_play_hz"] == pytest.approx(
        f0 * math.sqrt(_dead_zone(6.0)), rel=1e-6
    )
    assert play.status == "pass" and "it would meet 2P below 1.67° amplitude" in play.message


def test_nrel5mw_yaw_frequency_from_the_yaw_spring(shared):
    # ServoDyn YawSpr 9.02832e9 N·m/rad (DOMAIN.md §5) with the tower head's yaw inertia
    # assembled from the ElastoDyn deck (NacYIner, rotor about a diameter, hub and blade
    # masses at the overhang): f = √(k/J)/2π
    s = importers.load(shared / "reference/NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat")
    assert s.yaw.drive_stiffness_nm_rad == 9.02832e9
    h = s.tower_head
    j = h.inertia_yaw_kgm2 + h.mass_kg * h.cm_downwind_m**2
    f = next(m for m in audit.run(s).modes if m.id == "yaw.1").frequency_hz
    assert f == pytest.approx(math.sqrt(9.02832e9 / j) / (2 * math.pi), rel=1e-9)
    assert 2.5 < f < 3.5


def test_two_mass_yaw_model_against_its_characteristic_equation():
    """Head J_h on the drive k_d, the drive on the tower's torsional inertia J_t and spring
    k_t to the ground (Hau Fig. 7.17's two-mass model): ω² are the roots of
    J_tJ_h·ω⁴ − (J_h(k_t + k_d) + J_t·k_d)·ω² + k_t·k_d = 0 (by hand, J_h = 2e6, J_t = 5e5,
    k_d = 4e8, k_t = 1.2e9)."""
    jh, jt, kd, kt = 2.0e6, 5.0e5, 4.0e8, 1.2e9
    a, b, c = jt * jh, -(jh * (kt + kd) + jt * kd), kt * kd
    w2 = sorted(
        (
            (-b - math.sqrt(b * b - 4 * a * c)) / (2 * a),
            (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a),
        )
    )
    m = yaw.YawModel(jh, 0.0, kd, kt, jt, None, None)
    assert list(m.frequencies()) == pytest.approx(
        [math.sqrt(x) / (2 * math.pi) for x in w2], rel=1e-10
    )
