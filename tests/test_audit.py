"""The orchestrator: assumptions stated only when made, warnings for missing inputs that
change a frequency by a factor, the damping each mode is judged with."""

import pytest

from tests.conftest import TURBINES, spec_text
from wtvib import audit, importers, spec

HEAD = """
tower_head: {mass_kg: 300000, cm_downwind_m: 0.5, cm_above_top_m: 2.0}
yaw:
  drive_stiffness_nm_rad: 2.0e9
  rotor_polar_inertia_kgm2: 3.5e7
"""


def test_a_head_without_yaw_inertia_is_a_warning_with_an_estimate(write_spec):
    """With no yaw inertia the yaw model saw only m·x² = 75,000 kg·m² and gave a
    yaw frequency of 26 Hz silently; the rotor's J_p/2 = 1.75e7 kg·m² alone gives
    √(2e9/(1.75e7 + 7.5e4))/2π = 1.70 Hz (one-mass model, the yaw module's)."""
    r = audit.run(spec.load(write_spec(extra=HEAD)))
    yaw1 = next(m for m in r.modes if m.id == "yaw.1")
    assert yaw1.frequency_hz > 20  # what the inputs say
    warning = next(w for w in r.warnings if w.startswith("tower_head.inertia_yaw_kgm2"))
    assert "near 1.7 Hz" in warning
    given = spec.load(
        write_spec(
            extra=HEAD.replace(
                "cm_above_top_m: 2.0", "cm_above_top_m: 2.0, inertia_yaw_kgm2: 2.0e7"
            ),
            name="g.yaml",
        )
    )
    assert not [w for w in audit.run(given).warnings if "inertia_yaw" in w]


def test_a_given_damping_ratio_is_not_called_an_assumption(write_spec):
    base = spec.load(write_spec())
    assumed = audit.run(base)
    assert any("tower: damping ratio" in a and "assumed" in a for a in assumed.assumptions)
    text = write_spec().read_text().replace("tower:\n", "tower:\n  damping_ratio: 0.02\n", 1)
    given = audit.run(spec.load(write_spec(text, name="given.yaml")))
    assert not any(a.startswith("tower: damping ratio") for a in given.assumptions)
    fa1 = next(m for m in given.modes if m.id == "tower.fa1")
    assert fa1.damping_ratio == 0.02 and fa1.damping_source == "tower.damping_ratio (given)"
    # the ζ used is the one shown (JSON and the terminal's column)
    row = next(m for m in given.to_dict()["modes"] if m["id"] == "tower.fa1")
    assert row["damping_ratio"] == 0.02


def test_a_number_that_is_not_finite_is_null_with_a_reason(write_spec):
    """Reports carried Infinity/NaN (invalid JSON). Whatever a model returns, the
    JSON contract writes null for it and names the field in warnings."""
    import dataclasses
    import json

    from wtvib.outputs.report import to_json
    from wtvib.results import Check, Rule

    r = audit.run(spec.load(write_spec()))
    odd = Check(
        "x.odd",
        "tower",
        "info",
        "m",
        Rule("r", "s"),
        {"margin": float("inf"), "series": [1.0, float("nan")]},
    )
    r = dataclasses.replace(r, checks=(*r.checks, odd))
    doc = json.loads(to_json(r), parse_constant=lambda c: (_ for _ in ()).throw(ValueError(c)))
    row = next(c for c in doc["checks"] if c["id"] == "x.odd")
    assert row["margin"] is None and row["series"] == [1.0, None]
    assert any("checks[" in w and "margin" in w for w in doc["warnings"])


