"""Statements read by Lark with grammar/eds.lark: brace groups, syntax errors and their recovery.

The grammar is compiled once per process (and cached on disk by Lark). Lark applies
:class:`_Callbacks` while it parses, so entries become model objects as they are
reduced and no parse tree is kept. A syntax error never stops the read: a missing
``;`` is inserted and reported; any other error is reported, the text up to the next
``;`` or statement start is kept verbatim as :class:`~edsconv.eds.syntax.Unparsed`,
and reading resumes there.

:func:`read_all` reads a whole file this way: it is the reference the fast reader
(:mod:`edsconv.eds.reader`) is tested against.
"""

from __future__ import annotations

import contextlib
import re
import threading

from lark import Lark, Token
from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, UnexpectedToken

from edsconv.diagnostics import Rule
from edsconv.eds.lexicon import entry_keyword, grammar_text
from edsconv.eds.reader_rules import (
    MISSING_COMMA,
    MISSING_SEMICOLON,
    SYNTAX_ERROR,
    TOO_DEEP,
    TOO_MANY_ERRORS,
    UNTERMINATED_STRING,
)
from edsconv.eds.runs import comments_in, scan_run
from edsconv.eds.statements import SyntaxBuilder
from edsconv.eds.syntax import Entry, Field, Group
from edsconv.limits import shown

#: Syntax errors reported per file before the reader gives up (an assumed ';' included).
MAX_SYNTAX_ERRORS = 100
#: Brace groups nested deeper than this are kept as text: real files nest 3
#: deep, and a bound keeps every recursive walk of the model far from Python's
#: recursion limit.
MAX_BRACE_DEPTH = 64

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


def _parser() -> tuple[Lark, _Callbacks]:
    """One Lark parser and its callbacks per thread: Lark binds both at construction."""
    cached = getattr(_local, "parser", None)
    if cached is None:
        callbacks = _Callbacks()
        lark = Lark(grammar_text(), parser="lalr", lexer="contextual", transformer=callbacks,
                    lexer_callbacks={"TRIVIA": callbacks.on_trivia}, cache=True)
        cached = _local.parser = (lark, callbacks)
    return cached


class _Callbacks:
    """Lark's inline transformer: hands every statement Lark reduces to the current builder."""

    builder: SyntaxBuilder

    def start_of(self, token: Token) -> int:
        """Offset of a token in the whole text (tokens of the lexer always carry positions)."""
        return self.builder.base + (token.start_pos or 0)

    def end_of(self, token: Token) -> int:
        return self.builder.base + (token.end_pos or 0)

    def on_trivia(self, token: Token) -> None:
        if "$" in token.value:
            self.builder.take_comments(self.start_of(token), self.end_of(token))

    # --- rules ---------------------------------------------------------------------------------
    def start(self, children: list) -> None:
        return None

    def section(self, children: list[Token]) -> None:
        token = children[0]
        self.builder.add_section(token.value, self.start_of(token), self.end_of(token))

    def entry(self, children: list) -> None:
        builder = self.builder
        start_token, semicolon = children[0], children[-1]
        start, end = self.start_of(start_token), self.end_of(semicolon)
        keyword = entry_keyword(start_token.value)
        depth = max((child[4] for child in children[1:-1] if isinstance(child, tuple)), default=0)
        if depth > MAX_BRACE_DEPTH:
            builder.report(TOO_DEEP, f"{keyword} nests braces {depth} deep (at most {MAX_BRACE_DEPTH} are read); "
                           "the entry is kept as text", start)
            builder.keep_unparsed(start, end)
            return
        flat: list[Field] = []
        fields = self.fields(children[1:-1], self.start_of(semicolon), flat)
        head = list(comments_in(builder.text, start, start + len(start_token.value), builder.lines)) \
            if "$" in start_token.value else None  # between the keyword and its "=": before the first field
        builder.add_entry(Entry(keyword, fields, head, offset=start, end_offset=end, source=builder.lines), flat)

    def group(self, children: list) -> tuple[Group, int, int, list, int]:
        open_brace, close_brace = children[0], children[-1]
        inner = children[1:-1]
        depth = 1 + max((child[4] for child in inner if isinstance(child, tuple)), default=0)
        # The fields are built by the enclosing entry, in document order.
        return Group([]), self.start_of(open_brace), self.start_of(close_brace), inner, depth

    def fields(self, content: list, closer: int, flat: list[Field]) -> list[Field]:
        """Turn the RUN tokens and groups of an entry or group into fields.

        ``closer`` is the offset of the ';' or '}' that ends the list: an empty
        last field is placed there. ``flat`` receives every field of the entry
        in document order, for comment attachment.
        """
        builder = self.builder
        fields: list[Field] = []
        current: Field | None = None
        for child in content:
            if isinstance(child, Token):
                current = scan_run(builder.text, self.start_of(child), self.end_of(child), builder.lines, fields,
                                   current, flat, builder.report)
                continue
            group, start, close, inner, _ = child
            if current is not None:
                builder.report(MISSING_COMMA, "a ',' is missing before this '{'", start)
                fields.append(current)
            current = Field(group, None, start, builder.lines)
            flat.append(current)
            group.fields = self.fields(inner, close, flat)
        if current is None:
            current = Field(None, None, closer, builder.lines)
            flat.append(current)
        fields.append(current)
        return fields


