"""What an EDS says about a device, as one document of plain JSON data (``edsconv show``).

:func:`describe` turns a :class:`~edsconv.model.Device` into a document of
plain JSON types: bit fields spelled out in words (Tables C.15, C.23, C.24),
references resolved (an RPI named ``Param1`` shows that parameter's default
and range, a format ``Assem150`` that assembly's name and size), assemblies
laid out bit by bit and CIP paths decoded segment by segment
(:mod:`edsconv.model.epath`). ``edsconv show`` prints this document as JSON, or
renders its text tables from it (:mod:`edsconv.cli.show`), so both always say
the same thing.
"""

from __future__ import annotations

import dataclasses
from typing import Any

from edsconv import cip_tables
from edsconv import spec_tables as tables
from edsconv.model import (
    Assembly,
    Connection,
    ConnectionEndpoint,
    Device,
    GenericEntry,
    Parameter,
    Reference,
)
from edsconv.model.cip import DeviceNetIo, IoData, Service
from edsconv.model.cip_build import modelled
from edsconv.model.device import PARAMETER_FIELD_ATTRIBUTES
from edsconv.model.epath import decode_path
from edsconv.model.icon import Icon
from edsconv.model.plain import plain
from edsconv.model.values import PathItem

#: ``--section`` names -> the keys of the :func:`describe` document they show.
SECTIONS: dict[str, tuple[str, ...]] = {
    "identity": ("file", "identity", "classifications", "param_class", "additions"),
    "parameters": ("parameters",),
    "groups": ("groups",),
    "assemblies": ("assembly_revision", "assemblies", "extended_assemblies"),
    "connections": ("connections",),
    "ports": ("ports",),
    "modular": ("modular",),
    "capacity": ("capacity",),
    "network": ("network",),
    "objects": ("object_classes",),
    "devicenet": ("devicenet",),
    "icon": ("icon",),
    "other": ("other_sections", "extra_entries"),
}


def hex_code(value: Any, digits: int) -> str | None:
    """An integer in hex with ``digits`` digits; anything else as plain data."""
    return f"0x{value:0{digits}X}" if isinstance(value, int) else plain(value)


# --- parameters ---------------------------------------------------------------------------------


def _scaling_used(parameter: Parameter) -> bool:
    s = parameter.scaling
    factors = (s.multiplier, s.divisor, s.base, s.offset)
    numbers = [f for f in factors if isinstance(f, int)]
    return bool(numbers) and any(numbers) and s.divisor != 0


def _engineering(parameter: Parameter, value: Any) -> Any:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    try:
        result = parameter.engineering_value(value)
    except (ArithmeticError, TypeError, ValueError):
        return None
    if isinstance(result, float) and result.is_integer() and abs(result) < 2**53:
        result = int(result)
    return plain(result)


def describe_parameter(parameter: Parameter) -> dict:
    data_type = parameter.data_type
    doc: dict[str, Any] = {
        "keyword": parameter.keyword,
        "name": parameter.name,
        "data_type": {
            "name": data_type.name if data_type else None,
            "code": data_type.code if data_type else None,
            "written": plain(parameter.data_type_code),
        },
        "size": plain(parameter.data_size),
        "minimum": plain(parameter.minimum),
        "maximum": plain(parameter.maximum),
        "default": plain(parameter.default),
        "units": parameter.units,
        "help": parameter.help,
        "descriptor": hex_code(parameter.descriptor, 4),
        "flags": parameter.descriptor_flags() if isinstance(parameter.descriptor, int) else [],
        "enum": [{"value": value, "text": text} for value, text in (parameter.enum or {}).items()],
    }
    if parameter.link_path:
        doc["link_path"] = decode_path(parameter.link_path)
    if _scaling_used(parameter):
        s = parameter.scaling
        doc["scaling"] = {"multiplier": s.multiplier, "divisor": s.divisor, "base": s.base, "offset": s.offset,
                          "decimal_precision": s.decimal_precision}
        doc["engineering"] = {key: _engineering(parameter, getattr(parameter, key))
                              for key in ("minimum", "maximum", "default")}
    links = {name: getattr(parameter.scaling, f"{name}_link") for name in ("multiplier", "divisor", "base", "offset")}
    if any(links.values()):
        doc["scaling_links"] = links
    if parameter.size_adder:
        doc["size_adder"] = dict(zip(("minimum", "maximum", "default"), plain(parameter.size_adder), strict=False))
    unread = _unread_values(parameter)
    if unread:
        doc["invalid"] = unread
    return doc


