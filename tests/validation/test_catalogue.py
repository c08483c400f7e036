"""Each catalogue turbine tells the story of Hau ch. 7 (DOMAIN.md §4).

Expected classes and verdicts come from the book's statements quoted in each test; the
numbers the specs carry are labelled there as published, derived or representative.

These stories test the judgement — rules, regimes, energy classes, the verdict — not the
models: a spec tuned to the book's figure gives that figure back by construction. WKA-60's
DAF 4 comes from the damping ratio 0.125 its spec derives from that same 4; MOD-2's tower
frequency sits where the book places it (between 1P and 2P), Tjæreborg's tower modulus is
calibrated to its source's 0.81 Hz. The models are
validated against published, analytic and other tools' numbers in the other files of
``tests/validation/``.
"""

import math
import re
from pathlib import Path

import pytest

from wtvib import audit, spec

TURBINES = Path(__file__).resolve().parents[2] / "turbines"

# file: (tower class, verdict) — source: DOMAIN.md §4 table and Hau ch. 7.5.2
STORIES = {
    "mod-0": ("stiff", "fail"),  # stiff lattice; 2P drive-train resonance before the fix
    "mod-0-fluid-coupling": ("stiff", "pass"),  # the fluid coupling damps it (Hau 7.3.3)
    "mod-1": ("stiff", "pass"),  # "representatives of the stiff turbine design"
    "mod-2": ("soft", "pass"),  # "between the 1P and 2P excitation frequencies"
    "wts-75": ("stiff", "pass"),  # "The WTS-75 stood for the stiff design"
    "wts-3": ("soft", "pass"),  # "a soft tower between 1P and 2P"
    "wts-4": ("soft-soft", "warn"),  # "double-soft … extremely unpleasant" amplitudes
    "tjaereborg": ("soft", "pass"),  # "passes through the tower resonance during start-up"
    "wka-60": ("resonant", "fail"),  # "coincided precisely with the 2P excitation"
    "growian": ("soft", "warn"),  # soft tower; drive train meets 2P at 115 % overspeed
    "aeroman": ("stiff", "fail"),  # 4th drive-train mode on the stage-2 mesh; yaw play
    "aeroman-retrofit": ("stiff", "fail"),  # yaw cured by the active drive; gearbox unchanged
    "euros-44m": (None, "warn"),  # blade case: no tower; 3P meets flap only at 18 rpm
    # vertical axis: no stiff/soft class; with the measured Campbell diagram (SAND91-2228
    # Fig. 4.5) the 1st flatwise mode is 11 % above 2P at 34 rpm and meets it at
    # overspeed: warn (the representative values it replaced passed)
    "darrieus": (None, "warn"),
    "nrel-5mw": ("resonant", "fail"),  # 3P at 6.9 rpm is 6 % from the tower (< 10 %)
    "iea-15mw": ("soft", "warn"),  # 2P swept in partial load; 3P clear
    "stall-rotor-1mw": ("soft", "fail"),  # chordwise stall-induced vibration (Hau 7.2.3)
    # offshore (DOMAIN.md §6): on its soil the tower's first bending is a band between 1P
    # and 3P, 2P sweeping it in partial load; on the spar the free base lifts the NREL
    # 5-MW's tower into 3P's band (0.48 Hz; OpenFAST's linearisation: 0.484, test_floating.py)
    "iea-15mw-monopile": ("soft", "warn"),
    "nrel-5mw-oc3-spar": ("resonant", "fail"),
}


def report(name: str) -> audit.Report:
    return audit.run(spec.load(TURBINES / f"{name}.yaml"))


def check(r: audit.Report, check_id: str):
    return next(c for c in r.checks if c.id == check_id)


def test_every_catalogue_file_has_a_story():
    assert {p.stem for p in TURBINES.glob("*.yaml")} == set(STORIES)


@pytest.mark.parametrize(("name", "story"), sorted(STORIES.items()))
def test_tower_class_and_verdict(name, story):
    r = report(name)
    assert (r.tower_class, r.verdict) == story


