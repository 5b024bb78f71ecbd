"""The CIP device profile (ISO 15745-4 C.2.1, ``CIP_Device_Profile.xsd``), both directions.

:func:`device_profile` writes the device-profile parts of a :class:`~edsconv.model.Device`
([File], [Device], [Device Classification], [ParamClass], [Params], [Groups],
[Assembly], [Modular]) as schema elements; :func:`read_device_profile` reads them
back. docs/mapping.md maps every keyword and field.

Nothing is lost, by one generic rule: after writing the schema elements the
writer reads them back (the reader's own decoding) and compares the result with
the model, attribute by attribute. Every model value the schema elements do not
give back exactly (a value the XSD type cannot hold, an empty required field, a
"Module" field of a Proxy entry, an international string's language ...) is
stored as an ``edsconv:Value`` with its model path and a typed encoding, inside
``DeviceFunction`` (whose content C.2.1.2.4 leaves open). The entries and
sections the 2003 text does not define and the comments go there too. The
reader decodes the schema elements, then applies the stored values, so a
round trip gives the same model by construction.
"""

from __future__ import annotations

import dataclasses
import datetime
import json
import math
import re

from lxml import etree

from edsconv import spec_tables as tables
from edsconv.diagnostics import Diagnostic, Severity, rule
from edsconv.eds.syntax import Scalar, String
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
from edsconv.model.values import PathItem, Revision, StringIMember, path_items
from edsconv.xml.common import EDSCONV, NSMAP, Header, header_element, is_xml_text, xml_text

