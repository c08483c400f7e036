"""The windIO 2.x turbine schema, checked before a windIO file is imported.

The schema ships with the windio package (``wtvib[windio]``); it is read from the package's
data without importing windIO itself (which loads xarray and netCDF4, a second), and checked
with jsonschema (Draft 7, as windIO does; not restrictive: extra keys are allowed). Where
either is missing the import says so and goes on with wtvib's own checks.
"""

import importlib.util
from functools import lru_cache
from pathlib import Path
from typing import Any

from ..yamlio import parse_plain


@lru_cache(maxsize=1)
def _validator() -> Any:
    spec = importlib.util.find_spec("windIO")
    if spec is None or not spec.submodule_search_locations:
        return None
    path = Path(next(iter(spec.submodule_search_locations))) / "schemas/turbine/turbine_schema.yaml"
    try:
        import jsonschema
    except ImportError:
        return None
    if not path.is_file():
        return None
    return jsonschema.Draft7Validator(parse_plain(path.read_text(encoding="utf-8")).data)


def available() -> bool:
    """Whether the schema can be checked here."""
    return _validator() is not None


def problems(data: Any) -> list[tuple[tuple[str | int, ...], str]]:
    """The schema's objections to a windIO 2.x document: (field path, message), in the
    order of the document's paths (empty: valid)."""
    validator = _validator()
    if validator is None:
        return []
    found = sorted(validator.iter_errors(data), key=lambda e: [str(p) for p in e.absolute_path])
    return [(tuple(e.absolute_path), e.message) for e in found]
