"""Catalogue numbers cross-checked against the public reference decks in ../shared."""

import re

from conftest import TURBINES
from wtvib import spec


def deck_value(path, key: str) -> float:
    for line in path.read_text().splitlines():
        m = re.match(rf"^\s*(\S+)\s+{key}\s", line)
        if m:
            return float(m.group(1))
    raise AssertionError(f"{key} not in {path}")


def test_nrel5mw_spec_matches_its_elastodyn_deck(shared):
    # NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat (NREL/ROSCO, see SOURCES.txt)
    deck = shared / "reference/NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"
    s = spec.load(TURBINES / "nrel-5mw.yaml")
    assert deck_value(deck, "GBRatio") == s.drivetrain.gear_ratio == 97
    assert deck_value(deck, "NumBl") == s.rotor.blades == 3
    assert deck_value(deck, "RotSpeed") == s.rotor.speed.rated_rpm == 12.1
    assert deck_value(deck, "TowerHt") == s.tower.height_m == 87.6
