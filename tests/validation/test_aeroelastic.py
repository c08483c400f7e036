"""Blade aeroelastic stability against closed forms and the textbook typical section.

The typical section of Hodges & Pierce, *Introduction to Structural Dynamics and
Aeroelasticity* (2nd ed., §5.3–5.5): a = −1/5, x_θ = 1/10, μ = 20, r² = 6/25, σ = 2/5.
Speeds are U/(bω_θ).
"""

import math

import numpy as np
import pytest

from wtvib.aero import aeroelastic as ae
from wtvib.aero import stall

from .. import oracles

TEXTBOOK = {"a": -0.2, "x_theta": 0.1, "mu": 20.0, "r2": 6 / 25, "sigma": 0.4}


def section(**change: float) -> ae.Section:
    p = {**TEXTBOOK, **change}
    # the textbook section: b = 1, ω_θ = 1, ρ = 1 (speeds come out as U/(bω_θ)); m = μπ
    m = p["mu"] * math.pi
    return ae.Section(1.0, p["a"], p["x_theta"], m, p["r2"] * m, p["sigma"], 1.0, 1.0)


def test_typical_section_divergence_closed_form() -> None:
    # q_D = k_θ/(e·c·C_Lα) (DOMAIN.md §3) in the textbook's units: with k_θ = μπ r² (b = ρ =
    # ω_θ = 1), e·c = ½ + a, c = 2 and C_Lα = 2π, U_D = √(2 q_D) = √(μ r²/(½ + a)) = √8.
    s = section()
    assert ae.speed_of(ae.divergence_pressure(s), 1.0) == pytest.approx(math.sqrt(8), rel=1e-12)
    # the same instability as the real root of the steady-flow eigenproblem crossing zero
    sweep = ae.pk_sweep(section(x_theta=-0.1), np.linspace(0.01, 3.0, 150), steady=True)
    assert sweep.divergence_speed == pytest.approx(math.sqrt(8), rel=1e-6)


def test_the_charts_divergence_limit_is_the_sections_stiffness_at_its_divergence_speed() -> None:
    """The chart's divergence limit at air speed U is the stiffness q·e·c·C_Lα that
    diverges at U (q = ½ρU²). A section of 1.6 m chord (b = 0.8), its elastic axis 0.2b ahead
    of mid-chord (e = 0.3b = 0.24 m behind the aerodynamic centre), C_Lα = 2π, ρ = 1.225,
    k_θ = Iω_θ² = 10·40² = 16,000 N·m/rad per m (by hand): at U_D = √(2k_θ/(ρ·e·c·C_Lα))
    the limit is k_θ, at 2U_D four times it; the blade's own point at x_θ/2 = 5 % chord."""
    s = ae.Section(
        0.8, -0.2, 0.1, 200.0, 10.0, 5.0, 40.0, air_density=1.225, lift_slope=2 * math.pi
    )
    u_d = math.sqrt(2 * 16000 / (1.225 * 0.24 * 1.6 * 2 * math.pi))
    for factor in (1.0, 2.0):
        chart = ae.stability_chart(s, factor * u_d, points=3)
        assert chart.divergence_k_theta == pytest.approx(factor**2 * 16000, rel=1e-12)
        assert (chart.blade_offset_chord, chart.blade_k_theta) == pytest.approx((0.05, 16000))


def test_no_divergence_with_elastic_axis_ahead_of_the_aerodynamic_centre() -> None:
    # a = −0.6: EA at 0.2 c, ahead of the quarter chord; lift twists the nose down
    assert ae.divergence_pressure(section(a=-0.6)) == math.inf


def test_cantilever_divergence_fe_matches_closed_form() -> None:
    # uniform cantilever, uniform pressure: q_D = π²GJ/(4·e·c·C_Lα·l²) (DOMAIN.md §3)
    gj, arm, length = 2.0e6, 0.35, 12.0
    exact = oracles.cantilever_divergence_closed_form(gj, arm, length)
    fe = ae.cantilever_divergence(
        np.array([0.0, length]), np.full(2, gj), np.full(2, arm), np.ones(2), elements=60
    )
    # linear torsion elements converge from above as O(h²): 60 elements → ~0.01 %
    assert fe == pytest.approx(exact, rel=2e-4)
    assert fe >= exact


def test_rotating_pressure_and_propeller_moment_raise_the_cantilever_divergence() -> None:
    gj, arm, length = 2.0e6, 0.35, 12.0
    x = np.linspace(0, length, 5)
    uniform = ae.cantilever_divergence(x, np.full(5, gj), np.full(5, arm), np.ones(5))
    # on a rotor the local pressure grows as (r/R)²: less load near the root, higher q_tip
    rotor = ae.cantilever_divergence(x, np.full(5, gj), np.full(5, arm), (x / length) ** 2)
    spring = ae.cantilever_divergence(
        x, np.full(5, gj), np.full(5, arm), (x / length) ** 2, np.full(5, 5.0e4)
    )
    assert uniform < rotor < spring


