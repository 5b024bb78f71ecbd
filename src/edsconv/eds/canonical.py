"""Canonical EDS: one order and one layout for every file (what ``edsconv fmt`` writes).

:func:`canonical` reorders a syntax model (sections and entries in spec order)
without touching its values or comments; :func:`write_canonical` lays it out as
text; :func:`format_bytes` encodes that text as the file was. A typed Device is
rendered in the same order by :mod:`edsconv.eds.from_model`.

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

from dataclasses import dataclass

from edsconv import spec_tables as tables
from edsconv.eds.source import encode
from edsconv.eds.syntax import Comment, EdsFile, Entry, Field, Group, Section, Unparsed
from edsconv.model import MODULE_MEMBER_LIST

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
# Bytes
# ---------------------------------------------------------------------------------------


def format_bytes(eds: EdsFile) -> bytes:
    """The canonical text of a read file in its own encoding and line ends (UTF-8 when
    the encoding cannot hold it)."""
    text = write_canonical(eds)
    try:
        return encode(text, eds.encoding)
    except (UnicodeEncodeError, LookupError):
        return text.encode("utf-8")


__all__ = ["canonical", "entry_rank", "format_bytes", "section_rank", "write_canonical"]
