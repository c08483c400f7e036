"""The tower head as a rigid body on a (nearly) massless cantilever: its downwind offset x
in the fore-aft plane and in yaw, against the two-degree-of-freedom and single-spring
oracles written out here (Przemieniecki ch. 5: the clamped cantilever's tip stiffness
EI/L³·[[12, −6L], [−6L, 4L²]] in (u, u′); the head's mass matrix [[M, 0], [0, I + M·x²]]
with its CM at the top: a top rotation θ lifts a mass x downwind by x·θ). The tower weighs
6 kg against the head's 100 t: its own mass and the elements move them by 10⁻⁴ at most."""

import math

import numpy as np
import pytest

from wtvib.spec import from_data
from wtvib.subsystems import tower

L, D, T, E, G = 50.0, 4.0, 0.02, 2.1e11, 8.1e10
M, X, I_PITCH, I_ROLL, I_YAW = 1.0e5, 5.0, 2.0e6, 1.5e6, 1.0e6
SECOND = math.pi / 64 * (D**4 - (D - 2 * T) ** 4)  # second moment of area [m⁴]


def _modes(downwind: float) -> dict[str, float]:
    data = {
        "wtvib": 1,
        "turbine": {"name": "head on a light cantilever"},
        "rotor": {"blades": 3, "orientation": "upwind", "hub": "rigid", "speed": {"fixed_rpm": 20}},
        "tower": {
            "height_m": L,
            "gravity": False,
            "sections": {
                "height_m": [0, L],
                "outer_diameter_m": [D, D],
                "wall_thickness_m": [T, T],
            },
            "material": {"youngs_modulus_pa": E, "shear_modulus_pa": G, "density_kg_m3": 1.0},
        },
        "tower_head": {
            "mass_kg": M,
            "cm_above_top_m": 0.0,
            "cm_downwind_m": downwind,
            "inertia_pitch_kgm2": I_PITCH,
            "inertia_roll_kgm2": I_ROLL,
            "inertia_yaw_kgm2": I_YAW,
        },
    }
    return {m.id: m.frequency_hz for m in tower.structural_modes(from_data(data))}


def _two_dof(inertia: float) -> np.ndarray:
    ei = E * SECOND
    k = ei / L**3 * np.array([[12, -6 * L], [-6 * L, 4 * L**2]])
    m = np.diag([M, inertia])
    return np.sort(np.sqrt(np.linalg.eigvals(np.linalg.solve(m, k)).real)) / (2 * math.pi)


@pytest.mark.parametrize("downwind", [0.0, X])
def test_the_heads_downwind_offset_in_bending_and_yaw(downwind: float) -> None:
    modes = _modes(downwind)
    fa = _two_dof(I_PITCH + M * downwind**2)
    ss = _two_dof(I_ROLL)  # the offset does not move in side-side rolling
    assert [modes["tower.fa1"], modes["tower.fa2"]] == pytest.approx(fa, rel=5e-4)
    assert [modes["tower.ss1"], modes["tower.ss2"]] == pytest.approx(ss, rel=5e-4)
    polar = 2 * SECOND  # a thin tube's J
    yaw = math.sqrt(G * polar / L / (I_YAW + M * downwind**2)) / (2 * math.pi)
    assert modes["tower.tor1"] == pytest.approx(yaw, rel=1e-4)
