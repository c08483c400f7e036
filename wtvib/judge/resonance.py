"""The one resonance routine: any natural frequency of any subsystem against any excitation.

For a mode and an excitation line the routine finds the rotor speeds at which the margin
rule is violated, splits them by operating regime (steady, quick-pass band, overspeed,
start-up/shut-down), and turns them into a status by the excitation's energy class:

=================  ==============================================================
regime             status
=================  ==============================================================
steady             the severity of the energy class (default: dominant and
                   secondary fail, minor info); a secondary line (2P on three
                   blades) met only away from the dwell speeds (fixed or rated
                   speed) of a variable-speed rotor is one step milder
quick-pass band    one step milder (fail → warn): the controller must not dwell
overspeed only     one step milder: a transient state (Hau ch. 7.3.4, Growian)
start-up only      info for dominant/secondary lines: the "encounter" of soft
                   designs, passed quickly (Hau ch. 7.5.1); nothing for minor ones
=================  ==============================================================
"""

import functools
import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..results import Check, Mode, Rule
from ..rules import (
    HEAVY_DAMPING,
    NEGATIVE,
    STATUS_ORDER,
    MarginRule,
    Status,
    dynamic_amplification,
    worst,
)
from ..units import rad_s_to_rpm
from .excitation import Excitation, OperatingRange

Interval = tuple[float, float]
#: (an alias, so that the functions defined inside ``assess`` for every mode and line do not
#: subscript NDArray at each definition: typing's machinery on every call)
Floats = NDArray[np.float64]

_MILDER: dict[Status, Status] = {"fail": "warn", "warn": "info", "info": "info", "pass": "pass"}


@dataclass(frozen=True)
class Finding:
    """One mode against one excitation over the whole speed range (speeds in rad/s)."""

    mode: Mode
    excitation: Excitation
    status: Status
    regime: str | None
    margin: float
    speed: float
    excitation_hz: float
    natural_hz: float
    daf: float
    crossings: tuple[float, ...]
    forbidden: tuple[Interval, ...]
    violations: dict[str, tuple[Interval, ...]]
    regime_status: dict[str, Status]
    heavily_damped: bool = False
    energy: str = "dominant"  # the line's energy class on this mode (by its whirl)
    driven_by: str | None = None  # rotating-frame harmonic behind a fixed-frame rotor mode
    whirl: str | None = None  # the whirl the class was taken from (where the line meets it)
    damping: float = 0.0  # the damping ratio the DAF was computed with (at ``speed``)
    damping_in_operation: bool = False  # ζ from the aerodynamics at the operating points
    damping_met: float = 0.0  # the damping ratio where the line meets the mode (heavy or not)
    crossing_daf: tuple[float, ...] = ()  # DAF at each crossing, 1/(2ζ) with ζ there

    def status_at(self, omega: float, op: OperatingRange) -> Status:
        """Status of a violation at one rotor speed, by the regime that speed is in (pass
        where the mode does not exist, e.g. a grid mode during start-up)."""
        regime = regime_of(omega, op)
        if self.mode.regimes is not None and regime not in self.mode.regimes:
            return "pass"
        return self.regime_status[regime]


def assess(
    mode: Mode,
    exc: Excitation,
    op: OperatingRange,
    rule: MarginRule,
    severity: Mapping[str, Status],
    default_damping: float,
    heavy_damping: float = HEAVY_DAMPING,
) -> Finding:
    """Judge one mode against one excitation line over 0 → overspeed."""
    return _assess([(mode, exc)], op, rule, severity, default_damping, heavy_damping)[0]


def _assess(
    pairs: Sequence[tuple[Mode, Excitation]],
    op: OperatingRange,
    rule: MarginRule,
    severity: Mapping[str, Status],
    default_damping: float,
    heavy_damping: float,
) -> list[Finding]:
    """Judge modes against lines, pair by pair: the speed grid, the crossings and the edges
    of the forbidden runs of every pair computed together (a few array calls for all of
    them), each pair then judged on its own."""
    if not pairs:
        return []
    ev = _Pairs.of(pairs, rule)
    grid = _grid(op)
    diff, sep = ev.on_grid(grid)
    crossings = _crossings(ev, grid, diff)
    forbidden = _forbidden(ev, grid, sep, crossings)
    on_steady = ev.on_grid(_judged_speeds(op.steady))[1]
    return [
        _judge(
            mode,
            exc,
            ev.band[p],
            crossings[p],
            forbidden[p],
            on_steady[p],
            op,
            rule,
            severity,
            default_damping,
            heavy_damping,
        )
        for p, (mode, exc) in enumerate(pairs)
    ]


