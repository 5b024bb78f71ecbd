"""A RUN token's text -> fields, values and comments (grammar/eds.lark, regexes from :mod:`.lexicon`).

A RUN is a whole run of comma-separated fields with the white space and comments
between them. Both readers split RUNs here: the builder of entries with braces as
Lark reduces them, and :func:`entry_contents`, which makes the fields of an entry
read without braces when they are first asked for (:class:`~edsconv.eds.syntax.Entry`).
Splitting reports nothing: the reader checks strings (:func:`string_problems`) while
it reads, so that every diagnostic is known when ``parse`` returns.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Iterator

from edsconv.diagnostics import Rule
from edsconv.eds.lexicon import lexicon, undefined_escapes
from edsconv.eds.reader_rules import BAD_ESCAPE, LONG_PREFIX_ON_CONTINUATION, UNICODE_ESCAPE_IN_ASCII
from edsconv.eds.source import LineIndex
from edsconv.eds.syntax import Comment, Field, Scalar, String
from edsconv.limits import shown

_COMMENT = re.compile(r"\$[^\n]*")

#: reports a diagnostic: rule, message, offset
Report = Callable[[Rule, str, int], None]


@functools.lru_cache(maxsize=4096)
def scalar(raw: str) -> Scalar:
    """One Scalar per spelling: the same few ("0", "0x0000", "Param1") recur all over a file."""
    return Scalar(raw)


def comments_in(text: str, start: int, end: int, source: LineIndex) -> Iterator[Comment]:
    """The ``$`` comments of the TRIVIA ``text[start:end]``."""
    for found in _COMMENT.finditer(text, start, end):
        yield Comment(found.group()[1:], found.start(), source)


# --- strings ------------------------------------------------------------------------------------


def string_value(raw: str, offset: int, comments: list[Comment], source: LineIndex | None) -> String:
    """The String of a STRING token at ``offset``; comments between its parts go to ``comments``."""
    if '"' not in raw[1:-1] and "$" not in raw:
        return String((raw,))
    parts = []
    for piece in lexicon().string_piece.finditer(raw):
        if piece.group(2) is not None:
            comments.append(Comment(piece.group()[1:], offset + piece.start(), source))
        else:
            parts.append(piece.group())
    return String(tuple(parts))


def string_problems(raw: str, offset: int) -> Iterator[tuple[Rule, str, int]]:
    """What is wrong in a STRING token at ``offset``: an L prefix after the first part, bad escapes."""
    if '"' in raw[1:-1] or "$" in raw:
        first = True
        for piece in lexicon().string_piece.finditer(raw):
            if piece.group(2) is None:
                if not first and piece.group().startswith("L"):
                    yield (LONG_PREFIX_ON_CONTINUATION, "only the first part of a concatenated string may carry "
                           "the L prefix", offset + piece.start())
                first = False
    if "\\" in raw:
        for at, sequence, defined in undefined_escapes(raw, raw.startswith("L")):
            if not defined:
                yield (BAD_ESCAPE, f"escape sequence {shown(sequence)} is not defined in Table C.4; the "
                       "string is rejected (write '\\\\' for a backslash)", offset + at)
            else:
                yield UNICODE_ESCAPE_IN_ASCII, "\\u escapes are valid only in L\"...\" (UNICODE) strings", offset + at


def check_strings(text: str, start: int, end: int, report: Report) -> None:
    """Report what is wrong in the strings of the RUN ``text[start:end]``, without making its fields."""
    for piece in lexicon().run_piece.finditer(text, start, end):
        string = piece.group(2)
        if string is not None:
            for problem in string_problems(string, piece.start(2)):
                report(*problem)


# --- fields -------------------------------------------------------------------------------------


def scan_run(text: str, start: int, end: int, source: LineIndex, fields: list[Field], current: Field | None,
             flat: list[Field], report: Report | None = None, leading: list[Comment] | None = None) -> Field | None:
    """Split the RUN ``text[start:end]`` into ``fields``; returns the field still open at its end.

    ``flat`` receives every field in document order; a comment goes to the last field
    started (a RUN starts with a field, so one exists), or to ``leading`` while none has
    (:func:`entry_contents` scans the TRIVIA around the RUN too). This loop runs once per
    field of a RUN with strings or comments: keep it lean.
    """
    for piece in lexicon().run_piece.finditer(text, start, end):
        comment, string, raw, comma = piece.groups()
        if comment is not None:
            (flat[-1].comments if flat or leading is None else leading).append(
                Comment(comment[1:], piece.start(1), source))
            continue
        if string is not None or raw is not None:
            if current is not None:
                # The grammar puts a comma between items; stay safe all the same.
                fields.append(current)
            if string is not None:
                offset = piece.start(2)
                between: list[Comment] = []  # comments between the parts of a concatenated string
                current = Field(string_value(string, offset, between, source), between or None, offset, source)
                if report is not None:
                    for problem in string_problems(string, offset):
                        report(*problem)
            else:
                current = Field(scalar(raw), None, piece.start(3), source)
            flat.append(current)
        if comma is not None:
            if current is None:
                current = Field(None, None, piece.start(4), source)
                flat.append(current)
            fields.append(current)
            current = None
    return current


#: the white space of a gap between fields (grammar: _GAP), which ``str.strip()`` with no argument exceeds
GAP_CHARACTERS = " \t\n\f\v"
#: the white space of TRIVIA, which may also stand before and after a RUN: Ctrl-Z (end of file) too
TRIVIA_CHARACTERS = GAP_CHARACTERS + "\x1a"


def simple_pieces(body: str) -> list[str] | None:
    """The comma-separated pieces of an entry body (between ``=`` and ``;``), if splitting is exact.

    It is when the body holds no comment and no backslash and none of its strings holds a
    comma: then every comma separates fields. None otherwise (and when the quotes do not
    pair up, as when the ``;`` found is inside a string).
    """
    if "$" in body or "\\" in body:
        return None
    if '"' in body:
        segments = body.split('"')
        if not len(segments) % 2 or "," in "".join(segments[1::2]):
            return None
    return body.split(",")


def split_fields(pieces: list[str], start: int, closer: int, source: LineIndex) -> list[Field]:
    """The fields of a valid entry body split into ``pieces`` (:func:`simple_pieces`); it starts at ``start``.

    A field is a piece stripped of white space, in C instead of one regex match per
    field. An empty field stands at the comma that ends it; an empty last field at the
    ``closer`` (the ``;``).
    """
    fields: list[Field] = []
    append = fields.append
    position = start
    raw = ""
    for piece in pieces:
        raw = piece.strip(TRIVIA_CHARACTERS)  # the TRIVIA before and after the RUN may hold a Ctrl-Z
        if not raw:
            append(Field(None, None, position + len(piece), source))
        elif raw[-1] == '"':
            offset = position + piece.index(raw[0])
            append(Field(string_value(raw, offset, [], source), None, offset, source))  # no "$": no comment
        else:
            append(Field(scalar(raw), None, position + piece.index(raw[0]), source))
        position += len(piece) + 1
    if not raw:
        fields[-1].offset = closer
    return fields


def entry_contents(text: str, offset: int, end_offset: int, source: LineIndex,
                   trailing: Comment | None) -> tuple[list[Field], list[Comment]]:
    """The fields and comments of the brace-less entry ``text[offset:end_offset]`` (the reader matched it).

    ``trailing`` is the comment after its ``;`` on the same line, which the reader saw;
    it belongs to the last field, like every comment after the last field's start.
    """
    body_start = lexicon().statement_start.match(text, offset).end()  # type: ignore[union-attr]  # read so
    head = list(comments_in(text, offset, body_start, source))  # between the keyword and its "="
    closer = end_offset - 1
    pieces = simple_pieces(text[body_start:closer])
    if pieces is None:
        fields, comments = _scanned_contents(text, body_start, closer, source, trailing)
        return fields, head + comments
    simple = split_fields(pieces, body_start, closer, source)  # no comment inside
    if trailing is not None:
        simple[-1].comments.append(trailing)
    return simple, head


def _scanned_contents(text: str, body_start: int, closer: int, source: LineIndex,
                      trailing: Comment | None) -> tuple[list[Field], list[Comment]]:
    """:func:`entry_contents` of an entry with comments, or strings that hold commas or backslashes.

    The body is ``TRIVIA? RUN? TRIVIA?``; the TRIVIA holds only blanks and comments, which the
    RUN's regex reads as it reads those between fields, so the whole body is scanned as one: a
    comment goes to the last field that starts before it, or to the entry before the first.
    """
    fields: list[Field] = []
    flat: list[Field] = []
    comments: list[Comment] = []
    current = scan_run(text, body_start, closer, source, fields, None, flat, leading=comments)
    if current is None:
        current = Field(None, None, closer, source)
        flat.append(current)
    fields.append(current)
    if trailing is not None:
        flat[-1].comments.append(trailing)
    return fields, comments
