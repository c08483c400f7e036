"""The yaw system: one-mass frequency, gear play as a dead-zone spring, its protocol."""

import math

import numpy as np
import pytest

from tests.conftest import spec_text
from wtvib import audit, spec
from wtvib.subsystems import yaw

YAW = """tower_head: {mass_kg: 300000, inertia_yaw_kgm2: 2.0e7}
yaw:
  drive_stiffness_nm_rad: 2.0e9
"""


def test_one_mass_yaw_frequency(write_spec):
    # f = √(k/J)/2π = √(2e9/2e7)/2π = 1.5915 Hz (rigid tower in torsion)
    s = spec.load(write_spec(spec_text() + YAW, name="y.yaml"))
    (first,) = [m for m in yaw.build_modes(s, {}) if m.id == "yaw.1"]
    assert first.frequency_hz == pytest.approx(math.sqrt(2e9 / 2e7) / (2 * math.pi))
    assert first.origin == "computed"


def test_describing_function_of_the_dead_zone():
    # the docstring's values (Gelb & Vander Velde ch. 2): A/δ = 1.2, 2, 5 → N/k
    assert yaw.describing_function(np.array([1.2, 2.0, 5.0])) == pytest.approx(
        [0.0796, 0.3910, 0.7471], abs=1e-4
    )
    assert float(yaw.describing_function(0.5)) == 0.0  # inside the gap: no stiffness


def test_springs_in_series():
    assert yaw.series(2.0, 2.0) == pytest.approx(1.0)


def test_yaw_analysis_adds_its_own_checks(write_spec):
    s = spec.load(write_spec(spec_text() + YAW, name="y.yaml"))
    ids = [c.id for c in audit.run(s).checks if c.subsystem == "yaw"]
    assert "yaw.moments" in ids and any(i.startswith("yaw.resonance.") for i in ids)


def test_a_head_without_any_yaw_inertia_is_one_line_with_the_field(write_spec):
    # found by the unit tests: the CM on the tower axis and no inertia gave J = 0 and a
    # ZeroDivisionError (an internal error); it is the user's missing input
    from wtvib.errors import SpecError

    text = spec_text() + "tower_head: {mass_kg: 3.0e5}\nyaw:\n  drive_stiffness_nm_rad: 2.0e9\n"
    with pytest.raises(SpecError) as err:
        audit.run(spec.load(write_spec(text, name="z.yaml")))
    assert err.value.path == "tower_head.inertia_yaw_kgm2"


def test_a_head_yaw_inertia_below_half_the_rotors_polar_is_refused():
    """The extreme-value campaign: on the two-bladed Aeroman a yaw inertia
    below J_p/2 made the lowest instantaneous inertia negative and a math domain error;
    the head's mean yaw inertia includes the rotor's J_p/2, so it is the input's error."""
    from tests.conftest import TURBINES
    from wtvib.errors import SpecError
    from wtvib.spec.yamlio import parse_plain

    data = parse_plain((TURBINES / "aeroman.yaml").read_text()).data
    data["yaw"]["rotor_polar_inertia_kgm2"]["value"] = 1.0e9
    s = spec.from_data(data)
    with pytest.raises(SpecError, match="must exceed half the rotor's polar inertia") as err:
        audit.run(s)
    assert err.value.path == "yaw.inertia_kgm2"


def test_the_moment_budget_carries_the_gyroscopic_moment_of_the_yawing_rotor():
    """Aeroman retrofit, two blades: J_p 2,456 kg·m² (its spec), 56 rpm, yawing at 3 °/s —
    J_p·Ω·Ω_yaw = 2456 · (56·π/30) · (3·π/180) = 754.1 N·m, the tilt moment's mean over a
    revolution and (sin 2ψ) the yaw moment's peak (Hau 6.8, 7.4.1)."""
    import math

    from tests.conftest import TURBINES

    expected = 2456 * (56 * math.pi / 30) * math.radians(3)
    report = audit.run(spec.load(TURBINES / "aeroman-retrofit.yaml"))
    budget = next(c for c in report.checks if c.id == "yaw.moments")
    assert budget.numbers["gyroscopic_nm"] == pytest.approx(expected, rel=1e-6)
    assert f"up to {expected:,.0f} N·m about the yaw axis" in budget.message
    # three blades: the same mean, constant, and nothing about the yaw axis
    s = spec.load(TURBINES / "aeroman-retrofit.yaml")
    three = s.model_copy(update={"rotor": s.rotor.model_copy(update={"blades": 3})})
    budget = next(c for c in audit.run(three).checks if c.id == "yaw.moments")
    assert budget.numbers["gyroscopic_nm"] == pytest.approx(expected, rel=1e-6)
    assert f"{expected:,.0f} N·m, constant, about the tilt axis" in budget.message


