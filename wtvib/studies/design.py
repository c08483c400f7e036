"""Design-stage answers (Hau ch. 7.6): allowed frequency windows and tower sizing.

*Windows*: the bands in which a subsystem's first natural frequency would pass, as the
resonance routine judges it (:func:`wtvib.judge.resonance.assess_all`, the one ``check`` uses):
the mode moved to each candidate frequency and judged against every line over the whole
operating range — steady operation, quick-pass bands, overspeed, start-up — with its
damping, energy classes and the margin rule; a band is forbidden where that would warn or
fail. So 2P swept in partial load by a variable-speed three-bladed rotor (warn) forbids
its band as ``check`` does. For the tower they are the soft-soft, soft and stiff windows.

*Sizing*: the uniform scale factor on the tower's wall thickness (or diameter, or both) that
puts the first bending frequency at a target, found by a bracketing root finder on the real
model, with the tower mass it costs — the book's point that soft towers save steel.
"""

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Literal, Protocol

import numpy as np
from numpy.typing import NDArray

from ..errors import WtvibError
from ..judge.excitation import Excitation, OperatingRange
from ..judge.resonance import Finding, acts, assess_all
from ..numerics import beam
from ..results import Mode
from ..rules import STATUS_ORDER, MarginRule, Status, worst
from ..spec import AuditSettings, Spec
from ..subsystems import tower


class Report(Protocol):
    """What the windows read of an audit's report (:class:`wtvib.audit.Report`, a layer
    above: the windows are asked of a finished audit)."""

    @property
    def spec(self) -> Spec: ...
    @property
    def settings(self) -> AuditSettings: ...
    @property
    def modes(self) -> Sequence[Mode]: ...
    @property
    def findings(self) -> Sequence[Finding]: ...
    @property
    def operating_range(self) -> OperatingRange: ...
    @property
    def rule(self) -> MarginRule: ...
    @property
    def lines(self) -> Sequence[Excitation]: ...


Scale = Literal["wall", "diameter", "both"]


class DesignError(WtvibError, ValueError):
    """A design question the spec cannot answer (e.g. sizing a tower given by frequencies)."""


@dataclass(frozen=True)
class Band:
    """A frequency band [Hz] and its name (a window, or the line that forbids it)."""

    name: str
    low: float
    high: float  # math.inf for an open window

    def contains(self, f: float) -> bool:
        return self.low < f < self.high

    def to_dict(self) -> dict[str, object]:
        return {
            "name": self.name,
            "low_hz": round(self.low, 6),
            "high_hz": None if math.isinf(self.high) else round(self.high, 6),
        }


def windows(edges: Sequence[tuple[float, float]], tower_names: bool = False) -> list[Band]:
    """Allowed windows (low, high) [Hz] named: tower windows by class (soft-soft below
    every forbidden band, stiff above them all, soft between), others numbered."""
    named = []
    for i, (lo, hi) in enumerate(edges):
        if tower_names:
            name = (
                "soft-soft"
                if i == 0 and lo == 0.0
                else "stiff"
                if math.isinf(hi)
                else f"soft ({i})"
                if len(edges) > 3
                else "soft"
            )
        else:
            name = f"window {i + 1}"
        named.append(Band(name, lo, hi))
    return named


@dataclass(frozen=True)
class Position:
    """Where a frequency sits: the window (or forbidden band) and the nearest edge."""

    frequency_hz: float
    inside: Band | None
    blocked_by: Band | None
    edge_hz: float
    distance_hz: float

    def to_dict(self) -> dict[str, object]:
        return {
            "frequency_hz": round(self.frequency_hz, 6),
            "window": self.inside.name if self.inside else None,
            "forbidden_by": self.blocked_by.name if self.blocked_by else None,
            "nearest_edge_hz": round(self.edge_hz, 6),
            "distance_hz": round(self.distance_hz, 6),
            "distance_percent": round(100 * self.distance_hz / self.frequency_hz, 3),
        }


@dataclass(frozen=True)
class SubsystemWindows:
    """A subsystem's windows and where each of its judged modes sits; ``mode_id`` and
    ``position`` are the governing one (the first forbidden, else its first mode)."""

    subsystem: str
    mode_id: str | None
    forbidden: tuple[Band, ...]
    allowed: tuple[Band, ...]
    position: Position | None
    modes: tuple[tuple[str, Position], ...] = ()

    def to_dict(self) -> dict[str, object]:
        return {
            "subsystem": self.subsystem,
            "mode": self.mode_id,
            "forbidden": [b.to_dict() for b in self.forbidden],
            "allowed": [b.to_dict() for b in self.allowed],
            "position": self.position.to_dict() if self.position else None,
            "modes": [{"id": i, **p.to_dict()} for i, p in self.modes],
        }


