"""How the deck sets in ``decks.tar.gz`` were made (see SOURCES.md): r-test's
``5MW_Land_Linear_Aero_CalcSteady`` (the onshore NREL 5-MW, ElastoDyn, AeroDyn, ServoDyn's
simple variable-speed law) trimmed by OpenFAST's CalcSteady at other winds, its inputs
brought to OpenFAST 5.0's format.

    python tests/data/openfast_sweep/make_decks.py R_TEST/glue-codes/openfast OUT WIND [WIND …]
    python tests/data/openfast_sweep/make_decks.py --frozen R_TEST/glue-codes/openfast OUT …

``--frozen``: the same deck sets with AeroDyn's wake frozen for the linearisation
(``DBEMT_Mod`` −1, "Frozen Wake for linearization"), named ``ED_<wind>_frozen``: wtvib reads
that as its frozen induction — the induction it holds for its own specs and windIO files —
where ``DBEMT_Mod`` 0 is its induction in equilibrium with the motion.

What changes from the r-test deck, and why:

* the wind (InflowWind ``HWindSpeed``), the initial rotor speed and pitch — the NREL 5-MW's
  steady states (Jonkman et al. 2009, NREL/TP-500-38060, Fig. 9-1): the rated 12.1 rpm and
  the pitch trimmed above rated (``TrimCase`` 3, ``TrimGain`` 0.001 rad/(rad/s)); the
  generator torque trimmed below and at rated (``TrimCase`` 2, 100 N·m/(rad/s));
* the generator switched on (``TimGenOn`` 0: r-test's 9999.9 never does) with the NREL
  5-MW's simple variable-speed law (``VS_RtGnSp`` 1161.963 rpm; r-test's 12.1 held no
  region 3);
* the aerodynamics as wtvib's model holds them, so that the comparison is of one model:
  quasi-steady aerofoils (``UA_Mod`` 0), the induction in equilibrium with the motion
  (``DBEMT_Mod`` 0: BEMT without dynamic wake), no tower influence (``TwrPotent`` 0,
  ``TwrShadow`` 0, ``TwrAero`` False), and the inflow's component across the rotor thrown
  away (``Skew_Mod`` −1, AeroDyn's setting "for linearization", its input documentation:
  "makes sure the wind speed is always normal to the rotor to limit periodic variation of
  the wind speed if the rotor is not perpendicular to the wind (e.g. tower top tilting)").
  r-test's ``Skew_Mod`` 1 answers the tower top's sideways velocity with Pitt and Peters'
  skewed-wake redistribution of the induction at once, a yaw-wise cyclic load that damps
  the first side-side tower mode by 7 % of its damping more at 8 m/s (0.00587 against
  0.00547; the sets made with it until 2026-12-07); wtvib has no skewed wake;
* 12 linearisations over a revolution (``NLinTimes``), the initial flapwise tip deflection
  near the steady one (``OoPDefl``) to shorten the trim, ``DT`` 0.01 s;
* OpenFAST 5.0's new inputs, at the values that keep the r-test model
  (docs/source/user/api_change.rst, "Added in OpenFAST 5.0.0"): ``ModCoupling`` 2,
  ``NRotors`` 1, ``CompSoil`` 0, ``MirrorRotor`` F, ``SoilFile`` unused; ElastoDyn's
  ``PitchDOF`` False, ``PtfmRefxt``/``yt`` 0, ``PBrIner``/``BlPIner`` 0 (no pitch DOF),
  ``HubIner_Teeter`` 0, the yaw friction's new terms 0; ServoDyn's ``PitNeut`` at the
  pitch (without pitch control OpenFAST 5 holds the blades there), ``PitSpr``/``PitDamp``
  0; AeroDyn's ``Buoyancy`` line dropped and the tower table's ``TwrCp``, ``TwrCa`` 1.
"""

import re
import shutil
import sys
from pathlib import Path

CASE = "5MW_Land_Linear_Aero_CalcSteady"
#: wind [m/s] → (rotor speed [rpm], pitch [deg], trim case): Jonkman et al. 2009, Fig. 9-1
POINTS = {
    8.0: (9.16, 0.0, 2),
    10.0: (11.43, 0.0, 2),
    11.0: (11.85, 0.0, 2),  # region 2½ of the generator law: 11.73 … 11.98 rpm
    11.4: (12.1, 0.0, 2),
    16.0: (12.1, 12.1, 3),
    20.0: (12.1, 17.5, 3),
}


def setv(text: str, key: str, value: str) -> str:
    """The line whose second word is ``key`` with its value replaced."""
    pat = re.compile(r"^(\s*)(\S+)(\s+" + re.escape(key) + r"(?=\s))", re.M)
    new, n = pat.subn(lambda m: f"{m.group(1)}{value}{m.group(3)}", text, count=1)
    if n != 1:
        raise KeyError(key)
    return new


def _key(line: str) -> str | None:
    parts = line.split()
    return parts[1] if len(parts) > 1 else None


def _insert(
    lines: list[str], new: list[str], after: str | None = None, before: str | None = None
) -> list[str]:
    for i, line in enumerate(lines):
        if after is not None and _key(line) == after:
            return lines[: i + 1] + new + lines[i + 1 :]
        if before is not None and _key(line) == before:
            return lines[:i] + new + lines[i:]
    raise KeyError(after or before)


def _fst5(text: str) -> str:
    lines = text.splitlines()
    lines = _insert(
        lines, ["          2   ModCoupling     - Module coupling method (switch)"], after="DT"
    )
    lines = _insert(
        lines,
        ["          1   NRotors         - Number of rotors in turbine (-)"],
        before="CompElast",
    )
    lines = _insert(
        lines,
        ["          0   CompSoil        - Compute soil-structural dynamics (switch)"],
        after="CompIce",
    )
    lines = _insert(
        lines,
        ["          F   MirrorRotor     - Flag to reverse rotor rotation direction"],
        after="MHK",
    )
    lines = _insert(lines, ['"unused"      SoilFile        - SoilDyn input file'], after="IceFile")
    return "\n".join(lines) + "\n"


