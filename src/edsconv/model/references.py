"""Every place in an EDS that names an entry, with its position: for go-to-definition, find-references, rename.

The semantic model resolves references (:func:`edsconv.model.build.iter_references`:
group members, assembly members, connection RPI/size/format, the chassis
SlotDisplayRule); this module adds what an editor needs beyond the model: where
each one is written, the ``[ParamN]`` / ``ParamN`` substitutions inside path
strings (C.4.1.4.9.13), the entries paired with a parameter by number (EnumN
and ParamN, ProxyParamSizeAdderN and ProxyParamN, Table C.13 and C.4.1.5.3.1),
and the defining keywords themselves.

Scaling links (ParamN fields 17-20) hold parameter instance numbers, which the
model keeps as plain integers; they are not listed here.
"""

from __future__ import annotations

import bisect
import operator
import re
from collections.abc import Iterator, Sequence
from itertools import islice
from typing import NamedTuple

from edsconv import spec_tables as tables
from edsconv.eds.syntax import EdsFile, Entry, String
from edsconv.model import Device, Reference
from edsconv.model.build import iter_references
from edsconv.model.memo import MISSING, EntryMemo, Kind

#: A parameter substitution inside a path string, bracketed or not (C.4.1.4.9.13).
# a path reference standing alone: not part of a longer word
_PATH_REFERENCE = re.compile(rf"(?<![A-Za-z0-9_]){tables.PATH_REFERENCE_RE.pattern}(?![A-Za-z0-9_])")


class Occurrence(NamedTuple):
    """A span of the EDS text that names the entry ``target``.

    The span holds ``prefix`` followed by the number of the target (``Param3``,
    ``Enum3``), or only the number where the text names it by number (``prefix``
    is then empty: the members of a GroupN). A named tuple: a file has one or more
    per entry, made again when an edit moves their lines, and a tuple is made five
    times faster than a frozen dataclass.
    """

    target: str
    line: int
    column: int
    end_column: int
    prefix: str
    #: "definition", "paired entry", "group member", "assembly member", "connection", "path", "slot display rule"
    kind: str
    #: the keyword of the entry the span is written in
    entry: str

    def renamed(self, number: int) -> str:
        """The text of the span when the target is renumbered to ``number``."""
        return f"{self.prefix}{number}"


def spans_moved(spans: list[Occurrence], first_line: int, delta: int) -> list[Occurrence]:
    """``spans`` (in text order) after the lines from ``first_line`` on moved ``delta`` lines."""
    first = bisect.bisect_left(spans, first_line, key=_line_of)
    return spans[:first] + [Occurrence(target, line + delta, column, end_column, prefix, kind, entry)
                            for target, line, column, end_column, prefix, kind, entry in islice(spans, first, None)]


#: The spans of an entry (:func:`occurrences`)
SPANS = Kind("spans", spans_moved)


def definitions(device: Device) -> dict[str, Entry]:
    """The entries that references can name, by keyword (parameters, assemblies,
    connections, and numbered entries the 2003 text does not define such as AssemExaN)."""
    found: dict[str, Entry] = {}
    for records in (device.parameters, device.assemblies, device.connections):
        found.update(zip(records, map(_entry_of, records.values()), strict=True))  # in C: 40,000 in 2 ms
    if None in found.values():  # records made from XML have no entry
        found = {keyword: entry for keyword, entry in found.items() if entry is not None}
    for entries in device.extra_entries.values():
        for generic in entries:
            if generic.entry is not None and tables.split_numbered(generic.keyword)[1] and generic.keyword not in found:
                found[generic.keyword] = generic.entry
    return found


_entry_of = operator.attrgetter("entry")


def occurrences(eds: EdsFile, device: Device, lines: Sequence[str], memo: EntryMemo | None = None) -> list[Occurrence]:
    """Every span naming an entry, definitions included, in text order.

    ``lines`` are the lines of the text ``eds`` was read from (line ends may stay
    on them); they locate substitutions inside multi-part path strings. With a
    ``memo`` (:mod:`edsconv.model.memo`), the spans of an entry it knows are taken
    from it when the entry still defines what it defined and holds as many references.
    """
    defined = {id(entry): keyword for keyword, entry in definitions(device).items()}
    references: dict[int, list[Reference]] = {}
    for reference in iter_references(device):
        if reference.entry is not None:
            references.setdefault(id(reference.entry), []).append(reference)
    found: list[Occurrence] = []
    for section in eds.sections:
        for entry in section.entries:
            target, written = defined.get(id(entry)), references.get(id(entry), ())
            if memo is None:
                found += _entry_spans(section.name, entry, target, written, lines)
                continue
            context = (section.name, target, len(written))
            spans = memo.get(SPANS, entry, context)
            if spans is MISSING:
                spans = _entry_spans(section.name, entry, target, written, lines)
                memo.put(SPANS, entry, context, spans)
            found += spans
    return found


