"""The command line: each command declares its options and makes one library call
(:mod:`wtvib.workflows`), whose return is the exit code.

Exit codes: 0 pass or warn, 1 fail (or warn with ``--strict``), 2 bad input or output,
3 internal error (an exception wtvib did not expect: a bug, never a verdict). Errors are
caught in one place (:func:`_command`); a traceback only with ``--debug``.
"""

import contextlib
import copy
import dataclasses
import functools
import importlib
import inspect
import os
import sys
import warnings
from collections.abc import Callable
from enum import StrEnum
from pathlib import Path
from typing import Annotated, Any, NoReturn, TypeVar

import click
import typer

from .workflows import ui  # the standard library only: numpy waits for the BLAS setting
from .workflows.help import HELP
from .workflows.ui import EXIT_PASS

# One BLAS thread unless the user chose: the models solve small dense problems,
# where OpenBLAS's busy-waiting threads only fight each other and a batch's workers (one
# process per core). Set before numpy loads — nothing above imports it; bench/bench_threads.py
# measures the two side by side.
for _threads in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_threads, "1")

#: Old spellings of options, understood but not shown (one spelling per idea: ``--out-dir``
#: a folder, ``-o``/``--output`` a file, ``--no-plots`` no figures): command → {old token:
#: today's (None: dropped, it only restated the default)}.
_FOLDER_ALIASES: dict[str, str | None] = {"--out": "--out-dir", "-o": "--out-dir"}
_PLOT_ALIASES: dict[str, str | None] = {"--no-plot": "--no-plots", "--plot": None, "--plots": None}
ALIASES: dict[str, dict[str, str | None]] = {
    "check": {**_FOLDER_ALIASES, **_PLOT_ALIASES},
    "window": {**_FOLDER_ALIASES, **_PLOT_ALIASES},
    "batch": {**_FOLDER_ALIASES, "--plots": None},
}


def _respell(args: list[str], table: dict[str, str | None]) -> list[str]:
    """The command line with old option spellings replaced by today's (up to ``--``)."""
    out: list[str] = []
    for i, arg in enumerate(args):
        if arg == "--":
            return [*out, *args[i:]]
        key, sep, value = arg.partition("=") if arg.startswith("--") else (arg, "", "")
        if key not in table:
            out.append(arg)
        elif table[key] is not None:
            out.append(f"{table[key]}{sep}{value}")
    return out


def _help_all(ctx: typer.Context, value: bool) -> None:
    """``--help-all``: the help with every option, the ones ``--help`` leaves out too."""
    if not value or ctx.resilient_parsing:
        return
    for param in ctx.command.params:
        param.hidden = False  # type: ignore[attr-defined]  # options have it, arguments too
    typer.echo(ctx.get_help())
    raise typer.Exit(EXIT_PASS)


class _Command(typer.core.TyperCommand):
    """A command that understands the old spellings of its options (:data:`ALIASES`)."""

    def parse_args(self, ctx: Any, args: list[str]) -> list[str]:
        return super().parse_args(ctx, _respell(args, ALIASES.get(self.name or "", {})))


app = typer.Typer(
    help="Vibration audit of wind turbines: natural frequencies against rotor excitations, "
    "after Hau, Wind Turbines, ch. 7.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,  # click's plain help: fits 80 columns; usage errors on one line
)


def _usage_error_on_one_line(self: Any, file: Any = None) -> None:
    """A command-line mistake as one line, like every other error wtvib reports (click's
    own shows three: its usage, a hint and the error)."""
    where = f" (see '{self.ctx.command_path} --help')" if self.ctx is not None else ""
    message = self.format_message().replace("\n", " ")
    print(f"error: {message}{where}", file=file or sys.stderr)


# typer's own copy of click (from 0.16 on, ``typer._click``) and click's, both
for _name in ("typer._click.exceptions", "click.exceptions"):
    with contextlib.suppress(ImportError):
        importlib.import_module(_name).UsageError.show = _usage_error_on_one_line


