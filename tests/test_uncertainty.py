"""Uncertainty at unit level: distributions, the Wilson interval, given-mode sampling."""

import numpy as np
import pytest

from tests.conftest import spec_text
from wtvib import spec
from wtvib.studies import uncertainty


def test_distributions_have_the_documented_spread():
    rng = np.random.default_rng(3)
    normal = spec.Quantity(value=1.0, provenance="representative", tolerance=0.1)
    uniform = spec.Quantity(
        value=1.0, provenance="representative", tolerance=0.1, distribution="uniform"
    )
    assert np.std(uncertainty.draw(normal, 40_000, rng)) == pytest.approx(0.1, rel=0.03)
    u = uncertainty.draw(uniform, 40_000, rng)
    assert u.min() >= 0.9 and u.max() <= 1.1  # half-width


def test_wilson_interval_brackets_the_estimate():
    lo, hi = uncertainty.wilson(30, 100)
    assert lo < 0.3 < hi and hi - lo < 0.2


def test_a_given_frequency_with_a_tolerance_is_sampled_about_its_value(write_spec):
    text = spec_text(modes="fa1: {value: 0.5, provenance: representative, tolerance: 0.02}")
    s = spec.load(write_spec(text))
    assert uncertainty.nominal_of(s) == {"tower.fa1": 0.5}
    f = uncertainty.sample(s, 5000, seed=4).frequencies["tower.fa1"]
    assert np.mean(f) == pytest.approx(0.5, rel=2e-3) and np.std(f) == pytest.approx(0.01, rel=0.05)
    assert uncertainty.sensitivities(s) == {"tower.modes.fa1": {"tower.fa1": 1.0}}


def test_the_reduced_tower_samples_equal_each_sample_solved_anew():
    """The tower samples are solved on a Rayleigh–Ritz basis (the nominal's
    lowest modes and each input's doubled system's first): against every sample's own full
    beam problem (the path the non-linear soil inputs take), within 1e-9 over ±50 %."""
    from tests.conftest import TURBINES

    s = spec.load(TURBINES / "wka-60.yaml")  # concrete E, density and head mass uncertain
    inputs = sorted(p for p in uncertainty.uncertain(s) if p.startswith(uncertainty.LINEAR_TOWER))
    assert len(inputs) == 3
    rng = np.random.default_rng(5)
    factors = {p: rng.uniform(0.5, 1.5, 40) for p in inputs}
    ritz = uncertainty.tower_ritz(s)
    assert ritz is not None and ritz.paths == tuple(inputs)
    reduced = ritz.frequencies(np.stack([factors[p] for p in inputs], axis=1))
    full = uncertainty._tower_samples_direct(s, factors)
    for mode in ("tower.fa1", "tower.ss1"):
        assert np.allclose(reduced[mode], full[mode], rtol=1e-9, atol=0)


def test_the_schema_gives_each_sampled_field_its_range():
    from wtvib.spec.ranges import valid_range

    assert valid_range("tower.foundation.soil[0].friction_angle_deg") == (25, 45, False, False)
    assert valid_range("tower.material.youngs_modulus_pa")[:3] == (0, np.inf, True)
    assert valid_range("tower.modes.fa1")[:3] == (0, np.inf, True)  # a given frequency
    assert valid_range("blade.modes.flap1.damping_ratio") == (0, 1, False, True)
    assert valid_range("drivetrain.modes.grid[0].frequency_hz")[0] == 0
    assert valid_range("tower_head.cm_downwind_m") == (-1000, 1000, False, False)


def test_draws_outside_the_valid_range_are_drawn_again_and_counted():
    """A friction angle of 44° ± 5 % (normal) reaches past the 45° the spec accepts in
    ≈ 33 % of draws (P(z > 1/2.2) of a standard normal, 0.325); those are drawn again."""
    q = spec.Quantity(value=44.0, provenance="representative", tolerance=0.05)
    f, outside = uncertainty.draw_valid(
        "tower.foundation.soil[0].friction_angle_deg", q, 20_000, np.random.default_rng(1)
    )
    assert np.all(44.0 * f <= 45.0) and np.all(44.0 * f >= 25.0)
    assert outside / 20_000 == pytest.approx(0.325, abs=0.015)


def test_a_wide_tolerance_is_a_truncated_distribution_and_buckling_a_share():
    """WKA-60's concrete E at ±60 % (normal): 4.8 % of draws are ≤ 0 (P(z < −1/0.6)) and
    are drawn again; the softest samples buckle under the 80 t head — both reported, as
    warnings and in the JSON, where a crash ("the structure is unstable") stood before."""
    from tests.conftest import TURBINES, with_tolerance
    from wtvib import audit

    d = spec.load(TURBINES / "wka-60.yaml")  # model_dump drops the file's own tolerances
    wide = with_tolerance(d, "tower.material.youngs_modulus_pa", 0.6)
    r = audit.run(wide, samples=4000, seed=2)
    u = r.uncertainty
    assert u is not None
    t = u["truncated"]["tower.material.youngs_modulus_pa"]
    assert t["redrawn"] / 4000 == pytest.approx(0.048, abs=0.012)
    buckles = u["modes"]["tower.fa1"]["unstable"]["probability"]
    assert 0 < buckles < 0.02
    assert np.isfinite(u["modes"]["tower.fa1"]["p5_hz"])
    assert any("drawn again" in w for w in r.warnings)
    assert any("tower.fa1 buckles" in w for w in r.warnings)
