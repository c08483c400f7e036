"""Spec errors: one readable line naming the field and the YAML line, exit code 2."""

import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from tests.conftest import spec_text
from wtvib import spec
from wtvib.cli import app
from wtvib.errors import SpecError

runner = CliRunner()

GOOD = spec_text(speed="min_rpm: 10\nmax_rpm: 20", modes="fa1: 0.5")


def error_of(write_spec, text: str) -> SpecError:
    with pytest.raises(SpecError) as info:
        spec.load(write_spec(text))
    return info.value


CASES = [
    # (edit of GOOD, field path, line, words in the message); a missing field or a
    # cross-field error points at the line of the enclosing mapping
    (lambda t: t.replace("  blades: 3\n", ""), "rotor.blades", 3, "required field is missing"),
    (lambda t: t.replace("blades: 3", "blades: three"), "rotor.blades", 4, "a whole number"),
    (lambda t: t.replace("fa1: 0.5", "fa1: -0.5"), "tower.modes.fa1", 12, "greater than 0"),
    (lambda t: t.replace("min_rpm: 10", "min_rpm: 25"), "rotor.speed", 7, "exceeds max_rpm"),
    (
        lambda t: t.replace("fa1: 0.5", "fa1: 0.5\n    fa1: 0.6"),
        "tower.modes.fa1",
        13,
        "duplicate key 'fa1' (first given on line 12)",
    ),
    (
        lambda t: t.replace("hub: rigid", "hub: rigid\n  hubtype: x"),
        "rotor.hubtype",
        7,
        "unknown field",
    ),
    (lambda t: t.replace("fa1: 0.5", "fb1: 0.5"), "tower.modes.fb1", 12, "not a known mode"),
    (lambda t: t.replace("fa1: 0.5", "fa1: .nan"), "tower.modes.fa1", 12, "finite number"),
    (
        lambda t: t.replace("orientation: upwind", "orientation: sideways"),
        "rotor.orientation",
        5,
        "'upwind', 'downwind' or 'vertical-axis'",
    ),
    (
        lambda t: t.replace("fa1: 0.5", "fa1: {value: 0.5, provenance: guessed}"),
        "tower.modes.fa1.provenance",
        12,
        "'published', 'derived', 'tuned' or 'representative'",
    ),
    (
        lambda t: t.replace("fa1: 0.5", "fa1: {value: 0.5, provenance: published, source: x}"),
        "tower.modes.fa1.source",
        12,
        "not a key of the top-level 'sources'",
    ),
    (
        lambda t: t.replace("fa1: 0.5", "fa1: !!python/object:os.system ls"),
        "tower.modes.fa1",
        12,
        "not allowed",
    ),
]


@pytest.mark.parametrize(("edit", "path", "line", "words"), CASES)
def test_spec_error_names_field_and_line(write_spec, edit, path, line, words):
    err = error_of(write_spec, edit(GOOD))
    assert err.path == path
    assert err.line == line
    assert words in err.message


def test_the_good_spec_loads(write_spec):
    s = spec.load(write_spec(GOOD))
    assert s.rotor.speed.steady_rpm == [(10.0, 20.0)]


def test_quick_pass_bands_are_pairs_of_speeds(write_spec):
    """The README's ``quick_pass_rpm: [[10, 11]]``: YAML gives lists, which the strict
    schema refused as "not a valid tuple" — the documented field could not be used."""
    from wtvib.judge.excitation import operating_range
    from wtvib.units import rpm_to_rad_s

    good = GOOD.replace("max_rpm: 20", "max_rpm: 20\n    quick_pass_rpm: [[12, 13.5]]")
    s = spec.load(write_spec(good))
    band = operating_range(s.rotor.speed).quick_pass
    assert band == ((float(rpm_to_rad_s(12)), float(rpm_to_rad_s(13.5))),)
    err = error_of(write_spec, good.replace("[[12, 13.5]]", "[[12]]"))
    assert err.path == "rotor.speed.quick_pass_rpm[0]" and "at least 2 items" in err.message
    err = error_of(write_spec, good.replace("[[12, 13.5]]", "[['12', 13.5]]"))
    assert err.path == "rotor.speed.quick_pass_rpm[0][0]" and "should be a number" in err.message


