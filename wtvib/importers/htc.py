"""HAWC2's model files as data: the htc block syntax, st (beam) files, ae and pc
(aerodynamic) files and opt (operating point) files.

The htc syntax (HAWC2 user manual, §3): commands end in ``;`` and whatever follows the
``;`` on a line is a comment; ``begin NAME;`` … ``end NAME;`` nest blocks;
``continue_in_file FILE;`` reads FILE in its place (until its ``exit;``); ``exit;`` ends the
file. File names are relative to the folder HAWC2 runs in — by convention the model's
folder, the one that holds ``htc/`` (``./data/…``, ``../IEA-15-240-RWT/…``); where a name
does not resolve there, beside the htc file.

Every value keeps its file and line, so that a fault names where it is.
"""

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..errors import SpecError
from ..spec import read_text
from .deck import _NUMBER
from .paths import is_file, locate, note

#: The deepest continue_in_file nesting read (a file that names itself would not end).
MAX_INCLUDES = 20


@dataclass(frozen=True)
class Command:
    """One htc command: its key, the values after it, where it stands."""

    key: str
    values: tuple[str, ...]
    file: Path
    line: int

    def number(self, i: int) -> float:
        """The ``i``-th value as a number (its file and line named where it is not one)."""
        try:
            if not _NUMBER.match(self.values[i]):
                raise ValueError
            value = float(self.values[i].replace("D", "E").replace("d", "e"))
        except (IndexError, ValueError):
            got = self.values[i] if i < len(self.values) else "nothing"
            if got.startswith("["):  # a tag of a DLB template ([Rotor azimuth], [wsp] …)
                tag = " ".join(self.values[i:]).split("]")[0] + "]"
                raise SpecError(
                    f"{self.key}: value {i + 1} is a template's tag, {tag}, not a number — "
                    "a load-case template (a DLB master file); audit an htc made from it",
                    line=self.line,
                    source=str(self.file),
                ) from None
            said = repr(got) if i < len(self.values) else "nothing: the command ends before it"
            raise SpecError(
                f"{self.key}: value {i + 1} must be a number (got {said})",
                line=self.line,
                source=str(self.file),
            ) from None
        if not np.isfinite(value):
            raise SpecError(
                f"{self.key}: value {i + 1} must be a finite number",
                line=self.line,
                source=str(self.file),
            )
        return value

    def text(self, i: int = 0) -> str:
        """The ``i``-th value as it stands (a name, a file), or one line naming the command
        that lacks it."""
        if i >= len(self.values):
            raise SpecError(
                f"{self.key}: value {i + 1} is missing", line=self.line, source=str(self.file)
            )
        return self.values[i]

    def first(self, count: int, start: int = 0) -> list[float]:
        """``count`` numbers from the ``start``-th value on (a position's three, a damping's
        six): one missing or not a number is one line naming the command."""
        return [self.number(i) for i in range(start, start + count)]

    def numbers(self, start: int = 0) -> list[float]:
        return [self.number(i) for i in range(start, len(self.values))]

    def within(self, i: int, low: float, high: float, what: str) -> float:
        """The ``i``-th value as a number from ``low`` to ``high``, else one line naming
        ``what`` it is, its file and line."""
        value = self.number(i)
        if not low <= value <= high:
            raise SpecError(
                f"{what} {value:g} is outside {low:g} … {high:g}",
                line=self.line,
                source=str(self.file),
            )
        return value


@dataclass
class Block:
    """An htc block: its name, the comment after its ``begin`` (a body's name is often
    there: ``begin main_body;  tower``), its commands and blocks in order."""

    name: str
    file: Path
    line: int
    title: str = ""
    commands: list[Command] = field(default_factory=list)
    blocks: list["Block"] = field(default_factory=list)
    #: what reading the file took as HAWC2 takes it (the file's top block only)
    notes: list[str] = field(default_factory=list)

    def get(self, key: str) -> Command | None:
        return next((c for c in self.commands if c.key == key), None)

    def all(self, key: str) -> list[Command]:
        return [c for c in self.commands if c.key == key]

    def need(self, key: str) -> Command:
        found = self.get(key)
        if found is None:
            raise SpecError(
                f"block {self.name}: no {key} command", line=self.line, source=str(self.file)
            )
        return found

    def block(self, name: str) -> "Block | None":
        return next((b for b in self.blocks if b.name == name), None)

    def each(self, name: str) -> list["Block"]:
        return [b for b in self.blocks if b.name == name]


