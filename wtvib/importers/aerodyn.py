"""OpenFAST AeroDyn 15 inputs → the spec's ``aerodynamics`` block.

Follows the deck set: the ``.fst``'s AeroFile (``CompAero`` = 2), its blade file
(``ADBlFile(1)``: BlSpn, BlTwist, BlChord, BlAFID) and aerofoil files (``AFNames``:
AirfoilInfo tables, the first table of each); the controller's region-2 tip-speed ratio,
rated power and fine pitch from ROSCO's ``DISCON.IN`` (VS_TSRopt, VS_RtPwr, PC_FinePit) and
the generator efficiency from ServoDyn (GenEff). Only files the deck set names are read.

References
----------
OpenFAST AeroDyn 15 and AirfoilInfo input definitions (openfast.readthedocs.io, AeroDyn
"Input Files"); ROSCO input definitions (DISCON.IN).
"""

import math
from pathlib import Path
from typing import Any

from ..errors import SpecError
from ..spec import read_text
from ..spec.aerodynamics import MAX_AIRFOILS, MAX_POLAR_POINTS, MAX_STATIONS
from .deck import _NUMBER, Deck, _file, beside, environment, parse, present


def _number(cell: str, what: str, line: int, path: Path) -> float:
    value = float(cell.replace("D", "E").replace("d", "e")) if _NUMBER.match(cell) else math.nan
    if not math.isfinite(value):
        raise SpecError(f"{what}: {cell!r} is not a finite number", line=line, source=str(path))
    return value


def _table(
    path: Path, lines: list[str], start: int, rows: int, width: int, what: str
) -> list[list[float]]:
    """``rows`` numeric rows of at least ``width`` cells from line index ``start`` on
    (comment lines starting with ! skipped)."""
    out: list[list[float]] = []
    i = start
    while len(out) < rows:
        if i >= len(lines):
            raise SpecError(
                f"the {what} table ends after {len(out)} of {rows} rows (a truncated file?)",
                line=len(lines),
                source=str(path),
            )
        cells = lines[i].split()
        i += 1
        if not cells or cells[0].startswith("!"):
            continue
        if len(cells) < width:
            raise SpecError(
                f"the {what} table needs {width} columns (got {len(cells)})",
                line=i,
                source=str(path),
            )
        out.append([_number(c, what, i, path) for c in cells[:width]])
    return out


def _count(deck: Deck, key: str, high: int) -> int:
    n = deck.whole(key, low=1)
    if n > high:
        raise SpecError(
            f"{key} {n} exceeds wtvib's limit of {high}",
            line=deck.values[key][1],
            source=str(deck.path),
        )
    return n


def blade_stations(path: Path, hub_radius: float) -> dict[str, Any]:
    """The AeroDyn blade file's stations (radius = HubRad + BlSpn: precone neglected)."""
    deck = parse(path)
    n = _count(deck, "NumBlNds", MAX_STATIONS)
    lines = read_text(path, ansi=True).splitlines()
    head = next(
        (i for i, ln in enumerate(lines) if ln.split()[:1] == ["BlSpn"]),
        None,
    )
    if head is None:
        raise SpecError("the blade table (BlSpn … BlAFID) is missing", source=str(path))
    names = lines[head].split()
    for need in ("BlSpn", "BlTwist", "BlChord", "BlAFID"):
        if need not in names:
            raise SpecError(
                f"the blade table has no {need} column", line=head + 1, source=str(path)
            )
    rows = _table(path, lines, head + 2, n, len(names), "blade")
    col = {k: names.index(k) for k in ("BlSpn", "BlTwist", "BlChord", "BlAFID")}
    span = [r[col["BlSpn"]] for r in rows]
    keep = [0] + [i for i in range(1, n) if span[i] > span[i - 1]]  # repeated tip node
    if len(keep) < n - 1 or len(keep) < 3:
        raise SpecError(
            "BlSpn must increase from node to node (at least three nodes)",
            line=head + 3,
            source=str(path),
        )
    ids = []
    for i in keep:
        af = rows[i][col["BlAFID"]]
        if af != int(af) or af < 1:
            raise SpecError(
                f"BlAFID must be a whole number ≥ 1 (got {af:g})",
                line=head + 3 + i,
                source=str(path),
            )
        ids.append(int(af))
    return {
        "radius_m": [hub_radius + span[i] for i in keep],
        "chord_m": [rows[i][col["BlChord"]] for i in keep],
        "twist_deg": [rows[i][col["BlTwist"]] for i in keep],
        "ids": ids,
    }


