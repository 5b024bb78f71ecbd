"""Canonical EDS: one order and one layout for every file.

Two entry points:

- :func:`device_to_eds` renders a semantic :class:`~edsconv.model.Device` as a
  syntax model in canonical form. Every field is written from its typed value
  by the type its FieldSpec gives (the spelling of the source is not known, so
  a convention stands in for it, see :func:`render_value`). Invariant:
  ``build(parse(write(device_to_eds(d)))) == d``.
- :func:`canonical` reorders a syntax model (sections and entries in spec order)
  without touching its values or comments; :func:`write_canonical` lays it out
  as text. This is what ``edsconv fmt`` does.

Order (Table C.3): [File], [Device], [Device Classification], [ParamClass],
[Params], [Groups], [Assembly], [Connection Manager], [Port], [Modular], then
sections the 2003 text does not define in file order, vendor sections
(``[<VendorID>_<name>]``) last. Within a section the entries follow the order of
the section's EntrySpecs; a numbered family brings its paired families along
by number (Param1, Enum1, Param2, Enum2 ..., then ProxyParam1,
ProxyParamSizeAdder1, ProxyEnum1 ...); entries the text does not define
follow the known ones in file order.
"""

from __future__ import annotations

import datetime
import difflib
import math
import os
import stat
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import click

from edsconv import spec_tables as tables
from edsconv.eds.lexicon import scalar_kind
from edsconv.eds.source import encode
from edsconv.model import (
    MODULE,
    MODULE_MEMBER_LIST,
    Assembly,
    Connection,
    Device,
    GenericEntry,
    Parameter,
    Reference,
)
from edsconv.model.build import _Builder
from edsconv.eds.syntax import Comment, EdsFile, Entry, Field, Group, Scalar, Section, String, Unparsed
from edsconv.model.values import PathItem, Revision, StringIMember

# ---------------------------------------------------------------------------------------
# Order
# ---------------------------------------------------------------------------------------

_SPEC_SECTIONS = tuple(tables.SECTIONS)


def section_rank(name: str) -> tuple[int, int]:
    """Sort key of a section name: spec sections by Table C.3, then others, vendor sections last."""
    if name in tables.SECTIONS:
        return (0, _SPEC_SECTIONS.index(name))
    if tables.VENDOR_KEYWORD_RE.fullmatch(name):
        return (2, 0)
    return (1, 0)


def entry_rank(section: str, keyword: str) -> tuple[int, int, int]:
    """Sort key of an entry within its (spec) section; entries the spec does not
    define sort after every known one (a stable sort keeps their file order)."""
    section_spec = tables.SECTIONS.get(section)
    spec = tables.entry_spec(section, keyword)
    if section_spec is None or spec is None:
        return (len(section_spec.entries) if section_spec else 0, 0, 0)
    specs = section_spec.entries
    own = specs.index(spec)
    family = spec.pairs_with or spec.keyword
    primary = next((i for i, s in enumerate(specs) if s.keyword == family), own)
    number = tables.split_numbered(keyword)[1] if spec.numbered else 0
    return (primary, number or 0, own)


# ---------------------------------------------------------------------------------------
# Values -> syntax
# ---------------------------------------------------------------------------------------

_NAMED_ESCAPES = {"\\": "\\\\", '"': '\\"', "\n": "\\n", "\t": "\\t", "\v": "\\v", "\b": "\\b",
                  "\r": "\\r", "\f": "\\f", "\a": "\\a"}


def needs_unicode(text: str) -> bool:
    """A string must be written ``L"..."`` when it holds a character beyond Latin-1:
    only L strings may use ``\\unnnn`` (Table C.4)."""
    return any(ord(c) > 0xFF for c in text)


def quote(text: str) -> String:
    """An EDS_Char_Array with the Table C.4 escapes: ``\\\\``, ``\\"``, the named control
    escapes, other non-printable or non-ASCII characters as ``\\xnn`` (``\\unnnn``
    beyond Latin-1, which makes the string ``L"..."``; characters beyond the BMP
    are written as they are)."""
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
            out.append(char)
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

