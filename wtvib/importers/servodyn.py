"""How an OpenFAST deck set runs its rotor: the operating range, power regulation and
generator its ServoDyn inputs (and the controller file they name) describe.

A torque-controlled generator (DLL, simple variable speed) is the drive train's free end
(the controller's torque is not modelled); an induction generator on the grid is coupled.

* Bladed-style DLL (``VSContrl`` = 5, ROSCO): ``DLL_InFile``'s VS_MinOMSpd (the minimum
  generator speed, rad/s) and VS_RefSpd (rated; else PC_RefSpd) over WE_GearboxRatio (else
  GBRatio); VS_TSRopt, VS_RtPwr, PC_FinePit for the aerodynamics — ROSCO input definitions.
* Simple variable speed (``VSContrl`` = 1): the rated rotor speed VS_RtGnSp/GBRatio and the
  rated power VS_RtTq·VS_RtGnSp (at the generator efficiency); the law (VS_Rgn2K·ω² below
  rated) names no lowest speed: the deck's initial RotSpeed is taken as it, said.
* Fixed speed (``VSContrl`` = 0): the induction generator's synchronous speed — SIG_SySp
  (``GenModel`` 1) or 120·TEC_Freq/TEC_NPol (``GenModel`` 2) — plus the rated slip, over
  GBRatio; the generator on the grid (Hau Fig. 7.11: a damper to ground).
* Pitch control (``PCMode`` 3–5) regulates power above rated by pitch; without it (0) the
  blades stay at their initial pitch and the rotor is stall-regulated.

A deck set whose ServoDyn does not describe an operation — none (``CompServo`` = 0), a
user-defined controller, a generator never switched on (``TimGenOn`` past ``TMax``: the
linearisation and trim decks of OpenFAST's regression tests), OpenFAST's 9999.9 "unused"
values, a controller file it names but does not hold — is audited at its initial
``RotSpeed``, with a warning; at 0 rpm (a parked deck) the range must be given.

FAST User's Guide (NREL/EL-500-38230); OpenFAST ServoDyn input-file documentation.
"""

import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import SpecError
from ..spec import read_text
from .deck import _NUMBER, Deck, _file, _fortran, beside, parse, present

#: OpenFAST's decks mark an input they do not use with 9999.9 (or 9998/9999).
UNUSED = 9998.0


@dataclass
class Operation:
    """The rotor's operation as the deck set gives it: the spec's ``rotor.speed`` block
    (None: parked and not given), where it came from, warnings; the ``aerodynamics.control``
    entries; the drive train's generator entries; the controller input file read."""

    speed: dict[str, Any] | None
    note: str
    warnings: list[str] = field(default_factory=list)
    control: dict[str, Any] = field(default_factory=dict)
    generator: dict[str, Any] = field(default_factory=dict)
    controller_file: str | None = None
    #: the speed is the deck's initial RotSpeed, taken as fixed (no operating range given)
    initial: bool = False


def operation(main: Deck, servo: Deck | None, fst: Deck | None = None) -> Operation:
    """The operation a deck set describes (see the module's notes)."""
    pitch = main.num("BlPitch(1)", "BlPitch1", default=0.0)
    fixed_pitch = {"regulation": "stall", "fine_pitch_deg": pitch}
    if servo is None or "VSContrl" not in servo.values:
        named = fst is not None and "ServoFile" in fst.values and fst.num("CompServo", default=1)
        why = (
            f"its ServoDyn file {fst.text('ServoFile')!r} is not in the deck set"
            if named and fst is not None
            else "the deck set has no ServoDyn (CompServo = 0)"
        )
        return _initial(main, why, fixed_pitch)
    mode = switch(servo, "VSContrl")
    pc = switch(servo, "PCMode", default=0) if "PCMode" in servo.values else 0
    regulation = "pitch" if pc != 0 else "stall"  # FAST v7: 1, 2; OpenFAST: 3, 4, 5
    if mode == 5:
        return _dll(main, servo, regulation, pitch)
    if mode == 1:
        return _simple_variable_speed(main, servo, regulation, pitch)
    if mode == 0:
        return _constant_speed(main, servo, fst, regulation, pitch)
    return _initial(
        main, f"its controller is user-defined (VSContrl = {mode}), which wtvib cannot read",
        {"regulation": regulation, "fine_pitch_deg": pitch},
    )  # fmt: skip


