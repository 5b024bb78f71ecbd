"""IconContents decoded: the bytes its base64 text holds and what they are.

eds-pie types IconContents as a STRING; the real files write the base64 of an icon file
(cip_tables ``Base64Icon``): an ICO with BMP images (27 of 37 files), an ICO with a PNG
image (6), a BMP file (3), neither (1). That it is an ICO is practice, as the 2003 text's
``Icon = "*.ico"`` (C.4.1.4.3) is for the file named there. The formats are read as their
own specifications define them (ICO directory, BMP file header, PNG signature and IHDR), only
far enough to say what the data is and whether each image lies inside it.
"""

from __future__ import annotations

import base64
import binascii
import re
from dataclasses import dataclass, field

from edsconv.limits import shown

_PNG = b"\x89PNG\r\n\x1a\n"
#: BITMAPCOREHEADER, BITMAPINFOHEADER, V4 and V5 header sizes: what a BMP image inside an ICO starts with
_DIB_HEADER_SIZES = frozenset({12, 40, 108, 124})
_BASE64 = re.compile(r"[A-Za-z0-9+/]*={0,2}")
_WHITE_SPACE = re.compile(r"\s+")


@dataclass(frozen=True, slots=True)
class IconImage:
    """One image of an icon file."""

    width: int
    height: int
    #: bits per pixel as the directory or header says (None for a PNG, which has its own)
    bits_per_pixel: int | None
    #: "bmp" or "png"
    encoding: str
    #: bytes of the image data
    size: int


@dataclass(slots=True)
class Icon:
    """IconContents: the decoded bytes and what they are."""

    #: the bytes; None when the text is not base64
    data: bytes | None = field(repr=False)
    #: "ico", "bmp", "png", "other" or "not base64"
    kind: str
    images: tuple[IconImage, ...] = ()
    #: why it is not a valid ICO; None for one
    problem: str | None = None

    @property
    def valid_ico(self) -> bool:
        return self.kind == "ico" and self.problem is None


def decode_icon(text: str) -> Icon:
    """What the base64 ``text`` of an IconContents holds (white space between parts is ignored)."""
    compact = _WHITE_SPACE.sub("", text)
    if not _BASE64.fullmatch(compact):
        bad = next((c for c in compact if not re.fullmatch(r"[A-Za-z0-9+/=]", c)), None)
        if bad is None:  # every character is one of base64's, but '=' stands before the end
            return Icon(None, "not base64", problem="'=' pads only the end of base64 text")
        return Icon(None, "not base64", problem=f"{shown(bad)} is not a base64 character")
    try:
        data = base64.b64decode(compact, validate=True)
    except binascii.Error as error:
        return Icon(None, "not base64", problem=f"not base64 ({error})")
    if data[:4] == b"\0\0\1\0":
        return _ico(data)
    if data[:2] == b"BM":
        image = _dib_image(data[14:], len(data))
        return Icon(data, "bmp", (image,) if image else (), "a BMP file, not an ICO")
    if data[:8] == _PNG:
        image = _png_image(data)
        return Icon(data, "png", (image,) if image else (), "a PNG file, not an ICO")
    return Icon(data, "other", problem=f"neither an ICO nor a BMP or PNG file (starts {data[:4].hex(' ')})")


def _ico(data: bytes) -> Icon:
    count = int.from_bytes(data[4:6], "little")
    if count == 0:
        return Icon(data, "ico", problem="the ICO holds no image")
    if len(data) < 6 + 16 * count:
        return Icon(data, "ico", problem=f"the ICO directory of {count} images is longer than the data")
    images: list[IconImage] = []
    for index in range(count):
        directory = data[6 + 16 * index:22 + 16 * index]
        size, offset = int.from_bytes(directory[8:12], "little"), int.from_bytes(directory[12:16], "little")
        if offset + size > len(data):
            return Icon(data, "ico", tuple(images), f"image {index + 1} ({size} bytes at offset {offset}) lies "
                                                    f"beyond the end of the {len(data)} bytes")
        image_data = data[offset:offset + size]
        width, height = directory[0] or 256, directory[1] or 256
        bits = int.from_bytes(directory[6:8], "little") or None
        if image_data[:8] == _PNG:
            images.append(IconImage(width, height, None, "png", size))
        elif int.from_bytes(image_data[:4], "little") in _DIB_HEADER_SIZES:
            images.append(IconImage(width, height, bits, "bmp", size))
        else:
            return Icon(data, "ico", tuple(images), f"image {index + 1} is neither a BMP nor a PNG image")
    return Icon(data, "ico", tuple(images))


def _dib_image(header: bytes, size: int) -> IconImage | None:
    if int.from_bytes(header[:4], "little") not in _DIB_HEADER_SIZES or len(header) < 16:
        return None
    if int.from_bytes(header[:4], "little") == 12:
        width, height, bits = (int.from_bytes(header[4:6], "little"), int.from_bytes(header[6:8], "little"),
                               int.from_bytes(header[10:12], "little"))
    else:
        width, height = int.from_bytes(header[4:8], "little", signed=True), \
            int.from_bytes(header[8:12], "little", signed=True)
        bits = int.from_bytes(header[14:16], "little")
    return IconImage(abs(width), abs(height), bits, "bmp", size)


def _png_image(data: bytes) -> IconImage | None:
    if data[12:16] != b"IHDR" or len(data) < 24:
        return None
    return IconImage(int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big"), None, "png", len(data))
