"""The syntax model of an EDS: file -> sections -> entries -> fields -> values.

It is lossless for everything that has meaning: values keep their spelling
(hex stays hex), comments stay with the element they belong to, duplicate
sections and entries are all kept. Positions (1-based line and column) are kept
on every node but take no part in equality, so a model written out and read
back compares equal to the original.

Comment ownership, one rule for every level: a comment inside an entry belongs
to the last field (nested fields included) that starts before it, or to the
entry itself when no field does; a comment on a line of its own between
statements belongs to the next statement as a leading comment.

An entry read from a file without braces keeps only its place in the text until
its fields or comments are first asked for (:class:`Entry`); they are then made
from the text, once, and kept.
"""

from __future__ import annotations

import enum
import functools
import operator
import re
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Any

from edsconv.diagnostics import Diagnostic
from edsconv.eds.lexicon import scalar_kind
from edsconv.eds.source import LineIndex


class Located:
    """A node's place in its file, turned into line and column only when asked.

    Nodes store a character offset and a reference to the file's line index;
    most positions are never looked at, so none are computed while reading.
    Nodes built in code (not read from a file) have line and column 0.
    """

    __slots__ = ()
    # declared by each node class (annotations only: this mixin is not a dataclass)
    offset: int
    source: LineIndex | None

    @property
    def line(self) -> int:
        return self.source.position(self.offset)[0] if self.source else 0

    @property
    def column(self) -> int:
        return self.source.position(self.offset)[1] if self.source else 0


class ValueKind(enum.StrEnum):
    """Lexical kind of a value, named after the grammar terminals."""

    STRING = "STRING"
    REAL_WORD = "REAL_WORD"
    DATE = "DATE"
    TIME = "TIME"
    HEX = "HEX"
    BINARY = "BINARY"
    REAL = "REAL"
    INTEGER = "INTEGER"
    WORD = "WORD"
    WILDCARD = "WILDCARD"
    GROUP = "GROUP"


#: ValueKind by name, without the cost of an Enum call per lookup
_KINDS = {kind.value: kind for kind in ValueKind}


@dataclass(slots=True)
class Comment(Located):
    """A ``$`` comment; ``text`` is everything after the ``$`` up to the line end."""

    text: str
    offset: int = field(default=0, compare=False)
    source: LineIndex | None = field(default=None, compare=False, repr=False)

    @property
    def own_line(self) -> bool:
        """True when nothing but white space precedes it on its line."""
        return self.source is not None and self.source.starts_line(self.offset)


@dataclass(frozen=True, slots=True)
class Scalar:
    """A number, date, time, bare keyword or ``*``, spelled as in the file.

    Immutable, so that the reader can give every field of a file with the same spelling one object.
    """

    raw: str

    @property
    def kind(self) -> ValueKind:
        """The lexical kind, classified on demand (most values are never asked)."""
        kind = scalar_kind(self.raw)
        if not kind:
            raise ValueError(f"{self.raw!r} is not an EDS scalar")
        return _KINDS[kind]


@functools.cache
def _escapes() -> tuple[re.Pattern[str], dict[str, str]]:
    """Table C.4: one escape sequence, and the letter after the backslash -> the character.

    Made on first use: reading a file does not need the spec's tables, only a string with a backslash does.
    """
    from edsconv import spec_tables as tables

    pattern = re.compile("\\\\(" + "".join(f"{sequence[1:]}[0-9A-Fa-f]{{{digits}}}|"
                                            for sequence, digits in tables.NUMERIC_ESCAPES.items()) + ".)")
    return pattern, {sequence[1:]: char for sequence, char in tables.ESCAPE_SEQUENCES.items()}


_SURROGATE_PAIR = re.compile("[\ud800-\udbff][\udc00-\udfff]")


def _joined_pair(match: re.Match[str]) -> str:
    high, low = (ord(c) for c in match.group())
    return chr(0x10000 + ((high - 0xD800) << 10) + (low - 0xDC00))


def _unescape(match: re.Match[str]) -> str:
    body = match.group(1)
    if len(body) > 1:
        return chr(int(body[1:], 16))
    return _escapes()[1].get(body, body)


