"""Output formats shared by the commands: text, json, SARIF 2.1.0 and GitHub annotations.

Every formatter takes a list of file reports: objects with ``path``,
``diagnostics`` and ``as_dict()`` (:class:`FileReport` here; ``validate`` has
its own, which adds the profile kind). The json document has one shape for
every command: ``{"files": [report.as_dict(), ...], "summary": {...}}``.

This module is imported on the command line's start-up path: keep its imports light.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path, PurePath
from typing import Any, Protocol
from urllib.parse import quote

from edsconv.diagnostics import Diagnostic, Rule, Severity, all_rules

SARIF_VERSION = "2.1.0"
SARIF_SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
_SARIF_LEVEL = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "note"}
_GITHUB_COMMAND = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "notice"}


class Report(Protocol):
    path: str
    diagnostics: list[Diagnostic]

    def as_dict(self) -> dict: ...


@dataclass(slots=True)
class FileReport:
    """What linting one file gave; ``error`` says why the file could not be checked."""

    path: str
    diagnostics: list[Diagnostic] = field(default_factory=list)
    error: str | None = None
    #: what ``--fix`` repaired (or, with ``--diff``, would repair)
    fixed: list[Diagnostic] = field(default_factory=list)
    #: ``--diff``: the repair as a unified diff
    diff: str = ""
    #: ``--fix``: why the repaired file could not be written (the file is unchanged; exit 2)
    write_error: str | None = None

    def as_dict(self) -> dict:
        return {"path": self.path, "diagnostics": [d.as_dict() for d in self.diagnostics], "error": self.error}


def summarise(reports: Sequence[Report]) -> dict:
    diagnostics = [d for report in reports for d in report.diagnostics]
    return {
        "files": len(reports),
        "errors": sum(d.severity is Severity.ERROR for d in diagnostics),
        "warnings": sum(d.severity is Severity.WARNING for d in diagnostics),
    }


# --- text and json ----------------------------------------------------------------
def format_text(reports: Iterable[Report]) -> str:
    """``path:line:col: severity: CODE message [clause]``, one line per diagnostic."""
    return "".join(d.format() + "\n" for report in reports for d in report.diagnostics)


def json_document(reports: Sequence[Report]) -> dict:
    return {"files": [report.as_dict() for report in reports], "summary": summarise(reports)}


def format_json(reports: Sequence[Report]) -> str:
    return json.dumps(json_document(reports), indent=2) + "\n"


# --- SARIF 2.1.0 --------------------------------------------------------------------
def project_url() -> str | None:
    """The repository the installed package declares in ``[project.urls]`` (pyproject.toml), if any.

    The one place the project's address is written: SARIF's ``informationUri`` and each rule's
    ``helpUri`` (:func:`rule_help_uri`) are made from it.
    """
    from importlib import metadata

    try:
        urls = metadata.metadata("edsconv").get_all("Project-URL") or []
    except metadata.PackageNotFoundError:
        return None
    by_label = {label.strip().lower(): url.strip() for label, _, url in (entry.partition(",") for entry in urls)}
    for label in ("repository", "source", "homepage", "documentation"):
        if by_label.get(label):
            return by_label[label].rstrip("/")
    return None


def rule_help_uri(base: str, code: str) -> str:
    """The anchor of a rule's ``### CODE`` heading in docs/rules.md, in the repository at ``base``."""
    return f"{base}/blob/main/docs/rules.md#{code.lower()}"


def relative_to(path: str, root: Path) -> PurePath:
    """``path`` relative to ``root`` when it lies below it, else absolute."""
    absolute = Path(os.path.abspath(path))
    try:
        return absolute.relative_to(root)
    except ValueError:
        return absolute


def artifact_location(path: str, root: Path) -> dict:
    """A relative uri (against ``%SRCROOT%``, the cwd) when the file lies below it, else an absolute file uri."""
    where = relative_to(path, root)
    if where.is_absolute():
        return {"uri": Path(where).as_uri()}
    return {"uri": quote(where.as_posix()), "uriBaseId": "%SRCROOT%"}


def sarif_document(reports: Sequence[Report], root: Path | None = None) -> dict:
    """The SARIF log of a run: every rule with its documentation, one result per diagnostic."""
    root = Path(os.path.abspath(root or Path.cwd()))
    rules = all_rules()
    index = {r.code: i for i, r in enumerate(rules)}
    base = project_url()
    driver: dict = {"name": "edsconv", "version": _version(), "semanticVersion": _version(),
                    "rules": [_sarif_rule(r, base) for r in rules]}
    if base:
        driver["informationUri"] = base
    results = []
    for report in reports:
        location = artifact_location(report.path, root)
        fingerprints = line_fingerprints(report.path, relative_to(report.path, root).as_posix(), report.diagnostics)
        for d, fingerprint in zip(report.diagnostics, fingerprints, strict=True):
            # a finding about the whole file (no line) is placed on line 1, as code scanning needs a start line
            physical: dict = {"artifactLocation": location, "region": _region(d) if d.line > 0 else {"startLine": 1}}
            result: dict[str, Any] = {
                "ruleId": d.code,
                "level": _SARIF_LEVEL[d.severity],
                "message": {"text": f"{d.message} [{d.clause}]" if d.clause else d.message},
                "locations": [{"physicalLocation": physical}],
                "partialFingerprints": {FINGERPRINT: fingerprint},
            }
            if d.code in index:
                result["ruleIndex"] = index[d.code]
            results.append(result)
    run = {
        "tool": {"driver": driver},
        "originalUriBaseIds": {"%SRCROOT%": {"uri": root.as_uri() + "/"}},
        "results": results,
    }
    return {"$schema": SARIF_SCHEMA, "version": SARIF_VERSION, "runs": [run]}


