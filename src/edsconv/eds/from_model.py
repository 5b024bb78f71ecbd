"""A typed :class:`~edsconv.model.Device` -> the EDS syntax model, in canonical order.

:func:`device_to_eds` writes every field from its typed value by the type its
FieldSpec gives. The spelling of the source is not known (a Device read from
XML has none), so a convention stands in for it (see :func:`render_value`).
Invariant: ``build(parse(write(device_to_eds(d)))) == d``. Sections and entries
come in the order of :mod:`edsconv.eds.canonical`.
"""

from __future__ import annotations

import datetime
import math
from collections.abc import Iterable
from typing import Any

from edsconv import spec_tables as tables
from edsconv.eds.canonical import section_rank
from edsconv.eds.lexicon import scalar_kind
from edsconv.eds.syntax import Comment, EdsFile, Entry, Field, Group, Scalar, Section, String, Unparsed
from edsconv.model import (
    MODULE,
    MODULE_MEMBER_LIST,
    PARAMETER_FIELD_ATTRIBUTES,
    SINGLE_ENTRY_ATTRIBUTES,
    Assembly,
    CommentNote,
    Connection,
    Device,
    GenericEntry,
    Parameter,
    Reference,
    Unreadable,
    parameter_field,
    parameter_field_type,
)
from edsconv.model.values import PathItem, Revision, StringIMember

# ---------------------------------------------------------------------------------------
# Values -> syntax
# ---------------------------------------------------------------------------------------

# Table C.4 backwards; a single quote needs no escape between double quotes.
_NAMED_ESCAPES = {char: sequence for sequence, char in tables.ESCAPE_SEQUENCES.items() if char != "'"}


def needs_unicode(text: str) -> bool:
    """A string must be written ``L"..."`` when it holds a character beyond Latin-1:
    only L strings may use ``\\unnnn`` (Table C.4)."""
    return any(ord(c) > 0xFF for c in text)


def quote(text: str) -> String:
    """An EDS_Char_Array with the Table C.4 escapes: ``\\\\``, ``\\"``, the named control
    escapes, other non-printable or non-ASCII characters as ``\\xnn`` (``\\unnnn``
    beyond Latin-1, which makes the string ``L"..."``). A character beyond the BMP is
    two 16-bit characters of the L string (C.4.1.3.3.1), its UTF-16 surrogate pair
    ``\\uD83D\\uDE00``, which the reader joins again: the text is ASCII (C.4.1.3.2)."""
    unicode = needs_unicode(text)
    out = []
    for char in text:
        code = ord(char)
        if char in _NAMED_ESCAPES:
            out.append(_NAMED_ESCAPES[char])
        elif 0x20 <= code < 0x7F:
            out.append(char)
        elif code <= 0xFF:
            out.append(f"\\x{code:02X}")
        elif code <= 0xFFFF:
            out.append(f"\\u{code:04X}")
        else:
            high, low = divmod(code - 0x10000, 0x400)
            out.append(f"\\u{0xD800 + high:04X}\\u{0xDC00 + low:04X}")
    return String((("L" if unicode else "") + '"' + "".join(out) + '"',))


def path_text(items: Iterable[PathItem]) -> String:
    """An EPATH as ``"20 04 24 01"``, with ``[ParamN]`` and SLOT keywords."""
    return String(('"' + " ".join(str(item) for item in items) + '"',))


def hex_text(value: int, digits: int) -> Scalar:
    return Scalar(f"0x{value:0{digits}X}")


def _fits(text: str, type_name: str, value: float) -> bool:
    from edsconv.model.values import ValueProblem, to_real

    try:
        return to_real(Scalar(text), type_name) == value
    except (ValueProblem, ValueError):
        return False


