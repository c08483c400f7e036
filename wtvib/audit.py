"""The only orchestrator: collect modes and checks, derive the verdict (DESIGN.md)."""

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any

from . import aeroelastic, blade, coupled, drivetrain, floquet, stall, tower, yaw
from .excitation import excitations, operating_range
from .modal import ModalError
from .resonance import Finding, assess_all, resonance_checks
from .results import Check, Mode, Southwell
from .rules import MarginRule, Status, worst
from .spec import DEFAULT_OVERSPEED_FACTOR, AuditSettings, Spec

REPORT_SCHEMA = "wtvib-report/1"

Built = dict[str, list[Mode]]

#: Subsystems in report order: name, mode builder (given the modes built so far), default
#: damping ratio of the section (a mode without its own ζ is judged with it).
SUBSYSTEMS: tuple[tuple[str, Callable[[Spec, Built], list[Mode]], Callable[[Spec], float]], ...] = (
    ("tower", lambda s, b: tower.modes(s), lambda s: s.tower.damping_ratio),
    ("blade", lambda s, b: blade.modes(s), lambda s: s.blade.damping_ratio),
    (
        "drivetrain",
        lambda s, b: drivetrain.modes(s, b["blade"]),
        lambda s: s.drivetrain.damping_ratio,
    ),
    ("yaw", lambda s, b: yaw.modes(s), lambda s: s.yaw.damping_ratio),
    (
        "system",
        lambda s, b: coupled.modes(s),
        lambda s: min(s.tower.damping_ratio, s.blade.damping_ratio),
    ),
)


@dataclass(frozen=True)
class Report:
    """The result of an audit; ``to_dict()`` is the JSON contract ``wtvib-report/1``."""

    spec: Spec
    settings: AuditSettings
    modes: tuple[Mode, ...]
    checks: tuple[Check, ...]
    tower_class: str | None
    findings: tuple[Finding, ...] = field(default_factory=tuple)
    assumptions: tuple[str, ...] = field(default_factory=tuple)
    warnings: tuple[str, ...] = field(default_factory=tuple)
    uncertainty: dict[str, Any] | None = None

    @property
    def rule(self) -> MarginRule:
        return self.settings.margin_rule()

    @property
    def verdict(self) -> Status:
        """Worst check status; ``info`` counts as a pass."""
        w = worst([c.status for c in self.checks])
        return "pass" if w == "info" else w

    def to_dict(self) -> dict[str, Any]:
        spec = self.spec
        speed = spec.rotor.speed
        rule = self.rule
        return {
            "schema": REPORT_SCHEMA,
            "turbine": {
                "name": spec.turbine.name,
                "source_file": spec.source_file,
                **spec.turbine.model_dump(exclude={"name"}, exclude_none=True),
                "blades": spec.rotor.blades,
                "orientation": spec.rotor.orientation,
                "hub": spec.rotor.hub,
            },
            "verdict": self.verdict,
            "tower_class": self.tower_class,
            "operation": {
                "steady_rpm": [list(p) for p in speed.steady_rpm],
                "variable_speed": speed.fixed_rpm is None,
                "overspeed_rpm": round(speed.overspeed, 6),
                "quick_pass_rpm": [list(p) for p in speed.quick_pass_rpm],
            },
            "rule": {
                "kind": rule.kind,
                "margin": rule.margin,
                "preset": rule.preset,
                "source": rule.source,
                "harmonics": self.settings.harmonics,
                "severity": self.settings.severities(),
            },
            "modes": [m.to_dict() for m in self.modes],
            "checks": [c.to_dict() for c in self.checks],
            "assumptions": list(self.assumptions),
            "warnings": list(self.warnings),
            **({"uncertainty": self.uncertainty} if self.uncertainty is not None else {}),
            "inputs": {
                path: {
                    "value": q.value,
                    "provenance": q.provenance,
                    "source": spec.sources.get(q.source, q.source) if q.source else None,
                    **({"note": q.note} if q.note else {}),
                }
                for path, q in sorted(spec.provenance.items())
            },
        }


