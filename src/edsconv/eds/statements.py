"""Statements -> the syntax model: what both ways of reading a statement share.

The reader (:mod:`edsconv.eds.reader`) matches simple statements with one regex and
hands statements with braces, and syntax errors, to Lark (:mod:`edsconv.eds.lark_reader`).
Either way each statement comes here in file order: sections and entries are placed,
duplicates and misplaced entries reported, and comments given to their owners
(:mod:`edsconv.eds.syntax`) as soon as the statement after them is known, so that
nothing of a statement but the last one is kept while reading.
"""

from __future__ import annotations

import bisect
import re
import sys
from collections.abc import Callable

from edsconv.diagnostics import Diagnostic, Rule
from edsconv.eds.reader_rules import (
    DUPLICATE_ENTRY,
    DUPLICATE_SECTION,
    ENTRY_OUTSIDE_SECTION,
    SECTION_NAME,
)
from edsconv.eds.runs import comments_in
from edsconv.eds.source import LineIndex
from edsconv.eds.syntax import Comment, EdsFile, Entry, Field, Section, Unparsed

_WHITESPACE_AND_COMMENTS = re.compile(r"(?:[ \t\n\f\v\x1a]++|\$[^\n]*+)*+")
#: C.4.1.2.2.3 (the spec's tables hold it: SECTION_KEYWORD_RE); read on the first section name that is not plain
_PLAIN_SECTION_NAME = re.compile(r"[A-Za-z0-9_]+")

#: a statement as comments are attached to it: start, end of its last line, node, its fields in document
#: order (None for an entry whose fields are not made yet: only a comment after it can still come)
Statement = tuple[int, int, Section | Entry | Unparsed, list[Field] | None]


