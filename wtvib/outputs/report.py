"""Rendering a report: the terminal view (rich) and the JSON document.

Rendering never decides: everything shown here is read from :class:`~wtvib.audit.Report`.
"""

import json
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from rich import box
from rich.console import Console, Group
from rich.panel import Panel
from rich.table import Table
from rich.text import Text

from ..audit import Report
from ..document import CheckDoc, ModeDoc, ReportDoc, ShareDoc, UncertaintyDoc
from ..results import operating_points
from . import words
from .streams import shown

STYLE = {"pass": "green", "info": "cyan", "warn": "yellow", "fail": "bold red"}


def _t(value: object, style: str = "") -> Text:
    """User text as plain rich Text: no markup parsed ("NREL 5-MW [onshore]" stays whole,
    "[/]" cannot crash), control characters shown as "?" and bidi controls as escapes
    instead of reaching the terminal (:func:`wtvib.outputs.streams.shown`)."""
    return Text(shown(value), style=style)


def to_json(report: Report) -> str:
    """The JSON contract: exactly ``report.to_dict()``, stable key order, trailing newline."""
    return json.dumps(report.to_dict(), indent=2, ensure_ascii=False, allow_nan=False) + "\n"


def terminal(
    report: Report,
    console: Console,
    *,
    written: Sequence[Path] = (),
    show_all: bool = False,
    detail: bool = False,
) -> None:
    """Print the report: the summary panel, every failing, warning and info check in one
    line with its number, then (``detail``) the tables of modes and checks, and the
    assumptions. Ids are never cut."""
    data = report.to_dict()
    aero = report.spec.aerodynamics
    console.print(_summary(data, shed_wake=aero is None or aero.shed_wake))
    console.print(_findings(data["checks"]))
    if detail:
        console.print(_modes(data["modes"]))
        console.print(_checks(data["checks"], show_all))
        hidden = sum(1 for c in data["checks"] if not _shown(c, show_all))
        if hidden:
            console.print(
                f"[dim]{hidden} more checks pass on low-energy harmonics (--all shows them).[/dim]"
            )
        for table in (_blade_stability(data["checks"]), _coupling(data["checks"])):
            if table is not None:
                console.print(table)
    else:
        console.print(
            f"[dim]{len(data['modes'])} modes, {len(data['checks'])} checks: --detail prints "
            "their tables.[/dim]"
        )
    if data.get("uncertainty"):
        console.print(_uncertainty(data["uncertainty"]))
        if detail and data["uncertainty"].get("sensitivities"):
            console.print(_sensitivities(data["uncertainty"]["sensitivities"]))
    console.print(Text("Assumptions", style="bold"))
    for line in data["assumptions"]:
        console.print(_hanging("•", _t(line), width=3))
    wrote(console, written)


def wrote(console: Console, written: Sequence[Path]) -> None:
    """A line for each file written, the report's last lines; a path is never wrapped or
    cut."""
    for path in written:
        console.print(_t(f"wrote {path}", "dim"), soft_wrap=True)


def _summary(data: ReportDoc, shed_wake: bool = True) -> Panel:
    t = data["turbine"]
    op = data["operation"]
    verdict = data["verdict"]
    grid = Table.grid(padding=(0, 2))
    grid.add_column(style="bold")
    grid.add_column(overflow="fold")  # a long path wraps, never ends in "…"
    grid.add_row("Turbine", _t(t["name"]))
    grid.add_row("File", _t(t["source_file"]))
    grid.add_row(
        "Rotor", f"{words.counted(t['blades'], 'blade')}, {t['orientation']}, {t['hub']} hub"
    )
    # numbers for people: four significant digits (the JSON keeps them all)
    grid.add_row("Speed", _t(words.operation(op)))
    grid.add_row("Tower class", str(data["tower_class"] or "—"))
    camp = data.get("campbell", {})
    if data.get("damping") == "aeroelastic" and camp.get("wind_m_s"):
        winds = camp["wind_m_s"]
        lift = f"the {words.lift(shed_wake)}"
        grid.add_row(
            "Damping",
            f"aeroelastic: {operating_points(winds)} (aerodynamic + structural, {lift})",
        )
    elif data.get("damping") == "imported":
        grid.add_row("Damping", f"as computed by {data['results']['tool']} at its operating points")
    else:
        why = (
            "aerodynamics given, but no judged mode has a model to take them (blade mass or "
            "structure; tower mass and tower head)"
            if data.get("aerodynamics")
            else _without_aerodynamics(data["modes"])
        )
        grid.add_row("Damping", Text(f"the ratios given or assumed — {why}", style="yellow"))
    grid.add_row(
        "Rule",
        f"{data['rule']['kind']} margin {data['rule']['margin']:.0%} "
        f"({data['rule']['preset'] or 'custom'})",
    )
    grid.add_row("Verdict", Text(verdict.upper(), style=STYLE[verdict]))
    for line in data.get("warnings", []):  # what the audit had to assume, in the headline
        grid.add_row(Text("Warning", style="yellow"), _t(line, "yellow"))
    return Panel(grid, title="wtvib audit", border_style=STYLE[verdict])


