"""Hover: what the spec says a section, entry or field is, what a reference points to, and what
the bits of a bit-field value mean, in Markdown.

The words come from the tables the linter checks against (the 2003 tables of
:mod:`edsconv.spec_tables`, then the newer CIP tables of :mod:`edsconv.cip_tables`:
[Capacity], [TCP/IP Interface Class], the object class sections and the newer
entries of 2003 sections, with their source) and from the descriptions
``edsconv show`` prints (:mod:`edsconv.describe`), so the editor and the command
line say the same thing. Comment text has no hover.
"""

from __future__ import annotations

from typing import Any

from edsconv import cip_tables, describe
from edsconv import spec_tables as tables
from edsconv.eds.locate import Spot, locate, value_end
from edsconv.eds.syntax import Entry, Field, Section, String
from edsconv.lsp.analysis import Analysis
from edsconv.model import Assembly, Connection, Device, GenericEntry, Parameter
from edsconv.model.epath import decode_path
from edsconv.model.plain import plain
from edsconv.model.references import occurrence_at
from edsconv.model.values import ValueProblem, to_integer, to_path

#: (line, column, end_line, end_column), 1-based, end exclusive
Span = tuple[int, int, int, int]


def section_spec(name: str) -> tables.SectionSpec | None:
    """The table of a section: the 2003 text's, else the newer CIP tables' (as the linter reads them)."""
    return tables.section_spec(name) or cip_tables.section_spec(name)


def entry_spec(section: str, keyword: str) -> tables.EntrySpec | None:
    """The spec of an entry of ``section``: the 2003 text's, else the newer CIP tables'."""
    return tables.entry_spec(section, keyword) or cip_tables.entry_spec(section, keyword)


def text_at(line_text: str, column: int) -> str | None:
    """"comment" when ``column`` (1-based) lies in a ``$`` comment, "string" when inside a quoted
    string (C.4.1.2.2.5: ``\\`` escapes the next character), else None."""
    in_string = escaped = False
    for character in line_text[:column - 1]:
        if in_string:
            in_string = escaped or character != '"'
            escaped = not escaped and character == "\\"
        elif character == '"':
            in_string = True
        elif character == "$":
            return "comment"
    return "string" if in_string else None


def hover(analysis: Analysis, line: int, column: int) -> tuple[str, Span] | None:
    """The Markdown shown for ``line``:``column`` and the span it is about; None where there is nothing to say."""
    if text_at(analysis.line_text(line), column + 1) == "comment":
        return None
    spot = locate(analysis.eds, line, column)
    parts: list[str] = []
    span: Span | None = None
    reference = occurrence_at(analysis.spans, line, column)
    if reference is not None and reference.kind != "definition":
        parts.append(target_text(analysis.device, reference.target))
        span = (reference.line, reference.column, reference.line, reference.end_column)
    if spot.on_header and spot.section is not None:
        parts.append(section_text(spot.section))
        span = span or (spot.section.line, spot.section.column, spot.section.line,
                        spot.section.column + len(spot.section.name) + 2)
    elif spot.on_keyword and spot.entry is not None:
        parts.append(entry_text(spot.section, spot.entry))
        if spot.entry.keyword in analysis.definitions:
            parts.append(target_text(analysis.device, spot.entry.keyword))
        span = span or (spot.entry.line, spot.entry.column, spot.entry.line,
                        spot.entry.column + len(spot.entry.keyword))
    elif spot.field is not None and spot.field.value is not None:
        parts.append(field_text(spot, analysis.device))
        start_line, start_column = spot.field.line, spot.field.column
        span = span or (start_line, start_column, start_line,
                        value_end(analysis.line_text(start_line), start_column))
    parts = [part for part in parts if part]
    return ("\n\n---\n\n".join(parts), span) if parts and span else None


