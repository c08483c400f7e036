"""The terminal and the standard streams as the environment gives them: closed, full, a
pipe that went away, an encoding that cannot spell "Tjæreborg". None of these is a wtvib
bug (exit 3) or a verdict; each is one line and exit 2, or a quiet fallback where the user
asked for it (``>&-`` discards the output).

User text bound for a terminal also passes :func:`shown`: control characters never reach
it, and bidirectional overrides (U+202E, U+2066 …), which make a terminal show text in
another order than it is, are written as escapes.
"""

from __future__ import annotations

import codecs
import contextlib
import errno
import os
import re
import sys

#: C0/C1 control characters other than tab and newline.
_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f]")
#: Unicode's bidirectional formatting characters (UAX #9: embeddings, overrides,
#: isolates, marks) — the "Trojan Source" set, CVE-2021-42574.
_BIDI = re.compile("[\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069]")


def shown(text: object) -> str:
    """``text`` as a terminal may show it: controls as "?", bidi controls as ``\\u202e``,
    and a character the standard output's encoding cannot write as its escape here —
    before rich measures the text, so that its tables stay aligned."""
    plain = _BIDI.sub(lambda m: f"\\u{ord(m.group()):04x}", _CONTROL.sub("?", str(text)))
    encoding = getattr(sys.stdout, "encoding", None) or "utf-8"
    try:
        plain.encode(encoding)
    except UnicodeEncodeError:
        return plain.encode(encoding, errors="wtvib.escape").decode(encoding)
    except LookupError:  # an encoding Python does not know: the stream's handler escapes
        pass
    return plain


def _json_escape(error: UnicodeError) -> tuple[str, int]:
    """A character the stream's encoding cannot write, as a JSON/Python ``\\uXXXX`` escape
    (UTF-16 pairs above the BMP): valid inside a JSON string, readable in text."""
    if not isinstance(error, UnicodeEncodeError):
        raise error
    out = []
    for ch in error.object[error.start : error.end]:
        code = ord(ch)
        if code > 0xFFFF:
            code -= 0x10000
            out.append(f"\\u{0xD800 + (code >> 10):04x}\\u{0xDC00 + (code & 0x3FF):04x}")
        else:
            out.append(f"\\u{code:04x}")
    return "".join(out), error.end


codecs.register_error("wtvib.escape", _json_escape)

#: errno values that mean the output has nowhere to go.
_LOST = {errno.ENOSPC, errno.EPIPE, errno.EBADF, errno.EIO, errno.EDQUOT, errno.EFBIG}


def guard() -> None:
    """Make the standard streams safe to write for the whole run: a closed descriptor
    (``>&-``) becomes /dev/null — before any file wtvib opens could take its number and
    receive the report — and a stream whose encoding cannot write a character escapes it
    instead of raising."""
    for fd in (0, 1, 2):
        try:
            os.fstat(fd)
        except OSError:
            opened = os.open(os.devnull, os.O_RDWR)  # the lowest free number: this one
            if opened != fd:
                os.dup2(opened, fd)
                os.close(opened)
    for name, fd in (("stdout", 1), ("stderr", 2)):
        stream = getattr(sys, name)
        if stream is None:
            stream = open(fd, "w", encoding="utf-8", closefd=False)  # noqa: SIM115
            setattr(sys, name, stream)
        with contextlib.suppress(AttributeError, ValueError, OSError):  # not a TextIOWrapper
            stream.reconfigure(errors="wtvib.escape")


def lost_output(exc: BaseException) -> str | None:
    """The one line for an exception that says the standard output could not be written
    (full disk, closed pipe), or None when it is about something else."""
    if not isinstance(exc, OSError) or exc.errno not in _LOST or exc.filename is not None:
        return None
    return f"the output could not be written to standard output ({os.strerror(exc.errno)})"


def discard_stdout() -> None:
    """Point the standard output at /dev/null, so that what is still buffered for a full
    disk or a closed pipe does not fail again, with a traceback, when Python exits."""
    try:
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, sys.stdout.fileno())
        os.close(null)
    except (OSError, ValueError, AttributeError):
        pass
