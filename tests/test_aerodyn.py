"""AeroDyn 15 inputs of an OpenFAST deck set → the spec's aerodynamics block; a broken input
is one line naming file and line, never a traceback."""

import shutil
from pathlib import Path

import pytest

from wtvib.errors import SpecError
from wtvib.importers import load


@pytest.fixture
def deck(shared: Path, tmp_path: Path) -> Path:
    """A copy of the NREL 5-MW deck set to break."""
    dst = tmp_path / "NREL5MW"
    shutil.copytree(shared / "reference/NREL5MW", dst)
    return dst


def test_the_nrel_deck_set_gives_its_aerodynamics(shared: Path):
    spec = load(shared / "reference/NREL5MW/NREL-5MW.fst")
    aero = spec.aerodynamics
    assert aero is not None
    st = aero.stations
    assert len(st.radius_m) == 19  # NumBlNds (the 61.5 m row after the table is not read)
    assert st.radius_m[-1] == pytest.approx(1.5 + 61.4999)
    assert st.radius_m[0] == pytest.approx(1.5)  # HubRad + BlSpn
    assert st.chord_m[0] == pytest.approx(3.542) and st.twist_deg[0] == pytest.approx(13.308)
    assert st.airfoil[0] == "Cylinder1" and st.airfoil[-1] == "NACA64_A17"
    assert aero.control.tip_speed_ratio == pytest.approx(7.5)  # VS_TSRopt
    assert aero.control.generator_efficiency == pytest.approx(0.944)  # GenEff
    assert aero.control.rated_power_kw == pytest.approx(5000.0)  # VS_RtPwr
    assert aero.air_density_kg_m3 == pytest.approx(1.225)
    # where each controller value came from, as the audit states it
    told = [a for a in spec.assumptions if "From the controller (DISCON.IN)" in a]
    assert len(told) == 1 and "VS_TSRopt 7.5" in told[0] and "VS_RtPwr 5000 kW" in told[0]


