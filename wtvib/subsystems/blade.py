"""Rotor blades: flap, edge and torsion modes with rotational (centrifugal) stiffening."""

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..judge.analysis import Analysis, Context, Damping, Subsystem, section_damping
from ..numerics import beam, modal
from ..results import Mode, Sampled, Shape, Southwell, SpeedCurve, by_frequency, ordinal
from ..spec import BladeStructure, ModeSpec, Spec
from ..units import rpm_to_rad_s
from .given import given_modes

Array = NDArray[np.float64]

#: Southwell coefficients used when the spec gives none: uniform cantilever, no hub offset
#: (flap K ≈ 1.19; edge K_flap − 1 ≈ 0.19; torsion: no stiffening). DOMAIN.md §3, after
#: Southwell & Gough (1921).
DEFAULT_SOUTHWELL = {"flap": 1.19, "edge": 0.19, "tor": 0.0}

_KIND = {"flap": "flapwise bending", "edge": "edgewise (chordwise) bending", "tor": "torsion"}


def southwell_default(name: str) -> float:
    """Default Southwell coefficient of a blade mode name (``flap1`` → 1.19)."""
    return DEFAULT_SOUTHWELL[name.rstrip("0123456789")]


def modes(spec: Spec) -> list[Mode]:
    """Blade modes (ids ``blade.flap1``, ``blade.edge1``, ``blade.tor1`` …).

    Computed with their rotating curves where the spec gives the blade's structure; the
    given frequencies of modes the model does not compute are kept.
    """
    given = _given(spec)
    if spec.blade.structure is None:
        return given
    computed = structural_modes(spec)
    if spec.blade.dofs is not None:  # a deck's switches: only its degrees of freedom
        computed = [m for m in computed if m.id.removeprefix("blade.") in spec.blade.dofs]
    ids = {m.id for m in computed}
    return sorted(computed + [m for m in given if m.id not in ids], key=by_frequency)


def _given(spec: Spec) -> list[Mode]:
    """Given standstill frequencies with the curve f² = f₀² + K·(Ω/2π)² (Southwell)."""

    def describe(name: str) -> str:
        kind = name.rstrip("0123456789")
        return f"{ordinal(int(name[len(kind) :]))} blade {_KIND[kind]}"

    def curve(name: str, f0: float, full: ModeSpec | None) -> SpeedCurve | None:
        k = full.southwell if full and full.southwell is not None else southwell_default(name)
        return Southwell(f0, k) if k > 0 else None

    return given_modes("blade", spec.blade.modes, describe, curve)


# ---------------------------------------------------------------------------------------
# The structural model: a cantilevered, twisted beam bending in and out of the rotor plane,
# stiffened by the centrifugal force.

#: Elements of the default blade mesh (see wtvib.numerics.beam.BLADE_ELEMENTS).
DEFAULT_ELEMENTS = beam.BLADE_ELEMENTS
#: Rotor speeds at which the rotating modes are computed, 0 … overspeed.
SPEED_SAMPLES = 13
#: Standstill modes spanning the basis of the rotating blade, per mode kept (the
#: 13-speed sweep of the NREL 5-MW, IEA-15 and IEA-22 blades within 4e-8 of the full
#: model's, 7-10 times faster; tests/validation/test_structure.py).
RITZ_BLADE = 6


