"""The blade.divergence and blade.flutter checks: data flow from the spec to the verdict."""

import math
from collections.abc import Callable
from pathlib import Path

import pytest

from wtvib import audit
from wtvib.aero import aeroelastic as ae
from wtvib.spec import load

from . import oracles

# A MW-class blade section (illustrative numbers, not a published blade): chord 3 m at
# 0.75 R, elastic axis at 30 % chord, centre of mass at 38 %, μ = m/(πρb²) ≈ 21.
BLADE = """\
blade:
  modes: {{flap1: 0.67, edge1: 1.08, tor1: {tor1}}}
  aeroelastic:
    speed_margin: 0.15
    sections:
      - {{radius_fraction: 0.75, chord_m: 3.0, elastic_axis_chord: 0.30,
          centre_of_mass_chord: {cg}, mass_per_length_kg_m: 180, torsional_inertia_kgm: 25}}
"""
SPEED = "min_rpm: 6.9\nrated_rpm: 12.1\nmax_rpm: 12.1"


def checks(path: Path) -> dict[str, dict[str, object]]:
    report = audit.run(load(path))
    return {c.id: c.to_dict() for c in report.checks if c.id.startswith("blade.")}


def spec(write_spec: Callable[..., Path], tor1: float = 5.6, cg: float = 0.38) -> Path:
    extra = "  rotor_diameter_m: 126\n"
    path = write_spec(speed=SPEED, extra=BLADE.format(tor1=tor1, cg=cg))
    text = path.read_text().replace(
        "turbine: {name: Test turbine}", "turbine:\n  name: T\n" + extra
    )
    path.write_text(text)
    return path


def test_section_speed_and_ratios_follow_from_the_spec(write_spec: Callable[..., Path]) -> None:
    c = checks(spec(write_spec))
    flutter, divergence = c["blade.flutter"], c["blade.divergence"]
    # section speed: overspeed 1.15 × 12.1 rpm (default factor) at r = 0.75·63 m, with 25 m/s
    omega = 1.15 * 12.1 * 2 * math.pi / 60
    w = math.hypot(omega * 47.25, 25.0)
    section = flutter["sections"][0]  # type: ignore[index]
    assert section["section_speed_m_s"] == pytest.approx(w, rel=1e-5)
    # the k-method cross-check lands on the p-k flutter speed
    assert section["flutter_speed_k_method_m_s"] == pytest.approx(
        section["flutter_speed_m_s"], rel=1e-5
    )
    assert flutter["speed_ratio"] == pytest.approx(section["flutter_speed_m_s"] / w, rel=1e-5)
    # divergence: q_D = k_θ/(e·c·C_Lα), k_θ = I(ω_θ² + Ω²) (propeller moment at β = 0)
    k_theta = 25 * ((2 * math.pi * 5.6) ** 2 + omega**2)
    v_d = math.sqrt(2 * k_theta / (0.05 * 3.0 * 3.0 * 2 * math.pi) / 1.225)
    assert divergence["sections"][0]["divergence_speed_m_s"] == pytest.approx(v_d, rel=1e-5)  # type: ignore[index]
    assert flutter["status"] == "pass" and divergence["status"] == "pass"


def test_a_soft_torsion_fails_flutter(write_spec: Callable[..., Path]) -> None:
    c = checks(spec(write_spec, tor1=2.5))
    assert c["blade.flutter"]["status"] == "fail"
    assert "flutter at" in str(c["blade.flutter"]["message"])


def test_mass_balanced_section_does_not_flutter(write_spec: Callable[..., Path]) -> None:
    # centre of mass ahead of the elastic axis: no flutter in the swept range (3× speed)
    c = checks(spec(write_spec, cg=0.25))
    assert c["blade.flutter"]["speed_ratio"] is None
    assert c["blade.flutter"]["status"] == "pass"


def test_missing_torsion_frequency_is_reported_not_guessed(
    write_spec: Callable[..., Path],
) -> None:
    path = spec(write_spec)
    path.write_text(path.read_text().replace(", tor1: 5.6", ""))
    c = checks(path)
    assert c["blade.flutter"]["status"] == "info"
    assert "blade.modes.tor1" in str(c["blade.flutter"]["message"])


