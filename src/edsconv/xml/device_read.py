"""Reading the CIP device profile (ISO 15745-4 C.2.1, ``CIP_Device_Profile.xsd``) into a model.

:func:`read_device_profile` decodes the schema elements of a device profile ([File],
[Device], [Device Classification], [ParamClass], [Params], [Groups], [Assembly],
[Modular]; docs/mapping.md maps every keyword and field), then applies the edsconv
extension elements (:mod:`edsconv.xml.codec`), so that a profile written by
:func:`edsconv.xml.device_write.device_profile` gives back the same model. A value
it cannot read leaves its model field empty with a diagnostic. The element names
both directions share are here.
"""

from __future__ import annotations

import re

from lxml import etree

from edsconv import spec_tables as tables
from edsconv.diagnostics import Diagnostic, Rule, Severity, rule
from edsconv.model import (
    MODULE,
    MODULE_MEMBER_LIST,
    Assembly,
    AssemblyMember,
    Classification,
    CommentNote,
    Device,
    FileDescription,
    GenericEntry,
    GenericSection,
    Identity,
    Modular,
    ParamClass,
    Parameter,
    ParameterGroup,
    Query,
    Rack,
    Reference,
    Scaling,
)
from edsconv.model.build import iter_references
from edsconv.model.cip_build import attach
from edsconv.model.values import PathItem, Revision, StringIMember, path_items
from edsconv.xml.codec import decode, read_comment, read_entries, read_unreadable, reference, set_path
from edsconv.xml.common import EDSCONV
from edsconv.xml.datamodel import collapse, string_value, token, xsd_date, xsd_time
from edsconv.xml.newer import placed, read_entry_list, read_section
from edsconv.xml.safe import XmlDocument

BAD_DEVICE_VALUE = rule(
    "XML201", Severity.ERROR, "C.2.1.2",
    "A device profile element holds a value edsconv cannot read; the model field stays empty",
    explanation="""
        A device profile holds a value edsconv cannot read into the model (for example
        a DataType that is neither a hexadecimal code nor a path, or a group member
        that names no Param); that field of the model stays empty and the EDS written
        by xml2eds leaves it out, so xml2eds exits 1: a value is never dropped
        silently. Profiles that edsconv writes never trigger it.
    """,
    bad="`<DataType>word</DataType>`.",
    good="`<DataType>C7</DataType>`",
)
BAD_EXTENSION = rule(
    "XML202", Severity.ERROR, "edsconv",
    "An edsconv extension element of a device profile cannot be read and is ignored",
    clause_note="edsconv extension namespace",
    explanation="""
        An element of edsconv's extension namespace (`urn:x-edsconv:eds-extensions:1`)
        in a device profile cannot be read (hand-edited or from another version) and is
        ignored, so the EDS written by xml2eds lacks what it held and xml2eds exits 1;
        see docs/mapping.md for the elements.
    """,
    bad='`<edsconv:Value path="parameters.Param1.default" kind="nonsense">1</edsconv:Value>`',
    good='`<edsconv:Value path="parameters.Param1.default" kind="int">1</edsconv:Value>`',
)

#: The Device attributes the device profile carries (the rest is the network profile's).
DEVICE_PROFILE_PARTS = ("file", "identity", "classifications", "param_class", "parameters", "groups",
                        "assembly_revision", "assemblies", "modular")

#: Text of an international string read from a profile that carries no edsconv value for it:
#: one English STRING (0xD0) in ISO 8859-1 (IANA MIBenum 4).
DEFAULT_STRINGI = ("eng", 0xD0, 4)

PARAM_TAGS = ("Param", "ProxyParam", "ProxiedParam")
ASSEM_TAGS = ("Assem", "ProxyAssem", "ProxiedAssem")
SCALING_TAGS = (("ScalingMultiplier", "multiplier", "UINT"), ("ScalingDivider", "divisor", "UINT"),
                 ("ScalingBase", "base", "UINT"), ("ScalingOffset", "offset", "INT"),
                 ("MultiplierLink", "multiplier_link", "UINT"), ("DivisorLink", "divisor_link", "UINT"),
                 ("BaseLink", "base_link", "UINT"), ("OffsetLink", "offset_link", "INT"),
                 ("DecimalPrecision", "decimal_precision", "USINT"))
INTERNATIONAL_TAGS = (("InternationalParameterName", "international_name"),
                       ("InternationalEngineeringUnits", "international_units"),
                       ("InternationalHelpString", "international_help"))
VALUE_TAGS = (("MinimumValue", "minimum"), ("MaximumValue", "maximum"), ("DefaultValue", "default"))



