"""``edsconv show``: what an EDS says about a device, for people (terminal tables) and programs (JSON).

:func:`describe` turns a :class:`~edsconv.model.Device` into a document of
plain JSON types: bit fields spelled out in words (Tables C.15, C.23, C.24),
references resolved (an RPI named ``Param1`` shows that parameter's default
and range, a format ``Assem150`` that assembly's name and size), assemblies
laid out bit by bit and CIP paths decoded segment by segment. The text output
is rendered from the same document, so both always say the same thing.
rich is imported only when the text output is rendered.
"""

from __future__ import annotations

import dataclasses
import datetime
import json
import math
import sys
from pathlib import Path
from typing import Any

import click

from edsconv import spec_tables as tables
from edsconv.model import (
    Assembly,
    AssemblyMember,
    Connection,
    ConnectionEndpoint,
    Device,
    GenericEntry,
    Parameter,
    Reference,
)
from edsconv.model.values import PathItem, Revision, StringIMember

#: ``--section`` names -> the keys of the :func:`describe` document they show.
SECTIONS: dict[str, tuple[str, ...]] = {
    "identity": ("file", "identity", "classifications", "param_class"),
    "parameters": ("parameters",),
    "groups": ("groups",),
    "assemblies": ("assembly_revision", "assemblies"),
    "connections": ("connections",),
    "ports": ("ports",),
    "modular": ("modular",),
    "other": ("other_sections", "extra_entries"),
}

#: CIP object classes (CIP Vol 1 / Vol 2) most often named in EDS paths.
CIP_CLASSES: dict[int, str] = {
    0x01: "Identity", 0x02: "Message Router", 0x03: "DeviceNet", 0x04: "Assembly", 0x05: "Connection",
    0x06: "Connection Manager", 0x07: "Register", 0x08: "Discrete Input Point", 0x09: "Discrete Output Point",
    0x0A: "Analog Input Point", 0x0B: "Analog Output Point", 0x0E: "Presence Sensing", 0x0F: "Parameter",
    0x10: "Parameter Group", 0x12: "Group", 0x1D: "Discrete Input Group", 0x1E: "Discrete Output Group",
    0x1F: "Discrete Group", 0x20: "Analog Input Group", 0x21: "Analog Output Group", 0x22: "Analog Group",
    0x23: "Position Sensor", 0x24: "Position Controller Supervisor", 0x25: "Position Controller",
    0x26: "Block Sequencer", 0x27: "Command Block", 0x28: "Motor Data", 0x29: "Control Supervisor",
    0x2A: "AC/DC Drive", 0x2B: "Acknowledge Handler", 0x2C: "Overload", 0x2D: "Softstart", 0x2E: "Selection",
    0x30: "S-Device Supervisor", 0x31: "S-Analog Sensor", 0x32: "S-Analog Actor", 0x33: "S-Single Stage Controller",
    0x34: "S-Gas Calibration", 0x35: "Trip Point", 0x37: "File", 0x38: "S-Partial Pressure",
    0x39: "Safety Supervisor", 0x3A: "Safety Validator", 0x3B: "Safety Discrete Output Point",
    0x3C: "Safety Discrete Output Group", 0x3D: "Safety Discrete Input Point", 0x3E: "Safety Discrete Input Group",
    0x3F: "Safety Dual Channel Output", 0x40: "S-Sensor Calibration", 0x41: "Event Log", 0x42: "Motion Axis",
    0x43: "Time Sync", 0x44: "Modbus", 0x45: "Originator Connection List", 0x46: "Modbus Serial Link",
    0x47: "Device Level Ring", 0x48: "QoS", 0x4D: "Energy", 0x4E: "Base Energy", 0x4F: "Electrical Energy",
    0x50: "Non-Electrical Energy", 0x51: "Base Switch", 0x52: "SNMP", 0x53: "Power Management",
    0x54: "RSTP Bridge", 0x55: "RSTP Port", 0x56: "PRP/HSR Protocol", 0x57: "PRP/HSR Nodes Table",
    0x58: "Safety Feedback", 0x59: "Safety Dual Channel Feedback", 0x5A: "Safety Stop Functions",
    0x5B: "Safety Limit Functions", 0x5C: "Power Curtailment", 0x5D: "CIP Security", 0x5E: "EtherNet/IP Security",
    0x5F: "Certificate Management", 0x67: "PCCC", 0xF0: "ControlNet", 0xF1: "ControlNet Keeper",
    0xF2: "ControlNet Scheduling", 0xF3: "Connection Configuration", 0xF4: "Port", 0xF5: "TCP/IP Interface",
    0xF6: "Ethernet Link", 0xF7: "CompoNet Link", 0xF8: "CompoNet Repeater",
}

