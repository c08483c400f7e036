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
    r = audit.run(importers.load(deck, rpm=(6.9, 12.1)))
    assert any(a.startswith("Blade modes computed") for a in r.assumptions)
    assert {m.origin for m in r.modes if m.subsystem == "blade"} == {"computed"}