#: The mode a subsystem's windows are read for first (the design's governing frequency).
FIRST_MODES = {
    "tower": ("tower.fa1", "tower.ss1", "system.tower.fa1", "system.tower.ss1"),
    "blade": ("blade.flap1",),
    "drivetrain": ("drivetrain.grid.1", "drivetrain.free.1"),
    "yaw": ("yaw.1",),
}

#: Candidate frequencies per decade the windows are first judged at; each edge found
#: between two of them is then bisected to :data:`EDGE_REL`.
PER_DECADE = 120
EDGE_REL = 1e-10


@dataclass(frozen=True)
class _Scaled:
    """A mode's curve over rotor speed scaled by ``k`` (a candidate frequency)."""

    mode: Mode
    k: float

    def __call__(self, omega: NDArray[np.float64]) -> NDArray[np.float64]:
        return self.k * self.mode.frequency_at(omega)


def _candidate(mode: Mode, k: float) -> Mode:
    """The mode moved to ``k`` times its frequency at every speed — its damping, regimes,
    whirl and status cap kept: what the design would be judged as, frequency aside."""
    band = mode.band_hz
    return replace(
        mode,
        frequency_hz=k * mode.frequency_hz,
        curve=_Scaled(mode, k),
        band_hz=(k * band[0], k * band[1]) if band is not None else None,
    )


def _judged(report: Report, mode: Mode, ks: NDArray[np.float64]) -> list[tuple[Status, str]]:
    """The resonance routine's judgement of the mode moved to each factor ``ks``: the
    worst status over every line acting on it, and the lines that warn or fail there —
    exactly what ``check`` would say of a design with that frequency."""
    lines = [e for e in report.lines if acts(e, mode)]
    candidates = [_candidate(mode, float(k)) for k in ks]
    found = assess_all(
        candidates,
        lines,
        report.operating_range,
        report.rule,
        report.settings.severities(),
        mode.damping_ratio or 0.0,
        report.settings.heavy_damping_ratio,
    )
    by_mode: dict[int, list[Finding]] = {}
    for f in found:
        by_mode.setdefault(id(f.mode), []).append(f)
    out = []
    for c in candidates:
        fs = by_mode.get(id(c), [])
        status = worst([f.status for f in fs])
        bad = [f.excitation.id for f in fs if STATUS_ORDER[f.status] >= STATUS_ORDER["warn"]]
        out.append((status, "+".join(dict.fromkeys(bad))))
    return out


def _blocked(judged: tuple[Status, str]) -> bool:
    return STATUS_ORDER[judged[0]] >= STATUS_ORDER["warn"]


def _edges(report: Report, mode: Mode) -> tuple[list[tuple[float, float]], list[Band]]:
    """The allowed windows and forbidden bands [Hz] of a mode's frequency (at the dwell
    speed), found by the resonance routine on a log grid and bisected at each edge."""
    op = report.operating_range
    f0 = steady_frequency(mode, op)
    if f0 <= 0:
        return [(0.0, math.inf)], []
    lines = [e for e in report.lines if acts(e, mode)]
    top = max((float(e.frequency_hz(op.overspeed)) for e in lines), default=f0)
    low_line = min(
        (float(e.frequency_hz(max(op.lowest, 0.05 * op.highest))) for e in lines if e.order),
        default=f0,
    )
    f_lo, f_hi = 0.3 * min(low_line, f0), 1.5 * max(top, f0)
    n = max(2, int(PER_DECADE * math.log10(f_hi / f_lo)) + 1)
    ks = np.geomspace(f_lo, f_hi, n) / f0
    judged = _judged(report, mode, ks)
    flips = [i for i in range(n - 1) if _blocked(judged[i]) != _blocked(judged[i + 1])]
    lo_k, hi_k = ks[flips].copy(), ks[[i + 1 for i in flips]].copy()
    while flips and np.max(hi_k / lo_k) > 1 + EDGE_REL:  # every edge bisected at once
        mid = np.sqrt(lo_k * hi_k)
        at = _judged(report, mode, mid)
        for j, i in enumerate(flips):
            if _blocked(at[j]) == _blocked(judged[i]):
                lo_k[j] = mid[j]
            else:
                hi_k[j] = mid[j]
    cuts = [f0 * math.sqrt(a * b) for a, b in zip(lo_k, hi_k, strict=True)]
    bounds = [0.0, *cuts, math.inf]
    allowed, forbidden = [], []
    blocked = _blocked(judged[0])
    for j in range(len(bounds) - 1):
        lo, hi = bounds[j], bounds[j + 1]
        if not blocked:
            allowed.append((lo, hi))
        else:
            first, last = (flips[j - 1] + 1 if j else 0), (flips[j] if j < len(flips) else n - 1)
            names = [judged[i][1] for i in range(first, last + 1)]
            forbidden.append(Band(_joined(names), lo, hi))
        blocked = not blocked
    return allowed, forbidden


