"""Safe fixes: the repairs ``edsconv lint --fix`` applies and the language server offers.

A rule whose :attr:`~edsconv.diagnostics.Rule.fix` is ``safe`` has a fixer here:
given the syntax model and one of its diagnostics, the fixer returns the one
edit that repairs it, or None when this occurrence has no single repair (then
nothing is done). Edits are made on the text as the file has it, line by line,
so line ends, comments and the encoding stay as they were.

:func:`fix_source` repeats fix, re-read and re-check until nothing more can be
fixed (a fix can uncover another fault); the caller writes the result.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field

from edsconv import spec_tables as tables
from edsconv.diagnostics import Diagnostic, FixSafety, load_rules
from edsconv.eds.locate import locate
from edsconv.eds.reader import parse
from edsconv.eds.source import encode, split_lines
from edsconv.eds.syntax import EdsFile
from edsconv.suppress import SUPPRESSION

#: The clauses that require the null string ``""`` in an empty required field (C.4.1.4.9.12: "If no help
#: string is to be provided a "null" string shall be used").
NULL_STRING_CLAUSES = ("C.4.1.4.9.12",)
#: At most this many rounds of fix and re-check (each round fixes every fault it can).
MAX_ROUNDS = 10
_LEADING_ZEROS = re.compile(r"(?P<sign>[+-]?)0+(?P<digits>[0-9]+)")


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


Fixer = Callable[[EdsFile, list[str], Diagnostic], Fix | None]


def _line(lines: list[str], number: int) -> str:
    return lines[number - 1].rstrip("\r\n") if 0 < number <= len(lines) else ""


# --- the fixers, one per rule --------------------------------------------------------------
def _missing_semicolon(eds: EdsFile, lines: list[str], d: Diagnostic) -> Fix | None:
    """The `;` is added where the reader assumed it: at the end of the entry's last field."""
    return Fix("Add the missing ';'", (Edit(d.line, d.column, d.line, d.column, ";"),))


def _leading_zeros(eds: EdsFile, lines: list[str], d: Diagnostic) -> Fix | None:
    """The number is written without its leading zeros: `0254` is read as 254, so it becomes `254`."""
    found = locate(eds, d.line, d.column).field
    raw = found.raw if found is not None else None
    match = _LEADING_ZEROS.fullmatch(raw or "")
    if raw is None or match is None or _line(lines, d.line)[d.column - 1:d.column - 1 + len(raw)] != raw:
        return None
    written = f"{match['sign']}{match['digits']}"
    return Fix(f"Write {written} without leading zeros",
               (Edit(d.line, d.column, d.line, d.column + len(raw), written),))


def _null_string(eds: EdsFile, lines: list[str], d: Diagnostic) -> Fix | None:
    """Only for an empty field whose clause requires the null string when there is nothing to say (the help
    string of ConnectionN and ProxyConnectN, C.4.1.4.9.12): `""` is written in it. Other required fields
    have no fix: only the author knows their value."""
    spot = locate(eds, d.line, d.column)
    if spot.entry is None or spot.section is None or spot.field is None or len(spot.field_path) != 1 \
            or not spot.field.is_empty or (spot.field.line, spot.field.column) != (d.line, d.column):
        return None
    spec = tables.entry_spec(spot.section.name, spot.entry.keyword)
    field_spec = spec.field_at(spot.field_path[0] + 1) if spec is not None else None
    if field_spec is None or field_spec.clause not in NULL_STRING_CLAUSES:
        return None
    return Fix(f'Write the null string "" for the {field_spec.name} ({field_spec.clause})',
               (Edit(d.line, d.column, d.line, d.column, '""'),))


def _section_case(eds: EdsFile, lines: list[str], d: Diagnostic) -> Fix | None:
    """Only for a section the spec defines, spelled in other letter case (`[DEVICE]`) in a file that has no
    section of the spec's spelling: the name is written as Table C.3 does."""
    spot = locate(eds, d.line, d.column)
    section = spot.section
    if section is None or not spot.on_header:
        return None
    spelled = [name for name in tables.SECTIONS if name.casefold() == section.name.casefold()]
    if len(spelled) != 1 or any(s.name == spelled[0] for s in eds.sections):
        return None
    text = _line(lines, section.line)
    start = text.find(f"[{section.name}]", section.column - 1)
    if start < 0:
        return None
    return Fix(f"Write the section name as the spec does: [{spelled[0]}]",
               (Edit(section.line, start + 2, section.line, start + 2 + len(section.name), spelled[0]),))


def _unused_suppression(eds: EdsFile, lines: list[str], d: Diagnostic) -> Fix | None:
    """The code is removed from its comment, and the comment when it held nothing else."""
    text = _line(lines, d.line)
    match = next((m for m in SUPPRESSION.finditer(text) if m.start("codes") < d.column <= m.end("codes")), None)
    if match is None:
        return None
    codes = [c for c in re.finditer(r"[^,\s]+", match["codes"]) if match.start("codes") + c.start() + 1 != d.column]
    if codes:
        kept = ", ".join(c.group() for c in codes)
        return Fix("Remove the unused suppression code",
                   (Edit(d.line, match.start("codes") + 1, d.line, match.end("codes") + 1, kept),))
    dollar = text.rfind("$", 0, match.start())
    if dollar < 0 or text[dollar + 1:match.start()].strip() or text[match.end():].strip():
        return Fix("Remove the unused suppression", (Edit(d.line, match.start() + 1, d.line, match.end() + 1, ""),))
    before = text[:dollar].rstrip()
    if before:
        return Fix("Remove the unused suppression comment", (Edit(d.line, len(before) + 1, d.line, len(text) + 1, ""),))
    return Fix("Remove the unused suppression comment", (Edit(d.line, 1, d.line + 1, 1, ""),))


