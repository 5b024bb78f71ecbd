"""Output formats shared by the commands: text, json, SARIF 2.1.0 and GitHub annotations.

Every formatter takes a list of file reports: objects with ``path``,
``diagnostics`` and ``as_dict()`` (:class:`FileReport` here; ``validate`` has
its own, which adds the profile kind). The json document has one shape for
every command: ``{"files": [report.as_dict(), ...], "summary": {...}}``.

This module is imported on the command line's start-up path: keep its imports light.
"""

from __future__ import annotations

import functools
import hashlib
import json
import os
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path, PurePath
from typing import TYPE_CHECKING, Any, Protocol
from urllib.parse import quote, urlsplit

from edsconv.diagnostics import Diagnostic, Rule, Severity, all_rules

if TYPE_CHECKING:
    from edsconv.fix import Fix

SARIF_VERSION = "2.1.0"
SARIF_SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
_SARIF_LEVEL = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "note"}
_GITHUB_COMMAND = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "notice"}
#: GitHub code scanning's published limits of a SARIF upload: results in a run, and the gzip-compressed
#: size of the file; beyond either the upload is refused (docs.github.com, "SARIF support for code scanning").
SARIF_MAX_RESULTS = 25_000
SARIF_MAX_GZIP_BYTES = 10 * 1000 * 1000
#: How the summaries tell a user to see the notes left out by default.
SHOW_NOTES = "--show-notes"


# --- output encoding: the one place names and positions are made fit for each format ---------------
def printable(text: str) -> str:
    """A file name or message as text, JSON and GitHub annotations print it: valid Unicode whatever the bytes.

    A file name that is not UTF-8 reaches Python with lone surrogates (PEP 383); its bytes are
    shown as ``\\xe9`` escapes, so that strict JSON parsers and UTF-8 terminals accept the output.
    """
    return text.encode("utf-8", "surrogateescape").decode("utf-8", "backslashreplace")


def uri_path(path: PurePath) -> str:
    """A path as a SARIF URI path: the file name's bytes percent-encoded (RFC 3986), UTF-8 or not."""
    return quote(os.fsencode(path.as_posix()))


def position(d: Diagnostic) -> tuple[int, int]:
    """A diagnostic's line and column as the formats print them: a finding about the whole file (no
    line, no column) stands at 1:1, as SARIF and editors' problem matchers need a 1-based position."""
    return max(d.line, 1), max(d.column, 1)


def fix_key(d: Diagnostic) -> tuple[str, int, int, str]:
    """What identifies a diagnostic among its file's: the key of :attr:`FileReport.fixes`."""
    return d.code, d.line, d.column, d.message


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
    #: the safe fix of each diagnostic that has one here (by :func:`fix_key`): ``[*]`` and SARIF ``fixes``
    fixes: dict[tuple[str, int, int, str], Fix] = field(default_factory=dict)
    #: notes found but not shown (notes are shown on request: ``--show-notes``)
    hidden_notes: int = 0
    #: ``--fix``: why the repaired file could not be written (the file is unchanged; exit 2)
    write_error: str | None = None

    def as_dict(self) -> dict:
        return {"path": printable(self.path), "diagnostics": [self._entry(d) for d in self.diagnostics],
                "error": self.error and printable(self.error), "fixed": [self._entry(d) for d in self.fixed],
                "hidden_notes": self.hidden_notes}

    def fix_of(self, d: Diagnostic) -> Fix | None:
        return self.fixes.get(fix_key(d))

    def _entry(self, d: Diagnostic) -> dict:
        line, column = position(d)
        return {**d.as_dict(), "line": line, "column": column, "message": printable(d.message),
                "fixable": fix_key(d) in self.fixes, "url": rule_help_uri(d.code)}


def severity_counts(reports: Sequence[Report]) -> dict[Severity, int]:
    diagnostics = [d for report in reports for d in report.diagnostics]
    return {severity: sum(d.severity is severity for d in diagnostics) for severity in Severity}


