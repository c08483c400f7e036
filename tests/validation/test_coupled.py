"""The coupled rotor–tower model (wtvib.subsystems.coupled) against published and exact values.

Published: NREL 5-MW full-system natural frequencies, parked, generator locked — Jonkman et
al. 2009, NREL/TP-500-38060, Table 9-1, FAST and ADAMS columns (the first-mode values are
also in DOMAIN.md §5; the table's conditions, RotSpeed = 0 and GenDOF = False, are confirmed
by J. Jonkman on the NREL forum, "Full-System natural frequencies", topic 1462).

Exact: limits the coupled model must reach — a rotor made rigid gives back the tower with a
rigid tower head (wtvib.subsystems.tower); a rigid support gives back the isolated rotating blade
(wtvib.subsystems.blade), and in the fixed frame its cyclic modes at f ∓ Ω/2π (Coleman
transformation);
the multi-blade equations of an isotropic rotor are time-invariant and, with no damping,
have a symmetric mass and stiffness and a skew-symmetric gyroscopic matrix.
"""

import math
import re
from typing import Any

import numpy as np
import pytest

from wtvib import audit, importers, spec
from wtvib.numerics import modal
from wtvib.subsystems import blade, coupled, multiblade, periodic, tower

NREL = "reference/NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"

#: Table 9-1 (FAST, ADAMS) [Hz] by the coupled model's mode name; True for first modes.
TABLE_9_1 = {
    "tower.fa1": (0.3240, 0.3195, True),
    "tower.ss1": (0.3120, 0.3164, True),
    "drivetrain1": (0.6205, 0.6094, True),
    "blade.flap1.cyclic_yaw": (0.6664, 0.6296, True),  # 1st asymmetric flapwise yaw
    "blade.flap1.cyclic_tilt": (0.6675, 0.6686, True),  # 1st asymmetric flapwise pitch
    "blade.flap1.collective": (0.6993, 0.7019, True),
    "blade.edge1.cyclic_tilt": (1.0793, 1.0740, True),  # 1st asymmetric edgewise pitch
    "blade.edge1.cyclic_yaw": (1.0898, 1.0877, True),  # 1st asymmetric edgewise yaw
    "blade.flap2.cyclic_yaw": (1.9337, 1.6507, False),
    "blade.flap2.cyclic_tilt": (1.9223, 1.8558, False),
    "blade.flap2.collective": (2.0205, 1.9601, False),
    "tower.fa2": (2.9003, 2.8590, False),
    "tower.ss2": (2.9361, 2.9408, False),
}


@pytest.fixture(scope="module")
def nrel(shared: Any) -> spec.Spec:
    return importers.load(shared / NREL, importers.ReadOptions(rpm=(6.9, 12.1)))


def parked(s: spec.Spec, condition: str = "locked") -> dict[str, float]:
    res = multiblade.parked(coupled.build(s, condition))
    return dict(zip(res.names, res.frequency_hz.tolist(), strict=True))


def test_nrel5mw_parked_locked_against_table_9_1(nrel):
    """Every mode of Table 9-1 is in the model (tower, drive train, blades' first and second
    flap, first edge — the table lists no other); first modes within 3 % of the FAST–ADAMS
    band, second modes within 5 %. Not in the table, so not compared: the collective edge
    mode (it swings against the hub) and the nacelle yaw mode."""
    f = parked(nrel)
    for name, (fast, adams, first) in TABLE_9_1.items():
        tol = 0.03 if first else 0.05
        lo, hi = min(fast, adams), max(fast, adams)
        assert lo * (1 - tol) <= f[name] <= hi * (1 + tol), (name, f[name], lo, hi)


def test_second_tower_modes_need_the_flexible_rotor(nrel):
    """With the rotor as a rigid body on the tower top the second tower modes come out far
    below Table 9-1 (2.86–2.94 Hz): the blades' flexibility decouples most of the rotor's
    inertia from the tower's second mode. The isolated tower model therefore carries the
    rotor's mass at the apex and leaves its rotational inertia to the blades' and the drive
    train's own degrees of freedom (tower.bending_head, as ElastoDyn, BModes and pyBModes
    do): within 5 % of Table 9-1 (measured −1.9 % and −0.5 %), where the head as one rigid
    body is over 20 % low; the coupled model matches them too, and is what the audit
    judges."""
    iso = {m.id: m.frequency_hz for m in audit.run(nrel).modes}
    coupled_f = parked(nrel)
    b = tower.discretise(nrel.tower)
    rigid_fa, rigid_ss = tower.bending_pair(
        b, nrel.tower_head, [], nrel.tower.foundation, nrel.tower.gravity
    )
    rigid = {"fa2": rigid_fa.frequency_hz[1], "ss2": rigid_ss.frequency_hz[1]}
    for name, (fast, adams, _) in (
        ("fa2", TABLE_9_1["tower.fa2"]),
        ("ss2", TABLE_9_1["tower.ss2"]),
    ):
        lo = min(fast, adams)
        assert rigid[name] < 0.8 * lo  # the rigid rotor: more than 20 % low
        assert iso[f"tower.{name}"] == pytest.approx(lo, rel=0.05)
        assert coupled_f[f"tower.{name}"] >= 0.95 * lo
    superseded = {m.id: m.superseded_by for m in audit.run(nrel).modes}
    assert superseded["tower.fa2"] == "system.tower.fa2"
    assert superseded["tower.ss2"] == "system.tower.ss2"


