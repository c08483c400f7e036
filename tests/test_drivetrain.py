"""The drive train: conditions and the regimes they exist in, its analysis (torque
amplification on its resonance checks, the synchronous power curve)."""

import math

import pytest

from tests.conftest import TURBINES
from wtvib import audit, spec
from wtvib.subsystems import drivetrain


@pytest.fixture(scope="module")
def growian():
    return spec.load(TURBINES / "growian.yaml")


def test_conditions_and_their_regimes(growian):
    assert drivetrain.conditions(growian) == ["grid", "free", "locked"]
    assert drivetrain.regimes(growian, "grid") == {"steady", "quick-pass", "overspeed"}
    assert drivetrain.regimes(growian, "free") == {"start-up", "overspeed"}
    assert drivetrain.regimes(growian, "locked") == frozenset()  # reported only


def test_free_is_the_operating_condition_without_a_grid_model(growian):
    bare = growian.model_copy(
        update={"drivetrain": growian.drivetrain.model_copy(update={"grid_coupling": "isolated"})}
    )
    assert "grid" not in drivetrain.conditions(bare)
    assert "steady" in drivetrain.regimes(bare, "free")


def test_a_generator_held_at_the_rotor_s_speed_is_locked_in_every_regime(tmp_path):
    """A coupled model turning with its generator locked (an OpenFAST deck with ElastoDyn's
    GenDOF off, read as OpenFAST models it): the clamped-end modes are the turbine's in
    operation, judged in every regime, and the free-end modes no mode of it. (They were
    judged the other way round: a deck's fixed-speed drive train judged at its idling
    frequency, 1.81 Hz on r-test's BeamDyn 5-MW, where it turns at 0.62 Hz.) r-test's
    5MW_Land_Linear_Aero deck (tests/data/openfast_decks/rtest_aero.tar.gz), its generator
    free, then held."""
    import tarfile

    from tests.conftest import ROOT
    from wtvib import importers

    with tarfile.open(ROOT / "tests/data/openfast_decks/rtest_aero.tar.gz") as tar:
        tar.extractall(tmp_path, filter="data")
    case = "5MW_Land_Linear_Aero"
    free = importers.load(tmp_path / "glue-codes/openfast" / case / f"{case}.fst")
    assert free.coupled is not None and free.coupled.rotating_condition == "free"
    assert drivetrain.regimes(free, "locked") == frozenset()
    held = free.model_copy(
        update={"coupled": free.coupled.model_copy(update={"rotating_condition": "locked"})}
    )
    assert drivetrain.regimes(held, "locked") == drivetrain.ALWAYS
    assert drivetrain.regimes(held, "free") == frozenset()
    judged = {m.id for m in audit.run(held).modes if m.judged and "drivetrain" in m.id}
    assert "system.drivetrain1" in judged and not any(".free." in i for i in judged)


def test_every_computed_mode_carries_its_condition(growian):
    modes = drivetrain.build_modes(growian, {"blade": []})
    assert {m.condition for m in modes} == set(drivetrain.CONDITIONS.values())
    assert all(m.origin == "computed" for m in modes)


def test_resonance_checks_carry_the_torque_amplification(growian):
    r = audit.run(growian)
    checks = [c for c in r.checks if c.id.startswith("drivetrain.resonance.")]
    assert checks and all("torque_amplification" in c.numbers for c in checks)
    assert drivetrain.power_curve(growian) is None  # a converter: no grid power curve


def test_the_synchronous_power_curve_is_a_result_the_figure_draws():
    r = audit.run(spec.load(TURBINES / "mod-0.yaml"))
    curve = r.result(drivetrain.NAME, drivetrain.DrivetrainResults).power
    # Hau Fig. 7.14: the magnetic stiffness falls with power, and so does the frequency
    assert curve.frequency_hz[0] > curve.frequency_hz[-1]
    assert curve.lines == (
        ("1P at 40 rpm", pytest.approx(40 / 60)),
        ("2P at 40 rpm", pytest.approx(80 / 60)),
    )


