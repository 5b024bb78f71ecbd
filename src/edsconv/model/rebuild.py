"""The model made again after an edit of a few entries, from the model before it: what the language
server answers hover, completion and navigation from while the whole model is built again
(:mod:`edsconv.lsp.analysis`), the same as that build makes of the records.

Findings (diagnostics, unreadable and erroneous values, comment notes) stay those of the model
before: what reads them waits for the whole build.
"""

from __future__ import annotations

import bisect
from collections.abc import Sequence
from dataclasses import dataclass, replace
from itertools import islice
from typing import Any

from edsconv import spec_tables as tables
from edsconv.eds.syntax import EdsFile, Entry, Section
from edsconv.model import Device, GenericEntry, Parameter
from edsconv.model.build import ASSEMBLY_REVISION, RECORD_TABLES, ModelBuilder, resolve_references
from edsconv.model.cip_build import attach, section_table
from edsconv.model.cip_build import resolve as resolve_view

#: What the entries of each 2003 section other than those of records set on the device
_SECTION_ATTRIBUTES = {
    "File": ("file",), "Device": ("identity",), "Device Classification": ("classifications",),
    "ParamClass": ("param_class",), "Groups": ("groups",), "Port": ("ports",), "Modular": ("modular",),
}
#: The most entries a section other than one of records may have for :func:`with_entries_rebuilt` to make
#: its part of the model again whole (a hundredth of a second at most)
_REBUILT_AT_MOST = 500
#: The families of the entries paired with a parameter by number (EnumN, ProxyParamSizeAdderN: Table C.13)
_PAIRED_PREFIXES = tuple(spec.keyword for spec in tables.PARAMS_ENTRIES if spec.pairs_with is not None)


def with_entry_rebuilt(device: Device, eds: EdsFile, section: str, old: Entry, new: Entry) -> Device | None:
    """The model of ``eds``, which ``device``'s syntax model became when ``new`` took the place of
    ``old`` (an entry of ``section`` with the same keyword), where the record ``old`` made is all that
    can change: ``device`` with that record made again from ``new`` and every reference (of the
    typed view of the newer content too, which other entries make) resolved again; a parameter keeps
    the enum and size adder that other entries gave it when its data type, which types them, stays,
    and is given them anew otherwise. None for an entry that makes no record of its own, or not the
    one in the table.

    What the language server answers hover and completion from while the whole model is made again
    (:mod:`edsconv.lsp.analysis`): its findings (diagnostics, unreadable and erroneous values, comment
    notes) are still ``device``'s, and what reads them waits for the whole build.
    """
    table_name, spec = RECORD_TABLES.get(section), tables.entry_spec(section, new.keyword)
    table = getattr(device, table_name) if table_name is not None else {}
    known = table.get(new.keyword)
    if spec is None or known is None or known.entry is not old:
        return None
    record = _made(eds, section, [(new, spec)])[new.keyword]
    table = {**table, new.keyword: record}
    if isinstance(record, Parameter):
        if record.data_type == known.data_type:
            record.enum, record.size_adder = known.enum, known.size_adder
        else:
            table = _paired_anew(eds, _entries_of(eds, section), table, {new.keyword})
    rebuilt = replace(device, eds=eds, **{table_name: table})  # type: ignore[arg-type]
    resolve_references(rebuilt)
    resolve_view(rebuilt)  # the typed view is made of other entries: only its references may name the record
    return rebuilt


