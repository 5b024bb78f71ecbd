"""Shared paths and helpers for the test suite."""

from __future__ import annotations

from pathlib import Path

import edsconv
from edsconv.eds.syntax import EdsFile

REPO = Path(__file__).resolve().parents[1]
#: Real vendor EDS files, beside the repository (read-only, never copied in).
SHARED_REAL = Path(__file__).resolve().parents[2] / "shared" / "corpus" / "real"


def codes(eds: EdsFile) -> list[tuple[str, int, int]]:
    """(code, line, column) of every diagnostic, in report order."""
    return [(d.code, d.line, d.column) for d in eds.diagnostics]


def parse_ok(text: str | bytes) -> EdsFile:
    """Parse text that must give no diagnostic at all."""
    eds = edsconv.parse(text)
    assert eds.diagnostics == [], [d.format() for d in eds.diagnostics]
    return eds


def values(text: str) -> list:
    """The field values of the only entry of a clean one-section file."""
    eds = parse_ok(text)
    (section,) = eds.sections
    (entry,) = section.entries
    return [field.value for field in entry.fields]