_LOGICAL_TYPES = ("class", "instance", "member", "connection point", "attribute", "special", "service ID", "reserved")
_NETWORK_SEGMENTS = {0x41: "schedule", 0x42: "fixed tag", 0x43: "production inhibit time (ms)",
                     0x44: "fixed tag", 0x45: "production inhibit time (ms)", 0x46: "safety",
                     0x47: "production inhibit time (µs)"}
_PATH_KEYWORD_MEANINGS = {
    "SLOT": "the slot number of the module",
    "SLOT_MINUS_ONE": "the slot number of the module minus one",
    "SYMBOL_ANSI": "an ANSI extended symbol segment (a tag name) supplied by the configuration tool",
}


# --- plain JSON values --------------------------------------------------------------------------


def plain(value: Any) -> Any:
    """A model value as a JSON value: dates ISO, paths as text, references by keyword."""
    if value is None or isinstance(value, (bool, int, str)):
        return value
    if isinstance(value, float):
        return value if math.isfinite(value) else str(value)
    if isinstance(value, (datetime.date, datetime.time)):
        return value.isoformat()
    if isinstance(value, (Revision, Reference, PathItem)):
        return str(value)
    if isinstance(value, StringIMember):
        return {"language": value.language, "type": value.type_code, "charset": value.charset, "text": value.text}
    if isinstance(value, (bytes, bytearray)):
        return value.hex(" ").upper()
    if isinstance(value, tuple) and value and all(isinstance(item, PathItem) for item in value):
        return path_text(value)
    if isinstance(value, (list, tuple)):
        return [plain(item) for item in value]
    if isinstance(value, dict):
        return {str(key): plain(item) for key, item in value.items()}
    return str(value)


def path_text(path: tuple[PathItem, ...] | str | None) -> str | None:
    if path is None or isinstance(path, str):
        return path
    return " ".join(str(item) for item in path)


def hex_code(value: Any, digits: int) -> str | None:
    return f"0x{value:0{digits}X}" if isinstance(value, int) else plain(value)


# --- paths --------------------------------------------------------------------------------------


def _item_text(item: PathItem, device: Device | None) -> str:
    if item.byte is not None:
        return f"0x{item.byte:02X}"
    if item.keyword:
        return item.keyword
    text = str(item)
    target = device.parameters.get(item.reference) if device else None
    if target is not None:
        details = ", ".join(str(part) for part in (
            target.name and repr(target.name), target.default is not None and f"default {plain(target.default)}")
            if part)
        text += f" ({details})" if details else ""
    return text


def _number(items: list[PathItem], device: Device | None) -> tuple[Any, str]:
    """The little-endian value of ``items`` (all bytes) or, with substitutions, their spelling."""
    if len(items) == 1:
        item = items[0]
        value = item.byte if item.byte is not None else str(item)
        return value, _item_text(item, device)
    if all(item.byte is not None for item in items):
        value = int.from_bytes(bytes(item.byte for item in items), "little")
        return value, f"0x{value:0{2 * len(items)}X}"
    spelled = " ".join(str(item) for item in items)
    return spelled, spelled


