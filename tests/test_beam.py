"""Beam elements: the Gauss-integrated matrices against the textbook closed forms."""

import numpy as np
import pytest

from wtvib.numerics import beam

from . import oracles


@pytest.mark.parametrize("length", [0.5, 2.0, 7.3])
def test_gauss_elements_equal_closed_forms_for_constant_properties(length):
    # Przemieniecki ch. 5 and 11: closed-form stiffness, consistent mass, geometric stiffness
    nodes = np.array([0.0, length])
    ones = np.ones((1, 4))
    k, geo, m = beam.bending_elements(nodes, 3.0 * ones, 2.0 * ones, 5.0 * ones)
    assert k[0] == pytest.approx(oracles.bending_stiffness(3.0, length))
    assert m[0] == pytest.approx(oracles.bending_mass(2.0, length))
    assert geo[0] == pytest.approx(oracles.geometric_stiffness(5.0, length))
    kt, mt = beam.torsion_elements(nodes, 4.0 * ones, 1.5 * ones)
    assert kt[0] == pytest.approx(oracles.torsion_stiffness(4.0, length))
    assert mt[0] == pytest.approx(oracles.torsion_mass(1.5, length))


def test_linear_taper_is_integrated_exactly():
    # ∫ EI(x)·B'B over an element with EI linear equals the average of two constant-EI
    # elements weighted by the hat functions: check the total ∫EI·(w'')² for w = x²/2 (w''=1)
    nodes = np.array([0.0, 2.0])
    x, _ = beam.gauss_points(nodes)
    ei = 1.0 + x  # from 1 to 3
    k, _, _ = beam.bending_elements(nodes, ei, np.ones_like(x))
    w = np.array([0.0, 0.0, 2.0, 2.0])  # w = x²/2: w(2) = 2, w'(2) = 2
    assert w @ k[0] @ w == pytest.approx(4.0)  # ∫0² (1 + x)·1 dx = 4


def test_mesh_merges_near_duplicate_stations():
    nodes = beam.mesh(np.array([0.0, 13.0, 13.001, 100.0]), 10)
    assert np.min(np.diff(nodes)) > 1e-4 * 100
    assert 13.0 in nodes or 13.001 in nodes


def test_the_timoshenko_interpolation_is_hermites_without_shear_and_shears_evenly():
    """numerics.beam.timoshenko: at φ = 0 the Hermite cubics (deflection, slope) with the
    rotation equal to the slope; at any φ the shear strain dN/dx − Θ constant along each
    element (the interdependent interpolation's defining property), the nodal values the
    dofs (N = δ at the ends is checked through the end rows), and the moment equation of
    a uniform element, EI·Θ″ = κGA·(N′ − Θ) with φ = 12·EI/(κGA·L²), satisfied exactly."""
    nodes = np.array([0.0, 2.0, 5.0, 5.5])
    lengths = np.diff(nodes)
    b = beam.basis(nodes)
    n, n1, rot, rot1 = beam.timoshenko(lengths, np.zeros(3))
    for got, want in ((n, b.n), (n1, b.d1), (rot, b.d1), (rot1, b.d2)):
        np.testing.assert_allclose(got, want, rtol=0, atol=1e-12)
    phi = np.array([0.05, 0.8, 3.0])
    n, n1, rot, rot1 = beam.timoshenko(lengths, phi)
    shear = n1 - rot
    np.testing.assert_allclose(np.ptp(shear, axis=1), 0.0, atol=1e-12)
    # Θ is quadratic in x: its second derivative is the slope of Θ′ between Gauss points
    x = beam.GAUSS_XI * lengths[:, None]
    rot2 = (rot1[:, 1] - rot1[:, 0]) / (x[:, 1] - x[:, 0])[:, None]
    ei = 7.0
    ga = 12 * ei / (phi * lengths**2)
    np.testing.assert_allclose(ei * rot2, -ga[:, None] * shear[:, 0], rtol=1e-10)
