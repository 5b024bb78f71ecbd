"""Checks of how an EDS addresses the device: paths, instance numbers, ports, racks and slots.

Paths are walked segment by segment (CIP Vol 1 C-1) only as far as needed to say what the text
asks of them: the padded notation of connection paths (C.4.1.4.9.13), logical or data segments in
assembly paths (C.4.1.4.8), the Parameter and Assembly instance a ParamN or AssemN addresses
(C.4.1.4.6, C.4.1.4.8). A walk stops where it cannot go on (a keyword or ``[ParamN]`` standing for
a segment byte, a segment type it does not know); nothing beyond that point is reported.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass

from edsconv import spec_tables as tables
from edsconv.checks import Context, assembly_units, check, parameter_units
from edsconv.checks.addressing_rules import (
    ASSEM_INSTANCE_MISMATCH,
    DUPLICATE_RACK,
    LINK_SIZE_WITHOUT_PATH,
    NON_LOGICAL_SEGMENT,
    PACKED_CONNECTION_PATH,
    PACKED_MEMBER_PATH,
    PARAM_INSTANCE_MISMATCH,
    PORT_1_NOT_BACKPLANE,
    PORT_TYPE_VENDOR_ID,
    QUERY_NOT_SLOT_0,
)
from edsconv.diagnostics import Diagnostic
from edsconv.eds.syntax import Entry
from edsconv.model import Assembly, Parameter
from edsconv.model.values import PathItem

#: Segment types (bits 5-7 of the segment byte, CIP Vol 1 C-1.4).
PORT, LOGICAL, NETWORK, SYMBOLIC, DATA = range(5)
#: Logical segment types (bits 2-4) and the special type's electronic key format (C-1.4.2).
CLASS, INSTANCE, SPECIAL = 0, 1, 5
_ELECTRONIC_KEY_BYTES = 10
#: Data segments: simple data (a word count) and the ANSI extended symbol (a byte count).
_SIMPLE_DATA, _ANSI_SYMBOL = 0x80, 0x91
#: CIP class codes of the objects whose instance an entry's N names.
_PARAMETER_CLASS, _ASSEMBLY_CLASS = 0x0F, 0x04
#: 0-based fields: ParamN Link Path Size and Link Path, AssemN Path, ConnectionN Path.
_LINK_SIZE, _LINK_PATH, _ASSEM_PATH, _CONNECTION_PATH = 1, 2, 1, 14


@dataclass(frozen=True, slots=True)
class Segment:
    """One segment of a path: its type, where it starts, and for a logical segment its
    logical type, its value (when written as bytes) and whether it lacks its pad byte."""

    kind: int
    start: int
    logical: int | None = None
    value: int | None = None
    packed: bool = False


def segments(path: tuple[PathItem, ...]) -> Iterator[Segment]:
    """The segments of ``path`` in order, as far as they can be walked."""
    position = 0
    while position < len(path):
        walked = _segment(path, position)
        if walked is None:
            return
        segment, position = walked
        yield segment


def _segment(path: tuple[PathItem, ...], start: int) -> tuple[Segment, int] | None:
    """The segment at ``start`` and where the next begins; None when it cannot be walked."""
    head = path[start].byte
    if head is None:
        return None
    kind = head >> 5
    if kind == LOGICAL:
        return _logical(path, start, head)
    if kind == PORT:
        end = _port_end(path, start, head)
    elif kind == NETWORK:
        end = _sized_end(path, start + 1, 2) if head & 0xF0 == 0x50 else start + 2
    elif kind == SYMBOLIC and head & 0x1F:
        end = _padded(path, start, start + 1 + (head & 0x1F))
    elif head == _SIMPLE_DATA:
        end = _sized_end(path, start + 1, 2)
    elif head == _ANSI_SYMBOL:
        end = _padded(path, start, _sized_end(path, start + 1, 1))
    else:
        return None
    return (Segment(kind, start), end) if end is not None and end <= len(path) else None


def _logical(path: tuple[PathItem, ...], start: int, head: int) -> tuple[Segment, int] | None:
    logical, width = (head >> 2) & 7, head & 3
    if logical == SPECIAL and width == 0:
        return Segment(LOGICAL, start, logical), start + _ELECTRONIC_KEY_BYTES
    if width == 3:
        return None  # reserved format
    size = (1, 2, 4)[width]
    after = start + 1
    pad = width > 0 and after + 1 < len(path) and path[after].byte == 0
    first = after + 1 if pad else after
    value_items = 1 if first < len(path) and path[first].byte is None else size
    items = path[first:first + value_items]
    if len(items) < value_items:
        return None
    data = [item.byte for item in items if item.byte is not None]
    value = int.from_bytes(bytes(data), "little") if len(data) == len(items) else None
    return Segment(LOGICAL, start, logical, value, packed=width > 0 and not pad), first + value_items


def _port_end(path: tuple[PathItem, ...], start: int, head: int) -> int | None:
    """After a port segment: an extended port number (0x0F), then a one-byte or sized link address."""
    position = start + 1 + (2 if head & 0x0F == 0x0F else 0)
    if not head & 0x10:
        return position + 1
    return _padded(path, start, _sized_end(path, position, 1))


def _sized_end(path: tuple[PathItem, ...], count_at: int, unit: int) -> int | None:
    """After a count byte at ``count_at`` and that many units of ``unit`` bytes."""
    count = path[count_at].byte if count_at < len(path) else None
    return None if count is None else count_at + 1 + unit * count


def _padded(path: tuple[PathItem, ...], start: int, end: int | None) -> int | None:
    """``end``, past the pad byte a padded path puts after a segment of an odd number of bytes."""
    if end is not None and (end - start) % 2 and end < len(path) and path[end].byte == 0:
        return end + 1
    return end


def addressed_instance(path: object, class_code: int) -> int | None:
    """The instance a path addresses in the object class ``class_code``, when both are numbers."""
    if not isinstance(path, tuple):
        return None
    walked = [segment for segment in segments(path) if segment.kind == LOGICAL]
    classes = [segment for segment in walked if segment.logical == CLASS]
    instances = [segment for segment in walked if segment.logical == INSTANCE]
    if classes and instances and classes[0].value == class_code:
        return instances[0].value
    return None


def _field(entry: Entry | None, index: int):
    if entry is not None and 0 <= index < len(entry.fields):
        return entry.fields[index]
    return entry


def _path_text(path: object) -> str:
    return " ".join(str(item) for item in path) if isinstance(path, tuple) else str(path)


# --- paths ---------------------------------------------------------------------------------


def _packed(path: object) -> Segment | None:
    """The first 16- or 32-bit logical segment of ``path`` written without its pad byte."""
    return next((segment for segment in segments(path) if segment.packed), None) if isinstance(path, tuple) else None


@check(PACKED_CONNECTION_PATH, PACKED_MEMBER_PATH)
def packed_paths(ctx: Context) -> Iterator[Diagnostic]:
    """C.4.1.4.9.13: a connection path uses the padded path notation; a packed member path is allowed
    (C.4.1.4.8), and information for the tools that refuse it."""
    for connection in ctx.device.connections.values():
        packed = _packed(connection.path)
        if packed is not None:
            yield ctx.at(PACKED_CONNECTION_PATH, f"{connection.keyword}: path \"{_path_text(connection.path)}\" has a "
                         f"16- or 32-bit logical segment at byte {packed.start} without its pad byte; write the "
                         "padded EPATH (a 0x00 after the segment byte)", _field(connection.entry, _CONNECTION_PATH))
    for assembly in ctx.device.assemblies.values():
        for member in assembly.members:
            packed = _packed(member.reference)
            if packed is not None:
                yield ctx.at(PACKED_MEMBER_PATH, f"{assembly.keyword}: member path \"{_path_text(member.reference)}\" "
                             f"is packed at byte {packed.start}; the text allows it, but some tools refuse it",
                             _field(assembly.entry, member.field_index + 1))


#: Segment types an assembly path (logical) and a member path (logical or data) may hold (C.4.1.4.8).
_ASSEMBLY_PATH_KINDS, _MEMBER_PATH_KINDS = frozenset({LOGICAL}), frozenset({LOGICAL, DATA})
_KIND_NAMES = ("a port", "a logical", "a network", "a symbolic", "a data")


def _foreign_segment(path: tuple[PathItem, ...], allowed: frozenset[int]) -> Segment | None:
    return next((segment for segment in segments(path) if segment.kind not in allowed), None)


@check(NON_LOGICAL_SEGMENT)
def assembly_path_segments(ctx: Context) -> Iterator[Diagnostic]:
    """C.4.1.4.8: an assembly path is a logical path; a member path holds logical or data segments."""
    for assembly in ctx.device.assemblies.values():
        places: list[tuple[object, frozenset[int], str, str, int]] = [
            (assembly.path, _ASSEMBLY_PATH_KINDS, "path", "a logical path", _ASSEM_PATH)]
        places += [(member.reference, _MEMBER_PATH_KINDS, "member path", "logical or data segments",
                    member.field_index + 1) for member in assembly.members]
        for path, allowed, what, wanted, index in places:
            if not isinstance(path, tuple):
                continue
            foreign = _foreign_segment(path, allowed)
            if foreign is not None:
                yield ctx.at(NON_LOGICAL_SEGMENT, f"{assembly.keyword}: {what} \"{_path_text(path)}\" has "
                             f"{_KIND_NAMES[foreign.kind]} segment at byte {foreign.start}; it shall be {wanted}",
                             _field(assembly.entry, index))


# --- instance numbers ------------------------------------------------------------------------


@check(PARAM_INSTANCE_MISMATCH, ASSEM_INSTANCE_MISMATCH, LINK_SIZE_WITHOUT_PATH)
def instance_numbers(ctx: Context) -> Iterator[Diagnostic]:
    """C.4.1.4.6, C.4.1.4.8: the N of ParamN / AssemN is the instance their own path addresses;
    Table C.14: no Link Path Size without a Link Path."""
    yield from ctx.each(_parameter_instances, ctx.shared(parameter_units))
    yield from ctx.each(_assembly_instances, ctx.shared(assembly_units))


def _parameter_instances(ctx: Context, units: Iterable[tuple[Parameter, Entry | None]]) -> Iterator[Diagnostic]:
    for parameter, entry in units:
        instance = addressed_instance(parameter.link_path, _PARAMETER_CLASS)
        if instance is not None and instance != parameter.number:
            yield ctx.at(PARAM_INSTANCE_MISMATCH, f"{parameter.keyword}: the link path addresses Parameter "
                         f"instance {instance}, not {parameter.number}", _field(entry, _LINK_PATH))
        if entry is not None and len(entry.fields) > _LINK_SIZE and entry.fields[_LINK_SIZE].value is not None \
                and (len(entry.fields) <= _LINK_PATH or entry.fields[_LINK_PATH].value is None):
            yield ctx.at(LINK_SIZE_WITHOUT_PATH, f"{parameter.keyword}: Link Path Size "
                         f"{entry.fields[_LINK_SIZE].raw} without a Link Path; leave the size empty when the "
                         "parameter is not addressable", entry.fields[_LINK_SIZE])


def _assembly_instances(ctx: Context, units: Iterable[tuple[Assembly, Entry | None]]) -> Iterator[Diagnostic]:
    for assembly, entry in units:
        instance = addressed_instance(assembly.path, _ASSEMBLY_CLASS)
        if instance is not None and instance != assembly.number:
            yield ctx.at(ASSEM_INSTANCE_MISMATCH, f"{assembly.keyword}: the path addresses Assembly instance "
                         f"{instance}, not {assembly.number}", _field(entry, _ASSEM_PATH))


# --- ports, racks, slots ----------------------------------------------------------------------


@check(PORT_TYPE_VENDOR_ID, PORT_1_NOT_BACKPLANE)
def port_types_and_numbers(ctx: Context) -> Iterator[Diagnostic]:
    """C.4.1.4.10: a vendor port type carries the device's Vendor ID; port number 1 is the backplane."""
    vendor = ctx.device.identity.vendor_code
    network_types = tables.PORT_TYPE_KEYWORDS
    for port in ctx.device.ports:
        if isinstance(port.type_name, str) and tables.is_vendor_keyword(port.type_name) \
                and isinstance(vendor, int) and int(port.type_name.partition("_")[0]) != vendor:
            yield ctx.at(PORT_TYPE_VENDOR_ID, f"Port{port.number}: port type {port.type_name} begins with vendor ID "
                         f"{port.type_name.partition('_')[0]}, not the device's {vendor}", _field(port.entry, 0))
        if port.port_number == 1 and port.type_name in network_types:
            yield ctx.at(PORT_1_NOT_BACKPLANE, f"Port{port.number}: port number 1 is the backplane port, but this "
                         f"is a {port.type_name} port", _field(port.entry, 3))


@check(DUPLICATE_RACK, QUERY_NOT_SLOT_0)
def racks_and_slots(ctx: Context) -> Iterator[Diagnostic]:
    """C.4.1.5.2.3: one RackN per chassis; C.4.1.5.2.4: a Query belongs to a module in slot 0."""
    modular = ctx.device.modular
    if modular is None:
        return
    first_rack: dict[tuple, int] = {}
    for rack in modular.racks:
        if None in rack.key:
            continue
        if rack.key in first_rack:
            yield ctx.at(DUPLICATE_RACK, f"Rack{rack.number} names the chassis of Rack{first_rack[rack.key]} again; "
                         "give one RackN per chassis with all its legal slots", rack.entry)
        else:
            first_rack[rack.key] = rack.number
    if modular.query is not None and modular.racks and not any(0 in rack.legal_slots for rack in modular.racks):
        section = ctx.eds.section("Modular")
        yield ctx.at(QUERY_NOT_SLOT_0, "Query is only addressed to a module in slot 0, but no RackN lists slot 0 "
                     "among its legal slots", section.entry("Query") if section is not None else None)
