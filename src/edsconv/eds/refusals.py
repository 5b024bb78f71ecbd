"""The EDS input refused before it is read, with one diagnostic each (EDS025-EDS027).

Every command reads an EDS through :func:`edsconv.eds.reader.parse` (``load``, lint, fmt,
the language server), which asks :func:`refusal` first: a file past the size limit, a
binary file, UTF-16 without a byte order mark, and an XML profile get one line that says
what the file is, not a hundred syntax errors of escaped bytes or a MemoryError.
"""

from __future__ import annotations

import os
import re

from edsconv.diagnostics import Rule, Severity, block, rule
from edsconv.eds.source import has_wide_bom
from edsconv.limits import MAX_EDS_BYTES

TOO_LARGE = rule(
    "EDS025", Severity.ERROR, "edsconv", "The file exceeds the EDS input size limit and was not read",
    explanation=f"""
        edsconv reads EDS files of up to {MAX_EDS_BYTES // (1024 * 1024)} MiB (the largest real file
        is 364 KB; generated ones reach tens of MB). A larger file, or a device such as
        `/dev/zero`, is refused before it is read: its models would take gigabytes. The
        XML profiles have the same limit (XML006).
    """,
    bad="`edsconv lint /dev/zero`",
    good="`edsconv lint device.eds` (a file under the limit)",
)
NOT_TEXT = rule(
    "EDS026", Severity.ERROR, "C.4.1.3.2", "The file is binary, or UTF-16 text without a byte order mark",
    explanation="""
        An EDS is text (ASCII, C.4.1.3.2; edsconv also reads UTF-8, Windows-1252 and
        UTF-16/32 with a byte order mark). A file with NUL or other control bytes among
        its first bytes is not text (a program, an archive, an image), and one whose
        every other byte is NUL is UTF-16 saved without a byte order mark, which no tool
        can tell from binary reliably. One diagnostic says which; nothing else is read.
    """,
    bad="`cp /bin/ls device.eds; edsconv lint device.eds`",
    good="Save the file as ASCII (or UTF-16 with a byte order mark).",
)
XML_NOT_EDS = rule(
    "EDS027", Severity.ERROR, "C.4.1.2.2", "The file is XML (an ISO 15745 profile?), not an EDS",
    explanation="""
        The file starts with `<` (an XML declaration or element): it is an XML document,
        such as the ISO 15745-4 profiles eds2xml writes, not an EDS. `edsconv validate`
        checks a profile, and `edsconv xml2eds` converts one into an EDS.
    """,
    bad=block("""
        <?xml version="1.0" encoding="utf-8"?>
        <ISO15745Profile>
    """, "xml"),
    good="`edsconv validate device.xml`, `edsconv xml2eds device.xml commnet.xml`",
)

#: How much of the file start is examined.
_HEAD = 8192
#: Control bytes that text never holds (tab, line ends, form feed, vertical tab and Ctrl-Z excepted).
_CONTROL = re.compile(rb"[\x00-\x08\x0e-\x19\x1b-\x1f]")
_XML_START = re.compile(rb"(?:\xef\xbb\xbf)?\s*<[?!A-Za-z]")


def read_bytes(path: str | os.PathLike[str]) -> bytes:
    """The bytes of an EDS file, but never more than one past the size limit: a larger file (or
    ``/dev/zero``) is refused by :func:`refusal`, not read whole."""
    with open(path, "rb") as file:
        return file.read(MAX_EDS_BYTES + 1)


def refusal(data: bytes) -> tuple[Rule, str] | None:
    """The rule and message that refuse ``data`` before it is read as an EDS, or None."""
    if len(data) > MAX_EDS_BYTES:
        return TOO_LARGE, (f"the file is larger than {MAX_EDS_BYTES // (1024 * 1024)} MiB, the EDS input limit; "
                           f"it was not read")
    head = data[:_HEAD]
    if has_wide_bom(head):
        return None  # UTF-16/32 with a byte order mark: decoded, with a warning (EDS005)
    wide = _utf16_without_bom(head)
    if wide is not None:
        return NOT_TEXT, (f"the file looks like {wide} text without a byte order mark (every other byte is NUL); "
                          f"an EDS is ASCII: save it as ASCII, or with a byte order mark")
    control = len(_CONTROL.findall(head))
    # a stray control byte in a string is EDS116; a program or an image has NULs and controls throughout
    if head.count(0) >= 8 or (control >= 8 and control * 20 > len(head)):
        return NOT_TEXT, (f"the file is binary, not text ({control} NUL or control bytes among its first "
                          f"{len(head)}); an EDS is ASCII text")
    if _XML_START.match(head):
        return XML_NOT_EDS, ("the file is XML, not an EDS: `edsconv validate` checks a profile, `edsconv xml2eds` "
                             "converts one into an EDS")
    return None


def _utf16_without_bom(head: bytes) -> str | None:
    """"UTF-16-LE" or "UTF-16-BE" when most characters of ``head`` are ASCII with a NUL byte beside
    them; None otherwise (a BOM is read by the decoder, before this is asked)."""
    pairs = len(head) // 2
    if pairs < 2:
        return None
    odd_nuls, even_nuls = head[1::2].count(0), head[0::2].count(0)
    if odd_nuls * 10 >= pairs * 9 and even_nuls * 10 < pairs:
        return "UTF-16-LE"
    if even_nuls * 10 >= pairs * 9 and odd_nuls * 10 < pairs:
        return "UTF-16-BE"
    return None
