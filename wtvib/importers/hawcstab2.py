"""HAWCStab2 Campbell results: ``.cmb`` (frequencies and damping per operating point), named by
the ``.amp`` of the same name (modal amplitudes), placed on rotor speed by the ``.opt`` (or
``.pwr``) of the same name.

* ``.cmb``: one header line (the operating point's label — ``Wind [m/s]`` or ``Speed
  [rad/s]`` — then the mode numbers once per block), one row per point: the point, N
  frequencies [Hz], N damping ratios [% of critical] and, in newer versions, N real parts.
* ``.amp`` of a turbine analysis: per mode 15 amplitudes with phases — tower x (side-side),
  y (fore-aft), yaw; shaft x, y, torsion; symmetric, backward and forward whirling edge,
  flap and torsion of the blades. Of a blade analysis: per mode u_x (edgewise), u_y
  (flapwise) and θ (torsion) along the radius. A mode is named by its largest amplitude
  (rotations weighed as the motion 50 m away, like the OpenFAST reader), averaged over the
  points; ordinals count each kind in frequency order.
* ``.opt``: one header line, rows of wind speed, pitch, rotor speed [rpm] (…); ``.pwr``: the
  rotor speed in its column 10.

Only the files of the .cmb's own name are read (none found by globbing), each listed.
"""

import math
from collections import defaultdict
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import SpecError
from ..results import ordinal
from ..spec import read_bytes
from .campbell_results import MAX_MODES, results_spec
from .deck import finite

#: A rotation amplitude [rad] is weighed as the motion it gives this far away [m]: a yaw or
#: shaft torsion turns the rotor, whose blades are tens of metres long; a blade's torsion
#: turns a section of a few metres' chord (weighed like a flap or edge deflection of the
#: tip it would be 25 times too heavy: the IEA-15's first flap modes, their tips twisting
#: with the bend-twist coupling, were named torsion). Only the naming depends on them.
ROTOR_ARM_M, CHORD_ARM_M = 50.0, 2.0
#: A tower-top or shaft-end deflection [m] is weighed this many times a blade tip's: the
#: square root of the ratio of the masses they move (the tower head against the blades'
#: modal mass, ~20 for today's turbines; the IEA-15's tower fore-aft mode, whose tilting
#: rotor swings the blade tips twice the tower top's amplitude, was named a flap mode).
TOWER_WEIGHT = 5.0

#: A point where HAWCStab2 gives this damping ratio or more is no oscillation.
OVERDAMPED = 0.999

#: The turbine .amp's 15 sensors: (kind of motion, coordinate), in file order.
TURBINE_SENSORS = (
    ("tower.ss", "fixed"),
    ("tower.fa", "fixed"),
    ("yaw", "fixed"),
    ("shaft", "fixed"),
    ("shaft", "fixed"),
    ("drivetrain", "fixed"),
    ("blade.edge", "collective"),
    ("blade.edge", "backward"),
    ("blade.edge", "forward"),
    ("blade.flap", "collective"),
    ("blade.flap", "backward"),
    ("blade.flap", "forward"),
    ("blade.tor", "collective"),
    ("blade.tor", "backward"),
    ("blade.tor", "forward"),
)
#: The weight of each sensor: the arm [m] of each rotation (yaw, shaft torsion, blade
#: torsion in its three whirls), TOWER_WEIGHT for the tower top's and the shaft end's
#: deflections, 1 for the blade tips'.
_WEIGHTS = {
    0: TOWER_WEIGHT,
    1: TOWER_WEIGHT,
    2: ROTOR_ARM_M,
    3: TOWER_WEIGHT,
    4: TOWER_WEIGHT,
    5: ROTOR_ARM_M,
    12: CHORD_ARM_M,
    13: CHORD_ARM_M,
    14: CHORD_ARM_M,
}
#: The weight of a frequency change against a change of what a mode moves in
#: :func:`followed`: a cosine of 1 is worth a factor e in frequency.
FOLLOW_FREQUENCY = 1.0
#: What a column's own mode gains over the others in :func:`followed`: enough that two
#: columns alike to rounding keep their modes, far below what a swap changes (a cosine
#: from ≈1 to ≈0.2 for the IEA-15's crossing whirls).
FOLLOW_BIAS = 1e-6
_WORDS = {
    "tower.ss": "tower side-side",
    "tower.fa": "tower fore-aft",
    "yaw": "yaw",
    "shaft": "shaft bending",
    "drivetrain": "drive-train torsion",
    "blade.edge": "blade edgewise",
    "blade.flap": "blade flapwise",
    "blade.tor": "blade torsion",
}


