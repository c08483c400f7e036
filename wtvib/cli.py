"""The command line: each command declares its options and makes one library call
(:mod:`wtvib.workflows`), whose return is the exit code.

Exit codes: 0 pass or warn, 1 fail (or warn with ``--strict``), 2 bad input or output,
3 internal error (an exception wtvib did not expect: a bug, never a verdict). Errors are
caught in one place (:func:`_user_errors`); a traceback only with ``--debug``.
"""

import functools
import inspect
import math
import os
import sys
import warnings
from collections.abc import Callable
from enum import StrEnum
from pathlib import Path
from typing import Annotated, Any, TypeVar

import click
import typer

from .workflows import ui  # the standard library only: numpy waits for the BLAS setting
from .workflows.ui import EXIT_INPUT, EXIT_PASS

# One BLAS thread unless the user chose: the models solve small dense problems,
# where OpenBLAS's busy-waiting threads only fight each other and a batch's workers (one
# process per core). Set before numpy loads — nothing above imports it; bench/bench_threads.py
# measures the two side by side.
for _threads in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_threads, "1")

#: Old spellings of options, still understood but no longer shown (one spelling per idea:
#: ``--out-dir`` is a folder, ``-o``/``--output`` a file, ``--no-plots`` writes no figures):
#: command → {old token: today's (None: the old token is dropped, it only restated the
#: default)}.
_FOLDER_ALIASES: dict[str, str | None] = {"--out": "--out-dir", "-o": "--out-dir"}
ALIASES: dict[str, dict[str, str | None]] = {
    "check": {**_FOLDER_ALIASES, "--no-plot": "--no-plots", "--plot": None, "--plots": None},
    "window": {**_FOLDER_ALIASES, "--no-plot": "--no-plots", "--plot": None, "--plots": None},
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


#: The most Monte Carlo samples a run may ask for: 2,000 give the spread to a few per cent;
#: a million take minutes; more would only run without end.
MAX_SAMPLES = 1_000_000

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


def _one_line_usage_errors() -> None:
    """Typer's click (its own copy from 0.16 on, ``typer._click``) and click's, both."""
    import importlib

    for name in ("typer._click.exceptions", "click.exceptions"):
        try:
            module = importlib.import_module(name)
        except ImportError:
            continue
        module.UsageError.show = _usage_error_on_one_line


_one_line_usage_errors()


class Format(StrEnum):
    text = "text"
    json = "json"


class Figures(StrEnum):
    main = "main"
    all = "all"


class RuleKind(StrEnum):
    band = "band"
    ratio = "ratio"


class SortBy(StrEnum):
    file = "file"
    verdict = "verdict"
    name = "name"


class PresetName(StrEnum):
    hau = "hau"
    gl2010 = "gl2010"


def _option(*names: str, hidden: bool = False, **kw: Any) -> Any:
    return typer.Option(*names, hidden=hidden, **kw)


RpmOption = Annotated[
    str | None,
    _option(
        metavar="MIN:MAX",
        help="Operating range [rpm] (or one fixed speed) for imports that do not give it.",
    ),
]
RatedOption = Annotated[
    float | None, _option(metavar="RPM", hidden=True, help="Rated speed [rpm].")
]
HeadMassOption = Annotated[
    float | None,
    _option(
        metavar="KG",
        hidden=True,
        help="Tower-head mass [kg] for windIO files (1.x hold no hub/nacelle).",
    ),
]
CLAMPED = (
    "Audit a floating turbine's tower (windIO file or OpenFAST deck set) as if clamped at its "
    "base (said in the report's headline; platform and moorings are not modelled)."
)
ClampedOption = Annotated[bool, _option("--clamped-base", hidden=True, help=CLAMPED)]
DeckDofsOption = Annotated[
    bool,
    _option(
        "--deck-dofs",
        hidden=True,
        help="Model an OpenFAST deck with its degrees of freedom as it switches them (FlapDOF1 … "
        "PtfmYDOF, as OpenFAST models it); by default every mode of the structure is audited"
        " and the switches said.",
    ),
]
SoilOption = Annotated[
    Path | None,
    _option(
        metavar="FILE",
        hidden=True,
        help="Soil profile (YAML: soil layers, bounds) for a windIO monopile.",
    ),
]
BladesOption = Annotated[
    int | None,
    _option(
        min=1,
        max=10,
        metavar="N",
        hidden=True,
        help="Number of blades, for Campbell results that do not say.",
    ),
]
MarginOption = Annotated[
    float | None, _option(metavar="M", help="Margin, e.g. 0.05 (overrides the spec).")
]
RuleOption = Annotated[
    RuleKind | None, _option(hidden=True, help="Margin rule (overrides the spec).")
]
PresetOption = Annotated[PresetName | None, _option(help="Code preset for rule and margin.")]
DebugOption = Annotated[bool, _option("--debug", hidden=True, help="Show tracebacks for errors.")]
ForceOption = Annotated[
    bool,
    _option("--force", hidden=True, help="Replace existing output files not written by wtvib."),
]
FormatOption = Annotated[Format, _option("--format", "-f", help="Output format.")]
NoPlotsOption = Annotated[bool, _option("--no-plots", help="Write no figures.")]
StrictOption = Annotated[bool, _option("--strict", help="Exit 1 on warn as well as fail.")]
HelpAllOption = Annotated[
    bool,
    _option(
        "--help-all",
        is_eager=True,
        expose_value=False,
        callback=_help_all,
        help="Show every option (import, rule, figure and study options too).",
    ),
]
UncertaintyOption = Annotated[
    bool,
    _option("--uncertainty", hidden=True, help="Propagate the spec's tolerances (Monte Carlo)."),
]
SamplesOption = Annotated[
    int | None,
    _option(
        min=10,
        max=MAX_SAMPLES,
        metavar="N",
        hidden=True,
        help="Monte Carlo samples (2,000); needs --uncertainty.",
    ),
]
SeedOption = Annotated[
    int | None,
    _option(min=0, metavar="N", hidden=True, help="Seed of the sampling (0); needs --uncertainty."),
]
SchedulerOption = Annotated[
    str | None,
    _option(
        metavar="ADDRESS",
        hidden=True,
        help="Sample on a Dask scheduler (tcp://host:8786); needs --uncertainty.",
    ),
]
OutputOption = Annotated[Path, _option("--output", "-o", metavar="FILE", help="PDF file to write.")]
#: What a turbine file may be (wtvib.importers.load tells them apart).
SPEC_HELP = (
    "Turbine file: a wtvib spec, a windIO turbine YAML, an OpenFAST deck (.fst or ElastoDyn "
    ".dat), or another tool's Campbell results (.cmb, .csv, .lin, a linearisation folder)."
)
SpecArgument = Annotated[Path, typer.Argument(metavar="FILE", help=SPEC_HELP)]


def _out_dir(what: str) -> Any:
    return _option("--out-dir", "-d", metavar="DIR", help=what)


def _study(
    uncertainty: bool, samples: int | None, seed: int | None, scheduler: str | None = None
) -> tuple[int | None, int]:
    """--samples, --seed and --scheduler, which only an --uncertainty run uses (said where
    given without it), with their defaults; no samples without --uncertainty."""
    given = ((scheduler, "--scheduler"), (samples, "--samples"), (seed, "--seed"))
    for value, name in given:
        if value is not None and not uncertainty:
            raise typer.BadParameter(f"{name} applies to --uncertainty", param_hint=name)
    return ((2000 if samples is None else samples) if uncertainty else None), seed or 0


def _read(rpm: str | None, **given: Any) -> Any:
    from .importers import ReadOptions

    return ReadOptions(rpm=_rpm_range(rpm), **given)


def _options(
    rpm: str | None,
    rated: float | None,
    head_mass: float | None,
    clamped_base: bool,
    deck_dofs: bool,
    soil: Path | None,
    blades: int | None,
    margin: float | None,
    rule: RuleKind | None,
    preset: PresetName | None,
) -> Any:
    from .workflows.batch import Options

    read = _read(
        rpm,
        rated=rated,
        head_mass=head_mass,
        clamped_base=clamped_base,
        blades=blades,
        soil=soil,
        deck_dofs=deck_dofs,
    )
    return Options(
        read=read,
        margin=margin,
        rule=rule.value if rule is not None else None,
        preset=preset.value if preset is not None else None,
    )


F = TypeVar("F", bound=Callable[..., int | None])

#: The options every command that audits shares (an import's operating range, the rule).
RUN_OPTIONS: tuple[tuple[str, Any, Any], ...] = (
    ("rpm", RpmOption, None),
    ("rated", RatedOption, None),
    ("head_mass", HeadMassOption, None),
    ("clamped_base", ClampedOption, False),
    ("deck_dofs", DeckDofsOption, False),
    ("soil", SoilOption, None),
    ("blades", BladesOption, None),
    ("margin", MarginOption, None),
    ("rule", RuleOption, None),
    ("preset", PresetOption, None),
    ("help_all", HelpAllOption, False),  # --help shows the common options; this, every one
)


def _run_options(command: F) -> F:
    """Give a command the shared run options (RUN_OPTIONS) as one ``options`` argument:
    typer reads a command's parameters from its signature; this rewrites the signature so
    that the shared options are declared once, here, instead of in every command."""
    sig = inspect.signature(command)
    own = [p for name, p in sig.parameters.items() if name != "options"]
    extra = [
        inspect.Parameter(name, inspect.Parameter.KEYWORD_ONLY, default=default, annotation=kind)
        for name, kind, default in RUN_OPTIONS
    ]
    debug = [p for p in own if p.name == "debug"]
    rest = [p.replace(kind=inspect.Parameter.KEYWORD_ONLY) for p in own if p.name != "debug"]

    @functools.wraps(command)
    def wrapper(*args: object, **kwargs: Any) -> int | None:
        kwargs.pop("help_all", None)  # not exposed: its callback prints the help and exits
        if isinstance(kwargs.get("spec_file"), Path):  # a typo answered before the imports
            from .workflows.catalogue import resolve

            kwargs["spec_file"] = resolve(kwargs["spec_file"])
        shared = [kwargs.pop(name) for name, _, _ in RUN_OPTIONS if name != "help_all"]
        return command(*args, options=_options(*shared), **kwargs)

    wrapper.__signature__ = sig.replace(parameters=[*rest, *extra, *debug])  # type: ignore[attr-defined]
    wrapper.__annotations__ = {
        **{k: v for k, v in command.__annotations__.items() if k != "options"},
        **{name: kind for name, kind, _ in RUN_OPTIONS},
    }
    return wrapper  # type: ignore[return-value]


_state = {"debug": False}

#: Exceptions the last line of defence lets through for typer to report: exits, Ctrl-C and
#: usage errors — click's, and those of the click typer vendors (typer ≥ 0.16 raises
#: ``typer.BadParameter`` from its own copy, which click's class does not catch).
_PASS_THROUGH: tuple[type[BaseException], ...] = (
    typer.Exit,
    typer.Abort,
    KeyboardInterrupt,
    click.exceptions.ClickException,
    *((typer.TyperException,) if hasattr(typer, "TyperException") else ()),
)


def _user_errors(command: F) -> F:
    """The command's return as its exit code; an exception as one line and exit 2 or 3
    (:func:`wtvib.workflows.ui.failed`), a traceback with --debug."""

    @functools.wraps(command)
    def wrapper(*args: object, **kwargs: object) -> None:
        debug = _state["debug"] or kwargs.get("debug")
        try:
            with warnings.catch_warnings():
                if not debug:  # numpy's overflow notes on hostile numbers: the error or
                    warnings.simplefilter("ignore", RuntimeWarning)  # warning line says it
                code = command(*args, **kwargs)
        except _PASS_THROUGH:
            raise  # typer reports a usage error itself (one line, exit 2)
        except Exception as exc:
            if debug:
                raise
            inputs = next(
                (str(kwargs[k]) for k in ("spec_file", "source", "inputs") if k in kwargs), "wtvib"
            )
            raise typer.Exit(ui.failed(exc, kwargs.get("spec_file"), inputs)) from None
        raise typer.Exit(code or EXIT_PASS)

    return wrapper  # type: ignore[return-value]


def _version(value: bool) -> None:
    if value:
        from . import __version__

        typer.echo(f"wtvib {__version__}")
        raise typer.Exit(EXIT_PASS)


@app.callback()
def _root(
    debug: Annotated[bool, _option("--debug", help="Show tracebacks for errors.")] = False,
    version: Annotated[
        bool, _option("--version", callback=_version, is_eager=True, help="Print the version.")
    ] = False,
) -> None:
    _state["debug"] = debug


CheckOut = Annotated[
    Path | None, _out_dir("Folder for the figures (default: the current directory).")
]
CheckDetail = Annotated[bool, _option("--detail", help="Print the tables of modes and checks too.")]
CheckCampbellCsv = Annotated[
    Path | None,
    _option(
        "--campbell-csv",
        metavar="FILE",
        help="Write the Campbell data (frequency and damping of every judged mode per "
        "operating point) as CSV.",
    ),
]
CheckShowAll = Annotated[bool, _option("--all", hidden=True, help="Show passing minor checks too.")]
CheckFigures = Annotated[
    Figures,
    _option(
        hidden=True,
        help="main: the Campbell diagrams and damping; all: the detail figures too.",
    ),
]


@app.command(cls=_Command)
@_user_errors
@_run_options
def check(
    spec_file: SpecArgument,
    format: FormatOption = Format.text,
    out: CheckOut = None,
    no_plots: NoPlotsOption = False,
    detail: CheckDetail = False,
    strict: StrictOption = False,
    campbell_csv: CheckCampbellCsv = None,
    force: ForceOption = False,
    show_all: CheckShowAll = False,
    figures: CheckFigures = Figures.main,
    uncertainty: UncertaintyOption = False,
    samples: SamplesOption = None,
    seed: SeedOption = None,
    scheduler: SchedulerOption = None,
    *,
    options: Any,
    debug: DebugOption = False,
) -> int:
    """Audit one turbine: modes against excitations, tower class, verdict, Campbell PNGs."""
    from .workflows.check import Check, check

    drawn, seed_ = _study(uncertainty, samples, seed, scheduler)
    json_out, every = format is Format.json, figures is Figures.all
    shown = (json_out, out, not no_plots, detail, strict, campbell_csv, force, show_all, every)
    return check(Check(spec_file, options, *shown, drawn, seed_, scheduler))


@app.command(cls=_Command)
@_user_errors
@_run_options
def report(
    spec_file: SpecArgument,
    output: OutputOption,
    force: ForceOption = False,
    uncertainty: UncertaintyOption = False,
    samples: SamplesOption = None,
    seed: SeedOption = None,
    *,
    options: Any,
    debug: DebugOption = False,
) -> int:
    """Write the PDF audit report of one turbine."""
    from .workflows.check import pdf

    drawn, seed_ = _study(uncertainty, samples, seed)
    debugging = bool(debug or _state["debug"])
    return pdf(spec_file, output, options, force=force, samples=drawn, seed=seed_, debug=debugging)


BatchInputs = Annotated[
    list[Path], typer.Argument(metavar="FILE|FOLDER...", help="Spec files or folders.")
]
BatchOut = Annotated[Path | None, _out_dir("Folder for the JSON, CSV, PNG and PDF files.")]
BatchJobs = Annotated[
    int | None,
    _option("--jobs", "-j", min=1, metavar="N", help="Processes (default: all cores)."),
]
BatchNoPlots = Annotated[bool, _option("--no-plots", help="Write no figures and no PDF report.")]
BatchSort = Annotated[SortBy, _option(help="Order of the summary table.")]
BatchScheduler = Annotated[
    str | None,
    _option(
        metavar="ADDRESS",
        hidden=True,
        help="Audit on a Dask scheduler's workers (tcp://host:8786), not locally.",
    ),
]


@app.command("batch", cls=_Command)
@_user_errors
@_run_options
def batch_command(
    inputs: BatchInputs,
    out: BatchOut = None,
    format: FormatOption = Format.text,
    jobs: BatchJobs = None,
    no_plots: BatchNoPlots = False,
    sort: BatchSort = SortBy.file,
    strict: StrictOption = False,
    scheduler: BatchScheduler = None,
    force: ForceOption = False,
    *,
    options: Any,
    debug: DebugOption = False,
) -> int:
    """Audit a catalogue: every spec found, in parallel, with a summary and reports.


    The operating and rule options apply to every input."""
    from .workflows.fleet import Batch, run

    return run(
        Batch(
            inputs,
            options,
            out,
            format is Format.json,
            jobs,
            not no_plots,
            sort.value,
            strict,
            scheduler,
            force,
        )
    )


class Target(StrEnum):
    soft_soft = "soft-soft"
    soft = "soft"
    stiff = "stiff"


class ScaleWhat(StrEnum):
    wall = "wall"
    diameter = "diameter"
    both = "both"


@app.command(cls=_Command)
@_user_errors
@_run_options
def window(
    spec_file: SpecArgument,
    format: FormatOption = Format.text,
    out: Annotated[
        Path | None, _out_dir("Folder for the figure (default: the current directory).")
    ] = None,
    no_plots: NoPlotsOption = False,
    force: ForceOption = False,
    *,
    options: Any,
    debug: DebugOption = False,
) -> int:
    """Allowed frequency windows per subsystem, and where the design sits in them."""
    from .workflows.windows import window

    return window(
        spec_file, options, json=format is Format.json, out=out, plots=not no_plots, force=force
    )


@app.command("size", cls=_Command)
@_user_errors
@_run_options
def size_command(
    spec_file: Annotated[
        Path, typer.Argument(metavar="FILE", help="Turbine spec with tower sections.")
    ],
    target: Annotated[Target | None, _option(help="Window to land in (its middle).")] = None,
    target_hz: Annotated[
        float | None, _option(min=0.0, metavar="HZ", help="Or a first bending frequency [Hz].")
    ] = None,
    scale: Annotated[ScaleWhat, _option(help="What to scale.")] = ScaleWhat.wall,
    format: FormatOption = Format.text,
    *,
    options: Any,
    debug: DebugOption = False,
) -> int:
    """Scale the tower's wall (or diameter, or both) to put its first bending in a window
    (the windows of `window` under the same operating and rule options)."""
    from .workflows.windows import size

    if (target is None) == (target_hz is None):
        options.load(spec_file)  # a mistake in the input first
        raise typer.BadParameter("give --target WINDOW or --target-hz HZ")
    goal = target.value if target is not None else None
    return size(
        spec_file,
        options,
        target=goal,
        target_hz=target_hz,
        scale=scale.value,
        json=format is Format.json,
    )


def _rpm_range(text: str | None) -> tuple[float, float] | None:
    """``--rpm 6.9:12.1`` → (6.9, 12.1); ``--rpm 20`` → (20, 20)."""
    if text is None:
        return None
    try:
        parts = [float(x) for x in text.split(":")]
    except ValueError:
        raise typer.BadParameter(
            f"--rpm takes MIN:MAX in rpm, e.g. 6.9:12.1 (got {text!r})"
        ) from None
    if len(parts) == 1:
        parts *= 2
    if len(parts) != 2 or not (math.isfinite(parts[1]) and 0 <= parts[0] <= parts[1] > 0):
        raise typer.BadParameter(
            f"--rpm takes MIN:MAX with 0 <= MIN <= MAX and MAX above 0 (got {text!r}); a "
            "standstill linearisation is audited as one without --rpm"
        )
    return parts[0], parts[1]


ConvertSource = Annotated[
    Path,
    typer.Argument(
        metavar="FILE",
        help="windIO YAML, OpenFAST deck (.fst or ElastoDyn .dat) or Campbell results to convert.",
    ),
]
ConvertOutput = Annotated[
    Path, _option("--output", "-o", metavar="FILE", help="wtvib spec to write.")
]
ConvertRpm = Annotated[
    str | None, _option(metavar="MIN:MAX", help="Operating range [rpm] to put in the spec.")
]
ConvertRated = Annotated[
    float | None, _option(metavar="RPM", help="Rated speed [rpm] to put in the spec.")
]
ConvertHeadMass = Annotated[
    float | None,
    _option(
        metavar="KG",
        help="Tower-head mass [kg] to put in the spec (windIO files: 1.x hold no hub/nacelle).",
    ),
]
ConvertClampedBase = Annotated[
    bool,
    _option(
        "--clamped-base",
        help="Convert a floating turbine's tower (windIO file or OpenFAST deck set) as "
        "clamped at its base (the spec's assumptions say so; platform and moorings are "
        "not converted).",
    ),
]
ConvertForce = Annotated[bool, _option("--force", help="Replace an existing file.")]


@app.command(cls=_Command)
@_user_errors
def convert(
    source: ConvertSource,
    output: ConvertOutput,
    rpm: ConvertRpm = None,
    rated: ConvertRated = None,
    head_mass: ConvertHeadMass = None,
    clamped_base: ConvertClampedBase = False,
    soil: SoilOption = None,
    force: ConvertForce = False,
    help_all: HelpAllOption = False,
    debug: DebugOption = False,
) -> int:
    """Write an imported turbine as an editable wtvib spec (validated before writing)."""
    from .workflows.convert import convert

    read = _read(rpm, rated=rated, head_mass=head_mass, clamped_base=clamped_base, soil=soil)
    return convert(source, output, read, force=force)


ShapesDeck = Annotated[
    Path,
    typer.Argument(
        metavar="DECK", help="ElastoDyn main file (.dat), or the OpenFAST .fst that names it."
    ),
]
ShapesOutput = Annotated[
    Path | None,
    _option(
        "--output",
        "-o",
        metavar="DIR",
        help="Folder to write the tower and blade files with the computed polynomials into "
        "(never over the deck's own).",
    ),
]
ShapesRpm = Annotated[
    float | None,
    _option(
        min=0.0,
        metavar="RPM",
        help="Rotor speed [rpm] of the blade shapes (default: the highest steady speed).",
    ),
]


@app.command("shapes", cls=_Command)
@_user_errors
def shapes_command(
    deck: ShapesDeck,
    output: ShapesOutput = None,
    rpm: ShapesRpm = None,
    format: FormatOption = Format.text,
    no_plots: NoPlotsOption = False,
    force: ForceOption = False,
    help_all: HelpAllOption = False,
    debug: DebugOption = False,
) -> int:
    """ElastoDyn's mode-shape polynomials: computed from the deck's tower and blade, the
    deck's own audited, corrected files written with -o."""
    from . import importers
    from .workflows.convert import shapes

    if importers.kind(deck) != "elastodyn":
        raise typer.BadParameter(
            f"{deck} is not an ElastoDyn deck: shapes takes an ElastoDyn main file or the .fst "
            f"that names it"
        )
    json_out = format is Format.json
    return shapes(deck, output=output, rpm=rpm, json=json_out, plots=not no_plots, force=force)


@app.command("catalogue", cls=_Command)
@_user_errors
def catalogue_command(
    copy: Annotated[
        Path | None,
        _option("--copy", metavar="DIR", help="Write the catalogue's specs into DIR, to edit."),
    ] = None,
    force: ForceOption = False,
    format: FormatOption = Format.text,
    help_all: HelpAllOption = False,
) -> int:
    """List the turbines that ship with wtvib (check one by its name: wtvib check mod-2)."""
    from .workflows.catalogue import listing

    return listing(copy=copy, force=force, json_out=format is Format.json)


@app.command(cls=_Command)
@_user_errors
def schema(
    report: Annotated[
        bool, _option("--report", help="The report's schema (wtvib-report/1) instead.")
    ] = False,
    help_all: HelpAllOption = False,
) -> int:
    """Print the JSON Schema of the turbine spec, or of the JSON report (--report)."""
    from .workflows.contract import schema

    return schema(report)


def main() -> None:
    """Console entry point: the standard streams made safe first (:mod:`wtvib.outputs.streams`),
    and what is still buffered for the output flushed here, where a full disk is one line
    and exit 2 rather than Python's "Exception ignored" at exit."""
    from .outputs import streams

    streams.guard()
    ui.reuse_freed_memory()
    try:
        app()
        code: object = 0
    except SystemExit as exc:
        code = exc.code
    try:
        sys.stdout.flush()
    except OSError as exc:
        lost = streams.lost_output(exc) or str(exc)
        streams.discard_stdout()
        print(f"error: {lost}", file=sys.stderr)
        code = EXIT_INPUT
    raise SystemExit(code)
