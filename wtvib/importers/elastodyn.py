"""OpenFAST ElastoDyn (and FAST v7 ``.fst``) decks → wtvib spec data.

Reads the main deck's scalar inputs and the tower and blade files it names: the tower's
distributed properties and height, the nacelle, hub and blade masses and offsets, hub and
generator inertias, gear ratio and drive-shaft spring. The tower head is assembled from
its parts (nacelle, hub, blades, yaw bearing) as one rigid body.

References
----------
J. Jonkman, M. Buhl, *FAST User's Guide*, NREL/EL-500-38230, 2005 (input definitions);
OpenFAST ElastoDyn input-file documentation (same keys).
"""

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import SpecError
from ..numerics.rigid import Part, assembled, rotor_points
from ..spec.base import SHAPE_SUM_TOLERANCE
from . import beamdyn, stc
from .deck import Deck, _file, beside, parse, present
from .floating import refusal
from .servodyn import Operation, linearisation_point, operation
from .subdyn import STEP_M, Monopile, monopile, water


def deck_set(path: Path, text: str) -> tuple[Deck, Deck | None, Deck | None]:
    """The ElastoDyn deck, the OpenFAST main input (.fst) that names it, and the ServoDyn
    file that names — only files the deck set names, never files merely lying beside it.

    ``path`` may be an OpenFAST ``.fst`` (its EDFile is followed), an ElastoDyn deck (a
    ``.fst`` in the same folder whose EDFile is this file is taken as its main input) or a
    FAST v7 ``.fst`` (one file: its own controls).
    """
    first = parse(path, text)
    if "EDFile" in first.values:
        fst: Deck | None = first
        main = parse(_file(first, "EDFile"))
    else:
        main = first
        fst = None
        if "VSContrl" not in first.values:  # an OpenFAST ElastoDyn deck: find its .fst
            for cand in sorted(path.parent.glob("*.fst")):
                deck = parse(cand)
                if "EDFile" in deck.values:
                    named = beside(cand, deck.text("EDFile"))
                    if named == path.resolve():
                        fst = deck
                        break
    servo = None
    if fst is not None and "ServoFile" in fst.values and fst.num("CompServo", default=1) > 0:
        named = beside(fst.path, fst.text("ServoFile"))
        # a ServoDyn the .fst names but the deck set does not hold (OpenFAST's aero-map
        # case runs without it): none, which the operation then says
        servo = parse(_file(fst, "ServoFile")) if present(named) else None
    elif "VSContrl" in main.values:  # FAST v7: the controls are in the deck itself
        servo = main
    return main, fst, servo


#: ElastoDyn's platform degrees of freedom: any of them on, the tower's base moves.
PLATFORM_DOFS = ("PtfmSgDOF", "PtfmSwDOF", "PtfmHvDOF", "PtfmRDOF", "PtfmPDOF", "PtfmYDOF")


def platform(main: Deck, fst: Deck | None) -> tuple[str, bool] | None:
    """What the deck set puts under the tower that wtvib does not read — its platform
    degrees of freedom, the .fst's SubDyn, HydroDyn and mooring modules, FAST v7's
    PtfmModel — and whether it floats (moorings, or PtfmModel 3); None: a fixed base."""
    found = [k for k in PLATFORM_DOFS if main.flag(k)]
    floating = False
    if fst is not None:
        for key, name in (("CompSub", "SubDyn"), ("CompHydro", "HydroDyn")):
            if fst.num(key, default=0) > 0:
                found.append(f"{name} ({key})")
        if fst.num("CompMooring", default=0) > 0:
            found.append("moorings (CompMooring)")
            floating = True
    model = main.num("PtfmModel", default=0)  # FAST v7
    if model >= 2:
        found.append(f"PtfmModel {model:g}")
        floating = floating or model >= 3
    return (", ".join(found), floating) if found else None


#: ElastoDyn's degrees of freedom (its "DEGREES OF FREEDOM" switches).
DOFS = (
    "FlapDOF1",
    "FlapDOF2",
    "EdgeDOF",
    "TeetDOF",
    "DrTrDOF",
    "GenDOF",
    "YawDOF",
    "TwFADOF1",
    "TwFADOF2",
    "TwSSDOF1",
    "TwSSDOF2",
    *PLATFORM_DOFS,
)


@dataclass(frozen=True)
class _Switches:
    """ElastoDyn's degrees of freedom as the deck switches them, in wtvib's terms: the
    blade modes kept (None: all three), the nacelle held in yaw, the generator locked to
    the rotor's speed, the drive shaft rigid, the tower rigid, the platform held — and the
    sentence that says it (None: every DOF on)."""

    blade: list[str] | None
    yaw_held: bool
    generator_locked: bool
    shaft_rigid: bool
    tower_rigid: bool
    platform_held: bool
    note: str | None


def _switches(main: Deck, floating: bool, follow: bool, beamdyn: bool) -> _Switches:
    """What the deck's DOF switches leave of the turbine (a missing switch is on, as in
    ElastoDyn's templates), where the audit follows them (``follow``: ``--deck-dofs``);
    otherwise nothing is switched off and the note says what OpenFAST's model of the deck
    lacks. Where only some of a tower plane's or a platform's DOFs are off, the structure
    keeps them (said): wtvib's tower and platform are not built of ElastoDyn's modes."""

    def on(key: str) -> bool:
        return main.flag(key) if key in main.values else True

    # ElastoDyn's blade has these three DOFs and no more: followed, the coupled model has
    # them alone even where all are on
    blade = [n for n, k in (("flap1", "FlapDOF1"), ("flap2", "FlapDOF2"), ("edge1", "EdgeDOF"))
             if on(k)]  # fmt: skip
    tower = [k for k in ("TwFADOF1", "TwFADOF2", "TwSSDOF1", "TwSSDOF2") if on(k)]
    platform = [k for k in PLATFORM_DOFS if on(k)]
    off = [k for k in DOFS if k in main.values and not main.flag(k) and k != "TeetDOF"]
    if not floating:
        off = [k for k in off if k not in PLATFORM_DOFS]
    if beamdyn:  # BeamDyn's blades: ElastoDyn's blade switches do not apply
        blade_keys = ("FlapDOF1", "FlapDOF2", "EdgeDOF")
        off = [k for k in off if k not in blade_keys]
    if not follow:
        return _Switches(None, False, False, False, False, False, _unfollowed(off))
    out = _Switches(
        None if beamdyn else blade,
        not on("YawDOF"),
        not on("GenDOF"),
        not on("DrTrDOF"),
        not tower,
        floating and not platform,
        None,
    )
    if not off:
        return (
            out
            if any(k in main.values for k in DOFS)
            else _Switches(None, False, False, False, False, False, None)
        )
    kept = []
    if out.blade is not None:
        kept.append(f"the blades' {', '.join(out.blade) or 'no'} modes only")
    if out.yaw_held:
        kept.append("the nacelle held in yaw (no tower torsion assumed)")
    if out.generator_locked:
        kept.append("the generator locked to the rotor's speed")
    if out.shaft_rigid:
        kept.append("a rigid drive shaft")
    if out.tower_rigid:
        kept.append("a rigid tower")
    elif len(tower) < 4:
        tower_off = sorted(set(off) & {"TwFADOF1", "TwFADOF2", "TwSSDOF1", "TwSSDOF2"})
        kept.append(
            f"the tower flexible all the same ({', '.join(tower_off)} off in the deck: wtvib's "
            "tower is finite elements, not ElastoDyn's two shapes a plane)"
        )
    if out.platform_held:
        kept.append("the platform held (the tower clamped at its base)")
    elif floating and len(platform) < 6:
        kept.append("the platform free in all six motions all the same")
    note = (
        f"ElastoDyn's degrees of freedom as the deck switches them ({', '.join(off)} off): "
        f"modelled as OpenFAST models the deck — {'; '.join(kept)}."
    )
    return _Switches(out.blade, out.yaw_held, out.generator_locked, out.shaft_rigid,
                     out.tower_rigid, out.platform_held, note)  # fmt: skip


