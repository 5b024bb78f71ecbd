"""What ``edsconv verify`` compares of the EDS's I/O: the size of each assembly instance a connection
names, the values at the parameters' link paths, and (``--connect``) whether the device accepts each
ConnectionN: a Forward Open built from the entry alone, closed again at once.
"""

from __future__ import annotations

import struct
from collections.abc import Iterator
from dataclasses import dataclass

from edsconv import spec_tables as tables
from edsconv.diagnostics import Diagnostic
from edsconv.model import Device
from edsconv.model.device import Assembly, Connection, ConnectionEndpoint, Parameter, is_integer
from edsconv.model.epath import decode_path
from edsconv.verify import rules
from edsconv.verify.checks import ASSEMBLY_CLASS, Probe, number
from edsconv.verify.client import ATTRIBUTE_NOT_SUPPORTED
from edsconv.verify.forward import SEGMENT_NAMES, forward_open

#: the fields of a ConnectionN (C.4.1.4.9): O=>T RPI, size, format; T=>O RPI, size, format; the path
O_TO_T, T_TO_O, PATH_FIELD = (2, 3, 4), (5, 6, 7), 14
#: the fields of a ParamN (C.4.1.4.6): link path, minimum, maximum
LINK_PATH_FIELD, MINIMUM_FIELD, MAXIMUM_FIELD = 2, 9, 10
#: Assembly object attributes (CIP Vol 1 5-5): 3 the data, 4 its size in bytes
DATA, SIZE = 3, 4


@dataclass(frozen=True, slots=True)
class Expected:
    """The size the EDS gives an assembly instance, and the entry field that gives it."""

    size: int
    section: str
    keyword: str
    field: int


def segments(path: object) -> list[tuple[str, int]] | None:
    """(type, value) of each segment of a path of plain bytes; None when a segment is not logical."""
    if not isinstance(path, tuple) or any(item.byte is None for item in path):
        return None
    decoded = decode_path(path) or {"segments": []}
    found = [(s["type"], s.get("value")) for s in decoded["segments"]]
    if not found or any(kind not in SEGMENT_NAMES or not isinstance(value, int) for kind, value in found):
        return None
    return found


def assembly_instance(assembly: Assembly) -> int | None:
    """The Assembly instance an AssemN's path names (class 4, then an instance or connection point)."""
    found = segments(assembly.path) or []
    if not found or found[0] != ("class", ASSEMBLY_CLASS) or len(found) < 2:
        return None
    return found[1][1]


# --- assembly sizes --------------------------------------------------------------------------------


