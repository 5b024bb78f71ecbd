"""Validation of ISO 15745-4 XML profiles against the restored schemas (``edsconv validate``).

The profile kind is read from the header (ProfileClassID and
ISO15745Reference/ProfileTechnology) and picks the schema; ``--schema`` forces
one. Every problem becomes a :class:`~edsconv.diagnostics.Diagnostic` whose
message ends with the XPath of the offending element.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import cast

from lxml import etree

from edsconv.diagnostics import Diagnostic, Severity, block, rule
from edsconv.xml.safe import UnsafeXmlError, XmlDocument, XmlError, XmlSyntaxError, XmlTooLargeError, read_xml
from edsconv.xml.schemas import PROFILE_KINDS, ProfileKind, kind_named, load_schema, load_write_validator

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
    "A recognised ISO 15745 container (POWERLINK XDD) for which edsconv has no schema",
    explanation="""
        A recognised ISO 15745 container, a POWERLINK XDD (`ISO15745ProfileContainer`),
        for which edsconv has no schema: it is reported and not validated.
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

POWERLINK_XDD = kind_named("powerlink-xdd")

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
    query = "./" + "/".join(f"*[local-name()='{step}']" for step in steps) + "/text()"
    found = root.xpath(query)
    return found[0].strip() if isinstance(found, list) and found and isinstance(found[0], str) else ""


def detect_kind(root: etree._Element) -> ProfileKind | None:
    """The profile kind the document's root and header declare, or ``None``."""
    root_name = etree.QName(root).localname
    if root_name == "ISO15745ProfileContainer":
        return POWERLINK_XDD
    if root_name != "ISO15745Profile":
        return None
    profile_class = _header_text(root, "ProfileHeader", "ProfileClassID")
    technology = _header_text(root, "ProfileHeader", "ISO15745Reference", "ProfileTechnology").lower()
    name = _KIND_BY_HEADER.get((profile_class, technology))
    return kind_named(name) if name else None


def validate_file(path: Path, forced: ProfileKind | None = None) -> FileReport:
    """Validate one file; ``OSError`` propagates when it cannot be read."""
    return read_and_validate(path, forced)[1]


def read_and_validate(path: Path, forced: ProfileKind | None = None) -> tuple[XmlDocument | None, FileReport]:
    """The safely parsed document (None when it is not well-formed or unsafe) and its report."""
    report = FileReport(str(path), forced)
    try:
        document = read_xml(path)
    except XmlError as error:
        report.diagnostics.append(Diagnostic.of(_XML_ERROR_RULES[type(error)], error.message,
                                                error.line, error.column, report.path))
        return None, report
    root = document.tree.getroot()
    report.kind = forced or detect_kind(root)
    if report.kind is None:
        found = (f"ProfileClassID {_header_text(root, 'ProfileHeader', 'ProfileClassID')!r}, ProfileTechnology "
                 f"{_header_text(root, 'ProfileHeader', 'ISO15745Reference', 'ProfileTechnology')!r}")
        report.diagnostics.append(Diagnostic.of(
            UNKNOWN_KIND, f"unknown profile kind ({found}); choose a schema with --schema",
            *document.position(root), report.path))
    elif report.kind.xsd is None:
        report.diagnostics.append(Diagnostic.of(
            NOT_VALIDATED, "POWERLINK XDD profile container recognised; not validated (no schema for it)",
            *document.position(root), report.path))
    else:
        report.diagnostics.extend(_schema_diagnostics(document, report.kind, report.path))
    return document, report


_XML_ERROR_RULES = {XmlSyntaxError: NOT_WELL_FORMED, UnsafeXmlError: UNSAFE_XML, XmlTooLargeError: TOO_LARGE}


def _schema_diagnostics(document: XmlDocument, kind: ProfileKind, path: str) -> Iterable[Diagnostic]:
    if kind.xsd_version == "1.1" and load_write_validator(kind.xsd or "").validate(document.tree):
        # The XSD 1.0 rendition lxml reads is never more permissive than the 1.1 schema
        # (schemas/xsd10/README.md): valid, without loading xmlschema (0.2 s of start-up).
        # A document it rejects goes to xmlschema, which decides and words the report.
        return
    for error in load_schema(kind.xsd or "").iter_errors(document.tree):
        # the document is an lxml tree, so are the elements xmlschema reports
        element = cast(etree._Element, error.elem)
        line, column = document.position(element) if element is not None else (0, 0)
        reason = (error.reason or error.message).strip().rstrip(".")
        diagnostic = Diagnostic.of(SCHEMA_VIOLATION, f"{reason} (at {error.path or '/'})", line, column, path)
        diagnostic.clause = f"ISO 15745-4 {kind.clause}"
        yield diagnostic


#: The names ``--schema`` accepts: a profile kind or the file name of its schema.
SCHEMA_CHOICES = [kind.name for kind in PROFILE_KINDS if kind.xsd] + [kind.xsd for kind in PROFILE_KINDS if kind.xsd]
