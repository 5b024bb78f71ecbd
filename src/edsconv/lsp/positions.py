"""Positions between the syntax model (1-based line and column, in characters) and LSP
(0-based line and character, in the client's code units, UTF-16 unless it chose another)."""

from __future__ import annotations

from collections.abc import Sequence

from lsprotocol import types
from pygls.workspace.position_codec import PositionCodec, ServerTextPosition

from edsconv.lsp.document import column


class Positions:
    """Converts positions for one version of a document."""

    def __init__(self, codec: PositionCodec, lines: Sequence[str]) -> None:
        self._codec = codec
        self._lines = lines

    def to_client(self, line: int, column: int) -> types.Position:
        """A model position (1-based) as an LSP position."""
        server = ServerTextPosition(max(line - 1, 0), max(column - 1, 0))
        if server.line >= len(self._lines) or self._lines[server.line].isascii():
            return types.Position(server.line, server.character)
        return self._codec.position_to_client_units(self._lines, server)

    def range(self, line: int, column: int, end_line: int, end_column: int) -> types.Range:
        return types.Range(self.to_client(line, column), self.to_client(end_line, end_column))

    def from_client(self, position: types.Position) -> tuple[int, int]:
        """An LSP position as a model position (1-based line and column): a character past the line's
        end stands at its end, as LSP says (pygls' own conversion puts it one before the end, and
        writes that into the client's position)."""
        if position.line >= len(self._lines):
            return position.line + 1, position.character + 1
        content = self._lines[position.line].rstrip("\r\n")
        return position.line + 1, column(content, position.character, self._codec) + 1
