"""The PNG format, as much of it as wtvib writes and reads (W3C PNG specification, §5):
the signature, then chunks of a 4-byte length, a 4-byte type, the data and the CRC-32 of
type and data. Written by :func:`wtvib.outputs.plots.png_bytes`; read by :mod:`wtvib.outputs.files`
(is
a file wtvib's?) and :mod:`wtvib.outputs.pdfpng` (the PDF takes a PNG's compressed rows)."""

import struct
import zlib
from collections.abc import Iterator

SIGNATURE = b"\x89PNG\r\n\x1a\n"


def chunk(kind: bytes, data: bytes) -> bytes:
    """One chunk: length, type, data, CRC."""
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def text(keyword: str, value: str) -> bytes:
    """An international text chunk (iTXt, §11.3.4.5): a Latin-1 keyword of 1–79 bytes and
    an uncompressed UTF-8 value (a figure's title holds ζ and dashes, which tEXt's Latin-1
    cannot)."""
    key = keyword.encode("latin-1")
    assert 1 <= len(key) <= 79, keyword
    return chunk(b"iTXt", key + b"\x00\x00\x00" + b"\x00" + b"\x00" + value.encode("utf-8"))


def texts(data: bytes) -> dict[str, str]:
    """The text chunks (tEXt and uncompressed iTXt) of a PNG, by keyword."""
    out = {}
    for kind, body in chunks(data):
        if kind == b"tEXt":
            key, _, value = body.partition(b"\x00")
            out[key.decode("latin-1")] = value.decode("latin-1")
        elif kind == b"iTXt":
            key, _, rest = body.partition(b"\x00")
            if rest[:1] == b"\x00":  # not compressed
                _, _, rest = rest[2:].partition(b"\x00")  # the language tag
                _, _, value = rest.partition(b"\x00")  # the translated keyword
                out[key.decode("latin-1")] = value.decode("utf-8", "replace")
    return out


def chunks(data: bytes) -> Iterator[tuple[bytes, bytes]]:
    """The (type, data) of each whole chunk of a PNG, in order: none if ``data`` is not a
    PNG, and none from a chunk cut short on (a file's head, a truncated file)."""
    if not data.startswith(SIGNATURE):
        return
    pos = len(SIGNATURE)
    while pos + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[pos : pos + 8])
        body = data[pos + 8 : pos + 8 + length]
        if len(body) < length:
            return
        yield kind, body
        pos += 12 + length


def header(data: bytes) -> tuple[int, int, int, int, int, int, int] | None:
    """The IHDR fields — width, height, bit depth, colour type, compression, filter and
    interlace methods — or None if ``data`` is not a PNG with a whole IHDR first."""
    for kind, body in chunks(data):
        if kind == b"IHDR" and len(body) >= 13:
            return struct.unpack(">IIBBBBB", body[:13])
        return None  # IHDR must come first (§5.6)
    return None
