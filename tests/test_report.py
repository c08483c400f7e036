"""Rendering: the JSON is exactly Report.to_dict() (strict, no NaN); the terminal report
leads with the verdict and shows the headline warnings."""

import io
import json

from rich.console import Console

from tests.conftest import TURBINES
from wtvib import audit, spec
from wtvib.outputs.report import _shown, terminal, to_json


def strict(text: str) -> object:
    def refuse(name: str) -> None:
        raise ValueError(f"{name} is not JSON")

    return json.loads(text, parse_constant=refuse)


def test_json_is_the_report_dict_and_strict():
    r = audit.run(spec.load(TURBINES / "wka-60.yaml"))
    assert strict(to_json(r)) == json.loads(json.dumps(r.to_dict()))


def test_terminal_leads_with_the_verdict_and_warnings(write_spec):
    text = (
        write_spec().read_text()
        + "tower_head: {mass_kg: 3.0e5, cm_downwind_m: 0.5}\nyaw:\n"
        + "  drive_stiffness_nm_rad: 2.0e9\n"
    )
    r = audit.run(spec.load(write_spec(text, name="w.yaml")))
    out = io.StringIO()
    terminal(r, Console(file=out, width=100), written=[])
    head = out.getvalue().split("Findings")[0]
    assert "Verdict" in head and "Warning" in head and "inertia_yaw_kgm2" in head


def test_terminal_leads_with_a_summary_and_never_cuts_an_id():
    """At 80 columns the default report is the headline, each failing or warning
    check with its numbers, the info checks by id, and the assumptions; --detail adds the
    tables, whose id columns are as wide as the longest id (no "drivetrain.resonance.me…")."""
    r = audit.run(spec.load(TURBINES / "mod-0.yaml"))
    short, long = io.StringIO(), io.StringIO()
    terminal(r, Console(file=short, width=80))
    terminal(r, Console(file=long, width=80), detail=True)
    text = short.getvalue()
    assert "Natural frequencies (standstill)" not in text and "--detail" in text
    failing = [c for c in r.checks if c.status in ("fail", "warn")]
    assert failing and all(c.id in text for c in failing)
    table = long.getvalue()
    assert "Natural frequencies (standstill)" in table
    for c in r.to_dict()["checks"]:
        if _shown(c, False):  # (passing low-energy checks need --all)
            assert c["id"] in table, c["id"]  # whole, on one line
    assert "…" not in table


def test_batch_progress_redraws_without_a_thread():
    """The batch forks its workers inside the progress bar: no refresh thread may run
    beside them (its locks would be copied held). The bar still shows each completion."""
    import io
    import threading
    from types import SimpleNamespace

    from rich.console import Console

    from wtvib.outputs.report import batch_progress

    out = io.StringIO()
    console = Console(file=out, force_terminal=True, width=80)
    before = threading.active_count()
    with batch_progress(console, 3) as advance:
        assert threading.active_count() == before
        advance(SimpleNamespace(path="turbines/mod-2.yaml"))
        assert "1/3" in out.getvalue() and "mod-2.yaml" in out.getvalue()


def test_a_report_rendered_ahead_prints_as_one_printed_directly():
    """check renders its terminal report while the figures draw (captured), and prints it
    once they are written, then the files' lines (report.wrote): the same bytes, colours
    included, as printing it all at once."""
    from pathlib import Path

    from wtvib.outputs.report import wrote

    r = audit.run(spec.load(TURBINES / "mod-0.yaml"))
    files = [Path("out") / "mod-0.campbell.png", Path("out") / "mod-0.floquet.png"]
    direct = io.StringIO()
    terminal(r, Console(file=direct, force_terminal=True, width=100), written=files)
    later = io.StringIO()
    console = Console(file=later, force_terminal=True, width=100)
    with console.capture() as captured:
        terminal(r, console)
    later.write(captured.get())
    wrote(console, files)
    assert "\x1b[" in direct.getvalue() and later.getvalue() == direct.getvalue()


