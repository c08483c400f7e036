"""Campbell (resonance) diagrams: natural frequencies and excitation lines vs rotor speed.

Calculate first, draw second: everything drawn comes from the audit
:class:`~wtvib.audit.Report` (its modes, findings and operating range). matplotlib is
imported lazily, with the Agg backend, so ``wtvib --help`` stays fast.
"""

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from ..audit import Report
from ..excitation import operating_range
from ..results import Sampled
from ..rules import STATUS_ORDER
from ..units import rad_s_to_rpm, rpm_to_rad_s
from .layout import TITLE_LINE_IN, legend_below, plain_decades, text_width

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..design import Band

STATUS_COLOUR = {"pass": "#2e7d32", "info": "#1565c0", "warn": "#ef6c00", "fail": "#c62828"}
SUBSYSTEM_TITLE = {
    "tower": "tower",
    "blade": "blades",
    "drivetrain": "drive train",
    "yaw": "yaw system",
    "system": "coupled whole turbine",
}
#: Subsystems drawn together on one diagram.
DIAGRAMS: dict[str, tuple[str, ...]] = {
    "campbell": ("tower", "blade"),
    "campbell-drivetrain": ("drivetrain",),
    "campbell-yaw": ("yaw",),
    "campbell-system": ("system",),
}


