"""Code actions and formatting: the fewest edits that lay a document (or the entries of a range) out
as ``edsconv fmt`` does, and edits on one diagnostic.

Two kinds of code action: the fixes ``edsconv lint --fix`` makes (:mod:`edsconv.fix`,
through :func:`lint_fixes`, so that the command line and the editor fix the same way)
and "suppress this rule here", which writes the inline comment
``$ edsconv: ignore[CODE]`` (:mod:`edsconv.suppress`) on the entry the diagnostic is in.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterator, Sequence

from edsconv.diagnostics import Diagnostic, Severity
from edsconv.eds.canonical import write_canonical
from edsconv.eds.locate import locate
from edsconv.eds.source import split_lines
from edsconv.eds.syntax import Comment, EdsFile, Entry, Section
from edsconv.fix import Edit, Fix, fix_for
from edsconv.lsp.analysis import Analysis
from edsconv.suppress import SUPPRESSION as _SUPPRESSION

#: The inline suppression comment :mod:`edsconv.suppress` honours.
SUPPRESSION = "edsconv: ignore[{codes}]"

__all__ = ["SUPPRESSION", "Edit", "Fix", "format_refusal", "formatting_edits", "lint_fixes", "range_formatting_edits",
           "suppression"]


def lint_fixes(analysis: Analysis, code: str, line: int, column: int) -> list[Fix]:
    """The fix ``edsconv lint --fix`` applies to the diagnostic ``code`` at ``line``:``column`` (none, or one)."""
    found = next((d for d in analysis.diagnostics if d.code == code and (max(d.line, 1), max(d.column, 1))
                  == (line, column)), None)
    fix = fix_for(analysis.eds, list(analysis.lines), found or Diagnostic(code, "", line, column))
    return [fix] if fix is not None else []


def suppression(analysis: Analysis, code: str, line: int, column: int) -> Fix | None:
    """Write ``$ edsconv: ignore[CODE]`` on the entry at ``line``:``column`` (or the section header,
    or that line): added to an ignore comment there, at the end of the entry's first line when it
    has no comment, else on a comment line of its own just above the entry. None when it is there already."""
    spot = locate(analysis.eds, max(line, 1), max(column, 1))
    owner: Entry | Section | None = spot.entry or spot.section
    target = owner.line if owner is not None else max(line, 1)
    text = analysis.line_text(target)
    title = f"Suppress {code} here ($ edsconv: ignore[{code}])"
    for comment in _comments_on(owner, target):
        match = next((m for m in _SUPPRESSION.finditer(comment.text) if not m.group("file")), None)
        if match is None:
            continue
        codes = [c.strip() for c in match.group("codes").split(",") if c.strip()]
        if code in codes:
            return None
        at = comment.column + 1 + match.end("codes")  # the column of "]": after "$", then the text up to the codes' end
        return Fix(title, (Edit(target, at, target, at, f", {code}" if codes else code),))
    if not _comments_on(owner, target):
        end = len(text) + 1
        return Fix(title, (Edit(target, end, target, end, f" $ {SUPPRESSION.format(codes=code)}"),))
    indent = text[:len(text) - len(text.lstrip())]
    comment_line = f"{indent}$ {SUPPRESSION.format(codes=code)}{analysis.eds.newline}"
    return Fix(title, (Edit(target, 1, target, 1, comment_line),))


def _comments_on(owner: Entry | Section | None, line: int) -> list[Comment]:
    if owner is None:
        return []
    comments = list(owner.comments)
    if isinstance(owner, Entry):
        comments += [c for item in owner.walk_fields() for c in item.comments]
    return [c for c in comments if c.line == line]


def format_refusal(analysis: Analysis) -> str | None:
    """Why the document cannot be formatted (as ``edsconv fmt`` says it), or None when it can."""
    errors = [d for d in analysis.eds.diagnostics if d.severity is Severity.ERROR]
    if not errors:
        return None
    first = errors[0]
    return (f"edsconv: not formatted: {len(errors)} syntax error(s) leave text that cannot be laid out; "
            f"first: line {first.line}, column {first.column}: {first.code} {first.message}")


def formatting_edits(analysis: Analysis) -> list[Edit]:
    """The fewest whole-line edits that turn the document into ``edsconv fmt``'s text (none when
    :func:`format_refusal` refuses): what is already canonical keeps its place, and with it the
    editor's cursor, marks and folds."""
    if format_refusal(analysis) is not None:
        return []
    return minimal_edits(analysis.lines, split_lines(write_canonical(analysis.eds)), 1)


def range_formatting_edits(analysis: Analysis, first_line: int, last_line: int) -> list[Edit]:
    """The layout of ``edsconv fmt`` for each entry with a line in ``first_line``..``last_line``
    (1-based), in place: a range is never reordered (that could move text out of it), and an
    entry sharing a line with another one is left as it is."""
    if format_refusal(analysis) is not None:
        return []
    spans = sorted(_item_spans(analysis.eds))
    edits: list[Edit] = []
    for index, (start, end, section, entry) in enumerate(spans):
        if entry is None or end < first_line or start > last_line:
            continue
        alone = (index == 0 or spans[index - 1][1] < start) and (index + 1 == len(spans) or spans[index + 1][0] > end)
        if alone:
            laid_out = split_lines(write_canonical(EdsFile([Section(section, [entry])]), analysis.eds.newline))
            edits += minimal_edits(analysis.lines[start - 1:end], laid_out[1:], start)
    return edits


def _item_spans(eds: EdsFile) -> Iterator[tuple[int, int, str, Entry | None]]:
    """(first line, last line, section name, entry) of each entry with its comments, and of each
    section header and unparsed statement (entry None): what shares no line with another can be laid out alone."""
    for section in eds.sections:
        yield section.line, section.line, section.name, None
        for item in section.items():
            if not isinstance(item, Entry):
                yield item.line, item.line, section.name, None
                continue
            assert item.source is not None  # read from the document
            lines = [item.line, item.source.position(max(item.end_offset - 1, item.offset))[0]]
            lines += [c.line for c in (*item.leading_comments, *item.comments)]
            lines += [c.line for f in item.walk_fields() for c in f.comments]
            yield min(lines), max(lines), section.name, item


def minimal_edits(old: Sequence[str], new: Sequence[str], first_line: int) -> list[Edit]:
    """Edits of whole lines that turn the lines ``old`` (with their line ends; the first is line
    ``first_line``) into ``new``: one per differing run of lines, none where they agree."""
    edits = []
    matcher = difflib.SequenceMatcher(None, old, new, autojunk=False)
    for tag, start, end, new_start, new_end in matcher.get_opcodes():
        if tag == "equal":
            continue
        end_line, end_column = first_line + end, 1
        if end and end == len(old) and not old[-1].endswith(("\n", "\r")):  # the document's last line has no end
            end_line, end_column = first_line + end - 1, len(old[-1]) + 1
        edits.append(Edit(first_line + start, 1, end_line, end_column, "".join(new[new_start:new_end])))
    return edits
