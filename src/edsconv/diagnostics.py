"""Diagnostics and the rule registry.

Every problem edsconv reports is a :class:`Diagnostic` carrying a stable code
from :data:`RULES`. Rules are registered once, with their severity, the spec
clause they enforce and a one-line explanation, so that ``edsconv rules``,
docs/rules.md and every output format draw on the same table (the sqlfluff /
ruff model).
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field


class Severity(enum.IntEnum):
    """Ordered so that ``max()`` over diagnostics gives the worst one."""

    INFO = 1
    WARNING = 2
    ERROR = 3

    def __str__(self) -> str:
        return self.name.lower()


@dataclass(frozen=True, slots=True)
class Rule:
    code: str
    severity: Severity
    clause: str
    summary: str
    #: True when a major engineering tool refuses to import a file with this problem.
    import_blocking: bool = False


RULES: dict[str, Rule] = {}


def rule(code: str, severity: Severity, clause: str, summary: str, *, import_blocking: bool = False) -> Rule:
    """Register a rule; codes are unique and never reused."""
    if code in RULES:
        raise ValueError(f"duplicate rule code {code}")
    registered = Rule(code, severity, clause, summary, import_blocking)
    RULES[code] = registered
    return registered


@dataclass(slots=True)
class Diagnostic:
    code: str
    message: str
    line: int = 0
    column: int = 0
    path: str | None = None
    severity: Severity = field(default=Severity.ERROR)
    clause: str = ""
    end_line: int | None = None
    end_column: int | None = None

    @classmethod
    def of(cls, rule_: Rule, message: str, line: int = 0, column: int = 0, path: str | None = None,
           end_line: int | None = None, end_column: int | None = None) -> Diagnostic:
        return cls(rule_.code, message, line, column, path, rule_.severity, rule_.clause, end_line, end_column)

    def format(self) -> str:
        """``path:line:col: CODE message [clause]`` as flake8 and ruff print it."""
        where = f"{self.path or '<string>'}:{self.line}:{self.column}"
        clause = f" [{self.clause}]" if self.clause else ""
        return f"{where}: {self.code} {self.message}{clause}"

    def as_dict(self) -> dict:
        return {
            "code": self.code,
            "severity": str(self.severity),
            "line": self.line,
            "column": self.column,
            "end_line": self.end_line,
            "end_column": self.end_column,
            "message": self.message,
            "clause": self.clause,
        }


def has_errors(diagnostics: list[Diagnostic]) -> bool:
    return any(d.severity is Severity.ERROR for d in diagnostics)