def test_a_pull_out_power_below_rated_is_refused_with_the_field(tmp_path):
    """A pull-out power of 1e-15 kW ended in an internal ValueError inside the
    magnetic-spring formula; the spec now refuses P_max ≤ P_rated with field and line."""
    from tests.conftest import TURBINES
    from wtvib import spec
    from wtvib.errors import SpecError

    text = (TURBINES / "mod-0-fluid-coupling.yaml").read_text()
    text = text.replace("pull_out_power_kw: {value: 130,", "pull_out_power_kw: {value: 1.0e-15,")
    path = tmp_path / "p.yaml"
    path.write_text(text)
    with pytest.raises(SpecError, match=r"pull_out_power_kw .* must exceed rated_power_kw") as err:
        spec.load(path)
    assert err.value.path == "drivetrain.generator_model" and err.value.line is not None


def test_a_drive_train_damped_past_critical_is_one_line(tmp_path):
    """The extreme-value campaign: a 1e9 N·m·s/rad shaft damper left the
    grid-coupled power sweep no oscillatory mode and an IndexError; now a ModalError
    saying what happened (exit 2 in the CLI)."""
    from tests.conftest import TURBINES
    from wtvib import audit, spec
    from wtvib.numerics.modal import ModalError
    from wtvib.spec.yamlio import parse_plain

    data = parse_plain((TURBINES / "mod-0-fluid-coupling.yaml").read_text()).data
    data["drivetrain"]["shafts"][2] = {"stiffness_nm_rad": 150.0, "damping_nms_rad": 1.0e9}
    data["drivetrain"]["shafts"][2]["speed_ratio"] = 45.0
    with pytest.raises(ModalError, match=r"no oscillatory mode at .* power"):
        audit.run(spec.from_data(data))


def test_the_dampers_add_to_the_trains_material_damping():
    """The Aeroman's induction generator damps its first grid mode heavily (ζ ≈ 0.26) and
    its third hardly (2e-5, the generator barely moves in it): that mode keeps the train's
    material damping (the assumed 0.02) with the dampers' part on top — it was judged with
    the 2e-5 alone, a DAF of 22,000 at a crossing."""
    s = spec.load(TURBINES / "aeroman.yaml")
    default = drivetrain.default_damping(s).ratio
    modes = {m.id: m for m in audit.run(s).modes if m.subsystem == "drivetrain"}
    assert all(m.damping_ratio is not None and m.damping_ratio >= default for m in modes.values())
    third = modes["drivetrain.grid.3"]
    assert third.damping_ratio is not None and default < third.damping_ratio < default + 1e-3
    assert third.damping_source is not None and "dampers" in third.damping_source
    assert modes["drivetrain.grid.1"].damping_ratio > 0.25  # type: ignore[operator]


def test_modal_damping_gives_every_elastic_mode_its_ratio():
    """D = (MΦ)·diag(2ζω)·(MΦ)ᵀ: the damped roots of (M, D, K) have ζ exactly, a rigid
    mode none (a free train's turning)."""
    import numpy as np

    from wtvib.numerics import modal
    from wtvib.subsystems.drivetrain import modal_damping

    m = np.diag([3.0, 1.0, 2.0])
    k = np.array([[2.0, -2.0, 0.0], [-2.0, 5.0, -3.0], [0.0, -3.0, 3.0]])  # free: singular
    d = modal_damping(m, k, 0.02)
    roots = modal.damped(k, m, d)
    elastic = roots.frequency_hz > 1e-6
    assert np.allclose(roots.damping_ratio[elastic], 0.02, atol=1e-9)


def test_shaft_torque_amplification_is_bounded_by_the_modal_damping():
    """Aeroman's train has no damper: at its 5P resonance the forced response
    gave 9.02·10⁵. With the drive train's modal damping (2 %, the DAF's) it stays below
    the resonance's 1/(2ζ) = 25."""
    from wtvib import audit
    from wtvib.spec import load

    from .conftest import TURBINES

    report = audit.run(load(TURBINES / "aeroman.yaml"))
    check = next(c for c in report.checks if c.id == "drivetrain.resonance.5P")
    amp = check.numbers["torque_amplification"]
    assert 1.0 < amp < 1 / (2 * 0.02)