# the attribute each [File] / [Device] keyword lands in, as the builder maps them
_FILE_ATTRIBUTES = _Builder._FILE_ATTRIBUTES
_DEVICE_ATTRIBUTES = _Builder._DEVICE_ATTRIBUTES
_PARAM_CLASS_ATTRIBUTES = {"MaxInst": "max_instances", "Descriptor": "descriptor", "CfgAssembly": "cfg_assembly"}
_MODULAR_ATTRIBUTES = {"DefineSlotsInRack": "define_slots_in_rack", "SlotDisplayRule": "slot_display_rule",
                       "Width": "width", "ExternalID": "external_id", "GenericID": "generic_id",
                       "ExternIDExactMatch": "extern_id_exact_match"}


def _singles(section: str, record, attributes: dict[str, str]) -> list[Entry]:
    entries = []
    for spec in tables.SECTIONS[section].entries:
        attribute = attributes.get(spec.keyword)
        if attribute is None:
            continue
        value = getattr(record, attribute)
        if value is not None:
            entries.append(Entry(spec.keyword, [Field(render_value(value, spec.fields[0].eds_type.split("|")[0]))]))
    return entries


def _param_value_type(parameter: Parameter, attribute: str) -> str:
    """The type the builder reads a minimum / maximum / default with (Table C.17)."""
    data_type = parameter.data_type
    if data_type is None:
        return "plain"
    if attribute != "default" and tables.min_max_rule(data_type.name).meaning == "length":
        return "UINT"
    if data_type.kind in ("string", "epath"):
        return "EDS_Char_Array"
    if data_type.kind == "stringi" or data_type.size is None:
        return "plain"
    return data_type.name


def _param_values(parameter: Parameter, values, proxy: bool) -> list:
    return [render_value(v, _param_value_type(parameter, a), proxy)
            for v, a in zip(values, ("minimum", "maximum", "default"), strict=True)]


def _parameter_entries(parameter: Parameter) -> list[Entry]:
    proxy = parameter.family == "ProxyParam"
    s = parameter.scaling
    code = parameter.data_type_code
    fields = [
        Scalar("0"),
        render_value(parameter.link_path_size, "USINT"),
        render_value(parameter.link_path, "EPATH"),
        render_value(parameter.descriptor, "WORD", proxy),
        render_value(code, "code", proxy),
        render_value(parameter.data_size, "USINT", proxy),
        render_value(parameter.name, "EDS_Char_Array", proxy),
        render_value(parameter.units, "EDS_Char_Array", proxy),
        render_value(parameter.help, "EDS_Char_Array", proxy),
        *_param_values(parameter, (parameter.minimum, parameter.maximum, parameter.default), proxy),
        *(render_value(v, t) for v, t in ((s.multiplier, "UINT"), (s.divisor, "UINT"), (s.base, "UINT"),
                                          (s.offset, "INT"), (s.multiplier_link, "UINT"),
                                          (s.divisor_link, "UINT"), (s.base_link, "UINT"),
                                          (s.offset_link, "UINT"), (s.decimal_precision, "USINT"))),
        render_value(parameter.international_name), render_value(parameter.international_units),
        render_value(parameter.international_help),
    ]
    spec = tables.entry_spec("Params", parameter.keyword)
    entries = [_entry(parameter.keyword, fields, spec.required_count if spec else 0)]
    number = parameter.number
    if parameter.size_adder is not None:
        entries.append(_entry(f"ProxyParamSizeAdder{number}", _param_values(parameter, parameter.size_adder, False), 3))
    if parameter.enum is not None:
        family = {"Param": "Enum", "ProxyParam": "ProxyEnum", "ProxiedParam": "ProxiedEnum"}[parameter.family]
        data_type = parameter.data_type
        key_type = data_type.name if data_type and data_type.kind in ("unsigned", "signed", "bits", "bool") else "LINT"
        values: list = []
        for key, text in parameter.enum.items():
            values += [render_value(key, key_type), render_value(text, "EDS_Char_Array")]
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
    out["File"] = _singles("File", device.file, _FILE_ATTRIBUTES)
    out["Device"] = _singles("Device", device.identity, _DEVICE_ATTRIBUTES)
    out["Device Classification"] = [
        _entry(f"Class{c.number}", [render_value(c.classification, "Keyword"),
                                    *(plain_value(s, keywords=True) for s in c.subclassifications)])
        for c in _numbered(device.classifications)]
    if device.param_class is not None:
        entries = _singles("ParamClass", device.param_class, _PARAM_CLASS_ATTRIBUTES)
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
        entries = _singles("Modular", modular, _MODULAR_ATTRIBUTES)
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
    return eds


