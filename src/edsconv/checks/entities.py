"""Checks of parameters, assemblies, connections, ports and modules (C.4.1.4.6 - C.4.1.5).

Every limit comes from :mod:`edsconv.spec_tables` (bit tables, Table C.17's
min/max rules, Table C.18's numeric-only fields, the Port and Query field
specs). Values the model holds as None failed conversion and already carry an
EDS1xx diagnostic, and "Module" fields defer to another file: neither is
reported again here.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator
from typing import TypeGuard, TypeVar

from edsconv import spec_tables as tables
from edsconv.checks import Context, assembly_units, check, parameter_units, per_unit, with_entries
from edsconv.checks.coherence_rules import SCALING_ALL_ZERO
from edsconv.checks.entity_rules import (
    ASSEMBLY_CYCLE,
    ASSEMBLY_NOT_WHOLE_BYTES,
    ASSEMBLY_RESERVED_BITS,
    ASSEMBLY_SIZE_MISMATCH,
    BIT_STRING_MIN_MAX,
    DATA_SIZE_MISMATCH,
    DUPLICATE_CONNECTION_NAME,
    DUPLICATE_PORT_NUMBER,
    EMPTY_MEMBER,
    ENUM_NOT_PAIRS,
    ENUM_WITHOUT_DESCRIPTOR_BIT,
    GROUP_MEMBER_COUNT,
    LEGAL_SLOT_OUT_OF_RANGE,
    MEMBER_FIELDS_ODD,
    MODULE_IN_MEMBER,
    NESTED_ASSEMBLY,
    NO_CLASS_OR_TRIGGER,
    PARAM_RESERVED_BITS,
    PARAMCLASS_RESERVED_BITS,
    PARAMETERS_RESERVED_BITS,
    PROXY_CONNECT_NAME_MODULE,
    QUERY_FIELD_VALUE,
    RESERVED_REAL_TIME_FORMAT,
    SAFETY_REAL_TIME_FORMAT,
    SCALING_ON_NON_NUMERIC,
    SCALING_ZERO,
    SIZE_FORMAT_MISMATCH,
    SIZE_WITHOUT_FORMAT,
    SLOT_MASK_PAIR,
    SLOT_MASK_WITHOUT_SIZE,
    STRING_LENGTHS_MISSING,
    TRANSPORT_NOT_ONE,
    TRIGGER_RESERVED_BITS,
    UNDEFINED_REFERENCE,
    UNKNOWN_PORT_TYPE,
    UNPAIRED_ENTRY,
    VALUE_ORDER,
    WIDTH_ZERO,
    WRONG_PARAMETER_TYPE,
)
from edsconv.diagnostics import Diagnostic
from edsconv.eds.syntax import Entry
from edsconv.merge import BAD_MODULE_MEMBER_LIST, module_member_list_faults
from edsconv.model import (
    MODULE,
    MODULE_MEMBER_LIST,
    Assembly,
    AssemblyMember,
    Connection,
    ConnectionEndpoint,
    Device,
    Parameter,
    Rack,
    Reference,
)
from edsconv.model.build import iter_references
from edsconv.model.device import field_written as _written
from edsconv.model.device import is_integer as _is_int
from edsconv.model.values import PathItem

_E = TypeVar("_E", Parameter, Assembly, Connection)


def _node(entry: Entry | None, index: int):
    """Field ``index`` of ``entry`` for positions, else the entry itself (or None)."""
    if entry is not None and 0 <= index < len(entry.fields):
        return entry.fields[index]
    return entry


def _own(entities: Iterable[_E]) -> Iterator[_E]:
    """The entities whose fields are all used as written: not the Proxied entries of a module's file, whose
    fields count only where the adapter's Proxy entry says Module (C.4.1.5.3) and are documentation
    elsewhere. Rules that relate fields of one entry to each other (sizes against formats, minimum
    against maximum, Size against members) apply to the entry the pair forms: ``edsconv merge`` checks it."""
    return (entity for entity in entities if not entity.family.startswith("Proxied"))


_ParameterUnits = Iterable[tuple[Parameter, Entry | None]]


def _own_parameters(ctx: Context) -> _ParameterUnits:
    return with_entries(_own(ctx.device.parameters.values()))


def _is_number(value: object) -> TypeGuard[int | float]:
    return isinstance(value, int | float) and not isinstance(value, bool)


# --- references ------------------------------------------------------------------------


def _path_references(connection: Connection) -> Iterator[PathItem]:
    if isinstance(connection.path, tuple):
        yield from (item for item in connection.path if item.reference)


def _reference_clause(ref: Reference) -> str:
    """The clause that says what the field of a reference may name: an assembly member (C.4.1.4.8), a
    connection field (C.4.1.4.9.4 - .10), the chassis SlotDisplayRule (C.4.1.5.2.2)."""
    family = tables.split_numbered(ref.entry.keyword)[0] if ref.entry is not None else ""
    if family in _CONNECTION_FAMILIES and ref.field_index < len(tables.CONNECTION_FIELDS):
        return tables.CONNECTION_FIELDS[ref.field_index].clause
    if family == "SlotDisplayRule":
        return next(spec.clause for spec in tables.MODULAR_ENTRIES if spec.keyword == family)
    return tables.ASSEM_FIELDS[0].clause


_CONNECTION_FAMILIES = frozenset(spec.keyword for spec in tables.SECTIONS["Connection Manager"].entries)
#: C.4.1.4.9.13: the connection path may name Param / ProxyParam entries.
_PATH_CLAUSE = tables.CONNECTION_FIELDS[14].clause


@check(UNDEFINED_REFERENCE)
def undefined_references(ctx: Context) -> Iterator[Diagnostic]:
    """Every reference names a defined entry, but a group member: a GroupN lists Parameter object
    instances, and C.4.1.4.6 lets an instance go without a ParamN entry."""
    group_members = {id(member) for group in ctx.device.groups for member in group.members}
    for ref in iter_references(ctx.device):
        if ref.entry is not None and ref.entry.keyword.startswith("Proxied"):
            continue  # names an entry of the pair, maybe the adapter's: merge checks it (see _own)
        if ref.target is None and id(ref) not in group_members:
            where = ref.entry.keyword if ref.entry is not None else "a reference"
            yield ctx.at(UNDEFINED_REFERENCE, f"{where} names {ref.keyword}, which is not defined",
                         _node(ref.entry, ref.field_index), clause=_reference_clause(ref))
    for connection in _own(ctx.device.connections.values()):
        for item in _path_references(connection):
            if ctx.device.resolve(item.reference or "") is None:
                yield ctx.at(UNDEFINED_REFERENCE, f"{connection.keyword}: the path names [{item.reference}], "
                             "which is not defined", _node(connection.entry, 14), clause=_PATH_CLAUSE)


#: C.4.1.4.9.4 - .10 and .13: the type a parameter named in a connection field evaluates to.
_RPI_TYPES, _SIZE_TYPES, _PATH_TYPES = ("UDINT",), ("UINT",), ("USINT", "UINT", "UDINT")


def _connection_value_fields(connection: Connection) -> Iterator[tuple[str, int, object, tuple[str, ...]]]:
    """(field name, 0-based index, value, allowed data types) of the RPI and size fields."""
    directions = (("O=>T", 2, connection.o_to_t), ("T=>O", 5, connection.t_to_o))
    for name, first, endpoint in directions:
        yield f"{name} RPI", first, endpoint.rpi, _RPI_TYPES
        yield f"{name} size", first + 1, endpoint.size, _SIZE_TYPES
    for name, first, endpoint in (("config #1", 8, connection.config1), ("config #2", 10, connection.config2)):
        yield f"{name} size", first, endpoint.size, _SIZE_TYPES


@check(WRONG_PARAMETER_TYPE)
def connection_parameter_types(ctx: Context) -> Iterator[Diagnostic]:
    for connection in _own(ctx.device.connections.values()):
        for name, index, value, allowed in _connection_value_fields(connection):
            if isinstance(value, Reference) and isinstance(value.target, Parameter):
                data_type = value.target.data_type
                if data_type is not None and data_type.name not in allowed:
                    yield ctx.at(WRONG_PARAMETER_TYPE, f"{connection.keyword}: {name} names {value.keyword}, a "
                                 f"{data_type.name}; it shall evaluate to {' or '.join(allowed)}",
                                 _node(connection.entry, index), clause=tables.CONNECTION_FIELDS[index].clause)
        for item in _path_references(connection):
            target = ctx.device.resolve(item.reference or "")
            if isinstance(target, Parameter) and target.data_type is not None \
                    and target.data_type.name not in _PATH_TYPES:
                yield ctx.at(WRONG_PARAMETER_TYPE, f"{connection.keyword}: the path names {item.reference}, a "
                             f"{target.data_type.name}; path parameters shall be USINT, UINT or UDINT",
                             _node(connection.entry, 14), clause=_PATH_CLAUSE)


def _written_count(entry: Entry) -> int:
    """The number of fields up to the last one that holds a value."""
    return next((index + 1 for index in range(len(entry.fields) - 1, -1, -1) if entry.fields[index].value is not None),
                0)


@check(ENUM_NOT_PAIRS)
def enum_pairs(ctx: Context) -> Iterator[Diagnostic]:
    """C.4.1.4.6: "Each Enum entry shall consist of pairs of integers and strings"."""
    for section in ctx.eds.sections:
        if section.name == "Params":
            yield from ctx.each(_enum_pairs, section.entries)


def _enum_pairs(ctx: Context, entries: Iterable[Entry]) -> Iterator[Diagnostic]:
    for entry in entries:
        spec = tables.entry_spec("Params", entry.keyword)
        count = _written_count(entry)
        if spec is not None and spec.fields == tables.ENUM_FIELDS and count % 2:
            last = entry.fields[count - 1]
            yield ctx.at(ENUM_NOT_PAIRS, f"{entry.keyword} has {count} fields; its last value {last.raw} has no "
                         "string", last)


@check(UNPAIRED_ENTRY)
def unpaired_entries(ctx: Context) -> Iterator[Diagnostic]:
    """EnumN and the like name a parameter by their number (EntrySpec.pairs_with)."""
    paired_families = tuple(spec.keyword for spec in tables.PARAMS_ENTRIES if spec.pairs_with)
    for section in ctx.eds.sections:
        spec = tables.section_spec(section.name)
        if spec is None or spec.name != "Params":
            continue
        for entry in section.entries:
            entry_spec = spec.entry(entry.keyword) if entry.keyword.startswith(paired_families) else None
            if entry_spec is None or entry_spec.pairs_with is None:
                continue
            partner = f"{entry_spec.pairs_with}{tables.split_numbered(entry.keyword)[1]}"
            if partner not in ctx.device.parameters:
                yield ctx.at(UNPAIRED_ENTRY, f"{entry.keyword} has no {partner} to belong to", entry)


# --- groups ----------------------------------------------------------------------------


@check(GROUP_MEMBER_COUNT)
def group_member_counts(ctx: Context) -> Iterator[Diagnostic]:
    for group in ctx.device.groups:
        if group.entry is None or not _is_int(group.declared_members):
            continue
        listed = max(len(group.entry.fields) - 2, 0)
        if group.declared_members != listed:
            yield ctx.at(GROUP_MEMBER_COUNT, f"{group.entry.keyword} declares {group.declared_members} members but "
                         f"lists {listed}", _node(group.entry, 1))


# --- connections -----------------------------------------------------------------------


@check(DUPLICATE_CONNECTION_NAME)
def connection_names(ctx: Context) -> Iterator[Diagnostic]:
    # Proxied connections describe another device (the module's file); the names
    # the user chooses from are those of Connection and ProxyConnect entries.
    first_use: dict[str, str] = {}
    for connection in ctx.device.connections.values():
        if connection.family == "ProxiedConnect" or not isinstance(connection.name, str):
            continue
        if connection.family == "ProxyConnect" and connection.name == MODULE:
            continue  # EDS313 says what is wrong with it
        if connection.name in first_use:
            yield ctx.at(DUPLICATE_CONNECTION_NAME, f"{connection.keyword}: the name {connection.name!r} is already "
                         f"used by {first_use[connection.name]}", _node(connection.entry, 12))
        else:
            first_use[connection.name] = connection.keyword


def _reserved_bits(ctx: Context, rule_, keyword: str, label: str, value, table: tables.BitTable,
                   node) -> Iterator[Diagnostic]:
    """A diagnostic when ``value`` sets bits ``table`` reserves (or does not define)."""
    if not _is_int(value):
        return
    reserved = tables.reserved_bits_set(value, table)
    if reserved:
        bits = ", ".join(str(bit) for bit in range(table.width) if reserved >> bit & 1)
        yield ctx.at(rule_, f"{keyword}: {label} 0x{value:0{table.width // 4}X} sets reserved bit(s) {bits} "
                     f"(Table {table.table})", node)


def _trigger_transport(ctx: Context, connection: Connection, mask: int) -> Iterator[Diagnostic]:
    table, node = tables.TRIGGER_TRANSPORT_BITS, _node(connection.entry, 0)
    transports = [f.name for f in table.group("transport") if not f.reserved and f.extract(mask)]
    if len(transports) != 1:
        yield ctx.at(TRANSPORT_NOT_ONE, f"{connection.keyword}: trigger and transport 0x{mask:08X} sets "
                     f"{len(transports)} transport types ({', '.join(transports) or 'none'}); exactly one shall "
                     "be set", node)
    for group in ("class", "trigger"):
        if not any(f.extract(mask) for f in table.group(group) if not f.reserved):
            yield ctx.at(NO_CLASS_OR_TRIGGER, f"{connection.keyword}: trigger and transport 0x{mask:08X} sets no "
                         f"{group} bit", node)


def _real_time_formats(ctx: Context, connection: Connection, mask: int) -> Iterator[Diagnostic]:
    for bit_field, value in tables.reserved_values_set(mask, tables.CONNECTION_PARAMETER_BITS):
        rule_, note = RESERVED_REAL_TIME_FORMAT, "is reserved (Table C.24)"
        if value == _SAFETY_FORMAT:
            rule_, note = SAFETY_REAL_TIME_FORMAT, "is reserved in the 2003 text (CIP Safety in later editions)"
        yield ctx.at(rule_, f"{connection.keyword}: connection parameters 0x{mask:08X}: {bit_field.name} {value} "
                     f"{note}", _node(connection.entry, 1))


@check(
    TRIGGER_RESERVED_BITS,
    TRANSPORT_NOT_ONE,
    NO_CLASS_OR_TRIGGER,
    PARAMETERS_RESERVED_BITS,
    RESERVED_REAL_TIME_FORMAT,
    SAFETY_REAL_TIME_FORMAT,
)
def connection_masks(ctx: Context) -> Iterator[Diagnostic]:
    """Tables C.23 and C.24: reserved bits and values, one transport, a class and a trigger."""
    for connection in ctx.device.connections.values():
        yield from _reserved_bits(ctx, TRIGGER_RESERVED_BITS, connection.keyword, "trigger and transport",
                                  connection.trigger_transport, tables.TRIGGER_TRANSPORT_BITS,
                                  _node(connection.entry, 0))
        yield from _reserved_bits(ctx, PARAMETERS_RESERVED_BITS, connection.keyword, "connection parameters",
                                  connection.parameters, tables.CONNECTION_PARAMETER_BITS, _node(connection.entry, 1))
        if _is_int(connection.trigger_transport):
            yield from _trigger_transport(ctx, connection, connection.trigger_transport)
        if _is_int(connection.parameters):
            yield from _real_time_formats(ctx, connection, connection.parameters)


_DIRECTIONS = (("O=>T", 3, "o_to_t"), ("T=>O", 6, "t_to_o"))
#: Real time transfer format 5: reserved by Table C.24 but assigned to CIP Safety
#: by later editions, whose safety connections take their sizes from the safety
#: validator, so an empty size and format is how real safety EDS files write them.
_SAFETY_FORMAT = 5


def _real_time_format(connection: Connection, direction: str) -> int | None:
    if not _is_int(connection.parameters):
        return None
    return tables.CONNECTION_PARAMETER_BITS.field(f"{direction} real time format").extract(connection.parameters)


@check(SIZE_WITHOUT_FORMAT, SIZE_FORMAT_MISMATCH)
def connection_sizes_and_formats(ctx: Context) -> Iterator[Diagnostic]:
    for connection in _own(ctx.device.connections.values()):
        entry = connection.entry
        for name, size_index, attribute in _DIRECTIONS:
            endpoint: ConnectionEndpoint = getattr(connection, attribute)
            if entry is not None and not _written(entry, size_index) and not _written(entry, size_index + 1) \
                    and _real_time_format(connection, name) != _SAFETY_FORMAT:
                yield ctx.at(SIZE_WITHOUT_FORMAT, f"{connection.keyword}: {name} size and {name} format are both "
                             "empty; give the size or a format to take it from", _node(entry, size_index))
            if _is_int(endpoint.size) and isinstance(endpoint.format, Reference) \
                    and isinstance(endpoint.format.target, Assembly):
                assembly = endpoint.format.target
                if _is_int(assembly.size) and assembly.size != endpoint.size:
                    yield ctx.at(SIZE_FORMAT_MISMATCH, f"{connection.keyword}: {name} size is {endpoint.size} bytes "
                                 f"but its format {assembly.keyword} is {assembly.size} bytes",
                                 _node(entry, size_index))


@check(PROXY_CONNECT_NAME_MODULE)
def proxy_connect_names(ctx: Context) -> Iterator[Diagnostic]:
    for connection in ctx.device.connections.values():
        if connection.family == "ProxyConnect" and connection.name == MODULE:
            yield ctx.at(PROXY_CONNECT_NAME_MODULE, f"{connection.keyword}: the connection name shall be given, "
                         "not 'Module'", _node(connection.entry, 12))


# --- parameters ------------------------------------------------------------------------


@check(PARAM_RESERVED_BITS, ASSEMBLY_RESERVED_BITS, PARAMCLASS_RESERVED_BITS)
def descriptors(ctx: Context) -> Iterator[Diagnostic]:
    """Tables C.12, C.15 and C.21: reserved descriptor bits shall be 0."""
    param_class = ctx.device.param_class
    if param_class is not None:
        yield from _reserved_bits(ctx, PARAMCLASS_RESERVED_BITS, "[ParamClass] Descriptor", "parameter class "
                                  "descriptor", param_class.descriptor, tables.PARAMCLASS_DESCRIPTOR_BITS,
                                  _section_entry(ctx.device, "ParamClass", "Descriptor"))
    yield from ctx.each(_descriptors, ctx.shared(parameter_units))
    yield from ctx.each(_descriptors, ctx.shared(assembly_units))


_DESCRIPTOR_BITS = {Parameter: (PARAM_RESERVED_BITS, tables.PARAM_DESCRIPTOR_BITS),
                    Assembly: (ASSEMBLY_RESERVED_BITS, tables.ASSEM_DESCRIPTOR_BITS)}


def _descriptors(ctx: Context, units: Iterable[tuple[Parameter | Assembly, Entry | None]]) -> Iterator[Diagnostic]:
    for record, entry in units:
        rule_, table = _DESCRIPTOR_BITS[record.__class__]
        yield from _reserved_bits(ctx, rule_, record.keyword, "descriptor", record.descriptor, table, _node(entry, 3))


def _type_bounds(data_type: tables.DataType) -> tuple[float | None, float | None]:
    """The bounds of a data type's values: REAL and LREAL hold -INFINITY and INFINITY too (C.4.1.3.10)."""
    if data_type.kind == "real":
        return -math.inf, math.inf
    return data_type.minimum, data_type.maximum


