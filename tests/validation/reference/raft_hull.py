"""Reference numbers for tests/validation/test_windio_floating.py from NREL's RAFT.

RAFT (OpenRAFT 2.0.4, pip install openraft) computes a platform's hydrostatics and its
strip-theory added mass from its members. This script gives it the members wtvib reads
from a windIO file (wtvib.importers.windio_platform: joints resolved, pontoons cut at the
columns' surface) and prints RAFT's displaced volume, centre of buoyancy, hydrostatic
restoring (without the weight term) and Morison added mass at the PRP, to store in the
test. Run once, in an environment with both wtvib and openraft:

    python tests/validation/reference/raft_hull.py WINDIO.yaml

It is not run by the tests (RAFT is not a wtvib dependency).
"""

import contextlib
import itertools
import json
import sys
from pathlib import Path

import numpy as np
import raft
import yaml

from wtvib.importers.windio_platform import _Platform


def raft_member(m, st=None, l_fill=None, rho_fill=None) -> dict:  # type: ignore[no-untyped-def]
    """RAFT's member dict of a wtvib hull member, its stations ``st`` (shares of its length;
    the member's own where None), with ballast fills per section where given."""
    st = m.stations if st is None else np.asarray(st)
    t = sum(layer.thickness for layer in m.layers)
    out = {
        "name": m.name, "type": "rigid", "shape": "circ",
        "rA": m.a.tolist(), "rB": m.b.tolist(),
        "stations": (st * m.length).tolist(),
        "d": np.interp(st, m.stations, m.diameter).tolist(),
        "t": np.interp(st, m.stations, np.asarray(t) * np.ones(len(m.stations))).tolist(),
        "Ca": m.ca, "Cd": 0.8, "CdEnd": 0.0,
        "CaEnd": [m.ca_end if m.free_ends[0] else 0.0] + [m.ca_end] * (len(st) - 2)
        + [m.ca_end if m.free_ends[1] else 0.0],
        "rho_shell": m.layers[0].density * m.outfitting if m.layers else 7850.0,
        "potMod": False, "gamma": 0.0,
    }  # fmt: skip
    if l_fill is not None:
        out |= {
            "l_fill": l_fill, "rho_fill": rho_fill,
            "cap_stations": [b.station * m.length for b in m.bulkheads],
            "cap_t": [b.thickness for b in m.bulkheads],
            "cap_d_in": [0.0 for _ in m.bulkheads],
        }  # fmt: skip
    return out


def members(path: Path) -> list[dict]:
    d = yaml.safe_load(path.read_text())
    reader = _Platform(d, path)
    return [
        raft_member(m)
        for m in reader.members(reader.joints())
        if m.a[2] < 0 or m.b[2] < 0  # out of the water: no hydrostatics or added mass
    ]


def main(path: Path) -> None:
    design = {
        "type": "input file for RAFT",
        "name": path.stem,
        "settings": {"min_freq": 0.001, "max_freq": 0.2, "XiStart": 0, "nIter": 2},
        "site": {
            "water_depth": 200.0,
            "rho_water": 1025.0,
            "rho_air": 0.0,
            "mu_air": 0.0,
            "shearExp": 0.0,
        },
        "cases": {
            "keys": [
                "wind_speed",
                "wind_heading",
                "turbulence",
                "turbine_status",
                "turbine_heading",
                "wave_spectrum",
                "wave_period",
                "wave_height",
                "wave_heading",
                "current_speed",
                "current_heading",
                "current_turbulence",
            ],
            "data": [[0, 0, 0, "parked", 0, "still", 12, 1, 0, 0, 0, 0]],
        },
        "platform": {"potModMaster": 1, "dlsMax": 0.25, "members": members(path)},
    }
    with contextlib.redirect_stdout(sys.stderr):  # RAFT prints its progress
        model = raft.Model(design)
        fowt = model.fowtList[0]
        fowt.setPosition(np.zeros(6))
        fowt.calcStatics()
        fowt.calcHydroConstants()
    print(
        json.dumps(
            {
                "file": path.name,
                "raft": raft.__version__ if hasattr(raft, "__version__") else "2.0.4",
                "V": fowt.V,
                "rCB": np.asarray(fowt.rCB).tolist(),
                "C_hydro": np.round(fowt.C_hydro, 1).tolist(),
                "A_morison": np.round(fowt.A_hydro_morison, 1).tolist(),
            },
            indent=1,
        )
    )


