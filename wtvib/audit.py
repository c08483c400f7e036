"""The only orchestrator: collect modes and checks, derive the verdict (DESIGN.md)."""

import functools
import math
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from typing import Any, TypeVar, cast

import numpy as np

from .aero import aerodamping, aeroelastic, stall, tuned_damper
from .document import (
    InputDoc,
    OperationDoc,
    ReportDoc,
    RuleSettingsDoc,
    TurbineDoc,
    UncertaintyDoc,
)
from .errors import SpecError
from .judge import campbell
from .judge.analysis import Analysis, Context, Damping, Modifier, Subsystem
from .judge.excitation import Excitation, OperatingRange, excitations, operating_range
from .judge.resonance import Finding, Mark, assess_all, resonance_checks
from .judge.resonance import marks as resonance_marks
from .numerics.modal import ModalError
from .results import Check, Mode, Sampled, Southwell
from .rules import MarginRule, Status, worst
from .spec import DEFAULT_OVERSPEED_FACTOR, AuditSettings, RotorSpeed, Spec
from .studies import scaling
from .subsystems import blade, coupled, drivetrain, polynomials, rotor, tower, yaw
from .subsystems.tower import is_platform_mode

REPORT_SCHEMA = "wtvib-report/1"

R = TypeVar("R")

#: The analysed parts of a turbine, in report order: each module's declaration
#: (:class:`wtvib.judge.analysis.Subsystem`: modes, default damping, its own checks and
#: results, the lines that act on it alone, its spec section, diagram and figures).
SUBSYSTEMS: tuple[Subsystem, ...] = tuple(
    module.SUBSYSTEM
    for module in (
        tower,
        blade,
        drivetrain,
        yaw,
        coupled,
        aerodamping,
        rotor,
        aeroelastic,
        stall,
        polynomials,
    )
)

#: What changes every judged mode once the models are built
#: (:class:`wtvib.judge.analysis.Modifier`),
#: in order: a blade tip damper's added damping (structural), then the aerodynamic damping
#: at the operating points (on top of the structural).
MODIFIERS: tuple[Modifier, ...] = (tuned_damper, aerodamping)