def plain_text(markdown: str) -> str:
    """The hover text for a client that shows plain text only (eglot without markdown-mode): no
    emphasis, no code marks, a blank line between the parts instead of a rule."""
    return markdown.replace("\n\n---\n\n", "\n\n").replace("**", "").replace("`", "")


# --- the spec ------------------------------------------------------------------------------


def _source(provenance: tables.Provenance) -> str:
    """Where a fact beyond the 2003 text comes from, in a few words."""
    sources = [f"eds-pie `{provenance.eds_pie}`"] if provenance.eds_pie else []
    if provenance.files:
        sources.append(f"{provenance.files} of {cip_tables.CORPUS.split('(')[-1].rstrip(')')}")
    return "not in ISO 15745-4:2003; a later CIP edition, as " + " and ".join(sources or ["real files write it"])


def section_text(section: Section) -> str:
    spec = section_spec(section.name)
    if spec is None:
        return f"**[{section.name}]**: not a section of ISO 15745-4:2003 or the newer CIP tables; kept as written."
    if spec.provenance is not None:
        lines = [f"**[{section.name}]** {spec.title}: {spec.presence} ({_source(spec.provenance)})"]
        if spec.class_id is not None:
            lines.append(f"Describes CIP object class 0x{spec.class_id:02X}.")
    else:
        lines = [f"**[{section.name}]** {spec.title} ({spec.clause}): {spec.presence}"]
    enip = spec.network_presence.get(tables.ETHERNETIP)
    if enip is not None and enip is not spec.presence:
        lines[0] += f"; for EtherNet/IP (Table C.27) {enip}"
    if spec.note:
        lines.append(spec.note)
    if spec.entries:
        lines.append("Entries: " + ", ".join(f"`{e.keyword}{'N' if e.numbered else ''}`" for e in spec.entries))
    return "\n\n".join(lines)


def entry_text(section: Section | None, entry: Entry) -> str:
    spec = entry_spec(section.name, entry.keyword) if section is not None else None
    if spec is None:
        vendor = " (a vendor-specific keyword)" if tables.is_vendor_keyword(entry.keyword) else ""
        return (f"**{entry.keyword}**{vendor}: not an entry of this section in ISO 15745-4:2003 or the newer "
                "CIP tables; kept as written.")
    family = f"{spec.keyword}N" if spec.numbered else spec.keyword
    table = f", Table {spec.table}" if spec.table else ""
    source = _source(spec.provenance) if spec.provenance is not None else f"{spec.clause}{table}"
    text = f"**{family}** ({source}): {spec.description}. {str(spec.presence).capitalize()}."
    if spec.pairs_with:
        text += f" Belongs to `{spec.pairs_with}N` of the same number."
    if spec.sequential:
        text += " Numbers start at 1 and go up by one."
    return text


def field_text(spot: Spot, device: Device) -> str:
    entry, item, index = spot.entry, spot.field, spot.field_path[0]
    if entry is None or item is None:
        return ""
    spec = entry_spec(spot.section.name, entry.keyword) if spot.section is not None else None
    field_spec = spec.field_at(index + 1) if spec is not None else None
    if field_spec is None:
        return f"{entry.keyword} field {index + 1}: not a field the spec defines for this entry."
    lines = [f"**{entry.keyword} field {index + 1}: {field_spec.name}** ({_type_words(field_spec.eds_type)}), "
             f"{field_spec.presence}" + (f"; Table {field_spec.table}" if field_spec.table else "")
             + f" ({_source(field_spec.provenance) if field_spec.provenance else field_spec.clause})"]
    if field_spec.note:
        lines.append(field_spec.note)
    if field_spec.choices:
        lines.append("Allowed: " + ", ".join(f"`{choice}`" for choice in field_spec.choices))
    lines.append(_range_text(field_spec))
    if field_spec.name == "Data Type":
        lines.append(_data_type_text(item))
    if field_spec.bits and len(spot.field_path) == 1:
        lines.extend(bits_text(field_spec.bits, item, device.connections.get(entry.keyword)))
    if "EPATH" in field_spec.alternatives and isinstance(item.value, String):
        lines.append(_path_text(item.value, device))
    return "\n\n".join(line for line in lines if line)


