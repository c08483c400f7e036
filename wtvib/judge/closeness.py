"""Natural frequencies of different subsystems close to each other (Hau, ch. 7).

The chapter's first demand is two-fold: "the natural frequencies of rotor blades, tower and
mechanical drive train components must not be too close to each other, and their clearance
from the possible excitation frequencies must not be too small". The resonance checks judge
the second; this module the first, for the two couplings the chapter names:

* the blades' first flapwise mode and the tower's first fore-aft mode: the rotor's thrust
  ties them (7.5: the vibrational coupling between rotor and tower);
* the blades' first edgewise mode and the drive train's first torsional mode: the rotor's
  torque ties them (7.3.3: "in very large units, the first natural chordwise bending
  frequency of the rotor blades is often located close to the first natural torsional
  frequency of the drive train. This results in a coupling so that it is no longer
  permissible to consider the drive train in isolation").

A pair closer than :data:`CLOSE` at any speed it meets (standstill, and the steady
operating range where both modes exist) is a warning where the audit judges them apart
(isolated models), information where a coupled model judges the coupled modes in their
place (it says which). The isolated frequencies are compared: they are what a designer
places; the coupled model shows what the coupling makes of them.
"""

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..results import Check, Mode, Rule
from ..rules import Status
from .excitation import OperatingRange

#: Two modes closer than this (relative to the lower) are close: the margin Hau's rule keeps
#: between a natural frequency and an excitation (7.5.1), applied between two modes.
CLOSE = 0.10
#: Points of each steady speed range at which the frequencies are compared.
SPEED_POINTS = 21


@dataclass(frozen=True)
class Coupling:
    """A pair of subsystem modes the chapter names as coupled, and through what."""

    first: str  # mode id
    second: str  # mode id, or a prefix and suffix (``drivetrain.`` … ``.1``) for each condition
    through: str


COUPLINGS = (
    Coupling(
        "blade.flap1",
        "tower.fa1",
        "the rotor's thrust couples the blades' collective flap with the tower's fore-aft "
        "bending (Hau 7.5)",
    ),
    Coupling(
        "blade.edge1",
        "drivetrain.*.1",
        "the rotor's torque couples the blades' collective edgewise bending with the drive "
        "train's torsion (Hau 7.3.3: then 'no longer permissible to consider the drive train "
        "in isolation')",
    ),
)


@dataclass(frozen=True)
class Closeness:
    """Two modes of different subsystems at their closest."""

    first: Mode
    second: Mode
    separation: float  # |f₁ − f₂| / min(f₁, f₂) at its least
    rpm: float  # where
    first_hz: float
    second_hz: float
    through: str

    @property
    def close(self) -> bool:
        return self.separation < CLOSE

    @property
    def coupled(self) -> tuple[str, ...]:
        """The coupled modes judged in the pair's place (empty: judged apart)."""
        ids = (self.first.superseded_by, self.second.superseded_by)
        return tuple(dict.fromkeys(i for i in ids if i is not None))


def _matches(mode: Mode, pattern: str) -> bool:
    head, _, tail = pattern.partition("*")
    return mode.id == pattern if not tail else mode.id.startswith(head) and mode.id.endswith(tail)


def _speeds(mode: Mode, op: OperatingRange) -> np.ndarray:
    """Standstill, and the steady range where the mode exists there [rad/s]."""
    steady = mode.regimes is None or "steady" in mode.regimes
    ranges = [np.linspace(lo, hi, SPEED_POINTS) for lo, hi in op.steady] if steady else []
    parked = mode.regimes is None or not mode.regimes  # a mode of no regime: parked only
    return np.concatenate([[0.0] if parked else [], *ranges])


def assess(modes: Sequence[Mode], op: OperatingRange) -> list[Closeness]:
    """Each named coupling's pairs present in ``modes`` (isolated, computed or given), at
    their closest over the speeds both meet."""
    out = []
    for coupling in COUPLINGS:
        firsts = [m for m in modes if _matches(m, coupling.first)]
        seconds = [m for m in modes if _matches(m, coupling.second)]
        for a in firsts:
            for b in seconds:
                omega = np.intersect1d(_speeds(a, op), _speeds(b, op))
                fa, fb = a.frequency_at(omega), b.frequency_at(omega)
                usable = (fa > 0) & (fb > 0)
                if not usable.any():
                    continue
                gap = np.abs(fa - fb) / np.minimum(fa, fb)
                gap[~usable] = np.inf
                i = int(np.argmin(gap))
                out.append(
                    Closeness(
                        a,
                        b,
                        float(gap[i]),
                        float(omega[i] * 30 / np.pi),
                        float(fa[i]),
                        float(fb[i]),
                        coupling.through,
                    )
                )
    return out


RULE = Rule(
    "natural frequencies of different subsystems apart",
    "Hau, Wind Turbines, ch. 7: the natural frequencies of rotor blades, tower and drive "
    f"train must not be too close to each other (here: within {CLOSE:.0%}); 7.3.3, 7.5",
)


def check(modes: Sequence[Mode], op: OperatingRange) -> Check | None:
    """``system.closeness``: warn where a named pair is close and judged apart; info where a
    coupled model judges it; pass where every pair is apart. None: no pair to compare."""
    found = assess(modes, op)
    if not found:
        return None
    close = [c for c in found if c.close]
    apart = [c for c in close if not c.coupled]
    status: Status = "warn" if apart else "info" if close else "pass"

    def line(c: Closeness) -> str:
        where = "at standstill" if c.rpm == 0 else f"at {c.rpm:.3g} rpm"
        text = (
            f"{c.first.id} {c.first_hz:.3g} Hz and {c.second.id} {c.second_hz:.3g} Hz "
            f"{c.separation:.0%} apart {where}"
        )
        if not c.close:
            return text
        judged = (
            f"the coupled model judges {' and '.join(c.coupled)} in their place"
            if c.coupled
            else "judged apart, on isolated models: give the turbine a coupled model or move one"
        )
        return f"{text} — {c.through}; {judged}"

    shown = close or found
    message = (
        "; ".join(line(c) for c in shown)
        if close
        else "No two subsystems' modes the chapter names as coupled lie within "
        f"{CLOSE:.0%}: " + "; ".join(line(c) for c in shown)
    )
    return Check(
        id="system.closeness",
        subsystem="system",
        status=status,
        message=message,
        rule=RULE,
        numbers={
            "pairs": [
                {
                    "modes": [c.first.id, c.second.id],
                    "frequencies_hz": [round(c.first_hz, 6), round(c.second_hz, 6)],
                    "rpm": round(c.rpm, 4),
                    "separation": round(c.separation, 6),
                    "coupled": list(c.coupled),
                }
                for c in found
            ]
        },
    )