@dataclass(frozen=True)
class Report:
    """The result of an audit; ``to_dict()`` is the JSON contract ``wtvib-report/1``."""

    spec: Spec
    settings: AuditSettings
    modes: tuple[Mode, ...]
    checks: tuple[Check, ...]
    findings: tuple[Finding, ...] = field(default_factory=tuple)
    assumptions: tuple[str, ...] = field(default_factory=tuple)
    warnings: tuple[str, ...] = field(default_factory=tuple)
    uncertainty: UncertaintyDoc | None = None
    results: Mapping[str, object] = field(default_factory=dict)  # by subsystem (typed)
    lines: tuple[Excitation, ...] = ()  # the excitation lines judged (all_lines)

    def result(self, subsystem: str, kind: type[R]) -> R | None:
        """A subsystem's typed result object (``Analysis.results``), None where it gave none
        (a figure asks with the subsystem's NAME and result class)."""
        found = self.results.get(subsystem)
        return found if isinstance(found, kind) else None

    @property
    def tower_class(self) -> str | None:
        """stiff, soft, soft-soft or resonant (None: no tower classification)."""
        found = self.result(tower.NAME, tower.TowerResults)
        return found.classification.tower_class if found is not None else None

    @property
    def rule(self) -> MarginRule:
        return self.settings.margin_rule()

    @property
    def verdict(self) -> Status:
        """Worst check status; ``info`` counts as a pass."""
        w = worst([c.status for c in self.checks])
        return "pass" if w == "info" else w

    @functools.cached_property
    def operating_range(self) -> OperatingRange:
        """The rotor speeds judged, in rad/s."""
        return operating_range(self.spec.rotor.speed)

    @functools.cached_property
    def campbell(self) -> "campbell.Campbell":
        """The sampled curves of every judged mode (README: the JSON contract's
        ``campbell``)."""
        return campbell.build(self.modes, self.operating_range)

    @functools.cached_property
    def marks(self) -> tuple[Mark, ...]:
        """Every resonance the findings hold, one mark each (what the Campbell diagrams
        draw: :func:`wtvib.judge.resonance.marks`)."""
        return tuple(resonance_marks(self.findings, self.operating_range))

    @property
    def identity(self) -> str:
        """Which wtvib made the report from which input: one line for files that carry no
        JSON (the Campbell CSV)."""
        from . import __version__

        spec = self.spec
        digest = f", SHA-256 {spec.source_sha256}" if spec.source_sha256 else ""
        return f"produced by wtvib {__version__} from {spec.source_file or 'a spec'}{digest}"

    @property
    def damping_model(self) -> str:
        """How the judged modes were damped: ``imported`` (another tool's damping at its
        operating points, ``spec.results``), ``aeroelastic`` (some has damping at the
        operating points) or ``structural`` (given or assumed ratios only)."""
        damped = [m for m in self.modes if m.judged and m.operating]
        if any(m.origin == "imported" for m in damped):
            return "imported"
        return "aeroelastic" if damped else "structural"

    def to_dict(self) -> ReportDoc:
        """The JSON contract: every number finite — one that is not is written as null and
        named in ``warnings`` (strict JSON has no NaN or Infinity)."""
        nonfinite: list[str] = []
        doc: ReportDoc = _finite(self._document(), "", nonfinite)
        if nonfinite:
            doc["warnings"] = [
                *doc["warnings"],
                "numbers that came out infinite or undefined, written as null: "
                + ", ".join(nonfinite[:20])
                + (f" and {len(nonfinite) - 20} more" if len(nonfinite) > 20 else ""),
            ]
        return doc

    def _document(self) -> ReportDoc:
        spec = self.spec
        rule = self.rule
        from . import __version__

        rules: RuleSettingsDoc = {
            "kind": rule.kind,
            "margin": rule.margin,
            "preset": rule.preset,
            "source": rule.source,
            "harmonics": self.settings.harmonics,
            "severity": self.settings.severities(),
        }
        doc: dict[str, Any] = {  # in the contract's order, optional keys in their place
            "schema": REPORT_SCHEMA,
            "produced_by": {
                "tool": "wtvib",
                "version": __version__,
                "input": {"file": spec.source_file, "sha256": spec.source_sha256},
            },
            "turbine": _turbine(spec),
            "verdict": self.verdict,
            "tower_class": self.tower_class,
            "operation": _operation(spec.rotor.speed),
            "rule": rules,
            "damping": self.damping_model,
            "aerodynamics": spec.aerodynamics is not None,
        }
        if spec.results is not None:
            doc["results"] = {"tool": spec.results.tool, "files": list(spec.results.files)}
        doc["modes"] = [m.to_dict() for m in self.modes]
        doc["campbell"] = self.campbell.to_dict()
        doc["checks"] = [c.to_dict() for c in self.checks]
        doc["assumptions"] = list(self.assumptions)
        doc["warnings"] = list(self.warnings)
        if self.uncertainty is not None:
            doc["uncertainty"] = self.uncertainty
        doc["inputs"] = _inputs(spec)
        return cast(ReportDoc, doc)


def _turbine(spec: Spec) -> TurbineDoc:
    """The report's turbine: its name, the spec's identification, the rotor's layout."""
    given = spec.turbine.model_dump(exclude={"name"}, exclude_none=True)
    rotor = {"blades": spec.rotor.blades, "orientation": spec.rotor.orientation}
    doc = {"name": spec.turbine.name, "source_file": spec.source_file, **given, **rotor}
    return cast(TurbineDoc, {**doc, "hub": spec.rotor.hub})


def _operation(speed: RotorSpeed) -> OperationDoc:
    """The report's operating range (rpm)."""
    doc: OperationDoc = {
        "steady_rpm": [list(p) for p in speed.steady_rpm],
        "variable_speed": speed.fixed_rpm is None,
        "overspeed_rpm": round(speed.overspeed, 6),
        "quick_pass_rpm": [list(p) for p in speed.quick_pass_rpm],
    }
    if speed.parked:  # first, as the contract has it
        doc = {"parked": True, **doc}
    if speed.source:
        doc["source"] = speed.source
    return doc


