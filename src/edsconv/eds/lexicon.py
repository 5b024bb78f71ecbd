"""Regular expressions built from the grammar's own terminals.

The LALR parser sees coarse tokens (a whole run of fields is one RUN token);
the reader splits them with these expressions, which are assembled from the
terminal definitions of grammar/eds.lark so that the lexical rules live in one
place. The same terminals, composed as Lark's contextual lexer meets them, match
a whole simple statement (a section header, or an entry without braces) in one
regex call: the reader builds those without Lark (see :mod:`edsconv.eds.reader`).
"""

from __future__ import annotations

import functools
import hashlib
import importlib.util
import json
import re
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from edsconv import cache
from edsconv.resources import data_dir

#: The order in which a scalar is classified; the grammar's SCALAR accepts the union.
SCALAR_KINDS = ("REAL_WORD", "DATE", "TIME", "HEX", "BINARY", "REAL", "INTEGER", "WORD", "WILDCARD")


@dataclass(frozen=True, slots=True)
class Lexicon:
    #: one field of a RUN: groups (comment, string, scalar, comma)
    run_piece: re.Pattern[str]
    #: the parts and comments of a concatenated string
    string_piece: re.Pattern[str]
    #: one escape sequence of Table C.4
    escape: re.Pattern[str]
    #: the keyword at the start of an ENTRY_START token
    entry_keyword: re.Pattern[str]
    #: a whole scalar, with one named group per kind of SCALAR_KINDS
    scalar_kind: re.Pattern[str]
    #: a simple statement after optional TRIVIA: groups ``section``, or ``entry`` (its ENTRY_START),
    #: ``run`` (its RUN, if any) and ``end`` (its ``;``); see :func:`statement_pattern`
    statement: re.Pattern[str]
    #: TRIVIA (or nothing) up to the end of the text
    tail: re.Pattern[str]
    #: optional TRIVIA, then a SECTION (group ``section``) or an ENTRY_START (group ``entry``)
    statement_start: re.Pattern[str]
    #: a whole field of a RUN: a STRING, a SCALAR, or nothing
    item: re.Pattern[str]


def grammar_text() -> str:
    return (data_dir("grammar") / "eds.lark").read_text(encoding="utf-8")


_WANTED = ("STRING", "STRING_PART", "ESCAPE", "KEYWORD", "SCALAR", "TRIVIA", "SECTION", "ENTRY_START", "RUN",
           *SCALAR_KINDS)


def _lark_version() -> str:
    """The installed Lark's version line, read without importing Lark (whose import costs ~25 ms)."""
    spec = importlib.util.find_spec("lark")
    if spec is None or spec.origin is None:
        return ""
    found = re.search(r"^__version__\b.*$", Path(spec.origin).read_text(encoding="utf-8"), re.MULTILINE)
    return found.group() if found else ""


def cache_file(text: str) -> Path:
    """Where the terminal patterns of grammar ``text`` are cached (by grammar and Lark version)."""
    key = hashlib.sha256(f"{_lark_version()}\n{text}".encode()).hexdigest()[:20]
    return cache.cache_dir() / f"lexicon-{key}.json"


def terminal_patterns() -> dict[str, str]:
    """The regexes of the wanted terminals; kept in the per-user cache (:mod:`edsconv.cache`).

    Compiling the grammar costs ~40 ms, a large share of a short run's start-up.
    """
    text = grammar_text()
    path = cache_file(text)
    data = cache.read_file(path)
    if data is not None:
        try:
            cached = json.loads(data)
        except ValueError:
            cached = None  # damaged: computed and written again
        if isinstance(cached, dict) and all(isinstance(cached.get(name), str) for name in _WANTED):
            return cached
    from lark.load_grammar import load_grammar

    grammar, _ = load_grammar(text, "eds.lark", [], False)
    terminals, _, _ = grammar.compile(["start"], set(_WANTED))
    patterns = {t.name: t.pattern.to_regexp() for t in terminals if t.name in _WANTED}
    cache.write_file(path, json.dumps(patterns).encode())
    return patterns


def statement_pattern(pattern: dict[str, str]) -> str:
    """A simple statement exactly as Lark's contextual lexer and the LALR parser meet it.

    ``start: (section | entry)*`` with ``%ignore TRIVIA``: optional TRIVIA, then SECTION, or
    ENTRY_START, TRIVIA, RUN, TRIVIA and ``;`` with no brace group. At each place the
    terminals the parser allows begin with different characters, so the lexer's choice is
    the one terminal that can match there; each is matched possessively, as the lexer
    matches it on its own (a RUN never gives back characters to let what follows match).
    Anything else (braces, a syntax error) fails to match and goes to Lark.
    """
    trivia = f"(?:{pattern['TRIVIA']})?+"
    return (rf"{trivia}(?:(?P<section>{pattern['SECTION']})|(?P<entry>{pattern['ENTRY_START']}){trivia}"
            rf"(?P<run>(?>{pattern['RUN']}))?{trivia}(?P<end>;))")


@functools.cache
def lexicon() -> Lexicon:
    pattern = terminal_patterns()
    blank = r"[ \t\n\f\v]*"
    run_piece = re.compile(
        rf"{blank}(?:(\$[^\n]*)|(?:({pattern['STRING']})|({pattern['SCALAR']}))?{blank}(,)?)")
    scalar_kind = re.compile("|".join(f"(?P<{name}>{pattern[name]})" for name in SCALAR_KINDS))
    return Lexicon(
        run_piece=run_piece,
        string_piece=re.compile(rf"({pattern['STRING_PART']})|(\$[^\n]*)"),
        escape=re.compile(pattern["ESCAPE"]),
        entry_keyword=re.compile(pattern["KEYWORD"]),
        scalar_kind=scalar_kind,
        statement=re.compile(statement_pattern(pattern)),
        tail=re.compile(rf"(?:{pattern['TRIVIA']})?+\Z"),
        statement_start=re.compile(rf"(?:{pattern['TRIVIA']})?+(?:(?P<section>{pattern['SECTION']})"
                                   rf"|(?P<entry>{pattern['ENTRY_START']}))"),
        item=re.compile(rf"(?:{pattern['STRING']}|{pattern['SCALAR']})?"),
    )


def entry_keyword(entry_start: str) -> str:
    """The keyword of an ENTRY_START token: KEYWORD, then blanks, line ends and comments, then "="."""
    return lexicon().entry_keyword.match(entry_start).group()  # type: ignore[union-attr]  # it starts so


@functools.lru_cache(maxsize=8192)
def scalar_kind(raw: str) -> str:
    """The SCALAR_KINDS name of a scalar spelling, or "" when it is no scalar.

    Cached: the same spellings ("0", "0x0000", "Param1") recur all over a file.
    """
    match = lexicon().scalar_kind.fullmatch(raw)
    return (match.lastgroup or "") if match else ""


_BACKSLASH_PAIR = re.compile(r"\\.")


def undefined_escapes(raw: str, unicode: bool) -> Iterator[tuple[int, str, bool]]:
    """(offset in ``raw``, sequence, defined) of each escape of a string's spelling that is not
    valid there: not in Table C.4 (``defined`` False), or ``\\u`` outside an ``L"..."`` string
    (C.4.1.3.3.5)."""
    escape = lexicon().escape
    for found in _BACKSLASH_PAIR.finditer(raw):
        if not escape.match(raw, found.start()):
            yield found.start(), found.group(), False
        elif found.group() == "\\u" and not unicode:
            yield found.start(), found.group(), True
