"""Monopile foundations (wtvib.subsystems.soil) against closed forms.

Exact: a beam on a Winkler foundation of constant modulus k [N/m²] (Hetényi, Beams on
Elastic Foundation, 1946, ch. 2: semi-infinite beam loaded at its end), head stiffness in
the tower's convention (z up): K_L = 4EIβ³, K_LR = −2EIβ², K_R = 2EIβ, β = (k/4EI)^¼ — for
a pile many times longer than 1/β; a pile much stiffer than its soil moves as a rigid body:
K_L = kL, K_LR = −kL²/2, K_R = kL³/3 (the springs' energy ½∫k(u₀ + θ₀z)² dz).
"""

import math
from typing import Any

import pytest

from wtvib import audit, spec
from wtvib.spec.tower import Pile, SoilLayer
from wtvib.subsystems import soil, tower

E = 2.1e11


def pile(length: float, d: float = 6.0, t: float = 0.06) -> Pile:
    return Pile(embedded_length_m=length, diameter_m=d, wall_thickness_m=t, youngs_modulus_pa=E)


def uniform(k: float, bottom: float) -> list[SoilLayer]:
    return [SoilLayer(bottom_m=bottom, kind="modulus", modulus_pa=k)]


def test_a_long_pile_gives_hetenyis_semi_infinite_beam():
    p, k = pile(80.0, d=2.0, t=0.02), 2.0e7
    ei = E * math.pi / 64 * (2.0**4 - 1.96**4)
    beta = (k / (4 * ei)) ** 0.25
    assert 80.0 * beta > 8  # long: the far end does not matter
    h = soil.head_stiffness(p, uniform(k, 80.0), elements=120)
    assert h.lateral == pytest.approx(4 * ei * beta**3, rel=2e-3)
    assert h.coupling == pytest.approx(-2 * ei * beta**2, rel=2e-3)
    assert h.rocking == pytest.approx(2 * ei * beta, rel=2e-3)


def test_a_stiff_short_pile_moves_as_a_rigid_body():
    p, k, length = pile(5.0, d=8.0, t=0.3), 1.0e6, 5.0
    h = soil.head_stiffness(p, uniform(k, length))
    assert h.lateral == pytest.approx(k * length, rel=1e-4)
    assert h.coupling == pytest.approx(-k * length**2 / 2, rel=1e-4)
    assert h.rocking == pytest.approx(k * length**3 / 3, rel=1e-4)


def _lumped(
    length: float, k: float, step: float, ei: float, rotation: float = 0.0, coupling: float = 0.0
) -> tuple[Any, ...]:
    """A uniform pile (z up, head at z = 0) on springs k·step (lateral) and rotation·step
    (rocking) at nodes ``step`` apart (half at its ends), as SubDyn's reaction joints with
    their SSI files hold one, condensed to its head (importers.subdyn._condensed)."""
    import numpy as np

    from wtvib.importers import subdyn

    at = np.linspace(-length, 0.0, round(length / step) + 1)
    n = len(at)
    stations = (at, np.full(n, 1e4), np.full(n, ei), np.full(n, 0.8 * ei), np.full(n, 1e3))
    springs = np.zeros((n, 4))
    springs[:, 0] = k * step
    springs[:, 1] = rotation * step
    springs[:, 2] = coupling * step
    springs[[0, -1], :3] = springs[[0, -1], :3] / 2
    springs[:, 3] = 1e8 * step
    return subdyn._condensed(at, stations, springs, "test")


def test_springs_along_a_pile_are_hetenyis_beam_and_the_soil_model_s():
    """A SubDyn monopile on a reaction joint with its SSI file every 0.5 m of its embedded
    length (OWI-Lab's FOOS IEA-10), condensed to the mudline: a long uniform pile on
    springs k·Δ is Hetényi's semi-infinite beam within 1e-3 (measured 1e-4), and wtvib's
    soil model of the same pile on the continuous modulus k (subsystems.soil.head_stiffness,
    validated above and against pyBModes) within 2e-3 — three computations, one head."""
    p, k = pile(80.0, d=2.0, t=0.02), 2.0e7
    ei = E * math.pi / 64 * (2.0**4 - 1.96**4)
    beta = (k / (4 * ei)) ** 0.25
    (lateral, rocking, coupling, _), _ = _lumped(80.0, k, 0.5, ei)
    assert lateral == pytest.approx(4 * ei * beta**3, rel=1e-3)
    assert coupling == pytest.approx(-2 * ei * beta**2, rel=1e-3)
    assert rocking == pytest.approx(2 * ei * beta, rel=1e-3)
    h = soil.head_stiffness(p, uniform(k, 80.0), elements=120)
    assert (lateral, coupling, rocking) == pytest.approx(
        (h.lateral, h.coupling, h.rocking), rel=2e-3
    )