def _inputs(spec: Spec) -> dict[str, InputDoc]:
    """Every input of the spec with its value, provenance and source, by field path."""
    out: dict[str, InputDoc] = {}
    for path, q in sorted(spec.provenance.items()):
        out[path] = {
            "value": q.value,
            "provenance": q.provenance,
            "source": spec.sources.get(q.source, q.source) if q.source else None,
        }
        if q.note:
            out[path]["note"] = q.note
    return out


def _finite(value: Any, path: str, bad: list[str]) -> Any:
    """``value`` with every non-finite float replaced by None, its path recorded."""
    if isinstance(value, float) and not math.isfinite(value):
        bad.append(path or "(top)")
        return None
    if isinstance(value, dict):
        return {k: _finite(v, f"{path}.{k}" if path else str(k), bad) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_finite(v, f"{path}[{i}]", bad) for i, v in enumerate(value)]
    return value


def override(
    base: AuditSettings,
    *,
    margin: float | None = None,
    rule: str | None = None,
    preset: str | None = None,
) -> AuditSettings:
    """Audit settings with command-line overrides on top of the spec's ``audit`` section."""

    update: dict[str, Any] = {}
    if preset is not None:
        update["preset"] = preset
    if rule is not None:
        update["rule"] = rule
    if margin is not None:
        if not (math.isfinite(margin) and 0 < margin < 1):
            raise SpecError(f"--margin must lie between 0 and 1 (0.10 = 10 %); got {margin:g}")
        update["margin"] = margin
    return base.model_validate({**base.model_dump(), **update}) if update else base


def run(
    spec: Spec,
    settings: AuditSettings | None = None,
    *,
    samples: int | None = None,
    seed: int = 0,
    client: Any = None,
) -> Report:
    """Audit a turbine: every subsystem's modes against every excitation, plus the class.

    Parameters
    ----------
    spec
        The validated turbine.
    settings
        Audit settings overriding the spec's own ``audit`` section.
    samples
        Monte Carlo samples of the spec's tolerances (``check --uncertainty``); none: skip.
    seed
        Seed of the Monte Carlo sampling (reproducible results).
    client
        A ``distributed.Client``: the samples drawn on its cluster (the same samples).
    """
    try:
        return _run(spec, settings or spec.audit, samples, seed, client)
    except (OverflowError, FloatingPointError, np.linalg.LinAlgError) as exc:
        raise ModalError(
            f"a number in the spec is too large or too small for the models ({exc}); check "
            "the magnitudes"
        ) from None


def all_lines(spec: Spec) -> list[Excitation]:
    """Every excitation line the audit judges: the rotor's harmonics and each subsystem's
    own (its declaration's ``excitations``)."""
    return excitations(spec, [e for sub in SUBSYSTEMS for e in sub.excitations(spec)])


