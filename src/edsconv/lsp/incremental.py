"""The analysis of a document's new text re-uses what did not change since its last text.

A keystroke changes one entry of thousands. When it typed or deleted characters inside the
fields of one entry of an ASCII text (printable ASCII and line ends; the reader's offsets count
each line end as one character) and the reader reads the new entry as a simple statement
ending where the old one ended, only that entry is read again (:func:`reread`): the new
syntax model is the last one with that entry replaced, and the lines and line index are the
last ones with its lines replaced (the nodes after it moved, when lines came or went). When
it typed or deleted whole blank lines outside every entry (Enter at the end of a line, a blank
line deleted), nothing is read: the last syntax model is the new one, every node after the edit
moved to its new line (:func:`respaced`). Any other edit reads the new text whole, then every
entry whose lines the edit did not touch is replaced by the very same
:class:`~edsconv.eds.syntax.Entry` object of the last analysis (:func:`reuse_entries`). Either
way the model (:class:`~edsconv.model.memo.EntryMemo`) and the checks
(:class:`~edsconv.checks.CheckMemo`) find the records and diagnostics they made from the entries
they saw before.

An entry is the same when the text from its first leading comment to the end of its last
line lies wholly before or wholly after the changed lines, and the new reading found an
entry of the same keyword and length at the same place. Positions stay right: a node reports
the line and column of the text it was read from, through that text's line index. An edit
that adds or removes lines moves the nodes after it: the index of each older text they were
read from then numbers its lines from the first of them on that many more or fewer
(:meth:`~edsconv.eds.source.LineIndex.lines_moved`), and the records, spans and diagnostics the
memos hold move with them before they are next read (:meth:`Carried.settle`). Every
:data:`FULL_READ_EVERY`-th edit is analysed from scratch, which lets go of the older texts that
re-used entries still point into.

The analyses of one document run one at a time (:class:`edsconv.lsp.analysis.Analyses`): moving
an older text's lines changes what the analyses of the texts before this one answer, and no
request reads those any more.
"""

from __future__ import annotations

import bisect
import dataclasses
import operator
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from itertools import compress, islice
from typing import TYPE_CHECKING

from edsconv.checks import CheckMemo
from edsconv.diagnostics import Diagnostic
from edsconv.eds.reader import read_statement_by_statement, simple_entry_at
from edsconv.eds.reader_rules import DUPLICATE_ENTRY, ENTRY_OUTSIDE_SECTION, NAMING_A_LINE
from edsconv.eds.runs import comments_in
from edsconv.eds.source import LineIndex, as_read, newline_of, split_lines
from edsconv.eds.syntax import EdsFile, Entry, Section
from edsconv.model.memo import EntryMemo

if TYPE_CHECKING:
    from edsconv.lsp.analysis import Analysis

#: Incremental analyses between two from scratch: each keeps alive, at most, the text of one entry's
#: last edit (a re-used entry points into the text it was read from), so this bounds that memory
FULL_READ_EVERY = 16
#: Characters compared at a time when looking for where two texts start and stop differing
_CHUNK = 1 << 16
_LINE_BREAK = re.compile(r"\r\n|\r|\n")
#: What an edit re-read as one entry may have typed or deleted: characters that do not change how the
#: text is decoded
_PRINTABLE = re.compile(r"[\x20-\x7e\t\r\n]*")
#: The rest of an entry's last line when no other statement stands on it: blanks, perhaps a comment
REST_OF_LINE = re.compile(r"[ \t\f\v\x1a]*+(?:\$[^\n]*+)?(?:\n|\Z)")
#: Whole lines of blanks, as an edit between statements types or deletes them (:func:`respaced`)
_BLANK_LINES = re.compile(r"(?:[ \t]*(?:\r\n|\r|\n))*")
#: A place's entry and where its first leading comment starts (:data:`Place`), and a node's line index
_ENTRY_OF, _LEAD_OF, _SOURCE_OF = operator.itemgetter(0), operator.itemgetter(2), operator.attrgetter("source")
#: Diagnostics the reader gives an entry at its start whatever its fields say
_ABOUT_THE_KEYWORD = frozenset({DUPLICATE_ENTRY.code, ENTRY_OUTSIDE_SECTION.code})


