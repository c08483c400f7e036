"""Property-based fuzzing of the readers hostile input attacked: OpenFAST ``.lin`` sets,
HAWCStab2 ``.cmb``/``.amp``/``.opt``, Campbell tables, output paths and batch discovery.

The invariant is the README's: a user's input ends in a typed wtvib error (one line, exit
2) or a report whose JSON is strict — never another exception (exit 3), never a hang
(each example bounded by the ``fuzz`` profile's deadline), bounded memory (``make fuzz``
runs under ``ulimit -v``); an output path is written or refused with an OutputError;
discovery returns a list whatever the folder holds. The inputs are OpenFAST's and
HAWCStab2's own files (tests/data, SOURCES.md there), mutated one to three places at a
time. CI runs a few examples per property (derandomised); ``make fuzz`` the campaign
recorded in tests/FUZZ.md.
"""

import atexit
import gzip
import json
import os
import shutil
import tempfile
from pathlib import Path
from typing import Any

from hypothesis import given, settings
from hypothesis import strategies as st

from wtvib import audit, importers, spec
from wtvib.errors import OutputError, WtvibError
from wtvib.outputs.files import write_atomic
from wtvib.workflows import batch

DATA = Path(__file__).parent / "data"
EXAMPLES = int(os.environ.get("WTVIB_FUZZ_READER_EXAMPLES", "25000"))
if os.environ.get("HYPOTHESIS_PROFILE", "ci") == "ci":
    EXAMPLES = 20

_WORK = Path(tempfile.mkdtemp(prefix="wtvib-fuzz-readers-"))
atexit.register(shutil.rmtree, _WORK, ignore_errors=True)  # not left in /tmp, a copy a run

#: What replaces a token: numbers at and past their limits, text, half numbers, quotes.
junk = st.sampled_from(
    [
        "abc", "nan", "-nan", "inf", "-inf", "0", "-1", "1e300", "-1e300", "1e-300", "2.7",
        "4.2E+", "T", "F", '"', "", "1" * 400, "0x10", "²", "\ufeff", "1,5", "9" * 30,
        "-0", "3", "1000000",
    ]
)  # fmt: skip


def _mutated(text: str, draw: Any) -> str:
    lines = text.splitlines(keepends=True)
    for _ in range(draw(st.integers(1, 3))):
        if not lines:
            break
        i = draw(st.integers(0, len(lines) - 1))
        action = draw(st.sampled_from(["token"] * 4 + ["delete", "double", "cut", "blank"]))
        if action == "delete":
            del lines[i]
        elif action == "double":
            lines.insert(i, lines[i])
        elif action == "cut":
            lines = [*lines[:i], lines[i][: draw(st.integers(0, len(lines[i])))]]
        elif action == "blank":
            lines[i] = "\n"
        else:
            tokens = lines[i].split()
            if tokens:
                tokens[draw(st.integers(0, len(tokens) - 1))] = draw(junk)
                lines[i] = " ".join(tokens) + "\n"
    return "".join(lines)


def _reject_constant(name: str) -> Any:
    raise AssertionError(f"the report's JSON holds {name}")


def _audit_cleanly(path: Path, **options: Any) -> None:
    """Import and audit: a typed error in one line, or a strict-JSON report."""
    try:
        data = importers.to_data(path, importers.ReadOptions(**options))
        report = audit.run(spec.from_data(data, source=str(path)))
    except WtvibError as exc:
        assert "\n" not in str(exc).strip(), "a wtvib error is one line"
        return
    assert report.verdict in ("pass", "warn", "fail")
    json.loads(json.dumps(report.to_dict()), parse_constant=_reject_constant)


# --- OpenFAST .lin ------------------------------------------------------------------------

#: small full-system files: first-order aerodynamic states (UA), a parked WindPACT, a
#: structural control on a platform
LIN_CASES = ("Fake5MW_AeroLin_B3_UA6", "WP_Stationary_Linear", "StC_test_OC4Semi_Linear_Tow")
_LIN = {c: gzip.decompress((DATA / "openfast_lin" / f"{c}.1.lin.gz").read_bytes()).decode()
        for c in LIN_CASES}  # fmt: skip


@st.composite
def lin_set(draw: Any) -> tuple[str, str, int]:
    case = draw(st.sampled_from(LIN_CASES))
    return case, _mutated(_LIN[case], draw), draw(st.integers(1, 2))


