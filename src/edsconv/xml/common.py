"""What the XML writers and readers share: the extension namespace, the profile
header, and serialisation that validates before it writes (files are written by
:mod:`edsconv.atomic`).

ISO 15745-4 profiles have no target namespace; what the schemas do not model
(sections and keywords the 2003 text does not define, comments) goes into the
schemas' ``xsd:any`` extension points as elements of :data:`EDSCONV_NAMESPACE`
(documented in docs/mapping.md).
"""

from __future__ import annotations

import datetime
import re
from dataclasses import dataclass

from lxml import etree

from edsconv.model import Device

#: Namespace of edsconv's elements in the schemas' extension points.
EDSCONV_NAMESPACE = "urn:x-edsconv:eds-extensions:1"
EDSCONV = f"{{{EDSCONV_NAMESPACE}}}"
NSMAP = {"edsconv": EDSCONV_NAMESPACE}


class InvalidProfile(Exception):
    """A document edsconv produced does not validate: an internal error, never a file."""

    def __init__(self, kind: str, problems: list[str]) -> None:
        super().__init__(f"edsconv produced an invalid {kind} profile:\n" + "\n".join(problems))
        self.kind = kind
        self.problems = problems


@dataclass(slots=True)
class Header:
    """ProfileHeader values (ISO 15745-1), derived from the EDS unless given.

    - identification: ``<VendCode>-<ProdType>-<ProdCode>`` in decimal, the Identity
      key of the device; ``-DEV`` / ``-COMM`` is appended per profile.
    - revision: the EDS file revision ([File] Revision, ``1.0`` when absent).
    - name: [Device] ProdName (else DescText, else the file name).
    - source: [Device] VendName (else "edsconv").
    - date: [File] ModDate, else CreateDate, else today.
    """

    identification: str
    revision: str
    name: str
    source: str
    date: datetime.date

    @classmethod
    def derive(cls, device: Device, fallback_name: str = "EDS") -> Header:
        identity, file = device.identity, device.file
        key = [v if isinstance(v, int) else 0 for v in (identity.vendor_code, identity.product_type,
                                                         identity.product_code)]
        date = file.mod_date or file.create_date or datetime.date.today()
        return cls(
            identification="-".join(str(v) for v in key),
            revision=str(file.revision) if file.revision else "1.0",
            name=identity.product_name or file.description or fallback_name,
            source=identity.vendor_name or "edsconv",
            date=date,
        )


def header_element(header: Header, class_id: str, technology: str, suffix: str,
                   interface: str | None = None) -> etree._Element:
    """The ProfileHeader of one profile (ClassID Device or CommunicationNetwork).

    ``interface`` is the IASInterfaceType; the network profiles require ``CSI``.
    """
    element = etree.Element("ProfileHeader")
    for tag, text in (("ProfileIdentification", f"{header.identification}-{suffix}"),
                      ("ProfileRevision", header.revision), ("ProfileName", header.name),
                      ("ProfileSource", header.source), ("ProfileClassID", class_id),
                      ("ProfileDate", header.date.isoformat())):
        # header texts come from the EDS: characters XML cannot carry become U+FFFD
        etree.SubElement(element, tag).text = xml_text(text)
    reference = etree.SubElement(element, "ISO15745Reference")
    etree.SubElement(reference, "ISO15745Part").text = "4"
    etree.SubElement(reference, "ISO15745Edition").text = "1"
    etree.SubElement(reference, "ProfileTechnology").text = technology
    if interface is not None:
        etree.SubElement(element, "IASInterfaceType").text = interface
    return element


# XML 1.0 Char production: what a text node or attribute value can hold.
_NOT_XML_CHAR = re.compile("[^\t\n\r\u0020-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")
# dt_EDS_Revision of CIPDataTypes.xsd (one digit per part, 0.0 excluded).
_SCHEMA_REVISION = re.compile(r"[0-9]\.[1-9]|[1-9]\.[0-9]|[1-9]\.[1-9]")


def xml_text(text: str) -> str:
    """``text`` with every character XML 1.0 cannot hold replaced by U+FFFD."""
    return _NOT_XML_CHAR.sub("\ufffd", text)


def is_xml_text(text: str) -> bool:
    """True when XML 1.0 can hold ``text`` exactly."""
    return _NOT_XML_CHAR.search(text) is None


def file_description_attributes(device: Device, header: Header) -> dict[str, str]:
    """The ``ag_FileDescription`` attributes of a ProfileBody (both CIP profiles), from [File].

    The schemas require DescText, CreateDate, CreateTime, Revision and
    SpecificationConformance; where the EDS gives no value the schema can hold:
    DescText ``""``, CreateDate the header's date, CreateTime ``00:00:00``,
    Revision ``1.0`` (also for revisions such as ``2.11`` that dt_EDS_Revision
    cannot spell), SpecificationConformance ``""`` (an EDS never states it).
    ModDate, ModTime and HomeURL are written only when the EDS has them.
    """
    file = device.file
    revision = str(file.revision) if file.revision else ""
    attributes = {
        "DescText": xml_text(file.description or ""),
        "CreateDate": (file.create_date or header.date).isoformat(),
        "CreateTime": (file.create_time or datetime.time(0, 0, 0)).isoformat(),
    }
    if file.mod_date:
        attributes["ModDate"] = file.mod_date.isoformat()
    if file.mod_time:
        attributes["ModTime"] = file.mod_time.isoformat()
    attributes["Revision"] = revision if _SCHEMA_REVISION.fullmatch(revision) else "1.0"
    if file.home_url is not None:
        attributes["HomeURL"] = xml_text(file.home_url)
    attributes["SpecificationConformance"] = ""
    return attributes


def serialise(root: etree._Element, schema_kind: str) -> bytes:
    """The document's bytes, after validating it against its schema.

    ``schema_kind`` names a profile kind of :mod:`edsconv.xml.schemas` (``cip-device``,
    ``ethernetip-commnet``, ``eds-device-wrapper`` ...). Raises
    :class:`InvalidProfile` with the validation report when the document is not
    valid: that is a bug in edsconv, and no file must be written.

    lxml validates first (against the XSD 1.0 rendition of a 1.1 schema); a
    document it accepts is valid under the restored schema too, since the
    renditions are never more permissive (tests/test_xsd10.py). Only a document it
    rejects goes to xmlschema and the restored schema, which decides and words the
    report as ``edsconv validate`` does: the renditions reject a few valid
    documents that edsconv never writes (schemas/xsd10/README.md).
    """
    from edsconv.xml.schemas import kind_named, load_schema, load_write_validator

    data = etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True)
    xsd = kind_named(schema_kind).xsd
    document = etree.fromstring(data)
    if load_write_validator(xsd).validate(document):
        return data
    problems = [f"{error.path}: {error.reason}" for error in load_schema(xsd).iter_errors(document)]
    if problems:
        raise InvalidProfile(schema_kind, problems)
    return data
