"""OpenFAST ServoDyn's structural control read as tuned mass dampers
(wtvib.importers.stc): r-test's StC_test_OC4Semi_Linear_Tow deck set
(tests/data/openfast_decks/rtest_special.tar.gz), each case one edit of its files."""

import math
import tarfile
from pathlib import Path

import pytest
from typer.testing import CliRunner

from wtvib import importers
from wtvib.cli import app
from wtvib.spec import Spec

DECKS = Path(__file__).parent / "data" / "openfast_decks"
CASE = "StC_test_OC4Semi_Linear_Tow"


@pytest.fixture
def deck(tmp_path: Path) -> Path:
    with tarfile.open(DECKS / "rtest_special.tar.gz") as tar:
        tar.extractall(tmp_path, filter="data")
    return tmp_path / "glue-codes" / "openfast" / CASE


def _edit(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert old in text, old
    path.write_text(text.replace(old, new, 1))


def _load(deck: Path) -> Spec:
    return importers.load(deck / f"{CASE}.fst")


def test_the_tower_damper_is_read_as_its_file_gives_it(deck):
    """StC-Tow-XDir.dat: an X damper of 2291.5 kg on 229.15 N/m and 22.915 N·s/m at
    StC_P_Z = 77.6 m above the tower's base, fore-aft."""
    (d,) = _load(deck).tower.dampers
    assert (d.on, d.direction, d.height_m) == ("tower", "fore-aft", 77.6)
    assert (d.mass_kg, d.stiffness_n_m, d.damping_ns_m) == (2291.5, 229.15, 22.915)


def test_an_omnidirectional_damper_moves_in_both_planes(deck):
    """StC_DOF_MODE 2: one mass (StC_XY_M) on the X and the Y springs."""
    stc = deck / "StC-Tow-XDir.dat"
    _edit(stc, "          1   StC_DOF_MODE", "          2   StC_DOF_MODE")
    _edit(stc, "    0.         StC_XY_M", "    3000.      StC_XY_M")
    _edit(stc, "    0.    \t   StC_Y_K", "    300.    \t   StC_Y_K")
    dampers = _load(deck).tower.dampers
    assert [(d.direction, d.mass_kg) for d in dampers] == [
        ("fore-aft", 3000.0),
        ("side-side", 3000.0),
    ]
    assert dampers[1].frequency_hz == pytest.approx(math.sqrt(0.1) / (2 * math.pi))


def test_a_spring_given_as_a_force_table_is_taken_at_its_slope_at_rest(deck):
    """Use_F_TBL: the table's ±2 m rows hold ±65 kN, its slope at rest 32.5 kN/m."""
    _edit(deck / "StC-Tow-XDir.dat", "False         Use_F_TBL", "True          Use_F_TBL")
    (d,) = _load(deck).tower.dampers
    assert d.stiffness_n_m == pytest.approx(6.5e4 / 2.0)


@pytest.mark.parametrize(
    ("file", "old", "new", "said"),
    [
        ("StC-Tow-XDir.dat", "          1   StC_DOF_MODE", "          3   StC_DOF_MODE",
         "tuned liquid column damper (StC_DOF_MODE 3) — not modelled"),
        ("StC-Tow-XDir.dat", "          0   StC_CMODE", "          1   StC_CMODE",
         "modelled as its passive spring and dashpot"),
        ("SrvD_StC-Tow.dat", "          0   NumBStC", "          1   NumBStC",
         "1 blade damper(s) (NumBStC in SrvD_StC-Tow.dat) not modelled"),
    ],
)  # fmt: skip
def test_what_is_not_modelled_is_said(deck, file, old, new, said):
    _edit(deck / file, old, new)
    assert any(said in w for w in _load(deck).warnings), _load(deck).warnings


@pytest.mark.parametrize(
    ("old", "new", "said"),
    [
        ("    2291.5     StC_X_M", "    0.     StC_X_M", "StC_X_M = 0 kg: a damper needs a mass"),
        ("\t229.15    StC_X_K", "\t0.    StC_X_K", "StC_X_K: a stiffness of 0 N/m"),
        ("          1   StC_DOF_MODE", "          9   StC_DOF_MODE", "StC_DOF_MODE must be"),
    ],
)
def test_a_damper_that_cannot_be_is_one_line_naming_its_file(deck, old, new, said):
    _edit(deck / "StC-Tow-XDir.dat", old, new)
    result = CliRunner().invoke(app, ["check", str(deck / f"{CASE}.fst"), "--no-plots"])
    assert result.exit_code == 2, result.output
    lines = [ln for ln in result.stderr.splitlines() if ln.startswith("error:")]
    assert len(lines) == 1 and said in lines[0] and "StC-Tow-XDir.dat" in lines[0], lines