def stiffened(s: spec.Spec, blades: float = 1.0, tower_ei: float = 1.0) -> spec.Spec:
    """The spec with blades, tower, drive shaft and yaw drive made stiffer by factors."""
    d = s.model_dump()
    st = d["blade"]["structure"]
    for key in ("ei_flap_nm2", "ei_edge_nm2"):
        st[key] = [v * blades for v in st[key]]
    dist = d["tower"]["distributed"]
    for key in ("ei_fa_nm2", "ei_ss_nm2"):
        dist[key] = [v * tower_ei for v in dist[key]]
    if tower_ei > 1:
        d["tower"]["gravity"] = False
    shafts = d["drivetrain"]["shafts"]
    shafts[-1]["stiffness_nm_rad"] *= max(blades, tower_ei)
    d["yaw"]["drive_stiffness_nm_rad"] *= max(blades, tower_ei)
    return spec.Spec.model_validate(d)


def test_rigid_rotor_gives_back_the_tower_with_a_rigid_head(nrel):
    """Blades, shaft and yaw drive 10⁴ times stiffer: the coupled tower modes equal the
    tower model's with the whole tower head as one rigid body (same inertias by
    construction: the nacelle is the head minus the rotor)."""
    s = stiffened(nrel, blades=1e4)
    f = parked(s)
    b = tower.discretise(s.tower)
    fa, ss = tower.bending_pair(b, s.tower_head, [], s.tower.foundation, s.tower.gravity)
    assert f["tower.fa1"] == pytest.approx(fa.frequency_hz[0], rel=1e-4)
    assert f["tower.ss1"] == pytest.approx(ss.frequency_hz[0], rel=1e-4)
    assert f["tower.fa2"] == pytest.approx(fa.frequency_hz[1], rel=1e-3)
    assert f["tower.ss2"] == pytest.approx(ss.frequency_hz[1], rel=1e-3)


@pytest.mark.parametrize("rpm", [0.0, 12.1, 30.0])
def test_rigid_support_gives_back_the_rotating_blade(nrel, rpm):
    """Tower, shaft and yaw 10⁶ times stiffer: the collective modes are the isolated
    rotating blade's (centrifugal stiffening and in-plane softening from two different
    derivations), the cyclic ones appear in the fixed frame at f ∓ Ω/2π."""
    s = stiffened(nrel, tower_ei=1e6).model_copy(
        update={"coupled": nrel.coupled.model_copy(update={"blade_modes": 5})}  # type: ignore[union-attr]
    )
    omega = rpm * math.pi / 30
    model = coupled.build(s, "locked")
    res = multiblade.rotating(model, omega, 20)
    names, freqs, _, _ = blade.rotating_modes(s.blade.structure, np.array([omega]))  # type: ignore[arg-type]
    iso = dict(zip(names, freqs[0], strict=True))
    p = omega / (2 * math.pi)
    got = res.frequency_hz
    for mode in ("flap1", "edge1", "flap2"):
        expected = {iso[mode]} if rpm == 0 else {iso[mode], iso[mode] - p, iso[mode] + p}
        for f in expected:  # each expected line is present within 0.1 % (Ritz: 5 modes)
            assert np.min(np.abs(got / f - 1)) < 1e-3, (mode, f, got)
        if rpm > 0:  # the lower cyclic line whirls against the rotation, the upper with it
            for f, turn in ((iso[mode] - p, "backward"), (iso[mode] + p, "forward")):
                assert f"{turn} whirl" in res.descriptions[int(np.argmin(np.abs(got - f)))]


@pytest.mark.parametrize("blades", [3, 4, 5])
def test_multiblade_equations_are_time_invariant_and_gyroscopic(nrel, blades):
    head = nrel.tower_head
    assert head is not None
    more = {  # room in the head's inertias for the added blades
        k: 2 * getattr(head, k)
        for k in ("mass_kg", "inertia_pitch_kgm2", "inertia_roll_kgm2", "inertia_yaw_kgm2")
    }
    s = nrel.model_copy(
        update={
            "rotor": nrel.rotor.model_copy(update={"blades": blades}),
            "tower_head": head.model_copy(update=more),
        }
    )
    model = coupled.build(s, "free")
    a = multiblade.fixed_frame(model, 1.3, 0.0)
    b = multiblade.fixed_frame(model, 1.3, 0.77)
    for x, y in zip(a, b, strict=True):
        assert np.abs(x - y).max() <= 1e-12 * np.abs(x).max()
    m, d, k = a
    parked_m, d0, _ = multiblade.fixed_frame(model, 0.0, 0.3)  # parked shortcut: same inertia
    assert np.abs(parked_m - m).max() <= 1e-12 * np.abs(m).max()
    assert np.abs(m - m.T).max() <= 1e-12 * np.abs(m).max()
    g = d - d0  # without the drive-train damper: gyroscopic, skew
    assert np.abs(g + g.T).max() <= 1e-12 * np.abs(g).max()
    assert np.abs(k - k.T).max() <= 1e-12 * np.abs(k).max()
    assert np.all(np.linalg.eigvalsh(m) > 0)


