"""The command line: thin — load, call one library function, render, exit with a code.

Exit codes: 0 pass or warn, 1 fail (or warn with ``--strict``), 2 bad input or output,
3 internal error (an exception wtvib did not expect: a bug, never a verdict). Errors are
caught in one place (:func:`_user_errors`); a traceback only with ``--debug``.
"""

import contextlib
import functools
import inspect
import json
import math
import os
import sys
import warnings
from collections.abc import Callable, Iterator
from enum import StrEnum
from pathlib import Path
from typing import Annotated, Any, TypeVar

import click
import typer

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

EXIT_PASS, EXIT_FAIL, EXIT_INPUT, EXIT_INTERNAL = 0, 1, 2, 3


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


RpmOption = Annotated[
    str | None,
    typer.Option(
        metavar="MIN:MAX",
        help="Operating range [rpm] (or one fixed speed) for imports that do not give it.",
    ),
]
RatedOption = Annotated[
    float | None, typer.Option(metavar="RPM", hidden=True, help="Rated speed [rpm].")
]
HeadMassOption = Annotated[
    float | None,
    typer.Option(
        metavar="KG",
        hidden=True,
        help="Tower-head mass [kg] for windIO files (1.x hold no hub/nacelle).",
    ),
]
ClampedOption = Annotated[
    bool,
    typer.Option(
        "--clamped-base",
        hidden=True,
        help="Audit a floating turbine's tower (windIO file or OpenFAST deck set) as if "
        "clamped at its base (said in the report's headline; platform and moorings are not "
        "modelled).",
    ),
]
DeckDofsOption = Annotated[
    bool,
    typer.Option(
        "--deck-dofs",
        hidden=True,
        help="Model an OpenFAST deck with its degrees of freedom as it switches them "
        "(FlapDOF1 … PtfmYDOF, as OpenFAST models it); by default every mode of the "
        "structure is audited and the switches said.",
    ),
]
SoilOption = Annotated[
    Path | None,
    typer.Option(
        metavar="FILE",
        hidden=True,
        help="Soil profile (YAML: soil layers, bounds) for a windIO monopile.",
    ),
]
BladesOption = Annotated[
    int | None,
    typer.Option(
        min=1,
        max=10,
        metavar="N",
        hidden=True,
        help="Number of blades, for Campbell results that do not say.",
    ),
]
MarginOption = Annotated[
    float | None, typer.Option(metavar="M", help="Margin, e.g. 0.05 (overrides the spec).")
]
RuleOption = Annotated[
    RuleKind | None, typer.Option(hidden=True, help="Margin rule (overrides the spec).")
]
PresetOption = Annotated[PresetName | None, typer.Option(help="Code preset for rule and margin.")]
DebugOption = Annotated[
    bool, typer.Option("--debug", hidden=True, help="Show tracebacks for errors.")
]
ForceOption = Annotated[
    bool,
    typer.Option(
        "--force", hidden=True, help="Replace existing output files not written by wtvib."
    ),
]
FormatOption = Annotated[Format, typer.Option("--format", "-f", help="Output format.")]
NoPlotsOption = Annotated[bool, typer.Option("--no-plots", help="Write no figures.")]
StrictOption = Annotated[bool, typer.Option("--strict", help="Exit 1 on warn as well as fail.")]
HelpAllOption = Annotated[
    bool,
    typer.Option(
        "--help-all",
        is_eager=True,
        expose_value=False,
        callback=_help_all,
        help="Show every option (import, rule, figure and study options too).",
    ),
]


