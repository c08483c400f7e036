"""ElastoDyn's mode-shape polynomials: fitted to the finite-element modes, a deck's own
audited against them.

ElastoDyn (OpenFAST) does not compute tower or blade mode shapes: it takes each as a
polynomial φ(x) = Σ c_k·x^k, k = 2 … 6, over the flexible length (x = 0 at the root, 1 at
the tip; φ(1) = Σ c_k = 1, φ(0) = φ′(0) = 0) from the tower and blade files, and builds its
generalised mass and stiffness from them and the distributed properties. A polynomial
computed for another structure — a changed tower, head mass or blade — gives OpenFAST
other frequencies and loads without a word. This module computes the shapes as BModes
(Bir, NREL/TP-500-39133) and pyBModes compute them for ElastoDyn, fits the polynomials as
they fit them, and audits a deck's own:

* **Tower**: the finite-element tower of the spec with its tower head as ElastoDyn's
  tower-mode practice lumps it — the nacelle (its mass at its CM, its own inertias) and the
  rotor's mass at the apex with the hub's polar inertia about the shaft; the blades'
  rotational inertia is left to their own degrees of freedom, as BModes' tower-top mass and
  pyBModes' ElastoDyn adapter leave it (``_tower_top_assembly_mass``) — on the spec's
  foundation (a monopile, a platform: BModes' tower-on-support), gravity as the spec says.
  Modes 1 and 2 of each plane; on a support, the root's rigid motion is taken off before
  the fit (ElastoDyn's polynomials hold the tower's bending on its base).
* **Blade**: the cantilevered, twisted finite-element blade at a rotor speed — by
  default the highest steady one (the rated speed; the NREL 5-MW's RotSpeed, 12.1 rpm,
  which pyBModes takes): ElastoDyn adds the rotational stiffening to its generalised
  stiffness itself and keeps the shape at every speed, so the shape is best where the
  loads that matter are, at rated speed. Flap 1 and 2 and edge 1.
* **Fit**: the tower's by least squares on the finite-element mode at its nodes,
  normalised to 1 at the tip, c₆ = 1 − c₂ − … − c₅ (the constraint substituted: pyBModes
  ``fit_mode_shape``); the blade's as the Rayleigh–Ritz mode in the space ElastoDyn builds
  its blade from (the polynomial's curvature along the twisted principal axis,
  :func:`twisted_fit`), which reproduces the NREL 5-MW deck's BModes coefficients.
* **Audit**: for each deck polynomial its MAC against the computed shape (and against the
  other mode's of its plane, where a set holds the wrong one) and the frequency it implies —
  its Rayleigh quotient on the same finite-element model, which the exact mode minimises:
  a stale polynomial implies a higher frequency than the computed one. Both are judged
  against the computed polynomial, not the finite-element mode, so that what no polynomial
  of the family can carry (a twisted blade's flap–edge coupling, up to 3 % of its second
  flap frequency) is said once (:data:`FAMILY_GAP`) and not laid at the deck's door.

References
----------
G. Bir, "User's Guide to BModes", NREL/TP-500-39133 (2007); J. Jonkman et al., NREL/TP-
500-38060 (2009), §§ 2, 6 (the NREL 5-MW's polynomials from BModes); J. H. Seo, pyBModes
1.19 (``pybmodes.fitting.poly_fit``, ``pybmodes.io._elastodyn.adapter``).
"""

import functools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..errors import SpecError
from ..judge.analysis import Analysis, Context, Damping, Subsystem, no_modes
from ..numerics import beam, modal
from ..results import Check, Rule
from ..spec import Spec
from ..spec.base import ShapePolynomial
from . import blade, tower

Array = NDArray[np.float64]

#: Elements of the finite-element models the shapes are computed on: the fit needs the
#: shape at many points (the audit's own tower and blade models use 10 and 20).
ELEMENTS = 40
#: A polynomial whose MAC against its computed mode is below this warns (first modes; the
#: NREL 5-MW's own, from BModes, reach 0.999).
MAC_FIRST = 0.995
#: … second modes, whose shapes the head's inertia and the support move more.
MAC_SECOND = 0.95
#: A polynomial implying a frequency this much above the computed one's warns.
STIFFER = 0.02
#: A computed blade polynomial whose implied frequency is this far from the finite
#: element's is said to be the family's limit (the towers' fits come within 0.3 %).
FAMILY_GAP = 0.01