def _bounds(parameter: Parameter, data_type: tables.DataType) -> tuple[float, float] | None:
    """Effective (minimum, maximum) of a numeric parameter of ``data_type``: an absent bound
    is the type's own (Table C.17 note b); None when a bound is unusable."""
    type_minimum, type_maximum = _type_bounds(data_type)
    entry = parameter.entry
    bounds: list[float] = []
    for value, index, type_bound in ((parameter.minimum, 9, type_minimum), (parameter.maximum, 10, type_maximum)):
        if _is_number(value):
            bounds.append(value)
        elif not _written(entry, index) and type_bound is not None:
            bounds.append(type_bound)
        else:
            return None
    return bounds[0], bounds[1]


@check(VALUE_ORDER)
@per_unit(_own_parameters)
def parameter_value_order(ctx: Context, units: _ParameterUnits) -> Iterator[Diagnostic]:
    for parameter, _entry in units:
        data_type = parameter.data_type
        if data_type is None:
            continue
        rule_ = tables.min_max_rule(data_type.name)
        if rule_.meaning == "length":
            low, high = parameter.minimum, parameter.maximum
            if _is_int(low) and _is_int(high) and low > high:
                yield ctx.at(VALUE_ORDER, f"{parameter.keyword}: minimum length {low} is greater than maximum "
                             f"length {high}", _node(parameter.entry, 9))
            continue
        if rule_.meaning != "value":
            continue
        bounds = _bounds(parameter, data_type)
        if bounds is None:
            continue
        low, high = bounds
        if low > high:
            yield ctx.at(VALUE_ORDER, f"{parameter.keyword}: minimum {low} is greater than maximum {high}",
                         _node(parameter.entry, 9))
        elif _is_number(parameter.default) and not math.isnan(parameter.default) \
                and not low <= parameter.default <= high:
            yield ctx.at(VALUE_ORDER, f"{parameter.keyword}: default {parameter.default} is outside {low} to {high}",
                         _node(parameter.entry, 11))


