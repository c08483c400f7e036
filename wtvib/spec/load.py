"""Reading a spec: files (bounded, UTF-8), YAML documents, quantities, validation."""

import hashlib
import os
import re
import stat
from pathlib import Path as FsPath
from typing import Any

from pydantic import ValidationError

from ..errors import SpecError
from .base import Quantity
from .checks import (
    _check_aerodynamics,
    _check_coupled,
    _check_geometry,
    _check_results,
    _check_rotor_radius,
    _check_sources,
)
from .messages import _spec_error
from .turbine import Spec
from .yamlio import AUDITED, Document, Path, format_path, parse

FORMAT_VERSION = 1


#: Files larger than this are refused before parsing; override with the environment
#: variable WTVIB_MAX_BYTES (bytes) or the ``max_bytes`` argument.
MAX_FILE_BYTES = 20 * 1024 * 1024


def max_file_bytes() -> int:
    """The size limit in force: WTVIB_MAX_BYTES if set (a whole number of bytes), else
    :data:`MAX_FILE_BYTES`; a malformed setting is one line, not a crash."""
    raw = os.environ.get("WTVIB_MAX_BYTES")
    if raw is None:
        return MAX_FILE_BYTES
    try:
        value = int(raw.strip())
    except ValueError:
        value = -1
    if value <= 0:
        raise SpecError(f"WTVIB_MAX_BYTES must be a whole number of bytes above 0 (got {raw!r})")
    # a read allocates the limit plus one byte: more than memory can hold is no limit at all
    return min(value, MAX_SETTABLE_BYTES)


#: The largest WTVIB_MAX_BYTES taken as given (1 TiB): a 30-digit setting is read as this.
MAX_SETTABLE_BYTES = 1 << 40


def load(path: str | FsPath, *, max_bytes: int | None = None) -> Spec:
    """Read and validate a wtvib spec file.

    Raises
    ------
    SpecError
        Unreadable, oversized, non-UTF-8 or invalid file; the message names field and line.
    """
    text = read_text(path, max_bytes=max_bytes)
    return from_document(parse(text, source=str(path))).fingerprinted(fingerprint(text))


def fingerprint(text: str) -> str:
    """SHA-256 of a file's text as read (UTF-8), for the reports' identity block."""
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def file_fingerprint(path: str | FsPath) -> str:
    """SHA-256 of a file's bytes — what ``sha256sum`` prints, and :func:`fingerprint` of
    its text where that is UTF-8 without a byte-order mark — read a megabyte at a time: a
    linearisation of hundreds of megabytes is hashed, never held whole."""
    p = FsPath(path)
    digest = hashlib.sha256()
    try:
        if not stat.S_ISREG(p.stat().st_mode):
            raise SpecError("not a regular file; give a file", source=str(p))
        with p.open("rb") as fh:
            while chunk := fh.read(1 << 20):
                digest.update(chunk)
    except FileNotFoundError:
        raise SpecError("no such file", source=str(p)) from None
    except OSError as exc:
        raise SpecError(f"cannot read: {exc.strerror or exc}", source=str(p)) from None
    return digest.hexdigest()


def read_text(path: str | FsPath, *, max_bytes: int | None = None, ansi: bool = False) -> str:
    """A text file's content, refusing missing, oversized, binary or non-UTF-8 files.

    ``ansi``: a file of a Fortran code's fixed format (an OpenFAST or HAWC2 input), which a
    Windows editor saves in its ANSI code page (cp1252): where it is not UTF-8 it is read
    as that. Its values are ASCII — the bytes UTF-8 refuses are its comments' (DTU's htc
    files: "stig øye method", "måske") — and a value that is not ASCII is refused by the
    reader of its field. YAML is UTF-8 (YAML 1.2, §5.2): never read so."""
    p = FsPath(path)
    raw = read_bytes(p, max_bytes=max_bytes)
    if raw[:2] in (b"\xff\xfe", b"\xfe\xff"):  # UTF-16 with its byte-order mark (YAML 1.2
        try:  # §5.2; Windows PowerShell 5's `>`)
            return raw.decode("utf-16")
        except UnicodeDecodeError as exc:
            raise SpecError(f"not UTF-16 text (byte {exc.start})", source=str(p)) from None
    if b"\x00" in raw:
        kind = "a text file" if ansi else "a YAML text file"
        raise SpecError(f"binary file, not {kind}", source=str(p))
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        if ansi:
            return raw.decode("cp1252", errors="replace")
        line = raw[: exc.start].count(b"\n") + 1
        raise SpecError("not UTF-8 text", line=line, source=str(p)) from None


#: Every file this process has read (device, inode): an output is never written over one
#: of them (:func:`wtvib.outputs.files.write_atomic`), however it is named — a path, a link.
_READ: set[tuple[int, int]] = set()


def was_read(path: str | FsPath) -> bool:
    """Whether ``path`` is a file this process read as an input."""
    try:
        info = FsPath(path).stat()
    except (OSError, ValueError):
        return False
    return (info.st_dev, info.st_ino) in _READ