def _initial(main: Deck, why: str, control: dict[str, Any]) -> Operation:
    """The deck's initial rotor speed as a fixed operating speed, said; a parked deck (0
    rpm) has none."""
    rot = main.num("RotSpeed")
    if rot <= 0:
        return Operation(
            {"parked": True, "source": f"RotSpeed = {rot:g} rpm in {main.path.name}"},
            f"The deck set gives no operating speed ({why}) and is parked (RotSpeed = "
            f"{rot:g} rpm): a standstill audit of its modes, no rotor excitation judged.",
            [
                f"rotor.speed: the deck set is parked (RotSpeed {rot:g} rpm, {why}) — audited "
                "at standstill, its modes and their damping only; give the operating range "
                "with --rpm MIN:MAX to judge it in operation"
            ],
            control=control,
        )
    return Operation(
        {"fixed_rpm": rot, "source": f"the initial RotSpeed of {main.path.name}"},
        f"The deck set gives no operating range ({why}): its initial RotSpeed = {rot:g} rpm "
        "is taken as a fixed operating speed.",
        [
            f"rotor.speed: no operating range in the deck set ({why}) — audited at the initial "
            f"RotSpeed {rot:g} rpm as a fixed-speed turbine; give the range with --rpm MIN:MAX "
            "(and --rated)"
        ],
        control=control,
        initial=True,
    )


def _dll(main: Deck, servo: Deck, regulation: str, pitch: float) -> Operation:
    """ROSCO / Bladed-style controller: its input file's speeds, TSR, power, fine pitch."""
    gb = main.num("GBRatio", default=1.0)
    # the deck's pitch control (PCMode) holds whether or not its controller file is here
    fixed = {"regulation": regulation, "fine_pitch_deg": pitch}
    if "DLL_InFile" not in servo.values:
        return _initial(main, "its DLL controller names no input file (DLL_InFile)", fixed)
    name = servo.text("DLL_InFile")
    dll = beside(servo.path, name)
    if not present(dll):
        return _initial(
            main,
            f"its controller's input file {name!r} (DLL_InFile) is not in the deck set",
            fixed,
        )
    dll = _file(servo, "DLL_InFile")
    ctrl = discon(dll)
    control: dict[str, Any] = {"regulation": regulation}
    if "VS_TSRopt" in ctrl:
        control["tip_speed_ratio"] = ctrl["VS_TSRopt"][0]
    if "VS_RtPwr" in ctrl:
        control["rated_power_kw"] = ctrl["VS_RtPwr"][0] / 1e3
    if "PC_FinePit" in ctrl:
        control["fine_pitch_deg"] = math.degrees(ctrl["PC_FinePit"][0])
    _efficiency(servo, control)
    ratio = ctrl.get("WE_GearboxRatio", (gb, 0))[0]
    low = ctrl.get("VS_MinOMSpd")
    rated = ctrl.get("VS_RefSpd", ctrl.get("PC_RefSpd"))
    found = Operation(None, "", control=control, controller_file=dll.name)
    if low is None or rated is None:
        dtu = dtu_constants(dll)
        if 2 in dtu and 3 in dtu:  # the DTU Wind Energy controller's init block
            return _dtu(found, dtu, dll, servo)
        fallback = _initial(main, f"{dll.name} gives no VS_MinOMSpd and VS_RefSpd", control)
        fallback.controller_file = dll.name
        return fallback
    if not (0 < low[0] < rated[0] and ratio > 0):
        raise SpecError(
            f"VS_MinOMSpd {low[0]:g} rad/s must lie between 0 and the rated generator "
            f"speed {rated[0]:g} rad/s (and the gearbox ratio {ratio:g} above 0)",
            line=low[1],
            source=str(dll),
        )
    rpm_of = 30 / math.pi
    found.speed = {
        "min_rpm": low[0] / ratio * rpm_of,
        "max_rpm": rated[0] / ratio * rpm_of,
        "source": f"{dll.name} (VS_MinOMSpd, VS_RefSpd)",
    }
    found.note = (
        f"Operating range {found.speed['min_rpm']:.3g}–{found.speed['max_rpm']:.3g} rpm from "
        f"{dll.name} (VS_MinOMSpd {low[0]:g}, VS_RefSpd {rated[0]:g} rad/s, gearbox "
        f"{ratio:g}), named by {servo.path.name}."
    )
    _exclusion(found, ctrl, dll.name)
    return found


