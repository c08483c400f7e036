"""wtvib.numerics.hull against closed forms: a floating vertical cylinder, a tube's mass and
inertia, ballast levels, the parallel-axis theorem and the trim balance."""

import dataclasses

import numpy as np
import pytest

from wtvib.numerics import hull

RHO, G = 1025.0, 9.80665


def cylinder(d: float = 10.0, draft: float = 20.0, free: float = 10.0, **kw) -> hull.Member:
    return hull.Member(
        name="c",
        a=np.array([0.0, 0.0, -draft]),
        b=np.array([0.0, 0.0, free]),
        stations=np.array([0.0, 1.0]),
        diameter=np.array([d, d]),
        layers=[hull.Layer(np.array([0.05, 0.05]), 7850.0)],
        **kw,
    )


def test_a_vertical_cylinder_floats_by_the_book():
    """V = πD²T/4, z_B = −T/2, A_wp = πD²/4, C₃₃ = ρgA_wp, C₄₄ = ρg(πD⁴/64 − V·T/2)
    (Faltinsen 1990, §2.3)."""
    d, t = 10.0, 20.0
    b = hull.buoyancy([cylinder(d, t)])
    v = np.pi * d**2 / 4 * t
    assert b.volume == pytest.approx(v, rel=1e-9)
    assert b.centre[2] == pytest.approx(-t / 2, rel=1e-9)
    assert b.area == pytest.approx(np.pi * d**2 / 4, rel=1e-12)
    c = hull.hydrostatic(b, RHO, G)
    assert c[2, 2] == pytest.approx(RHO * G * np.pi * d**2 / 4, rel=1e-12)
    assert c[3, 3] == pytest.approx(RHO * G * (np.pi * d**4 / 64 - v * t / 2), rel=1e-9)
    assert c[4, 4] == pytest.approx(c[3, 3], rel=1e-12)


def test_an_off_axis_column_adds_its_waterplane_by_parallel_axes():
    """A column at (x, y): C₃₅ = −ρgA·x, C₃₄ = ρgA·y, C₅₅ gains ρgA·x², C₄₄ ρgA·y²,
    C₄₅ = −ρgA·xy (Faltinsen 1990, §2.3)."""
    x, y = 30.0, -12.0
    m = cylinder()
    shift = np.array([x, y, 0.0])
    moved = hull.Member(**{**m.__dict__, "a": m.a + shift, "b": m.b + shift})
    c0 = hull.hydrostatic(hull.buoyancy([m]), RHO, G)
    c = hull.hydrostatic(hull.buoyancy([moved]), RHO, G)
    area = np.pi * 100 / 4
    assert c[2, 4] == pytest.approx(-RHO * G * area * x, rel=1e-9)
    assert c[2, 3] == pytest.approx(RHO * G * area * y, rel=1e-9)
    assert c[4, 4] - c0[4, 4] == pytest.approx(RHO * G * area * x**2, rel=1e-9)
    assert c[3, 3] - c0[3, 3] == pytest.approx(RHO * G * area * y**2, rel=1e-9)
    assert c[3, 4] == pytest.approx(-RHO * G * area * x * y, rel=1e-9)


def test_strip_theory_added_mass_of_a_column():
    """Across the axis ρC_a·V (surge), its moment ρC_a(πD²/4)·T³/3 about the water line
    (pitch) and coupling −ρC_a(πD²/4)·T²/2 (surge–pitch); along it the bottom's
    ρC_a,end·πD³/12 (heave) — RAFT's strip theory (Hall et al. 2022)."""
    d, t, ca, end = 10.0, 20.0, 0.8, 0.6
    a = hull.added_mass([cylinder(d, t, ca=ca, ca_end=end, free_ends=(True, False))], RHO)
    area = np.pi * d**2 / 4
    assert a[0, 0] == pytest.approx(RHO * ca * area * t, rel=1e-9)
    assert a[4, 4] == pytest.approx(RHO * ca * area * t**3 / 3, rel=1e-4)
    assert a[0, 4] == pytest.approx(-RHO * ca * area * t**2 / 2, rel=1e-9)
    assert a[2, 2] == pytest.approx(RHO * end * np.pi / 12 * d**3, rel=1e-12)
    assert a[5, 5] == pytest.approx(0.0, abs=1e-6)