@pytest.mark.parametrize(
    ("turbine", "table"),
    [("aeroman", (87, 2, 9, 2)), ("wka-60", (91, 1, 7, 1)), ("growian", (85, 8, 5, 2))],
)
def test_inertia_shares_are_table_7_8(turbine, table):
    """Hau Table 7.8: the shares of the drive train's inertia on the rotor shaft (blades,
    hub, generator, rest) — reported for every chain; the book's three trains give the
    table's numbers to the percent (their chains are built from the book's inertias)."""
    from wtvib import audit
    from wtvib.spec import load
    from wtvib.subsystems import drivetrain

    from .conftest import TURBINES

    spec = load(TURBINES / f"{turbine}.yaml")
    shares = drivetrain.inertia_shares(spec)
    assert shares is not None
    assert [round(100 * shares[k]) for k in ("blades", "hub", "generator", "rest")] == list(table)
    assert any("Table 7.8" in a for a in audit.run(spec).assumptions)


def test_inertia_shares_reduce_each_mass_by_its_speed_squared(write_spec):
    """J·i²: a 10 kg·m² generator on a 50:1 shaft counts 25,000 kg·m² on the rotor's."""
    from wtvib.spec import load
    from wtvib.subsystems import drivetrain

    chain = (
        "drivetrain:\n  chain:\n"
        "    - {name: blades, inertia_kgm2: 70000}\n"
        "    - {name: hub, inertia_kgm2: 5000}\n"
        "    - {name: generator, inertia_kgm2: 10, speed_ratio: 50}\n"
        "  shafts:\n    - {stiffness_nm_rad: null}\n    - {stiffness_nm_rad: 1.0e9}\n"
    )
    shares = drivetrain.inertia_shares(load(write_spec(extra=chain)))
    assert shares == pytest.approx({"blades": 0.7, "hub": 0.05, "generator": 0.25, "rest": 0.0})


def test_an_induction_generator_on_the_grid_is_a_damper_and_its_frequencies_ignore_power():
    """Hau 7.3.3: the slip couples an induction generator to the grid as a damper only —
    the train's 'zeroth natural frequency' is its whole rotation, decaying in τ = ΣJ/d_m
    (d_m = T_rated/(s·Ω_s) on the generator shaft, reduced by i²) — and its frequencies do
    not depend on power. Aeroman (2 % slip)."""
    s = spec.load(TURBINES / "aeroman.yaml")
    modes = drivetrain.modes(s)
    chain = drivetrain.reduce(s, drivetrain.edge_frequency(s, modes))
    check = drivetrain.induction_check(s, chain, modes)
    assert check is not None and check.status == "info"
    g = s.drivetrain.generator_model
    omega_s = 2 * math.pi * g.grid_frequency_hz / g.pole_pairs
    d_m = g.rated_power_kw * 1e3 / (omega_s * (1 + g.rated_slip)) / (g.rated_slip * omega_s)
    assert check.numbers["damping_nms_rad"] == pytest.approx(d_m)
    tau = chain.inertia.sum() / (d_m * chain.generator_factor)
    assert check.numbers["time_constant_s"] == pytest.approx(tau)
    assert "drivetrain.grid.1" in check.message
    wka = spec.load(TURBINES / "wka-60.yaml")  # no induction generator on the grid
    wka_modes = drivetrain.modes(wka)
    wka_chain = drivetrain.reduce(wka, drivetrain.edge_frequency(wka, wka_modes))
    assert drivetrain.induction_check(wka, wka_chain, wka_modes) is None


