"""OpenFAST's own linearisations (its regression tests, OpenFAST/r-test) read as OpenFAST
writes them, against an independent MBC3 run on the same files.

The reference (``tests/data/openfast_lin/reference.json``, SOURCES.md there) is
openfast_toolbox's ``fx_mbc3`` and ``campbell_diagram_data_oneOP`` (OpenFAST/openfast_toolbox
@ d34b283), run once on each case: every root with Im λ > 0 of its azimuth-averaged
multi-blade state matrix, natural frequency and damping ratio.
"""

import gzip
import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from tests.tolerances import frequency_and_damping_bounds, half_unit, root_bounds
from wtvib.importers import openfast_lin as ol

DATA = Path(__file__).resolve().parents[1] / "data" / "openfast_lin"
REFERENCE = json.loads((DATA / "reference.json").read_text())
CASES = sorted(REFERENCE)


def _case(name: str, folder: Path) -> list[ol.LinFile]:
    out = folder / name
    out.mkdir(exist_ok=True)
    for gz in sorted(DATA.glob(f"{name}.*.lin.gz")):
        (out / gz.name.removesuffix(".gz")).write_bytes(gzip.decompress(gz.read_bytes()))
    return [ol.read(p) for p in sorted(out.glob("*.lin"))]


@pytest.mark.parametrize("case", CASES)
def test_mbc3_gives_openfast_toolboxs_roots(case, tmp_path):
    """Every root the reference finds is a root of wtvib's averaged multi-blade matrix: the
    same transformation (Bir 2008), the same rotor speed (the operating point's rates of
    generator azimuth and drive-train twist, as NREL's MBC3 takes it), the same state order
    — to what the arithmetic can promise on any machine: the reference's written digits
    (half a unit in the last) plus how far rounding may move each root of this matrix (its
    condition number on the balanced matrix, tests/tolerances.py). On most roots that is
    1e-9–1e-8 relative; on the free-free beam's near-rigid-body roots (0.089 Hz in a matrix
    of norm 4e10) it is 1e-2: their digits past the third are rounding, whatever the CPU.

    5MW_Land_BD_Linear: OpenFAST writes each BeamDyn node's three rotations under one name
    ("rotational displacement in X" thrice); openfast_toolbox pairs them across blades out
    of order (its triplet [12, 42, 70]: the third rotation of blade 1 and 2 with the first
    of blade 3) and finds 25 of the 30 triplets. wtvib pairs the k-th rotation with the
    k-th (the reference's numbers differ from its own by up to 1.5 %); with the
    reference's pairing put in, the arithmetic agrees to the same bound."""
    files = _case(case, tmp_path)
    ref = REFERENCE[case]
    lay = ol.layout(files[0].states, files[0].path, files[0].rotor_speed, files[0].a)
    if case == "5MW_Land_BD_Linear":
        ours = lay.triplets_q
        assert ours.shape == (30, 3)  # every BeamDyn DOF of every blade, once
        lay = replace(lay, triplets_q=np.asarray(ref["triplets"], dtype=np.intp))
    f, df, z, dz = frequency_and_damping_bounds(*root_bounds(ol.mbc_average(files, lay)))
    for f_ref, z_ref, _ in ref["modes"]:
        # the root nearest in the metric of the bounds themselves
        k = int(
            np.argmin(
                np.abs(f - f_ref) / (df + half_unit(f_ref))
                + np.abs(z - z_ref) / (dz + half_unit(z_ref))
            )
        )
        assert abs(f[k] - f_ref) <= df[k] + half_unit(f_ref), (case, f_ref, f[k], df[k])
        assert abs(z[k] - z_ref) <= dz[k] + half_unit(z_ref), (case, f_ref, z_ref, z[k], dz[k])