@pytest.mark.parametrize("name", sorted(STORIES))
def test_every_value_has_provenance_with_a_cited_source(name):
    """Every number in a catalogue spec is a quantity (published/derived/representative)."""
    text = (TURBINES / f"{name}.yaml").read_text(encoding="utf-8")
    s = spec.load(TURBINES / f"{name}.yaml")
    bare = [
        line.strip()
        for line in text.splitlines()
        if re.match(r"^\s*[\w\"]+:\s*-?[\d.]+(e\d+)?\s*(#.*)?$", line)
        and not line.strip().startswith(("wtvib:", "blades:", "teeth:", "year:", "southwell:"))
    ]
    assert bare == [], f"numbers without provenance: {bare}"
    for path, q in s.provenance.items():
        if q.provenance == "published":
            assert q.source, f"{path} is published but names no source"
            # a published value cites a publication, not the project's own brief or README
            cited = s.sources[q.source].lower()
            assert not any(w in cited for w in ("wtvib", "domain brief", "readme")), (
                f"{path} is marked published but cites {s.sources[q.source]!r}"
            )


def test_wka60_resonates_with_2p_at_rated_speed_with_daf_4():
    # Hau Fig. 7.26/7.27: tower = 2P at rated speed, cyclic force amplified by a factor 4
    # (the judgement's test: the spec's ζ = 0.125 is derived from that factor, 1/(2·4))
    c = check(report("wka-60"), "tower.resonance.2P")
    assert c.status == "fail" and c.numbers["mode"] == "tower.fa1"
    assert c.numbers["speed_rpm"] == pytest.approx(23.0, abs=0.01)
    assert c.numbers["daf"] == pytest.approx(4.0, rel=0.01)
    assert c.numbers["exclude_rpm"]  # the speed band that would have to be excluded


def test_growian_drive_train_meets_2p_only_at_overspeed():
    # Hau Fig. 7.16: first drive-train mode = 2P at 115 % overspeed (≈0.71 Hz)
    c = check(report("growian"), "drivetrain.resonance.2P")
    assert (c.status, c.numbers["regime"]) == ("warn", "overspeed")
    assert c.numbers["crossings_rpm"] == pytest.approx([21.27], abs=0.05)
    assert c.numbers["mode"] == "drivetrain.grid.1"


def test_aeroman_fourth_mode_meets_stage2_mesh():
    # Hau Fig. 7.15: the 2nd gear stage mesh excites the 4th drive-train mode
    c = check(report("aeroman"), "drivetrain.resonance.mesh.stage2")
    assert (c.status, c.numbers["mode"]) == ("fail", "drivetrain.grid.4")


def test_mod0_drive_train_resonates_with_2p_over_part_of_the_power_range():
    # Hau Figs. 7.13/7.14: synchronous generator on the grid, resonance with tower shadow 2P,
    # power dependent; the damping fluid coupling cured it (Hau ch. 7.3.3)
    c = check(report("mod-0"), "drivetrain.grid.power")
    assert c.status == "fail" and "2P" in c.message
    freqs = c.numbers["frequency_hz"]
    assert freqs[0] > freqs[-1]  # c_m ∝ cos δ₀ falls with power, and the frequency with it
    assert min(freqs) < 4 / 3 < max(freqs) * 1.1  # 2P = 2 × 40/60 Hz inside the swept band
    # the powers named are those at which the grid mode lies in 2P's 10 % band (by hand:
    # 1.2–1.467 Hz)
    inside = [
        p for p, f in zip(c.numbers["power_fraction"], freqs, strict=True) if 1.2 < f < 4.4 / 3
    ]
    assert f"between {100 * min(inside):.0f} and {100 * max(inside):.0f} % power" in c.message
    fixed = report("mod-0-fluid-coupling")
    assert check(fixed, "drivetrain.grid.power").status == "pass"
    assert fixed.verdict in ("pass", "warn")


def test_euros_flap_clear_at_16_rpm_and_meets_3p_at_18_rpm():
    # Hau Fig. 7.5: no 1P/3P resonance at 16 rpm; "3P … would only occur at 18 rpm";
    # higher harmonics in the partial-load range have little energy
    r = report("euros-44m")
    c3 = check(r, "blade.resonance.3P")
    assert (c3.status, c3.numbers["regime"]) == ("warn", "overspeed")
    assert c3.numbers["crossings_rpm"] == pytest.approx([18.0], abs=0.05)
    assert check(r, "blade.resonance.1P").status == "pass"
    minor = [c for c in r.checks if c.numbers.get("energy") == "minor" and c.status != "pass"]
    assert minor and all(c.status == "info" for c in minor)