def _elastodyn5(text: str) -> str:
    lines = text.splitlines()
    lines = _insert(lines, ["False         PitchDOF    - Blade pitch DOF (flag)"], after="EdgeDOF")
    lines = _insert(
        lines,
        ["          0   PtfmRefxt   - (m)", "          0   PtfmRefyt   - (m)"],
        before="PtfmRefzt",
    )
    last = max(i for i, x in enumerate(lines) if (_key(x) or "").startswith("TipMass("))
    lines = (
        lines[: last + 1]
        + [f"          0   {k}({b})  - (kg m^2)" for k in ("PBrIner", "BlPIner") for b in (1, 2, 3)]
        + lines[last + 1 :]
    )
    lines = _insert(lines, ["          0   HubIner_Teeter - (kg m^2)"], after="HubIner")
    lines = _insert(
        lines,
        ["          0   M_FCSmax    - (N-m)", "          0   M_MCSmax    - (N-m)"],
        after="M_CSmax",
    )
    lines = _insert(
        lines,
        ["          0   M_FCD       - (N-m)", "          0   M_MCD       - (N-m)"],
        after="M_CD",
    )
    lines = _insert(
        lines,
        ["          0   sig_v2      - (N-m/(rad/s)^2)", "          0   OmgCut      - (rad/s)"],
        after="sig_v",
    )
    return "\n".join(lines) + "\n"


def _aerodyn5(text: str) -> str:
    lines = [x for x in text.splitlines() if _key(x) != "Buoyancy"]
    i = next(i for i, x in enumerate(lines) if _key(x) == "NumTwrNds")
    n = int(lines[i].split()[0])
    lines[i + 1] += "  TwrCp  TwrCa"
    lines[i + 2] += "  (-)  (-)"
    for j in range(i + 3, i + 3 + n):
        lines[j] += "  1.0000000E+00  1.0000000E+00"
    return "\n".join(lines) + "\n"


def _servodyn5(text: str, pitch: float) -> str:
    lines = text.splitlines()
    new = [f"  {pitch:12g}   PitNeut({b})  - (deg)" for b in (1, 2, 3)]
    new += [f"          0   {k}({b})  -" for k in ("PitSpr", "PitDamp") for b in (1, 2, 3)]
    return "\n".join(_insert(lines, new, after="TPCOn")) + "\n"


def make(r_test: Path, out: Path, wind: float, frozen: bool = False) -> Path:
    """The deck set at ``wind`` [m/s] in ``out``/ED_<wind> (its ``../5MW_Baseline`` names
    r-test's files beside it); ``frozen``: the wake frozen, ``out``/ED_<wind>_frozen."""
    rpm, pitch, trim = POINTS[wind]
    src = r_test / CASE
    name = f"ED_{wind:g}" + ("_frozen" if frozen else "")
    d = out / name
    if d.exists():
        shutil.rmtree(d)
    d.mkdir(parents=True)
    fst = (src / f"{CASE}.fst").read_text()
    for key, value in (
        ("TMax", "900"), ("DT", "0.01"), ("TrimCase", str(trim)),
        ("TrimGain", "100" if trim == 2 else "0.001"), ("NLinTimes", "12"), ("WrVTK", "0"),
    ):  # fmt: skip
        fst = setv(fst, key, value)
    inflow = f"InflowWind_{wind:g}.dat"
    fst = fst.replace(
        '"../5MW_Baseline/NRELOffshrBsline5MW_InflowWind_Steady8mps.dat"', f'"{inflow}"'
    )
    (d / f"{name}.fst").write_text(_fst5(fst))
    ifw = (r_test / "5MW_Baseline/NRELOffshrBsline5MW_InflowWind_Steady8mps.dat").read_text()
    (d / inflow).write_text(setv(ifw, "HWindSpeed", f"{wind:g}"))
    ed = (src / "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat").read_text()
    ed = setv(ed, "RotSpeed", f"{rpm}")
    ed = setv(ed, "OoPDefl", "3.0" if wind >= 10 else "2.0")
    for b in (1, 2, 3):
        ed = setv(ed, f"BlPitch({b})", f"{pitch}")
    (d / "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat").write_text(_elastodyn5(ed))
    ad = (src / "NRELOffshrBsline5MW_Onshore_AeroDyn.dat").read_text()
    for key, value in (
        ("DBEMT_Mod", "-1" if frozen else "0"),
        ("UA_Mod", "0"),
        ("TwrPotent", "0"),
        ("TwrShadow", "0"),
        ("TwrAero", "False"),
        ("Skew_Mod", "-1"),
    ):
        ad = setv(ad, key, value)
    (d / "NRELOffshrBsline5MW_Onshore_AeroDyn.dat").write_text(_aerodyn5(ad))
    sd = (src / "NRELOffshrBsline5MW_Onshore_ServoDyn.dat").read_text()
    sd = setv(setv(sd, "TimGenOn", "0"), "VS_RtGnSp", "1161.963")
    (d / "NRELOffshrBsline5MW_Onshore_ServoDyn.dat").write_text(_servodyn5(sd, pitch))
    shutil.copy(src / "NRELOffshrBsline5MW_Onshore_ElastoDyn_Tower.dat", d)
    return d


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if a != "--frozen"]
    for w in args[2:]:
        print(make(Path(args[0]), Path(args[1]), float(w), frozen="--frozen" in sys.argv))