def test_campbell_curves_keep_their_names_and_split_into_whirl_pairs(nrel):
    """Over the sweep the first flapwise cyclic pair separates by 2P in the fixed frame at
    rated speed (Hansen 2003: backward f − 1P, forward f + 1P) and the tower modes stay put."""
    ms = {m.id: m for m in audit.run(nrel).modes if m.subsystem == "system"}
    rated = 12.1 * math.pi / 30
    fa1 = ms["system.tower.fa1"]
    assert float(fa1.frequency_at(rated)) == pytest.approx(fa1.frequency_hz, rel=0.01)
    whirl = sorted(
        float(m.frequency_at(rated)) for k, m in ms.items() if ".flap1." in k
    )  # backward, collective, forward
    assert whirl[2] - whirl[0] == pytest.approx(2 * rated / (2 * math.pi), rel=0.15)


def test_coupling_check_compares_isolated_and_coupled(nrel):
    r = audit.run(nrel)
    c = next(c for c in r.checks if c.id == "system.coupling")
    rows = {row["id"]: row for row in c.numbers["modes"]}
    fa2 = rows["system.tower.fa2"]
    # the isolated second mode carries the rotor's inertia as the blades do
    # (tower.bending_head): within 5 % of the coupled one, not 20 % below it as a rigid rotor
    assert fa2["isolated_id"] == "tower.fa2" and 0 < fa2["change"] < 0.05
    # compared in the condition the modes are judged in (generator free, standstill) ...
    assert c.numbers["condition"] == "generator free, standstill"
    assert rows["system.drivetrain1"]["isolated_id"] == "drivetrain.free.1"
    # ... and the parked, locked list: the drive train barely coupled there (Hau: one mode
    # dominates; Jonkman et al. 2009 Table 9-1's condition)
    locked = {r["name"]: r["frequency_hz"] for r in c.numbers["parked"]["modes"]}
    iso = {m.id: m.frequency_hz for m in r.modes}
    assert abs(locked["drivetrain1"] / iso["drivetrain.locked.1"] - 1) < 0.02
    for row in rows.values():  # kinetic-energy shares: at most the whole, ≥ 0.5 % listed
        assert 0.95 <= sum(row["energy"].values()) <= 1.0 + 1e-9
    assert rows["system.tower.fa1"]["energy"]["tower.fa"] > 0.9


def test_iea15_windio2_coupled_tower_mode_stays_in_the_published_band():
    """IEA-15 from its windIO 2.1.1 file (the importer fills the coupled block from the hub
    and nacelle geometry): the coupled first tower modes stay within the published
    tower + monopile band, 0.17 Hz in Gaertner et al. 2020, ≈ 0.18 Hz in later models (± 5 %)."""
    windio = pytest.importorskip("windIO", reason="the windio package (dev extra) is needed")
    import os

    path = os.path.join(os.path.dirname(windio.__file__), "examples", "turbine")
    s = importers.load(os.path.join(path, "IEA-15-240-RWT.yaml"))
    assert s.coupled is not None and s.coupled.hub_mass_kg > 0
    f = parked(s)
    for name in ("tower.fa1", "tower.ss1"):
        assert 0.17 * 0.95 <= f[name] <= 0.18 * 1.05
    # the drive train read from the file: the rotor turns on its chain, not held
    model = coupled.build(s, "locked")
    assert not any("rotor is held" in a for a in model.assumptions)
    assert s.drivetrain is not None and [c.name for c in s.drivetrain.chain] == [
        "blades",
        "hub",
        "generator",
    ]


def test_floquet_of_the_periodic_equations_matches_the_multiblade_eigenvalues(nrel):
    """Two independent routes through the rotating equations: Floquet theory on the periodic
    equations in physical blade coordinates (the route two-bladed rotors take), and the
    eigenvalues of the multi-blade (time-invariant) equations, in the same reduced basis.
    Floquet exponents are defined modulo iΩ, so the multi-blade frequencies are folded into
    [0, Ω/4π]; they agree to 5·10⁻⁴ Hz, and no multiplier exceeds 1 (undamped, stable)."""
    from wtvib.numerics import modal

    model = coupled.build(nrel, "locked")
    omega = 12.1 * math.pi / 30
    p = periodic.periodic(model, cutoff_hz=3.0)
    rho = periodic.multipliers(p, omega)
    assert rho is not None
    period = 2 * math.pi / omega
    floquet_f = np.sort(np.abs((np.log(rho) / period).imag)) / (2 * math.pi)
    basis = periodic.reduction(model, cutoff_hz=3.0)  # blade block identity: MBC as well
    m, d, k = (basis.T @ x @ basis for x in multiblade.fixed_frame(model, omega))
    f = np.abs(modal.state_roots(k, m, d).imag) / (2 * math.pi)
    rev = omega / (2 * math.pi)
    folded = np.sort(np.minimum(np.mod(f, rev), rev - np.mod(f, rev)))
    assert np.abs(floquet_f - folded).max() < 5e-4
    assert np.abs(rho).max() <= 1 + 1e-9


