"""ElastoDyn decks at unit level: values and tables, the operating range from the deck set."""

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

from wtvib import importers
from wtvib.errors import SpecError
from wtvib.importers import elastodyn, servodyn

DECK = """------- ELASTODYN -------
A deck for the tests (line 2 is the title, as OpenFAST reads it)
          3   NumBl       - Number of blades (-)
     12.1     RotSpeed    - Initial or fixed rotor speed (rpm)
     97.0     GBRatio     - Gearbox ratio (-)
---------------------- DISTRIBUTED TOWER PROPERTIES ----------------------------
  HtFract       TMassDen         TwFAStif       TwSSStif
   (-)           (kg/m)           (Nm^2)         (Nm^2)
 0.0            5590.87         6.14343E+11    6.14343E+11
 1.0            3235.34         1.87E+11       1.87E+11
"""


def test_values_and_tables_are_read(tmp_path):
    deck = elastodyn.parse(tmp_path / "d.dat", DECK)
    assert deck.num("NumBl") == 3 and deck.num("RotSpeed") == 12.1
    assert list(deck.column("HtFract", "TMassDen")) == [5590.87, 3235.34]
    assert deck.values["GBRatio"][1] == 5  # the line, for messages


def test_fixed_speed_from_an_induction_generator(tmp_path):
    # FAST v7 fixed speed: synchronous 1200 rpm + 1.5125 % slip over 22.5 → 54.14 rpm
    # (the AWT-27 deck, ../shared/reference/AWT27/Test01.fst)
    text = "0 VSContrl -\n1 GenModel -\n1.5125 SIG_SlPc -\n1200.0 SIG_SySp -\n22.5 GBRatio -\n"
    deck = elastodyn.parse(tmp_path / "t.fst", text)
    found = servodyn.operation(deck, deck)
    assert found.speed is not None
    assert found.speed["fixed_rpm"] == pytest.approx(1200 * 1.015125 / 22.5)
    assert "synchronous speed 1200 rpm" in found.note
    assert found.generator["generator"] == "induction"


def test_no_servodyn_is_audited_at_the_initial_speed_and_said(tmp_path):
    deck = elastodyn.parse(tmp_path / "d.dat", DECK)
    found = servodyn.operation(deck, None)
    assert found.speed == {"fixed_rpm": 12.1, "source": "the initial RotSpeed of d.dat"}
    assert "no ServoDyn" in found.warnings[0] and "--rpm" in found.warnings[0]


def test_a_parked_deck_without_servodyn_is_a_standstill_audit(tmp_path):
    """RotSpeed 0 and no controller: parked, said (it was refused without --rpm)."""
    deck = elastodyn.parse(tmp_path / "d.dat", DECK.replace("12.1     RotSpeed", "0 RotSpeed"))
    found = servodyn.operation(deck, None)
    assert found.speed == {"parked": True, "source": "RotSpeed = 0 rpm in d.dat"}
    assert "parked" in found.warnings[0] and "--rpm" in found.warnings[0]


def test_simple_variable_speed_gives_rated_speed_and_power(tmp_path):
    # the NREL 5-MW's generator (Jonkman 2009, NREL/TP-500-38060, Table 6-1 and §7):
    # rated 1173.7 rpm, 43093.55 N·m, gearbox 97, efficiency 94.4 % → 12.1 rpm, 5 MW
    servo = elastodyn.parse(
        tmp_path / "s.dat",
        "1 VSContrl -\n1 PCMode -\n94.4 GenEff -\n1173.7 VS_RtGnSp -\n43093.55 VS_RtTq -\n",
    )
    main = elastodyn.parse(tmp_path / "d.dat", DECK.replace("12.1     RotSpeed", "7 RotSpeed"))
    found = servodyn.operation(main, servo)
    assert found.speed is not None
    assert found.speed["min_rpm"] == 7 and found.speed["max_rpm"] == pytest.approx(1173.7 / 97)
    # P = T·ω·η = 43093.55 · 1173.7·π/30 · 0.944 = 5.0 MW
    power = 43093.55 * 1173.7 * math.pi / 30 * 0.944 / 1e3
    assert found.control["rated_power_kw"] == pytest.approx(power)
    assert found.control["regulation"] == "pitch"
    assert "names no lowest speed" in found.warnings[0]


