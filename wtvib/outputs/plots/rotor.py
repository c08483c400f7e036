"""The two-bladed rotor on the tower head: its Floquet stability map (Hau ch. 7.6)."""

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from ...results import Check
from ...spec import RotorSpeed
from ...subsystems import rotor
from . import headline
from .layout import FIGURE_DPI, fit, fixed_layout, title_height

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure


def floquet_plot(
    result: rotor.RotorResults,
    checks: Sequence[Check],
    turbine: str,
    speed: RotorSpeed,
    ax: "Axes | None" = None,
) -> "Figure":
    """The two-bladed rotor's stability map: largest Floquet multiplier over rotor speed,
    over the operating ranges of ``speed`` — on ``ax`` where given, else on a figure of
    its own headed by ``rotor.floquet``'s status among ``checks``."""
    from matplotlib.figure import Figure

    check = next((c for c in checks if c.id == "rotor.floquet"), None)
    smap = result.map
    rpm, rho = smap.speeds_rpm, smap.largest
    judged = headline.of_checks(checks, ("rotor.floquet",), headline.STATUS_ONLY)
    hub = f"{check.numbers['hub']} " if check is not None else ""  # rigid, teetered
    title = f"{turbine} — {hub}two-bladed rotor on the tower head: stability map ({judged.words})"
    heading = fit(title, 6.8, 10)
    if ax is None:
        fig = Figure(figsize=(7.2, 3.85), dpi=FIGURE_DPI)
        ax = fig.add_subplot()
        headline.stamp(fig, title, judged)
        fixed_layout(fig, top=0.2 + title_height(heading, 10))
    for a, b in speed.steady_rpm:
        if b > a:
            ax.axvspan(a, b, color="#c8e6c9", alpha=0.6, lw=0, label="steady operation")
        else:
            ax.axvline(a, color="#66bb6a", lw=6, alpha=0.5, label="operating speed")
    if speed.overspeed > speed.top_rpm:
        ax.axvspan(speed.top_rpm, speed.overspeed, color="#fff3e0", lw=0, label="overspeed")
    for a, b in smap.unstable_rpm:
        ax.axvspan(a, b, color="#e53935", alpha=0.2, lw=0, label="unstable: |ρ| > 1")
    ax.plot(rpm, rho, color="#1f77b4", lw=2, label="largest |ρ| (Floquet multiplier)")
    # a span of at least ±5 % about |ρ| = 1: rounding (1e-12) is not drawn as structure
    finite = rho[np.isfinite(rho)]
    low = min(0.95, float(finite.min(initial=1.0)) - 0.01)
    high = max(1.05, float(finite.max(initial=1.0)) + 0.01)
    ax.set_ylim(low, high)
    ax.ticklabel_format(axis="y", useOffset=False)
    ax.axhline(1.0, color="#212121", lw=1, ls="--", label="stability limit |ρ| = 1")
    ax.set_xlabel("rotor speed [rpm]")
    ax.set_ylabel("largest Floquet multiplier |ρ|")
    ax.set_title(heading, fontweight="bold", fontsize=10, y=1.0)
    ax.grid(True, alpha=0.3)
    handles, labels = ax.get_legend_handles_labels()
    unique = dict(zip(labels, handles, strict=True))
    ax.legend(unique.values(), unique.keys(), fontsize=8, loc="best")
    return ax.get_figure()  # type: ignore[return-value]  # a Figure's axes
