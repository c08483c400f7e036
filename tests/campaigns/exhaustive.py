"""Exhaustive mutation campaigns, complementing the hypothesis properties: every
place of a reference input mutated in turn, not a random sample of them.

    .venv/bin/python tests/campaigns/exhaustive.py deck      # NREL 5-MW OpenFAST deck set
    .venv/bin/python tests/campaigns/exhaustive.py windio    # IEA-15 windIO 2.x example
    .venv/bin/python tests/campaigns/exhaustive.py extremes  # catalogue specs' numbers
    .venv/bin/python tests/campaigns/exhaustive.py floating  # r-test's OC4 semisubmersible
    .venv/bin/python tests/campaigns/exhaustive.py windio-floating  # windIO OC3/OC4 platforms
    .venv/bin/python tests/campaigns/exhaustive.py hawc2     # the IEA-15 onshore HAWC2 model
    .venv/bin/python tests/campaigns/exhaustive.py hawc2-floating  # its UMaineSemi floater
    .venv/bin/python tests/campaigns/exhaustive.py beam      # r-test's BeamDyn, SubDyn, StC decks
    .venv/bin/python tests/campaigns/exhaustive.py monopile  # the IEA-22 monopile deck set
    .venv/bin/python tests/campaigns/exhaustive.py hawc2-fpm # its blades' 6×6 st set
    ... [--part I --parts N]  (run N processes, I = 0 … N-1, and add the counts)

deck: each line of the deck set's files (ElastoDyn, tower, blade, ServoDyn, AeroDyn,
AeroDyn blade, ROSCO, an aerofoil) deleted, cut in half, its first and last token replaced
by abc, nan, -1, 0, 1e300, 1e-300, 2.7 (and each line's first token dropped: a deck's
value, ``dropped``; in an htc file each command's values: ``bare``). windio: each key path
(list items: the first two) deleted, emptied, made text, negated, true, null. extremes:
each numeric leaf of every turbines/*.yaml at 1e-300, 1e-15, 1e9, 1e300. floating: as deck,
on the files of r-test's OC4 semisubmersible deck sets that make its platform (the .fst,
ElastoDyn, HydroDyn, SeaState, MAP++ and MoorDyn moorings, WAMIT's .hst and the first 120
lines of its .1; the archive tests/data/openfast_decks/rtest_floating.tar.gz). windio-
floating: as windio, on every key path of the windIO OC3 spar and OC4 semisubmersible
(tests/data/windio_floating), plus each number at 0, 1e-300 and 1e300; the platform read
under the NREL 5-MW catalogue turbine's head on the OC3/OC4 tower (its modes computed on
the platform) and audited. hawc2: as deck, on every file of the IEA-15 onshore HAWC2 model
(tests/data/hawc2: the main htc, the htc files it continues in, the st, ae and opt files,
the pc file's first 200 lines). hawc2-floating: as deck, on the IEA-15 UMaineSemi HAWC2
model's floater (its main htc's ext_sys floater and constraint blocks, the elasticBar
mooring system and its constraints, WAMIT's .hst). The invariant, as the CLI's: a typed
wtvib error, or a report whose JSON is strict, within 20 s. Prints the counts as JSON, then
one line per crash or slow case.
tests/FUZZ.md records the campaigns run.
"""

import argparse
import copy
import hashlib
import json
import os
import shutil
import signal
import sys
import tempfile
import time
import traceback
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import yaml

from wtvib import audit, importers, spec
from wtvib.errors import WtvibError
from wtvib.spec.yamlio import parse, parse_plain

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))  # run as a script: the tests package beside wtvib
from tests.conftest import NREL_DECK_FILES as DECK_FILES  # noqa: E402

NREL = ROOT.parent / "shared" / "reference" / "NREL5MW"
TOKENS = ["abc", "nan", "-1", "0", "1e300", "1e-300", "2.7"]
EXTREMES = [1e-300, 1e-15, 1e9, 1e300]
LIMIT_S = 20


class TooSlowError(Exception):
    """An example that ran past LIMIT_S."""


def _alarm(*_: object) -> None:
    raise TooSlowError


Case = tuple[str, Callable[[], dict[str, Any]]]  # label, the spec data it imports to


def deck_cases(work: Path) -> Iterator[Case]:
    for name in DECK_FILES:
        yield from _line_cases(NREL, work, "NREL-5MW.fst", name)


