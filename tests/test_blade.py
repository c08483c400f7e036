"""Blades: given modes stiffened by rotation (Southwell), the protocol's statements."""

import math

import numpy as np
import pytest

from tests.conftest import spec_text
from wtvib import audit, blade, spec
from wtvib.results import Southwell

GIVEN = """blade:
  modes: {flap1: 0.84, edge1: {frequency_hz: 1.35, southwell: 0.19}}
"""


def test_given_blade_modes_rise_with_speed_by_southwell(write_spec):
    s = spec.load(write_spec(spec_text() + GIVEN, name="b.yaml"))
    modes = {m.id: m for m in blade.build_modes(s, {})}
    flap = modes["blade.flap1"]
    assert isinstance(flap.curve, Southwell) and flap.curve.k == pytest.approx(1.19)  # default
    omega = 2 * math.pi * 0.5  # 30 rpm: Ω/2π = 0.5 Hz
    assert float(flap.frequency_at(np.array([omega]))[0]) == pytest.approx(
        math.sqrt(0.84**2 + 1.19 * 0.25)
    )
    assert modes["blade.edge1"].curve.k == pytest.approx(0.19)  # type: ignore[union-attr]


def test_blade_analysis_states_how_computed_modes_came_about(shared):
    from wtvib import importers

    deck = shared / "reference" / "NREL5MW" / "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"
    r = audit.run(importers.load(deck, importers.ReadOptions(rpm=(6.9, 12.1))))
    assert any(a.startswith("Blade modes computed") for a in r.assumptions)
    assert {m.origin for m in r.modes if m.subsystem == "blade"} == {"computed"}


def test_the_pitch_drive_softens_the_blade_s_torsion_by_the_closed_form():
    """A uniform blade (GJ, I_p, length L) on a root spring k_p, free at the tip: θ =
    cos β(L − x), and GJ·θ′(0) = k_p·θ(0) gives βL·tan βL = k_p·L/GJ, ω = β·√(GJ/I_p)
    (Hau 7.2.2; the clamped root is k_p → ∞, βL = π/2)."""
    from scipy.optimize import brentq

    from wtvib.spec.blade import BladeStructure

    gj, ip, length, kp = 5e7, 20.0, 40.0, 2.5e6
    base = {
        "span_m": [0.0, length],
        "mass_per_length_kg_m": [200.0, 200.0],
        "ei_flap_nm2": [1e9, 1e9],
        "ei_edge_nm2": [3e9, 3e9],
        "gj_nm2": [gj, gj],
        "torsional_inertia_kgm": [ip, ip],
    }
    c = (gj / ip) ** 0.5
    clamped = blade.torsion_frequency(BladeStructure.model_validate(base), elements=60)
    assert clamped == pytest.approx(np.pi / 2 / length * c / (2 * np.pi), rel=1e-3)
    sprung = blade.torsion_frequency(
        BladeStructure.model_validate(base | {"pitch_drive_nm_rad": kp}), elements=60
    )
    bl = brentq(lambda z: z * np.tan(z) - kp * length / gj, 1e-9, np.pi / 2 - 1e-9)
    assert sprung == pytest.approx(bl / length * c / (2 * np.pi), rel=1e-3)
    assert sprung < clamped
