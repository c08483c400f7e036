"""ElastoDyn's mode-shape polynomials at unit level (wtvib.subsystems.polynomials): the fit, the
blade's Rayleigh–Ritz polynomial, the audit's diagnosis, the written coefficients and files.

The exact reference is the uniform cantilever (Euler–Bernoulli): its first mode
φ(x) = cosh βx − cos βx − σ(sinh βx − sin βx), βL = 1.875104, σ = (cosh βL + cos βL) /
(sinh βL + sin βL), and f = (βL)²/2π·√(EI/mL⁴) (Meirovitch, Fundamentals of Vibrations,
§8.7; β₂L = 4.694091). The real decks are in tests/validation/test_polynomials.py.
"""

import math

import numpy as np
import pytest

from wtvib.errors import SpecError
from wtvib.spec import Spec
from wtvib.subsystems import polynomials
from wtvib.subsystems.polynomials import Fit, Polynomial, Row, fit, mac, patched, written

L_TOWER, M_TOWER, EI_TOWER = 80.0, 4000.0, 2.0e11
L_BLADE, M_BLADE, EI_FLAP, EI_EDGE = 60.0, 300.0, 2.0e9, 8.0e9
BETA = (1.8751040687, 4.6940911330)


def _uniform(twist_deg: float = 0.0) -> Spec:
    """A uniform tower without head or gravity and a uniform blade (optionally twisted
    uniformly), both cantilevers."""
    blade: dict[str, object] = {
        "span_m": [0.0, L_BLADE],
        "mass_per_length_kg_m": [M_BLADE, M_BLADE],
        "ei_flap_nm2": [EI_FLAP, EI_FLAP],
        "ei_edge_nm2": [EI_EDGE, EI_EDGE],
    }
    if twist_deg:
        blade["twist_deg"] = [twist_deg, twist_deg]
    return Spec.model_validate(
        {
            "wtvib": 1,
            "turbine": {"name": "uniform"},
            "rotor": {"blades": 3, "orientation": "upwind", "hub": "rigid",
                      "speed": {"fixed_rpm": 10.0}},
            "tower": {
                "height_m": L_TOWER,
                "gravity": False,
                "distributed": {"height_m": [0.0, L_TOWER],
                                "mass_per_length_kg_m": [M_TOWER, M_TOWER],
                                "ei_fa_nm2": [EI_TOWER, EI_TOWER],
                                "ei_ss_nm2": [EI_TOWER, EI_TOWER]},
            },
            "blade": {"structure": blade},
        }
    )  # fmt: skip


def _cantilever(x: np.ndarray, n: int = 0) -> np.ndarray:
    b = BETA[n]
    s = (math.cosh(b) + math.cos(b)) / (math.sinh(b) + math.sin(b))
    phi = np.cosh(b * x) - np.cos(b * x) - s * (np.sinh(b * x) - np.sin(b * x))
    return phi / phi[-1]


def _cantilever_hz(length: float, mass: float, ei: float, n: int = 0) -> float:
    return BETA[n] ** 2 / (2 * math.pi) * math.sqrt(ei / (mass * length**4))


def test_fit_recovers_a_polynomial_of_its_own_form():
    """Samples of an exact c₂ … c₆ polynomial (summing to 1) give it back: the 4 × 4 least
    squares on 41 stations has cond ≈ 1e3, so 1e-12 of the largest coefficient holds."""
    exact = Polynomial((-44.2, 26.4, 29.8, 3.70, -14.7))
    x = np.linspace(0.0, 1.0, 41)
    got = fit(x, 2.5 * exact.value(x))  # any scale: normalised to the tip
    assert got.polynomial.c == pytest.approx(exact.c, abs=1e-12 * 44.2)
    assert sum(got.polynomial.c) == pytest.approx(1.0, abs=1e-12)
    assert got.rms < 1e-12


def test_fit_refuses_too_few_stations_and_a_tip_that_does_not_move():
    x = np.linspace(0.0, 1.0, 5)  # four stations above the root for five coefficients
    with pytest.raises(SpecError, match="five stations"):
        fit(x, x**2)
    x = np.linspace(0.0, 1.0, 11)
    with pytest.raises(SpecError, match="does not move its tip"):
        fit(x, x * (1 - x))


def test_polynomial_derivatives_are_the_analytic_ones():
    p = Polynomial((0.5, 0.0, 0.0, 0.0, 0.5))  # ½x² + ½x⁶
    x = np.array([0.0, 0.5, 1.0])
    assert p.value(x) == pytest.approx(0.5 * x**2 + 0.5 * x**6)
    assert p.slope(x) == pytest.approx(x + 3 * x**5)
    assert p.curvature(x) == pytest.approx(1 + 15 * x**4)


