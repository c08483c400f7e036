"""Figures: calculate first, draw second (python-control's ``x_plot(result)``).

Every figure draws what the audit computed — :class:`~wtvib.audit.Report`'s modes,
findings, checks and typed ``results`` — and computes nothing. One module per subject:
:mod:`.campbell` (Campbell diagrams, the design windows), :mod:`.drivetrain`,
:mod:`.rotor`, :mod:`.blade`, :mod:`.system`; :func:`diagrams` is the list of what
``check`` writes, :mod:`.render` draws it beside the audit on the cores there are.
matplotlib is imported lazily, with the Agg backend, so ``wtvib --help`` stays fast.
"""

import functools
import struct
import zlib
from collections.abc import Callable
from typing import TYPE_CHECKING

from ... import __version__
from .. import png
from . import headline

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ...audit import Report


def png_bytes(fig: "Figure") -> bytes:
    """The figure as an RGB PNG, tagged as written by wtvib (see :mod:`wtvib.outputs.files`),
    with its title and judgement as text chunks where it was stamped
    (:func:`.headline.stamp`: ``Title``, ``wtvib:status``, ``wtvib:checks``).

    The pixels Agg draws, without its alpha channel (wtvib's figures are opaque: RGB is a
    tenth smaller and spares the PDF a soft mask per image), written here rather than by
    Pillow: rows unfiltered and zlib's fastest level, which for these flat-coloured figures
    is half Pillow's encoding time (its adaptive row filters) for files 4 % larger."""
    import numpy as np
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = fig.canvas if isinstance(fig.canvas, FigureCanvasAgg) else FigureCanvasAgg(fig)
    canvas.draw()  # type: ignore[no-untyped-call]
    width, height = canvas.get_width_height(physical=True)
    rows = np.empty((height, 1 + 3 * width), dtype=np.uint8)  # each row: filter 0, RGB
    rows[:, 0] = 0
    pixels = rows[:, 1:].reshape(height, width, 3)  # a view: the last axis splits in place
    assert np.may_share_memory(pixels, rows)
    pixels[...] = np.asarray(canvas.buffer_rgba())[:, :, :3]  # type: ignore[no-untyped-call]
    per_metre = round(fig.dpi / 0.0254)
    stamped = headline.stamp_of(fig)
    meta = (
        [
            png.text("Title", stamped[0]),
            png.text("wtvib:status", stamped[1].status),
            png.text("wtvib:checks", ",".join(stamped[1].checks)),
        ]
        if stamped is not None
        else []
    )
    return b"".join(
        [
            png.SIGNATURE,
            png.chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)),
            png.chunk(b"pHYs", struct.pack(">IIB", per_metre, per_metre, 1)),
            png.chunk(b"tEXt", b"Software\x00" + f"wtvib {__version__}".encode("latin-1")),
            *meta,
            png.chunk(b"IDAT", zlib.compress(rows.tobytes(), 1)),
            png.chunk(b"IEND", b""),
        ]
    )


#: The figures a reader looks at first: the Campbell diagrams and the damping in operation.
#: The others (mode shapes, power sweep, Floquet and stability charts, V–g, energy shares,
#: an ElastoDyn deck's polynomials) are detail: ``check --figures all``, and always in
#: ``report`` and ``batch``.
MAIN = ("campbell", "damping")


def drawers(report: "Report", detail: bool = True) -> dict[str, Callable[[], "Figure | None"]]:
    """What :func:`diagrams` draws, not yet drawn: each figure's maker by file stem suffix
    (a maker may find nothing to draw and return None)."""
    from .blade import flutter_plot, stability_chart_plot, stall_damping_plot
    from .campbell import DIAGRAMS, campbell_plot, damping_plot
    from .drivetrain import drivetrain_shapes_plot, power_curve_plot
    from .polynomials import shapes_plot
    from .rotor import floquet_plot
    from .system import coupled_energy_plot

    shapes = {"shapes": functools.partial(shapes_plot, report)} if detail else {}
    if report.spec.rotor.speed.parked:  # a standstill audit: no speed to draw over
        from .campbell import standstill_plot

        return {"standstill": functools.partial(standstill_plot, report), **shapes}
    # a subsystem whose modes are all judged elsewhere (coupled) or nowhere (locked) gets no
    # diagram of its own: the system diagram shows them where they are judged
    present = {m.subsystem for m in report.modes if m.judged}
    out: dict[str, Callable[[], Figure | None]] = {
        name: functools.partial(campbell_plot, report, subs)
        for name, subs in DIAGRAMS.items()
        if present.intersection(subs)
    }
    makers = {
        "damping": damping_plot,
        "drivetrain-modes": drivetrain_shapes_plot,
        "drivetrain-power": power_curve_plot,
        "floquet": floquet_plot,
        "blade-flutter": flutter_plot,
        "blade-stability": stability_chart_plot,
        "blade-stall": stall_damping_plot,
        "system-energy": coupled_energy_plot,
    }
    for name, make in makers.items():
        if detail or name in MAIN:
            out[name] = functools.partial(make, report)
    return out | shapes


def diagrams(report: "Report", detail: bool = True) -> dict[str, "Figure"]:
    """Every diagram the report has judged modes for (Campbell diagrams, drive-train mode
    shapes …), keyed by file stem suffix; without ``detail`` only the main ones (MAIN), the
    detail figures not even drawn."""
    drawn = {name: make() for name, make in drawers(report, detail).items()}
    return {name: fig for name, fig in drawn.items() if fig is not None}
