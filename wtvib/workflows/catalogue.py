"""The turbines that ship with wtvib (``wtvib/turbines``, ``turbines/`` in the repository):
Hau's turbines, each telling its chapter-7 story, and modern reference turbines.

``wtvib catalogue`` lists them from ``index.json`` — name, rotor, tower class, verdict and
the story each tells — without auditing seventeen turbines to print a table; the index is
written from the audits themselves (:func:`index`, ``python -m wtvib.workflows.catalogue``), and a
test holds it to them. ``wtvib check mod-2`` takes a catalogue turbine by its name.
"""

from __future__ import annotations

import json
import re
from dataclasses import asdict, dataclass
from pathlib import Path

from ..outputs.words import counted

#: The catalogue folder, inside the installed package.
FOLDER = Path(__file__).resolve().parents[1] / "turbines"
INDEX = FOLDER / "index.json"


@dataclass(frozen=True)
class Entry:
    """One catalogue turbine as ``wtvib catalogue`` lists it."""

    name: str  # the file's stem: what ``wtvib check NAME`` takes
    turbine: str
    rotor: str
    tower_class: str | None
    verdict: str
    story: str


def files() -> list[Path]:
    """The catalogue's spec files, by name."""
    return sorted(FOLDER.glob("*.yaml"))


def find(name: str) -> Path | None:
    """The catalogue spec a bare name means (``mod-2``, ``MOD-2``, ``mod-2.yaml``), or None
    where the name is a path or no catalogue turbine has it."""
    if "/" in name or "\\" in name:
        return None
    stem = name[:-5] if name.lower().endswith(".yaml") else name
    for path in files():
        if path.stem.casefold() == stem.casefold():
            return path
    return None


def story(path: Path) -> str:
    """The story a spec tells: its leading comment's first sentence (or line)."""
    lines = []
    for line in path.read_text(encoding="utf-8").splitlines():
        if not line.startswith("#"):
            break
        lines.append(line.lstrip("# ").strip())
    text = " ".join(lines)
    # a sentence ends at a full stop that is not an abbreviation's (Fig. 7.28, ch. 7.3)
    end = re.search(r"(?<!Fig)(?<!ch)(?<!No)(?<!e\.g)\.(\s|$)", text)
    return text[: end.start() + 1] if end else text


def entries() -> list[Entry]:
    """The catalogue as the index records it."""
    return [Entry(**e) for e in json.loads(INDEX.read_text(encoding="utf-8"))["turbines"]]


def index() -> list[Entry]:
    """The catalogue's entries from the audits themselves (what ``index.json`` holds)."""
    from .. import audit, spec

    out = []
    for path in files():
        turbine = spec.load(path)
        report = audit.run(turbine)
        t, r = turbine.turbine, turbine.rotor
        diameter = f"{t.rotor_diameter_m:g} m, " if t.rotor_diameter_m is not None else ""
        rotor = f"{diameter}{counted(r.blades, 'blade')}, {r.orientation}"
        out.append(Entry(path.stem, t.name, rotor, report.tower_class, report.verdict, story(path)))
    return out


def write_index() -> Path:
    """Write ``index.json`` from the audits (``python -m wtvib.workflows.catalogue``)."""
    from ..outputs.files import write_atomic

    doc = {"schema": "wtvib-catalogue/1", "turbines": [asdict(e) for e in index()]}
    text = json.dumps(doc, indent=2, ensure_ascii=False) + "\n"
    return write_atomic(INDEX, text.encode(), force=True)


if __name__ == "__main__":
    print(f"wrote {write_index()}")


def listing(*, copy: Path | None = None, force: bool = False, json_out: bool = False) -> int:
    """``wtvib catalogue``: the turbines as a table (or JSON), or their specs copied into
    ``copy`` to edit — all or none: a file there that differs from the catalogue's stops
    the copy before any is written, unless ``force``."""
    from . import ui

    found = entries()
    if copy is not None:
        _copy(copy, force)
        ui.say(f"copied {len(found)} turbine specs to {ui.shown(copy)}")
        return ui.EXIT_PASS
    if json_out:
        ui.dump({"schema": "wtvib-catalogue/1", "turbines": [asdict(e) for e in found]})
        return ui.EXIT_PASS
    from ..outputs.report import catalogue_table

    catalogue_table(ui.console(), found, FOLDER)
    return ui.EXIT_PASS


def _copy(folder: Path, force: bool) -> None:
    from ..errors import OutputError
    from ..outputs.files import write_atomic

    def differs(path: Path) -> bool:  # a file there that is not the catalogue's own
        target = folder / path.name
        return target.exists() and (
            not target.is_file() or target.read_bytes() != path.read_bytes()
        )

    edited = [p for p in files() if differs(p)]
    if edited and not force:  # checked before any is written: all or none
        raise OutputError(
            f"{folder / edited[0].name} exists"
            + (f" (and {len(edited) - 1} more)" if len(edited) > 1 else "")
            + " and differs from the catalogue's; use --force to replace"
        )
    for path in files():
        write_atomic(folder / path.name, path.read_bytes(), force=True, folder=True)


def resolve(path: Path) -> Path:
    """The file a command reads: ``path``, or — where no such file exists and the name is a
    catalogue turbine's (``mod-2``) — the catalogue's spec, said on stderr; a file that is
    neither is one line before any numerical module is imported."""
    import os

    if os.path.lexists(path):
        return path
    from . import ui

    found = find(str(path))
    if found is None:  # said now, not after a second of importing the numerical stack
        from ..errors import SpecError

        raise SpecError("no such file", source=str(path))
    ui.say(f"note: {ui.shown(path)} is the catalogue's {found.name} ({ui.shown(found)})", err=True)
    return found
