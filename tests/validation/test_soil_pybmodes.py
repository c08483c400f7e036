"""The monopile on soil, side by side with pyBModes.

Reference: pyBModes 1.19.1 run once on the same input (``bench/pybmodes_soil.py`` →
``tests/data/soil/pybmodes.json``): the OC3 monopile deck set of OpenFAST's regression tests
(the SubDyn pile under the ElastoDyn tower, tests/data/openfast_decks/rtest.tar.gz), its
tower top the tip mass pyBModes derives from the deck, on pyBModes' mudline coupled
springs for a 36 m embedded pile (6 m × 60 mm, E 210 GPa) in homogeneous soil of E_s 20,
50 and 100 MPa: the Shadlou & Bhattacharya (2016) closed forms, and Psaroudakis et al.
(2021) — a Winkler pile of line stiffness D·E_s, which is wtvib's soil model (the pile's
finite elements on distributed springs, condensed to the mudline) with E_py = D·E_s.

Shadlou's closed forms are compared for all three soil profiles (homogeneous, parabolic,
linear) and both pile behaviours as well (``shadlou_closed_forms`` in the same file).

Where the models are the same, they agree to the digits printed: the stiffnesses exactly,
the first and second tower frequencies within 0.2 %. Where they differ, pyBModes' own two
paths show it: its clamped cantilever (``hub_conn = 1``) gives 0.2905 Hz, 3 % above its
soft-monopile path with springs a thousand times stiffer than any soil (0.2818 Hz) — which
is the value wtvib's clamped base gives (0.2821 Hz). pyBModes' soft-monopile beam carries
no axial load: wtvib's tower is compared without gravity (with it, its first modes are
2 % lower).
"""

import json
import tarfile
from pathlib import Path

import pytest

from wtvib import importers
from wtvib.spec.tower import Foundation, Pile, SoilLayer, TowerHead
from wtvib.subsystems import soil, tower

DATA = Path(__file__).resolve().parents[1] / "data"
REF = json.loads((DATA / "soil" / "pybmodes.json").read_text())
PILE = Pile(
    embedded_length_m=REF["pile"]["embedded_m"],
    diameter_m=REF["pile"]["diameter_m"],
    wall_thickness_m=REF["pile"]["wall_thickness_m"],
    youngs_modulus_pa=REF["pile"]["E_pa"],
)


@pytest.fixture(scope="module")
def oc3(tmp_path_factory: pytest.TempPathFactory):  # type: ignore[no-untyped-def]
    root = tmp_path_factory.mktemp("oc3")
    with tarfile.open(DATA / "openfast_decks" / "rtest.tar.gz") as tar:
        tar.extractall(root, filter="data")
    return importers.load(root / "glue-codes/openfast/5MW_OC3Mnpl_Linear/5MW_OC3Mnpl_Linear.fst")


def _modes(spec, foundation: Foundation) -> list[float]:  # type: ignore[no-untyped-def]
    """First and second fore-aft and side-side frequencies of the tower on its pile, the
    tower top pyBModes' tip mass, without gravity (module notes)."""
    tip = REF["tip_mass"]
    head = TowerHead(
        mass_kg=tip["mass"],
        cm_above_top_m=tip["cm_axial"],
        inertia_pitch_kgm2=tip["iyy"],
        inertia_roll_kgm2=tip["ixx"],
        inertia_yaw_kgm2=tip["izz"],
    )
    t = spec.tower.model_copy(update={"foundation": foundation})
    fa, ss = tower.bending_pair(
        tower.discretise(t), head, t.point_masses, t.foundation, gravity=False, count=2
    )
    return sorted([*fa.frequency_hz[:2], *ss.frequency_hz[:2]])