def _edit(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert old in text
    path.write_text(text.replace(old, new, 1))


def test_a_last_node_at_a_many_digit_tip_radius_is_the_rotor_s_tip(deck: Path):
    """WISDEM writes TipRad to 17 digits and AeroDyn's last node at TipRad − HubRad
    (NREL/BAR_Designs' BAR_USC: TipRad 102.82618258545716): the rotor's diameter, twice
    TipRad, was rounded to six digits — 205.652 — and the deck refused ("the last station
    at 102.826 m lies beyond the rotor radius 102.826 m"). Twice TipRad keeps ten digits."""
    _edit(deck / "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat", "         63   TipRad",
          "  63.000182585   TipRad")  # fmt: skip
    _edit(deck / "NRELOffshrBsline5MW_AeroDyn_blade.dat", "6.1499900E+01 -3.2815226E-04",
          "6.1500182585E+01 -3.2815226E-04")  # fmt: skip
    spec = load(deck / "NREL-5MW.fst")
    # ten digits, as every number read from a deck (5e-10 at most)
    assert spec.turbine.rotor_diameter_m == pytest.approx(2 * 63.000182585, rel=1e-9)
    assert spec.aerodynamics is not None
    assert spec.aerodynamics.stations.radius_m[-1] == pytest.approx(63.000182585, rel=1e-12)


@pytest.mark.parametrize(
    ("file", "old", "new", "said"),
    [
        (
            "NRELOffshrBsline5MW_AeroDyn_blade.dat",
            "4.6520000E+00        4",
            "4.65x        4",
            "not a finite number",
        ),
        (
            "NRELOffshrBsline5MW_AeroDyn_blade.dat",
            "1.4190000E+00        8\n\n",
            "1.4190000E+00        9\n\n",
            "BlAFID 9 exceeds NumAFfiles 8",
        ),
        ("NRELOffshrBsline5MW_AeroDyn_blade.dat", "19   NumBlNds", "40   NumBlNds", "ends after"),
        (
            "NRELOffshrBsline5MW_Onshore_AeroDyn15.dat",
            '"Airfoils/DU25_A17.dat"',
            '"Airfoils/none.dat"',
            "does not exist",
        ),
        ("Airfoils/DU25_A17.dat", "140   NumAlf", "14.5   NumAlf", "whole number"),
        ("NRELOffshrBsline5MW_Onshore_ServoDyn.dat", "94.4   GenEff", "0   GenEff", "GenEff"),
    ],
)
def test_broken_aerodyn_inputs_name_file_and_line(
    deck: Path, file: str, old: str, new: str, said: str
):
    _edit(deck / file, old, new)
    with pytest.raises(SpecError) as err:
        load(deck / "NREL-5MW.fst")
    assert said in str(err.value)
    assert err.value.source is not None


def test_no_aerodyn_no_aerodynamics(deck: Path):
    _edit(deck / "NREL-5MW.fst", "2   CompAero", "0   CompAero")
    assert load(deck / "NREL-5MW.fst").aerodynamics is None


@pytest.mark.parametrize(
    ("mod", "shed", "stall", "time"),
    [("3", True, True, 3 + 1.7), ("0", False, False, 3.0), ("6", False, True, 3.0)],
)
def test_the_unsteady_aerofoil_follows_the_decks_model(shared, tmp_path, mod, shed, stall, time):
    """AeroDyn's UA_Mod decides how wtvib lags the lift. The shed wake: the ROSCO NREL-5MW
    deck's Minnema/Pierce Beddoes–Leishman model (3) lags it, quasi-steady (0) and Øye's
    model (6), which lags only the separation point, do not. The separation point (dynamic
    stall): the Beddoes–Leishman family (2–5) lags it behind its pressure lag, T_f0 + T_p of
    each aerofoil's first table (the NREL 5-MW's 3 + 1.7, one file saying "Default" for
    both: AeroDyn's defaults), Øye's by T_f0 alone; quasi-steady, not at all."""
    from tests.conftest import edited_reference
    from wtvib import importers

    folder = shared / "reference/NREL5MW"
    if mod != "3":
        folder = edited_reference(
            shared,
            tmp_path,
            "NREL5MW",
            "NRELOffshrBsline5MW_Onshore_AeroDyn15.dat",
            "3                      UA_Mod",
            f"{mod}                      UA_Mod",
        )
    aero = importers.load(folder / "NREL-5MW.fst").aerodynamics
    assert aero is not None
    assert (aero.shed_wake, aero.dynamic_stall) == (shed, stall)
    assert {a.separation_time for a in aero.airfoils.values()} == {time}


@pytest.mark.parametrize("value", ["-3", "-0.1", "1e6", "soon"])
def test_a_separation_time_a_model_cannot_have_names_file_and_line(
    shared: Path, tmp_path: Path, value: str
):
    """T_f0 is a number of half-chord transits from 0 (no lag: the UAE VI deck's cylinder
    writes 0) to 100 (AeroDyn's default 3): anything else is one line naming the aerofoil
    file, its line and the field."""
    from tests.conftest import edited_reference

    folder = edited_reference(
        shared,
        tmp_path,
        "NREL5MW",
        "Airfoils/DU40_A17.dat",
        "          3   T_f0",
        f"          {value}   T_f0",
    )
    with pytest.raises(SpecError) as err:
        load(folder / "NREL-5MW.fst")
    assert "DU40_A17.dat" in str(err.value) and "T_f0" in str(err.value)
    assert err.value.line == 23


@pytest.mark.parametrize(
    ("old", "new", "induction"),
    [
        # the reference file (OpenFAST 3.5 keys): Wake_Mod 1 with DBEMT_Mod 2 — a dynamic wake
        (None, None, "dynamic"),
        ("          2   DBEMT_Mod", "          0   DBEMT_Mod", "equilibrium"),
        ("          2   DBEMT_Mod", "         -1   DBEMT_Mod", "frozen"),
    ],
)
def test_the_induction_follows_the_decks_wake_model(shared, tmp_path, old, new, induction):
    """How the induction answers the blades' motion, as the deck's AeroDyn asks: in
    equilibrium with it where its BEMT has no dynamic wake (DBEMT_Mod 0, OpenFAST's default,
    as in the IEA-22 deck), held by a dynamic wake (DBEMT_Mod 1–3: the last node keeps
    a = 1), frozen for linearisation (−1: the induced velocity held at every node). Older
    files (WakeMod, FrozenWake): tests of aerodyn.induction below."""
    from tests.conftest import edited_reference
    from wtvib import importers

    folder = shared / "reference/NREL5MW"
    if old is not None:
        folder = edited_reference(
            shared, tmp_path, "NREL5MW", "NRELOffshrBsline5MW_Onshore_AeroDyn15.dat", old, new
        )
    s = importers.load(folder / "NREL-5MW.fst")
    assert s.aerodynamics is not None and s.aerodynamics.induction == induction


@pytest.mark.parametrize(
    ("lines", "induction"),
    [
        ("1 WakeMod\nFalse FrozenWake", "equilibrium"),  # AeroDyn 15 before OpenFAST 3.5
        ("1 WakeMod\nTrue FrozenWake", "frozen"),
        ("2 WakeMod", "dynamic"),  # DBEMT
        ("2 WakeMod\nTrue FrozenWake", "frozen"),
        ("0 WakeMod", "frozen"),  # no induction at all
        ("1 Wake_Mod\n0 DBEMT_Mod", "equilibrium"),
        ("1 Wake_Mod\n3 DBEMT_Mod", "dynamic"),
        ("1 Wake_Mod\n-1 DBEMT_Mod", "frozen"),
    ],
)
def test_the_wake_models_of_every_aerodyn_version(tmp_path, lines, induction):
    from wtvib.importers.aerodyn import induction as read
    from wtvib.importers.deck import parse

    path = tmp_path / "ad.dat"
    path.write_text("------- AeroDyn\ntitle\n" + lines + "\n")
    assert read(parse(path))[0] == induction
