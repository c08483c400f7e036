"""Excitations: rotor harmonics with their energy class, the operating range in rad/s."""

import math

import pytest

from tests.conftest import spec_text
from wtvib import spec
from wtvib.audit import all_lines
from wtvib.judge import excitation
from wtvib.subsystems import drivetrain


def test_harmonic_energy_classes(write_spec):
    # Hau ch. 7.1/7.2.2/7.5.2: 1P and N_b·P dominant, between them secondary, above minor
    assert [excitation.harmonic_energy(k, 3) for k in (1, 2, 3, 4)] == [
        "dominant",
        "secondary",
        "dominant",
        "minor",
    ]
    lines = excitation.rotor_harmonics(2, 1)  # N_b·P is always included
    assert [e.id for e in lines] == ["1P", "2P"]


def test_lines_are_straight_through_the_origin():
    e = excitation.rotor_harmonics(3, 3)[2]
    omega = 12.1 * math.pi / 30
    assert float(e.frequency_hz(omega)) == pytest.approx(3 * 12.1 / 60)


def test_operating_range_in_rad_s(write_spec):
    s = spec.load(write_spec(speed="min_rpm: 6.9\nmax_rpm: 12.1"))
    op = excitation.operating_range(s.rotor.speed)
    assert op.lowest == pytest.approx(6.9 * math.pi / 30)
    assert op.highest == pytest.approx(12.1 * math.pi / 30)
    assert op.overspeed == pytest.approx(1.15 * op.highest)  # the default overspeed factor
    assert op.variable and op.dwell == pytest.approx((op.highest,))


def test_gear_mesh_line_acts_on_the_drive_train_only(write_spec):
    extra = """drivetrain:
  gear_stages: [{name: stage2, teeth: 19, shaft_speed_ratio: 27}]
"""
    s = spec.load(write_spec(spec_text() + extra, name="g.yaml"))
    (mesh,) = drivetrain.gear_mesh(s)
    assert mesh.order == 19 * 27 and mesh.acts_on("drivetrain") and not mesh.acts_on("tower")


def test_the_high_speed_shaft_imbalance_is_a_minor_line_at_the_generator_speed(write_spec):
    """Hau 7.3.4: the rotating parts' mass imbalance — a line at gear ratio × 1P on the
    drive train only, minor (its torque is the eccentric mass's gravity torque); none where
    no gear ratio is given or the generator turns with the rotor."""
    geared = spec.load(write_spec(spec_text() + "drivetrain: {gear_ratio: 50}\n", name="h.yaml"))
    (line,) = drivetrain.shaft_imbalance(geared)
    assert line.order == 50.0 and line.energy == "minor"
    assert line.acts_on("drivetrain") and not line.acts_on("tower")
    assert line in all_lines(geared)  # the drive train's declaration gives it to the audit
    direct = spec.load(write_spec(spec_text() + "drivetrain: {gear_ratio: 1}\n", name="d.yaml"))
    assert drivetrain.shaft_imbalance(direct) == []
    assert drivetrain.shaft_imbalance(spec.load(write_spec())) == []