def _joined(names: Sequence[str]) -> str:
    """The lines of a forbidden band, each once, in the order they appear (``2P+3P``)."""
    return "+".join(dict.fromkeys(n for part in names for n in part.split("+") if n))


def steady_frequency(mode: Mode, op: OperatingRange) -> float:
    """A mode's frequency where the windows hold: at the dwell speed (rated or fixed), else
    the highest steady speed; the standstill value for modes that do not vary. [Hz]"""
    speed = op.dwell[-1] if op.dwell else op.highest
    return float(mode.frequency_at([speed])[0]) if mode.curve is not None else mode.frequency_hz


def all_windows(report: Report) -> list[SubsystemWindows]:
    """Windows of every subsystem with modes the audit judges in steady operation, and the
    position of each such mode — judged by the resonance routine itself, as ``check``
    judges (the same lines, regimes, energy classes, damping and rule): a window is where
    the subsystem's first mode, moved there, would be judged pass (or info); a band is
    forbidden where it would warn or fail, named by the lines that make it so. A mode's
    own position is its own findings' judgement."""
    out = []
    for sub in [*FIRST_MODES, "system"]:
        judged = [
            m
            for m in report.modes
            if m.subsystem == sub and m.judged and (m.regimes is None or "steady" in m.regimes)
        ]
        if not judged:
            continue
        first = next((m for i in FIRST_MODES.get(sub, ()) for m in judged if m.id == i), None)
        if sub == "system":
            first = next((m for m in judged if m.id.startswith("system.tower.")), first)
        lead = first or judged[0]
        edges, forbidden = _edges(report, lead)
        allowed = windows(edges, tower_names=sub in ("tower", "system"))
        placed = tuple((m.id, _position(report, m, allowed, forbidden)) for m in judged)
        gov = next((p for p in placed if p[1].blocked_by is not None), None)
        gov = gov or next((p for p in placed if p[0] == lead.id), placed[0])
        out.append(SubsystemWindows(sub, gov[0], tuple(forbidden), tuple(allowed), gov[1], placed))
    return out


def _position(
    report: Report, mode: Mode, allowed: Sequence[Band], forbidden: Sequence[Band]
) -> "Position":
    """Where a judged mode sits: its window, or the lines whose findings on it warn or fail
    (the report's own), and the nearest edge of a forbidden band."""
    f = steady_frequency(mode, report.operating_range)
    bad = [
        x.excitation.id
        for x in report.findings
        if x.mode.id == mode.id and STATUS_ORDER[x.status] >= STATUS_ORDER["warn"]
    ]
    holding = next((b for b in forbidden if b.low <= f <= b.high), None)
    blocked = None
    if bad:
        lo, hi = (holding.low, holding.high) if holding is not None else (f, f)
        blocked = Band("+".join(dict.fromkeys(bad)), lo, hi)
    inside = None if bad else next((w for w in allowed if w.low <= f <= w.high), None)
    edges = [x for b in forbidden for x in (b.low, b.high) if math.isfinite(x)]
    edge = min(edges, key=lambda x: abs(x - f)) if edges else math.inf
    return Position(f, inside, blocked, edge, abs(edge - f))


WINDOWS_SCHEMA = "wtvib-windows/1"
SIZE_SCHEMA = "wtvib-size/1"


def windows_document(spec: Spec, found: Sequence[SubsystemWindows], rule: MarginRule) -> dict:  # type: ignore[type-arg]
    """The ``wtvib window --format json`` document."""
    return {
        "schema": WINDOWS_SCHEMA,
        "turbine": spec.turbine.name,
        "rule": rule.label,
        "subsystems": [w.to_dict() for w in found],
    }


def tower_windows(found: Sequence[SubsystemWindows]) -> SubsystemWindows | None:
    """The tower's windows: its own, or — where the coupled model judges the tower's modes
    (a deck set) — those of the coupled tower mode (named by class as well)."""
    own = next((w for w in found if w.subsystem == "tower"), None)
    coupled = next(
        (
            w
            for w in found
            if w.subsystem == "system" and (w.mode_id or "").startswith("system.tower")
        ),
        None,
    )
    return own or coupled