def spans_replaced(spans: list[Occurrence], start: tuple[int, int], last_line: int, replacing: list[Occurrence],
                   moved: int = 0) -> list[Occurrence]:
    """``spans`` (in text order) with those from ``start`` (line, column) to the end of line ``last_line``
    replaced by ``replacing``, and those after them ``moved`` lines later."""
    first = bisect.bisect_left(spans, start, key=_position)
    last = bisect.bisect_right(spans, last_line, key=_line_of)
    after = spans_moved(spans[last:], last_line + 1, moved) if moved else spans[last:]
    return [*spans[:first], *replacing, *after]


def spans_of(device: Device, section: str, entries: Sequence[Entry], defined: dict[str, Entry],
             lines: Sequence[str]) -> list[Occurrence]:
    """The spans of ``entries``, which stand in this order in ``section``, in ``device`` (whose definitions
    are ``defined``): what :func:`occurrences` finds of them."""
    ids = {id(entry) for entry in entries}
    written: dict[int, list[Reference]] = {}
    for reference in iter_references(device):
        if id(reference.entry) in ids:
            written.setdefault(id(reference.entry), []).append(reference)
    return [span for entry in entries
            for span in _entry_spans(section, entry, entry.keyword if defined.get(entry.keyword) is entry else None,
                                     written.get(id(entry), ()), lines)]


def _line_of(span: Occurrence) -> int:
    return span.line


def _position(span: Occurrence) -> tuple[int, int]:
    return span.line, span.column


def _entry_spans(section: str, entry: Entry, target: str | None, written: Sequence[Reference],
                 lines: Sequence[str]) -> list[Occurrence]:
    """The spans of one entry: its keyword where it is a definition or paired with one, the
    references the model read from it, and those inside its path strings."""
    spans = [] if target is None else [_keyword_span(entry, target, "definition")]
    spec = tables.entry_spec(section, entry.keyword)
    if spec is not None and spec.pairs_with:
        spans.append(_keyword_span(entry, f"{spec.pairs_with}{tables.split_numbered(entry.keyword)[1]}",
                                   "paired entry"))
    fields = entry.fields
    spans += [_reference_span(reference, entry, section) for reference in written
              if reference.field_index < len(fields)]
    if spec is not None:
        spans += _path_references(spec, entry, lines)
    spans.sort(key=_position)  # an assembly's path, read after its members, stands before them
    return spans


def references_to(target: str, spans: Sequence[Occurrence]) -> list[Occurrence]:
    """The spans naming ``target``, in document order."""
    return sorted((s for s in spans if s.target == target), key=lambda s: (s.line, s.column))


def occurrence_at(spans: Sequence[Occurrence], line: int, column: int) -> Occurrence | None:
    """The span touching ``line``:``column`` (a cursor just after a word still touches it)."""
    return next((s for s in spans if s.line == line and s.column <= column <= s.end_column), None)


def _keyword_span(entry: Entry, target: str, kind: str) -> Occurrence:
    prefix = tables.split_numbered(entry.keyword)[0]
    return Occurrence(target, entry.line, entry.column, entry.column + len(entry.keyword), prefix, kind,
                      entry.keyword)


_KIND_BY_SECTION = {"Groups": "group member", "Assembly": "assembly member", "Connection Manager": "connection",
                    "Modular": "slot display rule"}


def _reference_span(reference: Reference, entry: Entry, section: str) -> Occurrence:
    item = entry.fields[reference.field_index]
    raw = item.raw or ""
    by_number = not raw.startswith(reference.family)
    text = raw if by_number else reference.keyword
    line, column = item.line, item.column
    return Occurrence(reference.keyword, line, column, column + len(text), "" if by_number else reference.family,
                      _KIND_BY_SECTION.get(section, "reference"), entry.keyword)


def _path_references(spec: tables.EntrySpec, entry: Entry, lines: Sequence[str]) -> Iterator[Occurrence]:
    """``[ParamN]`` and ``ParamN`` inside the entry's path strings (fields whose type is an EPATH)."""
    for index, item in enumerate(entry.fields):
        value = item.value
        if not isinstance(value, String) or "Param" not in value.raw:
            continue
        field_spec = spec.field_at(index + 1)
        if field_spec is None or "EPATH" not in field_spec.alternatives:
            continue
        for line, column, part in _string_parts(value, item.line, item.column, lines):
            for match in _PATH_REFERENCE.finditer(part):
                family = tables.split_numbered(match.group())[0]
                yield Occurrence(match.group(), line, column + match.start(),
                                 column + match.end(), family, "path", entry.keyword)


def _string_parts(value: String, line: int, column: int, lines: Sequence[str]) -> Iterator[tuple[int, int, str]]:
    """Each quoted part of a string with the line and column where it is written."""
    for part in value.parts:
        while line <= len(lines):
            found = lines[line - 1].find(part, column - 1)
            if found >= 0:
                yield line, found + 1, part
                column = found + 1 + len(part)
                break
            line, column = line + 1, 1
