"""Writing the CIP device profile (ISO 15745-4 C.2.1, ``CIP_Device_Profile.xsd``) of a model.

:func:`device_profile` writes the device-profile parts of a :class:`~edsconv.model.Device`
([File], [Device], [Device Classification], [ParamClass], [Params], [Groups],
[Assembly], [Modular]) as schema elements; docs/mapping.md maps every keyword and field.

Nothing is lost, by one generic rule: after writing the schema elements the
writer reads them back (the reader's own decoding) and compares the result with
the model, attribute by attribute. Every model value the schema elements do not
give back exactly (a value the XSD type cannot hold, an empty required field, a
"Module" field of a Proxy entry, an international string's language ...) is
stored as an ``edsconv:Value`` with its model path and a typed encoding
(:mod:`edsconv.xml.codec`), inside ``DeviceFunction`` (whose content C.2.1.2.4
leaves open). The entries and sections the 2003 text does not define and the
comments go there too. The reader decodes the schema elements, then applies the
stored values, so a round trip gives the same model by construction.
"""

from __future__ import annotations

import datetime
import re

from lxml import etree

from edsconv import spec_tables as tables
from edsconv.model import (
    MODULE_MEMBER_LIST,
    Assembly,
    Device,
    FileDescription,
    Modular,
    ParamClass,
    Parameter,
    Reference,
)
from edsconv.model.values import PathItem, Revision
from edsconv.xml.codec import (
    differences,
    encode,
    float_text,
    get_path,
    write_comment,
    write_entries,
    write_unreadable,
)
from edsconv.xml.common import EDSCONV, NSMAP, Header, header_element, is_xml_text, xml_text
from edsconv.xml.device_read import (
    ASSEM_TAGS,
    DEVICE_PROFILE_PARTS,
    INTERNATIONAL_TAGS,
    PARAM_TAGS,
    SCALING_TAGS,
    VALUE_TAGS,
    read_schema_part,
)
from edsconv.xml.newer import place, section_element, write_entry_list

_NMTOKEN = re.compile(r"[\w.\-:]+")
_MAIN_CLASS = re.compile("|".join((*tables.CLASSIFICATION_KEYWORDS, tables.XSD_VENDOR_KEYWORD)))
_REVISION = re.compile(r"[0-9]\.[1-9]|[1-9]\.[0-9]")

def device_profile(device: Device, header: Header, *, commnet_handle: bool = False) -> etree._Element:
    """The ISO15745Profile root of the device profile of ``device``.

    ``commnet_handle`` adds the ExternalProfileHandle naming the communication
    network profile of the same header (``<identification>-COMM``).
    """
    root = etree.Element("ISO15745Profile", nsmap=NSMAP)
    root.append(header_element(header, "Device", "CIP", "DEV"))
    body = etree.SubElement(root, "ProfileBody")
    _write_file(body, device.file, header)
    _write_identity(body, device)
    if device.modular is not None:
        modular = _write_modular(device.modular)
        if modular is not None:
            etree.SubElement(body, "DeviceManager").append(modular)
    function = etree.SubElement(body, "DeviceFunction")
    process = _write_application_process(device)
    if process is not None:
        body.append(process)
    if commnet_handle:
        handle = etree.SubElement(body, "ExternalProfileHandle")
        etree.SubElement(handle, "ProfileIdentification").text = f"{header.identification}-COMM"
        etree.SubElement(handle, "ProfileRevision").text = header.revision
    _write_extensions(function, device)
    place(body, function)
    decoded = Device()
    read_schema_part(body, decoded)
    patches = [path for part in DEVICE_PROFILE_PARTS
               for path in differences(getattr(device, part), getattr(decoded, part), [part])]
    if patches:
        values = etree.SubElement(function, EDSCONV + "Values")
        for path in patches:
            element = etree.SubElement(values, EDSCONV + "Value", path=".".join(path))
            encode(element, get_path(device, path))
    return root


def _clean(text: str | None) -> str | None:
    """Text for a schema element: characters XML cannot carry become U+FFFD
    (the exact text then goes into an edsconv:Value)."""
    return None if text is None else xml_text(text)


def _number(value, type_name: str) -> str | None:
    """Decimal text of an integer that fits the CIP type, else None."""
    if isinstance(value, int) and not isinstance(value, bool) and tables.DATA_TYPES_BY_NAME[type_name].in_range(value):
        return str(value)
    return None


