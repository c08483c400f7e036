"""Aerodynamic damping of isolated modes: the formulas as the module states them, wired to
the audit (the coupled model's validation is in tests/validation/test_aerodynamics.py)."""

import numpy as np
import pytest

from wtvib import audit
from wtvib.aero import aerodamping, bem
from wtvib.results import OperatingDamping
from wtvib.spec import load

from . import oracles

SPEC = """\
wtvib: 1
turbine: {name: T, rotor_diameter_m: 40, rated_power_kw: 500}
rotor: {blades: 3, orientation: upwind, hub: rigid, speed: {min_rpm: 15, max_rpm: 30}}
tower: {mass_kg: 40000, damping_ratio: 0.01, modes: {fa1: 0.8, ss1: 0.8}}
tower_head: {mass_kg: 30000, cm_downwind_m: 0, cm_above_top_m: 1}
blade: {mass_kg: 2000, damping_ratio: 0.005, modes: {flap1: 1.5, edge1: 2.5}}
aerodynamics:
  stations: {radius_m: [1.5, 5, 10, 15, 19.5], chord_m: [1.6, 1.5, 1.2, 0.9, 0.6],
             twist_deg: [12, 8, 4, 1, 0], airfoil: [f, f, f, f, f]}
  airfoils:
    f: {alpha_deg: [-180, -10, 0, 10, 20, 90, 180], cl: [0, -0.9, 0.3, 1.3, 1.1, 0, 0],
        cd: [0.02, 0.02, 0.008, 0.015, 0.3, 1.6, 0.02]}
"""


def test_isolated_first_tower_modes_carry_the_rotors_damping(write_spec):
    """Quasi-steady: ζ_fa1 = N_b∫C_nn dr / (2ω(M_head + 33/140·M_tower)); side-side the
    azimuth mean (N_b/2)∫C_tt dr; each on top of the tower's structural ratio. With the
    lift lagged (judged): the root of the single-mode characteristic equation with Jones's
    C(s̄) at the lift-weighted 2W/c, found as a quartic's roots (tests/oracles.py)."""
    spec = load(write_spec(SPEC))
    report = audit.run(spec)
    modes = {m.id: m for m in report.modes}
    sec = aerodamping.sections(spec)
    mass = 30000 + 33 / 140 * 40000
    w = 2 * np.pi * 0.8

    def rotor(table: np.ndarray, e: int, share: float) -> np.ndarray:
        return share * np.trapezoid(table[:, :, e, e], sec.radius, axis=1)

    lift_rate = sec.lift * sec.rate[..., None, None]
    steady = {}
    for mid, e, share in (("tower.fa1", 0, 3.0), ("tower.ss1", 1, 1.5)):
        c, lift = rotor(sec.c, e, share), rotor(sec.lift, e, share)
        rate = np.abs(rotor(lift_rate, e, share) / lift)
        steady[mid] = c / (2 * w * mass)
        lagged = [
            oracles.lagged_single_mode_zeta(mass, w, ck, lk, rk)
            for ck, lk, rk in zip(c, lift, rate, strict=True)
        ]
        op = modes[mid].operating
        assert op is not None and op.quasi_steady is not None
        np.testing.assert_allclose(op.quasi_steady, steady[mid] + 0.01, rtol=1e-12)
        np.testing.assert_allclose(op.aero, lagged, rtol=1e-7, atol=1e-9)
        np.testing.assert_allclose(op.total, np.asarray(op.aero) + 0.01, rtol=1e-12)
    fa, ss = steady["tower.fa1"], steady["tower.ss1"]
    assert min(fa) > 5 * max(abs(ss))  # fore-aft damped by the thrust gradient, side-side not


def test_operating_damping_is_the_lowest_at_a_shared_speed():
    """Several winds at the rated speed: the verdict at that speed takes the lowest ζ."""
    op = OperatingDamping(
        (5.0, 8.0, 12.0, 20.0),
        (1.0, 1.5, 2.0, 2.0),
        (0, 0, 0, 10),
        (0.1, 0.2, 0.3, 0.05),
        (0.11, 0.21, 0.31, 0.06),
        "test",
    )
    assert op.at(2.0) == 0.06
    assert op.at(1.25) == np.float64(0.16)  # between speeds: linear
    assert op.at(0.5) == 0.11 and op.at(3.0) == 0.06  # held beyond
    assert op.lowest == 3


