"""Campbell (resonance) diagrams: natural frequencies and excitation lines vs rotor speed.

Calculate first, draw second: everything drawn comes from the audit
:class:`~wtvib.audit.Report` (its modes, findings and operating range). matplotlib is
imported lazily, with the Agg backend, so ``wtvib --help`` stays fast.
"""

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from ...aero import aerodamping
from ...audit import SUBSYSTEMS, Report
from ...judge.analysis import DIAGRAMS as DIAGRAM_NAMES
from ...results import Mode, Sampled, by_frequency
from ...rules import NEGATIVE, STATUS_ORDER
from ...subsystems import tower as tower_model
from ...units import rad_s_to_rpm, rpm_to_rad_s
from .. import words
from . import headline
from .headline import Headline
from .layout import (
    FIGURE_DPI,
    MAX_FIGURE_IN,
    SMALL_PT,
    TITLE_LINE_IN,
    fit,
    fixed_layout,
    legend_below,
    plain_decades,
    text_width,
    title_height,
)

#: The Campbell diagram's size [in]: printed at the PDF's text width (6.85 in) its 8-pt
#: labels stay above 7 pt.
FIGURE_IN = (MAX_FIGURE_IN, 5.6)
#: matplotlib's "large" title at its default 10-pt base.
TITLE_PT = 12

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ...studies.design import Band

STATUS_COLOUR = {"pass": "#2e7d32", "info": "#1565c0", "warn": "#ef6c00", "fail": "#c62828"}
#: Each drawn subsystem's words in a diagram's title (its declaration's ``title``).
SUBSYSTEM_TITLE = {sub.name: sub.title for sub in SUBSYSTEMS if sub.title}
#: Subsystems drawn together on one diagram (their declarations' ``diagram``), by file stem
#: suffix.
DIAGRAMS: dict[str, tuple[str, ...]] = {
    name: tuple(sub.name for sub in SUBSYSTEMS if sub.diagram == name) for name in DIAGRAM_NAMES
}


