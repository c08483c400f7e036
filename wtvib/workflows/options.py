"""What the commands are asked besides their inputs, as the library takes it: how a file is
read and judged (:class:`Options`), the operating range given as text (``--rpm 6.9:12.1``)
and the uncertainty study's samples — each checked here, a mistake one line naming the
option (:class:`wtvib.errors.OptionError`, exit 2)."""

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import OptionError
from ..importers import ReadOptions

#: The samples of an uncertainty study where the user gives none.
DEFAULT_SAMPLES = 2000


@dataclass(frozen=True)
class Options:
    """What ``check``, ``report`` and ``batch`` share: how a file is read (``read``: the
    import options, :class:`~wtvib.importers.ReadOptions`), the audit overrides ``margin``,
    ``rule``, ``preset``, and the uncertainty study (``samples``, ``seed``)."""

    read: ReadOptions = field(default_factory=ReadOptions)
    margin: float | None = None
    rule: str | None = None
    preset: str | None = None
    samples: int | None = None  # Monte Carlo samples of the spec's tolerances (None: none)
    seed: int = 0

    def tag(self, uncertainty: bool = False) -> str:
        """What the options change in the figures, for their file names: ``.gl2010``,
        ``.margin15``, ``.ratio``, ``.uncertainty`` — a preset's run does not replace the
        plain run's ``mod-2.campbell.png``, it writes ``mod-2.gl2010.campbell.png``."""
        parts = [self.preset or "", self.rule or ""]
        if self.margin is not None:
            parts.append(f"margin{self.margin * 100:g}")
        if uncertainty or self.samples is not None:
            parts.append("uncertainty")
        return "".join(f".{p}" for p in parts if p)

    def load(self, path: str | Path) -> Any:
        """The turbine at ``path``, read with the import options."""
        from .. import importers

        return importers.load(path, self.read)

    def settings(self, turbine: Any) -> Any:
        """The turbine's audit settings with the overrides applied."""
        from ..audit import override

        return override(turbine.audit, margin=self.margin, rule=self.rule, preset=self.preset)


def options(
    rpm: str | None = None,
    margin: float | None = None,
    rule: str | None = None,
    preset: str | None = None,
    **read: Any,
) -> Options:
    """The options of a command line: ``rpm`` as text (:func:`rpm_range`), ``read`` the
    other :class:`~wtvib.importers.ReadOptions` fields."""
    return Options(
        read=ReadOptions(rpm=rpm_range(rpm), **read), margin=margin, rule=rule, preset=preset
    )


def rpm_range(text: str | None) -> tuple[float, float] | None:
    """``--rpm 6.9:12.1`` → (6.9, 12.1); ``--rpm 20`` → (20, 20)."""
    if text is None:
        return None
    try:
        parts = [float(x) for x in text.split(":")]
    except ValueError:
        raise OptionError("--rpm", f"takes MIN:MAX in rpm, e.g. 6.9:12.1 (got {text!r})") from None
    if len(parts) == 1:
        parts *= 2
    if len(parts) != 2 or not (math.isfinite(parts[1]) and 0 <= parts[0] <= parts[1] > 0):
        raise OptionError(
            "--rpm",
            f"takes MIN:MAX with 0 <= MIN <= MAX and MAX above 0 (got {text!r}); a standstill "
            "linearisation is audited as one without --rpm",
        )
    return parts[0], parts[1]


def study(
    uncertainty: bool,
    samples: int | None = None,
    seed: int | None = None,
    scheduler: str | None = None,
) -> tuple[int | None, int]:
    """The samples (None: no study) and seed of ``--uncertainty``: ``--samples``, ``--seed``
    and ``--scheduler`` apply to it alone (an error where given without it)."""
    given = ((scheduler, "--scheduler"), (samples, "--samples"), (seed, "--seed"))
    for value, name in given:
        if value is not None and not uncertainty:
            raise OptionError(name, "applies to --uncertainty")
    drawn = (DEFAULT_SAMPLES if samples is None else samples) if uncertainty else None
    return drawn, seed or 0