def decode_path(path: tuple[PathItem, ...] | str | None, device: Device | None = None) -> dict | None:
    """A CIP path segment by segment (CIP Vol 1 C-1): port, logical, network, symbolic and data
    segments, with ``[ParamN]`` substitutions and SLOT keywords where bytes stand."""
    if path is None:
        return None
    if isinstance(path, str):
        return {"text": path, "segments": [], "summary": path}
    items = list(path)
    segments: list[dict] = []
    position = 0

    def take(count: int) -> list[PathItem] | None:
        nonlocal position
        if position + count > len(items):
            return None
        taken = items[position:position + count]
        position += count
        return taken

    def add(kind: str, start: int, text: str, value: Any = None, **extra: Any) -> None:
        segment = {"bytes": " ".join(str(item) for item in items[start:position]), "type": kind, "text": text}
        if value is not None:
            segment["value"] = value
        segment.update(extra)
        segments.append(segment)

    while position < len(items):
        start = position
        head = items[position]
        position += 1
        if head.byte is None:
            if head.keyword:
                add("keyword", start, f"{head.keyword}: {_PATH_KEYWORD_MEANINGS.get(head.keyword, 'keyword')}",
                    head.keyword)
            else:
                add("substitution", start, f"value of {_item_text(head, device)}", str(head), parameter=head.reference)
            continue
        byte = head.byte
        segment_type = byte >> 5
        problem = None
        if segment_type == 0:  # port segment
            port = byte & 0x0F
            if port == 0x0F:
                extended = take(2)
                if extended is None:
                    problem = "port segment: the extended port number is missing"
                else:
                    port, _ = _number(extended, device)
            if problem is None and byte & 0x10:
                size = take(1)
                size_value = size[0].byte if size else None
                address = take(size_value) if size_value is not None else None
                if address is None:
                    problem = "port segment: the link address is missing"
                else:
                    if (position - start) % 2:
                        take(1)
                    link = " ".join(str(item) for item in address)
                    if all(item.byte is not None for item in address):
                        link = bytes(item.byte for item in address).decode("latin-1")
                    add("port", start, f"port {port}, link address {link}", port, link_address=link)
            elif problem is None:
                address = take(1)
                if address is None:
                    problem = "port segment: the link address is missing"
                else:
                    link_value, link_text = _number(address, device)
                    add("port", start, f"port {port}, link address {link_text}", port, link_address=link_value)
        elif segment_type == 1:  # logical segment
            logical = _LOGICAL_TYPES[(byte >> 2) & 7]
            width = byte & 3
            if logical == "special" and width == 0:
                key = take(9)
                if key is None or key[0].byte != 4 or any(item.byte is None for item in key):
                    problem = "electronic key segment: expected key format 4 and 8 bytes"
                else:
                    data = bytes(item.byte for item in key[1:])
                    vendor, device_type, product = (int.from_bytes(data[i:i + 2], "little") for i in (0, 2, 4))
                    major, minor = data[6] & 0x7F, data[7]
                    compatibility = " (compatible)" if data[6] & 0x80 else ""
                    add("electronic key", start, f"electronic key: vendor {vendor}, device type {device_type}, "
                        f"product code {product}, revision {major}.{minor}{compatibility}")
            elif width == 3:
                problem = f"logical segment 0x{byte:02X}: reserved format"
            else:
                size = (1, 2, 4)[width]
                # padded EPATH puts a 0x00 pad byte before a 16/32-bit value; EDS files often
                # write the packed form without it ("21 04 00" is class 0x0004)
                padded = width and position + size < len(items) and items[position].byte == 0
                if padded:
                    take(1)
                data = take(size)
                if data is None:
                    problem = f"{logical} segment: the value is missing"
                else:
                    value, text = _number(data, device)
                    if logical == "class" and isinstance(value, int) and value in CIP_CLASSES:
                        text += f" ({CIP_CLASSES[value]})"
                    references = [item.reference for item in data if item.reference]
                    add(logical, start, f"{logical} {text}", value,
                        **({"parameter": references[0]} if references else {}))
        elif segment_type == 2:  # network segment
            if byte in (0x46, 0x50) or byte & 0xF0 == 0x50:
                length = take(1)
                words = length[0].byte if length else None
                if words is None or take(2 * words) is None:
                    problem = f"network segment 0x{byte:02X}: its data is missing"
                else:
                    add("network", start, f"network segment 0x{byte:02X} ({words} words)")
            else:
                data = take(1)
                if data is None:
                    problem = f"network segment 0x{byte:02X}: its data is missing"
                else:
                    value, text = _number(data, device)
                    add("network", start, f"{_NETWORK_SEGMENTS.get(byte, f'network segment 0x{byte:02X}')} {text}",
                        value)
        elif segment_type == 3:  # symbolic segment
            size = byte & 0x1F
            symbol = take(size) if size else None
            if symbol is None or any(item.byte is None for item in symbol):
                problem = "symbolic segment: the symbol is missing"
            else:
                name = bytes(item.byte for item in symbol).decode("latin-1")
                add("symbolic", start, f"symbol {name!r}", name)
        elif byte in (0x80, 0x91):  # data segments
            length = take(1)
            count = length[0].byte if length else None
            data = take(count * (2 if byte == 0x80 else 1)) if count is not None else None
            if data is None:
                problem = "data segment: its data is missing"
            elif byte == 0x80:
                add("data", start, f"simple data, {count} words")
            else:
                if count % 2:
                    take(1)
                name = " ".join(str(item) for item in data)
                if all(item.byte is not None for item in data):
                    name = bytes(item.byte for item in data).decode("latin-1")
                add("symbolic", start, f"ANSI extended symbol {name!r}", name)
        elif byte in tables.DATA_TYPES_BY_CODE:
            add("data type", start, f"data type {tables.DATA_TYPES_BY_CODE[byte].name}", byte)
        else:
            problem = f"0x{byte:02X} is not a segment type edsconv decodes"
        if problem:
            position = len(items)
            add("undecoded", start, problem)
    return {"text": path_text(path), "segments": segments, "summary": ", ".join(s["text"] for s in segments)}


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
        doc["size_adder"] = dict(zip(("minimum", "maximum", "default"), plain(parameter.size_adder)))
    return doc


