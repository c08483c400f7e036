"""Monopile foundations: the embedded pile on distributed soil springs, reduced to the
stiffness it gives the tower base at the mudline, with lower- and upper-bound soil.

Winkler model: per unit length of pile the soil resists a lateral deflection y with
p = E_py(z)·y, E_py the initial (small-strain) slope of the p-y curves — the stiffness that
sets natural frequencies. Sand: E_py = k·z with k the initial modulus of subgrade reaction
for the friction angle φ′ (API RP 2GEO 2011 and DNV-RP-C212, which tabulate k against φ′;
the fit k = max(197.8·φ′² − 10,232·φ′ + 136,820, 5,400) kN/m³ of openpile's documentation,
TchilDill/openpile `docs/source/PYmodels.rst`, submerged sand). Stiff clay: E_py = k·z with
k for its undrained shear strength s_u from Reese, Cox & Koop (1975, OTC 2312; stiff clay
with free water, the initial straight line p = (k·z)·y; as given in Reese & Van Impe 2011
and OpenBrIM's technical background "Stiff Clay with Free Water"): k = 135, 270 and
540 MN/m³ static for s_u of 50–100, 100–200 and 200–400 kPa, interpolated linearly between
the bands' centres (75, 150, 300 kPa) and held at the end values beyond them; the static
values, since the small vibrations of a natural mode are what they describe (the cyclic
ones, 55/110/540, are within the default lower bound ×0.5 for the two softer bands). Soft
clay (Matlock 1970) has no finite initial slope: give its E_py. Other soils: E_py given
(a site's own value), constant or growing with depth.

The pile is an Euler–Bernoulli tube (wtvib.numerics.beam) with the springs' consistent stiffness
∫NᵀE_py N dz assembled like a mass matrix, condensed to the head's lateral and rocking
degrees of freedom: K = [[K_L, K_LR], [K_LR, K_R]] at the mudline. Closed forms this
reproduces (tests/validation/test_soil.py): a long pile in uniform springs (Hetényi 1946:
K_L = 4EIβ³, K_LR = −2EIβ², K_R = 2EIβ, β = (E_py/4EI)^¼) and a rigid one (K_L = E_py·L,
K_LR = −E_py·L²/2, K_R = E_py·L³/3).

Cross-checks for quick estimates: the continuum closed forms of Shadlou & Bhattacharya
(2016, Soil Dyn. Earthq. Eng. 88, 15–32) for a pile in homogeneous, parabolic or linear
soil (:func:`shadlou`, coefficients as tabulated in Yu & Amdahl 2023, Marine Structures 92,
103482, Table 1), and the pile clamped at an effective fixity depth (:func:`fixity_depth`,
Davisson & Robinson 1965: 1.4·(EI/k)^¼ for a constant modulus, 1.8·(EI/n_h)^⅕ for one
growing linearly with depth).
"""

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from ..numerics import beam

if TYPE_CHECKING:
    from ..spec.tower import Pile, SoilLayer

Array = NDArray[np.float64]

#: Elements along the embedded pile.
PILE_ELEMENTS = 40


def sand_subgrade_n_m3(phi_deg: float) -> float:
    """Initial modulus of subgrade reaction k of submerged sand [N/m³] (module docstring)."""
    return 1e3 * max(197.8 * phi_deg**2 - 10232.0 * phi_deg + 136820.0, 5400.0)


#: Reese et al. (1975) stiff clay: s_u at the bands' centres [Pa] and k static [N/m³].
CLAY_SU_PA = (75e3, 150e3, 300e3)
CLAY_K_N_M3 = (135e6, 270e6, 540e6)


def clay_subgrade_n_m3(su_pa: float) -> float:
    """Initial modulus of subgrade reaction k of stiff clay [N/m³] (module docstring)."""
    return float(np.interp(su_pa, CLAY_SU_PA, CLAY_K_N_M3))


def modulus(layers: "list[SoilLayer]", z: Array) -> Array:
    """E_py [N/m²] at depths ``z`` below the mudline."""
    out = np.zeros_like(z)
    top = 0.0
    for layer in layers:
        inside = (z >= top) & (z <= layer.bottom_m)
        if layer.kind == "sand":
            assert layer.friction_angle_deg is not None
            out[inside] = sand_subgrade_n_m3(layer.friction_angle_deg) * z[inside]
        elif layer.kind == "clay":
            assert layer.undrained_shear_strength_pa is not None
            out[inside] = clay_subgrade_n_m3(layer.undrained_shear_strength_pa) * z[inside]
        else:
            assert layer.modulus_pa is not None
            out[inside] = layer.modulus_pa + layer.gradient_pa_m * (z[inside] - top)
        top = layer.bottom_m
    return out