#: The floating campaign's files, each with the deck set that reads it and how many of its
#: lines are mutated (WAMIT's .1 has 6,000 rows of one form: its first 120).
OC4 = "glue-codes/openfast/5MW_OC4Semi_Linear/"
OC4_MD = "glue-codes/openfast/5MW_OC4Semi_MD_Linear/"
HYDRO_DATA = "glue-codes/openfast/5MW_Baseline/HydroData/"
FLOATING_FILES = (
    (OC4 + "5MW_OC4Semi_Linear.fst", OC4 + "5MW_OC4Semi_Linear.fst", None),
    (
        OC4 + "5MW_OC4Semi_Linear.fst",
        OC4 + "NRELOffshrBsline5MW_OC4DeepCwindSemi_ElastoDyn.dat",
        None,
    ),
    (
        OC4 + "5MW_OC4Semi_Linear.fst",
        OC4 + "NRELOffshrBsline5MW_OC4DeepCwindSemi_HydroDyn.dat",
        None,
    ),
    (OC4 + "5MW_OC4Semi_Linear.fst", OC4 + "SeaState.dat", None),
    (OC4 + "5MW_OC4Semi_Linear.fst", OC4 + "NRELOffshrBsline5MW_OC4DeepCwindSemi_MAP.dat", None),
    (OC4 + "5MW_OC4Semi_Linear.fst", HYDRO_DATA + "marin_semi.hst", None),
    (OC4 + "5MW_OC4Semi_Linear.fst", HYDRO_DATA + "marin_semi.1", 120),
    (
        OC4_MD + "5MW_OC4Semi_MD_Linear.fst",
        OC4_MD + "NRELOffshrBsline5MW_OC4DeepCwindSemi_MoorDyn.dat",
        None,
    ),
)


#: The HAWC2 campaign's files (the IEA-15 onshore model, tests/data/hawc2): the main htc
#: and every file it continues in or reads, the profile-coefficient file's first 200 lines.
H2_MAIN = "HAWC2/IEA-15-240-RWT-Onshore/htc/IEA_15MW_RWT_Onshore.htc"
H2_SHARED = "HAWC2/IEA-15-240-RWT/"
HAWC2_FILES = (
    (H2_MAIN, None),
    ("HAWC2/IEA-15-240-RWT-Onshore/data/IEA_15MW_RWT_Tower_st.dat", None),
    ("HAWC2/IEA-15-240-RWT-Onshore/data/IEA_15MW_RWT_Onshore.opt", None),
    (H2_SHARED + "IEA_15MW_RWT_WTG_bodies_noFPM.htc", None),
    (H2_SHARED + "IEA_15MW_RWT_WTG_orientation.htc", None),
    (H2_SHARED + "IEA_15MW_RWT_WTG_constraint.htc", None),
    (H2_SHARED + "IEA_15MW_RWT_WTG_aero.htc", None),
    (H2_SHARED + "IEA_15MW_RWT_Blade_st_noFPM.st", None),
    (H2_SHARED + "IEA_15MW_RWT_Shaft_st.dat", None),
    (H2_SHARED + "IEA_15MW_RWT_Dummy_st.dat", None),
    (H2_SHARED + "IEA_15MW_RWT_ae.dat", None),
    (H2_SHARED + "IEA_15MW_RWT_pc_OpenFASTpolars_3dcorr.dat", 200),
)


def hawc2_cases(source: Path, work: Path) -> Iterator[Case]:
    for name, first in HAWC2_FILES:
        yield from _line_cases(source, work, H2_MAIN, name, first)


#: The fully populated st set (tests/data/hawc2/IEA_15MW_RWT_Blade_st_FPM.st.gz, the same
#: blade's BECAS 6×6 matrices) and the row of it whose every value is also mutated.
H2_FPM = H2_SHARED + "IEA_15MW_RWT_Blade_st_FPM.st"
FPM_ROW = 6


def hawc2_fpm_cases(source: Path, work: Path) -> Iterator[Case]:
    """The onshore model with its blades' fully populated set (``FPM 1``): each line of the
    st file as :func:`_line_cases`, and each value of its first station replaced by each
    of TOKENS."""
    yield from _line_cases(source, work, H2_MAIN, H2_FPM)
    lines = (source / H2_FPM).read_text(encoding="latin-1").splitlines(keepends=True)
    tokens = lines[FPM_ROW - 1].split()
    for j in range(1, len(tokens) - 1):  # the first and last: _line_cases's
        for junk in TOKENS:
            row = " ".join([*tokens[:j], junk, *tokens[j + 1 :]]) + "\n"
            text = "".join([*lines[: FPM_ROW - 1], row, *lines[FPM_ROW:]])
            label = f"{H2_FPM}:{FPM_ROW} token{j}={junk}"
            yield label, _deck_import(source, work, H2_MAIN, H2_FPM, text)


