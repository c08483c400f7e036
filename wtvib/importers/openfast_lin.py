"""OpenFAST linearisation output (``*.lin``): the whole turbine's modes at each operating point.

OpenFAST with ``Linearize = True`` writes, per operating point, the state matrix A at several
rotor azimuths (``root.1.lin`` … ``root.N.lin``). Rotating-frame states (the blades') make A
periodic; the multi-blade coordinate transformation (MBC3, Bir 2008, NREL/CP-500-42553) —
here :func:`wtvib.multiblade.coleman`, the project's one Coleman transformation — turns each
into fixed-frame coordinates, A_NR = T⁻¹(A·T − Ṫ), averaged over the azimuths. Its eigenvalues
give the frequencies |λ|/2π and damping ratios −Re λ/|λ|; each mode is named by the state
group (tower fore-aft / side-side, drive train, yaw, each blade DOF's collective or cyclic
coordinates) where its displacement sits, and a cyclic blade mode's whirl by the phase of its
cos and sin coordinates. Modes are named at the slowest point and followed from point to point
by shape (MAC of the multi-blade displacements, one optimal assignment per step; a weak
match is a warning).

Reading: only the files of one root (a named ``.lin`` file's siblings ``root.<k>.lin``) or the
``.lin`` files of a named folder, each listed in the report.
"""

import math
import re
from collections import defaultdict
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import SpecError
from ..modal import assign, mac
from ..multiblade import coleman
from .campbell_results import results_spec

Array = NDArray[np.float64]

#: A rotation state [rad] is weighed as the motion it gives this far away [m] (about a blade
#: length of the turbines OpenFAST linearises); only the naming of modes depends on it.
ROTATION_ARM_M = 50.0
#: A tower displacement state [m] is weighed this many times a blade's tip displacement: the
#: .lin file holds no mass matrix, and a tower mode carries the whole tower head — the square
#: root of the ratio of modal masses, tower with head to three blades' flap (NREL 5-MW:
#: (350 t + ¼·347 t)/(3·¼·17.7 t) ≈ 33, √33 ≈ 6; wtvib's choice). Only the naming depends on it.
TOWER_WEIGHT = 6.0
#: Modes reported per operating point: the lowest oscillatory ones.
MODES_KEPT = 20

_ROOT = re.compile(r"^(?P<root>.+)\.(?P<k>\d+)\.lin$", re.IGNORECASE)
_BLADE = re.compile(r"\bblade (\d+)\b", re.IGNORECASE)
#: ElastoDyn's "(internal DOF index = DOF_BF(1,1))": blade-specific, not part of the DOF.
_INTERNAL = re.compile(r"\(internal DOF index = [^()]*(\([^()]*\))?\)")


@dataclass(frozen=True)
class State:
    rotating: bool
    order: int
    description: str


@dataclass(frozen=True)
class LinFile:
    path: Path
    rotor_speed: float  # rad/s
    azimuth: float  # rad
    wind: float | None  # m/s
    states: tuple[State, ...]
    a: Array


