"""Design answers at unit level: the window documents and targets (the hand-computed window
edges and sizing are in tests/validation/test_design.py)."""

import pytest

from wtvib import audit, design, spec


def windows(write_spec, **parts):  # type: ignore[no-untyped-def]
    s = spec.load(write_spec(**parts))
    r = audit.run(s)
    return s, r, design.all_windows(s, r.modes, r.rule)


def test_windows_document_names_its_schema_and_rule(write_spec):
    s, r, found = windows(write_spec, blades=2, speed="fixed_rpm: 30", modes="fa1: 0.75")
    doc = design.windows_document(s, found, r.rule)
    assert doc["schema"] == design.WINDOWS_SCHEMA and doc["rule"] == r.rule.label
    (tower,) = doc["subsystems"]
    assert tower["modes"][0]["id"] == "tower.fa1" and tower["modes"][0]["window"] == "soft"


def test_window_goal_is_the_middle_of_a_closed_window(write_spec):
    # 30 rpm, two blades: soft window (0.55, 0.9) Hz (tests/validation/test_design.py)
    _, _, found = windows(write_spec, blades=2, speed="fixed_rpm: 30", modes="fa1: 0.75")
    assert design.window_goal(found, "soft") == pytest.approx(0.5 * (0.55 + 0.9))
    with pytest.raises(design.DesignError, match="no tower mode"):
        design.window_goal([], "soft")
