"""A newcomer's first hour: the catalogue ships in the wheel and answers to its
names, a typo is answered before the numerical stack is imported, an output file's folder
is never made, the figures of a preset's run do not replace the plain run's, and piped
text is not hard-wrapped."""

import json
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from wtvib.cli import app
from wtvib.workflows import catalogue

from .conftest import TURBINES

runner = CliRunner()


def test_the_catalogue_is_inside_the_package_and_the_repositorys_turbines_is_it():
    """The wheel's package data (pyproject: wtvib/turbines/*.yaml); ``turbines/`` at the
    top of the repository is the same folder."""
    assert catalogue.FOLDER.parent == Path(catalogue.__file__).resolve().parents[1]
    assert {p.name for p in catalogue.files()} == {p.name for p in TURBINES.glob("*.yaml")}
    assert TURBINES.resolve() == catalogue.FOLDER


def test_the_index_is_what_the_audits_say():
    """``wtvib catalogue`` lists from index.json, written from the audits: it must still be
    what they say (rerun ``python -m wtvib.workflows.catalogue`` after changing a turbine)."""
    assert catalogue.entries() == catalogue.index()


def test_catalogue_lists_every_turbine_with_its_story():
    result = runner.invoke(app, ["catalogue", "--format", "json"])
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    names = [t["name"] for t in doc["turbines"]]
    assert names == [p.stem for p in catalogue.files()]
    mod2 = next(t for t in doc["turbines"] if t["name"] == "mod-2")
    assert mod2["tower_class"] == "soft" and "first soft tower" in mod2["story"]
    text = runner.invoke(app, ["catalogue"])
    assert text.exit_code == 0 and "tjaereborg" in text.stdout and "wtvib check NAME" in text.stdout


def test_catalogue_copy_writes_the_specs_and_never_over_a_users_file(tmp_path):
    result = runner.invoke(app, ["catalogue", "--copy", str(tmp_path / "mine")])
    assert result.exit_code == 0, result.output
    copied = sorted(p.name for p in (tmp_path / "mine").glob("*.yaml"))
    assert copied == [p.name for p in catalogue.files()]
    (tmp_path / "mine" / "mod-2.yaml").write_text("# my edits\n")
    again = runner.invoke(app, ["catalogue", "--copy", str(tmp_path / "mine")])
    assert again.exit_code == 2 and "mod-2.yaml exists" in again.stderr
    assert (tmp_path / "mine" / "mod-2.yaml").read_text() == "# my edits\n"


@pytest.mark.parametrize("name", ["mod-2", "MOD-2", "mod-2.yaml"])
def test_check_takes_a_catalogue_turbine_by_name_and_says_so(tmp_path, monkeypatch, name):
    monkeypatch.chdir(tmp_path)  # no file of that name here
    result = runner.invoke(app, ["check", name, "--no-plots", "-f", "json"])
    assert result.exit_code in (0, 1), result.output
    assert "is the catalogue's mod-2.yaml" in result.stderr
    assert json.loads(result.stdout)["turbine"]["name"] == "MOD-2"


def test_a_file_of_that_name_wins_over_the_catalogue(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "mod-2").write_text("wtvib: 1\n")  # the user's own file: read, not replaced
    result = runner.invoke(app, ["check", "mod-2", "--no-plots"])
    assert result.exit_code == 2 and "catalogue" not in result.stderr


def test_a_typo_is_answered_before_numpy_is_imported(tmp_path):
    """A missing file is one line from the command-line layer alone: numpy, scipy and
    matplotlib are not imported to say it (measured: 0.17 s beside 1.8 s before)."""
    code = (
        "import sys\n"
        "from wtvib import cli\n"
        "sys.argv = ['wtvib', 'check', 'no-such-turbine.yaml']\n"
        "try:\n    cli.main()\nexcept SystemExit as e:\n    code = e.code\n"
        "heavy = [m for m in ('numpy', 'scipy', 'matplotlib') if m in sys.modules]\n"
        "print(code, heavy, file=sys.stderr)\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=tmp_path, check=False
    )
    assert "no-such-turbine.yaml: no such file" in done.stderr
    assert done.stderr.strip().endswith("2 []"), done.stderr