def test_rotor_gyroscopic_coupling_of_tilt_and_yaw_is_polar_inertia_times_speed(nrel):
    """Rigid-rotor theory: a rotor spinning at Ω couples nacelle tilt and yaw by J_p·Ω
    (gyroscopic moment). Here the blades' share comes out of the point-mass kinematics and
    the hub's from its spinning inertia; their sum must be the rotor's polar inertia."""
    model = coupled.build(nrel, "locked")
    lay = model.layout
    _, d, _ = multiblade.fixed_frame(model, 1.0)
    d = d - model.d_v  # the drive-train damper is not gyroscopic
    tilt, yaw = lay.fa.stop - 1, lay.yaw
    j_polar = 3 * float(np.sum(model.rotor.mass * model.rotor.radius**2)) + model.hub_polar
    assert d[tilt, yaw] == pytest.approx(j_polar, rel=1e-9)
    assert d[yaw, tilt] == pytest.approx(-j_polar, rel=1e-9)


@pytest.mark.parametrize("condition", ["free", "locked", "grid"])
def test_rigid_support_gives_back_the_drive_train_in_each_generator_condition(nrel, condition):
    """Tower, yaw drive and blades made 10⁶ times stiffer, the shaft damper removed: the
    coupled drive-train modes equal the isolated chain model's (wtvib.subsystems.drivetrain) in each
    generator condition — grid with a made-up synchronous generator (any coupling spring
    will do for an identity)."""
    from wtvib.subsystems import drivetrain

    d = nrel.model_dump()
    for part, keys in (
        (d["blade"]["structure"], ("ei_flap_nm2", "ei_edge_nm2")),
        (d["tower"]["distributed"], ("ei_fa_nm2", "ei_ss_nm2")),
    ):
        for key in keys:
            part[key] = [v * 1e6 for v in part[key]]
    d["tower"]["gravity"] = False
    d["yaw"]["drive_stiffness_nm_rad"] *= 1e6
    d["drivetrain"]["shafts"][-1]["damping_nms_rad"] = 0.0
    d["drivetrain"].update(
        generator="synchronous",
        grid_coupling="direct",
        generator_model={"rated_power_kw": 5000, "pole_pairs": 2, "pull_out_power_kw": 10000},
    )
    d["coupled"]["rotating_condition"] = condition
    s = spec.Spec.model_validate(d)
    iso = sorted(m.frequency_hz for m in drivetrain.modes(s) if f".{condition}." in m.id)
    got = multiblade.rotating(coupled.build(s, condition), 0.0, 40).frequency_hz
    for f in iso[:2]:
        assert np.min(np.abs(got / f - 1)) < 2e-3, (condition, f, got[:6])


def test_drive_train_damper_damps_the_coupled_drive_train_mode(nrel):
    """The deck's shaft damper (DTTorDmp) is the only damping the coupled model keeps: the
    drive-train mode carries what it gives on top of the material default (used for its
    DAF), the tower modes the default alone, each labelled."""
    ms = {m.id: m for m in audit.run(nrel).modes if m.subsystem == "system"}
    default = coupled.default_damping(nrel).ratio
    drive = ms["system.drivetrain1"]
    assert drive.damping_source is not None and "dampers" in drive.damping_source
    assert default + 0.001 < drive.damping_ratio < 0.2  # type: ignore[operator]
    tower = ms["system.tower.fa1"]
    assert tower.damping_ratio is not None and tower.damping_source is not None
    assert "dampers" not in tower.damping_source


def test_coupled_modes_weigh_the_parts_damping_by_their_strain_energy(nrel):
    """A coupled mode's material damping is the tower's and the blades' ratios weighed by
    the strain energy the mode puts in each (modal strain energy), each as ElastoDyn
    applies the deck's ratios (TwrFADmp/TwrSSDmp 1 %, BldFlDmp/BldEdDmp 0.477 %):
    stiffness-proportional at the frequency the deck's polynomial implies on the part alone
    (the tower's first fore-aft 0.947 Hz, as ElastoDyn's own procedure computes it:
    test_rtest_models.py), so a mode at f carries ζ·f/f_alone — the tower's first pair
    within 10 % of OpenFAST's linearisation of the same deck (r-test 5MW_Land_BD_Linear,
    no aerodynamics: 0.357 % fore-aft, 0.377 % side-side, whose BeamDyn blades add their
    own; measured −7.7 %, −9.5 %), the second fore-aft within 15 % of 1 %·f/f_alone (its
    blade strain takes the blades' ratio); the first blade modes near 0.477 % at
    standstill, where they sit near their reference frequencies."""
    ms = {m.id: m for m in audit.run(nrel).modes if m.subsystem == "system"}
    alone = tower.alone_frequencies(nrel)
    assert alone["fa1"] == pytest.approx(0.947, rel=0.01)
    # (the second side-side couples with the blades' collective edge and the shaft in the
    # four-mode rotor, the drive train's dampers adding to it: not held here)
    for name, tol in (("fa1", 0.05), ("ss1", 0.05), ("fa2", 0.15)):
        m = ms[f"system.tower.{name}"]
        assert m.damping_ratio == pytest.approx(0.01 * m.frequency_hz / alone[name], rel=tol)
        assert "strain energy" in (m.damping_source or "")
    for name, theirs in (("tower.fa1", 0.00357), ("tower.ss1", 0.00377)):
        assert ms[f"system.{name}"].damping_ratio == pytest.approx(theirs, rel=0.1)
    for name in ("flap1.backward", "flap1.collective", "edge1.backward"):
        assert ms[f"system.blade.{name}"].damping_ratio == pytest.approx(0.00477465, rel=0.05)