def _deferred(entry: Entry | None, index: int) -> bool:
    return _written(entry, index) and entry.fields[index].raw == MODULE


@check(STRING_LENGTHS_MISSING, BIT_STRING_MIN_MAX)
@per_unit(_own_parameters)
def parameter_min_max_presence(ctx: Context, units: _ParameterUnits) -> Iterator[Diagnostic]:
    """Table C.17: required for strings, not allowed for bit strings."""
    for parameter, entry in units:
        if parameter.data_type is None or entry is None:
            continue
        presence = tables.min_max_rule(parameter.data_type.name).presence
        name = parameter.data_type.name
        if presence is tables.Presence.REQUIRED:
            missing = [label for label, index in (("minimum", 9), ("maximum", 10)) if not _written(entry, index)]
            if missing:
                yield ctx.at(STRING_LENGTHS_MISSING, f"{parameter.keyword}: a {name} parameter shall give its "
                             f"{' and '.join(missing)} length", _node(entry, 9) if len(entry.fields) > 9 else entry)
        elif presence is tables.Presence.NOT_ALLOWED:
            given = [label for label, index in (("minimum", 9), ("maximum", 10))
                     if _written(entry, index) and not _deferred(entry, index)]
            if given:
                yield ctx.at(BIT_STRING_MIN_MAX, f"{parameter.keyword}: a {name} parameter shall not give a "
                             f"{' or '.join(given)}", _node(entry, 9 if "minimum" in given else 10))


