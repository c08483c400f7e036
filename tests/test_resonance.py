"""The one resonance routine on hand-checked cases.

Speeds in rpm in the test names and comments; the routine works in rad/s.
Forbidden speed intervals follow from the band rule by hand: with natural frequency f_n
and harmonic k, the margin m is violated for k·n/60 in (f_n/(1+m), f_n/(1−m)).
"""

import dataclasses
import math

import pytest

from wtvib.judge.excitation import Excitation, OperatingRange, harmonic_energy
from wtvib.judge.resonance import assess, regime_of, resonance_checks
from wtvib.results import Mode, Sampled, Southwell
from wtvib.rules import MarginRule
from wtvib.units import rad_s_to_rpm, rpm_to_rad_s

BAND = MarginRule("band", 0.10, "Hau 7.5.1")
SEVERITY = {"dominant": "fail", "secondary": "fail", "minor": "info"}


def op(steady, overspeed, quick=(), variable=True, dwell=None):
    w = lambda x: float(rpm_to_rad_s(x))  # noqa: E731
    steady = tuple((w(a), w(b)) for a, b in steady)
    dwell = tuple(w(x) for x in dwell) if dwell else (steady[-1][1],)
    return OperatingRange(
        steady, tuple((w(a), w(b)) for a, b in quick), w(overspeed), variable, dwell
    )


def harmonic(k, blades=3):
    return Excitation(f"{k}P", float(k), harmonic_energy(k, blades), "test")


def mode(f, zeta=0.01, curve=None):
    return Mode("tower.fa1", "tower", "test mode", f, zeta, curve)


def rpm(x):
    return float(rad_s_to_rpm(x))


def test_fixed_speed_on_blade_passing_fails_with_resonant_daf():
    # 3P at 20 rpm = 1.0 Hz = f_n: separation 0, DAF = 1/(2·0.01) = 50
    f = assess(mode(1.0), harmonic(3), op([(20, 20)], 23, variable=False), BAND, SEVERITY, 0.01)
    assert f.status == "fail" and f.regime == "steady"
    assert f.margin == pytest.approx(0.0, abs=1e-12)
    assert f.daf == pytest.approx(50.0)


@pytest.mark.parametrize(("f_n", "inside"), [(1.1, False), (0.9, False), (1.0999, True)])
def test_fixed_speed_exactly_at_the_margin_passes(f_n, inside):
    # 3P at 20 rpm = 1.0 Hz; f_n = 1.1 and 0.9 are exactly 10 % away: no steady violation
    # (neighbouring speeds in start-up or overspeed may still be inside the band)
    f = assess(mode(f_n), harmonic(3), op([(20, 20)], 20.5, variable=False), BAND, SEVERITY, 0.01)
    assert bool(f.violations["steady"]) is inside
    assert (f.status == "fail") is inside
    assert f.margin == pytest.approx(abs(f_n - 1.0))


def test_variable_speed_forbidden_interval_matches_hand_computation():
    # f_n = 1 Hz, 3P: forbidden 60/(3·1.1) = 18.1818 … 60/(3·0.9) = 22.2222 rpm
    f = assess(mode(1.0), harmonic(3), op([(10, 30)], 34.5), BAND, SEVERITY, 0.01)
    ((lo, hi),) = f.violations["steady"]
    assert rpm(lo) == pytest.approx(60 / 3.3, rel=1e-9)
    assert rpm(hi) == pytest.approx(60 / 2.7, rel=1e-9)
    assert [rpm(c) for c in f.crossings] == pytest.approx([20.0])
    assert f.status == "fail"


def test_exclusion_band_is_reported_for_variable_speed():
    f = assess(mode(1.0), harmonic(3), op([(10, 30)], 34.5), BAND, SEVERITY, 0.01)
    [check] = resonance_checks([f], op([(10, 30)], 34.5), BAND)
    assert check.numbers["exclude_rpm"] == [
        [pytest.approx(18.1818, abs=1e-4), pytest.approx(22.2222, abs=1e-4)]
    ]
    assert check.id == "tower.resonance.3P"


