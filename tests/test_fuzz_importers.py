"""Property-based fuzzing of the importers: reference files mutated one or two
places at a time — a windIO key deleted, emptied, retyped or pushed to an extreme number; an
ElastoDyn/ServoDyn/AeroDyn/controller line's token replaced by junk, a line deleted or
doubled, a file cut short. The invariant is the CLI's contract: the import and the audit
end in a typed wtvib error (one line, exit 2) or in a report whose JSON is strict — nothing
else.

An audit of a reference turbine costs about a second, so each distinct imported spec is
audited once (mutations of data wtvib does not read import to the same spec; the audit is a
pure function of it). CI runs a few examples per property (derandomised); ``make fuzz``
runs the campaign recorded in tests/FUZZ.md.
"""

import atexit
import json
import os
import shutil
import tempfile
from pathlib import Path
from typing import Any

import pytest
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from wtvib import audit, importers, spec
from wtvib.errors import WtvibError
from wtvib.spec.yamlio import parse_plain

from .conftest import NREL_DECK_FILES, SHARED

#: Examples per property: few in CI (each costs up to a second), the campaign's in make
#: fuzz (WTVIB_FUZZ_IMPORTER_EXAMPLES; the spec properties' 40,000 would take hours here).
EXAMPLES = int(os.environ.get("WTVIB_FUZZ_IMPORTER_EXAMPLES", "2000"))
if os.environ.get("HYPOTHESIS_PROFILE", "ci") == "ci":
    EXAMPLES = 12

NREL = SHARED / "reference" / "NREL5MW"
IEA10 = SHARED / "reference" / "IEA10" / "IEA-10-198-RWT.yaml"
needs_shared = pytest.mark.skipif(
    not NREL.is_dir(), reason="../shared/reference (the NREL 5-MW deck set) is not beside the clone"
)

#: outcome of each distinct imported spec: None (a report with strict JSON) or the error
_AUDITED: dict[str, str | None] = {}


def _reject_constant(name: str) -> Any:
    raise AssertionError(f"the report's JSON holds {name}")


def _audit_cleanly(data: dict[str, Any], source: str) -> None:
    """The invariant after a successful import: a typed error, or a strict-JSON report."""
    key = json.dumps(data, sort_keys=True, default=str)
    if key in _AUDITED:
        return
    _AUDITED[key] = None
    try:
        report = audit.run(spec.from_data(data, source=source))
    except WtvibError as exc:
        _AUDITED[key] = str(exc)
        assert "\n" not in str(exc).strip(), "a wtvib error is one line"
        return
    assert report.verdict in ("pass", "warn", "fail")
    json.loads(json.dumps(report.to_dict()), parse_constant=_reject_constant)


def _import_cleanly(path: Path, **options: Any) -> None:
    try:
        data = importers.to_data(path, importers.ReadOptions(**options))
    except WtvibError as exc:
        assert "\n" not in str(exc).strip(), "a wtvib error is one line"
        return
    _audit_cleanly(data, str(path))


# --- windIO ------------------------------------------------------------------------------


def _windio_bases() -> list[tuple[str, dict[str, Any], dict[str, Any]]]:
    """(name, document, import options) of the windIO files mutated: the IEA-15 2.x example
    the windio package ships, and the IEA-10 1.x file of ../shared (its head mass given,
    as windIO 1.x files leave it to WISDEM: 6.6e5 kg, a round figure near the published
    nacelle + hub)."""
    bases = []
    import importlib.util

    found = importlib.util.find_spec("windIO")
    if found is not None and found.origin:
        p = Path(found.origin).parent / "examples" / "turbine" / "IEA-15-240-RWT.yaml"
        bases.append(("iea15-v2", parse_plain(p.read_text()).data, {}))
    if IEA10.is_file():
        bases.append(("iea10-v1", parse_plain(IEA10.read_text()).data, {"head_mass": 6.6e5}))
    return bases


def _paths(node: Any, path: tuple[Any, ...] = (), depth: int = 0) -> list[tuple[Any, ...]]:
    """Every key path into a document (list items: the first two and the last)."""
    found: list[tuple[Any, ...]] = []
    if depth > 8:
        return found
    if isinstance(node, dict):
        items = list(node.items())
    elif isinstance(node, list) and node:
        picks = sorted({0, min(1, len(node) - 1), len(node) - 1})
        items = [(i, node[i]) for i in picks]
    else:
        return found
    for key, value in items:
        found.append((*path, key))
        found.extend(_paths(value, (*path, key), depth + 1))
    return found


WINDIO_BASES = _windio_bases()
WINDIO_PATHS = [(i, p) for i, (_, doc, _) in enumerate(WINDIO_BASES) for p in _paths(doc)]

