"""ElastoDyn's mode-shape polynomials against the decks' own, pyBModes' and the
written files.

References, each on the same input:

* **The NREL 5-MW's own coefficients** (../shared/reference/NREL5MW: the onshore tower and
  blade files). NREL computed them with BModes from the same distributed properties and
  the rotor-nacelle assembly (Jonkman et al. 2009, NREL/TP-500-38060, §§ 2 and 6).
* **pyBModes 1.19.1**, run once on the NREL 5-MW, IEA-3.4 and IEA-10 decks
  (``bench/pybmodes_shapes.py`` → tests/data/polynomials/pybmodes.json): its tower-top
  mass, its tower's frequencies and coefficients (clamped, ``hub_conn = 1``, and on its
  soft-monopile path on springs a thousand times stiffer than any soil), its rotating
  blade's frequencies and coefficients at the deck's RotSpeed.
* **ElastoDyn itself** (OpenFAST ``modules/elastodyn/src/ElastoDyn.f90``): its tower-top
  mass ``TwrTpMass = RotMass + … + NacMass + YawBrMass``, the third reference where
  pyBModes and wtvib differ.

What the comparison shows: wtvib's finite elements give pyBModes' tower frequencies to
0.3 % where both carry the same tower-top mass, and pyBModes' shapes to MAC 0.9999 for the
first modes. They differ in three things, each shown by a third reference: pyBModes leaves
out ElastoDyn's yaw-bearing mass (IEA-10: 93 t of 867 t; ElastoDyn counts it); its
clamped path carries the head's height above the tower top as a sideways lever arm, which
stiffens the first pair by 3 % over its own soft-monopile path, whose frequencies are
wtvib's; and its blade polynomials are least-squares fits of the out-of-plane deflection,
which on a twisted blade are not ElastoDyn's shape — NREL's own BModes polynomial for the
5-MW's second flap mode implies within 0.1 % of wtvib's Rayleigh–Ritz one, pyBModes' 5.5 %
above.
"""

import json
import shutil
from pathlib import Path

import numpy as np
import pytest

from wtvib import importers
from wtvib.importers import elastodyn
from wtvib.spec.tower import TowerHead
from wtvib.subsystems import polynomials, tower
from wtvib.subsystems.polynomials import Polynomial, mac

DATA = Path(__file__).resolve().parents[1] / "data" / "polynomials"
PYB = json.loads((DATA / "pybmodes.json").read_text())["decks"]
NREL = "NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"
DECKS = {
    "NREL5MW": NREL,
    "IEA3.4": "IEA3.4/IEA-3.4-130-RWT_ElastoDyn.dat",
    "IEA10": "IEA10/IEA-10.0-198-RWT_ElastoDyn.dat",
    "IEA15": "IEA15/IEA-15-240-RWT-Monopile/IEA-15-240-RWT-Monopile_ElastoDyn.dat",
}
X = np.linspace(0.0, 1.0, 101)


@pytest.fixture(scope="module")
def loaded(shared: Path) -> dict[str, object]:
    return {name: importers.load(shared / "reference" / rel) for name, rel in DECKS.items()}


@pytest.fixture(scope="module")
def shapes(loaded) -> dict[str, polynomials.Shapes]:  # type: ignore[no-untyped-def]
    return {name: polynomials.compute(spec) for name, spec in loaded.items()}  # type: ignore[arg-type]


def _rows(result: polynomials.Shapes) -> dict[str, polynomials.Row]:
    return {r.key: r for r in (*result.tower, *result.blade)}


def test_the_nrel_5mw_decks_bmodes_shapes_are_its_modes(shapes):
    """NREL's BModes coefficients against wtvib's computed shapes of the same deck: first
    modes MAC ≥ 0.995 (the issue's bar; measured ≥ 0.9999), second ≥ 0.95 (measured
    ≥ 0.999); the blade's implied frequencies within 0.1 % of wtvib's Rayleigh–Ritz
    polynomials' (measured ≤ 0.01 %) — BModes and wtvib find the same polynomial."""
    rows = _rows(shapes["NREL5MW"])
    for key, row in rows.items():
        floor = 0.95 if "2" in key[-3:] else 0.995
        assert row.mac_deck is not None and row.mac_deck >= floor, key
    for key in ("BldFl1Sh", "BldFl2Sh", "BldEdgSh"):
        assert rows[key].deck_hz == pytest.approx(rows[key].computed_hz, rel=1e-3), key


