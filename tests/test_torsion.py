"""The blades' steady twist under their aerodynamic moment (wtvib.aero.torsion).

Expected values and where they come from: the twist of a cantilever in torsion under a
moment per unit length m(x), θ(x) = ∫₀ˣ T/GJ, T(x) = ∫ₓᴸ m (Hodges & Pierce, *Introduction to
Structural Dynamics and Aeroelasticity*, 2nd ed., §3.4): for a uniform m on a uniform blade
θ = m·(L·x − x²/2)/GJ — the trapezoidal rules are exact for it (T linear), so the
comparison is held to rounding (a few ε times the number of stations); the root's spring
adds T(0)/k_p. The BEM's steady twist is the fixed point θ = F·m(α(θ)): held by its own
residual at the converged solution, against the tolerance the Newton rounds stop at.
"""

import math

import numpy as np
import pytest

from wtvib.aero import bem, torsion
from wtvib.spec import load as load_spec

EPS = float(np.finfo(float).eps)


def test_a_uniform_moment_twists_a_uniform_blade_as_the_closed_form():
    root, tip = 1.5, 40.0
    radius = np.concatenate([[2.0, 2.7], np.linspace(4.0, tip, 23)])  # uneven spacing
    gj, m = 3.0e7, -1.2e3  # [N·m²], [N·m/m] nose-down
    f = torsion.flexibility(radius, root, np.full_like(radius, gj), gj, None)
    theta = f @ np.full_like(radius, m)
    # the moment acts from the first station outboard (nothing inboard of it)
    x, first = radius - root, radius[0] - root
    span = tip - root
    inner = m * (span - first) * np.minimum(x, first) / gj  # T constant root … first station
    outer = np.where(
        x > first,
        m * ((span * x - x**2 / 2) - (span * first - first**2 / 2)) / gj,
        0.0,
    )
    expected = inner + outer
    scale = abs(m) * span**2 / gj
    np.testing.assert_allclose(theta, expected, rtol=0, atol=100 * len(radius) * EPS * scale)
    # the pitch drive's spring turns the whole blade by the root's moment over it
    k = 5.0e6
    sprung = torsion.flexibility(radius, root, np.full_like(radius, gj), gj, k)
    root_moment = m * (tip - radius[0])
    np.testing.assert_allclose(
        sprung @ np.full_like(radius, m) - theta,
        root_moment / k,
        rtol=1e-12,
    )


def test_the_moment_is_the_quarter_chord_moment_plus_the_normal_force_on_its_arm():
    t = torsion.Torsion(np.zeros((2, 2)), np.array([0.0, 0.3]), np.zeros((2, 4)))
    chord, w = np.array([2.0, 1.5]), np.array([[40.0, 60.0]])
    alpha = np.radians(np.array([[5.0, 8.0]]))
    cl, cd, cm = np.array([[0.9, 1.1]]), np.array([[0.01, 0.02]]), np.array([[-0.1, -0.08]])
    m = torsion.moment(t, 1.225, chord, w, alpha, cl, cd, cm)
    q = 0.5 * 1.225 * w**2 * chord
    normal = cl * np.cos(alpha) + cd * np.sin(alpha)
    np.testing.assert_allclose(m, q * (chord * cm + np.array([0.0, 0.3]) * normal), rtol=1e-15)
    assert m[0, 0] < 0 < m[0, 1]  # C_M alone nose-down; a long arm behind it nose-up


ROTOR = """\
wtvib: 1
turbine: {{name: Twisting rotor, rotor_diameter_m: 80, rated_power_kw: 2000}}
rotor: {{blades: 3, orientation: upwind, hub: rigid, speed: {{min_rpm: 8, max_rpm: 17}}}}
tower: {{modes: {{fa1: 0.4}}}}
blade:
  structure:
    hub_radius_m: 2.0
    span_m: [0, 10, 20, 30, 38]
    mass_per_length_kg_m: [600, 350, 200, 120, 60]
    ei_flap_nm2: [8.0e9, 2.0e9, 5.0e8, 1.0e8, 2.0e7]
    ei_edge_nm2: [9.0e9, 3.0e9, 9.0e8, 2.0e8, 4.0e7]
    gj_nm2: [{gj}, {gj}, {gj}, {gj}, {gj}]
    torsional_inertia_kgm: [60, 30, 15, 8, 3]
aerodynamics:
  stations:
    radius_m: [3, 10, 20, 30, 38, 40]
    chord_m: [2.5, 3.0, 2.4, 1.8, 1.2, 0.8]
    twist_deg: [14, 8, 4, 1.5, 0.2, 0]
    airfoil: [foil, foil, foil, foil, foil, foil]
    shear_centre_chord: [{sc}, {sc}, {sc}, {sc}, {sc}, {sc}]
  airfoils:
    foil: {{alpha_deg: [-180, -20, -10, 0, 10, 14, 20, 45, 90, 180],
           cl: [0, -0.8, -0.9, 0.3, 1.3, 1.45, 1.1, 1.0, 0.0, 0],
           cd: [0.02, 0.3, 0.02, 0.008, 0.015, 0.05, 0.3, 1.0, 1.6, 0.02]{cm}}}
  control: {{cut_in_wind_m_s: 4, cut_out_wind_m_s: 25}}
"""


