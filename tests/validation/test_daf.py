"""Dynamic amplification factor against its analytic values (DOMAIN.md §5)."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from wtvib.rules import dynamic_amplification


def test_daf_at_resonance_is_one_over_two_zeta():
    # DAF(η = 1) = 1/(2ζ): ζ = 0.01 gives 50 (DOMAIN.md §5; Clough & Penzien eq. 3-21)
    assert dynamic_amplification(1.0, 0.01) == pytest.approx(50.0)


def test_daf_at_ninety_percent():
    # 1/sqrt((1-0.81)^2 + (2·0.01·0.9)^2) = 1/sqrt(0.0361 + 0.000324) = 5.2396 (DOMAIN.md §5)
    assert dynamic_amplification(0.9, 0.01) == pytest.approx(5.2396, abs=5e-4)


def test_wka60_factor_four_needs_twelve_and_a_half_percent_damping():
    # Hau Fig. 7.27 reports an amplification of 4 at resonance: 1/(2·0.125) = 4
    assert dynamic_amplification(1.0, 0.125) == pytest.approx(4.0)


def test_static_limit_is_one():
    assert dynamic_amplification(0.0, 0.05) == pytest.approx(1.0)


def test_undamped_resonance_is_infinite():
    assert np.isinf(dynamic_amplification(1.0, 0.0))


@given(st.floats(0.001, 0.5), st.floats(0.0, 0.6))
def test_more_damping_never_amplifies_more(zeta, eta):
    assert dynamic_amplification(eta, zeta * 1.5) <= dynamic_amplification(eta, zeta) + 1e-12
