"""Steady blade-element momentum: the solution satisfies both of its theories, and the
controller's schedule does what the controller does.

Expected relations (no reference number needed, each can fail): at a converged station the
blade-element thrust equals the momentum thrust 4πrρV²a(1 − a)F·dr (Hansen, *Aerodynamics of
Wind Turbines*, eq. 6.23, valid for a ≤ 0.4 where Buhl's correction is not used) and the
torque 4πr³ρVΩa′(1 − a)F·dr (eq. 6.24); the schedule holds rated aerodynamic power above the
rated wind and the optimal tip-speed ratio below rated speed.
"""

import math

import numpy as np
import pytest

from wtvib.aero import bem
from wtvib.importers import load


@pytest.fixture(scope="module")
def nrel(shared):  # type: ignore[no-untyped-def]
    return load(shared / "reference/NREL5MW/NREL-5MW.fst")


def test_element_and_momentum_thrust_agree_where_induction_is_moderate(nrel):
    r = bem.rotor(nrel)
    wind = np.array([6.0, 9.0])
    omega = 7.5 * wind / r.tip_radius
    sol = bem.solve(r, wind, omega, np.zeros(2))
    f = bem._losses(r, sol.phi)
    q = 0.5 * r.rho * sol.w**2 * r.chord
    s, c = np.sin(sol.phi), np.cos(sol.phi)
    element_dt = r.blades * q * (sol.cl * c + sol.cd * s)
    momentum_dt = 4 * np.pi * r.radius * r.rho * wind[:, None] ** 2 * sol.a * (1 - sol.a) * f
    element_dq = r.blades * q * (sol.cl * s - sol.cd * c) * r.radius
    momentum_dq = (
        4 * np.pi * r.radius**3 * r.rho * wind[:, None] * omega[:, None] * sol.a_t * (1 - sol.a) * f
    )
    ok = sol.converged & (sol.a > 0.02) & (sol.a < 0.35) & (r.radius < 0.97 * r.tip_radius)
    assert ok.sum() > 20
    np.testing.assert_allclose(element_dt[ok], momentum_dt[ok], rtol=1e-5)
    np.testing.assert_allclose(element_dq[ok], momentum_dq[ok], rtol=1e-5)


def test_the_polar_lookup_is_periodic_and_interpolates(nrel):
    r = bem.rotor(nrel)
    a = np.radians(np.array([[-179.9] * len(r.radius), [179.9] * len(r.radius)]))
    cl, _ = r.polar(a)
    np.testing.assert_allclose(cl[0], cl[1], atol=0.02)  # ±180° meet
    p = nrel.aerodynamics.airfoils["NACA64_A17"]
    i = len(r.radius) - 1  # the tip station uses NACA64_A17
    x = np.radians(np.full((1, len(r.radius)), 4.3))
    assert r.polar(x)[0][0, i] == pytest.approx(np.interp(4.3, p.alpha_deg, p.cl), abs=1e-3)


def test_schedule_regions(nrel):
    sch = bem.schedule(nrel)
    sol = sch.solution
    p_rated = 5000e3 / 0.944  # VS_RtPwr over GenEff: the aerodynamic power held
    full = np.array([reg == "full load" for reg in sch.region])
    assert full.any() and (~full).any()
    np.testing.assert_allclose(sol.power[full], p_rated, rtol=1e-3)
    assert np.all(sol.power[~full] <= p_rated * 1.001)
    assert np.all(np.diff(sch.pitch_deg[full]) > 0)  # feathering as the wind rises
    below = (~full) & (sch.rpm < 12.1 - 1e-6) & (sch.rpm > sch.rpm.min() + 1e-6)
    tsr = sol.omega[below] * 63.0 / sol.wind[below]
    np.testing.assert_allclose(tsr, 7.5, rtol=1e-9)  # VS_TSRopt
    assert sch.rated_wind is not None and sch.rated_wind in sch.wind
    # the rated wind is where the fine-pitch power reaches rated (bem._rated_wind): the
    # point there, still at the fine pitch, has rated power to 1e-6 (secant in a 3.5 mm cell)
    at = int(np.argmin(np.abs(sch.wind - sch.rated_wind)))
    assert sch.pitch_deg[at] == 0.0 and sol.power[at] == pytest.approx(p_rated, rel=1e-6)


def test_fixed_speed_stall_regulation_holds_pitch(write_spec):
    path = write_spec(SMALL + AERO.format(regulation="stall"))
    from wtvib.spec import load as load_spec

    sch = bem.schedule(load_spec(path))
    assert set(sch.region) == {"stall"}
    np.testing.assert_allclose(sch.rpm, 30.0)
    np.testing.assert_allclose(sch.pitch_deg, 2.0)


