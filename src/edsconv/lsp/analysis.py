"""One analysis of one version of a document: the syntax model, the typed model, every diagnostic
and every place that names an entry.

:class:`Analyses` keeps the latest analysis of each open document and runs new
ones in a worker thread of their own, one at a time, so that reading a large
file never holds up the messages the editor sends meanwhile. An analysis asked
for twice (diagnostics and a hover on the same version) runs once. A newer text
supersedes the analysis of an older one: a queued one never starts, a running
one stops at its next step (between reading, the model and each check), so that
a client sending a request per keystroke builds no backlog. An analysis is
ready in two steps: first the models and references (what hover, completion and
navigation read), then the diagnostics.
"""

from __future__ import annotations

import asyncio
import gc
import traceback
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field, replace

import edsconv
from edsconv.checks import CheckMemo
from edsconv.diagnostics import Diagnostic
from edsconv.eds.source import as_read, split_lines
from edsconv.eds.syntax import EdsFile, Entry
from edsconv.lsp.incremental import (
    Carried,
    Edit,
    EntryReplaced,
    LinesMoved,
    change_since,
    reread,
    respaced,
    reuse_entries,
)
from edsconv.lsp.region import reread_region
from edsconv.model import Device
from edsconv.model.build import build
from edsconv.model.rebuild import with_entries_rebuilt, with_entry_rebuilt
from edsconv.model.references import Occurrence, definitions, occurrences, spans_moved, spans_of, spans_replaced
from edsconv.spec_tables import split_numbered
from edsconv.suppress import Directives, directive_comments

#: Seconds without an analysis after which the garbage of the earlier ones is collected (see :class:`Analyses`)
IDLE_COLLECTION = 1.0
#: Every this many collections in a pause, a full one (the older generations too): rare, since it scans
#: every object the open documents' analyses and memos hold (a second or more for a 3 MB file), and the
#: young generations, collected every time, hold what an analysis made
FULL_COLLECTION_EVERY = 50


@dataclass(slots=True)
class Analysis:
    version: int | None
    text: str
    #: the lines of ``text`` with their line ends, as LSP counts them
    lines: tuple[str, ...]
    eds: EdsFile
    device: Device
    #: every diagnostic, sorted by position (empty until the checks have run: see :meth:`Analyses.checked`)
    diagnostics: list[Diagnostic]
    #: every place that names an entry, or what makes them (:attr:`spans`)
    made_spans: list[Occurrence] | Callable[[], list[Occurrence]] = field(repr=False)
    #: the entries references can name, by keyword
    definitions: dict[str, Entry] = field(repr=False)
    #: the comments that may be suppressions (:func:`edsconv.suppress.directive_comments`), once checked
    directives: Directives | None = field(default=None, repr=False)

    @property
    def spans(self) -> list[Occurrence]:
        """Every place that names an entry (hover and navigation). An early answer makes them when first
        asked: moving 40,000 of them takes 20 ms, which a completion, not reading them, need not wait for."""
        if callable(self.made_spans):
            self.made_spans = self.made_spans()
        return self.made_spans

    def line_text(self, line: int) -> str:
        """Line ``line`` (1-based) without its line end; "" beyond the end."""
        return self.lines[line - 1].rstrip("\r\n") if 0 < line <= len(self.lines) else ""


class Superseded(Exception):
    """A newer text of the document arrived before this analysis was done: it stopped."""


def _never() -> bool:
    return False


def analyse(text: str, version: int | None = None, path: str | None = None, *,
            superseded: Callable[[], bool] = _never,
            readable: Callable[[Analysis], object] | None = None, carried: Carried | None = None) -> Analysis:
    """Read and check ``text``; a failure of edsconv itself becomes an EDS000 diagnostic, never an exception.

    ``superseded`` is asked between the steps: when it says so, :class:`Superseded` is raised.
    ``readable`` is handed the analysis once its models and references are made, before the checks run.
    ``carried`` is what the analysis of the document's last text left (:mod:`edsconv.lsp.incremental`):
    what the edit did not change is taken from it, and it is left for the next one.
    """
    from edsconv.eds.reader import paused_gc

    def step() -> None:
        if superseded():
            raise Superseded

    step()
    before = carried.eds if carried is not None else None
    with paused_gc():  # reading again makes many objects too (the entries read, the lines)
        change = change_since(carried, text) if carried is not None else None
        spliced = (reread(carried, change) or respaced(carried, change) or reread_region(carried, change)) \
            if carried is not None and change is not None else None
    lines, eds = spliced or (tuple(split_lines(text)), edsconv.parse(text, path))
    step()
    with paused_gc():
        try:
            memo = None
            if carried is not None:
                if spliced is None:
                    reuse_entries(carried, text, as_read(text), lines, eds)
                if readable is not None:
                    _answer_early(carried, before, readable, version, text, lines, eds)
                carried.settle()
                memo = carried.memo
                memo.start()
            device = build(eds, memo)
            step()
            analysis = Analysis(version, text, lines, eds, device, [], occurrences(eds, device, lines, memo),
                                definitions(device))
            if readable is not None:
                readable(analysis)
            diagnostics = _checked(eds, device, carried.checks if carried is not None else None, path, step)
            analysis.directives = directive_comments(eds, memo, text)
            if memo is not None:
                memo.finish()
        except Superseded:
            raise
        except Exception as error:  # noqa: BLE001 - the editor gets a diagnostic, the server keeps running
            if carried is not None:
                carried.last = None
            return _failed(text, version, path, lines, eds, error)
    diagnostics.sort(key=lambda d: (d.line, d.column))
    analysis.diagnostics = diagnostics
    if carried is not None:
        carried.last = analysis
    return analysis


