"""The JSON contract: JSON Schemas (draft 2020-12) of the report and the batch documents.

``wtvib schema --report`` prints the report's. Every key is described here; a check's numbers
vary with its kind (resonance, class, stability …) and are described, not required. The
report keeps full precision; people-facing outputs round at the edge.
"""

from typing import Any, get_args, get_type_hints

from ..audit import REPORT_SCHEMA
from ..document import CheckDoc
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


def _check_numbers() -> dict[str, str]:
    """The numbers a check may carry and their descriptions, as
    :class:`wtvib.document.CheckDoc` declares them (which appear depends on the check)."""
    hints = get_type_hints(CheckDoc, include_extras=True)
    optional = CheckDoc.__optional_keys__
    return {k: get_args(get_args(t)[0])[1] for k, t in hints.items() if k in optional}


#: The numbers a check may carry, by key (documented; which appear depends on the check).
CHECK_NUMBERS: dict[str, str] = _check_numbers()

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
