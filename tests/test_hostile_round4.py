"""Hostile input, round four: batch integrity, outputs that never destroy an
input, impossible turbines that never pass, numbers only as the formats write them, the
environment's faults as one line, and processes that never outlive their parent.

Built as the campaign was: each class is a generator over the input formats (spec, windIO,
ElastoDyn deck, Campbell CSV, HAWCStab2 .cmb) or the output paths (report, check's
Campbell CSV and out-dir, convert, batch), the campaign's own examples among the cases;
tests/FUZZ.md records the campaign and its tally."""

import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from typer.testing import CliRunner

from wtvib.cli import app
from wtvib.workflows import batch

from .conftest import TURBINES, edited_reference

runner = CliRunner()
DATA = Path(__file__).parent / "data"
ED = "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"
TOWER = "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat"
FAST = TURBINES / "mod-0.yaml"  # the quickest catalogue audit (0.5 s)
WTVIB = [sys.executable, "-m", "wtvib"]


def _one_line_exit_2(args: list[str], *words: str) -> str:
    result = runner.invoke(app, args)
    assert result.exit_code == 2, result.output
    lines = [ln for ln in result.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), result.output
    assert "Traceback" not in result.output
    for w in words:
        assert w in lines[0], lines[0]
    return lines[0]


def _spec(tmp_path: Path, name: str = "t.yaml", source: Path = FAST, edit=None) -> Path:
    text = source.read_text()
    if edit is not None:
        assert edit[0] in text, edit
        text = text.replace(*edit)
    path = tmp_path / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


# --- Data loss in batch: output names unique by construction --------------------------

COLLIDING = [
    ["a/b.yaml", "c/b.yaml", "a__b.yaml"],  # the campaign's example: two stems a__b
    ["summary.yaml", "input__summary.yaml"],
    ["x.yml", "x__yml.yaml", "x.yaml"],
    ["X.yaml", "x.yaml"],  # one name on a case-insensitive file system
    ["run-metadata.yaml", "audit.yaml", "Summary.yaml"],
    ["d/e/f.yaml", "g/e/f.yaml", "d__e__f.yaml", "e__f.yaml", "f.yaml"],
    ["t.yaml", "t--2.yaml", "sub/t.yaml"],
]


@pytest.mark.parametrize("names", COLLIDING, ids=lambda n: "+".join(n))
def test_output_stems_are_unique_and_never_the_batchs_own(tmp_path, names):
    paths = [tmp_path / n for n in names]
    keys = batch.output_keys(paths)
    folded = [k.casefold() for k in keys]
    assert len(set(folded)) == len(keys), keys
    reserved = {r.casefold() for r in batch.RESERVED}
    assert not reserved & set(folded), keys


def test_a_batch_of_colliding_names_writes_every_turbines_files(tmp_path):
    """The campaign's example end to end: three inputs, three reports, none overwritten."""
    folder = tmp_path / "in"
    for n in COLLIDING[0]:
        _spec(folder, n)
    result = runner.invoke(app, ["batch", str(folder), "-o", str(tmp_path / "out"), "--no-plots"])
    assert result.exit_code in (0, 1), result.output
    reports = sorted((tmp_path / "out").glob("*.json"))
    sources = {json.loads(p.read_text()).get("turbine", {}).get("source_file") for p in reports}
    assert len(sources - {None}) == 3, [p.name for p in reports]


# --- An input destroyed by its own output -------------------------------------------


def _outputs_over(spec: Path) -> list[list[str]]:
    return [
        ["report", str(spec), "-o", str(spec), "--force"],
        ["check", str(spec), "--campbell-csv", str(spec), "--force", "--no-plots"],
        ["convert", str(spec), "-o", str(spec), "--force"],
    ]


@pytest.mark.parametrize("case", range(3), ids=["report", "campbell-csv", "convert"])
def test_no_output_replaces_an_input_of_the_same_run(tmp_path, case):
    spec = _spec(tmp_path)
    before = spec.read_bytes()
    _one_line_exit_2(_outputs_over(spec)[case], "is an input of this run")
    assert spec.read_bytes() == before


def test_a_deck_file_is_never_replaced_by_convert(shared, tmp_path):
    folder = edited_reference(shared, tmp_path, "NREL5MW", ED, "87.6   TowerHt", "87.6   TowerHt")
    for target in (folder / ED, folder / TOWER, folder / "NREL-5MW.fst"):
        before = target.read_bytes()
        args = ["convert", str(folder / "NREL-5MW.fst"), "-o", str(target), "--force"]
        _one_line_exit_2(args, "is an input of this run")
        assert target.read_bytes() == before