def _checked(eds: EdsFile, device: Device, checks: CheckMemo | None, path: str | None,
             step: Callable[[], None]) -> list[Diagnostic]:
    """What the reader, the model and every check found (``step`` is called before each check), with
    ``checks``, the memo of what they found in the document's earlier texts."""
    from edsconv.checks import Context, load_checks

    diagnostics = [*eds.diagnostics, *device.diagnostics]
    if checks is not None:
        checks.bind(path)
        checks.start()
    context = Context(eds, device, checks)
    for check in load_checks():
        step()
        diagnostics += check.run(context)
    if checks is not None:
        checks.finish()
    return diagnostics


def _answer_early(carried: Carried, before: EdsFile | None, readable: Callable[[Analysis], object],
                  version: int | None, text: str, lines: tuple[str, ...], eds: EdsFile) -> None:
    """Hand ``readable`` the models and references of ``text`` made from the last analysis, when the edit
    since (``carried.edit``, which made ``eds`` of ``before``) allows it: :func:`_answered_early`."""
    last, edit = carried.last, carried.edit
    if edit is not None and last is not None and last.eds is before:
        early = _answered_early(last, edit, version, text, lines, eds)
        if early is not None:
            readable(early)


def _answered_early(last: Analysis, edit: Edit, version: int | None, text: str,
                    lines: tuple[str, ...], eds: EdsFile) -> Analysis | None:
    """The models and references of ``text``, whose syntax model ``eds`` is ``last``'s after ``edit``,
    made from ``last``'s: what hover, completion and navigation answer from while the whole analysis is
    made. Where blank lines moved the nodes after them, ``last``'s model and the places naming entries,
    on their new lines; where entries were read again, when their records are all that changed
    (:func:`edsconv.model.rebuild.with_entry_rebuilt`, :func:`~edsconv.model.rebuild.with_entries_rebuilt`)
    and so are the definitions of their keywords, else None."""
    if isinstance(edit, LinesMoved):
        before, first_line, moved = last.spans, edit.first_line, edit.moved
        return Analysis(version, text, lines, eds, replace(last.device, eds=eds), [],
                        lambda: spans_moved(before, first_line, moved) if moved else before, last.definitions)
    old, new = edit.old, edit.new
    device = with_entry_rebuilt(last.device, eds, edit.section, old[0], new[0]) \
        if isinstance(edit, EntryReplaced) else None  # a parameter keeps its enum: no EnumN is read
    if device is None:
        device = with_entries_rebuilt(last.device, eds, edit.section, old, new, edit.first, edit.start)
    if device is None:
        return None
    defined = _definitions_after(last.definitions, device, old, new)
    if defined is None:
        return None
    moved = edit.lines.moved if edit.lines is not None else 0
    before, replaced = last.spans, edit
    return Analysis(version, text, lines, eds, device, [], lambda: spans_replaced(
        before, replaced.start, replaced.last_line, spans_of(device, replaced.section, new, defined, lines), moved),
        defined)


def _definitions_after(known: dict[str, Entry], device: Device, old: Sequence[Entry],
                       new: Sequence[Entry]) -> dict[str, Entry] | None:
    """The definitions of ``device``, made when the entries ``new`` took the place of ``old``, whose were
    ``known``; None when the entry defining a keyword other than these changed (a numbered entry kept
    as written elsewhere, which a record of that keyword now hides or no longer does)."""
    if len(old) == len(new) == 1 and old[0].keyword == new[0].keyword and known.get(old[0].keyword) is old[0]:
        return {**known, new[0].keyword: new[0]}  # what the device defines by that keyword has not changed
    if not any(split_numbered(entry.keyword)[1] for entry in (*old, *new)):
        return known  # only a numbered entry defines anything
    defined = definitions(device)
    replaced = {id(entry) for entry in (*old, *new)}
    for keyword in {entry.keyword for entry in (*old, *new)}:
        before, after = known.get(keyword), defined.get(keyword)
        if before is not after and any(entry is not None and id(entry) not in replaced for entry in (before, after)):
            return None
    return defined