def _study(uncertainty: bool, samples: int | None, seed: int | None) -> tuple[int, int]:
    """--samples and --seed, which only an --uncertainty run uses (said where given
    without it), with their defaults."""
    for value, name in ((samples, "--samples"), (seed, "--seed")):
        if value is not None and not uncertainty:
            raise typer.BadParameter(f"{name} applies to --uncertainty", param_hint=name)
    return (2000 if samples is None else samples), (0 if seed is None else seed)


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
) -> "batch.Options":  # type: ignore[name-defined]  # noqa: F821
    from .importers import ReadOptions
    from .workflows.batch import Options

    read = ReadOptions(
        rpm=_rpm_range(rpm),
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


F = TypeVar("F", bound=Callable[..., None])


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
    """Give a command the shared run options (RUN_OPTIONS) as one ``options`` argument.

    typer reads a command's parameters from its signature; this rewrites the signature so
    that the shared options are declared once, here, instead of in every command.
    """
    sig = inspect.signature(command)
    own = [p for name, p in sig.parameters.items() if name != "options"]
    extra = [
        inspect.Parameter(name, inspect.Parameter.KEYWORD_ONLY, default=default, annotation=kind)
        for name, kind, default in RUN_OPTIONS
    ]
    debug = [p for p in own if p.name == "debug"]
    rest = [p.replace(kind=inspect.Parameter.KEYWORD_ONLY) for p in own if p.name != "debug"]

    @functools.wraps(command)
    def wrapper(*args: object, **kwargs: Any) -> None:
        kwargs.pop("help_all", None)  # not exposed: its callback prints the help and exits
        if isinstance(kwargs.get("spec_file"), Path):  # a typo answered before the imports
            kwargs["spec_file"] = _input(kwargs["spec_file"])
        shared = [kwargs.pop(name) for name, _, _ in RUN_OPTIONS if name != "help_all"]
        command(*args, options=_options(*shared), **kwargs)

    wrapper.__signature__ = sig.replace(parameters=[*rest, *extra, *debug])  # type: ignore[attr-defined]
    wrapper.__annotations__ = {
        **{k: v for k, v in command.__annotations__.items() if k != "options"},
        **{name: kind for name, kind, _ in RUN_OPTIONS},
    }
    return wrapper  # type: ignore[return-value]


_state = {"debug": False}


def _shown(text: object) -> str:
    from .outputs.streams import shown

    return shown(text)


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
    """Turn a wtvib error into one line on stderr and exit code 2, and any other exception
    into one line naming the input and the exception with exit code 3 — never exit 1, the
    code of a FAIL verdict (tracebacks with --debug)."""

    @functools.wraps(command)
    def wrapper(*args: object, **kwargs: object) -> None:
        from .errors import WtvibError

        debug = _state["debug"] or kwargs.get("debug")
        try:
            with warnings.catch_warnings():
                if not debug:  # numpy's overflow notes on hostile numbers: the error or
                    # warning line the model raises says it, without the source lines
                    warnings.simplefilter("ignore", RuntimeWarning)
                command(*args, **kwargs)
        except WtvibError as exc:
            if debug:
                raise
            text = str(exc)
            source = kwargs.get("spec_file")
            modal = sys.modules.get("wtvib.numerics.modal")  # not imported for a typo's error
            if source is not None and modal is not None and isinstance(exc, modal.ModalError):
                text = f"{source}: {text}"  # a model that cannot be solved: which input
            typer.echo(f"error: {_shown(text)}", err=True)
            raise typer.Exit(EXIT_INPUT) from None
        except _PASS_THROUGH:
            raise  # typer reports a usage error itself (one line, exit 2)
        except OSError as exc:  # the environment's fault: a full disk, a closed pipe
            if debug:
                raise
            _environment_fault(exc, kwargs)
        except Exception as exc:  # the last line of defence
            if debug:
                raise
            from .workflows.batch import internal_message

            source = next(
                (str(kwargs[k]) for k in ("spec_file", "source", "inputs") if k in kwargs),
                "wtvib",
            )
            typer.echo(f"error: {_shown(internal_message(source, exc))}", err=True)
            raise typer.Exit(EXIT_INTERNAL) from None

    return wrapper  # type: ignore[return-value]


def _environment_fault(exc: OSError, kwargs: dict[str, object]) -> None:
    """An operating-system error as one line and exit 2: the standard output that could
    not take the report, or the file named in the error; an OSError naming no file and not
    about the output stays a wtvib bug (exit 3)."""
    from .outputs import streams
    from .workflows.batch import internal_message

    lost = streams.lost_output(exc)
    if lost is not None:
        streams.discard_stdout()
        typer.echo(f"error: {lost}", err=True)
        raise typer.Exit(EXIT_INPUT) from None
    if exc.filename is not None:
        reason = exc.strerror or type(exc).__name__
        typer.echo(f"error: {streams.shown(exc.filename)}: {reason}", err=True)
        raise typer.Exit(EXIT_INPUT) from None
    source = next(
        (str(kwargs[k]) for k in ("spec_file", "source", "inputs") if k in kwargs), "wtvib"
    )
    typer.echo(f"error: {_shown(internal_message(source, exc))}", err=True)
    raise typer.Exit(EXIT_INTERNAL) from None


def _version(value: bool) -> None:
    if value:
        from . import __version__

        typer.echo(f"wtvib {__version__}")
        raise typer.Exit(EXIT_PASS)


@app.callback()
def _root(
    debug: Annotated[bool, typer.Option("--debug", help="Show tracebacks for errors.")] = False,
    version: Annotated[
        bool,
        typer.Option("--version", callback=_version, is_eager=True, help="Print the version."),
    ] = False,
) -> None:
    _state["debug"] = debug


#: What a turbine file may be (wtvib.importers.load tells them apart).
SPEC_HELP = (
    "Turbine file: a wtvib spec, a windIO turbine YAML, an OpenFAST deck (.fst or ElastoDyn "
    ".dat), or another tool's Campbell results (.cmb, .csv, .lin, a linearisation folder)."
)


@app.command(cls=_Command)
@_user_errors
@_run_options
def check(
    spec_file: Annotated[Path, typer.Argument(metavar="FILE", help=SPEC_HELP)],
    format: FormatOption = Format.text,
    out: Annotated[
        Path | None,
        typer.Option(
            "--out-dir",
            "-d",
            metavar="DIR",
            help="Folder for the figures (default: the current directory).",
        ),
    ] = None,
    no_plots: NoPlotsOption = False,
    detail: Annotated[
        bool, typer.Option("--detail", help="Print the tables of modes and checks too.")
    ] = False,
    strict: StrictOption = False,
    campbell_csv: Annotated[
        Path | None,
        typer.Option(
            "--campbell-csv",
            metavar="FILE",
            help="Write the Campbell data (frequency and damping of every judged "
            "mode per operating point) as CSV.",
        ),
    ] = None,
    force: ForceOption = False,
    show_all: Annotated[
        bool, typer.Option("--all", hidden=True, help="Show passing minor checks too.")
    ] = False,
    figures: Annotated[
        Figures,
        typer.Option(
            hidden=True,
            help="main: the Campbell diagrams and damping; all: the detail figures too.",
        ),
    ] = Figures.main,
    uncertainty: Annotated[
        bool,
        typer.Option(
            "--uncertainty", hidden=True, help="Propagate the spec's tolerances (Monte Carlo)."
        ),
    ] = False,
    samples: Annotated[
        int | None,
        typer.Option(
            min=10,
            max=MAX_SAMPLES,
            metavar="N",
            hidden=True,
            help="Monte Carlo samples (2,000); needs --uncertainty.",
        ),
    ] = None,
    seed: Annotated[
        int | None,
        typer.Option(
            min=0, metavar="N", hidden=True, help="Seed of the sampling (0); needs --uncertainty."
        ),
    ] = None,
    scheduler: Annotated[
        str | None,
        typer.Option(
            metavar="ADDRESS",
            hidden=True,
            help="Sample on a Dask scheduler (tcp://host:8786); needs --uncertainty.",
        ),
    ] = None,
    *,
    options: "batch.Options",  # type: ignore[name-defined]  # noqa: F821
    debug: DebugOption = False,
) -> None:
    """Audit one turbine: modes against excitations, tower class, verdict, Campbell PNGs."""
    from .outputs.files import campbell_to_csv, write_atomic

    if scheduler is not None and not uncertainty:
        raise typer.BadParameter("--scheduler applies to --uncertainty", param_hint="--scheduler")
    samples, seed = _study(uncertainty, samples, seed)
    if campbell_csv is not None:
        from .outputs.files import folder_exists

        folder_exists(campbell_csv)
    plot = not no_plots
    written: list[Path] = []
    # the input read first: a mistake in it is answered before the models are imported
    turbine = options.load(spec_file)
    settings = options.settings(turbine)
    from . import audit
    from .outputs.plots.render import Drawer

    with Drawer(enabled=plot) as drawer:  # imports matplotlib beside the audit
        doing = f"auditing, {samples:,} Monte Carlo samples" if uncertainty else "auditing"
        with _cluster(scheduler) as client, _working(doing):
            report = audit.run(
                turbine,
                settings,
                samples=samples if uncertainty else None,
                seed=seed,
                client=client,
            )
        if plot:
            drawer.send(report, detail=figures is Figures.all)  # drawn while the text renders
        # the report rendered while the figures draw, printed once they are written (a
        # file that may not be replaced stops the check before anything is printed)
        console, text = _rendered(report, format, show_all=show_all, detail=detail)
        if plot:
            folder = out if out is not None else Path.cwd()  # never beside the input
            with _working("drawing the figures"):
                pngs = drawer.pngs(report, detail=figures is Figures.all)
            for suffix, png in pngs.items():
                path = folder / f"{spec_file.stem}{options.tag(uncertainty)}.{suffix}.png"
                written.append(write_atomic(path, png, force=force, folder=True))
    if campbell_csv is not None:
        data = campbell_to_csv(report.campbell, report.identity).encode()
        written.append(write_atomic(campbell_csv, data, force=force))
    sys.stdout.write(text)
    if console is None:
        for path in written:
            typer.echo(f"wrote {_shown(path)}", err=True)
    else:
        from .outputs.report import wrote

        sys.stdout.flush()
        wrote(console, written)
    for warning in report.warnings:
        typer.echo(f"warning: {_shown(warning)}", err=True)
    failing = report.verdict == "fail" or (strict and report.verdict == "warn")
    raise typer.Exit(EXIT_FAIL if failing else EXIT_PASS)


def _rendered(report: Any, format: Format, *, show_all: bool, detail: bool) -> "tuple[Any, str]":
    """The report as the text ``check`` prints: JSON (no console), or the terminal report
    captured from the console it is then printed beside (the files written)."""
    if format is Format.json:
        from .outputs.report import to_json

        return None, to_json(report)

    from .outputs.report import terminal

    console = _console()
    with console.capture() as captured:
        terminal(report, console, show_all=show_all, detail=detail or show_all)
    return console, captured.get()


@app.command(cls=_Command)
@_user_errors
@_run_options
def report(
    spec_file: Annotated[Path, typer.Argument(metavar="FILE", help=SPEC_HELP)],
    output: Annotated[
        Path, typer.Option("--output", "-o", metavar="FILE", help="PDF file to write.")
    ],
    force: ForceOption = False,
    uncertainty: Annotated[
        bool,
        typer.Option(
            "--uncertainty",
            hidden=True,
            help="Propagate the spec's tolerances (Monte Carlo) and report them.",
        ),
    ] = False,
    samples: Annotated[
        int | None,
        typer.Option(
            min=10,
            max=MAX_SAMPLES,
            metavar="N",
            hidden=True,
            help="Monte Carlo samples (2,000); needs --uncertainty.",
        ),
    ] = None,
    seed: Annotated[
        int | None,
        typer.Option(
            min=0, metavar="N", hidden=True, help="Seed of the sampling (0); needs --uncertainty."
        ),
    ] = None,
    *,
    options: "batch.Options",  # type: ignore[name-defined]  # noqa: F821
    debug: DebugOption = False,
) -> None:
    """Write the PDF audit report of one turbine."""
    import dataclasses

    from . import audit
    from .outputs import pdfreport  # audit: the models imported before the fork
    from .workflows import batch

    samples, seed = _study(uncertainty, samples, seed)
    if uncertainty:
        options = dataclasses.replace(options, samples=samples, seed=seed)
    from .outputs.files import folder_exists

    folder_exists(output)  # before the audit, not after it
    from .outputs.files import write_atomic
    from .outputs.plots.render import Drawer

    # every figure, drawn beside the audit as check draws its own (plots.render); forked
    # before the spinner's thread starts (a fork copies no thread, but a lock one holds)
    with Drawer() as drawer, _working("auditing and drawing the figures"):

        def draw(report: "audit.Report") -> dict[str, bytes]:
            return drawer.pngs(report, detail=True)

        if debug or _state["debug"]:
            item = batch._audit_one(str(spec_file), spec_file.stem, True, options, draw)
        else:
            item = batch.audit_one(str(spec_file), spec_file.stem, True, options, draw)
    if item.report is None:
        typer.echo(f"error: {_shown(item.error)}", err=True)
        raise typer.Exit(EXIT_INTERNAL if item.internal else EXIT_INPUT)
    with _working(f"writing {output.name}"):
        pdf = pdfreport.build([(item.report, item.pngs)])
    write_atomic(output, pdf, force=force)
    typer.echo(f"wrote {_shown(output)} (verdict {item.report['verdict']})")
    raise typer.Exit(EXIT_FAIL if item.report["verdict"] == "fail" else EXIT_PASS)


@app.command("batch", cls=_Command)
@_user_errors
@_run_options
def batch_command(
    inputs: Annotated[
        list[Path], typer.Argument(metavar="FILE|FOLDER...", help="Spec files or folders.")
    ],
    out: Annotated[
        Path | None,
        typer.Option(
            "--out-dir", "-d", metavar="DIR", help="Folder for the JSON, CSV, PNG and PDF files."
        ),
    ] = None,
    format: FormatOption = Format.text,
    jobs: Annotated[
        int | None,
        typer.Option("--jobs", "-j", min=1, metavar="N", help="Processes (default: all cores)."),
    ] = None,
    no_plots: Annotated[
        bool, typer.Option("--no-plots", help="Write no figures and no PDF report.")
    ] = False,
    sort: Annotated[SortBy, typer.Option(help="Order of the summary table.")] = SortBy.file,
    strict: StrictOption = False,
    scheduler: Annotated[
        str | None,
        typer.Option(
            metavar="ADDRESS",
            hidden=True,
            help="Audit on a Dask scheduler's workers (tcp://host:8786), not locally.",
        ),
    ] = None,
    force: ForceOption = False,
    *,
    options: "batch.Options",  # type: ignore[name-defined]  # noqa: F821
    debug: DebugOption = False,
) -> None:
    """Audit a catalogue: every spec found, in parallel, with a summary and reports.

    The operating and rule options apply to every input."""

    from .outputs.report import batch_progress, batch_summary
    from .workflows import batch

    plots = not no_plots
    paths, skipped = batch.discover_all(inputs)
    for where, why in skipped:  # said, never left out in silence
        print(f"skipped {_shown(where)}: {_shown(why)}", file=sys.stderr)
    if not paths:
        from .errors import SpecError

        raise SpecError(f"no spec files ({', '.join(batch.SPEC_SUFFIXES)}) found in the inputs")
    err = _console(stderr=True)
    lock = batch.FolderLock(out) if out is not None else None
    writer = _BatchWriter(out, force) if out is not None else None
    if writer is not None:
        writer.skipped = skipped
    done: list[batch.Item] = []
    with (
        lock or contextlib.nullcontext(),
        _cluster(scheduler) as client,
        batch.terminate_as_interrupt() as stopped,
    ):
        executor = client.get_executor() if client is not None else None
        with batch_progress(err, len(paths)) as advance:

            def on_done(item: batch.Item) -> None:
                if writer is not None:
                    writer.item(item)
                done.append(item)
                advance(item)

            try:
                items = batch.run(
                    paths,
                    jobs=jobs,
                    plots=plots,
                    on_done=on_done,
                    options=options,
                    executor=executor,
                    alive=_alive(client),
                )
                if writer is not None:  # a turbine whose files could not be written
                    items = writer.failed(items)
            except KeyboardInterrupt:
                if writer is not None:  # the summaries of what was completed
                    writer.finish(done, plots=False, interrupted=True)
                err.print(
                    f"interrupted: {len(done)} of {len(paths)} inputs completed; their files "
                    "and the summaries of them are written, nothing is half-written"
                )
                raise typer.Exit(143 if stopped() else 130) from None
        if writer is not None:
            writer.finish(items, plots)
    if format is Format.json:
        sys.stdout.write(batch.results_json(items))
    else:
        batch_summary(
            _console(), batch.sort_items(items, sort.value), writer.written if writer else []
        )
    raise typer.Exit(batch.exit_code(items, strict))


@contextlib.contextmanager
def _working(what: str) -> Iterator[None]:
    """A spinner saying ``what`` on stderr while a step runs — on a terminal only (rich is
    not imported otherwise), and gone after."""
    if not sys.stderr.isatty():
        yield
        return

    with _console(stderr=True).status(what, spinner="line"):
        yield


def _alive(client: Any) -> Any:
    """Whether the cluster still has a worker (None: a local run, always alive)."""
    if client is None:
        return None
    from .studies.cluster import has_workers

    return lambda: has_workers(client)


@contextlib.contextmanager
def _cluster(address: str | None) -> Iterator[Any]:
    """A Dask client on ``address`` for the command's duration (None: run locally)."""
    if address is None:
        yield None
        return
    from .studies.cluster import close, connect

    client = connect(address)
    try:
        yield client
    finally:
        close(client)


class _BatchWriter:
    """Writes a batch's files atomically as results arrive, then the summaries."""

    def __init__(self, folder: Path, force: bool) -> None:
        self.folder = folder
        self.force = force
        self.written: list[Path] = []
        self.timings: dict[str, dict[str, float]] = {}
        self.unwritten: dict[str, str] = {}  # item key → why its files were not written
        self.pdf_error: str | None = None
        self.skipped: list[tuple[str, str]] = []  # inputs left out, and why

    def _write(self, name: str, data: bytes) -> None:
        import time

        from .outputs.files import write_atomic

        t0 = time.perf_counter()
        self.written.append(write_atomic(self.folder / name, data, force=self.force, folder=True))
        key = name.split(".")[0]
        self.timings.setdefault(key, {}).setdefault("write", 0.0)
        self.timings[key]["write"] += time.perf_counter() - t0

    def item(self, item: "batch.Item") -> None:  # type: ignore[name-defined]  # noqa: F821
        """The item's files; one that cannot be written (a name too long for the file
        system, a full disk) fails that item alone: the others and the summaries go on."""
        from .errors import OutputError

        try:
            self._item(item)
        except OutputError as exc:
            self.unwritten[item.key] = str(exc)

    def failed(self, items: list) -> list:  # type: ignore[type-arg]
        """The items with those whose files could not be written turned into errors."""
        import dataclasses

        return [
            dataclasses.replace(
                it, report=None, pngs={}, campbell_csv=None,
                error=f"audited, but its files could not be written: {self.unwritten[it.key]}",
            )
            if it.key in self.unwritten
            else it
            for it in items
        ]  # fmt: skip

    def _item(self, item: "batch.Item") -> None:  # type: ignore[name-defined]  # noqa: F821
        if item.report is not None:
            text = json.dumps(item.report, indent=2, ensure_ascii=False, allow_nan=False) + "\n"
            self._write(f"{item.key}.json", _utf8(text))
        if item.campbell_csv is not None:
            self._write(f"{item.key}.campbell.csv", _utf8(item.campbell_csv))
        for suffix, png in item.pngs.items():
            self._write(f"{item.key}.{suffix}.png", png)
        self.timings.setdefault(item.key, {}).update(item.timings)

    def finish(self, items: list, plots: bool, interrupted: bool = False) -> None:  # type: ignore[type-arg]
        import platform

        from . import __version__
        from .outputs import pdfreport
        from .workflows import batch

        summary = json.dumps(batch.summary(items), indent=2, ensure_ascii=False) + "\n"
        self._write("summary.json", _utf8(summary))
        self._write("summary.csv", _utf8(batch.summary_csv(items)))
        if plots:
            import time

            entries = [(it.report, it.pngs) for it in items if it.report is not None]
            errors = [(it.path, str(it.error), it.outcome) for it in items if it.report is None]
            t0 = time.perf_counter()
            try:
                with _working(f"writing audit.pdf ({len(entries)} turbines)"):
                    pdf = pdfreport.build(entries, errors=errors)
            except Exception as exc:  # the PDF is lost, not the run's other files
                self.pdf_error = f"audit.pdf could not be laid out ({type(exc).__name__})"

                _console(stderr=True).print(
                    f"warning: {self.pdf_error}; the other files are written"
                )
            else:
                self.timings["audit"] = {"build": time.perf_counter() - t0}
                self._write("audit.pdf", pdf)
        meta = {
            "schema": "wtvib-run/1",
            "wtvib": __version__,
            "python": platform.python_version(),
            "machine": platform.machine(),
            "timings_s": self.timings,
            **({"interrupted": True} if interrupted else {}),
            **({"audit_pdf": self.pdf_error} if self.pdf_error else {}),
            **({"unwritten": self.unwritten} if self.unwritten else {}),
            **(
                {"skipped": [{"file": f, "why": w} for f, w in self.skipped]}
                if self.skipped
                else {}
            ),
        }
        self._write("run-metadata.json", _utf8(json.dumps(meta, indent=2) + "\n"))


def _utf8(text: str) -> bytes:
    """Text as UTF-8, a file name that is not (a byte Python keeps as a lone surrogate)
    written as its escape — still valid JSON, where it sits inside a string."""
    return text.encode("utf-8", errors="backslashreplace")


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
    spec_file: Annotated[Path, typer.Argument(metavar="FILE", help=SPEC_HELP)],
    format: FormatOption = Format.text,
    out: Annotated[
        Path | None,
        typer.Option(
            "--out-dir",
            "-d",
            metavar="DIR",
            help="Folder for the figure (default: the current directory).",
        ),
    ] = None,
    no_plots: NoPlotsOption = False,
    force: ForceOption = False,
    *,
    options: "batch.Options",  # type: ignore[name-defined]  # noqa: F821
    debug: DebugOption = False,
) -> None:
    """Allowed frequency windows per subsystem, and where the design sits in them."""
    from . import audit
    from .studies import design

    turbine = options.load(spec_file)
    report = audit.run(turbine, options.settings(turbine))
    found = design.all_windows(report)
    doc = design.windows_document(turbine, found, report.rule)
    if format is Format.json:
        sys.stdout.write(json.dumps(doc, indent=2, ensure_ascii=False) + "\n")
    else:
        from .outputs.report import windows_table

        windows_table(_console(), doc)
    if not no_plots:
        from .outputs.files import write_atomic
        from .outputs.plots import png_bytes
        from .outputs.plots.campbell import windows_plot

        tw = design.tower_windows(found)
        tower_w = tw.allowed if tw is not None else ()
        folder = out if out is not None else Path.cwd()  # never beside the input
        path = write_atomic(
            folder / f"{spec_file.stem}.windows.png",
            png_bytes(windows_plot(report, tower_w)),
            force=force,
            folder=True,
        )
        typer.echo(f"wrote {_shown(path)}", err=format is Format.json)


