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
    from .campbell import DIAGRAMS, campbell_plot

    out: dict[str, Callable[[], Figure | None]]
    if report.spec.rotor.speed.parked:  # a standstill audit: no speed to draw over
        from .campbell import standstill_plot

        out = {"standstill": functools.partial(standstill_plot, report)}
        figures = {"shapes": FIGURES["shapes"]}
    else:
        # a subsystem whose modes are all judged elsewhere (coupled) or nowhere (locked)
        # gets no diagram of its own: the system diagram shows them where they are judged
        present = {m.subsystem for m in report.modes if m.judged}
        out = {
            name: functools.partial(campbell_plot, report, subs)
            for name, subs in DIAGRAMS.items()
            if present.intersection(subs)
        }
        figures = FIGURES
    for name, make in figures.items():
        if detail or name in MAIN:
            out[name] = functools.partial(make, report)
    return out


def _damping(report: "Report") -> "Figure | None":
    from .campbell import damping_plot

    return damping_plot(report)


def _drivetrain_modes(report: "Report") -> "Figure | None":
    from ...subsystems import drivetrain
    from .drivetrain import drivetrain_shapes_plot

    found = report.result(drivetrain.NAME, drivetrain.DrivetrainResults)
    name, shaft = report.spec.turbine.name, report.spec.drivetrain.reference_shaft
    return drivetrain_shapes_plot(found, report.modes, name, shaft)


def _drivetrain_power(report: "Report") -> "Figure | None":
    from ...subsystems import drivetrain
    from .drivetrain import power_curve_plot

    found = report.result(drivetrain.NAME, drivetrain.DrivetrainResults)
    if found is None or found.power is None or not _has(report, "drivetrain.grid.power"):
        return None
    band = report.rule.natural_band(1.0)
    return power_curve_plot(found.power, report.checks, report.spec.turbine.name, band)


def _floquet(report: "Report") -> "Figure | None":
    from ...subsystems import rotor
    from .rotor import floquet_plot

    found = report.result(rotor.NAME, rotor.RotorResults)
    if found is None or not _has(report, "rotor.floquet"):
        return None
    speed = report.spec.rotor.speed
    return floquet_plot(found, report.checks, report.spec.turbine.name, speed)


def _flutter(report: "Report") -> "Figure | None":
    from ...aero import aeroelastic
    from .blade import flutter_plot

    found = report.result(aeroelastic.NAME, aeroelastic.AeroelasticResults)
    if found is None or not _has(report, "blade.flutter"):
        return None
    return flutter_plot(found, report.checks, report.spec.turbine.name)


def _blade_stability(report: "Report") -> "Figure | None":
    from ...aero import aeroelastic
    from .blade import stability_chart_plot

    found = report.result(aeroelastic.NAME, aeroelastic.AeroelasticResults)
    given = report.spec.blade.aeroelastic
    if found is None or given is None or not _has(report, "blade.flutter"):
        return None
    name = report.spec.turbine.name
    return stability_chart_plot(found, report.checks, name, given.speed_margin)


def _blade_stall(report: "Report") -> "Figure | None":
    from ...aero import stall
    from .blade import stall_damping_plot

    found = report.result(stall.NAME, stall.StallResults)
    if found is None:
        return None
    return stall_damping_plot(found, report.checks, report.spec.turbine.name)


def _system_energy(report: "Report") -> "Figure | None":
    from .system import coupled_energy_plot

    check = next((c for c in report.checks if c.id == "system.coupling"), None)
    return coupled_energy_plot(check, report.spec.turbine.name) if check is not None else None


def _shapes(report: "Report") -> "Figure | None":
    from ...subsystems import polynomials
    from .polynomials import polynomials_plot

    found = report.result(polynomials.NAME, polynomials.Shapes)
    return polynomials_plot(found, report.spec) if found is not None else None


def _has(report: "Report", check: str) -> bool:
    return any(c.id == check for c in report.checks)


#: The figures besides the Campbell diagrams, by file stem suffix, each named by the
#: declaration of the subsystem whose results it draws (``Subsystem.figures``): each takes
#: what it draws from the report — a subsystem's typed result (``Report.result``), its
#: checks, the turbine's name — and hands it to the plot function, which draws that alone
#: (python-control's ``x_plot(result)``); None where the report has nothing to draw.
FIGURES: dict[str, Callable[["Report"], "Figure | None"]] = {
    "damping": _damping,
    "drivetrain-modes": _drivetrain_modes,
    "drivetrain-power": _drivetrain_power,
    "floquet": _floquet,
    "blade-flutter": _flutter,
    "blade-stability": _blade_stability,
    "blade-stall": _blade_stall,
    "system-energy": _system_energy,
    "shapes": _shapes,
}


def diagrams(report: "Report", detail: bool = True) -> dict[str, "Figure"]:
    """Every diagram the report has judged modes for (Campbell diagrams, drive-train mode
    shapes …), keyed by file stem suffix; without ``detail`` only the main ones (MAIN), the
    detail figures not even drawn."""
    drawn = {name: make() for name, make in drawers(report, detail).items()}
    return {name: fig for name, fig in drawn.items() if fig is not None}