def attach_comments(eds: EdsFile, notes) -> None:
    """Put each CommentNote back on its section / entry / field. A note whose field is
    gone goes to the entry's last field; one whose entry is gone to its section's
    leading comments; one whose section is gone to the end of the file."""
    sections: dict[str, Section] = {}
    for section in eds.sections:
        sections.setdefault(section.name, section)
    entries: dict[tuple[str, str], Entry] = {}
    for section in eds.sections:
        for entry in section.entries:
            entries.setdefault((section.name, entry.keyword), entry)
    for note in notes:
        comment = Comment(note.text)
        section = sections.get(note.section)
        if section is None:
            eds.trailing_comments.append(comment)
            continue
        if note.keyword is None:
            (section.leading_comments if note.leading else section.comments).append(comment)
            continue
        entry = entries.get((note.section, note.keyword))
        if entry is None:
            section.leading_comments.append(comment)
        elif note.leading:
            entry.leading_comments.append(comment)
        elif note.field is None:
            entry.comments.append(comment)
        else:
            entry.fields[min(note.field, len(entry.fields) - 1)].comments.append(comment)


# ---------------------------------------------------------------------------------------
# Syntax model -> canonical order
# ---------------------------------------------------------------------------------------


def canonical(eds: EdsFile) -> EdsFile:
    """The same syntax model in canonical order: sections by :func:`section_rank`,
    entries by :func:`entry_rank` (stable: duplicates and unknown entries keep their
    file order). Values, spelling, comments and unparsed text are kept; unparsed
    text stays before the entry it stood before."""
    sections = [_canonical_section(s) for s in sorted(eds.sections, key=lambda s: section_rank(s.name))]
    return EdsFile(sections=sections, preamble=eds.preamble, trailing_comments=list(eds.trailing_comments),
                   diagnostics=eds.diagnostics, path=eds.path, encoding=eds.encoding, newline=eds.newline)


def _canonical_section(section: Section) -> Section:
    order = sorted(range(len(section.entries)), key=lambda i: entry_rank(section.name, section.entries[i].keyword))
    new_index = {old: new for new, old in enumerate(order)}
    unparsed = sorted(((new_index.get(index, len(order)), item) for index, item in section.unparsed),
                      key=lambda pair: pair[0])
    return Section(section.name, [section.entries[i] for i in order], list(section.comments),
                   list(section.leading_comments), unparsed, section.offset, section.source)


# ---------------------------------------------------------------------------------------
# Layout
# ---------------------------------------------------------------------------------------

_INDENT = "    "
_FIELD_INDENT = "        "
#: an entry whose one-line form is longer than this is laid out one field per line
LINE_LIMIT = 100
#: entries with more fixed fields than this are laid out one field per line
MAX_INLINE_FIELDS = 4
#: comments of a multi-line entry are aligned on this column at least
COMMENT_COLUMN = 40


@dataclass(slots=True)
class _Line:
    text: str
    comment: str | None = None
    #: lines of one entry (or header) share a block: their comments are aligned
    block: int = 0


class _Out:
    """Lines of text; a comment closes the line it is written on."""

    def __init__(self) -> None:
        self.lines: list[_Line] = []
        self.current = ""
        self.block = 0

    def new_block(self) -> None:
        self.end_line()
        self.block += 1

    def text(self, text: str, indent: str = _INDENT) -> None:
        if not self.current:
            self.current = indent
        self.current += text

    def comment(self, comment: Comment, indent: str = _INDENT) -> None:
        if self.current.strip():
            self.lines.append(_Line(self.current, comment.text, self.block))
        else:
            self.lines.append(_Line(indent, comment.text, self.block))
        self.current = ""

    def end_line(self) -> None:
        if self.current.strip():
            self.lines.append(_Line(self.current, None, self.block))
        self.current = ""

    def own_line(self, text: str, comment: str | None = None) -> None:
        self.end_line()
        self.lines.append(_Line(text, comment, self.block))


