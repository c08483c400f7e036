"""Tuned mass dampers on the tower (wtvib.subsystems.mass_damper, tower.dampers), against closed
forms: a damper on a rigid mount, a damper on a one-mass structure (the two-degree-of-freedom
system's characteristic polynomial, solved here on its own), and Den Hartog's optimum."""

import math

import numpy as np
import pytest

from tests.conftest import SHARED
from wtvib import audit, importers
from wtvib.numerics import modal
from wtvib.spec.tower import MassDamper
from wtvib.subsystems import mass_damper


def _damper(mass: float, k: float, c: float, on: str = "nacelle") -> MassDamper:
    return MassDamper(
        name="test", on=on, height_m=0.0, direction="fore-aft", mass_kg=mass,
        stiffness_n_m=k, damping_ns_m=c,
    )  # fmt: skip


def _two_dof_roots(m1: float, k1: float, c1: float, m2: float, k2: float, c2: float) -> np.ndarray:
    """The roots with Im λ > 0 of det(λ²M + λD + K) for a mass m1 on ground (k1, c1) carrying
    m2 on (k2, c2): the quartic's coefficients written out by hand."""
    # (m1λ² + (c1+c2)λ + k1+k2)(m2λ² + c2λ + k2) − (c2λ + k2)² = 0
    a = np.polymul([m1, c1 + c2, k1 + k2], [m2, c2, k2])
    b = np.polymul([c2, k2], [c2, k2])
    roots = np.roots(np.polysub(a, b))
    up = roots[roots.imag > 0]
    return up[np.argsort(np.abs(up))]


@pytest.mark.parametrize("c2", [0.0, 1500.0, 6000.0])
def test_a_damper_on_a_one_mass_structure_has_the_two_dof_roots(c2):
    """A 100 t mass on 4e6 N/m (1 % damped) carrying a 2 t damper tuned near it: the damped
    modes (|λ|/2π, −Re λ/|λ|) are the quartic's roots, undamped and damped."""
    m1, k1 = 1.0e5, 4.0e6
    zeta1 = 0.01
    c1 = 2 * zeta1 * math.sqrt(k1 * m1)
    m2, k2 = 2.0e3, 2.0e3 * (math.sqrt(k1 / m1) / 1.02) ** 2
    roots = mass_damper.damped_modes(
        np.array([[k1]]), np.array([[m1]]), [_damper(m2, k2, c2)], [np.array([1.0])],
        lambda r, f: zeta1, count=1,
    )  # fmt: skip
    want = _two_dof_roots(m1, k1, c1, m2, k2, c2)
    got = sorted(roots, key=lambda r: r.frequency_hz)
    assert [r.frequency_hz for r in got] == pytest.approx(np.abs(want) / (2 * np.pi), rel=1e-9)
    assert [r.damping_ratio for r in got] == pytest.approx(-want.real / np.abs(want), abs=1e-9)
    # the root moving the structure more keeps its name, the other is the damper's
    assert sorted(r.bare is None for r in got) == [False, True]


def test_den_hartog_s_optimum_damps_both_modes_alike():
    """Tuned and damped as Den Hartog's optimum (frequency ratio 1/(1 + μ), ζ_d =
    √(3μ/(8(1 + μ)³))) on an undamped mass, the two modes carry about the same damping, near
    √(μ/8)·… — within 15 % of each other and of the equivalent ratio 1/(2√(1 + 2/μ)) the
    blade tip damper uses (tuned_damper.equivalent_damping; Den Hartog 1956, §3.3)."""
    from wtvib.aero.tuned_damper import equivalent_damping, optimal_tuning

    m1, k1, mu = 1.0e5, 4.0e6, 0.02
    ratio, zeta_d = optimal_tuning(mu)
    m2 = mu * m1
    w2 = ratio * math.sqrt(k1 / m1)
    damper = _damper(m2, m2 * w2**2, 2 * zeta_d * m2 * w2)
    roots = mass_damper.damped_modes(
        np.array([[k1]]), np.array([[m1]]), [damper], [np.array([1.0])], lambda r, f: 0.0, 1
    )
    zetas = [r.damping_ratio for r in roots]
    assert zetas[0] == pytest.approx(zetas[1], rel=0.15)
    for z in zetas:
        assert z == pytest.approx(equivalent_damping(mu), rel=0.15)