@settings(max_examples=EXAMPLES)
@given(lin_set())
def test_mutated_lin_files_fail_cleanly(case: tuple[str, str, int]):
    """One file mutated, read alone or as the first of a two-azimuth set beside the
    original."""
    name, text, files = case
    folder = _WORK / "lin"
    folder.mkdir(exist_ok=True)
    for old in folder.glob("*.lin"):
        old.unlink()
    (folder / "t.1.lin").write_text(text)
    if files == 2:
        (folder / "t.2.lin").write_text(_LIN[name])
    _audit_cleanly(folder / "t.1.lin", rpm=(10.0, 12.0))


# --- HAWCStab2 ----------------------------------------------------------------------------

_HS2 = DATA / "campbell" / "hawcstab2" / "iea15"
_HS2_FILES = {
    p.name.removesuffix(".gz"): gzip.decompress(p.read_bytes()).decode() for p in _HS2.glob("*.gz")
}


@st.composite
def hs2_set(draw: Any) -> tuple[str, str]:
    name = draw(st.sampled_from(sorted(_HS2_FILES)))
    return name, _mutated(_HS2_FILES[name], draw)


@settings(max_examples=EXAMPLES)
@given(hs2_set())
def test_mutated_hawcstab2_files_fail_cleanly(case: tuple[str, str]):
    name, text = case
    folder = _WORK / "hs2"
    folder.mkdir(exist_ok=True)
    for other, original in _HS2_FILES.items():
        (folder / other).write_text(text if other == name else original)
    cmb = "aeroelastic_entire_turbine.cmb" if "aeroelastic" in name else (
        "structural_entire_turbine.cmb"
    )  # fmt: skip
    _audit_cleanly(folder / cmb)


# --- Campbell tables ----------------------------------------------------------------------

cell = st.one_of(
    st.sampled_from(["tower.fa1", "blade.flap1.backward", "5", "0.3", "0.01", "fixed"]),
    junk,
    st.text(max_size=20),
)


@st.composite
def campbell_table(draw: Any) -> str:
    columns = draw(
        st.lists(
            st.sampled_from(
                ["mode", "rpm", "frequency_hz", "damping_ratio", "whirl", "frame",
                 "wind_m_s", "description", "pitch_deg", "method", "x"]
            ),
            min_size=1,
            max_size=8,
        )
    )  # fmt: skip
    rows = draw(st.lists(st.lists(cell, min_size=1, max_size=9), max_size=12))
    end = draw(st.sampled_from(["\n", "\r\n", "\r"]))
    quote = draw(st.sampled_from(["", '"']))
    lines = [",".join(columns)] + [quote + ",".join(r) for r in rows]
    return end.join(lines) + end


@settings(max_examples=EXAMPLES)
@given(campbell_table())
def test_random_campbell_tables_fail_cleanly(text: str):
    path = _WORK / "t.csv"
    path.write_text(text, encoding="utf-8", errors="surrogatepass")
    _audit_cleanly(path)


# --- outputs and discovery ----------------------------------------------------------------

name_part = st.one_of(
    st.text(
        alphabet=st.characters(blacklist_characters="/\x00", blacklist_categories=("Cs",)),
        min_size=1,
        max_size=40,
    ).filter(
        lambda t: t != ".."  # a step out of the scratch folder: not a case of this property
    ),
    st.sampled_from(["x" * 300, ".", " ", "é" * 130, "-"]),
)


@settings(max_examples=EXAMPLES)
@given(st.lists(name_part, min_size=1, max_size=3), st.booleans())
def test_output_paths_are_written_or_refused(parts: list[str], force: bool):
    """Any path under the scratch folder: written whole, or an OutputError — never another
    exception, never a file outside it."""
    target = _WORK.joinpath("out", *parts)
    try:
        written = write_atomic(target, b"data", force=force)
    except OutputError:
        return
    assert written.read_bytes() == b"data"
    assert _WORK in written.resolve().parents


@settings(max_examples=EXAMPLES)
@given(
    st.lists(
        st.tuples(
            st.lists(name_part, min_size=1, max_size=2),
            st.sampled_from([".yaml", ".dat", ".fst", ".lin", ".txt", ""]),
            st.sampled_from([b"", b"TwrFile x", b"EDFile y", b"\x00\xff", b"wtvib: 1\n"]),
        ),
        max_size=6,
    )
)
def test_discovery_returns_a_list_whatever_the_folder_holds(files: list[Any]):
    root = Path(tempfile.mkdtemp(dir=_WORK))
    for parts, suffix, content in files:
        path = root.joinpath(*parts[:-1], parts[-1] + suffix)
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_bytes(content)
        except OSError:  # a name the file system refuses: not a case
            continue
    found = batch.discover([root])
    assert all(isinstance(p, Path) for p in found)