#: The floating HAWC2 campaign's files and lines (1-based, inclusive): the floater's
#: ext_sys and the constraint block of the main htc, the moorings, the hydrostatics.
H2_SEMI = "HAWC2/IEA-15-240-RWT-UMaineSemi/htc/IEA_15MW_RWT_UMaineSemi.htc"
H2_SEMI_DATA = "HAWC2/IEA-15-240-RWT-UMaineSemi/data/IEA_15MW_RWT_UMaineSemi_"
HAWC2_FLOATING_FILES = (
    (H2_SEMI, (73, 165)),
    (H2_SEMI_DATA + "mooring_system.htc", None),
    (H2_SEMI_DATA + "mooring_constraint.htc", None),
    ("OpenFAST/IEA-15-240-RWT-UMaineSemi/HydroData/IEA-15-240-RWT-UMaineSemi.hst", None),
)


def hawc2_floating_cases(source: Path, work: Path) -> Iterator[Case]:
    for name, span in HAWC2_FLOATING_FILES:
        yield from _line_cases(source, work, H2_SEMI, name, span)


#: The BeamDyn, SubDyn and structural-control campaign's files (r-test's deck sets in
#: tests/data/openfast_decks rtest and rtest_special), each with the deck set that reads
#: it and how many of its lines are mutated (the BeamDyn blade's 756: its first 160 — the
#: header, the first stations' 6×6 matrices). The .fst of one of them (the others' are
#: read by the same code).
R = "glue-codes/openfast/"
BEAM_FILES = (
    (R + "5MW_OC3Mnpl_Linear/5MW_OC3Mnpl_Linear.fst", "", None),
    (R + "5MW_OC3Mnpl_Linear/5MW_OC3Mnpl_Linear.fst", "_SubDyn.dat", None),
    (R + "5MW_Land_BD_Linear/5MW_Land_BD_Linear.fst", "_BDoutputs.dat", None),
    (
        R + "5MW_Land_BD_Linear/5MW_Land_BD_Linear.fst",
        R + "5MW_Baseline/NRELOffshrBsline5MW_BeamDyn.dat",
        None,
    ),
    (
        R + "5MW_Land_BD_Linear/5MW_Land_BD_Linear.fst",
        R + "5MW_Baseline/NRELOffshrBsline5MW_BeamDyn_Blade.dat",
        160,
    ),
    (R + "StC_test_OC4Semi_Linear_Tow/StC_test_OC4Semi_Linear_Tow.fst", "SrvD_StC-Tow.dat", None),
    (R + "StC_test_OC4Semi_Linear_Tow/StC_test_OC4Semi_Linear_Tow.fst", "StC-Tow-XDir.dat", None),
    (
        R + "Ideal_Beam_Fixed_Free_Linear/Ideal_Beam_Fixed_Free_Linear.fst",
        R + "Ideal_Beam/BeamDyn_Blade.dat",
        None,
    ),
)


#: The monopile campaign's files: the IEA-22 monopile deck set (tests/data/openfast_decks/
#: iea22.tar.gz) — its structure and sea: SubDyn, HydroDyn, SeaState, ElastoDyn and its
#: tower, BeamDyn and the first 120 lines of its blade.
I22 = "OpenFAST/IEA-22-280-RWT-Monopile/"
MONOPILE_FILES = (
    (I22 + "IEA-22-280-RWT_SubDyn.dat", None),
    (I22 + "IEA-22-280-RWT_HydroDyn.dat", None),
    (I22 + "IEA-22-280-RWT_SeaState.dat", None),
    (I22 + "IEA-22-280-RWT_ElastoDyn.dat", None),
    (I22 + "IEA-22-280-RWT_ElastoDyn_tower.dat", None),
    ("OpenFAST/IEA-22-280-RWT/IEA-22-280-RWT_BeamDyn.dat", None),
    ("OpenFAST/IEA-22-280-RWT/IEA-22-280-RWT_BeamDyn_Blade.dat", 120),
)


def monopile_cases(source: Path, work: Path) -> Iterator[Case]:
    for name, first in MONOPILE_FILES:
        yield from _line_cases(source, work, I22 + "IEA-22-280-RWT-Monopile.fst", name, first)


