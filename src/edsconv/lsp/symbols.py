"""Document symbols for the outline: sections, and in each its entries, named after what they
describe (a parameter's, assembly's or connection's name)."""

from __future__ import annotations

from lsprotocol import types

from edsconv import spec_tables as tables
from edsconv.eds.syntax import Entry, Section
from edsconv.lsp.analysis import Analysis
from edsconv.lsp.positions import Positions

_KIND_BY_FAMILY = {"Param": types.SymbolKind.Variable, "ProxyParam": types.SymbolKind.Variable,
                   "ProxiedParam": types.SymbolKind.Variable, "Assem": types.SymbolKind.Struct,
                   "ProxyAssem": types.SymbolKind.Struct, "ProxiedAssem": types.SymbolKind.Struct,
                   "Connection": types.SymbolKind.Event, "ProxyConnect": types.SymbolKind.Event,
                   "ProxiedConnect": types.SymbolKind.Event, "Enum": types.SymbolKind.Enum}


def document_symbols(analysis: Analysis, positions: Positions) -> list[types.DocumentSymbol]:
    return [_section_symbol(section, analysis, positions) for section in analysis.eds.sections]


def _section_symbol(section: Section, analysis: Analysis, positions: Positions) -> types.DocumentSymbol:
    header = positions.range(section.line, section.column, section.line, section.column + len(section.name) + 2)
    end = header.end
    if section.entries:
        last = section.entries[-1]
        end = positions.to_client(last.end_line, last.end_column)
    return types.DocumentSymbol(
        name=f"[{section.name}]", kind=types.SymbolKind.Namespace, range=types.Range(header.start, end),
        selection_range=header, children=[_entry_symbol(entry, analysis, positions) for entry in section.entries])


def _entry_symbol(entry: Entry, analysis: Analysis, positions: Positions) -> types.DocumentSymbol:
    device = analysis.device
    described = device.parameters.get(entry.keyword) or device.assemblies.get(entry.keyword) or \
        device.connections.get(entry.keyword)
    name = getattr(described, "name", None) if described is not None and described.entry is entry else None
    return types.DocumentSymbol(
        name=entry.keyword, detail=name or None,
        kind=_KIND_BY_FAMILY.get(tables.split_numbered(entry.keyword)[0], types.SymbolKind.Field),
        range=positions.range(entry.line, entry.column, entry.end_line, entry.end_column),
        selection_range=positions.range(entry.line, entry.column, entry.line, entry.column + len(entry.keyword)))
