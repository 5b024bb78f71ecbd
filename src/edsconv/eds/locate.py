"""What stands at a position of an EDS: the section, entry and field of the syntax model, and the word.

Editors ask "what is under the cursor" in 1-based line and column (as the
syntax model counts them, in characters). Positions are compared as
``(line, column)`` pairs, computed from the nodes' offsets only for the few
nodes a binary search visits. A field reaches from its first character to the
start of the next field (or the end of its entry), so a cursor on the comma or
on the comment after a field is still in that field.
"""

from __future__ import annotations

import bisect
import re
from dataclasses import dataclass

from edsconv.eds.syntax import EdsFile, Entry, Field, Group, Section

Position = tuple[int, int]

_WORD = re.compile(r"[A-Za-z0-9_]+")
#: Where an unquoted value ends (C.4.1.2.2: fields are separated by ',' and end at ';' or '}').
_VALUE_END = re.compile(r"[,;}{$\s]")


@dataclass(frozen=True, slots=True)
class Spot:
    """The nodes at one position; each is None where the position lies outside such a node."""

    section: Section | None = None
    entry: Entry | None = None
    #: 0-based field indexes from the entry's top-level field down into brace groups; () outside fields
    field_path: tuple[int, ...] = ()
    field: Field | None = None
    #: True on the ``[Section]`` header line
    on_header: bool = False
    #: True on the entry keyword (before its ``=``)
    on_keyword: bool = False


def start(node: Section | Entry | Field) -> Position:
    return node.line, node.column


def entry_end(entry: Entry) -> Position:
    """The position just after the entry's ``;``."""
    return entry.end_line, entry.end_column


def locate(eds: EdsFile, line: int, column: int) -> Spot:
    """The section, entry and field at ``line``:``column`` (1-based)."""
    where = (line, column)
    section = section_at(eds, where)
    if section is None:
        return Spot()
    if line == section.line and (not section.entries or where < start(section.entries[0])):
        return Spot(section, on_header=True)
    entry = entry_at(section, where)
    if entry is None:
        return Spot(section)
    keyword_end = (entry.line, entry.column + len(entry.keyword))
    if where <= keyword_end:
        return Spot(section, entry, on_keyword=True)
    path, found = field_at(entry.fields, where)
    return Spot(section, entry, path, found)


def section_at(eds: EdsFile, where: Position) -> Section | None:
    """The section whose header stands at or before ``where`` (the preamble before the first header)."""
    sections = eds.sections
    index = bisect.bisect_right(sections, where, key=start) - 1
    if index >= 0:
        return sections[index]
    return eds.preamble


def entry_at(section: Section, where: Position) -> Entry | None:
    """The entry of ``section`` that spans ``where``, from its keyword to just after its ``;``."""
    entries = section.entries
    index = bisect.bisect_right(entries, where, key=start) - 1
    if index < 0:
        return None
    entry = entries[index]
    return entry if where <= entry_end(entry) else None


def field_at(fields: list[Field], where: Position) -> tuple[tuple[int, ...], Field | None]:
    """The innermost field at ``where`` and its index path; ``((), None)`` before the first field."""
    index = bisect.bisect_right(fields, where, key=start) - 1
    if index < 0:
        return (), None
    found = fields[index]
    if isinstance(found.value, Group):
        inner, nested = field_at(found.value.fields, where)
        if nested is not None:
            return (index, *inner), nested
    return (index,), found


def word_at(line_text: str, column: int) -> tuple[int, int, str] | None:
    """The keyword-like word (letters, digits, ``_``) touching ``column`` (1-based) of a line:
    its first column, the column after it, and the word."""
    for match in _WORD.finditer(line_text):
        if match.start() + 1 <= column <= match.end() + 1:
            return match.start() + 1, match.end() + 1, match.group()
        if match.start() + 1 > column:
            break
    return None


def value_end(line_text: str, column: int) -> int:
    """The column after the value that starts at ``column`` of a line: a quoted string up to its
    closing quote, anything else up to the next separator. Used to give a diagnostic a range."""
    index = column - 1
    if index >= len(line_text):
        return column
    if line_text[index] == '"' or line_text.startswith('L"', index):
        closing = line_text.find('"', line_text.index('"', index) + 1)
        while closing > 0 and line_text[closing - 1] == "\\":
            closing = line_text.find('"', closing + 1)
        return (closing if closing >= 0 else len(line_text.rstrip("\r\n")) - 1) + 2
    match = _VALUE_END.search(line_text, index + 1)
    return (match.start() if match else len(line_text.rstrip("\r\n"))) + 1