def test_rotational_and_coupling_springs_along_a_stiff_pile():
    """PISA's distributed moment springs (the FOOS IEA-10's Ktyty at every reaction joint)
    and an SSI file's coupling Kxty: a pile much stiffer than its soil moves as a rigid
    body (w = u₀ + θz below its head, z < 0), the springs' energy ½∫(k w² + 2c w θ + k_θ θ²)
    dz gives K_L = kL, K_LR = −kL²/2 + cL, K_R = kL³/3 + k_θL − cL² (within 1e-3: the
    springs lumped every 10 cm; measured 3e-5)."""
    ei = E * math.pi / 64 * (8.0**4 - 7.4**4)
    k, k_theta, c, length = 1.0e6, 4.0e7, 2.0e6, 5.0
    (lateral, rocking, coupling, _), _ = _lumped(length, k, 0.1, ei, rotation=k_theta, coupling=c)
    assert lateral == pytest.approx(k * length, rel=1e-3)
    assert coupling == pytest.approx(-k * length**2 / 2 + c * length, rel=1e-3)
    assert rocking == pytest.approx(k * length**3 / 3 + k_theta * length - c * length**2, rel=1e-3)


def test_sand_modulus_grows_linearly_with_depth_at_the_api_rate():
    """Sand: E_py = k(φ′)·z; the fit of the API/DNV curve gives 21 MN/m³ at φ′ = 35°."""
    assert soil.sand_subgrade_n_m3(35.0) == pytest.approx(21.0e6, rel=2e-3)
    layers = [SoilLayer(bottom_m=40.0, kind="sand", friction_angle_deg=35.0)]
    import numpy as np

    z = np.array([1.0, 10.0, 30.0])
    assert soil.modulus(layers, z) == pytest.approx(21.0e6 * z, rel=2e-3)


def iea15_windio() -> Any:
    """The IEA-15-240-RWT windIO 2.x example of the windio package (skips without it)."""
    from pathlib import Path

    windio = pytest.importorskip("windIO", reason="the windio package (dev extra) is needed")
    return Path(windio.__file__).parent / "examples" / "turbine" / "IEA-15-240-RWT.yaml"


def monopile_turbine(kind: str = "soil") -> spec.Spec:
    foundation = (
        {
            "kind": "soil",
            "pile": {"embedded_length_m": 45, "diameter_m": 10, "wall_thickness_m": 0.09},
            "soil": [{"bottom_m": 60, "kind": "sand", "friction_angle_deg": 35}],
        }
        if kind == "soil"
        else {"kind": "clamped"}
    )
    return spec.from_data(
        {
            "wtvib": 1,
            "turbine": {"name": "monopile", "rotor_diameter_m": 240},
            "rotor": {
                "blades": 3,
                "orientation": "upwind",
                "hub": "rigid",
                "speed": {"min_rpm": 5.0, "max_rpm": 7.56},
            },
            "tower": {
                "sections": {
                    "height_m": [0, 30, 145],
                    "outer_diameter_m": [10, 10, 6.5],
                    "wall_thickness_m": [0.06, 0.05, 0.025],
                },
                "material": {"youngs_modulus_pa": 2.0e11, "density_kg_m3": 7800},
                "foundation": foundation,
            },
            "tower_head": {"mass_kg": 1.017e6, "cm_above_top_m": 4.0},
        }
    )


def test_soil_lowers_the_tower_and_its_bounds_bracket_it():
    """The same tower clamped (an upper bound, what wtvib did before) and on sand: the soil
    lowers the first bending; lower-bound soil lowers it more, upper-bound less, and the
    clamped value stays above the upper bound."""
    clamped = {m.id: m for m in audit.run(monopile_turbine("clamped")).modes}["tower.fa1"]
    r = audit.run(monopile_turbine())
    fa1 = {m.id: m for m in r.modes}["tower.fa1"]
    assert fa1.band_hz is not None
    lo, hi = fa1.band_hz
    assert lo < fa1.frequency_hz < hi < clamped.frequency_hz
    assert any("monopile in soil" in a for a in r.assumptions)