@dataclass(frozen=True)
class Polynomial:
    """φ(x) = Σ c_k·x^k, k = 2 … 6 (``c``: c₂ … c₆)."""

    c: tuple[float, float, float, float, float]

    def value(self, x: Array) -> Array:
        return np.asarray(sum(ck * x**k for k, ck in zip(range(2, 7), self.c, strict=True)))

    def slope(self, x: Array) -> Array:
        return np.asarray(
            sum(k * ck * x ** (k - 1) for k, ck in zip(range(2, 7), self.c, strict=True))
        )

    def curvature(self, x: Array) -> Array:
        return np.asarray(
            sum(k * (k - 1) * ck * x ** (k - 2) for k, ck in zip(range(2, 7), self.c, strict=True))
        )


@dataclass(frozen=True)
class Fit:
    """A fitted polynomial, the RMS of its residual on the tip-normalised shape, and the
    condition number of the least-squares problem (of the stations alone)."""

    polynomial: Polynomial
    rms: float
    condition: float


def fit(x: Array, y: Array) -> Fit:
    """The polynomial through a mode's displacement ``y`` at stations ``x`` ∈ [0, 1],
    normalised to 1 at the tip: least squares with c₆ = 1 − c₂ − … − c₅ substituted
    (pyBModes ``fit_mode_shape``; BModes fits the same form).

    Raises
    ------
    SpecError
        Fewer than five stations above the root, or a tip that does not move.
    """
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    if np.count_nonzero(x > 0) < 5:
        raise SpecError("a sixth-order polynomial needs the shape at five stations or more")
    if abs(y[-1]) < 1e-12 * max(float(np.abs(y).max()), 1e-300):
        raise SpecError("the mode does not move its tip: no polynomial normalised there")
    y = y / y[-1]
    a = np.column_stack([x**k - x**6 for k in range(2, 6)])
    c, *_ = np.linalg.lstsq(a, y - x**6, rcond=None)
    coeffs = (*(float(v) for v in c), 1.0 - float(np.sum(c)))
    poly = Polynomial(coeffs)  # type: ignore[arg-type]
    rms = float(np.sqrt(np.mean((poly.value(x) - y) ** 2)))
    return Fit(poly, rms, float(np.linalg.cond(a)))


def mac(a: Array, b: Array) -> float:
    """Modal assurance criterion of two shapes (unweighted). [-]"""
    a, b = np.ravel(a), np.ravel(b)
    den = float(a @ a) * float(b @ b)
    return float((a @ b) ** 2 / den) if den > 0 else 0.0


@dataclass(frozen=True)
class Row:
    """One of a deck's coefficient sets against its computed shape.

    The computed shape is the polynomial ElastoDyn's family comes nearest the finite-element
    mode with (``computed``: the tower's least-squares fit, the blade's Rayleigh–Ritz mode);
    a deck's polynomial is judged against it — its MAC, and the frequency it implies beside
    the computed one's — so that what no polynomial can carry (a blade's flap–edge coupling)
    is not laid at the deck's door. ``x`` and ``shape``: the finite-element mode's bending
    displacement at the fit's stations, normalised to the tip (what a figure draws)."""

    key: str  # ElastoDyn's name of the set (TwFAM1Sh …)
    mode: str  # the spec's name (tower.fa1, blade.flap1 …)
    frequency_hz: float  # the finite-element mode's
    computed: Fit
    computed_hz: float  # the computed polynomial's implied frequency
    computed_mac: float  # the computed polynomial's shape against the finite-element mode
    deck: Polynomial | None
    deck_hz: float | None  # the deck polynomial's implied frequency
    mac_deck: float | None  # the deck's shape against the computed one
    mac_other: float | None  # … against the computed shape of the other mode of its plane
    file: str | None
    line: int | None
    x: tuple[float, ...]
    shape: tuple[float, ...]

    @property
    def xs(self) -> Array:
        return np.asarray(self.x)

    @property
    def second(self) -> bool:
        return self.key[-3] == "2" or self.mode.endswith("2")

    @property
    def stiffer(self) -> float | None:
        """How much higher the deck's implied frequency is than the computed one's. [-]"""
        return None if self.deck_hz is None else self.deck_hz / self.computed_hz - 1

    @property
    def family_gap(self) -> float:
        """The computed polynomial's implied frequency against the finite element's: what
        ElastoDyn's shape family cannot come closer than. [-]"""
        return self.computed_hz / self.frequency_hz - 1

    def status(self) -> str:
        """pass, or warn with why (the words of :meth:`diagnosis`)."""
        return "pass" if self.diagnosis() is None else "warn"

    def diagnosis(self) -> str | None:
        """Why the deck's polynomial is not this mode's, or None where it is."""
        if self.deck is None or self.mac_deck is None or self.deck_hz is None:
            return None
        floor = MAC_SECOND if self.second else MAC_FIRST
        stiff = self.deck_hz / self.computed_hz - 1
        if self.mac_other is not None and self.mac_other > self.mac_deck and self.mac_deck < floor:
            return (
                f"the shape of the other mode of its plane (MAC {self.mac_other:.3f} against "
                f"it, {self.mac_deck:.3f} against its own)"
            )
        implied = (
            f"implying {self.deck_hz:.4g} Hz where the computed shape implies "
            f"{self.computed_hz:.4g} Hz ({stiff:+.1%}: ElastoDyn's mode of this deck is "
            "that much stiffer than its structure's)"
        )
        other = "tower or head" if self.mode.startswith("tower.") else "blade"
        if self.mac_deck < floor:
            return (
                f"the shape of another {other}: MAC {self.mac_deck:.4f} against the computed "
                f"shape (needs {floor:g}), {implied}"
            )
        if stiff > STIFFER:
            return (
                f"near the mode in shape (MAC {self.mac_deck:.4f}) but not in curvature, "
                f"{implied} — computed for another {other}"
            )
        return None