def _without_aerodynamics(modes: list[ModeDoc]) -> str:
    """What an audit without an aerodynamics block says of the modes aerodynamic damping
    acts on (the blades' and the tower's first fore-aft bending, which the rotor's thrust
    damps): judged on a ratio the spec gives them (which may hold it, as a measured one
    does), or without it where their ratio is their subsystem's default."""
    acted = [m for m in modes if m["subsystem"] == "blade" or m["id"] == "tower.fa1"]
    if not acted:
        return "no aerodynamics block (no mode here that aerodynamic damping acts on)"
    own = [m["id"] for m in acted if not m.get("damping_source")]
    rest = [m["id"] for m in acted if m.get("damping_source")]
    parts = []
    if own:
        parts.append(f"{_listed(own)} judged on the ratio{'s' if len(own) > 1 else ''} given")
    if rest:
        their = "their" if len(rest) > 1 else "its"
        parts.append(f"{_listed(rest)} judged without {their} aerodynamic damping")
    return "no aerodynamics block: " + "; ".join(parts)


def _listed(ids: list[str]) -> str:
    return ", ".join(ids[:4]) + (f" and {len(ids) - 4} more" if len(ids) > 4 else "")


def _modes(modes: list[ModeDoc]) -> Table:
    table = Table(title="Natural frequencies (standstill)", title_justify="left")
    table.add_column("mode", no_wrap=True, min_width=max((len(m["id"]) for m in modes), default=4))
    table.add_column("description")
    table.add_column("f [Hz]", justify="right")
    table.add_column("ζ", justify="right")
    operating = any(m.get("damping_in_operation") for m in modes)
    if operating:
        table.add_column("ζ min in op.", justify="right")
    for m in modes:
        zeta = "—" if m["damping_ratio"] is None else f"{m['damping_ratio']:.3g}"
        op = m.get("damping_in_operation")
        where = f"{op['at_wind_m_s']:.3g} m/s" if op and op["at_wind_m_s"] is not None else ""
        where = where or (f"{op['at_rpm']:.3g} rpm" if op else "")
        low = f"{op['lowest_total_damping_ratio']:.3g} @ {where}" if op else "—"
        f = f"{m['frequency_hz']:.4g}" + (" ↗" if m["speed_dependent"] else "")
        text = _t(m["description"])
        if m.get("superseded_by"):  # shown as what it is: the isolated value
            text.append(f" — isolated; judged as {m['superseded_by']}", style="dim")
        elif m.get("regimes") == []:
            text.append(" — reported only (exists in no operating regime)", style="dim")
        table.add_row(_t(m["id"]), text, f, zeta, *([low] if operating else []))
    return table


def _hanging(label: Text | str, text: Text | str, width: int = 6) -> Table:
    """``label`` then ``text``, the text's wrapped lines indented under its first (a
    hanging indent), two spaces in from the margin; the label column ``width`` wide."""
    grid = Table.grid(padding=(0, 1))
    grid.add_column(no_wrap=True, min_width=width)
    grid.add_column(overflow="fold")
    grid.add_row(Text("  ").append_text(label if isinstance(label, Text) else Text(label)), text)
    return grid