def read_bytes(path: str | FsPath, *, max_bytes: int | None = None, head: bool = False) -> bytes:
    """A file's bytes: only a regular file (not a device, pipe or socket), at most
    ``max_bytes`` (default: :func:`max_file_bytes`) — every file wtvib reads comes through
    here, the files a deck or a folder names too. ``head``: the file's first ``max_bytes``
    bytes, a longer file not refused (a reader that needs only the start of a large file:
    an OpenFAST linearisation's A, before its B, C and D)."""
    p = FsPath(path)
    max_bytes = max_bytes if max_bytes is not None else max_file_bytes()
    try:
        info = p.stat()
        if stat.S_ISDIR(info.st_mode):
            raise IsADirectoryError
        if not stat.S_ISREG(info.st_mode):  # /dev/zero, a FIFO, a socket: size says nothing
            raise SpecError(
                "not a regular file (a device, pipe or socket); give a file", source=str(p)
            )
        _READ.add((info.st_dev, info.st_ino))
        if info.st_size > max_bytes and not head:
            raise SpecError(
                f"file is {info.st_size:,} bytes, over the {max_bytes:,}-byte limit",
                source=str(p),
            )
        with p.open("rb") as fh:
            # no more than the file holds (a read allocates what it is asked for) and one
            # byte over: a file that grows while read is caught, not cut short
            raw = fh.read(min(max_bytes, info.st_size) + (0 if head else 1))
        if len(raw) > max_bytes:
            raise SpecError(f"file is over the {max_bytes:,}-byte limit", source=str(p))
        if len(raw) > info.st_size and not head:
            raise SpecError("the file grew while it was read; read it again", source=str(p))
    except IsADirectoryError:
        raise SpecError("is a folder, not a file", source=str(p)) from None
    except FileNotFoundError:
        raise SpecError("no such file", source=str(p)) from None
    except OSError as exc:
        raise SpecError(f"cannot read: {exc.strerror or exc}", source=str(p)) from None
    return raw


def load_document(path: str | FsPath, text: str) -> Document:
    """Parse a file's text as a YAML document (safe, with line numbers)."""
    return parse(text, source=str(path))


def from_data(data: dict[str, Any], source: str | None = None) -> Spec:
    """Validate a wtvib-format dictionary made by a program (an importer), not a file."""
    return from_document(Document(data=data, lines={}, source=source))


#: Top-level keys of WISDEM's and WEIS's modeling options (General, WISDEM) and analysis
#: options (driver, design_variables, merit_figure, …) files, which sit beside the windIO
#: turbine in every WISDEM example folder
_WISDEM_MODELING = {"General", "WISDEM"}
_WISDEM_ANALYSIS = {"driver", "recorder", "design_variables", "merit_figure", "constraints"}


#: What such a file is, said where one is given or found
OPTIONS_FILE = "a WISDEM/WEIS modeling or analysis options file, not a turbine"


def _options_keys(keys: set[str], names_output: bool) -> bool:
    """Whether a YAML document's top-level ``keys`` are a WISDEM/WEIS options file's —
    ``names_output``: its ``general`` block names an output folder (the smallest analysis
    options hold that block alone)."""
    analysis = len(keys & _WISDEM_ANALYSIS) >= 2 or (keys == {"general"} and names_output)
    return keys >= _WISDEM_MODELING or analysis


def _options_file(data: dict[str, Any]) -> bool:
    general = data.get("general")
    return _options_keys(set(data), isinstance(general, dict) and "folder_output" in general)


#: YAML files that sit beside turbines and are none, by what they are
ROSCO_TUNING = "a ROSCO controller tuning file, not a turbine"
IEA_RESULTS = "another tool's results in the IEA Wind systems' format, not a turbine"
PLANT = (
    "a wind-plant file (windIO's plant schema or a wake model's input: a turbine's power and "
    "thrust curves, a farm, its site or wind resource), not a turbine's structure"
)
#: The top-level keys of the wind-plant files (IEAWindTask37/IEA-Wind-740-10-ROWP: windIO's
#: plant turbine, farm, site, resource and system files; FLORIS's input): each set is one
#: kind's, all of whose keys it has.
_PLANT_KEYS = (
    {"performance", "hub_height", "rotor_diameter"},
    {"wind_resource"},
    {"layouts", "turbines"},
    {"site", "wind_farm"},
    {"boundaries", "energy_resource"},
    {"flow_field", "wake"},
)
TOOL_CONFIG = (
    "a tool's configuration (continuous integration, environment, documentation), not a turbine"
)

#: The top-level keys of the configuration files turbine repositories keep (Travis CI,
#: GitHub Actions, conda environments, MkDocs, pre-commit, Docker Compose): each set is one
#: file kind's, all of whose keys it has.
_CONFIG_KEYS = (
    {"language", "script"},
    {"language", "install"},
    {"jobs", "on"},
    {"channels", "dependencies"},
    {"site_name"},
    {"repos"},
    {"services", "version"},
)