def _parameter_summary(parameter: Parameter) -> dict:
    return {"kind": "parameter", "keyword": parameter.keyword, "name": parameter.name,
            "data_type": parameter.data_type.name if parameter.data_type else None,
            "default": plain(parameter.default), "minimum": plain(parameter.minimum),
            "maximum": plain(parameter.maximum), "units": parameter.units}


def _assembly_summary(assembly: Assembly, device: Device) -> dict:
    return {"kind": "assembly", "keyword": assembly.keyword, "name": assembly.name,
            "size": plain(assembly.size), "total_bits": _layout(assembly, device)[1]}


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


def _member_bits(member: AssemblyMember, device: Device, seen: frozenset[str]) -> int | None:
    if member.size is not None:
        return member.size
    reference = member.reference
    if not isinstance(reference, Reference):
        return None
    target = reference.target if reference.target is not None else device.resolve(reference.keyword)
    if isinstance(target, Parameter):
        if isinstance(target.data_size, int):
            return 8 * target.data_size
        return 8 * target.data_type.size if target.data_type and target.data_type.size else None
    if isinstance(target, Assembly) and target.keyword not in seen:
        if isinstance(target.size, int):
            return 8 * target.size
        return _layout(target, device, seen)[1]
    return None


def _layout(assembly: Assembly, device: Device, seen: frozenset[str] = frozenset()) -> tuple[list[dict], int | None]:
    """The members of an assembly with their bit offsets, and the total bits (None when a size is unknown)."""
    seen = seen | {assembly.keyword}
    members: list[dict] = []
    offset: int | None = 0
    for member in assembly.members:
        bits = _member_bits(member, device, seen)
        reference = member.reference
        if reference is None:
            what: dict[str, Any] = {"kind": "pad"}
        elif isinstance(reference, Reference):
            what = resolve(reference, device) if len(seen) < 16 else {"kind": "reference", "keyword": str(reference)}
        elif isinstance(reference, int):
            what = {"kind": "constant", "value": reference}
        elif isinstance(reference, str):
            what = {"kind": "keyword", "keyword": reference}
        else:
            what = {"kind": "path", "path": decode_path(reference, device)}
        members.append({"offset": offset, "bits": bits, "declared_bits": member.size, "member": what})
        offset = offset + bits if offset is not None and bits is not None else None
    if assembly.module_member_list or not assembly.members:
        return members, None  # the members come from the module, or are not listed
    return members, offset