def test_the_nrel_5mw_towers_first_fore_aft_polynomial_is_stiff_and_said_so(shapes, loaded):
    """The deck's TwFAM1Sh is the mode's shape (MAC 0.9999) but implies 3.3 % above the
    computed one: the check warns naming it, its file and line — and only it. (OpenFAST's
    own first fore-aft of this deck is 1.4 % above ADAMS' full finite elements, Jonkman et
    al. 2009 Table 9-1: 0.3240 against 0.3195 Hz; the side-side 1.4 % below, 0.3120 against
    0.3164, where the polynomial is within 1 %.)"""
    rows = _rows(shapes["NREL5MW"])
    assert rows["TwFAM1Sh"].stiffer == pytest.approx(0.033, abs=0.005)
    checks = {c.id: c for c in polynomials.checks(shapes["NREL5MW"])}
    tower_check = checks["polynomials.tower"]
    assert tower_check.status == "warn"
    assert "TwFAM1Sh (NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat:32)" in tower_check.message
    assert all(k not in tower_check.message for k in ("TwFAM2Sh", "TwSSM1Sh", "TwSSM2Sh"))
    assert checks["polynomials.blade"].status == "pass"


def test_the_tower_head_is_elastodyns_tower_top_mass(loaded, shared):
    """ElastoDyn's TwrTpMass = NacMass + YawBrMass + HubMass + NumBl·∫BMassDen·AdjBlMs (no tip
    brakes, furl or tail here; ElastoDyn.f90, ``p%TwrTpMass``): on the IEA-10 deck, whose
    93 457 kg yaw bearing pyBModes leaves out (its tip mass 773 928 kg)."""
    ed = elastodyn.parse(shared / "reference" / DECKS["IEA10"])
    blade = elastodyn.parse(shared / "reference" / "IEA10" / "IEA-10.0-198-RWT_ElastoDyn_blade.dat")
    length = ed.num("TipRad") - ed.num("HubRad")
    span = blade.column("BlFract", "BlFract") * length
    rot = ed.num("NumBl") * float(np.trapezoid(blade.column("BlFract", "BMassDen"), span))
    rot *= blade.num("AdjBlMs")
    twr_tp = ed.num("NacMass") + ed.num("YawBrMass") + ed.num("HubMass") + rot
    head = tower.bending_head(loaded["IEA10"])
    assert head is not None and head.mass_kg == pytest.approx(twr_tp, rel=1e-6)  # 7 digits
    assert PYB["IEA10"]["tip_mass"]["mass"] == pytest.approx(twr_tp - ed.num("YawBrMass"), rel=1e-6)


