"""The rules as documentation: docs/rules.md and the output of ``edsconv rules``, made from the registry.

Each rule carries its own text (:class:`~edsconv.diagnostics.Rule`); this module
holds the one thing the rules do not: the page's general text and its groups.
``edsconv rules --format markdown`` prints the page, and a test fails when
docs/rules.md differs from it.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterable
from dataclasses import dataclass

from edsconv.diagnostics import Alias, FixSafety, Rule, RuleRegistry, Selection, load_rules
from edsconv.fix import fix_documentation
from edsconv.idioms import idioms_section

PAGE_INTRO = """\
<!-- Generated from the rule definitions by `edsconv rules --format markdown`: edit those, not this file. -->

# edsconv rules

Every diagnostic edsconv reports carries one of these codes. Each rule is
defined, with its text on this page, in the module that reports it; this page
is generated from those definitions (`edsconv rules --format markdown`), and a
test fails when it differs from them. `edsconv rules` prints the same rules as
a table, `edsconv rules CODE` the text of one. Each rule has a `### CODE`
heading here, which SARIF output links to.

Severity: **error** fails `edsconv lint` (exit 1), **warning** fails it only
with `--warnings-as-errors`, **info** never does. *Import-blocking* marks
problems for which a major engineering tool refuses to import the file.

What ISO 15745-4:2003 says "shall" is an error, unless real tools widely accept
its breach: then it is a warning, and the rule's text says which practice (the
counts are over the 61 real files of the test corpus). Nothing the text allows
is an error. Each diagnostic cites the clause that states what it checks; where
one rule checks a requirement several clauses state (numbering, the range of a
data type), the diagnostic cites the clause of its case.

*Fix: safe* marks rules whose faults `edsconv lint --fix` repairs (`*` in
`edsconv rules`): each such fault has exactly one repair that keeps what the
file means. Some of these rules can be repaired only in the cases the rule's
text names.

Select or silence rules by code or prefix: `--select EDS0`, `--ignore EDS005,EDS006`.
An *alias* is a second code for the fault of a rule: `--select` and `--ignore`
accept it and act on the rule; no diagnostic carries it.

In the examples, `$` starts a comment, as in an EDS."""


@dataclass(frozen=True, slots=True)
class RuleGroup:
    """A section of the page: the rules whose codes start with one of ``prefixes``."""

    title: str
    prefixes: tuple[str, ...]
    intro: str = ""


#: The page's sections, in order; a code belongs to the group with its longest matching prefix.
GROUPS = (
    RuleGroup("Tool", ("EDS000", "EDS09")),
    RuleGroup("EDS syntax (reader)", ("EDS0",)),
    RuleGroup("Values (EDS1xx)", ("EDS1",), """\
A field's value is converted by the data type the spec gives the field
(C.4.1.3). These rules name what is wrong with the notation.

