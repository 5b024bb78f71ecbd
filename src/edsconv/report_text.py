"""The text output of ``edsconv lint``, for people: findings (concise or with the source), colour, the summary.

``concise`` is one line a finding, ``path:line:col: severity: CODE message [clause]``, what
compilers print and editors' problem matchers read; ``full`` adds, as rustc and ruff do, the
line at fault with a caret under the field and a link to the rule's documentation. ``text``
is full on a terminal and concise otherwise, so that CI logs stay short. Colour follows
:func:`colour_wanted`. The formats for machines are :mod:`edsconv.report`'s.
"""

from __future__ import annotations

import os
from collections import Counter
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TextIO

from edsconv.diagnostics import Diagnostic, Severity
from edsconv.report import FileReport, counts, file_lines, plural, position, printable, rule_help_uri

#: ANSI SGR codes of what is coloured: severities, the code, the path, the excerpt's gutter.
_SGR = {Severity.ERROR: "1;31", Severity.WARNING: "1;33", Severity.INFO: "1;36",
        "code": "1", "path": "1", "gutter": "1;34", "fixable": "1;32"}
#: How many rules the summary names (``Top rules: ...``).
TOP_RULES = 5
#: Tabs in an excerpt are shown as this many spaces, so that the caret stands under the field.
TAB_WIDTH = 4
#: A longer source line is shown as the part of this many characters around the field at fault.
EXCERPT_WIDTH = 120
FIX_COMMAND = "`edsconv lint --fix`"


def colour_wanted(choice: str, stream: TextIO, environ: dict[str, str] | None = None) -> bool:
    """``--color always|never`` decide; ``auto``: off when NO_COLOR is set (no-color.org), on when
    FORCE_COLOR is (force-color.org), else on only when ``stream`` is a terminal."""
    if choice != "auto":
        return choice == "always"
    environ = dict(os.environ) if environ is None else environ
    if environ.get("NO_COLOR"):
        return False
    if environ.get("FORCE_COLOR"):
        return True
    return stream.isatty()


@dataclass(frozen=True, slots=True)
class Style:
    """Paints text when colour is on; plain otherwise."""

    colour: bool = False

    def paint(self, text: str, what: Severity | str) -> str:
        return f"\x1b[{_SGR[what]}m{text}\x1b[0m" if self.colour else text


PLAIN = Style()


# --- findings -------------------------------------------------------------------------
def headline(report: FileReport, d: Diagnostic, style: Style = PLAIN) -> str:
    """``path:line:col: severity: CODE message [clause]``, and ``[*]`` when ``--fix`` repairs it."""
    line, column = position(d)
    clause = f" [{d.clause}]" if d.clause else ""
    fixable = " " + style.paint("[*]", "fixable") if report.fix_of(d) is not None else ""
    return (f"{style.paint(f'{printable(report.path)}:{line}:{column}', 'path')}: "
            f"{style.paint(str(d.severity), d.severity)}: {style.paint(d.code, 'code')} "
            f"{printable(d.message)}{clause}{fixable}")


def format_concise(reports: Sequence[FileReport], style: Style = PLAIN) -> str:
    """One line a finding: the format of scripts, CI logs and editors' problem matchers."""
    return "".join(headline(r, d, style) + "\n" for r in reports for d in r.diagnostics)


def format_full(reports: Sequence[FileReport], style: Style = PLAIN) -> str:
    """Each finding with the line at fault, a caret under the field, and the link to its rule."""
    out = []
    for report in reports:
        lines = _source_lines(report.path) if report.diagnostics else []
        for d in report.diagnostics:
            margin = " " * len(str(d.line))
            out.append(headline(report, d, style) + "\n" + excerpt(lines, d, style)
                       + f"{style.paint(margin + ' =', 'gutter')} docs: {rule_help_uri(d.code)}\n\n")
    return "".join(out)


