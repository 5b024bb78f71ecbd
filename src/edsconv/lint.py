"""Linting many EDS files: what ``edsconv lint`` runs.

:func:`lint_paths` finds the EDS files below the given paths, checks each one
(:func:`lint_file`) by the configuration found for it (:mod:`edsconv.config`), with
the suppressions its comments state (:mod:`edsconv.suppress`), on every core when
there are enough of them, and returns one :class:`~edsconv.report.FileReport` per
file in a stable order; ``--fix`` repairs what :mod:`edsconv.fix` can. A file that
cannot be read, or on which edsconv itself fails, gives an ``EDS000``
diagnostic: one broken file never stops the run.

Heavy imports (rich, concurrent.futures) happen inside the functions that need
them.
"""

from __future__ import annotations

import difflib
import enum
import os
import sys
import traceback
from collections.abc import Iterable, Sequence
from pathlib import Path

from edsconv.config import FileRules, Overrides, Resolver
from edsconv.diagnostics import EVERYTHING, Diagnostic, Selection, Severity, rule
from edsconv.eds.reader import parse
from edsconv.eds.refusals import read_bytes
from edsconv.eds.syntax import EdsFile
from edsconv.fix import fix_source, raw_text
from edsconv.report import FileReport
from edsconv.suppress import apply_suppressions

INTERNAL_ERROR = rule(
    "EDS000", Severity.ERROR, "edsconv",
    "edsconv could not check this file: it is unreadable, or edsconv failed on it (please report that)",
    explanation="""
        edsconv could not check this file: the file could not be read (permissions, a
        directory named like a file, a file removed during the run) or edsconv failed on
        it. The message says which. An internal failure is a bug in edsconv: please
        report it with the file. The rest of the run goes on; the other files are
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

#: The suffix of the files a directory is searched for, in any letter case (files named explicitly are
#: linted whatever their suffix).
EDS_SUFFIX = ".eds"
#: Below this many files the work stays in this process: starting workers costs more than it saves.
PARALLEL_THRESHOLD = 8
#: From this many files on, a progress bar is shown (on a terminal only).
PROGRESS_THRESHOLD = 20


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
            return FileReport(path, check(parse(data, path), rules))
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
    from edsconv.atomic import write_atomically

    # a symbolic link stays a link (its target is fixed), and the file keeps its mode: edsconv.atomic
    write_atomically(Path(path), outcome.data, force=True)
    return report


def _unreadable(path: str, error: OSError) -> str:
    where = Path(path)
    if where.is_symlink() and not where.exists():
        return f"cannot read the file: it is a symbolic link to {os.readlink(where)}, which does not exist"
    return f"cannot read the file: {error.strerror or error}"


def _failed(path: str, message: str, selection: Selection = EVERYTHING) -> FileReport:
    diagnostics = [Diagnostic.of(INTERNAL_ERROR, message, path=path)] if INTERNAL_ERROR.code in selection else []
    return FileReport(path, diagnostics, error=message)


# --- many files -------------------------------------------------------------------------
def discover(paths: Iterable[str | Path], resolver: Resolver | None = None) -> list[str]:
    """Files as given, and directories searched recursively for ``*.eds`` in any letter case, sorted.

    A dangling symbolic link found in a directory is kept (and reported when linted), never
    skipped in silence; a file a configuration's ``exclude`` matches is left out of directory
    searches (a file named explicitly is always linted). A file reached twice is linted once,
    where it first appears.
    """
    found: dict[str, None] = {}
    for path in map(Path, paths):
        if path.is_dir():
            below = sorted(str(p) for p in path.rglob("*") if _is_eds(p))
            if resolver is not None:
                below = [p for p in below if not resolver.settings_for(p).excludes(p)]
            found.update(dict.fromkeys(below))
        else:
            found[str(path)] = None
    return list(found)


def _is_eds(path: Path) -> bool:
    return path.suffix.lower() == EDS_SUFFIX and (path.is_file() or (path.is_symlink() and not path.exists()))


def lint_paths(paths: Iterable[str | Path], select: Sequence[str] = (), ignore: Sequence[str] = (),
               jobs: int | None = None, *, overrides: Overrides | None = None,
               fix: FixMode = FixMode.REPORT) -> list[FileReport]:
    """Lint every file :func:`discover` finds, each by the configuration found for it (:mod:`edsconv.config`)
    with ``overrides`` (or ``select``/``ignore``) on top; reports in discovery order.

    A check none of whose rules is selected does not run. :class:`~edsconv.config.ConfigError`
    when a configuration file is bad.
    """
    resolver = Resolver(overrides or Overrides(tuple(select), tuple(ignore)))
    files = discover(paths, resolver)
    tasks = [(f, resolver.settings_for(f).for_file(f)) for f in files]
    jobs = jobs or os.cpu_count() or 1
    if jobs > 1 and len(files) > PARALLEL_THRESHOLD:
        return _lint_parallel(tasks, jobs, fix)
    return [lint_file(f, rules, fix) for f, rules in _progress(tasks, len(tasks))]


def _lint_parallel(tasks: list[tuple[str, FileRules]], jobs: int, fix: FixMode) -> list[FileReport]:
    from concurrent.futures import ProcessPoolExecutor, as_completed
    from concurrent.futures.process import BrokenProcessPool

    reports: list[FileReport | None] = [None] * len(tasks)
    # Largest first, one file a task: sizes differ a hundredfold, and the last big file must not start alone.
    order = sorted(range(len(tasks)), key=lambda i: -_size(tasks[i][0]))
    try:
        with ProcessPoolExecutor(max_workers=min(jobs, len(tasks))) as pool:
            futures = {pool.submit(lint_file, *tasks[i], fix): i for i in order}
            for future in _progress(as_completed(futures), len(tasks)):
                reports[futures[future]] = future.result()
    except BrokenProcessPool as error:
        # A worker died (killed, out of memory): every file not answered for is reported, the rest kept.
        message = f"the worker process checking this file died ({error}); please report it"
        reports = [r or _failed(f, message, rules.selection) for (f, rules), r in zip(tasks, reports, strict=True)]
    return [r for r in reports if r is not None]  # every file has its report by now


def _size(path: str) -> int:
    try:
        return os.stat(path).st_size
    except OSError:
        return 0


def _progress(items: Iterable, total: int) -> Iterable:
    """``items``, with a progress bar on stderr when it is a terminal and there are many."""
    if total < PROGRESS_THRESHOLD or not sys.stderr.isatty():
        yield from items
        return
    from rich.console import Console
    from rich.progress import Progress

    with Progress(console=Console(stderr=True), transient=True) as progress:
        task = progress.add_task("linting", total=total)
        for item in items:
            yield item
            progress.advance(task)


def at_least(reports: Iterable[FileReport], severity: Severity) -> None:
    """``--min-severity``: drop the diagnostics below ``severity``."""
    for report in reports:
        report.diagnostics = [d for d in report.diagnostics if d.severity >= severity]
