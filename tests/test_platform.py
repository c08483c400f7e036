"""The floating platform under the tower (wtvib.subsystems.platform): its matrices against the
kinematics of point masses, the tower base's transformation against a rigid body's motion,
a rigid tower on a platform against the rigid-body eigenproblem written out by hand, the
added mass at a mode's own frequency, and the MAP++ reader's refusals."""

from pathlib import Path

import numpy as np
import pytest

from wtvib.errors import SpecError
from wtvib.importers import mooring
from wtvib.importers.deck import parse
from wtvib.numerics.modal import ModalError
from wtvib.spec import from_data
from wtvib.spec.tower import Platform
from wtvib.subsystems import platform, tower

G = 9.80665


def _rigid_body(r: np.ndarray) -> np.ndarray:
    """The displacement (3 × 6) of a point at r for the platform's (surge, sway, heave,
    roll, pitch, yaw): u = t + ω × r, small rotations."""
    x, y, z = r
    cross = np.array([[0.0, z, -y], [-z, 0.0, x], [y, -x, 0.0]])  # ω × r = cross @ ω
    return np.hstack([np.eye(3), cross])


def _platform(**change: object) -> Platform:
    data: dict[str, object] = {
        "tower_base_m": 30.0,
        "mass_kg": 5e6,
        "cm_m": -20.0,
        "inertia_roll_kgm2": 1e9,
        "inertia_pitch_kgm2": 1.2e9,
        "inertia_yaw_kgm2": 3e8,
        "added_mass": np.diag([1e6, 1.1e6, 2e6, 1.3e9, 1.5e9, 1e8]).tolist(),
        "stiffness": np.diag([5e4, 6e4, 1e6, 2e9, 2.2e9, 1e8]).tolist(),
    }
    return Platform.model_validate(data | change)


def test_rigid_mass_is_the_kinetic_energy_of_its_points() -> None:
    """Eight point masses, symmetric about the axis, their CM 12 m below the PRP: the rigid
    mass matrix from (m, z_G, inertias about the CM) equals Σ Jᵀ·m·J of the points."""
    points = [(sx * 7.0, sy * 4.0, z) for sx in (-1, 1) for sy in (-1, 1) for z in (-5.0, -19.0)]
    m_point = 1e5
    expected = sum(m_point * _rigid_body(np.array(r)).T @ _rigid_body(np.array(r)) for r in points)
    r = np.array(points)
    z_g = float(r[:, 2].mean())
    about_cm = r - [0.0, 0.0, z_g]
    p = _platform(
        mass_kg=m_point * len(points),
        cm_m=z_g,
        inertia_roll_kgm2=m_point * float(np.sum(about_cm[:, 1] ** 2 + about_cm[:, 2] ** 2)),
        inertia_pitch_kgm2=m_point * float(np.sum(about_cm[:, 0] ** 2 + about_cm[:, 2] ** 2)),
        inertia_yaw_kgm2=m_point * float(np.sum(about_cm[:, 0] ** 2 + about_cm[:, 1] ** 2)),
    )
    np.testing.assert_allclose(platform.rigid_mass(p), expected, rtol=1e-12, atol=1e-3)


@pytest.mark.parametrize(("direction", "dofs"), [("fa", (0, 4)), ("ss", (1, 3))])
def test_the_tower_base_moves_with_the_platform(direction: str, dofs: tuple[int, int]) -> None:
    """The tower base at h above the PRP, moved by the platform's translation and rotation
    in a plane: its translation from the rigid body's kinematics, its slope the rotation
    that tilts the axis towards +x (fore-aft) or +y (side-side); the transformation takes
    it back to the platform's motion."""
    p = _platform()
    h = p.tower_base_m
    rng = np.random.default_rng(7)
    for _ in range(5):
        motion = np.zeros(6)
        motion[list(dofs)] = rng.normal(size=2)
        base = _rigid_body(np.array([0.0, 0.0, h])) @ motion
        above = _rigid_body(np.array([0.0, 0.0, h + 1.0])) @ motion
        i = 0 if direction == "fa" else 1
        translation, slope = base[i], above[i] - base[i]  # a rigid body: exact per metre
        back = platform.transform(p, direction) @ [translation, slope]  # type: ignore[arg-type]
        np.testing.assert_allclose(back, motion[list(dofs)], atol=1e-12)