def summarise(reports: Sequence[Report]) -> dict:
    number = severity_counts(reports)
    summary = {"files": len(reports), "errors": number[Severity.ERROR], "warnings": number[Severity.WARNING],
               "notes": number[Severity.INFO]}
    if all(isinstance(r, FileReport) for r in reports):  # lint's own: fixes and hidden notes
        lint_reports = [r for r in reports if isinstance(r, FileReport)]
        summary |= {"hidden_notes": sum(r.hidden_notes for r in lint_reports),
                    "fixable": sum(fix_key(d) in r.fixes for r in lint_reports for d in r.diagnostics),
                    "fixed": sum(len(r.fixed) for r in lint_reports)}
    return summary


# --- json ----------------------------------------------------------------------------
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


def rule_help_uri(code: str) -> str:
    """Where rule ``code`` is documented: its ``### CODE`` heading in docs/rules.md.

    In the project's repository when pyproject.toml declares a real one; while it declares the
    ``.invalid`` placeholder (no public repository yet), in the documentation installed with the
    package, as a ``file:`` URL that opens on this machine. Every link to a rule is made here:
    SARIF ``helpUri``, the text and JSON formats, ``edsconv rules CODE`` and the language server.
    """
    base = project_url()
    if base and not urlsplit(base).hostname.endswith(".invalid"):  # type: ignore[union-attr]
        return f"{base}/blob/main/docs/rules.md#{code.lower()}"
    return f"{_installed_rules_page()}#{code.lower()}"


@functools.cache
def _installed_rules_page() -> str:
    from edsconv.resources import data_dir

    try:
        return (data_dir("docs") / "rules.md").as_uri()
    except FileNotFoundError:  # an installation without its docs: the name still says where to look
        return "docs/rules.md"


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
        return {"uri": "file://" + uri_path(where)}
    return {"uri": uri_path(where), "uriBaseId": "%SRCROOT%"}


def sarif_document(reports: Sequence[Report], root: Path | None = None,
                   max_results: int = SARIF_MAX_RESULTS) -> dict:
    """The SARIF log of a run: every rule with its documentation, one result per diagnostic (with its fix
    when it has one), at most ``max_results`` of them: the most severe are kept, and a notification of the
    run says how many were left out."""
    root = Path(os.path.abspath(root or Path.cwd()))
    rules = all_rules()
    index = {r.code: i for i, r in enumerate(rules)}
    base = project_url()
    driver: dict = {"name": "edsconv", "version": _version(), "semanticVersion": _version(),
                    "rules": [_sarif_rule(r) for r in rules]}
    if base:
        driver["informationUri"] = base
    kept = _most_severe(reports, max_results)
    results = []
    for report in reports:
        location = artifact_location(report.path, root)
        fingerprints = line_fingerprints(report.path, relative_to(report.path, root).as_posix(), report.diagnostics)
        for d, fingerprint in zip(report.diagnostics, fingerprints, strict=True):
            if id(d) not in kept:
                continue
            result = _sarif_result(d, location, fingerprint)
            if d.code in index:
                result["ruleIndex"] = index[d.code]
            fix = report.fix_of(d) if isinstance(report, FileReport) else None
            if fix is not None:
                result["fixes"] = [_sarif_fix(fix, location)]
            results.append(result)
    run: dict[str, Any] = {
        "tool": {"driver": driver},
        "originalUriBaseIds": {"%SRCROOT%": {"uri": root.as_uri() + "/"}},
        "results": results,
    }
    hidden = sum(getattr(r, "hidden_notes", 0) for r in reports)
    if hidden:
        run["properties"] = {"hiddenNotes": hidden}
    left_out = sum(len(r.diagnostics) for r in reports) - len(results)
    if left_out:
        run["invocations"] = [{"executionSuccessful": True, "toolExecutionNotifications": [{
            "level": "warning", "message": {"text": truncation_note(left_out, max_results)}}]}]
    return {"$schema": SARIF_SCHEMA, "version": SARIF_VERSION, "runs": [run]}


