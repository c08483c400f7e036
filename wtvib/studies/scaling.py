"""Mass scaling laws: what a tower head of a given rotor size and rating usually weighs.

A plausibility check of given or imported masses, not a model: the NREL Cost and Scaling
Model's component masses in their 2015 update (Fingersh, Hand and Laxson 2006,
NREL/TP-500-40566; coefficients as updated in 2015 and published in WISDEM's
``wisdem/nrelcsm/nrel_csm_mass_2015.py``), each a function of rotor diameter D [m], rated
power P [kW] and rated rotor torque Q:

* rotor: blades 0.5·(D/2)^2.5 each (class II+, no carbon), hub 2.3·m_blade + 1,320, pitch
  system (0.1295·N·m_blade + 491.31)·1.328 + 555, spinner 15.5·D − 980;
* nacelle: low-speed shaft 13·(m_blade·P/1000)^0.65 + 775, two main bearings 1e-4·D^3.5,
  gearbox 113·Q[kN·m]^0.71, high-speed side 0.19894·P, brake 0.00122·Q[N·m], generator
  2.3·P + 3,400, bedplate D^2.2 (and platforms 0.125 of it), yaw system 1.5·9e-4·D^3.314,
  cooling 0.08·P, cover 1.2817·P + 428.19, transformer 1.915·P + 1,910.

The regressions were fitted to geared turbines of the WindPACT era (0.75–5 MW); direct-drive
nacelles, the largest offshore machines and the prototypes of the 1980s depart from them by
tens of per cent to several times, so only a factor of :data:`FAR` either way is called far
off: the check catches a unit slip or a slipped digit, not a nacelle 25 % too heavy (the
windIO importer's comparison of a file's own two masses does that).
"""

import math
from dataclasses import dataclass

from ..spec import Spec

#: A tower head more than this factor above or below the scaling law's is far off (wtvib's
#: choice: the modern reference turbines lie within a factor 1.6 of the law —
#: tests/validation/test_scaling.py — but the prototypes of the 1980s were far heavier: the
#: Tjæreborg's published components weigh 292 t against the law's 65 t, 4.5 times; a head in
#: tonnes given as kilograms is 1000 times off, a slipped digit 10 times).
FAR = 5.0


@dataclass(frozen=True)
class HeadMass:
    """The scaling law's tower-head mass [kg]: rotor (blades, hub system) and nacelle."""

    rotor_kg: float
    nacelle_kg: float

    @property
    def total_kg(self) -> float:
        return self.rotor_kg + self.nacelle_kg


def head_mass(diameter_m: float, power_kw: float, blades: int, rated_rpm: float) -> HeadMass:
    """Rotor and nacelle mass of the NREL CSM (2015) for a geared turbine [kg]."""
    d, p = diameter_m, power_kw
    blade = 0.5 * (d / 2) ** 2.5
    hub = 2.3 * blade + 1320.0
    pitch = (0.1295 * blade * blades + 491.31) * 1.328 + 555.0
    spinner = max(15.5 * d - 980.0, 0.0)
    torque_nm = p * 1e3 / 0.95 / (rated_rpm * math.pi / 30)  # rotor torque at rated power
    bedplate = d**2.2
    nacelle = (
        13.0 * (blade * p / 1000) ** 0.65
        + 775.0
        + 2 * 1e-4 * d**3.5
        + 113.0 * (torque_nm / 1e3) ** 0.71
        + 0.19894 * p
        + 0.00122 * torque_nm
        + 2.3 * p
        + 3400.0
        + 1.125 * bedplate
        + 1.5 * 9e-4 * d**3.314
        + 0.08 * p
        + 1.2817 * p
        + 428.19
        + 1.915 * p
        + 1910.0
    )
    return HeadMass(blade * blades + hub + pitch + spinner, nacelle)


def rated_power_kw(spec: Spec) -> float | None:
    """The spec's rated power, wherever it is given."""
    aero = spec.aerodynamics.control.rated_power_kw if spec.aerodynamics else None
    gen = spec.drivetrain.generator_model
    return spec.turbine.rated_power_kw or aero or (gen.rated_power_kw if gen else None)


def head_warning(spec: Spec) -> str | None:
    """One line when the tower-head mass is more than :data:`FAR` from the scaling law's."""
    head, d, p = spec.tower_head, spec.turbine.rotor_diameter_m, rated_power_kw(spec)
    if head is None or not d or not p or spec.rotor.orientation == "vertical-axis":
        return None
    law = head_mass(d, p, spec.rotor.blades, spec.rotor.speed.top_rpm)
    ratio = head.mass_kg / law.total_kg
    if 1 / FAR <= ratio <= FAR:
        return None
    return (
        f"tower_head.mass_kg: {head.mass_kg / 1e3:,.0f} t is {ratio:.1f} times what the NREL "
        f"cost-and-scaling model (2015 masses) gives for a {d:g} m, {p:,.0f} kW rotor "
        f"({law.total_kg / 1e3:,.0f} t: rotor {law.rotor_kg / 1e3:,.0f} t, nacelle "
        f"{law.nacelle_kg / 1e3:,.0f} t) — check the head mass; the tower frequencies "
        "scale with it"
    )