@pytest.mark.parametrize("deck", ["AOC15-50/Test08.fst", "IEA3.4/IEA-3.4-130-RWT_ElastoDyn.dat"])
def test_the_dampers_add_to_every_coupled_modes_material_damping(shared, deck):
    """A mode the drive train's dampers touch only a little keeps its parts' damping: the AOC
    15/50's first side-side mode moves the gearbox enough for ζ = 0.0011 from the dampers,
    and was judged with that alone (DAF 450 at a crossing instead of ≤ 1/(2·0.03)); the
    IEA-3.4's second side-side likewise (0.00017)."""
    s = importers.load(
        shared / "reference" / deck,
        importers.ReadOptions(rpm=(3.8, 11.75) if "IEA" in deck else None),
    )
    system = [m for m in audit.run(s).modes if m.subsystem == "system"]
    assert system
    # the lowest material damping any part gives (the tower's as ElastoDyn applies it: its
    # first modes under the head carry TwrFADmp·f/f_alone, tower.mode_damping)
    floor = min(
        coupled.default_damping(s).ratio,
        *(tower.mode_damping(s, m.id.rsplit(".", 1)[1], m.frequency_hz)
          for m in system if m.id in ("system.tower.fa1", "system.tower.ss1")),
    )  # fmt: skip
    assert all(m.damping_ratio is not None and m.damping_ratio >= floor * 0.999 for m in system)
    assert any("dampers" in (m.damping_source or "") and m.damping_ratio > floor for m in system)


@pytest.mark.parametrize("rpm", [9.0, 12.1])
def test_whirl_labels_map_fixed_frame_lines_to_the_blade_harmonic(nrel, rpm):
    """On a rigid support the fixed-frame frequency of each whirl mode, in units of
    1P, plus the shift of excitation.driving_harmonic (backward +1, forward −1, collective
    0) is the isolated rotating blade's frequency in units of 1P — the blade harmonic that
    meets the mode where a fixed-frame line kP does. Derivation in driving_harmonic."""
    from wtvib.judge.excitation import driving_harmonic

    s = stiffened(nrel, tower_ei=1e6)
    omega = rpm * math.pi / 30
    res = multiblade.rotating(coupled.build(s, "locked"), omega, 20)
    names, freqs, _, _ = blade.rotating_modes(s.blade.structure, np.array([omega]))  # type: ignore[arg-type]
    iso = dict(zip(names, freqs[0], strict=True))
    p = omega / (2 * math.pi)
    seen = set()
    for f, name, whirl in zip(res.frequency_hz, res.names, res.whirl, strict=True):
        mode = name.split(".")[1] if name.startswith("blade.") else None
        if mode not in ("flap1", "edge1") or whirl not in ("backward", "forward", "collective"):
            continue
        k = f / p  # the fixed-frame "harmonic" this mode sits on
        shift = driving_harmonic(10, whirl) - 10
        assert k + shift == pytest.approx(iso[mode] / p, rel=2e-3), (name, whirl)
        seen.add((mode, whirl))
    assert {("flap1", w) for w in ("backward", "forward", "collective")} <= seen


def test_nrel_flap_backward_whirl_on_3p_is_the_blades_4p(nrel):
    """The resonance the isolated blade check called 4P (info) and the coupled check 3P
    (fail) — judged once: on fixed 3P the flap backward whirl is driven by the blades' 4P,
    a minor harmonic (info), and the isolated blade mode is not judged at all."""
    r = audit.run(nrel)
    f = next(
        f
        for f in r.findings
        if f.mode.id == "system.blade.flap1.backward" and f.excitation.id == "3P"
    )
    assert f.driven_by == "4P" and f.energy == "minor" and f.status == "info"
    assert not [x for x in r.findings if x.mode.id == "blade.flap1"]
    ids = {m.id: m for m in r.modes}
    assert ids["blade.flap1"].superseded_by == "system.blade.flap1.backward"


WINDPACT = "reference/WindPACT1.5/Test13.fst"


def _windpact_drive_train(shared: Any, blades: float, tower_ei: float) -> tuple[float, float]:
    """Frequency and drive-train energy share of the WindPACT 1.5 MW coupled mode with the
    most drive-train energy (free generator, parked), blades and tower stiffened."""
    d = importers.load(shared / WINDPACT).model_dump()
    for part, keys in (
        (d["blade"]["structure"], ("ei_flap_nm2", "ei_edge_nm2")),
        (d["tower"]["distributed"], ("ei_fa_nm2", "ei_ss_nm2", "gj_nm2")),
    ):
        for key in keys:
            part[key] = [
                v * (blades if part is d["blade"]["structure"] else tower_ei) for v in part[key]
            ]
    d["tower"]["gravity"] = tower_ei == 1.0
    res = multiblade.parked(coupled.build(spec.Spec.model_validate(d), "free"), count=40)
    # (with rigid blades the rotor turning on the free generator is a near-zero root)
    share = [
        e.get("drivetrain", 0.0) * (f > 0.1)
        for e, f in zip(res.energy, res.frequency_hz, strict=True)
    ]
    j = int(np.argmax(share))
    return float(res.frequency_hz[j]), share[j]


