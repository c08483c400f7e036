"""Format detection and the import options' one rule each."""

from pathlib import Path

import pytest

from wtvib import importers
from wtvib.errors import SpecError


@pytest.mark.parametrize(
    ("name", "text", "kind"),
    [
        ("t.yaml", "wtvib: 1\nturbine: {name: x}\n", "wtvib"),
        ("t.yaml", "windIO_version: 2.0\ncomponents: {}\nassembly: {}\n", "windio"),
        ("t.dat", '3 NumBl - blades\n"tower.dat" TwrFile - file\n', "elastodyn"),
        ("t.fst", '"ed.dat"  EDFile - ElastoDyn\n', "elastodyn"),
    ],
)
def test_formats_are_detected_by_content(name, text, kind):
    assert importers.detect(Path(name), text) == kind


def test_anything_else_names_the_formats_accepted():
    with pytest.raises(SpecError, match="not a format wtvib reads"):
        importers.detect(Path("t.txt"), "hello\n")


def test_head_mass_is_for_windio_files_only(tmp_path):
    p = tmp_path / "t.yaml"
    p.write_text("wtvib: 1\n")
    with pytest.raises(SpecError, match="--head-mass applies to windIO files only"):
        importers.load(p, importers.ReadOptions(head_mass=1000.0))


def test_the_headline_says_where_imported_speeds_come_from(shared):
    """windIO 1.x speeds: the IEA-3.4 1.x file's torque block gives no limits (VS_minspd 0,
    VS_maxspd 2 rad/s) but its tip-speed ratio, cut-in and tip-speed limit: the rotor runs
    3.53–11.75 rpm as WISDEM runs it (windio._Reader._torque_speeds) — its OpenFAST deck's
    controller 3.539–11.63 rpm (VS_MinOMSpd, VS_RefSpd), its HAWC2 model's 3.77–11.75
    (the DTU controller's constants 2 and 3; IEAWindTask37/IEA-3.4-130-RWT) — where its
    supervisory block's minOmega/maxOmega, the NREL 5-MW's 6.9–12.1 rpm, were taken
    before (and are said, not used). The report says where the range comes from
    (operation.source, the headline's Speed row); a range given on the command line says
    so instead."""
    from wtvib import audit
    from wtvib.importers import ReadOptions, load

    path = shared / "reference/IEA3.4/IEA-3.4-130-RWT.yaml"
    spec = load(path, ReadOptions(head_mass=1.5e5))
    assert spec.rotor.speed.min_rpm == pytest.approx(3.539, rel=0.01)
    assert spec.rotor.speed.max_rpm == pytest.approx(11.75, rel=0.01)
    assert any("6.9–12.1 rpm: not used" in a for a in spec.assumptions)
    doc = audit.run(spec).to_dict()
    assert "control.supervisory" in doc["operation"]["source"]
    assert "IEA-3.4-130-RWT.yaml" in doc["operation"]["source"]
    doc = audit.run(load(path, ReadOptions(head_mass=1.5e5, rpm=(3.8, 11.75)))).to_dict()
    assert doc["operation"]["source"] == "the command line (--rpm/--rated)"


def test_a_deck_on_a_platform_says_its_tower_is_clamped_at_its_base(shared):
    """The IEA-15 monopile deck enables ElastoDyn's platform degrees of freedom (SubDyn
    holds the pile, which wtvib does not read): its tower, clamped at TowerBsHt, has a first
    bending of 0.23 Hz where tower and monopile have 0.17–0.18 (Gaertner et al. 2020) — the
    headline says the frequencies are upper bounds; it said so in an assumption only."""
    deck = "reference/IEA15/IEA-15-240-RWT-Monopile/IEA-15-240-RWT-Monopile_ElastoDyn.dat"
    spec = importers.load(shared / deck, importers.ReadOptions(rpm=(5.0, 7.56)))
    said = [w for w in spec.warnings if w.startswith("tower.foundation")]
    assert said and "PtfmSgDOF" in said[0] and "TowerBsHt = 15 m" in said[0]
    assert "upper bounds" in said[0]
    onshore = importers.load(shared / "reference/NREL5MW/NREL-5MW.fst")
    assert not [w for w in onshore.warnings if w.startswith("tower.foundation")]


def test_a_floating_deck_set_is_refused_unless_clamped(shared, tmp_path):
    """Moorings in the .fst (CompMooring > 0) but no HydroDyn: a floating turbine whose
    platform nothing describes — refused naming what is missing, as a floating windIO file
    is, and audited clamped on request with the headline saying the platform's modes are
    missing."""
    from tests.conftest import edited_reference

    mooring = "          0   CompMooring", "          3   CompMooring"
    fst = edited_reference(shared, tmp_path, "NREL5MW", "NREL-5MW.fst", *mooring) / "NREL-5MW.fst"
    refused = r"floating turbine \(moorings \(CompMooring\)\) whose platform wtvib cannot model"
    with pytest.raises(SpecError, match=refused + ": no HydroDyn"):
        importers.load(fst)
    spec = importers.load(fst, importers.ReadOptions(clamped_base=True))
    said = [w for w in spec.warnings if w.startswith("tower.foundation")]
    assert said and "moorings' own modes are missing" in said[0]


