"""The checks: every rule the spec makes checkable, run over the models of one file.

A check is a function taking a :class:`Context` and yielding diagnostics; it is
registered with :func:`check`, its rules with :func:`edsconv.diagnostics.rule`
in the same module (so ``edsconv rules`` and docs/rules.md list them). The
check modules are imported at the end of this file.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass

from edsconv.diagnostics import Diagnostic, Rule
from edsconv.model import Device
from edsconv.eds.syntax import EdsFile


@dataclass(slots=True)
class Context:
    eds: EdsFile
    device: Device

    def at(self, rule_: Rule, message: str, node=None) -> Diagnostic:
        """A diagnostic at a syntax node (anything with line/column), or at the file start."""
        line = node.line if node is not None else 1
        column = node.column if node is not None else 1
        return Diagnostic.of(rule_, message, line, column, self.eds.path)


Check = Callable[[Context], Iterable[Diagnostic]]
CHECKS: list[Check] = []


def check(function: Check) -> Check:
    """Register a check function."""
    CHECKS.append(function)
    return function


def run_checks(eds: EdsFile, device: Device) -> Iterator[Diagnostic]:
    context = Context(eds, device)
    for function in CHECKS:
        yield from function(context)


# Registration happens on import; these modules use `check` and `Context` above.
from edsconv.checks import entities, structure  # noqa: E402,F401