def test_flutter_pk_and_k_methods_agree_on_the_textbook_section() -> None:
    s = section()
    pk = ae.flutter(s, 3.0)
    k = ae.k_method(s, np.geomspace(5.0, 0.05, 300))
    # both are exact where the damping vanishes: they must agree to solver precision
    assert pk.speed == pytest.approx(k.speed, rel=1e-6)
    assert pk.omega == pytest.approx(k.omega, rel=1e-6)
    # Hodges & Pierce Figs. 5.19/5.20 (p-k, Theodorsen) show flutter near U/(bω_θ) ≈ 2.2 at
    # ω/ω_θ ≈ 0.65: values read off plotted curves, not tabulated — hence the loose 3 % band;
    # the exact check is the p-k/k agreement above (both exact at zero damping)
    assert pk.speed == pytest.approx(2.17, rel=0.03)
    assert pk.omega == pytest.approx(0.65, rel=0.03)
    # and below divergence, as the textbook stresses for this section
    assert pk.speed < math.sqrt(8)


def test_the_textbook_sections_flutter_is_the_same_in_si_units() -> None:
    """Dimensional analysis: the flutter speed is U_F = (U_F/bω_θ)·b·ω_θ and its frequency
    (ω/ω_θ)·ω_θ for a section with the same a, x_θ, μ = m/(πρb²), r² and σ in any units —
    here b = 0.8 m, ω_θ = 40 rad/s, ρ = 1.225 kg/m³ against the textbook's b = ω_θ = ρ = 1."""
    a, xt, mu, r2, sig = TEXTBOOK.values()
    b, w_theta, rho = 0.8, 40.0, 1.225
    mass = mu * math.pi * rho * b**2
    si = ae.Section(b, a, xt, mass, r2 * mass * b**2, sig * w_theta, w_theta, air_density=rho)
    unit = ae.flutter(section(), 3.0)
    scaled = ae.flutter(si, 3.0 * b * w_theta)
    assert scaled.speed == pytest.approx(unit.speed * b * w_theta, rel=1e-6)
    assert scaled.omega == pytest.approx(unit.omega * w_theta, rel=1e-6)


def test_theodorsens_forces_on_a_section_pitching_about_its_three_quarter_chord() -> None:
    """Pitching about the ¾-chord point (a = ½) the downwash there is U·θ alone, so
    Theodorsen's forces per unit pitch (H&P eq. 5.310) reduce to
    L = πρb²(U·θ̇ − b/2·θ̈) + ρU²b·C_Lα·C(k)·θ and
    M = −πρb⁴(1/8 + 1/4)·θ̈ + ρU²b²·C_Lα·C(k)·θ, θ̇ = iω, θ̈ = −ω² — written out here at
    b = 0.8 m, U = 30 m/s, k = 0.3, for the thin aerofoil's 2π and a measured 5.7 per radian
    (the circulatory lift scaled to it); as k → 0 the forces are the steady model's."""
    b, rho, u, k = 0.8, 1.225, 30.0, 0.3
    w = k * u / b
    for slope in (2 * math.pi, 5.7):
        s = ae.Section(b, 0.5, 0.1, 200.0, 10.0, 5.0, 40.0, air_density=rho, lift_slope=slope)
        c = ae.theodorsen(k) * slope / (2 * math.pi)
        lift = math.pi * rho * b**2 * (u * 1j * w + b / 2 * w**2) + 2 * math.pi * rho * u**2 * b * c
        moment = math.pi * rho * b**4 * (1 / 8 + 1 / 4) * w**2 + 2 * math.pi * rho * u**2 * b**2 * c
        got = ae.aero_matrix(s, k, u)[:, 1]
        assert complex(got[0]) == pytest.approx(-lift, rel=1e-12)
        assert complex(got[1]) == pytest.approx(moment, rel=1e-12)
        steady = ae.aero_matrix(s, 0.0, u, steady=True)
        assert ae.aero_matrix(s, 1e-9, u) == pytest.approx(steady, rel=1e-6, abs=1e-3)
        assert complex(steady[0, 1]) == pytest.approx(-rho * u**2 * b * slope)