def campbell_plot(report: Report, subsystems: Sequence[str] = ("tower", "blade")) -> "Figure":
    """Draw the Campbell diagram of some subsystems of an audited turbine.

    Shows the mode curves with their margin bands, the excitation lines (dominant thick,
    secondary medium, minor thin), the steady operating range shaded, overspeed hatched,
    quick-pass bands, and each crossing marked in the colour of its status.
    """
    from matplotlib.figure import Figure

    spec = report.spec
    rule = report.rule
    op = operating_range(spec.rotor.speed)
    modes = [m for m in report.modes if m.subsystem in subsystems]
    findings = [f for f in report.findings if f.mode.subsystem in subsystems]
    rpm_top = float(rad_s_to_rpm(op.overspeed)) * 1.08
    rpm = np.linspace(0.0, rpm_top, 400)
    omega = rpm_to_rad_s(rpm)

    top_mode = max((float(m.frequency_at(omega).max()) for m in modes), default=1.0)
    blade_pass = spec.rotor.blades * rpm_top / 60.0
    top_line = max((f.excitation.order for f in findings), default=1.0) * rpm_top / 60.0
    # Modes above every excitation line cannot resonate: the axis stops there.
    f_top = max(min(top_mode * 1.18, top_line * 1.05), blade_pass * 1.1)
    covered, hidden = modes, [m for m in modes if m.frequency_hz > f_top]
    modes = [m for m in modes if m.frequency_hz <= f_top]

    fig = Figure(figsize=(10, 7), dpi=150)
    ax = fig.add_subplot()
    for a, b in spec.rotor.speed.steady_rpm:
        if b > a:
            ax.axvspan(a, b, color="#c8e6c9", alpha=0.55, lw=0)
        else:
            ax.axvline(a, color="#66bb6a", lw=6, alpha=0.45)
    for a, b in spec.rotor.speed.quick_pass_rpm:
        ax.axvspan(a, b, facecolor="none", hatch="//", edgecolor="#81c784", lw=0)
    shown: set[str] = set()  # what is drawn, for the legend to name (and nothing else)
    if spec.rotor.speed.overspeed > spec.rotor.speed.top_rpm:
        ax.axvspan(
            spec.rotor.speed.top_rpm,
            spec.rotor.speed.overspeed,
            facecolor="#fff3e0",
            hatch="xx",
            edgecolor="#ffcc80",
            lw=0,
        )
        shown.add("overspeed")
    if spec.rotor.speed.quick_pass_rpm:
        shown.add("quick-pass")

    excitations = {f.excitation.id: f.excitation for f in findings}
    right = 0.3  # the right margin [in]: room for the line labels at the right edge
    for exc in excitations.values():
        style = {
            "dominant": dict(color="#212121", lw=1.8, ls="-"),
            "secondary": dict(color="#424242", lw=1.2, ls="--"),
            "minor": dict(color="#9e9e9e", lw=0.8, ls=":"),
        }[exc.energy]
        f_line = exc.frequency_hz(omega)
        ax.plot(rpm, f_line, **style)  # type: ignore[arg-type]
        shown.add(exc.energy)
        right = max(right, _label_line(ax, exc.id, rpm, f_line, f_top, style["color"]))  # type: ignore[arg-type]

    colours = _palette(len(modes))
    drawn: list[np.ndarray] = []
    for mode, colour in zip(modes, colours, strict=True):
        f_n = mode.frequency_at(omega)
        label = f"{mode.id}  {mode.frequency_hz:.3g} Hz"
        if spec.rotor.orientation == "vertical-axis":  # Darrieus modes need their names
            label += f" — {mode.description}"
        if not mode.judged:  # shown as what it is: no margin band, no crossings
            label += (
                f" (isolated; judged as {mode.superseded_by})"
                if mode.superseded_by
                else " (reported only: exists in no operating regime)"
            )
            ax.plot(rpm, f_n, color=colour, lw=1.0, ls="--", alpha=0.7, label=label)
            continue
        lo, hi = rule.forbidden_band(1.0)
        ax.fill_between(rpm, f_n * lo, f_n * hi, color=colour, alpha=0.16, lw=0)
        shown.add("margin")
        # a mode on top of one drawn before (fa1 and ss1 of a round tower) is dashed, so
        # that both stay visible
        under = any(np.allclose(f_n, g, rtol=5e-3) for g in drawn)
        ax.plot(rpm, f_n, color=colour, lw=2.2, label=label, ls=(0, (4, 3)) if under else "-")
        drawn.append(f_n)
        if mode.origin == "imported" and isinstance(mode.curve, Sampled):
            # another tool's operating points: the line between and beyond them is drawn
            # as it is judged (linear between, held beyond); the points are the data
            pts = np.asarray(mode.curve.omega)
            ax.plot(pts * 30 / np.pi, mode.curve.hz, "o", color=colour, ms=4, mec="white")

    spread = (report.uncertainty or {}).get("modes", {})
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
    labels: list[tuple[float, float, float, str]] = []  # rpm, Hz, DAF, colour
    marks: dict[str, list[tuple[float, float]]] = {}  # the crossings by status: rpm, Hz
    for f in findings:
        for c, daf in zip(f.crossings, f.crossing_daf or [None] * len(f.crossings), strict=True):
            f_c = float(f.excitation.frequency_hz(np.array([c]))[0])
            if f_c > f_top:
                continue
            status = f.status_at(c, op)
            marks.setdefault(status, []).append((float(rad_s_to_rpm(c)), f_c))
            if status != "pass" and daf is not None:  # the crossing's amplification
                labels.append((float(rad_s_to_rpm(c)), f_c, daf, STATUS_COLOUR[status]))
    # a crossing under a worse one at the same place (two modes of one frequency, e.g. the
    # drive train with the generator on the grid and free) cannot be seen: not drawn, so
    # that the legend names only markers a reader can find
    worse: list[tuple[float, float]] = []
    for kind in sorted(marks, key=STATUS_ORDER.__getitem__, reverse=True):
        seen = [
            (x, y)
            for x, y in marks[kind]
            if not any(
                abs(x - wx) < 0.005 * rpm_top and abs(y - wy) < 0.005 * f_top for wx, wy in worse
            )
        ]
        worse += marks[kind]
        marks[kind] = seen
    marks = {kind: points for kind, points in marks.items() if points}
    # one marker line per status (a line per crossing cost a millisecond each), the worse
    # drawn over the milder where crossings coincide
    for kind in sorted(marks, key=STATUS_ORDER.__getitem__):
        big = STATUS_ORDER[kind] >= STATUS_ORDER["warn"]
        at_rpm, at_hz = zip(*marks[kind], strict=True)
        ax.plot(
            at_rpm,
            at_hz,
            ls="",
            marker="X" if big else "o",
            ms=11 if big else 6,
            color=STATUS_COLOUR[kind],
            mec="white",
            mew=0.8,
            zorder=5,
        )
        shown.add(f"crossing: {kind}")
    # each crossing's DAF, the largest first; one label where several crossings coincide
    placed: list[tuple[float, float]] = []
    for x, y, daf, colour in sorted(labels, key=lambda t: -t[2]):
        if any(abs(x - px) < 0.04 * rpm_top and abs(y - py) < 0.04 * f_top for px, py in placed):
            continue
        placed.append((x, y))
        ax.annotate(
            f"DAF {daf:.3g}" if np.isfinite(daf) else "DAF ∞",
            (x, y),
            xytext=(5, -10),
            textcoords="offset points",
            fontsize=7,
            color=colour,
            zorder=6,
        )

    # a band violated with no crossing in it (the line runs inside the margin, never meets
    # the mode: the Darrieus flap at 2P in overspeed) gets a square mid-band in the colour
    # of its status — else a warning or failure would have nothing drawn
    for f in findings:
        for a, b in (band for bands in f.violations.values() for band in bands):
            mid = 0.5 * (a + b)
            status = f.status_at(mid, op)
            if STATUS_ORDER[status] < STATUS_ORDER["warn"] or any(a <= c <= b for c in f.crossings):
                continue
            f_mid = float(f.mode.frequency_at(np.array([mid]))[0])
            if f_mid > f_top:  # a mode above the axis (noted, not drawn)
                continue
            ax.plot(
                float(rad_s_to_rpm(mid)),
                f_mid,
                marker="s",
                ms=8,
                ls="",
                color=STATUS_COLOUR[status],
                mec="black",
                mew=0.8,
                zorder=6,
            )
            shown.add("band violated")
    for f in findings:
        if f.regime in ("steady", "quick-pass") and STATUS_ORDER[f.status] >= STATUS_ORDER["warn"]:
            ax.plot(
                float(rad_s_to_rpm(f.speed)),
                f.excitation_hz,
                marker="D",
                ms=9,
                color=STATUS_COLOUR[f.status],
                mec="black",
                mew=0.8,
                zorder=6,
            )
            shown.add("least margin")

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
    verdict = report.verdict.upper()
    cls = f", {report.tower_class} tower" if report.tower_class and "tower" in subsystems else ""
    # the parts whose modes the diagram holds, drawn or noted above the lines (MOD-2's has
    # no blade model: "tower")
    held = [SUBSYSTEM_TITLE[s] for s in subsystems if any(m.subsystem == s for m in covered)]
    title = " and ".join(held or [SUBSYSTEM_TITLE[s] for s in subsystems])
    if spec.results is not None and "system" in subsystems:
        title = f"whole turbine as {spec.results.tool} computed it"
    if spec.rotor.orientation == "vertical-axis" and "tower" in subsystems:
        title = "Darrieus rotor"
    heading = f"{spec.turbine.name} — Campbell diagram, {title} — verdict {verdict}{cls}"
    if len(heading) > 90:  # a long turbine name on a line of its own, not cut off
        heading = f"{spec.turbine.name}\nCampbell diagram, {title} — verdict {verdict}{cls}"
    ax.set_title(heading, color=STATUS_COLOUR[report.verdict], fontweight="bold", y=1.0)
    if hidden:
        low_hz, high_hz = (f"{g(m.frequency_hz for m in hidden):.3g}" for g in (min, max))
        ax.text(
            0.99,
            0.99,
            f"{len(hidden)} mode{'s' if len(hidden) > 1 else ''} above every excitation line "
            f"not drawn ({low_hz if low_hz == high_hz else f'{low_hz}–{high_hz}'} Hz)",
            transform=ax.transAxes,
            ha="right",
            va="top",
            fontsize=8,
            color="#616161",
        )
    _legend(ax, rule.label, shown, title_lines=heading.count("\n") + 1, right=right)
    return fig


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
            "least margin in operation",
        ),
        (
            "band violated",
            Line2D([], [], marker="s", ls="", color="#9e9e9e", mec="black"),
            "margin violated, no crossing (warn/fail)",
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
    ncol = 2 if max(len(t) for t in labels) > 40 else 4
    top = 0.25 + TITLE_LINE_IN * title_lines
    legend_below(ax.figure, ax, handles, labels, columns=ncol, fontsize=8, top=top, right=right)


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
            (0.01, high),  # type: ignore[attr-defined]
            xycoords=("axes fraction", "data"),
            xytext=(0, -3),
            textcoords="offset points",
            fontsize=9,
            color="#2e7d32",
            fontweight="bold",
            va="top",
        )
    ax.set_title(ax.get_title() + " — allowed tower windows", fontsize=10, y=1.0)
    return fig