def _join(parts: list[str]) -> str:
    """Fields joined by ", "; empty fields leave just their comma."""
    out = ""
    for index, part in enumerate(parts):
        if index:
            out += "," + (" " + part if part else "")
        else:
            out += part
    return out


def _value_text(value) -> str:
    if value is None:
        return ""
    if isinstance(value, Group):
        return "{" + _join([_value_text(f.value) for f in value.fields]) + "}"
    return value.raw


def _has_comments(fields: list[Field]) -> bool:
    for item in fields:
        if item.comments:
            return True
        if isinstance(item.value, Group) and _has_comments(item.value.fields):
            return True
    return False


#: How the fixed fields of a long entry share lines (counts of fields per line),
#: after the spec's logical groups: Link Path Size and Link Path; minimum,
#: maximum and default; the four scaling factors; the four scaling links; one
#: connection direction (RPI, size, format); one config part (size, format);
#: the two reserved fields.
LINE_GROUPS: dict[str, tuple[int, ...]] = {
    "Param": (1, 2, 1, 1, 1, 1, 1, 1, 3, 4, 4, 1, 1, 1, 1),
    "Connection": (1, 1, 3, 3, 2, 2, 1, 1, 1),
    "Assem": (1, 1, 1, 1, 2),
    "Port": (1, 1, 1, 1, 2),
    "Rack": (1, 1, 1, 1, 1, 3),
}
_LINE_GROUP_FAMILY = {"ProxyParam": "Param", "ProxiedParam": "Param", "ProxyConnect": "Connection",
                      "ProxiedConnect": "Connection", "ProxyAssem": "Assem", "ProxiedAssem": "Assem"}


def _line_counts(section: str, entry: Entry) -> list[int]:
    """Fields per line of a long entry: the fixed fields by :data:`LINE_GROUPS` (one per
    line for other entries), then a repeating tail: one repeat per line when it has
    more than one field (assembly members, enum pairs), else packed up to the line limit."""
    spec = tables.entry_spec(section, entry.keyword)
    fields = entry.fields
    if spec is None:
        return [1] * len(fields)
    groups = LINE_GROUPS.get(_LINE_GROUP_FAMILY.get(spec.keyword, spec.keyword))
    fixed = len(spec.fields) - len(spec.repeating)
    counts = list(groups) if groups else [1] * fixed
    out: list[int] = []
    index = 0
    for count in counts:
        if index >= len(fields):
            return out
        count = min(count, len(fields) - index)
        out.append(count)
        index += count
    unit = len(spec.repeating) or 1
    width = 0
    while index < len(fields):
        if fields[index].raw == MODULE_MEMBER_LIST:
            out.append(1)
            index += 1
            continue
        count = min(unit, len(fields) - index)
        if unit == 1:
            text = len(_value_text(fields[index].value)) + 2
            if out and width and width + text <= LINE_LIMIT - len(_FIELD_INDENT):
                out[-1] += 1
                width += text
                index += 1
                continue
            width = text
        out.append(count)
        index += count
    return out


def _is_long(section: str, entry: Entry, one_line: str) -> bool:
    spec = tables.entry_spec(section, entry.keyword)
    fixed = len(spec.fields) - len(spec.repeating) if spec is not None else 0
    if fixed > MAX_INLINE_FIELDS:
        return True
    return len(_INDENT) + len(entry.keyword) + 3 + len(one_line) + 1 > LINE_LIMIT


