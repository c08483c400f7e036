"""Dynamic stall: the separation point's lag of the lift (wtvib/numerics/unsteady.py), against
its definitions and a closed form, then a deck set against OpenFAST's linearisation of it.

Definitions (AeroDyn theory manual, "Unsteady Aerodynamics", notations and Øye's model;
Hansen, Gaunaa & Madsen, Risø-R-1354, 2004): Kirchhoff's flat-plate separation
C_L = C_Lα(α − α₀)·((1 + √f)/2)², the fully separated lift C_fs = (C_L − C_inv·f)/(1 − f),
the dynamic lift f·C_inv + (1 − f)·C_fs with f lagging f_st by T_f = T_f0·c/(2W).
"""

import math

import numpy as np
import pytest

from wtvib.numerics import unsteady

#: The test polar: C_Lα = 2π/rad, α₀ = −2.1° (between the table's points), attached to 7°
#: above α₀ (and below), then the separation function falls as a cosine to nothing 20°
#: further.
SLOPE, ALPHA0, ATTACHED, FALL = 2 * math.pi, -2.1, 7.0, 20.0


def _kirchhoff(alpha_deg: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The test polar's separation function and its Kirchhoff lift, both analytic."""
    d = np.abs(alpha_deg - ALPHA0)
    t = np.clip((d - ATTACHED) / FALL, 0.0, 1.0)
    f = np.cos(0.5 * math.pi * t) ** 2
    lift = SLOPE * np.radians(alpha_deg - ALPHA0) * ((1 + np.sqrt(f)) / 2) ** 2
    return f, lift


def test_kirchhoffs_separation_is_read_back_from_its_polar():
    """From a polar built on a known separation function: the zero-lift angle, the inviscid
    slope (the steepest secant within 10° of α₀, which is the attached flow's slope) and
    f_st at every angle to rounding, 0 from the first full separation on."""
    grid = np.arange(-180.0, 180.0 + 1e-9, 0.25)
    f, lift = _kirchhoff(grid)
    table, alpha0, slope = unsteady.separation_table(grid, lift[None, :])
    assert alpha0[0] == pytest.approx(ALPHA0, abs=1e-9)
    assert math.degrees(1) * slope[0] == pytest.approx(SLOPE, rel=1e-9)
    assert np.abs(table[0] - f).max() < 1e-6
    # past the first full separation the flow stays separated, though a deep-stall lift
    # (a flat plate's, here half the inviscid line) would read as partly attached; a lift
    # above the inviscid line beyond the linear range is attached flow, f = 1, not more
    d = grid - ALPHA0
    deep = np.where(np.abs(d) > 35, 0.5 * SLOPE * np.radians(d), lift)
    table, _, _ = unsteady.separation_table(grid, deep[None, :])
    assert np.all(table[0][np.abs(d) > 27] == 0)
    above = np.where(np.abs(d) > 12, 1.2 * SLOPE * np.radians(d), lift)
    table, _, _ = unsteady.separation_table(grid, above[None, :])
    assert table[0].max() == 1 and np.all(table[0][np.abs(d) > 12] == 1)
    # a cylinder (no lift) has no separation dynamics
    none, _, flat = unsteady.separation_table(grid, np.zeros((1, len(grid))))
    assert flat[0] == 0 and np.all(none == 1)


@pytest.mark.parametrize("alpha", [8.0, 12.0, 16.0, 20.0, -14.0])
def test_the_lagged_slope_is_the_separation_points_share(alpha):
    """L = C_inv·(3 + √f)/(4(1 + √f))·f′ is (C_inv − C_fs)·f′ with C_fs from its definition,
    and the steady slope less L is the slope at a frozen separation point,
    f·C_Lα + (1 − f)·C_fs′ — each side by central differences of the analytic polar."""
    h = 1e-4  # [deg]

    def parts(a: float) -> tuple[float, float, float]:
        f, cl = _kirchhoff(np.array([a]))
        inviscid = SLOPE * math.radians(a - ALPHA0)
        fs = (cl[0] - inviscid * f[0]) / (1 - f[0])
        return float(f[0]), float(cl[0]), float(fs)

    f, _, fs = parts(alpha)
    (f_up, cl_up, fs_up), (f_dn, cl_dn, fs_dn) = parts(alpha + h), parts(alpha - h)
    per_rad = math.degrees(1) / (2 * h)
    df, dcl, dfs = (f_up - f_dn) * per_rad, (cl_up - cl_dn) * per_rad, (fs_up - fs_dn) * per_rad
    inviscid = SLOPE * math.radians(alpha - ALPHA0)
    lagged = float(unsteady.separated_slope(np.array(inviscid), np.array(f), np.array(df)))
    assert lagged == pytest.approx((inviscid - fs) * df, rel=1e-6)
    assert dcl - lagged == pytest.approx(f * SLOPE + (1 - f) * dfs, rel=1e-5)
    assert lagged < 0 < dcl - lagged  # past stall: the lagged part the negative one


def test_the_separation_lag_is_a_first_order_filter():
    """One mode, no shed wake (Øye), the lift's separated part through one pole at 1/T_f:
    the root is the cubic's (m s² + c₀ s + k)(s + β) + l_sep·β·s = 0 (c₀ the immediate
    damping; np.roots, independent of wtvib's state matrix). Past stall (quasi-steady ζ
    −1 %, the lift slope negative) the lag damps the mode: ζ rises from the quasi-steady
    value towards the frozen separation point's (+5 %) as ωT_f grows."""
    m, omega = 2.5, 2 * math.pi
    quasi, frozen = -0.01, 0.05
    lift = 2 * quasi * omega * m  # the whole lift slope's damping coefficient
    fast = 2 * frozen * omega * m  # its part at a frozen separation point
    separated = lift - fast
    zetas = []
    for w_t in (0.01, 0.3, 1.0, 3.0, 100.0):
        beta = omega / w_t
        root = unsteady.single_mode_roots(
            m, m * omega**2, 0.0, lift, 1.0, separated, beta, shed_wake=False
        )
        cubic = np.roots(
            np.polymul([m, fast, m * omega**2], [1.0, beta]) + np.array([0, 0, separated * beta, 0])
        )
        near = cubic[np.argmin(np.abs(cubic - root))]
        assert root == pytest.approx(near, rel=1e-9)
        zetas.append(-root.real / abs(root))
    assert zetas[0] == pytest.approx(quasi, abs=2e-4)
    assert zetas[-1] == pytest.approx(frozen, abs=2e-4)
    assert np.all(np.diff(zetas) > 0)


@pytest.mark.parametrize(("k", "w_t"), [(0.05, 0.3), (0.1, 1.0), (0.3, 3.0)])
def test_behind_the_shed_wake_the_separation_sees_the_effective_angle(k, w_t):
    """A Beddoes–Leishman section (shed wake and separation): the separation point follows
    the shed wake's effective angle of attack, so the separated part of the lift goes
    through both lags, C(s̄)/(1 + s·T_f), the attached part through Jones's C(s̄) alone. A
    lightly damped mode's ζ is then Re[l_att·C(ik) + l_sep·C(ik)/(1 + iωT_f)]/(2mω) — the
    p-k result, exact as ζ → 0 (the frequency-domain sum, independent of the state matrix)
    — within 1 %; with the separated part lagged by its pole alone (no shed wake before
    it) the sum would differ by the shed wake's deficiency on it, which the test tells."""
    m, omega = 3.0, 2 * math.pi
    zeta_att, zeta_sep = 0.004, -0.003  # stall: the separated part of the slope negative
    att, sep = 2 * zeta_att * omega * m, 2 * zeta_sep * omega * m
    kappa, beta = omega / k, omega / w_t
    root = unsteady.single_mode_roots(m, m * omega**2, 0.0, att + sep, kappa, sep, beta)
    jones = unsteady.lift_deficiency(np.array(1j * k))
    series = att * jones + sep * jones / (1 + 1j * w_t)
    expected = float(series.real) / (2 * m * omega)
    alone = float((att * jones + sep / (1 + 1j * w_t)).real) / (2 * m * omega)
    zeta = -root.real / abs(root)
    assert zeta == pytest.approx(expected, rel=0.01)
    assert abs(alone - expected) > 0.03 * abs(expected)


def test_a_separation_time_of_nothing_is_no_lag(tmp_path):
    """An aerofoil whose separation follows at once (T_f0 = 0: the UAE VI deck's cylinder)
    lags nothing: the catalogue's stall rotor with dynamic stall and every separation time 0
    damps its modes as without dynamic stall, to rounding (the lag states it keeps carry no
    force)."""
    import numpy as np

    from tests.conftest import TURBINES
    from wtvib import audit, importers

    text = (TURBINES / "stall-rotor-1mw.yaml").read_text()
    anchor = "  airfoils:\n    foil:"
    assert anchor in text
    totals = []
    for extra in ("", "  dynamic_stall: true\n"):
        body = text.replace(anchor, extra + anchor)
        if extra:
            body = body.replace("    foil:  #", "    foil:\n      separation_time: 0  #", 1)
        path = tmp_path / f"s{len(totals)}.yaml"
        path.write_text(body)
        spec = importers.load(path)
        assert spec.aerodynamics is not None
        assert spec.aerodynamics.dynamic_stall is bool(extra)
        assert spec.aerodynamics.airfoils["foil"].separation_time == (0 if extra else 3)
        modes = audit.run(spec).modes
        totals.append({m.id: np.asarray(m.operating.total) for m in modes if m.operating})
    assert totals[0].keys() == totals[1].keys() and totals[0]
    for key, off in totals[0].items():
        np.testing.assert_allclose(totals[1][key], off, atol=1e-9, err_msg=key)
