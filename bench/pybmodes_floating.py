"""pyBModes' floating tower, run once to give tests/validation/test_floating.py its reference
numbers (tests/data/floating/pybmodes.json): the NREL 5-MW on the OC4-DeepCwind
semisubmersible as OpenFAST's regression tests hold it (r-test ``5MW_OC4Semi_MD_Linear``:
ElastoDyn, HydroDyn with the WAMIT files ``marin_semi.1``/``.hst``, MoorDyn moorings;
tests/data/openfast_decks/rtest_floating.tar.gz), solved free on its platform by
``Tower.from_elastodyn_with_mooring`` (pyBModes' platform matrices — its platform mass and
inertias, hydrostatics, added mass and MoorDyn stiffness — are stored beside its modes, so
that a difference can be traced to the matrix it comes from).

Needs pyBModes (the bench extra: pip install 'wtvib[bench]'); run from the repository:

    python bench/pybmodes_floating.py > tests/data/floating/pybmodes.json
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
CASE = "glue-codes/openfast/5MW_OC4Semi_MD_Linear"
FILES = (
    "NRELOffshrBsline5MW_OC4DeepCwindSemi_ElastoDyn.dat",
    "NRELOffshrBsline5MW_OC4DeepCwindSemi_MoorDyn.dat",
    "NRELOffshrBsline5MW_OC4DeepCwindSemi_HydroDyn.dat",
)


def main() -> None:
    warnings.simplefilter("ignore")
    with tempfile.TemporaryDirectory() as tmp:
        with tarfile.open(ROOT / "tests/data/openfast_decks/rtest_floating.tar.gz") as tar:
            tar.extractall(tmp, filter="data")
        deck = Path(tmp) / CASE
        tower = Tower.from_elastodyn_with_mooring(*(deck / f for f in FILES))
        result = tower.run(n_modes=10, check_model=False)
        support = tower._bmi.support
        labels = list(getattr(result, "mode_labels", None) or [None] * len(result.shapes))
        out = {
            "tool": f"pyBModes {pybmodes.__version__}",
            "script": "bench/pybmodes_floating.py",
            "case": CASE,
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