@dataclass(slots=True)
class String:
    """An EDS_Char_Array (C.4.1.3.3): one or more adjacent quoted parts.

    ``parts`` keep their quotes; only the first may carry the ``L`` prefix that
    makes the whole string UNICODE.
    """

    parts: tuple[str, ...]

    kind = ValueKind.STRING

    @property
    def unicode(self) -> bool:
        return self.parts[0].startswith("L")

    @property
    def raw(self) -> str:
        return " ".join(self.parts)

    @property
    def text(self) -> str:
        """The characters the string stands for, escapes translated (Table C.4) in each part before the
        parts are joined: an escape never spans two parts (``"\\x4" "1"`` is not ``"A"``)."""
        inners = [part[part.index('"') + 1:-1] for part in self.parts]
        if not any("\\" in inner for inner in inners):
            return "".join(inners)
        pattern = _escapes()[0]
        text = "".join(pattern.sub(_unescape, inner) for inner in inners)
        # a character beyond the BMP is two 16-bit characters of an L string, its UTF-16 surrogates
        return _SURROGATE_PAIR.sub(_joined_pair, text) if self.unicode else text


@dataclass(slots=True)
class Group:
    """A brace group ``{ ... }`` (C.4.1.2.14): a list of fields, nested to any depth."""

    fields: list[Field]

    kind = ValueKind.GROUP


Value = Scalar | String | Group


class Field(Located):
    """One comma-separated field; ``value`` is None for an empty (omitted) field.

    An empty field is located at the comma, ``;`` or ``}`` that ends it. Its ``comments``
    list is made when first asked for: most fields never have one, and an empty list per
    field was a fifth of a dense file's model. Equality and ``repr`` are those of a dataclass
    with the fields ``value`` and ``comments`` (position not compared).
    """

    __slots__ = ("value", "_comments", "offset", "source")
    __hash__ = None  # type: ignore[assignment]  # mutable, compared by value

    def __init__(self, value: Value | None, comments: list[Comment] | None = None, offset: int = 0,
                 source: LineIndex | None = None) -> None:
        self.value = value
        self._comments = comments
        self.offset = offset
        self.source = source

    @property
    def comments(self) -> list[Comment]:
        comments = self._comments
        if comments is None:
            comments = self._comments = []
        return comments

    @comments.setter
    def comments(self, comments: list[Comment]) -> None:
        self._comments = comments

    @property
    def has_comments(self) -> bool:
        """True when a comment belongs to the field (without making its list)."""
        return bool(self._comments)

    def __eq__(self, other: object) -> bool:
        if other.__class__ is not self.__class__:
            return NotImplemented
        assert isinstance(other, Field)
        return self.value == other.value and (self._comments or []) == (other._comments or [])

    def __repr__(self) -> str:
        return f"Field(value={self.value!r}, comments={self._comments or []!r}, offset={self.offset!r})"

    @property
    def is_empty(self) -> bool:
        return self.value is None

    @property
    def raw(self) -> str | None:
        """The spelling of a scalar or string field; None for empty fields and groups."""
        value = self.value
        if value is None or isinstance(value, Group):
            return None
        return value.raw


