"""Bytes -> parse tree (grammar/eds.lark) -> syntax model with positions.

The grammar is compiled once per process (and cached on disk by Lark). Lark
applies :class:`_Builder` while it parses, so entries become model objects as
they are reduced and no parse tree is kept. A syntax error never stops the
read: a missing ``;`` is inserted and reported; any other error is reported,
the text up to the next ``;`` or statement start is kept verbatim as
:class:`~edsconv.eds.syntax.Unparsed`, and parsing resumes there.
"""

from __future__ import annotations

import bisect
import contextlib
import gc
import re
import threading
from pathlib import Path

from lark import Lark, Token, Transformer
from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, UnexpectedToken

from edsconv import spec_tables as tables
from edsconv.diagnostics import Diagnostic, Rule
from edsconv.eds.lexicon import grammar_text, lexicon, undefined_escapes
from edsconv.eds.reader_rules import (
    BAD_ESCAPE,
    CANOPEN_EDS,
    DUPLICATE_ENTRY,
    DUPLICATE_SECTION,
    ENTRY_OUTSIDE_SECTION,
    LONG_PREFIX_ON_CONTINUATION,
    MISSING_COMMA,
    MISSING_SEMICOLON,
    NO_SECTIONS,
    NOT_ASCII,
    SECTION_NAME,
    SYNTAX_ERROR,
    TOO_DEEP,
    TOO_MANY_ERRORS,
    UNICODE_ESCAPE_IN_ASCII,
    UNTERMINATED_STRING,
)
from edsconv.eds.source import DecodedSource, LineIndex, decode
from edsconv.eds.syntax import (
    Comment,
    EdsFile,
    Entry,
    Field,
    Group,
    Scalar,
    Section,
    String,
    Unparsed,
)

#: Syntax errors reported per file before the reader gives up (an assumed ';' included).
MAX_SYNTAX_ERRORS = 100
#: Brace groups nested deeper than this are kept as text: real files nest 3
#: deep, and a bound keeps every recursive walk of the model far from Python's
#: recursion limit.
MAX_BRACE_DEPTH = 64

_COMMENT = re.compile(r"\$[^\n]*")
_WHITESPACE_AND_COMMENTS = re.compile(r"(?:[ \t\n\f\v\x1a]++|\$[^\n]*+)*+")
_CANOPEN_SECTION = re.compile(r"^[ \t]*\[(?:FileInfo|DeviceInfo|MandatoryObjects|[0-9A-Fa-f]{4})\][ \t]*$",
                              re.MULTILINE | re.IGNORECASE)
#: How much of the file start is read to tell a CANopen EDS from a CIP EDS.
_SNIFF_LENGTH = 65536
_CIP_FILE_SECTION = re.compile(r"^[ \t]*\[File\]", re.MULTILINE)
# Where parsing resumes after an error: after the next ';', or at a line that
# starts a section or an entry. Strings and comments are stepped over whole.
_RESYNC = re.compile(r'L?"(?:[^"\\\n]++|\\.)*+"?|\$[^\n]*|;|\n(?=[ \t]*(?:\[|[A-Za-z0-9_]+[ \t]*=))')

#: Words a device engineer understands, for the terminals the parser expected.
_EXPECTED_WORDS = {
    "SEMICOLON": "';'",
    "LBRACE": "'{'",
    "RBRACE": "'}'",
    "RUN": "a field value or ','",
    "ENTRY_START": "an entry 'Keyword ='",
    "SECTION": "a section header '[Name]'",
    "$END": "the end of the file",
}


_local = threading.local()


def _parser() -> tuple[Lark, _Builder]:
    """One Lark parser and its builder per thread: Lark binds both at construction."""
    cached = getattr(_local, "parser", None)
    if cached is None:
        builder = _Builder()
        lark = Lark(
            grammar_text(),
            parser="lalr",
            lexer="contextual",
            transformer=builder,
            lexer_callbacks={"TRIVIA": builder.on_trivia},
            cache=True,
        )
        cached = _local.parser = (lark, builder)
    return cached


