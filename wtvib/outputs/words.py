"""Words the terminal report and the PDF both write from the JSON document, written once
(one story: the two say the same thing in the same words)."""

from collections.abc import Mapping
from typing import Any


def operation(op: Mapping[str, Any], digits: int = 4) -> str:
    """The operating range as a reader reads it: ``3.41–12.1 rpm (variable); overspeed
    13.91 rpm — from DISCON.IN …``, ``17.5 rpm (fixed); …``, or a standstill audit's
    ``parked (0 rpm): a standstill audit``."""
    if op.get("parked"):
        return "parked (0 rpm): a standstill audit, no rotor excitation"
    steady = op["steady_rpm"]
    speeds = (
        f"{steady[0][0]:.{digits}g}–{steady[-1][1]:.{digits}g} rpm (variable)"
        if op["variable_speed"]
        else ", ".join(f"{a:.{digits}g}" for a, _ in steady) + " rpm (fixed)"
    )
    source = f" — from {op['source']}" if op.get("source") else ""
    return f"{speeds}; overspeed {op['overspeed_rpm']:.4g} rpm{source}"


def signed_percent(value: float, digits: int = 1) -> str:
    """A relative difference as a reader reads it: +3.3 %, −1.2 %, 0 % (never −0.0 %)."""
    if abs(value) < 0.5 * 10.0 ** (-digits - 2):
        return "0 %"
    return f"{100 * value:+.{digits}f} %".replace("-", "−")


def counted(n: int, noun: str) -> str:
    """``n`` and the noun, plural where n is not 1: ``counted(1, "blade")`` → '1 blade'."""
    return f"{n} {noun}{'' if n == 1 else 's'}"


def lift(lagged: bool) -> str:
    """How the blades' lift answers their motion in the damping in operation, as the
    report and the damping figure say it (``aerodynamics.shed_wake``)."""
    return "lift lagged by the shed wake" if lagged else "lift quasi-steady"