def test_exclusion_band_holds_only_the_modes_that_need_clearing():
    """Two modes in one check against 3P over 10–30 rpm: 1 Hz, lightly damped, fails
    (forbidden 18.18–22.22 rpm by hand); 1.4 Hz with ζ = 0.4 (heavily damped: no resonant
    peak, info) sits within the margin at 25.45–31.11 rpm. Clearing the check needs the
    first band only — the JSON's exclude_rpm and the message say the same; a second failing
    mode at 1.05 Hz widens the band to 22.22 → 23.33 rpm, which the message states as the
    whole exclusion beside the governing mode's own."""
    steady = op([(10, 30)], 34.5)
    fail = assess(mode(1.0), harmonic(3), steady, BAND, SEVERITY, 0.01)
    damped = Mode("tower.fa2", "tower", "test mode", 1.4, 0.4, None)
    info = assess(damped, harmonic(3), steady, BAND, SEVERITY, 0.01)
    assert (fail.status, info.status) == ("fail", "info") and info.violations["steady"]
    [check] = resonance_checks([fail, info], steady, BAND)
    band = [[pytest.approx(60 / 3.3, abs=1e-4), pytest.approx(60 / 2.7, abs=1e-4)]]
    assert check.numbers["exclude_rpm"] == band
    assert "all together" not in check.message
    near = assess(
        Mode("tower.ss1", "tower", "test mode", 1.05, 0.01, None),
        harmonic(3),
        steady,
        BAND,
        SEVERITY,
        0.01,
    )
    [check] = resonance_checks([fail, info, near], steady, BAND)
    assert check.numbers["exclude_rpm"] == [
        [pytest.approx(60 / 3.3, abs=1e-4), pytest.approx(63 / 2.7, abs=1e-4)]
    ]
    assert "all together: exclude 18.2–23.3 rpm" in check.message
    # a minor harmonic inside the margin in steady operation (4P on three blades: 13.6–16.7
    # rpm by hand) is only told: nothing to exclude, and its message asks for no exclusion
    minor = assess(mode(1.0), harmonic(4), steady, BAND, SEVERITY, 0.01)
    assert minor.status == "info" and minor.violations["steady"]
    [told] = resonance_checks([minor], steady, BAND)
    assert told.numbers["exclude_rpm"] == []
    assert "to clear it" not in told.message and "exclude" not in told.message


def test_overspeed_only_warns():
    # forbidden from 18.18 rpm; steady up to 16 rpm, overspeed to 20 rpm
    f = assess(mode(1.0), harmonic(3), op([(10, 16)], 20), BAND, SEVERITY, 0.01)
    assert (f.status, f.regime) == ("warn", "overspeed")
    assert rpm(f.violations["overspeed"][0][0]) == pytest.approx(60 / 3.3)


def test_start_up_only_is_info():
    # forbidden 18.18 … 22.22 rpm lies below the 25 rpm minimum: the soft-tower encounter
    f = assess(mode(1.0), harmonic(3), op([(25, 30)], 34), BAND, SEVERITY, 0.01)
    assert (f.status, f.regime) == ("info", "start-up")


def test_quick_pass_band_covering_the_violation_warns():
    f = assess(mode(1.0), harmonic(3), op([(10, 30)], 34, quick=[(18, 23)]), BAND, SEVERITY, 0.01)
    assert (f.status, f.regime) == ("warn", "quick-pass")


def test_partial_quick_pass_still_fails_outside_it():
    f = assess(mode(1.0), harmonic(3), op([(10, 30)], 34, quick=[(19, 23)]), BAND, SEVERITY, 0.01)
    assert f.status == "fail"
    ((lo, hi),) = f.violations["steady"]
    assert (rpm(lo), rpm(hi)) == pytest.approx((60 / 3.3, 19.0))