def window_goal(found: Sequence[SubsystemWindows], target: str) -> float:
    """The first-bending frequency [Hz] in the middle of the tower's ``target`` window
    (soft-soft, soft or stiff; a split soft window: its first part)."""
    tw = tower_windows(found)
    if tw is None:
        raise DesignError("the turbine has no tower mode to place in a window")
    match = [w for w in tw.allowed if w.name == target or w.name.startswith(f"{target} (")]
    if not match:
        qualifier = " for this speed range and margin" if target == "soft" else ""
        raise DesignError(f"there is no {target} window{qualifier}")
    return window_target(match[0])


# ------------------------------------------------------------------------------------------
# Sizing


@dataclass(frozen=True)
class Sizing:
    scale: float
    target_hz: float
    frequency_hz: float
    mass_before_kg: float
    mass_after_kg: float
    what: Scale
    #: where the scaled tower leaves the range a tower can be built in (with the limit's
    #: source): a frequency reached is not a design
    warnings: tuple[str, ...] = ()

    def to_dict(self) -> dict[str, object]:
        return {
            "warnings": list(self.warnings),
            "scale": round(self.scale, 6),
            "applied_to": self.what,
            "target_hz": round(self.target_hz, 6),
            "frequency_hz": round(self.frequency_hz, 6),
            "tower_mass_before_kg": round(self.mass_before_kg, 1),
            "tower_mass_after_kg": round(self.mass_after_kg, 1),
            "mass_change_percent": round(100 * (self.mass_after_kg / self.mass_before_kg - 1), 3),
        }


def require_sections(spec: Spec) -> None:
    """Sizing scales tube sections: say so where the tower is given otherwise."""
    tower_ = spec.tower
    if tower_.sections is not None and tower_.material is not None:
        return
    given = (
        "as distributed properties (mass and stiffness per length: an ElastoDyn tower table, "
        "a windIO layup)"
        if tower_.distributed is not None
        else "by its natural frequencies"
        if tower_.modes
        else "without a structure"
    )
    how = (
        "convert it (wtvib convert) and give its sections to size it"
        if tower_.distributed is not None
        else "give its sections to size it"
    )
    raise DesignError(
        "sizing scales a tower's tube sections (tower.sections + tower.material); this one "
        f"is given {given} — {how}"
    )


#: The slenderest steel tube wall ``size`` accepts without a warning, D/t. At D/t = 400
#: (r/t = 200) the classical elastic critical meridional buckling stress of a cylinder,
#: σ_cr = 0.605·E·t/r (Timoshenko & Gere 1961 §11.4; EN 1993-1-6 Annex D.1.2.1), is 635 MPa
#: for steel — under twice the yield stress of S355, so that with the imperfection
#: reduction EN 1993-1-6 applies to a fabricated shell, local buckling, not stiffness,
#: sizes the wall there. Reference towers lie inside it: the NREL 5-MW's 157–171 (6 m /
#: 35.1 mm to 3.87 m / 24.7 mm, Jonkman et al. 2009 §6), the IEA-15's 253–327 (its windIO
#: 2.1.1 tower, the windio package's example: 10 m / 39.5 mm at the base).
STEEL_MAX_D_T = 400.0
#: The thinnest concrete tower wall ``size`` accepts without a warning [m]: two layers of
#: reinforcement with their concrete cover on both faces — EN 1992-1-1 §4.4.1 (Table 4.4N:
#: 25–45 mm minimum cover for outdoor exposure XC4–XD3, plus a 10 mm tolerance) and the bars
#: themselves leave little below 0.15 m; built concrete towers have 0.25–0.5 m walls.
CONCRETE_MIN_WALL_M = 0.15


def is_concrete(spec: Spec) -> bool:
    """Whether the tower is concrete: said so (``tower.construction``), else by its modulus
    (concrete 25–50 GPa, steel 200–210 GPa)."""
    t = spec.tower
    if t.construction is not None:
        return t.construction == "concrete"
    return t.material is not None and t.material.youngs_modulus_pa < 1.0e11