def test_steady_flow_coalescence_matches_the_analytic_root() -> None:
    # Steady-flow model: det(K − A(U) − λM) = 0 is a quadratic in λ = ω²; flutter where its
    # discriminant A1² − 4·A2·A0 first vanishes (frequency coalescence), H&P §5.3.3.
    a, xt, mu, r2, sig = TEXTBOOK.values()
    m = mu * math.pi
    c = 2 * math.pi * (0.5 + a)

    def disc(u2: float) -> float:
        a2 = m * m * (r2 - xt * xt)
        a1 = -(m * m * sig * sig * r2 + m * (m * r2 - c * u2)) + 2 * math.pi * m * xt * u2
        a0 = m * sig * sig * (m * r2 - c * u2)
        return a1 * a1 - 4 * a2 * a0

    # the discriminant is quadratic in U²: fit it exactly from three points
    pts = np.array([0.0, 1.0, 2.0])
    coeff = np.polyfit(pts, [disc(p) for p in pts], 2)
    u2 = min(r.real for r in np.roots(coeff) if abs(r.imag) < 1e-12 and r.real > 0)
    sweep = ae.pk_sweep(section(), np.linspace(0.01, 3.0, 300), steady=True)
    assert sweep.speed == pytest.approx(math.sqrt(u2), rel=1e-3)


@pytest.mark.parametrize("x_theta", [-0.1, -0.05, 0.0])
def test_no_steady_flow_flutter_with_the_centre_of_mass_at_or_ahead_of_the_axis(
    x_theta: float,
) -> None:
    # steady flow: without inertial coupling the aerodynamic coupling alone cannot merge the
    # frequencies (H&P §5.3.3); only divergence remains
    sweep = ae.pk_sweep(section(x_theta=x_theta), np.linspace(0.01, 2.8, 150), steady=True)
    assert sweep.speed == math.inf


@pytest.mark.parametrize("x_theta", [-0.1, -0.05])
def test_no_unsteady_flutter_below_divergence_with_the_centre_of_mass_ahead(
    x_theta: float,
) -> None:
    assert ae.flutter(section(x_theta=x_theta), 2.8).speed == math.inf


def test_flutter_moves_with_the_centre_of_mass() -> None:
    # mass balancing (centre of mass forward) raises the flutter speed
    speeds = [ae.flutter(section(x_theta=x), 3.0).speed for x in (0.2, 0.1, 0.05)]
    assert speeds[0] < speeds[1] < speeds[2]


def test_theodorsen_function_limits() -> None:
    # C(0) = 1; C(k → ∞) → ½; C(1) = 0.5394 − 0.1003i (Bisplinghoff, Ashley & Halfman table)
    assert ae.theodorsen(0.0) == 1
    assert ae.theodorsen(200.0).real == pytest.approx(0.5, abs=1e-3)
    c1 = ae.theodorsen(1.0)
    assert c1.real == pytest.approx(0.5394, abs=2e-4)
    assert c1.imag == pytest.approx(-0.1003, abs=2e-4)


def test_aerodynamic_damping_matches_a_finite_difference_of_the_section_forces() -> None:
    # Quasi-steady section forces for a velocity ẋ of the section along direction ψ measured
    # from the relative wind W: the flow changes in size and angle; the damping is −dF_ψ/dẋ.
    # Polar: a smooth post-stall curve with C_L′ < 0 (the unstable case).
    rho, chord, w0, alpha0 = 1.225, 2.0, 40.0, math.radians(16)

    def polar(alpha: float) -> tuple[float, float]:
        return 1.2 - 2.0 * (alpha - alpha0) + 0.3 * (alpha - alpha0) ** 2, 0.2 + 1.1 * (
            alpha - alpha0
        )

    def force_along(psi: float, xdot: float) -> float:
        # axes: e1 along the relative wind W, e2 the lift direction. The section moves with
        # ẋ(cos ψ, sin ψ); the flow it sees is (W − ẋ cos ψ, −ẋ sin ψ), turned by δ, so the
        # angle of attack becomes α0 + δ; drag acts along that flow, lift normal to it.
        u, v = w0 - xdot * math.cos(psi), -xdot * math.sin(psi)
        delta = math.atan2(v, u)
        cl, cd = polar(alpha0 + delta)
        q = 0.5 * rho * chord * (u * u + v * v)
        drag, lift = q * cd, q * cl
        f1 = drag * math.cos(delta) - lift * math.sin(delta)
        f2 = drag * math.sin(delta) + lift * math.cos(delta)
        return f1 * math.cos(psi) + f2 * math.sin(psi)

    cl0, cd0 = polar(alpha0)
    for psi in np.radians([0.0, 20.0, 45.0, 80.0, 90.0, 120.0]):
        h = 1e-4
        fd = -(force_along(psi, h) - force_along(psi, -h)) / (2 * h)
        formula = stall.aero_damping_coefficient(rho, chord, w0, psi, cl0, cd0, -2.0, 1.1)
        assert fd == pytest.approx(formula, rel=1e-6, abs=1e-6), math.degrees(psi)