def test_the_band_is_judged_not_only_its_middle():
    """A lowest speed whose 3P sits 10.7 % above the nominal first bending (clear of the 10 %
    margin) but 9.3 % above the upper-bound soil's: judged on the band it fails; with the
    bounds collapsed onto the nominal soil (×1, ×1) it does not."""
    base = monopile_turbine()
    fa1 = {m.id: m for m in audit.run(base).modes}["tower.fa1"]
    assert fa1.band_hz is not None
    x = 0.5 * (fa1.frequency_hz / 0.9 + fa1.band_hz[1] / 0.9)  # between the two limits
    assert (x - fa1.frequency_hz) / x > 0.10 > (x - fa1.band_hz[1]) / x
    rpm = 60 * x / 3

    def judged(lower: float, upper: float) -> str:
        d = base.model_dump()
        d["rotor"]["speed"] = {"min_rpm": rpm, "max_rpm": 7.56}
        d["tower"]["foundation"]["bounds"] = {"lower": lower, "upper": upper}
        r = audit.run(spec.Spec.model_validate(d))
        return next(c for c in r.checks if c.id == "tower.resonance.3P").status

    assert judged(0.5, 2.0) == "fail"
    assert judged(1.0, 1.0) != "fail"  # (info: 3P crosses it at start-up, below the range)


def test_iea15_monopile_on_soft_sand_against_clamped(tmp_path):
    """IEA-15-240-RWT (windIO 2.x example): clamped at the mudline (what wtvib did before)
    and on a soft sand profile given with --soil. The file's monopile reaches 45 m below the
    30 m mudline (Gaertner et al. 2020: 30 m water, 45 m embedded); the soil lowers the
    first bending (0.17 → 0.15 Hz here), the band brackets it, and the soft soil brings it
    near 1P at overspeed (1P = 0.151 Hz at 9.07 rpm)."""
    from wtvib import importers

    path = iea15_windio()
    profile = tmp_path / "soft.yaml"
    profile.write_text(
        "soil:\n  - {bottom_m: 10, kind: sand, friction_angle_deg: 30}\n"
        "  - {bottom_m: 80, kind: sand, friction_angle_deg: 33}\n"
    )
    clamped = importers.load(path)
    soft = importers.load(path, importers.ReadOptions(soil=profile))
    pile = soft.tower.foundation.pile
    assert pile is not None and pile.embedded_length_m == pytest.approx(45.0)
    f = {m.id: m for m in audit.run(clamped).modes}["tower.fa1"].frequency_hz
    fa1 = {m.id: m for m in audit.run(soft).modes}["tower.fa1"]
    assert fa1.band_hz is not None
    assert fa1.band_hz[0] < fa1.frequency_hz < fa1.band_hz[1] < f
    assert 0.8 * f < fa1.frequency_hz < 0.95 * f


def test_soil_is_refused_where_it_cannot_apply(tmp_path, shared):
    from wtvib import importers

    profile = tmp_path / "s.yaml"
    profile.write_text("soil:\n  - {bottom_m: 50, kind: sand, friction_angle_deg: 35}\n")
    deck = shared / "reference/NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"
    with pytest.raises(spec.SpecError, match="--soil applies to windIO files"):
        importers.load(deck, importers.ReadOptions(soil=profile))


@pytest.mark.parametrize(
    ("behaviour", "published"),
    [
        ("flexible", (1.31e9, -18.7e9, 469e9)),
        ("rigid", (2.25e9, -47.7e9, 1700e9)),
    ],
)
def test_shadlou_closed_form_reproduces_yu_and_amdahl_table_9(behaviour, published):
    """Yu & Amdahl (2023), Marine Structures 92, 103482, Table 9: the DTU 10 MW monopile
    (D 9 m, wall 0.11 m, 42 m embedded, E 210 GPa) in homogeneous soil of E_so = 30 MPa,
    ν 0.3, by Shadlou & Bhattacharya's formulas — K_L, K_LR, K_R to 5 % (the table rounds)."""
    p = Pile(embedded_length_m=42, diameter_m=9, wall_thickness_m=0.11, youngs_modulus_pa=2.1e11)
    h = soil.shadlou(p, 30e6, "homogeneous", behaviour)
    assert (h.lateral, h.coupling, h.rocking) == pytest.approx(published, rel=0.05)


