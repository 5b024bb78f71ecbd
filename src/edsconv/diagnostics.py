"""Diagnostics and the rule registry.

Every problem edsconv reports is a :class:`Diagnostic` carrying the stable code
of a :class:`Rule`. A rule is defined once, in the module that reports it, with
its severity, the spec clause it enforces, a one-line summary and its
documentation (explanation, a bad and a good example), so that ``edsconv rules``,
docs/rules.md and every output format draw on the same record (the sqlfluff /
ruff model). :func:`load_rules` collects them from :data:`RULE_MODULES`.
"""

from __future__ import annotations

import enum
import functools
import importlib
import re
import textwrap
from collections.abc import Iterable
from dataclasses import dataclass, field, replace


class Severity(enum.IntEnum):
    """Ordered so that ``max()`` over diagnostics gives the worst one."""

    INFO = 1
    WARNING = 2
    ERROR = 3

    def __str__(self) -> str:
        return self.name.lower()


class FixSafety(enum.StrEnum):
    """What ``edsconv lint --fix`` may do about a rule's faults (ruff's fix safety)."""

    #: no fix is known
    NONE = "none"
    #: exactly one fix keeps the file's meaning: ``--fix`` applies it (when the fault allows one)
    SAFE = "safe"
    #: a fix exists but may change what the file means: shown, never applied
    UNSAFE = "unsafe"


#: How a rule's documentation introduces its two examples: one that breaks the rule, one that does not.
BAD_GOOD = ("Bad", "Good")
#: For rules whose first example is not a mistake as such (information, or a condition a file may meet).
TRIGGERS = ("Triggers", "Does not")


@dataclass(frozen=True, slots=True)
class Alias:
    """A second code for the fault of a rule: ``--select``/``--ignore`` accept it, no diagnostic carries it."""

    code: str
    #: Where the code came from, for docs/rules.md.
    note: str


@dataclass(frozen=True, slots=True)
class Rule:
    """A rule and its documentation: docs/rules.md and ``edsconv rules`` are generated from these fields.

    ``explanation``, ``bad`` and ``good`` are Markdown: an example stands inline
    after its label unless it starts with a fenced block (:func:`block`).
    """

    code: str
    severity: Severity
    clause: str
    summary: str
    #: True when a major engineering tool refuses to import a file with this problem.
    import_blocking: bool = False
    #: More precise pointers than the clause (tables, further clauses), shown after it in the docs.
    clause_note: str = ""
    explanation: str = ""
    bad: str = ""
    good: str = ""
    labels: tuple[str, str] = BAD_GOOD
    aliases: tuple[Alias, ...] = ()
    fix: FixSafety = FixSafety.NONE

    def as_dict(self) -> dict:
        """The full record, as ``edsconv rules --format json`` prints it."""
        return {
            "code": self.code,
            "severity": str(self.severity),
            "clause": self.clause,
            "import_blocking": self.import_blocking,
            "summary": self.summary,
            "clause_note": self.clause_note,
            "explanation": self.explanation,
            "examples": {"labels": list(self.labels), "bad": self.bad, "good": self.good},
            "aliases": [{"code": a.code, "note": a.note} for a in self.aliases],
            "fix": str(self.fix),
        }


_CODE = re.compile(r"(EDS|XML)[0-9]{3}")


def rule(code: str, severity: Severity, clause: str, summary: str, *, explanation: str, bad: str, good: str,
         import_blocking: bool = False, clause_note: str = "", labels: tuple[str, str] = BAD_GOOD,
         aliases: dict[str, str] | None = None, fix: str = "none") -> Rule:
    """A rule with its documentation; the texts are dedented, so they may be indented like the code.

    ``fix`` is "safe" when ``edsconv lint --fix`` (:mod:`edsconv.fix`) repairs the fault, "unsafe" when a
    repair exists but is never applied.

    Defining a rule does not register it: :func:`load_rules` collects the rules of :data:`RULE_MODULES`.
    """
    for named in (code, *(aliases or ())):
        if not _CODE.fullmatch(named):
            raise ValueError(f"rule code {named!r} is not EDSnnn or XMLnnn")
    return Rule(code, severity, clause, summary, import_blocking, clause_note, _text(explanation), _text(bad),
                _text(good), labels, tuple(Alias(alias, _text(note)) for alias, note in (aliases or {}).items()),
                FixSafety(fix))


def block(code: str, language: str = "") -> str:
    """An example as a fenced Markdown code block (the code is dedented: indent it like the call)."""
    return f"```{language}\n{textwrap.dedent(code).strip(chr(10))}\n```"


def _text(markdown: str) -> str:
    return textwrap.dedent(markdown).strip()