Format = StrEnum("Format", {"text": "text", "json": "json"})
Figures = StrEnum("Figures", {"main": "main", "all": "all"})
RuleKind = StrEnum("RuleKind", {"band": "band", "ratio": "ratio"})
SortBy = StrEnum("SortBy", {"file": "file", "verdict": "verdict", "name": "name"})
PresetName = StrEnum("PresetName", {"hau": "hau", "gl2010": "gl2010"})
Target = StrEnum("Target", {"soft_soft": "soft-soft", "soft": "soft", "stiff": "stiff"})
ScaleWhat = StrEnum("ScaleWhat", {"wall": "wall", "diameter": "diameter", "both": "both"})

#: The most Monte Carlo samples a run may ask for: 2,000 give the spread to a few per cent;
#: a million take minutes; more would only run without end.
MAX_SAMPLES = 1_000_000


def _o(key: str, *names: str, hidden: bool = False, **kw: Any) -> Any:
    """An option with its help from :data:`HELP`."""
    return typer.Option(*names, hidden=hidden, help=HELP[key], **kw)


def _h(key: str, *names: str, **kw: Any) -> Any:
    """A hidden option: shown by ``--help-all`` only."""
    return _o(key, *names, hidden=True, **kw)


def _arg(key: str, metavar: str = "FILE") -> Any:
    return typer.Argument(metavar=metavar, help=HELP[key])


DebugOption = Annotated[bool, _h("debug", "--debug")]
ForceOption = Annotated[bool, _h("force", "--force")]
FormatOption = Annotated[Format, _o("format", "--format", "-f")]
NoPlotsOption = Annotated[bool, _o("no_plots", "--no-plots")]
StrictOption = Annotated[bool, _o("strict", "--strict")]
SoilOption = Annotated[Path | None, _h("soil", metavar="FILE")]
HelpAll = _o("help_all", "--help-all", is_eager=True, expose_value=False, callback=_help_all)
HelpAllOption = Annotated[bool, HelpAll]
SpecArgument = Annotated[Path, _arg("spec")]

F = TypeVar("F", bound=Callable[..., int | None])
#: Options several commands share: name, declaration, default.
Group = tuple[tuple[str, Any, Any], ...]
KEYWORD_ONLY = inspect.Parameter.KEYWORD_ONLY

#: The options every command that audits shares (an import's operating range, the rule).
RUN_OPTIONS: Group = (
    ("rpm", Annotated[str | None, _o("rpm", metavar="MIN:MAX")], None),
    ("rated", Annotated[float | None, _h("rated", metavar="RPM")], None),
    ("head_mass", Annotated[float | None, _h("head_mass", metavar="KG")], None),
    ("clamped_base", Annotated[bool, _h("clamped_base", "--clamped-base")], False),
    ("deck_dofs", Annotated[bool, _h("deck_dofs", "--deck-dofs")], False),
    ("soil", SoilOption, None),
    ("blades", Annotated[int | None, _h("blades", min=1, max=10, metavar="N")], None),
    ("margin", Annotated[float | None, _o("margin", metavar="M")], None),
    ("rule", Annotated[RuleKind | None, _h("rule")], None),
    ("preset", Annotated[PresetName | None, _o("preset")], None),
)


def _shown(group: Group) -> Group:
    """The options of ``group``, every one shown by ``--help``."""
    shown = []
    for name, declared, default in group:
        info = copy.copy(declared.__metadata__[0])
        info.hidden = False
        shown.append((name, Annotated[declared.__origin__, info], default))
    return tuple(shown)


