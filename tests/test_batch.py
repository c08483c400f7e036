"""Batch audits: a catalogue folder with a corrupt file and a failing turbine."""

import json
import shutil
from pathlib import Path

import pytest
from typer.testing import CliRunner

from tests.conftest import TURBINES, spec_text
from wtvib.cli import app
from wtvib.workflows import batch

runner = CliRunner()


@pytest.fixture
def folder(tmp_path):
    """Three good specs (pass, warn, fail), one corrupt file, one non-spec YAML."""
    d = tmp_path / "cat"
    d.mkdir()
    for name in ("mod-2", "wts-4", "wka-60"):
        shutil.copy(TURBINES / f"{name}.yaml", d)
    (d / "corrupt.yaml").write_bytes(b"wtvib: 1\nturbine: {name: [unclosed\n")
    (d / "sub").mkdir()
    (d / "sub" / "other.yml").write_text(
        spec_text(blades=3, speed="fixed_rpm: 30", modes="fa1: 0.75")
    )
    return d


def test_discover_finds_specs_recursively_in_a_stable_order(folder):
    names = [p.name for p in batch.discover([folder])]
    assert names == ["corrupt.yaml", "mod-2.yaml", "other.yml", "wka-60.yaml", "wts-4.yaml"]


def test_output_keys_are_unique():
    from pathlib import Path

    keys = batch.output_keys([Path("a/x.yaml"), Path("b/x.yaml"), Path("b/y.yaml")])
    assert keys == ["a__x", "b__x", "y"]


def test_one_bad_file_never_stops_the_run(folder):
    items = batch.run(batch.discover([folder]), jobs=2, plots=False)
    outcomes = {i.key: i.outcome for i in items}
    assert outcomes == {
        "corrupt": "input-error",
        "mod-2": "pass",
        "other": "pass",
        "wka-60": "fail",
        "wts-4": "warn",
    }
    bad = items[0]
    assert "corrupt.yaml:3: not valid YAML" in str(bad.error)
    assert "while parsing a flow sequence on line 2" in str(bad.error)
    assert batch.exit_code(items) == 2
    assert batch.exit_code([i for i in items if i.outcome != "input-error"]) == 1


def test_parallel_and_serial_runs_agree(folder):
    paths = batch.discover([folder])
    serial = [i.report for i in batch.run(paths, jobs=1, plots=False)]
    parallel = [i.report for i in batch.run(paths, jobs=2, plots=False)]
    assert serial == parallel


def test_cli_batch_writes_every_output_and_exits_with_the_worst(folder, tmp_path):
    out = tmp_path / "audit"
    result = runner.invoke(app, ["batch", str(folder), "--out", str(out), "-j", "2"])
    assert result.exit_code == 2
    assert "input error" in result.stdout and "corrupt.yaml" in result.stdout
    files = {p.name for p in out.iterdir()}
    for key in ("mod-2", "wts-4", "wka-60", "other"):
        assert f"{key}.json" in files and f"{key}.campbell.png" in files
        assert f"{key}.campbell.csv" in files  # the Campbell data beside the report
    assert {"summary.json", "summary.csv", "audit.pdf", "run-metadata.json"} <= files
    assert not [f for f in files if f.endswith(".tmp")]
    summary = json.loads((out / "summary.json").read_text())
    assert summary["counts"] == {
        "pass": 2,
        "info": 0,
        "warn": 1,
        "fail": 1,
        "input-error": 1,
        "internal-error": 0,
    }
    meta = json.loads((out / "run-metadata.json").read_text())
    assert set(meta["timings_s"]["wka-60"]) == {"load", "solve", "plot", "write"}


def test_batch_outputs_are_byte_identical_across_runs(folder, tmp_path):
    a, b = tmp_path / "a", tmp_path / "b"
    for out in (a, b):
        runner.invoke(app, ["batch", str(folder), "--out", str(out), "--no-plots"])
    for name in ("summary.json", "summary.csv", "wka-60.json", "mod-2.json"):
        assert (a / name).read_bytes() == (b / name).read_bytes()


def test_batch_json_is_one_document(folder):
    result = runner.invoke(app, ["batch", str(folder), "--format", "json", "--no-plots"])
    doc = json.loads(result.stdout)
    assert doc["schema"] == "wtvib-batch-results/1"
    assert [r["outcome"] for r in doc["results"]] == ["input-error", "pass", "pass", "fail", "warn"]


def test_sort_by_verdict_puts_the_worst_first(folder):
    items = batch.run(batch.discover([folder]), jobs=1, plots=False)
    assert [i.outcome for i in batch.sort_items(items, "verdict")] == [
        "input-error",
        "fail",
        "warn",
        "pass",
        "pass",
    ]


