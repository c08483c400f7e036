"""Campbell results of other tools through the CLI: formats, mistakes, judgement."""

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from wtvib import audit, importers, spec
from wtvib.cli import app
from wtvib.importers.campbell_results import merge_speeds

runner = CliRunner()
DATA = Path(__file__).resolve().parent / "data" / "campbell"

TABLE = """mode,rpm,frequency_hz,damping_ratio,whirl
tower.fa1,6.9,0.324,0.05,fixed
tower.fa1,12.1,0.325,0.06,fixed
blade.edge1.forward,6.9,1.20,0.004,forward
blade.edge1.forward,12.1,1.29,{last},forward
"""


def write(tmp_path: Path, text: str, name: str = "c.csv") -> Path:
    p = tmp_path / name
    p.write_text(text)
    return p


@pytest.mark.parametrize(
    ("args", "tool"),
    [
        ([str(DATA / "openfast" / "ws03.0.1.lin")], "OpenFAST linearisation (MBC3)"),
        ([str(DATA / "openfast")], "OpenFAST linearisation (MBC3)"),
        ([str(DATA / "hawcstab2" / "steady.cmb"), "--blades", "3"], "HAWCStab2"),
    ],
)
def test_each_format_audits_through_the_cli(args, tool):
    result = runner.invoke(app, ["check", *args, "--no-plot", "-f", "json"])
    assert result.exit_code in (0, 1), result.output  # a verdict, not an error
    doc = json.loads(result.stdout)
    assert doc["results"]["tool"] == tool
    assert doc["damping"] == "imported"
    assert any(c["id"] == "system.stability" for c in doc["checks"])


def test_a_table_is_judged_with_its_damping_and_negative_damping_fails(tmp_path):
    """The edge mode's ζ = −0.002 at 12.1 rpm is an instability: system.stability fails
    with the mode and speed; the tower's DAF at 3P uses the table's ζ there."""
    r = audit.run(
        importers.load(
            write(tmp_path, TABLE.format(last="-0.002")), importers.ReadOptions(blades=3)
        )
    )
    stab = next(c for c in r.checks if c.id == "system.stability")
    assert stab.status == "fail"
    assert stab.numbers["unstable"] == [
        {"mode": "system.blade.edge1.forward", "damping_ratio": -0.002, "rpm": 12.1}
    ]
    fa = next(m for m in r.modes if m.id == "system.tower.fa1")
    assert fa.damping_at(6.9 * 3.14159265 / 30, 0.0) == pytest.approx(0.05, rel=1e-3)
    ok = audit.run(
        importers.load(
            write(tmp_path, TABLE.format(last="0.003"), "d.csv"), importers.ReadOptions(blades=3)
        )
    )
    assert next(c for c in ok.checks if c.id == "system.stability").status == "pass"


def test_without_blades_three_are_assumed_and_said(tmp_path):
    s = importers.load(write(tmp_path, TABLE.format(last="0.003")))
    assert s.rotor.blades == 3
    assert any("3 assumed" in w for w in s.warnings)


@pytest.mark.parametrize(
    ("name", "text", "where"),
    [
        ("bad.csv", TABLE.format(last="abc"), ":5: column damping_ratio"),
        ("few.csv", TABLE.format(last="0.1").replace(",forward\n", "\n", 1), ":4: 4 cells"),
        ("id.csv", TABLE.format(last="0.1").replace("tower.fa1", "Tower FA", 1), ":2: column mode"),
        # a negative frequency beside a positive one at the same speed would have merged to
        # a mean near 0 Hz (a .cmb's rated points do): refused where it is written
        ("neg.csv", TABLE.format(last="0.1").replace("0.325", "-0.325", 1), ":3: column freq"),
        ("zero.csv", TABLE.format(last="0.1").replace("1.20", "0", 1), ":4: column freq"),
    ],
)
def test_a_broken_table_is_one_line_and_exit_2(tmp_path, name, text, where):
    result = runner.invoke(app, ["check", str(write(tmp_path, text, name)), "--no-plot"])
    assert result.exit_code == 2
    assert where in result.output and "Traceback" not in result.output


def test_a_truncated_lin_file_is_one_line_and_exit_2(tmp_path):
    src = (DATA / "openfast" / "ws03.0.1.lin").read_text()
    lines = src.splitlines()
    cut = next(i for i, ln in enumerate(lines) if ln.startswith("A:")) + 5
    (tmp_path / "op.1.lin").write_text("\n".join(lines[:cut]) + "\n   4.2277500E+\n")
    result = runner.invoke(app, ["check", str(tmp_path / "op.1.lin"), "--no-plot"])
    assert result.exit_code == 2
    assert "op.1.lin:" in result.output and "row 5 of A" in result.output


