"""The Campbell data: every judged mode's frequency and damping, sampled over speed.

With aerodynamics the samples are the steady operating points (wind, rotor speed, pitch),
the damping the mode's total (aerodynamic + structural) there; without, rotor speeds from
standstill to the overspeed limit and the structural damping. Frequencies are the judged
ones (the mode's curve), so each id has one frequency everywhere in the report.
"""

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, cast

import numpy as np

from ..document import CampbellDoc
from ..results import Mode
from .excitation import OperatingRange

#: Rotor speeds sampled without a schedule (standstill … overspeed).
SPEED_SAMPLES = 30


@dataclass(frozen=True)
class Campbell:
    """Sampled curves: ``rpm`` (and, with a schedule, ``wind``, ``pitch``) per sample."""

    rpm: tuple[float, ...]
    wind: tuple[float, ...] | None
    pitch_deg: tuple[float, ...] | None
    modes: dict[str, tuple[tuple[float, ...], tuple[float, ...]]]  # id → (f [Hz], ζ)
    aero: dict[str, tuple[float, ...]]  # id → aerodynamic part of ζ (modes in operation)
    #: id → the aeroelastic root at each point: natural and damped frequency [Hz] and how
    #: the point was obtained (results.OperatingDamping.method); modes in operation
    roots: dict[str, tuple[tuple[float, ...] | None, tuple[float, ...] | None, tuple[str, ...]]] = (
        field(default_factory=dict)
    )
    #: id → the total damping with quasi-steady aerodynamics (no shed-wake lag of the
    #: lift), for comparison; modes in operation
    quasi_steady: dict[str, tuple[float, ...]] = field(default_factory=dict)

    def to_dict(self) -> CampbellDoc:
        out: dict[str, Any] = {
            "damping": "in operation (aerodynamic + structural)" if self.wind else "structural",
            "rpm": [round(v, 4) for v in self.rpm],
        }
        if self.wind is not None and self.pitch_deg is not None:
            out["wind_m_s"] = [round(v, 4) for v in self.wind]
            out["pitch_deg"] = [round(v, 4) for v in self.pitch_deg]
        out["modes"] = {
            mid: {
                "frequency_hz": [round(v, 6) for v in f],
                "damping_ratio": [round(v, 6) for v in z],
                **(
                    {"aerodynamic_damping_ratio": [round(v, 6) for v in self.aero[mid]]}
                    if mid in self.aero
                    else {}
                ),
                **self._roots(mid),
                **(
                    {"quasi_steady_damping_ratio": [round(v, 6) for v in self.quasi_steady[mid]]}
                    if mid in self.quasi_steady
                    else {}
                ),
            }
            for mid, (f, z) in self.modes.items()
        }
        return cast(CampbellDoc, out)  # the optional keys where they apply

    def _roots(self, mid: str) -> dict[str, Any]:
        if mid not in self.roots:
            return {}
        natural, damped, method = self.roots[mid]
        out: dict[str, Any] = {"method": list(method)}
        if natural is not None and damped is not None:
            out["aeroelastic_frequency_hz"] = [round(v, 6) for v in natural]
            out["damped_frequency_hz"] = [round(v, 6) for v in damped]
        return out


def build(modes: Sequence[Mode], op: OperatingRange) -> Campbell:
    """The Campbell data of every judged mode (a mode without a speed curve is a constant
    line of the diagram, and is sampled as one)."""
    picked = [m for m in modes if m.judged]
    # the steady operating points of the aerodynamics (another tool's points carry no
    # schedule of ours: sampled over speed like a structural audit, its damping interpolated)
    scheduled = next(
        (m.operating for m in picked if m.operating is not None and m.origin != "imported"),
        None,
    )
    if scheduled is not None:
        omega = np.asarray(scheduled.omega)
        wind: tuple[float, ...] | None = scheduled.wind
        pitch: tuple[float, ...] | None = scheduled.pitch_deg
    else:
        omega = np.linspace(0.0, op.overspeed, SPEED_SAMPLES)
        wind = pitch = None
    rpm = tuple(float(v) for v in omega * 30 / np.pi)
    out: dict[str, tuple[tuple[float, ...], tuple[float, ...]]] = {}
    aero: dict[str, tuple[float, ...]] = {}
    roots = {}
    steady: dict[str, tuple[float, ...]] = {}
    for m in picked:
        f = tuple(float(v) for v in m.frequency_at(omega))
        if m.operating is not None and m.operating.omega == tuple(float(v) for v in omega):
            z = m.operating.total
            aero[m.id] = m.operating.aero
            if m.operating.method is not None:
                roots[m.id] = (m.operating.natural_hz, m.operating.damped_hz, m.operating.method)
            if m.operating.quasi_steady is not None:
                steady[m.id] = m.operating.quasi_steady
        else:
            z = tuple(m.damping_at(float(o), float(m.damping_ratio or 0.0)) for o in omega)
        out[m.id] = (f, z)
    return Campbell(rpm, wind, pitch, out, aero, roots, steady)