def real_text(value: float, type_name: str = "LREAL") -> Scalar:
    """A REAL / LREAL value in a notation that reads back to the same float and keeps
    the C.4.1.3.10 digit limits: ``repr`` when it fits, else the shortest scientific
    form; QUIET-NAN and (-)INFINITY for the specials."""
    if math.isnan(value):
        return Scalar("QUIET-NAN")
    if math.isinf(value):
        return Scalar("INFINITY" if value > 0 else "-INFINITY")
    text = repr(float(value))
    if _fits(text, type_name, value):
        return Scalar(text)
    for precision in range(17):
        candidate = f"{value:.{precision}e}"
        if _fits(candidate, type_name, value):
            return Scalar(candidate)
    return Scalar(text)


def _keyword_like(text: str) -> bool:
    return scalar_kind(text) == "WORD"


def plain_value(value: Any, keywords: bool = False):
    """A value kept as plain data (:func:`edsconv.model.build.plain`): a text that reads
    as a number, date, time or ``*`` goes back as a scalar; a keyword as a scalar
    when ``keywords`` (fields typed Keyword), else as a string; lists as groups."""
    if value is None:
        return None
    if isinstance(value, list):
        return Group([Field(plain_value(v, keywords)) for v in value])
    text = str(value)
    kind = scalar_kind(text) if text else None
    if kind and (kind != "WORD" or keywords):
        return Scalar(text)
    return quote(text)


def _bits_digits(type_name: str) -> int | None:
    data_type = tables.DATA_TYPES_BY_NAME.get(type_name)
    if data_type is not None and data_type.kind == "bits" and data_type.size:
        return 2 * data_type.size
    return None


def render_value(value: Any, type_name: str = "", proxy: bool = False):
    """The syntax value (Scalar, String, Group or None) of a typed field value.

    Convention (the XML side carries no spelling): bit strings (BYTE, WORD, DWORD,
    LWORD: descriptors, trigger/transport masks, connection parameters, values of
    bit-string parameters) in hex with the type's digit count; data type codes in
    hex with two digits (``type_name="code"``); every other integer in decimal;
    floats by :func:`real_text`; dates mm-dd-yyyy, times hh:mm:ss, revisions M.m;
    texts quoted (:func:`quote`); paths by :func:`path_text`; references by keyword;
    ``Module`` / ``ModuleMemberList`` of Proxy entries and keyword fields as keywords.
    """
    if value is None:
        return None
    if isinstance(value, Reference):
        return Scalar(value.keyword if value.bit is None else f"{value.keyword}:{value.bit}")
    if isinstance(value, str):
        if proxy and value in (MODULE, MODULE_MEMBER_LIST):
            return Scalar(value)
        if type_name in ("Keyword", "MemberKeyword"):
            return Scalar(value) if _keyword_like(value) else quote(value)
        if type_name in ("plain", "ParamDataType", "Integer", "PortSpecific"):
            return plain_value(value)
        return quote(value)
    if isinstance(value, bool):
        return Scalar(str(int(value)))
    if isinstance(value, int):
        if type_name == "code":
            return hex_text(value, 2) if 0 <= value <= 0xFF else Scalar(str(value))
        digits = _bits_digits(type_name)
        if digits is not None and value >= 0:
            return hex_text(value, digits)
        return Scalar(str(value))
    if isinstance(value, float):
        return real_text(value, type_name if type_name in ("REAL", "LREAL") else "LREAL")
    if isinstance(value, Revision):
        return Scalar(f"{value.major}.{value.minor}")
    if isinstance(value, datetime.date):
        return Scalar(value.strftime("%m-%d-%Y") if value.year >= 1000 else
                      f"{value.month:02d}-{value.day:02d}-{value.year:04d}")
    if isinstance(value, datetime.time):
        return Scalar(value.strftime("%H:%M:%S"))
    if isinstance(value, tuple):
        if value and all(isinstance(m, StringIMember) for m in value):
            return _stringi(value)
        if all(isinstance(item, PathItem) for item in value):
            return path_text(value)
    if isinstance(value, list):
        return plain_value(value)
    raise TypeError(f"cannot render {value!r} as an EDS value")