def _winkler(soil_e: float) -> Foundation:
    """wtvib's own soil model: the embedded pile on E_py = D·E_s (Psaroudakis' Winkler)."""
    layer = SoilLayer(bottom_m=PILE.embedded_length_m, kind="modulus",
                      modulus_pa=PILE.diameter_m * soil_e)  # fmt: skip
    return Foundation(kind="soil", pile=PILE, soil=[layer])


@pytest.mark.parametrize("case", REF["cases"], ids=lambda c: f"{c['formula']}-{c['soil_E_pa']:g}")
def test_mudline_stiffness_is_pybmodes(case):
    """Shadlou's closed forms (wtvib.subsystems.soil.shadlou) give pyBModes' K_hh, K_hr, K_rr to
    1e-9; wtvib's finite-element Winkler pile, condensed to the mudline, gives the
    Psaroudakis closed form pyBModes evaluates for the same line stiffness to 1e-4."""
    if case["formula"] == "shadlou":
        k = soil.shadlou(PILE, case["soil_E_pa"], "homogeneous", case["behaviour"])
        tol = 1e-9
    else:
        k = soil.head_stiffness(PILE, _winkler(case["soil_E_pa"]).soil)
        tol = 1e-4
    assert k.lateral == pytest.approx(case["K_hh"], rel=tol)
    assert k.coupling == pytest.approx(case["K_hr"], rel=tol)
    assert k.rocking == pytest.approx(case["K_rr"], rel=tol)


@pytest.mark.parametrize("case", REF["cases"], ids=lambda c: f"{c['formula']}-{c['soil_E_pa']:g}")
def test_tower_on_the_pile_on_its_springs_is_pybmodes(oc3, case):
    """The four lowest tower frequencies on the mudline springs within 0.2 % of pyBModes'
    (measured ≤ 0.13 %): the soil lowers the first pair by 9–17 %, and both tools by the
    same amount."""
    if case["formula"] == "shadlou":
        k = soil.shadlou(PILE, case["soil_E_pa"], "homogeneous", case["behaviour"])
        found = Foundation(kind="springs", lateral_n_m=k.lateral, rocking_nm_rad=k.rocking,
                           coupling_n=k.coupling)  # fmt: skip
    else:
        found = _winkler(case["soil_E_pa"])
    ours = _modes(oc3, found)
    assert ours == pytest.approx(case["frequencies_hz"], rel=2e-3)


def test_the_clamped_base_is_pybmodes_stiff_spring_limit(oc3):
    """Clamped, wtvib gives what pyBModes' soft-monopile path gives on springs a thousand
    times stiffer than soil (0.2818, 0.2822, 2.203, 2.276 Hz), not its hub_conn = 1
    cantilever (0.2905 Hz, module notes)."""
    ours = _modes(oc3, Foundation(kind="clamped"))
    assert ours == pytest.approx(REF["stiff_springs"], rel=2e-3)
    assert REF["clamped_hub_conn_1"][0] > 1.02 * REF["stiff_springs"][0]


@pytest.mark.parametrize(
    "case", REF["shadlou_closed_forms"], ids=lambda c: f"{c['behaviour']}-{c['profile']}"
)
def test_shadlous_closed_forms_for_every_profile_are_pybmodes(case):
    """Shadlou & Bhattacharya (2016) for the homogeneous, parabolic and linear soil profiles
    and flexible and rigid piles (their coefficient table, Yu & Amdahl 2023 Table 1): wtvib's
    K_L, K_LR, K_R are pyBModes' for the same pile and soil (the OC3 pile as flexible, a
    24 m one as rigid, E_s 50 MPa at one diameter's depth), to 1e-9 — every coefficient of
    the table is in play."""
    pile = PILE.model_copy(update={"embedded_length_m": case["embedded_m"]})
    k = soil.shadlou(pile, case["soil_E_pa"], case["profile"], case["behaviour"])
    assert (k.lateral, k.coupling, k.rocking) == pytest.approx(
        (case["K_hh"], case["K_hr"], case["K_rr"]), rel=1e-9
    )