@dataclass(frozen=True)
class HeadStiffness:
    """The foundation's stiffness at the mudline, tower convention (z up): lateral [N/m],
    coupling [N/rad], rocking [N·m/rad]."""

    lateral: float
    coupling: float
    rocking: float

    def matrix(self) -> Array:
        return np.array([[self.lateral, self.coupling], [self.coupling, self.rocking]])


def head_stiffness(
    pile: "Pile", layers: "list[SoilLayer]", factor: float = 1.0, elements: int = PILE_ELEMENTS
) -> HeadStiffness:
    """The embedded pile on its soil springs (``factor`` on every E_py: the bounds),
    condensed to the mudline."""
    nodes = np.linspace(0.0, pile.embedded_length_m, elements + 1)  # depth, downwards
    b = beam.basis(nodes)
    d, t = pile.diameter_m, pile.wall_thickness_m
    ei = pile.youngs_modulus_pa * np.pi / 64 * (d**4 - (d - 2 * t) ** 4)
    k, winkler = beam.assemble_bending(b, np.full_like(b.x, ei), factor * modulus(layers, b.x))
    total = k + winkler
    head, rest = np.arange(2), np.arange(2, total.shape[0])
    condensed = total[np.ix_(head, head)] - total[np.ix_(head, rest)] @ np.linalg.solve(
        total[np.ix_(rest, rest)], total[np.ix_(rest, head)]
    )
    # the pile's rotation is du/d(depth) = −du/dz of the tower: the coupling changes sign
    return HeadStiffness(float(condensed[0, 0]), -float(condensed[0, 1]), float(condensed[1, 1]))


#: Shadlou & Bhattacharya (2016) via Yu & Amdahl (2023) Table 1: (a, b) of
#: K = f(ν)·E_so·r^n·a·x^b, x = E_pe/E_so (flexible) or L/D (rigid), n = 1, 2, 3 for K_L,
#: K_LR (negative), K_R.
SHADLOU = {
    "flexible": {
        "homogeneous": ((2.9, 0.186), (1.2, 0.5), (1.5, 0.73)),
        "parabolic": ((2.03, 0.27), (1.17, 0.52), (1.42, 0.76)),
        "linear": ((1.58, 0.34), (1.07, 0.567), (1.38, 0.78)),
    },
    "rigid": {
        "homogeneous": ((6.4, 0.62), (7.1, 1.56), (13.2, 2.5)),
        "parabolic": ((5.33, 1.07), (7.2, 2.0), (13.0, 3.0)),
        "linear": ((4.7, 1.53), (7.1, 2.5), (12.7, 3.45)),
    },
}


def shadlou(
    pile: "Pile", soil_modulus_pa: float, profile: str, behaviour: str, poisson: float = 0.3
) -> HeadStiffness:
    """The closed-form mudline stiffness of Shadlou & Bhattacharya (2016) for a pile in
    soil of Young's modulus E_so (at one diameter's depth for parabolic and linear
    profiles), tower convention."""
    d = pile.diameter_m
    r = d / 2
    i = np.pi / 64 * (d**4 - (d - 2 * pile.wall_thickness_m) ** 4)
    e_pe = pile.youngs_modulus_pa * i / (np.pi * d**4 / 64)  # an equivalent solid pile
    x = e_pe / soil_modulus_pa if behaviour == "flexible" else pile.embedded_length_m / d
    f_nu = 1.0 + 0.6 * abs(poisson - 0.25)
    (a1, b1), (a2, b2), (a3, b3) = SHADLOU[behaviour][profile]
    e = f_nu * soil_modulus_pa
    return HeadStiffness(e * r * a1 * x**b1, -e * r**2 * a2 * x**b2, e * r**3 * a3 * x**b3)


def fixity_depth(pile: "Pile", modulus_pa: float = 0.0, gradient_pa_m: float = 0.0) -> float:
    """Depth below the mudline at which a pile clamped there has the soil-supported pile's
    lateral flexibility (Davisson & Robinson 1965): 1.4·R, R = (EI/k)^¼ for a constant
    E_py = k, or 1.8·T, T = (EI/n_h)^⅕ for E_py = n_h·z [m]."""
    d, t = pile.diameter_m, pile.wall_thickness_m
    ei = pile.youngs_modulus_pa * np.pi / 64 * (d**4 - (d - 2 * t) ** 4)
    if gradient_pa_m > 0:
        return float(1.8 * (ei / gradient_pa_m) ** 0.2)
    return float(1.4 * (ei / modulus_pa) ** 0.25)