@dataclass(frozen=True)
class Shapes:
    """The computed shapes of a spec's tower and blade, with its deck's own beside them
    (what ``wtvib shapes`` prints and writes, and the figure draws)."""

    tower: tuple[Row, ...]
    blade: tuple[Row, ...]
    rpm: float
    statements: tuple[str, ...]


# ------------------------------------------------------------------------------------------
# The tower


@dataclass(frozen=True)
class Judged:
    """A finite-element model a polynomial is judged on: how a polynomial becomes one of
    its vectors (``vector``), and what of that shape a MAC compares (``measure``)."""

    k: Array
    m: Array
    vector: Callable[[Polynomial], Array]
    measure: Callable[[Polynomial], Array]

    def implied(self, p: Polynomial) -> float:
        """The frequency the polynomial's shape implies here (Rayleigh quotient). [Hz]"""
        return _rayleigh(self.k, self.m, self.vector(p))


@dataclass(frozen=True)
class _Set:
    """One coefficient set's finite-element mode and the model it is judged on, before its
    row is written: ``mode_shape`` the mode in the judged measure, ``y`` its bending at the
    stations ``x`` (tip-normalised), ``pair`` the key of the other mode of its plane."""

    key: str
    mode: str
    frequency_hz: float
    fitted: Fit
    judged: Judged
    given: ShapePolynomial | None
    mode_shape: Array
    pair: str | None
    x: Array
    y: Array


def models(spec: Spec, rpm: float | None = None) -> dict[str, Judged]:
    """Each coefficient set's model (TwFAM1Sh … BldEdgSh → :class:`Judged`): the frequency
    any polynomial implies for that mode of the spec's structure, as the audit computes it."""
    return {s.key: s.judged for s in _sets(spec, _rpm(spec, rpm))}


def _rpm(spec: Spec, rpm: float | None) -> float:
    return spec.rotor.speed.top_rpm if rpm is None else rpm


def _sets(spec: Spec, rpm: float) -> list[_Set]:
    tower_sets = _tower_sets(spec) if spec.tower.has_structure else []
    s = spec.blade.structure  # ElastoDyn's blade is cantilevered: not a beam free at its root
    blade_sets = _blade_sets(spec, rpm) if s is not None and s.root == "clamped" else []
    return [*tower_sets, *blade_sets]


def _rows(sets: Sequence[_Set]) -> list[Row]:
    """The rows of the sets: each against its computed shape and its pair's."""
    by_key = {s.key: s for s in sets}
    rows = []
    for s in sets:
        given = s.given
        deck = Polynomial(tuple(given.coefficients)) if given is not None else None  # type: ignore[arg-type]
        own = s.judged.measure(s.fitted.polynomial)
        seen = s.judged.measure(deck) if deck is not None else None
        pair = by_key.get(s.pair) if s.pair is not None else None
        other = s.judged.measure(pair.fitted.polynomial) if pair is not None else None
        rows.append(
            Row(
                s.key,
                s.mode,
                s.frequency_hz,
                s.fitted,
                s.judged.implied(s.fitted.polynomial),
                mac(own, s.mode_shape),
                deck,
                s.judged.implied(deck) if deck is not None else None,
                mac(seen, own) if seen is not None else None,
                mac(seen, other) if seen is not None and other is not None else None,
                given.file if given is not None else None,
                given.line if given is not None else None,
                tuple(s.x.tolist()),
                tuple(s.y.tolist()),
            )
        )
    return rows