@app.command("size", cls=_Command)
@_user_errors
@_run_options
def size_command(
    spec_file: Annotated[
        Path, typer.Argument(metavar="FILE", help="Turbine spec with tower sections.")
    ],
    target: Annotated[Target | None, typer.Option(help="Window to land in (its middle).")] = None,
    target_hz: Annotated[
        float | None,
        typer.Option(min=0.0, metavar="HZ", help="Or a first bending frequency [Hz]."),
    ] = None,
    scale: Annotated[ScaleWhat, typer.Option(help="What to scale.")] = ScaleWhat.wall,
    format: FormatOption = Format.text,
    *,
    options: "batch.Options",  # type: ignore[name-defined]  # noqa: F821
    debug: DebugOption = False,
) -> None:
    """Scale the tower's wall (or diameter, or both) to put its first bending in a window
    (the windows of `window` under the same operating and rule options)."""
    from . import audit
    from .studies import design

    turbine = options.load(spec_file)
    if (target is None) == (target_hz is None):
        raise typer.BadParameter("give --target WINDOW or --target-hz HZ")
    design.require_sections(turbine)
    goal = target_hz
    if target is not None:
        report = audit.run(turbine, options.settings(turbine))
        found = design.all_windows(report)
        goal = design.window_goal(found, target.value)
    assert goal is not None
    result = design.size(turbine, goal, scale.value)  # type: ignore[arg-type]
    doc = {"schema": design.SIZE_SCHEMA, "turbine": turbine.turbine.name, **result.to_dict()}
    if format is Format.json:
        sys.stdout.write(json.dumps(doc, indent=2, ensure_ascii=False) + "\n")
        return
    typer.echo(
        f"{turbine.turbine.name}: scale the tower {scale.value} by {result.scale:.4f} → first "
        f"bending {result.frequency_hz:.4f} Hz (target {goal:.4f} Hz); tower mass "
        f"{result.mass_before_kg:,.0f} → {result.mass_after_kg:,.0f} kg "
        f"({doc['mass_change_percent']:+.1f} %)"
    )
    for line in result.warnings:
        typer.echo(f"warning: {_shown(line)}", err=True)


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