def test_a_fluid_coupling_is_a_damper_of_its_slip_and_no_spring(tmp_path):
    """Hau 7.3.3: a fluid coupling passes torque by slip, T = T_r·s/s_r: a damper
    d = T_r/(s_r·ω) on its shaft and no elastic stiffness (the MOD-0 retrofit's: 100 kW at
    40 rpm × 45, 3 % slip: 530.5 N·m / (0.03 × 188.5 rad/s) = 93.8 N·m·s/rad). Braked, the
    rotor side hangs on the coupling alone: no spring, so no mode — the fictitious
    150 N·m/rad spring the spec had carried gave a 0.46 Hz 'locked' mode."""
    from tests.conftest import TURBINES
    from wtvib import spec
    from wtvib.errors import SpecError

    s = spec.load(TURBINES / "mod-0-fluid-coupling.yaml")
    shaft = s.drivetrain.shafts[2]
    omega = 40 * math.pi / 30 * 45
    expected = 100e3 / omega / (0.03 * omega)
    assert drivetrain.fluid_coupling_damping(s, shaft) == pytest.approx(expected, rel=1e-12)
    assert expected == pytest.approx(93.8, abs=0.05)
    chain = drivetrain.reduce(s)
    assert chain.stiffness[-1] == 0.0
    assert chain.damping[-1] == pytest.approx(expected * 45**2, rel=1e-12)  # on the rotor
    locked = [m for m in audit.run(s).modes if m.id.startswith("drivetrain.locked")]
    assert locked and min(m.frequency_hz for m in locked) > 10.0
    text = (TURBINES / "mod-0-fluid-coupling.yaml").read_text()
    for edit, message in (
        ("    - fluid_coupling:\n", "    - stiffness_nm_rad: 150\n      fluid_coupling:\n"),
        ("    - fluid_coupling:\n", "    - damping_nms_rad: 5\n      fluid_coupling:\n"),
    ):
        bad = tmp_path / "bad.yaml"
        bad.write_text(text.replace(edit, message))
        with pytest.raises(SpecError, match="give fluid_coupling alone"):
            spec.load(bad)
    from wtvib.spec.yamlio import parse_plain

    data = parse_plain(text).data
    data["drivetrain"]["shafts"][2] = {"speed_ratio": 45.0}  # neither stiffness nor coupling
    with pytest.raises(SpecError, match="stiffness_nm_rad is needed"):
        spec.from_data(data)


def _chain_spec(shaft0, reference="rotor", edge_spring=True):  # type: ignore[no-untyped-def]
    """Blades (1e6 kg·m²), hub (2e4), generator (50 kg·m² turning 80 times faster) with a
    brake disc (10 kg·m²) rigidly on its shaft."""
    return spec.from_data(
        {
            "wtvib": 1,
            "turbine": {"name": "chain"},
            "rotor": {
                "blades": 3,
                "orientation": "upwind",
                "hub": "rigid",
                "speed": {"fixed_rpm": 20},
            },
            "drivetrain": {
                "chain": [
                    {"name": "blades", "inertia_kgm2": 1.0e6},
                    {"name": "hub", "inertia_kgm2": 2.0e4},
                    {"name": "generator", "inertia_kgm2": 50, "speed_ratio": 80},
                    {"name": "brake", "inertia_kgm2": 10, "speed_ratio": 80},
                ],
                "shafts": [
                    {"stiffness_nm_rad": shaft0},
                    {"stiffness_nm_rad": 1.0e8},
                    {"stiffness_nm_rad": None, "speed_ratio": 80},
                ],
                "reference_shaft": reference,
                "blade_edge_spring": edge_spring,
            },
        }
    )


def test_a_reduced_chain_keeps_each_masss_own_inertia_and_its_roll_coupling():
    """Each reduced mass carries Σ J_own (on its own shaft) and Σ J_own·i/i_ref (i its speed
    over the rotor's, i_ref the reference shaft's) — what the nacelle's roll feels of its
    spin; rigid connections merge masses and sum both (by hand)."""
    c = drivetrain.reduce(_chain_spec(None, edge_spring=False))
    assert c.names == ("blades+hub", "generator+brake")
    assert list(c.inertia) == pytest.approx([1.02e6, 60 * 80**2])
    assert list(c.own) == pytest.approx([1.02e6, 60])
    assert list(c.coupling) == pytest.approx([1.02e6, 60 * 80])
    g = drivetrain.reduce(_chain_spec(None, "generator", edge_spring=False))
    assert list(g.inertia) == pytest.approx([1.02e6 / 80**2, 60])
    assert list(g.coupling) == pytest.approx([1.02e6 / 80, 60])
    assert list(g.stiffness) == pytest.approx([1.0e8 / 80**2])