def _table(path: Path, skip: int = 0) -> tuple[list[str], np.ndarray, list[int]]:
    """Header lines ('#' or the first ``skip``), the numeric rows of a whitespace table, and
    each row's line in the file — read through the guards every input passes (a regular
    file, the size limit), the files found beside the .cmb too."""
    raw = read_bytes(path)
    if b"\x00" in raw:
        raise SpecError("binary file, not a HAWCStab2 table", source=str(path))
    lines = raw.decode("utf-8-sig", errors="replace").splitlines()
    header: list[str] = []
    rows: list[list[float]] = []
    at: list[int] = []
    for i, ln in enumerate(lines, start=1):
        if not ln.strip():
            continue
        if ln.lstrip().startswith("#") or i <= skip:
            header.append(ln)
            continue
        row = [finite(t, i, path) for t in ln.split()]  # strict: no "8_7.6", "١٢", "nan"
        if rows and len(row) != len(rows[0]):
            raise SpecError(
                f"{len(row)} numbers, the rows above have {len(rows[0])}", line=i, source=str(path)
            )
        rows.append(row)
        at.append(i)
    if not rows:
        raise SpecError("no rows of numbers", source=str(path))
    return header, np.array(rows), at


def _once_per_point(data: np.ndarray, at: list[int], path: Path) -> tuple[np.ndarray, list[int]]:
    """Each operating point once: a row repeated as it is is read once, a point given twice
    with other numbers is refused with both lines (which one would be the turbine's?)."""
    first: dict[float, int] = {}
    keep: list[int] = []
    for k, point in enumerate(data[:, 0]):
        if float(point) not in first:
            first[float(point)] = k
            keep.append(k)
            continue
        j = first[float(point)]
        if not np.array_equal(data[j], data[k]):
            raise SpecError(
                f"operating point {point:g} is given twice with other numbers (also on line "
                f"{at[j]}): which is the turbine's?",
                line=at[k],
                source=str(path),
            )
    return data[keep], [at[k] for k in keep]


def read_cmb(path: Path) -> tuple[str, np.ndarray, np.ndarray, np.ndarray]:
    """(point label, points, frequencies [points × modes], damping ratios or NaN)."""
    header, data, at = _table(path)
    if not header:
        raise SpecError("no header line: not a HAWCStab2 .cmb file", source=str(path))
    tokens = header[0].lstrip("# ").split()
    # ASCII digits only: "²" (in "[m²]") is a digit to str.isdigit, not to int()
    numbers = [int(t) for t in tokens if t.isascii() and t.isdigit()]
    label = " ".join(t for t in tokens if not (t.isascii() and t.isdigit()))
    n = max(numbers) if numbers else 0
    cols = data.shape[1] - 1
    if n > MAX_MODES:
        raise SpecError(
            f"{n} modes: a whole-turbine Campbell diagram has tens; wtvib reads at most "
            f"{MAX_MODES}",
            line=1,
            source=str(path),
        )
    if n == 0 or cols % n or cols // n not in (1, 2, 3):
        raise SpecError(
            f"{cols} value columns for {n} modes: expected 1, 2 or 3 blocks (frequency, "
            "damping, real part) per mode",
            line=1,
            source=str(path),
        )
    data, at = _once_per_point(data, at, path)
    freq = data[:, 1 : 1 + n].copy()
    bad = np.argwhere(freq < 0)
    if bad.size:
        row, mode = (int(x) for x in bad[0])
        raise SpecError(
            f"mode {mode + 1}: frequency {freq[row, mode]:g} Hz — a natural frequency is not "
            "negative",
            line=at[row],
            source=str(path),
        )
    freq[freq == 0] = np.nan  # HAWCStab2 writes 0 where it found no such mode: no data
    damp = data[:, 1 + n : 1 + 2 * n] / 100 if cols // n >= 2 else np.full_like(freq, np.nan)
    return label, data[:, 0], freq, damp