class SyntaxBuilder:
    """The syntax model of one file, built statement by statement in file order."""

    def __init__(self, text: str, path: str | None, lines: LineIndex) -> None:
        self.text = text
        self.path = path
        self.lines = lines
        #: where the text Lark is parsing starts in ``text``
        self.base = 0
        self.eds = EdsFile(path=path)
        self.current_section: Section | None = None
        self.seen_sections: dict[str, Section] = {}
        self.seen_entries: dict[str, Entry] = {}
        #: (offset, Comment) of comments whose owner is not known yet, in file order
        self.pending: list[tuple[int, Comment]] = []
        self.previous: Statement | None = None
        #: the end of the last statement
        self.last_end = 0
        #: where the reader may stop before the text's end (:func:`edsconv.eds.reader.read_on`; a whole
        #: read never does): at the end of a statement at or after ``stop_from`` that ``stops`` accepts,
        #: or before the section header that starts at ``header_stop``; ``stopped`` once it has
        self.stop_from = sys.maxsize
        self.stops: Callable[[int], bool] = _never
        self.header_stop = -1
        self.stopped = False
        self.give_up_at = sys.maxsize

    def report(self, rule: Rule, message: str, offset: int) -> None:
        line, column = self.lines.position(offset)
        self.eds.diagnostics.append(Diagnostic.of(rule, message, line, column, self.path))

    def take_comments(self, start: int, end: int) -> None:
        """The comments of the TRIVIA ``text[start:end]``; their owners are known with the next statement."""
        self.pending.extend((comment.offset, comment) for comment in comments_in(self.text, start, end, self.lines))

    # --- statements ---------------------------------------------------------------------------

    def add_section(self, token: str, start: int, end: int) -> None:
        """The SECTION token ``token`` (``[Name]``) at ``start``."""
        name = token[1:-1]
        section = Section(name=name.strip(), offset=start, source=self.lines)
        if not _PLAIN_SECTION_NAME.fullmatch(name) and not _section_keyword(name):
            self.report(SECTION_NAME, f"section name [{name}] uses characters or spacing outside the keyword "
                        "rules of ISO 15745-4 (letters, digits, '_', single inner spaces)", start)
        first = self.seen_sections.get(section.name)
        if first is not None:
            self.report(DUPLICATE_SECTION, f"section [{section.name}] appears again (first on line {first.line}); "
                        "both are kept, but tools read only one", start)
        else:
            self.seen_sections[section.name] = section
        self.eds.sections.append(section)
        self.current_section = section
        self.seen_entries = {}
        self.record(start, end, section, [])

    def add_entry(self, entry: Entry, flat: list[Field] | None) -> None:
        """An entry, with every field in document order (None while its fields are not made)."""
        keyword, start = entry.keyword, entry.offset
        section = self.current_section
        if section is None:
            self.report(ENTRY_OUTSIDE_SECTION, f"entry {keyword} stands before the first section header", start)
            section = self.eds.preamble = self.eds.preamble or Section(name="", offset=start, source=self.lines)
        first = self.seen_entries.get(keyword)
        if first is not None:
            self.report(DUPLICATE_ENTRY, f"{keyword} appears again in [{section.name}] (first on line "
                        f"{first.line}); tools reject a file with a duplicated entry", start)
        else:
            self.seen_entries[keyword] = entry
        section.entries.append(entry)
        self.record(start, entry.end_offset, entry, flat)

    def keep_unparsed(self, start: int, end: int) -> None:
        """Keep ``text[start:end]``, past its leading blanks and comments, as text that could not be parsed."""
        blank = _WHITESPACE_AND_COMMENTS.match(self.text, start, end)  # matches, if only the empty string
        start = blank.end() if blank else start
        if start >= end:
            return
        # comments inside it are part of its text
        self.pending = [item for item in self.pending if not start <= item[0] < end]
        section = self.current_section
        if section is None:
            section = self.eds.preamble = self.eds.preamble or Section(name="", offset=start, source=self.lines)
        unparsed = Unparsed(self.text[start:end].rstrip(), offset=start, source=self.lines)
        section.unparsed.append((len(section.entries), unparsed))
        self.record(start, end, unparsed, [])

    def record(self, start: int, end: int, node: Section | Entry | Unparsed, flat: list[Field] | None) -> None:
        """The next statement: comments before it now have their owner."""
        if self.pending:
            self.attach_pending(start, node)
        line_end = self.text.find("\n", end)
        self.previous = (start, len(self.text) if line_end == -1 else line_end, node, flat)
        self.last_end = end

    # --- comments -----------------------------------------------------------------------------

    def attach_pending(self, before: int, following: Section | Entry | Unparsed | None) -> None:
        """Give the comments before offset ``before`` to their owners (``following`` starts there).

        A comment belongs to the statement before it when it stands before the end of that
        statement's last line (inside it, or after it on the same line); otherwise it leads
        the statement that follows, or, at the end, trails the file.
        """
        kept = []
        previous = self.previous
        for offset, comment in self.pending:
            if offset >= before:
                kept.append((offset, comment))
            elif previous is not None and offset < previous[1]:
                _attach(previous, comment)
            elif following is not None:
                following.leading_comments.append(comment)
            else:
                self.eds.trailing_comments.append(comment)
        self.pending = kept

    def finish(self) -> EdsFile:
        self.attach_pending(len(self.text) + 1, None)
        return self.eds


def _never(_: int) -> bool:
    return False


def _attach(statement: Statement, comment: Comment) -> None:
    """A comment inside or after ``statement``: to the last field that starts before it, else to the node."""
    _, _, node, flat = statement
    if flat is None:
        assert isinstance(node, Entry)
        node.attach_trailing_comment(comment)
        return
    index = bisect.bisect_right(flat, comment.offset, key=_offset_of) - 1
    (flat[index].comments if index >= 0 else node.comments).append(comment)


def _offset_of(field: Field) -> int:
    return field.offset


def _section_keyword(name: str) -> bool:
    """Within C.4.1.2.2.3's keyword rules, or a name the newer CIP tables define as it stands
    ([TCP/IP Interface Class]): no EDS006."""
    from edsconv.cip_tables import known
    from edsconv.spec_tables import SECTION_KEYWORD_RE

    return SECTION_KEYWORD_RE.fullmatch(name) is not None or (name == name.strip() and known(name) is not None)
