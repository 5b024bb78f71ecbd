"""Validation of ISO 15745-4 XML profiles against the restored schemas (``edsconv validate``).

The profile kind is read from the header (ProfileClassID and
ISO15745Reference/ProfileTechnology) and picks the schema; ``--schema`` forces
one. Every problem becomes a :class:`~edsconv.diagnostics.Diagnostic` whose
message ends with the XPath of the offending element.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, cast

from lxml import etree

from edsconv.diagnostics import Diagnostic, Severity, block, rule
from edsconv.xml.datamodel import without_comments
from edsconv.xml.safe import UnsafeXmlError, XmlDocument, XmlError, XmlSyntaxError, XmlTooLargeError, read_xml
from edsconv.xml.schemas import PROFILE_KINDS, ProfileKind, as_printed, kind_named, load_schema, load_write_validator

if TYPE_CHECKING:  # xmlschema is imported only when a schema is loaded
    from xmlschema import XMLSchemaChildrenValidationError, XMLSchemaValidationError

NOT_WELL_FORMED = rule(
    "XML001", Severity.ERROR, "XML 1.0", "The file is not well-formed XML",
    explanation="The file is not well-formed XML; nothing else is checked.",
    bad=block("""
        <ISO15745Profile><ProfileHeader></ISO15745Profile>
    """, "xml"),
    good=block("""
        <ISO15745Profile><ProfileHeader></ProfileHeader></ISO15745Profile>
    """, "xml"),
)
UNSAFE_XML = rule(
    "XML002", Severity.ERROR, "ISO 15745-1",
    "The file declares entities (billion laughs, XXE); refused without expanding them",
    explanation="""
        The file declares entities in a document type declaration (the "billion
        laughs" and external entity attacks). edsconv refuses it without expanding
        anything; an ISO 15745 profile needs no DTD.
    """,
    bad=block("""
        <!DOCTYPE ISO15745Profile [<!ENTITY vendor SYSTEM "file:///etc/passwd">]>
        <ISO15745Profile>&vendor;</ISO15745Profile>
    """, "xml"),
    good=block("""
        <ISO15745Profile>...</ISO15745Profile>
    """, "xml"),
)
SCHEMA_VIOLATION = rule(
    "XML003", Severity.ERROR, "ISO 15745-4", "The profile does not conform to the schema of its kind",
    clause_note="the clause of the schema of the profile's kind",
    explanation="""
        The profile does not conform to the schema of its kind. The message names the
        problem and ends with the XPath of the offending element.
    """,
    bad="""
        a header without its required ProfileIdentification.

        ```xml
        <ProfileHeader>
          <ProfileRevision>1.0</ProfileRevision>
          ...
        </ProfileHeader>
        ```
    """,
    good=block("""
        <ProfileHeader>
          <ProfileIdentification>Example adapter</ProfileIdentification>
          <ProfileRevision>1.0</ProfileRevision>
          ...
        </ProfileHeader>
    """, "xml"),
)
UNKNOWN_KIND = rule(
    "XML004", Severity.ERROR, "ISO 15745-4",
    "The header's ProfileClassID and ProfileTechnology name no known profile kind",
    explanation="""
        The header's ProfileClassID and ProfileTechnology name no known profile kind, so
        no schema is chosen. Correct the header, or name the schema with `--schema`.
    """,
    bad=block("""
        <ProfileClassID>Device</ProfileClassID>
        <ISO15745Reference><ProfileTechnology>DeviceNet</ProfileTechnology></ISO15745Reference>
    """, "xml"),
    good=block("""
        <ProfileClassID>Device</ProfileClassID>
        <ISO15745Reference><ProfileTechnology>CIP</ProfileTechnology></ISO15745Reference>
    """, "xml"),
)
NOT_VALIDATED = rule(
    "XML005", Severity.INFO, "ISO 15745-1",
    "A recognised ISO 15745 profile of another family (POWERLINK, CANopen, GSDML, IODD), not validated",
    explanation="""
        The file is an ISO 15745 profile of a family edsconv recognises but holds no
        schema for, so it is named and not validated: a POWERLINK XDD/XDC or a CANopen
        XDD/XDC (CiA 311; `ISO15745ProfileContainer`), a PROFINET GSDML
        (`ISO15745Profile`) or an IO-Link IODD (`IODevice`). The family is read from
        the root element's namespace and the header's ProfileTechnology; when the two
        name different families the file is not recognised (XML004).
    """,
    bad=block("""
        <ISO15745ProfileContainer xmlns="http://www.ethernet-powerlink.org">...</ISO15745ProfileContainer>
    """, "xml"),
    good=block("""
        <ISO15745Profile>...</ISO15745Profile>
    """, "xml"),
    labels=("Triggers", "Does not (a profile edsconv has a schema for)"),
)
TOO_LARGE = rule(
    "XML006", Severity.ERROR, "edsconv", "The file exceeds the input size limit and was not read",
    explanation="""
        The file exceeds the input size limit (64 MiB) and was not read. Real profiles
        are far smaller; a file this large is most likely not a profile.
    """,
    bad="a 100 MiB file.",
    good="any profile under 64 MiB.",
)

NOT_CHECKABLE = rule(
    "XML007", Severity.ERROR, "ISO 15745-4", "A value lies beyond what the schema validator can check",
    explanation="""
        The schema validator (xmlschema) failed on a value it cannot represent, such as a
        date whose year has 40 digits (xs:date sets no bound, the validator does). The
        rest of the file is not validated, so the file is not taken as valid: xml2eds
        does not convert it. Real profiles never come near these limits.
    """,
    bad="`<ProfileDate>20242024202420242024202420242024-06-03</ProfileDate>`",
    good="`<ProfileDate>2024-06-03</ProfileDate>`",
)


@dataclass(frozen=True, slots=True)
class Family:
    """An ISO 15745 family edsconv recognises but does not validate (no schema)."""

    kind: str
    #: what the messages call it
    title: str
    root: str
    #: the start of the root element's namespace, as the family's published files declare it
    namespace: str
    #: ProfileTechnology in lower case
    technology: str


FAMILIES = (
    Family("powerlink-xdd", "POWERLINK device description (XDD/XDC)", "ISO15745ProfileContainer",
           "http://www.ethernet-powerlink.org", "powerlink"),
    Family("canopen-xdd", "CANopen device description (XDD/XDC, CiA 311)", "ISO15745ProfileContainer",
           "http://www.canopen.org/xml/", "canopen"),
    Family("profinet-gsdml", "PROFINET GSDML device description", "ISO15745Profile",
           "http://www.profibus.com/GSDML/", "gsdml"),
    Family("iolink-iodd", "IO-Link device description (IODD)", "IODevice", "http://www.io-link.com/IODD/", "iodd"),
)

# (ProfileClassID, ProfileTechnology in lower case) -> kind. CIP and EtherNet/IP
# both lead to the CIP schemas; each fixes its own technology, so a profile
# with the other spelling gets a precise schema error instead of "unknown".
_KIND_BY_HEADER = {
    ("Device", "cip"): "cip-device",
    ("Device", "ethernet/ip"): "cip-device",
    ("Device", "eds"): "eds-device-wrapper",
    ("CommunicationNetwork", "ethernet/ip"): "ethernetip-commnet",
    ("CommunicationNetwork", "cip"): "ethernetip-commnet",
    ("CommunicationNetwork", "eds"): "eds-commnet-wrapper",
    ("Device", "ads-net"): "adsnet-device",
    ("CommunicationNetwork", "ads-net"): "adsnet-commnet",
    ("Device", "fl-net"): "flnet-device",
    ("CommunicationNetwork", "fl-net"): "flnet-commnet",
}


_CIP_TECHNOLOGIES = {technology for _, technology in _KIND_BY_HEADER}


@dataclass(slots=True)
class FileReport:
    path: str
    kind: ProfileKind | None = None
    diagnostics: list[Diagnostic] = field(default_factory=list)

    def as_dict(self) -> dict:
        return {
            "path": self.path,
            "profile": self.kind.name if self.kind else None,
            "schema": self.kind.xsd if self.kind else None,
            "diagnostics": [d.as_dict() for d in self.diagnostics],
        }


def _header_text(root: etree._Element, *steps: str) -> str:
    """The header value at ``steps``: its whole text, comments and processing instructions
    skipped, white space collapsed (both header values are tokens to compare)."""
    query = "normalize-space(./" + "/".join(f"*[local-name()='{step}']" for step in steps) + ")"
    found = root.xpath(query)
    return found if isinstance(found, str) else ""


def detect_kind(root: etree._Element) -> ProfileKind | None:
    """The profile kind the document's root and header declare, or ``None``.

    Another family (:data:`FAMILIES`) is named when its root element holds its namespace or
    its ProfileTechnology, and neither names a different family.
    """
    family = detect_family(root)
    if family is not None:
        return kind_named(family.kind)
    if etree.QName(root).localname != "ISO15745Profile" or _family_hints(root) != (None, None):
        return None
    profile_class = _header_text(root, "ProfileHeader", "ProfileClassID")
    name = _KIND_BY_HEADER.get((profile_class, _technology(root)))
    return kind_named(name) if name else None


def detect_family(root: etree._Element) -> Family | None:
    """The family of :data:`FAMILIES` the document belongs to, or ``None``."""
    by_namespace, by_technology = _family_hints(root)
    if by_namespace is not None and by_technology is not by_namespace and (
            by_technology is not None or _technology(root) in _CIP_TECHNOLOGIES):
        return None  # the namespace and the header name different families
    family = by_namespace or by_technology
    return family if family is not None and family.root == etree.QName(root).localname else None


def _family_hints(root: etree._Element) -> tuple[Family | None, Family | None]:
    """The families the root element's namespace and the (first) header's ProfileTechnology name."""
    namespace = etree.QName(root).namespace or ""
    technology = _technology(root)
    return (next((f for f in FAMILIES if namespace.startswith(f.namespace)), None),
            next((f for f in FAMILIES if technology == f.technology), None))


def _technology(root: etree._Element) -> str:
    return _header_text(root, *_header_steps(root), "ISO15745Reference", "ProfileTechnology").lower()


def kind_title(kind: ProfileKind) -> str:
    """What messages call a kind: the family's name, or ``<kind> profile``."""
    return next((f.title for f in FAMILIES if f.kind == kind.name), f"{kind.name} profile")


def validate_file(path: Path, forced: ProfileKind | None = None, printed: bool = False) -> FileReport:
    """Validate one file; ``OSError`` propagates when it cannot be read."""
    return read_and_validate(path, forced, printed)[1]


def read_and_validate(path: Path, forced: ProfileKind | None = None,
                      printed: bool = False) -> tuple[XmlDocument | None, FileReport]:
    """The safely parsed document (None when it is not well-formed or unsafe; comments and
    processing instructions removed, :func:`~edsconv.xml.datamodel.without_comments`) and its report.

    ``printed``: validate against the wildcards as the standard prints them
    (:func:`~edsconv.xml.schemas.as_printed`) instead of the restored schema."""
    report = FileReport(str(path), forced)
    try:
        document = read_xml(path)
    except XmlError as error:
        report.diagnostics.append(Diagnostic.of(_XML_ERROR_RULES[type(error)], error.message,
                                                error.line, error.column, report.path))
        return None, report
    # validation sees the data model: comments and processing instructions are not content
    document = without_comments(document)
    root = document.tree.getroot()
    report.kind = forced or detect_kind(root)
    if printed and report.kind is not None:
        report.kind = as_printed(report.kind)
    if report.kind is None:
        report.diagnostics.append(Diagnostic.of(
            UNKNOWN_KIND, f"unknown profile kind ({_what_it_says(root)}); choose a schema with --schema",
            *document.position(root), report.path))
    elif report.kind.xsd is None:
        report.diagnostics.append(Diagnostic.of(
            NOT_VALIDATED, f"{kind_title(report.kind)} recognised; not validated (edsconv holds no schema for it)",
            *document.position(root), report.path))
    else:
        report.diagnostics.extend(_schema_diagnostics(document, report.kind, report.path))
    return document, report


def _what_it_says(root: etree._Element) -> str:
    """The header values a kind is detected from, the root element and its namespace."""
    header, qname = _header_steps(root), etree.QName(root)
    said = (f"ProfileClassID {_header_text(root, *header, 'ProfileClassID')!r}, ProfileTechnology "
            f"{_header_text(root, *header, 'ISO15745Reference', 'ProfileTechnology')!r}")
    if qname.localname == "ISO15745Profile" and not qname.namespace:
        return said
    return f"{said}; root {qname.localname}" + (f" in namespace {qname.namespace}" if qname.namespace else "")


def _header_steps(root: etree._Element) -> tuple[str, ...]:
    """The path to the (first) ProfileHeader: a container holds it in its first profile."""
    container = etree.QName(root).localname == "ISO15745ProfileContainer"
    return ("ISO15745Profile", "ProfileHeader") if container else ("ProfileHeader",)


_XML_ERROR_RULES = {XmlSyntaxError: NOT_WELL_FORMED, UnsafeXmlError: UNSAFE_XML, XmlTooLargeError: TOO_LARGE}


def _schema_diagnostics(document: XmlDocument, kind: ProfileKind, path: str) -> Iterable[Diagnostic]:
    """One XML003 per schema error, at the element at fault: for a content-model error the child that
    is not allowed (libxml2 and Xerces point there too), not its parent."""
    if kind.xsd_version == "1.1" and kind in PROFILE_KINDS and load_write_validator(kind.xsd or "").validate(
            document.tree):
        # The XSD 1.0 rendition lxml reads is never more permissive than the restored 1.1 schema
        # (schemas/xsd10/README.md): valid, without loading xmlschema (0.2 s of start-up). A document
        # it rejects, and every --as-printed check (stricter than the restored schema), goes to
        # xmlschema, which decides and words the report.
        return
    paths = ElementPaths()
    try:
        for error in load_schema(kind.xsd or "").iter_errors(document.tree):
            # the document is an lxml tree, so xmlschema's elements are lxml's
            child = cast("etree._Element | None", getattr(error, "invalid_child", None))
            at = child if child is not None else cast("etree._Element | None", error.elem)
            line, column = document.position(at) if at is not None else (0, 0)
            where = paths.path(cast("etree._Element | None", error.elem), error.namespaces) or "/"
            if child is not None:
                where = f"{where.rstrip('/')}/{_name(child)}"
            diagnostic = Diagnostic.of(SCHEMA_VIOLATION, f"{schema_reason(error)} (at {where})", line, column, path)
            diagnostic.clause = f"ISO 15745-4 {kind.clause}"
            yield diagnostic
    except (ArithmeticError, ValueError) as failure:  # xmlschema raises, e.g. for a date of year 10**40
        yield Diagnostic.of(NOT_CHECKABLE, f"a value lies beyond what the validator can check ({failure}); the "
                            "rest of the file is not validated", *document.position(document.tree.getroot()), path)


class ElementPaths:
    """The XPath xmlschema gives an error (``error.path``: names prefixed by the validation's
    namespaces, ``[n]`` among siblings of the same name), found from the element upwards.

    xmlschema finds each error's path by walking the whole tree from the root, and counts the
    siblings anew each time: size x errors (a 52 MB profile with 4,900 errors took 19.5 minutes).
    Here each parent's children are numbered once, the first time an error below it needs them:
    size + errors x depth. ``visited`` counts the children numbered (tests/test_validate_paths.py).
    """

    def __init__(self) -> None:
        self._steps: dict[etree._Element, str] = {}
        self.visited = 0

    def path(self, element: etree._Element | None, namespaces: Mapping[str, str] | None) -> str | None:
        if element is None:
            return None
        steps = []
        prefixes = dict(namespaces) if namespaces else {}
        node: etree._Element | None = element
        while node is not None:
            parent = node.getparent()
            steps.append(self._step(node, parent, prefixes))
            node = parent
        return "/" + "/".join(reversed(steps))

    def _step(self, element: etree._Element, parent: etree._Element | None, namespaces: dict[str, str]) -> str:
        if parent is None:
            return _prefixed(element.tag, namespaces)
        if element not in self._steps:
            self._number_children(parent, namespaces)
        return self._steps[element]

    def _number_children(self, parent: etree._Element, namespaces: dict[str, str]) -> None:
        children = list(parent)
        self.visited += len(children)
        totals: dict[object, int] = {}
        for child in children:
            totals[child.tag] = totals.get(child.tag, 0) + 1
        seen: dict[object, int] = {}
        for child in children:
            seen[child.tag] = position = seen.get(child.tag, 0) + 1
            name = _prefixed(child.tag, namespaces)
            self._steps[child] = name if totals[child.tag] == 1 else f"{name}[{position}]"


def _prefixed(tag: object, namespaces: dict[str, str]) -> str:
    """``tag`` as xmlschema writes it in a path: prefixed when the validation maps its namespace."""
    from xmlschema.utils.qnames import get_prefixed_qname

    return get_prefixed_qname(str(tag), namespaces) if namespaces else str(tag)


#: The XSD types whose values elementpath names by its Python class ("<class '...datetime.Date'>").
_XSD_TYPES = {"Date": "xsd:date (YYYY-MM-DD)", "DateTime": "xsd:dateTime (YYYY-MM-DDThh:mm:ss)",
              "DateTime10": "xsd:dateTime (YYYY-MM-DDThh:mm:ss)", "Date10": "xsd:date (YYYY-MM-DD)",
              "Time": "xsd:time (hh:mm:ss)", "Duration": "xsd:duration (PnYnMnDTnHnMnS)",
              "GregorianYear": "xsd:gYear (YYYY)", "GregorianYear10": "xsd:gYear (YYYY)",
              "GregorianMonth": "xsd:gMonth (--MM)", "GregorianDay": "xsd:gDay (---DD)",
              "GregorianMonthDay": "xsd:gMonthDay (--MM-DD)", "GregorianYearMonth": "xsd:gYearMonth (YYYY-MM)",
              "GregorianYearMonth10": "xsd:gYearMonth (YYYY-MM)"}
_BAD_DATETIME = re.compile(r"Invalid datetime string (?P<value>'[^']*'|\S+) for <class '(?:[\w.]+\.)?(?P<cls>\w+)'>")
_PYTHON_CLASS = re.compile(r"<class '(?:[\w.]+\.)?(?P<cls>\w+)'>")
#: an element as older xmlschema releases (4.0) name it: its Python repr, with a memory address
_ELEMENT_REPR = re.compile(r"<Element (?:\{[^}]*\})?(?P<name>[^\s>]+) at 0x[0-9a-fA-F]+>")
_IDENTITY = re.compile(r"duplicated value \((?P<values>.*?),?\) for "
                       r"Xsd(?:11)?(?P<kind>Key|Unique)\(name='(?P<name>[^']*)'\)")


def schema_reason(error: XMLSchemaValidationError) -> str:
    """What is wrong, in the schema's terms: the elements and XSD types it names, never a Python class."""
    from xmlschema import XMLSchemaChildrenValidationError

    if isinstance(error, XMLSchemaChildrenValidationError):
        return _content_model_reason(error)
    reason = (error.reason or error.message).strip().rstrip(".")
    reason = _BAD_DATETIME.sub(lambda m: f"{m['value']} is not a valid {_XSD_TYPES.get(m['cls'], m['cls'])}", reason)
    reason = _IDENTITY.sub(lambda m: f"the value {m['values']} appears more than once, but the schema's "
                           f"{m['kind'].lower()} constraint {m['name']} requires each to be unique", reason)
    reason = _ELEMENT_REPR.sub(lambda m: f"<{m['name']}>", reason)
    return _PYTHON_CLASS.sub(lambda m: _XSD_TYPES.get(m["cls"], m["cls"]), reason)


def _name(element: object) -> str:
    """The local name of an element of the document (an lxml element)."""
    return etree.QName(cast(etree._Element, element)).localname


#: how xmlschema names a wildcard among the expected tags: "from '##any' namespace/s"
_WILDCARD = re.compile(r"from (?P<namespaces>.*) namespace/s")
_WILDCARD_WORDS = {"'##any'": "an element of any namespace", "'##other'": "an element of another namespace",
                   "'##local'": "an element without a namespace", "'##targetNamespace'": "an element of this namespace"}


def _expected_tag(tag: str) -> str:
    """``<Name>`` for an element; a wildcard in words ("an element of any namespace"), not xmlschema's
    "<from '##any' namespace/s>"."""
    wildcard = _WILDCARD.fullmatch(tag)
    if wildcard is None:
        return f"<{tag}>"
    namespaces = wildcard["namespaces"]
    return _WILDCARD_WORDS.get(namespaces, f"an element of the namespace {namespaces}")


def _content_model_reason(error: XMLSchemaChildrenValidationError) -> str:
    parent = _name(error.elem) if error.elem is not None else "the element"
    expected = " or ".join(map(_expected_tag, getattr(error, "expected_tags", ()) or ()))
    child = error.invalid_child
    if child is not None:
        found = f"<{_name(child)}> is not allowed here (child {error.index + 1} of <{parent}>)"
        return f"{found}; the schema expects {expected}" if expected else found
    if expected:
        return f"<{parent}> is incomplete: the schema expects {expected} after its last child"
    return f"<{parent}> is incomplete"


#: The names ``--schema`` accepts: a profile kind or the file name of its schema.
SCHEMA_CHOICES = [kind.name for kind in PROFILE_KINDS if kind.xsd] + [kind.xsd for kind in PROFILE_KINDS if kind.xsd]
