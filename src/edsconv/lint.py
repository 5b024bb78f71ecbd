"""Linting many EDS files: what ``edsconv lint`` runs.

:func:`lint_paths` finds the EDS files below the given paths, checks each one
(:func:`lint_file`) by the configuration found for it (:mod:`edsconv.config`), with
the suppressions its comments state (:mod:`edsconv.suppress`), on every core when
there are enough of them, and returns one :class:`~edsconv.report.FileReport` per
file in a stable order; ``--fix`` repairs what :mod:`edsconv.fix` can. A file that
cannot be read (or a directory that cannot be searched), or on which edsconv itself
fails, gives an ``EDS000`` diagnostic: one broken file never stops the run. Which files
are checked is :mod:`edsconv.paths`'s rule; running them in workers, :mod:`edsconv.parallel`'s.

Heavy imports (rich, concurrent.futures) happen inside the functions that need
them.
"""

from __future__ import annotations

import difflib
import enum
import os
import traceback
from collections.abc import Iterable, Sequence
from pathlib import Path

from edsconv.config import FileRules, Overrides, Resolver
from edsconv.diagnostics import EVERYTHING, Diagnostic, Selection, Severity, rule
from edsconv.eds.reader import parse
from edsconv.eds.refusals import read_bytes
from edsconv.eds.syntax import EdsFile
from edsconv.fix import fix_source, fixes_of, raw_text
from edsconv.parallel import file_size, run_all
from edsconv.paths import Found
from edsconv.paths import discover as find
from edsconv.report import FileReport
from edsconv.suppress import apply_suppressions

INTERNAL_ERROR = rule(
    "EDS000", Severity.ERROR, "edsconv",
    "edsconv could not check this file: it is unreadable, or edsconv failed on it (please report that)",
    explanation="""
        edsconv could not check this file: the file could not be read (permissions, a
        dangling symbolic link, a file removed during the run), a directory below a
        searched one could not be searched (its files were never seen), or edsconv
        failed on it. The message says which. An internal failure is a bug in edsconv:
        please report it with the file. The rest of the run goes on; the other files are
        reported as usual.
    """,
    bad="""
        a file the linting user may not read.

        ```sh
        chmod 000 device.eds && edsconv lint device.eds
        ```
    """,
    good="""
        a readable file.

        ```sh
        chmod 644 device.eds && edsconv lint device.eds
        ```
    """,
)

#: Every rule reported, nothing dropped: a file without configuration.
EVERY_RULE = FileRules()


class FixMode(enum.Enum):
    """What ``lint`` does with the faults that have a safe fix."""

    REPORT = "report"
    #: ``--fix``: repair them and write the file
    FIX = "fix"
    #: ``--diff``: show the repair as a unified diff, write nothing
    DIFF = "diff"


# --- per file -------------------------------------------------------------------------
def analyse(eds: EdsFile, selection: Selection = EVERYTHING) -> list[Diagnostic]:
    """The diagnostics ``selection`` keeps of a file that has been read: syntax, values, checks."""
    from edsconv import analyse as analyse_device

    return analyse_device(eds, selection)[1]


def check(eds: EdsFile, rules: FileRules = EVERY_RULE) -> list[Diagnostic]:
    """What is reported for a file that has been read: the rules of ``rules``, less what its comments suppress."""
    diagnostics = apply_suppressions(eds, rules.kept(analyse(eds, rules.selection)), rules.reports)
    for d in diagnostics:
        if d.path is None:
            d.path = eds.path
        if rules.warnings_as_errors and d.severity is Severity.WARNING:
            d.severity = Severity.ERROR
    diagnostics.sort(key=lambda d: (d.line, d.column))
    return diagnostics


def lint_file(path: str, rules: FileRules = EVERY_RULE, fix: FixMode = FixMode.REPORT) -> FileReport:
    """Read and check one file (and fix it, as ``fix`` says); never raises for a problem of this file."""
    try:
        data = read_bytes(path)  # never more than one byte past the size limit (EDS025)
        if fix is FixMode.REPORT:
            eds = parse(data, path)
            diagnostics = check(eds, rules)
            return FileReport(path, diagnostics, fixes=fixes_of(eds, data, diagnostics))
        return _fixed(path, data, rules, fix)
    except OSError as error:
        return _failed(path, _unreadable(path, error), rules.selection)
    except Exception as error:  # noqa: BLE001 - one file must never stop the run
        where = traceback.extract_tb(error.__traceback__)[-1]
        return _failed(path, f"internal error {type(error).__name__}: {error} "
                       f"(at {Path(where.filename).name}:{where.lineno}); please report it", rules.selection)


