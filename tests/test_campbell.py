"""The Campbell data: the judged frequency curves and the damping they are judged with."""

import numpy as np

from wtvib import audit
from wtvib.judge.excitation import operating_range
from wtvib.outputs.files import campbell_to_csv
from wtvib.spec import load


def test_structural_campbell_samples_standstill_to_overspeed(write_spec):
    spec = load(
        write_spec(speed="min_rpm: 10\nmax_rpm: 20", extra="blade: {modes: {flap1: 1.2}}\n")
    )
    report = audit.run(spec)
    data = report.campbell.to_dict()
    assert data["damping"] == "structural" and "wind_m_s" not in data
    rpm = np.array(data["rpm"])
    assert rpm[0] == 0 and rpm[-1] == __import__("pytest").approx(
        operating_range(spec.rotor.speed).overspeed * 30 / np.pi, rel=1e-6
    )
    flap = data["modes"]["blade.flap1"]
    mode = next(m for m in report.modes if m.id == "blade.flap1")
    np.testing.assert_allclose(flap["frequency_hz"], mode.frequency_at(rpm * np.pi / 30), atol=1e-6)
    assert set(flap["damping_ratio"]) == {mode.damping_ratio}
    assert set(data["modes"]["tower.fa1"]["frequency_hz"]) == {0.5}  # a constant line


def test_campbell_csv_has_a_row_per_mode_and_sample(write_spec):
    report = audit.run(load(write_spec(extra="blade: {modes: {flap1: 1.2, edge1: 2.0}}\n")))
    csv = campbell_to_csv(report.campbell).splitlines()
    assert csv[0] == (
        "mode,rpm,wind_m_s,pitch_deg,frequency_hz,damping_ratio,aerodynamic_damping_ratio,"
        "aeroelastic_frequency_hz,damped_frequency_hz,method,quasi_steady_damping_ratio"
    )
    assert len(csv) == 1 + 3 * 30  # tower.fa1, blade.flap1, blade.edge1 × 30 speeds
    assert any(line.startswith("blade.flap1,0.0000,,,") for line in csv)


def test_aeroelastic_campbell_follows_the_operating_points(shared):
    from wtvib.importers import load as load_any

    report = audit.run(load_any(shared / "reference/NREL5MW/NREL-5MW.fst"))
    data = report.to_dict()["campbell"]
    assert data["damping"].startswith("in operation")
    # Each point says how it was obtained, with the aeroelastic root's natural and
    # damped frequencies; no oscillating point carries ζ > 1, an overdamped one none
    for mid, mode in data["modes"].items():
        if "method" not in mode:
            continue
        for z, how, fd in zip(
            mode["damping_ratio"], mode["method"], mode.get("damped_frequency_hz", []), strict=False
        ):
            assert how in ("eigenvalue", "overdamped", "first-order", "isolated"), mid
            assert z <= 1.0 and (how != "overdamped" or (z == 1.0 and fd == 0.0)), mid
    flap = data["modes"]["system.blade.flap1.collective"]
    assert set(flap["method"]) <= {"eigenvalue", "overdamped", "first-order"}
    assert len(flap["aeroelastic_frequency_hz"]) == len(flap["damping_ratio"])
    # the quasi-steady damping beside the judged one, for comparison: the shed wake's lag
    # of the lift takes damping from the flap modes (tests/validation/test_unsteady.py)
    steady = np.asarray(flap["quasi_steady_damping_ratio"])
    assert len(steady) == len(flap["damping_ratio"])
    assert np.all(np.asarray(flap["damping_ratio"]) < steady)
    n = len(data["wind_m_s"])
    assert n == len(data["rpm"]) == len(data["pitch_deg"]) >= 25
    fa = data["modes"]["system.tower.fa1"]
    mode = next(m for m in report.modes if m.id == "system.tower.fa1")
    assert mode.operating is not None
    np.testing.assert_allclose(fa["damping_ratio"], mode.operating.total, atol=1e-6)
    assert all(not k.startswith("tower.") for k in data["modes"])  # superseded: not judged