def _tower_sets(spec: Spec) -> list[_Set]:
    t = spec.tower
    b = tower.discretise(t, ELEMENTS)
    head = tower.bending_head(spec)
    top = float(b.nodes[-1])
    base = min(t.polynomial_base_m, top)
    length = top - base
    out: list[_Set] = []
    for plane, keys in (("fa", ("TwFAM1Sh", "TwFAM2Sh")), ("ss", ("TwSSM1Sh", "TwSSM2Sh"))):
        k, m = tower.bending_system(b, head, t.point_masses, t.foundation, plane, t.gravity)  # type: ignore[arg-type]
        start = 2 * len(b.nodes) - k.shape[0]  # the dofs the base condition removed
        found = modal.solve(k, m, min(8, k.shape[0]))
        modes = _bending(found, b.nodes, start, base)[:2]
        for i, j in enumerate(modes):
            x, y, rigid = _tower_shape(found.shapes[:, j], b.nodes, start, base)
            judged = Judged(
                k,
                m,
                functools.partial(
                    _tower_vector, nodes=b.nodes, start=start, base=base, length=length,
                    rigid=rigid,
                ),
                functools.partial(Polynomial.value, x=x),
            )  # fmt: skip
            name = f"{plane}{i + 1}"
            out.append(
                _Set(
                    keys[i],
                    f"tower.{name}",
                    float(found.frequency_hz[j]),
                    fit(x, y),
                    judged,
                    t.polynomials.get(name),  # type: ignore[call-overload]
                    y,
                    keys[1 - i] if len(modes) == 2 else None,
                    x,
                    y / y[-1],
                )
            )
    return out


def _full(v: Array, nodes: Array, start: int) -> tuple[Array, Array]:
    """Displacement and slope at every node of a vector of the kept dofs."""
    full = np.zeros(2 * len(nodes))
    full[start:] = v
    return full[0::2], full[1::2]


def _tower_shape(v: Array, nodes: Array, start: int, base: float) -> tuple[Array, Array, Array]:
    """A tower mode's bending above the polynomials' root (its rigid motion there taken
    off, pyBModes ``_remove_root_rigid_motion``): stations x ∈ [0, 1], the bending, and
    the mode's full displacement-and-slope vector with the bending scaled to 1 at the top
    (what the polynomial replaces above the root)."""
    w, slope = _full(v, nodes, start)
    i0 = int(np.argmin(np.abs(nodes - base)))
    h = nodes[i0:] - nodes[i0]
    bend = w[i0:] - w[i0] - slope[i0] * h
    scale = bend[-1] if abs(bend[-1]) > 0 else 1.0
    x = h / h[-1]
    return x, bend, np.asarray(v / scale)


def _bending(found: modal.Modes, nodes: Array, start: int, base: float) -> list[int]:
    """The modes that bend the tower (over a platform's rigid-body modes, which only move
    its base): bending above the root at least a third of the mode's motion."""
    out = []
    for j in range(found.shapes.shape[1]):
        w, _ = _full(found.shapes[:, j], nodes, start)
        _, bend, _ = _tower_shape(found.shapes[:, j], nodes, start, base)
        if np.abs(bend).max() >= 0.3 * np.abs(w).max():
            out.append(j)
    return out


def _tower_vector(
    p: Polynomial, nodes: Array, start: int, base: float, length: float, rigid: Array
) -> Array:
    """The kept dofs of a tower shape whose bending above the root is the polynomial (its
    tip 1) on the mode's own motion below the root and rigid motion there (``rigid``: the
    mode's vector scaled so that its bending is 1 at the top)."""
    w, slope = _full(rigid, nodes, start)
    i0 = int(np.argmin(np.abs(nodes - base)))
    h = nodes[i0:] - nodes[i0]
    x = h / length
    w = w.copy()
    slope = slope.copy()
    w[i0:] = w[i0] + slope[i0] * h + p.value(x)
    slope[i0:] = slope[i0] + p.slope(x) / length
    full = np.empty(2 * len(nodes))
    full[0::2], full[1::2] = w, slope
    return full[start:]


