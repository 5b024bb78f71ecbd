"""Checks of the content beyond the 2003 text: fields against the cip_tables types, keywords, class
codes, required entries, interface instances, the icon, references, DeviceNet I/O sizes (EDS501-EDS514).

Driven by :mod:`edsconv.cip_tables`: a field is read by its FieldSpec
(:func:`edsconv.model.cip_build.read_field`), and the record's ``provenance`` decides the severity,
as the issue's policy says: a fact eds-pie documents may be broken with an error, one known from
practice only with a warning at most. The rules and their documentation are in
:mod:`edsconv.checks.object_rules`.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from edsconv import cip_tables
from edsconv import spec_tables as tables
from edsconv.checks import Context, check
from edsconv.checks.object_rules import (
    CLASS_CODE_MISMATCH,
    CLASS_CODE_PRACTICE,
    ICON_NOT_BASE64,
    ICON_NOT_ICO,
    INTERFACE_BEYOND_MAX_INSTANCE,
    IO_SIZES_DISAGREE,
    MISSING_DOCUMENTED_ENTRY,
    NOT_A_LISTED_KEYWORD,
    NOT_DOCUMENTED_TYPE,
    NOT_PRACTICE_TYPE,
    OPAQUE_ASSEMBLY,
    OUT_OF_DOCUMENTED_RANGE,
    UNDEFINED_DOCUMENTED_REFERENCE,
    UNDEFINED_PRACTICE_REFERENCE,
)
from edsconv.diagnostics import Diagnostic
from edsconv.eds.syntax import Entry, Field, Scalar
from edsconv.model import Reference
from edsconv.model.cip_build import newer_entries, range_problem, reading
from edsconv.model.values import ValueProblem

#: The reference families whose entries the typed model holds (a VariantN ... is kept, not resolved).
_RESOLVED_FAMILIES = frozenset({"Param", "ProxyParam", "Assem", "ProxyAssem", "AssemExa"})


def _source(provenance: tables.Provenance | None) -> str:
    """The record a fact comes from, as a message names it."""
    if provenance is None or provenance.practice_only:
        return "known from the real files"
    return f"eds-pie {provenance.eds_pie}"


def _at(entry: Entry, index: int) -> Field | Entry:
    return entry.fields[index] if index < len(entry.fields) else entry


# --- fields ----------------------------------------------------------------------------------


@check(NOT_DOCUMENTED_TYPE, OUT_OF_DOCUMENTED_RANGE, NOT_PRACTICE_TYPE, NOT_A_LISTED_KEYWORD)
def field_types(ctx: Context) -> Iterator[Diagnostic]:
    """Each field of a newer entry is of one of its FieldSpec's types, in range, one of its keywords;
    required fields are given and no field lies beyond the layout. The fields were read once, by
    model.cip_build (GenericEntry.readings)."""
    for _, _, generic, spec in newer_entries(ctx.device):
        entry = generic.entry
        if entry is None:
            continue
        practice = spec.provenance is None or spec.provenance.practice_only
        if spec.max_fields is not None and len(entry.fields) > spec.max_fields:
            rule_ = NOT_PRACTICE_TYPE if practice else NOT_DOCUMENTED_TYPE
            yield ctx.at(rule_, f"{entry.keyword} has {len(entry.fields)} fields; it has {spec.max_fields} "
                                f"({_source(spec.provenance)})", entry.fields[spec.max_fields])
        readings = generic.readings or [reading(value, spec.field_at(i + 1)) for i, value in enumerate(generic.values)]
        for index in range(min(len(entry.fields), spec.max_fields or len(entry.fields))):
            field_spec = spec.field_at(index + 1)
            if field_spec is not None:
                yield from _field(ctx, entry, index, field_spec, readings[index])


def _field(ctx: Context, entry: Entry, index: int, field_spec: tables.FieldSpec,
           read: tuple[Any, Exception | None]) -> Iterator[Diagnostic]:
    practice = field_spec.provenance is None or field_spec.provenance.practice_only
    where = f"{entry.keyword} field {index + 1} ({field_spec.name})"
    item = entry.fields[index]
    value, problem = read
    if item.value is None:
        if field_spec.presence is tables.Presence.REQUIRED and not field_spec.repeats:
            rule_ = NOT_PRACTICE_TYPE if practice else NOT_DOCUMENTED_TYPE
            yield ctx.at(rule_, f"{where} is required but empty ({_source(field_spec.provenance)})", item)
    elif isinstance(problem, ValueProblem):
        if practice:
            rule_ = NOT_PRACTICE_TYPE
        else:
            rule_ = OUT_OF_DOCUMENTED_RANGE if range_problem(problem) else NOT_DOCUMENTED_TYPE
        yield ctx.at(rule_, f"{where}: {problem.message} ({_source(field_spec.provenance)})", item)
    elif field_spec.choices and isinstance(value, str) and isinstance(item.value, Scalar) \
            and value not in field_spec.choices:
        allowed = ", ".join(str(choice) for choice in field_spec.choices)
        rule_ = NOT_PRACTICE_TYPE if practice else NOT_A_LISTED_KEYWORD
        yield ctx.at(rule_, f"{where} is {value}; allowed: {allowed} ({_source(field_spec.provenance)})", item)


# --- object classes ----------------------------------------------------------------------------


def _class_source(name: str) -> tables.Provenance | None:
    """Where a section's class ID comes from (a vendor named section: its own name, practice)."""
    if cip_tables.vendor_class_section(name) is not None:
        return None
    table = cip_tables.section_spec(name)
    return table.provenance if table is not None else None