def campbell_plot(report: Report, subsystems: Sequence[str] = ("tower", "blade")) -> "Figure":
    """Draw the Campbell diagram of some subsystems of an audited turbine.

    Shows the mode curves with their margin bands, the excitation lines (dominant thick,
    secondary medium, minor thin), the steady operating range shaded, overspeed hatched,
    quick-pass bands, and each resonance (``Report.marks``) marked once in the colour of its
    status. The title says what the diagram shows and how it is judged — its own modes'
    worst finding, not the turbine's verdict.
    """
    from matplotlib.figure import Figure

    spec = report.spec
    covered = [m for m in report.modes if m.subsystem in subsystems]
    ids = {m.id for m in covered}
    findings = [f for f in report.findings if f.mode.id in ids]
    rpm_top = float(rad_s_to_rpm(report.operating_range.overspeed)) * 1.08
    rpm = np.linspace(0.0, rpm_top, 400)
    omega = rpm_to_rad_s(rpm)
    f_top = _top_frequency(covered, findings, spec.rotor.blades, rpm_top, omega)
    modes = [m for m in covered if m.frequency_hz <= f_top]
    hidden = [m for m in covered if m.frequency_hz > f_top]

    fig = Figure(figsize=FIGURE_IN, dpi=FIGURE_DPI)
    ax = fig.add_subplot()
    shown = _draw_operation(ax, spec.rotor.speed)
    right = _draw_lines(ax, findings, rpm, omega, f_top, shown)
    _draw_modes(ax, modes, report, rpm, omega, shown)
    marks = [m for m in report.marks if set(m.modes) & ids and m.hz <= f_top]
    spans = {m.id: computed_rpm(m) for m in covered}
    held = [m for m in marks if _on_held_values(m, spans)]
    _draw_marks(ax, [m for m in marks if m not in held], rpm_top, f_top, shown)
    _draw_held_marks(ax, held, shown)

    ax.set_xlim(0, rpm_top)
    low = min((m.frequency_hz for m in modes), default=f_top)
    shown_top = max((m.frequency_hz for m in modes), default=low)
    if shown_top / low > 20:  # modes spanning decades (drive trains): log scale
        ax.set_yscale("log")
        plain_decades(ax.yaxis)
        ax.set_ylim(low * 0.5, f_top)
    else:
        ax.set_ylim(0, f_top)
    ax.set_xlabel("rotor speed [rpm]")
    ax.set_ylabel("frequency [Hz]")
    ax.grid(True, alpha=0.3)
    heading, plain, judged = _title(report, subsystems, covered)
    ax.set_title(heading, color=STATUS_COLOUR[judged.status], fontweight="bold", y=1.0)
    headline.stamp(fig, plain, judged)
    notes = []
    if hidden:
        low_hz, high_hz = (f"{g(m.frequency_hz for m in hidden):.3g}" for g in (min, max))
        notes.append(
            f"{len(hidden)} mode{'s' if len(hidden) > 1 else ''} above every excitation line "
            f"not drawn ({low_hz if low_hz == high_hz else f'{low_hz}–{high_hz}'} Hz)"
        )
    if any(m.superseded_by for m in modes):
        notes.append("dashed: isolated models, judged as coupled modes (system diagram)")
    if any(not m.judged and not m.superseded_by for m in modes):
        notes.append("not judged: a mode of a condition in no operating regime")
    if notes:
        ax.text(
            0.99,
            0.99,
            "\n".join(notes),
            transform=ax.transAxes,
            ha="right",
            va="top",
            fontsize=SMALL_PT,
            color="#616161",
            bbox={"facecolor": "white", "alpha": 0.8, "edgecolor": "none", "pad": 1.5},
        )
    _legend(ax, report.rule.label, shown, title_lines=heading.count("\n") + 1, right=right)
    return fig


def computed_rpm(mode: Mode) -> tuple[float, float] | None:
    """The speeds [rpm] another tool computed a mode at (its first and last point), None
    for wtvib's own modes (computed at every speed drawn)."""
    if mode.origin != "imported" or not isinstance(mode.curve, Sampled):
        return None
    rpm = np.asarray(mode.curve.omega) * 30 / np.pi
    return float(rpm.min()), float(rpm.max())


def _top_frequency(modes, findings, blades: int, rpm_top: float, omega) -> float:  # type: ignore[no-untyped-def]
    """The top of the frequency axis: modes above every excitation line cannot resonate,
    so the axis stops there (but always shows the blade-passing line at overspeed)."""
    top_mode = max((float(m.frequency_at(omega).max()) for m in modes), default=1.0)
    blade_pass = blades * rpm_top / 60.0
    top_line = max((f.excitation.order for f in findings), default=1.0) * rpm_top / 60.0
    return max(min(top_mode * 1.18, top_line * 1.05), blade_pass * 1.1)


def _draw_operation(ax, speed) -> set[str]:  # type: ignore[no-untyped-def]
    """Steady operation shaded, quick-pass bands and overspeed hatched; what was drawn."""
    shown = {"steady"}
    for a, b in speed.steady_rpm:
        if b > a:
            ax.axvspan(a, b, color="#c8e6c9", alpha=0.55, lw=0)
        else:
            ax.axvline(a, color="#66bb6a", lw=6, alpha=0.45)
    for a, b in speed.quick_pass_rpm:
        ax.axvspan(a, b, facecolor="none", hatch="//", edgecolor="#81c784", lw=0)
        shown.add("quick-pass")
    if speed.overspeed > speed.top_rpm:
        ax.axvspan(
            speed.top_rpm,
            speed.overspeed,
            facecolor="#fff3e0",
            hatch="xx",
            edgecolor="#ffcc80",
            lw=0,
        )
        shown.add("overspeed")
    return shown