def _run(
    spec: Spec, settings: AuditSettings, samples: int | None, seed: int, client: Any
) -> Report:
    rule = settings.margin_rule()
    op = operating_range(spec.rotor.speed)
    lines = all_lines(spec)
    built: dict[str, list[Mode]] = {}
    for sub in SUBSYSTEMS:
        try:
            built[sub.name] = sub.build_modes(spec, built)
        except ModalError as exc:  # say which model could not be solved
            raise ModalError(f"{sub.name} model: {exc}") from None
    damping = {sub.name: sub.default_damping(spec) for sub in SUBSYSTEMS}
    built = _one_truth_per_mode(built, damping)
    assumptions: list[str] = []
    for modifier in MODIFIERS:  # the aerodynamics damp every judged mode in operation
        built, notes = modifier.modify(spec, built, settings.heavy_damping_ratio)
        assumptions += notes
    all_modes = [m for ms in built.values() for m in ms]
    checks: list[Check] = []
    findings: list[Finding] = []
    results: dict[str, object] = {}
    for sub in SUBSYSTEMS:
        found = assess_all(
            built[sub.name],
            lines,
            op,
            rule,
            settings.severities(),
            damping[sub.name].ratio,
            settings.heavy_damping_ratio,
        )
        resonance = resonance_checks(found, op, rule)
        ctx = Context(op, lines, rule, settings, tuple(all_modes), tuple(found), tuple(resonance))
        analysis: Analysis = sub.analyse(spec, ctx)
        if analysis.refine is not None:
            resonance = [analysis.refine(c) for c in resonance]
        findings += found
        checks += [*analysis.lead, *resonance, *analysis.checks]
        if analysis.results is not None:
            results[sub.name] = analysis.results
        assumptions += analysis.assumptions
    _assert_finite(all_modes)
    if not any(f.mode.judged for f in findings) and not spec.rotor.speed.parked:
        # a verdict on nothing is no pass (every mode in no operating regime, or none)
        raise SpecError(
            f"no natural frequency to judge: of {len(all_modes)} mode(s), none exists in an "
            "operating regime the audit judges — give the modes (or the structure they come "
            "from) that a verdict could rest on",
            source=spec.source_file,
        )
    spread = _uncertainty(spec, samples, seed, all_modes, rule, lines, client) if samples else None
    return Report(
        spec=spec,
        settings=settings,
        modes=tuple(all_modes),
        checks=tuple(checks),
        findings=tuple(findings),
        assumptions=tuple(_assumptions(spec, rule, all_modes, assumptions, damping)),
        # a warning said once, however many parts found it
        warnings=tuple(
            dict.fromkeys(
                suspicious(spec, all_modes)
                + _no_tolerance(spec, samples)
                + _uncertainty_warnings(spread)
            )
        ),
        uncertainty=spread,
        results=results,
        lines=tuple(lines),
    )


def _one_truth_per_mode(
    built: dict[str, list[Mode]], damping: Mapping[str, Damping]
) -> dict[str, list[Mode]]:
    """Mark the isolated modes a coupled mode stands for (``replaces``: shown, not judged;
    the first coupled mode of each wins) and give every mode without its own damping its
    subsystem's default, saying where it came from."""
    present = {m.id: m for ms in built.values() for m in ms}
    replaced: dict[str, str] = {}
    for ms in built.values():
        for m in ms:
            if m.replaces in present and m.replaces not in replaced:
                replaced[m.replaces] = m.id
    stands_for = {v: present[k] for k, v in replaced.items()}
    out = {}
    for sub in SUBSYSTEMS:
        own = damping[sub.name]
        out[sub.name] = [
            replace(
                m,
                superseded_by=replaced.get(m.id),
                damping_ratio=own.ratio if m.damping_ratio is None else m.damping_ratio,
                damping_source=own.source if m.damping_ratio is None else m.damping_source,
                band_hz=m.band_hz or _band_of(m, stands_for.get(m.id)),
            )
            for m in built[sub.name]
        ]
    return out


def _band_of(mode: Mode, isolated: Mode | None) -> tuple[float, float] | None:
    """A coupled mode's soil band: its isolated counterpart's, as factors (the coupled
    model is solved with the nominal soil only; stated where it is used)."""
    factors = isolated.band_factors() if isolated is not None else None
    if factors is None:
        return None
    return mode.frequency_hz * factors[0], mode.frequency_hz * factors[1]


def _no_tolerance(spec: Spec, samples: int | None) -> list[str]:
    if not samples:  # no study asked: its module stays unimported
        return []
    from .studies import uncertainty

    return [] if uncertainty.uncertain(spec) else [uncertainty.NO_TOLERANCE]


def _uncertainty_warnings(spread: UncertaintyDoc | None) -> list[str]:
    if not spread:  # no study: its module (and numpy.random) stays unimported
        return []
    from .studies import uncertainty

    return uncertainty.warnings_of(spread)