@pytest.mark.parametrize(
    ("content", "words"),
    [
        (b"", "the file is empty"),
        (b"# only a comment\n", "the file is empty"),
        (b"rotor: [1, 2\n", "not valid YAML"),
        # a tab indenting a line: YAML's own words do not say it is one
        (b"wtvib: 1\nturbine:\n\tname: x\n", "a tab: YAML indents with spaces only"),
        (b"\x89PNG\r\n\x1a\n\x00\x00binary", "binary file"),
        (b"wtvib: 1\nturbine: {name: \xff\xfe}\n", "not UTF-8"),
        (b"- just\n- a list\n", "expected a mapping"),
        (b"turbine: {name: x}\n", "not a wtvib spec"),
        # files that sit beside turbines in their repositories (IEAWindSystems/IEA-22-280-
        # RWT): said for what they are, not only for what they are not
        (
            b"path_params: {FAST_InputFile: x.fst}\ncontroller_params: {flag: true}\n",
            r"a ROSCO controller tuning file, not a turbine: .* \(x.fst\)",
        ),
        (
            b"cases:\n  - configuration: {wind_speed: 3.0}\n    outputs: {Damping_ratio: [0.1]}\n",
            "another tool's results in the IEA Wind systems' format",
        ),
        # windIO's plant files (IEAWindTask37/IEA-Wind-740-10-ROWP): a turbine's power
        # and thrust curves, a farm that includes its turbine, a wind resource
        (
            b"name: IEA 10MW\nperformance: {rated_power: 1.0e7}\nhub_height: 119.0\n"
            b"rotor_diameter: 198.0\n",
            "a wind-plant file .* not a turbine's structure",
        ),
        (b"name: farm\nturbines: !include t.yaml\n", "windIO's plant files"),
        (b"name: r\nwind_resource: {sector_probability: {data: [1.0]}}\n", "a wind-plant file"),
        # a repository's CI configuration (the IEA-10's .travis.yml)
        (b"language: python\ninstall:\n  - pip install .\n", "a tool's configuration"),
        (b"wtvib: 7\n", "unsupported spec format version 7"),
    ],
)
def test_files_that_are_not_specs(tmp_path, content, words):
    path = tmp_path / "bad.yaml"
    path.write_bytes(content)
    with pytest.raises(SpecError, match=words):
        spec.load(path)


def test_missing_file(tmp_path):
    with pytest.raises(SpecError, match="no such file"):
        spec.load(tmp_path / "nope.yaml")


def test_oversized_file_is_refused_before_parsing(tmp_path):
    path = tmp_path / "big.yaml"
    path.write_text("a: 1\n" * 100)
    with pytest.raises(SpecError, match="over the 100-byte limit"):
        spec.load(path, max_bytes=100)


def test_alias_bomb_is_refused(tmp_path, monkeypatch):
    from wtvib.spec import yamlio

    monkeypatch.setattr(yamlio, "MAX_NODES", 10_000)
    lines = ["a0: &a0 [x, x, x, x, x, x, x, x, x, x]"]
    for i in range(1, 8):
        lines.append(f"a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 10) + "]")
    path = tmp_path / "bomb.yaml"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(SpecError, match="alias bomb"):
        spec.load(path)


@pytest.mark.parametrize(("edit", "path", "line", "words"), CASES[:6])
def test_cli_gives_one_line_and_exit_2(write_spec, edit, path, line, words):
    file = write_spec(edit(GOOD))
    result = runner.invoke(app, ["check", str(file), "--no-plot"])
    assert result.exit_code == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in result.output
    assert lines[0].startswith(f"error: {file}:{line}: {path}: ")
    assert words in lines[0]


def test_main_prints_one_line_without_traceback(write_spec, capsys):
    from wtvib.cli import main

    file = write_spec(GOOD.replace("fa1: 0.5", "fa1: -0.5"))
    import sys

    argv = sys.argv
    sys.argv = ["wtvib", "check", str(file), "--no-plot"]
    try:
        with pytest.raises(SystemExit) as exit_info:
            main()
    finally:
        sys.argv = argv
    err = capsys.readouterr().err
    assert exit_info.value.code == 2
    assert err.count("\n") == 1 and "Traceback" not in err
    assert f"{file}:12: tower.modes.fa1: Input should be greater than 0" in err


