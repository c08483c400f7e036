"""Drive-train figures: the distribution of inertia and stiffness along the train (Hau
Fig. 7.10) above the mode shapes per generator condition (which masses swing against
which, Hau Fig. 7.12), and the grid mode over power (Hau Fig. 7.14)."""

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from ...results import Check, Mode
from ...subsystems import drivetrain as drivetrain_model
from . import headline
from .layout import FIGURE_DPI, MAX_FIGURE_IN, SMALL_PT, fit, fixed_layout, title_height

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ...subsystems.drivetrain import Chain


def drivetrain_shapes_plot(
    result: drivetrain_model.DrivetrainResults | None,
    modes: Sequence[Mode],
    turbine: str,
    reference_shaft: str,
) -> "Figure | None":
    """One panel per condition: each computed drive-train mode's twist amplitude per mass
    (the ``modes`` with a shape), under the train's inertia and stiffness (``result``'s
    chain, where the model gave one); None: no mode with a shape."""
    from matplotlib.figure import Figure

    modes = [m for m in modes if m.subsystem == "drivetrain" and m.shape is not None]
    if not modes:
        return None
    conditions = list(dict.fromkeys(m.id.split(".")[1] for m in modes))
    chain = result.chain if result is not None else None
    panels = len(conditions) + (chain is not None)
    fig = Figure(figsize=(MAX_FIGURE_IN, 1.95 * panels + 0.6), dpi=FIGURE_DPI)
    axes = fig.subplots(panels, 1, squeeze=False)[:, 0]
    title = f"{turbine} — drive-train mode shapes (reduced to the {reference_shaft} shaft)"
    heading = fit(title, 7.3)
    headline.stamp(fig, title, headline.NOTHING)  # shapes: no judgement drawn
    # the suptitle and each panel's title above it; the mass names under each panel
    # the stiffness axis on the right of the distribution panel needs its own margin
    right = 0.85 if chain is not None else 0.3
    fixed_layout(fig, top=0.4 + title_height(heading), bottom=0.4, gap=0.6, right=right)
    if chain is not None:
        _distribution(axes[0], chain, reference_shaft)
        axes = axes[1:]
    for ax, condition in zip(axes, conditions, strict=True):
        for m in (m for m in modes if m.id.split(".")[1] == condition):
            assert m.shape is not None
            x = np.arange(len(m.shape.deflection))
            ax.plot(
                x,
                m.shape.deflection,
                marker="o",
                lw=2,
                label=f"{m.id.split('.', 1)[1]}: {m.frequency_hz:.3g} Hz — "
                f"{m.description.split(': ', 1)[-1].replace(' (computed)', '')}",
            )
            ax.set_xticks(x, m.shape.labels or [str(i) for i in x])
            ax.set_xlim(-0.5, x[-1] + 0.5)  # room for the end masses' names
        ax.axhline(0, color="#9e9e9e", lw=0.8)
        ax.set_ylabel("twist amplitude")
        ax.set_title(f"condition: {condition}", loc="left", fontsize=10, y=1.0)
        ax.legend(fontsize=SMALL_PT, loc="best")
        ax.grid(True, alpha=0.3)
    fig.suptitle(heading, fontweight="bold")
    return fig


def _distribution(ax: "Axes", chain: "Chain", shaft: str) -> None:
    """Inertias at the masses and stiffnesses between them, on log scales (Hau Fig. 7.10)."""
    x = np.arange(len(chain.names))
    ax.bar(x, chain.inertia, width=0.5, color="#1565c0", label="inertia [kg·m²]")
    ax.set_yscale("log")
    ax.set_ylabel("inertia [kg·m²]", color="#1565c0")
    ax.set_xticks(x, list(chain.names))
    ax.set_xlim(-0.5, x[-1] + 0.5)
    springs = ax.twinx()
    springs.bar(x[:-1] + 0.5, chain.stiffness, width=0.25, color="#ef6c00")
    springs.set_yscale("log")
    springs.set_ylabel("stiffness [N·m/rad]", color="#ef6c00")
    ax.set_title(
        f"inertia (blue, at the masses) and stiffness (orange, between them), reduced to the "
        f"{shaft} shaft",
        loc="left",
        fontsize=SMALL_PT,
        y=1.0,
    )
    ax.grid(True, axis="y", alpha=0.3)


def power_curve_plot(
    curve: drivetrain_model.PowerCurve,
    checks: Sequence[Check],
    turbine: str,
    band: tuple[float, float],
    ax: "Axes | None" = None,
) -> "Figure":
    """The grid-coupled synchronous drive train's first mode over power (Hau Fig. 7.14),
    each excitation with the rule's band (``band``: factors on its frequency) — on ``ax``
    where given, else on a figure of its own headed by ``drivetrain.grid.power``'s status."""
    from matplotlib.figure import Figure

    power = 100 * np.asarray(curve.power_fraction)
    judged = headline.of_checks(checks, ("drivetrain.grid.power",), headline.STATUS_ONLY)
    title = f"{turbine} — drive train on the grid: frequency vs power ({judged.words})"
    heading = fit(title, 6.6)
    if ax is None:
        fig = Figure(figsize=(7.0, 3.95), dpi=FIGURE_DPI)
        ax = fig.add_subplot()
        headline.stamp(fig, title, judged)
        fixed_layout(fig, top=0.2 + title_height(heading))
    ax.plot(power, curve.frequency_hz, lw=2.2, color="#1f77b4", label="1st grid mode")
    lo, hi = band
    for label, f_e in curve.lines:
        ax.axhline(f_e, color="#212121", lw=1.4)
        ax.axhspan(f_e * lo, f_e * hi, color="#e53935", alpha=0.12, lw=0)
        ax.annotate(
            label,
            (power[-1], f_e),
            xytext=(-4, 3),
            textcoords="offset points",
            ha="right",
            fontsize=9,
        )
    ax.set_xlabel("electrical power [% of rated]")
    ax.set_ylabel("frequency [Hz]")
    ax.set_title(heading, fontweight="bold", y=1.0)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    return ax.get_figure()  # type: ignore[return-value]  # a Figure's axes
