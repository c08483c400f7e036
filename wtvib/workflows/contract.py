"""The JSON contract: JSON Schemas (draft 2020-12) of the report and the batch documents.

``wtvib schema --report`` prints the report's. Every key is described here; a check's numbers
vary with its kind (resonance, class, stability …) and are described, not required. The
report keeps full precision; people-facing outputs round at the edge.
"""

from typing import Any

from ..audit import REPORT_SCHEMA
from .batch import RESULTS_SCHEMA, SUMMARY_SCHEMA  # noqa: F401  (the batch documents' ids)

_NUM = {"type": "number"}
_NUM_OR_NULL = {"type": ["number", "null"]}
_STR = {"type": "string"}
_STATUS = {"enum": ["pass", "info", "warn", "fail"]}


def _d(text: str, schema: dict[str, Any] | None = None) -> dict[str, Any]:
    return {**(schema or {}), "description": text}


_MODE: dict[str, Any] = {
    "type": "object",
    "required": [
        "id",
        "subsystem",
        "description",
        "frequency_hz",
        "damping_ratio",
        "speed_dependent",
    ],
    "properties": {
        "id": _d("The mode's id, one truth everywhere (tower.fa1, system.blade.flap1…).", _STR),
        "subsystem": _d("tower, blade, drivetrain, yaw or system (whole turbine).", _STR),
        "description": _d("What the mode is, and where its frequency came from.", _STR),
        "frequency_hz": _d(
            "Standstill frequency (imported results: the first point's) [Hz].", _NUM
        ),
        "damping_ratio": _d(
            "Damping ratio judged without operation data (given or assumed).", _NUM_OR_NULL
        ),
        "speed_dependent": _d(
            "Whether the frequency changes with rotor speed.", {"type": "boolean"}
        ),
        "regimes": _d(
            "Operating regimes the mode exists in (absent: all).", {"type": "array", "items": _STR}
        ),
        "condition": _d("The condition the frequency holds in (generator free, a tool …).", _STR),
        "superseded_by": _d("The coupled or imported mode judged in this one's place.", _STR),
        "damping_source": _d("Where damping_ratio came from when it is not the mode's own.", _STR),
        "damping_in_operation": _d(
            "The lowest total damping at the operating points: lowest_total_damping_ratio, "
            "aerodynamic_damping_ratio (null where unknown), at_wind_m_s (null where "
            "unknown), at_rpm, source.",
            {"type": "object"},
        ),
        "whirl": _d("Whirl labels of a fixed-frame rotor mode per rpm.", {"type": "object"}),
        "band_hz": _d(
            "The frequency's band at standstill [Hz]: lower- and upper-bound soil, or a "
            "concrete tower's modulus (the checks judge the band).",
            {"type": "array", "items": _NUM, "minItems": 2, "maxItems": 2},
        ),
    },
    "additionalProperties": False,
}

