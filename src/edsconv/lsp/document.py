"""The server's text documents: the editor's changes applied as LSP means them, in time that does not
grow with the document.

pygls' TextDocument applies a change by splitting the whole text with ``str.splitlines`` and writing
every line again: 10-20 ms a keystroke in a 2.7 MB file, and wrong where a line holds one of the other
characters splitlines breaks at (\\v, \\f, \\x1c-\\x1e, \\x85, \\u2028, \\u2029): an edit after a form feed
lands a line too early. LspDocument breaks lines at \\r\\n, \\r and \\n only (as LSP, the EDS reader and the
analysis do), keeps where its lines start from one change to the next, and applies a change as one
slice-and-join of its text.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Generator
from typing import Any

from lsprotocol import types
from pygls.protocol import LanguageServerProtocol, lsp_method
from pygls.workspace import PositionCodec, TextDocument, Workspace

from edsconv.eds.source import split_lines

_LINE_BREAK = re.compile(r"\r\n|\r|\n")


class LineStarts:
    """The offsets at which the lines of a text start, kept across its edits.

    An edit replaces the starts of the lines it touched and moves every later start by its change
    of length. That move is only noted (from which line, by how much) and made when an edit before
    or after that line needs it, so that typing at one place costs the same in a long text as in a
    short one.
    """

    def __init__(self, text: str) -> None:
        # str.splitlines is the fastest split there is; of its breaks, LSP's are those ending in \r or \n
        pieces = text.splitlines(True)
        ends = itertools.accumulate(map(len, pieces))
        self._starts = [0, *(end for piece, end in zip(pieces, ends, strict=True) if piece[-1] in "\r\n")]
        self._moved_from = len(self._starts)  # the lines from here on start _moved_by later than _starts says
        self._moved_by = 0

    def __len__(self) -> int:
        return len(self._starts)

    def __getitem__(self, line: int) -> int:
        return self._starts[line] + (self._moved_by if line >= self._moved_from else 0)

    def edit(self, text: str, first: int, last: int, moved_by: int) -> None:
        """Follow an edit of lines ``first`` to ``last`` that made ``text`` ``moved_by`` characters longer."""
        after = last + 1
        # From the end of the break before the edit (an inserted \n joins a \r there), to the start of the
        # line after it, which may now start elsewhere; the breaks beyond are the old ones, moved.
        scan_from = self[first] - 1 if first else 0
        scan_to = self[after] + moved_by if after < len(self) else len(text)
        found = [match.end() for match in _LINE_BREAK.finditer(text, scan_from, scan_to)]
        replaced = max(first, 1)
        self._move_from(min(after + 1, len(self)))
        self._starts[replaced:after + 1] = found
        self._moved_from = replaced + len(found)
        self._moved_by += moved_by

    def _move_from(self, line: int) -> None:
        """Make the noted move start at ``line``, moving the starts between there and where it starts now."""
        starts, since, by = self._starts, self._moved_from, self._moved_by
        if by and since < line:
            starts[since:line] = [start + by for start in starts[since:line]]
        elif by and line < since:
            starts[line:since] = [start - by for start in starts[line:since]]
        self._moved_from = line


def column(content: str, units: int, codec: PositionCodec) -> int:
    """The column, in characters, that ``units`` of the client's position encoding reach in a line's
    ``content`` (without its line break): past its end, its end (LSP); inside a character (between
    the halves of a UTF-16 surrogate pair), after it, as pygls counts."""
    if content.isascii():
        return min(units, len(content))
    counted = 0
    for index, character in enumerate(content):
        if counted >= units:
            return index
        counted += codec.client_num_units(character)
    return len(content)


class LspDocument(TextDocument):
    """pygls' text document, with LSP's lines, and changes applied in time independent of its size.

    A change with a range replaces that range; one without replaces the whole text (whatever sync kind
    the server announced: the client's change says which it is). Where its lines start is worked out
    when a whole text comes (on opening, where the analysis takes far longer, rather than at the first
    keystroke) and kept through the changes from then on.
    """

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._index(self._source or "")
        self._lines: tuple[str, ...] = ()
        self._split = ""  # the text _lines are of

    @property
    def lines(self) -> tuple[str, ...]:
        """The lines of the text, each with its line break, as LSP counts them."""
        source = self.source
        if self._split is not source:
            self._lines, self._split = tuple(split_lines(source)), source
        return self._lines

    def apply_change(self, change: types.TextDocumentContentChangeEvent) -> None:
        if isinstance(change, types.TextDocumentContentChangePartial):
            self._replace(change.range, change.text)
        else:
            self._source = change.text
            self._index(change.text)

    def _index(self, text: str) -> None:
        self._line_starts = LineStarts(text)
        self._indexed = text  # the text whose line starts _line_starts holds

    def _replace(self, span: types.Range, text: str) -> None:
        source = self.source
        if self._indexed is not source:  # a text read from disk, which the document does not keep
            self._index(source)
        (first, start), (last, end) = sorted((self._locate(source, span.start), self._locate(source, span.end)))
        edited = "".join((source[:start], text, source[end:]))
        self._line_starts.edit(edited, first, last, len(edited) - len(source))
        self._source = self._indexed = edited

    def _locate(self, source: str, position: types.Position) -> tuple[int, int]:
        """The line of ``position`` and its offset in ``source``: a position past the last line stands at
        the end of the text."""
        starts = self._line_starts
        if position.line >= len(starts):
            return len(starts) - 1, len(source)
        line_start = starts[position.line]
        line_end = starts[position.line + 1] if position.line + 1 < len(starts) else len(source)
        content = source[line_start:line_end].rstrip("\r\n")
        return position.line, line_start + column(content, position.character, self.position_codec)


class LspWorkspace(Workspace):
    """pygls' workspace, whose text documents are LspDocuments."""

    def _create_text_document(self, doc_uri: str, source: str | None = None, version: int | None = None,
                              language_id: str | None = None) -> TextDocument:
        # pygls' one factory of text documents (for open ones and for those read from disk)
        return LspDocument(doc_uri, source=source, version=version, language_id=language_id,
                           position_codec=self.position_codec)


class LspProtocol(LanguageServerProtocol):
    """pygls' language server protocol, whose workspace is an LspWorkspace (``protocol_cls`` of the server)."""

    @lsp_method(types.INITIALIZE)
    def lsp_initialize(self, params: types.InitializeParams) -> Generator[Any, Any, types.InitializeResult]:
        result = yield from super().lsp_initialize(params)
        # pygls makes a plain Workspace here, with no hook for its class (hence the one use of its private
        # _workspace): one of the same root, folders and position encoding replaces it before the client
        # has the answer, and so before it can open a document.
        made = self.workspace
        self._workspace = LspWorkspace(made.root_uri, workspace_folders=list(made.folders.values()),
                                       position_encoding=made.position_encoding)
        return result