#: What a file's reading takes (``convert``, which shows them): the first run options.
READ_OPTIONS = _shown(RUN_OPTIONS[:6])
#: Every command's: --help-all (--help shows the common options; this, every one), --debug.
COMMON: Group = (("help_all", HelpAllOption, False), ("debug", DebugOption, False))
#: The uncertainty study's options (``check``, ``report``).
STUDY_OPTIONS: Group = (
    ("uncertainty", Annotated[bool, _h("uncertainty", "--uncertainty")], False),
    ("samples", Annotated[int | None, _h("samples", min=10, max=MAX_SAMPLES, metavar="N")], None),
    ("seed", Annotated[int | None, _h("seed", min=0, metavar="N")], None),
)
SCHEDULER: Group = (("scheduler", Annotated[str | None, _h("scheduler", metavar="ADDRESS")], None),)


#: Exceptions the last line of defence lets through for typer to report: exits, Ctrl-C and
#: usage errors — click's, and those of the click typer vendors (typer ≥ 0.16 raises
#: ``typer.BadParameter`` from its own copy, which click's class does not catch).
_PASS_THROUGH: tuple[type[BaseException], ...] = (typer.Exit, typer.Abort, KeyboardInterrupt)
_PASS_THROUGH += (click.exceptions.ClickException, getattr(typer, "TyperException", typer.Exit))
_state = {"debug": False}


def _command(name: str | None = None, *groups: Group) -> Callable[[F], F]:
    """Register ``function`` as a command with the shared options of ``groups`` and
    :data:`COMMON`. Typer reads a command's options from its signature, so the signature is
    rewritten with them; the run options arrive as one ``options`` argument, the study's as
    ``study`` (:func:`_arguments`). The command's return is its exit code; an exception is
    one line and exit 2 or 3 (:func:`wtvib.workflows.ui.failed`), a traceback with --debug."""
    table = [*(row for group in groups for row in group), *COMMON]
    names = {row[0] for row in table}

    def decorate(function: F) -> F:
        sig = inspect.signature(function)
        own = [p for n, p in sig.parameters.items() if n not in {"options", "study", *names}]
        shared = [inspect.Parameter(n, KEYWORD_ONLY, default=d, annotation=a) for n, a, d in table]

        @functools.wraps(function)
        def wrapper(**kwargs: Any) -> None:
            kwargs.pop("help_all", None)  # not exposed: its callback prints the help and exits
            debug = bool(kwargs.pop("debug") or _state["debug"])
            try:
                with warnings.catch_warnings():
                    if not debug:  # numpy's overflow notes on hostile numbers: the error or
                        warnings.simplefilter("ignore", RuntimeWarning)  # warning line says it
                    code = function(**_arguments(kwargs, sig.parameters, debug, names))
            except _PASS_THROUGH:
                raise  # typer reports a usage error itself (one line, exit 2)
            except Exception as exc:
                if debug:
                    raise
                given = (str(kwargs[k]) for k in ("spec_file", "source", "inputs") if k in kwargs)
                code = ui.failed(exc, kwargs.get("spec_file"), next(given, "wtvib"))
            raise typer.Exit(code or EXIT_PASS)

        keyword = [p.replace(kind=KEYWORD_ONLY) for p in own]
        wrapper.__signature__ = sig.replace(parameters=[*keyword, *shared])  # type: ignore[attr-defined]
        annotations = {k: v for k, v in function.__annotations__.items() if k in sig.parameters}
        wrapper.__annotations__ = {**annotations, **{n: a for n, a, _ in table}}
        app.command(name, cls=_Command)(wrapper)
        return function

    return decorate