def test_the_blades_edge_spring_sits_in_series_with_a_given_hub_shaft():
    """k = 1/(1/k_b + 1/k_shaft) with the blades' edgewise spring k_b = J_b·(2π f_edge)²
    (Hau 7.3.1: the chordwise flexibility in the train); alone where the connection is
    rigid. By hand at f_edge = 1.2 Hz and a hub shaft of 5e7 N·m/rad."""
    k_b = 1.0e6 * (2 * math.pi * 1.2) ** 2
    series = drivetrain.reduce(_chain_spec(5.0e7), edge_hz=1.2)
    assert series.stiffness[0] == pytest.approx(1 / (1 / k_b + 1 / 5.0e7), rel=1e-12)
    alone = drivetrain.reduce(_chain_spec(None), edge_hz=1.2)
    assert alone.stiffness[0] == pytest.approx(k_b, rel=1e-12)
    assert drivetrain.reduce(_chain_spec(5.0e7, edge_spring=False), 1.2).stiffness[0] == 5.0e7


def test_each_mode_is_described_by_its_own_shape():
    """Hau 7.3.3: "At the first natural frequency, the drive train vibrates around its
    largest mass, the rotor blades" — Aeroman's first grid mode is the blades against the
    grid; its fourth, which the second stage's mesh excites (Fig. 7.15), is the centrifugal
    switch on the high-speed shaft against the gearbox."""
    s = spec.load(TURBINES / "aeroman.yaml")
    described = {m.id: m.description for m in drivetrain.build_modes(s, {"blade": []})}
    assert "blades against the grid" in described["drivetrain.grid.1"]
    assert "centrifugal switch against gearbox" in described["drivetrain.grid.4"]
    assert "blades against the brake" in described["drivetrain.locked.1"]


def test_the_locked_train_is_the_free_one_clamped_at_the_generator():
    """Brake applied: the generator's angle is held, so the train's M, K and D are the free
    chain's with the generator's row and column struck out (three masses, a damper on each
    shaft here)."""
    import numpy as np

    s = _chain_spec(5.0e7, edge_spring=False)
    dt = s.drivetrain
    shafts = [
        sh.model_copy(update={"damping_nms_rad": 1e5 * (i + 1)}) for i, sh in enumerate(dt.shafts)
    ]
    s = s.model_copy(update={"drivetrain": dt.model_copy(update={"shafts": shafts})})
    chain = drivetrain.reduce(s)
    free = chain.matrices()
    locked = drivetrain.system(chain, s, "locked")
    for full, held in zip(free, locked, strict=True):
        np.testing.assert_array_equal(held, full[:-1, :-1])
    assert locked[2].shape == (2, 2) and locked[2][0, 1] != 0.0


@pytest.mark.parametrize("hz", ["1.0e+300", "1.0e-300"])
def test_a_grid_frequency_no_grid_has_is_refused_with_the_field(tmp_path, hz):
    """A grid frequency of 1e300 Hz made the induction generator's magnetic damping 0 and
    the grid check divided by it (exhaustive.py extremes, tests/FUZZ.md campaign 20): the
    spec keeps it within 1–1,000 Hz (16.7 Hz railways … 400 Hz on board)."""
    from tests.conftest import TURBINES
    from wtvib import spec
    from wtvib.errors import SpecError

    text = (TURBINES / "aeroman.yaml").read_text()
    assert "grid_frequency_hz: {value: 50," in text
    path = tmp_path / "g.yaml"
    path.write_text(
        text.replace("grid_frequency_hz: {value: 50,", f"grid_frequency_hz: {{value: {hz},")
    )
    with pytest.raises(SpecError, match="grid_frequency_hz") as err:
        spec.load(path)
    assert err.value.line is not None