@dataclass(frozen=True, slots=True)
class LinesMoved:
    """Lines typed or deleted (:func:`respaced`, :func:`reread`): the lines of the last text from
    ``first_line`` on moved ``moved`` lines (fewer, when negative)."""

    first_line: int
    moved: int


@dataclass(frozen=True, slots=True)
class EntriesReplaced:
    """An edit that changed where statements begin or end (:func:`edsconv.lsp.region.reread_region`): the
    entries ``old`` of section ``section`` from its ``first``-th on, read again as ``new`` (any number of
    each, keywords and unreadable text as they came), the lines they stood on (from ``start``, a line and
    column, to the end of ``last_line``: no other statement's), and the lines after them moved when the
    edit typed or deleted line breaks."""

    section: str
    old: tuple[Entry, ...]
    new: tuple[Entry, ...]
    first: int
    start: tuple[int, int]
    last_line: int
    lines: LinesMoved | None = None


@dataclass(frozen=True, slots=True)
class EntryReplaced(EntriesReplaced):
    """An edit inside one entry's fields (:func:`reread`): that entry read again, as one of the same keyword."""


#: What the last analysis changed of the syntax model before it, when it made its own of that one
Edit = EntriesReplaced | LinesMoved


@dataclass(frozen=True, slots=True)
class Change:
    """The edit that made the editor's ``raw`` of the last text ``old_raw`` (:func:`change_since`):
    ``raw[raw_start:raw_new_end]`` in place of ``old_raw[raw_start:raw_old_end]``; the same edit of the
    reader's texts, which count each CR LF as one character: ``text[start:new_end]`` in place of
    ``[start, old_end)``; the lines it added (removed, when negative); the last syntax model and line
    index. Made once per analysis for the splices that may take the edit (:func:`reread`,
    :func:`respaced`, :func:`edsconv.lsp.region.reread_region`)."""

    eds: EdsFile
    index: LineIndex
    old_raw: str
    raw: str
    raw_start: int
    raw_old_end: int
    raw_new_end: int
    text: str
    start: int
    old_end: int
    new_end: int
    moved: int

    def typed(self, allowed: Callable[[str, int, int], bool]) -> bool:
        """Whether what the edit took away and what it typed are both ``allowed``."""
        return allowed(self.old_raw, self.raw_start, self.raw_old_end) and allowed(self.raw, self.raw_start,
                                                                                   self.raw_new_end)

    def new_index(self) -> LineIndex:
        """The line index of ``text``; made before the nodes after the edit move (they use ``index``)."""
        return self.index.edited(self.text, self.start, self.old_end, self.new_end)

    def new_lines(self, lines: tuple[str, ...]) -> tuple[str, ...]:
        """``lines``, the last text's as the editor counts them, made those of ``raw``; before the move."""
        return lines_edited(lines, self.index.position(self.start)[0] - 1, self.old_raw, self.raw, self.raw_start,
                            self.raw_old_end)


#: Where an entry stands in the text of the analysis that holds it (its own offsets may be those of an
#: older text it was first read from): the entry, just after its ``;``, where its first leading
#: comment starts (else where it starts), its section's index in :meth:`EdsFile.holders` and its
#: index among the section's entries
Place = tuple[Entry, int, int, int, int]


