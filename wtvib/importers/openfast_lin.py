"""OpenFAST linearisation output (``*.lin``): the whole turbine's modes at each operating point.

OpenFAST with ``Linearize = True`` writes, per operating point, the state matrix A at several
rotor azimuths (``root.1.lin`` … ``root.N.lin``). The states come module by module —
ElastoDyn's displacements then its rates, BeamDyn's, SubDyn's, AeroDyn's inflow and
unsteady-aerodynamics states, HydroDyn's, ServoDyn's structural control — each with its
description, frame (rotating or not) and, in newer files, derivative order. This reader:

1. classifies every state from its own row: a displacement and its "First time derivative
   of" rate are a second-order pair (matched by description, module by module, however the
   modules interleave), every other state is first-order; a rotating state belongs to the
   blade its description names (``blade 2``, ``BD_2``);
2. takes the azimuth files of each point into multi-blade coordinates (MBC3, Bir 2008,
   NREL/CP-500-42553: A_NR = T⁻¹(A·T − Ṫ) with the project's one Coleman transformation,
   :func:`wtvib.numerics.coleman.coleman`) and averages them;
3. solves the averaged system once (:func:`wtvib.numerics.modal.state_modes`) and keeps the
   oscillating roots in which the structural states (ElastoDyn, BeamDyn, SubDyn, structural
   control) take part most — by participation factors, which do not depend on the units of
   the states — listing the others (inflow, unsteady aerodynamics, radiation) as
   non-structural, however many there are;
4. names each structural mode by the states that take part in it (tower fore-aft and
   side-side, platform, drive train, yaw, each blade DOF's collective and cyclic
   coordinates), with the share of the largest and the next where the mode is mixed; a
   cyclic mode's whirl comes from the phase of its cos and sin coordinates (forward where
   the sin coordinate lags the cos coordinate by a quarter period: the deflection pattern
   turns with the rotor; proven on a rotor of uncoupled blades, whose forward mode is the
   one at f + Ω);
5. follows each mode from point to point by shape (the participation of the structural
   coordinates, the whirl kept), naming a curve after its first point.

Reading: only the files of one root (a named ``.lin`` file's siblings ``root.<k>.lin``) or
the ``.lin`` files of a named folder, each read through the same guards as any input (a
regular file, a size limit); OpenFAST's per-module files (``root.1.ED.lin``) are not the
whole system and are left out (and refused where named).
"""

import math
import re
from collections import defaultdict
from dataclasses import dataclass, field, replace
from datetime import date
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import SpecError
from ..numerics.coleman import coleman
from ..numerics.modal import ModalError, assign, damping_ratio, mac, state_modes
from ..spec import read_bytes
from ..spec.load import MAX_FILE_BYTES
from .campbell_results import results_spec

Array = NDArray[np.float64]

#: The largest azimuth a header may give [rad] (OpenFAST writes it within one turn).
MAX_AZIMUTH = 1e6

#: A linearisation's header — everything before A: the operating point, the state, input
#: and output tables — is read up to this size, unless WTVIB_MAX_BYTES sets one; then A's
#: n rows, each at most :data:`ROW_BYTES` a number; B, C, D and the rest are not read.
LIN_MAX_BYTES = 4 * MAX_FILE_BYTES
#: The most bytes a number of A may take in its row (OpenFAST writes 21: ' -1.234567890123E+000').
ROW_BYTES = 40
#: At most this many continuous states: the dense eigen-solution of A grows with n³ (5,000
#: states: a minute and 2 GB on one core).
MAX_STATES = 5_000
#: A mode is structural where the structural states hold at least this share of it.
STRUCTURAL_SHARE = 0.5
#: A mode whose largest coordinate group holds less than this share is called mixed.
MIXED_SHARE = 0.6
#: A cyclic mode whirls where |Im(c̄·s)| is at least this fraction of (|c|² + |s|²)/2
#: (a standing pattern — parked, or a degenerate pair — has none).
WHIRL_FRACTION = 0.2

_ROOT = re.compile(r"^(?P<root>.+)\.(?P<k>\d+)\.lin$", re.IGNORECASE)
#: OpenFAST's per-module linearisation files (LinOutMod): root.1.ED.lin, root.1.BD1.lin
_MODULE_FILE = re.compile(r"^.+\.\d+\.[A-Za-z]+\d*\.lin$", re.IGNORECASE)
_BLADE = re.compile(r"\b[Bb]lade (\d+)\b")
_BD = re.compile(r"^BD_(\d+)$")
#: ElastoDyn's "(internal DOF index = DOF_BF(1,1))": blade-specific, not part of the DOF.
_INTERNAL = re.compile(r"\s*\(internal DOF index = [^()]*(\([^()]*\))?\)")
_RATE = "First time derivative of "
#: Modules whose states are the structure's (the rest: inflow, aerodynamics, hydrodynamic
#: radiation and excitation, mooring lines, controllers).
STRUCTURAL = frozenset({"ED", "BD", "SD", "ExtPtfm", "SrvD"})
#: DOFs free to move without a restoring force: where their own stiffness term
#: −A[q̇ᵢ, qᵢ] = ωᵢ² puts them under this frequency [Hz] (a yaw, furl or teeter DOF without
#: its spring; a platform without moorings). A root held at least half by them and the
#: generator azimuth — a quarter by them — is rigid-body motion (the rotor turning with a
#: free nacelle), which one azimuth's periodic terms turn into a spurious root (OpenFAST
#: r-test 5MW_OC3Mnpl_Linear: 0.02 Hz, ζ = ±0.76); the generator azimuth alone is no
#: sign (it carries the drive-train torsion of a BeamDyn rotor).
FREE_BELOW_HZ = (("nacelle yaw", 0.05), ("furl", 0.05), ("teeter", 0.05), ("platform", 0.001))
RIGID_SHARE, FREE_SHARE, TURNING_SHARE = 0.5, 0.25, 0.05
#: Two roots are mirror images (λ and −λ̄, :func:`_mirror_images`) within this share of
#: |λ|: rounding keeps the symmetry of an undamped motion to ~κ·ε; a damped structure's
#: roots are nowhere near it.
MIRROR = 1e-6
#: A root grows where ζ < −this (rounding writes an undamped root as ±1e-12 or so).
GROWING = 1e-6
#: The modules of the non-structural states, as a reader knows them.
MODULE_WORDS = {
    "AD": "AeroDyn (inflow, unsteady aerodynamics)",
    "HD": "HydroDyn (radiation, excitation)",
    "MD": "MoorDyn (mooring lines)",
    "IfW": "InflowWind",
    "rigid": "rigid-body motion (the rotor turning, a free nacelle yaw)",
    "images": "numerical images of rigid-body motion (pairs λ, −λ̄ below the first elastic mode)",
}


# ------------------------------------------------------------------------------------------
# Reading one file


@dataclass(frozen=True)
class State:
    """One continuous state: its module (``BD`` for ``BD_2``), frame, derivative order as
    the file gives it (None: an older file without the column), its description, and the
    blade it belongs to."""

    module: str
    rotating: bool
    order: int | None
    description: str
    blade: int | None
    line: int

    @property
    def text(self) -> str:
        """The description without the module token and the unit."""
        body = self.description.split(" ", 1)[1] if " " in self.description else ""
        return body.rsplit(",", 1)[0].strip() if "," in body else body.strip()


@dataclass(frozen=True)
class LinFile:
    path: Path
    rotor_speed: float  # rad/s
    azimuth: float  # rad
    wind: float | None  # m/s
    states: tuple[State, ...]
    a: Array
    rates: Array | None = None  # the operating point's state derivatives ẋ_op (where given)
    description: str | None = None  # the deck's title, as the header quotes it
    generated: date | None = None  # the day OpenFAST wrote it, as the header says
    version: tuple[int, int, int] | None = None  # the OpenFAST release it names (vX.Y.Z)
    pitch: tuple[float, ...] | None = None  # each blade's pitch command [rad], from the inputs

    def speed(self, lay: "Layout") -> tuple[float, float]:
        """Rotor speed Ω [rad/s] and its rate Ω̇ [rad/s²] at this azimuth, as MBC3 takes
        them (NREL's MBC3 and openfast_toolbox's ``get_Mats``): the operating point's rate
        of ElastoDyn's generator azimuth (else the header's speed) plus that of its
        drive-train twist — the rotor's own speed at this instant, which a point not
        trimmed to steady state makes differ from the header's mean."""
        if self.rates is None:
            return self.rotor_speed, 0.0
        omega, omega_dot = self.rotor_speed, 0.0
        if lay.generator >= 0:
            omega = float(self.rates[lay.q[lay.generator]])
            omega_dot = float(self.rates[lay.qd[lay.generator]])
        if lay.twist >= 0:
            omega += float(self.rates[lay.q[lay.twist]])
            omega_dot += float(self.rates[lay.qd[lay.twist]])
        return omega, omega_dot


