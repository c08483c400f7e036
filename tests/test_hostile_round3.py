"""Hostile input, round three: the new readers, outputs at their limits, batch
discovery — one line and exit 2 for a user's input, never an internal error, never a
hang or a file read whole when only its head is needed; one bad input never stops or
silently shrinks a batch."""

import gzip
import json
import os
import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from wtvib.cli import app
from wtvib.workflows import batch

from .conftest import TURBINES

LIN = Path(__file__).parent / "data" / "openfast_lin"
runner = CliRunner()


def _one_line_exit_2(args: list[str], words: str) -> None:
    result = runner.invoke(app, args)
    assert result.exit_code == 2, result.output
    assert result.stderr.count("\n") == 1 and "Traceback" not in result.output
    assert words in result.stderr, result.stderr


def _lin(folder: Path, name: str = "t.1.lin", edit: tuple[str, str] | None = None) -> Path:
    text = gzip.decompress((LIN / "5MW_OC3Mnpl_Linear.1.lin.gz").read_bytes()).decode()
    if edit is not None:
        text = re.sub(edit[0], edit[1], text, count=1)
    folder.mkdir(exist_ok=True)
    (folder / name).write_text(text)
    return folder / name


def test_a_fifo_among_a_lin_sets_files_is_refused_not_waited_on(tmp_path):
    """The other azimuth files of a .lin set pass the input guards: a FIFO t.2.lin hung."""
    first = _lin(tmp_path)
    os.mkfifo(tmp_path / "t.2.lin")
    _one_line_exit_2(["check", str(first), "--no-plots"], "not a regular file")


def test_a_sparse_giant_beside_the_file_is_refused_by_its_size(tmp_path):
    first = _lin(tmp_path)
    with (tmp_path / "t.2.lin").open("wb") as fh:
        fh.truncate(6 * 1024**3)  # 6 GB of holes: read whole, it took 6 GB; its head is read
    _one_line_exit_2(["check", str(first), "--no-plots"], "binary file")


def test_a_lin_file_is_read_to_the_end_of_a_only(tmp_path, monkeypatch):
    """A full-system linearisation's B, C and D can be many times A's size: wtvib reads the
    header and A's rows, not the rest — a file with 45 MB after A, far over the header
    limit (set here just above its header), audits as the file without them; a file whose
    header alone is over the limit is one line."""
    from wtvib.importers import openfast_lin

    plain = _lin(tmp_path / "plain")
    grown = _lin(tmp_path / "grown")
    text = grown.read_text()
    with grown.open("a") as fh:
        fh.write(("B: 1 x 1\n" + " 1.0E+000" * 1000 + "\n") * 5000)
    monkeypatch.setattr(openfast_lin, "LIN_MAX_BYTES", len(text.split("A:")[0]) + 100)
    a = runner.invoke(app, ["check", str(plain), "--no-plots", "-f", "json"])
    b = runner.invoke(app, ["check", str(grown), "--no-plots", "-f", "json"])
    assert a.exit_code == b.exit_code and a.exit_code in (0, 1), b.output
    modes = [json.loads(r.stdout)["modes"] for r in (a, b)]
    assert [m["frequency_hz"] for m in modes[0]] == [m["frequency_hz"] for m in modes[1]]
    monkeypatch.setattr(openfast_lin, "LIN_MAX_BYTES", 2000)
    _one_line_exit_2(["check", str(plain), "--no-plots"], "no state matrix 'A:' in the first")


