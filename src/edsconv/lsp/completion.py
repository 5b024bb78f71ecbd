"""Completion from the tables the linter checks against (the 2003 tables, then the newer CIP tables:
[Capacity], the object class sections, newer entries of 2003 sections) and the file itself: section
names, the keywords a section allows (numbered families with their next free number), data type
codes with their names, the choices a field allows, references to the entries the file defines, and
``ParamN``/``ProxyParamN`` after ``[`` in a path (C.4.1.4.9.13). Nothing inside a ``$`` comment, nor
inside another string."""

from __future__ import annotations

from lsprotocol import types

from edsconv import cip_tables
from edsconv import spec_tables as tables
from edsconv.eds.locate import Spot, locate
from edsconv.eds.syntax import Section
from edsconv.lsp.analysis import Analysis
from edsconv.lsp.hover import entry_spec, text_at

#: FIELD_VALUE_KINDS reference kind -> the family of the entries it names
_REFERENCE_FAMILIES = {"ParamRef": "Param", "ProxyParamRef": "ProxyParam", "AssemRef": "Assem",
                       "ProxyAssemRef": "ProxyAssem"}


def completions(analysis: Analysis, line: int, column: int) -> list[types.CompletionItem]:
    """What may be written at ``line``:``column``."""
    text = analysis.line_text(line)
    before = text[:column - 1]
    inside = text_at(text, column)
    if inside == "comment":
        return []
    if inside is None and before.lstrip().startswith("[") and "=" not in before:
        return section_names(analysis)
    spot = locate(analysis.eds, line, column)
    if inside == "string":
        return path_references(spot, analysis, before)
    if spot.section is None:
        return section_names(analysis)
    if spot.entry is None or spot.on_keyword:
        return entry_keywords(spot.section)
    return field_values(spot, analysis)


def section_names(analysis: Analysis) -> list[types.CompletionItem]:
    """The sections not in the file yet: the 2003 ones in Table C.3 order, then the newer CIP ones."""
    present = {section.name for section in analysis.eds.sections}
    specs = [*tables.SECTIONS.values(), *cip_tables.CIP_SECTIONS.values()]
    return [types.CompletionItem(label=spec.name, kind=types.CompletionItemKind.Module, detail=spec.title,
                                 documentation=f"{spec.clause}: {spec.presence}", sort_text=f"{rank:03}")
            for rank, spec in enumerate(specs) if spec.name not in present]


def entry_keywords(section: Section) -> list[types.CompletionItem]:
    """The keywords of the section's table not written yet (2003, then newer CIP entries); numbered
    families with their next free number."""
    specs = [spec for spec in (tables.section_spec(section.name), cip_tables.section_spec(section.name)) if spec]
    present = {entry.keyword for entry in section.entries}
    items = []
    for rank, spec in enumerate(spec for table in specs for spec in table.entries):
        if spec.numbered:
            keyword = f"{spec.keyword}{next_number(section, spec.keyword)}"
        elif spec.keyword in present:
            continue
        else:
            keyword = spec.keyword
        items.append(types.CompletionItem(
            label=keyword, kind=types.CompletionItemKind.Keyword, detail=spec.description,
            documentation=f"{spec.clause}: {spec.presence}", insert_text=f"{keyword} = ",
            sort_text=f"{rank:03}"))
    return items


def path_references(spot: Spot, analysis: Analysis, before: str) -> list[types.CompletionItem]:
    """Inside a string: after ``[`` in a path field (C.4.1.4.9.13: a ParamN or ProxyParamN in brackets
    holds its value for this path alone), the parameters; nothing anywhere else in a string."""
    if spot.section is None or spot.entry is None or not spot.field_path:
        return []
    spec = entry_spec(spot.section.name, spot.entry.keyword)
    field_spec = spec.field_at(spot.field_path[0] + 1) if spec is not None else None
    opened = before.rfind("[") > max(before.rfind("]"), before.rfind('"'))
    if field_spec is None or "EPATH" not in field_spec.alternatives or not opened:
        return []
    return references(analysis, ["Param", "ProxyParam"])


def next_number(section: Section, family: str) -> int:
    """One more than the highest number of ``family`` in ``section`` (1 for the first)."""
    numbers = [number for entry in section.entries
               for prefix, number in [tables.split_numbered(entry.keyword)] if prefix == family and number]
    return max(numbers, default=0) + 1


def field_values(spot: Spot, analysis: Analysis) -> list[types.CompletionItem]:
    if spot.section is None or spot.entry is None:
        return []
    spec = entry_spec(spot.section.name, spot.entry.keyword)
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
