"""The two-bladed rotor on the tower head: its protocol and the stability map it returns
(Mathieu and the minimal yaw model are in tests/validation/test_floquet.py)."""

import numpy as np

from tests.conftest import TURBINES
from wtvib import audit, rotor, spec


def test_three_blades_need_no_floquet_analysis(write_spec):
    r = audit.run(spec.load(write_spec(blades=3)))
    c = next(c for c in r.checks if c.id == "rotor.floquet")
    assert c.status == "info" and "time-invariant" in c.message
    assert "rotor" not in r.results  # no map to draw


def test_the_map_is_a_result_for_the_figure():
    r = audit.run(spec.load(TURBINES / "aeroman.yaml"))
    smap = r.results["rotor"]["map"]
    assert len(smap.speeds_rpm) == len(smap.largest) and np.all(np.isfinite(smap.largest))


def test_rotor_has_no_modes_of_its_own_and_judges_the_heads(write_spec):
    s = spec.load(write_spec(blades=2))
    assert rotor.build_modes(s, {}) == []
    assert rotor.NAME == "rotor"
