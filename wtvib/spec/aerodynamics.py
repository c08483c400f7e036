"""The rotor's aerodynamics: blade stations, aerofoil polars and the controller's schedule.

With this block the audit solves steady blade-element momentum operating points over the
wind range and adds the quasi-steady aerodynamic damping to the modes (``wtvib.aero.bem``,
``wtvib.aero.aerodamping``); without it the audit is structural and says so.
"""

from typing import Literal

from pydantic import Field, model_validator

from .base import Chord, Positive, _increasing, _same_length, _Strict
from .blade import MAX_WIND_M_S

#: The most aerofoils and stations a spec may name (the OpenFAST decks hold 8 aerofoils and
#: 19 nodes, windIO files ~10 aerofoils blended into one polar per station; the work of a
#: BEM solve grows with both).
MAX_AIRFOILS, MAX_STATIONS, MAX_POLAR_POINTS = 250, 200, 400

#: No aerofoil coefficient is larger (a flat plate's C_D peaks near 2).
MAX_COEFFICIENT = 10.0

#: No rotor is larger: radius and chord [m] (the largest turbines reach ~150 m).
MAX_RADIUS_M = 1000.0


class AirfoilPolar(_Strict):
    """One aerofoil's static polar: lift and drag over the angle of attack (−180 … 180°)."""

    alpha_deg: list[float] = Field(
        min_length=2, max_length=MAX_POLAR_POINTS, description="Angle of attack. [deg]"
    )
    cl: list[float] = Field(description="Lift coefficient C_L. [-]")
    cd: list[float] = Field(description="Drag coefficient C_D. [-]")
    cm: list[float] | None = Field(
        None,
        description="Pitching-moment coefficient C_M about the quarter chord, nose-up "
        "positive; with the blade's torsional stiffness it twists the blade in operation "
        "(aerodynamics.steady_torsion); none: 0. [-]",
    )
    separation_time: float = Field(
        3.0,
        ge=0,
        le=100,
        description="T_f0: the time the separation point takes to follow the angle of "
        "attack past the lift's linear range, in half-chord transits c/(2W) (used where "
        "aerodynamics.dynamic_stall; AeroDyn's T_f0, default 3, plus T_p for its "
        "Beddoes–Leishman models; Øye's model is usually run with 6; 0: no lag). [-]",
    )

    @model_validator(mode="after")
    def _consistent(self) -> "AirfoilPolar":
        _increasing("alpha_deg", self.alpha_deg)
        _same_length(self, "alpha_deg")
        if self.alpha_deg[0] < -180 or self.alpha_deg[-1] > 180:
            raise ValueError("alpha_deg must lie within -180 … 180")
        if min(self.cd) < 0 or max(self.cd) > MAX_COEFFICIENT:
            raise ValueError(f"cd must lie within 0 … {MAX_COEFFICIENT:g}")
        if max(abs(c) for c in self.cl) > MAX_COEFFICIENT:
            raise ValueError(f"cl must lie within ±{MAX_COEFFICIENT:g} (a lift coefficient)")
        if self.cm is not None and max(abs(c) for c in self.cm) > MAX_COEFFICIENT:
            raise ValueError(f"cm must lie within ±{MAX_COEFFICIENT:g} (a moment coefficient)")
        return self


class BladeStations(_Strict):
    """The blade's aerodynamic stations, from root to tip."""

    radius_m: list[float] = Field(
        min_length=3, max_length=MAX_STATIONS, description="Distance from the rotor axis. [m]"
    )
    chord_m: list[Chord] = Field(description="Chord. [m]")
    twist_deg: list[float] = Field(
        description="Aerodynamic twist: angle of the chord to the rotor plane at zero pitch "
        "(positive towards feather). [deg]"
    )
    airfoil: list[str] = Field(description="Aerofoil of each station (a key of `airfoils`).")
    shear_centre_chord: list[float] | None = Field(
        None,
        description="Where the section twists about (its shear centre), as a fraction of the "
        "chord from the leading edge; the lift and drag act at the quarter chord, so a shear "
        "centre aft of it lets them twist the blade nose-up (aerodynamics.steady_torsion); "
        "none: at the quarter chord. [-]",
    )

    @model_validator(mode="after")
    def _consistent(self) -> "BladeStations":
        _increasing("radius_m", self.radius_m)
        if self.radius_m[0] <= 0 or self.radius_m[-1] > MAX_RADIUS_M:
            raise ValueError(
                f"radius_m must lie within 0 … {MAX_RADIUS_M:g} m (measured from the rotor axis)"
            )
        _same_length(self, "radius_m")
        if max(self.chord_m) > self.radius_m[-1]:
            raise ValueError("chord_m longer than the rotor radius: a unit mistake?")
        if max(abs(t) for t in self.twist_deg) > 180:
            raise ValueError("twist_deg must lie within ±180 (degrees, not radians × …)")
        if self.shear_centre_chord is not None and any(
            not -0.5 <= x <= 1.5 for x in self.shear_centre_chord
        ):
            raise ValueError(
                "shear_centre_chord must lie within -0.5 … 1.5 chords of the leading edge "
                "(a fraction of the chord, not metres)"
            )
        return self