def polar(path: Path, cm_column: int = 0) -> dict[str, list[float]]:
    """The first table of an AirfoilInfo file: α [deg], C_L, C_D — and C_M from column
    ``cm_column`` (1-based: AeroDyn's InCol_Cm; 0: none)."""
    lines = read_text(path, ansi=True).splitlines()
    at = next((i for i, ln in enumerate(lines) if ln.split()[1:2] == ["NumAlf"]), None)
    if at is None:
        raise SpecError("NumAlf is missing (not an AirfoilInfo file?)", source=str(path))
    raw = lines[at].split()[0]
    count = _number(raw, "NumAlf", at + 1, path)
    if count != int(count) or not 3 <= count <= MAX_POLAR_POINTS:
        raise SpecError(
            f"NumAlf must be a whole number from 3 to {MAX_POLAR_POINTS} (got {raw!r})",
            line=at + 1,
            source=str(path),
        )
    rows = _table(path, lines, at + 1, int(count), max(3, cm_column), "aerofoil")
    out = {
        "alpha_deg": [r[0] for r in rows],
        "cl": [r[1] for r in rows],
        "cd": [r[2] for r in rows],
    }
    if cm_column > 0:
        out["cm"] = [r[cm_column - 1] for r in rows]
    return out


def negative_drag(name: str, table: dict[str, list[float]]) -> str | None:
    """A polar's drag coefficients below 0 (a fit's or an extrapolation's artefact in
    published files: the SWRT's and the IEA land-based RWT's aerofoils) taken as 0, and the
    warning that says so; None where there are none."""
    low = [(cd, a) for cd, a in zip(table["cd"], table["alpha_deg"], strict=True) if cd < 0]
    if not low:
        return None
    table["cd"] = [max(cd, 0.0) for cd in table["cd"]]
    worst = min(low)
    return (
        f"aerodynamics.airfoils.{name}: C_D below 0 at {len(low)} angle(s) of attack (lowest "
        f"{worst[0]:.3g} at α = {worst[1]:g}°) — a drag coefficient is not negative: taken as 0"
    )


def _airfoil_files(deck: Deck) -> list[Path]:
    """AFNames: the first on its key's line, the rest on the lines after it."""
    n = _count(deck, "NumAFfiles", MAX_AIRFOILS)
    lines = read_text(deck.path, ansi=True).splitlines()
    if "AFNames" not in deck.values:
        raise SpecError("AFNames (the aerofoil files) is missing", source=str(deck.path))
    line = deck.values["AFNames"][1]
    names = [deck.values["AFNames"][0]]
    i = line
    while len(names) < n and i < len(lines):
        cells = lines[i].split()
        i += 1
        if cells and not cells[0].startswith(("!", "-", "=")):
            names.append(cells[0])
    out = []
    for k, name in enumerate(names, start=1):
        p = beside(deck.path, name.strip('"'))
        if not present(p):
            raise SpecError(
                f"AFNames entry {k} names {name!r}, which does not exist",
                line=line + k - 1,
                source=str(deck.path),
            )
        out.append(p)
    return out


#: AeroDyn's unsteady aerofoil models that lag the lift in attached flow by the shed wake
#: (UA_Mod; AFAeroMod 2 in older files): the Beddoes–Leishman family — Gonzalez (2),
#: Minnema/Pierce (3), Hansen–Gaunaa–Madsen (4, 5), whose attached-flow part is the
#: circulatory lift through Jones's indicial function (AeroDyn theory manual, "Unsteady
#: Aerodynamics"). Øye's model (6) lags only the separation point — in attached flow its
#: lift is the quasi-steady one — and Boeing–Vertol's (7) corrects the angle of attack for
#: its rate, no shed wake either.
SHED_WAKE_UA = frozenset({2, 3, 4, 5})

