"""Bytes to text: encoding detection, line ends, and offset -> line/column.

An EDS is ASCII (C.4.1.3.2), but real files carry UTF-8 (with or without BOM)
and Windows-1252 / Latin-1 text, and some Windows tools save UTF-16 with a BOM.
We accept all of them and report one warning that names the first offending
line, as real configuration tools do.
"""

from __future__ import annotations

import bisect
import codecs
import re
from array import array
from dataclasses import dataclass

_NON_ASCII = re.compile(rb"[\x80-\xff]")
_LINE_START = re.compile(r"\n")
#: A line and its line end, as the reader and LSP count lines (\r\n, \r or \n).
_LINE = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+$")


@dataclass(frozen=True, slots=True)
class DecodedSource:
    text: str
    #: "ascii", "utf-8", "utf-8-sig", "cp1252"/"latin-1", or one of the UTF-16/32 codecs of :data:`_WIDE_BOMS`
    encoding: str
    #: "\n", "\r\n" or "\r": what the file used first, so a writer can keep it.
    newline: str
    #: 1-based line of the first byte outside ASCII, or None for a pure ASCII file.
    first_non_ascii_line: int | None


#: Byte order marks of the wide encodings, UTF-32 first: its little-endian BOM begins with UTF-16's.
_WIDE_BOMS = ((codecs.BOM_UTF32_LE, "utf-32-le"), (codecs.BOM_UTF32_BE, "utf-32-be"),
              (codecs.BOM_UTF16_LE, "utf-16-le"), (codecs.BOM_UTF16_BE, "utf-16-be"))


def _wide_encoding(data: bytes) -> tuple[str, int] | None:
    """The codec and BOM length of a UTF-16/UTF-32 file, recognised by its byte order mark."""
    for bom, encoding in _WIDE_BOMS:
        if data.startswith(bom):
            return encoding, len(bom)
    return None


def has_wide_bom(data: bytes) -> bool:
    """Whether ``data`` starts with the byte order mark of UTF-16 or UTF-32."""
    return _wide_encoding(data) is not None


def decode(data: bytes) -> DecodedSource:
    """Decode EDS bytes and normalise every line end to ``\\n``."""
    wide = _wide_encoding(data)
    if wide is not None:
        encoding, bom_length = wide
        # The byte order mark is outside ASCII, so a wide file's first such character is on line 1.
        return _with_newlines(data[bom_length:].decode(encoding, errors="replace"), encoding, 1)
    encoding = "ascii"
    if data.startswith(codecs.BOM_UTF8):
        data, encoding = data[len(codecs.BOM_UTF8):], "utf-8-sig"
    first = None if data.isascii() else _NON_ASCII.search(data)  # isascii() runs far faster than a regex
    first_line = data.count(b"\n", 0, first.start()) + 1 if first else None
    if first is None:
        text = data.decode("ascii")
    else:
        try:
            text = data.decode("utf-8")
            encoding = "utf-8-sig" if encoding == "utf-8-sig" else "utf-8"
        except UnicodeDecodeError:
            # cp1252 leaves five bytes undefined; Latin-1 maps every byte.
            try:
                text, encoding = data.decode("cp1252"), "cp1252"
            except UnicodeDecodeError:
                text, encoding = data.decode("latin-1"), "latin-1"
    return _with_newlines(text, encoding, first_line)


def _with_newlines(text: str, encoding: str, first_line: int | None) -> DecodedSource:
    """The source with every line end normalised to ``\\n``, remembering the first one used."""
    newline = newline_of(text)
    return DecodedSource(_with_line_feeds(text) if newline != "\n" else text, encoding, newline, first_line)


def _with_line_feeds(text: str) -> str:
    return text.replace("\r\n", "\n").replace("\r", "\n")


def as_read(text: str) -> str:
    """The text the reader makes of ``text`` (characters, as an editor holds them) and counts its
    offsets in: without a byte order mark, every line end ``\n`` (:func:`decode`)."""
    text = text.removeprefix("\ufeff")
    return _with_line_feeds(text) if "\r" in text else text


def split_lines(text: str) -> list[str]:
    """The lines of ``text`` with their line ends."""
    return _LINE.findall(text)


def newline_of(text: str) -> str:
    """The line end ``text`` uses first (``\n`` when it has no CR), which the reader keeps (:func:`decode`)."""
    first_cr = text.find("\r")
    return "\n" if first_cr == -1 else "\r\n" if text.startswith("\r\n", first_cr) else "\r"


def encode(text: str, encoding: str) -> bytes:
    """``text`` in the encoding a file was read in, with the byte order mark it had."""
    for bom, wide in _WIDE_BOMS:
        if wide == encoding:
            return bom + text.encode(encoding)
    return text.encode(encoding)


class LineIndex:
    """The text of a file, and its character offsets -> 1-based line and column numbers.

    The line starts are found on the first question (many reads never ask one) and kept
    as 8-byte machine integers, not a list of int objects (40 bytes a line).
    """

    __slots__ = ("_starts", "text")

    def __init__(self, text: str) -> None:
        self.text = text
        self._starts: array[int] | None = None

    def _line_starts(self) -> array[int]:
        if self._starts is None:
            self._starts = array("q", [0])
            self._starts.extend(map(re.Match.end, _LINE_START.finditer(self.text)))
        return self._starts

    def edited(self, text: str, at: int, old_end: int, new_end: int) -> LineIndex:
        """The index of ``text``, which an edit made of this index's text by putting ``text[at:new_end]`` in
        place of ``[at, old_end)``: the lines before the edit start where they did, those after it
        ``new_end - old_end`` characters later."""
        starts = self._line_starts()
        index = LineIndex(text)
        shift = new_end - old_end
        kept, after = bisect.bisect_right(starts, at), bisect.bisect_right(starts, old_end)
        typed = array("q", map(re.Match.end, _LINE_START.finditer(text, at, new_end)))
        if shift or typed or kept != after:
            starts = starts[:kept] + typed + array("q", [start + shift for start in starts[after:]])
        index._starts = starts  # never changed once made: shared when nothing moved
        return index

    def lines_moved(self, offset: int, delta: int) -> None:
        """Number the lines from the one holding ``offset`` on ``delta`` more (fewer, when negative), columns
        as they were: the language server re-uses nodes read from this text in a newer text, where an edit
        before them added (removed) that many lines (:mod:`edsconv.lsp.incremental`). The line starts
        removed are the last ones before that line: the caller knows that no node it still reads from
        this text lies on those lines."""
        starts = self._line_starts()
        line = bisect.bisect_right(starts, offset) - 1  # the last copy of the line's start
        # a new array: an index made by edited() may share this one
        if delta > 0:
            self._starts = starts[:line] + array("q", [starts[line]]) * delta + starts[line:]
        else:
            self._starts = starts[:line + delta] + starts[line:]

    def position(self, offset: int) -> tuple[int, int]:
        starts = self._line_starts()
        line = bisect.bisect_right(starts, offset)
        return line, offset - starts[line - 1] + 1

    def offset(self, line: int, column: int) -> int:
        """The offset of 1-based ``line`` and ``column``: :meth:`position` undone."""
        return self._line_starts()[line - 1] + column - 1

    def starts_line(self, offset: int) -> bool:
        """True when only white space stands between the line start and ``offset``."""
        starts = self._line_starts()
        line_start = starts[bisect.bisect_right(starts, offset) - 1]
        return not self.text[line_start:offset].strip()