def test_the_simple_variable_speed_law_is_read_as_torque_against_speed(tmp_path):
    """ServoDyn's simple law (its CalculateTorque; the NREL 5-MW's values, Jonkman 2009 §7:
    VS_Rgn2K 0.0255764 N·m/rpm², VS_SlPc 10 %, VS_RtGnSp 1161.963 rpm, VS_RtTq 43093.55
    N·m) on the rotor's shaft: k·(GB·n)²·GB in region 2, the line from the synchronous speed
    1161.963/1.1 = 1056.33 rpm to rated, VS_RtTq above — and the slope each operating point
    meets (aerodamping.generator_damping): 2T/Ω in region 2, the line's in region 2½, none
    on the flat top; at the kink a point's own torque decides the side."""
    from wtvib.aero import aerodamping

    servo = elastodyn.parse(
        tmp_path / "s.dat",
        "1 VSContrl -\n1 PCMode -\n100 GenEff -\n1161.963 VS_RtGnSp -\n43093.55 VS_RtTq -\n"
        "0.0255764 VS_Rgn2K -\n10 VS_SlPc -\n",
    )
    main = elastodyn.parse(tmp_path / "d.dat", DECK.replace("12.1     RotSpeed", "7 RotSpeed"))
    law = servodyn.operation(main, servo).control["generator_torque"]
    rpm, torque = law["rpm"], law["torque_nm"]
    gb, k = 97.0, 0.0255764
    # region 2 on the rotor's shaft: k·(97·n)² ·97
    assert torque[50] == pytest.approx(k * (gb * rpm[50]) ** 2 * gb, rel=1e-12)
    assert torque[-1] == torque[-2] == pytest.approx(43093.55 * gb)
    assert rpm[-2] == pytest.approx(1161.963 / gb)
    sync, rated = 1161.963 / 1.1, 1161.963
    # region 2 meets the line where k·ω² = slope·(ω − sync)
    line = 43093.55 / (rated - sync)
    meet = rpm[-3] * gb
    assert k * meet**2 == pytest.approx(line * (meet - sync), rel=1e-9)

    class _Sch:  # three points: region 2, region 2½ at the rated node, the flat top
        def __init__(self, n: list[float], torque: list[float]) -> None:
            omega = np.array(n) * math.pi / 30
            self.solution = type("S", (), {"omega": omega, "power": np.array(torque) * omega})
            self.region = ("partial load",) * len(n)

    n_rated = rated / gb
    sch = _Sch([9.0, n_rated, n_rated], [k * (gb * 9.0) ** 2 * gb, 3.8e6, 4.17e6])
    spec = type(
        "Spec", (), {"aerodynamics": type("A", (), {"control": type("C", (), {
            "generator_torque": type("G", (), law)})}), "coupled": type(
            "Cm", (), {"rotating_condition": "free"})}
    )  # fmt: skip
    slope = aerodamping.generator_damping(spec, sch)  # type: ignore[arg-type]
    omega9 = 9.0 * math.pi / 30
    assert slope[0] == pytest.approx(2 * sch.solution.power[0] / omega9**2, rel=1e-3)
    assert slope[1] == pytest.approx(line * gb * gb * 30 / math.pi, rel=1e-6)  # the line
    assert slope[2] == 0.0  # 4.17 MN·m: within 1 % of the flat top's 4.18


def test_rosco_discon_values(tmp_path):
    p = Path(tmp_path / "DISCON.IN")
    p.write_text(
        "34.64286   ! VS_MinOMSpd - Minimum generator speed [rad/s]\n"
        "122.90967  ! VS_RefSpd - Rated generator speed [rad/s]\n"
    )
    assert servodyn.discon(p) == {"VS_MinOMSpd": (34.64286, 1), "VS_RefSpd": (122.90967, 2)}


@pytest.mark.parametrize(
    ("discon", "message", "line"),
    [
        ("abc ! VS_MinOMSpd\n122.9 ! VS_RefSpd\n", "VS_MinOMSpd must be a", 1),
        ("inf ! VS_MinOMSpd\n122.9 ! VS_RefSpd\n", "VS_MinOMSpd must be a", 1),
        ("200 ! VS_MinOMSpd\n122.9 ! VS_RefSpd\n", "must lie between 0 and the rated", 1),
    ],
)
def test_a_bad_controller_input_is_one_line_with_file_and_line(tmp_path, discon, message, line):
    (tmp_path / "DISCON.IN").write_text(discon)
    servo = elastodyn.parse(tmp_path / "s.dat", '5 VSContrl -\n"DISCON.IN" DLL_InFile -\n')
    main = elastodyn.parse(tmp_path / "d.dat", DECK)
    with pytest.raises(elastodyn.SpecError, match=message) as err:
        servodyn.operation(main, servo)
    assert err.value.line == line and str(err.value.source).endswith("DISCON.IN")