#: Every module that defines rules: :func:`load_rules` collects their module-level :class:`Rule` objects.
RULE_MODULES = ("edsconv.lint", "edsconv.suppress", "edsconv.eds.refusals", "edsconv.eds.reader_rules",
                "edsconv.model.values", "edsconv.model.build", "edsconv.checks.structure_rules",
                "edsconv.checks.entity_rules", "edsconv.checks.addressing_rules", "edsconv.checks.object_rules",
                "edsconv.checks.coherence_rules", "edsconv.merge", "edsconv.xml.validate", "edsconv.xml.convert",
                "edsconv.xml.device_read", "edsconv.verify.rules")


@dataclass(frozen=True, slots=True)
class RuleRegistry:
    """Every rule by code (sorted), and every alias code with the rule it names."""

    rules: dict[str, Rule]
    aliases: dict[str, Rule]

    def resolve(self, code: str) -> str:
        """The code a diagnostic carries for ``code``: itself, or the rule an alias names."""
        return self.aliases[code].code if code in self.aliases else code

    def knows_prefix(self, prefix: str) -> bool:
        return any(code.startswith(prefix) for code in (*self.rules, *self.aliases))


@functools.cache
def load_rules() -> RuleRegistry:
    """Import each module of :data:`RULE_MODULES` and collect its rules; codes and aliases are unique."""
    rules: dict[str, Rule] = {}
    for name in RULE_MODULES:
        for value in vars(importlib.import_module(name)).values():
            if isinstance(value, Rule) and rules.setdefault(value.code, value) is not value:
                raise ValueError(f"duplicate rule code {value.code}")
    aliases: dict[str, Rule] = {}
    for registered in rules.values():
        for alias in registered.aliases:
            if alias.code in rules or aliases.setdefault(alias.code, registered) is not registered:
                raise ValueError(f"alias {alias.code} is already a rule or an alias")
    return RuleRegistry(dict(sorted(rules.items())), dict(sorted(aliases.items())))


def all_rules() -> list[Rule]:
    """Every rule, sorted by code."""
    return list(load_rules().rules.values())


@dataclass(frozen=True, slots=True)
class Selection:
    """``--select`` and ``--ignore``: codes or code prefixes, by ruff's rule.

    The longest matching prefix decides, ``ignore`` on a tie; no ``select``
    selects every code. An alias code stands for the code of its rule.
    """

    select: tuple[str, ...] = ()
    ignore: tuple[str, ...] = ()

    @classmethod
    def of(cls, select: Iterable[str] = (), ignore: Iterable[str] = ()) -> Selection:
        select, ignore = tuple(select), tuple(ignore)
        if not select and not ignore:
            return EVERYTHING  # without loading every rule module (XML ones import lxml): start-up
        registry = load_rules()
        return cls(tuple(map(registry.resolve, select)), tuple(map(registry.resolve, ignore)))

    @property
    def everything(self) -> bool:
        return not self.select and not self.ignore

    def __contains__(self, code: str) -> bool:
        chosen = max((len(p) for p in self.select if code.startswith(p)), default=None if self.select else 0)
        dropped = max((len(p) for p in self.ignore if code.startswith(p)), default=None)
        if chosen is None:
            return False
        return dropped is None or chosen > dropped

    def any_of(self, rules: Iterable[Rule]) -> bool:
        return any(r.code in self for r in rules)


EVERYTHING = Selection()


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
           end_line: int | None = None, end_column: int | None = None, clause: str = "") -> Diagnostic:
        """A diagnostic of ``rule_``; ``clause`` names the clause of this case where a rule checks one
        requirement that several clauses state (GroupN numbering is C.4.1.4.7, RackN C.4.1.5.2.3)."""
        return cls(rule_.code, message, line, column, path, rule_.severity, clause or rule_.clause, end_line,
                   end_column)

    def moved(self, first_line: int, delta: int) -> Diagnostic:
        """This diagnostic after the lines from ``first_line`` on moved ``delta`` lines (itself when it
        stands before them)."""
        def moved(line: int) -> int:
            return line + delta if line >= first_line else line

        if self.line < first_line and (self.end_line or 0) < first_line:
            return self
        return replace(self, line=moved(self.line), end_line=None if self.end_line is None else moved(self.end_line))

    def format(self) -> str:
        """``path:line:col: severity: CODE message [clause]``, as compilers print it (editors' problem matchers
        read the severity there). A finding about the whole file stands at 1:1, as in every format
        (``edsconv.report.position``: problem matchers need 1-based positions)."""
        where = f"{self.path or '<string>'}:{max(self.line, 1)}:{max(self.column, 1)}"
        clause = f" [{self.clause}]" if self.clause else ""
        return f"{where}: {self.severity}: {self.code} {self.message}{clause}"

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