def test_rerun_into_the_same_folder_replaces_only_own_files(folder, tmp_path):
    out = tmp_path / "audit"
    assert runner.invoke(app, ["batch", str(folder), "-o", str(out), "--no-plots"]).exit_code == 2
    assert runner.invoke(app, ["batch", str(folder), "-o", str(out), "--no-plots"]).exit_code == 2
    (out / "summary.csv").write_text("my own notes\n")
    result = runner.invoke(app, ["batch", str(folder), "-o", str(out), "--no-plots"])
    assert "was not written by wtvib" in result.stderr
    assert (out / "summary.csv").read_text() == "my own notes\n"


def test_empty_folder_is_an_input_error(tmp_path):
    result = runner.invoke(app, ["batch", str(tmp_path)])
    assert result.exit_code == 2 and "no spec files" in result.stderr


def test_interrupted_batch_says_what_was_completed(folder, tmp_path, monkeypatch):
    real_run = batch.run

    def interrupted(paths, **kw):
        def stop_after_first(item):
            kw_done(item)
            raise KeyboardInterrupt

        kw_done = kw["on_done"]
        return real_run(paths, **{**kw, "jobs": 1, "on_done": stop_after_first})

    monkeypatch.setattr(batch, "run", interrupted)
    out = tmp_path / "audit"
    result = runner.invoke(app, ["batch", str(folder), "--out", str(out), "--no-plots"])
    assert result.exit_code == 130
    assert "interrupted: 1 of 5 inputs completed" in result.stderr
    # What is complete is written — its summary says so — and nothing is half
    summary = json.loads((out / "summary.json").read_text())
    assert len(summary["turbines"]) == 1
    assert json.loads((out / "run-metadata.json").read_text())["interrupted"] is True
    assert list(out.glob(".*.tmp")) == [] and not (out / batch.FolderLock.NAME).exists()


def test_a_10_kw_and_a_22_mw_turbine_in_one_batch(tmp_path):
    windio = pytest.importorskip("windIO", reason="the windio package (dev extra) is needed")
    big = Path(windio.__file__).parent / "examples" / "turbine" / "IEA-22-280-RWT.yaml"
    small = tmp_path / "small.yaml"
    small.write_text(
        spec_text(blades=3, speed="fixed_rpm: 120", modes="fa1: 4.5\nss1: 4.4")
        + "blade: {modes: {flap1: 6.0, edge1: 11.0}}\n"
    )
    items = batch.run([small, big], jobs=2, plots=False)
    assert [i.outcome for i in items] != ["input-error", "input-error"]
    for it in items:
        assert it.report is not None, it.error
        assert all(0 <= m["frequency_hz"] < 1e4 for m in it.report["modes"])


def test_an_unexpected_exception_in_one_turbine_is_that_rows_internal_error(folder, tmp_path):
    """One turbine whose audit raises something wtvib did not expect (here a
    LinAlgError, as the Floquet check once did) must not empty the batch: its row is an
    internal error naming the exception, the rest completes, summaries and PDF are written,
    and the exit code is 3 — never 1, the code of a FAIL."""
    import numpy as np

    from wtvib import audit

    real = audit.run

    def flaky(turbine, *args, **kwargs):  # type: ignore[no-untyped-def]
        if turbine.turbine.name.startswith("WKA"):
            raise np.linalg.LinAlgError("Array must not contain infs or NaNs")
        return real(turbine, *args, **kwargs)

    out = tmp_path / "audit"
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(audit, "run", flaky)
        result = runner.invoke(app, ["batch", str(folder), "-o", str(out), "-j", "1"])
    assert result.exit_code == batch.EXIT_INTERNAL == 3
    summary = json.loads((out / "summary.json").read_text())
    rows = {Path(r["file"]).name: r for r in summary["turbines"]}
    assert rows["wka-60.yaml"]["verdict"] == "internal-error"
    assert "LinAlgError" in rows["wka-60.yaml"]["message"]
    assert summary["counts"]["internal-error"] == 1 and summary["counts"]["fail"] == 0
    assert (out / "audit.pdf").exists() and (out / "mod-2.json").exists()
    assert "internal error" in result.stdout


def test_worst_check_is_the_one_that_decided_the_verdict():
    checks = [
        {"id": "a", "status": "info", "margin": 0.0},
        {"id": "b", "status": "pass", "margin": 0.5},
    ]
    assert batch.worst_check(checks) is None  # a passing turbine: no info row as "worst"
    checks.append({"id": "c", "status": "warn", "margin": 0.2})
    assert batch.worst_check(checks)["id"] == "c"