def write_canonical(eds: EdsFile, newline: str | None = None) -> str:
    """The canonical text of a syntax model: :func:`canonical` order and this layout:

    - a blank line before every section header but the first; section headers at
      column 0, entries indented four spaces;
    - a short entry on one line: ``Keyword = f1, f2, f3;`` (empty fields leave just
      their comma);
    - an entry with more than four fixed fields (ParamN, AssemN, ConnectionN,
      PortN, RackN), a comment inside (other than one after the ``;``), or longer than 100 columns on one line:
      ``Keyword =`` on its own line, then one field per line indented eight
      spaces (a repeating group, e.g. an assembly member's size and reference
      or an enum's value and text, shares a line), the last one ending in ``;``;
    - comments at the end of the line of the field (or entry, or section header)
      they belong to, aligned on one column per entry (at least column 40 in
      multi-line entries); further comments of the same field on lines of their
      own; leading comments on their own lines before what they lead.
    """
    out = _Out()
    ordered = canonical(eds)
    if ordered.preamble is not None:
        _write_entries(out, ordered.preamble)
    for index, section in enumerate(ordered.sections):
        out.end_line()
        if index or out.lines:
            out.lines.append(_Line(""))
        out.new_block()
        for comment in section.leading_comments:
            out.own_line("", comment.text)
        out.own_line(f"[{section.name}]", section.comments[0].text if section.comments else None)
        for comment in section.comments[1:]:
            out.own_line(" " * (len(section.name) + 2), comment.text)
        _write_entries(out, section)
    out.end_line()
    if ordered.trailing_comments:
        out.lines.append(_Line(""))
    for comment in ordered.trailing_comments:
        out.own_line("", comment.text)
    out.end_line()
    eol = newline or eds.newline
    return eol.join(_render(out.lines)) + eol


def _render(lines: list[_Line]) -> list[str]:
    """Lines with their comments; the comments of one block share a column."""
    rendered = []
    start = 0
    while start < len(lines):
        end = start + 1
        while end < len(lines) and lines[end].block == lines[start].block:
            end += 1
        block = lines[start:end]
        code = [line.text.rstrip() for line in block]
        column = max((len(text) for text, line in zip(code, block, strict=True) if line.comment is not None
                      and text.strip()), default=0)
        for text, line in zip(code, block, strict=True):
            if line.comment is None:
                rendered.append(text)
            elif not text.strip():
                rendered.append(f"{line.text}${line.comment}")
            else:
                rendered.append(f"{text.ljust(column)}  ${line.comment}")
        start = end
    return rendered


def _write_entries(out: _Out, section: Section) -> None:
    for item in section.items():
        if isinstance(item, Unparsed):
            _write_unparsed(out, item)
        else:
            _write_entry(out, section.name, item)


def _write_unparsed(out: _Out, unparsed: Unparsed) -> None:
    for comment in unparsed.leading_comments:
        out.own_line("", comment.text)
    out.own_line(unparsed.text, unparsed.comments[0].text if unparsed.comments else None)
    for comment in unparsed.comments[1:]:
        out.own_line(" " * len(unparsed.text), comment.text)


def _write_entry(out: _Out, section: str, entry: Entry) -> None:
    out.new_block()
    for comment in entry.leading_comments:
        out.own_line(_INDENT, comment.text)
    one_line = _join([_value_text(f.value) for f in entry.fields])
    last_field = entry.fields[-1]
    if (not entry.comments and not _has_comments(entry.fields[:-1]) and len(last_field.comments) <= 1
            and not (isinstance(last_field.value, Group) and _has_comments(last_field.value.fields))
            and not _is_long(section, entry, one_line)):
        # a comment of the last field may follow the ';' on the same line
        out.own_line(f"{_INDENT}{entry.keyword} = {one_line};",
                     last_field.comments[0].text if last_field.comments else None)
        return
    out.text(f"{entry.keyword} =")
    for comment in entry.comments:
        out.comment(comment)
    out.end_line()
    fields = entry.fields
    last = len(fields) - 1
    index = 0
    for count in _line_counts(section, entry):
        for offset, item in enumerate(fields[index:index + count]):
            _write_field(out, item, index + offset == last, first_on_line=offset == 0)
        out.end_line()
        index += count


def _write_field(out: _Out, item: Field, is_last: bool, first_on_line: bool, closer: str = ";") -> None:
    """One field: its value, its comma (or the closer) and its comments, after the
    rules of :mod:`edsconv.eds.syntax` (a comment belongs to the last field started before it)."""
    value = item.value
    if not first_on_line and value is not None and out.current.strip():
        out.text(" ", _FIELD_INDENT)
    if isinstance(value, Group):
        out.text("{", _FIELD_INDENT)
        if item.comments or _has_comments(value.fields):
            for comment in item.comments:
                out.comment(comment, _FIELD_INDENT)
            sub_last = len(value.fields) - 1
            for sub_index, sub in enumerate(value.fields):
                _write_field(out, sub, sub_index == sub_last, first_on_line=not out.current.strip(), closer="}")
        else:
            out.text(_join([_value_text(f.value) for f in value.fields]) + "}")
        out.text(closer if is_last else ",")
        return
    if value is not None:
        out.text(value.raw, _FIELD_INDENT)
    if not is_last:
        out.text(",", _FIELD_INDENT)
        for comment in item.comments:
            out.comment(comment, _FIELD_INDENT)
        return
    # the last field: comments must stay after its start, and after the closer
    # when it is empty (an empty field starts at its closer)
    if value is None:
        out.text(closer, _FIELD_INDENT)
        for comment in item.comments:
            out.comment(comment, _FIELD_INDENT)
        return
    for comment in item.comments[:-1]:
        out.comment(comment, _FIELD_INDENT)
    out.text(closer, _FIELD_INDENT)
    for comment in item.comments[-1:]:
        out.comment(comment, _FIELD_INDENT)