def blade_parts(s: BladeStructure, nodes: Array) -> tuple[Array, Array, Array, Array]:
    """K₀ (elastic), G (geometric stiffness of the centrifugal tension per Ω²), M_v (the
    in-plane part of the mass) and M of the cantilevered blade: K(Ω) = K₀ + Ω²·(G − M_v),
    dofs per node (w, w', v, v'), w out of the rotor plane (downwind) and v in it (in the
    direction of rotation).

    Notes
    -----
    With structural twist β (to feather) the stiffnesses in rotor axes are EI_ww = EI_f·cos²β
    + EI_e·sin²β, EI_vv = EI_f·sin²β + EI_e·cos²β, EI_wv = (EI_f − EI_e)·sinβ·cosβ: a
    section turned to feather has its leading edge turned upwind, its flapwise principal
    axis (normal to the chord) from the downwind direction towards the direction of
    rotation, ê_f = (cos β, sin β) in (w, v) — HAWCStab2's first flapwise mode of the DTU
    10 MW blade moves towards its leading edge as it moves downwind, as wtvib's
    (tests/validation/test_hawc2.py). Rotation adds the
    geometric stiffness of the centrifugal tension N(r) = Ω²∫_r^R m(s)·(r_hub + s) ds to both
    planes and the in-plane softening −Ω²·M_v (the centrifugal force has a component along
    an in-plane displacement). The root is clamped (its four dofs removed), or free
    (``s.root``: every dof kept; the model then has four rigid-body modes at 0 Hz). With
    shear stiffnesses (``ga_flap_n``, ``ga_edge_n``) the blade is a Timoshenko beam
    (:func:`_shear_blocks`): the second dof of each plane is the section's rotation, not
    the slope.

    References
    ----------
    Hansen, *Aerodynamics of Wind Turbines*, 3rd ed., ch. 12; Wright et al., "Vibration
    modes of centrifugally stiffened beams", J. Appl. Mech. 49, 1982 (Southwell K ≈ 1.19).
    """
    b = beam.basis(nodes)
    m, ef, ee, beta = _sections(s, b)
    c, sn = np.cos(beta), np.sin(beta)
    ei_ww, ei_vv, ei_wv = ef * c**2 + ee * sn**2, ef * sn**2 + ee * c**2, (ef - ee) * sn * c
    # a tip mass pulls on every section (its centrifugal force per Ω²: m_tip·R)
    tension = _centrifugal_integral(nodes, m, s.hub_radius_m)
    tension = tension + s.tip_mass_kg * (s.hub_radius_m + nodes[-1])
    n_el = len(nodes) - 1
    w_dofs = beam.chain_dofs(n_el, 4, (0, 1))
    v_dofs = beam.chain_dofs(n_el, 4, (2, 3))
    both = np.concatenate([w_dofs, v_dofs], axis=1)
    size = 4 * len(nodes)
    if s.ga_flap_n is not None:
        blocks = _shear_blocks(s, b, m, ef, ee, beta, tension)[0]
    else:
        k_ww, geo, mass = beam.bending_elements(b, ei_ww, m, tension)
        k_vv, _, _ = beam.bending_elements(b, ei_vv, m)
        k_wv, _, _ = beam.bending_elements(b, ei_wv, m)
        blocks = np.zeros((4, n_el, 8, 8))  # K₀, G, M_v, M
        blocks[0, :, :4, :4] = k_ww
        blocks[0, :, 4:, 4:] = k_vv
        blocks[0, :, :4, 4:] = k_wv
        blocks[0, :, 4:, :4] = k_wv
        blocks[1, :, :4, :4] = geo
        blocks[1, :, 4:, 4:] = geo
        blocks[2, :, 4:, 4:] = mass
        blocks[3, :, :4, :4] = mass
        blocks[3, :, 4:, 4:] = mass
    kept = 0 if s.root == "free" else 4
    k0, g, m_v, mm = (beam.assemble(blk, both, size)[kept:, kept:] for blk in blocks)
    if s.tip_mass_kg:  # a point mass on the tip node's deflections (w, v): dofs −4 and −2
        for dof in (-4, -2):
            mm[dof, dof] += s.tip_mass_kg
        m_v[-2, -2] += s.tip_mass_kg
    return k0, g, m_v, mm


