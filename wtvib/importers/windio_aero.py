"""windIO blade outer shape, aerofoil polars and control → the spec's ``aerodynamics`` block.

windIO 2.x: ``components.blade.outer_shape`` (chord, twist in degrees, ``airfoils`` with
their spanwise positions), ``airfoils[].polars[0].re_sets[0]`` (α in degrees),
``control.optimal_tsr`` / ``fine_pitch`` (degrees), ``assembly.cut_in_wind_speed`` /
``cut_out_wind_speed``. windIO 1.x: ``outer_shape_bem`` (twist in radians,
``airfoil_position``), ``airfoils[].polars[0].c_l/c_d`` (α in radians),
``control.torque.tsr``, ``control.pitch.min_pitch`` (radians), ``control.supervisory.Vin/
Vout``; windIO 2.0 has 2.x's geometry and 1.x's control blocks, the pitch in degrees.
Between two named aerofoils a station's polar is blended linearly in span position
(as WISDEM does); stations sit at hub radius + span fraction × blade length (precone and
prebend neglected). windIO schema documentation (windio.readthedocs.io).
"""

import math
from typing import Any

import numpy as np

from ..errors import SpecError
from ..spec.aerodynamics import MAX_POLAR_POINTS, MAX_STATIONS

#: A blended polar on more points than the spec takes is resampled every 1°.
_RESAMPLED = np.arange(-180.0, 180.0 + 1e-9, 1.0)


def _field(node: Any, key: str) -> tuple[np.ndarray, np.ndarray]:
    f = node[key]
    return np.asarray(f["grid"], float), np.asarray(f["values"], float)


#: An aerofoil's polar: α [deg], C_L, C_D and C_M (None: the file gives none).
Polar = tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray | None]


def _polar(foil: Any, v2: bool, source: str) -> Polar:
    """α [deg], C_L, C_D, C_M of an aerofoil's first polar (first Reynolds set)."""
    p = foil["polars"][0]
    if v2:
        p = p["re_sets"][0]
    keys = ("cl", "cd", "cm") if v2 else ("c_l", "c_d", "c_m")
    a_l, cl = _field(p, keys[0])
    a_d, cd = _field(p, keys[1])
    moment = _field(p, keys[2]) if isinstance(p.get(keys[2]), dict) else None
    if not v2:  # windIO 1.x tabulates α in radians
        a_l, a_d = np.degrees(a_l), np.degrees(a_d)
        moment = None if moment is None else (np.degrees(moment[0]), moment[1])
    alpha = np.union1d(np.round(a_l, 6), np.round(a_d, 6))
    alpha = alpha[(alpha >= -180) & (alpha <= 180)]
    if len(alpha) < 2 or not (np.all(np.isfinite(cl)) and np.all(np.isfinite(cd))):
        raise SpecError(
            f"airfoils: {foil.get('name')!r} has no usable polar (α within ±180°)", source=source
        )
    cm = None
    if moment is not None and len(moment[0]) >= 2 and np.all(np.isfinite(moment[1])):
        cm = np.interp(alpha, moment[0], moment[1])
    return alpha, np.interp(alpha, a_l, cl), np.interp(alpha, a_d, cd), cm


def aerodynamics(
    d: Any, v2: bool, hub_radius: float, length: float, source: str
) -> tuple[dict[str, Any], str] | None:
    """The aerodynamics block and a sentence on how it was read; None where the file has
    no outer shape with aerofoils."""
    blade = d["components"]["blade"]
    shape = blade.get("outer_shape" if v2 else "outer_shape_bem")
    foils = {f.get("name"): f for f in d.get("airfoils", []) if isinstance(f, dict)}
    if not shape or "chord" not in shape or "twist" not in shape or not foils:
        return None
    grid, chord = _field(shape, "chord")
    t_grid, twist = _field(shape, "twist")
    twist = np.interp(grid, t_grid, twist if v2 else np.degrees(twist))
    if v2:
        placed = sorted(
            (float(a["spanwise_position"]), str(a["name"])) for a in shape.get("airfoils", [])
        )
    else:
        pos = shape["airfoil_position"]
        placed = sorted(zip(map(float, pos["grid"]), map(str, pos["labels"]), strict=True))
    if not placed:
        return None
    missing = sorted({n for _, n in placed} - set(foils))
    if missing:
        raise SpecError(
            f"the blade names aerofoils not in 'airfoils': {', '.join(missing)}", source=source
        )
    tip = float(d.get("assembly", {}).get("rotor_diameter", 0.0)) / 2
    if tip > hub_radius and hub_radius + length > tip:
        length = tip - hub_radius  # precone and prebend: the span projected on the rotor plane
    radius = hub_radius + grid * length
    keep = radius > 0
    if keep.sum() > MAX_STATIONS:  # thin a long table evenly
        keep &= np.isin(
            np.arange(len(grid)), np.linspace(0, len(grid) - 1, MAX_STATIONS).astype(int)
        )
    polars = {n: _polar(foils[n], v2, source) for n in {n for _, n in placed}}
    names, out_foils = _station_foils(grid[keep], placed, polars)
    control, tsr_key = _control(d, v2)
    tsr = control.get("tip_speed_ratio")
    block: dict[str, Any] = {
        "air_density_kg_m3": float((d.get("environment") or {}).get("air_density", 1.225)),
        "stations": {
            "radius_m": [float(r) for r in radius[keep]],
            "chord_m": [float(c) for c in chord[keep]],
            "twist_deg": [float(t) for t in twist[keep]],
            "airfoil": names,
        },
        "airfoils": out_foils,
        "control": control,
    }
    note = (
        f"Aerodynamics from the blade's outer shape ({int(keep.sum())} stations at hub radius + "
        "span fraction × the blade's length in the rotor plane, up to the rotor radius: "
        "precone and prebend otherwise neglected) and the first polar of "
        "each aerofoil, blended linearly between the named positions; rated power held as "
        "aerodynamic power (no drivetrain efficiency read)"
        + (
            "; below rated the pitch follows control.min_pitch_table"
            if "min_pitch" in control
            else ""
        )
        + (f"; the region-2 tip-speed ratio is {tsr_key} ({float(tsr):g})" if tsr else "")
        + "."
    )
    return block, note