def _arguments(
    kwargs: dict[str, Any], wanted: Any, debug: bool, shared: set[str]
) -> dict[str, Any]:
    """The command's arguments from its options: the input's name resolved (a typo answered
    before the imports), the run options as ``options``, the study's as ``study``."""
    from .workflows import catalogue

    kwargs = dict(kwargs)
    if isinstance(kwargs.get("spec_file"), Path):
        kwargs["spec_file"] = catalogue.resolve(kwargs["spec_file"])
    from .workflows import options  # the importers: after a typo's answer

    if "uncertainty" in shared:
        asked = [kwargs.pop(k, None) for k in ("uncertainty", "samples", "seed", "scheduler")]
        kwargs["study"] = options.study(*asked)
        kwargs.update({"scheduler": asked[3]} if "scheduler" in wanted else {})
    run = {n: kwargs.pop(n) for n, _, _ in RUN_OPTIONS if n in shared}
    if run:
        run = {k: v.value if isinstance(v, StrEnum) else v for k, v in run.items()}
        kwargs["options"] = options.options(**run)
    return {**kwargs, **({"debug": debug} if "debug" in wanted else {})}


def _version(value: bool) -> None:
    if value:
        from . import __version__

        typer.echo(f"wtvib {__version__}")
        raise typer.Exit(EXIT_PASS)


@app.callback()
def _root(
    debug: Annotated[bool, _o("debug", "--debug")] = False,
    version: Annotated[bool, _o("version", "--version", callback=_version, is_eager=True)] = False,
) -> None:
    _state["debug"] = debug


@_command(None, RUN_OPTIONS, STUDY_OPTIONS, SCHEDULER)
def check(
    spec_file: SpecArgument,
    format: FormatOption = Format.text,
    out: Annotated[Path | None, _o("check.out", "--out-dir", "-d", metavar="DIR")] = None,
    no_plots: NoPlotsOption = False,
    detail: Annotated[bool, _o("detail", "--detail")] = False,
    strict: StrictOption = False,
    campbell_csv: Annotated[Path | None, _o("campbell_csv", metavar="FILE")] = None,
    force: ForceOption = False,
    show_all: Annotated[bool, _h("show_all", "--all")] = False,
    figures: Annotated[Figures, _h("figures")] = Figures.main,
    *,
    options: Any,
    study: tuple[int | None, int],
    scheduler: str | None = None,
) -> int:
    """Audit one turbine: modes against excitations, tower class, verdict, Campbell PNGs."""
    from .workflows.check import Check, check

    asked = Check(
        spec_file,
        options,
        json=format is Format.json,
        out=out,
        plots=not no_plots,
        detail=detail,
        strict=strict,
        campbell_csv=campbell_csv,
        force=force,
        show_all=show_all,
        all_figures=figures is Figures.all,
        samples=study[0],
        seed=study[1],
        scheduler=scheduler,
    )
    return check(asked)


@_command(None, RUN_OPTIONS, STUDY_OPTIONS)
def report(
    spec_file: SpecArgument,
    output: Annotated[Path, _o("report.output", "--output", "-o", metavar="FILE")],
    force: ForceOption = False,
    *,
    options: Any,
    study: tuple[int | None, int],
    debug: bool = False,
) -> int:
    """Write the PDF audit report of one turbine."""
    from .workflows.check import pdf

    samples, seed = study
    return pdf(spec_file, output, options, force=force, samples=samples, seed=seed, debug=debug)


@_command("batch", RUN_OPTIONS)
def batch_command(
    inputs: Annotated[list[Path], _arg("inputs", metavar="FILE|FOLDER...")],
    out: Annotated[Path | None, _o("batch.out", "--out-dir", "-d", metavar="DIR")] = None,
    format: FormatOption = Format.text,
    jobs: Annotated[int | None, _o("jobs", "--jobs", "-j", min=1, metavar="N")] = None,
    no_plots: Annotated[bool, _o("batch.no_plots", "--no-plots")] = False,
    sort: Annotated[SortBy, _o("sort")] = SortBy.file,
    strict: StrictOption = False,
    scheduler: Annotated[str | None, _h("batch.scheduler", metavar="ADDRESS")] = None,
    force: ForceOption = False,
    *,
    options: Any,
) -> int:
    """Audit a catalogue: every spec found, in parallel, with a summary and reports.
    The operating and rule options apply to every input."""
    from .workflows.fleet import Batch, run

    json, plots = format is Format.json, not no_plots
    asked = Batch(inputs, options, out, json=json, jobs=jobs, plots=plots, sort=sort.value)
    return run(dataclasses.replace(asked, strict=strict, scheduler=scheduler, force=force))