def _tower_on(p: Platform, youngs_pa: float = 2.1e12) -> dict[str, float]:
    return {
        m.id: m.frequency_hz for m in tower.structural_modes(from_data(_tower_data(p, youngs_pa)))
    }


def _tower_data(p: Platform, youngs_pa: float = 2.1e12) -> dict[str, object]:
    data = {
        "wtvib": 1,
        "turbine": {"name": "rigid tower on a platform"},
        "rotor": {"blades": 3, "orientation": "upwind", "hub": "rigid", "speed": {"fixed_rpm": 20}},
        "tower": {
            "height_m": 50.0,
            "sections": {
                "height_m": [0, 50.0],
                "outer_diameter_m": [4.0, 4.0],
                "wall_thickness_m": [0.02, 0.02],
            },
            "material": {"youngs_modulus_pa": youngs_pa, "density_kg_m3": 7850.0},
            "foundation": {"kind": "platform", "platform": p.model_dump()},
        },
        "tower_head": {"mass_kg": 1e5, "cm_above_top_m": 0.0},
    }
    return data


def test_a_rigid_tower_on_a_platform_is_a_two_dof_rigid_body() -> None:
    """A tower ten thousand times stiffer than steel on the platform: surge and pitch (sway
    and roll) are the two modes of one rigid body about the PRP — its mass the platform's
    (rigid and added) with the tower's and the head's, its restoring the platform's with
    the whole weight's −Σm·g·z (the 2 × 2 eigenproblem written out here); heave the whole
    mass on the heave stiffness."""
    p = _platform()
    modes = _tower_on(p)
    h, length, d, t, rho = p.tower_base_m, 50.0, 4.0, 0.02, 7850.0
    mu = rho * np.pi * (d**2 - (d - 2 * t) ** 2) / 4
    tower_mass = mu * length
    first = mu * ((h + length) ** 2 - h**2) / 2  # ∫ μ z dz
    second = mu * ((h + length) ** 3 - h**3) / 3  # ∫ μ z² dz
    head, top = 1e5, h + length
    a = np.diag(p.added_mass)
    k = np.diag(p.stiffness)

    def rigid(i_cm: float, a_t: float, a_r: float, k_t: float, k_r: float) -> np.ndarray:
        coupling = p.mass_kg * p.cm_m + first + head * top
        m = np.array(
            [
                [p.mass_kg + a_t + tower_mass + head, coupling],
                [coupling, i_cm + p.mass_kg * p.cm_m**2 + a_r + second + head * top**2],
            ]
        )
        stiff = np.diag([k_t, k_r - G * coupling])
        return np.sort(np.sqrt(np.linalg.eigvals(np.linalg.solve(m, stiff)).real)) / (2 * np.pi)

    fa = rigid(p.inertia_pitch_kgm2, a[0], a[4], k[0], k[4])
    ss = rigid(p.inertia_roll_kgm2, a[1], a[3], k[1], k[3])
    got_fa = sorted([modes["tower.platform.surge"], modes["tower.platform.pitch"]])
    got_ss = sorted([modes["tower.platform.sway"], modes["tower.platform.roll"]])
    np.testing.assert_allclose(got_fa, fa, rtol=2e-3)
    np.testing.assert_allclose(got_ss, ss, rtol=2e-3)
    heave = np.sqrt(k[2] / (p.mass_kg + a[2] + tower_mass + head)) / (2 * np.pi)
    assert modes["tower.platform.heave"] == pytest.approx(heave, rel=1e-9)


def test_the_tower_bends_above_its_platform() -> None:
    """The same tower of steel: its first bending modes lie between a clamped base (a stiffer
    support) and the free-free beam's (the platform adds mass and little stiffness)."""
    p = _platform()
    modes = _tower_on(p, youngs_pa=2.1e11)
    assert modes["tower.platform.pitch"] < modes["tower.fa1"]
    assert modes["tower.platform.roll"] < modes["tower.ss1"]