@pytest.mark.parametrize("case", CASES)
def test_every_reference_root_is_a_mode_or_said_left_out(case, tmp_path):
    """No root is lost: each of the reference's roots is a structural mode of the report
    or among the roots it lists as left out (inflow, unsteady aerodynamics, radiation,
    rigid-body motion) — whatever their number (5MW_Land_Linear_Aero: 78 inflow roots,
    the lowest 0.13 Hz, below every structural mode but the tower's) — to the rounding the
    arithmetic allows each root (tests/tolerances.py). BeamDyn's states as OpenFAST wrote
    them, as the reference took them (wtvib turns them into the rotating frame first:
    test_beamdyn_states_are_turned_into_the_rotating_frame)."""
    files = _case(case, tmp_path)
    point, _ = ol.operating_point(files, as_written=True)
    left = point.left_out.get("roots", np.zeros(0, complex))
    found = np.concatenate([point.frequency_hz, np.abs(left) / (2 * math.pi)])
    lay = ol.layout(files[0].states, files[0].path, files[0].rotor_speed, files[0].a)
    f, df, _, _ = frequency_and_damping_bounds(*root_bounds(ol.mbc_average(files, lay)))
    for f_ref, z_ref, _ in REFERENCE[case]["modes"]:
        if z_ref > 0.999:  # a real root the reference keeps for an Im λ of 1e-15: no mode
            continue
        # BeamDyn: the reference's own blade pairing moves its roots up to 1.5 % (above)
        rounding = df[np.argmin(np.abs(f - f_ref))] + half_unit(f_ref)
        tol = 0.02 * f_ref if case == "5MW_Land_BD_Linear" else rounding
        assert np.min(np.abs(found - f_ref)) <= tol, (case, f_ref, tol)
    assert len(point.names) >= 1  # every r-test case has a structural mode to judge


def test_beamdyn_states_are_turned_into_the_rotating_frame(tmp_path):
    """OpenFAST writes BeamDyn's states in the blade root's frame frozen at the
    linearisation's instant but flags them rotating (OpenFAST issue #3394, its fix pull
    request #3400): MBC3 then adds a spurious rotor speed to every mode they take part in.
    wtvib turns them into the rotating frame as the fix does (openfast_lin.beamdyn_frame).
    Checked on r-test's 5MW_Land_BD_Linear (12.1 rpm, written in August 2024):

    * the rotor's free spin — a rigid-body motion, frequency zero — sits at 0.19 Hz (near
      Ω/2π = 0.20 Hz) as written, below 0.01 Hz turned (left out as rigid either way);
    * the tower's first side-side, 0.3221 Hz at standstill (the issue's NREL 5-MW with
      BeamDyn blades), droops to 0.3113 Hz as written (−3.4 %) — the issue's droop, 2.3 %
      at 12 rpm on its build — and is 0.3216 Hz turned: no droop, as the issue's
      RotStates = False control shows. Its fix's regenerated r-test baseline moves this mode
      +2.1 % and the fore-aft −0.4 % (r-test pull request #184, from 0.3087 Hz on a newer
      build); here +3.3 % and −0.5 %;
    * the modes named from the blades keep their order and whirl (forward above backward,
      2P apart: test_whirl_splits_by_twice_the_rotor_speed)."""
    files = _case("5MW_Land_BD_Linear", tmp_path)
    written, _ = ol.operating_point(files, as_written=True)
    turned, _ = ol.operating_point(files)
    spin = written.left_out["roots"]
    assert written.left_out["modules"] == {"rigid": 1}
    assert abs(spin[0]) / (2 * math.pi) == pytest.approx(
        files[0].rotor_speed / (2 * math.pi), rel=0.1
    )
    assert turned.left_out["modules"] == {"rigid": 1}
    assert abs(turned.left_out["roots"][0]) / (2 * math.pi) < 0.01
    at = dict(zip(turned.names, turned.frequency_hz, strict=True))
    was = dict(zip(written.names, written.frequency_hz, strict=True))
    assert at["tower.ss1"] == pytest.approx(0.3221, rel=0.01)
    assert was["tower.ss1"] < 0.975 * 0.3221
    assert at["tower.fa1"] / was["tower.fa1"] - 1 == pytest.approx(-0.004, abs=0.004)
    assert len(turned.notes) == 1 and "#3394" in turned.notes[0]
    assert not written.notes