def test_windpact_drive_train_mode_between_its_rigid_blade_and_hub_only_limits(shared):
    """WindPACT 1.5 MW deck (DTTorSpr 5.6e9 N·m/rad, GenIner 53.036 kg·m² × GBRatio
    87.965², HubIner 34,600 kg·m², rotor 2,962,444 kg·m² from the deck's own summary
    Test13.fsm). Tower 10⁶ times stiffer: with rigid blades too, the coupled drive-train
    mode is the two-inertia closed form √(k(1/J_rotor + 1/J_gen))/2π = 19.84 Hz (to 0.5 %);
    with the deck's flexible blades it lies between that and the hub-against-generator
    limit √(k(1/J_hub + 1/J_gen))/2π = 66.7 Hz (the blades' tips decouple above their edge
    frequencies) — 35.1 Hz with the blades' four modes, a drive-train mode (90 % of its
    energy and more); 25.6 Hz with their first edgewise bending alone, where FAST's
    linearisation of the deck (ElastoDyn's one edgewise DOF) has it (about 26 Hz): the
    second edgewise bending lets the blades' roots decouple further (five modes: 35.1)."""
    k, j_gen, j_hub, j_rotor = 5.6e9, 53.036 * 87.965**2, 34_600.0, 2_962_443.75
    rigid = math.sqrt(k * (1 / j_rotor + 1 / j_gen)) / (2 * math.pi)
    hub_only = math.sqrt(k * (1 / j_hub + 1 / j_gen)) / (2 * math.pi)
    f, share = _windpact_drive_train(shared, 1e6, 1e6)
    assert f == pytest.approx(rigid, rel=5e-3) and share > 0.95
    f, share = _windpact_drive_train(shared, 1.0, 1e6)
    assert rigid * 1.05 < f < hub_only and share > 0.9


def test_windpact_drive_train_torsion_is_kept_where_the_tower_takes_it(shared):
    """On the deck's own (flexible) tower the gearbox reaction on the tower top couples the
    drive-train torsion to the tower's side-side modes near it (with the blades' four modes
    the torsion lies near 35 Hz: a side-side mode there carries 23 % of it — no mode is
    dominated by it), above the lowest 16 modes the coupled model used to report: they are
    kept for their content and say so."""
    ms = [m for m in audit.run(importers.load(shared / WINDPACT)).modes if m.subsystem == "system"]
    share = re.compile(r"(\d+)% drive-train torsion")
    carrying = [
        int(hit.group(1)) / 100
        for m in ms
        if m.frequency_hz > 10 and (hit := share.search(m.description))
    ]
    assert len(carrying) >= 1, [(m.id, m.frequency_hz) for m in ms]
    assert min(carrying) >= multiblade.CONTENT_SHARE


@pytest.mark.parametrize(
    "deck",
    [
        "reference/NREL5MW/NREL-5MW.fst",
        "reference/AOC15-50/Test08.fst",  # a drive-train damper; 48 standstill modes: 3e-4
        WINDPACT,  # drive-train torsion kept by content above the lowest 16 modes
    ],
)
def test_the_rotating_sweep_in_its_ritz_basis_matches_the_full_model(shared, deck):
    """The sweep over rotor speed runs in the model's Ritz basis (standstill modes and what
    the dampers' and the rotation's loads excite beyond them, multiblade.RITZ_STANDSTILL):
    the same modes kept, and every frequency and damping ratio at every speed as the full
    multi-blade eigenproblem gives them, to 1e-7 (the reference: the full model itself)."""
    s = importers.load(shared / deck)
    model = coupled.build(s, s.coupled.rotating_condition)
    points = [(float(om), None) for om in coupled.speeds(s)]
    full = multiblade.track(model, points)
    reduced = multiblade.track(model, points, reduced=True)
    assert reduced.basis and model.ritz(reduced.basis)[0].shape[1] < model.multiblade[0].shape[0]
    assert reduced.first.names == full.first.names
    np.testing.assert_allclose(reduced.frequency_hz, full.frequency_hz, rtol=1e-7)
    np.testing.assert_allclose(reduced.damping_ratio, full.damping_ratio, atol=1e-7)


