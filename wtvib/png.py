"""The PNG format, as much of it as wtvib writes and reads (W3C PNG specification, §5):
the signature, then chunks of a 4-byte length, a 4-byte type, the data and the CRC-32 of
type and data. Written by :func:`wtvib.plots.png_bytes`; read by :mod:`wtvib.outputs` (is
a file wtvib's?) and :mod:`wtvib.pdfpng` (the PDF takes a PNG's compressed rows)."""

import struct
import zlib
from collections.abc import Iterator

SIGNATURE = b"\x89PNG\r\n\x1a\n"


def chunk(kind: bytes, data: bytes) -> bytes:
    """One chunk: length, type, data, CRC."""
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


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