class _Builder(Transformer):
    """Builds the syntax model while Lark reduces rules (inline transformer)."""

    def reset(self, text: str, path: str | None, lines: LineIndex) -> None:
        self.text = text
        self.path = path
        self.lines = lines
        self.base = 0
        self.lexicon = lexicon()
        self.eds = EdsFile(path=path)
        # the section being read; not named `section`, which is the rule callback Lark calls
        self.current_section: Section | None = None
        self.seen_sections: dict[str, Section] = {}
        self.seen_entries: dict[str, Entry] = {}
        # (offset, Comment) for the comments between tokens, attached at the end
        self.comments: list[tuple[int, Comment]] = []
        # (start, end of its last line, node, every field in document order) per statement
        self.statements: list[tuple[int, int, Section | Entry | Unparsed, list[Field]]] = []
        self.last_end = 0
        self.unparsed_ranges: list[tuple[int, int]] = []

    # --- diagnostics and positions -------------------------------------------------
    def token_start(self, token: Token) -> int:
        """Offset of a token in the whole text (tokens of the lexer always carry positions)."""
        return self.base + (token.start_pos or 0)

    def token_end(self, token: Token) -> int:
        return self.base + (token.end_pos or 0)

    def report(self, rule_, message: str, offset: int) -> None:
        line, column = self.lines.position(offset)
        self.eds.diagnostics.append(Diagnostic.of(rule_, message, line, column, self.path))

    def on_trivia(self, token: Token) -> None:
        """Comments between tokens; their owners are known only after the parse."""
        if "$" in token.value:
            start = self.token_start(token)
            for comment in _COMMENT.finditer(token.value):
                offset = start + comment.start()
                self.comments.append((offset, Comment(comment.group()[1:], offset, self.lines)))

    # --- rules ---------------------------------------------------------------------
    def start(self, children: list) -> None:
        return None

    def section(self, children: list[Token]) -> None:
        token = children[0]
        start = self.token_start(token)
        name = token.value[1:-1]
        section = Section(name=name.strip(), offset=start, source=self.lines)
        if not tables.SECTION_KEYWORD_RE.fullmatch(name):
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
        self._record_statement(start, self.token_end(token), section, [])

    def entry(self, children: list) -> None:
        start_token, semicolon = children[0], children[-1]
        start = self.base + start_token.start_pos
        match = self.lexicon.entry_keyword.match(start_token.value)
        keyword = match.group() if match else start_token.value  # ENTRY_START begins with its keyword
        end = self.base + semicolon.end_pos
        depth = max((child[4] for child in children[1:-1] if isinstance(child, tuple)), default=0)
        if depth > MAX_BRACE_DEPTH:
            self.report(TOO_DEEP, f"{keyword} nests braces {depth} deep (at most {MAX_BRACE_DEPTH} are read); "
                        "the entry is kept as text", start)
            self.keep_unparsed(start, end)
            return
        flat: list[Field] = []
        fields = self.fields(children[1:-1], self.base + semicolon.start_pos, flat)
        entry = Entry(keyword, fields, offset=start, end_offset=end, source=self.lines)
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
        self._record_statement(start, end, entry, flat)

    def group(self, children: list) -> tuple[Group, int, int, list, int]:
        open_brace, close_brace = children[0], children[-1]
        inner = children[1:-1]
        depth = 1 + max((child[4] for child in inner if isinstance(child, tuple)), default=0)
        # The fields are built by the enclosing entry, in document order.
        return Group([]), self.base + open_brace.start_pos, self.base + close_brace.start_pos, inner, depth

    def _record_statement(self, start: int, end: int, node, flat: list[Field]) -> None:
        line_end = self.text.find("\n", end)
        self.statements.append((start, len(self.text) if line_end == -1 else line_end, node, flat))
        self.last_end = end

    # --- fields --------------------------------------------------------------------
    def fields(self, content: list, closer: int, flat: list[Field]) -> list[Field]:
        """Turn the RUN tokens and groups of an entry or group into fields.

        ``closer`` is the offset of the ';' or '}' that ends the list: an empty
        last field is placed there. ``flat`` receives every field of the entry
        in document order, for comment attachment.
        """
        fields: list[Field] = []
        current: Field | None = None
        lines = self.lines
        for child in content:
            if isinstance(child, Token):
                current = self.scan_run(child, fields, current, flat)
                continue
            group, start, close, inner, _ = child
            if current is not None:
                self.report(MISSING_COMMA, "a ',' is missing before this '{'", start)
                fields.append(current)
            current = Field(group, [], start, lines)
            flat.append(current)
            group.fields = self.fields(inner, close, flat)
        if current is None:
            current = Field(None, [], closer, lines)
            flat.append(current)
        fields.append(current)
        return fields

    def scan_run(self, token: Token, fields: list[Field], current: Field | None, flat: list[Field]) -> Field | None:
        """Split one RUN token into fields; returns the field still open at its end.

        This loop runs once per field of the file: keep it lean.
        """
        lines = self.lines
        for piece in self.lexicon.run_piece.finditer(self.text, self.token_start(token), self.token_end(token)):
            comment, string, scalar, comma = piece.groups()
            if comment is not None:
                # A RUN starts with a field, so one exists, and the last one
                # started is the owner: attach now, sorting is not needed.
                flat[-1].comments.append(Comment(comment[1:], piece.start(1), lines))
                continue
            if string is not None or scalar is not None:
                if current is not None:
                    # The grammar puts a comma between items; stay safe all the same.
                    fields.append(current)
                if string is not None:
                    offset = piece.start(2)
                    current = Field(None, [], offset, lines)
                    current.value = self.string(string, offset, current.comments)
                else:
                    current = Field(Scalar(scalar), [], piece.start(3), lines)
                flat.append(current)
            if comma is not None:
                if current is None:
                    current = Field(None, [], piece.start(4), lines)
                    flat.append(current)
                fields.append(current)
                current = None
        return current

    def string(self, raw: str, offset: int, comments: list[Comment]) -> String:
        """The String of a STRING token; comments between its parts go to ``comments``."""
        if '"' in raw[1:-1] or "$" in raw:
            parts = []
            for piece in self.lexicon.string_piece.finditer(raw):
                if piece.group(2) is not None:
                    comments.append(Comment(piece.group()[1:], offset + piece.start(), self.lines))
                else:
                    parts.append(piece.group())
                    if len(parts) > 1 and piece.group().startswith("L"):
                        self.report(LONG_PREFIX_ON_CONTINUATION, "only the first part of a concatenated string "
                                    "may carry the L prefix", offset + piece.start())
        else:
            parts = [raw]
        if "\\" in raw:
            self.check_escapes(raw, offset, parts[0].startswith("L"))
        return String(tuple(parts))

    def check_escapes(self, raw: str, offset: int, unicode: bool) -> None:
        for at, sequence, defined in undefined_escapes(raw, unicode):
            if not defined:
                self.report(BAD_ESCAPE, f"escape sequence {sequence!r} is not defined in Table C.4; the "
                            "string is rejected (write '\\\\' for a backslash)", offset + at)
            else:
                self.report(UNICODE_ESCAPE_IN_ASCII, "\\u escapes are valid only in L\"...\" (UNICODE) "
                            "strings", offset + at)

    # --- after the parse -----------------------------------------------------------
    def attach_comments(self) -> None:
        statements = self.statements
        statement_starts = [s[0] for s in statements]
        leading: dict[int, list[Comment]] = {}
        self.comments.sort(key=lambda item: item[0])
        for offset, comment in self.comments:
            if any(low <= offset < high for low, high in self.unparsed_ranges):
                continue  # part of the text kept verbatim
            index = bisect.bisect_right(statement_starts, offset) - 1
            if index >= 0 and offset < statements[index][1]:
                _, _, node, flat = statements[index]
                field_index = bisect.bisect_right(flat, offset, key=_offset_of) - 1
                (flat[field_index].comments if field_index >= 0 else node.comments).append(comment)
            elif index + 1 < len(statements):
                leading.setdefault(index + 1, []).append(comment)
            else:
                self.eds.trailing_comments.append(comment)
        for index, comments in leading.items():
            statements[index][2].leading_comments.extend(comments)

    def keep_unparsed(self, start: int, end: int) -> None:
        blank = _WHITESPACE_AND_COMMENTS.match(self.text, start, end)  # matches, if only the empty string
        start = blank.end() if blank else start
        if start >= end:
            return
        self.unparsed_ranges.append((start, end))
        section = self.current_section
        if section is None:
            section = self.eds.preamble = self.eds.preamble or Section(name="", offset=start, source=self.lines)
        unparsed = Unparsed(self.text[start:end].rstrip(), offset=start, source=self.lines)
        section.unparsed.append((len(section.entries), unparsed))
        self._record_statement(start, end, unparsed, [])