def _stringi(members: tuple[StringIMember, ...]) -> Group:
    fields = [Field(Scalar(str(len(members))))]
    for member in members:
        fields.append(Field(Group([Field(quote(member.language)), Field(render_value(member.type_code, "code")),
                                   Field(Scalar(str(member.charset))), Field(quote(member.text))])))
    return Group(fields)


def _as_written(value) -> Any:
    if isinstance(value, list):
        return Group([Field(_as_written(v)) for v in value])
    return value


def _entry(keyword: str, values: list, required: int = 0) -> Entry:
    """An entry of syntax values; trailing empty fields beyond ``required`` are dropped
    (the ``;`` convention); an entry keeps at least one field."""
    values = list(values)
    while len(values) > max(required, 1) and values[-1] is None:
        values.pop()
    return Entry(keyword, [Field(v) for v in values] or [Field(None)])


# ---------------------------------------------------------------------------------------
# Device -> syntax model
# ---------------------------------------------------------------------------------------

def _singles(section: str, record) -> list[Entry]:
    attributes = SINGLE_ENTRY_ATTRIBUTES[section]
    entries = []
    for spec in tables.SECTIONS[section].entries:
        attribute = attributes.get(spec.keyword)
        if attribute is None:
            continue
        value = getattr(record, attribute)
        if value is not None:
            entries.append(Entry(spec.keyword, [Field(render_value(value, spec.fields[0].eds_type.split("|")[0]))]))
    return entries


def _param_values(parameter: Parameter, values, proxy: bool) -> list:
    return [render_value(v, parameter.value_type(a), proxy)
            for v, a in zip(values, ("minimum", "maximum", "default"), strict=True)]


def _parameter_entries(parameter: Parameter) -> list[Entry]:
    # C.4.1.5.3.1: any field of a ProxyParam may be Module
    proxy = parameter.family == "ProxyParam"
    fields = [Scalar("0")]  # field 1 is reserved and shall be 0
    for attribute in PARAMETER_FIELD_ATTRIBUTES[1:]:
        type_name = parameter_field_type(attribute) or parameter.value_type(attribute)
        fields.append(render_value(parameter_field(parameter, attribute), type_name, proxy))
    spec = tables.entry_spec("Params", parameter.keyword)
    entries = [_entry(parameter.keyword, fields, spec.required_count if spec else 0)]
    number = parameter.number
    if parameter.size_adder is not None:
        entries.append(_entry(f"ProxyParamSizeAdder{number}", _param_values(parameter, parameter.size_adder, False), 3))
    if parameter.enum is not None:
        family = tables.ENUM_FAMILIES[parameter.family]
        values: list = []
        for key, text in parameter.enum.items():
            values += [render_value(key, parameter.enum_key_type), render_value(text, "EDS_Char_Array")]
        entries.append(Entry(f"{family}{number}", [Field(v) for v in values] or [Field(None)]))
    return entries


def _assembly_entry(assembly: Assembly) -> Entry:
    proxy = assembly.family == "ProxyAssem"
    fixed = [render_value(assembly.name, "EDS_Char_Array", proxy), render_value(assembly.path, "EPATH", proxy),
             render_value(assembly.size, "UINT", proxy), render_value(assembly.descriptor, "WORD", proxy)]
    tail: list = []
    if assembly.module_member_list:
        tail.append(Scalar(MODULE_MEMBER_LIST))
    for member in assembly.members:
        tail += [render_value(member.size, "UINT"), render_value(member.reference, "MemberKeyword", proxy)]
    if not tail:
        return _entry(assembly.keyword, fixed)
    return Entry(assembly.keyword, [Field(v) for v in (*fixed, None, None, *tail)])


