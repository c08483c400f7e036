"""Given modes: spec entries (a number or a mapping) become modes, sorted by frequency."""

from wtvib.spec import ModeSpec
from wtvib.subsystems.given import given_modes


def test_numbers_and_mappings_become_modes_in_frequency_order():
    entries = {
        "ss1": 0.42,
        "fa1": ModeSpec(frequency_hz=0.40, damping_ratio=0.02),
    }
    modes = given_modes("tower", entries, lambda name: f"tower {name}")
    assert [m.id for m in modes] == ["tower.fa1", "tower.ss1"]
    assert modes[0].damping_ratio == 0.02 and modes[1].damping_ratio is None
    assert modes[1].description == "tower ss1" and modes[0].origin == "given"