def describe_assembly(assembly: Assembly, device: Device) -> dict:
    members, total = _layout(assembly, device)
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
        def get(name: str) -> int:
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
        "other_sections": [{"name": s.name, "entries": len(s.entries)} for s in device.other_sections],
        "extra_entries": {section: [e.keyword for e in entries] for section, entries in device.extra_entries.items()},
    }


def select(document: dict, sections: tuple[str, ...]) -> dict:
    """The parts of ``document`` that ``--section`` names (all of it for none)."""
    if not sections:
        return document
    keys = {key for section in sections for key in SECTIONS[section]}
    return {key: value for key, value in document.items() if key in keys}


# --- text ---------------------------------------------------------------------------------------


def _text(value: Any) -> str:
    if value is None:
        return ""
    if isinstance(value, float):
        return f"{value:g}"
    return str(value)


def _range(low: Any, high: Any) -> str:
    if low is None and high is None:
        return ""
    return f"{_text(low)} .. {_text(high)}"


def _joined(*parts: Any) -> str:
    return " ".join(_text(part) for part in parts if part not in (None, ""))


def _revision(major: Any, minor: Any) -> str:
    return "" if major is None and minor is None else f"{_text(major) or '?'}.{_text(minor) or '?'}"


def _reference_text(ref: dict | None) -> str:
    """One line for a resolved reference (rpi/size/format, group member, assembly member)."""
    if ref is None:
        return ""
    kind = ref.get("kind")
    keyword = ref.get("keyword", "")
    bit = f" bit {ref['bit']}" if ref.get("bit") is not None else ""
    if kind == "parameter":
        name = f" {ref['name']!r}" if ref.get("name") else ""
        units = f" {ref['units']}" if ref.get("units") else ""
        return (f"{keyword}{bit}{name}: default {_text(ref['default'])}{units}, range "
                f"{_range(ref['minimum'], ref['maximum'])}")
    if kind == "assembly":
        name = f" {ref['name']!r}" if ref.get("name") else ""
        size = f", {ref['size']} bytes" if ref.get("size") is not None else ""
        bits = f", members {ref['total_bits']} bits" if ref.get("total_bits") is not None else ""
        return f"{keyword}{name}{size}{bits}"
    if kind == "undefined":
        return f"{keyword} (undefined)"
    return f"{keyword}{bit}"


def _value_text(value: dict | None, unit: str = "") -> str:
    if value is None:
        return ""
    if "reference" in value:
        return _reference_text(value["reference"])
    return f"{_text(value['value'])}{unit}"


def _format_text(value: dict | None) -> str:
    if value is None:
        return ""
    return _text(value["written"]) if value.get("kind") == "value" else _reference_text(value)


def _member_text(member: dict) -> str:
    kind = member["kind"]
    if kind == "pad":
        return "(pad)"
    if kind == "constant":
        return f"constant {member['value']} (0x{member['value']:X})"
    if kind == "keyword":
        return member["keyword"]
    if kind == "path":
        return f"path {member['path']['text']} ({member['path']['summary']})"
    if kind == "parameter":
        name = f" {member['name']!r}" if member.get("name") else ""
        bit = f" bit {member['bit']}" if member.get("bit") is not None else ""
        return f"{member['keyword']}{bit}{name} ({member['data_type'] or '?'})"
    return _reference_text(member)