def _word(value) -> str | None:
    """hexBinary of at most two bytes (dt_WORD)."""
    return f"{value:04X}" if isinstance(value, int) and not isinstance(value, bool) and 0 <= value <= 0xFFFF else None


def _path_text(value) -> str | None:
    """dt_EPATH text: bytes, SLOT keywords and [ParamN] substitutions the XSD allows."""
    if not isinstance(value, tuple) or not all(isinstance(item, PathItem) for item in value):
        return None
    for item in value:
        if item.byte is None and item.keyword not in tables.PATH_KEYWORDS and \
                not (item.reference and tables.XSD_PATH_REFERENCE_RE.fullmatch(item.reference)):
            return None
    return " ".join(str(item) for item in value)


def _value_text(value) -> str | None:
    """Minimum / maximum / default (untyped in the XSD): numbers and text."""
    if isinstance(value, bool):
        return None
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return float_text(value)
    if isinstance(value, str):
        return _clean(value)
    return None


def _leaf(parent, tag: str, text: str | None, placeholder: str | None = None, **attributes) -> etree._Element | None:
    """Append ``<tag>text</tag>``; a None text writes ``placeholder`` (required
    elements) or nothing (optional ones, ``placeholder`` None)."""
    if text is None:
        text = placeholder
    if text is None:
        return None
    element = etree.SubElement(parent, tag, **attributes)
    element.text = text
    return element


def _write_file(body, file: FileDescription, header: Header) -> None:
    revision = str(file.revision) if isinstance(file.revision, Revision) else None
    attributes = {
        "DescText": _clean(file.description) or "",
        "CreateDate": (file.create_date or header.date).isoformat(),
        "CreateTime": (file.create_time or datetime.time(0, 0)).isoformat(),
        "ModDate": file.mod_date.isoformat() if file.mod_date else None,
        "ModTime": file.mod_time.isoformat() if file.mod_time else None,
        "Revision": revision if revision and _REVISION.fullmatch(revision) else "1.0",
        "HomeURL": _clean(file.home_url) if file.home_url and _is_uri(file.home_url) else None,
        # Table C.1: the EtherNet/IP specification version; an EDS does not state it.
        "SpecificationConformance": "",
    }
    for name, value in attributes.items():
        if value is not None:
            body.set(name, value)


def _is_uri(text: str) -> bool:
    # xsd:anyURI as xmlschema checks it: no spaces or characters outside URI references
    return not re.search(r"[\s<>\"{}|\\^`]", text) and is_xml_text(text)


def _write_identity(body, device: Device) -> None:
    identity = device.identity
    attributes = etree.SubElement(etree.SubElement(body, "DeviceIdentity"), "DeviceIdentity_InstanceAttributes")
    get = {"Access_Rule": "Get"}
    _leaf(attributes, "VendCode", _number(identity.vendor_code, "UINT"), "0", **get)
    _leaf(attributes, "VendName", _clean(identity.vendor_name), "")
    _leaf(attributes, "ProdType", _number(identity.product_type, "UINT"), "0", **get)
    _leaf(attributes, "ProdTypeStr", _clean(identity.product_type_string), "")
    _leaf(attributes, "ProdCode", _number(identity.product_code, "UINT"), "0", **get)
    revision = etree.SubElement(attributes, "ProdRevision", get)
    _leaf(revision, "MajRev", _number(identity.major_revision, "USINT"), "0")
    _leaf(revision, "MinRev", _number(identity.minor_revision, "USINT"), "0")
    _leaf(attributes, "ProdName", _clean(identity.product_name), "", **get)
    _leaf(attributes, "Catalog", _clean(identity.catalog))
    _leaf(attributes, "Icon", _clean(identity.icon))
    _leaf(attributes, "ExcludeFromAdapterRackConnection", _clean(identity.exclude_from_adapter_rack_connection))
    classes = [c for c in _unique(device.classifications, "Class") if isinstance(c.classification, str)
               and _MAIN_CLASS.fullmatch(c.classification) and all(_NMTOKEN.fullmatch(s) for s in c.subclassifications)]
    if classes:
        classification = etree.SubElement(attributes, "DeviceClassification")
        for item in classes:
            element = etree.SubElement(classification, "Class", id=f"Class{item.number}")
            _leaf(element, "MainClass", item.classification)
            for sub in item.subclassifications:
                _leaf(element, "SubClass", sub)