def _shear_blocks(
    s: BladeStructure, b: beam.Basis, m: Array, ef: Array, ee: Array, beta: Array, tension: Array
) -> tuple[Array, Array, Array]:
    """K₀, G, M_v, M of each element of a shear-deformable (Timoshenko) blade, (4, n, 8, 8)
    on the element dofs (w₁, θ_w₁, w₂, θ_w₂, v₁, θ_v₁, v₂, θ_v₂), and the deflections w
    and v at the Gauss points per element dof, (n, 4, 8) each.

    Each element is interpolated in its own principal frame, turned by its mean twist
    β_e (u_f = w·cos β_e + v·sin β_e, u_e = −w·sin β_e + v·cos β_e), each plane with its
    own φ = 12·EI/(κGA·L²) (:func:`wtvib.numerics.beam.timoshenko`); the sections'
    principal axes, at β − β_e in that frame, give the bending and shear stiffness tensors
    at each Gauss point as in the Euler–Bernoulli blade. Energy: ½∫κᵀ·EI·κ + ½∫γᵀ·κGA·γ
    (κ = Θ′, γ = w′ − Θ per plane); mass m on the deflections only (rotary inertia
    neglected); the tension on the deflections' slopes. As κGA → ∞ the blade of
    :func:`blade_parts` without shear.
    """
    span = np.asarray(s.span_m, dtype=float)
    assert s.ga_flap_n is not None and s.ga_edge_n is not None
    gf = beam.interpolate(b.x, span, np.asarray(s.ga_flap_n))
    ge = beam.interpolate(b.x, span, np.asarray(s.ga_edge_n))
    lengths = np.diff(b.nodes)
    weight = b.w / lengths[:, None]  # the Gauss weights on [0, 1]

    def mean(x: Array) -> Array:  # an element's average
        return np.asarray(np.sum(weight * x, axis=1))

    tables = [beam.timoshenko(lengths, 12 * mean(ei) / (mean(ga) * lengths**2))
              for ei, ga in ((ef, gf), (ee, ge))]  # fmt: skip
    (nf, nf1, rf, rf1), (ne, ne1, re, re1) = tables
    zero = np.zeros_like(nf)

    # element-frame rows (n, 4, 2, 8): the two planes' interpolation side by side
    def planes(a: Array, c: Array) -> Array:
        return np.stack([np.concatenate([a, zero], -1), np.concatenate([zero, c], -1)], axis=2)

    curvature, strain = planes(rf1, re1), planes(nf1 - rf, ne1 - re)
    deflection, slope = planes(nf, ne), planes(nf1, ne1)
    be = mean(beta)
    d = beta - be[:, None]
    c, sn = np.cos(d), np.sin(d)

    def tensor(f: Array, e: Array) -> Array:  # the section's tensor in the element frame
        return np.stack(
            [np.stack([f * c**2 + e * sn**2, (f - e) * sn * c], -1),
             np.stack([(f - e) * sn * c, f * sn**2 + e * c**2], -1)], -2
        )  # fmt: skip

    def energy(rows: Array, mid: Array) -> Array:
        return np.asarray(np.einsum("eg,egai,egab,egbj->eij", b.w, rows, mid, rows))

    eye = np.broadcast_to(np.eye(2), (*b.w.shape, 2, 2))
    ce, se = np.cos(be)[:, None, None], np.sin(be)[:, None, None]
    # w = u_f·cos β_e − u_e·sin β_e, v = u_f·sin β_e + u_e·cos β_e
    h_w = ce * deflection[:, :, 0] - se * deflection[:, :, 1]
    h_v = se * deflection[:, :, 0] + ce * deflection[:, :, 1]
    blocks = np.stack(
        [
            energy(curvature, tensor(ef, ee)) + energy(strain, tensor(gf, ge)),
            energy(slope, eye * tension[..., None, None]),
            np.einsum("eg,egi,egj->eij", b.w * m, h_v, h_v),
            energy(deflection, eye * m[..., None, None]),
        ]
    )
    # from the element frame to the rotor's dofs: p = T·q
    t = np.zeros((len(lengths), 8, 8))
    i4 = np.eye(4)
    t[:, :4, :4], t[:, :4, 4:] = ce * i4, se * i4
    t[:, 4:, :4], t[:, 4:, 4:] = -se * i4, ce * i4
    out = np.einsum("eki,xekl,elj->xeij", t, blocks, t)
    return out, np.einsum("egk,ekj->egj", h_w, t), np.einsum("egk,ekj->egj", h_v, t)


def deflections(s: BladeStructure, nodes: Array) -> tuple[Array, Array]:
    """How the blade model interpolates its deflections: w (out of the rotor plane) and v
    (in it) at the Gauss points of each element per element dof (w₁, w₁′ or θ₁, w₂, …,
    v₂′ or θ_v₂), (n, 4, 8) each — the Hermite cubics of an Euler–Bernoulli blade, the
    Timoshenko interpolation of a shear-deformable one (:func:`_shear_blocks`)."""
    b = beam.basis(nodes)
    if s.ga_flap_n is None:
        zero = np.zeros_like(b.n)
        return np.concatenate([b.n, zero], -1), np.concatenate([zero, b.n], -1)
    m, ef, ee, beta = _sections(s, b)
    _, h_w, h_v = _shear_blocks(s, b, m, ef, ee, beta, np.zeros_like(m))
    return h_w, h_v


