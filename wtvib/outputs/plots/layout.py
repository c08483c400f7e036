"""Fixed figure layouts: margins in inches, set once.

Constrained layout measured every text of a figure on every draw — a fifth of the drawing
time — to find margins these figures know beforehand: their tick labels, axis labels, title
lines and legend rows. Each figure states its margins where it is made; the pictures were
compared with the constrained ones side by side (the catalogue and the NREL 5-MW deck).
Titles are placed at ``y=1.0`` explicitly: matplotlib then does not measure the axes at
every draw for tick labels above them, which these axes do not have (the same picture).
"""

import math
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from matplotlib.figure import Figure


#: Every figure's resolution, and its smallest text [pt]. Figures are at most 7.5 in wide,
#: so that the PDF, which prints them at its text width (A4 less 36 mm: 6.85 in), keeps
#: their smallest text at 7 pt or more; 200 dpi gives a 7.5-in figure the 1,500 pixels the
#: PNGs had at 10 in and 150 dpi.
FIGURE_DPI = 200
SMALL_PT = 8
#: The widest figure [in] and the width the PDF prints figures at [in].
MAX_FIGURE_IN, PDF_FIGURE_IN = 7.5, 6.85

#: The least height [in] an axes keeps; margins that would leave less make the figure taller.
MIN_AXES_IN = 1.5

#: Inches per line of an axes title (12 pt, matplotlib's "large", line spacing 1.2).
TITLE_LINE_IN = 0.22

#: Mean character width of DejaVu Sans, in font sizes: regular about half its size, bold
#: 0.72 (9 pt bold measured: "mesh.stage2" 0.084 in a character, "12P" 0.089).
CHAR_EM, BOLD_CHAR_EM = 0.55, 0.72


def text_width(text: str, fontsize: float, bold: bool = False) -> float:
    """The width [in] a label of this text takes, estimated from its length (margins are
    set before anything is drawn)."""
    return len(text) * fontsize * (BOLD_CHAR_EM if bold else CHAR_EM) / 72.0


def fit(text: str, width: float, fontsize: float = 12, bold: bool = True) -> str:
    """``text`` broken into lines (at its own line breaks, then between words) so that
    each fits ``width`` [in] at ``fontsize`` [pt]: titles stay inside their figure."""
    lines: list[str] = []
    for paragraph in text.split("\n"):
        line = ""
        for word in paragraph.split(" "):
            trial = f"{line} {word}" if line else word
            if line and text_width(trial, fontsize, bold) > width:
                lines.append(line)
                line = word
            else:
                line = trial
        lines.append(line)
    return "\n".join(lines)


def title_height(text: str, fontsize: float = 12) -> float:
    """The height [in] of a title of these lines (1.2 line spacing)."""
    return (text.count("\n") + 1) * fontsize * 1.2 / 72.0


def fixed_layout(
    fig: "Figure",
    *,
    left: float = 0.8,
    right: float = 0.3,
    top: float = 0.45,
    bottom: float = 0.6,
    gap: float = 0.0,
) -> None:
    """Set the figure's margins, in inches, and ``gap`` between axes stacked in rows. The
    defaults hold a one-line title, tick labels up to five characters with an axis label,
    and an x-axis label."""
    width, height = fig.get_size_inches()
    specs = [ax.get_subplotspec() for ax in fig.axes]
    rows = max((s.get_gridspec().nrows for s in specs if s is not None), default=1)
    need = top + bottom + rows * MIN_AXES_IN + (rows - 1) * gap
    if height < need:  # a legend of many rows: the figure grows, the axes keep their room
        height = need
        fig.set_size_inches(width, height)
    if left + right > 0.7 * width:  # labels wider than the figure: cut, the axes stay
        left, right = (m * 0.7 * width / (left + right) for m in (left, right))
    span = height - top - bottom
    axes_height = (span - (rows - 1) * gap) / rows
    fig.subplots_adjust(
        left=left / width,
        right=1 - right / width,
        top=1 - top / height,
        bottom=bottom / height,
        hspace=gap / axes_height if rows > 1 and axes_height > 0 else None,
    )


def legend_height(entries: int, columns: int, fontsize: float) -> float:
    """The height [in] of a frameless legend of single-line entries: rows of 1.53 font
    sizes (the text and matplotlib's label spacing, 0.5) and 3 pt of border, as measured."""
    rows = -(-entries // max(columns, 1))
    return (rows * 1.53 * fontsize + 3.0) / 72.0


def legend_below(  # type: ignore[no-untyped-def]
    fig: "Figure",
    ax,
    handles,
    labels,
    *,
    columns: int,
    fontsize: float,
    top: float,
    left: float = 0.8,
    right: float = 0.3,
) -> None:
    """The legend under the axes at the bottom of the figure, the axes above it: margins
    set with :func:`fixed_layout` (``top``, ``left`` and ``right`` in inches)."""
    below = legend_height(len(labels), columns, fontsize)
    fixed_layout(fig, top=top, left=left, right=right, bottom=below + 0.62)  # may grow it
    ax.legend(
        handles,
        labels,
        loc="lower center",
        bbox_to_anchor=(0.5, 0.04 / fig.get_size_inches()[1]),  # 0.04 in above the edge
        bbox_transform=fig.transFigure,
        fontsize=fontsize,
        ncol=columns,
        frameon=False,
    )


def plain_decades(axis) -> None:  # type: ignore[no-untyped-def]
    """Label a log or symlog axis's decades as plain numbers — 100, 10, 1, 0.1, 0, −0.1 —
    rather than as powers of ten: read at a glance, and drawn without mathtext, whose
    parser matplotlib builds at its first use in each drawing process.
    Minor ticks keep matplotlib's labels (shown only on an axis of about one decade)."""
    from matplotlib.ticker import FuncFormatter

    axis.set_major_formatter(FuncFormatter(lambda value, _: _plain(value)))


def _plain(value: float) -> str:
    if value == 0:
        return "0"
    size = abs(value)
    text = f"{size:g}" if 1e-4 <= size < 1e6 else f"1e{round(math.log10(size))}"
    return ("\u2212" if value < 0 else "") + text