def test_a_slow_tip_speed_for_the_rotor_size_is_a_warning(shared):
    """The IEA-3.4 ElastoDyn file alone (no ServoDyn, no range) is audited at its
    initial RotSpeed, 5 rpm: 34 m/s at the tip of a 130 m rotor, well under audit.SLOW_TIP
    (the turbine runs 3.8–11.75 rpm, 80 m/s at rated). Given the range, no warning."""
    from wtvib import importers

    path = shared / "reference/IEA3.4/IEA-3.4-130-RWT_ElastoDyn.dat"
    slow = [w for w in audit.suspicious(importers.load(path), []) if "tip speed" in w]
    assert len(slow) == 1 and "34 m/s" in slow[0]
    ranged = importers.load(path, importers.ReadOptions(rpm=(3.8, 11.75)))
    assert not [w for w in audit.suspicious(ranged, []) if "tip speed" in w]


def test_a_rated_power_implausible_for_the_rotor_is_a_warning(write_spec):
    """2 kW on a 90 m rotor (0.31 W/m², a kW/MW slip) warns; 2 MW does not
    (314 W/m², between the catalogue's 88 and 837 W/m²)."""

    def warned(kw: float) -> list[str]:
        path = write_spec(
            text=spec_text(extra="").replace(
                "turbine: {name: Test turbine}",
                f"turbine: {{name: Test turbine, rotor_diameter_m: 90, rated_power_kw: {kw}}}",
            )
        )
        return [w for w in audit.run(spec.load(path)).warnings if "W/m²" in w]

    assert len(warned(2)) == 1 and "0.314 W/m²" in warned(2)[0]
    assert warned(2000) == []


def test_a_lowest_speed_far_below_the_highest_is_a_warning(write_spec):
    """A min_rpm of 0.94 on a 90 m rotor running up to 16 rpm (rad/s typed as rpm?)
    warns; 5 rpm does not."""

    def warned(low: float) -> list[str]:
        text = spec_text(speed=f"min_rpm: {low}\nmax_rpm: 16").replace(
            "turbine: {name: Test turbine}", "turbine: {name: Test turbine, rotor_diameter_m: 90}"
        )
        return [w for w in audit.run(spec.load(write_spec(text))).warnings if "rad/s typed" in w]

    assert len(warned(0.94)) == 1
    assert warned(5.0) == []


def test_a_natural_frequency_under_a_hundredth_of_a_hertz_is_a_warning():
    """Found setting every catalogue number to 1e-15: MOD-2 with a yaw mode of
    1e-15 Hz passed without a word; any mode under 0.01 Hz (a period over 100 s, below the
    slowest of the catalogue and the reference turbines, 0.126 Hz) now warns."""
    from tests.conftest import TURBINES

    base = spec.load(TURBINES / "mod-2.yaml")
    assert not [w for w in audit.run(base).warnings if "under 0.01 Hz" in w]
    d = base.model_dump()
    d["yaw"]["modes"]["1"] = 1e-15
    warned = [w for w in audit.run(spec.Spec.model_validate(d)).warnings if "under 0.01 Hz" in w]
    assert len(warned) == 1 and warned[0].startswith("yaw.1: 1e-15 Hz")


def test_a_stiffness_typed_far_too_large_is_a_warning(shared, tmp_path):
    """The NREL 5-MW deck with its drive-train spring (DTTorSpr 8.67637e8 N·m/rad) typed
    8.67637e28: the drive train's torsion mode lands at 1.4e11 Hz, which warns (above
    audit.FASTEST_MODE_HZ) and says the slow modes lose precision beside it — they do (the
    coupled fore-aft mode moves from 0.314 to 0.37 Hz): not a quiet answer. The deck as
    published warns of nothing of the kind."""
    import shutil

    deck = tmp_path / "NREL5MW"
    shutil.copytree(shared / "reference/NREL5MW", deck)
    ed = deck / "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"
    text = ed.read_text()
    assert "8.67637E+08   DTTorSpr" in text
    fast = "natural frequency over"
    assert not [w for w in audit.run(importers.load(deck / "NREL-5MW.fst")).warnings if fast in w]
    ed.write_text(text.replace("8.67637E+08   DTTorSpr", "8.67637E+28   DTTorSpr"))
    warned = [w for w in audit.run(importers.load(deck / "NREL-5MW.fst")).warnings if fast in w]
    assert warned and all("lose precision" in w for w in warned)
    assert any(w.startswith("drivetrain.") and "e+11 Hz" in w for w in warned)