#: The models whose separation point lags the angle of attack past stall (dynamic stall):
#: the Beddoes–Leishman family's f″ state behind its pressure lag (2–5) and Øye's (6).
SEPARATION_UA = frozenset({2, 3, 4, 5, 6})

#: AeroDyn's defaults of the separation's and the pressure's time constants, T_f0 and T_p
#: [half-chord transits] (AeroDyn theory manual, "Unsteady Aerodynamics": 3 and 1.7).
DEFAULT_TF0, DEFAULT_TP = 3.0, 1.7


def unsteady_model(ad: Deck) -> int:
    """The AeroDyn file's unsteady aerofoil model (UA_Mod; older files AFAeroMod 2 with
    UAMod, Beddoes–Leishman 1 counted with 2–3); 0: quasi-steady."""
    if "UA_Mod" in ad.values:
        return ad.whole("UA_Mod", low=0)
    if "AFAeroMod" in ad.values:  # older AeroDyn 15: 1 steady, 2 Beddoes–Leishman (UAMod)
        model = ad.whole("UAMod", low=1) if "UAMod" in ad.values else 3
        return (2 if model == 1 else model) if ad.whole("AFAeroMod", low=1) == 2 else 0
    return 0


def shed_wake(ad: Deck) -> bool:
    """Whether the AeroDyn file asks for an unsteady aerofoil model with a shed-wake lag
    (:data:`SHED_WAKE_UA`); quasi-steady where it says UA_Mod 0 (AFAeroMod 1)."""
    return unsteady_model(ad) in SHED_WAKE_UA


def separation_time(path: Path, model: int) -> float:
    """The first table's separation time constant of an AirfoilInfo file [half-chord
    transits]: T_f0, and for the Beddoes–Leishman models T_f0 + T_p (their f″ follows the
    pressure lag: one pole stands for the two, :mod:`wtvib.numerics.unsteady`); AeroDyn's
    defaults where the file has no unsteady data or says "default"."""
    lines = read_text(path, ansi=True).splitlines()
    end = next((i for i, ln in enumerate(lines) if ln.split()[1:2] == ["NumAlf"]), len(lines))

    def value(key: str, default: float) -> float:
        for i, ln in enumerate(lines[:end]):
            cells = ln.split()
            if cells[1:2] == [key] and cells[0].lower().strip('"') != "default":
                got = _number(cells[0], key, i + 1, path)
                if not 0 <= got <= 100:  # 0: the separation follows at once (the UAE's cylinder)
                    raise SpecError(
                        f"{key} must lie within 0 … 100 half-chord transits (got {got:g})",
                        line=i + 1,
                        source=str(path),
                    )
                return got
        return default

    tf0 = value("T_f0", DEFAULT_TF0)
    return tf0 if model == 6 else min(tf0 + value("T_p", DEFAULT_TP), 100.0)


def induction(ad: Deck) -> tuple[str, str]:
    """How the AeroDyn file has the wake's induction answer the blades' motion, and why:
    ``equilibrium`` where its BEMT has no dynamic wake (Wake_Mod 1 with DBEMT_Mod 0; older
    files: WakeMod 1 without FrozenWake), ``dynamic`` where it asks for a dynamic wake
    (DBEMT_Mod 1–3, WakeMod 2 — its time constant, seconds, holds the induction still over
    a flap mode's period; its last node keeps a = 1), ``frozen`` for a frozen wake
    (DBEMT_Mod −1, FrozenWake True: the induced velocity held at every node, the last one's
    flow turned by its motion too — OpenFAST 5's linearisations of the NREL 5-MW with it
    damp the flap family as wtvib's so within −3.7 … +5.5 %, −10 … +8 % with the last node's
    normal inflow held) and any other wake. AeroDyn input documentation (Wake_Mod,
    DBEMT_Mod; FrozenWake in AeroDyn 15 before OpenFAST 3.5)."""
    if "Wake_Mod" in ad.values:  # OpenFAST 3.5 and later
        wake = ad.whole("Wake_Mod", low=0)
        dbemt = int(ad.num("DBEMT_Mod", default=0)) if "DBEMT_Mod" in ad.values else 0
        if wake == 1 and dbemt == 0:
            return "equilibrium", "Wake_Mod 1 and DBEMT_Mod 0 (BEMT without dynamic wake)"
        if wake == 1 and dbemt > 0:
            return "dynamic", f"Wake_Mod 1, DBEMT_Mod {dbemt} (a dynamic wake)"
        return "frozen", f"Wake_Mod {wake}, DBEMT_Mod {dbemt} (a frozen wake)"
    if "WakeMod" in ad.values:  # AeroDyn 15 before OpenFAST 3.5
        wake = ad.whole("WakeMod", low=0)
        frozen = ad.flag("FrozenWake") if "FrozenWake" in ad.values else False
        if wake == 1 and not frozen:
            return "equilibrium", "WakeMod 1 without FrozenWake (BEMT without dynamic wake)"
        if wake == 2 and not frozen:
            return "dynamic", "WakeMod 2 (a dynamic wake)"
        return "frozen", f"WakeMod {wake}" + (", FrozenWake" if frozen else "")
    return "frozen", "no wake model named"


