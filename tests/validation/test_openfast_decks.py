"""OpenFAST deck sets as their users run them, against what OpenFAST computes on the same
decks and what their authors publish.

The deck sets (``tests/data/openfast_decks/*.tar.gz``, SOURCES.md there) hold exactly the
files wtvib reads, at their paths in the source repositories:

* OpenFAST's regression tests (OpenFAST/r-test) ship decks together with OpenFAST's own
  linearisation of them: ``5MW_OC3Mnpl_Linear`` (the NREL 5-MW on the OC3 monopile in
  SubDyn, clamped at the seabed, 12.1 rpm, no aerodynamics, no HydroDyn) and
  ``5MW_Land_BD_Linear`` (the onshore 5-MW with BeamDyn blades, 12.1 rpm, no
  aerodynamics). OpenFAST's modes are the roots of the azimuth-averaged multi-blade state
  matrix of the ``.lin`` files in ``tests/data/openfast_lin`` — the numbers below are
  openfast_toolbox's MBC3 on those files (``reference.json`` there), which wtvib's own
  reader reproduces to 1e-7 (test_openfast_lin.py); the modes are named after Jonkman et
  al. 2009, Table 9-1, as that reader names them.
* The IEA Wind reference turbines' own OpenFAST monopile deck sets, read without edits,
  against their published first tower-and-monopile frequencies.

Where wtvib and OpenFAST model the same structure differently, the tolerance says so:
ElastoDyn's tower bends in two assumed shapes per plane (Rayleigh–Ritz, the tower file's
polynomials), wtvib's in finite elements; ElastoDyn has no tower torsion.
"""

import tarfile
from pathlib import Path

import numpy as np
import pytest

from wtvib import audit, importers
from wtvib.subsystems import coupled

DATA = Path(__file__).resolve().parents[1] / "data" / "openfast_decks"