#: The numbers a check may carry, by key (documented; which appear depends on the check).
CHECK_NUMBERS: dict[str, str] = {
    "mode": "The governing mode's id.",
    "frequency_hz": "The governing mode's frequency where judged [Hz].",
    "margin": "Separation from the excitation, |f_n − f_exc|/f_exc (band) or the ratio rule's [-].",
    "required_margin": "The rule's margin [-].",
    "speed_rpm": "Rotor speed of the least margin [rpm].",
    "excitation": "The excitation line (1P, 3P, stage2 …).",
    "excitation_hz": "The line's frequency there [Hz].",
    "daf": "Dynamic amplification factor at that point (null: undefined) [-].",
    "damping_ratio": "The damping the DAF used [-].",
    "damping": "'in operation' where that damping came from the operating points.",
    "regime": "steady, start-up, overspeed or quick-pass: where the governing finding lies.",
    "energy": "The line's energy class (dominant, secondary, minor).",
    "energy_on_mode": "The energy class on the governing mode's whirl.",
    "heavily_damped": (
        "True where the governing resonance is told as info because the mode is heavily "
        "damped there (no resonant peak)."
    ),
    "crossings_rpm": "Speeds where the line crosses the mode's curve [rpm].",
    "exclude_rpm": (
        "Speed bands to exclude to clear the check: those of its modes that warn or fail "
        "(none where it passes or only informs) [rpm]."
    ),
    "modes": "Each mode's status against this line.",
    "torque_amplification": "Shaft torque amplification of a drive-train resonance [-].",
    "tower_class": "stiff, soft, soft-soft or resonant.",
    "startup_crossings": "Dominant lines the tower's first bending is crossed by at start-up.",
    "unstable": "Modes and where they are negatively damped.",
    "lowest": "The lowest damping found: mode, ratio, where.",
    "unstable_rpm": "Speed bands of Floquet instability [rpm].",
    "not_analysed_rpm": "Speed bands the Floquet check could not analyse [rpm].",
    "max_multiplier_in_operation": "Largest Floquet multiplier modulus in operation [-].",
    "points": "The steady operating points (wind, rpm, pitch, region, power, thrust, C_p, C_t).",
    "rated_wind_m_s": "Rated wind speed [m/s].",
    "tip_speed_ratio": "Region-2 tip-speed ratio [-].",
    "sections": "Blade stability per section (divergence, flutter).",
    "min_total_damping_ratio": "Lowest total damping of a stall check [-].",
    "at_wind_m_s": "Wind speed of that lowest damping [m/s].",
    "at_rpm": "Rotor speed of that lowest damping [rpm].",
    "curve": "A stall check's damping over the operating points.",
    "p1_hz_at_max": "1P at the highest steady speed (tower class) [Hz].",
    "hub": (
        "The hub type the Floquet check modelled (rigid or hingeless, teetered; a hinged hub "
        "is modelled hingeless)."
    ),
    "polar_inertia_kgm2": "Rotor polar inertia the Floquet check used [kg·m²].",
    "speed_ratio": "Divergence or flutter speed over the highest section speed [-].",
    "cantilever_load_factor": "Strip-theory cantilever factor on the divergence speed [-].",
    "vg_section_radius_m": "Radius of the section the V–g diagram shows [m].",
    "vg_section_speed_m_s": "That section's highest air speed [m/s].",
    "aerodynamic_cyclic_nm": "Cyclic aerodynamic yaw moment given [N·m].",
    "gyroscopic_nm": "Gyroscopic yaw-tilt moment J_p·Ω·Ω_yaw [N·m].",
    "friction_nm": "Yaw friction while yawing [N·m].",
    "brakes_nm": "Yaw brake moment when parked [N·m].",
    "inertia_mean_kgm2": "Mean yaw inertia of a two-bladed rotor over azimuth [kg·m²].",
    "inertia_variation_kgm2": "Its variation with azimuth [kg·m²].",
    "frequency_range_hz": "The yaw frequency's range over azimuth [Hz].",
    "half_gap_deg": "Half the yaw gear's play [deg].",
    "frequency_no_play_hz": "Yaw frequency without play [Hz].",
    "critical_amplitude_deg": "Amplitude below which the play dominates [deg].",
    "amplitude_deg": "The yaw amplitude judged [deg].",
    "frequency_with_play_hz": "Effective yaw frequency with the play at that amplitude [Hz].",
    "power_fraction": "Power fractions of the drive train's grid mode over the power range [-].",
    "damping_nms_rad": "An induction generator's slip damping on its shaft [N·m·s/rad].",
    "time_constant_s": (
        "The time constant of the drive train's whole rotation against that damping [s]."
    ),
    "wave_periods_s": "The site's wave band (shortest, longest period) [s].",
    "inside": "The platform modes inside the wave band.",
    "driven_by": (
        "The rotating-frame harmonic behind a fixed-frame rotor mode's resonance (a cyclic "
        "mode met by 6P is the blades' 7P or 5P) [-]."
    ),
    "condition": "system.coupling: the generator condition the coupled modes hold in.",
    "model": "system.coupling: what the coupled model holds and neglects, in words.",
    "parked": (
        "system.coupling: the coupled modes in the other generator condition (condition, "
        "modes: name, frequency [Hz])."
    ),
    "sets": (
        "An ElastoDyn deck's mode-shape polynomials (polynomials.tower, .blade): each set's "
        "name (TwFAM1Sh …), mode, file and line, the finite-element frequency [Hz], the "
        "frequency the deck's and the computed polynomial imply [Hz], the deck's MAC against "
        "the computed shape and against the other mode of its plane, and both coefficient "
        "lists (c₂ … c₆)."
    ),
    "pairs": (
        "Subsystems' modes the chapter names as coupled, at their closest: the two ids and "
        "frequencies [Hz], the rotor speed [rpm], the separation |f₁ − f₂|/min [-] and the "
        "coupled modes judged in their place (system.closeness)."
    ),
}

