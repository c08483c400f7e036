"""Figures draw results: each returns a figure where the report has its data and None
where it has not, and the registry lists what check writes (PNG tagged as wtvib's)."""

import dataclasses

import pytest

from tests.conftest import TURBINES
from wtvib import audit, spec
from wtvib.outputs.files import SOFTWARE_TAG
from wtvib.outputs.plots import FIGURES, campbell, diagrams, drivetrain, png_bytes, rotor
from wtvib.outputs.plots.layout import FIGURE_DPI


@pytest.fixture(scope="module")
def reports():
    return {
        name: audit.run(spec.load(TURBINES / f"{name}.yaml"))
        for name in ("mod-0", "stall-rotor-1mw", "wka-60")
    }


def test_each_figure_draws_only_what_its_report_has(reports):
    mod0, stall_rotor, wka = reports["mod-0"], reports["stall-rotor-1mw"], reports["wka-60"]
    assert FIGURES["drivetrain-power"](mod0) is not None  # synchronous on the grid
    assert FIGURES["drivetrain-power"](wka) is None
    assert FIGURES["floquet"](mod0) is not None and FIGURES["floquet"](wka) is None
    for name in ("blade-flutter", "blade-stability", "blade-stall"):
        assert FIGURES[name](stall_rotor) is not None and FIGURES[name](wka) is None
    assert FIGURES["system-energy"](wka) is None  # no coupled block
    assert campbell.campbell_plot(wka).axes  # the tower-and-blade diagram


def test_a_figure_draws_its_result_into_the_axes_it_is_given(reports):
    """python-control's ``x_plot(result, ax=None)``: a subsystem's figure takes its typed
    result and draws into the axes given (a reviewer's own figure), nothing computed."""
    from matplotlib.figure import Figure

    from wtvib.subsystems import drivetrain as model
    from wtvib.subsystems import rotor as rotor_model

    mod0 = reports["mod-0"]
    fig = Figure()
    left, right = fig.subplots(1, 2)
    found = mod0.result(model.NAME, model.DrivetrainResults)
    assert found is not None and found.power is not None
    band = mod0.rule.natural_band(1.0)
    drawn = drivetrain.power_curve_plot(found.power, mod0.checks, "MOD-0", band, ax=left)
    assert drawn is fig and left.lines and not right.lines
    floquet = mod0.result(rotor_model.NAME, rotor_model.RotorResults)
    assert floquet is not None
    speed = mod0.spec.rotor.speed
    assert rotor.floquet_plot(floquet, mod0.checks, "MOD-0", speed, ax=right) is fig
    assert right.lines and "stability map" in right.get_title()


def test_the_registry_names_every_figure_and_tags_the_png(reports):
    names = set(diagrams(reports["mod-0"]))
    assert {"campbell", "campbell-drivetrain", "drivetrain-power", "floquet"} <= names
    data = png_bytes(campbell.campbell_plot(reports["wka-60"]))
    assert data.startswith(b"\x89PNG") and SOFTWARE_TAG.encode() in data[:4096]


def test_the_png_holds_the_pixels_agg_drew(reports):
    """wtvib writes its PNGs itself (plots.png_bytes): a PNG reader gets Agg's pixels, RGB,
    at the figure's resolution."""
    import io

    import numpy as np
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from PIL import Image

    fig = campbell.campbell_plot(reports["wka-60"])
    image = Image.open(io.BytesIO(png_bytes(fig)))
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    assert image.mode == "RGB" and image.size == canvas.get_width_height(physical=True)
    assert np.array_equal(np.asarray(image), np.asarray(canvas.buffer_rgba())[:, :, :3])
    assert round(image.info["dpi"][0]) == FIGURE_DPI


def test_damping_diagram_and_crossing_dafs(shared, tmp_path):
    """With aerodynamics: a damping-versus-wind diagram beside the Campbell diagrams, and
    the Campbell crossings labelled with their DAF (the numbers the findings hold)."""
    from wtvib import audit
    from wtvib.importers import load as load_any
    from wtvib.outputs.plots import diagrams
    from wtvib.outputs.plots.campbell import campbell_plot

    report = audit.run(load_any(shared / "reference/NREL5MW/NREL-5MW.fst"))
    figs = diagrams(report)
    assert "damping" in figs
    ax = figs["damping"].axes[0]
    assert len(ax.get_lines()) >= sum(1 for m in report.modes if m.judged and m.operating)
    texts = [t.get_text() for t in campbell_plot(report, ("system",)).axes[0].texts]
    ss = next(
        f for f in report.findings if f.mode.id == "system.tower.ss1" and f.excitation.id == "3P"
    )
    assert f"DAF {ss.crossing_daf[0]:.3g}" in texts