@check(SCALING_ON_NON_NUMERIC, SCALING_ZERO, SCALING_ALL_ZERO)
@per_unit(_own_parameters)
def parameter_scaling(ctx: Context, units: _ParameterUnits) -> Iterator[Diagnostic]:
    scaling_bit = tables.PARAM_DESCRIPTOR_BITS.field("Supports scaling")
    for parameter, entry in units:
        data_type = parameter.data_type
        if data_type is None or entry is None:
            continue
        if not data_type.numeric:
            given = [spec for spec in tables.PARAM_FIELDS if spec.number in tables.NUMERIC_ONLY_PARAM_FIELDS
                     and _written(entry, spec.number - 1) and not _deferred(entry, spec.number - 1)]
            if given:
                names = ", ".join(f"{spec.number} ({spec.name})" for spec in given)
                yield ctx.at(SCALING_ON_NON_NUMERIC, f"{parameter.keyword}: a {data_type.name} parameter gives "
                             f"field(s) {names}, which only numeric types may give", _node(entry, given[0].number - 1))
            continue
        if not _is_int(parameter.descriptor) or not scaling_bit.extract(parameter.descriptor):
            continue  # Figure C.8 writes 0s for scaling that is not used
        scaling = parameter.scaling
        if (scaling.multiplier, scaling.divisor, scaling.base, scaling.offset) == (0, 0, 0, 0):
            yield ctx.at(SCALING_ALL_ZERO, f"{parameter.keyword}: the descriptor says scaling is supported but "
                         "every scaling field is 0, as Figure C.11 writes it; Figure C.5 divides by the divisor",
                         _node(entry, 13))
        elif scaling.divisor == 0 and _is_int(scaling.divisor):
            yield ctx.at(SCALING_ZERO, f"{parameter.keyword}: scaling divisor is 0 but the descriptor says scaling "
                         "is supported; Figure C.5 divides by it", _node(entry, 13))