@pytest.mark.parametrize("tip_brake", [0.0, 1500.0])
def test_the_shape_head_is_the_parts_elastodyn_lumps(shared, tmp_path, tip_brake):
    """The NREL 5-MW's tower head for its shapes, assembled here from the deck's own keys:
    the nacelle a point mass at (NacCMxn, NacCMzn) in pitch and roll (ElastoDyn gives it
    NacYIner alone), hub, blades (∫ BMassDen·AdjBlMs) and tip brakes (TipMass, here 0 and
    1.5 t each) at the apex (OverHang, Twr2Shft, ShftTilt; HubCM 0),
    the hub's HubIner about the shaft in roll, the blades' rotational inertia left out —
    mass and centre to 5e-6 (the importer writes the head's values to six significant
    digits: half a unit of the sixth), the pitch and roll inertias about the centre to 100
    kg·m² (the rotor's share is taken off the head's 22.9e6 and 38.6e6, written to ±50)."""
    import math

    from tests.conftest import edited_reference

    folder = edited_reference(
        shared, tmp_path, "NREL5MW", Path(NREL).name,
        "          0   TipMass(1)", f"{tip_brake:11g}   TipMass(1)",
    )  # fmt: skip
    for i in (2, 3):
        path = folder / Path(NREL).name
        path.write_text(
            path.read_text().replace(
                f"          0   TipMass({i})", f"{tip_brake:11g}   TipMass({i})"
            )
        )
    ed = elastodyn.parse(folder / Path(NREL).name)
    tilt = math.radians(ed.num("ShftTilt"))
    apex = (
        ed.num("OverHang") * math.cos(tilt),
        ed.num("Twr2Shft") + ed.num("OverHang") * math.sin(tilt),  # ShftTilt −5°: apex up
    )
    blade = elastodyn.parse(shared / "reference/NREL5MW/NRELOffshrBsline5MW_Blade.dat")
    span = blade.column("BlFract", "BlFract") * (ed.num("TipRad") - ed.num("HubRad"))
    per_blade = float(np.trapezoid(blade.column("BlFract", "BMassDen"), span))
    rotor = ed.num("HubMass") + 3 * (per_blade * blade.num("AdjBlMs") + tip_brake)
    parts = [(ed.num("NacMass"), ed.num("NacCMxn"), ed.num("NacCMzn")), (rotor, *apex)]
    mass = sum(m for m, _, _ in parts)
    x = sum(m * px for m, px, _ in parts) / mass
    z = sum(m * pz for m, _, pz in parts) / mass
    pitch = sum(m * ((px - x) ** 2 + (pz - z) ** 2) for m, px, pz in parts)
    roll = ed.num("HubIner") + sum(m * (pz - z) ** 2 for m, _, pz in parts)
    head = tower.bending_head(importers.load(folder / Path(NREL).name))
    assert head is not None
    assert (head.mass_kg, head.cm_downwind_m, head.cm_above_top_m) == pytest.approx(
        (mass, x, z), rel=5e-6
    )
    assert head.inertia_pitch_kgm2 == pytest.approx(pitch, abs=100)
    assert head.inertia_roll_kgm2 == pytest.approx(roll, abs=100)


def test_a_monopile_towers_shapes_start_at_its_base(tmp_path):
    """The OC3 monopile (r-test 5MW_OC3Mnpl_Linear): SubDyn's pile from the seabed below the
    ElastoDyn tower, whose polynomials run from TowerBsHt (10 m) to the top — NREL's, for
    that tower on that pile (BModes' monopile support), are wtvib's to MAC 0.9999 and implied
    frequency 0.1 % for the first pair (measured 0.999999, 0.003 %): the root offset, the
    pile's motion taken off and the flexible length right."""
    import tarfile

    with tarfile.open(DATA.parent / "openfast_decks" / "rtest.tar.gz") as tar:
        tar.extractall(tmp_path, filter="data")
    spec = importers.load(
        tmp_path / "glue-codes/openfast/5MW_OC3Mnpl_Linear/5MW_OC3Mnpl_Linear.fst"
    )
    assert spec.tower.polynomial_base_m == pytest.approx(
        30.0, abs=1e-3
    )  # 10 m above MSL, seabed −20 m
    rows = _rows(polynomials.compute(spec))
    for key in ("TwFAM1Sh", "TwSSM1Sh"):
        assert rows[key].mac_deck is not None and rows[key].mac_deck >= 0.9999, key
        assert rows[key].stiffer is not None and abs(rows[key].stiffer) <= 1e-3, key


def test_the_polynomial_familys_limit_is_said(shapes):
    """A blade whose best polynomial is more than 1 % from its finite-element frequency is
    said so, with the gap (the IEA-3.4's second flap: −2.8 %), not warned as the deck's
    fault: its own BldFl2Sh passes."""
    said = [s for s in shapes["IEA3.4"].statements if s.startswith("BldFl2Sh: no polynomial")]
    assert len(said) == 1 and "closer than -2.8%" in said[0], said
    assert _rows(shapes["IEA3.4"])["BldFl2Sh"].status() == "pass"
    assert not any(s.startswith("Tw") for s in shapes["IEA3.4"].statements)


def _pyb_head(name: str) -> TowerHead:
    tip = PYB[name]["tip_mass"]
    return TowerHead(
        mass_kg=tip["mass"],
        cm_above_top_m=tip["cm_axial"],
        inertia_pitch_kgm2=tip["iyy"],  # about the lateral axis (fore-aft rotation)
        inertia_roll_kgm2=tip["ixx"],
        inertia_yaw_kgm2=tip["izz"],
    )