def _assumed_modes(s: spec.Spec, deck: str, names: tuple[str, str], plane: str) -> float:
    """The first frequency of ElastoDyn's tower model: Rayleigh–Ritz on the deck's two
    polynomial mode shapes φ(x) = Σ cₖxᵏ (k = 2…6, x = z/L) with the tower's distributed
    properties, gravity's geometric stiffness ∫P(z)φ′² dz and the rigid head at the top —
    written out here from the tower file and the spec's head (mass, CM, inertia), not
    through wtvib.subsystems.tower."""
    coef = [
        [float(re.search(rf"^\s*(\S+)\s+{n}\({k}\)", deck, re.M).group(1)) for k in range(2, 7)]  # type: ignore[union-attr]
        for n in names
    ]
    d, head = s.tower.distributed, s.tower_head
    assert d is not None and head is not None
    length = s.tower.height_m
    z = np.linspace(0.0, length, 4001)
    mass = np.interp(z, d.height_m, d.mass_per_length_kg_m)
    ei = np.interp(z, d.height_m, d.ei_fa_nm2 if plane == "fa" else d.ei_ss_nm2)
    x = z / length
    powers = np.arange(2, 7)
    shape = np.array([np.sum(np.multiply.outer(x, np.ones(5)) ** powers * c, axis=1) for c in coef])
    slope = (
        np.array([np.sum(x[:, None] ** (powers - 1) * powers * c, axis=1) for c in coef]) / length
    )
    curve = (
        np.array(
            [np.sum(x[:, None] ** (powers - 2) * powers * (powers - 1) * c, axis=1) for c in coef]
        )
        / length**2
    )
    g = 9.80665
    above = np.array([np.trapezoid(mass[i:], z[i:]) for i in range(len(z))])
    axial = g * (head.mass_kg + above)
    k = np.einsum("az,bz->ab", curve * ei, curve) * (z[1] - z[0])
    k -= np.einsum("az,bz->ab", slope * axial, slope) * (z[1] - z[0])
    m = np.einsum("az,bz->ab", shape * mass, shape) * (z[1] - z[0])
    # the head: translation u + θ·h of its CM at height h above the top (fore-aft also the
    # vertical −θ·x of a CM x downwind), and its rotary inertia about the CM
    h, xd = head.cm_above_top_m, head.cm_downwind_m if plane == "fa" else 0.0
    inertia = head.inertia_pitch_kgm2 if plane == "fa" else head.inertia_roll_kgm2
    top = np.stack([shape[:, -1], slope[:, -1]], axis=1)
    mh = head.mass_kg * np.array([[1.0, h], [h, h * h + xd * xd]])
    mh[1, 1] += inertia
    m += top @ mh @ top.T
    lam = np.linalg.eigvals(np.linalg.solve(m, k))
    return float(np.sqrt(np.min(lam.real)) / (2 * math.pi))


def test_fasts_fore_aft_above_side_side_is_its_assumed_mode_shapes(nrel, shared):
    """FAST puts the parked NREL 5-MW's first fore-aft mode above the side-side
    one (0.3240 against 0.3120 Hz, Table 9-1; ADAMS 0.3195 / 0.3164). No term is missing
    from the coupled model: generator locked, as the table is, its side-side mode (the
    rotor's polar inertia rolling with the nacelle) lies below the fore-aft one too, within
    0.1 % of FAST's. FAST's fore-aft frequency is ElastoDyn's Rayleigh–Ritz estimate on the
    deck's polynomial shapes — an upper bound, +3.5 % above the converged beam with the same
    tower, head and gravity (0.3275 against 0.3164 Hz; written out in _assumed_modes), where
    its side-side shapes are within 1 % of it; with the generator free the side-side mode
    loses the rotor's roll inertia and rises above fore-aft (0.319 Hz), which is what an
    audit in operation sees."""
    locked, free = parked(nrel), parked(nrel, "free")
    assert locked["tower.ss1"] < locked["tower.fa1"]
    assert locked["tower.ss1"] == pytest.approx(0.3120, rel=0.001)
    assert free["tower.ss1"] > free["tower.fa1"]
    deck = (
        shared / "reference/NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat"
    ).read_text()
    b = tower.discretise(nrel.tower)
    fa, ss = tower.bending_pair(b, nrel.tower_head, [], nrel.tower.foundation, nrel.tower.gravity)
    fa_ritz = _assumed_modes(nrel, deck, ("TwFAM1Sh", "TwFAM2Sh"), "fa")
    ss_ritz = _assumed_modes(nrel, deck, ("TwSSM1Sh", "TwSSM2Sh"), "ss")
    # Rayleigh–Ritz bounds the converged beam from above, the fore-aft shapes by 3–4 %
    assert 1.03 < fa_ritz / fa.frequency_hz[0] < 1.04
    assert 1.0 <= ss_ritz / ss.frequency_hz[0] < 1.015
    # FAST's own values lie 1.1 % (fore-aft) and 1.6 % (side-side) below the written-out
    # estimates (0.3275, 0.3171 Hz): its blades are flexible, which lowers both tower modes
    # of the coupled model by 0.7 % from the rigid head's
    assert fa_ritz == pytest.approx(0.3240, rel=0.02)
    assert ss_ritz == pytest.approx(0.3120, rel=0.02)