def _uncertainty(
    spec: Spec,
    samples: int,
    seed: int,
    modes: list[Mode],
    rule: MarginRule,
    lines: list[Excitation],
    client: Any = None,
) -> UncertaintyDoc | None:
    from .studies import uncertainty

    if not uncertainty.uncertain(spec):
        return None  # said in the warnings
    nominal = uncertainty.nominal_of(spec, modes)
    drawn = (
        uncertainty.sample(spec, samples, seed, nominal=nominal)
        if client is None
        else uncertainty.sample_distributed(spec, samples, seed, client, nominal=nominal)
    )
    out = uncertainty.summary(spec, drawn, modes, rule, lines)
    out["seed"] = seed
    out["sensitivities"] = uncertainty.sensitivities(spec, nominal)
    return cast(UncertaintyDoc, out)


def _assert_finite(modes: list[Mode]) -> None:
    """Every reported frequency is finite and non-negative (the report boundary)."""
    for m in modes:
        if not (math.isfinite(m.frequency_hz) and m.frequency_hz >= 0):
            raise ModalError(
                f"mode {m.id} came out with frequency {m.frequency_hz}: the model "
                "is ill-conditioned; check its stiffnesses and masses"
            )


#: A lowest steady speed under this fraction of the highest is suspicious (wtvib's bound;
#: the reference turbines' ranges: NREL 5-MW 6.9/12.1, IEA-15 5/7.56, IEA-3.4 3.8/11.75 —
#: and the NREL deck's DISCON minimum 3.41/12.1 = 0.28).
SLOW_RANGE = 0.15

#: Any other mode below this [Hz] is suspicious: the slowest modes of the catalogue and the
#: reference turbines are the IEA-22 windIO example's coupled tower (0.126 Hz) and, outside
#: the tower, Growian's drive train with the rotor locked (0.188 Hz).
SLOWEST_MODE_HZ = 0.01
#: A floating platform's rigid-body mode below this [Hz] (a period over 500 s) is
#: suspicious: the slowest are surge and sway on slack catenary moorings, 0.008 Hz for the
#: OC3-Hywind spar (Jonkman 2010, NREL/TP-500-47535), a period of 125 s.
SLOWEST_PLATFORM_HZ = 0.002
#: Any mode above this [Hz] is suspicious: the fastest of the catalogue and the reference
#: turbines is the Aeroman's second gear-mesh mode (470 Hz). A stiffness typed far too large
#: lands here — and where it spans more orders of magnitude than double precision resolves,
#: the model's slow modes beside it are rounding (modal.ROUNDING).
FASTEST_MODE_HZ = 1e4

#: Rated power per swept area outside this band [W/m²] is suspicious (wtvib's bounds around
#: the catalogue's 88 (MOD-0) to 837 W/m² (WTS-4) and the reference turbines' 330–400:
#: NREL 5-MW 401, IEA-15 332, IEA-22 347).
POWER_DENSITY = (40.0, 1500.0)

#: A horizontal-axis rotor of 30 m or more whose top steady tip speed is under this [m/s]
#: is suspicious (wtvib's bound, well below the reference turbines' rated tip speeds: NREL
#: 5-MW 80 m/s, IEA-3.4 80, IEA-10 90, IEA-15 95, IEA-22 105 — rated rpm × radius).
SLOW_TIP = 40.0


