"""Linting many EDS files: what ``edsconv lint`` runs.

:func:`lint_paths` finds the EDS files below the given paths, checks each one
(:func:`lint_file`) on every core when there are enough of them, and returns
one :class:`~edsconv.report.FileReport` per file in a stable order. A file that
cannot be read, or on which edsconv itself fails, gives an ``EDS000``
diagnostic: one broken file never stops the run.

Heavy imports (rich, concurrent.futures) happen inside the functions that need
them.
"""

from __future__ import annotations

import os
import sys
import traceback
from collections.abc import Iterable, Sequence
from pathlib import Path

from edsconv.diagnostics import EVERYTHING, Diagnostic, Selection, Severity, rule
from edsconv.eds.reader import load
from edsconv.eds.syntax import EdsFile
from edsconv.report import FileReport

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

#: Suffixes of the files a directory is searched for (files named explicitly are linted whatever their suffix).
EDS_SUFFIXES = (".eds", ".EDS")
#: Below this many files the work stays in this process: starting workers costs more than it saves.
PARALLEL_THRESHOLD = 8
#: From this many files on, a progress bar is shown (on a terminal only).
PROGRESS_THRESHOLD = 20


# --- per file -------------------------------------------------------------------------
def analyse(eds: EdsFile, selection: Selection = EVERYTHING) -> list[Diagnostic]:
    """The diagnostics ``selection`` keeps of a file that has been read: syntax, values, checks."""
    from edsconv import analyse as analyse_device

    return analyse_device(eds, selection)[1]


def lint_file(path: str, selection: Selection = EVERYTHING) -> FileReport:
    """Read and check one file; never raises for a problem of this file."""
    try:
        diagnostics = analyse(load(path), selection)
    except OSError as error:
        return _failed(path, f"cannot read the file: {error.strerror or error}", selection)
    except Exception as error:  # noqa: BLE001 - one file must never stop the run
        where = traceback.extract_tb(error.__traceback__)[-1]
        return _failed(path, f"internal error {type(error).__name__}: {error} "
                       f"(at {Path(where.filename).name}:{where.lineno}); please report it", selection)
    for d in diagnostics:
        if d.path is None:
            d.path = path
    diagnostics.sort(key=lambda d: (d.line, d.column))
    return FileReport(path, diagnostics)


def _failed(path: str, message: str, selection: Selection = EVERYTHING) -> FileReport:
    diagnostics = [Diagnostic.of(INTERNAL_ERROR, message, path=path)] if INTERNAL_ERROR.code in selection else []
    return FileReport(path, diagnostics, error=message)


# --- many files -------------------------------------------------------------------------
def discover(paths: Iterable[str | Path]) -> list[str]:
    """Files as given, and directories searched recursively for ``*.eds``/``*.EDS``, sorted.

    A file reached twice is linted once, where it first appears.
    """
    found: dict[str, None] = {}
    for path in map(Path, paths):
        if path.is_dir():
            below = (p for p in path.rglob("*") if p.suffix in EDS_SUFFIXES and p.is_file())
            found.update(dict.fromkeys(sorted(str(p) for p in below)))
        else:
            found[str(path)] = None
    return list(found)


def lint_paths(paths: Iterable[str | Path], select: Sequence[str] = (), ignore: Sequence[str] = (),
               jobs: int | None = None) -> list[FileReport]:
    """Lint every file :func:`discover` finds; reports in its order, filtered by ``select``/``ignore``.

    A check none of whose rules is selected does not run.
    """
    files = discover(paths)
    selection = Selection.of(select, ignore)
    jobs = jobs or os.cpu_count() or 1
    if jobs > 1 and len(files) > PARALLEL_THRESHOLD:
        return _lint_parallel(files, jobs, selection)
    return [lint_file(f, selection) for f in _progress(files, len(files))]


def _lint_parallel(files: list[str], jobs: int, selection: Selection) -> list[FileReport]:
    from concurrent.futures import ProcessPoolExecutor, as_completed
    from concurrent.futures.process import BrokenProcessPool

    reports: list[FileReport | None] = [None] * len(files)
    # Largest first, one file a task: sizes differ a hundredfold, and the last big file must not start alone.
    order = sorted(range(len(files)), key=lambda i: -_size(files[i]))
    try:
        with ProcessPoolExecutor(max_workers=min(jobs, len(files))) as pool:
            futures = {pool.submit(lint_file, files[i], selection): i for i in order}
            for future in _progress(as_completed(futures), len(files)):
                reports[futures[future]] = future.result()
    except BrokenProcessPool as error:
        # A worker died (killed, out of memory): every file not answered for is reported, the rest kept.
        message = f"the worker process checking this file died ({error}); please report it"
        reports = [r or _failed(f, message, selection) for f, r in zip(files, reports, strict=True)]
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


def promote_warnings(reports: Iterable[FileReport]) -> None:
    """``--warnings-as-errors``: every warning becomes an error."""
    for report in reports:
        for d in report.diagnostics:
            if d.severity is Severity.WARNING:
                d.severity = Severity.ERROR
