"""The subsystem declaration: what every analysed part of a turbine gives the audit
(DESIGN.md).

A subsystem is a module that declares itself once, as its :data:`SUBSYSTEM`
(:class:`Subsystem`): its name, ``build_modes(spec, built)``, ``default_damping(spec)``,
``analyse(spec, context)``, and where it is optional the excitations that act on it alone,
its warnings, the spec section it reads, the Campbell diagram it is drawn on and the
figures that draw its results — so that the audit is a loop over the declarations plus the
one resonance judgement and the verdict, and a new subsystem is one module whose
declaration is added to :data:`wtvib.audit.SUBSYSTEMS` (``tests/test_analysis.py`` holds
every declared section, diagram and figure to exist):

1. ``build_modes`` computes (or takes as given) the natural modes, seeing the modes of the
   subsystems before it (``built``; the drive train takes the blades' edgewise frequency);
2. the audit marks the modes the coupled model supersedes, fills in default damping, lets
   each :class:`Modifier` (:data:`wtvib.audit.MODIFIERS`: the aerodynamic damping) change
   every mode, and judges every mode against every excitation (:mod:`wtvib.judge.resonance`);
3. ``analyse`` returns the subsystem's own checks and results, seeing every mode and the
   judgement of its own (:class:`Context`);
4. ``warnings(spec, modes)``, where a subsystem declares it, names the legal but suspicious
   values of its part (a tower's first bending at 0.01 Hz, a yaw model without the head's
   yaw inertia) for the report's warnings.
"""

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Protocol

if TYPE_CHECKING:
    from ..results import Check, Mode
    from ..rules import MarginRule
    from ..spec import AuditSettings, Spec
    from .excitation import Excitation, OperatingRange
    from .resonance import Finding


@dataclass(frozen=True)
class Context:
    """What an analysis sees: the operating range (rad/s), the excitation lines, the rule in
    force, every mode of the turbine (superseded ones marked) and the resonance judgement of
    the analysed subsystem (``findings``, ``resonance``)."""

    op: "OperatingRange"
    lines: "Sequence[Excitation]"
    rule: "MarginRule"
    settings: "AuditSettings"
    modes: "Sequence[Mode]"
    findings: "Sequence[Finding]" = ()
    resonance: "Sequence[Check]" = ()

    def own(self, subsystem: str) -> "list[Mode]":
        """The modes of one subsystem."""
        return [m for m in self.modes if m.subsystem == subsystem]


@dataclass(frozen=True)
class Analysis:
    """A subsystem's contribution to the report.

    ``lead`` checks go before the subsystem's resonance checks (the tower class), ``checks``
    after them; ``refine`` rewrites each of its resonance checks (the drive train adds the
    shaft-torque amplification); ``results`` is the subsystem's own typed result object,
    what its figures draw (``tower.TowerResults``, ``drivetrain.DrivetrainResults`` …;
    ``Report.result`` gives it back by type).
    """

    lead: "tuple[Check, ...]" = ()
    checks: "tuple[Check, ...]" = ()
    refine: "Callable[[Check], Check] | None" = None
    results: object | None = None
    assumptions: tuple[str, ...] = ()


@dataclass(frozen=True)
class Damping:
    """The damping ratio of a subsystem's modes that carry none of their own, and where it
    comes from (``assumed``: wtvib's default, not a value the spec gives)."""

    ratio: float
    source: str
    assumed: bool

    def with_dampers(
        self, zeta: float, floor: float, dampers: str
    ) -> tuple[float | None, str | None]:
        """A computed mode's damping ratio and its source: this (material) damping plus the
        ``zeta`` its ``dampers`` give it (the eigenvalue damping), which adds to it — a mode
        that barely moves a damper must not lose its material damping to the damper's
        tiny share. (None, None) where ``zeta`` is below ``floor``: the mode takes this
        damping as the default, and the audit states it as such."""
        if not zeta > floor:  # (a NaN too)
            return None, None
        return self.ratio + zeta, f"{self.source}, plus {zeta:.3g} from {dampers}"


def no_lines(spec: "Spec") -> "list[Excitation]":
    """``excitations`` of a subsystem that only the rotor's harmonics excite."""
    return []


@dataclass(frozen=True)
class Subsystem:
    """One subsystem, declared once (its module's ``SUBSYSTEM``).

    ``name`` is the subsystem of its modes and checks; ``build_modes`` gives its natural
    modes (``built``: the modes of the subsystems before it), ``default_damping`` the
    damping of the modes that carry none, ``analyse`` its own checks and results;
    ``excitations`` the lines that act on it alone (the drive train's gear mesh; the rotor's
    harmonics act on every subsystem); ``warnings`` names legal but suspicious values of its
    part; ``part`` is the spec section it reads (a :class:`wtvib.spec.Spec` field; None:
    it reads others'); ``diagram`` the Campbell diagram its modes are drawn on
    (:data:`DIAGRAMS`) and ``title`` its words there; ``figures`` the entries of
    :data:`wtvib.outputs.plots.FIGURES` that draw its results.
    """

    name: str
    build_modes: "Callable[[Spec, Mapping[str, list[Mode]]], list[Mode]]"
    default_damping: "Callable[[Spec], Damping]"
    analyse: "Callable[[Spec, Context], Analysis]"
    part: str | None = None
    excitations: "Callable[[Spec], list[Excitation]]" = no_lines
    warnings: "Callable[[Spec, Sequence[Mode]], list[str]] | None" = None
    diagram: str | None = None
    title: str = ""
    figures: tuple[str, ...] = ()


#: The Campbell diagrams by file stem suffix, in drawing order (a subsystem's ``diagram``).
DIAGRAMS = ("campbell", "campbell-drivetrain", "campbell-yaw", "campbell-system")


class Modifier(Protocol):
    """What changes every judged mode after the models are built — the aerodynamic damping at
    the operating points today, a foundation's or a platform's influence later: a module
    with ``modify``."""

    def modify(
        self, spec: "Spec", built: "Mapping[str, list[Mode]]", heavy: float
    ) -> "tuple[dict[str, list[Mode]], tuple[str, ...]]":
        """Every subsystem's modes, changed, and the statements the report makes about how
        (``heavy``: the damping ratio above which a mode has no resonant peak)."""
        ...


def section_damping(section: Any, name: str) -> Damping:
    """The ``damping_ratio`` of a spec section (``tower``, ``blade`` …): given, or the
    schema's default, which is then an assumption."""
    given = "damping_ratio" in section.model_fields_set
    source = f"{name}.damping_ratio (given)" if given else "assumed (no value given)"
    return Damping(float(section.damping_ratio), source, not given)


def no_modes(spec: "Spec", built: "Mapping[str, list[Mode]]") -> "list[Mode]":
    """``build_modes`` of an analysis that judges other subsystems' modes (it has none)."""
    return []