def _connection_entry(connection: Connection) -> Entry:
    proxy = connection.family == "ProxyConnect"
    c = connection
    values = [render_value(c.trigger_transport, "DWORD", proxy), render_value(c.parameters, "DWORD", proxy)]
    for endpoint in (c.o_to_t, c.t_to_o):
        values += [render_value(endpoint.rpi, "UDINT", proxy), render_value(endpoint.size, "UINT", proxy),
                   render_value(endpoint.format, "Keyword", proxy)]
    for endpoint in (c.config1, c.config2):
        values += [render_value(endpoint.size, "UINT", proxy), render_value(endpoint.format, "Keyword", proxy)]
    values += [render_value(c.name, "EDS_Char_Array", proxy), render_value(c.help, "EDS_Char_Array", proxy),
               render_value(c.path, "EPATH", proxy)]
    return _entry(c.keyword, values, 15)


def _numbered(items, key=lambda item: item.number):
    return sorted(items, key=lambda item: key(item) or 0)


def _family_sorted(records: dict, families: tuple[str, ...]):
    return sorted(records.values(), key=lambda r: (families.index(r.family) if r.family in families
                                                   else len(families), r.number))


def _known_sections(device: Device) -> dict[str, list[Entry]]:
    out: dict[str, list[Entry]] = {}
    out["File"] = _singles("File", device.file)
    out["Device"] = _singles("Device", device.identity)
    out["Device Classification"] = [
        _entry(f"Class{c.number}", [render_value(c.classification, "Keyword"),
                                    *(plain_value(s, keywords=True) for s in c.subclassifications)])
        for c in _numbered(device.classifications)]
    if device.param_class is not None:
        entries = _singles("ParamClass", device.param_class)
        out["ParamClass"] = entries or [Entry("MaxInst", [Field(None)])]
    out["Params"] = [e for p in _family_sorted(device.parameters, ("Param", "ProxyParam", "ProxiedParam"))
                     for e in _parameter_entries(p)]
    out["Groups"] = [
        _entry(f"Group{g.number}", [render_value(g.name, "EDS_Char_Array"), render_value(g.declared_members, "UINT"),
                                    *(Scalar(str(m.number)) for m in g.members)], 2)
        for g in _numbered(device.groups)]
    assembly = []
    if device.assembly_revision is not None:
        assembly.append(Entry("Revision", [Field(render_value(device.assembly_revision, "UINT"))]))
    assembly += [_assembly_entry(a) for a in
                 _family_sorted(device.assemblies, ("Assem", "ProxyAssem", "ProxiedAssem"))]
    out["Assembly"] = assembly
    out["Connection Manager"] = [_connection_entry(c) for c in _family_sorted(
        device.connections, ("Connection", "ProxyConnect", "ProxiedConnect"))]
    ports = []
    for port in _numbered(device.ports):
        fixed = [render_value(port.type_name, "Keyword"), render_value(port.name, "EDS_Char_Array"),
                 render_value(port.object_path, "EPATH"), render_value(port.port_number, "UINT")]
        specific = [plain_value(v, keywords=True) for v in port.specific]
        ports.append(Entry(f"Port{port.number}", [Field(v) for v in (*fixed, None, None, *specific)])
                     if specific else _entry(f"Port{port.number}", fixed, 4))
    out["Port"] = ports
    modular = device.modular
    if modular is not None:
        entries = _singles("Modular", modular)
        racks = [_entry(f"Rack{r.number}", [*(render_value(v, "UINT") for v in r.key), None, None, None,
                                             *(render_value(s, "UINT") for s in r.legal_slots)], 5)
                 for r in _numbered(modular.racks)]
        entries[_rack_position(entries):_rack_position(entries)] = racks
        if modular.query is not None:
            q = modular.query
            entries.append(_entry("Query", [render_value(q.path, "EPATH"), render_value(q.service, "USINT"),
                                            render_value(q.id_size, "USINT"),
                                            render_value(q.empty_slot_id, "EPATH")], 4))
        out["Modular"] = entries or [Entry("Width", [Field(None)])]
    return out