#: How each energy class of excitation line is drawn.
LINE_STYLE = {
    "dominant": dict(color="#212121", lw=1.8, ls="-"),
    "secondary": dict(color="#424242", lw=1.2, ls="--"),
    "minor": dict(color="#9e9e9e", lw=0.8, ls=":"),
}


def _draw_lines(ax, findings, rpm, omega, f_top: float, shown: set[str]) -> float:  # type: ignore[no-untyped-def]
    """The excitation lines, each named where it leaves the axes; the right margin [in]
    their names need."""
    right = 0.3
    for exc in {f.excitation.id: f.excitation for f in findings}.values():
        style = LINE_STYLE[exc.energy]
        f_line = exc.frequency_hz(omega)
        ax.plot(rpm, f_line, **style)
        shown.add(exc.energy)
        right = max(right, _label_line(ax, exc.id, rpm, f_line, f_top, style["color"]))  # type: ignore[arg-type]
    return right


def _draw_modes(ax, modes, report: Report, rpm, omega, shown: set[str]) -> None:  # type: ignore[no-untyped-def]
    """The mode curves with their margin bands (judged modes), the modes another mode
    stands for dashed, another tool's points, the sampled spread and the yaw play band."""
    rule = report.rule
    drawn: list[np.ndarray] = []
    for mode, colour in zip(modes, _palette(len(modes)), strict=True):
        f_n = mode.frequency_at(omega)
        label = f"{mode.id}  {mode.frequency_hz:.3g} Hz"
        if report.spec.rotor.orientation == "vertical-axis":  # Darrieus modes need names
            label += f" — {mode.description}"
        if not mode.judged:  # shown as what it is: no margin band, no crossings
            label += (
                f" (isolated; judged as {mode.superseded_by})"
                if mode.superseded_by
                else " (not judged)"
            )
            ax.plot(rpm, f_n, color=colour, lw=1.0, ls="--", alpha=0.7, label=label)
            continue
        lo, hi = rule.forbidden_band(1.0)
        ax.fill_between(rpm, f_n * lo, f_n * hi, color=colour, alpha=0.16, lw=0)
        shown.add("margin")
        # a mode on top of one drawn before (fa1 and ss1 of a round tower) is dashed, so
        # that both stay visible
        under = any(np.allclose(f_n, g, rtol=5e-3) for g in drawn)
        drawn.append(f_n)
        span = computed_rpm(mode)
        if span is None:
            ax.plot(rpm, f_n, color=colour, lw=2.2, label=label, ls=(0, (4, 3)) if under else "-")
            continue
        # another tool's operating points: solid where it computed (between its first and
        # last point), thin and dotted where the audit holds its values (beyond them)
        inside = (rpm >= span[0]) & (rpm <= span[1])
        ax.plot(rpm, np.where(inside, np.nan, f_n), color=colour, lw=0.9, ls=":")
        ax.plot(rpm, np.where(inside, f_n, np.nan), color=colour, lw=2.2, label=label)
        assert isinstance(mode.curve, Sampled)
        pts = np.asarray(mode.curve.omega)
        ax.plot(pts * 30 / np.pi, mode.curve.hz, "o", color=colour, ms=5, mec="white")
        shown.add("held")
    spread = report.uncertainty["modes"] if report.uncertainty is not None else {}
    for mode in modes:
        if "p5_hz" in spread.get(mode.id, {}):  # the 5–95 % band of the sampled frequency
            band = spread[mode.id]
            ax.axhspan(
                band["p5_hz"],
                band["p95_hz"],
                facecolor="none",
                hatch="...",
                edgecolor="#5c6bc0",
                lw=0,
            )
            shown.add("spread")
    by_id = {m.id: m for m in modes}
    if "yaw.1" in by_id and "yaw.play.1" in by_id:  # Hau Fig. 7.18: the band play opens
        ax.fill_between(
            rpm,
            by_id["yaw.play.1"].frequency_at(omega),
            by_id["yaw.1"].frequency_at(omega),
            color="#ff7043",
            alpha=0.25,
            lw=0,
            label="yaw frequency range with gear play",
        )