def rotor_speeds(
    cmb: Path, label: str, points: np.ndarray
) -> tuple[np.ndarray, np.ndarray | None, list[str]]:
    """Rotor speed [rpm] (and wind [m/s]) of each point, and the files read for them."""
    low = label.lower()
    if "speed" in low and "rad/s" in low:
        return points * 30 / math.pi, None, []
    if "speed" in low and "rpm" in low:
        return points, None, []
    if "wind" not in low:
        raise SpecError(
            f"operating points labelled {label!r}: expected wind or rotor speed",
            line=1,
            source=str(cmb),
        )
    for suffix, column, skip in ((".opt", 2, 1), (".pwr", 9, 0)):
        side = _beside(cmb, suffix)
        if side is not None:
            _, table, _ = _table(side, skip)
            if table.shape[1] <= column:
                raise SpecError(f"no rotor-speed column {column + 1}", source=str(side))
            order = np.argsort(table[:, 0])
            rpm = np.interp(points, table[order, 0], table[order, column])
            outside = (points < table[order[0], 0] - 1e-6) | (points > table[order[-1], 0] + 1e-6)
            if outside.any():
                raise SpecError(
                    f"wind speeds {points[outside].tolist()} of {cmb.name} lie outside its "
                    "operational data",
                    source=str(side),
                )
            return rpm, points, [str(side)]
    others = [p.name for p in _opt_files(cmb)]
    which = (
        f"; the folder has {len(others)} .opt files ({', '.join(others[:4])}"
        f"{', …' if len(others) > 4 else ''}): copy or link the one HAWCStab2 ran to "
        f"{cmb.with_suffix('.opt').name}"
        if others
        else ""
    )
    raise SpecError(
        f"the points are wind speeds, and neither {cmb.with_suffix('.opt').name} nor "
        f"{cmb.with_suffix('.pwr').name} (nor a folder's only .opt) gives the rotor speed at "
        f"them{which}",
        source=str(cmb),
    )


def _beside(cmb: Path, suffix: str) -> Path | None:
    """The file of this suffix that goes with a .cmb: the one of its own name, else — for
    the operational data, which HAWCStab2 runs name as they please
    (``operation_1_25_windspeed.opt``) — the folder's only one."""
    own = cmb.with_suffix(suffix)
    if own.exists():
        return own
    if suffix != ".opt":
        return None
    found = _opt_files(cmb)
    return found[0] if len(found) == 1 else None


def _opt_files(cmb: Path) -> list[Path]:
    """The operational data files in a .cmb's folder, by name (none where it cannot be
    listed)."""
    try:
        return sorted(p for p in cmb.parent.iterdir() if p.suffix.lower() == ".opt")
    except OSError:
        return []


def names_from_amp(
    amp: Path, modes: int, points: np.ndarray | None = None, freqs: np.ndarray | None = None
) -> tuple[list[tuple[str, str]], str, np.ndarray | None]:
    """(kind, coordinate) of each mode, the frame (``fixed`` turbine, ``rotating`` blade)
    and, for a turbine file whose rows are the .cmb's ``points``, the followed order of its
    columns (:func:`followed`: HAWCStab2 numbers its modes by frequency at each point, so
    a column changes mode where two cross) — None where there is nothing to follow."""
    header, data, _ = _table(amp)
    text = " ".join(header)
    if "TWR" in text:
        per = 2 * len(TURBINE_SENSORS)
        if (data.shape[1] - 1) % per or (data.shape[1] - 1) // per < modes:
            raise SpecError(
                f"{data.shape[1] - 1} columns do not hold {modes} modes × 15 sensors",
                source=str(amp),
            )
        weights = np.array([_WEIGHTS.get(i, 1.0) for i in range(len(TURBINE_SENSORS))])
        mags = data[:, 1 : 1 + modes * per].reshape(len(data), modes, -1)[:, :, ::2] * weights
        order = None
        once = _first_rows(data[:, 0])  # each point once, as read_cmb reads the .cmb
        if points is not None and freqs is not None and _same(data[once, 0], points):
            order = followed(mags[once], freqs)
            mags = np.take_along_axis(mags[once], order[:, :, None], axis=1)
        out = [TURBINE_SENSORS[int(np.argmax(mags[:, j].mean(axis=0)))] for j in range(modes)]
        return out, "fixed", order
    if "u_x" in text or "u_y" in text:
        per = 6
        if (data.shape[1] - 2) // per < modes:
            raise SpecError(
                f"{data.shape[1] - 2} columns do not hold {modes} modes", source=str(amp)
            )
        radius = data[:, 1]
        arm = 0.05 * float(np.max(radius))  # θ weighed at a twentieth of the radius (a chord)
        out = []
        for j in range(modes):
            ux, uy, th = (data[:, 2 + per * j + 2 * k] for k in range(3))
            energy = {
                "blade.edge": np.sum(ux**2),
                "blade.flap": np.sum(uy**2),
                "blade.tor": np.sum((arm * th) ** 2),
            }
            out.append((max(energy, key=lambda k: energy[k]), "rotating"))
        return out, "rotating", None
    raise SpecError(
        "neither a turbine (TWR …) nor a blade (u_x, u_y …) amplitude file", source=str(amp)
    )