# --- one statement -------------------------------------------------------------------------------


def read_region(builder: SyntaxBuilder, start: int, end: int) -> bool:
    """Read ``text[start:end]``, statements that end there, with Lark; False (and nothing kept) on an error.

    The reader gives a statement it cannot match to Lark up to the first ``;`` outside braces,
    strings and comments. Read alone, that text yields the tokens and reductions it yields
    within the whole file, as long as it parses: every token but the final ``;`` ends before
    it, and at ``start`` and ``end`` the parser stands between statements either way.
    """
    lark, callbacks = _parser()
    callbacks.builder = builder
    builder.base = start
    pending = len(builder.pending)
    try:
        lark.parse(builder.text[start:end])
    except UnexpectedInput:
        del builder.pending[pending:]  # the reduced statements are none: the first ';' was not reached
        return False
    return True


class _Resume(Exception):  # noqa: N818 - a signal, not an error
    """Raised by the error handler to stop Lark once an error is dealt with: reading resumes at ``offset``."""

    def __init__(self, offset: int) -> None:
        super().__init__(offset)
        self.offset = offset


def recover(builder: SyntaxBuilder, start: int, errors: int, *, to_the_end: bool = False) -> tuple[int | None, int]:
    """Read from ``start`` with Lark past the first syntax error; (where to resume or None at the end, errors).

    A missing ``;`` is inserted and reported. Any other error is reported and the text up to
    the next ``;`` or statement start kept as text. With ``to_the_end`` Lark reads on after an
    inserted ``;`` (as :func:`read_all` does); else the reader takes over at the next statement.
    """
    lark, callbacks = _parser()
    callbacks.builder = builder
    builder.base = start
    text = builder.text
    counted = [errors]  # the handler counts each ';' it assumes: each restarts the parser (0.2 ms for 5 bytes)
    try:
        lark.parse(text[start:] if start else text, on_error=_error_handler(builder, to_the_end, counted))
        return None, counted[0]
    except _Resume as resume:
        return resume.offset, counted[0]
    except UnexpectedInput as error:
        errors = counted[0] + 1
        position = _error_offset(error, text, start)
        builder.report(*_error_message(error, text, position), position)
        if errors >= MAX_SYNTAX_ERRORS:
            builder.report(TOO_MANY_ERRORS, f"{errors} syntax errors; the rest of the file is not read", position)
            builder.keep_unparsed(builder.last_end, len(text))
            return None, errors
        resume_at = _resync(text, position, _starts_statement(error))
        builder.keep_unparsed(builder.last_end, resume_at)
        return resume_at, errors


def read_all(builder: SyntaxBuilder) -> None:
    """Read the whole text with Lark (the reference for the fast reader)."""
    position: int | None = 0
    errors = 0
    while position is not None:
        position, errors = recover(builder, position, errors, to_the_end=True)


def _error_handler(builder: SyntaxBuilder, to_the_end: bool, counted: list[int]):
    def on_error(error: UnexpectedInput) -> bool:
        """Insert a missing ';' and go on; otherwise keep what is complete and give up."""
        accepted = error.interactive_parser.accepts() if isinstance(error, UnexpectedToken) else set()
        if not (isinstance(error, UnexpectedToken) and error.token.type in ("ENTRY_START", "SECTION", "$END")
                and "SEMICOLON" in accepted and counted[0] + 1 < MAX_SYNTAX_ERRORS):
            error.accepted = accepted  # type: ignore[attr-defined]  # for the message: the reduction spends the parser
            _reduce_complete_statements(error)
            return False
        stack = error.interactive_parser.parser_state.value_stack
        last = stack[-1] if stack else None
        if isinstance(last, Token):
            after = builder.base + (last.end_pos or 0)
        elif isinstance(last, tuple):
            after = last[2] + 1
        else:
            after = builder.base + (error.token.start_pos or len(builder.text) - builder.base)
        builder.report(MISSING_SEMICOLON, "the entry is not ended by ';' before "
                       f"{_describe(error.token)}; a ';' is assumed here", after)
        counted[0] += 1
        # Zero-width, at the end of the last field, so positions stay truthful.
        parser = error.interactive_parser
        parser.feed_token(Token("SEMICOLON", ";", start_pos=after - builder.base, end_pos=after - builder.base))
        if error.token.type == "$END":  # Lark feeds $END itself when the parse resumes
            return True
        if to_the_end:
            parser.feed_token(error.token)
            return True
        parser.feed_eof(error.token)  # reduces the entry; the next statement is read afresh
        raise _Resume(builder.base + (error.token.start_pos or 0))

    return on_error


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
        return SYNTAX_ERROR, (f"unexpected {shown(snippet)}: expected {_expected(allowed)}" if allowed
                              else f"unexpected {shown(snippet)}")
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
