"""Bytes -> the syntax model with positions and diagnostics (grammar/eds.lark).

Most statements are simple: a section header, or an entry without braces. One regex,
composed from the grammar's own terminals as Lark's lexer meets them
(:func:`edsconv.eds.lexicon.statement_pattern`), matches each of them whole, and the
reader builds it directly; an entry keeps its place in the text and makes its fields
when they are first asked for (:class:`~edsconv.eds.syntax.Entry`). Statements with
braces, and syntax errors, go to Lark (:mod:`edsconv.eds.lark_reader`), which parses,
reports and recovers. ``tests/test_reader_paths.py`` proves that both ways give the same
model, positions and diagnostics as Lark reading the whole file.
"""

from __future__ import annotations

import contextlib
import gc
import re
from collections.abc import Callable, Iterator
from itertools import repeat
from pathlib import Path

from edsconv.diagnostics import Diagnostic
from edsconv.eds.lexicon import entry_keyword, lexicon
from edsconv.eds.reader_rules import CANOPEN_EDS, NO_SECTIONS, NOT_ASCII
from edsconv.eds.refusals import read_bytes, refusal
from edsconv.eds.runs import GAP_CHARACTERS, Report, check_strings, simple_pieces
from edsconv.eds.source import DecodedSource, LineIndex, decode
from edsconv.eds.statements import SyntaxBuilder
from edsconv.eds.syntax import EdsFile, Entry

_CANOPEN_SECTION = re.compile(r"^[ \t]*\[(?:FileInfo|DeviceInfo|MandatoryObjects|[0-9A-Fa-f]{4})\][ \t]*$",
                              re.MULTILINE | re.IGNORECASE)
#: How much of the file start is read to tell a CANopen EDS from a CIP EDS.
_SNIFF_LENGTH = 65536
_CIP_FILE_SECTION = re.compile(r"^[ \t]*\[File\]", re.MULTILINE)
#: What a statement Lark reads ends with: its first ";" outside braces, strings and comments.
_STATEMENT_END_PIECE = re.compile(r'L?"(?:[^"\\\n]++|\\.)*+"|\$[^\n]*|[{};]')


@contextlib.contextmanager
def paused_gc() -> Iterator[None]:
    """No cyclic garbage collection while a file's model is made.

    The syntax and semantic models are many small objects and no cycles: the collector
    would only rescan them again and again (45 % of a 50 MB read; a third of the
    analysis when the fields are made then).
    """
    collecting = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if collecting:
            gc.enable()


def parse(source: str | bytes, filename: str | None = None) -> EdsFile:
    """Read an EDS from text or bytes; never raises for bad input, reports diagnostics."""
    with paused_gc():
        return _parse(source, filename, _read)


def parse_with_lark(source: str | bytes, filename: str | None = None) -> EdsFile:
    """:func:`parse` with every statement read by Lark: the reference :func:`parse` is tested against."""
    from edsconv.eds.lark_reader import read_all

    return _parse(source, filename, read_all)


def load(path: str | Path) -> EdsFile:
    """Read an EDS file from disk (see :func:`parse`)."""
    return parse(read_bytes(path), str(path))


def _not_ascii_message(decoded: DecodedSource) -> str:
    if decoded.encoding.startswith(("utf-16", "utf-32")):
        return (f"the file is saved as {decoded.encoding.upper()} (it starts with a byte order mark); "
                "an EDS is ASCII text, so other tools may not read it")
    return (f"the file is not plain ASCII (read as {decoded.encoding}); the first character outside "
            f"ASCII is on line {decoded.first_non_ascii_line}")


def _parse(source: str | bytes, filename: str | None, read) -> EdsFile:
    data = source.encode("utf-8") if isinstance(source, str) else source
    del source
    refused = refusal(data)
    if refused is not None:  # too large, binary, UTF-16 without BOM, XML: one diagnostic, nothing read
        eds = SyntaxBuilder("", filename, LineIndex("")).eds
        eds.diagnostics.append(Diagnostic.of(*refused, 1, 1, filename))
        return eds
    decoded = decode(data)
    del data  # the bytes are not needed once decoded
    text = decoded.text
    builder = SyntaxBuilder(text, filename, LineIndex(text))
    eds = builder.eds
    eds.encoding, eds.newline = decoded.encoding, decoded.newline
    if decoded.first_non_ascii_line is not None:
        eds.diagnostics.append(Diagnostic.of(
            NOT_ASCII, _not_ascii_message(decoded), decoded.first_non_ascii_line, 1, filename))
    if _canopen(text):
        builder.report(CANOPEN_EDS, "this is a CANopen EDS (CiA 306: [FileInfo], [DeviceInfo], object "
                       "sections such as [1000]); edsconv reads CIP EDS files (ISO 15745-4 Annex C.4)", 0)
        return eds
    read(builder)
    builder.finish()
    if not eds.sections and not eds.has_errors:
        eds.diagnostics.append(Diagnostic.of(NO_SECTIONS, "the file holds no [Section]", 1, 1, filename))
    return eds


def _canopen(text: str) -> bool:
    """Whether the start of ``text`` says it is a CANopen EDS (and not a CIP one)."""
    head = text[:_SNIFF_LENGTH]
    return not _CIP_FILE_SECTION.search(head) and _CANOPEN_SECTION.search(head) is not None


def read_statement_by_statement(raw: str, text: str) -> bool:
    """Whether :func:`parse` reads the ASCII ``raw`` statement by statement: it refuses it not, nor
    takes ``text``, what it decodes ``raw`` to, for a CANopen EDS."""
    return refusal(raw.encode("ascii")) is None and not _canopen(text)