#: How many folders above an htc file outside any ``htc/`` folder are looked at for the
#: model's ``data/`` (HAWCStab2's inputs kept in a ``hawcstab2/`` beside ``htc/``).
ROOT_SEARCH = 2


def root_folder(htc: Path) -> Path:
    """The folder HAWC2 runs the model in: the one holding the ``htc/`` the file is in (also
    from a folder below it: the DLB templates' ``htc/_master/``); else the nearest of the
    htc's own folder and the ROOT_SEARCH above it that holds a ``data/`` folder (the
    IEA-10's ``hawcstab2/steadystate_modal.htc`` names ``./data/…`` of the folder above);
    else the htc's own."""
    htc = htc.absolute()  # `wtvib check model.htc` run in the htc/ folder
    for folder in htc.parents:
        if folder.name.lower() == "htc":
            return folder.parent
    for folder in [htc.parent, *htc.parent.parents][: ROOT_SEARCH + 1]:
        if (folder / "data").is_dir():
            return folder
    return htc.parent


def resolve(name: str, root: Path, beside: Path, cmd: Command, suffix: str = "") -> Path:
    """A file the model names: relative to the model's folder, else beside the file that
    names it, else relative to one of the ROOT_SEARCH folders above that (noted: wetb's own
    test models keep their htc files in ``htcfiles/``, their data in a ``data/`` beside it);
    SpecError naming the command where none holds it. With ``suffix`` the
    name is a stem (WAMIT's results: ``stem.1``, ``stem.hst``): the stem returned where the
    file stem + suffix is."""
    name = name.strip('"')
    beside = beside.absolute()
    folders = list(dict.fromkeys((root, beside, *beside.parents[:ROOT_SEARCH])))
    for folder in folders:
        found = locate(folder, name + suffix)
        if is_file(found):
            if folder not in (root, beside):
                note(
                    f"the model's files found relative to {folder}, not to {root}, the "
                    "folder wtvib takes HAWC2 to run the model in (the one holding its htc/ "
                    "folder, or its data/)"
                )
            return found.with_name(found.name[: len(found.name) - len(suffix)])
    looked = ", ".join(map(str, folders))
    raise SpecError(
        f"{cmd.key} names {name!r}, which does not exist (looked in {looked})",
        line=cmd.line,
        source=str(cmd.file),
    )


def parse(path: Path) -> Block:
    """The htc file as a tree of blocks (continue_in_file read in place)."""
    top = Block("htc", path, 1)
    stack = [top]
    _read(path, root_folder(path), stack, 0)
    if len(stack) > 1:
        open_ = stack[-1]
        raise SpecError(
            f"begin {open_.name} has no end {open_.name} (the file ends first)",
            line=open_.line,
            source=str(open_.file),
        )
    return top


def _read(path: Path, root: Path, stack: list[Block], depth: int) -> None:
    if depth > MAX_INCLUDES:
        raise SpecError(
            f"continue_in_file nests more than {MAX_INCLUDES} deep (a file that names itself?)",
            source=str(path),
        )
    for number, raw in enumerate(read_text(path, ansi=True).splitlines(), start=1):
        text, sep, rest = raw.partition(";")
        tokens = text.split()
        if not tokens:
            continue
        key = tokens[0].lower()
        if key == "exit":
            return
        if key == "begin":
            if len(tokens) < 2:
                raise SpecError("begin without a block name", line=number, source=str(path))
            block = Block(tokens[1].lower(), path, number, rest.strip())
            stack[-1].blocks.append(block)
            stack.append(block)
        elif key == "end":
            _end(tokens[1].lower() if len(tokens) > 1 else "", stack, path, number)
        elif key == "continue_in_file":
            cmd = Command(key, tuple(tokens[1:]), path, number)
            if not cmd.values:
                raise SpecError("continue_in_file names no file", line=number, source=str(path))
            _read(resolve(cmd.values[0], root, path.parent, cmd), root, stack, depth + 1)
        elif sep or len(tokens) > 0:
            stack[-1].commands.append(Command(key, tuple(tokens[1:]), path, number))