def plausibility(spec: Spec) -> list[str]:
    """Where a tower's tube sections leave what can be built: a steel wall slenderer than
    :data:`STEEL_MAX_D_T`, a concrete wall thinner than :data:`CONCRETE_MIN_WALL_M`."""
    sec = spec.tower.sections
    if sec is None:
        return []
    d = np.asarray(sec.outer_diameter_m, dtype=float)
    t = np.asarray(sec.wall_thickness_m, dtype=float)
    if is_concrete(spec):
        i = int(np.argmin(t))
        if t[i] < CONCRETE_MIN_WALL_M:
            return [
                f"tower.sections.wall_thickness_m[{i}]: a {100 * t[i]:.3g} cm concrete wall is "
                f"under {100 * CONCRETE_MIN_WALL_M:.0f} cm — too thin for its reinforcement and "
                "cover on both faces (EN 1992-1-1 §4.4.1): not a tower that can be built"
            ]
        return []
    ratio = d / t
    i = int(np.argmax(ratio))
    if ratio[i] > STEEL_MAX_D_T:
        return [
            f"tower.sections: D/t = {ratio[i]:.0f} at {sec.height_m[i]:g} m is beyond "
            f"{STEEL_MAX_D_T:.0f} — local shell buckling (0.605·E·t/r, EN 1993-1-6 Annex D) "
            "would size that wall, not its stiffness: check it before taking this design"
        ]
    return []


def scaled(spec: Spec, s: float, what: Scale) -> Spec:
    """The spec with the tower's wall thickness and/or diameter scaled by s."""
    require_sections(spec)
    sec = spec.tower.sections
    assert sec is not None
    t = [w * s for w in sec.wall_thickness_m] if what in ("wall", "both") else sec.wall_thickness_m
    d = (
        [x * s for x in sec.outer_diameter_m]
        if what in ("diameter", "both")
        else sec.outer_diameter_m
    )
    new_sec = sec.model_copy(update={"wall_thickness_m": t, "outer_diameter_m": d})
    return spec.model_copy(update={"tower": spec.tower.model_copy(update={"sections": new_sec})})


def first_bending(spec: Spec) -> float:
    b = tower.discretise(spec.tower)
    fa, ss = tower.bending_pair(
        b, spec.tower_head, spec.tower.point_masses, spec.tower.foundation, spec.tower.gravity, 1
    )
    return float(min(fa.frequency_hz[0], ss.frequency_hz[0]))


def tower_mass(spec: Spec) -> float:
    b = tower.discretise(spec.tower)
    _, w = beam.gauss_points(b.nodes)
    return float(np.sum(w * b.mass))


def size(spec: Spec, target_hz: float, what: Scale = "wall") -> Sizing:
    """Scale factor s (on wall, diameter or both) giving the target first bending frequency.

    Notes
    -----
    Solved by bisection of f(s) − f_target on a bracket grown by factors of two; f rises
    monotonically with s for wall and diameter scaling of a tube (stiffness grows faster
    than mass), which the bracket search checks. The wall may not exceed half the diameter.
    """

    if not (math.isfinite(target_hz) and target_hz > 0):
        raise DesignError(f"the target frequency must be above 0 Hz (got {target_hz:g})")

    def f(s: float) -> float:
        return first_bending(scaled(spec, s, what)) - target_hz

    lo, hi = 1.0, 1.0
    f_lo = f_hi = f(1.0)
    for _ in range(40):
        if f_lo <= 0 <= f_hi:
            break
        if f_lo > 0:
            lo /= 1.5
            f_lo = f(lo)
        if f_hi < 0:
            hi *= 1.5
            try:
                f_hi = f(hi)
            except WtvibError:
                raise DesignError(
                    f"no {what} scaling reaches {target_hz:.4g} Hz (the wall "
                    "would exceed half the diameter)"
                ) from None
    else:
        raise DesignError(f"no {what} scale factor reaches {target_hz:.4g} Hz")
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if hi - lo < 1e-10 * mid:
            break
        if f(mid) < 0:
            lo = mid
        else:
            hi = mid
    s = 0.5 * (lo + hi)
    best = scaled(spec, s, what)
    reached = first_bending(best)
    # a bracket that closed on the tower's buckling limit (frequency → 0 under its head's
    # weight) is no answer: the target must really be reached
    if abs(reached - target_hz) > 1e-3 * target_hz:
        raise DesignError(
            f"no {what} scaling reaches {target_hz:.4g} Hz: the nearest is {reached:.4g} Hz "
            f"at a scale of {s:.4g} (the tower near its buckling limit)"
        )
    return Sizing(
        s, target_hz, reached, tower_mass(spec), tower_mass(best), what, tuple(plausibility(best))
    )


def window_target(w: Band) -> float:
    """The middle of a window; the open stiff window aims 25 % above its lower edge and the
    soft-soft window (from 0) 25 % below its upper edge, so that neither target is absurd."""
    if math.isinf(w.high):
        return w.low * 1.25
    if w.low == 0.0:
        return w.high / 1.25
    return 0.5 * (w.low + w.high)