BAD_DEVICE_VALUE = rule(
    "XML201", Severity.WARNING, "C.2.1.2",
    "A device profile element holds a value edsconv cannot read; the model field stays empty",
    explanation="""
        A device profile holds a value edsconv cannot read into the model (for example
        a DataType that is neither a hexadecimal code nor a path); that field of the
        model stays empty and the EDS written by xml2eds leaves it out. Profiles that
        edsconv writes never trigger it.
    """,
    bad="`<DataType>word</DataType>`.",
    good="`<DataType>C7</DataType>`",
)
BAD_EXTENSION = rule(
    "XML202", Severity.WARNING, "edsconv",
    "An edsconv extension element of a device profile cannot be read and is ignored",
    clause_note="edsconv extension namespace",
    explanation="""
        An element of edsconv's extension namespace (`urn:x-edsconv:eds-extensions:1`)
        in a device profile cannot be read (hand-edited or from another version) and is
        ignored; see docs/mapping.md for the elements.
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

_PARAM_TAGS = ("Param", "ProxyParam", "ProxiedParam")
_ASSEM_TAGS = ("Assem", "ProxyAssem", "ProxiedAssem")
_NMTOKEN = re.compile(r"[\w.\-:]+")
_MAIN_CLASS = re.compile("|".join((*tables.CLASSIFICATION_KEYWORDS, tables.XSD_VENDOR_KEYWORD)))
_REVISION = re.compile(r"[0-9]\.[1-9]|[1-9]\.[0-9]")
# characters XML 1.0 cannot carry (and lone surrogates, which UTF-8 cannot)

# --- the writer ---------------------------------------------------------------------------

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
    decoded = Device()
    _read_schema_part(body, decoded, [])
    patches = [path for part in DEVICE_PROFILE_PARTS
               for path in _diff(getattr(device, part), getattr(decoded, part), [part])]
    if patches:
        values = etree.SubElement(function, EDSCONV + "Values")
        for path in patches:
            element = etree.SubElement(values, EDSCONV + "Value", path=".".join(path))
            _encode(element, _get(device, path))
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


def _float_text(value: float) -> str:
    if math.isnan(value):
        return "NaN"
    if math.isinf(value):
        return "INF" if value > 0 else "-INF"
    return repr(value)


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
        return _float_text(value)
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
    revision = etree.SubElement(attributes, "ProdRevision", **get)
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
            for tag, text in zip(("Path", "Service", "Size", "ExternalID"), texts):
                _leaf(query_element, tag, text)
    return element


def _write_application_process(device: Device) -> etree._Element | None:
    process = etree.Element("ApplicationProcess")
    if device.param_class is not None or device.parameters:
        parameter = etree.SubElement(process, "Parameter")
        if device.param_class is not None:
            _write_param_class(parameter, device.param_class)
        for tag in _PARAM_TAGS:
            for item in device.parameters.values():
                if item.family == tag and re.fullmatch(tag + tables.INSTANCE_NUMBER, item.keyword):
                    _write_parameter(parameter, item)
    if device.assemblies:
        assembly = etree.SubElement(process, "Assembly")
        for tag in _ASSEM_TAGS:
            for item in device.assemblies.values():
                if item.family == tag and re.fullmatch(tag + tables.INSTANCE_NUMBER, item.keyword):
                    _write_assembly(assembly, item)
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
    etree.SubElement(attributes, "MaxInstance", **get)
    descriptor = _word(param_class.descriptor)
    _leaf(attributes, "ParameterClassDescriptor", descriptor and "0x" + descriptor, "", **get)
    _leaf(attributes, "ConfigurationAssemblyInstance", _number(param_class.cfg_assembly, "UINT"), "", **get)


_SCALING_TAGS = (("ScalingMultiplier", "multiplier", "UINT"), ("ScalingDivider", "divisor", "UINT"),
                 ("ScalingBase", "base", "UINT"), ("ScalingOffset", "offset", "INT"),
                 ("MultiplierLink", "multiplier_link", "UINT"), ("DivisorLink", "divisor_link", "UINT"),
                 ("BaseLink", "base_link", "UINT"), ("OffsetLink", "offset_link", "INT"),
                 ("DecimalPrecision", "decimal_precision", "USINT"))
_INTERNATIONAL_TAGS = (("InternationalParameterName", "international_name"),
                       ("InternationalEngineeringUnits", "international_units"),
                       ("InternationalHelpString", "international_help"))
_VALUE_TAGS = (("MinimumValue", "minimum"), ("MaximumValue", "maximum"), ("DefaultValue", "default"))


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
    for tag, attribute in _VALUE_TAGS:
        _leaf(element, tag, _value_text(getattr(item, attribute)))
    for tag, attribute, type_name in _SCALING_TAGS:
        _leaf(element, tag, _number(getattr(item.scaling, attribute), type_name))
    for tag, attribute in _INTERNATIONAL_TAGS:
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
        for (tag, _), value in zip(_VALUE_TAGS, item.size_adder):
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


# --- the edsconv extension elements ---------------------------------------------------------

def _set_text(element, text: str) -> None:
    """Text of an edsconv element; text XML cannot carry is stored as a JSON string."""
    if not is_xml_text(text):
        element.set("escaped", "json")
        element.text = json.dumps(text, ensure_ascii=True)
    else:
        element.text = text


def _get_text(element) -> str:
    text = element.text or ""
    return json.loads(text) if element.get("escaped") == "json" else text


def _write_extensions(function, device: Device) -> None:
    for section, entries in device.extra_entries.items():
        _write_entries(etree.SubElement(function, EDSCONV + "ExtraEntries", section=section), entries)
    for section in device.other_sections:
        _write_entries(etree.SubElement(function, EDSCONV + "Section", name=section.name), section.entries)
    if device.comments:
        comments = etree.SubElement(function, EDSCONV + "Comments")
        for note in device.comments:
            _write_comment(comments, note)


def _write_comment(parent, note: CommentNote) -> None:
    """One ``edsconv:Comment``: an element each, so that no text node grows with the file."""
    attributes = {"section": note.section, "keyword": note.keyword,
                  "field": None if note.field is None else str(note.field), "leading": "true" if note.leading else None}
    element = etree.SubElement(parent, EDSCONV + "Comment",
                               {key: xml_text(value) for key, value in attributes.items() if value is not None})
    _set_text(element, note.text)


def _write_entries(parent, entries: list[GenericEntry]) -> None:
    for entry in entries:
        element = etree.SubElement(parent, EDSCONV + "Entry", keyword=entry.keyword)
        for value in entry.values:
            _write_field(element, value)


def _write_field(parent, value) -> None:
    element = etree.SubElement(parent, EDSCONV + "Field")
    if value is None:
        element.set("kind", "empty")
    elif isinstance(value, list):
        element.set("kind", "group")
        for item in value:
            _write_field(element, item)
    elif isinstance(value, String):
        element.set("kind", "string")
        if len(value.parts) == 1:  # the usual case: the part as text, quotes included
            _set_text(element, value.parts[0])
        else:
            for part in value.parts:
                _set_text(etree.SubElement(element, EDSCONV + "Part"), part)
    else:
        element.set("kind", "scalar")
        _set_text(element, value.raw)


def _read_field(element):
    kind = element.get("kind")
    if kind == "empty":
        return None
    if kind == "group":
        return [_read_field(child) for child in element if child.tag == EDSCONV + "Field"]
    if kind == "string":
        parts = tuple(_get_text(part) for part in element if part.tag == EDSCONV + "Part")
        return String(parts or (_get_text(element),))
    if kind == "scalar":
        return Scalar(_get_text(element))
    raise ValueError(f"unknown field kind {kind!r}")


# --- typed values (edsconv:Value) ------------------------------------------------------------

_CLASSES = {cls.__name__: cls for cls in (
    FileDescription, Identity, Classification, ParamClass, Scaling, Parameter, ParameterGroup, AssemblyMember,
    Assembly, Rack, Query, Modular, Reference, StringIMember, PathItem)}


def _compared_fields(value) -> list[str]:
    return [f.name for f in dataclasses.fields(value) if f.compare and f.init]


def _encode(element, value) -> None:
    """Write a model value into ``element`` as ``kind`` plus text or child Values."""
    def child(item, **attributes):
        _encode(etree.SubElement(element, EDSCONV + "Value", **attributes), item)

    if value is None:
        element.set("kind", "none")
    elif isinstance(value, bool):
        element.set("kind", "bool")
        element.text = "true" if value else "false"
    elif isinstance(value, int):
        element.set("kind", "int")
        element.text = str(value)
    elif isinstance(value, float):
        element.set("kind", "float")
        element.text = _float_text(value)
    elif isinstance(value, str):
        element.set("kind", "str")
        _set_text(element, value)
    elif isinstance(value, datetime.time):
        element.set("kind", "time")
        element.text = value.isoformat()
    elif isinstance(value, datetime.date):
        element.set("kind", "date")
        element.text = value.isoformat()
    elif isinstance(value, Revision):
        element.set("kind", "revision")
        element.text = str(value)
    elif isinstance(value, tables.DataType):
        element.set("kind", "datatype")
        element.text = value.name
    elif isinstance(value, Reference):
        element.set("kind", "ref")
        element.text = value.text
    elif isinstance(value, tuple) and value and all(isinstance(item, PathItem) for item in value):
        element.set("kind", "path")
        element.text = " ".join(str(item) for item in value)
    elif isinstance(value, (list, tuple)):
        element.set("kind", type(value).__name__)
        for item in value:
            child(item)
    elif isinstance(value, dict):
        element.set("kind", "dict")
        for key, item in value.items():
            entry = etree.SubElement(element, EDSCONV + "Item")
            _encode(etree.SubElement(entry, EDSCONV + "Value"), key)
            _encode(etree.SubElement(entry, EDSCONV + "Value"), item)
    elif type(value).__name__ in _CLASSES:
        element.set("kind", "object")
        element.set("class", type(value).__name__)
        for name in _compared_fields(value):
            child(getattr(value, name), name=name)
    else:
        raise TypeError(f"cannot store a {type(value).__name__} in an edsconv:Value")


def _decode(element):
    kind = element.get("kind")
    text = element.text or ""
    values = [child for child in element if child.tag == EDSCONV + "Value"]
    match kind:
        case "none":
            return None
        case "bool":
            return text == "true"
        case "int":
            return int(text)
        case "float":
            return float(text)
        case "str":
            return _get_text(element)
        case "time":
            return datetime.time.fromisoformat(text)
        case "date":
            return datetime.date.fromisoformat(text)
        case "revision":
            major, minor = text.split(".")
            return Revision(int(major), int(minor))
        case "datatype":
            return tables.DATA_TYPES_BY_NAME[text]
        case "ref":
            return _reference(text)
        case "path":
            return path_items(text)
        case "list":
            return [_decode(child) for child in values]
        case "tuple":
            return tuple(_decode(child) for child in values)
        case "dict":
            return {_decode(item[0]): _decode(item[1]) for item in element if item.tag == EDSCONV + "Item"}
        case "object":
            cls = _CLASSES[element.get("class")]
            return cls(**{child.get("name"): _decode(child) for child in values})
    raise ValueError(f"unknown value kind {kind!r}")


def _same(a, b) -> bool:
    """Equal and of the same types, all the way down (1 is not 1.0 nor True; NaN is NaN)."""
    if type(a) is not type(b):
        return False
    if isinstance(a, float):
        return a == b or (math.isnan(a) and math.isnan(b))
    if isinstance(a, (list, tuple)):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    if isinstance(a, dict):
        return list(a) == list(b) and all(_same(a[k], b[k]) and type(k) is type(k2)
                                          for k, k2 in zip(a, b))
    if dataclasses.is_dataclass(a) and not isinstance(a, tables.DataType):
        return all(_same(getattr(a, name), getattr(b, name)) for name in _compared_fields(a))
    return a == b


_LEAF_CLASSES = (Reference, PathItem, StringIMember, Revision, tables.DataType)


def _diff(a, b, path: list[str]) -> list[list[str]]:
    """The model paths where ``a`` (the model) and ``b`` (read back) differ."""
    if type(a) is not type(b):
        return [path]
    if dataclasses.is_dataclass(a) and not isinstance(a, _LEAF_CLASSES):
        return [p for name in _compared_fields(a) for p in _diff(getattr(a, name), getattr(b, name), path + [name])]
    if isinstance(a, list):
        if len(a) != len(b):
            return [path]
        return [p for index, (x, y) in enumerate(zip(a, b)) for p in _diff(x, y, path + [str(index)])]
    if isinstance(a, dict) and all(isinstance(key, str) for key in a):
        if any(key not in a for key in b):
            return [path]
        return [p for key in a for p in (_diff(a[key], b[key], path + [key]) if key in b else [path + [key]])]
    return [] if _same(a, b) else [path]


def _get(obj, path: list[str]):
    for segment in path:
        obj = obj[int(segment)] if isinstance(obj, list) else obj[segment] if isinstance(obj, dict) \
            else getattr(obj, segment)
    return obj


def _set(obj, path: list[str], value) -> None:
    parent = _get(obj, path[:-1])
    last = path[-1]
    if isinstance(parent, list):
        parent[int(last)] = value
    elif isinstance(parent, dict):
        parent[last] = value
    elif dataclasses.is_dataclass(parent) and last in _compared_fields(parent):
        setattr(parent, last, value)
    else:
        raise KeyError(last)


# --- the reader -------------------------------------------------------------------------------

def read_device_profile(root, device: Device) -> list[Diagnostic]:
    """Fill the device-profile parts of ``device`` from a device profile (the
    ISO15745Profile element or its tree), edsconv extensions included.

    Values the reader cannot convert leave their model field empty (None) with a
    diagnostic; the network profile parts of ``device`` are left alone.
    """
    if isinstance(root, etree._ElementTree):
        root = root.getroot()
    diagnostics: list[Diagnostic] = []
    body = root.find("ProfileBody")
    if body is None:
        return diagnostics
    _read_schema_part(body, device, diagnostics)
    extra: dict[str, list[GenericEntry]] = {}
    sections: list[GenericSection] = []
    comments: list[CommentNote] = []
    values = []
    for function in body.findall("DeviceFunction"):
        for element in function:
            try:
                if element.tag == EDSCONV + "ExtraEntries":
                    extra.setdefault(element.get("section", ""), []).extend(_read_entries(element))
                elif element.tag == EDSCONV + "Section":
                    sections.append(GenericSection(element.get("name", ""), _read_entries(element)))
                elif element.tag == EDSCONV + "Comments":
                    comments.extend(_read_comment(c) for c in element if c.tag == EDSCONV + "Comment")
                elif element.tag == EDSCONV + "Values":
                    values.extend(v for v in element if v.tag == EDSCONV + "Value")
            except (ValueError, TypeError, KeyError) as error:
                _report(diagnostics, BAD_EXTENSION, element, f"{etree.QName(element).localname}: {error}")
    for element in values:
        try:
            _set(device, element.get("path", "").split("."), _decode(element))
        except (ValueError, TypeError, KeyError, IndexError, AttributeError) as error:
            _report(diagnostics, BAD_EXTENSION, element, f"Value {element.get('path')!r}: {error}")
    device.extra_entries = extra
    device.other_sections = sections
    device.comments = comments
    for ref in iter_references(device):
        ref.target = device.resolve(ref.keyword)
    return diagnostics


def _report(diagnostics: list[Diagnostic], rule_, element, message: str) -> None:
    diagnostics.append(Diagnostic.of(rule_, message, element.sourceline or 0, 0))


def _read_entries(parent) -> list[GenericEntry]:
    return [GenericEntry(entry.get("keyword", ""), [_read_field(f) for f in entry if f.tag == EDSCONV + "Field"])
            for entry in parent if entry.tag == EDSCONV + "Entry"]


def _read_comment(element) -> CommentNote:
    field = element.get("field")
    return CommentNote(element.get("section", ""), element.get("keyword"), None if field is None else int(field),
                       _get_text(element), element.get("leading") == "true")


class _Reader:
    """Decodes the schema elements; a value it cannot convert is None plus a diagnostic."""

    def __init__(self, diagnostics: list[Diagnostic]) -> None:
        self.diagnostics = diagnostics

    def bad(self, element, what: str, text: str) -> None:
        _report(self.diagnostics, BAD_DEVICE_VALUE, element, f"{what}: cannot read {text!r}")

    def convert(self, element, converter, what: str | None = None):
        """``converter(text)`` of ``element`` (None when absent or unreadable)."""
        if element is None:
            return None
        text = element.text or ""
        try:
            return converter(text)
        except (ValueError, KeyError, OverflowError):
            self.bad(element, what or etree.QName(element).localname, text)
            return None

    def child(self, parent, tag: str, converter=str):
        return self.convert(parent.find(tag) if parent is not None else None, converter)

    def attribute(self, element, name: str, converter):
        text = element.get(name)
        if text is None:
            return None
        try:
            return converter(text)
        except ValueError:
            self.bad(element, name, text)
            return None


def _integer(text: str) -> int:
    text = text.strip()
    if not re.fullmatch(r"[+-]?[0-9]+", text):
        raise ValueError(text)
    return int(text)


def _hex_binary(text: str) -> int:
    return int(text.strip(), 16)


def _class_word(text: str) -> int:
    text = text.strip()
    return int(text, 16) if text[:2].lower() == "0x" else _integer(text)


def _data_type_code(text: str) -> int | tuple[PathItem, ...]:
    """A USINT code; a one-byte EPATH (``C7``) is the code in hexadecimal; longer paths stay paths."""
    text = text.strip()
    if re.fullmatch("[0-9]+", text) and int(text) <= 255:
        return int(text)
    path = path_items(text)
    return path[0].byte if len(path) == 1 and path[0].byte is not None else path


def _float(text: str) -> float:
    return float(text.strip())


def _member_reference(text: str):
    text = text.strip()
    if re.fullmatch("[0-9]+", text):
        return int(text)
    found = Reference.parse(text)
    if found is not None:
        return found
    try:
        return path_items(text)
    except ValueError:
        return text


def _reference(text: str) -> Reference:
    found = Reference.parse(text.strip())
    if found is None:
        raise ValueError(text)
    return found


def _stringi(text: str) -> tuple[StringIMember, ...]:
    return (StringIMember(*DEFAULT_STRINGI, text),)


def _id_number(element, prefix: str) -> int | None:
    match = re.fullmatch(prefix + "([0-9]+)", element.get("id", ""))
    return int(match.group(1)) if match else None


def _read_schema_part(body, device: Device, diagnostics: list[Diagnostic]) -> None:
    reader = _Reader(diagnostics)
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
        if element.tag in _PARAM_TAGS:
            item = _read_parameter(reader, element)
            device.parameters.setdefault(item.keyword, item)
    for element in process.findall("Assembly/*"):
        if element.tag in _ASSEM_TAGS:
            item = _read_assembly(reader, element)
            device.assemblies.setdefault(item.keyword, item)
    for element in process.findall("ParameterGroup/Group"):
        device.groups.append(_read_group(reader, element))


def _read_file(reader: _Reader, body) -> FileDescription:
    def revision(text: str) -> Revision:
        major, minor = text.split(".")
        return Revision(int(major), int(minor))

    get = reader.attribute
    return FileDescription(
        body.get("DescText"), get(body, "CreateDate", datetime.date.fromisoformat),
        get(body, "CreateTime", datetime.time.fromisoformat), get(body, "ModDate", datetime.date.fromisoformat),
        get(body, "ModTime", datetime.time.fromisoformat), get(body, "Revision", revision), body.get("HomeURL"))


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
            classifications.append(Classification(number, child(element, "MainClass"),
                                                   tuple(s.text or "" for s in element.findall("SubClass"))))
    return identity, classifications


def _read_modular(reader: _Reader, element) -> Modular:
    modular = Modular()
    child = reader.child
    chassis, module = element.find("Chassis"), element.find("Module")
    if chassis is not None:
        modular.define_slots_in_rack = child(chassis, "DefineSlotsInRack", _integer)
        modular.slot_display_rule = child(chassis, "SlotDisplayRule", _reference)
    if module is not None:
        modular.width = child(module, "Width", _integer)
        for rack in module.findall("Rack"):
            number = _id_number(rack, "Rack")
            if number is not None:
                modular.racks.append(Rack(number, *(child(rack, tag, _integer) for tag in
                                                    ("VendCode", "ProdType", "ProdCode", "MajRev", "MinRev")),
                                          tuple(reader.convert(s, _integer) for s in rack.findall("LegalSlot"))))
        modular.external_id = child(module, "ExternalID", path_items)
        modular.generic_id = child(module, "GenericID", path_items)
        modular.extern_id_exact_match = child(module, "ExternIDExactMatch")
        query = module.find("Query")
        if query is not None:
            modular.query = Query(child(query, "Path", path_items), child(query, "Service", _integer),
                                  child(query, "Size", _integer), child(query, "ExternalID", path_items))
    return modular


def _read_parameter(reader: _Reader, element) -> Parameter:
    family = element.tag
    number = _id_number(element, family) or 0
    child = reader.child
    item = Parameter(f"{family}{number}", family, number)
    item.link_path_size = child(element, "LinkPathSize", _integer)
    item.link_path = child(element, "LinkPath", path_items)
    item.descriptor = child(element, "ParamDescriptor", _hex_binary)
    item.data_type_code = child(element, "DataType", _data_type_code)
    if isinstance(item.data_type_code, int):
        code = item.data_type_code
        item.data_type = tables.DATA_TYPES_BY_CODE.get(code) or tables.OBSOLETE_DATA_TYPE_IDS.get(code)
    item.data_size = child(element, "DataSize", _integer)
    item.name, item.units, item.help = (child(element, tag) for tag in ("ParameterName", "UnitsString", "HelpString"))
    for tag, attribute in _VALUE_TAGS:
        value_element = element.find(tag)
        if family == "ProxyParam" and value_element is not None and value_element.text == MODULE:
            setattr(item, attribute, MODULE)  # C.4.1.5.3.1: taken from the ProxiedParam
        else:
            setattr(item, attribute, reader.convert(value_element, _value_reader(item.data_type, attribute)))
    item.scaling = Scaling(**{attribute: child(element, tag, _integer) for tag, attribute, _ in _SCALING_TAGS})
    for tag, attribute in _INTERNATIONAL_TAGS:
        setattr(item, attribute, child(element, tag, _stringi))
    enum = element.find("Enum")
    if enum is not None:
        keys = [reader.convert(e, _integer) for e in enum.findall("EnumValue")]
        item.enum = {key: e.text or "" for key, e in zip(keys, enum.findall("EnumName")) if key is not None}
    adder = element.find("ProxyParamSizeAdder")
    if adder is not None:
        item.size_adder = tuple(child(adder, tag, _value_reader(item.data_type, attribute))
                                for tag, attribute in _VALUE_TAGS)
    return item


def _value_reader(data_type: tables.DataType | None, attribute: str):
    """Minimum / maximum / default by the parameter's data type (Table C.17), as the EDS reader types them."""
    if data_type is None:
        return str
    if attribute != "default" and tables.min_max_rule(data_type.name).meaning == "length":
        return _integer
    if data_type.kind in ("string", "epath", "stringi") or data_type.size is None:
        return str
    return _float if data_type.kind == "real" else _integer


def _read_assembly(reader: _Reader, element) -> Assembly:
    family = element.tag
    number = _id_number(element, family) or 0
    child = reader.child
    item = Assembly(f"{family}{number}", family, number, child(element, "AssemblyName"),
                    child(element, "AssemblyPath", path_items), child(element, "AssemblyDataSize", _integer),
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
            target = reader.convert(member, _reference)
            if target is not None:
                members.append(target)
    return ParameterGroup(_id_number(element, "Group") or 0, reader.child(element, "NameString"),
                          reader.child(element, "NumberOfMembers", _integer), members)


def equal_parts(a: Device, b: Device) -> list[str]:
    """The device-profile parts (and extensions) where two models differ: empty when
    a round trip kept everything."""
    names = DEVICE_PROFILE_PARTS + ("extra_entries", "other_sections")
    differ = [name for name in names if getattr(a, name) != getattr(b, name)]
    return differ + (["comments"] if list(a.comments) != list(b.comments) else [])
