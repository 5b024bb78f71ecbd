"""Inlay hints: what the text leaves implicit, written after it in the editor.

- after a reference to a parameter or assembly (assembly members, connection sizes and formats,
  path substitutions, group members): the name of the entry it names;
- after a data type code (``0xC8``): the type's name (Table C.16, via the spec tables);
- after a descriptor, trigger/transport or connection-parameter mask: the bits it sets, in the
  words ``edsconv show`` uses (:mod:`edsconv.describe`).
"""

from __future__ import annotations

from collections.abc import Iterator

from lsprotocol import types

from edsconv import describe
from edsconv import spec_tables as tables
from edsconv.eds.locate import value_end
from edsconv.eds.syntax import Entry, Field
from edsconv.lsp.analysis import Analysis
from edsconv.lsp.hover import data_type_of
from edsconv.lsp.positions import Positions
from edsconv.model.values import ValueProblem, to_integer

#: Hints longer than this are cut: a hint annotates, the hover explains.
MAX_LENGTH = 48
#: Occurrence kinds whose target's name is worth a hint (a definition names itself).
_NAMED_KINDS = frozenset({"assembly member", "connection", "path", "group member", "reference", "slot display rule"})

#: (line, column, label, kind), 1-based; the hint stands at line:column
Hint = tuple[int, int, str, types.InlayHintKind]


def inlay_hints(analysis: Analysis, positions: Positions, first_line: int, last_line: int) -> list[types.InlayHint]:
    """The hints on lines ``first_line``..``last_line`` (1-based, inclusive), in text order."""
    hints = [*_reference_hints(analysis, first_line, last_line), *_field_hints(analysis, first_line, last_line)]
    hints.sort(key=lambda hint: hint[:2])
    return [types.InlayHint(position=positions.to_client(line, column), label=_cut(label), kind=kind,
                            padding_left=True) for line, column, label, kind in hints]


def _cut(label: str) -> str:
    return label if len(label) <= MAX_LENGTH else label[:MAX_LENGTH - 1] + "…"


def _reference_hints(analysis: Analysis, first_line: int, last_line: int) -> Iterator[Hint]:
    device = analysis.device
    for occurrence in analysis.spans:
        if occurrence.kind not in _NAMED_KINDS or not first_line <= occurrence.line <= last_line:
            continue
        target = device.resolve(occurrence.target)
        name = getattr(target, "name", None)
        if name:
            yield occurrence.line, occurrence.end_column, f"'{name}'", types.InlayHintKind.Parameter


def _field_hints(analysis: Analysis, first_line: int, last_line: int) -> Iterator[Hint]:
    for section in analysis.eds.sections:
        for entry in section.entries:
            if entry.end_line < first_line or entry.line > last_line:
                continue
            spec = tables.entry_spec(section.name, entry.keyword)
            if spec is None:
                continue
            for index, item in enumerate(entry.fields):
                field_spec = spec.field_at(index + 1)
                if field_spec is None or item.value is None or not first_line <= item.line <= last_line:
                    continue
                label = _field_label(analysis, entry, field_spec, item)
                if label:
                    yield item.line, value_end(analysis.line_text(item.line), item.column), label, \
                        types.InlayHintKind.Type


def _field_label(analysis: Analysis, entry: Entry, field_spec: tables.FieldSpec, item: Field) -> str:
    if field_spec.name == "Data Type":
        return _data_type_name(item)
    if field_spec.bits:
        return _bits_label(analysis, entry, field_spec.bits, item)
    return ""


def _data_type_name(item: Field) -> str:
    found = data_type_of(item)
    return found[1].name if found is not None and found[1] is not None else ""


def _bits_label(analysis: Analysis, entry: Entry, table_name: str, item: Field) -> str:
    table = tables.BIT_TABLES[table_name]
    try:
        value = to_integer(item.value, "WORD" if table.width == 16 else "DWORD")
    except ValueProblem:
        return ""
    connection = analysis.device.connections.get(entry.keyword)
    if connection is not None and table is tables.TRIGGER_TRANSPORT_BITS:
        return _trigger_transport_label(describe.describe_trigger_transport(connection))
    if connection is not None and table is tables.CONNECTION_PARAMETER_BITS:
        return _connection_parameters_label(describe.describe_connection_parameters(connection))
    return ", ".join(tables.flags_set(value, table))


def _trigger_transport_label(doc: dict | None) -> str:
    if not doc or "class_names" not in doc:
        return ""
    words = [*(f"class {c}" for c in doc["classes"]), *doc["triggers"], *doc["transport"]]
    return ", ".join(words) or "no bit set"


def _connection_parameters_label(doc: dict | None) -> str:
    if not doc or "O=>T" not in doc:
        return ""
    return "; ".join(f"{direction} {'/'.join(doc[direction]['connection_types']) or '-'}"
                     for direction in ("O=>T", "T=>O"))