@dataclass(slots=True)
class Carried:
    """What the analyses of one document hand from one text to the next."""

    #: the text as the editor holds it, and as the reader made it (:func:`edsconv.eds.source.as_read`)
    raw: str = ""
    text: str = ""
    #: every entry of ``text`` by its offset in ``text``, in file order
    places: dict[int, Place] = field(default_factory=dict)
    #: the offsets of ``places``, in file order
    starts: list[int] = field(default_factory=list)
    #: the syntax model of ``text``, and its lines and line index
    eds: EdsFile | None = None
    lines: tuple[str, ...] = ()
    index: LineIndex | None = None
    #: what was made from the entries (records, comments, the places naming other entries)
    memo: EntryMemo = field(default_factory=EntryMemo)
    #: what the checks said of the entries and records (blocks of them)
    checks: CheckMemo = field(default_factory=CheckMemo)
    #: incremental analyses since the last one from scratch
    steps: int = 0
    #: entries re-used by the last analysis, and entries read anew (for the tests and benchmarks)
    reused: int = 0
    read: int = 0
    #: what the last analysis changed of the syntax model before it, when it made its own of that one
    #: (None: it read its text whole)
    edit: Edit | None = None
    #: the last analysis that ran to its end (:func:`edsconv.lsp.analysis.analyse`)
    last: Analysis | None = None
    #: the line moves the memos have yet to follow, in order (:meth:`settle`)
    pending: list[LinesMoved] = field(default_factory=list)
    #: what makes ``places`` (and ``starts``) those of ``text`` after a splice, until :meth:`settle` runs it
    places_to_come: Callable[[], dict[int, Place]] | None = None

    def settle(self) -> None:
        """Make ``places`` those of ``text``, and what the memos hold follow the lines the edits since they
        were last read moved: done after hover has had its answer, just before the memos are read
        (:func:`edsconv.lsp.analysis.analyse`), and before the next edit is looked at, should a newer
        text have stopped that analysis first (:func:`change_since`, :func:`reuse_entries`)."""
        if self.places_to_come is not None:
            self.places = self.places_to_come()
            self.starts, self.places_to_come = list(self.places), None
        for move in self.pending:
            self.memo.lines_moved(move.first_line, move.moved)
            self.checks.lines_moved(move.first_line, move.moved)
        self.pending.clear()

    @property
    def splice(self) -> str:
        """How the last analysis made its syntax model: "reread", "region", "respaced", or "" (read whole)."""
        return _SPLICES.get(type(self.edit), "")

    def keep(self, raw: str, text: str, lines: tuple[str, ...], eds: EdsFile, index: LineIndex | None,
             edit: Edit | None, places: Callable[[], dict[int, Place]]) -> None:
        """Describe ``raw`` (read as ``text``) from now on; ``places()`` makes the places of its entries
        (:meth:`settle`: rebuilding them for a file of 40,000 entries takes 10 ms, which hover need
        not wait for)."""
        self.raw, self.text, self.lines = raw, text, lines
        self.eds, self.index, self.edit, self.places_to_come = eds, index, edit, places


_SPLICES = {EntryReplaced: "reread", EntriesReplaced: "region", LinesMoved: "respaced"}