def _rack_position(entries: list[Entry]) -> int:
    before = ("DefineSlotsInRack", "SlotDisplayRule", "Width")
    return sum(1 for e in entries if e.keyword in before)


def _generic_entry(entry: GenericEntry) -> Entry:
    return Entry(entry.keyword, [Field(_as_written(v)) for v in entry.values] or [Field(None)])


def device_to_eds(device: Device) -> EdsFile:
    """The syntax model of ``device`` in canonical order, values rendered by
    :func:`render_value`, comments (``device.comments``) re-attached."""
    eds = EdsFile()
    known = _known_sections(device)
    for name in tables.SECTIONS:
        entries = known.get(name, []) + [_generic_entry(e) for e in device.extra_entries.get(name, ())]
        if entries:
            eds.sections.append(Section(name, entries))
    others = sorted(device.other_sections, key=lambda s: section_rank(s.name))
    eds.sections += [Section(s.name, [_generic_entry(e) for e in s.entries]) for s in others]
    if any(ord(c) > 0x7F for note in device.comments for c in note.text):
        eds.encoding = "utf-8"
    attach_comments(eds, device.comments)
    restore_unreadable(eds, device.unreadable)
    return eds


def restore_unreadable(eds: EdsFile, unreadable: Iterable[Unreadable]) -> None:
    """Write back, as spelt, each text the model had no reading for: a field into its entry (made when
    the model wrote none), a statement before the entry it stood before (docs/mapping.md)."""
    for item in unreadable:
        section = eds.section(item.section)
        if section is None:
            section = Section(item.section, [])
            eds.sections.append(section)
        if item.keyword is None:
            following = section.entry(item.before) if item.before is not None else None
            index = section.entries.index(following) if following is not None else len(section.entries)
            section.unparsed.append((index, Unparsed(item.text, [Comment(text) for text in item.comments])))
            section.unparsed.sort(key=lambda placed: placed[0])
            continue
        entry = section.entry(item.keyword)
        if entry is None:
            entry = Entry(item.keyword, [])
            section.entries.append(entry)
        index = item.field or 0
        while len(entry.fields) <= index:
            entry.fields.append(Field(None))
        entry.fields[index].value = Scalar(item.text)


#: A comment on a field beyond the entry's last is on a trailing empty field the writer dropped: at most
#: this many (no entry of the tables has as many fields), so a profile cannot make an entry of millions
#: of empty fields with one comment (found by fuzzing xml2eds).
MAX_DROPPED_FIELDS = 256


def attach_comments(eds: EdsFile, notes: Iterable[CommentNote]) -> None:
    """Put each CommentNote back on its section / entry / field. A note on a trailing
    empty field the entry dropped brings that field back (empty), so the comment stays
    with the field it describes; one whose entry is gone goes to its section's leading
    comments; one whose section is gone to the end of the file."""
    sections: dict[str, Section] = {}
    entries: dict[tuple[str, str], Entry] = {}
    for each_section in eds.sections:
        sections.setdefault(each_section.name, each_section)
        for each_entry in each_section.entries:
            entries.setdefault((each_section.name, each_entry.keyword), each_entry)
    for note in notes:
        comment = Comment(note.text)
        section = sections.get(note.section)
        if section is None:
            eds.trailing_comments.append(comment)
        elif note.keyword is None:
            (section.leading_comments if note.leading else section.comments).append(comment)
        elif (entry := entries.get((note.section, note.keyword))) is None:
            section.leading_comments.append(comment)
        elif note.leading:
            entry.leading_comments.append(comment)
        elif note.field is None or note.field - len(entry.fields) >= MAX_DROPPED_FIELDS:  # too far: the entry's
            entry.comments.append(comment)
        else:
            entry.fields.extend(Field(None) for _ in range(note.field + 1 - len(entry.fields)))
            entry.fields[note.field].comments.append(comment)


__all__ = ["attach_comments", "device_to_eds", "hex_text", "needs_unicode", "path_text", "plain_value", "quote",
           "real_text", "render_value"]
