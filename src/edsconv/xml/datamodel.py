"""Values as the XML data model and the schema types give them, for the profile readers.

A profile written by hand or by another tool may use everything XML allows around a value:
comments and processing instructions anywhere (also inside a value, which splits its text),
CDATA sections and character references (the parser resolves both), white space around
values. What a value is follows from the data model and the schema type, never from how the
text is split:

- :func:`string_value`: all the text an element holds, its descendants' too, comments and
  processing instructions skipped (XPath's string value; ``element.text`` stops at the
  first comment);
- :func:`collapse`: white space (space, tab, CR, LF) as the types whose ``whiteSpace`` facet is
  ``collapse`` see it: numbers, dates, times, booleans, hexBinary, anyURI, NMTOKEN and its
  enumerations, ID, lists (dt_EPATH). ``xsd:string`` (dt_EDS_Char_Array) and elements the
  schema leaves untyped keep their white space;
- :func:`xsd_date` / :func:`xsd_time`: the date and the time of day as written; a time zone
  (``Z``, ``+hh:mm``, ``-hh:mm``), which an EDS date or time cannot hold, is dropped;
- :func:`without_comments`: the document as schema validation sees it (comments and
  processing instructions removed, the text around them joined), element positions kept.
"""

from __future__ import annotations

import copy
import datetime
import re
from dataclasses import replace

from lxml import etree

from edsconv.xml.safe import XmlDocument

_XML_SPACE = re.compile("[ \t\r\n]+")
_DATE = re.compile(r"(\d{4})-(\d\d)-(\d\d)(?:Z|[+-]\d\d:\d\d)?")
_TIME = re.compile(r"(\d\d):(\d\d):(\d\d)(?:\.(\d+))?(?:Z|[+-]\d\d:\d\d)?")


def string_value(element: etree._Element) -> str:
    """The text of ``element`` and its descendants, without comments and processing instructions."""
    # lxml yields str (its stubs say str or bytes)
    return "".join(str(part) for part in element.itertext())


def collapse(text: str) -> str:
    """``text`` with XML white space collapsed: runs become one space, none at either end."""
    return _XML_SPACE.sub(" ", text).strip(" ")


def token(element: etree._Element) -> str:
    """The string value of an element of a collapsing type (NMTOKEN, enumerations, numbers ...)."""
    return collapse(string_value(element))


def xsd_date(text: str) -> datetime.date:
    """An ``xsd:date``; ValueError for a date Python cannot hold (a year before 1 or after 9999)."""
    match = _DATE.fullmatch(collapse(text))
    if match is None:
        raise ValueError(text)
    return datetime.date(int(match[1]), int(match[2]), int(match[3]))


def xsd_time(text: str) -> datetime.time:
    """An ``xsd:time`` as the time of day written; ValueError for ``24:00:00``, which Python cannot hold."""
    match = _TIME.fullmatch(collapse(text))
    if match is None:
        raise ValueError(text)
    microseconds = int((match[4] or "0")[:6].ljust(6, "0"))
    return datetime.time(int(match[1]), int(match[2]), int(match[3]), microseconds)


def without_comments(document: XmlDocument) -> XmlDocument:
    """A copy of ``document`` without comments and processing instructions inside its root; the text
    around each is joined, so that a simple-content element has its one text again. Elements keep
    the line libxml2 recorded for them (diagnostics point into the original)."""
    if next(document.tree.getroot().iter(etree.Comment, etree.ProcessingInstruction), None) is None:
        return document  # nothing to remove: no copy of a large document
    tree = copy.deepcopy(document.tree)
    etree.strip_elements(tree.getroot(), etree.Comment, etree.ProcessingInstruction, with_tail=False)
    return replace(document, tree=tree)
