"""The EtherNet/IP communication network profile (ENet_CommNet_Profile.xsd, C.3.1), both directions.

:func:`commnet_profile` turns the [Connection Manager] and [Port] parts of a
:class:`~edsconv.model.Device` into the ISO15745Profile root of a network
profile; :func:`read_commnet_profile` fills ``device.connections`` and
``device.ports`` back from one. ``build(eds)`` -> :func:`commnet_profile` ->
:func:`read_commnet_profile` gives connections and ports equal to the original's.

What the schema's types cannot hold exactly goes into its ``xsd:any`` extension
points as elements of the edsconv namespace (docs/mapping.md, "Communication
network profile"):

- ``edsconv:Module field="O-T_Size"``: the field is the keyword ``Module`` (C.4.1.5.3.3);
- ``edsconv:Empty field="Path"``: the EDS field is empty where the schema requires an element;
- ``edsconv:Value field="O-T_Format">AssemExa3<``: the exact value where the element's type cannot
  hold it (newer-spec references, a connection name another connection already has, characters
  XML cannot carry: ``escaped="true"``);
- ``edsconv:Connection`` / ``edsconv:Port``: an entry the Connection / Port elements cannot hold
  (keyword number beyond the id pattern, a port type name that is no keyword, a repeated PortN);
- ``edsconv:EntryOrder``: the order of the [Connection Manager] entries when it is not the
  schema's Connection*, ProxyConnect*, ProxiedConnect*;
- ``edsconv:Field`` / ``edsconv:Empty`` / ``edsconv:Group`` in PortSpecific: Port fields 7....
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

from lxml import etree

from edsconv import spec_tables as tables
from edsconv.diagnostics import Diagnostic
from edsconv.eds.reader_rules import DUPLICATE_ENTRY
from edsconv.model import MODULE, Connection, Device, Port, Reference
from edsconv.model.values import OUT_OF_RANGE, WRONG_KIND, PathItem, ValueProblem, path_items
from edsconv.xml.common import (
    EDSCONV,
    NSMAP,
    Header,
    file_description_attributes,
    header_element,
    is_xml_text,
    xml_text,
)
from edsconv.xml.datamodel import collapse, string_value, token
from edsconv.xml.safe import XmlDocument

#: Connection families in the order the schema's ConnectionDescriptions sequence wants them.
FAMILIES = ("Connection", "ProxyConnect", "ProxiedConnect")

_N = tables.INSTANCE_NUMBER
# The lexical spaces of ENet_CommNet_Profile.xsd the writer must meet.
_PORT_TYPE = re.compile("|".join((*tables.PORT_TYPE_KEYWORDS, tables.XSD_VENDOR_KEYWORD)))
_ENTRY_ID = {family: re.compile(f"{family}{_N}") for family in (*FAMILIES, "Port")}
_ANY_KEYWORD = re.compile(r"(Connection|ProxyConnect|ProxiedConnect|Port)([1-9][0-9]*)")
_ESCAPE = re.compile(r"\\(\\|u[0-9A-Fa-f]{4})")

_UDINT_MAX, _UINT_MAX = 0xFFFFFFFF, 0xFFFF


@dataclass(frozen=True, slots=True)
class _Field:
    """One element of et_ConnectionType and where the model keeps its value."""

    tag: str
    #: the ConnectionEndpoint attribute of Connection (o_to_t ...), None for the connection itself
    endpoint: str | None
    attribute: str
    #: dword, rpi, size, format, text, path
    kind: str

    @property
    def required(self) -> bool:
        return self.kind in ("dword", "text", "path")

    def get(self, connection: Connection) -> Any:
        return getattr(getattr(connection, self.endpoint) if self.endpoint else connection, self.attribute)

    def set(self, connection: Connection, value: Any) -> None:
        setattr(getattr(connection, self.endpoint) if self.endpoint else connection, self.attribute, value)


def _endpoint_fields(prefix: str, endpoint: str, rpi: bool) -> tuple[_Field, ...]:
    fields = (_Field(f"{prefix}_Size", endpoint, "size", "size"),
              _Field(f"{prefix}_Format", endpoint, "format", "format"))
    return ((_Field(f"{prefix}_RPI", endpoint, "rpi", "rpi"),) if rpi else ()) + fields


#: Table C.22 fields 1-15 as the elements of et_ConnectionType, in schema order.
CONNECTION_FIELDS: tuple[_Field, ...] = (
    _Field("Trigger_Transport", None, "trigger_transport", "dword"),
    _Field("Connection_Parameters", None, "parameters", "dword"),
    *_endpoint_fields("O-T", "o_to_t", True),
    *_endpoint_fields("T-O", "t_to_o", True),
    *_endpoint_fields("Config1", "config1", False),
    *_endpoint_fields("Config2", "config2", False),
    _Field("Name_String", None, "name", "text"),
    _Field("Help_String", None, "help", "text"),
    _Field("Path", None, "path", "path"),
)
_FIELDS_BY_TAG = {field.tag: field for field in CONNECTION_FIELDS}


def _ext(tag: str, text: str | None = None, **attributes: str) -> etree._Element:
    element = etree.Element(EDSCONV + tag, attributes, nsmap=NSMAP)
    element.text = text
    return element


def _escape(text: str) -> str:
    """``\\`` doubled and every character XML cannot hold as ``\\uXXXX`` (all are below U+10000)."""
    return "".join(f"\\u{ord(c):04X}" if not is_xml_text(c) else "\\\\" if c == "\\" else c for c in text)


def _unescape(text: str) -> str:
    return _ESCAPE.sub(lambda m: "\\" if m[1] == "\\" else chr(int(m[1][1:], 16)), text)


def _text_extension(tag: str, text: str, **attributes: str) -> etree._Element:
    """``text`` exactly, escaped when XML cannot hold it."""
    if is_xml_text(text):
        return _ext(tag, text, **attributes)
    return _ext(tag, _escape(text), escaped="true", **attributes)


#: The port elements whose exact text an edsconv:Value holds when XML cannot: the Port attribute it sets.
_PORT_TEXT_FIELDS = {"PortTypeName": "type_name", "PortName": "name", "PortObject": "object_path"}


def _path_text(path: Iterable[PathItem]) -> str:
    return " ".join(str(item) for item in path)


# --- writing -------------------------------------------------------------------------------

def _schema_text(field: _Field, value: Any) -> str | None:
    """``value`` in the type of the field's element, or None when the type cannot hold it."""
    if isinstance(value, int) and not isinstance(value, bool):
        if field.kind == "dword" and 0 <= value <= _UDINT_MAX:
            return f"{value:08X}"
        if (field.kind == "rpi" and 0 <= value <= _UDINT_MAX) or (field.kind == "size" and 0 <= value <= _UINT_MAX):
            return str(value)
        return None
    if isinstance(value, Reference) and field.kind in ("rpi", "size", "format"):
        text = value.text
        forms: tuple[re.Pattern[str], ...] = (tables.XSD_PARAM_REFERENCE_RE,)
        if field.kind == "format":
            forms += (tables.XSD_ASSEM_REFERENCE_RE,)
        return text if any(form.fullmatch(text) for form in forms) else None
    return None