def _expected_data_size(data_type: tables.DataType) -> int | None:
    """Table C.14: the type's size, or bytes per character / path entry; None when any N fits (STRINGN)."""
    return data_type.size if data_type.size is not None else data_type.char_size


@check(DATA_SIZE_MISMATCH)
@per_unit(_own_parameters)
def parameter_data_sizes(ctx: Context, units: _ParameterUnits) -> Iterator[Diagnostic]:
    for parameter, _entry in units:
        data_type, size = parameter.data_type, parameter.data_size
        if data_type is None or not _is_int(size):
            continue
        expected = _expected_data_size(data_type)
        if expected is not None and size != expected:
            unit = "bytes" if data_type.size is not None else "bytes per character or entry"
            yield ctx.at(DATA_SIZE_MISMATCH, f"{parameter.keyword}: Data Size {size} but {data_type.name} is "
                         f"{expected} {unit}", _node(parameter.entry, 5))


@check(ENUM_WITHOUT_DESCRIPTOR_BIT)
def enum_descriptor_bits(ctx: Context) -> Iterator[Diagnostic]:
    enum_bit = tables.PARAM_DESCRIPTOR_BITS.field("Supports enumerated strings")
    for parameter in _own(ctx.device.parameters.values()):
        if parameter.enum and _is_int(parameter.descriptor) and not enum_bit.extract(parameter.descriptor):
            yield ctx.at(ENUM_WITHOUT_DESCRIPTOR_BIT, f"{parameter.keyword} has an enumeration but descriptor "
                         f"0x{parameter.descriptor:04X} does not set bit 1", _node(parameter.entry, 3))