def test_convert_replaces_its_own_spec_while_unedited(tmp_path):
    """A spec convert wrote is replaced without --force; once edited, only with it (the
    header's digest says which)."""
    src = _spec(tmp_path, "src.yaml")
    out = tmp_path / "out.yaml"
    for _ in range(2):
        result = runner.invoke(app, ["convert", str(src), "-o", str(out)])
        assert result.exit_code == 0, result.output
    out.write_text(out.read_text() + "# an engineer's note\n")
    _one_line_exit_2(["convert", str(src), "-o", str(out)], "edited since", "--force")
    result = runner.invoke(app, ["convert", str(src), "-o", str(out), "--force"])
    assert result.exit_code == 0 and "an engineer's note" not in out.read_text()


# --- Impossible turbines never pass --------------------------------------------------

SPEC_GEOMETRY = [
    # the campaign's example: a table stopping at 28 m under height_m 56
    (
        "tjaereborg.yaml",
        ("height_m: [0, 14, 28, 42, 56]", "height_m: [0, 7, 14, 21, 28]"),
        "tower.sections.height_m",
    ),
    (
        "tjaereborg.yaml",
        ("height_m: [0, 14, 28, 42, 56]", "height_m: [0, 14, 28, 42, 90]"),
        "tower.sections.height_m",
    ),
    (
        "nrel-5mw.yaml",
        ("hub_height_m: {value: 90,", "hub_height_m: {value: 30,"),
        "the blade tips would strike the ground",
    ),
    # a point mass or a water table beyond the tower's stations made the tower that much
    # longer (the mesh took their heights as nodes, the last properties carried on)
    (
        "iea-15mw-monopile.yaml",
        ("height_m: {value: 45, provenance", "height_m: {value: 450, provenance"),
        "point_masses[0] at 450 m is not on the tower",
    ),
]


@pytest.mark.parametrize(("name", "edit", "words"), SPEC_GEOMETRY)
def test_a_spec_with_geometry_no_turbine_has_is_refused_with_its_line(tmp_path, name, edit, words):
    spec = _spec(tmp_path, source=TURBINES / name, edit=edit)
    line = _one_line_exit_2(["check", str(spec), "--no-plots"], words)
    assert f"{spec}:" in line  # file and line


DECK_GEOMETRY = [
    ("87.6   TowerHt", "10   TowerHt", "TowerHt"),  # under 63 m blades
    ("-5   ShftTilt", "90   ShftTilt", "ShftTilt"),
    ("-2.5   PreCone(1)", "90   PreCone(1)", "PreCone(1)"),
    ("-2.5   PreCone(2)", "-60   PreCone(2)", "PreCone(2)"),
]


@pytest.mark.parametrize(("old", "new", "key"), DECK_GEOMETRY, ids=[c[2] for c in DECK_GEOMETRY])
def test_a_deck_with_geometry_no_turbine_has_is_refused_with_its_line(
    shared, tmp_path, old, new, key
):
    folder = edited_reference(shared, tmp_path, "NREL5MW", ED, old, new)
    line = _one_line_exit_2(["check", str(folder / "NREL-5MW.fst"), "--no-plots"], key)
    assert f"{ED}:" in line


@pytest.mark.parametrize(
    "args",
    [
        ["--blades", "3"],  # the spec gives them
        ["--samples", "50"],  # without --uncertainty
        ["--seed", "1"],
    ],
    ids=["blades", "samples", "seed"],
)
def test_an_option_that_does_not_apply_says_so(args):
    _one_line_exit_2(["check", str(FAST), "--no-plots", *args], args[0])


# --- Numbers only as the formats write them ------------------------------------------

NOT_NUMBERS = ["8_7.6", "٨٧.٦", "８７.６", "87.6.1", "0x57", "nan", "-inf", "1e999"]


@pytest.mark.parametrize("bad", NOT_NUMBERS)
def test_a_deck_number_is_fortrans_not_pythons(shared, tmp_path, bad):
    folder = edited_reference(shared, tmp_path, "NREL5MW", ED, "87.6   TowerHt", f"{bad}   TowerHt")
    _one_line_exit_2(["check", str(folder / "NREL-5MW.fst"), "--no-plots"], "TowerHt", f"{ED}:")