def lin_max_bytes() -> int:
    """The size limit of a linearisation file: WTVIB_MAX_BYTES if set, else
    :data:`LIN_MAX_BYTES`."""
    import os

    from ..spec.load import max_file_bytes

    return max_file_bytes() if os.environ.get("WTVIB_MAX_BYTES") else LIN_MAX_BYTES


def _raw(path: Path) -> tuple[bytes, "re.Match[bytes] | None"]:
    """The file's bytes up to the end of its state matrix A (read no further), and the
    match of A's ``A: n x n`` line (None: no such line)."""
    raw = read_bytes(path, max_bytes=lin_max_bytes(), head=True)
    if b"\x00" in raw:
        raise SpecError("binary file, not an OpenFAST linearisation", source=str(path))
    marker = re.search(rb"^[ \t]*A:[ \t]*(\S+)[ \t]*x[ \t]*(\S+)", raw, re.MULTILINE)
    if marker is not None and marker.group(1).isdigit() and marker.group(1) == marker.group(2):
        n_a = min(int(marker.group(1)), MAX_STATES)  # A's rows: read them, not what follows
        need = marker.end() + n_a * (n_a * ROW_BYTES + 2)
        if len(raw) < lin_max_bytes() or need <= len(raw):  # the head read holds A already
            raw = raw[:need]
        else:
            raw = read_bytes(path, max_bytes=need, head=True)
            if b"\x00" in raw:
                raise SpecError("binary file, not an OpenFAST linearisation", source=str(path))
    elif marker is None and len(raw) == lin_max_bytes():
        raise SpecError(
            f"no state matrix 'A:' in the first {len(raw):,} bytes: not an OpenFAST "
            "linearisation, or its input and output tables are over that limit "
            "(WTVIB_MAX_BYTES)",
            source=str(path),
        )
    return raw, marker


def read(path: Path) -> LinFile:
    """One ``.lin`` file: the operating point, the continuous states and A."""
    if _MODULE_FILE.match(path.name):
        root = _MODULE_FILE.sub("", path.name)
        whole = re.sub(r"\.[A-Za-z]+\d*\.lin$", ".lin", path.name, flags=re.IGNORECASE)
        raise SpecError(
            f"one module's own linearisation, not the whole system's{root}: give {whole}",
            source=str(path),
        )
    raw, marker = _raw(path)
    head = raw[: marker.start() if marker else len(raw)].decode("utf-8", errors="replace")
    lines = head.splitlines()

    def fail(message: str, line: int | None = None) -> SpecError:
        return SpecError(message, line=line, source=str(path))

    def value(label: str, required: bool = True) -> tuple[float | None, int]:
        for i, ln in enumerate(lines[:200]):
            if ln.strip().startswith(label):
                tokens = ln.split(":", 1)[1].split()
                if not tokens:
                    raise fail(f"'{label}' gives no value", i + 1)
                try:
                    v = float(tokens[0])
                except ValueError:
                    raise fail(f"{label} {tokens[0][:40]!r} is not a number", i + 1) from None
                if not math.isfinite(v):
                    raise fail(f"{label} {tokens[0]} is not a finite number", i + 1)
                return v, i + 1
        if required:
            raise fail(f"no '{label}' line: not an OpenFAST linearisation file")
        return None, 0

    speed, speed_line = value("Rotor Speed:")
    azimuth, azimuth_line = value("Azimuth:")
    wind, wind_line = value("Wind Speed:", required=False)
    count, n_line = value("Number of continuous states:")
    assert speed is not None and azimuth is not None and count is not None
    if not 0 <= speed <= 1000:  # rad/s: 0 … ~9,500 rpm, as the spec bounds rotor speeds
        raise fail(
            f"Rotor Speed {speed:g} rad/s is not a rotor speed (0 to 1000 rad/s)", speed_line
        )
    if abs(azimuth) > MAX_AZIMUTH:  # a rotor turned a million radians is a broken header
        raise fail(
            f"Azimuth {azimuth:g} rad is not a rotor azimuth (|ψ| ≤ {MAX_AZIMUTH:g} rad)",
            azimuth_line,
        )
    azimuth = math.remainder(azimuth, 2 * math.pi)
    if wind is not None and not 0 <= wind <= 100:
        raise fail(f"Wind Speed {wind:g} m/s is not a wind speed (0 to 100 m/s)", wind_line)
    if count != int(count) or not 0 <= count <= MAX_STATES:
        raise fail(
            f"Number of continuous states {count:g} is not a count of at most {MAX_STATES:,}",
            n_line,
        )
    n = int(count)
    if n == 0:
        raise fail("the file holds no continuous states: no modes to find", n_line)
    states = _states(lines, n, fail)
    rates = _rates(lines, n)
    if marker is None:
        raise fail("no state matrix 'A:' (linearise with continuous states)")
    a = _matrix(raw, marker, n, fail)
    return LinFile(
        path, speed, azimuth, wind, states, a, rates, _description(lines), _generated(lines),
        _version(lines), _pitch(lines),
    )  # fmt: skip


_GENERATED = re.compile(r"generated on (\d{1,2})-([A-Za-z]{3})-(\d{4})")
_MONTHS = ("jan", "feb", "mar", "apr", "may", "jun", "jul", "aug", "sep", "oct", "nov", "dec")


def _generated(lines: list[str]) -> date | None:
    """The day the header says OpenFAST wrote the file ("Predictions were generated on
    29-Aug-2024 at …"), None where it says none or no real day."""
    for ln in lines[:10]:
        found = _GENERATED.search(ln)
        if found and found[2].lower() in _MONTHS:
            try:
                return date(int(found[3]), _MONTHS.index(found[2].lower()) + 1, int(found[1]))
            except ValueError:
                return None
    return None


_VERSION = re.compile(r"\bv(\d+)\.(\d+)\.(\d+)")


def _version(lines: list[str]) -> tuple[int, int, int] | None:
    """The OpenFAST release the header's first lines name ("using OpenFAST-v4.0.2", "at
    commit v3.5.2-957-g05b14cf": a build after that release), None where they name none."""
    for ln in lines[:10]:
        if "OpenFAST" in ln or "commit" in ln:
            found = _VERSION.search(ln)
            if found:
                return int(found[1]), int(found[2]), int(found[3])
    return None


_PITCH = re.compile(r"ED Blade (\d+) pitch command, rad")


def _pitch(lines: list[str]) -> tuple[float, ...] | None:
    """Each blade's pitch command at the operating point [rad], from the inputs' table
    ("ED Blade 1 pitch command, rad"), None where the file has no such inputs (the table
    left out, or the numbers not finite)."""
    start = next(
        (i for i, ln in enumerate(lines) if ln.strip().startswith("Order of inputs")), None
    )
    if start is None:
        return None
    found: dict[int, float] = {}
    for ln in lines[start + 3 :]:
        if not ln.strip() or not ln.split()[0].isdigit():
            break
        hit = _PITCH.search(ln)
        if hit:
            try:
                value = float(ln.split()[1].rstrip(","))
            except (IndexError, ValueError):
                return None
            if not math.isfinite(value):
                return None
            found[int(hit[1])] = value
    if not found or sorted(found) != list(range(1, len(found) + 1)):
        return None
    return tuple(found[k] for k in sorted(found))


#: The header line that carries the deck's own title (the .fst file's second line).
_DESCRIBED = "Description from the FAST input file:"


