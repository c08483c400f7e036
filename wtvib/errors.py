"""The project's exceptions and warnings (STYLE.md habit 7)."""


class WtvibError(Exception):
    """Base of every error wtvib raises on purpose."""


class SpecError(WtvibError, ValueError):
    """A turbine description that cannot be used: one readable line, naming field and line.

    Parameters
    ----------
    message
        What is wrong, in words a user understands.
    path
        Dotted field path inside the document (``rotor.speed.min_rpm``), if known.
    line
        1-based line number in the source file, if known.
    source
        The file the value came from, if known.
    """

    def __init__(
        self,
        message: str,
        *,
        path: str | None = None,
        line: int | None = None,
        source: str | None = None,
    ) -> None:
        self.message = message
        self.path = path
        self.line = line
        self.source = source
        super().__init__(self.one_line())

    def one_line(self) -> str:
        """``file:line: field: message``, each part at most :data:`LONGEST` characters (a
        100 kB mode id quoted in a message stays a line a terminal can show)."""
        where = _short(self.source or "")
        if self.line is not None:
            where = f"{where}:{self.line}" if where else f"line {self.line}"
        field = f"{_short(self.path)}: " if self.path else ""
        prefix = f"{where}: " if where else ""
        return f"{prefix}{field}{_short(self.message)}"


#: The longest part of an error line (file, field, message), characters.
LONGEST = 1000


def _short(text: str) -> str:
    if len(text) <= LONGEST:
        return text
    half = LONGEST // 2
    return f"{text[:half]}… ({len(text) - LONGEST:,} characters left out) …{text[-half:]}"


class OutputError(WtvibError, OSError):
    """An output file that could not be written (read-only folder, full disk, would overwrite)."""


class OptionError(WtvibError, ValueError):
    """A command-line option given a value it cannot take: ``--rpm: takes MIN:MAX …``."""

    def __init__(self, option: str, message: str) -> None:
        self.option = option
        super().__init__(f"{option}: {message}")