@_command(None, RUN_OPTIONS)
def window(
    spec_file: SpecArgument,
    format: FormatOption = Format.text,
    out: Annotated[Path | None, _o("window.out", "--out-dir", "-d", metavar="DIR")] = None,
    no_plots: NoPlotsOption = False,
    force: ForceOption = False,
    *,
    options: Any,
) -> int:
    """Allowed frequency windows per subsystem, and where the design sits in them."""
    from .workflows.windows import window

    json_out, plots = format is Format.json, not no_plots
    return window(spec_file, options, json=json_out, out=out, plots=plots, force=force)


@_command("size", RUN_OPTIONS)
def size_command(
    spec_file: Annotated[Path, _arg("size.spec")],
    target: Annotated[Target | None, _o("target")] = None,
    target_hz: Annotated[float | None, _o("target_hz", min=0.0, metavar="HZ")] = None,
    scale: Annotated[ScaleWhat, _o("scale")] = ScaleWhat.wall,
    format: FormatOption = Format.text,
    *,
    options: Any,
) -> int:
    """Scale the tower's wall (or diameter, or both) to put its first bending in a window
    (the windows of `window` under the same operating and rule options)."""
    from .workflows.windows import size

    goal = target.value if target is not None else None
    json_out = format is Format.json
    return size(
        spec_file, options, target=goal, target_hz=target_hz, scale=scale.value, json=json_out
    )


@_command(None, READ_OPTIONS)
def convert(
    source: Annotated[Path, _arg("convert.source")],
    output: Annotated[Path, _o("convert.output", "--output", "-o", metavar="FILE")],
    force: Annotated[bool, _o("convert.force", "--force")] = False,
    *,
    options: Any,
) -> int:
    """Write an imported turbine as an editable wtvib spec (validated before writing)."""
    from .workflows.convert import convert

    return convert(source, output, options.read, force=force)


@_command("shapes")
def shapes_command(
    deck: Annotated[Path, _arg("deck", metavar="DECK")],
    output: Annotated[Path | None, _o("shapes.output", "--output", "-o", metavar="DIR")] = None,
    rpm: Annotated[float | None, _o("shapes.rpm", min=0.0, metavar="RPM")] = None,
    format: FormatOption = Format.text,
    no_plots: NoPlotsOption = False,
    force: ForceOption = False,
) -> int:
    """ElastoDyn's mode-shape polynomials: computed from the deck's tower and blade, the
    deck's own audited, corrected files written with -o."""
    from .workflows.convert import shapes

    json_out = format is Format.json
    return shapes(deck, output=output, rpm=rpm, json=json_out, plots=not no_plots, force=force)


@_command("catalogue")
def catalogue_command(
    copy: Annotated[Path | None, _o("copy", "--copy", metavar="DIR")] = None,
    force: ForceOption = False,
    format: FormatOption = Format.text,
) -> int:
    """List the turbines that ship with wtvib (check one by its name: wtvib check mod-2)."""
    from .workflows.catalogue import listing

    return listing(copy=copy, force=force, json_out=format is Format.json)


@_command()
def schema(
    report: Annotated[bool, _o("schema.report", "--report")] = False,
) -> int:
    """Print the JSON Schema of the turbine spec, or of the JSON report (--report)."""
    from .workflows.contract import schema

    return schema(report)


def main() -> None:
    """The command line (:func:`wtvib.workflows.ui.main`): ends in SystemExit."""
    ui.main(app)


def program() -> NoReturn:
    """The ``wtvib`` program: :func:`main`, then ``ui.end`` (console script, ``-m``)."""
    ui.program(app)