def read(path: Path) -> LinFile:
    """One ``.lin`` file: the operating point, the continuous states and A."""
    try:
        lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError as exc:
        raise SpecError(f"cannot read: {exc.strerror or exc}", source=str(path)) from None

    def fail(message: str, line: int | None = None) -> SpecError:
        return SpecError(message, line=line, source=str(path))

    def value(label: str) -> tuple[float, int]:
        for i, ln in enumerate(lines):
            if ln.strip().startswith(label):
                token = ln.split(":", 1)[1].split()[0]
                try:
                    v = float(token)
                except ValueError:
                    raise fail(f"{label} {token!r} is not a number", i + 1) from None
                if not math.isfinite(v):
                    raise fail(f"{label} {token} is not a finite number", i + 1)
                return v, i + 1
        raise fail(f"no '{label}' line: not an OpenFAST linearisation file")

    speed, _ = value("Rotor Speed:")
    azimuth, _ = value("Azimuth:")
    wind = value("Wind Speed:")[0] if any("Wind Speed:" in ln for ln in lines) else None
    n, n_line = value("Number of continuous states:")
    if n != int(n) or not 0 < n <= 5000:
        raise fail(f"Number of continuous states {n:g} is not a count", n_line)
    n = int(n)
    start = next(
        (i for i, ln in enumerate(lines) if ln.startswith("Order of continuous states:")), None
    )
    if start is None:
        raise fail("no 'Order of continuous states:' table")
    states = []
    for k in range(n):
        i = start + 3 + k
        cells = lines[i].split() if i < len(lines) else []
        if len(cells) < 5 or cells[0] != str(k + 1) or cells[2] not in ("T", "F"):
            raise fail(f"state {k + 1} of {n} missing or malformed in the table", i + 1)
        try:
            order = int(cells[3])
        except ValueError:
            raise fail(
                f"state {k + 1}: derivative order {cells[3]!r} is not 1 or 2", i + 1
            ) from None
        states.append(State(cells[2] == "T", order, " ".join(cells[4:])))
    at = next((i for i, ln in enumerate(lines) if ln.strip().startswith("A:")), None)
    if at is None:
        raise fail("no state matrix 'A:' (linearise with continuous states and no Jacobians only)")
    rows = []
    for k in range(n):
        i = at + 1 + k
        try:
            row = [float(t) for t in lines[i].split()]
        except (IndexError, ValueError):
            raise fail(
                f"row {k + 1} of A is missing or holds a cell that is not a number", i + 1
            ) from None
        if len(row) != n:
            raise fail(f"row {k + 1} of A has {len(row)} numbers, expected {n}", i + 1)
        rows.append(row)
    a = np.array(rows)
    if not np.all(np.isfinite(a)):
        raise fail("A holds numbers that are not finite")
    return LinFile(path, speed, azimuth, wind, tuple(states), a)


def files_of(path: Path) -> dict[str, list[Path]]:
    """The ``.lin`` files to read, by operating point (root): a named file's siblings, or a
    folder's files."""
    if path.is_dir():
        found = sorted(p for p in path.iterdir() if p.suffix.lower() == ".lin")
        if not found:
            decks = sorted(p.name for p in path.iterdir() if p.suffix.lower() == ".fst")
            hint = f"; to audit its deck set, give {' or '.join(decks)}" if decks else ""
            raise SpecError(f"the folder holds no .lin files{hint}", source=str(path))
    else:
        m = _ROOT.match(path.name)
        if m is None:
            found = [path]
        else:
            pattern = re.compile(rf"^{re.escape(m['root'])}\.\d+\.lin$", re.IGNORECASE)
            found = sorted(p for p in path.parent.iterdir() if pattern.match(p.name))
    groups: dict[str, list[Path]] = defaultdict(list)
    for p in found:
        m = _ROOT.match(p.name)
        groups[m["root"] if m else p.stem].append(p)
    return dict(groups)


@dataclass(frozen=True)
class PointModes:
    rpm: float
    wind: float | None
    frequency_hz: Array
    damping_ratio: Array
    names: tuple[str, ...]
    descriptions: tuple[str, ...]
    whirl: tuple[str, ...]
    shapes: NDArray[np.complex128]  # weighted displacements, multi-blade coordinates


def _even(files: list[LinFile]) -> bool:
    """Whether an operating point's azimuths are at least three and evenly spaced round the
    rotor (no gap more than half again the even spacing)."""
    if len(files) < 3:
        return False
    psi = np.sort(np.mod([f.azimuth for f in files], 2 * np.pi))
    gaps = np.diff(np.append(psi, psi[0] + 2 * np.pi))
    return bool(gaps.max() <= 1.5 * 2 * np.pi / len(files))


