"""The checks: every rule the spec makes checkable, run over the models of one file.

A check is a function taking a :class:`Context` and yielding diagnostics,
declared with :func:`check` and the rules it can report (its module's rules are
documented in a sibling ``*_rules`` module). :func:`load_checks` collects the
checks of :data:`CHECK_MODULES`; :func:`run_checks` runs those whose rules the
``--select``/``--ignore`` selection keeps, as sqlfluff skips unselected rules.
"""

from __future__ import annotations

import functools
import importlib
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass

from edsconv.diagnostics import EVERYTHING, Diagnostic, Rule, Selection
from edsconv.eds.syntax import EdsFile
from edsconv.model import Device


@dataclass(slots=True)
class Context:
    eds: EdsFile
    device: Device

    def at(self, rule_: Rule, message: str, node=None, clause: str = "") -> Diagnostic:
        """A diagnostic at a syntax node (anything with line/column), or at the file start; ``clause``
        when this case has a clause of its own (see :meth:`Diagnostic.of`)."""
        line = node.line if node is not None else 1
        column = node.column if node is not None else 1
        return Diagnostic.of(rule_, message, line, column, self.eds.path, clause=clause)


CheckFunction = Callable[[Context], Iterable[Diagnostic]]


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


def run_checks(eds: EdsFile, device: Device, selection: Selection = EVERYTHING) -> Iterator[Diagnostic]:
    """The diagnostics of every check whose rules ``selection`` keeps any of (the others do not run)."""
    context = Context(eds, device)
    everything = selection.everything
    for check_ in load_checks():
        if everything or selection.any_of(check_.rules):
            yield from check_.run(context)