@app.command(cls=_Command)
@_user_errors
def convert(
    source: Annotated[
        Path,
        typer.Argument(
            metavar="FILE",
            help="windIO YAML, OpenFAST deck (.fst or ElastoDyn .dat) or Campbell results "
            "to convert.",
        ),
    ],
    output: Annotated[
        Path, typer.Option("--output", "-o", metavar="FILE", help="wtvib spec to write.")
    ],
    rpm: Annotated[
        str | None,
        typer.Option(metavar="MIN:MAX", help="Operating range [rpm] to put in the spec."),
    ] = None,
    rated: Annotated[
        float | None, typer.Option(metavar="RPM", help="Rated speed [rpm] to put in the spec.")
    ] = None,
    head_mass: Annotated[
        float | None,
        typer.Option(
            metavar="KG",
            help="Tower-head mass [kg] to put in the spec (windIO files: 1.x hold no hub/nacelle).",
        ),
    ] = None,
    clamped_base: Annotated[
        bool,
        typer.Option(
            "--clamped-base",
            help="Convert a floating turbine's tower (windIO file or OpenFAST deck set) as "
            "clamped at its base (the spec's assumptions say so; platform and moorings are "
            "not converted).",
        ),
    ] = False,
    soil: SoilOption = None,
    force: Annotated[bool, typer.Option("--force", help="Replace an existing file.")] = False,
    help_all: HelpAllOption = False,
    debug: DebugOption = False,
) -> None:
    """Write an imported turbine as an editable wtvib spec (validated before writing)."""
    import yaml

    from . import importers
    from .outputs.files import converted_spec, write_atomic
    from .spec import from_data

    read = importers.ReadOptions(
        rpm=_rpm_range(rpm),
        rated=rated,
        head_mass=head_mass,
        clamped_base=clamped_base,
        soil=soil,
    )
    data = _plain(importers.to_data(source, read))
    from_data(data, source=str(source))  # refuse to write a spec that would not load
    body = yaml.safe_dump(
        data, sort_keys=False, allow_unicode=True, width=100, default_flow_style=None
    )  # a list of numbers on one line: a table, not a column
    # a spec convert wrote is replaced while unedited; an edited one, or any other file,
    # only with --force (and never an input of this run)
    write_atomic(output, converted_spec(source.name, body), force=force)
    typer.echo(f"wrote {_shown(output)}")