def reuse_entries(carried: Carried, raw: str, text: str, lines: tuple[str, ...], eds: EdsFile) -> None:
    """Put the last analysis's entry objects into ``eds`` (just read whole from the editor's ``raw``,
    which the reader made ``text``: :func:`edsconv.eds.source.as_read`; ``lines`` as the editor counts
    them) wherever the edit left an entry as it was; then make ``carried`` describe ``raw``.

    An entry wholly before the changed lines stands at the same offset in both texts, one wholly
    after them ``shift`` characters later, and ``moved`` lines later (:func:`note_lines_moved`). This loop
    runs once per entry of the file: keep it lean.
    """
    carried.settle()
    start = end = shift = moved = 0
    reusing = carried.eds is not None and carried.steps < FULL_READ_EVERY
    if reusing:
        start, end, shift, moved = changed_lines(carried.text, text)
    known = carried.places
    places: dict[int, Place] = {}
    #: where the first node after the edit read from each older text stands in it (by its line index),
    #: when lines moved
    firsts: dict[LineIndex, int] = {}
    reused = 0
    for number, section in enumerate(eds.holders()):
        entries = section.entries
        for index, entry in enumerate(entries):
            offset, entry_end, lead = entry.offset, entry.end_offset, entry.lead_offset
            old_offset = offset if entry_end <= start else offset - shift if lead >= end else -1
            old = known.get(old_offset) if reusing and old_offset >= 0 else None
            if old is not None and old[0].keyword == entry.keyword and old[1] - old_offset == entry_end - offset \
                    and old_offset - old[2] == offset - lead:
                entries[index] = entry = old[0]
                reused += 1
                if moved and lead >= end:
                    if lead == offset:
                        firsts.setdefault(entry.source, entry.offset)  # type: ignore[arg-type]  # read entries have one
                    else:
                        _first_after(firsts, entry)
            places[offset] = (entry, entry_end, lead, number, index)
    if firsts:
        note_lines_moved(carried, firsts, carried.index.position(end - shift)[0], moved)  # type: ignore[union-attr]
    carried.steps = carried.steps + 1 if reusing else 0
    carried.reused, carried.read = reused, len(places) - reused
    carried.keep(raw, text, lines, eds, index_of(eds), None, lambda: places)


def _first_after(firsts: dict[LineIndex, int], entry: Entry) -> None:
    """Note where ``entry``, the next re-used entry after an edit, with leading comments, starts in the
    texts it was read from (its comments may come from an older text than the entry: :func:`reread`),
    unless an earlier node of that text is noted. Its first comment's offset is right for both: it
    stands before the edit that read the entry again, where the two texts are the same."""
    lead = entry.lead_offset
    firsts.setdefault(entry.source, lead)  # type: ignore[arg-type]  # read entries have one
    firsts.setdefault(entry.leading_comments[0].source, lead)  # type: ignore[arg-type]


def note_lines_moved(carried: Carried, firsts: dict[LineIndex, int], first_line: int, moved: int) -> None:
    """An edit added ``moved`` lines (removed, when negative) before line ``first_line`` of the last
    text: the nodes after it, read from older texts, say their new lines, and what the memos made of
    them will (:meth:`Carried.settle`).

    The nodes before and after the edit that were read from one text keep their order in it, so
    numbering the lines of that text from the first one after the edit on ``moved`` more (``firsts``:
    where that node stands) moves exactly those after it; the line starts removed when ``moved`` is
    negative lie between the two groups, on lines the edit removed (:meth:`LineIndex.lines_moved`)."""
    for index, offset in firsts.items():
        index.lines_moved(offset, moved)
    carried.pending.append(LinesMoved(first_line, moved))