def _judge(
    mode: Mode,
    exc: Excitation,
    band: Floats,
    crossings: tuple[float, ...],
    forbidden: tuple[Interval, ...],
    on_steady: Floats,
    op: OperatingRange,
    rule: MarginRule,
    severity: Mapping[str, Status],
    default_damping: float,
    heavy_damping: float,
) -> Finding:
    """One pair's finding from its crossings, forbidden speed runs and separation at the
    steady speeds."""

    def sep(omega: Floats) -> Floats:
        return _separation(rule, exc.frequency_hz(omega), mode.frequency_at(omega), *band)

    def gap(omega: float) -> float:
        return float(sep(np.array([omega]))[0] - rule.margin * (1.0 - 1e-9))

    violations = split_by_regime(forbidden, op, lambda w: gap(w) < 0)
    if mode.regimes is not None:  # a condition that exists only in some regimes
        violations = {k: (v if k in mode.regimes else ()) for k, v in violations.items()}
    speed, margin = _worst_judged(sep, op, crossings, mode.regimes, on_steady)
    # a fixed-frame rotor mode takes the class of the blade harmonic that drives it, at the
    # speed where it is met (its whirl can change along the curve)
    at = next((0.5 * (a + b) for r in _REGIMES for a, b in violations[r][:1]), speed)
    whirl = mode.whirl.at(at) if mode.whirl is not None else None
    line_energy = exc.energy_for(whirl)
    harmonic = exc.blade_harmonic(whirl)
    driven_by = f"{harmonic}P" if harmonic is not None else None
    if line_energy is None:  # e.g. forward whirl on 1P: a steady blade load, no vibration
        violations = {k: () for k in violations}
        line_energy = "minor"
    energy = severity[line_energy]
    if line_energy == "secondary" and not any(gap(w) < 0 for w in op.dwell):
        energy = _MILDER[energy]  # swept through in partial load, not dwelt at (Hau 7.5.2)
    # the damping where the line meets the mode (in operation: the aerodynamics' lowest
    # at that rotor speed, structural included)
    zeta_met = mode.damping_at(at, default_damping)
    heavily_damped = zeta_met >= heavy_damping
    regime_status = _regime_statuses(energy, line_energy, heavily_damped, mode.status_cap)
    if zeta_met < -NEGATIVE:  # negatively damped where it is met: any line's energy grows
        regime_status = {
            k: (v if k == "start-up" or STATUS_ORDER[v] >= STATUS_ORDER["warn"] else "warn")
            for k, v in regime_status.items()
        }
    status, regime = _governing(regime_status, violations)

    f_e, f_n, zeta, daf = _amplification(mode, exc, speed, default_damping)
    return Finding(
        mode,
        exc,
        status,
        regime,
        margin,
        speed,
        f_e,
        f_n,
        daf,
        crossings,
        forbidden,
        violations,
        regime_status,
        heavily_damped,
        line_energy,
        driven_by,
        whirl,
        zeta,
        mode.operating is not None,
        zeta_met,
        tuple(  # at each crossing η = 1: 1/(2ζ) with the ζ the mode has there
            float(dynamic_amplification(1.0, max(mode.damping_at(c, default_damping), 0.0)))
            for c in crossings
        ),
    )


def _amplification(
    mode: Mode, exc: Excitation, speed: float, default_damping: float
) -> tuple[float, float, float, float]:
    """At rotor speed ``speed`` [rad/s]: the line's and the mode's frequencies [Hz], the
    mode's damping ratio there and the dynamic amplification factor."""
    w = np.array([speed])
    f_e = float(exc.frequency_hz(w)[0])
    f_n = float(mode.frequency_at(w)[0])
    zeta = mode.damping_at(speed, default_damping)
    daf = float(dynamic_amplification(f_e / f_n, max(zeta, 0.0))) if f_n > 0 else float("inf")
    return f_e, f_n, zeta, daf


def _governing(
    regime_status: Mapping[str, Status], violations: Mapping[str, tuple[Interval, ...]]
) -> tuple[Status, str | None]:
    """The worst status of the regimes the line violates the margin in, and the governing
    regime: the first (most steady) one with that status (None where it passes)."""
    hit = [name for name in regime_status if violations[name]]
    status = worst([regime_status[name] for name in hit])
    regime = next((n for n in hit if regime_status[n] == status), None)
    return status, (None if status == "pass" else regime)


def _regime_statuses(
    energy: Status, line_energy: str, heavily_damped: bool, cap: Status | None
) -> dict[str, Status]:
    """The status a violation in each regime gets: the line's own (``energy``) in steady
    operation, one milder where the speed is passed quickly or only in overspeed, info at
    start-up; info only where the mode is heavily damped (no resonant peak to speak of:
    report, do not judge — see AuditSettings); at most ``cap`` where the mode's damping is
    beyond its model."""
    status: dict[str, Status] = {
        "steady": energy,
        "quick-pass": _MILDER[energy],
        "overspeed": _MILDER[energy],
        "start-up": "info" if line_energy != "minor" and energy != "pass" else "pass",
    }
    if heavily_damped:
        status = {k: ("info" if v != "pass" else v) for k, v in status.items()}
    if cap is not None:
        most = STATUS_ORDER[cap]
        status = {k: (cap if STATUS_ORDER[v] > most else v) for k, v in status.items()}
    return status


