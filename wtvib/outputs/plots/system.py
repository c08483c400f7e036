"""The coupled whole turbine: where each parked coupled mode's kinetic energy sits."""

from typing import TYPE_CHECKING

import numpy as np

from ...results import Check
from . import headline
from .layout import FIGURE_DPI, MAX_FIGURE_IN, SMALL_PT, fit, legend_below, text_width, title_height

if TYPE_CHECKING:
    from matplotlib.figure import Figure


#: Colours of the coordinate groups (blade groups take the rest in turn).
_GROUP_COLOUR = {
    "tower.fa": "#1f77b4",
    "tower.ss": "#17becf",
    "tower.tor": "#7f7f7f",
    "yaw": "#bcbd22",
    "drivetrain": "#8c564b",
}
_BLADE_COLOURS = ["#d62728", "#ff9896", "#2ca02c", "#98df8a", "#9467bd", "#c5b0d5"]


def coupled_energy_plot(check: Check, turbine: str) -> "Figure":
    """Where each parked coupled mode's kinetic energy sits (the numbers of the check
    ``system.coupling``): one bar per mode, split by tower, yaw, drive train and blade
    groups — a mode of one colour is a subsystem mode, a mixed bar is a coupling mode (Hau
    §7.6)."""
    from matplotlib.figure import Figure

    rows = check.numbers["modes"]
    groups = list(dict.fromkeys(g for r in rows for g in r["energy"]))
    blade_groups = [g for g in groups if g.startswith("blade.")]
    colour = {**_GROUP_COLOUR, **dict(zip(blade_groups, _BLADE_COLOURS * 3, strict=False))}
    fig = Figure(figsize=(MAX_FIGURE_IN, 0.3 * len(rows) + 1.5), dpi=FIGURE_DPI)
    ax = fig.subplots()
    y = np.arange(len(rows))[::-1]
    for g in groups:
        left = [sum(r["energy"].get(h, 0.0) for h in groups[: groups.index(g)]) for r in rows]
        width = [r["energy"].get(g, 0.0) for r in rows]
        ax.barh(y, width, left=left, color=colour.get(g, "#cccccc"), label=g, height=0.7)
    names = [f"{r['id'].removeprefix('system.')}  {r['coupled_hz']:.3g} Hz" for r in rows]
    ax.set_yticks(y, names)
    ax.tick_params(axis="y", labelsize=SMALL_PT)
    ax.set_xlim(0, 1)
    ax.set_xlabel("share of the mode's kinetic energy")
    handles, labels = ax.get_legend_handles_labels()
    margin = 0.3 + max(text_width(t, SMALL_PT) for t in names)  # the tick labels' width
    title = f"{turbine} — coupled modes, {check.numbers['condition']}: where the energy is"
    heading = fit(title, MAX_FIGURE_IN - margin + 0.3, 10)
    headline.stamp(fig, title, headline.NOTHING)  # energy shares: no judgement drawn
    legend_below(
        fig,
        ax,
        handles,
        labels,
        columns=3,
        fontsize=SMALL_PT,
        top=0.2 + title_height(heading, 10),
        left=margin,
    )
    ax.set_title(heading, fontweight="bold", fontsize=10, y=1.0)
    return fig