#: Said where a deck read as OpenFAST models it has ElastoDyn's yaw DOF on and no yaw spring.
FREE_YAW = (
    "ElastoDyn's yaw DOF is on and the deck set gives no yaw spring (ServoDyn's YawSpr, or no "
    "ServoDyn): as OpenFAST models it, the nacelle turns freely on the tower top, and the "
    "tower does not twist (ElastoDyn has no tower torsion) — a free yaw lifts the blades' "
    "cyclic flap modes."
)

#: ElastoDyn models one to three blades (NumBl; its blade inputs are BldFile(1..3)).
MAX_BLADES = 3


def _same(a: Deck, b: Deck) -> bool:
    """Two member files with the same inputs and tables (line numbers aside)."""
    values = {k: v for k, (v, _) in a.values.items()} == {k: v for k, (v, _) in b.values.items()}
    return (
        values
        and a.tables.keys() == b.tables.keys()
        and all(
            a.tables[k][0] == b.tables[k][0]
            and np.array_equal(a.tables[k][1], b.tables[k][1], equal_nan=True)
            for k in a.tables
        )
    )


def _blades_differ(main: Deck, first: Deck, blades: int) -> list[str]:
    """A warning where the deck names blade files whose tables differ from blade 1's: every
    blade is modelled as blade 1 (a rotor of unlike blades is out of balance — a 1P load
    wtvib does not size)."""
    other = []
    for b in range(2, min(blades, MAX_BLADES) + 1):  # ElastoDyn's blades: 1 to 3
        keys = (f"BldFile({b})", f"BldFile{b}")
        if not any(k in main.values for k in keys):
            continue
        path = _file(main, *keys)
        if path != first.path and not _same(parse(path), first):
            other.append(f"{keys[0]} = {path.name}")
    if not other:
        return []
    return [
        f"rotor: the deck's blades differ ({', '.join(other)} against BldFile(1) = "
        f"{first.path.name}): every blade is modelled as blade 1 — an unbalanced rotor's 1P "
        "load is not sized"
    ]


def to_spec_data(
    path: Path,
    text: str,
    clamped_base: bool = False,
    speed_given: bool = False,
    deck_dofs: bool = False,
) -> dict[str, Any]:
    """wtvib spec data from an ElastoDyn deck, an OpenFAST .fst or a FAST v7 .fst.

    A deck set whose tower stands on a platform (its platform degrees of freedom, SubDyn,
    HydroDyn or moorings) is audited with the tower clamped at its base, which the report's
    headline says; a floating one is refused unless ``clamped_base`` asks for that. A
    parked deck (no controller, RotSpeed 0) needs the operating range (``speed_given``:
    the command line gives it)."""
    main, fst, servo = deck_set(path, text)
    _refuse_marine(fst)
    path = main.path
    below = platform(main, fst)
    beamdyn = fst is not None and fst.num("CompElast", default=1) == 2
    if beamdyn and _beam_alone(main):
        assert fst is not None
        return _beam_data(main, fst)
    switches = _switches(main, below is not None and below[1], deck_dofs, beamdyn)
    held = clamped_base or switches.platform_held
    floater = _floater(main, fst, below, held)
    tower_file = parse(_file(main, "TwrFile"))
    source = f"{path.name} (OpenFAST ElastoDyn deck) and the tower and blade files it names"
    n_blades = main.whole("NumBl", low=1, high=MAX_BLADES)
    tower_height = main.num("TowerHt") - main.num("TowerBsHt", default=0.0)
    yaw_block = _yaw_block(main, servo, switches, deck_dofs)
    tw = _tower_on_support(
        main, fst, below, floater, tower_file, tower_height, bool(yaw_block) or switches.yaw_held
    )

    tip, hub_r = main.num("TipRad"), main.num("HubRad")
    length = tip - hub_r
    _check_geometry(main, tip)
    bl = _blade(main, fst, length, n_blades)
    hub = _hub_inertia(main, hub_r)
    head, breakdown = tower_head(
        main, bl.span, bl.mass, hub_r, n_blades, hub["inertia_kgm2"]["value"]
    )
    operating = _operating(main, servo, fst, speed_given)
    from .aerodyn import aerodynamics

    aero = aerodynamics(fst, hub_r, operating.control)
    blade = _blade_section(main, bl, length, hub_r)
    if bl.polynomials:
        blade["polynomials"] = bl.polynomials
    data: dict[str, Any] = {
        "wtvib": 1,
        "turbine": _turbine_block(main, path, tip, head),
        "sources": {"deck": source},
        "rotor": _rotor_block(main, n_blades, operating),
        "tower": _tower_section(tw, tower_file, floater is not None, tower_height),
        "tower_head": _head_block(head),
        "blade": blade,
        "drivetrain": {**_drivetrain_block(main, head, hub, n_blades), **operating.generator},
        **yaw_block,
        "coupled": _coupled_block(main, head),
        "assumptions": [
            f"Imported from the ElastoDyn deck {path.name}; tower and blade properties as "
            "tabulated there, with its adjustment factors applied.",
            "Tower head assembled from its parts: " + breakdown + ".",
            "Precone and shaft tilt are neglected in the head inertia"
            + _standing(floater is not None, bool(tw.block)),
            *bl.notes,
            *tw.notes,
            operating.note,
            *([FREE_YAW] if yaw_block.get("yaw", {}).get("drive") == "free" else []),
            _files_read(main, [d.path for d in (fst, main, servo) if d is not None], aero),
        ],
    }
    warnings = list(operating.warnings) + (aero[3] if aero else []) + bl.warnings + tw.warnings
    if beamdyn:
        _beamdyn_coupling(data)
    _finish(data, servo if fst is not None else None, switches, warnings, below, tw)
    if aero is not None:
        _add_aerodynamics(data, aero, operating)
    return data


def _operating(main: Deck, servo: Deck | None, fst: Deck | None, given: bool) -> Operation:
    """The deck set's operating range and control; a parked deck needs the range ``given``
    (the command line's --rpm)."""
    operating = operation(main, servo, fst)
    if operating.speed is None and not given:
        raise SpecError(
            f"{operating.note.removesuffix('.')}; give the operating range with --rpm MIN:MAX",
            source=str(main.path),
        )
    found = linearisation_point(main, fst) if operating.initial and not given else None
    if found is not None:  # the one point OpenFAST linearises, not a schedule invented
        operating.control["operating_points"], said = found
        operating.note += f" {said[0].upper()}{said[1:]}."
        operating.warnings = [
            w.replace("as a fixed-speed turbine;", f"as a fixed-speed turbine ({said});")
            for w in operating.warnings
        ]
    return operating


