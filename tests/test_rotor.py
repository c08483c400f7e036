"""The two-bladed rotor on the tower head: its protocol and the stability map it returns
(Mathieu and the minimal yaw model are in tests/validation/test_floquet.py)."""

import numpy as np

from tests.conftest import TURBINES
from wtvib import audit, spec
from wtvib.subsystems import rotor


def test_three_blades_need_no_floquet_analysis(write_spec):
    r = audit.run(spec.load(write_spec(blades=3)))
    c = next(c for c in r.checks if c.id == "rotor.floquet")
    assert c.status == "info" and "time-invariant" in c.message
    assert "rotor" not in r.results  # no map to draw


def test_the_map_is_a_result_for_the_figure():
    r = audit.run(spec.load(TURBINES / "aeroman.yaml"))
    smap = r.result(rotor.NAME, rotor.RotorResults).map
    assert len(smap.speeds_rpm) == len(smap.largest) and np.all(np.isfinite(smap.largest))


def test_rotor_has_no_modes_of_its_own_and_judges_the_heads(write_spec):
    s = spec.load(write_spec(blades=2))
    assert rotor.build_modes(s, {}) == []
    assert rotor.NAME == "rotor"


def test_a_speed_that_shows_growth_is_integrated_again_on_finer_steps(monkeypatch):
    """MOD-0's head model with every speed taken as growing (GROWTH = −1): the map then
    holds, at every speed, |ρ|max integrated with four times the steps (the finest of
    floquet.REFINE) — the same, to rounding, as integrating with four times the steps in
    the first place."""
    s = spec.load(TURBINES / "mod-0.yaml")
    model, _ = rotor.head_model(s, audit.run(s).modes)
    assert model is not None
    w = np.linspace(2.0, 6.0, 5)
    monkeypatch.setattr(rotor, "GROWTH", -1.0)
    refined = rotor.stability_map(model, w)
    monkeypatch.setattr(rotor, "REFINE", ())
    real_steps = rotor.steps_for
    monkeypatch.setattr(rotor, "steps_for", lambda f, t: 4 * real_steps(f, t))
    monkeypatch.setattr(rotor, "MIN_STEPS", 4 * rotor.MIN_STEPS)
    monkeypatch.setattr(rotor, "MAX_STEPS", 4 * rotor.MAX_STEPS)
    direct = rotor.stability_map(model, w)
    np.testing.assert_allclose(refined, direct, rtol=1e-10)


def test_a_hub_a_model_does_not_have_is_said_where_it_is_modelled_otherwise(tmp_path):
    """MOD-2 (teetered) with its hub declared hinged: the tower-head Floquet model has no
    flap hinges, so it models the rotor hingeless — and its check says so, in the message
    and in the hub it reports, instead of calling a hingeless result "hinged". As declared
    (teetered), nothing of the kind."""
    text = (TURBINES / "mod-2.yaml").read_text()
    assert "hub: teetered" in text
    path = tmp_path / "mod-2-hinged.yaml"
    path.write_text(text.replace("hub: teetered", "hub: hinged"))
    for file, hub, note in (
        (path, "hingeless", True),
        (TURBINES / "mod-2.yaml", "teetered", False),
    ):
        report = audit.run(spec.load(file))
        check = next(c for c in report.checks if c.id == "rotor.floquet")
        assert check.numbers["hub"] == hub and check.message.startswith(hub)
        assert ("hinged hub modelled as hingeless" in check.message) is note
