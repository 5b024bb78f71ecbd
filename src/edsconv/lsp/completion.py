"""Completion from the spec tables and the file itself: section names, the keywords a section
allows (numbered families with their next free number), data type codes with their names, the
choices a field allows, and references to the entries the file defines."""

from __future__ import annotations

from lsprotocol import types

from edsconv import spec_tables as tables
from edsconv.eds.locate import Spot, locate
from edsconv.eds.syntax import Section
from edsconv.lsp.analysis import Analysis

#: FIELD_VALUE_KINDS reference kind -> the family of the entries it names
_REFERENCE_FAMILIES = {"ParamRef": "Param", "ProxyParamRef": "ProxyParam", "AssemRef": "Assem",
                       "ProxyAssemRef": "ProxyAssem"}


def completions(analysis: Analysis, line: int, column: int) -> list[types.CompletionItem]:
    """What may be written at ``line``:``column``."""
    before = analysis.line_text(line)[:column - 1]
    if before.lstrip().startswith("[") and "=" not in before:
        return section_names(analysis)
    spot = locate(analysis.eds, line, column)
    if spot.section is None:
        return section_names(analysis)
    if spot.entry is None or spot.on_keyword:
        return entry_keywords(spot.section)
    return field_values(spot, analysis)


def section_names(analysis: Analysis) -> list[types.CompletionItem]:
    present = {section.name for section in analysis.eds.sections}
    return [types.CompletionItem(label=name, kind=types.CompletionItemKind.Module, detail=spec.title,
                                 documentation=f"{spec.clause}: {spec.presence}", sort_text=f"{rank:02}")
            for rank, (name, spec) in enumerate(tables.SECTIONS.items()) if name not in present]


def entry_keywords(section: Section) -> list[types.CompletionItem]:
    spec = tables.section_spec(section.name)
    if spec is None:
        return []
    present = {entry.keyword for entry in section.entries}
    items = []
    for rank, entry_spec in enumerate(spec.entries):
        if entry_spec.numbered:
            keyword = f"{entry_spec.keyword}{next_number(section, entry_spec.keyword)}"
        elif entry_spec.keyword in present:
            continue
        else:
            keyword = entry_spec.keyword
        items.append(types.CompletionItem(
            label=keyword, kind=types.CompletionItemKind.Keyword, detail=entry_spec.description,
            documentation=f"{entry_spec.clause}: {entry_spec.presence}", insert_text=f"{keyword} = ",
            sort_text=f"{rank:02}"))
    return items


def next_number(section: Section, family: str) -> int:
    """One more than the highest number of ``family`` in ``section`` (1 for the first)."""
    numbers = [number for entry in section.entries
               for prefix, number in [tables.split_numbered(entry.keyword)] if prefix == family and number]
    return max(numbers, default=0) + 1


def field_values(spot: Spot, analysis: Analysis) -> list[types.CompletionItem]:
    if spot.section is None or spot.entry is None:
        return []
    spec = tables.entry_spec(spot.section.name, spot.entry.keyword)
    index = spot.field_path[0] if spot.field_path else 0
    field_spec = spec.field_at(index + 1) if spec is not None else None
    if field_spec is None:
        return []
    if field_spec.name == "Data Type":
        return data_types()
    items = [types.CompletionItem(label=str(choice), kind=types.CompletionItemKind.EnumMember)
             for choice in field_spec.choices]
    families = [_REFERENCE_FAMILIES[kind] for kind in field_spec.alternatives if kind in _REFERENCE_FAMILIES]
    if families:
        items += references(analysis, families)
    return items


def data_types() -> list[types.CompletionItem]:
    """The CIP data type codes (Table C.16 and CIP Vol 1), with their names."""
    return [types.CompletionItem(label=f"0x{t.code:02X}", kind=types.CompletionItemKind.Constant,
                                 detail=t.name, documentation=t.description, filter_text=f"0x{t.code:02X} {t.name}")
            for t in tables.DATA_TYPES if t.code is not None]


def references(analysis: Analysis, families: list[str]) -> list[types.CompletionItem]:
    """The entries of ``families`` this file defines, with their names."""
    device = analysis.device
    items = []
    for keyword in analysis.definitions:
        if tables.split_numbered(keyword)[0] not in families:
            continue
        described = device.parameters.get(keyword) or device.assemblies.get(keyword)
        items.append(types.CompletionItem(label=keyword, kind=types.CompletionItemKind.Reference,
                                          detail=getattr(described, "name", None) or None))
    return items
