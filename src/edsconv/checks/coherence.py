"""Checks of issue 20: what the [Device Classification] says against what the file describes (EDS224 -
EDS226), in both directions, and an enumeration against its parameter's range (EDS351); the rules are in
:mod:`edsconv.checks.coherence_rules`.

EDS205 (no EtherNetIP class where nothing else is classified) and EDS221 (classified EtherNetIP, no TCP
port) are the structure checks' and are not repeated here.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from edsconv import spec_tables as tables
from edsconv.checks import Context, check
from edsconv.checks.coherence_rules import (
    CLASSIFIED_NETWORK_WITHOUT_PORT,
    ENUM_CHOICE_OUT_OF_RANGE,
    ETHERNETIP_CONTENT_UNCLASSIFIED,
    KEYWORD_CASE_VARIANTS,
    NETWORK_CONTENT_UNCLASSIFIED,
)
from edsconv.diagnostics import Diagnostic
from edsconv.eds.syntax import Entry, Field, Scalar, Section
from edsconv.model import Parameter
from edsconv.model.device import is_integer

#: Sections of objects only EtherNet/IP devices have (eds-pie 1.2.0 class IDs 0xF5, 0xF6, 0x47, 0x5E).
ETHERNETIP_OBJECT_SECTIONS = ("TCP/IP Interface Class", "Ethernet Link Class", "DLR Class",
                              "EtherNet/IP Security Class")
#: Sections that describe a DeviceNet node: its slave I/O messages and its DeviceNet object (class 3).
DEVICENET_NODE_SECTIONS = ("IO_Info", "DeviceNet Class")
#: The Port Type Names of C.4.1.4.10 for each public network but EtherNet/IP (EDS221 has that one).
NETWORK_PORT_TYPES = {"DeviceNet": ("DeviceNet",), "ControlNet": ("ControlNet", "ControlNet_Redundant")}


def _first_section(ctx: Context, names: tuple[str, ...]) -> Section | None:
    return next((section for section in ctx.eds.sections if section.name in names), None)


def _classification(ctx: Context) -> Section | None:
    return ctx.eds.section("Device Classification")


@check(ETHERNETIP_CONTENT_UNCLASSIFIED)
def ethernetip_content(ctx: Context) -> Iterator[Diagnostic]:
    """C.4.2.2.1: an EtherNet/IP device is classified EtherNetIP, whatever else it is classified."""
    public = set(ctx.device.networks) & set(tables.CLASSIFICATION_KEYWORDS)
    if _classification(ctx) is None or ctx.device.is_ethernetip or not public:
        return  # EDS201 / EDS205 say it where nothing public is classified
    port = next((port for port in ctx.device.ports if port.type_name == tables.ETHERNETIP_PORT_TYPE), None)
    if port is not None:
        yield ctx.at(ETHERNETIP_CONTENT_UNCLASSIFIED, f"Port{port.number} is a TCP port (EtherNet/IP) but the "
                     f"device is classified only {', '.join(sorted(public))}; add a ClassN = EtherNetIP", port.entry)
        return
    section = _first_section(ctx, ETHERNETIP_OBJECT_SECTIONS)
    if section is not None:
        yield ctx.at(ETHERNETIP_CONTENT_UNCLASSIFIED, f"[{section.name}] describes an EtherNet/IP object but the "
                     f"device is classified only {', '.join(sorted(public))}; add a ClassN = EtherNetIP", section)


@check(NETWORK_CONTENT_UNCLASSIFIED)
def devicenet_content(ctx: Context) -> Iterator[Diagnostic]:
    """C.4.1.4.4: the classification names what the file describes; a DeviceNet node's sections."""
    if _classification(ctx) is None or "DeviceNet" in ctx.device.networks:
        return
    section = _first_section(ctx, DEVICENET_NODE_SECTIONS)
    if section is not None:
        classes = ", ".join(ctx.device.networks) or "nothing"
        yield ctx.at(NETWORK_CONTENT_UNCLASSIFIED, f"[{section.name}] describes a DeviceNet node but "
                     f"[Device Classification] lists {classes}; add a ClassN = DeviceNet", section)


@check(CLASSIFIED_NETWORK_WITHOUT_PORT)
def classified_network_ports(ctx: Context) -> Iterator[Diagnostic]:
    """C.4.1.4.10: a device classified under DeviceNet or ControlNet lists that network's port."""
    port_section = ctx.eds.section("Port")
    if port_section is None or not ctx.device.ports:
        return
    types = {port.type_name for port in ctx.device.ports if isinstance(port.type_name, str)}
    if any(name not in tables.PORT_TYPE_KEYWORDS and not tables.is_vendor_keyword(name) for name in types):
        return  # a misspelt port type (EDS333) may be the one: one fault, one code
    for network, port_types in NETWORK_PORT_TYPES.items():
        if network in ctx.device.networks and not types & set(port_types):
            yield ctx.at(CLASSIFIED_NETWORK_WITHOUT_PORT, f"the device is classified {network} but no PortN has "
                         f"the port type {' or '.join(port_types)} (port types: {', '.join(sorted(types))})",
                         port_section)