def _path_text(path: dict | None) -> str:
    if not path:
        return ""
    return f"{path['text']}\n  = {path['summary']}" if path["summary"] and path["summary"] != path["text"] else \
        path["text"]


def _title(keyword: str, name: Any) -> str:
    return f"{keyword}  {name!r}" if name else keyword


def render(document: dict, console: Any, sections: tuple[str, ...] = ()) -> None:
    """Print the :func:`describe` document as rich tables on ``console``."""
    from rich import box
    from rich.table import Table
    from rich.text import Text

    wanted = sections or tuple(SECTIONS)

    first = True

    def heading(text: str) -> None:
        nonlocal first
        if not first:
            console.print()
        first = False
        console.print(Text(text, style="bold underline"))

    def table(*columns: str, **options: Any) -> Table:
        t = Table(box=box.SIMPLE_HEAD, show_edge=False, pad_edge=False, header_style="bold", **options)
        for column in columns:
            t.add_column(column, overflow="fold")
        return t

    def pairs(rows: list[tuple[str, Any]]) -> Table:
        """Label / value rows; rows without a value are left out."""
        t = table(show_header=False)
        t.add_column(style="bold", no_wrap=True)
        t.add_column(overflow="fold")
        for label, value in rows:
            if value not in (None, "", []):
                t.add_row(label, _text(value))
        if not t.rows:
            t.add_row("(nothing given)", "")
        return t

    if "identity" in wanted:
        identity, file = document["identity"], document["file"]
        heading("Identity")
        console.print(pairs([
            ("Product", identity["product_name"]),
            ("Vendor", _joined(identity["vendor_code"], identity["vendor_name"])),
            ("Product type", _joined(identity["product_type"], identity["product_type_string"])),
            ("Product code", identity["product_code"]),
            ("Revision", _revision(identity["major_revision"], identity["minor_revision"])),
            ("Catalog", identity["catalog"]),
            ("Icon", identity["icon"]),
            ("Networks", ", ".join(
                " ".join([c["classification"] or "?", *c["subclassifications"]]) for c in document["classifications"])),
            ("Description", file["description"]),
            ("File revision", file["revision"]),
            ("Created", " ".join(filter(None, (file["create_date"], file["create_time"])))),
            ("Modified", " ".join(filter(None, (file["mod_date"], file["mod_time"])))),
            ("Home URL", file["home_url"]),
        ]))
        if document["param_class"]:
            pc = document["param_class"]
            heading("Parameter class")
            console.print(pairs([("Max instances", pc["max_instances"]),
                                                    ("Descriptor", f"{pc['descriptor']} {', '.join(pc['flags'])}"),
                                                    ("Config assembly", pc["cfg_assembly"])]))

    if "parameters" in wanted and document["parameters"]:
        heading("Parameters")
        t = table("Keyword", "Name", "Type", "Range", "Default", "Units", "Details")
        for column in (0, 2, 3, 4):
            t.columns[column].no_wrap = True
        for p in document["parameters"]:
            data_type = p["data_type"]
            type_text = data_type["name"] or f"? ({_text(data_type['written'])})"
            if data_type["code"] is not None:
                type_text += f" 0x{data_type['code']:02X}"
            if p["size"] is not None:
                type_text += f", {p['size']} B"
            details = []
            engineering = p.get("engineering")
            if engineering:
                details.append(f"scaled: {_range(engineering['minimum'], engineering['maximum'])}, "
                               f"default {_text(engineering['default'])}")
            details += [f"{e['value']} = {e['text']}" for e in p["enum"]]
            if p["flags"]:
                details.append("flags: " + ", ".join(p["flags"]))
            if p.get("link_path"):
                details.append(f"link path {p['link_path']['text']} ({p['link_path']['summary']})")
            if p["help"]:
                details.append(p["help"])
            t.add_row(p["keyword"], _text(p["name"]), type_text, _range(p["minimum"], p["maximum"]),
                      _text(p["default"]), _text(p["units"]), "\n".join(details))
        console.print(t)

    if "groups" in wanted and document["groups"]:
        heading("Groups")
        t = table("Group", "Name", "Members")
        for g in document["groups"]:
            t.add_row(str(g["number"]), _text(g["name"]),
                      "\n".join(f"{m['keyword']} {m.get('name') or ''}".strip() for m in g["members"]))
        console.print(t)

    if "assemblies" in wanted:
        for a in document["assemblies"]:
            size = f", {a['size']} bytes" if a["size"] is not None else ""
            path = f", path {a['path']['text']} ({a['path']['summary']})" if a["path"] else ""
            heading(f"{_title(a['keyword'], a['name'])}{size}{path}")
            t = table("Bits", "Size", "Member")
            for m in a["members"]:
                offset, bits = m["offset"], m["bits"]
                where = "?" if offset is None or bits is None else f"{offset}" if bits <= 1 else \
                    f"{offset}-{offset + bits - 1}"
                t.add_row(where, "?" if bits is None else str(bits), _member_text(m["member"]))
            if a["module_member_list"]:
                t.add_row("", "", "the members of the module (ModuleMemberList)")
            elif not a["members"]:
                t.add_row("", "", "(no members listed)")
            if a["members"]:
                t.add_row("", _text(a["total_bits"]) if a["total_bits"] is not None else "?", "total bits")
            console.print(t)

    if "connections" in wanted:
        for c in document["connections"]:
            rows: list[tuple[str, Any]] = []
            tt = c["trigger_transport"]
            if tt:
                rows.append(("Trigger/transport", tt["value"]))
            if tt and "classes" in tt:
                rows += [("  class", ", ".join(tt["class_names"]) or "none"),
                         ("  trigger", ", ".join(tt["triggers"]) or "none"),
                         ("  transport type", ", ".join(tt["transport"]) or "none"),
                         ("  role", tt["role"]),
                         ("  reserved bits set", tt["reserved_bits"])]
            parameters = c["parameters"]
            if parameters:
                rows += [("Connection parameters", parameters["value"]),
                         ("  reserved bits set", parameters.get("reserved_bits"))]
            for direction in ("O=>T", "T=>O"):
                endpoint = c[direction]
                rows.append((direction, "(not given)" if endpoint is None else " "))
                if endpoint:
                    rows += [("  RPI", _value_text(endpoint["rpi"], " µs")),
                             ("  size", _value_text(endpoint["size"], " bytes")),
                             ("  format", _format_text(endpoint["format"]))]
                if parameters and direction in parameters:
                    d = parameters[direction]
                    sizes = [s for s, on in (("fixed", d["fixed_size"]), ("variable", d["variable_size"])) if on]
                    rows += [("  size type", " and ".join(sizes) or "none"),
                             ("  real-time format", d["real_time_format"]),
                             ("  connection type", ", ".join(d["connection_types"]) or "none"),
                             ("  priority", ", ".join(d["priorities"]) or "none")]
            for part in ("config1", "config2"):
                endpoint = c[part]
                if endpoint:
                    rows += [(f"Config part {part[-1]}", " "),
                             ("  size", _value_text(endpoint["size"], " bytes")),
                             ("  format", _format_text(endpoint["format"]))]
            rows += [("Path", _path_text(c["path"])), ("Help", c["help"])]
            heading(_title(c["keyword"], c["name"]))
            console.print(pairs(rows))

    if "ports" in wanted and document["ports"]:
        heading("Ports")
        t = table("Port", "Type", "Name", "Port number", "Object path")
        for p in document["ports"]:
            t.add_row(str(p["number"]), _text(p["type"]), _text(p["name"]), _text(p["port_number"]),
                      _path_text(p["object_path"]))
        console.print(t)

    if "modular" in wanted and document["modular"]:
        m = document["modular"]
        heading(f"Modular ({m['role'] or 'unknown role'})")
        console.print(pairs([
            ("Slots in rack", m["define_slots_in_rack"]),
            ("Slot display rule", _reference_text(m["slot_display_rule"])),
            ("Width (slots)", m["width"]),
            ("External ID", m["external_id"]),
            ("Generic ID", m["generic_id"]),
            ("ExternID exact match", m["extern_id_exact_match"]),
            ("Query", m["query"] and f"path {_path_text(m['query']['path'])}, service {m['query']['service']}, "
                                     f"ID size {_text(m['query']['id_size'])}, empty slot ID "
                                     f"{_text(m['query']['empty_slot_id'])}"),
        ]))
        if m["racks"]:
            heading("Racks")
            t = table("Rack", "Vendor", "Type", "Product", "Revision", "Legal slots")
            for r in m["racks"]:
                t.add_row(str(r["number"]), _text(r["vendor_code"]), _text(r["product_type"]),
                          _text(r["product_code"]), _revision(r["major_revision"], r["minor_revision"]),
                          ", ".join(map(str, r["legal_slots"])))
            console.print(t)

    if "other" in wanted and (document["other_sections"] or document["extra_entries"]):
        heading("Other sections and entries")
        t = table("Section", "Entries")
        for s in document["other_sections"]:
            t.add_row(f"[{s['name']}]", str(s["entries"]))
        for section, keywords in document["extra_entries"].items():
            t.add_row(f"[{section}] (not in the 2003 text)", ", ".join(keywords))
        console.print(t)