def test_a_damper_on_a_rigid_mount_oscillates_alone():
    """Nothing moves under it: √(k/m)/2π and c/(2√(km)) exactly (the r-test StC case's
    2291.5 kg, 229.15 N/m, 22.915 N·s/m: 0.050329 Hz, ζ 0.015811)."""
    d = _damper(2291.5, 229.15, 22.915)
    assert d.frequency_hz == pytest.approx(math.sqrt(0.1) / (2 * math.pi), rel=1e-12)
    assert d.damping_ratio == pytest.approx(22.915 / (2 * math.sqrt(229.15 * 2291.5)), rel=1e-12)


def test_the_attachment_is_the_mounting_points_motion():
    """On the nacelle, the tower top's deflection plus its slope times the height above it;
    on the tower, the node's deflection; on a clamped base, nothing."""
    nodes = np.array([0.0, 10.0, 20.0])
    size = 4  # a clamped base: (u, u′) of the two upper nodes
    nac = mass_damper.attachment(nodes, size, _damper(1.0, 1.0, 0.0).model_copy(
        update={"height_m": 2.5}))  # fmt: skip
    assert nac.tolist() == [0.0, 0.0, 1.0, 2.5]
    mid = mass_damper.attachment(nodes, size, _damper(1.0, 1.0, 0.0, on="tower").model_copy(
        update={"height_m": 10.0}))  # fmt: skip
    assert mid.tolist() == [1.0, 0.0, 0.0, 0.0]
    base = mass_damper.attachment(nodes, size, _damper(1.0, 1.0, 0.0, on="tower"))
    assert not base.any()


@pytest.fixture(scope="module")
def nrel_with_damper():
    """The NREL 5-MW ElastoDyn deck with a nacelle damper of 7 t tuned 2 % below its first
    fore-aft mode, 8.6 % damped."""
    if not SHARED.exists():
        pytest.skip("../shared is not beside the project")
    s = importers.load(
        SHARED / "reference/NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat",
        importers.ReadOptions(rpm=(6.9, 12.1)),
    )
    w = 2 * math.pi * 0.3142 / 1.02
    d = _damper(7000.0, 7000.0 * w**2, 2 * 7000.0 * w * 0.086)
    return s.model_copy(update={"tower": s.tower.model_copy(update={"dampers": [d]})})


def test_a_tuned_damper_splits_the_tower_mode_in_the_isolated_and_the_coupled_model(
    nrel_with_damper,
):
    """The first fore-aft mode splits in two on either side of the bare tower's, both far
    better damped than the tower's own 0.35 %; the coupled model (system.damper1 and
    system.tower.fa1) agrees with the isolated one within 2.5 % in frequency (its head's
    rotor is flexible), and the side-side mode is untouched by a fore-aft damper."""
    s = nrel_with_damper
    bare = s.model_copy(update={"tower": s.tower.model_copy(update={"dampers": []})})
    before = {m.id: m for m in audit.run(bare).modes}
    after = {m.id: m for m in audit.run(s).modes}
    f0 = before["tower.fa1"].frequency_hz
    low, high = sorted((after["tower.damper1"].frequency_hz, after["tower.fa1"].frequency_hz))
    assert low < f0 < high
    for name in ("tower.damper1", "tower.fa1", "system.damper1", "system.tower.fa1"):
        assert after[name].damping_ratio > 0.03, name
    assert after["system.damper1"].frequency_hz == pytest.approx(
        after["tower.damper1"].frequency_hz, rel=0.025
    )
    assert after["tower.ss1"].frequency_hz == pytest.approx(
        before["tower.ss1"].frequency_hz, rel=1e-9
    )
    assert after["tower.damper1"].superseded_by == "system.damper1"


def test_modal_damping_keeps_each_mode_s_ratio():
    """D = M·Φ·diag(2ζω)·ΦᵀM: each undamped mode keeps its ratio (a two-mass chain)."""
    k = np.array([[3.0e6, -1.0e6], [-1.0e6, 1.0e6]])
    m = np.diag([2.0e4, 1.0e4])
    bare = modal.solve(k, m)
    zeta = np.array([0.01, 0.03])
    d = mass_damper.modal_damping(m, bare, zeta)
    lam, _ = modal.oscillations(k, m, d)
    assert modal.damping_ratio(lam) == pytest.approx(zeta, rel=1e-9)