@pytest.mark.parametrize("name", ["NREL5MW", "IEA3.4", "IEA10"])
def test_tower_frequencies_are_pybmodes_on_its_own_head(loaded, name):
    """With pyBModes' tip mass and without gravity (pyBModes' tower carries no axial
    load), wtvib's four lowest tower frequencies are pyBModes' soft-monopile ones on stiff
    springs within 0.5 % (measured ≤ 0.3 %: its elements are the deck's 10–11 stations,
    wtvib's 40); its clamped path's first pair is above both, by as much as the head's
    height above the tower top makes (module notes; NREL 5-MW 3 %, IEA-3.4 1 %)."""
    spec = loaded[name]
    t = spec.tower  # type: ignore[attr-defined]
    fa, ss = tower.bending_pair(
        tower.discretise(t, polynomials.ELEMENTS), _pyb_head(name), t.point_masses,
        t.foundation, gravity=False, count=2,
    )  # fmt: skip
    ours = sorted([*fa.frequency_hz[:2], *ss.frequency_hz[:2]])
    assert ours == pytest.approx(PYB[name]["tower_lowest_hz_stiff_springs"], rel=5e-3)
    assert PYB[name]["tower_lowest_hz_clamped"][0] > 1.005 * ours[0]


@pytest.mark.parametrize("name", ["NREL5MW", "IEA3.4", "IEA10"])
def test_tower_and_blade_shapes_are_pybmodes(shapes, name):
    """wtvib's computed polynomials against pyBModes' for the same deck: the first tower
    modes and the first flap and edge modes MAC ≥ 0.9995 (measured ≥ 0.99987), the
    second modes ≥ 0.98 (measured ≥ 0.9827: pyBModes' second tower modes carry its clamped
    path's lever arm, and its second flap a least-squares fit, module notes)."""
    rows = _rows(shapes[name])
    for key, coefficients in {**PYB[name]["tower"], **PYB[name]["blade"]}.items():
        theirs = Polynomial(tuple(coefficients))  # type: ignore[arg-type]
        floor = 0.98 if "2" in key[-3:] else 0.9995
        got = mac(rows[key].computed.polynomial.value(X), theirs.value(X))
        assert got >= floor, (key, got)


@pytest.mark.parametrize("name", ["NREL5MW", "IEA3.4", "IEA10"])
def test_blade_frequencies_are_pybmodes(shapes, name):
    """The rotating blade at the deck's RotSpeed (both tools): first flap, first edge and
    second flap within 0.5 % of pyBModes' on the blade table interpolated onto 241
    stations (measured ≤ 0.4 %). On the deck's own 30 stations pyBModes' second flap is
    up to 1 % lower (its elements are the stations, their properties sampled at the
    midpoints) and moves toward wtvib's as its mesh is refined; wtvib's, whose elements
    interpolate the table as ElastoDyn does, moves by less than 1e-5 from 20 to 160
    elements."""
    rows = _rows(shapes[name])
    ours = sorted(rows[k].frequency_hz for k in ("BldFl1Sh", "BldEdgSh", "BldFl2Sh"))
    assert shapes[name].rpm == pytest.approx(PYB[name]["blade_rpm"])
    fine, coarse = PYB[name]["blade_lowest_hz_241_stations"][:3], PYB[name]["blade_lowest_hz"][:3]
    assert ours == pytest.approx(fine, rel=5e-3)
    if abs(fine[2] / coarse[2] - 1) > 1e-3:  # the mesh matters (IEA-3.4, IEA-10)
        assert abs(ours[2] - fine[2]) < abs(ours[2] - coarse[2])