#: The marker of each kind of mark: (marker, size [pt]) for warn/fail and milder.
MARKER = {"least margin": ("D", 9), "band violated": ("s", 8)}


def _draw_marks(ax, marks, rpm_top: float, f_top: float, shown: set[str]) -> None:  # type: ignore[no-untyped-def]
    """One marker per resonance (``Report.marks``), grouped by kind and status, the worse
    drawn over the milder; the dynamic amplification beside the ones that warn or fail
    (with ζ where it is below 1: damped so heavily that the line meets it unamplified)."""
    groups: dict[tuple[str, str], list[tuple[float, float]]] = {}
    for m in marks:
        groups.setdefault((m.kind, m.status), []).append((m.rpm, m.hz))
    for kind, status in sorted(groups, key=lambda k: STATUS_ORDER[k[1]]):
        big = STATUS_ORDER[status] >= STATUS_ORDER["warn"]
        marker, size = MARKER.get(kind, ("X", 11) if big else ("o", 6))
        at_rpm, at_hz = zip(*groups[(kind, status)], strict=True)
        ax.plot(
            at_rpm,
            at_hz,
            ls="",
            marker=marker,
            ms=size,
            color=STATUS_COLOUR[status],
            mec="black" if kind in MARKER else "white",
            mew=0.8,
            zorder=6 if kind in MARKER else 5,
        )
        shown.add(kind if kind in MARKER else f"crossing: {status}")
    # each resonance's DAF, the largest first; one label where several stand together
    placed: list[tuple[float, float]] = []
    for m in sorted(marks, key=lambda m: -(m.daf or 0.0)):
        if STATUS_ORDER[m.status] < STATUS_ORDER["warn"] or m.daf is None:
            continue
        if any(abs(m.rpm - x) < 0.04 * rpm_top and abs(m.hz - y) < 0.04 * f_top for x, y in placed):
            continue
        placed.append((m.rpm, m.hz))
        ax.annotate(
            _daf_label(m.daf, m.damping),
            (m.rpm, m.hz),
            xytext=(5, -11),
            textcoords="offset points",
            fontsize=SMALL_PT,
            color=STATUS_COLOUR[m.status],
            zorder=7,
        )


def _on_held_values(mark, spans) -> bool:  # type: ignore[no-untyped-def]
    """Whether a resonance is judged where no mode behind it was computed: another tool's
    modes beyond their first and last points, where the audit holds their values."""
    out = [spans.get(m) for m in mark.modes]
    tol = 1e-6 * max(mark.rpm, 1.0)
    return all(s is not None and not s[0] - tol <= mark.rpm <= s[1] + tol for s in out)


def _draw_held_marks(ax, marks, shown: set[str]) -> None:  # type: ignore[no-untyped-def]
    """The resonances judged on held values, hollow in their status's colour: where the
    tool computed nothing, the judgement rests on the audit's assumption alone."""
    for m in marks:
        ax.plot(
            m.rpm,
            m.hz,
            ls="",
            marker="o",
            ms=7,
            mfc="white",
            mec=STATUS_COLOUR[m.status],
            mew=1.6,
            zorder=5,
        )
    if marks:
        shown.add("held mark")


def _daf_label(daf: float, damping: float | None) -> str:
    """``DAF 95.4``; below 1 with the damping that explains it (ζ > 0.5 at resonance)."""
    if not np.isfinite(daf):
        return "DAF ∞"
    if daf < 1 and damping is not None:
        return f"DAF {daf:.2g} (ζ {damping:.0%})"
    return f"DAF {daf:.3g}"