def test_a_cmb_with_a_text_cell_is_one_line_and_exit_2(tmp_path):
    text = (DATA / "hawcstab2" / "blade.cmb").read_text().replace("0.610872E+00", "abc", 1)
    result = runner.invoke(app, ["check", str(write(tmp_path, text, "x.cmb")), "--no-plot"])
    assert result.exit_code == 2 and "x.cmb:3: 'abc' is not a finite number" in result.output


def test_a_cmb_with_a_frequency_that_is_not_positive_is_one_line_and_exit_2(tmp_path):
    """steady.cmb's first mode at 5 m/s typed negative: its low winds share one rotor speed,
    so the merge would have averaged −0.625 with +0.625 Hz into 4e-5 Hz and judged that."""
    for f in ("steady.pwr", "steady.amp"):
        (tmp_path / f).write_text((DATA / "hawcstab2" / f).read_text())
    text = (DATA / "hawcstab2" / "steady.cmb").read_text()
    assert "0.625376E+00" in text
    cmb = write(tmp_path, text.replace("0.625376E+00", "-0.625376E+00", 1), "steady.cmb")
    result = runner.invoke(app, ["check", str(cmb), "--blades", "3", "--no-plot"])
    assert result.exit_code == 2
    assert "steady.cmb:2: mode 1: frequency -0.625376 Hz" in result.output


def test_results_and_the_coupled_model_cannot_both_give_the_system_modes(write_spec):
    extra = (
        "coupled: {apex_downwind_m: -5, apex_above_top_m: 2}\n"
        "results:\n  tool: t\n  modes:\n    tower.fa1: {description: x, rpm: [10], "
        "frequency_hz: [0.3]}\n"
    )
    with pytest.raises(spec.SpecError, match="cannot both"):
        spec.load(write_spec(extra=extra))


def test_points_at_one_speed_merge_to_the_mean_frequency_and_lowest_damping():
    m = {
        "rpm": [6.0, 9.6, 9.6, 9.6],
        "frequency_hz": [1.0, 2.0, 2.2, 2.1],
        "damping_ratio": [0.1, 0.05, 0.02, 0.04],
        "wind_m_s": [5.0, 11.0, 15.0, 20.0],
    }
    spread = merge_speeds(m)
    assert m["rpm"] == [6.0, 9.6]
    assert m["frequency_hz"] == pytest.approx([1.0, 2.1])
    assert m["damping_ratio"] == [0.1, 0.02] and m["wind_m_s"] == [5.0, 15.0]
    assert spread == pytest.approx(0.1)


def test_every_per_point_list_of_a_linearisation_merges():
    """An OpenFAST linearisation's modes carry their damped frequency, whirl and energy share
    per point too. ROSCO 2.10's 240 linearisations of the IEA-15 semisubmersible (20 winds,
    five of them at the rated 7.56 rpm) were refused as "damped_frequency_hz has 20 values
    but rpm has 16": the merge left those lists whole."""
    m = {
        "rpm": [6.0, 9.6, 9.6],
        "frequency_hz": [1.0, 2.0, 2.2],
        "damped_frequency_hz": [0.9, 1.8, 2.0],
        "damping_ratio": [0.1, 0.05, 0.02],
        "whirl": ["", "backward", "forward"],
        "wind_m_s": [5.0, 11.0, 15.0],
        "share": [0.9, 0.8, 0.7],
        "description": "a mode",
    }
    merge_speeds(m)
    assert all(len(m[k]) == 2 for k in m if k != "description")
    assert m["damped_frequency_hz"] == pytest.approx([0.9, 1.9])
    assert m["whirl"] == ["", "backward"] and m["share"] == [0.9, 0.8]
    assert m["description"] == "a mode"


def test_azimuths_too_few_or_uneven_for_mbc3_are_a_warning(tmp_path):
    """The stored linearisation is three of OpenFAST's 36 azimuths (0.4°, 120°, 330°): MBC3's
    average does not cancel the rotor's periodic terms over them, and the import says so.
    The same files with the third azimuth moved to 240° (evenly spaced) say nothing; one
    file alone (one azimuth) warns again."""
    src = DATA / "openfast"
    files = sorted(src.glob("*.lin"))

    def warnings(folder: Path) -> list[str]:
        return [w for w in importers.load(folder).warnings if "azimuths" in w]

    assert len(warnings(src)) == 1 and "ws03.0 (3 at 6.972 rpm)" in warnings(src)[0]
    even = tmp_path / "even"
    even.mkdir()
    for f in files:
        (even / f.name).write_text(f.read_text().replace("5.7600 rad", "4.1888 rad"))
    assert warnings(even) == []
    one = tmp_path / "one"
    one.mkdir()
    (one / files[0].name).write_text(files[0].read_text())
    assert len(warnings(one)) == 1