def principal_twist(s: BladeStructure) -> Array:
    """The principal axes' twist along the table [deg], as lines: an axis turned by 180° is
    the same axis, so a step of more than 90° between stations is taken the short way round
    (the IEA-22's HAWC2 st file steps from −27° to 143° — 10° as axes; interpolated as
    numbers, the element between would turn through 58°)."""
    if not s.twist_deg:
        return np.zeros(len(s.span_m))
    twist = np.asarray(s.twist_deg, dtype=float)
    if np.any(np.abs(np.diff(twist)) > 90.0):
        twist = np.degrees(np.unwrap(np.radians(2 * twist)) / 2)
    return twist


def _sections(s: BladeStructure, b: beam.Basis) -> tuple[Array, Array, Array, Array]:
    """Mass per length, flapwise and edgewise bending stiffness and the principal axes'
    twist [rad] at the Gauss points (linear between the table's stations)."""
    span = np.asarray(s.span_m, dtype=float)
    m = beam.interpolate(b.x, span, np.asarray(s.mass_per_length_kg_m))
    ef = beam.interpolate(b.x, span, np.asarray(s.ei_flap_nm2))
    ee = beam.interpolate(b.x, span, np.asarray(s.ei_edge_nm2))
    return m, ef, ee, np.radians(beam.interpolate(b.x, span, principal_twist(s)))


def _centrifugal_integral(nodes: Array, m: Array, hub_radius: float) -> Array:
    """∫_x^R m(s)·(r_hub + s) ds at each Gauss point (tension per Ω²), (elements, 4)."""
    x, w = beam.gauss_points(nodes)
    seg = np.sum(w * m * (hub_radius + x), axis=1)
    beyond = np.cumsum(seg[::-1])[::-1] - seg
    top = nodes[1:, None]
    f_here = m * (hub_radius + x)
    f_top = m[:, -1:] * (hub_radius + top)
    return np.asarray(beyond[:, None] + (top - x) * 0.5 * (f_here + f_top))


#: Standstill modes the finite-element model keeps (:func:`fe_model`): the basis of a sweep
#: of four modes (RITZ_BLADE each), more than the coupled model's blade basis ever asks.
STANDSTILL_MODES = 4 * RITZ_BLADE


@dataclass(frozen=True)
class BladeFE:
    """The cantilevered blade on the default mesh: its matrices (:func:`blade_parts`) and
    its lowest standstill modes — one eigen-solve, which the blade's rotating sweep and the
    coupled model's blade basis share."""

    nodes: Array
    k0: Array
    geo: Array
    m_v: Array
    m: Array
    standstill: modal.Modes  # the lowest STANDSTILL_MODES (or all the mesh has)


def fe_model(spec: Spec) -> BladeFE:
    """The spec's blade model (computed once per spec object)."""
    s = spec.blade.structure
    assert s is not None
    out: BladeFE = spec.derived(("blade.fe", 0), s, lambda: _fe_model(s, DEFAULT_ELEMENTS))
    return out


#: A free blade's rigid-body modes in bending: a translation and a rotation in each plane.
FREE_RIGID_MODES = 4


def _fe_model(s: BladeStructure, elements: int, modes: int = STANDSTILL_MODES) -> BladeFE:
    nodes = beam.mesh(np.asarray(s.span_m, dtype=float), elements)
    k0, geo, m_v, m = blade_parts(s, nodes)
    if s.root == "clamped":
        return BladeFE(nodes, k0, geo, m_v, m, modal.solve(k0, m, min(modes, len(k0))))
    # a free beam: its rigid-body motion left out, the elastic modes M-orthogonal to it
    found = modal.solve(k0, m, min(modes + FREE_RIGID_MODES, len(k0)))
    elastic = modal.Modes(found.frequency_hz[FREE_RIGID_MODES:], found.shapes[:, FREE_RIGID_MODES:])
    return BladeFE(nodes, k0, geo, m_v, m, elastic)


