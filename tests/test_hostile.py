"""Hostile and broken inputs: each refused with its one-line message, exit code 2."""

from pathlib import Path

import pytest
from typer.testing import CliRunner

from wtvib.cli import app

HOSTILE = Path(__file__).parent / "data" / "hostile"


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
