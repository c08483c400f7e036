"""The periodic integrator and the two-bladed head's protocol (unit level; Mathieu's chart
and the multi-blade cross-check are in tests/validation/test_floquet.py)."""

import math

import numpy as np
import pytest
from scipy.linalg import expm

from wtvib import floquet


def test_constant_coefficients_give_the_matrix_exponential():
    a = np.array([[0.0, 1.0], [-9.0, -0.2]])
    res = floquet.stability(lambda t: a, 2.0, 50)
    assert np.sort(np.abs(res.multipliers)) == pytest.approx(
        np.sort(np.abs(np.linalg.eigvals(expm(2.0 * a))))
    )


def test_step_control_follows_the_fastest_mode():
    # two steps per period of the fastest mode, at least MIN_STEPS a revolution
    assert floquet.steps_for(0.1, 10.0) == floquet.MIN_STEPS
    assert floquet.steps_for(50.0, 10.0) == math.ceil(floquet.STEPS_PER_PERIOD * 500)
