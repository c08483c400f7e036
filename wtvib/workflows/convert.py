"""``convert`` and ``shapes``: an imported turbine written as an editable wtvib spec, and an
ElastoDyn deck's mode-shape polynomials computed, audited and written corrected."""

from pathlib import Path
from typing import Any

from . import ui


def convert(source: Path, output: Path, read: Any, *, force: bool = False) -> int:
    """Write ``source`` (read with the :class:`wtvib.importers.ReadOptions` ``read``) as a
    wtvib spec, validated before writing."""
    import yaml

    from .. import importers
    from ..outputs.files import converted_spec, write_atomic
    from ..spec import from_data

    data = plain(importers.to_data(source, read))
    from_data(data, source=str(source))  # refuse to write a spec that would not load
    body = yaml.safe_dump(
        data, sort_keys=False, allow_unicode=True, width=100, default_flow_style=None
    )  # a list of numbers on one line: a table, not a column
    # a spec convert wrote is replaced while unedited; an edited one, or any other file,
    # only with --force (and never an input of this run)
    write_atomic(output, converted_spec(source.name, body), force=force)
    ui.say(f"wrote {ui.shown(output)}")
    return ui.EXIT_PASS


def plain(node: Any) -> Any:
    """Spec data as YAML writes it: numpy's numbers and arrays (an importer's arithmetic
    leaves them: a floating platform's masses) as Python's."""
    if isinstance(node, dict):
        return {k: plain(v) for k, v in node.items()}
    if isinstance(node, list | tuple):
        return [plain(v) for v in node]
    tolist = getattr(node, "tolist", None)  # a numpy scalar or array
    return plain(tolist()) if callable(tolist) and not isinstance(node, str) else node


def shapes(
    deck: Path,
    *,
    output: Path | None = None,
    rpm: float | None = None,
    json: bool = False,
    plots: bool = True,
    force: bool = False,
) -> int:
    """The deck's polynomials against the computed shapes (a table or JSON), the corrected
    tower and blade files written into ``output``, the figure beside them."""
    from .. import importers
    from ..errors import SpecError
    from ..subsystems import polynomials

    if importers.kind(deck) != "elastodyn":
        raise SpecError(
            "not an ElastoDyn deck: shapes takes an ElastoDyn main file or the .fst that names it",
            source=str(deck),
        )
    speed = (rpm, rpm) if rpm is not None and rpm > 0 else None
    spec = importers.load(deck, importers.ReadOptions(rpm=speed))
    result = polynomials.compute(spec, rpm)
    written: list[str] = []
    if output is not None:
        written += _corrected(polynomials.corrected(result), output, force)
    if plots:
        from ..outputs.files import write_atomic
        from ..outputs.plots import png_bytes
        from ..outputs.plots.polynomials import polynomials_plot

        folder = output if output is not None else Path.cwd()
        path = write_atomic(
            folder / f"{deck.stem}.shapes.png",
            png_bytes(polynomials_plot(result, spec)),
            force=force,
            folder=True,
        )
        written.append(str(path))
    doc = polynomials.document(spec, result, written)
    if json:
        ui.dump(doc)
    else:
        from ..outputs.report import shapes_table

        shapes_table(ui.console(), doc)
    return ui.EXIT_PASS


def _corrected(files: dict[str, str], output: Path, force: bool) -> list[str]:
    """The corrected ElastoDyn files written into ``output`` — all refused before any is
    written: over the deck's own, over another file without ``force``, two of one name."""
    from ..errors import OutputError
    from ..outputs.files import write_atomic

    targets = {original: output / Path(original).name for original in files}
    for original, target in targets.items():
        if target.resolve() == Path(original).resolve():
            raise OutputError(f"{target} is the deck's own file: give another folder")
        if target.exists() and not force:  # an ElastoDyn file carries no mark of wtvib's
            raise OutputError(f"{target} exists; use --force to replace it")
    names = [t.name for t in targets.values()]
    twice = next((n for n in names if names.count(n) > 1), None)
    if twice is not None:
        raise OutputError(
            f"the tower and blade files share the name {twice}: they would be written "
            "over each other in one folder"
        )
    written = []
    for original, text in files.items():
        write_atomic(targets[original], text.encode("utf-8"), force=force, folder=True)
        written.append(str(targets[original]))
    return written
