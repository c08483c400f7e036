"""pydantic validation errors as one readable line with field path and YAML line."""

from collections.abc import Set as AbstractSet
from typing import Any

from pydantic import ValidationError

from ..errors import SpecError
from .yamlio import Document, Path, format_path


def _split(dotted: str) -> Path:
    parts: list[str | int] = []
    for piece in dotted.replace("]", "").replace("[", ".").split("."):
        parts.append(int(piece) if piece.isascii() and piece.isdigit() else piece)
    return tuple(parts)


_BRANCH = ("function-", "tuple[", "list[", "constrained-", "nullable[", "union[")


_SCALAR_TYPES = (
    "float_type",
    "float_parsing",
    "int_type",
    "int_parsing",
    "string_type",
    "bool_type",
    "none_required",
)


def _spec_error(exc: ValidationError, doc: Document, prefix: Path = ()) -> SpecError:
    """The most telling validation error as one line with field path and YAML line.

    A value that fails every branch of a union (a number or a list, say) reports the branch
    that matches its own shape: a list's error rather than "should be a number".
    """
    errors = exc.errors(include_url=False)

    def mismatch(e: Any) -> bool:
        return e["type"] in _SCALAR_TYPES and isinstance(e.get("input"), list | dict)

    err = min(errors, key=lambda e: (mismatch(e), errors.index(e)))
    # a misspelt key is two problems — the unknown key and the field it should have been:
    # report the unknown one (its line is where the mistake is) and name the other
    typo = _misspelt(errors)
    chosen: Any = err
    if typo is not None:
        chosen = {**typo[0], "missing_sibling": typo[1]}
    err = chosen
    loc = _field(err["loc"])
    path: Path = (*prefix, *loc)
    # every branch's complaint about this field: a number field (int | float) that got text
    # says "a number", not the first branch's "a valid integer"
    kinds = {e["type"] for e in errors if _field(e["loc"]) == loc}
    message = _message(err, kinds)
    extra = len({tuple(e["loc"][: len(loc)]) for e in errors}) - 1 - (typo is not None)
    more = f" (and {extra} more problem{'s' * (extra > 1)})" if extra > 0 else ""
    return SpecError(
        message + more,
        path=format_path(path) or None,
        line=doc.line_of(path),
        source=doc.source,
    )


def _field(where: Any) -> list[str | int]:
    """A validation error's location without pydantic's branch names."""
    return [
        part
        for part in where
        if not (
            part in ("number", "full", "[key]", "int", "float", "str")
            or (isinstance(part, str) and part.startswith(_BRANCH))
        )
    ]


def _message(err: Any, kinds: AbstractSet[str] = frozenset()) -> str:
    kind = err["type"]
    got = err.get("input")
    wanted = (
        "a number"
        if kinds & {"float_type", "float_parsing"}
        else "a whole number"
        if kinds & {"int_type", "int_parsing"}
        else None
    )
    if wanted is not None and kind in _SCALAR_TYPES:
        if isinstance(got, str):
            quoted = ": write it without quotes" if _numeric(got) else ""
            return f"should be {wanted}, not text (got {got!r}{quoted})"
        if isinstance(got, bool):
            return f"should be {wanted}, not {str(got).lower()}"
        if wanted == "a whole number" and isinstance(got, float):
            return f"should be a whole number (got {got!r})"
    if kind == "missing":
        return "required field is missing"
    if kind == "extra_forbidden":
        missing = err.get("missing_sibling")
        if missing is not None:
            return f"unknown field — did you mean {missing!r}? (a required field, missing)"
        return "unknown field (not part of the wtvib spec; check the spelling)"
    if kind == "string_pattern_mismatch":
        pattern = err.get("ctx", {}).get("pattern", "")
        names = {
            r"^(fa|ss|tor)[1-9]$": "fa1…fa9, ss1…ss9, tor1…tor9",
            r"^(flap|edge|tor)[1-9]$": "flap1…flap9, edge1…edge9, tor1…tor9",
            r"^[1-9]$": "1…9",
        }.get(pattern, pattern)
        return f"{got!r} is not a known mode name (expected {names})"
    if kind == "finite_number":
        return "must be a finite number (NaN and infinity are not allowed)"
    text = str(err["msg"])
    if kind.startswith("value_error"):
        text = text.removeprefix("Value error, ")
    if got is not None and not isinstance(got, dict | list) and kind != "literal_error":
        return f"{text} (got {got!r})"
    if kind == "literal_error":
        return f"{text} (got {got!r})"
    return text


def _numeric(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _misspelt(errors: list[Any]) -> tuple[Any, str] | None:
    """An unknown key and a missing required sibling of a similar name, if the errors hold
    such a pair (``outer_diamter_m`` for ``outer_diameter_m``)."""
    import difflib

    missing = [e for e in errors if e["type"] == "missing"]
    for e in errors:
        if e["type"] != "extra_forbidden" or not isinstance(e["loc"][-1], str):
            continue
        parent = e["loc"][:-1]
        names = [
            m["loc"][-1]
            for m in missing
            if m["loc"][:-1] == parent and isinstance(m["loc"][-1], str)
        ]
        close = difflib.get_close_matches(e["loc"][-1], names, n=1, cutoff=0.6)
        if close:
            return e, close[0]
    return None
