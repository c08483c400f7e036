"""What a figure says at its top: the worst status of the checks it draws, and which.

One rule for every figure kind, so that a figure never contradicts the verdict: its
headline is the worst status (info counts as a pass) of the checks whose judgement it
draws — a Campbell diagram the resonance checks of the modes on it (the status those
modes have in each check, ``numbers["modes"]``) and the tower's class where the classified
mode is on it; a damping figure the stability check; a flutter diagram ``blade.flutter``
… The same :class:`Headline` titles the figure and is written into its PNG (``Title``,
``wtvib:checks``), where a test holds it against the JSON report.
"""

from collections.abc import Collection, Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ...results import Check
from ...rules import STATUS_ORDER, Status

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ...audit import Report

#: The attribute a figure's title and headline travel on, from the plot that drew it to
#: the PNG writer (:func:`wtvib.outputs.plots.png_bytes`).
_STAMP = "_wtvib_headline"


@dataclass(frozen=True)
class Headline:
    """A figure's judgement: its status (``pass``/``warn``/``fail``, ``info`` where it
    draws no check), its words (``FAIL: 3P on system.tower.ss1; tower resonant``) and the
    ids of the checks it draws."""

    status: Status
    words: str
    checks: tuple[str, ...]


#: The words of a figure that draws one check: its status alone.
STATUS_ONLY: dict[Status, str] = {"pass": "PASS", "warn": "WARN", "fail": "FAIL"}
#: The judgement of a figure that draws none (mode shapes, energy shares).
NOTHING = Headline("info", "", ())


def stamp(fig: "Figure", title: str, judged: Headline) -> None:
    """Mark a figure with its title (on one line) and judgement, for its PNG."""
    setattr(fig, _STAMP, (" ".join(title.split()), judged))


def stamp_of(fig: "Figure") -> tuple[str, Headline] | None:
    """The title and judgement a figure was stamped with, if it was."""
    found = getattr(fig, _STAMP, None)
    return found if isinstance(found, tuple) else None


def of_checks(checks: Sequence[Check], ids: Sequence[str], words: dict[Status, str]) -> Headline:
    """A figure that draws whole checks (``ids``, those among ``checks``): the worst status
    and, by status, what to say (``{status}`` and ``{check}`` filled in)."""
    drawn = [c for c in checks if c.id in ids]
    if not drawn:
        return Headline("info", "nothing judged here", ())
    worst = max(drawn, key=lambda c: STATUS_ORDER[c.status])
    status: Status = "pass" if worst.status == "info" else worst.status
    text = words.get(status, "PASS" if status == "pass" else "{STATUS}: {check}")
    return Headline(
        status,
        text.format(STATUS=status.upper(), check=worst.id),
        tuple(c.id for c in drawn),
    )


def of_modes(report: "Report", modes: Collection[str], tower_mode: str | None) -> Headline:
    """A Campbell diagram of ``modes`` (the ids it draws and, for isolated modes judged as
    coupled ones, the ids judged in their place): the resonance checks whose status one of
    them carries, and the tower's class where its classified mode (``tower_mode``) is among
    them — so the figure's status is the worst status of the checks it lists."""
    rows: list[tuple[Status, Check, str | None]] = []
    for c in report.checks:
        per_mode = c.numbers.get("modes")
        if ".resonance." not in c.id or not isinstance(per_mode, dict):
            continue
        # drawn: a mode on the figure carries the check's status (its judgement is there
        # to see); a check that fails elsewhere and passes here is another figure's
        mine = {m: s for m, s in per_mode.items() if m in modes}
        if mine and _worst(mine.values()) == c.status:
            rows.append((c.status, c, _named(c, mine)))
    tower = next((c for c in report.checks if c.id == "tower.class"), None)
    cls = ""
    if tower is not None and tower_mode is not None and tower_mode in modes:
        rows.append((tower.status, tower, None))
        cls = f"; tower {tower.numbers.get('tower_class')}"
    if not rows:
        return Headline("info", "nothing judged here", ())
    ids = tuple(dict.fromkeys(c.id for _, c, _ in rows))
    status = _worst(s for s, _, _ in rows)
    if STATUS_ORDER[status] >= STATUS_ORDER["warn"]:
        bad = [(c, m) for s, c, m in rows if s == status]
        line = next(((c, m) for c, m in bad if m is not None), None)
        if line is None:  # the class alone (no resonance check on these modes)
            return Headline(status, f"{status.upper()}{cls.replace(';', ':', 1)}", ids)
        c, mode = line
        return Headline(status, f"{status.upper()}: {c.numbers['excitation']} on {mode}{cls}", ids)
    # resonances in steady operation told as info: by a low-energy line, or heavily damped
    steady = [c for s, c, _ in rows if s == "info" and c.numbers.get("regime") == "steady"]
    damped = _lines(c for c in steady if c.numbers.get("heavily_damped"))
    minor = _lines(c for c in steady if not c.numbers.get("heavily_damped"))
    told = [f"{minor} low-energy" if minor else "", f"{damped} heavily damped" if damped else ""]
    words = (
        "PASS: no resonance of a dominant line — info: " + "; ".join(t for t in told if t)
        if steady
        else "PASS: no resonance in operation"
    )
    return Headline("pass", words + cls, ids)


def _lines(checks: Iterable[Check]) -> str:
    """The excitation lines of some checks, in order (``4P, 5P``)."""
    return ", ".join(sorted({str(c.numbers["excitation"]) for c in checks}, key=_line_order))


def _worst(statuses: Iterable[Status]) -> Status:
    return max(statuses, key=STATUS_ORDER.__getitem__, default="pass")


def _named(c: Check, mine: dict[str, Status]) -> str:
    """The mode a check is told by on this figure: its governing mode where that is drawn
    at the status the figure reports (the name the terminal and the JSON give), else the
    first drawn mode at that status."""
    status = _worst(mine.values())
    governing = c.numbers.get("mode")
    if governing in mine and mine[governing] == status:
        return str(governing)
    return next(m for m, s in mine.items() if s == status)


def _line_order(line: str) -> tuple[int, str]:
    digits = "".join(ch for ch in line if ch.isdigit())
    return (int(digits) if digits else 10**6, line)
