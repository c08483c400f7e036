"""How the deck set behind ``5MW_OC4Semi_Linear.1.lin.gz`` here was made (see SOURCES.md):
r-test's ``5MW_OC4Semi_Linear`` (the NREL 5-MW on the OC4 DeepCwind semisubmersible,
ElastoDyn, ServoDyn, HydroDyn with WAMIT's matrices and state-space radiation, MAP++'s
moorings, no AeroDyn) brought to OpenFAST 5.0's format and linearised as r-test does, once.

    python tests/data/openfast_oc4/make_deck.py R_TEST/glue-codes/openfast OUT [CASE]

(``CASE``: ``5MW_OC4Semi_MD_Linear`` for the same turbine on MoorDyn's lines, made alike.)

What changes from the r-test deck, and why:

* HydroDyn's wave excitation off (``ExctnMod`` 0; r-test's 2, a state-space model): the
  excitation's WAMIT file (``HydroData/marin_semi.3``) is not in the r-test snapshot this
  project has (HydroDyn opens it all the same: an empty file stands in); in still water
  (SeaState's ``WaveMod`` 0) the excitation is no force, its states driven by the waves
  alone;
* no inputs or outputs in the linearisation (``LinInputs``, ``LinOutputs`` 0): the state
  matrix A is the same;
* OpenFAST 5.0's new inputs at the values that keep the r-test model (the sweep's
  ``make_decks.py`` for the .fst, ElastoDyn and ServoDyn — its ``PitNeut`` at 0°, the
  pitch this deck's blades are held at —, the spar's ``make_deck.py`` for HydroDyn and
  SeaState, the member-based coefficient table kept as r-test has it).
"""

import shutil
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "openfast_sweep"))
sys.path.insert(0, str(HERE.parent / "openfast_spar36"))
from make_deck import _hydrodyn5, _sea_state5  # noqa: E402  (the spar's)
from make_decks import _elastodyn5, _fst5, _key, _servodyn5, setv  # noqa: E402

CASE = "5MW_OC4Semi_Linear"
STEM = "NRELOffshrBsline5MW_OC4DeepCwindSemi"


def _member_based(text: str) -> str:
    """HydroDyn's member-based coefficient table as OpenFAST 5 names it: the cylindrical
    members' (r-test's rows, which already carry MemberCb), an empty rectangular one."""
    lines = text.splitlines()
    i = next(i for i, x in enumerate(lines) if _key(x) == "NCoefMembers")
    n = int(lines[i].split()[0])
    new = [f"            {n}   NCoefMembersCyl - (-)", *lines[i + 1 : i + 3 + n]]
    new += ["---- RECTANGULAR ----", "             0   NCoefMembersRec - (-)", "...", "..."]
    return "\n".join([*lines[:i], *new, *lines[i + 3 + n :]]) + "\n"


def _hydrodyn(text: str) -> str:
    return setv(_hydrodyn5(_member_based(text)), "ExctnMod", "0")


def _fst(text: str) -> str:
    text = _fst5(text)
    for key in ("LinInputs", "LinOutputs"):
        text = setv(text, key, "0")
    return text


def make(r_test: Path, out: Path, name: str = CASE) -> Path:
    """The deck set ``name`` (r-test's ``5MW_OC4Semi_Linear``, or ``5MW_OC4Semi_MD_Linear``:
    the same turbine on MoorDyn's lines, its MoorDyn file as r-test has it) in ``out``."""
    case = out / "glue-codes" / "openfast" / name
    shutil.copytree(r_test / name, case, dirs_exist_ok=True)
    for file, change in (
        (f"{name}.fst", _fst),
        (f"{STEM}_ElastoDyn.dat", _elastodyn5),
        (f"{STEM}_ServoDyn.dat", lambda t: _servodyn5(t, 0.0)),
        (f"{STEM}_HydroDyn.dat", _hydrodyn),
        ("SeaState.dat", _sea_state5),
    ):
        path = case / file
        path.write_text(change(path.read_text()))
    return case


if __name__ == "__main__":
    print(make(Path(sys.argv[1]), Path(sys.argv[2]), *sys.argv[3:4]))
