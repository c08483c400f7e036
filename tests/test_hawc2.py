"""HAWC2 files at unit level (wtvib.importers.htc, .hawc2): the htc block syntax, st sets,
and a broken model's one line with file, line and block."""

import math
import re
import tarfile
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from wtvib.cli import app
from wtvib.errors import SpecError
from wtvib.importers import htc, is_main_input

DATA = Path(__file__).resolve().parent / "data" / "hawc2"
IEA15 = "HAWC2/IEA-15-240-RWT-Onshore/htc/IEA_15MW_RWT_Onshore.htc"

HTC = """\
; a comment line
begin new_htc_structure;  the structure
  begin main_body;  tower
    name  tower ;   text after the semicolon is a comment
    sec 1 0 0 0 0 ;
  end main_body;
  continue_in_file ./part.htc;
end new_htc_structure;
"""
PART = """\
  begin main_body;
    name  blade1 ;
  end main_body;
exit;
  begin main_body;  after exit: never read
  end main_body;
"""


def test_blocks_nest_comments_end_and_files_continue(tmp_path):
    (tmp_path / "m.htc").write_text(HTC)
    (tmp_path / "part.htc").write_text(PART)
    top = htc.parse(tmp_path / "m.htc")
    structure = top.block("new_htc_structure")
    assert structure is not None and structure.title == "the structure"
    bodies = structure.each("main_body")
    assert [b.need("name").values[0] for b in bodies] == ["tower", "blade1"]
    assert bodies[0].get("sec").numbers() == [1, 0, 0, 0, 0]  # type: ignore[union-attr]
    assert bodies[1].file.name == "part.htc" and bodies[1].line == 1


@pytest.mark.parametrize(
    "text, words, line",
    [
        ("begin a;\n  begin b;\n  end a;\n", "end a where b is open", 3),
        ("begin a;\n  x 1;\n", "begin a has no end a", 1),
        ("begin a;\ncontinue_in_file ./nowhere.htc;\nend a;\n", "names './nowhere.htc'", 2),
    ],
)
def test_a_broken_htc_is_named_by_file_and_line(tmp_path, text, words, line):
    path = tmp_path / "m.htc"
    path.write_text(text)
    with pytest.raises(SpecError) as found:
        htc.parse(path)
    assert words in str(found.value) and found.value.line == line


ST = """\
2 ; number of sets
#1 first set
r m
$1 2 subset one
0.0 1.0 2.0
1.0 1.5 2.5
$2 1 subset two
0.0 9.0 9.0
#2 second set
$1 3 short
0.0 1 1
"""


def test_st_sets_and_subsets_are_read_by_their_marks(tmp_path):
    path = tmp_path / "a.st"
    path.write_text(ST)
    assert htc.read_st(path, 1, 1, 3).tolist() == [[0.0, 1.0, 2.0], [1.0, 1.5, 2.5]]
    assert htc.read_st(path, 1, 2, 3).tolist() == [[0.0, 9.0, 9.0]]
    with pytest.raises(SpecError, match="announces 3 rows, the file holds 1"):
        htc.read_st(path, 2, 1, 3)
    with pytest.raises(SpecError, match="no set #3"):
        htc.read_st(path, 3, 1, 3)
    path.write_text(ST.replace("1.0 1.5 2.5", "1.0 x 2.5"))
    with pytest.raises(SpecError, match="a number was expected") as found:
        htc.read_st(path, 1, 1, 3)
    assert found.value.line == 6


@pytest.fixture
def model(tmp_path: Path) -> Path:
    with tarfile.open(DATA / "iea15_onshore.tar.gz") as tar:
        tar.extractall(tmp_path, filter="data")
    return tmp_path / IEA15