#: the field index of each value show marks when it cannot be read
_VALUE_FIELDS = {name: PARAMETER_FIELD_ATTRIBUTES.index(name) for name in ("minimum", "maximum", "default")}


def _unread_values(parameter: Parameter) -> dict[str, str]:
    """The minimum, maximum and default the file writes but that have no reading (a BOOL default
    of 255: lint reports it), as written: show prints what the file says, marked, not a blank."""
    fields = parameter.entry.fields if parameter.entry is not None else []
    return {name: fields[index].raw or "" for name, index in _VALUE_FIELDS.items()
            if getattr(parameter, name) is None and index < len(fields) and fields[index].value is not None}


def _parameter_summary(parameter: Parameter) -> dict:
    return {"kind": "parameter", "keyword": parameter.keyword, "name": parameter.name,
            "data_type": parameter.data_type.name if parameter.data_type else None,
            "default": plain(parameter.default), "minimum": plain(parameter.minimum),
            "maximum": plain(parameter.maximum), "units": parameter.units}


def _assembly_summary(assembly: Assembly, device: Device) -> dict:
    return {"kind": "assembly", "keyword": assembly.keyword, "name": assembly.name,
            "size": plain(assembly.size), "total_bits": _total_bits(assembly, device)}


def resolve(reference: Reference, device: Device) -> dict:
    """What a reference names, summarised; ``kind`` is "undefined" when nothing does."""
    target = reference.target if reference.target is not None else device.resolve(reference.keyword)
    if isinstance(target, Parameter):
        summary = _parameter_summary(target)
    elif isinstance(target, Assembly):
        summary = _assembly_summary(target, device)
    elif isinstance(target, GenericEntry):
        summary = {"kind": "entry", "keyword": target.keyword, "values": plain(target.values)}
    else:
        summary = {"kind": "undefined", "keyword": reference.keyword}
    if reference.bit is not None:
        summary["bit"] = reference.bit
    return summary


# --- assemblies ---------------------------------------------------------------------------------


def _total_bits(assembly: Assembly, device: Device) -> int | None:
    """What the members add up to; None when a size is unknown, the members come from the
    module, or none is listed."""
    if assembly.module_member_list or not assembly.members:
        return None
    bits = [device.member_bits(assembly, member) for member in assembly.members]
    return None if None in bits else sum(b for b in bits if b is not None)


def _layout(assembly: Assembly, device: Device) -> list[dict]:
    """The members of an assembly with their bit offsets (None after a member of unknown size)."""
    members: list[dict] = []
    offset: int | None = 0
    for member in assembly.members:
        bits = device.member_bits(assembly, member)
        reference = member.reference
        if reference is None:
            what: dict[str, Any] = {"kind": "pad"}
        elif isinstance(reference, Reference):
            what = resolve(reference, device)
        elif isinstance(reference, int):
            what = {"kind": "constant", "value": reference}
        elif isinstance(reference, str):
            what = {"kind": "keyword", "keyword": reference}
        else:
            what = {"kind": "path", "path": decode_path(reference, device)}
        members.append({"offset": offset, "bits": bits, "declared_bits": member.size, "member": what})
        offset = offset + bits if offset is not None and bits is not None else None
    return members


def describe_assembly(assembly: Assembly, device: Device) -> dict:
    members, total = _layout(assembly, device), _total_bits(assembly, device)
    return {
        "keyword": assembly.keyword,
        "name": assembly.name,
        "size": plain(assembly.size),
        "descriptor": hex_code(assembly.descriptor, 4),
        "path": decode_path(assembly.path, device),
        "module_member_list": assembly.module_member_list,
        "members": members,
        "total_bits": total,
    }


# --- connections --------------------------------------------------------------------------------


def describe_trigger_transport(connection: Connection) -> dict | None:
    value = connection.trigger_transport
    if not isinstance(value, int):
        return None if value is None else {"value": plain(value)}
    table = tables.TRIGGER_TRANSPORT_BITS
    set_fields = [f for f, v, _ in connection.trigger_transport_bits() if v and not f.reserved]
    by_group = {group: [f for f in set_fields if f.group == group] for group in ("class", "trigger", "transport")}
    return {
        "value": f"0x{value:08X}",
        "classes": [f.first_bit for f in by_group["class"]],
        "class_names": [f.meanings[1] for f in by_group["class"]],
        "triggers": [f.name.removeprefix("trigger ") for f in by_group["trigger"]],
        "transport": [f.name for f in by_group["transport"]],
        "role": table.field("client/server").meanings[value >> 31 & 1],
        "reserved_bits": f"0x{tables.reserved_bits_set(value, table):08X}" if tables.reserved_bits_set(
            value, table) else None,
    }