def _offset_of(field: Field) -> int:
    return field.offset


def _describe(token: Token) -> str:
    if token.type == "$END":
        return "the end of the file"
    value = token.value.strip()
    if len(value) > 30:
        value = value[:27] + "..."
    return repr(value)


def _expected(expected: set[str]) -> str:
    words = sorted({_EXPECTED_WORDS.get(name, name) for name in expected})
    if len(words) <= 1:
        return words[0] if words else "something else"
    return ", ".join(words[:-1]) + " or " + words[-1]


def parse(source: str | bytes, filename: str | None = None) -> EdsFile:
    """Read an EDS from text or bytes; never raises for bad input, reports diagnostics."""
    # The model is millions of small objects and no cycles: the cyclic garbage
    # collector would only rescan them again and again (45% of a 50 MB read).
    collecting = gc.isenabled()
    gc.disable()
    try:
        return _parse(source, filename)
    finally:
        if collecting:
            gc.enable()


def _not_ascii_message(decoded: DecodedSource) -> str:
    if decoded.encoding.startswith(("utf-16", "utf-32")):
        return (f"the file is saved as {decoded.encoding.upper()} (it starts with a byte order mark); "
                "an EDS is ASCII text, so other tools may not read it")
    return (f"the file is not plain ASCII (read as {decoded.encoding}); the first character outside "
            f"ASCII is on line {decoded.first_non_ascii_line}")


