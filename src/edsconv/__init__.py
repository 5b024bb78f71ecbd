"""edsconv: parse, check and convert CIP Electronic Data Sheets (ISO 15745-4 Annex C.4).

The names below are imported on first use (module ``__getattr__``): ``edsconv parse``
loads the reader alone, not the semantic model and the checks behind ``analyse``.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from edsconv.diagnostics import EVERYTHING, Diagnostic, Selection, Severity

if TYPE_CHECKING:
    from edsconv.eds.reader import load, parse
    from edsconv.eds.syntax import Comment, EdsFile, Entry, Field, Group, Scalar, Section, String, ValueKind
    from edsconv.model import Device
    from edsconv.model.build import build

#: public name -> the module that defines it
_HOMES = {
    "load": "edsconv.eds.reader", "parse": "edsconv.eds.reader",
    **{name: "edsconv.eds.syntax" for name in
       ("Comment", "EdsFile", "Entry", "Field", "Group", "Scalar", "Section", "String", "ValueKind")},
    "Device": "edsconv.model", "build": "edsconv.model.build",
}


def __getattr__(name: str) -> Any:
    home = _HOMES.get(name)
    if home is None:
        raise AttributeError(f"module 'edsconv' has no attribute {name!r}")
    value = getattr(importlib.import_module(home), name)
    globals()[name] = value
    return value


def analyse(eds: EdsFile, selection: Selection = EVERYTHING) -> tuple[Device, list[Diagnostic]]:
    """The semantic model of a parsed EDS and its diagnostics: syntax, values, checks.

    Only the diagnostics ``selection`` keeps are returned, and checks whose rules it drops do not run.
    """
    from edsconv.checks import run_checks
    from edsconv.eds.reader import paused_gc
    from edsconv.model.build import build

    with paused_gc():
        device = build(eds)
        diagnostics = [*eds.diagnostics, *device.diagnostics, *run_checks(eds, device, selection)]
    if selection.everything:
        return device, diagnostics
    return device, [d for d in diagnostics if d.code in selection]


__all__ = ["Comment", "Device", "Diagnostic", "EdsFile", "Entry", "Field", "Group", "Scalar", "Section", "Selection",
           "Severity", "String", "ValueKind", "analyse", "build", "load", "parse"]