def rotating_modes(
    s: BladeStructure,
    speeds: Array,
    elements: int = DEFAULT_ELEMENTS,
    count: int = 4,
    fe: BladeFE | None = None,
) -> tuple[list[str], Array, Array, Array]:
    """Bending modes over rotor speeds, followed by shape (MAC), named at standstill;
    ``fe``: the blade's model on ``elements`` already built (:func:`fe_model`).

    Returns names (``flap1``, ``edge1``, …), frequencies [Hz] of shape (speeds, count), the
    node positions and the standstill shapes.
    """
    nodes = beam.mesh(np.asarray(s.span_m, dtype=float), elements)
    need = min(RITZ_BLADE * count, 4 * len(nodes) - 4)  # a clamped root's (or the free
    # beam's rigid) 4 dofs out
    if fe is None or not np.array_equal(fe.nodes, nodes) or fe.standstill.shapes.shape[1] < need:
        fe = _fe_model(s, elements, need)
    k0, geo, m_v, m = fe.k0, fe.geo, fe.m_v, fe.m
    # the rotating problems in the basis of the lowest standstill modes (Rayleigh–Ritz):
    # K(Ω) = K₀ + Ω²(G − M_v) is linear in Ω², so every speed is one small eigenproblem,
    # all solved as one stack
    basis = fe.standstill.shapes[:, :need]
    k_r, g_r, m_r = (basis.T @ a @ basis for a in (k0, geo - m_v, m))
    first = modal.solve(k_r, m_r, count)
    stack = modal.solve_stacked(
        np.stack([k_r + om**2 * g_r for om in speeds]),
        np.broadcast_to(m_r, (len(speeds), *m_r.shape)).copy(),
        count,
    )
    freqs = np.empty((len(speeds), count))
    shapes = first.shapes
    for i, res in enumerate(stack):
        order = modal.track(basis @ shapes, basis @ res.shapes)
        freqs[i] = res.frequency_hz[order]
        shapes = res.shapes[:, order]
    full = basis @ first.shapes
    names = plane_names(full)
    return names, freqs, nodes, full


def plane_names(shapes: Array) -> list[str]:
    """flap/edge names by which plane carries more of each mode's deflection."""
    counters = {"flap": 0, "edge": 0}
    names = []
    for j in range(shapes.shape[1]):
        w = np.sum(shapes[0::4, j] ** 2)
        v = np.sum(shapes[2::4, j] ** 2)
        kind = "flap" if w >= v else "edge"
        counters[kind] += 1
        names.append(f"{kind}{counters[kind]}")
    return names


def torsion_frequency(s: BladeStructure, elements: int = DEFAULT_ELEMENTS) -> float:
    """First torsion frequency of the blade (no rotational effect), its root clamped or,
    where the spec gives the pitch drive's stiffness, on that spring in series with its
    own torsion (Hau 7.2.2: the pitch mechanism's stiffness enters the blade's torsional
    frequency). [Hz]"""
    assert s.gj_nm2 is not None and s.torsional_inertia_kgm is not None
    span = np.asarray(s.span_m, dtype=float)
    nodes = beam.mesh(span, elements)
    x, _ = beam.gauss_points(nodes)
    k, m = beam.assemble_torsion(
        nodes,
        beam.interpolate(x, span, np.asarray(s.gj_nm2)),
        beam.interpolate(x, span, np.asarray(s.torsional_inertia_kgm)),
    )
    if s.root == "free":  # the first mode turns the beam whole
        return float(modal.solve(k, m, 2).frequency_hz[1])
    if s.pitch_drive_nm_rad is None:
        return float(modal.solve(k[1:, 1:], m[1:, 1:], 1).frequency_hz[0])
    k[0, 0] += s.pitch_drive_nm_rad
    return float(modal.solve(k, m, 1).frequency_hz[0])


def structural_modes(spec: Spec) -> list[Mode]:
    """Blade modes computed from the spec's structure, with their rotating curves."""
    s = spec.blade.structure
    assert s is not None
    top = float(rpm_to_rad_s(spec.rotor.speed.overspeed)) * 1.1
    # a free beam does not turn (nothing holds it against the centrifugal force)
    speeds = np.linspace(0.0, top if s.root == "clamped" else 0.0, SPEED_SAMPLES)
    names, freqs, nodes, shapes = rotating_modes(s, speeds, fe=fe_model(spec))
    out = []
    for j, name in enumerate(names):
        if name not in ("flap1", "flap2", "edge1", "edge2"):
            continue
        plane = 0 if name.startswith("flap") else 2
        root = [] if s.root == "free" else [0.0]
        defl = np.concatenate([root, shapes[plane::4, j]])
        peak = defl[np.argmax(np.abs(defl))] or 1.0
        out.append(
            _computed(
                spec,
                name,
                float(freqs[0, j]),
                Sampled(tuple(speeds.tolist()), tuple(freqs[:, j].tolist()))
                if s.root == "clamped"
                else None,
                Shape(tuple(nodes.tolist()), tuple((defl / peak).tolist())),
            )
        )
    if s.gj_nm2 is not None:
        out.append(_computed(spec, "tor1", torsion_frequency(s), None, None))
    return out