def expected_sizes(device: Device) -> dict[int, Expected]:
    """Each assembly instance the connections name, with the size the EDS gives it: its AssemN's size
    (or members), else the connection's size for that direction."""
    by_instance = {assembly_instance(a): a for a in device.assemblies.values()}
    expected: dict[int, Expected] = {}
    for connection in device.connections.values():
        points = [value for kind, value in segments(connection.path) or () if kind == "connection point"]
        for (endpoint, fields), point in zip(_directions(connection)[-len(points[-2:]):], points[-2:], strict=True) \
                if points else ():
            assembly = by_instance.get(point)
            bits = device.assembly_bits(assembly) if assembly is not None else None
            if assembly is not None and bits is not None:
                expected.setdefault(point, Expected(bits // 8, "Assembly", assembly.keyword, 2))
            elif is_integer(endpoint.size):
                expected.setdefault(point, Expected(endpoint.size, "Connection Manager", connection.keyword,
                                                    fields[1]))
    return expected


def _directions(connection: Connection) -> list[tuple[ConnectionEndpoint, tuple[int, int, int]]]:
    return [(connection.o_to_t, O_TO_T), (connection.t_to_o, T_TO_O)]


def assembly_sizes(probe: Probe) -> Iterator[Diagnostic]:
    for instance, expected in sorted(expected_sizes(probe.device).items()):
        size = probe.read(ASSEMBLY_CLASS, instance, SIZE)
        if size.absent:
            if expected.size:  # a heartbeat point (size 0) need not be an instance the device lets one read
                yield probe.at(rules.ASSEMBLY_ABSENT, f"the device has no assembly instance {instance} "
                               f"({expected.keyword}): {size.words()}", expected.section, expected.keyword)
            continue
        found = number(size) if size.ok else None
        if found is None:  # attribute 4 is optional: the data's length is the size
            data = probe.read(ASSEMBLY_CLASS, instance, DATA)
            found = len(data.data) if data.ok else None
        if found is None:
            yield probe.at(rules.NOT_CHECKED, f"the size of assembly instance {instance} could not be read: "
                           f"{size.words()}", expected.section, expected.keyword, expected.field)
        elif found != expected.size:
            yield probe.at(rules.ASSEMBLY_SIZE_MISMATCH, f"{expected.keyword} is {expected.size} bytes but the "
                           f"device's assembly instance {instance} holds {found}", expected.section,
                           expected.keyword, expected.field)


# --- parameter values ------------------------------------------------------------------------------


def parameter_values(probe: Probe) -> Iterator[Diagnostic]:
    for parameter in probe.device.parameters.values():
        if parameter.link_path is None or not parameter.link_path:
            continue
        found = segments(parameter.link_path)
        if found is None or [kind for kind, _ in found] != ["class", "instance", "attribute"]:
            yield probe.at(rules.NOT_CHECKED, f"{parameter.keyword}: the link path is not a class, instance and "
                           "attribute; its value is not read", "Params", parameter.keyword, LINK_PATH_FIELD)
            continue
        (_, class_id), (_, instance), (_, attribute) = found
        reply = probe.read(class_id, instance, attribute)
        where = f"class 0x{class_id:02X} instance {instance} attribute {attribute}"
        if reply.absent or reply.status == ATTRIBUTE_NOT_SUPPORTED:
            yield probe.at(rules.PARAMETER_PATH_ABSENT, f"{parameter.keyword}: the device has nothing at {where}: "
                           f"{reply.words()}", "Params", parameter.keyword, LINK_PATH_FIELD)
        elif not reply.ok:
            yield probe.at(rules.NOT_CHECKED, f"{parameter.keyword}: {where} could not be read: {reply.words()}",
                           "Params", parameter.keyword, LINK_PATH_FIELD)
        else:
            yield from _check_value(probe, parameter, reply.data, where)


def _check_value(probe: Probe, parameter: Parameter, data: bytes, where: str) -> Iterator[Diagnostic]:
    data_type = parameter.data_type
    if data_type is None or data_type.size is None:
        return
    if len(data) != data_type.size:
        yield probe.at(rules.PARAMETER_WRONG_SIZE, f"{parameter.keyword} is {data_type.name} ({data_type.size} "
                       f"bytes) but the device answers {len(data)} bytes at {where}", "Params", parameter.keyword, 4)
        return
    value = decode(data, data_type)
    if value is None:
        return
    low = parameter.minimum if isinstance(parameter.minimum, int | float) else data_type.minimum
    high = parameter.maximum if isinstance(parameter.maximum, int | float) else data_type.maximum
    if low is not None and value < low:
        yield probe.at(rules.PARAMETER_OUT_OF_RANGE, f"{parameter.keyword}: the device holds {value}, below the "
                       f"minimum {low} ({where})", "Params", parameter.keyword, MINIMUM_FIELD)
    elif high is not None and value > high:
        yield probe.at(rules.PARAMETER_OUT_OF_RANGE, f"{parameter.keyword}: the device holds {value}, above the "
                       f"maximum {high} ({where})", "Params", parameter.keyword, MAXIMUM_FIELD)


def decode(data: bytes, data_type: tables.DataType) -> int | float | None:
    """A value as CIP encodes it (little-endian); None for a kind that has no order (strings, paths)."""
    if data_type.kind in ("unsigned", "bits", "bool"):
        return int.from_bytes(data, "little")
    if data_type.kind == "signed":
        return int.from_bytes(data, "little", signed=True)
    if data_type.kind == "real":
        return struct.unpack("<f" if len(data) == 4 else "<d", data)[0]
    return None


# --- connections (--connect) -----------------------------------------------------------------------


def connections(probe: Probe) -> Iterator[Diagnostic]:
    """A Forward Open per ConnectionN, closed at once; a refusal with its status in words."""
    for serial, connection in enumerate(probe.device.connections.values(), start=1):
        request, missing = forward_open(probe.device, connection, serial, segments(connection.path))
        if request is None:
            yield probe.at(rules.NOT_CHECKED, f"{connection.keyword}: not opened: {missing}", "Connection Manager",
                           connection.keyword)
            continue
        reply = probe.session.forward_open(request)
        if not reply.ok:
            yield probe.at(rules.CONNECTION_REFUSED, f"{connection.keyword} ({connection.name}): the device refuses "
                           f"the Forward Open: {reply.words()}", "Connection Manager", connection.keyword)
