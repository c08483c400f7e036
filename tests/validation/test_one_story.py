"""One story everywhere: what a figure says is what the checks it draws say, a mode has one
name in every part of the report, and no pass shows a negative damping.

Every PNG carries its judgement as text chunks (``Title``, ``wtvib:status``,
``wtvib:checks``), read here with Pillow (an independent PNG reader) and held against the
JSON report of the same audit: the figure's status is the worst status of the checks it
lists (info counting as a pass, as the verdict counts it), its title says that status,
and every check that warns or fails on a resonance is drawn by some figure.
"""

import gzip
import io
import re
from pathlib import Path

import pytest
from PIL import Image

from tests.conftest import TURBINES
from wtvib import audit, spec
from wtvib.errors import SpecError
from wtvib.importers import ReadOptions, load
from wtvib.plots import diagrams, png_bytes
from wtvib.rules import worst

LIN = Path(__file__).resolve().parents[1] / "data" / "openfast_lin"
CATALOGUE = sorted(p.stem for p in TURBINES.glob("*.yaml"))
#: Reference inputs beside the catalogue (../shared/reference), with the options they need.
DECKS = {
    "NREL5MW/NREL-5MW.fst": ReadOptions(),
    "NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat": ReadOptions(rpm=(6.9, 12.1)),
    "WindPACT1.5/Test13.fst": ReadOptions(),
}
#: OpenFAST r-test linearisations: one operating point in operation, a parked one, and the
#: free-free beam (parked, with the numerical images of its rigid-body motion).
LINS = ("5MW_Land_Linear_Aero", "WP_Stationary_Linear", "Ideal_Beam_Free_Free_Linear")


def _lin(name: str, folder: Path) -> Path:
    for gz in sorted(LIN.glob(f"{name}.*.lin.gz")):
        (folder / gz.name.removesuffix(".gz")).write_bytes(gzip.decompress(gz.read_bytes()))
    return folder / f"{name}.1.lin"


def _meta(fig) -> dict[str, str]:  # type: ignore[no-untyped-def]
    return dict(Image.open(io.BytesIO(png_bytes(fig))).text)  # type: ignore[attr-defined]


def _figures_agree_with_the_json(report: audit.Report) -> None:
    doc = report.to_dict()
    status = {c["id"]: c["status"] for c in doc["checks"]}
    drawn: set[str] = set()
    for name, fig in diagrams(report).items():
        meta = _meta(fig)
        assert {"Title", "wtvib:status", "wtvib:checks"} <= set(meta), name
        listed = [c for c in meta["wtvib:checks"].split(",") if c]
        assert set(listed) <= set(status), (name, set(listed) - set(status))
        drawn |= set(listed)
        expected = worst([status[c] for c in listed]) if listed else "info"
        if listed and expected == "info":
            expected = "pass"  # info counts as a pass, as in the verdict
        assert meta["wtvib:status"] == expected, (name, meta)
        if listed:
            assert expected.upper() in meta["Title"], (name, meta["Title"])
        said = re.search(r"(WARN|FAIL): (\S+) on (\S+?)[;:]?(\s|$)", meta["Title"])
        if said:  # a resonance told by a mode at the check's own status (its one name)
            line, mode = said.group(2), said.group(3)
            assert any(
                c["id"] in listed
                and c.get("excitation") == line
                and c.get("modes", {}).get(mode) == c["status"]
                for c in doc["checks"]
            ), (name, meta["Title"])
    resonant = {
        c["id"]
        for c in doc["checks"]
        if c["status"] in ("warn", "fail")
        and (".resonance." in c["id"] or c["id"] == "tower.class")
    }
    assert resonant <= drawn, resonant - drawn  # no failing resonance undrawn


@pytest.mark.parametrize("name", CATALOGUE)
def test_every_catalogue_figure_says_what_its_checks_say(name):
    _figures_agree_with_the_json(audit.run(spec.load(TURBINES / f"{name}.yaml")))


@pytest.mark.parametrize("deck", sorted(DECKS))
def test_every_reference_deck_figure_says_what_its_checks_say(shared, deck):
    _figures_agree_with_the_json(audit.run(load(shared / "reference" / deck, DECKS[deck])))


@pytest.mark.parametrize("case", LINS)
def test_every_linearisation_figure_says_what_its_checks_say(tmp_path, case):
    _figures_agree_with_the_json(audit.run(load(_lin(case, tmp_path), ReadOptions())))