@dataclass(frozen=True)
class _Pairs:
    """Modes against lines, many pairs evaluated at once: pair ``ids[i]`` at rotor speed
    ``x[i]`` — elementwise the arithmetic of a single pair, so a batch and one pair agree to
    the bit."""

    modes: tuple[Mode, ...]  # the distinct modes
    mode_of: NDArray[np.intp]  # (pairs,): each pair's mode in ``modes``
    order: Floats  # (pairs,): the line's order
    offset: Floats  # (pairs,): the line's offset [Hz]
    band: Floats  # (pairs, 2): the mode's band factors on its frequency (NaN: no band)
    rule: MarginRule

    @classmethod
    def of(cls, pairs: Sequence[tuple[Mode, Excitation]], rule: MarginRule) -> "_Pairs":
        index: dict[int, int] = {}
        for mode, _ in pairs:
            index.setdefault(id(mode), len(index))
        modes = {id(mode): mode for mode, _ in pairs}
        bands = [mode.band_factors() or (math.nan, math.nan) for mode, _ in pairs]
        return cls(
            tuple(modes[k] for k in index),
            np.array([index[id(mode)] for mode, _ in pairs], dtype=np.intp),
            np.array([exc.order for _, exc in pairs], dtype=float),
            np.array([exc.offset_hz for _, exc in pairs], dtype=float),
            np.array(bands, dtype=float).reshape(len(pairs), 2),
            rule,
        )

    def excitation_hz(self, ids: NDArray[np.intp], x: Floats) -> Floats:
        """As :meth:`Excitation.frequency_hz`, pair by pair."""
        return np.asarray(self.order[ids] * x / (2.0 * np.pi) + self.offset[ids])

    def natural_hz(self, ids: NDArray[np.intp], x: Floats) -> Floats:
        """As :meth:`Mode.frequency_at`, pair by pair (one call per distinct mode)."""
        out = np.empty_like(x)
        which = self.mode_of[ids]
        for u in np.unique(which):
            sel = which == u
            out[sel] = self.modes[u].frequency_at(x[sel])
        return out

    def difference(self, ids: NDArray[np.intp], x: Floats) -> Floats:
        return self.excitation_hz(ids, x) - self.natural_hz(ids, x)

    def separation(self, ids: NDArray[np.intp], x: Floats) -> Floats:
        lo, hi = self.band[ids].T
        return _separation(self.rule, self.excitation_hz(ids, x), self.natural_hz(ids, x), lo, hi)

    def on_grid(self, grid: Floats) -> tuple[Floats, Floats]:
        """(pairs, speeds) tables of f_exc − f_n and of the separation on ``grid``."""
        f_n = np.stack([m.frequency_at(grid) for m in self.modes])[self.mode_of]
        f_e = self.order[:, None] * grid[None, :] / (2.0 * np.pi) + self.offset[:, None]
        lo, hi = self.band[:, 0, None], self.band[:, 1, None]
        return f_e - f_n, _separation(self.rule, f_e, f_n, lo, hi)


def _separation(
    rule: MarginRule, f_e: Floats, f_n: Floats, lo: Floats | float, hi: Floats | float
) -> Floats:
    """The rule's separation of a line from a mode; for a mode with a frequency band
    (lower/upper-bound soil: factors ``lo``, ``hi`` on f_n, NaN where none) the line's
    separation from the band — none where the line lies in it, else from its nearer end."""
    s = rule.separation(f_e, f_n)
    banded = np.broadcast_to(np.isfinite(lo), s.shape)
    if not banded.any():
        return s
    fe, fn = np.broadcast_to(f_e, s.shape)[banded], np.broadcast_to(f_n, s.shape)[banded]
    low = np.broadcast_to(lo, s.shape)[banded] * fn
    high = np.broadcast_to(hi, s.shape)[banded] * fn
    ends = np.minimum(rule.separation(fe, low), rule.separation(fe, high))
    s[banded] = np.where((fe - low) * (fe - high) <= 0, 0.0, np.minimum(s[banded], ends))
    return s


def _crossings(ev: _Pairs, grid: Floats, diff: Floats) -> list[tuple[float, ...]]:
    """Each pair's speeds where line and mode meet: zeros of ``diff`` on the grid and its
    sign changes refined, all pairs' in one bisection."""
    rows, cells = np.nonzero(np.sign(diff[:, :-1]) * np.sign(diff[:, 1:]) < 0)
    found = (
        bisect(lambda x: ev.difference(rows, x), grid[cells], grid[cells + 1])
        if rows.size
        else np.empty(0)
    )
    out: list[list[float]] = [[] for _ in range(len(diff))]
    for p, c in zip(*np.nonzero(diff == 0.0), strict=True):
        out[p].append(float(grid[c]))
    for p, x in zip(rows, found, strict=True):
        out[p].append(float(x))
    return [tuple(sorted(c)) for c in out]


def _forbidden(
    ev: _Pairs, grid: Floats, sep: Floats, crossings: Sequence[tuple[float, ...]]
) -> list[tuple[Interval, ...]]:
    """Each pair's maximal speed runs short of the margin (on the grid with its crossings
    added), the edges refined to the zeros of separation − margin: every run's start (unless
    at the grid's first point) in the cell before, its end (unless at the last) in the cell
    after — all pairs' edges in one bisection."""
    runs: list[tuple[Floats, NDArray[np.intp], NDArray[np.intp], int] | None] = []
    ids: list[int] = []
    lo_x: list[Floats] = []
    hi_x: list[Floats] = []
    for p, cross in enumerate(crossings):
        g, s = (grid, sep[p]) if not cross else _with_crossings(ev, p, grid, sep[p], cross)
        idx = np.nonzero(ev.rule.violates(s))[0]
        if idx.size == 0:
            runs.append(None)
            continue
        breaks = np.nonzero(np.diff(idx) != 1)[0]
        starts = np.concatenate([[idx[0]], idx[breaks + 1]])
        ends = np.concatenate([idx[breaks], [idx[-1]]])
        lo_cells, hi_cells = starts[starts > 0], ends[ends < len(g) - 1]
        runs.append((g, starts, ends, len(ids)))
        brackets = np.concatenate([lo_cells - 1, hi_cells])
        ids += [p] * brackets.size
        lo_x.append(g[brackets])
        hi_x.append(g[brackets + 1])
    if not ids:
        return [() for _ in crossings]
    pair = np.array(ids, dtype=np.intp)
    edges = bisect(
        lambda x: ev.separation(pair, x) - ev.rule.margin * (1.0 - 1e-9),
        np.concatenate(lo_x),
        np.concatenate(hi_x),
    )
    out: list[tuple[Interval, ...]] = []
    for run in runs:
        if run is None:
            out.append(())
            continue
        g, starts, ends, first = run
        lo, hi = g[starts].copy(), g[ends].copy()
        n_lo = int(np.count_nonzero(starts > 0))
        n_hi = int(np.count_nonzero(ends < len(g) - 1))
        lo[starts > 0] = edges[first : first + n_lo]
        hi[ends < len(g) - 1] = edges[first + n_lo : first + n_lo + n_hi]
        out.append(tuple((float(x), float(y)) for x, y in zip(lo, hi, strict=True)))
    return out