def test_a_cmb_among_several_opt_files_is_told_which_to_name(tmp_path):
    """wetb's test data (PyPI wetb 0.1.33, prepost/tests/data) keep campbell_diagram.cmb
    beside dtu10mw.opt and kb6.opt: which one HAWCStab2 ran is not for wtvib to guess —
    the line says how to tell it."""
    (tmp_path / "a.opt").write_text((DATA / "hawcstab2" / "steady.pwr").read_text())
    (tmp_path / "b.opt").write_text((DATA / "hawcstab2" / "steady.pwr").read_text())
    cmb = write(tmp_path, (DATA / "hawcstab2" / "steady.cmb").read_text(), "run.cmb")
    result = runner.invoke(app, ["check", str(cmb), "--blades", "3", "--no-plot"])
    assert result.exit_code == 2
    assert "the folder has 2 .opt files (a.opt, b.opt): copy or link" in result.output
    assert "to run.opt" in result.output


#: The heads of files that sit beside the models in IEAWindTask37/IEA-3.4-130-RWT and
#: IEA-10.0-198-RWT, as they are written there (an st file whose name ends in .dat, ROSCO's
#: controller input and performance table, BeamDyn's blade file)
ST_ROWS = "$1 2\n" + "  0.0" * 19 + "\n"
ROSCO = "! Controller parameter input file\n1   ! F_LPFType  - {1: first-order}\n"
PERFORMANCE = "# ----- Rotor performance tables for the WEIS Turbine wind turbine -----\n"
BEAMDYN_BLADE = (
    " ------- BEAMDYN V1.00.* INDIVIDUAL BLADE INPUT FILE ---------\n Test Format 1\n"
    " ---------------------- BLADE PARAMETERS -----------------\n"
    "21   station_total    - Number of blade input stations (-)\n"
    " 1   damp_type        - Damping type: 0: no damping; 1: damped\n"
)


@pytest.mark.parametrize(
    ("name", "text", "words"),
    [
        ("tower_st.dat", "#1 Tower\n r m x_cg\n" + ST_ROWS, "a HAWC2 structural (st) file"),
        ("IEA-3.4-130-RWT_DISCON.IN", ROSCO, "a ROSCO controller input (DISCON)"),
        ("IEA-3.4-130-RWT_Cp_Ct_Cq.txt", PERFORMANCE, "a rotor performance table"),
        ("IEA-3.4-130-RWT_BeamDyn_Blade.dat", BEAMDYN_BLADE, "an OpenFAST BeamDyn blade file"),
    ],
)
def test_a_file_beside_a_model_is_named_by_its_text(tmp_path, name, text, words):
    """The IEA-3.4's and IEA-10's repositories hold, beside their models, files whose names
    do not say what they are; each was "not a format wtvib reads" and is said for what it
    is and which file to give (exit 2, one line)."""
    path = write(tmp_path, text, name)
    result = runner.invoke(app, ["check", str(path), "--no-plot"])
    assert result.exit_code == 2 and words in result.output, result.output


@pytest.mark.parametrize(
    ("name", "words"),
    [
        ("run.opt", "HAWCStab2's operational data"),
        ("run.pwr", "HAWCStab2's steady-state results"),
        ("run.amp", "HAWCStab2's modal amplitudes"),
        ("run_u10000.ind", "HAWCStab2's induction and loads"),
        ("blade.st", "a HAWC2 structural (st) file"),
    ],
)
def test_a_hawcstab2_or_hawc2_part_file_is_named_for_what_it_is(tmp_path, name, words):
    """wetb's test data (PyPI wetb 0.1.33, prepost/tests/data) hold HAWCStab2's .opt, .pwr
    and .ind files beside its .cmb: each was "not a format wtvib reads"; each is said for
    what it is and which file to give."""
    path = write(tmp_path, " 0.5E+01  0.1E+01  0.2E+01\n", name)
    result = runner.invoke(app, ["check", str(path), "--no-plot"])
    assert result.exit_code == 2 and words in result.output, result.output