def _parse(source: str | bytes, filename: str | None) -> EdsFile:
    if isinstance(source, str):
        source = source.encode("utf-8")
    decoded = decode(source)
    text = decoded.text
    lines = LineIndex(text)
    lark, builder = _parser()
    builder.reset(text, filename, lines)
    eds = builder.eds
    eds.encoding, eds.newline = decoded.encoding, decoded.newline
    if decoded.first_non_ascii_line is not None:
        eds.diagnostics.append(Diagnostic.of(
            NOT_ASCII, _not_ascii_message(decoded), decoded.first_non_ascii_line, 1, filename))
    head = text[:_SNIFF_LENGTH]
    if _CANOPEN_SECTION.search(head) and not _CIP_FILE_SECTION.search(head):
        builder.report(CANOPEN_EDS, "this is a CANopen EDS (CiA 306: [FileInfo], [DeviceInfo], object "
                       "sections such as [1000]); edsconv reads CIP EDS files (ISO 15745-4 Annex C.4)", 0)
        return eds
    _parse_with_recovery(lark, builder, text)
    builder.attach_comments()
    if not eds.sections and not eds.has_errors:
        eds.diagnostics.append(Diagnostic.of(NO_SECTIONS, "the file holds no [Section]", 1, 1, filename))
    return eds