def _description(lines: list[str]) -> str | None:
    """The deck's title as the header quotes it (``NREL 5.0 MW Baseline Wind Turbine
    (Onshore), Linearization with AeroDyn + ED``), None where it gives none."""
    for ln in lines[:20]:
        text = ln.strip()
        if text.startswith(_DESCRIBED):
            found = " ".join(text.removeprefix(_DESCRIBED).split())[:120]
            return found or None
    return None


def _rates(lines: list[str], n: int) -> Array | None:
    """The operating point's state derivatives (the "Order of continuous state derivatives"
    table's values), or None where the table is missing or not numbers."""
    start = next(
        (
            i
            for i, ln in enumerate(lines)
            if ln.strip().startswith("Order of continuous state derivatives")
        ),
        None,
    )
    if start is None or start + 3 + n > len(lines):
        return None
    out = np.empty(n)
    for k in range(n):
        cells = lines[start + 3 + k].split()
        try:
            out[k] = float(cells[1].rstrip(","))
        except (IndexError, ValueError):
            return None
    return out if np.all(np.isfinite(out)) else None


def _states(lines: list[str], n: int, fail: Any) -> tuple[State, ...]:
    """The table of continuous states (module, frame, order, description, blade)."""
    start = next(
        (i for i, ln in enumerate(lines) if ln.strip().startswith("Order of continuous states")),
        None,
    )
    if start is None:
        raise fail("no 'Order of continuous states:' table")
    header = lines[start + 1] if start + 1 < len(lines) else ""
    has_order = "Derivative Order" in header
    out = []
    for k in range(n):
        i = start + 3 + k
        cells = lines[i].split() if i < len(lines) else []
        j = 1
        while j < len(cells) and cells[j].endswith(","):  # an orientation: three values
            j += 1
        if len(cells) < j + 3 or cells[j + 1] not in ("T", "F"):
            raise fail(f"state {k + 1} of {n} missing or malformed in the table", i + 1)
        order: int | None = None
        rest = cells[j + 2 :]
        if has_order:
            if rest[0] not in ("1", "2"):
                raise fail(f"state {k + 1}: derivative order {rest[0][:20]!r} is not 1 or 2", i + 1)
            order, rest = int(rest[0]), rest[1:]
        if not rest:
            raise fail(f"state {k + 1} has no description", i + 1)
        description = " ".join(rest)
        token = rest[0]
        bd = _BD.match(token)
        module = "BD" if bd else token
        blade = int(bd.group(1)) if bd else None
        if blade is None and (m := _BLADE.search(description)) is not None:
            blade = int(m.group(1))
        out.append(State(module, cells[j + 1] == "T", order, description, blade, i + 1))
    return tuple(out)


def _matrix(raw: bytes, marker: "re.Match[bytes]", n: int, fail: Any) -> Array:
    """A, read as one block of numbers (no Python loop per number)."""
    line = raw[: marker.start()].count(b"\n") + 1
    if marker.group(1) != str(n).encode() or marker.group(2) != str(n).encode():
        raise fail(
            f"A is {marker.group(1)[:20]!r} x {marker.group(2)[:20]!r}, expected {n} x {n}", line
        )
    body_start = raw.find(b"\n", marker.end())
    if body_start < 0:
        raise fail("A has no rows", line)
    end = body_start + 1
    for _ in range(n):  # A's n rows, a line each (OpenFAST's layout); B … follow
        newline = raw.find(b"\n", end)
        end = len(raw) if newline < 0 else newline + 1
    body = raw[body_start + 1 : end]
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # numpy says where parsing stopped; we say which row
        try:
            values = np.fromstring(body, sep=" ")
        except ValueError:  # numpy ≥ 2.3 raises where older ones warned and stopped
            values = np.zeros(0)
    if values.size != n * n or not np.all(np.isfinite(values)):
        rows = body.decode("ascii", errors="replace").splitlines()
        for r in range(n):
            cells = rows[r].split() if r < len(rows) else []
            try:
                numbers = [float(c) for c in cells]
            except ValueError:
                bad = next(c for c in cells if not _is_number(c))
                raise fail(
                    f"row {r + 1} of A holds {bad[:20]!r}, not a number", line + 1 + r
                ) from None
            if len(numbers) != n:
                raise fail(
                    f"row {r + 1} of A has {len(numbers)} numbers, expected {n}", line + 1 + r
                )
            if not all(math.isfinite(x) for x in numbers):
                raise fail(f"row {r + 1} of A holds numbers that are not finite", line + 1 + r)
        raise fail(f"A holds {values.size} numbers, expected {n} x {n}", line)
    return values.reshape(n, n)


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def files_of(path: Path) -> dict[str, list[Path]]:
    """The ``.lin`` files to read, by operating point (root): a named file's siblings, or a
    folder's files (OpenFAST's per-module files left out)."""
    if path.is_dir():
        try:
            names = sorted(p for p in path.iterdir() if p.suffix.lower() == ".lin")
        except OSError as exc:
            raise SpecError(
                f"cannot list the folder: {exc.strerror or exc}", source=str(path)
            ) from None
        found = [p for p in names if not _MODULE_FILE.match(p.name)]
        if not found:
            decks = sorted(p.name for p in path.iterdir() if p.suffix.lower() == ".fst")
            hint = f"; to audit its deck set, give {' or '.join(decks)}" if decks else ""
            what = "only per-module .lin files" if names else "no .lin files"
            raise SpecError(f"the folder holds {what}{hint}", source=str(path))
    else:
        m = _ROOT.match(path.name)
        if m is None or _MODULE_FILE.match(path.name):
            found = [path]
        else:
            pattern = re.compile(rf"^{re.escape(m['root'])}\.\d+\.lin$", re.IGNORECASE)
            try:
                found = sorted(p for p in path.parent.iterdir() if pattern.match(p.name))
            except OSError as exc:
                raise SpecError(
                    f"cannot list its folder: {exc.strerror or exc}", source=str(path)
                ) from None
            found = found or [path]
    groups: dict[str, list[Path]] = defaultdict(list)
    for p in found:
        m = _ROOT.match(p.name)
        groups[m["root"] if m else p.stem].append(p)
    return dict(groups)


# ------------------------------------------------------------------------------------------
# The states' layout: second-order pairs, first-order states, blade triplets


@dataclass(frozen=True)
class Layout:
    """Where each state goes: the displacements ``q`` (indices into the file's states), their
    rates ``qd`` (aligned), the first-order states; per blade DOF, the positions (within
    q, and within the first-order states) of blade 1 … N; the number of blades."""

    q: NDArray[np.intp]
    qd: NDArray[np.intp]
    first: NDArray[np.intp]
    triplets_q: NDArray[np.intp]  # (DOFs, blades)
    triplets_1: NDArray[np.intp]
    blades: int
    dofs: tuple[str, ...]  # per q position: the DOF (blade number replaced), for naming
    q_modules: tuple[str, ...]
    first_modules: tuple[str, ...]
    free: NDArray[np.bool_]  # per q position: free to move (FREE_BELOW_HZ)
    azimuth: NDArray[np.bool_]  # per q position: ElastoDyn's generator azimuth
    generator: int  # q position of ElastoDyn's generator azimuth (−1: none)
    twist: int  # q position of its drive-train twist (−1: none)

    @property
    def order(self) -> NDArray[np.intp]:
        return np.concatenate([self.q, self.qd, self.first])