def beam_cases(source: Path, work: Path) -> Iterator[Case]:
    """BEAM_FILES: a name beginning with glue-codes/ is the file; "" the .fst itself; any
    other the one file beside the .fst whose name ends so."""
    for fst, name, first in BEAM_FILES:
        if not name.startswith(R):  # the file beside the .fst whose name ends so
            ends = name or Path(fst).name
            found = sorted((source / Path(fst).parent).iterdir())
            name = str(next(p for p in found if p.name.endswith(ends)).relative_to(source))
        yield from _line_cases(source, work, fst, name, first)


def floating_cases(source: Path, work: Path) -> Iterator[Case]:
    for fst, name, first in FLOATING_FILES:
        yield from _line_cases(source, work, fst, name, first)


def _line_cases(
    source: Path,
    work: Path,
    fst: str,
    name: str,
    first: int | tuple[int, int] | None = None,
) -> Iterator[Case]:
    """Each line of ``name`` (of the first ``first``, or lines ``first`` = (from, to), 1-based
    and inclusive) deleted, cut, its first and last token replaced by each of TOKENS; the
    deck set ``fst`` imported with it."""
    lines = (source / name).read_text(encoding="latin-1").splitlines(keepends=True)
    start, stop = (first[0] - 1, first[1]) if isinstance(first, tuple) else (0, first)
    for i, line in enumerate(lines[start:stop], start=start):
        edits = [("delete", [*lines[:i], *lines[i + 1 :]])]
        edits.append(("cut", [*lines[:i], line[: len(line) // 2]]))
        tokens = line.split()
        for j in sorted({0, len(tokens) - 1}) if tokens else []:
            for junk in TOKENS:
                changed = " ".join([*tokens[:j], junk, *tokens[j + 1 :]]) + "\n"
                edits.append((f"token{j}={junk}", [*lines[:i], changed, *lines[i + 1 :]]))
        if name.endswith(".htc") and ";" in line and len(tokens) > 1:  # its values dropped
            bare = line[: len(line) - len(line.lstrip())] + tokens[0] + " ;\n"
            edits.append(("bare", [*lines[:i], bare, *lines[i + 1 :]]))
        elif not name.endswith(".htc") and len(tokens) > 1:  # a deck's value dropped
            dropped = " ".join(tokens[1:]) + "\n"
            edits.append(("dropped", [*lines[:i], dropped, *lines[i + 1 :]]))
        for label, text in edits:
            run = _deck_import(source, work, fst, name, "".join(text))
            yield f"{name}:{i + 1} {label}", run


def _deck_import(
    source: Path, work: Path, fst: str, name: str, text: str
) -> Callable[[], dict[str, Any]]:
    def run() -> dict[str, Any]:
        try:
            (work / name).write_text(text, encoding="latin-1")
            return importers.to_data(work / fst)
        finally:
            shutil.copyfile(source / name, work / name)

    return run


def windio_cases(work: Path) -> Iterator[Case]:
    import windIO

    source = Path(windIO.__file__).parent / "examples" / "turbine" / "IEA-15-240-RWT.yaml"
    base = parse_plain(source.read_text()).data
    for path in _paths(base):
        for kind in ("delete", "empty", "text", "negate", "true", "null"):
            doc = copy.deepcopy(base)
            parent = doc
            for key in path[:-1]:
                parent = parent[key]
            value = parent[path[-1]]
            if kind == "delete":
                if isinstance(parent, list):
                    continue
                del parent[path[-1]]
            elif kind == "negate":
                if not isinstance(value, int | float) or isinstance(value, bool):
                    continue
                parent[path[-1]] = -abs(value) - 1
            else:
                parent[path[-1]] = {"empty": [], "text": "abc", "true": True, "null": None}[kind]
            label = f"{'.'.join(map(str, path))} {kind}"
            yield label, _windio_import(work / "m.yaml", yaml.safe_dump(doc, sort_keys=False))


#: The OC3/OC4 tower (Jonkman 2010: 10 → 87.6 m, 6.5 → 3.87 m, walls 27 → 19 mm, E 210 GPa,
#: ρ 8,500 kg/m³) under the NREL 5-MW's head, so that every mutated platform is audited with
#: a computed tower on it (the catalogue NREL 5-MW gives its tower's modes).
FLOATING_TOWER = {
    "construction": "steel-tube",
    "height_m": 77.6,
    "sections": {
        "height_m": [0.0, 77.6],
        "outer_diameter_m": [6.5, 3.87],
        "wall_thickness_m": [0.027, 0.019],
    },
    "material": {"youngs_modulus_pa": 2.1e11, "density_kg_m3": 8500.0},
}


def windio_floating_cases() -> Iterator[Case]:
    from wtvib.importers import windio
    from wtvib.importers.windio_platform import platform

    turbine = parse_plain((ROOT / "turbines" / "nrel-5mw.yaml").read_text()).data
    for name in ("oc3_spar.yaml", "oc4_semi.yaml"):
        source = ROOT / "tests" / "data" / "windio_floating" / name
        base = parse_plain(source.read_text()).data
        for path in _paths(base):
            kinds: list[Any] = ["delete", "empty", "text", "negate", "true", "null"]
            for kind in [*kinds, 0.0, 1e-300, 1e300]:
                doc = copy.deepcopy(base)
                parent = doc
                for key in path[:-1]:
                    parent = parent[key]
                value = parent[path[-1]]
                numeric = isinstance(value, int | float) and not isinstance(value, bool)
                if kind == "delete":
                    if isinstance(parent, list):
                        continue
                    del parent[path[-1]]
                elif kind == "negate" or not isinstance(kind, str):
                    if not numeric:
                        continue
                    parent[path[-1]] = -abs(value) - 1 if kind == "negate" else kind
                else:
                    parent[path[-1]] = {"empty": [], "text": "abc", "true": True, "null": None}[
                        kind
                    ]
                label = f"{name} {'.'.join(map(str, path))} {kind}"

                def run(doc: Any = doc, source: Path = source) -> dict[str, Any]:
                    data = copy.deepcopy(turbine)
                    d = windio._paths(doc, (), str(source))
                    try:  # the windIO reader's own net for a file of the wrong shape
                        floater = platform(d, source, 7e5, 10.0)
                    except (KeyError, TypeError, ValueError, IndexError, AttributeError) as exc:
                        if isinstance(exc, WtvibError):
                            raise
                        raise spec.SpecError(f"{type(exc).__name__}: {exc}") from None
                    data["tower"] = {
                        **FLOATING_TOWER,
                        "foundation": {"kind": "platform", "platform": floater.block},
                    }
                    data["tower_head"] = {"mass_kg": 350000.0, "cm_above_top_m": 1.97}
                    return data

                yield label, run


def _windio_import(target: Path, text: str) -> Callable[[], dict[str, Any]]:
    def run() -> dict[str, Any]:
        target.write_text(text)
        return importers.to_data(target)

    return run


def _paths(node: Any, path: tuple[Any, ...] = (), depth: int = 0) -> Iterator[tuple[Any, ...]]:
    if depth > 6:
        return
    if isinstance(node, dict):
        items = list(node.items())
    elif isinstance(node, list) and node and not isinstance(node[0], int | float):
        items = list(enumerate(node[:2]))
    else:
        return
    for key, value in items:
        yield (*path, key)
        yield from _paths(value, (*path, key), depth + 1)


def extreme_cases() -> Iterator[Case]:
    for file in sorted((ROOT / "turbines").glob("*.yaml")):
        base = parse_plain(file.read_text()).data
        for path in _numbers(base):
            for value in EXTREMES:
                doc = copy.deepcopy(base)
                parent = doc
                for key in path[:-1]:
                    parent = parent[key]
                parent[path[-1]] = value
                text = yaml.safe_dump(doc, sort_keys=False)
                yield f"{file.name} {'.'.join(map(str, path))}={value:g}", _from_text(text)


def _from_text(text: str) -> Callable[[], dict[str, Any]]:
    return lambda: parse(text).data


def _numbers(node: Any, path: tuple[Any, ...] = ()) -> Iterator[tuple[Any, ...]]:
    if isinstance(node, dict):
        for key, value in node.items():
            yield from _numbers(value, (*path, key))
    elif isinstance(node, list):
        for i, value in enumerate(node[:3]):
            yield from _numbers(value, (*path, i))
    elif isinstance(node, int | float) and not isinstance(node, bool):
        yield path


#: The campaigns on archived inputs (tests/data/…tar.gz): their archives and their cases.
ARCHIVES: dict[str, tuple[tuple[str, ...], Callable[[Path, Path], Iterator[Case]]]] = {
    "floating": (("openfast_decks/rtest_floating",), floating_cases),
    "beam": (("openfast_decks/rtest", "openfast_decks/rtest_special"), beam_cases),
    "monopile": (("openfast_decks/iea22",), monopile_cases),
    "hawc2": (("hawc2/iea15_onshore",), hawc2_cases),
    "hawc2-fpm": (("hawc2/iea15_onshore",), hawc2_fpm_cases),
    "hawc2-floating": (
        ("hawc2/iea15_onshore", "hawc2/iea15_umainesemi", "openfast_decks/iea15_semi"),
        hawc2_floating_cases,
    ),
}


def _unpacked(work: Path, archives: tuple[str, ...], fpm: bool) -> Path:
    """The archives unpacked beside ``work`` (the source the cases restore each file from)
    and copied to ``work``; ``fpm``: the IEA-15 onshore model's blades on their fully
    populated st set (``FPM 1``)."""
    import gzip
    import tarfile

    source = work.parent / "source"
    for archive in archives:
        with tarfile.open(ROOT / f"tests/data/{archive}.tar.gz") as tar:
            tar.extractall(source, filter="data")
    if fpm:
        packed = (ROOT / "tests/data/hawc2/IEA_15MW_RWT_Blade_st_FPM.st.gz").read_bytes()
        (source / H2_FPM).write_bytes(gzip.decompress(packed))
        bodies = source / H2_SHARED / "IEA_15MW_RWT_WTG_bodies_noFPM.htc"
        text = bodies.read_text(encoding="latin-1")
        text = text.replace("IEA_15MW_RWT_Blade_st_noFPM.st;", "IEA_15MW_RWT_Blade_st_FPM.st;")
        bodies.write_text(text.replace("FPM 0;", "FPM 1;"), encoding="latin-1")
    shutil.copytree(source, work)
    return source


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument(
        "campaign",
        choices=[
            "deck",
            "windio",
            "extremes",
            "floating",
            "windio-floating",
            "hawc2",
            "hawc2-floating",
            "beam",
            "monopile",
            "hawc2-fpm",
        ],
    )
    ap.add_argument("--part", type=int, default=0)
    ap.add_argument("--parts", type=int, default=1)
    ap.add_argument("--only", default="", help="run only the cases whose label ends so (bare)")
    args = ap.parse_args()
    work = Path(tempfile.mkdtemp(prefix="wtvib-campaign-")) / "deck"
    if args.campaign == "deck":
        shutil.copytree(NREL, work)
        cases = deck_cases(work)
    elif args.campaign in ARCHIVES:
        archives, make = ARCHIVES[args.campaign]
        source = _unpacked(work, archives, args.campaign == "hawc2-fpm")
        cases = make(source, work)
    elif args.campaign == "windio":
        work.mkdir(parents=True)
        cases = windio_cases(work)
    elif args.campaign == "windio-floating":
        cases = windio_floating_cases()
    else:
        cases = extreme_cases()
    signal.signal(signal.SIGALRM, _alarm)
    counts = {"ok": 0, "input": 0, "crash": 0, "slow": 0, "audits": 0}
    findings: list[str] = []
    outcome: dict[str, str] = {}  # each distinct spec audited once (a pure function of it)
    for n, (label, load) in enumerate(cases):
        if n % args.parts != args.part or not label.endswith(args.only):
            continue
        signal.alarm(LIMIT_S)
        start = time.perf_counter()
        try:
            data = load()
            text = json.dumps(data, sort_keys=True, default=str).encode()
            key = hashlib.sha1(text).hexdigest()
            if key not in outcome:
                counts["audits"] += 1
                try:
                    report = audit.run(spec.from_data(data, source=label))
                    json.dumps(report.to_dict(), allow_nan=False)
                    outcome[key] = "ok"
                except WtvibError:
                    outcome[key] = "input"
            counts[outcome[key]] += 1
        except WtvibError:
            counts["input"] += 1
        except TooSlowError:
            counts["slow"] += 1
            findings.append(f"SLOW >{LIMIT_S} s {label}")
        except Exception as exc:
            counts["crash"] += 1
            where = traceback.extract_tb(exc.__traceback__)[-1]
            findings.append(
                f"{label}: {type(exc).__name__}: {str(exc)[:120]} "
                f"@ {Path(where.filename).name}:{where.lineno}"
            )
        finally:
            signal.alarm(0)
        if time.perf_counter() - start > LIMIT_S:
            findings.append(f"SLOW {time.perf_counter() - start:.0f} s {label}")
    print(json.dumps(counts))
    print("\n".join(findings))
    sys.exit(1 if counts["crash"] or counts["slow"] else 0)


if __name__ == "__main__":
    main()
