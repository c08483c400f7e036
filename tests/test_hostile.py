"""Hostile and broken inputs: each refused with its one-line message, exit code 2."""

from pathlib import Path

import pytest
from typer.testing import CliRunner

from wtvib.cli import app

DATA = Path(__file__).parent / "data"
HOSTILE = DATA / "hostile"


def expectations() -> list[tuple[str, str]]:
    rows = []
    for line in (HOSTILE / "EXPECTED.txt").read_text(encoding="utf-8").splitlines():
        if line.strip() and not line.startswith("#"):
            name, words = (part.strip() for part in line.split("|", 1))
            rows.append((name, words))
    return rows


def test_every_hostile_file_has_an_expectation():
    assert {n for n, _ in expectations()} == {p.name for p in HOSTILE.glob("*.yaml")}


@pytest.mark.parametrize(("name", "words"), expectations())
def test_hostile_file_gives_one_line_and_exit_2(name, words):
    result = CliRunner().invoke(app, ["check", str(HOSTILE / name), "--no-plot"])
    assert result.exit_code == 2, result.output
    err = result.stderr
    assert err.count("\n") == 1 and "Traceback" not in result.output
    assert err.startswith("error: ") and words in err


# --- importers: edits of reference files (tests/data/hostile/IMPORTERS.txt) ---------------


def importer_cases() -> list[tuple[str, str, str, str, str]]:
    rows = []
    for line in (HOSTILE / "IMPORTERS.txt").read_text(encoding="utf-8").splitlines():
        if line.strip() and not line.startswith("#"):
            name, checked, edited, edit, words = (part.strip() for part in line.split("|"))
            rows.append((name, checked, edited, edit, words))
    return rows


_FLOATING: list[Path] = []


def _floating() -> Path:
    """r-test's floating deck sets (tests/data/openfast_decks/rtest_floating.tar.gz),
    extracted once a session and removed when it ends (they were left in /tmp, one copy a
    run)."""
    if not _FLOATING:
        import atexit
        import shutil
        import tarfile
        import tempfile

        root = Path(tempfile.mkdtemp(prefix="wtvib-floating-"))
        atexit.register(shutil.rmtree, root, ignore_errors=True)
        with tarfile.open(DATA / "openfast_decks" / "rtest_floating.tar.gz") as tar:
            tar.extractall(root, filter="data")
        _FLOATING.append(root)
    return _FLOATING[0]


def _base(where: str) -> Path:
    kind, _, rest = where.partition(":")
    if kind == "floating":
        return _floating() / "glue-codes" / "openfast" / rest
    if kind == "windio":
        windio = pytest.importorskip("windIO", reason="the windio package (dev extra) is needed")
        return Path(windio.__file__).parent / "examples" / "turbine" / rest
    from .conftest import SHARED

    if not SHARED.is_dir():
        pytest.skip("../shared/reference is not beside the clone")
    return SHARED / "reference" / rest


def _edited(path: Path, edit: str) -> str:
    """The file's text after one corpus edit (which must apply: a stale case fails)."""
    text = path.read_text(encoding="latin-1")
    if " => " in edit:
        find, replace = edit.split(" => ", 1)
        assert text.count(find) >= 1, f"{find!r} is not in {path.name}"
        new = text.replace(find, replace, 1)
        return new.split("<EOF>", 1)[0]
    import yaml

    doc = yaml.safe_load(text)
    target, _, value = edit.removeprefix("del ").partition(" = ")
    *parents, last = target.split(".")
    node = doc
    for key in parents:
        node = node[int(key) if isinstance(node, list) else key]
    key = int(last) if isinstance(node, list) else last
    assert key in node if isinstance(node, dict) else key < len(node), f"{target} not in file"
    if edit.startswith("del "):
        del node[key]
    else:
        node[key] = yaml.safe_load(value)
    return yaml.safe_dump(doc, sort_keys=False)


@pytest.mark.parametrize(
    ("name", "checked", "edited", "edit", "words"), importer_cases(), ids=lambda v: v[:24]
)
def test_hostile_importer_input_gives_one_line_and_exit_2(
    tmp_path, name, checked, edited, edit, words
):
    """ElastoDyn and windIO files edited as a reviewer would — a text cell, a file
    cut mid-number, a NaN blade count, a missing member file, a true blade count, a negative
    mass, a modulus of `true`, a tower of no length or apart from its monopile, a water depth
    below the pile — each one line naming file and field, exit 2."""
    import shutil

    first, *options = checked.split()
    source = _base(first)
    folder = tmp_path / "deck"
    if first.startswith("floating:"):  # the deck sets name files in a sibling folder
        shutil.copytree(source.parents[1], tmp_path / "decks")
        folder = tmp_path / "decks" / source.parent.name
    elif source.name.endswith(".fst"):
        shutil.copytree(source.parent, folder)
    else:
        folder.mkdir()
        shutil.copyfile(source, folder / source.name)
    (folder / edited).write_text(_edited(source.parent / edited, edit), encoding="latin-1")
    result = CliRunner().invoke(app, ["check", str(folder / source.name), "--no-plot", *options])
    assert result.exit_code == 2, (name, result.output)
    err = result.stderr
    assert err.count("\n") == 1 and "Traceback" not in result.output, err
    assert err.startswith("error: ") and words in err, err