def _value_extension(field: _Field, value: Any) -> etree._Element:
    """edsconv:Value holding a value the field's element cannot."""
    if isinstance(value, Reference):
        return _ext("Value", value.text, field=field.tag)
    if isinstance(value, tuple):
        return _ext("Value", _path_text(value), field=field.tag)
    if isinstance(value, str):
        return _text_extension("Value", value, field=field.tag, type="string")
    return _ext("Value", str(value), field=field.tag)


def _field_content(field: _Field, value: Any, names: set[str], keyword: str) -> tuple[str | None, list]:
    """The element text (None: no element) and the extension elements of one field."""
    empty = "" if field.required else None
    if field.kind == "text":
        if value is None:
            text, extensions = "", [_ext("Empty", field=field.tag)]
        elif is_xml_text(value):
            text, extensions = value, []
        else:
            text, extensions = xml_text(value), [_value_extension(field, value)]
        if field.attribute == "name":
            # the schema's key ConnectionName: Name_String is unique among the connections
            unique = text
            while unique in names:
                unique = f"{unique} [{keyword}]".lstrip()
            names.add(unique)
            if unique != text and value is not None and not extensions:
                extensions = [_value_extension(field, value)]
            text = unique
        return text, extensions
    if value is None:
        # dword: an empty hexBinary is "no value" in its own type
        return empty, [_ext("Empty", field=field.tag)] if field.kind == "path" else []
    if value == MODULE:
        return empty, [_ext("Module", field=field.tag)]
    if field.kind == "path":
        if isinstance(value, tuple):
            return _path_text(value), []
        return empty, [_value_extension(field, value)]
    schema_text = _schema_text(field, value)
    if schema_text is None:
        return empty, [_value_extension(field, value)]
    return schema_text, []