#: The DTU Wind Energy controller's input as OpenFAST's DISCON interface hands it (the IEA-15
#: Monopile_wDTUcontroller deck's control/DISCON.IN, ROSCO 2.10 test cases: its first lines).
DTU_INIT = """begin init ;
; Overall parameters
constant  1    15000.0        ; Rated power [kW]
constant  2    0.524          ; Minimum rotor (LSS) speed [rad/s]
constant  3    0.792          ; Rated rotor (LSS) speed [rad/s]
constant  4    21586451.33303 ; Maximum allowable generator torque [Nm]
"""


def test_the_dtu_controller_s_input_gives_the_operating_range(tmp_path):
    """A deck set whose Bladed-style DLL is the DTU Wind Energy controller: its constants 2
    and 3 are the rotor's minimum and rated speed [rad/s], no gearbox between (0.524 and
    0.792 rad/s: 5.004–7.563 rpm, as the IEA-15's HAWC2 model's same constants give) —
    the deck was audited at its initial RotSpeed, warned, before."""
    (tmp_path / "DISCON.IN").write_text(DTU_INIT)
    servo = elastodyn.parse(tmp_path / "s.dat", '5 VSContrl -\n"DISCON.IN" DLL_InFile -\n')
    main = elastodyn.parse(tmp_path / "d.dat", DECK)
    found = servodyn.operation(main, servo)
    assert found.speed is not None and not found.initial and not found.warnings
    assert found.speed["min_rpm"] == pytest.approx(0.524 * 30 / math.pi, rel=1e-12)
    assert found.speed["max_rpm"] == pytest.approx(0.792 * 30 / math.pi, rel=1e-12)
    assert found.control["rated_power_kw"] == 15000.0


@pytest.mark.parametrize(
    ("old", "new", "message"),
    [
        ("0.524 ", "abc ", "constant 2 must be a finite number"),
        ("0.524 ", "0.9 ", "constant 2 (minimum rotor speed 0.9 rad/s) must lie between 0"),
    ],
)
def test_a_bad_dtu_controller_input_is_one_line(tmp_path, old, new, message):
    (tmp_path / "DISCON.IN").write_text(DTU_INIT.replace(old, new))
    servo = elastodyn.parse(tmp_path / "s.dat", '5 VSContrl -\n"DISCON.IN" DLL_InFile -\n')
    main = elastodyn.parse(tmp_path / "d.dat", DECK)
    with pytest.raises(elastodyn.SpecError, match=re.escape(message)) as err:
        servodyn.operation(main, servo)
    assert err.value.line == 4 and str(err.value.source).endswith("DISCON.IN")


def test_a_switch_must_be_a_whole_number(tmp_path):
    servo = elastodyn.parse(tmp_path / "s.dat", "2.7 VSContrl - mode\n")
    main = elastodyn.parse(tmp_path / "d.dat", DECK)
    with pytest.raises(elastodyn.SpecError, match="VSContrl is a switch") as err:
        servodyn.operation(main, servo)
    assert err.value.line == 1


@pytest.mark.parametrize(
    ("edit", "message", "line"),
    [
        (("5590.87", "abc"), "column TMassDen: 'abc' is not a finite number", 9),
        (("1.87E+11       1.87E+11", "1.87E+11       1.87E+"), r"column TwSSStif: '1\.87E\+'", 10),
        (("5590.87", "nan"), "column TMassDen: 'nan' is not a finite number", 9),
        (("          3   NumBl", "        2.7   NumBl"), "NumBl must be a whole number ≥ 1", 3),
        (("          3   NumBl", "        nan   NumBl"), "NumBl must be a finite number", 3),
    ],
)
def test_a_hostile_deck_is_one_line_with_file_and_line(tmp_path, edit, message, line):
    """The ElastoDyn mistakes of the extreme-value campaign: a text cell, a file cut off mid-number,
    NaN, a fractional or NaN blade count — each one line naming file and line, never a traceback or
    a silently truncated value."""
    text = DECK.replace(*edit)
    with pytest.raises(elastodyn.SpecError, match=message) as err:
        deck = elastodyn.parse(tmp_path / "d.dat", text)
        deck.whole("NumBl", low=1)
    assert err.value.line == line


