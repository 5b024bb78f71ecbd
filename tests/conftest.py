"""Shared paths and helpers for the test suite."""

from __future__ import annotations

from pathlib import Path

import pytest

import edsconv
from edsconv.eds.syntax import EdsFile

REPO = Path(__file__).resolve().parents[1]
#: Real vendor EDS files, beside the repository (read-only, never copied in).
SHARED_REAL = Path(__file__).resolve().parents[2] / "shared" / "corpus" / "real"
#: The real EDS files (any case of ``.eds``), sorted; empty when the corpus is not beside the repository.
REAL_EDS = sorted(p for p in SHARED_REAL.glob("*") if p.suffix.lower() == ".eds") if SHARED_REAL.is_dir() else []


#: A test over the real corpus: marked ``real_corpus`` (.ci/test-matrix's newest-release runs leave those
#: out) and skipped when ../shared/corpus/real is not beside the repository (a module's ``pytestmark``).
REAL_CORPUS_MARKS = [
    pytest.mark.real_corpus,
    pytest.mark.skipif(not SHARED_REAL.is_dir(), reason="../shared/corpus/real is not beside the repository"),
]


def needs_real_corpus(test):
    """:data:`REAL_CORPUS_MARKS` on one test."""
    for mark in REAL_CORPUS_MARKS:
        test = mark(test)
    return test


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """A test run with a real file as a parameter is a test over the real corpus, whatever else its
    parameters hold: one rule, where each module marked some of them and not others."""
    for item in items:
        parameters = getattr(item, "callspec", None)
        if parameters and any(isinstance(value, Path) and value.is_relative_to(SHARED_REAL)
                              for value in parameters.params.values()):
            item.add_marker(pytest.mark.real_corpus)


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
