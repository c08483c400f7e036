"""The coupled model from a user's spec: the JSON contract, mistakes as one line, two blades.

A small made-up turbine (uniform tower and blades, numbers chosen only to be plausible); the
physics is validated in tests/validation/test_coupled.py.
"""

import json

import pytest
from typer.testing import CliRunner

from wtvib import audit, spec
from wtvib.cli import app
from wtvib.numerics import coleman, floquet
from wtvib.subsystems import coupled, multiblade

SPEC = """\
wtvib: 1
turbine: {{name: Coupled test}}
rotor:
  blades: {blades}
  orientation: upwind
  hub: rigid
  speed: {{min_rpm: 10, max_rpm: 20}}
tower:
  distributed:
    height_m: [0, 60]
    mass_per_length_kg_m: [2000, 1200]
    ei_fa_nm2: [1.0e11, 4.0e10]
    ei_ss_nm2: [1.0e11, 4.0e10]
tower_head:
  mass_kg: {head}
  cm_downwind_m: 0.5
  cm_above_top_m: 1.5
  inertia_pitch_kgm2: 6.0e6
  inertia_roll_kgm2: 1.0e7
  inertia_yaw_kgm2: 6.0e6
blade:
  structure:
    hub_radius_m: 1.5
    span_m: [0, 35]
    mass_per_length_kg_m: [400, 100]
    ei_flap_nm2: [3.0e9, 1.0e8]
    ei_edge_nm2: [6.0e9, 3.0e8]
drivetrain:
  chain:
    - {{name: blades, inertia_kgm2: 1.0e6}}
    - {{name: hub, inertia_kgm2: 2.0e4}}
    - {{name: generator, inertia_kgm2: 50, speed_ratio: 80}}
  shafts:
    - {{stiffness_nm_rad: null}}
    - {{stiffness_nm_rad: 1.0e8}}
coupled:
  apex_downwind_m: -3.0
  apex_above_top_m: 1.8
  hub_mass_kg: 15000
"""


def write(tmp_path, blades=3, head=120_000):
    p = tmp_path / "coupled.yaml"
    p.write_text(SPEC.format(blades=blades, head=head), encoding="utf-8")
    return p


def test_json_carries_the_coupled_modes_and_the_comparison(tmp_path):
    result = CliRunner().invoke(
        app, ["check", str(write(tmp_path)), "--format", "json", "--no-plot"]
    )
    data = json.loads(result.stdout)
    ids = {m["id"] for m in data["modes"] if m["subsystem"] == "system"}
    assert {"system.tower.fa1", "system.tower.ss1", "system.blade.flap1.collective"} <= ids
    assert all(m["speed_dependent"] for m in data["modes"] if m["subsystem"] == "system")
    check = next(c for c in data["checks"] if c["id"] == "system.coupling")
    # one truth per mode: the table is in the condition the modes are judged in
    # (rotating: generator free, at standstill), so every id has one frequency in the report;
    # the parked (locked) frequencies are a separate list under their own names
    assert check["status"] == "info" and check["condition"] == "generator free, standstill"
    rows = {r["id"]: r for r in check["modes"]}
    assert rows["system.tower.fa1"]["isolated_id"] == "tower.fa1"
    modes = {m["id"]: m["frequency_hz"] for m in data["modes"]}
    for row in check["modes"]:
        if row["id"] in modes:
            assert row["coupled_hz"] == pytest.approx(modes[row["id"]], rel=1e-6)
    assert check["parked"]["condition"] == "generator locked, parked"
    assert all("id" not in r for r in check["parked"]["modes"])
    # the isolated modes the coupled model has are shown, not judged
    iso = {m["id"]: m for m in data["modes"]}
    assert iso["tower.fa1"]["superseded_by"] == "system.tower.fa1"
    judged = {c["mode"] for c in data["checks"] if c["id"].startswith("tower.resonance")}
    assert "tower.fa1" not in judged


def test_a_head_lighter_than_its_rotor_is_one_line_with_the_field_and_line(tmp_path):
    result = CliRunner().invoke(app, ["check", str(write(tmp_path, head=20_000)), "--no-plot"])
    assert result.exit_code == 2
    assert "coupled.yaml:15: tower_head.mass_kg:" in result.output  # file:line: field
    assert "Traceback" not in result.output


def test_coupled_without_the_structures_names_what_is_missing(tmp_path):
    p = tmp_path / "bad.yaml"
    bare = SPEC.format(blades=3, head=120_000)
    bare = bare[: bare.index("blade:\n")] + bare[bare.index("drivetrain:\n") :]
    p.write_text(bare, encoding="utf-8")
    with pytest.raises(spec.SpecError, match=r"coupled model needs blade\.structure"):
        spec.load(p)