def _dtu(found: Operation, dtu: dict[int, tuple[float, int]], dll: Path, servo: Deck) -> Operation:
    """The operating range of the DTU Wind Energy controller's input (the IEA-15's
    ``Monopile_wDTUcontroller`` deck: ``constant 2`` and ``3``, the minimum and rated rotor
    speed [rad/s], on the low-speed shaft; ``constant 1`` the rated power [kW]) — as a HAWC2
    model's type2_dll gives them (importers.hawc2)."""
    (low, line), (high, _) = dtu[2], dtu[3]
    low_rpm, high_rpm = dtu_speeds(low, high, line, str(dll))
    if 1 in dtu and dtu[1][0] > 0:
        found.control["rated_power_kw"] = dtu[1][0]
    found.speed = {
        "min_rpm": low_rpm,
        "max_rpm": high_rpm,
        "source": f"{dll.name} (the DTU Wind Energy controller's constants 2 and 3)",
    }
    found.note = (
        f"Operating range {low_rpm:.4g}–{high_rpm:.4g} rpm from {dll.name}, the DTU "
        f"Wind Energy controller's input named by {servo.path.name} (constants 2 and 3: "
        f"{low:g} and {high:g} rad/s, the rotor's minimum and rated speed)."
    )
    return found


def dtu_speeds(low: float, high: float, line: int | None, source: str) -> tuple[float, float]:
    """The DTU Wind Energy controller's constants 2 and 3 — the rotor's minimum and rated
    speed [rad/s], on the low-speed shaft — in rpm, read from an OpenFAST deck's controller
    input or a HAWC2 model's type2_dll alike; one line naming constant 2's line where they
    are not 0 < minimum < rated."""
    if not 0 < low < high:
        raise SpecError(
            f"constant 2 (minimum rotor speed {low:g} rad/s) must lie between 0 and constant 3 "
            f"(rated rotor speed {high:g} rad/s)",
            line=line,
            source=source,
        )
    return low * 30 / math.pi, high * 30 / math.pi


#: A DTU Wind Energy controller input's ``constant N value`` line.
_CONSTANT = re.compile(r"^\s*constant\s+(\d+)\s+(\S+?)\s*(?:;|$)", re.IGNORECASE)


def dtu_constants(path: Path) -> dict[int, tuple[float, int]]:
    """The ``constant N value ;`` lines of a DTU Wind Energy controller's input (its HAWC2
    ``init`` block, or the file OpenFAST's DISCON interface hands it): value and line; one
    whose value is not a finite number a SpecError naming file and line."""
    out: dict[int, tuple[float, int]] = {}
    for number, line in enumerate(read_text(path, ansi=True).splitlines(), start=1):
        found = _CONSTANT.match(line)
        if found is None:
            continue
        key, text = int(found.group(1)), found.group(2)
        value = float(_fortran(text)) if _NUMBER.match(text) else math.nan
        if not math.isfinite(value):  # 1e999 matches a number and overflows
            raise SpecError(
                f"constant {key} must be a finite number (got {text!r})",
                line=number,
                source=str(path),
            )
        out.setdefault(key, (value, number))
    return out


def _exclusion(found: Operation, ctrl: dict[str, tuple[float, int]], name: str) -> None:
    """ROSCO's tower-resonance avoidance (TRA_ExclSpeed ± TRA_ExclBand/2, rotor speed in
    rad/s): a band the torque controller passes quickly — the spec's quick-pass band."""
    centre, band = ctrl.get("TRA_ExclSpeed", (0.0, 0))[0], ctrl.get("TRA_ExclBand", (0.0, 0))[0]
    speed = found.speed
    if speed is None or centre <= 0 or band <= 0:
        return
    rpm_of = 30 / math.pi
    low = max((centre - band / 2) * rpm_of, speed["min_rpm"])
    high = min((centre + band / 2) * rpm_of, speed["max_rpm"])
    if low < high:
        speed["quick_pass_rpm"] = [[low, high]]
        found.note += (
            f" Tower-resonance avoidance (TRA_ExclSpeed {centre:g}, TRA_ExclBand {band:g} "
            f"rad/s in {name}): {low:.3g}–{high:.3g} rpm passed quickly, not dwelt in."
        )