def operating_point(files: list[LinFile]) -> tuple[PointModes, int]:
    """MBC3 over the azimuths of one point, the modes and the number of blades."""
    first = files[0]
    for f in files[1:]:
        if [s.description for s in f.states] != [s.description for s in first.states]:
            raise SpecError(
                f"its states differ from {first.path.name}'s: not the same model",
                source=str(f.path),
            )
        if not math.isclose(f.rotor_speed, first.rotor_speed, rel_tol=1e-3, abs_tol=1e-6):
            raise SpecError(
                f"rotor speed {f.rotor_speed:g} rad/s, {first.path.name} has "
                f"{first.rotor_speed:g}: not one operating point",
                source=str(f.path),
            )
    states = first.states
    n = len(states)
    second = [i for i, s in enumerate(states) if s.order == 2]
    n2 = len(second) // 2
    if len(second) % 2 or second != list(range(2 * n2)):
        raise SpecError(
            "the second-order states are not the displacements followed by their rates",
            source=str(first.path),
        )
    groups, blades = _triplets(states[:n2], first.path)
    first_order = list(range(2 * n2, n))
    groups1, blades1 = _triplets(states[2 * n2 :], first.path, offset=2 * n2)
    if blades1 and blades and blades1 != blades:
        raise SpecError(
            "first- and second-order states disagree on the blades", source=str(first.path)
        )
    nb = blades or blades1 or 3
    omega = first.rotor_speed
    a_nr = np.zeros((n, n))
    for f in files:
        t1, t2, t3 = _transform(n2, groups, nb, f.azimuth)
        f1, f2, _ = _transform(
            len(first_order), [[g - 2 * n2 for g in grp] for grp in groups1], nb, f.azimuth
        )
        t = np.zeros((n, n))
        tdot = np.zeros((n, n))
        t[:n2, :n2] = t1
        t[n2 : 2 * n2, n2 : 2 * n2] = t1
        t[n2 : 2 * n2, :n2] = omega * t2
        tdot[:n2, :n2] = omega * t2
        tdot[n2 : 2 * n2, n2 : 2 * n2] = omega * t2
        tdot[n2 : 2 * n2, :n2] = omega**2 * t3
        t[2 * n2 :, 2 * n2 :] = f1
        tdot[2 * n2 :, 2 * n2 :] = omega * f2
        a_nr += np.linalg.solve(t, f.a @ t - tdot)
    a_nr /= len(files)
    lam, vec = np.linalg.eig(a_nr)
    keep = np.where(lam.imag > 1e-6)[0]
    keep = keep[np.argsort(np.abs(lam[keep]))][:MODES_KEPT]
    lam, vec = lam[keep], vec[:, keep]
    labels = _labels(states[:n2], groups)
    names: list[str] = []
    texts: list[str] = []
    whirls: list[str] = []
    weight = np.array([_weight(s.description) for s in states[:n2]])
    shapes = vec[:n2, :] * weight[:, None]
    for j in range(len(lam)):
        x = shapes[:, j]
        name, text, whirl = _name(x, labels)
        k = 2
        base = name
        while name in names:
            name, k = f"{base}_{k}", k + 1
        names.append(name)
        texts.append(text)
        whirls.append(whirl)
    f_hz = np.abs(lam) / (2 * math.pi)
    zeta = -lam.real / np.abs(lam)
    rpm = omega * 30 / math.pi
    point = PointModes(
        rpm, first.wind, f_hz, zeta, tuple(names), tuple(texts), tuple(whirls), shapes
    )
    return point, nb


def _triplets(
    states: tuple[State, ...], path: Path, offset: int = 0
) -> tuple[list[list[int]], int]:
    """Indices (blade 1, 2, …) of each rotating DOF, and the number of blades."""
    by_dof: dict[str, dict[int, int]] = defaultdict(dict)
    for i, s in enumerate(states):
        if not s.rotating:
            continue
        m = _BLADE.search(s.description)
        if m is None:
            raise SpecError(
                f"rotating state {offset + i + 1} ({s.description[:60]}) names no blade",
                source=str(path),
            )
        by_dof[_BLADE.sub("blade #", _INTERNAL.sub("", s.description))][int(m.group(1))] = (
            offset + i
        )
    counts = {len(v) for v in by_dof.values()}
    if len(counts) > 1:
        raise SpecError(
            "the rotating states do not hold every DOF for every blade", source=str(path)
        )
    nb = counts.pop() if counts else 0
    if nb and nb < 3:
        raise SpecError(
            f"{nb} blades: the multi-blade transformation needs three or more (a two-bladed "
            "rotor stays periodic)",
            source=str(path),
        )
    return [[v[b] - offset for b in sorted(v)] for v in by_dof.values()], nb