@pytest.fixture(scope="module")
def decks(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("decks")
    for name in ("rtest", "rtest_aero", "iea15", "iea22"):
        with tarfile.open(DATA / f"{name}.tar.gz") as tar:
            tar.extractall(root / name, filter="data")
    return root


def _at_speed(spec, rpm: float) -> dict[str, float]:
    """The coupled model's modes at a rotor speed: name → frequency [Hz]."""
    sw = coupled.rotating_sweep(spec)
    omega = rpm * np.pi / 30
    return {
        n: float(np.interp(omega, sw.omega, sw.frequency_hz[:, j])) for j, n in enumerate(sw.names)
    }


#: OpenFAST on 5MW_OC3Mnpl_Linear (12.1 rpm): its first tower pair on the monopile [Hz]
#: (reference.json, the case's first two roots above the generator's).
OC3_TOWER = {"tower.fa1": 0.2755397832, "tower.ss1": 0.277581241}


def test_tower_on_its_subdyn_monopile_against_openfasts_linearisation(decks):
    """The 5-MW tower on the OC3 monopile: SubDyn's pile (6 m × 60 mm, seabed at −20 m,
    clamped) under the ElastoDyn tower from 10 m. OpenFAST's first fore-aft and side-side
    modes (0.2755, 0.2776 Hz at 12.1 rpm) within 2 %; measured −1.3 % and −0.5 %. Clamped
    at the transition piece instead (the tower alone, as wtvib read the deck before), the
    first pair comes out 21 % high."""
    deck = decks / "rtest/glue-codes/openfast/5MW_OC3Mnpl_Linear/5MW_OC3Mnpl_Linear.fst"
    s = importers.load(deck)
    # TowerHt 87.6 m above MSL, the reaction joint at −20.0001 m
    assert s.tower.foundation.kind == "clamped" and s.tower.height_m == pytest.approx(
        87.6 + 20.0001
    )
    assert not any("tower.foundation" in w for w in s.warnings)  # the pile is read, not warned
    f = _at_speed(s, 12.1)
    for name, openfast in OC3_TOWER.items():
        assert f[name] == pytest.approx(openfast, rel=0.02), name


#: OpenFAST on 5MW_Land_BD_Linear (12.1 rpm, BeamDyn blades, no aerodynamics) [Hz]: its
#: .lin (tests/data/openfast_lin) read by wtvib with BeamDyn's states in the rotating frame
#: (openfast_lin.beamdyn_frame: OpenFAST issue #3394 — as written, reference.json's
#: roots, the side-side is 0.3113, the first edgewise pair 0.9211/1.3173), named as wtvib's
#: .lin reader names them (Table 9-1's families, whirl from the cyclic phase).
BD_TOWER = {"tower.ss1": 0.3216252216, "tower.fa1": 0.3248856133, "tower.fa2": 2.9096657158}
BD_ROTOR = {
    "blade.flap1.backward": 0.5365956090,
    "blade.flap1.collective": 0.7622303129,
    "blade.edge1.backward": 0.8963687237,
    "blade.flap1.forward": 0.9357140050,
    "blade.edge1.forward": 1.3032366402,
    "drivetrain1": 1.6882661711,
    "blade.flap2.backward": 1.8269892441,
    "blade.flap2.collective": 2.1160708650,
    "blade.flap2.forward": 2.2148614244,
}


def test_beamdyn_rotor_against_openfasts_linearisation(decks):
    """The onshore 5-MW deck set with BeamDyn blades (ElastoDyn's blade files absent, as
    OpenFAST runs it): every rotor and drive-train mode OpenFAST finds below 2.3 Hz at 12.1
    rpm is wtvib's mode of the same name within 3 % (measured ≤ 2.2 %, the second flap
    family the farthest) — the BeamDyn blade's 6×6 sections read right (flapwise K55,
    edgewise K44: swapped, the first flap family moves 30 %), and each Campbell curve the
    same physical mode as OpenFAST's (before, the curve named after the collective
    flap mode at standstill was the forward whirl at 12.1 rpm). The tower's first pair
    within 5 % (measured −3.3 % fore-aft: ElastoDyn's assumed shapes, see the module notes;
    −0.6 % side-side) and its second fore-aft within 2 %."""
    deck = decks / "rtest/glue-codes/openfast/5MW_Land_BD_Linear/5MW_Land_BD_Linear.fst"
    s = importers.load(deck)
    assert any("Blade from BeamDyn" in a for a in s.assumptions)
    f = _at_speed(s, 12.1)
    for name, openfast in BD_TOWER.items():
        tol = 0.05 if name.endswith("1") else 0.02
        assert f[name] == pytest.approx(openfast, rel=tol), name
    from tests.validation.test_rtest_models import EXCEPTIONS

    for name, openfast in BD_ROTOR.items():
        if ("5MW_Land_BD_Linear", name) in EXCEPTIONS:  # the two held there, with why
            lo, hi, _ = EXCEPTIONS[("5MW_Land_BD_Linear", name)]
            assert lo <= f[name] / openfast - 1 <= hi, name
        else:  # 3 %, 5 % above 2 Hz (as test_rtest_models.py holds every case)
            assert f[name] == pytest.approx(openfast, rel=0.03 if openfast <= 2 else 0.05), name


def test_beamdyn_blade_damping_is_its_stiffness_proportional_mu(decks):
    """ζ = π·μ·f: the 5-MW's BeamDyn μ (flap 0.0022, edge 0.0014 s) at its first flap and
    edge frequencies give 0.48 % and 0.49 %; OpenFAST's linearisation has the collective
    flap at 0.45 % (reference.json) — the same damping, not ElastoDyn's 2.5 %."""
    from wtvib.subsystems import blade

    deck = decks / "rtest/glue-codes/openfast/5MW_Land_BD_Linear/5MW_Land_BD_Linear.fst"
    s = importers.load(deck)
    # the importer passes μ on as it is (the blade's physics turns it into ratios)
    assert s.blade.stiffness_damping_s is not None
    assert "damping_ratio" not in s.blade.model_fields_set
    assert blade.default_damping(s).ratio == pytest.approx(0.0045, rel=0.1)
    flap1 = next(m for m in blade.build_modes(s, {}) if m.id == "blade.flap1")
    assert flap1.damping_ratio == pytest.approx(0.0045, rel=0.1)


#: Published first tower-and-monopile frequencies [Hz]: IEA-15 — Gaertner et al. 2020
#: (NREL/TP-5000-75698), 0.17 Hz, and WISDEM's 0.181 / 0.180 Hz for the later model
#: (IEAWindSystems/IEA-15-240-RWT issue #247); IEA-22 — Zahle et al. 2024 (IEA Wind TCP Task
#: 55), Table 13: 0.16 Hz fore-aft and side-side, which OpenFAST on this deck set gives too
#: (IEAWindSystems/IEA-22-280-RWT issue #100: the monopile clamped at the mudline, −34 m).
PUBLISHED = {"iea15": (0.17, 0.181), "iea22": (0.16, 0.16)}
DECKS = {
    "iea15": "iea15/OpenFAST/IEA-15-240-RWT-Monopile/IEA-15-240-RWT-Monopile.fst",
    "iea22": "iea22/OpenFAST/IEA-22-280-RWT-Monopile/IEA-22-280-RWT-Monopile.fst",
}


@pytest.mark.parametrize("turbine", sorted(DECKS))
def test_iea_monopile_deck_sets_audit_without_edits_on_their_monopile(decks, turbine):
    """The IEA-15 and IEA-22 OpenFAST monopile deck sets, read as published (the IEA-22's
    BeamDyn blades, both SubDyn piles with their transition-piece masses, HydroDyn's added
    and enclosed water): the first tower pair within 5 % of the published band (measured:
    IEA-15 0.171 / 0.171 Hz, IEA-22 0.157 / 0.155 Hz); clamped at the transition piece
    they would be 0.23 and 0.20 Hz."""
    s = importers.load(decks / DECKS[turbine])
    assert s.tower.added_mass is not None and max(s.tower.added_mass.mass_per_length_kg_m) > 1e5
    lo, hi = PUBLISHED[turbine]
    modes = {m.id: m.frequency_hz for m in audit.run(s).modes}
    for name in ("tower.fa1", "tower.ss1"):
        assert lo * 0.95 <= modes[name] <= hi * 1.05, (name, modes[name])


def test_the_iea15_monopile_is_meshed_at_its_stations_not_at_its_water_tables(decks, monkeypatch):
    """HydroDyn's water along the IEA-15 monopile is a table of 401 heights; meshed at each
    (more than beam.MAX_STATION_NODES stations) the tower and pile were resampled into 200
    uniform elements that smeared their own property steps over an element: the second
    bending pair 4.4 and 5.2·10⁻⁴, the third 1.4 and 1.8·10⁻³ off a mesh at every station
    and every one of the water's heights (476 nodes, beam.MAX_STATION_NODES lifted), and
    815 coordinates in the coupled model. Meshed at the tower's stations and where the
    water table ends and steps (the still-water line): 25 nodes, its first three modes in
    each plane within 10⁻⁴ of the fine mesh (measured 1.2·10⁻⁵ at most: the 10-element
    grid's h⁴ error on the third)."""
    from wtvib.numerics import beam
    from wtvib.subsystems import tower

    s = importers.load(decks / DECKS["iea15"])
    t, head = s.tower, tower.bending_head(s)
    coarse = tower.discretise(t)
    assert len(coarse.nodes) < 30
    monkeypatch.setattr(beam, "MAX_STATION_NODES", 10**6)  # every station and water height
    monkeypatch.setattr(tower, "added_mass_breaks", lambda a: np.asarray(a.height_m))
    fine = tower.discretise(t, 80)
    assert len(fine.nodes) > 400
    for b in (coarse, fine):  # the water whole in both
        assert np.sum(beam.gauss_points(b.nodes)[1] * b.added) == pytest.approx(
            np.trapezoid(t.added_mass.mass_per_length_kg_m, t.added_mass.height_m), rel=2e-3
        )
    solved = [
        tower.bending_pair(b, head, t.point_masses, t.foundation, count=3) for b in (coarse, fine)
    ]
    for plane in (0, 1):
        ours, finer = solved[0][plane].frequency_hz, solved[1][plane].frequency_hz
        assert ours == pytest.approx(finer, rel=1e-4)


@pytest.mark.parametrize("turbine", sorted(DECKS))
def test_the_direct_drive_train_is_read_and_judged_once(decks, turbine):
    """The windIO files of the IEA-15 and IEA-22 give the drive train's spring and
    the generator's inertia (drivetrain.elastic_properties), which wtvib did not read — their
    coupled models had no drive train. Read as WISDEM writes them into the ElastoDyn decks of
    these deck sets (GenIner, DTTorSpr, DTTorDmp: the IEA-15's the same numbers, compared
    here; the IEA-22's deck was edited — GenIner 2.2 times the file's generator inertia, the
    shaft made rigid, 1e12 N·m/rad), both routes give the free generator's first drive-train
    mode — the blades' collective edgewise swing against the light generator (coupled, named
    blade.edge1.collective) — within 5 % (measured: IEA-15 1.66 / 1.70 Hz, IEA-22 1.29 /
    1.28 Hz), and on both that coupled mode stands for the isolated chain's first free mode,
    which is not judged a second time."""
    windio = pytest.importorskip("windIO")
    name = {"iea15": "IEA-15-240-RWT.yaml", "iea22": "IEA-22-280-RWT.yaml"}[turbine]
    from_file = importers.load(Path(windio.__file__).parent / "examples/turbine" / name)
    from_deck = importers.load(decks / DECKS[turbine])
    for s in (from_file, from_deck):
        assert s.drivetrain is not None and s.drivetrain.chain
    a, b = from_file.drivetrain, from_deck.drivetrain
    if turbine == "iea15":  # the IEA-22 deck was edited: GenIner 3.12e6, DTTorSpr 1e12
        assert a.chain[-1].inertia_kgm2 == pytest.approx(b.chain[-1].inertia_kgm2, rel=1e-6)
        assert a.shafts[-1].stiffness_nm_rad == pytest.approx(
            b.shafts[-1].stiffness_nm_rad, rel=1e-6
        )
    first = []
    for s in (from_file, from_deck):
        modes = {m.id: m for m in audit.run(s).modes}
        edge = modes["system.blade.edge1.collective"]
        assert modes["drivetrain.free.1"].superseded_by == edge.id
        assert modes["drivetrain.free.2"].superseded_by == "system.drivetrain1"
        first.append(edge.frequency_hz)
    assert first[0] == pytest.approx(first[1], rel=0.05)
    assert 1.0 < first[0] < 2.0


#: OpenFAST's linearisation of 5MW_Land_Linear_Aero (the NREL 5-MW at 8 m/s, 12.1 rpm,
#: pitch 0; aerofoils quasi-steady, UA_Mod = 0; dynamic inflow DBEMT, τ₁ = 4 s), damping
#: ratios from tests/data/openfast_lin/5MW_Land_Linear_Aero.1.lin.gz through wtvib's MBC3
#: (openfast_toolbox's roots to 1e-7: test_openfast_lin.py), by the mode names it gives.
LINEAR_AERO_8MS = {
    "tower.fa1": 0.0807,
    "blade.flap1.backward": 0.8072,
    "blade.flap1.collective": 0.6435,
    "blade.flap1.forward": 0.5405,
    "blade.flap2.backward": 0.2006,
    "blade.flap2.collective": 0.1736,
    "blade.flap2.forward": 0.1606,
}


def test_aerodynamic_damping_against_openfasts_linearisation_at_its_own_point(decks):
    """wtvib on the very deck set OpenFAST linearised (r-test 5MW_Land_Linear_Aero: fixed
    12.1 rpm, pitch 0), interpolated to 8 m/s. The deck's aerofoils are quasi-steady
    (UA_Mod 0), and so is wtvib's lift on it (aerodynamics.shed_wake false): the damping
    judged is the quasi-steady one. OpenFAST's lies below it by 2–9 %: its DBEMT inflow
    (τ₁ = 4 s; the near-wake filter τ₂ = τ₁·(0.39 − 0.26·(r/R)²), 0.5–1.6 s) follows the
    blades' motion in part, which frozen induction — wtvib's, the upper bound — does not."""
    import gzip

    from wtvib.importers import openfast_lin as ol

    lin = decks / "linear_aero.lin"
    lin.write_bytes(
        gzip.decompress((DATA.parent / "openfast_lin/5MW_Land_Linear_Aero.1.lin.gz").read_bytes())
    )
    point, _ = ol.operating_point([ol.read(lin)])
    ref = dict(zip(point.names, point.damping_ratio, strict=True))
    for name, zeta in LINEAR_AERO_8MS.items():
        assert ref[name] == pytest.approx(zeta, abs=1e-4), name  # the numbers above
    s = importers.load(
        decks / "rtest_aero/glue-codes/openfast/5MW_Land_Linear_Aero/5MW_Land_Linear_Aero.fst"
    )
    assert s.aerodynamics is not None and s.aerodynamics.shed_wake is False  # UA_Mod 0
    modes = {m.id: m for m in audit.run(s).modes}
    for name, zeta in LINEAR_AERO_8MS.items():
        op = modes[f"system.{name}"].operating
        assert op is not None and op.quasi_steady is not None
        assert op.omega[0] == pytest.approx(12.1 * np.pi / 30)
        judged = float(np.interp(8.0, op.wind, op.total))
        assert judged == pytest.approx(float(np.interp(8.0, op.wind, op.quasi_steady)))
        assert zeta < judged < 1.12 * zeta, (name, judged, zeta)