def campbell_headline(report: Report, subsystems: Sequence[str]) -> Headline:
    """The judgement a Campbell diagram of ``subsystems`` draws (:mod:`.headline`): the
    resonance checks of its modes — and of the coupled modes its isolated ones are judged
    as — and the tower's class where its classified mode is drawn."""
    covered = [m for m in report.modes if m.subsystem in subsystems]
    ids = {m.id for m in covered} | {m.superseded_by for m in covered if m.superseded_by}
    found = report.result(tower_model.NAME, tower_model.TowerResults)
    return headline.of_modes(report, ids, found.classification.mode_id if found else None)


def _title(report: Report, subsystems: Sequence[str], covered) -> tuple[str, str, Headline]:  # type: ignore[no-untyped-def]
    """What the diagram shows and its own judgement (:func:`campbell_headline`): in lines
    that fit the figure, on one line (its PNG's Title), and the judgement."""
    spec = report.spec
    held = [SUBSYSTEM_TITLE[s] for s in subsystems if any(m.subsystem == s for m in covered)]
    what = " and ".join(held or [SUBSYSTEM_TITLE[s] for s in subsystems])
    if spec.results is not None and "system" in subsystems:
        what = spec.results.tool
    if spec.rotor.orientation == "vertical-axis" and "tower" in subsystems:
        what = "Darrieus rotor"
    judged = campbell_headline(report, subsystems)
    first = f"{spec.turbine.name} — Campbell diagram, {what}"
    width = FIGURE_IN[0] - 0.4
    if text_width(first, TITLE_PT, bold=True) > width:  # the name on a line of its own
        first = f"{spec.turbine.name}\nCampbell diagram, {what}"
    plain = f"{spec.turbine.name} — Campbell diagram, {what}: {judged.words}"
    return fit(f"{first}\n{judged.words}", width, TITLE_PT), plain, judged


def _palette(n: int) -> list[str]:
    base = [
        "#1f77b4",
        "#d62728",
        "#9467bd",
        "#8c564b",
        "#e377c2",
        "#17becf",
        "#bcbd22",
        "#ff7f0e",
        "#7f7f7f",
        "#2ca02c",
    ]
    return [base[i % len(base)] for i in range(n)]


#: The room [in] between a line's end and its label (2 pt offset, and some), and the
#: label's size [pt], bold.
LABEL_OFFSET_IN, LABEL_PT = 0.06, 9


def _label_line(ax, text: str, rpm, f_line, f_top: float, colour: str) -> float:  # type: ignore[no-untyped-def]
    """Name an excitation line where it leaves the axes (the right edge or the top); the
    right margin [in] its label needs (0 where it is placed well inside)."""
    inside = np.nonzero(f_line <= f_top * 0.97)[0]
    if inside.size == 0:
        return 0.0
    i = inside[-1]
    ax.annotate(
        text,
        (rpm[i], f_line[i]),
        xytext=(2, 2),
        textcoords="offset points",
        fontsize=LABEL_PT,
        color=colour,
        fontweight="bold",
    )
    near_edge = i >= 0.8 * (len(rpm) - 1)  # a label further in has the axes' width
    return LABEL_OFFSET_IN + text_width(text, LABEL_PT, bold=True) if near_edge else 0.0