def reread(carried: Carried, change: Change) -> tuple[tuple[str, ...], EdsFile] | None:
    """The lines and syntax model of the editor's text after ``change``, made from those of the last text by
    reading again the one entry the edit changed; None when the edit did more than change that entry's
    fields (see the module).

    Exact because the reader, coming to that entry's start in the text it makes of the editor's, reads it as
    it does here, and then finds the text after it as it was; its other entries keep their places, and
    the nodes after it their lines, or move with the lines the edit typed or deleted (:func:`note_lines_moved`;
    not where a finding's message names a line). The last text was ASCII and the edit typed nothing
    but printable ASCII and line ends of the file's kind, no CR LF across its edges, so the reader's
    text (:func:`edsconv.eds.source.as_read`) is its last one with the same edit, each CR LF counted
    as one character.
    """
    if not change.typed(printable):
        return None
    eds, index, text, start, new_end, moved = change.eds, change.index, change.text, change.start, change.new_end, \
        change.moved
    at = bisect.bisect_right(carried.starts, start) - 1
    if at < 0:
        return None
    offset = carried.starts[at]
    entry, end, lead, number, position = carried.places[offset]
    shift = len(text) - len(carried.text)
    read = simple_entry_at(text, offset)
    if read is None:
        return None
    keyword, body, entry_end = read
    rest = REST_OF_LINE.match(text, entry_end)
    if keyword != entry.keyword or start < body or new_end > entry_end or entry_end != end + shift or rest is None \
            or not _quiet(eds.diagnostics, entry) or moved and any(d.code in NAMING_A_LINE for d in eds.diagnostics):
        return None
    lines, new_index = change.new_lines(carried.lines), change.new_index()
    spliced = Entry.unread(keyword, offset, entry_end, new_index)
    if entry.lead_offset != entry.offset:
        spliced.leading_comments = list(entry.leading_comments)
    for comment in comments_in(text, entry_end, rest.end(), new_index):
        spliced.attach_trailing_comment(comment)
    edited = _with_entry(eds, number, position, spliced)
    start_at, last_line = (entry.line, entry.column), index.position(end)[0]  # before the lines move
    lines_moved = _after_entry_moved(carried, eds, edited, at, last_line + 1, moved) if moved else None
    places = carried.places
    carried.steps += 1
    carried.reused, carried.read = len(places) - 1, 1
    section = edited.holders()[number].name
    carried.keep(change.raw, text, lines, edited, new_index, EntryReplaced(section, (entry,), (spliced,), position,
                                                                           start_at, last_line, lines_moved),
                 lambda: places_spliced(places, at, at + 1, [(spliced, entry_end, lead, number, position)], shift,
                                        offset))
    return lines, edited


def change_since(carried: Carried, raw: str) -> Change | None:
    """The edit that made the editor's ``raw`` of the last text; None unless the last model may be spliced:
    the last text was ASCII (one character a byte, no byte order mark) and the edit typed ASCII, the last
    full reading is recent enough (:data:`FULL_READ_EVERY`), ``raw`` differs, the file's first line end
    stays, and the reader reads ``raw`` statement by statement."""
    carried.settle()
    eds, index, old_raw = carried.eds, carried.index, carried.raw
    if eds is None or index is None or carried.steps >= FULL_READ_EVERY or eds.encoding != "ascii" \
            or raw == old_raw or newline_of(raw) != eds.newline:
        return None
    raw_start, raw_old_end, raw_new_end = changed_span(old_raw, raw)
    if not raw[raw_start:raw_new_end].isascii():
        return None  # the text is read again whole: it decodes differently
    text, start, old_end, new_end, moved = _as_read(carried, eds.newline, raw, raw_start, raw_old_end, raw_new_end)
    if not read_statement_by_statement(raw, text):
        return None
    return Change(eds, index, old_raw, raw, raw_start, raw_old_end, raw_new_end, text, start, old_end, new_end, moved)


def _after_entry_moved(carried: Carried, eds: EdsFile, edited: EdsFile, at: int, first_line: int,
                       moved: int) -> LinesMoved:
    """The lines of the last text from ``first_line`` on, those after its ``at``-th entry, moved ``moved``
    lines: the nodes of ``eds`` (its syntax model) there say so, and so do the findings of ``edited``,
    the new model."""
    end = carried.places[carried.starts[at]][1]
    note_lines_moved(carried, nodes_after(carried, eds, at + 1, end, first_line), first_line, moved)
    edited.diagnostics = [d.moved(first_line, moved) for d in edited.diagnostics]
    return LinesMoved(first_line, moved)


