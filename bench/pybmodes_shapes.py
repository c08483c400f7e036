"""pyBModes' ElastoDyn mode shapes, run once to give tests/validation/test_polynomials.py its
side-by-side numbers (tests/data/polynomials/pybmodes.json): for each ElastoDyn deck of
../shared/reference (NREL 5-MW onshore, IEA-3.4, IEA-10), pyBModes' tower (``Tower.
from_elastodyn``: clamped, its tower-top mass from the deck) and rotating blade
(``RotatingBlade.from_elastodyn``: at the deck's RotSpeed) — the tip mass it derives, the
frequencies of the modes its ElastoDyn report selects for each coefficient set, and the
coefficients (``compute_tower_params_report``, ``compute_blade_params``). The tower once
more on pyBModes' soft-monopile path (``attach_mudline_foundation``, ``hub_conn = 3``) on
springs a thousand times stiffer than any soil: there the tip mass's height above the
tower top couples its translation and rotation, which its clamped path (``hub_conn = 1``)
carries as a sideways lever arm instead (pyBModes ``fem/nondim.py``). The blade once more
with its table interpolated linearly (as ElastoDyn interpolates it) onto 241 stations:
pyBModes' elements are the deck's stations, their properties sampled at the midpoints, and
its second flap frequency moves with that mesh by up to 1 %.

Needs pyBModes (the bench extra: pip install 'wtvib[bench]') and ../shared beside the
clone; run from the repository:

    python bench/pybmodes_shapes.py > tests/data/polynomials/pybmodes.json
"""

import json
import re
import shutil
import tempfile
import warnings
from pathlib import Path

import numpy as np
import pybmodes
from pybmodes import MudlineFoundation
from pybmodes.elastodyn.params import compute_blade_params, compute_tower_params_report
from pybmodes.models import RotatingBlade, Tower

ROOT = Path(__file__).resolve().parents[1]
REFERENCE = ROOT.parent / "shared" / "reference"
DECKS = {
    "NREL5MW": "NREL5MW/NRELOffshrBsline5MW_Onshore_ElastoDyn.dat",
    "IEA3.4": "IEA3.4/IEA-3.4-130-RWT_ElastoDyn.dat",
    "IEA10": "IEA10/IEA-10.0-198-RWT_ElastoDyn.dat",
}
TOWER_SETS = ("TwFAM1Sh", "TwFAM2Sh", "TwSSM1Sh", "TwSSM2Sh")
BLADE_SETS = ("BldFl1Sh", "BldFl2Sh", "BldEdgSh")


def _coefficients(fit) -> list[float]:  # type: ignore[no-untyped-def]
    return [round(float(c), 9) for c in fit.coefficients()]


def _refined(path: Path, stations: int) -> Path:
    """A copy of the deck set whose blade table is interpolated onto ``stations``."""
    folder = Path(tempfile.mkdtemp())
    for f in path.parent.iterdir():
        if f.is_file():
            shutil.copy(f, folder / f.name)
    main = (folder / path.name).read_text()
    blade = folder / re.search(r'"([^"]+)"\s+BldFile\(?1\)?', main).group(1)  # type: ignore[union-attr]
    lines = blade.read_text().splitlines(keepends=True)
    head = next(i for i, ln in enumerate(lines) if ln.split()[:1] == ["BlFract"])
    end = head + 2
    while (
        end < len(lines) and re.match(r"^\s*[-+]?[0-9.]", lines[end]) and "--" not in lines[end][:4]
    ):
        end += 1
    table = np.array([[float(v) for v in ln.split()] for ln in lines[head + 2 : end]])
    x = np.linspace(0.0, 1.0, stations)
    rows = [" ".join(f"{v:.9e}" for v in [xi, *(np.interp(xi, table[:, 0], table[:, k])
            for k in range(1, table.shape[1]))]) + "\n" for xi in x]  # fmt: skip
    count = next(i for i, ln in enumerate(lines) if "NBlInpSt" in ln)
    lines[count] = f"{stations} NBlInpSt - Number of blade input stations (-)\n"
    blade.write_text("".join(lines[: head + 2] + rows + lines[end:]))
    return folder / path.name


def _deck(path: Path) -> dict:
    tower = Tower.from_elastodyn(path)
    modal = tower.run(n_modes=10, check_model=False)
    params, report = compute_tower_params_report(modal)
    fa, ss = report.selected_fa_modes, report.selected_ss_modes
    freq = [float(f) for f in modal.frequencies]
    tip = tower._bmi.tip_mass
    stiff = MudlineFoundation(
        K_hh=1e16, K_hr=0.0, K_rr=1e18, pile_behaviour="flexible",
        soil_profile="homogeneous", formula="shadlou",
    )  # fmt: skip
    springs = Tower.from_elastodyn(path).attach_mudline_foundation(stiff).run(n_modes=10)
    blade = RotatingBlade.from_elastodyn(path)
    blade_modal = blade.run(n_modes=10, check_model=False)
    fine = RotatingBlade.from_elastodyn(_refined(path, 241)).run(n_modes=10, check_model=False)
    return {
        "deck": str(path.relative_to(REFERENCE)),
        "flexible_height_m": float(tower._bmi.radius),
        "tip_mass": {k: float(getattr(tip, k)) for k in ("mass", "cm_axial", "ixx", "iyy", "izz")},
        "tower_modes": {  # pyBModes' mode numbers are 1-based
            "TwFAM1Sh": {"mode": fa[0], "frequency_hz": round(freq[fa[0] - 1], 6)},
            "TwFAM2Sh": {"mode": fa[1], "frequency_hz": round(freq[fa[1] - 1], 6)},
            "TwSSM1Sh": {"mode": ss[0], "frequency_hz": round(freq[ss[0] - 1], 6)},
            "TwSSM2Sh": {"mode": ss[1], "frequency_hz": round(freq[ss[1] - 1], 6)},
        },
        "tower": {k: _coefficients(getattr(params, k)) for k in TOWER_SETS},
        "tower_lowest_hz_clamped": [round(f, 6) for f in freq[:4]],
        "tower_lowest_hz_stiff_springs": [round(float(f), 6) for f in springs.frequencies[:4]],
        "blade_rpm": float(blade._bmi.rot_rpm),
        "blade_lowest_hz": [round(float(f), 6) for f in blade_modal.frequencies[:4]],
        "blade_lowest_hz_241_stations": [round(float(f), 6) for f in fine.frequencies[:4]],
        "blade": {
            k: _coefficients(getattr(compute_blade_params(blade_modal), k)) for k in BLADE_SETS
        },
    }


def main() -> None:
    warnings.simplefilter("ignore")
    out = {
        "tool": f"pyBModes {pybmodes.__version__}",
        "script": "bench/pybmodes_shapes.py",
        "decks": {name: _deck(REFERENCE / rel) for name, rel in DECKS.items()},
    }
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
