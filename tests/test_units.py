"""Unit conversions: rpm ↔ rad/s ↔ Hz (one place, STYLE.md habit 2)."""

import math

import numpy as np
import pytest

from wtvib import units


def test_rpm_and_rad_s_round_trip():
    rpm = np.array([0.0, 6.9, 12.1, 60.0])
    assert units.rad_s_to_rpm(units.rpm_to_rad_s(rpm)) == pytest.approx(rpm)
    assert float(units.rpm_to_rad_s(60.0)) == pytest.approx(2 * math.pi)  # 1 rev/s


def test_rotor_speed_to_1p():
    # 12.1 rpm is 1P = 12.1/60 Hz = 0.20167 Hz (the NREL 5-MW's rated 1P, Jonkman 2009)
    assert float(units.rad_s_to_hz(units.rpm_to_rad_s(12.1))) == pytest.approx(12.1 / 60)