@check(CLASS_CODE_MISMATCH, CLASS_CODE_PRACTICE)
def class_codes(ctx: Context) -> Iterator[Diagnostic]:
    """Object_Class_Code agrees with the class ID of the section's object."""
    for record in ctx.device.object_classes.values():
        if record.class_code is None or record.class_id is None or record.class_code == record.class_id:
            continue
        section = ctx.eds.section(record.section)
        entry = section.entry("Object_Class_Code") if section is not None else None
        source = _class_source(record.section)
        documented = source is not None and not source.practice_only
        why = _source(source) if source is not None else "the number in the section's name"
        yield ctx.at(CLASS_CODE_MISMATCH if documented else CLASS_CODE_PRACTICE,
                     f"[{record.section}] Object_Class_Code is 0x{record.class_code:X} ({record.class_code}), but "
                     f"the section describes class 0x{record.class_id:X} ({record.class_id}; {why})", entry)


@check(MISSING_DOCUMENTED_ENTRY)
def required_newer_entries(ctx: Context) -> Iterator[Diagnostic]:
    """The entries eds-pie marks required in a section beyond the 2003 text are there."""
    for section in ctx.eds.sections:
        table = cip_tables.CIP_SECTIONS.get(section.name)
        if table is None:
            continue
        for spec in table.entries:
            if spec.presence is tables.Presence.REQUIRED and not any(
                    tables.find_entry((spec,), entry.keyword) for entry in section.entries):
                yield ctx.at(MISSING_DOCUMENTED_ENTRY, f"[{section.name}] lacks {spec.keyword}, which it requires "
                                                       f"({_source(spec.provenance)})", section)


@check(INTERFACE_BEYOND_MAX_INSTANCE)
def interface_instances(ctx: Context) -> Iterator[Diagnostic]:
    """InterfaceLabelN / SpeedN / TypeN describe Ethernet Link instance N, at most MaxInst."""
    record = ctx.device.object_classes.get("Ethernet Link Class")
    section = ctx.eds.section("Ethernet Link Class")
    if record is None or record.max_instance is None or section is None:
        return
    for entry in section.entries:
        family, number = tables.split_numbered(entry.keyword)
        if family in ("InterfaceLabel", "InterfaceSpeed", "InterfaceType") and number and number > record.max_instance:
            yield ctx.at(INTERFACE_BEYOND_MAX_INSTANCE, f"{entry.keyword} describes Ethernet Link instance {number}, "
                                                        f"but MaxInst is {record.max_instance}", entry)


# --- the icon, references, DeviceNet I/O, the opaque assembly -------------------------------------


@check(ICON_NOT_BASE64, ICON_NOT_ICO)
def icon_contents(ctx: Context) -> Iterator[Diagnostic]:
    icon = ctx.device.icon_contents
    device = ctx.eds.section("Device")
    entry = device.entry("IconContents") if device is not None else None
    if icon is None or icon.problem is None:
        return
    if icon.kind == "not base64":
        yield ctx.at(ICON_NOT_BASE64, f"IconContents is not base64: {icon.problem}", entry)
    else:
        yield ctx.at(ICON_NOT_ICO, f"IconContents does not hold a valid ICO icon: {icon.problem}", entry)


def _dangling(references: Iterator[tuple[Reference | None, Entry | None]]) -> Iterator[tuple[Reference, Entry]]:
    for reference, entry in references:
        if reference is not None and entry is not None and reference.target is None:
            yield reference, entry


