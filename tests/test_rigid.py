"""The nacelle as the tower head less its rotor (parallel-axis theorem)."""

import numpy as np
import pytest

from wtvib.errors import SpecError
from wtvib.rigid import nacelle
from wtvib.spec import TowerHead


def test_the_nacelle_is_what_is_left_of_the_head():
    head = TowerHead(
        mass_kg=1000.0,
        cm_downwind_m=0.0,
        cm_above_top_m=0.0,
        inertia_roll_kgm2=5000.0,
        inertia_pitch_kgm2=5000.0,
        inertia_yaw_kgm2=5000.0,
    )
    apex = np.array([-2.0, 0.0, 0.0])
    part = nacelle(head, apex, m_rotor=200.0, j_polar=400.0)
    assert part.mass == pytest.approx(800.0)
    # the head's CM at 0: the nacelle's balances the rotor, 800·x = −200·(−2)
    assert part.c == pytest.approx([0.5, 0.0, 0.0])
    # yaw: 5000 = (J_p/2 + 200·2²) + (I_nac + 800·0.5²)
    assert part.inertia[2] == pytest.approx(5000 - 200 - 800 - 200)


def test_a_head_lighter_than_its_rotor_is_refused_with_the_field():
    head = TowerHead(mass_kg=100.0)
    with pytest.raises(SpecError) as err:
        nacelle(head, np.zeros(3), m_rotor=200.0, j_polar=0.0)
    assert err.value.path == "tower_head.mass_kg"


def test_rotor_points_weigh_a_uniform_blade_exactly():
    """A uniform blade of 100 kg/m over 40 m from a 2 m hub radius: mass 4,000 kg, polar
    inertia ∫m r² dr = 100·(42³ − 2³)/3 kg·m² — Gauss points integrate it exactly."""
    from wtvib.rigid import rotor_points

    pts = rotor_points(2.0, np.array([0.0, 40.0]), np.array([100.0, 100.0]))
    assert pts.mass.sum() == pytest.approx(4000.0)
    assert pts.polar() == pytest.approx(100 * (42**3 - 2**3) / 3)
