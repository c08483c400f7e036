"""Monte Carlo uncertainty against first-order (delta-method) predictions.

A tip-mass cantilever with a normally distributed Young's modulus, E ~ N(E₀, (σE₀)²):
f ∝ √E, so to first order mean f = f₀(1 − σ²/8) and std f = f₀·σ/2 (delta method), and
P(f > f₀(1 + σ/2·z)) = 1 − Φ(z) for the linearised (normal) frequency.
"""

import math

import numpy as np
import pytest

from wtvib import audit, spec
from wtvib.studies import uncertainty

SIGMA = 0.02  # 2 % standard deviation of E


def cantilever(tolerance: float = SIGMA, distribution: str = "normal") -> spec.Spec:
    return spec.from_data(
        {
            "wtvib": 1,
            "turbine": {"name": "tip-mass cantilever"},
            "rotor": {
                "blades": 3,
                "orientation": "upwind",
                "hub": "rigid",
                "speed": {"fixed_rpm": 5.0},
            },
            "tower": {
                "sections": {
                    "height_m": [0, 60],
                    "outer_diameter_m": [4, 4],
                    "wall_thickness_m": [0.03, 0.03],
                },
                "material": {
                    "youngs_modulus_pa": {
                        "value": 2.1e11,
                        "provenance": "representative",
                        "tolerance": tolerance,
                        "distribution": distribution,
                    },
                    "density_kg_m3": 7850,
                },
                "gravity": False,
            },
            "tower_head": {"mass_kg": 150000},
        }
    )


@pytest.fixture(scope="module")
def drawn():
    s = cantilever()
    f0 = next(m for m in audit.run(s).modes if m.id == "tower.fa1").frequency_hz
    return f0, uncertainty.sample(s, 20000, seed=7).frequencies["tower.fa1"]


def test_mean_and_std_match_the_delta_method(drawn):
    f0, f = drawn
    se_mean = f0 * SIGMA / 2 / math.sqrt(len(f))
    assert np.mean(f) == pytest.approx(f0 * (1 - SIGMA**2 / 8), abs=4 * se_mean)
    assert np.std(f) == pytest.approx(f0 * SIGMA / 2, rel=0.03)


def test_probability_and_its_confidence_interval(drawn):
    f0, f = drawn
    z = 1.0
    threshold = f0 * (1 + SIGMA / 2 * z)
    hits = int(np.sum(f > threshold))
    lo, hi = uncertainty.wilson(hits, len(f))
    expected = 0.5 * math.erfc(z / math.sqrt(2))  # 1 − Φ(1) = 0.1587
    assert lo <= expected <= hi
    assert hi - lo < 0.012  # 20,000 samples: the interval is about ±0.5 %


def test_wilson_interval_edges():
    assert uncertainty.wilson(0, 100)[0] == 0.0
    assert uncertainty.wilson(100, 100)[1] == pytest.approx(1.0)
    lo, hi = uncertainty.wilson(50, 100)
    assert lo < 0.5 < hi and hi - lo == pytest.approx(0.19, abs=0.01)


def test_same_seed_same_samples_and_chunking_does_not_matter():
    s = cantilever()
    a = uncertainty.sample(s, 3000, seed=3, chunk=1000).frequencies["tower.fa1"]
    b = uncertainty.sample(s, 3000, seed=3, chunk=1000).frequencies["tower.fa1"]
    assert np.array_equal(a, b)


def test_report_carries_percentiles_probabilities_and_sensitivities():
    report = audit.run(cantilever(), samples=500, seed=1)
    u = report.to_dict()["uncertainty"]
    fa1 = u["modes"]["tower.fa1"]
    assert fa1["p5_hz"] < fa1["p50_hz"] < fa1["p95_hz"]
    assert set(fa1["in_margin_band"]) >= {"1P", "3P"}
    # f ∝ √E: the normalised sensitivity of every bending frequency to E is 1/2
    sens = u["sensitivities"]["tower.material.youngs_modulus_pa"]
    assert sens["tower.fa1"] == pytest.approx(0.5, abs=1e-3)