@pytest.mark.parametrize("bad", NOT_NUMBERS[:5])
def test_a_cmb_number_is_a_number(tmp_path, bad):
    text = (
        (DATA / "campbell" / "hawcstab2" / "blade.cmb").read_text().replace("0.610872E+00", bad, 1)
    )
    path = tmp_path / "x.cmb"
    path.write_text(text)
    _one_line_exit_2(["check", str(path), "--no-plots"], "x.cmb:3:", "not a finite number")


def _campbell_csv(rows: list[str]) -> str:
    return "mode,rpm,frequency_hz\n" + "".join(r + "\n" for r in rows)


CSV_CASES = [
    (["tower.fa1,10,0.3", "tower.fa1,10,0.4"], "given twice"),  # conflicting duplicate
    (["tower.fa1,10,0.3", "tower.fa1,8_7,0.4"], "8_7"),
    (["tower.fa1,10,٠٫٣"], "٠٫٣"),
]


@pytest.mark.parametrize(("rows", "words"), CSV_CASES, ids=["duplicate", "underscore", "arabic"])
def test_a_campbell_csv_is_read_strictly(tmp_path, rows, words):
    path = tmp_path / "c.csv"
    path.write_text(_campbell_csv(rows))
    _one_line_exit_2(["check", str(path), "--blades", "3", "--no-plots"], "c.csv:", words)


def test_a_cmb_point_given_twice_with_other_numbers_is_refused(tmp_path):
    lines = (DATA / "campbell" / "hawcstab2" / "blade.cmb").read_text().splitlines()
    twin = lines[3].split()
    twin[1] = "0.999"
    path = tmp_path / "x.cmb"
    path.write_text("\n".join([*lines, " ".join(twin)]) + "\n")
    _one_line_exit_2(["check", str(path), "--no-plots"], "given twice", "also on line 4")
    path.write_text("\n".join([*lines, lines[3]]) + "\n")  # the same row again: read once
    assert runner.invoke(app, ["check", str(path), "--no-plots"]).exit_code in (0, 1)


def test_a_key_given_twice_with_other_values_is_refused(shared, tmp_path):
    folder = edited_reference(
        shared, tmp_path, "NREL5MW", ED, "          3   NumBl", "          3   NumBl\n 2   NumBl"
    )
    _one_line_exit_2(["check", str(folder / "NREL-5MW.fst"), "--no-plots"], "NumBl", "twice")


WINDIO_EDITS = [
    ("values: [5.99, 5.93,", "values: [-5.99, 5.93,", "outer_diameter"),
    ("values: [0.05697, 0.05697,", "values: [-0.05697, 0.05697,", "thickness"),
    ("values: [0.05697, 0.05697,", "values: [3.5, 0.05697,", "half the diameter"),
    (
        "            outer_diameter:\n                grid: *grid_tower",
        "            outer_diameter:\n                grid: [0., 0.2, 0.1, 0.3, 0.4, 0.5, 0.6,"
        " 0.7, 0.8, 0.9, 1.]",
        "increase",
    ),
]


@pytest.mark.parametrize(("old", "new", "words"), WINDIO_EDITS, ids=["d", "wall", "thick", "grid"])
def test_a_windio_tower_that_cannot_be_is_refused_with_its_line(shared, tmp_path, old, new, words):
    source = shared / "reference" / "IEA3.4" / "IEA-3.4-130-RWT.yaml"
    path = _spec(tmp_path, "w.yaml", source=source, edit=(old, new))
    _one_line_exit_2(["check", str(path), "--no-plots"], "w.yaml:", words)


def test_a_quoted_file_name_with_a_space_is_read(shared, tmp_path):
    """TwrFile "my tower.dat": legal in OpenFAST (a quoted string), refused as missing."""
    quoted = f'"{TOWER}"    TwrFile'
    folder = edited_reference(shared, tmp_path, "NREL5MW", ED, quoted, '"my tower.dat"    TwrFile')
    (folder / TOWER).rename(folder / "my tower.dat")
    result = runner.invoke(app, ["check", str(folder / "NREL-5MW.fst"), "--no-plots"])
    assert result.exit_code in (0, 1), result.output


