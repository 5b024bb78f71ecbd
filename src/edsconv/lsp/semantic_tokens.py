"""Semantic tokens: what each word of an EDS is, so that any LSP client highlights EDS without a
grammar of its own (Neovim, Emacs, Helix, VS Code).

The words are found with the grammar's own terminals (:func:`edsconv.eds.lexicon.terminal_patterns`,
the one home of the lexical rules), so a file is coloured as the reader reads it, broken files
included: a section header, an entry keyword (the first word of a statement, wherever its ``=``
stands), strings, numbers, keyword values, comments. Words that name an entry (``Param3`` in an
assembly) come from the analysis's references and are marked as such; the keywords that define
such an entry carry the ``declaration`` modifier.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Iterator
from dataclasses import dataclass

from lsprotocol import types

from edsconv.eds.lexicon import scalar_kind, terminal_patterns
from edsconv.lsp.analysis import Analysis
from edsconv.lsp.positions import Positions

#: The legend announced at initialisation: token types and modifiers by index.
TOKEN_TYPES = ("namespace", "property", "string", "number", "enumMember", "variable", "comment", "operator")
TOKEN_MODIFIERS = ("declaration", "readonly")
LEGEND = types.SemanticTokensLegend(token_types=list(TOKEN_TYPES), token_modifiers=list(TOKEN_MODIFIERS))

_TYPE = {name: index for index, name in enumerate(TOKEN_TYPES)}
_DECLARATION = 1 << TOKEN_MODIFIERS.index("declaration")
#: Scalars that are numbers in the grammar's sense (C.4.1.2); DATE and TIME read as numbers too.
_NUMBER_KINDS = frozenset({"HEX", "BINARY", "INTEGER", "REAL", "REAL_WORD", "DATE", "TIME"})


@dataclass(frozen=True, slots=True)
class Token:
    """One highlighted word: 1-based line and column, length in characters, type and modifiers."""

    line: int
    column: int
    length: int
    kind: str
    modifiers: int = 0


@functools.cache
def token_pattern() -> re.Pattern[str]:
    """One word of EDS text per match, the group naming what it is (white space matches no group)."""
    terminal = terminal_patterns()
    return re.compile(
        rf"(?P<comment>\$[^\r\n]*)|(?P<section>{terminal['SECTION']})|(?P<string>{terminal['STRING_PART']})"
        rf"|(?P<scalar>{terminal['SCALAR']})|(?P<punct>[=;{{}},])|(?P<line_end>\r\n?|\n)|[^\S\r\n]+|(?P<other>.)")


def tokens(analysis: Analysis) -> Iterator[Token]:
    """Every token of the document in text order."""
    references = {(o.line, o.column): o.kind for o in analysis.spans}
    line, line_start, statement_start = 1, 0, True
    for match in token_pattern().finditer(analysis.text):
        group = match.lastgroup
        if group == "line_end":
            line, line_start = line + 1, match.end()
            continue
        if group is None or group == "other":
            continue
        column = match.start() - line_start + 1
        if group == "punct":
            statement_start = match.group() == ";"
            if match.group() == "=":
                yield Token(line, column, 1, "operator")
            continue
        kind, modifiers = _classify(group, match.group(), statement_start, references.get((line, column)))
        if group in ("section", "scalar"):
            statement_start = group == "section"
        yield Token(line, column, match.end() - match.start(), kind, modifiers)


def _classify(group: str, text: str, statement_start: bool, reference: str | None) -> tuple[str, int]:
    if group in ("comment", "string"):
        return group, 0
    if group == "section":
        return "namespace", 0
    if statement_start:
        return "property", _DECLARATION if reference == "definition" else 0
    if reference is not None:
        return "variable", 0
    return ("number" if scalar_kind(text) in _NUMBER_KINDS else "enumMember"), 0


def encode(found: Iterator[Token], positions: Positions) -> list[int]:
    """The tokens in LSP's relative encoding: five integers per token, positions in the client's units."""
    data: list[int] = []
    previous_line = previous_start = 0
    for token in found:
        start = positions.to_client(token.line, token.column)
        end = positions.to_client(token.line, token.column + token.length)
        delta_line = start.line - previous_line
        delta_start = start.character - previous_start if delta_line == 0 else start.character
        data += [delta_line, delta_start, end.character - start.character, _TYPE[token.kind], token.modifiers]
        previous_line, previous_start = start.line, start.character
    return data


def in_range(found: Iterator[Token], first_line: int, last_line: int) -> Iterator[Token]:
    """The tokens on lines ``first_line``..``last_line`` (1-based, inclusive)."""
    return (token for token in found if first_line <= token.line <= last_line)