def layout(
    states: tuple[State, ...], path: Path, rotor_speed: float, a: Array | None = None
) -> Layout:
    """Second-order pairs by description ("X" and "First time derivative of X", module by
    module), the rest first-order; blade triplets by DOF; the DOFs free to move (from A's
    own stiffness terms, where A is given)."""
    q: list[int] = []
    qd: list[int] = []
    first: list[int] = []
    for run in _runs(states):
        tokens = states[run[0]].description.split(" ", 1)[0]
        order = states[run[0]].order
        half = len(run) // 2
        rates = [states[i].text.startswith(_RATE) for i in run[half:]]
        if order is None:  # an older file without the column: the rates' names tell
            order = 2 if len(run) % 2 == 0 and all(rates) and half else 1
        if order == 1:
            first += run
            continue
        if len(run) % 2:
            s = states[run[-1]]
            raise SpecError(
                f"{tokens}'s {len(run)} second-order states (to line {s.line}) are not "
                "displacements and their rates in two halves",
                line=s.line,
                source=str(path),
            )
        q += run[:half]
        qd += run[half:]
    trip_q, nb_q = _triplets([states[i] for i in q], path)
    trip_1, nb_1 = _triplets([states[i] for i in first], path)
    if nb_q and nb_1 and nb_q != nb_1:
        raise SpecError(
            f"the structural states have {nb_q} blades, the others {nb_1}", source=str(path)
        )
    nb = nb_q or nb_1
    if nb == 2 and rotor_speed > 0:
        raise SpecError(
            "2 blades: the multi-blade transformation needs three or more (a two-bladed "
            "rotor's equations stay periodic in the fixed frame)",
            source=str(path),
        )
    dofs = tuple(_dof(states[i]) for i in q)
    free = np.zeros(len(q), dtype=bool)
    azimuth = np.zeros(len(q), dtype=bool)
    for pos, (i, j) in enumerate(zip(q, qd, strict=True)):
        if states[i].module != "ED":
            continue
        azimuth[pos] = "variable speed generator" in dofs[pos].lower()
        limit = next((hz for key, hz in FREE_BELOW_HZ if key in dofs[pos].lower()), None)
        free[pos] = limit is not None and a is not None and -a[j, i] < (2 * math.pi * limit) ** 2
    return Layout(
        np.asarray(q, dtype=np.intp),
        np.asarray(qd, dtype=np.intp),
        np.asarray(first, dtype=np.intp),
        trip_q,
        trip_1,
        nb,
        dofs,
        tuple(states[i].module for i in q),
        tuple(states[i].module for i in first),
        free,
        azimuth,
        next((p for p, i in enumerate(q) if "DOF_GeAz" in states[i].description), -1),
        next((p for p, i in enumerate(q) if "DOF_DrTr" in states[i].description), -1),
    )


def _runs(states: tuple[State, ...]) -> list[list[int]]:
    """The states in runs of one module (``BD_1`` and ``BD_2`` apart) and one derivative
    order: OpenFAST writes each module's displacements, then their rates, then its
    first-order states."""
    out: list[list[int]] = []
    key = None
    for i, s in enumerate(states):
        k = (s.description.split(" ", 1)[0], s.order)
        if k != key:
            out.append([])
            key = k
        out[-1].append(i)
    return out


def _dof(s: State) -> str:
    """A state's DOF with its blade number and ElastoDyn's internal index taken out."""
    text = _INTERNAL.sub("", s.text)
    return f"{s.module} {_BLADE.sub('blade #', text)}"


def _triplets(states: list[State], path: Path) -> tuple[NDArray[np.intp], int]:
    """For each rotating DOF, the positions of its blade 1 … N states; N."""
    by_dof: dict[tuple[str, int], dict[int, int]] = defaultdict(dict)
    count: dict[tuple[int, str], int] = defaultdict(int)
    for i, s in enumerate(states):
        if not s.rotating:
            continue
        if s.blade is None:
            raise SpecError(
                f"rotating state ({s.description[:70]}) names no blade",
                line=s.line,
                source=str(path),
            )
        dof = _dof(s)
        k = count[(s.blade, dof)]  # BeamDyn writes its three rotations alike: by order
        count[(s.blade, dof)] += 1
        by_dof[(dof, k)][s.blade] = i
    if not by_dof:
        return np.zeros((0, 0), dtype=np.intp), 0
    blades = sorted({b for v in by_dof.values() for b in v})
    nb = len(blades)
    if blades != list(range(1, nb + 1)):
        raise SpecError(f"the rotating states name blades {blades}, not 1 … {nb}", source=str(path))
    for (dof, _), v in by_dof.items():
        missing = [b for b in blades if b not in v]
        if missing:
            raise SpecError(
                f"the rotating DOF '{dof[:60]}' has no state for blade {missing[0]}",
                source=str(path),
            )
    rows = [[v[b] for b in blades] for v in by_dof.values()]
    return np.asarray(rows, dtype=np.intp), nb


# ------------------------------------------------------------------------------------------
# Multi-blade coordinates


def mbc_average(files: list[LinFile], lay: Layout) -> Array:
    """A in multi-blade coordinates (displacements, rates, first-order states), averaged over
    the azimuths (Bir 2008): with q = T·z, q̇ = T·ż + Ω·T′·z, x₁ = T·y,
    ż = T⁻¹(A·L·X − Ω·T′·z) and z̈ = T⁻¹(A·L·X − (Ω²·T″ + Ω̇·T′)·z − 2Ω·T′·ż) row block by
    row block, only the rotating rows and columns changed; Ω and Ω̇ at each azimuth as
    :meth:`LinFile.speed` gives them."""
    order = lay.order
    n2 = len(lay.q)
    # the rotating states' triplets (a state per blade) as rows and columns of each file's A,
    # which is transformed in its own order and the average reordered once: the q block,
    # their rates, the first-order states; only their rows and columns change, and they
    # are summed over the azimuths apart (no copy of a whole A per azimuth)
    width = max(lay.blades, 1)  # a triplet's states: one a blade
    gq = order[lay.triplets_q].reshape(-1, width)
    gd = order[lay.triplets_q + n2].reshape(-1, width)
    g1 = order[lay.triplets_1 + 2 * n2].reshape(-1, width)
    turned = np.concatenate([gq.ravel(), gd.ravel(), g1.ravel()])

    def own(g: NDArray[np.intp]) -> tuple[NDArray[np.intp], ...]:
        """A column group's entries (row, DOF, blade) in the rows of ``g``, DOF for DOF: each
        DOF's own blades' block."""
        return g[:, :, None], np.arange(len(g))[:, None, None], np.arange(width)[None, None, :]

    total = np.zeros_like(files[0].a)
    columns = np.zeros((total.shape[0], turned.size))  # the turned columns, summed
    rows = np.zeros((turned.size, total.shape[0]))  # the turned rows, summed
    for f in files:
        a = f.a
        total += a
        if lay.blades < 3:
            continue
        omega, omega_dot = f.speed(lay)
        b, db, d2b, _ = coleman(lay.blades, f.azimuth)
        binv = np.linalg.inv(b)
        # columns: A·L, each group as (every row, DOF, blade)
        cq, cd, c1 = a[:, gq] @ b + omega * (a[:, gd] @ db), a[:, gd] @ b, a[:, g1] @ b
        # − Ṫ terms, block by block on each DOF's own blades
        cq[own(gq)] -= omega * db
        cq[own(gd)] -= omega**2 * d2b + omega_dot * db
        cd[own(gd)] -= 2 * omega * db
        c1[own(g1)] -= omega * db
        turned_columns = np.concatenate(
            [cq.reshape(len(a), -1), cd.reshape(len(a), -1), c1.reshape(len(a), -1)], axis=1
        )
        columns += turned_columns
        # rows: T⁻¹, over the rows with their turned columns
        changed = a[turned]
        changed[:, turned] = turned_columns[turned]
        at = 0
        for g in (gq, gd, g1):
            if not g.size:
                continue
            block = changed[at : at + g.size].reshape(g.shape[0], width, -1)
            rows[at : at + g.size] += np.einsum("ab,mbn->man", binv, block).reshape(g.size, -1)
            at += g.size
    if lay.blades >= 3:
        total[:, turned] = columns
        total[turned] = rows
    total /= len(files)
    return total[np.ix_(order, order)]


# ------------------------------------------------------------------------------------------
# BeamDyn's states in the rotating frame

#: OpenFAST writes BeamDyn's states (RotStates = True, its default) in the blade root's frame
#: frozen at the linearisation's instant, yet flags them rotating: MBC3 then adds the
#: rotation's terms to states that do not turn, a spurious Ω in every mode they take part in
#: (OpenFAST issue #3394). Its fix (pull request #3400, re-expressing the Jacobians in the
#: turning frame) was proposed on this day: files written before it carry the frozen frame.
BEAMDYN_FIX_PROPOSED = date(2026, 7, 21)
#: The release the fix was proposed for (OpenFAST pull request #3400 targets rc-5.0.1): a
#: file that names an earlier release has the frozen frame, whatever its date.
BEAMDYN_FIX_RELEASE = (5, 0, 1)


