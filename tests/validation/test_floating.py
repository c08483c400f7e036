"""The NREL 5-MW on its floating platforms, read from OpenFAST's own deck sets (r-test
``5MW_OC3Spar_Linear``, ``5MW_OC4Semi_Linear`` with MAP++ moorings, ``5MW_OC4Semi_MD_Linear``
with MoorDyn; tests/data/openfast_decks/rtest_floating.tar.gz), against three references:

* **published**: Jonkman 2010 (NREL/TP-500-47535, "Definition of the Floating System for
  Phase IV of OC3"): the spar's mooring stiffness (Table 5-1) and the whole system's
  natural frequencies from FAST free-decay tests (Table 7-1: surge and sway 0.0080 Hz,
  heave 0.0324, roll 0.0342, pitch 0.0343, yaw 0.1210); Robertson et al. 2014
  (NREL/TP-5000-60601, "Definition of the Semisubmersible Floating System for Phase II of
  OC4"): the semisubmersible's mass with ballast 1.3473·10⁷ kg (Table 3-1), its added mass
  A₁₁ 6.490·10⁶ kg, A₃₃ 1.470·10⁷ kg, A₄₄ 7.210·10⁹ kg·m² and hydrostatic C₃₃ 3.836·10⁶ N/m
  (Table 4-1 and §4.2), its mooring stiffness K₁₁ 7.08·10⁴ N/m, K₃₃ 1.91·10⁴ N/m, K₄₄
  8.73·10⁷ N·m/rad (Table 3-5);
* **pyBModes** 1.19.1 on the MoorDyn semisubmersible (``bench/pybmodes_floating.py`` →
  tests/data/floating/pybmodes.json) and on the spar (its MAP++ lines written as MoorDyn's:
  ``bench/pybmodes_floating.py oc3`` → pybmodes_oc3.json): its free tower on its own
  platform matrices;
* **OpenFAST**'s linearisation of the same decks at 12 rpm (r-test's ``.lin`` files, their
  eigenanalysis after MBC3 stored in tests/data/openfast_lin/reference.json).

What agrees and what does not, and why:

========================  =========  ==========  =========  ========
mode [Hz]                 wtvib      published   pyBModes   OpenFAST
========================  =========  ==========  =========  ========
OC3 surge / sway          0.00806    0.0080                 0.00814
OC3 heave                 0.03241    0.0324                 0.03243
OC3 roll / pitch          0.0335     0.0342/3               0.0342/0.0353
OC3 yaw                   0.1208     0.1210                 0.1302 (nacelle free)
OC3 tower fa1 / ss1       0.497/0.498           0.492/0.494 0.484/—
OC4 surge / sway          0.00884               0.00884     0.00887
OC4 heave                 0.05788               0.05785     0.05786
OC4 roll / pitch          0.0389                0.0390      0.0389/0.0387 (5.0)
OC4 yaw                   0.01258               0.01246     0.01283
OC4 tower fa1 / ss1       0.433/0.428           0.440/0.439 0.420/0.441
========================  =========  ==========  =========  ========

r-test's stored linearisation of the semisubmersible pitches and rolls 20 % faster (0.0469 /
0.0471 Hz), OpenFAST 5 on the same deck, run for wtvib, as pyBModes and wtvib do (the table's
column; tests/data/openfast_oc4, test_rtest_models.py). OpenFAST's spar yaw is the platform's
with the nacelle free in yaw on it (no yaw spring in the deck set: test_rtest_models.py),
the published and wtvib's with the head turning along. wtvib's tower is a beam under a
rigid head (its rotary inertia whole): its first bending modes lie within 3 % of both
tools', its second (2.5 Hz) not compared — stated in every floating audit.
"""

import json
import tarfile
from pathlib import Path

import pytest

from wtvib import importers
from wtvib.importers import mooring
from wtvib.importers.deck import parse
from wtvib.spec import Spec
from wtvib.subsystems import tower

DATA = Path(__file__).resolve().parents[1] / "data"
PYBMODES = json.loads((DATA / "floating" / "pybmodes.json").read_text())
PYBMODES_OC3 = json.loads((DATA / "floating" / "pybmodes_oc3.json").read_text())
CASES = ("5MW_OC3Spar_Linear", "5MW_OC4Semi_Linear", "5MW_OC4Semi_MD_Linear")
G, RHO = 9.80665, 1025.0


