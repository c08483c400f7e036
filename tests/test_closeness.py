"""Subsystems' natural frequencies close to each other (wtvib.judge.closeness; Hau ch. 7 intro,
7.3.3, 7.5): the pairs the chapter names, compared where both modes exist."""

from dataclasses import replace

import numpy as np
import pytest

from wtvib.judge import closeness
from wtvib.judge.excitation import OperatingRange
from wtvib.results import Mode
from wtvib.units import rpm_to_rad_s

OP = OperatingRange(
    steady=((float(rpm_to_rad_s(10.0)), float(rpm_to_rad_s(20.0))),),
    quick_pass=(),
    overspeed=float(rpm_to_rad_s(22.0)),
    variable=True,
)
IN_OPERATION = frozenset({"steady", "quick-pass", "overspeed"})


def _mode(id_: str, f: float, **kw: object) -> Mode:
    return Mode(id=id_, subsystem=id_.split(".")[0], description=id_, frequency_hz=f, **kw)  # type: ignore[arg-type]


def test_edgewise_close_to_the_drive_train_warns_with_the_books_reason() -> None:
    """Edge 1.00 Hz, the grid-coupled drive train 1.05 Hz in operation: 5 % apart, judged
    on isolated models — a warning quoting 7.3.3."""
    modes = [_mode("blade.edge1", 1.0), _mode("drivetrain.grid.1", 1.05, regimes=IN_OPERATION)]
    c = closeness.check(modes, OP)
    assert c is not None and c.status == "warn"
    assert "7.3.3" in c.message and "5% apart" in c.message
    assert c.numbers["pairs"][0]["separation"] == pytest.approx(0.05)


def test_a_coupled_model_judging_the_pair_makes_it_information() -> None:
    modes = [
        _mode("blade.edge1", 1.0, superseded_by="system.blade.edge1.collective"),
        _mode("drivetrain.grid.1", 1.05, regimes=IN_OPERATION, superseded_by="system.drivetrain1"),
    ]
    c = closeness.check(modes, OP)
    assert c is not None and c.status == "info"
    assert "system.blade.edge1.collective and system.drivetrain1" in c.message


def test_modes_apart_pass_and_say_how_far() -> None:
    modes = [_mode("blade.flap1", 0.7), _mode("tower.fa1", 0.32)]
    c = closeness.check(modes, OP)
    assert c is not None and c.status == "pass"
    assert "119% apart at standstill" in c.message  # (0.7 − 0.32)/0.32


def test_the_rotating_blade_meets_the_tower_in_operation() -> None:
    """A flap mode stiffened by rotation, 0.30 Hz at standstill rising linearly to 0.40 Hz at
    20 rpm, meets a 0.36 Hz tower at 12 rpm (its closest: 0 %), not at standstill (20 %)."""
    w = np.array([0.0, float(rpm_to_rad_s(20.0))])
    flap = _mode("blade.flap1", 0.30, curve=lambda om: np.interp(om, w, [0.30, 0.40]))
    found = closeness.assess([flap, _mode("tower.fa1", 0.36)], OP)
    assert len(found) == 1
    # (12 rpm is a point of the 21 speeds sampled over 10–20 rpm: found there exactly)
    assert found[0].separation < 0.005 and found[0].rpm == pytest.approx(12.0, abs=1e-9)


def test_a_parked_mode_is_compared_at_standstill_only() -> None:
    """The braked drive train (no operating regime) at 1.2 Hz against an edgewise mode that
    is 1.0 Hz at standstill and 1.2 Hz only in operation: 20 % apart, where both exist."""
    w = np.array([0.0, float(rpm_to_rad_s(20.0))])
    edge = _mode("blade.edge1", 1.0, curve=lambda om: np.interp(om, w, [1.0, 1.2]))
    locked = _mode("drivetrain.locked.1", 1.2, regimes=frozenset())
    (found,) = closeness.assess([edge, locked], OP)
    assert found.rpm == 0 and found.separation == pytest.approx(0.2)
    (meets,) = closeness.assess([edge, replace(locked, regimes=IN_OPERATION)], OP)
    assert meets.separation == pytest.approx(0.0, abs=1e-9)


def test_no_pair_no_check() -> None:
    assert closeness.check([_mode("tower.fa1", 0.3), _mode("yaw.1", 1.0)], OP) is None


def test_the_closeness_limit_is_ten_percent() -> None:
    """9.5 % apart is close, 10.5 % is not (Hau's 10 % margin, applied between modes)."""
    for gap, status in ((0.095, "warn"), (0.105, "pass")):
        modes = [_mode("blade.flap1", 1.0 + gap), _mode("tower.fa1", 1.0)]
        c = closeness.check(modes, OP)
        assert c is not None and c.status == status, gap