def _as_read(carried: Carried, newline: str, raw: str, raw_start: int, raw_old_end: int,
             raw_new_end: int) -> tuple[str, int, int, int, int]:
    """``(text, start, old_end, new_end, moved)``: the reader's text of ``raw``, where the edit that made
    ``raw[raw_start:raw_new_end]`` of the last text's ``[raw_start, raw_old_end)`` stands in it and in the
    last reader's text, and the lines it added (removed, when negative). The reader's offsets count
    each CR LF as one character (``newline``: the file's first line end; no CR LF across the edges)."""
    old = carried.text
    text, start, old_end, new_end = raw, raw_start, raw_old_end, raw_new_end
    if newline != "\n":
        start -= carried.raw.count("\r\n", 0, raw_start)
        typed = as_read(raw[raw_start:raw_new_end])
        old_end, new_end = start + len(as_read(carried.raw[raw_start:raw_old_end])), start + len(typed)
        text = old[:start] + typed + old[old_end:]
    return text, start, old_end, new_end, text.count("\n", start, new_end) - old.count("\n", start, old_end)


def printable(text: str, start: int, end: int) -> bool:
    """Whether ``text[start:end]`` is printable ASCII and line ends, no CR LF standing across its edges."""
    return _PRINTABLE.fullmatch(text, start, end) is not None \
        and not (start > 0 and text[start - 1] == "\r" and text.startswith("\n", start)) \
        and not (end > start and text[end - 1] == "\r" and text.startswith("\n", end))


def lines_edited(lines: tuple[str, ...], first: int, old_raw: str, raw: str, start: int,
                  old_end: int) -> tuple[str, ...]:
    """``lines`` (of ``old_raw``) made those of ``raw``, where ``old_raw[start:old_end]`` changed and the
    rest stayed; ``first``: the 0-based line of ``start``."""
    last = first + len(_LINE_BREAK.findall(old_raw, start, old_end))
    line_start = max(raw.rfind("\n", 0, start), raw.rfind("\r", 0, start)) + 1
    region_end = line_start + sum(map(len, lines[first:last + 1])) + len(raw) - len(old_raw)
    return lines[:first] + tuple(split_lines(raw[line_start:region_end])) + lines[last + 1:]


def respaced(carried: Carried, change: Change) -> tuple[tuple[str, ...], EdsFile] | None:
    """The lines and syntax model of the editor's text after ``change`` when it typed or deleted nothing but
    whole blank lines, outside every entry (Enter at the end of a line, a blank line deleted): the last
    syntax model with every node after the edit on its new line (:func:`note_lines_moved`); None for any
    other edit, or in a file with text the reader could not parse (whose extent blank lines may change)
    or with a finding whose message names a line.

    Exact because the reader makes nothing of blank lines between statements: they end no statement,
    and a comment keeps its owner (the statement whose last line it stands on, else the next one).
    The line ends typed must be those of the file (the reader keeps its first one).
    """
    eds, index, start, moved = change.eds, change.index, change.start, change.moved
    if not change.typed(_blank_lines) or any(section.unparsed for section in eds.holders()) \
            or any(d.code in NAMING_A_LINE for d in eds.diagnostics):
        return None
    at = bisect.bisect_left(carried.starts, start)  # the first entry after the edit
    if at > 0 and carried.places[carried.starts[at - 1]][1] > start:
        return None  # inside an entry
    first_line, first_moved_line = index.position(start)[0], index.position(change.old_end)[0]
    firsts = nodes_after(carried, eds, at, start, first_line)
    lines, new_index = change.new_lines(carried.lines), change.new_index()
    if moved:
        note_lines_moved(carried, firsts, first_moved_line, moved)
    moved_eds = dataclasses.replace(eds, diagnostics=[d.moved(first_moved_line, moved) for d in eds.diagnostics])
    places = carried.places
    carried.steps += 1
    carried.reused, carried.read = len(places), 0
    carried.keep(change.raw, change.text, lines, moved_eds, new_index, LinesMoved(first_moved_line, moved),
                 lambda: places_spliced(places, at, at, [], change.new_end - change.old_end, start))
    return lines, moved_eds


def _blank_lines(text: str, start: int, end: int) -> bool:
    """Whether ``text[start:end]`` is whole blank lines (or nothing), between two line starts."""
    return _starts_line(text, start) and _starts_line(text, end) \
        and _BLANK_LINES.fullmatch(text, start, end) is not None


