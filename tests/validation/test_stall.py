"""Stall-induced vibration: modal aerodynamic damping against a closed form, and the checks.

Expected numbers: the attached-flow flap damping of a uniform blade follows from the
quasi-steady formula (DOMAIN.md §3) with ψ → 90° (inflow angle → 0):
c(r) = ½ρcΩr(C_L′ + C_D), ζ = ∫c φ² dr / (2ω ∫m φ² dr), φ the uniform cantilever's first
mode (Blevins, *Formulas for Natural Frequency and Mode Shape*, Table 8-1, β₁l = 1.87510).
"""

import math
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from wtvib import audit
from wtvib.aero import stall
from wtvib.spec import load

BETA_L = 1.87510407


def cantilever_shape(xi: np.ndarray) -> np.ndarray:
    b = BETA_L * xi
    s = (math.cosh(BETA_L) + math.cos(BETA_L)) / (math.sinh(BETA_L) + math.sin(BETA_L))
    return np.cosh(b) - np.cos(b) - s * (np.sinh(b) - np.sin(b))


def blade_spec(
    write_spec: Callable[..., Path],
    *,
    speed: str = "fixed_rpm: 20",
    winds: str = "{min_wind_m_s: 0.2, max_wind_m_s: 0.2}",
    polar: str = "polar: {alpha_deg: [-90, 0, 90], cl: [-9.8696044, 0, 9.8696044], "
    "cd: [0.01, 0.01, 0.01]}",
) -> Path:
    text = f"""\
wtvib: 1
turbine: {{name: T, rotor_diameter_m: 100}}
rotor:
  blades: 3
  orientation: upwind
  hub: rigid
  speed: {{{speed}}}
tower:
  modes: {{fa1: 0.3}}
blade:
  mass_kg: 10000
  modes:
    flap1: {{frequency_hz: 0.8, southwell: 0}}
    edge1: {{frequency_hz: 1.2, southwell: 0}}
    tor1: 6
  damping_ratio: 0.005
  aeroelastic:
    {polar}
    planform: {{radius_fraction: [0.0001, 1.0], chord_m: [2.0, 2.0], twist_deg: [0, 0]}}
    sections:
      - {{chord_m: 2, elastic_axis_chord: 0.3, centre_of_mass_chord: 0.3,
          mass_per_length_kg_m: 200, torsional_inertia_kgm: 20}}
"""
    for key, value in load_flow(winds).items():
        text += f"    {key}: {value}\n"
    return write_spec(text)


def load_flow(text: str) -> dict[str, object]:
    import yaml

    return dict(yaml.safe_load(text))


def check(path: Path, cid: str) -> dict[str, object]:
    report = audit.run(load(path))
    return next(c.to_dict() for c in report.checks if c.id == cid)


def test_attached_flow_flap_damping_matches_the_closed_form(
    write_spec: Callable[..., Path],
) -> None:
    # polar: a straight line C_L = 2π·α (π² at 90°), C_D = 0.01 — attached flow everywhere
    c = check(blade_spec(write_spec), "blade.stall.flap1")
    got = c["curve"][0]["aero_damping_ratio"]  # type: ignore[index]
    rho, chord, radius, omega = 1.225, 2.0, 50.0, 20 * 2 * math.pi / 60
    m = 10000 / (radius * (1 - 0.0001))  # blade mass spread over the planform
    xi = np.linspace(0, 1, 20001)  # r = R·ξ (the root at 0.0001 R is negligible)
    phi2 = cantilever_shape(xi) ** 2
    c_over_r = 0.5 * rho * chord * omega * (2 * math.pi + 0.01)  # c(r) = this × r
    expected = (c_over_r * radius * np.trapezoid(xi * phi2, xi)) / (
        2 * (2 * math.pi * 0.8) * m * np.trapezoid(phi2, xi)
    )
    assert got == pytest.approx(expected, rel=0.01)
    assert c["status"] == "pass"


def test_edgewise_damping_goes_negative_past_stall(write_spec: Callable[..., Path]) -> None:
    # the built-in thin-aerofoil/flat-plate polar: C_L′ < 0 past 12°; a fixed-speed stall
    # rotor at 20 rpm, R = 50 m: the outer blade stalls above ~ 12–13 m/s wind
    path = blade_spec(write_spec, winds="{min_wind_m_s: 4, max_wind_m_s: 25}", polar="")
    edge = check(path, "blade.stall.edge1")
    assert edge["status"] == "fail"
    curve = edge["curve"]
    low = [p for p in curve if p["wind_m_s"] <= 8]  # type: ignore[union-attr,index]
    assert all(p["aero_damping_ratio"] > 0 for p in low)  # attached: positive
    assert edge["min_total_damping_ratio"] < 0  # type: ignore[operator]
    flap = check(path, "blade.stall.flap1")
    # flapwise damping is large in attached flow (Hau ch. 7.2.3)
    assert min(p["aero_damping_ratio"] for p in flap["curve"][:4]) > 0.05  # type: ignore[index]


def test_pitch_regulation_stops_at_the_rated_wind(write_spec: Callable[..., Path]) -> None:
    path = blade_spec(
        write_spec,
        winds="{min_wind_m_s: 4, max_wind_m_s: 25, regulation: pitch, rated_wind_m_s: 11}",
        polar="",
    )
    edge = check(path, "blade.stall.edge1")
    assert max(p["wind_m_s"] for p in edge["curve"]) == 11  # type: ignore[union-attr]
    assert edge["status"] == "pass"


def test_missing_planform_is_reported(write_spec: Callable[..., Path]) -> None:
    path = blade_spec(write_spec)
    path.write_text(path.read_text().replace("    planform:", "    # planform:"))
    c = check(path, "blade.stall.edge1")
    assert c["status"] == "info" and "planform" in str(c["message"])


def test_builtin_polar_shape() -> None:
    cl, cd = stall.builtin_polar(np.array([0.0, 6.0, 12.0, 45.0, 90.0]))
    # thin aerofoil 2πα below stall; flat plate 2 sinα cosα, 2 sin²α from 45°
    assert cl[1] == pytest.approx(2 * math.pi * math.radians(6))
    assert cl[3] == pytest.approx(1.0) and cd[3] == pytest.approx(1.0)
    assert cd[4] == pytest.approx(2.0) and cl[4] == pytest.approx(0.0, abs=1e-12)


def test_builtin_polar_blends_continuously_into_the_flat_plate() -> None:
    """A mutation survivor (`stall` 67, tests/MUTATION.md): between stall (STALL_DEG) and the flat
    plate (FLAT_PLATE_DEG) lift and drag blend linearly in α — continuous at both ends (a jump in
    C_D there would be a step in the damping the stall check integrates), the drag halfway between
    its attached value and the plate's 2·sin²α_f."""
    import math

    eps = 1e-7
    for edge in (stall.STALL_DEG, stall.FLAT_PLATE_DEG):
        (cl_lo, cl_hi), (cd_lo, cd_hi) = stall.builtin_polar(np.array([edge - eps, edge + eps]))
        assert cl_lo == pytest.approx(cl_hi, abs=1e-6) and cd_lo == pytest.approx(cd_hi, abs=1e-6)
    mid = 0.5 * (stall.STALL_DEG + stall.FLAT_PLATE_DEG)
    _, cd = stall.builtin_polar(np.array([mid]))
    plate = 2 * math.sin(math.radians(stall.FLAT_PLATE_DEG)) ** 2
    assert cd[0] == pytest.approx(stall.CD0 + 0.5 * (plate - stall.CD0), rel=1e-12)