def _end(name: str, stack: list[Block], path: Path, number: int) -> None:
    """``end name``: closes the innermost open block. A name that is no open block's is a
    misspelt end (DTU's own htc files have ``begin tower_shadow_potential_2; … end
    tower_shadow_potential;``), which HAWC2 and wetb's reader take as the innermost's end: so
    does wtvib, and says so. One that names an enclosing block leaves the blocks inside it
    without an end: refused."""
    if len(stack) == 1 or (name and name in (b.name for b in stack[1:-1])):
        expected = stack[-1].name if len(stack) > 1 else "no block"
        raise SpecError(f"end {name} where {expected} is open", line=number, source=str(path))
    if name and stack[-1].name != name:
        stack[0].notes.append(
            f"{path.name} line {number}: 'end {name}' read as the end of block "
            f"{stack[-1].name} (begun on line {stack[-1].line}), as HAWC2 reads it"
        )
    stack.pop()


# ------------------------------------------------------------------------------------------
# st, ae, pc, opt


def _numeric_rows(path: Path) -> list[tuple[int, list[str]]]:
    return [
        (i, ln.split()) for i, ln in enumerate(read_text(path, ansi=True).splitlines(), start=1)
    ]


def _floats(cells: list[str], path: Path, line: int, count: int | None = None) -> list[float]:
    try:
        if not all(_NUMBER.match(c) for c in cells[:count]):
            raise ValueError
        values = [float(c.replace("D", "E").replace("d", "e")) for c in cells[:count]]
    except ValueError:
        raise SpecError(
            f"a number was expected in every column (got {' '.join(cells[:6])} …)",
            line=line,
            source=str(path),
        ) from None
    if count is not None and len(values) < count:
        raise SpecError(
            f"{count} columns were expected, the line has {len(values)}",
            line=line,
            source=str(path),
        )
    if not np.all(np.isfinite(values)):
        raise SpecError("a number that is not finite", line=line, source=str(path))
    return values


#: No st file value reaches this — not even the moduli of the near-rigid sets HAWC2 models
#: use for their dummy bodies (the IEA-15's: up to 7e18): beyond it a number is typed wrong,
#: and the blade's and tower's inertia integrals would overflow.
ST_LIMIT = 1e30


def read_st(path: Path, set_no: int, subset: int, columns: int) -> np.ndarray:
    """Main set ``set_no``, subset ``subset`` of an st file: its rows, ``columns`` values
    each (19 for a classical Timoshenko set, 30 for a fully populated one). The file marks
    a main set with ``#n`` and a subset with ``$m rows``."""
    current = 0
    rows = _numeric_rows(path)
    for k, (line, cells) in enumerate(rows):
        if not cells:
            continue
        head = cells[0]
        if head.startswith("#"):
            digits = head[1:].strip() or (cells[1] if len(cells) > 1 else "")
            current = int(digits) if digits.isdigit() else current + 1
        elif head.startswith("$") and current == set_no:
            digits = head[1:].strip() or (cells[1] if len(cells) > 1 else "")
            rest = cells[1:] if head[1:].strip() else cells[2:]
            if not digits.isdigit() or not rest or not rest[0].isdigit():
                raise SpecError("a subset line is $number rows", line=line, source=str(path))
            if int(digits) != subset:
                continue
            count = int(rest[0])
            if count < 1:
                raise SpecError(
                    f"subset ${subset} of set #{set_no} announces {count} rows: a beam needs "
                    "its stations",
                    line=line,
                    source=str(path),
                )
            out: list[list[float]] = []
            for line2, cells2 in rows[k + 1 :]:
                if len(out) == count:
                    break
                if not cells2:
                    continue
                out.append(_floats(cells2, path, line2, columns))
                if max(abs(v) for v in out[-1]) > ST_LIMIT:
                    raise SpecError(
                        f"a value beyond any wind turbine's (|x| > {ST_LIMIT:g}; a near-rigid "
                        "dummy set's modulus is ~1e19): an exponent typed wrong?",
                        line=line2,
                        source=str(path),
                    )
            if len(out) < count:
                raise SpecError(
                    f"subset ${subset} of set #{set_no} announces {count} rows, the file "
                    f"holds {len(out)}",
                    line=line,
                    source=str(path),
                )
            table = np.array(out)
            if np.any(np.diff(table[:, 0]) < 0):
                raise SpecError(
                    f"set #{set_no} subset ${subset}: the stations (first column) must not "
                    "decrease",
                    line=line,
                    source=str(path),
                )
            return table
    raise SpecError(f"no set #{set_no} with a subset ${subset}", source=str(path))


