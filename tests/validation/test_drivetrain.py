"""Drive-train torsion against analytic and published values.

Two-mass closed forms (any vibration text, e.g. Den Hartog, *Mechanical Vibrations*, §5.2):
free–free ω² = k·(1/J₁ + 1/J₂); one end clamped ω² = roots of J₁J₂ω⁴ − (k(J₁+J₂)+… ) —
derived in the tests. Generator coupling examples: DOMAIN.md §3 (c_m ≈ 33,080
N·m/rad, d_m ≈ 6,019 N·m·s/rad). NREL 5-MW: Jonkman et al. 2009, NREL/TP-500-38060,
Table 9-1: 1st drivetrain torsion 0.6205 Hz (FAST) / 0.6094 Hz (ADAMS), parked with the
generator locked (RotSpeed = 0, GenDOF = False, NREL forum answer by J. Jonkman).
"""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from wtvib import audit, importers, spec
from wtvib.numerics import modal
from wtvib.subsystems import drivetrain


def two_mass(j1=1.0e6, j2=2.0e5, k=3.0e7, ratio=1.0, reference="rotor", c=0.0, **dt):
    """A two-mass train; the second mass and its shaft may turn ``ratio`` times faster; the
    shaft's damper ``c`` [N·m·s/rad]."""
    data = {
        "wtvib": 1,
        "turbine": {"name": "two-mass"},
        "rotor": {"blades": 3, "orientation": "upwind", "hub": "rigid", "speed": {"fixed_rpm": 20}},
        "drivetrain": {
            "chain": [
                {"name": "rotor", "inertia_kgm2": j1},
                {"name": "generator", "inertia_kgm2": j2 / ratio**2, "speed_ratio": ratio},
            ],
            "shafts": [{"stiffness_nm_rad": k, "damping_nms_rad": c}],
            "reference_shaft": reference,
            **dt,
        },
    }
    return spec.from_data(data)


def frequencies(s, condition):
    chain = drivetrain.reduce(s)
    m, k, d = drivetrain.system(chain, s, condition)
    return modal.damped(k, m, d)


def test_free_free_two_mass():
    # ω² = k(1/J₁ + 1/J₂) = 3e7·(1e-6 + 5e-6) = 180
    res = frequencies(two_mass(), "free")
    assert res.rigid == 1  # the 0 Hz rigid-body mode (a double root of the state matrix)
    assert res.frequency_hz[0] == pytest.approx(math.sqrt(180) / (2 * math.pi), rel=1e-6)


def test_clamped_two_mass_is_one_mass_on_the_shaft():
    # generator clamped (brake): ω² = k/J₁ = 30
    res = frequencies(two_mass(), "locked")
    assert res.frequency_hz == pytest.approx([math.sqrt(30) / (2 * math.pi)], rel=1e-6)


def test_two_mass_with_grid_spring():
    # synchronous generator on the grid, P = 0 → c_m = p²·P_max/(2πf) on the generator shaft;
    # |K − ω²M| = 0 with K = [[k, −k], [−k, k + c]], M = diag(J₁, J₂):
    # J₁J₂ω⁴ − (J₁(k + c) + J₂k)ω² + k·c = 0
    gm = {
        "rated_power_kw": 1.0,
        "pole_pairs": 2,
        "grid_frequency_hz": 50,
        "pull_out_power_kw": 3000,
    }
    s = two_mass(generator="synchronous", grid_coupling="direct", generator_model=gm)
    c = drivetrain.synchronous_stiffness(3e6, 1e3, 2, 50.0)
    j1, j2, k = 1.0e6, 2.0e5, 3.0e7
    a, b, cc = j1 * j2, -(j1 * (k + c) + j2 * k), k * c
    roots = sorted(
        math.sqrt((-b + sgn * math.sqrt(b * b - 4 * a * cc)) / (2 * a)) for sgn in (-1, 1)
    )
    res = frequencies(s, "grid")
    assert res.frequency_hz == pytest.approx([r / (2 * math.pi) for r in roots], rel=1e-6)


def test_synchronous_stiffness_example():
    # P_max 3 MW, P 1.5 MW, p = 2, 50 Hz: δ₀ = asin(0.5) = 30°, c_m = 4·3e6·cos30°/(2π·50)
    assert drivetrain.synchronous_stiffness(3e6, 1.5e6, 2, 50.0) == pytest.approx(33_080, rel=1e-3)


def test_induction_damping_example():
    # 1.5 MW, s = 1 %, p = 2, 50 Hz; rated torque at the supersynchronous speed Ω_s(1 + s):
    # T = 1.5e6/(157.08·1.01) = 9,454.7 N·m, d_m = T/(0.01·157.08) = 6,019 N·m·s/rad
    assert drivetrain.induction_damping(1.5e6, 0.01, 2, 50.0) == pytest.approx(6_019, rel=1e-3)


def test_induction_grid_leaves_a_zero_frequency_root():
    gm = {"rated_power_kw": 1500, "pole_pairs": 2, "grid_frequency_hz": 50, "rated_slip": 0.01}
    res = frequencies(
        two_mass(generator="induction", grid_coupling="direct", generator_model=gm), "grid"
    )
    assert res.rigid == 1  # the whole train turning on the damper: roots 0 and −d/J, no swing
    assert len(res.frequency_hz) == 1 and res.damping_ratio[0] > 0


