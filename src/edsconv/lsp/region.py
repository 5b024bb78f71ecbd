"""An edit that changes where statements begin or end, read again from the statement before it until
the reading meets the last one again (:func:`reread_region`).

A keyword typed, a ``;``, ``"`` or ``$`` typed or deleted, an entry begun on a blank line: such an
edit changes which statements the reader finds, so :func:`edsconv.lsp.incremental.reread` cannot
take it, and reading the whole text again costs a third of a second on a 3 MB file. Here the
reader (:func:`edsconv.eds.reader.read_on`) resumes at the end of the line of an entry (or of the
section header) before the edit, in the section the edit is in, and reads until it ends a
statement, past the edit, where the last reading ended an entry of that section with its ``;``, or
comes to the next section's header: from there on the text, and so the reading, are the last ones.
The entries and unreadable text read between replace the last ones in the section, the reader's
findings about them too, and the nodes after them move with the lines the edit typed or deleted.
"""

from __future__ import annotations

import bisect
import dataclasses
from collections.abc import Iterator
from dataclasses import dataclass
from itertools import chain, islice

from edsconv.diagnostics import Diagnostic
from edsconv.eds.lark_reader import MAX_SYNTAX_ERRORS
from edsconv.eds.reader import read_on
from edsconv.eds.reader_rules import NAMING_A_LINE
from edsconv.eds.source import LineIndex
from edsconv.eds.statements import SyntaxBuilder
from edsconv.eds.syntax import EdsFile, Entry, Section
from edsconv.lsp.incremental import (
    REST_OF_LINE,
    Carried,
    Change,
    EntriesReplaced,
    LinesMoved,
    nodes_after,
    note_lines_moved,
    places_spliced,
    printable,
    with_section,
)

#: How far past the edit the reader reads before it gives up meeting the last reading (a brace or quote
#: left open can make it read the rest of the file, which reading it whole does as fast)
_READ_PAST_AT_MOST = 1 << 16
#: Entries walked back from the edit for one the reader may resume after (each must end with its ``;``
#: and alone on its last line): more means text so packed that reading it whole is as well
_RESUME_TRIES = 16


@dataclass(frozen=True, slots=True)
class _Resume:
    """Where the reader resumes: at ``at``, the line end (in the last text and the new one) of the entry or
    header before the ``first``-th entry of holder ``number`` (:meth:`EdsFile.holders`)."""

    number: int
    first: int
    at: int


@dataclass(frozen=True, slots=True)
class _Extent:
    """What the new reading replaced of the last one: the section's entries from the ``first``-th
    (:class:`_Resume`) to before the ``after``-th, ``last`` the index in ``Carried.starts`` of the last of
    them, what the reader found in the text from the resume point to ``end`` (an offset of the last text),
    and the lines from ``first_line`` on: those after it, which move when the edit typed line breaks."""

    end: int
    after: int
    last: int
    first_line: int


def reread_region(carried: Carried, change: Change) -> tuple[tuple[str, ...], EdsFile] | None:
    """The lines and syntax model of the editor's text after ``change``, made from those of the last text by
    reading again the statements of one section an edit of printable ASCII touched (see the module);
    None where that cannot be exact: the reading did not meet the last one (it met a header typed,
    the text's end, or nothing within :data:`_READ_PAST_AT_MOST`), a keyword of the entries read or
    replaced stands elsewhere in the section (which entry is the duplicate may change), a finding
    names a line that moved, or the syntax errors come near the reader's limit
    (:data:`~edsconv.eds.lark_reader.MAX_SYNTAX_ERRORS`)."""
    eds, index, start, old_end, new_end, moved = change.eds, change.index, change.start, change.old_end, \
        change.new_end, change.moved
    if not change.typed(printable) or moved and any(d.code in NAMING_A_LINE for d in eds.diagnostics):
        return None
    resume = _resume_point(carried, eds, index, start)
    if resume is None:
        return None
    shift, header = new_end - old_end, _next_header(eds, index, resume.number, old_end)
    new_index = change.new_index()
    read = _read_again(carried, eds, new_index, resume, shift, new_end, header)
    extent = _extent(carried, eds, index, resume, read, shift, header) if read is not None else None
    section = eds.holders()[resume.number]
    if extent is None or read is None or read.current_section is None \
            or _keywords_clash(section.entries, resume.first, extent.after, read.current_section.entries) \
            or len(eds.diagnostics) + len(read.eds.diagnostics) + 1 >= MAX_SYNTAX_ERRORS:
        return None
    entries = read.current_section.entries
    # from here to the moves, positions are the last text's: the moves renumber the lines of its index
    start_at = (index.position(resume.at)[0] + 1, 1)
    lines = change.new_lines(carried.lines)
    diagnostics = _diagnostics_spliced(eds.diagnostics, index.position(resume.at), index.position(extent.end),
                                       read.eds.diagnostics, extent.first_line, moved)
    replaced = _section_spliced(section, resume, extent, read.current_section, index)
    if moved:
        note_lines_moved(carried, nodes_after(carried, eds, extent.last + 1, extent.end, extent.first_line),
                         extent.first_line, moved)
    edited = with_section(eds, resume.number, replaced, diagnostics)
    places, first = carried.places, bisect.bisect_right(carried.starts, resume.at)
    carried.steps += 1
    carried.reused, carried.read = len(places) - (extent.after - resume.first), len(entries)
    carried.keep(change.raw, change.text, lines, edited, new_index, EntriesReplaced(
        section.name, tuple(section.entries[resume.first:extent.after]), tuple(entries), resume.first, start_at,
        extent.first_line - 1, LinesMoved(extent.first_line, moved) if moved else None),
        lambda: places_spliced(places, first, extent.last + 1,
                               [(entry, entry.end_offset, entry.lead_offset, resume.number, position)
                                for position, entry in enumerate(entries, resume.first)],
                               shift, resume.at, resume.number, len(entries) - (extent.after - resume.first)))
    return lines, edited