def test_minor_harmonic_in_steady_operation_is_info():
    # 5P on a three-bladed rotor at 12 rpm = 1.0 Hz
    f = assess(mode(1.0), harmonic(5), op([(12, 12)], 13, variable=False), BAND, SEVERITY, 0.01)
    assert (f.status, f.regime) == ("info", "steady")


def test_secondary_harmonic_fails_at_rated_but_warns_when_only_swept():
    # 2P of a three-bladed rotor: f_n = 1 Hz meets 2P at 30 rpm
    at_rated = assess(mode(1.0), harmonic(2), op([(10, 30)], 34), BAND, SEVERITY, 0.01)
    assert at_rated.status == "fail"
    # rated 40 rpm: 2P only sweeps through f_n at 30 rpm in partial load
    swept = assess(mode(1.0), harmonic(2), op([(10, 40)], 44), BAND, SEVERITY, 0.01)
    assert swept.status == "warn"


def test_southwell_crossing_speed_is_analytic():
    # f² = f0² + K·(n/60)², 3P meets it where 9·x² = f0² + K·x², x = f0/√(9 − K) rev/s
    f0, k = 0.8, 1.19
    crossing = 60 * f0 / math.sqrt(9 - k)
    f = assess(
        mode(f0, curve=Southwell(f0, k)), harmonic(3), op([(5, 25)], 28), BAND, SEVERITY, 0.005
    )
    assert [rpm(c) for c in f.crossings] == pytest.approx([crossing], rel=1e-9)


def test_ratio_rule_gives_its_own_interval():
    # ratio rule m = 5 %: forbidden 3·n/60 in (0.95, 1.05) → n in (19, 21) rpm
    rule = MarginRule("ratio", 0.05, "test")
    f = assess(mode(1.0), harmonic(3), op([(10, 30)], 34), rule, SEVERITY, 0.01)
    ((lo, hi),) = f.violations["steady"]
    assert (rpm(lo), rpm(hi)) == pytest.approx((19.0, 21.0), rel=1e-9)


def test_regime_of_speed():
    o = op([(10, 20)], 23, quick=[(14, 15)])
    assert regime_of(float(rpm_to_rad_s(5)), o) == "start-up"
    assert regime_of(float(rpm_to_rad_s(12)), o) == "steady"
    assert regime_of(float(rpm_to_rad_s(14.5)), o) == "quick-pass"
    assert regime_of(float(rpm_to_rad_s(22)), o) == "overspeed"
    # a crossing computed at a range's edge carries round-off (a bisection, f/k): within
    # 1e-9 of the overspeed it belongs to the range it touches, beyond 1e-7 it does not
    top = o.overspeed
    for (a, b), regime in ((o.quick_pass[0], "quick-pass"), (o.steady[0], "steady")):
        assert regime_of(a - 5e-10 * top, o) == regime and regime_of(b + 5e-10 * top, o) == regime
    assert regime_of(o.quick_pass[0][0] - 1e-7 * top, o) == "steady"
    assert regime_of(o.steady[0][0] - 1e-7 * top, o) == "start-up"
    assert regime_of(o.steady[0][1] + 1e-7 * top, o) == "overspeed"


def test_fixed_frame_lines_take_the_class_of_the_blade_harmonic_behind_them():
    """DOMAIN.md §3 and excitation.driving_harmonic: three blades, fixed 3P on a backward
    whirl is the blades' 4P (minor), on a forward whirl their 2P (secondary), on a
    collective mode 3P (dominant); fixed 4P reaches a symmetric rotor's modes only through
    asymmetry (minor); a tower mode (no whirl) keeps the line's own class."""
    from wtvib.judge.excitation import driving_harmonic, rotor_harmonics

    lines = {e.id: e for e in rotor_harmonics(3, 6)}
    assert [driving_harmonic(3, w) for w in ("backward", "forward", "collective")] == [4, 2, 3]
    assert lines["3P"].energy_for("backward") == "minor"
    assert lines["3P"].energy_for("forward") == "secondary"
    assert lines["3P"].energy_for("collective") == "dominant"
    assert lines["4P"].energy_for("forward") == "minor"  # blades' 3P, but N ∤ 4
    assert lines["1P"].energy_for("forward") is None  # blades' 0P: a steady load
    assert lines["2P"].energy_for(None) == "secondary" == lines["2P"].energy
    assert lines["6P"].energy_for("forward") == "minor"  # blades' 5P


