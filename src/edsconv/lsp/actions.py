"""Code actions and formatting: whole-document edits and edits on one diagnostic.

Two kinds of code action: the fixes ``edsconv lint --fix`` makes (:mod:`edsconv.fix`,
through :func:`lint_fixes`, so that the command line and the editor fix the same way)
and "suppress this rule here", which writes the inline comment
``$ edsconv: ignore[CODE]`` (:mod:`edsconv.suppress`) on the entry the diagnostic is in.
"""

from __future__ import annotations

from edsconv.diagnostics import Diagnostic, Severity
from edsconv.eds.canonical import write_canonical
from edsconv.eds.locate import locate
from edsconv.eds.syntax import Comment, Entry, Section
from edsconv.fix import Edit, Fix, fix_for
from edsconv.lsp.analysis import Analysis
from edsconv.suppress import SUPPRESSION as _SUPPRESSION

#: The inline suppression comment :mod:`edsconv.suppress` honours.
SUPPRESSION = "edsconv: ignore[{codes}]"

__all__ = ["SUPPRESSION", "Edit", "Fix", "formatted", "lint_fixes", "suppression"]


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


def formatted(analysis: Analysis) -> str | None:
    """The canonical text of ``edsconv fmt``; None when syntax errors leave text that cannot be laid out."""
    if any(d.severity is Severity.ERROR for d in analysis.eds.diagnostics):
        return None
    return write_canonical(analysis.eds)