def test_provenance_is_kept(write_spec):
    text = (
        GOOD.replace(
            "fa1: 0.5", "fa1: {value: 0.5, provenance: derived, source: h, note: from a statement}"
        )
        + "sources: {h: Hau}\n"
    )
    s = spec.load(write_spec(text))
    q = s.provenance["tower.modes.fa1"]
    assert (q.value, q.provenance, q.source, q.note) == (0.5, "derived", "h", "from a statement")
    assert s.tower.modes["fa1"] == 0.5


def test_json_schema_accepts_quantities():
    schema = spec.json_schema()
    assert "Quantity" in schema["$defs"]
    assert schema["title"].startswith("wtvib turbine spec")


@pytest.mark.parametrize(
    ("line", "replacement", "message"),
    [
        ("  blades: 2", "  blades: true", "rotor.blades: should be a whole number, not true"),
        ("  blades: 2", "  blades: 2.0", "rotor.blades: should be a whole number (got 2.0)"),
        ("    fixed_rpm: 30", "    fixed_rpm: 1:30", "should be a number, not text (got '1:30')"),
        # a quoted number: what the field wants, and how to write it (a quoted
        # float in a quantity was told "Input should be a valid integer")
        (
            "    fixed_rpm: 30",
            '    fixed_rpm: "30"',
            "should be a number, not text (got '30': write it without quotes)",
        ),
        (
            "    fixed_rpm: 30",
            '    fixed_rpm: {value: "30.5", provenance: published}',
            "rotor.speed.fixed_rpm.value: should be a number, not text (got '30.5': write it",
        ),
        ("    fa1: 0.75", "    fa1: 0_75", "got '0_75'"),
    ],
)
def test_numbers_must_be_numbers(write_spec, line, replacement, message):
    """YAML 1.1 and lax validation made ``blades: true`` one blade, ``1:30`` 90 rpm
    and "0_5" 5 Hz, and took the text "30" for a number. Strict types refuse each with the
    field and line."""
    text = spec_text(blades=2, speed="fixed_rpm: 30", modes="fa1: 0.75")
    assert line in text
    with pytest.raises(spec.SpecError, match=re.escape(message) if "(" in message else message):
        spec.load(write_spec(text.replace(line, replacement)))


def test_special_files_are_not_specs(tmp_path):
    """/dev/zero has size 0 and grew to gigabytes; a FIFO blocked the read."""
    import os

    fifo = tmp_path / "spec.yaml"
    os.mkfifo(fifo)
    for path in (Path("/dev/zero"), fifo):
        with pytest.raises(SpecError, match="not a regular file"):
            spec.load(path)


def test_an_absurd_wind_speed_is_refused(write_spec):
    # Max_wind_m_s: 1e9 allocated 24 GB in the stall sweep
    from tests.conftest import TURBINES

    text = (TURBINES / "stall-rotor-1mw.yaml").read_text()
    assert "aeroelastic:" in text
    text = text.replace("max_wind_m_s: {value: 25,", "max_wind_m_s: {value: 1.0e9,", 1)
    assert "1.0e9" in text
    with pytest.raises(SpecError, match="max_wind_m_s: Input should be less than or equal to 100"):
        spec.load(write_spec(text))


def _readme_aerodynamics() -> tuple[str, str]:
    """The head of a small spec and the user guide's documented `aerodynamics` block."""
    from tests.conftest import ROOT

    readme = (ROOT / "docs" / "guide.md").read_text(encoding="utf-8")
    block = re.search(r"```yaml\n(aerodynamics:\n.*?)```", readme, re.S)
    assert block is not None
    head = (
        "wtvib: 1\nturbine: {name: T, rotor_diameter_m: 40, rated_power_kw: 500}\n"
        "rotor: {blades: 3, orientation: upwind, hub: rigid, speed: {min_rpm: 10, max_rpm: 30}}\n"
    )
    return head, block.group(1)