def test_a_table_cut_short_is_refused():
    # the tower table of a truncated file ends at 0.2 of the height: not the whole tower
    deck = elastodyn.parse(Path("d.dat"), DECK.replace(" 1.0            3235.34", " 0.2 3235.34"))
    with pytest.raises(elastodyn.SpecError, match="must increase from 0 to 1"):
        deck.fractions("HtFract")


def test_rosco_tower_resonance_avoidance_is_a_quick_pass_band(tmp_path):
    """ROSCO's TRA_ExclSpeed ± TRA_ExclBand/2 (rad/s, rotor side): the controller passes the
    band quickly — the spec's quick-pass band, in rpm. 0.32 ± 0.04 rad/s = 2.67–3.44 rpm."""
    (tmp_path / "DISCON.IN").write_text(
        "0.19331 ! VS_MinOMSpd\n0.73944 ! VS_RefSpd\n1 ! WE_GearboxRatio\n"
        "0.32 ! TRA_ExclSpeed\n0.08 ! TRA_ExclBand\n"
    )
    servo = elastodyn.parse(tmp_path / "s.dat", '5 VSContrl -\n"DISCON.IN" DLL_InFile -\n')
    main = elastodyn.parse(tmp_path / "d.dat", DECK)
    found = servodyn.operation(main, servo)
    assert found.speed is not None
    (low, high), *_ = found.speed["quick_pass_rpm"]
    assert (low, high) == (pytest.approx(0.28 * 30 / math.pi), pytest.approx(0.36 * 30 / math.pi))
    assert "passed quickly" in found.note


@pytest.mark.parametrize("vs", ["5", "3"])
def test_a_deck_s_pitch_control_holds_when_its_controller_cannot_be_read(tmp_path, vs):
    """OpenFAST's regression decks name a Bladed DLL compiled from NREL's baseline source,
    whose input file ('DISCON.IN') is not in the set; a user-defined controller (VSContrl
    3) cannot be read at all. The deck still says its pitch is controlled (PCMode 5): the
    operation taken is pitch-regulated, not a stall-regulated rotor at its fine pitch (which
    drove the NREL 5-MW's tips into stall at 25 m/s and failed it for the instability)."""
    servo = elastodyn.parse(
        tmp_path / "s.dat", f'5 PCMode -\n{vs} VSContrl -\n"DISCON.IN" DLL_InFile -\n'
    )
    main = elastodyn.parse(tmp_path / "d.dat", DECK)
    found = servodyn.operation(main, servo)
    assert found.speed == {"fixed_rpm": 12.1, "source": "the initial RotSpeed of d.dat"}
    assert found.control["regulation"] == "pitch"
    unpitched = elastodyn.parse(
        tmp_path / "u.dat", f'0 PCMode -\n{vs} VSContrl -\n"DISCON.IN" DLL_InFile -\n'
    )
    assert servodyn.operation(main, unpitched).control["regulation"] == "stall"


@pytest.mark.parametrize(
    ("case", "root"),
    [("Ideal_Beam_Fixed_Free_Linear", "clamped"), ("Ideal_Beam_Free_Free_Linear", "free")],
)
def test_a_deck_set_whose_structure_is_a_beamdyn_beam_alone_is_audited(tmp_path, case, root):
    """r-test's Ideal_Beam decks: every ElastoDyn DOF around the blade off and no hub or
    nacelle mass — the structure is BeamDyn's beam, clamped, or free where ElastoDyn's
    platform is free in all six motions with 1 kg under it. Audited at standstill (RotSpeed
    0), its undamped beam (damp_type 0) judged: not refused ("every ElastoDyn DOF is off",
    "HubIner is 0" before)."""
    import tarfile

    from typer.testing import CliRunner

    from wtvib.cli import app

    with tarfile.open(Path(__file__).parent / "data/openfast_decks/rtest_special.tar.gz") as tar:
        tar.extractall(tmp_path, filter="data")
    fst = tmp_path / "glue-codes/openfast" / case / f"{case}.fst"
    s = importers.load(fst)
    assert s.blade.structure is not None and s.blade.structure.root == root
    assert s.rotor.speed.parked and s.rotor.blades == 1 and s.blade.damping_ratio == 0.0
    result = CliRunner().invoke(app, ["check", str(fst), "--no-plots"])
    assert result.exit_code == 0, result.output
    assert "1 blade," in result.stdout
    result = CliRunner().invoke(app, ["check", str(fst), "--no-plots", "--format", "json"])
    checks = {c["id"]: c for c in json.loads(result.stdout)["checks"]}
    assert checks["system.stability"]["status"] == "pass"
    assert "no mode negatively damped" in checks["system.stability"]["message"]
    # ElastoDyn's polynomials: the clamped beam's computed, the free one's refused in a line
    # (its free root's four coordinates broke the cantilever's basis: an internal error)
    result = CliRunner().invoke(app, ["shapes", str(fst), "--no-plots"])
    if root == "clamped":
        assert result.exit_code == 0 and "BldFl1Sh" in result.stdout, result.output
    else:
        lines = [ln for ln in result.output.splitlines() if ln.strip()]
        assert result.exit_code == 2 and len(lines) == 1, result.output
        assert "a blade free at its root" in lines[0]