def format_sarif(reports: Sequence[Report], root: Path | None = None) -> str:
    return json.dumps(sarif_document(reports, root), indent=2) + "\n"


#: The fingerprint GitHub code scanning matches alerts by. Given here, the upload action does not compute
#: its own (which hashes only the line's text, so that two results on one line would share it).
FINGERPRINT = "primaryLocationLineHash"
#: Line numbers inside messages ("comes later (line 42)") change when lines move: they take no part.
_LINE_NUMBER = re.compile(r"\b(line|lines) \d+(-\d+)?")


def line_fingerprints(path: str, relative: str, diagnostics: Sequence[Diagnostic]) -> list[str]:
    """A fingerprint per diagnostic: a hash of the rule, the file, the text of its line and its message, and
    the count of earlier diagnostics with the same hash (``hash:N``). It stays the same when lines are
    added above, and differs for two results on one line unless rule and message are the same too."""
    lines = _file_lines(path) if any(d.line > 0 for d in diagnostics) else []
    seen: dict[str, int] = {}
    found = []
    for d in diagnostics:
        text = lines[d.line - 1].strip() if 0 < d.line <= len(lines) else ""
        key = "\0".join((d.code, relative, text, _LINE_NUMBER.sub(r"\1", d.message)))
        digest = hashlib.sha256(key.encode("utf-8", "surrogateescape")).hexdigest()[:32]
        seen[digest] = seen.get(digest, 0) + 1
        found.append(f"{digest}:{seen[digest]}")
    return found


def _file_lines(path: str) -> list[str]:
    from edsconv.eds.source import decode

    try:
        return decode(Path(path).read_bytes()).text.split("\n")
    except OSError:
        return []


def _sarif_rule(r: Rule, base: str | None) -> dict:
    from edsconv.rule_docs import rule_help_text, rule_section

    described = {
        "id": r.code,
        "name": _rule_name(r.summary),
        "shortDescription": {"text": r.summary},
        "fullDescription": {"text": (r.explanation or r.summary).replace("\n", " ")},
        "help": {"text": rule_help_text(r), "markdown": rule_section(r)},
        "defaultConfiguration": {"level": _SARIF_LEVEL[r.severity]},
        "properties": {"clause": r.clause, "import_blocking": r.import_blocking, "fix": str(r.fix),
                       "tags": ["EDS" if r.code.startswith("EDS") else "XML", f"ISO 15745-4 {r.clause}"]},
    }
    if base:
        described["helpUri"] = rule_help_uri(base, r.code)
    return described


def _rule_name(summary: str) -> str:
    """A rule's summary as the PascalCase identifier SARIF's ``name`` is meant to be."""
    return "".join(word[:1].upper() + word[1:] for word in re.findall(r"[A-Za-z0-9]+", summary))


def _region(d: Diagnostic) -> dict:
    region = {"startLine": d.line}
    if d.column > 0:
        region["startColumn"] = d.column
    if d.end_line:
        region["endLine"] = d.end_line
        if d.end_column:
            region["endColumn"] = d.end_column
    return region


def _version() -> str:
    from importlib import metadata

    try:
        return metadata.version("edsconv")
    except metadata.PackageNotFoundError:
        return "0"


# --- GitHub workflow annotations ------------------------------------------------------
def escape_data(text: str) -> str:
    """Escape an annotation's message as GitHub's workflow commands require."""
    return text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def escape_property(text: str) -> str:
    """Escape a property value (file, title): as :func:`escape_data`, and ``:`` and ``,`` too."""
    return escape_data(text).replace(":", "%3A").replace(",", "%2C")


def format_github(reports: Sequence[Report], root: Path | None = None) -> str:
    """``::error file=…,line=…,col=…,title=EDS001::message [clause]``, one line per diagnostic, then a summary.

    Errors come first, then warnings, then notes (each in file order): GitHub shows only the first
    ten annotations of each kind a step makes, and the summary line says how many there are in all.
    File paths are relative to ``root`` (the cwd: a workflow's repository checkout) when below it.
    """
    root = Path(os.path.abspath(root or Path.cwd()))
    found = [(relative_to(report.path, root).as_posix(), d) for report in reports for d in report.diagnostics]
    found.sort(key=lambda item: -item[1].severity)  # stable: file order within a severity
    lines = [_annotation(path, d) for path, d in found]
    return "".join(lines) + f"edsconv: {counts(reports)}\n"


def _annotation(path: str, d: Diagnostic) -> str:
    properties = [f"file={escape_property(path)}"]
    if d.line > 0:
        properties.append(f"line={d.line}")
        if d.column > 0:
            properties.append(f"col={d.column}")
        if d.end_line and d.end_line == d.line and d.end_column:
            properties.append(f"endColumn={d.end_column}")
        elif d.end_line:
            properties.append(f"endLine={d.end_line}")
    properties.append(f"title={escape_property(d.code)}")
    message = f"{d.message} [{d.clause}]" if d.clause else d.message
    return f"::{_GITHUB_COMMAND[d.severity]} {','.join(properties)}::{escape_data(message)}\n"


def counts(reports: Sequence[Report]) -> str:
    """``3 files: 1 errors, 2 warnings, 0 notes``: the summary line of a run."""
    diagnostics = [d for report in reports for d in report.diagnostics]
    number = {severity: sum(d.severity is severity for d in diagnostics) for severity in Severity}
    return (f"{len(reports)} file{'s' if len(reports) != 1 else ''}: {number[Severity.ERROR]} errors, "
            f"{number[Severity.WARNING]} warnings, {number[Severity.INFO]} notes")


FORMATTERS = {"text": format_text, "json": format_json, "sarif": format_sarif, "github": format_github}
