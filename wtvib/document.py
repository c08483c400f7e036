"""The report as a document: the shape of ``Report.to_dict()`` (the JSON contract
``wtvib-report/1``, described key by key in :mod:`wtvib.workflows.contract`) as typed
dictionaries, so that every consumer — the terminal, the PDF, batch — reads fields mypy
checks, and a key renamed on one side fails the type check on the other.

A check's numbers vary with its kind (resonance, class, stability …): every key a check may
carry is declared here once, optional, with its type and the description the JSON Schema
gives it (:data:`wtvib.workflows.contract.CHECK_NUMBERS` is read from here).
"""

from typing import Annotated, Any, Literal, NotRequired, TypedDict

Status = Literal["pass", "info", "warn", "fail"]


class RuleDoc(TypedDict):
    name: str
    source: str


class CheckDoc(TypedDict):
    """One finding: id, status, message, rule, and the numbers its kind carries."""

    id: str
    subsystem: str
    status: Status
    message: str
    rule: RuleDoc
    mode: NotRequired[Annotated[str, "The governing mode's id."]]
    frequency_hz: NotRequired[
        Annotated[float | None, "The governing mode's frequency where judged [Hz]."]
    ]
    margin: NotRequired[
        Annotated[
            float | None,
            "Separation from the excitation, |f_n − f_exc|/f_exc (band) or the ratio rule's [-].",
        ]
    ]
    required_margin: NotRequired[Annotated[float, "The rule's margin [-]."]]
    speed_rpm: NotRequired[Annotated[float | None, "Rotor speed of the least margin [rpm]."]]
    excitation: NotRequired[Annotated[str, "The excitation line (1P, 3P, stage2 …)."]]
    excitation_hz: NotRequired[Annotated[float | None, "The line's frequency there [Hz]."]]
    daf: NotRequired[
        Annotated[float | None, "Dynamic amplification factor at that point (null: undefined) [-]."]
    ]
    damping_ratio: NotRequired[Annotated[float | None, "The damping the DAF used [-]."]]
    damping: NotRequired[
        Annotated[str, "'in operation' where that damping came from the operating points."]
    ]
    regime: NotRequired[
        Annotated[
            str | None,
            "steady, start-up, overspeed or quick-pass: where the governing finding lies.",
        ]
    ]
    energy: NotRequired[Annotated[str, "The line's energy class (dominant, secondary, minor)."]]
    energy_on_mode: NotRequired[Annotated[Any, "The energy class on the governing mode's whirl."]]
    heavily_damped: NotRequired[
        Annotated[
            bool,
            "True where the governing resonance is told as info because the mode is heavily "
            "damped there (no resonant peak).",
        ]
    ]
    crossings_rpm: NotRequired[
        Annotated[list[float], "Speeds where the line crosses the mode's curve [rpm]."]
    ]
    exclude_rpm: NotRequired[
        Annotated[
            list[list[float]],
            "Speed bands to exclude to clear the check: those of its modes that warn or fail "
            "(none where it passes or only informs) [rpm].",
        ]
    ]
    modes: NotRequired[Annotated[Any, "Each mode's status against this line."]]
    torque_amplification: NotRequired[
        Annotated[float | None, "Shaft torque amplification of a drive-train resonance [-]."]
    ]
    tower_class: NotRequired[Annotated[str, "stiff, soft, soft-soft or resonant."]]
    startup_crossings: NotRequired[
        Annotated[list[str], "Dominant lines the tower's first bending is crossed by at start-up."]
    ]
    unstable: NotRequired[
        Annotated[list[dict[str, Any]], "Modes and where they are negatively damped."]
    ]
    lowest: NotRequired[
        Annotated[dict[str, Any] | None, "The lowest damping found: mode, ratio, where."]
    ]
    unstable_rpm: NotRequired[
        Annotated[list[list[float]], "Speed bands of Floquet instability [rpm]."]
    ]
    not_analysed_rpm: NotRequired[
        Annotated[list[list[float]], "Speed bands the Floquet check could not analyse [rpm]."]
    ]
    max_multiplier_in_operation: NotRequired[
        Annotated[float | None, "Largest Floquet multiplier modulus in operation [-]."]
    ]
    points: NotRequired[
        Annotated[
            list[dict[str, Any]],
            "The steady operating points (wind, rpm, pitch, region, power, thrust, C_p, C_t).",
        ]
    ]
    rated_wind_m_s: NotRequired[Annotated[float | None, "Rated wind speed [m/s]."]]
    tip_speed_ratio: NotRequired[Annotated[float, "Region-2 tip-speed ratio [-]."]]
    sections: NotRequired[
        Annotated[list[dict[str, Any]], "Blade stability per section (divergence, flutter)."]
    ]
    min_total_damping_ratio: NotRequired[
        Annotated[float, "Lowest total damping of a stall check [-]."]
    ]
    at_wind_m_s: NotRequired[Annotated[float | None, "Wind speed of that lowest damping [m/s]."]]
    at_rpm: NotRequired[Annotated[float, "Rotor speed of that lowest damping [rpm]."]]
    curve: NotRequired[
        Annotated[list[dict[str, Any]], "A stall check's damping over the operating points."]
    ]
    p1_hz_at_max: NotRequired[
        Annotated[float, "1P at the highest steady speed (tower class) [Hz]."]
    ]
    frequency_hz_at_max: NotRequired[
        Annotated[
            float,
            "The classifying mode's frequency at the highest steady speed, where the tower "
            "class is decided (its curve's value there) [Hz].",
        ]
    ]
    hub: NotRequired[
        Annotated[
            str,
            "The hub type the Floquet check modelled (rigid or hingeless, teetered; a hinged hub "
            "is modelled hingeless).",
        ]
    ]
    polar_inertia_kgm2: NotRequired[
        Annotated[float, "Rotor polar inertia the Floquet check used [kg·m²]."]
    ]
    speed_ratio: NotRequired[
        Annotated[float | None, "Divergence or flutter speed over the highest section speed [-]."]
    ]
    cantilever_load_factor: NotRequired[
        Annotated[float, "Strip-theory cantilever factor on the divergence speed [-]."]
    ]
    vg_section_radius_m: NotRequired[
        Annotated[float, "Radius of the section the V–g diagram shows [m]."]
    ]
    vg_section_speed_m_s: NotRequired[Annotated[float, "That section's highest air speed [m/s]."]]
    aerodynamic_cyclic_nm: NotRequired[
        Annotated[float, "Cyclic aerodynamic yaw moment given [N·m]."]
    ]
    gyroscopic_nm: NotRequired[Annotated[float, "Gyroscopic yaw-tilt moment J_p·Ω·Ω_yaw [N·m]."]]
    friction_nm: NotRequired[Annotated[float, "Yaw friction while yawing [N·m]."]]
    brakes_nm: NotRequired[Annotated[float, "Yaw brake moment when parked [N·m]."]]
    inertia_mean_kgm2: NotRequired[
        Annotated[float, "Mean yaw inertia of a two-bladed rotor over azimuth [kg·m²]."]
    ]
    inertia_variation_kgm2: NotRequired[Annotated[float, "Its variation with azimuth [kg·m²]."]]
    frequency_range_hz: NotRequired[
        Annotated[list[float], "The yaw frequency's range over azimuth [Hz]."]
    ]
    half_gap_deg: NotRequired[Annotated[float, "Half the yaw gear's play [deg]."]]
    frequency_no_play_hz: NotRequired[Annotated[float, "Yaw frequency without play [Hz]."]]
    critical_amplitude_deg: NotRequired[
        Annotated[float, "Amplitude below which the play dominates [deg]."]
    ]
    amplitude_deg: NotRequired[Annotated[float, "The yaw amplitude judged [deg]."]]
    frequency_with_play_hz: NotRequired[
        Annotated[float, "Effective yaw frequency with the play at that amplitude [Hz]."]
    ]
    power_fraction: NotRequired[
        Annotated[
            list[float], "Power fractions of the drive train's grid mode over the power range [-]."
        ]
    ]
    damping_nms_rad: NotRequired[
        Annotated[float, "An induction generator's slip damping on its shaft [N·m·s/rad]."]
    ]
    time_constant_s: NotRequired[
        Annotated[
            float, "The time constant of the drive train's whole rotation against that damping [s]."
        ]
    ]
    wave_periods_s: NotRequired[
        Annotated[list[float], "The site's wave band (shortest, longest period) [s]."]
    ]
    inside: NotRequired[Annotated[list[Any], "The platform modes inside the wave band."]]
    driven_by: NotRequired[
        Annotated[
            str | None,
            "The rotating-frame harmonic behind a fixed-frame rotor mode's resonance (a cyclic "
            "mode met by 6P is the blades' 7P or 5P) [-].",
        ]
    ]
    condition: NotRequired[
        Annotated[str, "system.coupling: the generator condition the coupled modes hold in."]
    ]
    model: NotRequired[
        Annotated[str, "system.coupling: what the coupled model holds and neglects, in words."]
    ]
    parked: NotRequired[
        Annotated[
            dict[str, Any],
            "system.coupling: the coupled modes in the other generator condition (condition, "
            "modes: name, frequency [Hz]).",
        ]
    ]
    sets: NotRequired[
        Annotated[
            list[dict[str, Any]],
            "An ElastoDyn deck's mode-shape polynomials (polynomials.tower, .blade): each set's "
            "name (TwFAM1Sh …), mode, file and line, the finite-element frequency [Hz], the "
            "frequency the deck's and the computed polynomial imply [Hz], the deck's MAC against "
            "the computed shape and against the other mode of its plane, and both coefficient "
            "lists (c₂ … c₆).",
        ]
    ]
    pairs: NotRequired[
        Annotated[
            list[dict[str, Any]],
            "Subsystems' modes the chapter names as coupled, at their closest: the two ids and "
            "frequencies [Hz], the rotor speed [rpm], the separation |f₁ − f₂|/min [-] and the "
            "coupled modes judged in their place (system.closeness).",
        ]
    ]