def test_beamdyn_s_frame_turns_with_the_rotor_s_spin_in_the_pitched_blade(tmp_path):
    """The turn's own terms, on A = 0 so that only they remain: each node triplet's block
    is −ω̃ (ω̃·x = ω × x) and the rates' rows take −ω̃·A of the displacements', with
    ω = Ω·(cos θ, sin θ, 0) the rotor's spin in ElastoDyn's pitched blade frame
    (j₁ = cos θ·i₁ − sin θ·i₂, j₂ = sin θ·i₁ + cos θ·i₂: ω·j₂ = Ω·sin θ; OpenFAST's
    ElastoDyn SetCoordSy), each blade with its own pitch."""
    files = _case("5MW_Land_BD_Linear", tmp_path)
    f = replace(files[0], a=np.zeros_like(files[0].a), pitch=(0.3, -0.2, 0.1))
    lay = ol.layout(f.states, f.path, f.rotor_speed, files[0].a)
    bd = [p for p, i in enumerate(lay.q) if f.states[i].module == "BD"]
    found = ol._node_triplets(f.states, lay, bd)
    assert found is not None
    positions, blades = found
    assert positions.shape == (30, 3) and sorted(set(blades.tolist())) == [1, 2, 3]
    a = ol._rotating_frame(f, lay, positions, blades)
    omega = f.speed(lay)[0]
    assert omega > 1.0
    x = np.array([0.3, -1.1, 0.7])
    for row, blade in zip(positions, blades, strict=True):
        theta = f.pitch[blade - 1]
        w = omega * np.array([math.cos(theta), math.sin(theta), 0.0])
        q, d = lay.q[row], lay.qd[row]
        assert a[np.ix_(q, q)] @ x == pytest.approx(-np.cross(w, x), abs=1e-12)
        assert a[np.ix_(d, d)] @ x == pytest.approx(-np.cross(w, x), abs=1e-12)
    # an isotropic oscillator q̈ = −k·q written in the frozen frame, seen from the turning
    # one: q̈ = −k·q − 2ω × q̇ − ω × (ω × q), q̇ = q̇ (Coriolis and centrifugal terms)
    k = 3.0
    plain = np.zeros_like(f.a)
    q, d = lay.q[positions[0]], lay.qd[positions[0]]
    plain[np.ix_(q, d)] = np.eye(3)
    plain[np.ix_(d, q)] = -k * np.eye(3)
    b = ol._rotating_frame(replace(f, a=plain), lay, positions[:1], blades[:1])
    w = omega * np.array([math.cos(0.3), math.sin(0.3), 0.0])
    assert b[np.ix_(q, q)] @ x == pytest.approx(np.zeros(3), abs=1e-12)
    assert b[np.ix_(q, d)] @ x == pytest.approx(x, abs=1e-12)
    assert b[np.ix_(d, d)] @ x == pytest.approx(-2 * np.cross(w, x), abs=1e-12)
    assert b[np.ix_(d, q)] @ x == pytest.approx(-k * x - np.cross(w, np.cross(w, x)), abs=1e-12)


def test_beamdyn_states_written_after_the_fix_are_taken_as_written(tmp_path):
    """A file written on or after the day OpenFAST's fix was proposed (2026-07-21) may come
    from a build with it: its states are taken as written, and the report says so — unless
    it names a release before the one the fix was proposed for (5.0.1: pull request #3400
    targets rc-5.0.1), which has the frozen frame whatever its date."""
    files = _case("5MW_Land_BD_Linear", tmp_path)
    later = [replace(f, generated=ol.BEAMDYN_FIX_PROPOSED, version=None) for f in files]
    point, _ = ol.operating_point(later)
    written, _ = ol.operating_point(files, as_written=True)
    assert np.array_equal(point.frequency_hz, written.frequency_hz)
    assert "taken as written" in point.notes[0]
    assert files[0].generated is not None and files[0].generated.isoformat() == "2024-08-29"
    old_release = [replace(f, version=(4, 1, 2)) for f in later]
    turned, _ = ol.operating_point(old_release)
    assert not np.array_equal(turned.frequency_hz, written.frequency_hz)
    assert "OpenFAST 4.1.2, before the fix" in turned.notes[0]
    new_release = [replace(f, version=(5, 0, 1)) for f in later]
    as_is, _ = ol.operating_point(new_release)
    assert np.array_equal(as_is.frequency_hz, written.frequency_hz)


def test_the_pitch_and_the_day_are_read_from_the_header():
    """The pitch each blade's BeamDyn frame is turned by comes from the inputs' table
    ("ED Blade k pitch command, rad", as OpenFAST writes it: r-test's full
    5MW_Land_BD_Linear.1.lin); a table without them gives none, not zeros."""
    head = [
        "Predictions were generated on 05-Mar-2025 at 10:00:00 using OpenFAST",
        "Order of inputs:",
        "   Row/Column Operating Point   Rotating Frame? Derivative Order Description",
        "   ---------- ---------------   --------------- ---------------- -----------",
        "          1    1.745329251994E-001   T   0   ED Blade 1 pitch command, rad",
        "          2    1.745329251994E-001   T   0   ED Blade 2 pitch command, rad",
        "          3    1.745329251994E-001   T   0   ED Blade 3 pitch command, rad",
        "          4    0.000000000000E+000   F   0   ED Yaw moment, Nm",
        "",
    ]
    assert ol._pitch(head) == pytest.approx((0.17453292519943,) * 3)
    assert ol._generated(head).isoformat() == "2025-03-05"
    assert ol._version(head) is None  # "using OpenFAST" with no release named
    # r-test's own headers: a development build after a release, and a release build
    built = "Predictions were generated on 20-Feb-2024 at 14:17:34 using OpenFAST, compiled "
    assert ol._version([built + "… at commit v3.5.2-957-g05b14cf"]) == (3, 5, 2)
    assert ol._version(["generated on 01-Jan-2026 using OpenFAST-v4.0.2, compiled"]) == (4, 0, 2)
    assert ol._pitch(head[:4] + head[7:]) is None
    assert ol._generated(["Predictions were generated on 31-Feb-2025 at"]) is None