What the typed model holds of a value that breaks a rule: the error is reported,
and where the text allows exactly one reading of the value the model keeps it,
marked erroneous (`Device.erroneous`): `ProdCode = 06402;` is 6402, `MinRev = 02;`
is 2, `06-6-2001` is June 6, a string with a control character keeps its text.
Where no reading exists, the model holds no value: a number outside its data
type (a BOOL default of 255, a USINT of 256), a day 32, a string rejected for an
escape sequence Table C.4 does not define (EDS003: C.4.1.3.3.5 says to "reject
the entire string"). A warning's value is always kept, unmarked."""),
    RuleGroup("File structure (EDS2xx)", ("EDS2",), """\
The checks of `src/edsconv/checks/structure.py`: which sections and entries a
file has, where they stand, how many fields an entry has, and which keywords it
uses. They are driven by the tables of ISO 15745-4:2003 (`spec_tables`).
Sections, entries and keywords that later CIP editions added are checked by the
EDS5xx rules (`cip_tables`); fields beyond both and keywords defined for another
section are information (EDS209, EDS219), a keyword no table defines a warning
(EDS222), never an error. An EDS is checked against Table C.27
(EtherNet/IP) unless it is classified only under DeviceNet or ControlNet, or is
a DeviceNet EDS without classification (it has an `[IO_Info]` section); those
follow Table C.3 alone."""),
    RuleGroup("Parameters, assemblies, connections, ports, modules (EDS3xx)", ("EDS3",), """\
Checks of `src/edsconv/checks/entities.py` and, for paths, instance numbers,
ports, racks and slots, `src/edsconv/checks/addressing.py`. They read the typed model: a value
that failed conversion already has an EDS1xx diagnostic and is not reported
again, and a `Module` field of a Proxy entry defers to the module's file.
Proxied entries without a matching Proxy entry are normal (the two live in
different files) and are not reported."""),
    RuleGroup("Merge of adapter and module EDS files (`edsconv merge`, EDS4xx)", ("EDS4",), """\
See docs/merge.md for what a matching Rack entry is and how entries combine.
The examples show the adapter's entries; the module (`ProxiedXN`) is named."""),
    RuleGroup("Content beyond the 2003 text (EDS5xx)", ("EDS5",), """\
Checks of `src/edsconv/checks/objects.py` on what later CIP editions define and
real files write: [Capacity], the object class sections, AssemExaN, IconContents,
DeviceNet `[IO_Info]`, CIP Safety entries (the tables: `cip_tables`, docs/spec_tables.md).
We do not hold the current CIP specification, so the clause of these rules is the
source of the fact: `eds-pie 1.2.0` (its references state the type, keyword list,
class ID or required entry: an error) or `real files` (known from practice only: a
warning at most). The message names the exact record."""),
    RuleGroup("The device against its EDS (`edsconv verify`, EDS6xx)", ("EDS6",), """\
Reported by `edsconv verify` (docs/verify.md, `src/edsconv/verify/`), never by lint: each
compares what the running device answers (List Identity, Get_Attribute_Single, with
`--connect` a Forward Open) with the EDS entry that states it, and is reported there."""),
    RuleGroup("XML profiles (`edsconv validate`)", ("XML0",)),
    RuleGroup("Conversion (`edsconv xml2eds`)", ("XML1", "XML2")),
)


def group_of(code: str) -> RuleGroup:
    """The group whose longest prefix matches ``code``."""
    length, group = max(((len(p), g) for g in GROUPS for p in g.prefixes if code.startswith(p)),
                        default=(0, None), key=lambda found: found[0])
    if group is None:
        raise LookupError(f"no group of docs/rules.md takes {code}: add a prefix to rule_docs.GROUPS")
    return group


# --- Markdown ------------------------------------------------------------------------
def alias_heading(alias: Alias, of: Rule) -> str:
    return f"### {alias.code} (alias of {of.code})"


_FIX_NOTE = {FixSafety.SAFE: "`edsconv lint --fix` repairs it", FixSafety.UNSAFE: "offered, never applied"}


def rule_section(r: Rule) -> str:
    """A rule's part of the page: heading, summary, severity and clause, explanation, the two examples."""
    blocking = " (import-blocking)" if r.import_blocking else ""
    clause = f"{r.clause} ({r.clause_note})" if r.clause_note else r.clause
    facts = [f"- Severity: {r.severity}{blocking}", f"- Clause: {clause}"]
    if r.fix is not FixSafety.NONE:
        facts.append(f"- Fix: {r.fix} ({_FIX_NOTE[r.fix]})")
    fix = f"Fix: {fix_documentation(r.code)}" if r.fix is not FixSafety.NONE and fix_documentation(r.code) else ""
    facts += [f"- Alias: [{a.code}](#{_anchor(alias_heading(a, r))})" for a in r.aliases]
    parts = [f"### {r.code}", _sentence(r.summary), "\n".join(facts), r.explanation, fix,
             _example(r.labels[0], r.bad), _example(r.labels[1], r.good)]
    return "\n\n".join(part for part in parts if part)