def test_no_damping_diagram_without_aerodynamics(write_spec):
    from wtvib import audit
    from wtvib.outputs.plots import diagrams
    from wtvib.spec import load

    assert "damping" not in diagrams(audit.run(load(write_spec())))


# --- drawing beside the audit (wtvib.outputs.plots.render) -----------------------------


def test_forked_drawing_gives_the_bytes_drawing_in_process_gives(reports, monkeypatch):
    """The forked drawing process (and its own forks, one per core) returns exactly the PNG
    bytes of in-process drawing, in the registry's order — here with every detail figure
    of MOD-0 (Floquet, drive train, power sweep), one process per figure (two per core, of
    three cores)."""
    from wtvib.outputs.plots import render

    monkeypatch.setattr(render, "forking", lambda: True)
    monkeypatch.setattr(render, "cores", lambda: 3)
    inline = render.inline(reports["mod-0"], detail=True)
    assert len(inline) >= 4
    with render.Drawer() as drawer:
        assert drawer._child is not None  # it did fork
        forked = drawer.pngs(reports["mod-0"], detail=True)
    assert list(forked) == list(inline) and forked == inline


def test_a_report_that_does_not_pickle_is_drawn_in_process(reports, monkeypatch):
    """The report goes to the drawing process pickled; one that cannot be (an unpicklable
    cache a model kept) costs the parallel drawing, never the figures or the verdict."""
    import pickle

    from wtvib.outputs.plots import render

    monkeypatch.setattr(render, "forking", lambda: True)
    monkeypatch.setattr(render, "cores", lambda: 3)
    inline = render.inline(reports["mod-0"], detail=False)
    with render.Drawer() as drawer:
        assert drawer._child is not None  # it did fork

        def refuse(*args: object, **kwargs: object) -> bytes:
            raise TypeError("cannot pickle 'mappingproxy' object")

        monkeypatch.setattr(pickle, "dumps", refuse)  # here only: the child forked already
        drawn = drawer.pngs(reports["mod-0"], detail=False)
        monkeypatch.undo()
    assert drawn == inline


_DRAW = """
import pickle, sys
if sys.argv[1] == "plain":
    import matplotlib.pyplot  # matplotlib as a user's program imports it
from wtvib import audit, spec
from wtvib.outputs.plots import render
pngs = render.inline(audit.run(spec.load(sys.argv[2])), detail=True)
import matplotlib.lines
sys.stdout.buffer.write(pickle.dumps((pngs, matplotlib.lines.Line2D.set.__doc__)))
"""


def test_matplotlib_without_its_help_text_draws_the_same_pixels():
    """render._lean_matplotlib skips matplotlib's generated docstrings and signatures: a
    fresh process drawing MOD-0's every figure that way writes the bytes of one that
    imported matplotlib as usual first (where the skip does not apply)."""
    import pickle
    import subprocess
    import sys

    def draw(how: str) -> tuple[dict[str, bytes], str | None]:
        run = subprocess.run(
            [sys.executable, "-c", _DRAW, how, str(TURBINES / "mod-0.yaml")],
            capture_output=True,
            check=True,
        )
        return pickle.loads(run.stdout)  # type: ignore[no-any-return]

    (lean, lean_doc), (plain, plain_doc) = draw("lean"), draw("plain")
    assert lean_doc is None and plain_doc  # the skip applied in one process only
    assert len(lean) >= 4 and lean == plain


def test_no_fork_while_another_thread_runs(monkeypatch):
    """A fork copies no thread but every lock a thread holds (a spinner's, a Dask client's):
    with another thread alive the figures are drawn in-process."""
    import threading

    from wtvib.outputs.plots import render

    monkeypatch.setattr(render, "cores", lambda: 2)
    monkeypatch.delenv("WTVIB_DRAW", raising=False)
    assert render.forking() or threading.active_count() > 1
    stop = threading.Event()
    other = threading.Thread(target=stop.wait)
    other.start()
    try:
        assert not render.forking()
        with render.Drawer() as drawer:
            assert drawer._child is None
    finally:
        stop.set()
        other.join()