class OperatingDoc(TypedDict):
    """A mode's lowest total damping at the operating points."""

    lowest_total_damping_ratio: float
    aerodynamic_damping_ratio: float | None
    at_wind_m_s: float | None
    at_rpm: float
    source: str


class WhirlDoc(TypedDict):
    rpm: list[float]
    labels: list[str]


class ModeDoc(TypedDict):
    """A natural mode: one id, one frequency, one name and one condition everywhere."""

    id: str
    subsystem: str
    description: str
    frequency_hz: float
    damping_ratio: float | None
    speed_dependent: bool
    regimes: NotRequired[list[str]]
    condition: NotRequired[str]
    superseded_by: NotRequired[str]
    damping_source: NotRequired[str]
    damping_in_operation: NotRequired[OperatingDoc]
    band_hz: NotRequired[list[float]]
    whirl: NotRequired[WhirlDoc]


class InputFileDoc(TypedDict):
    file: str | None
    sha256: str | None


class ProducedByDoc(TypedDict):
    tool: str
    version: str
    input: InputFileDoc


class TurbineDoc(TypedDict):
    name: str
    source_file: str | None
    manufacturer: NotRequired[str]
    year: NotRequired[int]
    rated_power_kw: NotRequired[float]
    rotor_diameter_m: NotRequired[float]
    hub_height_m: NotRequired[float]
    description: NotRequired[str]
    blades: int
    orientation: str
    hub: str


