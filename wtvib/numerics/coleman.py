"""The multi-blade (Coleman) transformation: each blade's coordinate as the rotor's
collective, cyclic and alternating coordinates, and its azimuth derivatives.

ηⱼ = a₀ + Σ_h (a_hc cos hψⱼ + a_hs sin hψⱼ) (+ (−1)ʲ a_alt for even N), ψⱼ = ψ + 2πj/N.
Used by the coupled model (:mod:`wtvib.subsystems.multiblade`) and by the reader of OpenFAST's
linearisations (MBC3), which must agree on it.

References
----------
G. Bir, "Multi-blade coordinate transformation and its application to wind turbine
analysis", AIAA 2008-1300.
"""

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]


def coleman(blades: int, psi: float) -> tuple[Array, Array, Array, tuple[str, ...]]:
    """B(ψ), dB/dψ, d²B/dψ² with ηⱼ = Σ_h B[j, h]·a_h, and the names of the a_h.

    Columns: collective, (cos h·ψⱼ, sin h·ψⱼ) for h = 1 … (N−1)//2, and for even N the
    alternating (−1)ʲ coordinate (Bir 2008).
    """
    psi_j = psi + 2 * np.pi * np.arange(blades) / blades
    cols: list[Array] = [np.ones(blades)]
    d1: list[Array] = [np.zeros(blades)]
    d2: list[Array] = [np.zeros(blades)]
    names = ["collective"]
    for h in range(1, (blades - 1) // 2 + 1):
        c, s = np.cos(h * psi_j), np.sin(h * psi_j)
        cols += [c, s]
        d1 += [-h * s, h * c]
        d2 += [-(h**2) * c, -(h**2) * s]
        names += [f"cos{h}", f"sin{h}"]
    if blades % 2 == 0:
        cols.append(np.where(np.arange(blades) % 2 == 0, 1.0, -1.0))
        d1.append(np.zeros(blades))
        d2.append(np.zeros(blades))
        names.append("alternating")
    return np.stack(cols, 1), np.stack(d1, 1), np.stack(d2, 1), tuple(names)