def _edit(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert old in text, old
    path.write_text(text.replace(old, new))


@pytest.mark.parametrize(
    "where, old, new, words",
    [
        ("htc", "filename ./data/IEA_15MW_RWT_Tower_st.dat;", "filename ./data/gone.dat;",
         "filename names './data/gone.dat', which does not exist"),
        ("htc", "set 1 1 ;", "set 1 7 ;", "no set #1 with a subset $7"),
        ("orientation", "mbdy1  towertop last;", "mbdy1  nacelle last;",
         "mbdy1 names the body 'nacelle', which the model does not have"),
        ("htc", "sec    2    0    0    -15.0     0    ;", "sec    2    0    0    -1a.0     0    ;",
         "sec: value 4 must be a number"),
        # the exhaustive HAWC2 campaign's crashes (tests/FUZZ.md, campaign 14), each now a line
        ("htc", "sec    2    0    0    -15.0     0    ;", "sec    2    0    0    -1e300     0    ;",
         "no wind turbine is that large"),
        ("orientation", "mbdy1  tower last;", "mbdy1  tower abc;", "is not 'last' or a node"),
        ("orientation", "mbdy2  towertop 1;", "mbdy2  towertop nan;", "is not 'last' or a node"),
        ("pc", "39 number of sections", "0 number of sections", "0 profiles: a whole number"),
        ("pc", "39 number of sections", "-1 number of sections", "-1 profiles"),
        ("pc", "1  200  21.1", "1  0  21.1", "0 rows of a profile"),
        ("pc", "1  200  21.1", "1  1e300  21.1", "rows of a profile: a whole number"),
        ("st", "$1 26", "$1 0", "announces 0 rows"),
        # the campaign's rerun: a blade's mass typed 1e300 overflowed its inertia integral
        # (a numpy warning before the spec's refusal)
        ("st", "3.1265243837780e+03", "3.1265243837780e+300", "beyond any wind turbine"),
        # a floater held by an external system wtvib does not read (no esys_node naming an
        # ESYSWamit system, as the IEA-15 and IEA-22 semisubmersibles' do) is refused, not
        # audited clamped
        ("htc", "begin fix0;  tower fixed to ground\n      body tower;\n    end fix0;",
         "begin dll;\n      mbdy_node tower 0;\n      dll 'ESYSWamit_64.dll';\n    end dll;",
         "held by the external systems ESYSWamit_64.dll: a floating model"),
        # a command's values dropped (the campaign's "bare" case, tests/FUZZ.md campaign
        # 18): a position, Euler angles, a damping and a mass each short of their numbers
        ("htc", "inipos        0.0 0.0 -15.0 ;", "inipos ;", "inipos: value 1 must be a number"),
        ("htc", "body_eulerang 0.0 0.0   0.0 ;", "body_eulerang ;",
         "body_eulerang: value 1 must be a number"),
        ("bodies", "damping_posdef  0.0 0.0 0.0 4.65E-04  4.65E-04  5.971406e-04 ;",
         "damping_posdef  0.0 0.0 ;", "damping_posdef: value 3 must be a number (got nothing"),
        ("bodies", "concentrated_mass  1  0.00   0.00    0.00    28249   0.00          0.00"
         "           0.00    ;", "concentrated_mass  1  0.00 ;",
         "concentrated_mass: value 3 must be a number (got nothing: the"),
        # a tower or blade on the model's rigid subset (wetb's test.htc: the DTU 10 MW's
        # tower on its E 2.1e17 Pa "stiff" subset, audited as a 266 Hz tower)
        ("htc", "set 1 1 ;", "set 1 3 ;", "body tower: its st subset has a modulus of"),
        ("st", "1.8877163007300e+10", "1.8877163007300e+16",
         "body blade1: its st subset has a modulus of 1.89e+16 Pa"),
        # a concentrated mass no turbine has: a negative inertia about the shaft took the
        # generator's from the hub's ("no inertia about the shaft"), node 0 was the first
        ("bodies", "concentrated_mass  1  0.0 0.0 0.0 0.0 0.0 0.0 1836784",
         "concentrated_mass  1  0.0 0.0 0.0 0.0 0.0 0.0 -1836784",
         "concentrated_mass: inertia Izz [kg·m²] -1.83678e+06 is outside 0"),
        ("bodies", "concentrated_mass  1  0.0 0.0 0.0 0.0 0.0 0.0 1836784",
         "concentrated_mass  0  0.0 0.0 0.0 0.0 0.0 0.0 1836784",
         "concentrated_mass: node 0 is outside 1"),
        ("bodies", "concentrated_mass  1  0.0 0.0 0.0 0.0 0.0 0.0 1836784",
         "concentrated_mass  1  0.0 0.0 0.0 -5.0 0.0 0.0 1836784",
         "concentrated_mass: mass [kg] -5 is outside 0"),
        # a node the body does not have (placed at its last node, silently)
        ("bodies", "concentrated_mass  1  0.0 0.0 0.0 0.0 0.0 0.0 1836784",
         "concentrated_mass  3  0.0 0.0 0.0 0.0 0.0 0.0 1836784",
         "concentrated_mass: node 3 is outside 1 … 2"),
        ("orientation", "mbdy1  tower last;", "mbdy1  tower 99;",
         "mbdy1: node 99 of body tower, which has"),
        ("bodies", "node_distribution     c2_def ;", "node_distribution     spline ;",
         "node_distribution: 'spline' is not c2_def or uniform"),
        # a load-case template's tag (the IEA-22's htc/_master DLB file)
        ("htc", "sec    2    0    0    -15.0     0    ;", "sec    2    0    0    [tz]     0    ;",
         "is a template's tag, [tz], not a number"),
    ],
)  # fmt: skip
def test_a_broken_model_is_one_line_and_exit_2(model, where, old, new, words):
    shared = model.parents[2] / "IEA-15-240-RWT"
    target = {
        "htc": model,
        "orientation": shared / "IEA_15MW_RWT_WTG_orientation.htc",
        "pc": shared / "IEA_15MW_RWT_pc_OpenFASTpolars_3dcorr.dat",
        "st": shared / "IEA_15MW_RWT_Blade_st_noFPM.st",
        "bodies": shared / "IEA_15MW_RWT_WTG_bodies_noFPM.htc",
    }[where]
    _one_line(model, target, old, new, words)


def _one_line(model: Path, target: Path, old: str, new: str, words: str) -> None:
    """``target`` edited (``old`` → ``new``), the model's check is one error line holding
    ``words``, exit 2."""
    _edit(target, old, new)
    result = CliRunner().invoke(app, ["check", str(model), "--no-plots"])
    assert result.exit_code == 2, result.output
    lines = [ln for ln in result.output.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: ") and words in lines[0], lines


def test_batch_finds_the_model_and_not_the_parts_it_continues_in(model):
    assert is_main_input(model)
    parts = model.parents[2] / "IEA-15-240-RWT"
    assert not any(is_main_input(p) for p in parts.glob("*.htc"))


def test_convert_writes_an_editable_spec_of_the_model(model, tmp_path):
    out = tmp_path / "iea15.yaml"
    result = CliRunner().invoke(app, ["convert", str(model), "-o", str(out)])
    assert result.exit_code == 0, result.output
    result = CliRunner().invoke(app, ["check", str(out), "--no-plots", "-f", "json"])
    assert result.exit_code in (0, 1), result.output


@pytest.mark.parametrize(
    ("method", "shed", "stall", "time"),
    [(2, True, True, 7.5), (3, True, True, 7.5), (1, False, True, 6.0), (0, False, False, 3.0)],
)
def test_the_unsteady_aerofoil_follows_dynstall_method(model, method, shed, stall, time):
    """HAWC2's ``dynstall_method``: MHH (2, the IEA-15 model's) lags the lift by the shed
    wake and the separation point by T_f0 + T_p0 = 6 + 1.5 half-chord transits; Øye's (1)
    the separation point only (6); none (0): the lift follows the static polar."""
    from wtvib.importers import load

    aero_htc = model.parents[2] / "IEA-15-240-RWT" / "IEA_15MW_RWT_WTG_aero.htc"
    if method != 2:
        _edit(aero_htc, "dynstall_method    2 ;", f"dynstall_method    {method} ;")
    aero = load(model).aerodynamics
    assert aero is not None
    assert (aero.shed_wake, aero.dynamic_stall) == (shed, stall)
    assert {a.separation_time for a in aero.airfoils.values()} == {time}


@pytest.mark.parametrize(
    ("text", "rows", "words", "line"),
    [
        ("3 wind pitch rpm\n4 0 5\n5 0 6\n6 1 7\n", 3, None, None),  # HAWCStab2's count line
        ("4 0 5\n5 0 6\n6 1 7\n", 3, None, None),  # the rows alone (the IEA-22's)
        ("4 0 5\n5 x 6\n", 0, "a number was expected", 2),
        ("4 0 5\n5 6\n", 0, "3 columns were expected", 2),
    ],
)
def test_an_operational_data_file_with_or_without_its_count_line(tmp_path, text, rows, words, line):
    """HAWCStab2 writes a .opt with the number of operating points first; the IEA-22's HAWC2
    model has the rows alone. Both read; a broken row is one line naming it."""
    from wtvib.errors import SpecError
    from wtvib.importers import htc

    path = tmp_path / "ops.opt"
    path.write_text(text)
    if words is None:
        table = htc.read_opt(path)
        assert table.shape == (rows, 3) and table[-1, 2] == 7
        return
    with pytest.raises(SpecError) as err:
        htc.read_opt(path)
    assert words in str(err.value) and err.value.line == line


def test_a_model_in_a_folder_below_htc_reads_its_files_from_the_model_s_folder(model):
    """HAWC2 runs a model from the folder that holds ``htc/``, also for an htc file in a
    folder below it (the IEA-22's DLB templates in ``htc/_master/``): its ``./data/…``
    names are the model folder's."""
    from wtvib.importers import load

    below = model.parent / "_master" / model.name
    below.parent.mkdir()
    below.write_text(model.read_text())  # its names the same: the run folder's
    there, here = load(below), load(model)
    assert there.rotor.speed.max_rpm == here.rotor.speed.max_rpm
    assert there.blade.mass_kg == here.blade.mass_kg


def test_a_shaft_with_its_inertia_at_one_end_turns_the_blades_against_it(model):
    """The shaft's masses all at its hub end (the IEA-15's generator inertia moved there):
    no shaft torsion to model — the blades against the one inertia, said so."""
    from wtvib import audit
    from wtvib.importers import load

    bodies = model.parents[2] / "IEA-15-240-RWT" / "IEA_15MW_RWT_WTG_bodies_noFPM.htc"
    _edit(
        bodies,
        "concentrated_mass  1  0.0 0.0 0.0 0.0 0.0 0.0 1836784",
        "concentrated_mass  2  0.0 0.0 0.0 0.0 0.0 0.0 1836784",
    )
    spec = load(model)
    assert [c.name for c in spec.drivetrain.chain] == ["blades", "hub"]
    assert spec.drivetrain.chain[1].inertia_kgm2 == 969_952 + 1_836_784
    assert any("at one end only" in a for a in spec.assumptions)
    assert audit.run(spec).verdict in ("pass", "warn", "fail")


SHAFT = "concentrated_mass  1  0.0 0.0 0.0 0.0 0.0 0.0 1836784"
#: the IEA-15's shaft (IEA_15MW_RWT_Shaft_st.dat, set 1): G·I_p = 7.93e10 × 3.9532 N·m²
SHAFT_GJ = 7.93e10 * 3.9532


def test_a_generator_partway_along_a_flexible_shaft_turns_through_the_shaft_between(model):
    """The IEA-10's HAWC2 model (IEAWindTask37/IEA-10.0-198-RWT) hangs its generator rotor
    at 5.78 m of a 9.67 m shaft, nearer the hub's end than the bearing's: once read as the
    hub's (the blades against one inertia, the rotor then held in the coupled model). A
    generator partway along a flexible shaft turns against the hub through the shaft between
    them — here the IEA-15's generator inertia moved to 2 m before the hub's node of its
    6.13 m shaft: k = GJ/2 m exactly (uniform GJ; the whole shaft's GJ/6.13 m before), and
    said where it sits."""
    from wtvib.importers import load

    bodies = model.parents[2] / "IEA-15-240-RWT" / "IEA_15MW_RWT_WTG_bodies_noFPM.htc"
    _edit(bodies, SHAFT, "concentrated_mass  2  0.0 0.0 -2.0 0.0 0.0 0.0 1836784")
    spec = load(model)
    assert [c.name for c in spec.drivetrain.chain] == ["blades", "hub", "generator"]
    assert spec.drivetrain.chain[1].inertia_kgm2 == 969_952
    assert spec.drivetrain.chain[2].inertia_kgm2 == 1_836_784
    k = spec.drivetrain.shafts[1].stiffness_nm_rad
    assert k == pytest.approx(SHAFT_GJ / 2.0, rel=1e-9)
    assert any("partway along the shaft" in a and "at 4.13 m" in a for a in spec.assumptions)


def test_a_uniform_node_distribution_puts_its_nodes_at_equal_distances(model):
    """``node_distribution uniform N``: N nodes at equal distances along the centre line
    (not the c2_def sections): the IEA-15's generator inertia on node 2 of a shaft with
    three uniform nodes (the hub's mass moved to node 3, the last) sits at its middle,
    3.06 m of 6.13, and turns against the hub through the half shaft beyond it
    (k = GJ/3.065 m)."""
    from wtvib.importers import load

    bodies = model.parents[2] / "IEA-15-240-RWT" / "IEA_15MW_RWT_WTG_bodies_noFPM.htc"
    text = bodies.read_text()
    start = text.index("name        shaft ;")
    at = text.index("node_distribution", start)
    end = text.index(";", at)
    bodies.write_text(text[:at] + "node_distribution uniform 3 " + text[end:])
    _edit(bodies, SHAFT, SHAFT.replace("mass  1", "mass  2"))
    _edit(
        bodies, "concentrated_mass  2  0.0 0.0 0.0 69131", "concentrated_mass  3  0.0 0.0 0.0 69131"
    )
    spec = load(model)
    k = spec.drivetrain.shafts[1].stiffness_nm_rad
    assert k == pytest.approx(SHAFT_GJ / (6.129880124703066 / 2), rel=1e-9)
    assert any("at 3.06 m" in a for a in spec.assumptions)


def test_a_shaft_s_torsion_is_integrated_as_hawc2_interpolates_its_st(model):
    """GJ linear in r between the st file's rows, as HAWC2 interpolates them: the IEA-15's
    shaft with its I_p doubled at the second row (r = 5.118 m; the body is 6.13 m long, the
    last row's GJ held beyond it) — compliance L·ln(g₂/g₁)/(g₂ − g₁) + 1.012 m/g₂ exactly
    (a trapezoid of 1/GJ over the rows is 7.2 % more compliant)."""
    from wtvib.importers import load

    st = model.parents[2] / "IEA-15-240-RWT" / "IEA_15MW_RWT_Shaft_st.dat"
    rows = st.read_text().splitlines()
    second = next(i for i, r in enumerate(rows) if r.startswith("5.118"))
    rows[second] = rows[second].replace("3.9532", "7.9064", 1)
    st.write_text("\n".join(rows) + "\n")
    spec = load(model)
    g1, g2 = SHAFT_GJ, 2 * SHAFT_GJ
    length = 6.129880124703066
    compliance = 5.118 * math.log(g2 / g1) / (g2 - g1) + (length - 5.118) / g2
    assert spec.drivetrain.shafts[1].stiffness_nm_rad == pytest.approx(1 / compliance, rel=1e-9)


def test_a_generator_no_turbine_has_is_warned(model):
    """The IEA-3.4's HAWC2 model (IEAWindTask37/IEA-3.4-130-RWT) turns 2,866 kg·m² on its
    shaft's generator side, 0.008 % of its blades' — a geared generator given at its own
    speed, not on the low-speed shaft (its OpenFAST deck: GenIner 1,056 kg·m² × 97² =
    9.9e6); direct drives carry 0.6–2 % (the IEA-15's own 1.84e6 kg·m², 0.6 %: not
    warned). Audited as written, warned."""
    from wtvib.importers import load

    assert not any("generator side" in w for w in load(model).warnings)
    bodies = model.parents[2] / "IEA-15-240-RWT" / "IEA_15MW_RWT_WTG_bodies_noFPM.htc"
    _edit(bodies, SHAFT, SHAFT.replace("1836784", "2866"))
    spec = load(model)
    assert any(
        "the generator side of the shaft shaft turns 2,866 kg·m²" in w for w in spec.warnings
    )


def test_a_rigid_shaft_s_modes_do_not_depend_on_where_its_inertia_sits(model):
    """On a rigid shaft the generator and the hub turn as one: the IEA-15 with its generator
    inertia at the hub's end (one mass: the blades against it) and at the shaft's first node
    (two masses, the shaft made rigid: G × 1e7) has the same coupled modes: the same
    matrices up to the order of their sums, within 1e-9 — with the shaft level (its 6° tilt,
    which the coupled model neglects, puts sin²6° of a spin inertia about the yaw axis of
    the head that keeps it: 3e-5 on the second flap's backward whirl). Two faults showed
    here: one mass behind the blades held the rotor on the nacelle where the generator is
    free (the collective edge at the clamped blade's 0.67 Hz instead of 1.44), and a
    generator-side spin inertia was counted twice in the nacelle's roll (the head's and the
    drive train's)."""
    from wtvib import audit
    from wtvib.importers import load

    bodies = model.parents[2] / "IEA-15-240-RWT" / "IEA_15MW_RWT_WTG_bodies_noFPM.htc"
    orientation = bodies.with_name("IEA_15MW_RWT_WTG_orientation.htc")
    _edit(orientation, "mbdy2_eulerang 6.0 0.0 0.0;", "mbdy2_eulerang 0.0 0.0 0.0;")
    _edit(bodies, SHAFT, SHAFT.replace("mass  1", "mass  2"))
    one = audit.run(load(model))
    _edit(bodies, SHAFT.replace("mass  1", "mass  2"), SHAFT)
    st = model.parents[2] / "IEA-15-240-RWT" / "IEA_15MW_RWT_Shaft_st.dat"
    _edit(st, "7.93E+10", "7.93E+17")
    two_spec = load(model)
    assert [c.name for c in two_spec.drivetrain.chain] == ["blades", "hub", "generator"]
    two = audit.run(two_spec)
    ours = {m.id: m.frequency_hz for m in one.modes if m.id.startswith("system.")}
    theirs = {m.id: m.frequency_hz for m in two.modes if m.id.startswith("system.")}
    assert set(ours) - {"system.drivetrain1"} == set(theirs) - {"system.drivetrain1"}
    for name, f in ours.items():
        if name != "system.drivetrain1":
            assert f == pytest.approx(theirs[name], rel=1e-9), name
    edge = [m for m in one.modes if m.id.startswith("system.blade.edge1.")]
    collective = next(m.frequency_hz for m in edge if m.id.endswith("collective"))
    assert collective > 1.5 * max(m.frequency_hz for m in edge if "collective" not in m.id)


def test_the_model_s_own_operating_points_and_twisting_blade_are_read(model):
    """The .opt's points are the audit's operating points (its wind, pitch and rotor speed:
    what HAWCStab2 was run at), the pc file's fourth column the aerofoils' C_M, the st file's
    x_sh the shear centres (HAWC2's blade x towards the leading edge: importers.hawc2.
    _shear_centre) — the IEA-15's at 25–37 % of the chord over its outer half, near the
    quarter chord as a blade's are."""
    from wtvib.aero import bem
    from wtvib.importers import load

    opt = np.loadtxt(model.parents[1] / "data" / "IEA_15MW_RWT_Onshore.opt", skiprows=1)
    spec = load(model)
    aero = spec.aerodynamics
    assert aero is not None
    pts = aero.control.operating_points
    assert pts is not None and pts.source == "IEA_15MW_RWT_Onshore.opt"
    np.testing.assert_array_equal(pts.wind_m_s, opt[:, 0])
    np.testing.assert_array_equal(pts.rpm, opt[:, 2])
    np.testing.assert_array_equal(pts.pitch_deg, opt[:, 1])
    sch = bem.schedule(spec)
    np.testing.assert_array_equal(sch.wind, opt[:, 0])
    np.testing.assert_allclose(sch.rpm, opt[:, 2], rtol=1e-12)
    # the rated wind: where the power the pitch holds (11 m/s, the first pitched point) is
    # reached from the last point below it (10.7 m/s, the top speed at the fine pitch), the
    # power growing as V³: 10.77 m/s on wtvib's BEM power, 10.74 on the .opt's own (15,497
    # and 15,664 kW; the IEA-15's documented 10.59 m/s, Gaertner et al. 2020, Table 1-1, is
    # its OpenFAST controller's); full load from the first pitched point
    p_lo, p_hi = opt[opt[:, 0] == 10.7, 3][0], opt[opt[:, 0] == 11.0, 3][0]
    assert sch.rated_wind == pytest.approx(10.7 * (p_hi / p_lo) ** (1 / 3), rel=0.005)
    assert [r == "full load" for r in sch.region] == list(opt[:, 0] >= 11.0)
    assert all(a.cm is not None for a in aero.airfoils.values())
    half = 0.5 * aero.stations.radius_m[-1]
    stations = zip(aero.stations.airfoil, aero.stations.radius_m, strict=True)
    cambered = [aero.airfoils[n] for n, r in stations if r > half]
    assert all(a.cm is not None and min(a.cm) < -0.05 for a in cambered)
    centre = np.asarray(aero.stations.shear_centre_chord)
    r = np.asarray(aero.stations.radius_m) / aero.stations.radius_m[-1]
    outer = (r > 0.5) & (r < 0.95)
    assert np.all((centre[outer] > 0.24) & (centre[outer] < 0.38)), centre[outer]
    assert bem.rotor(spec).torsion is not None


def test_an_operational_data_file_out_of_order_or_with_a_repeated_wind_is_read(model):
    """The .opt's rows taken in wind order, one per wind (the first of a repeated one), the
    parked rows (0 rpm) left out of the points: the points a valid file gives, never a
    refusal (reversed, a cut-in above the cut-out was refused)."""
    from wtvib.importers import load

    opt = model.parents[1] / "data" / "IEA_15MW_RWT_Onshore.opt"
    lines = opt.read_text().splitlines()
    head, rows = lines[0], lines[1:]
    rows = [*rows[::-1], rows[5]]
    opt.write_text("\n".join([head.replace("17", str(len(rows)), 1), *rows]) + "\n")
    aero = load(model).aerodynamics
    assert aero is not None and aero.control.operating_points is not None
    winds = aero.control.operating_points.wind_m_s
    assert winds == sorted(set(winds)) and len(winds) == 17
    assert (aero.control.cut_in_wind_m_s, aero.control.cut_out_wind_m_s) == (1.0, 25.0)
    # a parked row (0 rpm) is no operating point
    opt.write_text("\n".join([head.replace("17", "18", 1), *lines[1:], "  26.0  90.0  0.0  0 0"]))
    again = load(model).aerodynamics
    assert again is not None and again.control.operating_points is not None
    assert 26.0 not in again.control.operating_points.wind_m_s


def test_oye_s_model_in_attached_flow_damps_as_the_static_lift(model):
    """Øye's dynamic stall (``dynstall_method 1``: the separation point lagged, no shed
    wake) lags only the separated part of the lift; in attached flow that part is nearly
    zero and the coupled model damps as with the lift following the static polar (method
    0): the IEA-15's first flap collective and edge backward at 5–8 m/s within 5 % (measured
    −1.1 … −4.3 %, the thick inner aerofoils' separated share). The coupled model once
    dropped the attached part too without a shed wake: its flap damping fell to −0.014."""
    from wtvib import audit
    from wtvib.importers import load

    aero_htc = model.parents[2] / "IEA-15-240-RWT" / "IEA_15MW_RWT_WTG_aero.htc"

    def damping(method: int) -> dict[str, np.ndarray]:
        text = aero_htc.read_text()
        aero_htc.write_text(
            re.sub(r"dynstall_method\s+\d+ ;", f"dynstall_method    {method} ;", text)
        )
        report = audit.run(load(model))
        ops = {m.id: m.operating for m in report.modes if m.operating is not None}
        out = {}
        for name in ("system.blade.flap1.collective", "system.blade.edge1.backward"):
            op = ops[name]
            out[name] = np.interp([5.0, 6.0, 7.0, 8.0], np.asarray(op.wind), np.asarray(op.total))
        return out

    oye, static = damping(1), damping(0)
    for name in oye:
        np.testing.assert_allclose(oye[name], static[name], rtol=0.05, err_msg=name)


@pytest.fixture
def monopile(tmp_path: Path) -> Path:
    """The IEA-15's HAWC2 monopile model (its own folder's files beside the onshore
    archive's WTG files)."""
    for name in ("iea15_onshore.tar.gz", "iea15_monopile.tar.gz"):
        with tarfile.open(DATA / name) as tar:
            tar.extractall(tmp_path, filter="data")
    return tmp_path / "HAWC2/IEA-15-240-RWT-Monopile/htc/IEA_15MW_RWT_Monopile.htc"


EMBEDDED = "IEA_15MW_RWT_Embeddedmonopile_st.dat"


@pytest.mark.parametrize(
    "where, old, new, words",
    [
        # the st's A so large for its I that no tube has both
        ("st", "1.7290E+00", "3.7290E+01", "is no steel tube wtvib can stand on the soil"),
        ("htc", "datafile  ./soil/IEA_15MW_Soil.dat;", "datafile  ./soil/gone.dat;",
         "datafile names './soil/gone.dat', which does not exist"),
        ("htc", "mbdy_name  embedded_monopile;", "mbdy_name  embedded_pile;",
         "mbdy_name names the body 'embedded_pile', which the model does not have"),
    ],
)  # fmt: skip
def test_a_broken_soil_block_is_one_line(monopile, where, old, new, words):
    """The pile on the model's own soil: what it cannot stand on is one line, exit 2."""
    target = monopile if where == "htc" else monopile.parents[1] / "data" / EMBEDDED
    _one_line(monopile, target, old, new, words)


def test_a_pile_on_two_soil_elements_is_said_clamped(monopile):
    """Two soil elements (wtvib stands one pile on one soil): clamped at the mudline and
    said, as before the model's own soil was read."""
    from wtvib.importers import load

    text = monopile.read_text()
    start, end = text.index("begin soil_element;"), text.index("end soil_element;")
    element = text[start : end + len("end soil_element;")]
    monopile.write_text(text.replace(element, element + "\n" + element))
    spec = load(monopile)
    assert spec.tower.foundation is None or spec.tower.foundation.kind == "clamped"
    assert any("pile in the soil" in w for w in spec.warnings)


@pytest.fixture
def model22(tmp_path: Path) -> Path:
    with tarfile.open(DATA / "iea22_monopile.tar.gz") as tar:
        tar.extractall(tmp_path, filter="data")
    return tmp_path / "HAWC2/IEA-22-280-RWT-Monopile/htc/iea_22mw_rwt_steps.htc"


def test_the_water_a_monopile_moves_is_read_from_the_hydro_block(model22):
    """The IEA-22 monopile's hydro_element (sec z Cm Cd V Vr width: 0 and 34 m from its
    first node, at the seabed — mudlevel 34 m — Cm 1, Vr = π·10²/4 m²): ρ·Cm·Vr =
    1027·78.5398 = 80,660 kg/m from the tower's base to the mean water level, the tower's
    added mass. With the water 10 m lower (mwl 10: HAWC2's z points down) it stops 24 m
    above the base, the section above the water cut where the surface crosses it; with the
    seabed 4 m higher, it starts 4 m up."""
    from wtvib import importers

    spec = importers.load(model22)
    added = spec.tower.added_mass
    assert added is not None and added.height_m == [0.0, 34.0]
    assert added.mass_per_length_kg_m == pytest.approx([1027 * 78.5398] * 2, rel=1e-6)
    assert not any("hydro" in w for w in spec.warnings)
    _edit(model22, "mwl 0.0;", "mwl 10.0;")
    lower = importers.load(model22).tower.added_mass
    assert lower is not None and lower.height_m == pytest.approx([0.0, 24.0])
    assert lower.mass_per_length_kg_m == pytest.approx([1027 * 78.5398] * 2, rel=1e-6)
    # a seabed 4 m above the pile's first node (mudlevel 30, the pile's foot at 34): no water
    # below it
    _edit(model22, "mudlevel 34.0;", "mudlevel 30.0;")
    shallow = importers.load(model22).tower.added_mass
    assert shallow is not None and shallow.height_m == pytest.approx([4.0, 24.0])
    # the body named as the IEA-15 monopile model names it (HAWC2 reads both words)
    _edit(
        model22, "mbdy_name monopile;\n    hydrosections", "body_name monopile;\n    hydrosections"
    )
    named = importers.load(model22).tower.added_mass
    assert named is not None and named.height_m == pytest.approx([4.0, 24.0])


def test_a_hydro_element_off_the_tower_is_said_and_a_broken_one_refused(model22):
    """A hydro element on a body that is not the tower's is not read, and said so (its water
    is missing); a section off its body is one line with file and line, exit 2."""
    from wtvib import importers

    text = model22.read_text()
    _edit(
        model22, "mbdy_name monopile;\n    hydrosections", "mbdy_name towertop;\n    hydrosections"
    )
    spec = importers.load(model22)
    assert spec.tower.added_mass is None
    assert any("towertop" in w and "hydro" in w for w in spec.warnings)
    model22.write_text(text)
    _edit(model22, "sec 34.0 1.0 1.0 78.5398", "sec 340.0 1.0 1.0 78.5398")
    result = CliRunner().invoke(app, ["check", str(model22)])
    assert result.exit_code == 2, result.output
    assert "hydro_element monopile" in result.output and "Traceback" not in result.output
    assert re.search(r"iea_22mw_rwt_steps\.htc.*48[0-9]", result.output.replace("\n", " "))


def test_a_fully_populated_st_set_gives_the_shear_centre_of_the_classical_one(model):
    """The IEA-15's blade in both of HAWC2's forms (the repository's classical and fully
    populated st files of one blade): the shear centre found in the 6×6 stiffness — where a
    shear force does not twist the section, in the axes of the elastic centre turned by the
    structural pitch — is the classical set's x_sh at every station (to 2e-11 m), and the
    steady twist's arm the same."""
    import gzip

    from wtvib import importers

    classical = importers.load(model)
    st = model.parents[2] / "IEA-15-240-RWT" / "IEA_15MW_RWT_Blade_st_FPM.st"
    st.write_bytes(gzip.decompress((DATA / "IEA_15MW_RWT_Blade_st_FPM.st.gz").read_bytes()))
    bodies = model.parents[2] / "IEA-15-240-RWT" / "IEA_15MW_RWT_WTG_bodies_noFPM.htc"
    _edit(bodies, "IEA_15MW_RWT_Blade_st_noFPM.st;", "IEA_15MW_RWT_Blade_st_FPM.st;")
    _edit(bodies, "FPM 0;", "FPM 1;")
    full = importers.load(model)
    a, b = classical.aerodynamics, full.aerodynamics
    assert a is not None and b is not None
    assert any("fully populated" in note for note in full.assumptions)
    chord_a = a.stations.shear_centre_chord
    chord_b = b.stations.shear_centre_chord
    assert chord_a is not None and chord_b is not None
    np.testing.assert_allclose(chord_b, chord_a, atol=1e-9)
    assert 0.2 < float(np.median(chord_b)) < 0.45  # near the quarter chord, as a blade's are
    # and the same blade in bending and torsion (the 6×6 condensed: first four modes within
    # 0.3 %, measured −0.1 … −0.24 %; torsion 3.938 Hz in both)
    from wtvib.subsystems import blade

    assert classical.blade.structure is not None and full.blade.structure is not None
    one = blade.rotating_modes(classical.blade.structure, np.array([0.0]))
    two = blade.rotating_modes(full.blade.structure, np.array([0.0]))
    assert one[0] == two[0]
    np.testing.assert_allclose(two[1], one[1], rtol=3e-3)
    assert blade.torsion_frequency(full.blade.structure) == pytest.approx(
        blade.torsion_frequency(classical.blade.structure), rel=1e-3
    )


@pytest.mark.parametrize(
    ("old", "new", "words"),
    [
        ("rho 1027;", "rho 1e9;", "water_properties rho"),
        ("mudlevel 34.0;", "mudlevel nan;", "mudlevel"),
        ("sec 34.0 1.0 1.0 78.5398 78.5398", "sec 34.0 1e6 1.0 78.5398 78.5398", "Cm from 0 to 10"),
        ("sec 34.0 1.0 1.0 78.5398 78.5398", "sec 34.0 1.0 1.0 78.5398 -78.5398", "Vr from 0"),
        ("sec 34.0 1.0 1.0", "sec 0.0 1.0 1.0", "rising z"),
        ("nsec 2;\n    sec 0.0", "nsec 2;\n    sec x", "must be a number"),
    ],
)
def test_a_broken_hydro_block_is_one_line_with_file_and_line(model22, old, new, words):
    """The hydro block's numbers are read as any input's: a density that is no water's, a
    level that is no number, a section's coefficient or area that no monopile has, sections
    not along the body — one line naming the htc file and the line, exit 2, no traceback."""
    _edit(model22, old, new)
    result = CliRunner().invoke(app, ["check", str(model22)])
    assert result.exit_code == 2, result.output
    text = " ".join(result.output.split())
    assert words in text and "iea_22mw_rwt_steps.htc" in text, text
    assert "Traceback" not in result.output


def _points(model: Path) -> tuple[list[float], list[float], list[str]]:
    from wtvib.importers import load

    spec = load(model)
    assert spec.aerodynamics is not None
    pts = spec.aerodynamics.control.operating_points
    assert pts is not None
    return pts.wind_m_s, pts.rpm, spec.assumptions


def test_an_htc_beside_htc_runs_in_the_folder_that_holds_data(model):
    """HAWC2 runs a model in the folder that holds its htc/ and data/ folders; HAWCStab2's
    inputs are often kept in a folder beside htc/ (the IEA-10's hawcstab2/
    steadystate_modal.htc names ./data/…). Such an htc finds the model's files one folder
    up, as it does from htc/; a folder with no data/ near is still looked in alone."""
    wind, rpm, _ = _points(model)
    beside = model.parents[1] / "hawcstab2" / model.name
    beside.parent.mkdir()
    beside.write_text(model.read_text())
    assert _points(beside)[:2] == (wind, rpm)
    assert htc.root_folder(beside) == model.parents[1]
    alone = model.parents[3] / "elsewhere" / "x" / "y" / model.name
    assert htc.root_folder(alone) == alone.parent  # no data/ within reach: its own folder


def test_the_operational_data_file_is_the_one_the_model_names_else_one_that_turns(model):
    """A model's data/ folder may hold several .opt files — the IEA-10's a wind-only one
    (rotor speed 0 on every row: HAWCStab2's winds for a controller) beside the one its
    hawcstab2 block names. The named one is used; without a name, the first by name whose
    rotor turns, and the others are said; a wind-only file alone gives no operating points
    (the controller's constants do, said) — never a 0 rpm operating range."""
    data = model.parents[1] / "data"
    own = data / "IEA_15MW_RWT_Onshore.opt"
    wind, rpm, _ = _points(model)
    lines = own.read_text().splitlines()
    (data / "A_windonly.opt").write_text(
        "\n".join([lines[0], *(f"{r.split()[0]} 0 0" for r in lines[1:])]) + "\n"
    )
    found = _points(model)
    assert found[:2] == (wind, rpm)
    assert any("which holds A_windonly.opt too" in a for a in found[2])
    # the model names its file: that one, whatever the others' names
    own.rename(data / "Z_turning.opt")
    _edit(model, "begin dll;", "begin hawcstab2;\n  operational_data_filename ./data/Z_turning.opt;"
          "\nend hawcstab2;\nbegin dll;")  # fmt: skip
    found = _points(model)
    assert found[:2] == (wind, rpm)
    assert any("named by the htc's hawcstab2 block" in a for a in found[2])
    # it names the wind-only file: the controller's speed range, said
    _edit(model, "Z_turning.opt", "A_windonly.opt")
    from wtvib.importers import load

    spec = load(model)
    assert spec.rotor.speed.min_rpm > 0
    assert any("no operational data file where the rotor turns" in a for a in spec.assumptions)


SEMI = "HAWC2/IEA-15-240-RWT-UMaineSemi/htc/IEA_15MW_RWT_UMaineSemi.htc"


@pytest.fixture
def semi(tmp_path: Path) -> Path:
    """The IEA-15's HAWC2 model on its floater, with the WTG's files and the WAMIT results
    its floater names (tests/validation/test_hawc2.py: the same three archives)."""
    for archive in (
        DATA / "iea15_onshore.tar.gz",
        DATA / "iea15_umainesemi.tar.gz",
        DATA.parent / "openfast_decks" / "iea15_semi.tar.gz",
    ):
        with tarfile.open(archive) as tar:
            tar.extractall(tmp_path, filter="data")
    return tmp_path / SEMI


@pytest.mark.parametrize(
    "where, old, new, words",
    [
        ("htc", "data    MASS    1.7838E+07 ;", "", "ext_sys floater: no data MASS"),
        ("htc", "data    RIJ_COG 3 3 36.425 ;", "", "no RIJ_COG 3 3"),
        ("htc", "HydroData/IEA-15-240-RWT-UMaineSemi'", "HydroData/gone'",
         "WAMIT_FILE names '../../OpenFAST/IEA-15-240-RWT-UMaineSemi/HydroData/gone', which "
         "does not exist"),
        ("htc", "data    DENSITY 1025.0 ;", "data    DENSITY 1e9 ;", "density 1e+09 is outside"),
        ("htc", "data    COG     0.0 0.0 -14.94 ;", "data    COG     0.0 0.0 abc ;",
         "COG: value 3 must be a number"),
        ("constraint", "esys_node  line1 1 ;", "esys_node  line1 3 ;",
         "mooring line line1: no constraint fixes its first node to the ground"),
        ("mooring", "data mass  6.850e+02  5.957e+02", "data mass  6.850e+02  7.957e+02",
         "mass per length in water [kg/m] 795.7 is outside"),
        ("mooring", "data axial_stiff  3.270e+09 ;", "data axial_stiff  nan ;",
         "axial_stiff: value 1 must be a number"),
        ("mooring", "data start_pos  0.000e+00 -8.376e+02  2.000e+02 ;",
         "data start_pos  0.000e+00 -8.376e+02 ;", "start_pos: value 3 must be a number"),
        ("constraint", "mbdy_node  ifb 1 ;", "mbdy_node ;", "its fairlead's body '' does not"),
        ("constraint", "mbdy_node  ifb 1 ;", "mbdy_node  ifb abc ;", "node 'abc' is not 'last'"),
        ("htc", "mbdy_node ifb  0                   ;", "mbdy_node ;", "a floating model whose"),
        # a line laid 237 m long where its ends lie 790 m apart
        ("mooring", "data end_pos -0.000e+00  1.240e+01", "data end_pos -0.000e+00  -6.000e+02",
         "mooring line 1 is stretched 237% of its length"),
    ],
)  # fmt: skip
def test_a_broken_floater_is_one_line_and_exit_2(semi, where, old, new, words):
    data = semi.parents[1] / "data"
    target = {
        "htc": semi,
        "constraint": data / "IEA_15MW_RWT_UMaineSemi_mooring_constraint.htc",
        "mooring": data / "IEA_15MW_RWT_UMaineSemi_mooring_system.htc",
    }[where]
    _one_line(semi, target, old, new, words)


def test_the_floater_s_moorings_are_turned_into_the_platform_s_frame(semi):
    """HAWC2's frame (x lateral, y downwind, z down) is the platform's turned: (X, Y, Z) =
    (y, x, −z). The three chains at 120° stiffen surge and sway alike; the first alone,
    anchored upwind (HAWC2's −y), stiffens surge (along X) and not sway."""
    from wtvib import importers
    from wtvib.importers.hawc2_floater import to_platform

    assert to_platform(np.array([1.0, 2.0, 3.0])).tolist() == [2.0, 1.0, -3.0]
    k = np.asarray(importers.load(semi).tower.foundation.platform.stiffness)
    three = k[0, 0]  # the waterplane has no surge or sway stiffness: the chains' alone
    assert three == pytest.approx(k[1, 1], rel=1e-3) and three > 5e4
    mooring = semi.parents[1] / "data" / "IEA_15MW_RWT_UMaineSemi_mooring_system.htc"
    text = mooring.read_text()
    mooring.write_text(text[: text.index("begin ext_sys", text.index("name   line1"))])
    k = np.asarray(importers.load(semi).tower.foundation.platform.stiffness)
    assert k[0, 0] > 10 * k[1, 1] and k[0, 0] > 0.1 * three


MEMBER = """\
  begin main_body;
    name        column ;
    type        timoschenko ;
    nbodies       1 ;
    node_distribution c2_def ;
    begin  timoschenko_input ;
      filename ../IEA-15-240-RWT/IEA_15MW_RWT_Dummy_st.dat;
      set  1 1 ;
    end  timoschenko_input ;
    begin  c2_def ;
      nsec 2 ;
      sec  1  0.0e+00  0.0e+00 0.0e+00  0.0e+00 ;
      sec  2  0.0e+00  0.0e+00 1.0e+00  0.0e+00 ;
    end  c2_def ;{mass}
  end main_body ;
"""


@pytest.mark.parametrize("mass", ["", "\n    concentrated_mass 1 0 0 0 5e5 0 0 0 ;"])
def test_a_floater_s_members_stand_beside_the_turbine(semi, mass):
    """A floater whose members are main bodies of their own (the IEA-22 semisubmersible's
    columns and pontoons: placed by base blocks, joined by constraints, carrying the hydro
    elements of Morison's drag) — listed before the floater's body, the turbine is still
    found above the body that holds the rotor; their hydro elements are said as the
    floater's, not as water missing from the tower; a member with mass is a warning (the
    floater's MASS does not hold it)."""
    from wtvib import importers

    _edit(semi, "  begin main_body;\n    name        ifb ;",
          MEMBER.format(mass=mass) + "  begin main_body;\n    name        ifb ;")  # fmt: skip
    _edit(semi, "    begin base;\n\t  mbdy ifb ;",
          "    begin base;\n      mbdy column ;\n      inipos 0 -60 0 ;\n    end base;\n"
          "    begin base;\n\t  mbdy ifb ;")  # fmt: skip
    _edit(semi, "\tbegin water_properties;",
          "\tbegin hydro_element;\n\t  mbdy_name column;\n\t  hydrosections uniform 2;\n"
          "\t  nsec 2;\n\t  sec 0.0 -1.0 1.0 100 100 10 0 0 0 0 100;\n"
          "\t  sec 1.0 -1.0 1.0 100 100 10 0 0 0 0 100;\n\tend hydro_element;\n"
          "\tbegin water_properties;")  # fmt: skip
    spec = importers.load(semi)
    assert spec.tower.foundation.platform is not None
    said = " ".join(spec.assumptions)
    assert "hydro elements on column (the floater's members" in said
    warned = [w for w in spec.warnings if w.startswith("tower.")]
    if mass:
        assert len(warned) == 1 and "(column, ifb) carry 500,002 kg" in warned[0], warned
    else:
        assert warned == [], warned


def test_the_blades_damping_aniso_v2_is_read_as_damping_aniso(model22):
    """The IEA-22's blades give their damping with HAWC2's damping_aniso_v2 (the same six
    values Mx My Mz Kx Ky Kz as damping_aniso; its comment: "tuned to 0.5 % critical
    damping on first flap/edge modes and 2 % on first torsion"): read as the blade's
    stiffness-proportional damping, ζ = π·β·f — not a ratio assumed for want of one. Which
    direction each damps, as damping_posdef (Kx along the chord, edgewise; Ky flapwise): so
    the first flap and edge modes have the comment's 0.5 % (measured 0.51 %, 0.47 %); with
    Kx flapwise, as damping_aniso's, they would be 0.34 % and 0.70 %. A third witness: the
    same repository's BeamDyn blade of this turbine (tests/data/openfast_decks/iea22.tar.gz)
    damps flapwise with μ5 = 0.004048 s and edgewise with μ4 = 0.003153 s — Ky's and Kx's
    neighbours, not the other way round."""
    from wtvib import audit, importers

    spec = importers.load(model22)
    beta = spec.blade.stiffness_damping_s
    assert beta is not None
    assert (beta.bending_1, beta.bending_2, beta.torsion) == (0.004251, 0.002846, 0.001194)
    report = audit.run(spec)
    assert not any(a.startswith("blade: damping ratio") for a in report.assumptions)
    ratios = {m.id: m.damping_ratio for m in report.modes if m.subsystem == "blade"}
    for name in ("blade.flap1", "blade.edge1"):
        assert ratios[name] == pytest.approx(0.005, rel=0.1), name
    _edit(model22, "damping_aniso_v2", "damping_aniso_v3")  # a command HAWC2 has not
    assert importers.load(model22).blade.stiffness_damping_s is None


def test_the_blades_damping_aniso_damps_their_bending_about_x_flapwise(model):
    """The IEA-15's blades give damping_aniso (Kx 3.038e-3, Ky 2.167e-3 s; its comment:
    "blade damping tuned to 3 % log dec flap/edge"): damping_aniso damps the bending about
    the body's x — flapwise — with Kx, so the first flap and edge modes both have the 3 %
    logarithmic decrement, ζ = 0.03/2π = 0.477 % (measured 0.484 %, 0.477 %); with Kx
    edgewise, as damping_posdef's, 0.35 % and 0.67 %."""
    from wtvib import audit, importers

    report = audit.run(importers.load(model))
    ratios = {m.id: m.damping_ratio for m in report.modes if m.subsystem == "blade"}
    for name in ("blade.flap1", "blade.edge1"):
        assert ratios[name] == pytest.approx(0.03 / (2 * math.pi), rel=0.05), name


@pytest.mark.parametrize(
    "name, filename",
    [
        ("dtu_we_controller", "./control/dtu_we_controller.dll"),
        # wetb's DTU10MWRef6.0_IOS model (PyPI wetb 0.1.33): the old name, the new file
        ("risoe_controller", "./control/dtu_we_controller.dll"),
        # the DTU 10 MW RWT v1's htc: the controller before 2015, the same init constants
        ("risoe_controller", "./control/risoe_controller.dll"),
        ("my_controller", "./control/dtu_we_controller.dll"),
    ],
)
def test_the_dtu_controller_is_known_by_its_name_or_its_file(model, name, filename):
    """Without operational data the speed range is the controller's constants 2 and 3
    (0.524 / 0.792 rad/s in the IEA-15's htc: 5.004 / 7.563 rpm), whatever the type2_dll's
    name says where its file is the DTU controller's, and under its name before 2015."""
    (model.parents[1] / "data" / "IEA_15MW_RWT_Onshore.opt").unlink()
    _edit(model, "name dtu_we_controller ;", f"name {name} ;")
    _edit(model, "filename  ./control/dtu_we_controller.dll ;", f"filename  {filename} ;")
    from wtvib.importers import load

    speed = load(model).rotor.speed
    assert speed.min_rpm == pytest.approx(0.524 * 30 / math.pi, abs=1e-6)  # kept to 6 decimals
    assert speed.max_rpm == pytest.approx(0.792 * 30 / math.pi, abs=1e-6)


def test_a_type2_dll_that_is_no_dtu_controller_gives_no_speed_range(model):
    (model.parents[1] / "data" / "IEA_15MW_RWT_Onshore.opt").unlink()
    _edit(model, "name dtu_we_controller ;", "name my_controller ;")
    _edit(model, "filename  ./control/dtu_we_controller.dll ;", "filename  ./control/mine.dll ;")
    with pytest.raises(SpecError, match="no operating range"):
        from wtvib.importers import load

        load(model)


def test_a_dtu_controller_s_minimum_above_its_rated_speed_is_named_by_line(model):
    """The HAWC2 model's constants as an OpenFAST deck's DTU-controller input's
    (servodyn.dtu_speeds, one check for both): the line of constant 2, not the spec's
    rotor.speed."""
    (model.parents[1] / "data" / "IEA_15MW_RWT_Onshore.opt").unlink()
    _one_line(
        model,
        model,
        "constant   2  0.524 ",
        "constant   2  0.9 ",
        "IEA_15MW_RWT_Onshore.htc:132: constant 2 (minimum rotor speed 0.9 rad/s) must lie",
    )
