"""The one refusal both importers give a floating turbine.

wtvib has no platform or mooring model, so a floating turbine's tower modes (and the
platform's own rigid-body modes) cannot be computed. The windIO and ElastoDyn importers
detect a floating system in their own way and refuse it with the same sentence, unless the
user asks, with ``--clamped-base``, for the tower to be audited as if clamped at its base.
"""

from __future__ import annotations

from ..errors import SpecError


def refusal(what: str, source: str, path: str | None = None) -> SpecError:
    """The error for a floating turbine: ``what`` names the parts that make it floating."""
    return SpecError(
        f"a floating turbine ({what}): wtvib has no platform or mooring model, so its tower "
        "modes cannot be computed; --clamped-base audits the tower as if clamped at its base "
        "(not the floating system's modes)",
        path=path,
        source=source,
    )
