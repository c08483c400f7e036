"""Stall-induced vibration: the quasi-steady section damping c(ψ) (DOMAIN.md §3)."""

import math

import numpy as np
import pytest

from wtvib import stall


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