def _finish(
    data: dict[str, Any],
    servo: Deck | None,
    switches: _Switches,
    warnings: list[str],
    below: tuple[str, bool] | None,
    tw: "_TowerOnSupport",
) -> None:
    """The deck's structural control (ServoDyn's StC dampers), its degree-of-freedom
    switches applied, and the warnings and notes of the tower's support put in ``data``."""
    control = stc.read(servo)
    if control.dampers:
        data["tower"]["dampers"] = control.dampers
    data["assumptions"] += control.notes
    warnings = warnings + control.warnings
    _apply(switches, data)
    warnings += data.pop("warnings", [])
    if below is not None and not tw.block:
        warnings.append(_clamped_warning(below, tw.pile, tw.base))
    if warnings:
        data["warnings"] = warnings
    if tw.torsion is not None:
        data["assumptions"].append(tw.torsion[2])


def _turbine_block(main: Deck, path: Path, tip: float, head: dict[str, Any]) -> dict[str, Any]:
    """The spec's turbine block: the deck's name, rotor diameter and hub height."""
    return {
        "name": path.stem.replace("_ElastoDyn", ""),
        # twice TipRad is exact: kept to the deck's digits (six would put the rotor's tip
        # inside AeroDyn's last node at TipRad − HubRad: BAR_USC's TipRad 102.82618…)
        "rotor_diameter_m": _value(2 * tip, "2 × TipRad", "derived", digits=10),
        "hub_height_m": _value(
            main.num("TowerHt") + head["hub_above_top"],
            "TowerHt + Twr2Shft + OverHang·sin(ShftTilt)",
            "derived",
        ),
    }


def _rotor_block(main: Deck, n_blades: int, operating: Operation) -> dict[str, Any]:
    """The spec's rotor block: blades, orientation, hub and the operating speeds."""
    return {
        "blades": n_blades,
        "orientation": "upwind" if main.num("OverHang") < 0 else "downwind",
        "hub": "teetered" if n_blades == 2 and main.num("TeetMod", default=0) else "hingeless",
        "speed": _speed_block(operating.speed),
    }


def _beamdyn_coupling(data: dict[str, Any]) -> None:
    """BeamDyn's blade has every mode: the coupled model takes the second edgewise bending
    too, which carries the collective edge's coupling with the shaft and the tower's second
    side-side (5MW_Land_BD_Linear: 2.84/3.23 Hz against OpenFAST's 2.78/3.21, where three
    modes gave 2.94/3.92) and the yaw mode's root stiffness."""
    data["coupled"]["blade_modes"] = 5
    data["assumptions"].append(
        "BeamDyn blades: the coupled model carries five blade modes (flap 1 and 2, edge "
        "1 and 2 and the next), one more than by default — BeamDyn's blade has them all."
    )


#: ElastoDyn's DOFs of the turbine around its blades: all off (and no hub or nacelle mass),
#: a BeamDyn deck set's structure is its blade alone.
_AROUND_BLADES = ("DrTrDOF", "GenDOF", "YawDOF", "TwFADOF1", "TwFADOF2", "TwSSDOF1", "TwSSDOF2")


def _beam_alone(main: Deck) -> bool:
    """A BeamDyn deck set whose ElastoDyn has nothing around the blades: its drive train,
    yaw and tower DOFs off (a missing switch is on) and no hub, hub inertia or nacelle mass
    — OpenFAST's test beams (r-test ``Ideal_Beam_*``), a blade tested on its own."""
    on = [k for k in _AROUND_BLADES if k not in main.values or main.flag(k)]
    masses = (main.num(k, default=0.0) for k in ("HubMass", "HubIner", "NacMass", "YawBrMass"))
    return not on and not any(masses)


def _beam_data(main: Deck, fst: Deck) -> dict[str, Any]:
    """The spec of a deck set whose structure is BeamDyn's blade alone: the blade, free
    where ElastoDyn's platform is free in all six motions with nothing under it (no
    HydroDyn, SubDyn or moorings) and a mass negligible beside the blade's — the beam then
    stands on nothing — else clamped; at the deck's RotSpeed, a standstill audit at 0 rpm."""
    bd = beamdyn.blade(fst)
    n_blades = main.whole("NumBl", low=1, high=MAX_BLADES)
    modules = [k for k in ("CompHydro", "CompSub", "CompMooring") if fst.num(k, default=0) > 0]
    platform_mass = main.num("PtfmMass", default=0.0)
    free = (
        all(main.flag(k) for k in PLATFORM_DOFS)
        and not modules
        and platform_mass < 1e-3 * bd.mass_kg
    )
    rpm = main.num("RotSpeed", default=0.0)
    if rpm > 0 and free:
        raise SpecError(
            f"RotSpeed = {rpm:g} rpm for a beam free on nothing (every platform DOF on, "
            f"PtfmMass {platform_mass:g} kg): nothing holds it against the centrifugal force",
            line=main.line("RotSpeed"),
            source=str(main.path),
        )
    damping, how = _bd_damping(bd, None)
    if bd.mu is None:
        damping, how = (
            0.0,
            (
                "Blade damping: none — BeamDyn's beam is undamped (damp_type 0), as OpenFAST "
                "models it."
            ),
        )
    root = (
        "free: ElastoDyn's platform is free in all six motions, with nothing under it and a "
        f"mass ({platform_mass:g} kg) negligible beside the blade's {bd.mass_kg:,.0f} kg"
        if free
        else "clamped: ElastoDyn's platform and tower held"
    )
    speed = (
        {"fixed_rpm": rpm, "source": f"the deck's RotSpeed ({main.path.name})"}
        if rpm > 0
        else {"parked": True, "source": f"RotSpeed 0 in {main.path.name}: a standstill audit"}
    )
    return {
        "wtvib": 1,
        "turbine": {"name": fst.path.stem},
        "sources": {"deck": f"{fst.path.name} (OpenFAST, BeamDyn beam alone)"},
        "rotor": {
            "blades": n_blades,
            "orientation": "upwind",
            "hub": "hingeless",
            "speed": speed,
        },
        "blade": {
            "structure": {**bd.structure, "root": "free" if free else "clamped"},
            **({"damping_ratio": damping} if damping is not None else {}),
            **_mu(bd),
        },
        "assumptions": [
            f"A BeamDyn beam alone: the deck set's ElastoDyn has no DOF around its "
            f"blade{'s' if n_blades > 1 else ''} ({', '.join(_AROUND_BLADES)} off) and no hub, "
            "nacelle or yaw-bearing mass — its structure is BeamDyn's blade, modelled as a "
            f"beam {root}"
            + (
                f"; its {n_blades} blades are alike and apart (no hub joins them)"
                if n_blades > 1
                else ""
            )
            + ".",
            *bd.notes,
            how,
        ],
    }


def _unfollowed(off: list[str]) -> str | None:
    """The warning of a deck whose switched-off DOFs the audit does not follow."""
    if not off:
        return None
    return (
        f"dofs: the deck switches off {', '.join(off)} — OpenFAST's model of it lacks those "
        "modes; this audit has every mode of the structure (--deck-dofs models the deck as "
        "OpenFAST does)"
    )


#: Angles no turbine's shaft or cone has (ElastoDyn takes any): refused above this; a
#: reference turbine's tilt and cone are 4–6°, above the second bound is said.
ANGLE_LIMIT_DEG, ANGLE_ODD_DEG = 45.0, 15.0