def _plain(node: Any) -> Any:
    """Spec data as YAML writes it: numpy's numbers and arrays (an importer's arithmetic
    leaves them: a floating platform's masses) as Python's."""
    if isinstance(node, dict):
        return {k: _plain(v) for k, v in node.items()}
    if isinstance(node, list | tuple):
        return [_plain(v) for v in node]
    tolist = getattr(node, "tolist", None)  # a numpy scalar or array
    return _plain(tolist()) if callable(tolist) and not isinstance(node, str) else node


@app.command("shapes", cls=_Command)
@_user_errors
def shapes_command(
    deck: Annotated[
        Path,
        typer.Argument(
            metavar="DECK", help="ElastoDyn main file (.dat), or the OpenFAST .fst that names it."
        ),
    ],
    output: Annotated[
        Path | None,
        typer.Option(
            "--output",
            "-o",
            metavar="DIR",
            help="Folder to write the tower and blade files with the computed polynomials "
            "into (never over the deck's own).",
        ),
    ] = None,
    rpm: Annotated[
        float | None,
        typer.Option(
            min=0.0,
            metavar="RPM",
            help="Rotor speed [rpm] of the blade shapes (default: the highest steady speed).",
        ),
    ] = None,
    format: FormatOption = Format.text,
    no_plots: NoPlotsOption = False,
    force: ForceOption = False,
    help_all: HelpAllOption = False,
    debug: DebugOption = False,
) -> None:
    """ElastoDyn's mode-shape polynomials: computed from the deck's tower and blade, the
    deck's own audited, corrected files written with -o."""
    from . import importers
    from .errors import OutputError
    from .outputs.files import write_atomic
    from .subsystems import polynomials

    if importers.kind(deck) != "elastodyn":
        raise typer.BadParameter(
            f"{deck} is not an ElastoDyn deck: shapes takes an ElastoDyn main file or the .fst "
            "that names it"
        )
    speed = (rpm, rpm) if rpm is not None and rpm > 0 else None
    spec = importers.load(deck, importers.ReadOptions(rpm=speed))
    result = polynomials.compute(spec, rpm)
    written: list[str] = []
    if output is not None:
        files = polynomials.corrected(result)
        targets = {original: output / Path(original).name for original in files}
        for original, target in targets.items():  # all refused before any is written
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
        for original, text in files.items():
            write_atomic(targets[original], text.encode("utf-8"), force=force, folder=True)
            written.append(str(targets[original]))
    if not no_plots:
        from .outputs.plots import png_bytes
        from .outputs.plots.polynomials import polynomials_plot

        folder = output if output is not None else Path.cwd()
        path = write_atomic(
            folder / f"{deck.stem}.shapes.png",
            png_bytes(polynomials_plot(result, spec)),
            force=force,
            folder=True,
        )
        written.append(str(path))
    doc = polynomials.document(spec, result, written)
    if format is Format.json:
        sys.stdout.write(json.dumps(doc, indent=2, ensure_ascii=False) + "\n")
        return

    from .outputs.report import shapes_table

    shapes_table(_console(), doc)


