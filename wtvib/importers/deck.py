"""The text format of FAST / OpenFAST input files: ``value Key - description`` lines and
the tables of tower and blade stations; files named by a deck, resolved beside it.

Shared by the ElastoDyn and AeroDyn importers (OpenFAST input-file documentation).
"""

import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..errors import SpecError
from ..spec import read_text
from .paths import is_file, locate

#: A number as Fortran reads one: ASCII digits only (Python's float() also takes "8_7.6",
#: Arabic-Indic and full-width digits, "inf" and "nan", which no OpenFAST input holds).
_NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eEdD][-+]?\d+)?$", re.ASCII)


#: The largest magnitude an OpenFAST scalar input of each name may take here (and its
#: unit): far beyond any wind turbine, short of what overflows a model (a 1e300 m overhang
#: squares to infinity in the head inertia). Lengths as the spec bounds head offsets.
LIMITS: dict[str, tuple[float, str]] = {
    **{
        key: (1e3, "m")
        for key in (
            "TipRad",
            "HubRad",
            "HubCM",
            "UndSling",
            "OverHang",
            "ShftGagL",
            "NacCMxn",
            "NacCMyn",
            "NacCMzn",
            "Twr2Shft",
            "TowerHt",
            "TowerBsHt",
            "YawBrMass_zn",
        )
    },
    **{
        key: (1e10, "kg")
        for key in (
            "HubMass",
            "NacMass",
            "YawBrMass",
            "TipMass(1)",
            "TipMass(2)",
            "TipMass(3)",
            "TipMass1",
            "TipMass2",
            "TipMass3",
        )
    },
    **{key: (1e15, "kg·m²") for key in ("HubIner", "GenIner", "NacYIner")},
}

#: Distributed properties no tower or blade reaches (the largest reference towers and
#: monopiles: ~1e13 N·m² and ~2e4 kg/m; blades ~1e11 N·m² and ~5e3 kg/m), by column.
COLUMN_LIMITS: dict[str, tuple[float, str]] = {
    "TMassDen": (1e6, "kg/m"),
    "TwFAStif": (1e16, "N·m²"),
    "TwSSStif": (1e16, "N·m²"),
    "BMassDen": (1e5, "kg/m"),
    "FlpStff": (1e14, "N·m²"),
    "EdgStff": (1e14, "N·m²"),
}

#: Inputs an ElastoDyn deck gives once (a sectioned file, SubDyn's, may repeat a key in
#: another section): given twice with two values, the deck is refused — OpenFAST reads by
#: position, wtvib by key, and neither would read the deck as its author meant.
UNIQUE = frozenset({*LIMITS, "NumBl", "GBRatio", "DTTorSpr", "DTTorDmp", "RotSpeed",
                    "ShftTilt", "PreCone(1)", "NTwInpSt", "NBlInpSt"})  # fmt: skip