class OperationDoc(TypedDict):
    parked: NotRequired[bool]
    steady_rpm: list[list[float]]
    variable_speed: bool
    overspeed_rpm: float
    quick_pass_rpm: list[list[float]]
    source: NotRequired[str]


class RuleSettingsDoc(TypedDict):
    kind: str
    margin: float
    preset: str | None
    source: str
    harmonics: int
    severity: dict[str, Status]


class ResultsDoc(TypedDict):
    tool: str
    files: list[str]


class InputDoc(TypedDict):
    """A spec input's value and where it came from."""

    value: Any
    provenance: str
    source: str | None
    note: NotRequired[str]


class ShareDoc(TypedDict):
    """A sampled probability and its 95 % confidence interval."""

    probability: float
    ci95: list[float]


class SpreadDoc(TypedDict, total=False):
    """One uncertain mode's sampled frequencies and chances (a mode that buckles in some
    samples has ``unstable``; one with no stable sample no percentiles)."""

    mean_hz: float
    std_hz: float
    p5_hz: float
    p50_hz: float
    p95_hz: float
    in_margin_band: dict[str, ShareDoc]
    unstable: ShareDoc


class UncertaintyDoc(TypedDict):
    """The Monte Carlo study of the spec's tolerances (``--uncertainty``)."""

    samples: int
    rule: str
    judged_over: str
    modes: dict[str, SpreadDoc]
    not_propagated: list[str]
    truncated: dict[str, Any]
    seed: int
    sensitivities: dict[str, dict[str, float]]


class CampbellModeDoc(TypedDict):
    """One judged mode's curve at the Campbell points."""

    frequency_hz: list[float]
    damping_ratio: list[float]
    aerodynamic_damping_ratio: NotRequired[list[float]]
    method: NotRequired[list[str]]
    aeroelastic_frequency_hz: NotRequired[list[float]]
    damped_frequency_hz: NotRequired[list[float]]
    quasi_steady_damping_ratio: NotRequired[list[float]]


class CampbellDoc(TypedDict):
    """The sampled curves of every judged mode (rpm; wind and pitch at the operating points)."""

    damping: str
    rpm: list[float]
    wind_m_s: NotRequired[list[float]]
    pitch_deg: NotRequired[list[float]]
    modes: dict[str, CampbellModeDoc]


class ReportDoc(TypedDict):
    """The whole report, ``wtvib-report/1``."""

    schema: str
    produced_by: ProducedByDoc
    turbine: TurbineDoc
    verdict: Status
    tower_class: str | None
    operation: OperationDoc
    rule: RuleSettingsDoc
    damping: str
    aerodynamics: bool
    results: NotRequired[ResultsDoc]
    modes: list[ModeDoc]
    campbell: CampbellDoc
    checks: list[CheckDoc]
    assumptions: list[str]
    warnings: list[str]
    uncertainty: NotRequired[UncertaintyDoc]
    inputs: dict[str, InputDoc]
