"""A tuned mass damper in the blade tip (Hau 7.2.3: the dampers LM put in its blade tips
against edgewise vibration): what it adds to the damping of the mode it is tuned to.

A damper of mass m on a mode of generalised mass M (shape 1 where the damper sits), mass
ratio μ = m/M, tuned and damped as Den Hartog's optimum — frequency ratio 1/(1 + μ),
damping ratio √(3μ/(8(1 + μ)³)) — caps the mode's resonant amplification at √(1 + 2/μ)
(J. P. Den Hartog, *Mechanical Vibrations*, 4th ed., 1956, §3.3). The mode is judged as a
single mode with the equivalent damping ratio that gives the same peak,
ζ_e = 1/(2·√(1 + 2/μ)) ≈ √(μ/8), added to its own. The damper's own degree of freedom and
its detuning by rotation (centrifugal stiffening of the mode) are not modelled; stated.
"""

import math
from collections.abc import Mapping
from dataclasses import replace

from ..results import Mode
from ..rules import HEAVY_DAMPING
from ..spec import Spec
from .aerodamping import generalised_mass


def optimal_tuning(mu: float) -> tuple[float, float]:
    """Den Hartog's optimum for mass ratio μ: the damper's frequency over the mode's, and
    its damping ratio."""
    return 1.0 / (1.0 + mu), math.sqrt(3.0 * mu / (8.0 * (1.0 + mu) ** 3))


def equivalent_damping(mu: float) -> float:
    """The damping ratio that gives a single mode the optimally damped peak √(1 + 2/μ)."""
    return 1.0 / (2.0 * math.sqrt(1.0 + 2.0 / mu))


def modify(
    spec: Spec, built: Mapping[str, list[Mode]], heavy: float = HEAVY_DAMPING
) -> tuple[dict[str, list[Mode]], tuple[str, ...]]:
    """The :class:`wtvib.judge.analysis.Modifier` protocol: the tuned blade mode's damping, in the
    isolated blade model and in the coupled modes it stands in (``system.blade.<mode>.*``),
    raised by the damper's equivalent ζ; unchanged without a ``blade.tip_damper``."""
    damper = spec.blade.tip_damper
    if damper is None:
        return dict(built), ()
    target = f"blade.{damper.tuned_to}"
    base = next((m for ms in built.values() for m in ms if m.id == target), None)
    st = spec.blade.structure
    if base is None:
        return dict(built), (f"blade.tip_damper: no {target} mode to tune to; ignored.",)
    root = st.hub_radius_m if st is not None else 0.0
    tip = root + (st.span_m[-1] if st is not None else (spec.blade.length_m or 0.0))
    found = generalised_mass(spec, base, root, tip)
    if found is None:
        return dict(built), (
            "blade.tip_damper: the blade's mass and length (or structure) are needed for its "
            "mass ratio; ignored.",
        )
    mu = damper.mass_kg / found[2]
    zeta = equivalent_damping(mu)
    tuning, own = optimal_tuning(mu)
    source = f"+ tip damper ζ_e = {zeta:.4f} (μ = {mu:.4f})"
    out = {
        sub: [
            replace(
                m,
                damping_ratio=(m.damping_ratio or 0.0) + zeta,
                damping_source=f"{m.damping_source or 'structural'} {source}",
            )
            if m.id == target or m.id.startswith(f"system.{target}.")
            else m
            for m in modes
        ]
        for sub, modes in built.items()
    }
    note = (
        f"blade.tip_damper: a tuned mass damper of {damper.mass_kg:g} kg in each blade tip on "
        f"{target} (generalised mass {found[2]:,.0f} kg with its shape 1 at the tip: "
        f"μ = {mu:.4f}), tuned and damped as Den Hartog's optimum (frequency ratio "
        f"{tuning:.4f}, damper damping ratio {own:.4f}): the mode's peak amplification "
        f"√(1 + 2/μ) = {math.sqrt(1 + 2 / mu):.3g}, its damping raised by the equivalent "
        f"ζ_e = {zeta:.4f} (in the coupled modes of that family too); the damper's own mode "
        "and its detuning by rotation are not modelled."
    )
    return out, (note,)