def suspicious(spec: Spec, modes: list[Mode]) -> list[str]:
    """Legal but suspicious inputs, each with the reason (warn, do not refuse), and
    what an importer had to assume."""
    out = list(spec.warnings)
    speed = spec.rotor.speed
    diameter = spec.turbine.rotor_diameter_m
    if diameter and diameter > 40 and speed.top_rpm > 100:
        out.append(
            f"rotor.speed: {speed.top_rpm:g} rpm for a {diameter:g} m rotor — probably "
            "rad/s or the generator speed, not the rotor's rpm"
        )
    if diameter and not speed.parked:
        tip = math.pi * diameter * speed.top_rpm / 60
        if tip > 120:
            out.append(f"rotor.speed: tip speed {tip:.0f} m/s exceeds 120 m/s — unusual")
        elif tip < SLOW_TIP and diameter >= 30 and spec.rotor.orientation != "vertical-axis":
            out.append(
                f"rotor.speed: tip speed {tip:.0f} m/s at the top steady speed "
                f"({speed.top_rpm:g} rpm, {diameter:g} m rotor) is under {SLOW_TIP:g} m/s — "
                "slow for a rotor this size (the reference turbines run 80–105 m/s at "
                "rated); check the speed range and where it came from"
            )
    low = speed.steady_rpm[0][0]
    if diameter and diameter > 20 and 0 < low < SLOW_RANGE * speed.top_rpm:
        out.append(
            f"rotor.speed: the lowest steady speed {low:g} rpm is under {SLOW_RANGE:.0%} of "
            f"the highest ({speed.top_rpm:g} rpm) — rad/s typed as rpm? (variable-speed "
            "rotors run down to 30–70 % of rated)"
        )
    if speed.overspeed > 1.5 * speed.top_rpm:
        out.append(
            f"rotor.speed: overspeed {speed.overspeed:g} rpm is more than 150 % of the "
            "highest steady speed"
        )
    own: list[str] = []  # each subsystem's own warnings about its part
    for sub in SUBSYSTEMS:
        if sub.warnings is not None:
            own += sub.warnings(spec, modes)
    out += own
    for m in modes:
        slowest = SLOWEST_PLATFORM_HZ if is_platform_mode(m.id) else SLOWEST_MODE_HZ
        if any(w.startswith(f"{m.id}:") for w in own):
            continue  # its subsystem said it, with its own bounds
        if m.frequency_hz > FASTEST_MODE_HZ:
            out.append(
                f"{m.id}: {m.frequency_hz:.3g} Hz — a natural frequency over "
                f"{FASTEST_MODE_HZ:g} Hz is implausible for a wind turbine's structure (a "
                "stiffness typed far too large? units?); the slow modes of the same model lose "
                "precision beside it"
            )
        elif m.frequency_hz < slowest:
            out.append(
                f"{m.id}: {m.frequency_hz:.3g} Hz — a natural frequency under "
                f"{slowest:g} Hz (a period over {1 / slowest:.0f} s) is "
                "implausible for a wind turbine's structure (units? a typing slip?)"
            )
    out += _spikes(spec)
    far = scaling.head_warning(spec)
    if far:
        out.append(far)
    power = scaling.rated_power_kw(spec)
    if diameter and power and spec.rotor.orientation != "vertical-axis":
        density = power * 1e3 / (math.pi * diameter**2 / 4)
        if not POWER_DENSITY[0] <= density <= POWER_DENSITY[1]:
            out.append(
                f"turbine.rated_power_kw: {power:,.4g} kW on a {diameter:g} m rotor is "
                f"{density:,.3g} W/m² of swept area, outside {POWER_DENSITY[0]:g}–"
                f"{POWER_DENSITY[1]:g} W/m² — check the unit (kW) and the diameter"
            )
    head, blades = spec.tower_head, spec.blade.mass_kg
    if head and blades and blades * spec.rotor.blades > 0.9 * head.mass_kg:
        out.append(
            f"blade.mass_kg: {spec.rotor.blades} blades of {blades:,.0f} kg outweigh the "
            f"rest of the tower head ({head.mass_kg:,.0f} kg in all) — check the masses"
        )
    return out


#: A station of a distributed property this many times above or below both its neighbours
#: is suspicious (an exponent typed wrong: 2.9E-09 for 2.9E+11): the sharpest such step in
#: the reference turbines' tower and blade tables is 1.34 (the IEA-22's flapwise stiffness).
SPIKE = 100.0


