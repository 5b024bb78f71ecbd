"""Code actions and formatting: whole-document edits and edits on one diagnostic.

Two kinds of code action: the fixes ``edsconv lint --fix`` knows (taken from
:func:`lint_fixes`, so that the command line and the editor fix the same way)
and "suppress this rule here", which writes the inline comment
``$ edsconv: ignore[CODE]`` on the entry the diagnostic is in. The suppression
itself, and the fixes, come with the configuration issue (see :mod:`edsconv.lsp.settings`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from edsconv.diagnostics import Severity
from edsconv.eds.canonical import write_canonical
from edsconv.eds.locate import locate
from edsconv.eds.syntax import Comment, Entry, Section
from edsconv.lsp.analysis import Analysis

#: The inline suppression comment the configuration issue will honour.
SUPPRESSION = "edsconv: ignore[{codes}]"
_SUPPRESSION = re.compile(r"edsconv: ignore\[([^\]]*)\]")


@dataclass(frozen=True, slots=True)
class Edit:
    """Replace ``line``:``column`` .. ``end_line``:``end_column`` (1-based, end exclusive) by ``text``."""

    line: int
    column: int
    end_line: int
    end_column: int
    text: str


@dataclass(frozen=True, slots=True)
class Fix:
    title: str
    edits: tuple[Edit, ...]


def lint_fixes(analysis: Analysis, code: str, line: int, column: int) -> list[Fix]:
    """The fixes ``edsconv lint --fix`` would apply to the diagnostic ``code`` at ``line``:``column``.

    The seam for the fixes of the configuration issue: the library's fix for a rule is to be
    called here. No rule has one yet.
    """
    return []


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
        match = _SUPPRESSION.search(comment.text)
        if match is None:
            continue
        codes = [c.strip() for c in match.group(1).split(",") if c.strip()]
        if code in codes:
            return None
        at = comment.column + 1 + match.end(1)  # the column of "]": after "$", then the text up to the codes' end
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


def formatted(analysis: Analysis) -> str | None:
    """The canonical text of ``edsconv fmt``; None when syntax errors leave text that cannot be laid out."""
    if any(d.severity is Severity.ERROR for d in analysis.eds.diagnostics):
        return None
    return write_canonical(analysis.eds)
