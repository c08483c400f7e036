"""How the deck sets behind the ``.lin.gz`` files here were made (see SOURCES.md): the
IEA-15 on the UMaine VolturnUS-S (IEAWindTask37/IEA-15-240-RWT, ``OpenFAST/
IEA-15-240-RWT-UMaineSemi``, written for OpenFAST 3.x) brought to OpenFAST 5.0's format, its
structure alone linearised: ElastoDyn, HydroDyn (WAMIT's added mass and hydrostatics) and
MAP++'s moorings, no AeroDyn, no ServoDyn.

    python tests/data/openfast_iea15semi/make_deck.py IEA15_REPO OC4_DECK OUT

``IEA15_REPO``: a checkout of IEAWindTask37/IEA-15-240-RWT (its ``OpenFAST`` folder);
``OC4_DECK``: r-test's OC4 semisubmersible deck set as ``../openfast_oc4/make_deck.py``
makes it — OpenFAST 5.0's input files, whose layout the IEA-15's values are written into.
Three deck sets are made in ``OUT``:

* ``deck``: the deck's structure as it is, parked (0 rpm, the generator free, ElastoDyn's
  DOF switches as the deck sets them: drive train and yaw rigid);
* ``shapes``: the same with the tower and blade mode-shape polynomials wtvib computes for
  the deck (``wtvib shapes DECK -o``) in place of the deck's;
* ``rated``: ``shapes`` turning at the rated 7.56 rpm, linearised at 12 azimuths over one
  revolution (MBC3 then averages the periodic terms a single azimuth keeps).

What changes from the IEA deck, and why:

* every ElastoDyn value of the deck written into OpenFAST 5.0's ElastoDyn file (the inputs
  OpenFAST 5 added at the values that keep the model: no pitch DOF, no pitch-bearing or
  teeter inertia, no yaw friction, the platform's products of inertia 0); no gauges;
* HydroDyn: WAMIT's potential flow alone, as the deck has it (no Morison members), its
  infinite-frequency added mass and hydrostatics (``RdtnMod`` 0: no radiation memory; in
  still water, SeaState's ``WaveMod`` 0, ``ExctnMod`` 0 — HydroDyn opens WAMIT's excitation
  file all the same: an empty ``.3`` stands in); the deck's quadratic drag (``AddBQuad``)
  is no force at rest and is left out;
* the moorings: the deck set's MAP++ file (``IEA-15-240-RWT-UMaineSemi_MAP.dat``, the same
  three chains as its MoorDyn file, which wtvib reads), quasi-static as wtvib's mooring
  stiffness — MoorDyn's lines would add their own dynamic states;
* gravity 9.81 m/s², water depth 200 m (the deck's); no inputs or outputs in the
  linearisation (``LinInputs``, ``LinOutputs`` 0): the state matrix A is the same.
"""

import contextlib
import shutil
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "openfast_sweep"))
from make_decks import _key, setv  # noqa: E402

SEMI = "IEA-15-240-RWT-UMaineSemi"
OC4 = "NRELOffshrBsline5MW_OC4DeepCwindSemi"
RATED_RPM = 7.56
AZIMUTHS = 12
#: ElastoDyn inputs not taken from the deck: its outputs, and the blade and tower files
#: (named below)
_NOT_TAKEN = {"Echo", "NBlGages", "BldGagNd", "NTwGages", "TwrGagNd", "BldNd_BladesOut",
              "BldNd_BlOutNd", "OutList"}  # fmt: skip


def _values(text: str) -> dict[str, str]:
    """A v3 input file's one-value lines, key → value as written (first occurrence)."""
    out: dict[str, str] = {}
    for line in text.splitlines():
        parts = line.split()
        if len(parts) > 1 and not line.lstrip().startswith("--"):
            out.setdefault(parts[1], parts[0])
    return out


def _elastodyn(deck: str, layout: str, rpm: float) -> str:
    values = _values(deck)
    values.update({f"BldFile({b})": '"blade.dat"' for b in (1, 2, 3)})
    values.update({"TwrFile": '"tower.dat"', "RotSpeed": f"{rpm:g}"})
    text = layout
    for key, value in values.items():
        if key not in _NOT_TAKEN:
            # not in OpenFAST 5's layout: the deck's BldFile1..3 (renamed), its title words
            with contextlib.suppress(KeyError):
                text = setv(text, key, value)
    return setv(setv(text, "NBlGages", "0"), "NTwGages", "0")