def test_the_isolated_figure_of_a_failing_coupled_tower_says_fail(shared):
    """The NREL 5-MW deck set: 3P crosses the tower in steady operation (system.resonance.3P
    fails); the tower-and-blade figure, whose tower modes are judged as the coupled ones,
    said "PASS: no resonance in operation" in green."""
    report = audit.run(load(shared / "reference/NREL5MW/NREL-5MW.fst", ReadOptions()))
    check = next(c for c in report.checks if c.id == "system.resonance.3P")
    assert check.status == "fail"
    for name in ("campbell", "campbell-system"):
        meta = _meta(diagrams(report)[name])
        assert meta["wtvib:status"] == "fail"
        assert f"FAIL: 3P on {check.numbers['mode']}" in meta["Title"]


def test_the_coupling_table_names_the_modes_as_the_report_does(shared):
    """The coupled modes' energy table named the cyclic pairs by their standstill axis
    (system.blade.flap1.cyclic_yaw) where every other part of the report names the same
    mode by its whirl in operation (system.blade.flap1.backward)."""
    report = audit.run(load(shared / "reference/NREL5MW/NREL-5MW.fst", ReadOptions()))
    ids = {m.id for m in report.modes}
    coupling = next(c for c in report.checks if c.id == "system.coupling")
    rows = coupling.numbers["modes"]
    assert all(r["id"] in ids for r in rows), [r["id"] for r in rows if r["id"] not in ids]
    shapes = {r["id"]: r.get("standstill_shape") for r in rows}
    assert shapes["system.blade.flap1.backward"] in (
        "blade.flap1.cyclic_yaw",
        "blade.flap1.cyclic_tilt",
    )


def test_minor_harmonics_in_steady_operation_are_said_in_the_headline(shared):
    """NREL-5MW.fst: 4P–6P meet the tower within the margin in steady operation, info by
    Hau's energy argument (DAF 48–49); the headline says no resonance *of a dominant line*
    and names them, so that DAF 49 beside it is no contradiction."""
    report = audit.run(load(shared / "reference/NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat",
                            ReadOptions(rpm=(6.9, 12.1))))  # fmt: skip
    from wtvib.plots import headline

    judged = headline.of_modes(report, {"system.tower.fa1", "system.tower.ss1"}, None)
    info = [
        c.numbers["excitation"]
        for c in report.checks
        if c.id.startswith("system.resonance.")
        and c.status == "info"
        and c.numbers.get("regime") == "steady"
    ]
    assert info  # the case this test is about
    if judged.status == "pass":
        assert "no resonance of a dominant line" in judged.words
        assert all(line in judged.words for line in info)
    minor = next(c for c in report.checks if c.id == "system.resonance.5P")
    assert "low-energy" in minor.message and "beside the dominant 1P and 3P" in minor.message


# --------------------------------------------------------------------------------------
# No pass with a negative damping


def _negative_in_words(text: str) -> bool:
    return re.search(r"ζ\S* (=|of|down to)? ?[-−]0?\.?\d*[1-9]", text) is not None


def _no_pass_shows_a_negative_damping(report: audit.Report) -> None:
    for c in report.checks:
        if c.status in ("pass", "info"):
            assert not _negative_in_words(c.message), (c.id, c.message)


def test_the_free_beams_rigid_body_images_are_left_out_and_said(tmp_path):
    """OpenFAST r-test Ideal_Beam_Free_Free_Linear: its ±0.26 roots at 0.0888 Hz are the
    numerical images of the free beam's rigid-body motion (pairs λ, −λ̄ — one damped, its
    twin growing — below the first bending at 3.57 Hz). They were named blade flap1/flap2/
    edge1/edge2 (the bending modes then started at flap3) and system.stability passed with
    "lowest ζ = −0.2601". Now: left out with a warning, the bending modes named from 1,
    and no negative damping in a pass."""
    report = audit.run(load(_lin("Ideal_Beam_Free_Free_Linear", tmp_path), ReadOptions()))
    names = {m.id: m for m in report.modes}
    assert names["system.blade.flap1"].frequency_hz == pytest.approx(3.569, rel=1e-3)
    assert min(m.frequency_hz for m in report.modes) > 1.0  # no 0.0888 Hz mode judged
    assert any("numerical image of rigid-body motion" in w for w in report.warnings)
    stability = next(c for c in report.checks if c.id == "system.stability")
    assert stability.status == "pass"
    _no_pass_shows_a_negative_damping(report)