def test_pybmodes_second_flap_fit_is_not_elastodyns_shape(shapes, loaded):
    """On the twisted NREL 5-MW blade, pyBModes' BldFl2Sh (a least-squares fit of the
    out-of-plane deflection) implies a frequency 5.5 % above the Rayleigh–Ritz polynomial's
    on ElastoDyn's own shape family, where NREL's BModes coefficients are within 0.1 % of
    it (the doubtful reference, shown so by a third)."""
    judged = polynomials.models(loaded["NREL5MW"])  # type: ignore[arg-type]
    rows = _rows(shapes["NREL5MW"])
    theirs = Polynomial(tuple(PYB["NREL5MW"]["blade"]["BldFl2Sh"]))  # type: ignore[arg-type]
    assert judged["BldFl2Sh"].implied(theirs) / rows["BldFl2Sh"].computed_hz - 1 == (
        pytest.approx(0.055, abs=0.01)
    )
    assert rows["BldFl2Sh"].deck_hz == pytest.approx(rows["BldFl2Sh"].computed_hz, rel=1e-3)


@pytest.mark.parametrize("name", list(DECKS))
def test_written_polynomials_imply_the_finite_element_frequencies(shared, tmp_path, name):
    """``wtvib shapes`` writes the deck's tower and blade files with the computed
    coefficients; read back, the deck audits clean, and each written polynomial implies
    the frequency of the computed one (to the nine written digits: 1e-6) — for the tower
    within 1 % of the finite element's (measured ≤ 0.3 %), for the blade what no
    polynomial of ElastoDyn's family undercuts (:func:`polynomials.twisted_fit`; measured
    within 1.6 % on these four blades, the second flap of the IEA-3.4 −2.8 %: its flap and
    edge bending couple, said in the output)."""
    from typer.testing import CliRunner

    from wtvib.cli import app

    folder = tmp_path / "deck"
    top = Path(DECKS[name]).parts[0]  # the IEA-15's tower and blade files are in two folders
    shutil.copytree(shared / "reference" / top, folder)
    deck = folder.joinpath(*Path(DECKS[name]).parts[1:])
    before = polynomials.compute(importers.load(deck))
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["shapes", str(deck), "-o", str(out), "--no-plots"])
    assert result.exit_code == 0, result.output
    for written in out.iterdir():  # the corrected files over the originals' copies
        (original,) = folder.rglob(written.name)
        shutil.copy(written, original)
    after = polynomials.compute(importers.load(deck))
    old, new = _rows(before), _rows(after)
    assert set(new) == set(old)
    for key, row in new.items():
        assert row.deck_hz == pytest.approx(old[key].computed_hz, rel=1e-6), key
        assert row.status() == "pass", (key, row.diagnosis())
        if key.startswith("Tw"):
            assert row.deck_hz == pytest.approx(row.frequency_hz, rel=0.01), key
    for c in polynomials.checks(after):
        assert c.status == "pass", c.message


def test_a_swapped_tower_shape_is_flagged_as_the_other_mode(shared, tmp_path):
    """TwFAM1Sh and TwFAM2Sh exchanged in the NREL 5-MW tower file: each is named as the
    shape of the other mode of its plane, with its file and line."""
    from tests.conftest import edited_reference

    text = (
        shared / "reference" / "NREL5MW" / "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat"
    ).read_text()
    lines = text.splitlines(keepends=True)
    first = [i for i, ln in enumerate(lines) if "TwFAM1Sh(" in ln]
    second = [i for i, ln in enumerate(lines) if "TwFAM2Sh(" in ln]
    swapped = lines[:]
    for i, j in zip(first, second, strict=True):
        swapped[i] = lines[j].replace("TwFAM2Sh", "TwFAM1Sh")
        swapped[j] = lines[i].replace("TwFAM1Sh", "TwFAM2Sh")
    folder = edited_reference(
        shared, tmp_path, "NREL5MW", "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat",
        text, "".join(swapped),
    )  # fmt: skip
    result = polynomials.compute(importers.load(folder / Path(NREL).name))
    check = next(c for c in polynomials.checks(result) if c.id == "polynomials.tower")
    assert check.status == "warn"
    for key, line in (("TwFAM1Sh", first[0] + 1), ("TwFAM2Sh", second[0] + 1)):
        where = f"{key} (NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat:{line})"
        assert f"{where} is the shape of the other mode" in check.message


