"""edsconv: parse, check and convert CIP Electronic Data Sheets (ISO 15745-4 Annex C.4)."""

from edsconv.diagnostics import Diagnostic, Severity
from edsconv.model import Device
from edsconv.eds.reader import load, parse
from edsconv.model.build import build
from edsconv.eds.syntax import Comment, EdsFile, Entry, Field, Group, Scalar, Section, String, ValueKind


def analyse(eds: EdsFile) -> tuple[Device, list[Diagnostic]]:
    """The semantic model of a parsed EDS and every diagnostic: syntax, values, checks."""
    from edsconv.checks import run_checks

    device = build(eds)
    diagnostics = [*eds.diagnostics, *device.diagnostics, *run_checks(eds, device)]
    return device, diagnostics


__all__ = ["Comment", "Device", "Diagnostic", "EdsFile", "Entry", "Field", "Group", "Scalar", "Section", "Severity",
           "String", "ValueKind", "analyse", "build", "load", "parse"]