def _with_crossings(
    ev: _Pairs, p: int, grid: Floats, sep: Floats, crossings: tuple[float, ...]
) -> tuple[Floats, Floats]:
    """The grid with a pair's crossings added (those not on it already), and the pair's
    separation on it: ``sep`` on the grid with the crossings' own inserted."""
    cross = np.array(crossings, dtype=float)
    at = np.searchsorted(grid, cross)
    new = grid[np.minimum(at, len(grid) - 1)] != cross
    cross, at = cross[new], at[new]
    on_cross = ev.separation(np.full(cross.shape, p, dtype=np.intp), cross)
    return np.insert(grid, at, cross), np.insert(sep, at, on_cross)


def regime_of(omega: float, op: OperatingRange) -> str:
    """Which regime a rotor speed belongs to: steady, quick-pass, overspeed or start-up."""
    tol = 1e-9 * op.overspeed
    if any(a - tol <= omega <= b + tol for a, b in op.quick_pass):
        return "quick-pass"
    if any(a - tol <= omega <= b + tol for a, b in op.steady):
        return "steady"
    return "overspeed" if omega > op.highest else "start-up"


@functools.lru_cache(maxsize=64)
def _grid(op: OperatingRange) -> NDArray[np.float64]:
    """The speeds every line is sampled at (one grid per operating range: computed once
    for the audit's hundred-odd pairs, read-only)."""
    top = op.overspeed
    edges = [s for pair in op.steady + op.quick_pass for s in pair]
    grid = np.unique(
        np.concatenate(
            [np.linspace(0.0, top, 801), np.geomspace(top * 1e-4, top, 200), np.array(edges)]
        )
    )
    grid.flags.writeable = False
    return grid


ArrayFn = Callable[[NDArray[np.float64]], NDArray[np.float64]]


def bisect(
    f: ArrayFn,
    a: NDArray[np.float64],
    b: NDArray[np.float64],
    xtol: float = 1e-12,
    rtol: float = 1e-12,
) -> NDArray[np.float64]:
    """Roots of ``f`` in the brackets [a, b] (sign changes), all brackets at once, each to
    ``xtol + rtol·|x|``: ``f`` is evaluated on the vector of estimates, so the work is a
    handful of array calls whatever the number of roots.

    Notes
    -----
    The Illinois variant of regula falsi (Dowell & Jarratt 1971): the secant through the
    bracket's ends, the end kept twice in a row has its value halved — superlinear, and
    the root stays bracketed; every fourth step halves the bracket, so that no bracket
    shrinks slower than bisection. A bracket is also done where the secant moves less than
    the tolerance from the last point evaluated — the correction f·Δx/Δf that point still
    needs (the standard secant test; a halved end only makes it larger): a linear piece, as
    a sampled curve against a line is, is then solved by its first secant and confirmed by
    the next, where the bracket would take another ten steps to shrink round it. Plain
    numpy keeps scipy.optimize (0.2 s to import) off the check's start-up path.
    """
    a, b = np.array(a, dtype=float), np.array(b, dtype=float)
    fa, fb = f(a), f(b)
    root = np.where(fa == 0.0, a, np.where(fb == 0.0, b, np.nan))
    open_ = (fa != 0.0) & (fb != 0.0)
    side = np.zeros(a.shape, dtype=int)
    last = np.full(a.shape, np.nan)  # the point evaluated last
    for step in range(200):
        if not open_.any():
            break
        with np.errstate(divide="ignore", invalid="ignore"):
            secant = (a * fb - b * fa) / (fb - fa)
        settled = open_ & (np.abs(secant - last) <= xtol + rtol * np.abs(secant))
        root[settled], open_ = secant[settled], open_ & ~settled
        if not open_.any():
            break
        mid = 0.5 * (a + b)
        halve = step % 4 == 3
        x = np.where(
            halve
            | ~np.isfinite(secant)
            | (secant <= np.minimum(a, b))
            | (secant >= np.maximum(a, b)),
            mid,
            secant,
        )
        fx = f(x)
        last = x
        done = open_ & ((fx == 0.0) | (np.abs(b - a) <= xtol + rtol * np.abs(x)))
        root[done], open_ = x[done], open_ & ~done
        right = open_ & ((fx < 0) == (fb < 0))  # x replaces b
        left = open_ & ~right  # x replaces a
        fa = np.where(right & (side == -1) & ~halve, 0.5 * fa, fa)
        fb = np.where(left & (side == 1) & ~halve, 0.5 * fb, fb)
        b, fb = np.where(right, x, b), np.where(right, fx, fb)
        a, fa = np.where(left, x, a), np.where(left, fx, fa)
        side = np.where(right, -1, np.where(left, 1, side))
    return np.where(open_, 0.5 * (a + b), root)


def _overlap(a: Interval, b: Interval) -> Interval | None:
    lo, hi = max(a[0], b[0]), min(a[1], b[1])
    return (lo, hi) if hi - lo > 1e-9 * max(abs(hi), 1.0) else None


