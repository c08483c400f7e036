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

from ..spec.yamlio import parse_plain


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
    order of the document's paths (empty: valid).

    Long lists of plain numbers (grids, values: tens of thousands of entries in a large
    file, each a validator call — 0.45 s of the IEA-22's) are checked as a sample that
    keeps every verdict the schema's item keywords can reach: the smallest and the largest
    entry (minimum, maximum, their exclusive forms), a repeated value where there is one
    (uniqueItems), and enough of the first entries that no length limit changes (the schema's
    minItems and maxItems are at most 6; only lists of more than :data:`SAMPLE_ABOVE` are
    sampled). An objection inside a sampled list names the entry's own index."""
    return [(where, message) for where, message, _ in objections(data)]


def objections(data: Any) -> list[tuple[tuple[str | int, ...], str, bool]]:
    """:func:`problems` with, for each, whether it is a key the schema requires and the file
    leaves out (a ``required`` objection) rather than a value it refuses."""
    validator = _validator()
    if validator is None:
        return []
    index: dict[tuple[str | int, ...], list[int]] = {}
    sample = _sampled(data, (), index)
    found = sorted(validator.iter_errors(sample), key=lambda e: [str(p) for p in e.absolute_path])
    return [
        (
            _original(tuple(e.absolute_path), index),
            _message(e, data, index),
            e.validator == "required",
        )
        for e in found
    ]


def _message(error: Any, data: Any, index: dict[tuple[str | int, ...], list[int]]) -> str:
    """The objection's text as the whole document gives it: a message that quotes a sampled
    list (or what holds one) quotes the list itself."""
    text = str(error.message)
    for path in index:
        original: Any = data
        for key in path:
            original = original[key]
        short = repr([original[i] for i in index[path]])
        if short in text:
            text = text.replace(short, repr(original))
    return text


#: Lists of plain numbers longer than this are validated as a sample (:func:`problems`).
SAMPLE_ABOVE = 12


def _sampled(
    value: Any, path: tuple[str | int, ...], index: dict[tuple[str | int, ...], list[int]]
) -> Any:
    """``value`` with its long lists of plain numbers replaced by samples; ``index`` gets,
    for each sampled list's path, the original index of each sample entry."""
    if isinstance(value, dict):
        return {k: _sampled(v, (*path, k), index) for k, v in value.items()}
    if not isinstance(value, list):
        return value
    numbers = len(value) > SAMPLE_ABOVE and all(
        type(v) in (int, float)
        for v in value  # bool is no number here
    )
    if not numbers:
        return [_sampled(v, (*path, i), index) for i, v in enumerate(value)]
    keep = {min(range(len(value)), key=value.__getitem__)}
    keep.add(max(range(len(value)), key=value.__getitem__))
    first_seen: dict[float, int] = {}
    for i, v in enumerate(value):
        if v in first_seen:  # a repeated value: both entries
            keep.update((first_seen[v], i))
            break
        first_seen[v] = i
    keep.update(range(SAMPLE_ABOVE // 2))
    order = sorted(keep)
    index[path] = order
    return [value[i] for i in order]


def _original(
    path: tuple[str | int, ...], index: dict[tuple[str | int, ...], list[int]]
) -> tuple[str | int, ...]:
    """An error path in the sample, with a sampled list's index mapped back."""
    for cut in range(len(path)):
        order, at = index.get(path[:cut]), path[cut]
        if order is not None and isinstance(at, int):
            return (*path[:cut], order[at], *path[cut + 1 :])
    return path
