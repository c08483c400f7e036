"""The tower with its tower head: modes and the stiff / soft / soft-soft classification.

References
----------
Hau, *Wind Turbines*, ch. 7.5.1 (tower stiffness, Figs. 7.19 and 7.20) and 7.5.2.
"""

import functools
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from .. import spec as spec_mod
from ..judge.analysis import Analysis, Context, Damping, Subsystem, section_damping
from ..judge.excitation import Excitation, OperatingRange
from ..judge.resonance import Finding, assess, speed_span, standstill
from ..numerics import beam, modal, rigid
from ..numerics.modal import ModalError
from ..results import Check, Mode, Rule, Shape, by_frequency, ordinal
from ..rules import MarginRule, Status
from ..spec import Spec
from ..spec.tower import AddedMass
from ..units import STANDARD_GRAVITY, rad_s_to_hz, rad_s_to_rpm
from . import drivetrain, mass_damper, platform, soil
from .given import given_modes

TowerClass = Literal["stiff", "soft", "soft-soft", "resonant"]
Array = NDArray[np.float64]

_KIND = {"fa": "fore-aft bending", "ss": "side-side bending", "tor": "torsion"}


def modes(spec: Spec) -> list[Mode]:
    """Tower modes (ids ``tower.fa1``, ``tower.ss1``, ``tower.tor1`` …).

    Computed from the structure where the spec gives one; the given frequencies of modes the
    model does not compute (e.g. ``tor1`` without torsional data) are kept.
    """
    if spec.tower.rigid:  # a deck's tower with every DOF off: no tower modes
        return [_damper_mode(spec, k, d.frequency_hz, d.damping_ratio, d)
                for k, d in enumerate(_by_frequency(spec.tower.dampers), start=1)]  # fmt: skip
    if spec.tower.has_structure:
        computed = structural_modes(spec)
        ids = {m.id for m in computed}
        return sorted(computed + [m for m in _given(spec) if m.id not in ids], key=by_frequency)
    return _given(spec)


def _given(spec: Spec) -> list[Mode]:

    def describe(name: str) -> str:
        kind, k = name.rstrip("0123456789"), int(name.lstrip("afsort"))
        return f"{ordinal(k)} tower {_KIND[kind]}"

    return given_modes("tower", spec.tower.modes, describe)


def first_bending(tower_modes: Sequence[Mode]) -> Mode | None:
    """The first bending mode that classifies the tower: fore-aft, else side-side."""
    by_id = {m.id: m for m in tower_modes}
    return by_id.get("tower.fa1") or by_id.get("tower.ss1")


@dataclass(frozen=True)
class Classification:
    """Where the first bending frequency sits among the rotor excitations."""

    tower_class: TowerClass
    frequency_hz: float  # the mode's own (standstill) frequency, as everywhere in the report
    #: the mode's frequency at the highest steady speed, where the class is decided (its
    #: curve's value there; the standstill value for a mode without a curve)
    operating_hz: float
    findings: tuple[Finding, ...]
    mode_id: str = ""


def classify(
    mode: Mode,
    harmonics: Sequence[Excitation],
    blades: int,
    op: OperatingRange,
    rule: MarginRule,
    default_damping: float,
) -> Classification:
    """Classify the tower by its first bending mode (Hau ch. 7.5.1).

    Notes
    -----
    *resonant*: a dominant (1P, N_b·P) excitation violates the margin in steady operation,
    or a secondary one (kP, 1 < k < N_b) at a dwell speed. Otherwise, at the highest
    steady speed: *stiff* above N_b·P, *soft-soft* below 1P, *soft* between them — the
    mode's frequency there too (its curve's: a coupled tower mode turning with the rotor,
    or one that is a blade whirl at standstill and the tower's bending in operation, is
    classified as it is in operation).
    """
    strong = [e for e in harmonics if e.energy != "minor" and e.order <= blades]
    # Judged with fixed severities so that a relaxed severity setting cannot hide a
    # resonance from the classification.
    judge: dict[str, Status] = {"dominant": "fail", "secondary": "fail", "minor": "info"}
    findings = tuple(assess(mode, e, op, rule, judge, default_damping) for e in strong)
    f_t = float(mode.frequency_at(op.highest))
    top_1p = float(rad_s_to_hz(op.highest))
    if any(f.status == "fail" for f in findings):
        cls: TowerClass = "resonant"
    elif f_t > blades * top_1p:
        cls = "stiff"
    elif f_t < top_1p:
        cls = "soft-soft"
    else:
        cls = "soft"
    return Classification(cls, mode.frequency_hz, f_t, findings, mode.id)


def _violated(f: Finding, headline_hz: float) -> str:
    """Where a classifying excitation violates the margin: its speeds, and the numbers at
    the speed of least separation — with the mode's frequency there where its curve has
    moved from the headline's standstill value (the separation is measured there)."""
    regime = f.regime or "steady"
    spans = ", ".join(speed_span(iv) for iv in f.violations[regime])
    there = (
        f", the mode at {f.natural_hz:.3g} Hz"
        if f"{f.natural_hz:.3g}" != f"{headline_hz:.3g}"
        else ""
    )
    return (
        f"within the margin of {f.excitation.id} at {spans} ({f.excitation.id} = "
        f"{f.excitation_hz:.3g} Hz at {rad_s_to_rpm(f.speed):.3g} rpm{there}: separation "
        f"{f.margin:.1%})"
    )


def class_check(c: Classification, blades: int, op: OperatingRange, rule: MarginRule) -> Check:
    """The ``tower.class`` check: stiff and soft pass, soft-soft warns, resonant fails."""
    top = float(rad_s_to_rpm(op.highest))
    p1 = float(rad_s_to_hz(op.highest))
    where = f"at {top:.3g} rpm: 1P = {p1:.3g} Hz, {blades}P = {blades * p1:.3g} Hz"
    f_t = c.operating_hz
    # where the class was decided at the highest speed and the curve's value there differs
    # as printed (a resonant tower: where the margin fails, said with each violation)
    moved = c.tower_class != "resonant" and f"{f_t:.3g}" != f"{c.frequency_hz:.3g}"
    standstill = f"{c.frequency_hz:.3g} Hz at standstill"
    if moved:
        named = f"{c.mode_id}; {standstill}" if c.mode_id else standstill
        head = f"first bending {f_t:.3g} Hz at {top:.3g} rpm ({named})"
    else:
        named = f" ({c.mode_id})" if c.mode_id else ""
        head = f"first bending {c.frequency_hz:.3g} Hz{named}"
    startup = sorted(
        {f.excitation.id for f in c.findings if f.violations["start-up"]},
        key=lambda s: float(s.rstrip("P")),
    )
    crossed = f"; {' and '.join(startup)} sweep through it at start-up" if startup else ""
    if c.tower_class == "resonant":
        hit = [f for f in c.findings if f.status == "fail"]
        text = f"resonant: {head} " + "; ".join(_violated(f, c.frequency_hz) for f in hit)
        status = "fail"
    elif c.tower_class == "stiff":
        status, text = "pass", f"stiff: {head} above {blades}P ({where}); no start-up encounter"
    elif c.tower_class == "soft":
        band = _between(f_t, blades, p1)
        status = "pass"
        text = f"soft: {head} {band} ({where}){crossed} — the encounter of soft towers"
    else:
        status = "warn"
        text = (
            f"soft-soft: {head} below 1P ({where}){crossed}; large tower-head amplitudes "
            "(WTS-4 experience, Hau 7.5.2)"
        )
    return Check(
        id="tower.class",
        subsystem="tower",
        status=status,  # type: ignore[arg-type]
        message=text,
        rule=Rule(
            f"f_T above {blades}P: stiff; between 1P and {blades}P: soft; below 1P: soft-soft "
            f"(at the highest steady speed); resonant where {rule.label} fails in operation",
            "Hau, Wind Turbines, ch. 7.5.1 (Figs. 7.19, 7.20)",
        ),
        numbers={
            "tower_class": c.tower_class,
            "frequency_hz": c.frequency_hz,
            "frequency_hz_at_max": round(f_t, 6),
            "p1_hz_at_max": round(p1, 6),
            "startup_crossings": startup,
        },
    )