def split_by_regime(
    forbidden: Sequence[Interval], op: OperatingRange, violated: Callable[[float], bool]
) -> dict[str, tuple[Interval, ...]]:
    """Speed intervals [rad/s] split by regime: steady, quick-pass, overspeed, start-up
    (every transient speed below the highest steady one). ``violated(Ω)`` decides a fixed
    (zero-width) steady speed. Shared by every check that judges speeds by regime."""
    steady: list[Interval] = []
    quick: list[Interval] = []
    for a, b in op.steady:
        if a == b:
            if violated(a):
                steady.append((a, a))
            continue
        for f in forbidden:
            part = _overlap(f, (a, b))
            if part is None:
                continue
            inside = [q for q in (_overlap(part, qp) for qp in op.quick_pass) if q]
            quick += inside
            steady += _subtract(part, inside)
    over = [p for f in forbidden if (p := _overlap(f, (op.highest, op.overspeed)))]
    transient = [p for f in forbidden if (p := _overlap(f, (0.0, op.highest)))]
    startup = [piece for t in transient for piece in _subtract(t, op.steady)]
    return {
        "steady": tuple(steady),
        "quick-pass": tuple(quick),
        "overspeed": tuple(over),
        "start-up": tuple(startup),
    }


def _subtract(part: Interval, holes: Sequence[Interval]) -> list[Interval]:
    pieces = [part]
    for h in holes:
        nxt: list[Interval] = []
        for p in pieces:
            if h[1] <= p[0] or h[0] >= p[1]:
                nxt.append(p)
                continue
            if h[0] > p[0]:
                nxt.append((p[0], h[0]))
            if h[1] < p[1]:
                nxt.append((h[1], p[1]))
        pieces = [p for p in nxt if p[1] - p[0] > 1e-9 * max(p[1], 1.0)]
    return pieces


_REGIMES = ("steady", "quick-pass", "overspeed", "start-up")


def _worst_judged(
    sep: ArrayFn,
    op: OperatingRange,
    crossings: Sequence[float],
    regimes: frozenset[str] | None,
    on_steady: Floats | None = None,
) -> tuple[float, float]:
    """Speed of least separation where the mode is judged, and that separation: the steady
    speeds, or — for a mode that exists only in transients (generator free) — the overspeed
    band; NaN for a mode that exists only during start-up (a margin there means nothing).
    ``on_steady``: the separation at the steady ranges' speeds (:func:`_judged_speeds`),
    where already known."""
    if regimes is None or "steady" in regimes or "quick-pass" in regimes:
        ranges = op.steady
    elif "overspeed" in regimes:
        ranges = ((op.highest, op.overspeed),)
    else:
        return op.lowest, math.nan
    pts = _judged_speeds(ranges)
    inside = np.array([c for c in crossings for a, b in ranges if a <= c <= b], dtype=float)
    speeds = np.concatenate([pts, inside])
    if on_steady is not None and ranges is op.steady:  # computed with the other pairs'
        s = np.concatenate([on_steady, sep(inside)]) if inside.size else on_steady
    else:
        s = sep(speeds)
    i = int(np.argmin(s))
    return float(speeds[i]), float(s[i])


@functools.lru_cache(maxsize=64)
def _judged_speeds(ranges: tuple[Interval, ...]) -> Floats:
    """The speeds a margin is measured at: 201 across each range (a fixed speed once);
    computed once per set of ranges, read-only."""
    out = np.concatenate([np.linspace(a, b, 201) if b > a else np.array([a]) for a, b in ranges])
    out.flags.writeable = False
    return out


def steady_samples(op: OperatingRange, per_range: int = 25) -> NDArray[np.float64]:
    """Rotor speeds [rad/s] sampling every steady range (a fixed speed repeats)."""
    return np.concatenate([np.linspace(a, b, per_range) for a, b in op.steady])


def lines_met(
    frequency_hz: float,
    lines: Sequence[Excitation],
    op: OperatingRange,
    rule: MarginRule,
    subsystem: str,
    energy: str = "dominant",
) -> list[str]:
    """Ids of the lines of an energy class acting on ``subsystem`` whose margin band holds a
    natural frequency at some steady speed: the question the power-dependent drive train
    and the yaw system with gear play ask of frequencies that are not modes' curves."""
    speeds = steady_samples(op)
    return [
        e.id
        for e in lines
        if e.energy == energy
        and e.acts_on(subsystem)
        and np.any(rule.violates(rule.separation(e.frequency_hz(speeds), frequency_hz)))
    ]


def assess_all(
    modes: Sequence[Mode],
    excitations: Sequence[Excitation],
    op: OperatingRange,
    rule: MarginRule,
    severity: Mapping[str, Status],
    default_damping: float,
    heavy_damping: float = HEAVY_DAMPING,
) -> list[Finding]:
    """Every judged mode (:attr:`Mode.judged`) against every excitation acting on it — on a
    coupled mode, the lines that act on the part whose isolated mode it stands for too (the
    drive train's generator and gear-mesh lines on ``system.drivetrain1``, which supersedes
    ``drivetrain.free.1``: superseded, that mode is not judged, and those lines judged
    nothing)."""
    pairs = [(m, e) for e in excitations for m in modes if m.judged and acts(e, m)]
    return _assess(pairs, op, rule, severity, default_damping, heavy_damping)


def acts(e: Excitation, m: Mode) -> bool:
    """Whether line ``e`` acts on mode ``m``: on its subsystem, or — a coupled mode — on the
    subsystem of the isolated mode it stands for (``replaces``)."""
    if e.acts_on(m.subsystem):
        return True
    return m.replaces is not None and e.acts_on(m.replaces.split(".", 1)[0])


def resonance_checks(
    findings: Sequence[Finding], op: OperatingRange, rule: MarginRule
) -> list[Check]:
    """One check per subsystem and excitation, judged on its worst mode."""
    groups: dict[tuple[str, str], list[Finding]] = {}
    for f in findings:
        groups.setdefault((f.mode.subsystem, f.excitation.id), []).append(f)
    return [_check(sub, fs[0].excitation, fs, op, rule) for (sub, _), fs in groups.items()]


