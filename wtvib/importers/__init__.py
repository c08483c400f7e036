"""Reading the files users already have: wtvib specs, OpenFAST ElastoDyn decks, windIO.

:func:`load` detects the format and returns a validated :class:`~wtvib.spec.Spec`. An
importer produces a plain wtvib-format dictionary first, so ``wtvib convert`` can write
it out as an editable spec.
"""

import math
import re
import stat
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..errors import SpecError
from ..spec import Spec, from_data, load_document, read_text
from ..spec.load import file_fingerprint, fingerprint

FORMATS = "a wtvib spec (YAML with 'wtvib: 1'), a windIO turbine YAML (1.x or 2.x), an "
FORMATS += "OpenFAST ElastoDyn / FAST v7 deck (.dat/.fst), a HAWC2 model (.htc), or Campbell "
FORMATS += "results: OpenFAST "
FORMATS += "linearisation (.lin, or a folder of them), HAWCStab2 (.cmb) or a table (.csv)"


def detect(path: Path, text: str) -> str:
    """``wtvib``, ``windio``, ``elastodyn`` or a Campbell-results reader, by content;
    SpecError for anything else.

    Keys decide, never prose: a wtvib spec by its top-level ``wtvib:`` key (a converted deck
    set's assumptions mention ElastoDyn and BlSpn), a YAML file by its suffix, an OpenFAST
    input by a key in the key column of a ``value Key - description`` line.
    """
    suffix = path.suffix.lower()
    if path.is_dir():
        if _holds_specs(path):
            raise SpecError(
                "a folder of turbine files: audit them with `wtvib batch "
                f"{path}` (check takes one turbine file, or a folder of .lin files)",
                source=str(path),
            )
        return "openfast-lin"
    if suffix == ".lin":
        return "openfast-lin"
    if suffix == ".cmb":
        return "hawcstab2"
    if suffix == ".htc" or re.search(
        r"^\s*begin\s+new_htc_structure\s*;", text[:200_000], re.M | re.I
    ):
        return "hawc2"
    if suffix == ".csv":
        from .campbell_table import looks_like

        if looks_like(text):
            return "campbell-table"
    if _WTVIB_KEY.search(text[:100_000]):
        return "wtvib"
    if suffix in (".yaml", ".yml"):
        windio_like = "components:" in text and ("assembly:" in text or "windIO" in text)
        return "windio" if windio_like else "wtvib"
    keys = set(_DECK_KEY.findall(text))
    if keys & {"TwrFile", "EDFile", "NumBl"}:
        return "elastodyn"  # ElastoDyn deck, FAST v7 .fst, or an OpenFAST .fst naming one
    if suffix in _HAWC_PARTS:
        raise SpecError(_HAWC_PARTS[suffix], source=str(path))
    known = next((what for what, mark in _KNOWN_BY_TEXT if mark.search(text[:20_000])), None)
    if known is not None:
        raise SpecError(known, source=str(path))
    part = next((name for name, marks in _DECK_PARTS if keys & set(marks)), None)
    if part is not None:
        raise SpecError(
            f"an OpenFAST {part} file: wtvib reads it through the deck set that names it — "
            "give the .fst (or the ElastoDyn deck)",
            source=str(path),
        )
    raise SpecError(f"not a format wtvib reads; expected {FORMATS}", source=str(path))


#: A wtvib spec's format key, at the top level of the document.
_WTVIB_KEY = re.compile(r"^wtvib\s*:", re.MULTILINE)
#: The key of an OpenFAST ``value Key - description`` line (the second token).
_DECK_KEY = re.compile(r"^[ \t]*\S+[ \t]+([A-Za-z_][A-Za-z0-9_()]*)(?=\s|$)", re.MULTILINE)

#: HAWC2's and HAWCStab2's files other than the htc and the .cmb, by suffix: what each is
#: and how wtvib reads it.
_HAWC_PARTS = {
    ".opt": "HAWCStab2's operational data (wind, pitch, rotor speed): wtvib reads it with "
    "the .cmb of the same name (or a folder's only .opt), or through the htc that names it "
    "— give the .cmb or the .htc",
    ".pwr": "HAWCStab2's steady-state results (power, thrust, rotor speed per wind): wtvib "
    "reads their rotor speeds with the .cmb of the same name — give the .cmb",
    ".amp": "HAWCStab2's modal amplitudes: wtvib reads them with the .cmb of the same name "
    "— give the .cmb",
    ".ind": "HAWCStab2's induction and loads along the blade at one wind: not a turbine "
    "description nor a Campbell result — give the .htc (or the .cmb)",
    ".st": "a HAWC2 structural (st) file: wtvib reads it through the htc that names it — "
    "give the .htc",
}