def describe_connection_parameters(connection: Connection) -> dict | None:
    value = connection.parameters
    if not isinstance(value, int):
        return None if value is None else {"value": plain(value)}
    table = tables.CONNECTION_PARAMETER_BITS
    doc: dict[str, Any] = {"value": f"0x{value:08X}"}
    for direction in ("O=>T", "T=>O"):
        def get(name: str, direction: str = direction) -> int:
            return table.field(f"{direction} {name}").extract(value)

        doc[direction] = {
            "fixed_size": bool(get("fixed size")),
            "variable_size": bool(get("variable size")),
            "bytes_per_slot": table.field(f"{direction} bytes per slot").meanings[get("bytes per slot")],
            "real_time_format": table.field(f"{direction} real time format").meanings[get("real time format")],
            "connection_types": [t for t in ("NULL", "MULTICAST", "POINT2POINT") if get(t)],
            "priorities": [p for p in ("LOW", "HIGH", "SCHEDULED") if get(p)],
        }
    reserved = tables.reserved_bits_set(value, table)
    doc["reserved_bits"] = f"0x{reserved:08X}" if reserved else None
    return doc


def _endpoint_value(value: Any, device: Device) -> dict | None:
    if value is None:
        return None
    if isinstance(value, Reference):
        target = resolve(value, device)
        effective = target.get("default") if target["kind"] == "parameter" else None
        return {"written": value.keyword, "value": effective, "reference": target}
    return {"written": plain(value), "value": plain(value)}


def _format_value(value: Any, device: Device) -> dict | None:
    if isinstance(value, Reference):
        return {"written": value.keyword, **resolve(value, device)}
    return None if value is None else {"written": plain(value), "kind": "value"}


def describe_endpoint(endpoint: ConnectionEndpoint, device: Device, with_rpi: bool = True) -> dict | None:
    if endpoint.rpi is None and endpoint.size is None and endpoint.format is None:
        return None
    doc = {"size": _endpoint_value(endpoint.size, device), "format": _format_value(endpoint.format, device)}
    if with_rpi:
        doc = {"rpi": _endpoint_value(endpoint.rpi, device), **doc}
    return doc


def describe_connection(connection: Connection, device: Device) -> dict:
    return {
        "keyword": connection.keyword,
        "name": connection.name,
        "help": connection.help,
        "trigger_transport": describe_trigger_transport(connection),
        "parameters": describe_connection_parameters(connection),
        "O=>T": describe_endpoint(connection.o_to_t, device),
        "T=>O": describe_endpoint(connection.t_to_o, device),
        "config1": describe_endpoint(connection.config1, device, with_rpi=False),
        "config2": describe_endpoint(connection.config2, device, with_rpi=False),
        "path": decode_path(connection.path, device),
    }


# --- the document -------------------------------------------------------------------------------


def _fields(obj: Any) -> dict:
    return {f.name: plain(getattr(obj, f.name)) for f in dataclasses.fields(obj)}


def describe(device: Device) -> dict:
    """Everything ``edsconv show`` prints, as plain JSON data."""
    modular = device.modular
    return {
        "file": _fields(device.file),
        "identity": _fields(device.identity),
        "classifications": [{"number": c.number, "classification": c.classification,
                             "subclassifications": list(c.subclassifications)} for c in device.classifications],
        "param_class": None if device.param_class is None else {
            "max_instances": device.param_class.max_instances,
            "descriptor": hex_code(device.param_class.descriptor, 4),
            "flags": tables.flags_set(device.param_class.descriptor, tables.PARAMCLASS_DESCRIPTOR_BITS)
            if isinstance(device.param_class.descriptor, int) else [],
            "cfg_assembly": device.param_class.cfg_assembly,
        },
        "parameters": [describe_parameter(p) for p in device.parameters.values()],
        "groups": [{"number": g.number, "name": g.name, "declared_members": g.declared_members,
                    "members": [resolve(m, device) for m in g.members]} for g in device.groups],
        "assembly_revision": device.assembly_revision,
        "assemblies": [describe_assembly(a, device) for a in device.assemblies.values()],
        "connections": [describe_connection(c, device) for c in device.connections.values()],
        "ports": [{"number": p.number, "type": p.type_name, "name": p.name,
                   "object_path": decode_path(p.object_path, device), "port_number": p.port_number,
                   "specific": plain(p.specific)} for p in device.ports],
        "modular": None if modular is None else {
            "role": "chassis" if modular.is_chassis else "module" if modular.is_module else None,
            "define_slots_in_rack": modular.define_slots_in_rack,
            "slot_display_rule": resolve(modular.slot_display_rule, device) if modular.slot_display_rule else None,
            "width": modular.width,
            "racks": [{"number": r.number, "vendor_code": r.vendor_code, "product_type": r.product_type,
                       "product_code": r.product_code, "major_revision": r.major_revision,
                       "minor_revision": r.minor_revision, "legal_slots": list(r.legal_slots)} for r in modular.racks],
            "external_id": plain(modular.external_id),
            "generic_id": plain(modular.generic_id),
            "extern_id_exact_match": modular.extern_id_exact_match,
            "query": None if modular.query is None else {
                "path": decode_path(modular.query.path, device), "service": hex_code(modular.query.service, 2),
                "id_size": modular.query.id_size, "empty_slot_id": plain(modular.query.empty_slot_id)},
        },
        **describe_newer(device),
    }