def test_two_bladed_rotor_gets_parked_modes_and_a_floquet_check(tmp_path):
    s = spec.load(write(tmp_path, blades=2))
    report = audit.run(s)
    check = next(c for c in report.checks if c.id == "system.floquet")
    assert check.status == "pass" and check.numbers["unstable_rpm"] == []
    assert max(check.numbers["max_multiplier"]) <= 1 + floquet.GROWTH
    modes = [m for m in report.modes if m.subsystem == "system"]
    assert modes and all("parked" in m.description for m in modes)
    # solved parked; a blade mode turns stiffened as its isolated blade mode does (a
    # one-bladed rotor's against OpenFAST: test_rtest_models.py), the others stay as parked
    isolated = {m.id: m for m in report.modes if m.subsystem == "blade"}
    top = coupled.speeds(s)[-1:]
    for m in modes:
        name = m.id.removeprefix("system.")
        if not name.startswith("blade."):
            assert m.curve is None, m.id
            continue
        alone = isolated["blade." + name.split(".")[1]]
        rise = alone.frequency_at(top)[0] ** 2 - alone.frequency_hz**2
        assert rise > 0 and "stiffened as the isolated" in (m.condition or "")
        assert m.frequency_at(top)[0] ** 2 - m.frequency_hz**2 == pytest.approx(rise, rel=1e-9)
    names = {m.id for m in modes}
    assert "system.blade.flap1.alternating" in names  # two blades in opposition (teeter-like)
    with pytest.raises(ValueError, match="three or more blades"):
        multiblade.sweep(coupled.build(s, "free"), coupled.speeds(s))


def test_a_head_roll_inertia_below_the_rotors_is_one_line_with_the_field(tmp_path):
    p = write(tmp_path)
    p.write_text(p.read_text().replace("inertia_roll_kgm2: 1.0e7", "inertia_roll_kgm2: 1.0e5"))
    result = CliRunner().invoke(app, ["check", str(p), "--no-plot"])
    assert result.exit_code == 2
    assert "coupled.yaml:19: tower_head.inertia_roll_kgm2:" in result.output


def test_a_chain_without_its_blades_mass_is_one_line(tmp_path):
    # a lumped 'rotor' first mass would count the blades twice: asked to be named
    p = write(tmp_path)
    p.write_text(p.read_text().replace("{name: blades,", "{name: rotor,"))
    result = CliRunner().invoke(app, ["check", str(p), "--no-plot"])
    assert result.exit_code == 2
    assert "drivetrain.chain[0].name:" in result.output and "'blades'" in result.output


def test_blade_modes_are_computed_once_per_spec_and_never_shared_with_a_changed_copy(tmp_path):
    """The coupled model's blade modes are cached on the spec object (no module-level
    state); a copy with another blade (model_copy shares private state) gets its own."""
    s = spec.load(write(tmp_path))
    first = coupled.blade_modes(s, 3)
    assert coupled.blade_modes(s, 3) is first  # once per spec
    st = s.blade.structure
    assert st is not None
    stiffer = st.model_copy(update={"ei_flap_nm2": [2 * v for v in st.ei_flap_nm2]})
    other = s.model_copy(update={"blade": s.blade.model_copy(update={"structure": stiffer})})
    assert coupled.blade_modes(other, 3).omega[0] > first.omega[0]


def _dense_transform(model, psi):  # type: ignore[no-untyped-def]
    """T, T′, T″ of q = T(ψ)·z as dense matrices (the identity outside the blades)."""
    import numpy as np

    lay = model.layout
    b, b1, b2, _ = coleman.coleman(model.blades, psi)
    eye = np.eye(model.k_blades)
    out = []
    for mat in (b, b1, b2):
        t = np.eye(lay.size) if mat is b else np.zeros((lay.size, lay.size))
        t[lay.blades, lay.blades] = np.kron(mat, eye)
        out.append(t)
    return out


