"""Design windows and sizing against hand-computed edges (issue 10).

Band rule, m = 10 %: an excitation at f_e forbids natural frequencies in (0.9·f_e, 1.1·f_e);
over a speed range [n_lo, n_hi] a line kP forbids (0.9·k·n_lo/60, 1.1·k·n_hi/60).
"""

import math

import pytest

from tests.conftest import spec_text
from wtvib import audit, design, spec


def windows_of(write_spec, blades, speed):
    s = spec.load(write_spec(blades=blades, speed=speed, modes="fa1: 0.5"))
    found = design.all_windows(s, audit.run(s).modes)
    return next(w for w in found if w.subsystem == "tower")


def edges(ws):
    return [
        (
            w.name,
            pytest.approx(w.low, abs=1e-9),
            w.high if math.isinf(w.high) else pytest.approx(w.high, abs=1e-9),
        )
        for w in ws.allowed
    ]


def test_two_blades_fixed_speed(write_spec):
    # 30 rpm: 1P = 0.5 Hz forbids (0.45, 0.55); 2P = 1.0 Hz forbids (0.9, 1.1)
    ws = windows_of(write_spec, 2, "fixed_rpm: 30")
    assert edges(ws) == [("soft-soft", 0.0, 0.45), ("soft", 0.55, 0.9), ("stiff", 1.1, math.inf)]


def test_two_blades_variable_speed(write_spec):
    # 20–30 rpm: 1P 0.333–0.5 Hz → (0.3, 0.55); 2P 0.667–1.0 Hz → (0.6, 1.1)
    ws = windows_of(write_spec, 2, "min_rpm: 20\nmax_rpm: 30")
    assert edges(ws) == [("soft-soft", 0.0, 0.3), ("soft", 0.55, 0.6), ("stiff", 1.1, math.inf)]


def test_three_blades_fixed_speed_2p_splits_the_soft_window(write_spec):
    # 20 rpm: 1P 0.333 → (0.3, 0.3667); 2P at the (fixed) dwell speed 0.667 → (0.6, 0.7333);
    # 3P 1.0 → (0.9, 1.1)
    ws = windows_of(write_spec, 3, "fixed_rpm: 20")
    assert edges(ws) == [
        ("soft-soft", 0.0, 0.3),
        ("soft (1)", 1.1 / 3, 0.6),
        ("soft (2)", 2.2 / 3, 0.9),
        ("stiff", 1.1, math.inf),
    ]


def test_three_blades_variable_speed_2p_only_at_rated(write_spec):
    # 10–20 rpm, rated = max = 20: 1P (0.15, 0.3667); 2P at 20 rpm (0.6, 0.7333);
    # 3P 0.5–1.0 Hz → (0.45, 1.1): merges with 2P
    ws = windows_of(write_spec, 3, "min_rpm: 10\nmax_rpm: 20")
    assert edges(ws) == [
        ("soft-soft", 0.0, 0.15),
        ("soft", 1.1 / 3, 0.45),
        ("stiff", 1.1, math.inf),
    ]


def test_position_reports_the_nearest_edge(write_spec):
    ws = windows_of(write_spec, 2, "fixed_rpm: 30")
    # fa1 = 0.5 Hz sits on 1P (0.5 Hz), inside its forbidden band (0.45, 0.55)
    assert ws.position.inside is None
    assert ws.position.blocked_by is not None and ws.position.blocked_by.name == "1P"
    assert ws.position.distance_hz == pytest.approx(0.05)


TUBE = """\
tower:
  sections: {height_m: [0, 80], outer_diameter_m: [5.0, 3.5], wall_thickness_m: [0.03, 0.02]}
  material: {youngs_modulus_pa: 2.1e11, density_kg_m3: 8500}
tower_head: {mass_kg: 200000, cm_above_top_m: 2.0}
"""


@pytest.mark.parametrize("what", ["wall", "diameter", "both"])
def test_sizing_hits_the_target_within_a_tenth_of_a_percent(tmp_path, what):
    path = tmp_path / "t.yaml"
    path.write_text(
        spec_text(blades=3, speed="min_rpm: 8\nmax_rpm: 16", modes="{}").replace(
            "tower:\n  modes:\n    {}\n", ""
        )
        + TUBE
    )
    s = spec.load(path)
    base = design.first_bending(s)
    result = design.size(s, 1.15 * base, what)  # type: ignore[arg-type]
    again = design.first_bending(design.scaled(s, result.scale, what))  # type: ignore[arg-type]
    assert again == pytest.approx(1.15 * base, rel=1e-3)
    assert result.mass_after_kg > result.mass_before_kg  # a stiffer tube costs steel


def test_sizing_a_tower_given_by_frequencies_is_a_clear_error(write_spec):
    s = spec.load(write_spec())
    with pytest.raises(design.DesignError, match="tube sections"):
        design.size(s, 0.4)


def test_window_judges_every_mode_check_judges():
    """Issue 15: on the Aeroman, window said 'in window' where check fails on
    drivetrain.grid.4 (stage-2 mesh) and yaw.play.1 (2P with gear play)."""
    from tests.conftest import TURBINES

    s = spec.load(TURBINES / "aeroman.yaml")
    r = audit.run(s)
    found = {w.subsystem: w for w in design.all_windows(s, r.modes, r.rule)}
    assert "blade" not in found  # no empty windows for a subsystem without judged modes
    placed = {i: p for w in found.values() for i, p in w.modes}
    assert placed["drivetrain.grid.4"].blocked_by.name == "mesh.stage2"  # type: ignore[union-attr]
    assert placed["yaw.play.1"].blocked_by.name == "2P"  # type: ignore[union-attr]
    assert "drivetrain.locked.1" not in placed  # reported only, as in check


@pytest.mark.parametrize("name", ["aeroman", "mod-0", "mod-2", "wka-60", "growian", "wts-4"])
def test_every_steady_dominant_failure_of_check_is_forbidden_in_window(name):
    from tests.conftest import TURBINES

    s = spec.load(TURBINES / f"{name}.yaml")
    r = audit.run(s)
    placed = {i: p for w in design.all_windows(s, r.modes, r.rule) for i, p in w.modes}
    for f in r.findings:
        if f.regime == "steady" and f.energy == "dominant" and f.mode.curve is None:
            assert placed[f.mode.id].blocked_by is not None, (f.mode.id, f.excitation.id)
