"""Other tools' Campbell results read, transformed and named against the values their own
tests state (tests/data/campbell/SOURCES.md)."""

from pathlib import Path

import numpy as np
import pytest

from tests.tolerances import frequency_and_damping_bounds, root_bounds
from wtvib import audit, importers
from wtvib.importers import openfast_lin

DATA = Path(__file__).resolve().parents[1] / "data" / "campbell"


def test_openfast_mbc3_matches_openfast_toolbox():
    """NREL 5-MW at 3 m/s, three azimuths: MBC3 through wtvib's Coleman transformation gives
    openfast_toolbox's first three modes (test_mbc3_ED_Azi3: 0.31402747, 0.33140717,
    0.6263423 Hz; 0.43860177, 6.03443072, 2.48116647 % damping), named tower side-side,
    tower fore-aft (aerodynamically damped) and drive train (Jonkman et al. 2009 Table 9-1
    at standstill: 0.312, 0.324, 0.6205 Hz)."""
    files = openfast_lin.files_of(DATA / "openfast" / "ws03.0.1.lin")["ws03.0"]
    assert len(files) == 3
    lins = [openfast_lin.read(p) for p in files]
    pm, blades = openfast_lin.operating_point(lins)
    assert blades == 3
    # to 1e-7 Hz: the toolbox's own test values differ from this MBC3 by up to 7.6e-8 Hz
    # (the drive-train mode: a difference of method, the same on any machine), plus what
    # rounding may do to each root on any machine (tolerances.py: ~2e-12 Hz here)
    lay = openfast_lin.layout(lins[0].states, lins[0].path, lins[0].rotor_speed, lins[0].a)
    f, df, _, _ = frequency_and_damping_bounds(*root_bounds(openfast_lin.mbc_average(lins, lay)))
    for got, want in zip(pm.frequency_hz[:3], [0.31402747, 0.33140717, 0.6263423], strict=True):
        assert abs(got - want) <= 1e-7 + df[np.argmin(np.abs(f - want))], want
    np.testing.assert_allclose(
        100 * pm.damping_ratio[:3], [0.43860177, 6.03443072, 2.48116647], atol=5e-4
    )
    assert pm.names[:3] == ("tower.ss1", "tower.fa1", "drivetrain1")


def test_openfast_cyclic_modes_split_into_backward_and_forward_whirl():
    """Exact for an isotropic rotor: the fixed-frame pair of a cyclic blade mode of
    rotating-frame frequency f_R sits at f_R ∓ Ω/2π (backward below, forward above); the
    first edgewise pair is lightly damped, so its mean is f_R and its split 2·Ω/2π to the
    accuracy of the aerodynamic coupling."""
    files = openfast_lin.files_of(DATA / "openfast")["ws03.0"]
    pm, _ = openfast_lin.operating_point([openfast_lin.read(p) for p in files])
    f = dict(zip(pm.names, pm.frequency_hz, strict=True))
    rev = pm.rpm / 60
    assert f["blade.edge1.backward"] < f["blade.edge1.forward"]
    assert f["blade.flap1.backward"] < f["blade.flap1.forward"]
    split = f["blade.edge1.forward"] - f["blade.edge1.backward"]
    assert split == pytest.approx(2 * rev, rel=0.1)


def test_hawcstab2_blade_modes_named_as_casetoolbox_names_them():
    """DTU 10 MW blade, HAWCStab2: the .amp names the .cmb's modes 1F, 1E, 2F, 2E, 3F, 3E, 4F,
    1T, 5F as CASEToolBox's comparison does; the standstill frequencies are the .cmb's first
    row (0.610448, 0.930865, 1.73908 Hz)."""
    s = importers.load(
        DATA / "hawcstab2" / "blade.cmb", importers.ReadOptions(blades=3, rpm=(6.0, 9.6))
    )
    modes = [m for m in audit.run(s).modes if m.origin == "imported"]
    names = [m.id for m in modes]
    expected = ["flap1", "edge1", "flap2", "edge2", "flap3", "edge3", "flap4", "tor1", "flap5"]
    assert names[:9] == [f"blade.{n}" for n in expected]
    assert [m.frequency_hz for m in modes[:3]] == pytest.approx([0.610448, 0.930865, 1.73908])
    assert all(m.subsystem == "blade" for m in modes)  # a blade analysis: rotating frame


def test_hawcstab2_rated_points_merge_and_speeds_come_from_the_pwr():
    """The steady-state .cmb is over wind speed: the .pwr of the same name gives the rotor
    speed (6–9.6 rpm); the points above rated share 9.6 rpm and merge into one (mean
    frequency, lowest damping), said in the assumptions."""
    s = importers.load(DATA / "hawcstab2" / "steady.cmb", importers.ReadOptions(blades=3))
    assert s.rotor.speed.min_rpm == pytest.approx(6.0)
    assert s.rotor.speed.max_rpm == pytest.approx(9.6)
    assert s.results is not None
    assert str(DATA / "hawcstab2" / "steady.pwr") in s.results.files
    flap = s.results.modes["flap1"]
    assert len(set(flap.rpm)) == len(flap.rpm)
    assert any("merged per mode" in a for a in s.assumptions)


