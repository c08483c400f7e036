"""Multi-blade (Coleman) coordinates: the transformation and the frames it connects."""

import math

import numpy as np
import pytest

from wtvib.numerics import coleman


@pytest.mark.parametrize("blades", [3, 4, 5])
def test_coleman_transformation_is_invertible_and_its_derivatives_are_exact(blades):
    """Bir 2008 (NREL/CP-500-42553): B(ψ) is square and invertible for any azimuth; its
    derivative matches a central difference (1e-6)."""
    psi, h = 0.7, 1e-5
    b, d1, d2, names = coleman.coleman(blades, psi)
    assert b.shape == (blades, blades) and len(names) == blades
    assert abs(np.linalg.det(b)) > 1e-6
    plus, minus = coleman.coleman(blades, psi + h)[0], coleman.coleman(blades, psi - h)[0]
    assert d1 == pytest.approx((plus - minus) / (2 * h), abs=1e-6)
    assert d2 == pytest.approx((plus - 2 * b + minus) / h**2, abs=1e-3)
    assert names[0] == "collective" and ("alternating" in names) == (blades % 2 == 0)


def test_a_blade_load_fixed_in_space_reaches_the_cyclic_coordinates_at_1p():
    """Blade j at ψ_j sees a load cos ψ_j (wind shear, 1P in the rotating frame): its
    multi-blade coordinates are constant (0P) in the fixed frame — the frames' shift."""
    for psi in np.linspace(0, 2 * math.pi, 7):
        b, _, _, _ = coleman.coleman(3, float(psi))
        load = b[:, 1]  # cos ψ_j
        coords = np.linalg.solve(b, load)
        assert coords == pytest.approx([0.0, 1.0, 0.0], abs=1e-12)