@app.command("catalogue", cls=_Command)
@_user_errors
def catalogue_command(
    copy: Annotated[
        Path | None,
        typer.Option(
            "--copy", metavar="DIR", help="Write the catalogue's specs into DIR, to edit."
        ),
    ] = None,
    force: ForceOption = False,
    format: FormatOption = Format.text,
    help_all: HelpAllOption = False,
) -> None:
    """List the turbines that ship with wtvib (check one by its name: wtvib check mod-2)."""
    from .workflows import catalogue

    entries = catalogue.entries()
    if copy is not None:
        from .errors import OutputError
        from .outputs.files import write_atomic

        def differs(path: Path) -> bool:  # a file there that is not the catalogue's own
            target = copy / path.name
            return target.exists() and (
                not target.is_file() or target.read_bytes() != path.read_bytes()
            )

        edited = [p for p in catalogue.files() if differs(p)]
        if edited and not force:  # checked before any is written: all or none
            raise OutputError(
                f"{copy / edited[0].name} exists"
                + (f" (and {len(edited) - 1} more)" if len(edited) > 1 else "")
                + " and differs from the catalogue's; use --force to replace"
            )
        for path in catalogue.files():
            write_atomic(copy / path.name, path.read_bytes(), force=True, folder=True)
        typer.echo(f"copied {len(entries)} turbine specs to {_shown(copy)}")
        return
    if format is Format.json:
        import dataclasses

        doc = {"schema": "wtvib-catalogue/1", "turbines": [dataclasses.asdict(e) for e in entries]}
        sys.stdout.write(json.dumps(doc, indent=2, ensure_ascii=False) + "\n")
        return

    from .outputs.report import catalogue_table

    catalogue_table(_console(), entries, catalogue.FOLDER)