def test_added_mass_at_a_frequency() -> None:
    """The table interpolated linearly between its points; beyond it its nearest end; A∞
    without a table or a frequency."""
    low, high = np.diag([1.0, 2, 3, 4, 5, 6]) * 1e6, np.diag([2.0, 3, 4, 5, 6, 7]) * 1e6
    p = _platform(
        added_mass_by_frequency=[
            {"frequency_hz": 0.01, "matrix": low.tolist()},
            {"frequency_hz": 0.03, "matrix": high.tolist()},
        ]
    )
    np.testing.assert_allclose(platform.added_mass(p, 0.02), (low + high) / 2)
    np.testing.assert_allclose(platform.added_mass(p, 0.015), 0.75 * low + 0.25 * high)
    np.testing.assert_allclose(platform.added_mass(p, 0.001), low)
    np.testing.assert_allclose(platform.added_mass(p, 1.0), high)
    np.testing.assert_allclose(platform.added_mass(p), p.added_mass)
    np.testing.assert_allclose(platform.added_mass(_platform(), 0.02), _platform().added_mass)


def test_a_mode_takes_the_added_mass_at_its_own_frequency() -> None:
    """Heave with an added mass that falls with frequency (6·10⁶ kg at 0.04 Hz, 2·10⁶ kg at
    0.06 Hz): the mode's frequency is the fixed point f = √(k/(m + A(f)))/2π — where the
    added mass the table gives equals the one the frequency needs — not A∞'s frequency."""
    k, m_rigid = 0.9e6, 5e6
    table = [
        {"frequency_hz": f, "matrix": np.diag([1.0, 1, a, 1, 1, 1]).tolist()}
        for f, a in ((0.04, 6e6), (0.06, 2e6))
    ]
    stiffness = np.diag([5e4, 6e4, k, 2e9, 2.2e9, 1e8]).tolist()
    p = _platform(mass_kg=m_rigid, cm_m=0.0, added_mass_by_frequency=table, stiffness=stiffness)
    f = platform.heave_frequency(p, mass_above=0.0)
    assert 0.04 < f < 0.06
    needed = k / (2 * np.pi * f) ** 2 - m_rigid
    assert platform.added_mass(p, f)[2, 2] == pytest.approx(needed, rel=1e-4)
    infinite = np.sqrt(k / (m_rigid + p.added_mass[2][2])) / (2 * np.pi)
    assert f != pytest.approx(infinite, rel=0.1)


def test_a_frequency_with_no_fixed_point_is_an_error() -> None:
    """An oscillating map (f → 3 − f, from 2 Hz: 1, 2, 1 …) never reaches its fixed point:
    said, not returned."""
    with pytest.raises(ModalError, match="added mass"):
        platform.at_own_frequency(lambda f: 2.0 if f is None else 3.0 - f)


def test_platform_matrices_must_be_symmetric_with_positive_added_mass() -> None:
    a = np.diag([1e6, 1.1e6, 2e6, 1.3e9, 1.5e9, 1e8])
    skew = a.copy()
    skew[0, 4] = 1e7
    with pytest.raises(ValueError, match=r"symmetric: \[5\]\[1\]"):
        _platform(added_mass=skew.tolist())
    negative = a.copy()
    negative[2, 2] = -1.0
    with pytest.raises(ValueError, match="negative"):
        _platform(added_mass=negative.tolist())
    point = {"matrix": a.tolist()}
    with pytest.raises(ValueError, match="rising"):
        _platform(
            added_mass_by_frequency=[point | {"frequency_hz": 0.2}, point | {"frequency_hz": 0.1}]
        )
    # a frequency's added mass may be negative (a moonpool's sloshing: the ITI barge's WAMIT
    # table), not beyond the body's own inertia (the platform's 5e6 kg here)
    sloshing = a.copy()
    sloshing[2, 2] = -4e6
    _platform(added_mass_by_frequency=[{"frequency_hz": 0.5, "matrix": sloshing.tolist()}])
    sloshing[2, 2] = -6e6
    with pytest.raises(ValueError, match="beyond the platform's own mass"):
        _platform(added_mass_by_frequency=[{"frequency_hz": 0.5, "matrix": sloshing.tolist()}])


def test_a_wamit_table_s_resonance_beyond_the_body_s_inertia_is_left_out() -> None:
    """The ITI barge's WAMIT added mass in heave falls to −3.6e7 kg near 0.55 Hz (its
    moonpool), far beyond the barge's 5.5e6 kg: no rigid body has that inertia, so those
    periods leave the table (interpolated across), and the note says so."""
    from wtvib.importers.hydrodyn import _Body, _positive_inertia

    body = _Body(5.45e6, -0.28, 7.3e8, 7.3e8, 1.4e9)
    ok = np.diag([1e6, 1e6, 3e7, 1e9, 1e9, 1e8])
    bad = ok.copy()
    bad[2, 2] = -3.6e7
    table = [
        {"frequency_hz": f, "matrix": (bad if 0.52 < f < 0.58 else ok).tolist()}
        for f in (0.1, 0.3, 0.5, 0.55, 0.57, 0.7)
    ]
    kept, note = _positive_inertia(table, body)
    assert [q["frequency_hz"] for q in kept] == [0.1, 0.3, 0.5, 0.7]
    assert "2 periods (0.55–0.57 Hz)" in note and "moonpool" in note
    assert _positive_inertia(kept, body) == (kept, "")


