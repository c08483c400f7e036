"""The coupled two-bladed turbine's periodic equations: bounded cost, not-analysed speeds
said (the multi-blade cross-check is in tests/validation/test_coupled.py)."""

from tests.test_coupled import write
from wtvib import audit, spec
from wtvib.numerics import floquet
from wtvib.subsystems import coupled, periodic


def test_a_slow_two_bladed_rotor_with_stiff_blades_is_analysed_and_stable(tmp_path):
    # RK4 needed 240,000 steps a revolution here (FUZZ.md campaign 5); the Magnus step
    # control needs a few hundred. Undamped apart from the drive train: no growth.
    p = write(tmp_path, blades=2)
    text = p.read_text().replace("{min_rpm: 10, max_rpm: 20}", "{min_rpm: 0.2, max_rpm: 0.3}")
    p.write_text(text.replace("[3.0e9, 1.0e8]", "[3.0e13, 1.0e12]"))
    check = next(c for c in audit.run(spec.load(p)).checks if c.id == "system.floquet")
    assert max(check.numbers["max_multiplier"]) <= 1 + floquet.GROWTH
    assert not check.numbers["unstable_rpm"]
    # the slowest speeds still exceed the step budget: said, and not called a pass
    skipped = check.numbers["not_analysed_rpm"]
    assert check.status == ("warn" if skipped else "pass")
    assert not skipped or "not analysed at" in check.message


def test_a_speed_needing_too_many_steps_is_not_analysed(tmp_path):
    s = spec.load(write(tmp_path, blades=2))
    p = periodic.periodic(coupled.build(s, "free"))
    omega = 0.01  # rad/s: one revolution of 628 s against modes of several Hz
    assert floquet.steps_for(p.highest_hz, 2 * 3.141592653589793 / omega) > floquet.MAX_STEPS
    assert periodic.multipliers(p, omega) is None


def test_the_step_error_on_a_neutral_mode_is_not_called_growth(shared, monkeypatch):
    """The AWT-27 deck (two-bladed, teetered, generator free: its rotor turns on a shaft
    with no stiffness — a neutral, undamped slow mode). The Magnus step's error on it is
    erratic in the step count: at 54.1 rpm half the steps the check takes (69 a revolution)
    put that mode's multipliers at 1 + 4e-4, above GROWTH, where the check's own 138 put
    them at 1 to 1e-8 (once, with the blades' twist mirrored, 138 steps gave 1 + 2e-6 and
    the check failed the deck on it). So the check integrates again where it sees growth
    (floquet.REFINE): with its step halved here, it still finds no growth and passes; the
    deck's real finding, its tower 8.7 % from 1P, still fails."""
    import math

    import numpy as np

    from wtvib import importers
    from wtvib.units import rpm_to_rad_s

    s = importers.load(shared / "reference/AWT27/Test01.fst")
    model = coupled.build(s, s.coupled.rotating_condition)
    assert model.condition == "free"
    p = periodic.periodic(model, cutoff_hz=periodic.cutoff_hz(s))
    omega = float(rpm_to_rad_s(54.14))
    steps = floquet.steps_for(p.highest_hz, 2 * math.pi / omega)
    monkeypatch.setattr(
        periodic, "steps_for", lambda hz, period: floquet.steps_for(hz, period) // 2
    )
    coarse = np.abs(periodic.multipliers(p, omega)).max()
    assert coarse > 1 + floquet.GROWTH  # the half step's error
    confirmed = periodic._confirmed(p, omega)
    assert confirmed is not None and abs(np.abs(confirmed).max() - 1) < 1e-7
    fine = np.abs(periodic.multipliers(p, omega, steps=4 * steps, max_steps=10 * steps)).max()
    assert abs(fine - 1) < 1e-7
    report = audit.run(s)
    check = next(c for c in report.checks if c.id == "system.floquet")
    assert check.status == "pass" and "no growth" in check.message
    assert next(c for c in report.checks if c.id == "tower.class").status == "fail"
    # the coupled model clamps the blades to the teetered hub, and says so
    assert any("the model clamps the blades to it" in a for a in report.assumptions)


def test_a_rotor_at_rest_has_no_period(tmp_path):
    """A parked two-bladed turbine (r-test's 5MW_Land_BD_Init is a parked one-bladed one:
    it crashed here, dividing by its 0 rpm): its equations have no period, so neither
    Floquet check judges it — each says why, as information, not a warning."""
    from typer.testing import CliRunner

    from tests.conftest import TURBINES
    from wtvib.cli import app

    text = (TURBINES / "mod-2.yaml").read_text()
    old = "    fixed_rpm: {value: 17.5, provenance: representative, source: domain}"
    assert old in text
    path = tmp_path / "parked.yaml"
    path.write_text(text.replace(old, "    parked: true"))
    result = CliRunner().invoke(app, ["check", str(path), "--no-plots", "-f", "json"])
    assert result.exit_code in (0, 1), result.output
    import json

    checks = {c["id"]: c for c in json.loads(result.stdout)["checks"]}
    for key in ("rotor.floquet", "system.floquet"):
        if key in checks:
            assert checks[key]["status"] == "info" and "does not turn" in checks[key]["message"]
    assert "rotor.floquet" in checks