def _next_header(eds: EdsFile, index: LineIndex, number: int, old_end: int) -> int:
    """Where the header of the section after holder ``number`` starts in the last text, when the edit
    (which ends at ``old_end``) is before it; else -1."""
    holders = eds.holders()
    if number + 1 >= len(holders):
        return -1
    following = holders[number + 1]
    header = index.offset(following.line, following.column)
    return header if header >= old_end else -1


def _extent(carried: Carried, eds: EdsFile, index: LineIndex, resume: _Resume, read: SyntaxBuilder, shift: int,
            header: int) -> _Extent | None:
    """What ``read`` (the reader stopped: :func:`_read_again`) replaced of the last reading: up to the entry
    of the section whose end it met (whose last line's comments it then gives the last statement it
    read), or up to the next section's ``header`` (an offset of the last text). None when it gave up
    (:data:`_READ_PAST_AT_MOST`), a statement goes on after that entry on its line, or comments stand
    before that header (which of them lead it could change) or it does not start its line."""
    stop, text = read.last_end, read.text
    last = _entry_ending(carried, resume.number, stop - shift)
    if last >= 0:
        end, rest = stop - shift, REST_OF_LINE.match(text, stop)
        if rest is None:
            return None
        read.take_comments(stop, rest.end())
        read.attach_pending(rest.end(), None)
        return _Extent(end, carried.places[carried.starts[last]][4] + 1, last, index.position(end)[0] + 1)
    if header < 0 or text[stop:header + shift].strip() or text[header + shift - 1] != "\n" \
            or eds.holders()[resume.number + 1].leading_comments:
        return None  # it gave up, or comments stand before the header
    after = len(eds.holders()[resume.number].entries)
    last = bisect.bisect_right(carried.starts, resume.at) + after - resume.first - 1
    return _Extent(header, after, last, index.position(header)[0])


def _resume_point(carried: Carried, eds: EdsFile, index: LineIndex, start: int) -> _Resume | None:
    """Where the reader resumes for an edit at ``start`` of the last text: after the last entry before
    it, in the section the edit is in, that ends with its ``;`` alone on its line before the edit's
    line, else after the section's header line; None when the edit is in no section or on its header
    line, or no entry near enough qualifies."""
    sections = eds.sections
    holder = bisect.bisect_right(sections, start, key=lambda section: index.offset(section.line, section.column)) - 1
    if holder < 0:
        return None
    number = holder + (eds.preamble is not None)
    section, old, starts, places = sections[holder], carried.text, carried.starts, carried.places
    at = bisect.bisect_left(starts, start) - 1  # the last entry that starts before the edit
    for _ in range(_RESUME_TRIES):
        if at < 0 or places[starts[at]][3] != number:
            break
        _, end, _, _, position = places[starts[at]]
        resume = _Resume(number, position + 1, _line_end_before(old, end, start))
        if old[end - 1] == ";" and _nothing_between(carried, section, index, resume, at):
            return resume
        at -= 1
    else:
        return None
    resume = _Resume(number, 0, _line_end_before(old, index.offset(section.line, section.column), start))
    return resume if _nothing_between(carried, section, index, resume, at) else None