def _between(f_t: float, blades: int, p1: float) -> str:
    k = int(f_t // p1)
    return f"between {k}P and {k + 1}P" if k >= 1 else "below 1P"


# ---------------------------------------------------------------------------------------
# The structural model: a beam on its foundation with the tower head as a rigid body.

#: Elements of the default mesh (input stations are nodes too): the first two bending
#: frequencies of the NREL 5-MW tower agree to 1e-5 with a 4× finer mesh
#: (tests/validation/test_structure.py).
DEFAULT_ELEMENTS = 10

G = STANDARD_GRAVITY


@dataclass(frozen=True)
class Beam:
    """A tower discretised into elements: nodes and properties at each element's Gauss points.

    Property arrays have shape (elements, 4) (see :func:`wtvib.numerics.beam.gauss_points`).
    """

    nodes: Array
    mass: Array
    ei_fa: Array
    ei_ss: Array
    gj: Array | None
    polar: Array | None
    #: mass per length moving in bending only (water around and inside a submerged pile)
    added: Array | None = None

    @property
    def bending_mass(self) -> Array:
        """Mass per length in bending: the tower's own and the water moving with it."""
        return self.mass if self.added is None else self.mass + self.added

    @functools.cached_property
    def basis(self) -> beam.Basis:
        return beam.basis(self.nodes)

    @functools.cached_property
    def mass_above(self) -> Array:
        """Mass of the tower above each Gauss point, (elements, 4) [kg] (both bending planes
        load the tower with it: computed once)."""
        x, w = self.basis.x, self.basis.w
        element = np.sum(w * self.mass, axis=1)
        above_element = np.cumsum(element[::-1])[::-1] - element
        top = self.nodes[1:, None]
        # mass between the Gauss point and the element's top, trapezoidal in the element
        m_top = self.mass[:, -1:]
        return np.asarray(above_element[:, None] + (top - x) * 0.5 * (self.mass + m_top))


def discretise(t: "spec_mod.Tower", elements: int = DEFAULT_ELEMENTS) -> Beam:
    """Mesh a tower given by tube sections or distributed properties.

    Notes
    -----
    Tubes: A = π/4·(D² − d²), I = π/64·(D⁴ − d⁴), J = 2I with d = D − 2t, D and t linear
    between stations; mass per length ρ·A·(outfitting factor), polar mass inertia ρ·J·factor.
    """
    if t.sections is not None:
        sec, mat = t.sections, t.material
        assert mat is not None
        stations = np.asarray(sec.height_m, dtype=float)
        nodes = _nodes(t, stations, elements)
        x, _ = beam.gauss_points(nodes)
        d = beam.interpolate(x, stations, np.asarray(sec.outer_diameter_m))
        w = beam.interpolate(x, stations, np.asarray(sec.wall_thickness_m))
        inner = d - 2 * w
        area = np.pi / 4 * (d**2 - inner**2)
        second = np.pi / 64 * (d**4 - inner**4)
        return Beam(
            nodes,
            mat.density_kg_m3 * area * mat.mass_factor,
            mat.youngs_modulus_pa * second,
            mat.youngs_modulus_pa * second,
            mat.shear * 2 * second,
            mat.density_kg_m3 * 2 * second * mat.mass_factor,
            _added(t, x),
        )
    dist = t.distributed
    assert dist is not None
    stations = np.asarray(dist.height_m, dtype=float)
    nodes = _nodes(t, stations, elements)
    x, _ = beam.gauss_points(nodes)

    def at(values: list[float]) -> Array:
        return beam.interpolate(x, stations, np.asarray(values))

    return Beam(
        nodes,
        at(dist.mass_per_length_kg_m),
        at(dist.ei_fa_nm2),
        at(dist.ei_ss_nm2),
        at(dist.gj_nm2) if dist.gj_nm2 is not None else None,
        at(dist.polar_inertia_kgm) if dist.polar_inertia_kgm is not None else None,
        _added(t, x),
    )


def _nodes(t: "spec_mod.Tower", stations: Array, elements: int) -> Array:
    """The mesh: the tower's stations, its point masses' and dampers' heights and where its
    added mass breaks (:func:`added_mass_breaks`), ``elements`` divisions between them."""
    extra = [pm.height_m for pm in t.point_masses]
    extra += [d.height_m for d in t.dampers if d.on == "tower"]
    if t.added_mass is not None:
        extra += added_mass_breaks(t.added_mass).tolist()
    return beam.mesh(np.union1d(stations, np.asarray(extra, dtype=float)), elements)


#: A step of the added mass between two of its stations: a change of more than this share of
#: its largest value (the still-water line, where the water around a pile ends).
ADDED_MASS_STEP = 0.25


def added_mass_breaks(a: AddedMass) -> Array:
    """The heights the mesh needs a node at for the added mass: the ends of its table
    (outside them it is zero) and the two stations that bound each of its steps (between
    them the table is a ramp the elements' Gauss points then integrate whole).
    Not its every station: the table is interpolated at the elements' Gauss points like the
    tower's own properties, and a table sampled finely (HydroDyn's water along the IEA-15
    monopile: 401 heights) made more than :data:`wtvib.numerics.beam.MAX_STATION_NODES`
    stations, meshed uniformly — the tower's own steps smeared over an element (its second
    bending modes 4–5·10⁻⁴ off, tests/validation/test_openfast_decks.py) and 815 coordinates
    to solve in the coupled model where 111 do."""
    h = np.asarray(a.height_m, dtype=float)
    v = np.asarray(a.mass_per_length_kg_m, dtype=float)
    steps = np.flatnonzero(np.abs(np.diff(v)) > ADDED_MASS_STEP * max(float(v.max()), 0.0))
    return np.concatenate([h[[0, -1]], h[steps], h[steps + 1]])


def _added(t: "spec_mod.Tower", x: Array) -> Array | None:
    """The added mass per length at the Gauss points (zero outside its stations)."""
    a = t.added_mass
    if a is None:
        return None
    return np.interp(x, a.height_m, a.mass_per_length_kg_m, left=0.0, right=0.0)


def bending_modes(
    b: Beam,
    head: "spec_mod.TowerHead | None",
    point_masses: Sequence["spec_mod.PointMass"],
    foundation: "spec_mod.Foundation",
    direction: Literal["fa", "ss"],
    gravity: bool = True,
    count: int = 2,
    soil_factor: float = 1.0,
) -> modal.Modes:
    """Bending modes of the tower with its head, fore-aft or side-side (see
    :func:`bending_system`)."""
    k, m = bending_system(
        b, head, point_masses, foundation, direction, gravity, soil_factor=soil_factor
    )
    return modal.solve(k, m, count)


def bending_pair(
    b: Beam,
    head: "spec_mod.TowerHead | None",
    point_masses: Sequence["spec_mod.PointMass"],
    foundation: "spec_mod.Foundation",
    gravity: bool = True,
    count: int = 2,
    soil_factor: float = 1.0,
) -> tuple[modal.Modes, modal.Modes]:
    """Fore-aft and side-side modes, solved together (one stacked eigenproblem: the
    numbers of two :func:`bending_modes` calls)."""
    fa = bending_system(b, head, point_masses, foundation, "fa", gravity, soil_factor=soil_factor)
    ss = bending_system(b, head, point_masses, foundation, "ss", gravity, soil_factor=soil_factor)
    first, second = modal.solve_stacked(np.stack([fa[0], ss[0]]), np.stack([fa[1], ss[1]]), count)
    return first, second


def bending_system(
    b: Beam,
    head: "spec_mod.TowerHead | None",
    point_masses: Sequence["spec_mod.PointMass"],
    foundation: "spec_mod.Foundation",
    direction: Literal["fa", "ss"],
    gravity: bool = True,
    head_inertia: bool = True,
    soil_factor: float = 1.0,
    frequency_hz: float | None = None,
) -> tuple[Array, Array]:
    """K and M of the tower with its head in one bending plane, base condition applied
    (a monopile in soil: its mudline stiffness, every soil spring times ``soil_factor``; a
    floating platform: its added mass at ``frequency_hz``, A∞ if None).

    ``head_inertia=False`` leaves the head's inertia out of M (its weight still loads the
    tower): the coupled model (``wtvib.subsystems.coupled``) adds the head's parts itself.

    Notes
    -----
    The head is a rigid body at the top node with dofs (u, θ = u'): mass matrix
    [[M, M·z], [M·z, I + M·(z² + x²)]] with CM height z above the top and, fore-aft only,
    downwind offset x (x does not move in side-side rolling); I is the head's inertia about
    its CM (pitch for fore-aft, roll for side-side). Gravity: the tower is compressed by the
    weight above each element (geometric stiffness) and the head weight adds −M·g·z to the
    rotational stiffness at the top (P-δ). Base: clamped, lateral and rocking springs, the
    pile's mudline stiffness, or free on a floating platform, whose matrices enter at the
    base (:func:`wtvib.subsystems.platform.plane`); there the weight W of all above the base, h
    above
    the platform's reference point, adds −W·h to the base's rotational stiffness (the
    geometric stiffness counts the weight's lever from the base, a platform tilts about
    the PRP).
    """
    ei = b.ei_fa if direction == "fa" else b.ei_ss
    m_head = head.mass_kg if head else 0.0
    axial = None
    if gravity:
        xg = b.basis.x
        pm_above = sum((p.mass_kg * (xg < p.height_m) for p in point_masses), np.zeros_like(xg))
        axial = -G * (b.mass_above + pm_above + m_head)
    k, m = beam.assemble_bending(b.basis, ei, b.bending_mass, axial)
    for p in point_masses:
        i = 2 * int(np.argmin(np.abs(b.nodes - p.height_m)))
        m[i, i] += p.mass_kg
    if head is not None:
        z, x = head.cm_above_top_m, head.cm_downwind_m if direction == "fa" else 0.0
        inertia = head.inertia_pitch_kgm2 if direction == "fa" else head.inertia_roll_kgm2
        top = slice(-2, None)
        if head_inertia:
            m[top, top] += np.array(
                [[m_head, m_head * z], [m_head * z, inertia + m_head * (z**2 + x**2)]]
            )
        if gravity:
            k[-1, -1] -= m_head * G * z
    if foundation.kind == "springs":
        k[0, 0] += foundation.lateral_n_m or 0.0
        k[1, 1] += foundation.rocking_nm_rad or 0.0
        k[0, 1] += foundation.coupling_n or 0.0
        k[1, 0] += foundation.coupling_n or 0.0
        # no lateral spring given: the base is held laterally
        return _keep(k, m, slice(0 if foundation.lateral_n_m else 1, None))
    if foundation.kind == "soil":
        assert foundation.pile is not None
        k[:2, :2] += soil.head_stiffness(foundation.pile, foundation.soil, soil_factor).matrix()
        return k, m
    if foundation.kind == "platform":  # the base free on its floating platform
        floater = foundation.platform
        assert floater is not None
        m_p, k_p = platform.plane(floater, direction, frequency_hz)
        m[:2, :2] += m_p
        k[:2, :2] += k_p
        if gravity:
            k[1, 1] -= G * mass_above_base(b, head, point_masses) * floater.tower_base_m
        return k, m
    return _keep(k, m, slice(2, None))


def mass_above_base(
    b: Beam, head: "spec_mod.TowerHead | None", point_masses: Sequence["spec_mod.PointMass"]
) -> float:
    """The mass the tower's base carries: the tower's own, its point masses and the head."""
    head_mass = head.mass_kg if head is not None else 0.0
    return float(np.sum(b.mass * b.basis.w)) + head_mass + sum(q.mass_kg for q in point_masses)


def torsion_modes(
    b: Beam, head: "spec_mod.TowerHead | None", foundation: "spec_mod.Foundation", count: int = 1
) -> modal.Modes:
    """Torsion modes of the tower with the head's yaw inertia (I_yaw + M·x²) at the top."""
    return modal.solve(*torsion_system(b, head, foundation), count)


def torsion_system(
    b: Beam,
    head: "spec_mod.TowerHead | None",
    foundation: "spec_mod.Foundation",
    frequency_hz: float | None = None,
) -> tuple[Array, Array]:
    """K and M of the tower in torsion, base condition applied (clamped, or on the
    foundation's torsional spring); the head's yaw inertia at the top where a head is given
    (the coupled model passes none and adds the head's parts itself)."""
    assert b.gj is not None and b.polar is not None
    k, m = beam.assemble_torsion(b.nodes, b.gj, b.polar)
    if head is not None:
        m[-1, -1] += _yaw_inertia(head)
    if foundation.kind == "springs" and foundation.torsional_nm_rad:
        k[0, 0] += foundation.torsional_nm_rad
        return k, m
    if foundation.kind == "platform":  # the platform's yaw under the tower
        assert foundation.platform is not None
        inertia, stiffness = platform.yaw(foundation.platform, frequency_hz)
        m[0, 0] += inertia
        k[0, 0] += stiffness
        return k, m
    return _keep(k, m, slice(1, None))


def _keep(k: Array, m: Array, dofs: slice) -> tuple[Array, Array]:
    return k[dofs, dofs], m[dofs, dofs]


#: A computed tower mode below this [Hz] (a period over 15 minutes) is a mechanism, not a
#: structure: a pile or spring that carries nothing (a 1e-300 m pile wall gave
#: 0 Hz and the 1P-4P checks "passed" it).
NOT_HELD_HZ = 1e-3


def structural_modes(spec: Spec, elements: int = DEFAULT_ELEMENTS) -> list[Mode]:
    """Tower modes computed from the spec's structure: fa1, fa2, ss1, ss2 and tor1 (and, on
    a floating platform, the platform's six rigid-body modes, :func:`floating_modes`)."""
    t = spec.tower
    b = discretise(t, elements)
    if t.foundation.kind == "platform":
        return floating_modes(spec, b)
    out: list[Mode] = []
    bands = _soil_bands(spec, b) or _concrete_bands(spec, b)
    for d, (direction, res) in enumerate(zip(("fa", "ss"), _spec_bending(spec, b), strict=True)):
        for k, f in enumerate(res.frequency_hz, start=1):
            shape = res.shapes[0::2, k - 1]
            mode = _computed(spec, f"{direction}{k}", float(f), b.nodes, shape)
            if bands is not None:
                low, high = bands[0][d].frequency_hz, bands[1][d].frequency_hz
                mode = replace(mode, band_hz=(float(low[k - 1]), float(high[k - 1])))
            out.append(mode)
    if t.dampers:
        out = _with_dampers(spec, b, out)
    if b.gj is not None:
        res = torsion_modes(b, spec.tower_head, t.foundation)
        out.append(_computed(spec, "tor1", float(res.frequency_hz[0]), b.nodes, res.shapes[:, 0]))
    out.sort(key=by_frequency)
    if out[0].frequency_hz < NOT_HELD_HZ:
        raise modal.ModalError(
            f"{out[0].id} comes out at {out[0].frequency_hz:.3g} Hz — the tower "
            "is not held (its base, springs or pile carry next to no load): check "
            "tower.foundation and the tower's stiffness"
        )
    return out


#: A damper's plane and the tower's bending direction it moves in.
_DAMPER_PLANE: dict[str, Literal["fa", "ss"]] = {"fore-aft": "fa", "side-side": "ss"}


def _by_frequency(dampers: Sequence["spec_mod.MassDamper"]) -> list["spec_mod.MassDamper"]:
    return sorted(dampers, key=lambda d: d.frequency_hz)


def _with_dampers(spec: Spec, b: Beam, bare: list[Mode]) -> list[Mode]:
    """The tower's bending modes with its tuned mass dampers (:mod:`wtvib.subsystems.mass_damper`):
    in each plane that has some, the damped modes of the tower and its dampers — each
    tower mode's frequency and damping ratio as the dampers leave them, and each damper's
    own mode (``tower.damper<k>``, numbered by frequency over both planes)."""
    t = spec.tower
    out = [m for m in bare if not m.id.startswith(("tower.fa", "tower.ss"))]
    own: list[tuple[float, float, spec_mod.MassDamper]] = []
    for direction in ("fa", "ss"):
        mine = [m for m in bare if m.id.startswith(f"tower.{direction}")]
        dampers = [d for d in t.dampers if _DAMPER_PLANE[d.direction] == direction]
        if not dampers:
            out += mine
            continue
        k, m = bending_system(
            b, bending_head(spec), t.point_masses, t.foundation, direction, t.gravity
        )
        points = [mass_damper.attachment(b.nodes, k.shape[0], d) for d in dampers]

        def ratio(r: int, f: float, d: str = direction) -> float:
            # beyond the second mode: the second's ratio
            return mode_damping(spec, f"{d}{min(r + 1, 2)}", f)

        roots = mass_damper.damped_modes(k, m, dampers, points, ratio, len(mine))
        for root in roots:
            if root.bare is None:
                continue
            base = mine[root.bare]
            out.append(replace(
                base,
                frequency_hz=root.frequency_hz,
                damping_ratio=root.damping_ratio,
                damping_source=f"{_tower_ratio_source(spec)} with the tuned mass dampers "
                "(damped modes of the tower and its dampers)",
            ))  # fmt: skip
        free = [r for r in roots if r.bare is None]
        own += [(r.frequency_hz, r.damping_ratio, d) for r, d in zip(
            free, sorted(dampers, key=lambda d: d.frequency_hz), strict=False
        )]  # fmt: skip
    for number, (f, zeta, d) in enumerate(sorted(own, key=lambda x: x[0]), start=1):
        out.append(_damper_mode(spec, number, f, zeta, d))
    return out


def _tower_ratio_source(spec: Spec) -> str:
    return (
        "tower.damping_ratio (given)"
        if "damping_ratio" in spec.tower.model_fields_set
        else "the tower's damping ratio (assumed)"
    )


def _damper_mode(spec: Spec, k: int, f: float, zeta: float, damper: "spec_mod.MassDamper") -> Mode:
    """A tuned mass damper's own mode, ``tower.damper<k>``."""
    where = f"on the {damper.on} at {damper.height_m:g} m" + (
        " above the tower top" if damper.on == "nacelle" else ""
    )
    return Mode(
        id=f"tower.damper{k}",
        subsystem="tower",
        description=f"tuned mass damper {damper.name}, {damper.direction}, {where} "
        f"(own {damper.frequency_hz:.4g} Hz; computed)",
        frequency_hz=f,
        damping_ratio=zeta,
        damping_source=f"its dashpot ({damper.damping_ns_m:g} N·s/m) and the tower's damping",
        origin="computed",
    )


Pair = tuple[modal.Modes, modal.Modes]

#: The floating platform's rigid-body modes are named ``tower.platform.<motion>``.
PLATFORM_MODE = "tower.platform."


def is_platform_mode(mode_id: str) -> bool:
    """A floating platform's rigid-body mode, computed (``tower.platform.surge``) or from a
    whole-turbine model or linearisation (``system.platform.surge``)."""
    return mode_id.split(".")[1:2] == ["platform"]


#: A bending mode whose kinetic energy sits at least this much in the whole turbine's rigid
#: motion on the platform (translation and tilt about the PRP) is a platform mode (surge,
#: pitch …), the rest the tower's own bending.
PLATFORM_SHARE = 0.5
_PLATFORM = {
    "surge": "platform surge",
    "sway": "platform sway",
    "heave": "platform heave",
    "roll": "platform roll",
    "pitch": "platform pitch",
    "yaw": "platform yaw",
}


def floating_modes(spec: Spec, b: Beam) -> list[Mode]:
    """The tower on its floating platform: in each bending plane the four lowest modes of
    the tower with its base free on the platform — the two whose kinetic energy sits mostly
    in the whole turbine's rigid motion on the platform (:func:`rigid_share`) named after
    the platform's motion there (surge or pitch, sway or roll: the larger
    energy of translation or rotation at the PRP), the others the tower's bending (fa1,
    fa2 …, their base moving); torsion with the platform's yaw; heave with the whole
    turbine's mass (wtvib.subsystems.platform). Each mode has the platform's added mass at its own
    frequency (:func:`_own_frequency`)."""
    t = spec.tower
    p = t.foundation.platform
    assert p is not None
    _check_restoring(spec, b)
    out: list[Mode] = []
    for direction in ("fa", "ss"):

        def plane(f: float | None, d: Literal["fa", "ss"] = direction) -> tuple[Array, Array]:
            return bending_system(
                b, bending_head(spec), t.point_masses, t.foundation, d, t.gravity, frequency_hz=f
            )

        own = 0
        for f, x, m in _own_frequency(plane, 4):
            share = rigid_share(x, m, b.nodes + p.tower_base_m)
            if share >= PLATFORM_SHARE:
                name = platform_motion(p, direction, x[:2], f)
                out.append(_platform_mode(name, f, share))
            elif own < 2:
                own += 1
                out.append(_computed(spec, f"{direction}{own}", f, b.nodes, x[0::2]))
    above = mass_above_base(b, spec.tower_head, t.point_masses)
    out.append(_platform_mode("heave", platform.heave_frequency(p, above), 1.0))
    if b.gj is not None:

        def torsion(f: float | None) -> tuple[Array, Array]:
            return torsion_system(b, spec.tower_head, t.foundation, frequency_hz=f)

        (f_yaw, x, m), (f_tor, x_tor, _) = _own_frequency(torsion, 2)
        share = float(x[0] ** 2 * platform.yaw(p, f_yaw)[0]) / float(x @ m @ x)
        out.append(_platform_mode("yaw", f_yaw, share))
        out.append(_computed(spec, "tor1", f_tor, b.nodes, x_tor))
    else:
        head_yaw = _head_yaw(spec)

        def rigid_yaw(f: float | None) -> float:
            inertia, stiffness = platform.yaw(p, f)
            return float(np.sqrt(max(stiffness, 0.0) / (inertia + head_yaw)) / (2 * np.pi))

        out.append(_platform_mode("yaw", platform.at_own_frequency(rigid_yaw), 1.0))
    return sorted(out, key=lambda mode: mode.frequency_hz)


def _head_yaw(spec: Spec) -> float:
    """The tower head's inertia about the tower's axis that turns with the tower top
    (:func:`_yaw_inertia`, as :func:`torsion_system` has it): none where the nacelle is
    free in yaw (``Yaw.free``: an OpenFAST deck's yaw DOF without a yaw
    spring: the OC3 spar's platform then yaws at 0.130 Hz in OpenFAST's linearisation, not
    at the 0.121 Hz it has with the head turning along)."""
    h = spec.tower_head
    if h is None or spec.yaw.free:
        return 0.0
    return _yaw_inertia(h)


def _yaw_inertia(head: "spec_mod.TowerHead") -> float:
    """The head's inertia about the tower's axis: about its CM, and its mass's offset."""
    return head.inertia_yaw_kgm2 + head.mass_kg * head.cm_downwind_m**2


def rigid_share(x: Array, m: Array, heights: Array) -> float:
    """The share of a bending mode's kinetic energy in the rigid motion of the whole turbine
    on its platform: its mass-weighted projection on translation and tilt about the PRP
    (``heights`` of the nodes above it). A platform's surge or pitch moves the tower nearly
    whole (share near 1, however heavy the turbine above the platform); the tower's bending
    does not."""
    rigid = np.zeros((len(x), 2))
    rigid[0::2, 0] = 1.0  # translation
    rigid[0::2, 1], rigid[1::2, 1] = heights, 1.0  # tilt about the PRP
    return motion_share(x, m, rigid)


def motion_share(x: Array, m: Array, motions: Array) -> float:
    """The share of a mode's kinetic energy (shape ``x``, mass ``m``) in the span of the
    given motions (columns of ``motions``): its mass-weighted projection on them."""
    c = np.linalg.solve(motions.T @ m @ motions, motions.T @ m @ x)
    return float((motions @ c) @ m @ (motions @ c)) / float(x @ m @ x)


def _check_restoring(spec: Spec, b: Beam) -> None:
    """A floating turbine that capsizes or sinks has no mode to audit: its restoring in roll
    and pitch — the platform's with the whole weight's overturning moment, the rigid turbine
    tilted about the PRP (the tower model's own stiffness on that motion) — and in heave
    must be positive."""
    t = spec.tower
    p = t.foundation.platform
    assert p is not None
    planes: tuple[tuple[Literal["fa", "ss"], str, str], ...] = (
        ("fa", "pitch", "K55"),
        ("ss", "roll", "K44"),
    )
    for direction, motion, field in planes:
        k, _ = bending_system(b, spec.tower_head, t.point_masses, t.foundation, direction)
        tilt = np.empty(k.shape[0])
        tilt[0::2], tilt[1::2] = p.tower_base_m + b.nodes, 1.0  # rotation about the PRP
        restoring = float(tilt @ k @ tilt)
        if not restoring > 0:
            raise ModalError(
                f"tower.foundation.platform: the floating turbine capsizes in {motion}: its "
                f"restoring ({field} of the platform's stiffness, {restoring:.3g} N·m/rad with "
                "the whole weight's overturning moment) is not positive — check the "
                "platform's stiffness and centre of mass"
            )
    if not platform.restoring(p)[2, 2] > 0:
        raise ModalError(
            "tower.foundation.platform.stiffness: the floating turbine has no restoring in "
            "heave (K33 is not positive): it sinks"
        )


def _own_frequency(
    system: Callable[[float | None], tuple[Array, Array]], count: int
) -> list[tuple[float, Array, Array]]:
    """The lowest ``count`` modes of a tower on a platform whose added mass depends on
    frequency, each with the added mass at its own frequency: from its mode with A∞, the
    fixed point f = f(A(f)) (:func:`wtvib.subsystems.platform.at_own_frequency`), the mode followed
    by
    its shape (MAC) from step to step. Each mode's frequency, shape and mass matrix."""
    k, m = system(None)
    first = modal.solve(k, m, count)
    out = []
    for j in range(count):
        found = [(float(first.frequency_hz[j]), first.shapes[:, j], m)]

        def frequency(f: float | None, found: list[tuple[float, Array, Array]] = found) -> float:
            if f is None:
                return found[0][0]
            k, m = system(f)
            res = modal.solve(k, m, count)
            i = int(np.argmax(modal.mac(found[-1][1][:, None], res.shapes)[0]))
            found.append((float(res.frequency_hz[i]), res.shapes[:, i], m))
            return found[-1][0]

        platform.at_own_frequency(frequency)
        out.append(found[-1])
    return out


def platform_motion(
    p: "spec_mod.tower.Platform", direction: Literal["fa", "ss"], base: Array, f: float | None
) -> str:
    """Translation or rotation: which carries more of the platform's kinetic energy at the
    PRP in this mode (frequency ``f``)."""
    i, r = platform.PLANE_DOFS[direction]
    x = platform.transform(p, direction) @ base
    m = platform.mass(p, f)
    translation = m[i, i] * x[0] ** 2
    rotation = m[r, r] * x[1] ** 2
    names = {"fa": ("surge", "pitch"), "ss": ("sway", "roll")}[direction]
    return names[0] if translation >= rotation else names[1]


def _platform_mode(name: str, f: float, share: float) -> Mode:
    return Mode(
        id=PLATFORM_MODE + name,
        subsystem="tower",
        description=f"{_PLATFORM[name]} (rigid-body mode of the floating platform, "
        f"{share:.0%} of its kinetic energy in the turbine's rigid motion on it)",
        frequency_hz=f,
        origin="computed",
        condition="floating",
        status_cap="warn",
    )


def _soil_bands(spec: Spec, b: Beam) -> tuple[Pair, Pair] | None:
    """The fore-aft and side-side bending modes with lower- and upper-bound soil (a monopile
    in soil)."""
    t = spec.tower
    if t.foundation.kind != "soil":
        return None
    bounds = t.foundation.bounds
    return _spec_bending(spec, b, bounds.lower), _spec_bending(spec, b, bounds.upper)


#: A concrete tower's Young's modulus where the spec states no tolerance, as factors on the
#: given value: EN 1992-1-1 §3.1.3(2) gives the secant modulus for quartzite aggregates and
#: says to take it 10 % and 30 % lower for limestone and sandstone, 20 % higher for basalt.
CONCRETE_MODULUS = (0.7, 1.2)


def concrete_band(spec: Spec) -> bool:
    """Whether the tower is concrete with no tolerance stated on its numbers: then Hau's
    warning holds (7.5.2: "the actual natural frequencies of concrete towers differ
    considerably from the calculated values"), and its bending modes are judged as bands
    over :data:`CONCRETE_MODULUS`."""
    t = spec.tower
    if t.construction != "concrete" or t.foundation.kind != "clamped" or not t.has_structure:
        return False
    return not any(q.tolerance for p, q in spec.provenance.items() if p.startswith("tower."))


def _concrete_bands(spec: Spec, b: Beam) -> tuple[Pair, Pair] | None:
    """The bending modes with the concrete's modulus at its low and high bound."""
    if not concrete_band(spec):
        return None
    low, high = (
        replace(b, ei_fa=b.ei_fa * f, ei_ss=b.ei_ss * f) for f in CONCRETE_MODULUS
    )  # fmt: skip
    return _spec_bending(spec, low), _spec_bending(spec, high)


def bending_head(spec: Spec) -> "spec_mod.TowerHead | None":
    """The tower head as the tower's bending modes carry it. Where the spec models the
    rotor (a ``coupled`` block and a blade table), the rotor's mass sits at the apex and
    its rotational inertia is left to the degrees of freedom that carry it — the blades'
    flap and edge, the drive train's torsion — as ElastoDyn's tower modes, BModes' tower-top
    mass and pyBModes' adapter leave it: the nacelle as the head less the rotor, the rotor
    a point mass with the hub's polar inertia about the shaft (ElastoDyn's point hub). A
    rigid rotor's pitch inertia at the head (the NREL 5-MW's 19e6 kg·m²) held the second
    tower modes 22–36 % below every model of the whole turbine. Where the spec does not say
    where the rotor is, the head as given."""
    head, cm, s = spec.tower_head, spec.coupled, spec.blade.structure
    if head is None or cm is None or s is None:
        return head
    pts = rigid.rotor_points(
        s.hub_radius_m, np.asarray(s.span_m), np.asarray(s.mass_per_length_kg_m)
    )
    n = spec.rotor.blades
    hub_polar = drivetrain.hub_inertia(spec)
    m_rotor = n * (float(pts.mass.sum()) + s.tip_mass_kg) + cm.hub_mass_kg
    j_blades = n * (pts.polar() + s.tip_mass_kg * (s.hub_radius_m + float(s.span_m[-1])) ** 2)
    apex = np.array([cm.apex_downwind_m, 0.0, cm.apex_above_top_m])
    nac = rigid.nacelle(head, apex, m_rotor, j_blades + hub_polar)
    roll, pitch, yaw = (float(v) for v in nac.inertia)
    lumped = rigid.assembled(
        [
            rigid.Part("nacelle", nac.mass, float(nac.c[0]), float(nac.c[2]), pitch, roll, yaw),
            rigid.Part("rotor", m_rotor, float(apex[0]), float(apex[2]), roll=hub_polar),
        ]
    )
    return spec_mod.TowerHead.model_validate(lumped.as_head())


def _spec_bending(spec: Spec, b: Beam, soil_factor: float = 1.0) -> Pair:
    """The spec's tower bending modes, fore-aft and side-side (soil springs times
    ``soil_factor``), with the head as they carry it (:func:`bending_head`)."""
    t = spec.tower
    return bending_pair(
        b, bending_head(spec), t.point_masses, t.foundation, t.gravity, soil_factor=soil_factor
    )


def alone_frequencies(spec: Spec) -> dict[str, float]:
    """ElastoDyn's FreqTFA(:,1) and FreqTSS(:,1), the frequencies its damping is given at
    (``tower.damping_at: tower-alone``): of the first and second bending modes in each
    plane without the head, point masses, added mass or gravity, clamped where the
    polynomials start (``polynomial_base_m``: ElastoDyn's tower above a SubDyn pile or a
    platform) — what a mode's polynomial implies on the tower alone where the spec gives
    it (:func:`_polynomial_alone`), else the tower's own mode. [Hz]"""
    t = spec.tower
    given = {name: _polynomial_alone(t, name) for name in t.polynomials}
    found: dict[str, float] = {name: f for name, f in given.items() if f is not None}
    if set(found) >= {"fa1", "fa2", "ss1", "ss2"}:  # an ElastoDyn deck gives all four
        return found
    alone = t.model_copy(
        update={
            "point_masses": [],
            "added_mass": None,
            "foundation": spec_mod.Foundation(),
            "distributed": _above(t.distributed, t.polynomial_base_m),
        }
    )
    fa, ss = bending_pair(discretise(alone), None, [], alone.foundation, gravity=False)
    own = {
        f"{plane}{i + 1}": float(modes.frequency_hz[i])
        for plane, modes in (("fa", fa), ("ss", ss))
        for i in range(min(2, len(modes.frequency_hz)))
    }
    return own | found


def _polynomial_alone(t: "spec_mod.Tower", name: str) -> float | None:
    """ElastoDyn's FreqTFA(i,1) / FreqTSS(i,1) where the deck gives the mode's polynomial:
    the frequency its shape implies on the tower alone, √(∫EI·φ″² dh / ∫m·φ² dh)/2π over
    the flexible length above ``polynomial_base_m`` (ElastoDyn's KTFA(i,i) over MTFA(i,i)
    less the tower-top mass; OpenFAST ElastoDyn's SetTowerParameters). Its damping is
    given at that frequency — for a second mode, whose shape the head pins near the top,
    far below the bare tower's own second mode. [Hz] (None: no distributed table)."""
    d = t.distributed
    if d is None or t.height_m is None:
        return None
    ei = d.ei_fa_nm2 if name.startswith("fa") else d.ei_ss_nm2
    return beam.polynomial_frequency(
        np.asarray(d.height_m, dtype=float),
        np.asarray(ei, dtype=float),
        np.asarray(d.mass_per_length_kg_m, dtype=float),
        t.polynomials[name].coefficients,  # type: ignore[index]
        t.polynomial_base_m,
        t.height_m - t.polynomial_base_m,
    )


def _above(
    d: "spec_mod.DistributedTower | None", base: float
) -> "spec_mod.DistributedTower | None":
    """A distributed tower's table from ``base`` up, its heights from there (the table
    interpolated at ``base``)."""
    if d is None or base <= 0:
        return d
    h = np.asarray(d.height_m, dtype=float)
    keep = h > base
    heights = np.concatenate([[base], h[keep]])

    def at(values: Sequence[float]) -> list[float]:
        v = np.asarray(values, dtype=float)
        return [float(x) for x in np.concatenate([[np.interp(base, h, v)], v[keep]])]

    return d.model_copy(
        update={
            "height_m": (heights - base).tolist(),
            "mass_per_length_kg_m": at(d.mass_per_length_kg_m),
            "ei_fa_nm2": at(d.ei_fa_nm2),
            "ei_ss_nm2": at(d.ei_ss_nm2),
            "gj_nm2": at(d.gj_nm2) if d.gj_nm2 is not None else None,
            "polar_inertia_kgm": at(d.polar_inertia_kgm) if d.polar_inertia_kgm else None,
        }
    )


def mode_damping(spec: Spec, name: str, f: float) -> float:
    """The damping ratio of the tower mode ``name`` at its frequency ``f``: the ratio given
    (``damping_by_mode``, else ``damping_ratio``) and, where the ratios are ElastoDyn's
    (``damping_at: tower-alone``), that ratio times f/f_alone of the tower alone
    (:func:`alone_frequencies`; ElastoDyn's CTFA = 0.01·TwrFADmp·KTFA/(π·FreqTFA(:,1)), a
    stiffness-proportional damping: the NREL 5-MW's 1 % is 0.37 % on its first fore-aft
    mode under the head). A mode without such a reference (torsion) takes the ratio."""
    t = spec.tower
    if t.stiffness_damping_s is not None:  # stiffness-proportional: ζ = π·β·f
        return t.stiffness_damping_s.ratio(name.rstrip("0123456789"), f)
    zeta = t.damping_by_mode.get(name, t.damping_ratio)
    if t.damping_at != "tower-alone":
        return float(zeta)
    ref = alone_frequencies(spec).get(name)
    return float(zeta) * f / ref if ref else float(zeta)


def _computed(spec: Spec, name: str, f: float, nodes: Array, shape: Array) -> Mode:
    given = spec.tower.modes.get(name)
    zeta = given.damping_ratio if isinstance(given, spec_mod.ModeSpec) else None
    t = spec.tower
    if name in t.damping_by_mode or t.damping_at == "tower-alone" or t.stiffness_damping_s:
        zeta = mode_damping(spec, name, f)
    full = np.zeros(len(nodes))
    full[len(nodes) - len(shape) :] = shape
    peak = full[np.argmax(np.abs(full))] or 1.0
    kind, k = name.rstrip("0123456789"), int(name.lstrip("afsort"))
    return Mode(
        id=f"tower.{name}",
        subsystem="tower",
        description=f"{ordinal(k)} tower {_KIND[kind]} (computed)",
        frequency_hz=f,
        damping_ratio=zeta,
        shape=Shape(tuple(nodes.tolist()), tuple((full / peak).tolist())),
        origin="computed",
    )


# ---------------------------------------------------------------------------------------
# The subsystem protocol (wtvib.judge.analysis)

NAME = "tower"


def default_damping(spec: Spec) -> Damping:
    return section_damping(spec.tower, "tower")


def build_modes(spec: Spec, built: Mapping[str, list[Mode]]) -> list[Mode]:
    return modes(spec)


@dataclass(frozen=True)
class TowerResults:
    """What the tower's figures draw: its classification (the Campbell diagram's headline)."""

    classification: Classification


def analyse(spec: Spec, ctx: Context) -> Analysis:
    """The ``tower.class`` check, on the first bending mode as judged (the coupled one where
    the coupled model has it), placed before the tower's resonance checks."""
    statements = _statements(spec)
    if spec.rotor.speed.parked:  # no rotor speed to place the tower against
        said: tuple[Check, ...] = (
            (standstill("the turbine is parked", stability=True),) if spec.results is None else ()
        )
        return Analysis(lead=said, assumptions=statements)
    first = first_bending(ctx.own(NAME))
    if first is None:  # another tool's whole-turbine tower mode (spec.results), if any
        tool = {m.id: m for m in ctx.own("system") if m.origin == "imported"}
        first = tool.get("system.tower.fa1") or tool.get("system.tower.ss1")
    if first is not None and first.superseded_by is not None:
        first = next(m for m in ctx.modes if m.id == first.superseded_by)
    if first is None or spec.rotor.orientation == "vertical-axis":
        return Analysis(assumptions=statements)
    harmonics = [e for e in ctx.lines if e.acts_on(NAME)]
    ratio = default_damping(spec).ratio
    c = classify(first, harmonics, spec.rotor.blades, ctx.op, ctx.rule, ratio)
    check = class_check(c, spec.rotor.blades, ctx.op, ctx.rule)
    concept = concept_check(c, spec)
    lead = (check,) if concept is None else (check, concept)
    waves = wave_check(spec, ctx.own(NAME))
    return Analysis(
        lead=lead, checks=() if waves is None else (waves,), results=TowerResults(c),
        assumptions=statements,
    )  # fmt: skip


def wave_check(spec: Spec, tower_modes: Sequence[Mode]) -> Check | None:
    """``tower.platform.waves`` (information): the platform's rigid-body modes against the
    site's wave energy band where the spec gives one (``wave_periods_s``). A floating
    platform is designed with its natural periods outside the band — surge, sway and yaw
    above it, heave, roll and pitch above it or, rarely, below — so that first-order wave
    loads do not excite them directly (Jonkman 2010, NREL/TP-500-47535, §7: the OC3-Hywind's
    periods all above 25 s; DNV-ST-0119, Floating wind turbine structures, 2021). Whether a
    mode inside the band responds too much needs its damping (radiation, viscous), which
    wtvib does not model: information, not a verdict."""
    p = spec.tower.foundation.platform
    if p is None or p.wave_periods_s is None:
        return None
    short, long = p.wave_periods_s
    platform_modes = [m for m in tower_modes if is_platform_mode(m.id)]
    inside = [m for m in platform_modes if 1 / long <= m.frequency_hz <= 1 / short]
    band = f"the wave band {short:g}–{long:g} s ({1 / long:.3g}–{1 / short:.3g} Hz)"
    if inside:
        named = ", ".join(f"{m.id} {m.frequency_hz:.3g} Hz ({1 / m.frequency_hz:.3g} s)"
                          for m in inside)  # fmt: skip
        text = (
            f"{named} inside {band}: first-order wave loads excite "
            f"{'it' if len(inside) == 1 else 'them'} directly — its response depends on the "
            "platform's radiation and viscous damping, which wtvib does not model"
        )
    else:
        periods = sorted(1 / m.frequency_hz for m in platform_modes)
        text = (
            f"all {len(platform_modes)} platform modes outside {band} (their periods "
            f"{periods[0]:.3g}–{periods[-1]:.3g} s): first-order wave loads do not excite "
            "them directly"
        )
    return Check(
        id="tower.platform.waves",
        subsystem="tower",
        status="info",
        message=text,
        rule=Rule(
            "a floating platform's rigid-body periods lie outside the site's wave energy "
            "band (information: the response inside it needs hydrodynamic damping)",
            "Jonkman 2010 (NREL/TP-500-47535) §7; DNV-ST-0119 (2021), floating wind turbine "
            "structures",
        ),
        numbers={
            "wave_periods_s": [short, long],
            "inside": [m.id for m in inside],
        },
    )


def concept_check(c: Classification, spec: Spec) -> Check | None:
    """``tower.concept``: a two-bladed rotor with a hingeless hub on a flexible tower (soft or
    soft-soft). Its yaw and tilt moments alternate at 2P with the rotor's changing inertia
    (a parametric excitation) and its aerodynamic asymmetry, and reach the tower head
    undiminished — Hau 7.5.1: "a turbine with a hingeless rotor and flexible tower design
    would be an extremely hazardous concept"; a teetering hub decouples them (MOD-2, WTS-3),
    a stiff tower keeps the resonance out of the start-up (MOD-0, MOD-1, WTS-75). None for
    any other rotor."""
    if spec.rotor.blades != 2 or spec.rotor.hub in ("teetered", "hinged"):
        return None
    flexible = c.tower_class in ("soft", "soft-soft", "resonant")
    text = (
        f"hingeless two-bladed rotor on a {c.tower_class} tower (first bending "
        f"{c.frequency_hz:.3g} Hz): its 2P yaw and tilt moments reach the tower head "
        "undiminished and its first bending is met at start-up — an extremely hazardous "
        "concept (Hau 7.5.1); a teetering hub or a stiff tower is the book's remedy"
        if flexible
        else f"hingeless two-bladed rotor on a stiff tower (first bending {c.frequency_hz:.3g} "
        "Hz above 2P): the 2P yaw and tilt moments meet no tower resonance (the MOD-0 and "
        "WTS-75 concept, Hau 7.5.2)"
    )
    return Check(
        id="tower.concept",
        subsystem="tower",
        status="fail" if flexible else "pass",
        message=text,
        rule=Rule(
            "a two-bladed rotor with a hingeless hub needs a stiff tower (first bending above "
            "2P); soft and soft-soft towers need a teetering hub",
            "Hau, Wind Turbines, ch. 7.5.1 (tower torsion and bending under the two-bladed "
            "rotor's yaw moment) and 7.5.2 (MOD-0/1, MOD-2, WTS-3/4, WTS-75)",
        ),
        numbers={"tower_class": c.tower_class, "frequency_hz": c.frequency_hz},
    )


def _statements(spec: Spec) -> tuple[str, ...]:
    t = spec.tower
    if not t.has_structure:
        return ()
    kind = "tapered tube sections" if t.sections is not None else "distributed properties"
    head = spec.tower_head
    head_text = (
        f"tower head {head.mass_kg:,.0f} kg as a rigid body (CM {head.cm_downwind_m:+.2f} m "
        f"downwind, {head.cm_above_top_m:+.2f} m above the top)"
        if head
        else "no tower head given (bare tower)"
    )
    base = _foundation_statement(spec)
    table = t.sections.height_m if t.sections is not None else t.distributed.height_m  # type: ignore[union-attr]
    mesh = (
        f"a uniform mesh of {beam.MAX_STATION_NODES} elements sampling the table's "
        f"{len(table):,} stations"
        if beam.resampled(np.asarray(table))
        else f"{DEFAULT_ELEMENTS} elements"
    )
    concrete = (
        (
            f"Concrete tower with no tolerance stated: its bending stiffness taken "
            f"{CONCRETE_MODULUS[0] - 1:+.0%} … {CONCRETE_MODULUS[1] - 1:+.0%} of the given "
            "modulus (EN 1992-1-1 §3.1.3(2): the modulus by aggregate, sandstone 30 % lower, "
            "basalt 20 % higher), since concrete towers' frequencies \"differ considerably "
            'from the calculated values" (Hau 7.5.2): each bending mode is judged as its '
            f"band, f·{CONCRETE_MODULUS[0] ** 0.5:.2f} … f·{CONCRETE_MODULUS[1] ** 0.5:.2f}; a "
            "tolerance on the tower's numbers (--uncertainty) replaces it.",
        )
        if concrete_band(spec)
        else ()
    )
    return (
        f"Tower modes computed: Euler–Bernoulli beam, {mesh}, from "
        f"{kind}; {head_text}; foundation: {base}; gravity "
        f"{'included' if t.gravity else 'not included'}.",
        *concrete,
        *_damping_statement(spec),
    )


def _foundation_statement(spec: Spec) -> str:
    """What the tower stands on, as the statement of its modes says it: clamped, springs,
    a floating platform (its mass, added mass and restoring) or a monopile in soil (its
    layers and head stiffness, the soil's bounds)."""
    f = spec.tower.foundation
    if f.kind == "clamped":
        return "clamped base"
    elif f.kind == "springs":
        return (
            f"base on springs (lateral {f.lateral_n_m or '—'} N/m, rocking "
            f"{f.rocking_nm_rad or '—'} N·m/rad)"
        )
    elif f.kind == "platform":
        assert f.platform is not None
        p = f.platform
        m6, k6 = platform.mass(p), platform.restoring(p)
        added_surge = m6[0, 0] - p.mass_kg
        added_pitch = m6[4, 4] - p.inertia_pitch_kgm2 - p.mass_kg * p.cm_m**2
        return (
            f"base free on a floating platform ({p.mass_kg:,.0f} kg, CM {p.cm_m:g} m from the "
            f"PRP, tower base {p.tower_base_m:g} m above it; added mass A11 {added_surge:.3g} "
            f"kg, A55 {added_pitch:.3g} kg·m²; restoring "
            f"K11 {k6[0, 0]:.3g} N/m, K33 {k6[2, 2]:.3g} N/m, K55 {k6[4, 4]:.3g} N·m/rad "
            "with the platform's weight term, K66 "
            f"{k6[5, 5]:.3g} N·m/rad; wtvib.subsystems.platform): its surge, sway, roll and pitch "
            "in the "
            "bending planes, heave with the whole turbine's mass, yaw on the tower's torsion, "
            "each with the added mass at its own frequency; the head's rotary inertia turns "
            "whole with the tower top, which holds the first bending modes (within 3 % of "
            "pyBModes and OpenFAST on the OC3 and OC4 platforms) but puts the second bending "
            "modes low (OC4: 2.5 Hz where OpenFAST finds 3.9 Hz; the coupled model, where the "
            "spec has one, stands on the platform too and judges the tower's modes); "
            "radiation damping and viscous drag are not modelled"
        )
    else:
        assert f.pile is not None
        k = soil.head_stiffness(f.pile, f.soil)
        layers = ", ".join(
            f"{x.kind} to {x.bottom_m:g} m"
            + (f" (φ′ {x.friction_angle_deg:g}°)" if x.friction_angle_deg is not None else "")
            + (
                f" (s_u {x.undrained_shear_strength_pa / 1e3:g} kPa)"
                if x.undrained_shear_strength_pa is not None
                else ""
            )
            for x in f.soil
        )
        return (
            f"a monopile in soil at the mudline (tower base): {f.pile.diameter_m:g} m × "
            f"{f.pile.wall_thickness_m:g} m, {f.pile.embedded_length_m:g} m embedded, on "
            f"initial p-y springs ({layers}; wtvib.subsystems.soil) — K_L {k.lateral:.3g} N/m, "
            "K_LR "
            f"{k.coupling:.3g} N, K_R {k.rocking:.3g} N·m/rad; lower- and upper-bound soil "
            f"(×{f.bounds.lower:g}, ×{f.bounds.upper:g} on every spring) give each bending "
            "mode a band, judged as a band (coupled tower modes take their isolated "
            "counterpart's band as factors); torsion clamped at the mudline"
        )


def _damping_statement(spec: Spec) -> tuple[str, ...]:
    """How the tower's damping ratios are applied, where they are ElastoDyn's."""
    t = spec.tower
    if t.damping_at != "tower-alone":
        return ()
    ref = alone_frequencies(spec)
    given = ", ".join(
        f"{name} {100 * t.damping_by_mode.get(name, t.damping_ratio):.3g} % at {ref[name]:.3g} Hz"
        for name in ref
    )
    return (
        "Tower damping as ElastoDyn applies it: each mode's ratio is that of a "
        "stiffness-proportional damping at the frequency its deck's polynomial implies on "
        f"the tower alone ({given}; ElastoDyn.f90: CTFA = 0.01·TwrFADmp·KTFA/(π·FreqTFA)), so "
        "a mode at f carries ζ·f/f_alone — the first modes under the head far less than the "
        "ratio given.",
    )


#: A first tower bending frequency outside these bounds is implausible [Hz] (units? kHz,
#: rad/s?): a floating platform's pitch is not the tower's bending, and 20 Hz is a tower of
#: a few metres.
FIRST_BENDING_HZ = (0.05, 20.0)


def warnings(spec: Spec, modes: Sequence[Mode]) -> list[str]:
    """The tower's suspicious values: a first bending frequency outside
    :data:`FIRST_BENDING_HZ`."""
    low, high = FIRST_BENDING_HZ
    out = []
    for m in modes:
        if m.subsystem != NAME or not m.id.endswith(("fa1", "ss1")):
            continue
        if m.frequency_hz > high:
            out.append(
                f"{m.id}: {m.frequency_hz:.3g} Hz — a first tower bending frequency over "
                f"{high:g} Hz is implausible (units? kHz, rad/s?)"
            )
        elif m.frequency_hz < low:
            out.append(
                f"{m.id}: {m.frequency_hz:.3g} Hz — a first tower bending frequency under "
                f"{low:g} Hz is implausible"
            )
    return out


SUBSYSTEM = Subsystem(
    NAME,
    build_modes,
    default_damping,
    analyse,
    part="tower",
    warnings=warnings,
    diagram="campbell",
    title="tower",
)