def test_a_two_bladed_rotors_yaw_inertia_swings_by_half_its_polar_inertia():
    """Two blades, each J_p/2 about the shaft, at azimuth ψ and ψ + π: their inertia about
    the vertical yaw axis is J_p·sin²ψ (written out here over a revolution), which swings
    ±J_p/2 about its mean — the yaw model's variation (Aeroman retrofit: J_p 2,456 kg·m²),
    and the yaw frequency's range follows from the mean ± that swing."""
    import math

    from tests.conftest import TURBINES

    s = spec.load(TURBINES / "aeroman-retrofit.yaml")
    j_p = yaw.rotor_polar_inertia(s)
    psi = np.linspace(0, 2 * math.pi, 721)
    about_yaw = sum(j_p / 2 * np.sin(psi + k * math.pi) ** 2 for k in range(2))
    swing = (about_yaw.max() - about_yaw.min()) / 2
    mdl = yaw.model(s)
    assert j_p == pytest.approx(2456) and mdl.inertia_variation == pytest.approx(swing, rel=1e-6)
    check = next(c for c in audit.run(s).checks if c.id == "yaw.inertia")
    low, high = check.numbers["frequency_range_hz"]
    assert high == pytest.approx(mdl.frequencies(inertia=mdl.inertia - swing)[0], rel=1e-5)
    assert low == pytest.approx(mdl.frequencies(inertia=mdl.inertia + swing)[0], rel=1e-5)


def test_coulomb_friction_damps_the_yaw_modes_by_equal_energy_per_cycle():
    """Aeroman retrofit: the yaw modes' damping from the friction (and, parked, the brakes)
    is Den Hartog's equivalent viscous ratio ζ = 2·M/(π·J·ω²·A) at the mode's own angular
    frequency ω = 2π·f and the spec's amplitude A (Mechanical Vibrations §8.3), written out
    here for every yaw mode it damps."""
    import math

    from tests.conftest import TURBINES

    s = spec.load(TURBINES / "aeroman-retrofit.yaml")
    mdl = yaw.model(s)
    y = s.yaw
    modes = {m.id: m for m in yaw.modes(s)}
    moment = {"yaw.1": y.friction_moment_nm, "yaw.play.1": y.friction_moment_nm}
    moment["yaw.parked.1"] = y.brake_moment_nm + y.friction_moment_nm
    # the amplitude: the play's, else the cyclic yaw moment's static twist of the drives
    amplitude = mdl.amplitude or y.yaw_moment_amplitude_nm / mdl.drive
    judged = 0
    for mode_id, m_f in moment.items():
        if mode_id not in modes:
            continue
        m = modes[mode_id]
        omega = 2 * math.pi * m.frequency_hz
        expected = min(2 * m_f / (math.pi * mdl.inertia * omega**2 * amplitude), 0.99)
        assert m.damping_ratio == pytest.approx(expected, rel=1e-9), mode_id
        judged += 1
    assert judged >= 1


def test_the_rotors_polar_inertia_is_given_or_the_chains_blades_and_hub():
    """J_p about the shaft: the yaw block's value where given; else the drive train's first
    two masses when the first is the blades (blades 2,400 + hub 56 kg·m² here, by hand);
    nothing to take from a chain that does not start with its blades."""
    from tests.conftest import TURBINES

    s = spec.load(TURBINES / "aeroman-retrofit.yaml")
    dt = s.drivetrain
    chain = [
        dt.chain[0].model_copy(update={"name": "blades", "inertia_kgm2": 2400.0}),
        dt.chain[1].model_copy(update={"name": "hub", "inertia_kgm2": 56.0}),
    ]
    two = s.model_copy(
        update={
            "yaw": s.yaw.model_copy(update={"rotor_polar_inertia_kgm2": None}),
            "drivetrain": dt.model_copy(update={"chain": chain, "shafts": dt.shafts[:1]}),
        }
    )
    assert yaw.rotor_polar_inertia(two) == pytest.approx(2456.0)
    given = two.model_copy(
        update={"yaw": two.yaw.model_copy(update={"rotor_polar_inertia_kgm2": 3e3})}
    )
    assert yaw.rotor_polar_inertia(given) == 3e3
    hub_first = [chain[1], chain[0].model_copy(update={"name": "rotor"})]
    other = two.model_copy(
        update={"drivetrain": two.drivetrain.model_copy(update={"chain": hub_first})}
    )
    assert yaw.rotor_polar_inertia(other) is None


def test_the_yaw_drives_dashpot_damps_the_yaw_mode(shared):
    """ServoDyn's YawDamp (the NREL 5-MW's 1.916e7 N·m·s/rad) is read and damps the yaw
    mode by ζ = c/(2·J·ω) in the one-mass model (J the head's yaw inertia, ω its frequency)
    — and in the coupled model, where OpenFAST's linearisation of r-test's
    5MW_Land_Linear_Aero has ζ 0.046 (test_rtest_models.py holds it within 20 %)."""
    from wtvib import importers

    s = importers.load(shared / "reference/NREL5MW/NREL-5MW.fst")
    assert s.yaw.drive_damping_nms_rad == pytest.approx(1.916e7, rel=1e-3)
    m = {mode.id: mode for mode in yaw.modes(s)}["yaw.1"]
    inertia = yaw.model(s).inertia
    want = s.yaw.drive_damping_nms_rad / (2 * inertia * 2 * math.pi * m.frequency_hz)
    assert m.damping_ratio == pytest.approx(want, rel=1e-12)
    assert 0.02 < want < 0.08