def with_entries_rebuilt(device: Device, eds: EdsFile, section: str, old: Sequence[Entry], new: Sequence[Entry],
                         first: int, start: tuple[int, int]) -> Device | None:
    """The model of ``eds``, which ``device``'s syntax model became when the entries ``new`` took the place
    of ``old`` in ``section`` (one the file has once), from its ``first``-th entry on and at ``start``
    (line, column), where they are all that changed.

    In a section of records ([Params], [Assembly], [Connection Manager]): ``device`` with the records
    ``old`` made taken out of the section's table and those of ``new`` made and put in their place,
    the same for the entries kept as written, the parameters paired with the EnumN and
    ProxyParamSizeAdderN among them, and those made, given their enums and size adders anew, and every
    reference resolved again. Where each entry of ``old`` and ``new`` makes a record of its table, is
    paired with a parameter or is kept as written and read by nothing else (no newer table defines it);
    None otherwise ([Assembly]'s Revision), or when a record of ``new`` has a keyword already in the
    table.

    In another section of no more than :data:`_REBUILT_AT_MOST` entries: the section's part of the
    model made again whole, and the typed view of the newer content with it.
    """
    holders = [other for other in eds.sections if other.name == section]
    if len(holders) != 1:
        return None
    if section not in RECORD_TABLES:
        return _with_section_rebuilt(device, eds, holders[0])
    return _with_records_rebuilt(device, eds, holders[0], old, new, first, start)


def _with_records_rebuilt(device: Device, eds: EdsFile, holder: Section, old: Sequence[Entry],
                          new: Sequence[Entry], first: int, start: tuple[int, int]) -> Device | None:
    """:func:`with_entries_rebuilt` for a section of records."""
    section, table_name = holder.name, RECORD_TABLES[holder.name]
    table: dict[str, Any] = getattr(device, table_name)
    removed, added = _parts(section, old), _parts(section, new)
    if removed is None or added is None:
        return None
    gone = {entry.keyword for entry, _ in removed.records}
    if any(getattr(table.get(entry.keyword), "entry", None) is not entry for entry, _ in removed.records) \
            or any(entry.keyword in table and entry.keyword not in gone for entry, _ in added.records):
        return None
    made = _made(eds, section, added.records)
    table = _table_spliced(table, gone, made, holder.entries, first)
    paired = removed.paired | added.paired | {keyword for keyword, made_record in made.items()
                                              if isinstance(made_record, Parameter)}
    if paired:
        table = _paired_anew(eds, holder.entries, table, paired)
    rebuilt = replace(device, eds=eds, **{table_name: table},  # type: ignore[arg-type]
                      extra_entries=_written_spliced(device, eds, section, removed.written, added.written, start))
    resolve_references(rebuilt)
    resolve_view(rebuilt)
    return rebuilt


def _made(eds: EdsFile, section: str, entries: list[tuple[Entry, tables.EntrySpec]]) -> dict[str, Any]:
    """The records ``entries`` of a section of records make, by keyword (of two with a keyword, the first's,
    as in a build)."""
    builder = ModelBuilder(eds, section_of={id(entry): section for entry, _ in entries})
    make = {"Params": builder.parameter, "Assembly": builder.assembly, "Connection Manager": builder.connection}
    made: dict[str, Any] = {}
    for entry, spec in entries:
        if entry.keyword not in made:
            made[entry.keyword] = make[section](entry, spec)
    return made


def _with_section_rebuilt(device: Device, eds: EdsFile, holder: Section) -> Device | None:
    """:func:`with_entries_rebuilt` for a section without records: its part of the model made again whole,
    then the typed view of the newer content (which its entries kept as written may hold); None for a
    section of more than :data:`_REBUILT_AT_MOST` entries."""
    if len(holder.entries) > _REBUILT_AT_MOST:
        return None
    builder = ModelBuilder(eds, section_of={id(entry): holder.name for entry in holder.entries})
    builder.section(holder)
    made = builder.device
    if holder.name in _SECTION_ATTRIBUTES:
        attributes = {name: getattr(made, name) for name in _SECTION_ATTRIBUTES[holder.name]}
        written = made.extra_entries.get(holder.name, [])
        rebuilt = replace(device, eds=eds, **attributes, extra_entries=_with_written(device, eds, holder.name, written))
    else:
        others = [made.other_sections[0] if other.name == holder.name else other
                  for other in device.other_sections]
        rebuilt = replace(device, eds=eds, other_sections=others)
    attach(rebuilt)
    resolve_references(rebuilt)
    return rebuilt


@dataclass(frozen=True, slots=True)
class _Parts:
    """Entries of a section of records: those that make a record (with their specs), those kept as written,
    and the keywords of the parameters the others are paired with (EnumN, ProxyParamSizeAdderN)."""

    records: list[tuple[Entry, tables.EntrySpec]]
    written: list[Entry]
    paired: set[str]