def _check_geometry(main: Deck, tip: float) -> None:
    """Geometry no turbine can have, named by the deck's key and line: a hub lower than the
    rotor's radius (the tips through the ground: TowerHt + Twr2Shft against TipRad), a shaft
    tilt or a cone of any blade the rotor has of 45° and more."""
    hub = main.num("TowerHt") + main.num("Twr2Shft", default=0.0)
    if tip > 0 and hub <= tip:
        raise SpecError(
            f"TowerHt {main.num('TowerHt'):g} m puts the hub at about {hub:g} m under a rotor "
            f"radius TipRad = {tip:g} m: the blade tips would strike the ground",
            line=main.line("TowerHt"),
            source=str(main.path),
        )
    blades = int(main.num("NumBl", default=3.0))
    cones = [f"PreCone({i})" for i in range(1, blades + 1)]
    for key in ("ShftTilt", *cones, *(c.replace("(", "").replace(")", "") for c in cones)):
        if key in main.values and abs(main.num(key)) >= ANGLE_LIMIT_DEG:
            raise SpecError(
                f"{key} = {main.num(key):g}°: no rotor turns with its shaft or cone so far from "
                f"the plane (|{key}| < {ANGLE_LIMIT_DEG:g}°; reference turbines 4–6°)",
                line=main.values[key][1],
                source=str(main.path),
            )


def _apply(switches: _Switches, data: dict[str, Any]) -> None:
    """The deck's DOF switches on the spec data (:func:`_switches`): followed, or said."""
    if switches.blade is not None:  # followed (every one on: ElastoDyn's three alone)
        data["blade"]["dofs"] = switches.blade
    if switches.note is None:
        return
    if switches.note.startswith("dofs:"):  # not followed: a warning of what OpenFAST lacks
        data.setdefault("warnings", []).append(switches.note)
        return
    if switches.generator_locked:
        data["coupled"]["rotating_condition"] = "locked"
        data["coupled"]["parked_condition"] = "locked"
    if switches.shaft_rigid:
        data["drivetrain"]["shafts"][-1] = {"stiffness_nm_rad": None}
    if switches.tower_rigid:
        data["tower"]["rigid"] = True
    data["assumptions"].append(switches.note)


def _refuse_marine(fst: Deck | None) -> None:
    """A marine hydrokinetic turbine is refused: the water's loads are not modelled."""
    if fst is not None and fst.num("MHK", default=0) > 0:
        raise SpecError(
            f"a marine hydrokinetic (tidal) turbine (MHK = {fst.num('MHK'):g}): wtvib audits "
            "wind turbines — the water's loads and buoyancy on the tower and rotor are not "
            "modelled",
            line=fst.values["MHK"][1],
            source=str(fst.path),
        )


def _floater(
    main: Deck, fst: Deck | None, below: tuple[str, bool] | None, clamped_base: bool
) -> tuple[dict[str, Any], list[str]] | None:
    """A floating deck set's platform block and notes (HydroDyn, WAMIT, moorings), unless
    the tower is read clamped at its base; a floater wtvib cannot model is refused."""
    if below is None or not below[1] or clamped_base:
        return None
    from .hydrodyn import platform as floating_platform

    found = floating_platform(main, fst) if fst is not None else "no .fst names its modules"
    if isinstance(found, str):
        raise refusal(below[0], found, str(main.path))
    return found


@dataclass
class _TowerOnSupport:
    """The tower as audited: its tables (``heights`` from its base — on a monopile, from
    the pile's reaction joint up), its height, the spec's foundation block (empty where
    the tower is clamped at its base), and what the support adds to the notes and
    warnings."""

    heights: np.ndarray
    mass: np.ndarray
    ei_fa: np.ndarray
    ei_ss: np.ndarray
    torsion: tuple[np.ndarray, np.ndarray, str] | None
    height: float
    block: dict[str, Any]
    notes: list[str]
    warnings: list[str]
    pile: Any  # the Monopile read, or why there is none
    base: float  # ElastoDyn's TowerBsHt [m]


def _tower_on_support(
    main: Deck,
    fst: Deck | None,
    below: tuple[str, bool] | None,
    floater: tuple[dict[str, Any], list[str]] | None,
    tower_file: Deck,
    tower_height: float,
    yaw: bool,
) -> _TowerOnSupport:
    """The tower file's tables on what the tower stands on: SubDyn's monopile, a floating
    platform, or a clamped base."""
    frac, mass, ei_fa, ei_ss, torsion = _tower_tables(tower_file, yaw)
    ed_base = main.num("TowerBsHt", default=0.0)
    heights = frac * tower_height
    pile = _monopile(main, fst, below)
    notes: list[str] = []
    warnings: list[str] = []
    block: dict[str, Any] = {}
    if isinstance(pile, Monopile):
        heights, mass, ei_fa, ei_ss, torsion, block = _on_pile(
            pile, fst, ed_base, heights, mass, ei_fa, ei_ss, torsion
        )
        tower_height = heights[-1]
        notes, warnings = pile.notes, pile.warnings
    if floater is not None:
        block = {"foundation": {"kind": "platform", "platform": floater[0]}}
        notes = floater[1]
    return _TowerOnSupport(
        heights, mass, ei_fa, ei_ss, torsion, tower_height, block, notes, warnings, pile, ed_base
    )


def _tower_section(
    tw: _TowerOnSupport, tower_file: Deck, floating: bool, flexible: float
) -> dict[str, Any]:
    """The spec's tower block; ``flexible`` ElastoDyn's tower length (TowerHt − TowerBsHt),
    over which its polynomials run — on a pile, from the pile's top."""
    return {
        "polynomials": polynomials(tower_file, TOWER_POLYNOMIALS),
        **({"polynomial_base_m": tw.height - flexible} if tw.height > flexible + 1e-9 else {}),
        "height_m": _value(
            tw.height,
            "TowerHt − the SubDyn reaction joint's z"
            if tw.block and not floating
            else "TowerHt − TowerBsHt",
            "derived",
        ),
        "damping_ratio": main_damping(tower_file, "TwrFADmp(1)"),
        # ElastoDyn's (and FAST's) ratios: per mode, stiffness-proportional at the frequency
        # its polynomial implies on the tower alone (CTFA = 0.01·TwrFADmp·KTFA/(π·FreqTFA(:,1)))
        "damping_by_mode": {
            name: main_damping(tower_file, key)
            for name, key in (
                ("fa1", "TwrFADmp(1)"),
                ("fa2", "TwrFADmp(2)"),
                ("ss1", "TwrSSDmp(1)"),
                ("ss2", "TwrSSDmp(2)"),
            )
        },
        "damping_at": "tower-alone",
        **tw.block,
        "distributed": _distributed(tw.heights, tw.mass, tw.ei_fa, tw.ei_ss, tw.torsion)
        | _rows(tower_file, "HtFract", TOWER_COLUMNS, len(tw.heights)),
    }


#: The spec's tower and blade fields and the ElastoDyn columns they come from.
TOWER_COLUMNS = {
    "height_m": "HtFract",
    "mass_per_length_kg_m": "TMassDen",
    "ei_fa_nm2": "TwFAStif",
    "ei_ss_nm2": "TwSSStif",
    "gj_nm2": "TwGJStif",
}
BLADE_COLUMNS = {
    "span_m": "BlFract",
    "mass_per_length_kg_m": "BMassDen",
    "ei_flap_nm2": "FlpStff",
    "ei_edge_nm2": "EdgStff",
    "twist_deg": "StrcTwst",
}


def _rows(deck: Deck, table: str, columns: dict[str, str], stations: int) -> dict[str, Any]:
    """The table's ``rows`` block (spec.base.TableRows: file, line of each station, column
    names), where the spec's stations are the file's one for one (not under a monopile,
    whose stations are the pile's and the tower's together)."""
    lines = deck.station_lines(table)
    if lines is None or len(lines) != stations:
        return {}
    return {"rows": {"file": str(deck.path), "lines": lines, "columns": columns}}