def _simple_variable_speed(main: Deck, servo: Deck, regulation: str, pitch: float) -> Operation:
    """ServoDyn's simple variable-speed law (VS_RtGnSp, VS_RtTq, VS_Rgn2K, VS_SlPc)."""
    gb = main.num("GBRatio", default=1.0)
    rot = main.num("RotSpeed")
    gen_rpm = servo.num("VS_RtGnSp", default=0.0)
    torque = servo.num("VS_RtTq", default=0.0)
    rated = gen_rpm / gb
    control: dict[str, Any] = {"regulation": regulation, "fine_pitch_deg": pitch}
    _efficiency(servo, control)
    if not (0 < gen_rpm < UNUSED and 0 < torque < 1e12) or rated < 0.5 * rot:
        return _initial(
            main,
            f"its simple variable-speed inputs (VS_RtGnSp {gen_rpm:g} rpm over GBRatio {gb:g} "
            f"= {rated:.4g} rpm rated, VS_RtTq {torque:g} N·m) do not describe this rotor's "
            f"operation at RotSpeed {rot:g} rpm — a trimming controller",
            {"regulation": "stall", "fine_pitch_deg": pitch},
        )
    power_kw = torque * gen_rpm * math.pi / 30 * control.get("generator_efficiency", 1.0) / 1e3
    control["rated_power_kw"] = power_kw
    law = _torque_law(servo, gb, gen_rpm, torque)
    if law is not None:
        control["generator_torque"] = law
    source = f"{servo.path.name} (VS_RtGnSp, VS_RtTq; simple variable speed)"
    if 0 < rot < 0.999 * rated:
        speed: dict[str, Any] = {"min_rpm": rot, "max_rpm": rated, "source": source}
        warnings = [
            f"rotor.speed: ServoDyn's simple variable-speed law names no lowest speed — the "
            f"range is audited from the initial RotSpeed {rot:g} rpm to the rated "
            f"{rated:.4g} rpm; give the range with --rpm MIN:MAX"
        ]
    else:
        speed = {"fixed_rpm": rated, "source": source}
        warnings = [
            f"rotor.speed: ServoDyn's simple variable-speed law names no lowest speed — "
            f"audited at its rated {rated:.4g} rpm only; give the range with --rpm MIN:MAX"
        ]
    eff = control.get("generator_efficiency")
    regulated = (
        "pitch-regulated above rated."
        if regulation == "pitch"
        else f"no pitch control: the blades held at {pitch:g}° (stall regulation)."
    )
    note = (
        f"Simple variable-speed control ({servo.path.name}): rated {rated:.4g} rpm "
        f"(VS_RtGnSp {gen_rpm:g} rpm over GBRatio {gb:g}), rated power {power_kw:,.0f} kW "
        f"(VS_RtTq {torque:g} N·m at VS_RtGnSp"
        + (f", GenEff {100 * eff:g} %" if eff is not None else "")
        + f"); {regulated}"
    )
    return Operation(speed, note, warnings, control)


#: Rotor speeds at which the simple variable-speed law is tabulated below its region 2½.
LAW_POINTS = 200


def _torque_law(servo: Deck, gb: float, gen_rpm: float, torque: float) -> dict[str, Any] | None:
    """ServoDyn's simple variable-speed law (its ``CalculateTorque``) as torque on the rotor's
    shaft against rotor speed: k·ω² in region 2 (VS_Rgn2K, N·m/rpm² on the generator's
    side), a straight line from the synchronous speed VS_RtGnSp/(1 + VS_SlPc/100) to rated
    in region 2½, VS_RtTq above; None where VS_Rgn2K or VS_SlPc is not a law (0, unused)."""
    k = servo.num("VS_Rgn2K", default=0.0)
    slip = servo.num("VS_SlPc", default=0.0)
    if not (0 < k < UNUSED and 0 < slip < UNUSED):
        return None
    sync = gen_rpm / (1 + 0.01 * slip)
    slope = torque / (gen_rpm - sync)  # region 2½ [N·m/rpm]
    disc = slope * (slope - 4 * k * sync)
    if disc < 0:  # region 2's curve never meets the line: ServoDyn's own check
        return None
    trans = (slope - math.sqrt(disc)) / (2 * k)  # where region 2 meets region 2½ [rpm]
    if not 0 < trans < gen_rpm:  # k·ω² above VS_RtTq at rated: OpenFAST refuses the law too
        return None
    speeds = [trans * i / LAW_POINTS for i in range(LAW_POINTS + 1)] + [gen_rpm, 1.5 * gen_rpm]
    torques = [k * w * w for w in speeds[:-2]] + [torque, torque]
    return {
        "rpm": [w / gb for w in speeds],
        "torque_nm": [t * gb for t in torques],
        "source": f"{servo.path.name} (VS_Rgn2K, VS_SlPc, VS_RtGnSp, VS_RtTq; simple variable "
        "speed)",
    }