#: OpenFAST's linearisation of the NREL 5-MW at 8 m/s and 12.2 rpm (5MW_Land_Linear_Aero)
#: named by what takes part, against the FAST full-system modes of the parked turbine
#: (Jonkman et al. 2009, NREL/TP-500-38060, Table 9-1): the mode called X is the one at
#: X's frequency — within 10 % (rotation stiffens the blades: +7 % on the collective flap
#: at 12.2 rpm; aerodynamic damping moves the fore-aft tower mode 4 %).
JONKMAN_2009_FAST = {
    "tower.fa1": 0.3240,
    "tower.ss1": 0.3120,
    "blade.flap1.collective": 0.6993,
    "blade.flap2.collective": 2.0205,
    "tower.fa2": 2.9003,
    "tower.ss2": 2.9361,
}


def test_modes_are_named_after_what_moves(tmp_path):
    files = _case("5MW_Land_Linear_Aero", tmp_path)
    point, blades = ol.operating_point(files)
    assert blades == 3
    at = dict(zip(point.names, point.frequency_hz, strict=True))
    for name, f_ref in JONKMAN_2009_FAST.items():
        assert abs(at[name] / f_ref - 1) < 0.10, (name, at[name], f_ref)
    assert 5.5 < at["yaw1"] < 7.0  # the nacelle yaw mode of the 5-MW: ~6 Hz
    # no inflow root took a structural name: 78 left out, the first flap modes named
    assert point.left_out["modules"] == {"AD": 78}
    assert {"blade.flap1.backward", "blade.flap1.forward", "blade.edge1.backward"} <= set(at)


@pytest.mark.parametrize(
    "case", ["5MW_Land_Linear_Aero", "5MW_Land_BD_Linear", "5MW_OC4Semi_Linear"]
)
def test_whirl_splits_by_twice_the_rotor_speed(case, tmp_path):
    """In the fixed frame a cyclic blade mode splits into a backward whirl at f − 1P and a
    forward whirl at f + 1P (Bir 2008; DOMAIN.md): the modes named forward lie about 2P
    above those named backward — for the ElastoDyn blades and BeamDyn's alike."""
    files = _case(case, tmp_path)
    point, _ = ol.operating_point(files)
    at = dict(zip(point.names, point.frequency_hz, strict=True))
    two_p = 2 * point.rpm / 60
    for family in ("blade.flap1", "blade.edge1"):
        split = at[f"{family}.forward"] - at[f"{family}.backward"]
        assert 0.7 * two_p < split < 1.3 * two_p, (case, family, split, two_p)
    assert at["blade.flap1.backward"] < at["blade.flap1.collective"] < at["blade.flap1.forward"]


def _synthetic_lin(path: Path, omega: float, psi: float, f_blade: float) -> None:
    """Three uncoupled blade oscillators (ζ = 1 %) in the rotating frame, as a .lin file."""
    w = 2 * math.pi * f_blade
    n = 6
    rows = []
    for b in (1, 2, 3):
        rows.append(
            f"ED 1st flapwise bending-mode DOF of blade {b} (internal DOF index = DOF_BF({b},1)), m"
        )
    for b in (1, 2, 3):
        rows.append(
            f"ED First time derivative of 1st flapwise bending-mode DOF of blade {b} "
            f"(internal DOF index = DOF_BF({b},1)), m/s"
        )
    a = np.zeros((n, n))
    a[:3, 3:] = np.eye(3)
    a[3:, :3] = -(w**2) * np.eye(3)
    a[3:, 3:] = -2 * 0.01 * w * np.eye(3)
    table = "\n".join(f"{k + 1:11d}    0.0E+000    T    2    {d}" for k, d in enumerate(rows))
    matrix = "\n".join(" ".join(f"{v: .12E}" for v in row) for row in a)
    path.write_text(
        "Simulation information:\n"
        f"   Rotor Speed:    {omega:.6f} rad/s\n   Azimuth:    {psi:.6f} rad\n"
        f"   Wind Speed:    0.0 m/s\n   Number of continuous states:    {n}\n\n"
        "Order of continuous states:\n"
        "   Row/Column Operating Point  Rotating Frame? Derivative Order Description\n"
        "   ---------- ---------------  --------------- ---------------- -----------\n"
        f"{table}\n\nLinearized state matrices:\n\nA: {n} x {n}\n{matrix}\n"
    )