@pytest.mark.parametrize(
    "deck",
    [
        "reference/AOC15-50/Test08.fst",
        "reference/AWT27/Test01.fst",
        "reference/WindPACT1.5/Test13.fst",
        NREL,
        "reference/IEA3.4/IEA-3.4-130-RWT_ElastoDyn.dat",
        "reference/IEA10/IEA-10.0-198-RWT_ElastoDyn.dat",
    ],
)
def test_every_parked_mode_has_a_name_of_its_own(shared, deck):
    """Two coupled modes that share one blade family's coordinate (the AOC 15/50's
    cyclic edge modes with its tower torsion, 49 % and 43 %; its second flap modes, collective
    and cyclic mixed by the tower) were named alike and numbered (``cyclic_yaw_2``,
    ``collective_2``) while the family's other name went unused. The second takes its next
    group's free name — the other cyclic axis, a part's next number — and says so."""
    s = importers.load(shared / deck)
    res = multiblade.parked(coupled.build(s, "locked"))
    assert not [n for n in res.names if re.search(r"_\d+$", n)], res.names
    assert len(set(res.names)) == len(res.names)
    if "AOC" in deck:
        at = dict(zip(res.names, res.frequency_hz.tolist(), strict=True))
        # the family complete: one collective and both cyclic axes
        assert {
            "blade.flap2.collective",
            "blade.flap2.cyclic_tilt",
            "blade.flap2.cyclic_yaw",
        } <= set(at)
        # the edge–tower-torsion pair: the one with less edge energy named by its torsion
        assert at["blade.edge1.cyclic_yaw"] < at["tower.tor1"] < at["tower.tor2"]
        said = dict(zip(res.names, res.descriptions, strict=True))
        assert "(tilt)" in said["blade.flap2.cyclic_tilt"]  # its text follows the name
        assert "named by its second share" in said["tower.tor1"]


def test_a_mode_keeps_what_it_is_through_a_crossing(tmp_path):
    """An id names one physical mode from standstill to overspeed: on the NREL 5-MW on the
    OC3 monopile (r-test 5MW_OC3Mnpl_Linear's deck set) the first flap's forward whirl,
    rising as f + Ω, crosses the first edge's backward whirl, falling as f − Ω, near 12 rpm;
    for one speed of the sweep both look like the flap's forward whirl (mixed), and the
    sweep used to hand ``blade.flap1.forward`` on to a 4.3 Hz second-edge root and call
    ``blade.edge1.backward`` a forward flap whirl at overspeed. Each follows its own kind
    and part now: at every speed but that one its energy sits where its id says, its
    frequency moves by less than 5 % a step, and its description at overspeed names it."""
    import tarfile
    from pathlib import Path

    with tarfile.open(Path(__file__).parents[1] / "data/openfast_decks/rtest.tar.gz") as tar:
        tar.extractall(tmp_path, filter="data")
    case = "5MW_OC3Mnpl_Linear"
    s = importers.load(tmp_path / "glue-codes/openfast" / case / f"{case}.fst")
    sw = coupled.rotating_sweep(s)
    model = coupled.build(s, s.coupled.rotating_condition)
    mass = model.multiblade[0]
    where = [multiblade.parts(model, mass, shapes) for shapes in sw.path.shapes]
    for j, name in enumerate(sw.names):
        if not name.startswith("blade."):
            continue
        family = ".".join(name.split(".")[:2])  # blade.flap1
        own = sum(w[j] == family for w in where)
        assert own >= len(where) - 1, (name, [w[j] for w in where])
        steps = np.abs(np.diff(sw.frequency_hz[:, j])) / sw.frequency_hz[:-1, j]
        assert steps.max() < 0.05, (name, steps.max())
        kind = name.split(".")[-1]
        if kind in ("backward", "forward"):
            assert f"{kind} whirl" in sw.descriptions[j], (name, sw.descriptions[j])


def test_the_first_order_damping_of_a_whirling_mode_is_the_exact_roots_to_second_order(nrel):
    """:func:`multiblade.perturbed` — the damping the audit takes where no damped root
    resembles a structural mode — against the exact roots of the same problem: the NREL
    5-MW at 12.1 rpm with a small damping on each blade's first flap coordinate (ζ ≈ 0.002
    on the flap). Its first-order ζ of every kept mode, the first flap backward and
    forward whirls among them, agrees with the eigen-solution's to 3 % of the largest
    added ζ: the error is of second order. Its denominator xᴴ(2λM + G)x holds the rotor's
    gyroscopic terms (G = D₀ + Ω·D₁): with their sign flipped two whirls' added ζ is off by
    more than it (measured: by 115 %)."""
    model = coupled.build(nrel, nrel.coupled.rotating_condition)
    omega = 12.1 * math.pi / 30
    base = multiblade.rotating(model, omega, 12)
    n = model.layout.size
    flap = model.layout.blades.start + np.arange(model.blades) * model.k_blades
    d = np.zeros((n, n))
    mass = np.diag(model.multiblade[0])[flap]
    d[flap, flap] = 2 * 0.002 * (2 * math.pi * 0.7) * mass  # ζ ≈ 0.002 at the flap's 0.7 Hz
    extra = (d, np.zeros((n, n)))
    lam = modal.eigenvalue(base.frequency_hz, base.damping_ratio)
    first = multiblade.perturbed(model, omega, extra, base.shapes, lam)
    exact = multiblade.rotating(model, omega, 12, extra)
    weight = np.sqrt(np.diag(model.multiblade[0]))[:, None]
    order = modal.track(weight * base.shapes, weight * exact.shapes)
    added = exact.damping_ratio[order] - base.damping_ratio
    flapping = [j for j, name in enumerate(base.names) if name.startswith("blade.flap1")]
    assert min(added[flapping]) > 5e-4  # the flap modes are damped by the added matrix
    np.testing.assert_allclose(first - base.damping_ratio, added, atol=0.03 * float(np.max(added)))
