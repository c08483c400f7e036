"""The PDF audit report: real text, every check id, the Campbell figures."""

import io

import pytest
from pypdf import PdfReader
from typer.testing import CliRunner

from tests.conftest import TURBINES
from wtvib import audit, spec
from wtvib.cli import app
from wtvib.outputs import pdfreport

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
    assert "Inputs and their provenance" in text and "tuned" in text
    assert "Assumptions" in text


def test_pdf_has_pages_and_the_campbell_image(wka60_pdf):
    reader = PdfReader(io.BytesIO(wka60_pdf.read_bytes()))
    assert 2 <= len(reader.pages) <= 10  # the WKA-60 inputs table now lists its tower sections
    images = [img for page in reader.pages for img in page.images]
    from wtvib.outputs.plots import diagrams

    # one image per diagram: tower and blades, drive-train Campbell and mode shapes
    assert len(images) == len(diagrams(audit.run(spec.load(TURBINES / "wka-60.yaml")))) == 3
    assert images[0].image.size[0] >= 1500  # 10 in at 150 dpi


def test_pdf_is_marked_as_wtvib_output_and_reproducible(wka60_pdf, tmp_path, monkeypatch):
    """The same inputs give the same bytes where SOURCE_DATE_EPOCH fixes the date (the
    reproducible-builds convention); without it the PDF carries the day it was made."""
    from wtvib.outputs.files import is_ours

    assert is_ours(wka60_pdf)
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1733300000")  # 2024-12-04 08:13:20 UTC
    made = []
    for name in ("one.pdf", "two.pdf"):
        runner.invoke(app, ["report", str(TURBINES / "wka-60.yaml"), "-o", str(tmp_path / name)])
        made.append((tmp_path / name).read_bytes())
    assert made[0] == made[1]
    assert PdfReader(io.BytesIO(made[0])).metadata["/CreationDate"].startswith("D:20241204081320")


def test_pdf_is_dated_the_day_it_is_made(wka60_pdf, monkeypatch):
    """It said 2000-01-01 (reportlab's invariant mode): its date is the real one now."""
    import time

    monkeypatch.delenv("SOURCE_DATE_EPOCH", raising=False)
    created = PdfReader(io.BytesIO(wka60_pdf.read_bytes())).metadata["/CreationDate"]
    assert created.startswith("D:" + time.strftime("%Y", time.gmtime()))


def test_pdf_has_an_outline_of_turbines_and_sections(tmp_path):
    """A 115-page batch PDF had no bookmarks: each turbine is an outline entry, its
    sections under it."""
    result = runner.invoke(
        app,
        [
            "batch",
            str(TURBINES / "wka-60.yaml"),
            str(TURBINES / "mod-2.yaml"),
            "--out-dir",
            str(tmp_path / "out"),
        ],
    )
    assert result.exit_code in (0, 1), result.stdout
    outline = PdfReader(tmp_path / "out" / "audit.pdf").outline
    tops = [x.title for x in outline if not isinstance(x, list)]
    assert "WKA-60 (Helgoland)" in tops and any("MOD-2" in t for t in tops)
    sections = [
        x.title
        for x in outline[
            outline.index(
                next(o for o in outline if getattr(o, "title", "") == "WKA-60 (Helgoland)")
            )
            + 1
        ]
    ]
    assert "Summary of checks" in sections and "Tower" in sections


def test_pdf_labels_carry_their_units_and_numbers_stay_whole(shared, tmp_path):
    """The identity table said "rated power kw 5000.0"; a margin of 1899.1 % was broken
    into "1899.1" and "%" on two lines, a damping "0.068" from its wind."""
    out = tmp_path / "nrel.pdf"
    deck = shared / "reference/NREL5MW/NREL-5MW.fst"
    runner.invoke(app, ["report", str(deck), "-o", str(out)])
    text = "\n".join(page.extract_text() for page in PdfReader(out).pages)
    assert "rated power\n5,000 kW" in text and "rotor diameter\n126 m" in text
    assert "kw 5000" not in text
    import re

    assert re.search(r"\b\d{3,}%", text)  # a margin of hundreds of per cent, whole on a line
    assert not any(line.strip().startswith("%") for line in text.splitlines())