def test_winkler_closed_form_and_fixity_depth_agree_on_the_tower_frequency():
    """Three ways to put the same tower on the same soil (a constant E_py = 50 MN/m²): the
    Winkler pile (wtvib.subsystems.soil), Shadlou & Bhattacharya's closed form with E_so = E_py as
    mudline springs, and the pile clamped at Davisson & Robinson's fixity depth 1.4·R —
    within 6 % of each other, all 15 % or more below the tower clamped at the mudline."""
    base = monopile_turbine()
    p = Pile(embedded_length_m=45, diameter_m=10, wall_thickness_m=0.09)
    k = 5e7

    def first(foundation: dict, extend: float = 0.0) -> float:
        d = base.model_dump()
        d["tower"]["foundation"] = foundation
        if extend:  # the pile above the fixity depth, as a tower section
            sec = d["tower"]["sections"]
            sec["height_m"] = [0.0] + [h + extend for h in sec["height_m"]]
            sec["outer_diameter_m"] = [10.0, *sec["outer_diameter_m"]]
            sec["wall_thickness_m"] = [0.09, *sec["wall_thickness_m"]]
        r = audit.run(spec.Spec.model_validate(d))
        return next(m.frequency_hz for m in r.modes if m.id == "tower.fa1")

    winkler = first(
        {
            "kind": "soil",
            "pile": p.model_dump(),
            "soil": [{"bottom_m": 60, "kind": "modulus", "modulus_pa": k}],
        }
    )
    h = soil.shadlou(p, k, "homogeneous", "flexible")
    closed = first(
        {
            "kind": "springs",
            "lateral_n_m": h.lateral,
            "rocking_nm_rad": h.rocking,
            "coupling_n": h.coupling,
        }
    )
    fixity = first({"kind": "clamped"}, soil.fixity_depth(p, modulus_pa=k))
    clamped = first({"kind": "clamped"})
    for f in (closed, fixity):
        assert f == pytest.approx(winkler, rel=0.06)
    assert max(winkler, closed, fixity) < 0.9 * clamped


def test_soil_parameters_are_uncertain_inputs():
    """--uncertainty takes soil parameters too (sampled one by one: they enter the
    mudline stiffness non-linearly). First order (delta method): σ_f/f = S·σ_φ with the
    normalised sensitivity S the run reports; the samples agree within 20 %."""
    from tests.conftest import with_tolerance

    uncertain_sand = with_tolerance(
        monopile_turbine(), "tower.foundation.soil[0].friction_angle_deg", 0.05
    )
    r = audit.run(uncertain_sand, samples=400, seed=3)
    u = r.uncertainty
    assert u is not None and u["not_propagated"] == []
    sens = u["sensitivities"]["tower.foundation.soil[0].friction_angle_deg"]["tower.fa1"]
    assert 0.05 < sens < 0.5  # stiffer sand, stiffer tower, far less than proportionally
    fa1 = u["modes"]["tower.fa1"]
    assert fa1["std_hz"] / fa1["mean_hz"] == pytest.approx(sens * 0.05, rel=0.2)


def test_stiff_clay_takes_reeses_initial_slope_from_its_strength():
    """Stiff clay: E_py = k·z with k of Reese, Cox & Koop (1975, OTC 2312; as given in
    Reese & Van Impe 2011): 135, 270, 540 MN/m³ (static) for s_u of 50–100, 100–200,
    200–400 kPa — each band's value at its centre and its outer edges."""
    import numpy as np

    for su, k in [(75e3, 135e6), (150e3, 270e6), (300e3, 540e6), (50e3, 135e6), (400e3, 540e6)]:
        assert soil.clay_subgrade_n_m3(su) == pytest.approx(k, rel=1e-12)
    layers = [
        SoilLayer(bottom_m=10.0, kind="sand", friction_angle_deg=35.0),
        SoilLayer(bottom_m=40.0, kind="clay", undrained_shear_strength_pa=150e3),
    ]
    z = np.array([5.0, 20.0, 35.0])
    expected = [21.0e6 * 5.0, 270e6 * 20.0, 270e6 * 35.0]  # k·z, z below the mudline
    assert soil.modulus(layers, z) == pytest.approx(expected, rel=2e-3)


def test_a_clay_profile_audits_and_a_stiffer_clay_stiffens_the_tower():
    def fa1(su: float) -> float:
        d = monopile_turbine().model_dump()
        d["tower"]["foundation"]["soil"] = [
            {"bottom_m": 60, "kind": "clay", "undrained_shear_strength_pa": su}
        ]
        r = audit.run(spec.Spec.model_validate(d))
        assert any("clay to 60 m (s_u" in a for a in r.assumptions)
        return {m.id: m for m in r.modes}["tower.fa1"].frequency_hz

    assert fa1(60e3) < fa1(350e3)