def _connection_element(connection: Connection, tag: str, names: set[str]) -> etree._Element:
    element = etree.Element(tag, id=connection.keyword)
    extensions = []
    for field in CONNECTION_FIELDS:
        text, extension = _field_content(field, field.get(connection), names, connection.keyword)
        if text is not None:
            etree.SubElement(element, field.tag).text = text
        extensions.extend(extension)
    element.extend(extensions)
    return element


def _connection_descriptions(device: Device) -> etree._Element | None:
    if not device.connections:
        return None
    descriptions = etree.Element("ConnectionDescriptions")
    names: set[str] = set()
    standard = {family: [c for c in device.connections.values()
                         if c.family == family and _ENTRY_ID[family].fullmatch(c.keyword)] for family in FAMILIES}
    written = [c.keyword for family in FAMILIES for c in standard[family]]
    for family in FAMILIES:
        for connection in standard[family]:
            descriptions.append(_connection_element(connection, family, names))
    for connection in device.connections.values():
        if connection.keyword not in written:
            descriptions.append(_connection_element(connection, EDSCONV + "Connection", names))
            written.append(connection.keyword)
    if written != list(device.connections):
        descriptions.append(_ext("EntryOrder", " ".join(device.connections)))
    return descriptions


def _specific_elements(values: Iterable[Any]) -> list[etree._Element]:
    """Port Specific fields (plain values: text, None, lists for brace groups)."""
    elements = []
    for value in values:
        if value is None:
            elements.append(_ext("Empty"))
        elif isinstance(value, (list, tuple)):
            group = _ext("Group")
            group.extend(_specific_elements(value))
            elements.append(group)
        else:
            elements.append(_text_extension("Field", str(value)))
    return elements


def _port_fits(port: Port, ids: set[str]) -> bool:
    """True when a Port element can hold the port: its id, type name and number are in the schema's types."""
    keyword = f"Port{port.number}"
    return (_ENTRY_ID["Port"].fullmatch(keyword) is not None and keyword not in ids
            and isinstance(port.type_name, str) and _PORT_TYPE.fullmatch(port.type_name) is not None
            and isinstance(port.port_number, int) and 0 <= port.port_number <= _UINT_MAX)


def _port_element(port: Port, tag: str, **attributes: str) -> etree._Element:
    """A Port, or an edsconv:Port whose children are in the edsconv namespace too: an element without
    namespace inside an extension would be validated against the schema's global declarations."""
    namespace = tag[:tag.index("}") + 1] if tag.startswith("{") else ""
    element = etree.Element(tag, {"id": f"Port{port.number}", **attributes})
    extensions = []
    if port.type_name is not None:
        etree.SubElement(element, namespace + "PortTypeName").text = xml_text(port.type_name)
        if not is_xml_text(port.type_name):
            extensions.append(_text_extension("Value", port.type_name, field="PortTypeName"))
    if port.name is not None:
        etree.SubElement(element, namespace + "PortName").text = xml_text(port.name)
        if not is_xml_text(port.name):
            extensions.append(_text_extension("Value", port.name, field="PortName"))
    if isinstance(port.object_path, tuple):
        etree.SubElement(element, namespace + "PortObject").text = _path_text(port.object_path)
    elif port.object_path is not None:  # kept as written, not decodable: as a connection's path is
        etree.SubElement(element, namespace + "PortObject").text = ""
        extensions.append(_text_extension("Value", port.object_path, field="PortObject"))
    if port.port_number is not None:
        etree.SubElement(element, namespace + "PortNumber").text = str(port.port_number)
    specific = etree.SubElement(element, namespace + "PortSpecific")
    specific.extend(_specific_elements(port.specific))
    element.extend(extensions)
    return element


def _ports(device: Device) -> list[etree._Element]:
    """Ports (when any port fits a Port element) and an edsconv:Port for each one that does not."""
    ports = etree.Element("Ports")
    others = []
    ids: set[str] = set()
    for position, port in enumerate(device.ports):
        if _port_fits(port, ids):
            ids.add(f"Port{port.number}")
            ports.append(_port_element(port, "Port"))
        else:
            others.append(_port_element(port, EDSCONV + "Port", position=str(position)))
    return ([ports] if len(ports) else []) + others