def test_a_tube_s_mass_and_inertia():
    """m = ρπ(D² − (D − 2t)²)L/4; about its axis m(R_o² + R_i²)/2; about a diameter through
    its middle m((R_o² + R_i²)/4 + L²/12)."""
    d, t, length = 10.0, 0.05, 30.0
    m = hull.Member(
        name="t",
        a=np.array([0.0, 0.0, -length / 2]),
        b=np.array([0.0, 0.0, length / 2]),
        stations=np.array([0.0, 1.0]),
        diameter=np.array([d, d]),
        layers=[hull.Layer(np.array([t, t]), 7850.0)],
    )
    body = hull.structure(m)
    mass = 7850.0 * np.pi / 4 * (d**2 - (d - 2 * t) ** 2) * length
    ro, ri = d / 2, d / 2 - t
    assert body[0, 0] == pytest.approx(mass, rel=1e-9)
    assert body[5, 5] == pytest.approx(mass * (ro**2 + ri**2) / 2, rel=1e-9)
    # the slices' own length terms make the sum exact (a uniform rod's L²/12)
    assert body[3, 3] == pytest.approx(mass * ((ro**2 + ri**2) / 4 + length**2 / 12), rel=1e-9)


def test_at_point_is_the_parallel_axis_theorem():
    """A mass m at r: the translation block m·I, the rotation block m(|r|²I − r rᵀ), the
    coupling m z in surge–pitch."""
    m, r = 5.0, np.array([1.0, 2.0, 3.0])
    out = hull.at_point(m * np.eye(3), r)
    assert np.allclose(out[3:, 3:], m * (r @ r * np.eye(3) - np.outer(r, r)))
    assert out[0, 4] == pytest.approx(m * r[2])
    assert np.allclose(out, out.T)


def test_ballast_fills_a_column_from_the_bottom_and_a_pontoon_by_its_segment():
    """A vertical compartment holding V stands V/(πd²/4) deep; a level pipe half full has
    its water to its axis."""
    column = cylinder(10.0, 20.0, fills=[hull.Fill(0.0, 0.5, RHO)])
    f = column.fills[0]
    inside = np.pi / 4 * (10.0 - 0.1) ** 2
    level = hull.level([(column, f)], 300.0)
    assert level == pytest.approx(-20.0 + 300.0 / inside, rel=1e-6)
    pipe = hull.Member(
        name="p",
        a=np.array([0.0, 0.0, -10.0]),
        b=np.array([40.0, 0.0, -10.0]),
        stations=np.array([0.0, 1.0]),
        diameter=np.array([4.0, 4.0]),
        layers=[],
        fills=[hull.Fill(0.0, 1.0, RHO)],
    )
    half = hull.capacity(pipe, pipe.fills[0]) / 2
    assert hull.level([(pipe, pipe.fills[0])], half) == pytest.approx(-10.0, abs=1e-6)
    water = hull.ballast(pipe, pipe.fills[0], -10.0)
    # a half-full pipe's water: its centroid 4r/3π below the axis (a semicircle's)
    assert water[0, 4] / water[0, 0] == pytest.approx(-10.0 - 4 * 2.0 / (3 * np.pi), rel=1e-3)
    assert water[1, 5] / water[0, 0] == pytest.approx(20.0, rel=1e-9)  # along it: its middle


