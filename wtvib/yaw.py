"""Yaw system: natural frequencies of the tower head about the yaw axis."""

from .given import given_modes, ordinal
from .results import Mode
from .spec import Spec


def modes(spec: Spec) -> list[Mode]:
    """Yaw modes given in the spec (ids ``yaw.1``, ``yaw.2`` …)."""
    return given_modes("yaw", spec.yaw.modes, lambda n: f"{ordinal(int(n))} yaw mode")