def test_a_quoted_newline_in_a_csv_cell_is_read(tmp_path):
    path = tmp_path / "c.csv"
    path.write_text('mode,rpm,frequency_hz,description\ntower.fa1,10,0.3,"first\nbending"\n'
                    "tower.fa1,12,0.3,x\n")  # fmt: skip
    result = runner.invoke(app, ["check", str(path), "--blades", "3", "--no-plots"])
    assert result.exit_code in (0, 1), result.output


# --- Batch names what it leaves out -------------------------------------------------


def test_a_batch_audits_each_file_once_and_names_what_it_skips(tmp_path):
    folder = tmp_path / "in"
    spec = _spec(folder, "t.yaml")
    (folder / "link.yaml").symlink_to(spec)
    shutil.copy(DATA / "campbell" / "hawcstab2" / "blade.cmb", folder / "blade.cmb")
    result = runner.invoke(
        app, ["batch", str(folder), str(spec), "-o", str(tmp_path / "out"), "--no-plots"]
    )
    assert result.exit_code in (0, 1), result.output
    meta = json.loads((tmp_path / "out" / "run-metadata.json").read_text())
    skipped = {Path(s["file"]).name: s["why"] for s in meta["skipped"]}
    assert "the same file as" in skipped.pop("link.yaml", skipped.pop("t.yaml", ""))
    assert "HAWCStab2" in skipped["blade.cmb"]
    assert "skipped" in result.stderr and "blade.cmb" in result.stderr
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert len(summary["turbines"]) == 1


# --- Locks ------------------------------------------------------------------------


@pytest.mark.parametrize("content", ["99999999999999999999", "", "0", "-1", "abc", "1 2"])
def test_a_lock_that_names_no_live_process_does_not_block_the_folder(tmp_path, content):
    lock = tmp_path / batch.FolderLock.NAME
    lock.write_text(content)
    os.utime(lock, (time.time() - 3600, time.time() - 3600))  # not a writer starting now
    with batch.FolderLock(tmp_path):
        assert lock.read_text().strip() == str(os.getpid())
    assert not lock.exists()


# --- The environment's faults: one line, exit 2 -------------------------------------


def _wtvib(*args: str, **kwargs) -> subprocess.CompletedProcess:  # type: ignore[type-arg]
    env = {**os.environ, "MPLBACKEND": "Agg", **kwargs.pop("env", {})}
    return subprocess.run(
        [*WTVIB, *args], capture_output=True, env=env, timeout=120, check=False, **kwargs
    )


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="no /dev/full on this system")
@pytest.mark.parametrize("fmt", ["text", "json"])
def test_a_full_disk_on_stdout_is_one_line(fmt):
    with open("/dev/full", "w") as full:
        env = {**os.environ, "MPLBACKEND": "Agg"}
        done = subprocess.run(
            [*WTVIB, "check", str(FAST), "--no-plots", "-f", fmt],
            stdout=full, stderr=subprocess.PIPE, env=env, timeout=120, check=False,
        )  # fmt: skip
    err = done.stderr.decode()
    assert done.returncode == 2, err
    assert err.count("\n") == 1 and "standard output" in err and "Traceback" not in err


def test_a_closed_stdout_discards_the_report_and_keeps_the_verdict():
    done = subprocess.run(
        [*WTVIB, "check", str(FAST), "--no-plots"],
        stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, timeout=120, check=False,
        env={**os.environ, "MPLBACKEND": "Agg"},
        preexec_fn=lambda: os.close(1),
    )  # fmt: skip
    assert done.returncode in (0, 1) and b"Traceback" not in done.stderr, done.stderr


def test_an_ascii_terminal_gets_escapes_and_json_stays_json():
    spec = TURBINES / "tjaereborg.yaml"
    text = _wtvib("check", str(spec), "--no-plots", env={"PYTHONIOENCODING": "ascii"})
    assert text.returncode in (0, 1) and b"Tj\\u00e6reborg" in text.stdout, text.stderr
    doc = _wtvib("check", str(spec), "--no-plots", "-f", "json", env={"PYTHONIOENCODING": "ascii"})
    assert json.loads(doc.stdout)["turbine"]["name"] == "Tjæreborg"


