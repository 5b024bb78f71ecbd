"""Signature help inside an entry: the fields the spec defines for it, in order, with the one the
cursor is in marked; its name, type and clause as the documentation.

The field under the cursor is counted in the text from the entry's keyword to the cursor (commas
outside strings, comments and brace groups), so it is right while an entry is being typed and not
yet ended by its ``;``.
"""

from __future__ import annotations

from lsprotocol import types

from edsconv import spec_tables as tables
from edsconv.eds.locate import locate
from edsconv.lsp.analysis import Analysis
from edsconv.lsp.semantic_tokens import token_pattern

#: How many times a repeating tail (assembly members, enum pairs ...) is shown in the label.
_TAIL_SHOWN = 1


def signature_help(analysis: Analysis, line: int, column: int) -> types.SignatureHelp | None:
    spot = locate(analysis.eds, line, column)
    if spot.section is None or spot.entry is None or spot.on_keyword:
        return None
    spec = tables.entry_spec(spot.section.name, spot.entry.keyword)
    if spec is None or not spec.fields:
        return None
    position = _field_position(analysis, (spot.entry.line, spot.entry.column), (line, column))
    if position is None:
        return None
    label, parameters = _label(spot.entry.keyword, spec)
    return types.SignatureHelp(
        signatures=[types.SignatureInformation(label=label, parameters=parameters,
                                               documentation=_entry_documentation(spec))],
        active_signature=0, active_parameter=_parameter_index(spec, position))


def _field_position(analysis: Analysis, start: tuple[int, int], cursor: tuple[int, int]) -> int | None:
    """The 1-based top-level field at ``cursor``; None before the ``=`` or within a brace group."""
    offsets = _line_offsets(analysis.lines)
    begin = offsets[start[0] - 1] + start[1] - 1
    end = offsets[cursor[0] - 1] + cursor[1] - 1
    depth, commas, seen_equals = 0, 0, False
    for match in token_pattern().finditer(analysis.text, begin, end):
        if match.lastgroup != "punct":
            continue
        mark = match.group()
        if mark == "=":
            seen_equals = True
        elif mark == "{":
            depth += 1
        elif mark == "}":
            depth -= 1
        elif mark == "," and depth == 0:
            commas += 1
    return commas + 1 if seen_equals and depth == 0 else None


def _line_offsets(lines: tuple[str, ...]) -> list[int]:
    offsets, total = [], 0
    for text in lines:
        offsets.append(total)
        total += len(text)
    offsets.append(total)
    return offsets


def _shown_fields(spec: tables.EntrySpec) -> tuple[tables.FieldSpec, ...]:
    return spec.fields if not spec.repeating else (*spec.fields[:len(spec.fields) - len(spec.repeating)],
                                                  *spec.repeating * _TAIL_SHOWN)


def _label(keyword: str, spec: tables.EntrySpec) -> tuple[str, list[types.ParameterInformation]]:
    label = f"{keyword} = "
    parameters = []
    for index, field_spec in enumerate(_shown_fields(spec)):
        if index:
            label += ", "
        parameters.append(types.ParameterInformation(
            label=(len(label), len(label) + len(field_spec.name)), documentation=_field_documentation(field_spec)))
        label += field_spec.name
    return label + (", ...;" if spec.repeating else ";"), parameters


def _parameter_index(spec: tables.EntrySpec, position: int) -> int:
    """The index in the label of the field at 1-based ``position``, following a repeating tail."""
    fixed = len(spec.fields) - len(spec.repeating)
    if position <= fixed or not spec.repeating:
        return min(position, len(spec.fields)) - 1
    return fixed + (position - 1 - fixed) % len(spec.repeating)


def _field_documentation(field_spec: tables.FieldSpec) -> types.MarkupContent:
    kinds = " or ".join(field_spec.alternatives)
    table = f", Table {field_spec.table}" if field_spec.table else ""
    text = f"field {field_spec.number}: {field_spec.name} ({kinds}), {field_spec.presence} ({field_spec.clause}{table})"
    if field_spec.note:
        text += f"\n\n{field_spec.note}"
    if field_spec.choices:
        text += "\n\nAllowed: " + ", ".join(str(choice) for choice in field_spec.choices)
    return types.MarkupContent(types.MarkupKind.PlainText, text)


def _entry_documentation(spec: tables.EntrySpec) -> types.MarkupContent:
    table = f", Table {spec.table}" if spec.table else ""
    return types.MarkupContent(types.MarkupKind.PlainText, f"{spec.description} ({spec.clause}{table})")