def _parse_with_recovery(lark: Lark, builder: _Builder, text: str) -> None:
    errors = 0
    resume = 0

    def on_error(error: UnexpectedInput) -> bool:
        """Insert a missing ';' and go on; otherwise keep what is complete and give up."""
        nonlocal errors
        accepted = error.interactive_parser.accepts() if isinstance(error, UnexpectedToken) else set()
        # an inserted ';' counts as an error too: each restarts the parser (0.2 ms for 5 bytes)
        if not (isinstance(error, UnexpectedToken) and error.token.type in ("ENTRY_START", "SECTION", "$END")
                and "SEMICOLON" in accepted and errors + 1 < MAX_SYNTAX_ERRORS):
            error.accepted = accepted  # type: ignore[attr-defined]  # for the message: the reduction spends the parser
            _reduce_complete_statements(error)
            return False
        stack = error.interactive_parser.parser_state.value_stack
        last = stack[-1] if stack else None
        if isinstance(last, Token):
            after = builder.token_end(last)
        elif isinstance(last, tuple):
            after = last[2] + 1
        else:
            after = builder.base + (error.token.start_pos or len(text) - builder.base)
        builder.report(MISSING_SEMICOLON, "the entry is not ended by ';' before "
                       f"{_describe(error.token)}; a ';' is assumed here", after)
        # Zero-width, at the end of the last field, so positions stay truthful.
        error.interactive_parser.feed_token(
            Token("SEMICOLON", ";", start_pos=after - builder.base, end_pos=after - builder.base))
        if error.token.type != "$END":  # Lark feeds $END itself when the parse resumes
            error.interactive_parser.feed_token(error.token)
        errors += 1
        return True

    while True:
        builder.base = resume
        try:
            lark.parse(text[resume:] if resume else text, on_error=on_error)
            return
        except UnexpectedInput as error:
            errors += 1
            position = _error_offset(error, text, resume)
            builder.report(*_error_message(error, text, position), position)
            if errors >= MAX_SYNTAX_ERRORS:
                builder.report(TOO_MANY_ERRORS, f"{errors} syntax errors; the rest of the file is not read",
                               position)
                builder.keep_unparsed(builder.last_end, len(text))
                return
            resume = _resync(text, position, _starts_statement(error))
            builder.keep_unparsed(builder.last_end, resume)


def _reduce_complete_statements(error: UnexpectedInput) -> None:
    """Let the parser reduce a statement that was complete before the error.

    LALR reduces an entry only when it sees the token after its ';'; when that
    token is the error, the entry would be lost. Feeding the end of input
    reduces it (the builder records it). The parser is abandoned afterwards, so
    it is fed as it is: Lark's copy() would lose the tokens' end positions.
    """
    parser = getattr(error, "interactive_parser", None)
    if parser is None:
        return
    with contextlib.suppress(UnexpectedInput):  # the text before the error ends inside an entry
        parser.feed_eof()


def _error_offset(error: UnexpectedInput, text: str, base: int) -> int:
    if isinstance(error, UnexpectedCharacters):
        return base + (error.pos_in_stream or 0)
    if isinstance(error, UnexpectedToken) and error.token.start_pos is not None:
        return base + error.token.start_pos
    return len(text)


def _error_message(error: UnexpectedInput, text: str, position: int) -> tuple[Rule, str]:
    if isinstance(error, UnexpectedCharacters):
        character = text[position]
        if character == '"':
            return UNTERMINATED_STRING, "this string has no closing '\"' on its line"
        allowed = getattr(error, "allowed", None) or set()
        line_text = text[position:text.find("\n", position) if "\n" in text[position:] else len(text)]
        snippet = line_text.strip()[:30]
        return SYNTAX_ERROR, (f"unexpected {snippet!r}: expected {_expected(allowed)}" if allowed
                              else f"unexpected {snippet!r}")
    if isinstance(error, UnexpectedEOF):
        return SYNTAX_ERROR, f"the file ends early: expected {_expected(set(error.expected))}"
    assert isinstance(error, UnexpectedToken)
    if error.token.type == "RUN" and "SEMICOLON" in error.expected:
        return MISSING_COMMA, f"a ',' is missing before {_describe(error.token)}"
    # accepts() asks the parser state itself; ``expected`` is blurred by LALR's merged states.
    accepted = getattr(error, "accepted", None)
    if accepted is None:
        accepted = error.interactive_parser.accepts()
    return SYNTAX_ERROR, f"unexpected {_describe(error.token)}: expected {_expected(accepted)}"


def _starts_statement(error: UnexpectedInput) -> bool:
    """True when the unexpected token is a section header or an entry start (an
    unclosed brace before it): reading resumes with it rather than after it."""
    return isinstance(error, UnexpectedToken) and error.token.type in ("SECTION", "ENTRY_START")


def _resync(text: str, position: int, at_position: bool = False) -> int:
    if at_position:
        return position
    for match in _RESYNC.finditer(text, position):
        token = match.group()
        if token == ";":
            return match.end()
        if token == "\n" and match.start() > position:
            return match.end()
    return len(text)


def load(path: str | Path) -> EdsFile:
    """Read an EDS file from disk (see :func:`parse`)."""
    path = Path(path)
    return parse(path.read_bytes(), str(path))