def _station_foils(
    stations: np.ndarray,
    placed: list[tuple[float, str]],
    polars: dict[str, Polar],
) -> tuple[list[str], dict[str, dict[str, list[float]]]]:
    """Each station's aerofoil (span fractions ``stations``): the one named at or before
    it, or a linear blend of the two named around it (``a|b@t``), with the tables of every
    aerofoil and blend used."""
    out_foils: dict[str, dict[str, list[float]]] = {}
    names: list[str] = []
    where = np.array([p for p, _ in placed])
    for s in stations:
        k = int(np.clip(np.searchsorted(where, s, side="right") - 1, 0, len(placed) - 1))
        a = placed[k][1]
        b = placed[min(k + 1, len(placed) - 1)][1]
        span = where[min(k + 1, len(placed) - 1)] - where[k]
        t = float(np.clip((s - where[k]) / span, 0, 1)) if span > 0 else 0.0
        if a == b or t < 1e-3 or t > 1 - 1e-3:
            name = a if t <= 0.5 or a == b else b
            if name not in out_foils:
                out_foils[name] = _table(*polars[name])
        else:
            name = f"{a}|{b}@{t:.3f}"
            if name not in out_foils:
                out_foils[name] = _blend(polars[a], polars[b], t)
        names.append(name)
    return names, out_foils


def _control(d: Any, v2: bool) -> tuple[dict[str, Any], str]:
    """The aerodynamics' control block (fine pitch, a minimum-pitch schedule, the region-2
    tip-speed ratio, cut-in and cut-out winds) and the key the tip-speed ratio came from.

    2.1 names them at the top of control (degrees); 1.x and 2.0 in its torque, pitch and
    supervisory blocks — the pitch in radians in 1.x, in degrees in 2.0 (windIO's
    converter, converters/windIO2windIO.py, v1p0_to_v2p0.convert_controls)."""
    ctl = d.get("control", {})
    asm = d.get("assembly", {})
    sup = ctl.get("supervisory", {})
    tsr_key = "control.optimal_tsr" if "optimal_tsr" in ctl else "control.torque.tsr"
    tsr = ctl.get("optimal_tsr", ctl.get("torque", {}).get("tsr"))
    if "fine_pitch" in ctl:
        fine = float(ctl["fine_pitch"])
    else:
        raw = float(ctl.get("pitch", {}).get("min_pitch", 0.0))
        fine = raw if v2 else math.degrees(raw)
    cut_in = asm.get("cut_in_wind_speed", sup.get("Vin"))
    cut_out = asm.get("cut_out_wind_speed", sup.get("Vout"))
    control: dict[str, Any] = {"regulation": "pitch", "fine_pitch_deg": fine}
    table = ctl.get("min_pitch_table") if v2 else None
    if table and len(table.get("wind_speed", [])) >= 2:
        control["min_pitch"] = {
            "wind_m_s": [float(v) for v in table["wind_speed"]],
            "pitch_deg": [float(p) for p in table["min_pitch"]],
        }
    if tsr:
        control["tip_speed_ratio"] = float(tsr)
    if cut_in:
        control["cut_in_wind_m_s"] = float(cut_in)
    if cut_out:
        control["cut_out_wind_m_s"] = float(cut_out)
    return control, tsr_key


def _table(
    alpha: np.ndarray, cl: np.ndarray, cd: np.ndarray, cm: np.ndarray | None = None
) -> dict[str, list[float]]:
    if len(alpha) > MAX_POLAR_POINTS:
        cl, cd = np.interp(_RESAMPLED, alpha, cl), np.interp(_RESAMPLED, alpha, cd)
        cm = None if cm is None else np.interp(_RESAMPLED, alpha, cm)
        alpha = _RESAMPLED
    out = {"alpha_deg": alpha.tolist(), "cl": cl.tolist(), "cd": np.maximum(cd, 0.0).tolist()}
    if cm is not None:
        out["cm"] = cm.tolist()
    return out


def _blend(a: Polar, b: Polar, t: float) -> dict[str, list[float]]:
    alpha = np.union1d(a[0], b[0])
    cl = (1 - t) * np.interp(alpha, a[0], a[1]) + t * np.interp(alpha, b[0], b[1])
    cd = (1 - t) * np.interp(alpha, a[0], a[2]) + t * np.interp(alpha, b[0], b[2])
    cm = None
    if a[3] is not None and b[3] is not None:
        cm = (1 - t) * np.interp(alpha, a[0], a[3]) + t * np.interp(alpha, b[0], b[3])
    return _table(alpha, cl, cd, cm)
