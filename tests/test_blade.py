"""Blades: given modes stiffened by rotation (Southwell), the protocol's statements."""

import math

import numpy as np
import pytest

from tests.conftest import spec_text
from wtvib import audit, spec
from wtvib.results import Southwell
from wtvib.subsystems import blade

GIVEN = """blade:
  modes: {flap1: 0.84, edge1: {frequency_hz: 1.35, southwell: 0.19}}
"""


def test_given_blade_modes_rise_with_speed_by_southwell(write_spec):
    s = spec.load(write_spec(spec_text() + GIVEN, name="b.yaml"))
    modes = {m.id: m for m in blade.build_modes(s, {})}
    flap = modes["blade.flap1"]
    assert isinstance(flap.curve, Southwell) and flap.curve.k == pytest.approx(1.19)  # default
    omega = 2 * math.pi * 0.5  # 30 rpm: Ω/2π = 0.5 Hz
    assert float(flap.frequency_at(np.array([omega]))[0]) == pytest.approx(
        math.sqrt(0.84**2 + 1.19 * 0.25)
    )
    assert modes["blade.edge1"].curve.k == pytest.approx(0.19)  # type: ignore[union-attr]


def test_blade_analysis_states_how_computed_modes_came_about(shared):
    from wtvib import importers

    deck = shared / "reference" / "NREL5MW" / "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"
    r = audit.run(importers.load(deck, importers.ReadOptions(rpm=(6.9, 12.1))))
    assert any(a.startswith("Blade modes computed") for a in r.assumptions)
    assert {m.origin for m in r.modes if m.subsystem == "blade"} == {"computed"}


def test_the_pitch_drive_softens_the_blade_s_torsion_by_the_closed_form():
    """A uniform blade (GJ, I_p, length L) on a root spring k_p, free at the tip: θ =
    cos β(L − x), and GJ·θ′(0) = k_p·θ(0) gives βL·tan βL = k_p·L/GJ, ω = β·√(GJ/I_p)
    (Hau 7.2.2; the clamped root is k_p → ∞, βL = π/2)."""
    from scipy.optimize import brentq

    from wtvib.spec.blade import BladeStructure

    gj, ip, length, kp = 5e7, 20.0, 40.0, 2.5e6
    base = {
        "span_m": [0.0, length],
        "mass_per_length_kg_m": [200.0, 200.0],
        "ei_flap_nm2": [1e9, 1e9],
        "ei_edge_nm2": [3e9, 3e9],
        "gj_nm2": [gj, gj],
        "torsional_inertia_kgm": [ip, ip],
    }
    c = (gj / ip) ** 0.5
    clamped = blade.torsion_frequency(BladeStructure.model_validate(base), elements=60)
    assert clamped == pytest.approx(np.pi / 2 / length * c / (2 * np.pi), rel=1e-3)
    sprung = blade.torsion_frequency(
        BladeStructure.model_validate(base | {"pitch_drive_nm_rad": kp}), elements=60
    )
    bl = brentq(lambda z: z * np.tan(z) - kp * length / gj, 1e-9, np.pi / 2 - 1e-9)
    assert sprung == pytest.approx(bl / length * c / (2 * np.pi), rel=1e-3)
    assert sprung < clamped


def _uniform_beam(root: str) -> spec.BladeStructure:
    """The r-test Ideal_Beam: 100 m, EI 1.03713e12 N·m² both ways, 9517.14 kg/m."""
    return spec.BladeStructure(
        span_m=[0.0, 100.0],
        mass_per_length_kg_m=[9517.14, 9517.14],
        ei_flap_nm2=[1.03713e12, 1.03713e12],
        ei_edge_nm2=[1.03713e12, 1.03713e12],
        root=root,  # type: ignore[arg-type]
    )


@pytest.mark.parametrize(
    ("root", "betas"),
    [
        ("clamped", (1.875104, 4.694091)),  # the cantilever: cos βL cosh βL = −1
        ("free", (4.730041, 7.853205)),  # the free-free beam: cos βL cosh βL = 1
    ],
)
def test_a_uniform_beam_clamped_or_free_at_its_root_has_the_closed_form(root, betas):
    """f = (βL)²/(2πL²)·√(EI/m) for the first two bending modes in each plane (Euler–Bernoulli,
    e.g. Blevins, Formulas for Natural Frequency, Table 8-1): the free beam's four rigid-body
    modes are left out, so its first computed mode is its first bending. 0.5842/3.6607 Hz
    clamped, 3.7171/10.2465 free (r-test's Ideal_Beam frequencies.txt, 'Analytical')."""
    s = _uniform_beam(root)
    names, freqs, _, _ = blade.rotating_modes(s, np.array([0.0]), count=4)
    scale = math.sqrt(1.03713e12 / 9517.14) / (2 * math.pi * 100.0**2)
    got = dict(zip(names, freqs[0], strict=True))
    for k, beta in enumerate(betas, start=1):
        for plane in ("flap", "edge"):
            assert got[f"{plane}{k}"] == pytest.approx(beta**2 * scale, rel=1e-4)


