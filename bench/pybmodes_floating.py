"""pyBModes' floating tower, run once to give tests/validation/test_floating.py its reference
numbers (tests/data/floating/pybmodes.json): the NREL 5-MW on the OC4-DeepCwind
semisubmersible as OpenFAST's regression tests hold it (r-test ``5MW_OC4Semi_MD_Linear``:
ElastoDyn, HydroDyn with the WAMIT files ``marin_semi.1``/``.hst``, MoorDyn moorings;
tests/data/openfast_decks/rtest_floating.tar.gz), solved free on its platform by
``Tower.from_elastodyn_with_mooring`` (pyBModes' platform matrices — its platform mass and
inertias, hydrostatics, added mass and MoorDyn stiffness — are stored beside its modes, so
that a difference can be traced to the matrix it comes from).

The OC3-Hywind spar (r-test ``5MW_OC3Spar_Linear``) too, with ``oc3``: its moorings are a
MAP++ file (one line type, repeated at 0, 120 and 240°), which pyBModes does not read, so
the script writes the same three lines as a MoorDyn file (:data:`OC3_MOORDYN`: MAP++'s
diameter, mass per metre, EA, unstretched length, anchor and fairlead) for pyBModes to
linearise. pyBModes has no crow's-foot yaw spring (OpenFAST's r-test deck has none either):
its yaw is not a reference.

Needs pyBModes (the bench extra: pip install 'wtvib[bench]'); run from the repository:

    python bench/pybmodes_floating.py > tests/data/floating/pybmodes.json
    python bench/pybmodes_floating.py oc3 > tests/data/floating/pybmodes_oc3.json
"""

import json
import sys
import tarfile
import tempfile
import warnings
from pathlib import Path

import numpy as np
import pybmodes
from pybmodes.models import Tower

ROOT = Path(__file__).resolve().parents[1]
CASES = {
    "oc4": "glue-codes/openfast/5MW_OC4Semi_MD_Linear",
    "oc3": "glue-codes/openfast/5MW_OC3Spar_Linear",
}
#: r-test's OC3 MAP++ moorings (NRELOffshrBsline5MW_OC3Hywind_MAP.dat: 'Material' 0.09 m,
#: 77.7066 kg/m, EA 384.243e6 N, 902.2 m from an anchor at 853.87 m, 320 m deep, to a
#: fairlead at 5.2 m, 70 m below the still water; repeated at 120 and 240°) as MoorDyn lines
OC3_MOORDYN = """--------------------- MoorDyn Input File ---------------------------------------
OC3-Hywind moorings from r-test's MAP++ file (bench/pybmodes_floating.py)
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA     BA/-zeta    EI    Cd     Ca    CdAx    CaAx
(name)     (m)     (kg/m)     (N)    (N-s/-)     (-)   (-)    (-)   (-)     (-)
main       0.09    77.7066  384.243E6  -1.0      0     1.6    1.0   0.1     0.0
---------------------- POINTS --------------------------------
ID     Attachment  X         Y         Z      M     V     CdA  CA
(#)    (-)         (m)       (m)       (m)    (kg)  (m^3) (m^2) (-)
1      Fixed      853.87     0.0     -320.0   0     0     0    0
2      Fixed     -426.935  739.473   -320.0   0     0     0    0
3      Fixed     -426.935 -739.473   -320.0   0     0     0    0
4      Vessel       5.2      0.0      -70.0   0     0     0    0
5      Vessel      -2.6      4.5033   -70.0   0     0     0    0
6      Vessel      -2.6     -4.5033   -70.0   0     0     0    0
---------------------- LINES --------------------------------------
ID    LineType  AttachA  AttachB  UnstrLen  NumSegs  Outputs
(#)   (name)    (#)      (#)      (m)       (-)      (-)
1     main      1        4        902.2     20       -
2     main      2        5        902.2     20       -
3     main      3        6        902.2     20       -
---------------------- OPTIONS -----------------------------------------
320       depth
9.80665   g
1025      rho
------------------------- need this line --------------------------------------
"""
FILES = {
    "oc3": (
        "NRELOffshrBsline5MW_OC3Hywind_ElastoDyn.dat",
        "OC3_MoorDyn.dat",
        "NRELOffshrBsline5MW_OC3Hywind_HydroDyn.dat",
    ),
    "oc4": (
        "NRELOffshrBsline5MW_OC4DeepCwindSemi_ElastoDyn.dat",
        "NRELOffshrBsline5MW_OC4DeepCwindSemi_MoorDyn.dat",
        "NRELOffshrBsline5MW_OC4DeepCwindSemi_HydroDyn.dat",
    ),
}


def main() -> None:
    warnings.simplefilter("ignore")
    which = sys.argv[1] if len(sys.argv) > 1 else "oc4"
    with tempfile.TemporaryDirectory() as tmp:
        with tarfile.open(ROOT / "tests/data/openfast_decks/rtest_floating.tar.gz") as tar:
            tar.extractall(tmp, filter="data")
        deck = Path(tmp) / CASES[which]
        if which == "oc3":
            (deck / "OC3_MoorDyn.dat").write_text(OC3_MOORDYN)
        tower = Tower.from_elastodyn_with_mooring(*(deck / f for f in FILES[which]))
        result = tower.run(n_modes=10, check_model=False)
        support = tower._bmi.support
        labels = list(getattr(result, "mode_labels", None) or [None] * len(result.shapes))
        out = {
            "tool": f"pyBModes {pybmodes.__version__}",
            "script": "bench/pybmodes_floating.py",
            "case": CASES[which],
            "call": "Tower.from_elastodyn_with_mooring(ElastoDyn, MoorDyn, HydroDyn)"
            ".run(n_modes=10, check_model=False)",
            "modes": [
                {"frequency_hz": round(float(s.freq_hz), 6), "label": labels[i]}
                for i, s in enumerate(result.shapes)
            ],
            "platform": {
                "mass_kg": float(support.mass_pform),
                "cm_below_msl_m": float(support.cm_pform),
                "inertia_at_cm": np.round(np.asarray(support.i_matrix), 1).tolist(),
                "added_mass": np.round(np.asarray(support.hydro_M), 1).tolist(),
                "hydrostatic_with_weight": np.round(np.asarray(support.hydro_K), 1).tolist(),
                "mooring": np.round(np.asarray(support.mooring_K), 1).tolist(),
            },
        }
    json.dump(out, sys.stdout, indent=1)
    print()


if __name__ == "__main__":
    main()