class Entry(Located):
    """``Keyword = field, field, ... ;`` (C.4.1.2.2.8).

    Built in code, or read with braces, an entry holds its fields. Read without braces, it
    holds only its place in the text (and the comments around it that the reader saw) until
    ``fields`` or ``comments`` is first used: they are then made from the text
    (:func:`edsconv.eds.runs.entry_contents`) and kept. Either way it behaves the same.
    """

    __slots__ = ("keyword", "_fields", "_comments", "_leading_comments", "_trailing_comment",
                 "offset", "end_offset", "source")
    __hash__ = None  # type: ignore[assignment]  # mutable, compared by value

    def __init__(self, keyword: str, fields: list[Field], comments: list[Comment] | None = None,
                 leading_comments: list[Comment] | None = None, offset: int = 0, end_offset: int = 0,
                 source: LineIndex | None = None) -> None:
        self.keyword = keyword
        self._fields: list[Field] | None = fields
        #: comments between ``=`` and the first field
        self._comments: list[Comment] | None = [] if comments is None else comments
        self._leading_comments: list[Comment] | None = leading_comments
        #: a comment after the ``;`` on its line, kept for the fields not made yet
        self._trailing_comment: Comment | None = None
        self.offset = offset
        #: offset just after the closing ``;``
        self.end_offset = end_offset
        self.source = source

    @classmethod
    def unread(cls, keyword: str, offset: int, end_offset: int, source: LineIndex) -> Entry:
        """An entry read from ``source`` whose fields and comments are made when first asked for."""
        entry = cls(keyword, [], None, None, offset, end_offset, source)
        entry._fields = entry._comments = None
        return entry

    def _read(self) -> None:
        from edsconv.eds.runs import entry_contents

        assert self.source is not None  # only unread entries come here
        self._fields, self._comments = entry_contents(self.source.text, self.offset, self.end_offset, self.source,
                                                      self._trailing_comment)
        self._trailing_comment = None

    @property
    def fields(self) -> list[Field]:
        if self._fields is None:
            self._read()
        return self._fields  # type: ignore[return-value]  # made by _read

    @fields.setter
    def fields(self, fields: list[Field]) -> None:
        if self._fields is None:
            self._read()
        self._fields = fields

    @property
    def comments(self) -> list[Comment]:
        """Comments between ``=`` and the first field."""
        if self._comments is None:
            self._read()
        return self._comments  # type: ignore[return-value]  # made by _read

    @comments.setter
    def comments(self, comments: list[Comment]) -> None:
        if self._comments is None:
            self._read()
        self._comments = comments

    @property
    def leading_comments(self) -> list[Comment]:
        if self._leading_comments is None:
            self._leading_comments = []
        return self._leading_comments

    @leading_comments.setter
    def leading_comments(self, comments: list[Comment]) -> None:
        self._leading_comments = comments

    @property
    def lead_offset(self) -> int:
        """Where its first leading comment starts (they are kept in file order), else where it starts."""
        comments = self._leading_comments
        return comments[0].offset if comments else self.offset

    def attach_trailing_comment(self, comment: Comment) -> None:
        """The reader's, while the fields are not made: a comment after the ``;`` on the same line."""
        assert self._fields is None, "only the reader attaches, before anything reads the fields"
        self._trailing_comment = comment

    @property
    def is_read(self) -> bool:
        """False while the fields and comments are still only text (see the class)."""
        return self._fields is not None

    def _compared(self) -> tuple[Any, ...]:
        return self.keyword, self.fields, self.comments, self.leading_comments

    def __eq__(self, other: object) -> bool:
        if other.__class__ is not self.__class__:
            return NotImplemented
        assert isinstance(other, Entry)
        return self._compared() == other._compared()

    def __repr__(self) -> str:
        return (f"Entry(keyword={self.keyword!r}, fields={self.fields!r}, comments={self.comments!r}, "
                f"leading_comments={self.leading_comments!r}, offset={self.offset!r}, "
                f"end_offset={self.end_offset!r})")

    @property
    def end_line(self) -> int:
        return self.source.position(self.end_offset)[0] if self.source else 0

    @property
    def end_column(self) -> int:
        return self.source.position(self.end_offset)[1] if self.source else 0

    def walk_fields(self) -> Iterator[Field]:
        """Every field in document order, fields inside brace groups included."""
        stack = list(reversed(self.fields))
        while stack:
            current = stack.pop()
            yield current
            if isinstance(current.value, Group):
                stack.extend(reversed(current.value.fields))


@dataclass(slots=True)
class Unparsed(Located):
    """Text that could not be parsed, kept verbatim so that nothing is lost."""

    text: str
    #: comments after the text on its last line
    comments: list[Comment] = field(default_factory=list)
    leading_comments: list[Comment] = field(default_factory=list)
    offset: int = field(default=0, compare=False)
    source: LineIndex | None = field(default=None, compare=False, repr=False)