def _documented_references(ctx: Context) -> Iterator[tuple[Reference | None, Entry | None]]:
    for assembly in ctx.device.extended_assemblies.values():
        if isinstance(assembly.size, Reference):
            yield assembly.size, assembly.entry
        for member in assembly.members:
            if isinstance(member.reference, Reference) and member.reference.family in _RESOLVED_FAMILIES:
                yield member.reference, assembly.entry
    for record in ctx.device.object_classes.values():
        for description in record.service_descriptions:
            for reference in (description.request, description.response):
                if reference is not None and reference.family in _RESOLVED_FAMILIES:
                    yield reference, description.entry


def _practice_references(ctx: Context) -> Iterator[tuple[Reference | None, Entry | None]]:
    additions = ctx.device.additions
    if additions is not None:
        for reference in (*(additions.default_safety_connections or ()), additions.safety_cfg_assembly):
            yield reference, _entry_of(ctx, reference)
    devicenet = ctx.device.devicenet
    if devicenet is not None:
        for mode in devicenet.modes.values():
            yield mode.default_input, mode.entry
            yield mode.default_output, mode.entry


def _entry_of(ctx: Context, reference: Reference | None) -> Entry | None:
    if reference is None:
        return None
    section, keyword = ("Connection Manager", "DefaultSafetyConnections") if reference.family == "Connection" \
        else ("ParamClass", "SafetyCfgAssembly")
    found = ctx.eds.section(section)
    return found.entry(keyword) if found is not None else None


@check(UNDEFINED_DOCUMENTED_REFERENCE, UNDEFINED_PRACTICE_REFERENCE)
def newer_references(ctx: Context) -> Iterator[Diagnostic]:
    """The entries that newer entries name exist."""
    for reference, entry in _dangling(_documented_references(ctx)):
        yield ctx.at(UNDEFINED_DOCUMENTED_REFERENCE, f"{entry.keyword} refers to {reference.text}, which the file "
                                                     "does not define", _named(entry, reference))
    for reference, entry in _dangling(_practice_references(ctx)):
        yield ctx.at(UNDEFINED_PRACTICE_REFERENCE, f"{entry.keyword} names {reference.keyword}, which the file does "
                                                   "not define", entry)
    enum_par = ctx.eds.section("EnumPar")
    for entry in enum_par.entries if enum_par is not None else ():
        if cip_tables.known("EnumPar", entry.keyword) is cip_tables.Known.NEWER \
                and entry.keyword not in ctx.device.parameters:
            yield ctx.at(UNDEFINED_PRACTICE_REFERENCE, f"[EnumPar] {entry.keyword} gives the strings of "
                                                       f"{entry.keyword}, which [Params] does not define", entry)


def _named(entry: Entry, reference: Reference) -> Field | Entry:
    """The field of ``entry`` that writes ``reference``, or the entry."""
    return next((item for item in entry.fields if isinstance(item.value, Scalar) and item.value.raw == reference.text),
                entry)


@check(IO_SIZES_DISAGREE)
def devicenet_io_sizes(ctx: Context) -> Iterator[Diagnostic]:
    """An InputN / OutputN: the path size is the path's byte count, the bits fit in the bytes."""
    devicenet = ctx.device.devicenet
    for data in (*devicenet.inputs.values(), *devicenet.outputs.values()) if devicenet is not None else ():
        if data.path_size is not None and data.path is not None and data.path_size != len(data.path):
            yield ctx.at(IO_SIZES_DISAGREE, f"{data.keyword}: path size {data.path_size}, but the path has "
                                            f"{len(data.path)} bytes", _at(data.entry, 4) if data.entry else None)
        if data.size is not None and data.size_in_bits is not None and data.size_in_bits > 8 * data.size:
            yield ctx.at(IO_SIZES_DISAGREE, f"{data.keyword}: {data.size_in_bits} bits do not fit in {data.size} "
                                            "bytes", _at(data.entry, 1) if data.entry else None)


@check(OPAQUE_ASSEMBLY)
def opaque_assemblies(ctx: Context) -> Iterator[Diagnostic]:
    """EZ-EDS's opaque assembly, read as data of its size (not EDS327)."""
    for assembly in ctx.device.assemblies.values():
        if assembly.opaque:
            yield ctx.at(OPAQUE_ASSEMBLY, f"{assembly.keyword} is opaque data of {assembly.members[0].size} bits: "
                                          "its one member names the assembly itself (read as data, not as a cycle)",
                         _at(assembly.entry, 7) if assembly.entry else None)