def _rayleigh(k: Array, m: Array, v: Array) -> float:
    """The frequency a shape implies on a model, √(vᵀKv / vᵀMv)/2π. [Hz]"""
    return math.sqrt(max(float(v @ k @ v) / float(v @ m @ v), 0.0)) / (2 * math.pi)


# ------------------------------------------------------------------------------------------
# The blade


def _blade_sets(spec: Spec, rpm: float) -> list[_Set]:
    s = spec.blade.structure
    assert s is not None
    span = np.asarray(s.span_m, dtype=float)
    nodes = beam.mesh(span, ELEMENTS)
    k0, geo, m_v, m = blade.blade_parts(s, nodes)
    omega = rpm * math.pi / 30
    k = k0 + omega**2 * (geo - m_v)
    found = modal.solve(k, m, min(8, k.shape[0]))
    names = blade.plane_names(found.shapes)
    twist = np.radians(np.interp(nodes, span, blade.principal_twist(s)))
    x = (nodes - nodes[0]) / float(nodes[-1] - nodes[0])
    out = []
    for key, name, pair in (
        ("BldFl1Sh", "flap1", "BldFl2Sh"),
        ("BldFl2Sh", "flap2", "BldFl1Sh"),
        ("BldEdgSh", "edge1", None),
    ):
        if name not in names:
            continue
        v = found.shapes[:, names.index(name)]
        flap = name.startswith("flap")
        y = _tip_normalised(v, flap)
        vector = functools.partial(_blade_vector, nodes=nodes, twist=twist, flap=flap)
        out.append(
            _Set(
                key,
                f"blade.{name}",
                float(found.frequency_hz[names.index(name)]),
                twisted_fit(v, nodes, twist, flap, y, k, m),
                Judged(k, m, vector, functools.partial(_seen, vector=vector)),
                spec.blade.polynomials.get(name),  # type: ignore[call-overload]
                _deflections(v),
                pair,
                x,
                y,
            )
        )
    return out


def _tip_normalised(v: Array, flap: bool) -> Array:
    """A blade mode's out-of-plane (flap) or in-plane (edge) deflection at every node, the
    root's 0 first, scaled to 1 at the tip."""
    y = np.concatenate([[0.0], v[0 if flap else 2 :: 4]])
    peak = float(np.abs(y).max()) or 1.0
    return y / (y[-1] if abs(y[-1]) > 1e-9 * peak else peak)


def twisted_fit(
    mode: Array, nodes: Array, twist: Array, flap: bool, y: Array, k: Array, m: Array
) -> Fit:
    """The polynomial ElastoDyn's own model of the blade would take for this mode: the
    Rayleigh–Ritz mode, in the space of the shapes ElastoDyn builds from x² … x⁶ along
    the twisted principal axis (:func:`_blade_vector`), nearest the finite-element mode
    (MAC), scaled so that its coefficients add to 1 — the lowest frequency any polynomial
    of that family implies. A least-squares fit of the out-of-plane deflection, as
    pyBModes makes it, is ElastoDyn's shape only where the blade has no twist: for the
    NREL 5-MW's second flap mode it implies a frequency 6 % above the finite element's
    (tests/validation/test_polynomials.py). The RMS is that of its dominant component
    against ``y`` (the mode's, tip-normalised)."""
    basis = np.column_stack([_blade_vector(_power(n), nodes, twist, flap) for n in range(2, 7)])
    found = modal.solve(basis.T @ k @ basis, basis.T @ m @ basis, 5)
    target = _deflections(mode)
    j = max(range(5), key=lambda i: mac(_deflections(basis @ found.shapes[:, i]), target))
    q = found.shapes[:, j]
    if abs(q.sum()) < 1e-9 * np.abs(q).max():
        raise SpecError("the blade mode has no tip deflection along its axis to normalise")
    poly = Polynomial(tuple(float(v) for v in q / q.sum()))  # type: ignore[arg-type]
    mine = _deflections(_blade_vector(poly, nodes, twist, flap))
    half = len(mine) // 2
    comp = np.concatenate([[0.0], mine[:half] if flap else mine[half:]])
    scale = comp[-1] if abs(comp[-1]) > 0 else 1.0
    rms = float(np.sqrt(np.mean((comp / scale - y / y[-1]) ** 2)))
    return Fit(poly, rms, float(np.linalg.cond(basis.T @ basis)))