def _range_text(field_spec: tables.FieldSpec) -> str:
    """The field's own range, else the range of its data type when it has only one."""
    if field_spec.value_range:
        return f"Range: {field_spec.value_range[0]} .. {field_spec.value_range[1]}"
    data_type = tables.DATA_TYPES_BY_NAME.get(field_spec.eds_type)
    if data_type is None or data_type.minimum is None or data_type.kind == "real":
        return ""
    return f"Range: {data_type.minimum} .. {data_type.maximum} ({data_type.name})"


def _type_words(eds_type: str) -> str:
    return " or ".join(kind.removesuffix("Ref") + "N" if kind.endswith("Ref") else kind
                       for kind in eds_type.split("|"))


def _path_text(value: String, device: Device) -> str:
    """A path segment by segment, as ``edsconv show`` decodes it."""
    try:
        decoded = decode_path(to_path(value, allow_references=True), device)
    except ValueProblem:
        return ""
    return f"Path: {decoded['summary']}" if decoded and decoded["summary"] else ""


def data_type_of(item: Field) -> tuple[int, tables.DataType | None] | None:
    """The code a Data Type field holds and the type it names (Table C.16, obsolete codes included);
    None when the field holds no USINT."""
    try:
        code = to_integer(item.value, "USINT")
    except ValueProblem:
        return None
    return code, tables.DATA_TYPES_BY_CODE.get(code) or tables.OBSOLETE_DATA_TYPE_IDS.get(code)


def _data_type_text(item: Field) -> str:
    found = data_type_of(item)
    if found is None:
        return ""
    code, data_type = found
    if data_type is None:
        return f"`{item.raw}` is not a CIP data type code."
    obsolete = " (obsolete Table C.16 identifier)" if data_type.code != code else ""
    return f"`{item.raw}`{obsolete}: **{data_type.name}**, {data_type.description}"


# --- bit fields ----------------------------------------------------------------------------


def bits_text(table_name: str, item: Field, connection: Connection | None) -> list[str]:
    """The decoded bits of a descriptor or connection mask: as ``edsconv show`` prints them for the
    connection masks, as the spec's table lists them for the descriptors."""
    table = tables.BIT_TABLES[table_name]
    try:
        value = to_integer(item.value, "WORD" if table.width == 16 else "DWORD")
    except ValueProblem:
        return []
    if connection is not None and table is tables.TRIGGER_TRANSPORT_BITS:
        doc = describe.describe_trigger_transport(connection)
        return [_trigger_transport_text(doc)] if doc is not None else []
    if connection is not None and table is tables.CONNECTION_PARAMETER_BITS:
        doc = describe.describe_connection_parameters(connection)
        return [_connection_parameters_text(doc)] if doc is not None else []
    rows = [f"- bit {f.first_bit}: {f.name}: {meaning}" if f.width == 1 else
            f"- bits {f.first_bit}-{f.first_bit + f.width - 1}: {f.name}: {meaning}"
            for f, bits, meaning in tables.decode_bits(value, table) if bits or f.width > 1]
    return [f"{table.name} (Table {table.table}) `0x{value:0{table.width // 4}X}`:", "\n".join(rows) or "no bit set"]


def _trigger_transport_text(doc: dict[str, Any]) -> str:
    lines = [f"Trigger and transport `{doc['value']}`:",
             f"- class: {', '.join(doc['class_names']) or 'none'}",
             f"- trigger: {', '.join(doc['triggers']) or 'none'}",
             f"- transport type: {', '.join(doc['transport']) or 'none'}",
             f"- role: {doc['role']}"]
    if doc["reserved_bits"]:
        lines.append(f"- reserved bits set: {doc['reserved_bits']}")
    return "\n".join(lines)