#: the parameter families whose EnumN is checked against their own range, with their Enum family
_ENUM_OF = {"Param": "Enum", "ProxyParam": "ProxyEnum"}
_ENUM_FAMILIES = tuple(_ENUM_OF.values())
_INTEGER_KINDS = frozenset({"unsigned", "signed"})


def _integer(item: Field) -> int | None:
    """An Enum value field as an integer (decimal, 0x hex or 0b binary); None when it is no number (EDS101)."""
    raw = item.value.raw if isinstance(item.value, Scalar) else ""
    try:
        return int(raw, 0) if raw[:2].lower() in ("0x", "0b") else int(raw)
    except ValueError:
        return None


def _range(parameter: Parameter) -> tuple[int, int] | None:
    kind = parameter.data_type.kind if parameter.data_type is not None else None
    if kind in _INTEGER_KINDS and is_integer(parameter.minimum) and is_integer(parameter.maximum):
        return parameter.minimum, parameter.maximum
    return None


@check(ENUM_CHOICE_OUT_OF_RANGE)
def enum_ranges(ctx: Context) -> Iterable[Diagnostic]:
    """C.4.1.4.6: the choices of an EnumN are values of its parameter, within Minimum..Maximum."""
    params = ctx.eds.section("Params")
    if params is None:
        return ()
    entries: dict[str, Entry] = {}
    for entry in params.entries:  # the first of each keyword, as Section.entry finds it: one pass, not one per EnumN
        if entry.keyword.startswith(_ENUM_FAMILIES):  # those looked up below, a fraction of a [Params]
            entries.setdefault(entry.keyword, entry)
    if not entries:
        return ()
    # which EnumN belongs to a parameter is decided by the section, outside the memo
    units = ((parameter, parameter.entry, enum) for parameter in ctx.device.parameters.values()
             if parameter.family in _ENUM_OF
             and (enum := entries.get(f"{_ENUM_OF[parameter.family]}{parameter.number}")) is not None)
    return ctx.each(_enum_ranges, units)


def _enum_ranges(ctx: Context, units: Iterable[tuple[Parameter, Entry | None, Entry]]) -> Iterator[Diagnostic]:
    for parameter, _entry, enum in units:
        bounds = _range(parameter)
        if bounds is None:
            continue
        for item in enum.fields[::2]:
            value = _integer(item)
            if value is not None and not bounds[0] <= value <= bounds[1]:
                yield ctx.at(ENUM_CHOICE_OUT_OF_RANGE, f"{enum.keyword} offers {item.raw}, outside "
                             f"{parameter.keyword}'s minimum {bounds[0]} .. maximum {bounds[1]}", item)


def case_variants(names: Iterable[str]) -> set[str]:
    """The names that share their letters, in other case, with another of ``names`` (EDS230)."""
    names = list(names)
    if len(set(map(str.casefold, names))) == len(set(names)):
        return set()  # the common case, told in C: as many letter sequences as spellings
    spellings: dict[str, set[str]] = {}
    for name in names:
        spellings.setdefault(name.casefold(), set()).add(name)
    return {name for group in spellings.values() if len(group) > 1 for name in group}


@check(KEYWORD_CASE_VARIANTS)
def keyword_case(ctx: Context) -> Iterator[Diagnostic]:
    """C.4.1.2.2.3, C.4.1.2.2.9: keywords are case-sensitive and unique in their section; two spellings
    of one keyword that differ only in case are one keyword written twice, as a case-blind tool reads it."""
    first: dict[str, Section] = {}
    for section in ctx.eds.sections:
        earlier = first.setdefault(section.name.casefold(), section)
        if earlier.name != section.name:
            yield ctx.at(KEYWORD_CASE_VARIANTS, f"[{section.name}] and [{earlier.name}] (line {earlier.line}) "
                         "differ only in letter case; keywords are case-sensitive, so one of them is not the "
                         "section it looks like", section)
        entries: dict[str, Entry] = {}
        for entry in section.entries:
            seen = entries.setdefault(entry.keyword.casefold(), entry)
            if seen.keyword != entry.keyword:
                yield ctx.at(KEYWORD_CASE_VARIANTS, f"{entry.keyword} and {seen.keyword} (line {seen.line}) in "
                             f"[{section.name}] differ only in letter case; keywords are case-sensitive, so one of "
                             "them is not the keyword it looks like", entry)