def test_two_modes_crossed_alike_are_governed_by_the_less_damped():
    """Two modes both met by 3P in a variable-speed range have margin 0 up to rounding of
    their crossing speeds; which one governs the check must not hang on that rounding
    (the NREL 5-MW's 2P check flipped between tower fa1 and ss1 with the root finder):
    the larger amplification — the less damped mode — governs."""
    rng = op([(15, 25)], 28)
    damped = Mode("tower.fa1", "tower", "damped", 1.0, 0.08)
    lively = Mode("tower.ss1", "tower", "lively", 1.05, 0.005)
    for order in ((damped, lively), (lively, damped)):
        findings = [assess(m, harmonic(3), rng, BAND, SEVERITY, 0.01) for m in order]
        assert all(f.margin == pytest.approx(0.0, abs=1e-9) for f in findings)
        (check,) = resonance_checks(findings, rng, BAND)
        assert check.message.startswith("tower.ss1") and "also: tower.fa1" in check.message


def test_two_modes_crossed_with_one_damping_are_governed_by_the_first():
    """Crossed with the same ζ, both amplify by 1/(2ζ) up to the rounding of their crossing
    speeds (the IEA-3.4's 6P check went to one mode or the other with the root finder's
    last digits): the first listed (the lower frequency) governs, whatever the rounding —
    here each amplification nudged by 1e-13 either way."""
    from dataclasses import replace

    rng = op([(3.8, 11.75)], 13.5)
    modes = [
        Mode(f"tower.{n}", "tower", n, f, 0.01) for n, f in (("fa1", 0.40031), ("ss1", 0.40599))
    ]
    findings = [assess(m, harmonic(6), rng, BAND, SEVERITY, 0.01) for m in modes]
    assert [f.daf for f in findings] == pytest.approx([50.0, 50.0], rel=1e-9)
    for nudge in (1 - 1e-13, 1 + 1e-13):
        nudged = [findings[0], replace(findings[1], daf=findings[1].daf * nudge)]
        (check,) = resonance_checks(nudged, rng, BAND)
        assert check.numbers["mode"] == "tower.fa1"


def test_bisect_solves_a_linear_piece_at_its_first_secant_and_a_curve_to_the_tolerance():
    """A sampled curve against a line is linear between samples: the first secant is the
    root, and the next one, not moving, confirms it — three evaluations of f (the ends,
    then the root) instead of a dozen; a curved function (√x − 0.5, root 0.25, and a cubic
    with roots at ±1) still converges to 1e-12, as the tolerance asks."""
    import numpy as np

    from wtvib.judge.resonance import bisect

    calls = []

    def linear(x):  # roots 0.6521 and 1.7617; the first secant's f is rounding, not 0
        calls.append(len(x))
        return np.where(x < 1.0, 3.432 * (x - 0.6521), 1.529 * (1.7617 - x))

    got = bisect(linear, np.array([0.0, 1.0]), np.array([0.9, 1.9]))
    np.testing.assert_allclose(got, [0.6521, 1.7617], rtol=0, atol=1e-15)
    assert len(calls) == 3
    curved = bisect(lambda x: np.sqrt(x) - 0.5, np.array([0.0]), np.array([1.0]))
    np.testing.assert_allclose(curved, [0.25], rtol=0, atol=1e-12)
    cubic = bisect(lambda x: x**3 - x, np.array([-1.7, 0.4]), np.array([-0.3, 1.9]))
    np.testing.assert_allclose(cubic, [-1.0, 1.0], rtol=0, atol=1e-12)


