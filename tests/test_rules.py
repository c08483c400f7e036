"""Margin rules: separations, forbidden bands and the exact edge of the margin."""

import numpy as np
import pytest

from wtvib.rules import PRESETS, MarginRule, worst


def band(m: float = 0.10) -> MarginRule:
    return MarginRule("band", m, "test")


def ratio(m: float = 0.05) -> MarginRule:
    return MarginRule("ratio", m, "test")


def test_band_separation_is_relative_to_the_excitation():
    # |1.1 - 1.0| / 1.0 = 0.1 (hand computation)
    assert band().separation(1.0, 1.1) == pytest.approx(0.1)


def test_ratio_separation_is_the_frequency_ratio_offset():
    # 0.95 / 1.0 - 1 = -0.05 -> 0.05
    assert ratio().separation(0.95, 1.0) == pytest.approx(0.05)


@pytest.mark.parametrize(
    ("rule", "f_exc", "f_n", "violates"),
    [
        (band(0.10), 1.0, 1.1, False),  # exactly 10 % above: "at least 10 %" passes
        (band(0.10), 1.0, 0.9, False),  # exactly 10 % below
        (band(0.10), 1.0, 1.0999, True),  # just inside
        (ratio(0.05), 0.95, 1.0, False),  # f_exc/f_n = 0.95 exactly passes
        (ratio(0.05), 1.05, 1.0, False),  # = 1.05 exactly passes
        (ratio(0.05), 0.9501, 1.0, True),
    ],
)
def test_edge_of_the_margin_passes(rule, f_exc, f_n, violates):
    assert bool(rule.violates(rule.separation(f_exc, f_n))) is violates


def test_forbidden_band_edges_are_exactly_at_the_margin():
    for rule in (band(0.1), ratio(0.05), band(0.2)):
        lo, hi = rule.forbidden_band(2.0)
        sep = rule.separation(np.array([lo, hi]), 2.0)
        assert sep == pytest.approx([rule.margin, rule.margin])


def test_natural_band_is_the_inverse_view_of_the_forbidden_band():
    for rule in (band(0.1), ratio(0.05)):
        lo, hi = rule.natural_band(1.0)
        assert rule.separation(1.0, np.array([lo, hi])) == pytest.approx([rule.margin] * 2)


def test_presets_name_their_source():
    assert PRESETS["hau"].margin == 0.10 and PRESETS["hau"].rule == "band"
    assert PRESETS["gl2010"].margin == 0.05 and PRESETS["gl2010"].rule == "ratio"
    assert "not verified" in PRESETS["gl2010"].source


def test_worst_orders_statuses():
    assert worst(["pass", "info", "warn"]) == "warn"
    assert worst(["info", "fail", "pass"]) == "fail"
    assert worst([]) == "pass"


@pytest.mark.parametrize("kind", ["band", "ratio"])
def test_the_drawn_bands_end_where_the_judged_separation_meets_the_margin(kind):
    """The Campbell figure's bands are the rule's judgement drawn: at each edge of the band
    of excitations forbidden around a natural frequency (and of natural frequencies forbidden
    around an excitation) the separation the rule judges equals its margin exactly."""
    rule = MarginRule(kind, 0.1, "test")
    low, high = rule.forbidden_band(2.0)
    assert rule.separation(low, 2.0) == pytest.approx(0.1)
    assert rule.separation(high, 2.0) == pytest.approx(0.1)
    assert low < 2.0 < high
    low, high = rule.natural_band(3.0)
    assert rule.separation(3.0, low) == pytest.approx(0.1)
    assert rule.separation(3.0, high) == pytest.approx(0.1)
    assert low < 3.0 < high


def test_the_deciding_check_is_the_most_severe_then_the_least_margin():
    from wtvib.rules import worst_check

    checks = [
        {"id": "a", "status": "warn", "margin": 0.08},
        {"id": "b", "status": "warn", "margin": 0.05},
        {"id": "c", "status": "pass", "margin": 0.0},
        {"id": "d", "status": "info", "margin": None},
    ]
    assert worst_check(checks)["id"] == "b"  # type: ignore[index]
    assert worst_check([*checks, {"id": "e", "status": "fail", "margin": 0.09}])["id"] == "e"  # type: ignore[index]
    assert worst_check(checks[2:]) is None


def test_heavy_damping_is_one_threshold_with_its_stated_peak():
    """A mutation survivor (`resonance` 84, tests/MUTATION.md): the resonance routine's default
    heavy-damping limit was a second 0.3 beside the spec's; one constant now (rules.HEAVY_DAMPING),
    the limit at which the peak amplification 1/(2ζ√(1 − ζ²)) falls to 1.75 (its stated reason), the
    default of the audit setting and of the routine alike."""
    import inspect
    import math

    from wtvib import rules
    from wtvib.judge import resonance
    from wtvib.spec import AuditSettings

    z = rules.HEAVY_DAMPING
    assert 1 / (2 * z * math.sqrt(1 - z * z)) == pytest.approx(1.75, abs=0.005)
    assert AuditSettings().heavy_damping_ratio == z
    for fn in (resonance.assess, resonance.assess_all):
        assert inspect.signature(fn).parameters["heavy_damping"].default == z


def test_the_worst_status_orders_pass_info_warn_fail():
    """A resonance met only in start-up is information, worse than a pass: whatever the
    order the statuses come in, the worst is the later of pass < info < warn < fail."""
    from itertools import permutations

    ladder = ["pass", "info", "warn", "fail"]
    for top in range(1, 4):
        for order in permutations(ladder[: top + 1]):
            assert worst(order) == ladder[top]
    assert worst([]) == "pass"
