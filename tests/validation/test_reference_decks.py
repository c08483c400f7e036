"""Catalogue numbers cross-checked against the public reference decks in ../shared."""

import re

import pytest

from tests.conftest import TURBINES
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


def test_openfast_deck_set_gives_the_operating_range_from_rosco(shared):
    """The .fst names ServoDyn, which names ROSCO's DISCON.IN: VS_MinOMSpd
    34.64286 and VS_RefSpd 122.90967 rad/s (generator) over WE_GearboxRatio 97 are
    3.41–12.1 rpm at the rotor (DISCON.IN of ../shared/reference/NREL5MW)."""
    from wtvib import importers

    for name in ("NREL-5MW.fst", "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"):
        s = importers.load(shared / "reference" / "NREL5MW" / name)
        (low, high), *_ = s.rotor.speed.steady_rpm
        assert (low, high) == (pytest.approx(3.4105, abs=1e-3), pytest.approx(12.1, abs=1e-3))
        assert not s.warnings
        assert any("DISCON.IN" in a for a in s.assumptions)


def test_a_deck_without_an_operating_range_says_so_loudly(shared):
    from typer.testing import CliRunner

    from wtvib.cli import app

    deck = shared / "reference" / "WindPACT1.5" / "Test13.fst"  # simple VS: no lowest speed
    result = CliRunner().invoke(app, ["check", str(deck), "--no-plot"])
    assert result.exit_code in (0, 1)
    assert "names no" in result.stdout  # the headline
    assert "warning: rotor.speed: ServoDyn's simple variable-speed law names no lowest speed" in (
        result.stderr
    )
    assert "--rpm" in result.stderr
    ok = CliRunner().invoke(app, ["check", str(deck), "--no-plot", "--rpm", "11:20.5"])
    assert "names no lowest" not in ok.stderr
