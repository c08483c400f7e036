"""The report as a document: the shape of ``Report.to_dict()`` (the JSON contract
``wtvib-report/1``, described key by key in :mod:`wtvib.workflows.contract`) as typed
dictionaries, so that every consumer — the terminal, the PDF, batch — reads fields mypy
checks, and a key renamed on one side fails the type check on the other.

A check's numbers vary with its kind (resonance, class, stability …): every key a check may
carry is declared here as optional; ``tests/test_contract.py`` holds them equal to the
contract's documented keys.
"""

from typing import Any, Literal, NotRequired, TypedDict

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
    mode: NotRequired[str]
    frequency_hz: NotRequired[float | None]
    margin: NotRequired[float | None]
    required_margin: NotRequired[float]
    speed_rpm: NotRequired[float | None]
    excitation: NotRequired[str]
    excitation_hz: NotRequired[float | None]
    daf: NotRequired[float | None]
    damping_ratio: NotRequired[float | None]
    damping: NotRequired[str]
    regime: NotRequired[str | None]
    energy: NotRequired[str]
    energy_on_mode: NotRequired[Any]
    heavily_damped: NotRequired[bool]
    crossings_rpm: NotRequired[list[float]]
    exclude_rpm: NotRequired[list[list[float]]]
    modes: NotRequired[Any]
    torque_amplification: NotRequired[float | None]
    tower_class: NotRequired[str]
    startup_crossings: NotRequired[list[str]]
    unstable: NotRequired[list[dict[str, Any]]]
    lowest: NotRequired[dict[str, Any] | None]
    unstable_rpm: NotRequired[list[list[float]]]
    not_analysed_rpm: NotRequired[list[list[float]]]
    max_multiplier_in_operation: NotRequired[float | None]
    points: NotRequired[list[dict[str, Any]]]
    rated_wind_m_s: NotRequired[float | None]
    tip_speed_ratio: NotRequired[float]
    sections: NotRequired[list[dict[str, Any]]]
    min_total_damping_ratio: NotRequired[float]
    at_wind_m_s: NotRequired[float | None]
    at_rpm: NotRequired[float]
    curve: NotRequired[list[dict[str, Any]]]
    p1_hz_at_max: NotRequired[float]
    hub: NotRequired[str]
    polar_inertia_kgm2: NotRequired[float]
    speed_ratio: NotRequired[float | None]
    cantilever_load_factor: NotRequired[float]
    vg_section_radius_m: NotRequired[float]
    vg_section_speed_m_s: NotRequired[float]
    aerodynamic_cyclic_nm: NotRequired[float]
    gyroscopic_nm: NotRequired[float]
    friction_nm: NotRequired[float]
    brakes_nm: NotRequired[float]
    inertia_mean_kgm2: NotRequired[float]
    inertia_variation_kgm2: NotRequired[float]
    frequency_range_hz: NotRequired[list[float]]
    half_gap_deg: NotRequired[float]
    frequency_no_play_hz: NotRequired[float]
    critical_amplitude_deg: NotRequired[float]
    amplitude_deg: NotRequired[float]
    frequency_with_play_hz: NotRequired[float]
    power_fraction: NotRequired[list[float]]
    damping_nms_rad: NotRequired[float]
    time_constant_s: NotRequired[float]
    wave_periods_s: NotRequired[list[float]]
    inside: NotRequired[list[Any]]
    driven_by: NotRequired[str | None]
    condition: NotRequired[str]
    model: NotRequired[str]
    parked: NotRequired[dict[str, Any]]
    sets: NotRequired[list[dict[str, Any]]]
    pairs: NotRequired[list[dict[str, Any]]]


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