@dataclass(slots=True)
class Section(Located):
    """``[Name]`` and its entries, in file order."""

    name: str
    entries: list[Entry] = field(default_factory=list)
    #: comments on the header line, after ``]``
    comments: list[Comment] = field(default_factory=list)
    leading_comments: list[Comment] = field(default_factory=list)
    #: (index into ``entries`` before which it stood, text) for unparsable statements
    unparsed: list[tuple[int, Unparsed]] = field(default_factory=list)
    offset: int = field(default=0, compare=False)
    source: LineIndex | None = field(default=None, compare=False, repr=False)

    def items(self) -> Iterator[Entry | Unparsed]:
        """Entries and unparsable text, in file order."""
        unparsed = iter(self.unparsed)
        pending = next(unparsed, None)
        for index, entry in enumerate(self.entries):
            while pending is not None and pending[0] <= index:
                yield pending[1]
                pending = next(unparsed, None)
            yield entry
        while pending is not None:
            yield pending[1]
            pending = next(unparsed, None)

    def entry(self, keyword: str) -> Entry | None:
        """The first entry with this keyword (duplicates are reported, and kept)."""
        for entry in self.entries:
            if entry.keyword == keyword:
                return entry
        return None


@dataclass(slots=True)
class EdsFile:
    sections: list[Section] = field(default_factory=list)
    #: entries that stand before the first section header (an error, kept)
    preamble: Section | None = None
    #: comments after the last statement
    trailing_comments: list[Comment] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list, compare=False)
    path: str | None = field(default=None, compare=False)
    encoding: str = field(default="ascii", compare=False)
    newline: str = field(default="\n", compare=False)

    def holders(self) -> list[Section]:
        """The sections that hold entries, in file order: the preamble (entries before the first header,
        an error, kept) if there is one, then every section."""
        return [self.preamble, *self.sections] if self.preamble is not None else self.sections

    def section(self, name: str) -> Section | None:
        """The first section with this name (case as written in the spec)."""
        for section in self.sections:
            if section.name == name:
                return section
        return None

    @property
    def has_errors(self) -> bool:
        from edsconv.diagnostics import has_errors

        return has_errors(self.diagnostics)


_FIELD_COMMENTS = operator.attrgetter("_comments")
_FIELD_VALUE = operator.attrgetter("value")


def plain_fields(fields: list[Field]) -> bool:
    """True when no field has a comment and none is a brace group, as most entries: told in C, without
    a loop in Python (which, on a file of 40,000 entries, took a quarter of a second)."""
    return not any(map(_FIELD_COMMENTS, fields)) and Group not in map(type, map(_FIELD_VALUE, fields))


def _comments_json(comments: list[Comment]) -> list[str]:
    return [comment.text for comment in comments]


def _value_json(value: Value | None) -> dict | None:
    if value is None:
        return None
    if isinstance(value, Group):
        return {"kind": "GROUP", "fields": [_field_json(f) for f in value.fields]}
    if isinstance(value, String):
        return {"kind": "STRING", "raw": value.raw, "text": value.text, "unicode": value.unicode}
    return {"kind": str(value.kind), "raw": value.raw}


def _field_json(item: Field) -> dict:
    return {"line": item.line, "column": item.column, "value": _value_json(item.value),
            "comments": _comments_json(item.comments)}


def _entry_json(entry: Entry) -> dict:
    return {
        "keyword": entry.keyword, "line": entry.line, "column": entry.column,
        "end_line": entry.end_line, "end_column": entry.end_column,
        "comments": _comments_json(entry.comments), "leading_comments": _comments_json(entry.leading_comments),
        "fields": [_field_json(f) for f in entry.fields],
    }


def _section_json(section: Section) -> dict:
    return {
        "name": section.name, "line": section.line, "column": section.column,
        "comments": _comments_json(section.comments), "leading_comments": _comments_json(section.leading_comments),
        "entries": [_entry_json(e) for e in section.entries],
        "unparsed": [{"before_entry": index, "line": item.line, "text": item.text} for index, item in section.unparsed],
    }


def to_json(eds: EdsFile) -> dict:
    """The syntax model as plain JSON data (``edsconv parse --format json``)."""
    return {
        "path": eds.path,
        "encoding": eds.encoding,
        "preamble": _section_json(eds.preamble) if eds.preamble else None,
        "sections": [_section_json(s) for s in eds.sections],
        "trailing_comments": _comments_json(eds.trailing_comments),
        "diagnostics": [d.as_dict() for d in eds.diagnostics],
    }