def _blade_section(main: Deck, bl: "_BladeTable", length: float, hub_r: float) -> dict[str, Any]:
    """The spec's blade block; a tip brake's mass on the blade model too, not only in the
    head's mass."""
    structure: dict[str, Any] = {"hub_radius_m": hub_r, **bl.structure}
    tip_mass = main.num("TipMass(1)", "TipMass1", default=0.0)
    if tip_mass > 0:
        structure["tip_mass_kg"] = tip_mass
    return {
        "length_m": _value(length, "TipRad − HubRad", "derived", digits=10),  # ≤ TipRad
        "mass_kg": _value(float(np.trapezoid(bl.mass, bl.span)), bl.mass_source, "derived"),
        **({"damping_ratio": bl.damping} if bl.damping is not None else {}),
        **(_mu(bl) if bl.mu is not None else {}),
        **({"damping_by_mode": bl.by_mode, "damping_at": "blade-alone"} if bl.by_mode else {}),
        "structure": structure,
    }


def _standing(floating: bool, on_pile: bool) -> str:
    """The end of the assumption that says what the tower stands on."""
    if floating:
        return "; the tower stands on its floating platform (ElastoDyn's platform DOFs)."
    if on_pile:
        return (
            "; the tower stands on its SubDyn monopile (ElastoDyn's platform DOFs are "
            "the transition piece's motion on it)."
        )
    return "; the tower is clamped at its base (ElastoDyn's platform and foundation are not read)."


def _files_read(main: Deck, read: list[Path], aero: Any) -> str:
    """The assumption that lists the files read (beside the main deck: by name)."""
    return (
        "Files read: "
        + ", ".join(str(p) if p.parent != main.path.parent else p.name for p in dict.fromkeys(read))
        + " (and the tower and blade files the deck names"
        + (f"; AeroDyn: {', '.join(aero[1])}" if aero else "")
        + ")."
    )


def _tower_tables(tower: Deck, yaw: bool) -> tuple[Any, Any, Any, Any, Any]:
    """The tower file's stations (height fractions), mass and bending stiffness per length
    with its adjustment factors, and its torsion (:func:`_tower_torsion`; ``yaw``: the deck
    set has a yaw drive); a single station is a uniform tower."""
    frac = tower.fractions("HtFract")
    mass = tower.positive("HtFract", "TMassDen") * tower.factor("AdjTwMa")
    ei_fa = tower.positive("HtFract", "TwFAStif") * tower.factor("AdjFASt")
    ei_ss = tower.positive("HtFract", "TwSSStif") * tower.factor("AdjSSSt")
    torsion = _tower_torsion(tower, mass, ei_fa, yaw)
    if len(frac) == 1:  # one station (NTwInpSt = 1): a uniform tower
        frac = np.array([0.0, 1.0])
        mass, ei_fa, ei_ss = (np.repeat(a, 2) for a in (mass, ei_fa, ei_ss))
        torsion = (
            None
            if torsion is None
            else (np.repeat(torsion[0], 2), np.repeat(torsion[1], 2), torsion[2])
        )
    return frac, mass, ei_fa, ei_ss, torsion


def _distributed(
    heights: np.ndarray, mass: np.ndarray, ei_fa: np.ndarray, ei_ss: np.ndarray, torsion: Any
) -> dict[str, Any]:
    """The tower's distributed properties block (with torsion where the deck set gives or
    implies it)."""
    out = {
        "height_m": _list(heights),
        "mass_per_length_kg_m": _list(mass),
        "ei_fa_nm2": _list(ei_fa),
        "ei_ss_nm2": _list(ei_ss),
    }
    if torsion is not None:
        out |= {"gj_nm2": _list(torsion[0]), "polar_inertia_kgm": _list(torsion[1])}
    return out


def _head_block(head: dict[str, Any]) -> dict[str, Any]:
    """The tower head as one rigid body (:func:`tower_head`), each value with its source."""
    return {
        "mass_kg": _value(head["mass"], "NacMass + HubMass + blades + YawBrMass", "derived"),
        "cm_downwind_m": _value(head["x"], "mass-weighted over the parts", "derived"),
        "cm_above_top_m": _value(head["z"], "mass-weighted over the parts", "derived"),
        "inertia_pitch_kgm2": _value(
            head["pitch"],
            "parts about the head CM; rotor about a "
            "diameter; nacelle a point mass in pitch (as ElastoDyn)",
            "derived",
        ),
        "inertia_roll_kgm2": _value(
            head["roll"],
            "parts about the head CM; rotor polar inertia (rotor locked to the nacelle)",
            "derived",
        ),
        "inertia_yaw_kgm2": _value(
            head["yaw"], "NacYIner and rotor about a diameter, about the head CM", "derived"
        ),
    }


def _drivetrain_block(
    main: Deck, head: dict[str, Any], hub: dict[str, Any], n_blades: int
) -> dict[str, Any]:
    """The drive train's chain — blades, hub, generator on the high-speed shaft — with
    ElastoDyn's equivalent shaft spring and damper (the blades' edgewise spring between
    blades and hub)."""
    return {
        "gear_ratio": _value(main.num("GBRatio"), "GBRatio"),
        "chain": [
            {
                "name": "blades",
                "inertia_kgm2": _value(head["j_blades"], f"{n_blades} × ∫ m·r² dr", "derived"),
            },
            hub,
            {
                "name": "generator",
                "inertia_kgm2": _value(main.num("GenIner"), "GenIner (HSS)"),
                "speed_ratio": _value(main.num("GBRatio"), "GBRatio"),
            },
        ],
        "shafts": [
            {"stiffness_nm_rad": None},  # blades–hub: the blades' edgewise spring
            {
                "stiffness_nm_rad": _value(main.num("DTTorSpr"), "DTTorSpr (LSS equivalent)"),
                "damping_nms_rad": _value(main.num("DTTorDmp", default=0.0), "DTTorDmp"),
            },
        ],
    }


def _coupled_block(main: Deck, head: dict[str, Any]) -> dict[str, Any]:
    """Where the coupled model's rotor apex sits on the tower top, and the hub's mass."""
    return {
        "apex_downwind_m": _value(
            main.num("OverHang") * math.cos(math.radians(main.num("ShftTilt", default=0.0))),
            "OverHang·cos(ShftTilt)",
            "derived",
        ),
        "apex_above_top_m": _value(
            head["hub_above_top"], "Twr2Shft + OverHang·sin(ShftTilt)", "derived"
        ),
        "hub_mass_kg": _value(main.num("HubMass"), "HubMass"),
    }


def _clamped_warning(below: tuple[str, bool], pile: Any, base: float) -> str:
    """The headline warning of a tower whose platform wtvib does not model."""
    why = f": {pile}" if isinstance(pile, str) else ""
    return (
        f"tower.foundation: the deck set's tower stands on a platform ({below[0]}{why}), "
        "which wtvib does not model: the tower is clamped at its base (TowerBsHt = "
        f"{base:g} m), so its bending frequencies are upper bounds"
        + (
            " and the platform's and moorings' own modes are missing"
            if below[1]
            else " (the substructure's own flexibility lowers them)"
        )
    )


