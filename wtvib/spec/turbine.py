"""The whole spec: the coupled-model block, audit settings, and the Spec that holds every part."""

from collections.abc import Callable
from typing import Any, Literal

from pydantic import Field, PrivateAttr

from ..rules import HEAVY_DAMPING, PRESETS, MarginRule, Status
from .aerodynamics import Aerodynamics
from .base import Quantity, _Strict
from .blade import Blade
from .drivetrain import Drivetrain
from .results import Results
from .rotor import Rotor, TurbineInfo
from .tower import Tower, TowerHead
from .yaw import Yaw


class CoupledModel(_Strict):
    """What the coupled rotor–tower model (whole-turbine modes, Hau §7.6) needs beyond the
    subsystems: where the rotor sits on the tower head, the hub, and how many blade modes."""

    apex_downwind_m: float = Field(
        ge=-100,
        le=100,
        description="Rotor centre (apex) downwind of the tower axis; negative upwind. [m]",
    )
    apex_above_top_m: float = Field(
        ge=-100, le=100, description="Rotor centre above the tower top. [m]"
    )
    hub_mass_kg: float = Field(0.0, ge=0, description="Hub mass (part of tower_head). [kg]")
    hub_inertia_kgm2: float | None = Field(
        None,
        ge=0,
        description="Hub inertia about the shaft; default: the drive-train chain's hub (or "
        "0 without a chain). [kg·m²]",
    )
    blade_modes: int = Field(
        4,
        ge=1,
        le=6,
        description="Flexible modes per blade, lowest first (flap1, edge1, flap2, edge2, …): "
        "four by default — with three, the blades' collective edgewise swing against the "
        "drive train lacks the second edgewise shape and comes out 19 % high on the IEA-22 "
        "(1.28 against 1.07 Hz with four or more).",
    )
    parked_condition: Literal["locked", "free", "grid"] = Field(
        "locked", description="Generator when parked (Jonkman et al. 2009 Table 9-1: locked)."
    )
    rotating_condition: Literal["locked", "free", "grid"] = Field(
        "free",
        description="Generator in the rotating sweep: free (converter, torque-controlled), "
        "grid (the drivetrain.generator_model coupling), locked (held at the rotor's speed: "
        "its clamped-end drive-train modes are the turning turbine's, judged in every "
        "regime, and no free-end mode is).",
    )


class Severity(_Strict):
    """Status given to a margin violation in steady operation, by excitation energy."""

    dominant: Status = Field("fail", description="1P and N_b·P (Hau ch. 7.1).")
    secondary: Status | None = Field(
        None,
        description="kP with 1 < k < N_b, e.g. 2P on a three-bladed rotor, at a dwell speed "
        "(fixed or rated speed); one step milder elsewhere in a variable-speed range (Hau "
        "ch. 7.5.2: 'basically considered less critical', yet WKA-60's tower met 2P at rated "
        "speed and resonated). Default: the preset's (hau: fail, gl2010: warn).",
    )
    minor: Status = Field(
        "info", description="Higher harmonics above N_b·P (Hau ch. 7.2.2: little energy)."
    )


class AuditSettings(_Strict):
    """How strictly to judge: the margin rule, its margin, and how many harmonics."""

    preset: Literal["hau", "gl2010"] = Field(
        "hau", description="Code whose rule and margin are the defaults: " + ", ".join(PRESETS)
    )
    rule: Literal["band", "ratio"] | None = Field(
        None, description="band: |f_n−f_exc| ≥ m·f_exc; ratio: f_exc/f_n outside 1 ± m."
    )
    margin: float | None = Field(None, gt=0, lt=1, description="Margin m (0.10 = 10 %). [-]")
    harmonics: int = Field(6, ge=1, le=60, description="Highest rotor harmonic kP checked.")
    heavy_damping_ratio: float = Field(
        HEAVY_DAMPING,
        gt=0,
        le=1,
        description="A mode at least this damped (peak amplification 1/(2ζ√(1−ζ²)) ≤ 1.75 at "
        "0.3) has no resonant peak: its margin violations are reported as info. [-]",
    )
    severity: Severity = Field(default_factory=Severity)

    def severities(self) -> dict[str, Status]:
        """Status of a steady-state margin violation per energy class, preset applied."""
        out = self.severity.model_dump()
        if out["secondary"] is None:
            out["secondary"] = PRESETS[self.preset].secondary
        return out

    def margin_rule(self) -> MarginRule:
        """The rule in force: the preset's, with the explicit rule and margin on top."""
        preset = PRESETS[self.preset]
        kind = self.rule or preset.rule
        margin = self.margin if self.margin is not None else preset.margin
        if kind == preset.rule and margin == preset.margin:
            return MarginRule(kind, margin, preset.source, preset.name)
        return MarginRule(kind, margin, f"user setting (preset {preset.name} overridden)")