def test_heavily_damped_crossings_are_info_and_the_daf_uses_the_damping_there(write_spec):
    report = audit.run(load(write_spec(SPEC)))
    flap = [f for f in report.findings if f.mode.id == "blade.flap1" and f.crossings]
    assert flap
    for f in flap:
        assert f.damping_in_operation
        zeta = [f.mode.damping_at(c, 0.0) for c in f.crossings]
        np.testing.assert_allclose(f.crossing_daf, [1 / (2 * z) for z in zeta])
        if f.damping_met >= 0.3:
            assert f.status in ("pass", "info")


def test_aerodynamics_without_a_mode_to_damp_is_said(write_spec):
    """Aerodynamics given but no mass anywhere: no mode can take them; the audit is
    structural, and says what is missing instead of passing the stability check."""
    text = SPEC.replace("tower: {mass_kg: 40000, ", "tower: {").replace("mass_kg: 2000, ", "")
    text = text.replace("tower_head: {mass_kg: 30000, cm_downwind_m: 0, cm_above_top_m: 1}\n", "")
    report = audit.run(load(write_spec(text)))
    doc = report.to_dict()
    assert doc["damping"] == "structural" and doc["aerodynamics"] is True
    stab = next(c for c in report.checks if c.id == "aerodynamics.stability")
    assert stab.status == "info" and "blade.mass_kg" in stab.message
    assert any("No aerodynamic damping for" in a for a in report.assumptions)


def test_the_best_power_coefficient_is_named_over_its_plateau(write_spec):
    """Region 2 holds one tip-speed ratio at one pitch, so C_p is the same at every wind
    there to rounding: the message names those winds, not whichever one's rounding came
    out highest (that wind moved with the last bit of the BEM)."""
    spec = load(write_spec(SPEC))
    report = audit.run(spec)
    sch = bem.schedule(spec)
    inside = (sch.rpm > 15 * (1 + 1e-9)) & (sch.rpm < 30 * (1 - 1e-9))  # Ω follows the wind
    winds = sch.wind[inside]
    assert len(winds) >= 2
    text = next(c.message for c in report.checks if c.id == "aerodynamics.operation")
    assert f"at {len(winds)} winds {winds[0]:.3g}–{winds[-1]:.3g} m/s" in text


def test_sections_at_other_radii_is_np_interp_of_every_entry(write_spec):
    """Sections.at interpolates every operating point and matrix entry at once: the same
    numbers as np.interp of each (zero outside the stations, a station's own value on it)."""
    sec = aerodamping.sections(load(write_spec(SPEC)))
    x = sec.radius
    r = np.concatenate([np.linspace(x[0] - 1, x[-1] + 1, 97), x])
    flat = sec.c.reshape(len(sec.c), len(x), 4)
    expected = np.stack(
        [
            np.stack([np.interp(r, x, flat[k, :, e], left=0.0, right=0.0) for e in range(4)], -1)
            for k in range(len(sec.c))
        ]
    ).reshape(len(sec.c), len(r), 2, 2)
    assert np.array_equal(sec.at(r), expected)


def test_a_rotor_that_draws_no_power_is_a_warning_not_a_crash(write_spec):
    """A rotor turned far too fast (300 rpm on 40 m: tip speed 630 m/s) brakes at every
    wind, C_p < 0 everywhere: the operation check names its best (negative) C_p and warns
    that the input is likely wrong (a ROSCO gearbox ratio of 2.7 on the NREL 5-MW deck did
    this, and the best-C_p wind came out of an empty selection: an internal error)."""
    spec = load(write_spec(SPEC.replace("min_rpm: 15, max_rpm: 30", "min_rpm: 300, max_rpm: 400")))
    report = audit.run(spec)
    cp, _ = bem.schedule(spec).coefficients(bem.rotor(spec))
    assert cp.max() < 0
    check = next(c for c in report.checks if c.id == "aerodynamics.operation")
    assert check.status == "warn" and "draws no power" in check.message
    assert f"C_p up to {cp.max():.3f}" in check.message


def test_a_structural_audit_says_which_aeroelastic_checks_it_made():
    """Euros 44 m's report said 'no aeroelastic instability looked for' beside its
    own divergence, flutter and stall checks; MOD-2 has no section data and says so."""
    from wtvib import audit
    from wtvib.spec import from_data, load

    from .conftest import TURBINES

    def operation(name: str, aerodynamics: bool = True) -> str:
        s = load(TURBINES / f"{name}.yaml")
        if not aerodynamics:  # the catalogue's Euros has them since; audit it without
            data = s.model_dump(mode="json", exclude_none=True)
            data.pop("aerodynamics")
            s = from_data(data)
        report = audit.run(s)
        return next(c.message for c in report.checks if c.id == "aerodynamics.operation")

    structural = operation("euros-44m", aerodynamics=False)
    assert "blade.flutter" in structural and "looked for" not in structural
    assert "no aeroelastic instability looked for" in operation("mod-2")


