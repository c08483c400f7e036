"""Design-stage answers (Hau ch. 7.6): allowed frequency windows and tower sizing.

*Windows*: from the speed range, blade number, harmonics and margin rule, the bands in which
a subsystem's first natural frequency would pass — the complement of the bands the dominant
lines (1P, N_b·P, gear mesh) and, at a dwell speed, the secondary lines (2P on three blades)
forbid in steady operation. For the tower they are the soft-soft, soft and stiff windows.

*Sizing*: the uniform scale factor on the tower's wall thickness (or diameter, or both) that
puts the first bending frequency at a target, found by a bracketing root finder on the real
model, with the tower mass it costs — the book's point that soft towers save steel.
"""

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

import numpy as np

from . import beam, tower
from .errors import WtvibError
from .excitation import Excitation, OperatingRange, excitations, operating_range
from .results import Mode
from .rules import MarginRule
from .spec import Spec

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


def line_bands(
    lines: Sequence[Excitation], op: OperatingRange, rule: MarginRule, subsystem: str
) -> list[Band]:
    """The band each dominant (and dwelt-at secondary) line forbids in steady operation,
    one per line and steady piece; quick-pass bands are not steady operation."""
    pieces = _steady_pieces(op)
    out = []
    for e in lines:
        if not e.acts_on(subsystem) or e.energy == "minor":
            continue
        speeds = pieces if e.energy == "dominant" else [(w, w) for w in op.dwell]
        for a, b in speeds:
            lo = rule.natural_band(float(e.frequency_hz(a)))[0]
            hi = rule.natural_band(float(e.frequency_hz(b)))[1]
            out.append(Band(e.id, lo, hi))
    return out


def _steady_pieces(op: OperatingRange) -> list[tuple[float, float]]:
    pieces: list[tuple[float, float]] = []
    for a, b in op.steady:
        cuts = sorted(q for q in op.quick_pass if a <= q[0] and q[1] <= b)
        start = a
        for qa, qb in cuts:
            if qa > start:
                pieces.append((start, qa))
            start = qb
        if b >= start:
            pieces.append((start, b))
    return pieces


def _merge(bands: list[Band]) -> list[Band]:
    out: list[Band] = []
    for band in sorted(bands, key=lambda x: x.low):
        if out and band.low <= out[-1].high:
            last = out[-1]
            out[-1] = Band(f"{last.name}+{band.name}", last.low, max(last.high, band.high))
        else:
            out.append(band)
    return out


def windows(forbidden: Sequence[Band], blades: int, tower_names: bool = False) -> list[Band]:
    """Allowed windows between the forbidden bands; tower windows are named by class."""
    edges = [0.0, *[x for b in forbidden for x in (b.low, b.high)], math.inf]
    out = []
    for i in range(0, len(edges), 2):
        lo, hi = edges[i], edges[i + 1]
        if hi > lo:
            out.append(Band("", lo, hi))
    named = []
    for i, w in enumerate(out):
        if tower_names:
            name = (
                "soft-soft"
                if i == 0
                else "stiff"
                if math.isinf(w.high)
                else f"soft ({i})"
                if len(out) > 3
                else "soft"
            )
        else:
            name = f"window {i + 1}"
        named.append(Band(name, w.low, w.high))
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


def position(
    f: float, allowed: Sequence[Band], forbidden: Sequence[Band], by_line: Sequence[Band] = ()
) -> Position:
    """Where ``f`` [Hz] sits: its window, or the forbidden band that holds it — named after
    the lines whose own bands hold it (``by_line``; a merged band "2P+3P" forbids a mode
    that only 2P's band reaches in the name of 2P), and the nearest edge of a forbidden
    band."""
    inside = next((w for w in allowed if w.low <= f <= w.high), None)
    blocked = next((b for b in forbidden if b.contains(f)), None)
    holding = [b.name for b in by_line if b.contains(f)]
    if blocked is not None and holding:
        blocked = Band("+".join(dict.fromkeys(holding)), blocked.low, blocked.high)
    edges = [x for b in forbidden for x in (b.low, b.high)]
    edge = min(edges, key=lambda x: abs(x - f)) if edges else math.inf
    return Position(f, inside, blocked, edge, abs(edge - f))


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


def steady_frequency(mode: Mode, op: OperatingRange) -> float:
    """A mode's frequency where the windows hold: at the dwell speed (rated or fixed), else
    the highest steady speed; the standstill value for modes that do not vary. [Hz]"""
    speed = op.dwell[-1] if op.dwell else op.highest
    return float(mode.frequency_at([speed])[0]) if mode.curve is not None else mode.frequency_hz


def all_windows(
    spec: Spec, modes: Sequence[Mode], rule: MarginRule | None = None
) -> list[SubsystemWindows]:
    """Windows of every subsystem with modes the audit judges in steady operation, and the
    position of each such mode (the same modes ``check`` judges, under the same rule)."""
    rule = rule or spec.audit.margin_rule()
    op = operating_range(spec.rotor.speed)
    lines = excitations(spec)
    out = []
    order = [*FIRST_MODES, "system"]
    for sub in order:
        judged = [
            m
            for m in modes
            if m.subsystem == sub and m.judged and (m.regimes is None or "steady" in m.regimes)
        ]
        if not judged:
            continue
        by_line = line_bands(lines, op, rule, sub)
        forbidden = _merge(by_line)
        allowed = windows(forbidden, spec.rotor.blades, tower_names=(sub == "tower"))
        placed = tuple(
            (m.id, position(steady_frequency(m, op), allowed, forbidden, by_line)) for m in judged
        )
        first = [p for p in placed if p[1].blocked_by is not None]
        first += [p for i in FIRST_MODES.get(sub, ()) for p in placed if p[0] == i]
        gov = (first or list(placed))[0]
        out.append(SubsystemWindows(sub, gov[0], tuple(forbidden), tuple(allowed), gov[1], placed))
    return out


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


def window_goal(found: Sequence[SubsystemWindows], target: str) -> float:
    """The first-bending frequency [Hz] in the middle of the tower's ``target`` window
    (soft-soft, soft or stiff; a split soft window: its first part)."""
    tw = next((w for w in found if w.subsystem == "tower"), None)
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

    def to_dict(self) -> dict[str, object]:
        return {
            "scale": round(self.scale, 6),
            "applied_to": self.what,
            "target_hz": round(self.target_hz, 6),
            "frequency_hz": round(self.frequency_hz, 6),
            "tower_mass_before_kg": round(self.mass_before_kg, 1),
            "tower_mass_after_kg": round(self.mass_after_kg, 1),
            "mass_change_percent": round(100 * (self.mass_after_kg / self.mass_before_kg - 1), 3),
        }


def scaled(spec: Spec, s: float, what: Scale) -> Spec:
    """The spec with the tower's wall thickness and/or diameter scaled by s."""
    sec = spec.tower.sections
    if sec is None:
        raise DesignError("sizing needs the tower as tube sections (tower.sections + material)")
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
    return Sizing(s, target_hz, reached, tower_mass(spec), tower_mass(best), what)


def window_target(w: Band) -> float:
    """The middle of a window; the open stiff window aims 25 % above its lower edge and the
    soft-soft window (from 0) 25 % below its upper edge, so that neither target is absurd."""
    if math.isinf(w.high):
        return w.low * 1.25
    if w.low == 0.0:
        return w.high / 1.25
    return 0.5 * (w.low + w.high)