def test_a_failed_drawing_process_costs_time_not_figures(reports, monkeypatch):
    """A drawing process that fails (here: its import step raises) reports it, and the
    figures are drawn in-process instead — the same bytes."""
    from wtvib.outputs.plots import render

    def broken() -> None:
        raise MemoryError("no room for matplotlib")

    monkeypatch.setattr(render, "forking", lambda: True)
    monkeypatch.setattr(render, "_warm", broken)
    with render.Drawer() as drawer:
        got = drawer.pngs(reports["wka-60"], detail=False)
    assert got == render.inline(reports["wka-60"], detail=False)


def test_an_audit_that_fails_ends_the_drawing_process(monkeypatch):
    """Leaving the Drawer without asking for figures (a spec error, Ctrl-C) ends and reaps
    the drawing process: no orphan, no zombie."""
    import os

    from wtvib.outputs.plots import render

    monkeypatch.setattr(render, "forking", lambda: True)
    with pytest.raises(ValueError), render.Drawer() as drawer:
        assert drawer._child is not None
        pid = drawer._child[0]
        raise ValueError("the audit failed")
    with pytest.raises(ChildProcessError):
        os.waitpid(pid, os.WNOHANG)  # reaped already


def test_a_caller_that_fails_after_sending_the_report_ends_the_drawing(reports, monkeypatch):
    """send() starts the drawing; a caller that then fails (its text output, a file that
    may not be replaced) leaves the Drawer without collecting: the drawing process is
    killed and reaped, not waited for."""
    import os
    import signal

    from wtvib.outputs.plots import render

    monkeypatch.setattr(render, "forking", lambda: True)
    kills: list[tuple[int, int]] = []
    real_kill = os.kill
    monkeypatch.setattr(
        os, "kill", lambda pid, sig: (kills.append((pid, sig)), real_kill(pid, sig))
    )
    with pytest.raises(ValueError), render.Drawer() as drawer:
        assert drawer._child is not None
        pid = drawer._child[0]
        drawer.send(reports["mod-0"], detail=True)  # every figure: seconds of drawing
        raise ValueError("the caller failed")
    assert kills == [(pid, signal.SIGKILL)]  # killed, not waited for
    with pytest.raises(ChildProcessError):
        os.waitpid(pid, os.WNOHANG)  # reaped already


def test_send_then_pngs_gives_the_figures_once(reports, monkeypatch):
    from wtvib.outputs.plots import render

    monkeypatch.setattr(render, "forking", lambda: True)
    with render.Drawer() as drawer:
        drawer.send(reports["wka-60"], detail=False)
        got = drawer.pngs(reports["wka-60"], detail=False)
    assert got == render.inline(reports["wka-60"], detail=False)


def test_a_hung_drawing_process_is_killed_and_the_figures_drawn_in_process(reports, monkeypatch):
    import time

    from wtvib.outputs.plots import render

    monkeypatch.setattr(render, "forking", lambda: True)
    monkeypatch.setattr(render, "_warm", lambda: time.sleep(60))
    monkeypatch.setattr(render, "TIMEOUT_S", 0.5)
    start = time.monotonic()
    with render.Drawer() as drawer:
        got = drawer.pngs(reports["wka-60"], detail=False)
    assert time.monotonic() - start < 30
    assert got == render.inline(reports["wka-60"], detail=False)


def test_no_process_to_fork_means_drawing_in_process(reports, monkeypatch):
    import os

    from wtvib.outputs.plots import render

    def refused() -> int:
        raise BlockingIOError(11, "Resource temporarily unavailable")

    monkeypatch.setattr(render, "forking", lambda: True)
    monkeypatch.setattr(os, "fork", refused)
    with render.Drawer() as drawer:
        assert drawer._child is None
        got = drawer.pngs(reports["wka-60"], detail=False)
    assert got == render.inline(reports["wka-60"], detail=False)