def test_the_operating_points_thrust_and_power_agree_with_their_coefficients():
    """In aerodynamics.operation every point's thrust [kN] is C_t·½ρA·V² and its power [kW]
    C_p·½ρA·V³ with one ½ρA for all of them (the definitions of the coefficients, Burton et
    al. §3.2): thrust/(C_t·V²) and power/(C_p·V³) are the same constant at every point."""
    import pytest

    from tests.conftest import TURBINES

    s = load(TURBINES / "stall-rotor-1mw.yaml")
    report = audit.run(s)
    c = next(c for c in report.checks if c.id == "aerodynamics.operation")
    rows = [p for p in c.numbers["points"] if p["ct"] > 0.05 and p["cp"] > 0.05]
    assert len(rows) >= 5
    half_rho_area = [p["thrust_kn"] / (p["ct"] * p["wind_m_s"] ** 2) for p in rows]
    half_rho_area += [p["power_kw"] / (p["cp"] * p["wind_m_s"] ** 3) for p in rows]
    assert half_rho_area == pytest.approx([half_rho_area[0]] * len(half_rho_area), rel=2e-3)
    assert s.aerodynamics is not None and s.turbine.rotor_diameter_m is not None
    rho, radius = s.aerodynamics.air_density_kg_m3, s.turbine.rotor_diameter_m / 2
    assert half_rho_area[0] * 1e3 == pytest.approx(0.5 * rho * np.pi * radius**2, rel=0.01)
    # the message's "thrust up to" is the points' largest, in kN
    assert f"thrust up to {max(p['thrust_kn'] for p in c.numbers['points']):,.0f} kN" in c.message


def test_the_pitch_regulated_schedule_states_the_power_it_holds_in_kw():
    """Euros 44 m: a pitch-regulated rotor of 2,000 kW (its aerodynamics.control) holds that
    power above rated wind, stated in kW where the schedule is described."""
    from tests.conftest import TURBINES

    report = audit.run(load(TURBINES / "euros-44m.yaml"))
    assert any("pitch holding 2,000 kW aerodynamic" in a for a in report.assumptions)


def test_a_root_damped_past_critical_reports_a_damping_ratio_of_one():
    """Operating damping from matched damped roots: a root at or past critical (ζ ≥ 0.999,
    or a total that reaches it) is no oscillation — reported as ζ = 1 and marked
    "overdamped"; first-order estimates are marked so; every total is at most 1."""
    from types import SimpleNamespace

    from wtvib.aero import aerodamping

    sol = SimpleNamespace(wind=np.array([5.0, 8, 11, 14]), omega=np.ones(4), pitch=np.zeros(4))
    sch = SimpleNamespace(solution=sol)
    roots = (
        np.array([0.5, 0.6, 0.7, 0.8]),
        np.array([0.05, 0.9995, 0.3, 0.2]),
        np.array([False, False, False, True]),
    )
    od = aerodamping._operating(sch, np.array([0.04, 0.5, 1.2, 0.1]), 0.01, "test", roots=roots)  # type: ignore[arg-type]
    assert od.total == pytest.approx((0.05, 1.0, 1.0, 0.11))
    assert od.method == ("eigenvalue", "overdamped", "overdamped", "first-order")
    # isolated estimates (no roots): the totals and the quasi-steady comparison capped at 1
    quasi = np.array([0.02, 0.995, 1.3, 0.1])
    iso = aerodamping._operating(sch, np.array([0.04, 0.5, 1.2, 0.1]), 0.01, "t", quasi=quasi)  # type: ignore[arg-type]
    assert iso.total == pytest.approx((0.05, 0.51, 1.0, 0.11))
    assert iso.quasi_steady == pytest.approx((0.03, 1.0, 1.0, 0.11))


def test_a_blade_modes_assumed_shape_is_the_cantilevers_first():
    """Without a computed shape an isolated blade mode takes the uniform cantilever's first
    bending shape, normalised to the tip: clamped at the root (φ = φ′ = 0) and free at the
    tip — no bending moment or shear there (φ″ = φ‴ = 0, by finite differences on a fine
    grid; Blevins Table 8-1 has β₁L = 1.87510 for exactly these four conditions)."""
    from wtvib.results import Mode

    root, tip = 2.0, 62.0
    r = np.linspace(root, tip, 20001)
    phi = aerodamping.blade_shape(Mode("blade.flap1", "blade", "", 1.0), r, root)
    h = r[1] - r[0]
    d1 = np.gradient(phi, h, edge_order=2)
    d2 = np.gradient(d1, h, edge_order=2)
    d3 = np.gradient(d2, h, edge_order=2)
    assert phi[-1] == 1.0 and abs(phi[0]) < 1e-12 and abs(d1[0]) < 1e-6
    # at the tip, against their size along the blade (the third difference is the noisier)
    assert abs(d2[-50]) < 1e-3 * np.abs(d2).max() and abs(d3[-50]) < 2e-2 * np.abs(d3).max()