@pytest.mark.parametrize(
    ("edit", "words"),
    [
        ((r"Number of continuous states:\s+\d+", "Number of continuous states:"), "no value"),
        ((r"Azimuth:\s+\S+", "Azimuth:"), "not a number"),
        ((r"Wind Speed:\s+\S+", "Wind Speed:"), "not a number"),
        ((r"Rotor Speed:\s+\S+", "Rotor Speed: 1e300"), "is not a rotor speed"),
    ],
)
def test_a_lin_header_without_its_value_is_one_line(tmp_path, edit, words):
    path = _lin(tmp_path, edit=edit)
    _one_line_exit_2(["check", str(path), "--no-plots", "--rpm", "12.1"], words)


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ("mode,rpm,frequency_hz,description\ntower.fa1,5,0.3," + "x" * 200_000 + "\n", "131,072"),
        ('mode,rpm,frequency_hz,description\ntower.fa1,5,0.3,"open\ntower.fa1,10,0.3,x\n',
         "a quote left open"),
        ("mode,rpm,frequency_hz,frequency_hz\ntower.fa1,5,0.3,0.4\n", "given twice"),
        ("mode,rpm,frequency_hz\n" + "X" * 100_000 + ",5,0.3\n", "characters left out"),
    ],
)  # fmt: skip
def test_a_malformed_campbell_table_is_one_line(tmp_path, text, words):
    """A cell past Python's CSV limit was an internal error; an unterminated quote
    swallowed the next row and exited 0; a repeated column was dropped silently; a 100 kB
    mode id was echoed whole (the line now cut, saying how much)."""
    path = tmp_path / "t.csv"
    path.write_text(text)
    _one_line_exit_2(["check", str(path), "--no-plots"], words)
    if "X" * 10 in text:
        assert len(runner.invoke(app, ["check", str(path), "--no-plots"]).stderr) < 3000


def test_a_table_of_too_many_modes_is_refused_before_it_costs_memory(tmp_path):
    """20,000 modes took past 5 GB: at most campbell_results.MAX_MODES (1,000) are read."""
    rows = "".join(f"tower.fa{i + 1},{r},0.3\n" for i in range(1001) for r in (5, 10))
    path = tmp_path / "t.csv"
    path.write_text("mode,rpm,frequency_hz\n" + rows)
    _one_line_exit_2(["check", str(path), "--no-plots"], "more than 1000 modes")
    cmb = tmp_path / "hs.cmb"
    n = 20_000
    cmb.write_text(
        "# Wind [m/s] " + " ".join(str(i + 1) for i in range(n)) + "\n"
        + " ".join(["5"] + ["0.5"] * n + ["1.0"] * n) + "\n"
    )  # fmt: skip
    _one_line_exit_2(["check", str(cmb), "--no-plots"], "20000 modes")


def test_wtvib_reads_back_its_own_campbell_csv(tmp_path):
    csv = tmp_path / "own.csv"
    first = runner.invoke(
        app, ["check", str(TURBINES / "mod-2.yaml"), "--no-plots", "--campbell-csv", str(csv)]
    )
    assert first.exit_code in (0, 1)
    again = runner.invoke(app, ["check", str(csv), "--no-plots", "--blades", "2"])
    assert again.exit_code in (0, 1), again.output


def test_a_symlink_loop_named_by_a_deck_is_one_line(tmp_path):
    deck = tmp_path / "ed.dat"
    (tmp_path / "a").symlink_to(tmp_path / "b")
    (tmp_path / "b").symlink_to(tmp_path / "a")
    deck.write_text('--- ElastoDyn\ntitle\n3 NumBl -\n"a" TwrFile -\n"a" BldFile(1) -\n')
    _one_line_exit_2(["check", str(deck), "--no-plots"], "leads nowhere")


@pytest.mark.parametrize("option", ["--out-dir", "--campbell-csv"])
def test_an_output_name_too_long_for_the_file_system_is_one_line(tmp_path, option):
    name = tmp_path / ("x" * 300)
    _one_line_exit_2(
        ["check", str(TURBINES / "mod-2.yaml"), option, str(name)], "File name too long"
    )


def test_a_size_limit_of_thirty_digits_is_no_crash(monkeypatch):
    """WTVIB_MAX_BYTES=99…9 made every read allocate that much (an internal error)."""
    monkeypatch.setenv("WTVIB_MAX_BYTES", "9" * 30)
    result = runner.invoke(app, ["check", str(TURBINES / "mod-2.yaml"), "--no-plots"])
    assert result.exit_code in (0, 1), result.output


@pytest.mark.parametrize(
    ("option", "words"),
    [(["--samples", str(10**12)], "--samples"), (["--seed", "-5"], "--seed")],
)
def test_the_monte_carlo_options_are_bounded(option, words):
    args = ["check", str(TURBINES / "wka-60.yaml"), "--no-plots", "--uncertainty", *option]
    result = runner.invoke(app, args)
    assert result.exit_code == 2 and words in result.output