#: The fixer of each rule whose fix is safe (a test checks this against the registry).
FIXERS: dict[str, Fixer] = {
    "EDS002": _missing_semicolon,
    "EDS099": _unused_suppression,
    "EDS103": _leading_zeros,
    "EDS207": _null_string,
    "EDS228": _section_case,
}


def fix_documentation(code: str) -> str:
    """What the fix of rule ``code`` does, for docs/rules.md: its fixer's docstring."""
    fixer = FIXERS.get(code)
    return " ".join((fixer.__doc__ or "").split()) if fixer is not None else ""


def fix_for(eds: EdsFile, lines: list[str], diagnostic: Diagnostic) -> Fix | None:
    """The safe fix of ``diagnostic``, if its rule has one and this occurrence allows it."""
    registered = load_rules().rules.get(diagnostic.code)
    fixer = FIXERS.get(diagnostic.code)
    if registered is None or registered.fix is not FixSafety.SAFE or fixer is None or diagnostic.line < 1:
        return None
    return fixer(eds, lines, diagnostic)


def fixes_of(eds: EdsFile, data: bytes, diagnostics: Iterable[Diagnostic]) -> dict[tuple[str, int, int, str], Fix]:
    """The safe fix of each diagnostic of the file ``data`` that has one, by
    :func:`edsconv.report.fix_key` (what ``[*]`` marks and SARIF carries)."""
    from edsconv.report import fix_key

    fixable = [d for d in diagnostics if d.code in FIXERS]
    if not fixable:
        return {}
    lines = split_lines(raw_text(data, eds.encoding))
    return {fix_key(d): f for d in fixable if (f := fix_for(eds, lines, d)) is not None}


def apply_edits(text: str, edits: Iterable[Edit]) -> str:
    """``text`` with ``edits`` made (they must not overlap); line ends stay as they are."""
    lines = split_lines(text)
    starts = [0]
    for line in lines:
        starts.append(starts[-1] + len(line))

    def offset(line: int, column: int) -> int:
        return starts[min(line, len(lines) + 1) - 1] + column - 1 if line <= len(lines) else len(text)

    for edit in sorted(edits, key=lambda e: (e.line, e.column), reverse=True):
        text = text[:offset(edit.line, edit.column)] + edit.text + text[offset(edit.end_line, edit.end_column):]
    return text


def _disjoint(fixes: Iterable[Fix]) -> list[Edit]:
    """The edits of ``fixes``, leaving out every fix that overlaps one taken before (it waits a round)."""
    taken: list[Edit] = []
    for candidate in fixes:
        spans = [((e.line, e.column), (e.end_line, e.end_column)) for e in candidate.edits]
        if all(end < (t.line, t.column) or start > (t.end_line, t.end_column)
               for start, end in spans for t in taken):
            taken.extend(candidate.edits)
    return taken


@dataclass(slots=True)
class FixOutcome:
    """The text after fixing, what was fixed, and the diagnostics of the fixed text."""

    data: bytes
    #: the encoding the file was read in, and written back in
    encoding: str
    fixed: list[Diagnostic] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)


def fix_source(data: bytes, path: str | None, check: Callable[[EdsFile], list[Diagnostic]]) -> FixOutcome:
    """Fix every fault of the file ``data`` that ``check`` reports and that has a safe fix, round after round.

    ``check`` gives the diagnostics reported for a syntax model (selection, suppressions applied).
    """
    eds = parse(data, path)
    diagnostics = check(eds)
    fixed: list[Diagnostic] = []
    for _ in range(MAX_ROUNDS):
        text = raw_text(data, eds.encoding)
        lines = split_lines(text)
        fixes = [(d, f) for d in diagnostics if (f := fix_for(eds, lines, d)) is not None]
        edits = _disjoint(f for _, f in fixes)
        if not edits:
            break
        taken = set(edits)
        fixed += [d for d, f in fixes if taken.issuperset(f.edits)]
        data = encode(apply_edits(text, edits), eds.encoding)
        eds = parse(data, path)
        diagnostics = check(eds)
    return FixOutcome(data, eds.encoding, fixed, diagnostics)


def raw_text(data: bytes, encoding: str) -> str:
    """The text of a file as the reader decoded it (:mod:`edsconv.eds.source`), but with its line ends as they are."""
    text = data.decode(encoding, errors="replace")
    # utf-8-sig drops its byte order mark itself; the wide codecs keep it as a character
    return text[1:] if encoding.startswith(("utf-16", "utf-32")) and text.startswith("\ufeff") else text