def _legend(  # type: ignore[no-untyped-def]
    ax, rule_label: str, shown: set[str], title_lines: int, right: float
) -> None:
    """The modes' labels and a key to each kind of thing drawn — only those ``shown``."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    handles, labels = ax.get_legend_handles_labels()
    key = [
        ("steady", Patch(color="#c8e6c9"), "steady operation"),
        ("quick-pass", Patch(facecolor="none", hatch="//", edgecolor="#81c784"), "quick-pass band"),
        (
            "overspeed",
            Patch(facecolor="#fff3e0", hatch="xx", edgecolor="#ffcc80"),
            "overspeed (transient)",
        ),
        ("margin", Patch(color="#9e9e9e", alpha=0.3), f"margin band: {rule_label}"),
        (
            "spread",
            Patch(facecolor="none", hatch="...", edgecolor="#5c6bc0"),
            "5–95 % frequency band (tolerances sampled)",
        ),
        ("dominant", Line2D([], [], color="#212121", lw=1.8), "dominant excitation (1P, N_b·P)"),
        (
            "secondary",
            Line2D([], [], color="#424242", lw=1.2, ls="--"),
            "secondary (kP, 1<k<N_b)",
        ),
        ("minor", Line2D([], [], color="#9e9e9e", lw=0.8, ls=":"), "minor harmonic"),
        (
            "least margin",
            Line2D([], [], marker="D", ls="", color="#9e9e9e", mec="black"),
            "resonance in operation, at its least margin",
        ),
        (
            "band violated",
            Line2D([], [], marker="s", ls="", color="#9e9e9e", mec="black"),
            "margin violated, line and mode never meet",
        ),
        (
            "held",
            Line2D([], [], color="#616161", lw=0.9, ls=":", marker="o", mec="white"),
            "another tool's points (dotted: its values held beyond them)",
        ),
        (
            "held mark",
            Line2D([], [], marker="o", ls="", mfc="white", mec="#616161", mew=1.6),
            "judged on a held value: no point computed there",
        ),
        *(
            (
                f"crossing: {status}",
                Line2D(
                    [],
                    [],
                    marker="X" if status in ("fail", "warn") else "o",
                    ls="",
                    color=STATUS_COLOUR[status],
                ),
                f"crossing: {status}",
            )
            for status in ("fail", "warn", "info", "pass")
        ),
    ]
    for kind, h, label in key:
        if kind == "steady" or kind in shown:
            handles.append(h)
            labels.append(label)
    ncol = _columns(labels, FIGURE_IN[0] - 0.3)
    top = 0.25 + TITLE_LINE_IN * title_lines
    legend_below(
        ax.figure, ax, handles, labels, columns=ncol, fontsize=SMALL_PT, top=top, right=right
    )


def _columns(labels: Sequence[str], width: float, most: int = 3) -> int:
    """The most legend columns (up to ``most``) whose entries fit ``width`` [in] side by
    side: matplotlib fills the columns top to bottom, each as wide as its widest entry
    (its text and the 0.55 in of its handle and padding)."""
    for n in range(most, 1, -1):
        rows = -(-len(labels) // n)
        columns = [labels[i : i + rows] for i in range(0, len(labels), rows)]
        if sum(max(text_width(t, SMALL_PT) for t in c) + 0.55 for c in columns) <= width:
            return n
    return 1


def windows_plot(report: Report, tower_windows: "Sequence[Band]") -> "Figure":
    """The tower-and-blade Campbell diagram with the tower's allowed windows shaded."""
    fig = campbell_plot(report, ("tower", "blade"))
    ax = fig.axes[0]
    top = ax.get_ylim()[1]
    for w in tower_windows:
        low, high = w.low, min(w.high, top)
        if low >= top:
            continue
        ax.axhspan(low, high, color="#43a047", alpha=0.10, lw=0)
        # at the window's top edge, clear of the mode lines that sit inside it
        ax.annotate(
            f"{w.name} window",
            (0.01, high),
            xycoords=("axes fraction", "data"),
            xytext=(0, -3),
            textcoords="offset points",
            fontsize=9,
            color="#2e7d32",
            fontweight="bold",
            va="top",
        )
    heading = ax.get_title().replace("Campbell diagram,", "allowed tower windows,", 1)
    ax.set_title(heading, color=ax.title.get_color(), fontweight="bold", y=1.0)
    stamped = headline.stamp_of(fig)
    if stamped is not None:
        title = stamped[0].replace("Campbell diagram,", "allowed tower windows,", 1)
        headline.stamp(fig, title, stamped[1])
    return fig


