"""Invariants of the structural models: properties that must hold for any input.

* scaling every stiffness by s scales every frequency by √s (K φ = ω² M φ);
* adding mass never raises the first frequency (Rayleigh's principle);
* (the reduction to another drive-train shaft and the monotone tower class are tested in
  tests/validation/test_drivetrain.py and tests/test_tower.py).
"""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from wtvib import spec
from wtvib.numerics import modal
from wtvib.subsystems import drivetrain, tower

floats = st.floats


def tower_spec(ei: float, mass: float, head: float) -> tuple[spec.Tower, spec.TowerHead]:
    t = spec.Tower(
        distributed={
            "height_m": [0, 40, 80],
            "mass_per_length_kg_m": [mass, 0.8 * mass, 0.6 * mass],
            "ei_fa_nm2": [ei, 0.6 * ei, 0.3 * ei],
            "ei_ss_nm2": [ei, 0.6 * ei, 0.3 * ei],
        },
        gravity=False,
    )
    return t, spec.TowerHead(mass_kg=head, cm_above_top_m=1.5, inertia_pitch_kgm2=head * 4)


def first_two(t: spec.Tower, h: spec.TowerHead) -> list[float]:
    return list(
        tower.bending_modes(tower.discretise(t), h, [], t.foundation, "fa", False).frequency_hz
    )


@settings(max_examples=40, deadline=None)
@given(floats(1e9, 1e12), floats(200, 8000), floats(1e3, 5e5), floats(0.1, 10))
def test_scaling_stiffness_scales_tower_frequencies_by_root(ei, mass, head, s):
    base = first_two(*tower_spec(ei, mass, head))
    scaled = first_two(*tower_spec(ei * s, mass, head))
    assert scaled == pytest.approx([f * math.sqrt(s) for f in base], rel=1e-7)


@settings(max_examples=40, deadline=None)
@given(floats(1e9, 1e12), floats(200, 8000), floats(1e3, 5e5), floats(0.0, 5e5))
def test_adding_head_mass_never_raises_the_first_tower_frequency(ei, mass, head, extra):
    light = first_two(*tower_spec(ei, mass, head))[0]
    heavy = first_two(*tower_spec(ei, mass, head + extra))[0]
    assert heavy <= light * (1 + 1e-9)  # rounding of the eigen-solver: ~1e-11 relative


def chain(j_blades: float, j_gen: float, k: float) -> spec.Spec:
    return spec.from_data(
        {
            "wtvib": 1,
            "turbine": {"name": "x"},
            "rotor": {
                "blades": 3,
                "orientation": "upwind",
                "hub": "rigid",
                "speed": {"fixed_rpm": 15},
            },
            "drivetrain": {
                "chain": [
                    {"name": "blades", "inertia_kgm2": j_blades},
                    {"name": "hub", "inertia_kgm2": 0.05 * j_blades},
                    {"name": "generator", "inertia_kgm2": j_gen, "speed_ratio": 90},
                ],
                "shafts": [{"stiffness_nm_rad": 20 * k}, {"stiffness_nm_rad": k}],
            },
        }
    )


def locked(s: spec.Spec) -> list[float]:
    m, k, d = drivetrain.system(drivetrain.reduce(s), s, "locked")
    return list(modal.damped(k, m, d).frequency_hz)


@settings(max_examples=40, deadline=None)
@given(floats(1e4, 1e8), floats(1, 1e3), floats(1e6, 1e10), floats(0.1, 10))
def test_scaling_stiffness_scales_drive_train_frequencies_by_root(jb, jg, k, s):
    assert locked(chain(jb, jg, k * s)) == pytest.approx(
        [f * math.sqrt(s) for f in locked(chain(jb, jg, k))], rel=1e-7
    )


@settings(max_examples=40, deadline=None)
@given(floats(1e4, 1e8), floats(1, 1e3), floats(1e6, 1e10), floats(0.0, 1e8))
def test_adding_rotor_inertia_never_raises_the_first_drive_train_frequency(jb, jg, k, extra):
    assert locked(chain(jb + extra, jg, k))[0] <= locked(chain(jb, jg, k))[0] * (1 + 1e-9)