def _line_end_before(text: str, offset: int, start: int) -> int:
    """The end of the line of ``offset`` when it comes before ``start``, else -1."""
    line_end = text.find("\n", offset)
    return line_end if 0 <= line_end < start else -1


def _nothing_between(carried: Carried, section: Section, index: LineIndex, resume: _Resume, before: int) -> bool:
    """Whether ``resume`` is a line end after which the section's statements from its ``first``-th entry on
    start: that entry (``before + 1``-th of the file) and the unreadable text before it."""
    if resume.at < 0:
        return False
    starts = carried.starts
    if before + 1 < len(starts) and starts[before + 1] <= resume.at:
        return False
    return all(index.offset(item.line, item.column) > resume.at
               for position, item in section.unparsed if position == resume.first)


def _entry_ending(carried: Carried, number: int, end: int) -> int:
    """The index in ``carried.starts`` of the entry of holder ``number`` that ends with its ``;`` at ``end``
    of the last text; -1 when none does."""
    at = bisect.bisect_left(carried.starts, end) - 1  # the last entry that starts before end
    if at < 0:
        return -1
    _, entry_end, _, holder, _ = carried.places[carried.starts[at]]
    return at if entry_end == end and holder == number and carried.text[end - 1] == ";" else -1


def _read_again(carried: Carried, eds: EdsFile, new_index: LineIndex, resume: _Resume, shift: int,
                new_end: int, header: int) -> SyntaxBuilder | None:
    """The reader, resumed at ``resume`` of the new text and stopped where it meets the last reading past
    the edit (which ends at ``new_end`` of the new text, ``shift`` characters after its end in the last
    one), or before the next section's ``header`` (an offset of the last text, -1 for none); its section
    the statements it read. None when it met another header or the text's end first."""
    text = new_index.text
    builder = SyntaxBuilder(text, eds.path, new_index)
    builder.current_section = Section(name=eds.holders()[resume.number].name)
    builder.last_end = resume.at
    builder.stop_from, builder.give_up_at = new_end, new_end + _READ_PAST_AT_MOST
    builder.stops = lambda position: position > builder.give_up_at \
        or _entry_ending(carried, resume.number, position - shift) >= 0
    builder.header_stop = header + shift if header >= 0 else -1
    stop = read_on(builder, resume.at)
    read = builder.eds
    return None if stop is None or read.sections or read.preamble is not None or builder.pending else builder


def _keywords_clash(entries: list[Entry], first: int, after: int, read: list[Entry]) -> bool:
    """Whether a keyword of the entries replaced (``entries[first:after]``) or of those ``read`` in their
    place stands elsewhere in the section: which of two is the duplicate could change."""
    elsewhere = {entry.keyword for entry in chain(islice(entries, first), islice(entries, after, None))}
    return any(entry.keyword in elsewhere for entry in chain(islice(entries, first, after), read))


def _diagnostics_spliced(diagnostics: list[Diagnostic], low: tuple[int, int], high: tuple[int, int],
                         found_again: list[Diagnostic], first_line: int, moved: int) -> list[Diagnostic]:
    """The reader's findings with those between ``low`` and ``high`` (the statements read again) replaced by
    ``found_again``, and those after them ``moved`` lines later from ``first_line`` on."""
    after: Iterator[Diagnostic] = (d for d in diagnostics if (d.line, d.column) >= high)
    if moved:
        after = (d.moved(first_line, moved) for d in after)
    return [*(d for d in diagnostics if (d.line, d.column) < low), *found_again, *after]


def _section_spliced(section: Section, resume: _Resume, extent: _Extent, read: Section, index: LineIndex) -> Section:
    """``section`` with its entries from the ``first``-th to before the ``after``-th, and the unreadable text
    among them (between the resume point and the extent's end), replaced by those ``read``."""
    first, after = resume.first, extent.after
    moved = len(read.entries) - (after - first)
    at = [(index.offset(item.line, item.column), position, item) for position, item in section.unparsed]
    unparsed = [*((position, item) for offset, position, item in at if offset < resume.at),
                *((first + position, item) for position, item in read.unparsed),
                *((position + moved, item) for offset, position, item in at if offset >= extent.end)]
    entries = [*islice(section.entries, first), *read.entries, *islice(section.entries, after, None)]
    return dataclasses.replace(section, entries=entries, unparsed=unparsed)