# --- assemblies ------------------------------------------------------------------------


@check(EMPTY_MEMBER, ASSEMBLY_SIZE_MISMATCH, ASSEMBLY_NOT_WHOLE_BYTES, MODULE_IN_MEMBER)
def assembly_members(ctx: Context) -> Iterator[Diagnostic]:
    for assembly in ctx.device.assemblies.values():
        entry = assembly.entry
        total: int | None = 0
        for member in assembly.members:
            reference_index = member.field_index + 1
            if entry is not None and not _written(entry, member.field_index) and member.is_pad \
                    and not _written(entry, reference_index):
                yield ctx.at(EMPTY_MEMBER, f"{assembly.keyword}: member at field {member.field_index + 1} has "
                             "neither a Member Size nor a Member Reference", _node(entry, member.field_index))
                total = None
                continue
            if member.reference == MODULE:
                yield ctx.at(MODULE_IN_MEMBER, f"{assembly.keyword}: 'Module' is not allowed as a Member Reference; "
                             "use ModuleMemberList in place of the pair", _node(entry, reference_index))
            bits = ctx.device.member_bits(assembly, member)
            total = total + bits if total is not None and bits is not None else None
        if total is None or assembly.module_member_list or not assembly.members \
                or assembly.family.startswith("Proxied"):  # the pair's, see _own
            continue
        if _is_int(assembly.size):
            if assembly.size * 8 != total:
                yield ctx.at(ASSEMBLY_SIZE_MISMATCH, f"{assembly.keyword}: Size is {assembly.size} bytes "
                             f"({assembly.size * 8} bits) but the members add up to {total} bits", _node(entry, 2))
        elif not _written(entry, 2) and total % 8:
            yield ctx.at(ASSEMBLY_NOT_WHOLE_BYTES, f"{assembly.keyword}: the members add up to {total} bits, not a "
                         "whole number of bytes", entry)