class Spec(_Strict):
    """A wind turbine to audit (wtvib spec format version 1)."""

    wtvib: Literal[1] = Field(description="Spec format version; this is version 1.")
    turbine: TurbineInfo
    sources: dict[str, str] = Field(
        default_factory=dict, description="Citations, by a short key used in quantities."
    )
    rotor: Rotor
    tower: Tower = Field(default_factory=Tower)
    tower_head: TowerHead | None = Field(
        None, description="Rotor–nacelle assembly on the tower top (for the tower model)."
    )
    blade: Blade = Field(default_factory=Blade)
    drivetrain: Drivetrain = Field(default_factory=Drivetrain)
    yaw: Yaw = Field(default_factory=Yaw)
    coupled: CoupledModel | None = Field(
        None,
        description="Rotor position and hub for the coupled whole-turbine model (needs the "
        "tower and blade structures and tower_head); absent: no coupled modes.",
    )
    aerodynamics: Aerodynamics | None = Field(
        None,
        description="Blade stations, polars and control: steady operating points and the "
        "aerodynamic damping of the modes; absent: a structural audit (assumed damping).",
    )
    results: Results | None = Field(
        None,
        description="Modes another tool computed (OpenFAST linearisation, HAWCStab2, a "
        "table): judged as the turbine's modes, in place of the coupled model's.",
    )
    audit: AuditSettings = Field(default_factory=AuditSettings)
    notes: str | None = Field(None, description="Anything else worth keeping with the spec.")
    assumptions: list[str] = Field(
        default_factory=list,
        description="How the spec was made (e.g. by an importer): shown in the report.",
    )
    warnings: list[str] = Field(
        default_factory=list,
        description="What the importer could not find and had to assume, loudly: shown in the "
        "report's headline and warnings.",
    )

    _source_file: str | None = PrivateAttr(None)
    _source_sha256: str | None = PrivateAttr(None)  # of the input as read
    _provenance: dict[str, Quantity] = PrivateAttr(default_factory=dict)
    # results derived from this spec that several analyses of one audit reuse (the coupled
    # model's blade modes): they live and die with the spec object, never across specs
    _derived: dict[tuple[object, ...], tuple[object, Any]] = PrivateAttr(default_factory=dict)

    def __getstate__(self) -> dict[Any, Any]:
        """Pickled without the derived results: a process that receives a spec or a report
        (check's drawing process, a batch or Dask worker) recomputes whatever it asks for —
        the figures ask for none of it — and the coupled models and their caches are most of
        the bytes (4 of 6 MB for the NREL 5-MW deck's report, 19 of 21 MB for the IEA-22's)."""
        state: dict[Any, Any] = super().__getstate__()
        private = dict(state.get("__pydantic_private__") or {})
        if "_derived" in private:
            private["_derived"] = {}
        return {**state, "__pydantic_private__": private}

    def derived(self, key: tuple[object, ...], source: object, make: Callable[[], Any]) -> Any:
        """A value computed once from the part ``source`` of this spec (``make`` is pure in
        it). The entry is kept only while ``source`` is the very object it was made from:
        a copy of the spec with another part (model_copy shares private state) recomputes."""
        found = self._derived.get(key)
        if found is None or found[0] is not source:
            found = (source, make())
            self._derived[key] = found
        return found[1]

    @property
    def source_file(self) -> str | None:
        """The file this spec was read from."""
        return self._source_file

    @property
    def source_sha256(self) -> str | None:
        """SHA-256 of the input as it was read (the files of a folder: of their hashes)."""
        return self._source_sha256

    def fingerprinted(self, sha256: str) -> "Spec":
        """This spec, marked with the hash of the input it came from."""
        self._source_sha256 = sha256
        return self

    @property
    def provenance(self) -> dict[str, Quantity]:
        """Provenance of each annotated value, by dotted field path."""
        return dict(self._provenance)