def _fixed(path: str, data: bytes, rules: FileRules, fix: FixMode) -> FileReport:
    """Fix the file (``--fix``: written atomically, its permissions kept) or show the fix (``--diff``)."""
    outcome = fix_source(data, path, lambda eds: check(eds, rules))
    report = FileReport(path, outcome.diagnostics, fixed=outcome.fixed)
    if outcome.data == data:
        return report
    if fix is FixMode.DIFF:
        old, new = raw_text(data, outcome.encoding), raw_text(outcome.data, outcome.encoding)
        report.diff = "".join(difflib.unified_diff(old.splitlines(keepends=True), new.splitlines(keepends=True),
                                                   path, f"{path} (fixed)"))
        return report
    from edsconv.atomic import rewrite_in_place

    try:  # a symbolic link stays a link (its target is fixed), and the file keeps its mode: edsconv.atomic
        rewrite_in_place(Path(path), outcome.data)
    except OSError as error:  # the file is as it was: its findings are those of its text, nothing fixed
        return FileReport(path, check(parse(data, path), rules), write_error=error.strerror or str(error))
    return report


def _unreadable(path: str, error: OSError) -> str:
    if isinstance(error, FileNotFoundError) and os.path.islink(path):
        return f"cannot read the file: it is a symbolic link to {os.readlink(path)}, which does not exist"
    return f"cannot read the file: {error.strerror or error}"


def _failed(path: str, message: str, selection: Selection = EVERYTHING) -> FileReport:
    diagnostics = [Diagnostic.of(INTERNAL_ERROR, message, path=path)] if INTERNAL_ERROR.code in selection else []
    return FileReport(path, diagnostics, error=message)


# --- many files -------------------------------------------------------------------------
def discover(paths: Iterable[str | Path], resolver: Resolver | None = None, *,
             force_exclude: bool = False) -> list[str]:
    """The files ``lint`` checks below ``paths``, by the one rule of :mod:`edsconv.paths`."""
    return find(paths, resolver, force_exclude=force_exclude).files


def lint_paths(paths: Iterable[str | Path], select: Sequence[str] = (), ignore: Sequence[str] = (),
               jobs: int | None = None, *, overrides: Overrides | None = None,
               fix: FixMode = FixMode.REPORT, found: Found | None = None) -> list[FileReport]:
    """Lint every file :mod:`edsconv.paths` finds (or those of ``found``), each by the configuration found
    for it (:mod:`edsconv.config`) with ``overrides`` (or ``select``/``ignore``) on top; reports in
    discovery order, then one EDS000 report for each directory that could not be searched.

    A check none of whose rules is selected does not run. :class:`~edsconv.config.ConfigError`
    when a configuration file is bad.
    """
    resolver = Resolver(overrides or Overrides(tuple(select), tuple(ignore)))
    found = found or find(paths, resolver)
    tasks = [(f, resolver.settings_for(f).for_file(f), fix) for f in found.files]
    reports = run_all(lint_file, tasks, jobs or os.cpu_count() or 1, "linting", died=_died,
                      sizes=[file_size(f) for f in found.files])
    return reports + [_failed(directory, f"cannot search the directory: {reason}",
                              resolver.settings_for(directory).for_file(directory).selection)
                      for directory, reason in found.unsearchable]


def _died(task: tuple, message: str) -> FileReport:
    path, rules, _ = task
    return _failed(path, message, rules.selection)


def at_least(reports: Iterable[FileReport], severity: Severity, named: Iterable[str] = ()) -> None:
    """``--min-severity``: drop the diagnostics below ``severity``, but those of the rules ``named``
    (``--select EDS321`` asks for that note); count the notes dropped (``hidden_notes``)."""
    asked = frozenset(named)
    for report in reports:
        kept = [d for d in report.diagnostics if d.severity >= severity or d.code in asked]
        report.hidden_notes = _notes(report.diagnostics) - _notes(kept)
        report.diagnostics = kept


def _notes(diagnostics: list[Diagnostic]) -> int:
    return sum(d.severity is Severity.INFO for d in diagnostics)
