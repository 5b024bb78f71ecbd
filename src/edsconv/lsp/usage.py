"""Where an entry is used: every use of the entry under the cursor (document highlight) and the
number of references above each definition (code lens), over :mod:`edsconv.model.references`."""

from __future__ import annotations

from collections import Counter

from lsprotocol import types

from edsconv.lsp.analysis import Analysis
from edsconv.lsp.navigation import target_at
from edsconv.lsp.positions import Positions
from edsconv.model.references import references_to

#: A code lens with this command is a label: clients show it and run nothing (VS Code's convention).
LABEL_ONLY = ""


def highlights(analysis: Analysis, positions: Positions, line: int, column: int) -> list[types.DocumentHighlight]:
    """Every span naming the entry at ``line``:``column``; its definition is the write."""
    found = target_at(analysis, line, column)
    if found is None:
        return []
    return [types.DocumentHighlight(
        positions.range(o.line, o.column, o.line, o.end_column),
        types.DocumentHighlightKind.Write if o.kind == "definition" else types.DocumentHighlightKind.Read)
        for o in references_to(found.target, analysis.spans)]


def reference_lenses(analysis: Analysis, positions: Positions) -> list[types.CodeLens]:
    """A lens above each defined entry: how many places name it (definition and paired entries not counted)."""
    uses = Counter(o.target for o in analysis.spans if o.kind not in ("definition", "paired entry"))
    lenses = []
    for occurrence in analysis.spans:
        if occurrence.kind != "definition":
            continue
        count = uses[occurrence.target]
        title = f"{count} reference{'' if count == 1 else 's'}" if count else "no references"
        lenses.append(types.CodeLens(
            range=positions.range(occurrence.line, occurrence.column, occurrence.line, occurrence.end_column),
            command=types.Command(title=title, command=LABEL_ONLY)))
    return sorted(lenses, key=lambda lens: (lens.range.start.line, lens.range.start.character))
