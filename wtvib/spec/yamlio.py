"""Safe YAML reading that remembers where every value came from.

PyYAML's ``safe_load`` forgets line numbers and silently keeps the last of two duplicate
keys. Users' mistakes must name the field and the line (STYLE.md habit 4), so the document
is composed into nodes and converted here, keeping a map from field path to line, refusing
duplicate keys, object-constructing tags and documents that expand past a node budget
(alias bombs).
"""

import json
import re
from collections.abc import Hashable
from dataclasses import dataclass, field
from typing import Any

import yaml

from ..errors import SpecError

Path = tuple[str | int, ...]

#: Largest number of nodes (after alias expansion) a wtvib spec may have. The catalogue
#: specs have a few hundred; machine-written windIO files go through :func:`parse_plain`,
#: which shares aliases instead of expanding them. Guards against "billion laughs".
MAX_NODES = 100_000
#: Deepest nesting (mappings and lists in one another) a document may have.
MAX_DEPTH = 64

_MAP_TAG = "tag:yaml.org,2002:map"
_SEQ_TAG = "tag:yaml.org,2002:seq"

#: Plain scalars as the YAML 1.2 core schema reads them (PyYAML implements YAML 1.1, where
#: "1.6e7" is text but "1:30" is 90, "0_5" is 5 and "on" is true).
_CORE_INT = re.compile(r"[-+]?[0-9]+|0o[0-7]+|0x[0-9a-fA-F]+")
_CORE_FLOAT = re.compile(
    r"[-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?|[-+]?\.(inf|Inf|INF)|\.(nan|NaN|NAN)"
)
_CORE_BOOL = {"true": True, "True": True, "TRUE": True, "false": False, "False": False}
_CORE_BOOL["FALSE"] = False
_CORE_NULL = {"", "~", "null", "Null", "NULL"}
#: The tags PyYAML resolves plain scalars to; anything else on a plain scalar is explicit.
_IMPLICIT = {f"tag:yaml.org,2002:{t}" for t in ("str", "int", "float", "bool", "null")}
_IMPLICIT |= {"tag:yaml.org,2002:timestamp", "tag:yaml.org,2002:merge", "tag:yaml.org,2002:value"}
#: Longer integers are refused: no spec number needs them, and converting one is costly.
MAX_DIGITS = 30


@dataclass(frozen=True)
class Document:
    """A parsed YAML document with the 1-based line of each field path.

    ``redefined_anchors`` lists anchors defined twice (YAML 1.2 allows it: an alias refers
    to the latest definition; PyYAML's composer refuses it, wtvib accepts and reports it).
    """

    data: Any
    lines: dict[Path, int] = field(default_factory=dict)
    source: str | None = None
    redefined_anchors: tuple[str, ...] = ()

    def line_of(self, path: Path) -> int | None:
        """Line of ``path`` or of its nearest ancestor that has one."""
        for cut in range(len(path), -1, -1):
            line = self.lines.get(tuple(path[:cut]))
            if line is not None:
                return line
        return None


class _Loader(yaml.SafeLoader):
    """SafeLoader that accepts a redefined anchor (the IEA-10 windIO 1.x file has one)."""

    def __init__(self, stream: str) -> None:
        super().__init__(stream)
        self.redefined: list[str] = []

    def compose_node(self, parent: Any, index: Any) -> Any:
        event = self.peek_event()  # type: ignore[no-untyped-call]  # PyYAML: no annotations
        anchor = getattr(event, "anchor", None)
        if anchor is not None and not isinstance(event, yaml.AliasEvent) and anchor in self.anchors:
            self.redefined.append(anchor)
            del self.anchors[anchor]
        return super().compose_node(parent, index)


class _TooLongError(ValueError):
    """An integer of more digits than any value needs (converting one is costly)."""


#: What wtvib audits, as the messages on files it does not audit name it.
AUDITED = (
    "wtvib audits a turbine's description (a windIO turbine file, an OpenFAST deck set, a "
    "HAWC2 model or a wtvib spec)"
)