def test_openfast_modes_are_followed_across_operating_points_by_shape(tmp_path):
    """Two operating points — the 3 m/s files and the same files at a rotor speed 10 %
    higher (Ω enters the transformation's Ṫ terms, so the shapes move a little): every mode
    named at the slower point is followed to the faster one (MAC near 1, no warning), and
    its frequency moves by far less than the spacing of the modes."""
    src = DATA / "openfast"
    for p in sorted(src.glob("ws03.0.*.lin")):
        (tmp_path / p.name).write_text(p.read_text())
        text = p.read_text().replace("0.7301 rad/s", "0.8031 rad/s")
        (tmp_path / p.name.replace("ws03.0", "ws03.5")).write_text(text)
    s = importers.load(tmp_path)
    assert s.results is not None and len(s.results.files) == 6
    assert not [w for w in s.warnings if "MAC" in w]
    for name, m in s.results.modes.items():
        assert len(m.rpm) == 2, name
        assert abs(m.frequency_hz[1] / m.frequency_hz[0] - 1) < 0.05, name


def _iea15_hawcstab2(folder: Path) -> Path:
    import gzip

    for gz in (DATA / "hawcstab2" / "iea15").glob("*.gz"):
        (folder / gz.name.removesuffix(".gz")).write_bytes(gzip.decompress(gz.read_bytes()))
    return folder


@pytest.mark.parametrize("run", ["structural", "aeroelastic"])
def test_the_public_iea15_hawcstab2_example_audits(run, tmp_path):
    """The IEA-15 HAWCStab2 example as HAWCStab2 wrote it (DLR-AE/CampbellViewer): its mode 1
    has frequency 0 at every wind — HAWCStab2's mark for a mode it did not find (the drive
    train turning freely) — and was refused as "frequency 0 Hz"; its mode 4 is damped past
    critical. Both are left out and said; the operational data come from the folder's only
    .opt, whose name is not the .cmb's. The modes are named from the .amp: the tower's
    fore-aft (mode 2, tower-top y) and side-side (mode 3, x) first, then the first flap
    modes backward < collective < forward, each frequency the .cmb's own."""
    folder = _iea15_hawcstab2(tmp_path)
    s = importers.load(folder / f"{run}_entire_turbine.cmb", importers.ReadOptions(blades=3))
    assert s.results is not None
    modes = s.results.modes
    assert str(folder / "operation_1_25_windspeed.opt") in s.results.files
    assert len(modes) == 58 + (run == "structural")  # 60, less mode 1 (and 4, aeroelastic)
    said = " ".join(s.assumptions)
    assert "mode 1 (no frequency at every point)" in said
    first = sorted(modes, key=lambda n: modes[n].frequency_hz[0])[:2]
    assert set(first) == {"tower.fa1", "tower.ss1"}
    assert "(mode 2)" in modes["tower.fa1"].description
    assert "(mode 3)" in modes["tower.ss1"].description
    flap = [
        modes[f"blade.flap1.{w}"].frequency_hz[0] for w in ("backward", "collective", "forward")
    ]
    assert flap == sorted(flap)
    # the first point: the winds at the lowest rotor speed (5 rpm, from the .opt) merged —
    # the mean of the .cmb's own frequencies there (its modes 2 and 4)
    table = np.loadtxt(folder / f"{run}_entire_turbine.cmb", skiprows=1)
    opt = np.loadtxt(folder / "operation_1_25_windspeed.opt", skiprows=1)
    low = np.isclose(np.interp(table[:, 0], opt[:, 0], opt[:, 2]), 5.0)
    assert modes["tower.fa1"].frequency_hz[0] == pytest.approx(table[low, 2].mean(), rel=1e-9)
    if run == "structural":
        assert modes["blade.flap1.backward"].frequency_hz[0] == pytest.approx(
            table[low, 4].mean(), rel=1e-9
        )
    report = audit.run(s)
    assert report.verdict in ("pass", "warn", "fail") and report.findings


def test_hawcstab2_damping_in_operation_is_the_aeroelastic_runs(tmp_path):
    """The same tower fore-aft mode: 0.1 % damped in the structural run, several per cent
    with the rotor's aerodynamics — the aeroelastic run's own, the lowest of the winds
    merged at 5 rpm (the .cmb's mode 2, % of critical)."""
    folder = _iea15_hawcstab2(tmp_path)
    st = importers.load(
        folder / "structural_entire_turbine.cmb", importers.ReadOptions(blades=3)
    ).results
    ae = importers.load(
        folder / "aeroelastic_entire_turbine.cmb", importers.ReadOptions(blades=3)
    ).results
    assert st is not None and ae is not None
    assert st.modes["tower.fa1"].damping_ratio is not None
    assert ae.modes["tower.fa1"].damping_ratio is not None
    assert st.modes["tower.fa1"].damping_ratio[0] < 0.002
    table = np.loadtxt(folder / "aeroelastic_entire_turbine.cmb", skiprows=1)
    opt = np.loadtxt(folder / "operation_1_25_windspeed.opt", skiprows=1)
    low = np.isclose(np.interp(table[:, 0], opt[:, 0], opt[:, 2]), 5.0)
    assert 100 * ae.modes["tower.fa1"].damping_ratio[0] == pytest.approx(
        table[low, 62].min(), abs=1e-9
    )