SMALL = """\
wtvib: 1
turbine: {name: Small stall rotor, rotor_diameter_m: 40, rated_power_kw: 500}
rotor: {blades: 3, orientation: upwind, hub: rigid, speed: {fixed_rpm: 30}}
tower: {modes: {fa1: 0.8}}
blade: {mass_kg: 2000, modes: {flap1: 1.5, edge1: 2.5}}
"""

AERO = """
aerodynamics:
  stations:
    radius_m: [1.5, 5, 10, 15, 19.5]
    chord_m: [1.6, 1.5, 1.2, 0.9, 0.6]
    twist_deg: [12, 8, 4, 1, 0]
    airfoil: [foil, foil, foil, foil, foil]
  airfoils:
    foil: {{alpha_deg: [-180, -20, -10, 0, 10, 14, 20, 45, 90, 180],
           cl: [0, -0.8, -0.9, 0.3, 1.3, 1.45, 1.1, 1.0, 0.0, 0],
           cd: [0.02, 0.3, 0.02, 0.008, 0.015, 0.05, 0.3, 1.0, 1.6, 0.02]}}
  control: {{regulation: {regulation}, fine_pitch_deg: 2, cut_in_wind_m_s: 4,
            cut_out_wind_m_s: 25}}
"""


def test_the_optimal_tip_speed_ratio_maximises_cp(nrel):
    r = bem.rotor(nrel)
    best = bem.optimal_tsr(r, 0.0)
    cp = bem.power_coefficient(r, np.array([best - 0.5, best, best + 0.5]), 0.0)
    assert cp[1] >= cp[0] and cp[1] >= cp[2]
    assert math.isfinite(best)


def test_the_pitch_grid_in_chunks_gives_the_pitch_of_the_whole_grid(nrel, monkeypatch):
    """Above rated the pitch grid is solved PITCH_CHUNK points at a time, further points only
    for winds still above rated: the same brackets, so the same pitches to the last bit as
    the whole 0–60° grid at once — also where a wind needs the second chunk (a chunk of 2
    points: 0–5°)."""
    r = bem.rotor(nrel)
    wind = np.linspace(12.0, 25.0, 9)
    omega = np.full_like(wind, 1.2671)  # 12.1 rpm
    low = np.zeros_like(wind)
    p = 5e6 / 0.944
    chunked = bem._pitch_to_rated(r, wind, omega, low, p)
    for chunk in (13, 2):
        monkeypatch.setattr(bem, "PITCH_CHUNK", chunk)
        np.testing.assert_array_equal(bem._pitch_to_rated(r, wind, omega, low, p), chunked)
    assert np.all(np.diff(chunked) > 0) and math.degrees(chunked[-1]) > 15  # feathering


def test_prandtl_losses_are_the_textbook_factors_inside_and_outside_the_blade(nrel):
    """F = F_tip·F_hub with F = (2/π)·arccos(e^(−x)), x_tip = B/2·(R − r)/(r·|sin φ|),
    x_hub = B/2·(r − R_hub)/(R_hub·|sin φ|) (Hansen, Aerodynamics of Wind Turbines, §6.3),
    e^(−x) clipped to 1 at a station past the tip or inside the hub (F = 0 there, floored
    at 1e-6)."""
    import dataclasses

    r = bem.rotor(nrel)
    assert r.tip_loss and r.hub_loss  # AeroDyn's TipLoss and HubLoss, both on in the deck
    radius = np.array(
        [0.5 * r.hub_radius, r.hub_radius, 20.0, 50.0, r.tip_radius, 1.02 * r.tip_radius]
    )
    rot = dataclasses.replace(r, radius=radius, chord=np.ones(6), twist=np.zeros(6))
    phi = np.linspace(-0.6, 1.4, 7)[:, None] * np.ones(6)
    s = np.maximum(np.abs(np.sin(phi)), 1e-9)
    b = rot.blades / 2

    def factor(x: np.ndarray) -> np.ndarray:
        return 2 / np.pi * np.arccos(np.clip(np.exp(-x), 0.0, 1.0))

    tip = factor(b * (rot.tip_radius - radius) / (radius * s))
    hub = factor(b * (radius - rot.hub_radius) / (rot.hub_radius * s))
    np.testing.assert_allclose(bem._losses(rot, phi), np.maximum(tip * hub, 1e-6), rtol=1e-14)
    assert np.all(bem._losses(rot, phi)[:, [0, -1]] == 1e-6)
    # either loss alone (AeroDyn's TipLoss or HubLoss switched off) is its own factor
    for alone, expected in (("hub_loss", tip), ("tip_loss", hub)):
        one = dataclasses.replace(rot, **{alone: False})
        np.testing.assert_allclose(bem._losses(one, phi), np.maximum(expected, 1e-6), rtol=1e-14)
    neither = dataclasses.replace(rot, tip_loss=False, hub_loss=False)
    assert np.all(bem._losses(neither, phi) == 1.0)