def test_a_rated_power_the_rotor_never_reaches_is_said_in_kw():
    """Euros 44 m asked for 200 MW: its rotor never reaches it below cut-out, so it is
    never pitched — said with the power in kW."""
    from tests.conftest import TURBINES

    s = load(TURBINES / "euros-44m.yaml")
    assert s.aerodynamics is not None
    control = s.aerodynamics.control.model_copy(update={"rated_power_kw": 2.0e5})
    big = s.model_copy(
        update={"aerodynamics": s.aerodynamics.model_copy(update={"control": control})}
    )
    said = " ".join(audit.run(big).assumptions)
    assert "rated power 200,000 kW (aerodynamic) is not reached below cut-out" in said


def test_the_induction_in_equilibrium_answers_the_motion_as_the_momentum_balance_says(
    write_spec,
):
    """aerodamping.inflow_response against the annulus' momentum balance worked by hand, as
    AeroDyn's BEMT takes a section's motion into its inflow: V_x = V − v_n, V_y = Ωr + v_t,
    U_n = V_x(1 − a), U_t = V_y(1 + a′), and B·F(U) = M with M_n = 4πrρV_x²a(1 − a),
    M_t = 4πrρV_xV_y·a′(1 − a) (no tip or hub loss; Hansen, Aerodynamics of Wind Turbines,
    ch. 4). Linearised, x = (a, a′): B·F_U·(U_v δv + U_x δx) = M_v δv + M_x δx, with
    F_U = −C·S (S = diag(−1, 1), C the frozen section matrix), so that
    ∂U/∂v = U_v + U_x·(B·F_U·U_x − M_x)⁻¹·(M_v − B·F_U·U_v) and G = S·∂U/∂v. The code's
    central differences of re-solved BEM agree to 1e-5 (their step's O(δ²), the root's
    tolerance)."""
    text = SPEC.replace("aerodynamics:\n", "aerodynamics:\n  tip_loss: false\n  hub_loss: false\n")
    s = load(write_spec(text))
    r = bem.rotor(s)
    sol = bem.schedule(s).solution
    g = aerodamping.inflow_response(r, sol)
    h = np.radians(bem.SLOPE_STEP_DEG)
    (cl_p, cd_p), (cl_m, cd_m) = r.polar(sol.alpha + h), r.polar(sol.alpha - h)
    dcl, dcd = (cl_p - cl_m) / (2 * h), (cd_p - cd_m) / (2 * h)
    c = aerodamping.section_matrix(r.rho, r.chord, sol.w, sol.phi, sol.cl, sol.cd, dcl, dcd)
    sign = np.diag([-1.0, 1.0])
    checked = 0
    for k in range(len(sol.wind)):
        vx = sol.wind[k]
        for j, rad in enumerate(r.radius):
            a, at = sol.a[k, j], sol.a_t[k, j]
            # away from the polar's corners (10° steps in SPEC), where the ±0.5° slopes of
            # the section matrix and the re-solved BEM's tangent differ
            near = np.abs(np.degrees(sol.alpha[k, j]) - np.round(np.degrees(sol.alpha[k, j]), -1))
            if not (0.02 < a < 0.38 and sol.phi[k, j] > 0 and near > 1.0):
                continue
            vy, q = sol.omega[k] * rad, 4 * np.pi * rad * r.rho
            f_u = -c[k, j] @ sign
            u_v, u_x = np.diag([-(1 - a), 1 + at]), np.diag([-vx, vy])
            m_x = np.array([[q * vx**2 * (1 - 2 * a), 0.0],
                            [-q * vx * vy * at, q * vx * vy * (1 - a)]])  # fmt: skip
            m_v = np.array([[-2 * q * vx * a * (1 - a), 0.0],
                            [-q * vy * at * (1 - a), q * vx * at * (1 - a)]])  # fmt: skip
            b = r.blades
            du_dv = u_v + u_x @ np.linalg.solve(b * f_u @ u_x - m_x, m_v - b * f_u @ u_v)
            np.testing.assert_allclose(g[k, j], sign @ du_dv, atol=1e-5)
            checked += 1
    assert checked >= 15, checked
