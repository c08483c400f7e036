"""pyBModes' soil-coupled monopile, run once to give tests/validation/test_soil_pybmodes.py its
reference numbers (tests/data/soil/pybmodes.json): the OC3 monopile deck (SubDyn pile under
the ElastoDyn tower, OpenFAST r-test, tests/data/openfast_decks/rtest.tar.gz) clamped, on
pyBModes' mudline coupled springs (Shadlou & Bhattacharya 2016; Psaroudakis et al. 2021 —
a Winkler pile in homogeneous soil), a 36 m embedded pile (OC3: 6 m × 60 mm, E 210 GPa) in
homogeneous soil of E_s 20, 50 and 100 MPa (ν 0.3), and a stiff-spring limit; Shadlou's
closed forms for the parabolic and linear profiles and rigid piles too.

Needs pyBModes (the bench extra: pip install 'wtvib[bench]'); run from the repository:

    python bench/pybmodes_soil.py > tests/data/soil/pybmodes.json
"""

import json
import math
import sys
import tarfile
import tempfile
import warnings
from pathlib import Path

import numpy as np
import pybmodes
from pybmodes import MudlineFoundation
from pybmodes.models import Tower

ROOT = Path(__file__).resolve().parents[1]
CASE = "glue-codes/openfast/5MW_OC3Mnpl_Linear"
PILE = {"diameter_m": 6.0, "wall_thickness_m": 0.06, "embedded_m": 36.0, "E_pa": 2.1e11}


def main() -> None:
    warnings.simplefilter("ignore")
    with tempfile.TemporaryDirectory() as tmp:
        with tarfile.open(ROOT / "tests/data/openfast_decks/rtest.tar.gz") as tar:
            tar.extractall(tmp, filter="data")
        deck = Path(tmp) / CASE
        ed = deck / "NRELOffshrBsline5MW_OC3Monopile_ElastoDyn.dat"
        sd = deck / "NRELOffshrBsline5MW_OC3Monopile_SubDyn.dat"

        def tower() -> Tower:
            return Tower.from_elastodyn_with_subdyn(ed, sd)

        d, t = PILE["diameter_m"], PILE["wall_thickness_m"]
        ei = PILE["E_pa"] * math.pi / 64 * (d**4 - (d - 2 * t) ** 4)
        tip = tower()._bmi.tip_mass
        out: dict = {
            "tool": f"pyBModes {pybmodes.__version__}",
            "script": "bench/pybmodes_soil.py",
            "pile": PILE,
            "tip_mass": {k: getattr(tip, k) for k in ("mass", "cm_axial", "ixx", "iyy", "izz")},
            "clamped_hub_conn_1": list(np.round(tower().run().frequencies[:4], 6)),
            "cases": [],
        }
        stiff = MudlineFoundation(
            K_hh=1e16, K_hr=0.0, K_rr=1e18, pile_behaviour="flexible",
            soil_profile="homogeneous", formula="shadlou",
        )  # fmt: skip
        out["stiff_springs"] = list(
            np.round(tower().attach_mudline_foundation(stiff).run().frequencies[:4], 6)
        )
        for soil_e in (20e6, 50e6, 100e6):
            for formula in ("shadlou", "psaroudakis"):
                f = MudlineFoundation.from_soil_properties(
                    pile_diameter=d, pile_length_embedded=PILE["embedded_m"], pile_EI=ei,
                    soil_E=soil_e, soil_nu=0.3, soil_profile="homogeneous", formula=formula,
                )  # fmt: skip
                freq = tower().attach_mudline_foundation(f).run().frequencies[:4]
                out["cases"].append(
                    {
                        "soil_E_pa": soil_e,
                        "formula": formula,
                        "behaviour": f.pile_behaviour,
                        "K_hh": f.K_hh,
                        "K_hr": f.K_hr,
                        "K_rr": f.K_rr,
                        "frequencies_hz": list(np.round(freq, 6)),
                    }
                )
    # Shadlou & Bhattacharya's closed forms for every soil profile and pile behaviour (the
    # coefficient table, Yu & Amdahl 2023 Table 1, as pyBModes holds it): the OC3 pile as
    # flexible, a 24 m pile (L/D = 4) as rigid, in soil of 50 MPa at one diameter's depth
    out["shadlou_closed_forms"] = []
    for embedded, behaviour in ((PILE["embedded_m"], "flexible"), (24.0, "rigid")):
        for profile in ("homogeneous", "parabolic", "linear"):
            f = MudlineFoundation.from_soil_properties(
                pile_diameter=d, pile_length_embedded=embedded, pile_EI=ei, soil_E=50e6,
                soil_nu=0.3, soil_profile=profile, pile_behaviour=behaviour, formula="shadlou",
            )  # fmt: skip
            out["shadlou_closed_forms"].append(
                {"embedded_m": embedded, "profile": profile, "behaviour": behaviour,
                 "soil_E_pa": 50e6, "K_hh": f.K_hh, "K_hr": f.K_hr, "K_rr": f.K_rr}
            )  # fmt: skip
    json.dump(out, sys.stdout, indent=1)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