def test_the_readmes_aerodynamics_example_is_a_valid_block(write_spec):
    """The README's documented `aerodynamics` block loads as written, and its mistakes are
    one line with the field (a station beyond the tip, an aerofoil not defined)."""

    head, text = _readme_aerodynamics()
    loaded = spec.load(write_spec(head + text))
    assert loaded.aerodynamics is not None and loaded.aerodynamics.control.min_pitch is not None
    with pytest.raises(SpecError, match="beyond the rotor radius"):
        spec.load(write_spec(head.replace("rotor_diameter_m: 40", "rotor_diameter_m: 30") + text))
    with pytest.raises(SpecError, match="not in airfoils"):
        spec.load(write_spec(head + text.replace("airfoil: [foil,", "airfoil: [other,")))


@pytest.mark.parametrize(
    ("old", "new", "said"),
    [
        ("twist_deg: [12,", "twist_deg: [1200,", "twist_deg must lie within ±180"),
        ("chord_m: [1.6,", "chord_m: [160,", "longer than the rotor radius"),
        ("cl: [0, -0.9,", "cl: [0, -1.0e9,", "cl must lie within"),
        ("cd: [0.02, 0.02,", "cd: [0.02, -0.02,", "cd must lie within"),
        ("cut_out_wind_m_s: 25", "cut_out_wind_m_s: 2", "must be below cut_out_wind_m_s"),
    ],
)
def test_aerodynamics_mistakes_are_one_line(write_spec, old, new, said):
    """Magnitudes no rotor has (the extreme-value campaign's class) are refused with the field, not
    solved."""
    head, text = _readme_aerodynamics()
    assert old in text
    with pytest.raises(SpecError, match=re.escape(said)) as err:
        spec.load(write_spec(head + text.replace(old, new)))
    assert err.value.path is not None and err.value.path.startswith("aerodynamics")


@pytest.mark.parametrize(
    ("entry", "message"),
    [
        ("{frequency_hz: 1.0, speeds: {rpm: [10, 5], frequency_hz: [1.1, 1.2]}}", "increase"),
        ("{frequency_hz: 1.0, speeds: {rpm: [0, 5], frequency_hz: [1.1]}}", "values"),
        ("{frequency_hz: 1.0, speeds: {rpm: [0, 5], frequency_hz: [1.5, 1.2]}}", "agree"),
        (
            "{frequency_hz: 1.0, southwell: 1.2, speeds: {rpm: [0, 5], frequency_hz: [1, 1.2]}}",
            "not both",
        ),
    ],
)
def test_a_speed_table_is_validated(write_spec, entry, message):
    """A mode's frequency over rotor speed (measured Campbell curves) must be a
    table that increases in rpm, has a frequency per speed, agrees with the standstill value
    at 0 rpm and does not come with a Southwell coefficient too."""
    path = write_spec(extra=f"blade:\n  modes:\n    flap1: {entry}\n")
    with pytest.raises(spec.SpecError, match=message):
        spec.load(path)


def test_a_misspelt_key_names_itself_and_the_field_it_should_be(write_spec):
    """A key typo used to report only "required field is missing (and 1 more
    problem)" on the missing field's parent, never naming the unknown key."""
    extra = (
        "tower:\n  sections:\n    height_m: [0, 60]\n    outer_diamter_m: [4, 4]\n"
        "    wall_thickness_m: [0.03, 0.03]\n"
        "  material: {youngs_modulus_pa: 2.1e11, density_kg_m3: 7850}\n"
        "tower_head: {mass_kg: 150000}\n"
    )
    text = spec_text().replace("tower:\n  modes:\n    fa1: 0.5\n", extra)
    assert "outer_diamter_m" in text
    path = write_spec(text)
    with pytest.raises(SpecError) as exc:
        spec.load(path)
    message = str(exc.value)
    assert "outer_diamter_m: unknown field" in message
    assert "did you mean 'outer_diameter_m'" in message and "more problem" not in message


def test_a_spec_with_full_mode_entries_serialises_without_warnings():
    """A mode given as a mapping (frequency, damping, speeds) is a ModeSpec after
    validation; model_dump (the Monte Carlo rebuilds specs from it) must take it as one:
    the discriminator once tagged it "number" and pydantic warned on every dump."""
    import warnings

    from tests.conftest import TURBINES
    from wtvib.spec import from_data

    s = spec.load(TURBINES / "darrieus.yaml")  # its modes carry measured speed tables
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        data = s.model_dump()
    assert isinstance(data["blade"]["modes"]["flap1"], dict)
    assert from_data(data).model_dump() == data
