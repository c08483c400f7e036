"""The nacelle as the tower head less its rotor (parallel-axis theorem)."""

import numpy as np
import pytest

from wtvib.errors import SpecError
from wtvib.numerics.rigid import nacelle
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
    from wtvib.numerics.rigid import rotor_points

    pts = rotor_points(2.0, np.array([0.0, 40.0]), np.array([100.0, 100.0]))
    assert pts.mass.sum() == pytest.approx(4000.0)
    assert pts.polar() == pytest.approx(100 * (42**3 - 2**3) / 3)


def test_the_nacelle_left_when_a_rotor_of_point_masses_is_taken_out():
    """A head built by hand: a nacelle (4,000 kg, CM 1.5 m downwind and 2 m up, inertias
    3,000/5,000/4,000 kg·m² about its CM) and three 100 kg point blades 20 m from an apex 3 m
    upwind and 2.5 m up, in the rotor plane (shaft along x). The head's mass, CM and
    inertias about its CM are summed here by the parallel-axis theorem; taking the rotor
    (mass, apex, J_p) out must give the nacelle back — which holds only if the rotor's own
    inertia about a diameter is J_p/2 and the offsets are dz² (roll), dx² + dz² (pitch) and
    dx² (yaw)."""
    m_nac, c_nac, i_nac = 4000.0, np.array([1.5, 0.0, 2.0]), np.array([3000.0, 5000.0, 4000.0])
    apex, m_blade, r = np.array([-3.0, 0.0, 2.5]), 100.0, 20.0
    psi = np.radians([0.0, 120.0, 240.0]) + 0.3
    blades = [apex + r * np.array([0.0, np.sin(p), np.cos(p)]) for p in psi]
    masses = [m_nac] + [m_blade] * 3
    m = sum(masses)
    cm = (m_nac * c_nac + sum(m_blade * b for b in blades)) / m

    def about_cm(point: np.ndarray, mass: float) -> np.ndarray:  # roll, pitch, yaw
        d = point - cm
        return mass * np.array(
            [d[1] ** 2 + d[2] ** 2, d[0] ** 2 + d[2] ** 2, d[0] ** 2 + d[1] ** 2]
        )

    inertia = i_nac + about_cm(c_nac, m_nac) + sum(about_cm(b, m_blade) for b in blades)
    head = TowerHead(
        mass_kg=m,
        cm_downwind_m=float(cm[0]),
        cm_above_top_m=float(cm[2]),
        inertia_roll_kgm2=float(inertia[0]),
        inertia_pitch_kgm2=float(inertia[1]),
        inertia_yaw_kgm2=float(inertia[2]),
    )
    part = nacelle(head, apex, m_rotor=3 * m_blade, j_polar=3 * m_blade * r**2)
    assert part.mass == pytest.approx(m_nac)
    assert part.c == pytest.approx(c_nac)
    assert part.inertia == pytest.approx(i_nac, rel=1e-9)