def _transform(
    size: int, groups: list[list[int]], blades: int, psi: float
) -> tuple[Array, Array, Array]:
    """T1, dT1/dψ, d²T1/dψ² of the multi-blade transformation of ``size`` states."""
    t1, t2, t3 = np.eye(size), np.zeros((size, size)), np.zeros((size, size))
    if not groups:
        return t1, t2, t3
    b, db, d2b, _ = coleman(blades, psi)
    for grp in groups:
        idx = np.asarray(grp)
        t1[np.ix_(idx, idx)] = b
        t2[np.ix_(idx, idx)] = db
        t3[np.ix_(idx, idx)] = d2b
    return t1, t2, t3


def _weight(description: str) -> float:
    """How much one unit of a displacement state weighs in naming (see the constants)."""
    if description.rstrip().endswith(("rad", "rad/s")) or "yaw" in description.lower():
        return ROTATION_ARM_M
    return TOWER_WEIGHT if "tower" in description.lower() else 1.0


#: Name stems of ElastoDyn's DOF descriptions.
_KINDS = (
    ("1st tower fore-aft", "tower.fa1", "1st tower fore-aft"),
    ("2nd tower fore-aft", "tower.fa2", "2nd tower fore-aft"),
    ("1st tower side-to-side", "tower.ss1", "1st tower side-side"),
    ("2nd tower side-to-side", "tower.ss2", "2nd tower side-side"),
    ("nacelle yaw", "yaw1", "nacelle yaw"),
    ("drivetrain", "drivetrain1", "drive-train torsion"),
    ("generator", "drivetrain1", "drive-train torsion"),
    ("1st flapwise", "blade.flap1", "1st blade flapwise"),
    ("2nd flapwise", "blade.flap2", "2nd blade flapwise"),
    ("1st edgewise", "blade.edge1", "1st blade edgewise"),
)


def _labels(states: tuple[State, ...], groups: list[list[int]]) -> list[tuple[str, str, str]]:
    """(name stem, words, coordinate) per displacement state in multi-blade coordinates."""
    _, _, _, coords = coleman(max((len(g) for g in groups), default=3), 0.0)
    out: list[tuple[str, str, str]] = []
    member = {i: (gi, k) for gi, grp in enumerate(groups) for k, i in enumerate(grp)}
    for i, s in enumerate(states):
        low = s.description.lower()
        stem, words = next(
            ((n, w) for key, n, w in _KINDS if key in low), ("other", s.description[:40])
        )
        coord = coords[member[i][1]] if i in member else "fixed"
        out.append((stem, words, coord))
    return out


def _name(x: NDArray[np.complex128], labels: list[tuple[str, str, str]]) -> tuple[str, str, str]:
    """Name, description and whirl of a mode from its displacement in multi-blade
    coordinates."""
    energy = np.abs(x) ** 2
    share: dict[tuple[str, str], float] = defaultdict(float)
    for e, (stem, _, coord) in zip(energy, labels, strict=True):
        share[(stem, "cyclic" if coord.startswith(("cos", "sin")) else coord)] += float(e)
    stem, coord = max(share, key=lambda k: share[k])
    words = next(w for s, w, _ in labels if s == stem)
    if coord == "fixed":
        return stem, words, "fixed"
    if coord == "collective":
        return f"{stem}.collective", f"{words}, collective", "collective"
    if coord == "alternating":
        return f"{stem}.alternating", f"{words}, alternating", "fixed"
    c = next(x[i] for i, lab in enumerate(labels) if lab[0] == stem and lab[2] == "cos1")
    s = next(x[i] for i, lab in enumerate(labels) if lab[0] == stem and lab[2] == "sin1")
    whirl = float(np.imag(np.conj(c) * s))
    turn = "forward" if whirl < 0 else "backward"
    return f"{stem}.{turn}", f"{words}, cyclic, {turn} whirl", turn