def test_trim_balances_buoyancy_and_weight_and_says_what_is_missing():
    column = cylinder(10.0, 20.0, fills=[hull.Fill(0.0, 0.5, RHO)])
    parts = [(column, column.fills[0])]
    v = hull.buoyancy([column]).volume
    t = hull.trim(v, RHO, RHO * v - 200_000.0, parts)
    assert t.volume * RHO == pytest.approx(200_000.0, rel=1e-9)
    assert t.shortfall == pytest.approx(0.0, abs=1e-6)
    short = hull.trim(v, RHO, 0.0, parts)  # an empty hull: the compartments cannot sink it
    assert short.shortfall == pytest.approx(RHO * (v - hull.capacity(*parts[0])), rel=1e-9)
    heavy = hull.trim(v, RHO, RHO * v + 1000.0, parts)
    assert heavy.volume == 0.0 and heavy.shortfall == pytest.approx(-1000.0)


def test_a_bulkhead_at_a_step_of_diameter_closes_the_wider_side():
    """A disc across the inside, ρ·π(D − 2t)²/4·t_b: at a step (two stations at one place)
    the wider section's (its top closes the wider part, as OC4's base columns)."""
    t, plate = 0.05, 0.06

    def member(bulkheads, diameter=(20.0, 20.0, 10.0, 10.0)):  # type: ignore[no-untyped-def]
        return hull.Member(
            name="s",
            a=np.array([0.0, 0.0, -30.0]),
            b=np.array([0.0, 0.0, 10.0]),
            stations=np.array([0.0, 0.5, 0.5, 1.0]),
            diameter=np.array(diameter),
            layers=[hull.Layer(np.full(4, t), 7850.0)],
            bulkheads=bulkheads,
        )

    # a step the other way (narrow below, wide above): the wider side still
    up = member((hull.Disc(0.5, plate, 7850.0),), (10.0, 10.0, 20.0, 20.0))
    up_added = hull.structure(up) - hull.structure(dataclasses.replace(up, bulkheads=()))
    assert up_added[0, 0] == pytest.approx(7850.0 * np.pi / 4 * (20.0 - 2 * t) ** 2 * plate)
    bare = hull.structure(member(()))
    closed = hull.structure(member((hull.Disc(0.5, plate, 7850.0),)))
    d = 20.0 - 2 * t
    mass = 7850.0 * np.pi / 4 * d**2 * plate
    added = closed - bare
    assert added[0, 0] == pytest.approx(mass)
    # a thin disc: m·d²/8 about its axis (here yaw), m·d²/16 about a diameter, plus m·z² for
    # roll about the origin 10 m above it (parallel axes)
    assert added[5, 5] == pytest.approx(mass * d**2 / 8)
    assert added[3, 3] == pytest.approx(mass * (d**2 / 16 + 10.0**2))


def test_small_members_keep_their_end_added_mass_and_waterplane():
    """A 1 m column whose top is 0.5 m above the water: its waterplane πD²/4 and its bottom's
    ρC_a,end·πD³/12 (0.26 m³ of fluid) count like a big one's; its top, out of the water,
    adds none."""
    m = cylinder(1.0, 5.0, 0.5, free_ends=(True, True))
    assert hull.buoyancy([m]).area == pytest.approx(np.pi / 4, rel=1e-12)
    assert hull.added_mass([m], RHO)[2, 2] == pytest.approx(RHO * 0.6 * np.pi / 12, rel=1e-12)


def test_a_thin_pipe_below_its_level_holds_no_water_and_half_full_sits_low():
    pipe = hull.Member(
        name="p",
        a=np.array([0.0, 0.0, -10.0]),
        b=np.array([10.0, 0.0, -10.0]),
        stations=np.array([0.0, 1.0]),
        diameter=np.array([1.0, 1.0]),
        layers=[],
        fills=[hull.Fill(0.0, 1.0, RHO)],
    )
    fill = pipe.fills[0]
    assert hull.held(pipe, fill, -11.0).sum() == 0.0
    water = hull.ballast(pipe, fill, -10.0)
    assert water[0, 4] / water[0, 0] == pytest.approx(-10.0 - 4 * 0.5 / (3 * np.pi), rel=1e-6)