def test_soft_towers_note_the_start_up_encounter():
    for name in ("mod-2", "wts-3", "tjaereborg"):
        c = check(report(name), "tower.class")
        assert c.numbers["startup_crossings"], name


def test_wts4_both_1p_and_2p_cross_at_start_up():
    c = check(report("wts-4"), "tower.class")
    assert c.numbers["startup_crossings"] == ["1P", "2P"]
    assert "large tower-head amplitudes" in c.message


def test_stall_rotor_edgewise_damping_goes_negative_at_high_wind():
    # Hau ch. 7.2.3: "chordwise rotor blade vibration was observed in some larger
    # stall-controlled turbines … when they are operated at high wind velocities", while
    # "the chordwise movement … is not very damped aerodynamically, in contrast to the
    # flapwise movement"
    r = report("stall-rotor-1mw")
    edge, flap = check(r, "blade.stall.edge1"), check(r, "blade.stall.flap1")
    assert edge.status == "fail"
    unstable = [p["wind_m_s"] for p in edge.numbers["curve"] if p["total_damping_ratio"] < 0]
    assert min(unstable) > 12 and max(unstable) < 25  # in the stall range, not at low wind
    low_wind = [p for p in flap.numbers["curve"] if p["wind_m_s"] <= 8]
    edge_low = [p for p in edge.numbers["curve"] if p["wind_m_s"] <= 8]
    # flapwise aerodynamic damping in attached flow is tens of times the edgewise one
    assert min(p["aero_damping_ratio"] for p in low_wind) > 20 * max(
        abs(p["aero_damping_ratio"]) for p in edge_low
    )
    assert flap.status != "fail"
    # the same story from the BEM operating points (its aerodynamics block): the judged
    # edgewise mode unstable in the stall range, and the representative planform and polar
    # make the rotor its rating — a stall-regulated power curve peaking near 1 MW
    stab = check(r, "aerodynamics.stability")
    assert stab.status == "fail" and "blade.edge1" in stab.numbers["unstable"]
    assert all(12 < v < 25 for v in stab.numbers["unstable"]["blade.edge1"])
    power = [p["power_kw"] for p in check(r, "aerodynamics.operation").numbers["points"]]
    assert 800 < max(power) < 1200 and power[-1] < 0.8 * max(power)  # stall: power falls
    # divergence and flutter are not the problem of this stiff, short blade
    assert check(r, "blade.flutter").status == "pass"
    assert check(r, "blade.divergence").status == "pass"


def test_wka60_concrete_tower_uncertainty_and_the_size_that_clears_2p():
    """The WKA-60's concrete tower as sections (representative geometry scaled to
    the 2P coincidence Hau reports) with tolerances on E (15 %), density and head mass
    (5 %). Hau §7.5.2: "the actual natural frequencies of concrete towers differ
    considerably from the calculated values". Exact: f ∝ √(E/m), so the sensitivity to E is
    ½ and those to the masses sum to −½ (σ_f ≈ 7.7 % of f); the 2P band (±10 % around
    0.767 Hz at rated speed) then holds the frequency with a probability near
    P(|z| < 1.3) ≈ 0.8–0.95. A tower sized by wtvib's `size` into the soft window (wall
    scaled) no longer meets 2P."""
    from wtvib.studies import design

    s = spec.load(TURBINES / "wka-60.yaml")
    r = audit.run(s, samples=2000, seed=1)
    assert next(m for m in r.modes if m.id == "tower.fa1").origin == "computed"
    u = r.uncertainty
    assert u is not None
    sens = u["sensitivities"]
    assert sens["tower.material.youngs_modulus_pa"]["tower.fa1"] == pytest.approx(0.5, abs=0.01)
    masses = (
        sens["tower.material.density_kg_m3"]["tower.fa1"] + sens["tower_head.mass_kg"]["tower.fa1"]
    )
    assert masses == pytest.approx(-0.5, abs=0.01)
    assert 0.8 < u["modes"]["tower.fa1"]["in_margin_band"]["2P"]["probability"] < 0.97
    goal = design.window_goal(design.all_windows(r), "soft")
    sized = design.scaled(s, design.size(s, goal, "wall").scale, "wall")
    assert check(audit.run(sized), "tower.resonance.2P").status != "fail"


