"""PNG figures in a PDF without decoding them: the PNG's own compressed pixels as the image.

A PDF image may be Flate-compressed with PNG row predictors (PDF 1.7, ISO 32000-1 §7.4.4.4:
``/DecodeParms << /Predictor 15 /Colors 3 /BitsPerComponent 8 /Columns w >>``), which is
exactly what the IDAT chunks of a non-interlaced 8-bit PNG hold. reportlab's ``Image``
decodes each PNG, hashes the raw pixels and compresses them again: the 17-turbine
catalogue PDF took 4.6 s to build, 2.2 s with :class:`PngImage`, which embeds the IDAT data
as it is — the same pixels (a test decodes them back), no decoding. The file is larger
(9.1 MB against 7.6 MB: wtvib writes its PNGs at zlib's fastest level, reportlab
recompressed at its default). A PNG it cannot pass through (interlaced, palette, 16-bit,
alpha, truncated) is handed to reportlab's ``Image`` instead.

reportlab is imported at the top: import this module only where a PDF is built.
"""

import hashlib
import io
from dataclasses import dataclass
from typing import Any

from reportlab.pdfbase.pdfdoc import PDFDictionary, PDFImageXObject, PDFName, PDFStream
from reportlab.platypus import Flowable, Image

from . import png

#: PNG colour types a PDF can take straight: 0 grey (1 component), 2 RGB (3)
_COLOURS = {0: (1, "DeviceGray"), 2: (3, "DeviceRGB")}


@dataclass(frozen=True)
class PngStream:
    """What a PDF image needs from a PNG: size, components and the compressed rows."""

    width: int
    height: int
    colours: int
    colour_space: str
    data: bytes


def png_stream(data: bytes) -> PngStream | None:
    """The PNG's size and concatenated IDAT data, or None if a PDF cannot take it as it is
    (not a PNG, interlaced, not 8 bits per sample, palette or alpha channel, truncated)."""
    header = png.header(data)
    idat, complete = [], False
    for kind, body in png.chunks(data):
        if kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            complete = True
            break
    if header is None or not idat or not complete:
        return None
    width, height, depth, colour_type, compression, filtering, interlace = header
    if depth != 8 or colour_type not in _COLOURS or (compression, filtering, interlace) != (0,) * 3:
        return None
    colours, space = _COLOURS[colour_type]
    return PngStream(width, height, colours, space, b"".join(idat))


class _PngXObject(PDFImageXObject):  # type: ignore[misc]
    """An image XObject whose stream is a PNG's IDAT data, with the PNG predictors."""

    def __init__(self, name: str, stream: PngStream) -> None:
        super().__init__(name)  # reportlab's placeholder image, replaced below
        self.width, self.height = stream.width, stream.height
        self.bitsPerComponent = 8
        self.colorSpace = stream.colour_space
        self.streamContent = stream.data
        self._filters = ("FlateDecode",)
        self.mask = None
        self._stream = stream

    def format(self, document: Any) -> bytes:
        s = PDFStream(content=self.streamContent)
        d = s.dictionary
        d["Type"] = PDFName("XObject")
        d["Subtype"] = PDFName("Image")
        d["Width"] = self.width
        d["Height"] = self.height
        d["BitsPerComponent"] = 8
        d["ColorSpace"] = PDFName(self.colorSpace)
        # one filter, named (not an array): DecodeParms is then one dictionary, which every
        # reader applies (poppler ignores a dictionary beside a Filter array)
        d["Filter"] = PDFName("FlateDecode")  # set: reportlab compresses no more
        d["DecodeParms"] = PDFDictionary(
            {
                "Predictor": 15,  # PNG predictors, chosen per row (the row's filter byte)
                "Colors": self._stream.colours,
                "BitsPerComponent": 8,
                "Columns": self.width,
            }
        )
        d["Length"] = len(self.streamContent)
        return s.format(document)  # type: ignore[no-any-return]


class PngImage(Flowable):  # type: ignore[misc]
    """A PNG drawn ``width`` × ``height`` points, its compressed pixels embedded as they are
    (once per document however often it is drawn)."""

    def __init__(self, data: bytes, stream: PngStream, width: float, height: float) -> None:
        super().__init__()
        self._stream = stream
        self._name = "wtvibpng" + hashlib.sha1(data).hexdigest()
        self.drawWidth, self.drawHeight = width, height

    def wrap(self, available_width: float, available_height: float) -> tuple[float, float]:
        return self.drawWidth, self.drawHeight

    def draw(self) -> None:
        # what reportlab's Canvas.drawImage does for an image it has made itself
        canvas, doc = self.canv, self.canv._doc
        registered = doc.getXObjectName(self._name)
        if not doc.idToObject.get(registered):
            image = _PngXObject(self._name, self._stream)
            canvas._setXObjects(image)
            doc.Reference(image, registered)
            doc.addForm(self._name, image)
        canvas._currentPageHasImages = 1
        canvas.saveState()
        canvas.scale(self.drawWidth, self.drawHeight)
        canvas._code.append(f"/{registered} Do")
        canvas.restoreState()
        canvas._formsinuse.append(self._name)


def image(data: bytes, width: float, height: float) -> Any:
    """A flowable of the PNG ``data``: passed through where it can be, else reportlab's
    ``Image``."""
    stream = png_stream(data)
    if stream is None:
        return Image(io.BytesIO(data), width=width, height=height)
    return PngImage(data, stream, width, height)