# ---------------------------------------------------------------------------------------
# edsconv fmt
# ---------------------------------------------------------------------------------------


def format_bytes(eds: EdsFile) -> bytes:
    """The canonical text of a read file in its own encoding and line ends (UTF-8 when
    the encoding cannot hold it)."""
    text = write_canonical(eds)
    try:
        return encode(text, eds.encoding)
    except (UnicodeEncodeError, LookupError):
        return text.encode("utf-8")


@click.command("fmt")
@click.argument("files", nargs=-1, required=True, type=click.Path(dir_okay=False, path_type=Path))
@click.option("--check", is_flag=True, help="Write nothing; exit 1 when a file is not in canonical form.")
@click.option("--diff", "show_diff", is_flag=True, help="Write nothing; print a unified diff of each change.")
def fmt_command(files: tuple[Path, ...], check: bool, show_diff: bool) -> int:
    """Rewrite EDS files in canonical order and layout (docs/fmt.md).

    Values keep their spelling and comments stay with their fields. A file with
    syntax errors is not rewritten (its unparsed text cannot be laid out). Exit 0
    when every file is (or now is) canonical, 1 when --check / --diff found a file
    to change or a file has syntax errors, 2 when a file cannot be read or written.
    """
    from edsconv.cli import EXIT_CLEAN, EXIT_FINDINGS, EXIT_USAGE
    from edsconv.eds.reader import load
    from edsconv.xml.common import write_atomically

    exit_code = EXIT_CLEAN
    changed = unchanged = 0
    for path in files:
        try:
            original = path.read_bytes()
            eds = load(path)
        except OSError as error:
            click.echo(f"{path}: cannot read: {error.strerror or error}", err=True)
            exit_code = EXIT_USAGE
            continue
        errors = [d for d in eds.diagnostics if d.severity.name == "ERROR"]
        if errors:
            click.echo(f"{path}: not formatted: {len(errors)} syntax error(s) leave text that cannot be laid "
                       f"out; first: {errors[0].format()}", err=True)
            exit_code = max(exit_code, EXIT_FINDINGS)
            continue
        data = format_bytes(eds)
        if data == original:
            unchanged += 1
            continue
        changed += 1
        if show_diff:
            old = original.decode(eds.encoding, errors="replace").splitlines(keepends=True)
            new = data.decode(eds.encoding, errors="replace").splitlines(keepends=True)
            click.echo("".join(difflib.unified_diff(old, new, f"{path}", f"{path} (canonical)")), nl=False)
        if check or show_diff:
            click.echo(f"would reformat {path}", err=True)
            exit_code = max(exit_code, EXIT_FINDINGS)
            continue
        try:
            mode = path.stat().st_mode
            write_atomically(path, data, force=True)
            os.chmod(path, stat.S_IMODE(mode))
        except OSError as error:
            click.echo(f"{path}: cannot write: {error.strerror or error}", err=True)
            exit_code = EXIT_USAGE
            continue
        click.echo(f"reformatted {path}", err=True)
    verb = "would be reformatted" if check or show_diff else "reformatted"
    click.echo(f"{changed} file(s) {verb}, {unchanged} unchanged", err=True)
    return exit_code


__all__ = ["attach_comments", "canonical", "device_to_eds", "entry_rank", "fmt_command", "format_bytes", "needs_unicode", "plain_value",
           "quote", "real_text", "render_value", "section_rank", "write_canonical"]