def test_the_multi_blade_matrices_are_the_dense_transformation(tmp_path):
    """multiblade.fixed_frame: Tᵀ·M·T, Tᵀ·(2Ω·M·T′ + D·T), Tᵀ·(Ω²·M·T″ + Ω·D·T′ + K·T)
    with the dense transformation, at a rotor speed and an azimuth (only the blades' rows
    and columns are computed)."""
    import numpy as np

    model = coupled.build(spec.load(write(tmp_path)), "free")
    omega, psi = 1.3, 0.7
    m, d, k = model.matrices(omega, psi)
    t, t1, t2 = _dense_transform(model, psi)
    mm, dd, kk = multiblade.fixed_frame(model, omega, psi)
    scale = max(np.abs(x).max() for x in (m, d, k))
    np.testing.assert_allclose(mm, t.T @ m @ t, rtol=0, atol=1e-13 * scale)
    np.testing.assert_allclose(dd, t.T @ (2 * omega * m @ t1 + d @ t), rtol=0, atol=1e-13 * scale)
    want = t.T @ (omega**2 * m @ t2 + omega * d @ t1 + k @ t)
    np.testing.assert_allclose(kk, want, rtol=0, atol=1e-13 * scale)


def test_aerodynamic_damping_in_multi_blade_coordinates_is_the_dense_transformation(tmp_path):
    """multiblade.fixed_frame_damping changes only the blades' rows and columns (T is the
    identity elsewhere, T′ zero): the same matrices as Tᵀ·D·T and Ω·Tᵀ·D·T′ with the dense
    transformation, for a stack of damping matrices, each with its rotor speed."""
    import numpy as np

    model = coupled.build(spec.load(write(tmp_path)), "free")
    n = model.layout.size
    d = np.random.default_rng(7).standard_normal((4, n, n))
    omega = np.array([0.0, 0.4, 1.1, 2.0])
    t, t1, _ = _dense_transform(model, 0.0)
    damping, stiffness = multiblade.fixed_frame_damping(model, d, omega)
    np.testing.assert_allclose(damping, t.T @ d @ t, rtol=0, atol=1e-13)
    np.testing.assert_allclose(stiffness, omega[:, None, None] * (t.T @ d @ t1), atol=1e-13)
    single = multiblade.fixed_frame_damping(model, d[2], 1.1)
    np.testing.assert_array_equal(single[0], damping[2])


def test_a_rigid_shaft_leaves_the_hub_its_own_inertia(shared):
    """Read as OpenFAST models it (``deck_dofs``), the IEA-3.4 reference deck has its shaft
    rigid (DrTrDOF off) and its generator free: the hub and the geared generator turn as
    one mass (9.96e6 kg·m², the generator's 1,056 kg·m² times the gearbox ratio squared),
    and that merged mass was taken for the hub's own polar inertia — subtracted from the
    head with the blades, it left less than nothing for the nacelle, and a valid deck was
    refused ("tower_head.inertia_roll_kgm2 … is less than the rotor's …"). The hub is its
    own 31,094 kg·m² (the deck's HubIner; the spec's chain), the audit runs."""
    from wtvib import importers

    deck = shared / "reference" / "IEA3.4" / "IEA-3.4-130-RWT_ElastoDyn.dat"
    s = importers.load(deck, importers.ReadOptions(deck_dofs=True, rpm=(6.0, 12.0)))
    hub = next(c for c in s.drivetrain.chain if c.name == "hub")
    chain = coupled._chain(s, "free", [])
    assert chain.hub_polar == hub.inertia_kgm2
    assert chain.m[0, 0] > 100 * hub.inertia_kgm2  # the generator merged with it
    assert any(m.id == "system.tower.fa1" for m in audit.run(s).modes)


def test_the_drive_trains_lines_act_on_the_coupled_modes_that_stand_for_its_modes(shared):
    """The NREL 5-MW deck's coupled model supersedes both modes of the drive train's lumped
    chain (``system.drivetrain1`` at 1.68 Hz, ``system.drivetrain2`` at 3.2 Hz — the second
    47 % the tower's second side-side, named by its second share as the ElastoDyn DOF view
    names OpenFAST's drivetrain1_2; the chain's own 24 Hz second mode, the hub between the
    shaft and the blades' edgewise spring, is a frequency no model of the turbine has).
    Superseded, the isolated modes are not judged, and the drive train's own lines — the
    generator's speed (1G), gear mesh — judged nothing: now they act on the coupled modes
    that stand for its modes (``system.resonance.1G``)."""
    from wtvib import importers

    report = audit.run(importers.load(shared / "reference" / "NREL5MW" / "NREL-5MW.fst"))
    modes = {m.id: m for m in report.modes}
    assert modes["drivetrain.free.2"].superseded_by == "system.drivetrain2"
    assert "47% tower side-side" in modes["system.drivetrain2"].description
    check = next(c for c in report.checks if c.id == "system.resonance.1G")
    assert check.status == "pass" and "system.drivetrain" in check.message