def system(path: Path, raft_design: Path, head_mass: float) -> None:
    """RAFT's rigid-body frequencies of the whole floating turbine: RAFT's own IEA-15
    VolturnUS-S design (RAFT/designs/VolturnUS-S.yaml: its tower and RNA as rigid bodies)
    with its platform and moorings replaced by the windIO file's, the members as wtvib reads
    them and each ballast compartment filled with wtvib's trimmed water (RAFT fills along a
    member's axis: a partly filled pontoon's water is spread along it at the axis)."""
    from wtvib.importers import windio as w
    from wtvib.numerics import hull

    d = yaml.safe_load(path.read_text())
    data = w.to_spec_data(path, path.read_text(), head_mass=head_mass)
    reader = _Platform(d, path)
    joints = reader.joints()
    ms = reader.members(joints)
    design = yaml.safe_load(raft_design.read_text())
    carried = w._carried(data["tower"], data["tower_head"])
    # the same trim as wtvib's
    steel = sum(hull.structure(m)[0, 0] for m in ms)
    fixed = sum(
        hull.ballast(m, f, hull.level([(m, f)], f.volume))[0, 0]
        for m in ms
        for f in m.fills
        if f.volume is not None
    )
    _k, pull, _ = reader.moorings(joints)
    tp = float(reader.fp.get("transition_piece_mass", 0.0) or 0.0)
    variable = [(m, f) for m in ms for f in m.fills if f.volume is None]
    trimmed = hull.trim(
        hull.buoyancy(ms).volume, 1025.0, steel + fixed + tp + carried + pull / 9.80665, variable
    )
    out = []
    for m in ms:
        cuts = sorted({0.0, 1.0, *[f.start for f in m.fills], *[f.end for f in m.fills]})
        st = np.array(cuts)
        l_fill, rho_fill = [], []
        for a, b in itertools.pairwise(st):
            fill = next((f for f in m.fills if f.start <= a and b <= f.end), None)
            if fill is None:
                l_fill.append(0.0)
                rho_fill.append(0.0)
                continue
            volume = float(
                hull.held(
                    m,
                    fill,
                    trimmed.level if fill.volume is None else hull.level([(m, fill)], fill.volume),
                ).sum()
            )
            room = hull.capacity(m, fill)
            share = volume / room if room else 0.0
            if abs(m.axis[2]) >= np.sin(np.radians(hull.LEVEL_DEG)):  # from the low end
                l_fill.append((b - a) * m.length * min(share, 1 - 1e-9))
                rho_fill.append(fill.density)
            else:  # a level member's water spread along it
                l_fill.append((b - a) * m.length * (1 - 1e-9))
                rho_fill.append(fill.density * share)
        out.append(raft_member(m, st, l_fill, rho_fill))
    design["platform"] = {"potModMaster": 1, "dlsMax": 1.0, "members": out}
    tower = data["tower"]
    sec = tower["sections"]
    base = joints[next(str(j["name"]) for j in reader.fp["joints"] if j.get("transition"))][2]
    z = np.asarray(sec["height_m"]) + base
    design["turbine"]["tower"].update(
        {
            "rA": [0, 0, float(z[0])],
            "rB": [0, 0, float(z[-1])],
            "stations": z.tolist(),
            "d": sec["outer_diameter_m"],
            "t": sec["wall_thickness_m"],
            "rho_shell": tower["material"]["density_kg_m3"]
            * tower["material"].get("mass_factor", 1.0),
        }
    )
    head = data["tower_head"]
    design["turbine"].update(
        {
            "mRNA": head["mass_kg"],
            "xCG_RNA": head.get("cm_downwind_m", 0.0),
            "hHub": float(z[-1]) + head.get("cm_above_top_m", 0.0),
            "overhang": 0.0,
            "aeroServoMod": 0,
            "IxRNA": 0.0,
            "IrRNA": 0.0,
        }
    )
    moor = d["components"]["mooring"]
    points = []
    for n in moor["nodes"]:
        r = joints[str(n["joint"])]
        points.append(
            {
                "name": n["name"],
                "type": "fixed" if n["node_type"] == "fixed" else "vessel",
                "location": r.tolist(),
                **({"anchor_type": "drag_embedment"} if n["node_type"] == "fixed" else {}),
            }
        )
    import moorpy.helpers as mh

    from wtvib.importers.mooring import WINDIO_MATERIALS

    types = []
    for t in moor["line_types"]:
        material = WINDIO_MATERIALS[t["type"]]
        probe = mh.getLineProps(100.0, material, source="default")
        props = mh.getLineProps(
            t["diameter"] / (probe["d_vol"] / 0.1) * 1000, material, source="default"
        )
        types.append(
            {
                "name": t["name"],
                "diameter": props["d_vol"],
                "mass_density": props["m"],
                "stiffness": props["EA"],
                "breaking_load": 1e8,
                "cost": 0,
                "transverse_added_mass": 1.0,
                "tangential_added_mass": 0.0,
                "transverse_drag": 1.6,
                "tangential_drag": 0.1,
            }
        )
    design["mooring"] = {
        "water_depth": reader.depth(moor, joints),
        "points": points,
        "lines": [
            {
                "name": ln["name"],
                "endA": ln["node1"],
                "endB": ln["node2"],
                "type": ln["line_type"],
                "length": ln["unstretched_length"],
            }
            for ln in moor["lines"]
        ],
        "line_types": types,
        "anchor_types": [
            {
                "name": "drag_embedment",
                "mass": 0,
                "cost": 0,
                "max_vertical_load": 0,
                "max_lateral_load": 0,
            }
        ],
    }
    design["site"]["water_depth"] = design["mooring"]["water_depth"]
    with contextlib.redirect_stdout(sys.stderr):
        model = raft.Model(design)
        model.analyzeUnloaded()
        # back to the design draft (wtvib's linearisation point; RAFT's own weights leave it
        # a little off equilibrium there): RAFT's matrices at zero offset
        fowt = model.fowtList[0]
        fowt.setPosition(np.zeros(fowt.nDOF))
        fowt.calcStatics()
        fowt.calcHydroConstants()
        fowt.ms.bodyList[0].setPosition(np.zeros(6))
        fowt.ms.solveEquilibrium()
        fowt.C_moor[:6, :6] = fowt.ms.bodyList[0].getStiffnessA(lines_only=True)
        fns, _ = model.solveEigen()
        print(
            "M diag",
            np.diag(fowt.M_struc),
            "A diag",
            np.diag(fowt.A_hydro_morison),
            "C diag",
            np.diag(fowt.C_struc + fowt.C_hydro + fowt.C_moor),
            file=sys.stderr,
        )
    print(
        json.dumps(
            {
                "file": path.name,
                "head_mass": head_mass,
                "frequencies_hz": np.round(fns, 6).tolist(),
            },
            indent=1,
        )
    )


if __name__ == "__main__":
    if len(sys.argv) == 4:  # WINDIO.yaml RAFT/designs/VolturnUS-S.yaml HEAD_MASS
        system(Path(sys.argv[1]), Path(sys.argv[2]), float(sys.argv[3]))
    else:
        main(Path(sys.argv[1]))