def commnet_profile(device: Device, header: Header) -> etree._Element:
    """The ISO15745Profile root of the EtherNet/IP network profile of ``device``.

    It states only what the EDS states: its connections and ports. The schema requires
    ConnectionManager, MessageRouter and TransportLayers, none of their children; the
    objects whose services and attributes an EDS does not describe (Connection Manager
    and Message Router operations, the EtherNet/IP Link, TCP/IP Interface and
    encapsulation objects, NetworkManagement) are left out, since every SupportedService
    or Access_Rule written there would claim what the EDS does not say.
    """
    root = etree.Element("ISO15745Profile", nsmap=NSMAP)
    root.append(header_element(header, "CommunicationNetwork", "EtherNet/IP", "COMM", "CSI"))
    body = etree.SubElement(root, "ProfileBody", file_description_attributes(device, header))
    application = etree.SubElement(body, "ApplicationLayers")
    manager = etree.SubElement(application, "ConnectionManager")
    descriptions = _connection_descriptions(device)
    if descriptions is not None:
        manager.append(descriptions)
    etree.SubElement(application, "MessageRouter")
    etree.SubElement(body, "TransportLayers").extend(_ports(device))
    etree.cleanup_namespaces(root, top_nsmap=NSMAP)
    return root


# --- reading -------------------------------------------------------------------------------

class _Reader:
    def __init__(self, device: Device, document: XmlDocument) -> None:
        self.device = device
        self.document = document
        self.diagnostics: list[Diagnostic] = []

    def report(self, problem: ValueProblem, element: etree._Element) -> None:
        self.diagnostics.append(self.document.diagnostic(problem.rule, f"{_describe(element)}: {problem.message}",
                                                         element))

    # values
    @staticmethod
    def reference(text: str) -> Reference:
        found = Reference.parse(text)
        if found is None:
            raise ValueProblem(WRONG_KIND, f"{text!r} is neither a number nor a ParamN / AssemN reference")
        return found

    def number_or_reference(self, text: str) -> int | Reference:
        text = collapse(text)
        return int(text) if text.isascii() and text.isdigit() else self.reference(text)

    @staticmethod
    def path(text: str) -> tuple[PathItem, ...]:
        return path_items(text)

    def field_value(self, field: _Field, element: etree._Element) -> Any:
        text = string_value(element)
        if field.kind == "text":
            return text
        if field.kind == "path":
            return self.path(text)
        if field.kind == "dword":
            text = collapse(text)
            if not re.fullmatch(r"(?:[0-9A-Fa-f]{2}){0,4}", text):
                raise ValueProblem(WRONG_KIND, f"{text!r} is not a DWORD in hexBinary (at most 8 hexadecimal digits)")
            return int(text, 16) if text else None
        return self.number_or_reference(text)

    def extension_value(self, field: _Field | None, element: etree._Element) -> Any:
        text = string_value(element)
        if element.get("escaped") == "true":
            text = _unescape(text)
        if field is None or field.kind == "text" or element.get("type") == "string":
            return text
        if field.kind == "path":
            return self.path(text)
        return self.number_or_reference(text)

    # connections
    def connection(self, element: etree._Element, family: str, keyword: str, number: int) -> Connection:
        connection = Connection(keyword, family, number)
        for child in element.iterchildren(etree.Element):
            try:
                if child.tag in _FIELDS_BY_TAG:
                    field = _FIELDS_BY_TAG[child.tag]
                    field.set(connection, self.field_value(field, child))
                elif child.tag in (EDSCONV + "Module", EDSCONV + "Empty", EDSCONV + "Value"):
                    named = _FIELDS_BY_TAG.get(child.get("field", ""))
                    if named is None:
                        raise ValueProblem(WRONG_KIND, f"field {child.get('field')!r} is not a connection field")
                    field = named
                    marker = etree.QName(child).localname
                    value = MODULE if marker == "Module" else None if marker == "Empty" else \
                        self.extension_value(field, child)
                    field.set(connection, value)
            except ValueProblem as problem:
                self.report(problem, child)
        return connection

    def connections(self, descriptions: etree._Element) -> None:
        found: dict[str, Connection] = {}
        order: list[str] = []
        for child in descriptions:
            if child.tag == EDSCONV + "EntryOrder":
                order = string_value(child).split()
                continue
            if child.tag not in (*FAMILIES, EDSCONV + "Connection"):
                continue
            keyword = collapse(child.get("id", ""))
            match = _ANY_KEYWORD.fullmatch(keyword)
            if match is None or match[1] not in FAMILIES or (child.tag in FAMILIES and child.tag != match[1]):
                self.report(ValueProblem(WRONG_KIND, f"id {keyword!r} is not a {etree.QName(child).localname}N "
                                         "keyword"), child)
                continue
            if keyword in found:  # ids are unique among the schema's elements; an edsconv:Connection may repeat one
                self.diagnostics.append(self.document.diagnostic(
                    DUPLICATE_ENTRY, f"{_describe(child)}: id {keyword!r} repeats an earlier connection; the first "
                    "is kept", child))
                continue
            found[keyword] = self.connection(child, match[1], keyword, int(match[2]))
        for keyword in [k for k in order if k in found] + [k for k in found if k not in order]:
            self.device.connections[keyword] = found[keyword]

    # ports
    def specific(self, elements: Iterable[etree._Element]) -> list[Any]:
        values: list[Any] = []
        for element in elements:
            if element.tag == EDSCONV + "Empty":
                values.append(None)
            elif element.tag == EDSCONV + "Group":
                values.append(self.specific(element))
            elif element.tag == EDSCONV + "Field":
                values.append(self.extension_value(None, element))
        return values

    def port(self, element: etree._Element) -> Port | None:
        keyword = collapse(element.get("id", ""))
        match = _ANY_KEYWORD.fullmatch(keyword)
        if not match or match[1] != "Port":
            self.report(ValueProblem(WRONG_KIND, f"id {keyword!r} is not a PortN keyword"), element)
            return None
        port = Port(int(match[2]))
        for child in element.iterchildren(etree.Element):
            # an edsconv:Port's children are in its namespace, a Port's in none
            tag = etree.QName(child).localname if child.tag != EDSCONV + "Value" else child.tag
            try:
                if tag == "PortTypeName":
                    port.type_name = token(child)
                elif tag == "PortName":
                    port.name = string_value(child)
                elif tag == "PortObject":
                    port.object_path = self.path(token(child))
                elif tag == "PortNumber":
                    text = token(child)
                    if not (text.isascii() and text.isdigit()) or int(text) > _UINT_MAX:
                        raise ValueProblem(OUT_OF_RANGE, f"{text!r} is not a UINT port number")
                    port.port_number = int(text)
                elif tag == "PortSpecific":
                    port.specific = tuple(self.specific(child))
                elif tag == EDSCONV + "Value" and child.get("field") in _PORT_TEXT_FIELDS:
                    setattr(port, _PORT_TEXT_FIELDS[child.get("field", "")], self.extension_value(None, child))
            except ValueProblem as problem:
                self.report(problem, child)
        return port

    def ports(self, transport: etree._Element) -> None:
        ports: list[Port] = []
        placed: list[tuple[int, Port]] = []
        for element in transport.iterchildren("Ports", EDSCONV + "Port"):
            if element.tag == "Ports":
                ports.extend(p for p in map(self.port, element.iterchildren("Port")) if p is not None)
                continue
            port = self.port(element)
            position = element.get("position", "")
            if port is None:
                continue
            if position.isascii() and position.isdigit():
                placed.append((int(position), port))
            else:
                ports.append(port)
        for index, port in sorted(placed, key=lambda item: item[0]):
            ports.insert(index, port)
        self.device.ports.extend(ports)