def truncation_note(left_out: int, max_results: int) -> str:
    return (f"{plural(left_out, 'result')} left out: GitHub code scanning accepts at most {SARIF_MAX_RESULTS:,} "
            f"results and {SARIF_MAX_GZIP_BYTES // 1000 // 1000} MB (gzip) in a run; the {max_results:,} most severe "
            "are kept. Lint with --format text to see them all.")


def _most_severe(reports: Sequence[Report], limit: int) -> set[int]:
    """The ids of the ``limit`` most severe diagnostics (in file order within a severity)."""
    found = [d for report in reports for d in report.diagnostics]
    if len(found) > limit:
        found = sorted(found, key=lambda d: -d.severity)[:limit]  # stable: file order within a severity
    return {id(d) for d in found}


def _sarif_result(d: Diagnostic, location: dict, fingerprint: str) -> dict[str, Any]:
    # a finding about the whole file (no line) is placed on line 1, as code scanning needs a start line
    physical: dict = {"artifactLocation": location, "region": _region(d) if d.line > 0 else {"startLine": 1}}
    message = printable(f"{d.message} [{d.clause}]" if d.clause else d.message)
    return {
        "ruleId": d.code,
        "level": _SARIF_LEVEL[d.severity],
        "message": {"text": message},
        "locations": [{"physicalLocation": physical}],
        "partialFingerprints": {FINGERPRINT: fingerprint},
    }


def _sarif_fix(fix: Fix, location: dict) -> dict:
    """A safe fix as SARIF's ``fix``: the replacements of one artifact (columns as the result's region)."""
    replacements = [{"deletedRegion": {"startLine": e.line, "startColumn": e.column, "endLine": e.end_line,
                                       "endColumn": e.end_column},
                     "insertedContent": {"text": e.text}} for e in fix.edits]
    return {"description": {"text": fix.title},
            "artifactChanges": [{"artifactLocation": location, "replacements": replacements}]}


def format_sarif(reports: Sequence[Report], root: Path | None = None, max_results: int = SARIF_MAX_RESULTS,
                 max_gzip_bytes: int = SARIF_MAX_GZIP_BYTES) -> str:
    return sarif_log(reports, root, max_results, max_gzip_bytes)[0]


def sarif_log(reports: Sequence[Report], root: Path | None = None, max_results: int = SARIF_MAX_RESULTS,
              max_gzip_bytes: int = SARIF_MAX_GZIP_BYTES) -> tuple[str, str | None]:
    """The SARIF log within GitHub's limits: at most ``max_results`` results, and fewer (halved until it
    fits) when the file would exceed ``max_gzip_bytes`` once compressed; and the note that says how many
    results were left out (None when none was)."""
    import gzip

    while True:
        document = sarif_document(reports, root, max_results)
        text = json.dumps(document, indent=2) + "\n"
        if max_results == 0 or len(gzip.compress(text.encode("utf-8"), 6)) <= max_gzip_bytes:
            notes = document["runs"][0].get("invocations", [{}])[0].get("toolExecutionNotifications", [])
            return text, notes[0]["message"]["text"] if notes else None
        max_results //= 2


#: The fingerprint GitHub code scanning matches alerts by. Given here, the upload action does not compute
#: its own (which hashes only the line's text, so that two results on one line would share it).
FINGERPRINT = "primaryLocationLineHash"
#: Line numbers inside messages ("comes later (line 42)") change when lines move: they take no part.
_LINE_NUMBER = re.compile(r"\b(line|lines) \d+(-\d+)?")


