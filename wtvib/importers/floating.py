"""The one refusal both importers give a floating turbine they cannot model.

wtvib models a floating platform from an OpenFAST deck set (ElastoDyn's platform mass,
HydroDyn's WAMIT added mass and hydrostatics, MAP++ or MoorDyn moorings: :mod:`.hydrodyn`,
:mod:`.mooring`) or from windIO's ``floating_platform`` (:mod:`.windio_platform`). A floating
turbine described otherwise — a deck set without HydroDyn's potential-flow files, windIO
moorings with no platform — is refused with the same sentence naming what is missing,
unless the user asks, with ``--clamped-base``, for the tower to be audited as if clamped at
its base.
"""

from __future__ import annotations

from ..errors import SpecError


def refusal(what: str, why: str, source: str, path: str | None = None) -> SpecError:
    """The error for a floating turbine: ``what`` names the parts that make it floating,
    ``why`` what keeps wtvib from modelling its platform."""
    return SpecError(
        f"a floating turbine ({what}) whose platform wtvib cannot model: {why}; its tower "
        "modes depend on it, so --clamped-base is needed to audit the tower as if clamped at "
        "its base (not the floating system's modes)",
        path=path,
        source=source,
    )