@pytest.mark.parametrize(
    ("layer", "message"),
    [
        ({"kind": "clay"}, "a clay layer needs undrained_shear_strength_pa"),
        ({"kind": "clay", "undrained_shear_strength_pa": 20e3}, "greater than or equal to 50000"),
        (
            {"kind": "clay", "undrained_shear_strength_pa": 1e5, "friction_angle_deg": 30},
            "friction_angle_deg is not used by a clay layer",
        ),
        ({"kind": "sand", "friction_angle_deg": 30, "modulus_pa": 1e8}, "not used by a sand"),
    ],
)
def test_a_soil_layer_says_what_it_lacks_or_does_not_use(layer, message):
    with pytest.raises(ValueError, match=message):
        SoilLayer(bottom_m=20.0, **layer)


def test_a_mistake_in_a_soil_file_names_that_file_and_its_line(tmp_path):
    """`check windio.yaml --soil FILE`: an error in FILE named the windIO file, with no line
    (the profile was validated only inside the imported spec)."""
    from wtvib import importers

    path = iea15_windio()
    profile = tmp_path / "soft.yaml"
    profile.write_text(
        "soil:\n  - {bottom_m: 10, kind: sand, friction_angle_deg: 30}\n"
        "  - {bottom_m: 80, kind: clay, undrained_shear_strength_pa: abc}\n"
    )
    with pytest.raises(spec.SpecError) as err:
        importers.load(path, importers.ReadOptions(soil=profile))
    text = str(err.value)
    assert text.startswith(f"{profile}:3: soil[1].undrained_shear_strength_pa")
    tolerant = tmp_path / "tolerant.yaml"  # quantities with tolerances still pass through
    tolerant.write_text(
        "soil:\n  - {bottom_m: 80, kind: sand, friction_angle_deg: "
        "{value: 33, provenance: representative, tolerance: 0.05}}\n"
    )
    s = importers.load(path, importers.ReadOptions(soil=tolerant))
    assert "tower.foundation.soil[0].friction_angle_deg" in s.provenance


def test_the_tower_modes_solved_in_pairs_are_each_planes_own():
    """The spec's fore-aft and side-side modes, and their lower- and upper-bound soil
    bands, come from one stacked eigen-solve per soil case (tower.bending_pair): the same
    numbers as each plane solved alone (tower.bending_modes)."""
    s = monopile_turbine()
    t = s.tower
    b = tower.discretise(t)
    modes = {m.id: m for m in tower.structural_modes(s)}
    for direction in ("fa", "ss"):
        alone = [
            tower.bending_modes(
                b, s.tower_head, t.point_masses, t.foundation, direction, t.gravity, 2, factor
            ).frequency_hz
            for factor in (1.0, t.foundation.bounds.lower, t.foundation.bounds.upper)
        ]
        for k in (1, 2):
            mode = modes[f"tower.{direction}{k}"]
            assert mode.frequency_hz == alone[0][k - 1]
            assert mode.band_hz == (alone[1][k - 1], alone[2][k - 1])


def test_fixity_depth_for_a_modulus_growing_with_depth():
    """Davisson & Robinson (1965) for E_py = n_h·z: 1.8·T, T = (EI/n_h)^⅕. A 6 m × 60 mm
    steel pile (EI = 210e9·π/64·(6⁴ − 5.88⁴) = 1.0371e12 N·m², by hand) in n_h = 5 MN/m³:
    T = 11.57 m, the fixity depth 20.83 m; a constant modulus k gives 1.4·(EI/k)^¼."""
    import math

    p = Pile(embedded_length_m=36, diameter_m=6, wall_thickness_m=0.06)
    ei = 210e9 * math.pi / 64 * (6**4 - 5.88**4)
    assert ei == pytest.approx(1.0371e12, rel=1e-4)
    assert soil.fixity_depth(p, gradient_pa_m=5e6) == pytest.approx(1.8 * (ei / 5e6) ** 0.2)
    assert soil.fixity_depth(p, gradient_pa_m=5e6) == pytest.approx(20.83, abs=0.01)
    assert soil.fixity_depth(p, modulus_pa=5e7) == pytest.approx(1.4 * (ei / 5e7) ** 0.25)