def beamdyn_frame(files: list[LinFile], lay: Layout) -> tuple[list[LinFile], str | None]:
    """The files with BeamDyn's states re-expressed in the rotating frame, as OpenFAST's fix
    does (:data:`BEAMDYN_FIX_PROPOSED`), and what was done (None: nothing to do — no rotating
    BeamDyn state, or a rotor standing still, where the two frames are one).

    Each node's translation and rotation triplet q (BeamDyn's X, Y, Z: flapwise, edgewise,
    along the blade) and its rate: q̇ ← q̇ − ω̃·q, A ← S·A·S⁻¹ − blkdiag(ω̃) with
    S = [[I, 0], [−ω̃, I]] per pair — ω the rotor's spin in the pitched blade's frame,
    Ω·(cos θ, sin θ, 0) (ElastoDyn's j-axes: j₁ = cos θ·i₁ − sin θ·i₂; θ each blade's pitch
    command from the file's inputs, 0 where it has none). The cone, which the file does not
    give, is left out: Ω·sin(cone) along the blade moves the modes of r-test's
    5MW_Land_BD_Linear (2.5°) by under 0.1 %."""
    first = files[0]
    bd = [p for p, i in enumerate(lay.q) if first.states[i].module == "BD"]
    if not bd or not any(first.states[lay.q[p]].rotating for p in bd) or first.rotor_speed == 0:
        return files, None
    head = (
        "BeamDyn's states: OpenFAST writes them in the blade root's frame frozen at the "
        "linearisation's instant and flags them rotating, so MBC3 puts a spurious rotor "
        "speed into every mode they take part in (OpenFAST issue #3394: the rotor's free spin "
        "at Ω, not 0; the tower's side-side falling with speed)"
    )
    earlier = first.version is not None and first.version < BEAMDYN_FIX_RELEASE
    if not earlier and first.generated is not None and first.generated >= BEAMDYN_FIX_PROPOSED:
        return files, (
            f"{head}. These files were written on {first.generated.isoformat()}, after the "
            "fix was proposed (OpenFAST pull request #3400): taken as written — from a build "
            "without it their BeamDyn modes carry that error."
        )
    triples = _node_triplets(first.states, lay, bd)
    if triples is None:
        return files, (
            f"{head}. Their states here are not each node's translation and rotation "
            "triplets: taken as written, with that error."
        )
    positions, blades = triples
    # a pitch input for every blade the states name, else none (0°, said)
    files = [
        f if f.pitch and len(f.pitch) >= blades.max() else replace(f, pitch=None) for f in files
    ]
    pitch = [f.pitch for f in files if f.pitch is not None]
    out = [replace(f, a=_rotating_frame(f, lay, positions, blades)) for f in files]
    told = (
        f"pitch {', '.join(f'{math.degrees(t):.3g}°' for t in pitch[0])} from the inputs"
        if pitch
        else "the files give no pitch input: 0° taken"
    )
    when = (
        f"Written by OpenFAST {'.'.join(map(str, first.version))}, before the fix"
        if earlier and first.version is not None
        else "Written before the fix"
    )
    return out, (
        f"{head}. {when} (OpenFAST pull request #3400), they are turned into "
        "the rotating frame here as the fix does: each node's q̇ − ω×q, with ω the rotor's "
        f"spin in the pitched blade's frame ({told}; the cone, not in the files, left out)."
    )


def _node_triplets(
    states: tuple[State, ...], lay: Layout, bd: list[int]
) -> tuple[NDArray[np.intp], NDArray[np.intp]] | None:
    """BeamDyn's q positions as (translation X, Y, Z) and (rotation about X, Y, Z) triplets,
    node by node, with each triplet's blade; None where they are not written so."""
    if len(bd) % 6:
        return None
    rows, blades = [], []
    for k in range(0, len(bd), 6):
        six = [states[lay.q[p]] for p in bd[k : k + 6]]
        words = [s.description for s in six]
        moved = all(
            f"translational displacement in {a}" in w for a, w in zip("XYZ", words[:3], strict=True)
        )
        turned = all("rotational displacement" in w for w in words[3:])
        one = {s.blade for s in six}
        if not (moved and turned and len(one) == 1 and six[0].rotating):
            return None
        rows += [bd[k : k + 3], bd[k + 3 : k + 6]]
        blades += [six[0].blade or 1] * 2
    return np.asarray(rows, dtype=np.intp), np.asarray(blades, dtype=np.intp)


def _rotating_frame(
    f: LinFile, lay: Layout, positions: NDArray[np.intp], blades: NDArray[np.intp]
) -> Array:
    """A with the triplets at ``positions`` (q positions, (m, 3)) in the rotating frame:
    S·A·S⁻¹ − blkdiag(ω̃) (:func:`beamdyn_frame`)."""
    omega = f.speed(lay)[0]
    theta = np.asarray(f.pitch, dtype=float)[blades - 1] if f.pitch else np.zeros(len(blades))
    w = omega * np.stack([np.cos(theta), np.sin(theta), np.zeros_like(theta)], axis=-1)
    skew = np.zeros((len(w), 3, 3))  # ω̃·x = ω × x
    skew[:, 0, 1], skew[:, 0, 2] = -w[:, 2], w[:, 1]
    skew[:, 1, 0], skew[:, 1, 2] = w[:, 2], -w[:, 0]
    skew[:, 2, 0], skew[:, 2, 1] = -w[:, 1], w[:, 0]
    q, d = lay.q[positions], lay.qd[positions]
    a = f.a.copy()
    a[d] -= np.einsum("mab,mbn->man", skew, f.a[q])  # S·A: the rates' rows
    a[:, q] += np.einsum("nmb,mba->nma", a[:, d], skew)  # ·S⁻¹: the displacements' columns
    for rows in (q, d):  # − ω̃ on each triplet's own block
        a[rows[:, :, None], rows[:, None, :]] -= skew
    return a


def coordinates(lay: Layout) -> tuple[str, ...]:
    """The multi-blade coordinate of each q position: fixed, collective, cos1, sin1, …"""
    out = ["fixed"] * len(lay.q)
    if lay.blades >= 3 and lay.triplets_q.size:
        _, _, _, names = coleman(lay.blades, 0.0)
        for row in lay.triplets_q:
            for pos, name in zip(row, names, strict=True):
                out[pos] = name
    elif lay.triplets_q.size:  # one blade (or a parked pair): its own coordinates
        for row in lay.triplets_q:
            for b, pos in enumerate(row, start=1):
                out[pos] = f"blade{b}"
    return tuple(out)


# ------------------------------------------------------------------------------------------
# Modes at one operating point


#: Name stems of ElastoDyn's DOFs: (words in its description, stem, words for people).
_ED_KINDS = (
    ("1st tower fore-aft", "tower.fa1", "1st tower fore-aft bending"),
    ("2nd tower fore-aft", "tower.fa2", "2nd tower fore-aft bending"),
    ("1st tower side-to-side", "tower.ss1", "1st tower side-side bending"),
    ("2nd tower side-to-side", "tower.ss2", "2nd tower side-side bending"),
    ("nacelle yaw", "yaw1", "nacelle yaw"),
    ("variable speed generator", "drivetrain1", "drive-train torsion"),
    ("drivetrain rotational-flexibility", "drivetrain1", "drive-train torsion"),
    ("1st flapwise", "blade.flap1", "1st blade flapwise bending"),
    ("2nd flapwise", "blade.flap2", "2nd blade flapwise bending"),
    ("1st edgewise", "blade.edge1", "1st blade edgewise bending"),
    ("platform horizontal surge", "platform.surge", "platform surge"),
    ("platform horizontal sway", "platform.sway", "platform sway"),
    ("platform vertical heave", "platform.heave", "platform heave"),
    ("platform roll", "platform.roll", "platform roll"),
    ("platform pitch", "platform.pitch", "platform pitch"),
    ("platform yaw", "platform.yaw", "platform yaw"),
    ("rotor-furl", "rotor.furl1", "rotor furl"),
    ("tail-furl", "tail.furl1", "tail furl"),
    ("teeter", "rotor.teeter1", "rotor teeter"),
)
#: BeamDyn node states: translation in X (flapwise, toward the suction side), Y (edgewise,
#: toward the trailing edge), Z (along the pitch axis); rotation about X (the slope of edge
#: bending), Y (of flap bending), Z (torsion) — BeamDyn's blade frame (Wang et al. 2016,
#: NREL/TP-5000-66909, Fig. 1).
_BD_TRANSLATION = {"X": ("blade.flap", "blade flapwise"), "Y": ("blade.edge", "blade edgewise"),
                   "Z": ("blade.axial", "blade axial")}  # fmt: skip