def _kind(keys: set[str], results: bool) -> str | None:
    """The kind of a YAML file that is not a turbine from its top-level ``keys``: a ROSCO
    tuning file (``path_params``, ``controller_params``), another tool's results in the IEA
    Wind systems' format (``cases`` alone, each of ``configuration`` and ``outputs``:
    ``results``) — the IEA-22's repository keeps both beside its turbines."""
    if {"path_params", "controller_params"} <= keys:
        return ROSCO_TUNING
    if keys == {"cases"} and results:
        return IEA_RESULTS
    if "wtvib" in keys or "components" in keys:  # a turbine's, as far as the keys say
        return None
    if any(marks <= keys for marks in _CONFIG_KEYS):
        return TOOL_CONFIG
    if any(marks <= keys for marks in _PLANT_KEYS):
        return PLANT
    return None


def _another_yaml(data: dict[str, Any]) -> str | None:
    """What a parsed YAML file that is not a turbine is (:func:`_kind`), and what to give
    wtvib instead: the deck set a tuning file tunes, the results wtvib reads."""
    cases = data.get("cases")
    first = cases[0] if isinstance(cases, list) and cases else None
    kind = _kind(set(data), isinstance(first, dict) and {"configuration", "outputs"} <= set(first))
    if kind == ROSCO_TUNING:
        params = data.get("path_params")
        deck = params.get("FAST_InputFile") if isinstance(params, dict) else None
        named = f" ({deck})" if isinstance(deck, str) else ""
        return f"{kind}: audit the OpenFAST deck set it tunes{named}"
    if kind in (TOOL_CONFIG, PLANT):
        return f"{kind}: {AUDITED}"
    if kind == IEA_RESULTS:
        return (
            f"{kind} (cases of configuration and outputs): wtvib audits a turbine's "
            "description, or Campbell results as HAWCStab2's .cmb, OpenFAST's .lin files or a "
            "table (.csv)"
        )
    return None


_TOP_KEY = re.compile(r"^([A-Za-z_][\w-]*)\s*:", re.MULTILINE)


def other_kind(path: FsPath) -> str | None:
    """What a YAML file that sits beside turbines but is none is — a WISDEM/WEIS options
    file (:data:`OPTIONS_FILE`), a ROSCO tuning file, another tool's results
    (:func:`_kind`) — from its top-level keys in its first 200 kB, read once without parsing
    it (a batch's discovery stays cheap); None: a turbine, as far as the keys say."""
    try:
        with open(path, "rb") as fh:
            head = fh.read(200_000).decode("utf-8", "replace")
    except OSError:
        return None
    keys = set(_TOP_KEY.findall(head))
    if _options_keys(keys, "folder_output" in head):
        return OPTIONS_FILE
    return _kind(keys, "configuration:" in head and "outputs:" in head)


def from_document(doc: Document) -> Spec:
    """Validate a parsed document as a :class:`Spec`."""
    if not isinstance(doc.data, dict):
        raise SpecError(
            "expected a mapping of fields (wtvib:, turbine:, rotor:, …) at the top",
            line=doc.line_of(()),
            source=doc.source,
        )
    version = doc.data.get("wtvib")
    if "wtvib" not in doc.data:
        if _options_file(doc.data):
            raise SpecError(
                f"{OPTIONS_FILE}: give the turbine's windIO file (the geometry YAML the "
                "options go with)",
                line=1,
                source=doc.source,
            )
        other = _another_yaml(doc.data)
        raise SpecError(
            other or "not a wtvib spec: the version key 'wtvib: 1' is missing",
            line=1,
            source=doc.source,
        )
    if version != FORMAT_VERSION:
        raise SpecError(
            f"unsupported spec format version {version!r}; this wtvib reads version "
            f"{FORMAT_VERSION}",
            path="wtvib",
            line=doc.line_of(("wtvib",)),
            source=doc.source,
        )
    provenance: dict[str, Quantity] = {}
    data = _extract_quantities(doc, doc.data, (), provenance)
    try:
        spec = Spec.model_validate(data)
    except ValidationError as exc:
        raise _spec_error(exc, doc) from None
    _check_sources(spec, provenance, doc)
    _check_rotor_radius(spec, doc)
    _check_geometry(spec, doc)
    _check_results(spec, doc)
    _check_coupled(spec, doc)
    _check_aerodynamics(spec, doc)
    spec._source_file = doc.source
    spec._provenance = provenance
    return spec


def _extract_quantities(doc: Document, node: Any, path: Path, out: dict[str, Quantity]) -> Any:
    """Replace each ``{value: …, provenance: …}`` mapping by its number, recording it."""
    if isinstance(node, dict):
        if "value" in node and "provenance" in node:
            try:
                q = Quantity.model_validate(node)
            except ValidationError as exc:
                raise _spec_error(exc, doc, prefix=path) from None
            out[format_path(path)] = q
            return q.value
        return {k: _extract_quantities(doc, v, (*path, k), out) for k, v in node.items()}
    if isinstance(node, list):
        return [_extract_quantities(doc, v, (*path, i), out) for i, v in enumerate(node)]
    return node
