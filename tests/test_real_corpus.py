"""The reader on real vendor EDS files (shared corpus beside the repository; skipped when absent)."""

from __future__ import annotations

import functools

import pytest

import edsconv
from conftest import REAL_CORPUS_MARKS, REAL_EDS, SHARED_REAL
from edsconv.eds.syntax import EdsFile
from edsconv.eds.writer import write

pytestmark = REAL_CORPUS_MARKS


#: Files with error diagnostics: name -> [(code, line)], each checked by reading the file.
#: A code may be a tuple of codes that are equally right for the fault.
BROKEN = {
    # "Port1 = ..., Backplane, 20 66 24 01, 1;": the port's EPATH is written without quotes
    # (a syntax error; EDS012 once the reader names the missing comma between "20" and "66").
    "omidbimo__eds_pie__t.eds": [(("EDS001", "EDS012"), 240)],
    # a stray line "AssemExa101" with no '=' after Param2's ';' in [Params].
    "rossmann-engineering__EEIP.NET__fanucrobot0202.eds": [("EDS001", 57)],
}


@functools.cache
def load(name: str) -> EdsFile:
    return edsconv.load(SHARED_REAL / name)


def test_corpus_is_there():
    assert len(REAL_EDS) >= 50
    assert set(BROKEN) <= {p.name for p in REAL_EDS}


@pytest.mark.parametrize("name", [p.name for p in REAL_EDS])
def test_file_reads_and_round_trips(name):
    eds = load(name)
    assert eds.sections
    assert edsconv.parse(write(eds)) == eds


@pytest.mark.parametrize("name", [p.name for p in REAL_EDS])
def test_errors_are_exactly_the_expected_ones(name):
    errors = [(d.code, d.line) for d in load(name).diagnostics if d.severity.name == "ERROR"]
    expected = BROKEN.get(name, [])
    assert len(errors) == len(expected), errors
    for (code, line), (want_code, want_line) in zip(errors, expected, strict=True):
        assert line == want_line and code in (want_code if isinstance(want_code, tuple) else (want_code,)), errors


def test_diagnostic_totals():
    totals: dict[str, int] = {}
    for path in REAL_EDS:
        for diagnostic in load(path.name).diagnostics:
            totals[diagnostic.code] = totals.get(diagnostic.code, 0) + 1
    clean = sum(1 for path in REAL_EDS if not load(path.name).has_errors)
    assert clean == len(REAL_EDS) - len(BROKEN)
    assert set(totals) <= {"EDS001", "EDS005", "EDS006", "EDS012"}
    assert totals.get("EDS001", 0) + totals.get("EDS012", 0) == 2
    assert totals["EDS005"] == 3


def test_non_ascii_files_warn_with_a_line():
    flagged = {path.name for path in REAL_EDS if any(d.code == "EDS005" for d in load(path.name).diagnostics)}
    for name in flagged:
        (warning,) = [d for d in load(name).diagnostics if d.code == "EDS005"]
        raw_line = (SHARED_REAL / name).read_bytes().split(b"\n")[warning.line - 1]
        assert any(byte > 0x7F for byte in raw_line)
    for path in REAL_EDS:
        if path.name not in flagged:
            assert path.read_bytes().isascii(), path.name


def test_entry_before_the_stray_line_is_kept():
    params = load("rossmann-engineering__EEIP.NET__fanucrobot0202.eds").section("Params")
    assert [e.keyword for e in params.entries] == ["Param1", "Param2", "Param3", "Param4"]