windio_junk = st.one_of(
    st.sampled_from([None, True, False, "abc", "", [], {}, 0, -1, 0.0, 1e-300, 1e300, -1e300, 2.7]),
    st.floats(allow_nan=True, allow_infinity=True),
    st.lists(st.floats(-1e3, 1e3), min_size=1, max_size=3),
    st.integers(-(10**40), 10**40),
)


@st.composite
def mutated_windio(draw: Any) -> tuple[str, dict[str, Any], dict[str, Any]]:
    import copy

    base, path = draw(st.sampled_from(WINDIO_PATHS))
    name, doc, options = WINDIO_BASES[base]
    doc = copy.deepcopy(doc)
    for step in range(draw(st.integers(1, 2))):
        if step:  # a second mutation anywhere in the same document
            _, path = draw(st.sampled_from([bp for bp in WINDIO_PATHS if bp[0] == base]))
        parent = doc
        try:
            for key in path[:-1]:
                parent = parent[key]
            value = parent[path[-1]]
        except (KeyError, IndexError, TypeError):
            continue  # the first mutation removed this path
        action = draw(st.sampled_from(["delete", "replace", "negate", "scale"]))
        if action == "delete" and isinstance(parent, dict):
            del parent[path[-1]]
        elif action == "negate" and isinstance(value, (int, float)) and not isinstance(value, bool):
            parent[path[-1]] = -value - 1
        elif action == "scale" and isinstance(value, (int, float)) and not isinstance(value, bool):
            parent[path[-1]] = value * draw(st.sampled_from([0.0, 1e-9, 1e9, 1e200]))
        else:
            parent[path[-1]] = draw(windio_junk)
    return name, doc, options


_WORK = Path(tempfile.mkdtemp(prefix="wtvib-fuzz-"))
atexit.register(shutil.rmtree, _WORK, ignore_errors=True)  # not left in /tmp, a copy a run


@pytest.mark.skipif(not WINDIO_BASES, reason="neither windIO base file is available")
@settings(max_examples=EXAMPLES)
@given(mutated_windio())
def test_mutated_windio_files_fail_cleanly(case: tuple[str, dict[str, Any], dict[str, Any]]):
    name, doc, options = case
    path = _WORK / f"{name}.yaml"
    try:
        path.write_text(yaml.safe_dump(doc, sort_keys=False, allow_unicode=True))
    except (yaml.YAMLError, ValueError, OverflowError):
        return  # not writable as YAML: nothing to feed
    _import_cleanly(path, **options)


# --- OpenFAST deck set ---------------------------------------------------------------------

token_junk = st.sampled_from(
    [
        "abc",
        "nan",
        "inf",
        "-inf",
        "-1",
        "0",
        "1e300",
        "-1e300",
        "1e-300",
        "2.7",
        "4.2277500E+",
        "True",
        '"',
        '""',
        "1" * 400,
        "-0",
        "1,5",
        "0x10",
        "@",
    ]
)


def _deck() -> Path:
    """A private copy of the deck set (mutated in place, one file at a time)."""
    copy = _WORK / "NREL5MW"
    if not copy.is_dir():
        shutil.copytree(NREL, copy)
    return copy


@st.composite
def deck_mutation(draw: Any) -> tuple[str, str]:
    name = draw(st.sampled_from(NREL_DECK_FILES))
    lines = (NREL / name).read_text(encoding="latin-1").splitlines(keepends=True)
    for _ in range(draw(st.integers(1, 2))):
        i = draw(st.integers(0, len(lines) - 1))
        action = draw(st.sampled_from(["token", "token", "token", "delete", "double", "cut"]))
        if action == "delete":
            del lines[i]
        elif action == "double":
            lines.insert(i, lines[i])
        elif action == "cut":  # a file truncated mid-line
            lines = [*lines[:i], lines[i][: draw(st.integers(0, len(lines[i])))]]
        else:
            tokens = lines[i].split()
            if tokens:
                tokens[draw(st.integers(0, len(tokens) - 1))] = draw(token_junk)
                lines[i] = " ".join(tokens) + "\n"
        if not lines:
            break
    return name, "".join(lines)


@needs_shared
@settings(max_examples=EXAMPLES)
@given(deck_mutation())
def test_mutated_openfast_decks_fail_cleanly(case: tuple[str, str]):
    name, text = case
    deck = _deck()
    target = deck / name
    try:
        target.write_text(text, encoding="latin-1")
        _import_cleanly(deck / "NREL-5MW.fst")
    finally:
        shutil.copyfile(NREL / name, target)