def _unique(items, prefix: str) -> list:
    """The numbered objects whose ``<prefix>N`` id is valid and not taken by an earlier one."""
    seen, kept = set(), []
    for item in items:
        number = item.number
        if isinstance(number, int) and re.fullmatch(tables.INSTANCE_NUMBER, str(number)) and number not in seen:
            seen.add(item.number)
            kept.append(item)
    return kept


def _write_modular(modular: Modular) -> etree._Element | None:
    element = etree.Element("Modular")
    if _number(modular.define_slots_in_rack, "UINT") is not None:
        chassis = etree.SubElement(element, "Chassis")
        _leaf(chassis, "DefineSlotsInRack", str(modular.define_slots_in_rack))
        rule_ = modular.slot_display_rule
        if isinstance(rule_, Reference) and tables.XSD_PARAM_REFERENCE_RE.fullmatch(rule_.text):
            _leaf(chassis, "SlotDisplayRule", rule_.text)
        return element
    racks = [r for r in _unique(modular.racks, "Rack") if r.legal_slots and
             all(_number(s, "UINT") is not None for s in r.legal_slots)]
    if _number(modular.width, "UINT") is None or not racks:
        return None
    module = etree.SubElement(element, "Module")
    _leaf(module, "Width", str(modular.width))
    for rack in racks:
        rack_element = etree.SubElement(module, "Rack", id=f"Rack{rack.number}")
        for tag, value, type_name in (("VendCode", rack.vendor_code, "UINT"), ("ProdType", rack.product_type, "UINT"),
                                      ("ProdCode", rack.product_code, "UINT"),
                                      ("MajRev", rack.major_revision, "USINT"),
                                      ("MinRev", rack.minor_revision, "USINT")):
            _leaf(rack_element, tag, _number(value, type_name), "0")
        for slot in rack.legal_slots:
            _leaf(rack_element, "LegalSlot", str(slot))
    _leaf(module, "ExternalID", _path_text(modular.external_id))
    _leaf(module, "GenericID", _path_text(modular.generic_id))
    if modular.extern_id_exact_match in ("Yes", "No"):
        _leaf(module, "ExternIDExactMatch", modular.extern_id_exact_match)
    query = modular.query
    if query is not None:
        texts = (_path_text(query.path), _number(query.service, "USINT"),
                 str(query.id_size) if isinstance(query.id_size, int) and 1 <= query.id_size <= 16 else None,
                 _path_text(query.empty_slot_id))
        if None not in texts:
            query_element = etree.SubElement(module, "Query")
            for tag, text in zip(("Path", "Service", "Size", "ExternalID"), texts, strict=True):
                _leaf(query_element, tag, text)
    return element


def _write_application_process(device: Device) -> etree._Element | None:
    process = etree.Element("ApplicationProcess")
    if device.param_class is not None or device.parameters:
        parameter = etree.SubElement(process, "Parameter")
        if device.param_class is not None:
            _write_param_class(parameter, device.param_class)
        for tag in PARAM_TAGS:
            for item in device.parameters.values():
                if item.family == tag and re.fullmatch(tag + tables.INSTANCE_NUMBER, item.keyword):
                    _write_parameter(parameter, item)
    if device.assemblies:
        assembly = etree.SubElement(process, "Assembly")
        for tag in ASSEM_TAGS:
            for each in device.assemblies.values():
                if each.family == tag and re.fullmatch(tag + tables.INSTANCE_NUMBER, each.keyword):
                    _write_assembly(assembly, each)
    groups = [g for g in _unique(device.groups, "Group")]
    if groups:
        group_list = etree.SubElement(process, "ParameterGroup")
        for group in groups:
            element = etree.SubElement(group_list, "Group", id=f"Group{group.number}")
            _leaf(element, "NameString", _clean(group.name), "")
            _leaf(element, "NumberOfMembers", _number(group.declared_members, "UINT"), "0")
            for member in group.members:
                if member.family == "Param" and member.bit is None and _number(member.number, "UINT"):
                    _leaf(element, "ParameterRef", str(member.number))
                elif _NMTOKEN.fullmatch(member.text):
                    _leaf(element, "VariantRef", member.text)
    return process if len(process) else None


def _write_param_class(parameter, param_class: ParamClass) -> None:
    attributes = etree.SubElement(etree.SubElement(parameter, "Parameter_Class"), "Parameter_ClassAttributes")
    get = {"Access_Rule": "Get"}
    # MaxInstance has no content in the XSD: the [ParamClass] MaxInst value is an edsconv:Value
    etree.SubElement(attributes, "MaxInstance", get)
    descriptor = _word(param_class.descriptor)
    _leaf(attributes, "ParameterClassDescriptor", descriptor and "0x" + descriptor, "", **get)
    _leaf(attributes, "ConfigurationAssemblyInstance", _number(param_class.cfg_assembly, "UINT"), "", **get)


