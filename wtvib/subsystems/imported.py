"""Modes another tool computed (``spec.results``): OpenFAST linearisation, HAWCStab2, a table.

Each mode of :class:`wtvib.spec.results.Results` becomes a :class:`~wtvib.results.Mode` the
audit judges like its own: its frequency over rotor speed as a curve through the tool's
operating points (linear between them, held beyond), its whirl per point, and its damping
per point as the damping in operation (``Mode.operating``: the tool's total damping; the
tool does not separate its aerodynamic part). Whole-turbine modes (fixed frame) are
``system.*`` modes, in place of the coupled model's; rotating-frame blade modes are
``blade.*`` modes. A mode the tool finds negatively damped in the operating range fails
``system.stability``.
"""

import math

from ..judge.analysis import Analysis, Context
from ..judge.resonance import standstill
from ..results import Check, Mode, OperatingDamping, Rule, Sampled, Whirl, by_frequency
from ..rules import NEGATIVE
from ..spec import Spec
from ..spec.results import ResultMode

#: The subsystem each frame's modes belong to.
SUBSYSTEM = {"fixed": "system", "rotating": "blade"}


def modes(spec: Spec, frame: str) -> list[Mode]:
    """The spec's imported modes of one frame (``fixed`` or ``rotating``)."""
    r = spec.results
    if r is None:
        return []
    sub = SUBSYSTEM[frame]
    return sorted(
        (_mode(f"{sub}.{name}", sub, m, r.tool) for name, m in r.modes.items() if m.frame == frame),
        key=by_frequency,
    )


def _mode(mode_id: str, subsystem: str, m: ResultMode, tool: str) -> Mode:
    omega = tuple(r * math.pi / 30 for r in m.rpm)
    rpm = ", ".join(f"{r:.3g}" for r in m.rpm[:6]) + (" …" if len(m.rpm) > 6 else "")
    operating = None
    if m.damping_ratio is not None:
        nan = (math.nan,) * len(omega)
        wind = tuple(m.wind_m_s) if m.wind_m_s is not None else nan
        operating = OperatingDamping(
            wind, omega, nan, nan, tuple(m.damping_ratio), f"{tool} (total damping)"
        )
    return Mode(
        mode_id,
        subsystem,
        f"{m.description} ({tool}"
        + (f"; first point {m.rpm[0]:.4g} rpm)" if m.rpm[0] > 0 else ")"),
        m.frequency_hz[0],
        damping_ratio=m.damping_ratio[0] if m.damping_ratio is not None else None,
        curve=Sampled(omega, tuple(m.frequency_hz)),
        condition=f"{tool}, at {rpm} rpm",
        whirl=Whirl(omega, tuple(m.whirl)) if m.whirl is not None else None,
        origin="imported",
        operating=operating,
    )


def stability(spec: Spec, ctx: Context) -> Analysis:
    """``system.stability``: the imported modes' damping at the tool's points.

    A mode negatively damped at a point in the operating range (steady speeds and
    overspeed), or at the only points it has (held over the range: a parked linearisation
    audited over ``--rpm``), fails; negatively damped only outside the range judged, it
    warns — an instability at a speed the audit does not cover is still one."""
    r = spec.results
    if r is None:
        return Analysis()
    damped = [m for m in r.modes.values() if m.damping_ratio is not None]
    statements = (
        f"Modes as computed by {r.tool} ({len(r.modes)} modes from {len(r.files)} file(s): "
        f"{', '.join(r.files[:4])}{' …' if len(r.files) > 4 else ''}); frequencies linear "
        "between its operating points and held beyond them; "
        + (
            "damping: the tool's total damping at each point."
            if damped
            else "no damping given: each subsystem's default is assumed."
        ),
    )
    lead = (
        (standstill(f"{r.tool}'s results are of a parked rotor", stability=True),)
        if spec.rotor.speed.parked
        else ()
    )
    if not damped:
        return Analysis(lead=lead, assumptions=statements)
    inside, outside = _negative(spec, ctx)
    worst = min(
        (z, f"{SUBSYSTEM[m.frame]}.{name}", rpm)
        for name, m in r.modes.items()
        if m.damping_ratio
        for z, rpm in zip(m.damping_ratio, m.rpm, strict=True)
    )
    if inside:
        status = "fail"
        message = (
            f"{len({n for n, _, _ in inside})} mode(s) negatively damped in the operating "
            f"range per {r.tool}: " + _listed(inside)
        )
    elif outside:
        status = "warn"
        message = (
            f"{len({n for n, _, _ in outside})} mode(s) negatively damped outside the "
            f"operating range judged, per {r.tool}: " + _listed(outside)
        )
    else:
        status = "pass"
        message = (
            f"no mode negatively damped at the tool's operating points (lowest ζ = "
            f"{max(worst[0], 0.0):.4f}, {worst[1]} at {worst[2]:.3g} rpm)"
        )
    rows = inside or outside
    check = Check(
        id="system.stability",
        subsystem="system",
        status=status,  # type: ignore[arg-type]
        message=message,
        rule=Rule(
            "negative damping is an instability",
            f"the modes' damping as computed by {r.tool}; an oscillation with ζ < 0 grows",
        ),
        numbers={
            "lowest": {"mode": worst[1], "damping_ratio": worst[0], "rpm": worst[2]},
            "unstable": [{"mode": n, "damping_ratio": z, "rpm": rpm} for n, z, rpm in rows],
        },
    )
    return Analysis(lead=lead, checks=(check,), assumptions=statements)


def _negative(
    spec: Spec, ctx: Context
) -> tuple[list[tuple[str, float, float]], list[tuple[str, float, float]]]:
    """The negatively damped points (mode id, ζ, rpm): those judged in the operating range
    (or held over it, a mode with no point in it), and those outside it."""
    assert spec.results is not None
    # the steady range and overspeed (rpm, with a little slack for rounded speeds)
    low, high = ctx.op.lowest * 30 / math.pi - 1e-6, ctx.op.overspeed * 30 / math.pi + 1e-6
    inside: list[tuple[str, float, float]] = []
    outside: list[tuple[str, float, float]] = []
    for name, m in spec.results.modes.items():
        if m.damping_ratio is None:
            continue
        held = not any(low <= rpm <= high for rpm in m.rpm)
        for z, rpm in zip(m.damping_ratio, m.rpm, strict=True):
            if z < -NEGATIVE:
                row = (f"{SUBSYSTEM[m.frame]}.{name}", z, rpm)
                (inside if held or low <= rpm <= high else outside).append(row)
    return inside, outside


def _listed(rows: list[tuple[str, float, float]]) -> str:
    return "; ".join(f"{n} ζ = {z:.4f} at {rpm:.3g} rpm" for n, z, rpm in rows[:4]) + (
        f" and {len(rows) - 4} more" if len(rows) > 4 else ""
    )
