"""How the deck set behind the ``.lin.gz`` files here was made (see SOURCES.md): r-test's
``5MW_Land_BD_Linear_Aero`` (the onshore NREL 5-MW with BeamDyn blades, AeroDyn 15 at a
steady 8 m/s, ServoDyn without a torque law) brought to OpenFAST 5.0's format, settled and
linearised over one revolution.

    python tests/data/openfast_bd_aero/make_deck.py R_TEST/glue-codes/openfast OUT [elastodyn]

(``elastodyn``: the same deck set with ElastoDyn's blades in BeamDyn's place — ``CompElast``
1, the ElastoDyn file's own blade file, ``NRELOffshrBsline5MW_Blade.dat`` of
``5MW_Baseline``, beside it, OpenFAST's loose coupling — the third reference that tells the
BeamDyn blade's part.)

What changes from the r-test deck, and why:

* linearised at 12 azimuths over one revolution after 30 s (``LinTimes`` 30 … 34.55 s,
  every 0.413 s at 12.1 rpm), where r-test linearises once at 1 s, mid-transient: MBC3
  then averages the periodic terms, and the start's transient has died out;
* the generator held at the deck's 12.1 rpm (ElastoDyn's ``GenDOF`` off): the deck has no
  torque law (ServoDyn's ``VSContrl`` 0), and its rotor, free, speeds up under the 8 m/s
  wind — 12.24 rpm at r-test's 1 s, more by 30 s; wtvib reads the deck's switches as
  OpenFAST does (``--deck-dofs``), so the comparison stays like for like;
* OpenFAST 5's tight coupling at 0.01 s (``ModCoupling`` 3, ``RhoInf`` 0, ``MaxConvIter``
  20, as ``../openfast_sweep``'s BeamDyn runs), where r-test's loose coupling needs
  0.0015 s; no inputs or outputs in the linearisation (``LinInputs``, ``LinOutputs`` 0) and
  no module-level files (``LinOutMod``): the state matrix A is the same;
* OpenFAST 5.0's new inputs at the values that keep the r-test model (the sweep's
  ``make_decks.py`` for the .fst, ElastoDyn, AeroDyn and ServoDyn); BeamDyn's pitch
  actuator block (unused: ``UsePitchAct`` false) left out of its main file and its blade
  file given the modal-damping lines OpenFAST 5 reads (unused: ``damp_type`` 1).
"""

import re
import shutil
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "openfast_sweep"))
from make_decks import _aerodyn5, _elastodyn5, _fst5, _servodyn5, setv  # noqa: E402

CASE = "5MW_Land_BD_Linear_Aero"
RPM = 12.1
AZIMUTHS = 12
SETTLED_S = 30.0


def _fst(text: str) -> str:
    for key in ("LinInputs", "LinOutputs"):  # r-test's "1, 0": a list, one value kept
        text = re.sub(rf"^.*\b{key}\b", f"          0   {key}", text, count=1, flags=re.M)
    text = _fst5(text)
    period = 60 / RPM
    times = ", ".join(f"{SETTLED_S + period * k / AZIMUTHS:.4f}" for k in range(AZIMUTHS))
    for key, value in {
        "DT": "0.01", "ModCoupling": "3", "RhoInf": "0.0", "MaxConvIter": "20",
        "DT_UJac": "99999", "NumCrctn": "0", "LinOutJac": "False", "LinOutMod": "False",
        "TMax": f"{SETTLED_S + period * (AZIMUTHS - 1) / AZIMUTHS + 0.02:.3f}",
        "NLinTimes": str(AZIMUTHS), "LinTimes": times,
    }.items():  # fmt: skip
        text = setv(text, key, value)
    return text


def _beamdyn(text: str) -> str:
    """BeamDyn's main file without the pitch actuator block (OpenFAST 5 has none)."""
    return re.sub(r"-+ PITCH ACTUATOR PARAMETERS -+\r?\n(?:.*\n){4}", "", text)


def _beamdyn_blade(text: str) -> str:
    lines = text.splitlines()
    at = next(i for i, x in enumerate(lines) if "damp_type" in x) + 5  # after mu1 … mu6
    new = [
        " ---------------------- Modal Damping [used only if damp_type=2] ---------",
        " 1   n_modes - Number of modal damping coefficients (-)",
        " 0.0  zeta - Damping coefficients for mode 1 through n_modes",
    ]
    return "\n".join([*lines[:at], *new, *lines[at:]]) + "\n"


def make(r_test: Path, out: Path, blades: str = "beamdyn") -> Path:
    root = out / "glue-codes" / "openfast"
    case = root / CASE
    shutil.copytree(r_test / CASE, case, dirs_exist_ok=True)
    shutil.copytree(r_test / "5MW_Baseline", root / "5MW_Baseline", dirs_exist_ok=True)
    if blades == "elastodyn":
        shutil.copy(root / "5MW_Baseline/NRELOffshrBsline5MW_Blade.dat", case)
        fst = case / f"{CASE}.fst"
        fst.write_text(setv(fst.read_text(), "CompElast", "1"))
    for path, change in (
        (case / f"{CASE}.fst", _fst),
        (case / "NRELOffshrBsline5MW_Onshore_ElastoDyn_BDoutputs.dat",
         lambda t: setv(_elastodyn5(t), "GenDOF", "False")),
        (case / "NRELOffshrBsline5MW_Onshore_AeroDyn.dat", _aerodyn5),
        (case / "NRELOffshrBsline5MW_Onshore_ServoDyn.dat", lambda t: _servodyn5(t, 0.0)),
        (root / "5MW_Baseline/NRELOffshrBsline5MW_BeamDyn.dat", _beamdyn),
        (root / "5MW_Baseline/NRELOffshrBsline5MW_BeamDyn_Blade.dat", _beamdyn_blade),
    ):  # fmt: skip
        path.write_text(change(path.read_text()))
    if blades == "elastodyn":  # loose coupling, as r-test's ElastoDyn decks
        fst = case / f"{CASE}.fst"
        fst.write_text(setv(fst.read_text(), "ModCoupling", "2"))
    return case


if __name__ == "__main__":
    print(make(Path(sys.argv[1]), Path(sys.argv[2]), *sys.argv[3:4]))