def _power(k: int) -> Polynomial:
    """x^k as a polynomial of the basis (its coefficient 1; they need not add to 1)."""
    c = [0.0] * 5
    c[k - 2] = 1.0
    return Polynomial(tuple(c))  # type: ignore[arg-type]


def _seen(p: Polynomial, vector: Callable[[Polynomial], Array]) -> Array:
    """A blade polynomial's deflections as ElastoDyn builds them (what the MAC compares)."""
    return _deflections(vector(p))


def _deflections(v: Array) -> Array:
    """A blade vector's out-of-plane and in-plane deflections at its nodes (no slopes)."""
    return np.concatenate([v[0::4], v[2::4]])


def _blade_vector(p: Polynomial, nodes: Array, twist: Array, flap: bool) -> Array:
    """A blade shape as ElastoDyn builds it from a polynomial: its curvature φ″ along the
    principal flap (or edge) axis, which turns with the structural twist β — in rotor axes
    (w downwind, v in the plane in the direction of rotation) the flap axis is
    (cos β, sin β), the edge axis (−sin β, cos β) (:func:`wtvib.subsystems.blade.blade_parts`'
    stiffness rotation; ElastoDyn's own, its Lj₁ = cos θ·j₁ − sin θ·j₂ with j₂ towards the
    trailing edge) — integrated twice from the clamped root. The dofs (w, w′, v, v′) of every
    node but the root."""
    length = float(nodes[-1] - nodes[0])
    fine = np.linspace(0.0, 1.0, 4001)
    beta = np.interp(fine, (nodes - nodes[0]) / length, twist)
    kappa = p.curvature(fine) / length**2
    axis = (np.cos(beta), np.sin(beta)) if flap else (-np.sin(beta), np.cos(beta))
    h = fine * length
    out = []
    for comp in axis:
        curv = kappa * comp
        slope = _integral(curv, h)
        disp = _integral(slope, h)
        out.append((np.interp(nodes - nodes[0], h, disp), np.interp(nodes - nodes[0], h, slope)))
    (w, dw), (v, dv) = out
    vec = np.stack([w, dw, v, dv], axis=1).ravel()
    return vec[4:]


def _integral(f: Array, x: Array) -> Array:
    """∫₀ˣ f, trapezoidal, from 0 at the first point."""
    return np.concatenate([[0.0], np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(x))])


# ------------------------------------------------------------------------------------------
# Both, and the check


def compute(spec: Spec, rpm: float | None = None) -> Shapes:
    """The spec's tower and blade shapes for ElastoDyn, and its deck's polynomials beside
    them; ``rpm`` the blade's speed (default: the highest steady speed, the rated one).

    Raises
    ------
    SpecError
        The spec has neither a tower structure nor a blade table to compute shapes of.
    """
    speed = spec.rotor.speed
    where = "as asked"
    if rpm is None and speed.parked:
        where = "parked"
    elif rpm is None:
        where = "the highest steady speed" + (f", from {speed.source}" if speed.source else "")
    rpm = _rpm(spec, rpm)
    rows = _rows(_sets(spec, rpm))
    rows_t = [r for r in rows if r.mode.startswith("tower.")]
    rows_b = [r for r in rows if r.mode.startswith("blade.")]
    if not rows:
        free = spec.blade.structure is not None and spec.blade.structure.root == "free"
        raise SpecError(
            "no tower structure, and a blade free at its root (a beam alone, as BeamDyn's "
            "free-free test beams are): ElastoDyn's polynomials are a cantilevered blade's — "
            "nothing to compute mode shapes of"
            if free
            else "no tower structure and no blade table: nothing to compute mode shapes of",
            source=spec.source_file,
        )
    head = tower.bending_head(spec)
    said = (
        f"tower head {head.mass_kg:,.0f} kg at x = {head.cm_downwind_m:.2f} m, z = "
        f"{head.cm_above_top_m:.2f} m (pitch {head.inertia_pitch_kgm2:,.4g}, roll "
        f"{head.inertia_roll_kgm2:,.4g} kg·m²): ElastoDyn's tower-top mass — nacelle, yaw "
        "bearing, hub, blades at the apex — the blades' rotational inertia left to their own "
        "degrees of freedom, as BModes and pyBModes lump it"
        if head is not None
        else "no tower head"
    )
    statements = (
        f"ElastoDyn mode shapes: finite elements ({ELEMENTS} elements), the tower on its "
        f"{spec.tower.foundation.kind} base, gravity {'on' if spec.tower.gravity else 'off'}, "
        f"with its {said}; the blade at {rpm:.4g} rpm ({where}; "
        "ElastoDyn keeps the shape at every speed, so it is best where the loads are, at "
        "rated speed: --rpm). The tower's polynomials fitted by least squares with their "
        "coefficients adding to 1 (BModes, pyBModes), the blade's the Rayleigh–Ritz modes "
        "in ElastoDyn's twisted shape family; each deck polynomial's MAC and implied "
        "frequency (its Rayleigh quotient on the same model) against the computed one's.",
    )
    gaps = tuple(
        f"{r.key}: no polynomial of ElastoDyn's family implies the finite element's "
        f"{r.frequency_hz:.4g} Hz closer than {r.family_gap:+.1%} (the computed one, its "
        f"Rayleigh–Ritz best, {r.computed_hz:.4g} Hz): the blade's flap and edge bending "
        "couple, which ElastoDyn's separate flap and edge shapes do not carry"
        for r in rows_b
        if abs(r.family_gap) > FAMILY_GAP
    )
    return Shapes(tuple(rows_t), tuple(rows_b), rpm, statements + gaps)