def _damping_axes(ax: "Axes", rated_wind: float | None) -> None:
    """A damping chart's scale and marks: ζ on a symmetric log scale, the rated wind, the
    unstable region below zero and the 1 % line."""
    ax.set_yscale("symlog", linthresh=0.1)
    plain_decades(ax.yaxis)
    if rated_wind is not None:
        ax.axvline(rated_wind, color="#616161", lw=0.8, ls="--")
        ax.annotate(
            f"rated {rated_wind:.3g} m/s",
            (rated_wind, 0.99),
            xycoords=("data", "axes fraction"),
            xytext=(3, -3),
            textcoords="offset points",
            va="top",
            fontsize=8,
            color="#616161",
        )
    ax.axhspan(-100, 0, color="#ffcdd2", alpha=0.6, lw=0)
    ax.axhline(0, color="#c62828", lw=1.0)
    ax.axhline(1, color="#ef6c00", lw=0.8, ls=":")
    ax.annotate(
        "1 %",
        (0.995, 1),
        xycoords=("axes fraction", "data"),
        ha="right",
        va="bottom",
        fontsize=8,
        color="#ef6c00",
    )


def damping_plot(report: Report) -> "Figure | None":
    """The damping of every judged mode in operation (aerodynamic + structural) over the
    wind, as the aeroelastic solution gave it; None without aerodynamics."""
    from matplotlib.figure import Figure

    modes = [m for m in report.modes if m.judged and m.operating is not None]
    if not modes:
        return None
    from matplotlib import colormaps

    fig = Figure(figsize=(MAX_FIGURE_IN, 4.9), dpi=FIGURE_DPI)
    ax = fig.add_subplot()
    cmap = colormaps["tab10" if len(modes) <= 10 else "tab20"]  # distinct hues while they last
    colours = [cmap(i % cmap.N) for i in range(len(modes))]
    # another tool's damping is drawn over rotor speed, at its own points (its winds may be
    # unknown); wtvib's own over the wind of its operating points
    tool = report.spec.results.tool if report.spec.results is not None else None
    for mode, colour in zip(modes, colours, strict=True):
        op = mode.operating
        assert op is not None
        zeta = 100 * np.asarray(op.total)
        ls = "-" if zeta.min() < 5 else "--"  # lightly damped modes drawn solid
        x = np.asarray(op.omega) * 30 / np.pi if tool else np.asarray(op.wind)
        ax.plot(
            x,
            zeta,
            color=colour,
            lw=2.0 if ls == "-" else 1.2,
            ls=ls,
            label=mode.id,
            marker="o" if tool or len(x) == 1 else None,  # one point: a dot, not a line
            ms=4 if len(x) > 1 else 7,
        )
    aero = report.result(aerodamping.NAME, aerodamping.AerodynamicsResults)
    _damping_axes(ax, aero.schedule.rated_wind if aero is not None else None)
    low = min(100 * min(m.operating.total) for m in modes)  # type: ignore[union-attr]
    ax.set_ylim(min(-0.2, low * 1.3), 150)
    ax.set_xlabel("rotor speed [rpm]" if tool else "wind speed [m/s]")
    ax.set_ylabel("damping ratio ζ [% of critical]")
    ax.grid(True, which="both", alpha=0.3)
    how = f"total, as computed by {tool}" if tool else f"aerodynamic + structural; {_model(report)}"
    judged = headline.of_checks(
        report.checks,
        ("aerodynamics.stability", "system.stability"),
        {
            "pass": "PASS: no mode negatively damped",
            "warn": "WARN: {check}",
            "fail": "FAIL: {check} — negatively damped in operation",
        },
    )
    title = f"{report.spec.turbine.name} — damping in operation ({how}): {judged.words}"
    heading = fit(title, 7.1)
    ax.set_title(heading, fontweight="bold", y=1.0, color=STATUS_COLOUR[judged.status])
    headline.stamp(fig, title, judged)
    handles, labels = ax.get_legend_handles_labels()
    legend_below(
        fig, ax, handles, labels, columns=3, fontsize=SMALL_PT, top=0.2 + title_height(heading)
    )
    return fig