def test_the_batch_summary_breaks_a_long_check_id_after_a_dot_only():
    """At 80 columns the Aeroman's worst check, drivetrain.resonance.mesh.stage2 (32
    characters), is shown as "drivetrain.resonance." over "mesh.stage2" — not cut mid-word
    as it was ("drivetrain.grid.powe" / "r"), and not truncated: the turbine names wrap."""
    from pathlib import Path

    from wtvib.outputs.report import batch_summary

    class Item:
        def __init__(self, name: str, check: str) -> None:
            self.values = {
                "file": Path(f"{name}.yaml"),
                "turbine": name,
                "tower_class": "stiff",
                "verdict": "fail",
                "worst_check": check,
                "margin": 0.019,
                "message": "",
                "warnings": [],
            }

        def row(self) -> dict:
            return self.values

    items = [
        Item("Aeroman with active yaw retrofit", "drivetrain.resonance.mesh.stage2"),
        Item("MOD-0", "drivetrain.grid.power"),
        Item("Growian", "drivetrain.resonance.2P"),
    ]
    out = io.StringIO()
    batch_summary(Console(file=out, width=80), items, [])
    lines = out.getvalue().splitlines()
    assert any("drivetrain.resonance. " in ln for ln in lines)
    assert any("mesh.stage2" in ln for ln in lines)
    assert any("drivetrain.grid.power" in ln for ln in lines)
    assert any("drivetrain.resonance.2P" in ln for ln in lines)
    assert "…" not in out.getvalue()


def _text(report, width=80, **kw) -> str:  # type: ignore[no-untyped-def]
    console = Console(width=width, record=True, file=io.StringIO(), color_system=None)
    terminal(report, console, **kw)
    return console.export_text()


def test_wrapped_findings_and_assumptions_hang_under_their_first_line():
    """A finding wrapped at 80 columns continued at column 0."""
    text = _text(audit.run(spec.load(TURBINES / "wka-60.yaml")))
    body = text.split("Findings\n", 1)[1].split("\n14 modes", 1)[0]
    lines = body.splitlines()
    assert lines[0].startswith("  FAIL ") and len(lines) > 3
    for line in lines:
        assert line.startswith("  "), repr(line)  # nothing back at the margin
    bullets = text.split("Assumptions\n", 1)[1].splitlines()
    assert all(line.startswith(("  • ", "    ")) for line in bullets if line.strip())


def test_the_overspeed_reads_the_same_in_headline_and_assumptions():
    # the headline gave 26.45 rpm, the assumption 26.4 rpm
    text = _text(audit.run(spec.load(TURBINES / "wka-60.yaml")), width=200)
    assert "overspeed 26.45 rpm" in text and "(26.45 rpm) is checked" in text


def test_detail_prints_the_sensitivities_of_an_uncertainty_run():
    """The README promises a sensitivity table with --uncertainty; it was only in the JSON.
    WKA-60's tower: f ∝ √E, so ∂f/∂E·E/f ≈ +0.5 (a beam: exactly 0.5; the head's share is
    stiffness-free)."""
    report = audit.run(spec.load(TURBINES / "wka-60.yaml"), samples=200, seed=1)
    text = _text(report, width=120, detail=True)
    assert "Sensitivities" in text
    row = next(line for line in text.splitlines() if "youngs_modulus_pa" in line)
    assert "+0.50" in row or "+0.51" in row
    assert "Sensitivities" not in _text(report, width=120)  # --detail only


def test_a_structural_audit_names_the_modes_it_judges_without_aerodynamic_damping():
    """Hau 7.2.3: aerodynamic damping is large flapwise (and the rotor's thrust damps the
    tower's fore-aft bending). A spec without an aerodynamics block says which of its modes
    are judged without it; MOD-2, described without blades, has no flapwise resonance to
    speak of — its headline named one before."""

    def damping_row(name: str) -> str:
        out = io.StringIO()
        terminal(audit.run(spec.load(TURBINES / name)), Console(file=out, width=200))
        return next(line for line in out.getvalue().splitlines() if "Damping" in line)

    mod2 = damping_row("mod-2.yaml")
    assert "tower.fa1 judged without its aerodynamic damping" in mod2 and "flap" not in mod2
    darrieus = damping_row("darrieus.yaml")
    assert "blade.flap1" in darrieus and "tower.fa1" in darrieus