def test_a_table_station_far_from_both_neighbours_is_a_warning(shared, tmp_path):
    """An exponent typed wrong in the NREL 5-MW tower table (TwFAStif at HtFract 0.5:
    2.9101100E-09 for 2.9101100E+11 N·m²) leaves a tower that audits — fore-aft 0.26 Hz
    instead of 0.32 — so it must not pass quietly: the station is named, with its height
    (0.5 × 87.6 m = 43.8 m) and how far it sits below both neighbours. No reference or
    catalogue table has such a step (the sharpest: 1.34, audit.SPIKE); a deck's station is
    named by its file, line and column, a spec's by its field (the next test)."""
    import shutil

    deck = tmp_path / "NREL5MW"
    shutil.copytree(shared / "reference/NREL5MW", deck)
    tower = deck / "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat"
    text = tower.read_text()
    row = "5.0000000E-01  3.9164100E+03  2.9101100E+11"
    assert row in text
    tower.write_text(text.replace(row, row.replace("E+11", "E-09"), 1))
    warned = [
        w for w in audit.suspicious(importers.load(deck / "NREL-5MW.fst"), []) if "exponent" in w
    ]
    assert len(warned) == 1
    # named by the deck's file, line (header 18 + units + 6th row) and column
    assert warned[0].startswith(f"{tower}:25: TwFAStif: 2.91e-09 at 43.8 m"), warned[0]
    assert "below both its neighbours" in warned[0]


def test_a_verdict_resting_on_no_judged_mode_is_an_error_not_a_pass(monkeypatch):
    """A verdict that judged nothing is not a pass (a linearisation whose
    structural modes were all dropped passed): with no finding on any judged mode the audit
    stops with one line naming the input."""
    from wtvib import audit as audit_module
    from wtvib.errors import SpecError

    monkeypatch.setattr(audit_module, "assess_all", lambda *a, **k: [])
    s = spec.load(TURBINES / "mod-2.yaml")
    with pytest.raises(SpecError, match="no natural frequency to judge"):
        audit_module.run(s)


def test_a_vertical_axis_audit_says_what_it_does_not_judge():
    """Hau 7.5.2: a Darrieus rotor's blades see their angle of attack oscillate over each
    turn; wtvib judges the per-rev lines only and says that its own excitation is not
    modelled."""
    from tests.conftest import TURBINES

    report = audit.run(spec.load(TURBINES / "darrieus.yaml"))
    said = " ".join(report.assumptions)
    assert "Not judged: its own excitation" in said and "angle of attack" in said


def test_a_subsystem_s_own_warning_is_not_said_twice(write_spec):
    """A first tower bending at 0.008 Hz: the tower's own bound (tower.warnings, under 0.05
    Hz) says it; the bound every mode shares (under 0.01 Hz) does not say it again."""
    report = audit.run(spec.load(write_spec(modes="fa1: 0.008")))
    said = [w for w in report.warnings if w.startswith("tower.fa1:")]
    assert len(said) == 1 and "first tower bending" in said[0]
    assert audit.MODIFIERS and all(hasattr(m, "modify") for m in audit.MODIFIERS)


def test_a_specs_own_table_station_is_named_by_its_field(write_spec):
    """Tjæreborg's sections with one diameter typed 100 times too large: its field."""
    text = (TURBINES / "tjaereborg.yaml").read_text(encoding="utf-8")
    old = "      - {value: 4.75, provenance: published, source: stas}\n"
    assert text.count(old) == 3
    i = text.index(old) + len(old)  # the second diameter: the middle station of three
    text = text[:i] + old.replace("4.75", "475") + text[i + len(old) :]
    warned = [w for w in audit.suspicious(spec.load(write_spec(text)), []) if "exponent" in w]
    assert warned and warned[0].startswith("tower.sections.outer_diameter_m[2]: 475"), warned