def read_device_profile(source: XmlDocument | etree._ElementTree | etree._Element,
                        device: Device) -> list[Diagnostic]:
    """Fill the device-profile parts of ``device`` from a device profile (the document,
    the ISO15745Profile element or its tree), edsconv extensions included.

    Values the reader cannot convert leave their model field empty (None) with a
    diagnostic at the element (and the document's file); the network profile parts
    of ``device`` are left alone.
    """
    document = XmlDocument.of(source)
    reader = _Reader(document)
    body = document.tree.getroot().find("ProfileBody")
    if body is None:
        return reader.diagnostics
    read_schema_part(body, device, reader)
    _read_extensions(reader, body, device)
    for ref in iter_references(device):
        ref.target = device.resolve(ref.keyword)
    attach(device)  # the typed view of the content beyond the 2003 text, as model.build sets it
    return reader.diagnostics


def _read_extensions(reader: _Reader, body: etree._Element, device: Device) -> None:
    extra: dict[str, list[GenericEntry]] = {}
    sections: list[GenericSection] = []
    comments: list[CommentNote] = []
    values: list[etree._Element] = []
    for function in body.findall("DeviceFunction"):
        for element in function:
            try:
                if element.tag == EDSCONV + "ExtraEntries":
                    name = element.get("section", "")
                    extra.setdefault(name, []).extend(read_entry_list(element, name, extension=True))
                elif element.tag == EDSCONV + "Section":
                    sections.append(GenericSection(element.get("name", ""), read_entries(element)))
                elif (section := read_section(element)) is not None:
                    sections.append(section)
                elif element.tag == EDSCONV + "Comments":
                    comments.extend(read_comment(c) for c in element if c.tag == EDSCONV + "Comment")
                elif element.tag == EDSCONV + "UnreadableText":
                    device.unreadable.extend(read_unreadable(u) for u in element if u.tag == EDSCONV + "Unreadable")
                elif element.tag == EDSCONV + "Values":
                    values.extend(v for v in element if v.tag == EDSCONV + "Value")
            except (ValueError, TypeError, KeyError) as error:
                reader.report(BAD_EXTENSION, element, f"{etree.QName(element).localname}: {error}")
    try:
        entries, placed_sections = placed(body)
        for position, entry in entries:
            extra.setdefault("Device", []).insert(position, entry)
        for position, section in placed_sections:
            sections.insert(position, section)
    except (ValueError, TypeError, KeyError) as error:
        reader.report(BAD_EXTENSION, body, f"a placed edsconv element: {error}")
    for element in values:
        try:
            set_path(device, element.get("path", "").split("."), decode(element))
        except (ValueError, TypeError, KeyError, IndexError, AttributeError) as error:
            reader.report(BAD_EXTENSION, element, f"Value {element.get('path')!r}: {error}")
    device.extra_entries = extra
    device.other_sections = sections
    device.comments = comments


class _Reader:
    """Decodes the schema elements; a value it cannot convert is None plus a diagnostic."""

    def __init__(self, document: XmlDocument | None) -> None:
        #: where the elements come from (None: a tree the writer reads back, positions unused)
        self.document = document
        self.diagnostics: list[Diagnostic] = []

    def report(self, rule_: Rule, element: etree._Element, message: str) -> None:
        document = self.document or XmlDocument.of(element)
        self.diagnostics.append(document.diagnostic(rule_, message, element))

    def bad(self, element, what: str, text: str) -> None:
        self.report(BAD_DEVICE_VALUE, element, f"{what}: cannot read {text!r}")

    def convert(self, element, converter, what: str | None = None):
        """``converter(text)`` of ``element`` (None when absent or unreadable)."""
        if element is None:
            return None
        text = string_value(element)
        try:
            return converter(text)
        except (ValueError, KeyError, OverflowError):
            self.bad(element, what or etree.QName(element).localname, text)
            return None

    def child(self, parent, tag: str, converter=str):
        return self.convert(parent.find(tag) if parent is not None else None, converter)

    def attribute(self, element, name: str, converter=str):
        text = element.get(name)
        if text is None:
            return None
        try:
            return converter(text)
        except ValueError:
            self.bad(element, name, text)
            return None


def _integer(text: str) -> int:
    text = collapse(text)
    if not re.fullmatch(r"[+-]?[0-9]+", text):
        raise ValueError(text)
    return int(text)


def _hex_binary(text: str) -> int:
    text = collapse(text)
    if not re.fullmatch("[0-9A-Fa-f]+", text):
        raise ValueError(text)
    return int(text, 16)


def _class_word(text: str) -> int:
    text = collapse(text)
    return int(text, 16) if text[:2].lower() == "0x" else _integer(text)


def _path(text: str) -> tuple[PathItem, ...]:
    return path_items(collapse(text))


def _data_type_code(text: str) -> int | tuple[PathItem, ...]:
    """A USINT code; a one-byte EPATH (``C7``) is the code in hexadecimal; longer paths stay paths."""
    text = collapse(text)
    if re.fullmatch("[0-9]+", text) and int(text) <= 255:
        return int(text)
    path = path_items(text)
    return path[0].byte if len(path) == 1 and path[0].byte is not None else path