def test_a_legend_of_many_rows_makes_the_figure_taller_not_the_axes_vanish():
    """Fixed margins (plots.layout) with a legend under the axes: 90 entries (a results
    import with many modes) need more height than the figure has; it grows, the axes keep
    MIN_AXES_IN, and drawing does not fail (subplots_adjust refuses bottom ≥ top)."""
    from matplotlib.figure import Figure

    from wtvib.outputs.plots.layout import MIN_AXES_IN, fixed_layout, legend_below

    fig = Figure(figsize=(10, 7), dpi=150)
    ax = fig.add_subplot()
    for i in range(90):
        ax.plot([0, 1], [i, i + 1], label=f"mode {i}")
    handles, labels = ax.get_legend_handles_labels()
    legend_below(fig, ax, handles, labels, columns=2, fontsize=8, top=0.5)
    assert fig.get_size_inches()[1] > 7
    assert ax.get_position().height * fig.get_size_inches()[1] >= MIN_AXES_IN - 1e-9
    assert png_bytes(fig).startswith(b"\x89PNG")
    narrow = Figure(figsize=(4, 3))
    box = narrow.add_subplot()
    fixed_layout(narrow, left=9.0)  # tick labels wider than the figure: cut, not an error
    assert box.get_position().width > 0.2


# --- what a figure shows is inside it ----------------------------------------------------


@pytest.mark.parametrize(
    "name", ["aeroman", "stall-rotor-1mw", "euros-44m", "mod-2", "mod-0", "darrieus"]
)
def test_every_text_of_a_figure_is_inside_it(name):
    """Fixed margins (plots.layout) must leave room for what the figure writes: no title,
    tick, line label (Aeroman's "mesh.stage1" at the right edge) or legend entry is cut
    at the figure's edge — every figure of the turbine, drawn."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    report = audit.run(spec.load(TURBINES / f"{name}.yaml"))
    for suffix, fig in diagrams(report, detail=True).items():
        canvas = FigureCanvasAgg(fig)
        canvas.draw()
        drawn = fig.get_tightbbox(canvas.get_renderer())  # [in]: everything drawn
        width, height = fig.get_size_inches()
        tol = 1 / fig.dpi  # a pixel
        assert drawn.x0 >= -tol and drawn.y0 >= -tol, (suffix, drawn.bounds)
        assert drawn.x1 <= width + tol and drawn.y1 <= height + tol, (suffix, drawn.bounds)


@pytest.mark.parametrize("name", ["aeroman", "stall-rotor-1mw", "mod-0", "wka-60"])
def test_every_text_prints_at_7_pt_or_more_in_the_pdf(name):
    """The PDF prints each figure at its text width (6.85 in): a 10-in figure's 8-pt text
    came out at 5.5 pt. Every text of every figure, scaled to that width, is
    7 pt or more."""
    from matplotlib.text import Text

    from wtvib.outputs.plots.layout import PDF_FIGURE_IN

    report = audit.run(spec.load(TURBINES / f"{name}.yaml"))
    for suffix, fig in diagrams(report, detail=True).items():
        scale = min(1.0, PDF_FIGURE_IN / fig.get_size_inches()[0])
        small = [
            (t.get_text()[:30], t.get_fontsize())
            for t in fig.findobj(Text)
            if t.get_visible() and t.get_text().strip() and t.get_fontsize() * scale < 7 - 1e-9
        ]
        assert not small, (suffix, small[:5])


def test_one_resonance_is_one_marker(reports):
    """WKA-60 (the demo): the tower's first bending meets 2P at the rated speed, 23 rpm, in
    fore-aft and side-side alike — one resonance. It was drawn as a diamond, a square
    ("margin violated, no crossing") a rpm below and a warn cross under the diamond, with a
    legend naming markers nobody could see. Now one marker, and the key names only what is
    drawn."""
    wka = reports["wka-60"]
    on_2p = [m for m in wka.marks if m.line == "2P" and m.status in ("warn", "fail")]
    assert len(on_2p) == 1
    (mark,) = on_2p
    assert mark.kind == "least margin" and mark.rpm == pytest.approx(23.0, abs=0.05)
    assert set(mark.modes) == {"tower.fa1", "tower.ss1"}
    fig = campbell.campbell_plot(wka)
    warn_or_fail = [
        line
        for line in fig.axes[0].lines
        if line.get_marker() in ("D", "s", "X")
        and line.get_color() in (campbell.STATUS_COLOUR["fail"], campbell.STATUS_COLOUR["warn"])
    ]
    assert sum(len(line.get_xdata()) for line in warn_or_fail) == 1
    key = _legend_texts(fig)
    assert LEAST in key and BAND not in key
    assert "crossing: warn" not in key and "crossing: fail" not in key


def test_a_figure_is_titled_with_the_judgement_of_what_it_draws(shared):
    """The NREL 5-MW deck set: its tower-and-blade figure draws the isolated tower modes
    that are judged as the coupled ones, which 3P crosses in steady operation — it said
    "PASS: no resonance in operation" above a FAIL verdict. Both figures now say the
    failure of the modes they draw, in the words of the check (its governing mode, the one
    the terminal and the JSON name); the drive train's figure, whose modes pass, says so."""
    from wtvib.importers import ReadOptions, load

    deck = shared / "reference/NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"
    report = audit.run(load(deck, ReadOptions(rpm=(6.9, 12.1))))
    check = next(c for c in report.checks if c.id == "system.resonance.3P")
    said = f"FAIL: 3P on {check.numbers['mode']}"
    tower = campbell.campbell_plot(report, campbell.DIAGRAMS["campbell"]).axes[0]
    system_ = campbell.campbell_plot(report, campbell.DIAGRAMS["campbell-system"]).axes[0]
    assert said in tower.get_title().replace("\n", " ")
    assert "judged as coupled modes" in " ".join(t.get_text() for t in tower.texts)
    assert said in system_.get_title().replace("\n", " ")
    drive = campbell.campbell_plot(report, campbell.DIAGRAMS["campbell-drivetrain"]).axes[0]
    assert "FAIL" not in drive.get_title()


