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


def test_the_headline_says_where_imported_speeds_come_from(shared):
    """Issue 18 (windIO 1.x speeds): the IEA-3.4 1.x file's control block carries 6.9–12.1
    rpm; the report says they are the file's (operation.source, and the headline's Speed
    row), and a range given on the command line says so instead."""
    from wtvib import audit
    from wtvib.importers import load

    path = shared / "reference/IEA3.4/IEA-3.4-130-RWT.yaml"
    doc = audit.run(load(path, head_mass=1.5e5)).to_dict()
    assert "control.supervisory" in doc["operation"]["source"]
    assert "IEA-3.4-130-RWT.yaml" in doc["operation"]["source"]
    doc = audit.run(load(path, head_mass=1.5e5, rpm=(3.8, 11.75))).to_dict()
    assert doc["operation"]["source"] == "the command line (--rpm/--rated)"