def _add_aerodynamics(data: dict[str, Any], aero: Any, operating: Any) -> None:
    """The AeroDyn block into the spec data, the controller's rated power as the turbine's,
    and what was taken from where."""
    data["aerodynamics"] = aero[0]
    control = aero[0]["control"]
    rated = control.get("rated_power_kw")
    if rated is not None:
        data["turbine"]["rated_power_kw"] = _value(
            rated, f"VS_RtPwr ({operating.controller_file})"
            if operating.controller_file else "VS_RtTq·VS_RtGnSp·GenEff (ServoDyn)",
        )  # fmt: skip
    given = [
        f"{key} {control[field]:.6g}{unit}"
        for key, field, unit in (
            ("VS_TSRopt", "tip_speed_ratio", " (region-2 tip-speed ratio)"),
            ("VS_RtPwr", "rated_power_kw", " kW (rated power)"),
            ("PC_FinePit", "fine_pitch_deg", "° (fine pitch)"),
        )
        if field in control
    ]
    data["assumptions"].append(
        "Aerodynamics from AeroDyn 15 (stations at HubRad + BlSpn, precone neglected; the "
        "first table of each aerofoil file); cut-in and cut-out wind not in the deck set: "
        "3 and 25 m/s assumed."
        + (
            f" From the controller ({operating.controller_file}): {', '.join(given)}."
            if given and operating.controller_file
            else ""
        )
        + "".join(f" {note}." for note in aero[2])
    )


#: A steel tube tower's defaults where the deck set gives no torsion (Jonkman et al. 2009 §6,
#: the NREL 5-MW tower: E 210 GPa, G 80.8 GPa, effective density 8,500 kg/m³ with paint,
#: bolts and welds): thin-walled tube J = 2I, so GJ = 2(G/E)·EI and ρJ = 2ρ·EI/E — the
#: FAST v7 tower file of the NREL 5-MW has exactly these at every station.
STEEL_E, STEEL_G, STEEL_RHO = 210e9, 80.8e9, 8500.0


def _tower_torsion(
    tower: Deck, mass: np.ndarray, ei_fa: np.ndarray, yaw_spring: bool
) -> tuple[np.ndarray, np.ndarray, str] | None:
    """The tower's torsional stiffness and polar inertia per length, and how they were found:
    FAST v7's TwGJStif (with TwFAIner + TwSSIner, else the thin tube's m·2EI/EA from
    TwEAStif); without them, and only where the deck set has no yaw spring either (the
    nacelle would be held in yaw, stiffening the cyclic flap modes), the steel
    tube's defaults. None: no torsion (ElastoDyn has none, a yaw spring carries yaw)."""
    gj = tower.optional_column("HtFract", "TwGJStif")
    if gj is not None and np.all(gj > 0):
        fa = tower.optional_column("HtFract", "TwFAIner")
        ss = tower.optional_column("HtFract", "TwSSIner")
        ea = tower.optional_column("HtFract", "TwEAStif")
        if fa is not None and ss is not None and np.all(fa + ss > 0):
            return (
                gj,
                fa + ss,
                "Tower torsion from the tower file's TwGJStif and TwFAIner + TwSSIner.",
            )
        if ea is not None and np.all(ea > 0):
            return (
                gj,
                mass * 2 * ei_fa / ea,
                (
                    "Tower torsion from the tower file's TwGJStif; polar inertia per length "
                    "m·2EI/EA (thin-walled tube, TwEAStif: the file gives no TwFAIner/TwSSIner)."
                ),
            )
    if yaw_spring:
        return None
    return (
        2 * STEEL_G / STEEL_E * ei_fa,
        2 * STEEL_RHO * ei_fa / STEEL_E,
        (
            "Tower torsion not in the deck set, and no yaw spring: a steel tube's GJ = 2(G/E)·EI "
            "and ρJ = 2ρ·EI/E (E 210, G 80.8 GPa, ρ 8,500 kg/m³; thin-walled tube, J = 2I) so that "
            "the nacelle is not held in yaw — an assumption; give tower.distributed.gj_nm2 to "
            "replace it."
        ),
    )


def tower_head(
    main: Deck,
    span: np.ndarray,
    bmass: np.ndarray,
    hub_r: float,
    n_blades: int,
    hub_iner: float | None = None,
) -> tuple[dict[str, float], str]:
    """The tower head as one rigid body: mass, CM and inertias about the CM (tower-top axes);
    ``hub_iner`` the hub's polar inertia the drive train takes (default HubIner).

    Notes
    -----
    Rotor apex at x = OverHang·cos(tilt), z = Twr2Shft + OverHang·sin(tilt) (ElastoDyn
    geometry: gives the published 90 m hub height of the NREL 5-MW). Blades are point masses
    at the apex for the CM; their inertia enters as the rotor's polar inertia J_p = N·∫m·r² dr
    + HubIner (roll, rotor locked) and diametral inertia J_p/2 (pitch and yaw, exact for
    three or more blades, the azimuth mean for two).
    """
    tilt = math.radians(main.num("ShftTilt", default=0.0))
    over = main.num("OverHang")
    x_apex = over * math.cos(tilt)
    z_apex = main.num("Twr2Shft") + over * math.sin(tilt)
    # the blade's mass and polar inertia on the points the blade and coupled models use
    # (the spec's own check of the head takes them so: the same numbers, never 3 % apart)
    points = rotor_points(hub_r, span, bmass)
    tip = main.num("TipMass(1)", "TipMass1", default=0.0)
    m_blade = float(points.mass.sum()) + tip
    j_blades = n_blades * (points.polar() + tip * (hub_r + float(span[-1])) ** 2)
    if hub_iner is None:
        hub_iner = main.num("HubIner", default=0.0)
    j_polar = j_blades + hub_iner
    nac_mass, nac_x = main.num("NacMass"), main.num("NacCMxn", default=0.0)
    parts = [
        # NacYIner is about the yaw axis: the nacelle's own, about its CM, less m·x²
        Part(
            "nacelle",
            nac_mass,
            nac_x,
            main.num("NacCMzn", default=0.0),
            yaw=main.num("NacYIner", default=0.0) - nac_mass * nac_x**2,
        ),
        # at the apex, as the coupled model places it (HubCM, a few per cent of the
        # overhang, neglected — said in the breakdown)
        Part("hub", main.num("HubMass"), x_apex, z_apex),
        # the rotor's polar inertia (roll, rotor locked) and about a diameter J_p/2
        Part(
            f"{n_blades} blades",
            n_blades * m_blade,
            x_apex,
            z_apex,
            0.5 * j_polar,
            j_polar,
            0.5 * j_polar,
        ),
        Part("yaw bearing", main.num("YawBrMass", default=0.0), 0.0, 0.0),
    ]
    head = assembled(parts)
    text = ", ".join(
        f"{p.name} {p.mass:,.0f} kg at x = {p.x:.2f} m, z = {p.z:.2f} m" for p in parts
    )
    text += f"; total {head.mass:,.0f} kg; rotor polar inertia {j_polar:,.0f} kg·m²"
    if main.num("HubCM", default=0.0):
        text += f" (the hub at the apex: HubCM {main.num('HubCM'):g} m neglected)"
    return {
        "mass": head.mass,
        "x": head.x,
        "z": head.z,
        "pitch": head.pitch,
        "roll": head.roll,
        "yaw": head.yaw,
        "hub_above_top": z_apex,
        "j_blades": j_blades,
    }, text


