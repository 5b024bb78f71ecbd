"""Folding ranges: each section from its header to its last line, each entry written over
several lines, and each block of comment lines."""

from __future__ import annotations

from collections.abc import Iterator

from lsprotocol import types

from edsconv.lsp.analysis import Analysis


def folding_ranges(analysis: Analysis) -> list[types.FoldingRange]:
    """The ranges in 0-based lines, as LSP counts them (folding works on whole lines)."""
    found = [*_sections(analysis), *_entries(analysis), *_comment_blocks(analysis.lines)]
    return [types.FoldingRange(start_line=first - 1, end_line=last - 1, kind=kind) for first, last, kind in found
            if last > first]


def _sections(analysis: Analysis) -> Iterator[tuple[int, int, types.FoldingRangeKind | None]]:
    """From the header to the end of the last entry (comments after it lead the next section)."""
    for section in analysis.eds.sections:
        yield section.line, max([section.line, *(e.end_line for e in section.entries)]), types.FoldingRangeKind.Region


def _entries(analysis: Analysis) -> Iterator[tuple[int, int, types.FoldingRangeKind | None]]:
    for section in analysis.eds.sections:
        for entry in section.entries:
            yield entry.line, entry.end_line, None


def _comment_blocks(lines: tuple[str, ...]) -> Iterator[tuple[int, int, types.FoldingRangeKind | None]]:
    """Runs of two or more lines holding nothing but a comment."""
    start = None
    for number, line in enumerate(lines, 1):
        if line.lstrip().startswith("$"):
            start = number if start is None else start
            continue
        if start is not None:
            yield start, number - 1, types.FoldingRangeKind.Comment
            start = None
    if start is not None:
        yield start, len(lines), types.FoldingRangeKind.Comment