def test_the_uniform_cantilever_tower_mode_and_its_polynomial():
    """The finite-element first mode of the uniform tower is the analytic cantilever's:
    frequency within 1e-6 (measured 4e-9; rounding is bounded by ε·λ_max/λ₁ ≈ 1.6e-7 on
    λ for this 40-element model, half that on f), the fitted polynomial's shape MAC
    ≥ 1 − 1e-9 against the exact mode (measured 1 − 1e-11: a sixth-order polynomial
    carries it to 1.5e-6 RMS), and the frequency it implies — a Rayleigh quotient, in
    error by the square of the shape's — within 1e-6 above the exact one (measured 1e-7),
    never below it."""
    shapes = polynomials.compute(_uniform(), 0.0)
    fa1 = next(r for r in shapes.tower if r.key == "TwFAM1Sh")
    exact = _cantilever_hz(L_TOWER, M_TOWER, EI_TOWER)
    assert fa1.frequency_hz == pytest.approx(exact, rel=1e-6)
    x = np.linspace(0.0, 1.0, 201)
    assert mac(fa1.computed.polynomial.value(x), _cantilever(x)) > 1 - 1e-9
    assert fa1.computed_hz >= fa1.frequency_hz * (1 - 1e-9)
    assert fa1.computed_hz == pytest.approx(exact, rel=1e-6)
    assert fa1.deck is None and fa1.status() == "pass"  # nothing given, nothing judged


def test_an_untwisted_blades_ritz_polynomials_are_the_cantilevers():
    """Without twist, the blade's Rayleigh–Ritz polynomials in ElastoDyn's family are the
    uniform cantilever's flap and edge modes (at 0 rpm): first flap and edge within 1e-6 of
    the analytic frequency, second flap within 1e-4 (a sixth-order polynomial carries the
    second mode to 4e-4 RMS; its frequency error is the square of that)."""
    shapes = polynomials.compute(_uniform(), 0.0)
    by = {r.key: r for r in shapes.blade}
    x = np.linspace(0.0, 1.0, 201)
    for key, ei, n in (
        ("BldFl1Sh", EI_FLAP, 0),
        ("BldEdgSh", EI_EDGE, 0),
        ("BldFl2Sh", EI_FLAP, 1),
    ):
        exact = _cantilever_hz(L_BLADE, M_BLADE, ei, n)
        assert by[key].frequency_hz == pytest.approx(exact, rel=1e-6), key
        assert by[key].computed_hz == pytest.approx(exact, rel=1e-4 if n else 1e-6), key
        assert by[key].computed_hz >= by[key].frequency_hz * (1 - 1e-9), key
    assert mac(by["BldFl1Sh"].computed.polynomial.value(x), _cantilever(x)) > 1 - 1e-9


def test_the_ritz_polynomial_is_the_lowest_any_polynomial_of_its_family_implies():
    """Rayleigh's principle: on a twisted blade, no perturbation of the computed flap-1 or
    edge polynomial (its coefficients still adding to 1) implies a lower frequency. The
    least-squares fit of the out-of-plane deflection (pyBModes' way) implies a higher one."""
    spec = _uniform(twist_deg=20.0)
    shapes = polynomials.compute(spec, 12.0)
    rng = np.random.default_rng(1)
    judged = polynomials.models(spec, 12.0)
    for row in shapes.blade:
        if row.key == "BldFl2Sh":
            continue  # a saddle: the minimum only across shapes orthogonal to flap 1
        best = judged[row.key].implied(row.computed.polynomial)
        assert best == pytest.approx(row.computed_hz, rel=1e-12)
        c = np.asarray(row.computed.polynomial.c)
        for _ in range(20):
            d = rng.normal(size=5)
            d -= d.mean()  # keeps the sum at 1
            p = Polynomial(tuple(c + 1e-2 * np.abs(c).max() * d))  # type: ignore[arg-type]
            assert judged[row.key].implied(p) >= best * (1 - 1e-12), row.key
        lsq = fit(row.xs, np.asarray(row.shape)).polynomial
        assert judged[row.key].implied(lsq) >= best * (1 - 1e-12), row.key


def _row(**changes: object) -> Row:
    base = Row(
        key="TwFAM1Sh", mode="tower.fa1", frequency_hz=0.32,
        computed=Fit(Polynomial((1, 0, 0, 0, 0)), 0.0, 1.0),
        computed_hz=0.32, computed_mac=1.0, deck=Polynomial((1, 0, 0, 0, 0)), deck_hz=0.32,
        mac_deck=0.9999, mac_other=0.48, file="/d/Tower.dat", line=32, x=(0.0, 1.0),
        shape=(0.0, 1.0),
    )  # fmt: skip
    from dataclasses import replace

    return replace(base, **changes)  # type: ignore[arg-type]


