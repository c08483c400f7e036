"""Atomic writes that never replace a file wtvib did not write (without --force)."""

from pathlib import Path

import pytest

from wtvib.errors import OutputError
from wtvib.outputs.files import is_ours, write_atomic
from wtvib.outputs.plots import png_bytes


def test_a_users_file_is_never_replaced_without_force(tmp_path):
    target = tmp_path / "notes.json"
    target.write_text("my notes\n")
    with pytest.raises(OutputError, match="was not written by wtvib"):
        write_atomic(target, b'{\n  "schema": "wtvib-report/1"}\n')
    assert target.read_text() == "my notes\n"
    write_atomic(target, b"replaced\n", force=True)
    assert target.read_bytes() == b"replaced\n"


def test_own_files_are_recognised_and_replaced(tmp_path):
    from matplotlib.figure import Figure

    png = tmp_path / "a.png"
    write_atomic(png, png_bytes(Figure(figsize=(1, 1))))
    assert is_ours(png)  # the PNG's Software tag says wtvib
    write_atomic(png, png_bytes(Figure(figsize=(2, 1))))  # no --force needed
    assert not [p for p in tmp_path.iterdir() if p.suffix == ".tmp"]


def test_an_unwritable_folder_is_an_output_error(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    with pytest.raises(OutputError, match="cannot write"):
        write_atomic(blocker / "sub" / "out.json", b"{}")


def test_a_device_or_pipe_is_never_an_output(tmp_path):
    """The overwrite check opened the target for reading (a FIFO blocked forever)
    and --force replaced a device node."""
    import os

    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    assert not is_ours(fifo)  # returns at once, the FIFO is not opened
    for target in (fifo, Path("/dev/null")):
        with pytest.raises(OutputError, match="not a regular file"):
            write_atomic(target, b"x", force=True)


def test_a_file_where_the_output_folder_should_be_is_said_as_such(tmp_path):
    """``--out report.txt`` (an existing file): "cannot write to …: File exists" named no
    culprit; now the line says which path is a file, not a folder."""
    blocker = tmp_path / "afile"
    blocker.write_text("mine")
    for folder in (blocker, blocker / "sub"):
        with pytest.raises(OutputError, match=f"{blocker} is a file, not a folder"):
            write_atomic(folder / "x.png", b"data")
    assert blocker.read_text() == "mine"