MAP = """\
---------------------- LINE DICTIONARY ---------------------------------------
LineType  Diam      MassDenInAir   EA            CB   CIntDamp  Ca   Cdn    Cdt
(-)       (m)       (kg/m)        (N)           (-)   (Pa-s)    (-)  (-)    (-)
main      0.09      77.7066       384.243E6     1.0   1.0E8     0.6  -1.0   0.05
---------------------- NODE PROPERTIES ---------------------------------------
Node Type       X       Y         Z        M     V       FX     FY     FZ
(-)  (-)       (m)     (m)       (m)      (kg)  (m^3)   (N)    (N)    (N)
1    Fix     853.87     0      depth       0     0       #      #      #
2    Vessel  5.2        0      -70.0       0     0       #      #      #
---------------------- LINE PROPERTIES ---------------------------------------
Line    LineType  UnstrLen   NodeAnch  NodeFair  Flags
(-)      (-)       (m)       (-)       (-)       (-)
1       main      {length}     1         2
---------------------- SOLVER OPTIONS-----------------------------------------
Option
(-)
repeat 120 240
"""


def _moorings(tmp_path: Path, text: str) -> np.ndarray:
    (tmp_path / "map.dat").write_text(text)
    (tmp_path / "t.fst").write_text(
        '------- OpenFAST\ntest deck\n1 CompMooring - moorings\n"map.dat" MooringFile - file\n'
        "320 WtrDpth - water depth\n"
    )
    k, _ = mooring.stiffness(parse(tmp_path / "t.fst"), rho=1025.0, g=G)
    return k


def test_map_moorings_are_symmetric_about_the_axis(tmp_path: Path) -> None:
    """Three lines 120° apart (the OC3 lines, the delta connection left out): equal surge
    and sway stiffness, equal roll and pitch, no surge–sway coupling; a taut line stiffer."""
    k = _moorings(tmp_path, MAP.format(length=902.2))
    assert k[0, 0] > 0 and k[0, 0] == pytest.approx(k[1, 1], rel=1e-6)
    assert k[3, 3] == pytest.approx(k[4, 4], rel=1e-6)
    assert abs(k[0, 1]) < 1e-6 * k[0, 0]
    assert _moorings(tmp_path, MAP.format(length=880.0))[0, 0] > k[0, 0]


@pytest.mark.parametrize(
    ("old", "new", "message", "line"),
    [
        ("902.2", "-5", "positive length", 13),
        ("902.2", "nan", "not a finite number", 13),
        ("Vessel", "Buoy", "not fix, vessel or connect", 9),
        ("main      0.09", "main      -0.09", "positive Diam", 4),
        ("1       main      902.2     1         2", "1  main  902.2  1", "5 columns", 13),
        ("1       main      902.2     1", "1       rope      902.2     1", "type or node", 13),
    ],
)
def test_a_bad_map_file_is_refused_at_its_line(
    tmp_path: Path, old: str, new: str, message: str, line: int
) -> None:
    text = MAP.format(length=902.2).replace(old, new)
    with pytest.raises(SpecError, match=message) as error:
        _moorings(tmp_path, text)
    assert error.value.line == line


def test_a_platform_that_capsizes_or_sinks_is_refused() -> None:
    """CM 5 m above the PRP and a pitch stiffness of 10⁸ N·m/rad: the weight's overturning
    moment g·(m·z_G + ∫μz dz + M_head·z_top) = 3.38·10⁸ N·m/rad exceeds it (written out
    here), the turbine capsizes; no heave stiffness, it sinks — said, not audited at 0 Hz."""
    stiffness = np.diag([5e4, 6e4, 1e6, 2e9, 1e8, 1e8])
    p = _platform(cm_m=5.0, stiffness=stiffness.tolist())
    mu = 7850.0 * np.pi * (4.0**2 - 3.96**2) / 4
    first = mu * (80.0**2 - 30.0**2) / 2
    expected = 1e8 - G * (p.mass_kg * 5.0 + first + 1e5 * 80.0)
    with pytest.raises(ModalError, match=r"capsizes in pitch") as error:
        _tower_on(p, youngs_pa=2.1e11)
    assert f"{expected:.3g}" in str(error.value)
    stiffness[2, 2] = 0.0
    stiffness[4, 4] = 2.2e9
    with pytest.raises(ModalError, match="sinks"):
        _tower_on(_platform(stiffness=stiffness.tolist()))