def _hydrodyn(layout: str) -> str:
    """OC4's OpenFAST 5 HydroDyn file with WAMIT's potential flow alone (the IEA deck's)."""
    lines = layout.splitlines()
    out, i = [], 0
    while i < len(lines):
        line, key = lines[i], _key(lines[i])
        if key in ("NJoints", "NPropSetsCyl", "NCoefMembersCyl", "NMembers", "NFillGroups"):
            count = line.split()[0]
            out += [line.replace(count, "0", 1), lines[i + 1], lines[i + 2]]
            i += 3 + int(count)
            continue
        out.append(line)
        i += 1
    text = "\n".join(out) + "\n"
    for key, value in {
        "PotMod": "1", "ExctnMod": "0", "RdtnMod": "0", "PotFile": f'"HydroData/{SEMI}"',
        "WAMITULEN": "1", "PtfmVol0": "20206.34889", "PtfmCOBxt": "0", "PtfmCOByt": "0",
        "NJOutputs": "0",
    }.items():  # fmt: skip
        text = setv(text, key, value)
    return text


def _fst(layout: str, rpm: float) -> str:
    text = layout
    for key, value in {
        "EDFile": '"ElastoDyn.dat"', "HydroFile": '"HydroDyn.dat"', "SeaStFile": '"SeaState.dat"',
        "MooringFile": '"MAP.dat"', "CompServo": "0", "ServoFile": '"unused"',
        "Gravity": "9.81", "WtrDpth": "200", "DT": "0.01", "TMax": "0.1",
        "LinInputs": "0", "LinOutputs": "0",
    }.items():  # fmt: skip
        text = setv(text, key, value)
    if rpm > 0:  # AZIMUTHS linearisations over one revolution
        period = 60 / rpm
        times = ", ".join(f"{period * k / AZIMUTHS:.4f}" for k in range(AZIMUTHS))
        text = setv(text, "TMax", f"{period * (AZIMUTHS - 1) / AZIMUTHS + 0.05:.3f}")
        text = setv(setv(text, "NLinTimes", str(AZIMUTHS)), "LinTimes", times)
    return text


def make(repo: Path, oc4: Path, out: Path) -> list[Path]:
    deck = repo / "OpenFAST" / SEMI
    shapes = out / "wtvib-shapes"
    subprocess.run(
        ["wtvib", "shapes", str(deck / f"{SEMI}.fst"), "-o", str(shapes), "--no-plots"],
        check=True,
    )
    made = []
    for name, rpm, polynomials in (("deck", 0.0, False), ("shapes", 0.0, True),
                                   ("rated", RATED_RPM, True)):  # fmt: skip
        case = out / name
        (case / "HydroData").mkdir(parents=True, exist_ok=True)
        main = (deck / f"{SEMI}_ElastoDyn.dat").read_text()
        layout = (oc4 / f"{OC4}_ElastoDyn.dat").read_text()
        (case / "ElastoDyn.dat").write_text(_elastodyn(main, layout, rpm))
        tower = deck / f"{SEMI}_ElastoDyn_tower.dat"
        blade = repo / "OpenFAST/IEA-15-240-RWT/IEA-15-240-RWT_ElastoDyn_blade.dat"
        if polynomials:
            tower, blade = shapes / tower.name, shapes / blade.name
        shutil.copy(tower, case / "tower.dat")
        shutil.copy(blade, case / "blade.dat")
        (case / "HydroDyn.dat").write_text(_hydrodyn((oc4 / f"{OC4}_HydroDyn.dat").read_text()))
        for ext in ("1", "hst"):
            shutil.copy(deck / f"HydroData/{SEMI}.{ext}", case / "HydroData")
        (case / f"HydroData/{SEMI}.3").write_text("")
        sea = setv((oc4 / "SeaState.dat").read_text(), "WaveMod", "0")
        (case / "SeaState.dat").write_text(sea)
        shutil.copy(deck / f"{SEMI}_MAP.dat", case / "MAP.dat")
        fst = _fst((oc4 / "5MW_OC4Semi_Linear.fst").read_text(), rpm)
        (case / f"{name}.fst").write_text(fst)
        made.append(case)
    return made


if __name__ == "__main__":
    for case in make(Path(sys.argv[1]), Path(sys.argv[2]), Path(sys.argv[3])):
        print(case)