def _check(
    subsystem: str,
    exc: Excitation,
    findings: Sequence[Finding],
    op: OperatingRange,
    rule: MarginRule,
) -> Check:
    # the worst status; among equals a mode of the condition the turbine runs in, then the
    # least margin (a margin is measured where the mode exists: see _worst_judged) — to
    # 1e-9, so that two modes both crossed (margin 0 up to rounding) are not told apart by
    # the rounding — then the larger amplification (the less damped resonance), to nine
    # digits likewise (two modes crossed with one ζ: 1/(2ζ) each, up to rounding), then the
    # less damped, then the first (the lower frequency)
    gov = max(
        findings,
        key=lambda f: (
            STATUS_ORDER[f.status],
            f.mode.regimes is None or "steady" in f.mode.regimes,
            not math.isnan(f.margin),
            -round(f.margin, 9) if not math.isnan(f.margin) else 0.0,
            float(f"{min(f.daf, 1e300):.9g}") if not math.isnan(f.daf) else 0.0,
            -f.damping,
        ),
    )
    others = [f.mode.id for f in findings if f is not gov and f.status == gov.status != "pass"]
    message = _message(gov, op, rule)
    # the speed bands to exclude to clear the check: those of every mode that warns or fails
    # (one told only as info — heavily damped, a minor harmonic — needs no clearing)
    exclude = _merge(
        [
            iv
            for f in findings
            if STATUS_ORDER[f.status] >= STATUS_ORDER["warn"]
            for iv in f.violations["steady"] + f.violations["quick-pass"]
        ]
    )
    own = _merge(gov.violations["steady"] + gov.violations["quick-pass"])
    notes = [f"also: {', '.join(others)}"] if others else []
    if exclude and own and exclude != own and op.variable:  # the governing mode's are not all
        notes.append(f"all together: exclude {', '.join(speed_span(iv) for iv in exclude)}")
    if notes:
        message += f" ({'; '.join(notes)})"
    numbers = {
        "excitation": exc.id,
        "energy": exc.energy,
        "mode": gov.mode.id,
        "frequency_hz": _r(gov.natural_hz),
        "margin": _r(gov.margin) if math.isfinite(gov.margin) else None,
        "required_margin": rule.margin,
        "speed_rpm": _r(float(rad_s_to_rpm(gov.speed))),
        "excitation_hz": _r(gov.excitation_hz),
        "daf": _r(gov.daf) if np.isfinite(gov.daf) else None,
        **(
            {"damping_ratio": _r(gov.damping), "damping": "in operation"}
            if gov.damping_in_operation
            else {}
        ),
        "regime": gov.regime,
        **({"heavily_damped": True} if gov.heavily_damped and gov.regime else {}),
        "energy_on_mode": gov.energy,
        **({"driven_by": gov.driven_by} if gov.driven_by else {}),
        "crossings_rpm": [_r(float(rad_s_to_rpm(c))) for c in gov.crossings],
        "exclude_rpm": [
            [_r(float(rad_s_to_rpm(a))), _r(float(rad_s_to_rpm(b)))] for a, b in exclude
        ]
        if op.variable
        else [],
        "modes": {f.mode.id: f.status for f in findings},
    }
    return Check(
        id=f"{subsystem}.resonance.{exc.id}",
        subsystem=subsystem,
        status=gov.status,
        message=message,
        rule=Rule(rule.label, rule.source),
        numbers=numbers,
    )


def _merge(intervals: Sequence[Interval]) -> list[Interval]:
    out: list[Interval] = []
    for a, b in sorted(intervals):
        if out and a <= out[-1][1]:
            out[-1] = (out[-1][0], max(out[-1][1], b))
        else:
            out.append((a, b))
    return out


def _r(x: float) -> float:
    """Round for the report: 6 significant digits keep JSON stable and readable, and a
    value zero within the solvers' rounding (|x| < 1e-9: a margin of 9.9e-14) is 0."""
    return 0.0 if abs(x) < 1e-9 else float(f"{x:.6g}")


def _rpm(omega: float) -> str:
    return f"{float(rad_s_to_rpm(omega)):.3g} rpm"


def speed_span(iv: Interval) -> str:
    """A band of speeds as a reader reads it; one that rounds to a single speed is that
    speed ("6.72 rpm", never "6.72–6.72 rpm")."""
    a, b = (f"{float(rad_s_to_rpm(x)):.3g}" for x in iv)
    return f"{a} rpm" if a == b else f"{a}–{b} rpm"