def rule_help_text(r: Rule) -> str:
    """A rule's documentation as plain text (SARIF ``help.text``): the Markdown of :func:`rule_section`
    without its heading, fences and emphasis."""
    body = rule_section(r).split("\n\n", 1)[1]
    return re.sub(r"^```\w*\n|\n```$|\*\*|`", "", body, flags=re.MULTILINE).strip()


def alias_section(alias: Alias, of: Rule) -> str:
    return "\n\n".join([
        alias_heading(alias, of), alias.note,
        f"`--select {alias.code}` and `--ignore {alias.code}` act on [{of.code}](#{of.code.lower()}); "
        f"no diagnostic carries {alias.code}."])


def rules_page(registry: RuleRegistry | None = None) -> str:
    """docs/rules.md: the general text, then each group with its rules and aliases in code order."""
    registry = registry or load_rules()
    entries = [(r.code, rule_section(r)) for r in registry.rules.values()]
    entries += [(code, alias_section(_alias(of, code), of)) for code, of in registry.aliases.items()]
    sections = [PAGE_INTRO]
    for group in GROUPS:
        members = [text for code, text in sorted(entries) if group_of(code) is group]
        if members:
            sections.append("\n\n".join(part for part in (f"## {group.title}", group.intro, *members) if part))
    sections.append(idioms_section())
    return "\n\n".join(sections) + "\n"


def _example(label: str, text: str) -> str:
    """``Label: text`` for an inline example, the label on a line of its own before a fenced block."""
    if not text:
        return ""
    return f"{label}:\n\n{text}" if text.startswith("```") else f"{label}: {text}"


def _sentence(text: str) -> str:
    return text if text.endswith((".", "!", "?")) else text + "."


def _anchor(heading: str) -> str:
    """The anchor GitHub gives a heading: lower case, punctuation dropped, spaces as hyphens."""
    words = heading.lstrip("#").strip().lower()
    return "".join(c for c in words if c.isalnum() or c in " -_").replace(" ", "-")


def _alias(of: Rule, code: str) -> Alias:
    return next(a for a in of.aliases if a.code == code)


# --- edsconv rules ---------------------------------------------------------------------
def chosen_rules(codes: Iterable[str] = ()) -> list[Rule]:
    """The rules whose codes start with one of ``codes`` (an alias stands for its rule); all without codes."""
    selection = Selection.of(codes)
    return [r for r in load_rules().rules.values() if r.code in selection]


def rules_table(rules: list[Rule]) -> str:
    """One line a rule: code, severity, clause, ``!`` when import-blocking, ``*`` when ``--fix`` repairs it,
    summary, aliases."""
    clause_width = max((len(r.clause) for r in rules), default=0)
    lines = []
    for r in rules:
        mark = ("!" if r.import_blocking else " ") + ("*" if r.fix is FixSafety.SAFE else " ")
        aliases = f" (alias: {', '.join(a.code for a in r.aliases)})" if r.aliases else ""
        lines.append(f"{r.code}  {str(r.severity):7}  {r.clause:{clause_width}}  {mark} {r.summary}{aliases}\n")
    return "".join(lines)


def format_rules(output_format: str, codes: Iterable[str] = ()) -> str:
    """What ``edsconv rules [CODES]`` prints.

    text: the table, or the full text of each rule when codes are given; json: the full records;
    markdown: docs/rules.md, or the sections of the rules asked for.
    """
    codes = tuple(codes)
    rules = chosen_rules(codes)
    if output_format == "json":
        return json.dumps([r.as_dict() for r in rules], indent=2) + "\n"
    if output_format == "markdown" and not codes:
        return rules_page()
    if output_format == "text" and not codes:
        return rules_table(rules)
    if output_format == "text":  # each rule's text, and where it opens in the installed documentation
        from edsconv.report import rule_help_uri

        return "\n\n".join(f"{rule_section(r)}\n\nDocumentation: {rule_help_uri(r.code)}" for r in rules) + "\n"
    return "\n\n".join(rule_section(r) for r in rules) + "\n"