def _first_rows(keys: np.ndarray) -> np.ndarray:
    """The index of each key's first row, in the file's order."""
    _, first = np.unique(keys, return_index=True)
    return np.sort(first)


def _same(amp_points: np.ndarray, cmb_points: np.ndarray) -> bool:
    """Whether the .amp's points are the .cmb's, in the same order."""
    return amp_points.shape == cmb_points.shape and bool(np.allclose(amp_points, cmb_points))


def followed(amplitudes: np.ndarray, freq: np.ndarray) -> np.ndarray:
    """Which column holds each mode at each point: ``amplitudes`` (points × modes ×
    sensors, magnitudes) and frequencies ``freq`` [Hz] (points × modes, NaN: no mode)
    followed from the first point — at each next point the columns assigned one to one to
    the modes (:func:`scipy.optimize.linear_sum_assignment`) by what each moves, the cosine
    of their normalised amplitudes, less FOLLOW_FREQUENCY times how far their frequencies
    lie apart, |ln(f/f_before)|. So a curve stays one physical mode where HAWCStab2's
    frequency-ordered columns swap two (the IEA-15's first flap forward and first edge
    backward whirls between 5.7 and 6.4 rpm), and never jumps to another mode that moves
    the same sensors (a flap collective's higher namesake, four times its frequency)."""
    from scipy.optimize import linear_sum_assignment

    norm = np.linalg.norm(amplitudes, axis=2, keepdims=True)
    unit = np.divide(amplitudes, norm, out=np.zeros_like(amplitudes), where=norm > 0)
    points, modes = unit.shape[:2]
    order = np.tile(np.arange(modes), (points, 1))
    for i in range(1, points):
        before = np.take_along_axis(freq[i - 1], order[i - 1], axis=0)
        with np.errstate(divide="ignore", invalid="ignore"):
            apart = np.abs(np.log(freq[i][None, :] / before[:, None]))
        apart = np.where(np.isfinite(apart), apart, 1.0)  # a mode not found: far from all
        score = unit[i - 1][order[i - 1]] @ unit[i].T - FOLLOW_FREQUENCY * apart
        score[np.diag_indices(modes)] += FOLLOW_BIAS  # a column keeps its mode on a tie
        rows, cols = linear_sum_assignment(-score)
        order[i, rows] = cols
    return order


def _named(kind: str, coord: str, j: int, count: dict[str, int]) -> tuple[str, str]:
    """The id and words of column ``j`` (0-based) named ``kind`` in ``coord`` by the .amp
    file: the ``count``-th of its kind (``count`` counts them as they come)."""
    key = kind if coord in ("fixed", "rotating") else f"{kind}.{coord}"
    count[key] += 1
    k = count[key]
    if kind == "mode":
        return f"mode{j + 1}", f"HAWCStab2 mode {j + 1}"
    if coord in ("fixed", "rotating"):
        # a rotating-frame mode becomes blade.<name>: its kind without the prefix
        stem = kind.removeprefix("blade.") if coord == "rotating" else kind
        return f"{stem}{k}", f"{ordinal(k)} {_WORDS[kind]}"
    how = "symmetric" if coord == "collective" else f"{coord} whirl"
    return f"{kind}{k}.{coord}", f"{ordinal(k)} {_WORDS[kind]}, {how}"