def _nested_assemblies(assembly: Assembly) -> Iterator[tuple[AssemblyMember, Assembly]]:
    if assembly.opaque:
        return  # EZ-EDS's opaque data, not a nesting (EDS514)
    for member in assembly.members:
        if isinstance(member.reference, Reference) and isinstance(member.reference.target, Assembly):
            yield member, member.reference.target


@check(NESTED_ASSEMBLY, ASSEMBLY_CYCLE)
def assembly_nesting(ctx: Context) -> Iterator[Diagnostic]:
    for assembly in ctx.device.assemblies.values():
        nested = list(_nested_assemblies(assembly))
        if nested:
            names = ", ".join(dict.fromkeys(inner.keyword for _, inner in nested))
            yield ctx.at(NESTED_ASSEMBLY, f"{assembly.keyword} has assembly member(s) {names}; the spec allows it, "
                         "but some tools refuse nested assemblies", _node(assembly.entry, nested[0][0].field_index + 1))
        if _contains(assembly, assembly, set()):
            yield ctx.at(ASSEMBLY_CYCLE, f"{assembly.keyword} contains itself through its assembly members, so it "
                         "has no finite size", assembly.entry)


def _contains(outer: Assembly, wanted: Assembly, seen: set[str]) -> bool:
    for _, inner in _nested_assemblies(outer):
        if inner is wanted:
            return True
        if inner.keyword not in seen:
            seen.add(inner.keyword)
            if _contains(inner, wanted, seen):
                return True
    return False


def _unpaired_member_size(assembly: Assembly) -> int | None:
    """0-based index of a last Member Size without its Member Reference; a lone ModuleMemberList of a
    ProxyAssem stands for a whole pair (C.4.1.5.3.2), as the model reads it."""
    entry = assembly.entry
    if entry is None:
        return None
    index, end = tables.ASSEM_FIELDS[-2].number - 1, len(entry.fields)
    while index < end:
        lone = assembly.family == "ProxyAssem" and entry.fields[index].raw == MODULE_MEMBER_LIST
        if index + 1 == end and not lone:
            return index if entry.fields[index].value is not None else None  # empty: EDS323
        index += 1 if lone else 2
    return None


@check(MEMBER_FIELDS_ODD)
def assembly_member_pairs(ctx: Context) -> Iterator[Diagnostic]:
    """C.4.1.4.8: member fields are Member Size / Member Reference pairs, "making the total number of fields
    even"."""
    for assembly in ctx.device.assemblies.values():
        index = _unpaired_member_size(assembly)
        if index is not None:
            yield ctx.at(MEMBER_FIELDS_ODD, f"{assembly.keyword}: field {index + 1} is a Member Size without a "
                         "Member Reference; member fields come in pairs", _node(assembly.entry, index))


@check(BAD_MODULE_MEMBER_LIST)
def module_member_lists(ctx: Context) -> Iterator[Diagnostic]:
    """C.4.1.5.3.2: ModuleMemberList "shall only be used in place of a Member Size and Member Reference
    field pair"; in the adapter's file alone, as ``edsconv merge`` reports it."""
    for assembly in ctx.device.assemblies.values():
        if assembly.family == "ProxyAssem" and assembly.entry is not None:
            for item, message in module_member_list_faults(assembly.entry):
                yield ctx.at(BAD_MODULE_MEMBER_LIST, f"{assembly.keyword} {message}", item)


