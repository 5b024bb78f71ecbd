"""Output formats shared by the commands: text, json, SARIF 2.1.0 and GitHub annotations.

Every formatter takes a list of file reports: objects with ``path``,
``diagnostics`` and ``as_dict()`` (:class:`FileReport` here; ``validate`` has
its own, which adds the profile kind). The json document has one shape for
every command: ``{"files": [report.as_dict(), ...], "summary": {...}}``.

This module is imported on the command line's start-up path: keep its imports light.
"""

from __future__ import annotations

import json
import os
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
    """``path:line:col: CODE message [clause]``, one line per diagnostic."""
    return "".join(d.format() + "\n" for report in reports for d in report.diagnostics)


def json_document(reports: Sequence[Report]) -> dict:
    return {"files": [report.as_dict() for report in reports], "summary": summarise(reports)}


def format_json(reports: Sequence[Report]) -> str:
    return json.dumps(json_document(reports), indent=2) + "\n"


# --- SARIF 2.1.0 --------------------------------------------------------------------
def project_url() -> str | None:
    """The home page the installed package declares (``[project.urls]``), if any."""
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
    """The anchor of a rule's ``### CODE`` heading in docs/rules.md."""
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
    root = Path(os.path.abspath(root or Path.cwd()))
    rules = all_rules()
    index = {r.code: i for i, r in enumerate(rules)}
    base = project_url()
    driver: dict = {"name": "edsconv", "version": _version(), "rules": [_sarif_rule(r, base) for r in rules]}
    if base:
        driver["informationUri"] = base
    results = []
    for report in reports:
        location = artifact_location(report.path, root)
        for d in report.diagnostics:
            physical: dict = {"artifactLocation": location}
            if d.line > 0:
                physical["region"] = _region(d)
            result: dict[str, Any] = {
                "ruleId": d.code,
                "level": _SARIF_LEVEL[d.severity],
                "message": {"text": d.message},
                "locations": [{"physicalLocation": physical}],
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


def _sarif_rule(r: Rule, base: str | None) -> dict:
    described = {
        "id": r.code,
        "shortDescription": {"text": r.summary},
        "defaultConfiguration": {"level": _SARIF_LEVEL[r.severity]},
        "properties": {"clause": r.clause, "import_blocking": r.import_blocking},
    }
    if base:
        described["helpUri"] = rule_help_uri(base, r.code)
    return described


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


def format_github(reports: Iterable[Report], root: Path | None = None) -> str:
    """``::error file=…,line=…,col=…,title=EDS001::message [clause]``, one line per diagnostic.

    File paths are relative to ``root`` (the cwd: a workflow's repository checkout) when below it.
    """
    root = Path(os.path.abspath(root or Path.cwd()))
    lines = []
    for report in reports:
        path = relative_to(report.path, root).as_posix()
        for d in report.diagnostics:
            properties = [f"file={escape_property(path)}"]
            if d.line > 0:
                properties.append(f"line={d.line}")
                if d.column > 0:
                    properties.append(f"col={d.column}")
            properties.append(f"title={escape_property(d.code)}")
            message = f"{d.message} [{d.clause}]" if d.clause else d.message
            lines.append(f"::{_GITHUB_COMMAND[d.severity]} {','.join(properties)}::{escape_data(message)}\n")
    return "".join(lines)


FORMATTERS = {"text": format_text, "json": format_json, "sarif": format_sarif, "github": format_github}