def nodes_after(carried: Carried, eds: EdsFile, at: int, start: int, first_line: int) -> dict[LineIndex, int]:
    """Where the first node at or after offset ``start`` of the last text (line ``first_line``, the
    ``at``-th entry and the entries after it, headers, comments, unreadable statements) stands in the
    text it was read from, by that text's index."""
    firsts = _entries_after(carried, at, start)
    for section in eds.holders():
        unparsed = [node for _, item in section.unparsed for node in (*item.leading_comments, item, *item.comments)]
        for node in (*section.leading_comments, section, *section.comments, *unparsed):
            if node.source is not None and node.line >= first_line:
                firsts[node.source] = min(firsts.get(node.source, node.offset), node.offset)
    for comment in eds.trailing_comments:
        if comment.source is not None and comment.line >= first_line:
            firsts[comment.source] = min(firsts.get(comment.source, comment.offset), comment.offset)
    return firsts


def _entries_after(carried: Carried, at: int, start: int) -> dict[LineIndex, int]:
    """:func:`nodes_after` of the entries from the ``at``-th on. They were read from few texts (one per
    edit since the last full reading), so the first entry of each text is found in C (3 ms for 40,000
    entries, where a loop took 10), and the entries whose leading comments stand after ``start`` (which
    may come from another text: :func:`_first_after`) one by one: (index, offset) by text."""
    places = carried.places
    values = list(islice(places.values(), at, None))
    entries: list[Entry] = list(map(_ENTRY_OF, values))
    sources: list[LineIndex] = list(map(_SOURCE_OF, entries))
    found = {source: (index, entries[index].offset)
             for source, index in ((source, sources.index(source)) for source in dict.fromkeys(sources))}
    leads = list(map(_LEAD_OF, values))
    for index in compress(range(len(values)), map(operator.ne, leads, islice(places, at, None))):
        if leads[index] < start:
            continue  # its comments stand before the edit: the entry is the first node
        entry = entries[index]
        for source in (entry.source, entry.leading_comments[0].source):
            known = found.get(source)  # type: ignore[arg-type]  # read nodes have one
            if known is None or known[0] >= index:
                found[source] = (index, leads[index])  # type: ignore[index]
    return {source: offset for source, (_, offset) in found.items()}


def _quiet(diagnostics: list[Diagnostic], entry: Entry) -> bool:
    """Whether the reader said nothing of ``entry``'s fields and of the rest of its last line."""
    first = (entry.line, entry.column)
    last_line = entry.source.position(entry.end_offset)[0] if entry.source else 0
    return not any(first <= (d.line, d.column) and d.line <= last_line
                   and not ((d.line, d.column) == first and d.code in _ABOUT_THE_KEYWORD) for d in diagnostics)


def places_spliced(places: dict[int, Place], first: int, after: int, inserted: list[Place], shift: int, edit: int,
                   section: int = -1, moved: int = 0) -> dict[int, Place]:
    """``places`` with the ``first``-th to before the ``after``-th replaced by ``inserted``, and those after
    them ``shift`` characters later (their leading comments too, where they stand after offset ``edit``;
    the others stand before the edit), ``moved`` places later in holder ``section``."""
    items = iter(places.items())
    spliced = dict(islice(items, first))
    spliced.update((place[0].offset, place) for place in inserted)
    rest = islice(items, after - first, None)
    if not shift and not moved:
        spliced.update(rest)
        return spliced
    for offset, (entry, end, lead, number, position) in rest:
        spliced[offset + shift] = (entry, end + shift, lead + shift if lead >= edit else lead, number,
                                   position + moved if number == section else position)
    return spliced