def _float(text: str) -> float:
    return float(collapse(text))


def _member_reference(text: str):
    text = collapse(text)
    if re.fullmatch("[0-9]+", text):
        return int(text)
    found = Reference.parse(text)
    if found is not None:
        return found
    try:
        return path_items(text)
    except ValueError:
        return text


def _stringi(text: str) -> tuple[StringIMember, ...]:
    return (StringIMember(*DEFAULT_STRINGI, text),)


def _id_number(element, prefix: str) -> int | None:
    match = re.fullmatch(prefix + "([0-9]+)", collapse(element.get("id", "")))
    return int(match.group(1)) if match else None


def read_schema_part(body: etree._Element, device: Device, reader: _Reader | None = None) -> None:
    """The schema elements of a ProfileBody into ``device`` (a reader without a document:
    the writer reading back what it wrote)."""
    reader = reader or _Reader(None)
    device.file = _read_file(reader, body)
    attributes = body.find("DeviceIdentity/DeviceIdentity_InstanceAttributes")
    device.identity, device.classifications = _read_identity(reader, attributes)
    modular = body.find("DeviceManager/Modular")
    device.modular = _read_modular(reader, modular) if modular is not None else None
    process = body.find("ApplicationProcess")
    device.param_class, device.parameters = None, {}
    device.assembly_revision, device.assemblies, device.groups = None, {}, []
    if process is None:
        return
    class_attributes = process.find("Parameter/Parameter_Class/Parameter_ClassAttributes")
    if class_attributes is not None:
        device.param_class = ParamClass(None, reader.child(class_attributes, "ParameterClassDescriptor", _class_word),
                                        reader.child(class_attributes, "ConfigurationAssemblyInstance", _integer))
    for element in process.findall("Parameter/*"):
        if element.tag in PARAM_TAGS:
            parameter = _read_parameter(reader, element)
            device.parameters.setdefault(parameter.keyword, parameter)
    for element in process.findall("Assembly/*"):
        if element.tag in ASSEM_TAGS:
            assembly = _read_assembly(reader, element)
            device.assemblies.setdefault(assembly.keyword, assembly)
    for element in process.findall("ParameterGroup/Group"):
        device.groups.append(_read_group(reader, element))


def _read_file(reader: _Reader, body) -> FileDescription:
    def revision(text: str) -> Revision:
        major, minor = collapse(text).split(".")
        return Revision(int(major), int(minor))

    get = reader.attribute
    return FileDescription(
        body.get("DescText"), get(body, "CreateDate", xsd_date), get(body, "CreateTime", xsd_time),
        get(body, "ModDate", xsd_date), get(body, "ModTime", xsd_time), get(body, "Revision", revision),
        get(body, "HomeURL", collapse))


def _read_identity(reader: _Reader, attributes) -> tuple[Identity, list[Classification]]:
    if attributes is None:
        return Identity(), []
    child = reader.child
    identity = Identity(
        child(attributes, "VendCode", _integer), child(attributes, "VendName"), child(attributes, "ProdType", _integer),
        child(attributes, "ProdTypeStr"), child(attributes, "ProdCode", _integer),
        child(attributes, "ProdRevision/MajRev", _integer), child(attributes, "ProdRevision/MinRev", _integer),
        child(attributes, "ProdName"), child(attributes, "Catalog"), child(attributes, "Icon"),
        child(attributes, "ExcludeFromAdapterRackConnection"))
    classifications = []
    for element in attributes.findall("DeviceClassification/Class"):
        number = _id_number(element, "Class")
        if number is not None:
            subclasses = (reader.convert(s, collapse) for s in element.findall("SubClass"))
            classifications.append(Classification(number, child(element, "MainClass", collapse),
                                                   tuple(s for s in subclasses if s is not None)))
    return identity, classifications


def _read_modular(reader: _Reader, element) -> Modular:
    modular = Modular()
    child = reader.child
    chassis, module = element.find("Chassis"), element.find("Module")
    if chassis is not None:
        modular.define_slots_in_rack = child(chassis, "DefineSlotsInRack", _integer)
        modular.slot_display_rule = child(chassis, "SlotDisplayRule", reference)
    if module is not None:
        modular.width = child(module, "Width", _integer)
        for rack in module.findall("Rack"):
            number = _id_number(rack, "Rack")
            if number is not None:
                key = [child(rack, tag, _integer) for tag in ("VendCode", "ProdType", "ProdCode", "MajRev", "MinRev")]
                modular.racks.append(Rack(number, key[0], key[1], key[2], key[3], key[4],
                                          tuple(reader.convert(s, _integer) for s in rack.findall("LegalSlot"))))
        modular.external_id = child(module, "ExternalID", _path)
        modular.generic_id = child(module, "GenericID", _path)
        modular.extern_id_exact_match = child(module, "ExternIDExactMatch", collapse)
        query = module.find("Query")
        if query is not None:
            modular.query = Query(child(query, "Path", _path), child(query, "Service", _integer),
                                  child(query, "Size", _integer), child(query, "ExternalID", _path))
    return modular