def _constant_speed(
    main: Deck, servo: Deck, fst: Deck | None, regulation: str, pitch: float
) -> Operation:
    """A generator without speed control: the induction generator's speed on the grid."""
    gb = main.num("GBRatio", default=1.0)
    control: dict[str, Any] = {"regulation": regulation, "fine_pitch_deg": pitch}
    _efficiency(servo, control)
    t_max = fst.num("TMax", default=math.inf) if fst is not None else math.inf
    if servo.flag("GenTiStr") and servo.num("TimGenOn", default=0.0) >= min(t_max, UNUSED):
        return _initial(
            main,
            f"its generator is never switched on (TimGenOn {servo.num('TimGenOn'):g} s, past "
            "the run): a free-spinning rotor, as OpenFAST's linearisation decks set it up",
            control,
        )
    model = switch(servo, "GenModel", default=1)
    if model == 1:
        sync, slip = servo.num("SIG_SySp", default=0.0), servo.num("SIG_SlPc", default=0.0)
        torque = servo.num("SIG_RtTq", default=0.0)
        poles = None
    elif model == 2:
        freq, n_pol = servo.num("TEC_Freq", default=0.0), servo.num("TEC_NPol", default=0.0)
        sync = 120 * freq / n_pol if 0 < n_pol < UNUSED and 0 < freq < UNUSED else 0.0
        slip, torque, poles = 0.0, 0.0, n_pol
    else:
        return _initial(main, "its generator model is user-defined (GenModel 3)", control)
    if not (0 < sync < UNUSED and 0 <= slip < 50):
        return _initial(
            main,
            f"its induction generator's inputs (GenModel {model}) are OpenFAST's unused values",
            control,
        )
    fixed = sync * (1 + slip / 100) / gb
    source = f"the induction generator in {servo.path.name} (synchronous speed + slip)"
    note = (
        f"Fixed operating speed {fixed:.4g} rpm: the induction generator's synchronous speed "
        f"{sync:g} rpm plus rated slip {slip:g} % over the gearbox ratio {gb:g} "
        f"({servo.path.name})."
    )
    out = Operation({"fixed_rpm": fixed, "source": source}, note, control=control)
    out.generator = {"generator": "induction", "grid_coupling": "direct"}
    if model == 1 and 0 < torque < 1e12 and slip > 0:
        power_kw = torque * sync * math.pi / 30 * (1 + slip / 100) / 1e3
        out.generator["generator_model"] = {
            "rated_power_kw": power_kw * control.get("generator_efficiency", 1.0),
            "pole_pairs": _pole_pairs(sync),
            "grid_frequency_hz": _grid_frequency(sync),
            "rated_slip": slip / 100,
        }
    elif poles is not None:
        out.note += f" Thevenin generator, {poles:g} poles."
    return out


def _pole_pairs(sync_rpm: float) -> int:
    """Pole pairs of an induction generator of this synchronous speed on a 50 or 60 Hz grid
    (n_sync = 60·f/p): the grid frequency that gives a whole number of pairs."""
    return max(1, round(60 * _grid_frequency(sync_rpm) / sync_rpm))


def _grid_frequency(sync_rpm: float) -> float:
    return min((50.0, 60.0), key=lambda f: abs(60 * f / sync_rpm - round(60 * f / sync_rpm)))