def test_a_daf_below_one_says_why():
    # a crossing with ζ above 0.5 has 1/(2ζ) < 1: no amplification, and the label says so
    assert campbell._daf_label(0.65, 0.77) == "DAF 0.65 (ζ 77%)"
    assert campbell._daf_label(95.4, 0.0052) == "DAF 95.4"


def test_log_axes_label_their_decades_as_plain_numbers(reports):
    """Damping in % of critical on a symlog axis reads 100, 10, 1, 0.1, 0, −0.1 — plain
    numbers, no mathtext powers of ten (plots.layout.plain_decades)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from wtvib.outputs.plots.layout import _plain

    assert [_plain(v) for v in (100.0, 1.0, 0.1, 0.0, -0.1, 1e-5, 3e7)] == [
        "100", "1", "0.1", "0", "\u22120.1", "1e-5", "1e7"
    ]  # fmt: skip
    fig = campbell.damping_plot(reports["stall-rotor-1mw"])
    FigureCanvasAgg(fig).draw()
    labels = [t.get_text() for t in fig.axes[0].get_yticklabels() if t.get_text()]
    assert "10" in labels and "0" in labels and not any("$" in t for t in labels)


def test_the_damping_figure_says_the_aerodynamic_model_the_report_says(reports):
    """The damping figure's title names the model the audit used — the lift lagged or
    quasi-steady, the induction frozen or in equilibrium — as the terminal report does (an
    OpenFAST deck with UA_Mod 0 and DBEMT_Mod 0 was drawn as "lift lagged by the shed
    wake, frozen induction" under a report saying the lift quasi-steady)."""
    report = reports["stall-rotor-1mw"]
    aero = report.spec.aerodynamics
    assert aero is not None and aero.shed_wake and aero.induction != "equilibrium"
    title = campbell.damping_plot(report).axes[0].get_title()
    assert "lift lagged by the shed wake" in " ".join(title.split())
    quiet = report.spec.model_copy(
        update={
            "aerodynamics": aero.model_copy(update={"shed_wake": False, "induction": "equilibrium"})
        }
    )
    said = campbell.damping_plot(dataclasses.replace(report, spec=quiet)).axes[0].get_title()
    assert "lift quasi-steady, induction in equilibrium" in " ".join(said.split())


LEAST = "resonance in operation, at its least margin"
BAND = "margin violated, line and mode never meet"


def _legend_texts(fig) -> list[str]:  # type: ignore[no-untyped-def]
    return [t.get_text() for legend in fig.legends for t in legend.get_texts()] + [
        t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().get_texts()
    ]


def test_a_campbell_diagram_names_and_keys_only_what_it_draws(reports):
    """MOD-2 has a tower and no blade model: its diagram's title says "tower", not "tower
    and blades", and every crossing passes or is only told (info) — so its key names no
    fail or warn marker and no least-margin diamond (none is drawn). The Aeroman's drive
    train fails at a mesh line in steady operation: the diamond is drawn and keyed there."""
    mod2 = audit.run(spec.load(TURBINES / "mod-2.yaml"))
    fig = campbell.campbell_plot(mod2)
    title = fig.axes[0].get_title()
    assert "Campbell diagram, tower\n" in title and "blades" not in title
    key = _legend_texts(fig)
    assert "crossing: pass" in key and "crossing: info" in key
    assert not {"crossing: fail", "crossing: warn", LEAST} & set(key)
    assert not any("quick-pass" in t for t in key)  # MOD-2 has no quick-pass band
    aeroman = audit.run(spec.load(TURBINES / "aeroman.yaml"))
    drive = campbell.campbell_plot(aeroman, campbell.DIAGRAMS["campbell-drivetrain"])
    assert LEAST in _legend_texts(drive)
    both = campbell.campbell_plot(reports["stall-rotor-1mw"])  # tower and blade modes
    assert "Campbell diagram, tower and blades\n" in both.axes[0].get_title()
    assert BAND not in key


def test_a_warning_with_no_crossing_is_marked_on_the_diagram():
    """The Darrieus rotor warns because its first flatwise mode (1.26 Hz) sits inside the
    2P margin at overspeed, 34.6–35.7 rpm, without 2P ever meeting it there: no crossing
    marker would show the warning, so a square in the warning colour marks the band's
    middle (35.2 rpm) on the mode's curve, and the key names it."""
    r = audit.run(spec.load(TURBINES / "darrieus.yaml"))
    fig = campbell.campbell_plot(r)
    assert BAND in _legend_texts(fig)
    squares = [
        line
        for line in fig.axes[0].lines
        if line.get_marker() == "s" and line.get_color() == campbell.STATUS_COLOUR["warn"]
    ]
    assert len(squares) == 1
    (x,), (y,) = squares[0].get_data()
    assert 34.6 < x < 35.7 and abs(y - 1.28) < 0.05


def test_a_crossing_hidden_under_a_worse_one_is_not_in_the_legend(reports):
    """WKA-60's drive train has one frequency with the generator on the grid and free
    (1.88 Hz): the 6P and 5P lines cross both modes at the same place, once judged info,
    once pass. The info marker covers the pass one, so the legend names no pass crossing
    a reader could not find. (Without its gear ratio: the high-speed shaft's 1G line has
    pass crossings of its own, below the operating range, which the legend rightly names.)"""
    from wtvib.judge.excitation import operating_range

    data = reports["wka-60"].spec.model_dump(mode="json", exclude_none=True)
    data["drivetrain"].pop("gear_ratio")
    wka = audit.run(spec.from_data(data))
    op = operating_range(wka.spec.rotor.speed)
    marks = [
        (f.excitation.id, c, f.status_at(c, op))
        for f in wka.findings
        if f.mode.subsystem == "drivetrain"
        for c in f.crossings
    ]
    passes = [(line, c) for line, c, status in marks if status == "pass"]
    assert passes  # each within 0.1 % of the speed range of an info crossing of its line
    for line, c in passes:
        assert any(
            m[0] == line and m[2] == "info" and abs(m[1] - c) < 1e-3 * op.overspeed for m in marks
        )
    fig = diagrams(wka, detail=False)["campbell-drivetrain"]
    legends = [ax.get_legend() for ax in fig.axes if ax.get_legend()] + list(fig.legends)
    texts = [t.get_text() for legend in legends for t in legend.get_texts()]
    assert "crossing: info" in texts and "crossing: pass" not in texts


def test_the_drive_train_figure_draws_the_chain_it_was_computed_on(reports):
    """Hau Fig. 7.10: the distribution of inertia and stiffness along the train heads the
    mode shapes — the reduced chain the modes came from (the blades' edgewise spring too)."""
    from wtvib.subsystems import drivetrain as model

    wka = reports["wka-60"]
    chain = wka.result(model.NAME, model.DrivetrainResults).chain
    again = model.reduce(wka.spec, model.edge_frequency(wka.spec, list(wka.modes)))
    assert chain.names == again.names and list(chain.stiffness) == list(again.stiffness)
    fig = FIGURES["drivetrain-modes"](wka)
    assert fig is not None
    bars = fig.axes[0].patches
    assert [b.get_height() for b in bars] == pytest.approx(list(chain.inertia))
    assert "stiffness" in fig.axes[-1].get_ylabel() or any(
        "stiffness" in ax.get_ylabel() for ax in fig.axes
    )