def damping_plot(report: Report) -> "Figure | None":
    """The damping of every judged mode in operation (aerodynamic + structural) over the
    wind, as the aeroelastic solution gave it; None without aerodynamics."""
    from matplotlib.figure import Figure

    modes = [m for m in report.modes if m.judged and m.operating is not None]
    if not modes:
        return None
    from matplotlib import colormaps

    fig = Figure(figsize=(10, 6.5), dpi=150)
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
            marker="o" if tool else None,
            ms=4,
        )
    ax.set_yscale("symlog", linthresh=0.1)
    plain_decades(ax.yaxis)
    schedule = report.results.get("aerodynamics", {}).get("schedule")
    if schedule is not None and schedule.rated_wind is not None:
        ax.axvline(schedule.rated_wind, color="#616161", lw=0.8, ls="--")
        ax.annotate(
            f"rated {schedule.rated_wind:.3g} m/s",
            (schedule.rated_wind, 0.99),
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
    low = min(100 * min(m.operating.total) for m in modes)  # type: ignore[union-attr]
    ax.set_ylim(min(-0.2, low * 1.3), 150)
    ax.set_xlabel("rotor speed [rpm]" if tool else "wind speed [m/s]")
    ax.set_ylabel(
        f"damping ratio ζ [% of critical], as {tool} gives it"
        if tool
        else "damping ratio ζ [% of critical], aerodynamic + structural"
    )
    ax.grid(True, which="both", alpha=0.3)
    how = f"as computed by {tool}" if tool else "quasi-steady, frozen wake"
    ax.set_title(
        f"{report.spec.turbine.name} — damping in operation ({how})", fontweight="bold", y=1.0
    )
    handles, labels = ax.get_legend_handles_labels()
    legend_below(fig, ax, handles, labels, columns=3, fontsize=8, top=0.25 + TITLE_LINE_IN)
    return fig
