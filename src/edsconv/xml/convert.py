"""Whole conversions, EDS <-> ISO 15745-4 XML profiles (``edsconv eds2xml`` and ``edsconv xml2eds``).

eds2xml: EDS -> semantic model -> the device profile (CIP_Device_Profile.xsd)
and the communication network profile (ENet_CommNet_Profile.xsd), or, with
``--wrapper``, the EDS wrapper profiles that only reference the EDS (Table C.2).
Every document is validated before anything is written, and files are written
atomically: an invalid document is an internal error, never a file on disk.

xml2eds: XML profiles -> the same semantic model -> an EDS in canonical form.
A wrapper profile carries no device data: the EDS it references is looked up
next to it.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass, replace
from pathlib import Path

from lxml import etree

from edsconv.diagnostics import Diagnostic, Severity, block, has_errors, rule
from edsconv.eds.syntax import EdsFile
from edsconv.model import Device
from edsconv.xml.common import Header, header_element, is_xml_text, serialise
from edsconv.xml.datamodel import collapse, string_value
from edsconv.xml.safe import XmlDocument, XmlError, parse_xml

WRAPPER_NOT_FOUND = rule(
    "XML101", Severity.ERROR, "C.2.2.1", "The EDS a wrapper profile references is not next to it",
    explanation="""
        An EDS wrapper profile carries no device data: its ExternalProfileHandle names
        an EDS (Table C.2: by DescText, Revision and HomeURL with `FILEINFO`, or by
        vendor, device type, product code and revision with `DEVICEINFO`). xml2eds
        looks for that EDS in the wrapper's directory; this rule says it is not there,
        and the message says what the wrapper references.
    """,
    bad="`device_wrapper.xml` alone in a directory.",
    good="`device_wrapper.xml` beside the `io_adapter.eds` it names.",
)
NOT_A_PROFILE = rule(
    "XML102", Severity.ERROR, "C.2.1", "The file is not a profile xml2eds can read",
    explanation="""
        The file is a valid ISO 15745 profile, but not one xml2eds reads: only the
        EtherNet/IP device and communication network profiles and the EDS wrapper
        profiles describe an EDS (an ADS-net or FL-net profile does not).
    """,
    bad="`edsconv xml2eds flnet_device.xml`.",
    good="`edsconv xml2eds adapter_device.xml adapter_commnet.xml`",
)

NOT_CONVERTED = rule(
    "XML103", Severity.ERROR, "C.2.1", "eds2xml does not convert an EDS whose identity or values it cannot read",
    explanation="""
        eds2xml writes profiles only when they say what the EDS says. A value it cannot
        read (a date 13-11-2008, a BOOL default 255, a word where a string stands) does
        not stop it: every readable value is stated, the unreadable one is kept with its
        exact spelling in an `edsconv:Unreadable` of the device profile (the schema's
        element stays empty or absent where the schema allows it), the reader's error
        is reported (exit 1), and xml2eds writes the spelling back. So is a statement
        the reader could not parse (a stray word, an entry whose fields lack commas,
        EDS001/EDS012): the reader keeps its text, and so do the profiles. eds2xml
        writes nothing (exit 1) when:

        - [Device] does not give a readable VendCode, ProdType, ProdCode, MajRev and
          MinRev: the profile's identity (ProfileIdentification, DeviceIdentity) would
          be invented; the message names the missing ones;
        - an error of reading loses text the model cannot keep (an unterminated string,
          a duplicated section or entry ...);
        - a section name holds characters XML 1.0 cannot carry (control characters):
          the profiles name sections in attributes;
        - the profile would not be readable by an XML parser with the usual limits
          (edsconv's own reader included): a value or comment longer than 10 MB,
          or a document larger than 64 MiB.

        `--strict` refuses any error of reading, as eds2xml did before: for pipelines
        that want a profile only from a file without errors. Errors of the checks
        (EDS2xx to EDS4xx: a missing reference, sizes that do not add up ...) never
        stop the conversion.
    """,
    bad=block("""
        [Device]
            VendCode = 99999999999999999999;
    """, "ini"),
    good=block("""
        [Device]
            VendCode = 65535;
            ProdType = 12;
            ProdCode = 1001;
            MajRev = 1;
            MinRev = 2;
    """, "ini"),
)
NOT_ASCII = rule(
    "XML104", Severity.ERROR, "C.4.1.3.2", "xml2eds does not write an EDS holding characters outside ASCII",
    explanation=r"""
        An EDS is ASCII (C.4.1.3.2). xml2eds writes every character of a string that
        is not ASCII as an escape of Table C.4 (`\xnn`, or `\unnnn` in an `L` string,
        a character beyond the BMP as its two 16-bit UTF-16 characters), so the EDS it
        writes never draws EDS005. A comment, a section name or a keyword has no
        escapes: when a profile gives one of them a character outside ASCII (in an
        `edsconv:Comment` or a vendor section of the profile's `DeviceFunction`),
        xml2eds writes nothing and names the line the EDS would have had.
    """,
    bad='`<edsconv:Comment>Müller</edsconv:Comment>`',
    good='`<edsconv:Comment>Mueller</edsconv:Comment>`',
)
PROFILES_OF_TWO_DEVICES = rule(
    "XML008", Severity.ERROR, "C.2.1", "The device and network profiles given to xml2eds describe different devices",
    explanation="""
        xml2eds joins a device profile and a network profile into one EDS, so both must
        describe the same device: their ProfileIdentification, without the `-DEV` and
        `-COMM` endings eds2xml gives them, and their ProfileDate are the same (eds2xml
        writes both from the same EDS). Another device's network profile would name
        parameters and assemblies the device profile does not have. Nothing is written.
    """,
    bad="`edsconv xml2eds adapter_device.xml scanner_commnet.xml`",
    good="`edsconv xml2eds adapter_device.xml adapter_commnet.xml`",
)
PROFILES_NOT_ONE_DEVICE = rule(
    "XML009", Severity.ERROR, "C.2.1", "The profiles given to xml2eds are not one device profile and its network",
    explanation="""
        xml2eds reads one device profile, optionally followed by that device's
        communication network profile (or the wrapper profiles of one EDS). A network
        profile alone has no identity, parameters or assemblies: the EDS would hold only
        [Connection Manager] and [Port]. Two device profiles are two devices. Nothing is
        written.
    """,
    bad="`edsconv xml2eds adapter_commnet.xml`",
    good="`edsconv xml2eds adapter_device.xml adapter_commnet.xml`",
)
#: The [Device] entries the profile's identity is made of (ProfileIdentification, ProdRevision).
IDENTITY = (("VendCode", "vendor_code"), ("ProdType", "product_type"), ("ProdCode", "product_code"),
            ("MajRev", "major_revision"), ("MinRev", "minor_revision"))


class NotConverted(Exception):
    """The EDS cannot be converted without losing or inventing data; ``diagnostics`` say why."""

    def __init__(self, diagnostics: list[Diagnostic]) -> None:
        super().__init__("; ".join(d.message for d in diagnostics))
        self.diagnostics = diagnostics


#: Table C.2: WrapperReference values, by the --reference option.
WRAPPER_REFERENCES = {"fileinfo": "FILEINFO", "deviceinfo": "DEVICEINFO"}


@dataclass(frozen=True, slots=True)
class Output:
    """One document to write: file name, bytes."""

    name: str
    data: bytes


# --- eds2xml -----------------------------------------------------------------------------

#: Errors of the reader whose text the model keeps all the same: a string (its value read, or kept
#: unread); text in a statement the reader could not parse, kept verbatim (Unparsed -> Unreadable).
_KEPT_STRINGS = frozenset({"EDS003", "EDS004", "EDS016"})
_KEPT_STATEMENTS = frozenset({"EDS001", "EDS012"})


def _lost(eds: EdsFile, diagnostic: Diagnostic) -> bool:
    """Whether the profiles would lose text of ``eds`` that ``diagnostic`` (an error) is about. A value
    error (EDS1xx) loses nothing: the value is read, or kept as written (Device.unreadable)."""
    code = diagnostic.code
    if code in _KEPT_STRINGS or code.startswith("EDS1"):
        return False
    if code in _KEPT_STATEMENTS:
        return not any(item.line <= diagnostic.line <= item.line + item.text.count("\n")
                       for section in eds.sections for _, item in section.unparsed)
    return True


def conversion_refusals(eds: EdsFile, device: Device, strict: bool = False) -> list[Diagnostic]:
    """Why ``eds`` must not be converted (rule XML103): text the profiles would lose (with ``strict``:
    any error of reading, a value kept unread included), or an identity it does not give."""
    errors = [d for d in (*eds.diagnostics, *device.diagnostics) if d.severity is Severity.ERROR]
    unread = errors if strict else [d for d in errors if _lost(eds, d)]
    refusals = []
    if unread:
        first = unread[0]
        refusals.append(Diagnostic.of(
            NOT_CONVERTED, f"not converted{' (--strict)' if strict else ''}: the profiles would lose what "
            f"{len(unread)} error(s) could not read (the first: {first.code} at line {first.line})",
            first.line, first.column, eds.path))
    for section in eds.sections:
        if not is_xml_text(section.name):
            refusals.append(Diagnostic.of(
                NOT_CONVERTED, f"not converted: the section name {section.name!r} holds characters XML 1.0 cannot "
                "carry (control characters)", section.line, section.column, eds.path))
    missing = [keyword for keyword, attribute in IDENTITY if not isinstance(getattr(device.identity, attribute), int)]
    if missing:
        device_section = next((s for s in eds.sections if s.name == "Device"), None)
        line, column = (device_section.line, device_section.column) if device_section else (1, 1)
        refusals.append(Diagnostic.of(
            NOT_CONVERTED, f"not converted: [Device] gives no readable {', '.join(missing)}, which the profiles' "
            "identity is made of", line, column, eds.path))
    return refusals


def profile_documents(device: Device, header: Header, stem: str) -> list[Output]:
    """The device and communication network profiles, validated and readable by :func:`parse_xml`."""
    from edsconv.xml.commnet import commnet_profile
    from edsconv.xml.device_write import device_profile

    return [readable_document(f"{stem}_device.xml", device_profile(device, header), "cip-device", device),
            readable_document(f"{stem}_commnet.xml", commnet_profile(device, header), "ethernetip-commnet", device)]


def eds_documents(eds: EdsFile, device: Device, header: Header, stem: str, *, strict: bool = False,
                  wrapper_reference: str | None = None) -> list[Output]:
    """The profiles of an EDS (with ``wrapper_reference``, its wrapper profiles), validated, as eds2xml and
    the editor's convert command write them; :class:`NotConverted` (XML103) when it must not be converted."""
    refusals = conversion_refusals(eds, device, strict)
    if refusals:
        raise NotConverted(refusals)
    if wrapper_reference is not None:
        return wrapper_documents(device, header, stem, wrapper_reference)
    return profile_documents(device, header, stem)


def readable_document(name: str, root: etree._Element, kind: str, device: Device) -> Output:
    """The validated document (:func:`serialise`) when edsconv's reader reads it back, else
    :class:`NotConverted`: the writer never produces what the reader cannot read."""
    try:
        data = serialise(root, kind)
        parse_xml(data)
    except (etree.XMLSyntaxError, XmlError) as error:  # serialise may re-parse the document
        reason = error.message if isinstance(error, XmlError) else error.msg
        path = device.eds.path if device.eds is not None else None
        raise NotConverted([Diagnostic.of(
            NOT_CONVERTED, f"not converted: {name} would not be readable by XML parsers ({reason.split(',')[0]}): "
            "a value or comment longer than 10 MB, or a profile larger than 64 MiB, cannot stand in a profile",
            1, 1, path)]) from error
    return Output(name, data)


def wrapper_handle(device: Device, reference: str) -> etree._Element:
    """The ExternalProfileHandle of Table C.2."""
    handle = etree.Element("ExternalProfileHandle", WrapperReference=reference)
    if reference == "FILEINFO":
        values = (device.file.description or "", str(device.file.revision or ""), device.file.home_url)
    else:
        identity = device.identity
        key = (identity.vendor_code, identity.product_type, identity.product_code)
        values = (" ".join("" if v is None else str(v) for v in key),
                  f"{identity.major_revision}.{identity.minor_revision}", identity.icon)
    for tag, text in zip(("ProfileIdentification", "ProfileRevision", "ProfileLocation"), values, strict=True):
        if text is not None:
            etree.SubElement(handle, tag).text = text
    return handle


def wrapper_documents(device: Device, header: Header, stem: str, reference: str) -> list[Output]:
    """The EDS wrapper profiles (C.2.2, C.3.2): a header and a handle to the EDS."""
    outputs = []
    for class_id, suffix, kind, interface in (("Device", "DEV", "eds-device-wrapper", None),
                                              ("CommunicationNetwork", "COMM", "eds-commnet-wrapper", "CSI")):
        root = etree.Element("ISO15745Profile")
        root.append(header_element(header, class_id, "EDS", suffix, interface))
        body = etree.SubElement(root, "ProfileBody")
        if class_id == "Device":
            etree.SubElement(body, "DeviceFunction")  # required, content optional (C.2.2.2)
        body.append(wrapper_handle(device, reference))
        name = f"{stem}_device_wrapper.xml" if class_id == "Device" else f"{stem}_commnet_wrapper.xml"
        outputs.append(readable_document(name, root, kind, device))
    return outputs


def header_for(device: Device, fallback: str, overrides: dict) -> Header:
    """The profile header derived from ``device`` (``fallback`` names it when nothing else does),
    with the values of ``overrides`` that are not None in place of the derived ones."""
    header = Header.derive(device, fallback)
    given = {key: value for key, value in overrides.items() if value is not None}
    return replace(header, **given)


# --- xml2eds -----------------------------------------------------------------------------

_NOT_ASCII = re.compile(r"[^\x00-\x7f]")


def eds_text(device: Device, newline: str, path: str | None = None) -> str:
    """The EDS of ``device`` (canonical form) as text, ASCII only (C.4.1.3.2): strings carry their
    escapes; :class:`NotConverted` (XML104) when a comment, a name or a keyword holds another character."""
    from edsconv.eds.canonical import write_canonical
    from edsconv.eds.from_model import device_to_eds
    from edsconv.eds.reader import parse
    from edsconv.eds.writer import write

    # canonical as fmt lays it out (fmt --check accepts it): the model's EDS, read back and formatted
    text = write_canonical(parse(write(device_to_eds(device))), newline=newline)
    found = _NOT_ASCII.search(text)
    if found is None:
        return text
    line = text.count("\n", 0, found.start()) + 1
    column = found.start() - text.rfind("\n", 0, found.start())
    shown = text[found.start() - column + 1:].split("\n", 1)[0].strip()
    raise NotConverted([Diagnostic.of(
        NOT_ASCII, f"not converted: line {line} of the EDS would hold {found.group()!r} (U+{ord(found.group()):04X}) "
        f"in {shown[:80]!r}, which only a string can escape; an EDS is ASCII", 1, 1, path)])


def _handle_values(root: etree._Element) -> tuple[str, dict[str, str]]:
    """The WrapperReference (an NMTOKEN: white space collapsed; FILEINFO by default) and the
    handle's values by element name (each its whole text, comments skipped)."""
    handle = root.find("ProfileBody/ExternalProfileHandle")
    if handle is None:
        return "FILEINFO", {}
    values = {str(child.tag): string_value(child) for child in handle.iterchildren(etree.Element)}
    return collapse(handle.get("WrapperReference", "FILEINFO")), values


def _numbers(text: str, separator: str) -> tuple[int, ...] | None:
    """The decimal (or 0x hexadecimal) numbers of ``text`` split at ``separator``, None when a
    part is no number."""
    parts = re.split(separator, collapse(text))
    if not all(_NUMBER.fullmatch(part) for part in parts):
        return None
    return tuple(int(part, 0) if part[:2].lower() == "0x" else int(part) for part in parts)


#: Table C.2 writes DEVICEINFO's ProfileIdentification as "VendorID, Device Type, Product Code"
#: without a spelling: the numbers separated by spaces (as eds2xml writes them), by commas (as the
#: table lists them) or by hyphens (as edsconv spells a ProfileIdentification), with spaces around.
_KEY_SEPARATOR = r"\s*[,-]\s*|\s+"
_NUMBER = re.compile("0[xX][0-9A-Fa-f]+|[0-9]+")


def _wrapped_by(device: Device, reference: str, identification: str, revision: str) -> bool:
    """Whether ``device`` is the EDS a wrapper's handle names (Table C.2). Strings compare with
    their white space collapsed; numbers and revisions by value (``1.02`` is ``1.2``)."""
    written = _numbers(revision, r"\.")
    if reference == "FILEINFO":
        found = device.file.revision
        return (collapse(device.file.description or "") == collapse(identification)
                and (written == (found.major, found.minor) if found else written is None and not revision.strip()))
    identity = device.identity
    return (_numbers(identification, _KEY_SEPARATOR) ==
            (identity.vendor_code, identity.product_type, identity.product_code)
            and written == (identity.major_revision, identity.minor_revision))


def find_wrapped_eds(xml_path: Path, root: etree._Element) -> tuple[Path | None, str]:
    """The EDS a wrapper profile references, looked up next to it, and a description of the reference."""
    from edsconv import build, load

    reference, values = _handle_values(root)
    identification = values.get("ProfileIdentification", "")
    revision = values.get("ProfileRevision", "")
    location = collapse(values.get("ProfileLocation", ""))
    described = f"{reference}: identification {identification!r}, revision {revision!r}" + (
        f", location {location!r}" if location else "")
    candidates = sorted(p for p in xml_path.parent.iterdir() if p.suffix.lower() == ".eds")
    if reference == "FILEINFO" and location:
        named = xml_path.parent / location.rstrip("/").rsplit("/", 1)[-1]
        if named.is_file():
            return named, described
    for candidate in candidates:
        if _wrapped_by(build(load(candidate)), reference, identification, revision):
            return candidate, described
    return None, described


def device_from_profiles(paths: list[Path], *, network_alone: bool = False) -> tuple[Device | None, list[Diagnostic]]:
    """Read, validate and convert XML profiles into one Device; a wrapper resolves to its EDS.

    The profiles are read and validated first, then checked to make one device (a device
    profile, with at most the network profile of the same device: XML008, XML009), then converted.
    ``network_alone``: a network profile may stand alone (what it says, without a device; for tests
    of the network reader)."""
    from edsconv.xml.validate import read_and_validate

    read: list[tuple[Path, str, XmlDocument]] = []
    diagnostics: list[Diagnostic] = []
    for path in paths:
        document, report = read_and_validate(path)
        diagnostics.extend(report.diagnostics)
        if document is None or has_errors(report.diagnostics):
            return None, diagnostics
        if report.kind is None or report.kind.name not in _READ_KINDS:
            diagnostics.append(_not_a_profile(path, report.kind))
            return None, diagnostics
        read.append((path, report.kind.name, document))
    refusals = [] if network_alone and len(read) == 1 else list(_pairing_refusals(read))
    if refusals:
        return None, diagnostics + refusals
    return _converted(read, diagnostics)


#: The profile kinds xml2eds reads.
_READ_KINDS = ("cip-device", "ethernetip-commnet", "eds-device-wrapper", "eds-commnet-wrapper")


def _not_a_profile(path: Path, kind) -> Diagnostic:
    from edsconv.xml.validate import kind_title

    what = kind_title(kind) if kind else "a profile of unknown kind"
    return Diagnostic.of(NOT_A_PROFILE, f"not an EtherNet/IP device, network or EDS wrapper profile: {what}",
                         1, 1, str(path))


def _converted(read: list[tuple[Path, str, XmlDocument]],
               diagnostics: list[Diagnostic]) -> tuple[Device | None, list[Diagnostic]]:
    """The Device of profiles that make one device (a wrapper: the EDS it names)."""
    from edsconv import build, load
    from edsconv.xml.commnet import read_commnet_profile
    from edsconv.xml.device_read import read_device_profile

    device = Device()
    for path, kind, document in read:
        if kind == "cip-device":
            diagnostics.extend(read_device_profile(document, device))
        elif kind == "ethernetip-commnet":
            diagnostics.extend(read_commnet_profile(document, device))
        else:
            found, described = find_wrapped_eds(path, document.tree.getroot())
            if found is None:
                diagnostics.append(Diagnostic.of(WRAPPER_NOT_FOUND, f"the wrapper references an EDS ({described}); "
                                                 f"no such EDS is next to it in {path.parent}", 1, 1, str(path)))
                return None, diagnostics
            eds = load(found)
            diagnostics.extend(eds.diagnostics)
            return build(eds), diagnostics
    return device, diagnostics


#: ProfileIdentification's ending by kind, as eds2xml writes it (docs/mapping.md, "Profile header").
_SUFFIXES = {"cip-device": "-DEV", "ethernetip-commnet": "-COMM", "eds-device-wrapper": "-DEV",
             "eds-commnet-wrapper": "-COMM"}


def _header_text(document: XmlDocument, tag: str) -> str:
    element = document.tree.getroot().find(f"ProfileHeader/{tag}")
    return collapse(string_value(element)) if element is not None else ""


def _pairing_refusals(read: list[tuple[Path, str, XmlDocument]]) -> Iterator[Diagnostic]:
    """XML009 unless the profiles are one device profile and at most one network profile (or the
    wrappers of one EDS); XML008 when a pair's ProfileIdentification (without -DEV / -COMM) or
    ProfileDate differ: the network profile of another device, or of another conversion."""
    kinds = [kind for _, kind, _ in read]
    wrappers = all(kind.startswith("eds-") for kind in kinds)
    devices = sum(kind in ("cip-device", "eds-device-wrapper") for kind in kinds)
    path = read[-1][0]
    if devices != 1 and not (wrappers and len(kinds) == 1):
        what = "a network profile alone describes no device" if devices == 0 else "two device profiles"
        yield Diagnostic.of(PROFILES_NOT_ONE_DEVICE, f"{what}: give the device profile (DEVICE.xml), and its "
                            f"network profile (COMMNET.xml) after it", 1, 1, str(path))
    elif len(read) == 2:
        first, second = ((_header_text(document, "ProfileIdentification").removesuffix(_SUFFIXES[kind]),
                          _header_text(document, "ProfileDate"), path) for path, kind, document in read)
        if first[:2] != second[:2]:
            yield Diagnostic.of(PROFILES_OF_TWO_DEVICES, f"the profiles describe different devices: "
                                f"{first[2].name} is {first[0]!r} of {first[1]}, {second[2].name} is "
                                f"{second[0]!r} of {second[1]} (ProfileIdentification without -DEV/-COMM, "
                                f"ProfileDate)", 1, 1, str(second[2]))
