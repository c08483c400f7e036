"""Design answers at unit level: the window documents and targets (the hand-computed window
edges and sizing are in tests/validation/test_design.py)."""

import pytest

from tests.conftest import TURBINES
from wtvib import audit, spec
from wtvib.studies import design


def windows(write_spec, **parts):  # type: ignore[no-untyped-def]
    s = spec.load(write_spec(**parts))
    r = audit.run(s)
    return s, r, design.all_windows(r)


def test_windows_document_names_its_schema_and_rule(write_spec):
    s, r, found = windows(write_spec, blades=2, speed="fixed_rpm: 30", modes="fa1: 0.75")
    doc = design.windows_document(s, found, r.rule)
    assert doc["schema"] == design.WINDOWS_SCHEMA and doc["rule"] == r.rule.label
    (tower,) = doc["subsystems"]
    assert tower["modes"][0]["id"] == "tower.fa1" and tower["modes"][0]["window"] == "soft"


def test_window_goal_is_the_middle_of_a_closed_window(write_spec):
    # 30 rpm, overspeed 33, two blades: soft window (0.605, 0.9) Hz (1P to 33 rpm × 1.1,
    # 2P at 30 rpm × 0.9: tests/validation/test_design.py)
    _, _, found = windows(
        write_spec, blades=2, speed="fixed_rpm: 30\noverspeed_rpm: 33", modes="fa1: 0.75"
    )
    assert design.window_goal(found, "soft") == pytest.approx(0.5 * (0.605 + 0.9))
    with pytest.raises(design.DesignError, match="no tower mode"):
        design.window_goal([], "soft")


@pytest.mark.parametrize("target", [0.0, -1.0, float("nan"), 1e4])
def test_size_never_calls_an_unreached_target_a_success(write_spec, target):
    """--target-hz 0 returned a tower scaled to its buckling limit as a success.
    A target at or below 0 is refused; one no scaling reaches (10 kHz) is said so."""
    from tests.validation.test_design import TUBE

    text = (
        "wtvib: 1\nturbine: {name: tube}\nrotor:\n  blades: 3\n  orientation: upwind\n"
        "  hub: rigid\n  speed: {fixed_rpm: 15}\n" + TUBE
    )
    s = spec.load(write_spec(text))
    with pytest.raises(design.DesignError, match=r"above 0 Hz|no wall scaling reaches"):
        design.size(s, target, "wall")


def test_size_takes_the_windows_of_window_under_the_same_options():
    """``window --margin 0.05`` and ``size --target soft`` must aim at the same window: size
    took no operating or rule options and sized to the default rule's windows. WKA-60, the
    soft window's middle at the default 10 % and at 5 % (at 20 % it has none): ``size``
    lands on each, where ``check`` passes."""
    import json

    from typer.testing import CliRunner

    from tests.conftest import TURBINES
    from wtvib.cli import app

    runner = CliRunner()
    path = str(TURBINES / "wka-60.yaml")
    for margin in ("0.1", "0.05"):
        win = runner.invoke(app, ["window", path, "-f", "json", "--no-plot", "--margin", margin])
        (tower,) = [s for s in json.loads(win.stdout)["subsystems"] if s["subsystem"] == "tower"]
        # the soft window, or the first of a split one (design.window_goal)
        soft = next(w for w in tower["allowed"] if w["name"].split(" ")[0] == "soft")
        goal = 0.5 * (soft["low_hz"] + soft["high_hz"])
        out = runner.invoke(
            app, ["size", path, "--target", "soft", "--format", "json", "--margin", margin]
        )
        assert out.exit_code == 0, out.stdout
        assert json.loads(out.stdout)["frequency_hz"] == pytest.approx(goal, rel=1e-3)


def test_a_forbidden_mode_names_only_the_line_whose_band_holds_it():
    """WKA-60's tower (0.767 Hz) sits in 2P's band (0.69–0.843 Hz at 17.5–23 rpm); 3P's
    band (0.79–1.27 Hz) overlaps 2P's and the merged band was named "2P+3P": the window
    said "FORBIDDEN by 2P+3P" where only 2P forbids it."""
    s = spec.load(TURBINES / "wka-60.yaml")
    report = audit.run(s)
    tower = next(w for w in design.all_windows(report) if w.subsystem == "tower")
    placed = dict(tower.modes)
    assert placed["tower.fa1"].blocked_by is not None
    assert placed["tower.fa1"].blocked_by.name == "2P"
    assert any(b.name == "2P+3P" for b in tower.forbidden)  # the merged band keeps both