_CHECK: dict[str, Any] = {
    "type": "object",
    "required": ["id", "subsystem", "status", "message", "rule"],
    "properties": {
        "id": _d("Stable check id (subsystem.kind[.line]).", _STR),
        "subsystem": _d("The subsystem the check belongs to.", _STR),
        "status": _d("pass, info, warn or fail.", _STATUS),
        "message": _d("The finding in words, with its numbers.", _STR),
        "rule": _d(
            "The rule applied and its source.",
            {
                "type": "object",
                "required": ["name", "source"],
                "properties": {"name": _STR, "source": _STR},
            },
        ),
        **{k: {"description": v} for k, v in CHECK_NUMBERS.items()},
    },
    "additionalProperties": True,
}


def report_schema() -> dict[str, Any]:
    """The JSON Schema of ``wtvib check --format json`` (the report ``wtvib-report/1``)."""
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "$id": f"https://wtvib.invalid/{REPORT_SCHEMA}",
        "title": "wtvib audit report",
        "type": "object",
        "required": [
            "schema", "produced_by", "turbine", "verdict", "tower_class", "operation", "rule",
            "damping", "aerodynamics", "modes", "campbell", "checks", "assumptions",
            "warnings", "inputs",
        ],
        "properties": _report_properties(),
        "additionalProperties": False,
    }  # fmt: skip


#: The provenance of a report: which wtvib read which input (its SHA-256 as read).
_PRODUCED_BY = {
    "type": "object",
    "required": ["tool", "version", "input"],
    "properties": {
        "tool": {"const": "wtvib"},
        "version": _STR,
        "input": {
            "type": "object",
            "required": ["file", "sha256"],
            "properties": {
                "file": {"type": ["string", "null"]},
                "sha256": {"type": ["string", "null"], "pattern": "^[0-9a-f]{64}$"},
            },
        },
    },
}


def _report_properties() -> dict[str, Any]:
    """The report's top-level keys, each described."""
    return {
        "schema": _d("This contract's id and version.", {"const": REPORT_SCHEMA}),
        "produced_by": _d(
            "wtvib's version and the input with its SHA-256 (as read).", _PRODUCED_BY
        ),
        "turbine": _d(
            "Name, source file, the spec's turbine block, blades, orientation, hub.",
            {"type": "object", "required": ["name", "blades"]},
        ),
        "verdict": _d("pass, warn or fail: the worst check.", {"enum": ["pass", "warn", "fail"]}),
        "tower_class": _d(
            "stiff, soft, soft-soft, resonant, or null (no tower mode).",
            {"enum": ["stiff", "soft", "soft-soft", "resonant", None]},
        ),
        "operation": _d(
            "Steady speed intervals, variable speed, overspeed, quick-pass bands, where the "
            "speeds came from [rpm].",
            {"type": "object", "required": ["steady_rpm", "variable_speed", "overspeed_rpm"]},
        ),
        "rule": _d(
            "The margin rule in force: kind, margin, preset, source, harmonics, severity.",
            {"type": "object", "required": ["kind", "margin"]},
        ),
        "damping": _d(
            "How the judged modes were damped.",
            {"enum": ["structural", "aeroelastic", "imported"]},
        ),
        "aerodynamics": _d("Whether the spec has an aerodynamics block.", {"type": "boolean"}),
        "results": _d(
            "Another tool's results the modes came from: tool, files.",
            {"type": "object", "required": ["tool", "files"]},
        ),
        "modes": _d("Every mode, judged or shown.", {"type": "array", "items": _MODE}),
        "campbell": _d(
            "Every judged mode's frequency and damping sampled over speed (the CSV's data).",
            {"type": "object", "required": ["damping", "rpm", "modes"]},
        ),
        "checks": _d("Every check, in report order.", {"type": "array", "items": _CHECK}),
        "assumptions": _d(
            "What the audit assumed, each stated where it was made.",
            {"type": "array", "items": _STR},
        ),
        "warnings": _d(
            "Suspicious or missing inputs, what an importer had to assume, numbers written "
            "as null.",
            {"type": "array", "items": _STR},
        ),
        "uncertainty": _d(
            "Monte Carlo results (--uncertainty): samples, per-mode percentiles and "
            "margin-band probabilities (and the share of samples that buckle, "
            "`unstable`), sensitivities, inputs not propagated, and draws outside an "
            "input's valid range drawn again (`truncated`).",
            {"type": "object"},
        ),
        "inputs": _d(
            "Every value with provenance: value, provenance, source, note, tolerance.",
            {"type": "object"},
        ),
    }


def schema(report: bool = False) -> int:
    """``wtvib schema``: the JSON Schema of the turbine spec, or of the report."""
    from . import ui

    if report:
        ui.dump(report_schema())
    else:
        from ..spec import json_schema

        ui.dump(json_schema())
    return ui.EXIT_PASS