def _mode(
    description: str, frame: str, rpm: np.ndarray, freq: np.ndarray, damp: np.ndarray
) -> dict[str, Any]:
    """One mode's entry: its points' speeds and frequencies, its damping where every point
    has one (clipped to ±1: HAWCStab2 writes ζ past critical as it found it)."""
    m: dict[str, Any] = {
        "description": description,
        "frame": frame,
        "rpm": [round(float(v), 6) for v in rpm],
        "frequency_hz": [float(v) for v in freq],
    }
    if np.all(np.isfinite(damp)):
        m["damping_ratio"] = [max(-1.0, min(1.0, float(v))) for v in damp]
    return m


def to_spec_data(
    path: Path, text: str, blades: int | None, given: tuple[float, float] | None = None
) -> dict[str, Any]:
    """The wtvib-format dictionary of a HAWCStab2 .cmb with its .amp and .opt/.pwr.

    A mode HAWCStab2 did not find at a point (frequency 0 or NaN) has no data there, and a
    root damped at or past critical (ζ ≥ 99.9 %) does not oscillate there: those points
    are left out of the mode; a mode with no point left is left out, said.
    """
    label, points, freq, damp = read_cmb(path)
    rpm, wind, side = rotor_speeds(path, label, points)
    files = [str(path), *side]
    n = freq.shape[1]
    amp = path.with_suffix(".amp")
    warnings = []
    if amp.exists():
        kinds, frame, order = names_from_amp(amp, n, points, freq)
        files.append(str(amp))
        if order is not None:  # each column one physical mode from end to end
            freq = np.take_along_axis(freq, order, axis=1)
            damp = np.take_along_axis(damp, order, axis=1)
    else:
        kinds, frame = [("mode", "fixed")] * n, "fixed"
        warnings.append(
            f"no {amp.name} beside {path.name}: the modes are not named (mode1, mode2 …) and "
            "are judged as whole-turbine modes without whirl"
        )
    valid = np.isfinite(freq) & ~(np.nan_to_num(damp, nan=0.0) >= OVERDAMPED)
    typical = np.array([np.median(freq[valid[:, j], j]) if valid[:, j].any() else np.inf
                        for j in range(n)])  # fmt: skip
    order = np.argsort(typical, kind="stable")
    sort = np.argsort(rpm, kind="stable")
    count: dict[str, int] = defaultdict(int)
    modes: dict[str, dict[str, Any]] = {}
    dropped: list[str] = []
    partial: list[str] = []
    for j in order:
        ok = sort[valid[sort, j]]
        if ok.size == 0:
            why = "no frequency" if not np.isfinite(freq[:, j]).any() else "damped past critical"
            dropped.append(f"mode {j + 1} ({why} at every point)")
            continue
        if ok.size < len(sort):
            partial.append(f"mode {j + 1} ({len(sort) - ok.size} of {len(sort)} points)")
        kind, coord = kinds[j]
        name, words = _named(kind, coord, j, count)
        m = _mode(f"{words} (mode {j + 1})", frame, rpm[ok], freq[ok, j], damp[ok, j])
        if frame == "fixed" and coord not in ("fixed", "rotating"):
            m["whirl"] = [coord] * int(ok.size)
        if wind is not None:
            m["wind_m_s"] = [float(v) for v in wind[ok]]
        modes[name] = m
    if not modes:
        raise SpecError(
            f"no mode of {path.name} oscillates at any point ({'; '.join(dropped[:3])})",
            source=str(path),
        )
    data = results_spec(
        path, "HAWCStab2", modes, blades, files, f"HAWCStab2 {path.stem}", rpm=given
    )
    if dropped:
        data["assumptions"].append(
            "Left out: " + ", ".join(dropped) + " — HAWCStab2 writes 0 where it found no mode "
            "(a rigid-body mode, the drive train turning freely, has none), and a root damped "
            "past critical does not oscillate."
        )
    if partial:
        data["assumptions"].append(
            "Points without data (no frequency, or damped past critical) left out of "
            + ", ".join(partial)
            + "; the curve is linear between the points it has."
        )
    data["warnings"] += warnings
    return data