def _findings(checks: list[CheckDoc]) -> Group:
    """Every failing and warning check, worst first, one entry each: status, id (whole), its
    margin and DAF where it has them, the finding; then the info checks by id, and how many
    pass."""
    order = {"fail": 0, "warn": 1}
    shown = sorted((c for c in checks if c["status"] in order), key=lambda c: order[c["status"]])
    # one entry for one finding: checks that say word for word the same are named together
    same: dict[tuple[str, str], list[str]] = {}
    for c in shown:
        same.setdefault((c["status"], c["message"]), []).append(c["id"])
    lines: list[Any] = [Text("Findings", style="bold")]
    for c in shown:
        ids = same.pop((c["status"], c["message"]), None)
        if ids is None:
            continue  # named with the first that said it
        line = Text(", ".join(ids), style="bold")
        numbers = [f"margin {c['margin']:.1%}"] if c.get("margin") is not None else []
        if c.get("daf") is not None:
            numbers.append(f"DAF {c['daf']:.2g}")
        if numbers:
            line.append(f"  ({', '.join(numbers)})")
        line.append(f" — {c['message']}")
        lines.append(_hanging(Text(c["status"].upper(), style=STYLE[c["status"]]), line))
    infos = [c["id"] for c in checks if c["status"] not in order and c["status"] != "pass"]
    if infos:
        lines.append(
            _hanging(Text("info", style=STYLE["info"]), _t(", ".join(infos), STYLE["info"]))
        )
    passed = sum(1 for c in checks if c["status"] == "pass")
    said = f"  {passed} check passes." if passed == 1 else f"  {passed} checks pass."
    lines.append(Text(said, style="green" if passed else "dim"))
    return Group(*lines)


def _shown(check: CheckDoc, show_all: bool) -> bool:
    return show_all or check["status"] != "pass" or check.get("energy") != "minor"


def _checks(checks: list[CheckDoc], show_all: bool) -> Group:
    table = Table(title="Checks", title_justify="left", show_lines=False)
    table.add_column("status")
    table.add_column(
        "check", no_wrap=True, min_width=max((len(c["id"]) for c in checks), default=5)
    )
    table.add_column("margin", justify="right")
    table.add_column("DAF", justify="right")
    table.add_column("finding", ratio=1)
    for c in checks:
        if not _shown(c, show_all):
            continue
        margin = f"{c['margin']:.1%}" if "margin" in c else ""
        daf = f"{c['daf']:.3g}" if c.get("daf") is not None else ""
        table.add_row(
            Text(c["status"].upper(), style=STYLE[c["status"]]),
            _t(c["id"]),
            margin,
            daf,
            _t(c["message"]),
        )
    return Group(table)


@contextmanager
def batch_progress(console: Console, total: int) -> Iterator[Callable[[Any], None]]:
    """A progress bar on ``console`` with the time elapsed and the time to go (rich's
    estimate from the rate so far); yields ``advance(item)``, which redraws it. No
    thread redraws it in between: the batch forks its workers inside, and a fork beside a
    running thread copies every lock that thread holds (stderr's, mid-write: a worker
    that then writes a warning would wait for ever)."""
    from rich.progress import (
        BarColumn,
        MofNCompleteColumn,
        Progress,
        TextColumn,
        TimeElapsedColumn,
        TimeRemainingColumn,
    )

    with Progress(
        TextColumn("auditing"),
        BarColumn(),
        MofNCompleteColumn(),
        TimeElapsedColumn(),
        TextColumn("elapsed,"),
        TimeRemainingColumn(),
        TextColumn("to go"),
        TextColumn("{task.description}"),
        console=console,
        transient=True,
        auto_refresh=False,
    ) as progress:
        task = progress.add_task("", total=total)
        progress.refresh()

        def advance(item: Any) -> None:
            progress.update(task, advance=1, description=Path(item.path).name, refresh=True)

        yield advance