@pytest.mark.parametrize(
    "changes, words",
    [
        ({}, None),
        ({"deck_hz": 0.32 * 1.019}, None),  # within STIFFER of the computed shape's
        ({"deck_hz": 0.32 * 1.021}, "not in curvature"),
        ({"mac_deck": 0.99}, "the shape of another tower or head"),
        ({"mac_deck": 0.48, "mac_other": 0.9999}, "the other mode of its plane"),
        ({"key": "TwFAM2Sh", "mode": "tower.fa2", "mac_deck": 0.96}, None),  # second: 0.95
        ({"key": "TwFAM2Sh", "mode": "tower.fa2", "mac_deck": 0.94}, "another tower or head"),
        ({"key": "BldFl1Sh", "mode": "blade.flap1", "deck_hz": 0.34}, "for another blade"),
        # judged against the computed polynomial, not the finite element: a blade whose
        # best polynomial is 3 % off its coupled mode does not make the deck's stale
        ({"frequency_hz": 0.30, "deck_hz": 0.3201}, None),
    ],
)
def test_the_diagnosis_names_what_is_wrong_with_a_deck_polynomial(changes, words):
    row = _row(**changes)
    said = row.diagnosis()
    assert (said is None) == (words is None), said
    if words:
        assert words in said and row.status() == "warn"


def test_the_written_coefficients_add_to_one_to_rounding():
    """c₆ is written as 1 less the written c₂ … c₅, itself to nine digits: the written five
    add to 1 within half a unit of c₆'s ninth digit (5e-8 for c₆ ≈ −47.7) — far inside
    ElastoDyn's 0.0015 — where rounding each of the five alone could miss by five such."""
    p = Polynomial((-144.123456789123, 73.4567891234, 122.2345678912, -2.83456789123, 0.0))
    p = Polynomial((*p.c[:4], 1.0 - sum(p.c[:4])))
    got = written(p)
    unit = 10.0 ** (math.floor(math.log10(abs(got[4]))) - 8)
    assert abs(sum(got) - 1.0) <= 0.5 * unit * (1 + 1e-6)
    assert got[:4] == tuple(float(f"{c:.9g}") for c in p.c[:4])


TOWER_TEXT = """\
------- ELASTODYN V1.00.* TOWER INPUT FILE -------------------------------------
A tower (the title line).
---------------------- TOWER FORE-AFT MODE SHAPES ------------------------------
     0.7004   TwFAM1Sh(2) - Mode 1, coefficient of x^2 term
     2.1963   TwFAM1Sh(3) -       , coefficient of x^3 term
    -5.6202   TwFAM1Sh(4) -       , coefficient of x^4 term
     6.2275   TwFAM1Sh(5) -       , coefficient of x^5 term
     -2.504   TwFAM1Sh(6) -       , coefficient of x^6 term
! a comment line that stays
"""


def test_patched_changes_the_numbers_and_nothing_else():
    new = Polynomial((0.9966, 0.1371, -0.113, 0.0597, -0.0804))
    row = _row(computed=Fit(new, 0.0, 1.0))
    out = patched(TOWER_TEXT, [row])
    before, after = TOWER_TEXT.splitlines(), out.splitlines()
    assert len(before) == len(after)
    for old, now in zip(before, after, strict=True):
        if "TwFAM1Sh(" in old:
            assert now.split()[1:] == old.split()[1:]  # key and comment as they were
            assert now.index("TwFAM1Sh") == old.index("TwFAM1Sh") or len(now.split()[0]) > 10
        else:
            assert now == old
    values = [float(ln.split()[0]) for ln in after if "TwFAM1Sh(" in ln]
    assert values == list(written(new))


def test_patched_refuses_a_file_without_the_coefficient_line():
    row = _row(key="TwSSM1Sh")
    with pytest.raises(SpecError, match=r"no TwSSM1Sh\(2\) line"):
        patched(TOWER_TEXT, [row])


# ------------------------------------------------------------------------------------------
# Bad input and the command: one line naming file, line and field, exit 2

TOWER = "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat"
MAIN = "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"


def _run(*args: str):  # type: ignore[no-untyped-def]
    from typer.testing import CliRunner

    from wtvib.cli import app

    return CliRunner().invoke(app, list(args))


