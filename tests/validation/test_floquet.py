"""Floquet analysis against Mathieu's stability chart and independent integrations.

Mathieu: y″ + (a − 2q·cos 2t)·y = 0 has period π; between the characteristic values
b₁(q) and a₁(q) (scipy.special.mathieu_b / mathieu_a) it is unstable, just outside stable
(Abramowitz & Stegun, ch. 20; McLachlan, *Theory and Application of Mathieu Functions*).
"""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.linalg import expm
from scipy.special import mathieu_a, mathieu_b

from tests.conftest import TURBINES
from wtvib import audit, spec
from wtvib.numerics import floquet
from wtvib.subsystems import rotor


def largest(a, period: float, steps: int) -> float:  # type: ignore[no-untyped-def]
    """The largest Floquet multiplier |ρ|: the monodromy's eigenvalues (wtvib.numerics.floquet's
    integrator, the one the audit's rotor.floquet check runs over its speeds at once)."""
    return float(np.max(np.abs(np.linalg.eigvals(floquet.monodromy(a, period, steps)))))


def mathieu(a: float, q: float):  # type: ignore[no-untyped-def]
    return lambda t: np.array([[0.0, 1.0], [-(a - 2 * q * math.cos(2 * t)), 0.0]])


@pytest.mark.parametrize("q", [0.5, 1.0, 2.0])
@pytest.mark.parametrize("order", [1, 2])
def test_mathieu_stability_boundaries(q, order):
    b, a = mathieu_b(order, q), mathieu_a(order, q)
    lo, hi = min(a, b), max(a, b)
    inside = largest(mathieu(0.5 * (lo + hi), q), math.pi, 400)
    below = largest(mathieu(lo - 0.02, q), math.pi, 400)
    above = largest(mathieu(hi + 0.02, q), math.pi, 400)
    assert inside > 1.0 + 1e-3
    assert below == pytest.approx(1.0, abs=1e-7) and above == pytest.approx(1.0, abs=1e-7)


def test_monodromy_matches_the_matrix_exponential():
    a = np.array([[0.0, 1.0], [-4.0, -0.3]])
    phi = floquet.monodromy(lambda t: a, 2.0, 400)
    assert phi == pytest.approx(expm(2.0 * a), abs=1e-9)


def yaw_model(epsilon: float, ratio: float, zeta: float = 0.0):  # type: ignore[no-untyped-def]
    """J(t) = J̄(1 + ε cos 2Ωt): d/dt(J φ̇) + c φ̇ + k φ = 0 with Ω = 1, ω₀ = ratio·Ω."""

    def a(t: float) -> np.ndarray:
        j = 1 + epsilon * math.cos(2 * t)
        jd = -2 * epsilon * math.sin(2 * t)
        return np.array([[0.0, 1.0], [-(ratio**2) / j, -(jd + 2 * zeta * ratio) / j]])

    return a


def independent_largest(a, period: float) -> float:  # type: ignore[no-untyped-def]
    """The same multiplier from scipy's DOP853 (an independent integrator)."""
    cols = []
    for k in range(2):
        y0 = np.eye(2)[:, k]
        sol = solve_ivp(
            lambda t, y: a(t) @ y, (0, period), y0, method="DOP853", rtol=1e-11, atol=1e-12
        )
        cols.append(sol.y[:, -1])
    return float(np.max(np.abs(np.linalg.eigvals(np.array(cols).T))))


def unstable_band(epsilon: float, zeta: float = 0.0) -> tuple[float, float] | None:
    ratios = np.linspace(0.8, 1.2, 161)
    rho = [largest(yaw_model(epsilon, r, zeta), 2 * math.pi, 300) for r in ratios]
    bad = ratios[np.array(rho) > 1 + 1e-6]
    return (float(bad.min()), float(bad.max())) if bad.size else None


@pytest.mark.parametrize("epsilon", [0.1, 0.3])
def test_minimal_yaw_model_has_a_band_near_one_per_rev(epsilon):
    band = unstable_band(epsilon)
    assert band is not None and band[0] < 1.0 < band[1]  # ω₀/Ω ≈ 1: 2Ω = 2ω₀
    # the edges agree with an independent integration (DOP853)
    for r in (band[0] + 0.0025, band[1] - 0.0025):
        ours = largest(yaw_model(epsilon, r), 2 * math.pi, 300)
        assert ours == pytest.approx(
            independent_largest(yaw_model(epsilon, r), 2 * math.pi), rel=1e-6
        )


def test_band_grows_with_epsilon_and_damping_shrinks_it():
    narrow, wide = unstable_band(0.1), unstable_band(0.3)
    assert narrow and wide and (wide[1] - wide[0]) > (narrow[1] - narrow[0])
    damped = unstable_band(0.1, zeta=0.02)
    assert damped is None or (damped[1] - damped[0]) < (narrow[1] - narrow[0])