def checks(result: Shapes) -> list[Check]:
    """``polynomials.tower`` and ``polynomials.blade``: each deck polynomial against its
    computed mode — warns naming the set, its file and line, where it belongs to another
    structure, head mass or mode."""
    rule = Rule(
        f"a deck's mode-shape polynomial is its mode's: MAC ≥ {MAC_FIRST:g} (second modes "
        f"{MAC_SECOND:g}) and implied frequency within {STIFFER:.0%}",
        "ElastoDyn takes its shapes from the polynomials (OpenFAST ElastoDyn theory; Jonkman "
        "et al. 2009 §§ 2, 6: computed with BModes); the Rayleigh quotient is least for the "
        "exact mode (Meirovitch, Principles and Techniques of Vibrations, §7.5)",
    )
    out = []
    for part, rows in (("tower", result.tower), ("blade", result.blade)):
        judged = [r for r in rows if r.deck is not None]
        if not judged:
            continue
        bad = [r for r in judged if r.diagnosis() is not None]
        if bad:
            message = (
                "; ".join(f"{r.key} ({_where(r)}) is {r.diagnosis()}" for r in bad)
                + f" — `wtvib shapes` writes the {part} file with the computed ones"
            )
        else:
            worst = min(judged, key=lambda r: r.mac_deck or 0.0)
            message = (
                f"every {part} polynomial is its mode's (lowest MAC {worst.mac_deck:.4f}, "
                f"{worst.key}; implied frequencies within "
                f"{max(abs(r.stiffer or 0.0) for r in judged):.1%} of what the computed shapes "
                "imply)"
            )
        out.append(
            Check(
                f"polynomials.{part}",
                NAME,
                "warn" if bad else "pass",
                message,
                rule,
                {
                    "sets": [
                        {
                            "name": r.key,
                            "mode": r.mode,
                            "file": r.file,
                            "line": r.line,
                            "frequency_hz": round(r.frequency_hz, 6),
                            "implied_hz": round(r.deck_hz, 6) if r.deck_hz else None,
                            "computed_implied_hz": round(r.computed_hz, 6),
                            "mac": round(r.mac_deck, 6) if r.mac_deck is not None else None,
                            "mac_other_mode": round(r.mac_other, 6)
                            if r.mac_other is not None
                            else None,
                            "deck": list(r.deck.c) if r.deck else None,
                            "computed": [round(c, 6) for c in r.computed.polynomial.c],
                        }
                        for r in judged
                    ]
                },
            )
        )
    return out


def _where(r: Row) -> str:
    name = Path(r.file).name if r.file else "the deck"
    return f"{name}:{r.line}" if r.line else name


# ------------------------------------------------------------------------------------------
# Writing corrected files


def patched(text: str, rows: Sequence[Row]) -> str:
    """A tower or blade file's text with each of ``rows``' coefficient lines holding the
    computed coefficient — each value replaced where it stands, its width kept where it
    fits, every other character of the file as it was."""
    lines = text.splitlines(keepends=True)
    for r in rows:
        for k, value in zip(range(2, 7), written(r.computed.polynomial), strict=True):
            key = f"{r.key}({k})"
            i = next((n for n, ln in enumerate(lines) if _holds(ln, key)), None)
            if i is None:
                raise SpecError(f"no {key} line to write the coefficient on")
            lines[i] = _replaced(lines[i], value)
    return "".join(lines)