LIN_AERO = "glue-codes/openfast/5MW_Land_Linear_Aero/5MW_Land_Linear_Aero.fst"
INFLOW = "glue-codes/openfast/5MW_Baseline/NRELOffshrBsline5MW_InflowWind_Steady8mps.dat"


@pytest.fixture
def lin_aero(tmp_path: Path) -> Path:
    """r-test's 5MW_Land_Linear_Aero (tests/data/openfast_decks/rtest_aero.tar.gz): a
    linearisation deck set — Linearize on, no controller (the generator never switched on),
    InflowWind's steady 8 m/s, RotSpeed 12.1 rpm, pitch 0°."""
    import tarfile

    data = Path(__file__).resolve().parent / "data" / "openfast_decks" / "rtest_aero.tar.gz"
    with tarfile.open(data) as tar:
        tar.extractall(tmp_path, filter="data")
    return tmp_path / LIN_AERO


def test_a_linearisation_deck_is_judged_at_its_own_operating_point(lin_aero):
    """The deck describes one operating point, the one OpenFAST linearises: its damping is
    judged there, not over a fixed-pitch schedule of 3–25 m/s the deck does not describe
    (which stalled the rotor from 18 m/s and called the NREL 5-MW aeroelastically unstable);
    said in the warning about the range. The range given (--rpm), the schedule as before."""
    from wtvib import audit

    spec = importers.load(lin_aero)
    assert spec.aerodynamics is not None
    pts = spec.aerodynamics.control.operating_points
    assert pts is not None
    assert (pts.wind_m_s, pts.rpm, pts.pitch_deg) == ([8.0], [12.1], [0.0])
    assert any("its own operating point, 8 m/s at 12.1 rpm" in w for w in spec.warnings)
    report = audit.run(spec)
    stability = next(c for c in report.checks if c.id == "aerodynamics.stability")
    assert stability.status == "pass", stability.message
    ops = [m.operating for m in report.modes if m.judged and m.operating is not None]
    assert ops and all(list(op.wind) == [8.0] for op in ops)
    given = importers.load(lin_aero, importers.ReadOptions(rpm=(6.9, 12.1)))
    assert given.aerodynamics is not None and given.aerodynamics.control.operating_points is None


@pytest.mark.parametrize(
    "old, new, expect",
    [
        ("1   WindType", "3   WindType", None),  # a turbulent field: no steady point
        ("True          Linearize", "False         Linearize", None),  # not a linearisation
        (
            "          8   HWindSpeed",
            "1e300   HWindSpeed",
            r"Steady8mps.dat:14: HWindSpeed 1e\+300 m/s: a steady wind",
        ),
        # a breath of wind overflowed the BEM, named as its fault and not the file's line
        (
            "          8   HWindSpeed",
            "1e-300   HWindSpeed",
            r"Steady8mps.dat:14: HWindSpeed 1e-300",
        ),
    ],
)
def test_only_a_linearisation_deck_s_steady_wind_is_its_operating_point(lin_aero, old, new, expect):
    root = lin_aero.parents[3]
    for path in (root / INFLOW, lin_aero):
        text = path.read_text()
        if old in text:
            path.write_text(text.replace(old, new))
            break
    else:
        raise AssertionError(old)
    if expect is not None:
        with pytest.raises(SpecError, match=expect):
            importers.load(lin_aero)
        return
    spec = importers.load(lin_aero)
    assert spec.aerodynamics is not None and spec.aerodynamics.control.operating_points is None