def head(blades: int, hub: str = "hingeless") -> rotor.HeadModel:
    return rotor.HeadModel(
        blades,
        hub,
        1e6,
        5e5,
        5e5,
        5e5 * (2 * math.pi * 0.5) ** 2,
        5e5 * (2 * math.pi * 0.6) ** 2,
        0.0,
        0.0,
    )


def test_three_blades_give_a_time_invariant_system():
    w = np.array([1.0, 2.5])
    m = head(3)
    first = m.state_matrices(w, 0.0)
    for psi in (0.3, 1.1, 2.9, 5.0):
        assert np.array_equal(m.state_matrices(w, psi), first)
    phi = floquet.monodromy(m.state_matrix(2.5), 2 * math.pi / 2.5, 300)
    assert phi == pytest.approx(expm(first[1] * 2 * math.pi / 2.5), abs=1e-6)  # RK4, h⁴


def test_period_doubling_hingeless_coefficients_repeat_every_half_revolution():
    # the hingeless coefficients have period π/Ω: Φ(T) = Φ(T/2)², so multipliers square
    m = head(2)
    a, w = m.state_matrix(2.0), 2.0
    half = floquet.monodromy(a, math.pi / w, 300)
    full = floquet.monodromy(a, 2 * math.pi / w, 600)
    assert full == pytest.approx(half @ half, abs=1e-8)


def test_teetered_hub_decouples_and_hingeless_on_a_flexible_tower_is_hazardous():
    speeds = np.linspace(0.5, 6.0, 120)
    hingeless = rotor.stability_map(head(2), speeds)
    teetered = rotor.stability_map(head(2, "teetered"), speeds)
    assert np.any(hingeless > 1.01)  # parametric instability bands
    assert np.all(teetered <= 1 + 1e-6)


TWO_BLADED = ["mod-0", "mod-1", "mod-2", "wts-75", "wts-3", "wts-4", "growian", "aeroman"]


@pytest.mark.parametrize("name", TWO_BLADED)
def test_every_two_bladed_catalogue_turbine_gets_a_stability_map(name):
    r = audit.run(spec.load(TURBINES / f"{name}.yaml"))
    c = next(c for c in r.checks if c.id == "rotor.floquet")
    smap = r.result(rotor.NAME, rotor.RotorResults).map  # what the figure draws (not in JSON)
    assert len(smap.speeds_rpm) == len(smap.largest) > 50
    assert "map_rpm" not in c.numbers
    assert c.status == "pass"  # the built designs are stable where they run


def test_the_wts4_tower_with_a_hingeless_rotor_shows_instability_bands(tmp_path):
    # Hau 7.5.1: "a turbine with a hingeless rotor and flexible tower design would be an
    # extremely hazardous concept" — the same double-soft tower with a hingeless hub
    text = (TURBINES / "wts-4.yaml").read_text().replace("hub: teetered", "hub: hingeless")
    path = tmp_path / "wts-4-hingeless.yaml"
    path.write_text(text)
    hingeless = next(c for c in audit.run(spec.load(path)).checks if c.id == "rotor.floquet")
    teetered = next(
        c for c in audit.run(spec.load(TURBINES / "wts-4.yaml")).checks if c.id == "rotor.floquet"
    )
    assert hingeless.numbers["unstable_rpm"] and hingeless.status in ("warn", "fail")
    assert not teetered.numbers["unstable_rpm"]


def test_three_bladed_turbines_are_time_invariant():
    c = next(
        c
        for c in audit.run(spec.load(TURBINES / "nrel-5mw.yaml")).checks
        if c.id == "rotor.floquet"
    )
    assert c.status == "info" and "time-invariant" in c.message


def test_batched_expm_matches_scipy():
    # Higham's scaling and squaring against scipy's implementation, norms 0.01–30, and an
    # undamped oscillator of ω·t = 1000 (the slow-rotor case: bounded, many squarings)
    rng = np.random.default_rng(1)
    for scale in (0.01, 1.0, 30.0):
        x = (rng.random((50, 4, 4)) - 0.5) * scale
        ref = expm(x)
        assert np.abs(floquet.expm(x) - ref).max() <= 1e-11 * max(1.0, np.abs(ref).max())
    osc = np.array([[[0.0, 1.0], [-1e4, 0.0]]]) * 10.0  # ω = 100 rad/s over 10 s
    assert floquet.expm(osc) == pytest.approx(expm(osc), abs=1e-9 * np.abs(expm(osc)).max())


def test_magnus_step_does_not_amplify_a_stiff_mode_on_a_slow_rotor():
    """ω·h = 50 per step (RK4 diverges beyond 2.8): exact for constant coefficients, so the
    undamped oscillator keeps |ρ| = 1 to rounding."""
    w = 50.0
    a = np.array([[0.0, 1.0], [-(w**2), 0.0]])
    phi = floquet.monodromy(lambda t: a, 2 * math.pi, 6)  # ω·h = 52 per step
    assert np.abs(np.linalg.eigvals(phi)) == pytest.approx([1.0, 1.0], abs=1e-9)
    exact = expm(2 * math.pi * a)
    assert phi == pytest.approx(exact, abs=1e-8 * np.abs(exact).max())