def test_all_pairs_at_once_agree_with_each_pair_alone_to_the_bit():
    """assess_all solves every pair's crossings and run edges together: the same numbers as
    judging each pair alone (a sampled curve, a Southwell curve, a soil band, a fixed
    speed range and a quick-pass band among them)."""
    from wtvib.judge.resonance import assess_all
    from wtvib.results import Sampled

    sampled = Sampled((0.0, 1.0, 2.0, 3.0), (0.9, 0.95, 1.1, 1.2))
    banded = Mode("tower.ss1", "tower", "soil band", 0.35, 0.01, None, band_hz=(0.3, 0.4))
    modes = [mode(0.35), mode(1.0, curve=sampled), mode(0.8, curve=Southwell(0.7, 1.2)), banded]
    lines = [harmonic(k) for k in (1, 2, 3, 6)]
    o = op([(8, 14), (20, 20)], 24, quick=[(10, 11)])
    together = assess_all(modes, lines, o, BAND, SEVERITY, 0.01)
    alone = [assess(m, e, o, BAND, SEVERITY, 0.01) for e in lines for m in modes]
    assert together == alone
    assert any(f.crossings for f in together) and any(f.forbidden for f in together)


def test_a_crossing_mark_carries_the_damping_judged_there():
    """A mutation survivor (`resonance` 841, tests/MUTATION.md): the Campbell diagram's mark of a
    crossing shows the ζ its DAF came from — the crossed mode's damping at that rotor speed (its
    damping in operation where the aerodynamics give one; the least of coincident modes') — on every
    crossing of two catalogue turbines and an aeroelastic deck."""
    from tests.conftest import SHARED, TURBINES
    from wtvib import audit, importers, spec
    from wtvib.units import rpm_to_rad_s

    inputs = [spec.load(TURBINES / "wka-60.yaml"), spec.load(TURBINES / "aeroman.yaml")]
    deck = SHARED / "reference/NREL5MW/NREL-5MW.fst"
    if deck.exists():
        inputs.append(importers.load(deck))
    seen = 0
    for s in inputs:
        report = audit.run(s)
        modes = {m.id: m for m in report.modes}
        for mark in report.marks:
            if mark.kind != "crossing" or mark.damping is None:
                continue
            # a mark that stands for coincident resonances of several modes (WKA-60's grid
            # and free drive-train modes at one frequency) shows the least damped of them
            speed = float(rpm_to_rad_s(mark.rpm))
            judged = min(modes[m].damping_at(speed, 0.0) for m in mark.modes)
            # coincident crossings lie a little apart (the NREL deck's fore-aft and
            # side-side modes, 1.6 % apart, on 5P): each mode's ζ is taken at its own
            # crossing, the mark at one of them — 5e-4 apart at most here
            assert mark.damping == pytest.approx(judged, rel=2e-3), (mark, judged)
            assert mark.daf == pytest.approx(1 / (2 * mark.damping), rel=1e-9)
            seen += 1
    assert seen > 5


def test_a_band_from_the_grids_first_speed_ends_where_the_stiffened_mode_leaves_it():
    """A fixed-frequency line (order 0, 1 Hz) on a blade mode of 1 Hz at standstill that
    stiffens with speed, f² = 1 + 1.2·(n/60)²: the mode is inside the 10 % band from 0 rpm
    and leaves it where f = 1.1 Hz, n = 60·√((1.1² − 1)/1.2) = 25.100 rpm (by hand) — the
    run starts at the grid's first speed, whose edge is not refined, and only its end is."""
    line = Excitation("mesh", 0.0, "dominant", "test", offset_hz=1.0)
    blade = Mode("blade.flap1", "blade", "test mode", 1.0, 0.01, Southwell(1.0, 1.2))
    f = assess(blade, line, op([(10, 30)], 34.5), BAND, SEVERITY, 0.01)
    ((lo, hi),) = f.violations["steady"]
    assert rpm(lo) == pytest.approx(10.0, rel=1e-12)  # the steady range's start
    assert rpm(hi) == pytest.approx(60 * math.sqrt((1.1**2 - 1) / 1.2), rel=1e-9)