def override(
    base: AuditSettings,
    *,
    margin: float | None = None,
    rule: str | None = None,
    preset: str | None = None,
) -> AuditSettings:
    """Audit settings with command-line overrides on top of the spec's ``audit`` section."""
    from .errors import SpecError

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
    """
    try:
        return _run(spec, settings or spec.audit, samples, seed)
    except (OverflowError, FloatingPointError) as exc:
        raise ModalError(
            f"a number in the spec is too large for the models ({exc}); check the magnitudes"
        ) from None


def _run(spec: Spec, settings: AuditSettings, samples: int | None, seed: int) -> Report:
    rule = settings.margin_rule()
    op = operating_range(spec.rotor.speed)
    lines = excitations(spec)
    built: Built = {}
    for name, build, _ in SUBSYSTEMS:
        built[name] = build(spec, built)
    # one truth per mode: isolated modes the coupled model has are shown, not judged
    replaced = coupled.superseded(
        built["system"], [m for n, ms in built.items() if n != "system" for m in ms], spec
    )
    for name in built:
        built[name] = [
            replace(m, superseded_by=replaced[m.id]) if m.id in replaced else m for m in built[name]
        ]
    for name, _, damping in SUBSYSTEMS:  # each mode carries the ζ it is judged with
        source = _damping_source(spec, name)
        built[name] = [
            replace(m, damping_ratio=damping(spec), damping_source=source)
            if m.damping_ratio is None
            else m
            for m in built[name]
        ]
    all_modes = [m for ms in built.values() for m in ms]
    checks: list[Check] = []
    findings: list[Finding] = []
    tower_class = None
    for name, _, damping in SUBSYSTEMS:
        sub_modes = built[name]
        if name == "tower" and spec.rotor.orientation != "vertical-axis":
            first = tower.first_bending(sub_modes)
            if first is not None and first.superseded_by is not None:
                first = next(m for m in all_modes if m.id == first.superseded_by)
            if first is not None:
                harmonics = [e for e in lines if e.acts_on("tower")]
                c = tower.classify(first, harmonics, spec.rotor.blades, op, rule, damping(spec))
                tower_class = c.tower_class
                checks.append(tower.class_check(c, spec.rotor.blades, op, rule))
        found = assess_all(
            sub_modes,
            lines,
            op,
            rule,
            settings.severities(),
            damping(spec),
            settings.heavy_damping_ratio,
        )
        findings += found
        checks += resonance_checks(found, op, rule)
        if name == "yaw":
            checks += yaw.checks(spec, op, rule, lines)
        if name == "drivetrain":
            checks = drivetrain.annotate(spec, built["blade"], checks)
            power = drivetrain.power_check(spec, op, rule, lines, settings.heavy_damping_ratio)
            checks += [power] if power else []
    for extra in (coupled.check(spec, all_modes), coupled.stability_check(spec)):
        checks += [extra] if extra else []
    floquet_check, _ = floquet.check(spec, all_modes)
    checks.append(floquet_check)
    checks += aeroelastic.checks(spec, all_modes)[0]
    checks += stall.checks(spec, all_modes)
    _assert_finite(all_modes)
    return Report(
        spec=spec,
        settings=settings,
        modes=tuple(all_modes),
        checks=tuple(checks),
        tower_class=tower_class,
        findings=tuple(findings),
        assumptions=tuple(_assumptions(spec, rule, all_modes)),
        warnings=tuple(suspicious(spec, all_modes) + _no_tolerance(spec, samples)),
        uncertainty=_uncertainty(spec, samples, seed, all_modes, rule) if samples else None,
    )


def _no_tolerance(spec: Spec, samples: int | None) -> list[str]:
    from . import uncertainty

    return [uncertainty.NO_TOLERANCE] if samples and not uncertainty.uncertain(spec) else []


def _uncertainty(
    spec: Spec, samples: int, seed: int, modes: list[Mode], rule: MarginRule
) -> dict[str, Any] | None:
    from . import uncertainty

    if not uncertainty.uncertain(spec):
        return None  # said in the warnings
    drawn = uncertainty.sample(spec, samples, seed)
    out = uncertainty.summary(spec, drawn, modes, rule)
    out["seed"] = seed
    out["sensitivities"] = uncertainty.sensitivities(spec)
    return out


def _assert_finite(modes: list[Mode]) -> None:
    """Every reported frequency is finite and non-negative (the report boundary)."""
    for m in modes:
        if not (math.isfinite(m.frequency_hz) and m.frequency_hz >= 0):
            raise ModalError(
                f"mode {m.id} came out with frequency {m.frequency_hz}: the model "
                "is ill-conditioned; check its stiffnesses and masses"
            )


def suspicious(spec: Spec, modes: list[Mode]) -> list[str]:
    """Legal but suspicious inputs, each with the reason (issue 9: warn, do not refuse), and
    what an importer had to assume."""
    out = list(spec.warnings)
    speed = spec.rotor.speed
    diameter = spec.turbine.rotor_diameter_m
    if diameter and diameter > 40 and speed.top_rpm > 100:
        out.append(
            f"rotor.speed: {speed.top_rpm:g} rpm for a {diameter:g} m rotor — probably "
            "rad/s or the generator speed, not the rotor's rpm"
        )
    if diameter:
        tip = math.pi * diameter * speed.top_rpm / 60
        if tip > 120:
            out.append(f"rotor.speed: tip speed {tip:.0f} m/s exceeds 120 m/s — unusual")
    if speed.overspeed > 1.5 * speed.top_rpm:
        out.append(
            f"rotor.speed: overspeed {speed.overspeed:g} rpm is more than 150 % of the "
            "highest steady speed"
        )
    for m in modes:
        if m.subsystem == "tower" and m.id.endswith(("fa1", "ss1")):
            if m.frequency_hz > 20:
                out.append(
                    f"{m.id}: {m.frequency_hz:.3g} Hz — a first tower bending frequency "
                    "over 20 Hz is implausible (units? kHz, rad/s?)"
                )
            elif m.frequency_hz < 0.05:
                out.append(
                    f"{m.id}: {m.frequency_hz:.3g} Hz — a first tower bending frequency "
                    "under 0.05 Hz is implausible"
                )
    out += _missing_yaw_inertia(spec, modes)
    head, blades = spec.tower_head, spec.blade.mass_kg
    if head and blades and blades * spec.rotor.blades > 0.9 * head.mass_kg:
        out.append(
            f"blade.mass_kg: {spec.rotor.blades} blades of {blades:,.0f} kg outweigh the "
            f"rest of the tower head ({head.mass_kg:,.0f} kg in all) — check the masses"
        )
    return out


def _damping_source(spec: Spec, subsystem: str) -> str:
    """Where a subsystem's default damping ratio comes from: the spec, or wtvib's default."""
    keys = ("tower", "blade") if subsystem == "system" else (subsystem,)
    given = [k for k in keys if "damping_ratio" in getattr(spec, k).model_fields_set]
    if subsystem == "system":
        where = "the lower of tower.damping_ratio and blade.damping_ratio"
        return f"{where} ({'given' if len(given) == 2 else 'assumed: not all given'})"
    return f"{subsystem}.damping_ratio (given)" if given else "assumed (no value given)"


def _missing_yaw_inertia(spec: Spec, modes: list[Mode]) -> list[str]:
    """A yaw model on a tower head without a yaw inertia: the frequency can be off by a factor.

    The rotor alone has the inertia J_p/2 about a diameter (a planar body: J_x = J_y + J_z,
    J_y = J_z), a lower bound of the head's yaw inertia; the yaw frequency scales with
    1/√J.
    """
    head = spec.tower_head
    first = next((m for m in modes if m.id == "yaw.1"), None)
    if (
        first is None
        or head is None
        or spec.yaw.inertia_kgm2 is not None
        or "inertia_yaw_kgm2" in head.model_fields_set
    ):
        return []
    used = head.inertia_yaw_kgm2 + head.mass_kg * head.cm_downwind_m**2
    j_p = yaw.rotor_polar_inertia(spec)
    text = (
        f"tower_head.inertia_yaw_kgm2: not given, so the yaw model uses {used:.3g} kg·m² (the "
        f"head's mass at its CM offset only) and yaw.1 comes out at {first.frequency_hz:.3g} Hz"
    )
    if j_p and j_p / 2 > used:
        estimate = first.frequency_hz * math.sqrt(max(used, 1e-9) / (used + j_p / 2))
        text += (
            f"; the rotor alone adds J_p/2 = {j_p / 2:.3g} kg·m², which would put it near "
            f"{estimate:.3g} Hz"
        )
    return [text + " — give the head's yaw inertia"]


def _assumptions(spec: Spec, rule: MarginRule, modes: list[Mode]) -> list[str]:
    out = [f"Margin rule: {rule.label} — {rule.source}."]
    speed = spec.rotor.speed
    if speed.overspeed_rpm is None and speed.overspeed_factor is None:
        out.append(
            f"No overspeed given: a transient overspeed of {DEFAULT_OVERSPEED_FACTOR:.0%} of "
            f"the highest steady speed ({speed.overspeed:.3g} rpm) is checked."
        )
    for name, _, damping in SUBSYSTEMS:
        ids = [m.id for m in modes if m.subsystem == name and m.damping_source]
        source = _damping_source(spec, name)
        if ids and "assumed" in source:  # an assumption is stated only when it was made
            out.append(f"{name}: damping ratio {damping(spec):.3g} {source} for {', '.join(ids)}.")
    stiffened = [m.id for m in modes if isinstance(m.curve, Southwell)]
    if stiffened:
        out.append(
            "Blade frequencies are standstill values raised by rotation with "
            "f² = f₀² + K·(Ω/2π)² (Southwell); K = 1.19 flap / 0.19 edge unless given: "
            + ", ".join(stiffened)
            + "."
        )
    out += _model_statements(spec, modes)
    out += spec.assumptions
    if spec.rotor.orientation == "vertical-axis":
        out.append(
            "Vertical-axis rotor: no stiff/soft tower classification; resonance "
            "checks against per-rev excitations only."
        )
    return out


def _model_statements(spec: Spec, modes: list[Mode]) -> list[str]:
    """Say which frequencies were computed, how, and which were taken as given."""
    out = []
    t = spec.tower
    if t.has_structure:
        kind = "tapered tube sections" if t.sections is not None else "distributed properties"
        head = spec.tower_head
        head_text = (
            f"tower head {head.mass_kg:,.0f} kg as a rigid body (CM {head.cm_downwind_m:+.2f} m "
            f"downwind, {head.cm_above_top_m:+.2f} m above the top)"
            if head
            else "no tower head given (bare tower)"
        )
        base = (
            "clamped base"
            if t.foundation.kind == "clamped"
            else f"base on springs (lateral {t.foundation.lateral_n_m or '—'} N/m, rocking "
            f"{t.foundation.rocking_nm_rad or '—'} N·m/rad)"
        )
        out.append(
            f"Tower modes computed: Euler–Bernoulli beam, {tower.DEFAULT_ELEMENTS} elements, from "
            f"{kind}; {head_text}; foundation: {base}; gravity "
            f"{'included' if t.gravity else 'not included'}."
        )
    if spec.blade.structure is not None:
        out.append(
            "Blade modes computed: cantilevered twisted beam, flap–edge coupled, with centrifugal "
            f"stiffening and in-plane softening at {blade.SPEED_SAMPLES} speeds, followed by MAC."
        )
    if coupled.applies(spec):
        out.append(
            "Coupled whole-turbine modes (system.*): tower, nacelle, drive train and "
            f"{spec.rotor.blades} flexible blades in one model (Lagrange, multi-blade "
            "coordinates); shaft tilt, precone, blade torsion, gravity on the blades and "
            "all damping but the drive train's neglected."
        )
    given = sorted(
        {
            m.subsystem
            for m in modes
            if "(computed)" not in m.description and "(coupled" not in m.description
        }
    )
    if given:
        out.append(f"Natural frequencies taken as given in the spec: {', '.join(given)}.")
    return out
