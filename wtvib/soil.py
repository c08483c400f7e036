"""Monopile foundations: the embedded pile on distributed soil springs, reduced to the
stiffness it gives the tower base at the mudline, with lower- and upper-bound soil.

Winkler model: per unit length of pile the soil resists a lateral deflection y with
p = E_py(z)·y, E_py the initial (small-strain) slope of the p-y curves — the stiffness that
sets natural frequencies. Sand: E_py = k·z with k the initial modulus of subgrade reaction
for the friction angle φ′ (API RP 2GEO 2011 and DNV-RP-C212, which tabulate k against φ′;
the fit k = max(197.8·φ′² − 10,232·φ′ + 136,820, 5,400) kN/m³ of openpile's documentation,
TchilDill/openpile `docs/source/PYmodels.rst`, submerged sand). Other soils: E_py given
(a site's own value, or clay's from its report), constant or growing with depth.

The pile is an Euler–Bernoulli tube (wtvib.beam) with the springs' consistent stiffness
∫NᵀE_py N dz assembled like a mass matrix, condensed to the head's lateral and rocking
degrees of freedom: K = [[K_L, K_LR], [K_LR, K_R]] at the mudline. Closed forms this
reproduces (tests/validation/test_soil.py): a long pile in uniform springs (Hetényi 1946:
K_L = 4EIβ³, K_LR = −2EIβ², K_R = 2EIβ, β = (E_py/4EI)^¼) and a rigid one (K_L = E_py·L,
K_LR = −E_py·L²/2, K_R = E_py·L³/3).
"""

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from . import beam

if TYPE_CHECKING:
    from .spec.tower import Pile, SoilLayer

Array = NDArray[np.float64]

#: Elements along the embedded pile.
PILE_ELEMENTS = 40


def sand_subgrade_n_m3(phi_deg: float) -> float:
    """Initial modulus of subgrade reaction k of submerged sand [N/m³] (module docstring)."""
    return 1e3 * max(197.8 * phi_deg**2 - 10232.0 * phi_deg + 136820.0, 5400.0)


def modulus(layers: "list[SoilLayer]", z: Array) -> Array:
    """E_py [N/m²] at depths ``z`` below the mudline."""
    out = np.zeros_like(z)
    top = 0.0
    for layer in layers:
        inside = (z >= top) & (z <= layer.bottom_m)
        if layer.kind == "sand":
            assert layer.friction_angle_deg is not None
            out[inside] = sand_subgrade_n_m3(layer.friction_angle_deg) * z[inside]
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
