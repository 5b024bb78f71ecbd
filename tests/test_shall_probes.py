"""Fidelity to ISO 15745-4:2003 C.4.1.2 to C.4.1.5: one EDS file per checkable requirement, and files the
text allows (corpus/shall, corpus/allowed; both described in corpus/shall/README.md).

A probe breaks one requirement: edsconv must report the expected code at the expected line with the
expected severity, and at that line no other code than those of the ``also`` column (one fault, one
code). An allowed file is unusual but valid: edsconv must report no error in it, and never the code
of its ``must_not_report`` column. A row whose ``gap`` column is filled states what edsconv does not do
yet (issue 9); its test is a strict xfail, so it fails as soon as the gap closes: empty the column then.
"""

from __future__ import annotations

import csv
from pathlib import Path

import pytest

import edsconv
from conftest import REPO
from edsconv.diagnostics import Diagnostic, Severity
from edsconv.report import all_rules

SHALL, ALLOWED = REPO / "corpus" / "shall", REPO / "corpus" / "allowed"
#: Expected codes no rule registers yet are written "NEW <suggested name>".
NEW = "NEW "
CODES = frozenset(rule.code for rule in all_rules())


def manifest(folder: Path) -> list[dict[str, str]]:
    with (folder / "MANIFEST.tsv").open(encoding="utf-8", newline="") as table:
        return list(csv.DictReader(table, delimiter="\t", quoting=csv.QUOTE_NONE))


def cases(folder: Path) -> list:
    """One pytest parameter per manifest row, a strict xfail where the row names a gap."""
    return [pytest.param(row, id=row["file"],
                         marks=[pytest.mark.xfail(strict=True, reason=row["gap"])] if row["gap"] else [])
            for row in manifest(folder)]


def diagnostics(path: Path) -> list[Diagnostic]:
    return edsconv.analyse(edsconv.load(path))[1]


def described(found: list[Diagnostic]) -> list[str]:
    return [f"{d.code} {d.severity} line {d.line}: {d.message}" for d in found]


@pytest.mark.parametrize("row", cases(SHALL))
def test_probe_is_reported(row):
    line = int(row["expected_line"])
    at_line = [d for d in diagnostics(SHALL / row["file"]) if d.line == line]
    expected = [d for d in at_line if d.code == row["expected_code"] and str(d.severity) == row["expected_severity"]]
    others = {d.code for d in at_line} - {row["expected_code"], *filter(None, row["also"].split(","))}
    assert expected, f"{row['requirement']}: no {row['expected_code']} {row['expected_severity']} at line {line}; " \
                     f"found {described(at_line)}"
    assert not others, f"one fault, one code: {sorted(others)} also reported at line {line}"


@pytest.mark.parametrize("row", cases(ALLOWED))
def test_allowed_file_is_not_an_error(row):
    found = diagnostics(ALLOWED / row["file"])
    errors = [d for d in found if d.severity is Severity.ERROR]
    forbidden = [d for d in found if d.code == row["must_not_report"]]
    assert not errors, f"{row['allowance']}: {described(errors)}"
    assert not forbidden, f"{row['must_not_report']} reported: {described(forbidden)}"


@pytest.mark.parametrize("folder", [SHALL, ALLOWED], ids=["shall", "allowed"])
def test_manifest_lists_every_file_once(folder):
    listed = [row["file"] for row in manifest(folder)]
    assert sorted(listed) == sorted(path.name for path in folder.glob("*.eds"))
    assert len(set(listed)) == len(listed)


def test_probe_rows_are_well_formed():
    severities = {str(severity) for severity in Severity}
    for row in manifest(SHALL):
        code = row["expected_code"]
        assert code in CODES or code.startswith(NEW), row["file"]
        assert not code.startswith(NEW) or row["gap"], f"{row['file']}: a NEW rule is a gap"
        assert row["expected_severity"] in severities, row["file"]
        assert row["expected_severity"] == "error" or row["severity_reason"], f"{row['file']}: why not an error?"
        assert all(also in CODES for also in filter(None, row["also"].split(","))), row["file"]
        assert row["file"].startswith(row["clause"] + "_"), row["file"]
        assert 1 <= int(row["expected_line"]) <= len((SHALL / row["file"]).read_bytes().split(b"\n"))


def test_allowed_rows_are_well_formed():
    for row in manifest(ALLOWED):
        assert row["must_not_report"] in CODES or row["must_not_report"].startswith(NEW), row["file"]
        assert row["file"].startswith(row["clause"] + "_") and row["reason"], row["file"]
