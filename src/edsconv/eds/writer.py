"""Syntax model -> EDS text.

Values are written as they were spelled and every comment is placed where the
reader's ownership rule (see :mod:`edsconv.eds.syntax`) gives it back to the same
node, so ``parse(write(model)) == model``. Entries without comments go on one
line; a comment ends its line and the entry continues on the next.
"""

from __future__ import annotations

from edsconv.eds.syntax import Comment, EdsFile, Entry, Field, Group, Section, Unparsed

_INDENT = "    "


class _Lines:
    """Accumulates text; a comment closes the current line."""

    def __init__(self) -> None:
        self.lines: list[str] = []
        self.current = ""

    def text(self, text: str) -> None:
        if not self.current:
            self.current = _INDENT
        self.current += text

    def comment(self, comment: Comment) -> None:
        if self.current.strip():
            self.current += f"  ${comment.text}"
        else:
            self.current = f"{_INDENT}${comment.text}"
        self.end_line()

    def own_line(self, text: str) -> None:
        self.end_line()
        self.lines.append(text)

    def end_line(self) -> None:
        if self.current:
            # Comments keep trailing white space: it is part of their text.
            self.lines.append(self.current if self.current.strip() else "")
        self.current = ""


def write(eds: EdsFile, newline: str | None = None) -> str:
    """The EDS text of a syntax model, with the file's own line ends unless given."""
    out = _Lines()
    if eds.preamble is not None:
        _write_entries(out, eds.preamble)
    for section in eds.sections:
        for comment in section.leading_comments:
            out.own_line(f"${comment.text}")
        out.own_line(f"[{section.name}]")
        if section.comments:
            out.current = out.lines.pop()
            for comment in section.comments:
                out.comment(comment)
        _write_entries(out, section)
    for comment in eds.trailing_comments:
        out.own_line(f"${comment.text}")
    out.end_line()
    return (newline or eds.newline).join(out.lines) + (newline or eds.newline)


def _write_entries(out: _Lines, section: Section) -> None:
    for item in section.items():
        if isinstance(item, Unparsed):
            _write_unparsed(out, item)
        else:
            _write_entry(out, item)


def _write_unparsed(out: _Lines, unparsed: Unparsed) -> None:
    for comment in unparsed.leading_comments:
        out.own_line(f"${comment.text}")
    out.own_line(unparsed.text)
    if unparsed.comments:
        out.current = out.lines.pop()
        for comment in unparsed.comments:
            out.comment(comment)


def _write_entry(out: _Lines, entry: Entry) -> None:
    for comment in entry.leading_comments:
        out.own_line(f"{_INDENT}${comment.text}")
    out.end_line()
    out.text(f"{entry.keyword} =")
    for comment in entry.comments:
        out.comment(comment)
    _write_fields(out, entry.fields, ";")
    out.end_line()


def _write_fields(out: _Lines, fields: list[Field], closer: str) -> None:
    last = len(fields) - 1
    for index, field in enumerate(fields):
        value = field.value
        if value is not None:
            out.text(" ")
        if isinstance(value, Group):
            out.text("{")
            for comment in field.comments:
                out.comment(comment)
            _write_fields(out, value.fields, "}")
        elif value is not None:
            out.text(value.raw)
        if isinstance(value, Group) or index < last:
            if index < last:
                out.text(",")
                for comment in field.comments if not isinstance(value, Group) else ():
                    out.comment(comment)
            else:
                out.text(closer)
            continue
        # The last field: its comments must stay after its start and, when the
        # field is empty (it starts at the closer), after the closer.
        if value is None:
            out.text(closer)
            for comment in field.comments:
                out.comment(comment)
        else:
            for comment in field.comments[:-1]:
                out.comment(comment)
            out.text(closer)
            for comment in field.comments[-1:]:
                out.comment(comment)
