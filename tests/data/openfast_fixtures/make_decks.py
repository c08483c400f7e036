"""How the deck sets behind the .lin.gz files here were made (see SOURCES.md): r-test's two
AeroDyn linearisation fixtures (``Fake5MW_AeroLin_B3_UA6``, three blades, and
``Fake5MW_AeroLin_B1_UA4_DBEMT3``, one blade: the NREL 5-MW blade with its first flapwise
DOF only, a four-station AeroDyn blade, at 13 m/s and 12.1 rpm) brought to OpenFAST 5.0's
format, each in variants that separate ElastoDyn's blade discretisation from the
aerodynamics:

    python tests/data/openfast_fixtures/make_decks.py R_TEST/glue-codes/openfast OUT

=================  ==========  ========  ==============================================
variant            BldNodes    CompAero  what it shows
=================  ==========  ========  ==============================================
``n17``            17          2         the fixture with the 5-MW baseline's 17 nodes
``n17_structure``  17          0         the same without AeroDyn: the blade alone
``n3_structure``   3 (r-test)  0         r-test's fixture without AeroDyn
=================  ==========  ========  ==============================================

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
from make_decks import _aerodyn5, _elastodyn5, _fst5, setv  # noqa: E402

CASES = ("Fake5MW_AeroLin_B3_UA6", "Fake5MW_AeroLin_B1_UA4_DBEMT3")
#: variant → (BldNodes, CompAero)
VARIANTS = {"n17": (17, 2), "n17_structure": (17, 0), "n3_structure": (3, 0)}


def make(r_test: Path, out: Path, case: str, variant: str) -> Path:
    """``case`` in ``variant`` at ``out``/<case>_<variant> (its ``../5MW_Baseline`` the
    r-test files beside it)."""
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