@settings(max_examples=40, deadline=None)
@given(st.floats(1.5, 120.0), st.floats(1e4, 1e7), st.floats(1e6, 1e9))
def test_reference_shaft_does_not_change_frequencies(ratio, j2, k):
    """J′ = i²J, k′ = i²k: reduction to the generator shaft leaves the frequencies alone."""
    rotor = frequencies(two_mass(j2=j2, k=k, ratio=ratio, reference="rotor"), "free")
    gen = frequencies(two_mass(j2=j2, k=k, ratio=ratio, reference="generator"), "free")
    assert gen.frequency_hz == pytest.approx(rotor.frequency_hz, rel=1e-9)


def test_mode_names_say_who_swings_against_whom():
    s = two_mass()
    names = [m.description for m in drivetrain.modes(s)]
    assert any("generator against rotor" in n or "rotor against generator" in n for n in names)
    assert any("whole train against the brake" in n for n in names)


# --- NREL 5-MW from its ElastoDyn deck --------------------------------------------------


@pytest.fixture(scope="module")
def nrel(shared):
    s = importers.load(
        shared / "reference/NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat",
        importers.ReadOptions(rpm=(6.9, 12.1)),
    )
    return s, {m.id: m for m in audit.run(s).modes}


def test_nrel5mw_chain_from_the_deck(nrel):
    s, _ = nrel
    dt = s.drivetrain
    # DOMAIN.md §5: gear ratio 97, generator 534.116 kg·m² (HSS), shaft 8.67637e8 N·m/rad
    assert dt.gear_ratio == 97
    assert dt.chain[-1].inertia_kgm2 == 534.116 and dt.chain[-1].speed_ratio == 97
    assert dt.shafts[-1].stiffness_nm_rad == 8.67637e8
    # rotor inertia 38,759,236 kg·m² (blades + hub 115,926)
    assert dt.chain[0].inertia_kgm2 + dt.chain[1].inertia_kgm2 == pytest.approx(
        38_759_236, rel=0.01
    )


def test_nrel5mw_locked_three_mass_mode_is_table_9_1_drivetrain_torsion(nrel):
    # Locked generator, blades on their edgewise spring k_b = J_b·ω_edge² (edge frequency from
    # the blade model), hub, shaft: the first mode is the one Table 9-1 lists as "1st
    # drivetrain torsion", 0.6205 Hz (FAST) / 0.6094 Hz (ADAMS).
    _, m = nrel
    f = m["drivetrain.locked.1"].frequency_hz
    assert 0.6094 * 0.97 <= f <= 0.6205 * 1.03


def test_nrel5mw_free_two_mass_estimate(nrel):
    # Idling: the rigid-rotor two-mass estimate is √(k(1/J_rot + 1/(97²·534.116)))/2π =
    # 2.22 Hz; the blades' edgewise flexibility in series lowers it
    _, m = nrel
    rigid = math.sqrt(8.67637e8 * (1 / 38_759_236 + 1 / (97**2 * 534.116))) / (2 * math.pi)
    assert rigid == pytest.approx(2.22, abs=0.01)
    assert 0.7 * rigid < m["drivetrain.free.1"].frequency_hz < rigid


def test_forced_response_peaks_at_resonance():
    s = two_mass(k=3.0e7)
    chain = drivetrain.reduce(s)
    f_n = math.sqrt(180) / (2 * math.pi)
    below = drivetrain.torque_amplification(s, chain, "free", 0.2 * f_n)
    near = drivetrain.torque_amplification(s, chain, "free", 0.98 * f_n)
    # undamped free–free train: far below resonance the shaft passes J₂/(J₁+J₂) of the torque
    assert below == pytest.approx(2e5 / 1.2e6, rel=0.05)
    assert near > 10 * below


@pytest.mark.parametrize("condition", ["free", "locked"])
def test_shaft_torque_of_a_damped_two_mass_train_by_hand(condition):
    """The shaft torque per unit input torque on the rotor, (k + iωc)·θ, with the shaft's
    damper c and the modal damping 2ζω_n·μ that gives the train's elastic mode its ζ (one
    dashpot across the shaft, μ the mode's inertia). Free: the relative twist θ obeys
    μθ'' + (c + 2ζω_nμ)θ' + kθ = (J₂/(J₁ + J₂))·T, μ = J₁J₂/(J₁ + J₂); locked generator: the
    rotor alone on the shaft to ground, μ = J₁ and the whole torque. By hand at 0.3, 0.9, 1
    and 1.5 ω_n."""
    j1, j2, k, c, zeta = 1.0e6, 2.0e5, 3.0e7, 4.0e5, 0.02
    s = two_mass(j1, j2, k, c=c, damping_ratio=zeta)
    chain = drivetrain.reduce(s)
    mu, share = (j1 * j2 / (j1 + j2), j2 / (j1 + j2)) if condition == "free" else (j1, 1.0)
    w_n = math.sqrt(k / mu)
    for r in (0.3, 0.9, 1.0, 1.5):
        w = r * w_n
        theta = share / (k - w**2 * mu + 1j * w * (c + 2 * zeta * w_n * mu))
        expected = abs((k + 1j * w * c) * theta)
        got = drivetrain.torque_amplification(s, chain, condition, w / (2 * math.pi))
        assert got == pytest.approx(expected, rel=1e-9), r


def test_fixed_frequency_electrical_excitation_is_checked():
    # a converter-fed train (grid condition = free end) with a converter line on its mode
    f_n = math.sqrt(180) / (2 * math.pi)
    s = two_mass(
        generator="converter",
        grid_coupling="converter",
        electrical_excitations=[{"name": "converter", "frequency_hz": f_n * 1.02}],
    )
    c = next(c for c in audit.run(s).checks if c.id == "drivetrain.resonance.electrical.converter")
    assert c.status == "fail" and c.numbers["mode"] == "drivetrain.grid.1"
    assert c.numbers["excitation_hz"] == pytest.approx(f_n * 1.02, rel=1e-5)  # 6 digits