CM = ",\n           cm: [0, 0.1, 0.0, -0.08, -0.1, -0.11, -0.15, -0.3, -0.45, 0]"


def _text(gj: float = 2.0e7, sc: float = 0.3, cm: str = CM) -> str:
    return ROTOR.format(gj=gj, sc=sc, cm=cm)


def _rotor(write_spec, gj: float = 2.0e7, sc: float = 0.3) -> bem.Rotor:  # type: ignore[no-untyped-def]
    return bem.rotor(load_spec(write_spec(_text(gj, sc))))


def test_the_steady_twist_is_the_fixed_point_of_its_moment(write_spec):
    r = _rotor(write_spec)
    assert r.torsion is not None
    wind = np.array([6.0, 10.0, 14.0])
    omega = np.array([1.1, 1.6, 1.7])
    sol = bem.solve(r, wind, omega, np.radians([0.0, 0.0, 6.0]))
    assert sol.elastic_twist is not None and sol.twist_unsettled is not None
    assert not sol.twist_unsettled.any()
    residual = sol.elastic_twist - r.moment(sol.w, sol.alpha) @ r.torsion.flexibility.T
    # the last Newton step was below TORSION_TOLERANCE; the step left is smaller still
    assert np.max(np.abs(residual)) < 10 * bem.TORSION_TOLERANCE
    assert np.all(sol.elastic_twist[:, -1] < 0)  # C_M's nose-down wins over a short arm
    # the angle of attack grows by the twist: the rigid rotor at the twisted twist agrees
    rigid = bem._solve(r, wind, omega, np.radians([0.0, 0.0, 6.0]), elastic=sol.elastic_twist)
    np.testing.assert_array_equal(rigid.alpha, sol.alpha)
    # and the twist lowers the thrust of a nose-down blade
    held = bem._solve(r, wind, omega, np.radians([0.0, 0.0, 6.0]))
    assert np.all(sol.thrust < held.thrust)


def test_a_stiff_blade_is_the_rigid_one_and_nothing_twists_without_a_moment(write_spec):
    stiff = _rotor(write_spec, gj=1.0e15)
    wind, omega, pitch = np.array([8.0]), np.array([1.4]), np.zeros(1)
    sol = bem.solve(stiff, wind, omega, pitch)
    held = bem._solve(stiff, wind, omega, pitch)
    assert sol.elastic_twist is not None
    assert np.max(np.abs(sol.elastic_twist)) < 1e-6
    assert sol.thrust[0] == pytest.approx(held.thrust[0], rel=1e-5)
    # no C_M and the shear centre on the quarter chord: rigid, no torsion model at all
    spec = load_spec(write_spec(_text(sc=0.25, cm="")))
    assert bem.rotor(spec).torsion is None
    # steady_torsion false: rigid whatever the data
    twisting = load_spec(write_spec(_text()))
    assert twisting.aerodynamics is not None
    off = twisting.model_copy(
        update={"aerodynamics": twisting.aerodynamics.model_copy(update={"steady_torsion": False})}
    )
    assert bem.rotor(off).torsion is None


def test_a_blade_that_diverges_in_torsion_is_solved_rigid_and_the_audit_warns(write_spec):
    from wtvib import audit

    # the shear centre at 90 % of the chord and a soft blade: the lift's nose-up moment
    # grows faster with the twist than the blade resists it (torsional divergence)
    spec = load_spec(write_spec(_text(gj=2.0e5, sc=0.9)))
    sch = bem.schedule(spec)
    sol = sch.solution
    assert sol.twist_unsettled is not None and sol.twist_unsettled.any()
    assert sol.elastic_twist is not None
    assert np.all(sol.elastic_twist[sol.twist_unsettled] == 0.0)
    check = {c.id: c for c in audit.run(spec).checks}["aerodynamics.operation"]
    assert check.status == "warn" and "torsional divergence" in check.message
    assert math.isfinite(float(sol.thrust.max()))