# --- content beyond the 2003 text (model.cip) ------------------------------------------------------------


def _data(value: Any) -> Any:
    """A model.cip record as plain JSON data: its compared fields, references by keyword, paths as text."""
    if dataclasses.is_dataclass(value) and not isinstance(value, (type, Reference, PathItem, Service)):
        return {f.name: _data(getattr(value, f.name)) for f in dataclasses.fields(value) if f.compare}
    if isinstance(value, list):
        return [_data(item) for item in value]
    if isinstance(value, dict):
        return {str(key): _data(item) for key, item in value.items()}
    return plain(value)


def describe_icon(icon: Icon | None) -> dict | None:
    if icon is None:
        return None
    return {"kind": icon.kind, "valid_ico": icon.valid_ico, "bytes": len(icon.data) if icon.data is not None else None,
            "images": _data(list(icon.images)), "problem": icon.problem}


def describe_devicenet(io: DeviceNetIo | None, device: Device) -> dict | None:
    if io is None:
        return None

    def data(item: IoData) -> dict:
        return {**_data(item), "path": decode_path(item.path, device),
                "connection_mask": hex_code(item.connection_mask, 4)}

    return {"default": hex_code(io.default, 4),
            "modes": [{**_data(mode), "combination_mask": hex_code(mode.combination_mask, 4)}
                      for mode in io.modes.values()],
            "inputs": [data(item) for item in io.inputs.values()],
            "outputs": [data(item) for item in io.outputs.values()],
            "enum_strings": _data(io.enum_strings)}


def _unmodelled(device: Device) -> tuple[list[dict], dict[str, list[str]]]:
    """The sections and entries the typed model does not hold (vendor-specific, unknown), as written."""
    typed = {s.name for s in device.other_sections if cip_tables.section_spec(s.name) is not None}
    sections = [{"name": s.name, "entries": len(s.entries)} for s in device.other_sections if s.name not in typed]
    entries: dict[str, list[str]] = {}
    for name, generic in [*device.extra_entries.items(), *((s.name, s.entries) for s in device.other_sections
                                                             if s.name in typed)]:
        keywords = [e.keyword for e in generic if not modelled(name, e.keyword)]
        if keywords:
            entries.setdefault(name, []).extend(keywords)
    return sections, entries


def describe_newer(device: Device) -> dict:
    """The parts of the document for the content beyond the 2003 text, and what is kept only as written."""
    network = {"tcpip_interface": device.tcpip_interface, "ethernet_link": device.ethernet_link, "dlr": device.dlr,
               "ingress_egress": device.ingress_egress}
    others, extra = _unmodelled(device)
    return {
        "additions": _data(device.additions),
        "extended_assemblies": [describe_assembly(a, device) for a in device.extended_assemblies.values()],
        "capacity": _data(device.capacity),
        "network": _data(network) if any(network.values()) else None,
        "object_classes": [{**_data(record), "class_name": tables.CIP_CLASSES.get(record.class_id or -1)}
                           for record in device.object_classes.values()],
        "devicenet": describe_devicenet(device.devicenet, device),
        "icon": describe_icon(device.icon_contents),
        "other_sections": others,
        "extra_entries": extra,
    }


def select(document: dict, sections: tuple[str, ...]) -> dict:
    """The parts of ``document`` that ``--section`` names (all of it for none)."""
    if not sections:
        return document
    keys = {key for section in sections for key in SECTIONS[section]}
    return {key: value for key, value in document.items() if key in keys}
