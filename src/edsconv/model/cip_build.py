"""The typed view of the content beyond the 2003 text, built from the entries kept as written.

:func:`attach` reads ``Device.extra_entries`` and ``Device.other_sections`` (what
:mod:`edsconv.model.build` and the XML reader fill alike) and sets the :mod:`edsconv.model.cip`
records on the device: ``capacity``, ``object_classes``, the network objects, ``devicenet``,
``extended_assemblies``, ``icon_contents``, ``additions``. Every field is read by its
:mod:`edsconv.cip_tables` FieldSpec (:func:`read_field`, which the checks use too); a value that
fits none of its field's types is None here, and EDS501-EDS503 say why. References between entries
are resolved: AssemExaN members and sizes, ConnectionN of DefaultSafetyConnections, the AssemN of
SafetyCfgAssembly, the InputN / OutputN of DeviceNet I/O modes, Service_DescriptionN data.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Any

from edsconv import cip_tables
from edsconv import spec_tables as tables
from edsconv.eds.syntax import Scalar, String, ValueKind
from edsconv.model.cip import (
    INTERFACE_ATTRIBUTES,
    SINGLE_ATTRIBUTES,
    Additions,
    Capacity,
    DeviceLevelRing,
    DeviceNetIo,
    EthernetInterface,
    EthernetLink,
    IngressEgress,
    IoData,
    IoMode,
    ObjectClass,
    QuickConnectOriginator,
    QuickConnectTarget,
    Service,
    ServiceDescription,
    TcpIpInterface,
    TrafficSpec,
)
from edsconv.model.device import Assembly, AssemblyMember, Device, GenericEntry, Reference
from edsconv.model.icon import decode_icon
from edsconv.model.values import HEX_TOO_LONG, OUT_OF_RANGE, WRONG_KIND, ValueNote, ValueProblem, convert

#: A written value as GenericEntry keeps it: a Scalar, a String, None, or a list for a brace group.
Written = Any

_COMMON = cip_tables.COMMON_OBJECT_CLASS.name
_KINDS = {**tables.FIELD_VALUE_KINDS, **cip_tables.CIP_VALUE_KINDS}
#: Reference kinds: kind -> the pattern of the keyword it names.
_REFERENCE_KINDS = {kind: re.compile(pattern) for kind, pattern in _KINDS.items()
                    if kind.endswith("Ref") and pattern is not None}
#: The families AssemN-like entries hold (their members are read like an AssemN's, Table C.20).
ASSEMBLY_FAMILIES = ("AssemExa", "ProxyAssemExa", "ProxiedAssemExa")


# --- one field -------------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class _Plan:
    """How to read a field of one FieldSpec type (``UINT|ParamRef``): its alternatives by shape."""

    #: the keyword patterns of its reference kinds, in the type's order
    references: tuple[re.Pattern[str], ...]
    #: the data type and keyword alternatives, in the type's order
    values: tuple[str, ...]
    service: bool
    untyped: bool
    names: str


@functools.cache
def _plan(eds_type: str) -> _Plan:
    kinds = eds_type.split("|")
    values = tuple("EDS_Char_Array" if k == "Base64Icon" else k for k in kinds  # the icon's text: EDS509 / EDS510
                   if k not in _REFERENCE_KINDS and k not in ("Empty", "Untyped", "ServiceSpec"))
    names = " or ".join(k.removesuffix("Ref") + "N" if k in _REFERENCE_KINDS else k for k in kinds if k != "Empty")
    return _Plan(tuple(_REFERENCE_KINDS[k] for k in kinds if k in _REFERENCE_KINDS), values, "ServiceSpec" in kinds,
                 "Untyped" in kinds, names)


def read_field(value: Written, field_spec: tables.FieldSpec) -> Any:
    """A written field value as the Python value of the first of its FieldSpec's types it fits;
    None for an empty field. ValueProblem when it fits none: the notation or range problem of the
    type it was written as, else WRONG_KIND; a ValueNote (with the one reading) when that problem
    leaves the value one reading (leading zeros, too many hex digits), as the values policy says."""
    if value is None:
        return None
    plan = _plan(field_spec.eds_type)
    if plan.untyped:
        return _spelling(value)
    if plan.service:
        return _service(value)
    if isinstance(value, list):
        raise ValueProblem(WRONG_KIND, f"expected {plan.names}, found a brace group")
    if isinstance(value, Scalar) and value.kind is ValueKind.WORD:
        for pattern in plan.references:
            if pattern.fullmatch(value.raw):
                family, number = tables.split_numbered(value.raw)
                return Reference(value.raw, family, number or 0)
    found: list[ValueProblem] = []
    for kind in plan.values:
        try:
            return convert(value, kind)
        except ValueNote as note:
            if note.reported:
                return note.value  # a string flaw: the check of every string reports it (EDS116, EDS117)
            found.append(note)
        except ValueProblem as problem:
            found.append(problem)
    relevant = next((p for p in found if p.rule is not WRONG_KIND), None)
    if relevant is not None:
        raise relevant
    raise ValueProblem(WRONG_KIND, f"expected {plan.names}, found {_spelling(value)}")


def _service(value: Written) -> Service:
    """``0x0E`` or ``{0x0E,*}`` / ``{0x10,3,5}``: a USINT service code and UINT attribute IDs."""
    if not isinstance(value, list):
        return Service(convert(value, "USINT"))
    if not value or value[0] is None:
        raise ValueProblem(WRONG_KIND, "a service group starts with the service code")
    code = convert(value[0], "USINT")
    rest = value[1:]
    if len(rest) == 1 and isinstance(rest[0], Scalar) and rest[0].raw == "*":
        return Service(code, (), True)
    if any(item is None or isinstance(item, list) for item in rest):
        raise ValueProblem(WRONG_KIND, "a service group lists attribute IDs, or *")
    return Service(code, tuple(convert(item, "UINT") for item in rest))


def _spelling(value: Written) -> str:
    if isinstance(value, list):
        return "{" + ", ".join(_spelling(v) for v in value) + "}"
    if isinstance(value, String):
        return value.raw
    return "" if value is None else value.raw


def is_number(value: Written) -> bool:
    """A Scalar written as a number (integer, hex, binary or real), whatever its range."""
    return isinstance(value, Scalar) and value.kind in (ValueKind.INTEGER, ValueKind.HEX, ValueKind.BINARY,
                                                         ValueKind.REAL)


def range_problem(problem: ValueProblem) -> bool:
    """A number of the right notation that does not fit its type (OUT_OF_RANGE, too many hex digits)."""
    return problem.rule is OUT_OF_RANGE or problem.rule is HEX_TOO_LONG


# --- the sections ------------------------------------------------------------------------------


def section_table(name: str, extension: bool) -> tables.SectionSpec | None:
    """The cip_tables section of a section beyond the 2003 text (``extension`` False) or of the
    entries beyond the 2003 text in a 2003 section."""
    return cip_tables.SECTION_EXTENSIONS.get(name) if extension else cip_tables.section_spec(name)


def newer_entries(device: Device) -> Iterator[tuple[str, tables.SectionSpec, GenericEntry, tables.EntrySpec]]:
    """(section name, its cip_tables section, entry, entry spec) of every entry kept as written that
    the cip_tables define: in a section beyond the 2003 text, or added to a 2003 section."""
    for name, entries, extension in (*((n, e, True) for n, e in device.extra_entries.items()),
                                     *((s.name, s.entries, False) for s in device.other_sections)):
        table = section_table(name, extension)
        if table is None:
            continue
        for generic in entries:
            spec = tables.find_entry(table.entries, generic.keyword)
            if spec is not None:
                yield name, table, generic, spec


class _Builder:
    def __init__(self, device: Device) -> None:
        self.device = device
        self.handlers: dict[str, Callable[[str, GenericEntry, tables.EntrySpec, list[Any]], None]] = {
            "Capacity": self.capacity, "TCP/IP Interface Class": self.tcpip, "Ethernet Link Class": self.link,
            "DLR Class": self.dlr, "Ingress Egress Class": self.ingress_egress, "IO_Info": self.io_info,
            "EnumPar": self.enum_par, "Assembly": self.assembly, "Device": self.device_entry,
        }

    def entry(self, name: str, table: tables.SectionSpec, generic: GenericEntry, spec: tables.EntrySpec) -> None:
        generic.readings = [reading(value, spec.field_at(index + 1)) for index, value in enumerate(generic.values)]
        values = [value for value, _ in generic.readings]
        if spec.section == _COMMON:
            self.common(name, generic, spec, values)
        elif spec.keyword in SINGLE_ATTRIBUTES.get(table.name, {}) and table.name in _ADDITION_SECTIONS:
            attribute = SINGLE_ATTRIBUTES[table.name][spec.keyword]
            setattr(self.additions(), attribute, _naming(attribute, _single(spec, values)))
        elif table.name in self.handlers:
            self.handlers[table.name](name, generic, spec, values)

    def additions(self) -> Additions:
        self.device.additions = self.device.additions or Additions()
        return self.device.additions

    def common(self, name: str, generic: GenericEntry, spec: tables.EntrySpec, values: list[Any]) -> None:
        record = self.device.object_classes.get(name)
        if record is None:
            vendor = cip_tables.vendor_class_section(name)
            record = self.device.object_classes[name] = ObjectClass(
                name, cip_tables.class_id_of(name), vendor[1] if vendor else None)
        if spec.numbered:  # Service_DescriptionN
            code, name_, path, request, response = _padded(values, 5)
            record.service_descriptions.append(ServiceDescription(
                tables.instance_number(generic.keyword), code, name_, path, request, response, generic.entry))
        else:
            setattr(record, SINGLE_ATTRIBUTES[_COMMON][spec.keyword], _single(spec, values))

    def capacity(self, name: str, generic: GenericEntry, spec: tables.EntrySpec, values: list[Any]) -> None:
        capacity = self.device.capacity = self.device.capacity or Capacity()
        if spec.numbered:
            direction, size, rate = _padded(values, 3)
            capacity.traffic_specs.append(TrafficSpec(tables.instance_number(generic.keyword), direction, size, rate,
                                                      generic.entry))
        else:
            setattr(capacity, SINGLE_ATTRIBUTES["Capacity"][spec.keyword], _single(spec, values))

    def tcpip(self, name: str, generic: GenericEntry, spec: tables.EntrySpec, values: list[Any]) -> None:
        record = self.device.tcpip_interface = self.device.tcpip_interface or TcpIpInterface()
        number = tables.instance_number(generic.keyword)
        if spec.keyword == "ENetQCT":
            ready, accumulated = _padded(values, 2)
            record.quick_connect_targets.append(QuickConnectTarget(number, ready, accumulated, generic.entry))
        else:
            record.quick_connect_originators.append(QuickConnectOriginator(number, tuple(values), generic.entry))

    def link(self, name: str, generic: GenericEntry, spec: tables.EntrySpec, values: list[Any]) -> None:
        record = self.device.ethernet_link = self.device.ethernet_link or EthernetLink()
        number = tables.instance_number(generic.keyword)
        interface = next((i for i in record.interfaces if i.instance == number), None)
        if interface is None:
            interface = EthernetInterface(number)
            record.interfaces.append(interface)
            record.interfaces.sort(key=lambda i: i.instance)
        setattr(interface, INTERFACE_ATTRIBUTES[spec.keyword], _single(spec, values))

    def dlr(self, name: str, generic: GenericEntry, spec: tables.EntrySpec, values: list[Any]) -> None:
        record = self.device.dlr = self.device.dlr or DeviceLevelRing()
        setattr(record, SINGLE_ATTRIBUTES["DLR Class"][spec.keyword], _single(spec, values))

    def ingress_egress(self, name: str, generic: GenericEntry, spec: tables.EntrySpec, values: list[Any]) -> None:
        record = self.device.ingress_egress = self.device.ingress_egress or IngressEgress()
        setattr(record, SINGLE_ATTRIBUTES["Ingress Egress Class"][spec.keyword], _single(spec, values))

    def devicenet(self) -> DeviceNetIo:
        self.device.devicenet = self.device.devicenet or DeviceNetIo()
        return self.device.devicenet

    def io_info(self, name: str, generic: GenericEntry, spec: tables.EntrySpec, values: list[Any]) -> None:
        io = self.devicenet()
        keyword = generic.keyword
        if spec.keyword == "Default":
            io.default = _single(spec, values)
        elif spec.numbered:
            size, bits, mask, name_, path_size, path, help_ = _padded(values, 7)
            data = IoData(keyword, tables.instance_number(keyword), size, bits, mask, name_, path_size, path, help_,
                          generic.entry)
            (io.inputs if spec.keyword == "Input" else io.outputs).setdefault(keyword, data)
        else:
            mask, default_input, default_output = _padded(values, 3)
            io.modes.setdefault(keyword, IoMode(keyword, mask, _io_reference("Input", default_input),
                                                _io_reference("Output", default_output), generic.entry))

    def enum_par(self, name: str, generic: GenericEntry, spec: tables.EntrySpec, values: list[Any]) -> None:
        self.devicenet().enum_strings.setdefault(generic.keyword, tuple(values))

    def assembly(self, name: str, generic: GenericEntry, spec: tables.EntrySpec, values: list[Any]) -> None:
        if spec.keyword not in ASSEMBLY_FAMILIES or generic.keyword in self.device.extended_assemblies:
            return
        name_, path, size, descriptor = _padded(values, 4)
        written = generic.values
        members = [AssemblyMember(values[index], _member_reference(written, values, index + 1), index)
                   for index in range(6, len(values), 2)]
        self.device.extended_assemblies[generic.keyword] = Assembly(
            generic.keyword, spec.keyword, tables.instance_number(generic.keyword), name_, path, size, descriptor,
            members, entry=generic.entry)

    def device_entry(self, name: str, generic: GenericEntry, spec: tables.EntrySpec, values: list[Any]) -> None:
        if spec.keyword == "IconContents":
            text = generic.values[0] if generic.values else None
            self.device.icon_contents = decode_icon(text.text) if isinstance(text, String) else None


#: The sections whose single entries land in :class:`Additions`.
_ADDITION_SECTIONS = frozenset({"File", "Device", "ParamClass", "Connection Manager"})


#: Additions that name entries by their number: attribute -> the family they name.
_NAMES_BY_NUMBER = {"default_safety_connections": "Connection", "safety_cfg_assembly": "Assem"}


def _naming(attribute: str, value: Any) -> Any:
    """DefaultSafetyConnections names ConnectionN by number, SafetyCfgAssembly an AssemN: as references."""
    family = _NAMES_BY_NUMBER.get(attribute)
    if family is None or value is None:
        return value
    if isinstance(value, tuple):
        return tuple(Reference(f"{family}{n}", family, n) for n in value if isinstance(n, int))
    return Reference(f"{family}{value}", family, value) if isinstance(value, int) else None


def _member_reference(written: list[Written], values: list[Any], index: int) -> Any:
    """A Member Reference; ``""`` is a pad, like an empty field (Table C.20)."""
    if index >= len(values) or (isinstance(written[index], String) and written[index].text == ""):
        return None
    return values[index]


def _io_reference(family: str, number: Any) -> Reference | None:
    """An [IO_Info] default input or output: the N of an InputN / OutputN, 0 for none."""
    return Reference(f"{family}{number}", family, number) if isinstance(number, int) and number else None


def reading(value: Written, field_spec: tables.FieldSpec | None) -> tuple[Any, ValueProblem | None]:
    """A field read by its spec: (value, None), or (value or None, why it does not fit: a value when the
    breach leaves one reading); (None, None) without a spec."""
    if field_spec is None:
        return None, None
    try:
        return read_field(value, field_spec), None
    except ValueNote as note:
        return note.value, note  # one reading: kept, and reported (EDS501 / EDS502)
    except ValueProblem as problem:
        return None, problem


def _single(spec: tables.EntrySpec, values: list[Any]) -> Any:
    """The value of a one-field entry; a tuple for an entry of a repeating field (Class_Attributes)."""
    if spec.repeating or len(spec.fields) > 1:
        return tuple(values)
    return values[0] if values else None


def _padded(values: list[Any], count: int) -> list[Any]:
    return (values + [None] * count)[:count]


def attach(device: Device) -> Device:
    """Set the typed view of the content beyond the 2003 text on ``device``, from its
    ``extra_entries`` and ``other_sections``; returns the device. The view is made anew, so that
    attaching again (after reading a profile, which attaches) does not add the records twice."""
    device.capacity = device.tcpip_interface = device.ethernet_link = device.dlr = None
    device.ingress_egress = device.devicenet = device.icon_contents = device.additions = None
    device.object_classes, device.extended_assemblies = {}, {}
    builder = _Builder(device)
    for name, table, generic, spec in newer_entries(device):
        builder.entry(name, table, generic, spec)
    resolve(device)
    return device


def resolve(device: Device) -> None:
    """Point the references of the typed view at the records of ``device`` they name."""
    for assembly in device.extended_assemblies.values():
        for member in assembly.members:
            if isinstance(member.reference, Reference):
                member.reference.target = device.resolve(member.reference.keyword)
        if isinstance(assembly.size, Reference):
            assembly.size.target = device.resolve(assembly.size.keyword)
    for record in device.object_classes.values():
        for description in record.service_descriptions:
            for reference in (description.request, description.response):
                if reference is not None:
                    reference.target = device.resolve(reference.keyword)
    if device.additions is not None:
        named = (*(device.additions.default_safety_connections or ()), device.additions.safety_cfg_assembly)
        for reference in named:
            if reference is not None:
                reference.target = device.resolve(reference.keyword)
    if device.devicenet is not None:
        for mode in device.devicenet.modes.values():
            for reference, data in ((mode.default_input, device.devicenet.inputs),
                                    (mode.default_output, device.devicenet.outputs)):
                if reference is not None:
                    reference.target = data.get(reference.keyword)


@functools.cache
def modelled(section: str, keyword: str) -> bool:
    """True when the typed view holds the entry ``keyword`` of ``[section]`` (diff compares it there):
    every entry of these tables but the assembly entry types no real file writes (VariantN ...)."""
    spec = cip_tables.entry_spec(section, keyword)
    return spec is not None and (spec.section != "Assembly" or spec.keyword in ASSEMBLY_FAMILIES)