def test_a_file_name_that_is_not_utf8_does_not_stop_the_batch(tmp_path):
    folder = tmp_path / "in"
    folder.mkdir()
    try:
        name = os.fsdecode(b"t\xff.yaml")
        shutil.copy(FAST, folder / name)
    except (OSError, UnicodeError):
        pytest.skip("this file system refuses a name that is not UTF-8")
    _spec(folder, "u.yaml")
    done = _wtvib("batch", str(folder), "-o", str(tmp_path / "out"), "--no-plots")
    assert done.returncode in (0, 1), done.stderr
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert "t\\udcff.yaml" in json.dumps(summary) or "t\udcff" in json.dumps(summary)
    assert len(list((tmp_path / "out").glob("*.json"))) >= 4  # two reports, two summaries


# --- Injection and display ----------------------------------------------------------


@pytest.mark.parametrize("start", ["=", "+", "-", "@"])
def test_a_name_that_would_start_a_formula_is_quoted_in_the_summary_csv(tmp_path, start):
    folder = tmp_path / "in"
    _spec(folder, f"{start}cmd.yaml", edit=("name: MOD-0", f'name: "{start}HYPERLINK(1)"'))
    result = runner.invoke(app, ["batch", str(folder), "-o", str(tmp_path / "out"), "--no-plots"])
    assert result.exit_code in (0, 1), result.output
    import csv

    rows = list(csv.DictReader((tmp_path / "out" / "summary.csv").open()))
    assert rows[0]["turbine"] == f"'{start}HYPERLINK(1)"
    assert not rows[0]["file"].startswith(("=", "+", "-", "@", "\t"))


@pytest.mark.parametrize(
    ("cell", "shown"),
    [
        ("\tx", "'\tx"),
        ("\rx", "'\rx"),
        ("-0.5", "-0.5"),
        ("+1e3", "+1e3"),
        ("-x", "'-x"),
        ("a=b", "a=b"),
    ],
)
def test_a_spreadsheet_cell_is_text_unless_it_is_a_number(cell, shown):
    from wtvib.outputs.files import spreadsheet_cell

    assert spreadsheet_cell(cell) == shown


@pytest.mark.parametrize("control", ["\u202e", "\u2066", "\u200f"])
def test_bidi_controls_never_reach_the_terminal(tmp_path, control):
    spec = _spec(tmp_path, edit=("name: MOD-0", f'name: "MOD{control}-0"'))
    for args in (["check", str(spec), "--no-plots"], ["batch", str(spec), "--no-plots", "-o",
                 str(tmp_path / "o")]):  # fmt: skip
        result = runner.invoke(app, args)
        assert control not in result.output
        assert f"\\u{ord(control):04x}" in result.output


# --- Option errors: one line each -------------------------------------------------

OPTION_ERRORS = [
    ["check"],
    ["check", str(FAST), "--jobs", "2"],
    ["check", str(FAST), "--margin"],
    ["check", str(FAST), "--margin", "x"],
    ["check", str(FAST), "--margin", "nan"],
    ["check", str(FAST), "--rpm", "10-20"],
    ["check", str(FAST), "--format", "xml"],
    ["check", str(FAST), "--figures", "some"],
    ["check", str(FAST), "--uncertainty", "--samples", "3"],
    ["batch", "--jobs", "x", str(FAST)],
    ["batch", "--sort", "size", str(FAST)],
    ["report", str(FAST), "-o"],
    ["shapes"],
    ["convert", str(FAST)],
    ["nonsense"],
]


@pytest.mark.parametrize("args", OPTION_ERRORS, ids=lambda a: " ".join(a[:1] + a[2:]))
def test_an_option_error_is_one_line(args):
    _one_line_exit_2(args)


# --- Process hygiene ----------------------------------------------------------------