def test_the_pdf_lays_out_a_4000_character_name(tmp_path):
    """reportlab's LayoutError (a table row taller than a page) lost the PDF."""
    text = (TURBINES / "mod-2.yaml").read_text()
    path = tmp_path / "long.yaml"
    path.write_text(re.sub(r"name: .*", "name: " + "N" * 4000, text, count=1))
    result = runner.invoke(app, ["report", str(path), "-o", str(tmp_path / "r.pdf")])
    assert result.exit_code in (0, 1), result.output
    assert (tmp_path / "r.pdf").read_bytes().startswith(b"%PDF")


def test_one_turbine_whose_files_cannot_be_written_does_not_stop_the_batch(tmp_path):
    """An over-long output name wrote nothing — no summary, no other turbine's files."""
    inputs = tmp_path / "in"
    inputs.mkdir()
    text = (TURBINES / "mod-2.yaml").read_text()
    (inputs / "ok.yaml").write_text(text)
    (inputs / ("z" * 250 + ".yaml")).write_text(text)
    out = tmp_path / "out"
    result = runner.invoke(app, ["batch", str(inputs), "--out-dir", str(out), "--no-plots"])
    rows = json.loads((out / "summary.json").read_text())["turbines"]
    assert {r["verdict"] for r in rows} == {"pass", "input-error"}, result.output
    assert (out / "ok.json").is_file() and (out / "run-metadata.json").is_file()
    assert "could not be written" in result.output


def test_a_looping_symlink_among_the_inputs_is_its_own_row(tmp_path):
    (tmp_path / "a.yaml").symlink_to(tmp_path / "b.yaml")
    (tmp_path / "b.yaml").symlink_to(tmp_path / "a.yaml")
    result = runner.invoke(
        app, ["batch", str(tmp_path / "a.yaml"), str(TURBINES / "mod-2.yaml"), "--no-plots"]
    )
    assert result.exit_code == 2 and "1 input-error, 1 pass" in result.output


def test_an_unsearchable_subfolder_is_an_input_not_skipped(tmp_path, monkeypatch):
    """os.walk's error for a folder without read permission (simulated: the tests may run
    as root) makes that folder a row of the batch, whose audit says why."""
    (tmp_path / "ok.yaml").write_text((TURBINES / "mod-2.yaml").read_text())
    locked = tmp_path / "locked"
    locked.mkdir()
    real = os.walk

    def walk(top, onerror=None, **kw):  # type: ignore[no-untyped-def]
        for root, dirs, files in real(top, onerror=onerror, **kw):
            if Path(root) == locked:
                onerror(PermissionError(13, "Permission denied", str(locked)))
                continue
            yield root, dirs, files

    monkeypatch.setattr(batch.os, "walk", walk)
    found = batch.discover([tmp_path])
    assert locked in found and tmp_path / "ok.yaml" in found


def test_a_dangling_symlink_lock_is_named_as_such(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / batch.FolderLock.NAME).symlink_to(tmp_path / "nowhere")
    result = runner.invoke(
        app, ["batch", str(TURBINES / "mod-2.yaml"), "--out-dir", str(out), "--no-plots"]
    )
    assert result.exit_code == 2 and "not a wtvib lock file" in result.stderr


def test_a_batch_on_a_cluster_that_loses_its_workers_finishes(monkeypatch):
    """A worker killed mid-batch left the batch waiting forever: with no worker for
    WORKERLESS_S the items left are reported as not audited, the rest stands."""
    from concurrent.futures import Future

    class Stalled:  # an executor whose work never completes (its workers are gone)
        def submit(self, *args, **kwargs):  # type: ignore[no-untyped-def]
            return Future()

    monkeypatch.setattr(batch, "WORKERLESS_S", 0.2)
    monkeypatch.setattr(batch, "POLL_S", 0.05)
    items = batch.run(
        [TURBINES / "mod-2.yaml"], plots=False, executor=Stalled(), alive=lambda: False
    )
    assert items[0].internal and "no worker" in (items[0].error or "")