def test_a_station_at_the_tip_is_loaded_as_its_model_says(nrel):
    """Prandtl's tip loss is zero at the tip, where the momentum balance has no root. A
    station at the tip radius, or within a deck's rounding of it (r-test's AeroDyn blades
    end at BlSpn 61.4999 m on a 61.5 m blade: 1.6e-6 of R), carries no load in wtvib's own
    models (a = 1, a′ = −1: the flow stopped there) — with a floor on F instead it met
    105 m/s at the 5-MW's tip against 79 m/s a station inboard, and held a flap damping
    larger than any other section's. Read from an AeroDyn deck it carries what AeroDyn's
    BEMT gives its blade's last node, whose inductions it fixes at a = 1, a′ = 0 (BEMT.f90,
    FixedInductions: the node's tip-loss constant is 0 by construction): the rotation's
    speed alone at φ = 0, the lift at α = −θ (OpenFAST 5 on r-test's AeroDyn fixture,
    settled: its last node at a = 1, a′ = 0, W = 79.7 m/s = Ω·r, 2.3 kN/m normal to the
    plane). A station 1 % inboard is loaded as before; without tip loss the tip station
    is loaded too."""
    import dataclasses

    r = bem.rotor(nrel)
    assert r.tip_loss and r.radius[-1] == pytest.approx(r.tip_radius, rel=1e-5)
    assert r.fixed_tip_induction  # an AeroDyn deck
    wind = np.array([8.0, 14.0])
    omega = np.full(2, 12.1 * math.pi / 30)
    pitch = np.radians([0.0, 8.0])
    sol = bem.solve(r, wind, omega, pitch)
    assert np.all(sol.a[:, -1] == 1.0) and np.all(sol.a_t[:, -1] == 0.0)
    assert np.all(sol.phi[:, -1] == 0.0)
    np.testing.assert_allclose(sol.w[:, -1], omega * r.radius[-1], rtol=1e-12)
    np.testing.assert_allclose(sol.alpha[:, -1], -(r.twist[-1] + pitch), rtol=1e-12)
    own = dataclasses.replace(r, fixed_tip_induction=False)  # wtvib's own models
    sol = bem.solve(own, wind, omega, pitch)
    assert np.all(sol.w[:, -1] == 0.0) and np.all(sol.a[:, -1] == 1.0)
    assert np.all(sol.w[:, -2] > 50.0)  # the station inboard, loaded
    # the thrust: the trapezoid of the sections' loads, the tip's zero
    q = 0.5 * own.rho * sol.w**2 * own.chord
    f_n = q * (sol.cl * np.cos(sol.phi) + sol.cd * np.sin(sol.phi))
    assert f_n[:, -1] == pytest.approx(np.zeros(2), abs=0.0)
    np.testing.assert_allclose(sol.thrust, own.blades * np.trapezoid(f_n, own.radius, axis=1))
    rounded = dataclasses.replace(own, tip_radius=float(own.radius[-1]) * (1 + 5e-5))
    assert rounded.at_tip[-1] and not rounded.at_tip[-2]
    inboard = dataclasses.replace(own, tip_radius=float(own.radius[-1]) * 1.01)
    assert not inboard.at_tip.any()
    assert np.all(bem.solve(inboard, wind, omega, pitch).w[:, -1] > 50.0)
    free = dataclasses.replace(own, tip_loss=False)
    assert not free.at_tip.any()
    assert np.all(bem.solve(free, wind, omega, pitch).w[:, -1] > 50.0)