@pytest.mark.parametrize(
    "old, new, where",
    [
        # the set that does not add to 1, at its first coefficient's line
        (
            "     -2.504   TwFAM1Sh(6)",
            "     -2.404   TwFAM1Sh(6)",
            f"{TOWER}:32: TwFAM1Sh: its coefficients add to 1.1",
        ),
        (
            "    -5.6202   TwFAM1Sh(4)",
            "        NaN   TwFAM1Sh(4)",
            f"{TOWER}:34: TwFAM1Sh(4) must be a finite number",
        ),
        (
            "   -176.513   TwFAM2Sh(5) -       , coefficient of x^5 term\n",
            "",
            f"{TOWER}: TwFAM2Sh(5) is missing",
        ),
        (
            "4.0000000E-01  4.2277500E+03  3.4188300E+11",
            "4.0000000E-01  4.2277500E+03  0.0",
            f"{TOWER}:24: TwFAStif must be positive (got 0 at HtFract 0.4)",
        ),
        ("          1   AdjFASt", "         -1   AdjFASt", f"{TOWER}:15: AdjFASt must be positive"),
    ],
    ids=["sum", "nan", "missing-line", "zero-stiffness", "negative-factor"],
)
@pytest.mark.parametrize("command", ["shapes", "check"])
def test_a_bad_tower_file_is_one_line_naming_file_line_and_field(
    shared, tmp_path, old, new, where, command
):
    from tests.conftest import edited_reference

    folder = edited_reference(shared, tmp_path, "NREL5MW", TOWER, old, new)
    result = _run(command, str(folder / MAIN), "--no-plots")
    assert result.exit_code == 2, result.output
    lines = [ln for ln in result.output.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: ") and where in lines[0], lines


def test_a_one_station_tower_is_uniform_and_still_gets_its_shapes(shared, tmp_path):
    """ElastoDyn takes NTwInpSt = 1 as a uniform tower; the polynomials are fitted to the
    finite-element mode at its 41 nodes, not at the file's stations, so a file with too
    few stations for a sixth-order fit of its own still gets one (pyBModes, which fits at
    the stations, could not)."""
    from tests.conftest import edited_reference

    text = (shared / "reference" / "NREL5MW" / TOWER).read_text()
    start = text.index("1.0000000E-01  5.2324300E+03")
    end = text.index("---", start)
    folder = edited_reference(shared, tmp_path, "NREL5MW", TOWER, text[start:end], "")
    path = folder / TOWER
    path.write_text(path.read_text().replace("         11   NTwInpSt", "          1   NTwInpSt"))
    result = _run("shapes", str(folder / MAIN), "--format", "json", "--no-plots")
    assert result.exit_code == 0, result.output
    import json

    doc = json.loads(result.output)
    assert [r["name"] for r in doc["tower"]] == ["TwFAM1Sh", "TwFAM2Sh", "TwSSM1Sh", "TwSSM2Sh"]
    assert all(r["fit_rms"] < 0.01 for r in doc["tower"])


def test_shapes_writes_beside_never_over_the_deck(shared, tmp_path):
    import shutil

    folder = tmp_path / "NREL5MW"
    shutil.copytree(shared / "reference" / "NREL5MW", folder)
    before = {p.name: p.read_bytes() for p in folder.iterdir() if p.is_file()}
    result = _run("shapes", str(folder / MAIN), "-o", str(folder), "--force")
    assert result.exit_code == 2 and "is the deck's own file" in result.output, result.output
    assert {p.name: p.read_bytes() for p in folder.iterdir() if p.is_file()} == before
    out = tmp_path / "out"
    result = _run("shapes", str(folder / MAIN), "-o", str(out))
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in out.iterdir()) == sorted(
        [TOWER, "NRELOffshrBsline5MW_Blade.dat", "NRELOffshrBsline5MW_Onshore_ElastoDyn.shapes.png"]
    )
    # the originals' text line for line, only the coefficients' numbers changed
    for name in (TOWER, "NRELOffshrBsline5MW_Blade.dat"):
        old, new = (folder / name).read_text().splitlines(), (out / name).read_text().splitlines()
        assert len(old) == len(new)
        changed = [(a, b) for a, b in zip(old, new, strict=True) if a != b]
        assert changed and all(a.split()[1:] == b.split()[1:] for a, b in changed)
        assert all(a.split()[1][:2] in ("Tw", "Bl") and "Sh(" in a.split()[1] for a, _ in changed)
    again = _run("shapes", str(folder / MAIN), "-o", str(out))
    assert again.exit_code != 0 and "--force" in again.output  # no output over an output


def test_shapes_refuses_what_is_not_an_elastodyn_deck(tmp_path, write_spec):
    result = _run("shapes", str(write_spec()))
    assert result.exit_code == 2 and "not an ElastoDyn deck" in result.output