def test_a_free_beam_s_torsion_leaves_its_rigid_turn_out():
    """A free beam's first torsion is the free-free one, π·√(GJ/(ρJ))/(2πL) — twice the
    clamped-free beam's (a uniform shaft's closed forms)."""
    s = _uniform_beam("free").model_copy(
        update={"gj_nm2": [7.98098e12] * 2, "torsional_inertia_kgm": [8.39584e4] * 2}
    )
    clamped = s.model_copy(update={"root": "clamped"})
    c = math.sqrt(7.98098e12 / 8.39584e4)
    assert blade.torsion_frequency(s) == pytest.approx(c / 200.0, rel=1e-3)
    assert blade.torsion_frequency(clamped) == pytest.approx(c / 400.0, rel=1e-3)


def test_a_free_beam_is_a_standstill_model(write_spec):
    """Nothing holds a free beam against the centrifugal force: its modes carry no curve over
    the rotor speed, however fast the spec's rotor turns, and the audit says so."""
    text = spec_text(speed="fixed_rpm: 12") + (
        "blade:\n  structure:\n    span_m: [0, 100]\n    mass_per_length_kg_m: [9517.14, "
        "9517.14]\n    ei_flap_nm2: [1.03713e12, 1.03713e12]\n    ei_edge_nm2: [1.03713e12, "
        "1.03713e12]\n    root: free\n"
    )
    report = audit.run(spec.load(write_spec(text)))
    modes = [m for m in report.modes if m.id.startswith("blade.")]
    assert modes and all(m.curve is None for m in modes)
    assert any("a free twisted beam" in a for a in report.assumptions)


def test_a_principal_axis_turned_by_half_a_turn_is_the_same_axis():
    """A twist table that writes one station's principal axes 180° on (the IEA-22's HAWC2
    st file steps from −27° to 143°) is the same blade: its modes are those of the table
    written the short way round, to rounding — where the angles interpolated as numbers
    would turn the element between through half a turn and move the modes."""
    span = [0.0, 20.0, 40.0, 60.0]
    base = {
        "span_m": span,
        "mass_per_length_kg_m": [800.0, 500.0, 300.0, 150.0],
        "ei_flap_nm2": [2e10, 8e9, 2e9, 4e8],
        "ei_edge_nm2": [4e10, 2e10, 6e9, 1.5e9],
    }
    short = spec.BladeStructure.model_validate(base | {"twist_deg": [15.0, 10.0, 20.0, 5.0]})
    wrapped = spec.BladeStructure.model_validate(base | {"twist_deg": [15.0, 10.0, -160.0, 5.0]})
    np.testing.assert_allclose(blade.principal_twist(wrapped), [15.0, 10.0, 20.0, 5.0])
    _, f_short, _, _ = blade.rotating_modes(short, np.array([0.0, 1.0]), count=4)
    _, f_wrapped, _, _ = blade.rotating_modes(wrapped, np.array([0.0, 1.0]), count=4)
    np.testing.assert_allclose(f_wrapped, f_short, rtol=1e-9)


@pytest.mark.parametrize("shear", [False, True])
def test_a_blade_twisted_to_feather_bends_downwind_towards_the_direction_of_rotation(shear):
    """A uniform cantilever twisted 30° to feather (its leading edge turned upwind), flapwise
    10 times softer than edgewise, pushed downwind at the tip: it bends about its weak axis,
    normal to the chord — downwind and towards its leading edge, the direction of rotation:
    v/w = C_vw/C_ww, the compliance tensor's ratio (1/EI_f − 1/EI_e)·sin β·cos β /
    (cos²β/EI_f + sin²β/EI_e), flap axis (cos β, sin β) in (w, v) — in Euler–Bernoulli and
    Timoshenko blades alike (shear far stiffer than bending here). A blade model with the
    twist's coupling mirrored bends it the other way (test_hawc2: HAWCStab2's DTU 10 MW
    blade leans as this one)."""
    from wtvib.numerics import beam

    ef, ee, beta = 1e9, 1e10, math.radians(30.0)
    fields = {
        "span_m": [0.0, 50.0],
        "mass_per_length_kg_m": [300.0, 300.0],
        "ei_flap_nm2": [ef, ef],
        "ei_edge_nm2": [ee, ee],
        "twist_deg": [30.0, 30.0],
    }
    if shear:
        fields |= {"ga_flap_n": [1e15, 1e15], "ga_edge_n": [1e15, 1e15]}
    s = spec.BladeStructure.model_validate(fields)
    nodes = beam.mesh(np.asarray(s.span_m), 20)
    k0, _, _, _ = blade.blade_parts(s, nodes)
    load = np.zeros(len(k0))
    load[-4] = 1.0  # the tip's w (dofs per node w, w′, v, v′; the root's four removed)
    tip = np.linalg.solve(k0, load)
    c, sn = math.cos(beta), math.sin(beta)
    expected = (1 / ef - 1 / ee) * sn * c / (c**2 / ef + sn**2 / ee)
    assert tip[-2] > 0 and tip[-4] > 0
    assert tip[-2] / tip[-4] == pytest.approx(expected, rel=1e-4)