@dataclass
class _BladeTable:
    """Blade 1 as the deck set models it (ElastoDyn's table or BeamDyn's matrices)."""

    span: np.ndarray
    mass: np.ndarray
    structure: dict[str, Any]
    damping: float | None  # None: BeamDyn's μ, mode by mode (_bd_damping)
    mass_source: str
    notes: list[str]
    warnings: list[str]
    polynomials: dict[str, Any] = field(default_factory=dict)
    mu: tuple[float, float] | None = None  # BeamDyn's stiffness-proportional μ (flap, edge)
    #: ElastoDyn's ratio of each blade degree of freedom (BldFlDmp(1), (2), BldEdDmp(1))
    by_mode: dict[str, float] = field(default_factory=dict)


#: ElastoDyn's mode-shape polynomials: the spec's name of each set, by the deck's key.
TOWER_POLYNOMIALS = {"TwFAM1Sh": "fa1", "TwFAM2Sh": "fa2", "TwSSM1Sh": "ss1", "TwSSM2Sh": "ss2"}
BLADE_POLYNOMIALS = {"BldFl1Sh": "flap1", "BldFl2Sh": "flap2", "BldEdgSh": "edge1"}


def polynomials(deck: Deck, keys: dict[str, str]) -> dict[str, Any]:
    """The mode-shape polynomials of a tower or blade file (``keys``: the deck's key → the
    spec's name): c₂ … c₆ of each, with the file and the line of its first coefficient. A
    set that does not add to 1 is refused as ElastoDyn refuses it (ElastoDyn_IO.f90,
    ValidateModeShapeCoeffs); a coefficient missing or not a number names its key."""
    out = {}
    for key, name in keys.items():
        names = [f"{key}({k})" for k in range(2, 7)]
        absent = [n for n in names if n not in deck.values]
        if absent:
            near = [deck.values[n][1] for n in names if n in deck.values]
            raise SpecError(
                f"{absent[0]} is missing (ElastoDyn reads five coefficients of {key}, "
                "x² … x⁶, one a line)"
                + (f"; the others of the set are on lines {min(near)}–{max(near)}" if near else ""),
                line=None,
                source=str(deck.path),
            )
        coeffs = [deck.num(n) for n in names]
        first = names[0]
        total = sum(coeffs)
        if not all(math.isfinite(c) for c in coeffs) or abs(total - 1.0) > SHAPE_SUM_TOLERANCE:
            raise SpecError(
                f"{key}: its coefficients add to {total:.6g}, not 1 (φ(1) = 1) — ElastoDyn "
                f"stops on a sum more than {SHAPE_SUM_TOLERANCE:g} from 1",
                line=deck.values[first][1],
                source=str(deck.path),
            )
        out[name] = {
            "coefficients": coeffs,
            "name": key,
            "file": str(deck.path),
            "line": deck.values[first][1],
        }
    return out


def _blade(main: Deck, fst: Deck | None, length: float, n_blades: int) -> _BladeTable:
    """ElastoDyn's blade file, or BeamDyn's blade where the deck set runs BeamDyn
    (``CompElast`` = 2: ElastoDyn's blade files are then unused — said, with how the two
    differ where both are there)."""
    ed_keys = ("BldFile(1)", "BldFile1")
    ed_path = next(
        (beside(main.path, main.text(k)) for k in ed_keys if k in main.values),
        None,
    )
    ed = parse(_file(main, *ed_keys)) if ed_path is not None and present(ed_path) else None
    uses_bd = fst is not None and fst.num("CompElast", default=1) == 2
    if not uses_bd:
        if ed is None:
            _file(main, *ed_keys)  # the one-line error naming the key
        assert ed is not None
        span = ed.fractions("BlFract") * length
        mass = ed.positive("BlFract", "BMassDen") * ed.factor("AdjBlMs")
        structure: dict[str, Any] = {
            "span_m": _list(span),
            "mass_per_length_kg_m": _list(mass),
            "ei_flap_nm2": _list(ed.positive("BlFract", "FlpStff") * ed.factor("AdjFlSt")),
            "ei_edge_nm2": _list(ed.positive("BlFract", "EdgStff") * ed.factor("AdjEdSt")),
        }
        twist = ed.optional_column("BlFract", "StrcTwst")
        if twist is not None:
            structure["twist_deg"] = _list(twist)
        structure |= _rows(ed, "BlFract", BLADE_COLUMNS, len(span))
        # ElastoDyn's ratios, each at the frequency its polynomial implies on the blade
        # alone (CBF = 0.01·BldFDamp·KBF/(π·FreqBF(:,1)))
        by_mode = {
            name: main_damping(ed, key)
            for name, key in (
                ("flap1", "BldFlDmp(1)"), ("flap2", "BldFlDmp(2)"), ("edge1", "BldEdDmp(1)"),
            )
        }  # fmt: skip
        return _BladeTable(
            span, mass, structure, main_damping(ed, "BldFlDmp(1)"), "∫ BMassDen·AdjBlMs", [],
            _blades_differ(main, ed, n_blades), polynomials(ed, BLADE_POLYNOMIALS),
            by_mode=by_mode,
        )  # fmt: skip
    assert fst is not None
    bd = beamdyn.blade(fst)
    notes, warnings = list(bd.notes), []
    if abs(bd.length_m - length) > 0.01 * length:
        warnings.append(
            f"blade: BeamDyn's blade is {bd.length_m:.4g} m long but TipRad − HubRad is "
            f"{length:.4g} m: the blade is modelled at BeamDyn's length"
        )
    damping, how = _bd_damping(bd, ed)
    notes.append(how)
    if ed is not None:
        notes.append(_compare(ed, bd, length))
    return _BladeTable(
        bd.span, bd.mass, bd.structure, damping, "∫ M11 (BeamDyn)", notes, warnings, mu=bd.mu
    )


def _bd_damping(bd: beamdyn.Blade, ed: Deck | None) -> tuple[float | None, str]:
    """The blade's damping ratio and how it was found: with BeamDyn's stiffness-proportional
    μ none (each mode is damped ζ = π·μ·f at its own frequency, :func:`_mu`; a mode without
    one takes the blade's default, :func:`wtvib.subsystems.blade.default_damping`); without
    μ, ElastoDyn's BldFlDmp, else 1 %."""
    if bd.mu is None:
        if ed is not None:
            return main_damping(ed, "BldFlDmp(1)"), (
                "Blade damping: BeamDyn has none (damp_type 0); ElastoDyn's BldFlDmp(1) taken."
            )
        return 0.01, "Blade damping: BeamDyn has none (damp_type 0); 1 % of critical assumed."
    return None, (
        f"Blade damping from BeamDyn's stiffness-proportional μ (flapwise {bd.mu[0]:.4g} s, "
        f"edgewise {bd.mu[1]:.4g} s): each blade mode ζ = π·μ·f at its own frequency."
    )


def _mu(bl: Any) -> dict[str, Any]:
    """BeamDyn's damping as it is, stiffness-proportional (ζ = π·μ·f on every mode)."""
    if bl.mu is None:
        return {}
    return {"stiffness_damping_s": {"bending_1": bl.mu[0], "bending_2": bl.mu[1]}}


def _compare(ed: Deck, bd: beamdyn.Blade, length: float) -> str:
    """How ElastoDyn's (unused) blade file differs from the BeamDyn blade used."""
    span = ed.fractions("BlFract") * length
    ed_mass = float(np.trapezoid(ed.column("BlFract", "BMassDen"), span))
    out = []
    for key, column in (("FlpStff", "ei_flap_nm2"), ("EdgStff", "ei_edge_nm2")):
        theirs = np.interp(span, bd.span, bd.structure[column])
        diff = np.abs(ed.column("BlFract", key) / theirs - 1)
        out.append(
            f"{key} within {100 * float(np.max(diff)):.2g} % "
            f"(mean {100 * float(np.mean(diff)):.2g} %)"
        )
    return (
        f"ElastoDyn's blade file {ed.path.name} is unused with BeamDyn (CompElast = 2); "
        f"against the BeamDyn blade: mass {ed_mass:,.0f} vs {bd.mass_kg:,.0f} kg, "
        + ", ".join(out)
        + "."
    )