#: What a tag's refusal adds where the tag says what the file is.
_TAG_HINTS = {
    "!include": " — windIO's plant files (a wind farm, its site and energy resource) "
    f"include others so; {AUDITED}",
}


def _tag_refused(tag: str) -> str:
    """The message of a refused YAML tag."""
    return f"the tag {tag!r} is not allowed" + _TAG_HINTS.get(tag, "")


def core_plain(text: str) -> Any:
    """A plain scalar's value by the YAML 1.2 core schema (null, bool, int, float, or the
    text itself: 1:30, 0_5, on and 1e5-as-text surprises of YAML 1.1 do not happen)."""
    if text in _CORE_NULL:
        return None
    if text in _CORE_BOOL:
        return _CORE_BOOL[text]
    if _CORE_INT.fullmatch(text):
        if len(text) > MAX_DIGITS:
            raise _TooLongError(f"a number of {len(text)} digits is not a spec value")
        return int(text, 0) if text[:2] in ("0o", "0x") else int(text)
    if _CORE_FLOAT.fullmatch(text):
        low = text.lower()
        return float(low.replace(".", "") if low.lstrip("+-") in (".inf", ".nan") else text)
    return text


_CORE_TAG = "tag:wtvib,2026:core"
_FastLoader: Any = None


def _fast_loader() -> Any:
    """libyaml's safe loader resolving plain scalars by the YAML 1.2 core schema (PyYAML's
    own resolvers are YAML 1.1: 1e5 and 8e-05 stay text, 1:30 is 90, on is true)."""
    global _FastLoader
    base = getattr(yaml, "CSafeLoader", None)
    if _FastLoader is None and base is not None:

        class Loader(base):  # type: ignore[misc, valid-type]
            pass

        Loader.yaml_implicit_resolvers = {}
        Loader.add_implicit_resolver("tag:yaml.org,2002:merge", re.compile(r"^(?:<<)$"), ["<"])
        Loader.add_implicit_resolver(_CORE_TAG, re.compile(r".*", re.S), None)
        Loader.add_constructor(_CORE_TAG, lambda loader, node: core_plain(node.value))
        _FastLoader = Loader
    return _FastLoader


def parse_plain(text: str, source: str | None = None) -> Document:
    """Parse a large machine-written document (windIO) without line tracking.

    Same safety as :func:`parse` (safe constructors only; aliases are shared, not copied, so
    alias bombs cost no memory) but ~3× faster; duplicate keys are not checked. Falls back
    to :func:`parse` where the fast path refuses the file (e.g. a redefined anchor), so that
    errors still name a line.
    """
    _guard_depth(text, source)
    fast = _fast_loader()
    if fast is None:
        return parse(text, source)
    short, lists = _number_lists(text)
    try:
        data = yaml.load(short, Loader=fast)
    except (yaml.YAMLError, _TooLongError):
        return parse(text, source)  # the careful path names the line
    if data is None:
        raise SpecError("the file is empty (no YAML document in it)", source=source)
    if lists:
        data = _put_back(data, lists)
    return Document(data, {}, source)


#: A line that is a key (or a sequence entry's key) and a flow list of numbers, nothing
#: else: ``  grid: [0.0, 0.01, …]`` — the bulk of a windIO file.
_NUMBER_LINE = re.compile(
    r"^(?P<head>[ \t]*(?:- )?[A-Za-z_][A-Za-z0-9_-]*:[ \t]+)\[(?P<body>[-+0-9.eE, \t]*)\][ \t]*$",
    re.M,
)
#: A number JSON reads as the YAML 1.2 core schema does (an int, or a float by float()).
_JSON_NUMBER = re.compile(r"-?(?:0|[1-9][0-9]*)(?:\.[0-9]+)?(?:[eE][-+]?[0-9]+)?")