class MinimumPitch(_Strict):
    """The controller's minimum pitch over wind (ROSCO's peak shaving, windIO
    ``control.min_pitch_table``): the pitch is at least this below rated."""

    wind_m_s: list[float] = Field(min_length=2, max_length=400, description="Wind. [m/s]")
    pitch_deg: list[float] = Field(description="Minimum pitch. [deg]")

    @model_validator(mode="after")
    def _consistent(self) -> "MinimumPitch":
        _increasing("wind_m_s", self.wind_m_s)
        _same_length(self, "wind_m_s")
        if any(abs(p) > 90 for p in self.pitch_deg):
            raise ValueError("pitch_deg must lie within ±90")
        return self


class OperatingPoints(_Strict):
    """Steady operating points the model gives (a HAWC2 model's operational data file, a
    controller's published schedule): the blade-element momentum solution is found at these
    winds, rotor speeds and pitches instead of at the controller's schedule."""

    wind_m_s: list[float] = Field(min_length=1, max_length=400, description="Wind. [m/s]")
    rpm: list[float] = Field(description="Rotor speed. [rpm]")
    pitch_deg: list[float] = Field(description="Blade pitch, positive towards feather. [deg]")
    source: str | None = Field(None, description="Where the points come from.")

    @model_validator(mode="after")
    def _consistent(self) -> "OperatingPoints":
        if len(self.wind_m_s) > 1:  # one point: a linearisation deck's own
            _increasing("wind_m_s", self.wind_m_s)
        _same_length(self, "wind_m_s")
        if self.wind_m_s[0] <= 0 or self.wind_m_s[-1] > MAX_WIND_M_S:
            raise ValueError(f"wind_m_s must lie within 0 … {MAX_WIND_M_S:g} m/s")
        if any(not 0 < n <= 1000 for n in self.rpm):
            raise ValueError("rpm must lie within 0 … 1000 (a turning rotor)")
        if any(abs(p) > 90 for p in self.pitch_deg):
            raise ValueError("pitch_deg must lie within ±90")
        return self


class GeneratorTorque(_Strict):
    """The generator's torque against the rotor's speed as the controller holds it (a
    variable-speed law: ServoDyn's simple one, a controller's k·ω²), on the rotor's shaft.
    Its slope dT/dΩ damps the drive train — a damper from the generator to ground, 2T/Ω
    where T = k·Ω², none where the torque is held constant (OpenFAST linearises the law
    so: tests/validation/test_openfast_sweep.py)."""

    rpm: list[float] = Field(min_length=2, max_length=1000, description="Rotor speed. [rpm]")
    torque_nm: list[float] = Field(
        description="Generator torque on the rotor's shaft (the generator's times the gear "
        "ratio). [N·m]"
    )
    source: str | None = Field(None, description="Where the law comes from.")

    @model_validator(mode="after")
    def _consistent(self) -> "GeneratorTorque":
        _increasing("rpm", self.rpm)
        _same_length(self, "rpm")
        if self.rpm[0] < 0 or any(t < 0 for t in self.torque_nm):
            raise ValueError("rpm and torque_nm must not be negative")
        return self


class Control(_Strict):
    """The controller's steady schedule (Hau ch. 5; Jonkman et al. 2009 §7).

    Variable speed: the optimal tip-speed ratio between the rotor's min and rated speed,
    then constant speed; fixed speed: the rotor's fixed speed. Pitch regulation pitches to
    feather above rated power; stall regulation holds the fine pitch at every wind.
    """

    regulation: Literal["pitch", "stall"] = Field(
        "pitch", description="Power regulation above rated wind."
    )
    cut_in_wind_m_s: Positive = Field(
        3.0, le=MAX_WIND_M_S, description="Lowest wind in operation. [m/s]"
    )
    cut_out_wind_m_s: Positive = Field(
        25.0, le=MAX_WIND_M_S, description="Highest wind in operation. [m/s]"
    )
    rated_power_kw: Positive | None = Field(
        None,
        description="Rated electrical power; default turbine.rated_power_kw. Pitch regulation "
        "holds the aerodynamic power at rated / generator_efficiency. [kW]",
    )
    generator_efficiency: float = Field(
        1.0, gt=0, le=1, description="Drive train and generator efficiency. [-]"
    )
    tip_speed_ratio: Positive | None = Field(
        None,
        le=30,
        description="Region-2 tip-speed ratio; default: the one with the highest C_p at "
        "the fine pitch (from the BEM solution). [-]",
    )
    fine_pitch_deg: float = Field(
        0.0, ge=-30, le=90, description="Blade pitch below rated power. [deg]"
    )
    min_pitch: MinimumPitch | None = Field(
        None,
        description="Minimum pitch over wind (peak shaving); the pitch below rated is the "
        "higher of this and fine_pitch_deg.",
    )
    generator_torque: GeneratorTorque | None = Field(
        None,
        description="The generator's torque–speed law (variable speed); its slope damps the "
        "drive train at each operating point. Not given: the torque-controlled generator is "
        "the drive train's free end (no such damping).",
    )
    operating_points: OperatingPoints | None = Field(
        None,
        description="The model's own steady operating points (wind, rotor speed, pitch): "
        "the aerodynamics is solved at these; the schedule above (tip-speed ratio, fine and "
        "minimum pitch, pitching to rated power) is then not used.",
    )

    @model_validator(mode="after")
    def _range(self) -> "Control":
        if self.cut_in_wind_m_s >= self.cut_out_wind_m_s:
            raise ValueError(
                f"cut_in_wind_m_s ({self.cut_in_wind_m_s}) must be below cut_out_wind_m_s "
                f"({self.cut_out_wind_m_s})"
            )
        return self


