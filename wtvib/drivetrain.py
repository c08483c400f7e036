"""Drive-train torsion: modes per generator condition (grid, free, locked)."""

from .given import given_modes, ordinal
from .results import Mode
from .spec import Spec

CONDITIONS = {
    "grid": "generator on the grid",
    "free": "idling / isolated operation (free end)",
    "locked": "brake applied (clamped end)",
}


def modes(spec: Spec) -> list[Mode]:
    """Drive-train modes given in the spec (ids ``drivetrain.<condition>.<k>``)."""
    out: list[Mode] = []
    for condition, entries in spec.drivetrain.modes.items():
        out += given_modes(
            "drivetrain",
            {f"{condition}.{k}": e for k, e in enumerate(entries, start=1)},
            lambda name, c=condition: (  # type: ignore[misc]
                f"{ordinal(int(name.split('.')[1]))} drive-train torsion, {CONDITIONS[c]}"
            ),
        )
    return out