def test_forward_whirl_is_the_one_at_f_plus_1p(tmp_path):
    """The sign convention proven where the answer is known: three identical uncoupled
    blades of 0.7 Hz on a rotor at 1.2 rad/s give a collective mode at 0.7 Hz and cyclic
    ones at 0.7 ∓ 0.191 Hz — backward below, forward above (Bir 2008, Eqs. 16–17)."""
    omega = 1.2
    for k, psi in enumerate((0.3, 0.3 + 2 * math.pi / 3, 0.3 + 4 * math.pi / 3), start=1):
        _synthetic_lin(tmp_path / f"rotor.{k}.lin", omega, psi, 0.7)
    data = ol.to_spec_data(tmp_path, None)
    modes = data["results"]["modes"]
    one_p = omega / (2 * math.pi)
    assert modes["blade.flap1.collective"]["frequency_hz"][0] == pytest.approx(0.7, rel=1e-3)
    assert modes["blade.flap1.forward"]["frequency_hz"][0] == pytest.approx(0.7 + one_p, rel=1e-3)
    assert modes["blade.flap1.backward"]["frequency_hz"][0] == pytest.approx(0.7 - one_p, rel=1e-3)
    assert modes["blade.flap1.forward"]["whirl"] == ["forward"]


def test_a_floating_linearisations_platform_modes_are_not_called_implausible(tmp_path):
    """OpenFAST's OC4 semisubmersible at 12 rpm: its surge and sway at 0.0089 Hz (a period
    of 113 s on catenary moorings, reference.json) are platform modes, held to the
    platform's slowest plausible frequency (0.002 Hz, audit.SLOWEST_PLATFORM_HZ) like the
    ones wtvib computes — not to the 0.01 Hz of any other mode."""
    from wtvib import audit, importers

    _case("5MW_OC4Semi_Linear", tmp_path)
    lin = tmp_path / "5MW_OC4Semi_Linear" / "5MW_OC4Semi_Linear.1.lin"
    report = audit.run(importers.load(lin, importers.ReadOptions(rpm=(6.0, 12.1))))
    surge = next(m for m in report.modes if m.id == "system.platform.surge")
    assert surge.frequency_hz == pytest.approx(0.00887, rel=0.01)
    assert not [w for w in report.warnings if "platform" in w and "implausible" in w]


def test_beamdyn_states_not_in_node_triplets_are_taken_as_written_and_said(tmp_path):
    """A file whose BeamDyn states are not each node's translation and rotation triplets
    (here one rotation renamed a translation) is not turned: its states are taken as written
    and the report says why — never a guess at which state is which."""
    files = _case("5MW_Land_BD_Linear", tmp_path)
    f = files[0]
    states = list(f.states)
    for blade in (1, 2, 3):  # the same state of every blade, so the rotor's triplets hold
        k = next(
            i
            for i, s in enumerate(f.states)
            if s.description.startswith(f"BD_{blade} ")
            and "rotational displacement" in s.description
        )
        states[k] = replace(
            states[k], description=states[k].description.replace("rotational", "translational")
        )
    point, _ = ol.operating_point([replace(f, states=tuple(states))])
    written, _ = ol.operating_point(files, as_written=True)
    assert np.array_equal(point.frequency_hz, written.frequency_hz)
    assert len(point.notes) == 1 and "taken as written" in point.notes[0]


def test_a_pitch_input_for_fewer_blades_than_the_states_name_is_not_used(tmp_path):
    """A file whose inputs give the pitch of fewer blades than its BeamDyn states name turns
    every blade's states with 0° and says so (never an index past the inputs)."""
    files = _case("5MW_Land_BD_Linear", tmp_path)
    short = [replace(f, pitch=(0.2,)) for f in files]
    point, _ = ol.operating_point(short)
    assert "no pitch input" in point.notes[0]
    turned, _ = ol.operating_point(files)
    assert np.array_equal(point.frequency_hz, turned.frequency_hz)