# --- command ------------------------------------------------------------------------------------


def _section_names(ctx: click.Context, param: click.Parameter, value: tuple[str, ...]) -> tuple[str, ...]:
    names = tuple(name.strip().lower() for item in value for name in item.split(",") if name.strip())
    unknown = [name for name in names if name not in SECTIONS]
    if unknown:
        raise click.BadParameter(f"{', '.join(unknown)}: choose from {', '.join(SECTIONS)}")
    return tuple(dict.fromkeys(names))


@click.command("show")
@click.argument("file", type=click.Path(dir_okay=False, path_type=Path))
@click.option("--section", "sections", multiple=True, callback=_section_names, metavar="NAME",
              help=f"Show only these parts (repeat or comma-separate): {', '.join(SECTIONS)}.")
@click.option("--format", "output_format", type=click.Choice(["text", "json"]), default="text", show_default=True,
              help="text: tables for people; json: the same content for programs.")
def show_command(file: Path, sections: tuple[str, ...], output_format: str) -> int:
    """Show what an EDS says about a device: identity, parameters, assemblies, connections, ports, modules."""
    # cli.py imports this module to register the command, so its names are imported at call time.
    import edsconv
    from edsconv.cli import EXIT_CLEAN, EXIT_USAGE
    from edsconv.diagnostics import Severity

    try:
        eds = edsconv.load(file)
    except OSError as error:
        click.echo(f"{file}: cannot read: {error.strerror or error}", err=True)
        return EXIT_USAGE
    device, diagnostics = edsconv.analyse(eds)
    document = select(describe(device), sections)
    if output_format == "json":
        click.echo(json.dumps(document, indent=2, ensure_ascii=False))
    else:
        from rich.console import Console

        if sys.stdout.isatty():
            render(document, Console(markup=False, highlight=False, emoji=False), sections)
        else:  # piped: plain text, 120 columns, no trailing blanks
            console = Console(markup=False, highlight=False, emoji=False, no_color=True, width=120,
                              color_system=None)
            with console.capture() as capture:
                render(document, console, sections)
            click.echo("\n".join(line.rstrip() for line in capture.get().splitlines()))
    errors = sum(d.severity is Severity.ERROR for d in diagnostics)
    warnings = sum(d.severity is Severity.WARNING for d in diagnostics)
    if errors or warnings:
        click.echo(f"{file}: {errors} errors, {warnings} warnings (see 'edsconv lint {file}')", err=True)
    return EXIT_CLEAN
