"""Modes whose natural frequencies the spec gives directly (before any model computes them)."""

import math
from collections.abc import Callable, Mapping

from ..results import Mode, Sampled, SpeedCurve, by_frequency
from ..spec import ModeEntry, ModeSpec


def given_modes(
    subsystem: str,
    entries: Mapping[str, ModeEntry],
    describe: Callable[[str], str],
    curve: Callable[[str, float, ModeSpec | None], SpeedCurve | None] | None = None,
) -> list[Mode]:
    """Turn spec entries (a number, or a mapping with frequency and damping) into modes.

    Parameters
    ----------
    subsystem
        Subsystem name, also the prefix of each mode id (``tower`` → ``tower.fa1``).
    entries
        Mode name → spec entry.
    describe
        Mode name → human description.
    curve
        Optional: (name, standstill frequency, full entry) → frequency-vs-speed curve (the
        subsystem's stiffening law); an entry's own ``speeds`` table replaces it.
    """
    modes = []
    for name, entry in entries.items():
        full = entry if isinstance(entry, ModeSpec) else None
        f0 = full.frequency_hz if full else float(entry)  # type: ignore[arg-type]
        text = full.description if full and full.description else describe(name)
        modes.append(
            Mode(
                id=f"{subsystem}.{name}",
                subsystem=subsystem,
                description=text,
                frequency_hz=f0,
                damping_ratio=full.damping_ratio if full else None,
                curve=table(full)
                if full and full.speeds
                else (curve(name, f0, full) if curve else None),
            )
        )
    return sorted(modes, key=by_frequency)


def table(entry: ModeSpec) -> Sampled:
    """A mode's ``speeds`` table as a curve over rotor speed [rad/s], from standstill."""
    assert entry.speeds is not None
    rpm, hz = list(entry.speeds.rpm), list(entry.speeds.frequency_hz)
    if rpm[0] > 0:
        rpm, hz = [0.0, *rpm], [entry.frequency_hz, *hz]
    return Sampled(tuple(r * math.pi / 30 for r in rpm), tuple(hz))