def test_a_shape_for_another_tower_is_flagged_and_another_head_mass_barely_matters(
    shared, tmp_path
):
    """The NREL 5-MW tower softened to 30 % above mid-height: BModes' polynomials of the
    real tower are stale — the first fore-aft and side-side warn, MAC below 0.995 and
    implied frequencies 5 % and more above the computed shapes' (measured 0.988 and
    0.987, +14 % and +9 %).
    A head twice as heavy (NacMass 240 → 480 t) does not make them so: the shape of a
    first mode moves little with the mass on its tip and its Rayleigh quotient less
    (measured: MAC 0.9999, the same +3.3 % as on the real head)."""
    folder = tmp_path / "NREL5MW"
    shutil.copytree(shared / "reference" / "NREL5MW", folder)
    path = folder / "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat"
    out = []
    for line in path.read_text().splitlines(keepends=True):
        cells = line.split()
        if len(cells) == 4 and cells[0][0].isdigit() and float(cells[0]) >= 0.5:
            fa, ss = (0.3 * float(c) for c in cells[2:])
            line = f"{cells[0]}  {cells[1]}  {fa:.7E}  {ss:.7E}\n"
        out.append(line)
    path.write_text("".join(out))
    rows = _rows(polynomials.compute(importers.load(folder / Path(NREL).name)))
    for key in ("TwFAM1Sh", "TwSSM1Sh"):
        assert rows[key].status() == "warn", key
        assert rows[key].mac_deck is not None and rows[key].mac_deck < 0.995, key
        assert rows[key].stiffer is not None and rows[key].stiffer > 0.05, key

    from tests.conftest import edited_reference

    heavy = edited_reference(
        shared, tmp_path / "heavy", "NREL5MW", "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat",
        "     240000   NacMass", "     480000   NacMass",
    )  # fmt: skip
    rows = _rows(polynomials.compute(importers.load(heavy / Path(NREL).name)))
    assert rows["TwFAM1Sh"].mac_deck is not None and rows["TwFAM1Sh"].mac_deck > 0.999
    assert rows["TwFAM1Sh"].stiffer == pytest.approx(0.033, abs=0.005)


def test_a_floating_towers_shapes_are_computed_on_its_platform(tmp_path):
    """BModes' tower-on-support: the OC3-Hywind deck's polynomials, which NREL computed with
    BModes for the tower on its floating platform (BModes' OC3Hywind.bmi sample: the
    platform's inertia, hydrostatic and mooring stiffness of Jonkman 2010, NREL/TP-500-47535
    — NREL forum, forums.nrel.gov/t/604),
    against wtvib's on the deck's platform (its rigid motion taken off before the fit):
    all four MAC ≥ 0.999 and implied within 1 % of the computed shapes' (measured ≥ 0.9994,
    ≤ 0.8 %). The second modes are the platform's: clamped at the tower base instead, their
    MAC against the deck's drops (measured 0.9999 → 0.9967 fore-aft, 0.9994 → 0.9953
    side-side)."""
    import tarfile

    from wtvib.spec.tower import Foundation

    with tarfile.open(DATA.parent / "openfast_decks" / "rtest_floating.tar.gz") as tar:
        tar.extractall(tmp_path, filter="data")
    with tarfile.open(DATA.parent / "openfast_decks" / "rtest.tar.gz") as tar:
        tar.extractall(tmp_path, filter="data")
    spec = importers.load(
        tmp_path / "glue-codes/openfast/5MW_OC3Spar_Linear/5MW_OC3Spar_Linear.fst"
    )
    assert spec.tower.foundation.kind == "platform"
    floating = _rows(polynomials.compute(spec))
    for key in ("TwFAM1Sh", "TwFAM2Sh", "TwSSM1Sh", "TwSSM2Sh"):
        row = floating[key]
        assert row.mac_deck is not None and row.mac_deck >= 0.999, key
        assert row.stiffer is not None and abs(row.stiffer) <= 0.01, key
    clamped = _rows(
        polynomials.compute(
            spec.model_copy(
                update={"tower": spec.tower.model_copy(update={"foundation": Foundation()})}
            )
        )
    )
    for key in ("TwFAM2Sh", "TwSSM2Sh"):
        assert clamped[key].mac_deck < floating[key].mac_deck - 2e-3, key  # type: ignore[operator]