def _describe(element: etree._Element) -> str:
    qname = etree.QName(element)
    name = f"edsconv:{qname.localname}" if qname.namespace else qname.localname
    owner = next((a.get("id") for a in element.iterancestors() if a.get("id")), None)
    return f"{owner} {name}" if owner else name


def read_commnet_profile(source: XmlDocument | etree._ElementTree | etree._Element,
                         device: Device) -> list[Diagnostic]:
    """Fill ``device.connections`` and ``device.ports`` from a network profile (the document,
    its root or tree; the inverse of :func:`commnet_profile`, extension elements included);
    the diagnostics name values that could not be read, at their element. The objects'
    operations and attributes (SupportedService, Access_Rule) have no place in the model."""
    document = XmlDocument.of(source)
    reader = _Reader(device, document)
    body = document.tree.getroot().find("ProfileBody")
    if body is None:
        return reader.diagnostics
    descriptions = body.find("ApplicationLayers/ConnectionManager/ConnectionDescriptions")
    if descriptions is not None:
        reader.connections(descriptions)
    transport = body.find("TransportLayers")
    if transport is not None:
        reader.ports(transport)
    for connection in device.connections.values():
        for endpoint in (connection.o_to_t, connection.t_to_o, connection.config1, connection.config2):
            for value in (endpoint.rpi, endpoint.size, endpoint.format):
                if isinstance(value, Reference):
                    value.target = device.resolve(value.keyword)
    return reader.diagnostics
