"""BeamDyn blades at unit level: the 6×6 sections as wtvib's blade table, and malformed
files as one line naming file and line.

The files are OpenFAST's own (tests/data/openfast_decks/rtest.tar.gz, SOURCES.md there):
the NREL 5-MW's BeamDyn blade and its ElastoDyn blade table, which describe the same
blade (OpenFAST/r-test, glue-codes/openfast/5MW_Baseline).
"""

import math
import tarfile
from pathlib import Path

import numpy as np
import pytest

from wtvib.errors import SpecError
from wtvib.importers import beamdyn, deck

DATA = Path(__file__).resolve().parent / "data" / "openfast_decks"
BASE = "glue-codes/openfast/5MW_Baseline"
CASE = "glue-codes/openfast/5MW_Land_BD_Linear/5MW_Land_BD_Linear.fst"


@pytest.fixture
def files(tmp_path: Path) -> Path:
    with tarfile.open(DATA / "rtest.tar.gz") as tar:
        tar.extractall(tmp_path, filter="data")
    return tmp_path


def test_the_5mw_beamdyn_blade_is_its_elastodyn_blade(files):
    """The 5-MW's two blade files tabulate one blade: BeamDyn's K55 is ElastoDyn's FlpStff,
    K44 its EdgStff, M11 its BMassDen (before ElastoDyn's AdjBlMs), the key points' twist
    its StrcTwst — at every station, to the files' digits."""
    b = beamdyn.blade(deck.parse(files / CASE))
    ed = deck.parse(files / BASE / "NRELOffshrBsline5MW_Blade.dat")
    span = ed.fractions("BlFract") * 61.5
    for column, field in (
        ("FlpStff", "ei_flap_nm2"),
        ("EdgStff", "ei_edge_nm2"),
        ("BMassDen", "mass_per_length_kg_m"),
        ("StrcTwst", "twist_deg"),
    ):
        ours = np.interp(span, b.span, b.structure[field])
        assert ours == pytest.approx(ed.column("BlFract", column), rel=1e-9, abs=1e-9), column
    assert b.length_m == pytest.approx(61.5) and b.mu == (0.0022, 0.0014)
    # ∫ M11 over the span: the BeamDyn blade's own mass (ElastoDyn's table × 1.04536 is
    # the 17,740 kg of Jonkman et al. 2009, Table 2-1)
    assert b.mass_kg == pytest.approx(17740 / 1.04536, rel=0.01)


def _edited(files: Path, old: str, new: str, count: int = 1) -> deck.Deck:
    path = files / BASE / "NRELOffshrBsline5MW_BeamDyn_Blade.dat"
    text = path.read_text()
    assert old in text
    path.write_text(text.replace(old, new, count))
    return deck.parse(files / CASE)


@pytest.mark.parametrize(
    ("old", "new", "message"),
    [
        ("49   station_total", "50   station_total", "holds 49 whole stations"),
        ("49   station_total", "1e9   station_total", "station_total must be a whole number"),
        ("  0.003250\n", "  0.000000\n", "must increase from 0 to 1"),
        ("   9.729480E+08    0.000000E+00", "   9.729480E+08    0.0000x0E+00", "'0.0000x0E\\+00'"),
        (
            "   0.000000E+00    0.000000E+00    0.000000E+00    1.811360E+10",
            "   0.000000E+00    0.000000E+00    0.000000E+00    -1.811360E+10",
            "K44, K55 and the mass",
        ),
    ],
)
def test_a_malformed_blade_file_is_one_line_with_file_and_line(files, old, new, message):
    fst = _edited(files, old, new)
    with pytest.raises(SpecError, match=message) as err:
        beamdyn.blade(fst)
    assert str(err.value.source).endswith("NRELOffshrBsline5MW_BeamDyn_Blade.dat")
    assert err.value.line is not None


def test_prebent_key_points_are_said(files):
    """Key points off the pitch axis (a prebent blade): modelled straight, said."""
    path = files / BASE / "NRELOffshrBsline5MW_BeamDyn.dat"
    lines = path.read_text().splitlines()
    tip = next(i for i, line in enumerate(lines) if line.split()[2:3] == ["6.1500000E+01"])
    lines[tip] = "-4.0 0.0 6.1500000E+01 0.0"
    path.write_text("\n".join(lines))
    b = beamdyn.blade(deck.parse(files / CASE))
    assert any("modelled straight" in n and "4 m" in n for n in b.notes)
    assert math.isclose(b.length_m, 61.5)


@pytest.mark.parametrize("name", ["kp_xr", "kp_yr"])
def test_a_key_point_table_without_its_offsets_is_one_line(files, name):
    """The key points' table header without kp_xr or kp_yr (exhaustive.py beam, FUZZ.md
    campaign 21: its first word replaced was an internal ValueError): one line naming the
    column, the BeamDyn file and the header's line."""
    path = files / BASE / "NRELOffshrBsline5MW_BeamDyn.dat"
    lines = path.read_text().splitlines()
    head = next(i for i, line in enumerate(lines) if "kp_zr" in line.split())
    lines[head] = lines[head].replace(name, "abc")
    path.write_text("\n".join(lines))
    with pytest.raises(SpecError, match=f"names no {name} column") as err:
        beamdyn.blade(deck.parse(files / CASE))
    assert str(err.value.source).endswith("NRELOffshrBsline5MW_BeamDyn.dat")
    assert err.value.line == head + 1