class Aerodynamics(_Strict):
    """Blade stations, aerofoil polars and control: steady operating points and the
    aerodynamic damping of every mode in operation."""

    air_density_kg_m3: Positive = Field(1.225, le=2.0, description="Air density ρ. [kg/m³]")
    stations: BladeStations
    airfoils: dict[str, AirfoilPolar] = Field(
        min_length=1, max_length=MAX_AIRFOILS, description="Polars by name."
    )
    control: Control = Field(default_factory=Control)
    tip_loss: bool = Field(True, description="Prandtl's tip-loss factor. [-]")
    hub_loss: bool = Field(True, description="Prandtl's hub-loss factor. [-]")
    fixed_tip_induction: bool = Field(
        False,
        description="How a station at the tip, where Prandtl's tip loss vanishes, is "
        "loaded: false — as the loss says, not at all (the flow stopped there); true — as "
        "AeroDyn's BEMT loads the blade's last node (its inductions fixed at a = 1, a′ = 0: "
        "the section meets the rotation's speed alone, at φ = 0, and carries that lift; "
        "read from an AeroDyn deck with TipLoss on). [-]",
    )
    shed_wake: bool = Field(
        True,
        description="Lag the lift behind the angle of attack by the shed wake (Jones's "
        "approximation of Wagner's function), as unsteady aerofoil models do in attached "
        "flow; false: quasi-steady, the lift follows at once (AeroDyn with UA_Mod = 0). The "
        "lag stiffens heavily damped flap modes (Theodorsen's G < 0) and lowers their "
        "damping.",
    )

    dynamic_stall: bool = Field(
        False,
        description="Lag the separation point past the lift's linear range (Øye; the "
        "Beddoes–Leishman f″ state) by each aerofoil's separation_time: a vibration faster "
        "than the lag meets the attached-flow lift slope, and stall damps it more than the "
        "static polar says. false: the lift follows the static polar at once past stall "
        "(quasi-steady: the conservative stall damping, Hau ch. 7.2.3; AeroDyn with UA_Mod 0 "
        "or 7).",
    )

    induction: Literal["frozen", "dynamic", "equilibrium"] = Field(
        "frozen",
        description="How the wake's induction answers a blade's vibration: 'frozen', not at "
        "all — the induced velocity held, every section's flow turned by its motion "
        "(OpenFAST's frozen-wake linearisation, DBEMT_Mod −1); 'dynamic', as frozen over a "
        "vibration's period (the induction lags the motion by the wake's time constant, many "
        "periods of a flap mode: OpenFAST's DBEMT_Mod 1–3), except where the induction is "
        "fixed (fixed_tip_induction: AeroDyn's last node keeps a = 1, its normal inflow 0 "
        "whatever the motion); 'equilibrium', at once — each section's momentum balance "
        "re-solved with its motion (AeroDyn's BEMT without dynamic wake, DBEMT_Mod 0).",
    )
    steady_torsion: bool = Field(
        True,
        description="Let the blades twist under their steady aerodynamic moment (the "
        "polars' cm about the quarter chord, the lift's arm about stations.shear_centre_chord) "
        "where blade.structure gives the torsional stiffness gj_nm2: the operating points of "
        "a torsionally soft blade (large modern blades twist nose-down by degrees at rated) "
        "as HAWCStab2 and OpenFAST with BeamDyn compute them. false: the blade is rigid in "
        "torsion (OpenFAST with ElastoDyn).",
    )

    @model_validator(mode="after")
    def _named(self) -> "Aerodynamics":
        missing = sorted(set(self.stations.airfoil) - set(self.airfoils))
        if missing:
            raise ValueError(
                f"stations.airfoil names {', '.join(missing)}, not in airfoils "
                f"({', '.join(sorted(self.airfoils))})"
            )
        return self