def _console(stderr: bool = False) -> Any:
    """A rich console that does not hard-wrap text where it is not a terminal (a pipe, a
    file: ``window … | less`` had "74.3%)" alone on a line); tables and panels keep their
    width (COLUMNS where the user sets it)."""
    from rich.console import Console

    stream = sys.stderr if stderr else sys.stdout
    try:
        terminal = stream.isatty()
    except (AttributeError, ValueError):
        terminal = False
    return Console(stderr=stderr, soft_wrap=not terminal)


def _input(path: Path) -> Path:
    """The file a command reads: ``path``, or — where no such file exists and the name is a
    catalogue turbine's (``mod-2``) — the catalogue's spec, said on stderr; a file that is
    neither is one line before any numerical module is imported."""
    if os.path.lexists(path):
        return path
    from .workflows.catalogue import find

    found = find(str(path))
    if found is None:  # said now, not after a second of importing the numerical stack
        from .errors import SpecError

        raise SpecError("no such file", source=str(path))
    typer.echo(f"note: {_shown(path)} is the catalogue's {found.name} ({_shown(found)})", err=True)
    return found


@app.command(cls=_Command)
@_user_errors
def schema(
    report: Annotated[
        bool, typer.Option("--report", help="The report's schema (wtvib-report/1) instead.")
    ] = False,
    help_all: HelpAllOption = False,
) -> None:
    """Print the JSON Schema of the turbine spec, or of the JSON report (--report)."""
    if report:
        from .workflows.contract import report_schema

        doc = report_schema()
    else:
        from .spec import json_schema

        doc = json_schema()
    sys.stdout.write(json.dumps(doc, indent=2, ensure_ascii=False) + "\n")


