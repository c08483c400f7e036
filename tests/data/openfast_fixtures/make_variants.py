"""How the deck sets behind the .lin.gz files here were made (see SOURCES.md): r-test's two
AeroDyn linearisation fixtures (``Fake5MW_AeroLin_B3_UA6``, three blades, and
``Fake5MW_AeroLin_B1_UA4_DBEMT3``, one blade: the NREL 5-MW blade with its first flapwise
DOF only, a four-station AeroDyn blade, at 13 m/s and 12.1 rpm) brought to OpenFAST 5.0's
format, each in variants that separate ElastoDyn's blade discretisation from the
aerodynamics:

    python tests/data/openfast_fixtures/make_variants.py R_TEST/glue-codes/openfast OUT

=========================  ==========  ========  ======================================
variant                    BldNodes    CompAero  what it shows
=========================  ==========  ========  ======================================
``n17``                    17          2         the fixture with the 5-MW deck's 17 nodes
``n17_structure``          17          0         the same without AeroDyn: the blade alone
``n3_structure``           3 (r-test)  0         r-test's fixture without AeroDyn
``settled``                17          2         ``n17`` linearised at 60 s, not 1.1 s: the
                                                 blades settled (both fixtures)
``settled_qs``             17          2         … its aerofoils quasi-steady (UA_Mod 0;
                                                 the three-bladed fixture, as below)
``settled_qs_frozen``      17          2         … and its wake frozen (DBEMT_Mod −1)
``settled_qs_frozen_tip``  17          2         … and its last node's chord 1 mm
=========================  ==========  ========  ======================================

The settled variants separate AeroDyn's parts of the flap damping: the blades' swing at
1.1 s, the separation's lag, the induction's answer, the last node's load. ``tip`` applies
to any deck set (``tip_chord``): r-test's 5-MW sweep deck at 16 m/s with its last AeroDyn
node's chord 1 mm is ``ED_16_tip`` (``../openfast_sweep/make_decks.py`` first).

The fixtures integrate the blade over three ElastoDyn nodes (``BldNodes`` 3, "to limit the
size of the matrices", their README), where the NREL 5-MW's own deck has 17; the midpoint
rule over three elements gives the blade's first flap another frequency. Nothing else
changes: no inputs or outputs in the linearisation (``LinInputs``, ``LinOutputs`` 0; the
state matrix A is the same), OpenFAST 5.0's new inputs at the values that keep the r-test
model (``../openfast_sweep/make_decks.py``).
"""

import shutil
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "openfast_sweep"))
from make_decks import _aerodyn5, _elastodyn5, _fst5, _key, setv  # noqa: E402

CASES = ("Fake5MW_AeroLin_B3_UA6", "Fake5MW_AeroLin_B1_UA4_DBEMT3")
#: variant → (BldNodes, CompAero)
VARIANTS = {"n17": (17, 2), "n17_structure": (17, 0), "n3_structure": (3, 0)}
#: the settled variants of the three-bladed fixture → AeroDyn's changed inputs
SETTLED = {
    "settled": {},
    "settled_qs": {"UA_Mod": "0"},
    "settled_qs_frozen": {"UA_Mod": "0", "DBEMT_Mod": "-1"},
    "settled_qs_frozen_tip": {"UA_Mod": "0", "DBEMT_Mod": "-1"},
}


def tip_chord(blade: Path, chord: str = "1.0E-03") -> None:
    """The AeroDyn blade file's last node (the BlNumNd-th row) with its chord ``chord``."""
    lines = blade.read_text().splitlines()
    n = next(int(x.split()[0]) for x in lines if _key(x) == "NumBlNds")
    start = next(i for i, x in enumerate(lines) if _key(x) == "NumBlNds") + 3
    cells = lines[start + n - 1].split()
    cells[5] = chord
    lines[start + n - 1] = "  " + "  ".join(cells)
    blade.write_text("\n".join(lines) + "\n")


def make(r_test: Path, out: Path, case: str, variant: str) -> Path:
    """``case`` in ``variant`` at ``out``/<case>_<variant> (its ``../5MW_Baseline`` the
    r-test files beside it)."""
    if variant in SETTLED:
        fst = make(r_test, out, case, "n17")
        d = fst.parent.rename(out / f"{case}_{variant}")
        fst = d / fst.name
        text = fst.read_text()
        for key in ("TMax", "LinTimes"):
            text = setv(text, key, "60.0")
        fst.write_text(text)
        ad = d / "AD.dat"
        text = ad.read_text()  # the AeroDyn file's name is the same in both fixtures
        for key, value in SETTLED[variant].items():
            text = setv(text, key, value)
        ad.write_text(text)
        if variant.endswith("_tip"):
            tip_chord(d / "AD_blade_4stations.dat")
        return fst
    nodes, aero = VARIANTS[variant]
    d = out / f"{case}_{variant}"
    shutil.copytree(r_test / case, d, dirs_exist_ok=True)
    for old in d.glob("*.lin"):
        old.unlink()
    fst = d / f"{case}.fst"
    text = _fst5(fst.read_text())
    for key, value in (("LinInputs", "0"), ("LinOutputs", "0"), ("CompAero", str(aero))):
        text = setv(text, key, value)
    fst.write_text(text)
    ed = d / "ED.dat"
    ed.write_text(setv(_elastodyn5(ed.read_text()), "BldNodes", str(nodes)))
    ad = d / "AD.dat"
    ad.write_text(_aerodyn5(ad.read_text()))
    return fst


if __name__ == "__main__":
    for c in CASES:
        for v in VARIANTS:
            print(make(Path(sys.argv[1]), Path(sys.argv[2]), c, v))
    for v in SETTLED:
        print(make(Path(sys.argv[1]), Path(sys.argv[2]), CASES[0], v))
    print(make(Path(sys.argv[1]), Path(sys.argv[2]), CASES[1], "settled"))