def _batch_with_workers(tmp_path: Path) -> tuple[subprocess.Popen, list[int]]:  # type: ignore[type-arg]
    folder = tmp_path / "in"
    for i in range(8):
        _spec(folder, f"t{i}.yaml", source=TURBINES / "nrel-5mw.yaml")
    proc = subprocess.Popen(
        [*WTVIB, "batch", str(folder), "-o", str(tmp_path / "out"), "-j", "2"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True,
        env={**os.environ, "MPLBACKEND": "Agg"},
    )  # fmt: skip
    deadline = time.monotonic() + 60
    children: list[int] = []
    while time.monotonic() < deadline and not children:
        time.sleep(0.2)
        out = subprocess.run(["pgrep", "-P", str(proc.pid)], capture_output=True, text=True)
        children = [int(p) for p in out.stdout.split()]
    if not children:
        proc.kill()
        pytest.skip("the batch finished before its workers could be seen")
    return proc, children


def _gone(pids: list[int], within: float) -> bool:
    deadline = time.monotonic() + within
    while time.monotonic() < deadline:
        alive = []
        for p in pids:
            try:
                os.kill(p, 0)
                state = Path(f"/proc/{p}/stat").read_text().split()[2]
                if state != "Z":
                    alive.append(p)
            except (ProcessLookupError, FileNotFoundError):
                pass
        if not alive:
            return True
        time.sleep(0.2)
    return False


@pytest.mark.skipif(
    not sys.platform.startswith("linux") or shutil.which("pgrep") is None,
    reason="the workers are looked up with pgrep and /proc (Linux)",
)
def test_batch_workers_die_with_a_killed_parent_and_release_the_pipe(tmp_path):
    proc, children = _batch_with_workers(tmp_path)
    proc.kill()  # SIGKILL: no handler runs in the parent
    assert _gone(children, within=15.0), children  # the parent-death signal, or the watchdog
    proc.stdout.read()  # EOF: no worker holds the caller's pipe (a hang here fails by timeout)
    proc.wait(timeout=10)


@pytest.mark.skipif(
    not sys.platform.startswith("linux") or shutil.which("pgrep") is None,
    reason="the workers are looked up with pgrep and /proc (Linux)",
)
@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT])
def test_a_signal_ends_the_batch_without_tracebacks(tmp_path, sig):
    proc, children = _batch_with_workers(tmp_path)
    os.killpg(proc.pid, sig)  # as a terminal's Ctrl-C reaches the whole group
    _, err = proc.communicate(timeout=60)
    text = err.decode(errors="replace")
    assert "Traceback" not in text and "Exception ignored" not in text, text
    assert "interrupted" in text
    assert _gone(children, within=15.0)


@pytest.mark.skipif(not hasattr(os, "fork"), reason="fork")
def test_a_worker_forked_as_the_signal_comes_ends_quietly():
    """A worker forked just as Ctrl-C or SIGTERM reaches the whole group still carries the
    batch's handler: there it ends at once with the signal's code, without raising inside
    the fork's bookkeeping ("Exception ignored in _after_fork", once seen in CI, and a
    worker left alive holding the caller's pipe open for the test's whole minute)."""
    from wtvib.workflows.batch import terminate_as_interrupt

    with terminate_as_interrupt():
        pid = os.fork()
        if pid == 0:  # the child, before it could set handlers of its own
            time.sleep(10)
            os._exit(0)
        time.sleep(0.2)
        os.kill(pid, signal.SIGTERM)
        _, status = os.waitpid(pid, 0)
    assert os.WIFEXITED(status) and os.WEXITSTATUS(status) == 128 + signal.SIGTERM


# --- Refusals and warnings name the user's file, not the converted field ------------

DECK_TABLE_CASES = [
    (TOWER, "3.4188300E+11  3.4188300E+11", "3.4188300E+25  3.4188300E+11", 24, "TwFAStif", 2),
    (TOWER, "3.4188300E+11  3.4188300E+11", "3.4188300E+02  3.4188300E+11", 24, "TwFAStif", None),
    ("NRELOffshrBsline5MW_Blade.dat", "4.0063800E+02  5.5283600E+09",
     "4.0063800E+02  5.5283600E+02", 25, "FlpStff", None),
    ("NRELOffshrBsline5MW_Blade.dat", "7.7336300E+02", "7.7336300E+22", 19, "BMassDen", 2),
]  # fmt: skip


@pytest.mark.parametrize(("file", "old", "new", "line", "key", "code"), DECK_TABLE_CASES)
def test_a_deck_tables_odd_station_is_named_by_its_file_line_and_column(
    shared, tmp_path, file, old, new, line, key, code
):
    """The campaign's example: a spike warned as `tower.distributed.ei_fa_nm2[5]`; a
    stiffness of 1e25 said "the tower is not held"."""
    folder = edited_reference(shared, tmp_path, "NREL5MW", file, old, new)
    result = runner.invoke(app, ["check", str(folder / "NREL-5MW.fst"), "--no-plots"])
    said = f"{file}:{line}: {key}"
    if code == 2:
        assert result.exit_code == 2 and said in result.stderr, result.output
    else:
        warned = [ln for ln in result.stderr.splitlines() if "typed wrong" in ln]
        assert warned and said in warned[0], result.stderr
        assert "distributed." not in warned[0] and "structure." not in warned[0]