def _read_parameter(reader: _Reader, element) -> Parameter:
    family = element.tag
    number = _id_number(element, family) or 0
    child = reader.child
    item = Parameter(f"{family}{number}", family, number)
    item.link_path_size = child(element, "LinkPathSize", _integer)
    item.link_path = child(element, "LinkPath", _path)
    item.descriptor = child(element, "ParamDescriptor", _hex_binary)
    item.data_type_code = child(element, "DataType", _data_type_code)
    if isinstance(item.data_type_code, int):
        code = item.data_type_code
        item.data_type = tables.DATA_TYPES_BY_CODE.get(code) or tables.OBSOLETE_DATA_TYPE_IDS.get(code)
    item.data_size = child(element, "DataSize", _integer)
    item.name, item.units, item.help = (child(element, tag) for tag in ("ParameterName", "UnitsString", "HelpString"))
    for tag, attribute in VALUE_TAGS:
        value_element = element.find(tag)
        if family == "ProxyParam" and value_element is not None and token(value_element) == MODULE:
            setattr(item, attribute, MODULE)  # C.4.1.5.3.1: taken from the ProxiedParam
        else:
            setattr(item, attribute, reader.convert(value_element, _value_reader(item, attribute)))
    item.scaling = Scaling(**{attribute: child(element, tag, _integer) for tag, attribute, _ in SCALING_TAGS})
    for tag, attribute in INTERNATIONAL_TAGS:
        setattr(item, attribute, child(element, tag, _stringi))
    enum = element.find("Enum")
    if enum is not None:
        keys = [reader.convert(e, _integer) for e in enum.findall("EnumValue")]
        names = enum.findall("EnumName")
        item.enum = {key: string_value(e) for key, e in zip(keys, names, strict=False) if key is not None}
    adder = element.find("ProxyParamSizeAdder")
    if adder is not None:
        item.size_adder = tuple(child(adder, tag, _value_reader(item, attribute))
                                for tag, attribute in VALUE_TAGS)
    return item


def _value_reader(item: Parameter, attribute: str):
    """Minimum / maximum / default in the type the EDS reader gives them (Table C.17)."""
    type_name = item.value_type(attribute)
    if type_name in ("plain", "EDS_Char_Array"):
        return str  # kept as written, or text
    return _float if tables.DATA_TYPES_BY_NAME[type_name].kind == "real" else _integer


def _read_assembly(reader: _Reader, element) -> Assembly:
    family = element.tag
    number = _id_number(element, family) or 0
    child = reader.child
    item = Assembly(f"{family}{number}", family, number, child(element, "AssemblyName"),
                    child(element, "AssemblyPath", _path), child(element, "AssemblyDataSize", _integer),
                    child(element, "AssemblyDescriptor", _hex_binary))
    for member in element.findall("AssemblyMember"):
        size = child(member, "MemberSize", _integer)
        target = child(member, "MemberReference", _member_reference)
        if target == MODULE_MEMBER_LIST and size is None:
            item.module_member_list = True
        else:
            item.members.append(AssemblyMember(size, target))
    return item


def _read_group(reader: _Reader, element) -> ParameterGroup:
    members = []
    for member in element:
        if member.tag == "ParameterRef":
            number = reader.convert(member, _integer)
            if number is not None:
                members.append(Reference(f"Param{number}", "Param", number))
        elif member.tag == "VariantRef":
            target = reader.convert(member, reference)
            if target is not None and (target.family != "Param" or target.bit is not None):
                # an EDS group lists parameter instance numbers, which read back as ParamN:
                # ProxyParam1 written as 1 would name Param1, another entry
                reader.report(BAD_DEVICE_VALUE, member, f"VariantRef {target.text!r}: an EDS group member is a "
                              "parameter instance number naming a ParamN entry (C.4.1.4.7, Table C.19); "
                              f"{target.text} has none and is left out")
            elif target is not None:
                members.append(target)
    return ParameterGroup(_id_number(element, "Group") or 0, reader.child(element, "NameString"),
                          reader.child(element, "NumberOfMembers", _integer), members)


def equal_parts(a: Device, b: Device) -> list[str]:
    """The device-profile parts (and extensions) where two models differ: empty when
    a round trip kept everything."""
    names = DEVICE_PROFILE_PARTS + ("extra_entries", "other_sections")
    differ = [name for name in names if getattr(a, name) != getattr(b, name)]
    return differ + (["comments"] if list(a.comments) != list(b.comments) else [])