@dataclass(frozen=True)
class Deck:
    """Scalar inputs (key → raw text, line) and tables (first column name → rows)."""

    path: Path
    values: dict[str, tuple[str, int]]
    tables: dict[str, tuple[list[str], np.ndarray]]
    table_lines: dict[str, int] = field(default_factory=dict)  # header line of each table
    #: what "default" stands for where the deck set says where (AeroDyn's AirDens: the
    #: .fst's environment block): key → (value, where it came from)
    inherited: dict[str, tuple[float, str]] = field(default_factory=dict)
    #: the inputs read as "default", and what they were taken as (for the assumptions)
    defaulted: dict[str, str] = field(default_factory=dict)

    def line(self, key: str) -> int | None:
        """The line the input ``key`` stands on (None: not in this file)."""
        return self.values[key][1] if key in self.values else None

    def is_default(self, key: str) -> bool:
        """Whether the input is OpenFAST's "default" keyword (quoted or not)."""
        return key in self.values and self.values[key][0].strip('"').lower() == "default"

    def text(self, *keys: str) -> str:
        for key in keys:
            if key in self.values:
                return self.values[key][0].strip('"')
        raise SpecError(f"{keys[0]} is missing from the deck", source=str(self.path))

    def num(self, *keys: str, default: float | None = None) -> float:
        """A number; OpenFAST's "default" keyword takes what the deck set says it stands for
        (:attr:`inherited`), else ``default`` (OpenFAST's documented default, which the
        caller gives), each noted in :attr:`defaulted`."""
        for key in keys:
            if key in self.values and self.is_default(key):
                if key in self.inherited:
                    value, where = self.inherited[key]
                elif default is not None:
                    value, where = default, "OpenFAST's documented default"
                else:
                    raise SpecError(
                        f'{key} is "default", and the deck set does not say what that stands '
                        "for here: give its number",
                        line=self.values[key][1],
                        source=str(self.path),
                    )
                self.defaulted[key] = f'{key} "default" → {value:g} ({where})'
                return value
            if key in self.values:
                raw, line = self.values[key]
                if not _NUMBER.match(raw):
                    raise SpecError(
                        f"{key} must be a finite number (got {raw!r})",
                        line=line,
                        source=str(self.path),
                    )
                value = float(raw.replace("D", "E").replace("d", "e"))
                if not math.isfinite(value):
                    raise SpecError(
                        f"{key} must be a finite number (got {raw!r})",
                        line=line,
                        source=str(self.path),
                    )
                limit, unit = LIMITS.get(key, (math.inf, ""))
                if abs(value) > limit:
                    raise SpecError(
                        f"{key} = {raw} is out of range for a wind turbine (|{key}| ≤ "
                        f"{limit:g} {unit})",
                        line=line,
                        source=str(self.path),
                    )
                return value
        if default is not None:
            return default
        raise SpecError(f"{keys[0]} is missing from the deck", source=str(self.path))

    def factor(self, key: str) -> float:
        """An adjustment factor (AdjTwMa, AdjFlSt …): positive, 1 where absent."""
        value = self.num(key, default=1.0)
        if not value > 0:
            raise SpecError(
                f"{key} must be positive (got {value:g}): it scales a mass or stiffness",
                line=self.line(key),
                source=str(self.path),
            )
        return value

    def fractions(self, table: str) -> np.ndarray:
        """The table's first column (HtFract, BlFract): increasing from 0 to 1 — a table cut
        short (a truncated file) would otherwise describe part of the member as all of it."""
        frac = self.column(table, table)
        ok = len(frac) == 1 or (
            abs(frac[0]) < 1e-6 and abs(frac[-1] - 1.0) < 1e-6 and np.all(np.diff(frac) > 0)
        )
        if not ok:
            head = self.table_lines.get(table)
            falls = np.flatnonzero(np.diff(frac) <= 0)
            if falls.size:  # the row that does not rise above the one before
                k = int(falls[0]) + 1
                raise SpecError(
                    f"the {table} column must increase from 0 to 1 ({frac[k]:g} follows "
                    f"{frac[k - 1]:g})",
                    line=head + 2 + k if head is not None else None,
                    source=str(self.path),
                )
            raise SpecError(
                f"the {table} column must increase from 0 to 1 (it runs "
                f"{frac[0]:g} … {frac[-1]:g} over {len(frac)} stations: a truncated table?)",
                line=head,
                source=str(self.path),
            )
        return frac

    def flag(self, key: str) -> bool:
        """A logical input (True/False), read as Fortran reads one: an optional period, then
        T or F; an absent key is False."""
        if key not in self.values:
            return False
        raw, line = self.values[key]
        word = raw.strip('"').lstrip(".").lower()
        if word[:1] in ("t", "f"):
            return word[0] == "t"
        raise SpecError(
            f"{key} must be True or False (got {raw!r})", line=line, source=str(self.path)
        )

    def whole(self, key: str, low: int = 0, high: int | None = None) -> int:
        """A count (``NumBl``): a whole number ≥ ``low`` (and ≤ ``high``) — 2.7 blades is an
        error, not 2."""
        value = self.num(key)
        if value != int(value) or value < low or (high is not None and value > high):
            within = f"from {low} to {high}" if high is not None else f"≥ {low}"
            raise SpecError(
                f"{key} must be a whole number {within} (got {self.values[key][0]!r})",
                line=self.values[key][1],
                source=str(self.path),
            )
        return int(value)

    def column(self, table: str, *names: str) -> np.ndarray:
        """A table column by any of its names; SpecError naming the file if it is absent."""
        found = self.optional_column(table, *names)
        if found is None and table not in self.tables:
            raise SpecError(
                f"no {table} table (a table headed {table}); is the file cut short?",
                source=str(self.path),
            )
        if found is None:
            raise SpecError(f"the {table} table has no {names[0]} column", source=str(self.path))
        return found

    def positive(self, table: str, name: str) -> np.ndarray:
        """A column of distributed mass or stiffness: every value above 0 — a station with
        none is a beam that is not there, named by file, line and column."""
        found = self.column(table, name)
        limit, unit = COLUMN_LIMITS.get(name, (math.inf, ""))
        over = np.flatnonzero(found > limit)
        if over.size:  # 1e25 where 1e11 was meant: the model would lose its precision
            k = int(over[0])
            head = self.table_lines.get(table)
            raise SpecError(
                f"{name} = {found[k]:.4g} {unit} at {table} {self.column(table, table)[k]:g} "
                f"is beyond any wind turbine (≤ {limit:g} {unit}): an exponent typed wrong?",
                line=head + 2 + k if head is not None else None,
                source=str(self.path),
            )
        bad = np.flatnonzero(~(found > 0))
        if bad.size:
            k = int(bad[0])
            head = self.table_lines.get(table)
            raise SpecError(
                f"{name} must be positive (got {found[k]:g} at {table} "
                f"{self.column(table, table)[k]:g})",
                line=head + 2 + k if head is not None else None,
                source=str(self.path),
            )
        return found

    def station_lines(self, table: str) -> list[int] | None:
        """The file's line of each row of ``table`` (None where there is no such table)."""
        head = self.table_lines.get(table)
        if head is None or table not in self.tables:
            return None
        return [head + 2 + k for k in range(len(self.tables[table][1]))]

    def optional_column(self, table: str, *names: str) -> np.ndarray | None:
        if table not in self.tables:
            return None
        header, rows = self.tables[table]
        for name in names:
            if name in header:
                return np.asarray(rows[:, header.index(name)], dtype=float)
        return None