def batch_summary(console: Console, items: Sequence[Any], written: Sequence[Path]) -> None:
    """The batch summary table: verdict, turbine, tower class, worst check, margin."""
    table = Table(title="Batch summary", title_justify="left")
    table.add_column("verdict", no_wrap=True)
    table.add_column("turbine", min_width=8)  # never squeezed out on a narrow terminal
    table.add_column("tower class")
    rows = [it.row() for it in items]
    failed = ("input-error", "internal-error")
    worst = [
        f"{r['verdict'].replace('-', ' ')} (below)" if r["verdict"] in failed else r["worst_check"]
        for r in rows
    ]
    # a long check id is broken after a dot, not mid-word ("drivetrain.grid.powe" / "r")
    worst = [_dotted(w) if w else w for w in worst]
    width = max((len(line) for w in worst if w for line in w.splitlines()), default=0)
    table.add_column("worst check", no_wrap=True, min_width=width or None)
    table.add_column("margin", justify="right", no_wrap=True)
    counts: dict[str, int] = {}
    errors = []
    for row, check in zip(rows, worst, strict=True):
        counts[row["verdict"]] = counts.get(row["verdict"], 0) + 1
        # a verdict resting on an assumption (a speed range not found, a clamped platform)
        # must not read as a plain one: marked, and the warnings listed below the table
        mark = "*" if row["warnings"] else ""
        verdict = Text(row["verdict"].upper() + mark, style=STYLE.get(row["verdict"], "magenta"))
        if row["verdict"] in failed:
            errors.append(row)
            table.add_row(verdict, _t(Path(row["file"]).name), "—", check, "")
            continue
        margin = "" if row["margin"] is None else f"{row['margin']:.1%}"
        table.add_row(
            verdict,
            _t(row["turbine"]),
            row["tower_class"] or "—",
            _t(check or "—"),
            margin,
        )
    console.print(table)
    for row in errors:
        console.print(_t(f"{row['verdict'].replace('-', ' ')}: {row['message']}", "magenta"))
    warned = [row for row in rows if row["warnings"]]
    if warned:
        console.print(_t("* with warnings (each report lists them all):", STYLE["warn"]))
    for row in warned:
        more = f" (and {len(row['warnings']) - 1} more)" if len(row["warnings"]) > 1 else ""
        console.print(_t(f"  {row['turbine']}: {row['warnings'][0]}{more}", STYLE["warn"]))
    console.print(", ".join(f"{n} {k}" for k, n in sorted(counts.items())))
    if written:
        folder = {p.parent for p in written}
        console.print(_t(f"wrote {len(written)} files to {', '.join(map(str, folder))}", "dim"))


#: The widest line of a check id in the batch summary before it breaks after a dot.
ID_LINE = 24


def _dotted(name: str, width: int = ID_LINE) -> str:
    """A dotted id in lines of at most ``width`` characters, broken after a dot."""
    from ..results import dotted_lines

    return "\n".join(dotted_lines(name, lambda line: len(line) <= width))


def windows_table(console: Console, doc: dict[str, Any]) -> None:
    """The allowed windows per subsystem and where the design sits."""
    console.print(_t(f"{doc['turbine']} — allowed frequency windows ({doc['rule']})", "bold"))
    for sub in doc["subsystems"]:
        table = Table(
            title=f"{sub['subsystem']} ({sub['mode'] or 'no mode'})", title_justify="left"
        )
        table.add_column("window")
        table.add_column("from [Hz]", justify="right")
        table.add_column("to [Hz]", justify="right")
        for w in sub["allowed"]:
            high = "∞" if w["high_hz"] is None else f"{w['high_hz']:.4g}"
            table.add_row(w["name"], f"{w['low_hz']:.4g}", high)
        console.print(table)
        for pos in sub["modes"]:
            name = str(pos["window"])
            where = (
                (f"in {name}" if name.startswith("window") else f"in the {name} window")
                if pos["window"] and not pos["forbidden_by"]
                else f"FORBIDDEN by {pos['forbidden_by']}"
            )
            console.print(
                Text(
                    f"  {pos['id']} = {pos['frequency_hz']:.4g} Hz: {where}; nearest "
                    f"edge {pos['nearest_edge_hz']:.4g} Hz ({pos['distance_hz']:.3g} Hz, "
                    f"{pos['distance_percent']:.1f}%)",  # no space: "10.0" and "%" on one line
                    style="bold red" if pos["forbidden_by"] else "",
                )
            )