def test_report_and_batch_take_the_operating_and_rule_options(shared, tmp_path):
    deck = shared / "reference" / "NREL5MW" / "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"
    args = ["--rpm", "6.9:12.1", "--preset", "gl2010", "--no-plots", "-f", "json"]
    result = runner.invoke(app, ["batch", str(deck), *args])
    report = json.loads(result.stdout)["results"][0]["report"]
    assert report["operation"]["steady_rpm"] == [[6.9, 12.1]]
    assert report["rule"]["preset"] == "gl2010"


def test_output_keys_never_collide_nor_take_the_batch_own_names():
    """Two files a/t/x.yaml and b/t/x.yaml both wrote t__x.json, y.yaml and y.yml both
    y.json, and an input named summary.yaml was overwritten by the summary."""
    paths = [Path(p) for p in ("a/t/x.yaml", "b/t/x.yaml", "y.yaml", "y.yml", "summary.yaml")]
    keys = batch.output_keys(paths)
    assert keys == ["a__t__x", "b__t__x", "y__yaml", "y__yml", "input__summary"]
    assert len(set(keys)) == len(keys) and not set(keys) & batch.RESERVED


def test_two_batches_never_write_into_one_folder(folder, tmp_path):
    """Two batches into one --out interleaved (the summary disagreed with the
    reports). A live lock refuses the second; a stale one (its process gone) is taken over."""
    import os

    out = tmp_path / "audit"
    out.mkdir()
    lock = out / batch.FolderLock.NAME
    lock.write_text(str(os.getpid()))  # a live process holds it
    result = runner.invoke(app, ["batch", str(folder), "-o", str(out), "--no-plots"])
    assert result.exit_code == 2 and "another wtvib batch is writing into" in result.stderr
    lock.write_text("999999999")  # no such process
    result = runner.invoke(app, ["batch", str(folder), "-o", str(out), "--no-plots"])
    assert result.exit_code == 2 and (out / "summary.json").exists()  # (2: the corrupt file)
    assert not lock.exists()  # released


def test_a_verdict_resting_on_a_warning_is_marked_in_every_summary(shared, tmp_path):
    """WindPACT's deck set gives no lowest speed (ServoDyn's simple variable-speed law names
    only the rated one): it is audited from its initial RotSpeed, which its report warns of
    — and the batch summary said only WARN (others only PASS).
    The row carries the warnings (JSON: the list; CSV: joined), the table marks the verdict
    and lists them below it, the PDF's cover marks it and the turbine's page lists them."""
    import io

    from pypdf import PdfReader

    deck = shared / "reference" / "WindPACT1.5" / "Test13.fst"
    out = tmp_path / "audit"
    result = runner.invoke(app, ["batch", str(deck), "--out", str(out), "-j", "1"])
    assert "WARN*" in result.stdout and "* with warnings" in result.stdout
    assert "names no lowest" in result.stdout
    row = json.loads((out / "summary.json").read_text())["turbines"][0]
    assert row["warnings"] and row["warnings"][0].startswith("rotor.speed: ServoDyn's simple")
    csv_text = (out / "summary.csv").read_text()
    assert csv_text.splitlines()[0].endswith(",warnings")
    assert "names no lowest speed" in csv_text
    pdf = PdfReader(io.BytesIO((out / "audit.pdf").read_bytes()))
    text = "\n".join(p.extract_text() for p in pdf.pages)
    assert "WARN*" in text and "Warnings" in text and "names no lowest" in text


def test_wisdem_s_options_files_are_left_out_of_a_batch_and_said(tmp_path):
    """Every WISDEM example folder holds its modeling and analysis options beside the
    windIO turbine: a batch of such a folder audits the turbine, and says of each options
    file that it is one (they were eleven 'input errors' in WISDEM's reference-turbine
    folder); ``check`` on one says what it is, exit 2."""
    shutil.copy(TURBINES / "mod-2.yaml", tmp_path / "turbine.yaml")
    options = {
        "modeling_options.yaml": "General:\n  verbosity: False\nWISDEM:\n  RotorSE:\n"
        "    flag: True\n",
        "analysis_options.yaml": "general:\n  folder_output: outputs\n  fname_output: x\n",
        "analysis_options_opt.yaml": "general:\n  folder_output: o\ndriver:\n  optimization:\n"
        "    flag: False\nrecorder:\n  flag: False\n",
    }
    for name, text in options.items():
        (tmp_path / name).write_text(text)
    found, skipped = batch.discover_all([tmp_path])
    assert [p.name for p in found] == ["turbine.yaml"]
    assert sorted(Path(p).name for p, _ in skipped) == sorted(options)
    assert all(why == batch.OPTIONS for _, why in skipped)
    result = CliRunner().invoke(app, ["check", str(tmp_path / "modeling_options.yaml")])
    assert result.exit_code == 2
    assert "WISDEM/WEIS modeling or analysis options file, not a turbine" in result.stderr
    # a spec that merely has a 'general' block is not taken for one
    (tmp_path / "other.yaml").write_text("general:\n  note: mine\n")
    assert "other.yaml" in [p.name for p in batch.discover_all([tmp_path])[0]]