def read_ae(path: Path, set_no: int) -> np.ndarray:
    """An ae file's set: rows of radius along the blade, chord, relative thickness [%] and
    pc set."""
    rows = [(i, c) for i, c in _numeric_rows(path) if c]
    if not rows:
        raise SpecError("an empty ae file", source=str(path))
    k = 1
    while k < len(rows):
        line, cells = rows[k]
        number, count = _floats(cells, path, line, 2)
        k += 1
        block = [_floats(c, path, ln, 4) for ln, c in rows[k : k + int(count)]]
        if int(number) == set_no:
            if len(block) < int(count):
                raise SpecError(
                    f"set {set_no} announces {int(count)} rows", line=line, source=str(path)
                )
            return np.array(block)
        k += int(count)
    raise SpecError(f"no ae set {set_no}", source=str(path))


def read_pc(path: Path, set_no: int = 1) -> list[tuple[float, np.ndarray]]:
    """A pc file's set: its profiles as (relative thickness [%], rows of α [deg], C_L, C_D,
    C_M)."""
    rows = [(i, c) for i, c in _numeric_rows(path) if c]
    k = 1  # the first line: the number of sets and a title
    for current in range(1, set_no + 1):
        if k >= len(rows):
            raise SpecError(f"no pc set {set_no}", source=str(path))
        line, cells = rows[k]
        n_profiles = _whole(_floats(cells, path, line, 1)[0], "profiles", 1, path, line)
        k += 1
        profiles = []
        for _ in range(n_profiles):
            if k >= len(rows):
                raise SpecError(
                    f"the set announces {n_profiles} profiles, the file ends before them",
                    line=line,
                    source=str(path),
                )
            line, cells = rows[k]
            _, raw_count, thickness = _floats(cells, path, line, 3)
            count = _whole(raw_count, "rows of a profile", 2, path, line)
            k += 1
            table = np.array([_floats(c, path, ln, 4) for ln, c in rows[k : k + count]])
            if len(table) < count:
                raise SpecError(f"a profile announces {count} rows", line=line, source=str(path))
            k += count
            profiles.append((thickness, table))
        if current == set_no:
            return profiles
    raise SpecError(f"no pc set {set_no}", source=str(path))


def _whole(value: float, what: str, least: int, path: Path, line: int) -> int:
    """A count in a file: a whole number, at least ``least``, at most a million."""
    if value != int(value) or not least <= value <= 1_000_000:
        raise SpecError(
            f"{value:g} {what}: a whole number from {least} is expected",
            line=line,
            source=str(path),
        )
    return int(value)


def read_opt(path: Path) -> np.ndarray:
    """An operational data file (HAWCStab2's .opt): rows of wind [m/s], pitch [deg], rotor
    speed [rpm] (and power, thrust), after a first line with their count (and the columns'
    titles) — or without it, the rows alone (the IEA-22's HAWC2 model)."""
    rows = [(i, c) for i, c in _numeric_rows(path) if c]
    if not rows:
        raise SpecError("an empty operational data file", source=str(path))
    line, cells = rows[0]
    if len(cells) >= 3 and all(_NUMBER.match(c) for c in cells[:3]):  # no count line
        return np.array([_floats(c, path, ln, 3) for ln, c in rows])
    count = int(_floats(cells, path, line, 1)[0])
    table = np.array([_floats(c, path, ln, 3) for ln, c in rows[1 : 1 + count]])
    if len(table) < count or count < 1:
        raise SpecError(f"announces {count} operating points", line=line, source=str(path))
    return table
