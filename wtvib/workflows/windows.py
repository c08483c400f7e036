"""``window`` and ``size``: the frequency windows a finished audit leaves each subsystem, and
the tower scaled to put its first bending in one (:mod:`wtvib.studies.design`)."""

from pathlib import Path

from . import ui
from .options import Options


def window(
    spec_file: Path,
    options: Options,
    *,
    json: bool = False,
    out: Path | None = None,
    plots: bool = True,
    force: bool = False,
) -> int:
    """Print the windows (a table, or the JSON document) and write their figure."""
    from .. import audit
    from ..studies import design

    turbine = options.load(spec_file)
    ui.solve_on_every_core()
    report = audit.run(turbine, options.settings(turbine))
    found = design.all_windows(report)
    doc = design.windows_document(turbine, found, report.rule)
    if json:
        ui.dump(doc)
    else:
        from ..outputs.report import windows_table

        windows_table(ui.console(), doc)
    if plots:
        from ..outputs.files import write_atomic
        from ..outputs.plots import png_bytes
        from ..outputs.plots.campbell import windows_plot

        tw = design.tower_windows(found)
        tower_w = tw.allowed if tw is not None else ()
        folder = out if out is not None else Path.cwd()  # never beside the input
        path = write_atomic(
            folder / f"{spec_file.stem}.windows.png",
            png_bytes(windows_plot(report, tower_w)),
            force=force,
            folder=True,
        )
        ui.say(f"wrote {ui.shown(path)}", err=json)
    return ui.EXIT_PASS


def size(
    spec_file: Path,
    options: Options,
    *,
    target: str | None = None,
    target_hz: float | None = None,
    scale: str = "wall",
    json: bool = False,
) -> int:
    """Scale the tower to a window's middle (``target``) or to ``target_hz``; print what it
    takes."""
    from .. import audit
    from ..studies import design

    turbine = options.load(spec_file)  # a mistake in the input first
    ui.solve_on_every_core()
    if (target is None) == (target_hz is None):
        from ..errors import OptionError

        raise OptionError("--target", "give --target WINDOW or --target-hz HZ")
    design.require_sections(turbine)
    goal = target_hz
    if target is not None:
        report = audit.run(turbine, options.settings(turbine))
        found = design.all_windows(report)
        goal = design.window_goal(found, target)
    assert goal is not None
    result = design.size(turbine, goal, scale)  # type: ignore[arg-type]
    doc = {"schema": design.SIZE_SCHEMA, "turbine": turbine.turbine.name, **result.to_dict()}
    if json:
        ui.dump(doc)
        return ui.EXIT_PASS
    ui.say(
        f"{turbine.turbine.name}: scale the tower {scale} by {result.scale:.4f} → first "
        f"bending {result.frequency_hz:.4f} Hz (target {goal:.4f} Hz); tower mass "
        f"{result.mass_before_kg:,.0f} → {result.mass_after_kg:,.0f} kg "
        f"({doc['mass_change_percent']:+.1f} %)"
    )
    for line in result.warnings:
        ui.say(f"warning: {ui.shown(line)}", err=True)
    return ui.EXIT_PASS
