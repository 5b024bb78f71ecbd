"""How ``edsconv show`` lays its document out: a page of headings and tables, and JSON.

A part of the text (:mod:`edsconv.cli.show`) writes on a :class:`Page`: ``heading``, ``table``
(columns, then ``add_row``), ``pairs`` (label / value rows) and ``print``. On a terminal the
page is rich's (:class:`RichPage`, rich imported only then); piped, :class:`PlainPage` lays the
same tables out as text, column widths from one pass over the rows and no wrapping: rich's
layout was two thirds of ``show``'s time. :func:`json_text` writes JSON as the standard library
does with an indent, in less time.
"""

from __future__ import annotations

import itertools
import json
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from rich.console import Console
    from rich.table import Table

#: a label and its value in a two-column table
Row = tuple[str, Any]


def cell_text(value: Any) -> str:
    """A value as a table cell shows it: nothing for None, floats short."""
    if value is None:
        return ""
    if isinstance(value, float):
        return f"{value:g}"
    return str(value)


# --- pages -----------------------------------------------------------------------------------


class Page:
    """Headings and tables, a blank line between parts; how they look is the subclass's."""

    def __init__(self) -> None:
        self.first = True

    def heading(self, text: str) -> None:
        if not self.first:
            self.blank_line()
        self.first = False
        self.title(text)

    def blank_line(self) -> None:
        raise NotImplementedError

    def title(self, text: str) -> None:
        raise NotImplementedError

    def table(self, *columns: str, **options: Any) -> Any:
        raise NotImplementedError

    def print(self, table: Any) -> None:
        raise NotImplementedError

    def pairs(self, rows: list[Row]) -> Any:
        """Label / value rows; rows without a value are left out."""
        t = self.table(show_header=False)
        t.add_column(style="bold", no_wrap=True)
        t.add_column(overflow="fold")
        for label, value in rows:
            if value not in (None, "", []):
                t.add_row(label, cell_text(value))
        if not t.rows:
            t.add_row("(nothing given)", "")
        return t


class RichPage(Page):
    """rich tables on a console (a terminal)."""

    def __init__(self, console: Console) -> None:
        super().__init__()
        self.console = console

    def blank_line(self) -> None:
        self.console.print()

    def title(self, text: str) -> None:
        from rich.text import Text

        self.console.print(Text(text, style="bold underline"))

    def table(self, *columns: str, **options: Any) -> Table:
        from rich import box
        from rich.table import Table

        t = Table(box=box.SIMPLE_HEAD, show_edge=False, pad_edge=False, header_style="bold", **options)
        for column in columns:
            t.add_column(column, overflow="fold")
        return t

    def print(self, table: Table) -> None:
        self.console.print(table)


#: control characters a terminal would act on, dropped from the text as rich drops them
_CONTROL = dict.fromkeys(map(ord, "\a\b\v\f\r"))


def _printable(text: str) -> str:
    return text.translate(_CONTROL).expandtabs(8)


class _Column:
    """What a part may set on a column (``no_wrap``); plain text never wraps."""

    no_wrap = False


class PlainTable:
    """The part of rich's Table that the parts use, laid out as plain text."""

    #: between two columns, as rich lays them out
    GAP = "   "

    def __init__(self, *columns: str, show_header: bool = True) -> None:
        self.headers = list(columns)
        self.show_header = show_header
        self.columns = [_Column() for _ in columns]
        self.rows: list[list[str]] = []

    def add_column(self, header: str = "", **options: Any) -> None:
        self.headers.append(header)
        self.columns.append(_Column())

    def add_row(self, *cells: str) -> None:
        """A row; a cell of several lines makes as many lines of the table, the other cells blank below."""
        row = [cell if cell.isprintable() else _printable(cell) for cell in cells]
        if not any("\n" in cell for cell in row):
            self.rows.append(row)
            return
        split = [cell.split("\n") for cell in row]
        for index in range(max(map(len, split))):
            self.rows.append([cell[index] if index < len(cell) else "" for cell in split])

    def lines(self) -> list[str]:
        """The header, a rule under it, and every row."""
        widths = [len(header) if self.show_header else 0 for header in self.headers]
        for column, cells in enumerate(itertools.zip_longest(*self.rows, fillvalue="")):
            widths[column] = max(widths[column], *map(len, cells))
        out = []
        if self.show_header:
            out.append(self._line(self.headers, widths))
            out.append("\u2500" * (sum(widths) + len(self.GAP) * (len(widths) - 1)))
        out += map(self._line, self.rows, itertools.repeat(widths))
        return out

    def _line(self, cells: list[str], widths: list[int]) -> str:
        return self.GAP.join(map(str.ljust, cells, widths)).rstrip()


class PlainPage(Page):
    """The page as lines of plain text."""

    def __init__(self) -> None:
        super().__init__()
        self.lines: list[str] = []

    def blank_line(self) -> None:
        self.lines.append("")

    def title(self, text: str) -> None:
        self.lines.append(_printable(text))

    def table(self, *columns: str, **options: Any) -> PlainTable:
        return PlainTable(*columns, show_header=options.get("show_header", True))

    def print(self, table: PlainTable) -> None:
        self.lines += table.lines()


# --- JSON ---------------------------------------------------------------------------------------


class _NotPlain(Exception):  # noqa: N818 - a signal to fall back, not an error
    """A value json_text leaves to the standard library."""


def json_text(value: Any) -> str:
    """``json.dumps(value, indent=2, ensure_ascii=False)``, character for character, in a third less time.

    With an indent the standard library encodes in Python, one generator step per piece;
    this joins strings instead, and encodes strings with the same C function.
    """
    try:
        return _json(value, "\n")
    except _NotPlain:
        return json.dumps(value, indent=2, ensure_ascii=False)


def _json(value: Any, newline: str) -> str:
    """``value`` as JSON, its lines after the first indented as ``newline`` (a line end and blanks) says."""
    kind = type(value)
    if kind is str:
        return _encode_string(value)
    inner = newline + "  "
    if kind is dict:
        if not value:
            return "{}"
        items = [_encode_string(key) + ": " + (_encode_string(item) if type(item) is str else _json(item, inner))
                 for key, item in value.items() if type(key) is str or _not_plain()]
        return "{" + inner + ("," + inner).join(items) + newline + "}"
    if kind is list or kind is tuple:
        if not value:
            return "[]"
        items = [_encode_string(item) if type(item) is str else _json(item, inner) for item in value]
        return "[" + inner + ("," + inner).join(items) + newline + "]"
    leaf = _JSON_LEAVES.get(kind)
    if leaf is not None:
        return leaf(value)
    if isinstance(value, str):  # a StrEnum
        return _encode_string(value)
    if isinstance(value, int) and not isinstance(value, bool):  # an IntEnum
        return int.__repr__(value)
    return _not_plain()


def _not_plain() -> Any:
    raise _NotPlain


def _float(value: float) -> str:
    if value != value:
        return "NaN"
    return _JSON_INFINITIES.get(value) or float.__repr__(value)


_encode_string = json.encoder.encode_basestring  # the C function, as ensure_ascii=False uses
_JSON_INFINITIES = {float("inf"): "Infinity", float("-inf"): "-Infinity"}
_JSON_LEAVES = {int: int.__repr__, float: _float, bool: lambda value: "true" if value else "false",
                type(None): lambda value: "null"}