def excerpt(lines: list[str], d: Diagnostic, style: Style = PLAIN) -> str:
    """The line of ``d`` under a gutter with its number, and carets under the field at fault; nothing
    for a finding without a line (or a line the file no longer has)."""
    if not 0 < d.line <= len(lines):
        return ""
    text = lines[d.line - 1]
    column = max(d.column, 1)
    end = d.end_column if d.end_line == d.line and d.end_column and d.end_column > column \
        else _field_end(text, column)
    shown = text.expandtabs(TAB_WIDTH)
    start = len(text[:column - 1].expandtabs(TAB_WIDTH))
    width = max(len(text[:end - 1].expandtabs(TAB_WIDTH)) - start, 1)
    if len(shown) > EXCERPT_WIDTH:  # a long line (an icon, a long string): the part around the field
        left = max(start - EXCERPT_WIDTH // 4, 0)
        shown = ("..." if left else "") + shown[left:left + EXCERPT_WIDTH] + \
            ("..." if left + EXCERPT_WIDTH < len(shown) else "")
        start, width = start - left + (3 if left else 0), min(width, EXCERPT_WIDTH - (start - left))
    number = str(d.line)
    gutter = style.paint(" " * len(number) + " |", "gutter")
    return (f"{gutter}\n{style.paint(number + ' |', 'gutter')} {printable(shown)}\n"
            f"{gutter} {' ' * start}{style.paint('^' * width, d.severity)}\n")


def _field_end(text: str, column: int) -> int:
    """The column after the field at ``column``: a section header to its ``]``, any other value to its end."""
    from edsconv.eds.locate import value_end

    if text[column - 1:column] == "[" and "]" in text[column:]:
        return text.index("]", column) + 2
    return max(value_end(text, column), column + 1)


def _source_lines(path: str) -> list[str]:
    return [line.rstrip("\r") for line in file_lines(path)]


def format_text(reports: Sequence[FileReport], style: Style = PLAIN, terminal: bool = False) -> str:
    """``text``: full on a terminal, concise otherwise (CI logs, pipes, problem matchers)."""
    return (format_full if terminal else format_concise)(reports, style)


TEXT_FORMATS: dict[str, Callable[..., str]] = {"concise": format_concise, "full": format_full}


# --- the closing summary -------------------------------------------------------------------
def summary(reports: Sequence[FileReport], seconds: float, style: Style = PLAIN) -> str:
    """What a person acts on after a run: counts by severity, files with errors, the rules found most
    often, what ``--fix`` would repair, what could not be checked, and the time taken."""
    found = [d for r in reports for d in r.diagnostics]
    lines = [counts(reports)]
    with_errors = sum(any(d.severity is Severity.ERROR for d in r.diagnostics) for r in reports)
    if with_errors and len(reports) > 1:
        lines.append(f"{style.paint(plural(with_errors, 'file'), Severity.ERROR)} with errors")
    top = Counter(d.code for d in found).most_common(TOP_RULES)
    if len(found) > TOP_RULES:  # a handful of findings are read in full; a list of rules says nothing more
        lines.append("top rules: " + ", ".join(f"{style.paint(code, 'code')} ({n:,})" for code, n in top))
    fixed = sum(len(r.fixed) for r in reports)
    if fixed:
        lines.append(f"fixed {plural(fixed, 'problem')}")
    fixable = sum(r.fix_of(d) is not None for r in reports for d in r.diagnostics)
    if fixable:
        lines.append(f"{style.paint('[*]', 'fixable')} {fixable:,} fixable with {FIX_COMMAND}")
    failed = sum(r.error is not None for r in reports)
    if failed:
        lines.append(f"{plural(failed, 'file')} could not be checked")
    return "\n".join(lines) + f"\nchecked in {seconds:.2f} s\n"


def statistics(reports: Sequence[FileReport]) -> list[dict]:
    """``--statistics``: each rule found, most often first: its count, severity, fixable count, summary."""
    from edsconv.diagnostics import load_rules

    rules = load_rules().rules
    found = Counter(d.code for r in reports for d in r.diagnostics)
    fixable = Counter(d.code for r in reports for d in r.diagnostics if r.fix_of(d) is not None)
    return [{"code": code, "count": n, "fixable": fixable[code],
             "severity": str(rules[code].severity) if code in rules else "",
             "summary": rules[code].summary if code in rules else ""} for code, n in found.most_common()]


def format_statistics(rows: list[dict], style: Style = PLAIN) -> str:
    """ruff's ``--statistics`` table: count, code, ``[*]`` when some are fixable, summary."""
    width = max((len(f"{row['count']:,}") for row in rows), default=1)
    return "".join(f"{row['count']:>{width},}  {style.paint(row['code'], 'code')}  "
                   f"{style.paint('[*]', 'fixable') if row['fixable'] else '   '} {row['summary']}\n" for row in rows)