def test_a_negative_damping_outside_the_range_judged_warns(tmp_path):
    """A mode negatively damped only at a point outside the operating range judged (a
    parked point, the range from --rpm) passed system.stability with "every mode
    positively damped … lowest ζ = −0.26": an instability at a speed the audit does not
    cover is still said — warn, never pass."""
    text = """\
wtvib: 1
turbine: {name: table}
rotor: {blades: 3, orientation: upwind, hub: rigid, speed: {min_rpm: 5, max_rpm: 10}}
results:
  tool: a tool
  modes:
    tower.fa1: {description: tower, rpm: [0, 5, 10], frequency_hz: [0.3, 0.3, 0.3],
                damping_ratio: [-0.05, 0.01, 0.01]}
    blade.flap1: {description: flap, rpm: [0, 5, 10], frequency_hz: [0.9, 0.95, 1.0],
                  damping_ratio: [0.2, 0.2, 0.2]}
"""
    path = tmp_path / "t.yaml"
    path.write_text(text)
    report = audit.run(spec.load(path))
    stability = next(c for c in report.checks if c.id == "system.stability")
    assert stability.status == "warn" and "outside the operating range" in stability.message
    inside = text.replace("[-0.05, 0.01, 0.01]", "[0.01, -0.05, 0.01]")
    path.write_text(inside)
    again = next(c for c in audit.run(spec.load(path)).checks if c.id == "system.stability")
    assert again.status == "fail"


@pytest.mark.parametrize("name", CATALOGUE)
def test_no_catalogue_pass_shows_a_negative_damping(name):
    _no_pass_shows_a_negative_damping(audit.run(spec.load(TURBINES / f"{name}.yaml")))


@pytest.mark.parametrize("case", sorted({p.name.split(".")[0] for p in LIN.glob("*.lin.gz")}))
def test_no_linearisation_pass_shows_a_negative_damping(tmp_path, case):
    _no_pass_shows_a_negative_damping(audit.run(load(_lin(case, tmp_path), ReadOptions())))


# --------------------------------------------------------------------------------------
# A standstill audit


def test_a_parked_linearisation_is_a_standstill_audit(tmp_path):
    """A linearisation at 0 rpm with no --rpm was refused ("give the operating range"): it
    is audited at standstill — the modes' stability judged, no rotor harmonic (said as a
    check of its own), the operating range written as parked, and one figure of the modes
    as computed (frequency and damping at 0 rpm), no Campbell lines from 0 rpm."""
    report = audit.run(load(_lin("WP_Stationary_Linear", tmp_path), ReadOptions()))
    doc = report.to_dict()
    assert doc["operation"]["parked"] is True
    ids = {c["id"]: c for c in doc["checks"]}
    assert ids["system.resonance"]["status"] == "info"
    assert "standstill" in ids["system.resonance"]["message"]
    assert ids["system.stability"]["status"] in ("pass", "fail")
    assert not [c for c in doc["checks"] if c["id"].startswith("system.resonance.")]
    assert set(diagrams(report)) == {"standstill"}
    assert report.spec.turbine.name != tmp_path.name  # named from the file, not its folder


def test_a_range_from_standstill_is_taken(shared):
    """``--rpm 0:12.1`` was refused (MIN must be > 0): steady operation from standstill,
    no start-up regime."""
    deck = shared / "reference/NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"
    report = audit.run(load(deck, ReadOptions(rpm=(0.0, 12.1))))
    assert report.to_dict()["operation"]["steady_rpm"] == [[0.0, 12.1]]


def test_a_spec_cannot_be_parked_without_results(write_spec):
    text = (
        "wtvib: 1\nturbine: {name: t}\nrotor:\n  blades: 3\n  orientation: upwind\n"
        "  hub: rigid\n  speed:\n    parked: true\ntower:\n  modes: {fa1: 0.5}\n"
    )
    with pytest.raises(SpecError, match="standstill audit of another tool") as found:
        spec.load(write_spec(text))
    assert found.value.line == 8  # "parked: true"


def test_one_point_campbell_draws_its_point_and_holds_the_rest(tmp_path):
    """A single linearisation point (12.2 rpm) was drawn as constant lines from 0 rpm with
    "pass" crossings where nothing was computed. The point is drawn at its speed; the
    held values dotted; a resonance judged on held values is drawn hollow, and the title
    fits the figure."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from wtvib.plots import campbell

    report = audit.run(load(_lin("5MW_Land_Linear_Aero", tmp_path), ReadOptions()))
    assert report.spec.turbine.name.startswith("NREL 5.0 MW Baseline")  # from the header
    fig = campbell.campbell_plot(report, ("system",))
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    ax = fig.axes[0]
    legend = [t.get_text() for t in fig.legends[0].get_texts()] if fig.legends else []
    legend += [t.get_text() for t in ax.get_legend().get_texts()] if ax.get_legend() else []
    assert "judged on a held value: no point computed there" in legend
    title = ax.title.get_window_extent(canvas.get_renderer())
    assert title.x0 >= 0 and title.x1 <= canvas.get_width_height()[0]
