"""Blade stability figures: V-g / V-f of flutter, the stability-limits chart (Hau Fig.
7.6) and the stall-induced damping over wind speed (Hau ch. 7.2.3)."""

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from ...aero import aeroelastic, stall
from ...results import Check
from . import headline
from .layout import FIGURE_DPI, SMALL_PT, fit, fixed_layout, plain_decades, title_height

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure


def flutter_plot(
    result: aeroelastic.AeroelasticResults, checks: Sequence[Check], turbine: str
) -> "Figure":
    """V-g and V-f curves (p-k method) of the blade section nearest to flutter, headed by
    the status of ``checks``' ``blade.flutter``."""
    from matplotlib.figure import Figure

    worst, required = result.worst, result.required_speed_m_s
    fig = Figure(figsize=(7.2, 5.1), dpi=FIGURE_DPI)
    ax_g, ax_f = fig.subplots(2, 1, sharex=True)
    judged = headline.of_checks(checks, ("blade.flutter",), headline.STATUS_ONLY)
    title = (
        f"{turbine}\nblade flutter at r = {worst.radius_m:.3g} m, Theodorsen p-k ({judged.words})"
    )
    heading = fit(title, 6.0, 10)
    headline.stamp(fig, title.replace("\n", " — "), judged)
    fixed_layout(fig, left=1.0, top=0.2 + title_height(heading, 10), gap=0.15)
    colours = ("#1f77b4", "#d62728")
    names = ("bending branch", "torsion branch")
    for branch, colour, label in zip(worst.flutter.branches, colours, names, strict=False):
        f = np.asarray(branch.omega, dtype=float) / (2 * np.pi)
        # real (non-oscillatory) roots are outside the p-k method's validity: not drawn
        g = np.where(f > 0, -np.asarray(branch.damping), np.nan)
        ax_g.plot(branch.speed, g, color=colour, lw=2, label=label)
        ax_f.plot(branch.speed, np.where(f > 0, f, np.nan), color=colour, lw=2, label=label)
    for ax in (ax_g, ax_f):
        ax.axvline(worst.section_speed, color="#616161", ls="--", lw=1.2)
        ax.axvspan(
            worst.section_speed,
            required,
            color="#fff3e0",
            lw=0,
            label="required margin",
        )
        ax.grid(True, alpha=0.3)
    ax_g.axhline(0.0, color="#212121", lw=1)
    ax_g.text(
        0.99,
        0.02,
        "where the curves merge or end, the other root is overdamped (not oscillating)",
        transform=ax_g.transAxes,
        fontsize=SMALL_PT,
        ha="right",
        color="#616161",
    )
    ax_g.annotate(
        "highest section speed",
        (worst.section_speed, 0.98),
        xycoords=("data", "axes fraction"),
        fontsize=8,
        rotation=90,
        va="top",
        ha="right",
        color="#616161",
    )
    ax_g.set_ylabel("aeroelastic growth rate −ζ\n(> 0: unstable)")
    ax_f.set_ylabel("frequency [Hz]")
    ax_f.set_xlabel("section air speed [m/s]")
    ax_g.legend(fontsize=8, loc="best")
    ax_g.set_title(heading, fontweight="bold", fontsize=10, y=1.0)
    return fig


def _limits(
    ax: "Axes",
    x: NDArray[np.float64],
    flutter_k: NDArray[np.float64],
    divergence_k: float,
    bottom: float,
) -> None:
    """The flutter region below its limit (k_θ [kN·m/rad per m] at each offset ``x`` [%
    chord]) and the divergence region below its limit."""
    ax.fill_between(
        x,
        bottom,
        np.where(np.isfinite(flutter_k), flutter_k, bottom),
        where=np.isfinite(flutter_k).tolist(),
        color="#e53935",
        alpha=0.18,
        lw=0,
        label="flutter",
    )
    ax.plot(x, flutter_k, color="#c62828", lw=2, label="flutter limit")
    if divergence_k > 0:
        ax.axhspan(
            bottom,
            divergence_k,
            color="#fb8c00",
            alpha=0.15,
            lw=0,
            label="divergence",
        )
        ax.axhline(
            divergence_k,
            color="#ef6c00",
            lw=2,
            ls="--",
            label="divergence limit",
        )