def test_a_repository_s_hidden_folders_and_tool_configuration_are_left_out_and_said(tmp_path):
    """A turbine's repository as it is cloned (IEAWindTask37/IEA-10.0-198-RWT and
    IEA-3.4-130-RWT keep a .travis.yml beside their turbines): its hidden folders (.git,
    .github) are not searched and its tools' YAML files (Travis CI, a conda environment, a
    GitHub workflow) are not audited — each said with why; ``check`` on one says what it
    is, exit 2. A spec that merely has a 'language' key is still a turbine's."""
    shutil.copy(TURBINES / "mod-2.yaml", tmp_path / "turbine.yaml")
    configs = {
        ".travis.yml": "language: python\npython:\n  - 3.8\ninstall:\n  - pip install .\n",
        "environment.yml": "name: rwt\nchannels:\n  - conda-forge\ndependencies:\n  - numpy\n",
    }
    for name, text in configs.items():
        (tmp_path / name).write_text(text)
    for hidden in (".git", ".github/workflows"):
        (tmp_path / hidden).mkdir(parents=True)
        (tmp_path / hidden / "ci.yml").write_text("on: [push]\njobs:\n  test: {}\n")
    found, skipped = batch.discover_all([tmp_path])
    assert [p.name for p in found] == ["turbine.yaml"]
    why = {Path(p).name: w for p, w in skipped}
    assert why[".git"] == why[".github"] == "a hidden folder (a tool's), not searched"
    assert why[".travis.yml"] == why["environment.yml"]
    assert "a tool's configuration" in why[".travis.yml"]
    result = CliRunner().invoke(app, ["check", str(tmp_path / ".travis.yml")])
    assert result.exit_code == 2 and "a tool's configuration" in result.stderr
    (tmp_path / "other.yaml").write_text("language: en\nturbine: {name: x}\n")
    assert "other.yaml" in [p.name for p in batch.discover_all([tmp_path])[0]]


def test_a_deck_set_s_elastodyn_file_is_audited_with_it_not_again_alone(tmp_path):
    """A folder of OpenFAST cases (r-test's 5MW_Land_Linear_Aero, with the 5MW_Baseline
    files it names; tests/data/openfast_decks/rtest_aero.tar.gz) holds the .fst and the
    ElastoDyn file it names: both were audited, the ElastoDyn file alone without the deck
    set's AeroDyn and ServoDyn — two stories of one turbine in one summary. The .fst is
    audited; its ElastoDyn file is left out, named with why. Given by name, a file is
    audited as asked."""
    import tarfile

    data = Path(__file__).resolve().parent / "data" / "openfast_decks" / "rtest_aero.tar.gz"
    with tarfile.open(data) as tar:
        tar.extractall(tmp_path, filter="data")
    case = tmp_path / "glue-codes" / "openfast" / "5MW_Land_Linear_Aero"
    ed = case / "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"
    found, skipped = batch.discover_all([case])
    assert [p.name for p in found] == ["5MW_Land_Linear_Aero.fst"]
    why = dict(skipped)
    assert (
        why[str(ed)].startswith("the ElastoDyn file of ")
        and "5MW_Land_Linear_Aero.fst" in why[str(ed)]
    )
    assert [p.name for p in batch.discover_all([ed])[0]] == [ed.name]


def test_a_controller_tuning_or_results_yaml_beside_turbines_is_left_out_with_why(tmp_path):
    """The IEA-22's repository keeps YAML files beside its turbines that are none: its
    ROSCO tuning files, HAWC2's and OpenFAST's stability and steady-state results in the IEA
    Wind systems' format. A batch over it leaves them out, each named with what it is."""
    shutil.copy(TURBINES / "mod-2.yaml", tmp_path / "turbine.yaml")
    (tmp_path / "rosco.yaml").write_text(
        "path_params: {FAST_InputFile: x.fst}\ncontroller_params:\n  flag: true\n"
    )
    (tmp_path / "hawc2.yaml").write_text(
        "cases:\n  -\n    configuration:\n      wind_speed: 3.0\n    outputs:\n"
        "      Damping_ratio: [0.1]\n"
    )
    found, skipped = batch.discover_all([tmp_path])
    assert [p.name for p in found] == ["turbine.yaml"]
    why = {Path(p).name: w for p, w in skipped}
    assert why["rosco.yaml"] == "a ROSCO controller tuning file, not a turbine"
    assert why["hawc2.yaml"].startswith("another tool's results in the IEA Wind systems'")
