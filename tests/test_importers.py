"""Format detection and the import options' one rule each."""

from pathlib import Path

import pytest

from wtvib import importers
from wtvib.errors import SpecError


@pytest.mark.parametrize(
    ("name", "text", "kind"),
    [
        ("t.yaml", "wtvib: 1\nturbine: {name: x}\n", "wtvib"),
        ("t.yaml", "windIO_version: 2.0\ncomponents: {}\nassembly: {}\n", "windio"),
        ("t.dat", '3 NumBl - blades\n"tower.dat" TwrFile - file\n', "elastodyn"),
        ("t.fst", '"ed.dat"  EDFile - ElastoDyn\n', "elastodyn"),
    ],
)
def test_formats_are_detected_by_content(name, text, kind):
    assert importers.detect(Path(name), text) == kind


def test_anything_else_names_the_formats_accepted():
    with pytest.raises(SpecError, match="not a format wtvib reads"):
        importers.detect(Path("t.txt"), "hello\n")


def test_head_mass_is_for_windio_files_only(tmp_path):
    p = tmp_path / "t.yaml"
    p.write_text("wtvib: 1\n")
    with pytest.raises(SpecError, match="--head-mass applies to windIO files only"):
        importers.load(p, head_mass=1000.0)