def test_euros_blade_gets_its_stability_checks_and_the_closed_form_divergence():
    """Hau §7.2.1 ("it should nevertheless be checked in all real cases"): the
    Euros 44 m blade carries representative section data, so divergence, flutter and the
    stall checks are analysed, not skipped. Exact: the typical-section divergence dynamic
    pressure q_D = K_θ/(c·C_Lα·e), K_θ = I_θ·ω_θ² per unit span with the torsion stiffened by
    the propeller moment (ω_θ² = ω_θ0² + Ω²·cos 2β at overspeed), e the elastic axis behind
    the quarter chord — with the spec's I_θ = 6 kg·m, f_θ0 = 7 Hz, c = 1.55 m, EA at 0.30 c:
    V_D = √(2q_D/ρ) = 158.6 m/s."""
    r = report("euros-44m")
    s = spec.load(TURBINES / "euros-44m.yaml")
    ae = s.blade.aeroelastic
    assert ae is not None
    for cid in ("blade.divergence", "blade.flutter", "blade.stall.flap1", "blade.stall.edge1"):
        assert not check(r, cid).message.startswith("not analysed"), cid
    sec = ae.sections[0]
    omega = s.rotor.speed.overspeed * math.pi / 30
    beta = math.radians(sec.chord_angle_deg)
    w2 = (2 * math.pi * 7.0) ** 2 + omega**2 * math.cos(2 * beta)
    e = (sec.elastic_axis_chord - 0.25) * sec.chord_m
    q_d = 6.0 * w2 / (sec.chord_m * ae.lift_slope_per_rad * e)
    v_d = math.sqrt(2 * q_d / ae.air_density_kg_m3)
    assert f"V_D = {v_d:.1f} m/s" in check(r, "blade.divergence").message


def test_tjaereborg_tower_from_the_stas_model_gives_its_frequency():
    """The Tjæreborg tower and head from SINTEF's STAS model (spec sources: stas).
    Published there: E = 4.7e10 Pa, 'to be calibrated. ft = 0.81 Hz'. wtvib's beam with the
    source's own E lands within 1.5 % of 0.81 Hz (its head a rigid point mass, the source's
    nacelle a frame of beams); the spec's E is re-calibrated to 0.81 Hz (derived, +2.3 %)."""
    s = spec.load(TURBINES / "tjaereborg.yaml")
    f = next(m for m in audit.run(s).modes if m.id == "tower.fa1").frequency_hz
    assert f == pytest.approx(0.81, rel=2e-3)
    mat = s.tower.material
    assert mat is not None
    source_e = mat.model_copy(update={"youngs_modulus_pa": 4.7e10})
    raw = s.model_copy(update={"tower": s.tower.model_copy(update={"material": source_e})})
    f_raw = next(m for m in audit.run(raw).modes if m.id == "tower.fa1").frequency_hz
    assert f_raw == pytest.approx(0.81, rel=0.015)


def test_darrieus_modes_follow_the_measured_campbell_diagram():
    """The Sandia 34 m test bed's measured Campbell diagram (SAND91-2228 Fig. 4.5,
    digitised in OWENS.jl) as tables of rpm and Hz: the lead-lag mode 1BE softens with speed
    — 1.6389 Hz at 30 rpm, 1.5713 Hz at 35.169 rpm, so 1.5866 Hz at the 34 rpm of normal
    operation (linear between the points) — and the first flatwise 1F stiffens (1.2603 Hz at
    34.157 rpm); the audit judges both at those values."""
    r = report("darrieus")
    modes = {m.id: m for m in r.modes}
    omega = 34 * math.pi / 30
    edge = float(modes["blade.edge1"].frequency_at(omega)[()])
    assert edge == pytest.approx(1.6389 + (34 - 30) / (35.169 - 30) * (1.5713 - 1.6389), rel=1e-4)
    assert edge < modes["blade.edge1"].frequency_hz  # softened from 1.8111 Hz
    c = check(r, "blade.resonance.3P")
    assert c.numbers["mode"] == "blade.edge1"
    assert c.numbers["frequency_hz"] == pytest.approx(edge, rel=1e-3)
    assert any("tabulated in the spec" in a for a in r.assumptions)