def test_hawcstab2_columns_are_followed_by_what_they_move(tmp_path):
    """HAWCStab2 numbers a point's modes by frequency, so where two cross a column changes
    mode: the IEA-15 example's column 6 moves the first flap forward whirl at 5 rpm (its
    .amp: forward flap tip 1, backward edge 0.13) and the first edge backward whirl from
    6.4 rpm on, column 7 the other way round. Followed by what they move, blade.flap1.forward
    is column 6 at 5 rpm (0.5715 Hz, the .cmb's) and column 7 at 7.56 rpm, rising with the
    rotor speed as a forward whirl does; blade.edge1.backward the reverse, falling."""
    folder = _iea15_hawcstab2(tmp_path)
    cmb = folder / "structural_entire_turbine.cmb"
    modes = importers.load(cmb, importers.ReadOptions(blades=3)).results.modes
    table = np.loadtxt(cmb, skiprows=1)
    opt = np.loadtxt(folder / "operation_1_25_windspeed.opt", skiprows=1)
    rpm = np.interp(table[:, 0], opt[:, 0], opt[:, 2])
    # the points at one rotor speed merge to their mean (5 rpm: 1-7 m/s; 7.56: 11-25 m/s)
    first, last = table[rpm == rpm.min()].mean(axis=0), table[rpm == rpm.max()].mean(axis=0)
    forward, backward = modes["blade.flap1.forward"], modes["blade.edge1.backward"]
    assert forward.frequency_hz[0] == pytest.approx(first[6], rel=1e-9)
    assert backward.frequency_hz[0] == pytest.approx(first[7], rel=1e-9)
    assert forward.frequency_hz[-1] == pytest.approx(last[7], rel=1e-9)
    assert backward.frequency_hz[-1] == pytest.approx(last[6], rel=1e-9)
    assert forward.frequency_hz[-1] > forward.frequency_hz[0]
    assert backward.frequency_hz[-1] < backward.frequency_hz[0]


def test_following_swaps_columns_that_swap_modes_and_never_jumps_family():
    """Three columns at two points: the first two trade what they move (their frequencies
    cross), the third moves what the first does at four times its frequency — followed,
    the first two swap and the third keeps its own; two columns that move the same sensors
    and trade places are followed by frequency."""
    from wtvib.importers.hawcstab2 import followed

    flap, edge = [1.0, 0.1], [0.1, 1.0]
    amplitudes = np.array([[flap, edge, flap], [edge, flap, flap]])
    freq = np.array([[0.57, 0.61, 2.4], [0.59, 0.60, 2.4]])
    assert followed(amplitudes, freq).tolist() == [[0, 1, 2], [1, 0, 2]]
    alike = np.array([[flap, edge, flap], [flap, edge, flap]])
    assert followed(alike, freq).tolist() == [[0, 1, 2], [0, 1, 2]]
    # two that move the same sensors and trade columns: told apart by their frequencies
    moved = np.array([[0.9, 0.6, 3.6], [3.7, 0.6, 0.95]])
    assert followed(alike, moved).tolist() == [[0, 1, 2], [2, 1, 0]]


def test_hawcstab2_modes_without_an_amp_file_keep_their_column_numbers(tmp_path):
    """Without the .amp beside it, the .cmb's modes are named by their column — mode1 is
    HAWCStab2's mode 1 with its frequencies — and the audit says that they are unnamed."""
    for name in ("steady.cmb", "steady.pwr"):
        (tmp_path / name).write_bytes((DATA / "hawcstab2" / name).read_bytes())
    s = importers.load(tmp_path / "steady.cmb", importers.ReadOptions(blades=3))
    table = np.loadtxt(tmp_path / "steady.cmb", skiprows=1)
    pwr = np.loadtxt(tmp_path / "steady.pwr")
    rpm = np.interp(table[:, 0], pwr[:, 0], pwr[:, 9])
    first = table[rpm == rpm.min()].mean(axis=0)  # the points at the lowest speed, merged
    modes = s.results.modes
    assert modes["mode1"].frequency_hz[0] == pytest.approx(first[1], rel=1e-9)
    assert modes["mode3"].frequency_hz[0] == pytest.approx(first[3], rel=1e-9)
    assert modes["mode3"].description == "HAWCStab2 mode 3 (mode 3)"
    assert any("the modes are not named" in w for w in s.warnings)
