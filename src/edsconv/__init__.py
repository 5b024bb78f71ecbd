"""edsconv: parse, check and convert CIP Electronic Data Sheets (ISO 15745-4 Annex C.4)."""

from edsconv.diagnostics import EVERYTHING, Diagnostic, Selection, Severity
from edsconv.eds.reader import load, parse
from edsconv.eds.syntax import Comment, EdsFile, Entry, Field, Group, Scalar, Section, String, ValueKind
from edsconv.model import Device
from edsconv.model.build import build


def analyse(eds: EdsFile, selection: Selection = EVERYTHING) -> tuple[Device, list[Diagnostic]]:
    """The semantic model of a parsed EDS and its diagnostics: syntax, values, checks.

    Only the diagnostics ``selection`` keeps are returned, and checks whose rules it drops do not run.
    """
    from edsconv.checks import run_checks

    device = build(eds)
    diagnostics = [*eds.diagnostics, *device.diagnostics, *run_checks(eds, device, selection)]
    if selection.everything:
        return device, diagnostics
    return device, [d for d in diagnostics if d.code in selection]


__all__ = ["Comment", "Device", "Diagnostic", "EdsFile", "Entry", "Field", "Group", "Scalar", "Section", "Selection",
           "Severity", "String", "ValueKind", "analyse", "build", "load", "parse"]