@pytest.fixture(scope="module")
def decks(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("floating")
    with tarfile.open(DATA / "openfast_decks" / "rtest_floating.tar.gz") as tar:
        tar.extractall(root, filter="data")
    return root / "glue-codes" / "openfast"


@pytest.fixture(scope="module")
def specs(decks: Path) -> dict[str, Spec]:
    return {case: importers.load(decks / case / f"{case}.fst") for case in CASES}


def _modes(spec: Spec) -> dict[str, float]:
    return {m.id.removeprefix("tower."): m.frequency_hz for m in tower.structural_modes(spec)}


def test_oc3_spar_frequencies_match_jonkman_2010(specs: dict[str, Spec]) -> None:
    """Jonkman 2010 Table 7-1 (FAST free decay of the OC3-Hywind system): every rigid-body
    mode within 3 %."""
    modes = _modes(specs["5MW_OC3Spar_Linear"])
    published = {
        "platform.surge": 0.0080,
        "platform.sway": 0.0080,
        "platform.heave": 0.0324,
        "platform.roll": 0.0342,
        "platform.pitch": 0.0343,
        "platform.yaw": 0.1210,
    }
    for mode, f in published.items():
        assert modes[mode] == pytest.approx(f, rel=0.03), mode


def test_oc3_spar_matches_pybmodes(specs: dict[str, Spec]) -> None:
    """pyBModes 1.19.1 on the spar's deck (tests/data/floating/pybmodes_oc3.json; the MAP++
    lines as MoorDyn's, bench/pybmodes_floating.py): surge, heave, roll and pitch within
    1.5 % (measured +0.5 %, 0.0 %, −0.7 %), the first tower pair on the same rigid head
    within 2 % (measured +0.9 %: wtvib's head has its offsets and rotary inertia, and its
    tower the weight's softening, which pyBModes' reading leaves out — on land that puts
    pyBModes 5 % above wtvib, bench/RESULTS.md). pyBModes has no crow's-foot yaw spring:
    its 0.041 Hz yaw is not compared. The third reference of the spar's first fore-aft in
    test_rtest_models.EXCEPTIONS: the platform and tower under a rigid rotor are right."""
    modes = _modes(specs["5MW_OC3Spar_Linear"])
    reference = {m["label"]: m["frequency_hz"] for m in PYBMODES_OC3["modes"] if m["label"]}
    for label in ("surge", "sway", "heave", "roll", "pitch"):
        assert modes[f"platform.{label}"] == pytest.approx(reference[label], rel=0.015), label
    tower_pair = sorted(m["frequency_hz"] for m in PYBMODES_OC3["modes"] if not m["label"])[:2]
    assert [modes["fa1"], modes["ss1"]] == pytest.approx(tower_pair, rel=0.02)


def test_oc3_spar_matches_openfast_linearisation(specs: dict[str, Spec]) -> None:
    """OpenFAST's 5MW_OC3Spar_Linear.1.lin (reference.json): surge, heave and the tower's
    first bending modes within 3 % (its yaw turns with the rotor: module notes)."""
    modes = _modes(specs["5MW_OC3Spar_Linear"])
    assert modes["platform.surge"] == pytest.approx(0.0081362, rel=0.03)
    assert modes["platform.heave"] == pytest.approx(0.0324294, rel=0.03)
    assert modes["fa1"] == pytest.approx(0.4837530, rel=0.03)
    assert modes["ss1"] == pytest.approx(0.4953377, rel=0.03)


def test_oc3_moorings_match_jonkman_2010(decks: Path) -> None:
    """MoorPy on the deck's MAP++ file: Jonkman 2010 Table 5-1 within 1 %."""
    fst = parse(decks / "5MW_OC3Spar_Linear" / "5MW_OC3Spar_Linear.fst")
    k, source = mooring.stiffness(fst, RHO, G)
    assert "MAP++" in source
    published = {(0, 0): 41_180, (0, 4): -2.821e6, (2, 2): 11_940, (3, 3): 311.1e6, (5, 5): 11.56e6}
    for (i, j), value in published.items():
        assert k[i, j] == pytest.approx(value, rel=0.01), (i, j)
    assert k[1, 1] == pytest.approx(k[0, 0], rel=1e-6)


@pytest.mark.parametrize("case", ["5MW_OC4Semi_Linear", "5MW_OC4Semi_MD_Linear"])
def test_oc4_semisubmersible_matches_robertson_2014(
    specs: dict[str, Spec], decks: Path, case: str
) -> None:
    """The platform wtvib builds from the deck — ElastoDyn's mass with HydroDyn's ballast,
    WAMIT's A∞ and hydrostatics, the moorings by MoorPy (MAP++ and MoorDyn alike) — against
    Robertson et al. 2014's published matrices, within 1 %."""
    p = specs[case].tower.foundation.platform
    assert p is not None
    assert p.mass_kg == pytest.approx(1.3473e7, rel=0.01)
    assert p.added_mass[0][0] == pytest.approx(6.490e6, rel=0.01)
    assert p.added_mass[2][2] == pytest.approx(1.470e7, rel=0.01)
    assert p.added_mass[3][3] == pytest.approx(7.210e9, rel=0.01)
    k, _ = mooring.stiffness(parse(decks / case / f"{case}.fst"), RHO, G)
    assert k[0, 0] == pytest.approx(7.08e4, rel=0.01)
    assert k[2, 2] == pytest.approx(1.91e4, rel=0.01)
    assert k[3, 3] == pytest.approx(8.73e7, rel=0.01)
    assert p.stiffness[2][2] - k[2, 2] == pytest.approx(3.836e6, rel=0.01)  # hydrostatic


def test_oc4_semisubmersible_matches_pybmodes(specs: dict[str, Spec]) -> None:
    """pyBModes 1.19.1 on the same MoorDyn deck (tests/data/floating/pybmodes.json): the six
    rigid-body modes within 1.5 % (pyBModes takes the zero-frequency added mass, wtvib each
    mode's own), the tower's first bending pair within 3 % (module notes)."""
    modes = _modes(specs["5MW_OC4Semi_MD_Linear"])
    reference = {m["label"]: m["frequency_hz"] for m in PYBMODES["modes"] if m["label"]}
    assert set(reference) == {"surge", "sway", "heave", "roll", "pitch", "yaw"}
    for label, f in reference.items():
        assert modes[f"platform.{label}"] == pytest.approx(f, rel=0.015), label
    tower_pair = sorted(m["frequency_hz"] for m in PYBMODES["modes"] if not m["label"])[:2]
    assert sorted([modes["fa1"], modes["ss1"]]) == pytest.approx(tower_pair, rel=0.03)


def test_oc4_semisubmersible_matches_openfast_linearisation(specs: dict[str, Spec]) -> None:
    """OpenFAST's 5MW_OC4Semi_Linear.1.lin (reference.json): surge, heave and yaw within 3 %;
    its pitch and roll are not (module notes)."""
    modes = _modes(specs["5MW_OC4Semi_Linear"])
    assert modes["platform.surge"] == pytest.approx(0.0088697525, rel=0.03)
    assert modes["platform.heave"] == pytest.approx(0.0578595687, rel=0.03)
    assert modes["platform.yaw"] == pytest.approx(0.0128334521, rel=0.03)


def test_added_mass_at_each_modes_frequency_matters(specs: dict[str, Spec]) -> None:
    """The semisubmersible's surge added mass at its own 0.009 Hz (WAMIT: 8.7·10⁶ kg) is a
    third above A∞ (6.5·10⁶ kg): with A∞ its surge would be 5 % faster than OpenFAST's and
    pyBModes' (0.00932 Hz); at its own frequency it agrees with both."""
    spec = specs["5MW_OC4Semi_MD_Linear"]
    p = spec.tower.foundation.platform
    assert p is not None and p.added_mass_by_frequency
    at_infinity = p.model_copy(update={"added_mass_by_frequency": []})
    t = spec.tower.model_copy(
        update={"foundation": spec.tower.foundation.model_copy(update={"platform": at_infinity})}
    )
    infinite = _modes(spec.model_copy(update={"tower": t}))["platform.surge"]
    own = _modes(spec)["platform.surge"]
    assert infinite == pytest.approx(own * 1.05, rel=0.01)
    assert abs(own - 0.0088697525) < 0.005 * own < abs(infinite - 0.0088697525)


def test_floating_audit_states_its_model(specs: dict[str, Spec]) -> None:
    """Every floating audit says what the platform model leaves out and the tower's rigid
    head."""
    statements = " ".join(tower._statements(specs["5MW_OC3Spar_Linear"]))
    assert "radiation damping" in statements or "rigid body" in statements
    assert "second bending" in statements


@pytest.mark.parametrize(
    ("case", "fa", "ss"),
    [
        # OpenFAST's linearisations (reference.json): the first pair of tower modes, the
        # fore-aft one below the side-side one and mixed with the blades' flap (its largest
        # DOF a blade's), at 12 rpm
        ("5MW_OC3Spar_Linear", 0.4837530456, 0.495337718),
        ("5MW_OC4Semi_Linear", 0.4199174648, 0.4405829182),
    ],
)
def test_the_coupled_model_stands_on_the_platform(
    specs: dict[str, Spec], case: str, fa: float, ss: float
) -> None:
    """The whole-turbine coupled model on the floating base: its platform's rigid-body
    modes named ``platform.*`` and left to the isolated model (added mass at each mode's own
    frequency), none of them taken for the tower's bending; its first tower pair within
    2.5 % of OpenFAST's, fore-aft below side-side as OpenFAST has it (the isolated tower
    under a rigid rotor puts OC3's the other way round)."""
    from wtvib.subsystems import coupled

    spec = specs[case]
    sw = coupled.rotating_sweep(spec)
    named = {n for n in sw.names if n.startswith("platform.")}
    # yaw where the tower's torsion is modelled (OC3's deck gives its GJ, OC4's does not)
    twists = tower.discretise(spec.tower).gj is not None
    motions = ("surge", "sway", "roll", "pitch") + (("yaw",) if twists else ())
    assert named == {f"platform.{m}" for m in motions}
    found = {m.id: m.frequency_hz for m in coupled.modes(spec)}
    assert not any(i.startswith("system.platform") for i in found)
    assert found["system.tower.fa1"] == pytest.approx(fa, rel=0.025)
    assert found["system.tower.ss1"] == pytest.approx(ss, rel=0.025)
    assert found["system.tower.fa1"] < found["system.tower.ss1"]


def test_the_volturnus_s_deck_s_platform_modes_match_allen_2020(tmp_path: Path) -> None:
    """The IEA-15 on the UMaine VolturnUS-S, read from its OpenFAST deck set
    (IEAWindTask37/IEA-15-240-RWT, OpenFAST/IEA-15-240-RWT-UMaineSemi: WAMIT's added mass
    and hydrostatics, MoorDyn's 685 kg/m chain; tests/data/openfast_decks/iea15_semi.tar.gz)
    against the system's natural frequencies of Allen et al. 2020 (NREL/TP-5000-76773,
    "Definition of the UMaine VolturnUS-S Reference Platform", Table 8: surge 0.007, heave
    0.049, pitch 0.036, yaw 0.011 Hz): within 10 % (measured +6 %, −0.2 %, −3 %, +3 %).
    The windIO description of the same platform (the windio package's
    IEA-15-240-RWT_VolturnUS-S.yaml: circular Ø9.6 m pontoons, Ca = 1, strip theory) cannot
    give the heave of WAMIT's flat pontoons — 0.064 Hz in wtvib and in NREL's RAFT on it
    alike (test_windio_floating.py) — nor, its chain's 0.185 m read as the schema defines it
    (volume-equivalent, 211 kg/m), the published surge: the deck is the reference."""
    with tarfile.open(DATA / "openfast_decks" / "iea15_semi.tar.gz") as tar:
        tar.extractall(tmp_path, filter="data")
    deck = tmp_path / "OpenFAST/IEA-15-240-RWT-UMaineSemi/IEA-15-240-RWT-UMaineSemi.fst"
    modes = _modes(importers.load(deck))
    published = {"surge": 0.007, "heave": 0.049, "pitch": 0.036, "yaw": 0.011}
    for motion, f in published.items():
        assert modes[f"platform.{motion}"] == pytest.approx(f, rel=0.10), motion


def test_a_mode_that_bends_the_tower_as_its_first_bending_is_not_its_second(tmp_path: Path) -> None:
    """The IEA-15 on its VolturnUS-S has three modes near 0.5 Hz in which the tower bends
    fore-aft in its first shape, mixed with the blades' first flap collective and cyclic
    (tilt) modes (the rotor nods on a tower as soft as the blades). The third, 45 % tower,
    was named by its largest share the "2nd tower fore-aft" (0.61 Hz), where the tower's own
    second bending is at 2.5 Hz: a tower ordinal now counts bending shapes (the MAC of the
    curvatures), and the mode is named by its next share, the flap cyclic (tilt) mode the
    family lacked. The second fore-aft bending keeps its name and its frequency."""
    from wtvib.subsystems import coupled

    with tarfile.open(DATA / "openfast_decks" / "iea15_semi.tar.gz") as tar:
        tar.extractall(tmp_path, filter="data")
    deck = tmp_path / "OpenFAST/IEA-15-240-RWT-UMaineSemi/IEA-15-240-RWT-UMaineSemi.fst"
    spec = importers.load(deck)
    parked = coupled.parked_named(coupled.build(spec, spec.coupled.rotating_condition))
    f = dict(zip(parked.names, parked.frequency_hz, strict=True))
    assert f["tower.fa2"] > 2.0 and f["tower.ss2"] > 2.0  # the tower's second bending
    assert 0.55 < f["blade.flap1.cyclic_tilt"] < 0.65  # the third of the family, 45 % tower
    assert f["tower.fa1"] < 0.5
    text = dict(zip(parked.names, parked.descriptions, strict=True))["blade.flap1.cyclic_tilt"]
    assert "45% tower fore-aft (named by its second share)" in text