def shapes_table(console: Console, doc: dict[str, Any]) -> None:
    """``wtvib shapes``: each ElastoDyn polynomial, the deck's and the computed one, with
    the frequency each implies on the same finite-element model (and how far from the
    finite element's), the deck's MAC against the computed shape and its status."""
    console.print(
        _t(
            f"{doc['turbine']} — ElastoDyn mode shapes (blade at {doc['blade_rpm']:.4g} rpm): "
            "the finite element's frequency, the deck's and the computed coefficients "
            "(c₂ … c₆ downwards), the frequency each implies [Hz] and how far from the finite "
            "element's, the deck's MAC against the computed shape",
            "bold",
        )
    )
    table = Table(box=box.SIMPLE_HEAD, padding=(0, 1), show_edge=False)
    for col in ("set", "f [Hz]", "deck", "implies", "computed", "implies", "MAC", ""):
        table.add_column(
            col, justify="left" if col in ("set", "") else "right", no_wrap=True,
            min_width=4 if not col else None,
        )  # fmt: skip
    for row in [*doc["tower"], *doc["blade"]]:
        f = row["frequency_hz"]

        def coeffs(values: list[float] | None) -> str:
            return "—" if values is None else "\n".join(f"{v:.4g}" for v in values)

        def implied(hz: float | None, f: float = f) -> str:
            return "—" if hz is None else f"{hz:.4g}\n{words.signed_percent(hz / f - 1)}"

        status = row["status"].upper() if row["deck"] is not None else "new"
        table.add_row(
            f"{row['name']}\n{row['mode']}\n",
            f"{f:.4g}",
            coeffs(row["deck"]),
            implied(row["deck_implied_hz"]),
            coeffs(row["computed"]),
            implied(row["computed_implied_hz"]),
            "—" if row["mac_deck"] is None else f"{row['mac_deck']:.4f}",
            Text(status, style=STYLE.get(row["status"], "")),
        )
    console.print(table)
    for row in [*doc["tower"], *doc["blade"]]:
        if row.get("why"):
            console.print(_t(f"  {row['name']}: {row['why']}", "yellow"))
    for said in doc["assumptions"][1:]:  # the first is the model, in the JSON
        console.print(_t(f"  {said}", "dim"))
    for path in doc["written"]:
        console.print(_t(f"wrote {path}", "dim"), soft_wrap=True)


def _blade_stability(checks: list[CheckDoc]) -> Table | None:
    """Per-section divergence and flutter speeds, and the stall damping minima."""
    by_id = {c["id"]: c for c in checks}
    div, flut = by_id.get("blade.divergence"), by_id.get("blade.flutter")
    if not div or not flut or "sections" not in flut:
        return None
    table = Table(title="Blade stability", title_justify="left")
    for col in ("section", "section speed", "divergence", "flutter (p-k)", "k-method", "at"):
        table.add_column(col, justify="left" if col == "section" else "right")

    def speed(v: float | None, ref: float) -> str:
        return "none" if v is None else f"{v:.4g} m/s ({v / ref:.2f}×)"

    for d, f in zip(div["sections"], flut["sections"], strict=True):
        ref = f["section_speed_m_s"]
        table.add_row(
            f"r = {f['radius_m']:.3g} m",
            f"{ref:.4g} m/s",
            speed(d["divergence_speed_m_s"], ref),
            speed(f["flutter_speed_m_s"], ref),
            speed(f["flutter_speed_k_method_m_s"], ref),
            "—" if f["flutter_frequency_hz"] is None else f"{f['flutter_frequency_hz']:.3g} Hz",
        )
    for name in ("flap1", "edge1"):
        c = by_id.get(f"blade.stall.{name}")
        if c and "min_total_damping_ratio" in c:
            table.add_row(
                f"stall {name}",
                f"{c['at_wind_m_s']:g} m/s wind",
                f"ζ min {c['min_total_damping_ratio']:.4f}",
                "",
                "",
                f"{c['at_rpm']:.3g} rpm",
            )
    return table