def test_a_deck_whose_blades_differ_says_every_blade_is_modelled_as_the_first(shared, tmp_path):
    """Blade 2's file with its mass adjusted (AdjBlMs 1.04536 → 1.10): wtvib models every
    blade as blade 1's, which the headline now says; a second file identical to the first
    says nothing."""
    from tests.conftest import edited_reference

    deck = "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"
    line = '"NRELOffshrBsline5MW_Blade.dat"    BldFile(2)'
    folder = edited_reference(shared, tmp_path, "NREL5MW", deck, line, '"blade2.dat"    BldFile(2)')
    second = folder / "blade2.dat"
    second.write_text((folder / "NRELOffshrBsline5MW_Blade.dat").read_text())

    def said() -> list[str]:
        return [w for w in importers.load(folder / "NREL-5MW.fst").warnings if "blades differ" in w]

    assert said() == []  # the same blade in another file
    blade = second.read_text()
    assert "    1.04536   AdjBlMs" in blade
    second.write_text(blade.replace("    1.04536   AdjBlMs", "    1.10   AdjBlMs"))
    assert said() and "BldFile(2) = blade2.dat" in said()[0]


def test_the_other_files_of_a_deck_set_say_which_file_to_give(shared):
    """The AeroDyn input was taken for an ElastoDyn deck (its NumBlNds) and failed with
    "TwrFile is missing from the deck"; the blade, tower, ServoDyn and polar files got the
    generic "not a format"; the deck set's folder "holds no .lin files". Each now says what
    it is and which file to give."""
    folder = shared / "reference" / "NREL5MW"
    for name, what in (
        ("NRELOffshrBsline5MW_Onshore_AeroDyn15.dat", "AeroDyn"),
        ("NRELOffshrBsline5MW_AeroDyn_blade.dat", "AeroDyn"),
        ("NRELOffshrBsline5MW_Onshore_ServoDyn.dat", "ServoDyn"),
        ("NRELOffshrBsline5MW_Blade.dat", "ElastoDyn blade"),
        ("NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat", "ElastoDyn tower"),
        ("Airfoils/DU21_A17.dat", "aerofoil"),
    ):
        with pytest.raises(SpecError, match=f"an OpenFAST {what}.*give the .fst"):
            importers.load(folder / name)
    hint = r"no \.lin files; to audit its deck set, give NREL-5MW\.fst"
    with pytest.raises(SpecError, match=hint):
        importers.load(folder)


def test_a_spec_is_recognised_by_its_format_key_not_by_its_prose():
    # a converted deck set's assumptions name ElastoDyn, BlSpn and NumBl: detection read them
    # as an AeroDyn file and `convert … && check` failed on wtvib's own output
    text = (
        "# wtvib spec converted from NREL-5MW.fst\nwtvib: 1\nturbine: {name: n}\n"
        "assumptions:\n- 'ElastoDyn deck: 3 NumBl, AeroDyn BlSpn stations, TwrFile read'\n"
    )
    assert importers.detect(Path("n.yaml"), text) == "wtvib"
    assert importers.detect(Path("n.txt"), text) == "wtvib"


def test_a_deck_is_recognised_by_the_key_column_only():
    prose = "This text mentions TwrFile and NumBl in passing and PCMode too.\n"
    with pytest.raises(SpecError, match="not a format wtvib reads"):
        importers.detect(Path("notes.dat"), prose)
    with pytest.raises(SpecError, match="an OpenFAST SubDyn file"):
        importers.detect(Path("sd.dat"), "   3   NReact  - number of reactions\n")


def test_convert_then_check_round_trips_a_deck_set_with_aerodyn(shared, tmp_path):
    from wtvib.spec import from_document, load_document, read_text

    out = tmp_path / "n.yaml"
    data = importers.to_data(shared / "reference/NREL5MW/NREL-5MW.fst")
    import yaml

    out.write_text("wtvib: 1\n" + yaml.safe_dump({k: v for k, v in data.items() if k != "wtvib"}))
    assert importers.detect(out, read_text(out)) == "wtvib"
    from_document(load_document(out, read_text(out)))  # loads as a spec


def test_a_folder_of_specs_points_to_batch(tmp_path):
    (tmp_path / "a.yaml").write_text("wtvib: 1\n")
    with pytest.raises(SpecError, match="wtvib batch"):
        importers.detect(tmp_path, "")