def aerodynamics(
    fst: Deck | None, hub_radius: float, control: dict[str, Any]
) -> tuple[dict[str, Any], list[str], list[str], list[str]] | None:
    """The ``aerodynamics`` block (its ``control`` as the deck set's ServoDyn gives it:
    :func:`wtvib.importers.servodyn.operation`), the files read, what "default" inputs were
    taken as, and warnings; None where the deck set has no AeroDyn 15 input."""
    if fst is None or "AeroFile" not in fst.values or fst.num("CompAero", default=0) != 2:
        return None
    ad = parse(_file(fst, "AeroFile"))
    ad.inherited.update(environment(fst))
    blade = _file(ad, "ADBlFile(1)", "ADBlFile1")
    stations = blade_stations(blade, hub_radius)
    files = _airfoil_files(ad)
    ids = stations.pop("ids")
    if max(ids) > len(files):
        raise SpecError(f"BlAFID {max(ids)} exceeds NumAFfiles {len(files)}", source=str(blade))
    used = sorted(set(ids))
    cm = ad.whole("InCol_Cm", low=0) if "InCol_Cm" in ad.values else 0  # 0: no C_M column
    airfoils: dict[str, dict[str, Any]] = {files[i - 1].stem: polar(files[i - 1], cm) for i in used}
    model = unsteady_model(ad)
    if model in SEPARATION_UA:
        for i in used:
            airfoils[files[i - 1].stem]["separation_time"] = separation_time(files[i - 1], model)
    warnings = [w for name, table in airfoils.items() if (w := negative_drag(name, table))]
    stations["airfoil"] = [files[i - 1].stem for i in ids]
    rho = ad.num("AirDens", "AirDens(1)", default=1.225)
    key = next((k for k in ("AirDens", "AirDens(1)") if k in ad.values), None)
    tip_loss = ad.text("TipLoss").lower() in ("true", "t") if "TipLoss" in ad.values else True
    block = {
        "air_density_kg_m3": {
            "value": rho,
            "provenance": "published" if key is not None else "representative",
            "source": "deck",
            "note": ad.defaulted.get(key, f"{key} in {ad.path.name}")
            if key is not None
            else "no AirDens in the AeroDyn file: 1.225 kg/m³ (sea level, 15 °C)",
        },
        "tip_loss": tip_loss,
        "hub_loss": ad.text("HubLoss").lower() in ("true", "t") if "HubLoss" in ad.values else True,
        # AeroDyn's BEMT fixes the inductions of the blade's last node (its tip-loss
        # constant is 0 there by construction) at a = 1, a′ = 0 and loads it (BEMT.f90,
        # FixedInductions; BEMTUncoupled.f90)
        "fixed_tip_induction": tip_loss,
        "shed_wake": shed_wake(ad),
        "dynamic_stall": model in SEPARATION_UA,
        "induction": induction(ad)[0],
        "stations": stations,
        "airfoils": airfoils,
        "control": dict(control),
    }
    read = [ad.path.name, blade.name, *(files[i - 1].name for i in used)]
    return block, read, list(ad.defaulted.values()), warnings