def stability_chart_plot(
    result: aeroelastic.AeroelasticResults,
    checks: Sequence[Check],
    turbine: str,
    speed_margin: float,
    ax: "Axes | None" = None,
) -> "Figure":
    """Hau Fig. 7.6 for the blade section nearest to flutter: torsional stiffness against the
    centre-of-mass offset, divergence and flutter limits at the required speed (the highest
    section speed with ``speed_margin``), the blade — on ``ax`` where given, else on a
    figure of its own headed by ``checks``' divergence and flutter status."""
    from matplotlib.figure import Figure

    flutter = next((c for c in checks if c.id == "blade.flutter"), None)
    chart, speed, worst = result.chart, result.required_speed_m_s, result.worst
    x = 100 * chart.offset_chord
    kilo = 1e-3
    judged = headline.of_checks(checks, ("blade.divergence", "blade.flutter"), {})
    title = (
        f"{turbine}\nblade stability limits at {speed:.3g} m/s "
        f"({1 + speed_margin:g}× the highest section speed; Hau Fig. 7.6): {judged.words}"
    )
    heading = fit(title, 6.2, 10)
    if ax is None:
        fig = Figure(figsize=(7.2, 4.5), dpi=FIGURE_DPI)
        ax = fig.add_subplot()
        headline.stamp(fig, title.replace("\n", " — "), judged)
        fixed_layout(fig, left=0.85, top=0.2 + title_height(heading, 10))  # log tick labels
    flutter_k = chart.flutter_k_theta * kilo
    top = 3 * max(
        np.nanmax(flutter_k, initial=0.0),
        chart.divergence_k_theta * kilo,
        chart.blade_k_theta * kilo,
    )
    bottom = 0.1 * min(chart.blade_k_theta * kilo, chart.divergence_k_theta * kilo or top)
    _limits(ax, x, flutter_k, chart.divergence_k_theta * kilo, bottom)
    ax.plot(
        100 * chart.blade_offset_chord,
        chart.blade_k_theta * kilo,
        "o",
        ms=10,
        color="#1565c0",
        label=f"blade section at r = {worst.radius_m:.3g} m",
    )
    ratio = flutter.numbers.get("speed_ratio") if flutter is not None else None
    ax.annotate(
        f"flutter at {ratio:.2f}× the highest section speed" if ratio else "no flutter found",
        (100 * chart.blade_offset_chord, chart.blade_k_theta * kilo),
        xytext=(10, 10),
        textcoords="offset points",
        fontsize=8,
        color="#1565c0",
    )
    ax.axvline(0.0, color="#616161", lw=0.8)
    ax.set_yscale("log")
    plain_decades(ax.yaxis)
    ax.set_ylim(bottom, top)
    ax.set_xlabel("centre of mass behind the elastic axis [% chord]")
    ax.set_ylabel("torsional stiffness k_θ [kN·m/rad per m]")
    ax.set_title(heading, fontweight="bold", fontsize=10, y=1.0)
    ax.grid(True, which="both", alpha=0.25)
    ax.legend(fontsize=8, loc="lower right")
    return ax.get_figure()  # type: ignore[return-value]  # a Figure's axes, not a SubFigure's


def stall_damping_plot(
    result: stall.StallResults, checks: Sequence[Check], turbine: str
) -> "Figure | None":
    """Total and aerodynamic damping of the first flap and edge modes over the wind speed,
    each panel headed by its ``blade.stall.*`` check among ``checks`` (None: no curve)."""
    from matplotlib.figure import Figure

    found = result.curves
    by_id = {c.id: c for c in checks}
    curves = {name: by_id[f"blade.stall.{name}"] for name in found}
    if not curves:
        return None
    fig = Figure(figsize=(7.2, 4.2), dpi=FIGURE_DPI)
    axes = fig.subplots(len(curves), 1, sharex=True, squeeze=False)[:, 0]
    judged = headline.of_checks(checks, tuple(c.id for c in curves.values()), {})
    title = f"{turbine}\nstall-induced vibration: {result.damping} (Hau ch. 7.2.3): {judged.words}"
    heading = fit(title, 7.0, 10)
    headline.stamp(fig, title.replace("\n", " — "), judged)
    fixed_layout(fig, top=0.47 + title_height(heading, 10), gap=0.3)  # each panel's title
    colours = {"pass": "#2e7d32", "warn": "#ef6c00", "fail": "#c62828", "info": "#1565c0"}
    for ax, (name, check) in zip(axes, curves.items(), strict=True):
        pts = found[name]
        wind = np.array([p.wind for p in pts])
        total = 100 * np.array([p.total for p in pts])
        aero = 100 * np.array([p.aero for p in pts])
        ax.axhline(0.0, color="#212121", lw=1)
        ax.fill_between(
            wind,
            total,
            0,
            where=total < 0,
            color="#e53935",
            alpha=0.25,
            lw=0,
            label="negative total damping",
        )
        dot = "o" if len(wind) == 1 else None  # one operating point: a dot, not a line
        ax.plot(wind, total, color=colours[check.status], lw=2, marker=dot,
                label="total (aero + structural)")  # fmt: skip
        ax.plot(wind, aero, color="#616161", lw=1.2, ls="--", marker=dot, label="aerodynamic")
        ax.set_ylabel(f"{name}: ζ [%]")
        low = int(np.argmin(total))  # the title in the axis' unit (%), as the curves
        ax.set_title(
            f"{name}: {check.status.upper()} — lowest total ζ {total[low]:.2f} % at "
            f"{wind[low]:.3g} m/s (aerodynamic {aero[low]:+.2f} %)",
            fontsize=8,
            loc="left",
            y=1.0,
        )
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=SMALL_PT, loc="best")
    axes[-1].set_xlabel("wind speed [m/s]")
    fig.suptitle(heading, fontweight="bold", fontsize=10)
    return fig


#: Colours of the coordinate groups in the coupled-mode energy chart.