def _message(f: Finding, op: OperatingRange, rule: MarginRule) -> str:
    whirl = f.whirl if f.whirl not in (None, "fixed") else None
    name = f"{f.mode.id} ({f.natural_hz:.3g} Hz{', ' + whirl if whirl else ''})"
    if f.mode.band_hz is not None:
        lo, hi = f.mode.band_hz
        name += f" [band {lo:.3g}–{hi:.3g} Hz at standstill]"
    need = f"needs {rule.margin:.0%}"
    exc = f.excitation.id
    if f.driven_by and f.driven_by != exc:
        exc = f"{exc} (the blades' {f.driven_by} in the rotating frame)"
    if f.regime is None:
        if math.isnan(f.margin):
            return f"{name} exists only during start-up/shut-down: not judged against {exc}"
        regimes = f.mode.regimes
        if regimes is not None and "steady" not in regimes:
            where = f"in the regimes it exists in ({', '.join(sorted(regimes))})"
        else:
            where = "at the operating speed" if not op.variable else "over the operating range"
        return f"{name} clear of {exc} by {f.margin:.1%} {where} ({need})"
    spans = ", ".join(speed_span(iv) for iv in f.violations[f.regime])
    if f.heavily_damped and f.regime not in (None, "start-up"):
        where = f" {_damped_by(f)}" if f.damping_in_operation else ""
        return (
            f"{name} within the margin of {exc} ({f.regime}, {spans}) but heavily damped "
            f"(ζ = {f.damping_met:.2f}{where}): no resonant peak, info"
        )
    if f.regime == "steady":
        return _steady_message(f, op, name, exc, spans, need)
    if f.regime == "quick-pass":
        return (
            f"{name} within the margin of {exc} only inside the quick-pass band at {spans}: "
            "the speed controller must not dwell there"
        )
    if f.regime == "overspeed":
        return (
            f"{name} meets {exc} only at overspeed, {spans} (steady up to "
            f"{_rpm(op.highest)}, overspeed limit {_rpm(op.overspeed)}): a transient state"
        )
    return (
        f"{name} is crossed by {exc} during start-up/shut-down at {spans} "
        f"(below {_rpm(op.lowest)}): passed quickly, not a steady resonance"
    )


def _steady_message(
    f: Finding, op: OperatingRange, name: str, exc: str, spans: str, need: str
) -> str:
    """A resonance in steady operation in words: separation, DAF and damping there, and
    why its status is what it is (the line's energy, the mode's cap), what clears it."""
    text = f"{name} within the margin of {exc} in steady operation at {spans}: "
    text += f"separation {f.margin:.1%} ({need}), DAF {f.daf:.3g}"
    if f.damping_in_operation:
        text += f" (ζ = {f.damping:.3f} {_damped_by(f)})"
    if f.damping_met < -NEGATIVE:
        text += (
            "; negatively damped where the line meets it — an unstable mode amplifies "
            "any excitation, whatever its energy"
        )
    blades = f.excitation.blades
    dominant = f"the dominant 1P and {blades}P" if blades else "the dominant lines"
    told = f" ({f.status})" if f.status in ("info", "pass") else ""
    if f.driven_by and blades and round(f.excitation.order) % blades:
        text += (
            "; reaches the rotor modes only through rotor asymmetry (not a multiple of "
            f"{blades}P): a low-energy excitation beside {dominant}{told}"
        )
    elif f.energy == "minor":
        text += (
            f"; a low-energy harmonic, little excitation energy beside {dominant} (Hau 7.2.2){told}"
            if f.excitation.blades is not None
            else f"; a low-energy line ({f.excitation.description}){told}"
        )
    elif f.energy == "secondary":
        dwelt = any(a <= w <= b for w in op.dwell for a, b in f.violations["steady"])
        text += (
            "; a secondary harmonic at the rated speed: resonant in practice (WKA-60, Hau 7.5.2)"
            if dwelt
            else "; a secondary harmonic swept in partial load, not at rated speed: milder"
        )
    if f.mode.status_cap is not None and f.status == f.mode.status_cap:
        text += (
            f"; at most a {f.mode.status_cap}: this mode's damping (a floating platform's "
            "radiation and viscous damping) is beyond wtvib's model, which takes the "
            "structure's alone"
        )
    if op.variable and STATUS_ORDER[f.status] >= STATUS_ORDER["warn"]:  # (info: no need)
        text += f"; exclude {spans} to clear it"
    return text


def _damped_by(f: Finding) -> str:
    """Where a finding's damping in operation came from, in words."""
    if f.mode.origin == "imported" and f.mode.operating is not None:
        return f"in operation, from {f.mode.operating.source}"
    return "in operation, aerodynamic + structural"


#: What a point of the Campbell diagram marks: the least margin of a resonance met in steady
#: operation, a band where the margin is violated without the line meeting the mode, or a
#: crossing of line and mode (in the order in which they stand for a resonance).
MarkKind = str
MARK_KINDS: tuple[MarkKind, ...] = ("least margin", "band violated", "crossing")


@dataclass(frozen=True)
class Mark:
    """One physical resonance as the Campbell diagram marks it: where, how judged, and the
    dynamic amplification there (``daf``: 1/(2ζ) at a crossing; ``damping``: that ζ)."""

    rpm: float
    hz: float
    status: Status
    kind: MarkKind
    line: str
    modes: tuple[str, ...]
    daf: float | None = None
    damping: float | None = None