def line_fingerprints(path: str, relative: str, diagnostics: Sequence[Diagnostic]) -> list[str]:
    """A fingerprint per diagnostic: a hash of the rule, the file, the text of its line and its message, and
    the count of earlier diagnostics with the same hash (``hash:N``). It stays the same when lines are
    added above, and differs for two results on one line unless rule and message are the same too."""
    lines = file_lines(path) if any(d.line > 0 for d in diagnostics) else []
    seen: dict[str, int] = {}
    found = []
    for d in diagnostics:
        text = lines[d.line - 1].strip() if 0 < d.line <= len(lines) else ""
        key = "\0".join((d.code, relative, text, _LINE_NUMBER.sub(r"\1", d.message)))
        digest = hashlib.sha256(key.encode("utf-8", "surrogateescape")).hexdigest()[:32]
        seen[digest] = seen.get(digest, 0) + 1
        found.append(f"{digest}:{seen[digest]}")
    return found


def file_lines(path: str) -> list[str]:
    """The lines of a file as the reader decodes it (none when it cannot be read)."""
    from edsconv.eds.source import decode

    try:
        return decode(Path(path).read_bytes()).text.split("\n")
    except OSError:
        return []


def _sarif_rule(r: Rule) -> dict:
    from edsconv.rule_docs import rule_help_text, rule_section

    return {
        "id": r.code,
        "name": _rule_name(r.summary),
        "shortDescription": {"text": r.summary},
        "fullDescription": {"text": (r.explanation or r.summary).replace("\n", " ")},
        "help": {"text": rule_help_text(r), "markdown": rule_section(r)},
        "defaultConfiguration": {"level": _SARIF_LEVEL[r.severity]},
        "properties": {"clause": r.clause, "import_blocking": r.import_blocking, "fix": str(r.fix),
                       "tags": ["EDS" if r.code.startswith("EDS") else "XML", f"ISO 15745-4 {r.clause}"]},
        "helpUri": rule_help_uri(r.code),
    }


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
    found = [(printable(relative_to(report.path, root).as_posix()), d)
             for report in reports for d in report.diagnostics]
    found.sort(key=lambda item: -item[1].severity)  # stable: file order within a severity
    lines = [_annotation(path, d) for path, d in found]
    return "".join(lines) + f"edsconv: {counts(reports)}\n"


def _annotation(path: str, d: Diagnostic) -> str:
    line, column = position(d)
    properties = [f"file={escape_property(path)}", f"line={line}", f"col={column}"]
    if d.end_line and d.end_line == d.line and d.end_column:
        properties.append(f"endColumn={d.end_column}")
    elif d.end_line:
        properties.append(f"endLine={d.end_line}")
    properties.append(f"title={escape_property(d.code)}")
    message = printable(f"{d.message} [{d.clause}]" if d.clause else d.message)
    return f"::{_GITHUB_COMMAND[d.severity]} {','.join(properties)}::{escape_data(message)}\n"


def plural(number: int, noun: str) -> str:
    """``1 error``, ``2 errors``, ``1,234 notes``."""
    return f"{number:,} {noun}{'' if number == 1 else 's'}"


def counts(reports: Sequence[Report]) -> str:
    """``3 files: 1 error, 2 warnings, 0 notes``: the first line of a run's summary; notes left out by
    default are counted with a hint to show them."""
    number = severity_counts(reports)
    hidden = sum(getattr(r, "hidden_notes", 0) for r in reports)
    notes = plural(number[Severity.INFO], "note")
    if hidden:
        notes = (f"{plural(hidden, 'note')} hidden (show with {SHOW_NOTES})" if not number[Severity.INFO]
                 else f"{notes} ({hidden:,} more hidden: show with {SHOW_NOTES})")
    return (f"{plural(len(reports), 'file')}: {plural(number[Severity.ERROR], 'error')}, "
            f"{plural(number[Severity.WARNING], 'warning')}, {notes}")


def format_text(reports: Sequence[FileReport]) -> str:
    """``path:line:col: severity: CODE message [clause]``, one line per diagnostic: the text of commands
    other than lint (lint also has ``full``, colour and a summary: :mod:`edsconv.report_text`)."""
    from edsconv.report_text import format_concise

    return format_concise(reports)


#: Every command's output formats (lint adds ``concise`` and ``full``, and prints ``text`` as one of them).
FORMATTERS = {"text": format_text, "json": format_json, "sarif": format_sarif, "github": format_github}