_BD_ROTATION = {"X": ("blade.edge", "blade edgewise"), "Y": ("blade.flap", "blade flapwise"),
                "Z": ("blade.torsion", "blade torsion")}  # fmt: skip


def _stem(module: str, dof: str, rotation_index: int) -> tuple[str, str]:
    """The name stem of a structural DOF and its words (families without an ordinal — a
    BeamDyn, SubDyn or structural-control state's — get theirs by frequency)."""
    low = dof.lower()
    if module == "ED":
        return next(((s, w) for key, s, w in _ED_KINDS if key in low), ("other", dof[3:60]))
    if module == "BD":
        if "rotational" in low:
            axis = re.search(r"rotational displacement in ([XYZ])", dof)
            letter = "XYZ"[rotation_index % 3] if axis is None or rotation_index else axis[1]
            return _BD_ROTATION[letter]
        axis = re.search(r"displacement in ([XYZ])", dof)
        return _BD_TRANSLATION[axis[1]] if axis else ("blade.other", "blade")
    if module == "SD":
        return "support.mode", "support structure (SubDyn)"
    if module == "ExtPtfm":
        return "support.mode", "support structure (ExtPtfm)"
    if module == "SrvD":
        where = re.search(r"(Nacelle|Tower|Blade|Substructure|Platform)", dof, re.IGNORECASE)
        place = where[1].lower() if where else "structure"
        return f"damper.{place}", f"structural control ({place})"
    return "other", dof[:60]


@dataclass(frozen=True)
class PointModes:
    """The structural modes of one operating point, and what was left out."""

    rpm: float
    wind: float | None
    frequency_hz: Array  # natural frequency |λ|/2π
    damped_hz: Array  # Im λ/2π
    damping_ratio: Array
    names: tuple[str, ...]
    descriptions: tuple[str, ...]
    whirl: tuple[str, ...]
    share: Array  # the share of the coordinate group the mode is named after
    shapes: Array  # participation of each q coordinate (columns: modes)
    frame: str  # fixed (multi-blade coordinates) or rotating (one blade, its own frame)
    left_out: dict[str, Any] = field(default_factory=dict)
    notes: tuple[str, ...] = ()  # what was done to the states before MBC3


#: One operating point's linearisations share its rotor speed within this fraction: a free
#: rotor's speed follows gravity and the platform through the revolution (the r-test OC3 spar
#: deck with no generator torque linearised at 36 azimuths: 1.2648–1.2685 rad/s, 0.3 %);
#: MBC3 takes each azimuth's own speed (:func:`mbc_average`), the point's is their mean.
SPEED_SPREAD = 5e-3


def _mean_speed(files: list[LinFile]) -> float:
    """The point's rotor speed [rad/s]: the files' (their mean where they differ)."""
    speeds = [f.rotor_speed for f in files]
    return speeds[0] if len(set(speeds)) == 1 else math.fsum(speeds) / len(speeds)


def operating_point(files: list[LinFile], as_written: bool = False) -> tuple[PointModes, int]:
    """MBC3 over the azimuths of one point, its structural modes and the number of blades;
    BeamDyn's states turned into the rotating frame first (:func:`beamdyn_frame`), unless
    ``as_written`` (the states as OpenFAST wrote them: openfast_toolbox's MBC3)."""
    first = files[0]
    for f in files[1:]:
        if [s.description for s in f.states] != [s.description for s in first.states]:
            raise SpecError(
                f"its states differ from {first.path.name}'s: not the same model",
                source=str(f.path),
            )
        if not math.isclose(f.rotor_speed, first.rotor_speed, rel_tol=SPEED_SPREAD, abs_tol=1e-6):
            raise SpecError(
                f"rotor speed {f.rotor_speed:g} rad/s, {first.path.name} has "
                f"{first.rotor_speed:g}: not one operating point",
                source=str(f.path),
            )
    lay = layout(first.states, first.path, first.rotor_speed, first.a)
    if (
        lay.blades == 1
        and first.rotor_speed > 0
        and any(not first.states[i].rotating for i in lay.q)
    ):
        raise SpecError(
            "one blade on a structure in the fixed frame: neither frame is time-invariant, "
            "and the multi-blade transformation needs three or more blades",
            source=str(first.path),
        )
    frame_note = None
    if not as_written:
        files, frame_note = beamdyn_frame(files, lay)
    a_nr = mbc_average(files, lay)
    try:
        found = state_modes(a_nr)
    except ModalError as exc:
        raise SpecError(str(exc), source=str(first.path)) from None
    lam, vec, part = found.roots, found.vectors, found.participation
    n2 = len(lay.q)
    structural_q = np.array([m in STRUCTURAL for m in lay.q_modules], dtype=bool)
    s_q = part[:n2] + part[n2 : 2 * n2]  # a coordinate's displacement and rate together
    structural = (s_q * structural_q[:, None]).sum(axis=0)
    oscillating = _oscillating(lam)
    images = _mirror_images(lam, oscillating & (structural >= STRUCTURAL_SHARE))
    rigid = _rigid(s_q, lay, lam, first.rotor_speed)
    elastic = (structural >= STRUCTURAL_SHARE) & ~rigid & ~images
    keep = np.where(oscillating & elastic)[0]
    keep = keep[np.argsort(np.abs(lam[keep]))]
    left_out = _left_out(lam, part, oscillating & ~elastic, lay, rigid, images)
    coords = coordinates(lay)
    rows = [_name_one(lam[j], vec[:, j], s_q[:, j], structural_q, lay, coords, first) for j in keep]
    names = _ordinals([r[0] for r in rows], np.abs(lam[keep]))
    frame = (
        "rotating"
        if lay.blades == 1 and not any(not first.states[i].rotating for i in lay.q)
        else "fixed"
    )
    shapes = s_q[:, keep] * structural_q[:, None]
    point = PointModes(
        _mean_speed(files) * 30 / math.pi,
        first.wind,
        np.abs(lam[keep]) / (2 * math.pi),
        lam[keep].imag / (2 * math.pi),
        damping_ratio(lam[keep]),
        names,
        tuple(r[1] for r in rows),
        tuple(r[2] for r in rows),
        np.array([r[3] for r in rows]),
        shapes / np.maximum(shapes.sum(axis=0), 1e-300),
        frame,
        left_out,
        () if frame_note is None else (frame_note,),
    )
    return point, lay.blades


def _group(stem: str, coord: str) -> tuple[str, str]:
    kind = "cyclic" if coord.startswith(("cos", "sin")) else coord
    return stem, kind


def _name_one(
    lam: complex,
    v: NDArray[np.complex128],
    share: Array,
    structural: NDArray[np.bool_],
    lay: Layout,
    coords: tuple[str, ...],
    lin: LinFile,
) -> tuple[str, str, str, float]:
    """(name stem with coordinate and whirl, description, whirl, share) of one mode from the
    participation of its structural coordinates."""
    groups: dict[tuple[str, str], float] = defaultdict(float)
    words: dict[str, str] = {}
    rotation_seen: dict[tuple[int, str], int] = defaultdict(int)
    stems = []
    for pos in range(len(lay.q)):
        state = lin.states[lay.q[pos]]
        key = (state.blade or 0, re.sub(r"rotational displacement in [XYZ]", "rot", lay.dofs[pos]))
        idx = rotation_seen[key]
        if "rotational" in lay.dofs[pos]:
            rotation_seen[key] += 1
        stem, word = _stem(lay.q_modules[pos], lay.dofs[pos], idx)
        stems.append(stem)
        words.setdefault(stem, word)
        if structural[pos]:
            groups[_group(stem, coords[pos])] += float(share[pos])
    total = sum(groups.values()) or 1.0
    ranked = sorted(groups.items(), key=lambda kv: -kv[1])
    (stem, kind), best = ranked[0]
    best /= total
    whirl = "fixed"
    name = stem
    text = words[stem]
    if kind == "collective":
        name, text, whirl = f"{stem}.collective", f"{text}, collective", "collective"
    elif kind == "alternating":
        name, text = f"{stem}.alternating", f"{text}, alternating"
    elif kind == "cyclic":
        whirl = _whirl(v, share, stems, stem, lay.triplets_q, lin.rotor_speed)
        name = f"{stem}.{whirl}"
        text = f"{text}, cyclic" + (f", {whirl} whirl" if whirl != "cyclic" else "")
    elif kind.startswith("blade"):  # one blade, in its own (rotating) frame
        whirl = "fixed"
    if best < MIXED_SHARE and len(ranked) > 1:
        (s2, k2), second = ranked[1]
        text = (
            f"mixed: {text} {best:.0%}, {words[s2]}"
            + (f" ({k2})" if k2 not in ("fixed",) else "")
            + f" {second / total:.0%}"
        )
    else:
        text = f"{text} ({best:.0%} of the mode)"
    return name, text, whirl, best