def _tokens(line: str) -> list[str]:
    """A line's tokens, a quoted first value whole (``"my tower.dat"   TwrFile``: a file name
    may hold a space, as OpenFAST reads it)."""
    stripped = line.lstrip()
    if stripped.startswith('"'):
        end = stripped.find('"', 1)
        if end > 0:
            return [stripped[: end + 1], *stripped[end + 1 :].split()]
    return line.split()


def parse(path: Path, text: str | None = None) -> Deck:
    """Read a FAST/ElastoDyn-style input file: ``value Key - description`` lines and tables."""
    text = read_text(path, ansi=True) if text is None else text
    values: dict[str, tuple[str, int]] = {}
    tables: dict[str, tuple[list[str], np.ndarray]] = {}
    table_lines: dict[str, int] = {}
    lines = text.splitlines()
    # an OpenFAST input file opens with a rule line and a free-text title ("Fixed MHK
    # turbine, based on …" is not the value "Fixed" of a key "MHK")
    title = 1 if lines and lines[0].lstrip().startswith(("-", "=")) else -1
    i = 0
    while i < len(lines):
        tokens = _tokens(lines[i])
        if (
            i != title
            and len(tokens) >= 2
            and tokens[1][:1].isalpha()
            and not tokens[0].startswith("--")
        ):
            first = values.setdefault(tokens[1], (tokens[0], i + 1))
            if (
                tokens[1] in UNIQUE
                and first[0] != tokens[0]
                and _NUMBER.match(first[0])
                and _NUMBER.match(tokens[0])
            ):
                raise SpecError(
                    f"{tokens[1]} is given twice, {first[0]} (line {first[1]}) and {tokens[0]}: "
                    "which one is meant?",
                    line=i + 1,
                    source=str(path),
                )
        if (
            len(tokens) >= 3
            and all(t[:1].isalpha() for t in tokens[:3])
            and (tokens[0] in ("HtFract", "BlFract"))
        ):
            rows, j = [], i + 2  # skip the units line
            while j < len(lines):
                cells = lines[j].split()
                if not cells or not _NUMBER.match(cells[0]):
                    break
                rows.append(_row(path, tokens, cells, j + 1))
                j += 1
            if rows:
                width = min(len(r) for r in rows)
                tables[tokens[0]] = (tokens[:width], np.array([r[:width] for r in rows]))
                table_lines[tokens[0]] = i + 1
            i = j
            continue
        i += 1
    return Deck(path, values, tables, table_lines)