def marks(findings: Sequence[Finding], op: OperatingRange) -> list[Mark]:
    """The resonances of some findings, one mark each.

    Per mode and line: a resonance met in steady operation (warn or fail) is marked once, at
    its least margin; the crossings and violated speeds joined to it (the same run of
    violated speeds, into overspeed) are that resonance, not marked again. Other runs of
    violated speeds are marked at their crossings, or — where the line never meets the mode
    — at their middle. Other crossings (start-up, minor lines) are marked each. Marks of one
    line at one place (two modes of one frequency: a round tower's fore-aft and side-side)
    are one mark, in the worst status.
    """
    out: list[Mark] = []
    for f in findings:
        runs = _merge([iv for ivs in f.violations.values() for iv in ivs])
        taken: list[Interval] = []
        if f.regime in ("steady", "quick-pass") and STATUS_ORDER[f.status] >= STATUS_ORDER["warn"]:
            out.append(
                Mark(
                    float(rad_s_to_rpm(f.speed)),
                    f.excitation_hz,
                    f.status,
                    "least margin",
                    f.excitation.id,
                    (f.mode.id,),
                    f.daf,
                    f.damping,
                )
            )
            tol = 1e-6 * max(f.speed, 1e-9)
            taken = [(a, b) for a, b in runs if a - tol <= f.speed <= b + tol] or [
                (f.speed, f.speed)
            ]
        dafs = f.crossing_daf or (None,) * len(f.crossings)
        for c, daf in zip(f.crossings, dafs, strict=True):
            if any(a - 1e-6 * c <= c <= b + 1e-6 * c for a, b in taken):
                continue
            hz = float(f.excitation.frequency_hz(np.array([c]))[0])
            zeta = 1.0 / (2.0 * daf) if daf is not None and daf > 0 else None
            out.append(
                Mark(
                    float(rad_s_to_rpm(c)),
                    hz,
                    f.status_at(c, op),
                    "crossing",
                    f.excitation.id,
                    (f.mode.id,),
                    daf,
                    zeta,
                )
            )
        for a, b in runs:
            if (a, b) in taken or any(a <= c <= b for c in f.crossings):
                continue
            mid = 0.5 * (a + b)
            status = f.status_at(mid, op)
            if STATUS_ORDER[status] < STATUS_ORDER["warn"]:
                continue
            hz = float(f.mode.frequency_at(np.array([mid]))[0])
            out.append(
                Mark(
                    float(rad_s_to_rpm(mid)),
                    hz,
                    status,
                    "band violated",
                    f.excitation.id,
                    (f.mode.id,),
                )
            )
    return _one_per_place(out)


def _one_per_place(found: list[Mark], rel: float = 0.02) -> list[Mark]:
    """Marks of one line within ``rel`` of each other in speed and frequency as one: the
    worst status (then the kind that stands for more), naming every mode."""
    rank = {k: i for i, k in enumerate(MARK_KINDS)}
    order = sorted(found, key=lambda m: (-STATUS_ORDER[m.status], rank[m.kind], m.rpm, m.hz))
    kept: list[Mark] = []
    for m in order:
        same = next(
            (
                i
                for i, k in enumerate(kept)
                if k.line == m.line
                and abs(k.rpm - m.rpm) <= rel * max(k.rpm, m.rpm, 1e-9)
                and abs(k.hz - m.hz) <= rel * max(k.hz, m.hz, 1e-9)
            ),
            None,
        )
        if same is None:
            kept.append(m)
        elif m.modes[0] not in kept[same].modes:
            k = kept[same]
            # the resonance's amplification: the larger of the modes' (the less damped)
            daf, zeta = (
                (m.daf, m.damping) if (m.daf or 0.0) > (k.daf or 0.0) else (k.daf, k.damping)
            )
            kept[same] = Mark(
                k.rpm, k.hz, k.status, k.kind, k.line, (*k.modes, *m.modes), daf, zeta
            )
    return sorted(kept, key=lambda m: (m.rpm, m.hz, m.line))


def standstill(subject: str, stability: bool = False) -> Check:
    """What a standstill audit (``rotor.speed.parked``) does not judge, said as a check of
    its own (info): ``subject`` is whose modes they are ("OpenFAST's results are of a
    parked rotor", "the turbine is parked"); ``stability``: whether their damping is
    judged (another tool's, which can be negative)."""
    judged = "their stability judged" if stability else "their damping listed"
    return Check(
        id="system.resonance",
        subsystem="system",
        status="info",
        message=(
            f"a standstill audit: {subject} (0 rpm), which no rotor harmonic excites — the "
            f"modes are listed and {judged}, no resonance; give --rpm MIN:MAX to judge them "
            "against an operating range"
        ),
        rule=Rule("no rotor harmonic at standstill", "kP = k·Ω/2π is 0 Hz at Ω = 0"),
    )


def standstill_stability(modes: Sequence[Mode]) -> Check:
    """``system.stability`` of a standstill audit of wtvib's own models: the judged modes'
    damping ratios as the audit judges them. What a parked turbine's audit rests on is
    that damping; where all of it is wtvib's assumption (no value in the input), the
    verdict rests on nothing the input says: a warning, not a pass. A negative ratio (an
    unstable structure) fails; an undamped one (ζ = 0, as a model may be) passes as no
    negative damping."""
    judged = [m for m in modes if m.judged and m.damping_ratio is not None]
    rule = Rule(
        "negative damping is an instability",
        "the modes' damping ratios at standstill; an oscillation with ζ < 0 grows",
    )
    if not judged:
        return Check("system.stability", "system", "warn", "no mode to judge at standstill", rule)
    lowest = min(judged, key=lambda m: m.damping_ratio or 0.0)
    zeta = lowest.damping_ratio or 0.0
    assumed = [m.id for m in judged if (m.damping_source or "").startswith("assumed")]
    numbers = {"lowest": {"mode": lowest.id, "damping_ratio": zeta}, "assumed": assumed}
    lowest_said = f"lowest ζ = {zeta:.4f}, {lowest.id}"
    status: Status
    if zeta < -NEGATIVE:
        status = "fail"
        message = f"{lowest.id} negatively damped at standstill (ζ = {zeta:.4f})"
    elif len(assumed) == len(judged):
        status = "warn"
        message = (
            f"every mode's damping at standstill is wtvib's assumption ({lowest_said}): the "
            "stability a standstill audit judges rests on no value of the input — give the "
            "damping"
        )
    else:
        status = "pass"
        message = (
            ("every mode positively damped" if zeta > 0 else "no mode negatively damped")
            + f" at standstill ({lowest_said}"
            + (f"; assumed for {', '.join(assumed)}" if assumed else "")
            + ")"
        )
    return Check("system.stability", "system", status, message, rule, numbers)