#: Files a turbine's repository holds beside its models, told by their text (first match
#: wins): what each is and what to give instead.
_KNOWN_BY_TEXT = (
    (
        _HAWC_PARTS[".st"],
        # numbers parted by whitespace (not a pattern that may split one number many ways)
        re.compile(r"^[ \t]*\$\d+[ \t]+\d+.*\n[ \t]*[-+0-9.eE]+(?:\s+[-+0-9.eE]+){18}", re.M),
    ),
    (
        "a ROSCO controller input (DISCON): wtvib reads its speeds through the deck set "
        "whose ServoDyn names it — give the .fst (or the ElastoDyn deck)",
        re.compile(r"!\s*(?:F_LPFType|VS_ControlMode|PC_ControlMode)\b"),
    ),
    (
        "a rotor performance table (C_p, C_t, C_q over tip-speed ratio and pitch): not a "
        "turbine description — give the deck set (.fst) or the model it belongs to",
        re.compile(r"^#.*Rotor performance tables", re.M | re.I),
    ),
)

#: Keys that tell the other files of an OpenFAST deck set apart (first match wins).
_DECK_PARTS = (
    ("AeroDyn", ("AFNames", "ADBlFile", "NumBlNds")),
    ("ServoDyn", ("PCMode", "VSContrl", "DLL_FileName")),
    ("ElastoDyn tower", ("NTwInpSt", "TwrFADmp(1)", "TwrFADmp")),
    ("ElastoDyn blade", ("NBlInpSt", "BldFlDmp(1)", "BldFlDmp")),
    ("InflowWind", ("WindType",)),
    ("aerofoil (AeroDyn polar)", ("NumAlf", "InterpOrd")),
    ("BeamDyn", ("QuasiStaticInit", "member_total", "kp_total")),
    ("BeamDyn blade", ("station_total", "damp_type")),
    ("HydroDyn", ("PotMod", "PotFile")),
    ("SubDyn", ("FEMMod", "NReact", "SttcSolve")),
    ("SeaState", ("WaveHs", "WaveTp")),
    ("mooring (MoorDyn, MAP++ or FEAMooring)", ("NumLines", "LineTypes", "NLines")),
)


def _holds_specs(folder: Path) -> bool:
    """Whether a folder holds turbine specs or windIO files (what batch discovers) and no
    .lin or .fst file (a deck set's folder gets the name of its .fst instead)."""
    try:
        names = [p.name.lower() for p in folder.iterdir()]
    except OSError:
        return False
    if any(n.endswith((".lin", ".fst")) for n in names):
        return False
    return any(n.endswith((".yaml", ".yml")) for n in names)


@dataclass(frozen=True)
class ReadOptions:
    """What a file's format may not say, given by the user (the command line's import
    options): ``rpm`` [rpm] (MIN, MAX) and ``rated`` [rpm] set the operating range;
    ``head_mass`` [kg] replaces a windIO file's tower-head assembly (1.x files hold no hub
    or nacelle masses); ``clamped_base`` reads a floating turbine's tower as clamped at its
    base; ``blades`` is the number of blades of Campbell results that do not say; ``soil``
    a soil profile (YAML: ``soil`` layers and optional ``bounds``, or HAWC2's soil file)
    for a windIO monopile; ``deck_dofs`` models an OpenFAST deck with its degrees of
    freedom as the deck switches them (ElastoDyn's FlapDOF1 … PtfmYDOF: OpenFAST's model of
    the deck), where by default the structure's every mode is audited and the switches said."""

    rpm: tuple[float, float] | None = None
    rated: float | None = None
    head_mass: float | None = None
    clamped_base: bool = False
    blades: int | None = None
    soil: Path | None = None
    deck_dofs: bool = False


def to_data(path: str | Path, options: ReadOptions = ReadOptions()) -> dict[str, Any]:
    """The wtvib-format dictionary of any supported file (for ``wtvib convert``)."""
    return _to_data(*_opened(Path(path), options), options)