def _whirl(
    v: NDArray[np.complex128],
    share: Array,
    stems: list[str],
    stem: str,
    triplets: NDArray[np.intp],
    rotor_speed: float,
) -> str:
    """Forward, backward or (a standing pattern) cyclic, from the cos and sin coordinates of
    the mode's strongest cyclic DOF of ``stem``.

    With q_b = q_c·cos ψ_b + q_s·sin ψ_b and q_s = −i·q_c, the deflection over the rotor
    disk is |q_c|·cos(ψ − ωt): its peak turns with the rotor — forward whirl, where
    Im(q̄_c·q_s) < 0.
    """
    if rotor_speed <= 0 or triplets.shape[1] < 3:
        return "cyclic"
    rows = [r for r in triplets if stems[r[1]] == stem]
    if not rows:
        return "cyclic"
    row = max(rows, key=lambda r: share[r[1]] + share[r[2]])
    qc, qs = v[row[1]], v[row[2]]
    turn = float(np.imag(np.conj(qc) * qs)) / max((abs(qc) ** 2 + abs(qs) ** 2) / 2, 1e-300)
    if abs(turn) < WHIRL_FRACTION:
        return "cyclic"
    return "forward" if turn < 0 else "backward"


def _ordinals(names: list[str], omega: Array) -> tuple[str, ...]:
    """Number the families without an ordinal (``blade.flap.collective`` →
    ``blade.flap1.collective``, by frequency within each coordinate and whirl) and make
    every name unique."""
    out = list(names)
    counters: dict[str, int] = defaultdict(int)
    for j in np.argsort(omega, kind="stable"):
        parts = out[j].split(".")
        if parts[0] not in ("blade", "support", "damper") or parts[1][-1].isdigit():
            continue
        family, rest = ".".join(parts[:2]), ".".join(parts[2:])
        counters[f"{family}.{rest}"] += 1
        out[j] = f"{family}{counters[f'{family}.{rest}']}" + (f".{rest}" if rest else "")
    seen: dict[str, int] = defaultdict(int)
    unique = []
    for name in out:
        seen[name] += 1
        unique.append(name if seen[name] == 1 else f"{name}_{seen[name]}")
    return tuple(unique)


def _oscillating(lam: NDArray[np.complex128]) -> NDArray[np.bool_]:
    """The roots that oscillate: Im λ above rounding, |λ| above the near-zero roots of
    rigid-body motion (which rounding moves off zero by ~√ε of the largest root)."""
    scale = max(float(np.abs(lam).max(initial=0.0)), 1.0)
    return np.asarray((lam.imag > 1e-9 * scale) & (np.abs(lam) > 1e-8 * scale))


def _rigid(s_q: Array, lay: Layout, lam: NDArray[np.complex128], omega: float) -> NDArray[np.bool_]:
    """Which roots are rigid-body motion: held mostly by free DOFs and the generator
    azimuth (:data:`FREE_BELOW_HZ`), or undamped with the generator azimuth taking part —
    the rotor turning, which no structural damping resists (r-test 5MW_Land_BD_Linear:
    0.003 Hz, BeamDyn's collective edgewise states and the azimuth; 0.19 Hz = Ω/2π with
    BeamDyn's states as written, :func:`beamdyn_frame`). Undamped: |Re λ| within 1e-5 of
    |λ| or of the rotor speed Ω [rad/s] (one azimuth's periodic terms move the spin's zero
    root by ~1e-6 rad/s)."""
    free = (s_q * lay.free[:, None]).sum(axis=0)
    turning = (s_q * lay.azimuth[:, None]).sum(axis=0)
    undamped = np.abs(lam.real) <= 1e-5 * np.maximum(np.abs(lam), omega)
    return np.asarray(
        ((free >= FREE_SHARE) & (free + turning >= RIGID_SHARE))
        | (undamped & (turning >= TURNING_SHARE))
    )


def _mirror_images(lam: NDArray[np.complex128], candidates: NDArray[np.bool_]) -> NDArray[np.bool_]:
    """Which roots are the numerical image of rigid-body motion: pairs λ, −λ̄ — the same
    frequency, damping ratios equal and opposite — below the lowest other structural root.

    A free body's displacement has a double zero root per DOF; the linearisation's
    finite-difference stiffness and rounding move the pair off zero as λ² = δ, so they come
    back as ±√δ: one root damped, its mirror image growing by as much, with no damping in
    the motion to break the symmetry (OpenFAST r-test Ideal_Beam_Free_Free_Linear: 0.0888
    Hz, ζ = ±0.2601, twice, where the beam's first bending is 3.57 Hz). A physical
    oscillation of a damped structure has no such twin; an undamped flutter would — which
    is why each left out is said (:func:`to_spec_data`)."""
    idx = np.where(candidates)[0]
    out = np.zeros(lam.shape, dtype=bool)
    if idx.size < 2:
        return out
    z = lam[idx]
    # λ_k = −conj(λ_j): equal imaginary parts, opposite real parts beyond rounding
    twin = np.abs(z[:, None] + np.conj(z)[None, :]) <= MIRROR * np.abs(z)[:, None]
    damped = np.abs(z.real) > MIRROR * np.abs(z)
    paired = (twin & ~np.eye(idx.size, dtype=bool)).any(axis=1) & damped
    if not paired.any() or paired.all():  # all of them twins: no rigid body beside them
        return out
    lowest_other = np.abs(z[~paired]).min()
    out[idx[paired & (np.abs(z) < lowest_other)]] = True
    return out


def _left_out(
    lam: NDArray[np.complex128],
    part: Array,
    mask: NDArray[np.bool_],
    lay: Layout,
    rigid: NDArray[np.bool_],
    images: NDArray[np.bool_],
) -> dict[str, Any]:
    """The oscillating roots that are not structural: how many, their frequency range, the
    modules holding them, and those among them that grow (ζ < 0)."""
    idx = np.where(mask)[0]
    if idx.size == 0:
        return {}
    modules = [*lay.q_modules, *lay.q_modules, *lay.first_modules]
    owners: dict[str, int] = defaultdict(int)
    growing: list[tuple[str, float, float]] = []  # (owner, natural frequency [Hz], ζ)
    for j in idx:
        if images[j]:
            owner = "images"  # a free body's zero roots moved off zero: no vibration
        elif rigid[j]:
            owner = "rigid"  # the rotor turning with a free nacelle: no vibration
        else:
            owner = modules[int(np.argmax(part[:, j]))]
        owners[owner] += 1
        if lam[j].real > GROWING * abs(lam[j]):
            growing.append((owner, abs(lam[j]) / (2 * math.pi), float(damping_ratio(lam[j]))))
    f = np.abs(lam[idx]) / (2 * math.pi)
    return {
        "count": int(idx.size),
        "low_hz": float(f.min()),
        "high_hz": float(f.max()),
        "modules": dict(sorted(owners.items())),
        "roots": lam[idx],
        "growing": sorted(growing, key=lambda g: g[2]),
    }


# ------------------------------------------------------------------------------------------
# From point to point


#: A mode followed from one operating point to the next with a MAC under this is flagged.
TRACK_MAC = 0.5