#: A mode followed from one operating point to the next with a MAC under this is flagged.
TRACK_MAC = 0.5


def _followed(
    points: list[PointModes],
) -> tuple[dict[str, dict[str, Any]], tuple[float, str, float] | None]:
    """Each mode of the first (slowest) point followed point by point by shape (MAC of the
    multi-blade displacements, one optimal assignment per step), with the weakest match."""
    modes: dict[str, dict[str, Any]] = {}
    first = points[0]
    for j, name in enumerate(first.names):
        modes[name] = {
            "description": first.descriptions[j],
            "frame": "fixed",
            "rpm": [],
            "frequency_hz": [],
            "damping_ratio": [],
            "whirl": [],
            "wind_m_s": [],
        }
    current = {name: j for j, name in enumerate(first.names)}  # name → column at this point
    prev = first
    weakest: tuple[float, str, float] | None = None
    for k, pm in enumerate(points):
        if k:
            names = list(current)
            score = mac(prev.shapes[:, [current[n] for n in names]], pm.shapes)
            if score.shape[0] <= score.shape[1]:
                cols = assign(score, optimal=True)
                pairs = list(zip(range(len(names)), cols, strict=True))
            else:  # fewer modes here: each of them finds its predecessor
                rows = assign(score.T, optimal=True)
                pairs = [(int(r), c) for c, r in enumerate(rows)]
            current = {names[r]: int(c) for r, c in pairs}
            for r, c in pairs:
                if weakest is None or score[r, c] < weakest[0]:
                    weakest = (float(score[r, c]), names[r], pm.rpm)
            prev = pm
        for name, j in current.items():
            m = modes[name]
            m["rpm"].append(round(pm.rpm, 6))
            m["frequency_hz"].append(float(pm.frequency_hz[j]))
            m["damping_ratio"].append(max(-1.0, min(1.0, float(pm.damping_ratio[j]))))
            m["whirl"].append(pm.whirl[j])
            m["wind_m_s"].append(pm.wind)
    return modes, weakest


def to_spec_data(path: Path, blades: int | None) -> dict[str, Any]:
    """The wtvib-format dictionary of one or more operating points' ``.lin`` files."""
    groups = files_of(path)
    points = []
    nbs = set()
    read_files: list[str] = []
    uneven: list[str] = []
    for root, paths in sorted(groups.items()):
        lins = [read(p) for p in paths]
        read_files += [str(p) for p in paths]
        pm, nb = operating_point(lins)
        points.append(pm)
        nbs.add(nb)
        if lins[0].rotor_speed > 0 and not _even(lins):
            uneven.append(f"{root} ({len(lins)} at {pm.rpm:.3g} rpm)")
    points.sort(key=lambda p: p.rpm)
    modes, weakest = _followed(points)
    for m in modes.values():
        if any(w is None for w in m["wind_m_s"]):
            del m["wind_m_s"]
    found = max(nbs) if nbs else None
    data = results_spec(
        path,
        "OpenFAST linearisation (MBC3)",
        modes,
        blades,
        read_files,
        f"OpenFAST linearisation {path.name}",
        blades_found=found or None,
    )
    if weakest is not None and weakest[0] < TRACK_MAC:
        data["warnings"].append(
            f"{weakest[1]}: followed to {weakest[2]:.4g} rpm with a MAC of only "
            f"{weakest[0]:.2f} (under {TRACK_MAC}): check that curve"
        )
    if uneven:
        data["warnings"].append(
            "azimuths too few or unevenly spaced for MBC3 to average the rotor's periodic "
            f"terms out (OpenFAST's NLinTimes, at least 3, evenly spaced): {', '.join(uneven)}"
            " — the modes there keep some of them"
        )
    outside = [f for f in read_files if Path(f).parent != (path if path.is_dir() else path.parent)]
    if outside:
        data["warnings"].append(f"files read outside the named folder: {', '.join(outside)}")
    return data
