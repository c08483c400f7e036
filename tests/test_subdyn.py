"""SubDyn monopiles and HydroDyn's water at unit level: tables read by key, the pile's
sections, the reaction joint, the added mass — and every malformed file one line naming
file and line.

The files are OpenFAST's own (tests/data/openfast_decks, SOURCES.md there): the OC3
monopile's SubDyn file (OpenFAST/r-test, 5MW_OC3Mnpl_Linear) and the IEA-15 monopile deck
set (IEAWindTask37/IEA-15-240-RWT).
"""

import math
import tarfile
from pathlib import Path

import numpy as np
import pytest

from wtvib.errors import SpecError
from wtvib.importers import deck, subdyn

DATA = Path(__file__).resolve().parent / "data" / "openfast_decks"
OC3 = "glue-codes/openfast/5MW_OC3Mnpl_Linear"
#: the OC3 SubDyn file's reaction-joint row: joint 1, every DOF locked, no SSI file
REACTION = "   1" + "           1" * 6 + '        ""'
IEA15 = "OpenFAST/IEA-15-240-RWT-Monopile"


@pytest.fixture(scope="module")
def files(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("subdyn")
    for name in ("rtest", "iea15"):
        with tarfile.open(DATA / f"{name}.tar.gz") as tar:
            tar.extractall(root, filter="data")
    return root


def _oc3(files: Path, tmp_path: Path, *edits: tuple[str, str]) -> deck.Deck:
    """The OC3 deck set's .fst with its SubDyn file edited, in a scratch folder."""
    src = files / OC3
    for f in src.iterdir():
        text = f.read_text()
        if f.name.endswith("SubDyn.dat"):
            for old, new in edits:
                assert old in text, old
                text = text.replace(old, new)
        (tmp_path / f.name).write_text(text)
    return deck.parse(tmp_path / "5MW_OC3Mnpl_Linear.fst")


def test_the_oc3_pile_is_a_steel_tube_from_the_seabed_to_the_transition_piece(files, tmp_path):
    """6 m × 60 mm, E 210 GPa, ρ 8,500 kg/m³ (the file's property set 1): A = π/4·(D² − d²),
    I = π/64·(D⁴ − d⁴); clamped at −20.0001 m, up to the interface joint at 10 m."""
    pile = subdyn.monopile(_oc3(files, tmp_path), 10.0)
    assert isinstance(pile, subdyn.Monopile)
    d, t = 6.0, 0.06
    area = math.pi / 4 * (d**2 - (d - 2 * t) ** 2)
    second = math.pi / 64 * (d**4 - (d - 2 * t) ** 4)
    assert list(pile.z) == [-20.0001, -10.0, 0.0, 10.0]
    assert pile.mass == pytest.approx(np.full(4, 8500 * area))
    assert pile.ei == pytest.approx(np.full(4, 2.1e11 * second))
    assert pile.gj == pytest.approx(np.full(4, 8.08e10 * 2 * second))
    assert pile.foundation == {"kind": "clamped"} and pile.point_masses == []


def test_a_jacket_is_not_a_monopile_and_the_deck_says_what_it_is(files, tmp_path):
    """Two reaction joints: not one pile — the reason, for the report's warning."""
    fst = _oc3(
        files,
        tmp_path,
        ("1   NReact", "2   NReact"),
        (REACTION, REACTION + "\n" + REACTION.replace("   1 ", "   2 ", 1)),
    )
    assert subdyn.monopile(fst, 10.0) == (
        "its SubDyn substructure has 2 reaction and 1 interface joints — not a monopile (nor "
        "one on springs along it: each reaction joint free, with an SSI file)"
    )


def test_an_ssi_file_puts_the_pile_head_on_its_springs(files, tmp_path):
    """The SSI file of OpenFAST's SubDyn documentation (OC4_Jacket_SD_SSI.txt): named
    entries in any order; the fore-aft plane's Kxx, Ktyty and Kxty become the lateral,
    rocking and coupling springs, Ktztz the torsional one."""
    (tmp_path / "ssi.txt").write_text(
        "!---- Pile Head K and M elements ----!\n!Equivalent Stiffness Constants\n"
        "-1.98E+09 Kxty\n1.35E+10 Ktyty\n7.00E+08 Ktztz\n5.04E+08 Kxx\n5.06E+08 Kyy\n"
        "1.99E+09 Kytx\n1.35E+10 Ktxtx\n2.54E+09 Kzz\n"
    )
    fst = _oc3(
        files,
        tmp_path,
        (REACTION, REACTION.replace('        ""', '   "ssi.txt"')),
    )
    pile = subdyn.monopile(fst, 10.0)
    assert isinstance(pile, subdyn.Monopile)
    f = pile.foundation
    assert (f["kind"], f["lateral_n_m"], f["rocking_nm_rad"]) == ("springs", 5.04e8, 1.35e10)
    assert (f["coupling_n"], f["torsional_nm_rad"]) == (-1.98e9, 7.0e8)


FOOS = "IEA-10.0-198-RWT.fst"


@pytest.fixture(scope="module")
def foos(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """OWI-Lab's FOOS IEA-10 deck set (tests/data/openfast_decks/foos_iea10.tar.gz): a
    monopile on 100 reaction joints, each with the SSI file of its 0.5 m of soil (PISA's
    initial stiffness: lateral and rotational springs)."""
    root = tmp_path_factory.mktemp("foos")
    with tarfile.open(DATA / "foos_iea10.tar.gz") as tar:
        tar.extractall(root, filter="data")
    return root


def test_a_pile_on_springs_along_it_stands_on_them_at_the_mudline(foos):
    """The FOOS IEA-10's monopile was "not a monopile" (100 reaction joints) and its tower
    clamped at the transition piece, 10 m above the sea (first fore-aft 0.37 Hz). Its pile
    stands on its springs: from the highest (z = −23.5 m, the seabed at 23.35 m) up it is
    the tower's lower part; below, the springs' Kxx, Ktyty, Kxty and Ktztz condense to the
    mudline (:func:`subdyn._condensed`, checked against Hetényi in
    tests/validation/test_soil.py); the pile's mass below is said. The tower then bends at
    0.254 Hz, 12 % below the same turbine clamped at that mudline (0.288 Hz) — a soil's
    share of a monopile's first bending (5–15 %, as the IEA-15's on its HAWC2 springs:
    tests/validation/test_soil_hawc2.py)."""
    from wtvib import audit, importers

    fst = deck.parse(foos / FOOS)
    pile = subdyn.monopile(fst, 10.0)
    assert isinstance(pile, subdyn.Monopile)
    assert pile.base == pytest.approx(-23.5)
    f = pile.foundation
    assert f["kind"] == "springs" and f["coupling_n"] < 0
    assert f["lateral_n_m"] * f["rocking_nm_rad"] > f["coupling_n"] ** 2
    assert any("100 reaction joints" in n and "is left out" in n for n in pile.notes)
    spec = importers.load(foos / FOOS)
    ours = {m.id: m.frequency_hz for m in audit.run(spec).modes}
    from wtvib.spec.tower import Foundation

    clamp = spec.tower.model_copy(update={"foundation": Foundation()})
    held = spec.model_copy(update={"tower": clamp})
    clamped = {m.id: m.frequency_hz for m in audit.run(held).modes}
    for name in ("tower.fa1", "tower.ss1"):
        assert 0.8 * clamped[name] < ours[name] < 0.95 * clamped[name], name


def _foos_edited(foos: Path, tmp_path: Path, target: str, old: str, new: str) -> deck.Deck:
    """The FOOS deck set copied with one file edited."""
    import shutil

    root = tmp_path / "foos"
    shutil.copytree(foos, root)
    path = root / target
    text = path.read_text()
    assert old in text, old
    path.write_text(text.replace(old, new, 1))
    return deck.parse(root / FOOS)


SD = "08_SubDyn/owi_IEA-10.0-198-RWT_SubDyn.dat"


@pytest.mark.parametrize(
    ("target", "old", "new", "message"),
    [
        (SD, '"ssi/IEA-10.0-198-RWT_pisa_JointID_5.txt"', '"ssi/gone.txt"',
         "SSIfile names 'ssi/gone.txt', which does not exist"),
        # a spring of negative stiffness (it left the condensed head positive: accepted)
        ("08_SubDyn/ssi/IEA-10.0-198-RWT_pisa_JointID_1.txt", "4.48E+09				Kxx",
         "-4.48E+14				Kxx", "Kxx -4.48e\\+14: a spring of negative stiffness"),
        ("08_SubDyn/ssi/IEA-10.0-198-RWT_pisa_JointID_1.txt", "0.00E+00				Kxty",
         "9.00E+10				Kxty", "more coupling than Kxx"),
    ],
)  # fmt: skip
def test_a_broken_pile_on_springs_is_one_line(foos, tmp_path, target, old, new, message):
    fst = _foos_edited(foos, tmp_path, target, old, new)
    with pytest.raises(SpecError, match=message):
        subdyn.monopile(fst, 10.0)


def test_springs_along_a_pile_with_a_locked_joint_are_no_pile_on_springs(foos, tmp_path):
    """A reaction joint with a locked DOF among the springs: not a pile on springs (the
    reason said, the tower clamped at its base, as before)."""
    row = "  3          0           0           0           0           0           0"
    fst = _foos_edited(
        foos, tmp_path, SD, row, row.replace("0           0   ", "1           0   ", 1)
    )
    found = subdyn.monopile(fst, 10.0)
    assert isinstance(found, str) and "nor one on springs along it" in found


@pytest.mark.parametrize(
    ("edit", "message"),
    [
        (("   3           3           4", "   3           3           9"), "names joint 9"),
        (("4   NJoints", "5   NJoints"), "NJoints = 5, but the table has 4 rows"),
        (("4   NJoints", "4.5   NJoints"), "NJoints must be a whole number of rows"),
        (("   2              0.00000", "   2              0.0000x"), "column JointXss: '0.0000x'"),
        (("3   NMembers", "3   NMembersX"), "unknown layout: no NMembers"),
        (("   1        2.10000e+11", "   1        -2.10000e+11"), "property set 1: E, G, ρ"),
        (
            (
                "   1           1           1           1           1           1           1",
                "   1           1           1           1           1           0           1",
            ),
            "free DOFs and no SSI file",
        ),
    ],
)
def test_a_malformed_subdyn_file_is_one_line_naming_its_line(files, tmp_path, edit, message):
    fst = _oc3(files, tmp_path, edit)
    with pytest.raises(SpecError, match=message) as err:
        subdyn.monopile(fst, 10.0)
    assert str(err.value.source).endswith("SubDyn.dat")


def test_hydrodyn_water_is_added_mass_and_the_flooded_piles_water(files):
    """IEA-15's HydroDyn: one member D 10 m, t 55.341 mm from −30.1 to 15 m, SimplCa 1,
    flooded to MSL with sea water ("default": 1,025 kg/m³). Below MSL the pile carries
    Ca·ρ·πD²/4 + ρ·π(D − 2t)²/4 per metre; above, nothing."""
    fst = deck.parse(files / IEA15 / "IEA-15-240-RWT-Monopile.fst")
    pile = subdyn.monopile(fst, 15.0)
    assert isinstance(pile, subdyn.Monopile)
    wet = subdyn.water(fst, pile)
    assert isinstance(wet, subdyn.Water)
    rho, d, t = 1025.0, 10.0, 0.055341
    expected = rho * math.pi / 4 * d**2 + rho * math.pi / 4 * (d - 2 * t) ** 2
    assert np.interp(-20.0, wet.z, wet.mass) == pytest.approx(expected, rel=1e-6)
    assert np.interp(5.0, wet.z, wet.mass) == 0.0
    assert "1025" in wet.note


def test_no_hydrodyn_no_water_said(files, tmp_path):
    fst = _oc3(files, tmp_path)
    pile = subdyn.monopile(fst, 10.0)
    assert isinstance(pile, subdyn.Monopile)
    assert "HydroDyn is off (CompHydro = 0)" in str(subdyn.water(fst, pile))


def test_counted_tables_are_found_by_key_and_header_not_by_line():
    """SubDyn's NPropSets names both its circular and its rectangular table: the header
    tells them apart; units lines in parentheses are skipped."""
    text = (
        "-- head\ntitle\n"
        "1   NPropSets - rectangular\nPropSetID YoungE ShearG MatDens XsecA XsecB XsecT\n"
        "(-) (N/m2) (N/m2) (kg/m3) (m) (m) (m)\n1 2e11 8e10 7850 1 2 0.1\n"
        "2   NPropSets - circular\nPropSetID YoungE ShearG MatDens XsecD XsecT\n"
        "(-) (N/m2) (N/m2) (kg/m3) (m) (m)\n1 2e11 8e10 7850 6 0.06\n2 2e11 8e10 7850 5 0.05\n"
    )
    d = deck.parse(Path("sd.dat"), text)
    table = deck.counted(d, text, ("NPropSets",), "XsecD")
    assert table is not None and table.numbers("XsecD").tolist() == [6.0, 5.0]
    assert table.lines == [10, 11]