def test_stability_chart_flutter_limit_is_where_the_section_flutters_at_that_speed() -> None:
    # Each point of the chart's flutter limit (Hau Fig. 7.6), fed back into the p-k method
    # as the section's torsional stiffness, must flutter at the chart's speed
    s = section()
    chart = ae.stability_chart(s, 2.0)
    for i in (5, 8, 16, 24):
        k_theta = chart.flutter_k_theta[i]
        trial = ae.Section(
            **{
                **s.__dict__,
                "x_theta": 2 * chart.offset_chord[i],
                "omega_theta": math.sqrt(k_theta / s.inertia_kgm),
            }
        )
        assert ae.flutter(trial, 4.0).speed == pytest.approx(2.0, rel=0.01)
    # divergence limit: q·e·c·C_Lα at q = ½ρU² (ρ = b = 1: e = ½ + a, c = 2)
    assert chart.divergence_k_theta == pytest.approx(0.5 * 4.0 * 0.3 * 2 * 2 * math.pi)
    # centre of mass ahead of the elastic axis: no flutter limit
    assert np.isnan(chart.flutter_k_theta[0])


@pytest.mark.parametrize("a", [-0.4, 0.0, 0.3])
def test_still_air_leaves_the_flat_plates_added_mass(a: float) -> None:
    """In still air (U → 0, k → ∞) Theodorsen's forces are the apparent mass alone: a flat
    plate of chord 2b moves ρπb² of water-like fluid per metre in plunge and turns ρπb⁴·(1/8
    + a²) about an axis a semichords aft of mid-chord (potential flow; Newman, *Marine
    Hydrodynamics*, §4.13; H&P eq. 5.310 with U = 0), with the plunge–pitch coupling
    −ρπb³·a."""
    b, rho, w = 1.5, 1.225, 4.0
    s = ae.Section(
        semichord_m=b, a=a, x_theta=0.0, mass_kg_m=100.0, inertia_kgm=50.0,
        omega_h=2.0, omega_theta=8.0, air_density=rho,
    )  # fmt: skip
    speed = 1e-7
    matrix = ae.aero_matrix(s, w * b / speed, speed)
    expected = (
        rho * math.pi * b**2 * w**2 * np.array([[1.0, -b * a], [-b * a, b**2 * (1 / 8 + a**2)]])
    )
    np.testing.assert_allclose(matrix.real, expected, rtol=1e-5, atol=1e-9)


def test_the_speed_margin_bands_warn_between_one_and_one_plus_margin() -> None:
    """A divergence or flutter speed below the highest section speed fails, within the
    margin above it warns, beyond it passes (the bands' edges included upwards)."""
    assert [ae._status(r, 0.2) for r in (0.95, 1.0, 1.1, 1.2, 1.25)] == [
        "fail", "warn", "warn", "pass", "pass",
    ]  # fmt: skip


def test_the_figures_station_is_the_one_nearest_to_flutter() -> None:
    """A mutation survivor (`aeroelastic` 679, tests/MUTATION.md): of several sections, the V-g
    curves and the stability chart are drawn for the one whose flutter speed is the least multiple
    of its section speed — the one the flutter check names."""
    from tests.conftest import TURBINES
    from wtvib import audit
    from wtvib import spec as spec_mod

    base = spec_mod.load(TURBINES / "euros-44m.yaml")
    blade_ae = base.blade.aeroelastic
    assert blade_ae is not None and len(blade_ae.sections) == 1
    one = blade_ae.sections[0]
    sections = [
        one.model_copy(update={"radius_fraction": f, "centre_of_mass_chord": cm})
        for f, cm in ((0.5, 0.33), (0.75, 0.36), (0.9, 0.42))
    ]
    s = base.model_copy(
        update={
            "blade": base.blade.model_copy(
                update={"aeroelastic": blade_ae.model_copy(update={"sections": sections})}
            )
        }
    )
    report = audit.run(s)
    res = report.result("aeroelastic", ae.AeroelasticResults)
    assert res is not None and len(res.stations) == 3
    ratios = [r.flutter.speed / r.section_speed for r in res.stations]
    assert len(set(np.round(ratios, 6))) == 3  # the three differ
    assert res.worst is res.stations[int(np.argmin(ratios))]
    flutter = next(c for c in report.checks if c.id == "blade.flutter")
    assert f"r = {res.worst.radius_m:.3g} m" in flutter.message
