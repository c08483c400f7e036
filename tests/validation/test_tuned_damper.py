"""The blade tip damper (wtvib/aero/tuned_damper.py) against Den Hartog's tuned mass damper,
computed here as a two-degree-of-freedom frequency response, and wired into the audit."""

import math
from pathlib import Path

import numpy as np
import pytest

from wtvib import audit, spec
from wtvib.aero import tuned_damper
from wtvib.aero.aerodamping import generalised_mass

TURBINES = Path(__file__).parents[2] / "turbines"


@pytest.mark.parametrize("mu", [0.01, 0.02, 0.05, 0.1])
def test_den_hartogs_optimum_caps_the_peak_at_the_equal_peak_value(mu):
    """A mode (mass 1, ω = 1) with a damper of mass μ at Den Hartog's optimal frequency
    ratio and damping: the largest amplification of the mode's static deflection over
    frequency is √(1 + 2/μ) (Den Hartog 1956, §3.3; his optimum gives nearly equal peaks:
    within 2.5 % up to μ = 0.1), and a single mode with the equivalent ζ_e has that same
    peak, 1/(2ζ_e)."""
    tuning, zeta_d = tuned_damper.optimal_tuning(mu)
    w = np.linspace(0.5, 1.5, 200_001)
    k_d, c_d = mu * tuning**2, 2 * zeta_d * mu * tuning
    link = k_d + 1j * w * c_d  # the damper's spring and dashpot at each frequency
    # [[1 − ω² + link, −link], [−link, −μω² + link]]·X = [1, 0]: the mode's response X₁
    a11, a22 = 1 - w**2 + link, -mu * w**2 + link
    peak = float(np.max(np.abs(a22 / (a11 * a22 - link * link))))
    # measured: +0.06 % (μ = 0.01), +0.16 %, +0.67 %, +2.1 % (μ = 0.1) above √(1 + 2/μ)
    assert peak == pytest.approx(math.sqrt(1 + 2 / mu), rel=0.025)
    assert peak >= math.sqrt(1 + 2 / mu)  # the equal-peak value is the optimum's floor
    assert 1 / (2 * tuned_damper.equivalent_damping(mu)) == pytest.approx(
        math.sqrt(1 + 2 / mu), rel=1e-12
    )


def test_a_tip_damper_cures_the_stall_rotors_edgewise_vibration(tmp_path):
    """Hau 7.2.3: LM's tip dampers against the edgewise vibration of large stall-regulated
    blades. The catalogue's stall rotor fails its edgewise stall check (negative total
    damping at high wind); with a damper of 2 % of the first edge mode's generalised mass in
    each tip (μ = 0.02, ζ_e = 1/(2√101) = 0.0498) the edge modes gain that damping and the
    check passes; the statement gives μ and ζ_e."""
    base = spec.load(TURBINES / "stall-rotor-1mw.yaml")
    before = audit.run(base)
    edge = next(m for m in before.modes if m.id == "blade.edge1")
    st = base.blade.structure
    root = st.hub_radius_m if st is not None else 0.0
    tip = root + (st.span_m[-1] if st is not None else (base.blade.length_m or 0.0))
    found = generalised_mass(base, edge, root, tip)
    assert found is not None
    damper = {"mass_kg": 0.02 * found[2], "tuned_to": "edge1"}
    fitted = base.model_copy(
        update={"blade": base.blade.model_copy(update={"tip_damper": spec.TipDamper(**damper)})}
    )
    after = audit.run(fitted)
    zeta_e = 1 / (2 * math.sqrt(101))
    old = {m.id: m for m in before.modes}
    for m in after.modes:
        if m.id == "blade.edge1":
            assert m.damping_ratio == pytest.approx(old[m.id].damping_ratio + zeta_e, rel=1e-9)
    status = {c.id: c.status for c in after.checks}
    assert {c.id: c.status for c in before.checks}["blade.stall.edge1"] == "fail"
    assert status["blade.stall.edge1"] in ("pass", "warn")
    assert any("μ = 0.0200" in a and "ζ_e = 0.0498" in a for a in after.assumptions)
    assert any("√(1 + 2/μ) = 10," in a for a in after.assumptions)  # √101, the equal peak


def test_the_mass_ratio_uses_the_modes_generalised_mass_at_the_tip():
    """A uniform blade structure (m = 300 kg/m over 20 m from a 1.5 m hub radius): the
    first edgewise mode's generalised mass with its shape 1 at the tip is a uniform
    cantilever's 0.25·mL (∫₀¹φ² dx of the first clamped-free mode, Blevins Table 8-1) —
    1,500 kg, so a 30 kg damper is μ = 0.02 — whatever the model's mesh (within 1 %)."""
    base = spec.load(TURBINES / "stall-rotor-1mw.yaml")
    span = [0.0, 5.0, 10.0, 15.0, 20.0]
    structure = spec.BladeStructure(
        hub_radius_m=1.5,
        span_m=span,
        mass_per_length_kg_m=[300.0] * 5,
        ei_flap_nm2=[2.0e8] * 5,
        ei_edge_nm2=[6.0e8] * 5,
    )
    blade = base.blade.model_copy(
        update={
            "structure": structure,
            "tip_damper": spec.TipDamper(mass_kg=30.0, tuned_to="edge1"),
            "modes": {},
        }
    )
    report = audit.run(base.model_copy(update={"blade": blade}))
    said = next(a for a in report.assumptions if a.startswith("blade.tip_damper"))
    mu = float(said.split("μ = ")[1].split(")")[0])
    assert mu == pytest.approx(30.0 / (0.25 * 300.0 * 20.0), rel=0.01)
    assert f"√(1 + 2/μ) = {math.sqrt(1 + 2 / mu):.3g}" in said


def test_a_damper_on_a_blade_without_a_span_is_said_to_be_ignored():
    """No structure and no length: no generalised mass, no mass ratio — said, nothing
    changed."""
    base = spec.load(TURBINES / "stall-rotor-1mw.yaml")
    blade = base.blade.model_copy(
        update={
            "structure": None,
            "length_m": None,
            "tip_damper": spec.TipDamper(mass_kg=30.0),
        }
    )
    s = base.model_copy(update={"blade": blade})
    built = {"blade": [m for m in audit.run(base).modes if m.id == "blade.edge1"]}
    out, notes = tuned_damper.modify(s, built)
    assert out == built and "ignored" in notes[0]
