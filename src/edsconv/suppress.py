"""Inline suppression: EDS comments that silence rules on one entry or in the whole file.

``$ edsconv: ignore[EDS317]`` in a comment of an entry (after the entry or one of
its fields, or on a comment line just above it) silences those codes for
diagnostics on the entry's lines; on a section header line it silences them on
that line. ``$ edsconv: ignore-file[EDS005, EDS2]`` anywhere silences them in
the whole file. Codes may be prefixes and aliases, as ``--ignore`` takes them.
A suppression that silences nothing is itself reported (:data:`UNUSED_SUPPRESSION`),
as ruff reports an unused ``# noqa``; a code whose rule is not selected for the
file is not judged. The directive is read whatever its case and the blanks around
``:`` and ``[`` (``$ EDSCONV: IGNORE [EDS103]``); one edsconv does not know
(``edsconv: ignore-next[...]``, ``edsconv: ignore EDS103``) is EDS099 too, never
silently nothing.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass

from edsconv.diagnostics import Diagnostic, Severity, block, load_rules, rule
from edsconv.eds.syntax import Comment, EdsFile, Entry, Section, Unparsed, plain_fields
from edsconv.limits import shown
from edsconv.model.memo import MISSING, EntryMemo, Kind

#: Comments that name edsconv, each with the lines a suppression in it covers (:func:`directive_comments`)
Directives = list[tuple[Comment, tuple[int, int]]]

UNUSED_SUPPRESSION = rule(
    "EDS099", Severity.WARNING, "edsconv",
    "An edsconv: ignore[...] comment suppresses nothing, names no rule, or is malformed",
    explanation="""
        A suppression comment (`$ edsconv: ignore[CODE]` on an entry, `$ edsconv: ignore-file[CODE]`
        for the file) names a code that no diagnostic in its reach carries, or a code that names
        no rule. A stale suppression would silently hide the next real fault there: remove the
        code (`edsconv lint --fix` does). A code whose rule is not selected for the file
        (`--select`, `ignore`, `per-file-ignores`) is not judged.

        The directive is read in any case and with blanks around `:` and `[`
        (`$ EDSCONV: Ignore [EDS103]` works). A comment that looks like a directive but is none
        edsconv knows (`edsconv: ignore-next[EDS103]`, `edsconv: ignore EDS103` without brackets)
        is reported as malformed rather than silently suppressing nothing; it has no automatic fix.
    """,
    bad=block("""
        [Device]
                VendCode = 65535;       $ edsconv: ignore[EDS102]
    """),
    good=block("""
        [Device]
                VendCode = 65535;
    """),
    fix="safe",
)

#: ``edsconv: ignore[CODES]`` (an entry or a header line) and ``edsconv: ignore-file[CODES]`` (the file).
SUPPRESSION = re.compile(r"edsconv\s*:\s*ignore(?P<file>-file)?\s*\[(?P<codes>[^\]]*)\]", re.IGNORECASE)
#: What reads as an attempt at a directive: ``edsconv:`` and a word followed by ``[``, or a word of the
#: ignore family without brackets. Not a directive of SUPPRESSION: EDS099, malformed.
_DIRECTIVE_LIKE = re.compile(r"edsconv\s*:\s*(?:[A-Za-z][\w-]*\s*\[[^\]]*\]?|(?:ignore|noqa|disable)[\w-]*[^\n]*)",
                             re.IGNORECASE)
_CODE = re.compile(r"[^,\s]+")


@dataclass(frozen=True, slots=True)
class Suppression:
    """One code of a suppression comment, the lines it covers and where it is written."""

    code: str
    #: lines covered (first, last); (0, 0) for the whole file
    reach: tuple[int, int]
    line: int
    column: int
    end_column: int

    @property
    def file_level(self) -> bool:
        return self.reach == (0, 0)

    def covers(self, diagnostic: Diagnostic) -> bool:
        if not diagnostic.code.startswith(load_rules().resolve(self.code)):
            return False
        return self.file_level or self.reach[0] <= diagnostic.line <= self.reach[1]


def suppressions(eds: EdsFile) -> list[Suppression]:
    """Every code of every suppression comment of the file, in file order."""
    return _suppressions(directive_comments(eds))


def _suppressions(comments: Directives) -> list[Suppression]:
    found: list[Suppression] = []
    for comment, reach in comments:
        for match in SUPPRESSION.finditer(comment.text):
            where = (0, 0) if match.group("file") else reach
            start = comment.column + 1 + match.start("codes")  # the text starts after "$"
            found += [Suppression(code.group().upper(), where, comment.line, start + code.start(),
                                  start + code.end()) for code in _CODE.finditer(match.group("codes"))]
    found.sort(key=lambda s: (s.line, s.column))
    return found


def apply_suppressions(eds: EdsFile, diagnostics: Iterable[Diagnostic], reports: Callable[[str], bool],
                       directives: Directives | None = None) -> list[Diagnostic]:
    """The diagnostics no suppression covers, with an EDS099 for each suppression code that covers none.

    ``reports(code)`` says whether a code is reported for this file at all (selection, per-file ignores).
    ``directives``: :func:`directive_comments` of ``eds``, when they were found already.
    """
    kept = list(diagnostics)
    comments = directive_comments(eds) if directives is None else directives
    if not comments:
        return kept
    found = _suppressions(comments)
    malformed = list(_malformed(comments, eds.path)) if reports(UNUSED_SUPPRESSION.code) else []
    if not found:
        return kept + malformed
    used: set[Suppression] = set()
    remaining = []
    for diagnostic in kept:
        covering = [s for s in found if s.covers(diagnostic)]
        used.update(covering)
        if not covering:
            remaining.append(diagnostic)
    if reports(UNUSED_SUPPRESSION.code):
        remaining += [_unused(s, eds.path) for s in found if s not in used and _judged(s.code, reports)]
    return remaining + malformed


def _mentions_edsconv(eds: EdsFile, text: str | None) -> bool:
    """False when ``text``, else the text the file was read from, never says "edsconv": then no comment
    holds a directive, and walking every field's comments (a third of the language server's work per
    keystroke on a large file) is skipped. A file built in code has no text: its comments are walked."""
    if text is None:
        read_from = next((s.source for s in eds.holders() if s.source), None)
        if read_from is None:
            return True
        text = read_from.text
    # every directive, and every attempt at one, names edsconv (SUPPRESSION, _DIRECTIVE_LIKE); lower()
    # and find are ten times faster than a case-blind regular expression on a large text
    return "edsconv" in text.lower()


def _malformed(comments: Directives, path: str | None) -> Iterator[Diagnostic]:
    """EDS099 for each comment that attempts a directive edsconv does not know."""
    for comment, _ in comments:
        directives = [m.span() for m in SUPPRESSION.finditer(comment.text)]
        for attempt in _DIRECTIVE_LIKE.finditer(comment.text):
            if any(start <= attempt.start() < end for start, end in directives):
                continue
            column = comment.column + 1 + attempt.start()
            yield Diagnostic.of(UNUSED_SUPPRESSION, f"malformed edsconv comment {shown(attempt.group().strip())}: "
                                f"the directives are 'edsconv: ignore[CODES]' (this entry) and "
                                f"'edsconv: ignore-file[CODES]' (the file); it suppresses nothing",
                                comment.line, column, path)


def _judged(code: str, reports: Callable[[str], bool]) -> bool:
    """Unknown codes are always reported; a known one only when one of its rules is reported for the file."""
    registry = load_rules()
    resolved = registry.resolve(code)
    if not registry.knows_prefix(resolved):
        return True
    return any(reports(c) for c in registry.rules if c.startswith(resolved))


def _unused(suppression: Suppression, path: str | None) -> Diagnostic:
    registry = load_rules()
    if registry.knows_prefix(registry.resolve(suppression.code)):
        reach = "this file" if suppression.file_level else "this entry"
        message = f"edsconv: ignore[{suppression.code}] suppresses nothing: no {suppression.code} diagnostic in {reach}"
    else:
        message = f"edsconv: ignore[{suppression.code}] names no rule (see 'edsconv rules')"
    return Diagnostic.of(UNUSED_SUPPRESSION, message, suppression.line, suppression.column, path,
                         suppression.line, suppression.end_column)


def directive_comments(eds: EdsFile, memo: EntryMemo | None = None, text: str | None = None) -> Directives:
    """Every comment that names edsconv (as every directive, and every attempt at one, does), with the
    lines a suppression in it covers (an entry's, a header's line, or (0, 0) after the last statement).

    With a ``memo`` (the language server's, :mod:`edsconv.model.memo`), an entry it knows is not
    walked again: on a file of 40,000 entries that walk takes a tenth of a second. ``text`` is the
    text ``eds`` stands for, when the caller holds it: the language server's syntax model keeps
    sections and entries read from older texts (:mod:`edsconv.lsp.incremental`).
    """
    if not _mentions_edsconv(eds, text):
        return []
    found: Directives = []
    for comments, node in _comment_groups(eds, memo):
        mentions = [c for c in comments if "edsconv" in c.text.lower()]
        if mentions:
            reach = (0, 0) if node is None else \
                (node.line, max(node.end_line, node.line)) if isinstance(node, Entry) else (node.line, node.line)
            found += [(comment, reach) for comment in mentions]
    return found


#: The comments of an entry and of its fields (:func:`_comment_groups`): nodes, which compute their positions
ENTRY_COMMENTS = Kind("comments of")


def _comment_groups(eds: EdsFile, memo: EntryMemo | None = None) \
        -> Iterator[tuple[list[Comment], Section | Entry | Unparsed | None]]:
    """Each node's comments, with the node (None for the comments after the last statement)."""
    for section in eds.holders():
        yield [*section.leading_comments, *section.comments], section
        for entry in section.entries:
            if memo is None:
                yield _entry_comments(entry), entry
                continue
            comments = memo.get(ENTRY_COMMENTS, entry, None)
            if comments is MISSING:
                comments = _entry_comments(entry)
                memo.put(ENTRY_COMMENTS, entry, None, comments)
            yield comments, entry
        for _, unparsed in section.unparsed:
            yield [*unparsed.leading_comments, *unparsed.comments], unparsed
    yield eds.trailing_comments, None


def _entry_comments(entry: Entry) -> list[Comment]:
    comments = [*entry.leading_comments, *entry.comments]
    if not plain_fields(entry.fields):
        comments += [c for item in entry.walk_fields() if item.has_comments for c in item.comments]
    return comments