def _computed(
    spec: Spec, name: str, f0: float, curve: SpeedCurve | None, shape: Shape | None
) -> Mode:
    given = spec.blade.modes.get(name)
    kind = name.rstrip("0123456789")
    zeta = given.damping_ratio if isinstance(given, ModeSpec) else None
    if spec.blade.stiffness_damping_s is not None:  # ζ = π·β·f of its direction
        zeta = spec.blade.stiffness_damping_s.ratio(kind, f0)
    elif spec.blade.damping_at == "blade-alone" and kind in ("flap", "edge"):
        zeta = mode_damping(spec, name, f0)
    return Mode(
        id=f"blade.{name}",
        subsystem="blade",
        description=f"{ordinal(int(name[len(kind) :]))} blade {_KIND[kind]} (computed)",
        frequency_hz=f0,
        damping_ratio=zeta,
        curve=curve,
        shape=shape,
        origin="computed",
    )


# ---------------------------------------------------------------------------------------
# ElastoDyn's damping: stiffness-proportional, each mode's ratio at its own reference


def reference(name: str) -> str:
    """The ElastoDyn degree of freedom whose damping a blade mode takes: flap1, flap2
    (every higher flapwise mode) or edge1 (every edgewise one)."""
    if name.startswith("edge"):
        return "edge1"
    return "flap1" if name in ("flap1", "flap") else "flap2"


def alone_frequencies(spec: Spec) -> dict[str, float]:
    """ElastoDyn's FreqBF(:,1) and FreqBE(1,1), the frequencies its blade damping ratios are
    given at (``blade.damping_at: blade-alone``): what each of the deck's polynomials implies
    on the blade alone — not turning, without tip mass, flapwise on the flapwise stiffness,
    edgewise on the edgewise (OpenFAST's ElastoDyn, Coeff) — else the blade's own mode at
    standstill (computed once per spec). [Hz]"""
    found: dict[str, float] = spec.derived(
        ("blade.alone_frequencies",), spec.blade, lambda: _alone_frequencies(spec)
    )
    return found


def _alone_frequencies(spec: Spec) -> dict[str, float]:
    b = spec.blade
    s = b.structure
    if s is None:
        return {}
    span = np.asarray(s.span_m, dtype=float)
    out: dict[str, float] = {}
    if not set(REFERENCES) <= set(b.polynomials):  # the blade's own modes where none given
        names, freqs, _, _ = rotating_modes(s, np.array([0.0]), count=4)
        out = {n: float(f) for n, f in zip(names, freqs[0], strict=True) if n in REFERENCES}
    for name, poly in b.polynomials.items():
        ei = s.ei_edge_nm2 if name.startswith("edge") else s.ei_flap_nm2
        f = beam.polynomial_frequency(
            span, np.asarray(ei, dtype=float), np.asarray(s.mass_per_length_kg_m, dtype=float),
            poly.coefficients, float(span[0]), float(span[-1] - span[0]),
        )  # fmt: skip
        if f is not None:
            out[name] = f
    return out


#: ElastoDyn's blade degrees of freedom, whose damping ratios the deck gives.
REFERENCES = ("flap1", "flap2", "edge1")


def mode_damping(
    spec: Spec, name: str, f: float, alone: Mapping[str, float] | None = None
) -> float:
    """The damping ratio of the blade mode ``name`` at its frequency ``f`` where the ratios
    are ElastoDyn's (``damping_at: blade-alone``): its degree of freedom's ratio
    (:func:`reference`) times f/f_alone (:func:`alone_frequencies`; ``alone``: those
    frequencies, computed once by a caller with many modes)."""
    b = spec.blade
    ref = reference(name)
    zeta = float(b.damping_by_mode.get(ref, b.damping_ratio))  # type: ignore[call-overload]
    at = (alone if alone is not None else alone_frequencies(spec)).get(ref)
    return zeta * f / at if at else zeta


# ---------------------------------------------------------------------------------------
# The subsystem protocol (wtvib.judge.analysis)

NAME = "blade"