def _write_parameter(parent, item: Parameter) -> None:
    element = etree.SubElement(parent, item.family, id=item.keyword)
    _leaf(element, "LinkPathSize", _number(item.link_path_size, "USINT"))
    _leaf(element, "LinkPath", _path_text(item.link_path))
    _leaf(element, "ParamDescriptor", _word(item.descriptor), "0000")
    code = item.data_type_code
    _leaf(element, "DataType", _number(code, "USINT") or _path_text(code), "0")
    _leaf(element, "DataSize", _number(item.data_size, "USINT"), "0")
    _leaf(element, "ParameterName", _clean(item.name) if isinstance(item.name, str) else None, "")
    _leaf(element, "UnitsString", _clean(item.units) if isinstance(item.units, str) else None, "")
    _leaf(element, "HelpString", _clean(item.help) if isinstance(item.help, str) else None, "")
    for tag, attribute in VALUE_TAGS:
        _leaf(element, tag, _value_text(getattr(item, attribute)))
    for tag, attribute, type_name in SCALING_TAGS:
        _leaf(element, tag, _number(getattr(item.scaling, attribute), type_name))
    for tag, attribute in INTERNATIONAL_TAGS:
        members = getattr(item, attribute)
        if isinstance(members, tuple) and members:
            _leaf(element, tag, _clean(members[0].text))
    pairs = [(key, text) for key, text in (item.enum or {}).items() if _number(key, "LINT") is not None]
    if pairs:
        enum = etree.SubElement(element, "Enum")
        for key, text in pairs:
            _leaf(enum, "EnumValue", str(key))
            _leaf(enum, "EnumName", _clean(text) if isinstance(text, str) else "")
    if item.family == "ProxyParam" and item.size_adder is not None:
        adder = etree.SubElement(element, "ProxyParamSizeAdder")
        for (tag, _), value in zip(VALUE_TAGS, item.size_adder, strict=False):
            _leaf(adder, tag, _value_text(value), "")


def _write_assembly(parent, item: Assembly) -> None:
    element = etree.SubElement(parent, item.family, id=item.keyword)
    _leaf(element, "AssemblyName", _clean(item.name) if isinstance(item.name, str) else None)
    _leaf(element, "AssemblyPath", _path_text(item.path))
    _leaf(element, "AssemblyDataSize", _number(item.size, "UINT"))
    _leaf(element, "AssemblyDescriptor", _word(item.descriptor))
    for member in item.members:
        member_element = etree.SubElement(element, "AssemblyMember")
        size = _number(member.size, "UINT")
        target = _member_text(member.reference)
        # a member with neither size nor reference: a 0-bit pad here, its empty size in an edsconv:Value
        _leaf(member_element, "MemberSize", size, None if target else "0")
        _leaf(member_element, "MemberReference", target)
    if item.module_member_list:
        _leaf(etree.SubElement(element, "AssemblyMember"), "MemberReference", MODULE_MEMBER_LIST)


def _member_text(value) -> str | None:
    if isinstance(value, Reference):
        text = value.text
        return text if tables.XSD_PARAM_REFERENCE_RE.fullmatch(text) or tables.XSD_ASSEM_REFERENCE_RE.fullmatch(text) \
            or _NMTOKEN.fullmatch(text) else None
    if isinstance(value, int):
        return _number(value, "UDINT")
    if isinstance(value, tuple):
        return _path_text(value) or None
    if isinstance(value, str) and _NMTOKEN.fullmatch(value):
        return value
    return None


def _write_extensions(function, device: Device) -> None:
    for name, entries in device.extra_entries.items():
        write_entry_list(etree.SubElement(function, EDSCONV + "ExtraEntries", section=name), name, entries, True)
    for section in device.other_sections:
        typed = section_element(section)
        if typed is not None:
            function.append(typed)
        else:
            write_entries(etree.SubElement(function, EDSCONV + "Section", name=section.name), section.entries)
    if device.comments:
        comments = etree.SubElement(function, EDSCONV + "Comments")
        for note in device.comments:
            write_comment(comments, note)
    if device.unreadable:
        unreadable = etree.SubElement(function, EDSCONV + "UnreadableText")
        for item in device.unreadable:
            write_unreadable(unreadable, item)