@check(SLOT_MASK_PAIR, SLOT_MASK_WITHOUT_SIZE)
def slot_masks(ctx: Context) -> Iterator[Diagnostic]:
    masks = {keyword for pair in tables.SLOT_MASK_PAIRS for keyword in pair}
    for assembly in ctx.device.assemblies.values():
        used = {member.reference for member in assembly.members if isinstance(member.reference, str)}
        for first, second in tables.SLOT_MASK_PAIRS:
            if first in used and second in used:
                yield ctx.at(SLOT_MASK_PAIR, f"{assembly.keyword} uses both {first} and {second}", assembly.entry)
        for member in assembly.members:
            if isinstance(member.reference, str) and member.reference in masks \
                    and not _written(assembly.entry, member.field_index):
                yield ctx.at(SLOT_MASK_WITHOUT_SIZE, f"{assembly.keyword}: {member.reference} needs a Member Size",
                             _node(assembly.entry, member.field_index))


# --- ports and modules -----------------------------------------------------------------


@check(DUPLICATE_PORT_NUMBER, UNKNOWN_PORT_TYPE)
def ports(ctx: Context) -> Iterator[Diagnostic]:
    type_spec = tables.known_entry("Port", "Port1").fields[0]
    first_use: dict[int, int] = {}
    for port in ctx.device.ports:
        if isinstance(port.type_name, str) and port.type_name not in type_spec.choices \
                and not (type_spec.vendor_keywords and tables.is_vendor_keyword(port.type_name)):
            yield ctx.at(UNKNOWN_PORT_TYPE, f"Port{port.number}: port type {port.type_name!r} is not one of "
                         f"{', '.join(map(str, type_spec.choices))} nor a <VendorID>_<keyword>",
                         _node(port.entry, 0))
        if _is_int(port.port_number):
            if port.port_number in first_use:
                yield ctx.at(DUPLICATE_PORT_NUMBER, f"Port{port.number}: port number {port.port_number} is already "
                             f"used by Port{first_use[port.port_number]}", _node(port.entry, 3))
            else:
                first_use[port.port_number] = port.number


def _names_this_device(rack: Rack, device: Device) -> bool:
    """True when a RackN's electronic key is the device's own: vendor, type, product code and major
    revision (C.4.1.4.3: the minor revision shall not be used to match an EDS to a device)."""
    identity = device.identity
    return rack.key[:4] == (identity.vendor_code, identity.product_type, identity.product_code,
                            identity.major_revision)


def _section_entry(device: Device, section_name: str, keyword: str) -> Entry | None:
    section = device.eds.section(section_name) if device.eds is not None else None
    return section.entry(keyword) if section is not None else None


def _modular_entry(device: Device, keyword: str) -> Entry | None:
    return _section_entry(device, "Modular", keyword)


@check(LEGAL_SLOT_OUT_OF_RANGE, WIDTH_ZERO, QUERY_FIELD_VALUE)
def modular(ctx: Context) -> Iterator[Diagnostic]:
    modular = ctx.device.modular
    if modular is None:
        return
    slots = modular.define_slots_in_rack
    if _is_int(slots):
        # A file with both DefineSlotsInRack and a RackN naming its own chassis describes
        # a chassis with modules of its own: their legal slots are slots of that chassis.
        for rack in modular.racks:
            if not _names_this_device(rack, ctx.device):
                continue  # another chassis: its slots are its own EDS's matter
            for index, slot in enumerate(rack.legal_slots):
                if slot >= slots:
                    yield ctx.at(LEGAL_SLOT_OUT_OF_RANGE, f"Rack{rack.number}: legal slot {slot} is beyond the "
                                 f"{slots} slots (0 to {slots - 1}) of this chassis (DefineSlotsInRack)",
                                 _node(rack.entry, 8 + index))
    if modular.width == 0:
        yield ctx.at(WIDTH_ZERO, "Width is 0; a module consumes at least one slot", _modular_entry(ctx.device, "Width"))
    if modular.query is not None:
        query_spec = tables.known_entry("Modular", "Query")
        entry = _modular_entry(ctx.device, "Query")
        service_spec, size_spec = query_spec.fields[1], query_spec.fields[2]
        if _is_int(modular.query.service) and modular.query.service not in service_spec.choices:
            yield ctx.at(QUERY_FIELD_VALUE, f"Query: service {modular.query.service} is neither 1 (Get_Attributes_All)"
                         " nor 14 (Get_Attribute_Single)", _node(entry, 1))
        low, high = size_spec.value_range or (None, None)
        if _is_int(modular.query.id_size) and _is_int(low) and _is_int(high) \
                and not low <= modular.query.id_size <= high:
            yield ctx.at(QUERY_FIELD_VALUE, f"Query: ID size {modular.query.id_size} is outside {low} to {high}",
                         _node(entry, 2))
