"""The tower with its tower head: modes and the stiff / soft / soft-soft classification.

References
----------
Hau, *Wind Turbines*, ch. 7.5.1 (tower stiffness, Figs. 7.19 and 7.20) and 7.5.2.
"""

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

from .excitation import Excitation, OperatingRange
from .given import given_modes, ordinal
from .resonance import Finding, assess
from .results import Check, Mode, Rule
from .rules import MarginRule, Status
from .spec import Spec
from .units import rad_s_to_hz, rad_s_to_rpm

TowerClass = Literal["stiff", "soft", "soft-soft", "resonant"]

_KIND = {"fa": "fore-aft bending", "ss": "side-side bending", "tor": "torsion"}


def modes(spec: Spec) -> list[Mode]:
    """Tower modes given in the spec (ids ``tower.fa1``, ``tower.ss1``, ``tower.tor1`` …)."""

    def describe(name: str) -> str:
        kind, k = name.rstrip("0123456789"), int(name.lstrip("afsort"))
        return f"{ordinal(k)} tower {_KIND[kind]}"

    return given_modes("tower", spec.tower.modes, describe)


def first_bending(tower_modes: Sequence[Mode]) -> Mode | None:
    """The first bending mode that classifies the tower: fore-aft, else side-side."""
    by_id = {m.id: m for m in tower_modes}
    return by_id.get("tower.fa1") or by_id.get("tower.ss1")


@dataclass(frozen=True)
class Classification:
    """Where the first bending frequency sits among the rotor excitations."""

    tower_class: TowerClass
    frequency_hz: float
    findings: tuple[Finding, ...]


def classify(
    mode: Mode,
    harmonics: Sequence[Excitation],
    blades: int,
    op: OperatingRange,
    rule: MarginRule,
    default_damping: float,
) -> Classification:
    """Classify the tower by its first bending mode (Hau ch. 7.5.1).

    Notes
    -----
    *resonant*: a dominant (1P, N_b·P) excitation violates the margin in steady operation,
    or a secondary one (kP, 1 < k < N_b) at a dwell speed. Otherwise, at the highest
    steady speed: *stiff* above N_b·P, *soft-soft* below 1P, *soft* between them.
    """
    strong = [e for e in harmonics if e.energy != "minor" and e.order <= blades]
    # Judged with fixed severities so that a relaxed severity setting cannot hide a
    # resonance from the classification.
    judge: dict[str, Status] = {"dominant": "fail", "secondary": "fail", "minor": "info"}
    findings = tuple(assess(mode, e, op, rule, judge, default_damping) for e in strong)
    f_t = mode.frequency_hz
    top_1p = float(rad_s_to_hz(op.highest))
    if any(f.status == "fail" for f in findings):
        cls: TowerClass = "resonant"
    elif f_t > blades * top_1p:
        cls = "stiff"
    elif f_t < top_1p:
        cls = "soft-soft"
    else:
        cls = "soft"
    return Classification(cls, f_t, findings)


def class_check(c: Classification, blades: int, op: OperatingRange, rule: MarginRule) -> Check:
    """The ``tower.class`` check: stiff and soft pass, soft-soft warns, resonant fails."""
    top = float(rad_s_to_rpm(op.highest))
    p1 = float(rad_s_to_hz(op.highest))
    where = f"at {top:.3g} rpm: 1P = {p1:.3g} Hz, {blades}P = {blades * p1:.3g} Hz"
    head = f"first bending {c.frequency_hz:.3g} Hz"
    startup = sorted(
        {f.excitation.id for f in c.findings if f.violations["start-up"]},
        key=lambda s: float(s.rstrip("P")),
    )
    crossed = f"; {' and '.join(startup)} sweep through it at start-up" if startup else ""
    if c.tower_class == "resonant":
        hit = [f for f in c.findings if f.status == "fail"]
        names = ", ".join(f.excitation.id for f in hit)
        status, text = "fail", f"resonant: {head} within the margin of {names} ({where})"
    elif c.tower_class == "stiff":
        status, text = "pass", f"stiff: {head} above {blades}P ({where}); no start-up encounter"
    elif c.tower_class == "soft":
        band = _between(c.frequency_hz, blades, p1)
        status = "pass"
        text = f"soft: {head} {band} ({where}){crossed} — the encounter of soft towers"
    else:
        status = "warn"
        text = (
            f"soft-soft: {head} below 1P ({where}){crossed}; large tower-head amplitudes "
            "(WTS-4 experience, Hau 7.5.2)"
        )
    return Check(
        id="tower.class",
        subsystem="tower",
        status=status,  # type: ignore[arg-type]
        message=text,
        rule=Rule(
            f"stiff > {blades}P > soft > 1P > soft-soft; resonant within {rule.label}",
            "Hau, Wind Turbines, ch. 7.5.1 (Figs. 7.19, 7.20)",
        ),
        numbers={
            "tower_class": c.tower_class,
            "frequency_hz": c.frequency_hz,
            "p1_hz_at_max": round(p1, 6),
            "startup_crossings": startup,
        },
    )


def _between(f_t: float, blades: int, p1: float) -> str:
    k = int(f_t // p1)
    return f"between {k}P and {k + 1}P" if k >= 1 else "below 1P"