def _spikes(spec: Spec) -> list[str]:
    """A tower or blade table's station far above or below both its neighbours."""
    tables: list[tuple[str, Any, str, str]] = []
    if spec.tower.distributed is not None:
        tables.append(("tower.distributed", spec.tower.distributed, "height_m", "m"))
    if spec.tower.sections is not None:
        tables.append(("tower.sections", spec.tower.sections, "height_m", "m"))
    if spec.blade.structure is not None:
        tables.append(("blade.structure", spec.blade.structure, "span_m", "m from the root"))
    out = []
    for where, table, axis, unit in tables:
        at = getattr(table, axis)
        for name, values in table:
            if name == axis or not isinstance(values, list) or len(values) < 3:
                continue
            v = np.abs(np.asarray(values, dtype=float))
            a, b, c = v[:-2], v[1:-1], v[2:]
            with np.errstate(divide="ignore", invalid="ignore"):
                step = np.maximum(np.minimum(b / a, b / c), np.minimum(a / b, c / b))
            rows = getattr(table, "rows", None)
            for i in np.flatnonzero(step >= SPIKE)[:3] + 1:
                way = "above" if v[i] > v[i - 1] else "below"
                # an imported table's station by its file, line and column
                said = (
                    f"{rows.file}:{rows.lines[i]}: {rows.columns.get(name, name)}"
                    if rows is not None and i < len(rows.lines)
                    else f"{where}.{name}[{i}]"
                )
                out.append(
                    f"{said}: {values[i]:.4g} at {at[i]:g} {unit} is "
                    f"{float(step[i - 1]):.3g} times {way} both its neighbours' — an exponent "
                    "typed wrong?"
                )
    return out


def _assumptions(
    spec: Spec,
    rule: MarginRule,
    modes: list[Mode],
    statements: list[str],
    damping: Mapping[str, Damping],
) -> list[str]:
    out = [f"Margin rule: {rule.label} — {rule.source}."]
    speed = spec.rotor.speed
    if speed.overspeed_rpm is None and speed.overspeed_factor is None and not speed.parked:
        out.append(
            f"No overspeed given: a transient overspeed of {DEFAULT_OVERSPEED_FACTOR:.0%} of "
            f"the highest steady speed ({speed.overspeed:.4g} rpm) is checked."
        )
    for sub in SUBSYSTEMS:
        own = damping[sub.name]
        mine = [m for m in modes if m.subsystem == sub.name and m.damping_source]
        alone = [m.id for m in mine if m.damping_ratio == own.ratio]
        added = [m.id for m in mine if m.damping_ratio != own.ratio]
        if mine and own.assumed:  # an assumption is stated only when it was made
            parts = [f"for {', '.join(alone)}"] if alone else []
            if added:
                parts.append(f"added to what the dampers give for {', '.join(added)}")
            out.append(
                f"{sub.name}: damping ratio {own.ratio:.3g} {own.source} {'; '.join(parts)}."
            )
    stiffened = [m.id for m in modes if isinstance(m.curve, Southwell)]
    if stiffened:
        out.append(
            "Blade frequencies are standstill values raised by rotation with "
            "f² = f₀² + K·(Ω/2π)² (Southwell); K = 1.19 flap / 0.19 edge unless given: "
            + ", ".join(stiffened)
            + "."
        )
    tabled = [m.id for m in modes if m.origin == "given" and isinstance(m.curve, Sampled)]
    if tabled:
        out.append(
            "Frequencies over rotor speed as tabulated in the spec (speeds: linear between "
            f"the points, the last value held beyond them): {', '.join(tabled)}."
        )
    out += statements  # how each subsystem's modes came about
    given = sorted({m.subsystem for m in modes if m.origin == "given"})
    if given:
        out.append(f"Natural frequencies taken as given in the spec: {', '.join(given)}.")
    out += spec.assumptions
    tuned = sorted(path for path, q in spec.provenance.items() if q.provenance == "tuned")
    if tuned:
        out.append(
            "Tuned to the source's statements (provenance tuned): "
            + ", ".join(tuned[:8])
            + (f" and {len(tuned) - 8} more" if len(tuned) > 8 else "")
            + " — set so that the audit reproduces what the source says; where the audit "
            "then agrees with those statements, that agreement is built in, no validation."
        )
    if spec.rotor.orientation == "vertical-axis":
        out.append(
            "Vertical-axis rotor: no stiff/soft tower classification; resonance checks "
            "against per-rev excitations only. Not judged: its own excitation — the blades' "
            "free-stream velocity and angle of attack oscillate over each turn (Hau 7.5.2, "
            "Fig. 7.28), loading the symmetric and antisymmetric in-plane modes of a "
            "two-bladed rotor in ways the per-rev lines stand in for, not model."
        )
    return out