def test_momentum_theory_gives_the_induction_in_both_of_its_paths():
    """Below k = 2/3 the axial induction is momentum theory's a = k/(1 + k) (Ning 2014,
    eq. 14) — on the path taken when every station is lightly loaded and, station by station,
    on the mixed path beside Buhl's heavily loaded ones; above, Buhl's curve, which meets it
    at k = 2/3 (a = 0.4) continuously."""
    light = np.array([0.05, 0.3, 0.6])
    f = np.ones(3)
    np.testing.assert_allclose(bem._momentum(light, f), light / (1 + light), rtol=1e-12)
    mixed = np.array([0.05, 0.3, 0.6, 0.9, 1.5])
    a = bem._momentum(mixed, np.ones(5))
    np.testing.assert_allclose(a[:3], light / (1 + light), rtol=1e-12)
    edge = bem._momentum(np.array([2 / 3 - 1e-9, 2 / 3 + 1e-9]), np.ones(2))
    assert edge == pytest.approx([0.4, 0.4], abs=1e-6)
    # above, Buhl's a = (g1 − √g2)/g3 as Ning (2014) writes it, out here at k = 0.9 and 1.5
    for k, f in ((0.9, 1.0), (1.5, 0.8)):
        g1 = 2 * f * k - (10 / 9 - f)
        g2 = 2 * f * k - f * (4 / 3 - f)
        g3 = 2 * f * k - (25 / 9 - 2 * f)
        buhl = (g1 - math.sqrt(g2)) / g3
        assert bem._momentum(np.array([k]), np.array([f]))[0] == pytest.approx(buhl, rel=1e-12)
        assert buhl != pytest.approx(k / (1 + k), rel=1e-3)  # not momentum theory's


def test_nings_residual_in_the_momentum_and_propeller_brake_regions():
    """Ning (2014, Wind Energy 17, eq. 15): R(φ) = sin φ/(1 − a) − cos φ/λ_r·(1 − k′) where
    momentum theory holds (φ > 0), R(φ) = sin φ·(1 − k) − cos φ/λ_r·(1 − k′) in the propeller
    brake region (φ < 0) — written out here at λ_r = 5, k = 0.2, k′ = 0.05, a = 0.25."""
    phi = np.array([0.3, -0.1])
    s, c = np.sin(phi), np.cos(phi)
    k, kp, a, lam = np.full(2, 0.2), np.full(2, 0.05), np.full(2, 0.25), np.full(2, 5.0)
    got = bem._balance(phi, s, c, k, kp, a, lam)
    expected = [
        np.sin(0.3) / 0.75 - np.cos(0.3) / 5 * 0.95,
        np.sin(-0.1) * 0.8 - np.cos(-0.1) / 5 * 0.95,
    ]
    np.testing.assert_allclose(got, expected, rtol=1e-14)


GIVEN = """
  control:
    operating_points: {{wind_m_s: [5, 8, 11, 15, 20], rpm: [18, 26, 30, 30, {top}],
                        pitch_deg: [2, 2, 3, 9, 16], source: a published table}}
"""


def test_given_operating_points_are_solved_at_and_checked_against_the_speeds(write_spec):
    """A model's own operating points replace the controller's schedule: the BEM is solved
    at exactly those winds, speeds and pitches; the rated wind is the lowest at the top
    speed. A point outside the rotor's operating speeds is a one-line input error naming
    the point (file, line, field)."""
    from wtvib.errors import SpecError
    from wtvib.spec import load as load_spec

    small = SMALL.replace("speed: {fixed_rpm: 30}", "speed: {min_rpm: 15, max_rpm: 30}")
    aero = AERO.format(regulation="pitch").split("  control:")[0]
    spec = load_spec(write_spec(small + aero + GIVEN.format(top=30)))
    sch = bem.schedule(spec)
    np.testing.assert_array_equal(sch.wind, [5, 8, 11, 15, 20])
    np.testing.assert_allclose(sch.rpm, [18, 26, 30, 30, 30], rtol=1e-12)
    np.testing.assert_allclose(sch.pitch_deg, [2, 2, 3, 9, 16], rtol=1e-12)
    assert sch.region == ("partial load",) * 2 + ("full load",) * 3
    assert any("a published table" in a for a in sch.assumptions)
    # the region-2 tip-speed ratio: the median of the points below the top speed; the rated
    # wind where the first pitched point's power (11 m/s) is reached from 8 m/s, the power
    # growing as V³ — not before the tip-speed ratio reaches the top speed (30 rpm)
    lam = np.array([18, 26]) * np.pi / 30 * 20.0 / np.array([5.0, 8.0])
    assert sch.tip_speed_ratio == pytest.approx(float(np.median(lam)), rel=1e-12)
    power = sch.solution.power
    cube = 8.0 * float(power[2] / power[1]) ** (1 / 3)
    reached = 30 * np.pi / 30 * 20.0 / float(np.median(lam))
    assert sch.rated_wind == pytest.approx(min(max(cube, reached), 11.0), rel=1e-12)
    assert reached < sch.rated_wind < 11.0
    with pytest.raises(SpecError) as err:
        load_spec(write_spec(small + aero + GIVEN.format(top=45)))
    assert "operating point 5 turns at 45 rpm, outside the rotor's operating speeds" in str(
        err.value
    )
    assert err.value.path == "aerodynamics.control.operating_points.rpm.4"
    assert err.value.line is not None