def _failed(text: str, version: int | None, path: str | None, lines: tuple[str, ...], eds: EdsFile,
            error: Exception) -> Analysis:
    """The analysis of a text edsconv failed on: its syntax diagnostics and EDS000 saying where it failed."""
    from edsconv.lint import INTERNAL_ERROR

    where = traceback.extract_tb(error.__traceback__)[-1]
    message = f"internal error {type(error).__name__}: {error} (at {where.name}:{where.lineno}); please report it"
    device = Device(eds=eds)
    diagnostics = sorted([*eds.diagnostics, Diagnostic.of(INTERNAL_ERROR, message, 1, 1, path)],
                         key=lambda d: (d.line, d.column))
    return Analysis(version, text, lines, eds, device, diagnostics, occurrences(eds, device, lines),
                    definitions(device))


@dataclass(slots=True)
class _Run:
    """One analysis under way: its text, whether a newer text superseded it, and its two results."""

    text: str
    #: the models and references (hover, completion, navigation)
    readable: asyncio.Future[Analysis]
    #: everything, diagnostics included
    checked: asyncio.Future[Analysis]
    superseded: bool = False


class Analyses:
    """The latest analysis of each document, by URI.

    The server runs with the cyclic garbage collector off (:func:`edsconv.lsp.server.create_server`):
    an analysis is hundreds of thousands of small objects, and the first collection after one (a
    scan of all of them) fell on the next keystroke's path. Its garbage is collected here instead,
    once no analysis has run for :data:`IDLE_COLLECTION` seconds, a pause in typing.
    """

    def __init__(self) -> None:
        self._latest: dict[str, _Run] = {}
        #: what the analyses of each open document hand from one text to the next
        self._carried: dict[str, Carried] = {}
        #: one analysis at a time: two would share the interpreter and both be late
        self._worker = ThreadPoolExecutor(max_workers=1, thread_name_prefix="edsconv-analysis")
        self._collection: asyncio.TimerHandle | None = None
        self.collections = 0

    def _collect_when_idle(self, loop: asyncio.AbstractEventLoop) -> None:
        if self._collection is not None:
            self._collection.cancel()
        self._collection = loop.call_later(IDLE_COLLECTION, self._collect)

    def _collect(self) -> None:
        self._collection = None
        self.collections += 1
        gc.collect(2 if self.collections % FULL_COLLECTION_EVERY == 0 else 1)

    def of(self, uri: str, text: str, version: int | None, path: str | None) -> asyncio.Future[Analysis]:
        """The whole analysis of this text (diagnostics included); it fails with :class:`Superseded`
        when a newer text of the document is asked for before it is done."""
        return self._run(uri, text, version, path).checked

    def readable(self, uri: str, text: str, version: int | None, path: str | None) -> asyncio.Future[Analysis]:
        """The analysis of this text as soon as its models and references are made (its diagnostics may
        still be empty): what hover, completion and navigation need, without waiting for the checks."""
        return self._run(uri, text, version, path).readable

    def _run(self, uri: str, text: str, version: int | None, path: str | None) -> _Run:
        known = self._latest.get(uri)
        if known is not None and known.text == text:
            return known
        if known is not None:
            known.superseded = True
        loop = asyncio.get_running_loop()
        if self._collection is not None:
            self._collection.cancel()  # not while this one runs: it is collected in the pause after it
        run = _Run(text, loop.create_future(), loop.create_future())
        self._latest[uri] = run
        carried = self._carried.setdefault(uri, Carried())

        def settle(future: asyncio.Future[Analysis], analysis: Analysis | None, error: BaseException | None) -> None:
            if future.done():
                return
            if error is None:
                future.set_result(analysis)  # type: ignore[arg-type]  # given when there is no error
            else:
                future.set_exception(error)

        def work() -> None:
            try:
                analysis = analyse(text, version, path, superseded=lambda: run.superseded, carried=carried,
                                   readable=lambda a: loop.call_soon_threadsafe(settle, run.readable, a, None))
            except BaseException as error:  # noqa: BLE001 - handed to whoever waits for this text
                for future in (run.readable, run.checked):
                    loop.call_soon_threadsafe(settle, future, None, error)
                loop.call_soon_threadsafe(self._collect_when_idle, loop)
                return
            for future in (run.readable, run.checked):
                loop.call_soon_threadsafe(settle, future, analysis, None)
            loop.call_soon_threadsafe(self._collect_when_idle, loop)

        self._worker.submit(work)
        for future in (run.readable, run.checked):  # nobody may be waiting for a superseded text's analysis
            future.add_done_callback(lambda f: f.cancelled() or f.exception())
        return run

    def forget(self, uri: str, closed: bool = False) -> None:
        """The document changed or closed: the analysis of its old text stops at its next step; what
        its analyses handed on is dropped when it closed."""
        known = self._latest.pop(uri, None)
        if known is not None:
            known.superseded = True
        if closed:
            self._carried.pop(uri, None)
