"""The periodic integrator and the two-bladed head's protocol (unit level; Mathieu's chart
and the multi-blade cross-check are in tests/validation/test_floquet.py)."""

import math

import numpy as np
import pytest
from scipy.linalg import expm

from wtvib.numerics import floquet


def test_constant_coefficients_give_the_matrix_exponential():
    """With A constant the monodromy is exp(A·T): its multipliers by scipy's expm."""
    a = np.array([[0.0, 1.0], [-9.0, -0.2]])
    multipliers = np.linalg.eigvals(floquet.monodromy(lambda t: a, 2.0, 50))
    assert np.sort(np.abs(multipliers)) == pytest.approx(
        np.sort(np.abs(np.linalg.eigvals(expm(2.0 * a))))
    )


def test_step_control_follows_the_fastest_mode():
    # two steps per period of the fastest mode, at least MIN_STEPS a revolution
    assert floquet.steps_for(0.1, 10.0) == floquet.MIN_STEPS
    assert floquet.steps_for(50.0, 10.0) == math.ceil(floquet.STEPS_PER_PERIOD * 500)


def test_a_tower_mode_far_faster_than_the_rotor_is_said_not_analysed(tmp_path):
    """A 1e9 Hz tower on the two-bladed MOD-0 asked the Floquet sweep for ~1e10
    Magnus steps a revolution (an audit of minutes and gigabytes); speeds needing more than
    MAX_STEPS are now not analysed, and a rotor analysed at no operating speed is a warning
    saying so — not "stable"."""
    from tests.conftest import TURBINES
    from wtvib import audit, spec

    text = (TURBINES / "mod-0.yaml").read_text().replace("fa1: {value: 2.3,", "fa1: {value: 1.0e9,")
    assert "1.0e9" in text
    path = tmp_path / "fast.yaml"
    path.write_text(text)
    report = audit.run(spec.load(path))
    check = next(c for c in report.checks if c.id == "rotor.floquet")
    assert check.status == "warn" and "not analysed at any operating speed" in check.message
    assert f"{floquet.MAX_STEPS:,} integration steps" in check.message