def main() -> None:
    """Console entry point: the standard streams made safe first (:mod:`wtvib.outputs.streams`),
    and what is still buffered for the output flushed here, where a full disk is one line
    and exit 2 rather than Python's "Exception ignored" at exit."""
    from .outputs import streams

    streams.guard()
    _reuse_freed_memory()
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


def _reuse_freed_memory() -> None:
    """Ask glibc's allocator to serve large blocks from its heap and to keep freed ones for
    the next (``mallopt``: M_MMAP_THRESHOLD 1 GiB, M_TRIM_THRESHOLD 2 GiB) instead of mapping
    fresh pages for each block over 32 MB and unmapping it when freed. A full-system
    linearisation's check allocates dozens of 30–70 MB arrays one after another; where a
    fresh page is dear (the benchmark machine: ~4 ms a megabyte) that was 3 s of 24
    (bench/RESULTS.md). The command's process only — wtvib used as a library leaves the
    allocator alone — and nothing where the C library is not glibc."""
    import ctypes

    try:
        mallopt = ctypes.CDLL(None).mallopt
    except (OSError, AttributeError, TypeError):  # not glibc (macOS, musl; Windows)
        return
    mallopt(-3, 1 << 30)  # M_MMAP_THRESHOLD
    mallopt(-1, (1 << 31) - 1)  # M_TRIM_THRESHOLD (a C int)