def simple_entry_at(text: str, offset: int) -> tuple[str, int, int] | None:
    """``(keyword, body start, end)`` of the entry that starts at ``offset`` when the reader, coming to
    it, reads it as a simple statement and reports nothing in it (:func:`_read_simple_statements`);
    None when it does not (an entry with braces, a syntax error, a string with a problem)."""
    lex = lexicon()
    head = lex.statement_start.match(text, offset)
    if head is None or head.start("entry") != offset:
        return None
    end = _simple_entry_end(text, head.end(), lex.item.fullmatch, set())
    problems: list[object] = []
    if end < 0:
        end = _matched_statement_end(text, offset, lambda *problem: problems.append(problem))
    return None if end < 0 or problems else (entry_keyword(head.group("entry")), head.end(), end)


def _matched_statement_end(text: str, position: int, report: Report) -> int:
    """Just after the simple statement the grammar's statement pattern matches at ``position`` (after
    its TRIVIA), its strings' problems given to ``report``; -1 when the pattern does not match."""
    statement = lexicon().statement.match(text, position)
    if statement is None:
        return -1
    run_start, run_end = statement.span("run")
    if run_start >= 0 and (text.find("\\", run_start, run_end) != -1 or text.find('L"', run_start, run_end) != -1):
        check_strings(text, run_start, run_end, report)
    return statement.end()


def _read(builder: SyntaxBuilder) -> None:
    """Simple statements here, the others by Lark, each from where the last one ended."""
    read_on(builder, 0)


def read_on(builder: SyntaxBuilder, position: int) -> int | None:
    """Read the statements from ``position`` on (the text's start, or the end of a line after a statement
    of the builder's section): to the text's end (None), or to where the builder says to stop
    (:attr:`SyntaxBuilder.stops`), the end of the last statement read (returned); None also when a
    statement for Lark ends past ``builder.give_up_at``."""
    text = builder.text
    tail = lexicon().tail
    errors = 0
    resumed: int | None = position
    while resumed is not None:
        position = _read_simple_statements(builder, resumed)
        if builder.stopped:
            return position
        if tail.match(text, position):
            builder.take_comments(position, len(text))
            return None
        from edsconv.eds import lark_reader

        end = _statement_end(text, position)
        if end > builder.give_up_at:
            return None
        if lark_reader.read_region(builder, position, end):
            resumed = end
        else:
            resumed, errors = lark_reader.recover(builder, position, errors)
    return None


def _read_simple_statements(builder: SyntaxBuilder, position: int) -> int:
    """Read simple statements from ``position`` on; returns where the first other one starts.

    This loop runs once per statement of the file: keep it lean.
    """
    text, lines = builder.text, builder.lines
    lex = lexicon()
    match, find = lex.statement_start.match, text.find
    stop_from, stops, header_stop = builder.stop_from, builder.stops, builder.header_stop
    known: set[str] = set()
    while True:
        if position >= stop_from and stops(position):
            builder.stopped = True
            return position
        head = match(text, position)
        if head is None:
            return position
        start = head.start("entry")
        if start < 0:  # a section header
            start = head.start("section")
            if start == header_stop:
                builder.stopped = True
                return position
            if find("$", position, start) != -1:
                builder.take_comments(position, start)
            builder.add_section(head.group("section"), start, head.end())
            position = head.end()
            continue
        end = _simple_entry_end(text, head.end(), lex.item.fullmatch, known)
        if end < 0:
            end = _matched_statement_end(text, position, builder.report)
            if end < 0:
                return position
        if find("$", position, start) != -1:
            builder.take_comments(position, start)
        keyword = entry_keyword(head.group("entry"))
        builder.add_entry(Entry.unread(keyword, start, end, lines), None)
        position = end


#: how many field spellings :func:`_simple_entry_end` remembers as valid (a set of short strings)
_KNOWN_LIMIT = 20000


def _simple_entry_end(text: str, body_start: int, item: Callable[[str], object], known: set[str]) -> int:
    """Just after the ``;`` of an entry whose body splits at its commas into fields that are each
    a STRING, a SCALAR or nothing (:func:`edsconv.eds.runs.simple_pieces`); -1 for other entries.

    Such a body is ``TRIVIA? RUN? TRIVIA?`` exactly as Lark's lexer reads it. The check runs in C
    (split, strip, set lookups) where the grammar's RUN regex backtracks through every field:
    only spellings not seen before in the file (``known``) are matched against the grammar's
    terminals. Strings with an ``L`` prefix are left to that regex, which reports a misplaced one.
    """
    closer = text.find(";", body_start)
    if closer < 0:
        return -1
    body = text[body_start:closer]
    pieces = simple_pieces(body)
    if pieces is None or 'L"' in body:
        return -1
    spellings = set(map(str.strip, pieces, repeat(GAP_CHARACTERS)))
    if not known.issuperset(spellings):
        new = spellings - known
        if not all(map(item, new)):
            return -1
        if len(known) > _KNOWN_LIMIT:
            known.clear()
        known.update(new)
    return closer + 1


def _statement_end(text: str, start: int) -> int:
    """Just after the first ``;`` from ``start`` on outside braces, strings and comments (else the text's end)."""
    depth = 0
    for piece in _STATEMENT_END_PIECE.finditer(text, start):
        token = piece.group()
        if token == "{":
            depth += 1
        elif token == "}":
            depth = max(depth - 1, 0)
        elif token == ";" and depth == 0:
            return piece.end()
    return len(text)
