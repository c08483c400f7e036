"""How the deck set behind the ``.lin.gz`` files here was made (see SOURCES.md): r-test's
``5MW_OC3Spar_Linear`` (the NREL 5-MW on the OC3 Hywind spar, ElastoDyn, HydroDyn with
WAMIT's matrices, MAP++'s moorings, no AeroDyn, no ServoDyn) linearised at 36 azimuths
over one revolution instead of r-test's one, its inputs brought to OpenFAST 5.0's format.

    python tests/data/openfast_spar36/make_deck.py R_TEST/glue-codes/openfast OUT

What changes from the r-test deck, and why:

* 36 linearisations over one revolution at 12.1 rpm (``NLinTimes``, ``LinTimes`` every
  0.1375 s, ``TMax`` 4.85 s): MBC3 then averages the periodic terms a single azimuth keeps;
* no inputs or outputs in the linearisation (``LinInputs``, ``LinOutputs`` 0) and HydroDyn's
  Morison members in 10 m elements (``MDivSize``; r-test's 0.5 m): the state matrix A is
  the same (the members are potential-flow members, ``PropPot`` TRUE, with no added mass,
  ``Ca`` 0, and a quadratic drag that linearises to nothing at rest), and a linearisation
  takes 2 s instead of 5 minutes;
* OpenFAST 5.0's new inputs at the values that keep the r-test model (the sweep's
  ``make_decks.py`` for the .fst and ElastoDyn); HydroDyn's (``PtfmYMod`` 0, ``PtfmRefY`` 0,
  ``PtfmYCutOff``, ``NExctnHdg`` — unused with ``PtfmYMod`` 0 —, ``NAddDOF`` 0, ``HstMod`` 0,
  the cylindrical members' tables renamed and the rectangular members' tables empty, each
  member a circle, ``MSecGeom`` 1, ``MSpinOrient`` 0) and SeaState's ``WvCrntMod`` 0, read
  against OpenFAST 5.0's ``HydroDyn_Input.f90`` and ``SeaState_Input.f90``.
"""

import shutil
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "openfast_sweep"))
from make_decks import _elastodyn5, _fst5, _insert, _key, setv

CASE = "5MW_OC3Spar_Linear"
HYDRO = "NRELOffshrBsline5MW_OC3Hywind_HydroDyn.dat"
TIMES = ", ".join(f"{0.1375 * k:g}" for k in range(36))
#: the rectangular members' simple coefficients (none here): Cd, Ca 0, Cp 1, axial Cp 1, Cb 0
RECTANGLE = ["0.0"] * 8 + ["1.0", "1.0"] + ["0.0"] * 4 + ["1.0", "1.0", "0.0", "0.0"]


def _fst(text: str) -> str:
    text = setv(_fst5(text), "TMax", "4.85")
    text = setv(text, "NLinTimes", "36")
    text = setv(text, "LinTimes", TIMES)
    for key in ("LinInputs", "LinOutputs"):
        text = setv(text, key, "0")
    return text


def _hydrodyn5(text: str) -> str:
    lines = text.splitlines()
    lines = _insert(
        lines,
        [
            "             0   PtfmYMod       - (switch)",
            "             0   PtfmRefY       - (deg)",
            "          0.01   PtfmYCutOff    - (Hz)",
            "            36   NExctnHdg      - (-)",
        ],
        after="ExctnCutOff",
    )
    lines = _insert(lines, ["             0   NAddDOF        - (-)"], after="PtfmCOByt")
    lines = _insert(lines, ["             0   HstMod         - (switch)"], after="AMMod")
    out: list[str] = []
    i = 0
    while i < len(lines):
        line, key = lines[i], _key(lines[i])
        if key == "NPropSets":
            n = int(line.split()[0])
            out += [line.replace("NPropSets", "NPropSetsCyl", 1), *lines[i + 1 : i + 3 + n]]
            out += ["---- RECTANGULAR MEMBER CROSS-SECTION PROPERTIES ----",
                    "             0   NPropSetsRec   - (-)",
                    "PropSetID PropA PropB PropThck", "(-) (m) (m) (m)"]  # fmt: skip
            i += 3 + n
            continue
        if line.startswith("---------------------- SIMPLE HYDRODYNAMIC"):
            row = lines[i + 3].split()
            out += [line, lines[i + 1], lines[i + 2], "  ".join([*row[:12], "1.00", "1.00"])]
            out += ["---- SIMPLE RECTANGULAR-MEMBER HYDRODYNAMIC COEFFICIENTS ----",
                    "SimplCdA ... SimplCbMG", " ".join(["(-)"] * 18),
                    " ".join(RECTANGLE)]  # fmt: skip
            i += 4
            continue
        if key in ("NCoefDpth", "NCoefMembers"):
            assert int(line.split()[0]) == 0, "only empty tables are converted"
            out += [f"             0   {key}Cyl - (-)", lines[i + 1], lines[i + 2]]
            out += ["---- RECTANGULAR ----", f"             0   {key}Rec - (-)", "...", "..."]
            i += 3
            continue
        if key == "NMembers":
            n = int(line.split()[0])
            out += [line, lines[i + 1], lines[i + 2]]
            for row in lines[i + 3 : i + 3 + n]:
                c = row.split()
                c[5] = "10.0"  # MDivSize
                out.append("  ".join([*c[:5], "1", "0", *c[5:9]]))
            i += 3 + n
            continue
        out.append(line)
        i += 1
    return "\n".join(out) + "\n"


def make(r_test: Path, out: Path) -> Path:
    case = out / "glue-codes" / "openfast" / CASE
    shutil.copytree(r_test / CASE, case, dirs_exist_ok=True)
    for name, change in (
        (f"{CASE}.fst", _fst),
        ("NRELOffshrBsline5MW_OC3Hywind_ElastoDyn.dat", _elastodyn5),
        (HYDRO, _hydrodyn5),
    ):
        path = case / name
        path.write_text(change(path.read_text()))
    sea = case / "SeaState.dat"
    sea.write_text(_sea_state5(sea.read_text()))
    return case


def _sea_state5(text: str) -> str:
    """SeaState's new ``WvCrntMod`` (0: waves and current superposed, as before)."""
    lines = text.splitlines()
    mod = next(i for i, x in enumerate(lines) if _key(x) == "WaveStMod")
    new = ["             0   WvCrntMod      - (switch)"]
    return "\n".join([*lines[: mod + 1], *new, *lines[mod + 1 :]]) + "\n"


if __name__ == "__main__":
    print(make(Path(sys.argv[1]), Path(sys.argv[2])))