def test_report_of_a_bad_spec_is_one_line(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("wtvib: 1\n")
    result = runner.invoke(app, ["report", str(bad), "-o", str(tmp_path / "x.pdf")])
    assert result.exit_code == 2 and result.stderr.count("\n") == 1


def test_pdf_numbers_are_for_people():
    """A check's numbers are one readable line with units (not `key = value`
    reprs), and inputs are written as engineers write them."""
    from wtvib.outputs.pdfreport import _for_people, _numbers

    c = {
        "mode": "tower.fa1",
        "frequency_hz": 0.767036,
        "margin": 0.000481522,
        "required_margin": 0.1,
        "speed_rpm": 23.0,
        "daf": 4.0019,
        "crossings_rpm": [23.0111],
    }
    line = _numbers(c)
    assert line == (
        "mode tower.fa1; f 0.767 Hz; margin 0 %; needs 10.0 %; at 23 rpm; "
        "DAF 4.00; crossings 23 rpm"
    )
    assert "=" not in line and "0.000481522" not in line
    assert _for_people(2.275e6) == "2,275,000"
    assert _for_people(2.1e11) == "2.1×10<super>11</super>"
    assert _for_people(0.125) == "0.125"


def test_pdf_images_are_the_pngs_pixels_passed_through(wka60_pdf):
    """The figures are embedded as their PNGs' compressed rows (wtvib.outputs.pdfpng): a reader that
    applies the PNG predictors gets exactly the pixels wtvib drew."""
    from PIL import Image

    from wtvib.outputs.plots.render import inline

    reader = PdfReader(io.BytesIO(wka60_pdf.read_bytes()))
    drawn = inline(audit.run(spec.load(TURBINES / "wka-60.yaml")), detail=True)
    pixels = {Image.open(io.BytesIO(png)).convert("RGB").tobytes() for png in drawn.values()}
    images = [img for page in reader.pages for img in page.images]
    assert images and all(img.image.convert("RGB").tobytes() in pixels for img in images)
    for page in reader.pages:
        for obj in page["/Resources"].get("/XObject", {}).values():
            d = obj.get_object()
            # one filter by name and one parameter dictionary: poppler ignores a dictionary
            # beside a filter array (the pictures came out as noise there)
            assert d["/Filter"] == "/FlateDecode" and d["/DecodeParms"]["/Predictor"] == 15


def test_png_that_cannot_pass_through_goes_to_reportlab(tmp_path):
    """An RGBA, interlaced or truncated PNG is not passed through; the PDF still has it."""
    from PIL import Image
    from reportlab.platypus import Image as RLImage
    from reportlab.platypus import SimpleDocTemplate

    from wtvib.outputs.pdfpng import PngImage, image, png_stream

    def png(mode: str, **kw) -> bytes:
        buf = io.BytesIO()
        Image.new(mode, (40, 30), "red").save(buf, format="png", **kw)
        return buf.getvalue()

    rgb = png("RGB")
    stream = png_stream(rgb)
    assert stream is not None and (stream.width, stream.height, stream.colours) == (40, 30, 3)
    assert png_stream(png("RGBA")) is None
    interlaced = bytearray(rgb)
    interlaced[28] = 1  # IHDR's interlace method (Pillow writes no interlaced PNG)
    assert png_stream(bytes(interlaced)) is None
    assert png_stream(rgb[:40]) is None and png_stream(b"not a png") is None
    assert isinstance(image(rgb, 40, 30), PngImage)
    fallback = image(png("RGBA"), 40, 30)
    assert isinstance(fallback, RLImage)
    out = tmp_path / "two.pdf"
    SimpleDocTemplate(str(out)).build([image(rgb, 40, 30), fallback])
    assert len(PdfReader(out).pages[0].images) == 2


def test_a_figure_taller_than_a_page_is_drawn_to_fit():
    """A figure made taller by a legend of many rows (plots.layout) must still fit a page:
    reportlab refuses a flowable taller than its frame (LayoutError) — the PDF of a
    results import with very many modes would not build."""
    from PIL import Image

    from wtvib.outputs import pdfreport

    report = audit.run(spec.load(TURBINES / "wka-60.yaml")).to_dict()
    buf = io.BytesIO()
    Image.new("RGB", (1500, 4000), "white").save(buf, format="png")  # 10 × 26.7 in
    pdf = pdfreport.build([(report, {"campbell": buf.getvalue()})])
    reader = PdfReader(io.BytesIO(pdf))
    assert any(page.images for page in reader.pages)


def test_paragraphs_wrapped_once_give_the_same_document(monkeypatch):
    """pdfreport.once_wrapped reuses a paragraph's line breaks at an unchanged width: the
    catalogue's longest tables (Aeroman's drive train, MOD-0's checks), split across many
    pages, give the bytes reportlab's own Paragraph gives."""
    entries = [
        (audit.run(spec.load(TURBINES / f"{name}.yaml")).to_dict(), {})
        for name in ("aeroman", "mod-0")
    ]
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")  # the two builds the same second
    once = pdfreport.build(entries)
    monkeypatch.setattr(pdfreport, "once_wrapped", lambda paragraph: paragraph)
    plain = pdfreport.build(entries)
    assert len(PdfReader(io.BytesIO(once)).pages) >= 6
    assert once == plain


def test_a_subsystem_without_checks_says_where_its_modes_are_judged():
    """The catalogue NREL 5-MW's drive train has only its brake-locked mode (no regime),
    the OpenFAST deck's its free modes judged in the coupled model too: the section says
    so instead of an empty table of checks."""
    report = audit.run(spec.load(TURBINES / "nrel-5mw.yaml")).to_dict()
    assert not any(c["subsystem"] == "drivetrain" for c in report["checks"])
    text = " ".join(
        p.extract_text() for p in PdfReader(io.BytesIO(pdfreport.build([(report, {})]))).pages
    ).replace("\n", " ")
    assert "No checks of its own — in no operating regime: drivetrain.locked.1." in text
    deck = [
        {"id": "drivetrain.free.1", "superseded_by": "system.drivetrain1"},
        {"id": "drivetrain.locked.1", "regimes": []},
    ]
    assert pdfreport._judged_elsewhere(deck) == (
        "No checks of its own — judged in the whole-turbine model: drivetrain.free.1 as "
        "system.drivetrain1; in no operating regime: drivetrain.locked.1."
    )


def test_png_header_is_read_in_one_place():
    """wtvib.outputs.png.header: the IHDR of a PNG wtvib wrote (the size the PDF scales by), None
    for anything that is not a PNG with its IHDR first."""
    from wtvib.outputs import png
    from wtvib.outputs.plots import png_bytes
    from wtvib.outputs.plots.campbell import campbell_plot

    fig = campbell_plot(audit.run(spec.load(TURBINES / "mod-2.yaml")))
    data = png_bytes(fig)
    width, height = (round(v * fig.dpi) for v in fig.get_size_inches())
    assert png.header(data) == (width, height, 8, 2, 0, 0, 0)  # 8-bit RGB, not interlaced
    assert pdfreport._aspect(data) == height / width
    assert png.header(b"GIF89a") is None and png.header(data[:20]) is None
    assert pdfreport._aspect(b"GIF89a") == 0.7


def test_ids_break_after_a_dot_and_headings_do_not_empty_a_page():
    """The Aeroman's report: every check id of its summary is in the page text whole or
    broken after a dot (drivetrain.resonance. / mesh.stage2), never mid-word (it was
    "drivetrain.resonance.mesh.st" / "age2"); and the summary of checks starts on the page
    of the turbine's identity table — a heading kept with the page-long table after it had
    moved both on and left that page two-thirds empty."""
    r = audit.run(spec.load(TURBINES / "aeroman.yaml"))
    pages = PdfReader(io.BytesIO(pdfreport.build([(r.to_dict(), {})]))).pages
    text = "\n".join(p.extract_text() for p in pages)
    for c in r.checks:
        parts = c.id.split(".")
        broken = any(
            ".".join(parts[:i]) + ".\n" + ".".join(parts[i:]) in text for i in range(1, len(parts))
        )
        assert c.id in text or broken, c.id
    second = pages[1].extract_text()
    assert "Verdict" in second and "Summary of checks" in second


def test_pdf_of_an_uncertainty_run_has_its_spread_and_sensitivities(tmp_path):
    out = tmp_path / "u.pdf"
    result = CliRunner().invoke(
        app,
        ["report", str(TURBINES / "wka-60.yaml"), "-o", str(out), "--uncertainty",
         "--samples", "200"],
    )  # fmt: skip
    assert result.exit_code == 1, result.output  # WKA-60 fails: the PDF is written
    text = "".join(page.extract_text() for page in PdfReader(out).pages)
    assert "Uncertainty (200 samples, seed 0)" in text
    assert "youngs_modulus_pa" in text.replace("\n", "") and "(∂f/∂p)·(p/f)" in text


def _pdf_text(path) -> str:  # type: ignore[no-untyped-def]
    return "\n".join(page.extract_text() for page in PdfReader(path).pages)


def test_every_check_and_figure_of_a_deck_is_in_its_pdf(shared, tmp_path):
    """An ElastoDyn deck's polynomials are checks of their own subsystem: the PDF had no
    section for them (its checks and the shapes figure left out). Every check id is in the
    text, the shapes figure on the section's page, the sets' numbers in words."""
    deck = shared / "reference/NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"
    out = tmp_path / "nrel.pdf"
    result = runner.invoke(app, ["report", str(deck), "-o", str(out), "--rpm", "6.9:12.1"])
    assert result.exit_code == 1, result.stdout  # its tower fails
    text = _pdf_text(out)
    from wtvib import importers

    report = audit.run(importers.load(deck, importers.ReadOptions(rpm=(6.9, 12.1))))
    for check in report.checks:
        assert check.id in text, check.id
    assert "ElastoDyn's mode-shape polynomials" in text
    flat = " ".join(text.split())
    assert "TwFAM1Sh MAC 0.9999, implies 0.3297 Hz (+3.3 % on the computed 0.3193 Hz)" in flat
    pages = PdfReader(out).pages
    (page,) = [p for p in pages if "the deck's own against the" in p.extract_text()]
    assert page.images  # the figure drawn there


def test_a_standstill_audits_figure_is_in_its_pdf(tmp_path):
    """The standstill figure of a parked linearisation was drawn as a PNG and left out of
    the PDF (no section listed it)."""
    import gzip
    from pathlib import Path

    lin = Path(__file__).resolve().parent / "data" / "openfast_lin"
    for gz in sorted(lin.glob("WP_Stationary_Linear.*.lin.gz")):
        (tmp_path / gz.name.removesuffix(".gz")).write_bytes(gzip.decompress(gz.read_bytes()))
    out = tmp_path / "wp.pdf"
    result = runner.invoke(
        app, ["report", str(tmp_path / "WP_Stationary_Linear.1.lin"), "-o", str(out)]
    )
    assert result.exit_code in (0, 1), result.stdout
    assert sum(len(p.images) for p in PdfReader(out).pages) >= 1