def _row(path: Path, header: list[str], cells: list[str], line: int) -> list[float]:
    """One table row as numbers; a cell that is not a finite number names file, line and
    column (a text cell, a number cut off at the end of a truncated file)."""
    out = []
    for name, cell in zip(header, cells, strict=False):
        text = cell.replace("D", "E").replace("d", "e")
        value = float(text) if _NUMBER.match(cell) else math.nan
        if not math.isfinite(value):
            raise SpecError(
                f"column {name}: {cell!r} is not a finite number", line=line, source=str(path)
            )
        out.append(value)
    return out


def beside(base: Path, name: str) -> Path:
    """A file a deck names, resolved beside it (symlinks followed), the name read as Windows
    reads it where no file has it as written (:func:`.paths.locate`); a name that cannot be
    resolved (a symlink loop, a name too long) as given, for the reader to refuse."""
    path = locate(base.parent, name)
    try:
        return path.resolve()
    except (OSError, RuntimeError):  # RuntimeError: a symlink loop (Python < 3.13)
        return path


def finite(text: str, line: int, path: Path) -> float:
    """A cell of a file as a finite number, or one line naming file, line and cell."""
    value = float(_fortran(text)) if _NUMBER.match(text) else math.nan
    if not math.isfinite(value):
        raise SpecError(f"{text!r} is not a finite number", line=line, source=str(path))
    return value


#: Whether a named file is there (a name the file system cannot hold is not).
present = is_file


def _file(deck: Deck, *keys: str) -> Path:
    name = deck.text(*keys)
    path = beside(deck.path, name)
    line = next((deck.values[k][1] for k in keys if k in deck.values), None)
    try:
        found = path.is_file()
    except OSError as exc:  # a name too long for the file system
        raise SpecError(
            f"{keys[0]} names {name[:80]!r}: {exc.strerror}", line=line, source=str(deck.path)
        ) from None
    if not found:
        why = (
            "a symbolic link that leads nowhere (a loop, or a missing target)"
            if path.is_symlink()
            else "which does not exist"
        )
        raise SpecError(f"{keys[0]} names {name[:200]!r}, {why}", line=line, source=str(deck.path))
    return path


#: The .fst's environment block (OpenFAST ≥ 3.0), which a module's "default" air and water
#: properties stand for (OpenFAST input-file documentation, glue-code "ENVIRONMENTAL
#: CONDITIONS").
ENVIRONMENT = (
    "Gravity",
    "AirDens",
    "WtrDens",
    "KinVisc",
    "SpdSound",
    "Patm",
    "Pvap",
    "WtrDpth",
    "MSL2SWL",
)


def environment(fst: Deck | None) -> dict[str, tuple[float, str]]:
    """What a "default" environmental input stands for: the .fst's own value."""
    if fst is None:
        return {}
    return {
        key: (fst.num(key), f"the .fst's {key}, {fst.path.name} line {fst.values[key][1]}")
        for key in ENVIRONMENT
        if key in fst.values and not fst.is_default(key)
    }


#: OpenFAST's default sea-water density (kg/m³), its "default" WtrDens.
WATER_DENSITY = 1025.0


def sea_state(fst: Deck) -> Deck | None:
    """The deck set's SeaState file (OpenFAST ≥ 3.4), where it runs one."""
    if fst.num("CompSeaSt", default=0) > 0 and "SeaStFile" in fst.values:
        return parse(_file(fst, "SeaStFile"))
    return None


def sea_setting(hd: Deck, sea: Deck | None, key: str, default: float) -> float:
    """An environmental input of the water (WtrDens, MSL2SWL …): HydroDyn's own, else
    SeaState's, else the .fst's (through "default", :func:`environment` in ``hd.inherited``),
    else OpenFAST's default."""
    for deck in (hd, sea):
        if deck is not None and key in deck.values:
            return deck.num(key, default=default)
    env = hd.inherited.get(key)
    return env[0] if env is not None else default


