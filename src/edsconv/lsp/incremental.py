"""The analysis of a document's new text re-uses what did not change since its last text.

A keystroke changes one entry of thousands. The new text is read whole (the reader is the
fastest step), then every entry whose lines the edit did not touch is replaced by the very
same :class:`~edsconv.eds.syntax.Entry` object of the last analysis: its fields are made
already, and the model (:class:`~edsconv.model.memo.EntryMemo`) and the checks
(:class:`~edsconv.checks.CheckMemo`) find the records and diagnostics they made from it.

An entry is the same when the text from its first leading comment to the end of its last
line lies wholly before or wholly after the changed lines, and the new reading found an
entry of the same keyword and length at the same place. Positions stay right because only
edits that keep the number of lines are carried over: every other line keeps its number
and its text, and a re-used entry reports the line and column of its own text. An edit
that adds or removes a line (Enter, a deleted line, a paste) is analysed from scratch,
as is every :data:`FULL_READ_EVERY`-th edit, which lets go of the older texts that
re-used entries still point into.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from edsconv.checks import CheckMemo
from edsconv.eds.syntax import EdsFile, Entry
from edsconv.model.memo import EntryMemo

#: Incremental analyses between two from scratch: each keeps alive, at most, the text of one entry's
#: last edit (a re-used entry points into the text it was read from), so this bounds that memory
FULL_READ_EVERY = 16
#: Characters compared at a time when looking for where two texts start and stop differing
_CHUNK = 1 << 16
_LINE_BREAK = re.compile(r"\r\n|\r|\n")


#: Where an entry stands in the text of the analysis that holds it (its own offsets may be those of an
#: older text it was first read from): the entry, just after its ``;``, and where its first leading
#: comment starts (else where it starts)
Place = tuple[Entry, int, int]


@dataclass(slots=True)
class Carried:
    """What the analyses of one document hand from one text to the next."""

    text: str = ""
    line_count: int = -1
    #: every entry of ``text`` by its offset in ``text``
    places: dict[int, Place] = field(default_factory=dict)
    #: what was made from the entries (records, comments, the places naming other entries)
    memo: EntryMemo = field(default_factory=EntryMemo)
    #: what the checks said of the entries and records (blocks of them)
    checks: CheckMemo = field(default_factory=CheckMemo)
    #: incremental analyses since the last one from scratch
    steps: int = 0
    #: entries re-used by the last analysis, and entries read anew (for the tests and benchmarks)
    reused: int = 0
    read: int = 0


def reuse_entries(carried: Carried, text: str, line_count: int, eds: EdsFile) -> None:
    """Put the last analysis's entry objects into ``eds`` (just read from ``text``) wherever the edit
    left an entry as it was; then make ``carried`` describe ``text``.

    An entry wholly before the changed lines stands at the same offset in both texts, one wholly
    after them ``shift`` characters later. This loop runs once per entry of the file: keep it lean.
    """
    start = end = shift = 0
    reusing = carried.line_count == line_count and carried.steps < FULL_READ_EVERY
    if reusing:
        start, end, shift = changed_lines(carried.text, text)
    known = carried.places
    places: dict[int, Place] = {}
    reused = 0
    for section in (*([eds.preamble] if eds.preamble else []), *eds.sections):
        entries = section.entries
        for index, entry in enumerate(entries):
            offset, entry_end, lead = entry.offset, entry.end_offset, entry.lead_offset
            old_offset = offset if entry_end <= start else offset - shift if lead >= end else -1
            old = known.get(old_offset) if reusing and old_offset >= 0 else None
            if old is not None and old[0].keyword == entry.keyword and old[1] - old_offset == entry_end - offset \
                    and old_offset - old[2] == offset - lead:
                entries[index] = entry = old[0]
                reused += 1
            places[offset] = (entry, entry_end, lead)
    carried.steps = carried.steps + 1 if reusing else 0
    carried.text, carried.line_count, carried.places = text, line_count, places
    carried.reused, carried.read = reused, len(places) - reused


def changed_lines(old: str, new: str) -> tuple[int, int, int]:
    """``(start, end, shift)``: the lines of ``new`` an edit of ``old`` touched, from the start of the
    first to just after the line break of the last (or the end), and ``len(new) - len(old)``:
    what stands after ``end`` stood ``shift`` characters earlier in ``old``."""
    prefix = _common_prefix(old, new)
    suffix = _common_suffix(old, new, min(len(old), len(new)) - prefix)
    changed_end = max(len(new) - suffix, prefix)
    start = max(new.rfind("\n", 0, prefix), new.rfind("\r", 0, prefix)) + 1
    line_break = _LINE_BREAK.search(new, changed_end)
    return start, line_break.end() if line_break else len(new), len(new) - len(old)


def _common_prefix(a: str, b: str) -> int:
    """The length of the longest common prefix: whole chunks compared in C, then one chunk halved."""
    limit = min(len(a), len(b))
    low = 0
    while low + _CHUNK <= limit and a[low:low + _CHUNK] == b[low:low + _CHUNK]:
        low += _CHUNK
    high = min(low + _CHUNK, limit)
    while low < high:  # a[:low] == b[:low]; the first difference is before high, or high == limit
        middle = (low + high + 1) // 2
        if a[low:middle] == b[low:middle]:
            low = middle
        else:
            high = middle - 1
    return low


def _common_suffix(a: str, b: str, limit: int) -> int:
    """The length of the longest common suffix, at most ``limit`` (what the common prefix left)."""
    return _common_prefix(a[::-1][:limit], b[::-1][:limit]) if limit > 0 else 0
