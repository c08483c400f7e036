"""Stall-induced vibration: the quasi-steady section damping c(ψ) (DOMAIN.md §3)."""

import math

import numpy as np
import pytest

from wtvib.aero import stall


def test_section_damping_limits_of_the_formula():
    """c(ψ) = ½ρcW[2C_D cos²ψ + (C_L + C_D′) sinψ cosψ + (C_L′ + C_D) sin²ψ]: moving along
    the wind (ψ = 0) only drag damps, ρcW·C_D; across it (ψ = 90°) lift slope plus drag."""
    rho, c, w = 1.225, 2.0, 60.0
    args = dict(cl=1.0, cd=0.02, dcl=2 * math.pi, dcd=0.1)
    along = stall.aero_damping_coefficient(rho, c, w, 0.0, **args)
    across = stall.aero_damping_coefficient(rho, c, w, math.pi / 2, **args)
    assert along == pytest.approx(rho * c * w * 0.02)
    assert across == pytest.approx(0.5 * rho * c * w * (2 * math.pi + 0.02))
    # past stall (C_L′ < 0) the flapwise term turns negative: the instability's mechanism
    assert stall.aero_damping_coefficient(rho, c, w, math.pi / 2, 1.0, 0.3, -2.0, 0.5) < 0


def test_built_in_polar_is_thin_aerofoil_then_flat_plate():
    cl, cd = stall.builtin_polar(np.array([2.0, 90.0]))
    assert cl[0] == pytest.approx(2 * math.pi * math.radians(2.0), rel=1e-6)
    assert cl[1] == pytest.approx(0.0, abs=1e-9) and cd[1] == pytest.approx(2.0)  # flat plate


def test_the_tip_sees_the_wind_slowed_by_the_induction():
    """The stall rotor without its BEM block, with an axial induction of 1/3: at each point
    the tip's angle of attack is the velocity triangle's, atan(V·(1 − a)/(Ω·R)) less the
    tip's twist and pitch (Hau 7.2.3; Burton et al., Wind Energy Handbook, §3.5), written
    out here."""
    from tests.conftest import TURBINES
    from wtvib import audit, spec
    from wtvib.units import rpm_to_rad_s

    s = spec.load(TURBINES / "stall-rotor-1mw.yaml")
    ae = s.blade.aeroelastic
    # a tip twisted by 2° (the stall rotor's is 0), so that the twist's sign is in play
    twist = [*ae.planform.twist_deg[:-1], 2.0]
    ae = ae.model_copy(
        update={
            "axial_induction": 1 / 3,
            "planform": ae.planform.model_copy(update={"twist_deg": twist}),
        }
    )
    blade = s.blade.model_copy(update={"aeroelastic": ae})
    s = s.model_copy(update={"blade": blade, "aerodynamics": None})  # the strip-theory path
    modes = {m.id: m for m in audit.run(s).modes}
    radius = s.turbine.rotor_diameter_m / 2
    r_plan, _, twist = stall._planform(s, radius)
    theta_tip = float(np.interp(radius, r_plan, twist)) + ae.pitch_deg
    assert theta_tip == pytest.approx(2.0 + ae.pitch_deg)
    points = stall.damping_curve(s, modes["blade.edge1"], radius)
    assert points
    for p in points[:: max(1, len(points) // 5)]:
        omega = float(rpm_to_rad_s(p.rpm))
        expected = math.degrees(math.atan2(p.wind * (2 / 3), omega * radius)) - theta_tip
        assert p.alpha_tip_deg == pytest.approx(expected, abs=1e-9)


def test_a_variable_speed_rotor_follows_its_tip_speed_ratio_between_its_speed_limits():
    """The strip-theory operating points of a variable-speed rotor: n = 60·λV/(2πR),
    held at the lowest steady speed below and at rated above (by hand: the stall rotor's
    planform as a variable-speed rotor of 10–20 rpm at λ 7)."""
    from tests.conftest import TURBINES
    from wtvib import spec

    s = spec.load(TURBINES / "stall-rotor-1mw.yaml")
    speed = s.rotor.speed.model_copy(update={"fixed_rpm": None, "min_rpm": 10.0, "max_rpm": 20.0})
    ae = s.blade.aeroelastic.model_copy(update={"tip_speed_ratio": 7.0})
    s = s.model_copy(
        update={
            "rotor": s.rotor.model_copy(update={"speed": speed}),
            "blade": s.blade.model_copy(update={"aeroelastic": ae}),
        }
    )
    radius = s.turbine.rotor_diameter_m / 2
    points = stall.operating_points(s, radius)
    assert points
    for wind, rpm in points:
        assert rpm == pytest.approx(min(max(60 * 7.0 * wind / (2 * math.pi * radius), 10.0), 20.0))
    assert {rpm for _, rpm in points} >= {10.0, 20.0}  # both limits reached
