"""Rigid bodies on the tower top: the tower head assembled from its parts (the importers),
the nacelle as the tower head less its rotor.

Shared by the spec's load-time check of a ``coupled`` block (so that a mistake is one line
naming field and file line) and the coupled model (:mod:`wtvib.subsystems.coupled`), without either
importing the other.
"""

from dataclasses import dataclass
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from ..errors import SpecError
from . import beam


@dataclass(frozen=True)
class Part:
    """A rigid part on the tower top: its mass [kg] at x downwind of the tower axis and z
    above the top [m], and its own inertias about its centre of mass [kg·m²]."""

    name: str
    mass: float
    x: float
    z: float
    pitch: float = 0.0
    roll: float = 0.0
    yaw: float = 0.0

    def as_head(self) -> dict[str, float]:
        """The spec's ``tower_head`` entries of this body."""
        return {
            "mass_kg": self.mass,
            "cm_downwind_m": self.x,
            "cm_above_top_m": self.z,
            "inertia_pitch_kgm2": self.pitch,
            "inertia_roll_kgm2": self.roll,
            "inertia_yaw_kgm2": self.yaw,
        }


def assembled(parts: "list[Part]", name: str = "tower head") -> Part:
    """The parts as one rigid body: its mass, centre of mass and its inertias there — each
    part's own plus its mass times the square of its offset from the common centre
    (parallel axes); an inertia a part's own negative share (a measured total less a
    parallel-axis term) would make negative is held at zero."""
    mass = sum(p.mass for p in parts)
    x = sum(p.mass * p.x for p in parts) / mass
    z = sum(p.mass * p.z for p in parts) / mass
    pitch = sum(p.pitch + p.mass * ((p.x - x) ** 2 + (p.z - z) ** 2) for p in parts)
    roll = sum(p.roll + p.mass * (p.z - z) ** 2 for p in parts)
    yaw = sum(p.yaw + p.mass * (p.x - x) ** 2 for p in parts)
    return Part(name, mass, x, z, max(pitch, 0.0), max(roll, 0.0), max(yaw, 0.0))


class Head(Protocol):
    """What :func:`nacelle` reads of a tower head (the spec's ``TowerHead`` has it): its mass
    [kg], CM downwind of the tower axis and above the top [m], inertias about the CM
    [kg·m²]."""

    @property
    def mass_kg(self) -> float: ...
    @property
    def cm_downwind_m(self) -> float: ...
    @property
    def cm_above_top_m(self) -> float: ...
    @property
    def inertia_roll_kgm2(self) -> float: ...
    @property
    def inertia_pitch_kgm2(self) -> float: ...
    @property
    def inertia_yaw_kgm2(self) -> float: ...


Array = NDArray[np.float64]


@dataclass(frozen=True)
class Rigid:
    """A rigid part: mass at c (tower-top axes) and inertia about its CM (roll, tilt, yaw)."""

    mass: float
    c: Array
    inertia: Array


@dataclass(frozen=True)
class RotorPoints:
    """A blade as point masses at its elements' Gauss points: radius from the rotor axis
    [m] and mass [kg] of each point — how the coupled model carries the blades, and how the
    spec's load-time check weighs the rotor, so that both agree."""

    radius: Array
    mass: Array
    nodes: Array
    basis: beam.Basis

    def polar(self) -> float:
        """One blade's inertia about the rotor axis. [kg·m²]"""
        return float(np.sum(self.mass * self.radius**2))


def rotor_points(
    hub_radius: float, span: Array, mass_per_length: Array, elements: int = beam.BLADE_ELEMENTS
) -> RotorPoints:
    """The blade's Gauss points on the mesh the blade model uses (``beam.mesh``)."""
    span = np.asarray(span, dtype=float)
    nodes = beam.mesh(span, elements)
    b = beam.basis(nodes)
    m = beam.interpolate(b.x, span, np.asarray(mass_per_length, dtype=float)) * b.w
    return RotorPoints((hub_radius + b.x).ravel(), m.ravel(), nodes, b)


def nacelle(head: Head, apex: Array, m_rotor: float, j_polar: float) -> Rigid:
    """The tower head minus a rotor of mass m_rotor at the apex with polar inertia J_p (and
    J_p/2 about any diameter, exact for three or more blades).

    Raises
    ------
    SpecError
        The head's mass or an inertia cannot hold the rotor (``path`` names the field).
    """
    m_nac = head.mass_kg - m_rotor
    if m_nac <= 0:
        raise SpecError(
            f"{head.mass_kg:,.0f} kg is no more than the rotor it must include "
            f"({m_rotor:,.0f} kg, blades and hub) — the coupled model takes the nacelle as the "
            "tower head minus the rotor",
            path="tower_head.mass_kg",
        )
    c_head = np.array([head.cm_downwind_m, 0.0, head.cm_above_top_m])
    c_nac = (head.mass_kg * c_head - m_rotor * apex) / m_nac
    rotor_own = np.array([j_polar, 0.5 * j_polar, 0.5 * j_polar])
    head_i = np.array([head.inertia_roll_kgm2, head.inertia_pitch_kgm2, head.inertia_yaw_kgm2])

    def steiner(c: Array) -> Array:  # parallel-axis terms about the head CM: roll, tilt, yaw
        dx, dz = c[0] - c_head[0], c[2] - c_head[2]
        return np.array([dz**2, dx**2 + dz**2, dx**2])

    rotor_share = rotor_own + m_rotor * steiner(apex) + m_nac * steiner(c_nac)
    i_nac = head_i - rotor_share
    tolerance = 0.02 * np.maximum(head_i, 1.0)
    if np.any(i_nac < -tolerance):
        k = int(np.argmin(i_nac + tolerance))
        axis = ("roll", "pitch", "yaw")[k]
        raise SpecError(
            f"{head_i[k]:,.4g} kg·m² is less than the rotor's and the nacelle's offsets alone "
            f"need about the head's CM ({rotor_share[k]:,.4g} kg·m²) — the coupled model "
            "takes the tower head's inertias to include the rotor",
            path=f"tower_head.inertia_{axis}_kgm2",
        )
    return Rigid(m_nac, c_nac, np.maximum(i_nac, 0.0))
