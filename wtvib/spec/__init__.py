"""The turbine spec: wtvib's input format (version 1), validated once, at the boundary.

A spec is a YAML file written by hand. Units are in the key names (``_hz``, ``_rpm``,
``_m``, ``_kg``, ``_kw``); ratios have no suffix. Any number may instead be written as a
*quantity* mapping that records where it came from::

    fa1: {value: 0.42, provenance: derived, source: hau, note: "between 1P and 2P (Fig. 7.22)"}

``provenance`` is ``published`` (a number printed in the source), ``derived`` (computed or
read from a statement in the source) or ``representative`` (a plausible value chosen where
the source gives none). ``source`` names an entry of the top-level ``sources`` mapping.

Validation errors become one :class:`~wtvib.errors.SpecError` line naming the field path and
the YAML line. Past this module, code trusts the spec (STYLE.md habit 4).

The package: the schema by subject (:mod:`.base`, :mod:`.rotor`, :mod:`.tower`,
:mod:`.blade`, :mod:`.drivetrain`, :mod:`.yaw`, :mod:`.turbine`), reading (:mod:`.load`), the
translation of validation errors (:mod:`.messages`), the cross-checks that need several
fields (:mod:`.checks`) and the JSON Schema (:mod:`.export`). Everything public is importable
from ``wtvib.spec``.
"""

from ..errors import SpecError  # the error every spec mistake raises
from .aerodynamics import Aerodynamics, AirfoilPolar, BladeStations, Control
from .base import (
    BladeModeName,
    ModeEntry,
    ModeSpec,
    Positive,
    Quantity,
    Ratio,
    TowerModeName,
    YawModeName,
)
from .blade import (
    AeroSection,
    Blade,
    BladeAeroelastic,
    BladeStructure,
    Planform,
    Polar,
    TipDamper,
    check_section_inertia,
)
from .drivetrain import (
    ChainMass,
    ChainShaft,
    Drivetrain,
    FixedExcitation,
    FluidCoupling,
    GearStage,
    GeneratorModel,
    InertiaFractions,
)
from .export import json_schema
from .load import (
    FORMAT_VERSION,
    MAX_FILE_BYTES,
    from_data,
    from_document,
    load,
    load_document,
    read_bytes,
    read_text,
)
from .rotor import DEFAULT_OVERSPEED_FACTOR, Rotor, RotorSpeed, TurbineInfo
from .tower import (
    DistributedTower,
    Foundation,
    MassDamper,
    Material,
    PointMass,
    Tower,
    TowerHead,
    TubularSections,
)
from .turbine import AuditSettings, CoupledModel, Severity, Spec
from .yaw import Yaw, YawPlay

__all__ = [
    "DEFAULT_OVERSPEED_FACTOR",
    "FORMAT_VERSION",
    "MAX_FILE_BYTES",
    "AeroSection",
    "Aerodynamics",
    "AirfoilPolar",
    "AuditSettings",
    "Blade",
    "BladeAeroelastic",
    "BladeModeName",
    "BladeStations",
    "BladeStructure",
    "ChainMass",
    "ChainShaft",
    "Control",
    "CoupledModel",
    "DistributedTower",
    "Drivetrain",
    "FixedExcitation",
    "FluidCoupling",
    "Foundation",
    "GearStage",
    "GeneratorModel",
    "InertiaFractions",
    "MassDamper",
    "Material",
    "ModeEntry",
    "ModeSpec",
    "Planform",
    "PointMass",
    "Polar",
    "Positive",
    "Quantity",
    "Ratio",
    "Rotor",
    "RotorSpeed",
    "Severity",
    "Spec",
    "SpecError",
    "TipDamper",
    "Tower",
    "TowerHead",
    "TowerModeName",
    "TubularSections",
    "TurbineInfo",
    "Yaw",
    "YawModeName",
    "YawPlay",
    "check_section_inertia",
    "from_data",
    "from_document",
    "json_schema",
    "load",
    "load_document",
    "read_bytes",
    "read_text",
]
