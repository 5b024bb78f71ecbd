"""Go to definition, find references and rename, over :mod:`edsconv.model.references`.

A rename renumbers an entry within its family (``Param7`` -> ``Param12``) and
rewrites every place that names it: references, path substitutions, group
members (written as bare numbers) and the entries paired with it by number
(``Enum7`` -> ``Enum12``). It is refused when an entry of the new name exists, and
for a family whose numbers start at 1 and go up by one (ConnectionN, GroupN,
ClassN, RackN): any new number would leave a gap or a duplicate there.
"""

from __future__ import annotations

from edsconv import spec_tables as tables
from edsconv.lsp.analysis import Analysis
from edsconv.model.references import Occurrence, occurrence_at, references_to

#: (line, column, end_line, end_column), 1-based, end exclusive
Span = tuple[int, int, int, int]


class RenameRefused(ValueError):
    """A rename that would break the file; the message says why."""


def span_of(occurrence: Occurrence) -> Span:
    return occurrence.line, occurrence.column, occurrence.line, occurrence.end_column


def target_at(analysis: Analysis, line: int, column: int) -> Occurrence | None:
    """The span naming an entry (or defining it) at ``line``:``column``."""
    return occurrence_at(analysis.spans, line, column)


def definition(analysis: Analysis, line: int, column: int) -> Span | None:
    """Where the entry named at ``line``:``column`` is defined; None when it is not (or nothing is named)."""
    found = target_at(analysis, line, column)
    entry = analysis.definitions.get(found.target) if found is not None else None
    if entry is None:
        return None
    return entry.line, entry.column, entry.line, entry.column + len(entry.keyword)


def references(analysis: Analysis, line: int, column: int, include_declaration: bool) -> list[Span]:
    """Every place naming the entry named at ``line``:``column``, its definition only if asked."""
    found = target_at(analysis, line, column)
    if found is None:
        return []
    return [span_of(o) for o in references_to(found.target, analysis.spans)
            if include_declaration or o.kind != "definition"]


def rename(analysis: Analysis, line: int, column: int, new_name: str) -> list[tuple[Span, str]]:
    """The edits that renumber the entry named at ``line``:``column`` to ``new_name``."""
    found = target_at(analysis, line, column)
    if found is None:
        raise RenameRefused("there is no numbered entry or reference here to rename")
    family, _ = tables.split_numbered(found.target)
    new_family, number = tables.split_numbered(new_name.strip())
    if number is None or new_family != family:
        raise RenameRefused(f"{found.target} can only be renumbered within its family: {family}<number>")
    _refuse_sequential(analysis, found.target, new_name.strip())
    spans = references_to(found.target, analysis.spans)
    keywords = {entry.keyword for section in analysis.eds.sections for entry in section.entries}
    for span in spans:
        if span.kind in ("definition", "paired entry") and span.renamed(number) in keywords:
            raise RenameRefused(f"{span.renamed(number)} exists already")
    if new_name.strip() in keywords:
        raise RenameRefused(f"{new_name.strip()} exists already")
    return [(span_of(span), span.renamed(number)) for span in spans]


def _refuse_sequential(analysis: Analysis, target: str, new_name: str) -> None:
    """Refuse to renumber an entry of a family numbered 1, 2, 3 ... without gaps (spec ``sequential``)."""
    from edsconv.lsp.hover import entry_spec

    entry = analysis.definitions.get(target)
    section = next((s.name for s in analysis.eds.sections if any(e is entry for e in s.entries)), None)
    spec = entry_spec(section, target) if section is not None and entry is not None else None
    if spec is not None and spec.sequential and new_name != target:
        raise RenameRefused(f"{spec.keyword}N numbers start at 1 and go up by one ({spec.clause}): {target} "
                            f"cannot become {new_name} without leaving a gap; move the entries instead")
