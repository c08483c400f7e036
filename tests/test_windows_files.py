"""Models written on Windows, read on a case-sensitive system (wtvib.importers.paths, the
ANSI reading of spec.load.read_text): the same turbine as the model written here.

What a Windows-made model has that wtvib refused (wetb's own test models, PyPI ``wetb``
0.1.33, ``wetb/hawc2/tests/test_files``: a DTU 10 MW htc naming
``./data/dtu_10mw_rwt_tower_st.dat`` for ``DTU_10MW_RWT_Tower_st.dat``; ``ansi.htc`` with
cp1252 comments, "stig øye method", and ``begin tower_shadow_potential_2; … end
tower_shadow_potential;``): names in another case, backslashes, ANSI comments, a misspelt
end — and an htc audited from inside its ``htc/`` folder. Each edit below leaves the
turbine unchanged: the spec data read are the unedited model's, the notes aside, and the
notes say what was read so.
"""

import json
import re
import tarfile
from pathlib import Path

import pytest

from wtvib import importers
from wtvib.errors import SpecError

DATA = Path(__file__).resolve().parent / "data"
IEA15 = "HAWC2/IEA-15-240-RWT-Onshore/htc/IEA_15MW_RWT_Onshore.htc"
OC3 = "glue-codes/openfast/5MW_OC3Mnpl_Linear/5MW_OC3Mnpl_Linear.fst"


def _unpacked(archive: str, into: Path) -> Path:
    with tarfile.open(DATA / archive) as tar:
        tar.extractall(into, filter="data")
    return into


def _edit(path: Path, *changes: tuple[str, str], encoding: str = "utf-8") -> None:
    text = path.read_text(encoding="utf-8")
    for old, new in changes:
        assert old in text, old
        text = text.replace(old, new)
    path.write_bytes(text.encode(encoding))


def _same_turbine(found: dict, expected: dict, plain: Path, windows: Path) -> None:
    """The two models' spec data equal, the notes aside and the files' folders read as one."""
    drop = ("assumptions",)
    ours = json.dumps({k: v for k, v in found.items() if k not in drop}, sort_keys=True)
    theirs = json.dumps({k: v for k, v in expected.items() if k not in drop}, sort_keys=True)
    assert ours.replace(str(windows), str(plain)) == theirs


def test_a_hawc2_model_made_on_windows_is_the_same_turbine(tmp_path, monkeypatch):
    plain = _unpacked("hawc2/iea15_onshore.tar.gz", tmp_path / "plain") / IEA15
    windows = _unpacked("hawc2/iea15_onshore.tar.gz", tmp_path / "windows") / IEA15
    _edit(
        windows,
        (
            "filename ./data/IEA_15MW_RWT_Tower_st.dat;",
            "filename .\\data\\iea_15mw_rwt_tower_st.dat; stig øye method",
        ),
        (
            "continue_in_file ../IEA-15-240-RWT/IEA_15MW_RWT_WTG_bodies_noFPM.htc;",
            "continue_in_file ..\\IEA-15-240-RWT\\iea_15mw_rwt_wtg_bodies_nofpm.htc;",
        ),
        ("end wind;", "end wnd;"),
        encoding="cp1252",
    )
    expected = importers.to_data(plain)
    monkeypatch.chdir(windows.parent)  # audited from inside htc/, named relative
    found = importers.to_data(Path(windows.name))
    _same_turbine(found, expected, tmp_path / "plain", tmp_path / "windows")
    notes = "\n".join(found["assumptions"])
    assert "2 file name(s) of the model are no file's on this file system" in notes
    assert "'.\\\\data\\\\iea_15mw_rwt_tower_st.dat' → IEA_15MW_RWT_Tower_st.dat" in notes
    assert "'end wnd' read as the end of block wind" in notes


def test_a_name_two_files_answer_to_is_refused(tmp_path):
    """Where two entries differ in case only, Windows could not have held both: no guess."""
    path = _unpacked("hawc2/iea15_onshore.tar.gz", tmp_path) / IEA15
    data = path.parents[1] / "data"
    (data / "iea_15mw_rwt_tower_st.DAT").write_bytes(
        (data / "IEA_15MW_RWT_Tower_st.dat").read_bytes()
    )
    _edit(path, ("./data/IEA_15MW_RWT_Tower_st.dat", "./data/IEA_15MW_RWT_TOWER_ST.dat"))
    with pytest.raises(
        SpecError, match=re.escape("'./data/IEA_15MW_RWT_TOWER_ST.dat', which does not")
    ):
        importers.to_data(path)


def test_an_end_naming_an_enclosing_block_is_still_refused(tmp_path):
    """A misspelt end closes the innermost block; one naming an outer block would leave the
    blocks inside it without an end (the test_hawc2.py case, kept): not a misspelling."""
    path = _unpacked("hawc2/iea15_onshore.tar.gz", tmp_path) / IEA15
    _edit(path, ("end timoschenko_input;\n    begin c2_def;", "end main_body;\n    begin c2_def;"))
    with pytest.raises(SpecError, match="end main_body where timoschenko_input is open"):
        importers.to_data(path)


def test_an_openfast_deck_set_made_on_windows_is_the_same_turbine(tmp_path):
    plain = _unpacked("openfast_decks/rtest.tar.gz", tmp_path / "plain") / OC3
    windows = _unpacked("openfast_decks/rtest.tar.gz", tmp_path / "windows") / OC3
    ed = windows.parent / "NRELOffshrBsline5MW_OC3Monopile_ElastoDyn.dat"
    _edit(
        ed,
        (
            '"../5MW_Baseline/NRELOffshrBsline5MW_Blade.dat"    BldFile(1)',
            '"..\\5MW_Baseline\\nreloffshrbsline5mw_blade.dat"    BldFile(1)  [µ°]',
        ),
        encoding="cp1252",
    )
    expected = importers.to_data(plain)
    found = importers.to_data(windows)
    _same_turbine(found, expected, tmp_path / "plain", tmp_path / "windows")
    assert any(
        "'..\\\\5MW_Baseline\\\\nreloffshrbsline5mw_blade.dat' → NRELOffshrBsline5MW_Blade.dat"
        in note
        for note in found["assumptions"]
    )


def test_a_yaml_file_is_still_utf8(tmp_path):
    """YAML is UTF-8 (YAML 1.2 §5.2): a wtvib spec in cp1252 is refused by line, not read
    as ANSI."""
    spec = tmp_path / "t.yaml"
    spec.write_bytes(
        (Path(__file__).resolve().parents[1] / "turbines" / "mod-2.yaml").read_bytes()
        + "# tour de France: ø\n".encode("cp1252")
    )
    with pytest.raises(SpecError, match="not UTF-8 text"):
        importers.to_data(spec)


def test_a_spec_saved_as_utf16_is_the_same_spec(tmp_path):
    """Windows PowerShell 5's ``>`` writes UTF-16 with a byte-order mark, which YAML 1.2
    allows (§5.2): read as the UTF-8 file it was made from; a broken one refused by line."""
    text = (Path(__file__).resolve().parents[1] / "turbines" / "mod-2.yaml").read_text()
    (tmp_path / "u8.yaml").write_text(text, encoding="utf-8")
    (tmp_path / "u16.yaml").write_bytes(text.encode("utf-16"))
    assert importers.to_data(tmp_path / "u16.yaml") == importers.to_data(tmp_path / "u8.yaml")
    (tmp_path / "bad.yaml").write_bytes(b"\xff\xfea\x00\x00\xd8")
    with pytest.raises(SpecError, match="not UTF-16 text"):
        importers.to_data(tmp_path / "bad.yaml")