def _efficiency(servo: Deck, control: dict[str, Any]) -> None:
    if "GenEff" in servo.values:
        eff = servo.num("GenEff")
        if not 0 < eff <= 100:
            raise SpecError(
                f"GenEff must lie in (0, 100] % (got {eff:g})",
                line=servo.values["GenEff"][1],
                source=str(servo.path),
            )
        control["generator_efficiency"] = eff / 100


#: The controller inputs read from a ROSCO / Bladed-style input file (ROSCO's names).
DISCON_KEYS = (
    "VS_MinOMSpd",
    "VS_RefSpd",
    "PC_RefSpd",
    "WE_GearboxRatio",
    "VS_TSRopt",
    "VS_RtPwr",
    "PC_FinePit",
    "TRA_ExclSpeed",
    "TRA_ExclBand",
)


def discon(path: Path) -> dict[str, tuple[float, int]]:
    """The operating-range inputs of a ROSCO / Bladed-style controller file (``value ! Name``
    lines): value and line. One of them that is not a finite number is a SpecError naming
    file and line."""
    out: dict[str, tuple[float, int]] = {}
    for number, line in enumerate(read_text(path, ansi=True).splitlines(), start=1):
        value, _, rest = line.partition("!")
        names, parts = rest.split(), value.split()
        if len(parts) != 1 or not names or names[0] not in DISCON_KEYS:
            continue
        if not _NUMBER.match(parts[0]):
            raise SpecError(
                f"{names[0]} must be a finite number (got {parts[0]!r})",
                line=number,
                source=str(path),
            )
        out.setdefault(names[0], (float(parts[0].replace("D", "E")), number))
    return out


#: The winds a linearisation deck's point may have [m/s] (InflowWind's HWindSpeed): a
#: breath to above any turbine's cut-out — a wind turbine's steady operating point.
MIN_POINT_WIND, MAX_POINT_WIND = 0.1, 50.0


def linearisation_point(main: Deck, fst: Deck | None) -> tuple[dict[str, Any], str] | None:
    """A linearisation deck set's own operating point, where it gives no operating range:
    ``Linearize`` on in the .fst and InflowWind's steady wind (``WindType`` 1,
    ``HWindSpeed``) — the one point OpenFAST linearises, at the initial RotSpeed and
    BlPitch(1). The spec's ``operating_points`` of it and what it came from; None where the
    deck set is not such a one (no InflowWind in the set, another wind type)."""
    if fst is None or not fst.flag("Linearize") or "InflowFile" not in fst.values:
        return None
    if fst.num("CompInflow", default=0) != 1:
        return None
    path = beside(fst.path, fst.text("InflowFile"))
    if not present(path):
        return None
    inflow = parse(path)
    if "WindType" not in inflow.values or switch(inflow, "WindType") != 1:
        return None
    wind = inflow.num("HWindSpeed")
    if not MIN_POINT_WIND <= wind <= MAX_POINT_WIND:
        raise SpecError(
            f"HWindSpeed {wind:g} m/s: a steady wind of {MIN_POINT_WIND:g} … "
            f"{MAX_POINT_WIND:g} m/s",
            line=inflow.line("HWindSpeed"),
            source=str(path),
        )
    rpm = main.num("RotSpeed")
    pitch = main.num("BlPitch(1)", "BlPitch1", default=0.0)
    source = (
        f"the linearisation deck's own operating point: {path.name}'s HWindSpeed, "
        f"{main.path.name}'s RotSpeed and BlPitch(1)"
    )
    point = {"wind_m_s": [wind], "rpm": [rpm], "pitch_deg": [pitch], "source": source}
    return point, (
        f"the deck set is a linearisation set (Linearize): its aerodynamics judged at its own "
        f"operating point, {wind:g} m/s at {rpm:g} rpm and {pitch:g}° pitch, as OpenFAST "
        "linearises it"
    )


def switch(deck: Deck, key: str, default: int | None = None) -> int:
    """An integer switch of a deck (``VSContrl``, ``GenModel``): 2.7 is an error, not 2."""
    value = deck.num(key, default=None if default is None else float(default))
    if value != int(value):
        line = deck.values[key][1] if key in deck.values else None
        raise SpecError(
            f"{key} is a switch and must be a whole number (got {value:g})",
            line=line,
            source=str(deck.path),
        )
    return int(value)