def test_no_aeroelastic_block_no_checks(write_spec: Callable[..., Path]) -> None:
    report = audit.run(load(write_spec()))
    assert not [c for c in report.checks if c.id in ("blade.flutter", "blade.divergence")]
    assert ae.checks(load(write_spec()), report.modes) == ([], [])


def test_vg_and_stability_chart_drawn(write_spec: Callable[..., Path]) -> None:
    from wtvib.outputs.plots import diagrams

    figures = diagrams(audit.run(load(spec(write_spec))))
    assert {"blade-flutter", "blade-stability"} <= set(figures)
    # no planform or blade mass here: the stall checks are info, and there is no curve to draw
    assert "blade-stall" not in figures
    stall_rotor = Path(__file__).resolve().parents[1] / "turbines" / "stall-rotor-1mw.yaml"
    assert "blade-stall" in diagrams(audit.run(load(stall_rotor)))


def test_inertia_smaller_than_the_offset_mass_is_refused_with_the_field(
    write_spec: Callable[..., Path],
) -> None:
    # found by the fuzz campaign of 2026-11-23: I_EA < m·d² made the section's mass matrix
    # indefinite and the flutter solver produced NaN; it is a user mistake, named by field
    from wtvib.errors import SpecError

    path = spec(write_spec, cg=0.75)  # d = 0.45·3 m = 1.35 m: m·d² = 328 kg·m > 25
    with pytest.raises(SpecError, match="torsional_inertia_kgm") as info:
        load(path)
    assert info.value.line is not None


def test_whole_blade_divergence_lies_between_the_root_and_tip_pressure_bounds(
    write_spec: Callable[..., Path],
) -> None:
    # A uniform blade (GJ, e·c·C_Lα constant) under the rotor's pressure ½ρ((Ωr)² + V²):
    # its divergence load factor lies between the uniform-cantilever closed form
    # π²GJ/(4·e·c·C_Lα·l²) taken at the tip pressure and at the root pressure (DOMAIN.md §3)
    gj, length, hub = 5.0e6, 40.0, 2.0
    structure = f"""\
  structure:
    hub_radius_m: {hub}
    span_m: [0, {length}]
    mass_per_length_kg_m: [200, 200]
    ei_flap_nm2: [2.0e9, 2.0e9]
    ei_edge_nm2: [5.0e9, 5.0e9]
    gj_nm2: [{gj}, {gj}]
    torsional_inertia_kgm: [25, 25]
"""
    path = spec(write_spec)
    path.write_text(path.read_text().replace("  aeroelastic:\n", structure + "  aeroelastic:\n"))
    c = checks(path)["blade.divergence"]
    factor = c["cantilever_load_factor"]
    omega = 1.15 * 12.1 * 2 * math.pi / 60
    arm = (0.30 - 0.25) * 3.0 * 3.0 * 2 * math.pi  # e·c·C_Lα per unit pressure
    q_tip = 0.5 * 1.225 * ((omega * (hub + length)) ** 2 + 25.0**2)
    q_root = 0.5 * 1.225 * ((omega * hub) ** 2 + 25.0**2)
    closed = oracles.cantilever_divergence_closed_form(gj, arm, length)
    # pressure everywhere between q_root and q_tip bounds the factor; the propeller-moment
    # stiffness Ω²·I_θ ≈ 63 N·m/rad per m adds ≈ Ω²I·l²/GJ ≈ 2 % at most on top
    assert closed / q_tip < factor  # type: ignore[operator]
    assert factor < 1.05 * closed / q_root  # type: ignore[operator]
    assert "whole blade" in str(c["message"])
    # exactly: the torsion bar (validated against the closed form) under the pressure of each
    # station's air speed and the propeller moment's stiffness Ω²·I_θ·cos 2β, written out
    import numpy as np

    x = np.array([0.0, length])
    pressure = 0.5 * 1.225 * ((omega * (hub + x)) ** 2 + 25.0**2)
    spring = omega**2 * np.array([25.0, 25.0]) * math.cos(0.0)
    exact = ae.cantilever_divergence(x, np.full(2, gj), np.full(2, arm), pressure, spring)
    assert factor == pytest.approx(exact, rel=1e-5)