def _parts(section: str, entries: Sequence[Entry]) -> _Parts | None:
    """``entries`` of a section of records in their parts; None when one is the typed view's (a newer
    table defines it) or [Assembly]'s Revision."""
    parts = _Parts([], [], set())
    extension = section_table(section, extension=True)
    for entry in entries:
        spec = tables.entry_spec(section, entry.keyword)
        if spec is None:
            if extension is not None and tables.find_entry(extension.entries, entry.keyword) is not None:
                return None
            parts.written.append(entry)
        elif spec.pairs_with is not None:
            parts.paired.add(f"{spec.pairs_with}{tables.instance_number(entry.keyword)}")
        elif spec.keyword != ASSEMBLY_REVISION:
            parts.records.append((entry, spec))
        else:
            return None
    return parts


def _entries_of(eds: EdsFile, section: str) -> list[Entry]:
    """The entries of every section named ``section``, in file order."""
    return [entry for holder in eds.sections if holder.name == section for entry in holder.entries]


def _paired_anew(eds: EdsFile, entries: list[Entry], table: dict[str, Any], keywords: set[str]) -> dict[str, Any]:
    """``table`` (the parameters, of ``entries``) with those of ``keywords`` it holds copied with the enum
    and size adder that the entries paired with them give, as a build gives them
    (:meth:`ModelBuilder.attach_enums_and_adders`): the records of the model before keep theirs."""
    copies = {keyword: replace(table[keyword], enum=None, size_adder=None) for keyword in keywords if keyword in table}
    if not copies:
        return table
    builder = ModelBuilder(eds, section_of={})
    builder.device.parameters = copies
    for entry in entries:
        if entry.keyword.startswith(_PAIRED_PREFIXES):
            spec = tables.entry_spec("Params", entry.keyword)
            if spec is not None and f"{spec.pairs_with}{tables.instance_number(entry.keyword)}" in copies:
                builder.section_of[id(entry)] = "Params"
                builder.paired_entry(entry, spec)
    builder.attach_enums_and_adders()
    return {**table, **copies}


def _table_spliced(table: dict[str, Any], gone: set[str], made: dict[str, Any], entries: list[Entry],
                   first: int) -> dict[str, Any]:
    """``table`` without the records ``gone``, with those ``made`` where they stand in the section: after the
    record of the last entry before its ``first``-th that makes one."""
    if not gone and not made:
        return table
    items = list(table.items())
    at = 0
    for entry in reversed(entries[:first]):
        record = table.get(entry.keyword)
        if record is not None and record.entry is entry:
            at = list(table).index(entry.keyword) + 1
            break
    after = [item for item in islice(items, at, None) if item[0] not in gone]
    return dict([*items[:at], *made.items(), *after])


def _written_spliced(device: Device, eds: EdsFile, section: str, removed: list[Entry], added: list[Entry],
                     start: tuple[int, int]) -> dict[str, list[GenericEntry]]:
    """``device.extra_entries`` with the entries of ``section`` kept as written ``removed`` taken out and those
    ``added`` (at ``start``) put where they stand."""
    if not removed and not added:
        return device.extra_entries
    gone = {id(entry) for entry in removed}
    kept = [generic for generic in device.extra_entries.get(section, ()) if id(generic.entry) not in gone]
    at = bisect.bisect_left(kept, start, key=_written_at)
    return _with_written(device, eds, section, [*kept[:at], *map(ModelBuilder.generic, added), *kept[at:]])


def _with_written(device: Device, eds: EdsFile, section: str,
                  written: list[GenericEntry]) -> dict[str, list[GenericEntry]]:
    """``device.extra_entries`` with ``written`` the entries of ``section`` kept as written, in the order of
    the sections as a build makes it (none: no key)."""
    extra = device.extra_entries
    names = (other.name for other in eds.sections)
    return {name: written if name == section else extra[name]
            for name in names if name in extra and name != section or name == section and written}


def _written_at(generic: GenericEntry) -> tuple[int, int]:
    entry = generic.entry
    return (entry.line, entry.column) if entry is not None else (0, 0)