def test_platform_modes_are_compared_with_the_wave_band_as_information() -> None:
    """``tower.platform.waves``: none without a band; the modes inside a band named (their
    periods from the modes themselves), all outside said so; information either way."""
    p = _platform()
    spec = from_data(_tower_data(p))
    modes = tower.structural_modes(spec)
    assert tower.wave_check(spec, modes) is None
    periods = sorted(1 / m.frequency_hz for m in modes if tower.is_platform_mode(m.id))
    lo, hi = periods[0], periods[-1]
    clear = tower.wave_check(from_data(_tower_data(_platform(wave_periods_s=(1.0, lo * 0.9)))),
                             modes)  # fmt: skip
    assert clear is not None and clear.status == "info" and clear.numbers["inside"] == []
    assert f"all {len(periods)} platform modes outside" in clear.message
    around = (periods[1] * 0.99, periods[1] * 1.01)
    hit = tower.wave_check(from_data(_tower_data(_platform(wave_periods_s=around))), modes)
    assert hit is not None and hit.status == "info" and len(hit.numbers["inside"]) >= 1
    assert "inside the wave band" in hit.message
    named = [m for m in modes if m.id in hit.numbers["inside"]]
    assert named and all(f"({1 / m.frequency_hz:.3g} s)" in hit.message for m in named)
    assert hi > lo
    with pytest.raises(ValueError, match="shortest first"):
        _platform(wave_periods_s=(20.0, 5.0))


def test_a_platform_mode_on_a_rotor_line_is_at_most_a_warning() -> None:
    """The IEA-22 floater's heave (0.056 Hz) sits on 1P at 3.1–3.8 rpm of its 1.8–7.1 rpm
    range: with the structure's 1 % alone that would fail at DAF 50, but a platform mode's
    damping is its radiation and viscous damping, which wtvib does not model — a warning that
    says so, the verdict's worst; the tower's own bending is judged in full."""
    windio = pytest.importorskip("windIO", reason="the windio package (dev extra) is needed")
    from wtvib import audit, importers

    floater = Path(windio.__file__).parent / "examples" / "turbine" / "IEA-22-280-RWT_Floater.yaml"
    report = audit.run(importers.load(floater))
    one_p = next(c for c in report.checks if c.id == "tower.resonance.1P")
    assert one_p.status == "warn" and "tower.platform.heave" in one_p.message
    assert "at most a warn" in one_p.message
    heave = next(m for m in report.modes if m.id == "tower.platform.heave")
    assert heave.status_cap == "warn"
    assert all(m.status_cap is None for m in report.modes if m.id in ("tower.fa1", "tower.ss1"))


def test_a_tower_without_torsional_stiffness_yaws_rigidly_on_the_platform() -> None:
    """A tower given without GJ turns with its platform as one body: the yaw mode is
    √(C₆₆/(I₆₆ + A₆₆ + J_head))/2π — by hand 1e8/(3e8 + 1e8 + 5e7) here — the tower's own
    yaw inertia left out (no torsion model)."""
    data = _tower_data(_platform())
    data["tower"] = {
        "height_m": 50.0,
        "distributed": {
            "height_m": [0.0, 50.0],
            "mass_per_length_kg_m": [2000.0, 2000.0],
            "ei_fa_nm2": [1e12, 1e12],
            "ei_ss_nm2": [1e12, 1e12],
        },
        "foundation": data["tower"]["foundation"],  # type: ignore[index]
    }
    data["tower_head"] = {"mass_kg": 1e5, "cm_above_top_m": 0.0, "inertia_yaw_kgm2": 5e7}
    modes = {m.id: m for m in tower.structural_modes(from_data(data))}
    expected = np.sqrt(1e8 / (3e8 + 1e8 + 5e7)) / (2 * np.pi)
    assert modes["tower.platform.yaw"].frequency_hz == pytest.approx(expected, rel=1e-9)