def _connection_parameters_text(doc: dict[str, Any]) -> str:
    lines = [f"Connection parameters `{doc['value']}`:"]
    for direction in ("O=>T", "T=>O"):
        d = doc[direction]
        sizes = [s for s, on in (("fixed", d["fixed_size"]), ("variable", d["variable_size"])) if on]
        lines += [f"- {direction} size type: {' and '.join(sizes) or 'none'}",
                  f"- {direction} real-time format: {d['real_time_format']}",
                  f"- {direction} connection type: {', '.join(d['connection_types']) or 'none'}",
                  f"- {direction} priority: {', '.join(d['priorities']) or 'none'}"]
    if doc["reserved_bits"]:
        lines.append(f"- reserved bits set: {doc['reserved_bits']}")
    return "\n".join(lines)


# --- what a reference names ----------------------------------------------------------------


def target_text(device: Device, keyword: str) -> str:
    """A summary of the entry ``keyword`` names, from ``edsconv show``'s descriptions."""
    target = device.resolve(keyword)
    if isinstance(target, Parameter):
        return _parameter_text(describe.describe_parameter(target))
    if isinstance(target, Assembly):
        return _assembly_text(describe.describe_assembly(target, device))
    if isinstance(target, Connection):
        name = f" '{target.name}'" if target.name else ""
        return f"**{keyword}**{name}: a connection"
    if isinstance(target, GenericEntry):
        return f"**{keyword}**: {plain(target.values)}"
    return f"**{keyword}** is not defined in this file."


def _parameter_text(doc: dict[str, Any]) -> str:
    data_type = doc["data_type"]
    type_text = data_type["name"] or f"? ({data_type['written']})"
    if data_type["code"] is not None:
        type_text += f" 0x{data_type['code']:02X}"
    lines = [f"**{doc['keyword']}** '{doc['name'] or ''}': {type_text}"
             + (f", {doc['size']} B" if doc["size"] is not None else ""),
             f"- range: {_text(doc['minimum'])} .. {_text(doc['maximum'])}",
             f"- default: {_text(doc['default'])} {doc['units'] or ''}".rstrip()]
    if doc.get("engineering"):
        e = doc["engineering"]
        lines.append(f"- scaled: {_text(e['minimum'])} .. {_text(e['maximum'])}, default {_text(e['default'])}")
    lines += [f"- {e['value']} = {e['text']}" for e in doc["enum"]]
    if doc["flags"]:
        lines.append("- flags: " + ", ".join(doc["flags"]))
    if doc["help"]:
        lines.append(f"\n{doc['help']}")
    return "\n".join(lines)


def _assembly_text(doc: dict[str, Any]) -> str:
    size = f", {doc['size']} bytes" if doc["size"] is not None else ""
    lines = [f"**{doc['keyword']}** '{doc['name'] or ''}'{size}"]
    if doc["path"]:
        lines.append(f"- path {doc['path']['text']} ({doc['path']['summary']})")
    for member in doc["members"]:
        offset, bits = member["offset"], member["bits"]
        where = "?" if offset is None or bits is None else f"{offset}" if bits <= 1 else f"{offset}-{offset + bits - 1}"
        lines.append(f"- bits {where}: {_member_text(member['member'])}")
    if doc["module_member_list"]:
        lines.append("- the members of the module (ModuleMemberList)")
    if doc["total_bits"] is not None:
        lines.append(f"- total: {doc['total_bits']} bits")
    return "\n".join(lines)


def _member_text(member: dict[str, Any]) -> str:
    kind = member["kind"]
    if kind == "pad":
        return "(pad)"
    if kind == "constant":
        return f"constant {member['value']}"
    if kind == "path":
        return f"path {member['path']['text']}"
    name = f" '{member['name']}'" if member.get("name") else ""
    return f"{member.get('keyword', '')}{name}"


def _text(value: Any) -> str:
    if value is None:
        return ""
    return f"{value:g}" if isinstance(value, float) else str(value)