#: Significant digits a coefficient is written with: the second modes' coefficients run
#: to hundreds, and the written ones must still add to 1 within ElastoDyn's 0.0015.
DIGITS = 9


def written(p: Polynomial) -> tuple[float, ...]:
    """The coefficients as written: c₂ … c₅ to :data:`DIGITS` digits, c₆ = 1 less their
    written sum — what the file says adds to 1 to within rounding, not to 5e-4 a term."""
    head = [float(f"{c:.{DIGITS}g}") for c in p.c[:4]]
    return (*head, float(f"{1.0 - sum(head):.{DIGITS}g}"))


def _holds(line: str, key: str) -> bool:
    parts = line.split()
    return len(parts) >= 2 and parts[1] == key


def _replaced(line: str, value: float) -> str:
    """The line with its first token (the number) replaced by ``value``, ending in the
    column the old number ended in where the new one fits the leading blanks."""
    stripped = line.lstrip()
    token = stripped.split()[0]
    end = len(line) - len(stripped) + len(token)
    new = f"{value:.{DIGITS}g}"
    return new.rjust(end) + line[end:]


# ------------------------------------------------------------------------------------------
# The subsystem protocol (wtvib.judge.analysis): a deck's polynomials audited

NAME = "polynomials"


def default_damping(spec: Spec) -> Damping:
    return Damping(0.0, "no modes of its own", False)


build_modes = no_modes


def analyse(spec: Spec, ctx: Context) -> Analysis:
    """The deck's polynomials against the computed modes, where the spec has any."""
    if not spec.tower.polynomials and not spec.blade.polynomials:
        return Analysis()
    result = compute(spec)
    return Analysis(checks=tuple(checks(result)), results=result, assumptions=result.statements)


# ------------------------------------------------------------------------------------------
# ``wtvib shapes``: the document and the corrected files

SHAPES_SCHEMA = "wtvib-shapes/1"


def document(spec: Spec, result: Shapes, written: Sequence[str] = ()) -> dict[str, object]:
    """The ``wtvib shapes --format json`` document: every set, old and new."""

    def row(r: Row) -> dict[str, object]:
        return {
            "name": r.key,
            "mode": r.mode,
            "frequency_hz": round(r.frequency_hz, 6),
            "file": r.file,
            "line": r.line,
            "deck": list(r.deck.c) if r.deck else None,
            "deck_implied_hz": round(r.deck_hz, 6) if r.deck_hz else None,
            "mac_deck": round(r.mac_deck, 6) if r.mac_deck is not None else None,
            "mac_other_mode": round(r.mac_other, 6) if r.mac_other is not None else None,
            "computed": [round(c, 6) for c in r.computed.polynomial.c],
            "computed_implied_hz": round(r.computed_hz, 6),
            "computed_mac": round(r.computed_mac, 6),
            "fit_rms": round(r.computed.rms, 6),
            "status": r.status(),
            **({"why": r.diagnosis()} if r.diagnosis() else {}),
        }

    return {
        "schema": SHAPES_SCHEMA,
        "turbine": spec.turbine.name,
        "source_file": spec.source_file,
        "blade_rpm": result.rpm,
        "tower": [row(r) for r in result.tower],
        "blade": [row(r) for r in result.blade],
        "written": list(written),
        "assumptions": list(result.statements),
    }


def corrected(result: Shapes) -> dict[str, str]:
    """Each tower and blade file the deck's polynomials came from, its text with the
    computed coefficients (:func:`patched`), by the original's path."""
    from ..spec import read_text

    by_file: dict[str, list[Row]] = {}
    for r in (*result.tower, *result.blade):
        if r.file is not None:
            by_file.setdefault(r.file, []).append(r)
    out = {}
    for file, rows in by_file.items():
        try:
            text = read_text(Path(file), ansi=True)
        except OSError as exc:
            raise SpecError(
                f"cannot read it again to write it: {exc.strerror}", source=file
            ) from None
        out[file] = patched(text, rows)
    return out


SUBSYSTEM = Subsystem(
    NAME,
    build_modes,
    default_damping,
    analyse,
    figures=("shapes",),
)
