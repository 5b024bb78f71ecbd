"""The checks: every rule the spec makes checkable, run over the models of one file.

A check is a function taking a :class:`Context` and yielding diagnostics,
declared with :func:`check` and the rules it can report (its module's rules are
documented in a sibling ``*_rules`` module). :func:`load_checks` collects the
checks of :data:`CHECK_MODULES`; :func:`run_checks` runs those whose rules the
``--select``/``--ignore`` selection keeps, as sqlfluff skips unselected rules.

The language server re-checks a document on every keystroke: it hands each analysis the
:class:`CheckMemo` of the one before, and the part of a check that reads one entry (or one
record) at a time goes through :meth:`Context.each`, which reuses what that part said of the
very same objects last time instead of checking them again.
"""

from __future__ import annotations

import functools
import importlib
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from itertools import chain
from typing import Protocol, TypeVar

from edsconv.diagnostics import EVERYTHING, Diagnostic, Rule, Selection
from edsconv.eds.syntax import EdsFile, Entry
from edsconv.model import Assembly, Device, Parameter

_Unit = TypeVar("_Unit")
#: Units checked together (see :meth:`CheckMemo.each`): few enough that one edited entry re-checks
#: little, enough that an unchanged file costs a few lookups per check rather than one per entry.
_BLOCK = 64
#: A block of units and the identities of their objects.
_Block = tuple[list, tuple[int, ...]]
#: Checks each unit of a sequence on its own: reads nothing but the unit's objects and constant tables.
UnitCheck = Callable[["Context", Iterable[_Unit]], Iterable[Diagnostic]]


@dataclass(slots=True)
class Context:
    eds: EdsFile
    device: Device
    #: The diagnostics of the previous analyses of this document, by the objects they were made of (None:
    #: every command, which checks a file once).
    memo: CheckMemo | None = None
    #: the unit lists several checks share (:meth:`shared`), by the function that makes them
    _shared: dict[Callable, list] = field(default_factory=dict, init=False, repr=False)
    #: the blocks of each unit list the memo went over, by the list's identity (with the list, kept alive)
    _blocks: dict[int, tuple[list, list[_Block]]] = field(default_factory=dict, init=False, repr=False)

    def __post_init__(self) -> None:
        if self.memo is not None:
            self.memo.bind(self.eds.path)

    def each(self, function: UnitCheck[_Unit], units: Iterable[_Unit]) -> Iterable[Diagnostic]:
        """The diagnostics of ``function(self, units)``, in order.

        A unit is an object, or a tuple of the objects, that ``function`` reads to check it (an
        ``Entry``, a ``(Parameter, Entry)`` pair ...): ``function`` reads nothing else, no attribute
        that another entry decides (``Parameter.enum``, a reference's target, what the section holds
        besides) and no other state, so that the same objects always give the same diagnostics. With a
        memo, the diagnostics of units whose objects are the very ones (by identity: a string that is
        part of a unit is passed through :func:`sys.intern`) of the previous analysis are reused, and
        ``function`` only sees the others.
        """
        if self.memo is None:
            return function(self, units)
        return self.memo.each(self, function, units)

    def shared(self, units: Callable[[Context], Iterable[_Unit]]) -> list[_Unit]:
        """``units(self)``, made once for all the checks of this context that go over them."""
        found = self._shared.get(units)
        if found is None:
            found = self._shared[units] = list(units(self))
        return found

    def blocks(self, units: Iterable) -> list[_Block]:
        """The blocks of ``units`` and their objects' identities (:class:`CheckMemo`), made once for a
        list that several checks go over."""
        units = units if isinstance(units, list) else list(units)
        found = self._blocks.get(id(units))
        if found is None:
            blocks = [units[start:start + _BLOCK] for start in range(0, len(units), _BLOCK)]
            found = self._blocks[id(units)] = (units, [(block, _identities(block)) for block in blocks])
        return found[1]

    def at(self, rule_: Rule, message: str, node=None, clause: str = "") -> Diagnostic:
        """A diagnostic at a syntax node (anything with line/column), or at the file start; ``clause``
        when this case has a clause of its own (see :meth:`Diagnostic.of`)."""
        line = node.line if node is not None else 1
        column = node.column if node is not None else 1
        return Diagnostic.of(rule_, message, line, column, self.eds.path, clause=clause)


CheckFunction = Callable[[Context], Iterable[Diagnostic]]


def _identities(block: list) -> tuple[int, ...]:
    """The objects of a block of units (all objects, or all tuples of objects), by identity."""
    return tuple(map(id, chain.from_iterable(block) if block[0].__class__ is tuple else block))


