"""Resonance margin rules and the presets of the codes that define them.

A rule turns "is this natural frequency too close to that excitation?" into a number. Both
rules forbid a band of excitation frequencies around the natural frequency f_n:

* ``band`` (Hau): the natural frequency keeps a distance of at least ``m`` times the
  excitation frequency, ``|f_n - f_exc| >= m * f_exc``.
* ``ratio``: the frequency ratio stays outside ``1 ± m``, ``f_exc / f_n <= 1 - m`` or
  ``>= 1 + m``.

A separation exactly equal to the margin passes ("at least 10 %"); a relative tolerance of
:data:`EDGE_TOLERANCE` absorbs floating-point rounding at that edge.

References
----------
.. [1] E. Hau, *Wind Turbines*, ch. 7.5.1: "a safety distance of at least 10 % from the
   dominant frequency of excitation is a good guide value".
.. [2] Germanischer Lloyd, *Guideline for the Certification of Wind Turbines*, 2010,
   as widely quoted: f_exc/f_n <= 0.95 or >= 1.05. Not verified against the primary text.
"""

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Literal, TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

RuleName = Literal["band", "ratio"]
Status = Literal["pass", "info", "warn", "fail"]
Energy = Literal["dominant", "secondary", "minor"]

#: Relative slack at the margin edge so that a case exactly at the margin passes.
EDGE_TOLERANCE = 1e-9

#: A mode at least this damped has no resonant peak worth a margin: its peak amplification
#: 1/(2ζ√(1 − ζ²)) is at most 1.75 at 0.3 — its margin violations are reported as info
#: (``audit.heavy_damping_ratio``'s default, and the resonance routine's).
HEAVY_DAMPING = 0.3

STATUS_ORDER: dict[str, int] = {"pass": 0, "info": 1, "warn": 2, "fail": 3}

#: A damping ratio counts as negative below −this: the tools write a mode without any
#: damping (a platform yaw with no hydrodynamic damping) as −0.000000…, rounding's sign, and
#: a computed one lands within rounding of zero likewise. One threshold for every check that
#: judges a sign of damping (``system.stability``, ``aerodynamics.stability``, the stall
#: checks) and every figure that colours one.
NEGATIVE = 1e-6


def worst(statuses: "list[Status] | tuple[Status, ...]") -> Status:
    """The most severe of some statuses (``pass`` when there are none)."""
    return max(statuses, key=STATUS_ORDER.__getitem__, default="pass")


@dataclass(frozen=True)
class Preset:
    """Margin rule, margin and highest harmonic that a code or guideline prescribes."""

    name: str
    rule: RuleName
    margin: float
    source: str
    secondary: Status = "fail"


PRESETS: dict[str, Preset] = {
    "hau": Preset(
        "hau",
        "band",
        0.10,
        "Hau, Wind Turbines, ch. 7.5.1: safety distance of at least 10 % from the "
        "dominant excitation frequency (guide value from experience); 2P on three-bladed "
        "rotors fails at rated speed too (ch. 7.5.2, WKA-60)",
    ),
    "gl2010": Preset(
        "gl2010",
        "ratio",
        0.05,
        "GL Guideline 2010 as widely quoted: f_exc/f_n <= 0.95 or >= 1.05 "
        "(not verified against the primary text); only 1P and N_b·P fail",
        secondary="warn",
    ),
}


@dataclass(frozen=True)
class MarginRule:
    """A margin rule in force: its kind, margin and where it comes from."""

    kind: RuleName
    margin: float
    source: str
    preset: str | None = None

    @property
    def label(self) -> str:
        """Short text naming the rule, e.g. ``band ≥10 % (hau)``."""
        sym = "|f_n−f_exc| ≥ m·f_exc" if self.kind == "band" else "f_exc/f_n ∉ (1−m, 1+m)"
        name = f" ({self.preset})" if self.preset else ""
        return f"{sym}, m = {self.margin:.0%}{name}"

    def separation(self, f_exc: ArrayLike, f_n: ArrayLike) -> NDArray[np.float64]:
        """Separation of excitation and natural frequency in this rule's measure. [-]"""
        fe = np.asarray(f_exc, dtype=float)
        fn = np.asarray(f_n, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore"):
            if self.kind == "band":
                sep = np.where(fe > 0, np.abs(fn - fe) / fe, np.inf)
            else:
                sep = np.abs(fe / fn - 1.0)
        return np.asarray(sep, dtype=float)

    def violates(self, separation: ArrayLike) -> NDArray[np.bool_]:
        """True where a separation is short of the margin (the edge itself passes)."""
        return np.asarray(separation) < self.margin * (1.0 - EDGE_TOLERANCE)

    def forbidden_band(self, f_n: float) -> tuple[float, float]:
        """Excitation frequencies [Hz] this rule forbids around a natural frequency f_n."""
        if self.kind == "band":
            return f_n / (1.0 + self.margin), f_n / (1.0 - self.margin)
        return f_n * (1.0 - self.margin), f_n * (1.0 + self.margin)

    def natural_band(self, f_exc: float) -> tuple[float, float]:
        """Natural frequencies [Hz] this rule forbids around an excitation frequency."""
        if self.kind == "band":
            return f_exc * (1.0 - self.margin), f_exc * (1.0 + self.margin)
        return f_exc / (1.0 + self.margin), f_exc / (1.0 - self.margin)


def dynamic_amplification(eta: ArrayLike, zeta: float) -> NDArray[np.float64]:
    """Dynamic amplification factor of a single-degree-of-freedom oscillator.

    Parameters
    ----------
    eta
        Frequency ratio f_exc / f_n. [-]
    zeta
        Damping ratio. [-]

    Notes
    -----
    DAF = 1 / sqrt((1 - η²)² + (2ζη)²); at resonance (η = 1) it is 1/(2ζ), infinite for an
    undamped mode.

    References
    ----------
    Hau, ch. 7.5.2 (Fig. 7.27, WKA-60 amplification); any structural-dynamics text, e.g.
    Clough & Penzien, *Dynamics of Structures*, eq. 3-21.
    """
    e = np.asarray(eta, dtype=float)
    with np.errstate(divide="ignore"):
        return np.asarray(1.0 / np.sqrt((1.0 - e**2) ** 2 + (2.0 * zeta * e) ** 2))


#: A check as a document (:class:`wtvib.document.CheckDoc`, a batch row's dictionary).
C = TypeVar("C", bound=Mapping[str, object])


def worst_check(checks: Sequence[C]) -> C | None:
    """The check that decided the verdict: the most severe warn or fail, among equals the one
    with the least margin; None when every check passed (an info row decides nothing)."""

    def severity(c: C) -> tuple[int, float]:
        margin: Any = c.get("margin")
        return STATUS_ORDER[str(c["status"])], -margin if margin is not None else -math.inf

    deciding = [c for c in checks if c["status"] in ("warn", "fail")]
    return max(deciding, key=severity, default=None)
