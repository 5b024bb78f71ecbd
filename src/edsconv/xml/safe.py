"""The one place where edsconv parses XML it did not write.

Profiles come from vendors and download sites, so the parser is hardened:
entities are never expanded, no DTD is loaded, nothing is fetched from the
network, libxml2 keeps its size limits (``huge_tree=False``) and the input is
bounded by :data:`MAX_XML_BYTES`. A document type declaration that declares
entities (billion laughs, external entity / XXE attacks) is refused outright
with :class:`UnsafeXmlError` rather than parsed: no ISO 15745 profile needs one.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from edsconv.diagnostics import Diagnostic, Rule

#: Larger inputs are refused before parsing. The biggest real profiles are a few MiB.
MAX_XML_BYTES = 64 * 1024 * 1024


# An entity declaration can only stand in a DOCTYPE's internal subset; looking
# for one in the raw bytes, in each encoding XML allows without a declaration,
# refuses the document before libxml2 reads a single declaration.
_ENCODINGS = ("utf-8", "utf-16-le", "utf-16-be")


_ENTITY_MESSAGE = ("DOCTYPE declares entities; refused to prevent entity expansion "
                   "(billion laughs) and external entity (XXE) attacks")


class XmlError(Exception):
    """An XML input that cannot be used; carries the 1-based position of the problem."""

    def __init__(self, message: str, line: int = 0, column: int = 0) -> None:
        super().__init__(message)
        self.message = message
        self.line = line
        self.column = column


class XmlSyntaxError(XmlError):
    """The input is not well-formed XML."""


class UnsafeXmlError(XmlError):
    """The input uses a construct edsconv refuses to process (entity declarations)."""


class XmlTooLargeError(XmlError):
    """The input exceeds :data:`MAX_XML_BYTES`."""


@dataclass(frozen=True, slots=True)
class XmlDocument:
    tree: etree._ElementTree
    #: The decoded source lines, for the positions libxml2 does not record.
    lines: list[str]
    #: The file it was read from (None for bytes or a tree built in memory).
    path: str | None = None

    @classmethod
    def of(cls, source: XmlDocument | etree._ElementTree | etree._Element) -> XmlDocument:
        """``source`` as a document; a tree or element without its text gives the lines libxml2
        records and column 1."""
        if isinstance(source, XmlDocument):
            return source
        return cls(source if isinstance(source, etree._ElementTree) else source.getroottree(), [])

    def diagnostic(self, rule: Rule, message: str, element: etree._Element) -> Diagnostic:
        """A diagnostic of ``rule`` at ``element``'s start tag in this document's file."""
        return Diagnostic.of(rule, message, *self.position(element), self.path)

    def position(self, element: etree._Element) -> tuple[int, int]:
        """Line and column of ``element``'s start tag.

        libxml2 records the line where the start tag *ends* and no column, so
        the tag's ``<`` is looked for on that line and the few before it.
        """
        line = source_line(element)
        if not line:
            return 0, 0
        qname = etree.QName(element)
        opening = "<" + (f"{element.prefix}:" if element.prefix else "") + qname.localname
        for candidate in range(min(line, len(self.lines)), max(0, line - 20), -1):
            column = self.lines[candidate - 1].rfind(opening)
            if column >= 0:
                return candidate, column + 1
        return line, 1


def source_line(element: etree._Element) -> int:
    """The line libxml2 recorded for ``element``, 0 when none (lxml-stubs 0.5 leave ``sourceline`` untyped)."""
    line: object = element.sourceline
    return line if isinstance(line, int) else 0


def read_xml(path: str | Path, max_bytes: int = MAX_XML_BYTES) -> XmlDocument:
    """Read and parse the file at ``path``; ``OSError`` propagates for missing files."""
    with open(path, "rb") as stream:
        data = stream.read(max_bytes + 1)
    return parse_xml(data, max_bytes, str(path))


def parse_xml(data: bytes, max_bytes: int = MAX_XML_BYTES, path: str | None = None) -> XmlDocument:
    """Parse ``data`` (read from ``path``, if any) safely, raising an :class:`XmlError` subclass
    for anything unusable."""
    if len(data) > max_bytes:
        # not read, so no position within it: the file as a whole, from its start
        raise XmlTooLargeError(f"input larger than {max_bytes} bytes refused", 1, 1)
    _refuse_entity_declarations(data)
    parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False, dtd_validation=False,
                             huge_tree=False)
    try:
        root = etree.fromstring(data, parser)
    except etree.XMLSyntaxError as error:
        line, column = error.position
        # libxml2 repeats the position at the end of its message; the diagnostic carries it already.
        message = re.sub(r", line \d+, column \d+$", "", error.msg)
        raise XmlSyntaxError(f"not well-formed: {_plain(message)}{_eds_hint(data)}", line, column) from None
    tree = root.getroottree()
    dtd = tree.docinfo.internalDTD
    # lxml-stubs 0.5 do not declare DTD.iterentities
    if dtd is not None and any(True for _ in dtd.iterentities()):  # type: ignore[union-attr]
        # Reached only by encodings the byte scan does not cover.
        raise UnsafeXmlError(_ENTITY_MESSAGE, 1, 1)
    return XmlDocument(tree, data.decode(tree.docinfo.encoding or "utf-8", errors="replace").splitlines(), path)


#: libxml2's advice to use an option a user cannot set, in plain words
_EXCESSIVE_DEPTH = re.compile(r"Excessive depth in document: (\d+),? use XML_PARSE_HUGE option")
#: what an EDS starts with: a comment or a section header (after a UTF-8 byte order mark)
_EDS_START = re.compile(rb"(?:\xef\xbb\xbf)?\s*(?:\$|\[[^\]\n]*\])")


def _plain(message: str) -> str:
    return _EXCESSIVE_DEPTH.sub(r"elements nested deeper than \1 levels refused", message)


def _eds_hint(data: bytes) -> str:
    """A pointer to the right command when an EDS is given where a profile is expected."""
    if _EDS_START.match(data[:4096]):
        return "; this looks like an EDS file: `edsconv lint` checks it, `edsconv eds2xml` converts it"
    return ""


def _refuse_entity_declarations(data: bytes) -> None:
    for codec in _ENCODINGS:
        doctype = data.find("<!DOCTYPE".encode(codec))
        entity = data.find("<!ENTITY".encode(codec), doctype) if doctype >= 0 else -1
        if entity >= 0:
            before = data[:entity].decode(codec, errors="replace")
            line = before.count("\n") + 1
            column = len(before) - before.rfind("\n")
            raise UnsafeXmlError(_ENTITY_MESSAGE, line, column)