def _with_entry(eds: EdsFile, number: int, position: int, entry: Entry) -> EdsFile:
    """A copy of ``eds`` with ``entry`` in place of the ``position``-th entry of section ``number``."""
    section = eds.holders()[number]
    entries = list(section.entries)
    entries[position] = entry
    return with_section(eds, number, dataclasses.replace(section, entries=entries), list(eds.diagnostics))


def with_section(eds: EdsFile, number: int, section: Section, diagnostics: list[Diagnostic]) -> EdsFile:
    """A copy of ``eds`` with ``section`` in place of its ``number``-th (:meth:`EdsFile.holders`) and the
    reader's ``diagnostics``; ``eds`` is left as it was (an earlier analysis still answers from it)."""
    if number == 0 and eds.preamble is not None:
        return dataclasses.replace(eds, preamble=section, diagnostics=diagnostics)
    sections = list(eds.sections)
    sections[number - (eds.preamble is not None)] = section
    return dataclasses.replace(eds, sections=sections, diagnostics=diagnostics)


def index_of(eds: EdsFile) -> LineIndex | None:
    """The line index of the text ``eds`` was just read from whole (its sections share it)."""
    holders = eds.holders()
    return holders[0].source if holders else None


def changed_span(old: str, new: str) -> tuple[int, int, int]:
    """``(start, old_end, new_end)``: ``old[start:old_end]`` became ``new[start:new_end]``, the rest is alike."""
    start = _common_prefix(old, new)
    suffix = _common_suffix(old, new, min(len(old), len(new)) - start)
    return start, len(old) - suffix, len(new) - suffix


def changed_lines(old: str, new: str) -> tuple[int, int, int, int]:
    """``(start, end, shift, moved)``: the lines of ``new`` an edit of ``old`` touched, from the start of the
    first to just after the line break of the last (or the end; where the changed text ends at a line
    start of both texts, as when whole lines are typed or deleted, that line start), ``len(new) -
    len(old)`` and the lines the edit added (removed, when negative): what stands after ``end`` stood
    ``shift`` characters and ``moved`` lines earlier in ``old``."""
    prefix, old_end, changed_end = changed_span(old, new)
    start = max(new.rfind("\n", 0, prefix), new.rfind("\r", 0, prefix)) + 1
    moved = _line_breaks(new, prefix, changed_end) - _line_breaks(old, prefix, old_end)
    if _starts_line(new, changed_end) and _starts_line(old, old_end):
        return start, changed_end, len(new) - len(old), moved
    line_break = _LINE_BREAK.search(new, changed_end)
    return start, line_break.end() if line_break else len(new), len(new) - len(old), moved


def _starts_line(text: str, offset: int) -> bool:
    """Whether a line starts at ``offset`` (a CR followed by LF ends no line)."""
    if offset == 0:
        return True
    before = text[offset - 1]
    return before == "\n" or (before == "\r" and text[offset:offset + 1] != "\n")


def _line_breaks(text: str, start: int, end: int) -> int:
    """The line breaks in ``text[start:end]`` and the CR before or LF after it (the same in both texts
    compared), so that a CR LF across either edge counts once."""
    start -= start > 0 and text[start - 1] == "\r"
    end += end < len(text) and text[end] == "\n"
    return len(_LINE_BREAK.findall(text, start, end))


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
    """The length of the longest common suffix, at most ``limit`` (what the common prefix left): whole
    chunks from the ends compared in C, then one chunk halved (slices, never reversed copies of the texts)."""
    end_a, end_b = len(a), len(b)
    low = 0
    while low + _CHUNK <= limit and a[end_a - low - _CHUNK:end_a - low] == b[end_b - low - _CHUNK:end_b - low]:
        low += _CHUNK
    high = min(low + _CHUNK, limit)
    while low < high:  # the last ``low`` characters agree; the first difference from the end is within ``high``
        middle = (low + high + 1) // 2
        if a[end_a - middle:end_a - low] == b[end_b - middle:end_b - low]:
            low = middle
        else:
            high = middle - 1
    return low