def _number_lists(text: str) -> tuple[str, dict[str, list[Any]]]:
    """The text with each line's flow list of plain numbers replaced by a token, and the
    lists (read by json, in C: the windIO files' tens of thousands of numbers cost PyYAML a
    Python call each). A list with any entry JSON would read otherwise than YAML 1.2's core
    schema (``.5``, ``+1``, ``01``, ``.inf``) stays in the text, for the YAML reader."""
    prefix = "wtvib-number-list-"
    if prefix in text:
        return text, {}
    lists: dict[str, list[Any]] = {}

    def swap(m: re.Match[str]) -> str:
        items = [t.strip() for t in m["body"].split(",")]
        if items == [""]:
            return m[0]
        if not all(_JSON_NUMBER.fullmatch(t) for t in items):
            return m[0]
        if any(len(t) > MAX_DIGITS and _CORE_INT.fullmatch(t) for t in items):
            return m[0]  # an integer too long to be a value: the YAML reader refuses it
        token = f"{prefix}{len(lists)}"
        lists[token] = json.loads("[" + ",".join(items) + "]")
        return f"{m['head']}{token}"

    return _NUMBER_LINE.sub(swap, text), lists


def _put_back(value: Any, lists: dict[str, list[Any]]) -> Any:
    """The document with each token replaced by its list."""
    if isinstance(value, str):
        return lists.get(value, value)
    if isinstance(value, dict):
        for key, item in value.items():
            value[key] = _put_back(item, lists)
    elif isinstance(value, list):
        for i, item in enumerate(value):
            value[i] = _put_back(item, lists)
    return value


def format_path(path: Path) -> str:
    """``("rotor", "speed", 0)`` -> ``rotor.speed[0]``."""
    out = ""
    for part in path:
        out += f"[{part}]" if isinstance(part, int) else (f".{part}" if out else str(part))
    return out


_NOT_BRACKETS = re.compile(r"[^\[\]{}]+")


