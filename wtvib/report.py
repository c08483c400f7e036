"""Rendering a report: the terminal view (rich) and the JSON document.

Rendering never decides: everything shown here is read from :class:`~wtvib.audit.Report`.
"""

import json
from collections.abc import Sequence
from pathlib import Path

from rich.console import Console, Group
from rich.panel import Panel
from rich.table import Table
from rich.text import Text

from .audit import Report

STYLE = {"pass": "green", "info": "cyan", "warn": "yellow", "fail": "bold red"}


def to_json(report: Report) -> str:
    """The JSON contract: exactly ``report.to_dict()``, stable key order, trailing newline."""
    return json.dumps(report.to_dict(), indent=2, ensure_ascii=False) + "\n"


def terminal(
    report: Report,
    console: Console,
    *,
    written: Sequence[Path] = (),
    show_all: bool = False,
) -> None:
    """Print the report: summary panel, modes, checks, assumptions."""
    data = report.to_dict()
    console.print(_summary(data))
    console.print(_modes(data["modes"]))
    console.print(_checks(data["checks"], show_all))
    hidden = sum(1 for c in data["checks"] if not _shown(c, show_all))
    if hidden:
        console.print(
            f"[dim]{hidden} more checks pass on low-energy harmonics (--all shows them).[/dim]"
        )
    console.print(Text("Assumptions", style="bold"))
    for line in data["assumptions"]:
        console.print(Text(f"  • {line}"))
    for path in written:
        console.print(f"[dim]wrote {path}[/dim]")


def _summary(data: dict) -> Panel:  # type: ignore[type-arg]
    t = data["turbine"]
    op = data["operation"]
    verdict = data["verdict"]
    speeds = (
        f"{op['steady_rpm'][0][0]:g}–{op['steady_rpm'][-1][1]:g} rpm (variable)"
        if op["variable_speed"]
        else ", ".join(f"{a:g}" for a, _ in op["steady_rpm"]) + " rpm (fixed)"
    )
    grid = Table.grid(padding=(0, 2))
    grid.add_column(style="bold")
    grid.add_column()
    grid.add_row("Turbine", t["name"])
    grid.add_row("File", str(t["source_file"]))
    grid.add_row("Rotor", f"{t['blades']} blades, {t['orientation']}, {t['hub']} hub")
    grid.add_row("Speed", f"{speeds}; overspeed {op['overspeed_rpm']:.4g} rpm")
    grid.add_row("Tower class", str(data["tower_class"] or "—"))
    grid.add_row(
        "Rule",
        f"{data['rule']['kind']} margin {data['rule']['margin']:.0%} "
        f"({data['rule']['preset'] or 'custom'})",
    )
    grid.add_row("Verdict", Text(verdict.upper(), style=STYLE[verdict]))
    return Panel(grid, title="wtvib audit", border_style=STYLE[verdict])


def _modes(modes: list[dict]) -> Table:  # type: ignore[type-arg]
    table = Table(title="Natural frequencies (standstill)", title_justify="left")
    table.add_column("mode")
    table.add_column("description")
    table.add_column("f [Hz]", justify="right")
    table.add_column("ζ", justify="right")
    for m in modes:
        zeta = "—" if m["damping_ratio"] is None else f"{m['damping_ratio']:.3g}"
        f = f"{m['frequency_hz']:.4g}" + (" ↗" if m["speed_dependent"] else "")
        table.add_row(m["id"], m["description"], f, zeta)
    return table


def _shown(check: dict, show_all: bool) -> bool:  # type: ignore[type-arg]
    return show_all or check["status"] != "pass" or check.get("energy") != "minor"


def _checks(checks: list[dict], show_all: bool) -> Group:  # type: ignore[type-arg]
    table = Table(title="Checks", title_justify="left", show_lines=False)
    table.add_column("status")
    table.add_column("check")
    table.add_column("margin", justify="right")
    table.add_column("DAF", justify="right")
    table.add_column("finding", ratio=1)
    for c in checks:
        if not _shown(c, show_all):
            continue
        margin = f"{c['margin']:.1%}" if "margin" in c else ""
        daf = f"{c['daf']:.3g}" if c.get("daf") is not None else ""
        table.add_row(
            Text(c["status"].upper(), style=STYLE[c["status"]]), c["id"], margin, daf, c["message"]
        )
    return Group(table)