class CheckMemo:
    """What the checks said of each block of units in the last analysis of a document, and in this one.

    Generational, as :class:`edsconv.model.memo.EntryMemo`: :meth:`start` begins an analysis,
    :meth:`finish` ends it; what a finished analysis used (found or made) is kept for the next one and
    the rest dropped. One analysis at a time. A stored block keeps its units' objects alive, so no new
    object can take the identity of one whose diagnostics are stored. Diagnostics are immutable.
    """

    __slots__ = ("_previous", "_current", "_complete", "_path", "hits", "misses")

    def __init__(self) -> None:
        self._previous: dict[tuple, tuple[list, tuple[Diagnostic, ...]]] = {}
        self._current: dict[tuple, tuple[list, tuple[Diagnostic, ...]]] = {}
        self._complete = True
        self._path: str | None = None
        #: blocks of units whose diagnostics were found, and blocks checked, since the memo was made
        self.hits = self.misses = 0

    def start(self) -> None:
        """A new analysis: what the last one used is what is known (both what it used and what the one
        before left, when the last one stopped before its last check, superseded by a newer text)."""
        self._previous = self._current if self._complete else {**self._previous, **self._current}
        self._current, self._complete = {}, False

    def finish(self) -> None:
        """The analysis ran every check."""
        self._complete = True

    def lines_moved(self, first_line: int, delta: int) -> None:
        """The lines of the text from ``first_line`` on moved ``delta`` lines: the diagnostics the next
        analysis can find (:meth:`start`) say where their units now stand (they are in the last text's
        lines, and now in the next's)."""
        known = self._current if self._complete else {**self._previous, **self._current}
        self._current = {key: (block, tuple(d.moved(first_line, delta) for d in found) if found else found)
                         for key, (block, found) in known.items()}
        self._previous, self._complete = {}, True

    def bind(self, path: str | None) -> None:
        """Diagnostics carry the file's path: another path (a renamed document) starts afresh."""
        if path != self._path:
            self._previous.clear()
            self._current.clear()
            self._path = path

    def each(self, ctx: Context, function: UnitCheck[_Unit], units: Iterable[_Unit]) -> Iterator[Diagnostic]:
        """:meth:`Context.each` with this memo, a block of :data:`_BLOCK` units at a time."""
        current, previous = self._current, self._previous
        for block, identities in ctx.blocks(units):
            key = (function, identities)
            found = previous.pop(key, None) or current.get(key)
            if found is None:
                self.misses += 1
                found = (block, tuple(function(ctx, block)))
            else:
                self.hits += 1
            current[key] = found
            yield from found[1]


@dataclass(frozen=True, slots=True)
class Check:
    """A check function and every rule it can report."""

    run: CheckFunction
    rules: tuple[Rule, ...]

    @property
    def name(self) -> str:
        return self.run.__name__


def check(*rules: Rule) -> Callable[[CheckFunction], Check]:
    """Declare a check function and the rules it can report (its diagnostics carry no other code)."""
    if not rules:
        raise ValueError("a check reports at least one rule")

    def declare(function: CheckFunction) -> Check:
        return Check(function, rules)

    return declare


def per_unit(units: Callable[[Context], Iterable[_Unit]]) -> Callable[[UnitCheck[_Unit]], CheckFunction]:
    """Make a check of a function that checks units one by one, those ``units(ctx)`` gives (made once
    for every check of a context that goes over them), through :meth:`Context.each` (whose rules it
    follows); under :func:`check`, the check keeps the function's name."""
    def make(function: UnitCheck[_Unit]) -> CheckFunction:
        def run(ctx: Context) -> Iterable[Diagnostic]:
            return ctx.each(function, ctx.shared(units))

        return functools.update_wrapper(run, function)

    return make


class _Recorded(Protocol):
    """A model record read from an entry."""

    @property
    def entry(self) -> Entry | None: ...


_Record = TypeVar("_Record", bound=_Recorded)


def with_entries(records: Iterable[_Record]) -> Iterator[tuple[_Record, Entry | None]]:
    """(record, its entry): the units of a check that reads records' own fields (:meth:`Context.each`)."""
    return ((record, record.entry) for record in records)


def parameter_units(ctx: Context) -> Iterator[tuple[Parameter, Entry | None]]:
    """Every parameter with its entry (see :meth:`Context.shared`)."""
    return with_entries(ctx.device.parameters.values())


def assembly_units(ctx: Context) -> Iterator[tuple[Assembly, Entry | None]]:
    """Every assembly with its entry (see :meth:`Context.shared`)."""
    return with_entries(ctx.device.assemblies.values())


#: Every module that defines checks: :func:`load_checks` collects their module-level :class:`Check` objects.
CHECK_MODULES = ("edsconv.checks.entities", "edsconv.checks.addressing", "edsconv.checks.structure",
                 "edsconv.checks.objects", "edsconv.checks.coherence")


@functools.cache
def load_checks() -> tuple[Check, ...]:
    """The checks of :data:`CHECK_MODULES`, in the order the modules define them."""
    found: dict[int, Check] = {}
    for name in CHECK_MODULES:
        for value in vars(importlib.import_module(name)).values():
            if isinstance(value, Check):
                found.setdefault(id(value), value)
    return tuple(found.values())


def run_checks(eds: EdsFile, device: Device, selection: Selection = EVERYTHING,
               memo: CheckMemo | None = None) -> Iterator[Diagnostic]:
    """The diagnostics of every check whose rules ``selection`` keeps any of (the others do not run);
    ``memo`` carries the checks' findings from one analysis of a document to the next."""
    context = Context(eds, device, memo)
    everything = selection.everything
    for check_ in load_checks():
        if everything or selection.any_of(check_.rules):
            yield from check_.run(context)
