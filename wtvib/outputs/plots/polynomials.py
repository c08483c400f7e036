"""ElastoDyn's mode-shape polynomials: each set's computed mode, the deck's polynomial and
the computed one (``wtvib shapes``), for a reviewer to see which shapes are stale."""

from typing import TYPE_CHECKING

import numpy as np

from ...rules import Status
from ...spec import Spec
from ...subsystems.polynomials import Row, Shapes
from .. import words
from . import headline
from .campbell import STATUS_COLOUR
from .layout import FIGURE_DPI, MAX_FIGURE_IN, SMALL_PT, fit, fixed_layout, title_height

if TYPE_CHECKING:
    from matplotlib.figure import Figure
    from numpy.typing import ArrayLike, NDArray


def polynomials_plot(result: Shapes, spec: Spec) -> "Figure":
    """One panel a set: the finite-element mode at its stations (points), the deck's
    polynomial (dashed, in its status's colour) and the computed one (solid), each scaled
    to its largest deflection."""
    from matplotlib.figure import Figure

    rows = [*result.tower, *result.blade]
    cols = 4 if len(rows) > 4 else len(rows)
    lines = -(-len(rows) // cols)
    fig = Figure(figsize=(MAX_FIGURE_IN, 2.3 * lines + 1.2), dpi=FIGURE_DPI)
    judged = [r for r in rows if r.deck is not None]
    stale = [r.key for r in judged if r.status() == "warn"]
    status: Status = "warn" if stale else "pass" if judged else "info"
    words = (
        f"WARN: {', '.join(stale)} not the mode's"
        if stale
        else "PASS: every deck polynomial is its mode's"
        if judged
        else "computed (the deck gives none)"
    )
    title = f"{spec.turbine.name} — ElastoDyn mode-shape polynomials: {words}"
    heading = fit(title, MAX_FIGURE_IN - 0.4, 10)
    axes = fig.subplots(lines, cols, squeeze=False).ravel()
    # each panel's two-line title above it, its x label under it
    fixed_layout(fig, left=0.5, top=0.55 + title_height(heading, 10), bottom=0.5, gap=0.95)
    fig.subplots_adjust(wspace=0.35)
    x = np.linspace(0.0, 1.0, 101)
    for ax, row in zip(axes, rows, strict=False):
        _panel(ax, row, x)
    for ax in axes[len(rows) :]:
        ax.set_axis_off()
    fig.suptitle(heading, fontweight="bold", fontsize=10, color=STATUS_COLOUR[status], y=0.995)
    parts = (("tower", result.tower), ("blade", result.blade))
    checks = tuple(f"polynomials.{part}" for part, got in parts if any(r.deck for r in got))
    headline.stamp(fig, title, headline.Headline(status, words, checks))
    return fig


def _scaled(y: "ArrayLike") -> "NDArray[np.float64]":
    """A shape scaled to its largest deflection, its tip positive: a second mode barely
    moves its tip, where ElastoDyn normalises, and scaled there a small difference of the
    tip looks like a different shape (the MAC, which the panel states, does not care)."""
    y = np.asarray(y, dtype=float)
    peak = float(np.abs(y).max()) or 1.0
    return y / peak * (1.0 if y[-1] >= 0 else -1.0)


def _panel(ax, row: Row, x) -> None:  # type: ignore[no-untyped-def]
    ax.plot(row.x, _scaled(row.shape), "o", ms=2.5, color="#424242", label="finite elements")
    computed = _scaled(row.computed.polynomial.value(x))
    ax.plot(x, computed, color="#1565c0", lw=1.6, label="computed")
    if row.deck is not None:
        colour = STATUS_COLOUR[row.status()]
        ax.plot(x, _scaled(row.deck.value(x)), ls="--", color=colour, lw=1.4, label="deck")
    ax.axhline(0, color="#9e9e9e", lw=0.6)
    said = (
        f"MAC {row.mac_deck:.4f}, {words.signed_percent(row.stiffer)}"
        if row.mac_deck is not None and row.stiffer is not None
        else "no deck polynomial"
    )
    ax.set_title(f"{row.key}: {row.frequency_hz:.3g} Hz\n{said}", fontsize=SMALL_PT, y=1.0)
    ax.tick_params(labelsize=SMALL_PT)
    ax.grid(True, alpha=0.3)
    ax.set_xlabel("x (root 0, tip 1)", fontsize=SMALL_PT)
    if row.key in ("TwFAM1Sh", "BldFl1Sh"):
        ax.legend(fontsize=SMALL_PT - 1, loc="upper left")