@pytest.mark.parametrize(
    "args",
    [
        ["report", str(TURBINES / "mod-2.yaml"), "-o"],
        ["check", str(TURBINES / "mod-2.yaml"), "--no-plots", "--campbell-csv"],
    ],
    ids=["report", "campbell-csv"],
)
def test_an_output_files_folder_is_never_made(tmp_path, args):
    target = tmp_path / "nonexistent" / "x.out"
    result = runner.invoke(app, [*args, str(target)])
    assert result.exit_code == 2 and "does not exist" in result.stderr, result.output
    assert not target.parent.exists()


def test_an_out_dir_is_made(tmp_path):
    result = runner.invoke(
        app, ["check", str(TURBINES / "mod-2.yaml"), "-d", str(tmp_path / "a/b")]
    )
    assert result.exit_code in (0, 1) and (tmp_path / "a/b/mod-2.campbell.png").is_file()


def test_a_presets_figures_do_not_replace_the_plain_runs(tmp_path):
    spec = str(TURBINES / "mod-2.yaml")
    for extra in ([], ["--preset", "gl2010"], ["--margin", "0.15"]):
        result = runner.invoke(app, ["check", spec, "-d", str(tmp_path), *extra])
        assert result.exit_code in (0, 1), result.output
    names = {p.name for p in tmp_path.glob("*.campbell.png")}
    assert {"mod-2.campbell.png", "mod-2.gl2010.campbell.png"} <= names
    assert "mod-2.margin15.campbell.png" in names


def test_piped_text_is_not_hard_wrapped():
    """On a pipe, a finding is one line however long (``window … | less`` had "74.3%)"
    alone on a line); the panels keep their width."""
    done = subprocess.run(
        [sys.executable, "-m", "wtvib", "window", str(TURBINES / "mod-2.yaml"), "--no-plots"],
        capture_output=True, text=True, check=False, env={"COLUMNS": "60", "PATH": ""},
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    lines = [ln for ln in done.stdout.splitlines() if ln.startswith("  tower.fa1 = ")]
    assert lines and lines[0].rstrip().endswith("%)"), done.stdout


def test_convert_writes_a_floating_deck_as_a_spec_that_loads(tmp_path):
    """r-test's OC4 semisubmersible: the platform's numbers came from numpy and YAML could
    not write them (an internal error); lists of numbers are written one to a line."""
    import tarfile

    from wtvib import spec

    archive = Path(__file__).parent / "data" / "openfast_decks" / "rtest_floating.tar.gz"
    with tarfile.open(archive) as tar:
        tar.extractall(tmp_path, filter="data")
    fst = next(tmp_path.rglob("5MW_OC4Semi_Linear.fst"))
    out = tmp_path / "oc4.yaml"
    result = runner.invoke(app, ["convert", str(fst), "-o", str(out)])
    assert result.exit_code == 0, result.output
    loaded = spec.load(out)
    assert loaded.tower.foundation is not None and loaded.tower.foundation.kind == "platform"
    assert "coefficients: [" in out.read_text()


def test_a_broken_spec_is_answered_before_the_models_are_imported(tmp_path):
    """A spec without its version key: read, refused, before the audit's models and
    matplotlib are imported and before the drawing process is started (the error waited
    for it to finish importing matplotlib: 0.48 s, now 0.27 s here)."""
    (tmp_path / "t.yaml").write_text("turbine: {name: x}\n")
    code = (
        "import os, sys\n"
        "from wtvib import cli\n"
        "sys.argv = ['wtvib', 'check', 't.yaml']\n"
        "try:\n    cli.main()\nexcept SystemExit as e:\n    code = e.code\n"
        "late = ('wtvib.audit', 'matplotlib', 'wtvib.outputs.plots.render')\n"
        "heavy = [m for m in late if m in sys.modules]\n"
        "print(code, heavy, file=sys.stderr)\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=tmp_path, check=False
    )
    assert "the version key 'wtvib: 1' is missing" in done.stderr
    assert done.stderr.strip().endswith("2 []"), done.stderr
