"""The shared result types: curves over rotor speed, whirl labels, the JSON of a mode."""

import math

import numpy as np
import pytest

from wtvib.results import Mode, Sampled, Southwell, Whirl, by_frequency, ordinal


def test_southwell_curve_is_f0_at_standstill_and_grows_with_speed():
    # f² = f₀² + K·(Ω/2π)²: at Ω/2π = 1 Hz with K = 1.19, f = √(0.8² + 1.19) Hz
    curve = Southwell(0.8, 1.19)
    omega = np.array([0.0, 2 * math.pi])
    assert curve(omega) == pytest.approx([0.8, math.sqrt(0.64 + 1.19)])


def test_sampled_curve_interpolates_and_holds_beyond_its_range():
    curve = Sampled((0.0, 1.0), (1.0, 2.0))
    assert curve(np.array([0.5, 5.0])) == pytest.approx([1.5, 2.0])


def test_whirl_label_is_taken_at_the_nearest_sampled_speed():
    w = Whirl((0.0, 1.0, 2.0), ("cyclic", "backward", "backward"))
    assert w.at(0.1) == "cyclic" and w.at(1.6) == "backward"


def test_mode_json_and_judged():
    m = Mode("drivetrain.locked.1", "drivetrain", "locked", 0.62, 0.01, regimes=frozenset())
    assert not m.judged  # exists in no regime: reported only
    assert m.to_dict()["regimes"] == []
    shown = Mode("tower.fa1", "tower", "fa", 0.3, superseded_by="system.tower.fa1")
    assert not shown.judged and shown.to_dict()["superseded_by"] == "system.tower.fa1"
    assert Mode("tower.fa1", "tower", "fa", 0.3).judged


def test_modes_the_arithmetic_cannot_tell_apart_are_listed_by_id():
    """A symmetric floater's surge and sway, a round beam's flap and edge: equal but for
    rounding's last bits, which decided their order (and swapped it on another machine or
    solver) — listed by id; a difference in the eighth digit still orders by frequency."""
    sway = Mode("tower.platform.sway", "tower", "sway", 0.1 * (1 - 2e-16))
    surge = Mode("tower.platform.surge", "tower", "surge", 0.1 * (1 + 2e-16))
    assert sorted([sway, surge], key=by_frequency) == [surge, sway]
    sway = Mode("tower.platform.sway", "tower", "sway", 0.1 * (1 - 1e-8))
    assert sorted([surge, sway], key=by_frequency) == [sway, surge]


def test_ordinal():
    assert [ordinal(k) for k in (1, 2, 3, 4, 11, 12, 13, 21, 22)] == [
        "1st",
        "2nd",
        "3rd",
        "4th",
        "11th",
        "12th",
        "13th",
        "21st",
        "22nd",
    ]
