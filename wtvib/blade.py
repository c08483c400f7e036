"""Rotor blades: flap, edge and torsion modes with rotational (centrifugal) stiffening."""

from .given import given_modes, ordinal
from .results import Mode, Southwell, SpeedCurve
from .spec import ModeSpec, Spec

#: Southwell coefficients used when the spec gives none: uniform cantilever, no hub offset
#: (flap K ≈ 1.19; edge K_flap − 1 ≈ 0.19; torsion: no stiffening). DOMAIN.md §3, after
#: Southwell & Gough (1921).
DEFAULT_SOUTHWELL = {"flap": 1.19, "edge": 0.19, "tor": 0.0}

_KIND = {"flap": "flapwise bending", "edge": "edgewise (chordwise) bending", "tor": "torsion"}


def southwell_default(name: str) -> float:
    """Default Southwell coefficient of a blade mode name (``flap1`` → 1.19)."""
    return DEFAULT_SOUTHWELL[name.rstrip("0123456789")]


def modes(spec: Spec) -> list[Mode]:
    """Blade modes (ids ``blade.flap1``, ``blade.edge1``, ``blade.tor1`` …).

    Frequencies in the spec are standstill values; each mode gets the curve
    f² = f₀² + K·(Ω/2π)² with the spec's Southwell coefficient or the default.
    """

    def describe(name: str) -> str:
        kind = name.rstrip("0123456789")
        return f"{ordinal(int(name[len(kind) :]))} blade {_KIND[kind]}"

    def curve(name: str, f0: float, full: ModeSpec | None) -> SpeedCurve | None:
        k = full.southwell if full and full.southwell is not None else southwell_default(name)
        return Southwell(f0, k) if k > 0 else None

    return given_modes("blade", spec.blade.modes, describe, curve)