def nesting_depth(text: str) -> int:
    """A cheap upper estimate of a YAML text's nesting: flow brackets and block indents.

    Run before parsing, so that a deeply nested document is refused without recursion.
    """
    flow = depth = 0
    for ch in _NOT_BRACKETS.sub("", text):  # the brackets alone: a windIO file is 1 % them
        if ch in "[{":
            depth += 1
            flow = max(flow, depth)
        else:
            depth = max(depth - 1, 0)
    lines = [ln for ln in text.splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    indents = [len(ln) - len(ln.lstrip(" ")) for ln in lines]  # comments do not nest
    levels = len(set(indents))
    return max(flow, levels)


def _guard_depth(text: str, source: str | None) -> None:
    if nesting_depth(text) > MAX_DEPTH:
        raise SpecError(
            f"the document is nested more than {MAX_DEPTH} levels deep; refused", source=source
        )


def parse(text: str, source: str | None = None) -> Document:
    """Parse one YAML document safely, keeping line numbers.

    Raises
    ------
    SpecError
        Empty document, YAML syntax error, several documents, an unsafe tag, a duplicate
        key, a non-string key or a document larger than :data:`MAX_NODES` nodes.
    """
    _guard_depth(text, source)
    fast = getattr(yaml, "CSafeLoader", None)  # libyaml: ~10× faster on windIO files
    loader: Any = fast(text) if fast else _Loader(text)
    try:
        try:
            node = loader.get_single_node()
        except yaml.composer.ComposerError as exc:
            if "duplicate anchor" not in str(exc) or isinstance(loader, _Loader):
                raise
            loader.dispose()
            loader = _Loader(text)
            node = loader.get_single_node()
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        line = mark.line + 1 if mark is not None else None
        problem = exc.problem or exc.context or "invalid YAML"
        if exc.context and exc.context_mark and exc.problem:
            problem += f" ({exc.context} on line {exc.context_mark.line + 1})"
        if _tab_before(text, mark):
            problem += " — a tab: YAML indents with spaces only"
        raise SpecError(f"not valid YAML: {problem}", line=line, source=source) from None
    except yaml.YAMLError as exc:
        raise SpecError(f"not valid YAML: {exc}", source=source) from None
    except RecursionError:
        raise SpecError("the document is nested too deeply; refused", source=source) from None
    finally:
        loader.dispose()
    if node is None:
        raise SpecError("the file is empty (no YAML document in it)", source=source)
    walker = _Walker(loader, source)
    data = walker.convert(node, ())
    redefined = tuple(dict.fromkeys(getattr(loader, "redefined", ())))
    return Document(data, walker.lines, source, redefined)


def _tab_before(text: str, mark: Any) -> bool:
    """Whether the line of a YAML error holds a tab up to the error's column (YAML's own
    words, "found character that cannot start any token", do not say it is one)."""
    if mark is None:
        return False
    lines = text.splitlines()
    return mark.line < len(lines) and "\t" in lines[mark.line][: mark.column + 1]


class _Walker:
    def __init__(self, loader: Any, source: str | None) -> None:
        self.loader = loader
        self.source = source
        self.lines: dict[Path, int] = {}
        self.count = 0
        self.active: set[int] = set()  # nodes being converted (a recursive alias revisits one)

    def fail(self, message: str, path: Path, node: yaml.Node) -> SpecError:
        return SpecError(
            message,
            path=format_path(path) or None,
            line=node.start_mark.line + 1,
            source=self.source,
        )

    def convert(self, node: yaml.Node, path: Path) -> Any:
        if id(node) in self.active:
            raise self.fail("a recursive alias: the value contains itself", path, node)
        self.active.add(id(node))
        try:
            return self._convert(node, path)
        finally:
            self.active.discard(id(node))

    def _convert(self, node: yaml.Node, path: Path) -> Any:
        self.count += 1
        if self.count > MAX_NODES:
            raise self.fail(
                f"the document expands to more than {MAX_NODES:,} values (an alias bomb?); refused",
                path,
                node,
            )
        self.lines.setdefault(path, node.start_mark.line + 1)
        if isinstance(node, yaml.MappingNode):
            return self._mapping(node, path)
        if isinstance(node, yaml.SequenceNode):
            if node.tag != _SEQ_TAG:
                raise self.fail(_tag_refused(node.tag), path, node)
            return [self.convert(item, (*path, i)) for i, item in enumerate(node.value)]
        if isinstance(node, yaml.ScalarNode) and not node.style:  # plain: None or ""
            return self._plain(node, path)
        try:
            return self.loader.construct_object(node, deep=True)
        except yaml.constructor.ConstructorError as exc:
            raise self.fail(f"not allowed: {exc.problem}", path, node) from None

    def _plain(self, node: yaml.ScalarNode, path: Path) -> Any:
        """A plain (unquoted) scalar by the YAML 1.2 core schema: 1.6e7 is a number, 1:30,
        0_5 and on are text (which the spec then refuses where a number or flag goes)."""
        if node.tag not in _IMPLICIT:
            raise self.fail(_tag_refused(node.tag), path, node)
        try:
            return core_plain(node.value)
        except _TooLongError as exc:
            raise self.fail(str(exc), path, node) from None

    def _mapping(self, node: yaml.MappingNode, path: Path) -> dict[Hashable, Any]:
        if node.tag != _MAP_TAG:
            raise self.fail(_tag_refused(node.tag), path, node)
        own = sum(1 for k, _ in node.value if k.tag != "tag:yaml.org,2002:merge")
        try:
            self.loader.flatten_mapping(node)  # resolves YAML merge keys (<<)
        except yaml.constructor.ConstructorError as exc:
            raise self.fail(f"bad merge key: {exc.problem}", path, node) from None
        merged = len(node.value) - own  # flatten_mapping puts the merged pairs first
        out: dict[Hashable, Any] = {}
        from_merge: set[str] = set()
        for index, (key_node, value_node) in enumerate(node.value):
            key = self.loader.construct_object(key_node, deep=True)
            if not isinstance(key, str | int | float | bool):
                raise self.fail("a key must be a plain name", path, key_node)
            key = str(key) if not isinstance(key, str) else key
            if index < merged:
                from_merge.add(key)
            elif key in from_merge:  # an explicit key overrides a merged one (YAML merge)
                from_merge.discard(key)
                del out[key]
            if key in out:
                first = self.lines.get((*path, key))
                raise self.fail(
                    f"duplicate key {key!r} (first given on line {first})",
                    (*path, key),
                    key_node,
                )
            self.lines[(*path, key)] = key_node.start_mark.line + 1
            out[key] = self.convert(value_node, (*path, key))
        return out