def _opened(p: Path, options: ReadOptions) -> tuple[Path, str, str]:
    """The file, its text (none for Campbell results, which their reader reads) and its
    format, the options checked against that format."""
    results_files = p.is_dir() or p.suffix.lower() == ".lin"  # read by their reader alone
    text = "" if results_files else read_text(p, ansi=True)
    kind = detect(p, text)
    if kind in ("wtvib", "windio") and not text.isascii():
        read_text(p)  # YAML is UTF-8: refused as such where it is not
    _check_options(p, kind, options)
    return p, text, kind


def kind(path: str | Path) -> str:
    """The format of a file (:func:`detect`), read as :func:`load` reads it."""
    return _opened(Path(path), ReadOptions())[2]


def _to_data(p: Path, text: str, kind: str, options: ReadOptions) -> dict[str, Any]:
    """:func:`to_data` of a file already read and told apart (:func:`_opened`)."""
    rpm = options.rpm
    if options.soil is not None and kind != "windio":
        raise SpecError(
            "--soil applies to windIO files (their monopile); a wtvib spec gives its soil in "
            "tower.foundation",
            source=str(p),
        )
    if kind == "openfast-lin":
        from . import openfast_lin

        data = openfast_lin.to_spec_data(p, options.blades, rpm)
    elif kind == "hawcstab2":
        from . import hawcstab2

        data = hawcstab2.to_spec_data(p, text, options.blades, rpm)
    elif kind == "campbell-table":
        from . import campbell_table

        data = campbell_table.to_spec_data(p, text, options.blades, rpm)
    elif kind in ("elastodyn", "hawc2"):
        data = _model_data(p, text, kind, options)
    elif kind == "windio":
        from . import windio

        soil = _soil_profile(options.soil)
        data = windio.to_spec_data(p, text, options.head_mass, options.clamped_base, soil, rpm)
    else:
        doc = load_document(p, text)
        data = doc.data
    speed_given = rpm is not None or options.rated is not None
    return _with_speed(data, rpm, options.rated) if speed_given else data


def _model_data(p: Path, text: str, kind: str, options: ReadOptions) -> dict[str, Any]:
    """A deck set's or a HAWC2 model's spec data, with the names of the files it read as
    Windows reads them (:mod:`.paths`) in its assumptions."""
    from . import paths

    with paths.recording() as windows_names:
        if kind == "hawc2":
            from . import hawc2

            data = hawc2.to_spec_data(p, text)
        else:
            from . import elastodyn

            data = elastodyn.to_spec_data(
                p,
                text,
                options.clamped_base,
                speed_given=options.rpm is not None,
                deck_dofs=options.deck_dofs,
            )
    data.setdefault("assumptions", []).extend(windows_names)
    return data


def load(path: str | Path, options: ReadOptions = ReadOptions()) -> Spec:
    """Any supported file as a validated spec, read with ``options``."""
    p, text, kind = _opened(Path(path), options)
    if kind == "wtvib" and options.rpm is None and options.rated is None and options.soil is None:
        from ..spec import from_document

        return from_document(load_document(p, text)).fingerprinted(fingerprint(text))
    data = _to_data(p, text, kind, options)
    spec = from_data(data, source=str(p))
    if p.is_dir():  # a folder of results: the hash of its files' hashes, in order
        files = spec.results.files if spec.results is not None else []
        return spec.fingerprinted(
            fingerprint("\n".join(file_fingerprint(f) for f in sorted(files)))
        )
    if p.suffix.lower() == ".lin":  # a linearisation: its bytes hashed a megabyte at a time
        return spec.fingerprinted(file_fingerprint(p))
    return spec.fingerprinted(fingerprint(text))


def _check_options(path: Path, kind: str, options: ReadOptions) -> None:
    """The import options, one rule and one message each, for every format."""
    rpm, rated, head_mass = options.rpm, options.rated, options.head_mass
    if options.deck_dofs and kind != "elastodyn":
        raise SpecError(
            "--deck-dofs applies to OpenFAST deck sets (ElastoDyn's DOF switches); this "
            "file has none",
            source=str(path),
        )
    if options.blades is not None and kind not in ("openfast-lin", "hawcstab2", "campbell-table"):
        raise SpecError(
            "--blades applies to Campbell results that do not say how many blades the rotor "
            "has; this file gives them",
            source=str(path),
        )
    if head_mass is not None:
        if kind != "windio":
            what = "the deck's" if kind == "elastodyn" else "the spec's"
            raise SpecError(
                f"--head-mass applies to windIO files only; {what} own tower-head masses are "
                "used (edit them, or convert the file and edit the spec)",
                source=str(path),
            )
        if not (math.isfinite(head_mass) and head_mass > 0):
            raise SpecError(f"--head-mass must be a mass above 0 kg (got {head_mass:g})")
    if rated is not None and not (math.isfinite(rated) and rated > 0):
        raise SpecError(f"--rated must be a speed above 0 rpm (got {rated:g})")
    if (
        rpm is not None
        and rated is not None
        and rpm[0] != rpm[1]
        and not (rpm[0] <= rated <= rpm[1])
    ):
        raise SpecError(f"--rated {rated:g} rpm lies outside --rpm {rpm[0]:g}:{rpm[1]:g}")