def _coupling(checks: list[CheckDoc]) -> Table | None:
    """Coupled whole-turbine modes beside the isolated subsystems' (Hau §7.6)."""
    c = next((c for c in checks if c["id"] == "system.coupling"), None)
    if c is None:
        return None
    table = Table(
        title=f"Whole-turbine modes (coupled model, {c['condition']})",
        title_justify="left",
    )
    for col in ("coupled mode", "f [Hz]", "isolated subsystem", "f [Hz] ", "shift"):
        left = "mode" in col or "subsystem" in col
        table.add_column(col, justify="left" if left else "right", overflow="fold")
    for row in c["modes"]:
        shift = row["change"]
        style = "bold" if shift is not None and abs(shift) >= 0.05 else ""
        table.add_row(
            row["id"],
            f"{row['coupled_hz']:.4g}",
            row["isolated_id"] or "—",
            "—" if row["isolated_hz"] is None else f"{row['isolated_hz']:.4g}",
            Text("—" if shift is None else f"{shift:+.1%}", style=style),
        )
    return table


def _sensitivities(found: dict[str, dict[str, float]]) -> Table:
    """The normalised sensitivities (∂f/∂p)·(p/f): one row per uncertain input and mode."""
    table = Table(
        title="Sensitivities: (∂f/∂p)·(p/f), the % change of f per % of the input",
        title_justify="left",
    )
    table.add_column("input")
    table.add_column("mode")
    table.add_column("(∂f/∂p)·(p/f)", justify="right")
    for path, per_mode in found.items():
        for i, (mode, s) in enumerate(sorted(per_mode.items(), key=lambda kv: -abs(kv[1]))):
            table.add_row(_t(path) if i == 0 else "", _t(mode), f"{s:+.3f}")
    return table


def _uncertainty(u: UncertaintyDoc) -> Table:
    table = Table(
        title=f"Uncertainty ({u['samples']} samples, seed {u['seed']})", title_justify="left"
    )
    for col in ("mode", "p5 [Hz]", "p50 [Hz]", "p95 [Hz]", "P(in a margin band)"):
        table.add_column(col, justify="left" if col in ("mode", "P(in a margin band)") else "right")

    def share(k: str, v: ShareDoc) -> str:
        return f"{k} {v['probability']:.1%} [{v['ci95'][0]:.1%}–{v['ci95'][1]:.1%}]"

    for mode, s in u["modes"].items():
        risky = sorted(s.get("in_margin_band", {}).items(), key=lambda kv: -kv[1]["probability"])
        text = ", ".join(
            ([share("buckles", s["unstable"])] if "unstable" in s else [])
            + [share(k, v) for k, v in risky if v["probability"] > 0]
        )
        if "p5_hz" not in s:
            table.add_row(mode, "—", "—", "—", text)
            continue
        table.add_row(
            mode, f"{s['p5_hz']:.4g}", f"{s['p50_hz']:.4g}", f"{s['p95_hz']:.4g}", text or "none"
        )
    return table


def catalogue_table(console: Console, entries: Sequence[Any], folder: Path) -> None:
    """``wtvib catalogue``: the bundled turbines, each with its rotor and the story it tells."""
    table = Table(title=f"wtvib catalogue ({folder})", title_justify="left", show_lines=True)
    table.add_column("name", no_wrap=True)
    table.add_column("tower")
    table.add_column("verdict")
    table.add_column("turbine and its story", ratio=1)
    for e in entries:
        verdict = Text(e.verdict.upper(), style=STYLE.get(e.verdict, ""))
        about = _t(f"{e.turbine} ({e.rotor})", "bold")
        about.append("\n")
        about.append(_t(e.story))
        table.add_row(_t(e.name), _t(e.tower_class or "—"), verdict, about)
    console.print(table)
    console.print(
        "[dim]wtvib check NAME audits one; wtvib catalogue --copy DIR writes their specs to "
        "edit.[/dim]"
    )