def test_lognormal_and_uniform_factors():
    rng = np.random.default_rng(0)
    q_ln = spec.Quantity(
        value=1.0, provenance="representative", tolerance=2.0, distribution="lognormal"
    )
    x = uncertainty.draw(q_ln, 50_000, rng)
    assert np.std(np.log(x)) == pytest.approx(math.log(2.0), rel=0.02)  # ×/÷ 2 at 1 σ
    q_u = spec.Quantity(
        value=1.0, provenance="representative", tolerance=0.15, distribution="uniform"
    )
    u = uncertainty.draw(q_u, 50_000, rng)
    assert u.min() >= 0.85 and u.max() <= 1.15


def test_runs_unchanged_on_a_local_dask_cluster():
    distributed = pytest.importorskip(
        "distributed",
        reason="the 'distributed' extra is not installed (pip install 'wtvib[distributed]')",
    )
    s = cantilever()
    local = uncertainty.sample(s, 2000, seed=11, chunk=500).frequencies["tower.fa1"]
    with (
        distributed.LocalCluster(
            n_workers=1, threads_per_worker=2, processes=False, dashboard_address=None
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        remote = uncertainty.sample_distributed(s, 2000, 11, client, chunk=500)
    assert np.array_equal(local, remote.frequencies["tower.fa1"])


TIGHT = """\
wtvib: 1
turbine: {name: tight tolerance}
rotor:
  blades: 3
  orientation: upwind
  hub: rigid
  speed: {min_rpm: 8, max_rpm: 14}
tower:
  modes:
    fa1: {value: 0.35, provenance: representative, tolerance: 1.0e-9}
blade:
  modes:
    flap1: {value: 0.62, provenance: representative, tolerance: 1.0e-9}
"""


def test_probabilities_agree_with_the_deterministic_checks_of_the_run(tmp_path):
    """With a vanishing tolerance every sample is the nominal turbine, so the
    probability of a margin violation is 1 exactly where the run's own check finds one in
    steady operation and 0 elsewhere — under the run's margin (--margin), over the whole
    steady range (2P at 10.5 rpm here is partial load, not the 14 rpm dwell speed), and
    along the blade's rotating curve (flap1 0.62 Hz at standstill, Southwell K = 1.19)."""
    p = tmp_path / "t.yaml"
    p.write_text(TIGHT)
    s = spec.load(p)
    for margin in (0.05, 0.10, 0.20):
        settings = audit.override(s.audit, margin=margin)
        r = audit.run(s, settings, samples=200, seed=1)
        assert r.uncertainty is not None and f"{margin:.0%}" in r.uncertainty["rule"]
        for c in r.checks:
            if ".resonance." not in c.id or c.numbers.get("energy") == "minor":
                continue
            sub, line = c.subsystem, c.numbers["excitation"]
            mode = f"{sub}.{'fa1' if sub == 'tower' else 'flap1'}"
            prob = r.uncertainty["modes"][mode]["in_margin_band"][line]["probability"]
            steady = c.numbers["regime"] in ("steady", "quick-pass")
            assert prob == (1.0 if steady else 0.0), (margin, c.id, c.status, prob)


def test_uncertainty_without_any_tolerance_says_so_in_one_line(write_spec):
    from typer.testing import CliRunner

    from wtvib.cli import app

    result = CliRunner().invoke(app, ["check", str(write_spec()), "--uncertainty", "--no-plot"])
    assert result.exit_code in (0, 1)
    lines = [ln for ln in result.stderr.splitlines() if "tolerance" in ln]
    assert len(lines) == 1 and "no value in the spec carries a tolerance" in lines[0]
    assert "tolerance: 0.05" in lines[0]  # how to add one


def test_uncertainty_runs_the_audit_once(monkeypatch):
    """--uncertainty ran the whole audit once per 2,000-sample chunk plus twice
    per uncertain input for the sensitivities (7 audits for one run); now the audit runs
    once and hands its modes to one batched sampling."""
    calls = []
    real = audit._run

    def counted(*args, **kwargs):  # type: ignore[no-untyped-def]
        calls.append(1)
        return real(*args, **kwargs)

    monkeypatch.setattr(audit, "_run", counted)
    report = audit.run(cantilever(), samples=6000, seed=2)
    assert len(calls) == 1
    assert report.uncertainty is not None and report.uncertainty["samples"] == 6000
