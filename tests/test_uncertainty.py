"""Uncertainty at unit level: distributions, the Wilson interval, given-mode sampling."""

import numpy as np
import pytest

from tests.conftest import spec_text
from wtvib import spec, uncertainty


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
    """Issue 20: the tower samples are solved on a Rayleigh–Ritz basis (the nominal's
    lowest modes and each input's doubled system's first): against every sample's own full
    beam problem (the path the non-linear soil inputs take), within 1e-9 over ±50 %."""
    from tests.conftest import TURBINES

    s = spec.load(TURBINES / "wka-60.yaml")  # concrete E, density and head mass uncertain
    inputs = sorted(p for p in uncertainty.uncertain(s) if p.startswith(uncertainty.LINEAR_TOWER))
    assert len(inputs) == 3
    rng = np.random.default_rng(5)
    factors = {p: rng.uniform(0.5, 1.5, 40) for p in inputs}
    reduced = uncertainty._tower_samples(s, factors)
    full = uncertainty._tower_samples_direct(s, factors)
    for mode in ("tower.fa1", "tower.ss1"):
        assert np.allclose(reduced[mode], full[mode], rtol=1e-9, atol=0)
