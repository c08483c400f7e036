"""Second-order expansions of positions: the jets agree with the exact rotation."""

import math

import numpy as np
import pytest

from wtvib.numerics import kinematics as kin


def test_small_rotation_generators_give_cross_products():
    v = np.array([1.0, 2.0, 3.0])
    for i, e in enumerate(np.eye(3)):
        assert kin.GENERATORS[i] @ v == pytest.approx(np.cross(e, v))
    assert kin.skew(v) @ np.array([0.0, 0.0, 1.0]) == pytest.approx(np.cross(v, [0, 0, 1]))


def test_rx_is_a_rotation_about_x():
    r = kin.rx(math.pi / 2)
    assert r @ np.array([0.0, 1.0, 0.0]) == pytest.approx([0.0, 0.0, 1.0])
    assert r.T @ r == pytest.approx(np.eye(3))


def test_the_nacelle_rotation_jet_is_exact_to_second_order():
    """R(θ) ≈ I + Σθᵢ Gᵢ + ½ΣΣ θᵢθⱼ (GᵢGⱼ + GⱼGᵢ)/2 for a small rotation vector θ: the jet
    applied to a point agrees with the exact rotation (Rodrigues) to O(|θ|³)."""
    from scipy.spatial.transform import Rotation

    n = 8
    jet = kin.nacelle_rotation(n).apply(
        kin.Jet(np.array([1.0, 0.5, 2.0]), np.zeros((3, n)), np.zeros((3, n, n)))
    )
    q = np.zeros(n)
    theta = np.array([1e-3, -2e-3, 1.5e-3])
    q[kin.TX : kin.TZ + 1] = theta
    approx = jet.c0 + jet.c1 @ q + 0.5 * np.einsum("aij,i,j->a", jet.c2, q, q)
    exact = Rotation.from_rotvec(theta).apply([1.0, 0.5, 2.0])
    assert np.abs(approx - exact).max() < 1e-8  # |θ|³ ≈ 3e-8 × O(1)
