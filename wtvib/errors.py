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
        where = self.source or ""
        if self.line is not None:
            where = f"{where}:{self.line}" if where else f"line {self.line}"
        field = f"{self.path}: " if self.path else ""
        prefix = f"{where}: " if where else ""
        return f"{prefix}{field}{self.message}"


class OutputError(WtvibError, OSError):
    """An output file that could not be written (read-only folder, full disk, would overwrite)."""


class WtvibWarning(UserWarning):
    """A legal but suspicious input, or an assumption the user should know about."""
