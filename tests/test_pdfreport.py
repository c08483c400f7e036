"""The PDF audit report: real text, every check id, the Campbell figures."""

import io

import pytest
from pypdf import PdfReader
from typer.testing import CliRunner

from tests.conftest import TURBINES
from wtvib import audit, spec
from wtvib.cli import app

runner = CliRunner()


@pytest.fixture(scope="module")
def wka60_pdf(tmp_path_factory):
    out = tmp_path_factory.mktemp("pdf") / "wka-60.pdf"
    result = runner.invoke(app, ["report", str(TURBINES / "wka-60.yaml"), "-o", str(out)])
    assert result.exit_code == 1  # the WKA-60 fails
    return out


def test_pdf_text_names_turbine_verdict_and_every_check(wka60_pdf):
    reader = PdfReader(io.BytesIO(wka60_pdf.read_bytes()))
    text = "\n".join(page.extract_text() for page in reader.pages)
    assert "WKA-60 (Helgoland)" in text
    assert "FAIL" in text
    report = audit.run(spec.load(TURBINES / "wka-60.yaml"))
    for check in report.checks:
        assert check.id in text, check.id
    assert "Inputs and their provenance" in text and "derived" in text
    assert "Assumptions" in text


def test_pdf_has_pages_and_the_campbell_image(wka60_pdf):
    reader = PdfReader(io.BytesIO(wka60_pdf.read_bytes()))
    assert 2 <= len(reader.pages) <= 10  # the WKA-60 inputs table now lists its tower sections
    images = [img for page in reader.pages for img in page.images]
    from wtvib.plots import diagrams

    # one image per diagram: tower and blades, drive-train Campbell and mode shapes
    assert len(images) == len(diagrams(audit.run(spec.load(TURBINES / "wka-60.yaml")))) == 3
    assert images[0].image.size[0] >= 1500  # 10 in at 150 dpi


def test_pdf_is_marked_as_wtvib_output_and_reproducible(wka60_pdf, tmp_path):
    from wtvib.outputs import is_ours

    assert is_ours(wka60_pdf)
    again = tmp_path / "again.pdf"
    runner.invoke(app, ["report", str(TURBINES / "wka-60.yaml"), "-o", str(again)])
    assert again.read_bytes() == wka60_pdf.read_bytes()


def test_report_of_a_bad_spec_is_one_line(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("wtvib: 1\n")
    result = runner.invoke(app, ["report", str(bad), "-o", str(tmp_path / "x.pdf")])
    assert result.exit_code == 2 and result.stderr.count("\n") == 1