def default_damping(spec: Spec) -> Damping:
    """The damping ratio of a blade mode without its own: ``blade.damping_ratio`` as given
    (or the schema's default, assumed); with a stiffness-proportional damping and no ratio
    given (BeamDyn's μ), the lower of the first flapwise and edgewise cantilever modes'
    π·β·f at standstill."""
    b = spec.blade
    if b.stiffness_damping_s is None or "damping_ratio" in b.model_fields_set or not b.structure:
        return section_damping(b, "blade")
    clamped = b.structure.model_copy(update={"root": "clamped"})
    names, freqs, _, _ = rotating_modes(clamped, np.array([0.0]), count=4)
    first = {n: float(f) for n, f in zip(names, freqs[0], strict=True)}
    every = {
        n: b.stiffness_damping_s.ratio(n.rstrip("0123456789"), first[n])
        for n in ("flap1", "edge1")
        if n in first
    }
    ratios = {n: z for n, z in every.items() if z > 0}  # a direction with β = 0 aside
    if not ratios:
        return Damping(0.0, "none: the stiffness-proportional damping is zero", False)
    lower = min(ratios, key=lambda n: ratios[n])
    each = ", ".join(f"{n} {ratios[n]:.3%} at {first[n]:.3g} Hz" for n in ratios)
    return Damping(
        ratios[lower],
        f"the lower of the blade's stiffness-proportional ratios π·β·f ({each})",
        False,
    )


def build_modes(spec: Spec, built: Mapping[str, list[Mode]]) -> list[Mode]:
    from . import imported  # another tool's rotating-frame blade modes, where given

    return modes(spec) + imported.modes(spec, "rotating")


def _damping_statement(spec: Spec) -> tuple[str, ...]:
    """How the blades' damping ratios are applied, where they are ElastoDyn's."""
    b = spec.blade
    if b.damping_at != "blade-alone" or b.stiffness_damping_s is not None:
        return ()
    ref = alone_frequencies(spec)
    ratios = {name: mode_damping(spec, name, ref[name], ref) for name in REFERENCES if name in ref}
    given = ", ".join(f"{n} {100 * z:.3g} % at {ref[n]:.3g} Hz" for n, z in ratios.items())
    return (
        "Blade damping as ElastoDyn applies it: each degree of freedom's ratio is that of a "
        "stiffness-proportional damping at the frequency its deck's polynomial implies on "
        f"the blade alone, not turning ({given}; ElastoDyn.f90: CBF = "
        "0.01·BldFDamp·KBF/(π·FreqBF)), so a mode at f carries ζ·f/f_alone — every higher "
        "flapwise mode the second's ratio, every edgewise mode the first's.",
    )


def analyse(spec: Spec, ctx: Context) -> Analysis:
    """The blade's resonances are judged by the audit; this says how its modes came about."""
    s = spec.blade.structure
    if s is None:
        return Analysis()
    long = beam.resampled(np.asarray(s.span_m))
    mesh = (
        f" (a uniform mesh of {beam.MAX_STATION_NODES} elements samples the table's "
        f"{len(s.span_m):,} stations)"
        if long
        else ""
    )
    if s.root == "free":
        return Analysis(
            assumptions=(
                "Blade modes computed: a free twisted beam, flap–edge coupled, at standstill "
                f"(nothing holds a free beam against the centrifugal force){mesh}; its "
                f"{FREE_RIGID_MODES} rigid-body modes in bending (0 Hz) left out.",
            )
        )
    return Analysis(
        assumptions=(
            "Blade modes computed: cantilevered twisted beam, flap–edge coupled, with "
            "centrifugal stiffening and in-plane softening at "
            f"{SPEED_SAMPLES} speeds, followed by MAC{mesh}"
            + (
                f"; the hub is {spec.rotor.hub}, the blade clamped at its root all the same"
                + (
                    " (the teeter hinge frees the rotor's asymmetric flap motion, which this "
                    "model does not have)"
                    if spec.rotor.hub == "teetered"
                    else " (its flap hinge is not modelled)"
                )
                if spec.rotor.hub in ("teetered", "hinged")
                else ""
            )
            + (
                f"; torsion on the pitch drive's {s.pitch_drive_nm_rad:.3g} N·m/rad at the "
                "root, in series with the blade's own (Hau 7.2.2)"
                if s.pitch_drive_nm_rad is not None and s.gj_nm2 is not None
                else "; torsion clamped at the root (no pitch drive stiffness given)"
                if s.gj_nm2 is not None
                else ""
            )
            + ".",
            *_damping_statement(spec),
        )
    )


SUBSYSTEM = Subsystem(
    NAME,
    build_modes,
    default_damping,
    analyse,
    part="blade",
    diagram="campbell",
    title="blades",
)