@dataclass(frozen=True)
class Table:
    """A counted table of a SubDyn / HydroDyn file: its header's column names, its rows
    as text cells, and each row's line (for messages)."""

    path: Path
    header: list[str]
    rows: list[list[str]]
    lines: list[int]

    def has(self, name: str) -> bool:
        return name in self.header

    def numbers(self, name: str, default: float | None = None) -> np.ndarray:
        """A column as finite numbers; a missing column takes ``default`` (else SpecError),
        a cell that is not a number names file, line and column."""
        if name not in self.header:
            if default is not None:
                return np.full(len(self.rows), default)
            raise SpecError(
                f"the table headed {' '.join(self.header[:3])} … has no {name} column",
                line=self.lines[0] - 2 if self.lines else None,
                source=str(self.path),
            )
        col = self.header.index(name)
        out = []
        for row, line in zip(self.rows, self.lines, strict=True):
            cell = row[col] if col < len(row) else ""
            if not _NUMBER.match(cell) or not math.isfinite(value := float(_fortran(cell))):
                raise SpecError(
                    f"column {name}: {cell!r} is not a finite number"
                    if cell
                    else f"column {name} is missing from the row",
                    line=line,
                    source=str(self.path),
                )
            out.append(value)
        return np.asarray(out, dtype=float)

    def ids(self, name: str) -> list[int]:
        """An ID column (joint, member, property set): whole numbers."""
        values = self.numbers(name)
        for value, line in zip(values, self.lines, strict=True):
            if value != int(value):
                raise SpecError(
                    f"column {name}: {value:g} is not a whole-number ID",
                    line=line,
                    source=str(self.path),
                )
        return [int(v) for v in values]

    def texts(self, name: str) -> list[str]:
        col = self.header.index(name)
        return [row[col].strip('"') if col < len(row) else "" for row in self.rows]


def _fortran(cell: str) -> str:
    return cell.replace("D", "E").replace("d", "e")


#: The most rows a counted table may declare (a count of 1e9 in a corrupt file must not
#: make the reader walk the file for a billion rows).
MAX_TABLE_ROWS = 100_000


def counted(deck: Deck, text: str, keys: tuple[str, ...], column: str) -> Table | None:
    """The counted table whose count line has one of ``keys`` (``NJoints``, ``NPropSets``)
    and whose header has ``column`` — files read by key, never by line number (SubDyn and
    HydroDyn add, drop and rename sections between versions; a key used twice, such as
    SubDyn's NPropSets for circular and rectangular sections, is told apart by the
    header). The header is the next line, units lines in parentheses are skipped. None:
    no such count line; fewer rows than counted is a SpecError naming the line."""
    lines = text.splitlines()
    for i, line in enumerate(lines):
        tokens = line.split()
        if len(tokens) < 2 or tokens[1] not in keys or i + 1 >= len(lines):
            continue
        header = lines[i + 1].replace("!", " ").split()
        if column not in header:
            continue
        count_text = tokens[0]
        try:
            count = float(_fortran(count_text))
        except ValueError:
            count = math.nan
        if not (math.isfinite(count) and count == int(count) and 0 <= count <= MAX_TABLE_ROWS):
            raise SpecError(
                f"{tokens[1]} must be a whole number of rows from 0 to {MAX_TABLE_ROWS:,} "
                f"(got {count_text!r})",
                line=i + 1,
                source=str(deck.path),
            )
        j = i + 2
        while j < len(lines) and lines[j].strip().startswith("("):
            j += 1
        rows: list[list[str]] = []
        numbers: list[int] = []
        while len(rows) < int(count):
            cells = lines[j].split() if j < len(lines) else []
            if not cells or (cells[0].startswith("-") and not _NUMBER.match(cells[0])):
                raise SpecError(
                    f"{tokens[1]} = {int(count)}, but the table has {len(rows)} rows",
                    line=j + 1 if j < len(lines) else i + 1,
                    source=str(deck.path),
                )
            rows.append(cells)
            numbers.append(j + 1)
            j += 1
        return Table(deck.path, header, rows, numbers)
    return None