def is_main_input(path: Path) -> bool:
    """True for files a batch should audit: specs, windIO files and ElastoDyn main decks."""
    suffix = path.suffix.lower()
    if suffix in (".yaml", ".yml"):
        return True
    if suffix == ".htc":  # a HAWC2 model, not a part of one that another continues in
        try:
            with path.open("rb") as fh:
                head = fh.read(400_000).lower()
        except OSError:
            return True
        return b"new_htc_structure" in head
    if suffix in (".dat", ".fst"):
        try:  # the head only, of a regular file only: a sparse 8 GB .dat or a FIFO in a
            # folder must not cost its size or block discovery
            if not stat.S_ISREG(path.stat().st_mode):
                return True  # let the audit report what it is
            with path.open("rb") as fh:
                head = fh.read(200_000)
        except OSError:
            return True  # let the audit report the read error
        return b"TwrFile" in head or (suffix == ".fst" and b"EDFile" in head)
    return False


def _with_speed(
    data: dict[str, Any], rpm: tuple[float, float] | None, rated: float | None
) -> dict[str, Any]:
    speed = dict(data["rotor"]["speed"])
    if rpm is not None:
        low, high = rpm
        speed = {"fixed_rpm": low} if low == high else {"min_rpm": low, "max_rpm": high}
    if rated is not None:
        if "fixed_rpm" in speed:
            speed = {"fixed_rpm": rated}
        else:
            speed["rated_rpm"] = rated
    speed["source"] = "the command line (--rpm/--rated)"
    # the file's own range, which the command line replaces, is no longer the audit's: one
    # statement of where the speeds come from (an importer's begins "Operating range")
    replaced = [a for a in data.get("assumptions", []) if a.startswith("Operating range")]
    kept = [a for a in data.get("assumptions", []) if a not in replaced]
    said = "Operating speeds set on the command line (--rpm/--rated)" + (
        f", in place of the file's: {replaced[0][0].lower()}{replaced[0][1:].rstrip('.')}."
        if replaced
        else "."
    )
    notes = [*kept, said]
    # a range given on the command line answers the importer's "speed not found"
    warnings = [w for w in data.get("warnings", []) if "--rpm" not in w]
    out = {**data, "rotor": {**data["rotor"], "speed": speed}, "assumptions": notes}
    if "warnings" in data:
        out["warnings"] = warnings
    return out


def _soil_profile(path: Path | None) -> dict[str, Any] | None:
    """A soil profile file: YAML with ``soil`` (layers) and optional ``bounds``, the fields
    of a spec's ``tower.foundation``, validated here on its own (a mistake names this file
    and its line) and again with the turbine's foundation (the layers must reach the pile's
    tip)."""
    if path is None:
        return None
    from pydantic import ValidationError

    from ..spec.load import _extract_quantities
    from ..spec.messages import _spec_error
    from ..spec.tower import SoilProfile
    from . import hawc2_soil

    text = read_text(Path(path), ansi=True)
    if hawc2_soil.looks_like(text):  # HAWC2's distributed springs (its soil data file)
        return hawc2_soil.profile(Path(path))
    doc = load_document(Path(path), text)
    data = doc.data
    if not isinstance(data, dict) or "soil" not in data or set(data) - {"soil", "bounds"}:
        raise SpecError(
            "a soil profile holds 'soil' (layers) and optionally 'bounds', nothing else",
            source=str(path),
        )
    try:  # here, so that a mistake names this file and its line, not the turbine's
        SoilProfile.model_validate(_extract_quantities(doc, data, (), {}))
    except ValidationError as exc:
        raise _spec_error(exc, doc) from None
    return data