def test_an_imported_curve_leaving_and_reentering_a_fixed_lines_band():
    """An imported Campbell curve (linear between its points) of 1.0 Hz at 0 rpm, 1.3 Hz at
    15 rpm, back to 1.0 Hz at 30 rpm, against a fixed 1 Hz line: inside the 10 % band
    (0.9–1.1 Hz) from the grid's first speed to 5 rpm and again from 25 rpm (by hand:
    1 + 0.02·n = 1.1, 1.3 − 0.02·(n − 15) = 1.1). Two runs, the first from the grid's start:
    each edge refined is the one of its own run."""
    w = lambda x: float(rpm_to_rad_s(x))  # noqa: E731
    curve = Sampled((0.0, w(15), w(30)), (1.0, 1.3, 1.0))
    line = Excitation("mesh", 0.0, "dominant", "test", offset_hz=1.0)
    f = assess(Mode("x.1", "tower", "test", 1.0, 0.01, curve), line, op([(2, 30)], 34.5), BAND,
               SEVERITY, 0.01)  # fmt: skip
    runs = [(rpm(a), rpm(b)) for a, b in f.violations["steady"]]
    assert runs == [pytest.approx((2.0, 5.0), rel=1e-8), pytest.approx((25.0, 30.0), rel=1e-8)]


def test_marks_of_one_line_at_one_place_are_one_mark():
    """Two modes of one frequency on one line (a round tower's fore-aft and side-side) are
    one resonance: marks within 2 % of each other in speed and frequency merge into the worst
    status, naming both modes, with the larger amplification (the less damped mode); 2.1 %
    apart in either, or on another line, they stay apart."""
    from wtvib.judge.resonance import Mark, _one_per_place

    fa = Mark(23.0, 0.767, "warn", "crossing", "2P", ("tower.fa1",), 10.0, 0.05)
    ss = Mark(23.3, 0.775, "fail", "crossing", "2P", ("tower.ss1",), 25.0, 0.02)
    (one,) = _one_per_place([fa, ss])
    assert one.status == "fail" and set(one.modes) == {"tower.fa1", "tower.ss1"}
    assert (one.daf, one.damping) == (25.0, 0.02) and (one.rpm, one.hz) == (23.3, 0.775)
    (one,) = _one_per_place([fa, dataclasses.replace(ss, status="warn", daf=5.0, damping=0.1)])
    assert (one.daf, one.damping) == (10.0, 0.05)  # the first's, the less damped
    for apart in (
        dataclasses.replace(ss, rpm=23.0 * 1.021),
        dataclasses.replace(ss, hz=0.767 * 1.021),
        dataclasses.replace(ss, line="3P"),
    ):
        assert len(_one_per_place([fa, apart])) == 2


def _standstill_mode(zeta: float | None, source: str) -> Mode:
    return Mode("blade.flap1", "blade", "x", 0.7, zeta, damping_source=source)


@pytest.mark.parametrize(
    ("modes", "status"),
    [
        # the damping the input gives: a pass (ζ = 0, an undamped model, is no instability)
        ([_standstill_mode(0.0, "blade.damping_ratio (given)")], "pass"),
        # all of it wtvib's assumption: the verdict rests on nothing the input says
        ([_standstill_mode(0.005, "assumed (no value given)")], "warn"),
        # a negative damping ratio (another tool's, or a model's) is an instability
        ([_standstill_mode(-0.01, "given"), _standstill_mode(0.02, "given")], "fail"),
        ([], "warn"),
    ],
)
def test_a_standstill_audit_judges_the_modes_damping(modes, status):
    """``system.stability`` of a parked audit of wtvib's own models (resonance.
    standstill_stability): what such an audit rests on is the modes' damping."""
    from wtvib.judge.resonance import standstill_stability

    check = standstill_stability(modes)
    assert (check.id, check.status) == ("system.stability", status), check.message