def _monopile(
    main: Deck, fst: Deck | None, below: tuple[str, bool] | None
) -> Monopile | str | None:
    """The deck set's SubDyn monopile; a sentence where its substructure is something
    else; None where the tower stands on no SubDyn substructure."""
    if below is None or below[1] or fst is None or "SubFile" not in fst.values:
        return None
    if fst.num("CompSub", default=0) != 1:
        return None
    return monopile(fst, main.num("TowerBsHt", default=0.0))


def _on_pile(
    pile: Monopile,
    fst: Deck | None,
    ed_base: float,
    heights: np.ndarray,
    mass: np.ndarray,
    ei_fa: np.ndarray,
    ei_ss: np.ndarray,
    torsion: tuple[np.ndarray, np.ndarray, str] | None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, Any, dict[str, Any]]:
    """The ElastoDyn tower (``heights`` above TowerBsHt) on its pile: one table from the
    reaction joint up (the pile's stations below TowerBsHt, its top section carried up to
    a step just below it), the pile's point masses and foundation, the water moving with
    it (HydroDyn), heights above the reaction joint."""
    keep = pile.z < ed_base - STEP_M / 2
    z = np.append(pile.z[keep], ed_base - STEP_M)
    top = int(np.flatnonzero(keep)[-1]) if keep.any() else 0

    def joined(below: np.ndarray, above: np.ndarray) -> np.ndarray:
        return np.concatenate([below[keep], [below[top]], above])

    out_heights = np.concatenate([z - pile.base, heights + ed_base - pile.base])
    out_torsion = (
        None
        if torsion is None
        else (joined(pile.gj, torsion[0]), joined(pile.polar, torsion[1]), torsion[2])
    )
    foundation = dict(pile.foundation)
    note = foundation.pop("_note", None)
    if note:
        pile.notes.append(note)
    block: dict[str, Any] = {"foundation": foundation}
    masses = [
        {"height_m": float(zm - pile.base), "mass_kg": m}
        for zm, m in pile.point_masses
        if pile.base <= zm <= ed_base + 1e-6
    ]
    if masses:
        block["point_masses"] = masses
    if fst is not None:
        wet = water(fst, pile)
        if isinstance(wet, str):
            pile.notes.append(wet + ".")
        else:
            pile.notes.append(wet.note)
            block["added_mass"] = {
                "height_m": _list(wet.z - pile.base),
                "mass_per_length_kg_m": _list(wet.mass),
                "source": wet.note,
            }
    return (
        out_heights,
        joined(pile.mass, mass),
        joined(pile.ei, ei_fa),
        joined(pile.ei, ei_ss),
        out_torsion,
        block,
    )


def _hub_inertia(main: Deck, hub_radius: float) -> dict[str, Any]:
    """The hub in the drive train: HubIner; where a deck gives 0 (OpenFAST's rigid test
    turbines), a disc of HubMass and HubRad, ½·m·r², said — a chain mass of no inertia
    would leave its shafts without a mass between them."""
    given = main.num("HubIner", default=0.0)
    if given > 0:
        return {"name": "hub", "inertia_kgm2": _value(given, "HubIner")}
    mass = main.num("HubMass", default=0.0)
    disc = 0.5 * mass * hub_radius**2
    if disc <= 0:
        rigid = not any(main.flag(k) for k in DOFS)
        raise SpecError(
            "the deck set is a rigid test turbine: every ElastoDyn DOF is off and the hub has "
            "no mass or inertia (HubIner, HubMass 0) — there is no structure to audit"
            if rigid
            else "HubIner is 0 and HubMass or HubRad too: the drive train's hub has no inertia",
            line=main.line("HubIner"),
            source=str(main.path),
        )
    return {
        "name": "hub",
        "inertia_kgm2": _value(
            disc, "HubIner = 0 in the deck: a disc of HubMass and HubRad, ½·m·r²", "representative"
        ),
    }


def _speed_block(speed: dict[str, Any] | None) -> dict[str, Any]:
    """The spec's speed block (six digits); a parked deck's placeholder, which the command
    line's range replaces."""
    if speed is None:
        return {"fixed_rpm": 0.0, "source": "parked: the command line gives the range"}

    def six(v: Any) -> Any:
        return [six(x) for x in v] if isinstance(v, list) else float(f"{v:.6g}")

    return {k: v if k in ("source", "parked") else six(v) for k, v in speed.items()}


def _yaw_block(
    main: Deck, servo: Deck | None, switches: "_Switches", deck_dofs: bool
) -> dict[str, Any]:
    """The spec's yaw block: none where the deck holds the yaw (its DOF off), the yaw spring
    the deck set gives; read as OpenFAST models the deck (``deck_dofs``), a yaw DOF with no
    spring is a free yaw (:data:`FREE_YAW`)."""
    if switches.yaw_held:
        return {}
    block = _yaw(main, servo)
    return {"yaw": {"drive": "free"}} if deck_dofs and not block else block


def _yaw(main: Deck, servo: Deck | None) -> dict[str, Any]:
    """Yaw spring from the deck (FAST v7) or the ServoDyn file the deck set names."""
    decks = [main] + ([servo] if servo is not None and servo is not main else [])
    for deck in decks:
        if "YawSpr" in deck.values and deck.num("YawSpr") > 0:
            src = f"YawSpr in {deck.path.name}"
            yaw: dict[str, Any] = {
                "drive": "active",
                "drive_stiffness_nm_rad": {
                    "value": deck.num("YawSpr"),
                    "provenance": "published",
                    "source": "deck",
                    "note": src,
                },
            }
            if deck.num("YawDamp", default=0.0) > 0:
                yaw["drive_damping_nms_rad"] = deck.num("YawDamp")
            if deck.num("YawManRat", default=0.0) > 0:
                yaw["yaw_rate_deg_s"] = {
                    "value": deck.num("YawManRat"),
                    "provenance": "published",
                    "source": "deck",
                    "note": f"YawManRat in {deck.path.name}",
                }
            return {"yaw": yaw}
    return {}


def main_damping(deck: Deck, key: str) -> float:
    """A damping ratio from a percent-of-critical input (default 1 %), to the deck's own
    digits (5.9 % is 0.059, not 0.059000000000000004 in a converted spec)."""
    return round(deck.num(key, key.replace("(", "").replace(")", ""), default=1.0) / 100.0, 12)


def _list(a: np.ndarray) -> list[float]:
    return [float(f"{v:.10g}") for v in a]


def _value(
    value: float, note: str, provenance: str = "published", digits: int | None = None
) -> dict[str, Any]:
    """A spec quantity read from the deck (``note``: the keys it comes from)."""
    # a value computed from the deck's numbers (derived) keeps the deck's precision,
    # six digits: TowerHt + Twr2Shft + OverHang·sin(ShftTilt) is 90.0, not 90.00000339
    if digits is None:
        digits = 6 if provenance == "derived" else 10
    return {
        "value": float(f"{value:.{digits}g}"),
        "provenance": provenance,
        "source": "deck",
        "note": note,
    }