def _followed(
    points: list[PointModes],
) -> tuple[dict[str, dict[str, Any]], tuple[float, str, float] | None]:
    """Each mode of the first (slowest) point followed point by point by shape (MAC of the
    participation of the structural coordinates; forward turned backward, or back, halves
    it), one optimal assignment per step, with the weakest match."""
    modes: dict[str, dict[str, Any]] = {}
    first = points[0]
    for j, name in enumerate(first.names):
        modes[name] = {
            "description": first.descriptions[j],
            "frame": first.frame,
            **{
                k: []
                for k in (
                    "rpm",
                    "frequency_hz",
                    "damped_frequency_hz",
                    "damping_ratio",
                    "whirl",
                    "wind_m_s",
                    "share",
                )
            },
        }
    current = {name: j for j, name in enumerate(first.names)}  # name → column at this point
    prev = first
    weakest: tuple[float, str, float] | None = None
    for k, pm in enumerate(points):
        if k and current and len(pm.names):
            names = list(current)
            cols = [current[n] for n in names]
            score = mac(prev.shapes[:, cols], pm.shapes)
            turns = ("forward", "backward")
            flipped = np.array([[{prev.whirl[c], w} == set(turns) for w in pm.whirl] for c in cols])
            score = np.where(flipped, 0.5 * score, score)
            if score.shape[0] <= score.shape[1]:
                pairs = list(enumerate(assign(score, optimal=True)))
            else:  # fewer modes here: each of them finds its predecessor
                rows = assign(score.T, optimal=True)
                pairs = [(int(r), c) for c, r in enumerate(rows)]
            current = {names[r]: int(c) for r, c in pairs}
            for r, c in pairs:
                if weakest is None or score[r, c] < weakest[0]:
                    weakest = (float(score[r, c]), names[r], pm.rpm)
            prev = pm
        elif k:
            current = {}
        for name, j in current.items():
            m = modes[name]
            m["rpm"].append(round(pm.rpm, 6))
            m["frequency_hz"].append(float(pm.frequency_hz[j]))
            m["damped_frequency_hz"].append(float(pm.damped_hz[j]))
            m["damping_ratio"].append(max(-1.0, min(1.0, float(pm.damping_ratio[j]))))
            m["whirl"].append(pm.whirl[j])
            m["wind_m_s"].append(pm.wind)
            m["share"].append(round(float(pm.share[j]), 4))
    return modes, weakest


def to_spec_data(
    path: Path, blades: int | None, rpm: tuple[float, float] | None = None
) -> dict[str, Any]:
    """The wtvib-format dictionary of one or more operating points' ``.lin`` files."""
    groups = files_of(path)
    points = []
    nbs = set()
    read_files: list[str] = []
    uneven: list[str] = []
    left: list[str] = []
    growing: list[str] = []
    titles: dict[str, None] = {}
    notes: dict[str, None] = {}  # one statement however many points it applies to
    for root, paths in sorted(groups.items()):
        lins = [read(p) for p in paths]
        read_files += [str(p) for p in paths]
        if lins[0].description:
            titles[lins[0].description] = None
        pm, nb = operating_point(lins)
        points.append(pm)
        for note in pm.notes:
            notes[note] = None
        nbs.add(nb)
        if lins[0].rotor_speed > 0 and nb >= 3 and not _even(lins):
            uneven.append(f"{root} ({len(lins)} at {pm.rpm:.4g} rpm)")
        if pm.left_out:
            lo = pm.left_out
            owners = ", ".join(f"{MODULE_WORDS.get(m, m)} {c}" for m, c in lo["modules"].items())
            grows = (
                f"; growing, lowest ζ = {lo['growing'][0][2]:.4f} at {lo['growing'][0][1]:.3g} Hz"
                if lo["growing"]
                else ""
            )
            left.append(
                f"{root}: {lo['count']} ({lo['low_hz']:.3g}–{lo['high_hz']:.3g} Hz; {owners}"
                f"{grows})"
            )
            growing += _growing(root, lo["growing"])
    if not any(len(p.names) for p in points):
        what = "; ".join(left) if left else "no oscillating root"
        raise SpecError(
            "the linearisation holds no structural mode to judge — no oscillating root in which "
            f"ElastoDyn, BeamDyn, SubDyn or structural-control states take part most ({what})",
            source=str(path),
        )
    points.sort(key=lambda p: (p.rpm, p.wind if p.wind is not None else 0.0))
    modes, weakest = _followed([p for p in points if len(p.names)])
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
        _name(path, groups, list(titles)),
        blades_found=found or None,
        rpm=rpm,
    )
    data["assumptions"].append(
        "Modes: the oscillating roots of the azimuth-averaged multi-blade state matrix in "
        f"which the structural states (ElastoDyn, BeamDyn, SubDyn, structural control) take "
        f"part {STRUCTURAL_SHARE:.0%} or more (participation factors); each named after the "
        "coordinate group that takes part most, with its share."
    )
    data["assumptions"] += list(notes)
    if left:
        data["assumptions"].append(
            "Roots left out, no structural vibration (inflow, unsteady aerodynamics, "
            "radiation, mooring lines, rigid-body motion): " + "; ".join(left) + "."
        )
    data["warnings"] += growing
    _notes(data, modes, weakest, uneven)
    outside = [f for f in read_files if Path(f).parent != (path if path.is_dir() else path.parent)]
    if outside:
        data["warnings"].append(f"files read outside the named folder: {', '.join(outside)}")
    return data


def _notes(
    data: dict[str, Any],
    modes: dict[str, Any],
    weakest: tuple[float, str, float] | None,
    uneven: list[str],
) -> None:
    """What the spec says of its modes: the mixed ones, the curve followed with the weakest
    MAC, azimuths too few for MBC3."""
    mixed = sorted({n for n, m in modes.items() if m["description"].startswith("mixed")})
    if mixed:
        data["assumptions"].append(
            f"Mixed modes (no coordinate group holds {MIXED_SHARE:.0%}): {', '.join(mixed)} — "
            "each named after its largest group."
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


def _name(path: Path, groups: dict[str, list[Path]], titles: list[str]) -> str:
    """The turbine's name: the deck's own title the files quote (one title for all), else
    the case the files are named after (``5MW_Land_Linear_Aero``), else the folder."""
    if len(titles) == 1:
        return titles[0]
    roots = sorted(groups)
    case = roots[0] if len(roots) == 1 else path.name
    return f"OpenFAST linearisation {case}"


def _growing(root: str, found: list[tuple[str, float, float]]) -> list[str]:
    """What the report says of the roots left out that grow: the images of rigid-body motion
    as what they are, any other as the instability of the linear model it is (a growing
    inflow or radiation root is not a structural mode, but not a stable system either)."""
    out = []
    images = [(f, z) for owner, f, z in found if owner == "images"]
    if images:
        out.append(
            f"system.stability: {root}: {len(images)} root(s) left out as the numerical image "
            f"of rigid-body motion, each the twin of a damped one (ζ down to {images[0][1]:.4f} "
            f"at {images[0][0]:.4g} Hz) — a free body's zero roots, not a vibration; an "
            "undamped flutter would look the same: check the model has its rigid-body freedom"
        )
    # a rigid-body root that grows is the one-azimuth artefact FREE_BELOW_HZ describes
    others = [(owner, f, z) for owner, f, z in found if owner not in ("images", "rigid")]
    if others:
        owner, f, z = others[0]
        out.append(
            f"system.stability: {root}: {len(others)} root(s) left out as no structural "
            f"vibration grow (ζ down to {z:.4f} at {f:.4g} Hz, {MODULE_WORDS.get(owner, owner)})"
            " — the linear model is unstable there; wtvib judges the structural modes only"
        )
    return out


def _even(files: list[LinFile]) -> bool:
    """Whether an operating point's azimuths are at least three and evenly spaced round the
    rotor (no gap more than half again the even spacing)."""
    if len(files) < 3:
        return False
    psi = np.sort(np.mod([f.azimuth for f in files], 2 * np.pi))
    gaps = np.diff(np.append(psi, psi[0] + 2 * np.pi))
    return bool(gaps.max() <= 1.5 * 2 * np.pi / len(files))