#: The most modes a standstill chart names, lowest first (a BeamDyn beam has 48).
STANDSTILL_MODES = 30


def _model(report: Report) -> str:
    """The aerodynamic model the damping in operation was computed with, as the report
    says it: the lift lagged or quasi-steady (``aerodynamics.shed_wake``), the induction
    frozen or in equilibrium with the motion (``aerodynamics.induction``)."""
    aero = report.spec.aerodynamics
    lagged = aero is not None and aero.shed_wake
    equilibrium = aero is not None and aero.induction == "equilibrium"
    induction = "induction in equilibrium" if equilibrium else "frozen induction"
    return f"{words.lift(lagged)}, {induction}"


def standstill_plot(report: Report) -> "Figure | None":
    """A standstill audit's modes (another tool's parked results): each mode's frequency
    and damping ratio, the negatively damped side shaded — what was computed, where it was
    computed (0 rpm), and no excitation line, which a parked rotor has none of."""
    from matplotlib.figure import Figure

    if not report.spec.rotor.speed.parked:
        return None
    modes = sorted((m for m in report.modes if m.judged), key=by_frequency)
    shown, rest = modes[:STANDSTILL_MODES], modes[STANDSTILL_MODES:]
    if not shown:
        return None
    rows = len(shown)
    fig = Figure(figsize=(MAX_FIGURE_IN, 1.9 + 0.22 * rows), dpi=FIGURE_DPI)
    ax = fig.add_subplot()
    zeta = np.array([100 * (m.damping_ratio or 0.0) for m in shown])
    y = np.arange(rows)[::-1]
    # negatively damped beyond rounding's sign (imported.NEGATIVE, as system.stability)
    colours = [
        STATUS_COLOUR["fail"] if z < -100 * NEGATIVE else STATUS_COLOUR["pass"] for z in zeta
    ]
    ax.scatter(zeta, y, c=colours, s=30, zorder=3, edgecolors="white")
    names = [f"{m.id}  {m.frequency_hz:.4g} Hz" for m in shown]
    ax.set_yticks(y, names)
    ax.tick_params(axis="y", labelsize=SMALL_PT)
    ax.set_xscale("symlog", linthresh=0.1)
    plain_decades(ax.xaxis)
    low, high = min(-0.5, float(zeta.min()) * 1.5), max(10.0, float(zeta.max()) * 1.5)
    ax.set_xlim(low, high)
    ax.axvspan(low, 0, color="#ffcdd2", alpha=0.6, lw=0)
    ax.axvline(0, color="#c62828", lw=1.0)
    ax.set_xlabel("damping ratio ζ [% of critical], as the tool computed it")
    ax.grid(True, which="both", alpha=0.3)
    tool = report.spec.results.tool if report.spec.results is not None else "the tool"
    judged = headline.of_checks(
        report.checks,
        ("system.stability",),
        {"pass": "PASS: no mode negatively damped", "fail": "FAIL: negatively damped modes"},
    )
    more = f" ({len(rest)} higher modes not drawn)" if rest else ""
    title = (
        f"{report.spec.turbine.name} — modes at standstill (0 rpm) as {tool} computed "
        f"them{more}: {judged.words}"
    )
    margin = 0.3 + max(text_width(t, SMALL_PT) for t in names)
    heading = fit(title, MAX_FIGURE_IN - margin + 0.2, 10)
    fixed_layout(fig, left=margin, top=0.2 + title_height(heading, 10), bottom=0.55)
    ax.set_title(heading, fontweight="bold", fontsize=10, y=1.0, color=STATUS_COLOUR[judged.status])
    headline.stamp(fig, title, judged)
    return fig
